//! The coated models: [`Glazed`], [`Plastic`] and [`CompensatedPlastic`], as the base's
//! reflectance and the coat's index (and, for the plastics, its distribution). What the constructors compute from them
//! (the coat's average Fresnel, the plastic's table of coat albedos) is not written: the
//! constructor computes it again on the way in.

use super::refused;
use crate::bxdf::{CompensatedPlastic, Glazed, Plastic};
use crate::microfacet::NormalDistribution;
use crate::param::Eta;
use crate::spectrum::Spectrum;
use crate::tables::TabulatedDielectric;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Glazed`] on the wire: `{ "reflectance": …, "eta": 1.5 }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Glazed", deny_unknown_fields)]
struct GlazedRepr<S> {
    reflectance: S,
    eta: Eta,
}

impl<S: Spectrum + Serialize> Serialize for Glazed<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        GlazedRepr {
            reflectance: self.reflectance(),
            eta: self.eta(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Glazed<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = GlazedRepr::<S>::deserialize(deserializer)?;
        Glazed::new(r.reflectance, r.eta).map_err(refused)
    }
}

/// [`Plastic`] on the wire: `{ "reflectance": …, "distribution": …, "eta": 1.5 }`, in the
/// constructor's order. Serialised with `D = &D`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Plastic", deny_unknown_fields)]
struct PlasticRepr<S, D> {
    reflectance: S,
    distribution: D,
    eta: Eta,
}

impl<D, S> Serialize for Plastic<D, S>
where
    D: NormalDistribution + Serialize,
    S: Spectrum + Serialize,
{
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        PlasticRepr {
            reflectance: self.reflectance(),
            distribution: self.distribution(),
            eta: self.eta(),
        }
        .serialize(serializer)
    }
}

impl<'de, D, S> Deserialize<'de> for Plastic<D, S>
where
    D: NormalDistribution + Deserialize<'de>,
    S: Spectrum + Deserialize<'de>,
{
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = PlasticRepr::<S, D>::deserialize(deserializer)?;
        Plastic::new(r.reflectance, r.distribution, r.eta).map_err(refused)
    }
}

/// [`CompensatedPlastic`] on the wire: as [`Plastic`]; the type says the coat is compensated.
impl<D, S> Serialize for CompensatedPlastic<D, S>
where
    D: TabulatedDielectric + Serialize,
    S: Spectrum + Serialize,
{
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        PlasticRepr {
            reflectance: self.reflectance(),
            distribution: self.distribution(),
            eta: self.eta(),
        }
        .serialize(serializer)
    }
}

impl<'de, D, S> Deserialize<'de> for CompensatedPlastic<D, S>
where
    D: TabulatedDielectric + Deserialize<'de>,
    S: Spectrum + Deserialize<'de>,
{
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = PlasticRepr::<S, D>::deserialize(deserializer)?;
        Plastic::compensated(r.reflectance, r.distribution, r.eta).map_err(refused)
    }
}
