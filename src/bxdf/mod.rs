//! BRDF and BSDF models behind one interface, [`Bxdf`].
//!
//! Every model works in the local shading frame (`z` the shading normal) with unit
//! directions: `wo` toward the viewer, `wi` toward the light, both pointing away from the
//! surface (pbrt-v4's convention). The vocabulary is yocto-gl's: [`Bxdf::eval`] the BSDF value
//! `f(wo, wi)` *without* the cosine, [`Bxdf::sample`] a direction `wi` with random numbers the
//! caller passes in, [`Bxdf::pdf`] its solid-angle density.
//!
//! **Delta lobes.** A perfectly specular lobe (a mirror, smooth glass) has no density: `eval`
//! and `pdf` return zero for it, and only `sample` reaches it, with the lobe flagged
//! [`Lobes::SPECULAR`]. Its `f` is then the delta's coefficient divided by `|cos θi|` and its
//! `pdf` the probability of choosing it, so that [`BxdfSample::weight`] is the same formula
//! for every lobe.
//!
//! **Sides.** Reflection-only models are one-sided: `f = 0` unless `wo.z > 0` and `wi.z > 0`.
//! A renderer that shades both sides of a surface flips its shading frame toward `wo`.
//! Transmissive models take `wo` on either side; the relative index `eta` is
//! `η_inside / η_outside` with the normal pointing outside.
//!
//! ## The hot path: prepared state
//!
//! A renderer evaluates many `wi` against one `wo`: every light of next-event estimation, the
//! MIS partner of the BSDF's own sample, the sample itself. What depends on `wo` alone is
//! computed once, not once per call:
//!
//! * **Distribution layer.** [`NormalDistribution::view`](crate::microfacet::NormalDistribution::view)
//!   turns a direction into a [`View`](crate::microfacet::View): `Λ(w)`, the visible-normal
//!   factor `G1(w)/cos θ`, and what the distribution's sampler keeps (GGX: the stretched
//!   view, the bounded-VNDF cap, the reflection density's factor, `|(αx wx, αy wy, wz)|`).
//!   Its densities take `D(m)` from the caller, who evaluated it for the value already.
//! * **Model layer.** [`Prepare::prepare`] holds `wo` and the model's own state in an
//!   [`At`] (a microfacet model: the distribution's view of `wo`; [`Plastic`]: that and its
//!   coat's albedo at `wo`; [`Glazed`]: the coat's Fresnel at `wo`), and the
//!   `*_prepared` calls reuse it. [`Prepare::eval_pdf_prepared`] gives a light sample's value
//!   and density for one `D`; [`Prepare::sample_prepared`] returns the value and density it
//!   computed on the way.
//! * **Plain calls.** Every `Prepare` model is a [`Bxdf`], whose `eval(wo, wi)` is
//!   `eval_prepared(&prepare(wo), wi)`: the same numbers, bit for bit. For a single call the
//!   compiler inlines both and drops what the call does not use (`eval` never computes the
//!   sampler's cap).
//! * **Batches.** [`crate::batch`] runs the same prepared calls over slices, vectorised.
//!
//! The layers stay one-way: a model calls its distribution's view and densities, never the
//! reverse, and the batched loops call the models.
//!
//! ```
//! use lobe::bxdf::{Microfacet, Prepare};
//! use lobe::fresnel::Conductor;
//! use lobe::microfacet::{Ggx, Masking};
//! use lobe::{metals, Alpha, Vec2, Vec3};
//! let gold = Microfacet::new(
//!     Ggx::isotropic(Alpha::new(0.3)?),
//!     Masking::HeightCorrelated,
//!     Conductor { ior: metals::GOLD.rgb() },
//! );
//! let wo = Vec3::new(0.0, 0.6, 0.8);
//! let at = gold.prepare(wo); // once per shading point
//! let lights = [Vec3::new(0.0, -0.6, 0.8), Vec3::new(0.6, 0.0, 0.8)];
//! let direct: Vec3 = lights
//!     .iter()
//!     .map(|&wi| {
//!         let (f, _pdf) = gold.eval_pdf_prepared(&at, wi); // value and MIS density, one D
//!         f * wi.z
//!     })
//!     .sum();
//! let bounce = gold.sample_prepared(&at, Vec2::new(0.25, 0.75), 0.5);
//! assert!(direct.x > 0.0 && bounce.is_some());
//! # Ok::<(), lobe::ParamError>(())
//! ```

