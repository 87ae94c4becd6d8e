//! The Beckmann distribution, anisotropic, with exact Smith masking or Walter's rational fit.

use super::{NormalDistribution, SampleDCos, Sampling, View};
use crate::math::{erf_inv_approx, erfc, exp, ln, ln_1p, sin_cos_turns, sqrt};
use crate::param::Alpha;
use core::f32::consts::FRAC_1_PI;
use glam::{Vec2, Vec3};

/// `1/√π`.
const FRAC_1_SQRT_PI: f32 = 0.564_189_6;

/// Which Smith masking function a [`Beckmann`] distribution uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BeckmannMasking {
    /// The exact Smith `Λ(a) = (erf(a) − 1)/2 + e^(−a²)/(2a√π)`, `a = 1/(α tan θ)`
    /// (Walter et al. 2007, eq. 25 and the text after it).
    #[default]
    Exact,
    /// Walter's rational approximation (Walter et al. 2007, eq. 27;
    /// [ERRATA #9](crate::errata#erratum-9--walter-rational-g1)):
    /// `G1 = (3.535a + 2.181a²) / (1 + 2.276a + 2.577a²)` for `a < 1.6`, else `1`.
    /// Mitsuba 3 uses it. It is within 3.1e-3 of the exact `G1` (measured, at `a ≈ 1.34`),
    /// so it conserves the projected area only to that order (measured: at most 0.44% ± 0.18% off over
    /// `α ∈ [0.01, 2]`, `θ ≤ 89°`), and it exceeds 1 by up to 6.1e-5 just below `a = 1.6`.
    WalterRational,
}

/// The Beckmann distribution of microfacet normals (a Gaussian of slopes), with widths
/// `αx`, `αy` along the local `x` and `y` axes.
///
/// ```text
/// D(m) = exp(−((mx/αx)² + (my/αy)²) / mz²) / (π αx αy mz⁴)      (m.z > 0)
/// Λ(w) = (erf(a) − 1)/2 + exp(−a²) / (2 a √π),   a = wz / |(αx wx, αy wy)|
/// ```
///
/// Beckmann & Spizzichino 1963; Walter et al. 2007, eqs. 25–27; anisotropic form from Heitz
/// 2014, eqs. 83–84. Widths `α ∈ [1e-4, 10]` ([`Alpha`]).
///
/// Laws (measured by the crate's tests, `tests/microfacet.rs`): `D` is normalised; with
/// [`BeckmannMasking::Exact`] the projected area and `∫ D_w dm = 1` hold within the Monte
/// Carlo error for `α` from 0.01 to 2 at 1:1 and 1:4 anisotropy; with
/// [`BeckmannMasking::WalterRational`] the projected area is off by at most 0.5%.
///
/// Sampling: visible normals by inverting the conditional CDF of the visible slopes with a
/// safeguarded Newton iteration (the approach of Heitz & d'Eon 2014 and Jakob 2014), and
/// `D cos θ` by the slopes' Gaussian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beckmann {
    ax: f32,
    ay: f32,
    masking: BeckmannMasking,
}

impl Beckmann {
    /// An anisotropic Beckmann distribution with exact Smith masking.
    #[must_use]
    pub fn new(ax: Alpha, ay: Alpha) -> Self {
        Self {
            ax: ax.get(),
            ay: ay.get(),
            masking: BeckmannMasking::Exact,
        }
    }

    /// An isotropic Beckmann distribution of width `alpha`, with exact Smith masking.
    #[must_use]
    pub fn isotropic(alpha: Alpha) -> Self {
        Self::new(alpha, alpha)
    }

    /// The same distribution with the masking function `masking`.
    #[must_use]
    pub fn with_masking(self, masking: BeckmannMasking) -> Self {
        Self { masking, ..self }
    }

    /// The widths `(αx, αy)`.
    #[inline]
    #[must_use]
    pub fn alpha(&self) -> (f32, f32) {
        (self.ax, self.ay)
    }

    /// The masking function in use.
    #[inline]
    #[must_use]
    pub fn masking(&self) -> BeckmannMasking {
        self.masking
    }

    /// `a = 1 / (α(φ) tan θ) = |wz| / |(αx wx, αy wy)|`; `+∞` along the normal.
    #[inline]
    fn a(&self, w: Vec3) -> f32 {
        let (x, y) = (self.ax * w.x, self.ay * w.y);
        w.z.abs() / sqrt(x * x + y * y)
    }
}

