//! The batched calls of the models built from other models ([`Mix`], [`TwoSided`], [`Mono`]):
//! a chunk of lanes at a time ([`PART`] where values of the spectrum are held, [`WIDE`]
//! otherwise; a call of at most [`SHORT`] lanes in space of that many) through their parts'
//! own batched calls, with the parts' inputs and outputs in stack space.
//!
//! A part's own batched call runs the loop written for it: a microfacet model's masking term
//! fixed outside the loop, a compensated model's tables looked up a chunk at a time. The
//! parts' prepared calls inlined into one loop of the whole model (what `Batch`'s provided
//! methods would compile) keep those choices inside the loop, and the loop stays scalar. Each
//! lane gets the scalar call's numbers: a part's batched call gives its scalar call's, and the
//! combination per lane is the scalar model's own (`Mix::finish` for a blend's sample).
//!
//! A stochastic blend (a layered part) samples through the provided loop instead: its sample
//! carries the chosen part's random-walk estimates, which are not its `eval` and `pdf`.

use super::kernel::Plain;
use super::lanes::{PART, Rows, SHORT, chunks};
use super::{Batch, Lanes, LengthError, SampleOut, Vec2s, Vec3s, Vec3sMut};
use super::{lane_sample, run, same_length, sample_kernel};
use crate::bxdf::{BxdfSample, Lobes, Mix, Mono, Prepare, TwoSided};
use crate::sampling::{picks, reuse_uniform};
use crate::spectrum::Spectrum;
use glam::Vec3;

/// How many lanes a call passes to its parts at a time where it needs no stack space for
/// values of the spectrum ([`Rows`] holds [`PART`] lanes): a part's call has a fixed cost
/// (its loop's set-up, a remainder of lanes that runs outside the vector loop) that a longer
/// chunk spreads thinner. `TwoSided(GGX gold)`'s `pdf` costs 1.3× more per lane at 256 than
/// at 1,024 in a probe (AVX2).
const WIDE: usize = 1024;

/// Calls `$f::<L, ..>($args)` with `L` = [`SHORT`] for a call of at most that many lanes,
/// else `$long`: a short call zeroes stack space of its own length, not a long chunk's.
macro_rules! by_length {
    ($n:expr, $long:ident, $f:ident::<L $(, $t:tt)*>($($a:expr),* $(,)?)) => {
        if $n <= SHORT {
            $f::<SHORT $(, $t)*>($($a),*)
        } else {
            $f::<$long $(, $t)*>($($a),*)
        }
    };
}

/// Stack space for a chunk of `L` 3-vectors.
type Rows3<const L: usize> = [[f32; L]; 3];

/// The first `n` lanes of `rows` as a [`Vec3s`].
#[inline(always)]
fn view<const L: usize>(rows: &Rows3<L>, n: usize) -> Vec3s<'_> {
    let [x, y, z] = rows;
    Vec3s {
        x: &x[..n],
        y: &y[..n],
        z: &z[..n],
    }
}

/// The first `n` lanes of `rows` as a [`Vec3sMut`].
#[inline(always)]
fn view_mut<const L: usize>(rows: &mut Rows3<L>, n: usize) -> Vec3sMut<'_> {
    let [x, y, z] = rows;
    Vec3sMut {
        x: &mut x[..n],
        y: &mut y[..n],
        z: &mut z[..n],
    }
}

/// Lane `k` of `rows`.
#[inline(always)]
fn get<const L: usize>(rows: &Rows3<L>, k: usize) -> Vec3 {
    Vec3::new(rows[0][k], rows[1][k], rows[2][k])
}

/// Writes lane `k` of `rows`.
#[inline(always)]
fn put<const L: usize>(rows: &mut Rows3<L>, k: usize, w: Vec3) {
    (rows[0][k], rows[1][k], rows[2][k]) = (w.x, w.y, w.z);
}

