//! The Fresnel terms: [`Schlick`] (`f0`), [`Conductor`] (`ior`), [`Dielectric`] (`eta`) and
//! [`NoFresnel`] (no parameter).

use super::refused;
use crate::fresnel::{Conductor, Dielectric, NoFresnel, Schlick};
use crate::param::{ComplexIor, Eta};
use crate::spectrum::Spectrum;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Schlick`] on the wire: `{ "f0": 0.04 }`, one number per channel.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Schlick", deny_unknown_fields)]
struct SchlickRepr<S> {
    f0: S,
}

impl<S: Spectrum + Serialize> Serialize for Schlick<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        SchlickRepr { f0: self.f0() }.serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Schlick<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = SchlickRepr::<S>::deserialize(deserializer)?;
        Schlick::new(r.f0).map_err(refused)
    }
}

/// [`Conductor`] on the wire: `{ "ior": { "eta": …, "k": … } }`; the index validates itself.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Conductor", deny_unknown_fields)]
struct ConductorRepr<S: Spectrum> {
    ior: ComplexIor<S>,
}

impl<S: Spectrum + Serialize> Serialize for Conductor<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        ConductorRepr { ior: self.ior }.serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Conductor<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = ConductorRepr::<S>::deserialize(deserializer)?;
        Ok(Conductor { ior: r.ior })
    }
}

/// [`Dielectric`] on the wire: `{ "eta": 1.5 }`; the index validates itself.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Dielectric", deny_unknown_fields)]
struct DielectricRepr {
    eta: Eta,
}

impl Serialize for Dielectric {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        DielectricRepr { eta: self.eta }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Dielectric {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = DielectricRepr::deserialize(deserializer)?;
        Ok(Dielectric { eta: r.eta })
    }
}

/// [`NoFresnel`] on the wire: `{}`, a term without parameters.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "NoFresnel", deny_unknown_fields)]
struct NoFresnelRepr {}

impl<S> Serialize for NoFresnel<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        NoFresnelRepr {}.serialize(serializer)
    }
}

impl<'de, S> Deserialize<'de> for NoFresnel<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        NoFresnelRepr::deserialize(deserializer)?;
        Ok(NoFresnel::new())
    }
}
