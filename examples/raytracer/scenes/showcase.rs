//! The default scene: 19 spheres, one per material, in a grid of five columns and four rows (the
//! nearest row has four) on a checkered floor, lit by a quad area light and a sky.

use crate::camera::Camera;
use crate::checker::Checker;
use crate::environment::Environment;
use crate::material::{Interface, Material};
use crate::quad::Quad;
use crate::scene::{Scene, SceneBuilder};
use lobe::bxdf::Mono;
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, Mirror, OrenNayar, Phong, Plastic, RoughDielectric, SmoothDielectric,
    ThinDielectric,
};
use lobe::bxdf::{CoatedConductor, CoatedDiffuse, DiffuseTransmission, Sheen};
use lobe::fresnel::Conductor;
use lobe::metals;
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::{Alpha, Eta, ParamError, Roughness, Vec3};

/// Grid columns.
pub const COLUMNS: usize = 5;
/// The row names, back to front as the camera sees them.
pub const ROWS: [&str; 4] = ["back", "middle", "front", "nearest"];

/// The `lobe` type behind each sphere, in the order of [`materials`].
pub const TYPES: [&str; 19] = [
    "Lambert<Vec3>",
    "OrenNayar<Vec3>",
    "EnergyPreservingOrenNayar<Vec3>",
    "DisneyDiffuse<Vec3>",
    "Plastic<Ggx, Vec3>",
    "Phong<Vec3>",
    "BlinnPhong<Vec3> (BlinnPhongForm::Normalized)",
    "CompensatedMicrofacet<Ggx, fresnel::Conductor<Vec3>> (Microfacet::with_energy_compensation)",
    "CompensatedMicrofacet<Beckmann, fresnel::Conductor<Vec3>>",
    "CompensatedMicrofacet<Ggx, fresnel::Conductor<Vec3>> (Ggx::new(αx, αy))",
    "Glazed<Vec3>",
    "Mirror<fresnel::Conductor<Vec3>>",
    "SmoothDielectric (f32, lifted to RGB by Mono)",
    "RoughDielectric<Ggx> (f32, lifted to RGB by Mono)",
    "ThinDielectric (f32, lifted to RGB by Mono)",
    "CoatedDiffuse<Ggx, Vec3> (stochastic layered)",
    "CoatedConductor<Ggx, Ggx, Vec3> (stochastic layered)",
    "Sheen<Vec3>",
    "DiffuseTransmission<Vec3>",
];

/// The common reflectance of the diffuse models, so that they compare.
const CLAY: Vec3 = Vec3::new(0.80, 0.42, 0.28);

/// The 19 materials, back row first, left to right.
///
/// # Errors
/// A [`ParamError`] if a model refuses its parameters (it does not, for these).
pub fn materials() -> Result<Vec<Material>, ParamError> {
    // Measured complex indices, sampled at 650, 550 and 450 nm (`lobe::metals`).
    let [gold, copper, silver, aluminium] = [
        metals::GOLD,
        metals::COPPER,
        metals::SILVER,
        metals::ALUMINIUM,
    ]
    .map(|m| m.rgb());
    let glass = Eta::new(1.5)?;
    let ggx = |a: f32| Alpha::new(a).map(Ggx::isotropic);
    let blue = Vec3::new(0.12, 0.25, 0.55);
    Ok(vec![
        Material::new("Lambert", Lambert::new(CLAY)?),
        Material::new("Oren-Nayar σ=0.5", OrenNayar::new(CLAY, 0.5)?),
        Material::new("EON r=0.6", EnergyPreservingOrenNayar::new(CLAY, 0.6)?),
        Material::new(
            "Disney diffuse r=0.7",
            DisneyDiffuse::new(CLAY, Roughness::new(0.7)?)?,
        ),
        Material::new(
            "Plastic (GGX α=0.1 coat)",
            Plastic::new(Vec3::new(0.08, 0.45, 0.15), ggx(0.1)?, glass)?,
        ),
        Material::new("Phong p=80", Phong::new(blue, Vec3::splat(0.3), 80.0)?),
        Material::new(
            "Blinn-Phong p=120",
            BlinnPhong::new(blue, Vec3::splat(0.3), 120.0, BlinnPhongForm::Normalized)?,
        ),
        Material::new(
            "GGX gold α=0.15",
            Microfacet::new(
                ggx(0.15)?,
                Masking::HeightCorrelated,
                Conductor { ior: gold },
            )
            .with_energy_compensation()?,
        ),
        Material::new(
            "Beckmann copper α=0.25",
            Microfacet::new(
                Beckmann::isotropic(Alpha::new(0.25)?),
                Masking::HeightCorrelated,
                Conductor { ior: copper },
            )
            .with_energy_compensation()?,
        ),
        Material::new(
            "anisotropic GGX aluminium α=(0.05, 0.35)",
            Microfacet::new(
                Ggx::new(Alpha::new(0.05)?, Alpha::new(0.35)?),
                Masking::HeightCorrelated,
                Conductor { ior: aluminium },
            )
            .with_energy_compensation()?,
        ),
        Material::new(
            "Glazed η=1.5",
            Glazed::new(Vec3::new(0.85, 0.7, 0.15), glass)?,
        )
        .with_interface(Interface::Coat(glass)),
        Material::new("Mirror (silver)", Mirror::new(Conductor { ior: silver }))
            .with_interface(Interface::Conductor(silver)),
        Material::new(
            "smooth glass η=1.5",
            Mono::new(SmoothDielectric::new(glass)),
        )
        .with_interface(Interface::Dielectric(glass)),
        Material::new(
            "rough glass GGX α=0.15",
            Mono::new(RoughDielectric::new(ggx(0.15)?, glass)),
        )
        .with_interface(Interface::Dielectric(glass)),
        Material::new(
            "thin dielectric η=1.5",
            Mono::new(ThinDielectric::new(glass)),
        )
        .with_interface(Interface::Thin(ThinDielectric::new(glass))),
        // Composition and layering (issue 12): the nearest row.
        Material::new(
            "coated diffuse GGX α=0.1",
            CoatedDiffuse::coated_diffuse(Vec3::new(0.55, 0.08, 0.06), ggx(0.1)?, glass)?,
        ),
        Material::new(
            "coated copper, coat α=0.05, metal α=0.3",
            CoatedConductor::coated_conductor(ggx(0.05)?, glass, ggx(0.3)?, copper)?,
        ),
        Material::new("sheen r=0.4", Sheen::new(Vec3::new(0.9, 0.35, 0.6), 0.4)?),
        Material::new(
            "diffuse transmission (leaf)",
            DiffuseTransmission::new(Vec3::new(0.25, 0.45, 0.1), Vec3::new(0.3, 0.5, 0.1))?,
        ),
    ])
}

