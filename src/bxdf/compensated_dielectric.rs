//! Kulla & Conty's energy compensation of the rough dielectric interface.

use super::compensated::CompensatedState;
use super::{At, BxdfSample, Lobes, Prepare, RoughDielectric, TransportMode, usable_pdf};
use crate::fresnel::{Dielectric, FresnelAverage};
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::param::ParamError;
use crate::sampling::{cosine_hemisphere, reuse_uniform};
use crate::tables::{AlbedoRow, DielectricAlbedo, TabulatedDielectric};
use core::f32::consts::PI;
use glam::{Vec2, Vec3};

/// The compensation lobes for `wo` on one side of the interface: `f_ms = (1 − E(μo)) ·
/// c · (1 − E'(μi))` with `c` and `E'` those of reflection (`wi` on the same side) or of
/// transmission (the other side).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Side {
    /// `c` for reflection and transmission, in the model's transport mode.
    reflect: f32,
    transmit: f32,
    /// The share of the compensated energy that crosses (importance transport): the
    /// probability of sampling the transmission lobe.
    transmitted: f32,
}

/// A rough dielectric interface ([`RoughDielectric`]) with the energy it loses to multiple
/// scattering between microfacets put back, on both sides, after Kulla & Conty (2017,
/// "Revisiting Physically Based Shading at Imageworks", the dielectric extension).
///
/// The single-scattering interface keeps, in importance transport (where the albedo is the
/// fraction of the flux scattered), `E_out(μ)` of the light arriving from the outside and
/// `E_in(μ)` of the light arriving from the inside — rough glass (GGX, `α = 1`, `η = 1.5`)
/// only 0.70–0.89 from the outside and 0.42–0.52 from the inside for `θo ≤ 85°` (read off
/// the tables; toward grazing incidence up to 0.995 and 0.60). The missing energy is put
/// back by four lobes of Kulla & Conty's separable form, each symmetric in its two cosines:
///
/// ```text
/// f_ms(wo, wi) = c_ab (1 − E_a(μo)) (1 − E_b(μi)),      a, b ∈ {out, in}: the sides of wo, wi
/// c_out,out = (1 − t_out) / (π (1 − E_avg,out)),   c_out,in = t_out / (π (1 − E_avg,in))
/// c_in,in   = (1 − t_in)  / (π (1 − E_avg,in)),    c_in,out = c_out,in / η²
/// t_in      = t_out (1 − E_avg,out) / (η² (1 − E_avg,in)),   t_out = 1 − F_avg(η)  (η > 1)
/// ```
///
/// (importance transport). From either side the lobes' albedo is `1 − E(μo)`, so the
/// interface scatters all the flux it receives: `E + (1 − E) = 1` (the white furnace).
/// `t_out` and `t_in` are the shares of the compensated energy that cross the interface;
/// their ratio is not free: reciprocity across an interface,
/// `f(wo, wi)/η_i² = f(wi, wo)/η_o²` in importance transport (Veach 1997, §5.2), fixes
/// `c_in,out = c_out,in / η²`, and with it one share once the other is chosen. The share
/// that enters the denser medium is the smooth interface's hemispherical transmittance from
/// the less dense side, `1 − F_avg` ([`FresnelAverage`]; `t_out = 1 − F_avg(η)` for
/// `η > 1`), as light that has bounced between microfacets is close to diffuse; choosing it
/// on the less dense side makes the interface of `1/η` the same one seen from the other
/// side. Were the derived share above 1, it would be 1 and the chosen one scaled to match. In radiance transport
/// ([`TransportMode::Radiance`]) the transmission lobes carry the radiance scaling of
/// refraction, `1/η'²` (`η'` the index ratio crossed), as the single-scattering lobes do:
/// `f_radiance = f_importance / η'²`, which the tests check pair by pair.
///
/// `E_out`, `E_in` and their averages are the crate's baked tables
/// ([`crate::tables`]: 33 × 33 × 16 in `(μ, α, η)`) read at the distribution's width and the
/// interface's index; `η < 1` reads the tables of `1/η` with the sides exchanged.
///
/// Sampling: the compensation lobes with probability `1 − E(μo)` (their share of the
/// importance-transport albedo), then transmission with probability `t` of `wo`'s side, the
/// direction cosine-distributed on the chosen side; the model's own sampler otherwise. The
/// density is the mixture.
///
/// **Distributions.** The crate bakes the dielectric tables for [`Ggx`](crate::microfacet::Ggx)
/// ([`TabulatedDielectric`]); any other distribution takes tables of your own through
/// [`with_albedo`](Self::with_albedo) ([`bake::dielectric_entry`](crate::tables::bake::dielectric_entry)
/// computes Beckmann's).
///
/// **Range.** Height-correlated masking, `α ≤ 1` (anisotropic: the RMS width `√((αx² + αy²)/2)`), and
/// `η ∈ [1.01, 3]` or its reciprocals; [`new`](Self::new) refuses the rest.
///
/// Laws (measured by `tests/energy_compensation.rs`): importance-transport albedo from
/// 0.9939 to 1.0032 from both sides for `η ∈ {1.1, 1.33, 1.5, 2}`, `α` from 0.05 to 1,
/// `θo` up to 85° from the normal on either side (the bar is `1 ± 0.01`; single
/// scattering 0.32–1.00), the largest deviations from the inside near grazing at `η = 1.1`;
/// positive; reciprocal in the generalised form of each transport mode (to 3.1e-6, measured); the
/// radiance-mode value is the importance-mode one over `η'²` across (to 2.2e-7), and the
/// interface of `1/η` is this one seen from the other side (to 4.8e-6); sampler and density
/// agree (chi-square); `sample` equals `eval`/`pdf`.
///
/// ```
/// use lobe::bxdf::{Bxdf, RoughDielectric, TransportMode};
/// use lobe::microfacet::Ggx;
/// use lobe::{Alpha, Eta, Vec3};
/// let glass = RoughDielectric::new(Ggx::isotropic(Alpha::new(0.8)?), Eta::new(1.5)?)
///     .with_mode(TransportMode::Importance);
/// let compensated = glass.with_energy_compensation()?;
/// let (wo, wi) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.0, 0.6, -0.8));
/// assert!(compensated.eval(wo, wi) > glass.eval(wo, wi));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompensatedDielectric<D> {
    inner: RoughDielectric<D>,
    albedo: DielectricAlbedo,
    outside: Side,
    inside: Side,
}

