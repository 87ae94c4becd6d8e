//! The modified, normalised Phong BRDF (Lafortune & Willems 1994; ERRATA #12) through the law
//! suite, its sharp lobes, its closed-form albedo at normal incidence, reference values and
//! refused parameters.

mod common;

use common::exact::{
    assert_edge_samples, assert_lobe_choice, assert_lobes_follow_weights, assert_one_sided,
    assert_reciprocity_bit_exact, assert_values, hemisphere_pairs, near_lobe_pairs,
};
use common::laws::{
    Model, assert_albedo_against, assert_all_laws, assert_consistent, assert_reciprocal,
    assert_total, viewer_directions,
};
use common::{angle_f64, f64s, k_sigma};
use lobe::bxdf::{Bxdf, Lobes, Phong};
use lobe::verify::{BxdfCheck, Pcg32, albedo_sampled};
use lobe::{Vec2, Vec3};

fn phong(kd: f32, ks: f32, p: f32) -> Model {
    Model::new(
        format!("Phong kd={kd} ks={ks} p={p}"),
        Phong::new(kd, ks, p).unwrap(),
    )
}

/// The settings of the full law suite: pure glossy lobes of exponent 0 to 100 and mixtures.
/// The chi-square test bins equally in `cos θ × φ`; sharper lobes are tested below.
const LAW_SETTINGS: [(f32, f32, f32); 6] = [
    (0.0, 1.0, 1.0),
    (0.0, 1.0, 10.0),
    (0.0, 1.0, 100.0),
    (0.2, 0.8, 0.0),
    (0.5, 0.5, 10.0),
    (0.7, 0.3, 100.0),
];

#[test]
fn phong_obeys_every_law() {
    for (kd, ks, p) in LAW_SETTINGS {
        let model = phong(kd, ks, p);
        assert_all_laws(&model, LAW_SETTINGS.len());
        // The suite holds reciprocity to 1e-5 on its well-conditioned pairs; the formula is
        // symmetric, so it holds to the bit on every pair.
        let pairs = hemisphere_pairs(&mut Pcg32::new(7, 3), 20_000);
        assert_reciprocity_bit_exact(&model.name, model.bxdf.as_ref(), &pairs, false);
    }
}

/// Exponents 10³…10⁶, where the lobe fits in a bin or two of the chi-square test and cosine
/// sampling rarely finds it: totality, exact reciprocity, sample/eval/pdf consistency, and
/// the energy bound by the model's own sampler (whose weight is nearly constant there).
#[test]
fn sharp_lobes_are_consistent_and_conserve_energy() {
    let settings = [
        (0.0, 1.0, 1e3),
        (0.0, 1.0, 1e4),
        (0.0, 1.0, 1e6),
        (0.5, 0.5, 1e6),
    ];
    let k = k_sigma(0.01, settings.len() * 5);
    for (kd, ks, p) in settings {
        let model = phong(kd, ks, p);
        assert_total(&model, 20_000);
        let worst = assert_reciprocal(&model, 20_000, 1e-5);
        assert_eq!(worst, 0.0, "{}: the formula is symmetric", model.name);
        assert_consistent(&model, 1e-4);
        // Random pairs rarely land in so narrow a lobe: check reciprocity on pairs near the
        // mirror configuration, where the lobe is large.
        let pairs = near_lobe_pairs(p, |wo, d| {
            Vec3::new(-wo.x + d.x, -wo.y + d.y, wo.z).normalize()
        });
        assert_reciprocity_bit_exact(&model.name, model.bxdf.as_ref(), &pairs, true);
        for wo in viewer_directions(&model) {
            let a = albedo_sampled(model.bxdf.as_ref(), wo, &BxdfCheck::default());
            assert!(
                a.mean <= f64::from(kd + ks) + k * a.std_err + 1e-6,
                "{}: albedo {a} at {wo:?}",
                model.name
            );
        }
    }
}

