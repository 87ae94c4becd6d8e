//! Polar plots of the models' lobes: `f(wo, wi) · |cos θi|` in the plane of incidence.
//!
//! For each model and a few roughness or exponent settings, one panel draws the scattered
//! distribution for the viewer at θo = 0°, 30°, 60° and 80° (one colour each; a dashed ray
//! marks `wo`). The radius in the direction `wi` is `f(wo, wi) |cos θi|`, the integrand of
//! the directional albedo, on one scale per panel so that the curves of a panel compare; the
//! grey circles carry their radius. Reflection-only models draw the upper half plane, the
//! rough dielectric the full circle (reflection above, transmission below the surface).
//! Delta lobes have no density and are not drawn: `Glazed` shows its diffuse part only. On
//! the rough dielectric's common scale the reflection (about 4% of the light at η = 1.5) is
//! small beside the transmission, which refraction also concentrates.
//! This is the handout's "Phong model—plots" figure, for eleven models of the crate in ten figures
//! (the GTR and Blinn-Phong-distribution conductors, the sheen, the diffuse transmitter, the
//! energy-compensated models and the composites are not drawn).
//!
//! ```text
//! cargo run --release --example lobes
//! ```
//!
//! writes `docs/lobes/<model>.svg` and `docs/lobes/<model>.png`. The PNGs' text uses the
//! DejaVu Sans font shipped in `docs/fonts/` (Bitstream Vera licence), so no system font
//! library is needed.

use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, OrenNayar, Phong, Plastic, RoughDielectric,
};
use lobe::fresnel::Conductor;
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::{Alpha, ComplexIor, Eta, Roughness, Vec3};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::error::Error;
use std::path::{Path, PathBuf};

type Result<T> = std::result::Result<T, Box<dyn Error>>;

/// DejaVu Sans, for the text of the PNGs (the SVGs name the family only).
const FONT: &[u8] = include_bytes!("../docs/fonts/DejaVuSans.ttf");
/// The family every text style of this example uses.
const FAMILY: &str = "sans-serif";

/// The viewer's angles from the normal, in degrees, one curve each.
const THETA_O: [f32; 4] = [0.0, 30.0, 60.0, 80.0];
/// One colour per viewer angle.
const COLOURS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(214, 39, 40),
];
/// Angular step of the curves, in degrees.
const STEP_DEG: f32 = 0.25;

/// Pixel size of one panel: reflection-only (half plane) and full circle.
const HALF_PANEL: (u32, u32) = (470, 330);
const FULL_PANEL: (u32, u32) = (470, 540);
/// Height of a figure's title and legend strip.
const HEADER: u32 = 86;

type Model = Box<dyn Bxdf<Spectrum = f32>>;

/// One polar plot: a model with one setting.
struct Panel {
    title: String,
    model: Model,
}

/// One output file: a row-major grid of panels with a title.
struct Figure {
    file: &'static str,
    title: String,
    columns: usize,
    full_circle: bool,
    panels: Vec<Panel>,
}

fn panel(title: impl Into<String>, model: impl Bxdf<Spectrum = f32> + 'static) -> Panel {
    Panel {
        title: title.into(),
        model: Box::new(model),
    }
}

fn alpha(a: f32) -> Result<Alpha> {
    Ok(Alpha::new(a)?)
}

