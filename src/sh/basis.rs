//! The real spherical-harmonic basis: indexing, closed forms for bands `l ≤ 3`, and a
//! normalised recurrence for any band.
//!
//! The convention is the one the [module docs](super) state: orthonormal on the unit sphere,
//! no Condon–Shortley phase, `Y_{1,−1} ∝ y`, `Y_{1,0} ∝ z`, `Y_{1,1} ∝ x`, index `l(l+1) + m`.

use crate::math::sqrt;
use glam::Vec3;

/// `1 / (2√π)`: `Y_{0,0}`.
pub(crate) const K0: f32 = 0.282_094_79;
/// `√(3 / 4π)`: band 1.
pub(crate) const K1: f32 = 0.488_602_52;
/// `½ √(15/π)`: `Y_{2,−2}/(xy)`, `Y_{2,−1}/(yz)`, `Y_{2,1}/(xz)`.
pub(crate) const K2_XY: f32 = 1.092_548_4;
/// `¼ √(5/π)`: `Y_{2,0}/(3z² − 1)`.
pub(crate) const K2_ZZ: f32 = 0.315_391_57;
/// `¼ √(15/π)`: `Y_{2,2}/(x² − y²)`.
pub(crate) const K2_XX: f32 = 0.546_274_2;
/// `¼ √(35/2π)`: `Y_{3,−3}/(y(3x² − y²))`, `Y_{3,3}/(x(x² − 3y²))`.
const K3_3: f32 = 0.590_043_6;
/// `½ √(105/π)`: `Y_{3,−2}/(xyz)`.
const K3_XYZ: f32 = 2.890_611_4;
/// `¼ √(21/2π)`: `Y_{3,−1}/(y(5z² − 1))`, `Y_{3,1}/(x(5z² − 1))`.
const K3_1: f32 = 0.457_045_8;
/// `¼ √(7/π)`: `Y_{3,0}/(z(5z² − 3))`.
const K3_0: f32 = 0.373_176_33;
/// `¼ √(105/π)`: `Y_{3,2}/(z(x² − y²))`.
const K3_2: f32 = 1.445_305_7;

/// The number of bands (`l ≤ 3`) the closed forms cover: [`basis`] uses them for up to 16
/// coefficients.
pub const CLOSED_FORM_BANDS: usize = 4;

/// The flat index of `Y_lm`: `l(l + 1) + m`.
///
/// Precondition: `|m| ≤ l`. Otherwise the index belongs to another band, or, where
/// `l(l + 1) + m < 0`, wraps to a huge index (the function never panics; indexing with that
/// index does).
///
/// ```
/// use lobe::sh::index;
/// assert_eq!(index(0, 0), 0);
/// assert_eq!(index(1, -1), 1);
/// assert_eq!(index(2, 2), 8);
/// ```
#[inline]
#[must_use]
pub const fn index(l: usize, m: isize) -> usize {
    ((l * (l + 1)) as isize + m) as usize
}

/// The flat indices of band `l`: `l² .. (l + 1)²`.
#[inline]
#[must_use]
pub(crate) const fn band_range(l: usize) -> core::ops::Range<usize> {
    l * l..(l + 1) * (l + 1)
}

/// The band and order `(l, m)` of the flat index `i`, the inverse of [`index`].
#[inline]
#[must_use]
pub const fn band_of(i: usize) -> (usize, isize) {
    let l = i.isqrt();
    (l, i as isize - (l * (l + 1)) as isize)
}

/// The order (number of bands) of `n` coefficients, `√n`.
///
/// # Panics
///
/// When `n` is not a perfect square or is zero (an order-`L` expansion has `L²`
/// coefficients); at compile time where it is evaluated in a constant.
///
/// ```
/// assert_eq!(lobe::sh::order_of(9), 3);
/// ```
#[must_use]
pub const fn order_of(n: usize) -> usize {
    let l = n.isqrt();
    assert!(
        n > 0 && l * l == n,
        "an SH coefficient count must be a non-zero perfect square (order²)"
    );
    l
}

/// The first `N` basis functions at the unit direction `w`, in index order.
///
/// `N` must be a perfect square (a whole number of bands; checked at compile time). Up to 16
/// coefficients (bands `l ≤ 3`), the closed-form polynomials in `x, y, z` of
/// [`basis_closed_form`]; beyond, the recurrence of [`basis_recurrence`]. Precondition:
/// `w` has unit length (the polynomials use `x² + y² + z² = 1`).
///
/// ```
/// use lobe::sh::basis;
/// use lobe::Vec3;
/// let y: [f32; 9] = basis(Vec3::Z);
/// assert!((y[0] - 0.282_094_8).abs() < 1e-7); // 1 / (2√π)
/// assert!((y[2] - 0.488_602_5).abs() < 1e-7); // √(3/4π) z
/// ```
#[inline]
#[must_use]
pub fn basis<const N: usize>(w: Vec3) -> [f32; N] {
    const { order_of(N) };
    let mut out = [0.0; N];
    if N <= CLOSED_FORM_BANDS * CLOSED_FORM_BANDS {
        basis_closed_form(w, &mut out);
    } else {
        basis_recurrence(w, &mut out);
    }
    out
}