/// At normal incidence `r = n` and the lobe is never clipped: the albedo is exactly
/// `k_d + k_s`, and (measured) the largest over the viewing angles.
#[test]
fn albedo_is_kd_plus_ks_at_normal_incidence_and_falls_from_there() {
    let settings = [
        (0.0, 1.0, 0.0),
        (0.0, 1.0, 1.0),
        (0.0, 1.0, 10.0),
        (0.0, 1.0, 100.0),
        (0.3, 0.6, 30.0),
        (0.0, 1.0, 1e5),
    ];
    let angles = [0.0_f32, 15.0, 30.0, 45.0, 60.0, 75.0, 80.0, 89.0];
    let k = k_sigma(0.01, settings.len() * angles.len());
    for (kd, ks, p) in settings {
        let model = phong(kd, ks, p);
        let exact = f64::from(kd + ks);
        let mut previous = (f64::INFINITY, 0.0_f64);
        for t in angles {
            let wo = common::dir(t, 0.4);
            let a = albedo_sampled(model.bxdf.as_ref(), wo, &BxdfCheck::default());
            // The f32 rounding the helper allows for matters only at p = 10⁵, where the
            // standard error is 2e-8.
            let name = format!("{} at {t}°", model.name);
            assert_albedo_against(&name, &a, exact, k, t == 0.0);
            // Falls with the viewing angle (within the noise of the two estimates).
            assert!(
                a.mean <= previous.0 + k * a.std_err.hypot(previous.1),
                "{}: albedo {a} at {t}° above the previous angle's {}",
                model.name,
                previous.0
            );
            eprintln!("{}: albedo at {t}°: {a}", model.name);
            previous = (a.mean, a.std_err);
        }
    }
}

/// Values of `f` and `pdf` computed independently in f64 (a Python script from the formula:
/// `f = kd/π + ks (p+2)/(2π) max(0, r·wi)^p`, `pdf = P_d cos θi/π + (1 − P_d)(p+1)/(2π)
/// max(0, r·wi)^p`, `P_d = kd/(kd + ks)`), for `kd = 0.3, ks = 0.6, p = 20`.
#[test]
fn values_match_an_independent_computation() {
    let m = Phong::new(0.3_f32, 0.6, 20.0).unwrap();
    let cases = [
        (
            Vec3::new(0.3, -0.2, 0.9),
            Vec3::new(-0.25, 0.3, 0.85),
            1.898_034_105_278_850_5,
            2.008_200_871_858_291_3,
        ),
        (
            Vec3::new(0.3, -0.2, 0.9),
            Vec3::new(0.5, 0.5, 0.3),
            0.095_492_965_908_970_25,
            0.041_440_417_493_793_37,
        ),
        (
            Vec3::new(0.8, 0.1, 0.2),
            Vec3::new(-0.7, 0.0, 0.3),
            1.499_783_633_829_601_6,
            1.531_195_329_005_028_6,
        ),
    ];
    assert_values("Phong", &m, &cases, 1e-5);
    let (wo, wi) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(-0.6, 0.0, 0.8));
    assert_one_sided("Phong", &m, wo, wi);
}

