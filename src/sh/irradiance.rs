//! Irradiance from radiance coefficients: the general path for any order, and Ramamoorthi &
//! Hanrahan's 9-coefficient quadratic form.

use super::basis::{band_range, basis};
use super::coefficients::Sh;
use super::zonal::clamped_cosine_eigenvalue;
use crate::spectrum::Spectrum;
use glam::Vec3;

/// Ramamoorthi & Hanrahan 2001, eq. 12: `c₁ = Â₂ · ¼√(15/π) = √(15π)/16 ≈ 0.429043`.
pub const C1: f32 = 0.429_042_7;
/// `c₂ = ½ Â₁ √(3/4π) = ½ √(π/3) ≈ 0.511664`.
pub const C2: f32 = 0.511_664_2;
/// `c₃ = 3 Â₂ · ¼√(5/π) = 3√(5π)/16 ≈ 0.743125`.
pub const C3: f32 = 0.743_125;
/// `c₄ = Â₀ / (2√π) = √π/2 ≈ 0.886227`.
pub const C4: f32 = 0.886_226_9;
/// `c₅ = Â₂ · ¼√(5/π) = √(5π)/16 ≈ 0.247708`.
pub const C5: f32 = 0.247_708_3;

impl<const N: usize, S: Spectrum> Sh<N, S> {
    /// The irradiance `E(n) = ∫ L(ω) max(n·ω, 0) dω` on a surface with the unit normal `n`,
    /// for the radiance `L` these coefficients expand: `E(n) = Σ_l Â_l Σ_m L_lm Y_lm(n)`
    /// (Ramamoorthi & Hanrahan 2001, §3: the clamped cosine's Funk–Hecke eigenvalues `Â_l`,
    /// [`clamped_cosine_eigenvalue`]).
    ///
    /// Exact for radiance band-limited to the expansion's order; for any radiance, the
    /// error is that of truncating `L`. At order 3, Ramamoorthi & Hanrahan report average
    /// errors of about 1% for natural lighting; a single directional light is the hard case,
    /// off by up to `3/32` of its peak irradiance (at the terminator), `1/√768 ≈ 3.6%` RMS
    /// over all normals (`tests/sh.rs` derives and measures both).
    ///
    /// ```
    /// use lobe::sh::Sh;
    /// use lobe::Vec3;
    /// // A constant radiance L = 2 gives E = 2π for every normal.
    /// let l: Sh<9> = Sh::project(|_| 2.0, 1);
    /// assert!((l.irradiance(Vec3::X) - 2.0 * core::f32::consts::PI).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn irradiance(&self, n: Vec3) -> S {
        let y = basis::<N>(n);
        let mut sum = S::zero();
        for l in 0..Self::ORDER {
            let a = clamped_cosine_eigenvalue(l);
            if a == 0.0 {
                continue;
            }
            let mut band = S::zero();
            for (c, yi) in self.coeffs[band_range(l)].iter().zip(&y[band_range(l)]) {
                band += *c * *yi;
            }
            sum += band * a;
        }
        sum
    }

    /// The irradiance as a function of the normal, as SH: `E_lm = Â_l L_lm` (the convolution
    /// of the radiance with the clamped cosine). `eval` of the result is
    /// [`irradiance`](Self::irradiance).
    #[must_use]
    pub fn irradiance_sh(&self) -> Self {
        let a: [f32; N] = core::array::from_fn(clamped_cosine_eigenvalue);
        self.scale_bands(&a[..Self::ORDER.min(N)])
    }
}

/// Ramamoorthi & Hanrahan's quadratic form of order-3 irradiance: from 9 radiance
/// coefficients, `E(n) = nᵀ M n` with `n = (x, y, z, 1)` (2001, eqs. 12–13), precomputed
/// once per environment so that each normal costs one quadratic polynomial.
///
/// ```text
///     ⎡ c₁L₂₂   c₁L₂₋₂  c₁L₂₁   c₂L₁₁ ⎤
/// M = ⎢ c₁L₂₋₂  −c₁L₂₂  c₁L₂₋₁  c₂L₁₋₁⎥
///     ⎢ c₁L₂₁   c₁L₂₋₁  c₃L₂₀   c₂L₁₀ ⎥
///     ⎣ c₂L₁₁   c₂L₁₋₁  c₂L₁₀   c₄L₀₀ − c₅L₂₀ ⎦
/// ```
///
/// with the constants [`C1`] … [`C5`]. Equal to [`Sh::irradiance`] of the same coefficients
/// to round-off (the form is that sum written out in `x, y, z`, using `x² + y² + z² = 1`).
///
/// ```
/// use lobe::sh::{IrradianceQuadratic, Sh};
/// use lobe::Vec3;
/// let sky: Sh<9, Vec3> = Sh::project(|w| Vec3::new(0.2, 0.3, 0.5) * (1.0 + w.z), 2);
/// let e = IrradianceQuadratic::new(&sky);
/// let n = Vec3::new(0.0, 0.6, 0.8);
/// assert!((e.eval(n) - sky.irradiance(n)).abs().max_element() < 1e-5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IrradianceQuadratic<S = f32> {
    /// The constant term `c₄L₀₀ − c₅L₂₀`.
    k: S,
    /// Coefficients of `x`, `y`, `z`: `2c₂L₁₁`, `2c₂L₁₋₁`, `2c₂L₁₀`.
    linear: [S; 3],
    /// Coefficients of `xy`, `yz`, `xz`: `2c₁L₂₋₂`, `2c₁L₂₋₁`, `2c₁L₂₁`.
    cross: [S; 3],
    /// Coefficient of `x² − y²`: `c₁L₂₂`.
    xx_yy: S,
    /// Coefficient of `z²`: `c₃L₂₀`.
    zz: S,
}

impl<S: Spectrum> IrradianceQuadratic<S> {
    /// The quadratic form of the radiance coefficients `l` (bands 0–2).
    #[must_use]
    pub fn new(l: &Sh<9, S>) -> Self {
        let c = &l.coeffs;
        Self {
            k: c[0] * C4 - c[6] * C5,
            linear: [c[3] * (2.0 * C2), c[1] * (2.0 * C2), c[2] * (2.0 * C2)],
            cross: [c[4] * (2.0 * C1), c[5] * (2.0 * C1), c[7] * (2.0 * C1)],
            xx_yy: c[8] * C1,
            zz: c[6] * C3,
        }
    }

    /// The irradiance at the unit normal `n` (eq. 12 of Ramamoorthi & Hanrahan 2001).
    #[inline]
    #[must_use]
    pub fn eval(&self, n: Vec3) -> S {
        let (x, y, z) = (n.x, n.y, n.z);
        self.k
            + self.linear[0] * x
            + self.linear[1] * y
            + self.linear[2] * z
            + self.cross[0] * (x * y)
            + self.cross[1] * (y * z)
            + self.cross[2] * (x * z)
            + self.xx_yy * (x * x - y * y)
            + self.zz * (z * z)
    }

    /// The symmetric 4×4 matrix `M` of eq. 13, row by row, for `E(n) = nᵀ M n` with
    /// `n = (x, y, z, 1)` (what a shader uploads).
    #[must_use]
    pub fn matrix(&self) -> [[S; 4]; 4] {
        let h = |s: S| s * 0.5;
        let [lx, ly, lz] = self.linear.map(h);
        let [xy, yz, xz] = self.cross.map(h);
        [
            [self.xx_yy, xy, xz, lx],
            [xy, S::zero() - self.xx_yy, yz, ly],
            [xz, yz, self.zz, lz],
            [lx, ly, lz, self.k],
        ]
    }
}
