//! Rotation of SH coefficients: closed forms for bands 1 and 2, and Ivanic & Ruedenberg's
//! recurrence for every band.
//!
//! **Convention.** Rotating an expansion `f` by the rotation `R` gives the coefficients of
//! `g(ω) = f(R⁻¹ ω)`: the function carried along by `R`, so that what `f` had at direction
//! `d`, `g` has at `R d`. Each band `l` transforms on its own, by a `(2l+1) × (2l+1)`
//! orthogonal matrix `M^l(R)`: `g_lm = Σ_n M^l_mn f_ln`. In the basis order `(y, z, x)` of
//! band 1, `M^1` is `R` itself with its rows and columns permuted; higher bands follow.

use super::basis::{K2_XX, K2_XY, K2_ZZ, index, order_of};
use super::coefficients::Sh;
use crate::math::sqrt;
use crate::spectrum::Spectrum;
use glam::{Mat3, Quat};

/// The entries of `r` in band 1's basis order: `out[m+1][n+1] = R_{σ(m) σ(n)}` with
/// `σ(−1) = y`, `σ(0) = z`, `σ(1) = x`.
#[inline]
fn band1_matrix(r: &Mat3) -> [[f32; 3]; 3] {
    // glam is column-major: R_ij = r.col(j)[i].
    const SIGMA: [usize; 3] = [1, 2, 0];
    core::array::from_fn(|m| core::array::from_fn(|n| r.col(SIGMA[n])[SIGMA[m]]))
}

/// Band `l ≥ 2`'s matrix from band `l − 1`'s, by the recurrence of Ivanic & Ruedenberg 1996
/// (*J. Phys. Chem.* 100, 6342, tables 1–2) with the corrections of their 1998 erratum
/// (*J. Phys. Chem. A* 102, 9099), for real harmonics without the Condon–Shortley phase:
///
/// ```text
/// M^l_mn = u_mn U_mn + v_mn V_mn + w_mn W_mn
/// u = √((l+m)(l−m) / d),   v = ½ √((1+δ_m0)(l+|m|−1)(l+|m|) / d) (1 − 2δ_m0),
/// w = −½ √((l−|m|−1)(l−|m|) / d) (1 − δ_m0),   d = (l+n)(l−n) if |n| < l, else 2l(2l−1)
/// U = P⁰_mn;  V = P¹_1n + P⁻¹_−1,n (m = 0),  P¹_m−1,n √(1+δ_m1) − P⁻¹_−m+1,n (1−δ_m1) (m > 0),
///     P¹_m+1,n (1−δ_m,−1) + P⁻¹_−m−1,n √(1+δ_m,−1) (m < 0);
/// W = P¹_m+1,n + P⁻¹_−m−1,n (m > 0),  P¹_m−1,n − P⁻¹_−m+1,n (m < 0);
/// Pⁱ_ab = R_i0 M^(l−1)_ab (|b| < l),  R_i1 M^(l−1)_a,l−1 − R_i,−1 M^(l−1)_a,−l+1 (b = l),
///         R_i1 M^(l−1)_a,−l+1 + R_i,−1 M^(l−1)_a,l−1 (b = −l)
/// ```
///
/// `r1` is band 1's matrix ([`band1_matrix`]), `prev` band `l − 1`'s and `out` band `l`'s,
/// both row-major (`out[(m+l)(2l+1) + n+l]`). Precondition `l ≥ 2` (band 1 is `r1` itself).
fn next_band(l: usize, r1: &[[f32; 3]; 3], prev: &[f32], out: &mut [f32]) {
    let li = l as isize;
    let (pd, d) = (2 * li - 1, 2 * li + 1);
    let prev_at = |a: isize, b: isize| prev[((a + li - 1) * pd + (b + li - 1)) as usize];
    let r = |i: isize, j: isize| r1[(i + 1) as usize][(j + 1) as usize];
    let p = |i: isize, a: isize, b: isize| -> f32 {
        if b == li {
            r(i, 1) * prev_at(a, li - 1) - r(i, -1) * prev_at(a, -li + 1)
        } else if b == -li {
            r(i, 1) * prev_at(a, -li + 1) + r(i, -1) * prev_at(a, li - 1)
        } else {
            r(i, 0) * prev_at(a, b)
        }
    };
    let edge_den = (2 * li * (2 * li - 1)) as f32;
    for m in -li..=li {
        let am = m.abs();
        let d0 = m == 0;
        // Numerators of u, v, w (Ivanic & Ruedenberg 1998, table 1 corrected).
        let u_num = sqrt(((li + m) * (li - m)) as f32);
        let v_num = 0.5
            * sqrt((if d0 { 2 } else { 1 } * (li + am - 1) * (li + am)) as f32)
            * if d0 { -1.0 } else { 1.0 };
        let w_num = if d0 {
            0.0
        } else {
            -0.5 * sqrt(((li - am - 1) * (li - am)) as f32)
        };
        for n in -li..=li {
            let den = if n.abs() == li {
                edge_den
            } else {
                ((li + n) * (li - n)) as f32
            };
            let inv = 1.0 / sqrt(den);
            let mut value = 0.0;
            if u_num != 0.0 {
                value += u_num * inv * p(0, m, n);
            }
            if v_num != 0.0 {
                let big_v = if m == 0 {
                    p(1, 1, n) + p(-1, -1, n)
                } else if m > 0 {
                    let a = p(1, m - 1, n)
                        * if m == 1 {
                            core::f32::consts::SQRT_2
                        } else {
                            1.0
                        };
                    if m == 1 { a } else { a - p(-1, -m + 1, n) }
                } else {
                    let b = p(-1, -m - 1, n)
                        * if m == -1 {
                            core::f32::consts::SQRT_2
                        } else {
                            1.0
                        };
                    if m == -1 { b } else { p(1, m + 1, n) + b }
                };
                value += v_num * inv * big_v;
            }
            if w_num != 0.0 {
                let big_w = if m > 0 {
                    p(1, m + 1, n) + p(-1, -m - 1, n)
                } else {
                    p(1, m - 1, n) - p(-1, -m + 1, n)
                };
                value += w_num * inv * big_w;
            }
            out[((m + li) * d + (n + li)) as usize] = value;
        }
    }
}

