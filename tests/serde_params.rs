//! Serde for the parameter types (feature `serde`): what goes out comes back, and what comes
//! in is validated exactly as the constructors validate.

mod common;

use common::wire::{assert_all_refused, assert_refused};
use lobe::metals::{self, Metal};
use lobe::{Alpha, ComplexIor, Eta, Ior, Roughness, Vec3, Vec4};
use serde::Deserialize;

#[test]
fn scalars_are_plain_numbers_both_ways() {
    assert_eq!(
        serde_json::to_string(&Alpha::new(0.25).unwrap()).unwrap(),
        "0.25"
    );
    assert_eq!(
        serde_json::to_string(&Roughness::new(0.5).unwrap()).unwrap(),
        "0.5"
    );
    assert_eq!(
        serde_json::to_string(&Eta::new(1.5).unwrap()).unwrap(),
        "1.5"
    );
    assert_eq!(serde_json::to_string(&Ior::VACUUM).unwrap(), "1.0");
    assert_eq!(serde_json::from_str::<Alpha>("0.25").unwrap().get(), 0.25);
    assert_eq!(serde_json::from_str::<Roughness>("1").unwrap().get(), 1.0);
    assert_eq!(serde_json::from_str::<Eta>("1.33").unwrap().get(), 1.33);
    assert_eq!(serde_json::from_str::<Ior>("2.4").unwrap().get(), 2.4);
    // The range ends are accepted, as by the constructors.
    assert_eq!(
        serde_json::from_str::<Alpha>("0.0001").unwrap(),
        Alpha::new(1e-4).unwrap()
    );
    assert_eq!(
        serde_json::from_str::<Alpha>("10").unwrap(),
        Alpha::new(10.0).unwrap()
    );
}

#[test]
fn out_of_range_scalars_name_the_parameter_and_the_range() {
    assert_refused::<Alpha>("-1", "invalid alpha = -1: expected a value in [0.0001, 10]");
    assert_refused::<Alpha>("0", "invalid alpha = 0: expected a value in [0.0001, 10]");
    assert_refused::<Roughness>("1.5", "invalid roughness = 1.5: expected a value in [0, 1]");
    assert_refused::<Eta>("0", "invalid eta = 0: expected a value in [0.001, 1000]");
    assert_refused::<Ior>(
        "1e9",
        "invalid ior = 1000000000: expected a value in [0.001, 1000]",
    );
    // Not a number at all: serde's own error.
    assert!(serde_json::from_str::<Alpha>("\"rough\"").is_err());
    assert!(serde_json::from_str::<Alpha>("null").is_err());
}

