//! The Cook-Torrance microfacet reflection model, generic over distribution, masking and
//! Fresnel term.

use super::{At, BxdfSample, Lobes, Prepare, both_above, usable_pdf};
use crate::fresnel::{self, Fresnel};
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::spectrum::Spectrum;
use glam::{Vec2, Vec3};

/// The Cook-Torrance microfacet BRDF for reflection from a rough surface:
///
/// ```text
/// f(wo, wi) = D(h) G2(wo, wi, h) F(wo·h) / (4 cos θo cos θi),     h = normalize(wo + wi)
/// ```
///
/// Cook & Torrance 1982, eq. 4 ([the handouts'](crate::handouts#seed-003) "Microfacet BRDF Model");
/// Walter et al. 2007,
/// eq. 20. Any [`NormalDistribution`] `D`, any [`Masking`] (height-correlated Smith by
/// default, separable Smith, or Cook-Torrance's V-cavity), any [`Fresnel`] term `F`: [the
/// handouts'](crate::handouts) Cook-Torrance model is `Microfacet<Beckmann, _>` with
/// [`Masking::VCavity`], a
/// modern metal is `Microfacet<Ggx, fresnel::Conductor<Vec3>>` with the default masking.
///
/// Sampling: the distribution's own microfacet sampler (visible normals for GGX, with Eto &
/// Tokuyoshi's bounded variant; visible normals for Beckmann; `D cos θ` for GTR and
/// Blinn-Phong), reflected about the sampled normal; a reflection below the horizon is
/// `None`. The density is the normal's density times the reflection Jacobian `1/(4 wo·m)`
/// (Walter et al. 2007, eq. 14).
///
/// Laws (measured by `tests/bxdf_microfacet.rs`): reciprocal to f32 round-off (largest
/// relative error 3.5e-7 over well-conditioned pairs), positive, sampler and pdf agree
/// (chi-square). A single-scattering model loses the energy that scatters more than once
/// between microfacets: its albedo is below 1 even with `F = 1`, the more so the rougher the
/// surface. Measured for GGX with `F = 1` at `θo = 60°`: 0.993 (`α = 0.05`), 0.895 (0.2),
/// 0.698 (0.5), 0.451 (1).
///
/// ```
/// use lobe::bxdf::{Bxdf, Microfacet};
/// use lobe::microfacet::{Ggx, Masking};
/// use lobe::{fresnel, Alpha, ComplexIor, Vec2, Vec3};
/// let gold = ComplexIor::new(Vec3::new(0.143, 0.375, 1.442), Vec3::new(3.983, 2.386, 1.603))?;
/// let brdf = Microfacet::new(
///     Ggx::isotropic(Alpha::new(0.3)?),
///     Masking::HeightCorrelated,
///     fresnel::Conductor { ior: gold },
/// );
/// let wo = Vec3::new(0.0, 0.6, 0.8);
/// let s = brdf.sample(wo, Vec2::new(0.4, 0.7), 0.5).unwrap();
/// assert!((s.f - brdf.eval(wo, s.wi)).length() < 1e-4 * s.f.length());
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Microfacet<D, F> {
    distribution: D,
    masking: Masking,
    fresnel: F,
}

/// A rough conductor: [`Microfacet`] with the exact conductor Fresnel term.
pub type RoughConductor<D, S = f32> = Microfacet<D, fresnel::Conductor<S>>;

impl<D: NormalDistribution, F: Fresnel> Microfacet<D, F> {
    /// The model with distribution `distribution`, masking `masking` and Fresnel term
    /// `fresnel`.
    #[must_use]
    pub fn new(distribution: D, masking: Masking, fresnel: F) -> Self {
        Self {
            distribution,
            masking,
            fresnel,
        }
    }

    /// The distribution of microfacet normals.
    #[inline(always)]
    #[must_use]
    pub fn distribution(&self) -> &D {
        &self.distribution
    }