/// The [`Prepare`] impl of a model with delta lobes only (a mirror, smooth glass, a thin
/// sheet): it prepares `wo` alone, `eval` and `pdf` are zero, and `sample` is the model's own
/// `fn sample_delta(&self, wo: Vec3, uc: f32) -> Option<BxdfSample<S>>`.
macro_rules! delta_model {
    (impl$(<$g:ident: $b:path>)? for $t:ty, spectrum $s:ty, lobes $lobes:expr) => {
        impl$(<$g: $b>)? $crate::bxdf::Prepare for $t {
            type Spectrum = $s;
            type Prepared = glam::Vec3;

            #[inline(always)]
            fn prepare(&self, wo: glam::Vec3) -> glam::Vec3 {
                wo
            }

            #[inline(always)]
            fn eval_prepared(&self, _wo: &glam::Vec3, _wi: glam::Vec3) -> $s {
                <$s as $crate::spectrum::Spectrum>::zero()
            }

            #[inline(always)]
            fn pdf_prepared(&self, _wo: &glam::Vec3, _wi: glam::Vec3) -> f32 {
                0.0
            }

            #[inline(always)]
            fn sample_prepared(
                &self,
                &wo: &glam::Vec3,
                _u: glam::Vec2,
                uc: f32,
            ) -> Option<$crate::bxdf::BxdfSample<$s>> {
                self.sample_delta(wo, uc)
            }

            #[inline]
            fn lobes(&self) -> $crate::bxdf::Lobes {
                $lobes
            }
        }
    };
}

/// The [`Prepare`] impl of a Phong-family model (`diffuse_glossy.rs`): a one-sided mixture of
/// a cosine-sampled diffuse lobe, chosen with probability `self.p_diffuse`, and a glossy lobe.
/// The model supplies `fn lobe(&self, wo, wi) -> L` (what value and density share, evaluated
/// once), `fn value(&self, L) -> S`, `fn density(&self, cos θi, L) -> f32`, the glossy sampler
/// `fn sample_glossy(&self, wo, u) -> Vec3` and the weights `kd`, `ks`.
macro_rules! diffuse_glossy_model {
    ($t:ident) => {
        impl<S: $crate::spectrum::Spectrum> $crate::bxdf::Prepare for $t<S> {
            type Spectrum = S;
            type Prepared = glam::Vec3;

            #[inline]
            fn prepare(&self, wo: glam::Vec3) -> glam::Vec3 {
                wo
            }

            #[inline(always)]
            fn eval_prepared(&self, &wo: &glam::Vec3, wi: glam::Vec3) -> S {
                self.eval_pdf_prepared(&wo, wi).0
            }

            #[inline(always)]
            fn pdf_prepared(&self, &wo: &glam::Vec3, wi: glam::Vec3) -> f32 {
                self.eval_pdf_prepared(&wo, wi).1
            }

            #[inline(always)]
            fn eval_pdf_prepared(&self, &wo: &glam::Vec3, wi: glam::Vec3) -> (S, f32) {
                if $crate::bxdf::both_above(wo, wi) {
                    // One evaluation of the lobe serves both.
                    let lobe = self.lobe(wo, wi);
                    (self.value(lobe), self.density(wi.z, lobe))
                } else {
                    (S::zero(), 0.0)
                }
            }

            #[inline]
            fn sample_prepared(
                &self,
                &wo: &glam::Vec3,
                u: glam::Vec2,
                uc: f32,
            ) -> Option<$crate::bxdf::BxdfSample<S>> {
                use $crate::bxdf::Lobes;
                if !(wo.z > 0.0) {
                    return None;
                }
                let (wi, kind) = if $crate::sampling::picks(uc, self.p_diffuse) {
                    (
                        $crate::sampling::cosine_hemisphere(u),
                        Lobes::DIFFUSE_REFLECTION,
                    )
                } else {
                    (self.sample_glossy(wo, u), Lobes::GLOSSY_REFLECTION)
                };
                // Also catches a glossy direction turned below the surface.
                if !(wi.z > 0.0) {
                    return None;
                }
                let lobe = self.lobe(wo, wi);
                let pdf = self.density(wi.z, lobe);
                $crate::bxdf::usable_pdf(pdf)
                    .then(|| $crate::bxdf::BxdfSample::new(wi, self.value(lobe), pdf, kind))
            }

            #[inline]
            fn lobes(&self) -> $crate::bxdf::Lobes {
                $crate::bxdf::diffuse_glossy::weighted_lobes(self.kd, self.ks)
            }
        }
    };
}

