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
            // The inverse CDF below cancels for small |g|: its series in g to second order,
            // with the mass above cos θ equal to u.x (error about (1 − a²) g³ ≤ 1e-9 here;
            // a uniform cos θ alone is off by 0.75 (1 − a²) |g|, up to 7.5e-4 in the CDF).
            let a = 1.0 - 2.0 * u.x;
            let b = 1.0 - a * a;
            a - 1.5 * b * g - 2.0 * a * b * (g * g)
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

    /// For `|g| < 1e-3` the sampler's cos θ is a series, not the closed-form inverse: the
    /// mass above it is `u.x` to a few `f32` roundings of the cosine and the series' terms
    /// (each up to 6e-8 next to 1, times a density of at most 0.5: 1e-7 allows about three,
    /// the series' own error ≤ 0.5 g³ ≤ 5e-10 aside), against the closed-form CDF in `f64`.
    #[test]
    fn the_small_asymmetry_sampler_inverts_the_cdf() {
        for g in [9.9e-4f32, 5e-4, 1e-5, -1e-5, -5e-4, -9.9e-4] {
            let hg = HenyeyGreenstein::new(g);
            let gd = f64::from(g);
            // ∫_c^1 p dc' for the density in cos θ, (1 − g²) / (2 (1 + g² + 2gc)^{3/2}).
            let above = |c: f64| {
                (1.0 - gd * gd) / (2.0 * gd)
                    * ((1.0 + gd * gd + 2.0 * gd * c).powf(-0.5) - 1.0 / (1.0 + gd))
            };
            let mut worst = 0.0f64;
            for i in 0..=1000 {
                let u = i as f32 / 1000.0 * crate::sampling::ONE_MINUS_EPSILON;
                let wi = hg.sample(Vec3::Z, Vec2::new(u, 0.3)).wi;
                worst = worst.max((above(f64::from(wi.z)) - f64::from(u)).abs());
            }
            assert!(worst <= 1e-7, "g = {g}: max |CDF − u| = {worst:e}");
        }
    }
}
