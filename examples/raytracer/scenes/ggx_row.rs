//! Rows of GGX conductors from α = 0.1 to 1 in a white furnace, with and without energy
//! compensation (issue 11): the README's side-by-side.
//!
//! The upper row reflects with `F = 1` (no Fresnel): a lossless conductor, which in a
//! uniform environment of radiance 1 should vanish into it. The single-scattering model
//! loses the light that bounces between microfacets, so its spheres darken as they roughen
//! (at α = 1 to about a third at normal incidence); compensated (Kulla & Conty 2017) they
//! vanish. The lower row is gold: compensated, the rough spheres keep their brightness and
//! their colour deepens, as light that bounces more than once is tinted more than once.

use crate::camera::Camera;
use crate::environment::Environment;
use crate::material::Material;
use crate::scene::{Scene, SceneBuilder};
use lobe::bxdf::Microfacet;
use lobe::fresnel::{Conductor, NoFresnel};
use lobe::metals;
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, ParamError, Vec3};

/// Spheres per row.
pub const COUNT: usize = 10;

/// The row's widths: 0.1, 0.2, …, 1.
pub fn alphas() -> [f32; COUNT] {
    core::array::from_fn(|i| 0.1 * (i + 1) as f32)
}

/// The scene: the `F = 1` row above the gold row, compensated or not.
///
/// # Errors
/// A [`ParamError`] if a model refuses its parameters.
pub fn build(aspect: f32, compensated: bool) -> Result<Scene, ParamError> {
    let mut b = SceneBuilder::new();
    let gold = metals::GOLD.rgb();
    let (radius, spacing) = (0.45, 1.0);
    for (i, alpha) in alphas().into_iter().enumerate() {
        let x = (i as f32 - 0.5 * (COUNT - 1) as f32) * spacing;
        let ggx = Ggx::isotropic(Alpha::new(alpha)?);
        let white = Microfacet::new(ggx, Masking::HeightCorrelated, NoFresnel::<Vec3>::new());
        let metal = Microfacet::new(ggx, Masking::HeightCorrelated, Conductor { ior: gold });
        let (white, metal) = if compensated {
            (
                Material::new("GGX F = 1, compensated", white.with_energy_compensation()?),
                Material::new("GGX gold, compensated", metal.with_energy_compensation()?),
            )
        } else {
            (
                Material::new("GGX F = 1", white),
                Material::new("GGX gold", metal),
            )
        };
        let (w, m) = (b.material(white), b.material(metal));
        b.sphere(Vec3::new(x, 0.55, 0.0), radius, w);
        b.sphere(Vec3::new(x, -0.55, 0.0), radius, m);
    }
    b.environment(Environment::Constant(Vec3::ONE));
    let camera = Camera::look_at(Vec3::new(0.0, 0.0, 14.0), Vec3::ZERO, Vec3::Y, 10.5, aspect);
    Ok(b.build(camera))
}
