//! Owned structure-of-arrays buffers for the batched calls (`lobe::batch`), readable per lane,
//! and bit-for-bit equality: shared by `tests/batch.rs` and the fuzz example
//! (`examples/fuzz/`, which includes this file by its path).

use lobe::batch::{Lanes, Vec3s, Vec3sMut, Vec4sMut};
use lobe::{Spectrum, Vec3, Vec4};

/// One slice per coordinate.
pub struct Soa {
    /// The `x` of every lane.
    pub x: Vec<f32>,
    /// The `y` of every lane.
    pub y: Vec<f32>,
    /// The `z` of every lane.
    pub z: Vec<f32>,
}

impl Soa {
    /// The lanes `v`.
    pub fn of(v: &[Vec3]) -> Self {
        Self {
            x: v.iter().map(|w| w.x).collect(),
            y: v.iter().map(|w| w.y).collect(),
            z: v.iter().map(|w| w.z).collect(),
        }
    }
    /// `n` lanes of [`UNWRITTEN`].
    pub fn unwritten(n: usize) -> Self {
        Self {
            x: vec![UNWRITTEN; n],
            y: vec![UNWRITTEN; n],
            z: vec![UNWRITTEN; n],
        }
    }
    /// The lanes as a batched call's input.
    pub fn view(&self) -> Vec3s<'_> {
        Vec3s {
            x: &self.x,
            y: &self.y,
            z: &self.z,
        }
    }
    /// The lanes as a batched call's output.
    pub fn view_mut(&mut self) -> Vec3sMut<'_> {
        Vec3sMut {
            x: &mut self.x,
            y: &mut self.y,
            z: &mut self.z,
        }
    }
    /// Lane `k`.
    pub fn get(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }
}

/// What the output buffers hold before a batched call: a NaN whose bits no lane computes, so
/// that a lane the loop skipped differs, bit for bit, from the scalar call's answer (which is
/// often `+0`).
pub const UNWRITTEN: f32 = f32::from_bits(0x7fc0_beef);

/// A spectrum's batched output buffers, readable per lane.
pub trait Buffers: Lanes + Spectrum {
    /// The buffers: one `Vec` per channel.
    type Store;
    /// `n` lanes of [`UNWRITTEN`].
    fn store(n: usize) -> Self::Store;
    /// The buffers as a batched call's output.
    fn lanes_mut(s: &mut Self::Store) -> Self::Mut<'_>;
    /// Lane `k`.
    fn read(s: &Self::Store, k: usize) -> Self;
}

impl Buffers for f32 {
    type Store = Vec<f32>;
    fn store(n: usize) -> Vec<f32> {
        vec![UNWRITTEN; n]
    }
    fn lanes_mut(s: &mut Vec<f32>) -> &mut [f32] {
        s
    }
    fn read(s: &Vec<f32>, k: usize) -> f32 {
        s[k]
    }
}

impl Buffers for Vec3 {
    type Store = Soa;
    fn store(n: usize) -> Soa {
        Soa::unwritten(n)
    }
    fn lanes_mut(s: &mut Soa) -> Vec3sMut<'_> {
        s.view_mut()
    }
    fn read(s: &Soa, k: usize) -> Vec3 {
        s.get(k)
    }
}

/// Four channels (four wavelengths), one `Vec` each.
pub struct Channels4([Vec<f32>; 4]);

impl Buffers for Vec4 {
    type Store = Channels4;
    fn store(n: usize) -> Channels4 {
        Channels4([0; 4].map(|_| vec![UNWRITTEN; n]))
    }
    fn lanes_mut(s: &mut Channels4) -> Vec4sMut<'_> {
        let [x, y, z, w] = &mut s.0;
        Vec4sMut { x, y, z, w }
    }
    fn read(s: &Channels4, k: usize) -> Vec4 {
        Vec4::from_array(s.0.each_ref().map(|c| c[k]))
    }
}

/// Equal bit for bit, channel by channel: `-0` and `+0` differ (and a NaN equals only a NaN
/// of the same bits: no lane computes one, and [`UNWRITTEN`] marks a lane not written).
pub fn same<S: Spectrum>(a: S, b: S) -> bool {
    (0..S::CHANNELS).all(|c| a.channel(c).to_bits() == b.channel(c).to_bits())
}
