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
        let mu = if mu > 0.0 { mu.min(1.0) } else { 0.0 };
        let x = crate::math::sqrt(mu) * (MU_NODES - 1) as f32;
        let i = (x as usize).min(MU_NODES - 2);
        let t = x - i as f32;
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
