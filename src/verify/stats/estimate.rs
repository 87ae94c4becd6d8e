//! Monte Carlo estimates with their standard errors.

use std::fmt;

/// The round-off allowance of [`Estimate::within`], in units of `f64::EPSILON` relative to
/// the larger magnitude of the mean and the target.
const ROUND_OFF_ULPS: f64 = 64.0;

/// A Monte Carlo estimate of a mean: the sample mean, its standard error, and the number of
/// samples.
///
/// Built by an [`Accumulator`]. The standard error is `s / √n`, with `s²` the unbiased
/// sample variance; it is NaN when `n < 2` (one sample says nothing about the spread), and
/// the mean is NaN when `n = 0`, so that no claim can be made from too few samples: every
/// comparison ([`within`](Self::within)) with a NaN field is `false`.
///
/// ```
/// use lobe::verify::Estimate;
/// let e = Estimate::from_samples([1.0, 2.0, 3.0, 4.0]);
/// assert_eq!(e.mean, 2.5);
/// assert_eq!(e.n, 4);
/// // s² = 5/3, standard error √(5/3 / 4).
/// assert!((e.std_err - (5.0_f64 / 12.0).sqrt()).abs() < 1e-15);
/// assert!(e.within(3.0, 3.0));
/// assert!(!e.within(10.0, 3.0));
/// println!("{e}"); // 2.50 ± 0.65 (n = 4)
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The sample mean.
    pub mean: f64,
    /// The standard error of the mean, `s / √n`.
    pub std_err: f64,
    /// The number of samples.
    pub n: u64,
}

impl Estimate {
    /// The estimate of the samples of `samples`, accumulated in `f64` (see [`Accumulator`]).
    #[must_use]
    pub fn from_samples<I: IntoIterator<Item = f64>>(samples: I) -> Self {
        samples.into_iter().collect::<Accumulator>().finish()
    }

    /// The rounding allowance used when comparing the mean with `target`:
    /// `64 f64::EPSILON · max(|mean|, |target|)`.
    ///
    /// It lets an estimate whose samples are all identical (standard error exactly `0`)
    /// still match a target computed along a different path in `f64`.
    #[inline]
    #[must_use]
    pub fn round_off(&self, target: f64) -> f64 {
        ROUND_OFF_ULPS * f64::EPSILON * self.mean.abs().max(target.abs())
    }

    /// How many standard errors the mean lies from `target`: `(mean − target) / std_err`.
    ///
    /// When the standard error is `0` (all samples identical) the score is `0` if the mean
    /// equals `target` up to [`round_off`](Self::round_off), and `±∞` otherwise. NaN when
    /// the estimate is undefined (`n < 2`) or the mean, the standard error or `target` is not
    /// finite (an infinite sample makes the mean infinite and the spread NaN: no claim).
    #[must_use]
    pub fn z_score(&self, target: f64) -> f64 {
        if !self.is_finite_against(target) {
            return f64::NAN;
        }
        let diff = self.mean - target;
        if self.std_err == 0.0 {
            if diff.abs() <= self.round_off(target) {
                0.0
            } else {
                diff.signum() * f64::INFINITY
            }
        } else {
            diff / self.std_err
        }
    }

    /// Whether the mean is within `k_sigma` standard errors of `target`:
    /// `|mean − target| ≤ k_sigma · std_err + round_off(target)`.
    ///
    /// The [`round_off`](Self::round_off) term is what lets a zero-variance estimate pass
    /// against an exact target; it is negligible next to any real standard error. `false`
    /// when any of the numbers is NaN (in particular for `n < 2`) or infinite (an infinite
    /// mean would otherwise meet its own infinite round-off allowance).
    #[must_use]
    pub fn within(&self, target: f64, k_sigma: f64) -> bool {
        self.is_finite_against(target)
            && (self.mean - target).abs() <= k_sigma * self.std_err + self.round_off(target)
    }

