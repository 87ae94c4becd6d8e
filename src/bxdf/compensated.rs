//! Energy compensation of the microfacet reflection model: Kulla & Conty's multiple-scattering
//! lobe, or Turquin's scaling.

use super::{
    At, BxdfSample, Lobes, Microfacet, Prepare, both_above, glossy_or_diffuse, usable_pdf,
};
use crate::fresnel::{Fresnel, FresnelAverage};
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::param::ParamError;
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, reuse_uniform};
use crate::spectrum::Spectrum;
use crate::tables::{AlbedoRow, TabulatedAlbedo};
use core::f32::consts::FRAC_1_PI;
use glam::{Vec2, Vec3};

/// How [`CompensatedMicrofacet`] puts back the energy of multiple scattering.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Compensation {
    /// Kulla & Conty (2017): an added lobe, symmetric in `wo` and `wi`, so reciprocal. The
    /// default.
    #[default]
    KullaConty,
    /// Turquin (2019): the single-scattering lobe scaled by a factor of `wo` alone. Cheaper
    /// (no extra lobe to sample) and closer to a multiple-scattering reference in shape,
    /// but **not reciprocal**: `f(wo, wi) ≠ f(wi, wo)` wherever `E(μo) ≠ E(μi)`.
    Turquin,
}

/// A microfacet reflection model ([`Microfacet`]) with the energy it loses to multiple
/// scattering between microfacets put back.
///
/// A single-scattering model's directional albedo `E(μo)` (with `F = 1`) is below 1, the
/// more so the rougher the surface: GGX keeps 0.99 of the light at `α = 0.05` but 0.45 at
/// `α = 1` (60°). **Kulla & Conty** (2017, "Revisiting Physically Based Shading at
/// Imageworks", SIGGRAPH course *Physically Based Shading in Theory and Practice*) add the
/// lobe
///
/// ```text
/// f_ms(wo, wi) = F_ms · (1 − E(μo)) (1 − E(μi)) / (π (1 − E_avg)),     E_avg = 2 ∫₀¹ E(μ) μ dμ
/// F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)),                         F_avg = 2 ∫₀¹ F(μ) μ dμ
/// ```
///
/// whose albedo is `F_ms (1 − E(μo))`: with `F = 1`, `F_ms = 1` and the sum is exactly 1
/// (the white furnace); with a coloured Fresnel term, `F_ms` is the geometric series of
/// the light that bounces again with reflectance `F_avg` and escapes with `E_avg`, which
/// saturates a metal's colour as it roughens. `f_ms` is symmetric in `wo` and `wi`, so the
/// model stays reciprocal. `E` and `E_avg` are the crate's baked tables ([`crate::tables`])
/// read at the distribution's width, `F_avg` is the Fresnel term's own ([`FresnelAverage`]:
/// closed form for Schlick, quadrature for the exact conductor).
///
/// **Turquin** (2019, "Practical multiple scattering compensation for microfacet models",
/// Industrial Light & Magic technical report) scales instead: `f = f_ss · (1 + F0 (1/E(μo) − 1))`, `F0 = F(1)`. The albedo with
/// `F = 1` is again 1, but the factor depends on `wo` alone: **not reciprocal**
/// ([`Compensation::Turquin`]).
///
/// Sampling (Kulla & Conty): the compensation lobe's directions are cosine-distributed; it
/// is chosen with probability `p = F̄_ms (1 − E(μo)) / (F̄_avg E(μo) + F̄_ms (1 − E(μo)))`
/// (`F̄`: the mean over channels), the model's own sampler otherwise, and the density is
/// the mixture `(1 − p) pdf_ss + p cos θi / π`. Turquin's option keeps the model's sampler.
///
/// **Range.** The tables hold height-correlated masking
/// ([`Masking::HeightCorrelated`](crate::microfacet::Masking::HeightCorrelated), the default)
/// and `α ≤ 1`; [`new`](Self::new) refuses other masking and wider lobes.
/// Beckmann's tables use its exact `Λ`; with Walter's rational `G1` the furnace stays
/// within 1 ± 0.0036 (`|E − 1|` plus k standard errors, measured 3.2e-3 by
/// `tests/energy_compensation.rs`, `α` 0.1 to 1): the rational `G1` is within 3.2e-3 of the
/// exact one either way (it masks more below `a ≈ 0.9`, less above), so the compensated model
/// reflects from 0.21% less to 0.27% more than it receives (0.9979 ± 2.3e-4 at `α = 1`,
/// `θo = 60°`; 1.0027 ± 1.6e-4 at `α = 0.5`, `θo = 85°`).
/// [`with_albedo`](Self::with_albedo) takes a table of your own for anything else.
///
/// **Anisotropy is approximate.** An anisotropic distribution is read at its RMS width
/// `√((αx² + αy²)/2)` ([`TabulatedAlbedo`]), which matches the albedo at normal incidence
/// best of the simple means; but an anisotropic surface's albedo depends on the azimuth of
/// `wo`, which an isotropic table cannot follow. Measured furnace (GGX, `F = 1`, `θo` 0°, 60°
/// and 85° at azimuths 0, 0.8 and 1.6 rad; the estimates ± 3 standard errors): 0.975 to
/// 1.017 at `α = (0.2, 0.3)`, 0.90 to 1.036 at `(0.1, 0.4)`, 0.744 to 1.057 at
/// `(0.05, 0.8)` — above 1 near grazing along the wide axis, where the compensated model
/// **gains energy**.
///
/// Laws (measured by `tests/energy_compensation.rs`, with standard errors; the figures are
/// in the README): white furnace (`F = 1`) from 0.9997 to 1.0004 for GGX and Beckmann, `α`
/// from 0.05 to 1, `θo` from 0° to 85° (standard errors at most 4.3e-4; the bar is
/// `1 ± 0.005`), against 0.31–1.00 for single scattering; Turquin's scaling 0.9999–1.0003;
/// positive, reciprocal (Kulla & Conty's lobe; largest relative error measured 2.4e-7),
/// sampler and density agree (chi-square), `sample` equals `eval`/`pdf`. `eval` costs two
/// table lookups more (the README's cost table, from `benches/compensation.rs`).
///
/// ```
/// use lobe::bxdf::{Bxdf, Microfacet};
/// use lobe::fresnel::NoFresnel;
/// use lobe::microfacet::{Ggx, Masking};
/// use lobe::{Alpha, Vec3};
/// let single = Microfacet::new(Ggx::isotropic(Alpha::new(1.0)?), Masking::HeightCorrelated, NoFresnel::<f32>::new());
/// let compensated = single.with_energy_compensation()?;
/// let (wo, wi) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(-0.28, 0.0, 0.96));
/// assert!(compensated.eval(wo, wi) > single.eval(wo, wi)); // the energy put back
/// assert_eq!(compensated.eval(wo, wi), compensated.eval(wi, wo)); // still reciprocal
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompensatedMicrofacet<D, F: Fresnel> {
    inner: Microfacet<D, F>,
    albedo: AlbedoRow,
    compensation: Compensation,
    /// Kulla & Conty: `F_ms / (π (1 − E_avg))`; Turquin: `F0`.
    factor: F::Spectrum,
    /// `F_ms`, and the means over channels of `F_avg` and `F_ms` that weigh the lobe choice.
    f_ms: F::Spectrum,
    single_weight: f32,
    multiple_weight: f32,
}

