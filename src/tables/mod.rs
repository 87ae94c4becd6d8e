//! Albedo tables of the microfacet models, baked by the crate itself, for energy
//! compensation.
//!
//! A single-scattering microfacet model loses the light that bounces more than once between
//! microfacets. Kulla & Conty (2017) put it back with a lobe built from the model's
//! directional albedo `E(μ) = ∫ f(wo, wi) |cos θi| dωi` (`μ = cos θo`) and its average
//! `E_avg = 2 ∫₀¹ E(μ) μ dμ`; these are the tables of `E`:
//!
//! | table | what | grid |
//! | --- | --- | --- |
//! | [`GGX_E`], [`BECKMANN_E`] | `E(μ, α)` of `Microfacet<D, NoFresnel>` (`F = 1`), height-correlated masking | 65 (`μ`) × 65 (`α`) |
//! | [`GGX_E_AVG`], [`BECKMANN_E_AVG`] | `E_avg(α)` | 65 |
//! | [`GGX_DIELECTRIC_OUTSIDE`] | `E(μ, α, η)` of `RoughDielectric<Ggx>` in importance mode (reflection + transmission), `wo` outside | 33 × 33 × 16 (`η`) |
//! | [`GGX_DIELECTRIC_INSIDE`] | the same with `wo` inside | 33 × 33 × 16 |
//! | [`GGX_DIELECTRIC_REFLECTION`] | the reflected part of the outside albedo: a plastic's coat | 33 × 33 × 16 |
//!
//! The dielectric tables are GGX's only ([`TabulatedDielectric`]): Beckmann's visible-normal
//! sampler (Newton iterations on `erfc`) makes its 3-D bake take hours on a shared 2-core
//! machine. [`bake::dielectric_entry`] computes Beckmann's entries all the same, for a
//! renderer that wants them ([`CompensatedDielectric::with_albedo`](crate::bxdf::CompensatedDielectric::with_albedo)).
//!
//! **Coordinates.** Entries are indexed `[α][μ]` and `[η][α][μ]`. The nodes are uniform in
//! `x = √μ` (`μᵢ = (i/(n − 1))²`), in `r = √α` (`αⱼ = (j/(n − 1))²`, the perceptual
//! roughness) and in `c = √(η − 1)` between `η = 1.01` and `3` ([`eta_node`]): each places
//! more nodes where the albedo bends most — near grazing, for smooth surfaces, and for
//! indices near 1. Lookups interpolate linearly in these coordinates (bilinear, trilinear);
//! a model reads its roughness and index once, at construction, into an [`AlbedoRow`]
//! `E(μ)`, so that its hot loop interpolates in `μ` only.
//!
//! **Where the model has no value.** Node `μ = 0` (tangent `wo`) holds the albedo at half a
//! step in ([`bake::evaluation_mu`]); node `α = 0` holds the smooth surface's exact albedo
//! (1, and the Fresnel reflectance for the coat's table).
//!
//! **Where the model's `f32` rounding shows.** The two first `μ` nodes of the narrowest
//! non-zero width (`α = 2.4e-4`: `μ = 6.1e-5` and `2.4e-4`, within 0.02° of the horizon) hold
//! the crate's own `f32` model there: 0.9556 and 0.8974 where an `f64` integration of the
//! formulas gives 0.9526 and 0.8921 (a review's, with 1200² Gauss–Legendre points). In that
//! corner `E` depends on `μ/α` alone, and the next row's nodes at the same ratio agree with
//! `f64` to 5e-5: it is the model's rounding at a grazing narrow lobe, not the cubature.
//!
//! **Range.** `α ≤ 1` (an anisotropic distribution is read at its RMS width
//! `√((αx² + αy²)/2)`, see [`TabulatedAlbedo`]); `η ∈ [1.01, 3]`
//! and its reciprocals for the dielectric. The compensated models refuse parameters outside
//! it.
//!
//! **How they were made.** `cargo run --release --example bake_tables` evaluates every entry
//! with [`bake`]'s deterministic adaptive cubature of the models' own `eval` and rewrites
//! `src/tables/{ggx,beckmann,ggx_dielectric}.rs`; the averages are
//! those of the interpolated rows ([`AlbedoRow`]). `tests/energy_compensation.rs` re-bakes a
//! sample of entries and finds them identical, and measures the interpolation error against
//! fresh integration off the nodes.
//!
//! Plain Rust arrays, as immutable `static` items (one copy in the binary's read-only data;
//! a `const` would be copied into every use): `no_std`, no allocation, nothing computed at
//! run time but the interpolation.

