//! Lights: point, directional, spherical and quadrilateral area lights, and the environment.

use crate::environment::Environment;
use crate::quad::Quad;
use crate::ray::{Ray, offset_origin, shadow_ray};
use lobe::sampling::{uniform_cone_of_width, uniform_cone_pdf_of_width};
use lobe::{Frame, Vec2, Vec3};

/// A light source (seed 003: point, directional, area and environment sources).
#[derive(Clone, Copy, Debug)]
pub enum Light {
    /// An isotropic point source of intensity `I`: irradiance `I cos θ / r²` (seed 003,
    /// "Irradiance from isotropic point source").
    Point {
        /// The position.
        position: Vec3,
        /// The radiant intensity (W/sr per channel).
        intensity: Vec3,
    },
    /// A source infinitely far away (the sun): parallel light of irradiance `E` on a
    /// surface facing it.
    Directional {
        /// The unit direction toward the light.
        to_light: Vec3,
        /// The irradiance on a surface facing the light.
        irradiance: Vec3,
    },
    /// A sphere emitting `radiance` outward from its surface, sampled by solid angle.
    Sphere {
        /// The centre.
        center: Vec3,
        /// The radius.
        radius: f32,
        /// The emitted radiance.
        radiance: Vec3,
    },
    /// A parallelogram emitting `radiance` from its front (`u × v`) side, sampled by area.
    Quad {
        /// The geometry.
        quad: Quad,
        /// The emitted radiance.
        radiance: Vec3,
    },
    /// Light from infinitely far away in every direction.
    Environment(Environment),
}

/// A direction toward a light, drawn for next-event estimation.
#[derive(Clone, Copy, Debug)]
pub struct LightSample {
    /// The unit direction from the shaded point toward the light.
    pub wi: Vec3,
    /// The radiance arriving along `wi` (for a delta light, the incident "radiance" that
    /// makes `f Li |cos| / pdf` the right contribution with `pdf = 1`).
    pub li: Vec3,
    /// The solid-angle density of `wi`; `1` for a delta light.
    pub pdf: f32,
    /// True for a light no BSDF sample can hit (point, directional): no MIS.
    pub delta: bool,
    /// What the shadow ray must reach unoccluded.
    pub target: Target,
}

/// The end of a light sample's shadow ray.
#[derive(Clone, Copy, Debug)]
pub enum Target {
    /// A point light's position.
    Point(Vec3),
    /// The point `q` of a quad light, whose normal is `n`.
    Quad {
        /// The point.
        q: Vec3,
        /// The light's normal.
        n: Vec3,
    },
    /// The point `q` of a sphere light.
    Sphere {
        /// The point.
        q: Vec3,
        /// The light's centre.
        center: Vec3,
        /// The light's radius.
        radius: f32,
    },
    /// Infinitely far away along `wi` (the sun, the environment).
    Direction(Vec3),
}

impl LightSample {
    /// The shadow ray that must be unoccluded for the light to arrive: from `from` (the shaded
    /// point, or the point shadow rays start from, [`crate::shading::ShadingPoint::shadow_origin`]),
    /// on the surface of geometric normal `ng`, to the sampled point of the light. `None` when
    /// the two points coincide.
    pub fn shadow_ray(&self, from: Vec3, ng: Vec3) -> Option<Ray> {
        match self.target {
            Target::Point(q) => shadow_ray(from, ng, q, None),
            Target::Quad { q, n } => shadow_ray(from, ng, q, Some(n)),
            Target::Sphere { q, center, radius } => {
                // Seen from `from`, which need not be the point the sample was drawn for,
                // `q` may be just behind the rim: aim at it, but stop where that line first
                // meets the light, so that the light never shadows itself.
                let dir = (q - from).normalize_or_zero();
                let oc = center - from;
                let b = oc.dot(dir);
                let disc = radius * radius - (oc - b * dir).length_squared();
                let t = b - disc.max(0.0).sqrt();
                let q = if t > 0.0 { from + dir * t } else { q };
                shadow_ray(from, ng, q, Some((q - center) / radius))
            }
            Target::Direction(w) => Some(Ray::new(offset_origin(from, ng, w), w)),
        }
    }
}

