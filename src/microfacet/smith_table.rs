//! Exact Smith masking for an isotropic distribution without a closed-form `Λ`, tabulated.

use crate::math::{acos, atan2, cos, exp_m1, gauss_legendre, ln, ln_1p, safe_sqrt, sin, sqrt};
use core::f32::consts::{FRAC_PI_4, LN_2, TAU};

/// Nodes of the table.
const ENTRIES: usize = 128;

/// Smith's `G1` of an isotropic distribution, computed at construction from the
/// projected-area identity `G1(w) ∫ max(0, w·m) D(m) dωm = cos θw` (Heitz 2014, eq. 14), which
/// determines the Smith masking function uniquely.
///
/// The integral is reduced to one dimension by integrating `φm` in closed form, then
/// evaluated by 8-point Gauss-Legendre quadrature (see [`projected_area`]). The table holds
/// `G1` at 128 values of `p = v / (v + s)`, `v = asinh(cot θ / lo)`, `s = asinh(hi / lo)`,
/// uniformly spaced in `p ∈ [0, 1]`, where `lo` and `hi` are the slopes `tan θm` below which 10%
/// and 90% of `D cos θ` lie. `p` is linear in `cot θ` near grazing (where `G1` is), then
/// logarithmic across the lobe's slopes however many decades they span (GTR with `γ = 1` and
/// `α = 1e-4` spans about three and a quarter), then tends to 1 like `s / ln cot θ`, where `G1` is
/// 1 to within `(hi / cot θ)²`. Lookups interpolate by a Catmull-Rom cubic, with the values one
/// node beyond each end extrapolated quadratically.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SmithTable {
    /// `lo`, the slope that `cot θ` is measured in.
    lo: f32,
    /// `s = asinh(hi / lo)`.
    spread: f32,
    /// `G1` at the nodes, after one extrapolated value and before another.
    g1: [f32; ENTRIES + 2],
}

impl SmithTable {
    /// Tabulates the `G1` of the isotropic distribution `d(cos θm, sin θm)` (both given, so
    /// that `d` can avoid `1 − cos²` near the normal) whose lobe has median slope `beta` (the
    /// `tan θm` below which half of `D cos θ` lies) and spreads its slopes like Beckmann's,
    /// whose 10% and 90% slopes are 0.39 and 1.83 times the median; `width` as in
    /// [`SmithTable::with_slopes`].
    pub(crate) fn new(d: impl Fn(f32, f32) -> f32, beta: f32, width: f32) -> Self {
        Self::with_slopes(d, 0.39 * beta, 1.83 * beta, width)
    }

    /// Tabulates the `G1` of the isotropic distribution `d(cos θm, sin θm)` whose slopes
    /// `tan θm` lie below `lo` for 10% and below `hi` for 90% of `D cos θ`, and whose width
    /// scale is `width` (`α`: `D` changes over `θm ≈ α` near the normal and, for `α > 1`,
    /// over `cos θm ≈ 1/α` near grazing).
    pub(crate) fn with_slopes(d: impl Fn(f32, f32) -> f32, lo: f32, hi: f32, width: f32) -> Self {
        let lo = lo.clamp(1e-6, 1e6);
        let spread = asinh(hi / lo).max(1.0);
        let mut g1 = [0.0; ENTRIES + 2];
        for i in 0..ENTRIES {
            let p = i as f32 / (ENTRIES - 1) as f32;
            g1[i + 1] = if i == 0 {
                0.0
            } else if i == ENTRIES - 1 {
                1.0
            } else {
                // cot θw = lo sinh(v), v = s p / (1 − p); tan θw is 0 where sinh overflows.
                let v = spread * p / (1.0 - p);
                let tan_w = 1.0 / (lo * 0.5 * (exp_m1(v) - exp_m1(-v)));
                let cos_w = 1.0 / sqrt(1.0 + tan_w * tan_w);
                let sin_w = tan_w * cos_w;
                (cos_w / projected_area(&d, cos_w, sin_w, width)).min(1.0)
            };
        }
        // Quadratic extrapolation, which the linear behaviour of G1 in p at grazing obeys.
        g1[0] = 3.0 * (g1[1] - g1[2]) + g1[3];
        g1[ENTRIES + 1] = 3.0 * (g1[ENTRIES] - g1[ENTRIES - 1]) + g1[ENTRIES - 2];
        Self { lo, spread, g1 }
    }

    /// `G1` of a direction with `cos θ = cos_theta` and `sin θ = sin_theta ≥ 0`.
    #[inline]
    pub(crate) fn g1(&self, cos_theta: f32, sin_theta: f32) -> f32 {
        let v = asinh(cos_theta.abs() / (self.lo * sin_theta));
        // v = ∞ at the normal, where p = 1; NaN (a zero vector) counts as grazing (`max`).
        let p = if v == f32::INFINITY {
            1.0
        } else {
            v / (v + self.spread)
        };
        catmull_rom(&self.g1, p.max(0.0) * (ENTRIES - 1) as f32).clamp(0.0, 1.0)
    }
}

