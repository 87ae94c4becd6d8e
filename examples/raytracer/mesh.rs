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

impl Triangle {
    /// Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection": the ray
    /// parameter and the barycentric coordinates `(b1, b2)` of vertices 1 and 2 of the hit.
    #[inline]
    fn hit_t(&self, ray: &Ray) -> Option<(f32, f32, f32)> {
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
        ray.contains(t).then_some((t, b1, b2))
    }
}

/// The point of the smooth surface that vertex normals `n` describe over the flat triangle
/// `v`, above its point `p` of barycentric coordinates `b`, on the side `side` (`+1` the
/// normals' side, `−1` the other): the shadow-ray origin of Hanika 2021, "Hacking the shadow
/// terminator" (Ray Tracing Gems II, ch. 4).
///
/// `p` is projected onto each vertex's tangent plane (the plane through `v_i` normal to
/// `n_i`) where it lies below that plane, and the three projections are interpolated with
/// the barycentric weights: `p' = p − Σ b_i min(0, (p − v_i)·n_i) n_i` (with `n_i` turned to
/// `side`). Where the surface curves away from `side` (convex seen from there) `p'` rises
/// above the flat triangle, up to the height of the curved surface the normals suggest;
/// where it is flat or curves toward `side`, `p' = p`. At a vertex `p' = v_i`.
#[inline]
fn smooth_point(v: &[Vec3; 3], n: &[Vec3; 3], b: [f32; 3], p: Vec3, side: f32) -> Vec3 {
    let mut lift = Vec3::ZERO;
    for i in 0..3 {
        let ni = n[i] * side;
        lift -= ni * (b[i] * (p - v[i]).dot(ni).min(0.0));
    }
    p + lift
}

impl Surface for Triangle {
    fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let (t, b1, b2) = self.hit_t(ray)?;
        let ng = (self.p[1] - self.p[0])
            .cross(self.p[2] - self.p[0])
            .normalize_or_zero();
        if ng == Vec3::ZERO {
            return None;
        }
        let p = ray.at(t);
        let (ns, p_shadow, bend) = match self.n {
            Some(n) => {
                let b = [1.0 - b1 - b2, b1, b2];
                let raw = n[0] * b[0] + n[1] * b[1] + n[2] * b[2];
                // Keep the shading normal in the geometric normal's hemisphere.
                let agree = if raw.dot(ng) < 0.0 { -1.0 } else { 1.0 };
                let s = (raw * agree).normalize_or(ng);
                // The shadow-ray origin on the side the ray comes from (the side a
                // reflection model is shaded on), in the normals' orientation.
                let toward_ray = if ray.dir.dot(ng) < 0.0 { 1.0 } else { -1.0 };
                let cos = n.iter().fold(1.0_f32, |c, n| c.min(agree * n.dot(ng)));
                let bend = (1.0 - cos * cos).max(0.0).sqrt();
                (s, smooth_point(&self.p, &n, b, p, toward_ray * agree), bend)
            }
            None => (ng, p, 0.0),
        };
        Some(Hit {
            t,
            p,
            p_shadow,
            bend,
            ng,
            ns,
            tangent: self.p[1] - self.p[0],
            material: self.material,
            light: None,
        })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.hit_t(ray).is_some()
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

    /// On a triangle cut from the unit sphere, Hanika's point rises from the flat triangle
    /// toward the sphere seen from outside, stays on the triangle seen from inside (the
    /// surface is concave from there), and is the vertex itself at a vertex.
    #[test]
    fn smooth_point_rises_toward_the_curved_surface() {
        let v = [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        ];
        let b = [1.0 / 3.0; 3];
        let p = (v[0] + v[1] + v[2]) / 3.0;
        let lifted = smooth_point(&v, &v, b, p, 1.0);
        assert!(
            (lifted - p).normalize().dot(p.normalize()) > 0.999,
            "along the normal"
        );
        let (flat, smooth) = (p.length(), lifted.length());
        assert!(flat < smooth && smooth <= 1.0, "{flat} < {smooth} ≤ 1");
        assert_eq!(smooth_point(&v, &v, b, p, -1.0), p);
        assert_eq!(smooth_point(&v, &v, [1.0, 0.0, 0.0], v[0], 1.0), v[0]);
        // Through `intersect`: a ray from outside gets the lifted point, its shadow-ray
        // origin, and the bend of the normals (54.7° from the facet's: sin = √(2/3)).
        let tri = Triangle {
            p: v,
            n: Some(v),
            material: 0,
        };
        let h = tri.intersect(&Ray::new(p * 2.0, -p.normalize())).unwrap();
        assert!((h.p_shadow - lifted).length() < 1e-6);
        assert!((h.bend - (2.0_f32 / 3.0).sqrt()).abs() < 1e-6);
        let h = tri.intersect(&Ray::new(Vec3::ZERO, p.normalize())).unwrap();
        assert!((h.p_shadow - h.p).length() < 1e-6);
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
