//! The law suite every BSDF model runs through: totality, reciprocity, the energy bound by
//! two estimators, the sampler's chi-square test and `sample`/`eval`/`pdf` consistency.
//!
//! Each function asserts and prints its measured figure (`--nocapture` shows them).

use super::k_sigma;
use lobe::bxdf::Bxdf;
use lobe::verify::{
    BxdfCheck, Chi2Config, Pcg32, albedo_cosine, albedo_sampled, chi2_bxdf, reciprocity,
    sample_consistency, sidak,
};
use lobe::{Vec2, Vec3};

/// The relative round-off of a weight computed in `f32` (a few ulps): the allowance that
/// lets a zero-variance estimator (Lambert under cosine sampling) match its exact value.
const F32_ROUND_OFF: f64 = 1e-6;

/// A model under test.
pub struct Model {
    /// What the failure messages call it.
    pub name: String,
    /// The model, on `f32`.
    pub bxdf: Box<dyn Bxdf<Spectrum = f32>>,
    /// The relative index below the surface, for generalised reciprocity (1 for a BRDF).
    pub eta: f32,
    /// The largest directional albedo the model claims (1 for an energy-conserving model;
    /// the measured bound for one that gains energy).
    pub albedo_max: f64,
}

impl Model {
    /// A model that claims energy conservation.
    pub fn new(name: impl Into<String>, bxdf: impl Bxdf<Spectrum = f32> + 'static) -> Self {
        Self {
            name: name.into(),
            bxdf: Box::new(bxdf),
            eta: 1.0,
            albedo_max: 1.0,
        }
    }
}

/// The viewer directions of the energy and sampling checks: from the normal to 89°, at an
/// azimuth off the axes, on the outside (and, for transmissive models, the inside too).
pub fn viewer_directions(model: &Model) -> Vec<Vec3> {
    let mut out: Vec<Vec3> = [0.0f32, 30.0, 60.0, 80.0, 89.0]
        .iter()
        .map(|&t| super::dir(t, 0.4))
        .collect();
    if model.bxdf.lobes().is_transmissive() {
        let inside: Vec<Vec3> = out.iter().map(|w| Vec3::new(w.x, w.y, -w.z)).collect();
        out.extend(inside);
    }
    out
}

