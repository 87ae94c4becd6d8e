//! A diffuse base under a rough dielectric coat: the glazed material's rough variant.

use super::{
    At, Bxdf, BxdfSample, CompensatedMicrofacet, CompensatedState, Compensation, Lobes, Microfacet,
    Prepare, both_above, glossy_or_diffuse, usable_pdf,
};
use crate::fresnel::Dielectric;
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::param::{Eta, ParamError, unit_interval};
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, reuse_uniform};
use crate::spectrum::Spectrum;
use crate::tables::{TabulatedDielectric, node_below};
use core::f32::consts::FRAC_1_PI;
use core::marker::PhantomData;
use glam::{Vec2, Vec3};

/// Entries of the coat's albedo table, over `cos θ ∈ [0, 1]`.
const TABLE: usize = 32;
/// Stratified samples per axis when integrating the coat's albedo.
const STRATA: usize = 48;
/// The margin added to the tabulated coat albedo, above its quadrature error (about 3.5e-4,
/// measured against Monte Carlo by `tests/bxdf_coated.rs`), so that the diffuse weight never
/// lets the sum exceed 1.
const MARGIN: f32 = 1e-3;

/// A diffuse base of reflectance `ρ` under a rough dielectric coat (plastic, varnish): the
/// coat reflects through a [`Microfacet`] lobe `f_s` with the exact dielectric Fresnel term,
/// and the base's diffuse light is weighted by the coat's transmitted energy:
///
/// ```text
/// f = f_s(wo, wi) + ρ/π · (1 − E(cos θo)) (1 − E(cos θi)) / (1 − Ē),   Ē = 2 ∫₀¹ E(μ) μ dμ
/// ```
///
/// where `E(μ)` is the coat's directional albedo, tabulated at construction. This is the
/// coupling of Kelemen & Szirmay-Kalos (2001, eq. 5) with the coat's exact albedo in place of
/// its Fresnel factor: the directional albedo is `E(cos θo) + (1 − E(cos θo)) ρ`, at most 1.
/// The table's entries carry a margin of 1e-3 over their quadrature error, so that the sum
/// stays below 1 (the white-furnace albedo with `ρ = 1` is `1 − ~1e-3`). Reciprocal: both
/// terms are symmetric. Construction integrates the coat's albedo at 32 angles with
/// 48 × 48 stratified samples each (about 70 000 evaluations).
///
/// Sampling: the coat's lobe with probability `E / (E + (1 − E) ρ̄)`, cosine-weighted
/// directions otherwise; the density is the mixture of both.
///
/// **The compensated coat** ([`Plastic::compensated`], the type
/// `Plastic<D, S, CompensatedMicrofacet<D, Dielectric>>`): the coat is
/// [`CompensatedMicrofacet`] — Kulla & Conty's multiple-scattering lobe with the dielectric's
/// `F_ms` added to the coat's reflection — and its albedo `E(μ) = R(μ) + F_ms (1 − E₁(μ))`
/// comes from the crate's baked tables (`R`: the coat's reflection, `E₁`: the `F = 1`
/// albedo; [`crate::tables`]) without a margin, so the white furnace with `ρ = 1` is 1 to
/// the tables' interpolation error: measured from 0.9996 to 1.0013 (GGX, `η` 1.33 to 2,
/// `α` 0.05 to 1, `θo` up to 85°; `tests/energy_compensation.rs`).
#[derive(Debug, PartialEq)]
pub struct Plastic<D, S = f32, C = Microfacet<D, Dielectric>> {
    coat: C,
    reflectance: S,
    /// The coat's directional albedo (plus the margin) at `cos θ = i / (TABLE − 1)`.
    coat_albedo: [f32; TABLE],
    /// `1 / (π (1 − Ē))`.
    diffuse_scale: f32,
    /// The reflectance's channel average, for the lobe choice (stored: for RGB it is a
    /// division).
    mean_reflectance: f32,
    distribution: PhantomData<D>,
}