/// Band 2's matrix in closed form: band 2 is the space of traceless symmetric quadratic
/// forms `ωᵀ Q ω` on the sphere, and turning the function by `R` maps `Q` to `R Q Rᵀ`.
/// Column `n` of `M^2` is the image of the basis function `Y_{2,n}` ([`band2_rotate`] of a
/// unit coefficient vector). Row-major `out[(m+2)·5 + n+2]`.
fn band2_matrix(r: &Mat3) -> [f32; 25] {
    let mut out = [0.0; 25];
    for n in 0..5 {
        let mut e = [0.0_f32; 5];
        e[n] = 1.0;
        let col = band2_rotate(r, e);
        for m in 0..5 {
            out[m * 5 + n] = col[m];
        }
    }
    out
}

/// Band 1 turned by `r`: the coefficients `(c_{1,−1}, c_{1,0}, c_{1,1})` are the vector
/// `(x, y, z) = (c_{1,1}, c_{1,−1}, c_{1,0})` up to the common factor `√(3/4π)`, so
/// `f(R⁻¹ω) = √(3/4π) (R v)·ω`.
#[inline]
fn band1_rotate<S: Spectrum>(r: &Mat3, c: [S; 3]) -> [S; 3] {
    let v = [c[2], c[0], c[1]];
    let row = |i: usize| v[0] * r.col(0)[i] + v[1] * r.col(1)[i] + v[2] * r.col(2)[i];
    let (x, y, z) = (row(0), row(1), row(2));
    [y, z, x]
}

/// Band 2 turned by `r`, in closed form. With `a = K₂₀ c_{2,0}` and `b = K₂₂ c_{2,2}` (the
/// basis constants `¼√(5/π)` and `¼√(15/π)`), the band is `ωᵀ Q ω` on the unit sphere with
/// `Q_xx = b − a`, `Q_yy = −a − b`, `Q_zz = 2a` (from `3z² − 1 = 2z² − x² − y²`) and
/// `Q_xy = ½ K c_{2,−2}`, `Q_yz = ½ K c_{2,−1}`, `Q_xz = ½ K c_{2,1}` (`K = ½√(15/π)`);
/// then `Q′ = R Q Rᵀ` and back: `c′_{2,−2} = 2Q′_xy/K`, `c′_{2,−1} = 2Q′_yz/K`,
/// `c′_{2,0} = Q′_zz/(2K₂₀)`, `c′_{2,1} = 2Q′_xz/K`, `c′_{2,2} = (Q′_xx − Q′_yy)/(2K₂₂)`.
#[inline]
fn band2_rotate<S: Spectrum>(r: &Mat3, c: [S; 5]) -> [S; 5] {
    let a = c[2] * K2_ZZ;
    let b = c[4] * K2_XX;
    let h = 0.5 * K2_XY;
    let (qxy, qyz, qxz) = (c[0] * h, c[1] * h, c[3] * h);
    let q = [
        [b - a, qxy, qxz],
        [qxy, S::zero() - a - b, qyz],
        [qxz, qyz, a * 2.0],
    ];
    // T = Q Rᵀ: T_ij = Σ_k Q_ik R_jk; then Q′_ij = Σ_k R_ik T_kj.
    let rr = |i: usize, j: usize| r.col(j)[i];
    let t: [[S; 3]; 3] = core::array::from_fn(|i| {
        core::array::from_fn(|j| q[i][0] * rr(j, 0) + q[i][1] * rr(j, 1) + q[i][2] * rr(j, 2))
    });
    let qp = |i: usize, j: usize| t[0][j] * rr(i, 0) + t[1][j] * rr(i, 1) + t[2][j] * rr(i, 2);
    let inv_h = 1.0 / h;
    [
        qp(0, 1) * inv_h,
        qp(1, 2) * inv_h,
        qp(2, 2) * (0.5 / K2_ZZ),
        qp(0, 2) * inv_h,
        (qp(0, 0) - qp(1, 1)) * (0.5 / K2_XX),
    ]
}

