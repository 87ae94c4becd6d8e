//! Serde round trips and refusals, shared by `tests/serde_parts.rs`,
//! `tests/serde_models.rs` and `tests/serde_composed.rs`.

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
#[track_caller]
pub fn assert_refused<T: DeserializeOwned + Debug>(json: &str, message: &str) {
    match serde_json::from_str::<T>(json) {
        Ok(v) => panic!("{json} was accepted as {v:?}"),
        Err(e) => assert!(e.to_string().starts_with(message), "{json}: {e}"),
    }
}

/// [`assert_refused`] for each `(json, message)` of `cases`.
#[track_caller]
pub fn assert_all_refused<T: DeserializeOwned + Debug>(cases: &[(&str, &str)]) {
    for &(json, message) in cases {
        assert_refused::<T>(json, message);
    }
}