impl<D: TabulatedDielectric> CompensatedDielectric<D> {
    /// `inner` with Kulla & Conty's compensation, `E` from the crate's tables.
    ///
    /// # Errors
    /// [`ParamError`] naming `masking` for masking other than height-correlated,
    /// `alpha (compensated)` for a width above 1, or `eta (compensated)` for an index
    /// outside the tables.
    pub fn new(inner: RoughDielectric<D>) -> Result<Self, ParamError> {
        crate::tables::tabulated_masking(inner.masking())?;
        let albedo = inner.distribution().dielectric_albedo(inner.eta())?;
        Ok(Self::with_albedo(inner, albedo))
    }
}

impl<D: TabulatedDielectric> RoughDielectric<D> {
    /// The interface with Kulla & Conty's energy compensation
    /// ([`CompensatedDielectric::new`]).
    ///
    /// # Errors
    /// As [`CompensatedDielectric::new`].
    pub fn with_energy_compensation(self) -> Result<CompensatedDielectric<D>, ParamError> {
        CompensatedDielectric::new(self)
    }
}

impl<D: NormalDistribution> CompensatedDielectric<D> {
    /// `inner` with Kulla & Conty's compensation from the albedo `albedo` (`E_out`, `E_in`
    /// of `inner` in importance transport): a table of your own. Not checked against
    /// `inner`.
    #[must_use]
    pub fn with_albedo(inner: RoughDielectric<D>, albedo: DielectricAlbedo) -> Self {
        let eta = inner.eta().get();
        let eta2 = eta * eta;
        let (d_out, d_in) = (
            1.0 - albedo.outside.average(),
            1.0 - albedo.inside.average(),
        );
        let none = Side {
            reflect: 0.0,
            transmit: 0.0,
            transmitted: 0.0,
        };
        if !(d_out > 0.0 && d_in > 0.0) {
            // A smooth surface: nothing to put back.
            return Self {
                inner,
                albedo,
                outside: none,
                inside: none,
            };
        }
        // t_in = t_out (1 − E_avg,out) / (η² (1 − E_avg,in)), from c_in,out = c_out,in / η².
        // The share that enters the denser medium is the smooth interface's hemispherical
        // transmittance from the less dense side; the other follows, and a share above 1
        // is brought back to 1 with the first scaled to match.
        let ratio = d_out / (eta2 * d_in);
        let (t_out, t_in) = if eta >= 1.0 {
            let t = (1.0 - Dielectric { eta: inner.eta() }.average()).clamp(0.0, 1.0);
            let t = t.min(1.0 / ratio);
            (t, (t * ratio).min(1.0))
        } else {
            let t = (1.0
                - Dielectric {
                    eta: inner.eta().inv(),
                }
                .average())
            .clamp(0.0, 1.0);
            let t = t.min(ratio);
            ((t / ratio).min(1.0), t)
        };
        // Importance-transport constants; radiance transport scales the crossings by 1/η'².
        let c_out_in = t_out / (PI * d_in);
        let (scale_out, scale_in) = match inner.mode() {
            TransportMode::Importance => (1.0, 1.0),
            TransportMode::Radiance => (1.0 / eta2, eta2),
        };
        Self {
            inner,
            albedo,
            outside: Side {
                reflect: (1.0 - t_out) / (PI * d_out),
                transmit: c_out_in * scale_out,
                transmitted: t_out,
            },
            inside: Side {
                reflect: (1.0 - t_in) / (PI * d_in),
                transmit: c_out_in / eta2 * scale_in,
                transmitted: t_in,
            },
        }
    }

