//! lobe against the `bsdf` crate (0.1.1, `f64`) on the same 4,096 inputs: criterion's
//! per-function figures, then interleaved rounds (A B A B …) with the ratios.
//!
//! ```sh
//! cargo bench -p lobe-peers
//! ```

#[path = "../inputs.rs"]
mod inputs;
#[path = "../interleave.rs"]
mod interleave;

use bsdf::BSDF;
use criterion::{Criterion, Throughput};
use inputs::{Inputs, N, inputs};
use interleave::{Kernel, ratio, rounds, spread};
use lobe::bxdf::{Bxdf, Lambert, Microfacet};
use lobe::fresnel::Schlick;
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, Vec3};
use std::hint::black_box;
use std::time::Duration;

/// The conductor's normal-incidence reflectance (gold-like) and width.
const F0: [f32; 3] = [1.0, 0.78, 0.34];
const ALPHA: f32 = 0.3;

type Conductor = Microfacet<Ggx, Schlick<Vec3>>;

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
fn lobe_kernels<'a, B: Bxdf<Spectrum = Vec3>>(
    name: &str,
    m: &'a B,
    i: &'a Inputs,
) -> [Kernel<'a>; 3] {
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

fn main() {
    let inputs = inputs();
    let inputs64 = to_f64(&inputs);
    let (conductor, peer_conductor) = (lobe_conductor(), bsdf_conductor());
    let lambert = Lambert::new(Vec3::new(0.8, 0.6, 0.4)).unwrap();
    let peer_lambert = bsdf::lambert::Lambert {
        kd: bsdf::RgbF::new(0.8, 0.6, 0.4),
    };

    // Pairs of (lobe, peer) kernels for the same work.
    let mut pairs: Vec<(Kernel, Kernel)> = Vec::new();
    let lobe_c = lobe_kernels("GGX conductor, Schlick RGB: lobe", &conductor, &inputs);
    let peer_c = peer_kernels(
        "GGX conductor, Schlick RGB: bsdf",
        &peer_conductor,
        &inputs64,
    );
    pairs.extend(lobe_c.into_iter().zip(peer_c));
    let lobe_l = lobe_kernels("Lambert RGB: lobe", &lambert, &inputs);
    let peer_l = peer_kernels("Lambert RGB: bsdf", &peer_lambert, &inputs64);
    pairs.extend(lobe_l.into_iter().zip(peer_l));

    // Criterion's own figures, one group per work.
    let mut c = Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .configure_from_args();
    for (a, b) in &mut pairs {
        let work = a.name.replace(": lobe", "");
        let mut g = c.benchmark_group(work);
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("lobe", |bench| bench.iter(&mut a.pass));
        g.bench_function("bsdf 0.1.1", |bench| bench.iter(&mut b.pass));
        g.finish();
    }

    // Interleaved rounds: every kernel once per round, in the same order.
    let mut kernels: Vec<Kernel> = pairs.into_iter().flat_map(|(a, b)| [a, b]).collect();
    let times = rounds(&mut kernels, 15, Duration::from_millis(40));
    println!(
        "\nInterleaved, 15 rounds, ns per evaluation: median [min, max]; ratio = median of per-round lobe/bsdf"
    );
    println!("| work | lobe | bsdf 0.1.1 | ratio |");
    println!("| --- | --- | --- | --- |");
    for pair in kernels.chunks(2).zip(times.chunks(2)) {
        let (ks, ts) = pair;
        let (la, lmin, lmax) = spread(&ts[0]);
        let (pa, pmin, pmax) = spread(&ts[1]);
        let (r, rmin, rmax) = ratio(&ts[0], &ts[1]);
        println!(
            "| {} | {la:.1} [{lmin:.1}, {lmax:.1}] | {pa:.1} [{pmin:.1}, {pmax:.1}] | {r:.2}× [{rmin:.2}, {rmax:.2}] |",
            ks[0].name.replace(": lobe", ""),
        );
    }
}
