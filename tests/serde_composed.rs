//! Serde for the energy-compensated models and the combinators (feature `serde`): each goes
//! out as its constructor's parameters (the parts it combines written as their own), comes
//! back equal and with the same values, and what comes in goes through the constructors, so
//! a refusal names the field and its range.

mod common;

use common::wire::{assert_refused, assert_wire, round_trip};
use lobe::bxdf::{
    CoatedConductor, CoatedDiffuse, CompensatedDielectric, CompensatedMicrofacet,
    CompensatedPlastic, Compensation, DiffuseTransmission, Lambert, Layered, Microfacet, Mix,
    Plastic, RoughDielectric, Sheen, SmoothDielectric, TransportMode, TwoSided,
};
use lobe::fresnel::{Conductor, Schlick};
use lobe::metals;
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::tables::TabulatedAlbedo;
use lobe::{Alpha, Eta, Vec3, Vec4};

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

fn eta(e: f32) -> Eta {
    Eta::new(e).unwrap()
}

fn ggx(a: f32) -> Ggx {
    Ggx::isotropic(alpha(a))
}

#[test]
fn compensated_conductors_are_the_single_scattering_model_and_the_compensation() {
    let gold = Microfacet::new(
        ggx(0.5),
        Masking::HeightCorrelated,
        Conductor {
            ior: metals::GOLD.rgb(),
        },
    );
    let compensated = gold.with_energy_compensation().unwrap();
    let json = round_trip(&compensated);
    assert!(
        json.starts_with(r#"{"distribution":{"alpha":0.5},"fresnel":{"ior":{"eta":["#),
        "{json}"
    );
    assert!(
        !json.contains("compensation"),
        "the default is left out: {json}"
    );
    let read: CompensatedMicrofacet<Ggx, Conductor<Vec3>> = serde_json::from_str(&json).unwrap();
    assert_eq!(read, compensated);

    let white = Microfacet::new(
        Beckmann::isotropic(alpha(0.7)),
        Masking::HeightCorrelated,
        Schlick::new(1.0_f32).unwrap(),
    );
    let turquin = CompensatedMicrofacet::new(white, Compensation::Turquin).unwrap();
    assert_wire(
        &turquin,
        r#"{"distribution":{"alpha":0.7},"fresnel":{"f0":1.0},"compensation":"turquin"}"#,
    );
    assert_wire(&Compensation::KullaConty, r#""kulla_conty""#);

    // The tables end at α = 1: a rougher surface is refused by name, as in code.
    assert_refused::<CompensatedMicrofacet<Ggx, Schlick>>(
        r#"{"distribution":{"alpha":1.5},"fresnel":{"f0":1.0}}"#,
        "invalid alpha (compensated) = 1.5",
    );
    // Masking is the tables' (height-correlated) and not a field.
    assert_refused::<CompensatedMicrofacet<Ggx, Schlick>>(
        r#"{"distribution":{"alpha":0.5},"masking":"separable","fresnel":{"f0":1.0}}"#,
        "unknown field `masking`",
    );
}

#[test]
fn a_compensated_model_with_a_table_of_its_own_cannot_be_written() {
    let inner = Microfacet::new(
        ggx(0.5),
        Masking::HeightCorrelated,
        Schlick::new(1.0_f32).unwrap(),
    );
    // Beckmann's row on a GGX model: a table the file could not name.
    let row = Beckmann::isotropic(alpha(0.5)).conductor_albedo().unwrap();
    let own = CompensatedMicrofacet::with_albedo(inner, row, Compensation::KullaConty);
    let err = serde_json::to_string(&own).unwrap_err().to_string();
    assert!(err.contains("table of its own"), "{err}");
    // The same model with the crate's table is written.
    let row = ggx(0.5).conductor_albedo().unwrap();
    let tabulated = CompensatedMicrofacet::with_albedo(inner, row, Compensation::KullaConty);
    assert_eq!(tabulated, inner.with_energy_compensation().unwrap());
    round_trip(&tabulated);
}

#[test]
fn compensated_glass_and_plastic_are_their_uncompensated_parameters() {
    let glass = RoughDielectric::new(ggx(0.3), eta(1.5))
        .with_mode(TransportMode::Importance)
        .with_energy_compensation()
        .unwrap();
    assert_wire(
        &glass,
        r#"{"distribution":{"alpha":0.3},"eta":1.5,"mode":"importance"}"#,
    );
    let read: CompensatedDielectric<Ggx> = serde_json::from_str(
        r#"{ "distribution": { "alpha": 0.3 }, "eta": 1.5, "mode": "importance" }"#,
    )
    .unwrap();
    assert_eq!(read, glass);
    assert_refused::<CompensatedDielectric<Ggx>>(
        r#"{"distribution":{"alpha":0.3},"eta":4.0}"#,
        "invalid eta (compensated) = 4",
    );

    let r = [0.8, 0.5, 0.25, 0.125];
    round_trip(&CompensatedPlastic::compensated(r[0], ggx(0.2), eta(1.5)).unwrap());
    round_trip(&CompensatedPlastic::compensated(Vec4::from_array(r), ggx(0.2), eta(1.5)).unwrap());
    let rgb: CompensatedPlastic<Ggx, Vec3> =
        Plastic::compensated(Vec3::new(0.8, 0.5, 0.25), ggx(0.2), eta(1.5)).unwrap();
    assert_wire(
        &rgb,
        r#"{"reflectance":[0.8,0.5,0.25],"distribution":{"alpha":0.2},"eta":1.5}"#,
    );
    let read: CompensatedPlastic<Ggx, Vec3> = serde_json::from_str(
        r#"{"reflectance":[0.8,0.5,0.25],"distribution":{"alpha":0.2},"eta":1.5}"#,
    )
    .unwrap();
    assert_eq!(read, rgb);
}

#[test]
fn diffuse_transmission_and_sheen_are_their_constructors_parameters() {
    let leaf =
        DiffuseTransmission::new(Vec3::new(0.3, 0.5, 0.1), Vec3::new(0.2, 0.4, 0.1)).unwrap();
    assert_wire(
        &leaf,
        r#"{"reflectance":[0.3,0.5,0.1],"transmittance":[0.2,0.4,0.1]}"#,
    );
    round_trip(&DiffuseTransmission::new(0.5_f32, 0.25).unwrap());
    round_trip(&DiffuseTransmission::new(Vec4::splat(0.5), Vec4::splat(0.5)).unwrap());
    // R + T > 1 is refused in the channel that breaks it, naming the transmittance.
    assert_refused::<DiffuseTransmission<Vec3>>(
        r#"{"reflectance":[0.3,0.5,0.1],"transmittance":[0.2,0.6,0.1]}"#,
        "invalid transmittance = 0.6",
    );

    let velvet = Sheen::new(Vec3::new(0.9, 0.2, 0.3), 0.5).unwrap();
    assert_wire(&velvet, r#"{"color":[0.9,0.2,0.3],"roughness":0.5}"#);
    // A roughness whose reciprocal is not exact still comes back equal.
    round_trip(&Sheen::new(0.7_f32, 0.3).unwrap());
    round_trip(&Sheen::new(Vec4::splat(0.7), 0.03).unwrap());
    let read: Sheen<Vec3> =
        serde_json::from_str(r#"{ "color": [0.9, 0.2, 0.3], "roughness": 0.5 }"#).unwrap();
    assert_eq!(read, velvet);
    // The exact Smith masking travels as a flag; the fit, the default, is not written.
    let exact = Sheen::new(Vec3::new(0.9, 0.2, 0.3), 0.03)
        .unwrap()
        .with_exact_smith();
    assert_wire(
        &exact,
        r#"{"color":[0.9,0.2,0.3],"roughness":0.03,"exact_smith":true}"#,
    );
    round_trip(&Sheen::new(0.7_f32, 0.3).unwrap().with_exact_smith());
    assert_refused::<Sheen>(
        r#"{"color":0.5,"roughness":0.001}"#,
        "invalid roughness = 0.001: expected a value in [0.01, 1]",
    );
}

#[test]
fn mix_and_two_sided_are_the_models_they_combine() {
    let red = Lambert::new(Vec3::new(0.8, 0.1, 0.1)).unwrap();
    let gloss = Microfacet::new(
        ggx(0.2),
        Masking::HeightCorrelated,
        Schlick::new(Vec3::splat(0.04)).unwrap(),
    );
    let mix = Mix::new(red, gloss, 0.25).unwrap();
    assert_wire(
        &mix,
        r#"{"first":{"reflectance":[0.8,0.1,0.1]},"second":{"distribution":{"alpha":0.2},"fresnel":{"f0":[0.04,0.04,0.04]}},"weight":0.25}"#,
    );
    let read: Mix<Lambert<Vec3>, Microfacet<Ggx, Schlick<Vec3>>> = serde_json::from_str(
        r#"{ "first": { "reflectance": [0.8, 0.1, 0.1] },
             "second": { "distribution": { "alpha": 0.2 }, "fresnel": { "f0": [0.04, 0.04, 0.04] } },
             "weight": 0.25 }"#,
    )
    .unwrap();
    assert_eq!(read, mix);
    assert_refused::<Mix<Lambert, Lambert>>(
        r#"{"first":{"reflectance":0.5},"second":{"reflectance":0.5},"weight":1.5}"#,
        "invalid weight = 1.5: expected a value in [0, 1]",
    );
    // A part's refusal is the part's own.
    assert_refused::<Mix<Lambert, Lambert>>(
        r#"{"first":{"reflectance":0.5},"second":{"reflectance":-0.5},"weight":0.5}"#,
        "invalid reflectance = -0.5",
    );

    let paper = TwoSided::new(Lambert::new(0.7_f32).unwrap());
    assert_wire(&paper, r#"{"inner":{"reflectance":0.7}}"#);
    let read: TwoSided<Lambert> = serde_json::from_str(r#"{"inner":{"reflectance":0.7}}"#).unwrap();
    assert_eq!(read, paper);
}

#[test]
fn layered_models_are_their_layers_and_the_options_that_differ_from_the_defaults() {
    let coated =
        CoatedDiffuse::coated_diffuse(Vec3::new(0.7, 0.3, 0.1), ggx(0.1), eta(1.5)).unwrap();
    let json = r#"{"top":{"distribution":{"alpha":0.1},"eta":1.5},"bottom":{"reflectance":[0.7,0.3,0.1]}}"#;
    assert_wire(&coated, json);
    let read: CoatedDiffuse<Ggx, Vec3> = serde_json::from_str(json).unwrap();
    assert_eq!(read, coated);

    let full = coated
        .with_thickness(0.1)
        .and_then(|m| m.with_medium(Vec3::splat(0.5), 0.3))
        .and_then(|m| m.with_max_depth(32))
        .and_then(|m| m.with_samples(4))
        .unwrap();
    let json = r#"{"top":{"distribution":{"alpha":0.1},"eta":1.5},"bottom":{"reflectance":[0.7,0.3,0.1]},"thickness":0.1,"medium":{"albedo":[0.5,0.5,0.5],"g":0.3},"max_depth":32,"samples":4}"#;
    assert_wire(&full, json);
    let read: CoatedDiffuse<Ggx, Vec3> = serde_json::from_str(json).unwrap();
    assert_eq!(read, full);
    // An isotropic medium leaves out its g.
    let isotropic = coated.with_medium(Vec3::splat(0.5), 0.0).unwrap();
    assert!(round_trip(&isotropic).ends_with(r#""medium":{"albedo":[0.5,0.5,0.5]}}"#));

    let copper =
        CoatedConductor::coated_conductor(ggx(0.05), eta(1.5), ggx(0.3), metals::COPPER.rgb())
            .unwrap();
    let json = round_trip(&copper);
    let read: CoatedConductor<Ggx, Ggx, Vec3> = serde_json::from_str(&json).unwrap();
    assert_eq!(read, copper);

    let glass_over_lambert =
        r#"{"top":{"distribution":{"alpha":0.1},"eta":1.5},"bottom":{"reflectance":0.5}"#;
    // Each option out of range is refused by name, and a misspelt one is an error, never a
    // silent default.
    for (option, message) in [
        (
            r#""thickness":-1"#,
            "invalid thickness = -1: expected a value in [0, 1000]",
        ),
        (
            r#""samples":0"#,
            "invalid samples = 0: expected a value in [1, 4096]",
        ),
        (
            r#""max_depth":0"#,
            "invalid max_depth = 0: expected a value in [1, 4096]",
        ),
        (
            r#""medium":{"albedo":0.5,"g":1}"#,
            "invalid g = 1: expected a value in [-0.99, 0.99]",
        ),
        (
            r#""medium":{"albedo":1.5}"#,
            "invalid albedo = 1.5: expected a value in [0, 1]",
        ),
        (r#""thicknes":0.1"#, "unknown field `thicknes`"),
    ] {
        assert_refused::<Layered<RoughDielectric<Ggx>, Lambert>>(
            &format!("{glass_over_lambert},{option}}}"),
            message,
        );
    }
}

#[test]
fn every_top_interface_and_medium_goes_out_and_comes_back() {
    let base = Lambert::new(Vec3::new(0.6, 0.5, 0.4)).unwrap();
    // A medium that absorbs everything but still has an asymmetry: written, as built.
    let black = Layered::new(RoughDielectric::new(ggx(0.2), eta(1.5)), base)
        .with_medium(Vec3::ZERO, -0.5)
        .unwrap();
    assert!(round_trip(&black).ends_with(r#""medium":{"albedo":[0.0,0.0,0.0],"g":-0.5}}"#));
    let compensated = Layered::new(
        RoughDielectric::new(ggx(0.4), eta(1.33))
            .with_energy_compensation()
            .unwrap(),
        base,
    );
    assert_wire(
        &compensated,
        r#"{"top":{"distribution":{"alpha":0.4},"eta":1.33},"bottom":{"reflectance":[0.6,0.5,0.4]}}"#,
    );
    let read: Layered<CompensatedDielectric<Ggx>, Lambert<Vec3>> = serde_json::from_str(
        r#"{"top":{"distribution":{"alpha":0.4},"eta":1.33},"bottom":{"reflectance":[0.6,0.5,0.4]}}"#,
    )
    .unwrap();
    assert_eq!(read, compensated);
    let smooth = Layered::new(SmoothDielectric::new(eta(1.5)), base)
        .with_samples(2)
        .unwrap();
    assert_wire(
        &smooth,
        r#"{"top":{"eta":1.5},"bottom":{"reflectance":[0.6,0.5,0.4]},"samples":2}"#,
    );
}
