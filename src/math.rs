//! `f32` math shims over `std` or `libm`, so the crate builds without the standard library.
//!
//! With the `std` feature (the default) each function calls the standard library's
//! method; without it, the `libm` crate's. The two paths agree to within a few units in the
//! last place, not bit for bit. So that the test suite measures what a `no_std` build
//! computes, the configuration flag `lobe_force_libm` takes the `libm` path with `std` on
//! (`RUSTFLAGS="--cfg lobe_force_libm" cargo test --features libm`, as CI runs it): a flag
//! and not a feature, so that no dependency's feature can switch a renderer's float
//! functions. The error function, its complement and its inverse are implemented here, the
//! same on both paths, because neither `core` nor `std` offers them on stable Rust.

/// Declares a one-argument shim with a `std` path and a `libm` path.
macro_rules! shim {
    ($(#[$doc:meta])* $name:ident => $std:ident, $libm:ident) => {
        $(#[$doc])*
        #[inline(always)]
        #[must_use]
        pub fn $name(x: f32) -> f32 {
            #[cfg(all(feature = "std", not(lobe_force_libm)))]
            {
                x.$std()
            }
            #[cfg(any(not(feature = "std"), lobe_force_libm))]
            {
                libm::$libm(x)
            }
        }
    };
}

shim!(/// Absolute value.
    abs => abs, fabsf);
shim!(/// Square root; NaN for negative input (see [`safe_sqrt`]).
    sqrt => sqrt, sqrtf);

/// The smallest `x` whose `e^x` does not round to zero: glibc's `expf` and the `libm`
/// crate's (musl's) both return `+0` for every `x` below `-0x1.9fe368p6 = −103.97208`, and
/// compute `e^x` (a subnormal) at that value.
const EXP_UNDERFLOW: f32 = -103.972_08;

/// `e^x`: `+0` where it rounds to zero, the library's `expf` elsewhere; the same numbers
/// bit for bit as the library alone (`exp_matches_the_library` checks both sides of the
/// threshold). glibc reaches its zero through a call that raises the underflow flag and sets
/// `errno` (with the C library's `powf`'s, 8% of a Phong pass in a profile); a lobe's tails
/// (a narrow Beckmann `D`, a large Phong exponent) reach it often.
#[inline(always)]
#[must_use]
pub fn exp(x: f32) -> f32 {
    // Selects rather than a branch: the library never sees an argument below the threshold
    // (NaN passes through to it), and the answer there is +0.
    let below = x < EXP_UNDERFLOW;
    let y = if below { EXP_UNDERFLOW } else { x };
    #[cfg(all(feature = "std", not(lobe_force_libm)))]
    let e = y.exp();
    #[cfg(any(not(feature = "std"), lobe_force_libm))]
    let e = libm::expf(y);
    if below { 0.0 } else { e }
}
shim!(/// Natural logarithm.
    ln => ln, logf);
shim!(/// `e^x − 1`, accurate for small `x`.
    exp_m1 => exp_m1, expm1f);
shim!(/// `ln(1 + x)`, accurate for small `x`.
    ln_1p => ln_1p, log1pf);
shim!(/// Sine of an angle in radians.
    sin => sin, sinf);
shim!(/// Cosine of an angle in radians.
    cos => cos, cosf);
shim!(/// Tangent of an angle in radians.
    tan => tan, tanf);
shim!(/// Arc cosine in radians; NaN outside `[-1, 1]` (see [`safe_acos`]).
    acos => acos, acosf);
shim!(/// Arc sine in radians; NaN outside `[-1, 1]` (see [`safe_asin`]).
    asin => asin, asinf);
shim!(/// Arc tangent in radians.
    atan => atan, atanf);
shim!(/// Largest integer not above `x`.
    floor => floor, floorf);

/// `x` raised to the power `y`.
#[inline(always)]
#[must_use]
pub fn powf(x: f32, y: f32) -> f32 {
    #[cfg(all(feature = "std", not(lobe_force_libm)))]
    {
        x.powf(y)
    }
    #[cfg(any(not(feature = "std"), lobe_force_libm))]
    {
        libm::powf(x, y)
    }
}

mod power;
pub use power::Power;

/// Four-quadrant arc tangent of `y / x`, in `(-π, π]`.
#[inline(always)]
#[must_use]
pub fn atan2(y: f32, x: f32) -> f32 {
    #[cfg(all(feature = "std", not(lobe_force_libm)))]
    {
        y.atan2(x)
    }
    #[cfg(any(not(feature = "std"), lobe_force_libm))]
    {
        libm::atan2f(y, x)
    }
}

/// Square root in `f64`, for the few places where `f32` cancels (the rough dielectric's
/// generalised half vector).
#[inline(always)]
#[must_use]
pub fn sqrt_f64(x: f64) -> f64 {
    #[cfg(all(feature = "std", not(lobe_force_libm)))]
    {
        x.sqrt()
    }
    #[cfg(any(not(feature = "std"), lobe_force_libm))]
    {
        libm::sqrt(x)
    }
}

/// The magnitude of `x` with the sign bit of `sign`.
#[inline(always)]
#[must_use]
pub fn copysign(x: f32, sign: f32) -> f32 {
    f32::from_bits((x.to_bits() & 0x7fff_ffff) | (sign.to_bits() & 0x8000_0000))
}

/// Sine and cosine of the same angle, `(sin x, cos x)`.
#[inline(always)]
#[must_use]
pub fn sin_cos(x: f32) -> (f32, f32) {
    (sin(x), cos(x))
}

/// `(sin θ, cos θ)` for `θ ∈ [−π/4, π/4]`, by minimax polynomials of degree 7 and 8: the
/// coefficients of Moshier's Cephes library (`sinf.c`, `cosf.c`), within about one `f32` ulp
/// on that interval. Branch-free and without a library call: the kernel of
/// [`sin_cos_turns`] and of the concentric disk map.
#[inline(always)]
#[must_use]
pub fn sin_cos_octant(theta: f32) -> (f32, f32) {
    let x2 = theta * theta;
    let s = theta + theta * x2 * (-1.666_665_5e-1 + x2 * (8.332_161e-3 + x2 * -1.951_529_6e-4));
    let c =
        1.0 - 0.5 * x2 + x2 * x2 * (4.166_664_6e-2 + x2 * (-1.388_731_6e-3 + x2 * 2.443_315_7e-5));
    (s, c)
}

/// `(sin 2πt, cos 2πt)` for a fraction of a turn `t ∈ [−1000, 1000]` (the samplers pass
/// `t ∈ [0, 1]`), without a library call and without branches, so that it is cheap in the
/// shading loop and vectorises in a batch.
///
/// `t` is reduced to the nearest quarter turn `q/4` (exactly: rounding `4t` by adding
/// `1.5 · 2²³`, and `t − q/4` is a difference of nearby floats), the remainder
/// `θ = 2π (t − q/4) ∈ [−π/4, π/4]` goes through [`sin_cos_octant`], and the quadrant swaps
/// and negates the pair. Within a few `f32` ulps of the exact values, and exactly `(0, 1)`,
/// `(1, 0)`, … at the quarter turns.
#[inline(always)]
#[must_use]
pub fn sin_cos_turns(t: f32) -> (f32, f32) {
    // 1.5 · 2²³: in [2²³, 2²⁴) floats are the integers, so the sum rounds 4t to the nearest
    // one, whose low bits are those of the sum's bit pattern.
    const ROUND: f32 = 12_582_912.0;
    let y = 4.0 * t + ROUND;
    let q = y.to_bits();
    let (s, c) = sin_cos_octant(core::f32::consts::TAU * (t - (y - ROUND) * 0.25));
    // Quadrant q: (sin, cos) of θ + qπ/2 is (s, c), (c, −s), (−s, −c), (−c, s); chosen with
    // bit masks, since q is as random as t and a branch on it would be mispredicted.
    let swap = 0_u32.wrapping_sub(q & 1);
    let sign_s = (q & 2) << 30;
    let sign_c = (q.wrapping_add(1) & 2) << 30;
    let (sb, cb) = (s.to_bits(), c.to_bits());
    (
        f32::from_bits(((sb & !swap) | (cb & swap)) ^ sign_s),
        f32::from_bits(((cb & !swap) | (sb & swap)) ^ sign_c),
    )
}

/// `x` raised to the fifth power, by three multiplications.
#[inline(always)]
#[must_use]
pub fn pow5(x: f32) -> f32 {
    let x2 = x * x;
    x2 * x2 * x
}

/// `cos^p θ` for `p ≥ 0`, given `cos θ ≥ 0` and `sin² θ`. Near the axis, where `cos θ` rounds
/// to 1 and a large `p` magnifies that, it is `exp(p/2 · ln(1 − sin² θ))` from the
/// better-conditioned `sin² θ`; elsewhere `powf(cos θ, p)`. [`Power::cos_pow`] gives the same
/// bits and answers the powers that round to zero without the library, for one exponent
/// raised at many calls.
#[inline(always)]
#[must_use]
pub fn cos_pow(cos: f32, sin2: f32, p: f32) -> f32 {
    if sin2 < 0.5 {
        exp(0.5 * p * ln_1p(-sin2))
    } else {
        powf(cos.max(0.0), p)
    }
}

/// Square root clamped at zero: `sqrt(max(x, 0))`, never NaN for non-NaN input.
#[inline(always)]
#[must_use]
pub fn safe_sqrt(x: f32) -> f32 {
    sqrt(x.max(0.0))
}

/// Arc cosine with its argument clamped to `[-1, 1]`, never NaN for non-NaN input.
#[inline(always)]
#[must_use]
pub fn safe_acos(x: f32) -> f32 {
    acos(x.clamp(-1.0, 1.0))
}

/// Arc sine with its argument clamped to `[-1, 1]`, never NaN for non-NaN input.
#[inline(always)]
#[must_use]
pub fn safe_asin(x: f32) -> f32 {
    asin(x.clamp(-1.0, 1.0))
}

/// `c₀ + c₁x + … + c₁₀x¹⁰` in Estrin's scheme (pairs, then pairs of pairs): five dependent
/// multiply-adds where Horner's rule chains ten, for the fitted polynomials below (a shorter
/// one padded with zeros, which add nothing).
#[inline(always)]
fn estrin(c: [f32; 11], x: f32) -> f32 {
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = (c[0] + c[1] * x + x2 * (c[2] + c[3] * x))
        + x4 * (c[4] + c[5] * x + x2 * (c[6] + c[7] * x));
    low + x4 * x4 * (c[8] + c[9] * x + x2 * c[10])
}

/// The scaled complementary error function `erfcx(x) = e^(x²) erfc(x)`, to a relative error
/// below `(2 + x²) · 2e-7` (the tests measure it on a grid from −4 to 9).
///
/// For `x ≥ 0` it is `t · Q(2t − 1)` with `t = 1/(1 + x/2)`, where `Q` is a degree-10 fit of
/// `erfcx(x)/t` on `t ∈ [0, 1]` (weighted least squares in relative error on Chebyshev nodes,
/// refined towards equal ripple; fit error 1.1e-8, the rest is `f32` rounding); it tends to 0
/// as `1/(x√π)`. The variable follows Numerical Recipes' `erfcc` (Press et al., §6.2), whose
/// fit is of `ln(erfcx(x)/t)`: fitting `erfcx` itself leaves [`erfc`] one exponential,
/// `e^(−x²)`, which a caller that needs `e^(−x²)` anyway shares. For `x < 0` it is
/// `2e^(x²) − erfcx(−x)`, `+∞` below about −9.4.
#[inline]
#[must_use]
pub fn erfcx(x: f32) -> f32 {
    if x < 0.0 {
        2.0 * exp(x * x) - erfcx_nonnegative(-x)
    } else {
        erfcx_nonnegative(x)
    }
}

/// [`erfcx`] of `z ≥ 0`: the fit at `t = 1/(1 + z/2)`.
#[inline(always)]
fn erfcx_nonnegative(z: f32) -> f32 {
    erfcx_at(1.0 / (1.0 + 0.5 * z))
}

/// The coefficients of [`erfcx`]'s fit, lowest degree first.
const ERFCX_FIT: [f32; 11] = [
    0.510_791_36,
    0.343_580_3,
    0.139_735_71,
    0.018_221_898,
    -0.010_751_343,
    -0.003_244_405_1,
    0.001_528_014_7,
    4.320_930_7e-4,
    -2.977_117e-4,
    -3.729_379_4e-5,
    4.136_054e-5,
];

/// [`erfcx`] of `z ≥ 0` from its variable `t = 1/(1 + z/2)`, for a caller that has `t` at
/// hand.
#[inline(always)]
#[must_use]
pub(crate) fn erfcx_at(t: f32) -> f32 {
    t * estrin(ERFCX_FIT, 2.0 * t - 1.0)
}

/// The complementary error function `erfc(x) = 1 − erf(x)`, with a relative error below
/// `(2 + x²) · 2e-7` for `x ≤ 9`: its tail, where `erfc` is tiny, keeps its digits up to the
/// rounding of `e^(−x²)`'s argument, which no `f32` evaluation escapes. Beyond 9 the value
/// (`erfc(9) = 4.1e-37`) turns subnormal and loses relative precision, then is 0 (from
/// `x ≈ 10`); below `−4` it is 2 to `f32` precision.
///
/// [`erfcx`]`(|x|) · e^(−x²)`, and `2 −` that for negative `x`.
#[must_use]
pub fn erfc(x: f32) -> f32 {
    erfc_given_exp(x, exp(-x * x))
}

/// [`erfc`]`(x)` given `e = e^(−x²)`, for a caller that needs that exponential too.
#[inline(always)]
#[must_use]
pub(crate) fn erfc_given_exp(x: f32, e: f32) -> f32 {
    let r = erfcx_nonnegative(abs(x)) * e;
    if x >= 0.0 { r } else { 2.0 - r }
}

/// The error function `erf(x) = 2/√π ∫₀ˣ e^(−t²) dt`, accurate to a few ulps.
///
/// A Maclaurin series near zero (where `1 − erfc` would lose the relative precision) and
/// [`erfc`] elsewhere.
#[must_use]
pub fn erf(x: f32) -> f32 {
    if abs(x) < 0.5 {
        // erf x = 2/√π Σ (−1)ⁿ x^(2n+1) / (n! (2n+1)); the x¹³ term is below 3e-8 relative.
        let x2 = x * x;
        let s = 1.0
            + x2 * (-1.0 / 3.0
                + x2 * (1.0 / 10.0
                    + x2 * (-1.0 / 42.0 + x2 * (1.0 / 216.0 + x2 * (-1.0 / 1320.0)))));
        core::f32::consts::FRAC_2_SQRT_PI * x * s
    } else {
        1.0 - erfc(x)
    }
}

/// The inverse error function: the `y` with `erf(y) = x`, for `x` in `(-1, 1)`.
///
/// Returns `±∞` at `x = ±1` and NaN outside `[-1, 1]`. Giles (2010), "Approximating the
/// erfinv function", *GPU Computing Gems Jade*, single-precision branch-split fit, refined by
/// one Newton step (`erf′(y) = 2/√π e^(−y²)`) on [`erf`] for `|x| ≤ 1/2` and on [`erfc`] beyond,
/// where the residual `(1 − |x|) − erfc(|y|)` keeps its digits (`1 − |x|` is exact there, and
/// `erf(y) − x` would be a difference of two numbers next to 1). Relative error within 4e-7
/// (measured against SciPy's `erfinv` at `f32` inputs from 0.6 to `1 − 2⁻²⁴`).
#[must_use]
pub fn erf_inv(x: f32) -> f32 {
    let y = erf_inv_approx(x);
    if !y.is_finite() {
        return y;
    }
    // One Newton step; skipped in the far tail where erf is flat to f32 precision.
    let slope = core::f32::consts::FRAC_2_SQRT_PI * exp(-y * y);
    if !(slope > 1e-30) {
        return y;
    }
    if abs(x) <= 0.5 {
        y - (erf(y) - x) / slope
    } else {
        // erf(y) − x = (1 − x) − erfc(y) for y > 0; odd in (x, y).
        let (ax, ay) = (abs(x), abs(y));
        copysign(ay - ((1.0 - ax) - erfc(ay)) / slope, y)
    }
}

/// Giles' single-precision approximation of [`erf_inv`] without its Newton polish (a
/// relative error of a few 1e-7, up to 1.04e-6 for `|x|` within 1e-6 of 1): for a sampler
/// that refines the result itself, or that needs no more than the `f32` rounding of its input.
/// `±∞` at `±1`, NaN outside `[-1, 1]`.
#[inline]
#[must_use]
pub(crate) fn erf_inv_approx(x: f32) -> f32 {
    if !(abs(x) < 1.0) {
        return if abs(x) == 1.0 {
            copysign(f32::INFINITY, x)
        } else {
            f32::NAN
        };
    }
    let w = -ln((1.0 - x) * (1.0 + x));
    // Giles' coefficients, lowest degree first, padded with zeros.
    let p = if w < 5.0 {
        let c = [
            1.501_409_4,
            0.246_640_73,
            -4.177_681_6e-3,
            -1.253_725e-3,
            2.185_808_7e-4,
            -4.391_506_5e-6,
            -3.523_387_7e-6,
            3.432_739_4e-7,
            2.810_226_4e-8,
            0.0,
            0.0,
        ];
        estrin(c, w - 2.5)
    } else {
        let c = [
            2.832_976_8,
            1.001_674,
            9.438_870_5e-3,
            -7.622_461_3e-3,
            5.739_507_7e-3,
            -3.673_428_4e-3,
            1.349_343_2e-3,
            1.009_505_6e-4,
            -2.002_142_6e-4,
            0.0,
            0.0,
        ];
        estrin(c, sqrt(w) - 3.0)
    };
    p * x
}

/// Gauss-Legendre nodes (the positive half) and weights on `[−1, 1]`, 8 points
/// (Abramowitz & Stegun, table 25.4).
pub(crate) const GL8_NODES: [f32; 4] = [0.183_434_64, 0.525_532_4, 0.796_666_5, 0.960_289_85];
pub(crate) const GL8_WEIGHTS: [f32; 4] = [0.362_683_78, 0.313_706_65, 0.222_381_03, 0.101_228_54];

/// 8-point Gauss-Legendre quadrature of `f` over `[a, b]`: exact for polynomials of degree 15.
/// For the one-time tables models build at construction.
pub(crate) fn gauss_legendre(a: f32, b: f32, f: impl Fn(f32) -> f32) -> f32 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut sum = 0.0;
    for (x, w) in GL8_NODES.iter().zip(GL8_WEIGHTS) {
        sum += w * (f(mid - half * x) + f(mid + half * x));
    }
    sum * half
}

/// Stafford's variant 13 of the MurmurHash3 finaliser (as in SplitMix64): a bijection of
/// `u64` in which every input bit affects every output bit. The seeds of the layered models'
/// random walks and of `verify`'s estimates are hashed through it.
#[inline(always)]
#[must_use]
pub(crate) fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The library's `expf`, on the path the build takes.
    fn exp_of_the_library(x: f32) -> f32 {
        #[cfg(all(feature = "std", not(lobe_force_libm)))]
        {
            x.exp()
        }
        #[cfg(any(not(feature = "std"), lobe_force_libm))]
        {
            libm::expf(x)
        }
    }

    /// `exp` answers `+0` below the threshold and the library elsewhere: the same bits as the
    /// library alone for every `f32` within 2¹⁶ of the threshold's bit pattern, a stride of
    /// 61 bit patterns over every `f32` (NaNs included), the infinities, ±0 and NaN.
    #[test]
    fn exp_matches_the_library() {
        let threshold = EXP_UNDERFLOW.to_bits();
        assert_eq!(threshold, 0xc2cf_f1b4);
        let near = (threshold - (1 << 16))..(threshold + (1 << 16));
        let stride = (0..=u32::MAX / 61).map(|k| k * 61);
        let ends = [f32::NEG_INFINITY, f32::INFINITY, f32::NAN, -0.0, 0.0].map(f32::to_bits);
        let mut below = 0_u32;
        for bits in near.chain(stride).chain(ends) {
            let x = f32::from_bits(bits);
            let (ours, theirs) = (exp(x), exp_of_the_library(x));
            // Bits, NaN payloads included: a NaN fails the threshold's comparison and reaches
            // the library, which answers it.
            assert_eq!(
                ours.to_bits(),
                theirs.to_bits(),
                "exp({x:e}) = {ours:e}, the library's {theirs:e}"
            );
            below += u32::from(x < EXP_UNDERFLOW);
        }
        // The answer below the threshold was reached, and the library's subnormals above it.
        assert!(below > 15_000_000, "{below}");
        assert!(exp(EXP_UNDERFLOW) > 0.0);
    }

    #[test]
    fn sin_cos_turns_matches_the_library_in_f64() {
        let mut worst = 0.0_f64;
        for k in 0..=200_000 {
            let t = k as f32 / 100_000.0 - 0.5; // [−0.5, 1.5]
            let (s, c) = sin_cos_turns(t);
            let a = std::f64::consts::TAU * f64::from(t);
            worst = worst.max((f64::from(s) - a.sin()).abs());
            worst = worst.max((f64::from(c) - a.cos()).abs());
        }
        // A few f32 ulps of values of size 1.
        assert!(worst < 3e-7, "largest error {worst:e}");
        // Exact at the quarter turns, and far from the origin.
        assert_eq!(sin_cos_turns(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_turns(0.25), (1.0, -0.0));
        assert_eq!(sin_cos_turns(0.5), (-0.0, -1.0));
        assert_eq!(sin_cos_turns(1.0), (0.0, 1.0));
        let (s, c) = sin_cos_turns(-999.875);
        assert!((s - core::f32::consts::FRAC_1_SQRT_2).abs() < 1e-4 && (c - s).abs() < 1e-4);
    }

    // Tabulated values (Abramowitz & Stegun, table 7.1, and 30-digit evaluations).
    const ERF_TABLE: [(f32, f64); 7] = [
        (0.0, 0.0),
        (0.1, 0.112_462_916_018_284_9),
        (0.5, 0.520_499_877_813_046_5),
        (1.0, 0.842_700_792_949_714_9),
        (1.5, 0.966_105_146_475_310_7),
        (2.0, 0.995_322_265_018_952_7),
        (3.0, 0.999_977_909_503_001_4),
    ];

    #[test]
    fn erf_matches_table() {
        for (x, want) in ERF_TABLE {
            let got = f64::from(erf(x));
            assert!(
                (got - want).abs() <= 2e-7 * want.abs().max(1e-30),
                "erf({x}) = {got}, want {want}"
            );
            let got_neg = f64::from(erf(-x));
            assert!((got_neg + want).abs() <= 2e-7 * want.abs().max(1e-30));
        }
    }

    #[allow(dead_code)]
    mod reference {
        include!(concat!(env!("CARGO_MANIFEST_DIR"), "/build/slopes.rs"));
    }

    /// The largest relative error of `f` against the `f64` reference `want`, divided by
    /// `2 + x²` (the form of the documented bounds), over a grid of step 1/2000 from −4 to 9,
    /// and where it is; printed.
    fn worst_scaled_error(name: &str, f: impl Fn(f32) -> f32, want: impl Fn(f64) -> f64) -> f64 {
        let mut worst = (0.0_f64, 0.0_f32);
        for i in -8000..=18000 {
            let x = i as f32 / 2000.0;
            let (got, want) = (f64::from(f(x)), want(f64::from(x)));
            let rel = ((got - want) / want).abs() / (2.0 + f64::from(x) * f64::from(x));
            if rel > worst.0 {
                worst = (rel, x);
            }
        }
        std::eprintln!(
            "largest {name} error / (2 + x²): {:e} at x = {}",
            worst.0,
            worst.1
        );
        worst.0
    }

    /// `erfcx` within its documented `(2 + x²) · 2e-7` of `e^(x²) erfc(x)` against the `f64`
    /// reference the build script uses (series and continued fraction to 1e-14). Measured:
    /// 1.58e-7 at x = −0.0315. Its limits: `+∞` far below zero, `0` at `+∞`, NaN for NaN.
    #[test]
    fn erfcx_meets_its_documented_bound() {
        let want = |x: f64| reference::erfc64(x) * (x * x).exp();
        assert!(worst_scaled_error("erfcx", erfcx, want) < 2e-7);
        assert_eq!(erfcx(-10.0), f32::INFINITY);
        assert_eq!(erfcx(f32::INFINITY), 0.0);
        assert!(erfcx(f32::NAN).is_nan());
    }

    /// `erfc` within its documented `(2 + x²) · 2e-7`, likewise. Measured: 1.45e-7 at
    /// x = 0.301, a few ulps of `erfc ≈ 1` (the previous fit, Numerical Recipes' `erfcc`:
    /// 1.65e-7 in Estrin's evaluation, 1.82e-7 in Horner's).
    #[test]
    fn erfc_meets_its_documented_bound() {
        assert!(worst_scaled_error("erfc", erfc, reference::erfc64) < 2e-7);
    }

    #[test]
    fn erfc_keeps_relative_precision_in_the_tail() {
        // erfc(3) = 2.209049699858544e-5, erfc(5) = 1.537459794428035e-12.
        for (x, want) in [
            (3.0_f32, 2.209_049_699_858_544e-5_f64),
            (5.0, 1.537_459_794_428_035e-12),
        ] {
            let got = f64::from(erfc(x));
            // The documented bound: the rounding of e^(−x²)'s argument grows with x².
            let bound = (2.0 + f64::from(x * x)) * 2e-7;
            assert!(
                ((got - want) / want).abs() < bound,
                "erfc({x}) = {got}, want {want}"
            );
        }
        assert!((erfc(-3.0) - (2.0 - 2.209_049_7e-5)).abs() < 1e-6);
        // Outside the measured range: 2 below −4 (erfc(−4) = 2 − 1.5e-8), and a tail that
        // only shrinks, down to 0, beyond 9.
        for x in [-4.0_f32, -6.0, -30.0, -1e30, f32::NEG_INFINITY] {
            assert_eq!(erfc(x), 2.0, "erfc({x})");
        }
        let mut last = erfc(9.0);
        for i in 1..=200 {
            let e = erfc(9.0 + i as f32 * 0.01);
            assert!(
                (0.0..=last).contains(&e),
                "erfc({}) = {e}",
                9.0 + i as f32 * 0.01
            );
            last = e;
        }
        assert_eq!(erfc(11.0), 0.0);
        assert_eq!(erfc(f32::INFINITY), 0.0);
    }

    #[test]
    fn erf_inv_inverts_erf() {
        let mut x = -0.999_9_f32;
        while x < 1.0 {
            let y = erf_inv(x);
            assert!(y.is_finite());
            assert!(
                (erf(y) - x).abs() <= 4.0 * f32::EPSILON,
                "erf(erf_inv({x})) = {}",
                erf(y)
            );
            x += 0.000_7;
        }
        assert_eq!(erf_inv(1.0), f32::INFINITY);
        assert_eq!(erf_inv(-1.0), f32::NEG_INFINITY);
        // SciPy's erfinv (f64) at the f32 inputs, on both sides: the tails keep their digits.
        for (x, want) in [
            (0.6f32, 0.595_116_111_558_982f64),
            (0.9, 1.163_087_071_945_772_2),
            (0.99, 1.821_386_600_900_278),
            (0.999_85, 2.680_661_778_617_085_7),
            (0.999_97, 2.951_187_632_524_838),
            (0.999_999, 3.457_074_726_035_950_5),
            (0.999_999_9, 3.743_921_162_776_8),
            (1.0 - f32::EPSILON / 2.0, 3.832_506_856_900_710_4),
        ] {
            for s in [1.0f32, -1.0] {
                let got = f64::from(erf_inv(s * x));
                let err = (got - f64::from(s) * want).abs() / want;
                assert!(
                    err <= 4e-7,
                    "erf_inv({}) = {got}, SciPy {want}: {err:.2e}",
                    s * x
                );
            }
        }
        assert!(erf_inv(1.5).is_nan());
        assert_eq!(erf_inv(0.0), 0.0);
    }

    #[test]
    fn safe_functions_never_nan() {
        assert_eq!(safe_sqrt(-1e-9), 0.0);
        assert_eq!(safe_acos(1.000_001), 0.0);
        assert!((safe_asin(-1.5) + core::f32::consts::FRAC_PI_2).abs() < 1e-7);
        assert_eq!(copysign(2.0, -0.0), -2.0);
        assert_eq!(pow5(2.0), 32.0);
    }
}
