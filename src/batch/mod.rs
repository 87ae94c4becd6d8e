//! Batched shading: `eval`, `pdf` and `sample` over structure-of-arrays batches, compiled for
//! the widest SIMD the CPU has.
//!
//! A renderer that shades many points at once (a wavefront path tracer, a GPU-style
//! queue on the CPU) hands a model slices of directions and random numbers, one slice per
//! coordinate ([`Vec3s`], [`Vec2s`]), and slices to write into: the values per channel
//! ([`Lanes`]), the densities, the sampled directions ([`Vec3sMut`]). Every model of the crate
//! implements [`Batch`]:
//!
//! ```
//! use lobe::batch::{Batch, Vec3s, Vec3sMut};
//! use lobe::bxdf::{Bxdf, Microfacet};
//! use lobe::fresnel::Schlick;
//! use lobe::microfacet::{Ggx, Masking};
//! use lobe::{Alpha, Vec3};
//! let brdf = Microfacet::new(
//!     Ggx::isotropic(Alpha::new(0.3)?),
//!     Masking::HeightCorrelated,
//!     Schlick::new(Vec3::new(0.95, 0.64, 0.54))?,
//! );
//! // Two viewer and two light directions, one slice per coordinate.
//! let wo = Vec3s { x: &[0.0, 0.6], y: &[0.6, 0.0], z: &[0.8, 0.8] };
//! let wi = Vec3s { x: &[0.0, -0.6], y: &[-0.6, 0.0], z: &[0.8, 0.8] };
//! let (mut r, mut g, mut b) = ([0.0; 2], [0.0; 2], [0.0; 2]);
//! brdf.eval_batch(wo, wi, Vec3sMut { x: &mut r, y: &mut g, z: &mut b })?;
//! let one = brdf.eval(Vec3::new(0.6, 0.0, 0.8), Vec3::new(-0.6, 0.0, 0.8));
//! assert_eq!(Vec3::new(r[1], g[1], b[1]), one); // the scalar path's value, bit for bit
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! **The same numbers as the scalar path.** A batched call runs the model's own scalar code
//! ([`Prepare`]) on every lane (the exceptions, below: some models' lanes run a second form
//! written beside the scalar one and equal to it by construction, and look their albedo tables
//! up in passes of their own, by the scalar path's lookup; the models built from others call
//! their parts' batched calls), and the results
//! equal `eval`, `pdf` and `sample` bit for bit where the compiler keeps the operations as
//! written (it does not contract or reassociate `f32` arithmetic, so that is every lane the
//! tests have seen; `tests/batch.rs` checks adversarial lanes — grazing, below the horizon,
//! mirror pairs — against the scalar calls, and the fuzz example, `examples/fuzz/`, the 187 M
//! inputs of its configurations).
//!
//! **Preconditions are not checked.** The scalar `eval`, `pdf` and `sample` assert unit
//! directions and random numbers in `[0, 1]` in debug builds; the batched calls, like the
//! `*_prepared` calls they run, check nothing (a check per lane would keep the loop from
//! vectorising in the debug builds where tests run). A lane given other finite inputs gets a
//! finite, non-negative answer, the scalar path's.
//!
//! **Speed.** The loops are written so that the compiler vectorises them: inputs and outputs are
//! separate slices re-sliced to one length (no bounds checks inside the loop) and passed to the
//! loop one to an argument (so that the compiler knows no two overlap, checks at run time only a
//! spectrum's output channels against each other, and vectorises from 8 lanes on under AVX2, 16
//! under AVX-512: a call of 16 lanes runs at 0.2–0.4× of the scalar calls for the GGX conductor
//! under AVX2, `cargo bench --bench batched -- --lanes 16`, the `eval` of Oren-Nayar, EON, Disney
//! diffuse and the diffuse transmitter at 0.33–0.62× and `Lambert`'s, mostly the call's fixed cost,
//! at about 1×, `docs/batched-loops.md`, rule 10; under AVX2 a call of fewer than 8 lanes fills no
//! vector, and at 4 lanes the calls timed in the repository's `docs/benchmarks.md` run at 1.1–3.9×
//! of the scalar calls: call those), the per-lane code is inlined, its early returns become
//! selects, and what the loop would branch on per call (a microfacet model's masking term) is fixed
//! outside it. Each loop runs on its own copy of the model (a clone per batched call, hence
//! [`Batch`]'s `Clone` bound), whose parameters the compiler then keeps in registers: read through
//! the caller's reference, a parameter that only some lanes reach (behind a lane's early return)
//! was vectorised as a masked gather from one address, every iteration — ten of them in the GGX
//! gold conductor's `eval` loop, a quarter of its time. The hot models' lane code has no library
//! calls (sine and cosine are [`crate::math::sin_cos_turns`]); a lane that calls one (Beckmann's
//! `erfc`, Phong's `powf`) still runs, one lane at a time. The microfacet models (plain and
//! energy-compensated, reflecting and refracting) have one loop per masking term, and the
//! energy-compensated microfacet model one per masking term and compensation (with the choice
//! between Kulla & Conty's lobe and Turquin's scaling inside the loop, LLVM weighed both samplers
//! in every lane). That model's loops, both plastics' and the compensated glass's take 256 lanes at
//! a time: a pass looks the albedo table up at each lane's `wo` (and `wi`), the
//! [`AlbedoRow`](crate::tables::AlbedoRow) lookup split into the positions, which vectorise, and
//! the reads (the compensated plastic looks up two tables, its coat albedo and the coat's own; the
//! glass both sides' rows, then keeps each lane's side with a select); then the model's arithmetic
//! runs in a loop that reads no table; `sample` then looks the tables up at the sampled directions
//! and adds what needs them (the compensation lobe's value, the plastic's diffuse term) in a last
//! pass. Each pass takes the chunk's slices one to an argument, as the plain loops do. The chunk's
//! buffers are on the stack (up to 14 KiB, for a `Vec4` compensated plastic's `sample`), zeroed on
//! each call: a call of at most 64 lanes takes buffers of 64 lanes, so that it does not pay for a
//! long chunk's (at 16 lanes a call these models run at 0.28–0.44× of the scalar calls, AVX2). A
//! microfacet model's loops, and the energy-compensated microfacet model's, take the Fresnel term
//! channel by channel ([`Fresnel::eval_per_channel`](crate::fresnel::Fresnel::eval_per_channel)):
//! the exact conductor's scalar `eval` puts an RGB spectrum's channels side by side in one SIMD
//! register, which a loop cannot widen across calls (the same numbers either way). The other loops
//! run that scalar form, one call per lane. A model whose `sample` picks one of two lobes per lane
//! branches between them; the energy-compensated microfacet model's batched `sample` instead draws
//! both lobes' directions in every lane and keeps the one the lane picks, which vectorises for GGX
//! (the same numbers: each lobe's value and density come from the same arithmetic; Beckmann's
//! sampler, a Newton iteration, runs one lane at a time and leaves that model's batched `sample` at
//! about the scalar speed either way); so do both plastics' (the plastic's diffuse lobe and the
//! compensated coat's compensation lobe draw the same cosine-weighted direction, so a lane forms
//! two directions and evaluates the coat once). The plastics' loops call the coat with its masking
//! term (and the compensated coat's compensation) fixed, as the microfacet models' loops do (read
//! per lane, the term kept the loop from vectorising). The compensated glass's batched `sample`
//! forms the compensation lobes' direction and the interface's in every lane and evaluates the
//! interface once, at the one the lane picks; an index-matched interface's delta sample (the same
//! for every lane) is chosen by a select, not a branch: that branch, and a short-circuit `||` in
//! the glass's prepared state, had kept its `sample` and `pdf` loops scalar under AVX2 (LLVM's
//! loop-vectoriser remarks, `-C llvm-args=-pass-remarks-missed=loop-vectorize`, name the loops it
//! leaves and why).
//!
//! **Under AVX2 without AVX-512** LLVM's cost model weighs a gather, an `f64` operation and a
//! branch that a loop must turn into selects more heavily than under AVX-512, and some loops stay
//! scalar there, or nearly (measured on an AMD EPYC with AVX2 and FMA only, 2026-11-29; the
//! repository's `docs/benchmarks.md` has the run, under "Against other implementations"). The
//! energy-compensated microfacet model's loops, both plastics' and the compensated glass's stayed
//! scalar until they looked their tables up in passes of their own (above), and their `sample`
//! evaluated the drawn lobe without early returns and finished its lanes without a branch:
//! `cargo bench -p lobe-peers`, old and new builds interleaved over three rounds, 4,096 lanes, the
//! batched calls went to 0.20× (`eval`), 0.23× (`pdf`) and 0.21× (`sample`) of the old for the
//! compensated gold conductor, 0.19×, 0.64× and 0.30× for the plastic (whose `pdf` loop was already
//! vectorised) and 0.25×, 0.20× and 0.30× for the compensated plastic (a probe, five rounds, had
//! the compensated Schlick conductor's at 0.64×, 0.33× and 0.43×); the compensated glass's, once
//! its lanes lost their last branches (above), 0.38×, 0.27× and 0.37× (the same bench, three
//! rounds). The rough dielectric's `eval` and `sample` stayed scalar there too until their batched
//! loops took forms without early returns: every lane forms both directions, the configuration and
//! the value, and an unusable lane discards them (the same numbers). With its `f64` half vector
//! (for refraction `wo + η' wi` cancels), the branches had tipped the balance. AVX-512 vectorised
//! all of them before the table passes; the passes are not measured there. Three more ran slower
//! batched than scalar under AVX2 (0.6–0.7×, the repository's `docs/benchmarks.md` has the
//! figures): EON, whose albedo's form (exact or fitted) its lanes read (now fixed outside the loop,
//! as the masking terms are), and the smooth glass and the glazed model, whose `sample` a loop
//! called once per lane (now inlined always; the glazed model's also without branches). The diffuse
//! transmitter's `sample` vectorised under AVX-512 but not under AVX2 (LLVM's cost model judged
//! eight lanes not worth it) until it lost its early return for a tangent `wo`, which its density
//! refuses anyway, and its side was chosen by a select.
//!
//! **Models built from others.** [`Mix`](crate::bxdf::Mix), [`TwoSided`](crate::bxdf::TwoSided) and
//! [`Mono`](crate::bxdf::Mono) pass a chunk of lanes at a time to their parts' own batched calls,
//! with the parts' inputs and outputs in stack space, so that each part runs the loop written for
//! it: a microfacet part's loop has its masking term fixed, a compensated part's looks its tables
//! up in passes. Their parts must therefore implement [`Batch`] themselves (every model of the
//! crate does; a model of your own gets it from `impl Batch for MyModel {}`). Inlined into one loop
//! of the whole blend, a microfacet part's choice of masking term stayed inside the loop, which
//! stayed scalar: the batched `Mix(Lambert, GGX gold)` `eval` cost what the scalar calls did. A
//! blend's `sample` gathers the lanes whose `uc` chose each part, has that part sample them and the
//! other part evaluate its value and density at the sampled directions (which blend with the
//! sampled part's, as in the scalar call), and scatters the results back: the scalar calls' work,
//! one part's sample and the other's evaluation per lane. A blend with a stochastic part (a layered
//! model) samples through the provided loop: its sample carries the chosen part's random-walk
//! estimates, not `eval`'s and `pdf`'s. Stack space, per call: 21 KiB for a blend's `sample` (256
//! lanes; each level of a nested blend adds its own), 8 KiB for its `eval` (256 lanes of values of
//! up to four channels) and `pdf` (1,024 lanes), 8 KiB for `TwoSided` (the mirrored `z` of 1,024
//! lanes of `wo` and `wi`), 4 KiB for `Mono` (1,024 values). A call of at most 64 lanes takes space
//! for 64: the space is zeroed on every call, and the long chunks' space cost a short call more
//! than its parts did (`TwoSided(GGX gold)`'s `pdf` at 16 lanes a call spent more than half its
//! time in `memset`). Each part's call has a fixed cost (its loop's set-up, a remainder that runs
//! outside the vector loop) that these chunk lengths keep to a few percent.
//! `cargo bench --bench batched` times every model's batched calls against its scalar calls; the
//! repository's `docs/benchmarks.md` has a run. The rules these loops follow, and how to find why
//! one stays scalar, are in the repository's `docs/batched-loops.md`.
//!
//! **Batch size.** Keep a batch within the L2 cache: an RGB `eval`'s slices take 36 bytes per lane,
//! so 2¹⁵ lanes are 1.1 MiB (the machine measured here has a 2 MiB L2). The outputs are written
//! with ordinary stores, which read each cache line before writing it; past the L2 that doubles an
//! output's memory traffic, and a model as light as a memory pass (`wo + wi`) waits on it:
//! Lambert's batched `eval` costs 0.45–0.49 ns per lane over 4,096 and 2¹⁵ lanes and 0.90 over 2²⁰,
//! the GGX Schlick conductor's 1.3 and 1.5, the GGX gold conductor's 4.9 and 5.1 (its arithmetic
//! hides the traffic; `batch-timing sizes` in the repository's `docs/benchmarks.md`). A streaming
//! store would skip the read, but it needs `unsafe`, and within the L2 it made a memory pass 1.8×
//! slower: it sends every line on to memory, where an ordinary store leaves it in the cache for the
//! next stage (the comparison with Mitsuba 3 in the repository's `docs/benchmarks.md`, whose JIT
//! streams its stores, has the figures).
//!
//! **Run-time dispatch.** The default `x86_64` target has only SSE2, and a library cannot
//! ask its users for `-C target-cpu=native`. On x86 and x86_64 each batched call asks the
//! [`pulp`](https://docs.rs/pulp) crate for the widest instruction set the CPU has — AVX-512
//! (x86-64-v4), AVX2 with FMA (v3), or the baseline — and runs the loop compiled for it (the
//! delta models' `eval` and `pdf`, which only write zeros, skip the dispatch, which cost more
//! than their loop at 16 lanes a call: [`Batch::DELTA_ONLY`]). pulp does the `unsafe` part
//! (calling a `#[target_feature]` function after checking the CPU), so this crate keeps
//! `#![forbid(unsafe_code)]`; it was chosen over hand-written intrinsics for that, and over
//! `multiversion`, whose generated code is `unsafe` in the calling crate. Other targets run
//! the same loop compiled for the target's own features: the portable fallback.
//! The dispatch needs the `std` feature (the default): without it, on x86, the batched calls
//! run the baseline loop only, compiled for the target's own features (SSE2 on the default
//! `x86_64` target; more if the build enables more, with `-C target-cpu` or `-C
//! target-feature`). Using AVX takes both a CPU that has it and an operating system that saves
//! its registers; std's feature detection checks both (XCR0), while pulp without std reads
//! CPUID alone, which would pick AVX2 or AVX-512 in a kernel or a UEFI application that has
//! not enabled them, where the first AVX instruction faults. Checking XCR0 needs `unsafe`
//! (`xgetbv`), which this crate forbids, and pulp offers no safe check without std.
//! [`instruction_set`] says which path this CPU runs. Every path gives the scalar path's
//! numbers, bit for bit: `tests/batch.rs` checks the machine's own path, and CI, where QEMU's
//! user mode can be installed, runs it again emulating a CPU with AVX2 and one with the
//! baseline only, and built for aarch64.
//!
//! **Lengths.** Every slice of a call must have the same length; otherwise the call writes
//! nothing and returns [`LengthError`]. It never panics.

