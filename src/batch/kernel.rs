//! The batched loops and their run-time dispatch.

use super::SampleOut;
use super::lanes::{Lanes, Vec2s, Vec3s, Vec3sMut};
use crate::bxdf::{BxdfSample, Lobes, Prepare};
use crate::spectrum::Spectrum;
use core::marker::PhantomData;
use glam::{Vec2, Vec3};

/// A loop to compile for the widest SIMD the CPU has. `run` must be `#[inline(always)]`, so
/// that it is compiled inside the dispatcher's `#[target_feature]` function, must re-slice
/// its inputs to one length itself, so that the compiler sees that every index is in
/// bounds, and runs the model from a local clone, so that the compiler sees that no store of
/// the loop changes the model's parameters and that reading them is always safe: through a
/// reference, a parameter read on only some lanes (after a lane's early return) is
/// vectorised as a masked gather from one address per iteration.
pub(crate) trait Kernel {
    /// The loop.
    fn run(self);
}

/// A [`Kernel`] as a pulp operation.
#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
struct Pulp<K>(K);

#[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
impl<K: Kernel> pulp::WithSimd for Pulp<K> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        self.0.run();
    }
}

/// Runs `kernel` compiled for the widest instruction set the CPU and the operating system
/// have, on x86 with `std` (pulp asks std's `is_x86_feature_detected!` once and caches the
/// answer); otherwise compiled for the target: on other architectures, and on x86 without
/// `std`, where pulp would read CPUID alone and could pick AVX that the OS has not enabled
/// (the [module docs](super) say more).
#[inline(always)]
pub(crate) fn dispatch<K: Kernel>(kernel: K) {
    #[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
    pulp::Arch::new().dispatch(Pulp(kernel));
    #[cfg(not(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64"))))]
    kernel.run();
}

/// How one lane is computed.
pub(crate) trait LaneOp<M: Prepare> {
    /// `eval(wo, wi)`.
    fn eval(m: &M, wo: Vec3, wi: Vec3) -> M::Spectrum;
    /// `pdf(wo, wi)`.
    fn pdf(m: &M, wo: Vec3, wi: Vec3) -> f32;
    /// `sample(wo, u, uc)`.
    fn sample(m: &M, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<M::Spectrum>>;
}

/// The model's own prepared calls.
pub(crate) struct Plain;

impl<M: Prepare> LaneOp<M> for Plain {
    #[inline(always)]
    fn eval(m: &M, wo: Vec3, wi: Vec3) -> M::Spectrum {
        m.eval_prepared(&m.prepare(wo), wi)
    }

    #[inline(always)]
    fn pdf(m: &M, wo: Vec3, wi: Vec3) -> f32 {
        m.pdf_prepared(&m.prepare(wo), wi)
    }

    #[inline(always)]
    fn sample(m: &M, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<M::Spectrum>> {
        m.sample_prepared(&m.prepare(wo), u, uc)
    }
}

/// `f[k] = eval(wo[k], wi[k])` over the first `n` lanes (every slice has at least `n`).
pub(crate) struct EvalKernel<'a, 'f, M: Prepare, O>
where
    M::Spectrum: Lanes,
{
    pub(super) m: &'a M,
    pub(super) wo: Vec3s<'a>,
    pub(super) wi: Vec3s<'a>,
    pub(super) f: <M::Spectrum as Lanes>::Mut<'f>,
    pub(super) n: usize,
    pub(super) op: PhantomData<O>,
}

/// Re-slices a [`Vec3s`] to `n` lanes, in the loop's own function.
#[inline(always)]
pub(super) fn cut(v: Vec3s<'_>, n: usize) -> Vec3s<'_> {
    Vec3s {
        x: &v.x[..n],
        y: &v.y[..n],
        z: &v.z[..n],
    }
}

impl<M: Prepare + Clone, O: LaneOp<M>> Kernel for EvalKernel<'_, '_, M, O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let n = self.n;
        let (wo, wi) = (cut(self.wo, n), cut(self.wi, n));
        let mut f = M::Spectrum::truncate(self.f, n);
        let m = self.m.clone();
        for k in 0..n {
            M::Spectrum::put(&mut f, k, O::eval(&m, wo.get(k), wi.get(k)));
        }
    }
}

/// `pdf[k] = pdf(wo[k], wi[k])` over the first `n` lanes.
pub(crate) struct PdfKernel<'a, 'f, M, O> {
    pub(super) m: &'a M,
    pub(super) wo: Vec3s<'a>,
    pub(super) wi: Vec3s<'a>,
    pub(super) pdf: &'f mut [f32],
    pub(super) n: usize,
    pub(super) op: PhantomData<O>,
}

impl<M: Prepare + Clone, O: LaneOp<M>> Kernel for PdfKernel<'_, '_, M, O> {
    #[inline(always)]
    fn run(self) {
        let n = self.n;
        let (wo, wi) = (cut(self.wo, n), cut(self.wi, n));
        let m = self.m.clone();
        for (k, pdf) in self.pdf[..n].iter_mut().enumerate() {
            *pdf = O::pdf(&m, wo.get(k), wi.get(k));
        }
    }
}

/// `(wi, f, pdf, lobe, eta)[k] = sample(wo[k], u[k], uc[k])` over the first `n` lanes, zeros
/// (and [`Lobes::NONE`]) for no sample.
pub(crate) struct SampleKernel<'a, 'f, M: Prepare, O>
where
    M::Spectrum: Lanes,
{
    pub(super) m: &'a M,
    pub(super) wo: Vec3s<'a>,
    pub(super) u: Vec2s<'a>,
    pub(super) uc: &'a [f32],
    pub(super) out: SampleOut<'f, M::Spectrum>,
    pub(super) n: usize,
    pub(super) op: PhantomData<O>,
}

impl<M: Prepare + Clone, O: LaneOp<M>> Kernel for SampleKernel<'_, '_, M, O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let n = self.n;
        let wo = cut(self.wo, n);
        let u = Vec2s {
            x: &self.u.x[..n],
            y: &self.u.y[..n],
        };
        let uc = &self.uc[..n];
        let SampleOut {
            wi,
            f,
            pdf,
            lobe,
            eta,
        } = self.out;
        let (mut wi, mut f): (Vec3sMut<'_>, _) = (wi.truncate(n), M::Spectrum::truncate(f, n));
        let (pdf, lobe, eta) = (&mut pdf[..n], &mut lobe[..n], &mut eta[..n]);
        let m = self.m.clone();
        for k in 0..n {
            let (w, v, p, l, e) = match O::sample(&m, wo.get(k), u.get(k), uc[k]) {
                Some(s) => (s.wi, s.f, s.pdf, s.lobe, s.eta),
                None => (Vec3::ZERO, M::Spectrum::zero(), 0.0, Lobes::NONE, 0.0),
            };
            wi.put(k, w);
            M::Spectrum::put(&mut f, k, v);
            pdf[k] = p;
            lobe[k] = l;
            eta[k] = e;
        }
    }
}
