//! Kulla & Conty's energy compensation of the rough dielectric interface.

use super::compensated::CompensatedState;
use super::{At, BxdfSample, Lobes, Prepare, RoughDielectric, TransportMode, usable_pdf};
use crate::fresnel::{Dielectric, FresnelAverage};
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::param::ParamError;
use crate::sampling::{cosine_hemisphere, reuse_uniform};
use crate::tables::{DielectricAlbedo, TabulatedDielectric};
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

    /// The lobes of the side of a direction whose cosine is `z` (the outside's for `z > 0`),
    /// picked field by field: selects of values in a batched loop. (Written so while the
    /// glass's loops were made to vectorise; what kept them scalar was elsewhere, and whether
    /// a select of the whole `Side` would vectorise as well was not measured.)
    #[inline(always)]
    fn side_of(&self, z: f32) -> Side {
        let outside = z > 0.0;
        let pick = |a: f32, b: f32| if outside { a } else { b };
        let (o, i) = (&self.outside, &self.inside);
        Side {
            reflect: pick(o.reflect, i.reflect),
            transmit: pick(o.transmit, i.transmit),
            transmitted: pick(o.transmitted, i.transmitted),
        }
    }

    /// The compensation lobes' value and their sampling density (given their probability
    /// `p`) at `wi`, for `wo` with `outgoing = 1 − E(μo)`. `E` is read on `wi`'s side:
    /// reflection stays on `wo`'s, transmission reaches the other.
    #[inline(always)]
    fn lobes_at(&self, wo: Vec3, outgoing: f32, p: f32, wi: Vec3) -> (f32, f32) {
        if wo.z == 0.0 || wi.z == 0.0 {
            return (0.0, 0.0);
        }
        let e_wi = self.albedo.row(wi.z).e(wi.z.abs());
        (
            self.lobes_value(wo.z, outgoing, wi.z, e_wi),
            self.lobes_pdf(wo.z, p, wi.z),
        )
    }

    /// The compensation lobes' value `outgoing · c · (1 − E(μi))`, `c` of reflection or of
    /// transmission, given `e_wi = E(μi)` on `wi`'s side; 0 for a direction in the surface.
    /// `wo_z`, `wi_z`: the directions' cosines. Without a branch (selects), for a batched loop.
    #[inline(always)]
    fn lobes_value(&self, wo_z: f32, outgoing: f32, wi_z: f32, e_wi: f32) -> f32 {
        let side = self.side_of(wo_z);
        let c = if (wo_z > 0.0) == (wi_z > 0.0) {
            side.reflect
        } else {
            side.transmit
        };
        let f = outgoing * c * (1.0 - e_wi);
        if wo_z == 0.0 || wi_z == 0.0 { 0.0 } else { f }
    }

    /// The compensation lobes' sampling density, given their probability `p`: the cosine
    /// density on `wi`'s side times the chance of that side; 0 for a direction in the
    /// surface. Without a branch, as [`lobes_value`](Self::lobes_value).
    #[inline(always)]
    fn lobes_pdf(&self, wo_z: f32, p: f32, wi_z: f32) -> f32 {
        let side = self.side_of(wo_z);
        let t = if (wo_z > 0.0) == (wi_z > 0.0) {
            1.0 - side.transmitted
        } else {
            side.transmitted
        };
        let pdf = p * t * wi_z.abs() * core::f32::consts::FRAC_1_PI;
        if wo_z == 0.0 || wi_z == 0.0 { 0.0 } else { pdf }
    }

    /// The compensation lobes' draw for `wo` on the side of `wo_z`, once `uc` has picked them
    /// (with probability `p`): transmission with the side's share, reflection otherwise, the
    /// direction cosine-distributed on the chosen side; with its lobe and relative index.
    #[inline(always)]
    fn draw_compensation(&self, wo_z: f32, p: f32, u: Vec2, uc: f32) -> (Vec3, Lobes, f32) {
        let transmit = crate::sampling::picks(uc, p * self.side_of(wo_z).transmitted);
        let mut wi = cosine_hemisphere(u);
        // Same side as wo for reflection, the other for transmission.
        if (wo_z > 0.0) == transmit {
            wi.z = -wi.z;
        }
        if transmit {
            let eta = self.inner.eta().seen_from(wo_z);
            (wi, Lobes::DIFFUSE | Lobes::TRANSMISSION, eta)
        } else {
            (wi, Lobes::DIFFUSE_REFLECTION, 1.0)
        }
    }
}

