//! Structure-of-arrays slices: the batched calls' inputs and outputs.

use super::{LengthError, same_length};
use crate::spectrum::Spectrum;
use glam::{Vec2, Vec3, Vec4};

/// Directions (or any 3-vectors) as one slice per coordinate: lane `k` is
/// `(x[k], y[k], z[k])`.
#[derive(Clone, Copy, Debug)]
pub struct Vec3s<'a> {
    /// The `x` coordinates.
    pub x: &'a [f32],
    /// The `y` coordinates.
    pub y: &'a [f32],
    /// The `z` coordinates.
    pub z: &'a [f32],
}

impl Vec3s<'_> {
    /// The number of lanes.
    ///
    /// # Errors
    /// [`LengthError`] when the coordinate slices differ in length.
    #[inline]
    pub fn lanes(&self) -> Result<usize, LengthError> {
        same_length(&[self.x.len(), self.y.len(), self.z.len()])
    }

    /// Lane `k`; `k` must be below the length (panics otherwise).
    #[inline(always)]
    #[must_use]
    pub fn get(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }

    /// Lanes `start..end`.
    #[inline(always)]
    pub(crate) fn range(&self, start: usize, end: usize) -> Self {
        Self {
            x: &self.x[start..end],
            y: &self.y[start..end],
            z: &self.z[start..end],
        }
    }
}

/// Points of the unit square (a sampler's random numbers) as one slice per coordinate.
#[derive(Clone, Copy, Debug)]
pub struct Vec2s<'a> {
    /// The first coordinates.
    pub x: &'a [f32],
    /// The second coordinates.
    pub y: &'a [f32],
}

impl Vec2s<'_> {
    /// The number of lanes.
    ///
    /// # Errors
    /// [`LengthError`] when the coordinate slices differ in length.
    #[inline]
    pub fn lanes(&self) -> Result<usize, LengthError> {
        same_length(&[self.x.len(), self.y.len()])
    }

    /// Lane `k`; `k` must be below the length (panics otherwise).
    #[inline(always)]
    #[must_use]
    pub fn get(&self, k: usize) -> Vec2 {
        Vec2::new(self.x[k], self.y[k])
    }

    /// Lanes `start..end`.
    #[inline(always)]
    pub(crate) fn range(&self, start: usize, end: usize) -> Self {
        Self {
            x: &self.x[start..end],
            y: &self.y[start..end],
        }
    }
}

/// Slices to write 3-vectors (directions, RGB values) into, one per coordinate.
#[derive(Debug)]
pub struct Vec3sMut<'a> {
    /// The `x` coordinates (red).
    pub x: &'a mut [f32],
    /// The `y` coordinates (green).
    pub y: &'a mut [f32],
    /// The `z` coordinates (blue).
    pub z: &'a mut [f32],
}

impl<'a> Vec3sMut<'a> {
    /// The number of lanes.
    ///
    /// # Errors
    /// [`LengthError`] when the coordinate slices differ in length.
    #[inline]
    pub fn lanes(&self) -> Result<usize, LengthError> {
        same_length(&[self.x.len(), self.y.len(), self.z.len()])
    }

    /// The first `n` lanes (`n` must not exceed the length).
    #[inline(always)]
    pub(crate) fn truncate(self, n: usize) -> Self {
        Self {
            x: &mut self.x[..n],
            y: &mut self.y[..n],
            z: &mut self.z[..n],
        }
    }

    /// Lanes `start..end`, reborrowed.
    #[inline(always)]
    pub(crate) fn range(&mut self, start: usize, end: usize) -> Vec3sMut<'_> {
        Vec3sMut {
            x: &mut self.x[start..end],
            y: &mut self.y[start..end],
            z: &mut self.z[start..end],
        }
    }

    /// Writes lane `k`.
    #[inline(always)]
    pub(crate) fn put(&mut self, k: usize, v: Vec3) {
        self.x[k] = v.x;
        self.y[k] = v.y;
        self.z[k] = v.z;
    }
}