// Written out rather than derived: a derive would ask `D: Clone` for the `PhantomData` alone;
// the coat `C`, which holds the distribution, says whether it can be cloned.
impl<D, S: Clone, C: Clone> Clone for Plastic<D, S, C> {
    #[inline]
    fn clone(&self) -> Self {
        Self {
            coat: self.coat.clone(),
            reflectance: self.reflectance.clone(),
            coat_albedo: self.coat_albedo,
            diffuse_scale: self.diffuse_scale,
            mean_reflectance: self.mean_reflectance,
            distribution: PhantomData,
        }
    }
}

impl<D, S: Copy, C: Copy> Copy for Plastic<D, S, C> {}

impl<D: NormalDistribution, S: Spectrum> Plastic<D, S> {
    /// A plastic with base reflectance `ρ ∈ [0, 1]` under a coat of relative index `eta`
    /// whose roughness is the distribution `distribution` (height-correlated Smith masking).
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`.
    pub fn new(reflectance: S, distribution: D, eta: Eta) -> Result<Self, ParamError> {
        let coat = Microfacet::new(distribution, Masking::HeightCorrelated, Dielectric { eta });
        Self::with_coat(reflectance, coat, |coat, mu| {
            (coat_directional_albedo(coat, mu.max(1e-3)) + MARGIN).min(1.0)
        })
    }
    /// The coat's distribution of microfacet normals.
    #[inline]
    #[must_use]
    pub fn distribution(&self) -> &D {
        self.coat.distribution()
    }

    /// The coat's relative index `η_inside / η_outside`.
    #[inline]
    #[must_use]
    pub fn eta(&self) -> Eta {
        self.coat.fresnel().eta
    }
}

impl<D: TabulatedDielectric, S: Spectrum> Plastic<D, S, CompensatedMicrofacet<D, Dielectric>> {
    /// A plastic whose coat is energy-compensated (Kulla & Conty 2017): base reflectance
    /// `ρ ∈ [0, 1]` under a coat of relative index `eta ∈ [1.01, 3]` whose roughness is
    /// `distribution` (GGX, `α ≤ 1`), the coat's albedo from the crate's tables.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel outside `[0, 1]`,
    /// `alpha (compensated)` or `eta (compensated)` outside the tables.
    pub fn compensated(reflectance: S, distribution: D, eta: Eta) -> Result<Self, ParamError> {
        let reflection = distribution.coat_albedo(eta)?;
        let coat = CompensatedMicrofacet::new(
            Microfacet::new(distribution, Masking::HeightCorrelated, Dielectric { eta }),
            Compensation::KullaConty,
        )?;
        let (single, f_ms) = (*coat.albedo(), coat.multiple_scattering_fresnel());
        Self::with_coat(reflectance, coat, |_, mu| {
            (reflection.e(mu) + f_ms * (1.0 - single.e(mu))).clamp(0.0, 1.0)
        })
    }

    /// The coat's distribution of microfacet normals.
    #[inline]
    #[must_use]
    pub fn distribution(&self) -> &D {
        self.coat.inner().distribution()
    }

    /// The coat's relative index `η_inside / η_outside`.
    #[inline]
    #[must_use]
    pub fn eta(&self) -> Eta {
        self.coat.inner().fresnel().eta
    }
}

impl<D, S: Spectrum, C> Plastic<D, S, C> {
    /// The plastic with the coat `coat`, whose directional albedo is `coat_albedo(coat, μ)`.
    fn with_coat(
        reflectance: S,
        coat: C,
        coat_albedo: impl Fn(&C, f32) -> f32,
    ) -> Result<Self, ParamError> {
        let reflectance = unit_interval("reflectance", reflectance)?;
        let mut table = [0.0; TABLE];
        for (i, e) in table.iter_mut().enumerate() {
            *e = coat_albedo(&coat, i as f32 / (TABLE - 1) as f32);
        }
        let mut plastic = Self {
            coat,
            reflectance,
            coat_albedo: table,
            diffuse_scale: 0.0,
            mean_reflectance: reflectance.average(),
            distribution: PhantomData,
        };
        let e_avg = crate::fresnel::cosine_weighted_average(|mu| plastic.coat_albedo_at(mu));
        plastic.diffuse_scale = if e_avg < 1.0 {
            FRAC_1_PI / (1.0 - e_avg)
        } else {
            0.0
        };
        Ok(plastic)
    }

    /// The coat's tabulated directional albedo `E(μ)` (with its margin).
    #[inline]
    #[must_use]
    pub fn coat_albedo_at(&self, cos_theta: f32) -> f32 {
        let (i, f) = node_below(cos_theta.clamp(0.0, 1.0) * (TABLE - 1) as f32, TABLE - 2);
        self.coat_albedo_between(i as usize, f)
    }

    /// The table's interpolant at the fraction `f` of the way from node `i` to node `i + 1`
    /// (`f ∈ [0, 1]`, or `−0` or NaN, as [`node_below`] gives them).
    #[inline(always)]
    fn coat_albedo_between(&self, i: usize, f: f32) -> f32 {
        let i = i.min(TABLE - 2);
        self.coat_albedo[i] + f * (self.coat_albedo[i + 1] - self.coat_albedo[i])
    }

    /// [`coat_albedo_at`](Self::coat_albedo_at) of every `cos_theta[k]`, into `e[k]` (at most
    /// `L` lanes), in two passes as [`AlbedoRow`](crate::tables::AlbedoRow)'s chunked
    /// lookup: the positions, which vectorise, then the reads (for a batched loop).
    #[inline(always)]
    pub(crate) fn coat_albedo_chunk<const L: usize>(&self, cos_theta: &[f32], e: &mut [f32; L]) {
        debug_assert!(cos_theta.len() <= L);
        let mut node = [0_u32; L];
        for ((&c, e), node) in cos_theta.iter().zip(e.iter_mut()).zip(node.iter_mut()) {
            (*node, *e) = node_below(c.clamp(0.0, 1.0) * (TABLE - 1) as f32, TABLE - 2);
        }
        for (e, &i) in e.iter_mut().zip(&node).take(cos_theta.len()) {
            *e = self.coat_albedo_between(i as usize, *e);
        }
    }

    /// The diffuse term for `wo`, `wi` above the surface, with `t_o = 1 − E(cos θo)` and
    /// `e_wi = E(cos θi)`.
    #[inline]
    fn diffuse(&self, t_o: f32, e_wi: f32) -> S {
        let t = t_o * (1.0 - e_wi);
        self.reflectance * (t * self.diffuse_scale)
    }

    /// The probability of sampling the coat's lobe, given the coat's albedo `e` at `wo`.
    #[inline]
    fn coat_probability(&self, e: f32) -> f32 {
        let total = e + (1.0 - e) * self.mean_reflectance;
        if total > 0.0 { e / total } else { 1.0 }
    }

    getters! {
        /// The diffuse base's reflectance.
        reflectance: S,
    }
}

/// A [`Plastic`] with the energy-compensated coat ([`Plastic::compensated`]).
pub type CompensatedPlastic<D, S = f32> = Plastic<D, S, CompensatedMicrofacet<D, Dielectric>>;

/// What [`Plastic`] keeps about `wo` ([`Prepare::prepare`]): the coat's prepared state, the
/// probability of sampling the coat and the coat's transmittance `1 − E(cos θo)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlasticState<C> {
    coat: C,
    p_coat: f32,
    t_o: f32,
}

/// The coat's directional albedo at `cos θo = mu`, by its own sampler on a stratified grid.
fn coat_directional_albedo<D: NormalDistribution>(
    coat: &Microfacet<D, Dielectric>,
    mu: f32,
) -> f32 {
    let wo = Vec3::new(crate::math::safe_sqrt(1.0 - mu * mu), 0.0, mu);
    let mut sum = 0.0;
    for a in 0..STRATA {
        for b in 0..STRATA {
            let u = Vec2::new(
                (a as f32 + 0.5) / STRATA as f32,
                (b as f32 + 0.5) / STRATA as f32,
            );
            if let Some(s) = coat.sample(wo, u, 0.5) {
                sum += s.weight();
            }
        }
    }
    sum / (STRATA * STRATA) as f32
}

impl<D, S: Spectrum, C: Prepare<Spectrum = f32>> Plastic<D, S, C> {
    /// The coat.
    #[inline(always)]
    pub(crate) fn coat(&self) -> &C {
        &self.coat
    }

