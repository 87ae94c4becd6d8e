//! Spheres.

use crate::aabb::Aabb;
use crate::ray::Ray;
use crate::surface::{Hit, MaterialId, Surface};
use lobe::Vec3;

/// A sphere with outward normals.
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    /// The centre.
    pub center: Vec3,
    /// The radius, positive.
    pub radius: f32,
    /// The material.
    pub material: MaterialId,
    /// The area light the sphere is, if it emits.
    pub light: Option<u32>,
}

impl Sphere {
    /// A sphere of material `material` that does not emit.
    pub fn new(center: Vec3, radius: f32, material: MaterialId) -> Self {
        Self {
            center,
            radius,
            material,
            light: None,
        }
    }

    /// The two ray parameters where the ray's line meets the sphere, nearest first.
    ///
    /// The discriminant is computed as `r² − |f − (f·d) d|²` (f = o − c) rather than
    /// `b² − c`, which cancels catastrophically for small spheres far away (Haines et al.,
    /// *Ray Tracing Gems*, ch. 7); the roots come from the stable form of the quadratic.
    #[inline]
    fn roots(&self, ray: &Ray) -> Option<(f32, f32)> {
        let f = ray.origin - self.center;
        let b = f.dot(ray.dir);
        let perp = f - b * ray.dir;
        let disc = self.radius * self.radius - perp.length_squared();
        if disc < 0.0 {
            return None;
        }
        let c = f.length_squared() - self.radius * self.radius;
        let q = -b - disc.sqrt().copysign(b);
        if q == 0.0 {
            return Some((0.0, 0.0));
        }
        let (t0, t1) = (c / q, q);
        Some(if t0 <= t1 { (t0, t1) } else { (t1, t0) })
    }
}

impl Surface for Sphere {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let (t0, t1) = self.roots(ray)?;
        let t = if ray.contains(t0) {
            t0
        } else if ray.contains(t1) {
            t1
        } else {
            return None;
        };
        let p = ray.at(t);
        let n = ((p - self.center) / self.radius).normalize_or(Vec3::Y);
        Some(Hit {
            t,
            p,
            p_shadow: p,
            bend: 0.0,
            ng: n,
            ns: n,
            // ∂p/∂φ around the y axis: the direction of the lines of latitude.
            tangent: Vec3::new(-n.z, 0.0, n.x),
            material: self.material,
            light: self.light,
        })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.roots(ray)
            .is_some_and(|(t0, t1)| ray.contains(t0) || ray.contains(t1))
    }

    fn bounds(&self) -> Aabb {
        Aabb {
            min: self.center - Vec3::splat(self.radius),
            max: self.center + Vec3::splat(self.radius),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_front_then_back() {
        let s = Sphere::new(Vec3::ZERO, 1.0, 0);
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        let h = s.intersect(&ray).unwrap();
        assert!((h.t - 4.0).abs() < 1e-5);
        assert!((h.ng - -Vec3::Z).length() < 1e-5);
        let inside = Ray::new(Vec3::ZERO, Vec3::Z);
        let h = s.intersect(&inside).unwrap();
        assert!((h.t - 1.0).abs() < 1e-5);
        assert!((h.ng - Vec3::Z).length() < 1e-5, "the normal stays outward");
    }

    #[test]
    fn small_far_sphere_is_hit_precisely() {
        let s = Sphere::new(Vec3::new(0.0, 0.0, 1e4), 0.01, 0);
        let h = s.intersect(&Ray::new(Vec3::ZERO, Vec3::Z)).unwrap();
        assert!((h.p.z - (1e4 - 0.01)).abs() < 2e-3);
        let miss = Ray::new(Vec3::new(0.02, 0.0, 0.0), Vec3::Z);
        assert!(s.intersect(&miss).is_none());
    }
}
