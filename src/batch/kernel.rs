//! The batched loops and their run-time dispatch.

use super::lanes::{Lanes, Vec2s, Vec3s};
use super::{SampleOut, lane_sample};
use crate::bxdf::{BxdfSample, Lobes, Prepare};
use core::marker::PhantomData;
use glam::{Vec2, Vec3};

/// A loop to compile for the widest SIMD the CPU has (or, through `run_here` in the module
/// above, for the target alone). `run` must be `#[inline(always)]`, so that it is compiled
/// inside the dispatcher's `#[target_feature]` function, must re-slice its
/// inputs to one length itself (or in an `#[inline(always)]` function it calls), so that the
/// compiler sees that every index is in bounds, and runs the model from a local clone, so that
/// the compiler sees that no store of the loop changes the model's parameters and that reading
/// them is always safe: through a reference, a parameter read on only some lanes (after a
/// lane's early return) is vectorised as a masked gather from one address per iteration. Its
/// loop takes each slice as an argument of its own (`pair_lanes`, `sample_lanes`) and reads a
/// lane's inputs from those slices, not through a [`Vec3s`] built from them: slices passed so
/// are known not to overlap, while an output read out of a struct is compared with every input
/// at run time before the vectorised loop, which short batches then skip, and inputs read
/// through a `Vec3s`'s `get` raised the length from which the loop is vectorised from 8 lanes
/// to 16 or 24 for some models (`docs/batched-loops.md`, rule 10). The table models' chunked
/// loops in the module `tabulated` (`pair_chunk`, `draw_chunk`) index their slice arguments
/// the same way.
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

/// Runs `kernel` compiled for the widest instruction set the CPU and the operating system have, on
/// x86 with `std` (pulp asks std's `is_x86_feature_detected!`, which detects once and caches the
/// answer); otherwise compiled for the target: on other architectures, and on x86 without `std`,
/// where pulp would read CPUID alone and could pick AVX that the OS has not enabled (the [module
/// docs](super) say more).
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

/// What a loop over pairs `(wo, wi)` writes per lane: [`Value`]'s spectrum or
/// [`Density`]'s density.
pub(crate) trait PairOut<M> {
    /// The lane's result.
    type Out: Lanes;
}

/// The value `eval` gives, each lane's computed by `O`: a [`LaneOp`] here, a table model's
/// lane operation in the module `tabulated`.
pub(crate) struct Value<O>(PhantomData<O>);

impl<M: Prepare, O> PairOut<M> for Value<O>
where
    M::Spectrum: Lanes,
{
    type Out = M::Spectrum;
}

/// The density `pdf` gives, each lane's computed by `O`: a [`LaneOp`] here; `()`, a table
/// model's own lane form, in the module `tabulated`.
pub(crate) struct Density<O>(PhantomData<O>);

impl<M, O> PairOut<M> for Density<O> {
    type Out = f32;
}

/// `out[k] = eval(wo[k], wi[k])` ([`Value`]) or `pdf(wo[k], wi[k])` ([`Density`]) over the
/// first `n` lanes (every slice has at least `n`).
pub(crate) struct PairKernel<'a, 'f, M, P: PairOut<M>> {
    pub(super) m: &'a M,
    pub(super) wo: Vec3s<'a>,
    pub(super) wi: Vec3s<'a>,
    pub(super) out: <P::Out as Lanes>::Mut<'f>,
    pub(super) n: usize,
    pub(super) op: PhantomData<P>,
}

impl<M: Prepare + Clone, P: PairOp<M>> Kernel for PairKernel<'_, '_, M, P> {
    #[inline(always)]
    fn run(self) {
        let (wo, wi, m) = (self.wo, self.wi, self.m.clone());
        pair_lanes::<M, P>(&m, self.n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, self.out);
    }
}

/// How a [`PairKernel`]'s lane is computed from `wo` and `wi`.
trait PairOp<M>: PairOut<M> {
    /// The result for `wo` and `wi`.
    fn lane(m: &M, wo: Vec3, wi: Vec3) -> Self::Out;
}