/// The lane count of a sample call's slices, which must agree (inlined, as the plain calls'
/// check is: `docs/batched-loops.md`, rule 13).
#[inline(always)]
fn sample_lanes<S: Lanes>(
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    out: &SampleOut<'_, S>,
) -> Result<usize, LengthError> {
    same_length(&[
        wo.lanes()?,
        u.lanes()?,
        uc.len(),
        out.wi.lanes()?,
        S::lanes(&out.f)?,
        out.pdf.len(),
        out.lobe.len(),
        out.eta.len(),
    ])
}

/// Lanes `start..end` of a sample call's outputs, reborrowed.
#[inline(always)]
fn out_range<'b, S: Lanes>(
    out: &'b mut SampleOut<'_, S>,
    start: usize,
    end: usize,
) -> SampleOut<'b, S> {
    SampleOut {
        wi: out.wi.range(start, end),
        f: S::lanes_of(&mut out.f, start, end),
        pdf: &mut out.pdf[start..end],
        lobe: &mut out.lobe[start..end],
        eta: &mut out.eta[start..end],
    }
}

/// A chunk's stack space for a part's samples, `L` lanes.
struct Samples<const L: usize> {
    wi: Rows3<L>,
    f: Rows<L>,
    pdf: [f32; L],
    lobe: [Lobes; L],
    eta: [f32; L],
}

impl<const L: usize> Samples<L> {
    /// Zeroed space.
    #[inline(always)]
    fn new() -> Self {
        Self {
            wi: [[0.0; L]; 3],
            f: [[0.0; L]; 4],
            pdf: [0.0; L],
            lobe: [Lobes::NONE; L],
            eta: [0.0; L],
        }
    }

    /// The first `n` lanes, for a part's sample call to write.
    #[inline(always)]
    fn out<S: Lanes>(&mut self, n: usize) -> SampleOut<'_, S> {
        SampleOut {
            wi: view_mut(&mut self.wi, n),
            f: S::rows_mut(&mut self.f, n),
            pdf: &mut self.pdf[..n],
            lobe: &mut self.lobe[..n],
            eta: &mut self.eta[..n],
        }
    }

    /// Lane `k`'s sample, `None` where the part had none ([`Lobes::NONE`] marks it: a sample
    /// may have a density of 0, a delta lobe of probability 0).
    #[inline(always)]
    fn get<S: Lanes>(&self, k: usize) -> Option<BxdfSample<S>> {
        (self.lobe[k] != Lobes::NONE).then(|| BxdfSample {
            wi: get(&self.wi, k),
            f: S::rows_get(&self.f, k),
            pdf: self.pdf[k],
            lobe: self.lobe[k],
            eta: self.eta[k],
        })
    }
}

/// Writes a sample (or, for `None`, the zeros of a lane without one) to lane `k` of `out`.
#[inline(always)]
fn put_sample<S: Lanes>(out: &mut SampleOut<'_, S>, k: usize, s: Option<BxdfSample<S>>) {
    let (w, v, p, l, e) = lane_sample(s);
    out.wi.put(k, w);
    S::put(&mut out.f, k, v);
    out.pdf[k] = p;
    out.lobe[k] = l;
    out.eta[k] = e;
}

impl<A, B> Batch for Mix<A, B>
where
    A: Batch,
    B: Batch<Spectrum = A::Spectrum>,
    A::Spectrum: Lanes,
{
    fn eval_batch(
        &self,
        wo: Vec3s<'_>,
        wi: Vec3s<'_>,
        f: <A::Spectrum as Lanes>::Mut<'_>,
    ) -> Result<(), LengthError> {
        let n = same_length(&[wo.lanes()?, wi.lanes()?, A::Spectrum::lanes(&f)?])?;
        by_length!(n, PART, mix_eval::<L, _, _>(self, wo, wi, f, n))
    }

    fn pdf_batch(&self, wo: Vec3s<'_>, wi: Vec3s<'_>, pdf: &mut [f32]) -> Result<(), LengthError> {
        let n = same_length(&[wo.lanes()?, wi.lanes()?, pdf.len()])?;
        by_length!(n, WIDE, mix_pdf::<L, _, _>(self, wo, wi, pdf, n))
    }

    /// Each part samples the lanes whose `uc` chose it, gathered into stack space, and the
    /// other part's value and density are evaluated at those samples' directions: the scalar
    /// calls' work, one part's sample and the other's evaluation per lane.
    fn sample_batch(
        &self,
        wo: Vec3s<'_>,
        u: Vec2s<'_>,
        uc: &[f32],
        out: SampleOut<'_, A::Spectrum>,
    ) -> Result<(), LengthError> {
        if self.stochastic() {
            return run(sample_kernel::<_, Plain>(self, wo, u, uc, out));
        }
        let n = sample_lanes(wo, u, uc, &out)?;
        by_length!(n, PART, mix_sample::<L, _, _>(self, wo, u, uc, out, n))
    }
}

