//! [`AlbedoRow`]: a directional albedo `E(μ)` at one roughness, and its average.

use super::MU_NODES;
use crate::param::ParamError;

/// A directional albedo `E(μ)` over `μ = cos θ ∈ [0, 1]` at one roughness (and index), with
/// its cosine-weighted average `E_avg = 2 ∫₀¹ E(μ) μ dμ`: what a compensated model reads in
/// its hot loop.
///
/// `E` is held at the [`MU_NODES`] nodes `μᵢ = xᵢ²`, `xᵢ = i / (MU_NODES − 1)`, and
/// interpolated linearly in `x = √μ`, which spaces the nodes closer where `E` bends most
/// (near grazing). `E_avg` is the average of that interpolant, exactly (by 3-point
/// Gauss–Legendre on each interval, exact for the degree-4 integrand `E(x) x³`), so that the
/// compensation lobe `(1 − E(μo))(1 − E(μi)) / (π (1 − E_avg))` integrates to
/// `1 − E(μo)` over the hemisphere to `f32` round-off: the white furnace of a compensated
/// model is then off by the table's own error only.
///
/// Built by the distributions' [`TabulatedAlbedo`](super::TabulatedAlbedo) and [`TabulatedDielectric`](super::TabulatedDielectric) methods from the
/// baked tables, or from any function with [`from_fn`](Self::from_fn) (a table of your
/// own, for a masking function the crate does not tabulate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlbedoRow {
    e: [f32; MU_NODES],
    average: f32,
}

impl AlbedoRow {
    /// `μ` at node `i` of the row: `(i / (MU_NODES − 1))²`.
    #[inline]
    #[must_use]
    pub fn node(i: usize) -> f32 {
        let x = i as f32 / (MU_NODES - 1) as f32;
        x * x
    }

    /// The row of the node values `e` (`e[i] = E(μᵢ)`, [`node`](Self::node)), with the
    /// average of their interpolant.
    ///
    /// # Errors
    /// [`ParamError`] naming `albedo` for a value that is NaN or outside `[0, 1]`.
    pub fn from_nodes(e: [f32; MU_NODES]) -> Result<Self, ParamError> {
        for &v in &e {
            if !(0.0..=1.0).contains(&v) {
                return Err(ParamError::new("albedo", v, "[0, 1]"));
            }
        }
        Ok(Self {
            e,
            average: interpolant_average(&e) as f32,
        })
    }

    /// The row of `e(μ)` sampled at the nodes ([`from_nodes`](Self::from_nodes)).
    ///
    /// # Errors
    /// [`ParamError`] naming `albedo` for a value that is NaN or outside `[0, 1]`.
    pub fn from_fn(e: impl Fn(f32) -> f32) -> Result<Self, ParamError> {
        let mut nodes = [0.0; MU_NODES];
        for (i, v) in nodes.iter_mut().enumerate() {
            *v = e(Self::node(i));
        }
        Self::from_nodes(nodes)
    }

    /// The same row with the average `average` in place of its own: for a table whose
    /// average was baked separately, or for a fault check (an average that does not belong
    /// to the row).
    ///
    /// # Errors
    /// [`ParamError`] naming `average` for NaN or a value outside `[0, 1]`.
    pub fn with_average(self, average: f32) -> Result<Self, ParamError> {
        if !(0.0..=1.0).contains(&average) {
            return Err(ParamError::new("average", average, "[0, 1]"));
        }
        Ok(Self { average, ..self })
    }

    /// `E(μ)`, interpolated linearly in `√μ` between the nodes; `μ` outside `[0, 1]` (or NaN)
    /// is clamped to it. Finite for any input.
    #[inline(always)]
    #[must_use]
    pub fn e(&self, mu: f32) -> f32 {
        let (i, t) = position(mu);
        self.between(i as usize, t)
    }

