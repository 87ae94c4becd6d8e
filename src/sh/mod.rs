//! Real spherical harmonics: basis, projection, rotation, zonal convolution, irradiance and
//! BRDF transfer, `no_std` and allocation-free.
//!
//! A function on the sphere is expanded as `f(ω) = Σ_l Σ_m f_lm Y_lm(ω)`; an expansion of
//! **order `L`** keeps the bands `l < L`, `L²` coefficients ([`Sh`]`<L², S>`, e.g. [`Sh3`]
//! for order 3, 9 coefficients, the irradiance order). Order follows Sloan 2008; a *band* is
//! one `l`.
//!
//! # Convention
//!
//! The renderer convention (Sloan 2008; Ramamoorthi & Hanrahan 2001): **real**,
//! **orthonormal** on the unit sphere (`∫ Y_i Y_j dω = δ_ij`), **no Condon–Shortley phase**
//! (band 1 is `+y, +z, +x`), directions as unit `Vec3` with `θ` measured from `+z` and `φ`
//! from `+x` toward `+y` (the crate's local frame: `z` is the normal), and the flat
//! **index `l(l + 1) + m`** ([`index`]). For `m > 0`, `Y_lm = √2 K_l^m P_l^m(cos θ) cos mφ`;
//! `Y_{l,−m} = √2 K_l^m P_l^m(cos θ) sin mφ`; `Y_l0 = K_l^0 P_l(cos θ)`, with
//! `K_l^m = √((2l+1)/4π · (l−m)!/(l+m)!)` and `P_l^m` the associated Legendre function
//! without the `(−1)^m` factor. The first nine, as used by [`basis`]:
//!
//! | index | `l, m` | `Y_lm(x, y, z)` | constant |
//! |---|---|---|---|
//! | 0 | 0, 0 | `½ √(1/π)` | 0.282095 |
//! | 1 | 1, −1 | `√(3/4π) y` | 0.488603 |
//! | 2 | 1, 0 | `√(3/4π) z` | 0.488603 |
//! | 3 | 1, 1 | `√(3/4π) x` | 0.488603 |
//! | 4 | 2, −2 | `½ √(15/π) xy` | 1.092548 |
//! | 5 | 2, −1 | `½ √(15/π) yz` | 1.092548 |
//! | 6 | 2, 0 | `¼ √(5/π) (3z² − 1)` | 0.315392 |
//! | 7 | 2, 1 | `½ √(15/π) xz` | 1.092548 |
//! | 8 | 2, 2 | `¼ √(15/π) (x² − y²)` | 0.546274 |
//!
//! These are Ramamoorthi & Hanrahan's (2001, eq. 3); Sloan 2008 tabulates the same
//! functions with the Condon–Shortley sign on odd `m` (negate `f_lm` for odd `m` to convert).
//! Band 3 is in [`basis_closed_form`]'s source; beyond, [`basis_recurrence`].
//!
//! # What is here
//!
//! | job | items | reference |
//! |---|---|---|
//! | basis | [`basis`], [`basis_closed_form`] (`l ≤ 3`, polynomials in `x, y, z`), [`basis_recurrence`] (any `l`), [`sh_basis`], [`index`] | Sloan 2008; Holmes & Featherstone 2002 |
//! | coefficients | [`Sh`]: `+`, `−`, `× f32`, [`dot`](Sh::dot), [`eval`](Sh::eval), [`band_energy`](Sh::band_energy) | — |
//! | projection | [`Sh::project`] (exact for band-limited input), [`SphereQuadrature`]; `project_monte_carlo` (feature `verify`) | Gauss–Legendre: Abramowitz & Stegun 25.4 |
//! | zonal harmonics | [`Zonal`] (clamped cosine, any profile), [`Sh::convolve`] (Funk–Hecke), [`Zonal::rotated`] | Ramamoorthi & Hanrahan 2001; Sloan 2008 |
//! | rotation | [`Sh::rotated`], [`ShRotation`] | Ivanic & Ruedenberg 1996, 1998 |
//! | irradiance | [`Sh::irradiance`] (any order), [`IrradianceQuadratic`] (9 coefficients) | Ramamoorthi & Hanrahan 2001, eqs. 12–13 |
//! | BRDF transfer | [`Transfer`]: the cosine-weighted lobe `f(wo, ·) cos θi` projected, and the share of it an order keeps | Sloan, Kautz & Snyder 2002 |
//!
//! # Example
//!
//! ```
//! use lobe::sh::{IrradianceQuadratic, Sh};
//! use lobe::Vec3;
//!
//! // A sky: brighter overhead (+z), projected onto order 3 (exact: it is band-limited).
//! let sky = |w: Vec3| Vec3::new(0.3, 0.4, 0.6) * (1.0 + 0.5 * w.z);
//! let l: Sh<9, Vec3> = Sh::project(sky, 2);
//! let e = IrradianceQuadratic::new(&l);
//! // A surface facing up receives more light than one facing down.
//! assert!(e.eval(Vec3::Z).x > e.eval(-Vec3::Z).x);
//! // Turning the sky turns the irradiance with it.
//! let r = glam::Mat3::from_rotation_x(core::f32::consts::FRAC_PI_2); // +z to −y
//! let turned = l.rotated(r);
//! assert!((turned.irradiance(-Vec3::Y) - l.irradiance(Vec3::Z)).abs().max_element() < 1e-4);
//! ```
//!
//! # References
//!
//! * Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment
//!   Maps", SIGGRAPH: the clamped cosine's coefficients and the quadratic form.
//! * Sloan 2008, "Stupid Spherical Harmonics (SH) Tricks", GDC: conventions, zonal harmonics.
//! * Green 2003, "Spherical Harmonic Lighting: The Gritty Details", GDC: projection.
//! * Ivanic & Ruedenberg 1996, "Rotation Matrices for Real Spherical Harmonics. Direct
//!   Determination by Recursion", *J. Phys. Chem.* 100(15), and the 1998 erratum, *J. Phys.
//!   Chem. A* 102(45): rotation.
//! * Sloan, Kautz & Snyder 2002, "Precomputed Radiance Transfer for Real-Time Rendering in
//!   Dynamic, Low-Frequency Lighting Environments", SIGGRAPH: transfer vectors.
//! * Holmes & Featherstone 2002, "A unified approach to the Clenshaw summation and the
//!   recursive computation of very high degree and order normalised associated Legendre
//!   functions", *J. Geodesy* 76: the normalised recurrence.

mod basis;
mod coefficients;
mod irradiance;
#[cfg(feature = "verify")]
mod monte_carlo;
mod projection;
mod rotation;
mod transfer;
mod zonal;

pub use basis::{
    CLOSED_FORM_BANDS, band_of, basis, basis_closed_form, basis_recurrence, index, legendre,
    order_of, sh_basis,
};
pub use coefficients::{Sh, Sh2, Sh3, Sh4};
pub use irradiance::{C1, C2, C3, C4, C5, IrradianceQuadratic};
#[cfg(feature = "verify")]
#[cfg_attr(docsrs, doc(cfg(feature = "verify")))]
pub use monte_carlo::{ShEstimate, project_monte_carlo, transfer_monte_carlo};
pub use projection::SphereQuadrature;
pub use rotation::{ShRotation, world_to_local};
pub use transfer::Transfer;
pub use zonal::{Zonal, clamped_cosine_eigenvalue};
