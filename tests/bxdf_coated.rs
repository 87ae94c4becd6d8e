//! The coated models, glazed (smooth coat) and plastic (rough coat): the law suite, the
//! closed-form albedo of the glazed material, and the plastic's coat-albedo table measured
//! against Monte Carlo.

mod common;

use common::k_sigma;
use common::laws::{Model, assert_every_model_obeys_every_law};
use lobe::bxdf::{Bxdf, Glazed, Microfacet, Plastic};
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

/// The glazed albedo is `F + (1 − F) ρ`, with `F` the textbook Fresnel term in `f64`: measured
/// by sampling (1 for a white base: the white furnace), and given by `Glazed::albedo`.
#[test]
fn glazed_albedo_matches_its_closed_form() {
    let check = BxdfCheck::default();
    let k = k_sigma(0.01, 2 * 5);
    for rho in [0.3f32, 1.0] {
        let g = Glazed::new(rho, glass()).unwrap();
        for theta in [0.0f32, 30.0, 60.0, 80.0, 89.0] {
            let wo = common::dir(theta, 0.2);
            let e = albedo_sampled(&g, wo, &check);
            let (f, _) = common::dielectric_f64(f64::from(wo.z), 1.5);
            let want = f + (1.0 - f) * f64::from(rho);
            assert!(
                e.within(want, k) || (e.mean - want).abs() < 1e-6,
                "ρ={rho} θ={theta}: {e} vs {want}"
            );
            let closed = f64::from(g.albedo(wo));
            assert!(
                (closed - want).abs() < 1e-6,
                "ρ={rho} θ={theta}: albedo() {closed}"
            );
        }
    }
}

/// The glazed diffuse lobe's albedo is `(1 − F(cos θo)) ρ` — what `F̄` in its normalisation
/// is for — for a coat denser than the outside and for one less dense (`η < 1`: total internal
/// reflection beyond the critical angle puts a kink in `F` that `F̄`'s quadrature must go
/// round; integrated straight across it, a white base reflected up to 1.03 at `η = 1/2.4`).
/// The albedo is integrated in `f64` by the midpoint rule in `μ = cos θi` (the lobe does not
/// depend on the azimuth; 2¹⁶ nodes, an error below 1e-8 at the kink, which the Gauss panels
/// of `common::quadrature::albedo_quadrature` are not split at), `F` is the crate's
/// exact Fresnel term (pinned against Mitsuba by `tests/fresnel.rs`; what is tested here is the
/// normalisation), and the bound 1e-5 covers the `f32` evaluations (1e-6 relative) and `F̄`'s
/// quadrature (2.5e-7).
#[test]
fn glazed_diffuse_albedo_is_exact_on_both_sides_of_one() {
    let mut worst = 0.0_f64;
    for e in [1.5f32, 1.0 / 1.33, 1.0 / 1.5, 1.0 / 2.4] {
        let eta = Eta::new(e).unwrap();
        let g = Glazed::new(1.0f32, eta).unwrap();
        for theta in [0.0f32, 20.0, 40.0] {
            let wo = common::dir(theta, 0.2);
            let n = 1 << 16;
            let sum: f64 = (0..n)
                .map(|k| {
                    let mu = (k as f64 + 0.5) / f64::from(n);
                    let wi = lobe::Vec3::new((1.0 - mu * mu).sqrt() as f32, 0.0, mu as f32);
                    f64::from(g.eval(wo, wi)) * mu
                })
                .sum();
            let albedo = 2.0 * core::f64::consts::PI * sum / f64::from(n);
            let want = 1.0 - f64::from(lobe::fresnel::dielectric(wo.z, eta));
            eprintln!("glazed η {e:.4}, θo {theta}°: diffuse albedo {albedo:.7}, want {want:.7}");
            worst = worst.max((albedo - want).abs());
        }
    }
    assert!(worst < 1e-5, "largest error {worst:.2e}");
}

/// A compensated plastic's samples carry the lobe label of the coat's lobe that drew them:
/// with a black base every sample is the coat's, and the compensated coat draws some from its
/// multiple-scattering lobe, which is diffuse (988 of 19 167 samples here, 5%, at `α = 0.8`,
/// `η = 1.5`); the plastic
/// once labelled every coat sample glossy.
#[test]
fn compensated_plastic_samples_keep_the_coats_lobe() {
    let plastic = Plastic::compensated(0.0f32, Ggx::isotropic(a(0.8)), glass()).unwrap();
    let mut rng = lobe::verify::Pcg32::new(5, 9);
    let wo = common::dir(40.0, 0.1);
    let (mut diffuse, mut glossy) = (0_u32, 0_u32);
    for _ in 0..20_000 {
        if let Some(s) = plastic.sample(wo, rng.next_vec2(), rng.next_f32()) {
            if s.lobe == lobe::bxdf::Lobes::DIFFUSE_REFLECTION {
                diffuse += 1;
            } else {
                assert_eq!(s.lobe, lobe::bxdf::Lobes::GLOSSY_REFLECTION);
                glossy += 1;
            }
        }
    }
    eprintln!("compensated plastic, black base: {diffuse} diffuse, {glossy} glossy samples");
    assert!(
        diffuse > 0 && glossy > 0,
        "{diffuse} diffuse, {glossy} glossy"
    );
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
