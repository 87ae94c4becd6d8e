//! Serde for every model (feature `serde`): a model goes out as its constructor's parameters
//! and comes back equal on every spectrum carrier; what comes in goes through the model's
//! constructor, so a file cannot describe a model that breaks the "total" promise, and a
//! refusal names the field and its range.

mod common;

use common::wire::{assert_all_refused, assert_refused, assert_wire, round_trip};
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, Mirror, Mono, OrenNayar, Phong, Plastic, RoughConductor, RoughDielectric,
    SmoothDielectric, ThinDielectric, TransportMode,
};
use lobe::fresnel::{Conductor, Dielectric, NoFresnel, Schlick};
use lobe::metals;
use lobe::microfacet::{Beckmann, BlinnPhongNdf, Ggx, Gtr, Masking};
use lobe::{Alpha, Eta, Roughness, Vec3, Vec4};
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt::Debug;

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

fn eta(e: f32) -> Eta {
    Eta::new(e).unwrap()
}

/// The same reflectance on each carrier: one channel, RGB, four wavelengths.
fn carriers(r: [f32; 4]) -> (f32, Vec3, Vec4) {
    (r[0], Vec3::new(r[0], r[1], r[2]), Vec4::from_array(r))
}

/// Round-trips the models built on every carrier from `r`, and returns the RGB model's JSON.
fn round_trip_carriers<F32, RGB, WL>(
    r: [f32; 4],
    build_f32: impl Fn(f32) -> F32,
    build_rgb: impl Fn(Vec3) -> RGB,
    build_wl: impl Fn(Vec4) -> WL,
) -> String
where
    F32: Serialize + DeserializeOwned + PartialEq + Debug,
    RGB: Serialize + DeserializeOwned + PartialEq + Debug,
    WL: Serialize + DeserializeOwned + PartialEq + Debug,
{
    let (mono, rgb, wl) = carriers(r);
    round_trip(&build_f32(mono));
    round_trip(&build_wl(wl));
    round_trip(&build_rgb(rgb))
}

/// Round-trips every carrier of a model generic over its spectrum, built by the generic
/// function `$build`, and evaluates to the RGB model's JSON.
macro_rules! every_carrier {
    ($r:expr, $build:expr) => {
        round_trip_carriers(
            $r,
            |s: f32| $build(s),
            |s: Vec3| $build(s),
            |s: Vec4| $build(s),
        )
    };
}

