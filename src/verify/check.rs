//! The law checks of a BSDF as reports, and [`check_bxdf`], which runs every law that applies.

use super::bxdf::{
    BxdfCheck, SUBNORMAL_FLOOR, albedo_cosine, albedo_sampled, chi2_bxdf, reciprocity_pair,
    sample_consistency,
};
use super::report::{Law, LawReport, Report};
use super::{Chi2Config, Estimate, Pcg32, gamma_q, sidak};
use crate::bxdf::Bxdf;
use crate::sampling::uniform_sphere;
use glam::Vec3;
use std::format;
use std::string::String;
use std::vec::Vec;

/// The relative round-off of a weight computed in `f32` (a few ulps): what lets a
/// zero-variance estimator match an exact bound.
const F32_ROUND_OFF: f64 = 1e-6;

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

    fn bxdf_check(&self, samples: usize) -> BxdfCheck {
        BxdfCheck {
            samples,
            seed: self.seed,
        }
    }
}

/// The two-sided normal quantile `k` with `P(|Z| > k) = p`, by bisection on
/// `erfc(k/√2) = Q(½, k²/2)`.
#[must_use]
pub fn two_sided_quantile(p: f64) -> f64 {
    let tail = |k: f64| gamma_q(0.5, 0.5 * k * k);
    let (mut lo, mut hi) = (0.0_f64, 40.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if tail(mid) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// A direction for the positivity check: uniform on the sphere (half the draws), within
/// 1e-7…1e-2 of the horizon (a quarter), or one of the places where formulas divide by zero
/// (a quarter): exactly on the horizon (`z = ±0`), a subnormal `z`, or exactly `±z`.
fn adversarial_direction(rng: &mut Pcg32) -> Vec3 {
    let u = rng.next_vec2();
    let pick = rng.next_f32();
    let sign = if rng.next_f32() < 0.5 { 1.0 } else { -1.0 };
    let phi = core::f32::consts::TAU * u.y;
    let around = |z: f32| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    };
    if pick < 0.5 {
        uniform_sphere(u)
    } else if pick < 0.75 {
        around(sign * 10f32.powf(-7.0 + 5.0 * u.x))
    } else if pick < 0.85 {
        around(sign * 0.0)
    } else if pick < 0.92 {
        around(sign * 1e-40)
    } else {
        Vec3::new(0.0, 0.0, sign)
    }
}

/// **Positivity** and totality: over `config.pairs` adversarial direction pairs (uniform,
/// grazing down to `cos θ = 1e-7`, exactly on the horizon, subnormal, and exactly along the
/// normal), `eval` and `pdf` are finite and non-negative, and
/// every sample has a unit `wi`, a finite non-negative `f` and a positive finite `pdf`.
/// The figure is the number of violations.
#[must_use]
pub fn positivity<B: Bxdf<Spectrum = f32> + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut rng = Pcg32::new(config.seed, 0x0070_6f73);
    let mut violations = 0usize;
    let mut detail = String::from("every value finite and non-negative");
    for _ in 0..config.pairs {
        let (wo, wi) = (
            adversarial_direction(&mut rng),
            adversarial_direction(&mut rng),
        );
        let (f, p) = (bxdf.eval(wo, wi), bxdf.pdf(wo, wi));
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        let bad_value = !(f.is_finite() && f >= 0.0 && p.is_finite() && p >= 0.0);
        let sample = bxdf.sample(wo, u, uc);
        let bad_sample = sample.is_some_and(|s| {
            !(s.wi.is_finite()
                && (s.wi.length() - 1.0).abs() < 1e-4
                && s.f.is_finite()
                && s.f >= 0.0
                && s.pdf.is_finite()
                && s.pdf > 0.0)
        });
        if bad_value || bad_sample {
            if violations == 0 {
                detail = if bad_value {
                    format!("first at wo = {wo:?}, wi = {wi:?}: eval = {f}, pdf = {p}")
                } else {
                    format!("first at wo = {wo:?}, u = {u:?}, uc = {uc}: {sample:?}")
                };
            }
            violations += 1;
        }
    }
    LawReport {
        law: Law::Positivity,
        passed: violations == 0,
        figure: violations as f64,
        uncertainty: 0.0,
        figure_name: "violations",
        budget: format!("{} direction pairs", config.pairs),
        detail,
    }
}

