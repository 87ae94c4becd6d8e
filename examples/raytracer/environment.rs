//! Environment light: radiance arriving from infinitely far away, by direction.

use lobe::sampling::{uniform_sphere, uniform_sphere_pdf};
use lobe::{Vec2, Vec3};

/// The light that reaches a ray escaping the scene (seed 003: "environment sources (the
/// sky)").
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Environment {
    /// The same radiance from every direction (the white furnace's "oven").
    Constant(Vec3),
    /// A sky gradient: `horizon` at the horizon blending to `zenith` overhead (+y), and a
    /// uniform `ground` below the horizon.
    Sky {
        /// Radiance straight up.
        zenith: Vec3,
        /// Radiance at the horizon.
        horizon: Vec3,
        /// Radiance from below the horizon.
        ground: Vec3,
    },
}

impl Environment {
    /// The radiance arriving along `-dir`, that is, seen looking in the unit direction `dir`.
    #[inline]
    pub fn radiance(&self, dir: Vec3) -> Vec3 {
        match *self {
            Self::Constant(l) => l,
            Self::Sky {
                zenith,
                horizon,
                ground,
            } => {
                if dir.y < 0.0 {
                    ground
                } else {
                    // A smooth blend, faster near the horizon.
                    let t = dir.y.sqrt();
                    horizon.lerp(zenith, t)
                }
            }
        }
    }

    /// A direction sampled for next-event estimation: uniform over the sphere. Returns the
    /// direction and its solid-angle density.
    #[inline]
    pub fn sample(&self, u: Vec2) -> (Vec3, f32) {
        (uniform_sphere(u), uniform_sphere_pdf())
    }

    /// The density with which [`sample`](Self::sample) draws `dir`.
    #[inline]
    pub fn pdf(&self, _dir: Vec3) -> f32 {
        uniform_sphere_pdf()
    }

    /// The radiance averaged over the sphere of directions: the Whitted integrator's
    /// ambient light.
    pub fn mean(&self) -> Vec3 {
        match *self {
            Self::Constant(l) => l,
            Self::Sky { .. } => {
                // Half the sphere is ground; the upper half by the midpoint rule in y (the
                // solid angle is uniform in y).
                const N: usize = 256;
                let upper = (0..N)
                    .map(|i| self.radiance(Vec3::new(0.0, (i as f32 + 0.5) / N as f32, 0.0)))
                    .sum::<Vec3>()
                    / N as f32;
                0.5 * (upper + self.radiance(-Vec3::Y))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sky_blends_and_constant_is_constant() {
        let sky = Environment::Sky {
            zenith: Vec3::Z,
            horizon: Vec3::X,
            ground: Vec3::Y,
        };
        assert_eq!(sky.radiance(Vec3::Y), Vec3::Z);
        assert_eq!(sky.radiance(Vec3::X), Vec3::X);
        assert_eq!(sky.radiance(-Vec3::Y), Vec3::Y);
        assert_eq!(Environment::Constant(Vec3::ONE).mean(), Vec3::ONE);
        let m = sky.mean();
        assert!((m.y - 0.5).abs() < 1e-6 && (m.x + m.z - 0.5).abs() < 1e-3);
    }
}
