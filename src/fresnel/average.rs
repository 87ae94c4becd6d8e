//! The hemispherical average of a Fresnel term, which energy compensation needs.

use super::{Conductor, Dielectric, Fresnel, NoFresnel, Schlick, dielectric};
use crate::spectrum::Spectrum;

use crate::math::{GL8_NODES as NODES, GL8_WEIGHTS as WEIGHTS};
/// Panels of the composite rule over `μ ∈ [0, 1]` (8 nodes each).
const PANELS: usize = 8;

/// `2 ∫₀¹ F(μ) μ dμ` by the composite 8-point Gauss–Legendre rule on 8 panels:
/// 64 evaluations of `F`, exact for a polynomial of degree 15 on each panel, so for a smooth
/// integrand only: a kink, as a dielectric's at the critical angle seen from the denser side
/// (`η < 1`), costs digits (5e-3 at `η = 1/2.4`; [`Dielectric`]'s [`FresnelAverage`] goes
/// round it). Measured against a 2¹⁶-interval midpoint rule in `f64`
/// (`tests/energy_compensation.rs`, which asserts 2.5e-7): Schlick's term within 1.0e-7, the
/// exact conductor's for `η ≥ 1` or large `κ` (with `η < 1` and small `κ` it has a kink or a sharp
/// bend: [`Conductor`]'s [`FresnelAverage`] grades its panels there, within 2.0e-7 for `η` from
/// 0.143 to 1.5 and `κ` from 0 to 4), the dielectric's ([`FresnelAverage`], `η` from 1/2.4 to 2.4
/// with `|η − 1| ≥ 1e-3`) within 1.6e-7; closer to 1 the dielectric's rise at grazing incidence is
/// narrower than a panel (6.9e-7 at `η = 1.0001`, of an average of 3.3e-5, held below 1e-6 by the
/// same test). Also the average of a directional albedo `E(μ)` over uniformly incident light (`Ē`),
/// for the tables models build at construction ([`Plastic`](crate::bxdf::Plastic)'s).
#[must_use]
pub fn cosine_weighted_average<S: Spectrum>(f: impl Fn(f32) -> S) -> S {
    cosine_weighted_part(&f, 0.0, 1.0, PANELS)
}

/// A Fresnel term whose hemispherical average is known:
///
/// ```text
/// F_avg = 2 ∫₀¹ F(μ) μ dμ
/// ```
///
/// the cosine-weighted mean reflectance over incident directions, from which Kulla & Conty
/// (2017, "Revisiting Physically Based Shading at Imageworks") build the colour of the multiply scattered light,
/// `F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg))` (see
/// [`CompensatedMicrofacet`](crate::bxdf::CompensatedMicrofacet)).
///
/// Implemented for [`Schlick`] (closed form), [`Conductor`] and [`Dielectric`]
/// (quadrature, [`cosine_weighted_average`]) and [`NoFresnel`] (1).
pub trait FresnelAverage: Fresnel {
    /// `F_avg = 2 ∫₀¹ F(μ) μ dμ`, per channel, in `[0, 1]`.
    #[must_use]
    fn average(&self) -> Self::Spectrum;
}

impl<S: Spectrum> FresnelAverage for Schlick<S> {
    /// `F0 + (1 − F0) · 2 ∫₀¹ (1 − μ)⁵ μ dμ = F0 + (1 − F0)/21`, since
    /// `∫₀¹ (1 − μ)⁵ μ dμ = B(2, 6) = 1/42`.
    #[inline]
    fn average(&self) -> S {
        let f0 = self.eval(1.0);
        f0 + (S::one() - f0) * (1.0 / 21.0)
    }
}

/// `2 ∫ F(μ) μ dμ` over `[lo, hi]` by the 8-point Gauss–Legendre rule on `panels` equal
/// panels ([`cosine_weighted_average`] is this on `[0, 1]` with 8 panels).
fn cosine_weighted_part<S: Spectrum>(f: &impl Fn(f32) -> S, lo: f32, hi: f32, panels: usize) -> S {
    let half = 0.5 / panels as f32 * (hi - lo);
    let mut sum = S::zero();
    for p in 0..panels {
        let mid = lo + (2 * p + 1) as f32 * half;
        for (x, w) in NODES.iter().zip(WEIGHTS) {
            for mu in [mid - half * x, mid + half * x] {
                sum += f(mu) * (w * half * mu);
            }
        }
    }
    sum * 2.0
}

