//! Burley's generalised Trowbridge-Reitz (GTR) distribution, isotropic, `γ ∈ (0, 10]`.

use super::smith_table::{SmithTable, lambda_from_g1};
use super::{NormalDistribution, SampleDCos, Sampling, View};
use crate::math::{exp, exp_m1, ln, ln_1p, sin_cos_turns, sqrt};
use crate::param::{Alpha, ParamError};
use core::f32::consts::PI;
use glam::{Vec2, Vec3};

/// Burley's generalised Trowbridge-Reitz distribution (isotropic):
///
/// ```text
/// D(m) = c / (1 + (α² − 1) cos² θm)^γ                                   (m.z > 0)
/// c = (γ − 1)(α² − 1) / (π (1 − (α²)^(1−γ)))     γ ≠ 1
/// c = (α² − 1) / (π ln α²)                       γ = 1   (Disney's clearcoat lobe)
/// c = α² / π                                     γ = 2   (GGX)
/// ```
///
/// Burley 2012, "Physically-Based Shading at Disney", appendix B.2, eqs. 4–5; [the
/// handout](crate::handouts#seed-000) omits `c`
/// ([ERRATA #3](crate::errata#erratum-3--gtr-normalisation)).
/// `α ∈ [1e-4, 10]` ([`Alpha`]), `γ ∈ (0, 10]`; `α = 1` is the
/// uniform `D = 1/π` for every `γ`.
///
/// **Masking.** GTR has no closed-form Smith `Λ` for general `γ`. This type computes the
/// exact Smith `G1` from the projected-area identity `G1(w) ∫ max(0, w·m) D(m) dωm = cos θw`
/// (Heitz 2014, eq. 14): the integral, reduced to one dimension by integrating `φm` in closed
/// form, is evaluated by Gauss-Legendre quadrature at construction (on intervals refined
/// geometrically toward the normal and toward grazing, where `α > 1` puts the lobe) into a
/// 128-entry table over a map of `cot θ` that is logarithmic across the lobe's slopes,
/// interpolated by a cubic. The table is part of the value (no allocation, about 0.5 KiB);
/// construction costs up to about 24 000 evaluations of `D` (some 0.25 ms). Against `f64`
/// references (`tests/microfacet_gtr.rs`: GGX's closed form at `γ = 2`, an adaptive quadrature of
/// eq. 14 elsewhere) on a grid of `α ∈ [1e-4, 10]` and `γ ∈ [0.1, 10]`, the largest `|ΔG1|` is
/// 2.5e-5 (at `γ = 1`, `α = 1e-4`, whose slopes span about three and a quarter decades), held below
/// 3e-5; 1.3e-6 at `γ = 2`.
///
/// Sampling: `D cos θ` by inverting its CDF in closed form, with `sin² θm` and `cos² θm` each
/// from its own expression so that neither is a difference near its end: the sample's CDF is
/// within a few `f32` roundings of `u` for every `α` and `γ`. GTR has no exact visible-normal
/// sampler, so [`sample`](NormalDistribution::sample) is that sampler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gtr {
    alpha: f32,
    shape: Shape,
    /// Smith's `G1`, tabulated at construction.
    smith: SmithTable,
}

impl Gtr {
    /// A GTR distribution of width `alpha` and exponent `gamma ∈ (0, 10]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `gamma` when it is NaN or outside `(0, 10]`.
    pub fn new(alpha: Alpha, gamma: f32) -> Result<Self, ParamError> {
        if !(gamma > 0.0 && gamma <= 10.0) {
            return Err(ParamError::new("gamma", gamma, "(0, 10]"));
        }
        let alpha = alpha.get();
        let shape = Shape::new(alpha, gamma);
        // The slopes below which 10% and 90% of D cos θ lie (the sampler's u = 0.9 and 0.1).
        let slope = |u: f32| {
            let (sin2, cos2) = shape.sample_sin2_cos2(u);
            sqrt(sin2) / sqrt(cos2).max(1e-30)
        };
        let d = move |c: f32, s: f32| shape.d(c * c, s * s);
        Ok(Self {
            alpha,
            shape,
            smith: SmithTable::with_slopes(d, slope(0.9), slope(0.1), alpha),
        })
    }

    getters! {
        /// The width `α`.
        alpha: f32,
    }

    /// The exponent `γ`.
    #[inline]
    #[must_use]
    pub fn gamma(&self) -> f32 {
        self.shape.gamma
    }
}

