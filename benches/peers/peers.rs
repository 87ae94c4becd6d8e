//! lobe (scalar and batched) against the `bsdf` crate (0.1.1, `f64`) on the same 4,096
//! inputs: criterion's per-function figures, then interleaved rounds (A B C A B C …) with the
//! ratios. (Mitsuba 3, which needs Python and LLVM: `benches/peers/vs_mitsuba.py`.)
//!
//! Then lobe alone, scalar against batched, where the peer has no model: the GGX rough
//! dielectric (η 1.5, the sides mixed as in the shading benchmarks), and the
//! energy-compensated GGX gold conductor and rough glass (Kulla & Conty's lobe on top), the
//! GGX plastic, plain and with the compensated coat, the energy-preserving Oren-Nayar model
//! (EON, its albedo fitted), the glazed diffuse model and the smooth glass (the sides mixed).
//!
//! Last, the ceiling of batching for work bound by the divider: one square root and one
//! division per element, scalar (measured as lobe's scalar calls are) against the same loop
//! compiled for the widest instruction set (pulp's run-time dispatch, as `lobe::batch` does).
//! A kernel whose time is mostly square roots and divisions cannot gain more from batching
//! than this ratio, whatever else it does.
//!
//! ```sh
//! cargo bench -p lobe-peers
//! ```

#[path = "../common/inputs.rs"]
mod inputs;
#[path = "../common/interleave.rs"]
mod interleave;
mod lanes;

use bsdf::BSDF;
use criterion::{Criterion, Throughput};
use inputs::{Inputs, N, inputs, two_sided};
use interleave::{Kernel, ratio, rounds, spread};
use lanes::PerLane;
use lobe::batch::{Batch, Lanes, SampleOut, Vec2s, Vec3s, Vec3sMut};
use lobe::bxdf::{Bxdf, Lambert, Lobes, Microfacet, Plastic, Prepare, RoughDielectric};
use lobe::bxdf::{EnergyPreservingOrenNayar, Glazed, SmoothDielectric};
use lobe::fresnel::{Conductor as ExactConductor, Fresnel, Schlick};
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, Eta, Vec3};
use std::hint::black_box;
use std::time::Duration;

/// The conductor's normal-incidence reflectance (gold-like) and width.
const F0: [f32; 3] = [1.0, 0.78, 0.34];
const ALPHA: f32 = 0.3;

type Conductor = Microfacet<Ggx, Schlick<Vec3>>;

/// The `bsdf` crate's conductor Fresnel term, for lobe to compute the peer's own model: the
/// exact dielectric reflectance `F` at its `ior` (1.5), blended toward white,
/// `c (1 − F) + F` (its `fresnel_colored`; not Schlick's, and 0.04 + 0.96 c head-on).
#[derive(Clone, Copy)]
struct PeerFresnel {
    color: Vec3,
    eta: Eta,
}

impl Fresnel for PeerFresnel {
    type Spectrum = Vec3;
    #[inline]
    fn eval(&self, cos_d: f32) -> Vec3 {
        let f = lobe::fresnel::dielectric(cos_d, self.eta);
        self.color * (1.0 - f) + Vec3::splat(f)
    }
}

/// The `bsdf` crate's GGX conductor as lobe computes it: its Fresnel term, separable Smith
/// masking `G1(wo) G1(wi)`, and Heitz's visible normals without the bounded cap (lobe's
/// default GGX draws from Eto & Tokuyoshi's bounded sampler, another density).
fn lobe_as_peer_conductor() -> Microfacet<Ggx, PeerFresnel> {
    Microfacet::new(
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()).with_bounded_reflection(false),
        Masking::Separable,
        PeerFresnel {
            color: Vec3::from(F0),
            eta: Eta::new(1.5).unwrap(),
        },
    )
}

fn lobe_conductor() -> Conductor {
    Microfacet::new(
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        Masking::HeightCorrelated,
        Schlick::new(Vec3::from(F0)).unwrap(),
    )
}

fn bsdf_conductor() -> bsdf::conductive::Conductive {
    bsdf::conductive::Conductive {
        color: bsdf::RgbF::from(F0),
        ggx: bsdf::ggx::GGX {
            alpha_x: f64::from(ALPHA),
            alpha_y: f64::from(ALPHA),
        },
        ior: 1.5,
    }
}

