//! The shading frame is orthonormal and right-handed, and reflect/refract obey the laws of
//! reflection and Snell's law.

mod common;

use lobe::frame::{reflect_about, reflect_away, refract_away};
use lobe::{Eta, Frame, Vec3};
use proptest::prelude::*;

/// Unit directions: uniform on the sphere, plus the poles and points within 1e-6 of them.
fn unit_vector() -> impl Strategy<Value = Vec3> {
    let uniform = (-1.0f32..=1.0, 0.0f32..core::f32::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    });
    let near_pole = (-1e-6f32..1e-6, -1e-6f32..1e-6, prop::bool::ANY)
        .prop_map(|(x, y, up)| Vec3::new(x, y, if up { 1.0 } else { -1.0 }).normalize());
    prop_oneof![
        4 => uniform,
        2 => near_pole,
        1 => Just(Vec3::Z),
        1 => Just(-Vec3::Z),
    ]
}

fn eta() -> impl Strategy<Value = Eta> {
    (-3.0f32..3.0).prop_map(|e| Eta::new(10f32.powf(e)).unwrap())
}

proptest! {
    #![proptest_config(common::proptest_config(4096))]

    #[test]
    fn frame_is_orthonormal_and_right_handed(n in unit_vector()) {
        let f = Frame::from_normal(n);
        for (name, v) in [("x", f.x), ("y", f.y), ("z", f.z)] {
            prop_assert!((v.length() - 1.0).abs() < 1e-5, "|{}| = {}", name, v.length());
        }
        prop_assert!(f.x.dot(f.y).abs() < 1e-5);
        prop_assert!(f.x.dot(f.z).abs() < 1e-5);
        prop_assert!(f.y.dot(f.z).abs() < 1e-5);
        prop_assert!((f.x.cross(f.y) - f.z).length() < 1e-5, "not right-handed: x × y = {:?}", f.x.cross(f.y));
    }

    #[test]
    fn frame_round_trips(n in unit_vector(), v in unit_vector()) {
        let f = Frame::from_normal(n);
        let local = f.to_local(v);
        prop_assert!((f.to_world(local) - v).length() < 2e-6);
        prop_assert!((local.z - n.dot(v)).abs() < 2e-6);
        prop_assert!((local.length() - 1.0).abs() < 2e-6);
    }

    #[test]
    fn reflection_keeps_the_angle_and_the_plane(n in unit_vector(), w in unit_vector()) {
        let r = reflect_away(w, n);
        prop_assert!((r.length() - 1.0).abs() < 1e-5);
        prop_assert!((r.dot(n) - w.dot(n)).abs() < 1e-5);
        // Coplanar with w and n, and w + r lies along n.
        prop_assert!(((w + r).cross(n)).length() < 1e-5);
    }

    #[test]
    fn reflection_about_any_length_is_the_reflection_about_the_unit_normal(
        n in unit_vector(), w in unit_vector(), scale in -20.0f32..20.0,
    ) {
        // n scaled by 2^scale: the direction is reflected about the same line, to a few ulps
        // of the f64 reflection about it.
        let s = n * scale.exp2();
        let r = reflect_about(w, s);
        let f64s = |v: Vec3| [v.x as f64, v.y as f64, v.z as f64];
        let (w64, s64, r64) = (f64s(w), f64s(s), f64s(r));
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let k = 2.0 * dot(w64, s64) / dot(s64, s64);
        let error = (0..3).map(|i| (r64[i] - (k * s64[i] - w64[i])).powi(2)).sum::<f64>().sqrt();
        prop_assert!(error < 1e-6, "{:?}: {} from the reflection", r, error);
        prop_assert!((r - reflect_away(w, n)).length() < 2e-6);
    }

    #[test]
    fn refraction_obeys_snell_and_inverts(w in unit_vector(), eta in eta()) {
        let n = Vec3::Z;
        let cos_i = w.z;
        // η_i / η_t for this side.
        let eta_it = if cos_i >= 0.0 { 1.0 / eta.get() } else { eta.get() };
        // sin θ from the tangential components, which keep their digits near the normal.
        let sin = |v: Vec3| (v.x as f64).hypot(v.y as f64);
        let sin2_t = (eta_it as f64 * sin(w)).powi(2);
        match refract_away(w, n, eta) {
            None => prop_assert!(sin2_t > 1.0 - 1e-5, "no refraction though sin²θt = {}", sin2_t),
            Some(t) => {
                prop_assert!(sin2_t <= 1.0 + 1e-5, "refracted though sin²θt = {}", sin2_t);
                prop_assert!((t.length() - 1.0).abs() < 1e-4, "|t| = {}", t.length());
                // The transmitted direction is on the other side (or in the plane at grazing).
                prop_assert!(t.z * cos_i <= 1e-6);
                // Snell: η_i sin θ_i = η_t sin θ_t, and the plane of incidence is kept.
                let (sin_i, sin_t) = (sin(w), sin(t));
                // f32 keeps sin θ's relative precision (the tangential components are scaled,
                // not cancelled), so both sides agree to a few ulps of the larger.
                let (lhs, rhs) = (eta_it as f64 * sin_i, sin_t);
                prop_assert!((lhs - rhs).abs() <= 1e-6 * lhs.max(rhs) + 1e-12, "Snell: {} vs {}", lhs, rhs);
                prop_assert!((w.x * t.y - w.y * t.x).abs() <= 1e-6 * sin_i.max(1e-12) as f32 + 1e-12);
                // Refracting back returns the original direction. The way back has
                // sin²θ = sin²θ_i, so skip w within 2° of grazing, where it is itself at the
                // edge of total internal reflection and f32 cannot decide.
                if cos_i.abs() > 0.035 && t.z.abs() > 1e-3 {
                    let back = refract_away(t, n, eta).expect("the way back never reflects totally");
                    // The vector form adds terms of size η' = η_i/η_t that cancel to a unit
                    // vector, so each refraction's absolute error is a few ε·(1 + η'); the
                    // way back uses 1/η'. cos θ = √(1 − sin²θ) then amplifies an error in
                    // sin θ by tan θ (at most 1/0.035 here).
                    let eta_max = eta_it.max(1.0 / eta_it);
                    let bound = 4.0 * f32::EPSILON * (1.0 + eta_max) * (1.0 + sin_i as f32 / cos_i.abs());
                    prop_assert!((back - w).length() < bound, "back = {:?}, w = {:?}, |Δ| = {}", back, w, (back - w).length());
                }
            }
        }
    }
}