/// What a compensated model keeps about `wo` ([`Prepare::prepare`]): the inner model's
/// prepared state, the compensation's factor at `wo` (Kulla & Conty:
/// `F_ms (1 − E(μo)) / (π (1 − E_avg))`; Turquin: `1 + F0 (1/E(μo) − 1)`) and the
/// probability with which `sample` draws the compensation lobe (`0` for Turquin's scaling),
/// which also weighs the lobes' densities in `pdf` (`eval` needs no more).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompensatedState<P, S> {
    pub(crate) inner: P,
    pub(crate) outgoing: S,
    pub(crate) probability: f32,
}

impl<D: TabulatedAlbedo, F: FresnelAverage> CompensatedMicrofacet<D, F> {
    /// `inner` compensated by `compensation`, with `E` and `E_avg` from the crate's tables at
    /// the distribution's width.
    ///
    /// # Errors
    /// [`ParamError`] naming `masking` for masking other than height-correlated (the tables'),
    /// or `alpha (compensated)` for a width above 1.
    pub fn new(inner: Microfacet<D, F>, compensation: Compensation) -> Result<Self, ParamError> {
        crate::tables::tabulated_masking(inner.masking())?;
        let albedo = inner.distribution().conductor_albedo()?;
        Ok(Self::with_albedo(inner, albedo, compensation))
    }
}

impl<D: TabulatedAlbedo, F: FresnelAverage> Microfacet<D, F> {
    /// The model with Kulla & Conty's energy compensation
    /// ([`CompensatedMicrofacet::new`] with [`Compensation::KullaConty`]).
    ///
    /// # Errors
    /// As [`CompensatedMicrofacet::new`].
    pub fn with_energy_compensation(self) -> Result<CompensatedMicrofacet<D, F>, ParamError> {
        CompensatedMicrofacet::new(self, Compensation::KullaConty)
    }
}

