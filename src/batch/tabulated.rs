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
//! Each chunk's loop takes its slices one to an argument, counts its lanes, and reads every
//! member of the buffers it reads (`docs/batched-loops.md`, rules 10 and 11): a short batch
//! then runs in the vectorised loop rather than in the scalar code beside it.
//!
//! The chunk's buffers live on the stack: up to 14 KiB for a `Vec4` compensated plastic's
//! `sample` (two tables' values per lane, and its lookups' temporaries), 11 KiB for a `Vec4`
//! compensated conductor's, 5 KiB for an `f32` one's, zeroed on every call. A call of at most
//! [`SHORT`] lanes takes buffers of that many lanes (a quarter of the size), so that a short
//! call does not pay for zeroing a long chunk's.

use super::kernel::{Density, Kernel, PairKernel, PairOut, SampleKernel, Value};
use super::lanes::{Lanes, Vec2s, Vec3s, Vec3sMut};
use super::lanes::{SHORT, chunks};
use super::{LengthError, SampleOut, lane_sample};
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
    /// The tables' values at each direction whose `z` is `z[k]`, into `e[k]` (at most `L`
    /// lanes; [`AlbedoRow::e_chunk`]).
    fn look_up<const L: usize>(&self, z: &[f32], e: &mut [Self::Looked; L]);
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
    /// prepared state, and the sampled direction's `wi_z = cos θi` (the glass reads the side
    /// from it) and tables' values `e_wi` there.
    fn finish(
        &self,
        f: Self::Spectrum,
        outgoing: Self::Outgoing,
        wi_z: f32,
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

/// A batched call's kernel ([`PairKernel`], [`SampleKernel`]) run a chunk
/// of `L` lanes at a time, for a table model's lane operation.
pub(crate) struct Chunked<const L: usize, K>(K);

/// A kernel's number of lanes.
pub(crate) trait Counted {
    /// The lanes the kernel runs.
    fn lanes(&self) -> usize;
}

impl<M, P: PairOut<M>> Counted for PairKernel<'_, '_, M, P> {
    #[inline(always)]
    fn lanes(&self) -> usize {
        self.n
    }
}

impl<M: Prepare, O> Counted for SampleKernel<'_, '_, M, O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn lanes(&self) -> usize {
        self.n
    }
}

/// `f[k] = eval(wo[k], wi[k])` over the first `n` lanes, a chunk at a time.
impl<const L: usize, M: TableLanes + Clone, O: TableOp<M>> Kernel
    for Chunked<L, PairKernel<'_, '_, M, Value<O>>>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn run(self) {
        let PairKernel {
            m, wo, wi, out, n, ..
        } = self.0;
        eval_chunks::<L, M, O>(&m.clone(), wo, wi, out, n);
    }
}

/// [`Chunked`] `eval` over `n` lanes, `L` at a time.
#[inline(always)]
fn eval_chunks<const L: usize, M: TableLanes, O: TableOp<M>>(
    m: &M,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    mut f: <M::Spectrum as Lanes>::Mut<'_>,
    n: usize,
) where
    M::Spectrum: Lanes,
{
    let placeholder = M::Looked::placeholder();
    let (mut e_wo, mut e_wi) = ([placeholder; L], [placeholder; L]);
    for (start, end) in chunks::<L>(n) {
        let (o, i) = (wo.range(start, end), wi.range(start, end));
        m.look_up(o.z, &mut e_wo);
        m.look_up(i.z, &mut e_wi);
        let f = M::Spectrum::lanes_of(&mut f, start, end);
        pair_chunk::<L, M, Value<O>>(m, o.x, o.y, o.z, &e_wo, i.x, i.y, i.z, &e_wi, f);
    }
}

/// How [`Chunked`] `eval` and `pdf` compute a lane from the prepared state: a [`TableOp`]'s
/// value ([`Value`]), or [`TableLanes::pdf_lane`]'s density (`Density<()>`).
trait ChunkPair<M: TableLanes>: PairOut<M> {
    /// The result at `wi`, whose tables' values are `e_wi`.
    fn lane(m: &M, at: &M::Prepared, wi: Vec3, e_wi: M::Looked) -> Self::Out;
}

impl<M: TableLanes, O: TableOp<M>> ChunkPair<M> for Value<O>
where
    M::Spectrum: Lanes,
{
    #[inline(always)]
    fn lane(m: &M, at: &M::Prepared, wi: Vec3, e_wi: M::Looked) -> M::Spectrum {
        O::eval(m, at, wi, e_wi)
    }
}

/// The density of a lane, which reads no table at `wi`.
impl<M: TableLanes> ChunkPair<M> for Density<()> {
    #[inline(always)]
    fn lane(m: &M, at: &M::Prepared, wi: Vec3, _: M::Looked) -> f32 {
        m.pdf_lane(at, wi)
    }
}

