//! The batched loops of a model that reads an albedo table at each lane's directions (the
//! energy-compensated microfacet model): a chunk of lanes at a time, the table first
//! ([`AlbedoRow::e_chunk`]), then the model's arithmetic in a loop that reads no table (and
//! for `sample`, the table at the sampled directions, then the samples' values).
//!
//! A read at a different place in each lane is a gather. On a target with AVX2 and no
//! AVX-512, LLVM's cost model takes gathers for slow and then leaves the whole loop scalar:
//! with the lookups in a pass of their own the rest vectorises (the [module docs](super) have
//! the figures). The numbers are those of the scalar path: the same lookups, the same
//! arithmetic, in another order of passes.
//!
//! The chunk's buffers live on the stack: up to 11 KiB for a `Vec4` model's `sample` (5 KiB
//! for `f32`), zeroed on every call; a batch of a few lanes pays for that, one of 256 or
//! more does not notice it.

use super::kernel::{Kernel, cut, dispatch};
use super::lanes::{Lanes, Vec2s, Vec3s, Vec3sMut};
use super::{LengthError, SampleOut, same_length};
use crate::bxdf::{BxdfSample, Lobes, Prepare};
use crate::spectrum::Spectrum;
#[cfg(doc)]
use crate::tables::AlbedoRow;
use crate::tables::CHUNK;
use core::marker::PhantomData;
use glam::{Vec2, Vec3};

/// A model whose prepared state reads an albedo table at `wo`, and whose value reads it at
/// `wi`.
pub(crate) trait TableLanes: Prepare {
    /// The table's value at each direction whose `z` is `z[k]`, into `e[k]` (at most
    /// [`CHUNK`] lanes; [`AlbedoRow::e_chunk`]).
    fn look_up(&self, z: &[f32], e: &mut [f32; CHUNK]);
    /// [`Prepare::prepare`] with the table's value at `wo` given as `e_wo`.
    fn prepare_from(&self, wo: Vec3, e_wo: f32) -> Self::Prepared;
}

/// A [`TableLanes`] model whose sample, drawn, may be left unfinished for want of the
/// table's value at the sampled direction.
pub(crate) trait TableSample: TableLanes {
    /// What [`finish`](Self::finish) needs of the prepared state.
    fn outgoing(at: &Self::Prepared) -> Self::Spectrum;
    /// An unfinished sample's value, from its value `f` as drawn, what it needs of the
    /// prepared state, and the table's value `e_wi` at the sampled direction.
    fn finish(&self, f: Self::Spectrum, outgoing: Self::Spectrum, e_wi: f32) -> Self::Spectrum;
}

/// How one lane's value is computed from the prepared state and the table's value at `wi`.
pub(crate) trait TableOp<M: TableLanes> {
    /// `eval(wo, wi)`, with `e_wi` the table's value at `wi`.
    fn eval(m: &M, at: &M::Prepared, wi: Vec3, e_wi: f32) -> M::Spectrum;
}

/// How one lane's sample is drawn from the prepared state.
pub(crate) trait TableSampleOp<M: TableSample> {
    /// Whether [`sample`](Self::sample) leaves its samples unfinished: the loop then looks
    /// the table up at the sampled directions and [finishes](TableSample::finish) them.
    const UNFINISHED: bool;
    /// `sample(wo, u, uc)`, unfinished where [`UNFINISHED`](Self::UNFINISHED) says so.
    fn sample(m: &M, at: &M::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<M::Spectrum>>;
}

/// The chunks of `0..n`, as `(start, end)`.
#[inline(always)]
fn chunks(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n)
        .step_by(CHUNK)
        .map(move |start| (start, (start + CHUNK).min(n)))
}

/// `f[k] = eval(wo[k], wi[k])` over the first `n` lanes, a chunk at a time.
pub(crate) struct TableEvalKernel<'a, 'f, M: Prepare, O>
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

