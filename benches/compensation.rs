//! The cost of energy compensation: each compensated model against the model it
//! compensates, measured in the same run over the same 1024 pre-generated direction pairs.
//!
//! ```sh
//! cargo bench --bench compensation
//! ```
//!
//! The criterion group times every pair's `eval` twice, in the order A B A B, so that the machine's
//! drift between the first and the second half falls on both, and `pdf` and `sample` once each;
//! then the interleaved rounds of `common/interleave.rs` time the GGX conductor pair against each
//! other in alternation (A B A B …, 31 rounds) and print each one's median and the median of the
//! per-round ratios — the figure the issue's bar (compensated `eval` at most 1.3× the uncompensated
//! one) is read from.

#[path = "common/interleave.rs"]
mod interleave;

use criterion::{Criterion, criterion_group, criterion_main};
use lobe::bxdf::{Bxdf, Microfacet, Plastic, RoughDielectric};
use lobe::fresnel::{Conductor, Schlick};
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::sampling::{uniform_hemisphere, uniform_sphere};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Eta, Vec2, Vec3};
use std::hint::black_box;
use std::time::Duration;

const N: usize = 1024;

/// Fixed viewer and light directions (above the surface, or anywhere for a transmissive
/// model), and random numbers: `u` for the direction, `uc` for the choice of lobe (uniform,
/// so that the compensation lobe is sampled as often as it is in a renderer).
fn inputs(sphere: bool) -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec2>, Vec<f32>) {
    let mut rng = Pcg32::new(42, 0);
    let dir = |rng: &mut Pcg32| {
        if sphere {
            uniform_sphere(rng.next_vec2())
        } else {
            uniform_hemisphere(rng.next_vec2())
        }
    };
    let wo = (0..N).map(|_| dir(&mut rng)).collect();
    let wi = (0..N).map(|_| dir(&mut rng)).collect();
    let u = (0..N).map(|_| rng.next_vec2()).collect();
    let uc = (0..N).map(|_| rng.next_f32()).collect();
    (wo, wi, u, uc)
}

/// One pass of `eval` over the inputs.
fn eval_pass<B: Bxdf>(bxdf: &B, wo: &[Vec3], wi: &[Vec3]) {
    for k in 0..N {
        black_box(bxdf.eval(black_box(wo[k]), black_box(wi[k])));
    }
}

/// `eval` of `base` and `compensated` in the order A B A B, then `pdf` and `sample` of each once.
fn pair<A: Bxdf, B: Bxdf>(c: &mut Criterion, name: &str, base: &A, compensated: &B) {
    let (wo, wi, u, uc) = inputs(base.lobes().is_transmissive());
    for round in ["", " (again)"] {
        c.bench_function(&format!("{name}/eval{round}"), |b| {
            b.iter(|| eval_pass(base, &wo, &wi))
        });
        c.bench_function(&format!("{name} compensated/eval{round}"), |b| {
            b.iter(|| eval_pass(compensated, &wo, &wi))
        });
    }
    c.bench_function(&format!("{name}/pdf"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(base.pdf(black_box(wo[k]), black_box(wi[k])));
            }
        })
    });
    c.bench_function(&format!("{name} compensated/pdf"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(compensated.pdf(black_box(wo[k]), black_box(wi[k])));
            }
        })
    });
    c.bench_function(&format!("{name}/sample"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(base.sample(black_box(wo[k]), black_box(u[k]), black_box(uc[k])));
            }
        })
    });
    c.bench_function(&format!("{name} compensated/sample"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(compensated.sample(black_box(wo[k]), black_box(u[k]), black_box(uc[k])));
            }
        })
    });
}

fn compensation(c: &mut Criterion) {
    let a = |x| Alpha::new(x).unwrap();
    let gold = ComplexIor::new(
        Vec3::new(0.143, 0.375, 1.442),
        Vec3::new(3.983, 2.386, 1.603),
    )
    .unwrap();
    let hc = Masking::HeightCorrelated;
    let ggx_gold = Microfacet::new(Ggx::isotropic(a(0.3)), hc, Conductor { ior: gold });
    pair(
        c,
        "GGX gold RGB",
        &ggx_gold,
        &ggx_gold.with_energy_compensation().unwrap(),
    );
    let ggx_schlick = Microfacet::new(
        Ggx::isotropic(a(0.3)),
        hc,
        Schlick::new(Vec3::new(0.95, 0.64, 0.54)).unwrap(),
    );
    pair(
        c,
        "GGX Schlick RGB",
        &ggx_schlick,
        &ggx_schlick.with_energy_compensation().unwrap(),
    );
    let beckmann = Microfacet::new(Beckmann::isotropic(a(0.3)), hc, Conductor { ior: gold });
    pair(
        c,
        "Beckmann gold RGB",
        &beckmann,
        &beckmann.with_energy_compensation().unwrap(),
    );
    let glass = RoughDielectric::new(Ggx::isotropic(a(0.3)), Eta::new(1.5).unwrap());
    pair(
        c,
        "Rough glass GGX",
        &glass,
        &glass.with_energy_compensation().unwrap(),
    );
    let blue = Vec3::new(0.12, 0.25, 0.55);
    let eta = Eta::new(1.5).unwrap();
    pair(
        c,
        "Plastic GGX RGB",
        &Plastic::new(blue, Ggx::isotropic(a(0.3)), eta).unwrap(),
        &Plastic::compensated(blue, Ggx::isotropic(a(0.3)), eta).unwrap(),
    );

    // The bar's pair, in alternation.
    let compensated = ggx_gold.with_energy_compensation().unwrap();
    let (wo, wi, _, _) = inputs(false);
    let mut kernels = vec![
        interleave::Kernel::new("GGX gold RGB/eval", N, || eval_pass(&ggx_gold, &wo, &wi)),
        interleave::Kernel::new("GGX gold RGB compensated/eval", N, || {
            eval_pass(&compensated, &wo, &wi)
        }),
    ];
    let times = interleave::rounds(&mut kernels, 31, Duration::from_millis(60));
    for (k, t) in kernels.iter().zip(&times) {
        let (median, min, max) = interleave::spread(t);
        println!(
            "interleaved {}: median {median:.2} ns per call (min {min:.2}, max {max:.2})",
            k.name
        );
    }
    let (ratio, min, max) = interleave::ratio(&times[1], &times[0]);
    println!(
        "interleaved ratio compensated / uncompensated eval: median {ratio:.3} (min {min:.3}, max {max:.3}) over 31 rounds"
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    targets = compensation
}
criterion_main!(benches);
