//! The small generator inside the stochastic models, seeded from a hash of their arguments.

use crate::math::mix64;
use crate::sampling::ONE_MINUS_EPSILON;
use glam::{Vec2, Vec3};

/// A PCG32 generator (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient
/// Statistically Good Algorithms for Random Number Generation", the XSH-RR output) seeded
/// from a hash of a call's arguments, so that a stochastic model's `eval`, `pdf` and `sample`
/// are deterministic functions of their inputs (pbrt-v4 §14.3.2 seeds its `LayeredBxDF`'s
/// generator the same way) and estimates with different seeds are independent.
///
/// Eight bytes of state on the stack: the hot loop does not allocate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WalkRng {
    state: u64,
}

/// PCG32's multiplier.
const MULTIPLIER: u64 = 0x5851_f42d_4c95_7f2d;
/// PCG32's increment (any odd number; this is the reference implementation's default).
const INCREMENT: u64 = 0x1405_7b7e_f767_814f;

/// A running hash of words: each word is folded in through [`mix64`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Hasher(u64);

impl Hasher {
    /// A hash that starts from `tag` (which call is hashing) and `seed`.
    #[inline(always)]
    pub(crate) fn new(tag: u64, seed: u64) -> Self {
        Self(mix64(mix64(tag ^ 0x9e37_79b9_7f4a_7c15) ^ seed))
    }

    /// Folds in a 32-bit word.
    #[inline(always)]
    pub(crate) fn word(self, w: u32) -> Self {
        Self(mix64(
            self.0 ^ u64::from(w).wrapping_mul(0x9e37_79b9_7f4a_7c15),
        ))
    }

    /// Folds in the bits of a float.
    #[inline(always)]
    pub(crate) fn float(self, x: f32) -> Self {
        self.word(x.to_bits())
    }

    /// Folds in the bits of a direction.
    #[inline(always)]
    pub(crate) fn vec3(self, v: Vec3) -> Self {
        self.float(v.x).float(v.y).float(v.z)
    }

    /// The generator seeded with the hash.
    #[inline(always)]
    pub(crate) fn rng(self) -> WalkRng {
        WalkRng::new(self.0)
    }
}

impl WalkRng {
    /// A generator whose sequence is fixed by `seed`.
    #[inline(always)]
    pub(crate) fn new(seed: u64) -> Self {
        let mut rng = Self { state: 0 };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(seed);
        rng.next_u32();
        rng
    }

    /// The next 32 random bits.
    #[inline(always)]
    pub(crate) fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(INCREMENT);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// A number uniform in `[0, 1)`: 24 random bits.
    #[inline(always)]
    pub(crate) fn next_f32(&mut self) -> f32 {
        ((self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)).min(ONE_MINUS_EPSILON)
    }

    /// Two numbers uniform in `[0, 1)`.
    #[inline(always)]
    pub(crate) fn next_vec2(&mut self) -> Vec2 {
        let x = self.next_f32();
        Vec2::new(x, self.next_f32())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_numbers_are_in_the_unit_interval_and_look_uniform() {
        let mut rng = Hasher::new(1, 2).vec3(Vec3::Z).rng();
        let n = 100_000;
        let mut sum = 0.0_f64;
        let mut below = 0;
        for _ in 0..n {
            let x = rng.next_f32();
            assert!((0.0..1.0).contains(&x));
            sum += f64::from(x);
            below += usize::from(x < 0.25);
        }
        // Mean 1/2 with standard error 1/√(12 n); a quarter below 1/4, standard error
        // √(3/16 / n); each within five standard errors.
        let n = n as f64;
        let (mean_err, quarter_err) = ((1.0 / (12.0 * n)).sqrt(), (0.1875 / n).sqrt());
        assert!((sum / n - 0.5).abs() <= 5.0 * mean_err);
        assert!((below as f64 / n - 0.25).abs() <= 5.0 * quarter_err);
    }

    #[test]
    fn different_inputs_give_different_streams() {
        let a = Hasher::new(1, 0).vec3(Vec3::Z).rng().next_u32();
        let b = Hasher::new(1, 1).vec3(Vec3::Z).rng().next_u32();
        let c = Hasher::new(2, 0).vec3(Vec3::Z).rng().next_u32();
        let d = Hasher::new(1, 0).vec3(Vec3::X).rng().next_u32();
        assert!(a != b && a != c && a != d && b != c);
        assert_eq!(a, Hasher::new(1, 0).vec3(Vec3::Z).rng().next_u32());
    }
}
