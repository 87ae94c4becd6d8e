//! Serde for the parts models are built from (feature `serde`): the microfacet distributions,
//! the Fresnel terms and the closed choices. What goes out is the constructor's parameters and
//! comes back equal; what comes in goes through the constructor, and a refusal names the field
//! and its range.

mod common;

use common::wire::{assert_all_refused, assert_refused, assert_wire, round_trip};
use lobe::bxdf::{BlinnPhongForm, TransportMode};
use lobe::fresnel::{Conductor, Dielectric, NoFresnel, Schlick};
use lobe::metals;
use lobe::microfacet::{Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr, Masking};
use lobe::{Alpha, ComplexIor, Eta, Vec3, Vec4};

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

#[test]
fn choices_are_snake_case_names() {
    assert_wire(&Masking::HeightCorrelated, r#""height_correlated""#);
    assert_wire(&Masking::Separable, r#""separable""#);
    assert_wire(&Masking::VCavity, r#""v_cavity""#);
    assert_wire(&BeckmannMasking::Exact, r#""exact""#);
    assert_wire(&BeckmannMasking::WalterRational, r#""walter_rational""#);
    assert_wire(&TransportMode::Radiance, r#""radiance""#);
    assert_wire(&TransportMode::Importance, r#""importance""#);
    assert_wire(&BlinnPhongForm::Modified, r#""modified""#);
    assert_wire(&BlinnPhongForm::Normalized, r#""normalized""#);
    assert_refused::<Masking>(
        r#""smith""#,
        "unknown variant `smith`, expected one of `height_correlated`, `separable`, `v_cavity`",
    );
    assert_refused::<TransportMode>(r#""Radiance""#, "unknown variant `Radiance`");
}

#[test]
fn ggx_is_its_widths_and_its_switch() {
    assert_wire(&Ggx::isotropic(alpha(0.3)), r#"{"alpha":0.3}"#);
    assert_wire(
        &Ggx::new(alpha(0.3), alpha(0.05)),
        r#"{"alpha_x":0.3,"alpha_y":0.05}"#,
    );
    assert_wire(
        &Ggx::isotropic(alpha(0.3)).with_bounded_reflection(false),
        r#"{"alpha":0.3,"bounded_reflection":false}"#,
    );
    // What a file says builds what the constructors build; the switch is on unless said.
    let read: Ggx = serde_json::from_str(r#"{ "alpha_x": 0.2, "alpha_y": 0.2 }"#).unwrap();
    assert_eq!(read, Ggx::isotropic(alpha(0.2)));
    assert!(read.bounded_reflection());
    let read: Ggx = serde_json::from_str(r#"{ "alpha": 1, "bounded_reflection": true }"#).unwrap();
    assert_eq!(read, Ggx::isotropic(alpha(1.0)));
}

#[test]
fn ggx_refuses_bad_widths_by_their_field() {
    assert_all_refused::<Ggx>(&[
        (
            r#"{ "alpha": -1 }"#,
            "invalid alpha = -1: expected a value in [0.0001, 10]",
        ),
        (
            r#"{ "alpha_x": 0.3, "alpha_y": 0 }"#,
            "invalid alpha_y = 0: expected a value in [0.0001, 10]",
        ),
        (
            r#"{ "alpha_x": 11, "alpha_y": 0.3 }"#,
            "invalid alpha_x = 11: expected a value in [0.0001, 10]",
        ),
        // JSON has no NaN or infinity, but a number beyond f32 becomes one: refused all the
        // same.
        (
            r#"{ "alpha": 1e39 }"#,
            "invalid alpha = inf: expected a value in [0.0001, 10]",
        ),
        ("{}", "missing field `alpha`"),
        (r#"{ "alpha_x": 0.3 }"#, "missing field `alpha_y`"),
        (
            r#"{ "alpha": 0.3, "alpha_y": 0.3 }"#,
            "`alpha` (isotropic) and `alpha_x`/`alpha_y` (anisotropic) exclude each other",
        ),
        (r#"{ "roughness": 0.3 }"#, "unknown field `roughness`"),
        (r#"{ "alpha": "0.3" }"#, "invalid type: string"),
    ]);
}

#[test]
fn beckmann_is_its_widths_and_its_masking() {
    assert_wire(&Beckmann::isotropic(alpha(0.5)), r#"{"alpha":0.5}"#);
    assert_wire(
        &Beckmann::new(alpha(0.1), alpha(0.4)).with_masking(BeckmannMasking::WalterRational),
        r#"{"alpha_x":0.1,"alpha_y":0.4,"masking":"walter_rational"}"#,
    );
    let read: Beckmann = serde_json::from_str(r#"{ "alpha": 0.5, "masking": "exact" }"#).unwrap();
    assert_eq!(read, Beckmann::isotropic(alpha(0.5)));
    assert_all_refused::<Beckmann>(&[
        (
            r#"{ "alpha_x": 0.1, "alpha_y": -0.4 }"#,
            "invalid alpha_y = -0.4: expected a value in [0.0001, 10]",
        ),
        (
            r#"{ "alpha": 0.5, "masking": "v_cavity" }"#,
            "unknown variant `v_cavity`, expected `exact` or `walter_rational`",
        ),
    ]);
}

#[test]
fn gtr_is_its_width_and_exponent_and_rebuilds_its_table() {
    // The Smith table (128 entries) stays out of the file; the constructor tabulates it again,
    // to the same numbers.
    for (a, gamma) in [(0.1, 1.0), (0.3, 2.0), (0.05, 0.5), (1.0, 10.0)] {
        let gtr = Gtr::new(alpha(a), gamma).unwrap();
        assert_wire(&gtr, &format!(r#"{{"alpha":{a:?},"gamma":{gamma:?}}}"#));
    }
    assert_all_refused::<Gtr>(&[
        (
            r#"{ "alpha": 0.1, "gamma": 0 }"#,
            "invalid gamma = 0: expected a value in (0, 10]",
        ),
        (
            r#"{ "alpha": 0, "gamma": 1 }"#,
            "invalid alpha = 0: expected a value in [0.0001, 10]",
        ),
        (r#"{ "alpha": 0.1 }"#, "missing field `gamma`"),
    ]);
}

#[test]
fn blinn_phong_ndf_comes_back_from_either_constructor() {
    // The two constructors round differently; each value comes back equal, with or without its
    // own Smith table.
    for a in [1e-3, 0.05, 0.3, 0.7, 1.0] {
        let ndf = BlinnPhongNdf::new(alpha(a)).unwrap();
        round_trip(&ndf);
        round_trip(&ndf.with_exact_smith());
    }
    for p in [0.0, 1.0, 20.0, 333.3, 1e5, 1e8] {
        let ndf = BlinnPhongNdf::from_exponent(p).unwrap();
        round_trip(&ndf);
        let json = round_trip(&ndf.with_exact_smith());
        assert!(json.ends_with(r#","exact_smith":true}"#), "{json}");
    }
    // Each is written as the shorter of the parameters that build it again.
    let from_exponent = |p| BlinnPhongNdf::from_exponent(p).unwrap();
    let from_width = |a| BlinnPhongNdf::new(alpha(a)).unwrap();
    assert_eq!(round_trip(&from_exponent(20.0)), r#"{"exponent":20.0}"#);
    assert_eq!(round_trip(&from_exponent(1e5)), r#"{"exponent":100000.0}"#);
    assert_eq!(round_trip(&from_width(0.3)), r#"{"alpha":0.3}"#);
    assert_eq!(round_trip(&from_width(0.7)), r#"{"alpha":0.7}"#);
    let ndf = from_exponent(20.0);
    let read: BlinnPhongNdf = serde_json::from_str(r#"{ "exponent": 20 }"#).unwrap();
    assert_eq!(read, ndf);
    let read: BlinnPhongNdf =
        serde_json::from_str(r#"{ "alpha": 0.3, "exact_smith": true }"#).unwrap();
    assert_eq!(
        read,
        BlinnPhongNdf::new(alpha(0.3)).unwrap().with_exact_smith()
    );
}

#[test]
fn blinn_phong_ndf_refusals_name_the_field() {
    assert_all_refused::<BlinnPhongNdf>(&[
        (
            r#"{ "alpha": 2 }"#,
            "invalid alpha = 2: expected a value in [0.0001, 1] (Blinn-Phong)",
        ),
        (
            r#"{ "alpha": 0 }"#,
            "invalid alpha = 0: expected a value in [0.0001, 1] (Blinn-Phong)",
        ),
        // Beyond Alpha's own range too, the range named is Blinn-Phong's (it said
        // [0.0001, 10]).
        (
            r#"{ "alpha": 50 }"#,
            "invalid alpha = 50: expected a value in [0.0001, 1] (Blinn-Phong)",
        ),
        (
            r#"{ "exponent": -1 }"#,
            "invalid exponent = -1: expected a value in [0, 1e8]",
        ),
        (
            r#"{ "alpha": 0.3, "exponent": 20 }"#,
            "a Blinn-Phong distribution takes `alpha` or `exponent`, not both",
        ),
        (r#"{ "exact_smith": true }"#, "missing field `alpha`"),
    ]);
}

#[test]
fn fresnel_terms_are_their_parameters() {
    assert_wire(&Schlick::new(0.04_f32).unwrap(), r#"{"f0":0.04}"#);
    assert_wire(
        &Schlick::new(Vec3::new(0.95, 0.64, 0.54)).unwrap(),
        r#"{"f0":[0.95,0.64,0.54]}"#,
    );
    round_trip(&Schlick::new(Vec4::new(0.9, 0.8, 0.7, 0.6)).unwrap());
    assert_wire(
        &Conductor {
            ior: ComplexIor::new(0.2_f32, 3.9).unwrap(),
        },
        r#"{"ior":{"eta":0.2,"k":3.9}}"#,
    );
    round_trip(&Conductor {
        ior: metals::GOLD.rgb(),
    });
    round_trip(&Conductor {
        ior: metals::COPPER.spectral(Vec4::new(450.0, 520.0, 590.0, 660.0)),
    });
    assert_wire(
        &Dielectric {
            eta: Eta::new(1.5).unwrap(),
        },
        r#"{"eta":1.5}"#,
    );
    assert_wire(&NoFresnel::<f32>::new(), "{}");
    assert_wire(&NoFresnel::<Vec3>::new(), "{}");
}

#[test]
fn fresnel_refusals_name_the_field() {
    assert_all_refused::<Schlick<Vec3>>(&[
        (
            r#"{ "f0": [0.9, 1.5, 0.5] }"#,
            "invalid f0 = 1.5: expected a value in [0, 1]",
        ),
        (r#"{ "f0": 0.04 }"#, "invalid type: floating point `0.04`"),
    ]);
    assert_refused::<Schlick>(
        r#"{ "f0": -0.1 }"#,
        "invalid f0 = -0.1: expected a value in [0, 1]",
    );
    assert_all_refused::<Conductor<Vec3>>(&[
        (
            r#"{ "ior": { "eta": [0.2, 0.4, 1.4], "k": [3.9, -2.4, 1.6] } }"#,
            "invalid k = -2.4: expected a value in [0, 1000]",
        ),
        (r#"{ "ior": "gold" }"#, "invalid type: string"),
    ]);
    assert_refused::<Dielectric>(
        r#"{ "eta": 0 }"#,
        "invalid eta = 0: expected a value in [0.001, 1000]",
    );
    assert_refused::<NoFresnel>(r#"{ "f0": 1 }"#, "unknown field `f0`");
}
