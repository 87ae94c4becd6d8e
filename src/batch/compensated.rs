//! [`Batch`] for the energy-compensated glass: the default loops over its [`Prepare`] code
//! (the compensated microfacet model takes the microfacet models' loops, and the compensated
//! plastic shares [`Plastic`](crate::bxdf::Plastic)'s, in `models.rs`).

use super::Batch;
use crate::bxdf::CompensatedDielectric;
use crate::microfacet::NormalDistribution;

impl<D: NormalDistribution + Clone> Batch for CompensatedDielectric<D> {}
