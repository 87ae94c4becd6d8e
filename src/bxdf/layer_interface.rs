//! What a layered BSDF needs of its top interface.

use super::{CompensatedDielectric, Prepare, RoughDielectric, SmoothDielectric, TransportMode};
use crate::microfacet::NormalDistribution;
use crate::param::Eta;

/// A dielectric interface that can be the top of a [`Layered`](super::Layered) BSDF: a
/// monochrome BSDF that reflects and transmits light, both ways, with its relative index
/// `η = η_inside / η_outside` and the same interface for the other transport mode.
///
/// The layered random walk crosses the interface both ways. On the way in from the viewer it uses
/// the interface in radiance mode, whatever mode it was given in (`Layered::new` takes
/// [`for_transport`](Self::for_transport)`(Radiance)`: the `1/η'²` of refraction applies), and
/// where it samples the interface from the light's side (the exit direction `wi`, pbrt-v4's `wis`)
/// it uses the adjoint, [`for_transport`](Self::for_transport)`(Importance)`, whose value
/// `f*(wi, w) = f(w, wi)` is the one the path needs (Veach 1997, §5.2; pbrt-v4 §14.3.2). An
/// interface is either made of delta lobes only ([`SmoothDielectric`]) or of lobes with a density
/// only ([`RoughDielectric`]); the walk's estimators choose their form from [`Prepare::lobes`].
///
/// Implemented for [`RoughDielectric`], [`SmoothDielectric`] and [`CompensatedDielectric`]
/// (a rough coat that keeps the energy its microfacets scatter more than once: the stack's
/// white furnace then holds to the compensated interface's own accuracy). An interface of
/// your own should be `Clone`, so that [`Layered`](super::Layered) runs batched
/// ([`Batch`](crate::batch::Batch)).
pub trait LayerInterface: Prepare<Spectrum = f32> + Sized {
    /// The relative index of refraction `η = η_inside / η_outside`.
    #[must_use]
    fn eta(&self) -> Eta;

    /// The same interface for the transport mode `mode`.
    #[must_use]
    fn for_transport(&self, mode: TransportMode) -> Self;
}

impl<D: NormalDistribution + Clone> LayerInterface for RoughDielectric<D> {
    #[inline]
    fn eta(&self) -> Eta {
        RoughDielectric::eta(self)
    }

    #[inline]
    fn for_transport(&self, mode: TransportMode) -> Self {
        self.clone().with_mode(mode)
    }
}

impl LayerInterface for SmoothDielectric {
    #[inline]
    fn eta(&self) -> Eta {
        SmoothDielectric::eta(self)
    }

    #[inline]
    fn for_transport(&self, mode: TransportMode) -> Self {
        self.with_mode(mode)
    }
}

impl<D: NormalDistribution + Clone> LayerInterface for CompensatedDielectric<D> {
    #[inline]
    fn eta(&self) -> Eta {
        self.inner().eta()
    }

    /// The same interface and tables in `mode`: the compensation lobes follow the inner
    /// interface's transport mode.
    #[inline]
    fn for_transport(&self, mode: TransportMode) -> Self {
        CompensatedDielectric::with_albedo(self.inner().clone().with_mode(mode), *self.albedo())
    }
}
