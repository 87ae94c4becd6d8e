//! Directional albedo `E(θo) = ∫ f(wo, wi) |cos θi| dωi` of white models (the panels below list
//! them), against the viewing angle θo from 0° to 89°.
//!
//! Every model is white (ρ = 1, `k_s = 1`, or `F = 1` through
//! [`NoFresnel`](lobe::fresnel::NoFresnel)), so an energy-conserving model that loses nothing
//! draws `E = 1` (the dashed line), one that loses energy falls below it and one that creates
//! energy rises above it. The panels show:
//!
//! * diffuse models: Lambert and EON stay at 1, the qualitative Oren-Nayar loses energy with
//!   its roughness, Disney diffuse exceeds 1 at grazing angles when rough;
//! * Phong and the normalised Blinn-Phong: at most 1 (the latter up to its 7.52% margin),
//!   falling with θo as the horizon clips the lobe;
//! * the seed's modified Blinn-Phong: far above 1 for broad lobes (≈2.9 at `p = 1`);
//! * GGX and Beckmann conductors with `F = 1`: single scattering loses the energy that
//!   bounces between microfacets, the more the rougher the surface (GGX at `α = 1` keeps
//!   only `1 − ln 2 ≈ 0.31` at normal incidence); smooth surfaces lose it
//!   near grazing (a dip at 80°–85°), very rough ones most at normal incidence;
//! * the rough dielectric (reflection plus transmission, importance transport, so `E` is the
//!   fraction of the flux scattered) loses energy the same way; glazed and plastic (ρ = 1) stay
//!   just at or below 1;
//! * dashed, in the same colour: the same models with Kulla & Conty's energy compensation
//!   ([`CompensatedMicrofacet`](lobe::bxdf::CompensatedMicrofacet),
//!   [`CompensatedDielectric`](lobe::bxdf::CompensatedDielectric), the plastic's compensated
//!   coat), which put back the light that scatters more than once and sit on `E = 1`.
//!
//! Each point is the mean of [`lobe::verify::albedo_sampled`] (the model's own sampler,
//! 20 000 samples, the same random numbers at every θo); the shaded band is ±2 standard
//! errors.
//!
//! ```text
//! cargo run --release --example albedo
//! ```
//!
//! writes `docs/albedo.svg` and `docs/albedo.png` (a few seconds in release). The PNG's text
//! uses the DejaVu Sans font shipped in `docs/fonts/` (Bitstream Vera licence), so no system
//! font library is needed.

use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, OrenNayar, Phong, Plastic, RoughDielectric, TransportMode,
};
use lobe::fresnel::NoFresnel;
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::tables::TabulatedAlbedo;
use lobe::verify::{BxdfCheck, Estimate, albedo_sampled};
use lobe::{Alpha, Eta, Roughness, Vec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::error::Error;
use std::path::Path;

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// DejaVu Sans, for the text of the PNG (the SVG names the family only).
const FONT: &[u8] = include_bytes!("../docs/fonts/DejaVuSans.ttf");
/// The family every text style of this example uses.
const FAMILY: &str = "sans-serif";

/// Monte Carlo samples per point.
const SAMPLES: usize = 20_000;
/// The viewing angles, in degrees: 0°, 1°, …, 89°.
const THETA_MAX: u32 = 89;

/// Distinct colours for the curves of a panel.
const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// Pixel size of one panel, and of the legend column inside it.
const PANEL: (u32, u32) = (640, 430);
const LEGEND_WIDTH: u32 = 205;
const COLUMNS: usize = 3;
/// Height of the figure's title strip.
const HEADER: u32 = 70;

type Model = Box<dyn Bxdf<Spectrum = f32>>;

/// One curve: a model with one setting, and its measured albedo.
struct Curve {
    label: String,
    model: Model,
    points: Vec<(f64, Estimate)>,
    /// The index of its colour in [`COLOURS`].
    colour: usize,
    /// Dashed: an energy-compensated model, in the colour of the model it compensates.
    dashed: bool,
}

/// One panel of the figure.
struct Panel {
    title: &'static str,
    curves: Vec<Curve>,
}

fn curve(label: impl Into<String>, model: impl Bxdf<Spectrum = f32> + 'static) -> Curve {
    Curve {
        label: label.into(),
        model: Box::new(model),
        points: Vec::new(),
        colour: 0,
        dashed: false,
    }
}

/// Colours the curves of a panel in order, a compensated curve in the colour of the one
/// before it.
fn coloured(mut curves: Vec<Curve>) -> Vec<Curve> {
    let mut next = 0;
    for c in &mut curves {
        if c.dashed {
            c.colour = next.max(1) - 1;
        } else {
            c.colour = next;
            next += 1;
        }
    }
    curves
}

/// A compensated model's curve: dashed, in its uncompensated model's colour.
fn compensated(label: impl Into<String>, model: impl Bxdf<Spectrum = f32> + 'static) -> Curve {
    Curve {
        dashed: true,
        ..curve(label, model)
    }
}

/// The single-scattering conductor with `F = 1` on `dist`, and its compensated curve.
fn conductor_pair<D: TabulatedAlbedo + Copy + 'static>(a: f32, dist: D) -> Result<[Curve; 2]> {
    let single = Microfacet::new(dist, Masking::HeightCorrelated, NoFresnel::<f32>::new());
    Ok([
        curve(format!("α = {a}"), single),
        compensated("  compensated", single.with_energy_compensation()?),
    ])
}

