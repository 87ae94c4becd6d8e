//! White furnace tests of the whole renderer, run by `cargo test`.
//!
//! A sphere of a lossless material inside a uniform environment of radiance 1 must render
//! to 1 at every pixel: the test renders it with the path tracer and checks each pixel and
//! the mean over the sphere's pixels against the expected value within their Monte Carlo
//! error. A single-scattering microfacet model is not lossless: a GGX conductor with `F = 1`
//! reflects its directional albedo `E(μ)`, a little below 1, and its expected value at a
//! pixel is `E` at that pixel's view angle, estimated independently with
//! `lobe::verify::albedo_sampled` on the same model in `f32`.

use crate::camera::Camera;
use crate::environment::Environment;
use crate::heckbert::PathFilter;
use crate::integrator::Integrator;
use crate::material::Material;
use crate::path::PathTracer;
use crate::render::{RenderSettings, rng_for, sample_pixel};
use crate::scene::{Scene, SceneBuilder};
use crate::scenes::furnace;
use lobe::bxdf::Microfacet;
use lobe::fresnel::NoFresnel;
use lobe::microfacet::{Ggx, Masking};
use lobe::verify::{Accumulator, BxdfCheck, Estimate, albedo_sampled};
use lobe::{Alpha, Vec2, Vec3};
use rayon::prelude::*;

/// Image size: the sphere covers about 2 500 of its pixels.
const SIZE: u32 = 64;
/// Samples per pixel.
const SPP: u32 = 1024;
/// How many standard errors the mean over the sphere may be off.
const K_MEAN: f64 = 4.0;
/// How many standard errors one pixel may be off (about 2 500 pixels per test: a Gaussian
/// exceeds 5.5σ once in 2.6e7 draws).
const K_PIXEL: f64 = 5.5;
/// How far one pixel may be off, whatever its error (the "wildly off" bound).
const MAX_PIXEL_ERROR: f64 = 0.05;
/// The GGX width of the conductor test.
const GGX_ALPHA: f32 = 0.05;

/// One sphere of `material` (centre at the origin, radius 1) in the furnace, filling most
/// of a square image.
fn single(material: Material) -> Scene {
    let mut b = SceneBuilder::new();
    let id = b.material(material);
    b.sphere(Vec3::ZERO, 1.0, id);
    b.environment(Environment::Constant(Vec3::ONE));
    let camera = Camera::look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y, 32.0, 1.0);
    b.build(camera)
}

fn settings(seed: u64) -> RenderSettings {
    RenderSettings {
        width: SIZE,
        height: SIZE,
        spp: SPP,
        seed,
    }
}

fn path_tracer(max_depth: u32, filter: Option<&str>) -> Integrator {
    Integrator::Path(PathTracer {
        max_depth,
        filter: filter.map(|f| PathFilter::parse(f).unwrap()),
        irradiance: false,
        clamp: None,
        roulette: true,
    })
}

/// Every pixel's estimate of the mean channel, with its standard error.
fn render_stats(scene: &Scene, integrator: &Integrator, s: &RenderSettings) -> Vec<Estimate> {
    (0..s.width * s.height)
        .into_par_iter()
        .map(|i| {
            let (x, y) = (i % s.width, i / s.width);
            let mut rng = rng_for(s, x, y);
            let mut acc = Accumulator::new();
            for _ in 0..s.spp {
                let l = sample_pixel(scene, integrator, s, x, y, &mut rng);
                assert!(l.is_finite(), "non-finite sample {l} at ({x}, {y})");
                acc.push(f64::from(l.element_sum()) / 3.0);
            }
            acc.finish()
        })
        .collect()
}

/// The view cosines `μ = n · wo` at the centres of an 8 × 8 grid of cells of pixel
/// `(x, y)`, or `None` when the pixel is not wholly on the sphere. (A sphere projects to a
/// convex region of the film, so four corners on it put the whole pixel on it.)
fn pixel_cosines(scene: &Scene, s: &RenderSettings, x: u32, y: u32) -> Option<Vec<f32>> {
    const N: u32 = 8;
    let film = |fx: f32, fy: f32| {
        Vec2::new(
            (x as f32 + fx) / s.width as f32,
            (y as f32 + fy) / s.height as f32,
        )
    };
    for (fx, fy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
        scene.intersect(&scene.camera.ray(film(fx, fy)))?;
    }
    let mut mus = Vec::with_capacity((N * N) as usize);
    for i in 0..N {
        for j in 0..N {
            let ray = scene.camera.ray(film(
                (i as f32 + 0.5) / N as f32,
                (j as f32 + 0.5) / N as f32,
            ));
            let hit = scene.intersect(&ray)?;
            mus.push(hit.ng.dot(-ray.dir).clamp(0.0, 1.0));
        }
    }
    Some(mus)
}