/// The inputs in the peer's `f64` vectors.
struct Inputs64 {
    wo: Vec<bsdf::Vec3d>,
    wi: Vec<bsdf::Vec3d>,
    rnd: Vec<bsdf::Vec3d>,
}

fn to_f64(i: &Inputs) -> Inputs64 {
    let v = |w: &Vec3| bsdf::Vec3d::new(w.x.into(), w.y.into(), w.z.into());
    Inputs64 {
        wo: i.wo.iter().map(v).collect(),
        wi: i.wi.iter().map(v).collect(),
        rnd: (0..N)
            .map(|k| bsdf::Vec3d::new(i.u[k].x.into(), i.u[k].y.into(), i.uc[k].into()))
            .collect(),
    }
}

/// The three calls of a lobe model over the inputs, as kernels.
fn lobe_kernels<'a, B: Bxdf>(name: &str, m: &'a B, i: &'a Inputs) -> [Kernel<'a>; 3] {
    // The model through `black_box`, so that its parameters are not folded into the loop;
    // the inputs are read from memory as a renderer's would be.
    let m = black_box(m);
    [
        Kernel::new(format!("{name} eval"), N, move || {
            for k in 0..N {
                black_box(m.eval(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name} pdf"), N, move || {
            for k in 0..N {
                black_box(m.pdf(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name} sample"), N, move || {
            for k in 0..N {
                black_box(m.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
    ]
}

/// The inputs as structure-of-arrays slices, and output buffers, for the batched calls.
struct Soa {
    wo: [Vec<f32>; 3],
    wi: [Vec<f32>; 3],
    u: [Vec<f32>; 2],
    uc: Vec<f32>,
}

fn to_soa(i: &Inputs) -> Soa {
    let col = |v: &[Vec3], c: usize| v.iter().map(|w| w[c]).collect::<Vec<f32>>();
    Soa {
        wo: [col(&i.wo, 0), col(&i.wo, 1), col(&i.wo, 2)],
        wi: [col(&i.wi, 0), col(&i.wi, 1), col(&i.wi, 2)],
        u: [
            i.u.iter().map(|u| u.x).collect(),
            i.u.iter().map(|u| u.y).collect(),
        ],
        uc: i.uc.clone(),
    }
}

impl Soa {
    /// The directions and random numbers as the batched calls take them.
    fn views(&self) -> (Vec3s<'_>, Vec3s<'_>, Vec2s<'_>) {
        fn v3(v: &[Vec<f32>; 3]) -> Vec3s<'_> {
            Vec3s {
                x: &v[0],
                y: &v[1],
                z: &v[2],
            }
        }
        let u = Vec2s {
            x: &self.u[0],
            y: &self.u[1],
        };
        (v3(&self.wo), v3(&self.wi), u)
    }
}

/// A spectrum's batched values, written into one buffer per channel.
trait Channels: Lanes {
    /// How many channels.
    const COUNT: usize;
    /// The output slices over `buffers` (`COUNT` of them).
    fn slices(buffers: &mut [Vec<f32>]) -> Self::Mut<'_>;
}

impl Channels for f32 {
    const COUNT: usize = 1;
    fn slices(buffers: &mut [Vec<f32>]) -> &mut [f32] {
        &mut buffers[0]
    }
}

impl Channels for Vec3 {
    const COUNT: usize = 3;
    fn slices(buffers: &mut [Vec<f32>]) -> Vec3sMut<'_> {
        let [x, y, z] = buffers else { unreachable!() };
        Vec3sMut { x, y, z }
    }
}

/// The three calls of a lobe model through `lobe::batch`, each kernel owning its output
/// buffers.
fn batch_kernels<'a, B: Batch>(name: &str, m: &'a B, s: &'a Soa) -> [Kernel<'a>; 3]
where
    B::Spectrum: Channels,
{
    let m = black_box(m);
    let (wo, wi, u) = s.views();
    let buffers = |n: usize| -> Vec<Vec<f32>> { vec![vec![0.0; N]; n] };
    let channels = <B::Spectrum as Channels>::COUNT;
    [
        Kernel::new(format!("{name} eval"), N, {
            let mut o = buffers(channels);
            move || {
                m.eval_batch(wo, wi, B::Spectrum::slices(&mut o)).unwrap();
                black_box(&o);
            }
        }),
        Kernel::new(format!("{name} pdf"), N, {
            let mut o = vec![0.0; N];
            move || {
                m.pdf_batch(wo, wi, &mut o).unwrap();
                black_box(&o);
            }
        }),
        Kernel::new(format!("{name} sample"), N, {
            // wi's three coordinates, the value's channels, the density, eta; the lobes.
            let mut o = buffers(3 + channels + 2);
            let mut lobes = vec![Lobes::NONE; N];
            move || {
                let (dir, rest) = o.split_at_mut(3);
                let (f, rest) = rest.split_at_mut(channels);
                let [x, y, z] = dir else { unreachable!() };
                let [pdf, eta] = rest else { unreachable!() };
                let out = SampleOut {
                    wi: Vec3sMut { x, y, z },
                    f: B::Spectrum::slices(f),
                    pdf,
                    lobe: &mut lobes,
                    eta,
                };
                m.sample_batch(wo, u, &s.uc, out).unwrap();
                black_box((&o, &lobes));
            }
        }),
    ]
}

/// The three calls of a lobe model, scalar and batched, as pairs of kernels for the same work.
fn scalar_and_batched<'a, B: Bxdf + Batch>(
    name: &str,
    m: &'a B,
    i: &'a Inputs,
    s: &'a Soa,
) -> impl Iterator<Item = [Kernel<'a>; 2]>
where
    <B as Prepare>::Spectrum: Channels,
{
    let (scalar, batched) = (lobe_kernels(name, m, i), batch_kernels(name, m, s));
    scalar.into_iter().zip(batched).map(|(a, b)| [a, b])
}

/// The divider's ceiling, scalar and batched: one square root and one division per element,
/// on `1 + cos θo` and `1 + cos θi` of the inputs.
fn divider_kernels(i: &Inputs) -> [Kernel<'static>; 2] {
    let x: Vec<f32> = i.wo.iter().map(|w| 1.0 + w.z).collect();
    let y: Vec<f32> = i.wi.iter().map(|w| 1.0 + w.z).collect();
    let (xs, ys) = (x.clone(), y.clone());
    let arch = pulp::Arch::new();
    let mut out = vec![0.0; N];
    [
        Kernel::new("divider alone (√x / y): scalar", N, move || {
            for k in 0..N {
                black_box(xs[k].sqrt() / ys[k]);
            }
        }),
        Kernel::new("divider alone (√x / y): batched", N, move || {
            arch.dispatch(PerLane {
                x: &x,
                y: &y,
                out: &mut out,
                f: |x: f32, y: f32| x.sqrt() / y,
            });
            black_box(&out);
        }),
    ]
}

/// The same three calls of a `bsdf` model.
fn peer_kernels<'a, B: BSDF>(name: &str, m: &'a B, i: &'a Inputs64) -> [Kernel<'a>; 3] {
    let m = black_box(m);
    [
        Kernel::new(format!("{name} eval"), N, move || {
            for k in 0..N {
                black_box(m.evaluate(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name} pdf"), N, move || {
            for k in 0..N {
                black_box(m.sample_incoming_pdf(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name} sample"), N, move || {
            for k in 0..N {
                black_box(m.sample_incoming(i.wo[k], i.rnd[k]));
            }
        }),
    ]
}

/// Asserts that lobe's `m` computes the peer's `peer` on the inputs: `eval` and `pdf` within
/// 1e-4 relative (`f32` against `f64`) wherever the peer's value is above 1e-3 of its largest,
/// and printing the largest differences.
fn same_model<B: Bxdf<Spectrum = Vec3>, P: BSDF>(m: &B, peer: &P, i: &Inputs, i64: &Inputs64) {
    let (mut worst_f, mut worst_p, mut fmax, mut pmax) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    let values: Vec<_> = (0..N)
        .map(|k| {
            let f = peer.evaluate(i64.wo[k], i64.wi[k]);
            let p = peer.sample_incoming_pdf(i64.wo[k], i64.wi[k]);
            ([f.x, f.y, f.z], p)
        })
        .collect();
    for (f, p) in &values {
        fmax = f.iter().copied().fold(fmax, f64::max);
        pmax = pmax.max(*p);
    }
    for (k, (f, p)) in values.iter().enumerate() {
        let (ours, our_pdf) = (m.eval(i.wo[k], i.wi[k]), m.pdf(i.wo[k], i.wi[k]));
        for c in 0..3 {
            if f[c] > 1e-3 * fmax {
                worst_f = worst_f.max((f64::from(ours[c]) - f[c]).abs() / f[c]);
            }
        }
        if *p > 1e-3 * pmax {
            worst_p = worst_p.max((f64::from(our_pdf) - p).abs() / p);
        }
    }
    println!("the peer's model in lobe: eval within {worst_f:.1e}, pdf within {worst_p:.1e}");
    assert!(worst_f < 1e-4 && worst_p < 1e-4, "not the same model");
}

fn main() {
    let inputs = inputs();
    let inputs64 = to_f64(&inputs);
    let (conductor, peer_conductor) = (lobe_conductor(), bsdf_conductor());
    let lambert = Lambert::new(Vec3::new(0.8, 0.6, 0.4)).unwrap();
    let peer_lambert = bsdf::lambert::Lambert {
        kd: bsdf::RgbF::new(0.8, 0.6, 0.4),
    };

    // Triples of (lobe scalar, lobe batched, peer) kernels for the same work.
    let soa = to_soa(&inputs);
    let mut triples: Vec<[Kernel; 3]> = Vec::new();
    let lobe_c = lobe_kernels("GGX conductor, Schlick RGB: lobe", &conductor, &inputs);
    let batch_c = batch_kernels("GGX conductor, Schlick RGB: lobe batched", &conductor, &soa);
    let peer_c = peer_kernels(
        "GGX conductor, Schlick RGB: bsdf",
        &peer_conductor,
        &inputs64,
    );
    for ((a, b), c) in lobe_c.into_iter().zip(batch_c).zip(peer_c) {
        triples.push([a, b, c]);
    }
    // The peer's own model on both sides (its Fresnel, separable masking, unbounded VNDF),
    // checked to be the same function before it is timed.
    let as_peer = lobe_as_peer_conductor();
    same_model(&as_peer, &peer_conductor, &inputs, &inputs64);
    let name = "GGX conductor, the peer's model on both sides";
    let lobe_p = lobe_kernels(&format!("{name}: lobe"), &as_peer, &inputs);
    let batch_p = batch_kernels(&format!("{name}: lobe batched"), &as_peer, &soa);
    let peer_p = peer_kernels(&format!("{name}: bsdf"), &peer_conductor, &inputs64);
    for ((a, b), c) in lobe_p.into_iter().zip(batch_p).zip(peer_p) {
        triples.push([a, b, c]);
    }
    let lobe_l = lobe_kernels("Lambert RGB: lobe", &lambert, &inputs);
    let batch_l = batch_kernels("Lambert RGB: lobe batched", &lambert, &soa);
    let peer_l = peer_kernels("Lambert RGB: bsdf", &peer_lambert, &inputs64);
    for ((a, b), c) in lobe_l.into_iter().zip(batch_l).zip(peer_l) {
        triples.push([a, b, c]);
    }

    // Criterion's own figures, one group per work.
    let mut c = Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .configure_from_args();
    for [a, b, p] in &mut triples {
        let work = a.name.replace(": lobe", "");
        let mut g = c.benchmark_group(work);
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("lobe", |bench| bench.iter(&mut a.pass));
        g.bench_function("lobe batched", |bench| bench.iter(&mut b.pass));
        g.bench_function("bsdf 0.1.1", |bench| bench.iter(&mut p.pass));
        g.finish();
    }

    // Pairs of (lobe scalar, lobe batched) for work the peer has no model of: the rough
    // dielectric (the sides mixed), the compensated models, the plastics, EON, the glazed
    // model, the smooth glass, and the divider alone.
    let glass = RoughDielectric::new(
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        Eta::new(1.5).unwrap(),
    );
    let mixed = two_sided(&inputs);
    let mixed_soa = to_soa(&mixed);
    let mut pairs: Vec<[Kernel; 2]> = Vec::new();
    let name = "GGX rough glass η 1.5, sides mixed";
    pairs.extend(scalar_and_batched(name, &glass, &mixed, &mixed_soa));
    let compensated_gold = Microfacet::new(
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        Masking::HeightCorrelated,
        ExactConductor {
            ior: lobe::metals::GOLD.rgb(),
        },
    )
    .with_energy_compensation()
    .unwrap();
    let name = "compensated GGX gold";
    pairs.extend(scalar_and_batched(name, &compensated_gold, &inputs, &soa));
    let compensated_glass = glass.with_energy_compensation().unwrap();
    let name = "compensated GGX rough glass η 1.5, sides mixed";
    pairs.extend(scalar_and_batched(
        name,
        &compensated_glass,
        &mixed,
        &mixed_soa,
    ));
    let plastic = Plastic::new(
        Vec3::new(0.8, 0.6, 0.4),
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        Eta::new(1.5).unwrap(),
    )
    .unwrap();
    pairs.extend(scalar_and_batched(
        "GGX plastic RGB",
        &plastic,
        &inputs,
        &soa,
    ));
    let compensated_plastic = Plastic::compensated(
        Vec3::new(0.8, 0.6, 0.4),
        Ggx::isotropic(Alpha::new(ALPHA).unwrap()),
        Eta::new(1.5).unwrap(),
    )
    .unwrap();
    pairs.extend(scalar_and_batched(
        "compensated GGX plastic RGB",
        &compensated_plastic,
        &inputs,
        &soa,
    ));
    let eon = EnergyPreservingOrenNayar::new(Vec3::new(0.8, 0.6, 0.4), 0.5).unwrap();
    pairs.extend(scalar_and_batched("EON RGB", &eon, &inputs, &soa));
    let glazed = Glazed::new(Vec3::new(0.8, 0.6, 0.4), Eta::new(1.5).unwrap()).unwrap();
    let name = "glazed RGB η 1.5";
    pairs.extend(scalar_and_batched(name, &glazed, &inputs, &soa));
    let smooth = SmoothDielectric::new(Eta::new(1.5).unwrap());
    let name = "smooth glass η 1.5, sides mixed";
    pairs.extend(scalar_and_batched(name, &smooth, &mixed, &mixed_soa));
    pairs.push(divider_kernels(&inputs));
    for [a, b] in &mut pairs {
        let mut g = c.benchmark_group(a.name.replace(": scalar", ""));
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("lobe", |bench| bench.iter(&mut a.pass));
        g.bench_function("lobe batched", |bench| bench.iter(&mut b.pass));
        g.finish();
    }

    // Interleaved rounds: every kernel once per round, in the same order.
    let sizes: Vec<usize> = triples
        .iter()
        .map(|_| 3)
        .chain(pairs.iter().map(|_| 2))
        .collect();
    let mut kernels: Vec<Kernel> = triples.into_iter().flatten().collect();
    kernels.extend(pairs.into_iter().flatten());
    let times = rounds(&mut kernels, 15, Duration::from_millis(40));
    println!(
        "\nInterleaved, 15 rounds, ns per evaluation: median [min, max]; ratios = medians of the per-round ratios"
    );
    println!(
        "| work (ns per call) | lobe | lobe batched | bsdf 0.1.1 | lobe / bsdf | lobe scalar / batched |"
    );
    println!("| --- | --- | --- | --- | --- | --- |");
    let fmt = |t: &[f64]| {
        let (m, lo, hi) = spread(t);
        format!("{m:.2} [{lo:.2}, {hi:.2}]")
    };
    let mut first = 0;
    for size in sizes {
        let (ks, ts) = (&kernels[first..first + size], &times[first..first + size]);
        first += size;
        // Each row: lobe scalar, lobe batched and, in a triple, the peer.
        let (peer, versus) = match ts.get(2) {
            Some(p) => {
                let (r, rmin, rmax) = ratio(&ts[0], p);
                (fmt(p), format!("{r:.2}× [{rmin:.2}, {rmax:.2}]"))
            }
            None => ("—".to_owned(), "—".to_owned()),
        };
        let (x, xmin, xmax) = ratio(&ts[0], &ts[1]);
        println!(
            "| {} | {} | {} | {peer} | {versus} | {x:.1}× [{xmin:.1}, {xmax:.1}] |",
            ks[0].name.replace(": lobe", "").replace(": scalar", ""),
            fmt(&ts[0]),
            fmt(&ts[1]),
        );
    }
}
