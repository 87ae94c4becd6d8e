//! The layered models against a brute-force random walk written here, independently of
//! `lobe::bxdf::Layered` (issue 12, "Reference comparison").
//!
//! The reference follows light the simplest way: from `wo` it samples the top interface; a
//! reflection ends the path, a refraction starts a walk that crosses the layer (taking the
//! slab's transmittance, or sampling a free-flight distance and a Henyey-Greenstein phase
//! function — written here from the formulas — when the layer scatters), bounces off the base
//! by the base's own sampler and hits the underside of the top by the top's own sampler, until
//! the top transmits. Nothing else: no next-event estimation through a direction sampled from
//! `wi`, no multiple importance sampling, no Russian roulette (the model's `eval` uses all
//! three). It uses only the parts' public `eval` and `sample`.
//!
//! * **Albedo**: the mean of the walk's weight (the product of `f |cos| / pdf` along the
//!   path) is `∫ f cos θi dωi`; compared with the model's sampled and cosine-weighted albedo.
//! * **Value**: at each hit of the top from inside, `f_top(−w, wi)` times the walk's
//!   throughput is an estimate of the light leaving toward `wi` there; their sum plus the
//!   top's reflection `f_top(wo, wi)` estimates `f(wo, wi)`; compared with the mean of the
//!   model's independent estimates (`eval_seeded`).
//!
//! Both sides count the same paths: at most `max_depth` events, an event being a crossing to
//! an interface or a scattering in the medium. Agreement within `k` combined standard errors,
//! Šidák-corrected over every comparison in the file.

mod common;

use core::f32::consts::PI;
use lobe::bxdf::{
    Bxdf, CoatedConductor, CoatedDiffuse, Lambert, LayerInterface, Layered, Mirror, Mix,
    SmoothDielectric,
};
use lobe::fresnel::NoFresnel;
use lobe::microfacet::Ggx;
use lobe::verify::{Accumulator, Config, Estimate, Pcg32, albedo};
use lobe::{Alpha, Eta, Vec3, metals};

/// Comparisons in this file: 4 configurations × (2 albedo directions × 2 estimators + 3
/// pairs), and 6 stacks with a delta base × 2 viewer directions × (3 albedo estimators + the
/// integral of `pdf`).
const TESTS: usize = 4 * (2 * 2 + 3) + 6 * 2 * 4;

/// What the reference needs of a stack.
struct Stack<'a> {
    top: &'a dyn Bxdf<Spectrum = f32>,
    bottom: &'a dyn Bxdf<Spectrum = f32>,
    thickness: f32,
    /// Single-scattering albedo and HG asymmetry of the medium, if it scatters.
    medium: Option<(f32, f32)>,
    max_depth: u32,
}

