//! Exact Smith masking for an isotropic distribution without a closed-form `Λ`, tabulated.

use crate::math::{acos, atan2, cos, gauss_legendre, safe_sqrt, sin, sqrt, tan};
use core::f32::consts::{FRAC_2_PI, FRAC_PI_2, TAU};

/// Entries of the table.
const ENTRIES: usize = 128;

/// Smith's `G1` of an isotropic distribution, computed at construction from the
/// projected-area identity `G1(w) ∫ max(0, w·m) D(m) dωm = cos θw` (Heitz 2014, eq. 14), which
/// determines the Smith masking function uniquely.
///
/// The integral is reduced to one dimension by integrating `φm` in closed form, then
/// evaluated by 8-point Gauss-Legendre quadrature on intervals of `θm` that grow
/// geometrically from the lobe's width, with a break at the kink `θm = π/2 − θw`. The table
/// holds `G1` at 128 values of `p = (2/π) atan(cot θ / β)`, where `β` is the lobe's median
/// slope, so that the entries crowd where `G1` changes; lookups interpolate linearly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SmithTable {
    beta: f32,
    g1: [f32; ENTRIES],
}

impl SmithTable {
    /// Tabulates the `G1` of the isotropic distribution `d(cos θm, sin θm)` (both given, so
    /// that `d` can avoid `1 − cos²` near the normal) whose lobe has median
    /// slope `beta` (the `tan θm` below which half of `D cos θ` lies) and width scale
    /// `width` (where `D` changes fastest near the normal).
    pub(crate) fn new(d: impl Fn(f32, f32) -> f32, beta: f32, width: f32) -> Self {
        let beta = beta.clamp(1e-4, 1e4);
        let mut g1 = [0.0; ENTRIES];
        for (i, g) in g1.iter_mut().enumerate() {
            let p = i as f32 / (ENTRIES - 1) as f32;
            *g = if i == 0 {
                0.0
            } else if i == ENTRIES - 1 {
                1.0
            } else {
                // cot θw = β tan(π p / 2).
                let cot = beta * tan(FRAC_PI_2 * p);
                let inv = 1.0 / sqrt(1.0 + cot * cot);
                let (cos_w, sin_w) = (cot * inv, inv);
                (cos_w / projected_area(&d, cos_w, sin_w, width)).min(1.0)
            };
        }
        Self { beta, g1 }
    }

    /// `G1` of a direction with `cos θ = cos_theta` and `sin θ = sin_theta ≥ 0`.
    #[inline]
    pub(crate) fn g1(&self, cos_theta: f32, sin_theta: f32) -> f32 {
        let p = FRAC_2_PI * atan2(cos_theta.abs(), self.beta * sin_theta);
        let x = p * (ENTRIES - 1) as f32;
        let i = (x as usize).min(ENTRIES - 2);
        let f = x - i as f32;
        self.g1[i] + f * (self.g1[i + 1] - self.g1[i])
    }
}

/// `Λ = 1/G1 − 1` from a tabulated `G1`, `+∞` where `G1` is 0 (a tangent direction).
#[inline]
pub(crate) fn lambda_from_g1(g1: f32) -> f32 {
    if g1 == 0.0 {
        f32::INFINITY
    } else {
        1.0 / g1 - 1.0
    }
}

