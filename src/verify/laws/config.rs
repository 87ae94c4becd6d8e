//! The one configuration of every law check, [`Config`] (sample counts, seed, significance,
//! viewer directions, what the model claims, tolerances, and the distribution checks'
//! proposal), and [`BxdfCheck`], the older two-field budget of an albedo estimate that
//! converts into it.

use crate::bxdf::Bxdf;
use glam::{Vec2, Vec3};
use std::vec::Vec;

/// The settings of every law check of [`verify`](crate::verify), for a BSDF
/// ([`check_bxdf`](super::check_bxdf) and its laws) and for a microfacet distribution
/// ([`check_ndf`](super::check_ndf) and its laws) alike: one type to learn, with defaults
/// that suit both. Each check reads the fields it needs and ignores the others, so one
/// `Config` can serve a whole test file.
///
/// Build one with struct update syntax over [`Default`]:
///
/// ```
/// use lobe::verify::Config;
/// use lobe::Vec2;
/// // A quicker BSDF run.
/// let quick = Config { albedo_samples: 20_000, chi2_samples: 50_000, ..Config::default() };
/// assert_eq!(quick.albedo_bound, 1.0);
/// // A distribution of width α = 0.3: the integrals' proposal stretched to it.
/// let ggx = Config { stretch: Vec2::splat(0.3), ..Config::default() };
/// assert_eq!(ggx.integral_samples, 200_000);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// Monte Carlo samples per albedo estimate (per direction, per estimator). Default 100 000.
    pub albedo_samples: usize,
    /// Samples per chi-square test (per direction), of a BSDF's or a distribution's sampler.
    /// Default 200 000.
    pub chi2_samples: usize,
    /// Random direction pairs for positivity and reciprocity. Default 20 000.
    pub pairs: usize,
    /// Samples per direction for the consistency check. Default 20 000.
    pub consistency_samples: usize,
    /// Monte Carlo samples per integral of a distribution's laws (`D` normalisation, projected
    /// area, visible normals; see [`integrate_hemisphere`](crate::verify::integrate_hemisphere)).
    /// Default 200 000.
    pub integral_samples: usize,
    /// Seed of every generator. Default 1.
    pub seed: u64,
    /// The chance of failing a correct model, for the whole run: each statistical test is
    /// held to the Šidák-corrected share of it. Default 0.01.
    pub significance: f64,
    /// The viewer directions of the checks that take one (albedo, sampling, consistency;
    /// projected area, visible normals and sampling of a distribution). Empty (the default)
    /// means each subject's own set: for a BSDF `θo ∈ {0°, 30°, 60°, 80°, 89°}` at `φ = 0.4`,
    /// mirrored below the surface too for a transmissive model; for a distribution
    /// `θ ∈ {0°, 30°, 60°, 85°, 89°}` at `φ = 0.7`.
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
    /// The stretch `(sx, sy)` of the distribution integrals' proposal and of their
    /// chi-square test: about the distribution's widths `(αx, αy)`, so that a narrow lobe is
    /// sampled at its own scale. Default `(1, 1)`.
    pub stretch: Vec2,
    /// For a [`stochastic`](crate::bxdf::Bxdf::stochastic) model (laws in expectation): the
    /// independent estimates averaged per value — each side of a reciprocity pair — and, sixteen
    /// times as many, per bin of the expected density and value. Default 64.
    pub expectation_evaluations: usize,
    /// For a stochastic model: the direction pairs of reciprocity in expectation.
    /// Default 200.
    pub expectation_pairs: usize,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            albedo_samples: 100_000,
            chi2_samples: 200_000,
            pairs: 20_000,
            consistency_samples: 20_000,
            integral_samples: 200_000,
            seed: 1,
            significance: 0.01,
            directions: Vec::new(),
            albedo_bound: 1.0,
            eta: 1.0,
            reciprocity_tolerance: 1e-5,
            consistency_tolerance: 1e-4,
            stretch: Vec2::ONE,
            expectation_evaluations: 64,
            expectation_pairs: 200,
        }
    }
}

impl Config {
    /// The same configuration with the significance of one of `laws` statistical laws that
    /// share the run's ([`sidak`](crate::verify::sidak)): what [`check_bxdf`] gives each, so
    /// that [`significance`](Self::significance) holds for the whole run.
    ///
    /// [`check_bxdf`]: crate::verify::check_bxdf
    #[must_use]
    pub fn shared_among(&self, laws: usize) -> Self {
        Self {
            significance: crate::verify::sidak(self.significance, laws),
            ..self.clone()
        }
    }

