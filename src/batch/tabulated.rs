//! The batched loops of a model that reads albedo tables at each lane's directions (the
//! energy-compensated microfacet model's, both plastics', the compensated glass's): a chunk of
//! lanes at a time, the tables first ([`AlbedoRow::e_chunk`]; the compensated plastic reads
//! two, its coat albedo and the coat's own `E`; the glass the row of each direction's side),
//! then the model's arithmetic in a loop that reads no table (and for
//! `sample`, the tables at the sampled directions, then the samples' values).
//!
//! A read at a different place in each lane is a gather. On a target with AVX2 and no
//! AVX-512, LLVM's cost model takes gathers for slow and then leaves the whole loop scalar:
//! with the lookups in a pass of their own the rest vectorises (the [module docs](super) have
//! the figures). The numbers are those of the scalar path: the same lookups, the same
//! arithmetic, in another order of passes.
//!
//! The chunk's buffers live on the stack: up to 14 KiB for a `Vec4` compensated plastic's
//! `sample` (two tables' values per lane, and its lookups' temporaries), 11 KiB for a `Vec4`
//! compensated conductor's, 5 KiB for an `f32` one's; zeroed on every call, so a batch of a
//! few lanes pays for that, one of 256 or more does not notice it.

use super::kernel::{EvalKernel, Kernel, PdfKernel, SampleKernel, cut};
use super::lanes::{Lanes, Vec2s, Vec3sMut};
use super::{LengthError, SampleOut};
use crate::bxdf::{BxdfSample, Lobes, Prepare};
use crate::spectrum::Spectrum;
#[cfg(doc)]
use crate::tables::AlbedoRow;
use crate::tables::CHUNK;
use glam::{Vec2, Vec3};

/// A lane's entry in a chunk's buffer, and what fills the buffer before the lanes do.
pub(crate) trait Slot: Copy {
    /// The filler.
    fn placeholder() -> Self;
}

impl<S: Spectrum> Slot for S {
    #[inline(always)]
    fn placeholder() -> S {
        S::zero()
    }
}

impl Slot for (f32, f32) {
    #[inline(always)]
    fn placeholder() -> Self {
        (0.0, 0.0)
    }
}

/// A model whose prepared state reads an albedo table at `wo`, and whose value reads it at
/// `wi` (or two tables: the compensated plastic's own and its coat's).
pub(crate) trait TableLanes: Prepare {
    /// What the tables give at one direction.
    type Looked: Slot;
    /// The tables' values at each direction whose `z` is `z[k]`, into `e[k]` (at most
    /// [`CHUNK`] lanes; [`AlbedoRow::e_chunk`]).
    fn look_up(&self, z: &[f32], e: &mut [Self::Looked; CHUNK]);
    /// [`Prepare::prepare`] with the tables' values at `wo` given as `e_wo`.
    fn prepare_from(&self, wo: Vec3, e_wo: Self::Looked) -> Self::Prepared;
    /// [`Prepare::pdf_prepared`] as a batched loop's lane computes it (the same numbers;
    /// a model may give a form without a branch).
    #[inline(always)]
    fn pdf_lane(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        self.pdf_prepared(at, wi)
    }
}

/// A [`TableLanes`] model whose sample, drawn, may be left unfinished for want of the
/// table's value at the sampled direction.
pub(crate) trait TableSample: TableLanes {
    /// What [`finish`](Self::finish) needs of the prepared state.
    type Outgoing: Slot;
    /// That part of the prepared state.
    fn outgoing(at: &Self::Prepared) -> Self::Outgoing;
    /// An unfinished sample's value, from its value `f` as drawn, what it needs of the
    /// prepared state, and the tables' values `e_wi` at the sampled direction.
    fn finish(
        &self,
        f: Self::Spectrum,
        outgoing: Self::Outgoing,
        e_wi: Self::Looked,
    ) -> Self::Spectrum;
}

/// How one lane's value is computed from the prepared state and the table's value at `wi`.
pub(crate) trait TableOp<M: TableLanes> {
    /// `eval(wo, wi)`, with `e_wi` the tables' values at `wi`.
    fn eval(m: &M, at: &M::Prepared, wi: Vec3, e_wi: M::Looked) -> M::Spectrum;
}

/// How one lane's sample is drawn from the prepared state.
pub(crate) trait TableSampleOp<M: TableSample> {
    /// Whether [`sample`](Self::sample) leaves its samples unfinished: the loop then looks
    /// the table up at the sampled directions and [finishes](TableSample::finish) them.
    const UNFINISHED: bool;
    /// `sample(wo, u, uc)`, unfinished where [`UNFINISHED`](Self::UNFINISHED) says so.
    fn sample(m: &M, at: &M::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<M::Spectrum>>;
}

/// A batched call's kernel ([`EvalKernel`], [`PdfKernel`], [`SampleKernel`]) run a chunk
/// of lanes at a time, for a table model's lane operation.
pub(crate) struct Chunked<K>(K);

/// The chunks of `0..n`, as `(start, end)`.
#[inline(always)]
fn chunks(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n)
        .step_by(CHUNK)
        .map(move |start| (start, (start + CHUNK).min(n)))
}