    /// The mean, the standard error and `target` are all finite: the comparisons mean
    /// something.
    #[inline]
    fn is_finite_against(&self, target: f64) -> bool {
        self.is_finite() && target.is_finite()
    }

    /// The mean and the standard error are both finite (an estimate of at least two finite
    /// samples whose spread did not overflow).
    #[inline]
    pub(crate) fn is_finite(&self) -> bool {
        self.mean.is_finite() && self.std_err.is_finite()
    }

    /// The relative standard error `std_err / |mean|` (infinite for a zero mean with a
    /// non-zero error, NaN for `0 / 0`).
    #[inline]
    #[must_use]
    pub fn relative_error(&self) -> f64 {
        self.std_err / self.mean.abs()
    }
}

impl fmt::Display for Estimate {
    /// `mean ± std_err (n = N)`. With an explicit precision (`{:.4}`) both numbers use it;
    /// otherwise the standard error is shown to two significant digits and the mean to the
    /// same decimal place.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let decimals = f.precision().unwrap_or_else(|| {
            if self.std_err.is_finite() && self.std_err > 0.0 {
                // Two significant digits of the error: 0.0012 → 4 decimals.
                let leading = self.std_err.log10().floor();
                (1.0 - leading).clamp(0.0, 17.0) as usize
            } else {
                6
            }
        });
        write!(
            f,
            "{:.*} ± {:.*} (n = {})",
            decimals, self.mean, decimals, self.std_err, self.n
        )
    }
}

/// Closeness of two estimates *as numbers*: the means within the tolerance, the standard
/// errors within the tolerance, and the same sample count. It answers "is this the same
/// estimate?" — one accumulated per thread and [merged](Accumulator::merge) against one
/// accumulated in a single pass, one read back from a log — not "do these two measurements
/// agree?", which is a statistical question for [`Estimate::z_score`] and
/// [`Estimate::within`]. A NaN field (an estimate of fewer than two samples) is never close
/// to anything.
///
/// ```
/// use approx::assert_relative_eq;
/// use lobe::verify::{Accumulator, Estimate};
///
/// let xs: Vec<f64> = (0..100).map(|i| f64::from(i).sqrt()).collect();
/// let mut a: Accumulator = xs[..40].iter().copied().collect();
/// a.merge(&xs[40..].iter().copied().collect());
/// assert_relative_eq!(a.finish(), Estimate::from_samples(xs), max_relative = 1e-12);
/// ```
#[cfg(feature = "approx")]
impl approx::AbsDiffEq for Estimate {
    type Epsilon = f64;

    #[inline]
    fn default_epsilon() -> f64 {
        f64::EPSILON
    }

    fn abs_diff_eq(&self, other: &Self, epsilon: f64) -> bool {
        self.n == other.n
            && self.mean.abs_diff_eq(&other.mean, epsilon)
            && self.std_err.abs_diff_eq(&other.std_err, epsilon)
    }
}

#[cfg(feature = "approx")]
impl approx::RelativeEq for Estimate {
    #[inline]
    fn default_max_relative() -> f64 {
        f64::EPSILON
    }

    fn relative_eq(&self, other: &Self, epsilon: f64, max_relative: f64) -> bool {
        self.n == other.n
            && self.mean.relative_eq(&other.mean, epsilon, max_relative)
            && self
                .std_err
                .relative_eq(&other.std_err, epsilon, max_relative)
    }
}

/// Accumulates samples into an [`Estimate`] with Welford's single-pass update in `f64`
/// (Welford 1962; Knuth, *TAOCP* vol. 2, §4.2.2), which keeps the variance accurate when the
/// mean is large next to the spread.
///
/// Accumulators over disjoint sample sets can be [`merge`](Self::merge)d (Chan, Golub &
/// LeVeque 1979), e.g. one per thread.
///
/// ```
/// use lobe::verify::Accumulator;
/// let mut acc = Accumulator::new();
/// for x in [2.0, 4.0, 6.0] {
///     acc.push(x);
/// }
/// let e = acc.finish();
/// assert_eq!((e.mean, e.n), (4.0, 3));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Accumulator {
    /// The number of samples so far.
    n: u64,
    /// Their running mean.
    mean: f64,
    /// The running sum of squared deviations from the mean.
    m2: f64,
}