/// [`Mix`]'s `eval_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn mix_eval<const L: usize, A, B>(
    mix: &Mix<A, B>,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    mut f: <A::Spectrum as Lanes>::Mut<'_>,
    n: usize,
) -> Result<(), LengthError>
where
    A: Batch,
    B: Batch<Spectrum = A::Spectrum>,
    A::Spectrum: Lanes,
{
    type S<A> = <A as Prepare>::Spectrum;
    let (mut fa, mut fb): (Rows<L>, Rows<L>) = ([[0.0; L]; 4], [[0.0; L]; 4]);
    for (start, end) in chunks::<L>(n) {
        let (o, i, m) = (wo.range(start, end), wi.range(start, end), end - start);
        mix.first().eval_batch(o, i, S::<A>::rows_mut(&mut fa, m))?;
        mix.second()
            .eval_batch(o, i, S::<A>::rows_mut(&mut fb, m))?;
        for k in 0..m {
            let v = mix.blend(S::<A>::rows_get(&fa, k), S::<A>::rows_get(&fb, k));
            S::<A>::put(&mut f, start + k, v);
        }
    }
    Ok(())
}

/// [`Mix`]'s `pdf_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn mix_pdf<const L: usize, A, B>(
    mix: &Mix<A, B>,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    pdf: &mut [f32],
    n: usize,
) -> Result<(), LengthError>
where
    A: Batch,
    B: Batch<Spectrum = A::Spectrum>,
    A::Spectrum: Lanes,
{
    let (mut pa, mut pb) = ([0.0; L], [0.0; L]);
    for (start, end) in chunks::<L>(n) {
        let (o, i, m) = (wo.range(start, end), wi.range(start, end), end - start);
        mix.first().pdf_batch(o, i, &mut pa[..m])?;
        mix.second().pdf_batch(o, i, &mut pb[..m])?;
        for (k, p) in pdf[start..end].iter_mut().enumerate() {
            *p = mix.blend_pdf(pa[k], pb[k]);
        }
    }
    Ok(())
}

/// [`Mix`]'s `sample_batch` over `n` lanes, a chunk of `L` at a time through a [`Share`].
#[inline(always)]
fn mix_sample<const L: usize, A, B>(
    mix: &Mix<A, B>,
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    mut out: SampleOut<'_, A::Spectrum>,
    n: usize,
) -> Result<(), LengthError>
where
    A: Batch,
    B: Batch<Spectrum = A::Spectrum>,
    A::Spectrum: Lanes,
{
    let (wa, wb) = (1.0 - mix.weight(), mix.weight());
    let share = &mut Share::<L>::new();
    for (start, end) in chunks::<L>(n) {
        let (o, v, c) = (wo.range(start, end), u.range(start, end), &uc[start..end]);
        share.gather(o, v, c, |uc| {
            picks(uc, wa).then(|| reuse_uniform(uc, 0.0, wa))
        });
        share.sample(mix, mix.first(), mix.second(), true, wa, &mut out, start)?;
        let b = |uc| (!picks(uc, wa)).then(|| reuse_uniform(uc, wa, wb));
        share.gather(o, v, c, b);
        share.sample(mix, mix.second(), mix.first(), false, wb, &mut out, start)?;
    }
    Ok(())
}