/// The numbers that define the distribution, prepared so that neither `D` nor its sampler
/// overflows or cancels: `α` from 1e-4 with `γ` up to 10 puts `(α²)^(−γ)` far beyond `f32`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Shape {
    gamma: f32,
    /// `α²`.
    a2: f32,
    /// `α² − 1`, as `(α − 1)(α + 1)`.
    t: f32,
    /// `ln α²`.
    ln_a2: f32,
    /// `ln c`, the log of the normalisation.
    ln_c: f32,
    /// The sampler's inverted CDF read from the normal (`q = 1 − u`, `ℓ = −ln α²`) and from
    /// grazing (`q = u`, `ℓ = ln α²`): its exponential, which depends on `α` and `γ` only.
    ends: [End; 2],
}

/// One end of [`Shape::ln_one_plus`]: `x = (1 − γ) ℓ` and `expm1(x)`, or `e^(−x)` where
/// `x > 64` (see there).
#[derive(Clone, Copy, Debug, PartialEq)]
struct End {
    x: f32,
    e: f32,
}

impl End {
    fn new(gamma: f32, ell: f32) -> Self {
        let x = (1.0 - gamma) * ell;
        let e = if x > 64.0 { exp(-x) } else { exp_m1(x) };
        Self { x, e }
    }
}

impl Shape {
    fn new(alpha: f32, gamma: f32) -> Self {
        let t = (alpha - 1.0) * (alpha + 1.0);
        let ln_a2 = if t.abs() < 0.5 {
            ln_1p(t)
        } else {
            2.0 * ln(alpha)
        };
        Self {
            gamma,
            a2: alpha * alpha,
            t,
            ln_a2,
            ln_c: ln_normalisation(t, ln_a2, gamma),
            ends: [End::new(gamma, -ln_a2), End::new(gamma, ln_a2)],
        }
    }

    /// `D` from `cos² θm` and `sin² θm`: `c / (sin² θ + α² cos² θ)^γ`, [the
    /// handout's](crate::handouts#seed-000)
    /// `1 + (α² − 1) cos² θ` written so that it does not cancel near the normal.
    #[inline]
    fn d(&self, cos2: f32, sin2: f32) -> f32 {
        exp(self.ln_c - self.gamma * ln(sin2 + self.a2 * cos2))
    }

    /// `(sin² θm, cos² θm)` at the quantile `u` of `D cos θ` (`u = 0` at grazing, `1` at the
    /// normal); see [`Gtr::sample_d_cos`].
    ///
    /// `sin² θ` comes from its own closed form, not from `1 − cos² θ` (which rounds every
    /// `sin² θ` below about `6e-8` to a multiple of `2⁻²⁴`: for `α` below about `3e-3` that
    /// snaps the lobe onto a few rings around the normal). Where it exceeds ½, `cos² θ` comes
    /// from its closed form instead, so that the small one of the two is never a difference.
    fn sample_sin2_cos2(&self, u: f32) -> (f32, f32) {
        let Self { a2, t, .. } = *self;
        if t.abs() < 1e-7 {
            // α = 1: D is uniform and D cos θ is the cosine distribution, cos² θ uniform.
            return (1.0 - u, u);
        }
        // sin² θ = α² y with ln(1 + (1 − α²) y) from the quantile 1 − u measured from the
        // normal (see `ln_one_plus`); 1 + (1 − α²) y = (1 + t cos² θ)/α².
        let sin2 = a2 * (exp_m1(self.ln_one_plus(1.0 - u, 0)) / -t);
        if sin2 <= 0.5 {
            return (sin2.max(0.0), 1.0 - sin2);
        }
        // cos² θ = x with ln(1 + t x) from the quantile u measured from grazing.
        let cos2 = (exp_m1(self.ln_one_plus(u, 1)) / t).clamp(0.0, 1.0);
        (1.0 - cos2, cos2)
    }