    /// The single-scattering interface.
    #[inline]
    #[must_use]
    pub fn inner(&self) -> &RoughDielectric<D> {
        &self.inner
    }

    /// The albedo tables the compensation reads.
    #[inline]
    #[must_use]
    pub fn albedo(&self) -> &DielectricAlbedo {
        &self.albedo
    }

    /// The share of the compensated energy that crosses the interface from the outside
    /// (`outside = true`, `t_out`) or from the inside (`t_in`).
    #[inline]
    #[must_use]
    pub fn transmitted_share(&self, outside: bool) -> f32 {
        if outside {
            self.outside.transmitted
        } else {
            self.inside.transmitted
        }
    }

    /// `wo`'s side's lobes and the rows `E` of that side and of the other.
    #[inline(always)]
    fn side(&self, outside: bool) -> (&Side, &AlbedoRow, &AlbedoRow) {
        if outside {
            (&self.outside, &self.albedo.outside, &self.albedo.inside)
        } else {
            (&self.inside, &self.albedo.inside, &self.albedo.outside)
        }
    }

    /// The compensation lobes' value and their sampling density (given their probability
    /// `p`) at `wi`, for `wo` with `outgoing = 1 − E(μo)`.
    #[inline(always)]
    fn lobes_at(&self, wo: Vec3, outgoing: f32, p: f32, wi: Vec3) -> (f32, f32) {
        if wo.z == 0.0 || wi.z == 0.0 {
            return (0.0, 0.0);
        }
        let (side, same, other) = self.side(wo.z > 0.0);
        let cos = wi.z.abs();
        if (wo.z > 0.0) == (wi.z > 0.0) {
            (
                outgoing * side.reflect * (1.0 - same.e(cos)),
                p * (1.0 - side.transmitted) * cos * core::f32::consts::FRAC_1_PI,
            )
        } else {
            (
                outgoing * side.transmit * (1.0 - other.e(cos)),
                p * side.transmitted * cos * core::f32::consts::FRAC_1_PI,
            )
        }
    }
}