/// A part's share of a chunk of a blend's lanes (`L` at most): the lanes whose `uc` chose
/// it, gathered, and the stack space for its samples and the other part's evaluation at them.
struct Share<const L: usize> {
    /// How many lanes are gathered.
    n: usize,
    /// Each gathered lane's index in the chunk.
    lane: [u32; L],
    wo: Rows3<L>,
    u: [[f32; L]; 2],
    /// The `uc` the part gets (remapped to `[0, 1)` as in the scalar call).
    uc: [f32; L],
    samples: Samples<L>,
    /// The other part's value and density at each sample's direction.
    f: Rows<L>,
    pdf: [f32; L],
}

impl<const L: usize> Share<L> {
    /// Zeroed space.
    #[inline(always)]
    fn new() -> Self {
        Self {
            n: 0,
            lane: [0; L],
            wo: [[0.0; L]; 3],
            u: [[0.0; L]; 2],
            uc: [0.0; L],
            samples: Samples::new(),
            f: [[0.0; L]; 4],
            pdf: [0.0; L],
        }
    }

    /// Gathers the lanes of a chunk for which `part(uc)` gives the part's `uc`.
    #[inline(always)]
    fn gather(
        &mut self,
        wo: Vec3s<'_>,
        u: Vec2s<'_>,
        uc: &[f32],
        part: impl Fn(f32) -> Option<f32>,
    ) {
        self.n = 0;
        for (k, &c) in uc.iter().enumerate() {
            if let Some(c) = part(c) {
                let j = self.n;
                put(&mut self.wo, j, wo.get(k));
                (self.u[0][j], self.u[1][j], self.uc[j]) = (u.x[k], u.y[k], c);
                self.lane[j] = k as u32;
                self.n += 1;
            }
        }
    }

    /// Samples the gathered lanes with `drawn` (the blend's first part if `first`), chosen
    /// with probability `p`, evaluates `other` at the samples, and writes each lane's result
    /// to `out` (whose chunk starts at `start`) through `Mix::finish`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn sample<A, B, P, Q>(
        &mut self,
        mix: &Mix<A, B>,
        drawn: &P,
        other: &Q,
        first: bool,
        p: f32,
        out: &mut SampleOut<'_, A::Spectrum>,
        start: usize,
    ) -> Result<(), LengthError>
    where
        A: Prepare,
        B: Prepare<Spectrum = A::Spectrum>,
        P: Batch<Spectrum = A::Spectrum>,
        Q: Batch<Spectrum = A::Spectrum>,
        A::Spectrum: Lanes,
    {
        type S<A> = <A as Prepare>::Spectrum;
        let m = self.n;
        if m == 0 {
            return Ok(());
        }
        let (wo, u) = (
            view(&self.wo, m),
            Vec2s {
                x: &self.u[0][..m],
                y: &self.u[1][..m],
            },
        );
        let s = &mut self.samples;
        drawn.sample_batch(wo, u, &self.uc[..m], s.out(m))?;
        // A lane without a sample is evaluated at the normal, and its numbers unused.
        for j in 0..m {
            if s.lobe[j] == Lobes::NONE {
                put(&mut s.wi, j, Vec3::Z);
            }
        }
        other.eval_batch(wo, view(&s.wi, m), S::<A>::rows_mut(&mut self.f, m))?;
        other.pdf_batch(wo, view(&s.wi, m), &mut self.pdf[..m])?;
        for j in 0..m {
            let at = || (S::<A>::rows_get(&self.f, j), self.pdf[j]);
            let r = s.get(j).and_then(|x| mix.finish(x, p, first, at));
            put_sample(out, start + self.lane[j] as usize, r);
        }
        Ok(())
    }
}

/// The `z` of a chunk of `wo` seen from above, as [`TwoSided`] sees it.
#[inline(always)]
fn from_above<const L: usize>(wo_z: &[f32], up: &mut [f32; L]) {
    // Every slice cut to one length, so that the loop has no bounds checks and vectorises.
    let n = wo_z.len();
    let (z, up) = (&wo_z[..n], &mut up[..n]);
    for k in 0..n {
        up[k] = if z[k] < 0.0 { -z[k] } else { z[k] };
    }
}