    /// [`Prepare::prepare`] with the coat's albedo at `wo` given as `e` and the coat's
    /// prepared state as `coat` (a batched loop looks the tables they read up beforehand).
    #[inline(always)]
    pub(crate) fn prepare_given(
        &self,
        wo: Vec3,
        e: f32,
        coat: C::Prepared,
    ) -> At<PlasticState<C::Prepared>> {
        At {
            wo,
            state: PlasticState {
                coat,
                p_coat: self.coat_probability(e),
                t_o: 1.0 - e,
            },
        }
    }

    /// [`Prepare::eval_prepared`].
    #[inline(always)]
    fn eval_with(&self, at: &At<PlasticState<C::Prepared>>, wi: Vec3) -> S {
        if !both_above(at.wo, wi) {
            return S::zero();
        }
        let coat_f = self.coat.eval_prepared(&at.state.coat, wi);
        self.eval_given(at, wi, coat_f, self.coat_albedo_at(wi.z))
    }

    /// [`eval_with`](Self::eval_with) with the coat's value `coat_f` and its albedo `e_wi` at
    /// `wi` given (a batched loop evaluates the coat in every lane and looks the table up
    /// beforehand): zero unless both directions are above the surface. (The coat's value is
    /// a number, not a closure: with the coat's evaluation in a closure, LLVM kept it out of
    /// line and the scalar `eval` took twice as long.)
    #[inline(always)]
    pub(crate) fn eval_given(
        &self,
        at: &At<PlasticState<C::Prepared>>,
        wi: Vec3,
        coat_f: f32,
        e_wi: f32,
    ) -> S {
        if !both_above(at.wo, wi) {
            return S::zero();
        }
        S::splat(coat_f) + self.diffuse(at.state.t_o, e_wi)
    }

