//! A scene of every light but the area quad: a point light, a directional light (the
//! sun), a spherical area light and a dim constant environment, over a triangle mesh loaded
//! from an OBJ file and two spheres.

use crate::camera::Camera;
use crate::environment::Environment;
use crate::light::Light;
use crate::material::{Interface, Material};
use crate::mesh::Mesh;
use crate::quad::Quad;
use crate::scene::{Scene, SceneBuilder};
use crate::surface::{MaterialId, Surface};
use lobe::bxdf::Mono;
use lobe::bxdf::{Lambert, Microfacet, Plastic, SmoothDielectric};
use lobe::fresnel::Conductor;
use lobe::metals;
use lobe::microfacet::{Ggx, Masking};
use lobe::{Alpha, Eta, ParamError, Vec3};
use std::path::Path;

/// The OBJ file of the mesh, relative to the crate.
const TORUS: &str = "examples/raytracer/assets/torus.obj";
/// The same file where the crate was built.
const TORUS_AT_BUILD: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/examples/raytracer/assets/torus.obj"
);

/// Where the torus sits: the OBJ's coordinates are moved by this.
pub const TORUS_OFFSET: Vec3 = Vec3::new(0.0, 0.25, 0.0);

/// Builds the scene.
///
/// # Errors
/// A message when the OBJ file cannot be loaded or a model refuses its parameters.
pub fn build(aspect: f32) -> Result<Scene, String> {
    // Where the crate was built, or else relative to the working directory.
    let path = [Path::new(TORUS_AT_BUILD), Path::new(TORUS)]
        .into_iter()
        .find(|p| p.exists())
        .unwrap_or(Path::new(TORUS));
    build_with(aspect, |material| {
        Mesh::load_obj(path, 1.0, TORUS_OFFSET, material)
    })
}

/// Builds the scene with the torus that `torus` makes for the material it is given (the
/// tests swap in finer tessellations of the same surface).
///
/// # Errors
/// A message when `torus` fails or a model refuses its parameters.
pub fn build_with<S: Surface + 'static>(
    aspect: f32,
    torus: impl FnOnce(MaterialId) -> Result<S, String>,
) -> Result<Scene, String> {
    let param = |e: ParamError| format!("scene parameter refused: {e}");
    let mut b = SceneBuilder::new();
    let glass = Eta::new(1.5).map_err(param)?;
    let ggx = Ggx::isotropic(Alpha::new(0.2).map_err(param)?);
    let red = Plastic::new(Vec3::new(0.7, 0.08, 0.05), ggx, glass).map_err(param)?;
    let red = b.material(Material::new("red plastic", red));
    let gold = Microfacet::new(
        ggx,
        Masking::HeightCorrelated,
        Conductor {
            ior: metals::GOLD.rgb(),
        },
    );
    let gold = b.material(Material::new("GGX gold", gold));
    let clear = b.material(
        Material::new("glass", Mono::new(SmoothDielectric::new(glass)))
            .with_interface(Interface::Dielectric(glass)),
    );
    let floor = b.material(Material::new(
        "floor",
        Lambert::new(Vec3::splat(0.5)).map_err(param)?,
    ));

    b.surface(torus(red)?);
    b.sphere(Vec3::new(-1.6, 0.5, 0.3), 0.5, gold);
    b.sphere(Vec3::new(1.6, 0.5, 0.3), 0.5, clear);
    if let Some(q) = Quad::new(
        Vec3::new(-10.0, 0.0, 10.0),
        Vec3::new(20.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, -20.0),
        floor,
    ) {
        b.surface(q);
    }
    b.light(Light::Point {
        position: Vec3::new(1.5, 3.0, 2.0),
        intensity: Vec3::new(6.0, 5.0, 4.0),
    });
    b.light(Light::Directional {
        to_light: Vec3::new(-0.5, 0.8, 0.4).normalize(),
        irradiance: Vec3::new(1.2, 1.1, 0.9),
    });
    b.sphere_light(Vec3::new(-2.4, 1.3, -1.8), 0.3, Vec3::new(5.0, 8.0, 16.0));
    b.environment(Environment::Constant(Vec3::splat(0.08)));
    let camera = Camera::look_at(
        Vec3::new(0.0, 2.8, 5.0),
        Vec3::new(0.0, 0.3, 0.0),
        Vec3::Y,
        38.0,
        aspect,
    );
    Ok(b.build(camera))
}
