//! `Mix` and `TwoSided` (issue 12): the blend's value, pdf and albedo are the weighted sums of
//! its parts', its weight is validated and its sampler draws each part by its weight;
//! `TwoSided` is its model from above and the model's mirror image from below; both pass every
//! law through `check_bxdf`.

mod common;

use lobe::bxdf::{Bxdf, Lambert, Microfacet, Mix, Phong, TwoSided};
use lobe::fresnel::Schlick;
use lobe::microfacet::{Ggx, Masking};
use lobe::verify::{Config, Pcg32, albedo, check_bxdf};
use lobe::{Alpha, Vec3};

/// Statistical tests in this file: 3 harness runs and 3 × 2 albedo comparisons.
const TESTS: usize = 3 + 6;

fn glossy() -> Microfacet<Ggx, Schlick<f32>> {
    Microfacet::new(
        Ggx::isotropic(Alpha::new(0.2).unwrap()),
        Masking::HeightCorrelated,
        Schlick::new(0.9_f32).unwrap(),
    )
}

fn config() -> Config {
    common::combinator_budget(50_000, TESTS)
}

#[test]
fn the_blend_is_the_weighted_sum_of_its_parts() {
    let (a, b) = (Lambert::new(0.6_f32).unwrap(), glossy());
    let mut rng = Pcg32::new(3, 1);
    for w in [0.0_f32, 0.25, 0.7, 1.0] {
        let mix = Mix::new(a, b, w).unwrap();
        for _ in 0..2_000 {
            let wo = lobe::sampling::uniform_sphere(rng.next_vec2());
            let wi = lobe::sampling::uniform_sphere(rng.next_vec2());
            let f = (1.0 - w) * a.eval(wo, wi) + w * b.eval(wo, wi);
            let p = (1.0 - w) * a.pdf(wo, wi) + w * b.pdf(wo, wi);
            assert!((mix.eval(wo, wi) - f).abs() <= 1e-6 * f, "w={w}");
            assert!((mix.pdf(wo, wi) - p).abs() <= 1e-6 * p, "w={w}");
            // A sample's value and density are the blend's at its direction.
            if let Some(s) = mix.sample(wo, rng.next_vec2(), rng.next_f32()) {
                assert!((s.f - mix.eval(wo, s.wi)).abs() <= 1e-5 * s.f, "{s:?}");
                assert!((s.pdf - mix.pdf(wo, s.wi)).abs() <= 1e-5 * s.pdf, "{s:?}");
            }
        }
    }
}

#[test]
fn the_albedo_is_the_weighted_sum_of_the_albedos() {
    let k = common::k_sigma(0.01, TESTS);
    let (a, b) = (Phong::new(0.3_f32, 0.6, 30.0).unwrap(), glossy());
    let w = 0.4;
    let mix = Mix::new(a, b, w).unwrap();
    let c = config();
    for theta in [10.0, 50.0, 80.0] {
        let wo = common::dir(theta, 0.3);
        let (am, aa, ab) = (albedo(&mix, wo, &c), albedo(&a, wo, &c), albedo(&b, wo, &c));
        let expected = (1.0 - f64::from(w)) * aa.sampled.mean + f64::from(w) * ab.sampled.mean;
        let se =
            ((1.0 - f64::from(w)) * aa.sampled.std_err).hypot(f64::from(w) * ab.sampled.std_err);
        for (name, e) in [("sampled", am.sampled), ("cosine", am.cosine.unwrap())] {
            let sigma = e.std_err.hypot(se);
            eprintln!("θo={theta}° mix albedo {name} {e} against {expected:.5} ± {se:.1e}");
            assert!(
                (e.mean - expected).abs() <= k * sigma,
                "θo={theta}° {name}: {e}"
            );
        }
    }
}

#[test]
fn the_weight_is_validated() {
    let (a, b) = (Lambert::new(0.5_f32).unwrap(), glossy());
    for bad in [f32::NAN, -0.1, 1.5, f32::INFINITY] {
        assert_eq!(Mix::new(a, b, bad).unwrap_err().param(), "weight");
    }
    assert_eq!(Mix::new(a, b, 0.3).unwrap().weight(), 0.3);
}

