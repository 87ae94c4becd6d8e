//! Warps from the unit square to the disk and to directions, with their densities and
//! inverses, and the multiple-importance-sampling weights.
//!
//! ## Conventions
//!
//! * Inputs `u` are points of the unit square `[0, 1]²`, typically two uniform random
//!   numbers. Every warp is total on the closed square: `u = 1.0` exactly is fine, and the
//!   output is always finite.
//! * Directions are unit [`Vec3`]s in the **local frame**, `z` up: the hemisphere warps
//!   produce `z ≥ 0`, the cone warps are centred on `+z`, and `cos θ = w.z`.
//! * Densities (`*_pdf`) are with respect to **solid angle** on the unit sphere.
//! * The `*_inverse` functions map a direction back to the point of the square the warp
//!   sends there, clamped to `[0, 1]²`, so `inverse(forward(u)) ≈ u`. They are meant for
//!   directions the warp can produce; for others they return some point of the square.
//!
//! Sources: Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square" (JGT 2(3))
//! for the concentric map; Pharr, Jakob & Humphreys, *Physically Based Rendering*, 4th ed.,
//! §A.5 for the hemisphere, sphere and cone warps; Veach 1997, *Robust Monte Carlo Methods
//! for Light Transport Simulation*, §9.2 for the heuristics.
//!
//! ```
//! use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, cosine_hemisphere_inverse};
//! use lobe::Vec2;
//!
//! let u = Vec2::new(0.3, 0.8);
//! let w = cosine_hemisphere(u);
//! assert!(w.z >= 0.0 && (w.length() - 1.0).abs() < 1e-6);
//! assert!((cosine_hemisphere_pdf(w.z) - w.z / core::f32::consts::PI).abs() < 1e-7);
//! assert!((cosine_hemisphere_inverse(w) - u).length() < 1e-5);
//! ```

use crate::math::{
    atan, atan2, copysign, exp, exp_m1, ln, safe_sqrt, sin_cos_octant, sin_cos_turns,
};
use core::f32::consts::{FRAC_1_PI, FRAC_PI_4, TAU};
use glam::{Vec2, Vec3};

/// `1 / (2π)`, the density of the uniform hemisphere.
const INV_2PI: f32 = 0.5 * FRAC_1_PI;
/// `1 / (4π)`, the density of the uniform sphere.
const INV_4PI: f32 = 0.25 * FRAC_1_PI;
/// The largest `f32` below 1, where a number meant to be uniform in `[0, 1)` is clamped.
pub(crate) const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// Whether the lobe-choice number `uc` picks the branch of probability `p` (the one that owns
/// `[0, p)`): `uc < p`, with `uc = 1` read as the largest `f32` below 1, so that a branch of
/// zero weight is never picked, at any `uc ∈ [0, 1]` (a NaN reads as 1 too).
#[inline(always)]
#[must_use]
pub(crate) fn picks(uc: f32, p: f32) -> bool {
    uc.min(ONE_MINUS_EPSILON) < p
}

/// `u ∈ [lo, lo + width)` carried back onto `[0, 1)`: once `u` has chosen the branch that
/// owns that interval, what is left of it is a fresh uniform number for the branch's own
/// sampler (the reuse of a lobe-selection sample, as in pbrt-v4's `LayeredBxDF`). Clamped to
/// `[0, 1)` against rounding (and a NaN to `0`).
#[inline(always)]
#[allow(clippy::manual_clamp)] // `clamp` would pass a NaN through; `max` turns it into 0.
pub(crate) fn reuse_uniform(u: f32, lo: f32, width: f32) -> f32 {
    ((u - lo) / width).max(0.0).min(ONE_MINUS_EPSILON)
}

/// The angle `atan2(y, x)` moved into `[0, 2π)`, as a fraction of a full turn in `[0, 1]`.
#[inline(always)]
fn turn_fraction(y: f32, x: f32) -> f32 {
    let phi = atan2(y, x);
    let phi = if phi < 0.0 { phi + TAU } else { phi };
    (phi * (1.0 / TAU)).clamp(0.0, 1.0)
}