mod blinn_phong;
mod coated_conductor;
mod coated_diffuse;
mod compensated;
mod compensated_dielectric;
mod diffuse_glossy;
mod diffuse_transmission;
mod disney_diffuse;
mod eon;
mod glazed;
mod henyey_greenstein;
mod lambert;
mod layer_interface;
pub(crate) mod layered;
mod microfacet;
mod mirror;
mod mix;
mod mono;
mod oren_nayar;
mod phong;
mod plastic;
mod rough_dielectric;
mod sheen;
mod smooth_dielectric;
mod thin_dielectric;
mod two_sided;
mod walk_rng;

pub use blinn_phong::{BlinnPhong, BlinnPhongForm};
pub use coated_conductor::CoatedConductor;
pub use coated_diffuse::CoatedDiffuse;
pub use compensated::{CompensatedMicrofacet, CompensatedState, Compensation};
pub use compensated_dielectric::CompensatedDielectric;
pub use diffuse_transmission::DiffuseTransmission;
pub use disney_diffuse::DisneyDiffuse;
pub use eon::EnergyPreservingOrenNayar;
pub(crate) use eon::FixedForm;
pub use glazed::Glazed;
pub use lambert::Lambert;
pub use layer_interface::LayerInterface;
pub use layered::Layered;
pub use microfacet::{Microfacet, RoughConductor};
pub use mirror::Mirror;
pub use mix::Mix;
pub use mono::Mono;
pub use oren_nayar::OrenNayar;
pub use phong::Phong;
pub use plastic::{CompensatedPlastic, Plastic, PlasticState};
pub use rough_dielectric::RoughDielectric;
pub use sheen::Sheen;
pub use smooth_dielectric::SmoothDielectric;
pub use thin_dielectric::ThinDielectric;
pub use two_sided::TwoSided;

use crate::spectrum::Spectrum;
use core::fmt;
use core::ops::{BitOr, BitOrAssign};
use glam::{Vec2, Vec3};

/// A set of lobe kinds: reflection or transmission, crossed with diffuse, glossy or
/// specular (delta).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Lobes(u8);

impl Lobes {
    /// No lobe.
    pub const NONE: Self = Self(0);
    /// Light leaves on the side it arrived from.
    pub const REFLECTION: Self = Self(1);
    /// Light crosses the surface.
    pub const TRANSMISSION: Self = Self(1 << 1);
    /// A smooth, wide lobe (Lambert, Oren-Nayar).
    pub const DIFFUSE: Self = Self(1 << 2);
    /// A lobe with a density, concentrated around a direction (microfacet, Phong).
    pub const GLOSSY: Self = Self(1 << 3);
    /// A delta lobe: reached only through [`Bxdf::sample`].
    pub const SPECULAR: Self = Self(1 << 4);
    /// Diffuse reflection.
    pub const DIFFUSE_REFLECTION: Self = Self(Self::DIFFUSE.0 | Self::REFLECTION.0);
    /// Glossy reflection.
    pub const GLOSSY_REFLECTION: Self = Self(Self::GLOSSY.0 | Self::REFLECTION.0);
    /// Glossy transmission.
    pub const GLOSSY_TRANSMISSION: Self = Self(Self::GLOSSY.0 | Self::TRANSMISSION.0);
    /// Specular reflection.
    pub const SPECULAR_REFLECTION: Self = Self(Self::SPECULAR.0 | Self::REFLECTION.0);
    /// Specular transmission.
    pub const SPECULAR_TRANSMISSION: Self = Self(Self::SPECULAR.0 | Self::TRANSMISSION.0);

    /// True when every kind in `other` is in `self`.
    #[inline(always)]
    #[must_use]
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// True when `self` and `other` share a kind.
    #[inline(always)]
    #[must_use]
    pub const fn intersects(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }

    /// True when the set has a delta lobe.
    #[inline(always)]
    #[must_use]
    pub const fn is_specular(self) -> bool {
        self.intersects(Self::SPECULAR)
    }

    /// True when the set has a lobe with a density (diffuse or glossy).
    #[inline(always)]
    #[must_use]
    pub const fn is_non_specular(self) -> bool {
        self.intersects(Self(Self::DIFFUSE.0 | Self::GLOSSY.0))
    }

    /// True when the set reflects.
    #[inline(always)]
    #[must_use]
    pub const fn is_reflective(self) -> bool {
        self.intersects(Self::REFLECTION)
    }

    /// True when the set transmits.
    #[inline(always)]
    #[must_use]
    pub const fn is_transmissive(self) -> bool {
        self.intersects(Self::TRANSMISSION)
    }
}

impl BitOr for Lobes {
    type Output = Self;
    #[inline(always)]
    fn bitor(self, rhs: Self) -> Self {
        Self(self.0 | rhs.0)
    }
}

