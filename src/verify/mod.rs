//! The verification harness: measurements, with their uncertainty, of whether a model
//! obeys the laws it claims.
//!
//! Available with the `verify` feature (which implies `std`). The crate's own test suite
//! is built on it, and a renderer can point the same checks at its own models from its
//! tests.
//!
//! A law is a claim about an integral or an identity, so a check is a measurement, not a
//! comparison against a hand-picked epsilon. The module has two rooms (its items are all
//! public here, at `lobe::verify::…`):
//!
//! **The laws**, one subject a file, each measuring, reporting and checking its subject:
//!
//! * [`check_bxdf`] runs every law of a BSDF that applies: [`positivity`], [`reciprocity`],
//!   [`energy_bound`] (the directional [`albedo`] by two independent estimators,
//!   [`albedo_sampled`] and [`albedo_cosine`]), [`sampling_chi2`] ([`chi2_bxdf`] per viewer
//!   direction) and [`consistency`] ([`sample_consistency`]). A model of any
//!   [`Spectrum`](crate::Spectrum) — `f32`, RGB `Vec3`, four wavelengths `Vec4` — is checked
//!   per channel, each report naming its worst channel; [`Channel`] views one channel as a
//!   monochrome model for the measurements.
//! * A [`stochastic`](crate::bxdf::Bxdf::stochastic) model (a layered BSDF, whose `eval` and
//!   `pdf` are Monte Carlo estimates) is checked in expectation: [`check_bxdf`] hands it to
//!   [`check_bxdf_in_expectation`], which averages independent seeded estimates and compares
//!   with their standard errors ([`reciprocity_in_expectation`], [`sampling_in_expectation`]
//!   against the expected density, [`consistency_in_expectation`] of the sampled weight with
//!   the expected value).
//! * [`check_ndf`] runs the laws of a microfacet distribution: [`d_normalization`],
//!   [`projected_area`], [`visible_normalization`] and its sampler ([`chi2_normals`]).
//! * One [`Config`] sets every check's budget, seed, significance, viewer directions and
//!   tolerances; each returns a [`LawReport`] (a [`Report`] for a whole model) that says
//!   which [`Law`] held, the measured figure with its uncertainty, and where the worst case
//!   was.
//!
//! **The statistics** they measure with, public because a check built outside the crate
//! needs them too:
//!
//! * [`Estimate`] / [`Accumulator`]: a Monte Carlo mean with its standard error, accumulated
//!   in `f64`. Assert with [`Estimate::within`]`(target, k)` — "within `k` standard
//!   errors" — or read [`Estimate::z_score`].
//! * [`chi2_sphere`]: Pearson's chi-square goodness-of-fit test of a direction sampler
//!   against its solid-angle density ([`Chi2Config`] sets its bins and budget), with
//!   low-count bins pooled and outright failures (samples where the density is zero,
//!   invalid samples or densities) reported.
//! * [`integrate_hemisphere`]: a Monte Carlo integral over the hemisphere whose proposal
//!   follows a lobe of a given width.
//! * [`sidak`]: the per-test significance for a family of tests, so that a file of `n`
//!   tests keeps its overall false-rejection rate; [`two_sided_quantile`]: the `k` of
//!   "within `k` standard errors" at a significance.
//! * [`Pcg32`], [`gamma_p`], [`gamma_q`], [`ln_gamma`], [`chi2_survival`]: the generator
//!   and the special functions underneath.
//!
//! **Every test is seeded and reproducible.** Random numbers come from [`Pcg32`], whose
//! sequence for a given seed is pinned by a test, so a check that passes once passes on
//! every machine and every run, and a failure can be replayed exactly. A statistical test
//! at significance `α` still rejects a correct model for a fraction `α` of seeds; that is
//! what the significance means, and why suites correct it with [`sidak`] rather than
//! retrying with other seeds.
//!
//! ## Verifying your own BRDF
//!
//! A renderer's own model implements [`Bxdf`](crate::bxdf::Bxdf), in whatever spectrum it
//! shades with (here RGB); then three lines in its tests run every law that applies, on
//! every channel, and say, on failure, which law failed, in which channel and where:
//!
//! ```
//! use lobe::bxdf::{Bxdf, BxdfSample, Lobes};
//! use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
//! use lobe::{Vec2, Vec3};
//!
//! /// A renderer's own diffuse BRDF, an orange of reflectance (0.9, 0.6, 0.3).
//! struct MyDiffuse;
//!
//! impl Bxdf for MyDiffuse {
//!     type Spectrum = Vec3;
//!     fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
//!         let rho = Vec3::new(0.9, 0.6, 0.3);
//!         if wo.z > 0.0 && wi.z > 0.0 { rho / std::f32::consts::PI } else { Vec3::ZERO }
//!     }
//!     fn sample(&self, wo: Vec3, u: Vec2, _uc: f32) -> Option<BxdfSample<Vec3>> {
//!         let wi = cosine_hemisphere(u);
//!         let pdf = self.pdf(wo, wi);
//!         (pdf > 0.0).then(|| BxdfSample { wi, f: self.eval(wo, wi), pdf, lobe: Lobes::DIFFUSE_REFLECTION, eta: 1.0 })
//!     }
//!     fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
//!         if wo.z > 0.0 && wi.z > 0.0 { cosine_hemisphere_pdf(wi.z) } else { 0.0 }
//!     }
//!     fn lobes(&self) -> Lobes {
//!         Lobes::DIFFUSE_REFLECTION
//!     }
//! }
//!
//! // The test: (a smaller budget than the default, to keep this example quick)
//! let config = lobe::verify::Config { albedo_samples: 20_000, chi2_samples: 50_000, pairs: 2_000, ..Default::default() };
//! let report = lobe::verify::check_bxdf("my diffuse", &MyDiffuse, &config);
//! assert!(report.passed(), "{report}");
//! ```
//!
//! ## Example
//!
//! Check that cosine-weighted hemisphere sampling produces the density it claims:
//!
//! ```
//! use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
//! use lobe::verify::{chi2_sphere, Chi2Config};
//!
//! let config = Chi2Config { samples: 100_000, ..Chi2Config::default() };
//! let report = chi2_sphere(
//!     |u| Some(cosine_hemisphere(u)),
//!     |w| f64::from(cosine_hemisphere_pdf(w.z)),
//!     &config,
//! );
//! assert!(report.passed(), "{report}");
//! assert_eq!(report.zero_bin_hits, 0);
//!
//! // The mean of cos θ under that density is 2/3.
//! use lobe::verify::{Accumulator, Pcg32};
//! let mut rng = Pcg32::new(7, 0);
//! let mut acc = Accumulator::new();
//! for _ in 0..100_000 {
//!     acc.push(f64::from(cosine_hemisphere(rng.next_vec2()).z));
//! }
//! let estimate = acc.finish();
//! assert!(estimate.within(2.0 / 3.0, 4.0), "{estimate}");
//! ```

mod laws;
mod stats;
#[cfg(feature = "proptest")]
pub mod strategies;

pub use laws::{
    Albedo, BxdfCheck, Channel, Config, Law, LawReport, ReciprocityPair, Report, SUBNORMAL_FLOOR,
    albedo, albedo_cosine, albedo_sampled, check_bxdf, check_ndf, chi2_bxdf, chi2_normals,
    consistency, d_normalization, energy_bound, positivity, projected_area, projected_area_masked,
    reciprocity, reciprocity_pair, sample_consistency, sampling_chi2, visible_normalization,
};
pub use laws::{
    ExpectedPair, check_bxdf_in_expectation, consistency_in_expectation,
    reciprocity_in_expectation, reciprocity_pair_in_expectation,
    sampling_and_consistency_in_expectation, sampling_in_expectation,
};
pub use stats::{
    Accumulator, Chi2Bin, Chi2Config, Chi2Report, Chi2Residual, Estimate, Pcg32, chi2_sphere,
    chi2_sphere_rng, chi2_survival, gamma_p, gamma_q, integrate_hemisphere, ln_gamma, sidak,
    two_sided_quantile,
};
