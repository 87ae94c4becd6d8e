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
    /// [`Hit::p_shadow`] for a reflection model under the terminator fix, `p` otherwise (a
    /// model with transmission has lights on both sides).
    p_shadow: Vec3,
    /// True when the shadow terminator fix is on for this point (see
    /// [`shadow_origin`](Self::shadow_origin) and
    /// [`light_direction`](Self::light_direction)).
    smooth: bool,
    /// [`Hit::bend`].
    bend: f32,
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
    ///
    /// `terminator_fix` ([`Scene::terminator_fix`](crate::scene::Scene::terminator_fix))
    /// turns on the shadow terminator fix for reflection models: shadow rays near the facet's
    /// horizon from [`Hit::p_shadow`], and light accepted by the shading normal alone.
    pub fn new(material: &'a Material, hit: &Hit, wo_world: Vec3, terminator_fix: bool) -> Self {
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
        let smooth = terminator_fix && !material.transmits();
        Self {
            material,
            p: hit.p,
            p_shadow: if smooth { hit.p_shadow } else { hit.p },
            smooth,
            bend: hit.bend,
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

    /// Where the shadow ray toward the world direction `w` starts.
    ///
    /// Without the terminator fix, and for directions well above the flat facet's horizon,
    /// the hit point `p`. Under the fix, for directions that leave the facet within the angle
    /// `δ` by which its vertex normals bend away from it (`w·n_g ≤ sin δ`,
    /// [`Hit::bend`]), the smooth surface point [`Hit::p_shadow`] (Hanika 2021): those are
    /// the rays the facet itself or its neighbours (which rise by up to about `2δ` where the
    /// mesh is concave) may stop although the shading normal sees the light. Between `sin δ`
    /// and `2 sin δ` the origin slides back to `p`, so that the shadows other objects cast
    /// on the mesh stay where the mesh is (Blender's Cycles limits its offset the same way,
    /// with a fixed threshold).
    #[inline]
    pub fn shadow_origin(&self, w: Vec3) -> Vec3 {
        if !self.smooth || !(self.bend > 0.0) {
            return self.p;
        }
        let lift = (2.0 - w.dot(self.ng) / self.bend).clamp(0.0, 1.0);
        self.p + (self.p_shadow - self.p) * lift
    }

    /// Whether light may arrive along the world direction `w` toward a light (local form
    /// `w_local`) in next-event estimation: `None` if not, `Some(mis)` if it may, once the
    /// shadow ray from [`shadow_origin`](Self::shadow_origin) finds the way clear, with `mis` true when
    /// a BSDF sample in that direction would be followed too (so the two estimates of that
    /// light share it by MIS), false when only the light sample can find it.
    ///
    /// Without the terminator fix the two normals must agree ([`consistent`](Self::consistent)).
    /// With it (a reflection model), the shading normal alone decides: a direction above
    /// the shading normal's horizon but below the flat facet's is lit, if the shadow ray from
    /// the smooth surface point gets through. That is where a coarse mesh with interpolated
    /// normals otherwise shows its facets as a hard-edged shadow on the lit side of the
    /// terminator (the shadow terminator problem; Hanika 2021). A BSDF sample there is still
    /// dropped (it would start a path under the facet), so the light sample takes the whole
    /// weight: `mis = false`.
    #[inline]
    pub fn light_direction(&self, w: Vec3, w_local: Vec3) -> Option<bool> {
        let consistent = self.consistent(w, w_local);
        if consistent {
            Some(true)
        } else if self.smooth && w_local.z > 0.0 {
            Some(false)
        } else {
            None
        }
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
            p_shadow: Vec3::ZERO,
            bend: 0.0,
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
        let sp = ShadingPoint::new(&white, &hit(Vec3::Y), below, true);
        assert!(sp.wo.z > 0.0 && sp.ng == -Vec3::Y);
        let sp = ShadingPoint::new(&glass, &hit(Vec3::Y), below, true);
        assert!(sp.wo.z < 0.0 && sp.ng == Vec3::Y);
    }
}
