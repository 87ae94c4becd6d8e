//! Microfacet normal distributions and their masking-shadowing functions.
//!
//! A rough surface is modelled as a random height field of tiny mirrors (microfacets) whose
//! normals `m` follow a distribution `D(m)`, normalised so that the microfacets' projected
//! area is the macro-surface's: `∫ D(m) cos θm dωm = 1`. Smith's model of masking gives the
//! fraction of microfacets visible from a direction `w`, `G1(w) = 1 / (1 + Λ(w))`, through
//! the distribution's `Λ` (Heitz 2014, "Understanding the Masking-Shadowing Function in
//! Microfacet-Based BRDFs", JCGT 3(2), §5).
//!
//! One trait, [`NormalDistribution`], and one type per distribution:
//!
//! | type | distribution | Λ | sampling |
//! | --- | --- | --- | --- |
//! | [`Ggx`] | Trowbridge-Reitz / GGX, anisotropic | exact, closed form | visible normals (spherical caps) and bounded VNDF for reflection |
//! | [`Beckmann`] | Beckmann, anisotropic | exact (erf), or Walter's rational G1 | visible normals, `D cos θ` |
//! | [`Gtr`] | Burley's generalised Trowbridge-Reitz, any `γ > 0`, isotropic | exact Smith, tabulated at construction | `D cos θ` |
//! | [`BlinnPhongNdf`] | normalised Blinn-Phong, isotropic | Beckmann's of the same `α` (approximate), or exact Smith tabulated | `D cos θ` |
//!
//! All functions work in the local frame (`z` the macro-normal) and are total: grazing
//! directions, tiny `α` and normals below the horizon give finite values, zero where the
//! physics says zero.

mod beckmann;
mod blinn_phong;
mod ggx;
mod gtr;
mod masking;
mod smith_table;

pub use beckmann::{Beckmann, BeckmannMasking};
pub use blinn_phong::BlinnPhongNdf;
pub use ggx::Ggx;
pub use gtr::Gtr;
pub use masking::{Masking, v_cavity};

use glam::{Vec2, Vec3};

/// A microfacet normal distribution with Smith masking.
///
/// Directions are local (`z` the macro-surface normal) and unit length. `m` is a
/// microfacet normal; `w` a direction away from the surface.
pub trait NormalDistribution {
    /// The distribution of normals `D(m)`, normalised so that `∫ D(m) cos θm dωm = 1`;
    /// zero for `m.z ≤ 0`.
    #[must_use]
    fn d(&self, m: Vec3) -> f32;

    /// Smith's auxiliary function `Λ(w)`, with `G1(w) = 1 / (1 + Λ(w))`.
    ///
    /// Depends on `w` only through `tan² θ` and `φ`, so `Λ(w) = Λ(x, y, −z)`. `0` along the
    /// normal, `+∞` in the tangent plane.
    #[must_use]
    fn lambda(&self, w: Vec3) -> f32;

