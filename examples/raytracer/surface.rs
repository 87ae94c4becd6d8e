//! The [`Surface`] abstraction and the intersection record it fills in.

use crate::aabb::Aabb;
use crate::ray::Ray;
use lobe::Vec3;

/// The index of a material in the scene's material list.
pub type MaterialId = u32;

/// What a ray hit: the seed's "intersection record" (t, point, normals, material).
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// The ray parameter of the hit.
    pub t: f32,
    /// The hit point.
    pub p: Vec3,
    /// Where shadow rays start: `p` itself, except on a triangle with vertex normals, where
    /// it is `p` lifted off the flat triangle to the smooth surface the normals describe, on
    /// the side the ray came from (Hanika 2021; see [`crate::mesh`]), so that the coarse
    /// facets do not shadow light the shading normal sees.
    pub p_shadow: Vec3,
    /// The sine of the largest angle between the geometric normal and the vertex normals
    /// (`0` without them): how far above the flat surface's horizon the shading normals'
    /// horizon may lie, which says which shadow rays start from `p_shadow`
    /// ([`crate::shading::ShadingPoint::shadow_origin`]).
    pub bend: f32,
    /// The unit geometric normal, with the surface's own orientation (outward for closed
    /// surfaces): not flipped toward the ray.
    pub ng: Vec3,
    /// The unit shading normal (interpolated for meshes), in the hemisphere of `ng`.
    pub ns: Vec3,
    /// A tangent (`∂p/∂u`), which orients anisotropic lobes; need not be unit or
    /// orthogonal to `ns`.
    pub tangent: Vec3,
    /// The surface's material.
    pub material: MaterialId,
    /// The area light this surface is, if it emits.
    pub light: Option<u32>,
}

/// Anything a ray can hit (seed 003: "make these all subclasses of Surface"): a primitive,
/// a mesh, a group with an acceleration structure.
pub trait Surface: Send + Sync {
    /// The closest hit with `t` in the ray's valid range, if any.
    fn intersect(&self, ray: &Ray) -> Option<Hit>;

    /// True when anything is hit in the ray's valid range (shadow rays: any hit will do).
    fn occluded(&self, ray: &Ray) -> bool {
        self.intersect(ray).is_some()
    }

    /// A box that holds the whole surface.
    fn bounds(&self) -> Aabb;
}