/// **Reciprocity**: over `config.pairs` random pairs, `f(wo, wi)/η_o² = f(wi, wo)/η_i²`
/// within `config.reciprocity_tolerance` plus each pair's round-off allowance (see
/// [`ReciprocityPair`](super::ReciprocityPair)); `config.eta` gives the generalised form. The
/// figure is the largest relative error over the well-conditioned pairs.
#[must_use]
pub fn reciprocity<B: Bxdf<Spectrum = f32> + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut rng = Pcg32::new(config.seed, 0x0072_6563);
    let tol = config.reciprocity_tolerance;
    let (mut worst, mut ill, mut failures) = (0.0_f64, 0usize, 0usize);
    let mut detail = String::new();
    for _ in 0..config.pairs {
        let (wo, wi) = (
            uniform_sphere(rng.next_vec2()),
            uniform_sphere(rng.next_vec2()),
        );
        let r = reciprocity_pair(bxdf, wo, wi, config.eta);
        if !r.holds(tol) {
            if failures == 0 {
                detail = format!(
                    "first failure at wo = {wo:?}, wi = {wi:?}: {:.6e} vs {:.6e}",
                    r.forward, r.backward
                );
            }
            failures += 1;
        }
        let scale = r.forward.abs().max(r.backward.abs());
        if r.forward.is_nan() || r.backward.is_nan() {
            // Not a number: no figure can stand for it (`max` would drop it).
            worst = f64::NAN;
        } else if scale > 1e3 * SUBNORMAL_FLOOR && r.round_off - SUBNORMAL_FLOOR <= tol * scale {
            worst = worst.max(r.relative_error());
        } else if scale > 0.0 {
            ill += 1;
        }
    }
    if failures == 0 {
        detail = format!("{ill} ill-conditioned pairs checked against their round-off only");
    } else {
        detail = format!("{failures} pairs failed; {detail}");
    }
    LawReport {
        law: Law::Reciprocity,
        passed: failures == 0,
        figure: worst,
        uncertainty: 0.0,
        figure_name: "max relative error",
        budget: format!("{} pairs, η = {}", config.pairs, config.eta),
        detail,
    }
}