/// The exact Beckmann Smith `Λ(a)`, written with `erfc` so that its small tail keeps digits.
#[inline]
fn lambda_exact(a: f32) -> f32 {
    if a == f32::INFINITY {
        return 0.0;
    }
    // (erf a − 1)/2 + e^(−a²)/(2a√π) = (e^(−a²)/(a√π) − erfc a) / 2; +∞ at a = 0.
    (0.5 * (exp(-a * a) * FRAC_1_SQRT_PI / a - erfc(a))).max(0.0)
}

/// Walter's rational `G1(a)` (Walter et al. 2007, eq. 27).
#[inline]
fn g1_rational(a: f32) -> f32 {
    if a >= 1.6 {
        1.0
    } else {
        (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a)
    }
}

impl NormalDistribution for Beckmann {
    #[inline]
    fn sampling(&self) -> Sampling {
        Sampling::VisibleNormals
    }

    #[inline]
    fn d(&self, m: Vec3) -> f32 {
        if !(m.z > 0.0) {
            return 0.0;
        }
        let (x, y) = (m.x / self.ax, m.y / self.ay);
        let z2 = m.z * m.z;
        let e = exp(-(x * x + y * y) / z2);
        if e == 0.0 {
            return 0.0;
        }
        e * FRAC_1_PI / (self.ax * self.ay * z2 * z2)
    }

    #[inline]
    fn lambda(&self, w: Vec3) -> f32 {
        let a = self.a(w);
        match self.masking {
            BeckmannMasking::Exact => lambda_exact(a),
            // Λ = 1/G1 − 1 = (1 − 1.259a + 0.396a²) / (3.535a + 2.181a²) for a < 1.6.
            BeckmannMasking::WalterRational => {
                if a >= 1.6 {
                    0.0
                } else {
                    (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a)
                }
            }
        }
    }

    #[inline]
    fn g1(&self, w: Vec3) -> f32 {
        let a = self.a(w);
        match self.masking {
            BeckmannMasking::Exact => 1.0 / (1.0 + lambda_exact(a)),
            BeckmannMasking::WalterRational => g1_rational(a),
        }
    }

    /// In the configuration stretched to `α = 1`, with the view at polar angle `θ`, the
    /// visible slope `x̃` along the view's azimuth has the density `∝ (cos θ − x̃ sin θ) e^(−x̃²)`
    /// for `x̃ < cot θ` and the other slope `ỹ` is an independent Gaussian (Heitz & d'Eon
    /// 2014, §4 and supplemental). The CDF of `x̃`,
    /// `C(x) = cos θ · erfc(−x)/2 + sin θ · e^(−x²)/(2√π)`, is inverted by Newton steps kept
    /// inside a shrinking bracket.
    fn sample(&self, view: &View, u: Vec2) -> Vec3 {
        let w = view.w;
        let ws = Vec3::new(self.ax * w.x, self.ay * w.y, w.z).normalize_or(Vec3::Z);
        let sin_t = sqrt(ws.x * ws.x + ws.y * ws.y);
        let cos_t = ws.z;
        let x = sample_visible_slope(cos_t, sin_t, u.x);
        let y = erf_inv_approx((2.0 * u.y - 1.0).clamp(-1.0 + f32::EPSILON, 1.0 - f32::EPSILON));
        // Rotate from the view's azimuth back to the stretched frame, then unstretch.
        let (cos_p, sin_p) = if sin_t > 0.0 {
            (ws.x / sin_t, ws.y / sin_t)
        } else {
            (1.0, 0.0)
        };
        let (sx, sy) = (cos_p * x - sin_p * y, sin_p * x + cos_p * y);
        Vec3::new(-self.ax * sx, -self.ay * sy, 1.0).normalize_or(Vec3::Z)
    }
}

impl SampleDCos for Beckmann {
    /// Slopes drawn from the Gaussian slope distribution, radius `√(−ln(1 − u))`, stretched
    /// by `(αx, αy)` (Walter et al. 2007, eq. 28, in slope form).
    #[inline]
    fn sample_d_cos(&self, u: Vec2) -> Vec3 {
        let r = sqrt(-ln_1p(-u.x.min(1.0 - f32::EPSILON / 2.0)));
        let (s, c) = sin_cos_turns(u.y);
        Vec3::new(-self.ax * r * c, -self.ay * r * s, 1.0).normalize_or(Vec3::Z)
    }
}

// SLOPE_TABLE: the quantile x̃(cos θ, u), computed by build.rs.
include!(concat!(env!("OUT_DIR"), "/beckmann_slopes.rs"));

