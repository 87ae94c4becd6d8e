//! The shadow terminator on the `lights` scene's torus, run by `cargo test`.
//!
//! The torus (`assets/torus.obj`) is coarse: 24 × 8 segments, 45° of tube per facet, with
//! vertex normals. Near the terminator of the point light and the sun, its interpolated
//! normals see light that its flat facets do not: the facet's plane puts the light below the
//! horizon, and a shadow ray from the flat facet runs into the mesh itself. Without the fix
//! the renderer cut that light, and the inner rim showed a hard-edged dark patch along the
//! facets. [`Scene::terminator_fix`] lets such light through, its shadow ray starting from
//! the smooth surface point of Hanika 2021 ([`crate::surface::Hit::p_shadow`]).
//!
//! The test renders the pixels of the patch as `--scene lights` frames them (640 × 360), with
//! the direct light of the two lights that make it, and compares them with a reference in
//! which the torus casts no shadow on itself. That reference is the right answer there: the
//! smooth torus (stood in for by a tessellation 8 × finer in each direction) shadows none of
//! those pixels. All three renders use the same random numbers, so the differences are
//! exactly the light the torus's own shadow rays cut.

use crate::aabb::Aabb;
use crate::integrator::Integrator;
use crate::light::Light;
use crate::mesh::{Mesh, Triangle};
use crate::path::PathTracer;
use crate::ray::Ray;
use crate::render::{RenderSettings, rng_for};
use crate::scene::Scene;
use crate::scenes::lights::{self, TORUS_OFFSET};
use crate::shading::ShadingPoint;
use crate::surface::{Hit, MaterialId, Surface};
use lobe::{Vec2, Vec3};
use rayon::prelude::*;
use std::f32::consts::TAU;

/// The frame of `--scene lights` at its default size.
const W: u32 = 640;
/// See [`W`].
const H: u32 = 360;
/// Samples per pixel of the renders.
const SPP: u32 = 16;
/// The torus's major and minor radii (`assets/make_torus.py`).
const RADII: (f32, f32) = (0.75, 0.25);
/// The material id of the torus in the `lights` scene (its first material).
const TORUS: MaterialId = 0;
/// Rec. 709 luminance weights.
const LUMINANCE: Vec3 = Vec3::new(0.2126, 0.7152, 0.0722);

/// The torus of `assets/make_torus.py` with `nu × nv` segments, built in code.
fn torus(nu: u32, nv: u32, material: MaterialId) -> Mesh {
    let vertex = |i: u32, j: u32| {
        let (p, n) = smooth_torus(
            TAU * (i % nu) as f32 / nu as f32,
            TAU * (j % nv) as f32 / nv as f32,
        );
        (p, n)
    };
    let mut triangles = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            let mut quad =
                [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)].map(|(a, b)| vertex(a, b));
            let face = (quad[1].0 - quad[0].0).cross(quad[2].0 - quad[0].0);
            if face.dot(quad[0].1) < 0.0 {
                quad.reverse();
            }
            for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
                triangles.push(Triangle {
                    p: [quad[a].0, quad[b].0, quad[c].0],
                    n: Some([quad[a].1, quad[b].1, quad[c].1]),
                    material,
                });
            }
        }
    }
    Mesh::new(triangles)
}

/// The point and normal of the smooth torus at the angles `u` (around the axis) and `v`
/// (around the tube), in the scene.
fn smooth_torus(u: f32, v: f32) -> (Vec3, Vec3) {
    let n = Vec3::new(v.cos() * u.cos(), v.sin(), v.cos() * u.sin());
    let centre = Vec3::new(RADII.0 * u.cos(), 0.0, RADII.0 * u.sin());
    (centre + RADII.1 * n + TORUS_OFFSET, n)
}

/// The point and normal of the smooth torus at the angles of the mesh point `p`.
fn smooth_torus_at(p: Vec3) -> (Vec3, Vec3) {
    let q = p - TORUS_OFFSET;
    smooth_torus(q.z.atan2(q.x), q.y.atan2(q.x.hypot(q.z) - RADII.0))
}

/// A surface that casts no shadow: shadow rays pass through it.
struct Shadowless<S>(S);

impl<S: Surface> Surface for Shadowless<S> {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.0.intersect(ray)
    }

    fn occluded(&self, _: &Ray) -> bool {
        false
    }

    fn bounds(&self) -> Aabb {
        self.0.bounds()
    }
}

/// The `lights` scene with its torus from `assets/torus.obj`, wrapped by `wrap`, lit by the
/// point light and the sun only (the sphere light dark, no environment).
fn scene<S: Surface + 'static>(wrap: impl FnOnce(Mesh) -> S) -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/raytracer/assets/torus.obj");
    let mut scene = lights::build_with(W as f32 / H as f32, |m| {
        Mesh::load_obj(&path, 1.0, TORUS_OFFSET, m).map(wrap)
    })
    .unwrap();
    delta_lights_only(&mut scene);
    scene
}

/// Turns off every light but the point light and the sun.
fn delta_lights_only(scene: &mut Scene) {
    for light in &mut scene.lights {
        if let Light::Sphere { radiance, .. } = light {
            *radiance = Vec3::ZERO;
        }
    }
    if let Some((index, _)) = scene.environment.take() {
        scene.lights.remove(index);
    }
    scene.irradiance = None;
}

/// The centre of pixel `(x, y)` on the film.
fn centre(x: u32, y: u32) -> Vec2 {
    Vec2::new((x as f32 + 0.5) / W as f32, (y as f32 + 0.5) / H as f32)
}

