//! The one configuration of the law checks, [`Config`]: sample counts, seed, significance,
//! viewer directions and the tolerances of every law.

use super::bxdf::BxdfCheck;
use crate::bxdf::Bxdf;
use glam::Vec3;
use std::vec::Vec;

/// Settings of the BSDF law checks.
///
/// ```
/// use lobe::verify::Config;
/// let quick = Config { albedo_samples: 20_000, chi2_samples: 50_000, ..Config::default() };
/// assert_eq!(quick.albedo_bound, 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// Monte Carlo samples per albedo estimate (per direction, per estimator). Default 100 000.
    pub albedo_samples: usize,
    /// Samples per chi-square test (per direction). Default 200 000.
    pub chi2_samples: usize,
    /// Random direction pairs for positivity and reciprocity. Default 20 000.
    pub pairs: usize,
    /// Samples per direction for the consistency check. Default 20 000.
    pub consistency_samples: usize,
    /// Seed of every generator. Default 1.
    pub seed: u64,
    /// The chance of failing a correct model, for the whole run: each statistical test is
    /// held to the Šidák-corrected share of it. Default 0.01.
    pub significance: f64,
    /// The viewer directions of the albedo, sampling and consistency checks. Empty (the
    /// default) means `θo ∈ {0°, 30°, 60°, 80°, 89°}` at `φ = 0.4`, mirrored below the
    /// surface too for a transmissive model.
    pub directions: Vec<Vec3>,
    /// The largest directional albedo the model claims. Default 1 (energy conservation).
    pub albedo_bound: f64,
    /// The relative index below the surface, for generalised reciprocity: `η` for a model in
    /// radiance mode, `1/η` in importance mode, 1 (the default) for a BRDF.
    pub eta: f32,
    /// The relative tolerance of reciprocity (beyond each pair's round-off allowance).
    /// Default 1e-5.
    pub reciprocity_tolerance: f64,
    /// The relative tolerance of `sample` against `eval`/`pdf`. Default 1e-4.
    pub consistency_tolerance: f64,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            albedo_samples: 100_000,
            chi2_samples: 200_000,
            pairs: 20_000,
            consistency_samples: 20_000,
            seed: 1,
            significance: 0.01,
            directions: Vec::new(),
            albedo_bound: 1.0,
            eta: 1.0,
            reciprocity_tolerance: 1e-5,
            consistency_tolerance: 1e-4,
        }
    }
}

impl Config {
    /// The viewer directions for `bxdf`: [`Config::directions`], or the default set.
    #[must_use]
    pub fn viewer_directions<B: Bxdf + ?Sized>(&self, bxdf: &B) -> Vec<Vec3> {
        if !self.directions.is_empty() {
            return self.directions.clone();
        }
        let mut out: Vec<Vec3> = [0.0f32, 30.0, 60.0, 80.0, 89.0]
            .iter()
            .map(|t| {
                let (s, c) = t.to_radians().sin_cos();
                Vec3::new(s * 0.4f32.cos(), s * 0.4f32.sin(), c)
            })
            .collect();
        if bxdf.lobes().is_transmissive() {
            let below: Vec<Vec3> = out.iter().map(|w| Vec3::new(w.x, w.y, -w.z)).collect();
            out.extend(below);
        }
        out
    }

    pub(super) fn bxdf_check(&self, samples: usize) -> BxdfCheck {
        BxdfCheck {
            samples,
            seed: self.seed,
        }
    }
}