impl BitOrAssign for Lobes {
    #[inline(always)]
    fn bitor_assign(&mut self, rhs: Self) {
        self.0 |= rhs.0;
    }
}

impl fmt::Display for Lobes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = [
            (Self::REFLECTION, "reflection"),
            (Self::TRANSMISSION, "transmission"),
            (Self::DIFFUSE, "diffuse"),
            (Self::GLOSSY, "glossy"),
            (Self::SPECULAR, "specular"),
        ];
        let mut first = true;
        for (lobe, name) in names {
            if self.contains(lobe) {
                if !first {
                    f.write_str(" ")?;
                }
                f.write_str(name)?;
                first = false;
            }
        }
        if first {
            f.write_str("none")?;
        }
        Ok(())
    }
}

/// Whether a BSDF transports radiance (from lights, a camera path) or importance (from the
/// camera, a light path). Only refraction cares: radiance crossing an interface is scaled by
/// `(η_i/η_t)²`, importance is not (Veach 1997, §5.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TransportMode {
    /// Paths traced from the camera (the usual case).
    #[default]
    Radiance,
    /// Paths traced from the lights.
    Importance,
}

/// A direction drawn by [`Bxdf::sample`], with what a renderer needs to weigh it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BxdfSample<S> {
    /// The sampled direction toward the light, unit, local frame.
    pub wi: Vec3,
    /// The BSDF value `f(wo, wi)` (for a delta lobe, its coefficient over `|cos θi|`).
    pub f: S,
    /// The solid-angle density of `wi` (for a delta lobe, the probability of choosing it).
    pub pdf: f32,
    /// The lobe the sample came from: one of reflection/transmission and one of
    /// diffuse/glossy/specular, never [`Lobes::NONE`] (the batched calls mark a lane without a
    /// sample with it, and the batched `Mix` and `TwoSided` read their parts' lanes so).
    pub lobe: Lobes,
    /// The relative index `η_t/η_i` the path crossed, `1` for reflection.
    pub eta: f32,
}

impl<S> BxdfSample<S> {
    /// A sample of `wi` with value `f` and density `pdf` from a lobe of kind `lobe` that does
    /// not refract (`eta = 1`: reflection, or transmission without a change of medium); a
    /// refracting model sets [`eta`](Self::eta) after.
    #[inline(always)]
    #[must_use]
    pub fn new(wi: Vec3, f: S, pdf: f32, lobe: Lobes) -> Self {
        Self {
            wi,
            f,
            pdf,
            lobe,
            eta: 1.0,
        }
    }
}

impl<S: Spectrum> BxdfSample<S> {
    /// The throughput weight `f |cos θi| / pdf` a path tracer multiplies by.
    #[inline(always)]
    #[must_use]
    pub fn weight(&self) -> S {
        self.f * (self.wi.z.abs() / self.pdf)
    }

    /// True when the sample came from a delta lobe.
    #[inline(always)]
    #[must_use]
    pub fn is_specular(&self) -> bool {
        self.lobe.is_specular()
    }
}

/// What a model keeps about `wo` between [`Prepare::prepare`] and the `*_prepared` calls:
/// `wo` itself and the model's own state (for a microfacet model, the distribution's
/// [`View`](crate::microfacet::View) of `wo`). Built only by the models.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct At<V> {
    pub(crate) wo: Vec3,
    pub(crate) state: V,
}

impl At<crate::microfacet::View> {
    /// `wo` and the distribution's view of it: what a microfacet model prepares.
    #[inline(always)]
    pub(crate) fn view<D: crate::microfacet::NormalDistribution + ?Sized>(
        dist: &D,
        wo: Vec3,
    ) -> Self {
        Self {
            wo,
            state: dist.view(wo),
        }
    }
}

impl<V> At<V> {
    /// The prepared viewer direction.
    #[inline(always)]
    #[must_use]
    pub fn wo(&self) -> Vec3 {
        self.wo
    }
}

/// A BRDF or BSDF in the local shading frame.
///
/// Implementations are total: for any finite unit `wo`, `wi` and `u ∈ [0, 1]²`, `uc ∈ [0, 1]`,
/// `eval` is finite and non-negative, `pdf` finite and non-negative, and `sample` returns
/// either `None` or a sample with a unit `wi`, a finite non-negative `f` and a positive finite
/// `pdf`. The crate's models check the unit lengths and the random numbers' range with
/// `debug_assert!` in debug builds; release builds check nothing and stay total.
///
/// The crate's models implement [`Prepare`], which gives them this trait; implement it
/// directly for a model of your own (or implement [`Prepare`], or [`CosineSampled`] for a
/// diffuse one, and get it).
pub trait Bxdf {
    /// The carrier of the BSDF's values: `f32`, RGB `Vec3` or four wavelengths `Vec4`.
    type Spectrum: Spectrum;

