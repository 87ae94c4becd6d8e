//! The batched `eval` and `pdf` of a model that reads an albedo table at each lane's
//! directions (the energy-compensated microfacet model): a chunk of lanes at a time, the
//! table first ([`AlbedoRow::e_chunk`]), then the model's arithmetic in a loop that reads no
//! table.
//!
//! A read at a different place in each lane is a gather. On a target with AVX2 and no
//! AVX-512, LLVM's cost model takes gathers for slow and then leaves the whole loop scalar:
//! with the lookups in a pass of their own the rest vectorises (the [module docs](super) have
//! the figures). The numbers are those of the scalar path: the same lookups, the same
//! arithmetic, in another order of lanes.

use super::kernel::{Kernel, cut, dispatch};
use super::lanes::{Lanes, Vec3s};
use super::{LengthError, same_length};
use crate::bxdf::Prepare;
use crate::tables::{AlbedoRow, CHUNK};
use core::marker::PhantomData;
use glam::Vec3;

/// A model whose prepared state reads one [`AlbedoRow`] at `μo = wo.z`.
pub(crate) trait TableLanes: Prepare {
    /// The row read at each lane's directions.
    fn row(&self) -> &AlbedoRow;
    /// [`Prepare::prepare`] with the row's value at `wo.z` given as `e_wo`.
    fn prepare_given(&self, wo: Vec3, e_wo: f32) -> Self::Prepared;
}

/// How one lane's value is computed from the prepared state and the row's value at `wi.z`.
pub(crate) trait TableOp<M: TableLanes> {
    /// `eval(wo, wi)`, with `e_wi` the row's value at `wi.z`.
    fn eval(m: &M, at: &M::Prepared, wi: Vec3, e_wi: f32) -> M::Spectrum;
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
            m.row().e_chunk(&wo.z[start..end], &mut e_wo);
            m.row().e_chunk(&wi.z[start..end], &mut e_wi);
            for (j, k) in (start..end).enumerate() {
                let at = m.prepare_given(wo.get(k), e_wo[j]);
                M::Spectrum::put(&mut f, k, O::eval(&m, &at, wi.get(k), e_wi[j]));
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
            m.row().e_chunk(&wo.z[start..end], &mut e_wo);
            for (j, k) in (start..end).enumerate() {
                pdf[k] = m.pdf_prepared(&m.prepare_given(wo.get(k), e_wo[j]), wi.get(k));
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
