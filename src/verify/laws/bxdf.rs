//! The laws of a BSDF, measured, reported and checked: positivity, reciprocity (plain and
//! generalised across an interface), the energy bound by two independent albedo estimators,
//! the sampler against its pdf (chi-square), and the agreement of `sample` with `eval` and
//! `pdf`; [`check_bxdf`] runs every law that applies.
//!
//! The measurements come first (the albedo estimators, one reciprocity pair, the consistency
//! of one viewer direction), then the law reports built on them.
//!
//! The laws are checked on `f32` models (they hold per channel); a spectral model is checked
//! by instantiating it on `f32`.

use super::config::Config;
use super::report::{Law, LawReport, Report};
use crate::bxdf::Bxdf;
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, uniform_sphere};
use crate::verify::stats::{
    Accumulator, Chi2Config, Chi2Report, Estimate, Pcg32, chi2_sphere_rng, sidak,
    two_sided_quantile,
};
use glam::Vec3;
use std::format;
use std::string::String;
use std::vec::Vec;

/// The relative round-off of a weight computed in `f32` (a few ulps): what lets a
/// zero-variance estimator match an exact bound.
const F32_ROUND_OFF: f64 = 1e-6;

/// The stream of these checks' generator, apart from the chi-square test's.
const STREAM: u64 = 0x0062_7364;

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` estimated with the model's own sampler:
/// the mean of [`BxdfSample::weight`](crate::bxdf::BxdfSample::weight), a failed sample
/// counting as zero. Includes delta lobes.
#[must_use]
pub fn albedo_sampled<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> Estimate
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    let config = config.into();
    let mut rng = Pcg32::new(config.seed, STREAM);
    let mut acc = Accumulator::new();
    for _ in 0..config.albedo_samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        let w = bxdf
            .sample(wo, u, uc)
            .map_or(0.0, |s| f64::from(s.weight()));
        acc.push(w);
    }
    acc.finish()
}

/// The directional albedo estimated independently of the model's sampler: `wi` cosine-
/// distributed over the upper hemisphere, and also over the lower one (each with probability
/// ½) when the model transmits. Misses delta lobes, which have no density.
#[must_use]
pub fn albedo_cosine<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> Estimate
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    let config = config.into();
    let both_sides = bxdf.lobes().is_transmissive();
    let mut rng = Pcg32::new(config.seed, STREAM ^ 1);
    let mut acc = Accumulator::new();
    for _ in 0..config.albedo_samples {
        let mut wi = cosine_hemisphere(rng.next_vec2());
        let mut pdf = f64::from(cosine_hemisphere_pdf(wi.z));
        if both_sides {
            pdf *= 0.5;
            if rng.next_f32() < 0.5 {
                wi.z = -wi.z;
            }
        }
        let value = if pdf > 0.0 {
            f64::from(bxdf.eval(wo, wi)) * f64::from(wi.z.abs()) / pdf
        } else {
            0.0
        };
        acc.push(value);
    }
    acc.finish()
}

/// The chi-square test of [`Bxdf::sample`] against [`Bxdf::pdf`] for the viewer direction
/// `wo`. Samples from delta lobes, and failed samples, count as "no sample": `pdf` then
/// integrates to less than one, and the test checks that the missing mass matches them.
pub fn chi2_bxdf<B: Bxdf + ?Sized>(bxdf: &B, wo: Vec3, config: &Chi2Config) -> Chi2Report {
    chi2_sphere_rng(
        |rng| {
            let u = rng.next_vec2();
            let uc = rng.next_f32();
            bxdf.sample(wo, u, uc)
                .filter(|s| !s.is_specular())
                .map(|s| s.wi)
        },
        |wi| f64::from(bxdf.pdf(wo, wi)),
        config,
    )
}

/// How far [`Bxdf::sample`]'s `f` and `pdf` are from [`Bxdf::eval`] and [`Bxdf::pdf`] at the
/// sampled direction: the largest relative differences `(f, pdf)` over `config.consistency_samples`
/// non-delta samples; NaN if any comparison is NaN.
#[must_use]
pub fn sample_consistency<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> (f64, f64)
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    let config = config.into();
    let rel = |a: f32, b: f32| {
        let (a, b) = (f64::from(a), f64::from(b));
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    };
    let mut rng = Pcg32::new(config.seed, STREAM ^ 2);
    let (mut worst_f, mut worst_pdf) = (0.0_f64, 0.0_f64);
    for _ in 0..config.consistency_samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        if let Some(s) = bxdf.sample(wo, u, uc).filter(|s| !s.is_specular()) {
            // `f64::max` drops NaN; keep it, so that a NaN can only make things worse.
            let keep = |worst: f64, x: f64| {
                if x.is_nan() || worst.is_nan() {
                    f64::NAN
                } else {
                    worst.max(x)
                }
            };
            worst_f = keep(worst_f, rel(s.f, bxdf.eval(wo, s.wi)));
            worst_pdf = keep(worst_pdf, rel(s.pdf, bxdf.pdf(wo, s.wi)));
        }
    }
    (worst_f, worst_pdf)
}

/// One reciprocity measurement: the two sides of the (generalised) reciprocity relation for
/// a pair of directions, and how far apart f32 round-off alone can put them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReciprocityPair {
    /// `f(wo, wi) / η_o²`.
    pub forward: f64,
    /// `f(wi, wo) / η_i²`.
    pub backward: f64,
    /// The round-off allowance: the largest change of either side when `wo` or `wi` moves by
    /// a few ulps (four perturbations of `4 ε` radians each), twice, plus an absolute
    /// [`SUBNORMAL_FLOOR`]. An ill-conditioned pair (a microfacet seen edge-on) gets a large
    /// allowance; a well-conditioned one, almost none.
    pub round_off: f64,
}

impl ReciprocityPair {
    /// `|forward − backward| / max(|forward|, |backward|)`, zero when both are zero.
    #[must_use]
    pub fn relative_error(&self) -> f64 {
        let (a, b) = (self.forward, self.backward);
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    }

    /// True when the sides agree within `rel_tol` relative error plus the round-off
    /// allowance.
    #[must_use]
    pub fn holds(&self, rel_tol: f64) -> bool {
        let (a, b) = (self.forward, self.backward);
        (a - b).abs() <= rel_tol * a.abs().max(b.abs()) + self.round_off
    }
}

/// Values this small are products whose intermediate factors went below
/// `f32::MIN_POSITIVE` and lost their relative precision (a far tail of `D`); reciprocity is
/// not checked below it.
pub const SUBNORMAL_FLOOR: f64 = 1e-30;

/// Measures reciprocity for one pair: `f(wo, wi)/η_o²` against `f(wi, wo)/η_i²`, where
/// `η_o`, `η_i` are the indices on the sides of `wo` and `wi` (`1` above the surface, `eta`
/// below). With `eta = 1`, or both directions on one side, this is plain Helmholtz
/// reciprocity; across an interface it is the generalised form for radiance transport (Veach
/// 1997, eq. 5.12). For a model in importance mode pass `1/η`.
#[must_use]
pub fn reciprocity_pair<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
) -> ReciprocityPair {
    let side = |w: Vec3| if w.z >= 0.0 { 1.0 } else { f64::from(eta) };
    let forward = |a: Vec3, b: Vec3| f64::from(bxdf.eval(a, b)) / (side(a) * side(a));
    let (a, b) = (forward(wo, wi), forward(wi, wo));
    let mut spread = 0.0_f64;
    let eps = 4.0 * f32::EPSILON;
    for k in 0..4 {
        let (po, pi) = (nudge(wo, k, eps), nudge(wi, k, eps));
        spread = spread
            .max((forward(po, wi) - a).abs())
            .max((forward(wo, pi) - a).abs())
            .max((forward(wi, po) - b).abs())
            .max((forward(pi, wo) - b).abs());
    }
    ReciprocityPair {
        forward: a,
        backward: b,
        round_off: 2.0 * spread + SUBNORMAL_FLOOR,
    }
}

/// `w` turned by `eps` radians toward one of four tangent directions (`k` = 0…3).
fn nudge(w: Vec3, k: usize, eps: f32) -> Vec3 {
    let frame = crate::Frame::from_normal(w);
    let t = match k {
        0 => frame.x,
        1 => -frame.x,
        2 => frame.y,
        _ => -frame.y,
    };
    (w + t * eps).normalize()
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
/// [`ReciprocityPair`]); `config.eta` gives the generalised form. The
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
    Albedo {
        sampled: albedo_sampled(bxdf, wo, config),
        cosine: (!bxdf.lobes().is_specular()).then(|| albedo_cosine(bxdf, wo, config)),
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
    let mut worst = (0.0_f64, Vec3::Z);
    for wo in config.viewer_directions(bxdf) {
        let (f, p) = sample_consistency(bxdf, wo, config);
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
