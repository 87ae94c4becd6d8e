//! [`Power`]: one exponent raised to many bases, answering the bases whose power rounds to
//! zero without the library.

use super::{ln_1p, powf};
use crate::math::exp;

/// The exponent below whose power of two every power rounds to zero: `x^p < 2⁻¹⁵¹` for
/// `x < 2^(−151/p)`, half of `2⁻¹⁵⁰`, the largest value that rounds to `+0` (half the
/// smallest subnormal).
const ZERO_LOG2: f32 = -151.0;

/// An exponent `p ≥ 0` and the base `b` below which `x^p` rounds to `+0`, for raising many
/// bases to the same power (a Phong lobe's exponent, the Blinn-Phong distribution's).
///
/// [`of`](Self::of) answers `+0` for `0 < x < b` and calls the library's `powf` elsewhere:
/// the same bits as `powf` alone (a unit test compares them around `b` and over a stride of
/// every `f32`). glibc's `powf` reaches its zero through a call that raises the underflow
/// flag and sets `errno`, as its `expf` does ([`exp`]): a narrow lobe's tail reaches it at
/// most calls.
///
/// `b` is the library's `2^(−151/p)` rounded down by four units in the last place, and the
/// proof that `x < b` gives a zero power has two steps. First, `b < 2^q` exactly, where
/// `q = −151/p` rounded to `f32`: the library's power of two is within an ulp of `2^q` and
/// four ulps are more than one. Then `x^p < b^p < 2^(pq)`, and `pq` is `−151` to within
/// `2⁻²⁴` relative, so `x^p < 2⁻¹⁵¹ (1 + 6.3e-6)`: half of `2⁻¹⁵⁰`, the largest value that
/// rounds to `+0` (the smallest subnormal is `2⁻¹⁴⁹`). What carries the proof is that factor
/// of two: an error "within an ulp" says nothing down there, where one ulp is `2⁻¹⁴⁹`
/// absolute. `powf` rounds to `+0` any value it computes below `2⁻¹⁵⁰`, so it is enough that
/// its result before the final rounding is within a factor `1.99` of `x^p`; glibc's and the
/// `libm` crate's are within far less, and other platforms' `powf` are assumed to be too.
/// (With `−150` in place of `−151` there is no such margin, and the library answers the
/// smallest subnormal for some `x < b`.) Between `b` and the exact threshold `powf`
/// answers, as before.
///
/// ```
/// use lobe::math::{Power, powf};
/// let p = Power::new(512.0);
/// assert_eq!(p.of(0.5), 0.0); // 2⁻⁵¹²
/// assert_eq!(p.of(0.99).to_bits(), powf(0.99, 512.0).to_bits());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Power {
    p: f32,
    zero_below: f32,
}

impl Power {
    /// The exponent `p`, for `p ≥ 0` (for a negative or NaN `p`, [`of`](Self::of) is `powf`
    /// everywhere).
    #[must_use]
    pub fn new(p: f32) -> Self {
        let b = if p > 0.0 {
            powf(2.0, ZERO_LOG2 / p)
        } else {
            0.0
        };
        // Four ulps down, and no threshold where 2^(−151/p) is subnormal or zero (p < 1.2).
        let zero_below = if (f32::MIN_POSITIVE..f32::INFINITY).contains(&b) {
            f32::from_bits(b.to_bits() - 4)
        } else {
            0.0
        };
        Self { p, zero_below }
    }

    /// The exponent `p`.
    #[inline(always)]
    #[must_use]
    pub fn exponent(self) -> f32 {
        self.p
    }

    /// The base below which [`of`](Self::of) answers `+0` without the library (`0` when
    /// there is none).
    #[inline(always)]
    #[must_use]
    pub fn zero_below(self) -> f32 {
        self.zero_below
    }

    /// `x^p`, bit for bit [`powf`]`(x, p)`. Selects, not a branch: for `0 < x <`
    /// [`zero_below`](Self::zero_below) the library computes `1^p` and the answer is `+0`.
    #[inline(always)]
    #[must_use]
    pub fn of(self, x: f32) -> f32 {
        // `0 < x`: ±0 keep the library's answer (a −0 to an odd power is −0).
        let zero = 0.0 < x && x < self.zero_below;
        let e = powf(if zero { 1.0 } else { x }, self.p);
        if zero { 0.0 } else { e }
    }