fn figures() -> Result<Vec<Figure>> {
    // Aluminium at 550 nm, the conductors' metal (one channel).
    let aluminium = ComplexIor::new(0.96_f32, 6.69)?;
    let glass = Eta::new(1.5)?;
    let mut out = Vec::new();

    out.push(Figure {
        file: "lambert",
        title: "Lambert, ρ = 0.8".into(),
        columns: 1,
        full_circle: false,
        panels: vec![panel(
            "ρ = 0.8 (one circle for every θo)",
            Lambert::new(0.8_f32)?,
        )],
    });

    let mut panels = Vec::new();
    for sigma in [0.2_f32, 0.5, 1.0] {
        panels.push(panel(
            format!("σ = {sigma} rad"),
            OrenNayar::new(0.8_f32, sigma)?,
        ));
    }
    out.push(Figure {
        file: "oren_nayar",
        title: "Oren-Nayar (qualitative model), ρ = 0.8".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for r in [0.25_f32, 0.5, 1.0] {
        panels.push(panel(
            format!("r = {r}"),
            EnergyPreservingOrenNayar::new(0.8_f32, r)?,
        ));
    }
    out.push(Figure {
        file: "eon",
        title: "Energy-preserving Oren-Nayar (EON), ρ = 0.8".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for r in [0.0_f32, 0.5, 1.0] {
        panels.push(panel(
            format!("r = {r}"),
            DisneyDiffuse::new(0.8_f32, Roughness::new(r)?)?,
        ));
    }
    out.push(Figure {
        file: "disney_diffuse",
        title: "Disney diffuse, ρ = 0.8".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for p in [1.0_f32, 10.0, 100.0] {
        panels.push(panel(format!("p = {p}"), Phong::new(0.0_f32, 1.0, p)?));
    }
    out.push(Figure {
        file: "phong",
        title: "Modified Phong (Lafortune & Willems), k_d = 0, k_s = 1".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for (form, name) in [
        (BlinnPhongForm::Normalized, "normalised"),
        (BlinnPhongForm::Modified, "modified (seed)"),
    ] {
        for p in [1.0_f32, 10.0, 100.0] {
            panels.push(panel(
                format!("{name}, p = {p}"),
                BlinnPhong::new(0.0_f32, 1.0, p, form)?,
            ));
        }
    }
    out.push(Figure {
        file: "blinn_phong",
        title: "Blinn-Phong, k_s = 1: normalised (top) and the seed's modified form (bottom)"
            .into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for a in [0.1_f32, 0.3, 0.6] {
        panels.push(panel(
            format!("α = {a}"),
            Microfacet::new(
                Ggx::isotropic(alpha(a)?),
                Masking::HeightCorrelated,
                Conductor { ior: aluminium },
            ),
        ));
    }
    out.push(Figure {
        file: "ggx_conductor",
        title: "GGX conductor (aluminium, η = 0.96 + 6.69i), height-correlated Smith".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for a in [0.1_f32, 0.3, 0.6] {
        panels.push(panel(
            format!("α = {a}"),
            Microfacet::new(
                Beckmann::isotropic(alpha(a)?),
                Masking::HeightCorrelated,
                Conductor { ior: aluminium },
            ),
        ));
    }
    out.push(Figure {
        file: "beckmann_conductor",
        title: "Beckmann conductor (aluminium, η = 0.96 + 6.69i), height-correlated Smith".into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    let mut panels = Vec::new();
    for a in [0.1_f32, 0.3, 0.6] {
        panels.push(panel(
            format!("α = {a}"),
            RoughDielectric::new(Ggx::isotropic(alpha(a)?), glass),
        ));
    }
    out.push(Figure {
        file: "rough_dielectric",
        title: "Rough dielectric (GGX, η = 1.5, seen from outside): reflection above, transmission below"
            .into(),
        columns: 3,
        full_circle: true,
        panels,
    });

    let mut panels = vec![panel("glazed (smooth coat)", Glazed::new(0.8_f32, glass)?)];
    for a in [0.05_f32, 0.3] {
        panels.push(panel(
            format!("plastic, GGX coat α = {a}"),
            Plastic::new(0.8_f32, Ggx::isotropic(alpha(a)?), glass)?,
        ));
    }
    out.push(Figure {
        file: "glazed_plastic",
        title: "Diffuse base (ρ = 0.8) under a coat of η = 1.5: glazed (delta part not drawn) and plastic"
            .into(),
        columns: 3,
        full_circle: false,
        panels,
    });

    Ok(out)
}

/// The direction at `deg` degrees from the normal in the plane of incidence, `x` toward the
/// viewer's side.
fn direction(deg: f32) -> Vec3 {
    let (s, c) = deg.to_radians().sin_cos();
    Vec3::new(s, 0.0, c)
}

/// The polar curve `f(wo, wi)|cos θi|` for the viewer at `theta_o` degrees, as `(x, z)`
/// points, over the upper half plane or the full circle.
fn curve(model: &dyn Bxdf<Spectrum = f32>, theta_o: f32, full: bool) -> Vec<(f64, f64)> {
    let wo = direction(theta_o);
    let limit = if full { 180.0 } else { 90.0 };
    let n = (2.0 * limit / STEP_DEG).round() as usize;
    (0..=n)
        .map(|k| {
            let wi = direction(-limit + k as f32 * STEP_DEG);
            let v = model.eval(wo, wi) * wi.z.abs();
            let r = if v.is_finite() { f64::from(v) } else { 0.0 };
            (r * f64::from(wi.x), r * f64::from(wi.z))
        })
        .collect()
}

/// A "nice" grid step (1, 2 or 5 times a power of ten) giving two to five circles up to `r`.
fn grid_step(r: f64) -> f64 {
    let raw = r / 4.0;
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| r / s <= 4.0)
        .unwrap_or(10.0 * mag)
}

/// Formats a grid radius with as many decimals as the grid step needs.
fn label(v: f64, step: f64) -> String {
    let digits = (-(step.log10() + 1e-9).floor()).max(0.0) as usize;
    format!("{v:.digits$}")
}

fn text_style(size: f64, colour: RGBColor) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&colour)
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    p: &Panel,
    full: bool,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let curves: Vec<Vec<(f64, f64)>> = THETA_O
        .iter()
        .map(|&t| curve(p.model.as_ref(), t, full))
        .collect();
    let peak = curves
        .iter()
        .flatten()
        .map(|(x, y)| x.hypot(*y))
        .fold(0.0_f64, f64::max);
    let step = if peak > 0.0 { grid_step(peak) } else { 0.1 };
    let circles = (peak / step).ceil().max(1.0);
    let r_max = circles * step;

    let area = area.titled(&p.title, text_style(19.0, BLACK))?;
    let area = area.margin(4, 14, 10, 10);
    // Equal scales on both axes: widen whichever range the pixel box leaves room for.
    let (w, h) = area.dim_in_pixel();
    let (w, h) = (f64::from(w.max(1)), f64::from(h.max(1)));
    let pad = 1.1 * r_max;
    let (y_lo, y_hi) = if full {
        (-pad, pad)
    } else {
        (-0.12 * r_max, pad)
    };
    let scale = (w / (2.0 * pad)).min(h / (y_hi - y_lo));
    let (half_w, y_mid, half_h) = (w / scale / 2.0, (y_lo + y_hi) / 2.0, h / scale / 2.0);
    let mut chart = ChartBuilder::on(&area)
        .build_cartesian_2d(-half_w..half_w, (y_mid - half_h)..(y_mid + half_h))?;

    let grid = RGBColor(200, 200, 200);
    let grid_text = RGBColor(110, 110, 110);
    let lowest: i32 = if full { -180 } else { -90 };
    let arc = |r: f64| {
        (lowest..=-lowest).map(move |d| {
            let w = direction(d as f32);
            (r * f64::from(w.x), r * f64::from(w.z))
        })
    };
    // Spokes every 30° from the normal, labelled at the outer circle.
    for d in (lowest..=-lowest).step_by(30) {
        let w = direction(d as f32);
        let (x, y) = (f64::from(w.x), f64::from(w.z));
        chart.draw_series(std::iter::once(PathElement::new(
            vec![(0.0, 0.0), (r_max * x, r_max * y)],
            grid.stroke_width(1),
        )))?;
        if d.abs() % 180 != 90 && d.abs() < 180 {
            let text = format!("{}°", d.abs());
            chart.draw_series(std::iter::once(Text::new(
                text,
                (1.06 * r_max * x, 1.06 * r_max * y),
                text_style(12.0, grid_text).pos(Pos::new(HPos::Center, VPos::Center)),
            )))?;
        }
    }
    // Circles of constant f·cos θi, labelled along the viewer's side of the surface.
    for k in 1..=(circles as usize) {
        let r = k as f64 * step;
        chart.draw_series(std::iter::once(PathElement::new(
            arc(r).collect::<Vec<_>>(),
            grid.stroke_width(1),
        )))?;
        chart.draw_series(std::iter::once(Text::new(
            label(r, step),
            (r, -0.015 * r_max),
            text_style(12.0, grid_text).pos(Pos::new(HPos::Center, VPos::Top)),
        )))?;
    }
    // The surface.
    chart.draw_series(std::iter::once(PathElement::new(
        vec![(-r_max * 1.04, 0.0), (r_max * 1.04, 0.0)],
        BLACK.stroke_width(2),
    )))?;
    // The viewer directions and the lobes.
    for ((&t, c), points) in THETA_O.iter().zip(COLOURS).zip(&curves) {
        let w = direction(t);
        let end = (r_max * f64::from(w.x), r_max * f64::from(w.z));
        chart.draw_series(DashedLineSeries::new(
            vec![(0.0, 0.0), end],
            6,
            5,
            c.stroke_width(1),
        ))?;
        chart.draw_series(LineSeries::new(points.iter().copied(), c.stroke_width(2)))?;
    }
    Ok(())
}

fn draw_figure<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, fig: &Figure) -> Result<()>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let (header, body) = root.split_vertically(HEADER);
    let (width, _) = header.dim_in_pixel();
    let centre = i32::try_from(width / 2).unwrap_or(0);
    header.draw(&Text::new(
        fig.title.clone(),
        (centre, 10),
        text_style(22.0, BLACK).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    // The legend: one entry per viewer angle, and the meaning of the radius.
    let entries: Vec<String> = THETA_O.iter().map(|t| format!("θo = {t}°")).collect();
    let entry_width = 120;
    let note = "radius: f(wo, wi)·|cos θi|,  dashed: direction to the viewer wo";
    let note_width = 520;
    let total = entry_width * entries.len() as i32 + note_width;
    let mut x = centre - total / 2;
    let y = 58;
    for (text, c) in entries.iter().zip(COLOURS) {
        header.draw(&PathElement::new(
            vec![(x, y), (x + 30, y)],
            c.stroke_width(3),
        ))?;
        header.draw(&Text::new(
            text.clone(),
            (x + 36, y),
            text_style(16.0, BLACK).pos(Pos::new(HPos::Left, VPos::Center)),
        ))?;
        x += entry_width;
    }
    header.draw(&Text::new(
        note,
        (x + 10, y),
        text_style(16.0, RGBColor(80, 80, 80)).pos(Pos::new(HPos::Left, VPos::Center)),
    ))?;

    let rows = fig.panels.len().div_ceil(fig.columns);
    let cells = body.split_evenly((rows, fig.columns));
    for (cell, p) in cells.iter().zip(&fig.panels) {
        draw_panel(cell, p, fig.full_circle)?;
    }
    root.present()?;
    Ok(())
}

fn figure_size(fig: &Figure) -> (u32, u32) {
    let (w, h) = if fig.full_circle {
        FULL_PANEL
    } else {
        HALF_PANEL
    };
    let columns = fig.columns.max(1);
    let rows = fig.panels.len().div_ceil(columns);
    let columns = u32::try_from(columns).unwrap_or(1);
    let rows = u32::try_from(rows).unwrap_or(1);
    // A one-panel figure still needs room for the legend strip.
    ((w * columns).max(1050), HEADER + h * rows)
}

fn main() -> Result<()> {
    plotters::style::register_font(FAMILY, FontStyle::Normal, FONT)
        .map_err(|_| "docs/fonts/DejaVuSans.ttf is not a usable font")?;
    let dir: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs")
        .join("lobes");
    std::fs::create_dir_all(&dir)?;
    for fig in figures()? {
        let size = figure_size(&fig);
        let svg = dir.join(format!("{}.svg", fig.file));
        draw_figure(&SVGBackend::new(&svg, size).into_drawing_area(), &fig)?;
        let png = dir.join(format!("{}.png", fig.file));
        draw_figure(&BitMapBackend::new(&png, size).into_drawing_area(), &fig)?;
        println!("wrote {} and {}", svg.display(), png.display());
    }
    Ok(())
}
