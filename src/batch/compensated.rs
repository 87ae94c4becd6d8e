//! [`Batch`] for the energy-compensated models: the default loops over their [`Prepare`]
//! code.

use super::{Batch, Lanes};
use crate::bxdf::{CompensatedDielectric, CompensatedMicrofacet, Plastic};
use crate::fresnel::{Dielectric, FresnelAverage};
use crate::microfacet::NormalDistribution;
use crate::spectrum::Spectrum;

impl<D: NormalDistribution, F: FresnelAverage> Batch for CompensatedMicrofacet<D, F> where
    F::Spectrum: Lanes
{
}

impl<D: NormalDistribution> Batch for CompensatedDielectric<D> {}

impl<D: NormalDistribution, S: Spectrum + Lanes> Batch
    for Plastic<D, S, CompensatedMicrofacet<D, Dielectric>>
{
}