    /// The viewer directions of the BSDF checks for `bxdf`: [`Config::directions`], or the
    /// default set.
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

    /// The viewer directions of the distribution checks, each with its polar angle in degrees
    /// (as the reports name it): [`Config::directions`], or the default set.
    pub(super) fn distribution_directions(&self) -> Vec<(f32, Vec3)> {
        if !self.directions.is_empty() {
            return self
                .directions
                .iter()
                .map(|w| (w.z.clamp(-1.0, 1.0).acos().to_degrees(), *w))
                .collect();
        }
        [0.0f32, 30.0, 60.0, 85.0, 89.0]
            .iter()
            .map(|&t| {
                let (s, c) = t.to_radians().sin_cos();
                (t, Vec3::new(s * 0.7f32.cos(), s * 0.7f32.sin(), c))
            })
            .collect()
    }
}

/// The budget of one albedo estimate as earlier versions wrote it: a sample count and a seed.
///
/// It converts into a [`Config`] (`samples` becomes the sample count of each estimate —
/// albedo, consistency, integral —, `seed` the seed, the rest the defaults), so the
/// estimators that take any `&C` with `&C: Into<Config>` ([`albedo_sampled`](super::albedo_sampled),
/// [`albedo_cosine`](super::albedo_cosine), [`sample_consistency`](super::sample_consistency))
/// accept it, as they did before `Config` was the one configuration; new code passes a
/// `&Config`.
///
/// ```
/// use lobe::bxdf::Lambert;
/// use lobe::verify::{albedo_sampled, BxdfCheck, Config};
/// use lobe::Vec3;
/// let lambert = Lambert::new(0.5_f32)?;
/// let old = albedo_sampled(&lambert, Vec3::Z, &BxdfCheck { samples: 1_000, seed: 3 });
/// let new = albedo_sampled(&lambert, Vec3::Z, &Config { albedo_samples: 1_000, seed: 3, ..Config::default() });
/// assert_eq!(old, new);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BxdfCheck {
    /// Samples per estimate. Default 200 000.
    pub samples: usize,
    /// Seed of the [`Pcg32`](crate::verify::Pcg32) that draws the random numbers. Default 1.
    pub seed: u64,
}

impl Default for BxdfCheck {
    fn default() -> Self {
        Self {
            samples: 200_000,
            seed: 1,
        }
    }
}

impl From<BxdfCheck> for Config {
    fn from(check: BxdfCheck) -> Self {
        Self {
            albedo_samples: check.samples,
            consistency_samples: check.samples,
            integral_samples: check.samples,
            seed: check.seed,
            ..Self::default()
        }
    }
}

impl From<&BxdfCheck> for Config {
    fn from(check: &BxdfCheck) -> Self {
        Self::from(*check)
    }
}

/// A `&Config` where an estimator takes `&C` with `&C: Into<Config>` (a clone: the
/// estimators read a few numbers from it once).
impl From<&Config> for Config {
    fn from(config: &Config) -> Self {
        config.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec;

    #[test]
    fn a_bxdf_check_becomes_every_estimate_budget() {
        let c = Config::from(BxdfCheck {
            samples: 1234,
            seed: 9,
        });
        assert_eq!(
            (
                c.albedo_samples,
                c.consistency_samples,
                c.integral_samples,
                c.seed
            ),
            (1234, 1234, 1234, 9)
        );
        assert_eq!(
            Config {
                albedo_samples: 1234,
                consistency_samples: 1234,
                integral_samples: 1234,
                seed: 9,
                ..Config::default()
            },
            c
        );
    }

    #[test]
    fn distribution_directions_are_the_defaults_or_the_given_ones() {
        let defaults = Config::default().distribution_directions();
        let thetas: Vec<f32> = defaults.iter().map(|&(t, _)| t).collect();
        assert_eq!(thetas, [0.0, 30.0, 60.0, 85.0, 89.0]);
        assert!(
            defaults
                .iter()
                .all(|(_, w)| (w.length() - 1.0).abs() < 1e-6)
        );
        let given = Config {
            directions: vec![Vec3::Z, Vec3::new(0.6, 0.0, 0.8)],
            ..Config::default()
        };
        let dirs = given.distribution_directions();
        assert_eq!(dirs[0], (0.0, Vec3::Z));
        assert!((dirs[1].0 - 36.869_9).abs() < 1e-3, "{dirs:?}");
    }
}
