//! The glossy models: [`Phong`] and [`BlinnPhong`], as `kd`, `ks`, the exponent (and
//! Blinn-Phong's form), and [`Sheen`], as its colour and roughness (and its masking). The lobes'
//! normalisations, sampling weights and the sheen's albedo table are computed again on the
//! way in.

use super::is_default;
use crate::bxdf::{BlinnPhong, BlinnPhongForm, Phong, Sheen};
use crate::spectrum::Spectrum;

wire! {
    /// [`Phong`] on the wire: `{ "kd": …, "ks": …, "exponent": 50 }`.
    impl[S: Spectrum] Phong<S> as "Phong" PhongRepr<S> |m| {
        kd: S = m.kd(),
        ks: S = m.ks(),
        exponent: f32 = m.exponent(),
    } via |r| Phong::new(r.kd, r.ks, r.exponent)
}

wire! {
    /// [`BlinnPhong`] on the wire: `{ "kd": …, "ks": …, "exponent": 50 }`, and
    /// `"form": "modified"` for the unnormalised lobe.
    impl[S: Spectrum] BlinnPhong<S> as "BlinnPhong" BlinnPhongRepr<S> |m| {
        kd: S = m.kd(),
        ks: S = m.ks(),
        exponent: f32 = m.exponent(),
        #[serde(default, skip_serializing_if = "is_default")]
        form: BlinnPhongForm = m.form(),
    } via |r| BlinnPhong::new(r.kd, r.ks, r.exponent, r.form)
}

wire! {
    /// [`Sheen`] on the wire: `{ "color": …, "roughness": 0.5 }`, and `"exact_smith": true`
    /// for the exact Smith masking instead of the fit.
    impl[S: Spectrum] Sheen<S> as "Sheen" SheenRepr<S> |m| {
        color: S = m.color(),
        roughness: f32 = m.roughness(),
        #[serde(default, skip_serializing_if = "is_default")]
        exact_smith: bool = m.has_exact_smith(),
    } via |r| {
        if r.exact_smith {
            Sheen::new_exact_smith(r.color, r.roughness)
        } else {
            Sheen::new(r.color, r.roughness)
        }
    }
}