/// Maps the unit square onto the unit disk with Shirley & Chiu's concentric map, which
/// preserves relative area (uniform in, uniform out) and keeps adjacency with low distortion.
///
/// Shirley & Chiu 1997, §3: with `(a, b) = 2u − 1`, the square ring `max(|a|, |b|) = r`
/// goes to the circle of radius `r`, at angle `φ = (π/4) b/a` where `|a| > |b|` and
/// `φ = π/2 − (π/4) a/b` otherwise. Precondition: `u ∈ [0, 1]²`; the result has length ≤ 1
/// (up to rounding).
#[inline(always)]
#[must_use]
pub fn square_to_disk_concentric(u: Vec2) -> Vec2 {
    concentric(u).0
}

/// [`square_to_disk_concentric`] with the point's distance from the centre, `max(|a|, |b|)`,
/// known exactly before the angle's sine and cosine are.
#[inline(always)]
fn concentric(u: Vec2) -> (Vec2, f32) {
    let a = 2.0 * u.x - 1.0;
    let b = 2.0 * u.y - 1.0;
    if a == 0.0 && b == 0.0 {
        return (Vec2::ZERO, 0.0);
    }
    // A negative radius flips the point through the origin, which covers the left and
    // lower quarters of the square with the same two formulas. φ = (π/4) b/a, or
    // φ = π/2 − (π/4) a/b, whose sine and cosine are those of (π/4) a/b swapped. (Branches
    // rather than selects: the scalar sampler runs ahead on the predicted side, faster than
    // waiting for the comparison; a batched loop turns them into selects anyway.)
    if a.abs() > b.abs() {
        let (s, c) = sin_cos_octant(FRAC_PI_4 * (b / a));
        (Vec2::new(a * c, a * s), a.abs())
    } else {
        let (s, c) = sin_cos_octant(FRAC_PI_4 * (a / b));
        (Vec2::new(b * s, b * c), b.abs())
    }
}

/// The inverse of [`square_to_disk_concentric`]: the point of the unit square that the
/// concentric map sends to `p`.
///
/// Inverts Shirley & Chiu 1997, §3: the signed radius is `±|p|` (the sign of the dominant
/// coordinate) and the ratio of the square coordinates is `(4/π) atan(y/x)` (or of `x/y`).
/// Precondition: `|p| ≤ 1`; the result is clamped to `[0, 1]²`.
#[inline(always)]
#[must_use]
pub fn disk_to_square_concentric(p: Vec2) -> Vec2 {
    let r = p.length();
    let (a, b) = if r == 0.0 {
        (0.0, 0.0)
    } else if p.x.abs() >= p.y.abs() {
        // The sector |a| ≥ |b|: φ = (π/4) b/a ∈ [−π/4, π/4] and tan φ = y/x.
        let a = copysign(r, p.x);
        (a, a * (atan(p.y / p.x) * (1.0 / FRAC_PI_4)))
    } else {
        // The sector |b| > |a|: π/2 − φ = (π/4) a/b ∈ (−π/4, π/4) and tan(π/2 − φ) = x/y.
        let b = copysign(r, p.y);
        (b * (atan(p.x / p.y) * (1.0 / FRAC_PI_4)), b)
    };
    Vec2::new(
        (0.5 * (a + 1.0)).clamp(0.0, 1.0),
        (0.5 * (b + 1.0)).clamp(0.0, 1.0),
    )
}

/// A direction on the upper hemisphere (`z ≥ 0`) distributed with density `cos θ / π`.
///
/// Malley's method (PBR 4th ed., §A.5): a uniform point of the disk
/// ([`square_to_disk_concentric`]) lifted to the hemisphere, `z = √(1 − r²)` with `r` the
/// point's radius, computed as `√((1 − r)(1 + r))` from the concentric map's exact `r` (rather
/// than from `x² + y²`, whose rounding it would inherit). Precondition: `u ∈ [0, 1]²`.
#[inline(always)]
#[must_use]
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let (d, r) = concentric(u);
    Vec3::new(d.x, d.y, safe_sqrt((1.0 - r) * (1.0 + r)))
}

/// The solid-angle density of [`cosine_hemisphere`]: `max(cos θ, 0) / π` (PBR 4th ed., §A.5).
#[inline(always)]
#[must_use]
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) * FRAC_1_PI
}

/// The inverse of [`cosine_hemisphere`]: projects `w` onto the disk and inverts the
/// concentric map.
///
/// Precondition: `w` is a unit vector with `w.z ≥ 0`; the result is in `[0, 1]²`.
#[inline(always)]
#[must_use]
pub fn cosine_hemisphere_inverse(w: Vec3) -> Vec2 {
    disk_to_square_concentric(Vec2::new(w.x, w.y))
}