/// The scene, and its layout: the material names by row (back to front) and column (left
/// to right).
///
/// # Errors
/// A [`ParamError`] if a model refuses its parameters.
pub fn build(aspect: f32) -> Result<(Scene, Vec<Vec<String>>), ParamError> {
    let mut b = SceneBuilder::new();
    let mut layout = vec![Vec::new(); ROWS.len()];
    let radius = 0.45;
    let spacing = 1.1;
    for (i, material) in materials()?.into_iter().enumerate() {
        let (row, col) = (i / COLUMNS, i % COLUMNS);
        layout[row].push(material.name.clone());
        let id = b.material(material);
        let x = (col as f32 - 0.5 * (COLUMNS - 1) as f32) * spacing;
        let z = (row as f32 - 1.0) * spacing;
        b.sphere(Vec3::new(x, radius, z), radius, id);
    }
    checkered_floor(&mut b)?;
    b.quad_light(
        Vec3::new(-4.0, 4.2, 0.0),
        // x × z = −y: the light faces down.
        Vec3::new(3.5, 0.0, 0.0),
        Vec3::new(0.0, 0.0, 3.5),
        Vec3::new(9.0, 8.5, 7.5),
    );
    b.environment(Environment::Sky {
        zenith: Vec3::new(0.10, 0.18, 0.40),
        horizon: Vec3::new(0.42, 0.42, 0.45),
        ground: Vec3::new(0.10, 0.09, 0.08),
    });
    let camera = Camera::look_at(
        Vec3::new(0.0, 3.4, 6.4),
        Vec3::new(0.0, 0.1, -0.2),
        Vec3::Y,
        34.0,
        aspect,
    );
    Ok((b.build(camera), layout))
}

/// A floor of square tiles in two greys, 60 × 60 units (to the horizon, nearly).
fn checkered_floor(b: &mut SceneBuilder) -> Result<(), ParamError> {
    let light = b.material(Material::new(
        "floor, light tiles",
        Lambert::new(Vec3::splat(0.65))?,
    ));
    let dark = b.material(Material::new(
        "floor, dark tiles",
        Lambert::new(Vec3::splat(0.25))?,
    ));
    let (size, tiles) = (0.8, 75);
    let side = size * tiles as f32;
    // Edges z then x: the normal u × v is +y. A tile corner at the origin.
    let corner = Vec3::new(-0.5 * side, 0.0, -0.5 * side);
    if let Some(quad) = Quad::new(
        corner,
        Vec3::new(0.0, 0.0, side),
        Vec3::new(side, 0.0, 0.0),
        light,
    ) {
        b.surface(Checker {
            quad,
            other: dark,
            tiles,
        });
    }
    Ok(())
}

/// The layout as a Markdown table, for the README.
pub fn layout_markdown(layout: &[Vec<String>]) -> String {
    let mut s = String::from(
        "# The default scene\n\n`cargo run --release --example raytracer` renders 19 spheres, one \
         per `lobe` material, in a grid of five columns and four rows (the nearest row has \
         four) on a checkered floor, lit by a quad area light (upper left) and a sky. As seen in \
         `render.png`:\n\n\
         | row | 1 (left) | 2 | 3 | 4 | 5 (right) |\n\
         | --- | --- | --- | --- | --- | --- |\n",
    );
    for (name, row) in ROWS.iter().zip(layout) {
        s.push_str(&format!("| {name} | {} |\n", row.join(" | ")));
    }
    s.push_str("\nThe models, back row first, left to right:\n\n");
    for (i, (name, ty)) in layout.iter().flatten().zip(TYPES).enumerate() {
        s.push_str(&format!("{}. {name}: `{ty}`\n", i + 1));
    }
    s.push_str(
        "\nThe diffuse models of the back row share the reflectance (0.80, 0.42, 0.28); Phong \
         and Blinn-Phong share a blue diffuse term with k_s = 0.3. The metals use measured \
         complex indices of refraction, and the three rough metals of the middle row are \
         energy-compensated (Kulla & Conty 2017: the light that scatters more than once \
         between microfacets put back; the coated copper's base is not); the dielectrics and \
         the coats have η = 1.5. The nearest row is stochastic layered models (a red coated \
         diffuse, coated copper), a pink sheen and a leaf that transmits green light. \
         Generated by `--layout`.\n\n\
         ![The default scene, path traced at 256 samples per pixel](../../docs/render.png)\n\n\
         `docs/render.png` is `--spp 256 --output docs/render.png`; the default \
         64 spp is noisier, most visibly in the caustics of the glass spheres.\n",
    );
    s
}