    /// [`cos_pow`](super::cos_pow) to this power: `cos^p θ` given `cos θ ≥ 0` and `sin² θ`,
    /// the same bits.
    #[inline(always)]
    #[must_use]
    pub fn cos_pow(self, cos: f32, sin2: f32) -> f32 {
        if sin2 < 0.5 {
            exp(0.5 * self.p * ln_1p(-sin2))
        } else {
            self.of(cos.max(0.0))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The library's `powf`, which [`Power::of`] answers for.
    fn powf_of_the_library(x: f32, p: f32) -> f32 {
        #[cfg(all(feature = "std", not(lobe_force_libm)))]
        {
            x.powf(p)
        }
        #[cfg(any(not(feature = "std"), lobe_force_libm))]
        {
            libm::powf(x, p)
        }
    }

    /// Exponents from below the first with a threshold (`p ≈ 1.2`) to the largest the models
    /// take (Phong's 10⁶, the Blinn-Phong distribution's `2·10⁸` at `α = 10⁻⁴`), the
    /// degenerate ones and NaN.
    const EXPONENTS: [f32; 17] = [
        0.0,
        0.5,
        1.0,
        1.2,
        1.5,
        4.0,
        19.0,
        50.0,
        150.0,
        151.0,
        300.5,
        512.0,
        4_096.0,
        1e6,
        1e8,
        2e8,
        f32::NAN,
    ];

    #[test]
    fn power_matches_the_library() {
        let mut zeros = 0_u64;
        for p in EXPONENTS {
            let power = Power::new(p);
            let b = power.zero_below().to_bits();
            // Every pattern within 2¹⁴ of the threshold, a stride of 4,099 over all of them
            // (negative, NaN and infinite bases included), and the ends.
            let near = b.saturating_sub(1 << 14)..b.saturating_add(1 << 14);
            let stride = (0..=u32::MAX / 4_099).map(|k| k * 4_099);
            let ends =
                [0.0, -0.0, 1.0, f32::MIN_POSITIVE, f32::INFINITY, f32::NAN].map(f32::to_bits);
            for bits in near.chain(stride).chain(ends) {
                let x = f32::from_bits(bits);
                let (ours, theirs) = (power.of(x), powf_of_the_library(x, p));
                assert_eq!(
                    ours.to_bits(),
                    theirs.to_bits(),
                    "{x:e}^{p}: {ours:e}, {theirs:e}"
                );
                zeros += u64::from(0.0 < x && x < power.zero_below());
                // cos_pow's powf branch, and its exp branch unchanged.
                if (0.0..=1.0).contains(&x) {
                    let sin2 = (1.0 - x * x).max(0.0);
                    let want = super::super::cos_pow(x, sin2, p);
                    assert_eq!(power.cos_pow(x, sin2).to_bits(), want.to_bits());
                }
            }
        }
        // The zero answer was reached (not only the library's).
        assert!(zeros > 1_000_000, "{zeros}");
    }

    /// The threshold is close to the exact one: the library's power is zero at it and
    /// subnormal or larger a little above it, at the larger of a factor `2^(1.5/p)` and six
    /// ulps. The factor covers the two that `−151` leaves below `2⁻¹⁵⁰`; the ulps cover the
    /// four-ulp margin where one ulp moves `b^p` by more than that factor (from `p ≈ 10⁷`,
    /// where `2^(1.5/p)` rounds to within an ulp of one).
    #[test]
    fn threshold_is_tight() {
        for p in [1.5, 4.0, 50.0, 150.0, 512.0, 4_096.0, 1e6, 1e7, 1e8, 2e8] {
            let b = Power::new(p).zero_below();
            assert!(b > 0.0, "p = {p}");
            assert_eq!(powf_of_the_library(b, p), 0.0, "p = {p}");
            let above =
                (b * powf_of_the_library(2.0, 1.5 / p)).max(f32::from_bits(b.to_bits() + 6));
            assert!(powf_of_the_library(above, p) > 0.0, "p = {p}");
        }
        for p in [0.0, 1.0, -2.0, f32::NAN] {
            assert_eq!(Power::new(p).zero_below(), 0.0, "p = {p}");
        }
    }

    /// The first step of the proof in [`Power`]'s docs, checked in `f64` over 10⁵ exponents
    /// spaced evenly in `log p` from 1.2 to `2·10⁸`: the threshold lies strictly below
    /// `2^q`, `q = −151/p` rounded to `f32`, and so its power below `2⁻¹⁵¹ (1 + 6.2e-6)`.
    /// Without the four-ulp margin the first fails wherever the library's `2^q` rounds up.
    #[test]
    fn threshold_is_below_the_exact_power_of_two() {
        let n = 100_000;
        let (lo, hi) = (1.2_f64.ln(), 2e8_f64.ln());
        let mut checked = 0;
        for k in 0..=n {
            let p = (lo + (hi - lo) * f64::from(k) / f64::from(n)).exp() as f32;
            let b = Power::new(p).zero_below();
            if b == 0.0 {
                continue; // `2^(−151/p)` subnormal: no threshold
            }
            let q = f64::from(ZERO_LOG2 / p);
            assert!(f64::from(b) < q.exp2(), "p = {p}: {b:e}");
            let power = f64::from(b).powf(f64::from(p));
            assert!(
                power < 2f64.powi(-151) * (1.0 + 6.2e-6),
                "p = {p}: {power:e}"
            );
            checked += 1;
        }
        assert!(checked > 99_000, "{checked}");
    }
}