pub mod bake;
mod beckmann;
mod dielectric_albedo;
mod ggx;
mod ggx_dielectric;
mod row;

pub use beckmann::{BECKMANN_E, BECKMANN_E_AVG};
pub use dielectric_albedo::DielectricAlbedo;
pub use ggx::{GGX_E, GGX_E_AVG};
pub use ggx_dielectric::{
    GGX_DIELECTRIC_INSIDE, GGX_DIELECTRIC_OUTSIDE, GGX_DIELECTRIC_REFLECTION,
};
pub use row::AlbedoRow;
pub(crate) use row::{CHUNK, node_below};

use crate::microfacet::{Beckmann, Ggx, Masking, NormalDistribution};
use crate::param::{Eta, ParamError};

/// Nodes in `μ` of the conductor tables and of every [`AlbedoRow`].
pub const MU_NODES: usize = 65;
/// Nodes in `α` of the conductor tables.
pub const ALPHA_NODES: usize = 65;
/// Nodes in `μ` of the dielectric tables.
pub const DIELECTRIC_MU_NODES: usize = 33;
/// Nodes in `α` of the dielectric tables.
pub const DIELECTRIC_ALPHA_NODES: usize = 33;
/// Nodes in `η` of the dielectric tables.
pub const ETA_NODES: usize = 16;
/// The smallest relative index the dielectric tables hold (the largest below 1 is its
/// reciprocal).
pub const ETA_MIN: f32 = 1.01;
/// The largest relative index the dielectric tables hold (the smallest is its reciprocal).
pub const ETA_MAX: f32 = 3.0;
/// The largest width the tables hold.
pub const ALPHA_MAX: f32 = 1.0;

/// A conductor table: `E[αⱼ][μᵢ]`.
pub type ConductorTable = [[f32; MU_NODES]; ALPHA_NODES];
/// A dielectric table: `E[ηₖ][αⱼ][μᵢ]`.
pub type DielectricTable = [[[f32; DIELECTRIC_MU_NODES]; DIELECTRIC_ALPHA_NODES]; ETA_NODES];

/// `α` at node `j` of `nodes`: `(j / (nodes − 1))²`.
#[inline]
#[must_use]
pub fn alpha_node(j: usize, nodes: usize) -> f32 {
    let r = j as f32 / (nodes - 1) as f32;
    r * r
}

/// `η` at node `k`: `1 + c²` with `c` uniform from `√(ETA_MIN − 1)` to `√(ETA_MAX − 1)`.
#[inline]
#[must_use]
pub fn eta_node(k: usize) -> f32 {
    let (lo, hi) = (eta_coordinate(ETA_MIN), eta_coordinate(ETA_MAX));
    let c = lo + (hi - lo) * k as f32 / (ETA_NODES - 1) as f32;
    1.0 + c * c
}

/// The `η` coordinate `c = √(η − 1)`.
#[inline]
fn eta_coordinate(eta: f32) -> f32 {
    crate::math::sqrt((eta - 1.0).max(0.0))
}

/// Where `t ∈ [0, 1]` falls on `nodes` uniform nodes: the lower node and the fraction.
#[inline]
fn locate(t: f32, nodes: usize) -> (usize, f32) {
    let x = t.clamp(0.0, 1.0) * (nodes - 1) as f32;
    let i = (x as usize).min(nodes - 2);
    (i, x - i as f32)
}

/// Checks a width against the tables' range.
fn check_alpha(alpha: f32) -> Result<f32, ParamError> {
    if alpha > 0.0 && alpha <= ALPHA_MAX {
        Ok(alpha)
    } else {
        Err(ParamError::new("alpha (compensated)", alpha, "(0, 1]"))
    }
}

