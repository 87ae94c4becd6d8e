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
//! | [`Gtr`] | Burley's generalised Trowbridge-Reitz, `γ ∈ (0, 10]`, isotropic | exact Smith, tabulated at construction | `D cos θ` |
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
mod widths;

pub use beckmann::{Beckmann, BeckmannMasking};
#[cfg(feature = "serde")]
pub(crate) use blinn_phong::BLINN_PHONG_ALPHA;
pub use blinn_phong::BlinnPhongNdf;
pub use ggx::Ggx;
pub use gtr::Gtr;
pub use masking::{Masking, v_cavity};
pub(crate) use smith_table::{catmull_rom, projected_area};
use widths::Widths;

use glam::{Vec2, Vec3};

/// The density a distribution's [`sample`](NormalDistribution::sample) draws normals from,
/// which fixes its [`pdf`](NormalDistribution::pdf).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    /// The normals visible from the view, `D_w(m) = G1(w) max(0, w·m) D(m) / cos θw`
    /// (Heitz & d'Eon 2014, eq. 2): the better strategy, exact where the distribution can
    /// invert it (GGX, Beckmann).
    VisibleNormals,
    /// `D(m) cos θm`, which ignores the view (Walter et al. 2007, §5.3): the classic sampler,
    /// for distributions without a visible-normal sampler (GTR, Blinn-Phong).
    DCos,
}

/// What a distribution computes once about a direction `w` and reuses for every normal it
/// evaluates or draws against it: a model prepares one for `wo` per shading point.
///
/// Built by [`NormalDistribution::view`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// The direction turned into the upper hemisphere ([`upper`]).
    pub w: Vec3,
    /// Smith's `Λ(w)` (and `G1(w) = 1 / (1 + Λ(w))`).
    pub lambda: f32,
    /// `G1(w) / cos θw` with the distribution's exact Smith `G1`, the view's factor in the
    /// visible-normal density; `0` for a tangent `w`. It has a finite limit at grazing, so it
    /// is kept rather than the two factors. For a masking that approximates `G1`
    /// ([`BeckmannMasking::WalterRational`]) it is the exact one's, which normalises the
    /// density the sampler draws, while `lambda` is the approximation's.
    pub visible: f32,
    /// Room for what the distribution's own sampler keeps about `w` ([`Ggx`]: its stretched
    /// view and bounded cap; [`Beckmann`]: the view's stretched tangent part and its
    /// length), written and read by the distribution alone; zero otherwise.
    pub extra: [f32; 6],
}

impl View {
    /// The view of `w` (already in the upper hemisphere) with Smith's `Λ(w)` and the
    /// distribution's own `extra`: the visible-normal factor `G1/cos θ = 1/((1 + Λ) cos θ)`
    /// is finite as `cos θ → 0`, where `Λ` grows as `1/cos θ`, and `0` for a tangent `w`.
    #[inline(always)]
    #[must_use]
    pub(crate) fn with_lambda(w: Vec3, lambda: f32, extra: [f32; 6]) -> Self {
        Self {
            w,
            lambda,
            visible: Self::visible_factor(w, lambda),
            extra,
        }
    }

    /// The visible-normal factor `1/((1 + Λ) cos θ)` of `w` (in the upper hemisphere) with
    /// Smith's `Λ(w)`; `0` for a tangent `w`.
    #[inline(always)]
    #[must_use]
    pub(crate) fn visible_factor(w: Vec3, lambda: f32) -> f32 {
        if w.z > 0.0 {
            1.0 / ((1.0 + lambda) * w.z)
        } else {
            0.0
        }
    }

    /// The density of the normals visible from the view, given `d = D(m)`:
    /// `D_w(m) = G1(w) max(0, w·m) D(m) / cos θw` (Heitz & d'Eon 2014, eq. 2).
    #[inline(always)]
    #[must_use]
    pub fn visible_density(&self, m: Vec3, d: f32) -> f32 {
        let wm = self.w.dot(m);
        if wm > 0.0 { self.visible * wm * d } else { 0.0 }
    }
}