/// Applies the row-major `(2l+1)²` matrix `m` to band `l` of `src`, into `dst`.
#[inline]
fn apply_band<const N: usize, S: Spectrum>(
    l: usize,
    m: &[f32],
    src: &Sh<N, S>,
    dst: &mut Sh<N, S>,
) {
    let d = 2 * l + 1;
    let base = index(l, -(l as isize));
    for row in 0..d {
        let mut sum = S::zero();
        for col in 0..d {
            sum += src.coeffs[base + col] * m[row * d + col];
        }
        dst.coeffs[base + row] = sum;
    }
}

/// The offset of band `l`'s block in the packed storage: `Σ_{k<l} (2k+1)² = l(2l−1)(2l+1)/3`.
#[inline]
const fn block_offset(l: usize) -> usize {
    l * (2 * l + 1) * (2 * l).saturating_sub(1) / 3
}

/// The rotation matrices of every band of an order-`√N` expansion, computed once and
/// applied to any number of expansions (e.g. every transfer vector of an object, or the
/// three channels of RGB lighting).
///
/// Band 1 is the rotation matrix itself, band 2 its closed form ([`ShRotation::new`]) or the
/// recurrence ([`ShRotation::ivanic_ruedenberg`]), bands `l ≥ 3` Ivanic & Ruedenberg's
/// recurrence: exact, for every band, to `f32` round-off. The blocks are packed in an
/// `N × N` array (they need `L(4L² − 1)/3` of its `L⁴` entries).
///
/// ```
/// use lobe::sh::{Sh, ShRotation};
/// use lobe::{Vec3, sh::Zonal};
/// use glam::Quat;
/// // Turning a lobe about +z toward +x by 90° about +y.
/// let lobe: Sh<16> = Zonal::<4>::clamped_cosine().rotated(Vec3::Z);
/// let rot = ShRotation::<16>::from_quat(Quat::from_rotation_y(core::f32::consts::FRAC_PI_2));
/// let turned = rot.apply(&lobe);
/// assert!((turned.eval(Vec3::X) - lobe.eval(Vec3::Z)).abs() < 1e-5);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ShRotation<const N: usize> {
    /// Band `l`'s row-major block at [`block_offset`]`(l)` of the flattened array.
    blocks: [[f32; N]; N],
}

impl<const N: usize> ShRotation<N> {
    /// The order (number of bands), `√N`.
    pub const ORDER: usize = order_of(N);

    /// The band matrices of the rotation `r` (orthogonal; a reflection works too, as for
    /// [`Sh::rotated`]), band 2 in closed form.
    #[must_use]
    pub fn new(r: Mat3) -> Self {
        Self::build(r, true)
    }

    /// The band matrices of the rotation `q` (a unit quaternion).
    #[must_use]
    pub fn from_quat(q: Quat) -> Self {
        Self::new(Mat3::from_quat(q))
    }

    /// The band matrices of `r` with band 2 too by Ivanic & Ruedenberg's recurrence: the
    /// reference the closed form is tested against, and the slower path.
    #[must_use]
    pub fn ivanic_ruedenberg(r: Mat3) -> Self {
        Self::build(r, false)
    }

    /// Builds every block; band 2 in closed form when `closed` is set.
    fn build(r: Mat3, closed: bool) -> Self {
        let order = Self::ORDER;
        let mut s = Self {
            blocks: [[0.0; N]; N],
        };
        let flat = s.blocks.as_flattened_mut();
        flat[0] = 1.0;
        if order < 2 {
            return s;
        }
        let r1 = band1_matrix(&r);
        for (m, row) in r1.iter().enumerate() {
            flat[1 + 3 * m..4 + 3 * m].copy_from_slice(row);
        }
        for l in 2..order {
            let (done, rest) = flat.split_at_mut(block_offset(l));
            let prev = &done[block_offset(l - 1)..];
            let out = &mut rest[..(2 * l + 1) * (2 * l + 1)];
            if l == 2 && closed {
                out.copy_from_slice(&band2_matrix(&r));
            } else {
                next_band(l, &r1, prev, out);
            }
        }
        s
    }

