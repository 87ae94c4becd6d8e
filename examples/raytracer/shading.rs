//! The local shading frame at a hit, set up the way each kind of model needs it.

use crate::material::Material;
use crate::surface::Hit;
use lobe::{Frame, Vec3};

/// A hit seen from a viewer: the material, the shading frame and `wo` in it.
pub struct ShadingPoint<'a> {
    /// The material.
    pub material: &'a Material,
    /// The hit point.
    pub p: Vec3,
    /// The geometric normal: the surface's own for transmissive models, turned toward the
    /// viewer for one-sided reflection models.
    pub ng: Vec3,
    /// The shading frame (`z` the shading normal, `x` the surface tangent).
    pub frame: Frame,
    /// The direction toward the viewer, local.
    pub wo: Vec3,
}

impl<'a> ShadingPoint<'a> {
    /// The shading point of `hit` seen along `-wo_world` (so `wo_world` points to the
    /// viewer).
    ///
    /// A model with transmission keeps the surface's orientation (the normal says which
    /// side is outside, and so the meaning of `eta`). A one-sided reflection model is shaded
    /// on both sides: its frame is flipped toward the viewer; and where an interpolated
    /// shading normal faces away from the viewer, the geometric normal stands in for it.
    pub fn new(material: &'a Material, hit: &Hit, wo_world: Vec3) -> Self {
        let (mut ng, mut ns) = (hit.ng, hit.ns);
        if !material.transmits() && wo_world.dot(ng) < 0.0 {
            ng = -ng;
            ns = -ns;
        }
        let mut frame = Frame::from_normal_tangent(ns, hit.tangent);
        let mut wo = frame.to_local(wo_world);
        if !material.transmits() && wo.z <= 0.0 && ns != ng {
            frame = Frame::from_normal_tangent(ng, hit.tangent);
            wo = frame.to_local(wo_world);
        }
        Self {
            material,
            p: hit.p,
            ng,
            frame,
            wo,
        }
    }

    /// True when the world direction `w` and its local form `w_local` are on the same side
    /// of the surface by both normals: where they disagree (a shading normal tilted far
    /// from the geometric one), light would leak through the surface.
    #[inline]
    pub fn consistent(&self, w: Vec3, w_local: Vec3) -> bool {
        w.dot(self.ng) * w_local.z > 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lobe::Eta;
    use lobe::bxdf::Mono;
    use lobe::bxdf::{Lambert, SmoothDielectric};

    fn hit(n: Vec3) -> Hit {
        Hit {
            t: 1.0,
            p: Vec3::ZERO,
            ng: n,
            ns: n,
            tangent: Vec3::X,
            material: 0,
            light: None,
        }
    }

    #[test]
    fn reflection_flips_toward_the_viewer_transmission_does_not() {
        let white = Material::new("white", Lambert::new(Vec3::ONE).unwrap());
        let glass = Material::new(
            "glass",
            Mono::new(SmoothDielectric::new(Eta::new(1.5).unwrap())),
        );
        let below = -Vec3::Y;
        let sp = ShadingPoint::new(&white, &hit(Vec3::Y), below);
        assert!(sp.wo.z > 0.0 && sp.ng == -Vec3::Y);
        let sp = ShadingPoint::new(&glass, &hit(Vec3::Y), below);
        assert!(sp.wo.z < 0.0 && sp.ng == Vec3::Y);
    }
}
