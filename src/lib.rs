//! # lobe
//!
//! Physically based reflectance math: typed BRDF/BSDF models, their microfacet parts,
//! Fresnel terms and importance sampling, with a verification harness that measures
//! whether a model obeys the physical laws it claims.
//!
//! ## Conventions
//!
//! * Every model works in a **local shading frame**: `z` is the shading normal, so
//!   `cos θ = w.z`. [`Frame`] converts between world and local space.
//! * `wo` points toward the viewer, `wi` toward the light; both point *away* from the
//!   surface and are unit [`Vec3`]s.
//! * Roughness is typed: [`Alpha`] is the microfacet width, [`Roughness`] the perceptual
//!   roughness with `α = r²`. An index of refraction is typed too: [`Eta`] is always
//!   *relative* (`η_inside / η_outside`, the normal points outside), [`Ior`] absolute,
//!   [`ComplexIor`] a conductor's `η + iκ`.
//! * Hot-loop functions do not validate their arguments, but are total: finite unit
//!   inputs give finite, non-negative results. Constructors validate and return
//!   [`ParamError`].
//!
//! ## A first look
//!
//! ```
//! use lobe::{fresnel, metals, Eta, Frame, Vec3};
//!
//! // Glass seen from air, 60° from the normal.
//! let eta = Eta::new(1.5)?;
//! let f = fresnel::dielectric(0.5, eta);
//! assert!(f > 0.04 && f < 0.1);
//!
//! // Gold at normal incidence, from its measured complex index.
//! let gold = metals::GOLD.rgb();
//! let f0: Vec3 = fresnel::conductor(1.0, &gold);
//! assert!(f0.x > f0.y && f0.y > f0.z); // yellow: red, then green, then blue
//!
//! // A shading frame around a world-space normal.
//! let frame = Frame::from_normal(Vec3::new(0.0, 1.0, 0.0));
//! let local = frame.to_local(Vec3::new(0.0, 1.0, 0.0));
//! assert!((local.z - 1.0).abs() < 1e-6);
//! # Ok::<(), lobe::ParamError>(())
//! ```
//!
//! ## Sources and errata
//!
//! The models began as the formulas of two ray-tracing lecture handouts, corrected where
//! those slip. [`handouts`] says what the two cover and which item implements each of their
//! formulas; [`errata`] gives every slip with its correct form, its reference and the test
//! that pins it, and those the crate's own measurements found. Doc comments cite them as
//! "seed 000", "seed 003", "the handout" and "ERRATA #n", linked to these pages.
//!
//! ## Spherical harmonics
//!
//! [`sh`] holds a real spherical-harmonic toolkit for lighting: the basis (closed forms for
//! bands `l ≤ 3`, a recurrence beyond), fixed-size coefficient vectors, exact projection,
//! rotation, zonal convolution, Ramamoorthi & Hanrahan's irradiance and the transfer vector
//! of any [`bxdf::Bxdf`] — `no_std`, without allocation.
//!
//! ## Features
//!
//! | feature | default | gives |
//! | --- | --- | --- |
//! | `std` | yes | the standard library's float functions, `std::error::Error` for [`ParamError`], and [`batch`]'s run-time AVX2/AVX-512 dispatch on x86 (without it: the baseline loop) |
//! | `libm` | no | the `no_std` math path (`--no-default-features --features libm`) |
//! | `verify` | no | [`verify`]: the law checks, Monte Carlo estimators with standard errors, the chi-square test, and the seeded [`Pcg32`](verify::Pcg32), which implements `rand_core`'s `RngCore` and `SeedableRng` (implies `std`) |
//! | `proptest` | no | `verify::strategies`: proptest strategies for directions, α, η and complex indices (implies `verify`) |
//! | `serde` | no | `Serialize`/`Deserialize` for the parameters ([`Alpha`], [`Roughness`], [`Eta`], [`Ior`], [`ComplexIor`], see [`param`]), [`metals::Metal`] (by name) and every model, distribution and Fresnel term (as their constructors' parameters, see `serde_impls`), validated on the way in: `alpha = -1` is refused with the parameter's name and range; turns on glam's `serde` |
//! | `approx` | no | `approx` 0.5's `AbsDiffEq`/`RelativeEq` for [`bxdf::BxdfSample`] and `verify::Estimate`; turns on glam's `approx-05` |
//! | `mint` | no | glam's `mint-05`: conversions between [`Vec3`] & co. and `mint` 0.5's types |
//! | `bytemuck` | no | glam's `bytemuck`: `Pod`/`Zeroable` for [`Vec3`] & co. |
//!
//! Every feature but `std`, `verify` and `proptest` builds without std: the `no_std` path is
//! `--no-default-features --features libm` plus any of `serde`, `approx`, `mint`, `bytemuck`.
//!
//! ## glam is public API
//!
//! Directions and spectra are [`glam`](https://docs.rs/glam/0.34) 0.34 types, re-exported as
//! [`lobe::Vec2`](Vec2), [`lobe::Vec3`](Vec3) and [`lobe::Vec4`](Vec4). A renderer on glam
//! 0.34.x shares them as they are: Cargo unifies semver-compatible versions into one crate.
//! A renderer on another glam minor (0.33, or a later 0.x or 1.x) gets two distinct glam
//! crates in its build, whose `Vec3`s are different types; it converts at the boundary, by
//! value, which costs nothing measurable:
//!
//! * `lobe::Vec3::from_array(v.to_array())` (or `from`/`into` with `[f32; 3]`) works across
//!   any two glam versions;
//! * with `lobe`'s `mint` feature and its own glam's mint feature, `mint::Vector3<f32>` is a
//!   common currency: `lobe::Vec3::from(mint::Vector3::from(v))`.
//!
//! Moving `lobe` to another glam minor is a breaking change of `lobe`'s API and gets a new
//! `lobe` minor version (0.x) or major version (1.x and later).
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(missing_debug_implementations)]
#![cfg_attr(docsrs, feature(doc_cfg))]
// The docs link to the law checks of `verify` (a model's docs name the check that proves its
// law); without the feature those links have no target. The documentation built with every
// feature (docs.rs, and CI with warnings denied) checks them all.
#![cfg_attr(not(feature = "verify"), allow(rustdoc::broken_intra_doc_links))]

#[cfg(feature = "std")]
extern crate std;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("lobe needs a float library: enable the `std` (default) or the `libm` feature");

#[cfg(all(lobe_force_libm, not(feature = "libm")))]
compile_error!(
    "`--cfg lobe_force_libm` takes the float functions from libm: enable the `libm` feature"
);

#[macro_use]
mod macros;

pub mod batch;
pub mod bxdf;
pub mod frame;
pub mod fresnel;
pub mod math;
pub mod metals;
pub mod microfacet;

pub mod param;
pub mod sampling;
#[cfg(feature = "serde")]
pub mod serde_impls;
pub mod sh;
pub mod spectrum;
pub mod tables;
#[cfg(feature = "verify")]
pub mod verify;

#[doc = include_str!("handouts.md")]
pub mod handouts {}
#[doc = include_str!("errata.md")]
pub mod errata {}

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

pub use frame::Frame;
pub use glam::{Vec2, Vec3, Vec4};
pub use param::{Alpha, ComplexIor, Eta, Ior, ParamError, Roughness};
pub use spectrum::Spectrum;
