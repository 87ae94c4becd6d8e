//! pbrt-v4's coated conductor material: a rough dielectric coat over a rough conductor.

use super::{Layered, Microfacet, RoughConductor, RoughDielectric};
use crate::fresnel::Conductor;
use crate::microfacet::{Masking, NormalDistribution};
use crate::param::{ComplexIor, Eta, ParamError};
use crate::spectrum::Spectrum;

/// A rough conductor base (a [`Microfacet`] model with the exact conductor Fresnel term) under
/// a rough dielectric coat, with the
/// light that bounces between them followed by the stochastic random walk of [`Layered`]:
/// pbrt-v4's `CoatedConductorBxDF` (*PBR* 4th ed., §14.3.3; Guo, Hašan & Zhao 2018). The
/// coat's and the base's roughness are separate distributions.
///
/// Its `eval` and `pdf` are estimates, deterministic for given inputs (see [`Layered`] for
/// the estimators, their variance and the laws).
///
/// ```
/// use lobe::bxdf::{Bxdf, CoatedConductor};
/// use lobe::microfacet::Ggx;
/// use lobe::{metals, Alpha, Eta, Vec3};
/// let lacquered_gold = CoatedConductor::coated_conductor(
///     Ggx::isotropic(Alpha::new(0.05)?),
///     Eta::new(1.5)?,
///     Ggx::isotropic(Alpha::new(0.3)?),
///     metals::GOLD.rgb(),
/// )?;
/// let f = lacquered_gold.eval(Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.0, -0.6, 0.8));
/// assert!(f.x > f.z); // gold
/// # Ok::<(), lobe::ParamError>(())
/// ```
pub type CoatedConductor<D, DB = D, S = f32> = Layered<RoughDielectric<D>, RoughConductor<DB, S>>;

impl<D, DB, S> Layered<RoughDielectric<D>, RoughConductor<DB, S>>
where
    D: NormalDistribution + Clone,
    DB: NormalDistribution,
    S: Spectrum,
{
    /// A conductor of complex index `ior` (relative to the outside, as [`metals`](crate::metals)
    /// gives it) and roughness `base` (height-correlated Smith masking) under a coat of
    /// relative index `eta` and roughness `coat`, with [`Layered::new`]'s defaults; change
    /// them with the `with_*` methods of [`Layered`]. Under the coat the metal meets the coat's
    /// medium, so its index becomes `ior / η` (as pbrt-v4's `CoatedConductorMaterial` does).
    ///
    /// # Errors
    /// [`ParamError`] naming `eta` or `k` when `ior / η` leaves [`ComplexIor`]'s range.
    pub fn coated_conductor(
        coat: D,
        eta: Eta,
        base: DB,
        ior: ComplexIor<S>,
    ) -> Result<Self, ParamError> {
        let e = eta.get();
        let relative = ComplexIor::new(ior.eta() * (1.0 / e), ior.k() * (1.0 / e))?;
        Ok(Layered::new(
            RoughDielectric::new(coat, eta),
            Microfacet::new(base, Masking::HeightCorrelated, Conductor { ior: relative }),
        ))
    }
}
