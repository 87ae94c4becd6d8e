//! Scene files: `Serialize` and `Deserialize` for every model, its distribution of normals
//! and its Fresnel term (feature `serde`).
//!
//! The module has no items of its own: it implements serde's traits for the crate's types and
//! says here what they look like in a file. The parameter types ([`Alpha`](crate::Alpha),
//! [`Roughness`](crate::Roughness), [`Eta`](crate::Eta), [`Ior`](crate::Ior),
//! [`ComplexIor`](crate::ComplexIor)) and the named metals ([`Metal`](crate::metals::Metal))
//! are serialisable too, see [`param`](crate::param) and [`metals`](crate::metals).
//!
//! ## The rules
//!
//! * **Out: the constructor's parameters.** A model is written as the arguments of its
//!   constructor and of its `with_*` builders, under the names the constructor and the getters
//!   give them; never what the constructor derives from them (GGX's `1/α`, Oren-Nayar's `A`
//!   and `B`, GTR's Smith table, a plastic's table of coat albedos).
//! * **In: through the constructor.** Reading a model calls its validating constructor, so a
//!   file cannot hold a model the constructor would refuse, and every model read keeps the
//!   crate's promise of finite, non-negative values. A refusal is the constructor's
//!   [`ParamError`], whose message names the field and its range:
//!   `invalid alpha = -1: expected a value in [0.0001, 10]`,
//!   `invalid reflectance = 1.5: expected a value in [0, 1]`. A number beyond `f32` (`1e39`)
//!   reads as infinity and is refused the same way. Unknown fields are refused too: a
//!   misspelt field is an error, never a silent default.
//! * **Defaults may be left out**, and are left out on the way out: `masking` (height-correlated
//!   Smith), `mode` (radiance), GGX's `bounded_reflection` (on), Beckmann's `masking` (exact),
//!   `exact_smith` and `exact_albedo` (off), Blinn-Phong's `form` (normalised), the
//!   `compensation` (Kulla & Conty's), a layered model's `thickness` (0.01), `medium` (none),
//!   `max_depth` (64) and `samples` (1).
//! * **Spectra** are one number for `f32`, an array of three for RGB [`Vec3`](crate::Vec3),
//!   of four for [`Vec4`](crate::Vec4) (glam's own representation). **Choices** are `snake_case`
//!   names.
//! * **No type tags.** A model's Rust type says which distribution and Fresnel term it holds,
//!   so the file does not repeat it. A scene whose materials are of different types tells them
//!   apart with an enum of its own, tagged as it likes (the example below).
//! * **Self-describing formats** such as JSON, RON, TOML or YAML (the crate's tests use JSON):
//!   a field left out must be recognisable as missing, which formats that read fields by
//!   position (bincode, postcard) cannot do.
//!
//! | type | in a JSON file |
//! | --- | --- |
//! | [`Ggx`](crate::microfacet::Ggx) | `{"alpha": 0.3}`, or `{"alpha_x": 0.3, "alpha_y": 0.1}`; `"bounded_reflection": false` |
//! | [`Beckmann`](crate::microfacet::Beckmann) | `{"alpha": 0.3}`, or `{"alpha_x": …, "alpha_y": …}`; `"masking": "walter_rational"` |
//! | [`Gtr`](crate::microfacet::Gtr) | `{"alpha": 0.1, "gamma": 1.0}` |
//! | [`BlinnPhongNdf`](crate::microfacet::BlinnPhongNdf) | `{"alpha": 0.3}` or `{"exponent": 20.0}` (the two constructors); `"exact_smith": true` |
//! | [`Masking`](crate::microfacet::Masking) | `"height_correlated"`, `"separable"`, `"v_cavity"` |
//! | [`BeckmannMasking`](crate::microfacet::BeckmannMasking) | `"exact"`, `"walter_rational"` |
//! | [`TransportMode`](crate::bxdf::TransportMode) | `"radiance"`, `"importance"` |
//! | [`BlinnPhongForm`](crate::bxdf::BlinnPhongForm) | `"normalized"`, `"modified"` |
//! | [`Schlick`](crate::fresnel::Schlick) | `{"f0": 0.04}` |
//! | [`Conductor`](crate::fresnel::Conductor) | `{"ior": {"eta": [0.16, 0.42, 1.38], "k": [3.64, 2.41, 1.89]}}` |
//! | [`Dielectric`](crate::fresnel::Dielectric) | `{"eta": 1.5}` |
//! | [`NoFresnel`](crate::fresnel::NoFresnel) | `{}` |
//! | [`Lambert`](crate::bxdf::Lambert) | `{"reflectance": [0.8, 0.8, 0.8]}` |
//! | [`OrenNayar`](crate::bxdf::OrenNayar) | `{"reflectance": [0.8, 0.8, 0.8], "sigma": 0.35}` (radians) |
//! | [`EnergyPreservingOrenNayar`](crate::bxdf::EnergyPreservingOrenNayar) | `{"reflectance": [0.8, 0.8, 0.8], "roughness": 0.5}`; `"exact_albedo": true` |
//! | [`DisneyDiffuse`](crate::bxdf::DisneyDiffuse) | `{"reflectance": [0.8, 0.8, 0.8], "roughness": 0.5}` |
//! | [`Phong`](crate::bxdf::Phong) | `{"kd": [0.5, 0.4, 0.3], "ks": [0.2, 0.2, 0.2], "exponent": 50.0}` |
//! | [`BlinnPhong`](crate::bxdf::BlinnPhong) | `{"kd": …, "ks": …, "exponent": 80.0}`; `"form": "modified"` |
//! | [`Microfacet`](crate::bxdf::Microfacet) | `{"distribution": {"alpha": 0.2}, "fresnel": {"f0": 0.04}}`; `"masking": "separable"` |
//! | [`RoughDielectric`](crate::bxdf::RoughDielectric) | `{"distribution": {"alpha": 0.1}, "eta": 1.5}`; `"masking"`, `"mode": "importance"` |
//! | [`Mirror`](crate::bxdf::Mirror) | `{"fresnel": {"ior": {"eta": …, "k": …}}}` |
//! | [`SmoothDielectric`](crate::bxdf::SmoothDielectric) | `{"eta": 1.5}`; `"mode": "importance"` |
//! | [`ThinDielectric`](crate::bxdf::ThinDielectric) | `{"eta": 1.5}` |
//! | [`Glazed`](crate::bxdf::Glazed) | `{"reflectance": [0.7, 0.1, 0.1], "eta": 1.5}` |
//! | [`Plastic`](crate::bxdf::Plastic) | `{"reflectance": [0.7, 0.1, 0.1], "distribution": {"alpha": 0.1}, "eta": 1.5}` |
//! | [`CompensatedPlastic`](crate::bxdf::CompensatedPlastic) | as [`Plastic`](crate::bxdf::Plastic) (the type says the coat is compensated) |
//! | [`CompensatedMicrofacet`](crate::bxdf::CompensatedMicrofacet) | `{"distribution": {"alpha": 0.5}, "fresnel": {"f0": 1.0}}`; `"compensation": "turquin"` |
//! | [`CompensatedDielectric`](crate::bxdf::CompensatedDielectric) | `{"distribution": {"alpha": 0.3}, "eta": 1.5}`; `"mode": "importance"` |
//! | [`Compensation`](crate::bxdf::Compensation) | `"kulla_conty"`, `"turquin"` |
//! | [`DiffuseTransmission`](crate::bxdf::DiffuseTransmission) | `{"reflectance": [0.3, 0.5, 0.1], "transmittance": [0.2, 0.4, 0.1]}` |
//! | [`Sheen`](crate::bxdf::Sheen) | `{"color": [0.9, 0.2, 0.3], "roughness": 0.5}`; `"exact_smith": true` for the exact masking |
//! | [`Mix`](crate::bxdf::Mix) | `{"first": …, "second": …, "weight": 0.3}` (the weight of `second`) |
//! | [`TwoSided`](crate::bxdf::TwoSided) | `{"inner": …}` |
//! | [`Layered`](crate::bxdf::Layered), `CoatedDiffuse`, `CoatedConductor` | `{"top": …, "bottom": …}`; `"thickness": 0.1`, `"medium": {"albedo": [0.5, 0.5, 0.5], "g": 0.3}`, `"max_depth": 32`, `"samples": 4` |
//! | [`Mono`](crate::bxdf::Mono) | the wrapped model's, unchanged |
//!
//! (After the `;`: an optional field, shown with a value other than its default.)
//!
//! [`BlinnPhongNdf`](crate::microfacet::BlinnPhongNdf)'s two constructors round differently,
//! so it is written as whichever of `alpha` and `exponent` builds the very same value again
//! (the shorter number when both do). Every value comes back equal (`==`) to the one written.
//! A compensated model built with an albedo table of its own (`with_albedo`) is the one value
//! that cannot be written: serialising it is an error, since a file names the crate's tables
//! only.
//!
//! ## A material list
//!
//! A renderer's materials are of different types; an enum of its own, tagged by `"type"`,
//! holds them. Gold is picked by name from the crate's measured [`metals`](crate::metals):
//!
//! ```
//! use lobe::bxdf::{Bxdf, Lambert, Microfacet, Mono, Plastic, RoughDielectric};
//! use lobe::fresnel::Conductor;
//! use lobe::metals::{self, Metal};
//! use lobe::microfacet::{Ggx, Masking};
//! use lobe::Vec3;
//! use serde::{Deserialize, Serialize};
//!
//! /// The materials of a scene file, told apart by their `"type"`.
//! #[derive(Debug, Serialize, Deserialize)]
//! #[serde(tag = "type", rename_all = "snake_case")]
//! enum Material {
//!     Lambert(Lambert<Vec3>),
//!     /// A rough metal, by name: its RGB complex index comes from `lobe::metals`.
//!     Metal { metal: Metal, distribution: Ggx },
//!     /// Rough glass, its one value repeated in the three channels.
//!     Glass(Mono<RoughDielectric<Ggx>>),
//!     Plastic(Plastic<Ggx, Vec3>),
//! }
//!
//! impl Material {
//!     /// The model the renderer shades with.
//!     fn bxdf(&self) -> Box<dyn Bxdf<Spectrum = Vec3>> {
//!         match *self {
//!             Material::Lambert(m) => Box::new(m),
//!             Material::Metal { metal, distribution } => Box::new(Microfacet::new(
//!                 distribution,
//!                 Masking::HeightCorrelated,
//!                 Conductor { ior: metal.rgb() },
//!             )),
//!             Material::Glass(m) => Box::new(m),
//!             Material::Plastic(m) => Box::new(m),
//!         }
//!     }
//! }
//!
//! let scene = r#"[
//!     { "type": "lambert", "reflectance": [0.8, 0.8, 0.8] },
//!     { "type": "metal", "metal": "gold", "distribution": { "alpha": 0.2 } },
//!     { "type": "glass", "distribution": { "alpha": 0.05 }, "eta": 1.5 },
//!     { "type": "plastic", "reflectance": [0.7, 0.1, 0.1],
//!       "distribution": { "alpha": 0.1 }, "eta": 1.5 }
//! ]"#;
//! let materials: Vec<Material> = serde_json::from_str(scene)?;
//! assert_eq!(materials.len(), 4);
//! assert!(matches!(materials[1], Material::Metal { metal, .. } if metal == metals::GOLD));
//!
//! // Each is a model like any other: the gold is yellow, the plastic red.
//! let (wo, wi) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.0, -0.6, 0.8));
//! let f: Vec<Vec3> = materials.iter().map(|m| m.bxdf().eval(wo, wi)).collect();
//! assert!(f[1].x > f[1].y && f[1].y > f[1].z);
//! assert!(f[3].x > f[3].y);
//! assert!(f.iter().all(|f| f.is_finite() && f.min_element() >= 0.0));
//!
//! // Written back, a material is its type and its constructor's parameters.
//! assert_eq!(
//!     serde_json::to_string(&materials[2])?,
//!     r#"{"type":"glass","distribution":{"alpha":0.05},"eta":1.5}"#
//! );
//!
//! // A value out of a model's range refuses the whole file, naming the field and the range.
//! let bad = scene.replace(r#""alpha": 0.05"#, r#""alpha": -1"#);
//! let err = serde_json::from_str::<Vec<Material>>(&bad).unwrap_err().to_string();
//! assert!(err.starts_with("invalid alpha = -1: expected a value in [0.0001, 10]"), "{err}");
//! let bad = scene.replace("[0.7, 0.1, 0.1]", "[1.5, 0.1, 0.1]");
//! let err = serde_json::from_str::<Vec<Material>>(&bad).unwrap_err().to_string();
//! assert!(err.starts_with("invalid reflectance = 1.5: expected a value in [0, 1]"), "{err}");
//! let bad = scene.replace(r#""gold""#, r#""mithril""#);
//! assert!(serde_json::from_str::<Vec<Material>>(&bad).is_err());
//! # Ok::<(), serde_json::Error>(())
//! ```
#![cfg_attr(docsrs, doc(cfg(feature = "serde")))]