impl<M: TableLanes + Clone, O: TableOp<M>> Kernel for TableEvalKernel<'_, '_, M, O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let n = self.n;
        let (wo, wi) = (cut(self.wo, n), cut(self.wi, n));
        let mut f = M::Spectrum::truncate(self.f, n);
        let m = self.m.clone();
        let (mut e_wo, mut e_wi) = ([0.0; CHUNK], [0.0; CHUNK]);
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
pub(crate) struct TablePdfKernel<'a, 'f, M> {
    pub(super) m: &'a M,
    pub(super) wo: Vec3s<'a>,
    pub(super) wi: Vec3s<'a>,
    pub(super) pdf: &'f mut [f32],
    pub(super) n: usize,
}

impl<M: TableLanes + Clone> Kernel for TablePdfKernel<'_, '_, M> {
    #[inline(always)]
    fn run(self) {
        let n = self.n;
        let (wo, wi) = (cut(self.wo, n), cut(self.wi, n));
        let pdf = &mut self.pdf[..n];
        let m = self.m.clone();
        let mut e_wo = [0.0; CHUNK];
        for (start, end) in chunks(n) {
            m.look_up(&wo.z[start..end], &mut e_wo);
            for (k, &e_wo) in (start..end).zip(&e_wo) {
                pdf[k] = m.pdf_prepared(&m.prepare_from(wo.get(k), e_wo), wi.get(k));
            }
        }
    }
}

/// `(wi, f, pdf, lobe, eta)[k] = sample(wo[k], u[k], uc[k])` over the first `n` lanes, zeros
/// (and [`Lobes::NONE`]) for no sample, a chunk at a time: the row at `wo.z`, the samples, the
/// row at the sampled directions' `wi.z` (where the samples are unfinished), their values.
pub(crate) struct TableSampleKernel<'a, 'f, M: Prepare, O>
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

impl<M: TableSample + Clone, O: TableSampleOp<M>> Kernel for TableSampleKernel<'_, '_, M, O>
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
        let (mut e_wo, mut e_wi) = ([0.0; CHUNK], [0.0; CHUNK]);
        // Per lane of the chunk: the value as drawn, what finishing it needs, and whether
        // there is a sample.
        let mut drawn = [M::Spectrum::zero(); CHUNK];
        let mut outgoing = [M::Spectrum::zero(); CHUNK];
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

/// [`Batch::eval_batch`](super::Batch::eval_batch) through [`TableEvalKernel`] with the lane
/// operation `O`.
#[inline(always)]
pub(super) fn table_eval<M: TableLanes + Clone, O: TableOp<M>>(
    m: &M,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    f: <M::Spectrum as Lanes>::Mut<'_>,
) -> Result<(), LengthError>
where
    M::Spectrum: Lanes,
{
    let n = same_length(&[wo.lanes()?, wi.lanes()?, M::Spectrum::lanes(&f)?])?;
    let op = PhantomData::<O>;
    dispatch(TableEvalKernel {
        m,
        wo,
        wi,
        f,
        n,
        op,
    });
    Ok(())
}

/// [`Batch::pdf_batch`](super::Batch::pdf_batch) through [`TablePdfKernel`].
#[inline(always)]
pub(super) fn table_pdf<M: TableLanes + Clone>(
    m: &M,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    pdf: &mut [f32],
) -> Result<(), LengthError> {
    let n = same_length(&[wo.lanes()?, wi.lanes()?, pdf.len()])?;
    dispatch(TablePdfKernel { m, wo, wi, pdf, n });
    Ok(())
}

/// [`Batch::sample_batch`](super::Batch::sample_batch) through [`TableSampleKernel`] with the
/// lane operation `O`.
#[inline(always)]
pub(super) fn table_sample<M: TableSample + Clone, O: TableSampleOp<M>>(
    m: &M,
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    out: SampleOut<'_, M::Spectrum>,
) -> Result<(), LengthError>
where
    M::Spectrum: Lanes,
{
    let n = same_length(&[
        wo.lanes()?,
        u.lanes()?,
        uc.len(),
        out.wi.lanes()?,
        M::Spectrum::lanes(&out.f)?,
        out.pdf.len(),
        out.lobe.len(),
        out.eta.len(),
    ])?;
    let op = PhantomData::<O>;
    dispatch(TableSampleKernel {
        m,
        wo,
        u,
        uc,
        out,
        n,
        op,
    });
    Ok(())
}