impl<D: NormalDistribution, F: FresnelAverage> CompensatedMicrofacet<D, F> {
    /// `inner` compensated by `compensation` with the albedo `albedo` (`E(μ)` and `E_avg` of
    /// `inner` with `F = 1`): a table of your own, for a distribution or masking the crate
    /// does not tabulate. Not checked against `inner`.
    #[must_use]
    pub fn with_albedo(
        inner: Microfacet<D, F>,
        albedo: AlbedoRow,
        compensation: Compensation,
    ) -> Self {
        let e_avg = albedo.average();
        let f_avg = inner.fresnel().average();
        // F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg)) (Kulla & Conty 2017); the
        // denominator is at least E_avg.
        let f_ms = f_avg.map(|f| {
            let den = 1.0 - f * (1.0 - e_avg);
            if den > 0.0 { f * f * e_avg / den } else { 0.0 }
        });
        let factor = match compensation {
            Compensation::KullaConty if e_avg < 1.0 => f_ms * (FRAC_1_PI / (1.0 - e_avg)),
            Compensation::KullaConty => F::Spectrum::zero(),
            Compensation::Turquin => inner.fresnel().eval(1.0),
        };
        Self {
            inner,
            albedo,
            compensation,
            factor,
            f_ms,
            single_weight: f_avg.average(),
            multiple_weight: f_ms.average(),
        }
    }

    /// The single-scattering model.
    #[inline]
    #[must_use]
    pub fn inner(&self) -> &Microfacet<D, F> {
        &self.inner
    }

    /// The albedo `E(μ)`, `E_avg` the compensation reads.
    #[inline]
    #[must_use]
    pub fn albedo(&self) -> &AlbedoRow {
        &self.albedo
    }

    getters! {
        /// Which compensation.
        compensation: Compensation,
    }

    /// Kulla & Conty's `F_ms = F_avg² E_avg / (1 − F_avg (1 − E_avg))`: the colour of the
    /// multiply scattered light (1 for `F = 1`).
    #[inline]
    #[must_use]
    pub fn multiple_scattering_fresnel(&self) -> F::Spectrum {
        self.f_ms
    }

    /// The probability of sampling the compensation lobe when the single-scattering lobe
    /// loses `share = 1 − E(μo)`:
    /// `F̄_ms share / (F̄_avg (1 − share) + F̄_ms share)`.
    #[inline(always)]
    fn probability(&self, share: f32) -> f32 {
        let ms = self.multiple_weight * share;
        let total = ms + self.single_weight * (1.0 - share);
        if total > 0.0 { ms / total } else { 0.0 }
    }

    /// Turquin's scaling of a single-scattering value `f` by the factor at `wo`, held finite:
    /// `f` may be `f32::MAX` already (a grazing mirror pair of a narrow lobe under V-cavity
    /// masking, where `Microfacet` clamps), and the factor is at least 1.
    #[inline(always)]
    fn turquin(f: F::Spectrum, outgoing: F::Spectrum) -> F::Spectrum {
        (f * outgoing).map(|v| v.min(f32::MAX))
    }

    /// [`Prepare::prepare`] with `E(μo)` from `e_wo` (called only for `wo` above the
    /// surface): the table's value there, or, in a batched loop, that value looked up for a
    /// chunk of lanes beforehand ([`AlbedoRow::e_chunk`]).
    #[inline(always)]
    pub(crate) fn prepare_given(
        &self,
        wo: Vec3,
        e_wo: impl FnOnce() -> f32,
    ) -> CompensatedState<At<View>, F::Spectrum> {
        let inner = self.inner.prepare(wo);
        let e = if wo.z > 0.0 { e_wo() } else { 1.0 };
        let (outgoing, share) = match self.compensation {
            Compensation::KullaConty => (self.factor * (1.0 - e), 1.0 - e),
            Compensation::Turquin => {
                // E below 1e-4 (only a table of your own has it) is held there, so that the
                // factor stays finite.
                let scale = if e > 0.0 {
                    1.0 / e.max(1e-4) - 1.0
                } else {
                    0.0
                };
                (F::Spectrum::one() + self.factor * scale, 0.0)
            }
        };
        CompensatedState {
            inner,
            outgoing,
            probability: self.probability(share),
        }
    }

    /// The inner model's masking term (what a batched loop fixes outside the loop).
    #[inline(always)]
    pub(crate) fn masking(&self) -> Masking {
        self.inner.masking()
    }

