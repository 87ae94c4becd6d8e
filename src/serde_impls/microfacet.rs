//! The microfacet models: [`Microfacet`] (Cook-Torrance with any distribution and Fresnel
//! term) and [`RoughDielectric`], as their distribution, Fresnel term or index, and choices.

use super::is_default;
use crate::bxdf::{Microfacet, RoughDielectric, TransportMode};
use crate::fresnel::Fresnel;
use crate::microfacet::{Masking, NormalDistribution};
use crate::param::Eta;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Microfacet`] on the wire: `{ "distribution": …, "fresnel": … }`, and
/// `"masking": "separable"` or `"v_cavity"` when it is not height-correlated Smith.
/// Serialised with `D = &D` and `F = &F`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Microfacet", deny_unknown_fields)]
struct MicrofacetRepr<D, F> {
    distribution: D,
    #[serde(default, skip_serializing_if = "is_default")]
    masking: Masking,
    fresnel: F,
}

impl<D, F> Serialize for Microfacet<D, F>
where
    D: NormalDistribution + Serialize,
    F: Fresnel + Serialize,
{
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        MicrofacetRepr {
            distribution: self.distribution(),
            masking: self.masking(),
            fresnel: self.fresnel(),
        }
        .serialize(serializer)
    }
}

impl<'de, D, F> Deserialize<'de> for Microfacet<D, F>
where
    D: NormalDistribution + Deserialize<'de>,
    F: Fresnel + Deserialize<'de>,
{
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = MicrofacetRepr::<D, F>::deserialize(deserializer)?;
        Ok(Microfacet::new(r.distribution, r.masking, r.fresnel))
    }
}

/// [`RoughDielectric`] on the wire: `{ "distribution": …, "eta": 1.5 }`, and `"masking"`
/// and `"mode": "importance"` when they are not the defaults.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "RoughDielectric", deny_unknown_fields)]
struct RoughDielectricRepr<D> {
    distribution: D,
    eta: Eta,
    #[serde(default, skip_serializing_if = "is_default")]
    masking: Masking,
    #[serde(default, skip_serializing_if = "is_default")]
    mode: TransportMode,
}

impl<D: NormalDistribution + Serialize> Serialize for RoughDielectric<D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        RoughDielectricRepr {
            distribution: self.distribution(),
            eta: self.eta(),
            masking: self.masking(),
            mode: self.mode(),
        }
        .serialize(serializer)
    }
}

impl<'de, D: NormalDistribution + Deserialize<'de>> Deserialize<'de> for RoughDielectric<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = RoughDielectricRepr::<D>::deserialize(deserializer)?;
        Ok(RoughDielectric::new(r.distribution, r.eta)
            .with_masking(r.masking)
            .with_mode(r.mode))
    }
}