#[test]
fn total_internal_reflection_exactly_past_the_critical_angle() {
    // Glass to air: critical angle asin(1/1.5) = 41.81°.
    let eta = Eta::new(1.5).unwrap();
    let critical = (1.0f32 / 1.5).asin();
    for (theta, tir) in [
        (critical - 1e-3, false),
        (critical + 1e-3, true),
        (1.2, true),
        (0.3, false),
    ] {
        let w = Vec3::new(theta.sin(), 0.0, -theta.cos()); // inside the glass
        assert_eq!(refract_away(w, Vec3::Z, eta).is_none(), tir, "θ = {theta}");
    }
    // From the outside there is never total internal reflection into a denser medium.
    for theta in [0.0f32, 0.7, 1.5, core::f32::consts::FRAC_PI_2 - 1e-6] {
        let w = Vec3::new(theta.sin(), 0.0, theta.cos());
        assert!(refract_away(w, Vec3::Z, eta).is_some());
    }
    // Normal incidence goes straight through.
    let t = refract_away(Vec3::Z, Vec3::Z, eta).unwrap();
    assert!((t + Vec3::Z).length() < 1e-6);
}

/// `refract_away` against an f64 refraction of the same (normalised) `f32` direction, at
/// incidence from normal to 1e-7 of grazing, from both sides, for indices near 1 and far from
/// it. The bound is the forward error of `cos θ_t = √(cos² θ_i + (1 − η'²) sin² θ_i)`: a few
/// ulps of each term, divided by `2 cos θ_t` (its conditioning near the critical angle).
#[test]
fn refraction_keeps_its_digits_at_grazing_incidence() {
    let eps = f64::from(f32::EPSILON);
    let mut worst = 0.0f64;
    for eta in [1.0f32, 1.0001, 0.9999, 1.5, 1.0 / 1.5, 2.4, 1e-3, 1e3] {
        let eta_p = Eta::new(eta).unwrap();
        for k in 0..=140 {
            let c = 10f64.powf(-7.0 * f64::from(k) / 140.0);
            for (phi, side) in [(0.3f64, 1.0f64), (2.0, -1.0), (4.4, 1.0), (5.9, -1.0)] {
                let s = (1.0 - c * c).sqrt();
                let w = Vec3::new(
                    (s * phi.cos()) as f32,
                    (s * phi.sin()) as f32,
                    (side * c) as f32,
                )
                .normalize();
                // The reference: the same f32 direction, normalised in f64.
                let w64 = [f64::from(w.x), f64::from(w.y), f64::from(w.z)];
                let len = (w64[0] * w64[0] + w64[1] * w64[1] + w64[2] * w64[2]).sqrt();
                let (wx, wy, wz) = (w64[0] / len, w64[1] / len, w64[2] / len);
                let eta_it = if wz >= 0.0 {
                    1.0 / f64::from(eta)
                } else {
                    f64::from(eta)
                };
                let cos2_t = 1.0 - eta_it * eta_it * (1.0 - wz * wz);
                let t = refract_away(w, Vec3::Z, eta_p);
                // Total internal reflection is decided within the rounding of cos² θ_t.
                let decided = cos2_t.abs() > 8.0 * eps * (1.0 + eta_it * eta_it);
                if !decided {
                    continue;
                }
                assert_eq!(
                    t.is_none(),
                    cos2_t < 0.0,
                    "η {eta} cos θ {wz:e}: cos² θt = {cos2_t:e}"
                );
                let Some(t) = t else { continue };
                let cos_t = cos2_t.sqrt();
                let tz = -wz.signum() * cos_t;
                let bound_z = 8.0
                    * eps
                    * ((1.0 - eta_it * eta_it).abs() * (1.0 - wz * wz) + wz * wz + cos2_t)
                    / cos_t;
                let err_z = (f64::from(t.z) - tz).abs();
                assert!(
                    err_z <= bound_z,
                    "η {eta} cos θ {wz:e}: t.z {} vs {tz:e} (bound {bound_z:e})",
                    t.z
                );
                worst = worst.max(err_z / bound_z);
                for (got, want) in [(t.x, -eta_it * wx), (t.y, -eta_it * wy)] {
                    let err = (f64::from(got) - want).abs();
                    assert!(
                        err <= 4.0 * eps * want.abs() + 1e-300,
                        "η {eta} cos θ {wz:e}: {got} vs {want:e}"
                    );
                }
            }
        }
    }
    println!("worst error / bound of cos θt: {worst:.3}");
}