#[test]
fn diffuse_models_are_their_reflectance_and_roughness() {
    let r = [0.8, 0.5, 0.25, 0.125];
    let json = every_carrier!(r, |s| Lambert::new(s).unwrap());
    assert_eq!(json, r#"{"reflectance":[0.8,0.5,0.25]}"#);
    assert_wire(&Lambert::new(0.5_f32).unwrap(), r#"{"reflectance":0.5}"#);
    assert_wire(
        &Lambert::new(Vec4::new(0.1, 0.2, 0.3, 0.4)).unwrap(),
        r#"{"reflectance":[0.1,0.2,0.3,0.4]}"#,
    );

    let json = every_carrier!(r, |s| OrenNayar::new(s, 0.35).unwrap());
    assert_eq!(json, r#"{"reflectance":[0.8,0.5,0.25],"sigma":0.35}"#);

    let json = every_carrier!(r, |s| EnergyPreservingOrenNayar::new(s, 0.5).unwrap());
    assert_eq!(json, r#"{"reflectance":[0.8,0.5,0.25],"roughness":0.5}"#);
    let json = every_carrier!(r, |s| EnergyPreservingOrenNayar::new(s, 1.0)
        .unwrap()
        .with_exact_albedo());
    assert_eq!(
        json,
        r#"{"reflectance":[0.8,0.5,0.25],"roughness":1.0,"exact_albedo":true}"#
    );

    let rough = Roughness::new(0.6).unwrap();
    let json = every_carrier!(r, |s| DisneyDiffuse::new(s, rough).unwrap());
    assert_eq!(json, r#"{"reflectance":[0.8,0.5,0.25],"roughness":0.6}"#);
}

#[test]
fn diffuse_refusals_name_the_field() {
    assert_all_refused::<Lambert<Vec3>>(&[
        (
            r#"{ "reflectance": [0.8, 1.5, 0.2] }"#,
            "invalid reflectance = 1.5: expected a value in [0, 1]",
        ),
        (r#"{ "reflectance": [0.8, 0.5] }"#, "invalid length 2"),
        (r#"{ "albedo": [0.8, 0.5, 0.2] }"#, "unknown field `albedo`"),
    ]);
    assert_all_refused::<Lambert>(&[
        (
            r#"{ "reflectance": -0.5 }"#,
            "invalid reflectance = -0.5: expected a value in [0, 1]",
        ),
        ("{}", "missing field `reflectance`"),
    ]);
    assert_refused::<OrenNayar>(
        r#"{ "reflectance": 0.5, "sigma": 2 }"#,
        "invalid sigma = 2: expected a value in [0, π/2]",
    );
    assert_refused::<OrenNayar<Vec3>>(
        r#"{ "reflectance": [0.5, 2, 0.5], "sigma": 0.3 }"#,
        "invalid reflectance = 2: expected a value in [0, 1]",
    );
    assert_all_refused::<EnergyPreservingOrenNayar>(&[
        (
            r#"{ "reflectance": 0.5, "roughness": 1.5 }"#,
            "invalid roughness = 1.5: expected a value in [0, 1]",
        ),
        (
            r#"{ "reflectance": 0.5, "roughness": 0.5, "exact_albedo": "yes" }"#,
            "invalid type: string",
        ),
    ]);
    assert_all_refused::<DisneyDiffuse<Vec3>>(&[
        (
            r#"{ "reflectance": [0.5, 0.5, 0.5], "roughness": -0.1 }"#,
            "invalid roughness = -0.1: expected a value in [0, 1]",
        ),
        (
            r#"{ "reflectance": [0.5, 0.5, 1.01], "roughness": 0.1 }"#,
            "invalid reflectance = 1.01: expected a value in [0, 1]",
        ),
    ]);
}

#[test]
fn phong_models_are_kd_ks_and_exponent() {
    let kd = [0.5, 0.4, 0.3, 0.2];
    let json = every_carrier!(kd, |s| Phong::new(s, s * 0.5, 50.0).unwrap());
    assert_eq!(
        json,
        r#"{"kd":[0.5,0.4,0.3],"ks":[0.25,0.2,0.15],"exponent":50.0}"#
    );
    let json = every_carrier!(kd, |s| {
        BlinnPhong::new(s, s * 0.5, 80.0, BlinnPhongForm::Normalized).unwrap()
    });
    assert_eq!(
        json,
        r#"{"kd":[0.5,0.4,0.3],"ks":[0.25,0.2,0.15],"exponent":80.0}"#
    );
    let json = every_carrier!(kd, |s| {
        BlinnPhong::new(s, s * 0.5, 80.0, BlinnPhongForm::Modified).unwrap()
    });
    assert_eq!(
        json,
        r#"{"kd":[0.5,0.4,0.3],"ks":[0.25,0.2,0.15],"exponent":80.0,"form":"modified"}"#
    );
    let read: BlinnPhong =
        serde_json::from_str(r#"{ "kd": 0.5, "ks": 0.25, "exponent": 8, "form": "normalized" }"#)
            .unwrap();
    assert_eq!(
        read,
        BlinnPhong::new(0.5, 0.25, 8.0, BlinnPhongForm::Normalized).unwrap()
    );
}

/// The refusals Phong and Blinn-Phong share: their weights, their sum and the exponent.
fn phong_family_refusals<M: serde::de::DeserializeOwned + std::fmt::Debug>() {
    for (json, message) in [
        (
            r#"{ "kd": [0.5, 0.5, 1.2], "ks": [0, 0, 0], "exponent": 10 }"#,
            "invalid kd = 1.2: expected a value in [0, 1]",
        ),
        (
            r#"{ "kd": [0.5, 0.5, 0.5], "ks": [0, -1, 0], "exponent": 10 }"#,
            "invalid ks = -1: expected a value in [0, 1]",
        ),
        (
            r#"{ "kd": [0.5, 0.5, 0.5], "ks": [0.25, 0.75, 0.25], "exponent": 10 }"#,
            "invalid kd + ks = 1.25: expected a value in [0, 1]",
        ),
        (
            r#"{ "kd": [0.5, 0.5, 0.5], "ks": [0.25, 0.25, 0.25], "exponent": -3 }"#,
            "invalid exponent = -3: expected a value in [0, 1000000]",
        ),
        (
            r#"{ "kd": [0.5, 0.5, 0.5], "ks": [0.25, 0.25, 0.25], "exponent": 1e7 }"#,
            "invalid exponent = 10000000: expected a value in [0, 1000000]",
        ),
        (
            r#"{ "kd": [0.5, 0.5, 0.5], "ks": [0.25, 0.25, 0.25] }"#,
            "missing field `exponent`",
        ),
    ] {
        assert_refused::<M>(json, message);
    }
}

#[test]
fn phong_refusals_name_the_field() {
    phong_family_refusals::<Phong<Vec3>>();
    phong_family_refusals::<BlinnPhong<Vec3>>();
    assert_refused::<BlinnPhong>(
        r#"{ "kd": 0.5, "ks": 0.25, "exponent": 8, "form": "phong" }"#,
        "unknown variant `phong`, expected `modified` or `normalized`",
    );
    // Phong has no form.
    assert_refused::<Phong>(
        r#"{ "kd": 0.5, "ks": 0.25, "exponent": 8, "form": "modified" }"#,
        "unknown field `form`",
    );
}

#[test]
fn microfacet_models_are_their_parts() {
    let gold: RoughConductor<Ggx, Vec3> = Microfacet::new(
        Ggx::isotropic(alpha(0.2)),
        Masking::HeightCorrelated,
        Conductor {
            ior: metals::GOLD.rgb(),
        },
    );
    let json = round_trip(&gold);
    assert!(
        json.starts_with(r#"{"distribution":{"alpha":0.2},"fresnel":{"ior":{"eta":["#),
        "{json}"
    );
    let mono = Microfacet::new(
        Beckmann::new(alpha(0.1), alpha(0.3)),
        Masking::VCavity,
        Schlick::new(0.04_f32).unwrap(),
    );
    assert_wire(
        &mono,
        r#"{"distribution":{"alpha_x":0.1,"alpha_y":0.3},"masking":"v_cavity","fresnel":{"f0":0.04}}"#,
    );
    round_trip(&Microfacet::new(
        Gtr::new(alpha(0.25), 1.5).unwrap(),
        Masking::Separable,
        NoFresnel::<Vec4>::new(),
    ));
    round_trip(&Microfacet::new(
        BlinnPhongNdf::from_exponent(100.0)
            .unwrap()
            .with_exact_smith(),
        Masking::HeightCorrelated,
        Dielectric { eta: eta(1.33) },
    ));
    round_trip(&Microfacet::new(
        Ggx::new(alpha(0.5), alpha(0.05)).with_bounded_reflection(false),
        Masking::HeightCorrelated,
        Conductor {
            ior: metals::ALUMINIUM.spectral(Vec4::new(400.0, 500.0, 600.0, 700.0)),
        },
    ));

    let glass = RoughDielectric::new(Ggx::isotropic(alpha(0.1)), eta(1.5));
    assert_wire(&glass, r#"{"distribution":{"alpha":0.1},"eta":1.5}"#);
    assert_wire(
        &RoughDielectric::new(Beckmann::isotropic(alpha(0.3)), eta(0.75))
            .with_masking(Masking::Separable)
            .with_mode(TransportMode::Importance),
        r#"{"distribution":{"alpha":0.3},"eta":0.75,"masking":"separable","mode":"importance"}"#,
    );
    round_trip(&RoughDielectric::new(
        Gtr::new(alpha(0.2), 2.5).unwrap(),
        eta(2.4),
    ));
    round_trip(&RoughDielectric::new(
        BlinnPhongNdf::new(alpha(0.4)).unwrap(),
        eta(1.2),
    ));
}

#[test]
fn microfacet_refusals_name_the_field() {
    assert_refused::<RoughConductor<Ggx, Vec3>>(
        r#"{ "distribution": { "alpha": -1 }, "fresnel": { "ior": { "eta": [0.2, 0.4, 1.4], "k": [3.9, 2.4, 1.6] } } }"#,
        "invalid alpha = -1: expected a value in [0.0001, 10]",
    );
    assert_refused::<RoughConductor<Ggx, Vec3>>(
        r#"{ "distribution": { "alpha": 0.2 }, "fresnel": { "ior": { "eta": [0.2, 0.4, 1.4], "k": [3.9, 2.4, -1.6] } } }"#,
        "invalid k = -1.6: expected a value in [0, 1000]",
    );
    assert_all_refused::<Microfacet<Ggx, Schlick>>(&[
        (
            r#"{ "distribution": { "alpha": 0.2 }, "fresnel": { "f0": 1.5 } }"#,
            "invalid f0 = 1.5: expected a value in [0, 1]",
        ),
        (
            r#"{ "distribution": { "alpha": 0.2 }, "masking": "smith", "fresnel": { "f0": 0.5 } }"#,
            "unknown variant `smith`",
        ),
        (
            r#"{ "distribution": { "alpha": 0.2 } }"#,
            "missing field `fresnel`",
        ),
    ]);
    assert_all_refused::<RoughDielectric<Ggx>>(&[
        (
            r#"{ "distribution": { "alpha": 0.2 }, "eta": 0 }"#,
            "invalid eta = 0: expected a value in [0.001, 1000]",
        ),
        (
            r#"{ "distribution": { "alpha": 0.2 }, "eta": 1.5, "mode": "photons" }"#,
            "unknown variant `photons`, expected `radiance` or `importance`",
        ),
    ]);
    assert_refused::<RoughDielectric<Gtr>>(
        r#"{ "distribution": { "alpha": 0.2, "gamma": 20 }, "eta": 1.5 }"#,
        "invalid gamma = 20: expected a value in (0, 10]",
    );
}

#[test]
fn delta_models_are_their_index_or_fresnel_term() {
    let silver = round_trip(&Mirror::new(Conductor {
        ior: metals::SILVER.rgb(),
    }));
    assert!(
        silver.starts_with(r#"{"fresnel":{"ior":{"eta":["#) && silver.ends_with("]}}}"),
        "{silver}"
    );
    assert_wire(
        &Mirror::new(Schlick::new(Vec3::new(0.9, 0.8, 0.5)).unwrap()),
        r#"{"fresnel":{"f0":[0.9,0.8,0.5]}}"#,
    );
    assert_wire(&Mirror::new(NoFresnel::<f32>::new()), r#"{"fresnel":{}}"#);
    assert_wire(&SmoothDielectric::new(eta(1.5)), r#"{"eta":1.5}"#);
    assert_wire(
        &SmoothDielectric::new(eta(1.5)).with_mode(TransportMode::Importance),
        r#"{"eta":1.5,"mode":"importance"}"#,
    );
    assert_wire(&ThinDielectric::new(eta(1.33)), r#"{"eta":1.33}"#);

    assert_refused::<Mirror<Schlick>>(
        r#"{ "fresnel": { "f0": 2 } }"#,
        "invalid f0 = 2: expected a value in [0, 1]",
    );
    assert_refused::<SmoothDielectric>(
        r#"{ "eta": -1.5 }"#,
        "invalid eta = -1.5: expected a value in [0.001, 1000]",
    );
    assert_all_refused::<ThinDielectric>(&[
        (
            r#"{ "eta": 2000 }"#,
            "invalid eta = 2000: expected a value in [0.001, 1000]",
        ),
        (
            r#"{ "eta": 1.5, "mode": "radiance" }"#,
            "unknown field `mode`",
        ),
    ]);
}

#[test]
fn coated_models_are_base_and_coat() {
    let r = [0.7, 0.2, 0.1, 0.05];
    let json = every_carrier!(r, |s| Glazed::new(s, eta(1.5)).unwrap());
    assert_eq!(json, r#"{"reflectance":[0.7,0.2,0.1],"eta":1.5}"#);
    // The plastic's table of coat albedos (32 numbers) stays out of the file; the constructor
    // computes it again, to the same numbers.
    let json = every_carrier!(r, |s| Plastic::new(s, Ggx::isotropic(alpha(0.1)), eta(1.5))
        .unwrap());
    assert_eq!(
        json,
        r#"{"reflectance":[0.7,0.2,0.1],"distribution":{"alpha":0.1},"eta":1.5}"#
    );
    round_trip(&Plastic::new(Vec3::splat(0.5), Beckmann::isotropic(alpha(0.4)), eta(1.6)).unwrap());

    assert_refused::<Glazed<Vec3>>(
        r#"{ "reflectance": [0.7, 0.2, 1.1], "eta": 1.5 }"#,
        "invalid reflectance = 1.1: expected a value in [0, 1]",
    );
    assert_refused::<Glazed>(
        r#"{ "reflectance": 0.7, "eta": 0 }"#,
        "invalid eta = 0: expected a value in [0.001, 1000]",
    );
    assert_all_refused::<Plastic<Ggx, Vec3>>(&[
        (
            r#"{ "reflectance": [1.5, 0.2, 0.1], "distribution": { "alpha": 0.1 }, "eta": 1.5 }"#,
            "invalid reflectance = 1.5: expected a value in [0, 1]",
        ),
        (
            r#"{ "reflectance": [0.5, 0.2, 0.1], "distribution": { "alpha": 20 }, "eta": 1.5 }"#,
            "invalid alpha = 20: expected a value in [0.0001, 10]",
        ),
        (
            r#"{ "reflectance": [0.5, 0.2, 0.1], "distribution": { "alpha": 0.1 }, "eta": 1e4 }"#,
            "invalid eta = 10000: expected a value in [0.001, 1000]",
        ),
        (
            r#"{ "reflectance": [0.5, 0.2, 0.1], "eta": 1.5 }"#,
            "missing field `distribution`",
        ),
    ]);
}

#[test]
fn mono_is_the_wrapped_model() {
    let glass = RoughDielectric::new(Ggx::isotropic(alpha(0.2)), eta(1.5));
    let wrapped = Mono::<_, Vec3>::new(glass);
    assert_eq!(round_trip(&wrapped), serde_json::to_string(&glass).unwrap());
    round_trip(&Mono::<_, Vec4>::new(SmoothDielectric::new(eta(1.33))));
    assert_refused::<Mono<ThinDielectric>>(
        r#"{ "eta": 0 }"#,
        "invalid eta = 0: expected a value in [0.001, 1000]",
    );
}

#[test]
fn models_read_from_a_file_are_the_models_built_in_code() {
    let read: Plastic<Ggx, Vec3> = serde_json::from_str(
        r#"{ "reflectance": [0.8, 0.1, 0.1], "distribution": { "alpha": 0.15 }, "eta": 1.5 }"#,
    )
    .unwrap();
    let built = Plastic::new(
        Vec3::new(0.8, 0.1, 0.1),
        Ggx::isotropic(alpha(0.15)),
        eta(1.5),
    )
    .unwrap();
    assert_eq!(read, built);

    let read: RoughDielectric<Beckmann> = serde_json::from_str(
        r#"{ "distribution": { "alpha_x": 0.2, "alpha_y": 0.4 }, "eta": 1.45, "mode": "importance" }"#,
    )
    .unwrap();
    let built = RoughDielectric::new(Beckmann::new(alpha(0.2), alpha(0.4)), eta(1.45))
        .with_mode(TransportMode::Importance);
    assert_eq!(read, built);

    let read: EnergyPreservingOrenNayar<Vec3> = serde_json::from_str(
        r#"{ "reflectance": [0.9, 0.6, 0.3], "roughness": 0.8, "exact_albedo": true }"#,
    )
    .unwrap();
    let built = EnergyPreservingOrenNayar::new(Vec3::new(0.9, 0.6, 0.3), 0.8)
        .unwrap()
        .with_exact_albedo();
    assert_eq!(read, built);
}
