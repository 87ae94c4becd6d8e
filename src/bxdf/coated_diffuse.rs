//! pbrt-v4's coated diffuse material: a rough dielectric coat over a Lambertian base.

use super::{Lambert, Layered, RoughDielectric};
use crate::microfacet::NormalDistribution;
use crate::param::{Eta, ParamError};
use crate::spectrum::Spectrum;

/// A Lambertian base of reflectance `ρ` under a rough dielectric coat, with the light that
/// bounces between them followed by the stochastic random walk of [`Layered`]: pbrt-v4's
/// `CoatedDiffuseBxDF` (*PBR* 4th ed., §14.3.3; Guo, Hašan & Zhao 2018).
///
/// Unlike [`Plastic`](super::Plastic) and [`Glazed`](super::Glazed), which weigh the base by
/// the coat's transmittance once in and once out, it follows the light the coat reflects
/// back into the base, so a white base under a clear coat reflects everything the coat does
/// not lose (a smooth coat: all of it). Its `eval` and `pdf` are estimates, deterministic
/// for given inputs (see [`Layered`] for the estimators, their variance and the laws).
///
/// ```
/// use lobe::bxdf::{Bxdf, CoatedDiffuse};
/// use lobe::microfacet::Ggx;
/// use lobe::{Alpha, Eta, Vec2, Vec3};
/// let paint = CoatedDiffuse::coated_diffuse(
///     Vec3::new(0.7, 0.1, 0.1),
///     Ggx::isotropic(Alpha::new(0.1)?),
///     Eta::new(1.5)?,
/// )?;
/// let s = paint.sample(Vec3::new(0.0, 0.6, 0.8), Vec2::new(0.3, 0.4), 0.9).unwrap();
/// assert!(s.weight().max_element() <= 1.0);
/// # Ok::<(), lobe::ParamError>(())
/// ```
pub type CoatedDiffuse<D, S = f32> = Layered<RoughDielectric<D>, Lambert<S>>;

impl<D: NormalDistribution + Clone, S: Spectrum> Layered<RoughDielectric<D>, Lambert<S>> {
    /// A Lambertian base of reflectance `reflectance ∈ [0, 1]` under a coat of relative index
    /// `eta` whose roughness is `distribution`, with [`Layered::new`]'s defaults (a purely
    /// absorbing layer 0.01 mean free paths thick, walks of at most 64 events, one walk per
    /// estimate); change them with the `with_*` methods of [`Layered`].
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` for a channel that is NaN or outside `[0, 1]`.
    pub fn coated_diffuse(reflectance: S, distribution: D, eta: Eta) -> Result<Self, ParamError> {
        Ok(Layered::new(
            RoughDielectric::new(distribution, eta),
            Lambert::new(reflectance)?,
        ))
    }
}
