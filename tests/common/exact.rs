//! The laws a model obeys exactly, with no statistics: bit-exact reciprocity of a formula that
//! is symmetric term by term, one-sidedness (nothing below or on the horizon), and totality at
//! grazing and at the edges of the sampler's unit square. Shared by the model files that
//! assert them, so that each law is written once.

use lobe::bxdf::{Bxdf, Lobes};
use lobe::sampling::{cosine_hemisphere, uniform_hemisphere};
use lobe::verify::Pcg32;
use lobe::{Vec2, Vec3};

/// `n` pairs `(wo, wi)` drawn from `rng`: `wo` cosine-distributed, `wi` uniform, both above the
/// surface.
pub fn hemisphere_pairs(rng: &mut Pcg32, n: usize) -> Vec<(Vec3, Vec3)> {
    (0..n)
        .map(|_| {
            let wo = cosine_hemisphere(rng.next_vec2());
            let wi = uniform_hemisphere(rng.next_vec2());
            (wo, wi)
        })
        .collect()
}

/// 2 000 pairs near a lobe of exponent `p`: `wo` uniform on the hemisphere (from
/// `Pcg32::new(5, 0)`), `wi = to_wi(wo, d)` for an offset `d` uniform in a square of side
/// `2/√p`; the pairs with both directions above the surface. Random pairs rarely land in a
/// narrow lobe; these do.
pub fn near_lobe_pairs(p: f32, to_wi: impl Fn(Vec3, Vec2) -> Vec3) -> Vec<(Vec3, Vec3)> {
    let mut rng = Pcg32::new(5, 0);
    let spread = 2.0 / p.sqrt();
    (0..2_000)
        .map(|_| {
            let wo = uniform_hemisphere(rng.next_vec2());
            let d = (rng.next_vec2() - 0.5) * spread;
            (wo, to_wi(wo, d))
        })
        .filter(|(wo, wi)| wo.z > 0.0 && wi.z > 0.0)
        .collect()
}

/// **Bit-exact reciprocity**: `f(wo, wi)` and `f(wi, wo)` have the same bits for every pair,
/// as a formula symmetric term by term must give; with `in_lobe`, both are also positive, so
/// that the pairs test the lobe and not its zeros.
pub fn assert_reciprocity_bit_exact<B: Bxdf<Spectrum = f32> + ?Sized>(
    name: &str,
    bxdf: &B,
    pairs: &[(Vec3, Vec3)],
    in_lobe: bool,
) {
    for &(wo, wi) in pairs {
        let (f, b) = (bxdf.eval(wo, wi), bxdf.eval(wi, wo));
        assert!(
            f.to_bits() == b.to_bits() && (!in_lobe || f > 0.0),
            "{name}: f({wo}, {wi}) = {f}, reversed {b}"
        );
    }
}

/// Directions exactly on the horizon: along the axes and at an azimuth of one radian.
fn horizon() -> [Vec3; 3] {
    [Vec3::X, Vec3::Y, Vec3::new(1f32.cos(), 1f32.sin(), 0.0)]
}

/// **One-sidedness** of a reflector: given a pair with `f(wo, wi) > 0`, `eval` and `pdf` are
/// exactly zero when either direction is flipped below the surface or lies on the horizon,
/// and `sample` gives nothing for a viewer below the surface or on the horizon.
pub fn assert_one_sided<B: Bxdf<Spectrum = f32> + ?Sized>(
    name: &str,
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
) {
    assert!(
        bxdf.eval(wo, wi) > 0.0,
        "{name}: f({wo}, {wi}) must be in the lobe"
    );
    let mut pairs = vec![(wo, -wi), (-wo, wi), (-wo, -wi)];
    for h in horizon() {
        pairs.extend([(h, wi), (wo, h)]);
    }
    for (a, b) in pairs {
        assert_eq!(bxdf.eval(a, b), 0.0, "{name}: f({a}, {b})");
        assert_eq!(bxdf.pdf(a, b), 0.0, "{name}: pdf({a}, {b})");
    }
    for below in [-wo].into_iter().chain(horizon()) {
        for uc in [0.0, 0.5] {
            let s = bxdf.sample(below, Vec2::splat(0.5), uc);
            assert!(s.is_none(), "{name}: sample({below}) = {s:?}");
        }
    }
}

