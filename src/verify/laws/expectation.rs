//! The laws of a stochastic BSDF, checked in expectation: reciprocity of the expected value,
//! the sampler against the expected density (chi-square), and the sampled weight against the
//! expected value; [`check_bxdf_in_expectation`] runs them with the laws that hold as they
//! are (positivity, the energy bound and the estimators' agreement).
//!
//! A [`stochastic`](Bxdf::stochastic) model's `eval` and `pdf` are Monte Carlo estimates (a
//! layered BSDF's random walk): one evaluation is noisy, so a law cannot be checked pair by
//! pair to round-off. Its seeded variants ([`Bxdf::eval_seeded`], [`Bxdf::pdf_seeded`]) give
//! independent estimates; each check here averages `k` of them and compares with the
//! standard errors:
//!
//! * **reciprocity**: `E[f(wo, wi)] / η_o² = E[f(wi, wo)] / η_i²` within `k` combined
//!   standard errors for each pair (Šidák-corrected over the pairs and channels);
//! * **sampling**: Pearson's statistic of `sample`'s histogram against the counts the
//!   *expected* density predicts, each bin's mass estimated by averaging `pdf_seeded` over
//!   stratified points of the bin (its variance from the differences of neighbouring strata,
//!   not the points' spread); that variance is added to each term's denominator,
//!   `Σ (O − E)² / (E + Var Ê)`, so that a noisy density weakens the test rather than fail a
//!   correct model by its noise (but see **Calibration** below: skewed estimates understate
//!   their own spread);
//! * **consistency**: in every bin, the mean of `sample`'s weight `f |cos θi| / pdf` over the
//!   samples that land there equals `∫_bin E[f] |cos θi| dωi`, estimated by averaging
//!   `eval_seeded` over stratified points of the bin, within `k` combined standard errors
//!   (Šidák-corrected over the bins, directions and channels). This is what a renderer relies
//!   on: the sampled weight and the evaluated value describe the same BSDF.
//!
//! The samples that drew nothing (`None`, or a delta lobe the histogram cannot place) are
//! expected `N (1 − Σ mass)` times. Their count is one of the chi-square's cells when it
//! expects at least 5, and is always tested alone too, by the Poisson chance of as many or
//! more for the expectation raised by `k` of its own standard errors; the chi-square and this
//! test share the direction's significance (Šidák), as in [`chi2_sphere`](crate::verify::chi2_sphere)'s no-sample bin.
//!
//! The energy bound and the agreement of the two albedo estimators hold as they are: every
//! sample is an independent estimate already (the sampler's own random numbers, and `eval` at
//! a new direction each time).
//!
//! **Calibration.** The comparisons take the standard errors from the estimates themselves,
//! so they assume the estimates' spread is finite and not dominated by rare large values. A
//! layered model's estimates are skewed (a coated conductor's `eval` has a kurtosis up to
//! ~270 where two sharp lobes meet) and an average of few of them underestimates its own
//! spread more often than not, which makes a test reject a correct model more often than its
//! significance says. With the default 64 estimates a side and 1,024 a bin, 20 seeds of a
//! coated conductor (coat `α = 0.1` over a gold `α = 0.3`) gave a median smallest p-value
//! over five directions of 0.039 (0.13 expected) and a median largest bin gap of 3.53 σ
//! (about 3.1 expected for ~300 bins), none rejected at the default significance; with 256
//! estimates (4,096 a bin), 0.16 and 3.28 σ over 8 seeds. Raise
//! [`Config::expectation_evaluations`] for models with sharper lobes. (Until the bins'
//! variance was taken from neighbouring strata, the same runs gave 0.15 and 3.05 σ: the
//! points' spread, which counts the density's variation across a bin, hid the skew at the
//! cost of the test's power.)

use super::bxdf::{SUBNORMAL_FLOOR, channels, energy_bound, positivity, worst_channel};
use super::config::Config;
use super::report::{Law, LawReport, Report};
use crate::Spectrum;
use crate::bxdf::Bxdf;
use crate::math::mix64;
use crate::sampling::uniform_sphere;
use crate::verify::stats::{Accumulator, Pcg32, chi2_survival, gamma_p, sidak, two_sided_quantile};
use glam::Vec3;
use std::f64::consts::TAU;
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

