//! The Whitted integrator: the handout's shading, with recursive mirror reflection and
//! refraction.

use crate::heckbert::{DIFFUSE, PathFilter, SPECULAR};
use crate::light::Light;
use crate::material::Interface;
use crate::ray::{Ray, offset_origin};
use crate::scene::Scene;
use crate::shading::ShadingPoint;
use core::f32::consts::FRAC_1_PI;
use lobe::Vec3;
use lobe::bxdf::Lobes;
use lobe::frame::refract_away;
use lobe::fresnel;
use lobe::verify::Pcg32;

/// Recursive rays whose contribution to the pixel falls below this are not traced.
const MIN_THROUGHPUT: f32 = 1e-3;

/// Whitted-style ray tracing (Whitted 1980; seed 003, "Ray Tracing: shading"):
///
/// ```text
/// L = L_a ρ_a + Σ_lights f(wo, wi) L_i |cos θi| / pdf  [unoccluded]  + recursion
/// ```
///
/// The ambient term is the environment's mean radiance times the material's non-delta
/// albedo; every light but the environment is sampled once with a shadow ray (an area
/// light by one random point, so that soft shadows converge over the pixel samples); then
/// the material's [`Interface`] spawns a mirror ray weighted by the exact Fresnel
/// reflectance `F` (`lobe::fresnel`), and a refracted ray weighted by `1 − F`, up to
/// `max_depth`, or until a ray's share of the pixel falls below 0.1%. Rough glass is traced as smooth glass; refracted radiance is not rescaled
/// by `η²` (it cancels on leaving a closed object). Paths are labelled for the filter like
/// the path tracer's: direct and ambient light as `L D …`, recursion as `S`.
///
/// With `irradiance` (`--shading irradiance`), a purely diffuse model's ambient term is the
/// environment's order-3 irradiance instead of its mean: `a/π E(n)` at the shading normal
/// (Ramamoorthi & Hanrahan 2001), the use irradiance environment maps were made for.
#[derive(Clone, Debug)]
pub struct Whitted {
    /// The deepest recursion.
    pub max_depth: u32,
    /// Keep only the contributions of paths that match.
    pub filter: Option<PathFilter>,
    /// Diffuse models' ambient term from the environment's SH irradiance.
    pub irradiance: bool,
}

impl Whitted {
    /// The radiance arriving at the camera along `ray`.
    pub fn radiance(&self, scene: &Scene, ray: Ray, rng: &mut Pcg32) -> Vec3 {
        let mut labels = Vec::new();
        self.trace(scene, ray, 0, Vec3::ONE, &mut labels, rng)
    }

    /// The radiance along `ray`, a recursive ray of depth `depth` whose contribution to the
    /// pixel is scaled by `throughput`.
    fn trace(
        &self,
        scene: &Scene,
        ray: Ray,
        depth: u32,
        throughput: Vec3,
        labels: &mut Vec<u8>,
        rng: &mut Pcg32,
    ) -> Vec3 {
        let Some(hit) = scene.intersect(&ray) else {
            let background = scene
                .environment
                .map_or(Vec3::ZERO, |(_, e)| e.radiance(ray.dir));
            return self.keep(background, None, labels);
        };
        if let Some(index) = hit.light {
            let le = scene.lights[index as usize].emitted(hit.ng, -ray.dir);
            return self.keep(le, None, labels);
        }
        let sp = ShadingPoint::new(
            scene.material(hit.material),
            &hit,
            -ray.dir,
            scene.terminator_fix,
        );
        let mut c = match scene.irradiance {
            Some(e) if self.irradiance && sp.material.lobes == Lobes::DIFFUSE_REFLECTION => {
                sp.material.ambient * e.eval(sp.frame.z).max(Vec3::ZERO) * FRAC_1_PI
            }
            _ => scene.ambient * sp.material.ambient,
        };
        // Glass is traced as smooth glass: its interface's rays carry all its light, and the
        // model's own value (rough glass's glossy lobe) would show each light a second time.
        let traced = matches!(
            sp.material.interface,
            Interface::Dielectric(_) | Interface::Thin(_)
        );
        for light in scene.lights.iter().filter(|_| !traced) {
            if matches!(light, Light::Environment(_)) {
                continue; // the ambient term stands for it
            }
            let Some(ls) = light.sample(sp.p, rng.next_vec2()) else {
                continue;
            };
            let wi = sp.frame.to_local(ls.wi);
            if sp.light_direction(ls.wi, wi).is_none() {
                continue;
            }
            match ls.shadow_ray(sp.shadow_origin(ls.wi), sp.ng) {
                Some(shadow) if !scene.occluded(&shadow) => {}
                _ => continue,
            }
            c += sp.material.bsdf.eval(sp.wo, wi) * ls.li * (wi.z.abs() / ls.pdf);
        }
        let mut l = self.keep(c, Some(DIFFUSE), labels);
        if depth >= self.max_depth {
            return l;
        }
        let wo = sp.wo;
        let mirror = sp.frame.to_world(Vec3::new(-wo.x, -wo.y, wo.z));
        // Glass spawns two rays per hit: prune the tree where a ray's share of the pixel is
        // negligible (Hall & Greenberg 1983, adaptive tree-depth control).
        let mut spawn = |w: Vec3, weight: Vec3, labels: &mut Vec<u8>| {
            if (throughput * weight).max_element() < MIN_THROUGHPUT {
                return Vec3::ZERO;
            }
            labels.push(SPECULAR);
            let r = Ray::new(offset_origin(sp.p, sp.ng, w), w);
            let li = self.trace(scene, r, depth + 1, throughput * weight, labels, rng);
            labels.pop();
            weight * li
        };
        match sp.material.interface {
            Interface::None => {}
            Interface::Conductor(ior) => {
                l += spawn(mirror, fresnel::conductor(wo.z.abs(), &ior), labels);
            }
            Interface::Coat(eta) => {
                let f = fresnel::dielectric(wo.z, eta);
                l += spawn(mirror, Vec3::splat(f), labels);
            }
            Interface::Thin(sheet) => {
                let r = sheet.reflectance(wo.z);
                l += spawn(mirror, Vec3::splat(r), labels);
                l += spawn(-sp.frame.to_world(wo), Vec3::splat(1.0 - r), labels);
            }
            Interface::Dielectric(eta) => {
                let f = fresnel::dielectric(wo.z, eta);
                l += spawn(mirror, Vec3::splat(f), labels);
                if let Some(t) = refract_away(wo, Vec3::Z, eta) {
                    l += spawn(sp.frame.to_world(t), Vec3::splat(1.0 - f), labels);
                }
            }
        }
        l
    }

    /// `c` if the filter (if any) accepts the path `L`, `last`, `labels` reversed, `E`.
    fn keep(&self, c: Vec3, last: Option<u8>, labels: &[u8]) -> Vec3 {
        match &self.filter {
            Some(f) if !f.accepts(last, labels) => Vec3::ZERO,
            _ => c,
        }
    }
}
