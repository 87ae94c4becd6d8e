//! Timing kernels against each other in interleaved rounds (A B A B …), so that the
//! machine's drift (this VM varies by ±30% between runs) falls on all of them alike; the
//! summary gives each kernel's median time per element with its spread, and each ratio as
//! the median of the per-round ratios.

use std::hint::black_box;
use std::time::{Duration, Instant};

/// A kernel: one pass over `elements` inputs.
pub struct Kernel<'a> {
    /// What the summary calls it.
    pub name: String,
    /// One pass.
    pub pass: Box<dyn FnMut() + 'a>,
    /// Elements per pass.
    pub elements: usize,
}

impl<'a> Kernel<'a> {
    /// A kernel named `name` running `pass` over `elements` inputs.
    pub fn new(name: impl Into<String>, elements: usize, pass: impl FnMut() + 'a) -> Self {
        Self {
            name: name.into(),
            pass: Box::new(pass),
            elements,
        }
    }
}

/// Nanoseconds per element of every kernel in every round: `times[kernel][round]`.
pub fn rounds(kernels: &mut [Kernel<'_>], rounds: usize, per_round: Duration) -> Vec<Vec<f64>> {
    // Calibrate: passes per measurement so that each takes about `per_round`.
    let passes: Vec<u32> = kernels
        .iter_mut()
        .map(|k| {
            (k.pass)();
            let t = Instant::now();
            let mut n = 0u32;
            while t.elapsed() < per_round / 4 {
                (k.pass)();
                n += 1;
            }
            (n * 4).max(1)
        })
        .collect();
    let mut times = vec![Vec::with_capacity(rounds); kernels.len()];
    for _ in 0..rounds {
        for (i, k) in kernels.iter_mut().enumerate() {
            let t = Instant::now();
            for _ in 0..passes[i] {
                (k.pass)();
            }
            let ns = t.elapsed().as_nanos() as f64;
            times[i].push(black_box(ns / (f64::from(passes[i]) * k.elements as f64)));
        }
    }
    times
}

/// The median of `xs`.
pub fn median(xs: &[f64]) -> f64 {
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// `(median, min, max)` of `xs`.
pub fn spread(xs: &[f64]) -> (f64, f64, f64) {
    let min = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let max = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (median(xs), min, max)
}

/// The median over rounds of `a[round] / b[round]`, with its min and max.
pub fn ratio(a: &[f64], b: &[f64]) -> (f64, f64, f64) {
    let r: Vec<f64> = a.iter().zip(b).map(|(x, y)| x / y).collect();
    spread(&r)
}