/// Bins in `cos θ ∈ [−1, 1]` of the expectation checks (equal area).
const THETA_BINS: usize = 8;
/// Bins in `φ`.
const PHI_BINS: usize = 16;
/// Points per bin at which the expected density and value are estimated, per unit of
/// [`Config::expectation_evaluations`].
const POINTS_PER_EVALUATION: usize = 16;
/// The chi-square test pools bins expecting fewer samples than this.
const MIN_EXPECTED: f64 = 5.0;
/// The weight test pools bins with fewer samples than this (a bin's mean weight must be
/// nearly normal for a z-test).
const MIN_SAMPLES: u64 = 100;
/// The generator streams of these checks.
const STREAM_RECIPROCITY: u64 = 0x0065_7872;
const STREAM_POINTS: u64 = 0x0065_7870;
const STREAM_SAMPLES: u64 = 0x0065_7873;

/// The seed of estimate `k` of the `i`-th value a check averages: a hash of the three, so
/// that seeds repeat only by a 2⁻⁶⁴ chance for any counts and configured seeds (bit fields
/// `s << 44 ^ i << 20 ^ k` collided once `k` reached 2²⁰, or seeds differed by 2²⁰).
fn estimate_seed(config_seed: u64, i: u64, k: u64) -> u64 {
    mix64(mix64(mix64(config_seed) ^ i) ^ k)
}

// ---------------------------------------------------------------------------------------
// Reciprocity
// ---------------------------------------------------------------------------------------

/// One reciprocity pair measured in expectation: the mean of `k` independent estimates of each
/// side, with their standard errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExpectedPair {
    /// `E[f(wo, wi)] / η_o²`, estimated.
    pub forward: crate::verify::Estimate,
    /// `E[f(wi, wo)] / η_i²`, estimated.
    pub backward: crate::verify::Estimate,
}

impl ExpectedPair {
    /// `|forward − backward|` in combined standard errors: `0` when the means agree to 1e-5
    /// relative (round-off), `∞` when they differ with no spread, NaN when a mean or a standard
    /// error is not finite (an infinite estimate: no claim, and a failed check).
    #[must_use]
    pub fn z_score(&self) -> f64 {
        if !(self.forward.is_finite() && self.backward.is_finite()) {
            return f64::NAN;
        }
        let d = (self.forward.mean - self.backward.mean).abs();
        let s = (self.forward.std_err.powi(2) + self.backward.std_err.powi(2)).sqrt();
        let round_off = 1e-5 * self.forward.mean.abs().max(self.backward.mean.abs());
        if d <= round_off + SUBNORMAL_FLOOR {
            0.0
        } else if s > 0.0 {
            d / s
        } else {
            f64::INFINITY
        }
    }
}

/// Measures reciprocity in expectation for one pair: `k` estimates of `f(wo, wi)/η_o²` and `k`
/// of `f(wi, wo)/η_i²` (`η` the index below the surface, as in
/// [`reciprocity_pair`](super::reciprocity_pair)), each with its own seed from `seed`.
#[must_use]
pub fn reciprocity_pair_in_expectation<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
    k: usize,
    seed: u64,
) -> ExpectedPair {
    expected_pair_channels(bxdf, wo, wi, eta, k, seed, 0)[0]
}

/// [`reciprocity_pair_in_expectation`] of every channel.
fn expected_pair_channels<B: Bxdf + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
    k: usize,
    seed: u64,
    index: u64,
) -> Vec<ExpectedPair> {
    let side = |w: Vec3| if w.z >= 0.0 { 1.0 } else { f64::from(eta) };
    let n = channels(bxdf);
    let (mut fwd, mut bwd) = (vec![Accumulator::new(); n], vec![Accumulator::new(); n]);
    let (so, si) = (side(wo) * side(wo), side(wi) * side(wi));
    for j in 0..k as u64 {
        let f = bxdf.eval_seeded(wo, wi, estimate_seed(seed, 2 * index, j));
        let b = bxdf.eval_seeded(wi, wo, estimate_seed(seed, 2 * index + 1, j));
        for c in 0..n {
            fwd[c].push(f64::from(f.channel(c)) / so);
            bwd[c].push(f64::from(b.channel(c)) / si);
        }
    }
    fwd.iter()
        .zip(&bwd)
        .map(|(f, b)| ExpectedPair {
            forward: f.finish(),
            backward: b.finish(),
        })
        .collect()
}

