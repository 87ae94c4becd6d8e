//! Axis-aligned bounding boxes, the bricks of the BVH.

use lobe::Vec3;

/// An axis-aligned box `[min, max]`; the empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The lower corner.
    pub min: Vec3,
    /// The upper corner.
    pub max: Vec3,
}

impl Aabb {
    /// The empty box: the identity of [`Aabb::union`].
    pub const EMPTY: Self = Self {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    /// The smallest box holding every point of `points`.
    pub fn from_points(points: &[Vec3]) -> Self {
        points.iter().fold(Self::EMPTY, |b, &p| Self {
            min: b.min.min(p),
            max: b.max.max(p),
        })
    }

    /// The smallest box holding both boxes.
    pub fn union(self, other: Self) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The centre of the box.
    pub fn centroid(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// The box grown by `pad` on every side (keeps flat boxes from being degenerate).
    pub fn padded(self, pad: f32) -> Self {
        Self {
            min: self.min - Vec3::splat(pad),
            max: self.max + Vec3::splat(pad),
        }
    }

    /// The ray-box slab test: true when the ray `origin + t dir` (with `inv_dir = 1/dir`)
    /// meets the box for some `t` in `(t_min, t_max)`. IEEE infinities in `inv_dir` make
    /// axis-parallel rays work (Williams et al. 2005, "An efficient and robust ray-box
    /// intersection algorithm").
    #[inline]
    pub fn hit(&self, origin: Vec3, inv_dir: Vec3, t_min: f32, t_max: f32) -> bool {
        let t0 = (self.min - origin) * inv_dir;
        let t1 = (self.max - origin) * inv_dir;
        // `min`/`max` of glam ignore a NaN operand (0 · ∞ on a slab boundary), which keeps
        // the other bound.
        let near = t0.min(t1).max_element().max(t_min);
        let far = t0.max(t1).min_element().min(t_max);
        near <= far
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slab_test_hits_and_misses() {
        let b = Aabb::from_points(&[Vec3::ZERO, Vec3::ONE]);
        let o = Vec3::new(0.5, 0.5, -1.0);
        let inv = Vec3::ONE / Vec3::Z;
        assert!(b.hit(o, inv, 0.0, f32::INFINITY));
        assert!(!b.hit(o, inv, 0.0, 0.5));
        let inv_away = Vec3::ONE / -Vec3::Z;
        assert!(!b.hit(o, inv_away, 0.0, f32::INFINITY));
        assert_eq!(b.centroid(), Vec3::splat(0.5));
    }
}