/// The direction at `cos θ = z` and azimuth `phi`: near the horizon for a tiny `z`.
pub fn graze(z: f32, phi: f32) -> Vec3 {
    let r = (1.0 - z * z).sqrt();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// **Totality at grazing** of a diffuse reflector: for `cos θ` down to the smallest subnormal,
/// both directions grazing (the same, apart, or one at the normal or at 60°) and both orders,
/// `eval` is finite and non-negative, and a sample drawn there has a finite value and weight.
pub fn assert_total_at_grazing<B: Bxdf<Spectrum = f32> + ?Sized>(name: &str, bxdf: &B) {
    for z in [1e-7f32, 1e-20, 1e-38, 1e-45] {
        for (wo, wi) in [
            (graze(z, 0.0), graze(z, 0.0)),
            (graze(z, 0.0), graze(z, 3.0)),
            (graze(z, 0.1), Vec3::Z),
            (graze(z, 0.0), graze(0.5, 0.0)),
        ] {
            for (x, y) in [(wo, wi), (wi, wo)] {
                let f = bxdf.eval(x, y);
                assert!(f.is_finite() && f >= 0.0, "{name}: f({x}, {y}) = {f}");
                if let Some(s) = bxdf.sample(x, Vec2::new(0.999, 0.5), 0.0) {
                    assert!(s.f.is_finite() && s.weight().is_finite(), "{name}: {s:?}");
                }
            }
        }
    }
}

/// **Totality at the edges of the unit square**: every sample drawn from each of `viewers`
/// with `u` and `uc` at `0`, `1e-7`, the middle and `1 − 6e-8` is above the surface, finite,
/// with a finite non-negative value, a positive finite pdf and a finite weight.
pub fn assert_edge_samples<B: Bxdf<Spectrum = f32> + ?Sized>(
    name: &str,
    bxdf: &B,
    viewers: &[Vec3],
) {
    let edges = [0.0_f32, 1e-7, 0.5, 1.0 - 6e-8];
    let mut drawn = 0;
    for &wo in viewers {
        for &x in &edges {
            for &y in &edges {
                for uc in [0.0_f32, 0.4, 1.0 - 6e-8] {
                    if let Some(s) = bxdf.sample(wo, Vec2::new(x, y), uc) {
                        assert!(s.wi.z > 0.0 && s.wi.is_finite(), "{name}: {s:?}");
                        assert!(s.f.is_finite() && s.f >= 0.0, "{name}: {s:?}");
                        assert!(s.pdf.is_finite() && s.pdf > 0.0, "{name}: {s:?}");
                        assert!(s.weight().is_finite(), "{name}: {s:?}");
                        drawn += 1;
                    }
                }
            }
        }
    }
    assert!(
        drawn > 0,
        "{name}: no sample drawn at the edges: nothing was checked"
    );
}

/// **Values** against an independent computation: for each `(wo, wi, f, pdf)` (directions
/// normalised here), `eval` and `pdf` are within `rel` of the reference.
pub fn assert_values<B: Bxdf<Spectrum = f32> + ?Sized>(
    name: &str,
    bxdf: &B,
    cases: &[(Vec3, Vec3, f64, f64)],
    rel: f64,
) {
    for &(wo, wi, f, pdf) in cases {
        let (wo, wi) = (wo.normalize(), wi.normalize());
        let (got_f, got_pdf) = (f64::from(bxdf.eval(wo, wi)), f64::from(bxdf.pdf(wo, wi)));
        assert!(
            (got_f - f).abs() <= rel * f,
            "{name}: f({wo}, {wi}) = {got_f}, expected {f}"
        );
        assert!(
            (got_pdf - pdf).abs() <= rel * pdf,
            "{name}: pdf({wo}, {wi}) = {got_pdf}, expected {pdf}"
        );
    }
}

/// The lobes of a diffuse + glossy model are those with weight: `lobes(kd, ks)` reports both
/// lobes, the diffuse alone, the glossy alone, and for a black model the diffuse lobe (which
/// it samples, with `f = 0`).
pub fn assert_lobes_follow_weights(lobes: impl Fn(f32, f32) -> Lobes) {
    assert_eq!(
        lobes(0.5, 0.5),
        Lobes::DIFFUSE_REFLECTION | Lobes::GLOSSY_REFLECTION
    );
    assert_eq!(lobes(0.5, 0.0), Lobes::DIFFUSE_REFLECTION);
    assert_eq!(lobes(0.0, 0.5), Lobes::GLOSSY_REFLECTION);
    assert_eq!(lobes(0.0, 0.0), Lobes::DIFFUSE_REFLECTION);
}

/// The lobe of a diffuse + glossy model follows `uc`: at normal incidence with
/// `u = (0.3, 0.6)`, `uc = diffuse_uc` (below the diffuse probability) samples the diffuse
/// lobe and `uc = glossy_uc` (above it) the glossy one.
pub fn assert_lobe_choice<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    diffuse_uc: f32,
    glossy_uc: f32,
) {
    let u = Vec2::new(0.3, 0.6);
    let lobe = |uc| bxdf.sample(Vec3::Z, u, uc).expect("a sample").lobe;
    assert_eq!(lobe(diffuse_uc), Lobes::DIFFUSE_REFLECTION);
    assert_eq!(lobe(glossy_uc), Lobes::GLOSSY_REFLECTION);
}

/// **Values** of a grey RGB model against an independent computation: every channel of
/// `f(wo, wi)` within `rel` of `want`.
pub fn assert_grey_value<B: Bxdf<Spectrum = Vec3> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    want: f64,
    rel: f64,
) {
    let got = bxdf.eval(wo, wi);
    for c in [got.x, got.y, got.z] {
        assert!(
            ((f64::from(c) - want) / want).abs() < rel,
            "f({wo}, {wi}) = {c}, want {want}"
        );
    }
}

/// A diffuse model's reflectance is validated by name: `mono(ρ)` refuses NaN, negative,
/// above 1 and infinite values, `rgb(ρ)` a NaN in any channel, and both accept 0 and 1.
pub fn assert_reflectance_validated<A, B>(
    mono: impl Fn(f32) -> Result<A, lobe::ParamError>,
    rgb: impl Fn(Vec3) -> Result<B, lobe::ParamError>,
) {
    for rho in [f32::NAN, -0.1, 1.01, f32::INFINITY] {
        let e = mono(rho).err().expect("refused");
        assert_eq!(e.param(), "reflectance", "ρ = {rho}");
    }
    for c in 0..3 {
        let mut rho = Vec3::splat(0.5);
        rho[c] = f32::NAN;
        let e = rgb(rho).err().expect("refused");
        assert_eq!(e.param(), "reflectance", "ρ = {rho}");
    }
    assert!(mono(0.0).is_ok() && mono(1.0).is_ok());
}