/// **Reciprocity in expectation**: over `config.expectation_pairs` random pairs (on the upper
/// hemisphere for a model that does not transmit, on the sphere otherwise), the means of
/// `config.expectation_evaluations` independent estimates of each side agree within `k`
/// combined standard errors, `k` Šidák-corrected over the pairs and channels; `config.eta`
/// gives the generalised form. The figure is the largest gap in standard errors.
#[must_use]
pub fn reciprocity_in_expectation<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut rng = Pcg32::new(config.seed, STREAM_RECIPROCITY);
    let n = channels(bxdf);
    let pairs = config.expectation_pairs;
    let k_sigma = two_sided_quantile(sidak(config.significance, pairs * n));
    let transmissive = bxdf.lobes().is_transmissive();
    let mut worst = vec![(0.0_f64, Vec3::Z, Vec3::Z); n];
    let mut failures = vec![(0usize, String::new()); n];
    for i in 0..pairs {
        let (mut wo, mut wi) = (
            uniform_sphere(rng.next_vec2()),
            uniform_sphere(rng.next_vec2()),
        );
        if !transmissive {
            wo.z = wo.z.abs();
            wi.z = wi.z.abs();
        }
        let measured = expected_pair_channels(
            bxdf,
            wo,
            wi,
            config.eta,
            config.expectation_evaluations,
            config.seed,
            i as u64,
        );
        for (c, p) in measured.iter().enumerate() {
            let z = p.z_score();
            if z.is_nan() || z > worst[c].0 {
                worst[c] = (z, wo, wi);
            }
            if !(z <= k_sigma) {
                if failures[c].0 == 0 {
                    failures[c].1 = format!(
                        "first failure at wo = {wo:?}, wi = {wi:?}: {} vs {}",
                        p.forward, p.backward
                    );
                }
                failures[c].0 += 1;
            }
        }
    }
    let reports = worst
        .into_iter()
        .zip(failures)
        .map(|((z, wo, wi), (failed, first))| LawReport {
            law: Law::Reciprocity,
            passed: failed == 0,
            figure: z,
            uncertainty: 0.0,
            figure_name: "max |Δ|/σ (in expectation)",
            budget: format!(
                "{pairs} pairs × {} estimates per side, k = {k_sigma:.2}, η = {}",
                config.expectation_evaluations, config.eta
            ),
            detail: if failed == 0 {
                format!("largest at wo = {wo:?}, wi = {wi:?}")
            } else {
                format!("{failed} pairs failed; {first}")
            },
        })
        .collect();
    worst_channel(reports)
}

// ---------------------------------------------------------------------------------------
// Sampling and consistency
// ---------------------------------------------------------------------------------------

/// The bin of a unit direction.
fn bin_of(w: Vec3) -> Option<usize> {
    let (x, y, z) = (f64::from(w.x), f64::from(w.y), f64::from(w.z));
    let len = (x * x + y * y + z * z).sqrt();
    if !w.is_finite() || (len - 1.0).abs() > 1e-3 {
        return None;
    }
    let t = ((0.5 * (z / len + 1.0) * THETA_BINS as f64) as usize).min(THETA_BINS - 1);
    let phi = y.atan2(x);
    let phi = if phi < 0.0 { phi + TAU } else { phi };
    let p = ((phi / TAU * PHI_BINS as f64) as usize).min(PHI_BINS - 1);
    Some(t * PHI_BINS + p)
}

/// The solid angle of a bin.
fn bin_area() -> f64 {
    (2.0 / THETA_BINS as f64) * (TAU / PHI_BINS as f64)
}

/// The mean of a bin's stratified points and its variance, from the differences of the points
/// in pairs of neighbouring strata (strata `2i` and `2i + 1` of a column of [`bin_point`]'s
/// grid, neighbours in `cos θ`; with an odd number of rows each column's last stratum is
/// left unpaired): `Var x̄ ≈ Σ (a − b)² / m²`, since `E[(a − b)²] = Var a + Var b +
/// (μa − μb)²` for independent points, and neighbouring strata's means differ little. A
/// stratified estimate's variance is its points' own noise (a stochastic model's estimates),
/// not the integrand's variation across the bin, which the points' spread would count (the
/// paired-difference estimator of a systematic or finely stratified sample: Wolter 2007,
/// *Introduction to Variance Estimation*, 2nd ed., on systematic sampling).
#[derive(Clone, Copy, Debug, Default)]
struct Stratified {
    sum: f64,
    /// The sum of the squared differences within pairs.
    diff2: f64,
    n: u64,
    pairs: u64,
    /// The first point of the pair being filled.
    first: Option<f64>,
}

impl Stratified {
    /// Adds the next stratum's point: the first or second of a pair, or (`lone`) a stratum
    /// without a neighbour to pair with.
    fn push(&mut self, x: f64, lone: bool) {
        self.sum += x;
        self.n += 1;
        if lone {
            return;
        }
        match self.first.take() {
            Some(a) => {
                self.diff2 += (x - a) * (x - a);
                self.pairs += 1;
            }
            None => self.first = Some(x),
        }
    }