/// `∫ max(0, w·m) D(m) dωm` for `w` at `(cos_w, sin_w)`: `∫ D(θ) sin θ Φ(θ) dθ` with `Φ` the
/// closed-form `φ` integral, by Gauss-Legendre on geometrically growing intervals.
pub(crate) fn projected_area(
    d: &impl Fn(f32, f32) -> f32,
    cos_w: f32,
    sin_w: f32,
    width: f32,
) -> f32 {
    let kink = FRAC_PI_2 - atan2(sin_w, cos_w);
    let mut lo = 0.0_f32;
    let mut hi = (width.min(1.0) / 16.0).max(1e-6);
    let mut total = 0.0_f32;
    while lo < FRAC_PI_2 {
        let top = hi.min(FRAC_PI_2);
        // Split the interval at the kink of Φ. Beyond it Φ departs from 2πA like
        // (θ − kink)^(3/2); θ = kink + (top − kink) s² makes that smooth in s.
        if kink > lo && kink < top {
            total += gauss_legendre(lo, kink, |t| integrand(d, t, cos_w, sin_w));
            let span = top - kink;
            total += gauss_legendre(0.0, 1.0, |s| {
                2.0 * s * span * integrand(d, kink + span * s * s, cos_w, sin_w)
            });
        } else {
            total += gauss_legendre(lo, top, |t| integrand(d, t, cos_w, sin_w));
        }
        lo = top;
        hi = top * 2.0;
    }
    total
}

/// `D(θm) sin θm Φ(θw, θm)`.
#[inline]
fn integrand(d: &impl Fn(f32, f32) -> f32, theta: f32, cos_w: f32, sin_w: f32) -> f32 {
    let (s, c) = (sin(theta), cos(theta));
    d(c, s) * s * phi_integral(cos_w * c, sin_w * s)
}

/// `Φ = ∫₀^2π max(0, A + B cos φ) dφ` for `A ≥ 0`, `B ≥ 0`: `2πA` when `A ≥ B`, else
/// `2 (A φ0 + √(B² − A²))` with `φ0 = acos(−A/B)`.
#[inline]
pub(crate) fn phi_integral(a: f32, b: f32) -> f32 {
    if a >= b {
        TAU * a
    } else {
        let phi0 = acos((-a / b).clamp(-1.0, 1.0));
        2.0 * (a * phi0 + safe_sqrt(b * b - a * a))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::{FRAC_1_PI, PI};

    #[test]
    fn phi_integral_of_the_clamped_cosine() {
        assert!((phi_integral(0.5, 0.0) - TAU * 0.5).abs() < 1e-6);
        // A = 0: ∫ max(0, B cos φ) dφ = 2B.
        assert!((phi_integral(0.0, 0.7) - 1.4).abs() < 1e-6);
        // Continuous at A = B.
        assert!((phi_integral(0.4, 0.400_001) - TAU * 0.4).abs() < 1e-4);
    }

    #[test]
    fn uniform_distribution_has_the_closed_form_projected_area() {
        // D = 1/π: ∫ max(0, w·m) dω / π over the upper hemisphere = (1 + cos θ)/2
        // (the projected area of a hemisphere seen at θ, over π).
        for theta in [0.0_f32, 0.3, 1.0, 1.5] {
            let got = projected_area(&|_, _| FRAC_1_PI, theta.cos(), theta.sin(), 1.0);
            assert!(
                (got - 0.5 * (1.0 + theta.cos())).abs() < 1e-5,
                "θ = {theta}: {got}"
            );
        }
    }

    #[test]
    fn ggx_table_matches_the_closed_form() {
        for alpha in [0.01_f32, 0.2, 1.0, 3.0] {
            let a2 = alpha * alpha;
            let d = |c: f32, s: f32| {
                let t = s * s + a2 * c * c;
                a2 / (PI * t * t)
            };
            let table = SmithTable::new(d, alpha, alpha);
            for theta in [0.1_f32, 0.5, 1.0, 1.3, 1.5, 1.56] {
                let (s, c) = theta.sin_cos();
                let exact = 2.0 / (1.0 + (1.0 + a2 * (s / c) * (s / c)).sqrt());
                let got = table.g1(c, s);
                let direct = (c / projected_area(&d, c, s, alpha)).min(1.0);
                std::eprintln!("α={alpha} θ={theta}: table {got} direct {direct} exact {exact}");
                assert!(
                    (got - exact).abs() < 2e-4,
                    "α = {alpha}, θ = {theta}: {got} vs {exact}"
                );
            }
        }
    }
}