/// Writes the closed forms of the first `min(out.len(), 16)` basis functions at the unit
/// direction `w` (bands `l ≤ 3`): polynomials in `x, y, z`, no trigonometry and no square
/// root. Whole bands only: `out.len()` should be 1, 4, 9 or 16 (a partial band is left
/// unwritten).
///
/// The polynomials are the real harmonics `√2 K_l^m P_l^m(cos θ) cos(mφ)` (and `sin(|m|φ)` for
/// `m < 0`) written in Cartesian form with `K_l^m = √((2l+1)/4π · (l−m)!/(l+m)!)`, without the
/// Condon–Shortley phase; the constants are those tabulated by Sloan 2008 ("Stupid Spherical
/// Harmonics (SH) Tricks", appendix; he includes the `(−1)^m` sign) and, for `l ≤ 2`, by
/// Ramamoorthi & Hanrahan 2001 (eq. 3).
#[inline]
pub fn basis_closed_form(w: Vec3, out: &mut [f32]) {
    let n = out.len();
    let (x, y, z) = (w.x, w.y, w.z);
    if n >= 1 {
        out[0] = K0;
    }
    if n >= 4 {
        out[1] = K1 * y;
        out[2] = K1 * z;
        out[3] = K1 * x;
    }
    if n >= 9 {
        let (xx, yy, zz) = (x * x, y * y, z * z);
        out[4] = K2_XY * x * y;
        out[5] = K2_XY * y * z;
        out[6] = K2_ZZ * (3.0 * zz - 1.0);
        out[7] = K2_XY * x * z;
        out[8] = K2_XX * (xx - yy);
        if n >= 16 {
            let five_zz_1 = 5.0 * zz - 1.0;
            out[9] = K3_3 * y * (3.0 * xx - yy);
            out[10] = K3_XYZ * x * y * z;
            out[11] = K3_1 * y * five_zz_1;
            out[12] = K3_0 * z * (5.0 * zz - 3.0);
            out[13] = K3_1 * x * five_zz_1;
            out[14] = K3_2 * z * (xx - yy);
            out[15] = K3_3 * x * (xx - 3.0 * yy);
        }
    }
}

/// Writes the first `out.len()` basis functions at the unit direction `w` by the normalised
/// associated-Legendre recurrence, for any band. `out.len()` should be a perfect square
/// (whole bands); a partial last band is written in part.
///
/// The recurrence runs on the fully normalised functions `Q_l^m = K_l^m P_l^m / sin^m θ`, so
/// that no factorial is formed and nothing overflows, and the azimuthal factor
/// `sin^m θ (cos mφ, sin mφ)` is built as the real and imaginary parts of `(x + iy)^m`, so
/// that neither `θ` nor `φ` is ever formed:
///
/// * `Q_0^0 = 1/√(4π)`, `Q_m^m = √((2m+1)/(2m)) Q_{m−1}^{m−1}` (the sectoral step);
/// * `Q_{m+1}^m = √(2m+3) z Q_m^m`;
/// * `Q_l^m = a_l^m (z Q_{l−1}^m − b_l^m Q_{l−2}^m)` with `a_l^m = √((4l²−1)/(l²−m²))`,
///   `b_l^m = √(((l−1)²−m²)/(4(l−1)²−1))`.
///
/// This is the standard three-term recurrence for normalised Legendre functions, stable in
/// the direction of increasing `l` (Holmes & Featherstone 2002, *J. Geodesy* 76, eqs. 11–13;
/// Press et al., *Numerical Recipes* 3rd ed. §6.7), here without the Condon–Shortley phase.
/// Then `Y_{l,0} = Q_l^0`, `Y_{l,m} = √2 Q_l^m Re (x+iy)^m`, `Y_{l,−m} = √2 Q_l^m Im (x+iy)^m`.
pub fn basis_recurrence(w: Vec3, out: &mut [f32]) {
    let len = out.len();
    if len == 0 {
        return;
    }
    let order = (len - 1).isqrt() + 1; // bands touched, the last possibly partial
    let z = w.z;
    let mut put = |l: usize, m: usize, q: f32, re: f32, im: f32| {
        let centre = l * (l + 1);
        if m == 0 {
            if centre < len {
                out[centre] = q;
            }
        } else {
            let q = core::f32::consts::SQRT_2 * q;
            if centre + m < len {
                out[centre + m] = q * re;
            }
            if centre - m < len {
                out[centre - m] = q * im;
            }
        }
    };
    // (x + iy)^m as (re, im).
    let (mut re, mut im) = (1.0_f32, 0.0_f32);
    let mut q_mm = K0;
    for m in 0..order {
        if m > 0 {
            let mf = m as f32;
            q_mm *= sqrt((2.0 * mf + 1.0) / (2.0 * mf));
            (re, im) = (re * w.x - im * w.y, re * w.y + im * w.x);
        }
        put(m, m, q_mm, re, im);
        if m + 1 >= order {
            continue;
        }
        let mut q_prev = q_mm;
        let mut q = sqrt(2.0 * m as f32 + 3.0) * z * q_mm;
        put(m + 1, m, q, re, im);
        for l in m + 2..order {
            let (a, b) = recurrence_coefficients(l, m);
            let next = a * (z * q - b * q_prev);
            q_prev = q;
            q = next;
            put(l, m, q, re, im);
        }
    }
}

