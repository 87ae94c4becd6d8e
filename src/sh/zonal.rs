//! Zonal harmonics: functions symmetric about an axis, the clamped-cosine kernel, Funk–Hecke
//! convolution and zonal lobes turned to any direction.

use super::basis::{band_range, basis, index, legendre};
use super::coefficients::Sh;
use super::projection::gauss_legendre;
use crate::math::sqrt;
use crate::spectrum::Spectrum;
use core::f32::consts::PI;
use glam::Vec3;

/// `√((2l + 1) / 4π)`: `Y_{l,0} = √((2l+1)/4π) P_l(cos θ)`.
#[inline]
#[must_use]
pub(crate) fn zonal_norm(l: usize) -> f32 {
    sqrt((2.0 * l as f32 + 1.0) / (4.0 * PI))
}

/// `Â_l`, the Funk–Hecke eigenvalue of the clamped cosine `max(cos θ, 0)`: convolving a
/// radiance with it gives the irradiance, band by band, `E_lm = Â_l L_lm`.
///
/// Ramamoorthi & Hanrahan 2001, §3 (`Â_l = 2π ∫₀¹ t P_l(t) dt`): `Â_0 = π`,
/// `Â_1 = 2π/3`, `Â_l = 0` for odd `l > 1`, and for even `l`
///
/// ```text
/// Â_l = 2π (−1)^(l/2 − 1) / ((l + 2)(l − 1)) · l! / (2^l (l/2)!²)
/// ```
///
/// so `π/4, −π/24, π/64, …` for `l = 2, 4, 6`. The central binomial ratio
/// `l! / (2^l (l/2)!²) = Π_{k ≤ l/2} (2k − 1)/(2k)` is formed as that product, so no
/// factorial overflows at any band.
///
/// ```
/// use lobe::sh::clamped_cosine_eigenvalue;
/// use core::f32::consts::PI;
/// assert!((clamped_cosine_eigenvalue(2) - PI / 4.0).abs() < 1e-6);
/// assert!((clamped_cosine_eigenvalue(4) + PI / 24.0).abs() < 1e-6);
/// assert_eq!(clamped_cosine_eigenvalue(3), 0.0);
/// ```
#[must_use]
pub fn clamped_cosine_eigenvalue(l: usize) -> f32 {
    match l {
        0 => PI,
        1 => 2.0 * PI / 3.0,
        l if l % 2 == 1 => 0.0,
        l => {
            let half = l / 2;
            let mut ratio = 1.0_f64;
            for k in 1..=half {
                ratio *= (2 * k - 1) as f64 / (2 * k) as f64;
            }
            let sign = if half % 2 == 1 { 1.0 } else { -1.0 };
            let lf = l as f64;
            (2.0 * core::f64::consts::PI * sign * ratio / ((lf + 2.0) * (lf - 1.0))) as f32
        }
    }
}

/// A zonal function: symmetric about `+z`, given by one coefficient per band `l < L`, its
/// expansion `k(θ) = Σ_l k_l Y_{l,0}(θ)` (`k_l` is the coefficient of `Y_{l,0}`; every
/// `m ≠ 0` coefficient is zero).
///
/// Zonal functions are the kernels of convolution on the sphere: by the Funk–Hecke theorem,
/// `∫ k(n·ω) Y_lm(ω) dω = λ_l Y_lm(n)` with `λ_l = √(4π/(2l+1)) k_l`
/// ([`eigenvalues`](Self::eigenvalues); Driscoll & Healy 1994, theorem 1; Sloan 2008 §"Zonal
/// harmonics"), so [`Sh::convolve`] is a per-band scale. A zonal lobe turned to point along
/// `d` ([`rotated`](Self::rotated)) has the coefficients `λ_l Y_lm(d)` (Sloan 2008, §"Zonal Harmonics").
///
/// ```
/// use lobe::sh::{Sh, Zonal};
/// use lobe::Vec3;
/// // The clamped cosine about a direction, and its value along it.
/// let d = Vec3::new(0.0, 0.6, 0.8);
/// let lobe: Sh<9> = Zonal::<3>::clamped_cosine().rotated(d);
/// assert!((lobe.eval(d) - Zonal::<3>::clamped_cosine().eval(1.0)).abs() < 1e-5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Zonal<const L: usize> {
    /// `k_l`, the coefficient of `Y_{l,0}`, for `l < L`.
    pub coeffs: [f32; L],
}

impl<const L: usize> Zonal<L> {
    /// The zonal function with the coefficients `k_l`.
    #[inline]
    #[must_use]
    pub const fn new(coeffs: [f32; L]) -> Self {
        Self { coeffs }
    }

