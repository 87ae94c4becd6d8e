//! The batched calls (`lobe::batch`) on the fuzz's inputs, lane for lane against the scalar
//! calls' answers, bit for bit.
//!
//! `tests/batch.rs` compares the two paths over 4,099 adversarial lanes per model; this runs
//! every configuration of the fuzz (widths and indices at the ends of their ranges, every
//! masking term and transport mode) through them, each `catch_unwind` batch of inputs cut into
//! calls from 1 to 1,025 lanes long ([`CALLS`]), on the instruction set the run-time dispatch
//! picks for this CPU. A lane without a sample must have every output zero and the lobe
//! [`Lobes::NONE`](lobe::bxdf::Lobes::NONE), as `SampleOut` documents.

use super::soa::{Buffers, eval_pdf_batched, same, sample_batched};
use super::{Input, Kind, Tally};
use core::ops::Range;
use lobe::batch::Batch;
use lobe::bxdf::BxdfSample;
use lobe::{Vec2, Vec3};

/// The scalar calls' answers for one input.
pub struct Scalar<S> {
    /// `eval`'s.
    pub f: S,
    /// `pdf`'s.
    pub pdf: f32,
    /// `sample`'s.
    pub sample: Option<BxdfSample<S>>,
}

/// The lengths of the batched calls that [`check`] cuts its inputs into, in turn (what is left
/// after the last is one more call): around the vector widths (8 and 16 lanes), the longest
/// call that takes short buffers (64), the chunks of 256 lanes (the tables' passes, `Mix`'s,
/// `TwoSided`'s and `Mono`'s values) and of 1,024 (`Mix`'s densities, `TwoSided`'s and
/// `Mono`'s `z`), so that every form of the loops (short buffers, chunked passes, the lanes
/// after the last full vector or chunk) meets the adversarial lanes. A batch shorter than
/// their sum stops early: the corner grid's 2,268 inputs end with a call of 658 lanes after
/// the one of 511.
const CALLS: [usize; 19] = [
    1, 2, 7, 8, 9, 15, 16, 17, 31, 33, 63, 64, 65, 255, 256, 257, 511, 1024, 1025,
];

/// The lanes of each batched call over `n` inputs: [`CALLS`], then the rest.
pub fn calls(n: usize) -> impl Iterator<Item = Range<usize>> {
    let lengths = CALLS.into_iter().chain(core::iter::repeat(n));
    lengths
        .scan(0, move |start, len| {
            let r = *start..n.min(*start + len);
            *start = r.end;
            Some(r)
        })
        .take_while(|r| !r.is_empty())
}

/// Runs `inputs` through `m`'s batched `eval`, `pdf` and `sample`, in calls of the lengths
/// [`CALLS`] ([`check_call`]).
pub fn check<M>(m: &M, inputs: &[Input], want: &[Scalar<M::Spectrum>], t: &mut Tally)
where
    M: Batch<Spectrum: Buffers>,
{
    for r in calls(inputs.len()) {
        check_call(m, &inputs[r.clone()], &want[r], t);
    }
}

/// Runs `inputs` through `m`'s batched `eval`, `pdf` and `sample`, one call each, and counts a
/// [`Kind::Batched`] failure for every lane and call whose answer differs from `want`'s.
pub fn check_call<M>(m: &M, inputs: &[Input], want: &[Scalar<M::Spectrum>], t: &mut Tally)
where
    M: Batch<Spectrum: Buffers>,
{
    let wo: Vec<Vec3> = inputs.iter().map(|x| x.wo).collect();
    let wi: Vec<Vec3> = inputs.iter().map(|x| x.wi).collect();
    let u: Vec<Vec2> = inputs.iter().map(|x| x.u).collect();
    let uc: Vec<f32> = inputs.iter().map(|x| x.uc).collect();
    let values = eval_pdf_batched(m, &wo, &wi);
    let samples = sample_batched(m, &wo, &u, &uc);

    for (k, (x, w)) in inputs.iter().zip(want).enumerate() {
        let got = M::Spectrum::read(&values.f, k);
        if !same(got, w.f) {
            let v = format_args!("{got:?} batched, {:?} scalar", w.f);
            t.fail(Kind::Batched, "eval_batch", x, &v);
        }
        if !same(values.pdf[k], w.pdf) {
            let v = format_args!("{:?} batched, {:?} scalar", values.pdf[k], w.pdf);
            t.fail(Kind::Batched, "pdf_batch", x, &v);
        }
        let lane = samples.lane(k);
        if !lane.agrees(w.sample.as_ref()) {
            let v = format_args!("{lane:?} batched, {:?} scalar", w.sample);
            t.fail(Kind::Batched, "sample_batch", x, &v);
        }
    }
}