    /// `f` for `wo`, `wi` above the surface, their sum `s = wo + wi` (the half vector
    /// before normalising) with `s2 = |s|²`, and `d = D(s/|s|)`, under `masking` (the model's;
    /// a parameter so that a batched loop can fix it, and its branch, outside the loop). A
    /// batched loop sets `PER_CHANNEL`, for the Fresnel term's
    /// [`eval_per_channel`](Fresnel::eval_per_channel): the same numbers.
    #[inline(always)]
    fn value<const PER_CHANNEL: bool>(
        &self,
        at: &At<View>,
        wi: Vec3,
        s: Vec3,
        s2: f32,
        d: f32,
        masking: Masking,
    ) -> F::Spectrum {
        let wo = at.wo;
        // A product of cosines that underflows (subnormal cos θ) would divide 0 by 0: the
        // light there is grazing to within 1e-38 and contributes nothing.
        let cos2 = wo.z * wi.z;
        if d == 0.0 || !(cos2 > 0.0) {
            return F::Spectrum::zero();
        }
        // G2 / (4 cos θo cos θi); the V-cavity term takes the normal's direction from s.
        let v = masking.visibility(&self.distribution, &at.state, wi, s);
        // Finite even where the V-cavity term keeps G = 1 for a grazing mirror pair of a very
        // narrow lobe, where D / (4 cos θo cos θi) exceeds f32.
        let scale = (d * v).min(f32::MAX);
        // wo·h = (1 + wo·wi)/|s| = |s|/2 for unit directions.
        let cos_d = 0.5 * crate::math::sqrt(s2);
        if PER_CHANNEL {
            self.fresnel.eval_per_channel(cos_d) * scale
        } else {
            self.fresnel.eval(cos_d) * scale
        }
    }

    /// The density of `wi` reflected about a normal drawn from the distribution, at their
    /// sum `s` with `d = D(s/|s|)`: the normal's density times `1/(4 wo·h)`.
    #[inline(always)]
    fn density(&self, at: &At<View>, s: Vec3, d: f32) -> f32 {
        self.distribution.pdf_reflection(&at.state, s, d)
    }

    /// `(s, |s|²)` for `s = wo + wi` of a pair above the surface with a non-zero sum (the
    /// microfacet normal's direction), or `None`.
    #[inline(always)]
    fn half_above(at: &At<View>, wi: Vec3) -> Option<(Vec3, f32)> {
        if !both_above(at.wo, wi) {
            return None;
        }
        let s = at.wo + wi;
        let s2 = s.length_squared();
        if s2 > 0.0 { Some((s, s2)) } else { None }
    }

    /// [`Prepare::eval_prepared`] under `masking` (and, for a batched loop, `PER_CHANNEL`: see
    /// [`value`](Self::value)).
    #[inline(always)]
    pub(crate) fn eval_with<const PER_CHANNEL: bool>(
        &self,
        at: &At<View>,
        wi: Vec3,
        masking: Masking,
    ) -> F::Spectrum {
        match Self::half_above(at, wi) {
            Some((s, s2)) => {
                let d = self.distribution.d_unnormalized(s, s2);
                self.value::<PER_CHANNEL>(at, wi, s, s2, d, masking)
            }
            None => F::Spectrum::zero(),
        }
    }

    /// [`Prepare::eval_pdf_prepared`] under `masking`.
    #[inline(always)]
    pub(crate) fn eval_pdf_with<const PER_CHANNEL: bool>(
        &self,
        at: &At<View>,
        wi: Vec3,
        masking: Masking,
    ) -> (F::Spectrum, f32) {
        match Self::half_above(at, wi) {
            Some((s, s2)) => {
                let d = self.distribution.d_unnormalized(s, s2);
                (
                    self.value::<PER_CHANNEL>(at, wi, s, s2, d, masking),
                    self.density(at, s, d),
                )
            }
            None => (F::Spectrum::zero(), 0.0),
        }
    }

