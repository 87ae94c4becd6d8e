//! The diffuse-plus-glossy models: [`Phong`] and [`BlinnPhong`], as `kd`, `ks`, the exponent
//! (and Blinn-Phong's form). The lobes' normalisations and sampling weights are computed
//! again on the way in.

use super::{is_default, refused};
use crate::bxdf::{BlinnPhong, BlinnPhongForm, Phong};
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