/// A direction around `+z` with density `(n + 1)/(2π) cos^n θ` on the hemisphere (`n ≥ 0`):
/// `cos θ = u.x^(1/(n+1))`, the inverse of its CDF in `cos θ`, with
/// `sin θ = √(−expm1(2 ln u.x/(n + 1)))`, which keeps its digits for large `n`.
///
/// The lobe of Phong-like models (Lafortune & Willems 1994) and the `D cos θ` sampler of the
/// normalised Blinn-Phong distribution (`n = p + 1`; Walter et al. 2007, eq. 31).
#[inline(always)]
#[must_use]
pub fn cosine_power_hemisphere(u: Vec2, n: f32) -> Vec3 {
    let l = ln(u.x.max(f32::MIN_POSITIVE)) / (n + 1.0);
    let cos = exp(l);
    let sin = safe_sqrt(-exp_m1(2.0 * l));
    let (s, c) = sin_cos_turns(u.y);
    Vec3::new(sin * c, sin * s, cos)
}

/// The density of [`cosine_power_hemisphere`]: `(n + 1)/(2π) max(0, cos θ)^n`.
#[inline(always)]
#[must_use]
pub fn cosine_power_hemisphere_pdf(cos_theta: f32, n: f32) -> f32 {
    if cos_theta > 0.0 {
        (n + 1.0) * 0.5 * FRAC_1_PI * crate::math::powf(cos_theta.min(1.0), n)
    } else {
        0.0
    }
}

/// A direction uniformly distributed on the upper hemisphere (`z ≥ 0`).
///
/// PBR 4th ed., §A.5: `z = u.x`, `φ = 2π u.y`, `sin θ = √((1 − z)(1 + z))`.
/// Precondition: `u ∈ [0, 1]²`.
#[inline(always)]
#[must_use]
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x;
    let r = safe_sqrt((1.0 - z) * (1.0 + z));
    let (s, c) = sin_cos_turns(u.y);
    Vec3::new(r * c, r * s, z)
}

/// The solid-angle density of [`uniform_hemisphere`], `1 / (2π)`, for directions with
/// `z ≥ 0` (PBR 4th ed., §A.5).
#[inline(always)]
#[must_use]
pub fn uniform_hemisphere_pdf() -> f32 {
    INV_2PI
}

/// The inverse of [`uniform_hemisphere`]: `(z, φ / 2π)` with `φ ∈ [0, 2π)`.
///
/// Precondition: `w` is a unit vector with `w.z ≥ 0`; the result is in `[0, 1]²`.
#[inline(always)]
#[must_use]
pub fn uniform_hemisphere_inverse(w: Vec3) -> Vec2 {
    Vec2::new(w.z.clamp(0.0, 1.0), turn_fraction(w.y, w.x))
}

/// A direction uniformly distributed on the unit sphere.
///
/// PBR 4th ed., §A.5: `z = 1 − 2u.x`, `φ = 2π u.y`, `sin θ = 2√(u.x (1 − u.x))`
/// (that is `√(1 − z²)` factored so it keeps its digits near the poles).
/// Precondition: `u ∈ [0, 1]²`.
#[inline(always)]
#[must_use]
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = 2.0 * safe_sqrt(u.x * (1.0 - u.x));
    let (s, c) = sin_cos_turns(u.y);
    Vec3::new(r * c, r * s, z)
}

/// The solid-angle density of [`uniform_sphere`], `1 / (4π)` (PBR 4th ed., §A.5).
#[inline(always)]
#[must_use]
pub fn uniform_sphere_pdf() -> f32 {
    INV_4PI
}

/// The inverse of [`uniform_sphere`]: `((1 − z) / 2, φ / 2π)` with `φ ∈ [0, 2π)`.
///
/// Precondition: `w` is a unit vector; the result is in `[0, 1]²`.
#[inline(always)]
#[must_use]
pub fn uniform_sphere_inverse(w: Vec3) -> Vec2 {
    Vec2::new((0.5 * (1.0 - w.z)).clamp(0.0, 1.0), turn_fraction(w.y, w.x))
}