impl AlbedoRow {
    /// The row of a conductor table at width `alpha`: linear in `√α` between the table's rows,
    /// with the baked average `average` interpolated the same way (a table and its
    /// average, like [`GGX_E`] and [`GGX_E_AVG`]).
    ///
    /// # Errors
    /// [`ParamError`] naming `alpha (compensated)` outside `(0, 1]`, or `albedo` for a table
    /// value outside `[0, 1]`.
    pub fn from_table(
        table: &ConductorTable,
        average: &[f32; ALPHA_NODES],
        alpha: f32,
    ) -> Result<Self, ParamError> {
        let alpha = check_alpha(alpha)?;
        let (j, t) = locate(crate::math::sqrt(alpha), ALPHA_NODES);
        let mut e = [0.0; MU_NODES];
        for (i, v) in e.iter_mut().enumerate() {
            *v = lerp(table[j][i], table[j + 1][i], t);
        }
        Self::from_nodes(e)?.with_average(lerp(average[j], average[j + 1], t))
    }

    /// The row of a dielectric table at width `alpha` and index node position `(k, s)`:
    /// bilinear in `(√α, √(η − 1))`, then carried onto the finer `μ` nodes of a row (exactly:
    /// the row's nodes include the table's).
    fn from_dielectric(
        table: &DielectricTable,
        alpha: f32,
        (k, s): (usize, f32),
    ) -> Result<Self, ParamError> {
        let (j, t) = locate(crate::math::sqrt(alpha), DIELECTRIC_ALPHA_NODES);
        let at = |i: usize| {
            let lo = lerp(table[k][j][i], table[k][j + 1][i], t);
            let hi = lerp(table[k + 1][j][i], table[k + 1][j + 1][i], t);
            lerp(lo, hi, s)
        };
        let ratio = (MU_NODES - 1) / (DIELECTRIC_MU_NODES - 1);
        let mut e = [0.0; MU_NODES];
        for (n, v) in e.iter_mut().enumerate() {
            let (i, r) = (n / ratio, n % ratio);
            *v = if r == 0 {
                at(i)
            } else {
                lerp(at(i), at(i + 1), r as f32 / ratio as f32)
            };
        }
        Self::from_nodes(e)
    }
}

#[inline(always)]
fn lerp(a: f32, b: f32, t: f32) -> f32 {
    a + t * (b - a)
}

/// A distribution whose albedo the crate tabulates: [`Ggx`] and [`Beckmann`].
///
/// The tables are isotropic; an anisotropic distribution is read at its RMS width
/// `α_eq = √((αx² + αy²)/2)`. Of the geometric, arithmetic and RMS means, the RMS width
/// matches GGX's anisotropic albedo at normal incidence best (measured by
/// `tests/energy_compensation.rs`: 0.884 for 0.878 at `α = (0.1, 0.4)`, 0.623 for 0.636 at
/// `(0.05, 0.8)`; the geometric mean gives 0.948 and 0.948, the arithmetic mean 0.916 and
/// 0.762). Away from the normal an anisotropic surface's albedo depends on the azimuth of
/// `wo`, which no isotropic table holds: the compensated furnace of an anisotropic model
/// is off by what `tests/energy_compensation.rs` measures and
/// [`CompensatedMicrofacet`](crate::bxdf::CompensatedMicrofacet) documents.
pub trait TabulatedAlbedo: NormalDistribution {
    /// The width the tables are read at: `√((αx² + αy²)/2)`, `α` itself when isotropic.
    #[must_use]
    fn tabulated_alpha(&self) -> f32;

    /// `E(μ)` and `E_avg` of the `F = 1` conductor on this distribution with height-correlated
    /// masking ([`GGX_E`], [`BECKMANN_E`]).
    ///
    /// # Errors
    /// [`ParamError`] naming `alpha (compensated)` for a width above 1.
    fn conductor_albedo(&self) -> Result<AlbedoRow, ParamError>;
}

/// `Ok` for the masking the tables hold (height-correlated Smith); for any other, the
/// [`ParamError`] naming `masking` that the compensated models' constructors return.
pub(crate) fn tabulated_masking(masking: Masking) -> Result<(), ParamError> {
    match masking {
        Masking::HeightCorrelated => Ok(()),
        other => Err(ParamError::new(
            "masking (0 height-correlated, 1 separable, 2 V-cavity)",
            if other == Masking::Separable {
                1.0
            } else {
                2.0
            },
            "{0}",
        )),
    }
}

/// A distribution whose rough dielectric interface the crate tabulates: [`Ggx`].
pub trait TabulatedDielectric: TabulatedAlbedo {
    /// `E_out(μ)` and `E_in(μ)` of the rough dielectric interface of relative index `eta` on
    /// this distribution (importance mode, height-correlated masking); for `η < 1` the
    /// tables of `1/η` with the sides exchanged.
    ///
    /// # Errors
    /// [`ParamError`] naming `alpha (compensated)` for a width above 1, or `eta (compensated)`
    /// for `η` outside `[1/3, 1/1.01] ∪ [1.01, 3]`.
    fn dielectric_albedo(&self, eta: Eta) -> Result<DielectricAlbedo, ParamError>;