/// [`Chunked`] `eval`'s and `pdf`'s loop over one chunk, every slice an argument of its own
/// (the generic loops' rule: `docs/batched-loops.md`, rule 10).
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the point: one slice to an argument
fn pair_chunk<const L: usize, M: TableLanes, P: ChunkPair<M>>(
    m: &M,
    ox: &[f32],
    oy: &[f32],
    oz: &[f32],
    e_wo: &[M::Looked; L],
    ix: &[f32],
    iy: &[f32],
    iz: &[f32],
    e_wi: &[M::Looked; L],
    out: <P::Out as Lanes>::Mut<'_>,
) {
    let n = ox.len().min(L);
    let (ox, oy, oz) = (&ox[..n], &oy[..n], &oz[..n]);
    let (ix, iy, iz) = (&ix[..n], &iy[..n], &iz[..n]);
    let (e_wo, e_wi) = (&e_wo[..n], &e_wi[..n]);
    let mut out = P::Out::truncate(out, n);
    for k in 0..n {
        let at = m.prepare_from(Vec3::new(ox[k], oy[k], oz[k]), e_wo[k]);
        let wi = Vec3::new(ix[k], iy[k], iz[k]);
        P::Out::put(&mut out, k, P::lane(m, &at, wi, e_wi[k]));
    }
}

/// `pdf[k] = pdf(wo[k], wi[k])` over the first `n` lanes, a chunk at a time.
impl<const L: usize, M: TableLanes + Clone> Kernel
    for Chunked<L, PairKernel<'_, '_, M, Density<()>>>
{
    #[inline(always)]
    fn run(self) {
        let PairKernel {
            m, wo, wi, out, n, ..
        } = self.0;
        pdf_chunks::<L, M>(&m.clone(), wo, wi, out, n);
    }
}

/// [`Chunked`] `pdf` over `n` lanes, `L` at a time.
#[inline(always)]
fn pdf_chunks<const L: usize, M: TableLanes>(
    m: &M,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    pdf: &mut [f32],
    n: usize,
) {
    let mut e_wo = [M::Looked::placeholder(); L];
    for (start, end) in chunks::<L>(n) {
        let (o, i) = (wo.range(start, end), wi.range(start, end));
        m.look_up(o.z, &mut e_wo);
        let pdf = &mut pdf[start..end];
        // `pdf` reads no table at `wi`: `e_wo` stands in for it, unread.
        pair_chunk::<L, M, Density<()>>(m, o.x, o.y, o.z, &e_wo, i.x, i.y, i.z, &e_wo, pdf);
    }
}

/// `(wi, f, pdf, lobe, eta)[k] = sample(wo[k], u[k], uc[k])` over the first `n` lanes, zeros
/// (and [`Lobes::NONE`]) for no sample, a chunk at a time: the row at `wo.z`, the samples, the
/// row at the sampled directions' `wi.z` (where the samples are unfinished), their values.
impl<const L: usize, M: TableSample + Clone, O: TableSampleOp<M>> Kernel
    for Chunked<L, SampleKernel<'_, '_, M, O>>
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
        sample_chunks::<L, M, O>(&m.clone(), wo, u, uc, out, n);
    }
}

/// [`Chunked`] `sample` over `n` lanes, `L` at a time.
#[inline(always)]
fn sample_chunks<const L: usize, M: TableSample, O: TableSampleOp<M>>(
    m: &M,
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    out: SampleOut<'_, M::Spectrum>,
    n: usize,
) where
    M::Spectrum: Lanes,
{
    let SampleOut {
        mut wi,
        mut f,
        pdf,
        lobe,
        eta,
    } = out;
    let placeholder = M::Looked::placeholder();
    let (mut e_wo, mut e_wi) = ([placeholder; L], [placeholder; L]);
    let mut drawn = Drawn::<L, M> {
        f: [M::Spectrum::zero(); L],
        outgoing: [M::Outgoing::placeholder(); L],
        sampled: [false; L],
    };
    for (start, end) in chunks::<L>(n) {
        let (wo, u, uc) = (wo.range(start, end), u.range(start, end), &uc[start..end]);
        m.look_up(wo.z, &mut e_wo);
        let Vec3sMut {
            x: ix,
            y: iy,
            z: iz,
        } = wi.range(start, end);
        let (pdf, lobe) = (&mut pdf[start..end], &mut lobe[start..end]);
        let eta = &mut eta[start..end];
        draw_chunk::<L, M, O>(
            m, wo.x, wo.y, wo.z, &e_wo, u.x, u.y, uc, pdf, lobe, eta, ix, iy, iz, &mut drawn,
        );
        let f = M::Spectrum::lanes_of(&mut f, start, end);
        if O::UNFINISHED {
            m.look_up(iz, &mut e_wi);
            finish_chunk(m, &drawn, iz, &e_wi, f);
        } else {
            copy_chunk::<L, M>(&drawn.f, f, end - start);
        }
    }
}

