//! The delta-lobe models (mirror, smooth and thin dielectric), checked by their weights and
//! directions: they have no density, so no chi-square test; instead every sample's weight is
//! compared with its closed form, the lobe frequencies with the Fresnel probabilities
//! (binomial standard errors), and the directions with the laws of reflection and refraction.

mod common;

use common::k_sigma;
use common::laws::{Model, assert_energy_bound, assert_total};
use lobe::bxdf::{Bxdf, Mirror, SmoothDielectric, ThinDielectric, TransportMode};
use lobe::fresnel::{self, Conductor, NoFresnel};
use lobe::verify::{BxdfCheck, Pcg32};
use lobe::{Eta, Vec3};

fn viewer(theta: f32, below: bool) -> Vec3 {
    let w = common::dir(theta, 0.9);
    if below { Vec3::new(w.x, w.y, -w.z) } else { w }
}

#[test]
fn delta_models_are_total_and_bounded() {
    let eta = Eta::new(1.5).unwrap();
    let models = [
        Model::new("ideal mirror", Mirror::new(NoFresnel::<f32>::new())),
        Model {
            eta: 1.0 / 1.5,
            ..Model::new(
                "smooth glass (importance)",
                SmoothDielectric::new(eta).with_mode(TransportMode::Importance),
            )
        },
        Model {
            albedo_max: 2.25,
            eta: 1.5,
            ..Model::new("smooth glass (radiance)", SmoothDielectric::new(eta))
        },
        Model::new("thin glass", ThinDielectric::new(eta)),
    ];
    for m in &models {
        assert_total(m, 20_000);
        assert_energy_bound(m, &BxdfCheck::default(), models.len() * 10);
        // No density anywhere.
        let mut rng = Pcg32::new(5, 0);
        for _ in 0..1000 {
            let (a, b) = (
                lobe::sampling::uniform_sphere(rng.next_vec2()),
                lobe::sampling::uniform_sphere(rng.next_vec2()),
            );
            assert_eq!((m.bxdf.eval(a, b), m.bxdf.pdf(a, b)), (0.0, 0.0));
        }
    }
}

#[test]
fn mirror_reflects_with_the_fresnel_weight() {
    let gold = common::gold();
    let mirror = Mirror::new(Conductor { ior: gold });
    for theta in [0.0f32, 30.0, 60.0, 85.0, 89.9] {
        let wo = viewer(theta, false);
        let s = mirror.sample(wo, lobe::Vec2::ZERO, 0.3).unwrap();
        assert!((s.wi - Vec3::new(-wo.x, -wo.y, wo.z)).length() < 1e-7);
        assert!(s.is_specular() && s.lobe.is_reflective());
        let want = fresnel::conductor(wo.z, &gold);
        assert!(
            (s.weight() - want).abs().max_element() < 1e-6 * want.max_element(),
            "θ = {theta}"
        );
    }
    assert!(
        mirror
            .sample(viewer(30.0, true), lobe::Vec2::ZERO, 0.3)
            .is_none()
    );
}

