//! Significance levels and their normal quantiles: [`sidak`], the per-test level of a family
//! of tests, and [`two_sided_quantile`], the `k` of "within `k` standard errors" at a level.

use super::gamma::gamma_q;

/// The per-test significance that keeps the chance of *any* false rejection among
/// `n_tests` independent tests at `alpha`: Šidák's correction `1 − (1 − α)^(1/n)`
/// (Šidák 1967, "Rectangular Confidence Regions for the Means of Multivariate Normal
/// Distributions", JASA 62).
///
/// Computed as `−expm1(ln1p(−α) / n)` so that small `α` keep their digits. `n_tests = 0`
/// is treated as a single test. Precondition: `alpha ∈ [0, 1]`.
///
/// ```
/// use lobe::verify::sidak;
/// // Ten tests at a family-wise 1 %: each runs at about 0.1005 %.
/// assert!((sidak(0.01, 10) - 0.001_004_529).abs() < 1e-9);
/// assert_eq!(sidak(0.05, 1), 0.05);
/// ```
#[must_use]
pub fn sidak(alpha: f64, n_tests: usize) -> f64 {
    if n_tests <= 1 {
        return alpha;
    }
    -((-alpha).ln_1p() / n_tests as f64).exp_m1()
}

/// The two-sided normal quantile `k` with `P(|Z| > k) = p`, by bisection on
/// `erfc(k/√2) = Q(½, k²/2)`: the `k` of [`Estimate::within`](super::Estimate::within) for a
/// test at significance `p`.
///
/// ```
/// use lobe::verify::{sidak, two_sided_quantile};
/// // 5 %: the familiar 1.96.
/// assert!((two_sided_quantile(0.05) - 1.959_964).abs() < 1e-6);
/// // One of ten estimates at a family-wise 1 %.
/// let k = two_sided_quantile(sidak(0.01, 10));
/// assert!((k - 3.289).abs() < 1e-3);
/// ```
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn family_wise_rate_is_restored() {
        // (1 − α_test)^n = 1 − α by construction.
        for (alpha, n) in [(0.01, 2), (0.05, 7), (0.001, 1000), (0.5, 3)] {
            let per = sidak(alpha, n);
            assert!(per > 0.0 && per <= alpha);
            let family = 1.0 - (1.0 - per).powi(n as i32);
            // (The check itself rounds: (1 − per)ⁿ loses about n ulps.)
            assert!((family - alpha).abs() < 1e-12, "{alpha} {n}: {family}");
        }
        // Two tests at 5 %: 1 − √0.95 = 0.025320565519103...
        assert!((sidak(0.05, 2) - 0.025_320_565_519_103_6).abs() < 1e-15);
        assert_eq!(sidak(0.01, 0), 0.01);
        assert_eq!(sidak(0.0, 5), 0.0);
        assert_eq!(sidak(1.0, 5), 1.0);
    }
}