/// The expected value of a pixel and its standard error.
#[derive(Clone, Copy, Debug)]
struct Expected {
    value: f64,
    std_err: f64,
}

/// What a furnace test measured.
#[derive(Debug)]
struct Report {
    /// Pixels wholly on the sphere.
    pixels: usize,
    /// Mean over those pixels of (rendered − expected).
    mean_error: f64,
    /// The standard error of that mean.
    mean_std_err: f64,
    /// The largest |z| of one pixel.
    max_z: f64,
    /// The largest |rendered − expected| of one pixel.
    max_error: f64,
    /// The mean rendered value over the sphere.
    mean_value: f64,
}

/// Renders `scene` and compares every pixel wholly on the sphere with `expected(μs)`;
/// every other pixel sees the environment and must be exactly 1.
fn furnace(
    scene: &Scene,
    max_depth: u32,
    seed: u64,
    expected: impl Fn(&[f32]) -> Expected,
) -> Report {
    let s = settings(seed);
    let stats = render_stats(scene, &path_tracer(max_depth, None), &s);
    let mut report = Report {
        pixels: 0,
        mean_error: 0.0,
        mean_std_err: 0.0,
        max_z: 0.0,
        max_error: 0.0,
        mean_value: 0.0,
    };
    // The render's pixels are independent; the expected values' errors are not (pixels
    // share the albedo table's entries), so they add linearly: a conservative bound.
    let mut render_variance = 0.0;
    let mut expected_err = 0.0;
    for (i, e) in stats.iter().enumerate() {
        let (x, y) = (i as u32 % s.width, i as u32 / s.width);
        let hits_sphere = scene.intersect(&scene.camera.ray(Vec2::new(
            (x as f32 + 0.5) / s.width as f32,
            (y as f32 + 0.5) / s.height as f32,
        )));
        let Some(mus) = pixel_cosines(scene, &s, x, y) else {
            if hits_sphere.is_none() && pixel_misses(scene, &s, x, y) {
                assert!(
                    (e.mean - 1.0).abs() < 1e-6,
                    "background pixel ({x}, {y}) = {}",
                    e.mean
                );
            }
            continue;
        };
        let exp = expected(&mus);
        let diff = e.mean - exp.value;
        // A floor on the error for estimates whose samples are all but identical: f32
        // round-off along a path.
        let sigma = (e.std_err.powi(2) + exp.std_err.powi(2)).sqrt().max(1e-5);
        report.max_z = report.max_z.max(diff.abs() / sigma);
        report.max_error = report.max_error.max(diff.abs());
        report.mean_error += diff;
        report.mean_value += e.mean;
        render_variance += e.std_err * e.std_err;
        expected_err += exp.std_err;
        report.pixels += 1;
    }
    let n = report.pixels as f64;
    report.mean_error /= n;
    report.mean_value /= n;
    // Floored at f32 round-off along a path (glass: every sample is 1 up to rounding).
    report.mean_std_err = (render_variance / (n * n) + (expected_err / n).powi(2))
        .sqrt()
        .max(1e-6);
    println!("{report:?}");
    report
}

/// True when no ray through pixel `(x, y)` can reach the sphere (all four corners miss, and
/// the pixel is away from the silhouette).
fn pixel_misses(scene: &Scene, s: &RenderSettings, x: u32, y: u32) -> bool {
    (-1..=2).all(|i| {
        (-1..=2).all(|j| {
            let film = Vec2::new(
                (x as f32 + i as f32) / s.width as f32,
                (y as f32 + j as f32) / s.height as f32,
            );
            scene.intersect(&scene.camera.ray(film)).is_none()
        })
    })
}

fn assert_report(name: &str, r: &Report) {
    assert!(
        r.pixels > 2000,
        "{name}: the sphere covers {} pixels",
        r.pixels
    );
    assert!(
        r.mean_error.abs() <= K_MEAN * r.mean_std_err,
        "{name}: the mean over the sphere is off by {:.2e} ± {:.1e} ({:.1} σ)",
        r.mean_error,
        r.mean_std_err,
        r.mean_error / r.mean_std_err
    );
    assert!(
        r.max_z <= K_PIXEL,
        "{name}: a pixel is {:.1} σ off",
        r.max_z
    );
    assert!(
        r.max_error <= MAX_PIXEL_ERROR,
        "{name}: a pixel is off by {:.3}",
        r.max_error
    );
}