/// For a large exponent `cos^p α` is computed from `1 − cos α` without cancellation: it
/// matches an f64 evaluation of the same `f32` directions at 10⁻⁴…3·10⁻³ rad from the mirror
/// direction, for 400 viewer directions. The bound is the forward error of
/// `exp(p ln(1 − x))` with `x = 1 − cos α` held to a few ulps: `p x` times `x`'s relative
/// error, plus the exponential's own (`(4 + 4 p x) ε` relative).
#[test]
fn large_exponents_keep_their_shape_near_the_mirror_direction() {
    let mut rng = lobe::verify::Pcg32::new(11, 0);
    let eps = f64::from(f32::EPSILON);
    let mut worst = 0.0f64;
    for p in [1e4_f32, 1e5, 1e6] {
        let m = Phong::new(0.0_f32, 1.0, p).unwrap();
        let norm = (f64::from(p) + 2.0) / std::f64::consts::TAU;
        for _ in 0..400 {
            let theta = 0.05 + 1.35 * rng.next_f32();
            let phi = std::f32::consts::TAU * rng.next_f32();
            let wo = Vec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let r = Vec3::new(-wo.x, -wo.y, wo.z);
            let axis = r.cross(Vec3::Z).normalize();
            let turn = std::f32::consts::TAU * rng.next_f32();
            // An axis perpendicular to r, at a random angle about it.
            let axis = axis * turn.cos() + r.cross(axis) * turn.sin();
            for alpha in [0.0_f32, 1e-4, 3e-4, 1e-3, 3e-3] {
                let wi = (r * alpha.cos() + axis.cross(r) * alpha.sin()).normalize();
                // The f64 reference from the actual f32 directions.
                let angle = angle_f64(f64s(Vec3::new(-wo.x, -wo.y, wo.z)), f64s(wi));
                let expect = norm * angle.cos().powf(f64::from(p));
                let got = f64::from(m.eval(wo, wi));
                let px = f64::from(p) * (1.0 - angle.cos());
                let bound = (4.0 + 4.0 * px) * eps;
                let err = (got - expect).abs() / expect.max(1e-300);
                worst = worst.max(err / bound);
                assert!(
                    err <= bound,
                    "p = {p}, wo = {wo:?}, α = {alpha}: {got} vs {expect}"
                );
            }
        }
    }
    println!("worst error / bound: {worst:.3}");
}

#[test]
fn exact_and_grazing_configurations_are_finite() {
    let grazing = Vec3::new((1.0_f32 - 1e-14).sqrt(), 0.0, 1e-7);
    let mirror = Vec3::new(-grazing.x, -grazing.y, grazing.z);
    for p in [0.0_f32, 1.0, 100.0, 1e6] {
        for (kd, ks) in [(0.0_f32, 1.0_f32), (0.5, 0.5), (0.0, 0.0)] {
            let m = Phong::new(kd, ks, p).unwrap();
            let peak = kd / core::f32::consts::PI + ks * (p + 2.0) / core::f32::consts::TAU;
            // The exact mirror configuration at normal incidence and at grazing.
            for (wo, wi) in [(Vec3::Z, Vec3::Z), (grazing, mirror)] {
                let f = m.eval(wo, wi);
                assert!((f - peak).abs() <= 1e-6 * peak, "p = {p}: {f} vs {peak}");
                assert!(m.pdf(wo, wi).is_finite());
            }
            for (wo, wi) in [(grazing, grazing), (grazing, -mirror), (Vec3::Z, grazing)] {
                let (f, pdf) = (m.eval(wo, wi), m.pdf(wo, wi));
                assert!(f.is_finite() && f >= 0.0 && pdf.is_finite() && pdf >= 0.0);
            }
            assert_edge_samples("Phong", &m, &[Vec3::Z, grazing]);
        }
    }
}

#[test]
fn spectral_weights_act_per_channel() {
    let kd = Vec3::new(0.1, 0.4, 0.0);
    let ks = Vec3::new(0.9, 0.2, 0.0);
    let m = Phong::new(kd, ks, 20.0).unwrap();
    let (wo, wi) = (
        Vec3::new(0.3, -0.2, 0.9).normalize(),
        Vec3::new(-0.25, 0.3, 0.85).normalize(),
    );
    let f = m.eval(wo, wi);
    for c in 0..3 {
        let mono = Phong::new(kd[c], ks[c], 20.0).unwrap();
        assert!((f[c] - mono.eval(wo, wi)).abs() <= 1e-6 * f[c].max(1e-30));
    }
    assert_eq!(m.albedo_upper_bound(), kd + ks);
    // The lobe choice uses the channel averages: P_d = 0.5/1.6.
    let pd = 0.5_f32 / 1.6;
    let r = Vec3::new(-wo.x, -wo.y, wo.z);
    let lobe = f64::from(r.dot(wi)).powi(20) as f32;
    let expect =
        pd * wi.z / core::f32::consts::PI + (1.0 - pd) * 21.0 / core::f32::consts::TAU * lobe;
    assert!((m.pdf(wo, wi) - expect).abs() <= 1e-5 * expect);
}

