//! Criterion benchmarks of the shading hot loop, on the fixed 4,096 inputs of
//! `benches/common/inputs.rs` (5% of the directions within 1° of the horizon):
//!
//! * `eval`, `pdf` and `sample` of 17 configurations of the models, from Lambert to the
//!   plastic (RGB where the model is generic over its spectrum; the combinators, the sheen, the
//!   diffuse transmitter and the layered models are timed by `combinators.rs`, the
//!   energy-compensated models by `compensation.rs`);
//! * for the GGX conductor and the rough dielectric, the prepared path: `eval_pdf_prepared` on
//!   states prepared ahead, the renderer's pattern of one `prepare(wo)` followed by eight
//!   `eval_pdf_prepared` (each light, each MIS pair at one shading point), and the unprepared
//!   `eval` + `pdf` it replaces;
//! * every distribution's `d`, `lambda`, `g1`, `view` (what a model prepares per `wo`) and
//!   sampler on a prepared view (`sample`, `sample_reflected` — the reflected direction a
//!   reflection model draws — and `sample_reflection` for GGX's bounded sampler);
//! * the four Fresnel functions.
//!
//! ```sh
//! cargo bench --bench shading
//! ```
//!
//! Every benchmark is one pass over the 4,096 inputs, reported with
//! `Throughput::Elements(4096)`: the time per call is criterion's time divided by 4,096. The
//! inputs are read from memory as a renderer's would be and each result goes through
//! `black_box`; the model goes through `black_box` once, so that its parameters are not
//! folded into the loop (the inputs are not: a `black_box` per input forces a store and a
//! reload, and the figure would then measure store-forwarding stalls rather than the code).
//! The transmissive models run on the same inputs with the sides mixed (`wi` below the
//! surface for odd `k`, `wo` below for `k mod 4 ≥ 2`), so that refraction and the inside are
//! timed too. Measurement windows are short (0.3 s warm-up, 1 s of 20 samples), so that the
//! 86 benchmarks take about two minutes.

#[path = "common/inputs.rs"]
mod inputs;
#[path = "common/passes.rs"]
mod passes;

use criterion::{Criterion, criterion_group, criterion_main};
use inputs::{Inputs, N, inputs, two_sided};
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, Mirror, OrenNayar, Phong, Plastic, Prepare, RoughDielectric, SmoothDielectric,
    ThinDielectric,
};
use lobe::fresnel::{self, Conductor};
use lobe::microfacet::{Beckmann, BlinnPhongNdf, Ggx, Gtr, Masking, NormalDistribution};
use lobe::{Alpha, Eta, Roughness, Vec3};
use passes::{group, model};
use std::hint::black_box;

/// Evaluations per prepared state in the renderer's pattern.
const PER_POINT: usize = 8;

/// The prepared path of `model`: `eval_pdf_prepared` on states prepared ahead; one `prepare`
/// and [`PER_POINT`] `eval_pdf_prepared` per shading point (per evaluation, the prepare's
/// cost shared by eight); and the unprepared `eval` + `pdf` for the same pairs.
fn prepared<M: Prepare>(c: &mut Criterion, name: &str, model: &M, i: &Inputs) {
    let m = black_box(model);
    let states: Vec<M::Prepared> = i.wo.iter().map(|&wo| m.prepare(wo)).collect();
    let mut g = group(c, name);
    g.bench_function("eval_pdf_prepared", |b| {
        b.iter(|| {
            for (at, &wi) in states.iter().zip(&i.wi) {
                black_box(m.eval_pdf_prepared(at, wi));
            }
        })
    });
    g.bench_function("prepare + 8 eval_pdf_prepared", |b| {
        b.iter(|| {
            for point in 0..N / PER_POINT {
                let first = point * PER_POINT;
                let at = m.prepare(i.wo[first]);
                for k in first..first + PER_POINT {
                    black_box(m.eval_pdf_prepared(&at, i.wi[k]));
                }
            }
        })
    });
    g.bench_function("eval + pdf", |b| {
        b.iter(|| {
            for k in 0..N {
                black_box(m.eval(i.wo[k], i.wi[k]));
                black_box(m.pdf(i.wo[k], i.wi[k]));
            }
        })
    });
    g.finish();
}

