//! The proptest strategies of `lobe::verify::strategies` produce what they promise: unit
//! directions in their ranges, parameters the constructors accept, over the whole range and
//! with the special values mixed in. Then a few properties of the crate over them, the way a
//! downstream crate would write them.
#![cfg(feature = "proptest")]

use lobe::bxdf::{Bxdf, Lambert, Microfacet};
use lobe::fresnel::{self, Schlick};
use lobe::microfacet::{Ggx, Masking, NormalDistribution};
use lobe::verify::strategies::{
    adversarial_directions, alphas, complex_iors, directions, etas, grazing_directions,
    near_normal_directions, unit_f32, unit_vec2, upper_directions,
};
use lobe::{Alpha, Eta, Vec3};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngSeed, TestRunner};

/// Draws.
const N: usize = 20_000;

/// `n` values of `strategy` from a seeded runner.
fn draw<S: Strategy>(strategy: S, n: usize) -> Vec<S::Value> {
    let mut runner = TestRunner::new(Config {
        rng_seed: RngSeed::Fixed(0x5eed),
        ..Config::default()
    });
    (0..n)
        .map(|_| strategy.new_tree(&mut runner).unwrap().current())
        .collect()
}

fn assert_unit(w: Vec3) {
    assert!(w.is_finite(), "{w:?}");
    let len = f64::from(w.x).hypot(f64::from(w.y)).hypot(f64::from(w.z));
    assert!((len - 1.0).abs() < 1e-6, "|{w:?}| = {len}");
}

/// How many of `xs` satisfy `p`.
fn count<T: Copy>(xs: &[T], p: impl Fn(T) -> bool) -> usize {
    xs.iter().filter(|&&x| p(x)).count()
}

/// `N` directions of `strategy`, each asserted to be of unit length.
fn draw_directions<S: Strategy<Value = Vec3>>(strategy: S) -> Vec<Vec3> {
    let ws = draw(strategy, N);
    ws.iter().copied().for_each(assert_unit);
    ws
}

/// A seeded configuration for the property tests that writes no regression files.
fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x10be),
        failure_persistence: None,
        ..Config::default()
    }
}

#[test]
fn directions_are_uniform_on_the_sphere() {
    let ws = draw_directions(directions());
    // Uniform on the sphere: z, x and y are uniform in [−1, 1] with variance 1/3, mean 0.
    let sigma = (1.0 / 3.0 / N as f64).sqrt();
    for axis in 0..3 {
        let mean = ws.iter().map(|w| f64::from(w[axis])).sum::<f64>() / N as f64;
        assert!(mean.abs() < 5.0 * sigma, "axis {axis}: mean {mean}");
    }
    // Equal-area bands in z hold equal shares.
    let upper = ws.iter().filter(|w| w.z > 0.5).count() as f64 / N as f64;
    assert!(
        (upper - 0.25).abs() < 5.0 * (0.25 * 0.75 / N as f64).sqrt(),
        "{upper}"
    );
}

#[test]
fn upper_directions_are_strictly_above() {
    let ws = draw_directions(upper_directions());
    for &w in &ws {
        assert!(w.z > 0.0 && w.z <= 1.0, "{w:?}");
    }
    // Uniform in solid angle: cos θ uniform in (0, 1].
    let mean = ws.iter().map(|w| f64::from(w.z)).sum::<f64>() / N as f64;
    assert!(
        (mean - 0.5).abs() < 5.0 * (1.0 / 12.0 / N as f64).sqrt(),
        "{mean}"
    );
}

#[test]
fn grazing_directions_stay_within_1e_7_and_1e_2_of_the_horizon() {
    let ws = draw_directions(grazing_directions());
    for w in &ws {
        assert!((0.999e-7..=1.001e-2).contains(&w.z.abs()), "{w:?}");
    }
    let below = count(&ws, |w| w.z < 0.0);
    let tiny = count(&ws, |w| w.z.abs() < 1e-6);
    let wide = count(&ws, |w| w.z.abs() > 1e-3);
    // Both sides, and log-uniform: each decade holds about a fifth.
    assert!(below > N / 3 && below < 2 * N / 3, "{below} below");
    assert!(
        tiny > N / 8 && wide > N / 8,
        "{tiny} below 1e-6, {wide} above 1e-3"
    );
}

