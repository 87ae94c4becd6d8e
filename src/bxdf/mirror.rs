//! A perfect mirror: delta reflection, weighted by a Fresnel term.

use super::{BxdfSample, Lobes, Prepare, delta_scale};
use crate::fresnel::Fresnel;
use crate::spectrum::Spectrum;
use glam::{Vec2, Vec3};

/// Perfect specular reflection, `wi = 2 (wo·n) n − wo`, with reflectance `F(cos θo)`:
///
/// ```text
/// f(wo, wi) = F(cos θo) δ(wi − reflect(wo)) / |cos θi|
/// ```
///
/// The handouts' "Mirror reflection" (seed 003), with the Fresnel term that their "Specular
/// reflection from metal/glass" slides describe; pbrt-v4 §9.3. Use [`NoFresnel`] for an ideal
/// mirror, [`Conductor`] for a polished metal.
///
/// A delta lobe: [`eval`](super::Bxdf::eval) and [`pdf`](super::Bxdf::pdf) are zero, and
/// [`sample`](super::Bxdf::sample) returns the mirror direction with `pdf = 1` and a weight of exactly
/// `F(cos θo)`. One-sided (`None` for `wo.z ≤ 0`). Laws: positive; its albedo is `F ≤ 1`.
///
/// [`NoFresnel`]: crate::fresnel::NoFresnel
/// [`Conductor`]: crate::fresnel::Conductor
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror<F> {
    fresnel: F,
}

impl<F: Fresnel> Mirror<F> {
    /// A mirror with the reflectance `fresnel`.
    #[must_use]
    pub fn new(fresnel: F) -> Self {
        Self { fresnel }
    }

    /// The Fresnel term.
    #[inline]
    #[must_use]
    pub fn fresnel(&self) -> &F {
        &self.fresnel
    }
}

impl<F: Fresnel> Prepare for Mirror<F> {
    type Spectrum = F::Spectrum;
    type Prepared = Vec3;

    #[inline]
    fn prepare(&self, wo: Vec3) -> Vec3 {
        wo
    }

    #[inline]
    fn eval_prepared(&self, _wo: &Vec3, _wi: Vec3) -> F::Spectrum {
        F::Spectrum::zero()
    }

    #[inline]
    fn sample_prepared(&self, &wo: &Vec3, _u: Vec2, _uc: f32) -> Option<BxdfSample<F::Spectrum>> {
        if !(wo.z > 0.0) {
            return None;
        }
        let wi = Vec3::new(-wo.x, -wo.y, wo.z);
        Some(BxdfSample {
            wi,
            f: self.fresnel.eval(wo.z) * delta_scale(wi)?,
            pdf: 1.0,
            lobe: Lobes::SPECULAR_REFLECTION,
            eta: 1.0,
        })
    }

    #[inline]
    fn pdf_prepared(&self, _wo: &Vec3, _wi: Vec3) -> f32 {
        0.0
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::SPECULAR_REFLECTION
    }
}
