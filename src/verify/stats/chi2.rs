//! Pearson's chi-square goodness-of-fit test of a direction sampler against its density:
//! its settings ([`Chi2Config`]), the test ([`chi2_sphere`], [`chi2_sphere_rng`]) and its
//! report. The expected counts come from the adaptive quadrature of
//! `integrate`; the p-value from [`chi2_survival`].

use super::gamma::{chi2_survival, gamma_p};
use super::integrate::Quadrature;
use super::rng::Pcg32;
use super::significance::sidak;
use glam::{Vec2, Vec3};
use std::f64::consts::TAU;
use std::fmt;
use std::vec;
use std::vec::Vec;

/// The PCG stream that [`chi2_sphere`] draws from (the seed comes from the configuration).
const STREAM: u64 = 0;
/// A sample whose length is further than this from 1 is invalid.
const UNIT_TOLERANCE: f64 = 1e-3;
/// The quadrature aims at an error in each expected count below this fraction of the
/// count's Poisson standard deviation `√E`, which inflates the expected statistic by at most
/// about its square (`0.0025`) per bin. The same goes for the no-sample bin, whose expected
/// count is what the other bins leave over, so that their errors add up in it.
const STAT_TOL: f64 = 0.05;
/// The quadrature never aims at a relative accuracy finer than this, which `f32` densities
/// cannot deliver anyway.
const REL_TOL_FLOOR: f64 = 1e-7;
/// Nor at an absolute accuracy finer than this many expected samples per bin.
const ABS_TOL_SAMPLES: f64 = 1e-3;

/// Settings of [`chi2_sphere`].
///
/// Build one with struct update syntax over [`Default`]:
///
/// ```
/// use lobe::verify::{sidak, Chi2Config};
/// let config = Chi2Config {
///     samples: 200_000,
///     significance: sidak(0.01, 4), // one of four tests in this file
///     ..Chi2Config::default()
/// };
/// assert_eq!(config.theta_bins, 16);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Chi2Config {
    /// Bins in `cos θ ∈ [−1, 1]`, equal width (so equal area). An even number puts a bin
    /// edge on the horizon `z = 0`, where hemispherical densities jump. Default 16.
    pub theta_bins: usize,
    /// Bins in `φ ∈ [0, 2π)`, equal width. Default 32.
    pub phi_bins: usize,
    /// Number of samples drawn. Default 1 000 000.
    pub samples: usize,
    /// Seed of the [`Pcg32`] that draws the sampler's random numbers. Default 1.
    pub seed: u64,
    /// The whole test's level, default 0.01: the chi-square and the no-sample count each reject at
    /// its Šidák share of two, so that the test rejects a correct sampler with this probability. A
    /// caller running several tests should pass the Šidák-corrected level
    /// [`sidak(0.01, n)`](super::sidak) so that the chance of any false rejection stays at 1 %.
    pub significance: f64,
    /// Bins expecting fewer samples than this are pooled (see [`chi2_sphere`]). Default 5,
    /// the usual rule of thumb for Pearson's approximation.
    pub min_expected: f64,
    /// Base quadrature grid per bin: each bin is split into `integration_res ×
    /// integration_res` cells in `(cos θ, φ)`, and each cell is integrated by adaptive
    /// Simpson quadrature. A lobe narrower than a base cell can be missed between its
    /// nodes (and then rejected: see [`chi2_sphere`]); raise this for very sharp
    /// densities. Default 8.
    pub integration_res: usize,
}

impl Default for Chi2Config {
    fn default() -> Self {
        Self {
            theta_bins: 16,
            phi_bins: 32,
            samples: 1_000_000,
            seed: 1,
            significance: 0.01,
            min_expected: 5.0,
            integration_res: 8,
        }
    }
}

