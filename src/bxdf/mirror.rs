//! A perfect mirror: delta reflection, weighted by a Fresnel term.

use super::{BxdfSample, Lobes, delta_scale};
use crate::fresnel::Fresnel;
use glam::Vec3;

/// Perfect specular reflection, `wi = 2 (wo·n) n − wo`, with reflectance `F(cos θo)`:
///
/// ```text
/// f(wo, wi) = F(cos θo) δ(wi − reflect_away(wo)) / |cos θi|
/// ```
///
/// The handouts' "Mirror reflection" ([seed 003](crate::handouts#seed-003)), with the Fresnel term that
/// their "Specular
/// reflection from metal/glass" slides describe; pbrt-v4 §9.3. Use [`NoFresnel`] for an ideal
/// mirror, [`Conductor`] for a polished metal.
///
/// A delta lobe: [`eval`](super::Bxdf::eval) and [`pdf`](super::Bxdf::pdf) are zero, and
/// [`sample`](super::Bxdf::sample) returns the mirror direction with `pdf = 1` and a weight of
/// `F(cos θo)` up to `f32` rounding (within 1e-6 relative, `tests/bxdf_specular.rs`). One-sided
/// (`None` for `wo.z ≤ 0`). Laws: positive; its albedo is `F ≤ 1`.
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

    /// `sample` (its lobes are delta lobes: `eval` and `pdf` are zero).
    #[inline(always)]
    fn sample_delta(&self, wo: Vec3, _uc: f32) -> Option<BxdfSample<F::Spectrum>> {
        if !(wo.z > 0.0) {
            return None;
        }
        let wi = Vec3::new(-wo.x, -wo.y, wo.z);
        Some(BxdfSample::new(
            wi,
            self.fresnel.eval(wo.z) * delta_scale(wi)?,
            1.0,
            Lobes::SPECULAR_REFLECTION,
        ))
    }
}

delta_model!(impl<F: Fresnel> for Mirror<F>, spectrum F::Spectrum, lobes Lobes::SPECULAR_REFLECTION);
