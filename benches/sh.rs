//! Criterion benchmarks of the spherical-harmonic hot paths: evaluating the basis, the
//! irradiance `E(n)` from 9 RGB coefficients, and rotating coefficients. Each iteration
//! runs over 1024 pre-generated inputs, so a figure divided by 1024 is the time per call.
//!
//! ```sh
//! cargo bench --bench sh
//! ```

use criterion::{Criterion, criterion_group, criterion_main};
use glam::{Mat3, Quat};
use lobe::sh::{IrradianceQuadratic, Sh, ShRotation, basis, basis_recurrence};
use lobe::verify::Pcg32;
use lobe::{Vec3, sampling::uniform_sphere};
use std::hint::black_box;

const N: usize = 1024;

/// Seeded unit directions.
fn directions() -> Vec<Vec3> {
    let mut rng = Pcg32::new(7, 0);
    (0..N).map(|_| uniform_sphere(rng.next_vec2())).collect()
}

/// Seeded rotations (Shoemake's uniform quaternions).
fn rotations() -> Vec<Mat3> {
    let mut rng = Pcg32::new(8, 0);
    (0..N)
        .map(|_| {
            let (u1, u2, u3) = (rng.next_f32(), rng.next_f32(), rng.next_f32());
            let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
            let (t2, t3) = (std::f32::consts::TAU * u2, std::f32::consts::TAU * u3);
            Mat3::from_quat(
                Quat::from_xyzw(a * t2.sin(), a * t2.cos(), b * t3.sin(), b * t3.cos()).normalize(),
            )
        })
        .collect()
}

/// Seeded RGB coefficients.
fn coefficients<const C: usize>() -> Sh<C, Vec3> {
    let mut rng = Pcg32::new(9, 0);
    Sh::new(std::array::from_fn(|_| {
        Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5
    }))
}

fn basis_benches(c: &mut Criterion) {
    let dirs = directions();
    c.bench_function("basis/order 3 (closed form)", |b| {
        b.iter(|| {
            for w in &dirs {
                black_box(basis::<9>(black_box(*w)));
            }
        })
    });
    c.bench_function("basis/order 3 (recurrence)", |b| {
        b.iter(|| {
            for w in &dirs {
                let mut y = [0.0_f32; 9];
                basis_recurrence(black_box(*w), &mut y);
                black_box(y);
            }
        })
    });
    c.bench_function("basis/order 4 (closed form)", |b| {
        b.iter(|| {
            for w in &dirs {
                black_box(basis::<16>(black_box(*w)));
            }
        })
    });
    c.bench_function("basis/order 9 (recurrence)", |b| {
        b.iter(|| {
            for w in &dirs {
                black_box(basis::<81>(black_box(*w)));
            }
        })
    });
}

fn irradiance_benches(c: &mut Criterion) {
    let dirs = directions();
    let l = coefficients::<9>();
    let quad = IrradianceQuadratic::new(&l);
    c.bench_function("irradiance RGB/quadratic form (9 coefficients)", |b| {
        b.iter(|| {
            for n in &dirs {
                black_box(black_box(&quad).eval(black_box(*n)));
            }
        })
    });
    c.bench_function("irradiance RGB/general path (order 3)", |b| {
        b.iter(|| {
            for n in &dirs {
                black_box(black_box(&l).irradiance(black_box(*n)));
            }
        })
    });
    c.bench_function("irradiance RGB/quadratic form setup", |b| {
        b.iter(|| {
            for _ in 0..N {
                black_box(IrradianceQuadratic::new(black_box(&l)));
            }
        })
    });
}

fn rotation_benches(c: &mut Criterion) {
    let rots = rotations();
    let sh3 = coefficients::<9>();
    let sh4 = coefficients::<16>();
    let mono3 = sh3.channel(0);
    c.bench_function("rotate order 3 RGB/closed form (Sh::rotated)", |b| {
        b.iter(|| {
            for r in &rots {
                black_box(black_box(&sh3).rotated(black_box(*r)));
            }
        })
    });
    c.bench_function(
        "rotate order 3 RGB/Ivanic-Ruedenberg (build + apply)",
        |b| {
            b.iter(|| {
                for r in &rots {
                    let rot = ShRotation::<9>::ivanic_ruedenberg(black_box(*r));
                    black_box(rot.apply(black_box(&sh3)));
                }
            })
        },
    );
    c.bench_function(
        "rotate order 3 RGB/closed-form matrices (build + apply)",
        |b| {
            b.iter(|| {
                for r in &rots {
                    let rot = ShRotation::<9>::new(black_box(*r));
                    black_box(rot.apply(black_box(&sh3)));
                }
            })
        },
    );
    let built: Vec<ShRotation<9>> = rots.iter().map(|r| ShRotation::new(*r)).collect();
    c.bench_function("rotate order 3 RGB/apply a built rotation", |b| {
        b.iter(|| {
            for rot in &built {
                black_box(black_box(rot).apply(black_box(&sh3)));
            }
        })
    });
    c.bench_function("rotate order 3 mono/closed form (Sh::rotated)", |b| {
        b.iter(|| {
            for r in &rots {
                black_box(black_box(&mono3).rotated(black_box(*r)));
            }
        })
    });
    c.bench_function(
        "rotate order 3 mono/Ivanic-Ruedenberg (build + apply)",
        |b| {
            b.iter(|| {
                for r in &rots {
                    let rot = ShRotation::<9>::ivanic_ruedenberg(black_box(*r));
                    black_box(rot.apply(black_box(&mono3)));
                }
            })
        },
    );
    c.bench_function("rotate order 4 RGB/Sh::rotated", |b| {
        b.iter(|| {
            for r in &rots {
                black_box(black_box(&sh4).rotated(black_box(*r)));
            }
        })
    });
}

criterion_group!(benches, basis_benches, irradiance_benches, rotation_benches);
criterion_main!(benches);