    /// The mean of the points (NaN with none).
    fn mean(&self) -> f64 {
        if self.n == 0 {
            f64::NAN
        } else {
            self.sum / self.n as f64
        }
    }

    /// The variance of [`mean`](Self::mean); 0 without a pair. Unpaired points count as
    /// the pairs' average.
    fn variance_of_mean(&self) -> f64 {
        if self.pairs == 0 {
            return 0.0;
        }
        let n = self.n as f64;
        self.diff2 * (n / (2 * self.pairs) as f64) / (n * n)
    }
}

/// True for the stratum `j` of [`bin_point`]'s grid of `rows` rows that [`Stratified`] leaves
/// unpaired: an odd column's last (its strata are `j % rows` in `cos θ`, paired `0–1`,
/// `2–3`, …).
#[inline]
fn unpaired(j: usize, rows: usize) -> bool {
    rows % 2 == 1 && j % rows == rows - 1
}

/// The grid of `m` strata of a bin, `(rows, cols)` in `(cos θ, φ)`: `rows` the largest
/// divisor of `m` not above `√m`, so that `rows · cols = m` (`√m × √m` for a square `m`).
fn strata(m: usize) -> (usize, usize) {
    let m = m.max(1);
    let rows = (1..=m.isqrt())
        .rev()
        .find(|&d| m.is_multiple_of(d))
        .unwrap_or(1);
    (rows, m / rows)
}

/// A point of bin `b`, stratum `j` of `m`: a grid of [`strata`], jittered. Every stratum is used once, so the `m` points are a stratified uniform sample of the bin
/// (a `⌈√m⌉ × ⌈√m⌉` grid of which only the first `m` strata were used left a band of the bin
/// unsampled when `m` is not a square).
fn bin_point(b: usize, j: usize, m: usize, rng: &mut Pcg32) -> Vec3 {
    let (rows, cols) = strata(m);
    let (sj, sk) = (j % rows, j / rows);
    let (t, p) = (b / PHI_BINS, b % PHI_BINS);
    let u = rng.next_vec2();
    let c =
        -1.0 + 2.0 * (t as f64 + (sj as f64 + f64::from(u.x)) / rows as f64) / THETA_BINS as f64;
    let phi = TAU * (p as f64 + (sk as f64 + f64::from(u.y)) / cols as f64) / PHI_BINS as f64;
    let c = c.clamp(-1.0, 1.0);
    let s = (1.0 - c * c).max(0.0).sqrt();
    Vec3::new((s * phi.cos()) as f32, (s * phi.sin()) as f32, c as f32)
}

/// What the sampling and consistency checks measured at one viewer direction.
struct DirectionMeasure {
    /// The chi-square statistic, its degrees of freedom and p-value, and the bins the
    /// sampler hit where the estimated density was zero everywhere.
    statistic: f64,
    dof: usize,
    p_value: f64,
    zero_hits: u64,
    /// The samples that drew nothing, their expected count and the chance of as many.
    missing: u64,
    expected_missing: f64,
    missing_p: f64,
    /// Per channel: the largest `|Δ|/σ` of the weight test and its bin.
    weight_z: Vec<(f64, usize)>,
}

