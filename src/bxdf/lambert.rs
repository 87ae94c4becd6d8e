//! The Lambertian (ideal diffuse) BRDF.

use super::CosineSampled;
use crate::param::ParamError;
use crate::spectrum::Spectrum;
use core::f32::consts::FRAC_1_PI;
use glam::Vec3;

/// Lambert's ideal diffuse reflector: `f = ρ / π` for `wo`, `wi` above the surface.
///
/// Lambert 1760; the handouts' "Lambertian shading" ([seed 003](crate::handouts#seed-003))
/// with reflectance `R`. Sampled by
/// cosine-weighted directions, whose density `cos θi / π` makes the sample weight exactly `ρ`.
///
/// Laws: reciprocal, positive, and its directional albedo is `ρ` for every `wo` (so it is
/// energy-conserving for `ρ ≤ 1`, which the constructor requires).
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert};
/// use lobe::{Vec2, Vec3};
/// let white = Lambert::new(0.8_f32)?;
/// let wo = Vec3::Z;
/// let s = white.sample(wo, Vec2::new(0.3, 0.6), 0.5).unwrap();
/// assert!((s.weight() - 0.8).abs() < 1e-6);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambert<S = f32> {
    reflectance: S,
}

impl<S: Spectrum> Lambert<S> {
    /// A Lambertian reflector with reflectance `ρ ∈ [0, 1]` per channel.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`.
    pub fn new(reflectance: S) -> Result<Self, ParamError> {
        Ok(Self {
            reflectance: crate::param::unit_interval("reflectance", reflectance)?,
        })
    }

    /// The reflectance `ρ`, which is also the directional albedo for every `wo`.
    #[inline]
    #[must_use]
    pub fn albedo(&self) -> S {
        self.reflectance
    }
}

impl<S: Spectrum> CosineSampled for Lambert<S> {
    type Spectrum = S;

    #[inline(always)]
    fn value(&self, _wo: Vec3, _wi: Vec3) -> S {
        self.reflectance * FRAC_1_PI
    }
}
