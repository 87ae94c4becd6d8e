//! The Henyey-Greenstein phase function of the medium between a layered BSDF's interfaces.

use crate::frame::Frame;
use crate::math::{safe_sqrt, sin_cos_turns};
use core::f32::consts::PI;
use glam::{Vec2, Vec3};

/// Henyey & Greenstein's phase function (1941, "Diffuse radiation in the galaxy", ApJ 93):
///
/// ```text
/// p(wo, wi) = (1 − g²) / (4π (1 + g² + 2 g cos θ)^{3/2}),     cos θ = wo·wi
/// ```
///
/// with both directions pointing away from the scattering point (pbrt-v4 §11.3.1), so that
/// `g > 0` scatters forward (`wi ≈ −wo`). Sampled exactly by inverting its CDF in `cos θ`
/// (pbrt-v4, `SampleHenyeyGreenstein`), so the sample's weight is 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct HenyeyGreenstein {
    g: f32,
}

/// A phase-function sample: the direction and its density, which is also its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PhaseSample {
    pub(crate) wi: Vec3,
    pub(crate) pdf: f32,
}

impl HenyeyGreenstein {
    /// The phase function of asymmetry `g ∈ (−1, 1)` (the constructor of the model checks it).
    pub(crate) fn new(g: f32) -> Self {
        Self { g }
    }

    /// `p` for the cosine `cos θ = wo·wi`.
    #[inline(always)]
    fn value_cos(&self, cos_theta: f32) -> f32 {
        let g = self.g;
        let denom = (1.0 + g * g + 2.0 * g * cos_theta).max(f32::MIN_POSITIVE);
        (1.0 - g * g) / (4.0 * PI * denom * crate::math::sqrt(denom))
    }

    /// `p(wo, wi)`, which is also the density of [`sample`](Self::sample).
    #[inline(always)]
    pub(crate) fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.value_cos(wo.dot(wi).clamp(-1.0, 1.0))
    }

    /// A direction `wi` distributed as `p(wo, ·)`, for `u ∈ [0, 1)²`.
    #[inline(always)]
    pub(crate) fn sample(&self, wo: Vec3, u: Vec2) -> PhaseSample {
        let g = self.g;
        let cos_theta = if g.abs() < 1e-3 {
            1.0 - 2.0 * u.x
        } else {
            let s = (1.0 - g * g) / (1.0 + g - 2.0 * g * u.x);
            (-(1.0 + g * g - s * s) / (2.0 * g)).clamp(-1.0, 1.0)
        };
        let sin_theta = safe_sqrt(1.0 - cos_theta * cos_theta);
        let (s, c) = sin_cos_turns(u.y);
        let frame = Frame::from_normal(wo);
        let wi = frame.to_world(Vec3::new(sin_theta * c, sin_theta * s, cos_theta));
        PhaseSample {
            wi,
            pdf: self.value_cos(cos_theta),
        }
    }
}

#[cfg(all(test, feature = "verify"))]
mod tests {
    use super::*;
    use crate::verify::{Chi2Config, Pcg32, chi2_sphere};

    #[test]
    fn the_sampler_draws_the_density_and_it_integrates_to_one() {
        for g in [-0.7, 0.0, 0.3, 0.9] {
            let hg = HenyeyGreenstein::new(g);
            let wo = Vec3::new(0.36, 0.48, 0.8);
            let config = Chi2Config {
                samples: 100_000,
                significance: 0.01 / 4.0,
                ..Chi2Config::default()
            };
            let r = chi2_sphere(
                |u| Some(hg.sample(wo, u).wi),
                |wi| f64::from(hg.eval(wo, wi)),
                &config,
            );
            assert!(r.passed(), "g = {g}: {r}");
            assert!((r.pdf_integral - 1.0).abs() < 1e-3, "g = {g}: {r}");
            // The sample's density is the density at its direction.
            let mut rng = Pcg32::new(3, 0);
            for _ in 0..100 {
                let s = hg.sample(wo, rng.next_vec2());
                let p = hg.eval(wo, s.wi);
                assert!((s.pdf - p).abs() <= 1e-3 * p, "{s:?} {p}");
            }
        }
    }
}