impl<D: NormalDistribution> CompensatedDielectric<D> {
    /// The interface's masking term (what a batched loop fixes outside the loop).
    #[inline(always)]
    pub(crate) fn masking(&self) -> Masking {
        self.inner.masking()
    }

    /// The sample of [`sample_prepared`](Prepare::sample_prepared) with the interface's value
    /// alone in place of the sample's value (the mixture's density is the sample's): what
    /// [`finish`](Self::finish) completes, given `E` at the sampled direction. A batched loop
    /// (`LANES`) draws with [`draw_lane`](Self::draw_lane), the scalar path one lobe only.
    #[inline(always)]
    pub(crate) fn sample_unfinished<const LANES: bool>(
        &self,
        at: &CompensatedState<At<View>, f32>,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<f32>> {
        let wo = at.inner.wo;
        let p = at.probability;
        let (wi, f, pdf, lobe, eta) = if LANES {
            self.draw_lane(at, u, uc, masking)
        } else if crate::sampling::picks(uc, p) {
            let (wi, lobe, eta) = self.draw_compensation(wo.z, p, u, uc);
            let (f, pdf) = self.inner.eval_pdf_with(&at.inner, wi, masking);
            (wi, f, pdf, lobe, eta)
        } else {
            let uc = reuse_uniform(uc, p, 1.0 - p);
            let s = self.inner.sample_with(&at.inner, u, uc, masking)?;
            (s.wi, s.f, s.pdf, s.lobe, s.eta)
        };
        let pdf = (1.0 - p) * pdf + self.lobes_pdf(wo.z, p, wi.z);
        let kept = wo.z != 0.0 && lobe != Lobes::NONE && usable_pdf(pdf);
        kept.then_some(BxdfSample {
            wi,
            f,
            pdf,
            lobe,
            eta,
        })
    }

    /// A batched lane's draw, without a branch: the compensation lobes' direction and the
    /// interface's are both formed, and the one `uc` picks is evaluated, once. The
    /// interface's value and density there, and the lobe; [`Lobes::NONE`] where the
    /// interface's own sample would be refused. The same numbers as the scalar draws, for an
    /// index-matched interface too (its sample, the delta of `−wo`, chosen by a select: a
    /// branch on it in the loop, though the same for every lane, kept LLVM from vectorising
    /// the loop under AVX2).
    #[inline(always)]
    fn draw_lane(
        &self,
        at: &CompensatedState<At<View>, f32>,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> (Vec3, f32, f32, Lobes, f32) {
        let (wo, p) = (at.inner.wo, at.probability);
        let drawn = self.inner.draw(&at.inner, u, reuse_uniform(uc, p, 1.0 - p));
        let (w_ms, lobe_ms, eta_ms) = self.draw_compensation(wo.z, p, u, uc);
        let compensate = crate::sampling::picks(uc, p);
        let matched = self.inner.index_matched();
        let wi = if compensate { w_ms } else { drawn.wi };
        let e = self.inner.evaluate(&at.inner, wi, masking);
        if compensate {
            // `eval` and `pdf` of the interface: 0 for a pair no microfacet connects.
            let (f, pdf) = if e.usable { (e.f, e.pdf) } else { (0.0, 0.0) };
            (wi, f, pdf, lobe_ms, eta_ms)
        } else if matched {
            match RoughDielectric::<D>::pass_through(wo) {
                Some(s) => (s.wi, s.f, s.pdf, s.lobe, s.eta),
                None => (wi, 0.0, 0.0, Lobes::NONE, 0.0),
            }
        } else if drawn.fits(&e) && usable_pdf(e.pdf) {
            (wi, e.f, e.pdf, e.lobe, e.eta)
        } else {
            (wi, 0.0, 0.0, Lobes::NONE, 0.0)
        }
    }

    /// [`Prepare::prepare`] with `E(|cos θo|)` of `wo`'s side given by `e_wo` (called only
    /// where the compensation is on).
    #[inline(always)]
    pub(crate) fn prepare_given(
        &self,
        wo: Vec3,
        e_wo: impl FnOnce() -> f32,
    ) -> CompensatedState<At<View>, f32> {
        let inner = self.inner.prepare(wo);
        let side = self.side_of(wo.z);
        // `|`, not `||`: a branch there kept the batched `pdf` and `sample` loops from
        // vectorising under AVX2.
        let off = (wo.z == 0.0) | (side.reflect + side.transmit == 0.0);
        let outgoing = if off {
            0.0
        } else {
            (1.0 - e_wo()).clamp(0.0, 1.0)
        };
        CompensatedState {
            inner,
            outgoing,
            probability: outgoing,
        }
    }

    /// [`eval_prepared`](Prepare::eval_prepared) for a batched loop, the same numbers: `e_wi` is
    /// `E(|cos θi|)` of `wi`'s side, looked up beforehand, and no lane returns early.
    #[inline(always)]
    pub(crate) fn eval_lane(
        &self,
        at: &CompensatedState<At<View>, f32>,
        wi: Vec3,
        e_wi: f32,
        masking: Masking,
    ) -> f32 {
        let f = self.inner.eval_lane(&at.inner, wi, masking);
        f + self.lobes_value(at.inner.wo.z, at.outgoing, wi.z, e_wi)
    }

    /// [`Prepare::pdf_prepared`] for a batched loop, the same numbers, without a branch.
    #[inline(always)]
    pub(crate) fn pdf_lane(&self, at: &CompensatedState<At<View>, f32>, wi: Vec3) -> f32 {
        let pdf = self.inner.pdf_lane(&at.inner, wi);
        (1.0 - at.probability) * pdf + self.lobes_pdf(at.inner.wo.z, at.probability, wi.z)
    }

    /// A [`sample_unfinished`](Self::sample_unfinished)'s value `f` finished: plus the
    /// compensation lobes' value, for `wo` with `outgoing = (1 − E(μo), cos θo)`, at the
    /// sampled direction with `cos θi = wi_z` and `e_wi = E(μi)` of its side.
    #[inline(always)]
    pub(crate) fn finish(&self, f: f32, outgoing: (f32, f32), wi_z: f32, e_wi: f32) -> f32 {
        let (outgoing, wo_z) = outgoing;
        f + self.lobes_value(wo_z, outgoing, wi_z, e_wi)
    }
}

impl<D: NormalDistribution> Prepare for CompensatedDielectric<D> {
    type Spectrum = f32;
    type Prepared = CompensatedState<At<View>, f32>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        self.prepare_given(wo, || self.albedo.row(wo.z).e(wo.z.abs()))
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        let f = self.inner.eval_prepared(&at.inner, wi);
        f + self
            .lobes_at(at.inner.wo, at.outgoing, at.probability, wi)
            .0
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        let pdf = self.inner.pdf_prepared(&at.inner, wi);
        (1.0 - at.probability) * pdf + self.lobes_pdf(at.inner.wo.z, at.probability, wi.z)
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (f32, f32) {
        let (f, pdf) = self.inner.eval_pdf_prepared(&at.inner, wi);
        let (f_ms, pdf_ms) = self.lobes_at(at.inner.wo, at.outgoing, at.probability, wi);
        (f + f_ms, (1.0 - at.probability) * pdf + pdf_ms)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        let wo = at.inner.wo;
        // `sample_unfinished` refuses it too, but only after drawing.
        if wo.z == 0.0 {
            return None;
        }
        let masking = self.inner.masking();
        let s = self.sample_unfinished::<false>(at, u, uc, masking)?;
        let e_wi = self.albedo.row(s.wi.z).e(s.wi.z.abs());
        Some(BxdfSample {
            f: self.finish(s.f, (at.outgoing, wo.z), s.wi.z, e_wi),
            ..s
        })
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        Prepare::lobes(&self.inner)
            | Lobes::DIFFUSE_REFLECTION
            | Lobes::DIFFUSE
            | Lobes::TRANSMISSION
    }
}
