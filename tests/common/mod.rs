//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod buggy_ggx;
pub mod laws;
pub mod quadrature;
pub mod reference;

use lobe::Vec3;
use proptest::test_runner::{Config, RngSeed};

/// A seeded, reproducible proptest configuration that writes no regression files.
pub fn proptest_config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x10be),
        failure_persistence: None,
        ..Config::default()
    }
}

/// The two-sided normal quantile `k` such that each of `n_tests` estimates falls outside
/// `±k σ` with probability `sidak(family_alpha, n_tests)`: the Šidák-corrected "k sigma",
/// by the harness's own [`two_sided_quantile`](lobe::verify::two_sided_quantile).
pub fn k_sigma(family_alpha: f64, n_tests: usize) -> f64 {
    use lobe::verify::{sidak, two_sided_quantile};
    two_sided_quantile(sidak(family_alpha, n_tests))
}

/// The unit direction at polar angle `theta_deg` and azimuth `phi` (radians).
pub fn dir(theta_deg: f32, phi: f32) -> Vec3 {
    let t = theta_deg.to_radians();
    Vec3::new(t.sin() * phi.cos(), t.sin() * phi.sin(), t.cos())
}