/// `f[k] = eval(wo[k], wi[k])` over the first `n` lanes, a chunk at a time.
impl<M: TableLanes + Clone, O: TableOp<M>> Kernel for Chunked<EvalKernel<'_, '_, M, O>>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let EvalKernel {
            m, wo, wi, f, n, ..
        } = self.0;
        let (wo, wi) = (cut(wo, n), cut(wi, n));
        let mut f = M::Spectrum::truncate(f, n);
        let m = m.clone();
        let placeholder = M::Looked::placeholder();
        let (mut e_wo, mut e_wi) = ([placeholder; CHUNK], [placeholder; CHUNK]);
        for (start, end) in chunks(n) {
            m.look_up(&wo.z[start..end], &mut e_wo);
            m.look_up(&wi.z[start..end], &mut e_wi);
            for (k, (&e_wo, &e_wi)) in (start..end).zip(e_wo.iter().zip(&e_wi)) {
                let at = m.prepare_from(wo.get(k), e_wo);
                M::Spectrum::put(&mut f, k, O::eval(&m, &at, wi.get(k), e_wi));
            }
        }
    }
}

/// `pdf[k] = pdf(wo[k], wi[k])` over the first `n` lanes, a chunk at a time.
impl<M: TableLanes + Clone> Kernel for Chunked<PdfKernel<'_, '_, M, ()>> {
    #[inline(always)]
    fn run(self) {
        let PdfKernel {
            m, wo, wi, pdf, n, ..
        } = self.0;
        let (wo, wi) = (cut(wo, n), cut(wi, n));
        let pdf = &mut pdf[..n];
        let m = m.clone();
        let mut e_wo = [M::Looked::placeholder(); CHUNK];
        for (start, end) in chunks(n) {
            m.look_up(&wo.z[start..end], &mut e_wo);
            for (k, &e_wo) in (start..end).zip(&e_wo) {
                pdf[k] = m.pdf_lane(&m.prepare_from(wo.get(k), e_wo), wi.get(k));
            }
        }
    }
}

/// `(wi, f, pdf, lobe, eta)[k] = sample(wo[k], u[k], uc[k])` over the first `n` lanes, zeros
/// (and [`Lobes::NONE`]) for no sample, a chunk at a time: the row at `wo.z`, the samples, the
/// row at the sampled directions' `wi.z` (where the samples are unfinished), their values.
impl<M: TableSample + Clone, O: TableSampleOp<M>> Kernel for Chunked<SampleKernel<'_, '_, M, O>>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let SampleKernel {
            m,
            wo,
            u,
            uc,
            out,
            n,
            ..
        } = self.0;
        let wo = cut(wo, n);
        let u = Vec2s {
            x: &u.x[..n],
            y: &u.y[..n],
        };
        let uc = &uc[..n];
        let SampleOut {
            wi,
            f,
            pdf,
            lobe,
            eta,
        } = out;
        let (mut wi, mut f): (Vec3sMut<'_>, _) = (wi.truncate(n), M::Spectrum::truncate(f, n));
        let (pdf, lobe, eta) = (&mut pdf[..n], &mut lobe[..n], &mut eta[..n]);
        let m = m.clone();
        let placeholder = M::Looked::placeholder();
        let (mut e_wo, mut e_wi) = ([placeholder; CHUNK], [placeholder; CHUNK]);
        // Per lane of the chunk: the value as drawn, what finishing it needs, and whether
        // there is a sample.
        let mut drawn = [M::Spectrum::zero(); CHUNK];
        let mut outgoing = [M::Outgoing::placeholder(); CHUNK];
        let mut sampled = [false; CHUNK];
        for (start, end) in chunks(n) {
            m.look_up(&wo.z[start..end], &mut e_wo);
            let kept = drawn.iter_mut().zip(&mut outgoing).zip(&mut sampled);
            for (k, (&e_wo, ((drawn, outgoing), sampled))) in
                (start..end).zip(e_wo.iter().zip(kept))
            {
                let at = m.prepare_from(wo.get(k), e_wo);
                let (w, v, p, l, e) = match O::sample(&m, &at, u.get(k), uc[k]) {
                    Some(s) => (s.wi, s.f, s.pdf, s.lobe, s.eta),
                    None => (Vec3::ZERO, M::Spectrum::zero(), 0.0, Lobes::NONE, 0.0),
                };
                wi.put(k, w);
                pdf[k] = p;
                lobe[k] = l;
                eta[k] = e;
                (*drawn, *outgoing, *sampled) = (v, M::outgoing(&at), l != Lobes::NONE);
            }
            if !O::UNFINISHED {
                for (k, &v) in (start..end).zip(&drawn) {
                    M::Spectrum::put(&mut f, k, v);
                }
                continue;
            }
            m.look_up(&wi.z[start..end], &mut e_wi);
            // Zipped, so that no index is checked; every lane finished and the value chosen
            // after, so that the loop has no branch.
            let lanes = drawn.iter().zip(&outgoing).zip(sampled.iter().zip(&e_wi));
            for (k, ((&v, &o), (&s, &e))) in (start..end).zip(lanes) {
                let finished = m.finish(v, o, e);
                M::Spectrum::put(&mut f, k, if s { finished } else { v });
            }
        }
    }
}

/// [`run`](super::run)s a call's kernel in chunks.
#[inline(always)]
pub(super) fn chunked<K>(kernel: Result<K, LengthError>) -> Result<(), LengthError>
where
    Chunked<K>: Kernel,
{
    super::run(kernel.map(Chunked))
}