/// Implements `Serialize` and `Deserialize` for a model through its wire struct, which it
/// also defines: the constructor's parameters as the struct's fields (with their serde
/// attributes), each read from the model `m` by a getter, and the constructor that builds the
/// model again from the struct `r`, its refusal (a [`ParamError`]) the deserialiser's error.
///
/// The wire struct's type parameters are the model's: each must be `Serialize` for the one
/// impl and `Deserialize` for the other, and nothing more. A getter may return a reference
/// (`m.distribution()`): the struct is then written with `&D` in place of `D`, so writing a
/// model clones nothing.
///
/// ```text
/// wire! {
///     /// [`Lambert`] on the wire: `{ "reflectance": [0.8, 0.8, 0.8] }`.
///     impl[S: Spectrum] Lambert<S> as "Lambert" LambertRepr<S> |m| {
///         reflectance: S = m.albedo(),
///     } via |r| Lambert::new(r.reflectance)
/// }
/// ```
macro_rules! wire {
    (
        $(#[$attr:meta])*
        impl[$($gen:tt)*] $ty:ty as $name:literal $repr:ident $(<$($p:ident),*>)? |$m:ident| {
            $($(#[$fattr:meta])* $field:ident: $fty:ty = $get:expr),* $(,)?
        } via |$r:ident| $make:expr
    ) => {
        $(#[$attr])*
        #[derive(serde::Serialize, serde::Deserialize)]
        #[serde(rename = $name, deny_unknown_fields)]
        struct $repr$(<$($p),*>)? {
            $($(#[$fattr])* $field: $fty,)*
        }

        impl<$($gen)*> serde::Serialize for $ty
        where
            $($($p: serde::Serialize,)*)?
        {
            fn serialize<Ser: serde::Serializer>(
                &self,
                serializer: Ser,
            ) -> Result<Ser::Ok, Ser::Error> {
                let $m = self;
                let repr = $repr { $($field: $get),* };
                serde::Serialize::serialize(&repr, serializer)
            }
        }

        impl<'de, $($gen)*> serde::Deserialize<'de> for $ty
        where
            $($($p: serde::Deserialize<'de>,)*)?
        {
            fn deserialize<De: serde::Deserializer<'de>>(
                deserializer: De,
            ) -> Result<Self, De::Error> {
                let $r = <$repr$(<$($p),*>)? as serde::Deserialize>::deserialize(deserializer)?;
                let made: Result<Self, $crate::param::ParamError> = $make;
                made.map_err($crate::serde_impls::refused)
            }
        }
    };
}

mod coated;
mod compensated;
mod composition;
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
fn is_true(v: &bool) -> bool {
    *v
}
