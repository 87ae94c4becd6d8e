//! Placeholder
#![cfg_attr(docsrs, doc(cfg(feature = "serde")))]

mod choices;
mod coated;
mod diffuse;
mod distributions;
mod fresnel;
mod glossy;
mod microfacet;
mod mono;
mod specular;

use crate::param::ParamError;
use serde::de;

/// A constructor's refusal as the deserialiser's error. [`ParamError`]'s message names the
/// parameter and its valid range: `invalid alpha = -1: expected a value in [0.0001, 10]`.
fn refused<E: de::Error>(e: ParamError) -> E {
    E::custom(e)
}

/// The refusal `e` under the name the parameter has in the file.
fn renamed(e: ParamError, field: &'static str) -> ParamError {
    ParamError::new(field, e.value(), e.range())
}

/// Whether `v` is its type's default: such a field is left out on the way out.
fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

/// `true`, the default of a switch that is on unless the file says otherwise.
fn yes() -> bool {
    true
}

/// Whether a switch that is on by default is on: such a field is left out on the way out.
#[allow(clippy::trivially_copy_pass_by_ref)] // serde's `skip_serializing_if` passes a reference
fn is_true(v: &bool) -> bool {
    *v
}
