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
//! use lobe::{fresnel, Eta, Frame};
//! use glam::Vec3;
//!
//! // Glass seen from air, 60° from the normal.
//! let eta = Eta::new(1.5)?;
//! let f = fresnel::dielectric(0.5, eta);
//! assert!(f > 0.04 && f < 0.1);
//!
//! // A shading frame around a world-space normal.
//! let frame = Frame::from_normal(Vec3::new(0.0, 1.0, 0.0));
//! let local = frame.to_local(Vec3::new(0.0, 1.0, 0.0));
//! assert!((local.z - 1.0).abs() < 1e-6);
//! # Ok::<(), lobe::ParamError>(())
//! ```
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
//! * `std` (default): the standard library's float functions and `std::error::Error`.
//! * `libm`: the `no_std` math path (`--no-default-features --features libm`).
//! * `verify`: [`verify`], the Monte Carlo estimators and statistical tests.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "std")]
extern crate std;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("lobe needs a float library: enable the `std` (default) or the `libm` feature");

pub mod bxdf;
pub mod frame;
pub mod fresnel;
pub mod math;
pub mod microfacet;

pub mod param;
pub mod sampling;
pub mod sh;
pub mod spectrum;
#[cfg(feature = "verify")]
pub mod verify;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

pub use frame::Frame;
pub use glam::{Vec2, Vec3, Vec4};
pub use param::{Alpha, ComplexIor, Eta, Ior, ParamError, Roughness};
pub use spectrum::Spectrum;
