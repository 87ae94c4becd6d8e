//! The command line: options, their defaults, `--help`.

use crate::heckbert::PathFilter;
use crate::scenes::SceneChoice;
use std::path::PathBuf;

/// Which integrator `--integrator` asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntegratorChoice {
    /// Path tracing.
    Path,
    /// Whitted ray tracing.
    Whitted,
}

/// The parsed options.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub spp: u32,
    /// The integrator.
    pub integrator: IntegratorChoice,
    /// The PNG to write.
    pub output: PathBuf,
    /// The random seed.
    pub seed: u64,
    /// The scene.
    pub scene: SceneChoice,
    /// The most bounces (path) or recursion depth (Whitted).
    pub max_depth: u32,
    /// A light-path filter in Heckbert's notation.
    pub paths: Option<String>,
    /// Also write linear HDR (OpenEXR).
    pub exr: bool,
    /// Exposure multiplier before tone mapping.
    pub exposure: f32,
    /// Write the default scene's label layout (Markdown) here.
    pub layout: Option<PathBuf>,
    /// Light the scene by its environment's order-3 SH projection (`--env sh`).
    pub env_sh: bool,
    /// Light diffuse models by the environment's SH irradiance (`--shading irradiance`).
    pub irradiance: bool,
    /// Worker threads; `None` for one per core (`--threads`).
    pub threads: Option<u32>,
    /// Clamp each contribution of indirect light to this (`--clamp`, biased); `None` by
    /// default.
    pub clamp: Option<f32>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            width: 640,
            height: 360,
            spp: 64,
            integrator: IntegratorChoice::Path,
            output: PathBuf::from("render.png"),
            seed: 1,
            scene: SceneChoice::Default,
            max_depth: 12,
            paths: None,
            exr: false,
            exposure: 1.0,
            layout: None,
            env_sh: false,
            irradiance: false,
            threads: None,
            clamp: None,
        }
    }
}

/// What the command line asks for.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// Render with these options.
    Render(Options),
    /// Print the help and stop.
    Help,
}

/// The text of `--help`.
pub const HELP: &str = "\
raytracer: the reference ray tracer of the `lobe` crate

USAGE:
    cargo run --release --example raytracer -- [OPTIONS]

OPTIONS:
    --width N          image width in pixels (default 640)
    --height N         image height in pixels (default 360)
    --spp N            samples per pixel (default 64)
    --integrator NAME  path: unbiased path tracing with next-event estimation, MIS and
                       Russian roulette (default); whitted: direct light with shadow rays,
                       an ambient term, and recursive mirror reflection and refraction
    --max-depth N      the most bounces on a path, or the Whitted recursion depth
                       (default 12)
    --scene NAME       default: 19 spheres of lobe materials, floor, area light, sky;
                       furnace: lossless white spheres in a uniform environment (they
                       should vanish); lights: an OBJ mesh under point, directional and
                       spherical lights; ggx-row, ggx-row-compensated: GGX spheres
                       α = 0.1 … 1 (F = 1 above, gold below) in a uniform environment,
                       single scattering or energy-compensated
    --env NAME         sky: the scene's own environment (default); sh: its projection onto
                       order-3 spherical harmonics (9 coefficients per channel), which then
                       lights the scene and shows as the background
    --shading NAME     full: every light traced (default); irradiance: diffuse models take
                       the environment's light from its order-3 irradiance E(n)
                       (Ramamoorthi & Hanrahan 2001), unshadowed and noise-free, instead of
                       sampling it; other lights and models unchanged
    --paths EXPR       keep only light paths matching EXPR, in Heckbert's notation, from
                       the light to the eye: L (a light or the environment), D (diffuse
                       or glossy bounce),
                       S (specular bounce), E (eye), with | * + ? ( ) and {SD} or [SD]
                       for a set; spaces are ignored. Examples: 'L D E' (direct light on
                       diffuse), 'L S+ D E' (caustics), 'L D S+ E' (reflections of lit
                       diffuse surfaces), 'L (S|D)* E' (everything)
    --output FILE      the PNG to write (default render.png): sRGB, ACES tone-mapped
    --exr              also write linear HDR radiance next to it as OpenEXR (FILE with
                       the extension .exr; 32-bit float RGB, uncompressed)
    --exposure X       multiply the radiance by X before tone mapping (default 1)
    --seed N           the random seed (default 1): a render is reproducible for a seed,
                       whatever the number of threads
    --threads N        render on N threads (default: one per core)
    --clamp X          path tracer: clamp each contribution of indirect light (light a
                       path finds after a diffuse or glossy bounce that is not its last
                       scattering, e.g. a caustic on the floor) to at most X, scaling its
                       RGB down to keep the hue; direct light and what mirrors and smooth
                       glass show of it are never clamped. Off by default. BIASED: it
                       removes fireflies (such as the caustics rough and thin glass throw
                       on the floor at 64 spp) by removing real light, so the image is
                       darker than the truth where those paths carry it, and it no longer
                       converges to the right answer as samples grow
    --layout FILE      write the default scene's label layout (which model is where) as
                       Markdown to FILE
    -h, --help         print this help
";

