//! Burley's Disney diffuse BRDF.

use super::CosineSampled;
use crate::math::pow5;
use crate::param::{ParamError, Roughness};
use crate::spectrum::Spectrum;
use core::f32::consts::FRAC_1_PI;
use glam::Vec3;

/// The diffuse lobe of the Disney "principled" BRDF:
///
/// `f = ρ/π (1 + (F_D90 − 1)(1 − cos θl)⁵)(1 + (F_D90 − 1)(1 − cos θv)⁵)`,
/// `F_D90 = 0.5 + 2 r cos²θd`,
///
/// with `θl = θi` (light), `θv = θo` (viewer), `θd` the angle between `wi` and the half
/// vector `h = (wi + wo)/|wi + wo|`, and `r` the perceptual [`Roughness`].
///
/// Burley 2012, "Physically-Based Shading at Disney" (SIGGRAPH course notes), §5.3, eq. 4;
/// named only in the handout ([seed 000](crate::handouts#seed-000)), spelled out in
/// [ERRATA #11](crate::errata#erratum-11--disney-diffuse). A Schlick-like
/// retro-reflection factor for each direction: smooth surfaces (`F_D90 = 0.5`) darken at
/// grazing angles, rough ones (`F_D90` up to 2.5) brighten.
///
/// `cos²θd` is computed as `(1 + wi·wo)/2`, which equals `(wi·h)²` for unit vectors, so no
/// half vector is normalised and the value is symmetric in `wo` and `wi`. Every factor is
/// at least `0.5` for directions above the surface, and none divides: the value is finite
/// at the normal and at grazing.
///
/// Sampled by cosine-weighted directions (density `cos θi / π`).
///
/// Parameters: reflectance `ρ ∈ [0, 1]` per channel (`baseColor`), roughness `r ∈ [0, 1]`.
///
/// # Laws
///
/// Reciprocal (exactly: the formula is symmetric term by term, measured error 0) and
/// positive. **Not energy-conserving**
/// ([ERRATA #11](crate::errata#erratum-11--disney-diffuse)): the factors are not normalised, so the
/// directional albedo with `ρ = 1` is below 1 for smooth surfaces and above it for rough
/// ones. Measured by quadrature of [`Bxdf::eval`](super::Bxdf::eval) (`tests/bxdf_disney_diffuse.rs`; agrees with
/// an independent evaluation to 1e-6):
///
/// | r | θo = 0° | 30° | 60° | 80° | 85° | 89° | → 90° | max over θo |
/// | --- | --- | --- | --- | --- | --- | --- | --- | --- |
/// | 0 | 0.9762 | 0.9762 | 0.9609 | 0.7881 | 0.6668 | 0.5292 | 0.4881 | 0.9762 (0°–10°) |
/// | 0.5 | 1.0060 | 1.0052 | 1.0083 | 1.0254 | 1.0224 | 1.0104 | 1.0055 | 1.0255 (≈81°) |
/// | 1 | 1.0357 | 1.0342 | 1.0569 | 1.2767 | 1.4006 | 1.5236 | 1.5575 | 1.5575 (90°) |
///
/// At `r = 1` a white surface seen at grazing angles reflects up to 1.56 times the light it
/// receives (a 56 % gain; 52 % at 89°); at `r = 0` it loses up to 51 % there. The energy
/// bound therefore holds only as `albedo ≤ 1.5575 ρ`. For an energy-preserving rough diffuse
/// model, use [`EnergyPreservingOrenNayar`](super::EnergyPreservingOrenNayar).
///
/// ```
/// use lobe::bxdf::{Bxdf, DisneyDiffuse};
/// use lobe::{Roughness, Vec2, Vec3};
/// let rough = DisneyDiffuse::new(0.8_f32, Roughness::new(1.0)?)?;
/// // At the normal, looking straight back at the light: F_D90 = 2.5, both factors are 1.
/// assert!((rough.eval(Vec3::Z, Vec3::Z) - 0.8 / core::f32::consts::PI).abs() < 1e-7);
/// // Grazing retro-reflection is brightened by up to F_D90² = 6.25.
/// let w = Vec3::new(0.999_95, 0.0, 0.01);
/// assert!(rough.eval(w, w) > 5.0 * rough.eval(Vec3::Z, Vec3::Z));
/// let s = rough.sample(w, Vec2::new(0.3, 0.6), 0.5).unwrap();
/// assert_eq!(s.f, rough.eval(w, s.wi));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DisneyDiffuse<S = f32> {
    reflectance: S,
    roughness: Roughness,
}

impl<S: Spectrum> DisneyDiffuse<S> {
    /// A Disney diffuse surface with reflectance `ρ ∈ [0, 1]` per channel and perceptual
    /// roughness `r`.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`.
    pub fn new(reflectance: S, roughness: Roughness) -> Result<Self, ParamError> {
        Ok(Self {
            reflectance: crate::param::unit_interval("reflectance", reflectance)?,
            roughness,
        })
    }

    getters! {
        /// The reflectance `ρ`.
        reflectance: S,
        /// The perceptual roughness `r`.
        roughness: Roughness,
    }
}

impl<S: Spectrum> CosineSampled for DisneyDiffuse<S> {
    type Spectrum = S;

    #[inline(always)]
    fn value(&self, wo: Vec3, wi: Vec3) -> S {
        // cos²θd = (wi·h)² = (1 + wi·wo)/2 for unit vectors.
        let cos2_d = (0.5 + 0.5 * wo.dot(wi)).max(0.0);
        let fd90_m1 = 2.0 * self.roughness.get() * cos2_d - 0.5;
        let light = 1.0 + fd90_m1 * pow5(1.0 - wi.z.min(1.0));
        let view = 1.0 + fd90_m1 * pow5(1.0 - wo.z.min(1.0));
        self.reflectance * (light * view * FRAC_1_PI)
    }
}
