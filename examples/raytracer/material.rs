//! [`Material`]: a `lobe` model behind a trait object, with what the integrators need to know
//! about it.

use lobe::bxdf::{Bxdf, Lobes, ThinDielectric};
use lobe::{ComplexIor, Eta, Vec2, Vec3};

/// A scattering model as the renderer holds it: any `lobe` model with RGB values.
pub type DynBxdf = dyn Bxdf<Spectrum = Vec3> + Send + Sync;

/// The perfectly specular part of a material as the Whitted integrator sees it: which
/// recursive rays to trace (seed 003, "Mirror reflection", "Refraction at boundary of
/// media"). The path tracer ignores it and uses the model's own `sample`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interface {
    /// Nothing to trace recursively.
    None,
    /// Mirror reflection off a metal of this complex index, with the exact conductor
    /// Fresnel reflectance.
    Conductor(ComplexIor<Vec3>),
    /// A dielectric boundary of relative index `η`: reflection weighted by the exact Fresnel
    /// reflectance `F`, refraction by `1 − F`.
    Dielectric(Eta),
    /// A thin dielectric sheet: reflection weighted by the sheet's total reflectance `R'`,
    /// straight-through transmission by `1 − R'`.
    Thin(ThinDielectric),
    /// A clear coat of relative index `η` over the model's diffuse base: reflection
    /// weighted by `F`; the base is lit directly.
    Coat(Eta),
}

/// A surface's material (seed 003: "separate class: Material … its job is to compute the
/// color"): the model, its lobes, its Whitted description and its ambient reflectance.
pub struct Material {
    /// A short name, for the label layout.
    pub name: String,
    /// The scattering model.
    pub bsdf: Box<DynBxdf>,
    /// `bsdf.lobes()`, cached.
    pub lobes: Lobes,
    /// What the Whitted integrator traces recursively.
    pub interface: Interface,
    /// The directional albedo of the model's non-delta lobes at normal incidence: the
    /// Whitted integrator's ambient reflectance.
    pub ambient: Vec3,
}

impl Material {
    /// A material around `bsdf`, named `name`, with no Whitted recursion.
    pub fn new(name: &str, bsdf: impl Bxdf<Spectrum = Vec3> + Send + Sync + 'static) -> Self {
        let ambient = non_delta_albedo(&bsdf);
        Self {
            name: name.to_owned(),
            lobes: bsdf.lobes(),
            bsdf: Box::new(bsdf),
            interface: Interface::None,
            ambient,
        }
    }

    /// The same material, traced by the Whitted integrator through `interface`.
    pub fn with_interface(self, interface: Interface) -> Self {
        Self { interface, ..self }
    }

    /// True when light crosses the surface: the shading frame must then keep the surface's
    /// own orientation (it says which side is inside).
    pub fn transmits(&self) -> bool {
        self.lobes.is_transmissive()
    }
}

/// The albedo of the non-delta lobes at normal incidence, by 32 × 32 stratified samples of
/// the model's own sampler (deterministic).
fn non_delta_albedo(bsdf: &impl Bxdf<Spectrum = Vec3>) -> Vec3 {
    const N: usize = 32;
    let mut sum = Vec3::ZERO;
    for i in 0..N {
        for j in 0..N {
            let u = Vec2::new((i as f32 + 0.5) / N as f32, (j as f32 + 0.5) / N as f32);
            // A low-discrepancy lobe choice decorrelated from the direction.
            let uc = ((i * N + j) as f32 * 0.618_034).fract();
            if let Some(s) = bsdf.sample(Vec3::Z, u, uc)
                && !s.is_specular()
                && s.pdf > 0.0
            {
                sum += s.weight();
            }
        }
    }
    let a = sum / (N * N) as f32;
    if a.is_finite() { a } else { Vec3::ZERO }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lobe::bxdf::{Lambert, Mono, SmoothDielectric};

    #[test]
    fn mono_repeats_the_channel_and_ambient_skips_deltas() {
        let glass = Material::new(
            "glass",
            Mono::new(SmoothDielectric::new(Eta::new(1.5).unwrap())),
        );
        assert!(glass.transmits());
        assert_eq!(glass.ambient, Vec3::ZERO);
        let s = glass.bsdf.sample(Vec3::Z, Vec2::splat(0.5), 0.9).unwrap();
        assert_eq!(s.f.x, s.f.z);
        let white = Material::new("white", Lambert::new(Vec3::splat(0.5)).unwrap());
        assert!((white.ambient - Vec3::splat(0.5)).abs().max_element() < 1e-3);
        assert!(!white.transmits());
    }
}
