//! The delta models: [`Mirror`], [`SmoothDielectric`] and [`ThinDielectric`].

use super::is_default;
use crate::bxdf::{Mirror, SmoothDielectric, ThinDielectric, TransportMode};
use crate::fresnel::Fresnel;
use crate::param::Eta;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Mirror`] on the wire: `{ "fresnel": … }`. Serialised with `F = &F`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Mirror", deny_unknown_fields)]
struct MirrorRepr<F> {
    fresnel: F,
}

impl<F: Fresnel + Serialize> Serialize for Mirror<F> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        MirrorRepr {
            fresnel: self.fresnel(),
        }
        .serialize(serializer)
    }
}

impl<'de, F: Fresnel + Deserialize<'de>> Deserialize<'de> for Mirror<F> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = MirrorRepr::<F>::deserialize(deserializer)?;
        Ok(Mirror::new(r.fresnel))
    }
}

/// [`SmoothDielectric`] on the wire: `{ "eta": 1.5 }`, and `"mode": "importance"` when it
/// transports importance.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "SmoothDielectric", deny_unknown_fields)]
struct SmoothDielectricRepr {
    eta: Eta,
    #[serde(default, skip_serializing_if = "is_default")]
    mode: TransportMode,
}

impl Serialize for SmoothDielectric {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        SmoothDielectricRepr {
            eta: self.eta(),
            mode: self.mode(),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for SmoothDielectric {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = SmoothDielectricRepr::deserialize(deserializer)?;
        Ok(SmoothDielectric::new(r.eta).with_mode(r.mode))
    }
}

/// [`ThinDielectric`] on the wire: `{ "eta": 1.5 }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "ThinDielectric", deny_unknown_fields)]
struct ThinDielectricRepr {
    eta: Eta,
}

impl Serialize for ThinDielectric {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        ThinDielectricRepr { eta: self.eta() }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for ThinDielectric {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = ThinDielectricRepr::deserialize(deserializer)?;
        Ok(ThinDielectric::new(r.eta))
    }
}