/// The fraction of reflected samples is `F` (binomial error), reflected and refracted weights
/// are `1` (importance) or `1` and `1/η'²` (radiance), and refraction obeys Snell's law.
#[test]
fn smooth_dielectric_splits_by_fresnel_and_refracts_by_snell() {
    let n = 100_000;
    let k = k_sigma(0.01, 2 * 2 * 5);
    for eta_value in [1.5f32, 1.0 / 1.33] {
        let eta = Eta::new(eta_value).unwrap();
        for below in [false, true] {
            for theta in [0.0f32, 30.0, 45.0, 60.0, 85.0] {
                let wo = viewer(theta, below);
                let radiance = SmoothDielectric::new(eta);
                let importance = radiance.with_mode(TransportMode::Importance);
                let f = f64::from(fresnel::dielectric(wo.z, eta));
                let etap = if wo.z > 0.0 {
                    eta_value
                } else {
                    1.0 / eta_value
                };
                let mut rng = Pcg32::new(9, 0);
                let mut reflected = 0usize;
                for _ in 0..n {
                    let (u, uc) = (rng.next_vec2(), rng.next_f32());
                    let s = radiance.sample(wo, u, uc).unwrap();
                    let t = importance.sample(wo, u, uc).unwrap();
                    assert_eq!(s.wi, t.wi);
                    assert!(
                        (t.weight() - 1.0).abs() < 1e-5,
                        "importance weight {}",
                        t.weight()
                    );
                    if s.lobe.is_reflective() {
                        reflected += 1;
                        assert!((s.wi - Vec3::new(-wo.x, -wo.y, wo.z)).length() < 1e-6);
                        assert!((s.weight() - 1.0).abs() < 1e-5);
                    } else {
                        assert!(s.wi.z * wo.z < 0.0, "refraction stays on one side");
                        // η_i sin θi = η_t sin θt, from the tangential components.
                        let (si, st) = (wo.truncate().length(), s.wi.truncate().length());
                        assert!(
                            (si - etap * st).abs() < 2e-6,
                            "Snell: {si} vs {}",
                            etap * st
                        );
                        assert!((s.weight() - 1.0 / (etap * etap)).abs() < 1e-5 / (etap * etap));
                        assert_eq!(s.eta, etap);
                    }
                }
                let p = reflected as f64 / n as f64;
                let sigma = (f * (1.0 - f) / n as f64).sqrt();
                assert!(
                    (p - f).abs() <= k * sigma + 1e-9,
                    "η={eta_value} θ={theta} below={below}: reflected {p} vs F = {f}"
                );
            }
        }
    }
}

#[test]
fn thin_dielectric_sums_the_inter_reflections() {
    let glass = ThinDielectric::new(Eta::new(1.5).unwrap());
    // Normal incidence: R = 0.04, R' = R + T²R/(1 − R²) = 0.04 + 0.9216·0.04/0.9984.
    let want = 0.04 + 0.9216 * 0.04 / 0.9984;
    assert!((glass.reflectance(1.0) - want).abs() < 1e-6);
    // Oblique incidence, from either side (both faces border the outside, so the sheet
    // reflects alike from above and below: a signed cosine would find total internal
    // reflection from below), against the same sum over the textbook Fresnel equations in f64
    // (`common::dielectric_f64`), entered from outside.
    let sheet = |cos_i: f64| {
        let r = common::dielectric_f64(cos_i, 1.5).0;
        r + (1.0 - r) * (1.0 - r) * r / (1.0 - r * r)
    };
    for theta in [0.0f32, 60.0, 89.0] {
        let want = sheet(f64::from(theta.to_radians().cos()));
        for below in [false, true] {
            let wo = viewer(theta, below);
            let got = f64::from(glass.reflectance(wo.z));
            assert!(
                (got - want).abs() < 2e-6,
                "θ={theta} below={below}: {got} vs {want}"
            );
        }
    }
    let k = k_sigma(0.01, 3);
    for theta in [0.0f32, 60.0, 89.0] {
        let wo = viewer(theta, theta > 50.0);
        let r = f64::from(glass.reflectance(wo.z));
        let mut rng = Pcg32::new(4, 0);
        let n = 100_000;
        let mut reflected = 0usize;
        for _ in 0..n {
            let s = glass.sample(wo, rng.next_vec2(), rng.next_f32()).unwrap();
            assert!((s.weight() - 1.0).abs() < 1e-5);
            if s.lobe.is_reflective() {
                reflected += 1;
            } else {
                assert_eq!(s.wi, -wo);
            }
        }
        let p = reflected as f64 / n as f64;
        assert!(
            (p - r).abs() <= k * (r * (1.0 - r) / n as f64).sqrt() + 1e-9,
            "θ={theta}: {p} vs {r}"
        );
    }
}