/// Slices to write four-channel values (four wavelengths) into, one per channel.
#[derive(Debug)]
pub struct Vec4sMut<'a> {
    /// The first channel.
    pub x: &'a mut [f32],
    /// The second channel.
    pub y: &'a mut [f32],
    /// The third channel.
    pub z: &'a mut [f32],
    /// The fourth channel.
    pub w: &'a mut [f32],
}

/// A [`Spectrum`] whose batched values go to one slice per channel: `&mut [f32]` for `f32`,
/// [`Vec3sMut`] for `Vec3`, [`Vec4sMut`] for `Vec4`.
///
/// Its hidden methods (a chunk of lanes in stack space, a range of an output) serve the
/// batched calls of the models built from others; a spectrum of your own implements them as
/// the crate's three do, on `lobe::batch::Rows<L>` (stack space of `L` lanes for up to four
/// channels: a spectrum of more does not fit, and cannot be a part of `Mix`, `TwoSided` or
/// `Mono`).
pub trait Lanes: Spectrum {
    /// The slices a batched call writes this spectrum's values into.
    type Mut<'a>;

    /// The number of lanes of `out`.
    ///
    /// # Errors
    /// [`LengthError`] when its channel slices differ in length.
    fn lanes(out: &Self::Mut<'_>) -> Result<usize, LengthError>;

    /// The first `n` lanes of `out` (`n` must not exceed its length).
    #[doc(hidden)]
    fn truncate<'a>(out: Self::Mut<'a>, n: usize) -> Self::Mut<'a>;

    /// Writes `v` to lane `k` of `out`.
    #[doc(hidden)]
    fn put(out: &mut Self::Mut<'_>, k: usize, v: Self);

    /// Lanes `start..end` of `out`, reborrowed.
    #[doc(hidden)]
    fn lanes_of<'b>(out: &'b mut Self::Mut<'_>, start: usize, end: usize) -> Self::Mut<'b>;

    /// The first `n` lanes of a chunk's stack space, one row per channel.
    #[doc(hidden)]
    fn rows_mut<const L: usize>(rows: &mut Rows<L>, n: usize) -> Self::Mut<'_>;

    /// Lane `k` of a chunk's stack space.
    #[doc(hidden)]
    fn rows_get<const L: usize>(rows: &Rows<L>, k: usize) -> Self;
}

/// How many lanes the models built from other models (`Mix`, `TwoSided`, `Mono`) pass to
/// their parts' batched calls at a time where they hold values of the spectrum, through stack
/// space of this many lanes (a call of at most [`SHORT`] lanes: of that many).
pub(crate) const PART: usize = 256;

/// The most lanes of a call that holds its chunk in stack space of this many lanes, not of a
/// long chunk's ([`PART`], the tables' 256, the 1,024 lanes of `Mix`'s densities, `TwoSided`'s
/// and `Mono`'s `z` and values): the space is zeroed on every call, and for a short call that
/// cost more than the lanes did (`TwoSided(GGX gold)`'s `pdf` at 16 lanes a call spent more
/// than half its time in `memset`, a profile under AVX2).
pub(crate) const SHORT: usize = 64;

/// The chunks `start..end` of `n` lanes, `L` at a time.
#[inline(always)]
pub(crate) fn chunks<const L: usize>(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n)
        .step_by(L)
        .map(move |start| (start, n.min(start + L)))
}

/// A chunk's stack space for the values of a spectrum of up to four channels, `L` lanes.
#[doc(hidden)]
pub type Rows<const L: usize = PART> = [[f32; L]; 4];

impl Lanes for f32 {
    type Mut<'a> = &'a mut [f32];

    #[inline]
    fn lanes(out: &&mut [f32]) -> Result<usize, LengthError> {
        Ok(out.len())
    }

