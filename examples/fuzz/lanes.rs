//! The batched calls (`lobe::batch`) on the fuzz's inputs, lane for lane against the scalar
//! calls' answers, bit for bit.
//!
//! `tests/batch.rs` compares the two paths over 4,099 adversarial lanes per model; this runs
//! every configuration of the fuzz (widths and indices at the ends of their ranges, every
//! masking term and transport mode) through them, each `catch_unwind` batch of inputs cut into
//! calls from 1 to 1,025 lanes long ([`CALLS`]), on the instruction set the run-time dispatch
//! picks for this CPU. A lane without a sample must have every output zero and the lobe
//! [`Lobes::NONE`](lobe::bxdf::Lobes::NONE), as `SampleOut` documents.

use super::soa::{Buffers, Soa, UNWRITTEN, same};
use super::{Input, Kind, Tally};
use core::ops::Range;
use lobe::batch::{Batch, SampleOut, Vec2s};
use lobe::bxdf::{BxdfSample, Lobes};
use lobe::{Spectrum, Vec3};

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
    let n = inputs.len();
    let wo = Soa::of(&inputs.iter().map(|x| x.wo).collect::<Vec<_>>());
    let wi = Soa::of(&inputs.iter().map(|x| x.wi).collect::<Vec<_>>());
    let (ux, uy): (Vec<f32>, Vec<f32>) = inputs.iter().map(|x| (x.u.x, x.u.y)).unzip();
    let uc: Vec<f32> = inputs.iter().map(|x| x.uc).collect();

    let mut f = M::Spectrum::store(n);
    let mut pdf = vec![UNWRITTEN; n];
    let (mut s_wi, mut s_f, mut s_pdf) =
        (Soa::unwritten(n), M::Spectrum::store(n), vec![UNWRITTEN; n]);
    // Values no lane writes (no sample comes from reflection and transmission at once), so
    // that a lane the loop skipped shows.
    let never = Lobes::REFLECTION | Lobes::TRANSMISSION | Lobes::SPECULAR;
    let (mut s_lobe, mut s_eta) = (vec![never; n], vec![-1.0; n]);
    let lengths = "the inputs' and outputs' slices have one length";
    m.eval_batch(wo.view(), wi.view(), M::Spectrum::lanes_mut(&mut f))
        .expect(lengths);
    m.pdf_batch(wo.view(), wi.view(), &mut pdf).expect(lengths);
    let out = SampleOut {
        wi: s_wi.view_mut(),
        f: M::Spectrum::lanes_mut(&mut s_f),
        pdf: &mut s_pdf,
        lobe: &mut s_lobe,
        eta: &mut s_eta,
    };
    m.sample_batch(wo.view(), Vec2s { x: &ux, y: &uy }, &uc, out)
        .expect(lengths);

    for (k, (x, w)) in inputs.iter().zip(want).enumerate() {
        let got = M::Spectrum::read(&f, k);
        if !same(got, w.f) {
            let v = format_args!("{got:?} batched, {:?} scalar", w.f);
            t.fail(Kind::Batched, "eval_batch", x, &v);
        }
        if !same(pdf[k], w.pdf) {
            let v = format_args!("{:?} batched, {:?} scalar", pdf[k], w.pdf);
            t.fail(Kind::Batched, "pdf_batch", x, &v);
        }
        let (d, v, p) = (s_wi.get(k), M::Spectrum::read(&s_f, k), s_pdf[k]);
        let (lobe, eta) = (s_lobe[k], s_eta[k]);
        let agrees = match &w.sample {
            Some(s) => {
                same(d, s.wi)
                    && same(v, s.f)
                    && same(p, s.pdf)
                    && lobe == s.lobe
                    && same(eta, s.eta)
            }
            None => {
                same(d, Vec3::ZERO)
                    && same(v, M::Spectrum::zero())
                    && same(p, 0.0)
                    && lobe == Lobes::NONE
                    && same(eta, 0.0)
            }
        };
        if !agrees {
            let got = format_args!("({d:?}, {v:?}, {p:?}, {lobe}, {eta:?}) batched");
            let v = format_args!("{got}, {:?} scalar", w.sample);
            t.fail(Kind::Batched, "sample_batch", x, &v);
        }
    }
}
