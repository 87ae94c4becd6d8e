//! The exact conductor Fresnel term with an RGB spectrum's channels side by side in one SIMD
//! register (`fresnel::conductor`, what a scalar call runs) against the same arithmetic one
//! channel at a time (`Fresnel::eval_per_channel`, what the batched microfacet loops run and
//! what every call ran before), alone and inside the GGX and Beckmann gold conductors, on the
//! 4,096 inputs of `benches/common/inputs.rs`.
//!
//! ```sh
//! cargo bench --bench conductor
//! ```
//!
//! The per-channel baseline is a [`Fresnel`] term of this file whose `eval` is `eval_per_channel`:
//! the models built with it return the same numbers, bit for bit (checked here before timing).
//! Criterion times the bare term's pair in the order A B A B and each model's pair once, A then B;
//! then the interleaved rounds of `common/interleave.rs` time every kernel in alternation (31
//! rounds) and print each one's median with its range and the median of the per-round ratios.

// Its `two_sided` is for the transmissive models of the other benches.
#[allow(dead_code)]
#[path = "common/inputs.rs"]
mod inputs;
#[path = "common/interleave.rs"]
mod interleave;
#[path = "common/passes.rs"]
mod passes;

use criterion::{Criterion, criterion_group, criterion_main};
use inputs::{Inputs, N, inputs};
use lobe::bxdf::{Bxdf, Microfacet};
use lobe::fresnel::{Conductor, Fresnel};
use lobe::microfacet::{Beckmann, Ggx, Masking, NormalDistribution};
use lobe::{Alpha, Vec3};
use std::hint::black_box;
use std::time::Duration;

/// The conductor term evaluated one channel at a time: the baseline.
#[derive(Clone, Copy)]
struct PerChannel(Conductor<Vec3>);

impl Fresnel for PerChannel {
    type Spectrum = Vec3;

    #[inline(always)]
    fn eval(&self, cos_d: f32) -> Vec3 {
        self.0.eval_per_channel(cos_d)
    }
}

fn gold() -> Conductor<Vec3> {
    Conductor {
        ior: lobe::metals::GOLD.rgb(),
    }
}

/// The gold conductor on `d`, with the term side by side and channel by channel.
fn pair<D: NormalDistribution + Copy>(
    d: D,
) -> (Microfacet<D, Conductor<Vec3>>, Microfacet<D, PerChannel>) {
    let hc = Masking::HeightCorrelated;
    (
        Microfacet::new(d, hc, gold()),
        Microfacet::new(d, hc, PerChannel(gold())),
    )
}

/// Panics unless the two models give the same `eval` and `sample` on every input.
fn assert_same<A: Bxdf<Spectrum = Vec3>, B: Bxdf<Spectrum = Vec3>>(a: &A, b: &B, i: &Inputs) {
    for k in 0..N {
        assert_eq!(a.eval(i.wo[k], i.wi[k]), b.eval(i.wo[k], i.wi[k]));
        let (sa, sb) = (
            a.sample(i.wo[k], i.u[k], i.uc[k]),
            b.sample(i.wo[k], i.u[k], i.uc[k]),
        );
        assert_eq!(
            sa.map(|s| (s.wi, s.f, s.pdf)),
            sb.map(|s| (s.wi, s.f, s.pdf))
        );
    }
}

