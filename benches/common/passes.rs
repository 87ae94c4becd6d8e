//! The benchmark passes shared by the criterion benches (`shading.rs`, `combinators.rs`,
//! `conductor.rs`, `materials.rs`): a group reported per input, and one pass of `eval`, `pdf` and
//! `sample` over the inputs.

use super::inputs::{Inputs, N};
use criterion::{BenchmarkGroup, Criterion, Throughput};
use lobe::bxdf::Bxdf;
use std::hint::black_box;
use std::time::Duration;

/// The criterion configuration of these benches: short windows (0.3 s warm-up, 1 s of 20
/// samples), so that a full run takes minutes on the project's 2-core machine.
pub fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1000))
        .sample_size(20)
        .nresamples(10_000)
}

/// A group of benchmarks over the `N` inputs, each reported per element.
pub fn group<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(N as u64));
    g
}

/// `eval`, `pdf` and `sample` of `model` over the inputs.
pub fn model<M: Bxdf>(c: &mut Criterion, name: &str, model: &M, i: &Inputs) {
    let m = black_box(model);
    let mut g = group(c, name);
    g.bench_function("eval", |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(m.eval(i.wo[k], i.wi[k]));
            }
        })
    });
    g.bench_function("pdf", |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(m.pdf(i.wo[k], i.wi[k]));
            }
        })
    });
    g.bench_function("sample", |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(m.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        })
    });
    g.finish();
}
