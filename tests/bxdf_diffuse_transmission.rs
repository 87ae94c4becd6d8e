//! `DiffuseTransmission` (issue 12): its albedo is `R + T` — in closed form, by its sampler
//! and by cosine sampling —, `R + T ≤ 1` is validated, and it passes every law.

mod common;

use lobe::bxdf::{Bxdf, DiffuseTransmission};
use lobe::verify::{Config, albedo, check_bxdf};
use lobe::{Spectrum, Vec3};

/// Statistical tests in this file: 2 harness runs, 3 sheets × 4 directions × 2 estimators.
const TESTS: usize = 2 + 24;

fn config() -> Config {
    common::combinator_budget(50_000, TESTS)
}

#[test]
fn the_albedo_is_r_plus_t_by_both_estimators() {
    let k = common::k_sigma(0.01, TESTS);
    let c = config();
    for (r, t) in [(0.3_f32, 0.5_f32), (0.9, 0.0), (0.05, 0.95)] {
        let sheet = DiffuseTransmission::new(r, t).unwrap();
        assert_eq!(sheet.albedo(), r + t);
        for theta in [0.0_f32, 70.0, 110.0, 180.0] {
            let wo = common::dir(theta, 0.7);
            let a = albedo(&sheet, wo, &c);
            let exact = f64::from(r + t);
            let cosine = a.cosine.unwrap();
            eprintln!(
                "R={r} T={t} θo={theta}°: sampled {}, cosine {cosine}",
                a.sampled
            );
            // A grey sheet's every sample weighs R + T: the sampled estimate is exact.
            assert!((a.sampled.mean - exact).abs() <= 1e-6, "{}", a.sampled);
            assert!(
                (cosine.mean - exact).abs() <= k * cosine.std_err + 1e-6,
                "{cosine}"
            );
        }
    }
}

#[test]
fn reflectance_and_transmittance_are_validated() {
    assert_eq!(
        DiffuseTransmission::new(0.6_f32, 0.5).unwrap_err().param(),
        "transmittance"
    );
    assert_eq!(
        DiffuseTransmission::new(f32::NAN, 0.5).unwrap_err().param(),
        "reflectance"
    );
    assert_eq!(
        DiffuseTransmission::new(0.2_f32, -0.1).unwrap_err().param(),
        "transmittance"
    );
    // Per channel: blue's R + T is 1.1.
    let e =
        DiffuseTransmission::new(Vec3::new(0.2, 0.2, 0.6), Vec3::new(0.5, 0.5, 0.5)).unwrap_err();
    assert_eq!((e.param(), e.value()), ("transmittance", 0.5));
    assert!(DiffuseTransmission::new(0.5_f32, 0.5).is_ok());
}

#[test]
fn diffuse_transmission_obeys_every_law() {
    let c = config();
    let leaf = DiffuseTransmission::new(0.25_f32, 0.6).unwrap();
    let report = check_bxdf("DiffuseTransmission R=0.25 T=0.6", &leaf, &c);
    eprintln!("{report}");
    assert!(report.passed(), "{report}");
    let rgb = DiffuseTransmission::new(Vec3::new(0.1, 0.4, 0.2), Vec3::new(0.2, 0.5, 0.1)).unwrap();
    let report = check_bxdf("DiffuseTransmission RGB", &rgb, &c);
    eprintln!("{report}");
    assert!(report.passed(), "{report}");
    // The values, from either side.
    let (up, down) = (common::dir(30.0, 0.0), -common::dir(50.0, 1.0));
    let pi = core::f32::consts::PI;
    assert_eq!(leaf.eval(up, up), 0.25 / pi);
    assert_eq!(leaf.eval(up, down), 0.6 / pi);
    assert_eq!(leaf.eval(down, up), 0.6 / pi);
    assert_eq!(leaf.eval(down, down), 0.25 / pi);
    assert_eq!(rgb.albedo().max_channel(), 0.9);
}

/// `lobes` names the sides the sampler can draw: a side of zero weight is left out (so a
/// black transmittance makes a one-sided reflector, which `verify` checks as one).
#[test]
fn lobes_name_only_the_sides_of_non_zero_weight() {
    use lobe::bxdf::Lobes;
    let both = DiffuseTransmission::new(0.3f32, 0.5).unwrap();
    let reflect = DiffuseTransmission::new(0.3f32, 0.0).unwrap();
    let transmit = DiffuseTransmission::new(0.0f32, 0.5).unwrap();
    assert_eq!(
        both.lobes(),
        Lobes::DIFFUSE_REFLECTION | Lobes::DIFFUSE | Lobes::TRANSMISSION
    );
    assert_eq!(reflect.lobes(), Lobes::DIFFUSE_REFLECTION);
    assert_eq!(transmit.lobes(), Lobes::DIFFUSE | Lobes::TRANSMISSION);
    // Even at a lobe choice of 1, the reflector only reflects.
    let wo = Vec3::new(0.48, 0.36, 0.8);
    let s = reflect
        .sample(wo, lobe::Vec2::new(0.3, 0.6), 1.0)
        .expect("a reflection");
    assert!(s.wi.z > 0.0 && s.lobe == Lobes::DIFFUSE_REFLECTION, "{s:?}");
}
