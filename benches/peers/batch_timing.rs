//! The batched half of the Mitsuba 3 comparison (`benches/peers/vs_mitsuba.py` runs it):
//!
//! ```sh
//! batch-timing write FILE N   # writes N (wo, wi, u, uc) lanes, f32 little-endian, one array per coordinate
//! batch-timing time FILE      # times lobe's batched GGX gold conductor on them; prints ns per lane
//! batch-timing sizes          # lobe's batched eval at 4,096, 2^15 and 2^20 lanes (no Mitsuba)
//! ```
//!
//! Besides the model's three calls it times, on the same lanes, a memory pass (`wo + wi`: the
//! floor with ordinary stores; Dr.Jit's kernels store with streaming stores, see the script)
//! and three parts of the work, which the script times on Mitsuba's side too: the
//! exact conductor Fresnel term alone (gold, RGB, at `cos θ = wo.z`), a chain of twelve
//! divisions `z ← y/z + 1` and a chain of twelve square roots `z ← √(z + y)` (`y = 1 + wi.z`,
//! from `z = 1 + wo.z`), which show what one division and one square root cost each side.
//! These loops are compiled for the widest instruction set the CPU has, by the same run-time
//! dispatch as `lobe::batch`.
//!
//! The model is Mitsuba's `roughconductor` with `distribution = ggx`, `alpha = 0.3`,
//! `material = Au`, `sample_visible = true`: the GGX conductor with gold's complex index and
//! plain visible-normal sampling (`with_bounded_reflection(false)`). The timing runs on one
//! thread, five passes per kernel after a warm-up pass, and prints the median.

#[path = "../common/inputs.rs"]
#[allow(dead_code)]
mod inputs;
// The medians and spreads of the peer bench's interleaved rounds (its round runner is unused
// here).
#[path = "../common/interleave.rs"]
#[allow(dead_code)]
mod interleave;
mod lanes;

use lanes::PerLane;
use lobe::batch::{Batch, SampleOut, Vec2s, Vec3s, Vec3sMut};
use lobe::bxdf::{Lambert, Lobes, Microfacet};
use lobe::fresnel::{Conductor, Fresnel, Schlick};
use lobe::microfacet::{Ggx, Masking};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Vec3};
use std::hint::black_box;
use std::time::Instant;

/// The benchmarks' directions (5% grazing) and random numbers, `n` lanes, one array per
/// coordinate: wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, u.x, u.y, uc.
fn lanes(n: usize) -> Vec<Vec<f32>> {
    let mut rng = Pcg32::new(0x10be, 11);
    let mut cols: Vec<Vec<f32>> = (0..9).map(|_| Vec::with_capacity(n)).collect();
    for _ in 0..n {
        let (wo, wi) = (inputs::direction(&mut rng), inputs::direction(&mut rng));
        for (c, v) in [wo.x, wo.y, wo.z, wi.x, wi.y, wi.z].into_iter().enumerate() {
            cols[c].push(v);
        }
        cols[6].push(rng.next_f32());
        cols[7].push(rng.next_f32());
        cols[8].push(rng.next_f32());
    }
    cols
}

fn write(path: &str, n: usize) {
    let bytes: Vec<u8> = lanes(n)
        .iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    std::fs::write(path, bytes).expect("write the inputs");
}

/// The batch sizes of [`sizes`]: a renderer's queue, one that stays in a 2 MiB L2 with six
/// inputs and three outputs, and one far past it.
const SIZES: [usize; 3] = [4096, 1 << 15, 1 << 20];

/// The first `n` lanes of the three coordinate arrays `c[first..first + 3]` (`first` 0 for
/// `wo`, 3 for `wi`).
fn vec3s(c: &[Vec<f32>], first: usize, n: usize) -> Vec3s<'_> {
    Vec3s {
        x: &c[first][..n],
        y: &c[first + 1][..n],
        z: &c[first + 2][..n],
    }
}