/// A unit direction from the generator: uniform on the sphere, or (one time in four) within
/// 1e-7…1e-2 of the horizon.
pub fn adversarial_direction(rng: &mut Pcg32) -> Vec3 {
    let u = rng.next_vec2();
    let z = if rng.next_f32() < 0.25 {
        let mag = 10f32.powf(-7.0 + 5.0 * u.x);
        if rng.next_f32() < 0.5 { mag } else { -mag }
    } else {
        2.0 * u.x - 1.0
    };
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = core::f32::consts::TAU * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// Finite, non-negative `eval`, `pdf` and samples over `n` adversarial direction pairs.
pub fn assert_total(model: &Model, n: usize) {
    let mut rng = Pcg32::new(11, 0);
    for _ in 0..n {
        let (wo, wi) = (
            adversarial_direction(&mut rng),
            adversarial_direction(&mut rng),
        );
        let f = model.bxdf.eval(wo, wi);
        let p = model.bxdf.pdf(wo, wi);
        assert!(
            f.is_finite() && f >= 0.0,
            "{}: eval({wo:?}, {wi:?}) = {f}",
            model.name
        );
        assert!(
            p.is_finite() && p >= 0.0,
            "{}: pdf({wo:?}, {wi:?}) = {p}",
            model.name
        );
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        if let Some(s) = model.bxdf.sample(wo, u, uc) {
            let ok = s.wi.is_finite()
                && (s.wi.length() - 1.0).abs() < 1e-4
                && s.f.is_finite()
                && s.f >= 0.0
                && s.pdf.is_finite()
                && s.pdf > 0.0
                && s.eta.is_finite()
                && s.eta > 0.0;
            assert!(ok, "{}: sample({wo:?}, {u:?}, {uc}) = {s:?}", model.name);
        }
    }
}

/// Reciprocity over `n` random pairs: the two sides must agree within `tol` relative error
/// plus the pair's own round-off allowance (see [`lobe::verify::Reciprocity`]). Returns the
/// largest relative error among well-conditioned pairs (allowance below `tol`).
pub fn assert_reciprocal(model: &Model, n: usize, tol: f64) -> f64 {
    let mut rng = Pcg32::new(12, 0);
    let (mut worst, mut ill, mut zero) = (0.0f64, 0usize, 0usize);
    for _ in 0..n {
        let (wo, wi) = (random_direction(&mut rng), random_direction(&mut rng));
        let r = reciprocity(model.bxdf.as_ref(), wo, wi, model.eta);
        assert!(
            r.holds(tol),
            "{}: reciprocity {r:?} at wo = {wo:?}, wi = {wi:?}",
            model.name
        );
        let scale = r.forward.abs().max(r.backward.abs());
        if scale == 0.0 {
            zero += 1;
        } else if r.round_off - lobe::verify::SUBNORMAL_FLOOR <= tol * scale {
            worst = worst.max(r.relative_error());
        } else {
            ill += 1;
        }
    }
    eprintln!(
        "{}: max reciprocity error {worst:.1e} over well-conditioned pairs ({ill} of {n} ill-conditioned, {zero} zero)",
        model.name
    );
    worst
}

fn random_direction(rng: &mut Pcg32) -> Vec3 {
    let u: Vec2 = rng.next_vec2();
    lobe::sampling::uniform_sphere(u)
}

/// The energy bound: at each viewer direction, the albedo by the model's sampler and (for
/// models without delta lobes) by cosine sampling must agree within their combined error and
/// stay at or below `model.albedo_max` within `k` standard errors. Returns the largest albedo.
pub fn assert_energy_bound(model: &Model, check: &BxdfCheck, n_tests: usize) -> f64 {
    let k = k_sigma(0.01, n_tests);
    let mut largest = 0.0f64;
    for wo in viewer_directions(model) {
        let sampled = albedo_sampled(model.bxdf.as_ref(), wo, check);
        assert!(
            sampled.mean <= model.albedo_max * (1.0 + F32_ROUND_OFF) + k * sampled.std_err,
            "{}: albedo {sampled} above {} at wo = {wo:?}",
            model.name,
            model.albedo_max
        );
        if !model.bxdf.lobes().is_specular() {
            let cosine = albedo_cosine(model.bxdf.as_ref(), wo, check);
            let sigma = (sampled.std_err.powi(2) + cosine.std_err.powi(2)).sqrt();
            assert!(
                (sampled.mean - cosine.mean).abs()
                    <= k * sigma + F32_ROUND_OFF * sampled.mean.abs(),
                "{}: the estimators disagree at wo = {wo:?}: sampled {sampled}, cosine {cosine}",
                model.name
            );
        }
        largest = largest.max(sampled.mean);
    }
    eprintln!("{}: max albedo {largest:.4}", model.name);
    largest
}

/// The sampler against its pdf at every viewer direction, Šidák-corrected over `n_tests`.
pub fn assert_sampling(model: &Model, samples: usize, n_tests: usize) {
    for (i, wo) in viewer_directions(model).into_iter().enumerate() {
        let config = Chi2Config {
            samples,
            seed: 1 + i as u64,
            significance: sidak(0.01, n_tests),
            ..Chi2Config::default()
        };
        let report = chi2_bxdf(model.bxdf.as_ref(), wo, &config);
        assert!(report.passed(), "{} at wo = {wo:?}: {report}", model.name);
    }
}

/// `sample`'s `f` and `pdf` equal `eval` and `pdf` at the sampled direction within `tol`.
pub fn assert_consistent(model: &Model, tol: f64) {
    let check = BxdfCheck {
        samples: 20_000,
        ..BxdfCheck::default()
    };
    for wo in viewer_directions(model) {
        let (f, pdf) = sample_consistency(model.bxdf.as_ref(), wo, &check);
        assert!(
            f <= tol && pdf <= tol,
            "{}: sample vs eval/pdf differ by {f:.1e}/{pdf:.1e} at wo = {wo:?}",
            model.name
        );
    }
}

/// Every law above with the suite's default budgets; `n_tests` is the number of models in
/// the calling file, for the Šidák corrections.
pub fn assert_all_laws(model: &Model, n_tests: usize) {
    assert_total(model, 20_000);
    assert_reciprocal(model, 20_000, 1e-5);
    assert_energy_bound(model, &BxdfCheck::default(), n_tests * 10);
    assert_sampling(model, 200_000, n_tests * 10);
    assert_consistent(model, 1e-4);
}
