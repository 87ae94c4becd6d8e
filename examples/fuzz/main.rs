//! Fuzzes every model through adversarial inputs and counts the bad values (issue 9, item 7).
//!
//! ```sh
//! cargo run --release --example fuzz -- 100000
//! ```
//!
//! The argument is the number of random inputs per configuration (default 100,000); each
//! configuration also runs a fixed grid of corner inputs first. A configuration is one model
//! with one set of parameters: every model and combinator (the energy-compensated ones on
//! their own and as coats, and `Mono`), every distribution and masking term for the
//! microfacet ones, both transport modes for the dielectrics, `f32` and RGB where the model
//! is generic over its spectrum, with widths at both ends of their range (`α` = 1e-4 and 10,
//! anisotropic 1e-4 × 10; 1 for the compensated models' tables), relative indices `η` = 1,
//! 1 ± 1e-4, 1e±3, 1.5, 1/1.5, and complex indices with `κ` up to 1,000 and `η` down to the
//! smallest normal `f32` (the ends of `ComplexIor`'s range). Four-wavelength (`Vec4`) spectra
//! have a row of their own (fifteen configurations: the models' code is generic over the
//! carrier, and `f32` and RGB run most of it).
//!
//! The inputs: cosines `0, ±1e-7, ±1e-20, ±1`, uniform on the sphere and uniform within 1e-3 of the
//! horizon; azimuths random or exactly on an axis or a diagonal; `wi = wo`, `wi = −wo`, the mirror
//! pair `(−wo.x, −wo.y, wo.z)`, the refraction pair through the macro-surface (for the
//! dielectrics), a slightly perturbed mirror pair; directions of length `1 ± 1e-6`; `u` and `uc` at
//! `0`, `1 − 2⁻²⁴`, `1` and random. For each input it calls `eval`, `pdf`, `sample`, `prepare`,
//! `eval_prepared`, `pdf_prepared`, `eval_pdf_prepared` and `sample_prepared`; then it passes each
//! batch of up to 4,096 inputs (the corner grid: one batch) to `eval_batch`, `pdf_batch` and
//! `sample_batch`, cut into calls of 1 to 1,025 lanes, on the instruction set the run-time dispatch
//! picks for this CPU (`lanes.rs`). It counts, per model:
//!
//! * **NaN**, **inf**, **neg**: results (a value's channel, a density, a sample's direction,
//!   value or pdf) that are NaN, infinite, or negative;
//! * **non-unit**: samples whose `||wi| − 1|` exceeds 1e-3;
//! * **bad sample**: samples with a `pdf` that is not a positive normal finite number (a
//!   subnormal one included: the models refuse them), a non-finite weight
//!   `f |cos θi| / pdf`, or a crossed index `eta` that is not positive and finite;
//! * **split**: `eval_pdf_prepared` differing from `(eval_prepared, pdf_prepared)` in any bit
//!   (the models share work between the two, and a renderer's MIS relies on the two paths
//!   agreeing);
//! * **batched**: lanes of a batched call whose answer differs from the scalar call's in any
//!   bit (`lobe::batch` promises the scalar path's numbers; a lane without a sample must have
//!   every output zero and the lobe `Lobes::NONE`), one count per lane and call;
//! * **panics**: inputs whose calls panicked (each batch of calls runs under
//!   `catch_unwind`; a batch that panicked is replayed input by input to find them, a batched
//!   call one lane a call, and counted once at its first input if no lane panics alone).
//!
//! It prints the table (with, per model, how many of the bad results came from inputs with a
//! random number equal to 1, outside the documented `[0, 1)`), then, when a count is not zero,
//! the failing configurations and the first failing inputs exactly (model, parameters, call,
//! `wo`, `wi`, `u`, `uc`, the value; `{:?}` prints an `f32` so that it parses back to the same
//! bits), and exits with status 1. Deterministic: every configuration draws from its own
//! seeded `Pcg32` stream, whatever the number of threads.

use lobe::batch::Batch;
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, BxdfSample, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed,
    Lambert, Microfacet, Mirror, OrenNayar, Phong, Plastic, Prepare, RoughDielectric,
    SmoothDielectric, ThinDielectric, TransportMode,
};
use lobe::bxdf::{
    CoatedDiffuse, CompensatedMicrofacet, Compensation, DiffuseTransmission, Layered, Mix, Mono,
    Sheen, TwoSided,
};
use lobe::fresnel::{Conductor, Dielectric, Fresnel, NoFresnel, Schlick};
use lobe::microfacet::{
    Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr, Masking, NormalDistribution,
};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Eta, Roughness, Spectrum, Vec2, Vec3, Vec4};
use std::cell::RefCell;
use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

mod lanes;
// Shared with tests/batch.rs.
#[path = "../../tests/common/soa.rs"]
mod soa;
use lanes::Scalar;
use soa::Buffers;

/// A model the fuzz takes: its scalar and batched calls, with a spectrum whose batched
/// outputs [`lanes::check`] can hold (`f32`, RGB or `Vec4`).
trait Fuzzed: Batch<Spectrum: Buffers> {}

impl<M: Batch<Spectrum: Buffers>> Fuzzed for M {}

/// The seed of every configuration's stream (the stream is the configuration's index).
const SEED: u64 = 0xf022;
/// Inputs per `catch_unwind` batch.
const BATCH: usize = 4096;
/// How far a sample's `|wi|` may be from 1.
const UNIT_TOLERANCE: f32 = 1e-3;
/// Failing inputs printed per model and kind of failure.
const SHOWN: usize = 3;

// ---------------------------------------------------------------------------------------
// Inputs
// ---------------------------------------------------------------------------------------

/// One input of every call.
#[derive(Clone, Copy, Debug)]
struct Input {
    wo: Vec3,
    wi: Vec3,
    u: Vec2,
    uc: f32,
}

/// The adversarial cosines.
const COSINES: [f32; 7] = [0.0, 1e-7, -1e-7, 1e-20, -1e-20, 1.0, -1.0];
/// `1 − 2⁻²⁴`, the largest `f32` below 1.
const ONE_MINUS: f32 = 1.0 - 1.0 / 16_777_216.0;
/// The adversarial random numbers (`1` is outside the documented `[0, 1)`, and tried anyway).
const US: [f32; 3] = [0.0, ONE_MINUS, 1.0];

/// How `wi` is made from `wo`.
#[derive(Clone, Copy)]
enum Pair {
    /// A direction of its own.
    Free,
    Same,
    Opposite,
    Mirror,
    /// Refracted through the macro-surface with the configuration's `η` (the mirror pair
    /// under total internal reflection or without an index).
    Refracted,
    /// The mirror pair tilted by about 1e-3.
    NearMirror,
}

const PAIRS: [Pair; 5] = [
    Pair::Same,
    Pair::Opposite,
    Pair::Mirror,
    Pair::Refracted,
    Pair::NearMirror,
];