/// A bin of the chi-square test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Chi2Bin {
    /// The direction bin with `cos θ ∈ [−1 + 2 theta / T, −1 + 2 (theta + 1) / T)` and
    /// `φ ∈ [2π phi / P, 2π (phi + 1) / P)`.
    Direction {
        /// The `cos θ` index, from `0` (around `−z`) to `theta_bins − 1` (around `+z`).
        theta: usize,
        /// The `φ` index.
        phi: usize,
    },
    /// The samples for which the sampler returned `None`, expected `N (1 − ∫ pdf)`.
    NoSample,
    /// The pool of low-count bins (merged into the bin of smallest expectation, which may be
    /// the no-sample bin, when the pool alone expects fewer than `min_expected` samples).
    Pooled,
}

impl fmt::Display for Chi2Bin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Direction { theta, phi } => write!(f, "bin (θ {theta}, φ {phi})"),
            Self::NoSample => f.write_str("the no-sample bin"),
            Self::Pooled => f.write_str("the pooled bin"),
        }
    }
}

/// The observed and expected counts of one bin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chi2Residual {
    /// Which bin.
    pub bin: Chi2Bin,
    /// Samples that landed in it.
    pub observed: u64,
    /// Samples the density predicts for it, `N ∫_bin pdf dω`.
    pub expected: f64,
}

impl Chi2Residual {
    /// The bin's term of Pearson's statistic, `(O − E)² / E` (`∞` for `E = 0 < O`).
    #[must_use]
    pub fn contribution(&self) -> f64 {
        let d = self.observed as f64 - self.expected;
        if d == 0.0 { 0.0 } else { d * d / self.expected }
    }
}

/// The outcome of [`chi2_sphere`]. [`passed`](Self::passed) is the verdict; the other fields
/// say why, and `Display` prints them in two or three lines.
#[derive(Clone, Debug, PartialEq)]
pub struct Chi2Report {
    /// Pearson's statistic `Σ (O − E)² / E` over the bins after pooling.
    pub statistic: f64,
    /// Degrees of freedom: the number of bins after pooling, minus one.
    pub dof: usize,
    /// `P(χ²_dof ≥ statistic)`, [`chi2_survival`](super::chi2_survival); NaN when
    /// `dof = 0`.
    pub p_value: f64,
    /// The significance level the chi-square was held to: the configuration's Šidák share of
    /// two, the other share holding the test of the samples that returned `None` on their own
    /// (see [`zero_bin_hits`](Self::zero_bin_hits)).
    pub significance: f64,
    /// Samples drawn, `N`.
    pub samples: usize,
    /// Samples for which the sampler returned `None`.
    pub rejected_samples: usize,
    /// `N (1 − ∫ pdf dω)`: how many `None`s the density predicts (it may integrate to less
    /// than one when the sampler can fail).
    pub expected_rejected: f64,
    /// The density's integral over the sphere, as computed by the quadrature.
    pub pdf_integral: f64,
    /// The quadrature's estimate of its own absolute error in `pdf_integral` (the sum of
    /// the adaptive error estimates; an overestimate for densities with rounding noise).
    pub integration_error: f64,
    /// Samples that were not finite or not of unit length (`|‖w‖ − 1| > 10⁻³`): an outright
    /// failure.
    pub invalid_samples: usize,
    /// Samples in bins over which the density integrates to zero, and the samples that
    /// returned `None` when there are more of them than a Poisson count of their expectation
    /// admits (at any expectation): an outright failure (the sampler produces directions, or
    /// failures, its pdf says are impossible or improbable).
    pub zero_bin_hits: usize,
    /// Density evaluations that were negative, infinite or NaN (counted as zero in the
    /// integral): an outright failure.
    pub invalid_pdf_values: usize,
    /// Number of low-count bins that were pooled.
    pub pooled_bins: usize,
    /// Number of bins in the statistic, after pooling (`dof + 1`).
    pub bins: usize,
    /// How many times the quadrature evaluated the density.
    pub pdf_evaluations: u64,
    /// The bin that speaks most against the density: the zero-density bin with the most
    /// hits if there is one, else the bin with the largest term `(O − E)² / E`.
    pub worst: Option<Chi2Residual>,
}

