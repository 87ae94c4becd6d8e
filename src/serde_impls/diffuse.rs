//! The diffuse models: [`Lambert`], [`OrenNayar`], [`EnergyPreservingOrenNayar`] and
//! [`DisneyDiffuse`], and [`DiffuseTransmission`], as their constructors' parameters.
//! Oren-Nayar's `A`, `B` and EON's single- and multiple-scattering factors are computed again
//! on the way in.

use super::is_default;
use crate::bxdf::{
    DiffuseTransmission, DisneyDiffuse, EnergyPreservingOrenNayar, Lambert, OrenNayar,
};
use crate::param::Roughness;
use crate::spectrum::Spectrum;

wire! {
    /// [`Lambert`] on the wire: `{ "reflectance": [0.8, 0.8, 0.8] }`.
    impl[S: Spectrum] Lambert<S> as "Lambert" LambertRepr<S> |m| {
        reflectance: S = m.albedo(),
    } via |r| Lambert::new(r.reflectance)
}

wire! {
    /// [`OrenNayar`] on the wire: `{ "reflectance": …, "sigma": 0.35 }`, `σ` in radians.
    impl[S: Spectrum] OrenNayar<S> as "OrenNayar" OrenNayarRepr<S> |m| {
        reflectance: S = m.reflectance(),
        sigma: f32 = m.sigma(),
    } via |r| OrenNayar::new(r.reflectance, r.sigma)
}

wire! {
    /// [`EnergyPreservingOrenNayar`] on the wire: `{ "reflectance": …, "roughness": 0.5 }`,
    /// and `"exact_albedo": true` for the exact compensation instead of the fit.
    impl[S: Spectrum] EnergyPreservingOrenNayar<S> as "EnergyPreservingOrenNayar" EonRepr<S> |m| {
        reflectance: S = m.reflectance(),
        roughness: f32 = m.roughness(),
        #[serde(default, skip_serializing_if = "is_default")]
        exact_albedo: bool = m.is_exact(),
    } via |r| {
        EnergyPreservingOrenNayar::new(r.reflectance, r.roughness)
            .map(|eon| if r.exact_albedo { eon.with_exact_albedo() } else { eon })
    }
}

wire! {
    /// [`DisneyDiffuse`] on the wire: `{ "reflectance": …, "roughness": 0.5 }` (perceptual
    /// roughness; it validates itself).
    impl[S: Spectrum] DisneyDiffuse<S> as "DisneyDiffuse" DisneyDiffuseRepr<S> |m| {
        reflectance: S = m.reflectance(),
        roughness: Roughness = m.roughness(),
    } via |r| DisneyDiffuse::new(r.reflectance, r.roughness)
}

wire! {
    /// [`DiffuseTransmission`] on the wire: `{ "reflectance": …, "transmittance": … }`.
    impl[S: Spectrum] DiffuseTransmission<S> as "DiffuseTransmission"
        DiffuseTransmissionRepr<S> |m| {
        reflectance: S = m.reflectance(),
        transmittance: S = m.transmittance(),
    } via |r| DiffuseTransmission::new(r.reflectance, r.transmittance)
}
