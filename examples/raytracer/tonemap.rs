//! From linear radiance to display pixels: exposure, a filmic curve, sRGB encoding.

use lobe::Vec3;

/// Narkowicz's fit of the ACES filmic tone curve (2015, "ACES Filmic Tone Mapping Curve"):
/// maps `[0, ∞)` to `[0, 1]` per channel (clamped at 1, which it reaches near 7.24), with a
/// gentle shoulder.
#[inline]
pub fn aces(x: Vec3) -> Vec3 {
    let x = x.max(Vec3::ZERO);
    let (a, b, c, d, e) = (2.51, 0.03, 2.43, 0.59, 0.14);
    ((x * (a * x + b)) / (x * (c * x + d) + e)).clamp(Vec3::ZERO, Vec3::ONE)
}

/// The sRGB transfer function (IEC 61966-2-1) of a linear value in `[0, 1]`.
#[inline]
pub fn srgb_encode(v: f32) -> f32 {
    if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

/// A pixel's 8-bit sRGB bytes: `exposure` scaling, ACES, sRGB, rounding. Non-finite input
/// gives black.
pub fn to_srgb8(linear: Vec3, exposure: f32) -> [u8; 3] {
    let v = if linear.is_finite() {
        linear
    } else {
        Vec3::ZERO
    };
    let t = aces(v * exposure);
    let q = |c: f32| (srgb_encode(c) * 255.0 + 0.5).clamp(0.0, 255.0) as u8;
    [q(t.x), q(t.y), q(t.z)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curve_is_monotone_and_bounded() {
        let mut last = -1.0;
        for i in 0..200 {
            let y = aces(Vec3::splat(i as f32 * 0.1)).x;
            assert!((0.0..=1.0).contains(&y) && y >= last);
            last = y;
        }
        assert_eq!(to_srgb8(Vec3::ZERO, 1.0), [0, 0, 0]);
        assert_eq!(to_srgb8(Vec3::splat(1e6), 1.0), [255, 255, 255]);
        assert_eq!(to_srgb8(Vec3::NAN, 1.0), [0, 0, 0]);
        assert!((srgb_encode(0.5) - 0.735_356_6).abs() < 1e-5);
    }
}