/// The Catmull-Rom cubic through equally spaced nodes, at `x ≥ 0` node spacings past the first
/// node; `g` holds the nodes between one extrapolated value before the first and one after
/// the last (so `N − 2` nodes), and `x` beyond the last node extrapolates the last interval's
/// cubic.
#[inline(always)]
pub(crate) fn catmull_rom<const N: usize>(g: &[f32; N], x: f32) -> f32 {
    let i = (x as usize).min(N - 4);
    let f = x - i as f32;
    let [a, b, c, e] = [g[i], g[i + 1], g[i + 2], g[i + 3]];
    // Through the nodes i − 1 .. i + 2 (padded indices i .. i + 3).
    b + 0.5 * f * (c - a + f * (2.0 * a - 5.0 * b + 4.0 * c - e + f * (3.0 * (b - c) + e - a)))
}

/// `asinh x` for `x ≥ 0` (`+∞` at `+∞`), accurate near 0.
///
/// `ln(x + √(1 + x²))` from `x = ½`, where the logarithm's argument is at least 1.6 and nothing
/// cancels; below, `ln_1p` of the same argument less 1, written without the cancellation. (The
/// `ln_1p` form holds everywhere, but glibc's `log1pf` costs about four times its `logf`,
/// 12.9 against 3.0 ns a call in a throughput loop on the project's machine, and a table
/// coordinate needs no more than a few units in the last place.)
#[inline]
fn asinh(x: f32) -> f32 {
    if x > 1e9 {
        ln(x) + LN_2
    } else if x >= 0.5 {
        ln(x + sqrt(1.0 + x * x))
    } else {
        ln_1p(x + x * x / (1.0 + sqrt(1.0 + x * x)))
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
/// closed-form `φ` integral, by Gauss-Legendre on intervals that grow geometrically away from
/// both ends of `[0, π/2]`: in `θm` from the normal, starting at `width / 16` (at most 1/16),
/// and in `ψ = π/2 − θm` from grazing, starting at `1 / (16 width)` (at most 1/16), so that
/// a lobe at either end (`α > 1` puts `D`'s mass near grazing) is resolved; the two meet at
/// `π/4`. The integrand is written in `ψ`, with `sin θm = cos ψ` and `cos θm = sin ψ`, on the
/// grazing half. The interval holding the kink of `Φ` at `θm = π/2 − θw` (`ψ = θw`) is split
/// there.
pub(crate) fn projected_area(
    d: &impl Fn(f32, f32) -> f32,
    cos_w: f32,
    sin_w: f32,
    width: f32,
) -> f32 {
    let near_normal = (width.min(1.0) / 16.0).max(1e-6);
    let near_grazing = (1.0 / width).min(1.0) / 16.0;
    half(d, cos_w, sin_w, near_normal, atan2(cos_w, sin_w), false)
        + half(d, cos_w, sin_w, near_grazing, atan2(sin_w, cos_w), true)
}

/// The part of [`projected_area`] over `x ∈ [0, π/4]`, with `x = θm` or, `from_grazing`,
/// `x = π/2 − θm`, on intervals `[0, h], [h, 2h], [2h, 4h], …`; `kink` is `Φ`'s kink in `x`.
fn half(
    d: &impl Fn(f32, f32) -> f32,
    cos_w: f32,
    sin_w: f32,
    first: f32,
    kink: f32,
    from_grazing: bool,
) -> f32 {
    let f = |x: f32| {
        let (s, c) = (sin(x), cos(x));
        let (sin_m, cos_m) = if from_grazing { (c, s) } else { (s, c) };
        d(cos_m, sin_m) * sin_m * phi_integral(cos_w * cos_m, sin_w * sin_m)
    };
    let (mut lo, mut hi) = (0.0_f32, first);
    let mut total = 0.0_f32;
    while lo < FRAC_PI_4 {
        let top = hi.min(FRAC_PI_4);
        if kink > lo && kink < top {
            // On one side of the kink Φ departs from 2πA like |x − kink|^(3/2);
            // x = kink ∓ span s² makes both sides smooth in s.
            let (left, right) = (kink - lo, top - kink);
            total += gauss_legendre(0.0, 1.0, |s| 2.0 * s * left * f(kink - left * s * s));
            total += gauss_legendre(0.0, 1.0, |s| 2.0 * s * right * f(kink + right * s * s));
        } else {
            total += gauss_legendre(lo, top, f);
        }
        lo = top;
        hi = top * 2.0;
    }
    total
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

    /// `asinh` against `f64`'s over a log grid of 200,000 points from 1e-30 to 1e30, both
    /// branches and their seam at ½: within 4e-7 relative (measured 2.3e-7; the `ln_1p` form alone,
    /// 1.4e-7).
    #[test]
    fn asinh_is_accurate_on_both_branches() {
        let mut worst = (0.0_f64, 0.0_f32);
        for i in 0..=200_000 {
            let x = 10f32.powf(-30.0 + 60.0 * i as f32 / 200_000.0);
            for x in [x, 0.5 * (1.0 + (i as f32 - 100_000.0) * 1e-6)] {
                let want = f64::from(x).asinh();
                let err = ((f64::from(asinh(x)) - want) / want).abs();
                if err > worst.0 {
                    worst = (err, x);
                }
            }
        }
        std::println!(
            "asinh: worst relative error {:.3e} at x = {:e}",
            worst.0,
            worst.1
        );
        assert!(worst.0 < 4e-7, "{worst:?}");
    }

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
