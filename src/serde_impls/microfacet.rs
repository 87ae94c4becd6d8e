//! The microfacet models: [`Microfacet`] (Cook-Torrance with any distribution and Fresnel
//! term) and [`RoughDielectric`], as their distribution, Fresnel term or index, and choices.

use super::is_default;
use crate::bxdf::{Microfacet, RoughDielectric, TransportMode};
use crate::fresnel::Fresnel;
use crate::microfacet::{Masking, NormalDistribution};
use crate::param::Eta;

wire! {
    /// [`Microfacet`] on the wire: `{ "distribution": …, "fresnel": … }`, and
    /// `"masking": "separable"` or `"v_cavity"` when it is not height-correlated Smith.
    impl[D: NormalDistribution, F: Fresnel] Microfacet<D, F> as "Microfacet"
        MicrofacetRepr<D, F> |m| {
        distribution: D = m.distribution(),
        #[serde(default, skip_serializing_if = "is_default")]
        masking: Masking = m.masking(),
        fresnel: F = m.fresnel(),
    } via |r| Ok(Microfacet::new(r.distribution, r.masking, r.fresnel))
}

wire! {
    /// [`RoughDielectric`] on the wire: `{ "distribution": …, "eta": 1.5 }`, and `"masking"`
    /// and `"mode": "importance"` when they are not the defaults.
    impl[D: NormalDistribution] RoughDielectric<D> as "RoughDielectric"
        RoughDielectricRepr<D> |m| {
        distribution: D = m.distribution(),
        eta: Eta = m.eta(),
        #[serde(default, skip_serializing_if = "is_default")]
        masking: Masking = m.masking(),
        #[serde(default, skip_serializing_if = "is_default")]
        mode: TransportMode = m.mode(),
    } via |r| {
        Ok(RoughDielectric::new(r.distribution, r.eta)
            .with_masking(r.masking)
            .with_mode(r.mode))
    }
}
