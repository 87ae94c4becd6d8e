//! The [`Spectrum`] carrier that models are generic over.
//!
//! A spectrum is a small fixed set of channels with per-channel arithmetic:
//! `f32` (monochrome), [`Vec3`] (RGB) or [`Vec4`] (four wavelength samples). The
//! physical laws are checked on `f32` and hold per channel.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Sub};
use glam::{Vec3, Vec4};

/// A per-channel radiometric quantity: reflectance, radiance, a BSDF value.
///
/// Arithmetic is channel-wise. Implemented for `f32`, [`Vec3`] and [`Vec4`].
pub trait Spectrum:
    Copy
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Mul<f32, Output = Self>
    + Div<f32, Output = Self>
    + AddAssign
    + MulAssign<f32>
{
    /// The number of channels.
    const CHANNELS: usize;

    /// Every channel set to `v`.
    #[must_use]
    fn splat(v: f32) -> Self;

    /// Channel `i`; `i` must be below [`Self::CHANNELS`] (panics otherwise).
    #[must_use]
    fn channel(&self, i: usize) -> f32;

    /// Applies `f` to every channel.
    #[must_use]
    fn map(self, f: impl Fn(f32) -> f32) -> Self;

    /// Applies `f` to every pair of matching channels of `self` and `other`.
    #[must_use]
    fn zip_map(self, other: Self, f: impl Fn(f32, f32) -> f32) -> Self;

    /// The spectrum whose channel `i` is `f(i)`, as `core::array::from_fn` builds an array.
    #[must_use]
    fn from_fn(f: impl Fn(usize) -> f32) -> Self;

    /// All channels zero.
    #[inline(always)]
    #[must_use]
    fn zero() -> Self {
        Self::splat(0.0)
    }

    /// All channels one.
    #[inline(always)]
    #[must_use]
    fn one() -> Self {
        Self::splat(1.0)
    }

    /// The largest channel.
    #[must_use]
    fn max_channel(&self) -> f32 {
        (1..Self::CHANNELS).fold(self.channel(0), |m, i| m.max(self.channel(i)))
    }

    /// The smallest channel.
    #[must_use]
    fn min_channel(&self) -> f32 {
        (1..Self::CHANNELS).fold(self.channel(0), |m, i| m.min(self.channel(i)))
    }

    /// The mean of the channels.
    #[must_use]
    fn average(&self) -> f32 {
        (0..Self::CHANNELS).map(|i| self.channel(i)).sum::<f32>() / Self::CHANNELS as f32
    }

    /// True when every channel is finite.
    #[must_use]
    fn is_finite(&self) -> bool {
        (0..Self::CHANNELS).all(|i| self.channel(i).is_finite())
    }

    /// True when every channel is zero.
    #[must_use]
    fn is_black(&self) -> bool {
        (0..Self::CHANNELS).all(|i| self.channel(i) == 0.0)
    }
}

impl Spectrum for f32 {
    const CHANNELS: usize = 1;

    #[inline(always)]
    fn splat(v: f32) -> Self {
        v
    }

    #[inline(always)]
    fn channel(&self, i: usize) -> f32 {
        assert!(i == 0, "channel {i} of a 1-channel spectrum");
        *self
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> Self {
        f(self)
    }

    #[inline(always)]
    fn zip_map(self, other: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        f(self, other)
    }

    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> f32) -> Self {
        f(0)
    }
}

impl Spectrum for Vec3 {
    const CHANNELS: usize = 3;

    #[inline(always)]
    fn splat(v: f32) -> Self {
        Vec3::splat(v)
    }

    #[inline(always)]
    fn channel(&self, i: usize) -> f32 {
        self[i]
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> Self {
        Vec3::new(f(self.x), f(self.y), f(self.z))
    }

    #[inline(always)]
    fn zip_map(self, other: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        Vec3::new(f(self.x, other.x), f(self.y, other.y), f(self.z, other.z))
    }

    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> f32) -> Self {
        Vec3::new(f(0), f(1), f(2))
    }
}

impl Spectrum for Vec4 {
    const CHANNELS: usize = 4;

    #[inline(always)]
    fn splat(v: f32) -> Self {
        Vec4::splat(v)
    }

    #[inline(always)]
    fn channel(&self, i: usize) -> f32 {
        self[i]
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f32) -> f32) -> Self {
        Vec4::new(f(self.x), f(self.y), f(self.z), f(self.w))
    }

    #[inline(always)]
    fn zip_map(self, other: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        Vec4::new(
            f(self.x, other.x),
            f(self.y, other.y),
            f(self.z, other.z),
            f(self.w, other.w),
        )
    }

    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> f32) -> Self {
        Vec4::new(f(0), f(1), f(2), f(3))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check<S: Spectrum>(a: S) {
        assert_eq!(S::zero().max_channel(), 0.0);
        assert_eq!(S::one().min_channel(), 1.0);
        assert!(S::zero().is_black());
        assert_eq!(a.map(|x| 2.0 * x), a * 2.0);
        assert_eq!(a.zip_map(S::one(), |x, y| x + y), a + S::one());
        assert_eq!(S::from_fn(|i| a.channel(i)), a);
        assert_eq!(
            S::from_fn(|i| i as f32).channel(S::CHANNELS - 1),
            (S::CHANNELS - 1) as f32
        );
        assert!(a.is_finite());
        assert!(!S::splat(f32::NAN).is_finite());
    }

    #[test]
    fn carriers_agree() {
        check(0.25_f32);
        check(Vec3::new(0.1, 0.5, 0.9));
        check(Vec4::new(0.1, 0.5, 0.9, 0.3));
        let v = Vec3::new(0.1, 0.5, 0.9);
        assert_eq!(v.max_channel(), 0.9);
        assert_eq!(v.min_channel(), 0.1);
        assert!((v.average() - 0.5).abs() < 1e-7);
    }
}