/// Levels of the panels graded toward a conductor's bend at `μc`, each a quarter of the last.
const GRADED_LEVELS: i32 = 10;

/// `2 ∫ F(μ) μ dμ` on both sides of `μc`, with one-panel rules whose widths shrink
/// geometrically (by 4) toward `μc` from each side down to 4⁻¹⁰ of the side's length: a bend
/// there, a kink or a square-root edge, is resolved as a smooth integrand's would be.
fn cosine_weighted_graded(f: &impl Fn(f32) -> f32, mu_c: f32) -> f32 {
    let mut sum = 0.0_f32;
    for (lo, hi) in [(0.0, mu_c), (mu_c, 1.0)] {
        let toward_hi = lo == 0.0;
        let len = hi - lo;
        // Edges at μc ∓ len·4⁻ʲ, j = 0..=GRADED_LEVELS, then the last panel to μc itself.
        // (4⁻ʲ by repeated quartering, exact in f32: `powi` is not in `core`.)
        let edge = |j: i32| {
            let d = (0..j).fold(len, |d, _| d * 0.25);
            if toward_hi { hi - d } else { lo + d }
        };
        for j in 0..GRADED_LEVELS {
            let (a, b) = (edge(j), edge(j + 1));
            sum += cosine_weighted_part(f, a.min(b), a.max(b), 1);
        }
        let last = edge(GRADED_LEVELS);
        sum += cosine_weighted_part(f, last.min(mu_c), last.max(mu_c), 1);
    }
    sum
}

impl<S: Spectrum> FresnelAverage for Conductor<S> {
    /// By quadrature of the exact conductor term, channel by channel
    /// ([`cosine_weighted_average`]'s rule). In a channel with `η < 1` the term bends at
    /// `μc = √(1 − η²)` (`κ = 0`: total internal reflection below it, a square-root edge; small
    /// `κ`: a bend of width about `κ`), where a single rule across it was 7e-3 off at
    /// `η = 0.3, κ = 0`: there the panels are graded toward `μc` from both sides
    /// (tested within 2.5e-7 for `κ` from 0 to 4 and `η` from 0.143 to 0.7).
    #[inline]
    fn average(&self) -> S {
        let eta = self.ior.eta();
        S::from_fn(|i| {
            let f = |mu| self.eval(mu).channel(i);
            let n = eta.channel(i);
            let avg = if n < 1.0 {
                cosine_weighted_graded(&f, crate::math::sqrt((1.0 - n) * (1.0 + n)))
            } else {
                cosine_weighted_part(&f, 0.0, 1.0, PANELS)
            };
            avg.clamp(0.0, 1.0)
        })
    }
}

impl FresnelAverage for Dielectric {
    /// By quadrature from the less dense side, where the term is smooth; from the denser side
    /// (`η < 1` seen from the outside) through the reciprocity of the smooth interface,
    /// `1 − F_avg(1/n) = (1 − F_avg(n)) / n²` for `n > 1`, which skips the kink at the
    /// critical angle. (The identity: the smooth interface's transmission is reciprocal in
    /// the generalised form `T(wo → wi)/η_o² = T(wi → wo)/η_i²` (Veach 1997, §5.2), and
    /// Snell's map `n² μt dμt = μi dμi` carries one side's cosine-weighted hemisphere onto the
    /// part of the other's that escapes total internal reflection.)
    #[inline]
    fn average(&self) -> f32 {
        let n = self.eta.get();
        if n >= 1.0 {
            cosine_weighted_average(|mu| dielectric(mu, self.eta)).clamp(0.0, 1.0)
        } else {
            let outer = cosine_weighted_average(|mu| dielectric(mu, self.eta.inv()));
            (1.0 - n * n * (1.0 - outer)).clamp(0.0, 1.0)
        }
    }
}

impl<S: Spectrum> FresnelAverage for NoFresnel<S> {
    /// `1`.
    #[inline]
    fn average(&self) -> S {
        S::one()
    }
}