    /// The coat's prepared state within the plastic's.
    #[inline(always)]
    pub(crate) fn coat_state(at: &At<PlasticState<C::Prepared>>) -> &C::Prepared {
        &at.state.coat
    }

    /// The plastic's density for `wo`, `wi` above the surface: the coat's density `coat_pdf`
    /// and the cosine-weighted one at `cos θi = cos_i`, mixed by the probability of sampling
    /// the coat.
    #[inline(always)]
    fn mixture_pdf(st: &PlasticState<C::Prepared>, coat_pdf: f32, cos_i: f32) -> f32 {
        st.p_coat * coat_pdf + (1.0 - st.p_coat) * cosine_hemisphere_pdf(cos_i)
    }

    /// [`Prepare::eval_pdf_prepared`].
    #[inline(always)]
    fn eval_pdf_with(&self, at: &At<PlasticState<C::Prepared>>, wi: Vec3) -> (S, f32) {
        if !both_above(at.wo, wi) {
            return (S::zero(), 0.0);
        }
        let st = &at.state;
        let (coat_f, coat_pdf) = self.coat.eval_pdf_prepared(&st.coat, wi);
        (
            S::splat(coat_f) + self.diffuse(st.t_o, self.coat_albedo_at(wi.z)),
            Self::mixture_pdf(st, coat_pdf, wi.z),
        )
    }

