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

impl DielectricAlbedo {
    /// The row of a direction's own side: [`outside`](Self::outside) for `z > 0`, else
    /// [`inside`](Self::inside).
    #[inline(always)]
    pub(crate) fn row(&self, z: f32) -> &AlbedoRow {
        if z > 0.0 { &self.outside } else { &self.inside }
    }

    /// `row(z).e(|z|)` of every `z[k]`, into `e[k]` (at most `L` lanes): both rows
    /// looked up with [`AlbedoRow::e_chunk`], then each lane's side kept (a select), so that
    /// the numbers are [`row`](Self::row)'s and a batched loop reads no table.
    #[inline(always)]
    pub(crate) fn e_chunk<const L: usize>(&self, z: &[f32], e: &mut [f32; L]) {
        debug_assert!(z.len() <= L, "{} lanes for a chunk of {L}", z.len());
        let n = z.len().min(L);
        let mut mu = [0.0; L];
        for (mu, &z) in mu.iter_mut().zip(z) {
            *mu = z.abs();
        }
        let (mut outside, mut inside) = ([0.0; L], [0.0; L]);
        self.outside.e_chunk(&mu[..n], &mut outside);
        self.inside.e_chunk(&mu[..n], &mut inside);
        let sides = outside.iter().zip(&inside);
        for ((e, &z), (&o, &i)) in e.iter_mut().zip(z).zip(sides) {
            *e = if z > 0.0 { o } else { i };
        }
    }
}
