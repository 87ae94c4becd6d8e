//! [`Scene`]: geometry, materials, lights and camera, and the builder that assembles them.

use crate::bvh::Group;
use crate::camera::Camera;
use crate::environment::Environment;
use crate::light::Light;
use crate::material::Material;
use crate::quad::Quad;
use crate::ray::Ray;
use crate::sphere::Sphere;
use crate::surface::{Hit, MaterialId, Surface};
use lobe::Vec3;
use lobe::bxdf::Lambert;
use lobe::sh::IrradianceQuadratic;

/// Everything a render needs.
pub struct Scene {
    /// All the surfaces, behind one BVH.
    pub geometry: Group,
    /// The materials, indexed by [`MaterialId`].
    pub materials: Vec<Material>,
    /// The lights, the environment included.
    pub lights: Vec<Light>,
    /// The environment, if the scene has one (it is also in `lights`).
    pub environment: Option<(usize, Environment)>,
    /// The camera.
    pub camera: Camera,
    /// The Whitted integrator's ambient radiance.
    pub ambient: Vec3,
    /// The environment's irradiance `E(n)` from its order-3 SH projection (Ramamoorthi &
    /// Hanrahan's quadratic form), for the irradiance shading mode; `None` without an
    /// environment.
    pub irradiance: Option<IrradianceQuadratic<Vec3>>,
    /// The shadow terminator fix for meshes with vertex normals (on by default): shadow rays
    /// leave reflection models from the smooth surface point [`Hit::p_shadow`] (Hanika
    /// 2021), and light above the shading normal's horizon counts even where it is below
    /// the flat facet's ([`ShadingPoint::light_direction`](crate::shading::ShadingPoint::light_direction)).
    /// Off, a coarse mesh shows its facets in a hard-edged shadow along the terminator.
    pub terminator_fix: bool,
}

impl Scene {
    /// The closest hit along the ray.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.geometry.intersect(ray)
    }

    /// True when something blocks the (shadow) ray.
    #[inline]
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.geometry.occluded(ray)
    }

    /// The material of a hit.
    #[inline]
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id as usize]
    }

    /// The same scene lit by its environment's order-3 SH projection (`--env sh`) instead
    /// of the environment itself; unchanged without an environment.
    pub fn with_sh_environment(mut self) -> Self {
        if let Some((index, env)) = self.environment {
            let l = env.project_sh();
            let sh = Environment::Sh(l);
            self.lights[index] = Light::Environment(sh);
            self.environment = Some((index, sh));
            self.ambient = sh.mean();
            self.irradiance = Some(IrradianceQuadratic::new(&l));
        }
        self
    }
}

/// Assembles a [`Scene`] piece by piece.
pub struct SceneBuilder {
    /// The surfaces so far.
    surfaces: Vec<Box<dyn Surface>>,
    /// The materials so far.
    materials: Vec<Material>,
    /// The lights so far.
    lights: Vec<Light>,
    /// The environment and its index in `lights`.
    environment: Option<(usize, Environment)>,
    /// The black material that emitters' surfaces wear.
    emitter: Option<MaterialId>,
}

impl SceneBuilder {
    /// An empty scene.
    pub fn new() -> Self {
        Self {
            surfaces: Vec::new(),
            materials: Vec::new(),
            lights: Vec::new(),
            environment: None,
            emitter: None,
        }
    }

    /// Adds a material and returns its id.
    pub fn material(&mut self, material: Material) -> MaterialId {
        self.materials.push(material);
        (self.materials.len() - 1) as MaterialId
    }

    /// Adds a surface.
    pub fn surface(&mut self, surface: impl Surface + 'static) {
        self.surfaces.push(Box::new(surface));
    }

    /// Adds a sphere.
    pub fn sphere(&mut self, center: Vec3, radius: f32, material: MaterialId) {
        self.surface(Sphere::new(center, radius, material));
    }

    /// Adds a light without a surface (point, directional).
    pub fn light(&mut self, light: Light) {
        self.lights.push(light);
    }

    /// Sets the environment (a light too).
    pub fn environment(&mut self, env: Environment) {
        self.lights.push(Light::Environment(env));
        self.environment = Some((self.lights.len() - 1, env));
    }

    /// The non-scattering material of emitters' surfaces.
    fn emitter_material(&mut self) -> MaterialId {
        if let Some(id) = self.emitter {
            return id;
        }
        let black = Lambert::new(Vec3::ZERO).unwrap_or_else(|_| unreachable!("0 is valid"));
        let id = self.material(Material::new("emitter", black));
        self.emitter = Some(id);
        id
    }

    /// Adds a spherical area light: a sphere that is both a surface and a light.
    pub fn sphere_light(&mut self, center: Vec3, radius: f32, radiance: Vec3) {
        let material = self.emitter_material();
        self.lights.push(Light::Sphere {
            center,
            radius,
            radiance,
        });
        let mut s = Sphere::new(center, radius, material);
        s.light = Some((self.lights.len() - 1) as u32);
        self.surface(s);
    }

    /// Adds a quadrilateral area light emitting toward `u × v`; ignores degenerate edges.
    pub fn quad_light(&mut self, corner: Vec3, u: Vec3, v: Vec3, radiance: Vec3) {
        let material = self.emitter_material();
        if let Some(mut quad) = Quad::new(corner, u, v, material) {
            self.lights.push(Light::Quad { quad, radiance });
            quad.light = Some((self.lights.len() - 1) as u32);
            self.surface(quad);
        }
    }

    /// The finished scene, seen through `camera`.
    pub fn build(self, camera: Camera) -> Scene {
        let ambient = self.environment.map_or(Vec3::ZERO, |(_, e)| e.mean());
        let irradiance = self
            .environment
            .map(|(_, e)| IrradianceQuadratic::new(&e.project_sh()));
        Scene {
            geometry: Group::new(self.surfaces),
            materials: self.materials,
            lights: self.lights,
            environment: self.environment,
            camera,
            ambient,
            irradiance,
            terminator_fix: true,
        }
    }
}