    /// The BSDF value `f(wo, wi)`, without the cosine; zero for delta lobes.
    #[must_use]
    fn eval(&self, wo: Vec3, wi: Vec3) -> Self::Spectrum;

    /// Draws `wi` for the viewer direction `wo`, with `u` uniform in `[0, 1)²` for the
    /// direction and `uc` uniform in `[0, 1)` for the choice of lobe (the crate's models read
    /// `uc = 1` as the largest `f32` below 1); `None` when no direction can be produced (the
    /// pdf's missing mass).
    #[must_use]
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<Self::Spectrum>>;

    /// The solid-angle density with which [`sample`](Self::sample) produces `wi`, over its
    /// non-delta lobes.
    #[must_use]
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32;

    /// The kinds of lobe the model has.
    #[must_use]
    fn lobes(&self) -> Lobes;

    /// True when the model's `eval` and `pdf` are Monte Carlo estimates (a stochastic layered
    /// BSDF, [`Layered`]; a combinator of one), false (the default) when they are exact.
    ///
    /// A stochastic model is deterministic for given inputs — its estimators draw from a
    /// generator seeded with a hash of the arguments —, so two calls with the same arguments
    /// agree; [`eval_seeded`](Self::eval_seeded) and [`pdf_seeded`](Self::pdf_seeded) give
    /// independent estimates, one per seed, whose expectation is the BSDF's value and
    /// density. Its laws hold in expectation, and
    /// [`verify::check_bxdf`](crate::verify::check_bxdf) checks them so when this says so.
    /// For such a model a [`BxdfSample`]'s [`weight`](BxdfSample::weight) is the random walk's
    /// unbiased weight, its `pdf` an independent estimate of the density at its direction
    /// (the kind of number [`pdf`](Self::pdf) returns, for multiple importance sampling) and
    /// its `f` the value that makes `f |cos θi| / pdf` that weight; so MIS code written for
    /// exact models works unchanged (pbrt-v4 returns the path's density instead and flags it
    /// `pdfIsProportional`, leaving the renderer to call `pdf`).
    ///
    /// A provided method: an exact model, the crate's or a user's, need not mention it.
    #[inline(always)]
    #[must_use]
    fn stochastic(&self) -> bool {
        false
    }

    /// [`eval`](Self::eval) as the estimate numbered `seed`: for a
    /// [`stochastic`](Self::stochastic) model, estimates with different seeds are independent
    /// and share the expectation `f(wo, wi)` (the crate's models: `eval(wo, wi)` is
    /// `eval_seeded(wo, wi, 0)`). The default, for an exact model, ignores the seed and
    /// returns `eval(wo, wi)`.
    ///
    /// Independent means it: hash the seed and the arguments together into the generator's
    /// *seed* (the crate's models fold them through a 64-bit mixer). A PCG generator whose
    /// *stream* was taken from the direction's bits gave estimates at neighbouring directions
    /// that were not independent, and `verify`'s in-expectation checks judged a correct model
    /// on that correlated noise: its p-values crowded toward 0 (`tests/verify_power.rs`).
    #[inline(always)]
    #[must_use]
    fn eval_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> Self::Spectrum {
        let _ = seed;
        self.eval(wo, wi)
    }

    /// [`pdf`](Self::pdf) as the estimate numbered `seed`, like
    /// [`eval_seeded`](Self::eval_seeded): independent estimates of the density of
    /// [`sample`](Self::sample)'s directions for a stochastic model, `pdf(wo, wi)` itself
    /// (the default) for an exact one.
    #[inline(always)]
    #[must_use]
    fn pdf_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> f32 {
        let _ = seed;
        self.pdf(wo, wi)
    }
}