#[test]
fn lobes_are_those_with_weight() {
    assert_lobes_follow_weights(|kd, ks| Phong::new(kd, ks, 10.0).unwrap().lobes());
    // A black model samples (and reports) its diffuse lobe, with f = 0.
    let black = Phong::new(0.0_f32, 0.0, 10.0).unwrap();
    let s = black.sample(Vec3::Z, Vec2::new(0.3, 0.6), 0.99).unwrap();
    assert_eq!((s.f, s.lobe), (0.0, Lobes::DIFFUSE_REFLECTION));
    // The choice follows uc: below P_d = 0.25 diffuse, above glossy.
    assert_lobe_choice(&Phong::new(0.2_f32, 0.6, 10.0).unwrap(), 0.2, 0.3);
}

#[test]
fn refuses_bad_parameters() {
    for bad in [f32::NAN, -0.1, 1.5, f32::INFINITY] {
        assert_eq!(Phong::new(bad, 0.0, 1.0).unwrap_err().param(), "kd");
        assert_eq!(Phong::new(0.0, bad, 1.0).unwrap_err().param(), "ks");
    }
    let e = Phong::new(0.6_f32, 0.5, 1.0).unwrap_err();
    assert_eq!((e.param(), e.range()), ("kd + ks", "[0, 1]"));
    let e = Phong::new(Vec3::new(0.5, 0.9, 0.1), Vec3::new(0.5, 0.2, 0.1), 1.0).unwrap_err();
    assert_eq!(e.param(), "kd + ks");
    assert!((e.value() - 1.1).abs() < 1e-6);
    for bad in [f32::NAN, -1.0, 1.1e6, f32::INFINITY] {
        let e = Phong::new(0.5_f32, 0.5, bad).unwrap_err();
        assert_eq!((e.param(), e.range()), ("exponent", "[0, 1000000]"));
    }
    // The ends of the ranges are accepted.
    assert!(Phong::new(0.0_f32, 0.0, 0.0).is_ok());
    assert!(Phong::new(0.3_f32, 0.7, Phong::<f32>::MAX_EXPONENT).is_ok());
    assert!(Phong::new(1.0_f32, 0.0, 1.0).is_ok() && Phong::new(0.0_f32, 1.0, 1.0).is_ok());
    let m = Phong::new(0.25_f32, 0.5, 7.0).unwrap();
    assert_eq!((m.kd(), m.ks(), m.exponent()), (0.25, 0.5, 7.0));
}

/// With a black specular coefficient the glossy lobe has weight 0: a lobe choice of exactly 1
/// (inside the range `debug_check` accepts) still draws the diffuse lobe, whose density the
/// sample reports.
#[test]
fn a_lobe_choice_of_one_draws_no_lobe_of_zero_weight() {
    let phong = Phong::new(0.5f32, 0.0, 50.0).unwrap();
    assert!(!phong.lobes().intersects(Lobes::GLOSSY));
    let wo = Vec3::new(0.48, 0.36, 0.8);
    for u in [[0.2f32, 0.7], [0.9, 0.1], [0.5, 0.5]] {
        let s = phong
            .sample(wo, Vec2::from(u), 1.0)
            .expect("a diffuse sample");
        assert_eq!(s.lobe, Lobes::DIFFUSE_REFLECTION);
        let p = phong.pdf(wo, s.wi);
        assert!(
            (s.pdf - p).abs() <= 1e-6 * p,
            "sample pdf {} vs pdf {p}",
            s.pdf
        );
    }
}