/// A distribution's `d` (at the inputs' half vectors), `lambda`, `g1` and `view` (at `wo`),
/// and its sampler on views prepared ahead.
fn distribution<D: NormalDistribution>(
    c: &mut Criterion,
    name: &str,
    d: &D,
    i: &Inputs,
) -> Vec<lobe::microfacet::View> {
    let d = black_box(d);
    let h: Vec<Vec3> = (0..N).map(|k| (i.wo[k] + i.wi[k]).normalize()).collect();
    let views: Vec<_> = i.wo.iter().map(|&wo| d.view(wo)).collect();
    let mut g = group(c, name);
    g.bench_function("d", |b| {
        b.iter(|| {
            for m in &h {
                black_box(d.d(*m));
            }
        })
    });
    g.bench_function("lambda", |b| {
        b.iter(|| {
            for w in &i.wo {
                black_box(d.lambda(*w));
            }
        })
    });
    g.bench_function("g1", |b| {
        b.iter(|| {
            for w in &i.wo {
                black_box(d.g1(*w));
            }
        })
    });
    g.bench_function("view", |b| {
        b.iter(|| {
            for w in &i.wo {
                black_box(d.view(*w));
            }
        })
    });
    g.bench_function("sample", |b| {
        b.iter(|| {
            for (view, &u) in views.iter().zip(&i.u) {
                black_box(d.sample(view, u));
            }
        })
    });
    g.bench_function("sample_reflected", |b| {
        b.iter(|| {
            for (view, &u) in views.iter().zip(&i.u) {
                black_box(d.sample_reflected(view, u));
            }
        })
    });
    g.finish();
    views
}

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

fn parts(c: &mut Criterion) {
    let i = inputs();
    let a = alpha(0.3);
    let ggx = Ggx::isotropic(a);
    let views = distribution(c, "GGX α 0.3", &ggx, &i);
    {
        let d = black_box(&ggx);
        let mut g = group(c, "GGX α 0.3");
        g.bench_function("sample_reflection", |b| {
            b.iter(|| {
                for (view, &u) in views.iter().zip(&i.u) {
                    black_box(d.sample_reflection(view, u));
                }
            })
        });
        g.finish();
    }
    distribution(c, "Beckmann α 0.3", &Beckmann::isotropic(a), &i);
    distribution(c, "GTR α 0.3 γ 1.5", &Gtr::new(a, 1.5).unwrap(), &i);
    distribution(
        c,
        "BlinnPhongNdf α 0.3",
        &BlinnPhongNdf::new(a).unwrap(),
        &i,
    );

    // Fresnel at the inputs' wo·h; the dielectric from both sides (odd k inside).
    let cos_d: Vec<f32> = (0..N)
        .map(|k| i.wo[k].dot((i.wo[k] + i.wi[k]).normalize()))
        .collect();
    let cos_signed: Vec<f32> = (0..N)
        .map(|k| if k % 2 == 1 { -cos_d[k] } else { cos_d[k] })
        .collect();
    let f0 = black_box(Vec3::new(1.0, 0.78, 0.34));
    let glass = black_box(Eta::new(1.5).unwrap());
    let gold = lobe::metals::GOLD.rgb();
    let gold = black_box(&gold);
    let mut g = group(c, "Fresnel");
    g.bench_function("schlick RGB", |b| {
        b.iter(|| {
            for &x in &cos_d {
                black_box(fresnel::schlick(f0, x));
            }
        })
    });
    g.bench_function("dielectric", |b| {
        b.iter(|| {
            for &x in &cos_signed {
                black_box(fresnel::dielectric(x, glass));
            }
        })
    });
    g.bench_function("conductor RGB", |b| {
        b.iter(|| {
            for &x in &cos_d {
                black_box(fresnel::conductor(x, gold));
            }
        })
    });
    g.bench_function("conductor_approx RGB", |b| {
        b.iter(|| {
            for &x in &cos_d {
                black_box(fresnel::conductor_approx(x, gold));
            }
        })
    });
    g.finish();
}

