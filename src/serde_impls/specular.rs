//! The delta models: [`Mirror`], [`SmoothDielectric`] and [`ThinDielectric`].

use super::is_default;
use crate::bxdf::{Mirror, SmoothDielectric, ThinDielectric, TransportMode};
use crate::fresnel::Fresnel;
use crate::param::Eta;

wire! {
    /// [`Mirror`] on the wire: `{ "fresnel": … }`.
    impl[F: Fresnel] Mirror<F> as "Mirror" MirrorRepr<F> |m| {
        fresnel: F = m.fresnel(),
    } via |r| Ok(Mirror::new(r.fresnel))
}

wire! {
    /// [`SmoothDielectric`] on the wire: `{ "eta": 1.5 }`, and `"mode": "importance"` when it
    /// transports importance.
    impl[] SmoothDielectric as "SmoothDielectric" SmoothDielectricRepr |m| {
        eta: Eta = m.eta(),
        #[serde(default, skip_serializing_if = "is_default")]
        mode: TransportMode = m.mode(),
    } via |r| Ok(SmoothDielectric::new(r.eta).with_mode(r.mode))
}

wire! {
    /// [`ThinDielectric`] on the wire: `{ "eta": 1.5 }`.
    impl[] ThinDielectric as "ThinDielectric" ThinDielectricRepr |m| {
        eta: Eta = m.eta(),
    } via |r| Ok(ThinDielectric::new(r.eta))
}
