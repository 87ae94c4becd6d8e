//! The path tracer: an unbiased estimate of the rendering equation with next-event
//! estimation, multiple importance sampling and Russian roulette.

use crate::heckbert::{DIFFUSE, PathFilter, SPECULAR};
use crate::light::Light;
use crate::ray::{Ray, offset_origin};
use crate::scene::Scene;
use crate::shading::ShadingPoint;
use lobe::Vec3;
use lobe::bxdf::Lobes;
use lobe::sampling::power_heuristic;
use lobe::verify::Pcg32;

/// The number of bounces after which Russian roulette may end a path.
const ROULETTE_DEPTH: u32 = 3;

/// Unidirectional path tracing from the camera (Kajiya 1986; PBR 4th ed. §13.4).
///
/// At every vertex with a non-delta lobe, each light is sampled once (next-event
/// estimation) and the BSDF once; both estimates of the light are combined with the power
/// heuristic (Veach 1997, §9.2), using each model's `eval`, `sample` and `pdf`. Delta lobes
/// (`BxdfSample::is_specular`) are reached only by sampling: no light sampling through
/// them, and the light they find counts in full. After [`ROULETTE_DEPTH`] bounces a path
/// survives with probability `min(1, max(β η²))` and is reweighted (unbiased); `η²` undoes
/// the radiance scaling of refraction, so that paths in glass are not killed for it.
///
/// **Irradiance shading** (`irradiance`, `--shading irradiance`): at a vertex of a purely
/// diffuse model, the environment's light is not sampled but read from the scene's order-3
/// irradiance `E(n)` (Ramamoorthi & Hanrahan 2001): the vertex adds `β a/π E(n)`, with `a`
/// the model's albedo at normal incidence (exact for Lambert, the usual diffuse
/// approximation for the others) and `n` the shading normal, and neither next-event
/// estimation nor the BSDF sample that escapes from it counts the environment again. It is
/// unshadowed (the environment's occlusion by the scene is lost) and noise-free; every
/// other light, every other model and all interreflection are traced as before.
///
/// **Clamping** (`clamp`, `--clamp X`, off by default): every contribution of *indirect*
/// light — light a path finds after a diffuse or glossy bounce that is not its last
/// scattering vertex, as in a caustic on a floor (floor, then glass, then the light) — is
/// scaled down so that its largest channel is at most `X` ([`clamp_contribution`]). Those are
/// the rare bright paths that make fireflies. Direct light, and light seen directly through
/// mirrors and smooth glass (the highlights of the area light, say), is never clamped.
/// Biased: the light taken away is real, so the image converges to something darker than
/// the truth wherever such paths carry it.
#[derive(Clone, Debug)]
pub struct PathTracer {
    /// The most scattering vertices on a path.
    pub max_depth: u32,
    /// Keep only the contributions of paths that match.
    pub filter: Option<PathFilter>,
    /// Light diffuse models by the environment's SH irradiance instead of sampling it.
    pub irradiance: bool,
    /// Clamp each contribution of indirect light to this (biased); `None`: off.
    pub clamp: Option<f32>,
    /// Russian roulette after [`ROULETTE_DEPTH`] bounces (on in every render; off only to test
    /// that it is unbiased, `furnace_tests`).
    pub roulette: bool,
}

/// What the previous vertex's BSDF sample needs to say for MIS at the next hit.
struct Previous {
    /// The point the sample was drawn at.
    p: Vec3,
    /// The sample's solid-angle density.
    pdf: f32,
    /// True for a delta lobe (and for the camera): the light found counts in full.
    specular: bool,
    /// True when the vertex took its environment light from `E(n)`: the environment the
    /// sample finds was counted already.
    environment_done: bool,
    /// True when a vertex before this one took a diffuse or glossy sample: the light found
    /// by this vertex's sample is indirect (see [`PathTracer::clamp`]).
    rough_before: bool,
}