/// A direction with cosine `z` and an azimuth that is random or (one time in four) exactly
/// on an axis or a diagonal.
fn with_cos(z: f32, rng: &mut Pcg32) -> Vec3 {
    let r = (1.0 - z * z).max(0.0).sqrt();
    if rng.next_f32() < 0.25 {
        let d = core::f32::consts::FRAC_1_SQRT_2 * r;
        match rng.next_u32() % 4 {
            0 => Vec3::new(r, 0.0, z),
            1 => Vec3::new(0.0, -r, z),
            2 => Vec3::new(-d, d, z),
            _ => Vec3::new(d, d, z),
        }
    } else {
        let phi = core::f32::consts::TAU * rng.next_f32();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

/// A cosine: one of [`COSINES`], or uniform in `[-1, 1]` (a uniform direction on the
/// sphere), or uniform within 1e-3 of the horizon.
fn cosine(rng: &mut Pcg32) -> f32 {
    match rng.next_u32() % 4 {
        0 => COSINES[rng.next_u32() as usize % COSINES.len()],
        1 => 1e-3 * (2.0 * rng.next_f32() - 1.0),
        _ => 2.0 * rng.next_f32() - 1.0,
    }
}

fn paired(wo: Vec3, pair: Pair, eta: Option<Eta>, rng: &mut Pcg32) -> Vec3 {
    let mirror = Vec3::new(-wo.x, -wo.y, wo.z);
    match pair {
        Pair::Free => with_cos(cosine(rng), rng),
        Pair::Same => wo,
        Pair::Opposite => -wo,
        Pair::Mirror => mirror,
        Pair::Refracted => eta
            .and_then(|eta| lobe::frame::refract_away(wo, Vec3::Z, eta))
            .unwrap_or(mirror),
        Pair::NearMirror => {
            let t = 1e-3 * (Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5);
            (mirror + t).normalize_or(mirror)
        }
    }
}

/// A random number: one of [`US`] one time in four, else uniform in `[0, 1)`.
fn unit(rng: &mut Pcg32) -> f32 {
    if rng.next_f32() < 0.25 {
        US[rng.next_u32() as usize % US.len()]
    } else {
        rng.next_f32()
    }
}

/// A length off 1 by `±1e-6`, one time in four.
fn stretch(rng: &mut Pcg32) -> f32 {
    match rng.next_u32() % 8 {
        0 => 1.0 + 1e-6,
        1 => 1.0 - 1e-6,
        _ => 1.0,
    }
}

/// A random adversarial input.
fn random_input(eta: Option<Eta>, rng: &mut Pcg32) -> Input {
    let wo = with_cos(cosine(rng), rng);
    let pair = if rng.next_f32() < 0.5 {
        Pair::Free
    } else {
        PAIRS[rng.next_u32() as usize % PAIRS.len()]
    };
    let wi = paired(wo, pair, eta, rng);
    Input {
        wo: wo * stretch(rng),
        wi: wi * stretch(rng),
        u: Vec2::new(unit(rng), unit(rng)),
        uc: unit(rng),
    }
}

/// The corner grid: every adversarial cosine of `wo` against every cosine and every pairing
/// of `wi`, with every corner of `(u, uc)` (azimuths random).
fn corner_inputs(eta: Option<Eta>, rng: &mut Pcg32) -> Vec<Input> {
    let mut inputs = Vec::new();
    for &co in &COSINES {
        let wo = with_cos(co, rng);
        let mut wis: Vec<Vec3> = COSINES.iter().map(|&ci| with_cos(ci, rng)).collect();
        wis.extend(PAIRS.iter().map(|&p| paired(wo, p, eta, rng)));
        for &wi in &wis {
            for &ux in &US {
                for &uy in &US {
                    for &uc in &US {
                        let u = Vec2::new(ux, uy);
                        inputs.push(Input { wo, wi, u, uc });
                    }
                }
            }
        }
    }
    inputs
}

// ---------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------

/// The kinds of failure, in the table's order.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Nan,
    Inf,
    Negative,
    NonUnit,
    BadSample,
    Split,
    Batched,
    Panic,
}

const KINDS: [Kind; 8] = [
    Kind::Nan,
    Kind::Inf,
    Kind::Negative,
    Kind::NonUnit,
    Kind::BadSample,
    Kind::Split,
    Kind::Batched,
    Kind::Panic,
];

impl Kind {
    fn header(self) -> &'static str {
        match self {
            Kind::Nan => "NaN",
            Kind::Inf => "inf",
            Kind::Negative => "neg",
            Kind::NonUnit => "non-unit",
            Kind::BadSample => "bad sample",
            Kind::Split => "split",
            Kind::Batched => "batched",
            Kind::Panic => "panics",
        }
    }
}

/// A failing input, as printed.
#[derive(Clone, Debug)]
struct Failure {
    kind: Kind,
    call: &'static str,
    input: Input,
    value: String,
}

/// Counts and the first failures of a run.
#[derive(Clone, Debug, Default)]
struct Tally {
    inputs: u64,
    counts: [u64; KINDS.len()],
    /// The bad results of inputs with `u.x`, `u.y` or `uc` equal to 1 (outside the
    /// documented `[0, 1)`).
    at_one: u64,
    failures: Vec<Failure>,
}

/// True when the two inputs are the same, bit for bit.
fn same_input(a: &Input, b: &Input) -> bool {
    let bits = |x: &Input| {
        [
            x.wo.x, x.wo.y, x.wo.z, x.wi.x, x.wi.y, x.wi.z, x.u.x, x.u.y, x.uc,
        ]
        .map(f32::to_bits)
    };
    bits(a) == bits(b)
}

/// True when a random number of the input is 1.
fn has_one(x: &Input) -> bool {
    x.u.x == 1.0 || x.u.y == 1.0 || x.uc == 1.0
}

impl Tally {
    fn add(&mut self, other: Tally) {
        self.inputs += other.inputs;
        self.at_one += other.at_one;
        for (a, b) in self.counts.iter_mut().zip(other.counts) {
            *a += b;
        }
        for f in other.failures {
            self.note(f);
        }
    }

    /// Keeps `f` if fewer than [`SHOWN`] failures of its kind are kept, none of them on the
    /// same input (`sample` and `sample_prepared` fail together).
    fn note(&mut self, f: Failure) {
        let kept = || self.failures.iter().filter(|g| g.kind == f.kind);
        if kept().count() < SHOWN && !kept().any(|g| same_input(&g.input, &f.input)) {
            self.failures.push(f);
        }
    }

    fn fail(&mut self, kind: Kind, call: &'static str, input: &Input, value: &dyn std::fmt::Debug) {
        self.counts[kind as usize] += 1;
        if has_one(input) {
            self.at_one += 1;
        }
        if self.failures.iter().filter(|g| g.kind == kind).count() < SHOWN {
            self.note(Failure {
                kind,
                call,
                input: *input,
                value: format!("{value:?}"),
            });
        }
    }

    fn total(&self) -> u64 {
        self.counts.iter().sum()
    }

