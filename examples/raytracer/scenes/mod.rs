//! The scenes the renderer knows, by name.

pub mod furnace;
pub mod ggx_row;
pub mod lights;
pub mod showcase;

use crate::scene::Scene;
use lobe::ParamError;

/// Material names by row (back to front) and column (left to right).
pub type Layout = Vec<Vec<String>>;

/// A scene the command line can ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneChoice {
    /// One sphere per model on a checkered floor, under an area light and a sky.
    Default,
    /// White spheres of lossless models in a uniform environment: they should vanish.
    Furnace,
    /// A mesh (OBJ) and spheres under a point, a directional and a spherical light.
    Lights,
    /// GGX spheres α = 0.1 … 1 (`F = 1` and gold) in a uniform environment, single
    /// scattering (`false`) or energy-compensated (`true`).
    GgxRow(bool),
}

impl SceneChoice {
    /// The names accepted by `--scene`.
    pub const NAMES: &'static str = "default, furnace, lights, ggx-row, ggx-row-compensated";

    /// The scene called `name`, if there is one.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "default" | "showcase" => Some(Self::Default),
            "furnace" => Some(Self::Furnace),
            "lights" => Some(Self::Lights),
            "ggx-row" => Some(Self::GgxRow(false)),
            "ggx-row-compensated" => Some(Self::GgxRow(true)),
            _ => None,
        }
    }

    /// Builds the scene for an image of aspect ratio `aspect` (width / height), with its
    /// label layout (material names by row and column) when it has one.
    ///
    /// # Errors
    /// A message when a model refuses its parameters or an asset cannot be loaded.
    pub fn build(self, aspect: f32) -> Result<(Scene, Option<Layout>), String> {
        let param = |e: ParamError| format!("scene parameter refused: {e}");
        match self {
            Self::Default => showcase::build(aspect)
                .map(|(scene, layout)| (scene, Some(layout)))
                .map_err(param),
            Self::Furnace => furnace::build(aspect).map(|s| (s, None)).map_err(param),
            Self::Lights => lights::build(aspect).map(|s| (s, None)),
            Self::GgxRow(compensated) => ggx_row::build(aspect, compensated)
                .map(|s| (s, None))
                .map_err(param),
        }
    }
}