/// The microfacet conductor with distribution `d`: gold's complex index (RGB), height-correlated
/// masking.
fn conductor<D: NormalDistribution>(d: D) -> Microfacet<D, Conductor<Vec3>> {
    let gold = Conductor {
        ior: lobe::metals::GOLD.rgb(),
    };
    Microfacet::new(d, Masking::HeightCorrelated, gold)
}

fn models(c: &mut Criterion) {
    let i = inputs();
    let both = two_sided(&i);
    let a = alpha(0.3);
    let glass = Eta::new(1.5).unwrap();
    let rho = Vec3::new(0.8, 0.6, 0.4);
    let (kd, ks) = (Vec3::new(0.3, 0.2, 0.1), Vec3::new(0.6, 0.6, 0.6));
    let gold = Conductor {
        ior: lobe::metals::GOLD.rgb(),
    };

    model(c, "Lambert RGB", &Lambert::new(rho).unwrap(), &i);
    model(
        c,
        "OrenNayar RGB σ 0.5",
        &OrenNayar::new(rho, 0.5).unwrap(),
        &i,
    );
    let eon = EnergyPreservingOrenNayar::new(rho, 0.5).unwrap();
    model(c, "EON RGB r 0.5", &eon, &i);
    let disney = DisneyDiffuse::new(rho, Roughness::new(0.5).unwrap()).unwrap();
    model(c, "DisneyDiffuse RGB r 0.5", &disney, &i);
    model(c, "Phong RGB p 20", &Phong::new(kd, ks, 20.0).unwrap(), &i);
    for (name, form) in [
        ("BlinnPhong modified RGB p 32", BlinnPhongForm::Modified),
        ("BlinnPhong normalized RGB p 32", BlinnPhongForm::Normalized),
    ] {
        model(c, name, &BlinnPhong::new(kd, ks, 32.0, form).unwrap(), &i);
    }
    let ggx = conductor(Ggx::isotropic(a));
    model(c, "GGX gold RGB α 0.3", &ggx, &i);
    prepared(c, "GGX gold RGB α 0.3", &ggx, &i);
    model(
        c,
        "Beckmann gold RGB α 0.3",
        &conductor(Beckmann::isotropic(a)),
        &i,
    );
    model(
        c,
        "GTR γ 1.5 gold RGB α 0.3",
        &conductor(Gtr::new(a, 1.5).unwrap()),
        &i,
    );
    let blinn = conductor(BlinnPhongNdf::new(a).unwrap());
    model(c, "BlinnPhongNdf gold RGB α 0.3", &blinn, &i);
    let rough = RoughDielectric::new(Ggx::isotropic(a), glass);
    model(c, "RoughDielectric GGX α 0.3 η 1.5", &rough, &both);
    prepared(c, "RoughDielectric GGX α 0.3 η 1.5", &rough, &both);
    model(c, "Mirror gold RGB", &Mirror::new(gold), &i);
    model(
        c,
        "SmoothDielectric η 1.5",
        &SmoothDielectric::new(glass),
        &both,
    );
    model(
        c,
        "ThinDielectric η 1.5",
        &ThinDielectric::new(glass),
        &both,
    );
    model(c, "Glazed RGB η 1.5", &Glazed::new(rho, glass).unwrap(), &i);
    let plastic = Plastic::new(rho, Ggx::isotropic(a), glass).unwrap();
    model(c, "Plastic GGX RGB α 0.3 η 1.5", &plastic, &i);
}

criterion_group! {
    name = benches;
    config = passes::config();
    targets = parts, models
}
criterion_main!(benches);