#[test]
fn complex_indices_round_trip_on_every_carrier() {
    let mono = ComplexIor::new(0.2_f32, 3.9).unwrap();
    let json = serde_json::to_string(&mono).unwrap();
    assert_eq!(json, r#"{"eta":0.2,"k":3.9}"#);
    assert_eq!(serde_json::from_str::<ComplexIor>(&json).unwrap(), mono);

    let rgb = metals::GOLD.rgb();
    let json = serde_json::to_string(&rgb).unwrap();
    assert_eq!(
        serde_json::from_str::<ComplexIor<Vec3>>(&json).unwrap(),
        rgb
    );
    let parsed: ComplexIor<Vec3> =
        serde_json::from_str(r#"{ "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.1] }"#).unwrap();
    assert_eq!(parsed.eta(), Vec3::new(0.2, 0.9, 1.1));
    assert_eq!(parsed.k(), Vec3::new(3.9, 2.4, 2.1));

    let four = metals::SILVER.spectral(Vec4::new(400.0, 500.0, 600.0, 700.0));
    let json = serde_json::to_string(&four).unwrap();
    assert_eq!(
        serde_json::from_str::<ComplexIor<Vec4>>(&json).unwrap(),
        four
    );
}

#[test]
fn complex_indices_are_validated_on_the_way_in() {
    assert_all_refused::<ComplexIor<Vec3>>(&[
        (
            r#"{ "eta": [0.2, 0.0, 1.1], "k": [3.9, 2.4, 2.1] }"#,
            "invalid eta = 0: expected a value in [1.1754944e-38, 1000]",
        ),
        (
            r#"{ "eta": [0.2, 0.9, 1.1], "k": [3.9, -2.4, 2.1] }"#,
            "invalid k = -2.4: expected a value in [0, 1000]",
        ),
        // Structural mistakes: a missing part; an unknown field and the wrong number of
        // channels below.
        (r#"{ "eta": [0.2, 0.9, 1.1] }"#, "missing field `k`"),
    ]);
    assert_all_refused::<ComplexIor>(&[
        (
            r#"{ "eta": 1.0, "k": 1e4 }"#,
            "invalid k = 10000: expected a value in [0, 1000]",
        ),
        // An unknown field.
        (
            r#"{ "eta": 0.2, "k": 3.0, "kappa": 3.0 }"#,
            "unknown field `kappa`",
        ),
    ]);
    // The wrong number of channels.
    assert!(serde_json::from_str::<ComplexIor<Vec3>>(r#"{ "eta": 0.2, "k": 3.0 }"#).is_err());
    assert!(
        serde_json::from_str::<ComplexIor<Vec3>>(r#"{ "eta": [0.2, 0.9], "k": [3, 2] }"#).is_err()
    );
}

/// A renderer's material description, as a scene file would hold it.
#[derive(Debug, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
enum Material {
    Metal { metal: Metal, roughness: Roughness },
    CustomMetal { ior: ComplexIor<Vec3>, alpha: Alpha },
    Glass { eta: Eta, alpha: Option<Alpha> },
}

#[test]
fn a_scene_file_names_its_metals_and_is_checked_whole() {
    let scene = r#"[
        { "type": "metal", "metal": "gold", "roughness": 0.4 },
        { "type": "metal", "metal": "Cu", "roughness": 0.1 },
        { "type": "custom_metal", "ior": { "eta": [1.66, 0.88, 0.52], "k": [9.2, 6.3, 4.8] },
          "alpha": 0.05 },
        { "type": "glass", "eta": 1.5, "alpha": null }
    ]"#;
    let materials: Vec<Material> = serde_json::from_str(scene).unwrap();
    assert_eq!(materials.len(), 4);
    match &materials[0] {
        Material::Metal { metal, roughness } => {
            assert_eq!(*metal, metals::GOLD);
            assert_eq!(roughness.get(), 0.4);
            assert_eq!(roughness.alpha().get(), 0.4_f32 * 0.4); // α = r², in f32
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(&materials[1], Material::Metal { metal, .. } if *metal == metals::COPPER));
    match &materials[2] {
        Material::CustomMetal { ior, alpha } => {
            assert_eq!(ior.eta(), Vec3::new(1.66, 0.88, 0.52));
            assert_eq!(ior.k(), Vec3::new(9.2, 6.3, 4.8));
            assert_eq!(alpha.get(), 0.05);
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(&materials[3], Material::Glass { eta, alpha: None } if eta.get() == 1.5));

    // One bad value anywhere refuses the whole file, saying what and where.
    let bad = scene.replace(r#""alpha": 0.05"#, r#""alpha": -1"#);
    assert_refused::<Vec<Material>>(&bad, "invalid alpha = -1: expected a value in [0.0001, 10]");
    let bad = scene.replace(r#""gold""#, r#""mithril""#);
    assert_refused::<Vec<Material>>(&bad, "unknown variant `mithril`, expected one of `gold`");
}

#[test]
fn metals_serialise_by_name() {
    for m in metals::ALL {
        let json = serde_json::to_string(&m).unwrap();
        assert_eq!(json, format!("\"{}\"", m.name()));
        assert_eq!(serde_json::from_str::<Metal>(&json).unwrap(), m);
        let by_symbol = format!("\"{}\"", m.symbol());
        assert_eq!(serde_json::from_str::<Metal>(&by_symbol).unwrap(), m);
    }
    assert!(serde_json::from_str::<Metal>("42").is_err());
}