impl Chi2Report {
    /// Whether the sampler matches the density: no invalid sample, no sample where the
    /// density is zero, no invalid density value, at least one degree of freedom, and
    /// `p_value ≥ significance`.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.invalid_samples == 0
            && self.zero_bin_hits == 0
            && self.invalid_pdf_values == 0
            && self.dof >= 1
            && self.p_value >= self.significance
    }
}

impl fmt::Display for Chi2Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "chi-square {:.2} with {} dof, p = {:.4e} (significance {:.4e}): {}",
            self.statistic,
            self.dof,
            self.p_value,
            self.significance,
            if self.passed() { "passed" } else { "FAILED" }
        )?;
        write!(
            f,
            "  {} samples: {} rejected (expected {:.1}), {} invalid, {} in zero-pdf bins or \
             rejected beyond the expectation; \
             {} invalid pdf values; {} low-count bins pooled; integral of pdf {:.6} \
             (quadrature error ~{:.0e})",
            self.samples,
            self.rejected_samples,
            self.expected_rejected,
            self.invalid_samples,
            self.zero_bin_hits,
            self.invalid_pdf_values,
            self.pooled_bins,
            self.pdf_integral,
            self.integration_error
        )?;
        if let Some(w) = &self.worst {
            write!(
                f,
                "\n  largest residual: {}: observed {}, expected {:.1}",
                w.bin, w.observed, w.expected
            )?;
        }
        Ok(())
    }
}

/// Pearson's chi-square test of a direction sampler against its solid-angle density.
///
/// Draws `config.samples` points `u ∈ [0, 1)²` from [`Pcg32::new(config.seed, 0)`](Pcg32),
/// maps each through `sampler`, and compares the histogram of the directions with the counts
/// the density predicts. See [`chi2_sphere_rng`] for samplers that need more random numbers.
///
/// * **Bins.** `theta_bins × phi_bins` equal-area bins in `(cos θ, φ)`, plus one bin for the
///   samples that returned `None`, which expects `N (1 − ∫ pdf)`. A sampler that fails more
///   often than its density admits is caught by that count alone: it is always tested by its
///   Poisson tail, for the expectation raised by the quadrature's error and accuracy floors,
///   and the chi-square and this test each hold the Šidák share of two of the significance
///   (among 256 bins of the chi-square, 298 failures against 207 expected, 6.3 σ, passed
///   with p = 0.12). When the expectation is at least `min_expected` the bin is also one of
///   the chi-square's; below that it is never pooled with others.
/// * **Expected counts.** `N ∫_bin pdf dω`, integrated in `(cos θ, φ)`, where
///   `dω = d(cos θ) dφ` exactly. A first pass applies Simpson's product rule on an
///   `integration_res × integration_res` grid of cells per bin; a second pass integrates
///   each cell by nested adaptive Simpson quadrature (over `φ` inside, over `cos θ`
///   outside; Lyness 1969), which follows jumps such as a cone's rim. The tolerance is
///   statistical: each expected count, the no-sample bin's included, is aimed at an error
///   below `0.05 √E` (and never finer than `1e-7` relative), so the quadrature adds at
///   most a few thousandths to each term of the statistic. The density is evaluated in
///   `f32` at directions built from `f64` angles.
/// * **Pooling.** Bins expecting fewer than `min_expected` samples are summed into one
///   pooled bin. If that pool still expects fewer than `min_expected`, it is merged into
///   the kept bin with the smallest expectation (or, if there is none, kept as it is). The
///   no-sample bin is never merged into another: it is one of the bins when it expects at
///   least `min_expected`, and left out of the statistic otherwise (its count is tested alone
///   in any case, above); a small pool may be merged into it, when it is the smallest bin
///   kept.
/// * **Outright failures.** A non-finite or non-unit sample, a sample in a bin where the
///   density integrates to zero, and a negative or non-finite density value each fail the
///   test whatever the statistic; they are counted in the report.
/// * **Verdict.** `p = Q(dof / 2, χ² / 2)` with `dof = bins − 1`;
///   [`Chi2Report::passed`] iff there is no outright failure, `dof ≥ 1`, and
///   `p ≥ significance`.
///
/// The test is deterministic for a given configuration. It can reject a correct sampler
/// with probability `significance`, by chance; and it can reject one whose density has a
/// feature narrower than the quadrature grid, which the quadrature then misses. It does
/// not accept a wrong one for either reason. Its power is limited by the bins: a lobe that
/// fits in a few bins is tested on a few degrees of freedom only (and one inside a single
/// bin on none, which does not pass), so test sharp lobes with more `theta_bins` or
/// `phi_bins`, and more samples.
///
/// # Panics
///
/// If `theta_bins`, `phi_bins`, `samples` or `integration_res` is zero.
///
/// ```
/// use lobe::verify::{chi2_sphere, Chi2Config};
/// use lobe::sampling::{uniform_sphere, uniform_sphere_pdf};
///
/// let config = Chi2Config { samples: 100_000, ..Chi2Config::default() };
/// let report = chi2_sphere(|u| Some(uniform_sphere(u)), |_| f64::from(uniform_sphere_pdf()), &config);
/// assert!(report.passed(), "{report}");
/// ```
pub fn chi2_sphere(
    mut sampler: impl FnMut(Vec2) -> Option<Vec3>,
    pdf: impl Fn(Vec3) -> f64,
    config: &Chi2Config,
) -> Chi2Report {
    chi2_sphere_rng(|rng| sampler(rng.next_vec2()), pdf, config)
}