mod isa;
mod kernel;
mod lanes;
mod models;
mod parts;
mod tabulated;

pub use isa::{InstructionSet, instruction_set};
#[doc(hidden)]
pub use lanes::Rows;
pub use lanes::{Lanes, Vec2s, Vec3s, Vec3sMut, Vec4sMut};

use crate::bxdf::{BxdfSample, Lobes, Prepare};
use crate::spectrum::Spectrum;
use core::fmt;
use glam::Vec3;
use kernel::{Density, Kernel, PairKernel, PairOut, Plain, SampleKernel, Value, dispatch};

/// A batched call's slices disagree in length; nothing was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LengthError {
    /// The first slice's length.
    pub expected: usize,
    /// A slice whose length differs.
    pub found: usize,
}

impl fmt::Display for LengthError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "batched slices differ in length: {} and {}",
            self.expected, self.found
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LengthError {}

/// `Ok(n)` when every length in `lens` is `n`. Inlined: out of line, the three calls of a
/// batched call's length check cost a short call more than its loop (Lambert's `pdf` over 16
/// lanes).
#[inline(always)]
fn same_length(lens: &[usize]) -> Result<usize, LengthError> {
    let n = lens.first().copied().unwrap_or(0);
    match lens.iter().find(|&&l| l != n) {
        Some(&found) => Err(LengthError { expected: n, found }),
        None => Ok(n),
    }
}