/// A tangent within 1e-2 to 1.1e-6 rad of the normal still gives an orthonormal frame: one
/// Gram-Schmidt pass cancels there (its error grows as ε / angle, 0.13 at 1e-6 rad).
#[test]
fn a_nearly_parallel_tangent_gives_an_orthonormal_frame() {
    let n = Vec3::new(0.36, 0.48, 0.8);
    let (u, v) = {
        let f = Frame::from_normal(n);
        (f.x, f.y)
    };
    let mut worst = 0.0f32;
    for angle in [1e-2f32, 1e-3, 1e-4, 1e-5, 3e-6, 1.1e-6] {
        for k in 0..64 {
            let phi = k as f32 * 0.098;
            let t = n + angle * (phi.cos() * u + phi.sin() * v);
            let f = Frame::from_normal_tangent(n, t * 3.0);
            let err = [
                f.x.dot(n).abs(),
                f.y.dot(n).abs(),
                f.x.dot(f.y).abs(),
                (f.x.length() - 1.0).abs(),
                (f.y.length() - 1.0).abs(),
            ]
            .into_iter()
            .fold(0.0f32, f32::max);
            worst = worst.max(err);
            assert!(
                err <= 4.0 * f32::EPSILON,
                "angle {angle} φ {phi}: error {err:e}"
            );
            // x still follows the tangent's direction away from n.
            assert!(
                f.x.dot(phi.cos() * u + phi.sin() * v) > 0.99,
                "angle {angle} φ {phi}"
            );
        }
    }
    println!("worst orthonormality error: {worst:e}");
}