/// Parses the arguments (without the program name).
///
/// # Errors
/// A message for an unknown option, a missing or malformed value, or a value out of range.
pub fn parse<I: IntoIterator<Item = String>>(args: I) -> Result<Command, String> {
    let mut o = Options::default();
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let (name, inline) = match arg.split_once('=') {
            Some((n, v)) if n.starts_with("--") => (n.to_owned(), Some(v.to_owned())),
            _ => (arg.clone(), None),
        };
        let mut value = || {
            inline
                .clone()
                .or_else(|| args.next())
                .ok_or_else(|| format!("{name} needs a value"))
        };
        match name.as_str() {
            "-h" | "--help" => return Ok(Command::Help),
            "--width" => o.width = number(&name, &value()?, 1, 16_384)?,
            "--height" => o.height = number(&name, &value()?, 1, 16_384)?,
            "--spp" => o.spp = number(&name, &value()?, 1, 1 << 20)?,
            "--max-depth" => o.max_depth = number(&name, &value()?, 0, 1024)?,
            "--seed" => {
                let v = value()?;
                o.seed = v
                    .parse()
                    .map_err(|_| format!("{name} expects a whole number, got {v:?}"))?;
            }
            "--integrator" => {
                o.integrator = match value()?.as_str() {
                    "path" => IntegratorChoice::Path,
                    "whitted" => IntegratorChoice::Whitted,
                    other => {
                        return Err(format!("unknown integrator {other:?}: use path or whitted"));
                    }
                }
            }
            "--scene" => {
                let v = value()?;
                o.scene = SceneChoice::from_name(&v).ok_or_else(|| {
                    format!("unknown scene {v:?}: use one of {}", SceneChoice::NAMES)
                })?;
            }
            "--env" => {
                o.env_sh = match value()?.as_str() {
                    "sky" => false,
                    "sh" => true,
                    other => return Err(format!("unknown environment {other:?}: use sky or sh")),
                }
            }
            "--shading" => {
                o.irradiance = match value()?.as_str() {
                    "full" => false,
                    "irradiance" => true,
                    other => {
                        return Err(format!("unknown shading {other:?}: use full or irradiance"));
                    }
                }
            }
            "--output" => o.output = PathBuf::from(value()?),
            "--paths" => {
                let v = value()?;
                PathFilter::parse(&v)?;
                o.paths = Some(v);
            }
            "--layout" => o.layout = Some(PathBuf::from(value()?)),
            "--exposure" => {
                let v = value()?;
                o.exposure = v
                    .parse::<f32>()
                    .ok()
                    .filter(|x| x.is_finite() && *x > 0.0)
                    .ok_or_else(|| format!("{name} expects a positive number, got {v:?}"))?;
            }
            "--threads" => o.threads = Some(number(&name, &value()?, 1, 1024)?),
            "--clamp" => {
                let v = value()?;
                o.clamp = Some(
                    v.parse::<f32>()
                        .ok()
                        .filter(|x| x.is_finite() && *x > 0.0)
                        .ok_or_else(|| format!("{name} expects a positive number, got {v:?}"))?,
                );
            }
            "--exr" if inline.is_none() => o.exr = true,
            _ => return Err(format!("unknown option {arg:?}")),
        }
    }
    if o.output.as_os_str().is_empty() {
        return Err("--output needs a file name".to_owned());
    }
    Ok(Command::Render(o))
}

/// Checks, before a long render, that the files asked for can be written: their folders
/// exist.
///
/// # Errors
/// A message naming the missing folder.
pub fn check_paths(o: &Options) -> Result<(), String> {
    for path in [Some(&o.output), o.layout.as_ref()].into_iter().flatten() {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty())
            && !dir.is_dir()
        {
            return Err(format!(
                "the folder {} of {} does not exist",
                dir.display(),
                path.display()
            ));
        }
    }
    Ok(())
}

/// Parses a whole number in `[lo, hi]`.
fn number(name: &str, v: &str, lo: u32, hi: u32) -> Result<u32, String> {
    match v.parse::<u32>() {
        Ok(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => Err(format!(
            "{name} expects a whole number from {lo} to {hi}, got {v:?}"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<String> {
        s.split_whitespace().map(str::to_owned).collect()
    }

    #[test]
    fn defaults_and_overrides() {
        assert_eq!(parse(args("")), Ok(Command::Render(Options::default())));
        let Ok(Command::Render(o)) = parse(args(
            "--width 32 --height=16 --spp 4 --integrator whitted --scene furnace --exr --seed 9 --paths LDE",
        )) else {
            panic!("parses");
        };
        assert_eq!((o.width, o.height, o.spp, o.seed), (32, 16, 4, 9));
        assert_eq!(o.integrator, IntegratorChoice::Whitted);
        assert_eq!(o.scene, SceneChoice::Furnace);
        assert!(o.exr);
        assert_eq!(o.paths.as_deref(), Some("LDE"));
        assert!(!o.env_sh && !o.irradiance);
        let Ok(Command::Render(o)) = parse(args("--env sh --shading=irradiance")) else {
            panic!("parses");
        };
        assert!(o.env_sh && o.irradiance);
        assert_eq!(
            (o.threads, o.clamp),
            (None, None),
            "all cores, no clamp by default"
        );
        let Ok(Command::Render(o)) = parse(args("--threads 3 --clamp=20")) else {
            panic!("parses");
        };
        assert_eq!((o.threads, o.clamp), (Some(3), Some(20.0)));
        assert_eq!(parse(args("--help")), Ok(Command::Help));
    }

    #[test]
    fn bad_input_gives_messages() {
        for bad in [
            "--width 0",
            "--width -3",
            "--width",
            "--spp x",
            "--integrator bdpt",
            "--scene moon",
            "--frobnicate",
            "--exposure -1",
            "--exposure nan",
            "--paths LXE",
            "--paths (LDE",
            "--seed 1.5",
            "--exr=yes",
            "--output=",
            "--env map",
            "--shading flat",
            "--threads 0",
            "--threads",
            "--clamp 0",
            "--clamp -2",
            "--clamp inf",
            "--clamp x",
        ] {
            let err = parse(args(bad)).unwrap_err();
            assert!(!err.is_empty(), "{bad}");
        }
    }
}
