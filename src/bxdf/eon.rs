//! The energy-preserving Oren-Nayar rough diffuse BRDF (EON).

use super::CosineSampled;
use crate::param::ParamError;
use crate::spectrum::Spectrum;
use core::f32::consts::{FRAC_1_PI, PI};
use glam::Vec3;

/// `1/2 − 2/(3π)`: the FON normalisation constant, `A_F = 1/(1 + C1 r)`, and also `G(0)/π`.
const C1: f32 = 0.5 - 2.0 / (3.0 * PI);
/// `2/3 − 28/(15π)`: the FON average albedo is `Ē_F = (1 + C2 r)/(1 + C1 r)`.
const C2: f32 = 2.0 / 3.0 - 28.0 / (15.0 * PI);
/// The paper's fit of `G(μ)/π` by a quartic in `1 − μ` (no constant term), with the digits
/// as published (rounded to `f32` by the compiler).
#[allow(clippy::excessive_precision)]
const G_FIT: [f32; 4] = [
    0.057_108_528_9,
    0.491_881_867,
    -0.332_181_442,
    0.071_442_995_3,
];

/// The energy-preserving Oren-Nayar model ("EON") of a rough diffuse surface: Fujii's
/// improved Oren-Nayar lobe (FON) plus an analytic multiple-scattering lobe that returns the
/// energy FON loses, so that a white surface (`ρ = 1`) reflects all the light for every
/// viewing direction (the white furnace test).
///
/// Portsmouth, Kutz & Hill, "EON: A Practical Energy-Preserving Rough Diffuse BRDF",
/// *Journal of Computer Graphics Techniques* 14(1), 2025 (arXiv:2410.18026): the FON
/// single-scattering lobe, its exact directional and average albedo, the fitted albedo and
/// the energy-compensation lobe as the paper defines them and gives them in its Listing 1
/// (`f_EON`, `E_FON_exact`, `E_FON_approx`); the same definitions appear in the MaterialX
/// specification's appendix "EON Reflectance Model". Fujii's FON model:
/// <https://mimosa-pudica.net/improved-oren-nayar.html>.
///
/// With roughness `r ∈ [0, 1]`, `μ = cos θ`, and `s = wi·wo − μi μo`:
///
/// * single scattering: `f_ss = ρ/π · A_F (1 + r s/t)`, `A_F = 1/(1 + (1/2 − 2/(3π)) r)`,
///   `t = max(μi, μo)` when `s > 0` and `t = 1` otherwise;
/// * its albedo (`ρ = 1`): `E_F(μ) = A_F (1 + r G(μ)/π)`, with
///   `G(μ) = sin θ (θ − sin θ cos θ) + (2/3)(sin θ (1 − sin³θ)/cos θ − sin θ)`, and its
///   cosine-weighted average `Ē_F = A_F (1 + (2/3 − 28/(15π)) r)`;
/// * multiple scattering: `f_ms = ρ_ms/π · (1 − E_F(μo))(1 − E_F(μi))/(1 − Ē_F)`, with
///   `ρ_ms = ρ² Ē_F / (1 − ρ (1 − Ē_F))`;
/// * `f = f_ss + f_ms`.
///
/// `E_F` is evaluated, as the paper recommends for speed, by its fit
/// `G(μ)/π ≈ x (0.0571085289 + x (0.491881867 + x (−0.332181442 + 0.0714429953 x)))`,
/// `x = 1 − μ`; [`with_exact_albedo`](Self::with_exact_albedo) switches to the exact `G`
/// (one `acos` per direction). Written as `1 − E_F(μ) = A_F r (1/2 − 2/(3π) − G(μ)/π)`, the
/// lobe has no `0/0` at `r = 0` (where it vanishes) and is clamped at zero where the fit
/// overshoots `E_F = 1` near the horizon. `s` equals `wi.xy · wo.xy` for unit vectors and is
/// computed so; `s/t` is bounded by `1/max(μi, μo)`, and `t` is kept above
/// `f32::MIN_POSITIVE` so the value is finite even when both directions graze.
///
/// Sampled by cosine-weighted directions (density `cos θi / π`). The paper's clipped
/// linearly transformed cosine sampler is not provided.
///
/// Parameters: reflectance `ρ ∈ [0, 1]` per channel (the single-scattering albedo), roughness
/// `r ∈ [0, 1]` (the paper's `r`, Fujii's `σ'`, OpenPBR's `base_diffuse_roughness`; not the
/// microfacet [`Roughness`](crate::Roughness), which maps to `α = r²`). At `r = 0` the model
/// is Lambert's `ρ/π`.
///
/// # Laws
///
/// Reciprocal (exactly: every term is symmetric in `wo`, `wi`; measured error 0) and
/// positive. **Energy**: the directional albedo is `ρ E_F(μo) + ρ_ms (1 − E_F(μo))` (see
/// [`albedo`](Self::albedo)), exactly `1` for `ρ = 1` when `E_F` is exact. Measured by
/// quadrature of [`Bxdf::eval`](super::Bxdf::eval) with `ρ = 1` over `θo ∈ [0°, 89°]` (`tests/bxdf_eon.rs`):
///
/// | `r` | fitted `E_F`: max \|albedo − 1\| | at θo | exact `E_F`: max \|albedo − 1\| |
/// | --- | --- | --- | --- |
/// | 0.1 | 6.8e-5 | 17.5° | 6e-8 |
/// | 0.5 | 3.1e-4 | 17.5° | 1.0e-7 |
/// | 1.0 | 5.4e-4 | 17.5° | 6e-8 |
///
/// With the fit the albedo is mostly just below 1; its largest excess over all `r ∈ [0, 1]`
/// and `θo < 90°` is `1.5e-4` (at `r = 1`, `θo ≈ 82°`), so the energy bound holds up to
/// `1 + 1.5e-4`; with the exact `E_F` it holds to `f32` round-off. For `ρ < 1`,
/// `ρ_ms ≤ ρ`, so the albedo is at most `ρ` (up to the same fit error).
///
/// ```
/// use lobe::bxdf::{Bxdf, EnergyPreservingOrenNayar};
/// use lobe::{Vec2, Vec3};
/// // A white, fully rough surface reflects everything it receives, from every direction.
/// let white = EnergyPreservingOrenNayar::new(1.0_f32, 1.0)?;
/// for mu in [1.0, 0.5, 0.1] {
///     assert!((white.albedo(mu) - 1.0).abs() < 1e-6);
/// }
/// // A grey one: the multiple-scattering lobe is tinted by ρ², so rough surfaces saturate.
/// let grey = EnergyPreservingOrenNayar::new(0.5_f32, 1.0)?.with_exact_albedo();
/// assert!(grey.albedo(1.0) < 0.5);
/// let wo = Vec3::new(0.6, 0.0, 0.8);
/// let s = grey.sample(wo, Vec2::new(0.3, 0.6), 0.5).unwrap();
/// assert_eq!(s.f, grey.eval(wo, s.wi));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyPreservingOrenNayar<S = f32> {
    reflectance: S,
    roughness: f32,
    /// Exact `G(μ)` instead of the paper's fit.
    exact: bool,
    /// `ρ A_F / π`, the single-scattering lobe's factor.
    single: S,
    /// `ρ_ms A_F r / (π (C1 − C2))`: the multiple-scattering lobe is this times
    /// `(C1 − G(μo)/π)(C1 − G(μi)/π)`.
    multi: S,
}