    /// Band `l`'s matrix, row-major: entry `(m, n)` at `(m + l)(2l + 1) + n + l`. Empty for a
    /// band beyond the order.
    #[must_use]
    pub fn block(&self, l: usize) -> &[f32] {
        if l >= Self::ORDER {
            return &[];
        }
        let d = 2 * l + 1;
        &self.blocks.as_flattened()[block_offset(l)..block_offset(l) + d * d]
    }

    /// The entry `M^l_mn`. Preconditions: `l` below the order, `|m|, |n| ≤ l`.
    ///
    /// # Panics
    /// If `l` is not below the order, or when `m` or `n` outside the band take the flat
    /// position `(m + l)(2l + 1) + n + l` out of the band's block; inside it they read
    /// another entry.
    #[must_use]
    pub fn entry(&self, l: usize, m: isize, n: isize) -> f32 {
        let li = l as isize;
        self.block(l)[((m + li) * (2 * li + 1) + n + li) as usize]
    }

    /// The coefficients of `f` turned by the rotation: those of `f(R⁻¹ ω)`.
    #[must_use]
    pub fn apply<S: Spectrum>(&self, f: &Sh<N, S>) -> Sh<N, S> {
        let mut out = Sh::<N, S>::zero();
        out.coeffs[0] = f.coeffs[0];
        for l in 1..Self::ORDER {
            apply_band(l, self.block(l), f, &mut out);
        }
        out
    }
}

impl<const N: usize, S: Spectrum> Sh<N, S> {
    /// The coefficients of this function turned by the rotation `r`: those of
    /// `g(ω) = f(R⁻¹ ω)`. Precondition: `r` orthogonal (`rᵀ r = I`). A reflection (det −1)
    /// works too: every formula is a polynomial of degree `l` in `r`'s entries, so band `l`
    /// picks up the parity `(−1)^l` as it should.
    ///
    /// Bands 1 and 2 in closed form (the rotation matrix on band 1's vector, a similarity
    /// transform of band 2's quadratic form), bands `l ≥ 3` by Ivanic & Ruedenberg's
    /// recurrence, one band at a time with `8N` floats of scratch on the stack. To turn many
    /// expansions by one rotation, build an [`ShRotation`] once.
    ///
    /// ```
    /// use lobe::sh::{Sh, Zonal};
    /// use lobe::Vec3;
    /// use glam::Mat3;
    /// let f: Sh<9> = Zonal::<3>::clamped_cosine().rotated(Vec3::Z);
    /// let r = Mat3::from_rotation_x(-core::f32::consts::FRAC_PI_2); // +z to +y
    /// assert!((f.rotated(r).eval(Vec3::Y) - f.eval(Vec3::Z)).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn rotated(&self, r: Mat3) -> Self {
        let order = Self::ORDER;
        let mut out = *self;
        if order < 2 {
            return out;
        }
        let band1 = band1_rotate(&r, [self.coeffs[1], self.coeffs[2], self.coeffs[3]]);
        out.coeffs[1..4].copy_from_slice(&band1);
        if order < 3 {
            return out;
        }
        let c = &self.coeffs;
        let band2 = band2_rotate(&r, [c[4], c[5], c[6], c[7], c[8]]);
        out.coeffs[4..9].copy_from_slice(&band2);
        if order < 4 {
            return out;
        }
        // Bands ≥ 3: the recurrence, seeded with band 2's closed-form matrix. Each block has
        // at most (2L − 1)² < 4N entries.
        let r1 = band1_matrix(&r);
        let mut scratch_a = [[0.0_f32; N]; 4];
        let mut scratch_b = [[0.0_f32; N]; 4];
        let (mut prev, mut next) = (scratch_a.as_flattened_mut(), scratch_b.as_flattened_mut());
        prev[..25].copy_from_slice(&band2_matrix(&r));
        for l in 3..order {
            let d = 2 * l + 1;
            next_band(l, &r1, &prev[..(d - 2) * (d - 2)], &mut next[..d * d]);
            apply_band(l, &next[..d * d], self, &mut out);
            core::mem::swap(&mut prev, &mut next);
        }
        out
    }

    /// [`rotated`](Self::rotated) by the unit quaternion `q`.
    #[inline]
    #[must_use]
    pub fn rotated_quat(&self, q: Quat) -> Self {
        self.rotated(Mat3::from_quat(q))
    }
}

/// The rotation taking world directions to a shading frame's local ones (rows `x, y, z` of
/// the frame): rotate world lighting by it to shade with a transfer vector built in the
/// local frame. Precondition: the frame is right-handed (as [`crate::Frame`] builds it).
#[inline]
#[must_use]
pub fn world_to_local(frame: &crate::Frame) -> Mat3 {
    Mat3::from_cols(frame.x, frame.y, frame.z).transpose()
}
