//! A thin dielectric sheet (a window pane): delta reflection and straight-through transmission.

use super::{BxdfSample, Lobes, delta_scale};
use crate::fresnel::dielectric;
use crate::param::Eta;
use glam::Vec3;

/// A thin slab of dielectric with parallel faces, such as a window pane, with the light's
/// inter-reflections between its two faces summed in closed form:
///
/// ```text
/// R' = R + T² R / (1 − R²),   T' = 1 − R'        (R = F(cos θo), T = 1 − R)
/// ```
///
/// The geometric series of reflections inside the slab (pbrt-v4 §9.5.3). Refraction at the second
/// face undoes the first, so transmitted light continues along `−wo`, with no radiance scaling.
/// Delta lobes only: `eval` and `pdf` are zero; every sample's weight is 1 up to `f32` rounding
/// (within 1e-5, `tests/bxdf_specular.rs`), so the albedo is `R' + T' = 1`. Two-sided: `wo` may be
/// on either side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinDielectric {
    eta: Eta,
}

impl ThinDielectric {
    /// A thin sheet of relative index `eta`.
    #[must_use]
    pub fn new(eta: Eta) -> Self {
        Self { eta }
    }

    /// The sheet's total reflectance `R'` at `cos θo`.
    #[inline]
    #[must_use]
    pub fn reflectance(&self, cos_o: f32) -> f32 {
        // Both faces see the light from the outside of the slab's material.
        let r = dielectric(cos_o.abs(), self.eta);
        if r < 1.0 {
            let t = 1.0 - r;
            r + t * t * r / (1.0 - r * r)
        } else {
            1.0
        }
    }

    getters! {
        /// The relative index `η_inside / η_outside` of the sheet.
        eta: Eta,
    }

    /// `sample` (its lobes are delta lobes: `eval` and `pdf` are zero).
    #[inline(always)]
    fn sample_delta(&self, wo: Vec3, uc: f32) -> Option<BxdfSample<f32>> {
        if wo.z == 0.0 {
            return None;
        }
        let r = self.reflectance(wo.z);
        let (wi, p, lobe) = if crate::sampling::picks(uc, r) {
            (Vec3::new(-wo.x, -wo.y, wo.z), r, Lobes::SPECULAR_REFLECTION)
        } else {
            (-wo, 1.0 - r, Lobes::SPECULAR_TRANSMISSION)
        };
        if !(p > 0.0) {
            return None;
        }
        Some(BxdfSample::new(wi, p * delta_scale(wi)?, p, lobe))
    }
}

delta_model!(impl for ThinDielectric, spectrum f32, lobes Lobes::SPECULAR_REFLECTION | Lobes::SPECULAR_TRANSMISSION);