/// The directional albedo at `wo` by two independent estimators.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Albedo {
    /// By the model's own sampler, delta lobes included.
    pub sampled: Estimate,
    /// By cosine sampling, or `None` for a model with delta lobes (which it cannot see).
    pub cosine: Option<Estimate>,
}

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` at `wo` by the model's sampler and, for
/// a model without delta lobes, by cosine sampling.
#[must_use]
pub fn albedo<B: Bxdf<Spectrum = f32> + ?Sized>(bxdf: &B, wo: Vec3, config: &Config) -> Albedo {
    let check = config.bxdf_check(config.albedo_samples);
    Albedo {
        sampled: albedo_sampled(bxdf, wo, &check),
        cosine: (!bxdf.lobes().is_specular()).then(|| albedo_cosine(bxdf, wo, &check)),
    }
}

/// **Energy bound** and **albedo estimators**: at every viewer direction the sampled albedo
/// is at most `config.albedo_bound` within `k` standard errors (Šidák-corrected `k`), and
/// the two estimators agree within `k` combined standard errors. Returns the two reports.
#[must_use]
pub fn energy_bound<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    config: &Config,
) -> (LawReport, Option<LawReport>) {
    let directions = config.viewer_directions(bxdf);
    let k = two_sided_quantile(sidak(config.significance, 2 * directions.len()));
    let mut largest: Option<(Estimate, Vec3)> = None;
    let mut bound_ok = true;
    // The largest gap between the estimators: (|Δ|, its standard error, wo).
    let mut worst_gap = (0.0_f64, 0.0_f64, Vec3::ZERO);
    let mut agreement_checked = false;
    let mut agreement_failure = None;
    for &wo in &directions {
        let a = albedo(bxdf, wo, config);
        let s = a.sampled;
        let allowance = k * s.std_err + F32_ROUND_OFF * config.albedo_bound;
        // Written so that a NaN estimate fails.
        bound_ok &= s.mean <= config.albedo_bound + allowance;
        if s.mean.is_nan() {
            largest = Some((s, wo));
        }
        if largest.is_none_or(|(l, _)| s.mean > l.mean && !l.mean.is_nan()) {
            largest = Some((s, wo));
        }
        if let Some(c) = a.cosine {
            agreement_checked = true;
            let sigma = (s.std_err.powi(2) + c.std_err.powi(2)).sqrt();
            let diff = (s.mean - c.mean).abs();
            let agrees = diff <= k * sigma + F32_ROUND_OFF * s.mean.abs();
            if !agrees && agreement_failure.is_none() {
                agreement_failure = Some(format!("at wo = {wo:?}: sampled {s}, cosine {c}"));
            }
            if diff > worst_gap.0 || diff.is_nan() {
                worst_gap = (diff, sigma, wo);
            }
        }
    }
    let (best, at) = largest.unwrap_or((
        Estimate {
            mean: 0.0,
            std_err: 0.0,
            n: 0,
        },
        Vec3::Z,
    ));
    let budget = format!(
        "{} samples × {} directions, k = {k:.2}",
        config.albedo_samples,
        directions.len()
    );
    let bound = LawReport {
        law: Law::EnergyBound,
        passed: bound_ok,
        figure: best.mean,
        uncertainty: best.std_err,
        figure_name: "max albedo",
        budget: budget.clone(),
        detail: format!(
            "largest {best} at wo = {at:?}, bound {}",
            config.albedo_bound
        ),
    };
    let agreement = agreement_checked.then(|| LawReport {
        law: Law::AlbedoEstimators,
        passed: agreement_failure.is_none(),
        figure: worst_gap.0,
        uncertainty: worst_gap.1,
        figure_name: "max |sampled − cosine|",
        budget,
        detail: agreement_failure.unwrap_or_else(|| format!("largest at wo = {:?}", worst_gap.2)),
    });
    (bound, agreement)
}

/// **Sampling**: the chi-square test of `sample` against `pdf` at every viewer direction,
/// Šidák-corrected over the directions. The figure is the smallest p-value. Delta-lobe
/// samples count as "no sample" (see [`chi2_bxdf`]).
#[must_use]
pub fn sampling_chi2<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let directions = config.viewer_directions(bxdf);
    let significance = sidak(config.significance, directions.len());
    let mut min_p = (1.0_f64, Vec3::Z);
    let mut failure = None;
    for (i, &wo) in directions.iter().enumerate() {
        let chi = Chi2Config {
            samples: config.chi2_samples,
            seed: config.seed.wrapping_add(i as u64),
            significance,
            ..Chi2Config::default()
        };
        let r = chi2_bxdf(bxdf, wo, &chi);
        if r.p_value < min_p.0 {
            min_p = (r.p_value, wo);
        }
        if !r.passed() && failure.is_none() {
            failure = Some(format!(
                "at wo = {wo:?}: p = {:.3e}, {} samples in zero-density bins, {} invalid samples, \
                 {} invalid pdf values, {} samples rejected (expected {:.1})",
                r.p_value,
                r.zero_bin_hits,
                r.invalid_samples,
                r.invalid_pdf_values,
                r.rejected_samples,
                r.expected_rejected
            ));
        }
    }
    LawReport {
        law: Law::Sampling,
        passed: failure.is_none(),
        figure: min_p.0,
        uncertainty: 0.0,
        figure_name: "min p-value",
        budget: format!(
            "{} samples × {} directions, significance {significance:.1e} each",
            config.chi2_samples,
            directions.len()
        ),
        detail: failure.unwrap_or_else(|| format!("smallest at wo = {:?}", min_p.1)),
    }
}

/// **Consistency**: `sample`'s `f` and `pdf` equal `eval` and `pdf` at the sampled direction
/// within `config.consistency_tolerance` (relative). The figure is the largest relative
/// difference.
#[must_use]
pub fn consistency<B: Bxdf<Spectrum = f32> + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let check = config.bxdf_check(config.consistency_samples);
    let mut worst = (0.0_f64, Vec3::Z);
    for wo in config.viewer_directions(bxdf) {
        let (f, p) = sample_consistency(bxdf, wo, &check);
        // `f64::max` would drop a NaN: keep it, so that it fails.
        let gap = if f.is_nan() || p.is_nan() {
            f64::NAN
        } else {
            f.max(p)
        };
        if gap > worst.0 || gap.is_nan() {
            worst = (gap, wo);
        }
    }
    LawReport {
        law: Law::Consistency,
        passed: worst.0 <= config.consistency_tolerance, // false for NaN
        figure: worst.0,
        uncertainty: 0.0,
        figure_name: "max relative difference",
        budget: format!("{} samples per direction", config.consistency_samples),
        detail: format!(
            "largest at wo = {:?}, tolerance {:.0e}",
            worst.1, config.consistency_tolerance
        ),
    }
}

/// Runs every law that applies to `bxdf`: positivity, the energy bound, and — for a model with
/// a lobe that has a density — reciprocity, sampling and consistency; the agreement of the two
/// albedo estimators for a model without delta lobes.
///
/// ```
/// use lobe::bxdf::Lambert;
/// use lobe::verify::{check_bxdf, Config};
/// let quick = Config { albedo_samples: 20_000, chi2_samples: 50_000, pairs: 2_000, ..Config::default() };
/// let report = check_bxdf("Lambert", &Lambert::new(0.8_f32)?, &quick);
/// assert!(report.passed(), "{report}");
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[must_use]
pub fn check_bxdf<B: Bxdf<Spectrum = f32> + ?Sized>(
    name: &str,
    bxdf: &B,
    config: &Config,
) -> Report {
    let mut laws = Vec::new();
    laws.push(positivity(bxdf, config));
    // A model made only of delta lobes has `eval = 0` everywhere: nothing to compare.
    if bxdf.lobes().is_non_specular() {
        laws.push(reciprocity(bxdf, config));
    }
    let (bound, agreement) = energy_bound(bxdf, config);
    laws.push(bound);
    laws.extend(agreement);
    if bxdf.lobes().is_non_specular() {
        laws.push(sampling_chi2(bxdf, config));
        laws.push(consistency(bxdf, config));
    }
    Report {
        name: name.into(),
        laws,
    }
}