/// ns per lane of `m.eval_batch` over the first `n` lanes of `c`: the median of five passes
/// of 2²² lanes each (the batch repeated), after one untimed pass.
fn eval_per_lane<M: Batch<Spectrum = Vec3>>(m: &M, c: &[Vec<f32>], n: usize) -> f64 {
    let (wo, wi) = (vec3s(c, 0, n), vec3s(c, 3, n));
    let mut o: Vec<Vec<f32>> = vec![vec![0.0; n]; 3];
    let [r, g, b] = &mut o[..] else {
        unreachable!()
    };
    let reps = (1 << 22) / n;
    time(n * reps, || {
        for _ in 0..reps {
            m.eval_batch(wo, wi, Vec3sMut { x: r, y: g, z: b }).unwrap();
            black_box(&r[0]);
        }
    })
}

/// The batched `eval` of a light model (Lambert), a Schlick conductor and the gold conductor
/// over the three [`SIZES`], in five interleaved rounds: what a batch past the L2 costs.
fn sizes() {
    let c = lanes(SIZES[2]);
    let alpha = Alpha::new(0.3).unwrap();
    let lambert = Lambert::new(Vec3::new(0.8, 0.6, 0.4)).unwrap();
    let schlick = Microfacet::new(
        Ggx::isotropic(alpha),
        Masking::HeightCorrelated,
        Schlick::new(Vec3::new(1.0, 0.78, 0.34)).unwrap(),
    );
    let gold = gold_conductor();
    let names = ["Lambert RGB", "GGX Schlick RGB", "GGX gold"];
    // t[model][size]: one figure per round.
    let mut t = vec![vec![Vec::new(); SIZES.len()]; names.len()];
    for _ in 0..5 {
        for (k, &n) in SIZES.iter().enumerate() {
            t[0][k].push(eval_per_lane(&lambert, &c, n));
            t[1][k].push(eval_per_lane(&schlick, &c, n));
            t[2][k].push(eval_per_lane(&gold, &c, n));
        }
    }
    println!(
        "batched eval ({}), ns per lane: median [min, max] over 5 interleaved rounds\n",
        lobe::batch::instruction_set()
    );
    println!("| model | 4,096 lanes | 2^15 lanes | 2^20 lanes |");
    println!("| --- | --- | --- | --- |");
    for (name, row) in names.iter().zip(&t) {
        let cells: Vec<String> = row
            .iter()
            .map(|xs| {
                let (median, min, max) = interleave::spread(xs);
                format!("{median:.2} [{min:.2}, {max:.2}]")
            })
            .collect();
        println!("| {name} | {} |", cells.join(" | "));
    }
}

fn read(path: &str) -> Vec<Vec<f32>> {
    let bytes = std::fs::read(path).expect("read the inputs");
    let floats: Vec<f32> = bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let n = floats.len() / 9;
    floats.chunks_exact(n).map(<[f32]>::to_vec).collect()
}

/// Gold's complex index, RGB.
fn gold() -> ComplexIor<Vec3> {
    ComplexIor::new(
        Vec3::new(0.143, 0.375, 1.442),
        Vec3::new(3.983, 2.386, 1.603),
    )
    .unwrap()
}

/// The model of the comparison: Mitsuba's `roughconductor` (GGX, α 0.3, gold, plain
/// visible-normal sampling).
fn gold_conductor() -> Microfacet<Ggx, Conductor<Vec3>> {
    Microfacet::new(
        Ggx::isotropic(Alpha::new(0.3).unwrap()).with_bounded_reflection(false),
        Masking::HeightCorrelated,
        Conductor { ior: gold() },
    )
}

/// `(r, g, b)[k] = F(cos[k])`, the exact conductor term channel by channel (the form the
/// batched microfacet loops use).
struct FresnelLanes<'a> {
    fresnel: &'a Conductor<Vec3>,
    cos: &'a [f32],
    out: [&'a mut [f32]; 3],
}

impl pulp::WithSimd for FresnelLanes<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        // Outputs re-sliced to the inputs' length (no bounds checks in the loop), and the
        // term copied out of the reference (its parameters then stay in registers), as the
        // batched loops do.
        let n = self.cos.len();
        let [r, g, b] = self.out.map(|o| &mut o[..n]);
        let fresnel = *self.fresnel;
        for (k, &c) in self.cos.iter().enumerate() {
            let f = fresnel.eval_per_channel(c);
            (r[k], g[k], b[k]) = (f.x, f.y, f.z);
        }
    }
}

