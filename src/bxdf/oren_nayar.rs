//! The qualitative Oren-Nayar rough diffuse BRDF.

use super::CosineSampled;
use crate::param::ParamError;
use crate::spectrum::Spectrum;
use core::f32::consts::{FRAC_1_PI, FRAC_PI_2};
use glam::Vec3;

/// The qualitative Oren-Nayar model of a rough diffuse surface ("QON"):
///
/// `f = ρ/π (A + B max(0, cos(φi − φo)) sin α tan β)`, with
/// `A = 1 − 0.5 σ²/(σ² + 0.33)`, `B = 0.45 σ²/(σ² + 0.09)`, `α = max(θi, θo)`,
/// `β = min(θi, θo)` and `σ` the standard deviation of the facet slope angle, in radians.
///
/// Oren & Nayar 1994, "Generalization of Lambert's Reflectance Model" (SIGGRAPH '94),
/// eq. 30; the handout's "Diffuse BRDFs" ([seed 000](crate::handouts#seed-000)), correct as printed
/// ([ERRATA #10](crate::errata#erratum-10--oren-nayar-energy)). At
/// `σ = 0` it is Lambert's `ρ/π`.
///
/// **Evaluation without trigonometry.** For unit directions `sin θ = |w.xy|`, so
/// `cos(φi − φo) = (wi.xy · wo.xy)/(|wi.xy| |wo.xy|)` and
/// `sin α tan β = sin θi sin θo / max(cos θi, cos θo)`; their product is
/// `max(0, wi.xy · wo.xy) / max(wi.z, wo.z)`: no square root, no division by `sin θ` (the
/// term is exactly zero at the normal, where `φ` is undefined), and the same expression for
/// `f(wo, wi)` and `f(wi, wo)`. When both directions graze, the term grows like `1/cos θ`
/// (the model's own `tan β`); the denominator is kept above `f32::MIN_POSITIVE`, so the value
/// stays finite for every unit input.
///
/// Sampled by cosine-weighted directions (density `cos θi / π`).
///
/// Parameters: reflectance `ρ ∈ [0, 1]` per channel, roughness `σ ∈ [0, π/2]` radians.
///
/// # Laws
///
/// Reciprocal (exactly: the formula is symmetric in `wo`, `wi` term by term, measured error
/// 0) and positive. **Not energy-conserving**
/// ([ERRATA #10](crate::errata#erratum-10--oren-nayar-energy)): the model drops the light that
/// inter-reflects between facets, so it *loses* energy, most at normal incidence, and it
/// also slightly *gains* at grazing for small `σ`. Its directional albedo has a closed form
/// (integrate the term above against `cos θi`; see [`albedo`](Self::albedo)):
///
/// `E(θo) = ρ (A + (2B/π) sin θo [θo/2 − sin θo cos θo/2 + (1 − sin³θo)/(3 cos θo)])`,
///
/// which rises from `ρA` at the normal to `ρ(A + B/2)` at the horizon. With `ρ = 1`
/// (figures from the closed form, confirmed by quadrature of [`Bxdf::eval`](super::Bxdf::eval) to 2e-6 and by
/// Monte Carlo in `tests/bxdf_oren_nayar.rs`):
///
/// | σ (rad) | θo = 0° | 30° | 60° | 80° | 89° | → 90° | worst loss |
/// | --- | --- | --- | --- | --- | --- | --- | --- |
/// | 0 | 1 | 1 | 1 | 1 | 1 | 1 | 0 |
/// | 0.25 | 0.9204 | 0.9428 | 0.9754 | 1.0012 | 1.0116 | 1.0126 | 8.0 % |
/// | 0.5 | 0.7845 | 0.8247 | 0.8831 | 0.9294 | 0.9481 | 0.9499 | 21.6 % |
/// | 1.0 | 0.6241 | 0.6743 | 0.7471 | 0.8049 | 0.8282 | 0.8305 | 37.6 % |
/// | π/2 | 0.5590 | 0.6118 | 0.6884 | 0.7492 | 0.7736 | 0.7761 | 44.1 % |
///
/// The worst loss is `1 − A` at normal incidence (37.6 % at `σ = 1`, 44.1 % at `σ = π/2`).
/// The largest albedo over all `σ` and `θo` is `A + B/2 = 1.0152` at `σ ≈ 0.199` and
/// grazing `wo`: a gain of 1.5 % ([found by
/// measurement](crate::errata#measured-1--oren-nayar-gain-at-grazing)), so the energy bound
/// holds only up to that factor. For a
/// rough diffuse model that keeps energy, use
/// [`EnergyPreservingOrenNayar`](super::EnergyPreservingOrenNayar).
///
/// ```
/// use lobe::bxdf::{Bxdf, OrenNayar};
/// use lobe::{Vec2, Vec3};
/// let clay = OrenNayar::new(0.8_f32, 0.5)?;
/// // Seen from the normal it reflects A = 1 − 0.5σ²/(σ² + 0.33) of a Lambertian surface.
/// let a = 1.0 - 0.5 * 0.25 / (0.25 + 0.33);
/// assert!((clay.albedo(1.0) - 0.8 * a).abs() < 1e-6);
/// // Backscattering: brighter toward the light than away from it.
/// let wo = Vec3::new(0.6, 0.0, 0.8);
/// let back = clay.eval(wo, wo);
/// let away = clay.eval(wo, Vec3::new(-0.6, 0.0, 0.8));
/// assert!(back > away);
/// let s = clay.sample(wo, Vec2::new(0.3, 0.6), 0.5).unwrap();
/// assert_eq!(s.f, clay.eval(wo, s.wi));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrenNayar<S = f32> {
    reflectance: S,
    sigma: f32,
    /// `A/π`.
    a: f32,
    /// `B/π`.
    b: f32,
}