    /// [`eval_pdf_with`](Self::eval_pdf_with) without an early return, for a batched loop:
    /// an unusable pair (not both above the surface, or `wo + wi = 0`) is evaluated at the
    /// stand-in `s = z` and answered with zeros at the end. The same numbers: it repeats
    /// `half_above` and `eval_pdf_with` step for step (change them together), and
    /// `tests/batch.rs` compares the batched samples that use it (the compensated models', the
    /// plastics') with the scalar ones.
    #[inline(always)]
    pub(crate) fn eval_pdf_lane<const PER_CHANNEL: bool>(
        &self,
        at: &At<View>,
        wi: Vec3,
        masking: Masking,
    ) -> (F::Spectrum, f32) {
        let s = at.wo + wi;
        let s2 = s.length_squared();
        let usable = both_above(at.wo, wi) & (s2 > 0.0);
        let (s, s2) = if usable { (s, s2) } else { (Vec3::Z, 1.0) };
        let d = self.distribution.d_unnormalized(s, s2);
        let f = self.value::<PER_CHANNEL>(at, wi, s, s2, d, masking);
        let pdf = self.density(at, s, d);
        if usable {
            (f, pdf)
        } else {
            (F::Spectrum::zero(), 0.0)
        }
    }

    /// The direction [`sample_with`](Self::sample_with) draws for `u`: `wo` reflected about
    /// a normal drawn from the distribution (possibly below the surface: `sample_with`
    /// refuses it there, and where its density is unusable).
    #[inline(always)]
    pub(crate) fn sample_direction(&self, at: &At<View>, u: Vec2) -> Vec3 {
        // The view's `w` is `wo` itself here: the callers sample for `wo` above the surface.
        self.distribution.sample_reflected(&at.state, u)
    }

    /// [`Prepare::sample_prepared`] under `masking`.
    #[inline(always)]
    pub(crate) fn sample_with<const PER_CHANNEL: bool>(
        &self,
        at: &At<View>,
        u: Vec2,
        _uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<F::Spectrum>> {
        if !(at.wo.z > 0.0) {
            return None;
        }
        // The batched forms of `CompensatedMicrofacet`'s and the plastics' samples rely on
        // this: the sample is `eval_pdf_with` at `sample_direction` (which `eval_pdf_lane`
        // repeats without early returns), refused exactly where that density is unusable.
        let wi = self.sample_direction(at, u);
        // Evaluate at wo + wi, as `eval` and `pdf` do, rather than at `m`: the two differ by
        // rounding, and a renderer's MIS needs `pdf` to reproduce the sample's density
        // exactly. D once, for both the value and the density.
        let (s, s2) = Self::half_above(at, wi)?;
        let d = self.distribution.d_unnormalized(s, s2);
        let pdf = self.density(at, s, d);
        if !usable_pdf(pdf) {
            return None;
        }
        Some(BxdfSample::new(
            wi,
            self.value::<PER_CHANNEL>(at, wi, s, s2, d, masking),
            pdf,
            Lobes::GLOSSY_REFLECTION,
        ))
    }

    /// The masking-shadowing term.
    #[inline(always)]
    #[must_use]
    pub fn masking(&self) -> Masking {
        self.masking
    }

    /// The Fresnel term.
    #[inline(always)]
    #[must_use]
    pub fn fresnel(&self) -> &F {
        &self.fresnel
    }
}

impl<D: NormalDistribution, F: Fresnel> Prepare for Microfacet<D, F> {
    type Spectrum = F::Spectrum;
    type Prepared = At<View>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At::view(&self.distribution, wo)
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> F::Spectrum {
        self.eval_with::<false>(at, wi, self.masking)
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        match Self::half_above(at, wi) {
            Some((s, s2)) => self.density(at, s, self.distribution.d_unnormalized(s, s2)),
            None => 0.0,
        }
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (F::Spectrum, f32) {
        self.eval_pdf_with::<false>(at, wi, self.masking)
    }

    #[inline(always)]
    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        _uc: f32,
    ) -> Option<BxdfSample<F::Spectrum>> {
        self.sample_with::<false>(at, u, _uc, self.masking)
    }

    #[inline(always)]
    fn lobes(&self) -> Lobes {
        Lobes::GLOSSY_REFLECTION
    }
}