    /// The clamped cosine `max(cos θ, 0)`: `k_l = √((2l+1)/4π) Â_l` with `Â_l` from
    /// [`clamped_cosine_eigenvalue`] (Ramamoorthi & Hanrahan 2001, §3), so
    /// `k_0 = √π/2`, `k_1 = √(π/3)`, `k_2 = √(5π)/8`, `k_3 = 0`, ….
    #[must_use]
    pub fn clamped_cosine() -> Self {
        Self::new(core::array::from_fn(|l| {
            zonal_norm(l) * clamped_cosine_eigenvalue(l)
        }))
    }

    /// The coefficients of the profile `k(cos θ)`: `k_l = 2π ∫ k(t) √((2l+1)/4π) P_l(t) dt`
    /// by Gauss–Legendre quadrature with `nodes` points on each of `[−1, 0]` and `[0, 1]`
    /// (exact when `k` is a polynomial of degree `≤ 2 nodes − L` on each half, such as a
    /// clamped cosine power; a converging approximation otherwise).
    #[must_use]
    pub fn from_profile(mut profile: impl FnMut(f32) -> f32, nodes: usize) -> Self {
        let nodes = nodes.max(1);
        let mut sums = [0.0_f64; L];
        for (a, b) in [(-1.0_f64, 0.0_f64), (0.0, 1.0)] {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for i in 0..nodes {
                let (x, w) = gauss_legendre(nodes, i);
                let t = (mid + half * x) as f32;
                let v = f64::from(profile(t)) * w * half;
                for (l, s) in sums.iter_mut().enumerate() {
                    *s += v * f64::from(zonal_norm(l) * legendre(l, t));
                }
            }
        }
        Self::new(sums.map(|s| (2.0 * core::f64::consts::PI * s) as f32))
    }

    /// The function's value at polar angle `θ` from its axis: `Σ_l k_l √((2l+1)/4π)
    /// P_l(cos θ)`.
    #[must_use]
    pub fn eval(&self, cos_theta: f32) -> f32 {
        let mut sum = 0.0;
        for (l, k) in self.coeffs.iter().enumerate() {
            sum += k * zonal_norm(l) * legendre(l, cos_theta);
        }
        sum
    }

    /// The Funk–Hecke eigenvalues `λ_l = √(4π/(2l+1)) k_l`: convolution with this kernel
    /// scales band `l` by `λ_l`.
    #[must_use]
    pub fn eigenvalues(&self) -> [f32; L] {
        core::array::from_fn(|l| self.coeffs[l] / zonal_norm(l))
    }

    /// The zonal function as a full expansion about `+z`: `f_{l,0} = k_l`, zero elsewhere
    /// (bands beyond `L` are zero; bands beyond the target order are dropped).
    #[must_use]
    pub fn to_sh<const N: usize>(&self) -> Sh<N, f32> {
        let mut out = Sh::<N, f32>::zero();
        for (l, k) in self.coeffs.iter().enumerate().take(Sh::<N, f32>::ORDER) {
            out.coeffs[index(l, 0)] = *k;
        }
        out
    }

    /// The zonal function turned so that its axis points along the unit direction `dir`:
    /// `f_lm = √(4π/(2l+1)) k_l Y_lm(dir)` (Sloan 2008, §"Zonal Harmonics"). Bands beyond `L` are zero.
    #[must_use]
    pub fn rotated<const N: usize>(&self, dir: Vec3) -> Sh<N, f32> {
        let y = basis::<N>(dir);
        let lambda = self.eigenvalues();
        let mut out = Sh::<N, f32>::zero();
        for (l, lambda_l) in lambda.iter().enumerate().take(Sh::<N, f32>::ORDER) {
            for (c, yi) in out.coeffs[band_range(l)].iter_mut().zip(&y[band_range(l)]) {
                *c = lambda_l * yi;
            }
        }
        out
    }
}

impl<const N: usize, S: Spectrum> Sh<N, S> {
    /// The convolution `(k ⋆ f)(n) = ∫ k(n·ω) f(ω) dω` with the zonal kernel `k`, by the
    /// Funk–Hecke theorem: band `l` scaled by `λ_l = √(4π/(2l+1)) k_l`. Bands the kernel does
    /// not hold are zeroed.
    ///
    /// ```
    /// use lobe::sh::{Sh, Zonal};
    /// // Convolving a constant radiance L = 1 with the clamped cosine gives the irradiance π.
    /// let l: Sh<9> = Sh::project(|_| 1.0, 1);
    /// let e = l.convolve(&Zonal::<3>::clamped_cosine());
    /// assert!((e.eval(lobe::Vec3::Y) - core::f32::consts::PI).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn convolve<const L: usize>(&self, kernel: &Zonal<L>) -> Self {
        self.scale_bands(&kernel.eigenvalues())
    }
}
