//! Parallelograms ("quads"); a large one is the floor plane.

use crate::aabb::Aabb;
use crate::ray::Ray;
use crate::surface::{Hit, MaterialId, Surface};
use lobe::Vec3;

/// The parallelogram `corner + a u + b v`, `a, b ∈ [0, 1]`, with normal `u × v` normalised.
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    /// One corner.
    pub corner: Vec3,
    /// The first edge.
    pub u: Vec3,
    /// The second edge.
    pub v: Vec3,
    /// The unit normal `u × v / |u × v|`.
    pub normal: Vec3,
    /// `n / (n · n)` with `n = u × v`, for the barycentric solve.
    w: Vec3,
    /// The material.
    pub material: MaterialId,
    /// The area light the quad is, if it emits.
    pub light: Option<u32>,
}

impl Quad {
    /// The quad with corner `corner` and edges `u`, `v` (facing `u × v`); `None` when the
    /// edges are parallel or not finite.
    pub fn new(corner: Vec3, u: Vec3, v: Vec3, material: MaterialId) -> Option<Self> {
        let n = u.cross(v);
        let len2 = n.length_squared();
        if !(len2 > 0.0) || !len2.is_finite() {
            return None;
        }
        Some(Self {
            corner,
            u,
            v,
            normal: n / len2.sqrt(),
            w: n / len2,
            material,
            light: None,
        })
    }

    /// The area `|u × v|`.
    pub fn area(&self) -> f32 {
        self.u.cross(self.v).length()
    }

    /// The point at parameters `(a, b) ∈ [0, 1]²`.
    pub fn point(&self, a: f32, b: f32) -> Vec3 {
        self.corner + a * self.u + b * self.v
    }

    /// The hit of the ray with the quad, and its parameters `(a, b)`.
    #[inline]
    pub fn intersect_params(&self, ray: &Ray) -> Option<(Hit, f32, f32)> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = self.normal.dot(self.corner - ray.origin) / denom;
        if !ray.contains(t) {
            return None;
        }
        let p = ray.at(t);
        let planar = p - self.corner;
        let a = self.w.dot(planar.cross(self.v));
        let b = self.w.dot(self.u.cross(planar));
        if !((0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b)) {
            return None;
        }
        let hit = Hit {
            t,
            p,
            p_shadow: p,
            bend: 0.0,
            ng: self.normal,
            ns: self.normal,
            tangent: self.u,
            material: self.material,
            light: self.light,
        };
        Some((hit, a, b))
    }
}

impl Surface for Quad {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.intersect_params(ray).map(|(hit, _, _)| hit)
    }

    fn bounds(&self) -> Aabb {
        let c = [
            self.corner,
            self.corner + self.u,
            self.corner + self.v,
            self.corner + self.u + self.v,
        ];
        Aabb::from_points(&c).padded(1e-4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_inside_and_misses_outside() {
        let q = Quad::new(Vec3::ZERO, Vec3::X, Vec3::Z, 0).unwrap();
        assert!((q.normal - -Vec3::Y).length() < 1e-6);
        let down = Ray::new(Vec3::new(0.5, 1.0, 0.5), -Vec3::Y);
        let h = q.intersect(&down).unwrap();
        assert!((h.t - 1.0).abs() < 1e-6);
        let outside = Ray::new(Vec3::new(1.5, 1.0, 0.5), -Vec3::Y);
        assert!(q.intersect(&outside).is_none());
        assert!((q.area() - 1.0).abs() < 1e-6);
        assert!(Quad::new(Vec3::ZERO, Vec3::X, Vec3::X, 0).is_none());
    }
}
