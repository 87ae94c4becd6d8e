//! Criterion benchmarks of the combinators and the stochastic layered models (issue 12), on
//! the fixed 4,096 inputs of `benches/common/inputs.rs`:
//!
//! * `eval`, `pdf` and `sample` of `Mix` (Lambert and a GGX conductor), `TwoSided` (the GGX
//!   conductor, viewed from below for half the inputs), `DiffuseTransmission` (sides mixed),
//!   and the Charlie `Sheen`, all RGB, with the parts alone for comparison;
//! * `eval`, `pdf` and `sample` of `CoatedDiffuse` (GGX `α = 0.3`, `η = 1.5`) and
//!   `CoatedConductor` (coat GGX `α = 0.1`, gold GGX `α = 0.3`) at the default sample count
//!   (one walk per `eval` and `pdf`), and `CoatedDiffuse` with four walks, and with a
//!   scattering layer; a smooth coat over `Mix(Mirror, Lambert)` and over a mirror under a
//!   scattering layer (the walks' delta chains); the construction of a `Sheen` (its albedo
//!   table; with the exact Smith masking, its projected-area table too).
//!
//! ```sh
//! cargo bench --bench combinators
//! ```
//!
//! As in `benches/shading.rs`: one pass over the 4,096 inputs per iteration, reported with
//! `Throughput::Elements(4096)` (time per call = criterion's time / 4,096), results through
//! `black_box`, short measurement windows.

#[path = "common/inputs.rs"]
mod inputs;
#[path = "common/passes.rs"]
mod passes;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use inputs::{inputs, mirrored, two_sided};
use lobe::bxdf::{
    CoatedConductor, CoatedDiffuse, DiffuseTransmission, Lambert, Layered, Microfacet, Mirror, Mix,
    Sheen, SmoothDielectric, TwoSided,
};
use lobe::fresnel::{Conductor, NoFresnel};
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, Eta, Vec3, metals};
use passes::{group, model};
use std::hint::black_box;

fn ggx(a: f32) -> Ggx {
    Ggx::isotropic(Alpha::new(a).unwrap())
}

fn combinators(c: &mut Criterion) {
    let i = inputs();
    let rho = Vec3::new(0.8, 0.5, 0.2);
    let gold = Microfacet::new(
        ggx(0.3),
        Masking::HeightCorrelated,
        Conductor {
            ior: metals::GOLD.rgb(),
        },
    );
    let lambert = Lambert::new(rho).unwrap();
    model(c, "Lambert RGB (part)", &lambert, &i);
    model(c, "GGX gold RGB α 0.3 (part)", &gold, &i);
    model(
        c,
        "Mix(Lambert, GGX gold) RGB w 0.5",
        &Mix::new(lambert, gold, 0.5).unwrap(),
        &i,
    );
    model(
        c,
        "TwoSided(GGX gold) RGB, half from below",
        &TwoSided::new(gold),
        &mirrored(&i),
    );
    model(
        c,
        "DiffuseTransmission RGB",
        &DiffuseTransmission::new(rho * 0.5, rho * 0.4).unwrap(),
        &two_sided(&i),
    );
    model(c, "Sheen RGB r 0.5", &Sheen::new(rho, 0.5).unwrap(), &i);
    model(
        c,
        "Sheen RGB r 0.5, exact Smith",
        &Sheen::new_exact_smith(rho, 0.5).unwrap(),
        &i,
    );
    let mut g = group(c, "Sheen construction");
    g.throughput(Throughput::Elements(1));
    g.bench_function("Sheen::new", |b| {
        b.iter(|| black_box(Sheen::new(black_box(rho), 0.5).unwrap()))
    });
    g.bench_function("Sheen::with_exact_smith", |b| {
        b.iter(|| black_box(Sheen::new(black_box(rho), 0.5).unwrap().with_exact_smith()))
    });
    g.bench_function("Sheen::new_exact_smith", |b| {
        b.iter(|| black_box(Sheen::new_exact_smith(black_box(rho), 0.5).unwrap()))
    });
    g.finish();
}

fn layered(c: &mut Criterion) {
    let i = inputs();
    let rho = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    let coated = CoatedDiffuse::coated_diffuse(rho, ggx(0.3), glass).unwrap();
    model(c, "CoatedDiffuse RGB α 0.3 η 1.5 (1 walk)", &coated, &i);
    model(
        c,
        "CoatedDiffuse RGB α 0.3 η 1.5 (4 walks)",
        &coated.with_samples(4).unwrap(),
        &i,
    );
    model(
        c,
        "CoatedDiffuse RGB, scattering layer (0.5 mfp, albedo 0.8, g 0.3)",
        &coated
            .with_thickness(0.5)
            .unwrap()
            .with_medium(Vec3::splat(0.8), 0.3)
            .unwrap(),
        &i,
    );
    // A smooth coat over a base with a delta lobe: the walks connect through delta chains.
    let mirror = || Mirror::new(NoFresnel::<Vec3>::new());
    let half_mirror = Mix::new(mirror(), Lambert::new(Vec3::splat(0.8)).unwrap(), 0.5).unwrap();
    model(
        c,
        "Layered RGB smooth coat η 1.5 over Mix(Mirror, Lambert 0.8)",
        &Layered::new(SmoothDielectric::new(glass), half_mirror),
        &i,
    );
    model(
        c,
        "Layered RGB smooth coat η 1.5, scattering layer (0.5 mfp, albedo 0.9), mirror",
        &Layered::new(SmoothDielectric::new(glass), mirror())
            .with_thickness(0.5)
            .unwrap()
            .with_medium(Vec3::splat(0.9), 0.0)
            .unwrap(),
        &i,
    );
    let conductor =
        CoatedConductor::coated_conductor(ggx(0.1), glass, ggx(0.3), metals::GOLD.rgb()).unwrap();
    model(
        c,
        "CoatedConductor RGB coat α 0.1, gold α 0.3 (1 walk)",
        &conductor,
        &i,
    );
}

criterion_group! {
    name = benches;
    config = passes::config();
    targets = combinators, layered
}
criterion_main!(benches);