/// Both measurements at `wo`, from one set of samples and one set of bin points.
fn measure_direction<B: Bxdf + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    config: &Config,
    index: u64,
    missing_significance: f64,
) -> DirectionMeasure {
    let nbins = THETA_BINS * PHI_BINS;
    let n = channels(bxdf);
    let samples = config.chi2_samples;
    // The sampler's histogram and the weight sums per bin and channel.
    let mut observed = vec![0_u64; nbins];
    let mut weight_sum = vec![vec![0.0_f64; n]; nbins];
    let mut weight_sq = vec![vec![0.0_f64; n]; nbins];
    let mut missing = 0_u64;
    let mut rng = Pcg32::new(config.seed.wrapping_add(index), STREAM_SAMPLES);
    for _ in 0..samples {
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        match bxdf
            .sample(wo, u, uc)
            .filter(|s| !s.is_specular())
            .and_then(|s| bin_of(s.wi).map(|b| (b, s)))
        {
            Some((b, s)) => {
                observed[b] += 1;
                let w = s.weight();
                for c in 0..n {
                    let x = f64::from(w.channel(c));
                    weight_sum[b][c] += x;
                    weight_sq[b][c] += x * x;
                }
            }
            None => missing += 1,
        }
    }
    // The expected density's and value's bin integrals, with the variance of a stratified
    // estimate: from neighbouring strata taken in pairs ([`Stratified`]). (The points' spread,
    // used before, counts the density's variation across the bin, which a stratified estimate
    // does not have: a correct model's p-values crowded toward 1, median 0.98 over 12 seeds,
    // and a density 1% off passed.)
    let m = POINTS_PER_EVALUATION * config.expectation_evaluations.max(1);
    let area = bin_area();
    let mut prng = Pcg32::new(config.seed.wrapping_add(index), STREAM_POINTS);
    let mut mass = vec![Stratified::default(); nbins];
    let mut value = vec![vec![Stratified::default(); n]; nbins];
    let mut point = 0_u64;
    let rows = strata(m).0;
    for b in 0..nbins {
        for j in 0..m {
            let w = bin_point(b, j, m, &mut prng);
            let seed = estimate_seed(config.seed, index, point);
            point += 1;
            let lone = unpaired(j, rows);
            mass[b].push(f64::from(bxdf.pdf_seeded(wo, w, seed)) * area, lone);
            let f = bxdf.eval_seeded(wo, w, seed);
            let cos = f64::from(w.z.abs()) * area;
            for (c, v) in value[b].iter_mut().enumerate() {
                v.push(f64::from(f.channel(c)) * cos, lone);
            }
        }
    }
    let total = samples as f64;

    // Chi-square against the expected density, with the estimate's variance.
    let mut cells: Vec<(f64, f64, f64)> = Vec::with_capacity(nbins + 1); // (O, E, Var E)
    let mut zero_hits = 0;
    let (mut mass_total, mut mass_var) = (0.0, 0.0);
    for b in 0..nbins {
        let (mean, var) = (mass[b].mean(), mass[b].variance_of_mean());
        mass_total += mean;
        mass_var += var;
        if mean <= 0.0 && observed[b] > 0 {
            zero_hits += observed[b];
            continue;
        }
        if mean > 0.0 || observed[b] > 0 {
            cells.push((observed[b] as f64, total * mean, total * total * var));
        }
    }
    // The samples that drew nothing: one of the chi-square's cells when it expects enough, never
    // merged into another (merged into a direction bin, 390 failures against none expected passed
    // with p = 0.0044), and always tested alone: the Poisson chance of as many or more for the
    // expectation raised by k of its own standard errors. The test's share of the significance, α,
    // is halved between the raise (k = Φ⁻¹(1 − α/2): the estimate falls that far below the true
    // expectation with probability α/2) and the Poisson tail (rejected below α/2), so that a
    // correct model fails it with probability α at most. The direction's significance is shared
    // with the chi-square (Šidák). A small pool of bins may still be merged into this cell, when it
    // is the smallest kept (below).
    let expected_missing = total * (1.0 - mass_total).max(0.0);
    if expected_missing >= MIN_EXPECTED {
        cells.push((missing as f64, expected_missing, total * total * mass_var));
    }
    let missing_p = if missing == 0 {
        1.0
    } else {
        let raised = expected_missing
            + two_sided_quantile(missing_significance) * total * mass_var.max(0.0).sqrt();
        gamma_p(missing as f64, raised.max(f64::MIN_POSITIVE))
    };
    let (mut kept, small): (Vec<_>, Vec<_>) = cells.into_iter().partition(|c| c.1 >= MIN_EXPECTED);
    if !small.is_empty() {
        let pool = small
            .iter()
            .fold((0.0, 0.0, 0.0), |a, c| (a.0 + c.0, a.1 + c.1, a.2 + c.2));
        if pool.1 >= MIN_EXPECTED || kept.is_empty() {
            kept.push(pool);
        } else if let Some(smallest) = kept
            .iter_mut()
            .min_by(|a, b| a.1.partial_cmp(&b.1).unwrap_or(core::cmp::Ordering::Equal))
        {
            smallest.0 += pool.0;
            smallest.1 += pool.1;
            smallest.2 += pool.2;
        }
    }
    let statistic: f64 = kept
        .iter()
        .map(|&(o, e, v)| {
            let d = o - e;
            if d == 0.0 { 0.0 } else { d * d / (e + v) }
        })
        .sum();
    let dof = kept.len().saturating_sub(1);
    let p_value = if dof == 0 {
        f64::NAN
    } else {
        chi2_survival(statistic, dof)
    };

    // The sampled weight against the expected value, bin by bin (pooling sparse bins).
    let mut weight_z = vec![(0.0_f64, 0usize); n];
    for (c, wz) in weight_z.iter_mut().enumerate() {
        // (sampled mean, its variance, evaluated integral, its variance, bin)
        let mut pool = (0.0, 0.0, 0.0, 0.0);
        let mut rows = Vec::with_capacity(nbins + 1);
        for b in 0..nbins {
            let s = weight_sum[b][c] / total;
            let s_var = (weight_sq[b][c] / total - s * s).max(0.0) / (total - 1.0).max(1.0);
            let (e, e_var) = (value[b][c].mean(), value[b][c].variance_of_mean());
            if observed[b] >= MIN_SAMPLES {
                rows.push((s, s_var, e, e_var, b));
            } else {
                pool = (pool.0 + s, pool.1 + s_var, pool.2 + e, pool.3 + e_var);
            }
        }
        rows.push((pool.0, pool.1, pool.2, pool.3, nbins));
        for (s, sv, e, ev, b) in rows {
            let d = (s - e).abs();
            let sigma = (sv + ev).sqrt();
            let z = if d <= 1e-6 * s.abs().max(e.abs()) + 1e-30 {
                0.0
            } else if sigma > 0.0 {
                d / sigma
            } else {
                f64::INFINITY
            };
            if z.is_nan() || z > wz.0 {
                *wz = (z, b);
            }
        }
    }
    DirectionMeasure {
        statistic,
        dof,
        p_value,
        zero_hits,
        missing,
        expected_missing,
        missing_p,
        weight_z,
    }
}

