//! [`Sh`]: a fixed-size vector of spherical-harmonic coefficients.

use super::basis::{band_range, basis, index, order_of};
use crate::spectrum::Spectrum;
use core::ops::{Add, AddAssign, Index, IndexMut, Mul, MulAssign, Sub, SubAssign};
use glam::Vec3;

/// The coefficients of a function on the sphere in the real SH basis of the
/// [module docs](super), up to order `√N` (bands `l < √N`).
///
/// `N` is the number of coefficients, the square of the order: `Sh<9, S>` holds bands 0–2
/// (the irradiance order), `Sh<16, S>` bands 0–3. A count that is not a perfect square is
/// refused at compile time by [`new`](Self::new), [`ORDER`](Self::ORDER) and every method
/// that uses them (the public field lets a struct literal of such a count compile, but
/// nothing that needs its order). `S` is the carrier: `f32`, or an RGB `Vec3` with one expansion
/// per channel. No allocation: the coefficients are an inline array, `Copy`.
///
/// ```
/// use lobe::sh::Sh;
/// use lobe::Vec3;
/// // A directional light of irradiance 2 from +z, and its value back at +z.
/// let light: Sh<9> = Sh::from_direction(Vec3::Z, 2.0);
/// let sum = light + light * 0.5;
/// assert!(sum.eval(Vec3::Z) > 0.0);
/// assert_eq!(Sh::<9>::ORDER, 3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sh<const N: usize, S = f32> {
    /// The coefficients, at the flat index `l(l + 1) + m` ([`index`]).
    pub coeffs: [S; N],
}

/// Order 2 (bands 0–1): 4 coefficients.
pub type Sh2<S = f32> = Sh<4, S>;
/// Order 3 (bands 0–2): 9 coefficients, the irradiance order of Ramamoorthi & Hanrahan.
pub type Sh3<S = f32> = Sh<9, S>;
/// Order 4 (bands 0–3): 16 coefficients, the reach of the closed-form basis.
pub type Sh4<S = f32> = Sh<16, S>;

impl<const N: usize, S: Spectrum> Default for Sh<N, S> {
    #[inline]
    fn default() -> Self {
        Self::zero()
    }
}

impl<const N: usize, S: Spectrum> Sh<N, S> {
    /// The order: the number of bands, `√N`.
    pub const ORDER: usize = order_of(N);

    /// The coefficients `coeffs`, in index order.
    #[inline]
    #[must_use]
    pub const fn new(coeffs: [S; N]) -> Self {
        const { order_of(N) };
        Self { coeffs }
    }

    /// All coefficients zero.
    #[inline]
    #[must_use]
    pub fn zero() -> Self {
        Self::new([S::zero(); N])
    }

    /// The coefficient `f_lm`; zero outside the expansion's bands. Precondition `|m| ≤ l`:
    /// otherwise the flat index `l(l + 1) + m` ([`index`]) may name another band's
    /// coefficient.
    ///
    /// # Panics
    /// When that index leaves the array: `l(l + 1) + m < 0` (it wraps) or `≥ N`.
    #[inline]
    #[must_use]
    pub fn get(&self, l: usize, m: isize) -> S {
        if l < Self::ORDER {
            self.coeffs[index(l, m)]
        } else {
            S::zero()
        }
    }

    /// The projection of a delta `value · δ(ω − dir)`: `f_lm = value · Y_lm(dir)`. A
    /// directional light of irradiance `value` (on a surface facing it) from the unit
    /// direction `dir` (toward the light).
    #[inline]
    #[must_use]
    pub fn from_direction(dir: Vec3, value: S) -> Self {
        let y = basis::<N>(dir);
        Self::new(core::array::from_fn(|i| value * y[i]))
    }

    /// The expansion's value at the unit direction `w`: `Σ f_lm Y_lm(w)`.
    #[inline]
    #[must_use]
    pub fn eval(&self, w: Vec3) -> S {
        let y = basis::<N>(w);
        self.dot_basis(&y)
    }

    /// `Σ f_i y_i` for basis values `y` already evaluated (e.g. by [`basis`] once for
    /// several expansions).
    #[inline]
    #[must_use]
    pub fn dot_basis(&self, y: &[f32; N]) -> S {
        let mut sum = S::zero();
        for (c, &yi) in self.coeffs.iter().zip(y) {
            sum += *c * yi;
        }
        sum
    }

    /// The inner product `∫ f g dω = Σ f_i g_i` (Parseval; per channel).
    #[inline]
    #[must_use]
    pub fn dot(&self, other: &Self) -> S {
        let mut sum = S::zero();
        for (a, b) in self.coeffs.iter().zip(&other.coeffs) {
            sum += *a * *b;
        }
        sum
    }

