//! The pinhole camera.

use crate::ray::Ray;
use lobe::{Vec2, Vec3};

/// A pinhole camera: rays from one point through an image plane (seed 003,
/// `camera.getRay(ix, iy)`).
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// The pinhole.
    origin: Vec3,
    /// Unit view direction.
    forward: Vec3,
    /// Image-plane x per unit of normalised image coordinate.
    right: Vec3,
    /// Image-plane y per unit of normalised image coordinate.
    up: Vec3,
}

impl Camera {
    /// A camera at `from` looking at `at`, with `up` roughly up, a vertical field of view
    /// of `vfov_deg` degrees and the image aspect ratio `aspect` (width / height).
    pub fn look_at(from: Vec3, at: Vec3, up: Vec3, vfov_deg: f32, aspect: f32) -> Self {
        let forward = (at - from).normalize_or(-Vec3::Z);
        let right = forward.cross(up).normalize_or(Vec3::X);
        let true_up = right.cross(forward);
        let half_h = (0.5 * vfov_deg.to_radians()).tan();
        Self {
            origin: from,
            forward,
            right: right * half_h * aspect,
            up: true_up * half_h,
        }
    }

    /// The ray through the film point `film` in `[0, 1]²` (x to the right, y downward).
    #[inline]
    pub fn ray(&self, film: Vec2) -> Ray {
        let sx = 2.0 * film.x - 1.0;
        let sy = 1.0 - 2.0 * film.y;
        let dir = (self.forward + sx * self.right + sy * self.up).normalize();
        Ray::new(self.origin, dir)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_ray_looks_at_the_target_and_corners_spread() {
        let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 90.0, 2.0);
        let c = cam.ray(Vec2::splat(0.5));
        assert!((c.dir - -Vec3::Z).length() < 1e-6);
        let top_left = cam.ray(Vec2::ZERO).dir;
        assert!(top_left.x < 0.0 && top_left.y > 0.0);
        // 90° vertical field: the top edge is at 45°.
        let top = cam.ray(Vec2::new(0.5, 0.0)).dir;
        assert!((top.y - top.z.abs()).abs() < 1e-6);
    }
}
