//! The combinators: [`Mix`], [`TwoSided`] and [`Layered`] (with its named instances
//! `CoatedDiffuse` and `CoatedConductor`), as the models they combine and their own
//! parameters. A layered model's adjoint top interface and its phase function are derived
//! again on the way in.

use super::{is_default, refused};
use crate::bxdf::layered::{DEFAULT_MAX_DEPTH, DEFAULT_THICKNESS};
use crate::bxdf::{Bxdf, LayerInterface, Layered, Mix, Prepare, TwoSided};
use crate::spectrum::Spectrum;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

wire! {
    /// [`Mix`] on the wire: `{ "first": …, "second": …, "weight": 0.3 }`, the weight of the
    /// second.
    impl[A: Prepare, B: Prepare<Spectrum = A::Spectrum>] Mix<A, B> as "Mix"
        MixRepr<A, B> |m| {
        first: A = m.first(),
        second: B = m.second(),
        weight: f32 = m.weight(),
    } via |r| Mix::new(r.first, r.second, r.weight)
}

wire! {
    /// [`TwoSided`] on the wire: `{ "inner": … }`, the one-sided model.
    impl[B: Prepare] TwoSided<B> as "TwoSided" TwoSidedRepr<B> |m| {
        inner: B = m.inner(),
    } via |r| Ok(TwoSided::new(r.inner))
}

/// A layered model's medium on the wire: `{ "albedo": …, "g": 0.3 }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Medium", deny_unknown_fields)]
struct MediumRepr<S> {
    albedo: S,
    #[serde(default, skip_serializing_if = "is_default")]
    g: f32,
}

/// [`Layered`] on the wire: `{ "top": …, "bottom": … }`, and, when they are not the
/// defaults, `"thickness"` (0.01), `"medium"` (none), `"max_depth"` (64) and `"samples"` (1).
/// Serialised with `T = &T`, `B = &B`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Layered", deny_unknown_fields)]
struct LayeredRepr<T, B, S> {
    top: T,
    bottom: B,
    #[serde(
        default = "default_thickness",
        skip_serializing_if = "is_default_thickness"
    )]
    thickness: f32,
    // A path rather than plain `default`, which would make the derive ask for `S: Default`.
    #[serde(default = "Option::default", skip_serializing_if = "Option::is_none")]
    medium: Option<MediumRepr<S>>,
    #[serde(
        default = "default_max_depth",
        skip_serializing_if = "is_default_max_depth"
    )]
    max_depth: u32,
    #[serde(default = "one", skip_serializing_if = "is_one")]
    samples: u32,
}

fn default_thickness() -> f32 {
    DEFAULT_THICKNESS
}

fn is_default_thickness(t: &f32) -> bool {
    *t == DEFAULT_THICKNESS
}

fn default_max_depth() -> u32 {
    DEFAULT_MAX_DEPTH
}

fn is_default_max_depth(d: &u32) -> bool {
    *d == DEFAULT_MAX_DEPTH
}

fn one() -> u32 {
    1
}

fn is_one(n: &u32) -> bool {
    *n == 1
}

impl<T, B> Serialize for Layered<T, B>
where
    T: LayerInterface + Serialize,
    B: Bxdf + Serialize,
    B::Spectrum: Serialize,
{
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        let (albedo, g) = self.medium();
        // `with_medium(0, 0)` is the model without a medium: nothing to write.
        let medium = (!albedo.is_black() || g != 0.0).then_some(MediumRepr { albedo, g });
        LayeredRepr {
            top: self.top(),
            bottom: self.bottom(),
            thickness: self.thickness(),
            medium,
            max_depth: self.max_depth(),
            samples: self.samples(),
        }
        .serialize(serializer)
    }
}

impl<'de, T, B> Deserialize<'de> for Layered<T, B>
where
    T: LayerInterface + Deserialize<'de>,
    B: Bxdf + Deserialize<'de>,
    B::Spectrum: Deserialize<'de>,
{
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = LayeredRepr::<T, B, B::Spectrum>::deserialize(deserializer)?;
        let mut m = Layered::new(r.top, r.bottom)
            .with_thickness(r.thickness)
            .and_then(|m| m.with_max_depth(r.max_depth))
            .and_then(|m| m.with_samples(r.samples))
            .map_err(refused)?;
        if let Some(medium) = r.medium {
            m = m.with_medium(medium.albedo, medium.g).map_err(refused)?;
        }
        Ok(m)
    }
}