fn alpha(a: f32) -> Result<Alpha> {
    Ok(Alpha::new(a)?)
}

fn panels() -> Result<Vec<Panel>> {
    let glass = Eta::new(1.5)?;
    let roughnesses = [0.1_f32, 0.3, 0.6, 1.0];

    let mut diffuse = vec![curve("Lambert", Lambert::new(1.0_f32)?)];
    for sigma in [0.5_f32, 1.0] {
        diffuse.push(curve(
            format!("Oren-Nayar σ = {sigma}"),
            OrenNayar::new(1.0_f32, sigma)?,
        ));
    }
    for r in [0.5_f32, 1.0] {
        diffuse.push(curve(
            format!("EON r = {r}"),
            EnergyPreservingOrenNayar::new(1.0_f32, r)?,
        ));
    }
    for r in [0.0_f32, 0.5, 1.0] {
        diffuse.push(curve(
            format!("Disney r = {r}"),
            DisneyDiffuse::new(1.0_f32, Roughness::new(r)?)?,
        ));
    }

    let mut phong = Vec::new();
    for p in [1.0_f32, 10.0, 100.0] {
        phong.push(curve(
            format!("Phong p = {p}"),
            Phong::new(0.0_f32, 1.0, p)?,
        ));
    }
    for p in [1.0_f32, 10.0, 100.0] {
        phong.push(curve(
            format!("Blinn-Phong p = {p}"),
            BlinnPhong::new(0.0_f32, 1.0, p, BlinnPhongForm::Normalized)?,
        ));
    }

    let mut modified = Vec::new();
    for p in [1.0_f32, 5.0, 10.0, 20.0, 100.0] {
        modified.push(curve(
            format!("p = {p}"),
            BlinnPhong::new(0.0_f32, 1.0, p, BlinnPhongForm::Modified)?,
        ));
    }

    let mut ggx = Vec::new();
    let mut beckmann = Vec::new();
    for a in roughnesses {
        ggx.extend(conductor_pair(a, Ggx::isotropic(alpha(a)?))?);
        beckmann.extend(conductor_pair(a, Beckmann::isotropic(alpha(a)?))?);
    }

    let mut coated = Vec::new();
    for a in [0.1_f32, 0.5, 1.0] {
        let single = RoughDielectric::new(Ggx::isotropic(alpha(a)?), glass)
            .with_mode(TransportMode::Importance);
        coated.push(curve(format!("dielectric α = {a}"), single));
        coated.push(compensated(
            "  compensated",
            single.with_energy_compensation()?,
        ));
    }
    coated.push(curve("glazed ρ = 1", Glazed::new(1.0_f32, glass)?));
    coated.push(curve(
        "plastic ρ = 1, α = 0.6",
        Plastic::new(1.0_f32, Ggx::isotropic(alpha(0.6)?), glass)?,
    ));
    coated.push(compensated(
        "  compensated coat",
        Plastic::compensated(1.0_f32, Ggx::isotropic(alpha(0.6)?), glass)?,
    ));
    let (ggx, beckmann, coated) = (coloured(ggx), coloured(beckmann), coloured(coated));
    let (diffuse, phong, modified) = (coloured(diffuse), coloured(phong), coloured(modified));

    Ok(vec![
        Panel {
            title: "Diffuse models, ρ = 1",
            curves: diffuse,
        },
        Panel {
            title: "Phong, normalised Blinn-Phong (k_s = 1)",
            curves: phong,
        },
        Panel {
            title: "The seed's modified Blinn-Phong (k_s = 1)",
            curves: modified,
        },
        Panel {
            title: "GGX conductor, F = 1 (dashed: compensated)",
            curves: ggx,
        },
        Panel {
            title: "Beckmann conductor, F = 1 (dashed: compensated)",
            curves: beckmann,
        },
        Panel {
            title: "Rough glass η = 1.5 (R + T), glazed, plastic",
            curves: coated,
        },
    ])
}

