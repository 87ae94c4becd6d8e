//! Walter et al.'s rough dielectric through the law suite, in both transport modes and from
//! both sides, with the energy bound checked where it holds: in importance mode, where the
//! albedo is the fraction of flux scattered (radiance mode scales refracted radiance by
//! `1/η'²`, so its albedo from inside a dense medium exceeds 1 by design).

mod common;

use common::laws::{Model, assert_every_model_obeys_every_law};
use lobe::bxdf::{Bxdf, RoughDielectric, TransportMode};
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::verify::{BxdfCheck, albedo_sampled};
use lobe::{Alpha, Eta};

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

fn e(x: f32) -> Eta {
    Eta::new(x).unwrap()
}

/// The model in both modes: radiance with its weaker bound `max(1, η²)` and the generalised
/// reciprocity for `η`, importance with the bound 1 and reciprocity for `1/η`.
fn both_modes(
    name: &str,
    bxdf: RoughDielectric<impl lobe::microfacet::NormalDistribution + Copy + 'static>,
) -> [Model; 2] {
    let eta = bxdf.eta().get();
    let radiance = Model {
        name: format!("{name} (radiance)"),
        bxdf: Box::new(bxdf),
        eta,
        albedo_max: f64::from(eta.max(1.0 / eta)).powi(2),
    };
    let importance = Model {
        name: format!("{name} (importance)"),
        bxdf: Box::new(bxdf.with_mode(TransportMode::Importance)),
        eta: 1.0 / eta,
        albedo_max: 1.0,
    };
    [radiance, importance]
}

fn models() -> Vec<Model> {
    let mut out = Vec::new();
    out.extend(both_modes(
        "GGX glass α=0.3",
        RoughDielectric::new(Ggx::isotropic(a(0.3)), e(1.5)),
    ));
    out.extend(both_modes(
        "GGX anisotropic α=(0.2, 0.5) η=1.33",
        RoughDielectric::new(Ggx::new(a(0.2), a(0.5)), e(1.33)),
    ));
    out.extend(both_modes(
        "Beckmann α=0.5 η=1.5",
        RoughDielectric::new(Beckmann::isotropic(a(0.5)), e(1.5)),
    ));
    out.extend(both_modes(
        "GGX bubble α=0.3 η=1/1.33",
        RoughDielectric::new(Ggx::isotropic(a(0.3)), e(1.0 / 1.33)),
    ));
    out.extend(both_modes(
        "GGX separable α=0.6 η=2.4",
        RoughDielectric::new(Ggx::isotropic(a(0.6)), e(2.4)).with_masking(Masking::Separable),
    ));
    out
}

#[test]
fn rough_dielectric_obeys_every_law() {
    assert_every_model_obeys_every_law(&models());
}

/// Near-index-matched and extreme interfaces stay total (finite, non-negative) and keep
/// generalised reciprocity.
#[test]
fn extreme_interfaces_are_total_and_reciprocal() {
    for (alpha, eta) in [
        (1e-4, 1.0001),
        (1e-4, 1.5),
        (10.0, 1.5),
        (0.3, 1.0 + 1e-4),
        (0.3, 1e-3),
        (0.3, 1e3),
    ] {
        let bxdf = RoughDielectric::new(Ggx::isotropic(a(alpha)), e(eta));
        let model = Model {
            name: format!("GGX α={alpha} η={eta}"),
            bxdf: Box::new(bxdf),
            eta,
            albedo_max: 1.0,
        };
        common::laws::assert_total(&model, 20_000);
        // At η = 1e-3 or 1e3 a refracted pair has |wi·h| ≪ 1 (the transmitted direction is
        // nearly tangent to the microfacet), and f ∝ |wi·h| carries h's f32 rounding amplified
        // by 1/|wi·h|: measured up to 6e-5, so those two are held to 1e-4; the others to the
        // suite's 1e-5.
        let tol = if !(1e-2..=1e2).contains(&eta) {
            1e-4
        } else {
            1e-5
        };
        common::laws::assert_reciprocal(&model, 20_000, tol);
    }
}

