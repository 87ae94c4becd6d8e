//! The statistics room: the tools the laws measure with, and nothing about reflectance.
//!
//! What lives here: the seeded generator ([`Pcg32`], `rng.rs`); Monte Carlo estimates with
//! their standard errors ([`Estimate`], [`Accumulator`], `estimate.rs`); integration
//! (`integrate.rs`: the adaptive Simpson quadrature behind the chi-square test's expected
//! counts, and [`integrate_hemisphere`], the Monte Carlo integral with a stretched proposal);
//! Pearson's chi-square test of a direction sampler ([`chi2_sphere`], `chi2.rs`); the special
//! functions its p-value needs ([`gamma_q`] and friends, `gamma.rs`); and significance levels
//! with their normal quantiles ([`sidak`], [`two_sided_quantile`], `significance.rs`).
//!
//! The tools are public through [`crate::verify`], because a check built outside the crate
//! needs them too (only the stretch of a direction stays inside, shared with the distribution
//! laws). Nothing here depends on the laws room.

mod chi2;
mod estimate;
mod gamma;
mod integrate;
mod rng;
mod significance;

pub use chi2::{Chi2Bin, Chi2Config, Chi2Report, Chi2Residual, chi2_sphere, chi2_sphere_rng};
pub use estimate::{Accumulator, Estimate};
pub use gamma::{chi2_survival, gamma_p, gamma_q, ln_gamma};
pub use integrate::integrate_hemisphere;
pub(in crate::verify) use integrate::stretch_direction;
pub use rng::Pcg32;
pub use significance::{sidak, two_sided_quantile};