#[test]
fn near_normal_directions_are_near_either_pole() {
    let ws = draw_directions(near_normal_directions());
    let sin = |w: Vec3| f64::from(w.x).hypot(f64::from(w.y));
    for &w in &ws {
        assert!(sin(w) <= 0.1001, "{w:?}");
    }
    let below = count(&ws, |w| w.z < 0.0);
    let exact = count(&ws, |w| sin(w) == 0.0);
    let tiny = count(&ws, |w| sin(w) > 0.0 && sin(w) < 1e-6);
    assert!(below > N / 3 && below < 2 * N / 3, "{below} below");
    assert!(exact > N / 20, "{exact} exactly on the normal");
    assert!(tiny > N / 20, "{tiny} within 1e-6 of the normal");
}

#[test]
fn adversarial_directions_include_the_horizon_itself() {
    let ws = draw_directions(adversarial_directions());
    let horizon = count(&ws, |w| w.z == 0.0);
    let negative_zero = count(&ws, |w| w.z == 0.0 && w.z.is_sign_negative());
    let grazing = count(&ws, |w| w.z != 0.0 && w.z.abs() <= 1e-2);
    let poles = count(&ws, |w| w.z.abs() == 1.0);
    assert!(
        horizon > N / 20 && negative_zero > 0,
        "{horizon} on the horizon"
    );
    assert!(grazing > N / 8, "{grazing} grazing");
    assert!(poles > 0, "{poles} at the poles");
}

#[test]
fn alphas_cover_the_accepted_range_log_uniformly() {
    let alphas: Vec<f32> = draw(alphas(), N).into_iter().map(Alpha::get).collect();
    for &a in &alphas {
        assert!((Alpha::MIN..=Alpha::MAX).contains(&a), "{a}");
    }
    assert!(count(&alphas, |a| a == Alpha::MIN) > N / 20);
    assert!(count(&alphas, |a| a == Alpha::MAX) > N / 20);
    // Five decades, log-uniform: each holds about 16% of the draws.
    for decade in -4..1 {
        let lo = 10f32.powi(decade);
        let share = count(&alphas, |a| a > lo && a < 10.0 * lo) as f64 / N as f64;
        assert!(
            (0.1..0.25).contains(&share),
            "[1e{decade}, 1e{}]: {share}",
            decade + 1
        );
    }
}

#[test]
fn etas_cover_the_range_index_matching_and_common_media() {
    let etas: Vec<f32> = draw(etas(), N).into_iter().map(Eta::get).collect();
    for &e in &etas {
        assert!((Eta::MIN..=Eta::MAX).contains(&e), "{e}");
    }
    assert!(count(&etas, |e| e < 1e-2) > N / 40, "far below 1");
    assert!(count(&etas, |e| e > 1e2) > N / 40, "far above 1");
    assert!(count(&etas, |e| e == 1.0) > N / 50, "exactly 1");
    assert!(
        count(&etas, |e| e != 1.0 && (e - 1.0).abs() < 1e-5) > N / 50,
        "near 1"
    );
    assert!(
        count(&etas, |e| e > 1.0 && e < 1.0 + 1e-2) > N / 50,
        "just above 1"
    );
    assert!(
        count(&etas, |e| e < 1.0 && e > 1.0 - 1e-2) > N / 50,
        "just below 1"
    );
    for common in [1.33, 1.5, 2.4, 1.0 / 1.33, 1.0 / 1.5, 1.0 / 2.4] {
        assert!(count(&etas, |e| e == common) > N / 50, "{common}");
    }
}