/// A chunk's samples as drawn, per lane (`L` at most): the value, what finishing it needs of
/// the prepared state, and whether there is a sample.
struct Drawn<const L: usize, M: TableSample> {
    /// The values as drawn.
    f: [M::Spectrum; L],
    /// What [`TableSample::finish`] needs.
    outgoing: [M::Outgoing; L],
    /// Whether the lane has a sample.
    sampled: [bool; L],
}

/// [`Chunked`] `sample`'s draws over one chunk, every slice an argument of its own: the
/// densities, lobes, `η` and directions into the outputs, the values into `drawn`.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the point: one slice to an argument
fn draw_chunk<const L: usize, M: TableSample, O: TableSampleOp<M>>(
    m: &M,
    ox: &[f32],
    oy: &[f32],
    oz: &[f32],
    e_wo: &[M::Looked; L],
    ux: &[f32],
    uy: &[f32],
    uc: &[f32],
    pdf: &mut [f32],
    lobe: &mut [Lobes],
    eta: &mut [f32],
    ix: &mut [f32],
    iy: &mut [f32],
    iz: &mut [f32],
    drawn: &mut Drawn<L, M>,
) {
    let n = ox.len().min(L);
    let (ox, oy, oz) = (&ox[..n], &oy[..n], &oz[..n]);
    let (ux, uy, uc) = (&ux[..n], &uy[..n], &uc[..n]);
    let (ix, iy, iz) = (&mut ix[..n], &mut iy[..n], &mut iz[..n]);
    let (pdf, lobe, eta, e_wo) = (&mut pdf[..n], &mut lobe[..n], &mut eta[..n], &e_wo[..n]);
    let (f, outgoing, sampled) = (
        &mut drawn.f[..n],
        &mut drawn.outgoing[..n],
        &mut drawn.sampled[..n],
    );
    for k in 0..n {
        let at = m.prepare_from(Vec3::new(ox[k], oy[k], oz[k]), e_wo[k]);
        let u = Vec2::new(ux[k], uy[k]);
        let (w, v, p, l, e) = lane_sample(O::sample(m, &at, u, uc[k]));
        (ix[k], iy[k], iz[k]) = (w.x, w.y, w.z);
        (pdf[k], lobe[k], eta[k]) = (p, l, e);
        (f[k], outgoing[k], sampled[k]) = (v, M::outgoing(&at), l != Lobes::NONE);
    }
}

/// The values of a chunk's unfinished samples, whose directions' `z` is `iz` and tables'
/// values `e_wi`, into `f`: every lane finished and the value chosen after, so that the loop
/// has no branch.
#[inline(always)]
fn finish_chunk<const L: usize, M: TableSample>(
    m: &M,
    drawn: &Drawn<L, M>,
    iz: &[f32],
    e_wi: &[M::Looked; L],
    f: <M::Spectrum as Lanes>::Mut<'_>,
) where
    M::Spectrum: Lanes,
{
    let n = iz.len().min(L);
    let (v, o, s, e) = (
        &drawn.f[..n],
        &drawn.outgoing[..n],
        &drawn.sampled[..n],
        &e_wi[..n],
    );
    let mut f = M::Spectrum::truncate(f, n);
    for k in 0..n {
        let finished = m.finish(v[k], o[k], iz[k], e[k]);
        M::Spectrum::put(&mut f, k, if s[k] { finished } else { v[k] });
    }
}

/// The values of a chunk's finished samples into `f`'s first `n` lanes.
#[inline(always)]
fn copy_chunk<const L: usize, M: TableSample>(
    drawn: &[M::Spectrum; L],
    f: <M::Spectrum as Lanes>::Mut<'_>,
    n: usize,
) where
    M::Spectrum: Lanes,
{
    let n = n.min(L);
    let mut f = M::Spectrum::truncate(f, n);
    for (k, &v) in drawn[..n].iter().enumerate() {
        M::Spectrum::put(&mut f, k, v);
    }
}

/// [`run`](super::run)s a call's kernel in chunks: of [`SHORT`] lanes for a call of at most
/// that many, else of [`CHUNK`]. Each length is dispatched on its own: two lengths in one
/// dispatched function left the compensated glass's `eval` loop scalar under AVX2 (LLVM's
/// cost model called it not beneficial, in whichever came first).
#[inline(always)]
pub(super) fn chunked<K: Counted>(kernel: Result<K, LengthError>) -> Result<(), LengthError>
where
    Chunked<SHORT, K>: Kernel,
    Chunked<CHUNK, K>: Kernel,
{
    let kernel = kernel?;
    if kernel.lanes() <= SHORT {
        super::run(Ok(Chunked::<SHORT, K>(kernel)))
    } else {
        super::run(Ok(Chunked::<CHUNK, K>(kernel)))
    }
}