/// A BSDF that does the work depending on `wo` alone once per shading point.
///
/// A renderer evaluates many `wi` against one `wo`: each light, each MIS pair, the BSDF's own
/// sample. [`prepare`](Self::prepare) computes what depends on `wo` only — for a microfacet
/// model the distribution's [`View`](crate::microfacet::View) of `wo` (Smith's `Λ(wo)` and
/// `G1(wo)`, the visible-normal factor, GGX's stretched view and bounded cap) — into a small
/// `Copy` value, and the `*_prepared` calls reuse it. [`sample_prepared`](Self::sample_prepared)
/// returns the value and the density from what it computed on the way (one `D`, at
/// `wo + wi`, so that they are exactly what `eval` and `pdf` give), and [`eval_pdf_prepared`](Self::eval_pdf_prepared) gives a light sample's value
/// and density for one `D`.
///
/// Every type that implements it is a [`Bxdf`] whose `eval(wo, wi)` is
/// `eval_prepared(&prepare(wo), wi)`, and likewise for `pdf` and `sample`: the same numbers,
/// bit for bit, whichever way a renderer calls.
///
/// ```
/// use lobe::bxdf::{Bxdf, Microfacet, Prepare};
/// use lobe::fresnel::Schlick;
/// use lobe::microfacet::{Ggx, Masking};
/// use lobe::{Alpha, Vec2, Vec3};
/// let brdf = Microfacet::new(
///     Ggx::isotropic(Alpha::new(0.3)?),
///     Masking::HeightCorrelated,
///     Schlick::new(Vec3::new(0.95, 0.64, 0.54))?,
/// );
/// let wo = Vec3::new(0.0, 0.6, 0.8);
/// let at = brdf.prepare(wo); // once per shading point
/// for wi in [Vec3::new(0.0, -0.6, 0.8), Vec3::new(0.36, -0.48, 0.8)] {
///     let (f, pdf) = brdf.eval_pdf_prepared(&at, wi); // a light sample, one D
///     assert_eq!((f, pdf), (brdf.eval(wo, wi), brdf.pdf(wo, wi)));
/// }
/// let s = brdf.sample_prepared(&at, Vec2::new(0.4, 0.7), 0.5).unwrap();
/// // The sample's value and density are the ones `eval` and `pdf` find for its direction.
/// assert_eq!((s.f, s.pdf), brdf.eval_pdf_prepared(&at, s.wi));
/// # Ok::<(), lobe::ParamError>(())
/// ```
pub trait Prepare {
    /// The carrier of the BSDF's values.
    type Spectrum: Spectrum;

    /// What the model keeps about `wo`.
    type Prepared: Copy;

    /// Computes what depends on `wo` alone.
    #[must_use]
    fn prepare(&self, wo: Vec3) -> Self::Prepared;

    /// [`Bxdf::eval`] for the prepared `wo`.
    #[must_use]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> Self::Spectrum;

    /// [`Bxdf::pdf`] for the prepared `wo`.
    #[must_use]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32;

    /// `(eval, pdf)` for the prepared `wo`, sharing their work (a microfacet model evaluates
    /// `D` once): what a renderer needs for a light sample weighed by MIS.
    #[inline(always)]
    #[must_use]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (Self::Spectrum, f32) {
        (self.eval_prepared(at, wi), self.pdf_prepared(at, wi))
    }

    /// [`Bxdf::sample`] for the prepared `wo`.
    #[must_use]
    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<Self::Spectrum>>;

    /// [`Bxdf::lobes`].
    #[must_use]
    fn lobes(&self) -> Lobes;

    /// [`Bxdf::stochastic`]: false (the default) for an exact model.
    #[inline(always)]
    #[must_use]
    fn stochastic(&self) -> bool {
        false
    }

    /// [`Bxdf::eval_seeded`] for the prepared `wo`; the default ignores the seed.
    #[inline(always)]
    #[must_use]
    fn eval_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> Self::Spectrum {
        let _ = seed;
        self.eval_prepared(at, wi)
    }

    /// [`Bxdf::pdf_seeded`] for the prepared `wo`; the default ignores the seed.
    #[inline(always)]
    #[must_use]
    fn pdf_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> f32 {
        let _ = seed;
        self.pdf_prepared(at, wi)
    }
}

/// The preconditions of a hot-loop call, checked in debug builds (like glam's `glam_assert`):
/// directions of unit length (squared length within 1e-3 of 1; the models are accurate for any
/// rounding of a unit vector) and random numbers in `[0, 1]`. Release builds check nothing and stay
/// total: any finite input gives a finite, non-negative answer.
#[inline(always)]
fn debug_check(w: &[Vec3], u: &[f32]) {
    debug_assert!(
        w.iter().all(|w| (w.length_squared() - 1.0).abs() <= 1e-3),
        "lobe: a direction is not of unit length: {w:?}"
    );
    debug_assert!(
        u.iter().all(|u| (0.0..=1.0).contains(u)),
        "lobe: a random number is outside [0, 1]: {u:?}"
    );
}

/// Every [`Prepare`] model is a [`Bxdf`], its calls checking their preconditions in debug
/// builds ([`debug_assert!`]: unit directions, random numbers in `[0, 1]`).
impl<T: Prepare> Bxdf for T {
    type Spectrum = T::Spectrum;