/// What a bin index says in a report.
fn bin_name(b: usize) -> String {
    if b >= THETA_BINS * PHI_BINS {
        String::from("the pool of sparse bins")
    } else {
        let (t, p) = (b / PHI_BINS, b % PHI_BINS);
        let c0 = -1.0 + 2.0 * t as f64 / THETA_BINS as f64;
        format!(
            "bin cos θ ∈ [{c0:.2}, {:.2}), φ bin {p} of {PHI_BINS}",
            c0 + 2.0 / THETA_BINS as f64
        )
    }
}

/// **Sampling** and **consistency** in expectation, from the same samples: the reports of
/// [`sampling_in_expectation`] and [`consistency_in_expectation`].
#[must_use]
pub fn sampling_and_consistency_in_expectation<B: Bxdf + ?Sized>(
    bxdf: &B,
    config: &Config,
) -> (LawReport, LawReport) {
    let directions = config.viewer_directions(bxdf);
    let n = channels(bxdf);
    // Per direction, the chi-square and the test of the samples that drew nothing.
    let chi_significance = sidak(config.significance, 2 * directions.len());
    let bins = THETA_BINS * PHI_BINS + 1;
    let k_sigma = two_sided_quantile(sidak(config.significance, directions.len() * n * bins));
    let mut min_p = (1.0_f64, Vec3::Z);
    let mut chi_failure: Option<String> = None;
    let mut worst = vec![(0.0_f64, Vec3::Z, 0usize); n];
    let mut weight_failure: Vec<Option<String>> = vec![None; n];
    for (i, &wo) in directions.iter().enumerate() {
        let d = measure_direction(bxdf, wo, config, i as u64, chi_significance);
        let chi_passed = d.zero_hits == 0 && d.dof >= 1 && d.p_value >= chi_significance;
        // Half the share for the tail, half for the expectation's raise (above).
        let missing_passed = d.missing_p >= 0.5 * chi_significance;
        if d.p_value < min_p.0 || d.p_value.is_nan() {
            min_p = (d.p_value, wo);
        }
        if !(chi_passed && missing_passed) && chi_failure.is_none() {
            let mut why = format!("at wo = {wo:?}:");
            if !chi_passed {
                why += &format!(
                    " χ² = {:.1} with {} dof, p = {:.3e}, {} samples in bins of zero expected \
                     density;",
                    d.statistic, d.dof, d.p_value, d.zero_hits
                );
            }
            if !missing_passed {
                why += &format!(
                    " too many samples drew nothing: {} (expected {:.1}, p = {:.3e});",
                    d.missing, d.expected_missing, d.missing_p
                );
            }
            chi_failure = Some(why);
        }
        for (c, &(z, b)) in d.weight_z.iter().enumerate() {
            if z > worst[c].0 || z.is_nan() {
                worst[c] = (z, wo, b);
            }
            if !(z <= k_sigma) && weight_failure[c].is_none() {
                weight_failure[c] = Some(format!(
                    "at wo = {wo:?}, {}: sampled weight and eval differ by {z:.1} σ",
                    bin_name(b)
                ));
            }
        }
    }
    let m = POINTS_PER_EVALUATION * config.expectation_evaluations.max(1);
    let sampling = LawReport {
        law: Law::Sampling,
        passed: chi_failure.is_none(),
        figure: min_p.0,
        uncertainty: 0.0,
        figure_name: "min p-value (expected pdf)",
        budget: format!(
            "{} samples × {} directions, {THETA_BINS} × {PHI_BINS} bins of {m} pdf estimates, \
             significance {chi_significance:.1e} each",
            config.chi2_samples,
            directions.len()
        ),
        detail: chi_failure.unwrap_or_else(|| format!("smallest at wo = {:?}", min_p.1)),
    };
    let reports = worst
        .into_iter()
        .zip(weight_failure)
        .map(|((z, wo, b), failure)| LawReport {
            law: Law::Consistency,
            passed: failure.is_none(),
            figure: z,
            uncertainty: 0.0,
            figure_name: "max |weight − eval|/σ per bin",
            budget: format!(
                "{} samples × {} directions, {m} eval estimates per bin, k = {k_sigma:.2}",
                config.chi2_samples,
                directions.len()
            ),
            detail: failure.unwrap_or_else(|| format!("largest at wo = {wo:?}, {}", bin_name(b))),
        })
        .collect();
    (sampling, worst_channel(reports))
}

