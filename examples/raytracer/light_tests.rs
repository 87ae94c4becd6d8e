//! Direct lighting against closed forms, run by `cargo test`: a Lambert floor lit by each
//! kind of light, rendered with the path tracer (next-event estimation and BSDF sampling
//! combined by MIS), must show the radiance `ρ E / π` that the light's irradiance `E`
//! predicts, within the Monte Carlo error.

use crate::camera::Camera;
use crate::environment::Environment;
use crate::integrator::Integrator;
use crate::light::Light;
use crate::material::Material;
use crate::path::PathTracer;
use crate::quad::Quad;
use crate::render::{RenderSettings, rng_for, sample_pixel};
use crate::scene::{Scene, SceneBuilder};
use lobe::Vec3;
use lobe::bxdf::Lambert;
use lobe::verify::{Accumulator, Estimate};
use std::f64::consts::PI;

/// The floor's reflectance.
const RHO: f32 = 0.5;
/// Samples of the one-pixel image.
const SAMPLES: u32 = 200_000;

/// A large Lambert floor at `y = 0` with the lights that `add` puts in, seen through a
/// one-pixel camera with a 0.02° field of view aimed at the origin from the side.
fn floor_scene(add: impl FnOnce(&mut SceneBuilder)) -> Scene {
    let lambert = Material::new("floor", Lambert::new(Vec3::splat(RHO)).unwrap());
    floor_scene_of(lambert, add)
}

/// [`floor_scene`] with a floor of `material`.
fn floor_scene_of(material: Material, add: impl FnOnce(&mut SceneBuilder)) -> Scene {
    let mut b = SceneBuilder::new();
    let floor = b.material(material);
    let quad = Quad::new(
        Vec3::new(-50.0, 0.0, 50.0),
        Vec3::new(100.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, -100.0),
        floor,
    );
    b.surface(quad.unwrap());
    add(&mut b);
    let camera = Camera::look_at(Vec3::new(0.0, 3.0, 4.0), Vec3::ZERO, Vec3::Y, 0.02, 1.0);
    b.build(camera)
}

/// The path-traced radiance of the origin, direct light only (one bounce).
fn rendered(scene: &Scene) -> Estimate {
    let integrator = Integrator::Path(PathTracer {
        max_depth: 1,
        filter: None,
        irradiance: false,
        clamp: None,
        roulette: true,
    });
    let s = RenderSettings {
        width: 1,
        height: 1,
        spp: SAMPLES,
        seed: 3,
    };
    let mut rng = rng_for(&s, 0, 0);
    let mut acc = Accumulator::new();
    for _ in 0..SAMPLES {
        let l = sample_pixel(scene, &integrator, &s, 0, 0, &mut rng);
        acc.push(f64::from(l.x));
    }
    acc.finish()
}

/// Asserts that the render shows the radiance `ρ E / π` for the irradiance `e`, within 4
/// standard errors plus 1e-4 relative: the pixel's footprint (0.02° wide, where the
/// irradiance varies) and f32 round-off, which is all that is left for the delta lights,
/// whose estimates have no variance.
fn assert_irradiance(name: &str, scene: &Scene, e: f64) {
    let expected = f64::from(RHO) * e / PI;
    let got = rendered(scene);
    println!("{name}: rendered {got}, expected {expected:.6}");
    let tolerance = 4.0 * got.std_err + 1e-4 * expected;
    assert!(
        (got.mean - expected).abs() <= tolerance,
        "{name}: {got} vs {expected}"
    );
}

#[test]
fn point_light_falls_off_as_the_inverse_square() {
    // I cos θ / r² at distance √(1 + 4) with cos θ = 2 / √5.
    let scene = floor_scene(|b| {
        b.light(Light::Point {
            position: Vec3::new(1.0, 2.0, 0.0),
            intensity: Vec3::splat(10.0),
        });
    });
    let r2 = 5.0_f64;
    assert_irradiance("point", &scene, 10.0 * (2.0 / r2.sqrt()) / r2);
}

#[test]
fn directional_light_gives_e_cos() {
    let to_light = Vec3::new(0.6, 0.8, 0.0);
    let scene = floor_scene(|b| {
        b.light(Light::Directional {
            to_light,
            irradiance: Vec3::splat(2.0),
        });
    });
    assert_irradiance("directional", &scene, 2.0 * 0.8);
}

#[test]
fn sphere_light_gives_pi_l_sin2() {
    // A sphere straight above: E = π L sin² α, sin α = r / d.
    let (r, d, l) = (0.5_f64, 2.0_f64, 3.0_f64);
    let scene = floor_scene(|b| {
        b.sphere_light(
            Vec3::new(0.0, d as f32, 0.0),
            r as f32,
            Vec3::splat(l as f32),
        )
    });
    assert_irradiance("sphere", &scene, PI * l * (r / d).powi(2));
}

