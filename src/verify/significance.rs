//! Significance levels for families of tests.

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