/// A direction uniformly distributed over the cone of directions within angle
/// `θ_max = acos(cos_theta_max)` of `+z`.
///
/// PBR 4th ed., §A.5: `cos θ = 1 − u.x (1 − cos θ_max)`, `φ = 2π u.y`; `sin θ` is
/// computed as `√((1 − cos θ)(1 + cos θ))` so that narrow cones keep their digits.
/// Precondition: `u ∈ [0, 1]²` and `cos_theta_max ∈ [−1, 1]` (`−1` is the whole sphere,
/// `1` the single direction `+z`).
#[inline(always)]
#[must_use]
pub fn uniform_cone(u: Vec2, cos_theta_max: f32) -> Vec3 {
    uniform_cone_of_width(u, 1.0 - cos_theta_max)
}

/// [`uniform_cone`] for the cone given by its width `w = 1 − cos θ_max`, which a narrow cone
/// keeps to full precision where `cos θ_max` rounds toward 1: a sphere of radius `r` seen from
/// distance `d` subtends `w = s / (1 + √(1 − s))` with `s = r²/d²` (below `r/d ≈ 1.7e-4`, the
/// `f32` cosine is exactly 1 and the cone would be lost).
///
/// `cos θ = 1 − u.x w`, `sin θ = √(u.x w (2 − u.x w))`, `φ = 2π u.y`. Precondition:
/// `u ∈ [0, 1]²` and `w ∈ [0, 2]`.
#[inline(always)]
#[must_use]
pub fn uniform_cone_of_width(u: Vec2, width: f32) -> Vec3 {
    let one_minus_cos = u.x * width;
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = safe_sqrt(one_minus_cos * (2.0 - one_minus_cos));
    let (s, c) = sin_cos_turns(u.y);
    Vec3::new(sin_theta * c, sin_theta * s, cos_theta)
}

/// The solid-angle density of [`uniform_cone`] inside the cone, `1 / (2π (1 − cos θ_max))`
/// (PBR 4th ed., §A.5).
///
/// The cone of `cos_theta_max = 1` is a single direction, and its density is `+∞` (a delta);
/// [`balance_heuristic`] and [`power_heuristic`] accept that. Precondition:
/// `cos_theta_max ∈ [−1, 1]`.
#[inline(always)]
#[must_use]
pub fn uniform_cone_pdf(cos_theta_max: f32) -> f32 {
    uniform_cone_pdf_of_width(1.0 - cos_theta_max)
}

/// The density of [`uniform_cone_of_width`] inside the cone, `1 / (2π w)`; `+∞` for `w = 0`.
/// Precondition: `w ∈ [0, 2]`.
#[inline(always)]
#[must_use]
pub fn uniform_cone_pdf_of_width(width: f32) -> f32 {
    INV_2PI / width
}

/// The inverse of [`uniform_cone`]: `((1 − cos θ) / (1 − cos θ_max), φ / 2π)`.
///
/// Precondition: `w` is a unit vector inside the cone and `cos_theta_max ∈ [−1, 1]`; the
/// result is in `[0, 1]²`. For the degenerate cone `cos_theta_max = 1`, whose every `u`
/// gives `+z`, the first coordinate is `0`.
#[inline(always)]
#[must_use]
pub fn uniform_cone_inverse(w: Vec3, cos_theta_max: f32) -> Vec2 {
    let width = 1.0 - cos_theta_max;
    let ux = if width > 0.0 {
        ((1.0 - w.z) / width).clamp(0.0, 1.0)
    } else {
        0.0
    };
    Vec2::new(ux, turn_fraction(w.y, w.x))
}

/// The weighted densities `(nf f_pdf, ng g_pdf)` as a ratio `(ng g_pdf) / (nf f_pdf)`, or the
/// weight itself where that ratio is not a number.
#[inline(always)]
fn mis_ratio(nf: f32, f_pdf: f32, ng: f32, g_pdf: f32) -> Result<f32, f32> {
    let f = nf * f_pdf;
    // `0 · ∞` (a strategy that takes no samples) carries no weight.
    let g = ng * g_pdf;
    let g = if g.is_nan() { 0.0 } else { g };
    if f == f32::INFINITY {
        // A delta strategy against another delta strategy: neither dominates.
        return Err(if g == f32::INFINITY { 0.5 } else { 1.0 });
    }
    if g == f32::INFINITY || f.is_nan() || f <= 0.0 {
        return Err(0.0);
    }
    // A ratio rather than f / (f + g): no overflow for large finite densities.
    Ok(g / f)
}

