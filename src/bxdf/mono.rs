//! A monochrome model in an RGB (or spectral) renderer.

use super::{BxdfSample, Lobes, Prepare};
use crate::spectrum::Spectrum;
use core::marker::PhantomData;
use glam::{Vec2, Vec3};

/// Lifts a model whose values are `f32` to the spectrum `S` (RGB `Vec3` by default) by
/// repeating its value in every channel.
///
/// The dielectric models ([`RoughDielectric`](super::RoughDielectric),
/// [`SmoothDielectric`](super::SmoothDielectric), [`ThinDielectric`](super::ThinDielectric))
/// are `f32`: one relative index, the same at every wavelength, so their value is one
/// number. A renderer that holds every material as an RGB model wraps them in `Mono`; the
/// directions, densities and lobes are the model's own. Batched
/// ([`Batch`](crate::batch::Batch)): through the model's own batched calls, a chunk of lanes at
/// a time, its values then repeated, so the model implements `Batch`.
///
/// ```
/// use lobe::bxdf::{Bxdf, Mono, SmoothDielectric};
/// use lobe::{Eta, Vec2, Vec3};
/// let glass = Mono::<_, Vec3>::new(SmoothDielectric::new(Eta::new(1.5)?));
/// let s = glass.sample(Vec3::Z, Vec2::ZERO, 0.01).unwrap(); // uc below F: the reflection
/// assert_eq!(s.f, Vec3::splat(s.f.x));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mono<B, S = Vec3> {
    inner: B,
    spectrum: PhantomData<S>,
}

impl<B, S> Mono<B, S> {
    /// `inner`, its values repeated in every channel of `S`.
    #[must_use]
    pub const fn new(inner: B) -> Self {
        Self {
            inner,
            spectrum: PhantomData,
        }
    }

    /// The wrapped model.
    #[inline]
    #[must_use]
    pub fn inner(&self) -> &B {
        &self.inner
    }
}

impl<B: Prepare<Spectrum = f32>, S: Spectrum> Prepare for Mono<B, S> {
    type Spectrum = S;
    type Prepared = B::Prepared;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> B::Prepared {
        self.inner.prepare(wo)
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &B::Prepared, wi: Vec3) -> S {
        S::splat(self.inner.eval_prepared(at, wi))
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &B::Prepared, wi: Vec3) -> f32 {
        self.inner.pdf_prepared(at, wi)
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &B::Prepared, wi: Vec3) -> (S, f32) {
        let (f, pdf) = self.inner.eval_pdf_prepared(at, wi);
        (S::splat(f), pdf)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &B::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<S>> {
        self.inner.sample_prepared(at, u, uc).map(|s| BxdfSample {
            wi: s.wi,
            f: S::splat(s.f),
            pdf: s.pdf,
            lobe: s.lobe,
            eta: s.eta,
        })
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        self.inner.lobes()
    }

    #[inline(always)]
    fn stochastic(&self) -> bool {
        self.inner.stochastic()
    }

    #[inline(always)]
    fn eval_seeded_prepared(&self, at: &B::Prepared, wi: Vec3, seed: u64) -> S {
        S::splat(self.inner.eval_seeded_prepared(at, wi, seed))
    }

    #[inline(always)]
    fn pdf_seeded_prepared(&self, at: &B::Prepared, wi: Vec3, seed: u64) -> f32 {
        self.inner.pdf_seeded_prepared(at, wi, seed)
    }
}