    /// Counts one result whose numbers are `xs`, of which `signed` may be negative: NaN,
    /// infinite, negative, each at most once.
    fn numbers(
        &mut self,
        call: &'static str,
        input: &Input,
        signed: impl Iterator<Item = f32>,
        xs: impl Iterator<Item = f32>,
        value: &dyn std::fmt::Debug,
    ) {
        let (mut nan, mut inf, mut neg) = (false, false, false);
        for x in signed {
            nan |= x.is_nan();
            inf |= x.is_infinite();
        }
        for x in xs {
            nan |= x.is_nan();
            inf |= x.is_infinite();
            neg |= x < 0.0;
        }
        if nan {
            self.fail(Kind::Nan, call, input, value);
        }
        if inf {
            self.fail(Kind::Inf, call, input, value);
        }
        if neg {
            self.fail(Kind::Negative, call, input, value);
        }
    }

    fn value<S: Spectrum>(&mut self, call: &'static str, input: &Input, f: S) {
        let xs = (0..S::CHANNELS).map(|c| f.channel(c));
        self.numbers(call, input, core::iter::empty(), xs, &f);
    }

    fn density(&mut self, call: &'static str, input: &Input, p: f32) {
        self.numbers(call, input, core::iter::empty(), core::iter::once(p), &p);
    }

    fn sample<S: Spectrum>(&mut self, call: &'static str, input: &Input, s: Option<BxdfSample<S>>) {
        let Some(s) = s else { return };
        // The direction's components may be negative; the value and the pdf may not.
        let signed = s.wi.to_array().into_iter().chain([s.eta]);
        let xs = (0..S::CHANNELS).map(|c| s.f.channel(c)).chain([s.pdf]);
        self.numbers(call, input, signed, xs, &s);
        if s.wi.is_finite() && (s.wi.length() - 1.0).abs() > UNIT_TOLERANCE {
            self.fail(Kind::NonUnit, call, input, &s);
        }
        let w = s.weight();
        let weight_finite = (0..S::CHANNELS).all(|c| w.channel(c).is_finite());
        // A subnormal density is refused by the crate's models (its weight can overflow, or
        // carry 30 orders of magnitude of a value that is not there): it counts as bad.
        let valid = s.pdf >= f32::MIN_POSITIVE
            && s.pdf.is_finite()
            && weight_finite
            && s.eta > 0.0
            && s.eta.is_finite();
        if !valid {
            self.fail(Kind::BadSample, call, input, &s);
        }
    }
}

/// Every scalar call on one input; returns `eval`'s, `pdf`'s and `sample`'s answers.
fn check_input<M: Prepare>(m: &M, x: &Input, t: &mut Tally) -> Scalar<M::Spectrum> {
    t.inputs += 1;
    let want = Scalar {
        f: Bxdf::eval(m, x.wo, x.wi),
        pdf: Bxdf::pdf(m, x.wo, x.wi),
        sample: Bxdf::sample(m, x.wo, x.u, x.uc),
    };
    t.value("eval", x, want.f);
    t.density("pdf", x, want.pdf);
    t.sample("sample", x, want.sample);
    let at = m.prepare(x.wo);
    let f = m.eval_prepared(&at, x.wi);
    t.value("eval_prepared", x, f);
    let p = m.pdf_prepared(&at, x.wi);
    t.density("pdf_prepared", x, p);
    let (f2, p2) = m.eval_pdf_prepared(&at, x.wi);
    t.value("eval_pdf_prepared", x, f2);
    t.density("eval_pdf_prepared", x, p2);
    if !soa::same(f, f2) || p.to_bits() != p2.to_bits() {
        t.fail(
            Kind::Split,
            "eval_pdf_prepared",
            x,
            &format_args!(
                "({f2:?}, {p2:?}) against ({f:?}, {p:?}) from eval_prepared, pdf_prepared"
            ),
        );
    }
    t.sample("sample_prepared", x, m.sample_prepared(&at, x.u, x.uc));
    want
}