    /// [`Prepare::sample_prepared`].
    #[inline(always)]
    fn sample_with(
        &self,
        at: &At<PlasticState<C::Prepared>>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<S>> {
        let s = self.sample_unfinished(at, u, uc)?;
        let e_wi = self.coat_albedo_at(s.wi.z);
        Some(BxdfSample {
            f: self.finish(s.f, at.state.t_o, e_wi),
            ..s
        })
    }

    /// [`sample_with`](Self::sample_with) but for the diffuse term, which needs the coat's
    /// albedo at the sampled direction: the sample's `f` is the coat's value alone, to
    /// [`finish`](Self::finish). Its batched form is [`sample_lane`](Self::sample_lane)
    /// (whose samples a batched loop finishes after looking the albedo up for a chunk of
    /// lanes).
    #[inline(always)]
    fn sample_unfinished(
        &self,
        at: &At<PlasticState<C::Prepared>>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<S>> {
        if !(at.wo.z > 0.0) {
            return None;
        }
        let st = &at.state;
        // The coat's value and density at wi: from its own sample when it drew wi (the same
        // numbers its eval and pdf give), else evaluated together with one D.
        let (wi, coat_f, coat_pdf, lobe) = if crate::sampling::picks(uc, st.p_coat) {
            // The coat's own lobe choice (a compensated coat has two, its multiple-scattering
            // lobe diffuse), from what is left of uc, and the coat's label for it.
            let s = self
                .coat
                .sample_prepared(&st.coat, u, reuse_uniform(uc, 0.0, st.p_coat))?;
            (s.wi, s.f, s.pdf, s.lobe)
        } else {
            let wi = cosine_hemisphere(u);
            let (f, pdf) = self.coat.eval_pdf_prepared(&st.coat, wi);
            (wi, f, pdf, Lobes::DIFFUSE_REFLECTION)
        };
        self.drawn(st, wi, coat_f, coat_pdf, lobe)
    }

    /// The unfinished sample of the direction `wi`, drawn from `lobe`, at which the coat's
    /// value and density are `coat_f` and `coat_pdf`: its density is the mixture's; none
    /// below the surface or where that density is unusable.
    #[inline(always)]
    fn drawn(
        &self,
        st: &PlasticState<C::Prepared>,
        wi: Vec3,
        coat_f: f32,
        coat_pdf: f32,
        lobe: Lobes,
    ) -> Option<BxdfSample<S>> {
        if !(wi.z > 0.0) {
            return None;
        }
        let pdf = Self::mixture_pdf(st, coat_pdf, wi.z);
        if !usable_pdf(pdf) {
            return None;
        }
        Some(BxdfSample::new(wi, S::splat(coat_f), pdf, lobe))
    }

    /// The value of a sample for `wo`, `wi` above the surface from the coat's value in `f`
    /// (as [`sample_unfinished`](Self::sample_unfinished) leaves it), the coat's
    /// transmittance `t_o` at `wo` and its albedo `e_wi` at `wi`: `f` plus the diffuse term.
    #[inline(always)]
    pub(crate) fn finish(&self, f: S, t_o: f32, e_wi: f32) -> S {
        f + self.diffuse(t_o, e_wi)
    }

    /// The coat's transmittance `1 − E(cos θo)` at the prepared `wo` (what
    /// [`finish`](Self::finish) needs of the prepared state).
    #[inline(always)]
    pub(crate) fn transmittance(at: &At<PlasticState<C::Prepared>>) -> f32 {
        at.state.t_o
    }
}

/// How a plastic's batched lane draws from its coat: without a branch between the lobes, so
/// that the loop vectorises ([`Plastic::sample_lane`]).
pub(crate) trait LaneCoat: Prepare<Spectrum = f32> {
    /// For a lane that picked the coat's lobe (`coat`) or the plastic's diffuse lobe (the
    /// cosine-weighted direction for `u`): the direction, the coat's value (unfinished, for a
    /// coat that reads a table at it) and density there, and whether the coat's glossy lobe
    /// drew it; `None` where the coat's own sample refuses it (and, for the compensated coat,
    /// any direction below the surface, which the plastic refuses anyway). `uc` is what is
    /// left of the plastic's random number for the coat's own choice of lobe.
    fn draw_lane(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
        coat: bool,
        masking: Masking,
    ) -> Option<(Vec3, f32, f32, bool)>;
}

/// The plain coat: one glossy lobe, its sample the lobe's `eval_pdf` at the direction it
/// draws, refused where that density is unusable.
impl<D: NormalDistribution> LaneCoat for Microfacet<D, Dielectric> {
    #[inline(always)]
    fn draw_lane(
        &self,
        at: &At<View>,
        u: Vec2,
        _uc: f32,
        coat: bool,
        masking: Masking,
    ) -> Option<(Vec3, f32, f32, bool)> {
        let reflected = self.sample_direction(at, u);
        let wi = if coat {
            reflected
        } else {
            cosine_hemisphere(u)
        };
        let (f, pdf) = self.eval_pdf_lane::<true>(at, wi, masking);
        if coat && !usable_pdf(pdf) {
            return None;
        }
        Some((wi, f, pdf, coat))
    }
}

/// The compensated coat (Kulla & Conty's compensation, the constructor's): its compensation
/// lobe and the plastic's diffuse lobe draw the same cosine-weighted direction, so a lane
/// forms it and the reflected one, keeps one and evaluates the single-scattering lobe there
/// once ([`CompensatedMicrofacet::draw_lane`]); the value is left for the compensation lobe's.
impl<D: NormalDistribution> LaneCoat for CompensatedMicrofacet<D, Dielectric> {
    #[inline(always)]
    fn draw_lane(
        &self,
        at: &CompensatedState<At<View>, f32>,
        u: Vec2,
        uc: f32,
        coat: bool,
        masking: Masking,
    ) -> Option<(Vec3, f32, f32, bool)> {
        let glossy = coat & !crate::sampling::picks(uc, at.probability);
        let (wi, f, pdf) = self.draw_lane(at, u, !glossy, masking);
        // The coat's own sample refuses its reflected direction where the single-scattering
        // density is unusable, and any direction where its mixture's is; the plastic's diffuse
        // lobe takes the coat's value and density as they are (the plastic's mixture decides).
        if glossy && !usable_pdf(pdf) {
            return None;
        }
        if !(wi.z > 0.0) {
            return None;
        }
        let pdf = Self::mixture_pdf(at, pdf, wi.z);
        if coat && !usable_pdf(pdf) {
            return None;
        }
        Some((wi, f, pdf, glossy))
    }
}

impl<D, S: Spectrum, C: Prepare<Spectrum = f32>> Plastic<D, S, C> {
    /// [`sample_unfinished`](Self::sample_unfinished) for a batched loop, with the coat's
    /// masking term `masking`: every lane forms the directions of the lobes it might pick and
    /// keeps one ([`LaneCoat`]), so that the loop has no branch between lobes and vectorises.
    /// The same numbers as the scalar form (`tests/batch.rs` compares them bit for bit).
    #[inline(always)]
    pub(crate) fn sample_lane(
        &self,
        at: &At<PlasticState<C::Prepared>>,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<S>>
    where
        C: LaneCoat,
    {
        if !(at.wo.z > 0.0) {
            return None;
        }
        let st = &at.state;
        let coat = crate::sampling::picks(uc, st.p_coat);
        let uc = reuse_uniform(uc, 0.0, st.p_coat);
        let (wi, f, pdf, glossy) = self.coat.draw_lane(&st.coat, u, uc, coat, masking)?;
        self.drawn(st, wi, f, pdf, glossy_or_diffuse(glossy))
    }
}

impl<D: NormalDistribution, S: Spectrum> CompensatedPlastic<D, S> {
    /// What [`finish_compensated`](Self::finish_compensated) needs of the prepared state:
    /// the coat's transmittance and its compensation factor at `wo`.
    #[inline(always)]
    pub(crate) fn finishing_state(
        at: &At<PlasticState<CompensatedState<At<View>, f32>>>,
    ) -> (f32, f32) {
        (at.state.t_o, at.state.coat.outgoing)
    }

    /// The value of a sample that [`sample_lane`](Self::sample_lane) left unfinished, from
    /// the coat's single-scattering value in `f`, the coat's transmittance `t_o` and its
    /// compensation factor `outgoing` at `wo`, and at the sampled direction the plastic's
    /// coat albedo `e_wi` and the coat's own table's `E(μi)`, `coat_e_wi`: the coat's
    /// compensation lobe added to its value, then the diffuse term.
    #[inline(always)]
    pub(crate) fn finish_compensated(
        &self,
        f: S,
        (t_o, outgoing): (f32, f32),
        (e_wi, coat_e_wi): (f32, f32),
    ) -> S {
        // `f` is the coat's value in every channel.
        let coat_f = self.coat.finish(f.channel(0), outgoing, coat_e_wi);
        self.finish(S::splat(coat_f), t_o, e_wi)
    }
}

impl<D, S: Spectrum, C: Prepare<Spectrum = f32>> Prepare for Plastic<D, S, C> {
    type Spectrum = S;
    type Prepared = At<PlasticState<C::Prepared>>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        self.prepare_given(wo, self.coat_albedo_at(wo.z), self.coat.prepare(wo))
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> S {
        self.eval_with(at, wi)
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        if !both_above(at.wo, wi) {
            return 0.0;
        }
        let st = &at.state;
        Self::mixture_pdf(st, self.coat.pdf_prepared(&st.coat, wi), wi.z)
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (S, f32) {
        self.eval_pdf_with(at, wi)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<S>> {
        self.sample_with(at, u, uc)
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION | Lobes::GLOSSY_REFLECTION
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::microfacet::Ggx;
    use crate::param::Alpha;
    use crate::tables::CHUNK;
    use std::vec::Vec;

    fn plastic() -> Plastic<Ggx, f32> {
        let ggx = Ggx::isotropic(Alpha::new(0.3).unwrap());
        Plastic::new(0.5, ggx, Eta::new(1.5).unwrap()).unwrap()
    }

    /// Cosines at and within three ulps of every node, halfway between nodes (where rounding
    /// to the nearest whole number ties), on a grid of step 10⁻⁵, outside `[0, 1]`, and NaN.
    fn cosines() -> Vec<f32> {
        let mut c = std::vec![-1.0, -0.0, 0.0, 1.0, 1.5, f32::INFINITY, f32::NEG_INFINITY];
        c.push(f32::NAN);
        c.extend((0..TABLE).map(|i| (i as f32 + 0.5) / (TABLE - 1) as f32));
        for i in 0..TABLE {
            let node = i as f32 / (TABLE - 1) as f32;
            let (mut below, mut above) = (node, node);
            for _ in 0..4 {
                c.extend([below, above]);
                below = f32::from_bits(below.to_bits().saturating_sub(1));
                above = f32::from_bits(above.to_bits() + 1);
            }
        }
        c.extend((0..=100_000).map(|k| k as f32 / 100_000.0));
        c
    }

    /// The lookup as the table's docs define it (the node below by a float-to-integer
    /// conversion, the straight line to the next), bit for bit.
    #[test]
    fn coat_albedo_is_the_interpolant_of_the_table_bit_for_bit() {
        let p = plastic();
        for c in cosines() {
            let x = c.clamp(0.0, 1.0) * (TABLE - 1) as f32;
            let i = (x as usize).min(TABLE - 2);
            let (a, b) = (p.coat_albedo[i], p.coat_albedo[i + 1]);
            let want = a + (x - i as f32) * (b - a);
            if c.is_nan() {
                assert!(p.coat_albedo_at(c).is_nan(), "NaN in, NaN out");
                continue;
            }
            assert_eq!(
                p.coat_albedo_at(c).to_bits(),
                want.to_bits(),
                "cos θ = {c:e}"
            );
        }
    }

    #[test]
    fn chunked_coat_albedo_is_the_lookup() {
        let p = plastic();
        let c = cosines();
        for part in c.chunks(CHUNK).chain([&c[..3]]) {
            // A value no lookup gives, so that a lane written past the input shows.
            let mut e = [-7.0; CHUNK];
            p.coat_albedo_chunk(part, &mut e);
            for (k, &c) in part.iter().enumerate() {
                let want = p.coat_albedo_at(c);
                let agree = e[k].to_bits() == want.to_bits() || (c.is_nan() && e[k].is_nan());
                assert!(agree, "cos θ = {c:e}: {} against {want}", e[k]);
            }
            assert!(e[part.len()..].iter().all(|&v| v == -7.0));
        }
    }
}
