//! A weighted blend of two models.

use super::{At, BxdfSample, Lobes, Prepare, usable_pdf};
use crate::param::ParamError;
use crate::sampling::{picks, reuse_uniform};
use crate::spectrum::Spectrum;
use glam::{Vec2, Vec3};

/// The blend of two models `A` and `B` with weight `w ∈ [0, 1]`:
///
/// ```text
/// f = (1 − w) f_A + w f_B,        pdf = (1 − w) pdf_A + w pdf_B
/// ```
///
/// Mitsuba 3's `blendbsdf` (its `weight` is `w`); pbrt-v4's `MixMaterial` chooses one material
/// per shading point instead, which is the same in expectation. A convex combination of two
/// energy-conserving, reciprocal models is energy conserving and reciprocal, and its albedo
/// is the same blend of theirs.
///
/// Sampling: `A` with probability `1 − w` and `B` with probability `w`, chosen by `uc` (which
/// is then remapped to `[0, 1)` for the chosen model's own lobe choice). A sample from a
/// lobe with a density returns the blend's value and the mixture density `pdf` at its
/// direction (one-sample MIS with the balance heuristic, Veach 1997 §9.2.4), so that it is
/// exactly what `eval` and `pdf` give. A delta sample returns the chosen model's value and
/// probability scaled by the choice's probability. When either part is
/// [`stochastic`](super::Bxdf::stochastic), a sample keeps the chosen model's weight (a
/// one-sample estimator: a random walk's weight is not a value that could be blended) and
/// carries an estimate of the mixture's density at its direction, the chosen model's
/// estimate blended with the other's `pdf`, with the value `f = weight · pdf / |cos θi|`.
///
/// Batched ([`Batch`](crate::batch::Batch)): through the parts' own batched calls, a chunk of
/// lanes at a time, so both parts implement `Batch` (see the [`batch`](crate::batch) docs).
///
/// Laws (measured by `tests/bxdf_mix.rs`): whatever the parts meet, since value and pdf are
/// exactly the weighted sums and the albedo the weighted sum of theirs (within Monte Carlo
/// error); `check_bxdf` passes for the blends tested there.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert, Microfacet, Mix};
/// use lobe::fresnel::Schlick;
/// use lobe::microfacet::{Ggx, Masking};
/// use lobe::{Alpha, Vec3};
/// let glossy = Microfacet::new(Ggx::isotropic(Alpha::new(0.2)?), Masking::HeightCorrelated, Schlick::new(0.9_f32)?);
/// let matte = Lambert::new(0.5_f32)?;
/// let satin = Mix::new(matte, glossy, 0.25)?;
/// let (wo, wi) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.0, -0.6, 0.8));
/// let expected = 0.75 * matte.eval(wo, wi) + 0.25 * glossy.eval(wo, wi);
/// assert!((satin.eval(wo, wi) - expected).abs() <= 1e-6 * expected);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mix<A, B> {
    a: A,
    b: B,
    weight: f32,
}

impl<A: Prepare, B: Prepare<Spectrum = A::Spectrum>> Mix<A, B> {
    /// `(1 − weight) a + weight b`.
    ///
    /// # Errors
    /// [`ParamError`] naming `weight` for NaN or a value outside `[0, 1]`.
    pub fn new(a: A, b: B, weight: f32) -> Result<Self, ParamError> {
        if !(0.0..=1.0).contains(&weight) {
            return Err(ParamError::new("weight", weight, "[0, 1]"));
        }
        Ok(Self { a, b, weight })
    }

    /// The weight `w` of `B` (`A` has `1 − w`).
    #[must_use]
    pub fn weight(&self) -> f32 {
        self.weight
    }

    /// The first model, weighted `1 − w`.
    #[must_use]
    pub fn first(&self) -> &A {
        &self.a
    }

    /// The second model, weighted `w`.
    #[must_use]
    pub fn second(&self) -> &B {
        &self.b
    }

    /// The blend of two values.
    #[inline(always)]
    pub(crate) fn blend(&self, fa: A::Spectrum, fb: A::Spectrum) -> A::Spectrum {
        fa * (1.0 - self.weight) + fb * self.weight
    }

