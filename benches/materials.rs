//! Criterion benchmarks of the shading hot loop as a renderer runs it: the material changes
//! from one call to the next. Each model runs over the fixed 4,096 inputs of
//! `benches/common/inputs.rs` three times:
//!
//! * `one: eval` (and `pdf`, `sample`): one material for the whole pass, as in
//!   `benches/shading.rs`; what depends only on the model's parameters may be computed once,
//!   outside the loop, by the compiler;
//! * `one, indexed: eval`: sixteen copies of that material, call `k` shading with copy
//!   `index[k]` (a fixed pseudo-random index in `0..16`): the same numbers, but the compiler
//!   cannot know that the copies are equal, so what depends only on the parameters is paid
//!   per call, as in a renderer;
//! * `16: eval`: sixteen materials of the same model with different parameters, call `k`
//!   shading with material `index[k]`: what a renderer's pass over mixed materials costs.
//!
//! ```sh
//! cargo bench --bench materials
//! ```
//!
//! The first two rows of a model differ by the per-call work on its parameters and by reading
//! the material through the index; the last two by the other materials' own costs (a
//! narrower lobe, a larger exponent, branches that differ from call to call). The one
//! material is the eighth of the sixteen, near the middle of each range (`t = 7/15`). Every
//! figure is per call, like the shading benchmarks' (criterion's time divided by 4,096).

#[path = "common/inputs.rs"]
mod inputs;
// Its `model` pass is the shading benchmarks': the rows here are `Sets::rows`.
#[allow(dead_code)]
#[path = "common/passes.rs"]
mod passes;

use criterion::{Criterion, criterion_group, criterion_main};
use inputs::{Inputs, N, inputs, two_sided};
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, Mirror, OrenNayar, Phong, Plastic, RoughDielectric, Sheen, SmoothDielectric,
    ThinDielectric,
};
use lobe::fresnel::Conductor;
use lobe::microfacet::{Beckmann, BlinnPhongNdf, Ggx, Gtr, Masking, NormalDistribution};
use lobe::verify::Pcg32;
use lobe::{Alpha, Eta, Roughness, Vec3};
use passes::group;
use std::hint::black_box;

/// How many materials the renderer's pass cycles through.
const MATERIALS: usize = 16;

/// The material of each call: a fixed pseudo-random index in `0..MATERIALS`.
fn material_indices() -> Vec<usize> {
    let mut rng = Pcg32::new(0x3a7e, 5);
    (0..N)
        .map(|_| (rng.next_u32() as usize) % MATERIALS)
        .collect()
}

/// `t = j / 15` for material `j`: where it lies in each parameter's range.
fn t(j: usize) -> f32 {
    j as f32 / (MATERIALS - 1) as f32
}

/// A reflectance that changes with `j`.
fn rho(j: usize) -> Vec3 {
    Vec3::new(0.8, 0.6, 0.4) * (0.5 + 0.5 * t(j))
}

/// The material timed alone: the middle of each parameter's range.
const ONE: usize = 7;

/// The sixteen materials `make(0..16)` of one model, timed as the file's docs say.
fn materials<M: Bxdf + Clone>(
    c: &mut Criterion,
    name: &str,
    make: impl Fn(usize) -> M,
    i: &Inputs,
) {
    let table: Vec<M> = (0..MATERIALS).map(make).collect();
    let copies: Vec<M> = vec![table[ONE].clone(); MATERIALS];
    let index = material_indices();
    let mut g = group(c, name);
    let sets = Sets {
        one: black_box(&table[ONE]),
        copies: black_box(&copies),
        table: black_box(&table),
        index: black_box(&index),
    };
    sets.rows(&mut g, "eval", |m, k| {
        black_box(m.eval(i.wo[k], i.wi[k]));
    });
    sets.rows(&mut g, "pdf", |m, k| {
        black_box(m.pdf(i.wo[k], i.wi[k]));
    });
    sets.rows(&mut g, "sample", |m, k| {
        black_box(m.sample(i.wo[k], i.u[k], i.uc[k]));
    });
    g.finish();
}

/// The three ways one model is timed.
struct Sets<'a, M> {
    /// The material alone.
    one: &'a M,
    /// Sixteen copies of it.
    copies: &'a [M],
    /// The sixteen materials.
    table: &'a [M],
    /// The material of each call.
    index: &'a [usize],
}

impl<M> Sets<'_, M> {
    /// The rows `one: {call}`, `one, indexed: {call}` and `16: {call}` of `f(material, k)`
    /// over the inputs `k`.
    fn rows(&self, g: &mut Group, call: &str, f: impl Fn(&M, usize)) {
        g.bench_function(format!("one: {call}"), |b| {
            b.iter(|| {
                for k in 0..N {
                    f(self.one, k);
                }
            })
        });
        g.bench_function(format!("one, indexed: {call}"), |b| {
            b.iter(|| {
                for k in 0..N {
                    f(&self.copies[self.index[k]], k);
                }
            })
        });
        g.bench_function(format!("16: {call}"), |b| {
            b.iter(|| {
                for k in 0..N {
                    f(&self.table[self.index[k]], k);
                }
            })
        });
    }
}