impl Light {
    /// Draws a direction toward the light from the point `p`, with `u` uniform in `[0, 1)²`;
    /// `None` when the light cannot reach `p` this time.
    pub fn sample(&self, p: Vec3, u: Vec2) -> Option<LightSample> {
        match *self {
            Self::Point {
                position,
                intensity,
            } => {
                let to = position - p;
                let d2 = to.length_squared();
                if !(d2 > 0.0) || !d2.is_finite() {
                    return None;
                }
                Some(LightSample {
                    wi: to / d2.sqrt(),
                    li: intensity / d2,
                    pdf: 1.0,
                    delta: true,
                    target: Target::Point(position),
                })
            }
            Self::Directional {
                to_light,
                irradiance,
            } => Some(LightSample {
                wi: to_light,
                li: irradiance,
                pdf: 1.0,
                delta: true,
                target: Target::Direction(to_light),
            }),
            Self::Sphere {
                center,
                radius,
                radiance,
            } => {
                let to_center = center - p;
                let d2 = to_center.length_squared();
                let r2 = radius * radius;
                if d2 <= r2 * 1.0001 {
                    return None; // inside (or on) the light: it does not light itself
                }
                let d = d2.sqrt();
                let axis = to_center / d;
                let width = cone_width(r2, d2);
                let wi = Frame::from_normal(axis).to_world(uniform_cone_of_width(u, width));
                // The nearer point where `wi` meets the sphere; at the rim, where rounding
                // can make the ray miss, the point of closest approach.
                let b = to_center.dot(wi);
                let disc = r2 - (to_center - b * wi).length_squared();
                let q = p + wi * (b - disc.max(0.0).sqrt());
                Some(LightSample {
                    wi,
                    li: radiance,
                    pdf: uniform_cone_pdf_of_width(width),
                    delta: false,
                    target: Target::Sphere { q, center, radius },
                })
            }
            Self::Quad { quad, radiance } => {
                let q = quad.point(u.x, u.y);
                let to = q - p;
                let d2 = to.length_squared();
                let wi = to / d2.sqrt();
                let cos_l = -wi.dot(quad.normal);
                if !(cos_l > 0.0) {
                    return None; // the back of the light, or grazing
                }
                Some(LightSample {
                    wi,
                    li: radiance,
                    pdf: d2 / (cos_l * quad.area()),
                    delta: false,
                    target: Target::Quad { q, n: quad.normal },
                })
            }
            Self::Environment(env) => {
                let (wi, pdf) = env.sample(u);
                Some(LightSample {
                    wi,
                    li: env.radiance(wi),
                    pdf,
                    delta: false,
                    target: Target::Direction(wi),
                })
            }
        }
    }

    /// The radiance the light emits from its surface point `q` (normal `n`) toward `w`
    /// (unit, pointing away from the light); zero for lights without a surface.
    pub fn emitted(&self, n: Vec3, w: Vec3) -> Vec3 {
        match *self {
            Self::Sphere { radiance, .. } => radiance,
            Self::Quad { radiance, .. } if w.dot(n) > 0.0 => radiance,
            _ => Vec3::ZERO,
        }
    }

    /// The solid-angle density with which [`sample`](Self::sample) from `p` draws the
    /// direction that reaches the light's surface point `q` (normal `n`): for MIS when a
    /// BSDF sample hits the light.
    pub fn pdf_hit(&self, p: Vec3, q: Vec3, n: Vec3) -> f32 {
        match *self {
            Self::Sphere { center, radius, .. } => {
                let d2 = (center - p).length_squared();
                let r2 = radius * radius;
                if d2 <= r2 * 1.0001 {
                    return 0.0;
                }
                uniform_cone_pdf_of_width(cone_width(r2, d2))
            }
            Self::Quad { quad, .. } => {
                let to = q - p;
                let d2 = to.length_squared();
                let cos_l = (to.dot(n) / d2.sqrt()).abs();
                if cos_l > 0.0 {
                    d2 / (cos_l * quad.area())
                } else {
                    0.0
                }
            }
            _ => 0.0,
        }
    }
}