/// Measures every curve at θo = 0°, 1°, …, 89° (in the plane `φ = 0`).
fn measure(panels: &mut [Panel]) {
    let check = BxdfCheck {
        samples: SAMPLES,
        seed: 7,
    };
    for c in panels.iter_mut().flat_map(|p| p.curves.iter_mut()) {
        c.points = (0..=THETA_MAX)
            .map(|t| {
                let (s, z) = (t as f32).to_radians().sin_cos();
                let e = albedo_sampled(c.model.as_ref(), Vec3::new(s, 0.0, z), &check);
                (f64::from(t), e)
            })
            .collect();
    }
}

fn text_style(size: f64, colour: RGBColor) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&colour)
}

/// A y range holding every curve's ±2σ band and the line `E = 1`, padded.
fn y_range(panel: &Panel) -> (f64, f64) {
    let (mut lo, mut hi) = (1.0_f64, 1.0_f64);
    for (_, e) in panel.curves.iter().flat_map(|c| &c.points) {
        if e.mean.is_finite() && e.std_err.is_finite() {
            lo = lo.min(e.mean - 2.0 * e.std_err);
            hi = hi.max(e.mean + 2.0 * e.std_err);
        }
    }
    let pad = 0.06 * (hi - lo).max(0.1);
    ((lo - pad).max(0.0), hi + pad)
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let (width, _) = area.dim_in_pixel();
    let (plot, legend) = area.split_horizontally(width.saturating_sub(LEGEND_WIDTH));
    let (y_lo, y_hi) = y_range(panel);
    let mut chart = ChartBuilder::on(&plot)
        .caption(panel.title, text_style(19.0, BLACK))
        .margin(8)
        .x_label_area_size(44)
        .y_label_area_size(58)
        .build_cartesian_2d(0.0_f64..90.0, y_lo..y_hi)?;
    chart
        .configure_mesh()
        .x_labels(7)
        .y_labels(8)
        .x_label_formatter(&|x| format!("{x:.0}°"))
        .y_label_formatter(&|y| format!("{y:.2}"))
        .x_desc("viewing angle θo")
        .y_desc("directional albedo E(θo)")
        .label_style(text_style(14.0, BLACK))
        .axis_desc_style(text_style(15.0, BLACK))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()?;
    chart.draw_series(DashedLineSeries::new(
        vec![(0.0, 1.0), (90.0, 1.0)],
        8,
        6,
        BLACK.stroke_width(2),
    ))?;
    for c in &panel.curves {
        let colour = &COLOURS[c.colour % COLOURS.len()];
        let band: Vec<(f64, f64)> = c
            .points
            .iter()
            .map(|(t, e)| (*t, e.mean + 2.0 * e.std_err))
            .chain(
                c.points
                    .iter()
                    .rev()
                    .map(|(t, e)| (*t, e.mean - 2.0 * e.std_err)),
            )
            .collect();
        chart.draw_series(std::iter::once(Polygon::new(band, colour.mix(0.25))))?;
        let line = c.points.iter().map(|(t, e)| (*t, e.mean));
        if c.dashed {
            chart.draw_series(DashedLineSeries::new(line, 7, 4, colour.stroke_width(2)))?;
        } else {
            chart.draw_series(LineSeries::new(line, colour.stroke_width(2)))?;
        }
    }

    // The legend, beside the plot.
    let mut y = 60;
    for c in &panel.curves {
        let colour = &COLOURS[c.colour % COLOURS.len()];
        if c.dashed {
            for x in [4, 14, 24] {
                legend.draw(&PathElement::new(
                    vec![(x, y), (x + 6, y)],
                    colour.stroke_width(3),
                ))?;
            }
        } else {
            legend.draw(&PathElement::new(
                vec![(4, y), (30, y)],
                colour.stroke_width(3),
            ))?;
        }
        legend.draw(&Text::new(
            c.label.clone(),
            (36, y),
            text_style(14.0, BLACK).pos(Pos::new(HPos::Left, VPos::Center)),
        ))?;
        y += 24;
    }
    legend.draw(&PathElement::new(
        vec![(4, y), (30, y)],
        BLACK.stroke_width(2),
    ))?;
    legend.draw(&Text::new(
        "E = 1",
        (36, y),
        text_style(14.0, BLACK).pos(Pos::new(HPos::Left, VPos::Center)),
    ))?;
    Ok(())
}