/// Energy is lost to single scattering only: with a smooth-ish surface the albedo from
/// outside is close to 1 in importance mode, and it falls with roughness.
#[test]
fn importance_albedo_is_nearly_one_for_smooth_glass() {
    let check = BxdfCheck::default();
    let wo = common::dir(30.0, 0.0);
    let albedos: Vec<_> = [0.02, 0.3, 1.0]
        .into_iter()
        .map(|alpha| {
            let glass = RoughDielectric::new(Ggx::isotropic(a(alpha)), e(1.5))
                .with_mode(TransportMode::Importance);
            let albedo = albedo_sampled(&glass, wo, &check);
            eprintln!("GGX glass α={alpha}, θo=30°, importance: albedo {albedo}");
            (format!("α = {alpha}"), albedo)
        })
        .collect();
    // One bound and two falls.
    let k = common::k_sigma(0.01, 3);
    let smooth = &albedos[0].1;
    assert!(smooth.mean - k * smooth.std_err > 0.99, "{smooth}");
    common::assert_falling("the albedo", &albedos, k);
    assert!(glass_lobes_are_reflection_and_transmission());
}

/// An index-matched interface (`η = 1`) is invisible: every sample passes straight through,
/// to `−wo`, with weight 1 in both transport modes, from either side, and `eval` and `pdf` are
/// zero (the microfacet formulas lost 37% to 49% of the light there). The `f32` values next
/// to 1 are left to the formulas, ill-conditioned still: their figures are printed (the docs
/// quote them) and the energy bound is checked, the law they meet.
#[test]
fn index_matched_interface_passes_light_through() {
    let mut rng = lobe::verify::Pcg32::new(8, 1);
    for alpha in [0.01f32, 1.0] {
        for mode in [TransportMode::Radiance, TransportMode::Importance] {
            let glass = RoughDielectric::new(Ggx::isotropic(a(alpha)), e(1.0)).with_mode(mode);
            assert_eq!(glass.lobes(), lobe::bxdf::Lobes::SPECULAR_TRANSMISSION);
            for theta in [0.0f32, 30.0, 89.0] {
                for below in [false, true] {
                    let mut wo = common::dir(theta, 0.4);
                    if below {
                        wo.z = -wo.z;
                    }
                    let s = glass.sample(wo, rng.next_vec2(), rng.next_f32()).unwrap();
                    assert_eq!(
                        (s.wi, s.lobe),
                        (-wo, lobe::bxdf::Lobes::SPECULAR_TRANSMISSION)
                    );
                    assert!((s.weight() - 1.0).abs() < 1e-6, "{s:?}");
                    let other = common::dir(40.0, 2.0) * if below { 1.0 } else { -1.0 };
                    assert_eq!((glass.eval(wo, other), glass.pdf(wo, other)), (0.0, 0.0));
                }
            }
        }
    }
    let check = BxdfCheck::default();
    let wo = common::dir(30.0, 0.0);
    let k = common::k_sigma(0.01, 6);
    for eta in [1.0 - f32::EPSILON / 2.0, 1.0 + f32::EPSILON] {
        for alpha in [0.01f32, 0.3, 1.0] {
            let glass = RoughDielectric::new(Ggx::isotropic(a(alpha)), e(eta))
                .with_mode(TransportMode::Importance);
            let albedo = albedo_sampled(&glass, wo, &check);
            eprintln!("GGX glass α={alpha}, η={eta}, θo=30°, importance: albedo {albedo}");
            assert!(albedo.mean <= 1.0 + k * albedo.std_err, "{albedo}");
        }
    }
}

fn glass_lobes_are_reflection_and_transmission() -> bool {
    let l = RoughDielectric::new(Ggx::isotropic(a(0.3)), e(1.5)).lobes();
    l.is_reflective() && l.is_transmissive() && !l.is_specular()
}