impl<D: NormalDistribution> CompensatedDielectric<D> {
    /// The interface's masking term (what a batched loop fixes outside the loop).
    #[inline(always)]
    pub(crate) fn masking(&self) -> Masking {
        self.inner.masking()
    }

    /// [`Prepare::eval_prepared`] under the interface's masking term `masking`.
    #[inline(always)]
    pub(crate) fn eval_with(
        &self,
        at: &CompensatedState<At<View>, f32>,
        wi: Vec3,
        masking: Masking,
    ) -> f32 {
        let f = self.inner.eval_with(&at.inner, wi, masking);
        f + self
            .lobes_at(at.inner.wo, at.outgoing, at.probability, wi)
            .0
    }

    /// [`Prepare::sample_prepared`] under the interface's masking term `masking`.
    #[inline(always)]
    pub(crate) fn sample_with(
        &self,
        at: &CompensatedState<At<View>, f32>,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<f32>> {
        let wo = at.inner.wo;
        if wo.z == 0.0 {
            return None;
        }
        let p = at.probability;
        let (wi, f, pdf, lobe, eta) = if crate::sampling::picks(uc, p) {
            let (side, _, _) = self.side(wo.z > 0.0);
            let transmit = crate::sampling::picks(uc, p * side.transmitted);
            let mut wi = cosine_hemisphere(u);
            // Same side as wo for reflection, the other for transmission.
            if (wo.z > 0.0) == transmit {
                wi.z = -wi.z;
            }
            let (f, pdf) = self.inner.eval_pdf_with(&at.inner, wi, masking);
            let (lobe, eta) = if transmit {
                (
                    Lobes::DIFFUSE | Lobes::TRANSMISSION,
                    self.inner.eta().seen_from(wo.z),
                )
            } else {
                (Lobes::DIFFUSE_REFLECTION, 1.0)
            };
            (wi, f, pdf, lobe, eta)
        } else {
            let uc = reuse_uniform(uc, p, 1.0 - p);
            let s = self.inner.sample_with(&at.inner, u, uc, masking)?;
            (s.wi, s.f, s.pdf, s.lobe, s.eta)
        };
        let (f_ms, pdf_ms) = self.lobes_at(wo, at.outgoing, p, wi);
        let pdf = (1.0 - p) * pdf + pdf_ms;
        if !usable_pdf(pdf) {
            return None;
        }
        Some(BxdfSample {
            wi,
            f: f + f_ms,
            pdf,
            lobe,
            eta,
        })
    }
}

impl<D: NormalDistribution> Prepare for CompensatedDielectric<D> {
    type Spectrum = f32;
    type Prepared = CompensatedState<At<View>, f32>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        let inner = self.inner.prepare(wo);
        let (side, same, _) = self.side(wo.z > 0.0);
        let outgoing = if wo.z == 0.0 || side.reflect + side.transmit == 0.0 {
            0.0
        } else {
            (1.0 - same.e(wo.z.abs())).clamp(0.0, 1.0)
        };
        CompensatedState {
            inner,
            outgoing,
            probability: outgoing,
        }
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        self.eval_with(at, wi, self.inner.masking())
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        let pdf = self.inner.pdf_prepared(&at.inner, wi);
        (1.0 - at.probability) * pdf
            + self
                .lobes_at(at.inner.wo, at.outgoing, at.probability, wi)
                .1
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (f32, f32) {
        let (f, pdf) = self.inner.eval_pdf_prepared(&at.inner, wi);
        let (f_ms, pdf_ms) = self.lobes_at(at.inner.wo, at.outgoing, at.probability, wi);
        (f + f_ms, (1.0 - at.probability) * pdf + pdf_ms)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        self.sample_with(at, u, uc, self.inner.masking())
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        Prepare::lobes(&self.inner)
            | Lobes::DIFFUSE_REFLECTION
            | Lobes::DIFFUSE
            | Lobes::TRANSMISSION
    }
}
