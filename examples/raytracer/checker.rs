//! A checkerboard: a quad whose tiles alternate between two materials.

use crate::aabb::Aabb;
use crate::quad::Quad;
use crate::ray::Ray;
use crate::surface::{Hit, MaterialId, Surface};

/// A quad divided into `tiles × tiles` squares of its parameter space, alternating between
/// the quad's own material and `other`: one primitive for a whole tiled floor.
#[derive(Clone, Copy, Debug)]
pub struct Checker {
    /// The geometry and the first material.
    pub quad: Quad,
    /// The second material.
    pub other: MaterialId,
    /// Tiles along each edge.
    pub tiles: u32,
}

impl Surface for Checker {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let (mut hit, a, b) = self.quad.intersect_params(ray)?;
        let n = self.tiles as f32;
        let (i, j) = ((a * n) as u32, (b * n) as u32);
        if (i + j) % 2 == 1 {
            hit.material = self.other;
        }
        Some(hit)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.quad.occluded(ray)
    }

    fn bounds(&self) -> Aabb {
        self.quad.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lobe::Vec3;

    #[test]
    fn tiles_alternate() {
        let quad = Quad::new(Vec3::ZERO, Vec3::Z * 2.0, Vec3::X * 2.0, 0).unwrap();
        let c = Checker {
            quad,
            other: 1,
            tiles: 2,
        };
        let at = |x: f32, z: f32| {
            c.intersect(&Ray::new(Vec3::new(x, 1.0, z), -Vec3::Y))
                .map(|h| h.material)
        };
        assert_eq!(at(0.5, 0.5), Some(0));
        assert_eq!(at(1.5, 0.5), Some(1));
        assert_eq!(at(1.5, 1.5), Some(0));
        assert_eq!(at(2.5, 0.5), None);
    }
}