/// [`chi2_sphere`] for a sampler that draws its own random numbers from the test's
/// generator, for instance a BSDF sampler that needs a third number to choose a lobe.
///
/// # Panics
///
/// As [`chi2_sphere`]: if `theta_bins`, `phi_bins`, `samples` or `integration_res` is zero.
///
/// ```
/// use lobe::verify::{chi2_sphere_rng, Chi2Config};
/// use lobe::sampling::{uniform_hemisphere, uniform_sphere_pdf};
/// use lobe::Vec3;
///
/// // Upper or lower hemisphere with a coin flip: uniform on the sphere.
/// let sampler = |rng: &mut lobe::verify::Pcg32| {
///     let w = uniform_hemisphere(rng.next_vec2());
///     Some(if rng.next_f32() < 0.5 { w } else { Vec3::new(w.x, w.y, -w.z) })
/// };
/// let config = Chi2Config { samples: 100_000, ..Chi2Config::default() };
/// let report = chi2_sphere_rng(sampler, |_| f64::from(uniform_sphere_pdf()), &config);
/// assert!(report.passed(), "{report}");
/// ```
pub fn chi2_sphere_rng(
    mut sampler: impl FnMut(&mut Pcg32) -> Option<Vec3>,
    pdf: impl Fn(Vec3) -> f64,
    config: &Chi2Config,
) -> Chi2Report {
    assert!(
        config.theta_bins > 0 && config.phi_bins > 0,
        "chi2_sphere needs at least one bin on each axis"
    );
    assert!(config.samples > 0, "chi2_sphere needs at least one sample");
    assert!(
        config.integration_res > 0,
        "chi2_sphere needs integration_res ≥ 1"
    );
    let (nt, np) = (config.theta_bins, config.phi_bins);

    // Histogram the samples.
    let mut observed = vec![0_u64; nt * np];
    let mut rejected = 0_usize;
    let mut invalid = 0_usize;
    let mut rng = Pcg32::new(config.seed, STREAM);
    for _ in 0..config.samples {
        let Some(w) = sampler(&mut rng) else {
            rejected += 1;
            continue;
        };
        let (x, y, z) = (f64::from(w.x), f64::from(w.y), f64::from(w.z));
        let len = (x * x + y * y + z * z).sqrt();
        if !w.is_finite() || (len - 1.0).abs() > UNIT_TOLERANCE {
            invalid += 1;
            continue;
        }
        let t = ((0.5 * (z / len + 1.0) * nt as f64) as usize).min(nt - 1);
        let phi = y.atan2(x);
        let phi = if phi < 0.0 { phi + TAU } else { phi };
        let p = ((phi / TAU * np as f64) as usize).min(np - 1);
        observed[t * np + p] += 1;
    }

    // Expected counts: a first pass on the base grid gives each bin's rough mass, which
    // sets the tolerance of the adaptive second pass.
    let n = config.samples as f64;
    let mut quad = Quadrature::new(&pdf, config.integration_res);
    let dc = 2.0 / nt as f64;
    let dphi = TAU / np as f64;
    let bin_bounds = |t: usize, p: usize| {
        let c0 = -1.0 + dc * t as f64;
        let c1 = if t + 1 == nt { 1.0 } else { c0 + dc };
        let phi0 = dphi * p as f64;
        let phi1 = if p + 1 == np { TAU } else { phi0 + dphi };
        (c0, c1, phi0, phi1)
    };
    let rough: Vec<f64> = (0..nt * np)
        .map(|k| {
            let (c0, c1, phi0, phi1) = bin_bounds(k / np, k % np);
            quad.grid(c0, c1, phi0, phi1)
        })
        .collect();
    let rough_total: f64 = rough.iter().sum();
    let rough_missing = (1.0 - rough_total).max(0.0);
    quad.invalid = 0;

    let mut integral = 0.0;
    let mut cells: Vec<Chi2Residual> = Vec::with_capacity(nt * np + 1);
    let mut zero_bin_hits = 0_usize;
    let mut worst_zero: Option<Chi2Residual> = None;
    // Relative tolerance for the no-sample bin: the bins' errors add up in it, so each bin
    // gets the share of STAT_TOL √(N m) (m the missing mass, at least one sample's worth)
    // that its mass is of the total.
    let rel_tol_missing = if rough_total > 0.0 {
        STAT_TOL * (rough_missing.max(1.0 / n) / n).sqrt() / rough_total
    } else {
        f64::INFINITY
    };
    for (k, &p0) in rough.iter().enumerate() {
        let (t, p) = (k / np, k % np);
        let (c0, c1, phi0, phi1) = bin_bounds(t, p);
        // The bin's own count: |N error| ≤ STAT_TOL √(N p0).
        let tol_own = STAT_TOL * (p0.max(1.0 / n) / n).sqrt();
        let tol = tol_own
            .min(rel_tol_missing * p0)
            .max(REL_TOL_FLOOR * p0)
            .max(ABS_TOL_SAMPLES / n);
        let mass = quad.bin(c0, c1, phi0, phi1, tol);
        integral += mass;
        let cell = Chi2Residual {
            bin: Chi2Bin::Direction { theta: t, phi: p },
            observed: observed[k],
            expected: n * mass,
        };
        if mass > 0.0 {
            cells.push(cell);
        } else if cell.observed > 0 {
            zero_bin_hits += cell.observed as usize;
            if worst_zero.is_none_or(|w| w.observed < cell.observed) {
                worst_zero = Some(cell);
            }
        }
    }
    let expected_rejected = n * (1.0 - integral).max(0.0);
    // The no-sample bin. With an expectation the chi-square can weigh it is one of its bins;
    // below that it is never pooled (among direction bins, a hundred failures against an
    // expectation of 0.04 drowned: p = 0.27), but tested alone: the chance of as many
    // failures or more for a Poisson count whose mean is the expectation raised by what the
    // quadrature may have missed, held with the chi-square to the run's significance (Šidák
    // over the two). Too many, and they count as hits where nothing is expected.
    let significance = sidak(config.significance, 2);
    let no_sample = Chi2Residual {
        bin: Chi2Bin::NoSample,
        observed: rejected as u64,
        expected: expected_rejected,
    };
    if expected_rejected >= config.min_expected {
        cells.push(no_sample);
    }
    if rejected > 0 {
        // The expectation, raised by what the quadrature may have missed: its own error
        // estimate, and the floors it stops at in every bin (an absolute share of a sample,
        // a relative 1e-7 that `f32` densities cannot beat), which add up in this remainder.
        // A sampler whose `f32` guards drop a sample or two against a density of mass one
        // passes; dozens do not.
        let floors =
            (config.theta_bins * config.phi_bins) as f64 * ABS_TOL_SAMPLES + n * REL_TOL_FLOOR;
        let mean = expected_rejected + n * quad.error.max(0.0) + floors;
        // P(X ≥ k) for X ~ Poisson(mean) is the regularised P(k, mean).
        if !(gamma_p(rejected as f64, mean) >= significance) {
            zero_bin_hits += rejected;
            if worst_zero.is_none_or(|w| w.observed < no_sample.observed) {
                worst_zero = Some(no_sample);
            }
        }
    }

    // Pool the low-count bins.
    let (mut bins, small): (Vec<_>, Vec<_>) = cells
        .into_iter()
        .partition(|c| c.expected >= config.min_expected);
    if !small.is_empty() {
        let pool = Chi2Residual {
            bin: Chi2Bin::Pooled,
            observed: small.iter().map(|c| c.observed).sum(),
            expected: small.iter().map(|c| c.expected).sum(),
        };
        let smallest = bins
            .iter_mut()
            .min_by(|a, b| a.expected.total_cmp(&b.expected));
        match smallest {
            Some(target) if pool.expected < config.min_expected => {
                target.bin = Chi2Bin::Pooled;
                target.observed += pool.observed;
                target.expected += pool.expected;
            }
            _ => bins.push(pool),
        }
    }

    let statistic: f64 = bins.iter().map(Chi2Residual::contribution).sum();
    let dof = bins.len().saturating_sub(1);
    let worst = worst_zero.or_else(|| {
        bins.iter()
            .copied()
            .max_by(|a, b| a.contribution().total_cmp(&b.contribution()))
    });
    Chi2Report {
        statistic,
        dof,
        p_value: chi2_survival(statistic, dof),
        significance,
        samples: config.samples,
        rejected_samples: rejected,
        expected_rejected,
        pdf_integral: integral,
        integration_error: quad.error,
        invalid_samples: invalid,
        zero_bin_hits,
        invalid_pdf_values: quad.invalid,
        pooled_bins: small.len(),
        bins: bins.len(),
        pdf_evaluations: quad.evals,
        worst,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;
    use std::string::ToString;

    fn small_config() -> Chi2Config {
        Chi2Config {
            theta_bins: 8,
            phi_bins: 16,
            samples: 50_000,
            ..Chi2Config::default()
        }
    }

    /// Uniform on the sphere by normalising a rejection-sampled point of the ball: an
    /// independent sampler, not the one in `sampling`.
    fn ball_sampler(rng: &mut Pcg32) -> Option<Vec3> {
        loop {
            let p = Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) * 2.0 - Vec3::ONE;
            let l2 = p.length_squared();
            if l2 > 1e-4 && l2 <= 1.0 {
                return Some(p / l2.sqrt());
            }
        }
    }

    #[test]
    fn quadrature_integrates_known_densities() {
        let config = small_config();
        // ∫ 1/(4π) dω = 1; ∫ max(z, 0)/π dω = 1; ∫ 3/(2π) z² [z > 0] dω = 1.
        let densities: [&dyn Fn(Vec3) -> f64; 3] = [
            &|_| 1.0 / (4.0 * PI),
            &|w| f64::from(w.z).max(0.0) / PI,
            &|w| {
                if w.z > 0.0 {
                    1.5 / PI * f64::from(w.z).powi(2)
                } else {
                    0.0
                }
            },
        ];
        for pdf in densities {
            let r = chi2_sphere_rng(
                ball_sampler,
                pdf,
                &Chi2Config {
                    samples: 10,
                    ..config.clone()
                },
            );
            assert!(
                (r.pdf_integral - 1.0).abs() < 1e-6,
                "∫ pdf = {}",
                r.pdf_integral
            );
        }
        // A cone of half-angle 60° that is not aligned with the bins: ∫ = 2π (1 − ½) = π.
        let cone = |w: Vec3| if w.z >= 0.5 { 1.0 } else { 0.0 };
        let r = chi2_sphere_rng(
            ball_sampler,
            cone,
            &Chi2Config {
                theta_bins: 7,
                samples: 10,
                ..config
            },
        );
        assert!(
            (r.pdf_integral - PI).abs() < 1e-5 * PI,
            "∫ = {}",
            r.pdf_integral
        );
    }

    #[test]
    fn independent_uniform_sampler_passes() {
        let r = chi2_sphere_rng(ball_sampler, |_| 1.0 / (4.0 * PI), &small_config());
        assert!(r.passed(), "{r}");
        assert_eq!(r.dof, 8 * 16 - 1);
        assert_eq!((r.pooled_bins, r.rejected_samples), (0, 0));
    }

    /// A sampler that fails at a rate of 2e-4 while its density integrates to 1 (an
    /// expectation of about none, about 40 failures at 200 000 samples) fails the test, as the
    /// docs promise; pooled with the direction bins, such failures once passed. The same
    /// sampler against the density that admits the failures, `(1 − 2e-4)/(4π)`, passes, and
    /// so does one that fails once in the run (the quadrature's floors admit that much).
    #[test]
    fn failing_more_often_than_the_density_admits_is_caught() {
        let config = Chi2Config {
            samples: 200_000,
            ..small_config()
        };
        let rate = 2e-4;
        let sampler = |rng: &mut Pcg32| {
            let w = ball_sampler(rng)?;
            if rng.next_f32() < rate { None } else { Some(w) }
        };
        let r = chi2_sphere_rng(sampler, |_| 1.0 / (4.0 * PI), &config);
        assert!(!r.passed(), "{r}");
        assert_eq!(r.zero_bin_hits, r.rejected_samples);
        assert!(r.rejected_samples > 10, "{r}");
        let admitted = 1.0 - f64::from(rate);
        let r = chi2_sphere_rng(sampler, |_| admitted / (4.0 * PI), &config);
        assert!(r.passed(), "{r}");
        let mut calls = 0_u32;
        let once = |rng: &mut Pcg32| {
            calls += 1;
            if calls == 1_000 {
                None
            } else {
                ball_sampler(rng)
            }
        };
        let r = chi2_sphere_rng(once, |_| 1.0 / (4.0 * PI), &config);
        assert!(r.passed() && r.rejected_samples == 1, "{r}");
    }

    #[test]
    fn same_seed_same_report() {
        let a = chi2_sphere_rng(ball_sampler, |_| 1.0 / (4.0 * PI), &small_config());
        let b = chi2_sphere_rng(ball_sampler, |_| 1.0 / (4.0 * PI), &small_config());
        assert_eq!(a, b);
        let c = chi2_sphere_rng(
            ball_sampler,
            |_| 1.0 / (4.0 * PI),
            &Chi2Config {
                seed: 2,
                ..small_config()
            },
        );
        assert_ne!(a.statistic, c.statistic);
    }

    #[test]
    fn invalid_samples_fail_outright() {
        let mut k = 0_u32;
        let sampler = |rng: &mut Pcg32| {
            k += 1;
            let w = ball_sampler(rng)?;
            Some(match k % 1000 {
                0 => w * 1.01,
                500 => Vec3::NAN,
                _ => w,
            })
        };
        let r = chi2_sphere_rng(sampler, |_| 1.0 / (4.0 * PI), &small_config());
        assert_eq!(r.invalid_samples, 100);
        assert!(!r.passed());
    }

    #[test]
    fn invalid_pdf_values_fail_outright() {
        let r = chi2_sphere_rng(
            ball_sampler,
            |w| {
                if w.x > 0.9 {
                    f64::NAN
                } else {
                    1.0 / (4.0 * PI)
                }
            },
            &small_config(),
        );
        assert!(r.invalid_pdf_values > 0);
        assert!(!r.passed());
    }

    #[test]
    fn pdf_missing_a_region_is_a_zero_bin_hit() {
        // The density claims nothing below z = −0.5, the sampler goes there anyway.
        let r = chi2_sphere_rng(
            ball_sampler,
            |w| if w.z >= -0.5 { 1.0 / (3.0 * PI) } else { 0.0 },
            &small_config(),
        );
        // The ring cos θ ∈ [−1, −0.75) gets 1/8 of the samples, about 6250, and its density
        // is zero at every node. (The ring above it touches z = −0.5, where the density is
        // not zero, so it expects a sliver and is pooled instead.)
        assert!(r.zero_bin_hits > 5_000, "{r}");
        assert!(
            matches!(
                r.worst,
                Some(Chi2Residual {
                    bin: Chi2Bin::Direction { theta: 0, .. },
                    expected: 0.0,
                    ..
                })
            ),
            "{r}"
        );
        assert!(!r.passed());
    }

    #[test]
    fn low_count_bins_are_pooled() {
        // 16 × 32 bins, 2000 samples: about 3.9 expected per bin, all pooled into one bin;
        // with no regular bin left, the pool stands alone and the test has no dof.
        let r = chi2_sphere_rng(
            ball_sampler,
            |_| 1.0 / (4.0 * PI),
            &Chi2Config {
                samples: 2000,
                ..Chi2Config::default()
            },
        );
        assert_eq!((r.pooled_bins, r.bins, r.dof), (512, 1, 0));
        assert!(r.p_value.is_nan() && !r.passed());
        // A density with a faint tail: the tail bins are pooled, the rest stand.
        let faint = |w: Vec3| {
            let z = f64::from(w.z);
            if z > 0.0 {
                0.999 * z / PI
            } else {
                0.001 * (-z) / PI
            }
        };
        let faint_sampler = |rng: &mut Pcg32| loop {
            // Cosine-weighted by rejection from the uniform sphere, then flipped below the
            // horizon with probability 0.001.
            let w = ball_sampler(rng)?;
            let up = Vec3::new(w.x, w.y, w.z.abs());
            if rng.next_f32() < up.z {
                let below = rng.next_f32() < 0.001;
                return Some(if below {
                    Vec3::new(up.x, up.y, -up.z)
                } else {
                    up
                });
            }
        };
        let r = chi2_sphere_rng(faint_sampler, faint, &small_config());
        // The 64 lower bins expect 50 samples between them: pooled into one bin of their
        // own, next to the 64 upper bins.
        assert_eq!((r.pooled_bins, r.bins, r.dof), (64, 65, 64), "{r}");
        assert!(r.passed(), "{r}");
        // Against the density without its tail, the flipped samples are zero-bin hits.
        let r = chi2_sphere_rng(
            faint_sampler,
            |w| f64::from(w.z).max(0.0) / PI,
            &small_config(),
        );
        assert!(r.zero_bin_hits > 0 && !r.passed(), "{r}");
    }

    #[test]
    fn no_sample_bin_expects_the_missing_mass() {
        // A uniform sampler that fails 30 % of the time, against the density 0.7 / (4π).
        let sampler = |rng: &mut Pcg32| {
            let w = ball_sampler(rng)?;
            (rng.next_f32() >= 0.3).then_some(w)
        };
        let config = small_config();
        let r = chi2_sphere_rng(sampler, |_| 0.7 / (4.0 * PI), &config);
        assert!(r.passed(), "{r}");
        // The expectation is exact to far below its Poisson deviation √(0.3 N) ≈ 122.
        let want = 0.3 * config.samples as f64;
        assert!((r.expected_rejected - want).abs() < 0.01, "{r}");
        assert_eq!(r.dof, 8 * 16);
        // The same sampler against the full density: rejected.
        let r = chi2_sphere_rng(sampler, |_| 1.0 / (4.0 * PI), &config);
        assert!(!r.passed() && r.p_value < 1e-100, "{r}");
    }

    #[test]
    fn display_mentions_the_verdict() {
        let r = chi2_sphere_rng(ball_sampler, |_| 1.0 / (4.0 * PI), &small_config());
        let text = r.to_string();
        assert!(
            text.contains("passed") && text.contains("127 dof"),
            "{text}"
        );
    }
}
