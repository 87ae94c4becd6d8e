//! [The handouts'](crate::handouts#seed-003) glazed material: a diffuse base under a smooth dielectric
//! coat.

use super::{At, BxdfSample, Lobes, Prepare, both_above, usable_pdf};
use crate::fresnel::{Dielectric, FresnelAverage, dielectric};
use crate::param::{Eta, ParamError, unit_interval};
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
use crate::spectrum::Spectrum;
use core::f32::consts::FRAC_1_PI;
use glam::{Vec2, Vec3};

/// A diffuse base of reflectance `ρ` under a smooth dielectric coat of relative index `η`:
/// the coat reflects as a mirror with the exact Fresnel reflectance `F`, and the base's
/// diffuse light is weighted by what the coat lets through on the way in and out:
///
/// ```text
/// f = F(cos θo) δ(wi − reflect_away(wo)) / cos θi
///   + ρ/π · (1 − F(cos θo)) (1 − F(cos θi)) / (1 − F̄),     F̄ = 2 ∫₀¹ F(μ) μ dμ
/// ```
///
/// The handouts' "glazed" material ([seed 003](crate::handouts#seed-003): "mirror reflection and
/// diffuse"), made energy
/// conserving with the coupling of Kelemen & Szirmay-Kalos (2001, "A Microfacet Based Coupled
/// Specular-Matte BRDF Model with Importance Sampling", eq. 5): the directional albedo is
/// `F(cos θo) + (1 − F(cos θo)) ρ`, never above 1 and exactly 1 for `ρ = 1`. The diffuse
/// term is symmetric in `wo` and `wi`, so the model is reciprocal. It leaves out the light
/// the coat reflects back into the base, which a physical stack bounces again and partly
/// absorbs: a smooth coat over Lambert with the same `ρ` and `η` ([`Layered`](super::Layered),
/// which keeps it) is darker as well as more saturated.
///
/// Sampling: the mirror lobe with probability `F / (F + (1 − F) ρ̄)` (`ρ̄` the mean channel),
/// cosine-weighted directions otherwise. `F̄` is integrated once at construction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glazed<S = f32> {
    reflectance: S,
    eta: Eta,
    /// `1 / (π (1 − F̄))`.
    diffuse_scale: f32,
    /// The reflectance's channel average, for the lobe choice (stored: for RGB it is a
    /// division).
    mean_reflectance: f32,
}

impl<S: Spectrum> Glazed<S> {
    /// A glazed surface with base reflectance `ρ ∈ [0, 1]` and a coat of relative index
    /// `eta`.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`.
    pub fn new(reflectance: S, eta: Eta) -> Result<Self, ParamError> {
        let reflectance = unit_interval("reflectance", reflectance)?;
        // F̄ by `Dielectric`'s average, which goes round the kink that total internal
        // reflection puts in F at the critical angle when η < 1 (integrated straight across
        // it, F̄ was off by up to 5e-3 and the albedo of a white base up to 1.03).
        let f_avg = Dielectric { eta }.average();
        // A coat that reflects everything (η far below 1: total internal reflection at almost
        // every angle) lets no light reach the base: no diffuse term, rather than 0 · ∞.
        let diffuse_scale = if f_avg < 1.0 {
            FRAC_1_PI / (1.0 - f_avg)
        } else {
            0.0
        };
        Ok(Self {
            reflectance,
            eta,
            diffuse_scale,
            mean_reflectance: reflectance.average(),
        })
    }

    /// The directional albedo `F(cos θo) + (1 − F(cos θo)) ρ`, in closed form.
    #[must_use]
    pub fn albedo(&self, wo: Vec3) -> S {
        if !(wo.z > 0.0) {
            return S::zero();
        }
        let f = dielectric(wo.z, self.eta);
        S::splat(f) + self.reflectance * (1.0 - f)
    }

    /// The probability of sampling the mirror lobe, and `F(cos θo)`.
    #[inline]
    fn mirror_probability(&self, wo: Vec3) -> (f32, f32) {
        let f = dielectric(wo.z, self.eta);
        let diffuse = (1.0 - f) * self.mean_reflectance;
        let total = f + diffuse;
        (if total > 0.0 { f / total } else { 0.0 }, f)
    }

    getters! {
        /// The diffuse base's reflectance.
        reflectance: S,
        /// The coat's relative index `η_inside / η_outside`.
        eta: Eta,
    }
}

impl<S: Spectrum> Prepare for Glazed<S> {
    type Spectrum = S;
    /// `wo` with the probability of the mirror lobe and the coat's `F(cos θo)`.
    type Prepared = At<(f32, f32)>;

    #[inline]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At {
            wo,
            state: self.mirror_probability(wo),
        }
    }

    #[inline]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> S {
        if !both_above(at.wo, wi) {
            return S::zero();
        }
        let t = (1.0 - at.state.1) * (1.0 - dielectric(wi.z, self.eta));
        self.reflectance * (t * self.diffuse_scale)
    }

    /// Both lobes' directions are formed and the one `uc` picks is kept, a refused sample
    /// refused at the end: no branch for a batched loop to turn into selects. (Under AVX2, with
    /// early returns, its batched `sample` took 0.9× the scalar call's time, not vectorised;
    /// measured 2026-11-29.)
    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<S>> {
        let wo = at.wo;
        let (p_mirror, f) = at.state;
        let mirror = crate::sampling::picks(uc, p_mirror);
        let reflected = Vec3::new(-wo.x, -wo.y, wo.z);
        let diffuse = cosine_hemisphere(u);
        let pdf_diffuse = (1.0 - p_mirror) * cosine_hemisphere_pdf(diffuse.z);
        let t = (1.0 - f) * (1.0 - dielectric(diffuse.z, self.eta));
        let (wi, value, pdf, lobe) = if mirror {
            // `f / |cos θi|`: `delta_scale`'s value where it has one (checked below).
            let value = S::splat(f * (1.0 / reflected.z.abs()));
            (reflected, value, p_mirror, Lobes::SPECULAR_REFLECTION)
        } else {
            let value = self.reflectance * (t * self.diffuse_scale);
            (diffuse, value, pdf_diffuse, Lobes::DIFFUSE_REFLECTION)
        };
        // `&` and `|`, not `&&` and `||`: no branch.
        let usable = (mirror & (reflected.z.abs() >= f32::MIN_POSITIVE))
            | (!mirror & usable_pdf(pdf_diffuse));
        let kept = (wo.z > 0.0) & usable;
        kept.then(|| BxdfSample::new(wi, value, pdf, lobe))
    }

    #[inline]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        if !both_above(at.wo, wi) {
            return 0.0;
        }
        (1.0 - at.state.0) * cosine_hemisphere_pdf(wi.z)
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION | Lobes::SPECULAR_REFLECTION
    }
}