/// Exactly one, whatever the view angle.
fn one(_: &[f32]) -> Expected {
    Expected {
        value: 1.0,
        std_err: 0.0,
    }
}

#[test]
fn white_lambert_sphere_vanishes() {
    let scene = single(furnace::white_lambert().unwrap());
    let r = furnace(&scene, 16, 1, one);
    assert_report("white Lambert", &r);
}

#[test]
fn smooth_glass_sphere_vanishes() {
    // Refraction scales radiance by 1/η² going in and η² coming out; Russian roulette sees
    // β η², which stays 1, so the depth limit is what ends the rare long paths.
    let scene = single(furnace::smooth_glass().unwrap());
    let r = furnace(&scene, 64, 2, one);
    assert_report("smooth glass", &r);
}

#[test]
fn white_glazed_sphere_vanishes() {
    // Albedo F + (1 − F) ρ = 1 for ρ = 1, by the Kelemen & Szirmay-Kalos coupling.
    let scene = single(furnace::white_glazed().unwrap());
    let r = furnace(&scene, 16, 3, one);
    assert_report("white glazed", &r);
}

/// The GGX conductor with `F = 1` reflects its single-scattering albedo `E(μ)`: below 1
/// at grazing angles. `E` is tabulated at 129 cosines with `lobe::verify::albedo_sampled`
/// (the model's own sampler, 200 000 samples each) and interpolated linearly.
#[test]
fn ggx_sphere_without_fresnel_reflects_its_albedo() {
    const NODES: usize = 129;
    let model = Microfacet::new(
        Ggx::isotropic(Alpha::new(GGX_ALPHA).unwrap()),
        Masking::HeightCorrelated,
        NoFresnel::<f32>::new(),
    );
    let check = BxdfCheck {
        samples: 200_000,
        seed: 11,
    };
    let table: Vec<Estimate> = (0..NODES)
        .into_par_iter()
        .map(|i| {
            let mu = (i as f32 / (NODES - 1) as f32).max(1e-4);
            let wo = Vec3::new((1.0 - mu * mu).sqrt(), 0.0, mu);
            albedo_sampled(&model, wo, &check)
        })
        .collect();
    let albedo = |mu: f32| {
        let x = mu.clamp(0.0, 1.0) * (NODES - 1) as f32;
        let i = (x as usize).min(NODES - 2);
        let t = f64::from(x - i as f32);
        let (a, b) = (table[i], table[i + 1]);
        (a.mean * (1.0 - t) + b.mean * t, a.std_err.max(b.std_err))
    };
    let lowest = table.iter().map(|e| e.mean).fold(f64::INFINITY, f64::min);
    println!(
        "GGX α = {GGX_ALPHA}, F = 1: E(0.5) = {:.5}, E(1) = {:.5}, min E = {lowest:.4}",
        albedo(0.5).0,
        albedo(1.0).0
    );
    let scene = single(furnace::ggx_no_fresnel(GGX_ALPHA).unwrap());
    let r = furnace(&scene, 16, 4, |mus| {
        let n = mus.len() as f64;
        let (sum, err) = mus.iter().fold((0.0, 0.0), |(s, e), &mu| {
            let (v, se) = albedo(mu);
            (s + v, f64::max(e, se))
        });
        Expected {
            value: sum / n,
            std_err: err,
        }
    });
    assert_report("GGX, F = 1", &r);
    // And the loss is real: the sphere is measurably darker than 1 on average.
    assert!(r.mean_value < 1.0 - 4.0 * r.mean_std_err, "{r:?}");
}

/// Heckbert filters that split the paths into disjoint sets give images that add up to the
/// unfiltered one, sample for sample (the random numbers do not depend on the filter).
#[test]
fn disjoint_path_filters_add_up() {
    let scene = single(furnace::white_lambert().unwrap());
    let s = RenderSettings {
        width: 16,
        height: 16,
        spp: 8,
        seed: 5,
    };
    let full = render_stats(&scene, &path_tracer(8, None), &s);
    let parts: Vec<Vec<Estimate>> = ["L E", "L D E", "L D D+ E"]
        .iter()
        .map(|f| render_stats(&scene, &path_tracer(8, Some(f)), &s))
        .collect();
    let mut direct = 0.0;
    for (i, whole) in full.iter().enumerate() {
        let sum: f64 = parts.iter().map(|p| p[i].mean).sum();
        assert!(
            (sum - whole.mean).abs() < 1e-5,
            "pixel {i}: {sum} vs {}",
            whole.mean
        );
        direct += parts[1][i].mean;
    }
    assert!(
        direct > 0.0,
        "the sphere's direct light shows up in 'L D E'"
    );
}

