//! The Fresnel terms: [`Schlick`] (`f0`), [`Conductor`] (`ior`), [`Dielectric`] (`eta`) and
//! [`NoFresnel`] (no parameter).

use crate::fresnel::{Conductor, Dielectric, NoFresnel, Schlick};
use crate::param::{ComplexIor, Eta};
use crate::spectrum::Spectrum;

wire! {
    /// [`Schlick`] on the wire: `{ "f0": 0.04 }`, one number per channel.
    impl[S: Spectrum] Schlick<S> as "Schlick" SchlickRepr<S> |m| {
        f0: S = m.f0(),
    } via |r| Schlick::new(r.f0)
}

wire! {
    /// [`Conductor`] on the wire: `{ "ior": { "eta": …, "k": … } }`; the index validates
    /// itself.
    impl[S: Spectrum] Conductor<S> as "Conductor" ConductorRepr<S> |m| {
        #[serde(bound(
            serialize = "S: Spectrum + serde::Serialize",
            deserialize = "S: Spectrum + serde::Deserialize<'de>"
        ))]
        ior: ComplexIor<S> = m.ior,
    } via |r| Ok(Conductor { ior: r.ior })
}

wire! {
    /// [`Dielectric`] on the wire: `{ "eta": 1.5 }`; the index validates itself.
    impl[] Dielectric as "Dielectric" DielectricRepr |m| {
        eta: Eta = m.eta,
    } via |r| Ok(Dielectric { eta: r.eta })
}

wire! {
    /// [`NoFresnel`] on the wire: `{}`, a term without parameters.
    impl[S] NoFresnel<S> as "NoFresnel" NoFresnelRepr |_m| {} via |_r| Ok(NoFresnel::new())
}