/// **Sampling in expectation**: at every viewer direction, Pearson's chi-square of
/// `config.chi2_samples` samples against the counts of the *expected* density, each bin's mass the
/// mean of `16 × config.expectation_evaluations` seeded `pdf` estimates at stratified points of the
/// bin, its variance added to the term's denominator. `8 × 16` equal-area bins, low-count bins
/// pooled, delta samples and failures counted in a no-sample bin; Šidák over the directions and, at
/// each, between the chi-square and the no-sample test. The figure is the smallest p-value.
#[must_use]
pub fn sampling_in_expectation<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    sampling_and_consistency_in_expectation(bxdf, config).0
}

/// **Consistency in expectation**: at every viewer direction and in every bin (bins with
/// fewer than 100 samples pooled), the mean of `sample`'s weight `f |cos θi| / pdf` times the
/// bin's indicator equals `∫_bin E[f] |cos θi| dωi`, estimated from
/// `16 × config.expectation_evaluations` seeded `eval` estimates at stratified points, within
/// `k` combined standard errors, Šidák-corrected over bins, directions and channels. The
/// figure is the largest gap in standard errors.
#[must_use]
pub fn consistency_in_expectation<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    sampling_and_consistency_in_expectation(bxdf, config).1
}

/// [`check_bxdf`](super::check_bxdf) for a [`stochastic`](Bxdf::stochastic) model (which
/// `check_bxdf` calls by itself for one): positivity and the energy bound with the
/// estimators' agreement as for any model, and reciprocity, sampling and consistency in
/// expectation ([`reciprocity_in_expectation`], [`sampling_in_expectation`],
/// [`consistency_in_expectation`]). Callable on an exact model too, where the expectation is
/// the value itself.
#[must_use]
pub fn check_bxdf_in_expectation<B: Bxdf + ?Sized>(
    name: &str,
    bxdf: &B,
    config: &Config,
) -> Report {
    let mut laws = vec![positivity(bxdf, config)];
    let density = bxdf.lobes().is_non_specular();
    // The statistical laws (reciprocity, the energy bound, sampling and consistency here: all
    // but positivity) share the run's significance.
    let shared = config.shared_among(1 + 3 * usize::from(density));
    if density {
        laws.push(reciprocity_in_expectation(bxdf, &shared));
    }
    let (bound, agreement) = energy_bound(bxdf, &shared);
    laws.push(bound);
    laws.extend(agreement);
    if density {
        let (sampling, consistency) = sampling_and_consistency_in_expectation(bxdf, &shared);
        laws.push(sampling);
        laws.push(consistency);
    }
    Report {
        name: name.into(),
        laws,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The points of a bin cover it evenly for any count: their mean position in the bin is
    /// its middle (within the jitter's standard error), for a square count and for counts that
    /// are not squares (16 × 128 = 2048 left one of 46 azimuth strata unsampled: mean 0.484).
    #[test]
    fn bin_points_cover_a_bin_evenly() {
        for m in [16_usize, 48, 2048, 1024] {
            let mut rng = Pcg32::new(3, 4);
            let b = 5 * PHI_BINS + 7;
            let (mut sum_c, mut sum_p) = (0.0_f64, 0.0_f64);
            for j in 0..m {
                let w = bin_point(b, j, m, &mut rng);
                assert_eq!(bin_of(w), Some(b), "{w:?}");
                let c = 0.5 * (f64::from(w.z) + 1.0) * THETA_BINS as f64 - 5.0;
                let phi = f64::from(w.y).atan2(f64::from(w.x)).rem_euclid(TAU);
                sum_c += c;
                sum_p += phi / TAU * PHI_BINS as f64 - 7.0;
            }
            // One jittered point per stratum of a rows × cols grid: the mean fraction along a
            // coordinate is ½ plus the jitters' mean less ½, over the strata across it, whose
            // standard deviation is 1/(√12 · √m · strata across): five of those.
            let (rows, cols) = strata(m);
            assert_eq!(rows * cols, m);
            let sd = |across: usize| 1.0 / (12.0_f64.sqrt() * (m as f64).sqrt() * across as f64);
            let (mc, mp) = (sum_c / m as f64, sum_p / m as f64);
            assert!(
                (mc - 0.5).abs() < 5.0 * sd(rows),
                "m {m}: mean cos fraction {mc}"
            );
            assert!(
                (mp - 0.5).abs() < 5.0 * sd(cols),
                "m {m}: mean φ fraction {mp}"
            );
        }
    }

    /// Estimate seeds do not repeat where the old bit fields did: across values once the
    /// estimates reach 2²⁰ (`(i, 2²⁰)` was `(i + 1, 0)`), and across configured seeds 2²⁰
    /// apart (shifted out of the word). Three values of 2²⁰ + 2 estimates, all distinct.
    #[test]
    fn estimate_seeds_do_not_collide() {
        let n = (1_u64 << 20) + 2;
        let mut seeds: Vec<u64> = (0..3)
            .flat_map(|i| (0..n).map(move |k| estimate_seed(7, i, k)))
            .collect();
        seeds.sort_unstable();
        seeds.dedup();
        assert_eq!(seeds.len() as u64, 3 * n);
        for (i, k) in [(0, 0), (1, 5), (2, 1 << 20)] {
            assert_ne!(estimate_seed(7, i, k), estimate_seed(7 + (1 << 20), i, k));
        }
    }

    /// The paired-difference variance is unbiased for a grid with an odd number of rows
    /// (15 strata: 3 rows of 5, each column's third stratum unpaired) and does not count a
    /// trend across the columns: over 40,000 replicates of independent noise (uniform,
    /// variance 1/12) on a mean that rises by 1 from column to column, the average estimate
    /// is the variance of the mean, 1/(12 · 15), within five of its standard errors. (The
    /// points' spread would have counted the trend: 2 per point, 24 times the noise.)
    #[test]
    fn stratified_variance_is_unbiased_with_unpaired_strata() {
        let m = 15;
        let (rows, cols) = strata(m);
        assert_eq!((rows, cols), (3, 5));
        let lone: Vec<usize> = (0..m).filter(|&j| unpaired(j, rows)).collect();
        assert_eq!(lone, [2, 5, 8, 11, 14]);
        assert!(
            (0..16).all(|j| !unpaired(j, strata(16).0)),
            "4 rows pair every stratum"
        );
        let mut rng = Pcg32::new(11, 12);
        let replicates = 40_000;
        let (mut est, mut est2) = (0.0_f64, 0.0_f64);
        for _ in 0..replicates {
            let mut s = Stratified::default();
            for j in 0..m {
                let column = (j / rows) as f64;
                s.push(column + rng.next_f64() - 0.5, unpaired(j, rows));
            }
            assert_eq!((s.n, s.pairs), (15, 5));
            let v = s.variance_of_mean();
            est += v;
            est2 += v * v;
        }
        let r = f64::from(replicates);
        let mean = est / r;
        let se = ((est2 / r - mean * mean) / r).sqrt();
        let want = 1.0 / (12.0 * 15.0);
        assert!(
            (mean - want).abs() < 5.0 * se,
            "{mean} against {want} ± {se}"
        );
    }

    #[test]
    fn bins_cover_the_sphere_with_equal_areas() {
        assert!((bin_area() * (THETA_BINS * PHI_BINS) as f64 - 2.0 * TAU).abs() < 1e-12);
        let mut rng = Pcg32::new(1, 2);
        for b in [0, 17, 64, THETA_BINS * PHI_BINS - 1] {
            for j in 0..16 {
                let w = bin_point(b, j, 16, &mut rng);
                assert_eq!(bin_of(w), Some(b), "{w:?}");
            }
        }
    }
}