/// The median of five timed passes of `f`, in ns per lane, after one untimed pass.
fn time(n: usize, mut f: impl FnMut()) -> f64 {
    f();
    let t: Vec<f64> = (0..5)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_nanos() as f64 / n as f64
        })
        .collect();
    interleave::median(&t)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    match args.get(1).map(String::as_str) {
        Some("write") => write(&args[2], args[3].parse().expect("N")),
        Some("time") => {
            let c = read(&args[2]);
            let n = c[0].len();
            let m = gold_conductor();
            let m = black_box(&m);
            let (wo, wi) = (vec3s(&c, 0, n), vec3s(&c, 3, n));
            let u = Vec2s { x: &c[6], y: &c[7] };
            let mut o: Vec<Vec<f32>> = vec![vec![0.0; n]; 8];
            let mut lobes = vec![Lobes::NONE; n];
            let [a, b, cc, d, e, f, g, h] = &mut o[..] else {
                unreachable!()
            };
            let eval = time(n, || {
                m.eval_batch(wo, wi, Vec3sMut { x: a, y: b, z: cc })
                    .unwrap();
            });
            let pdf = time(n, || m.pdf_batch(wo, wi, d).unwrap());
            let sample = time(n, || {
                let out = SampleOut {
                    wi: Vec3sMut { x: a, y: b, z: cc },
                    f: Vec3sMut { x: d, y: e, z: f },
                    pdf: g,
                    lobe: &mut lobes,
                    eta: h,
                };
                m.sample_batch(wo, u, &c[8], out).unwrap();
            });
            // A pass that reads the eval inputs and writes its outputs: the memory floor,
            // compiled for the widest instruction set as the batched calls are (the baseline
            // SSE2 loop was slower than Mitsuba's pass on some machines of this kind).
            let arch = pulp::Arch::new();
            let copy = time(n, || {
                for (out, (x, y)) in
                    [&mut *a, &mut *b, &mut *cc]
                        .into_iter()
                        .zip([(0, 3), (1, 4), (2, 5)])
                {
                    arch.dispatch(PerLane {
                        x: &c[x],
                        y: &c[y],
                        out,
                        f: |p: f32, q: f32| p + q,
                    });
                }
            });
            let fresnel = black_box(Conductor { ior: gold() });
            let fresnel_alone = time(n, || {
                arch.dispatch(FresnelLanes {
                    fresnel: &fresnel,
                    cos: &c[2],
                    out: [&mut *a, &mut *b, &mut *cc],
                });
            });
            let (x, y): (Vec<f32>, Vec<f32>) = c[2]
                .iter()
                .zip(&c[5])
                .map(|(o, i)| (1.0 + o, 1.0 + i))
                .unzip();
            // Twelve dependent divisions per lane: z ← y/z + 1, from z = x.
            let divide = time(n, || {
                arch.dispatch(PerLane {
                    x: &x,
                    y: &y,
                    out: &mut *a,
                    f: |x: f32, y: f32| (0..12).fold(x, |z, _| y / z + 1.0),
                });
            }) / 12.0;
            // Twelve dependent square roots per lane: z ← √(z + y), from z = x.
            let root = time(n, || {
                arch.dispatch(PerLane {
                    x: &x,
                    y: &y,
                    out: &mut *a,
                    f: |x: f32, y: f32| (0..12).fold(x, |z, _| (z + y).sqrt()),
                });
            }) / 12.0;
            black_box(&o);
            println!(
                "{{\"eval\": {eval}, \"pdf\": {pdf}, \"sample\": {sample}, \"copy\": {copy}, \"fresnel\": {fresnel_alone}, \"divide\": {divide}, \"root\": {root}, \"isa\": \"{}\"}}",
                lobe::batch::instruction_set()
            );
        }
        Some("sizes") => sizes(),
        _ => eprintln!(
            "usage: batch-timing write FILE N | batch-timing time FILE | batch-timing sizes"
        ),
    }
}