    /// `ln(1 + k z)` for the `z` at which `(1 + k z)^(1−γ) = 1 + q (e^((1−γ) ℓ) − 1)`, that
    /// is `ln(1 + q expm1((1 − γ) ℓ)) / (1 − γ)`, and `q ℓ` at `γ = 1` (the limit). This is
    /// Burley 2012, appendix B.2, eqs. 6–7: the inverted CDF of `D cos θ`, which in `cos² θ`
    /// reads `(1 + t cos² θ)^(1−γ) = 1 + u ((α²)^(1−γ) − 1)` (`(α²)^u` at `γ = 1`), read from
    /// either end:
    ///
    /// * `q = u`, `ℓ = ln α²`: `ln(1 + t cos² θ)`;
    /// * `q = 1 − u`, `ℓ = −ln α²`: `ln(1 + (1 − α²) y)` with `y = sin² θ / α²`, since
    ///   `1 + t cos² θ = α² (1 + (1 − α²) y)` turns the same equation into
    ///   `(1 + (1 − α²) y)^(1−γ) = 1 + (1 − u) ((α²)^(γ−1) − 1)`.
    ///
    /// Every step keeps its relative precision (`expm1`, `ln_1p`, and `1 − γ`, which is exact
    /// in `f32` near 1), for every `γ ≠ 1` however close to 1. `expm1((1 − γ) ℓ)` is taken up
    /// to `(1 − γ) ℓ = 64`; beyond, which only `q = u` with `α < 1 < γ` reaches (up to 166 at
    /// `α = 1e-4`, `γ = 10`), `ln(1 + q (eˣ − 1)) = x + ln(q + (1 − q) e⁻ˣ)` cannot overflow.
    ///
    /// `end` picks `ℓ`: 0 for `−ln α²`, 1 for `ln α²` ([`ends`](Self::ends), which hold the
    /// exponential, a constant of the distribution).
    #[inline]
    fn ln_one_plus(&self, q: f32, end: usize) -> f32 {
        let one_minus_gamma = 1.0 - self.gamma;
        if one_minus_gamma == 0.0 {
            let ell = if end == 0 { -self.ln_a2 } else { self.ln_a2 };
            return q * ell;
        }
        let End { x, e } = self.ends[end];
        let ln_rhs = if x > 64.0 {
            // 1 + q (eˣ − 1) = eˣ (q + (1 − q) e⁻ˣ), which cannot overflow; for q ≥ 2⁻²⁴ the
            // log is above −17, so adding it to x > 64 loses under two bits.
            x + ln(q + (1.0 - q) * e)
        } else {
            ln_1p(q * e)
        };
        ln_rhs / one_minus_gamma
    }
}

/// `ln c` for the normalisation `c` of [ERRATA #3](crate::errata#erratum-3--gtr-normalisation), in log
/// form because `c` and `(α²)^(−γ)`
/// under- and overflow `f32` for small `α` and large `γ`; accurate as `α → 1` (where
/// `c → 1/π`) and across `γ = 1`.
fn ln_normalisation(t: f32, ln_a2: f32, gamma: f32) -> f32 {
    let ln_pi = ln(PI);
    if t.abs() < 1e-4 {
        // c = (1 + γ t/2 + O(t²)) / π.
        return ln_1p(0.5 * gamma * t) - ln_pi;
    }
    let one_minus_gamma = 1.0 - gamma;
    if one_minus_gamma == 0.0 {
        // c = (α² − 1) / (π ln α²); both factors share their sign.
        return ln(t / ln_a2) - ln_pi;
    }
    // c = (γ − 1)(α² − 1) / (π (1 − (α²)^(1−γ))), with 1 − (α²)^(1−γ) = −expm1(x).
    let x = one_minus_gamma * ln_a2;
    if one_minus_gamma.abs() < 1e-6 {
        // Next to γ = 1 the ratio (1 − γ)/expm1(x) ≈ 1/ln α² is formed directly: the logs of
        // its two small factors (down to ln 6e-8 ≈ −16.6) would each round by about 1e-6,
        // relative in c. (The limit 1/ln α², taken here before, is off by x/2: 9e-6 at most.)
        return ln(t * (one_minus_gamma / exp_m1(x))) - ln_pi;
    }
    let ln_abs_expm1 = if x > 15.0 {
        x + ln_1p(-exp(-x))
    } else {
        ln(exp_m1(x).abs())
    };
    ln(one_minus_gamma.abs()) + ln(t.abs()) - ln_pi - ln_abs_expm1
}

impl NormalDistribution for Gtr {
    #[inline]
    fn sampling(&self) -> Sampling {
        Sampling::DCos
    }

    #[inline]
    fn d(&self, m: Vec3) -> f32 {
        if !(m.z > 0.0) {
            return 0.0;
        }
        self.shape.d(m.z * m.z, m.x * m.x + m.y * m.y)
    }

    #[inline]
    fn lambda(&self, w: Vec3) -> f32 {
        lambda_from_g1(self.g1(w))
    }

    #[inline]
    fn g1(&self, w: Vec3) -> f32 {
        self.smith.g1(w.z, sqrt(w.x * w.x + w.y * w.y))
    }

