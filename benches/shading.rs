//! Criterion benchmarks of the shading hot loop: the microfacet parts (D, G, Fresnel) and
//! `eval`, `sample` and `pdf` of the models, each over a fixed set of 1024 pre-generated
//! direction pairs (so the figure is per call, averaged over a spread of configurations).
//!
//! ```sh
//! cargo bench --bench shading
//! ```

use criterion::{Criterion, criterion_group, criterion_main};
use lobe::bxdf::{
    Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Lambert, Microfacet, OrenNayar, Phong,
    RoughDielectric,
};
use lobe::fresnel::{self, Conductor};
use lobe::microfacet::{Beckmann, Ggx, Masking, NormalDistribution};
use lobe::sampling::uniform_hemisphere;
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Eta, Roughness, Vec2, Vec3};
use std::hint::black_box;

const N: usize = 1024;

/// Fixed viewer and light directions above the surface, and random numbers.
fn inputs() -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec2>) {
    let mut rng = Pcg32::new(42, 0);
    let wo = (0..N)
        .map(|_| uniform_hemisphere(rng.next_vec2()))
        .collect();
    let wi = (0..N)
        .map(|_| uniform_hemisphere(rng.next_vec2()))
        .collect();
    let u = (0..N).map(|_| rng.next_vec2()).collect();
    (wo, wi, u)
}

fn bench_model<B: Bxdf<Spectrum = S>, S>(c: &mut Criterion, name: &str, bxdf: &B) {
    let (wo, wi, u) = inputs();
    c.bench_function(&format!("{name}/eval"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(bxdf.eval(black_box(wo[k]), black_box(wi[k])));
            }
        })
    });
    c.bench_function(&format!("{name}/pdf"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(bxdf.pdf(black_box(wo[k]), black_box(wi[k])));
            }
        })
    });
    c.bench_function(&format!("{name}/sample"), |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(bxdf.sample(black_box(wo[k]), black_box(u[k]), 0.5));
            }
        })
    });
}

fn parts(c: &mut Criterion) {
    let (wo, wi, _) = inputs();
    let ggx = Ggx::isotropic(Alpha::new(0.3).unwrap());
    let beckmann = Beckmann::isotropic(Alpha::new(0.3).unwrap());
    let gold = ComplexIor::new(
        Vec3::new(0.143, 0.375, 1.442),
        Vec3::new(3.983, 2.386, 1.603),
    )
    .unwrap();
    let glass = Eta::new(1.5).unwrap();
    let h: Vec<Vec3> = wo
        .iter()
        .zip(&wi)
        .map(|(a, b)| (*a + *b).normalize())
        .collect();
    c.bench_function("GGX/D", |b| {
        b.iter(|| h.iter().map(|m| ggx.d(black_box(*m))).sum::<f32>())
    });
    c.bench_function("GGX/G2", |b| {
        b.iter(|| (0..N).map(|k| ggx.g2(black_box(wo[k]), wi[k])).sum::<f32>())
    });
    c.bench_function("Beckmann/D", |b| {
        b.iter(|| h.iter().map(|m| beckmann.d(black_box(*m))).sum::<f32>())
    });
    c.bench_function("Beckmann/G2", |b| {
        b.iter(|| {
            (0..N)
                .map(|k| beckmann.g2(black_box(wo[k]), wi[k]))
                .sum::<f32>()
        })
    });
    c.bench_function("Fresnel/schlick", |b| {
        b.iter(|| {
            wo.iter()
                .map(|w| fresnel::schlick(0.04f32, black_box(w.z)))
                .sum::<f32>()
        })
    });
    c.bench_function("Fresnel/dielectric", |b| {
        b.iter(|| {
            wo.iter()
                .map(|w| fresnel::dielectric(black_box(w.z), glass))
                .sum::<f32>()
        })
    });
    c.bench_function("Fresnel/conductor RGB", |b| {
        b.iter(|| {
            wo.iter()
                .map(|w| fresnel::conductor(black_box(w.z), &gold))
                .sum::<Vec3>()
        })
    });
}

fn models(c: &mut Criterion) {
    let a = |x| Alpha::new(x).unwrap();
    let gold = ComplexIor::new(
        Vec3::new(0.143, 0.375, 1.442),
        Vec3::new(3.983, 2.386, 1.603),
    )
    .unwrap();
    bench_model(c, "Lambert RGB", &Lambert::new(Vec3::splat(0.8)).unwrap());
    bench_model(
        c,
        "Oren-Nayar RGB",
        &OrenNayar::new(Vec3::splat(0.8), 0.5).unwrap(),
    );
    bench_model(
        c,
        "EON RGB",
        &EnergyPreservingOrenNayar::new(Vec3::splat(0.8), 0.5).unwrap(),
    );
    bench_model(
        c,
        "Disney diffuse RGB",
        &DisneyDiffuse::new(Vec3::splat(0.8), Roughness::new(0.5).unwrap()).unwrap(),
    );
    bench_model(
        c,
        "Phong RGB",
        &Phong::new(Vec3::splat(0.3), Vec3::splat(0.7), 20.0).unwrap(),
    );
    bench_model(
        c,
        "GGX gold RGB",
        &Microfacet::new(
            Ggx::isotropic(a(0.3)),
            Masking::HeightCorrelated,
            Conductor { ior: gold },
        ),
    );
    bench_model(
        c,
        "Beckmann gold RGB",
        &Microfacet::new(
            Beckmann::isotropic(a(0.3)),
            Masking::HeightCorrelated,
            Conductor { ior: gold },
        ),
    );
    bench_model(
        c,
        "Rough glass GGX",
        &RoughDielectric::new(Ggx::isotropic(a(0.3)), Eta::new(1.5).unwrap()),
    );
}

criterion_group!(benches, parts, models);
criterion_main!(benches);