impl<S: Spectrum> OrenNayar<S> {
    /// The largest accepted roughness `σ`, `π/2` radians.
    pub const SIGMA_MAX: f32 = FRAC_PI_2;

    /// A qualitative Oren-Nayar surface with reflectance `ρ ∈ [0, 1]` per channel and
    /// roughness `σ ∈ [0, π/2]`: the standard deviation of the facet slope angle, in radians.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`, or
    /// `sigma` for a NaN or out-of-range roughness.
    pub fn new(reflectance: S, sigma: f32) -> Result<Self, ParamError> {
        let reflectance = crate::param::unit_interval("reflectance", reflectance)?;
        // `contains` is false for NaN, which is refused with the out-of-range values.
        if !(0.0..=Self::SIGMA_MAX).contains(&sigma) {
            return Err(ParamError::new("sigma", sigma, "[0, π/2]"));
        }
        let s2 = sigma * sigma;
        let a = 1.0 - 0.5 * s2 / (s2 + 0.33);
        let b = 0.45 * s2 / (s2 + 0.09);
        Ok(Self {
            reflectance,
            sigma,
            a: a * FRAC_1_PI,
            b: b * FRAC_1_PI,
        })
    }

    getters! {
        /// The reflectance `ρ`.
        reflectance: S,
        /// The roughness `σ`, in radians.
        sigma: f32,
    }

    /// The coefficients `(A, B)` of the formula.
    #[inline]
    #[must_use]
    pub fn coefficients(&self) -> (f32, f32) {
        (
            self.a * core::f32::consts::PI,
            self.b * core::f32::consts::PI,
        )
    }

    /// The directional albedo `∫ f(wo, wi) cos θi dωi` for a viewer at `cos θo`, in closed
    /// form (see the type's docs); zero for `cos θo ≤ 0` (below the surface) or NaN.
    ///
    /// Not a hot-path function: it calls `acos`.
    #[must_use]
    pub fn albedo(&self, cos_theta_o: f32) -> S {
        if !(cos_theta_o > 0.0) {
            return S::zero();
        }
        let mu = cos_theta_o.min(1.0);
        let sin = crate::math::safe_sqrt(1.0 - mu * mu);
        let theta = crate::math::safe_acos(mu);
        // (1 − sin³θ)/(3 cos θ), rewritten as cos θ (1 + sin θ + sin²θ)/(3 (1 + sin θ)) so
        // that it has no 0/0 at the horizon.
        let tail = mu * (1.0 + sin + sin * sin) / (3.0 * (1.0 + sin));
        let bracket = 0.5 * theta - 0.5 * sin * mu + tail;
        // A/π · π + (2B/π) sin θ · bracket, with a = A/π, b = B/π.
        let e = core::f32::consts::PI * self.a + 2.0 * self.b * sin * bracket;
        self.reflectance * e
    }
}

impl<S: Spectrum> CosineSampled for OrenNayar<S> {
    type Spectrum = S;

    #[inline(always)]
    fn value(&self, wo: Vec3, wi: Vec3) -> S {
        // max(0, cos Δφ) sin α tan β = max(0, wi.xy·wo.xy) / max(cos θi, cos θo).
        let s = wo.x * wi.x + wo.y * wi.y;
        let t = wo.z.max(wi.z).max(f32::MIN_POSITIVE);
        let g = if s > 0.0 { s / t } else { 0.0 };
        self.reflectance * (self.a + self.b * g)
    }
}
