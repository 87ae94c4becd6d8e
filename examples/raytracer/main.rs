//! `raytracer`: the reference ray tracer of the `lobe` crate.
//!
//! A small but real renderer that uses the crate the way a renderer would: every surface holds a
//! `lobe` model behind the `Bxdf` trait, and the path tracer calls only `eval`, `sample`, `pdf` and
//! `lobes` (the Whitted integrator also takes a specular surface's Fresnel reflectance from
//! `lobe::fresnel`). The architecture follows the handout (seed 003, "Ray tracer architecture
//! 101"): [`ray::Ray`] with a valid `t` range; the [`surface::Surface`] trait, implemented by
//! spheres, quads, triangle meshes (OBJ files through `tobj`) and [`bvh::Group`], which holds a
//! BVH; an intersection record ([`surface::Hit`]); a [`material::Material`] holding the model; a
//! pinhole [`camera::Camera`]. Lights are point, directional, spherical and quadrilateral area
//! lights, and an environment (constant, a sky gradient, or its order-3 spherical-harmonic
//! projection with `--env sh`; `--shading irradiance` lights diffuse models by its irradiance
//! `E(n)`). Two integrators: [`path::PathTracer`] (next-event estimation, MIS, Russian roulette)
//! and [`whitted::Whitted`]. A light-path filter in Heckbert's notation ([`heckbert`]) keeps only
//! the paths asked for.
//!
//! `cargo run --release --example raytracer -- --help` lists the options. Under
//! `cargo test` (the example has `test = true`) run the unit tests of every module, the
//! white furnace tests ([`furnace_tests`]), direct lighting against closed forms
//! ([`light_tests`]), the SH environment and irradiance shading ([`sh_tests`]) and the
//! shadow terminator of a coarse mesh ([`terminator_tests`]).

mod aabb;
mod bvh;
mod camera;
mod checker;
mod cli;
mod environment;
mod exr;
mod heckbert;
mod integrator;
mod light;
mod material;
mod mesh;
mod output;
mod path;
mod quad;
mod ray;
mod render;
mod rng;
mod scene;
mod scenes;
mod shading;
mod sphere;
mod surface;
mod tonemap;
mod whitted;

#[cfg(test)]
mod furnace_tests;
#[cfg(test)]
mod light_tests;
#[cfg(test)]
mod sh_tests;
#[cfg(test)]
mod terminator_tests;

use cli::{Command, IntegratorChoice, Options};
use heckbert::PathFilter;
use integrator::Integrator;
use path::PathTracer;
use render::RenderSettings;
use std::process::ExitCode;
use std::time::Instant;
use whitted::Whitted;

/// Parses the command line and runs the render; exit code 2 for bad input.
fn main() -> ExitCode {
    match cli::parse(std::env::args().skip(1)) {
        Ok(Command::Help) => {
            print!("{}", cli::HELP);
            ExitCode::SUCCESS
        }
        Ok(Command::Render(options)) => {
            if let Err(e) = cli::check_paths(&options) {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
            match render::with_threads(options.threads, || run(&options)) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::FAILURE
                }
            }
        }
        Err(e) => {
            eprintln!("error: {e}\n\nRun with --help to see the options.");
            ExitCode::from(2)
        }
    }
}

/// Builds the scene, renders it and writes the images.
fn run(o: &Options) -> Result<(), String> {
    let aspect = o.width as f32 / o.height as f32;
    let (mut scene, layout) = o.scene.build(aspect)?;
    if o.env_sh {
        if scene.environment.is_none() {
            println!(
                "note: the {:?} scene has no environment to project (--env sh)",
                o.scene
            );
        }
        scene = scene.with_sh_environment();
    }
    if o.irradiance && scene.irradiance.is_none() {
        println!(
            "note: the {:?} scene has no environment: --shading irradiance changes nothing",
            o.scene
        );
    }
    if let Some(layout) = &layout {
        println!("Label layout (rows back to front, columns left to right):");
        for (row, names) in scenes::showcase::ROWS.iter().zip(layout) {
            println!("  {row:>6}: {}", names.join(" | "));
        }
        if let Some(path) = &o.layout {
            std::fs::write(path, scenes::showcase::layout_markdown(layout))
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            println!("Wrote the layout to {}", path.display());
        }
    }
    let filter = o.paths.as_deref().map(PathFilter::parse).transpose()?;
    let integrator = match o.integrator {
        IntegratorChoice::Path => Integrator::Path(PathTracer {
            max_depth: o.max_depth,
            filter,
            irradiance: o.irradiance,
            clamp: o.clamp,
            roulette: true,
        }),
        IntegratorChoice::Whitted => Integrator::Whitted(Whitted {
            max_depth: o.max_depth,
            filter,
            irradiance: o.irradiance,
        }),
    };
    let settings = RenderSettings {
        width: o.width,
        height: o.height,
        spp: o.spp,
        seed: o.seed,
    };
    println!(
        "Rendering {:?} scene{}{}, {}×{} at {} spp, {:?} integrator, max depth {}{}{}, {} threads",
        o.scene,
        if o.env_sh {
            ", SH environment (order 3)"
        } else {
            ""
        },
        if o.irradiance {
            ", irradiance shading"
        } else {
            ""
        },
        o.width,
        o.height,
        o.spp,
        o.integrator,
        o.max_depth,
        o.paths
            .as_deref()
            .map_or(String::new(), |p| format!(", paths {p:?}")),
        o.clamp.map_or(String::new(), |c| format!(
            ", indirect light clamped to {c} (biased)"
        )),
        rayon::current_num_threads(),
    );
    let start = Instant::now();
    let film = render::render(&scene, &integrator, &settings, true);
    let seconds = start.elapsed().as_secs_f64();
    let samples = f64::from(o.width) * f64::from(o.height) * f64::from(o.spp);
    println!(
        "Rendered in {seconds:.2} s: {:.2} M samples/s ({:.0} k samples/s per thread)",
        samples / seconds / 1e6,
        samples / seconds / 1e3 / rayon::current_num_threads() as f64,
    );
    if film.dropped > 0 {
        println!("warning: {} non-finite samples were dropped", film.dropped);
    }
    output::write_png(&film, &o.output, o.exposure)?;
    println!("Wrote {}", o.output.display());
    if o.exr {
        let hdr = o.output.with_extension("exr");
        output::write_hdr(&film, &hdr)?;
        println!("Wrote {} (linear radiance)", hdr.display());
    }
    Ok(())
}