impl PathTracer {
    /// The radiance arriving at the camera along `ray`: one sample of the estimator.
    pub fn radiance(&self, scene: &Scene, mut ray: Ray, rng: &mut Pcg32) -> Vec3 {
        let mut l = Vec3::ZERO;
        let mut beta = Vec3::ONE;
        let mut eta_scale = 1.0_f32;
        // The camera path's vertex labels, eye first; kept only for a filter.
        let mut labels: Vec<u8> = Vec::new();
        let mut prev = Previous {
            p: ray.origin,
            pdf: 0.0,
            specular: true,
            environment_done: false,
            rough_before: false,
        };
        // True once a vertex has taken a diffuse or glossy sample: the light later vertices
        // scatter is indirect.
        let mut rough = false;
        let mut depth = 0;
        loop {
            let Some(hit) = scene.intersect(&ray) else {
                if let Some((_, env)) = scene.environment.filter(|_| !prev.environment_done) {
                    let w = mis_weight(&prev, env.pdf(ray.dir));
                    let c = beta * env.radiance(ray.dir) * w;
                    self.add(&mut l, self.limit(c, prev.rough_before), None, &labels);
                }
                break;
            };
            if let Some(index) = hit.light {
                let light = &scene.lights[index as usize];
                let le = light.emitted(hit.ng, -ray.dir);
                if le != Vec3::ZERO {
                    let w = mis_weight(&prev, light.pdf_hit(prev.p, hit.p, hit.ng));
                    let c = self.limit(beta * le * w, prev.rough_before);
                    self.add(&mut l, c, None, &labels);
                }
            }
            if depth >= self.max_depth {
                break;
            }
            let sp = ShadingPoint::new(
                scene.material(hit.material),
                &hit,
                -ray.dir,
                scene.terminator_fix,
            );
            let bsdf = &sp.material.bsdf;

            // Next-event estimation, through the non-delta lobes only. The random numbers
            // are drawn whatever the filter says, so that filtered renders use the same
            // paths as the full one (their images add up to it).
            let nee = sp.material.lobes.is_non_specular() && self.allows(Some(DIFFUSE), &labels);
            let by_irradiance = match scene.irradiance {
                Some(e) if self.irradiance && sp.material.lobes == Lobes::DIFFUSE_REFLECTION => {
                    let c = beta * sp.material.ambient * e.eval(sp.frame.z).max(Vec3::ZERO);
                    self.add(
                        &mut l,
                        self.limit(c * core::f32::consts::FRAC_1_PI, rough),
                        Some(DIFFUSE),
                        &labels,
                    );
                    true
                }
                _ => false,
            };
            for light in &scene.lights {
                let u = rng.next_vec2();
                if nee && !(by_irradiance && matches!(light, Light::Environment(_))) {
                    let Some(ls) = light.sample(sp.p, u) else {
                        continue;
                    };
                    let wi = sp.frame.to_local(ls.wi);
                    let Some(mis) = sp.light_direction(ls.wi, wi) else {
                        continue;
                    };
                    let f = bsdf.eval(sp.wo, wi);
                    if f == Vec3::ZERO || ls.li == Vec3::ZERO {
                        continue;
                    }
                    match ls.shadow_ray(sp.shadow_origin(ls.wi), sp.ng) {
                        Some(shadow) if !scene.occluded(&shadow) => {}
                        _ => continue,
                    }
                    // Without MIS where the BSDF sample would be dropped (below the facet).
                    let w = if ls.delta || !mis {
                        1.0
                    } else {
                        power_heuristic(1.0, ls.pdf, 1.0, bsdf.pdf(sp.wo, wi))
                    };
                    l += self.limit(beta * f * ls.li * (wi.z.abs() * w / ls.pdf), rough);
                }
            }

            // Continue the path by sampling the BSDF.
            let Some(s) = bsdf.sample(sp.wo, rng.next_vec2(), rng.next_f32()) else {
                break;
            };
            let wi = sp.frame.to_world(s.wi);
            if !(s.pdf > 0.0) || !sp.consistent(wi, s.wi) {
                break;
            }
            beta *= s.weight();
            if !beta.is_finite() || beta == Vec3::ZERO {
                break;
            }
            if s.lobe.is_transmissive() {
                eta_scale *= s.eta * s.eta;
            }
            if self.filter.is_some() {
                labels.push(if s.is_specular() { SPECULAR } else { DIFFUSE });
            }
            prev = Previous {
                p: sp.p,
                pdf: s.pdf,
                specular: s.is_specular(),
                environment_done: by_irradiance,
                rough_before: rough,
            };
            rough |= !s.is_specular();
            ray = Ray::new(offset_origin(sp.p, sp.ng, wi), wi);
            depth += 1;

            if self.roulette && depth >= ROULETTE_DEPTH {
                let survive = (beta * eta_scale).max_element().min(1.0);
                if !(rng.next_f32() < survive) {
                    break;
                }
                beta /= survive;
            }
        }
        l
    }

