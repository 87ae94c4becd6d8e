//! The laws of a microfacet distribution, measured, reported and checked: `D`
//! normalisation, projected area, visible-normal normalisation, and the sampler against its
//! density (chi-square); [`check_ndf`] runs them all.
//!
//! The integrals are estimated by importance sampling with a proposal that knows nothing of the
//! distribution under test ([`integrate_hemisphere`]): a defensive mixture, in equal parts, of
//! cosine-weighted and uniform directions *stretched* by the caller's `stretch = (sx, sy)` (usually
//! the distribution's widths), so that the proposal has the right scale for a narrow lobe, and of
//! uniform directions unstretched, whose heavier tails bound the weights where a distribution's
//! tails are wider than its width suggests. A check that used the distribution's own sampler would
//! be circular.
//!
//! For the same reason the sampler checks run the chi-square test on *unstretched*
//! normals, where a narrow lobe covers many bins instead of one.

use super::config::Config;
use super::report::{Law, LawReport, Report};
use crate::microfacet::NormalDistribution;
use crate::verify::stats::{
    Chi2Config, Chi2Report, Estimate, chi2_sphere_rng, integrate_hemisphere, sidak,
    stretch_direction as stretch, two_sided_quantile,
};
use glam::{Vec2, Vec3};
use std::format;
use std::string::String;
use std::vec;

/// The density of `normalize(M h)`, `M = diag(sx, sy, 1)`, for `h` of density `pdf_h`:
/// `pdf_h · |M h|³ / (sx sy)` (the Jacobian of a linear map of directions).
fn stretched_density(h: Vec3, s: Vec2, pdf_h: f64) -> f64 {
    let (sx, sy) = (f64::from(s.x), f64::from(s.y));
    let (x, y, z) = (sx * f64::from(h.x), sy * f64::from(h.y), f64::from(h.z));
    let len = (x * x + y * y + z * z).sqrt();
    pdf_h * len * len * len / (sx * sy)
}

/// `∫ f(m) dωm` over the upper hemisphere with `config`'s integral budget, seed and stretch.
fn integrate(config: &Config, f: impl Fn(Vec3) -> f64) -> Estimate {
    integrate_hemisphere(f, config.integral_samples, config.seed, config.stretch)
}

/// `∫ D(m) cos θm dωm`, which must be `1` (Heitz 2014, eq. 4), estimated with
/// `config.integral_samples` samples of [`integrate_hemisphere`]'s proposal stretched by
/// `config.stretch`.
#[must_use]
pub fn d_normalization<D: NormalDistribution + ?Sized>(dist: &D, config: &Config) -> Estimate {
    integrate(config, |m| f64::from(dist.d(m)) * f64::from(m.z))
}

/// `∫ G1(wo) max(0, wo·m) D(m) dωm`, which must be `cos θo` for a masking function that
/// conserves the projected area (Heitz 2014, eq. 14; [the handout's](crate::handouts#seed-000) fourth
/// law).
#[must_use]
pub fn projected_area<D: NormalDistribution + ?Sized>(
    dist: &D,
    wo: Vec3,
    config: &Config,
) -> Estimate {
    let g1 = f64::from(dist.g1(wo));
    projected_area_masked(dist, wo, |_| g1, config)
}

/// [`projected_area`] with a masking function `g1(m)` of the microfacet normal, for masking
/// terms that are not Smith's (such as Cook-Torrance's V-cavity).
#[must_use]
pub fn projected_area_masked<D: NormalDistribution + ?Sized>(
    dist: &D,
    wo: Vec3,
    g1: impl Fn(Vec3) -> f64,
    config: &Config,
) -> Estimate {
    integrate(config, |m| {
        let wm = f64::from(wo.dot(m));
        if wm > 0.0 {
            g1(m) * wm * f64::from(dist.d(m))
        } else {
            0.0
        }
    })
}

/// `∫ D_w(m) dωm` of the visible normals, which must be `1`.
#[must_use]
pub fn visible_normalization<D: NormalDistribution + ?Sized>(
    dist: &D,
    w: Vec3,
    config: &Config,
) -> Estimate {
    integrate(config, |m| f64::from(dist.d_visible(w, m)))
}

/// The chi-square test of a sampler of microfacet normals against its density, run on the
/// normals unstretched by `stretch = (sx, sy)`: `h = normalize(mx/sx, my/sy, mz)`, whose
/// density is `pdf(m) · sx sy / |(sx hx, sy hy, hz)|³`.
///
/// With `stretch` about the distribution's widths the lobe fills the hemisphere, so the
/// test has power even for `α = 0.01`.
pub fn chi2_normals(
    mut sampler: impl FnMut(Vec2) -> Vec3,
    pdf: impl Fn(Vec3) -> f64,
    stretch_by: Vec2,
    config: &Chi2Config,
) -> Chi2Report {
    let s = stretch_by;
    chi2_sphere_rng(
        |rng| {
            let m = sampler(rng.next_vec2());
            Some(Vec3::new(m.x / s.x, m.y / s.y, m.z).normalize_or(Vec3::NAN))
        },
        // The density of h is pdf(m) · dω_m/dω_h, the reciprocal of `stretched_density`'s factor.
        |h| {
            let m = stretch(h, s);
            let p = pdf(m);
            if p == 0.0 {
                0.0
            } else {
                p / stretched_density(h, s, 1.0)
            }
        },
        config,
    )
}