    /// Smith's masking function `G1(w) = 1 / (1 + Λ(w))`, without the microfacet-side
    /// factor `χ⁺(w·m)`, which the caller applies.
    #[inline]
    #[must_use]
    fn g1(&self, w: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(w))
    }

    /// Height-correlated masking-shadowing `G2 = 1 / (1 + Λ(wo) + Λ(wi))` (Heitz 2014,
    /// eq. 99), the physically preferred form; without the `χ⁺` factors.
    #[inline]
    #[must_use]
    fn g2(&self, wo: Vec3, wi: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(wo) + self.lambda(wi))
    }

    /// Separable masking-shadowing `G2 = G1(wo) G1(wi)` (Heitz 2014, eq. 98), which counts
    /// a microfacet hidden from both directions twice and so is never above [`g2`](Self::g2).
    #[inline]
    #[must_use]
    fn g2_separable(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.g1(wo) * self.g1(wi)
    }

    /// The distribution of normals visible from `w` (Heitz & d'Eon 2014, eq. 2):
    /// `D_w(m) = G1(w) max(0, w·m) D(m) / cos θw`, a density in `m` that integrates to 1.
    ///
    /// `w` below the horizon is first replaced by `−w` ([`upper`]), the convention of
    /// [`sample`](Self::sample): a refracting model sees the surface from either side.
    #[must_use]
    fn d_visible(&self, w: Vec3, m: Vec3) -> f32 {
        self.d_visible_given_d(w, m, self.d(m))
    }

    /// [`d_visible`](Self::d_visible) when `d = D(m)` is already known: a model that has
    /// evaluated `D` for its value passes it here instead of evaluating it again.
    #[must_use]
    fn d_visible_given_d(&self, w: Vec3, m: Vec3, d: f32) -> f32 {
        let w = upper(w);
        let wm = w.dot(m);
        if !(w.z > 0.0 && wm > 0.0) || d == 0.0 {
            return 0.0;
        }
        // G1/cos θ has a finite limit at grazing; keep the product in that order.
        self.g1(w) / w.z * wm * d
    }

    /// Draws a microfacet normal with the distribution's own sampler, with density
    /// [`pdf`](Self::pdf) in solid angle of `m`: the visible normals `D_w(m)` where the
    /// distribution can sample them, `D(m) cos θm` otherwise.
    ///
    /// `u` is uniform in `[0, 1)²`. `w` below the horizon is replaced by `−w` as in
    /// [`d_visible`](Self::d_visible). Always returns a unit vector with `m.z ≥ 0`.
    #[must_use]
    fn sample(&self, w: Vec3, u: Vec2) -> Vec3;

    /// The density of [`sample`](Self::sample), in solid angle of `m`.
    #[must_use]
    fn pdf(&self, w: Vec3, m: Vec3) -> f32;

    /// [`pdf`](Self::pdf) when `d = D(m)` is already known. The default evaluates `pdf`
    /// (and so `D`) again; the crate's distributions use `d`.
    #[inline]
    #[must_use]
    fn pdf_given_d(&self, w: Vec3, m: Vec3, d: f32) -> f32 {
        let _ = d;
        self.pdf(w, m)
    }

    /// Draws a normal for *reflecting* `w` (`w` above the surface), with density
    /// [`pdf_reflection`](Self::pdf_reflection). The default is [`sample`](Self::sample);
    /// a distribution may instead skip normals that would reflect `w` below the horizon
    /// ([`Ggx`] uses Eto & Tokuyoshi's bounded sampler).
    #[inline]
    #[must_use]
    fn sample_reflection(&self, w: Vec3, u: Vec2) -> Vec3 {
        self.sample(w, u)
    }

    /// The density of [`sample_reflection`](Self::sample_reflection), in solid angle of `m`.
    #[inline]
    #[must_use]
    fn pdf_reflection(&self, w: Vec3, m: Vec3) -> f32 {
        self.pdf(w, m)
    }

    /// [`pdf_reflection`](Self::pdf_reflection) when `d = D(m)` is already known.
    #[inline]
    #[must_use]
    fn pdf_reflection_given_d(&self, w: Vec3, m: Vec3, d: f32) -> f32 {
        self.pdf_given_d(w, m, d)
    }

    /// Draws a microfacet normal with density `D(m) cos θm` (the classic sampler of Walter
    /// et al. 2007, §5.3, eq. 28's density), `u` uniform in `[0, 1)²`.
    #[must_use]
    fn sample_d_cos(&self, u: Vec2) -> Vec3;

    /// The density of [`sample_d_cos`](Self::sample_d_cos): `D(m) max(0, cos θm)`.
    #[inline]
    #[must_use]
    fn pdf_d_cos(&self, m: Vec3) -> f32 {
        self.d(m) * m.z.max(0.0)
    }
}

/// A distribution that can draw its visible normals exactly.
pub trait VisibleNormals: NormalDistribution {
    /// Draws `m` with density [`d_visible(w, m)`](NormalDistribution::d_visible), `u`
    /// uniform in `[0, 1)²`; `w` below the horizon is replaced by `−w` ([`upper`]).
    #[must_use]
    fn sample_visible(&self, w: Vec3, u: Vec2) -> Vec3;
}

/// `w` turned into the upper hemisphere: `−w` when `w.z < 0`, else `w`.
///
/// A direction below the macro-surface sees the microsurface from the inside, where the
/// visible microfacets are those that `−w` sees from the outside (pbrt-v4's and Mitsuba 3's
/// convention for refraction).
#[inline]
#[must_use]
pub fn upper(w: Vec3) -> Vec3 {
    if w.z < 0.0 { -w } else { w }
}