    #[inline]
    fn sample(&self, _view: &View, u: Vec2) -> Vec3 {
        self.sample_d_cos(u)
    }
}

impl SampleDCos for Gtr {
    /// Inverts the CDF of `x = cos² θm`, whose density is `∝ (1 + t x)^(−γ)` with
    /// `t = α² − 1`: `(1 + t x)^(1−γ) = 1 + u ((α²)^(1−γ) − 1)` (`γ ≠ 1`), or
    /// `1 + t x = (α²)^u` (`γ = 1`); Burley 2012, appendix B.2, eqs. 6–7 in `cos²` form,
    /// solved for `sin² θm` from the normal's end where that is at most ½, and for `cos² θm`
    /// from grazing's elsewhere.
    fn sample_d_cos(&self, u: Vec2) -> Vec3 {
        let (sin2, cos2) = self.shape.sample_sin2_cos2(u.x);
        let sin = sqrt(sin2);
        let (s, c) = sin_cos_turns(u.y);
        Vec3::new(sin * c, sin * s, sqrt(cos2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f32::consts::FRAC_1_PI;

    fn c(alpha: f32, gamma: f32) -> f32 {
        Shape::new(alpha, gamma).ln_c.exp()
    }

    #[test]
    fn normalisation_matches_the_special_cases() {
        for a in [1e-4_f32, 0.05, 0.3, 0.9, 2.0] {
            // γ = 2 is GGX: c = α²/π.
            assert!(
                (c(a, 2.0) - a * a / PI).abs() < 2e-6 * a * a / PI,
                "α = {a}"
            );
            // γ = 1: c = (α² − 1)/(π ln α²).
            let want = (a * a - 1.0) / (PI * (a * a).ln());
            assert!((c(a, 1.0) - want).abs() < 2e-6 * want, "α = {a}");
        }
        // α → 1 tends to 1/π from both sides and for any γ.
        for g in [0.5_f32, 1.0, 3.0] {
            assert!((c(1.000_005, g) - FRAC_1_PI).abs() < 1e-5);
            assert!((c(0.9995, g) - FRAC_1_PI).abs() < 2e-3);
        }
        // No overflow at the corner of the domain: D at the normal is finite and large.
        let s = Shape::new(1e-4, 10.0);
        let d0 = s.d(1.0, 0.0);
        assert!(d0.is_finite() && d0 > 1e8, "{d0}");
    }

    /// Next to `γ = 1`, `c` against its `f64` form `(1 − γ)(α² − 1) / (π expm1((1 − γ) ln α²))`,
    /// which keeps full precision there, at the 32 `f32` values on each side of 1. Measured
    /// worst: 3.8e-7 relative within 1e-6 of 1, where the limit `(α² − 1)/(π ln α²)` (taken
    /// there before) is off by up to 9.1e-6 (at `α = 1e-4`); 1.5e-6 beyond, by the log form.
    #[test]
    fn normalisation_is_accurate_next_to_gamma_one() {
        let (mut near, mut beyond) = (0.0_f64, 0.0_f64);
        for a in [1e-4_f32, 0.05, 0.3, 0.9, 2.0, 10.0] {
            let (mut below, mut above) = (1.0_f32, 1.0_f32);
            for _ in 0..32 {
                below = f32::from_bits(below.to_bits() - 1);
                above = f32::from_bits(above.to_bits() + 1);
                for g in [below, above] {
                    let (a2, g64) = (f64::from(a) * f64::from(a), f64::from(g));
                    let x = (1.0 - g64) * a2.ln();
                    let want = (1.0 - g64) * (a2 - 1.0) / (core::f64::consts::PI * x.exp_m1());
                    let err = (f64::from(c(a, g)) - want).abs() / want;
                    let worst = if (1.0 - g).abs() < 1e-6 {
                        &mut near
                    } else {
                        &mut beyond
                    };
                    *worst = worst.max(err);
                }
            }
        }
        assert!(near < 1e-6, "within 1e-6 of γ = 1: {near:e}");
        assert!(beyond < 2.5e-6, "beyond: {beyond:e}");
    }

    #[test]
    fn refuses_bad_gamma() {
        let a = Alpha::new(0.5).unwrap();
        for g in [0.0_f32, -1.0, f32::NAN, 11.0, f32::INFINITY] {
            assert_eq!(Gtr::new(a, g).unwrap_err().param(), "gamma");
        }
    }
}