    #[inline(always)]
    fn eval(&self, wo: Vec3, wi: Vec3) -> T::Spectrum {
        debug_check(&[wo, wi], &[]);
        self.eval_prepared(&self.prepare(wo), wi)
    }

    #[inline(always)]
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<T::Spectrum>> {
        debug_check(&[wo], &[u.x, u.y, uc]);
        self.sample_prepared(&self.prepare(wo), u, uc)
    }

    #[inline(always)]
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        debug_check(&[wo, wi], &[]);
        self.pdf_prepared(&self.prepare(wo), wi)
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        Prepare::lobes(self)
    }

    #[inline(always)]
    fn stochastic(&self) -> bool {
        Prepare::stochastic(self)
    }

    #[inline(always)]
    fn eval_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> T::Spectrum {
        debug_check(&[wo, wi], &[]);
        self.eval_seeded_prepared(&self.prepare(wo), wi, seed)
    }

    #[inline(always)]
    fn pdf_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> f32 {
        debug_check(&[wo, wi], &[]);
        self.pdf_seeded_prepared(&self.prepare(wo), wi, seed)
    }
}

/// A one-sided reflection model sampled by cosine-weighted directions, as the diffuse models
/// are: write its value for directions above the surface, and [`Prepare`] (and so [`Bxdf`])
/// follows — zero unless both directions are above, directions drawn with density
/// `cos θi / π` (Malley's method), lobe [`Lobes::DIFFUSE_REFLECTION`].
///
/// ```
/// use lobe::bxdf::{Bxdf, CosineSampled};
/// use lobe::{Vec2, Vec3};
/// /// A grey Lambertian reflector of your own.
/// struct Grey;
/// impl CosineSampled for Grey {
///     type Spectrum = f32;
///     fn value(&self, _wo: Vec3, _wi: Vec3) -> f32 {
///         0.5 / core::f32::consts::PI
///     }
/// }
/// let s = Grey.sample(Vec3::Z, Vec2::new(0.3, 0.6), 0.5).unwrap();
/// assert!((s.weight() - 0.5).abs() < 1e-6);
/// ```
pub trait CosineSampled {
    /// The carrier of the BSDF's values.
    type Spectrum: Spectrum;

    /// `f(wo, wi)` for `wo` and `wi` strictly above the surface: finite and non-negative.
    #[must_use]
    fn value(&self, wo: Vec3, wi: Vec3) -> Self::Spectrum;
}

impl<T: CosineSampled> Prepare for T {
    type Spectrum = T::Spectrum;
    /// `wo` itself: the cosine sampler needs nothing else.
    type Prepared = Vec3;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Vec3 {
        wo
    }

    #[inline(always)]
    fn eval_prepared(&self, &wo: &Vec3, wi: Vec3) -> T::Spectrum {
        if both_above(wo, wi) {
            self.value(wo, wi)
        } else {
            T::Spectrum::zero()
        }
    }

    #[inline(always)]
    fn pdf_prepared(&self, &wo: &Vec3, wi: Vec3) -> f32 {
        pdf_cosine(wo, wi)
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, &wo: &Vec3, wi: Vec3) -> (T::Spectrum, f32) {
        if both_above(wo, wi) {
            (
                self.value(wo, wi),
                crate::sampling::cosine_hemisphere_pdf(wi.z),
            )
        } else {
            (T::Spectrum::zero(), 0.0)
        }
    }

    #[inline(always)]
    fn sample_prepared(&self, &wo: &Vec3, u: Vec2, _uc: f32) -> Option<BxdfSample<T::Spectrum>> {
        sample_cosine(wo, u, |wi| self.value(wo, wi))
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION
    }
}

/// Cosine-weighted sampling, shared by the diffuse models: `wi` with density `cos θi / π`
/// for `wo` above the surface, its value given by `value(wi)`.
#[inline(always)]
pub(crate) fn sample_cosine<S>(
    wo: Vec3,
    u: Vec2,
    value: impl FnOnce(Vec3) -> S,
) -> Option<BxdfSample<S>> {
    if !(wo.z > 0.0) {
        return None;
    }
    let wi = crate::sampling::cosine_hemisphere(u);
    let pdf = crate::sampling::cosine_hemisphere_pdf(wi.z);
    if !usable_pdf(pdf) {
        return None;
    }
    Some(BxdfSample::new(
        wi,
        value(wi),
        pdf,
        Lobes::DIFFUSE_REFLECTION,
    ))
}

/// The density of [`sample_cosine`]: `cos θi / π` where both directions are above the
/// surface, else 0.
#[inline(always)]
pub(crate) fn pdf_cosine(wo: Vec3, wi: Vec3) -> f32 {
    if both_above(wo, wi) {
        crate::sampling::cosine_hemisphere_pdf(wi.z)
    } else {
        0.0
    }
}