/// Where [`Batch::sample_batch`] writes: every field of the scalar
/// [`BxdfSample`], one slice per field (per coordinate, per channel).
///
/// As in the scalar sample, a lane whose [`lobe`](Self::lobe) is specular (a delta lobe) has
/// `f` = the lobe's coefficient over `|cos θi|` and `pdf` = the probability of choosing that
/// lobe, not a solid-angle density; a renderer that weighs samples by multiple importance
/// sampling reads `lobe` to tell the two apart (with both kinds in one model, such as
/// [`Glazed`](crate::bxdf::Glazed), a batch holds both). A lane without a sample (the scalar
/// `sample` returned `None`) has every output zero: `wi = 0`, `f = 0`, `pdf = 0`,
/// `lobe` = [`Lobes::NONE`] and `eta = 0`.
#[derive(Debug)]
pub struct SampleOut<'a, S: Lanes> {
    /// The sampled directions `wi`.
    pub wi: Vec3sMut<'a>,
    /// The values `f(wo, wi)`, per channel.
    pub f: S::Mut<'a>,
    /// The densities; `0` marks a lane without a sample.
    pub pdf: &'a mut [f32],
    /// The lobes the samples came from; [`Lobes::NONE`] for a lane without a sample.
    pub lobe: &'a mut [Lobes],
    /// The relative indices `η_t/η_i` the paths crossed (`1` for reflection); `0` for a lane
    /// without a sample.
    pub eta: &'a mut [f32],
}