impl<M: Prepare, O: LaneOp<M>> PairOp<M> for Value<O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn lane(m: &M, wo: Vec3, wi: Vec3) -> M::Spectrum {
        O::eval(m, wo, wi)
    }
}

impl<M: Prepare, O: LaneOp<M>> PairOp<M> for Density<O> {
    #[inline(always)]
    fn lane(m: &M, wo: Vec3, wi: Vec3) -> f32 {
        O::pdf(m, wo, wi)
    }
}

/// [`PairKernel`]'s loop over the first `n` lanes (every slice has at
/// least `n`), every slice an argument of its own: the compiler then knows that the output
/// overlaps no input (see [`Kernel`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the point: one slice to an argument
fn pair_lanes<M, P: PairOp<M>>(
    m: &M,
    n: usize,
    ox: &[f32],
    oy: &[f32],
    oz: &[f32],
    ix: &[f32],
    iy: &[f32],
    iz: &[f32],
    out: <P::Out as Lanes>::Mut<'_>,
) {
    let (ox, oy, oz) = (&ox[..n], &oy[..n], &oz[..n]);
    let (ix, iy, iz) = (&ix[..n], &iy[..n], &iz[..n]);
    let mut out = P::Out::truncate(out, n);
    for k in 0..n {
        let wo = Vec3::new(ox[k], oy[k], oz[k]);
        let wi = Vec3::new(ix[k], iy[k], iz[k]);
        P::Out::put(&mut out, k, P::lane(m, wo, wi));
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
        let (wo, u, m) = (self.wo, self.u, self.m.clone());
        let SampleOut {
            wi,
            f,
            pdf,
            lobe,
            eta,
        } = self.out;
        let (ix, iy, iz) = (wi.x, wi.y, wi.z);
        sample_lanes::<M, O>(
            &m, self.n, wo.x, wo.y, wo.z, u.x, u.y, self.uc, ix, iy, iz, f, pdf, lobe, eta,
        );
    }
}

/// [`SampleKernel`]'s loop over the first `n` lanes, every slice an argument of its own (see
/// [`pair_lanes`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the point: one slice to an argument
fn sample_lanes<M: Prepare, O: LaneOp<M>>(
    m: &M,
    n: usize,
    ox: &[f32],
    oy: &[f32],
    oz: &[f32],
    ux: &[f32],
    uy: &[f32],
    uc: &[f32],
    ix: &mut [f32],
    iy: &mut [f32],
    iz: &mut [f32],
    f: <M::Spectrum as Lanes>::Mut<'_>,
    pdf: &mut [f32],
    lobe: &mut [Lobes],
    eta: &mut [f32],
) where
    M::Spectrum: Lanes,
{
    let (ox, oy, oz) = (&ox[..n], &oy[..n], &oz[..n]);
    let (ux, uy, uc) = (&ux[..n], &uy[..n], &uc[..n]);
    let (ix, iy, iz) = (&mut ix[..n], &mut iy[..n], &mut iz[..n]);
    let mut f = M::Spectrum::truncate(f, n);
    let (pdf, lobe, eta) = (&mut pdf[..n], &mut lobe[..n], &mut eta[..n]);
    // Counted: a loop over `uc.iter().enumerate()` kept the bounds checks of the other slices,
    // whose exit forced a scalar epilogue of up to 8 lanes (`docs/batched-loops.md`, rule 10).
    for k in 0..n {
        let (wo, u) = (Vec3::new(ox[k], oy[k], oz[k]), Vec2::new(ux[k], uy[k]));
        let (w, v, p, l, e) = lane_sample(O::sample(m, wo, u, uc[k]));
        (ix[k], iy[k], iz[k]) = (w.x, w.y, w.z);
        M::Spectrum::put(&mut f, k, v);
        pdf[k] = p;
        lobe[k] = l;
        eta[k] = e;
    }
}
