//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod buggy_ggx;
pub mod exact;
pub mod laws;
pub mod quadrature;
pub mod reference;
pub mod soa;
pub mod wire;

use lobe::Vec3;
use lobe::verify::Pcg32;
use proptest::test_runner::{Config, RngSeed};

/// Gold's complex index of refraction at the red, green and blue primaries (η, k), the
/// conductor of the tests that want a coloured metal.
pub fn gold() -> lobe::ComplexIor<Vec3> {
    lobe::ComplexIor::new(
        Vec3::new(0.143, 0.375, 1.442),
        Vec3::new(3.983, 2.386, 1.603),
    )
    .unwrap()
}

/// A seeded, reproducible proptest configuration that writes no regression files.
pub fn proptest_config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x10be),
        failure_persistence: None,
        ..Config::default()
    }
}

/// The law budget of the combinator tests (`bxdf_mix`, `bxdf_diffuse_transmission`,
/// `bxdf_sheen`): `albedo_samples` per albedo, 200 000 chi-square samples, 5 000 pairs and
/// consistency samples, at the Šidák-corrected significance of `n_tests` tests.
pub fn combinator_budget(albedo_samples: usize, n_tests: usize) -> lobe::verify::Config {
    lobe::verify::Config {
        albedo_samples,
        chi2_samples: 200_000,
        pairs: 5_000,
        consistency_samples: 5_000,
        significance: lobe::verify::sidak(0.01, n_tests),
        ..lobe::verify::Config::default()
    }
}

/// The two-sided normal quantile `k` such that each of `n_tests` estimates falls outside
/// `±k σ` with probability `sidak(family_alpha, n_tests)`: the Šidák-corrected "k sigma",
/// by the harness's own [`two_sided_quantile`](lobe::verify::two_sided_quantile).
pub fn k_sigma(family_alpha: f64, n_tests: usize) -> f64 {
    use lobe::verify::{sidak, two_sided_quantile};
    two_sided_quantile(sidak(family_alpha, n_tests))
}

/// Asserts that each estimate of `estimates` (labelled, in order) lies below the one before
/// it by more than `k` standard errors of their difference: a significant fall, not noise.
pub fn assert_falling(what: &str, estimates: &[(String, lobe::verify::Estimate)], k: f64) {
    for pair in estimates.windows(2) {
        let ((la, a), (lb, b)) = (&pair[0], &pair[1]);
        assert!(
            a.mean - b.mean > k * a.std_err.hypot(b.std_err),
            "{what} should fall: {a} at {la}, then {b} at {lb}"
        );
    }
}

/// The unit direction at polar angle `theta_deg` and azimuth `phi` (radians).
pub fn dir(theta_deg: f32, phi: f32) -> Vec3 {
    let t = theta_deg.to_radians();
    Vec3::new(t.sin() * phi.cos(), t.sin() * phi.sin(), t.cos())
}

/// A `wi` for `wo` by `rng.next_u32() % kinds`: its mirror, itself, its opposite, else `fresh`.
pub fn partner(rng: &mut Pcg32, wo: Vec3, kinds: u32, fresh: fn(&mut Pcg32) -> Vec3) -> Vec3 {
    match rng.next_u32() % kinds {
        0 => Vec3::new(-wo.x, -wo.y, wo.z),
        1 => wo,
        2 => -wo,
        _ => fresh(rng),
    }
}

/// The directions at polar angles `thetas` (degrees, azimuth 0.4), each followed by its opposite.
pub fn both_sides(thetas: &[f32]) -> Vec<Vec3> {
    thetas
        .iter()
        .flat_map(|&t| [dir(t, 0.4), -dir(t, 0.4)])
        .collect()
}

/// The angle between two directions given in `f64`, as the `atan2` of the cross and dot
/// products of the normalised vectors (accurate at small angles, where `acos` is not).
pub fn angle_f64(a: [f64; 3], b: [f64; 3]) -> f64 {
    let n = |v: [f64; 3]| {
        let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / l, v[1] / l, v[2] / l]
    };
    let (a, b) = (n(a), n(b));
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let sin = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
    sin.atan2(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])
}

/// `v` in `f64`.
pub fn f64s(v: Vec3) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

/// Textbook dielectric Fresnel in `f64` (Born & Wolf §1.5.2), written without the
/// rearrangements the crate uses: `(F, |cos θt|)` for light at `cos_i` on an interface of
/// relative index `eta` (inside over outside; `cos_i < 0` meets it from inside), 1 under
/// total internal reflection.
pub fn dielectric_f64(cos_i: f64, eta: f64) -> (f64, f64) {
    let (n, ci) = if cos_i >= 0.0 {
        (eta, cos_i)
    } else {
        (1.0 / eta, -cos_i)
    };
    let sin2_t = (1.0 - ci * ci) / (n * n);
    if sin2_t >= 1.0 {
        return (1.0, 0.0);
    }
    let ct = (1.0 - sin2_t).sqrt();
    let rs = (ci - n * ct) / (ci + n * ct);
    let rp = (ct - n * ci) / (ct + n * ci);
    (0.5 * (rs * rs + rp * rp), ct)
}