/// A lane's sample outputs `(wi, f, pdf, lobe, eta)`: the scalar sample's, or for `None` the
/// zeros [`SampleOut`] documents for a lane without one (`wi`, `f`, `pdf` and `eta` zero, the
/// lobe [`Lobes::NONE`]). Every loop that writes samples takes them from here.
#[inline(always)]
pub(crate) fn lane_sample<S: Spectrum>(s: Option<BxdfSample<S>>) -> (Vec3, S, f32, Lobes, f32) {
    match s {
        Some(s) => (s.wi, s.f, s.pdf, s.lobe, s.eta),
        None => (Vec3::ZERO, S::zero(), 0.0, Lobes::NONE, 0.0),
    }
}

/// A model's `eval`, `pdf` and `sample` over batches: see the [module docs](self).
///
/// Every model of the crate implements it; a model of your own that implements [`Prepare`] and
/// `Clone`, with a spectrum that implements [`Lanes`], gets it from `impl Batch for MyModel {}`. A
/// batched call clones the model once, for its loop (see the [module docs](self); a combinator's
/// parts, once per chunk of 256 or 1,024 lanes); a model is a handful of numbers and, at most, a
/// table of them, so that costs nothing per lane. (A model that owns heap data, a measured BRDF in
/// a `Vec`, would allocate on every batched call: hold such data by reference or in an `Arc`.) Two
/// consequences of the bound: `Batch` is not object safe (there is no `dyn Batch`: a renderer with
/// materials chosen at run time matches on its own enum once per batch), and a model with interior
/// mutability (a cache in a `Cell`) sees a batched call's writes on the clone, not on itself. The
/// generic models need their parts to be `Clone`: a
/// [`NormalDistribution`](crate::microfacet::NormalDistribution) or
/// [`LayerInterface`](crate::bxdf::LayerInterface) of your own should derive it.
pub trait Batch: Prepare + Clone
where
    Self::Spectrum: Lanes,
{
    /// Whether the model has delta lobes only, so that its `eval` and `pdf` are zero for every
    /// pair (the crate's mirror, smooth and thin glass). The provided
    /// [`eval_batch`](Self::eval_batch) and [`pdf_batch`](Self::pdf_batch) then run their
    /// loops, which only write zeros, compiled for the target without the run-time dispatch:
    /// at 16 lanes a call the dispatch cost more than the loop. A hint only: the loops compute
    /// every lane either way, so a model that sets it without being delta-only gets the same
    /// numbers from the baseline loop (SSE2 on `x86_64`), without AVX2 or AVX-512. `false`
    /// unless a model says otherwise, which says nothing about its lobes: the crate's models
    /// built from delta parts (`TwoSided<Mirror>`, `Mono<SmoothDielectric>`) leave it `false`.
    const DELTA_ONLY: bool = false;

    /// `f[k] = eval(wo[k], wi[k])` for every lane `k`.
    ///
    /// # Errors
    /// [`LengthError`] when the slices differ in length (nothing is written).
    fn eval_batch(
        &self,
        wo: Vec3s<'_>,
        wi: Vec3s<'_>,
        f: <Self::Spectrum as Lanes>::Mut<'_>,
    ) -> Result<(), LengthError> {
        let kernel = eval_kernel::<Self, Plain>(self, wo, wi, f);
        if Self::DELTA_ONLY {
            run_here(kernel)
        } else {
            run(kernel)
        }
    }

    /// `pdf[k] = pdf(wo[k], wi[k])` for every lane `k`.
    ///
    /// # Errors
    /// [`LengthError`] when the slices differ in length (nothing is written).
    fn pdf_batch(&self, wo: Vec3s<'_>, wi: Vec3s<'_>, pdf: &mut [f32]) -> Result<(), LengthError> {
        let kernel = pdf_kernel::<Self, Plain>(self, wo, wi, pdf);
        if Self::DELTA_ONLY {
            run_here(kernel)
        } else {
            run(kernel)
        }
    }

    /// `sample(wo[k], u[k], uc[k])` for every lane `k`, written to `out`.
    ///
    /// # Errors
    /// [`LengthError`] when the slices differ in length (nothing is written).
    fn sample_batch(
        &self,
        wo: Vec3s<'_>,
        u: Vec2s<'_>,
        uc: &[f32],
        out: SampleOut<'_, Self::Spectrum>,
    ) -> Result<(), LengthError> {
        run(sample_kernel::<Self, Plain>(self, wo, u, uc, out))
    }
}