/// The Whitted integrator in the furnace: its ambient term is the environment's mean
/// radiance times the non-delta albedo (1 for white Lambert), and glass splits each ray
/// into `F` and `1 − F`; both come out at 1, up to the rays pruned below 0.1% of the pixel.
#[test]
fn whitted_furnace_is_white_too() {
    let integrator = Integrator::Whitted(crate::whitted::Whitted {
        max_depth: 16,
        filter: None,
        irradiance: false,
    });
    let s = RenderSettings {
        width: 24,
        height: 24,
        spp: 4,
        seed: 6,
    };
    for material in [
        furnace::white_lambert().unwrap(),
        furnace::smooth_glass().unwrap(),
    ] {
        let name = material.name.clone();
        let scene = single(material);
        let stats = render_stats(&scene, &integrator, &s);
        let worst = stats
            .iter()
            .map(|e| (e.mean - 1.0).abs())
            .fold(0.0, f64::max);
        println!("Whitted, {name}: largest |L − 1| = {worst:.2e}");
        assert!(worst < 3e-3, "{name}: {worst}");
    }
}

/// Many bounces and Russian roulette, against a closed form: an integrating sphere. Inside a
/// Lambert sphere of radius `R` and reflectance `ρ`, a spherical light of radius `r` and
/// radiance `L` at the centre lights every wall point head-on with `E = π L r²/R²`; light
/// leaving a wall is uniform and diffuse, and a fraction `s = r²/R²` of it (the light's
/// cosine-weighted share of the wall's hemisphere, `sin²` of its half-angle) falls on the
/// light, which absorbs it, the rest on the wall again. So the walls' radiance is
/// `ρ E/π · Σ (ρ (1 − s))ᵏ = ρ L s / (1 − ρ (1 − s))`. With `ρ = 0.9` nine tenths of it has
/// bounced more than once and most of it more than [`ROULETTE_DEPTH`](crate::path) times, where
/// roulette ends paths: the render, with roulette and without (128 bounces: the series beyond
/// leaves 1e-6), shows the closed form within k standard errors plus 1e-5 relative. (A roulette
/// that forgets to reweight its survivors renders far too dark here.)
#[test]
fn an_integrating_sphere_renders_its_closed_form_with_and_without_roulette() {
    let (big, small, rho, l) = (1.0_f32, 0.05_f32, 0.9_f32, 50.0_f32);
    let mut b = SceneBuilder::new();
    let wall = b.material(Material::new(
        "wall",
        lobe::bxdf::Lambert::new(Vec3::splat(rho)).unwrap(),
    ));
    b.sphere(Vec3::ZERO, big, wall);
    b.sphere_light(Vec3::ZERO, small, Vec3::splat(l));
    // From inside, looking away from the light at the wall.
    let camera = Camera::look_at(
        Vec3::new(0.0, 0.0, 0.3),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::Y,
        30.0,
        1.0,
    );
    let scene = b.build(camera);
    let s_frac = f64::from(small / big).powi(2);
    let rho = f64::from(rho);
    let expected = rho * f64::from(l) * s_frac / (1.0 - rho * (1.0 - s_frac));
    for (roulette, seed) in [(true, 21), (false, 22)] {
        let integrator = Integrator::Path(PathTracer {
            max_depth: 128,
            filter: None,
            irradiance: false,
            clamp: None,
            roulette,
        });
        // Roulette's estimates are the noisier (it trades variance for shorter paths).
        let s = RenderSettings {
            width: 8,
            height: 8,
            spp: if roulette { 2048 } else { 256 },
            seed,
        };
        let stats = render_stats(&scene, &integrator, &s);
        let n = stats.len() as f64;
        let mean = stats.iter().map(|e| e.mean).sum::<f64>() / n;
        let se = stats
            .iter()
            .map(|e| e.std_err * e.std_err)
            .sum::<f64>()
            .sqrt()
            / n;
        println!("roulette {roulette}: {mean:.5} ± {se:.1e}, closed form {expected:.5}");
        assert!(
            (mean - expected).abs() <= K_MEAN * se + 1e-5 * expected,
            "roulette {roulette}: {mean} ± {se} vs {expected}"
        );
    }
}
