//! The microfacet law checks can fail: each is fed a distribution with a realistic bug and
//! must reject it, while accepting the correct distribution under the same settings.

mod common;

use common::{dir, k_sigma};
use lobe::microfacet::{Ggx, NormalDistribution, VisibleNormals};
use lobe::verify::{
    Chi2Config, NdfCheck, chi2_normals, d_normalization, projected_area, visible_normalization,
};
use lobe::{Alpha, Vec2, Vec3};

/// The bugs, each a one-line slip away from GGX.
#[derive(Clone, Copy, PartialEq)]
enum Bug {
    None,
    /// `D` without its `1/π`.
    DMissingPi,
    /// `D` 10% too large.
    DTenPercent,
    /// `G1 = 1/(1/Λ)`, that is `Λ`, instead of `1/(1 + Λ)`.
    G1IsLambda,
    /// The visible-normal density without `G1`: `max(0, w·m) D(m) / cos θw`.
    VisibleWithoutG1,
}

struct Buggy {
    ggx: Ggx,
    bug: Bug,
}

impl NormalDistribution for Buggy {
    fn d(&self, m: Vec3) -> f32 {
        let d = self.ggx.d(m);
        match self.bug {
            Bug::DMissingPi => d * core::f32::consts::PI,
            Bug::DTenPercent => d * 1.1,
            _ => d,
        }
    }
    fn lambda(&self, w: Vec3) -> f32 {
        self.ggx.lambda(w)
    }
    fn g1(&self, w: Vec3) -> f32 {
        if self.bug == Bug::G1IsLambda {
            1.0 / (1.0 / self.lambda(w))
        } else {
            1.0 / (1.0 + self.lambda(w))
        }
    }
    fn d_visible(&self, w: Vec3, m: Vec3) -> f32 {
        if self.bug == Bug::VisibleWithoutG1 {
            w.dot(m).max(0.0) * self.d(m) / w.z
        } else {
            self.g1(w) * w.dot(m).max(0.0) * self.d(m) / w.z
        }
    }
    fn sample(&self, w: Vec3, u: Vec2) -> Vec3 {
        self.ggx.sample(w, u)
    }
    fn pdf(&self, w: Vec3, m: Vec3) -> f32 {
        self.d_visible(w, m)
    }
    fn sample_d_cos(&self, u: Vec2) -> Vec3 {
        self.ggx.sample_d_cos(u)
    }
}

const ALPHA: f32 = 0.3;

fn buggy(bug: Bug) -> Buggy {
    Buggy {
        ggx: Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        bug,
    }
}

fn check() -> NdfCheck {
    NdfCheck {
        samples: 300_000,
        ..NdfCheck::stretched(ALPHA, ALPHA)
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
        |u| ggx.sample_visible(w, u),
        |m| f64::from(ggx.d_visible(w, m)),
        stretch,
        &config,
    );
    assert!(good.passed(), "{good}");
    let wrong = |m: Vec3| f64::from(ggx.d_visible(w, m)) * if m.y > 0.0 { 1.1 } else { 0.9 };
    let bad = chi2_normals(|u| ggx.sample_visible(w, u), wrong, stretch, &config);
    assert!(!bad.passed(), "a 10% wrong pdf passed: {bad}");
}