#[test]
fn complex_iors_are_accepted_and_span_metals_and_extremes() {
    let iors = draw(complex_iors(), N);
    for ior in &iors {
        let (eta, k) = (ior.eta(), ior.k());
        assert!(
            eta > 0.0 && eta <= 1e3 && (0.0..=1e3).contains(&k),
            "{ior:?}"
        );
        assert_eq!(lobe::ComplexIor::new(eta, k).as_ref(), Ok(ior));
    }
    let count = |p: &dyn Fn(f32, f32) -> bool| iors.iter().filter(|i| p(i.eta(), i.k())).count();
    assert!(
        count(&|e, k| e == 0.143 && k == 3.983) > N / 200,
        "gold (red)"
    );
    assert!(count(&|_, k| k == 0.0) > N / 50, "κ = 0");
    assert!(count(&|e, _| e < 1e-2) > N / 50, "tiny η");
    assert!(count(&|e, _| e > 1e2) > N / 50, "huge η");
    assert!(count(&|_, k| k > 1e2) > N / 50, "huge κ");
    assert!(count(&|e, k| (0.01..=5.0).contains(&e) && (0.0..=10.0).contains(&k)) > N / 2);
}

#[test]
fn unit_numbers_are_in_the_half_open_interval() {
    let us = draw(unit_f32(), N);
    assert!(us.iter().all(|u| (0.0..1.0).contains(u)));
    let mean = us.iter().map(|&u| f64::from(u)).sum::<f64>() / N as f64;
    assert!(
        (mean - 0.5).abs() < 5.0 * (1.0 / 12.0 / N as f64).sqrt(),
        "{mean}"
    );
    let vs = draw(unit_vec2(), N);
    assert!(
        vs.iter()
            .all(|v| (0.0..1.0).contains(&v.x) && (0.0..1.0).contains(&v.y))
    );
}

// Properties of the crate over the strategies, written as a downstream crate would.
proptest! {
    #![proptest_config(config(2_000))]

    #[test]
    fn lambert_is_total_and_reciprocal(
        wo in adversarial_directions(),
        wi in adversarial_directions(),
    ) {
        let brdf = Lambert::new(0.8_f32).unwrap();
        let f = brdf.eval(wo, wi);
        prop_assert!(f.is_finite() && f >= 0.0);
        prop_assert_eq!(f, brdf.eval(wi, wo));
    }

    #[test]
    fn ggx_is_total(
        wo in adversarial_directions(),
        wi in adversarial_directions(),
        a in alphas(),
        u in unit_vec2(),
        uc in unit_f32(),
    ) {
        let fresnel = Schlick::new(0.04_f32).unwrap();
        let brdf = Microfacet::new(Ggx::isotropic(a), Masking::HeightCorrelated, fresnel);
        let (f, pdf) = (brdf.eval(wo, wi), brdf.pdf(wo, wi));
        prop_assert!(f.is_finite() && f >= 0.0, "f = {f}");
        prop_assert!(pdf.is_finite() && pdf >= 0.0, "pdf = {pdf}");
        if let Some(s) = brdf.sample(wo, u, uc) {
            prop_assert!(s.f.is_finite() && s.f >= 0.0, "{s:?}");
            prop_assert!(s.pdf.is_finite() && s.pdf > 0.0, "{s:?}");
        }
        let g1 = brdf.distribution().g1(wo);
        prop_assert!((0.0..=1.0).contains(&g1), "G1 = {g1}");
    }

    #[test]
    fn fresnel_terms_are_fractions(c in unit_f32(), eta in etas(), ior in complex_iors()) {
        for cos in [c, -c] {
            let f = fresnel::dielectric(cos, eta);
            let e = eta.get();
            prop_assert!((0.0..=1.0).contains(&f), "dielectric F({cos}) = {f} at η = {e}");
        }
        let f = fresnel::conductor(c, &ior);
        prop_assert!((0.0..=1.0).contains(&f), "conductor F({c}) = {f} for {ior:?}");
    }
}