fn draw_figure<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, panels: &[Panel]) -> Result<()>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let (header, body) = root.split_vertically(HEADER);
    let (width, _) = header.dim_in_pixel();
    let centre = i32::try_from(width / 2).unwrap_or(0);
    header.draw(&Text::new(
        "Directional albedo E(θo) = ∫ f(wo, wi) |cos θi| dωi of white models",
        (centre, 10),
        text_style(22.0, BLACK).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    header.draw(&Text::new(
        format!(
            "mean of lobe::verify::albedo_sampled, {SAMPLES} samples per point; \
             shaded: ±2 standard errors; dashed black: E = 1 (energy conserved, nothing lost); \
             dashed colour: energy-compensated"
        ),
        (centre, 42),
        text_style(15.0, RGBColor(80, 80, 80)).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let rows = panels.len().div_ceil(COLUMNS);
    let cells = body.split_evenly((rows, COLUMNS));
    for (cell, panel) in cells.iter().zip(panels) {
        draw_panel(cell, panel)?;
    }
    root.present()?;
    Ok(())
}

fn main() -> Result<()> {
    plotters::style::register_font(FAMILY, FontStyle::Normal, FONT)
        .map_err(|_| "docs/fonts/DejaVuSans.ttf is not a usable font")?;
    let mut panels = panels()?;
    measure(&mut panels);

    let rows = u32::try_from(panels.len().div_ceil(COLUMNS)).unwrap_or(1);
    let columns = u32::try_from(COLUMNS).unwrap_or(1);
    let size = (PANEL.0 * columns, HEADER + PANEL.1 * rows);
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    std::fs::create_dir_all(&docs)?;
    let svg = docs.join("albedo.svg");
    draw_figure(&SVGBackend::new(&svg, size).into_drawing_area(), &panels)?;
    let png = docs.join("albedo.png");
    draw_figure(&BitMapBackend::new(&png, size).into_drawing_area(), &panels)?;
    println!("wrote {} and {}", svg.display(), png.display());
    for c in panels.iter().flat_map(|p| &p.curves) {
        let (lo, hi) = c
            .points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (_, e)| {
                (lo.min(e.mean), hi.max(e.mean))
            });
        println!("{:<28} E from {lo:.3} to {hi:.3}", c.label);
    }
    Ok(())
}