fn conductor(c: &mut Criterion) {
    let i = inputs();
    // The term's argument in the models, `wo·h = |wo + wi|/2`.
    let cos_d: Vec<f32> =
        i.wo.iter()
            .zip(&i.wi)
            .map(|(o, w)| (*o + *w).length() * 0.5)
            .collect();
    let (term, baseline) = (black_box(gold()), black_box(PerChannel(gold())));
    for (t, b) in cos_d.iter().map(|&x| (term.eval(x), baseline.eval(x))) {
        assert_eq!(t, b);
    }
    let a = Alpha::new(0.3).unwrap();
    let (ggx, ggx_pc) = pair(Ggx::isotropic(a));
    let (beckmann, beckmann_pc) = pair(Beckmann::isotropic(a));
    assert_same(&ggx, &ggx_pc, &i);
    assert_same(&beckmann, &beckmann_pc, &i);

    let mut g = passes::group(c, "conductor RGB");
    for name in [
        "side by side",
        "per channel",
        "side by side (again)",
        "per channel (again)",
    ] {
        g.bench_function(name, |bench| {
            bench.iter(|| {
                for &x in &cos_d {
                    if name.starts_with("side") {
                        black_box(term.eval(x));
                    } else {
                        black_box(baseline.eval(x));
                    }
                }
            })
        });
    }
    g.finish();
    passes::model(c, "GGX gold RGB α 0.3, side by side", &ggx, &i);
    passes::model(c, "GGX gold RGB α 0.3, per channel", &ggx_pc, &i);
    passes::model(c, "Beckmann gold RGB α 0.3, side by side", &beckmann, &i);
    passes::model(c, "Beckmann gold RGB α 0.3, per channel", &beckmann_pc, &i);

    // Every kernel in alternation; ratios side by side / per channel.
    let (ggx, ggx_pc) = (black_box(&ggx), black_box(&ggx_pc));
    let (beckmann, beckmann_pc) = (black_box(&beckmann), black_box(&beckmann_pc));
    let i = &i;
    let cos_d = &cos_d;
    let mut kernels = vec![
        interleave::Kernel::new("conductor RGB", N, move || {
            for &x in cos_d {
                black_box(term.eval(x));
            }
        }),
        interleave::Kernel::new("conductor RGB, per channel", N, move || {
            for &x in cos_d {
                black_box(baseline.eval(x));
            }
        }),
        interleave::Kernel::new("GGX gold eval", N, move || {
            for k in 0..N {
                black_box(ggx.eval(i.wo[k], i.wi[k]));
            }
        }),
        interleave::Kernel::new("GGX gold eval, per channel", N, move || {
            for k in 0..N {
                black_box(ggx_pc.eval(i.wo[k], i.wi[k]));
            }
        }),
        interleave::Kernel::new("GGX gold sample", N, move || {
            for k in 0..N {
                black_box(ggx.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
        interleave::Kernel::new("GGX gold sample, per channel", N, move || {
            for k in 0..N {
                black_box(ggx_pc.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
        interleave::Kernel::new("Beckmann gold eval", N, move || {
            for k in 0..N {
                black_box(beckmann.eval(i.wo[k], i.wi[k]));
            }
        }),
        interleave::Kernel::new("Beckmann gold eval, per channel", N, move || {
            for k in 0..N {
                black_box(beckmann_pc.eval(i.wo[k], i.wi[k]));
            }
        }),
        interleave::Kernel::new("Beckmann gold sample", N, move || {
            for k in 0..N {
                black_box(beckmann.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
        interleave::Kernel::new("Beckmann gold sample, per channel", N, move || {
            for k in 0..N {
                black_box(beckmann_pc.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
    ];
    let times = interleave::rounds(&mut kernels, 31, Duration::from_millis(40));
    println!("| kernel (ns per call) | side by side | per channel | ratio |");
    println!("| --- | --- | --- | --- |");
    for (k, t) in kernels.chunks(2).zip(times.chunks(2)) {
        let (a, a_min, a_max) = interleave::spread(&t[0]);
        let (b, b_min, b_max) = interleave::spread(&t[1]);
        let (r, r_min, r_max) = interleave::ratio(&t[0], &t[1]);
        println!(
            "| {} | {a:.1} [{a_min:.1}, {a_max:.1}] | {b:.1} [{b_min:.1}, {b_max:.1}] | \
             {r:.2} [{r_min:.2}, {r_max:.2}] |",
            k[0].name
        );
    }
}

criterion_group! {
    name = benches;
    config = passes::config();
    targets = conductor
}
criterion_main!(benches);