/// Lanes `start..end` of `wo` and `wi` as [`TwoSided`] sees them: `wo` from above and `wi`
/// mirrored with it (their `z` written to `up` and `wi_up`).
#[inline(always)]
fn pair_from_above<'a, const L: usize>(
    (wo, wi): (Vec3s<'a>, Vec3s<'a>),
    (start, end): (usize, usize),
    up: &'a mut [f32; L],
    wi_up: &'a mut [f32; L],
) -> (Vec3s<'a>, Vec3s<'a>) {
    let oz = &wo.z[start..end];
    from_above(oz, up);
    // Cut to one length, as in `from_above`.
    let n = oz.len();
    let (oz, iz, mirrored) = (&oz[..n], &wi.z[start..end][..n], &mut wi_up[..n]);
    for k in 0..n {
        mirrored[k] = if oz[k] < 0.0 { -iz[k] } else { iz[k] };
    }
    (with_z(wo, start, end, up), with_z(wi, start, end, wi_up))
}

/// Lanes `start..end` of `w`, with the `z` of `z`.
#[inline(always)]
fn with_z<'a>(w: Vec3s<'a>, start: usize, end: usize, z: &'a [f32]) -> Vec3s<'a> {
    Vec3s {
        z: &z[..end - start],
        ..w.range(start, end)
    }
}

impl<B: Batch> Batch for TwoSided<B>
where
    B::Spectrum: Lanes,
{
    fn eval_batch(
        &self,
        wo: Vec3s<'_>,
        wi: Vec3s<'_>,
        f: <B::Spectrum as Lanes>::Mut<'_>,
    ) -> Result<(), LengthError> {
        let n = same_length(&[wo.lanes()?, wi.lanes()?, B::Spectrum::lanes(&f)?])?;
        by_length!(n, WIDE, two_sided_eval::<L, _>(self, wo, wi, f, n))
    }

    fn pdf_batch(&self, wo: Vec3s<'_>, wi: Vec3s<'_>, pdf: &mut [f32]) -> Result<(), LengthError> {
        let n = same_length(&[wo.lanes()?, wi.lanes()?, pdf.len()])?;
        by_length!(n, WIDE, two_sided_pdf::<L, _>(self, wo, wi, pdf, n))
    }

    fn sample_batch(
        &self,
        wo: Vec3s<'_>,
        u: Vec2s<'_>,
        uc: &[f32],
        out: SampleOut<'_, B::Spectrum>,
    ) -> Result<(), LengthError> {
        let n = sample_lanes(wo, u, uc, &out)?;
        by_length!(n, WIDE, two_sided_sample::<L, _>(self, wo, u, uc, out, n))
    }
}

/// [`TwoSided`]'s `eval_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn two_sided_eval<const L: usize, B: Batch>(
    two: &TwoSided<B>,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    mut f: <B::Spectrum as Lanes>::Mut<'_>,
    n: usize,
) -> Result<(), LengthError>
where
    B::Spectrum: Lanes,
{
    let (mut up, mut wi_up) = ([0.0; L], [0.0; L]);
    for (start, end) in chunks::<L>(n) {
        let (o, i) = pair_from_above((wo, wi), (start, end), &mut up, &mut wi_up);
        let out = B::Spectrum::lanes_of(&mut f, start, end);
        two.inner().eval_batch(o, i, out)?;
    }
    Ok(())
}

/// [`TwoSided`]'s `pdf_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn two_sided_pdf<const L: usize, B: Batch>(
    two: &TwoSided<B>,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    pdf: &mut [f32],
    n: usize,
) -> Result<(), LengthError>
where
    B::Spectrum: Lanes,
{
    let (mut up, mut wi_up) = ([0.0; L], [0.0; L]);
    for (start, end) in chunks::<L>(n) {
        let (o, i) = pair_from_above((wo, wi), (start, end), &mut up, &mut wi_up);
        two.inner().pdf_batch(o, i, &mut pdf[start..end])?;
    }
    Ok(())
}

