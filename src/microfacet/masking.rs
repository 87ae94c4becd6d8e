//! The choice of masking-shadowing term `G2` in a microfacet BRDF.

use super::{NormalDistribution, View};
use glam::Vec3;

/// Which masking-shadowing term a microfacet model uses.
///
/// A closed set of choices rather than a type parameter: the choice is made once per
/// material and the branch is perfectly predicted in a shading loop.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Masking {
    /// Height-correlated Smith, `1 / (1 + Λ(wo) + Λ(wi))` (Heitz 2014, eq. 99): the default,
    /// and the most accurate of the three for a random height field. That is the form for a
    /// reflected pair; [`RoughDielectric`](crate::bxdf::RoughDielectric) uses it for a
    /// transmitted pair too, as pbrt-v4 and Mitsuba 3 do (Heitz derives another
    /// height-correlated form for transmission, a Beta function of `1 + Λ(wo)` and
    /// `1 + Λ(wi)`).
    #[default]
    HeightCorrelated,
    /// Separable Smith, `G1(wo) G1(wi)` (Heitz 2014, eq. 98): Mitsuba 3's choice.
    Separable,
    /// Cook & Torrance's V-cavity term (Cook & Torrance 1982, eq. 5;
    /// [ERRATA #2](crate::errata#erratum-2--v-cavity-factor-two)):
    /// `min(1, 2 (n·h)(n·wo)/(wo·h), 2 (n·h)(n·wi)/(wo·h))`. It ignores `Λ`: it models a
    /// microsurface of V-shaped grooves rather than a random height field, but a consistent
    /// one, whose masking conserves the projected area (Heitz 2014, §4.3; measured within the
    /// Monte Carlo error by the crate's tests). It exists to build [the
    /// handouts'](crate::handouts) Cook-Torrance model.
    VCavity,
}

impl Masking {
    /// `G2(wo, wi, m)` for the distribution `dist`, without the `χ⁺` orientation factors
    /// (the model applies them). `m` is used only by [`Masking::VCavity`].
    #[inline(always)]
    #[must_use]
    pub fn g2<D: NormalDistribution + ?Sized>(self, dist: &D, wo: Vec3, wi: Vec3, m: Vec3) -> f32 {
        match self {
            Self::HeightCorrelated => dist.g2(wo, wi),
            Self::Separable => dist.g2_separable(wo, wi),
            Self::VCavity => v_cavity(wo, wi, m),
        }
    }

    /// `G2 / (4 |cos θo| |cos θi|)` with `wo` prepared as `view`: the masking-shadowing factor
    /// of a microfacet model's value, the height-correlated one through
    /// [`NormalDistribution::visibility`]. For `|cos θo cos θi|` above `f32::MIN_POSITIVE`.
    #[inline(always)]
    #[must_use]
    pub fn visibility<D: NormalDistribution + ?Sized>(
        self,
        dist: &D,
        view: &View,
        wi: Vec3,
        m: Vec3,
    ) -> f32 {
        // Λ(wo), G1(wo) and |wo.z| come from the view: every term depends on wo only
        // through |wo.z|, |wo·m| and Λ, which are even, so view.w = ±wo gives the same value.
        let g2 = match self {
            Self::HeightCorrelated => return dist.visibility(view, wi),
            // G1(wo) = 1/(1 + Λ(wo)), from the view's Λ (its visible factor may use another).
            Self::Separable => dist.g1(wi) / (1.0 + view.lambda),
            Self::VCavity => v_cavity(view.w, wi, m),
        };
        g2 / (4.0 * view.w.z * wi.z.abs())
    }
}

/// Cook-Torrance's V-cavity masking-shadowing term, with `m` the microfacet normal.
///
/// `min(1, 2 |m.z wo.z| / |wo·m|, 2 |m.z wi.z| / |wi·m|)`: each direction's term divides by its
/// own `|w·m|`. For reflection `wo·m = wi·m` and this is Cook & Torrance's formula; for
/// refraction (Walter et al. 2007, §5.1) it keeps the term symmetric in `wo` and `wi`, so that
/// a refracting model built on it stays reciprocal. `0` when either `w·m` is `0`.
#[inline(always)]
#[must_use]
pub fn v_cavity(wo: Vec3, wi: Vec3, m: Vec3) -> f32 {
    let (wom, wim) = (wo.dot(m).abs(), wi.dot(m).abs());
    if wom == 0.0 || wim == 0.0 {
        return 0.0;
    }
    let k = 2.0 * m.z.abs();
    (k * wo.z.abs() / wom).min(k * wi.z.abs() / wim).min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn v_cavity_matches_cook_torrance_by_hand() {
        // wo at 60°, wi at 30° on the other side; h bisects them.
        let wo = Vec3::new(0.866_025_4, 0.0, 0.5);
        let wi = Vec3::new(-0.5, 0.0, 0.866_025_4);
        let h = (wo + wi).normalize();
        // n·h = cos 15°, wo·h = cos 45°: 2 cos15° cos60° / cos45° = 1.366 (> 1), so G = 1.
        assert_eq!(v_cavity(wo, wi, h), 1.0);
        // Grazing wo at 85°, wi at normal incidence: 2 (n·h)(n·wo)/(wo·h) with
        // n·h = cos 42.5°, wo·h = cos 42.5°: 2 cos 85° = 0.1743.
        let wo = Vec3::new(85f32.to_radians().sin(), 0.0, 85f32.to_radians().cos());
        let wi = Vec3::Z;
        let h = (wo + wi).normalize();
        let want = 2.0 * 85f32.to_radians().cos();
        assert!((v_cavity(wo, wi, h) - want).abs() < 1e-6);
        // The slip of ERRATA #2 (no factor 2) would give half of that.
        assert!((v_cavity(wo, wi, h) - want / 2.0).abs() > 0.08);
    }
}