/// The patch: the torus pixels where, at the pixel's centre, the renderer without the fix
/// cuts the light of the point light or the sun (in front of the shading normal, so
/// `eval > 0`), and the renderer with it does not.
fn patch(scene: &Scene) -> Vec<(u32, u32)> {
    let lit = |hit: &Hit, wo: Vec3, fix: bool, light: &Light| {
        let sp = ShadingPoint::new(scene.material(hit.material), hit, wo, fix);
        light.sample(sp.p, Vec2::splat(0.5)).is_some_and(|ls| {
            let wi = sp.frame.to_local(ls.wi);
            sp.light_direction(ls.wi, wi).is_some()
                && sp.material.bsdf.eval(sp.wo, wi) != Vec3::ZERO
                && ls
                    .shadow_ray(sp.shadow_origin(ls.wi), sp.ng)
                    .is_some_and(|r| !scene.occluded(&r))
        })
    };
    let mut pixels = Vec::new();
    for y in 0..H {
        for x in 0..W {
            let ray = scene.camera.ray(centre(x, y));
            let Some(hit) = scene.intersect(&ray).filter(|h| h.material == TORUS) else {
                continue;
            };
            if scene
                .lights
                .iter()
                .filter(|l| matches!(l, Light::Point { .. } | Light::Directional { .. }))
                .any(|l| !lit(&hit, -ray.dir, false, l) && lit(&hit, -ray.dir, true, l))
            {
                pixels.push((x, y));
            }
        }
    }
    pixels
}

/// Every pixel's mean luminance of direct light over its samples whose camera ray hits the
/// torus (the same random numbers as `render::sample_pixel`), or `None` if none does.
fn direct_light(scene: &Scene, pixels: &[(u32, u32)]) -> Vec<Option<f64>> {
    let integrator = Integrator::Path(PathTracer {
        max_depth: 1,
        filter: None,
        irradiance: false,
        clamp: None,
        roulette: true,
    });
    let settings = RenderSettings {
        width: W,
        height: H,
        spp: SPP,
        seed: 7,
    };
    pixels
        .par_iter()
        .map(|&(x, y)| {
            let mut rng = rng_for(&settings, x, y);
            let (mut sum, mut n) = (0.0, 0);
            for _ in 0..SPP {
                let jitter = rng.next_vec2();
                let film = Vec2::new(
                    (x as f32 + jitter.x) / W as f32,
                    (y as f32 + jitter.y) / H as f32,
                );
                let ray = scene.camera.ray(film);
                let on_torus = scene.intersect(&ray).is_some_and(|h| h.material == TORUS);
                let l = integrator.radiance(scene, ray, &mut rng);
                if on_torus {
                    sum += f64::from(l.dot(LUMINANCE));
                    n += 1;
                }
            }
            (n > 0).then(|| sum / f64::from(n))
        })
        .collect()
}

#[test]
fn the_coarse_torus_has_no_terminator_patch() {
    let mut fixed = scene(|m| m);
    let pixels = patch(&fixed);
    println!("patch: {} pixels", pixels.len());
    assert!(pixels.len() >= 100, "the case is there: {}", pixels.len());

    // The reference is right where the smooth torus does not shadow itself: from its point
    // at each patch pixel's centre, no shadow ray toward a light it faces is blocked by a
    // tessellation with 8 × the segments each way (1.9° and 5.6° per facet).
    let mut fine = lights::build_with(W as f32 / H as f32, |m| Ok(torus(192, 64, m))).unwrap();
    delta_lights_only(&mut fine);
    let (mut rays, mut blocked) = (0, 0);
    for &(x, y) in &pixels {
        let hit = fixed.intersect(&fixed.camera.ray(centre(x, y))).unwrap();
        let (p, n) = smooth_torus_at(hit.p);
        for light in &fine.lights {
            let Some(ls) = light.sample(p, Vec2::ZERO) else {
                continue;
            };
            if ls.delta && ls.wi.dot(n) > 0.0 {
                rays += 1;
                blocked += usize::from(ls.shadow_ray(p, n).is_none_or(|r| fine.occluded(&r)));
            }
        }
    }
    println!("smooth torus: {blocked} of {rays} shadow rays from the patch blocked");
    assert!(rays >= pixels.len() && blocked == 0);

    let reference = direct_light(&scene(Shadowless), &pixels);
    let with_fix = direct_light(&fixed, &pixels);
    fixed.terminator_fix = false;
    let without = direct_light(&fixed, &pixels);

    // The light each render loses against the reference, over the patch.
    let (mut total, mut lost_with, mut lost_without) = (0.0, 0.0, 0.0);
    let (mut darker_with, mut darker_without) = (0, 0);
    for ((r, a), b) in reference.iter().zip(&with_fix).zip(&without) {
        let (Some(r), Some(a), Some(b)) = (r, a, b) else {
            continue;
        };
        assert!(
            a <= r && b <= r,
            "the torus's own shadow only takes light away"
        );
        total += r;
        lost_with += r - a;
        lost_without += r - b;
        darker_with += usize::from(a < r);
        darker_without += usize::from(b < r);
    }
    println!(
        "light lost in the patch: {:.2}% without the fix ({darker_without} pixels darker), \
         {:.3}% with it ({darker_with} pixels darker): the fix gives back {:.1}% of it",
        100.0 * lost_without / total,
        100.0 * lost_with / total,
        100.0 * (1.0 - lost_with / lost_without),
    );
    // Without the fix, the patch is the artefact: a sizeable share of its light is cut.
    assert!(lost_without > 0.05 * total);
    // With it, what is left (where Hanika's point meets the flat facet, at the vertices) is
    // under a tenth of that, an order of magnitude.
    assert!(lost_with < 0.1 * lost_without);
}