#[test]
fn blends_obey_every_law() {
    let c = config();
    let satin = Mix::new(Lambert::new(0.5_f32).unwrap(), glossy(), 0.3).unwrap();
    let report = check_bxdf("Mix(Lambert 0.5, GGX α=0.2 Schlick 0.9, 0.3)", &satin, &c);
    eprintln!("{report}");
    assert!(report.passed(), "{report}");
    // RGB, a blend of two RGB models.
    let rgb = Mix::new(
        Lambert::new(Vec3::new(0.8, 0.3, 0.1)).unwrap(),
        Phong::new(Vec3::splat(0.1), Vec3::splat(0.5), 50.0).unwrap(),
        0.5,
    )
    .unwrap();
    let report = check_bxdf("Mix RGB (Lambert, Phong)", &rgb, &c);
    eprintln!("{report}");
    assert!(report.passed(), "{report}");
}

#[test]
fn two_sided_is_the_model_above_and_its_mirror_below() {
    let inner = glossy();
    let two = TwoSided::new(inner);
    let mirror = |w: Vec3| Vec3::new(w.x, w.y, -w.z);
    let mut rng = Pcg32::new(9, 2);
    for _ in 0..5_000 {
        let wo = lobe::sampling::uniform_sphere(rng.next_vec2());
        let wi = lobe::sampling::uniform_sphere(rng.next_vec2());
        let (f, p) = (two.eval(wo, wi), two.pdf(wo, wi));
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        if wo.z >= 0.0 {
            assert_eq!((f, p), (inner.eval(wo, wi), inner.pdf(wo, wi)));
            assert_eq!(two.sample(wo, u, uc), inner.sample(wo, u, uc));
        } else {
            let (mo, mi) = (mirror(wo), mirror(wi));
            assert_eq!((f, p), (inner.eval(mo, mi), inner.pdf(mo, mi)));
            let (s, t) = (two.sample(wo, u, uc), inner.sample(mo, u, uc));
            assert_eq!(
                s.map(|s| (mirror(s.wi), s.f, s.pdf)),
                t.map(|t| (t.wi, t.f, t.pdf))
            );
        }
        // Light never crosses.
        if wo.z * wi.z < 0.0 {
            assert_eq!(f, 0.0);
        }
    }
    let both_sides = Config {
        directions: common::both_sides(&[0.0, 40.0, 80.0]),
        ..config()
    };
    let report = check_bxdf("TwoSided(GGX α=0.2)", &two, &both_sides);
    eprintln!("{report}");
    assert!(report.passed(), "{report}");
}

/// A lobe choice of exactly 1 (inside the range `debug_check` accepts) picks no part of zero
/// weight: the sample's density is the model's `pdf` at its direction, and the lobe the
/// chosen part's.
#[test]
fn a_lobe_choice_of_one_picks_no_part_of_zero_weight() {
    let glossy = Phong::new(0.0f32, 0.9, 1000.0).unwrap();
    let mix = Mix::new(Lambert::new(0.8f32).unwrap(), glossy, 0.0).unwrap();
    let wo = Vec3::new(0.48, 0.36, 0.8);
    for u in [[0.2f32, 0.7], [0.9, 0.1], [0.5, 0.5]] {
        let s = mix
            .sample(wo, lobe::Vec2::from(u), 1.0)
            .expect("a diffuse sample");
        assert!(
            !s.lobe.intersects(lobe::bxdf::Lobes::GLOSSY),
            "{:?}",
            s.lobe
        );
        let p = mix.pdf(wo, s.wi);
        assert!(
            (s.pdf - p).abs() <= 1e-6 * p,
            "sample pdf {} vs pdf {p}",
            s.pdf
        );
    }
}

/// `lobes` names the lobes of the parts that can be drawn: a part of weight 0 adds none.
#[test]
fn lobes_leave_out_a_part_of_zero_weight() {
    use lobe::bxdf::Lobes;
    let glossy = Phong::new(0.0f32, 0.9, 100.0).unwrap();
    let matte = Lambert::new(0.8f32).unwrap();
    assert_eq!(
        Mix::new(matte, glossy, 0.0).unwrap().lobes(),
        Lobes::DIFFUSE_REFLECTION
    );
    assert_eq!(
        Mix::new(matte, glossy, 1.0).unwrap().lobes(),
        Lobes::GLOSSY_REFLECTION
    );
    assert_eq!(
        Mix::new(matte, glossy, 0.5).unwrap().lobes(),
        Lobes::DIFFUSE_REFLECTION | Lobes::GLOSSY_REFLECTION
    );
}