impl Accumulator {
    /// An empty accumulator.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds one sample.
    #[inline]
    pub fn push(&mut self, x: f64) {
        self.n += 1;
        let delta = x - self.mean;
        self.mean += delta / self.n as f64;
        self.m2 += delta * (x - self.mean);
    }

    /// Adds the samples of `other` (Chan, Golub & LeVeque 1979, the pairwise update of the
    /// mean and the sum of squared deviations).
    pub fn merge(&mut self, other: &Self) {
        if other.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *other;
            return;
        }
        let n = self.n + other.n;
        let (na, nb) = (self.n as f64, other.n as f64);
        let delta = other.mean - self.mean;
        self.mean += delta * (nb / n as f64);
        self.m2 += other.m2 + delta * delta * (na * nb / n as f64);
        self.n = n;
    }

    /// The number of samples so far.
    #[inline]
    #[must_use]
    pub fn len(&self) -> u64 {
        self.n
    }

    /// Whether no sample has been pushed.
    #[inline]
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The unbiased sample variance `s² = Σ (x − x̄)² / (n − 1)`; NaN for `n < 2`, and NaN
    /// when a sample was infinite or NaN (the running sum of squares is then NaN, and stays
    /// so: `f64::max` would have turned it into a spread of zero).
    #[must_use]
    pub fn variance(&self) -> f64 {
        if self.n < 2 {
            f64::NAN
        } else {
            // Round-off can leave the sum of squares a hair below zero; a NaN stays NaN.
            let m2 = if self.m2 < 0.0 { 0.0 } else { self.m2 };
            m2 / (self.n - 1) as f64
        }
    }

    /// The estimate of the mean so far (see [`Estimate`] for `n < 2`).
    #[must_use]
    pub fn finish(&self) -> Estimate {
        let mean = if self.n == 0 { f64::NAN } else { self.mean };
        Estimate {
            mean,
            std_err: (self.variance() / self.n as f64).sqrt(),
            n: self.n,
        }
    }
}

impl Extend<f64> for Accumulator {
    fn extend<I: IntoIterator<Item = f64>>(&mut self, iter: I) {
        for x in iter {
            self.push(x);
        }
    }
}