/// A benchmark group.
type Group<'a> = criterion::BenchmarkGroup<'a, criterion::measurement::WallTime>;

/// `α` from 0.05 to 0.8.
fn alpha(j: usize) -> Alpha {
    Alpha::new(0.05 + 0.75 * t(j)).unwrap()
}

/// A relative index from 1.3 to 1.8.
fn eta(j: usize) -> Eta {
    Eta::new(1.3 + 0.5 * t(j)).unwrap()
}

/// A microfacet conductor of distribution `d`, height-correlated, of the `j`-th metal.
fn conductor<D: NormalDistribution>(d: D, j: usize) -> Microfacet<D, Conductor<Vec3>> {
    Microfacet::new(d, Masking::HeightCorrelated, metal(j))
}

/// The `j`-th of the crate's metals as a Fresnel term (RGB; the list repeats after eleven).
fn metal(j: usize) -> Conductor<Vec3> {
    let metals = lobe::metals::ALL;
    Conductor {
        ior: metals[j % metals.len()].rgb(),
    }
}

fn diffuse(c: &mut Criterion) {
    let i = inputs();
    materials(c, "Lambert RGB", |j| Lambert::new(rho(j)).unwrap(), &i);
    let sigma = |j| 0.1 + 1.2 * t(j);
    materials(
        c,
        "OrenNayar RGB σ 0.1..1.3",
        |j| OrenNayar::new(rho(j), sigma(j)).unwrap(),
        &i,
    );
    let r = |j| 0.05 + 0.9 * t(j);
    materials(
        c,
        "EON RGB r 0.05..0.95",
        |j| EnergyPreservingOrenNayar::new(rho(j), r(j)).unwrap(),
        &i,
    );
    let disney = |j| DisneyDiffuse::new(rho(j), Roughness::new(r(j)).unwrap()).unwrap();
    materials(c, "DisneyDiffuse RGB r 0.05..0.95", disney, &i);
    let sheen = |j| Sheen::new(rho(j), 0.05 + 0.9 * t(j)).unwrap();
    materials(c, "Sheen RGB r 0.05..0.95", sheen, &i);
    materials(
        c,
        "Sheen RGB r 0.05..0.95, exact Smith",
        |j| Sheen::new_exact_smith(rho(j), 0.05 + 0.9 * t(j)).unwrap(),
        &i,
    );
}

fn glossy(c: &mut Criterion) {
    let i = inputs();
    let (kd, ks) = (Vec3::new(0.3, 0.2, 0.1), Vec3::new(0.6, 0.6, 0.6));
    // Exponents from 4 to 512, evenly in their logarithm.
    let p = |j| 4.0 * 128f32.powf(t(j));
    materials(
        c,
        "Phong RGB p 4..512",
        |j| Phong::new(kd, ks, p(j)).unwrap(),
        &i,
    );
    for (name, form) in [
        ("BlinnPhong modified RGB p 4..512", BlinnPhongForm::Modified),
        (
            "BlinnPhong normalized RGB p 4..512",
            BlinnPhongForm::Normalized,
        ),
    ] {
        materials(
            c,
            name,
            |j| BlinnPhong::new(kd, ks, p(j), form).unwrap(),
            &i,
        );
    }
    let ggx = |j| conductor(Ggx::isotropic(alpha(j)), j);
    materials(c, "GGX metals RGB α 0.05..0.8", ggx, &i);
    let beckmann = |j| conductor(Beckmann::isotropic(alpha(j)), j);
    materials(c, "Beckmann metals RGB α 0.05..0.8", beckmann, &i);
    let gtr = |j| conductor(Gtr::new(alpha(j), 1.2 + 1.6 * t(j)).unwrap(), j);
    materials(c, "GTR metals RGB α 0.05..0.8 γ 1.2..2.8", gtr, &i);
    let blinn = |j| conductor(BlinnPhongNdf::new(alpha(j)).unwrap(), j);
    materials(c, "BlinnPhongNdf metals RGB α 0.05..0.8", blinn, &i);
    materials(c, "Mirror metals RGB", |j| Mirror::new(metal(j)), &i);
    let glazed = |j| Glazed::new(rho(j), eta(j)).unwrap();
    materials(c, "Glazed RGB η 1.3..1.8", glazed, &i);
    let plastic = |j| Plastic::new(rho(j), Ggx::isotropic(alpha(j)), eta(j)).unwrap();
    materials(c, "Plastic GGX RGB α 0.05..0.8 η 1.3..1.8", plastic, &i);
}

fn transmissive(c: &mut Criterion) {
    let both = two_sided(&inputs());
    let rough = |j| RoughDielectric::new(Ggx::isotropic(alpha(j)), eta(j));
    materials(
        c,
        "RoughDielectric GGX α 0.05..0.8 η 1.3..1.8",
        rough,
        &both,
    );
    materials(
        c,
        "SmoothDielectric η 1.3..1.8",
        |j| SmoothDielectric::new(eta(j)),
        &both,
    );
    materials(
        c,
        "ThinDielectric η 1.3..1.8",
        |j| ThinDielectric::new(eta(j)),
        &both,
    );
}

criterion_group! {
    name = benches;
    config = passes::config();
    targets = diffuse, glossy, transmissive
}
criterion_main!(benches);