/// `(a_l^m, b_l^m)` of the three-term recurrence in [`basis_recurrence`].
#[inline]
fn recurrence_coefficients(l: usize, m: usize) -> (f32, f32) {
    let (lf, mf) = (l as f32, m as f32);
    let a = sqrt((4.0 * lf * lf - 1.0) / (lf * lf - mf * mf));
    let l1 = lf - 1.0;
    let b = sqrt((l1 * l1 - mf * mf) / (4.0 * l1 * l1 - 1.0));
    (a, b)
}

/// One basis function `Y_lm` at the unit direction `w`, by the recurrence of
/// [`basis_recurrence`] (`O(l)` work). Precondition: `|m| ≤ l` (otherwise 0).
///
/// ```
/// use lobe::sh::sh_basis;
/// use lobe::Vec3;
/// // Y_{1,1} = √(3/4π) x.
/// assert!((sh_basis(1, 1, Vec3::X) - 0.488_602_5).abs() < 1e-6);
/// ```
#[must_use]
pub fn sh_basis(l: usize, m: isize, w: Vec3) -> f32 {
    let am = m.unsigned_abs();
    if am > l {
        return 0.0;
    }
    let (mut re, mut im) = (1.0_f32, 0.0_f32);
    let mut q = K0;
    for k in 1..=am {
        let kf = k as f32;
        q *= sqrt((2.0 * kf + 1.0) / (2.0 * kf));
        (re, im) = (re * w.x - im * w.y, re * w.y + im * w.x);
    }
    if l > am {
        let mut q_prev = q;
        q *= sqrt(2.0 * am as f32 + 3.0) * w.z;
        for k in am + 2..=l {
            let (a, b) = recurrence_coefficients(k, am);
            let next = a * (w.z * q - b * q_prev);
            q_prev = q;
            q = next;
        }
    }
    match m {
        0 => q,
        m if m > 0 => core::f32::consts::SQRT_2 * q * re,
        _ => core::f32::consts::SQRT_2 * q * im,
    }
}

/// The Legendre polynomial `P_l(x)` by Bonnet's recurrence
/// `(k+1) P_{k+1} = (2k+1) x P_k − k P_{k−1}` (Abramowitz & Stegun 8.5.3).
///
/// ```
/// // P_2(x) = (3x² − 1)/2.
/// assert!((lobe::sh::legendre(2, 0.5) + 0.125).abs() < 1e-7);
/// ```
#[must_use]
pub fn legendre(l: usize, x: f32) -> f32 {
    let (mut p_prev, mut p) = (1.0_f32, x);
    if l == 0 {
        return 1.0;
    }
    for k in 1..l {
        let kf = k as f32;
        let next = ((2.0 * kf + 1.0) * x * p - kf * p_prev) / (kf + 1.0);
        p_prev = p;
        p = next;
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_round_trips() {
        for i in 0..200 {
            let (l, m) = band_of(i);
            assert!(m.unsigned_abs() <= l);
            assert_eq!(index(l, m), i);
        }
        assert_eq!(order_of(1), 1);
        assert_eq!(order_of(81), 9);
    }

    #[test]
    fn band_and_order_hold_at_the_top_of_usize() {
        // The largest square a usize holds, its neighbours, and usize::MAX itself: an integer
        // square root that squared its candidate would overflow here.
        let top = (1_usize << (usize::BITS / 2)) - 1;
        assert_eq!(order_of(top * top), top);
        assert_eq!(band_of(top * top - 1), (top - 1, top as isize - 1));
        assert_eq!(band_of(usize::MAX).0, top);
        assert!(std::panic::catch_unwind(|| order_of(usize::MAX)).is_err());
    }

    #[test]
    fn single_function_matches_the_array() {
        let w = Vec3::new(0.3, -0.5, 0.7).normalize();
        let mut all = [0.0; 81];
        basis_recurrence(w, &mut all);
        for (i, v) in all.iter().enumerate() {
            let (l, m) = band_of(i);
            assert!((sh_basis(l, m, w) - v).abs() <= 1e-6, "{l} {m}");
        }
    }
}
