//! [`Batch`] for the energy-compensated models: the default loops over their [`Prepare`]
//! code (the compensated plastic shares [`Plastic`](crate::bxdf::Plastic)'s, in `models.rs`).

use super::{Batch, Lanes};
use crate::bxdf::{CompensatedDielectric, CompensatedMicrofacet};
use crate::fresnel::FresnelAverage;
use crate::microfacet::NormalDistribution;

impl<D: NormalDistribution + Clone, F: FresnelAverage> Batch for CompensatedMicrofacet<D, F> where
    F::Spectrum: Lanes
{
}

impl<D: NormalDistribution + Clone> Batch for CompensatedDielectric<D> {}