/// Runs a batched call's kernel (compiled for the CPU's widest instruction set), or returns
/// the length error its slices gave.
#[inline(always)]
fn run<K: Kernel>(kernel: Result<K, LengthError>) -> Result<(), LengthError> {
    dispatch(kernel?);
    Ok(())
}

/// Runs a batched call's kernel compiled for the target, without the dispatch: for a loop
/// that only writes zeros ([`Batch::DELTA_ONLY`]), where the dispatch is most of a short
/// call's cost.
#[inline(always)]
fn run_here<K: Kernel>(kernel: Result<K, LengthError>) -> Result<(), LengthError> {
    kernel?.run();
    Ok(())
}

/// The `eval` [`PairKernel`] of a call, its lanes computed by `O`.
#[inline(always)]
fn eval_kernel<'a, 'f, M: Prepare, O>(
    m: &'a M,
    wo: Vec3s<'a>,
    wi: Vec3s<'a>,
    f: <M::Spectrum as Lanes>::Mut<'f>,
) -> Result<PairKernel<'a, 'f, M, Value<O>>, LengthError>
where
    M::Spectrum: Lanes,
{
    pair_kernel(m, wo, wi, f)
}

/// The `pdf` [`PairKernel`] of a call, its lanes computed by `O`.
#[inline(always)]
fn pdf_kernel<'a, 'f, M, O>(
    m: &'a M,
    wo: Vec3s<'a>,
    wi: Vec3s<'a>,
    pdf: &'f mut [f32],
) -> Result<PairKernel<'a, 'f, M, Density<O>>, LengthError> {
    pair_kernel(m, wo, wi, pdf)
}

/// The [`PairKernel`] of a call, whose slices must have one length.
#[inline(always)]
fn pair_kernel<'a, 'f, M, P: PairOut<M>>(
    m: &'a M,
    wo: Vec3s<'a>,
    wi: Vec3s<'a>,
    out: <P::Out as Lanes>::Mut<'f>,
) -> Result<PairKernel<'a, 'f, M, P>, LengthError> {
    let n = same_length(&[wo.lanes()?, wi.lanes()?, P::Out::lanes(&out)?])?;
    let op = core::marker::PhantomData;
    Ok(PairKernel {
        m,
        wo,
        wi,
        out,
        n,
        op,
    })
}

/// The [`SampleKernel`] of a call, whose slices must have one length.
#[inline(always)]
fn sample_kernel<'a, 'f, M: Prepare, O>(
    m: &'a M,
    wo: Vec3s<'a>,
    u: Vec2s<'a>,
    uc: &'a [f32],
    out: SampleOut<'f, M::Spectrum>,
) -> Result<SampleKernel<'a, 'f, M, O>, LengthError>
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
    let op = core::marker::PhantomData;
    Ok(SampleKernel {
        m,
        wo,
        u,
        uc,
        out,
        n,
        op,
    })
}