    /// [`Prepare::eval_prepared`] with the inner model's masking term `masking` and, for a
    /// batched loop, its Fresnel term channel by channel (`PER_CHANNEL`: the same numbers;
    /// see [`Microfacet`]'s `value`).
    #[inline(always)]
    pub(crate) fn eval_with<const PER_CHANNEL: bool>(
        &self,
        at: &CompensatedState<At<View>, F::Spectrum>,
        wi: Vec3,
        masking: Masking,
    ) -> F::Spectrum {
        let e_wi = || self.albedo.e(wi.z);
        self.eval_given::<PER_CHANNEL>(at, wi, masking, self.compensation, e_wi)
    }

    /// [`eval_with`](Self::eval_with) with `E(μi)` from `e_wi` (called only for a pair above
    /// the surface), as [`prepare_given`](Self::prepare_given) takes `E(μo)`, and the
    /// compensation a parameter, as [`sample_compensated`](Self::sample_compensated) takes it.
    #[inline(always)]
    pub(crate) fn eval_given<const PER_CHANNEL: bool>(
        &self,
        at: &CompensatedState<At<View>, F::Spectrum>,
        wi: Vec3,
        masking: Masking,
        compensation: Compensation,
        e_wi: impl FnOnce() -> f32,
    ) -> F::Spectrum {
        let f = self.inner.eval_with::<PER_CHANNEL>(&at.inner, wi, masking);
        match compensation {
            Compensation::KullaConty if both_above(at.inner.wo, wi) => {
                self.finish(f, at.outgoing, e_wi())
            }
            Compensation::KullaConty => f,
            Compensation::Turquin => Self::turquin(f, at.outgoing),
        }
    }

    /// [`Prepare::eval_pdf_prepared`] under `masking` (and `PER_CHANNEL`, as
    /// [`eval_with`](Self::eval_with)).
    #[inline(always)]
    pub(crate) fn eval_pdf_with<const PER_CHANNEL: bool>(
        &self,
        at: &CompensatedState<At<View>, F::Spectrum>,
        wi: Vec3,
        masking: Masking,
    ) -> (F::Spectrum, f32) {
        let (f, pdf) = self
            .inner
            .eval_pdf_with::<PER_CHANNEL>(&at.inner, wi, masking);
        let p = at.probability;
        match self.compensation {
            Compensation::KullaConty if both_above(at.inner.wo, wi) => (
                self.finish(f, at.outgoing, self.albedo.e(wi.z)),
                Self::mixture_pdf(at, pdf, wi.z),
            ),
            Compensation::KullaConty => (f, (1.0 - p) * pdf),
            Compensation::Turquin => (Self::turquin(f, at.outgoing), pdf),
        }
    }

    /// Kulla & Conty's value for `wo`, `wi` above the surface: the single-scattering value
    /// `f` plus the compensation lobe's, `outgoing · (1 − E(μi))`, from the factor `outgoing`
    /// at `wo` and `E(μi)` at `wi` (for `eval`, and for a sample that
    /// [`sample_compensated`](Self::sample_compensated) left unfinished).
    #[inline(always)]
    pub(crate) fn finish(&self, f: F::Spectrum, outgoing: F::Spectrum, e_wi: f32) -> F::Spectrum {
        f + outgoing * (1.0 - e_wi)
    }

    /// Kulla & Conty's density for `wo`, `wi` above the surface: the single-scattering lobe's
    /// density `pdf` and the compensation lobe's cosine-weighted one at `cos θi = cos_i`,
    /// mixed by the probability of drawing the compensation lobe.
    #[inline(always)]
    pub(crate) fn mixture_pdf(
        at: &CompensatedState<At<View>, F::Spectrum>,
        pdf: f32,
        cos_i: f32,
    ) -> f32 {
        let p = at.probability;
        (1.0 - p) * pdf + p * cosine_hemisphere_pdf(cos_i)
    }

    /// What a batched lane of [`sample_compensated`](Self::sample_compensated) draws for `u`:
    /// the compensation lobe's cosine-weighted direction where `diffuse`, else `wo` reflected
    /// about a normal drawn from the distribution (both formed, one kept, so that a loop has
    /// no branch between lobes), and the single-scattering lobe's value and density there,
    /// evaluated without early returns (zeros for an unusable pair).
    #[inline(always)]
    pub(crate) fn draw_lane(
        &self,
        at: &CompensatedState<At<View>, F::Spectrum>,
        u: Vec2,
        diffuse: bool,
        masking: Masking,
    ) -> (Vec3, F::Spectrum, f32) {
        let inner = &self.inner;
        let (cosine, reflected) = (cosine_hemisphere(u), inner.sample_direction(&at.inner, u));
        let wi = if diffuse { cosine } else { reflected };
        let (f, pdf) = inner.eval_pdf_lane::<true>(&at.inner, wi, masking);
        (wi, f, pdf)
    }

