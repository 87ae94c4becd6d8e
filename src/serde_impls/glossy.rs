//! The glossy models: [`Phong`] and [`BlinnPhong`], as `kd`, `ks`, the exponent (and
//! Blinn-Phong's form), and [`Sheen`], as its colour and roughness. The lobes'
//! normalisations, sampling weights and the sheen's albedo table are computed again on the
//! way in.

use super::{is_default, refused};
use crate::bxdf::{BlinnPhong, BlinnPhongForm, Phong, Sheen};
use crate::spectrum::Spectrum;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// [`Phong`] on the wire: `{ "kd": …, "ks": …, "exponent": 50 }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Phong", deny_unknown_fields)]
struct PhongRepr<S> {
    kd: S,
    ks: S,
    exponent: f32,
}

impl<S: Spectrum + Serialize> Serialize for Phong<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        PhongRepr {
            kd: self.kd(),
            ks: self.ks(),
            exponent: self.exponent(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Phong<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = PhongRepr::<S>::deserialize(deserializer)?;
        Phong::new(r.kd, r.ks, r.exponent).map_err(refused)
    }
}

/// [`BlinnPhong`] on the wire: `{ "kd": …, "ks": …, "exponent": 50 }`, and
/// `"form": "modified"` for the unnormalised lobe.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "BlinnPhong", deny_unknown_fields)]
struct BlinnPhongRepr<S> {
    kd: S,
    ks: S,
    exponent: f32,
    #[serde(default, skip_serializing_if = "is_default")]
    form: BlinnPhongForm,
}

impl<S: Spectrum + Serialize> Serialize for BlinnPhong<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        BlinnPhongRepr {
            kd: self.kd(),
            ks: self.ks(),
            exponent: self.exponent(),
            form: self.form(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for BlinnPhong<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = BlinnPhongRepr::<S>::deserialize(deserializer)?;
        BlinnPhong::new(r.kd, r.ks, r.exponent, r.form).map_err(refused)
    }
}

/// [`Sheen`] on the wire: `{ "color": …, "roughness": 0.5 }`.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "Sheen", deny_unknown_fields)]
struct SheenRepr<S> {
    color: S,
    roughness: f32,
}

impl<S: Spectrum + Serialize> Serialize for Sheen<S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        SheenRepr {
            color: self.color(),
            roughness: self.roughness(),
        }
        .serialize(serializer)
    }
}

impl<'de, S: Spectrum + Deserialize<'de>> Deserialize<'de> for Sheen<S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = SheenRepr::<S>::deserialize(deserializer)?;
        Sheen::new(r.color, r.roughness).map_err(refused)
    }
}
