//! White furnace scenes: lossless materials inside a uniform environment of radiance 1.
//!
//! A surface that neither absorbs nor emits, lit by the same radiance from every direction,
//! reflects exactly that radiance: it vanishes into the background. Whatever shows is a
//! loss (single-scattering microfacet models lose a little at grazing angles) or a bug.

use crate::camera::Camera;
use crate::environment::Environment;
use crate::material::{Interface, Material};
use crate::scene::{Scene, SceneBuilder};
use lobe::bxdf::Mono;
use lobe::bxdf::{Glazed, Lambert, Microfacet, SmoothDielectric};
use lobe::fresnel::NoFresnel;
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, Eta, ParamError, Vec3};

/// The white Lambert sphere (ρ = 1).
pub fn white_lambert() -> Result<Material, ParamError> {
    Ok(Material::new("white Lambert", Lambert::new(Vec3::ONE)?))
}

/// A GGX conductor with `F = 1` (no Fresnel) and width `alpha`.
pub fn ggx_no_fresnel(alpha: f32) -> Result<Material, ParamError> {
    Ok(Material::new(
        "GGX, F = 1",
        Microfacet::new(
            Ggx::isotropic(Alpha::new(alpha)?),
            Masking::HeightCorrelated,
            NoFresnel::<Vec3>::new(),
        ),
    ))
}

/// Smooth glass, η = 1.5.
pub fn smooth_glass() -> Result<Material, ParamError> {
    let eta = Eta::new(1.5)?;
    let glass = Material::new("smooth glass", Mono::new(SmoothDielectric::new(eta)));
    Ok(glass.with_interface(Interface::Dielectric(eta)))
}

/// The glazed material with a white base (ρ = 1).
pub fn white_glazed() -> Result<Material, ParamError> {
    let eta = Eta::new(1.5)?;
    let glazed = Material::new("white glazed", Glazed::new(Vec3::ONE, eta)?);
    Ok(glazed.with_interface(Interface::Coat(eta)))
}

/// The `--scene furnace` image: white Lambert, GGX with `F = 1` (α = 0.05), smooth glass
/// and white glazed spheres in a row.
///
/// # Errors
/// A [`ParamError`] if a model refuses its parameters.
pub fn build(aspect: f32) -> Result<Scene, ParamError> {
    let mut b = SceneBuilder::new();
    let materials = [
        white_lambert()?,
        ggx_no_fresnel(0.05)?,
        smooth_glass()?,
        white_glazed()?,
    ];
    for (i, m) in materials.into_iter().enumerate() {
        let id = b.material(m);
        b.sphere(Vec3::new(-3.3 + 2.2 * i as f32, 0.0, 0.0), 1.0, id);
    }
    b.environment(Environment::Constant(Vec3::ONE));
    let camera = Camera::look_at(Vec3::new(0.0, 0.0, 9.0), Vec3::ZERO, Vec3::Y, 32.0, aspect);
    Ok(b.build(camera))
}