impl<'a> Stack<'a> {
    /// The stack `model` describes: its layers, thickness, medium and depth, to walk
    /// independently of its own walk.
    fn of<T, B>(model: &'a Layered<T, B>) -> Self
    where
        T: LayerInterface + Bxdf<Spectrum = f32>,
        B: Bxdf<Spectrum = f32>,
    {
        let (albedo, g) = model.medium();
        Stack {
            top: model.top(),
            bottom: model.bottom(),
            thickness: model.thickness(),
            medium: (albedo > 0.0).then_some((albedo, g)),
            max_depth: model.max_depth(),
        }
    }
}

/// Henyey-Greenstein, written from the formula: `(1 − g²) / (4π (1 + g² + 2 g cos)^{3/2})`
/// with `cos` between the two directions pointing away from the scattering point.
fn hg(g: f32, cos: f32) -> f32 {
    let d = 1.0 + g * g + 2.0 * g * cos;
    (1.0 - g * g) / (4.0 * PI * d * d.sqrt())
}

/// A direction with density `hg(g, wo · wi)`, by rejection from the uniform sphere against
/// the largest value `hg(g, −sign(g))` (slow, and independent of the model's inversion).
fn sample_hg(g: f32, wo: Vec3, rng: &mut Pcg32) -> Vec3 {
    let max = hg(g, if g >= 0.0 { -1.0 } else { 1.0 });
    loop {
        let w = lobe::sampling::uniform_sphere(rng.next_vec2());
        if rng.next_f32() * max <= hg(g, wo.dot(w)) {
            return w;
        }
    }
}

/// One walk from `wo`: returns the weight of the path that leaves (or 0), for `wi` the sum
/// of the exit estimates at the top hits (excluding the entry's reflection), and whether the
/// path met a lobe with a density (a medium scattering or a non-delta sample of an
/// interface): a path that did not is one of the model's delta lobes.
fn walk(s: &Stack, wo: Vec3, wi: Option<Vec3>, rng: &mut Pcg32) -> (f64, f64, bool) {
    let Some(s0) = s.top.sample(wo, rng.next_vec2(), rng.next_f32()) else {
        return (0.0, 0.0, false);
    };
    let w0 = f64::from(s0.f * s0.wi.z.abs() / s0.pdf);
    let mut scattered = !s0.is_specular();
    if s0.wi.z > 0.0 {
        return (w0, 0.0, scattered);
    }
    let mut beta = w0;
    let mut exit_sum = 0.0;
    let (mut z, mut w) = (s.thickness, s0.wi);
    for depth in 0..s.max_depth {
        // Cross (part of) the layer.
        let mut at_interface = true;
        if let Some((albedo, g)) = s.medium {
            let t = -(1.0 - rng.next_f64()).ln();
            let zp = z + (t as f32) * w.z;
            if zp > 0.0 && zp < s.thickness {
                z = zp;
                beta *= f64::from(albedo);
                w = sample_hg(g, -w, rng);
                at_interface = false;
                scattered = true;
            } else {
                z = if w.z > 0.0 { s.thickness } else { 0.0 };
            }
        } else {
            z = if w.z > 0.0 { s.thickness } else { 0.0 };
            beta *= f64::from((-s.thickness / w.z.abs()).exp());
        }
        if !at_interface {
            continue;
        }
        if w.z > 0.0 {
            // The underside of the top: light leaves toward wi with f_top(−w, wi).
            if let Some(wi) = wi {
                exit_sum += beta * f64::from(s.top.eval(-w, wi));
            }
            let _ = depth;
            let Some(t) = s.top.sample(-w, rng.next_vec2(), rng.next_f32()) else {
                return (0.0, exit_sum, scattered);
            };
            let weight = f64::from(t.f * t.wi.z.abs() / t.pdf);
            scattered |= !t.is_specular();
            if t.wi.z > 0.0 {
                return (beta * weight, exit_sum, scattered);
            }
            beta *= weight;
            w = t.wi;
        } else {
            let Some(b) = s.bottom.sample(-w, rng.next_vec2(), rng.next_f32()) else {
                return (0.0, exit_sum, scattered);
            };
            if b.wi.z <= 0.0 {
                return (0.0, exit_sum, scattered);
            }
            scattered |= !b.is_specular();
            beta *= f64::from(b.f * b.wi.z.abs() / b.pdf);
            w = b.wi;
        }
    }
    (0.0, exit_sum, scattered)
}

/// The reference albedo at `wo` from `n` walks, and on the same walks the albedo of the
/// paths that met a lobe with a density (the model's lobes with a density).
fn reference_albedo(s: &Stack, wo: Vec3, n: usize, seed: u64) -> (Estimate, Estimate) {
    let (all, density, _) = reference_walks(s, wo, n, seed);
    (all, density)
}

/// [`reference_albedo`]'s two estimates and, on the same walks, the probability that a walk
/// leaves after meeting a lobe with a density (the integral of the model's `pdf`, which
/// counts the sampler's directions from those lobes; a walk that leaves has a positive
/// weight in the stacks this file builds).
fn reference_walks(s: &Stack, wo: Vec3, n: usize, seed: u64) -> (Estimate, Estimate, Estimate) {
    let mut rng = Pcg32::new(seed, 11);
    let (mut all, mut density, mut leaves) =
        (Accumulator::new(), Accumulator::new(), Accumulator::new());
    for _ in 0..n {
        let (w, _, scattered) = walk(s, wo, None, &mut rng);
        all.push(w);
        density.push(if scattered { w } else { 0.0 });
        leaves.push(if scattered && w > 0.0 { 1.0 } else { 0.0 });
    }
    (all.finish(), density.finish(), leaves.finish())
}

/// `∫ pdf(wo, wi) dωi` over the upper hemisphere by `n` cosine-distributed directions.
fn pdf_integral(m: &dyn Bxdf<Spectrum = f32>, wo: Vec3, n: usize, seed: u64) -> Estimate {
    let mut rng = Pcg32::new(seed, 13);
    let mut acc = Accumulator::new();
    for _ in 0..n {
        let wi = lobe::sampling::cosine_hemisphere(rng.next_vec2());
        let p = lobe::sampling::cosine_hemisphere_pdf(wi.z);
        acc.push(if p > 0.0 {
            f64::from(m.pdf(wo, wi) / p)
        } else {
            0.0
        });
    }
    acc.finish()
}

/// The reference value `f(wo, wi)` from `n` walks.
fn reference_eval(s: &Stack, wo: Vec3, wi: Vec3, n: usize, seed: u64) -> Estimate {
    let mut rng = Pcg32::new(seed, 12);
    let reflection = f64::from(s.top.eval(wo, wi));
    let mut acc = Accumulator::new();
    for _ in 0..n {
        acc.push(reflection + walk(s, wo, Some(wi), &mut rng).1);
    }
    acc.finish()
}

/// The model's value `E[f(wo, wi)]` from `n` seeded estimates.
fn model_eval(m: &dyn Bxdf<Spectrum = f32>, wo: Vec3, wi: Vec3, n: usize) -> Estimate {
    Estimate::from_samples((0..n as u64).map(|s| f64::from(m.eval_seeded(wo, wi, s))))
}

fn assert_agree(what: &str, model: Estimate, reference: Estimate, k: f64) {
    let sigma = (model.std_err.powi(2) + reference.std_err.powi(2)).sqrt();
    let gap = (model.mean - reference.mean).abs();
    eprintln!(
        "{what}: model {model}, reference {reference}: {:.2} σ",
        gap / sigma
    );
    assert!(
        gap <= k * sigma + 1e-6 * reference.mean.abs(),
        "{what}: model {model} and reference {reference} differ by {:.1} σ (k = {k:.2})",
        gap / sigma
    );
}

/// Compares one stack: albedo at two viewer directions by both of the model's estimators,
/// and the value at three pairs.
fn compare(name: &str, model: &dyn Bxdf<Spectrum = f32>, stack: &Stack, k: f64, seed: u64) {
    let config = Config {
        albedo_samples: 200_000,
        seed,
        ..Config::default()
    };
    for theta in [20.0, 70.0] {
        let wo = common::dir(theta, 0.3);
        let r = reference_albedo(stack, wo, 200_000, seed).0;
        let a = albedo(model, wo, &config);
        assert_agree(
            &format!("{name} albedo θo={theta}° sampled"),
            a.sampled,
            r,
            k,
        );
        if let Some(c) = a.cosine {
            assert_agree(&format!("{name} albedo θo={theta}° cosine"), c, r, k);
        }
    }
    let pairs = [
        (common::dir(30.0, 0.0), common::dir(30.0, PI)),
        (common::dir(10.0, 0.5), common::dir(60.0, 2.0)),
        (common::dir(75.0, 1.0), common::dir(45.0, 1.5)),
    ];
    for (i, (wo, wi)) in pairs.into_iter().enumerate() {
        let r = reference_eval(stack, wo, wi, 400_000, seed + i as u64);
        let m = model_eval(model, wo, wi, 100_000);
        assert_agree(&format!("{name} f at pair {i}"), m, r, k);
    }
}

fn ggx(a: f32) -> Ggx {
    Ggx::isotropic(Alpha::new(a).unwrap())
}

#[test]
fn coated_diffuse_matches_the_brute_force_walk() {
    let k = common::k_sigma(0.01, TESTS);
    let eta = Eta::new(1.5).unwrap();
    let model = CoatedDiffuse::coated_diffuse(0.8_f32, ggx(0.3), eta).unwrap();
    let stack = Stack::of(&model);
    compare("CoatedDiffuse α=0.3 η=1.5 ρ=0.8", &model, &stack, k, 1);
}

#[test]
fn coated_conductor_matches_the_brute_force_walk() {
    let k = common::k_sigma(0.01, TESTS);
    let copper = metals::COPPER.rgb();
    let red = lobe::ComplexIor::new(copper.eta().x, copper.k().x).unwrap();
    let model =
        CoatedConductor::coated_conductor(ggx(0.1), Eta::new(1.5).unwrap(), ggx(0.3), red).unwrap();
    let stack = Stack::of(&model);
    compare(
        "CoatedConductor coat α=0.1, copper (red) α=0.3",
        &model,
        &stack,
        k,
        2,
    );
}

#[test]
fn a_scattering_layer_matches_the_brute_force_walk() {
    let k = common::k_sigma(0.01, TESTS);
    let model = CoatedDiffuse::coated_diffuse(0.5_f32, ggx(0.2), Eta::new(1.33).unwrap())
        .unwrap()
        .with_thickness(0.5)
        .unwrap()
        .with_medium(0.9, 0.4)
        .unwrap();
    // The reference walks the stack the model says it is: check that it is the one built.
    assert_eq!((model.thickness(), model.medium()), (0.5, (0.9, 0.4)));
    let stack = Stack::of(&model);
    compare(
        "CoatedDiffuse with a medium (albedo 0.9, g 0.4, 0.5 mfp)",
        &model,
        &stack,
        k,
        3,
    );
}

#[test]
fn a_short_walk_counts_the_same_paths() {
    // max_depth = 3: entry, base, top (exit) — and one more round trip cut off.
    let k = common::k_sigma(0.01, TESTS);
    let model = Layered::new(
        lobe::bxdf::RoughDielectric::new(ggx(0.4), Eta::new(2.0).unwrap()),
        lobe::bxdf::Lambert::new(1.0_f32).unwrap(),
    )
    .with_thickness(0.0)
    .unwrap()
    .with_max_depth(3)
    .unwrap();
    assert_eq!((model.thickness(), model.max_depth()), (0.0, 3));
    let stack = Stack::of(&model);
    compare(
        "rough η=2 coat over white Lambert, max depth 3",
        &model,
        &stack,
        k,
        4,
    );
}

/// A smooth coat over a base with a delta lobe: the light that reaches the exit through the
/// base's mirror after a diffuse bounce or a scattering in the medium is counted by `sample`,
/// and by `eval` through its connections along the delta chains (the reference walks it
/// bounce by bounce). Before the chains, both lost it: the sampled albedo over
/// `Mix(Mirror, Lambert 0.8)` was 4% low at normal incidence, over a mirror under a scattering
/// layer 38% low at 45°. The model has delta lobes and lobes with a density: its full albedo
/// by its sampler, and the part with a density by its sampler and by cosine sampling of
/// `eval`, against the reference's paths, all of them and those that met a lobe with a
/// density. Then a stack whose chains carry much of the light with a density (a coat of
/// η 3, whose underside reflects 25% to 100% inside the escape cone, over a mirror) with
/// walks short enough to cut the chains (`max_depth` 5 and 4): counting one round trip too
/// many or too few where the depth ends fails it by 5.6 and 8.0 σ. Then the same coat over
/// `Mix(Mirror, Lambert 0.8)`, whose base connects too, at `max_depth` 5 and 6: a round trip
/// too many or too few in the base's connections fails it by 10 to 19 σ (`eval`'s and
/// `pdf`'s alike). Every stack also checks `pdf`: its integral over the hemisphere against
/// the share of the reference's walks that leave after a lobe with a density.
#[test]
fn a_smooth_coat_over_a_delta_base_matches_the_brute_force_walk() {
    let coat = || SmoothDielectric::new(Eta::new(1.5).unwrap());
    let mirror = || Mirror::new(NoFresnel::<f32>::new());
    let half_mirror = Mix::new(mirror(), Lambert::new(0.8_f32).unwrap(), 0.5).unwrap();
    let over_mix = Layered::new(coat(), half_mirror);
    compare_delta_base(
        "smooth coat over Mix(Mirror, Lambert 0.8)",
        &over_mix,
        200_000,
        10,
    );
    let over_mirror = Layered::new(coat(), mirror())
        .with_thickness(0.5)
        .unwrap()
        .with_medium(0.9, 0.0)
        .unwrap();
    let name = "smooth coat, scattering layer (albedo 0.9, 0.5 mfp), mirror";
    compare_delta_base(name, &over_mirror, 200_000, 12);
    // The short walks' reference takes ten times the walks: the part of their light with a
    // density is small (2%), and the test must see a round trip more or less in it.
    let dense = |depth| {
        Layered::new(SmoothDielectric::new(Eta::new(3.0).unwrap()), mirror())
            .with_thickness(0.3)
            .unwrap()
            .with_medium(0.9, 0.0)
            .unwrap()
            .with_max_depth(depth)
            .unwrap()
    };
    let name = "smooth coat η 3, scattering layer (albedo 0.9, 0.3 mfp), mirror, max depth";
    compare_delta_base(&format!("{name} 5"), &dense(5), 2_000_000, 14);
    compare_delta_base(&format!("{name} 4"), &dense(4), 2_000_000, 16);
    // And the base's own connections (the stacks above have none: a bare mirror) cut short.
    // Both parities of the depth: a round trip too many or too few shows in one of them.
    let short = |depth| {
        let half_mirror = Mix::new(mirror(), Lambert::new(0.8_f32).unwrap(), 0.5).unwrap();
        Layered::new(SmoothDielectric::new(Eta::new(3.0).unwrap()), half_mirror)
            .with_max_depth(depth)
            .unwrap()
    };
    let name = "smooth coat η 3 over Mix(Mirror, Lambert 0.8), max depth";
    compare_delta_base(&format!("{name} 5"), &short(5), 2_000_000, 18);
    compare_delta_base(&format!("{name} 6"), &short(6), 2_000_000, 20);
}

/// One stack of [`a_smooth_coat_over_a_delta_base_matches_the_brute_force_walk`] at two
/// viewer directions, the reference from `n` walks.
fn compare_delta_base<T, B>(name: &str, model: &Layered<T, B>, n: usize, seed: u64)
where
    T: LayerInterface + Bxdf<Spectrum = f32>,
    B: Bxdf<Spectrum = f32>,
{
    let k = common::k_sigma(0.01, TESTS);
    let stack = Stack::of(model);
    for (j, theta) in [20.0, 70.0].into_iter().enumerate() {
        let wo = common::dir(theta, 0.3);
        let seed = seed + j as u64;
        let (all, density, leaves) = reference_walks(&stack, wo, n, seed);
        let config = Config {
            albedo_samples: 200_000,
            seed,
            ..Config::default()
        };
        let a = albedo(model, wo, &config);
        let (sampled_part, cosine) = a
            .density_lobes
            .expect("delta lobes and lobes with a density");
        let what = format!("{name} albedo θo={theta}°");
        assert_agree(&format!("{what} sampled"), a.sampled, all, k);
        let part = format!("{what} sampled, lobes with a density");
        assert_agree(&part, sampled_part, density, k);
        assert_agree(&format!("{what} cosine (eval)"), cosine, density, k);
        let pdf = pdf_integral(model, wo, 200_000, seed);
        let what = format!("{name} θo={theta}°: ∫ pdf against the walks that leave");
        assert_agree(&what, pdf, leaves, k);
    }
}
