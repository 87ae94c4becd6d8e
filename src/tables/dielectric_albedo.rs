//! [`DielectricAlbedo`]: a rough dielectric interface's directional albedo from both sides.

use super::AlbedoRow;

/// The single-scattering directional albedo of a rough dielectric interface (reflection plus
/// transmission, importance transport: the fraction of the flux scattered) seen from the
/// outside and from the inside, at one roughness and one relative index `η`: the tables
/// Kulla & Conty's dielectric compensation reads
/// ([`CompensatedDielectric`](crate::bxdf::CompensatedDielectric)).
///
/// Built by [`TabulatedDielectric::dielectric_albedo`](super::TabulatedDielectric::dielectric_albedo).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DielectricAlbedo {
    /// `E_out(μ)`: `wo` outside (`wo.z > 0`), relative index `η`.
    pub outside: AlbedoRow,
    /// `E_in(μ)`: `wo` inside (`wo.z < 0`, `μ = |cos θo|`), the interface seen with `1/η`.
    pub inside: AlbedoRow,
}