impl<S: Spectrum> EnergyPreservingOrenNayar<S> {
    /// An EON surface with single-scattering albedo `ρ ∈ [0, 1]` per channel and roughness
    /// `r ∈ [0, 1]`, using the paper's fitted FON albedo (see
    /// [`with_exact_albedo`](Self::with_exact_albedo)).
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`, or
    /// `roughness` for a NaN roughness or one outside `[0, 1]`.
    pub fn new(reflectance: S, roughness: f32) -> Result<Self, ParamError> {
        let reflectance = crate::param::unit_interval("reflectance", reflectance)?;
        // `contains` is false for NaN, which is refused with the out-of-range values.
        if !(0.0..=1.0).contains(&roughness) {
            return Err(ParamError::new("roughness", roughness, "[0, 1]"));
        }
        let r = roughness;
        let a_f = 1.0 / (1.0 + C1 * r);
        let rho_ms = multiple_scattering_albedo(reflectance, r);
        Ok(Self {
            reflectance,
            roughness,
            exact: false,
            single: reflectance * (a_f * FRAC_1_PI),
            multi: rho_ms * (a_f * r * FRAC_1_PI / (C1 - C2)),
        })
    }

    /// The same surface, evaluating the FON albedo `E_F` in the multiple-scattering lobe
    /// exactly instead of by the paper's fit: the white furnace then holds to `f32`
    /// round-off, at the cost of an `acos` and a square root per direction.
    #[inline]
    #[must_use]
    pub fn with_exact_albedo(self) -> Self {
        Self {
            exact: true,
            ..self
        }
    }

    getters! {
        /// The reflectance (single-scattering albedo) `ρ`.
        reflectance: S,
        /// The roughness `r`.
        roughness: f32,
    }

    /// True when the FON albedo is evaluated exactly rather than by the paper's fit.
    #[inline]
    #[must_use]
    pub fn is_exact(&self) -> bool {
        self.exact
    }

    /// The directional albedo for a viewer at `cos θo`: `ρ E_F(μo) + ρ_ms (1 − E_F(μo))`
    /// (the paper's `E_EON`), with `E_F` fitted or exact as the model evaluates it; zero for
    /// `cos θo ≤ 0` or NaN. Exact for the exact model; for the fitted one it differs from
    /// the integral of [`Bxdf::eval`](super::Bxdf::eval) by the fit's error (at most `5.4e-4` for `ρ = 1`).
    #[must_use]
    pub fn albedo(&self, cos_theta_o: f32) -> S {
        if !(cos_theta_o > 0.0) {
            return S::zero();
        }
        let r = self.roughness;
        let a_f = 1.0 / (1.0 + C1 * r);
        // 1 − E_F(μ) = A_F r (C1 − G(μ)/π), clamped where the fit overshoots.
        let loss = (a_f * r * self.compensation(cos_theta_o.min(1.0))).clamp(0.0, 1.0);
        let rho_ms = multiple_scattering_albedo(self.reflectance, r);
        self.reflectance * (1.0 - loss) + rho_ms * loss
    }

    /// `max(0, C1 − G(μ)/π)`, proportional to the single-scattering lobe's missing albedo
    /// `1 − E_F(μ)`; for `μ ∈ (0, 1]`.
    #[inline(always)]
    fn compensation(&self, mu: f32) -> f32 {
        if self.exact {
            Self::compensation_in::<true>(mu)
        } else {
            Self::compensation_in::<false>(mu)
        }
    }

    /// [`compensation`](Self::compensation) with `G` exact (`EXACT`) or the paper's fit.
    #[inline(always)]
    fn compensation_in<const EXACT: bool>(mu: f32) -> f32 {
        let g_over_pi = if EXACT {
            g_exact_over_pi(mu)
        } else {
            let x = 1.0 - mu;
            x * (G_FIT[0] + x * (G_FIT[1] + x * (G_FIT[2] + x * G_FIT[3])))
        };
        (C1 - g_over_pi).max(0.0)
    }

    /// [`CosineSampled::value`] with `G` exact (`EXACT`) or the paper's fit, whatever the
    /// model holds (its callers pass [`is_exact`](Self::is_exact)'s answer): a batched loop
    /// fixes the form outside the loop ([`FixedForm`]); read per
    /// lane, the choice kept the loops from vectorising under AVX2 (`eval` ran at 0.6× the
    /// scalar speed; measured 2026-11-29).
    #[inline(always)]
    fn value_in<const EXACT: bool>(&self, wo: Vec3, wi: Vec3) -> S {
        // s = wi·wo − μi μo = wi.xy·wo.xy for unit vectors, without the cancellation.
        let s = wo.x * wi.x + wo.y * wi.y;
        let s_over_t = if s > 0.0 {
            s / wo.z.max(wi.z).max(f32::MIN_POSITIVE)
        } else {
            s
        };
        // 1 + r s ≥ 0 for s ≥ −1 and r ≤ 1; the clamp absorbs round-off.
        let single = (1.0 + self.roughness * s_over_t).max(0.0);
        // The product of the two directions' factors first, so that f(wo, wi) and
        // f(wi, wo) round identically.
        let ms = Self::compensation_in::<EXACT>(wo.z) * Self::compensation_in::<EXACT>(wi.z);
        self.single * single + self.multi * ms
    }
}

/// The model with its albedo's form fixed (`EXACT`: [`is_exact`]'s answer), for a batched
/// loop: the same numbers as the model's own calls.
///
/// [`is_exact`]: EnergyPreservingOrenNayar::is_exact
pub(crate) struct FixedForm<'a, S, const EXACT: bool>(pub(crate) &'a EnergyPreservingOrenNayar<S>);

impl<S: Spectrum, const EXACT: bool> CosineSampled for FixedForm<'_, S, EXACT> {
    type Spectrum = S;

    #[inline(always)]
    fn value(&self, wo: Vec3, wi: Vec3) -> S {
        self.0.value_in::<EXACT>(wo, wi)
    }
}

/// `ρ_ms = ρ² Ē_F / (1 − ρ (1 − Ē_F))` per channel, with `Ē_F = (1 + C2 r)/(1 + C1 r)` and
/// `1 − Ē_F = (C1 − C2) r/(1 + C1 r)` (no cancellation at small `r`).
fn multiple_scattering_albedo<S: Spectrum>(reflectance: S, r: f32) -> S {
    let denom = 1.0 + C1 * r;
    let e_avg = (1.0 + C2 * r) / denom;
    let loss_avg = (C1 - C2) * r / denom;
    reflectance.map(|p| p * p * e_avg / (1.0 - p * loss_avg))
}

/// The exact `G(μ)/π` of the FON albedo, for `μ ∈ [0, 1]`, with the `(1 − sin³θ)/cos θ`
/// term rewritten as `cos θ (1 + sin θ + sin²θ)/(1 + sin θ)` (finite at the horizon).
#[inline(always)]
fn g_exact_over_pi(mu: f32) -> f32 {
    let sin = crate::math::safe_sqrt(1.0 - mu * mu);
    let theta = crate::math::safe_acos(mu);
    let tail = mu * (1.0 + sin + sin * sin) / (1.0 + sin);
    (sin * (theta - sin * mu) + (2.0 / 3.0) * sin * (tail - 1.0)) * FRAC_1_PI
}

impl<S: Spectrum> CosineSampled for EnergyPreservingOrenNayar<S> {
    type Spectrum = S;

    #[inline(always)]
    fn value(&self, wo: Vec3, wi: Vec3) -> S {
        if self.exact {
            self.value_in::<true>(wo, wi)
        } else {
            self.value_in::<false>(wo, wi)
        }
    }
}