/// `1/|cos θi|` for a delta lobe's value, or `None` when `|cos θi|` is subnormal (or zero),
/// where the value `F/|cos θi|` would overflow `f32`: such a sample is refused rather than
/// returned with an infinite value.
#[inline(always)]
pub(crate) fn delta_scale(wi: Vec3) -> Option<f32> {
    let c = wi.z.abs();
    (c >= f32::MIN_POSITIVE).then(|| 1.0 / c)
}

/// Whether a sample's density can be returned: positive, finite, and not subnormal, so that
/// the weight `f |cos θi| / pdf` cannot overflow where a narrow lobe's density underflows
/// (found by `examples/fuzz/main.rs`: a pdf of 2e-40 gave an infinite weight).
#[inline(always)]
#[must_use]
pub(crate) fn usable_pdf(pdf: f32) -> bool {
    (f32::MIN_POSITIVE..f32::INFINITY).contains(&pdf)
}

/// The lobe a sample of a glossy and a diffuse reflection lobe came from, chosen per lane
/// in a batched loop: [`Lobes::GLOSSY_REFLECTION`] where `glossy`, else
/// [`Lobes::DIFFUSE_REFLECTION`].
#[inline(always)]
#[must_use]
pub(crate) fn glossy_or_diffuse(glossy: bool) -> Lobes {
    if glossy {
        Lobes::GLOSSY_REFLECTION
    } else {
        Lobes::DIFFUSE_REFLECTION
    }
}

/// `wo` and `wi` both strictly above the surface: the support of a one-sided BRDF.
#[inline(always)]
#[must_use]
pub(crate) fn both_above(wo: Vec3, wi: Vec3) -> bool {
    wo.z > 0.0 && wi.z > 0.0
}

// `approx`'s AbsDiffEq and RelativeEq for BxdfSample (feature `approx`).
#[cfg(feature = "approx")]
mod approx_impls {
    use super::BxdfSample;
    use approx::{AbsDiffEq, RelativeEq};

    /// Closeness of two samples (feature `approx`): the directions, values, pdfs and crossed
    /// indices within the tolerance, channel by channel, and the same lobe, exactly. For
    /// comparing a model's `sample` with a reference implementation's, or one build's with
    /// another's. As everywhere in `approx`, a relative tolerance alone never accepts a
    /// difference from an exact zero (a direction's component, a black channel): give an
    /// absolute floor with `epsilon` too.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use lobe::bxdf::{Bxdf, Lambert};
    /// use lobe::{Vec2, Vec3};
    ///
    /// let a = Lambert::new(Vec3::splat(0.5))?;
    /// let b = Lambert::new(Vec3::splat(0.5 + 1e-7))?;
    /// let wo = Vec3::new(0.0, 0.6, 0.8);
    /// let (u, uc) = (Vec2::new(0.25, 0.5), 0.5);
    /// let (sa, sb) = (a.sample(wo, u, uc).unwrap(), b.sample(wo, u, uc).unwrap());
    /// assert_ne!(sa, sb);
    /// assert_relative_eq!(sa, sb, epsilon = 1e-6, max_relative = 1e-6);
    /// # Ok::<(), lobe::ParamError>(())
    /// ```
    impl<S: AbsDiffEq<Epsilon = f32>> AbsDiffEq for BxdfSample<S> {
        type Epsilon = f32;

        #[inline(always)]
        fn default_epsilon() -> f32 {
            f32::EPSILON
        }

        fn abs_diff_eq(&self, other: &Self, epsilon: f32) -> bool {
            self.lobe == other.lobe
                && self.wi.abs_diff_eq(other.wi, epsilon)
                && self.f.abs_diff_eq(&other.f, epsilon)
                && self.pdf.abs_diff_eq(&other.pdf, epsilon)
                && self.eta.abs_diff_eq(&other.eta, epsilon)
        }
    }

    impl<S: RelativeEq<Epsilon = f32>> RelativeEq for BxdfSample<S> {
        #[inline(always)]
        fn default_max_relative() -> f32 {
            f32::EPSILON
        }

        fn relative_eq(&self, other: &Self, epsilon: f32, max_relative: f32) -> bool {
            self.lobe == other.lobe
                && self.wi.relative_eq(&other.wi, epsilon, max_relative)
                && self.f.relative_eq(&other.f, epsilon, max_relative)
                && self.pdf.relative_eq(&other.pdf, epsilon, max_relative)
                && self.eta.relative_eq(&other.eta, epsilon, max_relative)
        }
    }
}