    #[inline(always)]
    fn truncate<'a>(out: Self::Mut<'a>, n: usize) -> Self::Mut<'a> {
        &mut out[..n]
    }

    #[inline(always)]
    fn put(out: &mut &mut [f32], k: usize, v: f32) {
        out[k] = v;
    }

    #[inline(always)]
    fn lanes_of<'b>(out: &'b mut &mut [f32], start: usize, end: usize) -> &'b mut [f32] {
        &mut out[start..end]
    }

    #[inline(always)]
    fn rows_mut<const L: usize>(rows: &mut Rows<L>, n: usize) -> &mut [f32] {
        &mut rows[0][..n]
    }

    #[inline(always)]
    fn rows_get<const L: usize>(rows: &Rows<L>, k: usize) -> f32 {
        rows[0][k]
    }
}

impl Lanes for Vec3 {
    type Mut<'a> = Vec3sMut<'a>;

    #[inline]
    fn lanes(out: &Vec3sMut<'_>) -> Result<usize, LengthError> {
        out.lanes()
    }

    #[inline(always)]
    fn truncate<'a>(out: Self::Mut<'a>, n: usize) -> Self::Mut<'a> {
        out.truncate(n)
    }

    #[inline(always)]
    fn put(out: &mut Vec3sMut<'_>, k: usize, v: Vec3) {
        out.put(k, v);
    }

    #[inline(always)]
    fn lanes_of<'b>(out: &'b mut Vec3sMut<'_>, start: usize, end: usize) -> Vec3sMut<'b> {
        out.range(start, end)
    }

    #[inline(always)]
    fn rows_mut<const L: usize>(rows: &mut Rows<L>, n: usize) -> Vec3sMut<'_> {
        let [x, y, z, _] = rows;
        Vec3sMut {
            x: &mut x[..n],
            y: &mut y[..n],
            z: &mut z[..n],
        }
    }

    #[inline(always)]
    fn rows_get<const L: usize>(rows: &Rows<L>, k: usize) -> Vec3 {
        Vec3::new(rows[0][k], rows[1][k], rows[2][k])
    }
}

impl Lanes for Vec4 {
    type Mut<'a> = Vec4sMut<'a>;

    #[inline]
    fn lanes(out: &Vec4sMut<'_>) -> Result<usize, LengthError> {
        same_length(&[out.x.len(), out.y.len(), out.z.len(), out.w.len()])
    }

    #[inline(always)]
    fn truncate<'a>(out: Self::Mut<'a>, n: usize) -> Self::Mut<'a> {
        Vec4sMut {
            x: &mut out.x[..n],
            y: &mut out.y[..n],
            z: &mut out.z[..n],
            w: &mut out.w[..n],
        }
    }

    #[inline(always)]
    fn put(out: &mut Vec4sMut<'_>, k: usize, v: Vec4) {
        out.x[k] = v.x;
        out.y[k] = v.y;
        out.z[k] = v.z;
        out.w[k] = v.w;
    }

    #[inline(always)]
    fn lanes_of<'b>(out: &'b mut Vec4sMut<'_>, start: usize, end: usize) -> Vec4sMut<'b> {
        Vec4sMut {
            x: &mut out.x[start..end],
            y: &mut out.y[start..end],
            z: &mut out.z[start..end],
            w: &mut out.w[start..end],
        }
    }

    #[inline(always)]
    fn rows_mut<const L: usize>(rows: &mut Rows<L>, n: usize) -> Vec4sMut<'_> {
        let [x, y, z, w] = rows;
        Vec4sMut {
            x: &mut x[..n],
            y: &mut y[..n],
            z: &mut z[..n],
            w: &mut w[..n],
        }
    }

    #[inline(always)]
    fn rows_get<const L: usize>(rows: &Rows<L>, k: usize) -> Vec4 {
        Vec4::new(rows[0][k], rows[1][k], rows[2][k], rows[3][k])
    }
}
