//! Environment light: radiance arriving from infinitely far away, by direction.

use glam::Mat3;
use lobe::sampling::{uniform_sphere, uniform_sphere_pdf};
use lobe::sh::{Sh, SphereQuadrature};
use lobe::{Vec2, Vec3};
use std::f32::consts::PI;

/// The order of the SH environment: 3 (bands 0–2, 9 coefficients), the irradiance order of
/// Ramamoorthi & Hanrahan 2001.
pub const SH_COEFFICIENTS: usize = 9;

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
    /// A radiance given by its spherical-harmonic coefficients (world frame, `y` up),
    /// clamped at zero where the truncated expansion rings below it: `--env sh`, the sky
    /// projected onto order 3 by [`Environment::project_sh`].
    Sh(Sh<SH_COEFFICIENTS, Vec3>),
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
            Self::Sh(l) => l.eval(dir).max(Vec3::ZERO),
        }
    }

    /// The order-3 SH coefficients of the radiance (world frame).
    ///
    /// A constant projects exactly. The sky is symmetric about `+y` with a jump at the
    /// horizon, so it is projected in a frame whose pole is `+y` (the rotation `P` with
    /// columns `ẑ, x̂, ŷ` takes local `z` to world `y`): there a
    /// [`SphereQuadrature`] split at the equator puts its nodes on each side of the jump
    /// (64 Gauss–Legendre nodes in `cos θ` per hemisphere for the `√y` blend, 8 azimuths
    /// for a function without azimuthal dependence). The coefficients of `h(ω) = sky(P ω)`
    /// are then turned by `P` (`sky(ω) = h(P⁻¹ ω)`), an exact rotation.
    pub fn project_sh(&self) -> Sh<SH_COEFFICIENTS, Vec3> {
        match *self {
            Self::Constant(l) => Sh::project(|_| l, 1),
            Self::Sky { .. } => {
                let p = Mat3::from_cols(Vec3::Z, Vec3::X, Vec3::Y);
                let rule = SphereQuadrature::new(64, 8).split_at_equator();
                let h: Sh<SH_COEFFICIENTS, Vec3> =
                    Sh::project_with(|w| self.radiance(p * w), &rule);
                h.rotated(p)
            }
            Self::Sh(l) => l,
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
            // The mean of the expansion, f_00 Y_00 = f_00 / (2√π) (before clamping).
            Self::Sh(l) => l.coeffs[0] * (0.5 / PI.sqrt()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sh_projection_keeps_the_sky_upright() {
        let sky = Environment::Sky {
            zenith: Vec3::new(0.10, 0.18, 0.40),
            horizon: Vec3::new(0.42, 0.42, 0.45),
            ground: Vec3::new(0.10, 0.09, 0.08),
        };
        let sh = Environment::Sh(sky.project_sh());
        // Up is sky-coloured, down is ground-coloured, and both sides alike.
        assert!(
            (sh.radiance(Vec3::Y) - sky.radiance(Vec3::Y))
                .abs()
                .max_element()
                < 0.1
        );
        assert!(
            (sh.radiance(-Vec3::Y) - sky.radiance(-Vec3::Y))
                .abs()
                .max_element()
                < 0.1
        );
        assert!(
            (sh.radiance(Vec3::X) - sh.radiance(-Vec3::Z))
                .abs()
                .max_element()
                < 1e-5
        );
        // The mean radiance is the sky's.
        assert!((sh.mean() - sky.mean()).abs().max_element() < 1e-3);
        // A constant stays a constant.
        let c = Environment::Constant(Vec3::splat(0.7));
        let sh = Environment::Sh(c.project_sh());
        assert!(
            (sh.radiance(Vec3::new(0.6, 0.0, 0.8)) - Vec3::splat(0.7))
                .abs()
                .max_element()
                < 1e-5
        );
    }

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
