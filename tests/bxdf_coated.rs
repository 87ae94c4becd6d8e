//! The coated models, glazed (smooth coat) and plastic (rough coat): the law suite, the
//! closed-form albedo of the glazed material, and the plastic's coat-albedo table measured
//! against Monte Carlo.

mod common;

use common::k_sigma;
use common::laws::{Model, assert_every_model_obeys_every_law};
use lobe::bxdf::{Glazed, Microfacet, Plastic};
use lobe::fresnel::Dielectric;
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::verify::{BxdfCheck, albedo_sampled};
use lobe::{Alpha, Eta};

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

fn glass() -> Eta {
    Eta::new(1.5).unwrap()
}

#[test]
fn coated_models_obey_every_law() {
    let models = [
        Model::new("glazed ρ=0.8", Glazed::new(0.8f32, glass()).unwrap()),
        Model::new("glazed ρ=1", Glazed::new(1.0f32, glass()).unwrap()),
        Model::new(
            "plastic GGX α=0.3 ρ=0.5",
            Plastic::new(0.5f32, Ggx::isotropic(a(0.3)), glass()).unwrap(),
        ),
        Model::new(
            "plastic Beckmann α=0.6 ρ=1",
            Plastic::new(1.0f32, Beckmann::isotropic(a(0.6)), glass()).unwrap(),
        ),
    ];
    assert_every_model_obeys_every_law(&models);
}

/// The glazed albedo is `F + (1 − F) ρ`: measured by sampling, and exactly 1 for a white base
/// (the white furnace).
#[test]
fn glazed_albedo_matches_its_closed_form() {
    let check = BxdfCheck::default();
    let k = k_sigma(0.01, 2 * 5);
    for rho in [0.3f32, 1.0] {
        let g = Glazed::new(rho, glass()).unwrap();
        for theta in [0.0f32, 30.0, 60.0, 80.0, 89.0] {
            let wo = common::dir(theta, 0.2);
            let e = albedo_sampled(&g, wo, &check);
            let want = f64::from(g.albedo(wo));
            assert!(
                e.within(want, k) || (e.mean - want).abs() < 1e-6,
                "ρ={rho} θ={theta}: {e} vs {want}"
            );
            if rho == 1.0 {
                assert!((want - 1.0).abs() < 1e-6);
            }
        }
    }
}

/// The plastic's tabulated coat albedo, less its margin, agrees with a Monte Carlo estimate of
/// the coat's albedo: the margin covers the table's error, so the sum cannot exceed 1.
#[test]
fn plastic_coat_table_is_within_its_margin() {
    let check = BxdfCheck {
        samples: 400_000,
        ..BxdfCheck::default()
    };
    let k = k_sigma(0.01, 3 * 6);
    let mut worst: f64 = 0.0;
    for alpha in [0.05f32, 0.3, 1.0] {
        let plastic = Plastic::new(1.0f32, Ggx::isotropic(a(alpha)), glass()).unwrap();
        let coat = Microfacet::new(
            Ggx::isotropic(a(alpha)),
            Masking::HeightCorrelated,
            Dielectric { eta: glass() },
        );
        for theta in [0.0f32, 20.0, 45.0, 60.0, 75.0, 85.0] {
            let wo = common::dir(theta, 0.0);
            let mc = albedo_sampled(&coat, wo, &check);
            // The stored entry includes the 1e-3 margin: it must not fall below the true
            // albedo (else the diffuse weight could push the sum above 1), nor sit more than
            // twice the margin above it (else the margin wastes energy).
            let stored = f64::from(plastic.coat_albedo_at(wo.z));
            worst = worst.max((stored - 1e-3 - mc.mean).abs());
            assert!(
                stored >= mc.mean - k * mc.std_err,
                "α={alpha} θ={theta}: table {stored} below Monte Carlo {mc}"
            );
            assert!(
                stored - mc.mean <= 2e-3 + k * mc.std_err,
                "α={alpha} θ={theta}: table {stored} far above Monte Carlo {mc}"
            );
            // The quadrature's own error, `Plastic`'s docs' "about 3.5e-4": under half the
            // margin.
            assert!(
                (stored - 1e-3 - mc.mean).abs() <= 5e-4 + k * mc.std_err,
                "α={alpha} θ={theta}: table {stored} vs Monte Carlo {mc}"
            );
        }
    }
    eprintln!("plastic coat table: max |table − MC| = {worst:.1e}");
}