impl FromIterator<f64> for Accumulator {
    fn from_iter<I: IntoIterator<Item = f64>>(iter: I) -> Self {
        let mut acc = Self::new();
        acc.extend(iter);
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;
    use std::string::ToString;
    use std::vec::Vec;

    #[test]
    fn mean_and_error_match_two_pass_formulas() {
        // 1..=10: mean 5.5, s² = 55/6 (Σ(x − 5.5)² = 82.5, / 9), std_err = √(55/6 / 10).
        let e = Estimate::from_samples((1..=10).map(f64::from));
        assert_eq!(e.n, 10);
        assert!((e.mean - 5.5).abs() < 1e-15);
        assert!((e.std_err - (55.0_f64 / 60.0).sqrt()).abs() < 1e-15);
    }

    /// An infinite sample, or an infinite target, makes no claim: the spread is NaN (not the
    /// zero that `f64::max` made of it) and every comparison fails, where an infinite mean
    /// used to meet its own infinite round-off allowance.
    #[test]
    fn infinities_make_no_claim() {
        let e = Estimate::from_samples([1.0, 1.0, 1.0, f64::INFINITY]);
        assert!(e.std_err.is_nan(), "{e}");
        assert!(!e.within(1.0, 3.0) && !e.within(1e9, 3.0) && !e.within(f64::INFINITY, 3.0));
        assert!(e.z_score(1.0).is_nan());
        let finite = Estimate::from_samples([1.0, 2.0, 3.0]);
        assert!(!finite.within(f64::INFINITY, 3.0) && finite.z_score(f64::INFINITY).is_nan());
        // A spread that overflows is not finite either.
        let huge = Estimate::from_samples([-1e200, 1e200]);
        assert!(!huge.within(0.0, 3.0), "{huge}");
        // Finite estimates still compare as before.
        assert!(finite.within(2.0, 1.0) && finite.z_score(2.0) == 0.0);
    }

    #[test]
    fn welford_keeps_precision_with_a_large_offset() {
        // Samples 1e9 + {4, 7, 13, 16}: variance 30 survives the offset.
        let acc: Accumulator = [4.0, 7.0, 13.0, 16.0].iter().map(|x| 1e9 + x).collect();
        assert!((acc.variance() - 30.0).abs() < 1e-6, "{}", acc.variance());
    }

    #[test]
    fn merge_equals_single_pass() {
        let xs: Vec<f64> = (0..1000).map(|i| f64::from(i).sin() * 3.0 + 1.0).collect();
        let whole: Accumulator = xs.iter().copied().collect();
        let mut a: Accumulator = xs[..317].iter().copied().collect();
        let b: Accumulator = xs[317..].iter().copied().collect();
        a.merge(&b);
        assert_eq!(a.len(), whole.len());
        assert!((a.finish().mean - whole.finish().mean).abs() < 1e-13);
        assert!((a.variance() - whole.variance()).abs() < 1e-12);
        let mut empty = Accumulator::new();
        empty.merge(&whole);
        assert_eq!(empty, whole);
    }

    #[test]
    fn zero_variance_compares_up_to_round_off() {
        let e = Estimate::from_samples([0.1; 1000]);
        assert_eq!(e.std_err, 0.0);
        assert!(e.within(0.1, 3.0));
        // 1 − 0.9 ≠ 0.1 in f64, but within round-off.
        assert!(e.within(1.0 - 0.9, 0.0));
        assert_eq!(e.z_score(1.0 - 0.9), 0.0);
        assert!(!e.within(0.100_001, 3.0));
        assert_eq!(e.z_score(0.2), f64::NEG_INFINITY);
        assert_eq!(e.z_score(0.0), f64::INFINITY);
        let zero = Estimate::from_samples([0.0; 10]);
        assert!(zero.within(0.0, 0.0));
    }

    #[test]
    fn too_few_samples_claim_nothing() {
        let none = Accumulator::new().finish();
        assert_eq!(none.n, 0);
        assert!(none.mean.is_nan() && !none.within(0.0, 1e9));
        let one = Estimate::from_samples([1.0]);
        assert_eq!(one.mean, 1.0);
        assert!(one.std_err.is_nan() && !one.within(1.0, 1e9));
        assert!(one.z_score(1.0).is_nan());
    }

    #[test]
    fn z_score_and_within() {
        let e = Estimate {
            mean: 1.0,
            std_err: 0.01,
            n: 100,
        };
        assert!((e.z_score(0.97) - 3.0).abs() < 1e-12);
        assert!(e.within(0.975, 3.0));
        assert!(!e.within(0.965, 3.0));
        assert!((e.relative_error() - 0.01).abs() < 1e-15);
    }

    #[test]
    fn display_rounds_to_the_error() {
        let e = Estimate {
            mean: 0.998_712_3,
            std_err: 0.001_234,
            n: 100_000,
        };
        assert_eq!(e.to_string(), "0.9987 ± 0.0012 (n = 100000)");
        assert_eq!(format!("{e:.2}"), "1.00 ± 0.00 (n = 100000)");
        let big = Estimate {
            mean: 1234.4,
            std_err: 56.0,
            n: 7,
        };
        assert_eq!(big.to_string(), "1234 ± 56 (n = 7)");
    }
}