    /// [`Prepare::sample_prepared`] under `masking` and `compensation` (the model's: a
    /// parameter so that a batched loop can fix it outside the loop, as `masking`; with the
    /// branch between the two in the loop, LLVM weighs both samplers in every lane, and
    /// leaves the loop scalar for a costly Fresnel term, the exact conductor's).
    ///
    /// `LANES` is the form for a batched loop: every lane draws both lobes' directions and
    /// keeps the one its `uc` picks ([`draw_lane`](Self::draw_lane)), so that the loop has no
    /// branch between lobes and vectorises, and the Fresnel term is taken channel by channel.
    /// The same numbers as the scalar form: the single-scattering lobe's `sample` is its
    /// `eval_pdf` at the direction it draws, refused where that density is unusable.
    ///
    /// Unless `FINISH`, under Kulla & Conty's compensation the sample's `f` is the
    /// single-scattering lobe's value alone, to [`finish`](Self::finish) with the table's
    /// `E(μi)` at the sampled direction, which a batched loop looks up for a chunk of lanes in
    /// between; under Turquin's scaling the sample is complete either way. (The scalar path
    /// finishes here, in the tail: finished by its caller instead, the scalar `sample` took
    /// 8–10% longer.)
    #[inline(always)]
    pub(crate) fn sample_compensated<const LANES: bool, const FINISH: bool>(
        &self,
        at: &CompensatedState<At<View>, F::Spectrum>,
        u: Vec2,
        uc: f32,
        masking: Masking,
        compensation: Compensation,
    ) -> Option<BxdfSample<F::Spectrum>> {
        let inner = &self.inner;
        if compensation == Compensation::Turquin {
            let mut s = inner.sample_with::<LANES>(&at.inner, u, uc, masking)?;
            s.f = Self::turquin(s.f, at.outgoing);
            return Some(s);
        }
        if !(at.inner.wo.z > 0.0) {
            return None;
        }
        let p = at.probability;
        let diffuse = crate::sampling::picks(uc, p);
        // The single-scattering lobe's value and density at wi: from its own sample when it
        // drew wi (the numbers its eval and pdf give), else evaluated together.
        let (wi, f, pdf, lobe) = if LANES {
            let (wi, f, pdf) = self.draw_lane(at, u, diffuse, masking);
            if !diffuse && !usable_pdf(pdf) {
                return None;
            }
            (wi, f, pdf, glossy_or_diffuse(!diffuse))
        } else if diffuse {
            let wi = cosine_hemisphere(u);
            let (f, pdf) = inner.eval_pdf_with::<false>(&at.inner, wi, masking);
            (wi, f, pdf, Lobes::DIFFUSE_REFLECTION)
        } else {
            let uc = reuse_uniform(uc, p, 1.0 - p);
            let s = inner.sample_with::<false>(&at.inner, u, uc, masking)?;
            (s.wi, s.f, s.pdf, s.lobe)
        };
        if !(wi.z > 0.0) {
            return None;
        }
        let pdf = Self::mixture_pdf(at, pdf, wi.z);
        if !usable_pdf(pdf) {
            return None;
        }
        let f = if FINISH {
            self.finish(f, at.outgoing, self.albedo.e(wi.z))
        } else {
            f
        };
        Some(BxdfSample::new(wi, f, pdf, lobe))
    }
}

impl<D: NormalDistribution, F: FresnelAverage> Prepare for CompensatedMicrofacet<D, F> {
    type Spectrum = F::Spectrum;
    type Prepared = CompensatedState<At<View>, F::Spectrum>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        self.prepare_given(wo, || self.albedo.e(wo.z))
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> F::Spectrum {
        self.eval_with::<false>(at, wi, self.inner.masking())
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        let pdf = self.inner.pdf_prepared(&at.inner, wi);
        let p = at.probability;
        if p > 0.0 && both_above(at.inner.wo, wi) {
            Self::mixture_pdf(at, pdf, wi.z)
        } else {
            (1.0 - p) * pdf
        }
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (F::Spectrum, f32) {
        self.eval_pdf_with::<false>(at, wi, self.inner.masking())
    }

    #[inline(always)]
    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<F::Spectrum>> {
        let (masking, compensation) = (self.inner.masking(), self.compensation);
        self.sample_compensated::<false, true>(at, u, uc, masking, compensation)
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        match self.compensation {
            Compensation::KullaConty => Prepare::lobes(&self.inner) | Lobes::DIFFUSE_REFLECTION,
            Compensation::Turquin => Prepare::lobes(&self.inner),
        }
    }
}