/// [`TwoSided`]'s `sample_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn two_sided_sample<const L: usize, B: Batch>(
    two: &TwoSided<B>,
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    mut out: SampleOut<'_, B::Spectrum>,
    n: usize,
) -> Result<(), LengthError>
where
    B::Spectrum: Lanes,
{
    let mut up = [0.0; L];
    for (start, end) in chunks::<L>(n) {
        let oz = &wo.z[start..end];
        from_above(oz, &mut up);
        let (v, c) = (u.range(start, end), &uc[start..end]);
        let part = out_range(&mut out, start, end);
        two.inner()
            .sample_batch(with_z(wo, start, end, &up), v, c, part)?;
        // A sample drawn from above goes back below with `wo` (a lane without one stays 0).
        let (z, lobe) = (&mut out.wi.z[start..end], &out.lobe[start..end]);
        for k in 0..oz.len() {
            let below = (oz[k] < 0.0) & (lobe[k] != Lobes::NONE);
            z[k] = if below { -z[k] } else { z[k] };
        }
    }
    Ok(())
}

impl<B, S> Batch for Mono<B, S>
where
    B: Batch<Spectrum = f32>,
    S: Spectrum + Lanes,
{
    fn eval_batch(&self, wo: Vec3s<'_>, wi: Vec3s<'_>, f: S::Mut<'_>) -> Result<(), LengthError> {
        let n = same_length(&[wo.lanes()?, wi.lanes()?, S::lanes(&f)?])?;
        by_length!(n, WIDE, mono_eval::<L, _, _>(self, wo, wi, f, n))
    }

    fn pdf_batch(&self, wo: Vec3s<'_>, wi: Vec3s<'_>, pdf: &mut [f32]) -> Result<(), LengthError> {
        self.inner().pdf_batch(wo, wi, pdf)
    }

    fn sample_batch(
        &self,
        wo: Vec3s<'_>,
        u: Vec2s<'_>,
        uc: &[f32],
        out: SampleOut<'_, S>,
    ) -> Result<(), LengthError> {
        let n = sample_lanes(wo, u, uc, &out)?;
        by_length!(n, WIDE, mono_sample::<L, _, _>(self, wo, u, uc, out, n))
    }
}

/// [`Mono`]'s `eval_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn mono_eval<const L: usize, B, S>(
    mono: &Mono<B, S>,
    wo: Vec3s<'_>,
    wi: Vec3s<'_>,
    mut f: S::Mut<'_>,
    n: usize,
) -> Result<(), LengthError>
where
    B: Batch<Spectrum = f32>,
    S: Spectrum + Lanes,
{
    let mut g = [0.0; L];
    for (start, end) in chunks::<L>(n) {
        let g = &mut g[..end - start];
        mono.inner()
            .eval_batch(wo.range(start, end), wi.range(start, end), g)?;
        for (k, &v) in g.iter().enumerate() {
            S::put(&mut f, start + k, S::splat(v));
        }
    }
    Ok(())
}

/// [`Mono`]'s `sample_batch` over `n` lanes, `L` at a time.
#[inline(always)]
fn mono_sample<const L: usize, B, S>(
    mono: &Mono<B, S>,
    wo: Vec3s<'_>,
    u: Vec2s<'_>,
    uc: &[f32],
    mut out: SampleOut<'_, S>,
    n: usize,
) -> Result<(), LengthError>
where
    B: Batch<Spectrum = f32>,
    S: Spectrum + Lanes,
{
    let mut g = [0.0; L];
    for (start, end) in chunks::<L>(n) {
        let g = &mut g[..end - start];
        let (o, v, c) = (wo.range(start, end), u.range(start, end), &uc[start..end]);
        let inner = SampleOut {
            wi: out.wi.range(start, end),
            f: &mut *g,
            pdf: &mut out.pdf[start..end],
            lobe: &mut out.lobe[start..end],
            eta: &mut out.eta[start..end],
        };
        mono.inner().sample_batch(o, v, c, inner)?;
        for (k, &v) in g.iter().enumerate() {
            S::put(&mut out.f, start + k, S::splat(v));
        }
    }
    Ok(())
}