/// Runs the laws of a microfacet distribution as reports: `D` normalisation, projected area
/// (the figure is the largest `|∫ … / cos θo − 1|` over the angles), visible normalisation
/// (largest `|∫ D_w − 1|`) and the chi-square test of [`NormalDistribution::sample`] against
/// [`NormalDistribution::pdf`], each Šidák-corrected over its angles.
///
/// It reads `config.integral_samples`, `chi2_samples`, `seed`, `significance`, `directions`
/// (each above the surface; empty for the default angles) and `stretch` (set it to the
/// distribution's widths).
///
/// ```
/// use lobe::microfacet::Ggx;
/// use lobe::verify::{check_ndf, Config};
/// use lobe::{Alpha, Vec2};
/// let config = Config {
///     integral_samples: 50_000,
///     chi2_samples: 50_000,
///     stretch: Vec2::splat(0.3),
///     ..Config::default()
/// };
/// let report = check_ndf("GGX", &Ggx::isotropic(Alpha::new(0.3)?), &config);
/// assert!(report.passed(), "{report}");
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[must_use]
pub fn check_ndf<D: NormalDistribution + ?Sized>(name: &str, dist: &D, config: &Config) -> Report {
    let dirs = config.distribution_directions();
    let n = dirs.len().max(1);
    let k1 = two_sided_quantile(config.significance / 4.0);
    let k = two_sided_quantile(sidak(config.significance / 4.0, n));
    let budget = format!("{} samples", config.integral_samples);

    let e = d_normalization(dist, config);
    let norm = LawReport {
        law: Law::DNormalization,
        passed: e.within(1.0, k1),
        figure: e.mean,
        uncertainty: e.std_err,
        figure_name: "∫ D cos θ",
        budget: budget.clone(),
        detail: format!("want 1 within {k1:.2}σ"),
    };

    // The largest relative deviation of an integral from its target over the angles.
    let worst = |f: &dyn Fn(Vec3) -> (Estimate, f64)| {
        let mut out = (0.0_f64, 0.0_f64, 0.0_f32, true);
        for &(t, w) in &dirs {
            let (e, target) = f(w);
            let dev = (e.mean / target - 1.0).abs();
            let ok = e.within(target, k);
            if dev > out.0 {
                out = (dev, e.std_err / target, t, out.3);
            }
            out.3 &= ok;
        }
        out
    };
    // The report of the largest deviation, `detail` saying at which angle.
    let deviation =
        |law, figure_name, detail: &dyn Fn(f32) -> String, (dev, sd, at, ok)| LawReport {
            law,
            passed: ok,
            figure: dev,
            uncertainty: sd,
            figure_name,
            budget: format!("{budget} × {n} angles"),
            detail: detail(at),
        };
    let area = deviation(
        Law::ProjectedArea,
        "max |∫ G1 ⟨wo,m⟩ D / cos θo − 1|",
        &|at| format!("largest at θo = {at}°, k = {k:.2}"),
        worst(&|w| (projected_area(dist, w, config), f64::from(w.z))),
    );
    let visible = deviation(
        Law::VisibleNormalization,
        "max |∫ D_w − 1|",
        &|at| format!("largest at θ = {at}°"),
        worst(&|w| (visible_normalization(dist, w, config), 1.0)),
    );

    let significance = sidak(config.significance / 4.0, n);
    let mut min_p = (1.0_f64, 0.0_f32);
    let mut failure = None;
    for (i, &(t, w)) in dirs.iter().enumerate() {
        let chi = Chi2Config {
            samples: config.chi2_samples,
            seed: config.seed.wrapping_add(i as u64),
            significance,
            ..Chi2Config::default()
        };
        let view = dist.view(w);
        let r = chi2_normals(
            |u| dist.sample(&view, u),
            |m| f64::from(dist.pdf(&view, m, dist.d(m))),
            config.stretch,
            &chi,
        );
        // A NaN (no degrees of freedom: a failed check) is reported, not hidden behind 1.
        if r.p_value < min_p.0 || r.p_value.is_nan() {
            min_p = (r.p_value, t);
        }
        if !r.passed() && failure.is_none() {
            failure = Some(format!("at θ = {t}°: p = {:.2e}", r.p_value));
        }
    }
    let sampling = LawReport {
        law: Law::Sampling,
        passed: failure.is_none(),
        figure: min_p.0,
        uncertainty: 0.0,
        figure_name: "min p-value",
        budget: format!("{} samples × {n} angles", config.chi2_samples),
        detail: failure.unwrap_or_else(|| format!("smallest at θ = {}°", min_p.1)),
    };
    Report {
        name: name.into(),
        laws: vec![norm, area, visible, sampling],
    }
}
