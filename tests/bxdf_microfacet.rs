//! The Cook-Torrance microfacet BRDF through the law suite, for every distribution and
//! masking choice, and its single-scattering energy loss measured.

mod common;

use common::laws::{Model, assert_every_model_obeys_every_law};
use lobe::bxdf::Microfacet;
use lobe::fresnel::{Conductor, NoFresnel, Schlick};
use lobe::microfacet::{Beckmann, BlinnPhongNdf, Ggx, Gtr, Masking};
use lobe::verify::{BxdfCheck, albedo_sampled};
use lobe::{Alpha, ComplexIor};

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

fn models() -> Vec<Model> {
    let gold_r = Conductor {
        ior: ComplexIor::new(0.143, 3.983).unwrap(),
    };
    let copper_g = Conductor {
        ior: ComplexIor::new(0.95, 2.57).unwrap(),
    };
    let mut out = vec![
        Model::new(
            "GGX gold α=0.3",
            Microfacet::new(Ggx::isotropic(a(0.3)), Masking::HeightCorrelated, gold_r),
        ),
        Model::new(
            "GGX anisotropic α=(0.15, 0.6)",
            Microfacet::new(
                Ggx::new(a(0.15), a(0.6)),
                Masking::HeightCorrelated,
                copper_g,
            ),
        ),
        Model::new(
            "Beckmann copper α=0.4",
            Microfacet::new(
                Beckmann::isotropic(a(0.4)),
                Masking::HeightCorrelated,
                copper_g,
            ),
        ),
        Model::new(
            "Beckmann V-cavity (Cook-Torrance) α=0.3",
            Microfacet::new(
                Beckmann::isotropic(a(0.3)),
                Masking::VCavity,
                Schlick::new(0.04).unwrap(),
            ),
        ),
        Model::new(
            "GTR γ=1 α=0.3",
            Microfacet::new(
                Gtr::new(a(0.3), 1.0).unwrap(),
                Masking::HeightCorrelated,
                Schlick::new(0.04).unwrap(),
            ),
        ),
        Model::new(
            "Blinn-Phong NDF α=0.3",
            Microfacet::new(
                BlinnPhongNdf::new(a(0.3)).unwrap().with_exact_smith(),
                Masking::Separable,
                Schlick::new(0.5).unwrap(),
            ),
        ),
    ];
    for alpha in [0.2, 1.0] {
        out.push(Model::new(
            format!("GGX F=1 α={alpha}"),
            Microfacet::new(
                Ggx::isotropic(a(alpha)),
                Masking::HeightCorrelated,
                NoFresnel::<f32>::new(),
            ),
        ));
    }
    out
}

#[test]
fn microfacet_models_obey_every_law() {
    assert_every_model_obeys_every_law(&models());
}

/// With `F = 1` the albedo is the fraction of light that leaves after one bounce: below 1,
/// falling with roughness. The figures are printed; the test asserts the ordering that single
/// scattering implies at 60°, and that `α = 1` loses more than 10% there.
#[test]
fn single_scattering_loses_energy_with_roughness() {
    let check = BxdfCheck::default();
    let wo = common::dir(60.0, 0.0);
    let albedos: Vec<_> = [0.05, 0.2, 0.5, 1.0]
        .into_iter()
        .map(|alpha| {
            let m = Microfacet::new(
                Ggx::isotropic(a(alpha)),
                Masking::HeightCorrelated,
                NoFresnel::<f32>::new(),
            );
            let e = albedo_sampled(&m, wo, &check);
            eprintln!("GGX F=1 α={alpha}, θo=60°: albedo {e}");
            (format!("α = {alpha}"), e)
        })
        .collect();
    let k = common::k_sigma(0.01, 4);
    common::assert_falling("the albedo", &albedos, k);
    let last = &albedos[3].1;
    assert!(
        last.mean + k * last.std_err < 0.9,
        "α = 1 should lose more than 10% at 60°: {last}"
    );
}