    /// The inner product with a monochrome expansion, `Σ f_i g_i`: an RGB lighting against
    /// a grey transfer vector (precomputed radiance transfer's shading step).
    #[inline]
    #[must_use]
    pub fn dot_mono(&self, other: &Sh<N, f32>) -> S {
        self.dot_basis(&other.coeffs)
    }

    /// The energy of band `l`, `Σ_m f_lm²` (per channel): invariant under rotation. Zero for
    /// a band the expansion does not hold.
    #[must_use]
    pub fn band_energy(&self, l: usize) -> S {
        if l >= Self::ORDER {
            return S::zero();
        }
        let mut sum = S::zero();
        for c in &self.coeffs[band_range(l)] {
            sum += *c * *c;
        }
        sum
    }

    /// `∫ f² dω = Σ f_i²` (per channel).
    #[inline]
    #[must_use]
    pub fn squared_norm(&self) -> S {
        self.dot(self)
    }

    /// The expansion with band `l` multiplied by `weights[l]`; bands without a weight are
    /// zeroed.
    #[must_use]
    pub fn scale_bands(&self, weights: &[f32]) -> Self {
        let mut out = *self;
        for l in 0..Self::ORDER {
            let w = weights.get(l).copied().unwrap_or(0.0);
            for c in &mut out.coeffs[band_range(l)] {
                *c *= w;
            }
        }
        out
    }

    /// The same function at another order: truncated (the least-squares approximation at
    /// the lower order), or padded with zero bands.
    #[must_use]
    pub fn resize<const M: usize>(&self) -> Sh<M, S> {
        Sh::<M, S>::new(core::array::from_fn(|i| {
            self.coeffs.get(i).copied().unwrap_or(S::zero())
        }))
    }

    /// Channel `c` of every coefficient, as a monochrome expansion.
    ///
    /// # Panics
    /// If `c ≥ S::CHANNELS`.
    #[must_use]
    pub fn channel(&self, c: usize) -> Sh<N, f32> {
        Sh::new(core::array::from_fn(|i| self.coeffs[i].channel(c)))
    }

    /// Applies `f` to every coefficient.
    #[must_use]
    pub fn map<T: Spectrum>(&self, f: impl Fn(S) -> T) -> Sh<N, T> {
        Sh::new(core::array::from_fn(|i| f(self.coeffs[i])))
    }
}

impl<const N: usize> Sh<N, f32> {
    /// A monochrome expansion lifted to a carrier `S` with the value in every channel.
    #[must_use]
    pub fn splat<S: Spectrum>(&self) -> Sh<N, S> {
        self.map(S::splat)
    }
}

impl<const N: usize, S: Spectrum> Index<usize> for Sh<N, S> {
    type Output = S;
    #[inline]
    fn index(&self, i: usize) -> &S {
        &self.coeffs[i]
    }
}

impl<const N: usize, S: Spectrum> IndexMut<usize> for Sh<N, S> {
    #[inline]
    fn index_mut(&mut self, i: usize) -> &mut S {
        &mut self.coeffs[i]
    }
}

impl<const N: usize, S: Spectrum> Add for Sh<N, S> {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::new(core::array::from_fn(|i| self.coeffs[i] + rhs.coeffs[i]))
    }
}

impl<const N: usize, S: Spectrum> Sub for Sh<N, S> {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::new(core::array::from_fn(|i| self.coeffs[i] - rhs.coeffs[i]))
    }
}

impl<const N: usize, S: Spectrum> AddAssign for Sh<N, S> {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        for (a, b) in self.coeffs.iter_mut().zip(rhs.coeffs) {
            *a += b;
        }
    }
}

impl<const N: usize, S: Spectrum> SubAssign for Sh<N, S> {
    #[inline]
    fn sub_assign(&mut self, rhs: Self) {
        for (a, b) in self.coeffs.iter_mut().zip(rhs.coeffs) {
            *a = *a - b;
        }
    }
}

impl<const N: usize, S: Spectrum> Mul<f32> for Sh<N, S> {
    type Output = Self;
    #[inline]
    fn mul(self, k: f32) -> Self {
        Self::new(self.coeffs.map(|c| c * k))
    }
}

impl<const N: usize, S: Spectrum> MulAssign<f32> for Sh<N, S> {
    #[inline]
    fn mul_assign(&mut self, k: f32) {
        for c in &mut self.coeffs {
            *c *= k;
        }
    }
}
