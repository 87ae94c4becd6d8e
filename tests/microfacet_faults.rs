//! The microfacet law checks can fail: each is fed a distribution with a realistic bug and
//! must reject it, while accepting the correct distribution under the same settings.

mod common;

use common::buggy_ggx::{BuggyNdf, NdfBug as Bug};
use common::{dir, k_sigma};
use lobe::microfacet::{Ggx, NormalDistribution};
use lobe::verify::{
    Chi2Config, Config, chi2_normals, d_normalization, projected_area, visible_normalization,
};
use lobe::{Alpha, Vec2, Vec3};

const ALPHA: f32 = 0.3;

fn buggy(bug: Bug) -> BuggyNdf {
    BuggyNdf::new(ALPHA, bug)
}

fn check() -> Config {
    Config {
        integral_samples: 300_000,
        stretch: Vec2::splat(ALPHA),
        ..Config::default()
    }
}

#[test]
fn normalisation_check_rejects_a_wrong_d() {
    let k = k_sigma(0.01, 3);
    assert!(d_normalization(&buggy(Bug::None), &check()).within(1.0, k));
    for bug in [Bug::DMissingPi, Bug::DTenPercent] {
        let e = d_normalization(&buggy(bug), &check());
        assert!(!e.within(1.0, k), "a wrong D passed: {e}");
    }
}

#[test]
fn projected_area_check_rejects_g1_equal_to_lambda() {
    let k = k_sigma(0.01, 6);
    let wo = dir(60.0, 0.3);
    let want = f64::from(wo.z);
    let good = projected_area(&buggy(Bug::None), wo, &check());
    assert!(good.within(want, k), "{good}");
    let bad = projected_area(&buggy(Bug::G1IsLambda), wo, &check());
    assert!(!bad.within(want, k), "G1 = Λ passed: {bad}");
}

#[test]
fn visible_normalization_rejects_a_density_without_g1() {
    let k = k_sigma(0.01, 2);
    let w = dir(70.0, 0.0);
    assert!(visible_normalization(&buggy(Bug::None), w, &check()).within(1.0, k));
    let bad = visible_normalization(&buggy(Bug::VisibleWithoutG1), w, &check());
    assert!(!bad.within(1.0, k), "D_w without G1 passed: {bad}");
}

/// A sampler checked against a pdf that is 10% off on one side of the lobe (and renormalised,
/// so that only the shape is wrong) is rejected; against the right pdf it passes.
#[test]
fn chi_square_rejects_a_pdf_ten_percent_off() {
    let ggx = Ggx::isotropic(Alpha::new(ALPHA).unwrap());
    let w = dir(45.0, 0.0);
    let stretch = Vec2::splat(ALPHA);
    let config = Chi2Config {
        samples: 200_000,
        significance: 0.01 / 2.0,
        ..Chi2Config::default()
    };
    let good = chi2_normals(
        |u| ggx.sample(&ggx.view(w), u),
        |m| f64::from(ggx.d_visible(w, m)),
        stretch,
        &config,
    );
    assert!(good.passed(), "{good}");
    let wrong = |m: Vec3| f64::from(ggx.d_visible(w, m)) * if m.y > 0.0 { 1.1 } else { 0.9 };
    let bad = chi2_normals(|u| ggx.sample(&ggx.view(w), u), wrong, stretch, &config);
    assert!(!bad.passed(), "a 10% wrong pdf passed: {bad}");
}