/// The start of the visible-slope iteration: [`SLOPE_TABLE`] (the quantile on a 33 × 65 grid
/// in `cos θ` and `u`, computed in `f64` by the build script) interpolated bilinearly.
///
/// In the first and last intervals of `u` the quantile runs off steeply (to `−∞` like the
/// Rayleigh quantile `−√(−ln u)` below, toward `cot θ` above), which no linear interpolation
/// follows: there the start blends the two limits the density interpolates between, weighted
/// by their masses, the Gaussian quantile (normal incidence, exact there) and that Rayleigh
/// quantile (grazing).
#[inline]
fn slope_start(cos_t: f32, u: f32) -> f32 {
    let (rows, cols) = (SLOPE_TABLE.len() - 1, SLOPE_TABLE[0].len() - 1);
    let a = cos_t.clamp(0.0, 1.0) * rows as f32;
    let b = u.clamp(0.0, 1.0) * cols as f32;
    if !(1.0..(cols - 1) as f32).contains(&b) {
        let sin_t = crate::math::safe_sqrt(1.0 - cos_t * cos_t);
        let gauss = erf_inv_approx((2.0 * u - 1.0).max(-1.0 + f32::EPSILON));
        let rayleigh = -sqrt(-ln(u.max(f32::MIN_POSITIVE)));
        let w_gauss = cos_t / (cos_t + sin_t * FRAC_1_SQRT_PI);
        return w_gauss * gauss + (1.0 - w_gauss) * rayleigh;
    }
    let (i, j) = ((a as usize).min(rows - 1), (b as usize).min(cols - 1));
    let (fa, fb) = (a - i as f32, b - j as f32);
    let lerp = |r: &[f32; 65]| r[j] + fb * (r[j + 1] - r[j]);
    let (p, q) = (lerp(&SLOPE_TABLE[i]), lerp(&SLOPE_TABLE[i + 1]));
    p + fa * (q - p)
}

/// Samples the visible slope `x̃ ≤ cot θ` with density `∝ (cos θ − x̃ sin θ) e^(−x̃²)`.
///
/// Newton steps on the CDF, kept inside a shrinking bracket, from the tabulated quantile
/// ([`slope_start`]). The iteration stops when the CDF matches `u` to its own `f32`
/// resolution, or when the step is below 1e-6; each step costs one `erfc` and one `exp`.
fn sample_visible_slope(cos_t: f32, sin_t: f32, u: f32) -> f32 {
    // The unnormalised CDF C(x) and its derivative C'(x) = (cos θ − x sin θ) e^(−x²)/√π,
    // sharing the one exponential.
    let cdf_slope = |x: f32| {
        let e = exp(-x * x) * FRAC_1_SQRT_PI;
        (
            0.5 * (cos_t * erfc(-x) + sin_t * e),
            (cos_t - x * sin_t) * e,
        )
    };
    const LIMIT: f32 = 6.0;
    let mu = if sin_t > 0.0 {
        cos_t / sin_t
    } else {
        f32::INFINITY
    };
    let (mut lo, mut hi) = (-LIMIT, mu.min(LIMIT));
    let total = cdf_slope(hi).0;
    let target = u.clamp(0.0, 1.0) * total;
    let mut x = slope_start(cos_t, u);
    if !(x > lo && x < hi) {
        x = 0.5 * (lo + hi);
    }
    for _ in 0..40 {
        let (c, slope) = cdf_slope(x);
        let f = c - target;
        if f.abs() <= 2.0 * f32::EPSILON * total {
            return x;
        }
        if f > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        let newton = x - f / slope;
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - x).abs() <= 1e-6 * (1.0 + x.abs()) {
            return next;
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The build script's table starts the iteration close to where it ends, over the grid's
    /// interior in `u` (the end intervals start from the analytic blend instead).
    #[test]
    fn tabulated_start_is_close_to_the_solution() {
        let mut worst = (0.0_f32, 0.0, 0.0);
        for i in 0..=40 {
            let cos_t = 0.02 + 0.96 * i as f32 / 40.0;
            let sin_t = (1.0 - cos_t * cos_t).sqrt();
            for j in 2..=98 {
                let u = j as f32 / 100.0;
                let x = sample_visible_slope(cos_t, sin_t, u);
                let e = (slope_start(cos_t, u) - x).abs();
                if e > worst.0 {
                    worst = (e, cos_t, u);
                }
            }
        }
        std::eprintln!("largest start error {worst:?} (error, cos θ, u)");
        let worst = worst.0;
        // Measured: 0.031, next to the last interval of a near-normal view, where the
        // quantile steepens toward its Gaussian tail; a few thousandths elsewhere.
        assert!(worst < 0.05, "largest start error {worst}");
    }
}
