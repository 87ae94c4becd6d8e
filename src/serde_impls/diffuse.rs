//! The diffuse models: [`Lambert`], [`OrenNayar`], [`EnergyPreservingOrenNayar`] and
//! [`DisneyDiffuse`], and [`DiffuseTransmission`], as their constructors' parameters. Oren-Nayar's `A`, `B` and EON's
//! single- and multiple-scattering factors are computed again on the way in.

use super::{is_default, refused};
use crate::bxdf::{
    DiffuseTransmission, DisneyDiffuse, EnergyPreservingOrenNayar, Lambert, OrenNayar,
};
use crate::param::Roughness;
use crate::spectrum::Spectrum;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Lambert`] on the wire: `{ "reflectance": [0.8, 0.8, 0.8] }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Lambert", deny_unknown_fields)]
struct LambertRepr<S> {
    reflectance: S,
}

impl<S: Spectrum + Serialize> Serialize for Lambert<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        LambertRepr {
            reflectance: self.albedo(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Lambert<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = LambertRepr::<S>::deserialize(deserializer)?;
        Lambert::new(r.reflectance).map_err(refused)
    }
}

/// [`OrenNayar`] on the wire: `{ "reflectance": …, "sigma": 0.35 }`, `σ` in radians.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "OrenNayar", deny_unknown_fields)]
struct OrenNayarRepr<S> {
    reflectance: S,
    sigma: f32,
}

impl<S: Spectrum + Serialize> Serialize for OrenNayar<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        OrenNayarRepr {
            reflectance: self.reflectance(),
            sigma: self.sigma(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for OrenNayar<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = OrenNayarRepr::<S>::deserialize(deserializer)?;
        OrenNayar::new(r.reflectance, r.sigma).map_err(refused)
    }
}

/// [`EnergyPreservingOrenNayar`] on the wire: `{ "reflectance": …, "roughness": 0.5 }`, and
/// `"exact_albedo": true` for the exact compensation instead of the fit.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "EnergyPreservingOrenNayar", deny_unknown_fields)]
struct EonRepr<S> {
    reflectance: S,
    roughness: f32,
    #[serde(default, skip_serializing_if = "is_default")]
    exact_albedo: bool,
}

impl<S: Spectrum + Serialize> Serialize for EnergyPreservingOrenNayar<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        EonRepr {
            reflectance: self.reflectance(),
            roughness: self.roughness(),
            exact_albedo: self.is_exact(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for EnergyPreservingOrenNayar<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = EonRepr::<S>::deserialize(deserializer)?;
        let eon = EnergyPreservingOrenNayar::new(r.reflectance, r.roughness).map_err(refused)?;
        Ok(if r.exact_albedo {
            eon.with_exact_albedo()
        } else {
            eon
        })
    }
}

/// [`DisneyDiffuse`] on the wire: `{ "reflectance": …, "roughness": 0.5 }` (perceptual
/// roughness; it validates itself).
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "DisneyDiffuse", deny_unknown_fields)]
struct DisneyDiffuseRepr<S> {
    reflectance: S,
    roughness: Roughness,
}

impl<S: Spectrum + Serialize> Serialize for DisneyDiffuse<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        DisneyDiffuseRepr {
            reflectance: self.reflectance(),
            roughness: self.roughness(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for DisneyDiffuse<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = DisneyDiffuseRepr::<S>::deserialize(deserializer)?;
        DisneyDiffuse::new(r.reflectance, r.roughness).map_err(refused)
    }
}

/// [`DiffuseTransmission`] on the wire: `{ "reflectance": …, "transmittance": … }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "DiffuseTransmission", deny_unknown_fields)]
struct DiffuseTransmissionRepr<S> {
    reflectance: S,
    transmittance: S,
}

impl<S: Spectrum + Serialize> Serialize for DiffuseTransmission<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        DiffuseTransmissionRepr {
            reflectance: self.reflectance(),
            transmittance: self.transmittance(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for DiffuseTransmission<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = DiffuseTransmissionRepr::<S>::deserialize(deserializer)?;
        DiffuseTransmission::new(r.reflectance, r.transmittance).map_err(refused)
    }
}