    /// The blend's sample from a part's sample `s`, which `A` drew (`choose_a`) or `B`,
    /// chosen with probability `p`, for parts that are not stochastic (or a specular `s`).
    /// `other` gives the other part's value and density at `s.wi`, asked for a sample that is
    /// not specular only; the sampled part's are its sample's (the numbers its `eval` and
    /// `pdf` give). Shared by the scalar sample and the batched one (`lobe::batch`).
    #[inline(always)]
    pub(crate) fn finish(
        &self,
        s: BxdfSample<A::Spectrum>,
        p: f32,
        choose_a: bool,
        other: impl FnOnce() -> (A::Spectrum, f32),
    ) -> Option<BxdfSample<A::Spectrum>> {
        if s.is_specular() {
            let pdf = p * s.pdf;
            if !usable_pdf(pdf) {
                return None;
            }
            return Some(BxdfSample {
                f: s.f * p,
                pdf,
                ..s
            });
        }
        let (fo, po) = other();
        let (f, pdf) = if choose_a {
            (self.blend(s.f, fo), self.blend_pdf(s.pdf, po))
        } else {
            (self.blend(fo, s.f), self.blend_pdf(po, s.pdf))
        };
        if !usable_pdf(pdf) {
            return None;
        }
        Some(BxdfSample { f, pdf, ..s })
    }

    /// The blend of two densities.
    #[inline(always)]
    pub(crate) fn blend_pdf(&self, pa: f32, pb: f32) -> f32 {
        (1.0 - self.weight) * pa + self.weight * pb
    }
}

impl<A: Prepare, B: Prepare<Spectrum = A::Spectrum>> Prepare for Mix<A, B> {
    type Spectrum = A::Spectrum;
    /// `wo` and both models' prepared states.
    type Prepared = At<(A::Prepared, B::Prepared)>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At {
            wo,
            state: (self.a.prepare(wo), self.b.prepare(wo)),
        }
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> A::Spectrum {
        self.blend(
            self.a.eval_prepared(&at.state.0, wi),
            self.b.eval_prepared(&at.state.1, wi),
        )
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        self.blend_pdf(
            self.a.pdf_prepared(&at.state.0, wi),
            self.b.pdf_prepared(&at.state.1, wi),
        )
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (A::Spectrum, f32) {
        let (fa, pa) = self.a.eval_pdf_prepared(&at.state.0, wi);
        let (fb, pb) = self.b.eval_pdf_prepared(&at.state.1, wi);
        (self.blend(fa, fb), self.blend_pdf(pa, pb))
    }

    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<A::Spectrum>> {
        let wa = 1.0 - self.weight;
        let choose_a = picks(uc, wa);
        let (s, p) = if choose_a {
            let uc = reuse_uniform(uc, 0.0, wa);
            (self.a.sample_prepared(&at.state.0, u, uc)?, wa)
        } else {
            let uc = reuse_uniform(uc, wa, self.weight);
            (self.b.sample_prepared(&at.state.1, u, uc)?, self.weight)
        };
        if self.stochastic() && !s.is_specular() {
            // The chosen part's weight, an estimate of the mixture's density at the direction
            // (the chosen part's own estimate, the other's `pdf`), and the value that keeps the
            // weight.
            let pdf = if choose_a {
                self.blend_pdf(s.pdf, self.b.pdf_prepared(&at.state.1, s.wi))
            } else {
                self.blend_pdf(self.a.pdf_prepared(&at.state.0, s.wi), s.pdf)
            };
            if !usable_pdf(pdf) || s.wi.z == 0.0 {
                return None;
            }
            let f = s.weight() * (pdf / s.wi.z.abs());
            return f.is_finite().then_some(BxdfSample { f, pdf, ..s });
        }
        self.finish(s, p, choose_a, || {
            if choose_a {
                self.b.eval_pdf_prepared(&at.state.1, s.wi)
            } else {
                self.a.eval_pdf_prepared(&at.state.0, s.wi)
            }
        })
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        // The lobes of the parts that can be drawn (of non-zero weight).
        let mut lobes = Lobes::NONE;
        if self.weight < 1.0 {
            lobes |= self.a.lobes();
        }
        if self.weight > 0.0 {
            lobes |= self.b.lobes();
        }
        lobes
    }

    #[inline]
    fn stochastic(&self) -> bool {
        self.a.stochastic() || self.b.stochastic()
    }

    #[inline]
    fn eval_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> A::Spectrum {
        self.blend(
            self.a.eval_seeded_prepared(&at.state.0, wi, seed),
            self.b.eval_seeded_prepared(&at.state.1, wi, seed),
        )
    }

    #[inline]
    fn pdf_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> f32 {
        self.blend_pdf(
            self.a.pdf_seeded_prepared(&at.state.0, wi, seed),
            self.b.pdf_seeded_prepared(&at.state.1, wi, seed),
        )
    }
}