thread_local! {
    /// The message of the last panic on this thread.
    static PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Runs `inputs` through `m`'s scalar calls, then through its batched ones
/// ([`lanes::check`]); a batch that panics is replayed input by input, so that the panicking
/// inputs are counted and shown and the others still checked (the batched calls then take the
/// inputs that did not panic).
fn check_batch<M: Fuzzed>(m: &M, inputs: &[Input], t: &mut Tally) {
    let mut batch = Tally::default();
    let ok = catch_unwind(AssertUnwindSafe(|| {
        let want: Vec<_> = inputs
            .iter()
            .map(|x| check_input(m, x, &mut batch))
            .collect();
        (want, batch)
    }));
    if let Ok((want, batch)) = ok {
        t.add(batch);
        check_lanes(m, inputs, &want, t);
        return;
    }
    let (mut kept, mut want) = (Vec::new(), Vec::new());
    for x in inputs {
        let mut one = Tally::default();
        match catch_unwind(AssertUnwindSafe(|| check_input(m, x, &mut one))) {
            Ok(w) => {
                t.add(one);
                kept.push(*x);
                want.push(w);
            }
            Err(_) => {
                t.inputs += 1;
                let message = PANIC.with(|p| p.borrow().clone());
                t.fail(Kind::Panic, "one of the calls", x, &message);
            }
        }
    }
    check_lanes(m, &kept, &want, t);
}

/// [`lanes::check`] on `inputs`, whose scalar answers are `want`. Where it panics, each of its
/// calls ([`lanes::calls`]) is replayed on its own, and a call that panics one lane a call, so
/// that the panicking lanes are counted and shown; a call that panics when none of its lanes
/// does alone counts once, at its first input.
fn check_lanes<M: Fuzzed>(m: &M, inputs: &[Input], want: &[Scalar<M::Spectrum>], t: &mut Tally) {
    let mut batch = Tally::default();
    if catch_unwind(AssertUnwindSafe(|| {
        lanes::check(m, inputs, want, &mut batch)
    }))
    .is_ok()
    {
        t.add(batch);
        return;
    }
    for r in lanes::calls(inputs.len()) {
        let (inputs, want) = (&inputs[r.clone()], &want[r]);
        let mut call = Tally::default();
        let whole = |call: &mut Tally| lanes::check_call(m, inputs, want, call);
        if catch_unwind(AssertUnwindSafe(|| whole(&mut call))).is_ok() {
            t.add(call);
            continue;
        }
        let message = PANIC.with(|p| p.borrow().clone());
        let mut found = false;
        for (k, x) in inputs.iter().enumerate() {
            let mut one = Tally::default();
            let lane = |one: &mut Tally| lanes::check_call(m, &inputs[k..=k], &want[k..=k], one);
            if catch_unwind(AssertUnwindSafe(|| lane(&mut one))).is_ok() {
                t.add(one);
            } else {
                found = true;
                let message = PANIC.with(|p| p.borrow().clone());
                t.fail(Kind::Panic, "a batched call of one lane", x, &message);
            }
        }
        if !found {
            let what = format_args!("{} lanes from this one: {message}", inputs.len());
            t.fail(Kind::Panic, "a batched call", &inputs[0], &what);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Configurations
// ---------------------------------------------------------------------------------------

/// The work of one configuration: the corner grid and `n` random inputs.
type Run = Box<dyn Fn(usize, u64) -> Tally + Send + Sync>;

/// One model with one set of parameters.
struct Config {
    /// The table's row.
    model: String,
    /// What distinguishes it from the row's other configurations.
    params: String,
    run: Run,
}

/// The configurations being built.
#[derive(Default)]
struct Configs(Vec<Config>);

impl Configs {
    /// Adds the model `m` to the table's row `model`; `eta`, the index of a model with a
    /// dielectric interface, makes the inputs' refraction pairs.
    fn push<M>(&mut self, model: &str, params: String, eta: Option<Eta>, m: M)
    where
        M: Fuzzed + Send + Sync + 'static,
    {
        let run: Run = Box::new(move |n, stream| {
            let mut rng = Pcg32::new(SEED, stream);
            let mut t = Tally::default();
            check_batch(&m, &corner_inputs(eta, &mut rng), &mut t);
            let mut done = 0;
            let mut inputs = Vec::with_capacity(BATCH);
            while done < n {
                inputs.clear();
                let k = BATCH.min(n - done);
                inputs.extend((0..k).map(|_| random_input(eta, &mut rng)));
                check_batch(&m, &inputs, &mut t);
                done += k;
            }
            t
        });
        self.0.push(Config {
            model: model.to_owned(),
            params,
            run,
        });
    }
}

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).expect("a valid width")
}

fn eta(e: f32) -> Eta {
    Eta::new(e).expect("a valid index")
}

/// The widths: both ends of the range, a middle one, and anisotropic both ways.
const ALPHAS: [(f32, f32); 5] = [
    (1e-4, 1e-4),
    (10.0, 10.0),
    (0.3, 0.3),
    (1e-4, 10.0),
    (10.0, 1e-4),
];

/// The relative indices: 1 and just off it, the range's ends, glass from both sides.
const ETAS: [f32; 7] = [1.0, 1.0 + 1e-4, 1.0 - 1e-4, 1e-3, 1e3, 1.5, 1.0 / 1.5];

const MASKINGS: [Masking; 3] = [
    Masking::HeightCorrelated,
    Masking::Separable,
    Masking::VCavity,
];

const MODES: [TransportMode; 2] = [TransportMode::Radiance, TransportMode::Importance];

/// Conductors with `κ` up to 50 and `η` from 1e-3 to 1e3.
fn extreme_conductor() -> Conductor<Vec3> {
    Conductor {
        ior: ComplexIor::new(Vec3::new(1e-3, 1.0, 1e3), Vec3::new(50.0, 0.0, 50.0))
            .expect("a valid complex index"),
    }
}

/// A microfacet model with distribution `d` under every Fresnel term the crate has, `f32` and
/// RGB.
fn push_fresnels<D>(c: &mut Configs, row: &str, what: &str, d: D, masking: Masking)
where
    D: NormalDistribution + Copy + Send + Sync + 'static,
{
    fn one<D, F>(c: &mut Configs, row: &str, what: String, d: D, masking: Masking, f: F)
    where
        D: NormalDistribution + Copy + Send + Sync + 'static,
        F: Fresnel<Spectrum: Buffers> + Clone + Send + Sync + 'static,
    {
        c.push(row, what, None, Microfacet::new(d, masking, f));
    }
    let gold = lobe::metals::GOLD.rgb();
    let p = |f: &str| format!("{what}, {masking:?}, {f}");
    one(c, row, p("gold RGB"), d, masking, Conductor { ior: gold });
    one(
        c,
        row,
        p("η (1e-3, 1, 1e3) κ (50, 0, 50) RGB"),
        d,
        masking,
        extreme_conductor(),
    );
    let k50 = ComplexIor::new(0.2f32, 50.0).expect("a valid complex index");
    one(
        c,
        row,
        p("η 0.2 κ 50 f32"),
        d,
        masking,
        Conductor { ior: k50 },
    );
    one(
        c,
        row,
        p("Schlick RGB"),
        d,
        masking,
        Schlick::new(Vec3::new(1.0, 0.5, 0.0)).unwrap(),
    );
    one(
        c,
        row,
        p("Schlick 0.04 f32"),
        d,
        masking,
        Schlick::new(0.04f32).unwrap(),
    );
    for e in [1.0, 1.0 + 1e-4, 1.0 - 1e-4, 1e-3, 1e3] {
        let f = Dielectric { eta: eta(e) };
        one(c, row, p(&format!("dielectric η {e:e}")), d, masking, f);
    }
    one(c, row, p("no Fresnel"), d, masking, NoFresnel::<f32>::new());
    one(
        c,
        row,
        p("η (1.2e-38, 1, 1e3) κ (1e3, 0, 1e3) RGB"),
        d,
        masking,
        outermost_conductor(),
    );
}

/// The complex index at the ends of `ComplexIor`'s range: `η` from the smallest normal
/// `f32` to 1,000, `κ` to 1,000.
fn outermost_conductor() -> Conductor<Vec3> {
    Conductor {
        ior: ComplexIor::new(
            Vec3::new(f32::MIN_POSITIVE, 1.0, 1e3),
            Vec3::new(1e3, 0.0, 1e3),
        )
        .expect("a valid complex index"),
    }
}

/// A microfacet model with distribution `d` and every masking term, with the gold conductor
/// (RGB) and the extreme one; every Fresnel term under height-correlated masking.
fn push_microfacet<D>(c: &mut Configs, row: &str, what: &str, d: D)
where
    D: NormalDistribution + Copy + Send + Sync + 'static,
{
    push_fresnels(c, row, what, d, Masking::HeightCorrelated);
    for masking in [Masking::Separable, Masking::VCavity] {
        let gold = Conductor {
            ior: lobe::metals::GOLD.rgb(),
        };
        let p = |f: &str| format!("{what}, {masking:?}, {f}");
        c.push(row, p("gold RGB"), None, Microfacet::new(d, masking, gold));
        c.push(
            row,
            p("η (1e-3, 1, 1e3) κ (50, 0, 50) RGB"),
            None,
            Microfacet::new(d, masking, extreme_conductor()),
        );
    }
}

/// A rough dielectric with distribution `d`, every index, mode and masking term.
fn push_rough_dielectric<D>(c: &mut Configs, row: &str, what: &str, d: D)
where
    D: NormalDistribution + Copy + Send + Sync + 'static,
{
    for e in ETAS {
        for mode in MODES {
            for masking in MASKINGS {
                c.push(
                    row,
                    format!("{what}, η {e:e}, {mode:?}, {masking:?}"),
                    Some(eta(e)),
                    RoughDielectric::new(d, eta(e))
                        .with_masking(masking)
                        .with_mode(mode),
                );
            }
        }
    }
}

/// A plastic with distribution `d` under every index, `f32` and RGB.
fn push_plastic<D>(c: &mut Configs, row: &str, what: &str, d: D)
where
    D: NormalDistribution + Copy + Send + Sync + 'static,
{
    for e in ETAS {
        let p = |r: &str| format!("{what}, η {e:e}, ρ {r}");
        let m = Plastic::new(Vec3::new(1.0, 0.5, 0.0), d, eta(e)).expect("a valid plastic");
        c.push(row, p("(1, 0.5, 0) RGB"), Some(eta(e)), m);
        let m = Plastic::new(1.0f32, d, eta(e)).expect("a valid plastic");
        c.push(row, p("1 f32"), Some(eta(e)), m);
    }
}

fn configs() -> Vec<Config> {
    let mut c = Configs::default();
    let rgb = Vec3::new(1.0, 0.5, 0.0);

    // Diffuse models: reflectance at its ends, roughness at its ends, f32 and RGB.
    for r in [0.0f32, 1.0] {
        c.push(
            "Lambert",
            format!("ρ {r} f32"),
            None,
            Lambert::new(r).unwrap(),
        );
    }
    c.push(
        "Lambert",
        "ρ (1, 0.5, 0) RGB".into(),
        None,
        Lambert::new(rgb).unwrap(),
    );
    for sigma in [0.0, 1e-4, OrenNayar::<f32>::SIGMA_MAX] {
        let p = |s: &str| format!("σ {sigma}, ρ {s}");
        c.push(
            "OrenNayar",
            p("1 f32"),
            None,
            OrenNayar::new(1.0f32, sigma).unwrap(),
        );
        c.push(
            "OrenNayar",
            p("(1, 0.5, 0) RGB"),
            None,
            OrenNayar::new(rgb, sigma).unwrap(),
        );
    }
    for r in [0.0, 1e-4, 1.0] {
        let fitted = EnergyPreservingOrenNayar::new(rgb, r).unwrap();
        let row = "EnergyPreservingOrenNayar";
        c.push(row, format!("r {r}, fitted, RGB"), None, fitted);
        c.push(
            row,
            format!("r {r}, exact, RGB"),
            None,
            fitted.with_exact_albedo(),
        );
        let mono = EnergyPreservingOrenNayar::new(1.0f32, r).unwrap();
        c.push(row, format!("r {r}, fitted, f32"), None, mono);
        c.push(
            row,
            format!("r {r}, exact, f32"),
            None,
            mono.with_exact_albedo(),
        );
    }
    for r in [0.0, 1.0] {
        let rough = Roughness::new(r).unwrap();
        let p = |s: &str| format!("roughness {r}, ρ {s}");
        c.push(
            "DisneyDiffuse",
            p("1 f32"),
            None,
            DisneyDiffuse::new(1.0f32, rough).unwrap(),
        );
        c.push(
            "DisneyDiffuse",
            p("(1, 0.5, 0) RGB"),
            None,
            DisneyDiffuse::new(rgb, rough).unwrap(),
        );
    }

    // Phong and Blinn-Phong: exponents at their ends, each lobe alone and mixed.
    let weights: [(&str, f32, f32); 3] = [
        ("kd 0, ks 1", 0.0, 1.0),
        ("kd 1, ks 0", 1.0, 0.0),
        ("kd 0.3, ks 0.7", 0.3, 0.7),
    ];
    for p in [0.0, 1e-4, 1.0, 1e6] {
        for (w, kd, ks) in weights {
            let name = |s: &str| format!("p {p:e}, {w}, {s}");
            c.push("Phong", name("f32"), None, Phong::new(kd, ks, p).unwrap());
            let m = Phong::new(Vec3::new(kd, kd, 0.0), Vec3::new(ks, 0.0, ks), p).unwrap();
            c.push("Phong", name("RGB"), None, m);
            for (row, form) in [
                ("BlinnPhong (modified)", BlinnPhongForm::Modified),
                ("BlinnPhong (normalized)", BlinnPhongForm::Normalized),
            ] {
                c.push(
                    row,
                    name("f32"),
                    None,
                    BlinnPhong::new(kd, ks, p, form).unwrap(),
                );
                let m = BlinnPhong::new(Vec3::new(kd, kd, 0.0), Vec3::new(ks, 0.0, ks), p, form)
                    .unwrap();
                c.push(row, name("RGB"), None, m);
            }
        }
    }

    // Microfacet conductors (and every other Fresnel term): every distribution, width,
    // masking term.
    for (ax, ay) in ALPHAS {
        let w = format!("α ({ax:e}, {ay:e})");
        let ggx = Ggx::new(alpha(ax), alpha(ay));
        push_microfacet(&mut c, "Microfacet<Ggx>", &format!("{w}, bounded"), ggx);
        let unbounded = ggx.with_bounded_reflection(false);
        push_microfacet(
            &mut c,
            "Microfacet<Ggx>",
            &format!("{w}, unbounded"),
            unbounded,
        );
        let beckmann = Beckmann::new(alpha(ax), alpha(ay));
        push_microfacet(
            &mut c,
            "Microfacet<Beckmann>",
            &format!("{w}, exact Λ"),
            beckmann,
        );
        let walter = beckmann.with_masking(BeckmannMasking::WalterRational);
        push_microfacet(
            &mut c,
            "Microfacet<Beckmann>",
            &format!("{w}, Walter G1"),
            walter,
        );
    }
    for a in [1e-4, 0.3, 10.0] {
        for gamma in [0.01, 1.0, 2.0, 10.0] {
            let gtr = Gtr::new(alpha(a), gamma).unwrap();
            push_microfacet(
                &mut c,
                "Microfacet<Gtr>",
                &format!("α {a:e}, γ {gamma}"),
                gtr,
            );
        }
    }
    for a in [1e-4, 0.3, 1.0] {
        let bp = BlinnPhongNdf::new(alpha(a)).unwrap();
        let row = "Microfacet<BlinnPhongNdf>";
        push_microfacet(&mut c, row, &format!("α {a:e}, Beckmann Λ"), bp);
        push_microfacet(
            &mut c,
            row,
            &format!("α {a:e}, exact Smith"),
            bp.with_exact_smith(),
        );
    }

    // Rough dielectrics: every distribution, width, index, mode and masking term.
    for (ax, ay) in ALPHAS {
        let w = format!("α ({ax:e}, {ay:e})");
        let ggx = Ggx::new(alpha(ax), alpha(ay));
        push_rough_dielectric(&mut c, "RoughDielectric<Ggx>", &w, ggx);
        let beckmann = Beckmann::new(alpha(ax), alpha(ay));
        push_rough_dielectric(&mut c, "RoughDielectric<Beckmann>", &w, beckmann);
    }
    for (a, gamma) in [
        (1e-4, 0.01),
        (1e-4, 10.0),
        (10.0, 0.01),
        (10.0, 10.0),
        (0.3, 2.0),
    ] {
        let gtr = Gtr::new(alpha(a), gamma).unwrap();
        push_rough_dielectric(
            &mut c,
            "RoughDielectric<Gtr>",
            &format!("α {a:e}, γ {gamma}"),
            gtr,
        );
    }
    for a in [1e-4, 1.0] {
        let bp = BlinnPhongNdf::new(alpha(a)).unwrap().with_exact_smith();
        let row = "RoughDielectric<BlinnPhongNdf>";
        push_rough_dielectric(&mut c, row, &format!("α {a:e}, exact Smith"), bp);
    }

    // Delta models.
    c.push(
        "Mirror",
        "gold RGB".into(),
        None,
        Mirror::new(Conductor {
            ior: lobe::metals::GOLD.rgb(),
        }),
    );
    c.push(
        "Mirror",
        "η (1e-3, 1, 1e3) κ (50, 0, 50) RGB".into(),
        None,
        Mirror::new(extreme_conductor()),
    );
    c.push(
        "Mirror",
        "Schlick 1 f32".into(),
        None,
        Mirror::new(Schlick::new(1.0f32).unwrap()),
    );
    c.push(
        "Mirror",
        "no Fresnel".into(),
        None,
        Mirror::new(NoFresnel::<Vec3>::new()),
    );
    for e in ETAS {
        c.push(
            "Mirror",
            format!("dielectric η {e:e}"),
            None,
            Mirror::new(Dielectric { eta: eta(e) }),
        );
        for mode in MODES {
            let m = SmoothDielectric::new(eta(e)).with_mode(mode);
            c.push(
                "SmoothDielectric",
                format!("η {e:e}, {mode:?}"),
                Some(eta(e)),
                m,
            );
        }
        c.push(
            "ThinDielectric",
            format!("η {e:e}"),
            Some(eta(e)),
            ThinDielectric::new(eta(e)),
        );
        for r in [0.0f32, 1.0] {
            c.push(
                "Glazed",
                format!("η {e:e}, ρ {r} f32"),
                Some(eta(e)),
                Glazed::new(r, eta(e)).unwrap(),
            );
        }
        c.push(
            "Glazed",
            format!("η {e:e}, ρ (1, 0.5, 0) RGB"),
            Some(eta(e)),
            Glazed::new(rgb, eta(e)).unwrap(),
        );
    }

    // Plastic: every distribution at the ends of its width.
    for (ax, ay) in [(1e-4, 1e-4), (10.0, 10.0), (1e-4, 10.0)] {
        let w = format!("α ({ax:e}, {ay:e})");
        push_plastic(&mut c, "Plastic<Ggx>", &w, Ggx::new(alpha(ax), alpha(ay)));
        push_plastic(
            &mut c,
            "Plastic<Beckmann>",
            &w,
            Beckmann::new(alpha(ax), alpha(ay)),
        );
    }
    for (a, gamma) in [(1e-4, 10.0), (10.0, 0.01)] {
        push_plastic(
            &mut c,
            "Plastic<Gtr>",
            &format!("α {a:e}, γ {gamma}"),
            Gtr::new(alpha(a), gamma).unwrap(),
        );
    }
    for a in [1e-4, 1.0] {
        push_plastic(
            &mut c,
            "Plastic<BlinnPhongNdf>",
            &format!("α {a:e}"),
            BlinnPhongNdf::new(alpha(a)).unwrap(),
        );
    }
    push_compensated(&mut c);
    push_compositions(&mut c);
    push_four_wavelengths(&mut c);
    c.0
}

/// A row of four-wavelength (`Vec4`) models: the carrier through the scalar code and the
/// batched loops (four channels, the most the combinators' stack space holds, and the
/// compensated models' largest chunk buffers), at the widths' ends.
fn push_four_wavelengths(c: &mut Configs) {
    const ROW: &str = "four wavelengths (Vec4)";
    let rho = Vec4::new(1.0, 0.5, 0.0, 0.25);
    let gold = Conductor {
        ior: lobe::metals::GOLD.spectral(Vec4::new(650.0, 550.0, 450.0, 700.0)),
    };
    let lambert = Lambert::new(rho).unwrap();
    c.push(ROW, "Lambert".into(), None, lambert);
    let sigma = OrenNayar::<Vec4>::SIGMA_MAX;
    c.push(
        ROW,
        "Oren-Nayar σ max".into(),
        None,
        OrenNayar::new(rho, sigma).unwrap(),
    );
    for (a, masking) in [
        (1e-4, Masking::HeightCorrelated),
        (10.0, Masking::HeightCorrelated),
        (0.3, Masking::Separable),
        (0.3, Masking::VCavity),
    ] {
        let m = Microfacet::new(Ggx::isotropic(alpha(a)), masking, gold);
        c.push(ROW, format!("GGX α {a:e}, {masking:?}, gold"), None, m);
    }
    let schlick = Microfacet::new(
        Ggx::isotropic(alpha(0.3)),
        Masking::HeightCorrelated,
        Schlick::new(rho).unwrap(),
    );
    c.push(ROW, "GGX α 0.3, Schlick".into(), None, schlick);
    for a in [1e-4, 1.0] {
        let m = Microfacet::new(Ggx::isotropic(alpha(a)), Masking::HeightCorrelated, gold);
        let m = m.with_energy_compensation().unwrap();
        c.push(ROW, format!("GGX α {a:e}, gold, compensated"), None, m);
    }
    for e in [1.5, 1e3] {
        let m = Plastic::new(rho, Ggx::isotropic(alpha(0.3)), eta(e)).unwrap();
        c.push(ROW, format!("Plastic, η {e:e}"), Some(eta(e)), m);
    }
    let m = Plastic::compensated(rho, Ggx::isotropic(alpha(1.0)), eta(1.5)).unwrap();
    c.push(ROW, "Plastic::compensated, α 1".into(), Some(eta(1.5)), m);
    let mix = Mix::new(lambert, schlick, 0.5).unwrap();
    c.push(ROW, "Mix(Lambert, GGX Schlick)".into(), None, mix);
    c.push(
        ROW,
        "TwoSided(GGX Schlick)".into(),
        None,
        TwoSided::new(schlick),
    );
    let rough = RoughDielectric::new(Ggx::isotropic(alpha(0.3)), eta(1.5));
    let mono = Mono::<_, Vec4>::new(rough);
    c.push(ROW, "Mono(rough glass η 1.5)".into(), Some(eta(1.5)), mono);
}

/// The energy-compensated models on their own (the tables' widths run to 1), both
/// compensations, and the monochrome models as RGB (`Mono`, as a renderer's glass).
fn push_compensated(c: &mut Configs) {
    let gold = Conductor {
        ior: lobe::metals::GOLD.rgb(),
    };
    for (ax, ay) in [(1e-4, 1e-4), (1.0, 1.0), (1e-4, 1.0), (0.3, 0.3)] {
        let w = format!("α ({ax:e}, {ay:e})");
        let ggx = Ggx::new(alpha(ax), alpha(ay));
        for compensation in [Compensation::KullaConty, Compensation::Turquin] {
            for (what, f) in [
                ("gold", gold),
                ("η (1e-3, 1, 1e3) κ (50, 0, 50)", extreme_conductor()),
                ("η (1.2e-38, 1, 1e3) κ (1e3, 0, 1e3)", outermost_conductor()),
            ] {
                let inner = Microfacet::new(ggx, Masking::HeightCorrelated, f);
                c.push(
                    "CompensatedMicrofacet<Ggx>",
                    format!("{w}, {compensation:?}, {what} RGB"),
                    None,
                    CompensatedMicrofacet::new(inner, compensation).unwrap(),
                );
            }
        }
        let beckmann = Microfacet::new(
            Beckmann::new(alpha(ax), alpha(ay)),
            Masking::HeightCorrelated,
            Schlick::new(0.04f32).unwrap(),
        );
        c.push(
            "CompensatedMicrofacet<Beckmann>",
            format!("{w}, Schlick 0.04 f32"),
            None,
            beckmann.with_energy_compensation().unwrap(),
        );
        for e in [1.01, 1.5, 3.0, 1.0 / 3.0, 1.0 / 1.01] {
            for mode in MODES {
                let m = RoughDielectric::new(ggx, eta(e))
                    .with_mode(mode)
                    .with_energy_compensation()
                    .unwrap();
                c.push(
                    "CompensatedDielectric<Ggx>",
                    format!("{w}, η {e:e}, {mode:?}"),
                    Some(eta(e)),
                    m,
                );
            }
            // A compensated plastic's coat is seen from outside: η ∈ [1.01, 3].
            for r in [0.0f32, 1.0].into_iter().filter(|_| e > 1.0) {
                c.push(
                    "Plastic::compensated<Ggx>",
                    format!("{w}, η {e:e}, ρ {r} f32"),
                    Some(eta(e)),
                    Plastic::compensated(r, ggx, eta(e)).unwrap(),
                );
            }
        }
    }
    for e in ETAS {
        let rough = RoughDielectric::new(Ggx::isotropic(alpha(0.15)), eta(e));
        c.push(
            "Mono (RGB)",
            format!("RoughDielectric GGX α 0.15, η {e:e}"),
            Some(eta(e)),
            Mono::<_, Vec3>::new(rough),
        );
        c.push(
            "Mono (RGB)",
            format!("SmoothDielectric η {e:e}"),
            Some(eta(e)),
            Mono::<_, Vec3>::new(SmoothDielectric::new(eta(e))),
        );
    }
}

/// The combinators and the layered models (issue 12): widths and indices at their ends, the
/// layer's thickness and medium at theirs, walks of one event and of many.
fn push_compositions(c: &mut Configs) {
    let gold = Conductor {
        ior: lobe::metals::GOLD.rgb(),
    };
    let rgb = Vec3::new(1.0, 0.5, 0.0);
    // Rough coats over a white base, every index, the widths' ends.
    for (ax, ay) in [(1e-4, 1e-4), (10.0, 10.0), (1e-4, 10.0), (0.3, 0.3)] {
        for e in ETAS {
            let top = RoughDielectric::new(Ggx::new(alpha(ax), alpha(ay)), eta(e));
            c.push(
                "Layered<RoughDielectric, Lambert>",
                format!("α ({ax:e}, {ay:e}), η {e:e}, ρ 1 f32"),
                Some(eta(e)),
                Layered::new(top, Lambert::new(1.0f32).unwrap()),
            );
        }
    }
    // Energy-compensated coats over a white base, at the ends of the tables' range.
    for (ax, ay) in [(1e-4, 1e-4), (1.0, 1.0), (1e-4, 1.0), (0.3, 0.3)] {
        for e in [1.01, 1.5, 3.0, 1.0 / 3.0, 1.0 / 1.01] {
            let top = RoughDielectric::new(Ggx::new(alpha(ax), alpha(ay)), eta(e))
                .with_energy_compensation()
                .unwrap();
            c.push(
                "Layered<CompensatedDielectric, Lambert>",
                format!("α ({ax:e}, {ay:e}), η {e:e}, ρ 1 f32"),
                Some(eta(e)),
                Layered::new(top, Lambert::new(1.0f32).unwrap()),
            );
        }
    }
    // Rough conductors under a coat, the extreme conductor too, RGB.
    for e in [1.5, 1e-3, 1e3] {
        let top = RoughDielectric::new(Beckmann::isotropic(alpha(0.2)), eta(e));
        for (what, cond) in [("gold", gold), ("extreme", extreme_conductor())] {
            let base =
                Microfacet::new(Ggx::isotropic(alpha(0.05)), Masking::HeightCorrelated, cond);
            c.push(
                "Layered<RoughDielectric, Microfacet> (coated conductor)",
                format!("Beckmann α 0.2, η {e:e}, {what} GGX α 0.05 RGB"),
                Some(eta(e)),
                Layered::new(top, base),
            );
        }
    }
    // Smooth coats, every index, RGB base.
    for e in ETAS {
        c.push(
            "Layered<SmoothDielectric, Lambert>",
            format!("η {e:e}, ρ (1, 0.5, 0) RGB, no layer"),
            Some(eta(e)),
            Layered::new(SmoothDielectric::new(eta(e)), Lambert::new(rgb).unwrap())
                .with_thickness(0.0)
                .unwrap(),
        );
    }
    // Smooth coats over a base with a delta lobe, every index, a scattering layer: the walks
    // connect through the delta chains, from the base's diffuse lobe and from the medium.
    for e in ETAS {
        let half_mirror = Mix::new(
            Mirror::new(NoFresnel::<Vec3>::new()),
            Lambert::new(rgb).unwrap(),
            0.5,
        )
        .unwrap();
        c.push(
            "Layered<SmoothDielectric, Mix<Mirror, Lambert>>",
            format!("η {e:e}, half mirror, ρ (1, 0.5, 0) RGB, 0.5 mfp, albedo 0.9"),
            Some(eta(e)),
            Layered::new(SmoothDielectric::new(eta(e)), half_mirror)
                .with_thickness(0.5)
                .unwrap()
                .with_medium(Vec3::splat(0.9), 0.0)
                .unwrap(),
        );
    }
    // The layer's ends: thick and scattering, forward and backward, walks of 1 and 256
    // events, several walks per estimate.
    let coated =
        |r: f32| CoatedDiffuse::coated_diffuse(rgb, Ggx::isotropic(alpha(r)), eta(1.5)).unwrap();
    for (what, m) in [
        (
            "thickness 1e3, albedo 1, g 0.99",
            coated(0.3)
                .with_thickness(1e3)
                .unwrap()
                .with_medium(Vec3::ONE, 0.99)
                .unwrap(),
        ),
        (
            "thickness 1, albedo 1, g −0.99",
            coated(0.3)
                .with_thickness(1.0)
                .unwrap()
                .with_medium(Vec3::ONE, -0.99)
                .unwrap(),
        ),
        (
            "thickness 0, albedo (1, 0.5, 0), g 0",
            coated(1e-4)
                .with_thickness(0.0)
                .unwrap()
                .with_medium(rgb, 0.0)
                .unwrap(),
        ),
        ("max depth 1", coated(10.0).with_max_depth(1).unwrap()),
        (
            "max depth 256, 4 walks",
            coated(0.3)
                .with_max_depth(256)
                .unwrap()
                .with_samples(4)
                .unwrap(),
        ),
    ] {
        c.push(
            "CoatedDiffuse<Ggx, Vec3>",
            what.to_owned(),
            Some(eta(1.5)),
            m,
        );
    }
    // Blends: a weight at each end and between, exact and stochastic parts, a delta part.
    for w in [0.0, 0.5, 1.0] {
        let gloss = Microfacet::new(Ggx::new(alpha(1e-4), alpha(10.0)), Masking::VCavity, gold);
        c.push(
            "Mix",
            format!("Lambert RGB + GGX gold α (1e-4, 10), w {w}"),
            None,
            Mix::new(Lambert::new(rgb).unwrap(), gloss, w).unwrap(),
        );
        c.push(
            "Mix",
            format!("Mirror gold + Lambert RGB, w {w}"),
            None,
            Mix::new(Mirror::new(gold), Lambert::new(rgb).unwrap(), w).unwrap(),
        );
        c.push(
            "Mix",
            format!("CoatedDiffuse + Lambert RGB, w {w}"),
            Some(eta(1.5)),
            Mix::new(coated(0.3), Lambert::new(rgb).unwrap(), w).unwrap(),
        );
    }
    // Two-sided: a glossy model, a layered one.
    c.push(
        "TwoSided",
        "GGX extreme conductor α 1e-4".to_owned(),
        None,
        TwoSided::new(Microfacet::new(
            Ggx::isotropic(alpha(1e-4)),
            Masking::HeightCorrelated,
            extreme_conductor(),
        )),
    );
    c.push(
        "TwoSided",
        "CoatedDiffuse α 0.3".to_owned(),
        Some(eta(1.5)),
        TwoSided::new(coated(0.3)),
    );
    // Diffuse transmission at the ends of R + T ≤ 1.
    for (r, t) in [(0.0f32, 0.0f32), (1.0, 0.0), (0.0, 1.0), (0.5, 0.5)] {
        c.push(
            "DiffuseTransmission",
            format!("R {r}, T {t} f32"),
            None,
            DiffuseTransmission::new(r, t).unwrap(),
        );
    }
    c.push(
        "DiffuseTransmission",
        "R (1, 0.5, 0), T (0, 0.5, 1) RGB".to_owned(),
        None,
        DiffuseTransmission::new(rgb, Vec3::new(0.0, 0.5, 1.0)).unwrap(),
    );
    // Sheen at the ends of its roughness, with the fitted and the exact Smith masking.
    for r in [0.01f32, 0.3, 1.0] {
        c.push(
            "Sheen",
            format!("r {r}, colour (1, 0.5, 0) RGB"),
            None,
            Sheen::new(rgb, r).unwrap(),
        );
        c.push(
            "Sheen",
            format!("r {r}, exact Smith, colour (1, 0.5, 0) RGB"),
            None,
            Sheen::new_exact_smith(rgb, r).unwrap(),
        );
    }
}

// ---------------------------------------------------------------------------------------
// Main
// ---------------------------------------------------------------------------------------

fn main() {
    let n: usize = match std::env::args().nth(1) {
        None => 100_000,
        Some(a) => a.parse().unwrap_or_else(|_| {
            eprintln!("usage: fuzz [N]   (N: random inputs per configuration, default 100000)");
            std::process::exit(2)
        }),
    };
    // Building the models is not fuzzed: a panic there is reported as usual.
    let start = Instant::now();
    let configs = configs();
    let built = start.elapsed();
    // Panics are expected and counted: keep their messages for the report, not stderr.
    std::panic::set_hook(Box::new(|info| {
        // "panicked at file:line:column:\nmessage"
        let message = info.to_string().replace('\n', " ");
        PANIC.with(|p| *p.borrow_mut() = message);
    }));
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = AtomicUsize::new(0);
    let results: Vec<Mutex<Option<Tally>>> = configs.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(config) = configs.get(i) else { break };
                    let tally = (config.run)(n, i as u64);
                    *results[i].lock().unwrap() = Some(tally);
                }
            });
        }
    });

    // Rows in the order of first appearance, with their configurations' tallies summed; the
    // failing configurations; and failing inputs from as many configurations as possible.
    let mut rows: Vec<(String, usize, Tally)> = Vec::new();
    let mut failing: Vec<(String, String, u64, u64)> = Vec::new();
    let mut shown: Vec<(String, String, Failure)> = Vec::new();
    let tallies: Vec<Tally> = results
        .into_iter()
        .map(|r| r.into_inner().unwrap().expect("every configuration ran"))
        .collect();
    for round in 0..SHOWN {
        for (config, tally) in configs.iter().zip(&tallies) {
            for kind in KINDS {
                let kept = shown
                    .iter()
                    .filter(|(m, _, g)| *m == config.model && g.kind == kind)
                    .count();
                let nth = tally.failures.iter().filter(|f| f.kind == kind).nth(round);
                if let (true, Some(f)) = (kept < SHOWN, nth) {
                    shown.push((config.model.clone(), config.params.clone(), f.clone()));
                }
            }
        }
    }
    for (config, tally) in configs.iter().zip(tallies) {
        if tally.total() > 0 {
            failing.push((
                config.model.clone(),
                config.params.clone(),
                tally.total(),
                tally.at_one,
            ));
        }
        match rows.iter_mut().find(|(m, _, _)| *m == config.model) {
            Some((_, k, t)) => {
                *k += 1;
                t.add(tally);
            }
            None => rows.push((config.model.clone(), 1, tally)),
        }
    }

    let mut out = String::new();
    let corners = corner_inputs(None, &mut Pcg32::new(0, 0)).len();
    writeln!(
        out,
        "lobe fuzz: {} configurations, {corners} corner + {n} random inputs each, \
         8 scalar calls and 3 batched lanes per input",
        configs.len()
    )
    .unwrap();
    writeln!(out).unwrap();
    write!(out, "| model | configs | inputs |").unwrap();
    for k in KINDS {
        write!(out, " {} |", k.header()).unwrap();
    }
    writeln!(out, " of which u = 1 |").unwrap();
    writeln!(out, "|---|---:|---:|{}", "---:|".repeat(KINDS.len() + 1)).unwrap();
    let mut total = Tally::default();
    for (model, k, t) in &rows {
        write!(out, "| {model} | {k} | {} |", t.inputs).unwrap();
        for c in t.counts {
            write!(out, " {c} |").unwrap();
        }
        writeln!(out, " {} |", t.at_one).unwrap();
        total.inputs += t.inputs;
        total.at_one += t.at_one;
        for (a, b) in total.counts.iter_mut().zip(t.counts) {
            *a += b;
        }
    }
    write!(out, "| **all** | {} | {} |", configs.len(), total.inputs).unwrap();
    for c in total.counts {
        write!(out, " {c} |").unwrap();
    }
    writeln!(out, " {} |", total.at_one).unwrap();
    print!("{out}");

    if !failing.is_empty() {
        println!("\nFailing configurations (bad results; of which with u or uc = 1):");
        for (model, params, bad, at_one) in &failing {
            println!("  {model} ({params}): {bad}; {at_one}");
        }
    }

    if !shown.is_empty() {
        println!("\nFirst failing inputs (at most {SHOWN} per model and kind):");
        for (model, params, f) in &shown {
            let Input { wo, wi, u, uc } = f.input;
            println!(
                "  [{}] {model} ({params}): {}(wo = {wo:?}, wi = {wi:?}, u = {u:?}, uc = {uc:?}) = {}",
                f.kind.header(),
                f.call,
                f.value
            );
        }
    }
    println!(
        "\n{threads} threads, {:.1} s ({:.1} s building the models)",
        start.elapsed().as_secs_f64(),
        built.as_secs_f64()
    );
    if total.total() > 0 {
        println!("FAIL: {} bad results", total.total());
        std::process::exit(1);
    }
    println!("OK: no bad results");
}