/// Small, distant spheres keep their irradiance: the same `E` as
/// [`sphere_light_gives_pi_l_sin2`] from spheres 1e-3 and 1.5e-4 of their distance in radius
/// (brighter by the ratio of solid angles). With the cone's `1 − cos θmax` taken from the
/// `f32` cosine, the first rendered 0.9% too bright (16 σ) and the second black.
#[test]
fn a_small_distant_sphere_light_keeps_its_irradiance() {
    let d = 2.0_f64;
    for r_over_d in [1e-3_f64, 1.5e-4] {
        let r = r_over_d * d;
        let l = 3.0 * (0.5 / r).powi(2);
        let scene = floor_scene(|b| {
            b.sphere_light(
                Vec3::new(0.0, d as f32, 0.0),
                r as f32,
                Vec3::splat(l as f32),
            )
        });
        let name = format!("sphere r/d = {r_over_d:e}");
        assert_irradiance(&name, &scene, PI * l * r_over_d * r_over_d);
    }
}

#[test]
fn quad_light_gives_the_rectangle_form_factor() {
    // A square of side 2a centred at height c above the point, facing down: four
    // rectangles with a corner above the point, each with the form factor
    // F = 1/(2π) [X/√(1+X²) atan(Y/√(1+X²)) + Y/√(1+Y²) atan(X/√(1+Y²))], X = Y = a/c.
    let (a, c, l) = (0.75_f64, 1.5_f64, 4.0_f64);
    let scene = floor_scene(|b| {
        let side = 2.0 * a as f32;
        b.quad_light(
            Vec3::new(-a as f32, c as f32, -a as f32),
            Vec3::new(side, 0.0, 0.0),
            Vec3::new(0.0, 0.0, side),
            Vec3::splat(l as f32),
        );
    });
    let x = a / c;
    let s = (1.0 + x * x).sqrt();
    let f_corner = (2.0 * x / s * (x / s).atan()) / (2.0 * PI);
    assert_irradiance("quad", &scene, PI * l * 4.0 * f_corner);
}

#[test]
fn sky_gives_its_cosine_weighted_integral() {
    // E = ∫ L(ω) cos θ dω over the upper hemisphere: with L = h + (z − h) √y (y = cos θ),
    // E = 2π ∫₀¹ (h + (z − h) √y) y dy = 2π (h/2 + 2(z − h)/5).
    let (z, h) = (0.8_f32, 0.2_f32);
    let scene = floor_scene(|b| {
        b.environment(Environment::Sky {
            zenith: Vec3::splat(z),
            horizon: Vec3::splat(h),
            ground: Vec3::splat(5.0),
        });
    });
    let (z, h) = (f64::from(z), f64::from(h));
    assert_irradiance("sky", &scene, 2.0 * PI * (h / 2.0 + 2.0 * (z - h) / 5.0));
}

/// The Whitted integrator traces rough glass as smooth glass (its docs): a point light at
/// the mirror direction of the view shows no highlight, since a mirror ray cannot meet a
/// point light. (It added rough glass's glossy value for each light as well: 0.149 here.)
#[test]
fn whitted_traces_rough_glass_as_smooth_glass() {
    use crate::whitted::Whitted;
    use lobe::bxdf::{Mono, RoughDielectric};
    use lobe::microfacet::Ggx;
    use lobe::{Alpha, Eta};
    let glass = Eta::new(1.5).unwrap();
    let rough = Mono::<_, Vec3>::new(RoughDielectric::new(
        Ggx::isotropic(Alpha::new(0.15).unwrap()),
        glass,
    ));
    let floor = Material::new("rough glass", rough)
        .with_interface(crate::material::Interface::Dielectric(glass));
    let scene = floor_scene_of(floor, |b| {
        b.light(Light::Point {
            position: Vec3::new(0.0, 3.0, -4.0),
            intensity: Vec3::splat(10.0),
        })
    });
    let integrator = Integrator::Whitted(Whitted {
        max_depth: 4,
        filter: None,
        irradiance: false,
    });
    let s = RenderSettings {
        width: 1,
        height: 1,
        spp: 16,
        seed: 3,
    };
    let mut rng = rng_for(&s, 0, 0);
    for _ in 0..16 {
        let l = sample_pixel(&scene, &integrator, &s, 0, 0, &mut rng);
        assert_eq!(l, Vec3::ZERO, "a highlight of the point light: {l}");
    }
}
