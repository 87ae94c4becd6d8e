//! The coated models: [`Glazed`], [`Plastic`] and [`CompensatedPlastic`], as the base's
//! reflectance and the coat's index (and, for the plastics, its distribution). What the
//! constructors compute from them (the coat's average Fresnel, the plastic's table of coat
//! albedos) is not written: the constructor computes it again on the way in.

use crate::bxdf::{CompensatedPlastic, Glazed, Plastic};
use crate::microfacet::NormalDistribution;
use crate::param::Eta;
use crate::spectrum::Spectrum;
use crate::tables::TabulatedDielectric;

wire! {
    /// [`Glazed`] on the wire: `{ "reflectance": …, "eta": 1.5 }`.
    impl[S: Spectrum] Glazed<S> as "Glazed" GlazedRepr<S> |m| {
        reflectance: S = m.reflectance(),
        eta: Eta = m.eta(),
    } via |r| Glazed::new(r.reflectance, r.eta)
}

wire! {
    /// [`Plastic`] on the wire: `{ "reflectance": …, "distribution": …, "eta": 1.5 }`, in the
    /// constructor's order.
    impl[D: NormalDistribution, S: Spectrum] Plastic<D, S> as "Plastic"
        PlasticRepr<S, D> |m| {
        reflectance: S = m.reflectance(),
        distribution: D = m.distribution(),
        eta: Eta = m.eta(),
    } via |r| Plastic::new(r.reflectance, r.distribution, r.eta)
}

wire! {
    /// [`CompensatedPlastic`] on the wire: as [`Plastic`]; the type says the coat is
    /// compensated.
    impl[D: TabulatedDielectric, S: Spectrum] CompensatedPlastic<D, S> as "Plastic"
        CompensatedPlasticRepr<S, D> |m| {
        reflectance: S = m.reflectance(),
        distribution: D = m.distribution(),
        eta: Eta = m.eta(),
    } via |r| Plastic::compensated(r.reflectance, r.distribution, r.eta)
}