/// `1 − cos θmax` of the cone a sphere of squared radius `r2` subtends from squared distance
/// `d2`, as `s / (1 + √(1 − s))` with `s = sin² θmax = r2/d2`: without the cancellation of
/// `1 − √(1 − s)`, which made small lights too bright (0.9% at `r/d = 1e-3`) and lost those
/// below `r/d ≈ 1.7e-4` (the `f32` cosine rounded to 1).
fn cone_width(r2: f32, d2: f32) -> f32 {
    let s = (r2 / d2).min(1.0);
    s / (1.0 + (1.0 - s).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::Surface;

    #[test]
    fn point_light_falls_off_with_the_square_of_distance() {
        let light = Light::Point {
            position: Vec3::new(0.0, 2.0, 0.0),
            intensity: Vec3::splat(8.0),
        };
        let s = light.sample(Vec3::ZERO, Vec2::ZERO).unwrap();
        assert!((s.li.x - 2.0).abs() < 1e-5 && s.delta);
        assert!((s.wi - Vec3::Y).length() < 1e-6);
    }

    /// The solid angle of a sphere, `2π (1 − cos θmax)`, by integrating `1/pdf`.
    #[test]
    fn sphere_light_pdf_matches_its_samples_and_hits() {
        let light = Light::Sphere {
            center: Vec3::new(0.0, 3.0, 0.0),
            radius: 1.0,
            radiance: Vec3::ONE,
        };
        let sphere = crate::sphere::Sphere::new(Vec3::new(0.0, 3.0, 0.0), 1.0, 0);
        for i in 0..64 {
            let u = Vec2::new((i as f32 + 0.5) / 64.0, (i as f32 * 0.618).fract());
            let s = light.sample(Vec3::ZERO, u).unwrap();
            let hit = sphere.intersect(&Ray::new(Vec3::ZERO, s.wi));
            let hit = hit.expect("a sampled direction reaches the sphere");
            let pdf = light.pdf_hit(Vec3::ZERO, hit.p, hit.ng);
            assert!((pdf - s.pdf).abs() < 1e-4 * s.pdf);
            let shadow = s.shadow_ray(Vec3::ZERO, Vec3::Y).unwrap();
            assert!(shadow.t_max < hit.t);
            // From a point beside the sampled one, the ray still stops short of the light.
            let beside = Vec3::new(0.05, 0.0, 0.0);
            let shadow = s.shadow_ray(beside, Vec3::Y).unwrap();
            assert!(!sphere.occluded(&shadow), "{i}");
        }
    }

    #[test]
    fn quad_light_emits_from_the_front_only() {
        let quad = Quad::new(Vec3::new(-0.5, 2.0, -0.5), Vec3::X, Vec3::Z, 0).unwrap();
        assert!(quad.normal.y < 0.0, "faces down");
        let light = Light::Quad {
            quad,
            radiance: Vec3::ONE,
        };
        let s = light.sample(Vec3::ZERO, Vec2::splat(0.5)).unwrap();
        // Straight below the centre: pdf = d² / (cos · A) = 4.
        assert!((s.pdf - 4.0).abs() < 1e-4);
        assert!(
            (light.pdf_hit(Vec3::ZERO, Vec3::new(0.0, 2.0, 0.0), quad.normal) - 4.0).abs() < 1e-4
        );
        assert_eq!(light.emitted(quad.normal, -Vec3::Y), Vec3::ONE);
        assert_eq!(light.emitted(quad.normal, Vec3::Y), Vec3::ZERO);
        assert!(
            light
                .sample(Vec3::new(0.0, 3.0, 0.0), Vec2::splat(0.5))
                .is_none()
        );
    }
}