/// A microfacet normal distribution with Smith masking.
///
/// Directions are local (`z` the macro-surface normal) and unit length. `m` is a
/// microfacet normal; `w` a direction away from the surface.
///
/// **What an implementation writes.** `D` ([`d`](Self::d)), Smith's `Λ`
/// ([`lambda`](Self::lambda)), a sampler of normals ([`sample`](Self::sample)) and which
/// density it draws from ([`sampling`](Self::sampling)). Everything else — `G1`, `G2`, the
/// visible normals, the sampler's density — follows, and the crate's models
/// ([`Microfacet`](crate::bxdf::Microfacet), [`RoughDielectric`](crate::bxdf::RoughDielectric),
/// [`Plastic`](crate::bxdf::Plastic)) are then correct and fast for it: they prepare a
/// [`View`] of `wo` once and evaluate `D` once per direction. The other methods are
/// shortcuts a distribution may take where its formulas allow, each documented with the
/// result it must keep: a sampler with per-view set-up overrides [`view`](Self::view) and
/// keeps it in [`View::extra`]; [`Ggx`] also overrides `d_unnormalized`, `g1`, `visibility`,
/// `sample_reflection`, `sample_reflected` and `pdf_reflection`, [`Beckmann`]
/// `d_unnormalized`, `g1` and `sample_reflected`. Derive `Clone` (and `Copy`,
/// if it holds only numbers) as well: the models' batched calls
/// ([`Batch`](crate::batch::Batch)) clone the model, distribution included.
///
/// **The prepared view.** Everything that depends on the direction alone (`Λ(w)`,
/// the visible-normal factor, the sampler's set-up) is computed once by [`view`](Self::view)
/// and passed to [`sample`](Self::sample) and [`pdf`](Self::pdf); the densities take `D(m)`
/// from the caller, who has evaluated it for the value already.
///
/// A distribution of your own, with `D`, `Λ` and a sampler only (here the uniform
/// distribution `D = 1/π`, whose Smith `Λ(w) = (1 − cos θ)/(2 cos θ)` follows from its projected
/// area `(1 + cos θ)/2`), checked like the crate's own:
///
/// ```
/// use lobe::microfacet::{NormalDistribution, Sampling, View};
/// use lobe::sampling::cosine_hemisphere;
/// use lobe::{Vec2, Vec3};
///
/// #[derive(Clone, Copy)] // `Clone` lets the models built on it run batched (`lobe::batch`)
/// struct Uniform;
///
/// impl NormalDistribution for Uniform {
///     fn sampling(&self) -> Sampling {
///         Sampling::DCos
///     }
///     fn d(&self, m: Vec3) -> f32 {
///         if m.z > 0.0 { core::f32::consts::FRAC_1_PI } else { 0.0 }
///     }
///     fn lambda(&self, w: Vec3) -> f32 {
///         let c = w.z.abs();
///         (1.0 - c) / (2.0 * c)
///     }
///     fn sample(&self, _view: &View, u: Vec2) -> Vec3 {
///         cosine_hemisphere(u) // density D(m) cos θm = cos θm / π
///     }
/// }
///
/// let uniform = Uniform;
/// let wo = Vec3::new(0.6, 0.0, 0.8);
/// let view = uniform.view(wo);
/// let m = uniform.sample(&view, Vec2::new(0.3, 0.6));
/// assert!((uniform.pdf(&view, m, uniform.d(m)) - m.z / core::f32::consts::PI).abs() < 1e-6);
///
/// // Its laws (normalisation, projected area, visible normals, the sampler against its
/// // density), and the laws of the Cook-Torrance model built on it, measured like the
/// // crate's own (a small budget, to keep the example quick):
/// use lobe::bxdf::Microfacet;
/// use lobe::fresnel::NoFresnel;
/// use lobe::microfacet::Masking;
/// use lobe::verify::{check_bxdf, check_ndf, Config};
/// let config = Config {
///     integral_samples: 40_000,
///     albedo_samples: 20_000,
///     chi2_samples: 40_000,
///     pairs: 1_000,
///     consistency_samples: 1_000,
///     ..Config::default()
/// };
/// let report = check_ndf("uniform", &uniform, &config);
/// assert!(report.passed(), "{report}");
/// let brdf = Microfacet::new(Uniform, Masking::HeightCorrelated, NoFresnel::<f32>::new());
/// let report = check_bxdf("uniform microfacets", &brdf, &config);
/// assert!(report.passed(), "{report}");
/// ```
pub trait NormalDistribution {
    /// The distribution of normals `D(m)`, normalised so that `∫ D(m) cos θm dωm = 1`;
    /// zero for `m.z ≤ 0`.
    #[must_use]
    fn d(&self, m: Vec3) -> f32;