    /// The contribution `c`, clamped if it is indirect light and a clamp is set.
    #[inline]
    fn limit(&self, c: Vec3, indirect: bool) -> Vec3 {
        match self.clamp {
            Some(max) if indirect => clamp_contribution(c, max),
            _ => c,
        }
    }

    /// True when the filter (if any) accepts a path ending `last`, then `labels` reversed.
    #[inline]
    fn allows(&self, last: Option<u8>, labels: &[u8]) -> bool {
        self.filter.as_ref().is_none_or(|f| f.accepts(last, labels))
    }

    /// Adds the contribution `c` of the path `L`, `last`, `labels` reversed, `E`, if the
    /// filter accepts it.
    #[inline]
    fn add(&self, l: &mut Vec3, c: Vec3, last: Option<u8>, labels: &[u8]) {
        if self.allows(last, labels) {
            *l += c;
        }
    }
}

/// `c` scaled down, if need be, so that its largest channel is at most `max` (the hue is
/// kept, as with pbrt-v4's `maxcomponentvalue`); a non-finite `c` is returned as it is (the
/// render counts and drops it).
#[inline]
pub fn clamp_contribution(c: Vec3, max: f32) -> Vec3 {
    let m = c.max_element();
    if m > max && c.is_finite() {
        c * (max / m)
    } else {
        c
    }
}

/// The MIS weight of light found by a BSDF sample, against the light's own sampling density
/// `light_pdf` for that direction; `1` after a delta lobe or the camera.
#[inline]
fn mis_weight(prev: &Previous, light_pdf: f32) -> f32 {
    if prev.specular {
        1.0
    } else {
        power_heuristic(1.0, prev.pdf, 1.0, light_pdf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::Integrator;
    use crate::render::{RenderSettings, render};
    use crate::scenes::SceneChoice;

    #[test]
    fn clamping_keeps_the_hue_and_leaves_small_contributions_alone() {
        let c = Vec3::new(40.0, 20.0, 10.0);
        assert_eq!(clamp_contribution(c, 8.0), Vec3::new(8.0, 4.0, 2.0));
        assert_eq!(clamp_contribution(c, 40.0), c);
        assert_eq!(clamp_contribution(Vec3::splat(0.5), 1.0), Vec3::splat(0.5));
        let bad = Vec3::new(f32::INFINITY, 1.0, 1.0);
        assert!(
            !clamp_contribution(bad, 1.0).is_finite(),
            "left for the render to drop"
        );
    }

    /// The default scene (19 materials, glass included), 32 × 18 at 8 spp.
    fn default_scene(clamp: Option<f32>, filter: Option<&str>) -> Vec<Vec3> {
        let (scene, _) = SceneChoice::Default.build(16.0 / 9.0).unwrap();
        let integrator = Integrator::Path(PathTracer {
            max_depth: 12,
            filter: filter.map(|f| PathFilter::parse(f).unwrap()),
            irradiance: false,
            clamp,
            roulette: true,
        });
        let settings = RenderSettings {
            width: 32,
            height: 18,
            spp: 8,
            seed: 4,
        };
        render(&scene, &integrator, &settings, false).pixels
    }

    /// The clamp takes exactly the indirect light: clamped to (nearly) nothing, the render
    /// is the one that keeps only the paths without a diffuse or glossy bounce before their
    /// last scattering vertex, `L (D|S)? S* E` in Heckbert's notation (same random numbers;
    /// each clamped contribution leaves at most 1e-30 behind). A clamp no contribution
    /// reaches changes nothing, to the bit.
    #[test]
    fn the_clamp_takes_the_indirect_light_only() {
        let unclamped = default_scene(None, None);
        let direct = default_scene(None, Some("L (D|S)? S* E"));
        let nothing_left = default_scene(Some(1e-30), None);
        let mut indirect = 0.0;
        for ((a, b), full) in nothing_left.iter().zip(&direct).zip(&unclamped) {
            assert!((*a - *b).abs().max_element() <= 1e-25, "{a} vs {b}");
            indirect += (*full - *b).element_sum();
        }
        assert!(indirect > 0.0, "the scene has indirect light to clamp");
        assert_eq!(default_scene(Some(f32::MAX), None), unclamped);
    }
}