    /// `E(μ)` of every `mu[k]`, into `e[k]` (`mu` has at most `L` lanes; the rest of
    /// `e` is left as it is): the numbers of [`e`](Self::e), in two passes, the positions
    /// first, then the reads of the row. A batched loop looks a chunk of lanes up this way
    /// before its own pass: the positions vectorise, and the pass that reads the table at
    /// each lane's node is a short loop of its own, out of the way of the model's arithmetic
    /// (a read at a different place per lane, a gather, keeps LLVM from vectorising a whole
    /// loop on a target with AVX2 and no AVX-512).
    #[inline(always)]
    pub(crate) fn e_chunk<const L: usize>(&self, mu: &[f32], e: &mut [f32; L]) {
        debug_assert!(mu.len() <= L, "{} lanes for a chunk of {L}", mu.len());
        let mut node = [0_u32; L];
        for ((&mu, e), node) in mu.iter().zip(e.iter_mut()).zip(node.iter_mut()) {
            let (i, t) = position(mu);
            (*node, *e) = (i, t);
        }
        for (e, &i) in e.iter_mut().zip(&node).take(mu.len()) {
            *e = self.between(i as usize, *e);
        }
    }

    /// The interpolant at `t ∈ [0, 1]` of the way from node `i` to node `i + 1`.
    #[inline(always)]
    fn between(&self, i: usize, t: f32) -> f32 {
        let i = i.min(MU_NODES - 2);
        let (a, b) = (self.e[i], self.e[i + 1]);
        a + t * (b - a)
    }

    /// `E_avg = 2 ∫₀¹ E(μ) μ dμ` of the interpolant.
    #[inline(always)]
    #[must_use]
    pub fn average(&self) -> f32 {
        self.average
    }

    /// The node values `E(μᵢ)`.
    #[inline]
    #[must_use]
    pub fn nodes(&self) -> &[f32; MU_NODES] {
        &self.e
    }
}

/// How many lanes the batched loops of the models that read albedo tables look up at once
/// ([`AlbedoRow::e_chunk`]; a call of at most `batch::lanes::SHORT` lanes, that many).
pub(crate) const CHUNK: usize = 256;

/// The node `i` below `μ` and the fraction `t` of the way to the next, for
/// `x = (MU_NODES − 1) √μ` ([`AlbedoRow::e`]); `μ` outside `[0, 1]` (or NaN) is clamped to it.
#[inline(always)]
fn position(mu: f32) -> (u32, f32) {
    let mu = if mu > 0.0 { mu.min(1.0) } else { 0.0 };
    node_below(crate::math::sqrt(mu) * (MU_NODES - 1) as f32, MU_NODES - 2)
}

/// For `x ∈ [0, 2²²]`, the whole number `i = min(⌊x⌋, last)` and `x − i`: a table's node below
/// `x` and the way to the next (`i` is `x as usize` held at `last`, the same numbers). A NaN
/// `x` gives `(last, NaN)`.
///
/// By adding and taking away 2²³ (whose ulp is 1): `x + 2²³ − 2²³` is x rounded to the nearest
/// whole number, one less where that rounded up; and the bits of `2²³ + i` below the
/// exponent's are `i`. Neither a `floor` (a library call on x86-64's baseline, SSE2) nor a
/// float-to-integer conversion (whose saturating form, NaN to 0, LLVM splits into one scalar
/// conversion per lane on AVX2): adds, compares and selects, which vectorise. It needs `f32`
/// arithmetic rounded to `f32` at every step (every target but x87 without SSE2, where extra
/// precision would round `x` instead of truncating: the lookups' unit tests would fail there).
#[inline(always)]
pub(crate) fn node_below(x: f32, last: usize) -> (u32, f32) {
    const TWO_23: f32 = 8_388_608.0;
    let nearest = (x + TWO_23) - TWO_23;
    let whole = if nearest > x { nearest - 1.0 } else { nearest };
    let node = whole.min(last as f32);
    ((node + TWO_23).to_bits() - TWO_23.to_bits(), x - node)
}

