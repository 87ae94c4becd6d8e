//! The choice of integrator.

use crate::path::PathTracer;
use crate::ray::Ray;
use crate::scene::Scene;
use crate::whitted::Whitted;
use lobe::Vec3;
use lobe::verify::Pcg32;

/// An estimator of the radiance along a camera ray.
#[derive(Clone, Debug)]
pub enum Integrator {
    /// Unbiased path tracing (the default).
    Path(PathTracer),
    /// Whitted-style recursive ray tracing.
    Whitted(Whitted),
}

impl Integrator {
    /// One sample of the radiance arriving at the camera along `ray`.
    #[inline]
    pub fn radiance(&self, scene: &Scene, ray: Ray, rng: &mut Pcg32) -> Vec3 {
        match self {
            Self::Path(p) => p.radiance(scene, ray, rng),
            Self::Whitted(w) => w.radiance(scene, ray, rng),
        }
    }
}