    /// `D` at the unit normal `s / |s|`, given a non-zero `s` with `s2 = |s|²`: what a model
    /// holds after adding two directions, before normalising their half vector. The default
    /// normalises; a distribution homogeneous in `m` skips the square root and the division
    /// ([`Ggx`]: `D = c / t(s/|s|)² = c (|s|² / t(s))²`).
    #[inline(always)]
    #[must_use]
    fn d_unnormalized(&self, s: Vec3, s2: f32) -> f32 {
        self.d(s / crate::math::sqrt(s2))
    }

    /// Smith's auxiliary function `Λ(w)`, with `G1(w) = 1 / (1 + Λ(w))`.
    ///
    /// Depends on `w` only through `tan² θ` and `φ`, so `Λ(w) = Λ(x, y, −z)`. `0` along the
    /// normal, `+∞` in the tangent plane.
    #[must_use]
    fn lambda(&self, w: Vec3) -> f32;

    /// The density [`sample`](Self::sample) draws from.
    #[must_use]
    fn sampling(&self) -> Sampling;

    /// Draws a microfacet normal for the view `view` with the density named by
    /// [`sampling`](Self::sampling), `u` uniform in `[0, 1)²`. Always returns a unit vector
    /// with `m.z ≥ 0`. The view's `w` is above the horizon ([`upper`]): a refracting model
    /// sees the surface from either side.
    #[must_use]
    fn sample(&self, view: &View, u: Vec2) -> Vec3;

