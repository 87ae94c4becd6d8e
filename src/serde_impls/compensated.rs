//! The energy-compensated models: [`CompensatedMicrofacet`] and [`CompensatedDielectric`], as
//! the single-scattering model's parameters (and the compensation's kind). The albedo tables
//! are not written: the constructor reads them from the crate's tables again on the way in,
//! so a model built with a table of its own (`with_albedo`) cannot be written at all.

use super::{is_default, refused};
use crate::bxdf::{
    CompensatedDielectric, CompensatedMicrofacet, Compensation, Microfacet, RoughDielectric,
    TransportMode,
};
use crate::fresnel::FresnelAverage;
use crate::microfacet::Masking;
use crate::param::Eta;
use crate::tables::{TabulatedAlbedo, TabulatedDielectric};
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Error as _, Serialize, Serializer};

/// The refusal to write a compensated model whose albedo is not the crate's own.
const OWN_TABLE: &str = "a compensated model built with a table of its own (`with_albedo`) \
                         cannot be written: a file holds the crate's tables only";

/// [`CompensatedMicrofacet`] on the wire: `{ "distribution": …, "fresnel": … }` (the
/// [`Microfacet`]'s, whose masking is height-correlated), and `"compensation": "turquin"`
/// when it is not Kulla & Conty's. Serialised with `D = &D` and `F = &F`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "CompensatedMicrofacet", deny_unknown_fields)]
struct CompensatedMicrofacetRepr<D, F> {
    distribution: D,
    fresnel: F,
    #[serde(default, skip_serializing_if = "is_default")]
    compensation: Compensation,
}

impl<D, F> Serialize for CompensatedMicrofacet<D, F>
where
    D: TabulatedAlbedo + Serialize,
    F: FresnelAverage + Serialize,
{
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let inner = self.inner();
        let own = inner.masking() == Masking::HeightCorrelated
            && inner.distribution().conductor_albedo().as_ref() == Ok(self.albedo());
        if !own {
            return Err(S::Error::custom(OWN_TABLE));
        }
        CompensatedMicrofacetRepr {
            distribution: inner.distribution(),
            fresnel: inner.fresnel(),
            compensation: self.compensation(),
        }
        .serialize(serializer)
    }
}

impl<'de, D, F> Deserialize<'de> for CompensatedMicrofacet<D, F>
where
    D: TabulatedAlbedo + Deserialize<'de>,
    F: FresnelAverage + Deserialize<'de>,
{
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = CompensatedMicrofacetRepr::<D, F>::deserialize(deserializer)?;
        let inner = Microfacet::new(r.distribution, Masking::HeightCorrelated, r.fresnel);
        CompensatedMicrofacet::new(inner, r.compensation).map_err(refused)
    }
}

/// [`CompensatedDielectric`] on the wire: `{ "distribution": …, "eta": 1.5 }` (the
/// [`RoughDielectric`]'s, whose masking is height-correlated), and `"mode": "importance"`
/// when it is not the default.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "CompensatedDielectric", deny_unknown_fields)]
struct CompensatedDielectricRepr<D> {
    distribution: D,
    eta: Eta,
    #[serde(default, skip_serializing_if = "is_default")]
    mode: TransportMode,
}

impl<D: TabulatedDielectric + Serialize> Serialize for CompensatedDielectric<D> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let inner = self.inner();
        let own = inner.masking() == Masking::HeightCorrelated
            && inner.distribution().dielectric_albedo(inner.eta()).as_ref() == Ok(self.albedo());
        if !own {
            return Err(S::Error::custom(OWN_TABLE));
        }
        CompensatedDielectricRepr {
            distribution: inner.distribution(),
            eta: inner.eta(),
            mode: inner.mode(),
        }
        .serialize(serializer)
    }
}

impl<'de, D: TabulatedDielectric + Deserialize<'de>> Deserialize<'de> for CompensatedDielectric<D> {
    fn deserialize<De: Deserializer<'de>>(deserializer: De) -> Result<Self, De::Error> {
        let r = CompensatedDielectricRepr::<D>::deserialize(deserializer)?;
        RoughDielectric::new(r.distribution, r.eta)
            .with_mode(r.mode)
            .with_energy_compensation()
            .map_err(refused)
    }
}
