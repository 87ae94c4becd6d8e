//! BRDF transfer: a BSDF's cosine-weighted lobe for one viewing direction, projected onto
//! the basis (the transfer vector of precomputed radiance transfer).

use super::basis::basis;
use super::coefficients::Sh;
use super::projection::SphereQuadrature;
use crate::bxdf::Bxdf;
use crate::spectrum::Spectrum;
use glam::Vec3;

/// The transfer vector of a BSDF for a fixed `wo`: the coefficients `t_i` of
/// `g(ωi) = f(wo, ωi) |cos θi|`, so that the radiance leaving toward `wo` under any lighting
/// `L` band-limited to the same order is `L_o(wo) = Σ_i t_i L_i` ([`radiance`](Self::radiance);
/// Sloan, Kautz & Snyder 2002, "Precomputed Radiance Transfer", §4; for lighting with
/// higher bands, the sum is the exact response to its projection).
///
/// Everything is in the BSDF's local frame (`z` the normal): rotate world lighting into it
/// first ([`world_to_local`](super::world_to_local) and [`Sh::rotated`]).
///
/// **What an order captures.** The total, `∫ g dω = √(4π) t₀₀`, is the directional albedo
/// at every order: the projection never loses it, it spreads it. What a finite order loses
/// is the lobe's *shape*, measured by [`captured_fraction`](Self::captured_fraction):
/// `Σ t_i² / ∫ g² dω`, the share of the lobe's `L²` energy in the bands kept (Parseval), which
/// is also the fraction of the reflected radiance the order reproduces under lighting
/// shaped like the lobe itself (`L ∝ g`, the lighting it reflects most): near 1 for a
/// diffuse lobe, falling as a glossy lobe narrows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transfer<const N: usize, S = f32> {
    /// The coefficients `t_i = ∫ f(wo, ω) |cos θ| Y_i(ω) dω`.
    pub coefficients: Sh<N, S>,
    /// The directional albedo `∫ f(wo, ω) |cos θ| dω` by the same quadrature.
    pub albedo: S,
    /// `∫ (f(wo, ω) |cos θ|)² dω` by the same quadrature.
    pub squared_norm: S,
}

impl<const N: usize, S: Spectrum> Transfer<N, S> {
    /// The cosine-weighted lobe of `bxdf` for the viewing direction `wo` (local, unit),
    /// projected by the quadrature `rule` over the whole sphere (so transmission is
    /// included). The lobe is not band-limited: the rule should resolve it, with more
    /// nodes for narrower lobes (`SphereQuadrature::new(96, 192).split_at_equator()` gives
    /// GGX at `α = 0.2` the same captured fraction to four decimals as twice the nodes, and
    /// agrees with importance-sampled Monte Carlo in `tests/sh.rs`); splitting at the
    /// equator makes diffuse lobes exact. Delta lobes (mirror, smooth glass) have no value to
    /// project and give zero.
    ///
    /// ```
    /// use lobe::bxdf::Lambert;
    /// use lobe::sh::{SphereQuadrature, Transfer};
    /// use lobe::Vec3;
    /// let white = Lambert::new(1.0_f32)?;
    /// let rule = SphereQuadrature::exact_for_degree(4).split_at_equator();
    /// let t: Transfer<9> = Transfer::project(&white, Vec3::Z, &rule);
    /// assert!((t.albedo - 1.0).abs() < 1e-5);
    /// // Under a constant radiance 1, a white Lambertian surface reflects 1.
    /// let l = lobe::sh::Sh::<9>::project(|_| 1.0, 1);
    /// assert!((t.radiance(&l) - 1.0).abs() < 1e-5);
    /// # Ok::<(), lobe::ParamError>(())
    /// ```
    #[must_use]
    pub fn project<B: Bxdf<Spectrum = S>>(bxdf: &B, wo: Vec3, rule: &SphereQuadrature) -> Self {
        let mut coefficients = Sh::<N, S>::zero();
        let (mut albedo, mut squared_norm) = (S::zero(), S::zero());
        rule.for_each_ring(|weight, ring| {
            let mut ring_sh = Sh::<N, S>::zero();
            let (mut ring_a, mut ring_q) = (S::zero(), S::zero());
            for wi in ring.directions() {
                let g = bxdf.eval(wo, wi) * wi.z.abs();
                if g.is_black() {
                    continue;
                }
                let y = basis::<N>(wi);
                for (c, yi) in ring_sh.coeffs.iter_mut().zip(y) {
                    *c += g * yi;
                }
                ring_a += g;
                ring_q += g * g;
            }
            coefficients += ring_sh * weight;
            albedo += ring_a * weight;
            squared_norm += ring_q * weight;
        });
        Self {
            coefficients,
            albedo,
            squared_norm,
        }
    }

    /// The radiance leaving toward `wo` under the lighting `l` (radiance coefficients in the
    /// same local frame): `Σ_i t_i L_i` per channel.
    #[inline]
    #[must_use]
    pub fn radiance(&self, l: &Sh<N, S>) -> S {
        self.coefficients.dot(l)
    }

    /// The share of the lobe's `L²` energy the order keeps, `Σ t_i² / ∫ g²` per channel
    /// (in `[0, 1]` up to quadrature error; zero for a black lobe).
    #[must_use]
    pub fn captured_fraction(&self) -> S {
        self.coefficients
            .squared_norm()
            .zip_map(self.squared_norm, |kept, total| {
                if total > 0.0 { kept / total } else { 0.0 }
            })
    }
}