    /// Smith's masking function `G1(w) = 1 / (1 + Λ(w))`, without the microfacet-side
    /// factor `χ⁺(w·m)`, which the caller applies.
    #[inline(always)]
    #[must_use]
    fn g1(&self, w: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(w))
    }

    /// Height-correlated masking-shadowing `G2 = 1 / (1 + Λ(wo) + Λ(wi))` (Heitz 2014,
    /// eq. 99), the physically preferred form; without the `χ⁺` factors.
    #[inline(always)]
    #[must_use]
    fn g2(&self, wo: Vec3, wi: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(wo) + self.lambda(wi))
    }

    /// Separable masking-shadowing `G2 = G1(wo) G1(wi)` (Heitz 2014, eq. 98), which counts
    /// a microfacet hidden from both directions twice and so is never above [`g2`](Self::g2).
    #[inline(always)]
    #[must_use]
    fn g2_separable(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.g1(wo) * self.g1(wi)
    }

    /// The height-correlated masking-shadowing term over the model's cosines,
    /// `V = G2(w, wi) / (4 |cos θw| |cos θi|)` with `G2 = 1 / (1 + Λ(w) + Λ(wi))` (Heitz 2014,
    /// eq. 99), for the view's `w` and a direction `wi`: the factor of a microfacet model's
    /// value that depends on the two directions alone (the "visibility" of real-time
    /// renderers). For `|cos θw cos θi|` above `f32::MIN_POSITIVE`.
    ///
    /// A distribution with a closed-form `Λ` can fold the division into one ([`Ggx`]:
    /// `V = 1 / (2 (Lw |cos θi| + Li |cos θw|))`, `L = |(αx x, αy y, z)|`).
    #[inline(always)]
    #[must_use]
    fn visibility(&self, view: &View, wi: Vec3) -> f32 {
        1.0 / ((1.0 + view.lambda + self.lambda(wi)) * 4.0 * view.w.z * wi.z.abs())
    }

    /// The view of `w`: what the densities and the sampler need about it, computed once.
    /// `w` below the horizon is first replaced by `−w` ([`upper`]).
    #[inline(always)]
    #[must_use]
    fn view(&self, w: Vec3) -> View {
        let w = upper(w);
        View::with_lambda(w, self.lambda(w), [0.0; 6])
    }

    /// The distribution of normals visible from `w` (Heitz & d'Eon 2014, eq. 2):
    /// `D_w(m) = G1(w) max(0, w·m) D(m) / cos θw`, a density in `m` that integrates to 1.
    ///
    /// `w` below the horizon is first replaced by `−w` ([`upper`]), the convention of
    /// [`view`](Self::view). (A model holds a view and calls [`View::visible_density`].)
    #[inline(always)]
    #[must_use]
    fn d_visible(&self, w: Vec3, m: Vec3) -> f32 {
        self.view(w).visible_density(m, self.d(m))
    }

    /// The density of [`sample`](Self::sample) at `m`, in solid angle of `m`, given
    /// `d = D(m)` (which the caller has evaluated for its value already): the visible normals
    /// [`View::visible_density`] or `D(m) max(0, cos θm)`, as [`sampling`](Self::sampling) says.
    #[inline(always)]
    #[must_use]
    fn pdf(&self, view: &View, m: Vec3, d: f32) -> f32 {
        match self.sampling() {
            Sampling::VisibleNormals => view.visible_density(m, d),
            Sampling::DCos => d * m.z.max(0.0),
        }
    }

    /// Draws a normal for *reflecting* the view's `w`, with density
    /// [`pdf_reflection`](Self::pdf_reflection). The default is [`sample`](Self::sample); a
    /// distribution may instead skip normals that would reflect `w` below the horizon
    /// ([`Ggx`] uses Eto & Tokuyoshi's bounded sampler).
    #[inline(always)]
    #[must_use]
    fn sample_reflection(&self, view: &View, u: Vec2) -> Vec3 {
        self.sample(view, u)
    }

    /// The view's `w` reflected about a normal drawn by
    /// [`sample_reflection`](Self::sample_reflection) for `u`: `2 (w·m) m − w`, possibly below
    /// the horizon (a reflection model refuses it there), with the density
    /// [`pdf_reflection`](Self::pdf_reflection) gives. The default reflects about the unit
    /// normal; a sampler that ends by normalising may instead reflect about the normal it
    /// had before, with [`reflect_about`](crate::frame::reflect_about): one division in
    /// place of a square root and a division, the same direction to `f32` round-off
    /// ([`Ggx`] and [`Beckmann`] do).
    #[inline(always)]
    #[must_use]
    fn sample_reflected(&self, view: &View, u: Vec2) -> Vec3 {
        crate::frame::reflect_away(view.w, self.sample_reflection(view, u))
    }

    /// The density, in solid angle of `wi`, of the direction `wi = 2 (w·m) m − w` reflected
    /// about a normal `m` drawn by [`sample_reflection`](Self::sample_reflection), given
    /// `d = D(m)` (`m` may be any positive multiple of the unit normal: the density depends on
    /// its direction only): the normal's density times the reflection's Jacobian `1 / (4 w·m)` (Walter
    /// et al. 2007, eq. 14), for an `m` that reflects the view's `w` *above* the horizon — the
    /// only normals for which a reflection model has a value. (A bounded sampler's density of
    /// normals that reflect below can be zero where this is not: [`Ggx::d_visible_bounded`]
    /// is exact everywhere.)
    ///
    /// For visible normals the `w·m` of the density cancels the Jacobian's:
    /// `D_w(m) / (4 w·m) = G1(w) D(m) / (4 cos θw)`.
    #[inline(always)]
    #[must_use]
    fn pdf_reflection(&self, view: &View, m: Vec3, d: f32) -> f32 {
        let wm = view.w.dot(m);
        if !(wm > 0.0) {
            return 0.0;
        }
        match self.sampling() {
            Sampling::VisibleNormals => 0.25 * view.visible * d,
            Sampling::DCos => d * m.z.max(0.0) / (4.0 * wm),
        }
    }
}

/// A distribution that can draw normals with density `D(m) cos θm`, the classic sampler of
/// Walter et al. (2007, §5.3), which ignores the view. The distributions without a
/// visible-normal sampler use it as their [`sample`](NormalDistribution::sample); for GGX and
/// Beckmann it is the alternative the visible normals improve on.
pub trait SampleDCos: NormalDistribution {
    /// Draws a microfacet normal with density [`pdf_d_cos`](Self::pdf_d_cos), `u` uniform in
    /// `[0, 1)²`.
    #[must_use]
    fn sample_d_cos(&self, u: Vec2) -> Vec3;

    /// The density of [`sample_d_cos`](Self::sample_d_cos): `D(m) max(0, cos θm)`.
    #[inline(always)]
    #[must_use]
    fn pdf_d_cos(&self, m: Vec3) -> f32 {
        self.d(m) * m.z.max(0.0)
    }
}

/// `w` turned into the upper hemisphere: `−w` when `w.z < 0`, else `w`.
///
/// A direction below the macro-surface sees the microsurface from the inside, where the
/// visible microfacets are those that `−w` sees from the outside (pbrt-v4's and Mitsuba 3's
/// convention for refraction).
#[inline(always)]
#[must_use]
pub fn upper(w: Vec3) -> Vec3 {
    if w.z < 0.0 { -w } else { w }
}