    /// `R(μ)` from the outside of the same interface: the albedo of a coat
    /// (`Microfacet<D, Dielectric>`) of relative index `η ∈ [1.01, 3]`.
    ///
    /// # Errors
    /// As [`dielectric_albedo`](Self::dielectric_albedo), for `η` outside `[1.01, 3]`.
    fn coat_albedo(&self, eta: Eta) -> Result<AlbedoRow, ParamError>;
}

/// `√((αx² + αy²)/2)`, exactly `αx` when the two are equal.
#[inline]
fn rms((ax, ay): (f32, f32)) -> f32 {
    if ax == ay {
        ax
    } else {
        crate::math::sqrt(0.5 * (ax * ax + ay * ay))
    }
}

/// Where `eta` falls on the `η` nodes; `None` outside `[ETA_MIN, ETA_MAX]` (each caller
/// names the range it accepts).
fn locate_eta(eta: f32) -> Option<(usize, f32)> {
    if !(ETA_MIN..=ETA_MAX).contains(&eta) {
        return None;
    }
    let (lo, hi) = (eta_coordinate(ETA_MIN), eta_coordinate(ETA_MAX));
    Some(locate((eta_coordinate(eta) - lo) / (hi - lo), ETA_NODES))
}

/// Where a coat's `eta` (light enters the coat from outside: `η ≥ 1`) falls on the `η`
/// nodes.
fn coat_eta(eta: Eta) -> Result<(usize, f32), ParamError> {
    locate_eta(eta.get())
        .ok_or_else(|| ParamError::new("eta (compensated)", eta.get(), "[1.01, 3]"))
}

/// [`TabulatedAlbedo::dielectric_albedo`] from a pair of tables.
fn dielectric_rows(
    (outside, inside): (&DielectricTable, &DielectricTable),
    alpha: f32,
    eta: Eta,
) -> Result<DielectricAlbedo, ParamError> {
    let alpha = check_alpha(alpha)?;
    let n = eta.get();
    let (flip, n) = if n < 1.0 { (true, 1.0 / n) } else { (false, n) };
    let at = locate_eta(n).ok_or_else(|| {
        ParamError::new("eta (compensated)", eta.get(), "[1/3, 1/1.01] ∪ [1.01, 3]")
    })?;
    let (o, i) = (
        AlbedoRow::from_dielectric(outside, alpha, at)?,
        AlbedoRow::from_dielectric(inside, alpha, at)?,
    );
    Ok(if flip {
        DielectricAlbedo {
            outside: i,
            inside: o,
        }
    } else {
        DielectricAlbedo {
            outside: o,
            inside: i,
        }
    })
}

impl TabulatedAlbedo for Ggx {
    #[inline]
    fn tabulated_alpha(&self) -> f32 {
        rms(self.alpha())
    }

    fn conductor_albedo(&self) -> Result<AlbedoRow, ParamError> {
        AlbedoRow::from_table(&GGX_E, &GGX_E_AVG, self.tabulated_alpha())
    }
}

impl TabulatedDielectric for Ggx {
    fn dielectric_albedo(&self, eta: Eta) -> Result<DielectricAlbedo, ParamError> {
        dielectric_rows(
            (&GGX_DIELECTRIC_OUTSIDE, &GGX_DIELECTRIC_INSIDE),
            self.tabulated_alpha(),
            eta,
        )
    }

    fn coat_albedo(&self, eta: Eta) -> Result<AlbedoRow, ParamError> {
        let alpha = check_alpha(self.tabulated_alpha())?;
        AlbedoRow::from_dielectric(&GGX_DIELECTRIC_REFLECTION, alpha, coat_eta(eta)?)
    }
}

impl TabulatedAlbedo for Beckmann {
    #[inline]
    fn tabulated_alpha(&self) -> f32 {
        rms(self.alpha())
    }

    fn conductor_albedo(&self) -> Result<AlbedoRow, ParamError> {
        AlbedoRow::from_table(&BECKMANN_E, &BECKMANN_E_AVG, self.tabulated_alpha())
    }
}
