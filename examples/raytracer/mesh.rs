//! Triangles and triangle meshes loaded from Wavefront OBJ files (with `tobj`).

use crate::aabb::Aabb;
use crate::bvh::Group;
use crate::ray::Ray;
use crate::surface::{Hit, MaterialId, Surface};
use lobe::Vec3;
use std::path::Path;

/// A triangle with optional per-vertex shading normals.
#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    /// The vertices, counter-clockwise seen from the front.
    pub p: [Vec3; 3],
    /// Vertex normals for smooth shading, if the mesh has them.
    pub n: Option<[Vec3; 3]>,
    /// The material.
    pub material: MaterialId,
}

impl Surface for Triangle {
    /// Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection".
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let e1 = self.p[1] - self.p[0];
        let e2 = self.p[2] - self.p[0];
        let pv = ray.dir.cross(e2);
        let det = e1.dot(pv);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inv = 1.0 / det;
        let tv = ray.origin - self.p[0];
        let b1 = tv.dot(pv) * inv;
        if !(0.0..=1.0).contains(&b1) {
            return None;
        }
        let qv = tv.cross(e1);
        let b2 = ray.dir.dot(qv) * inv;
        if !(b2 >= 0.0 && b1 + b2 <= 1.0) {
            return None;
        }
        let t = e2.dot(qv) * inv;
        if !ray.contains(t) {
            return None;
        }
        let ng = e1.cross(e2).normalize_or_zero();
        if ng == Vec3::ZERO {
            return None;
        }
        let ns = match self.n {
            Some(n) => {
                let s = (n[0] * (1.0 - b1 - b2) + n[1] * b1 + n[2] * b2).normalize_or(ng);
                // Keep the shading normal in the geometric normal's hemisphere.
                if s.dot(ng) < 0.0 { -s } else { s }
            }
            None => ng,
        };
        Some(Hit {
            t,
            p: ray.at(t),
            ng,
            ns,
            tangent: e1,
            material: self.material,
            light: None,
        })
    }

    fn bounds(&self) -> Aabb {
        Aabb::from_points(&self.p).padded(1e-5)
    }
}

/// A triangle mesh: its triangles behind their own BVH.
pub struct Mesh {
    /// The triangles, behind their BVH.
    triangles: Group,
}

impl Mesh {
    /// The mesh of `triangles`.
    pub fn new(triangles: Vec<Triangle>) -> Self {
        Self {
            triangles: Group::new(
                triangles
                    .into_iter()
                    .map(|t| Box::new(t) as Box<dyn Surface>)
                    .collect(),
            ),
        }
    }

    /// The number of triangles.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Loads every model of the OBJ file `path`, triangulated, scaled by `scale` and moved
    /// by `offset`, with the material `material` (the file's own materials are ignored).
    ///
    /// # Errors
    /// A message naming the file when it cannot be read or parsed, or holds no triangle.
    pub fn load_obj(
        path: &Path,
        scale: f32,
        offset: Vec3,
        material: MaterialId,
    ) -> Result<Self, String> {
        let options = tobj::LoadOptions {
            triangulate: true,
            single_index: true,
            ..Default::default()
        };
        let (models, _) = tobj::load_obj(path, &options)
            .map_err(|e| format!("cannot load {}: {e}", path.display()))?;
        let mut triangles = Vec::new();
        for model in &models {
            let m = &model.mesh;
            let vertex = |i: u32| {
                let i = 3 * i as usize;
                m.positions
                    .get(i..i + 3)
                    .map(|p| Vec3::new(p[0], p[1], p[2]) * scale + offset)
            };
            let normal = |i: u32| {
                let i = 3 * i as usize;
                m.normals
                    .get(i..i + 3)
                    .map(|n| Vec3::new(n[0], n[1], n[2]).normalize_or_zero())
            };
            for face in m.indices.chunks_exact(3) {
                let (Some(a), Some(b), Some(c)) =
                    (vertex(face[0]), vertex(face[1]), vertex(face[2]))
                else {
                    return Err(format!(
                        "{}: a face refers to a missing vertex",
                        path.display()
                    ));
                };
                let n = match (normal(face[0]), normal(face[1]), normal(face[2])) {
                    (Some(x), Some(y), Some(z)) => Some([x, y, z]),
                    _ => None,
                };
                triangles.push(Triangle {
                    p: [a, b, c],
                    n,
                    material,
                });
            }
        }
        if triangles.is_empty() {
            return Err(format!("{} holds no triangle", path.display()));
        }
        Ok(Self::new(triangles))
    }
}

impl Surface for Mesh {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.triangles.intersect(ray)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.triangles.occluded(ray)
    }

    fn bounds(&self) -> Aabb {
        self.triangles.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_hit_and_barycentric_normal() {
        let tri = Triangle {
            p: [Vec3::ZERO, Vec3::X, Vec3::Y],
            n: Some([Vec3::Z, Vec3::Z, Vec3::new(0.0, 0.6, 0.8)]),
            material: 0,
        };
        let h = tri
            .intersect(&Ray::new(Vec3::new(0.2, 0.2, 1.0), -Vec3::Z))
            .unwrap();
        assert!((h.t - 1.0).abs() < 1e-6);
        assert!((h.ng - Vec3::Z).length() < 1e-6);
        assert!(h.ns.y > 0.0 && (h.ns.length() - 1.0).abs() < 1e-5);
        assert!(
            tri.intersect(&Ray::new(Vec3::new(0.8, 0.8, 1.0), -Vec3::Z))
                .is_none()
        );
    }

    #[test]
    fn the_committed_obj_loads() {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/raytracer/assets/torus.obj");
        let mesh = Mesh::load_obj(&path, 1.0, Vec3::ZERO, 0).unwrap();
        assert!(mesh.len() >= 100 && mesh.len() <= 1000, "{}", mesh.len());
        let hit = mesh.intersect(&Ray::new(Vec3::new(0.0, 5.0, 0.75), -Vec3::Y));
        assert!(hit.is_some(), "a ray down through the tube hits the torus");
        assert!(Mesh::load_obj(Path::new("/nonexistent.obj"), 1.0, Vec3::ZERO, 0).is_err());
    }
}
