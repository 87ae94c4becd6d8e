//! Serde round trips and refusals, shared by `tests/serde_parts.rs`,
//! `tests/serde_models.rs` and `tests/serde_composed.rs`.

use lobe::bxdf::Bxdf;
use lobe::{Spectrum, Vec2, Vec3};
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::fmt::Debug;

/// Serialises `value`, reads it back, asserts that the two are equal and returns the JSON.
pub fn round_trip<T: Serialize + DeserializeOwned + PartialEq + Debug>(value: &T) -> String {
    let json = serde_json::to_string(value).unwrap();
    let back: T = serde_json::from_str(&json).unwrap_or_else(|e| panic!("{json}: {e}"));
    assert_eq!(&back, value, "{json}");
    json
}

/// Asserts that `value` serialises to exactly `json` and comes back equal.
pub fn assert_wire<T: Serialize + DeserializeOwned + PartialEq + Debug>(value: &T, json: &str) {
    assert_eq!(round_trip(value), json);
}

/// Asserts that `json` is refused with a message that starts with `message`.
pub fn assert_refused<T: DeserializeOwned + Debug>(json: &str, message: &str) {
    match serde_json::from_str::<T>(json) {
        Ok(v) => panic!("{json} was accepted as {v:?}"),
        Err(e) => assert!(e.to_string().starts_with(message), "{json}: {e}"),
    }
}

/// A model read from a file behaves as the one built in code: the same `eval`, `pdf` and
/// `sample`, bit for bit (the layered models' estimates are seeded by their inputs, so they too).
pub fn assert_same_values<B: Bxdf + Debug>(read: &B, built: &B)
where
    B::Spectrum: Spectrum,
{
    let wo = Vec3::new(0.3, -0.2, 0.9).normalize();
    for wi in [
        Vec3::new(-0.4, 0.1, 0.8).normalize(),
        Vec3::new(0.1, 0.5, -0.7).normalize(),
        Vec3::Z,
    ] {
        assert_eq!(read.eval(wo, wi), built.eval(wo, wi), "{built:?}");
        assert_eq!(read.pdf(wo, wi), built.pdf(wo, wi), "{built:?}");
    }
    let s = read.sample(wo, Vec2::new(0.3, 0.6), 0.4);
    assert_eq!(s, built.sample(wo, Vec2::new(0.3, 0.6), 0.4), "{built:?}");
    assert!(s.is_some(), "{built:?}");
}