/// The balance heuristic weight of a sample drawn from strategy `f`, when `nf` samples come
/// from `f` and `ng` from `g`: `nf p_f / (nf p_f + ng p_g)` (Veach 1997, §9.2).
///
/// Total: `0` when `nf p_f = 0` (including both densities `0`), `1` when `nf p_f` is
/// infinite (a delta strategy) and `ng p_g` is not, `0` in the opposite case, and `½` when
/// both are infinite. Precondition: non-negative, non-NaN arguments.
#[inline(always)]
#[must_use]
pub fn balance_heuristic(nf: f32, f_pdf: f32, ng: f32, g_pdf: f32) -> f32 {
    match mis_ratio(nf, f_pdf, ng, g_pdf) {
        Ok(r) => 1.0 / (1.0 + r),
        Err(w) => w,
    }
}

/// The power heuristic weight (exponent β = 2) of a sample drawn from strategy `f`:
/// `(nf p_f)² / ((nf p_f)² + (ng p_g)²)` (Veach 1997, §9.2).
///
/// Total, with the same conventions as [`balance_heuristic`]: `0` when `nf p_f = 0`, `1` for
/// an infinite `nf p_f` against a finite `ng p_g`, `0` in the opposite case, `½` when both
/// are infinite. Precondition: non-negative, non-NaN arguments.
#[inline(always)]
#[must_use]
pub fn power_heuristic(nf: f32, f_pdf: f32, ng: f32, g_pdf: f32) -> f32 {
    match mis_ratio(nf, f_pdf, ng, g_pdf) {
        Ok(r) => 1.0 / (1.0 + r * r),
        Err(w) => w,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid over the closed unit square, corners and edges included.
    fn grid(n: usize) -> impl Iterator<Item = Vec2> {
        (0..=n).flat_map(move |i| {
            (0..=n).map(move |j| Vec2::new(i as f32 / n as f32, j as f32 / n as f32))
        })
    }

    /// The distance between two points of the square, with the second coordinate periodic
    /// (`φ = 0` and `φ = 2π` are the same direction).
    fn periodic_distance(a: Vec2, b: Vec2) -> f32 {
        let dy = (a.y - b.y).abs();
        Vec2::new(a.x - b.x, dy.min(1.0 - dy)).length()
    }

    fn assert_unit(w: Vec3, u: Vec2) {
        assert!(w.is_finite(), "non-finite direction {w} for u = {u}");
        assert!(
            (w.length() - 1.0).abs() < 2e-6,
            "|w| = {} for u = {u}",
            w.length()
        );
    }

    #[test]
    fn concentric_map_lands_in_disk_and_inverts() {
        for u in grid(64) {
            let p = square_to_disk_concentric(u);
            assert!(p.is_finite() && p.length() <= 1.0 + 1e-6, "u = {u} → {p}");
            let back = disk_to_square_concentric(p);
            assert!((back - u).length() < 2e-6, "u = {u} → {p} → {back}");
        }
    }

    #[test]
    fn concentric_map_sends_the_square_boundary_to_the_circle() {
        // Shirley & Chiu: the square ring max(|a|, |b|) = r maps to the circle of radius r.
        for i in 0..=32 {
            let t = i as f32 / 32.0;
            for u in [
                Vec2::new(t, 0.0),
                Vec2::new(t, 1.0),
                Vec2::new(0.0, t),
                Vec2::new(1.0, t),
            ] {
                assert!((square_to_disk_concentric(u).length() - 1.0).abs() < 1e-6);
            }
            let ring = Vec2::new(0.5 + 0.25 * (2.0 * t - 1.0), 0.75); // max(|a|, |b|) = 0.5
            assert!((square_to_disk_concentric(ring).length() - 0.5).abs() < 1e-6);
        }
        assert_eq!(square_to_disk_concentric(Vec2::splat(0.5)), Vec2::ZERO);
        assert_eq!(disk_to_square_concentric(Vec2::ZERO), Vec2::splat(0.5));
        // The right edge midpoint goes to (1, 0), the top edge midpoint to (0, 1).
        assert!((square_to_disk_concentric(Vec2::new(1.0, 0.5)) - Vec2::X).length() < 1e-6);
        assert!((square_to_disk_concentric(Vec2::new(0.5, 1.0)) - Vec2::Y).length() < 1e-6);
    }

    #[test]
    fn cosine_hemisphere_is_unit_upper_and_inverts() {
        for u in grid(64) {
            let w = cosine_hemisphere(u);
            assert_unit(w, u);
            assert!(w.z >= 0.0);
            let back = cosine_hemisphere_inverse(w);
            assert!((back - u).length() < 2e-6, "u = {u} → {w} → {back}");
        }
        assert_eq!(cosine_hemisphere(Vec2::splat(0.5)), Vec3::Z);
    }

    #[test]
    fn cosine_hemisphere_pdf_values() {
        assert!((f64::from(cosine_hemisphere_pdf(1.0)) - 1.0 / core::f64::consts::PI).abs() < 3e-8);
        assert!((cosine_hemisphere_pdf(0.5) - 0.159_154_94).abs() < 1e-7);
        assert_eq!(cosine_hemisphere_pdf(0.0), 0.0);
        assert_eq!(cosine_hemisphere_pdf(-0.3), 0.0);
    }

    #[test]
    fn uniform_hemisphere_is_unit_upper_and_inverts() {
        for u in grid(64) {
            let w = uniform_hemisphere(u);
            assert_unit(w, u);
            assert!(w.z >= 0.0);
            assert!((w.z - u.x).abs() < 1e-7, "z follows u.x");
            if u.x < 1.0 {
                let back = uniform_hemisphere_inverse(w);
                assert!(periodic_distance(back, u) < 2e-6, "u = {u} → {w} → {back}");
            }
        }
        assert!((uniform_hemisphere_pdf() - 0.159_154_94).abs() < 1e-8);
    }

    #[test]
    fn uniform_sphere_is_unit_and_inverts() {
        for u in grid(64) {
            let w = uniform_sphere(u);
            assert_unit(w, u);
            assert!((w.z - (1.0 - 2.0 * u.x)).abs() < 1e-7);
            if u.x > 0.0 && u.x < 1.0 {
                let back = uniform_sphere_inverse(w);
                assert!(periodic_distance(back, u) < 2e-6, "u = {u} → {w} → {back}");
            }
        }
        assert!((uniform_sphere_pdf() - 0.079_577_47).abs() < 1e-8);
        assert_eq!(uniform_sphere(Vec2::ZERO), Vec3::Z);
        assert_eq!(uniform_sphere(Vec2::new(1.0, 0.0)), -Vec3::Z);
    }

    #[test]
    fn uniform_cone_stays_in_the_cone_and_inverts() {
        for cos_max in [-1.0_f32, -0.4, 0.0, 0.5, 0.99, 0.999_999, 1.0] {
            for u in grid(48) {
                let w = uniform_cone(u, cos_max);
                assert_unit(w, u);
                assert!(
                    w.z >= cos_max - 1e-6 && w.z <= 1.0,
                    "z = {} outside cone {cos_max}",
                    w.z
                );
                let back = uniform_cone_inverse(w, cos_max);
                assert!(
                    back.is_finite() && back.cmpge(Vec2::ZERO).all() && back.cmple(Vec2::ONE).all()
                );
                // The inverse is well conditioned where the cone has width and u.x > 0.
                // (u.x = 1 with cos θmax = −1 is the pole −z, where φ is lost.)
                let pole = cos_max == -1.0 && u.x == 1.0;
                if cos_max < 0.99 && u.x > 0.0 && !pole {
                    assert!(
                        periodic_distance(back, u) < 4e-6,
                        "cos_max {cos_max}: {u} → {back}"
                    );
                }
            }
        }
        // The rim is reached at u.x = 1.
        assert!((uniform_cone(Vec2::new(1.0, 0.3), 0.5).z - 0.5).abs() < 1e-6);
        // A narrow cone keeps its angle: θ_max = 1e-3 rad, sin θ_max ≈ 1e-3.
        let cos_max = 0.999_999_5_f32;
        let rim = uniform_cone(Vec2::new(1.0, 0.0), cos_max);
        let expect = (2.0 * (1.0 - f64::from(cos_max))).sqrt();
        assert!((f64::from(rim.x) - expect).abs() < 1e-3 * expect);
    }

    #[test]
    fn uniform_cone_pdf_values() {
        assert!((uniform_cone_pdf(-1.0) - uniform_sphere_pdf()).abs() < 1e-8);
        assert!((uniform_cone_pdf(0.0) - uniform_hemisphere_pdf()).abs() < 1e-8);
        // 1 / (2π · 0.5) = 1/π.
        assert!((f64::from(uniform_cone_pdf(0.5)) - 1.0 / core::f64::consts::PI).abs() < 3e-8);
        assert_eq!(uniform_cone_pdf(1.0), f32::INFINITY);
    }

    #[test]
    fn warps_are_total_at_the_edges() {
        // Values at and next to the corners, edges and centre lines of the square.
        let edge = [
            0.0,
            1e-30,
            1e-7,
            0.5 - 3e-8,
            0.5,
            0.5 + 3e-8,
            1.0 - 6e-8,
            1.0,
        ];
        for &x in &edge {
            for &y in &edge {
                let u = Vec2::new(x, y);
                let d = square_to_disk_concentric(u);
                assert!(d.is_finite() && d.length() <= 1.0 + 1e-6, "{u} → {d}");
                let back = disk_to_square_concentric(d);
                assert!((back - u).length() < 4e-6, "{u} → {d} → {back}");
                for w in [
                    cosine_hemisphere(u),
                    uniform_hemisphere(u),
                    uniform_sphere(u),
                    uniform_cone(u, 0.7),
                    uniform_cone(u, -1.0),
                    uniform_cone(u, 1.0),
                ] {
                    assert_unit(w, u);
                }
            }
        }
    }

    #[test]
    fn inverses_are_total_on_edges() {
        for w in [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            -Vec3::Y,
            Vec3::new(0.0, -0.0, 1.0),
        ] {
            for u in [
                cosine_hemisphere_inverse(w),
                uniform_hemisphere_inverse(w),
                uniform_sphere_inverse(w),
                uniform_cone_inverse(w, 0.3),
                uniform_cone_inverse(w, 1.0),
            ] {
                assert!(u.is_finite() && u.cmpge(Vec2::ZERO).all() && u.cmple(Vec2::ONE).all());
            }
        }
    }

    #[test]
    fn heuristics_match_definitions() {
        // nf = 1, p_f = 2; ng = 3, p_g = 1: balance 2 / (2 + 3), power 4 / (4 + 9).
        assert!((balance_heuristic(1.0, 2.0, 3.0, 1.0) - 0.4).abs() < 1e-7);
        assert!((power_heuristic(1.0, 2.0, 3.0, 1.0) - 4.0 / 13.0).abs() < 1e-7);
        // The weights of the two strategies sum to one.
        for (pf, pg) in [(0.1_f32, 7.0_f32), (3.0, 3.0), (1e-30, 1e30), (1e30, 1e30)] {
            let b = balance_heuristic(1.0, pf, 1.0, pg) + balance_heuristic(1.0, pg, 1.0, pf);
            let p = power_heuristic(1.0, pf, 1.0, pg) + power_heuristic(1.0, pg, 1.0, pf);
            assert!(
                (b - 1.0).abs() < 1e-6 && (p - 1.0).abs() < 1e-6,
                "{pf} {pg}: {b} {p}"
            );
        }
    }

    #[test]
    fn heuristics_are_total() {
        for h in [balance_heuristic, power_heuristic] {
            assert_eq!(h(1.0, 0.0, 1.0, 0.0), 0.0);
            assert_eq!(h(1.0, 0.0, 1.0, 2.0), 0.0);
            assert_eq!(h(1.0, 2.0, 1.0, 0.0), 1.0);
            assert_eq!(h(1.0, f32::INFINITY, 1.0, 5.0), 1.0);
            assert_eq!(h(1.0, 5.0, 1.0, f32::INFINITY), 0.0);
            assert_eq!(h(1.0, f32::INFINITY, 1.0, f32::INFINITY), 0.5);
            assert_eq!(h(0.0, 5.0, 1.0, 5.0), 0.0);
            assert_eq!(h(1.0, 5.0, 0.0, f32::INFINITY), 1.0);
            // Large finite densities overflow neither the sum nor the squares.
            let w = h(1.0, 3e38, 1.0, 3e38);
            assert!((w - 0.5).abs() < 1e-6, "{w}");
        }
    }
}