/// `2 ∫₀¹ E(μ) μ dμ = 4 ∫₀¹ E(x) x³ dx` for `E` linear in `x = √μ` between the nodes, in
/// `f64`: 3-point Gauss–Legendre per interval, exact for the degree-4 integrand.
pub(crate) fn interpolant_average(e: &[f32]) -> f64 {
    // Nodes ±√(3/5), 0 and weights 5/9, 8/9, 5/9 on [−1, 1].
    const GL3: [(f64, f64); 3] = [
        (-0.774_596_669_241_483_4, 5.0 / 9.0),
        (0.0, 8.0 / 9.0),
        (0.774_596_669_241_483_4, 5.0 / 9.0),
    ];
    let n = e.len() - 1;
    let h = 1.0 / n as f64;
    let mut sum = 0.0;
    for i in 0..n {
        let (a, b) = (f64::from(e[i]), f64::from(e[i + 1]));
        for (t, w) in GL3 {
            let s = 0.5 * (1.0 + t);
            let x = (i as f64 + s) * h;
            sum += w * 0.5 * h * (a + s * (b - a)) * x * x * x;
        }
    }
    4.0 * sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec;
    use std::vec::Vec;

    /// A row with nodes that differ from each other in every bit of interest.
    fn row() -> AlbedoRow {
        AlbedoRow::from_fn(|mu| 0.3 + 0.5 * mu - 0.2 * mu * mu).unwrap()
    }

    /// The lookup as the type's docs define it: the node below `x = 64 √μ` by a
    /// float-to-integer conversion, held below the last, and the straight line between it
    /// and the next.
    fn by_definition(row: &AlbedoRow, mu: f32) -> f32 {
        let mu = if mu > 0.0 { mu.min(1.0) } else { 0.0 };
        let x = mu.sqrt() * (MU_NODES - 1) as f32;
        let i = (x as usize).min(MU_NODES - 2);
        let (a, b) = (row.nodes()[i], row.nodes()[i + 1]);
        a + (x - i as f32) * (b - a)
    }

    /// `μ` at and within three ulps of every node, halfway between nodes in `x` (where
    /// rounding to the nearest whole number ties), on a grid of step 10⁻⁵, and outside
    /// `[0, 1]`.
    fn mus() -> Vec<f32> {
        let mut mus = vec![
            f32::NAN,
            f32::NEG_INFINITY,
            -1.0,
            -0.0,
            0.0,
            1.0,
            1.5,
            f32::INFINITY,
        ];
        for i in 0..MU_NODES {
            let node = AlbedoRow::node(i);
            let mut below = node;
            let mut above = node;
            for _ in 0..4 {
                mus.extend([below, above]);
                below = f32::from_bits(below.to_bits().saturating_sub(1));
                above = f32::from_bits(above.to_bits() + 1);
            }
        }
        mus.extend((0..=100_000).map(|k| k as f32 / 100_000.0));
        mus.extend((0..MU_NODES).map(|i| {
            let x = (i as f32 + 0.5) / (MU_NODES - 1) as f32;
            x * x
        }));
        mus
    }

    #[test]
    fn lookup_is_the_interpolant_of_the_nodes_bit_for_bit() {
        let row = row();
        for mu in mus() {
            let (got, want) = (row.e(mu), by_definition(&row, mu));
            assert_eq!(
                got.to_bits(),
                want.to_bits(),
                "μ = {mu:e}: {got} against {want}"
            );
        }
    }

    #[test]
    fn chunked_lookup_is_the_lookup() {
        let row = row();
        let mus = mus();
        // Whole chunks and a short one.
        for part in mus.chunks(CHUNK).chain([&mus[..3]]) {
            // A value no lookup gives, so that a lane written past the input shows.
            let mut e = [-7.0; CHUNK];
            row.e_chunk(part, &mut e);
            for (k, &mu) in part.iter().enumerate() {
                assert_eq!(e[k].to_bits(), row.e(mu).to_bits(), "μ = {mu:e}");
            }
            // Lanes past the input are left alone.
            assert!(e[part.len()..].iter().all(|&v| v == -7.0));
        }
    }
}
