//! [Proptest](mod@proptest) strategies for the inputs of reflectance code: directions
//! (uniform, grazing, near the normal, adversarial), microfacet widths, relative and complex
//! indices of refraction, and the random numbers a sampler takes.
//!
//! Available with the `proptest` feature (which implies `verify`). Each function returns a
//! [`Strategy`], so a downstream property test over a model is one line of arguments:
//!
//! ```
//! use lobe::bxdf::{Bxdf, Microfacet};
//! use lobe::fresnel::Schlick;
//! use lobe::microfacet::{Ggx, Masking};
//! use lobe::verify::strategies::{adversarial_directions, alphas};
//! use proptest::prelude::*;
//!
//! proptest! {
//!     // `#[test]` in a test file; called by hand in this example.
//!     fn ggx_is_total(
//!         wo in adversarial_directions(),
//!         wi in adversarial_directions(),
//!         a in alphas(),
//!     ) {
//!         let fresnel = Schlick::new(0.04_f32).unwrap();
//!         let brdf = Microfacet::new(Ggx::isotropic(a), Masking::HeightCorrelated, fresnel);
//!         let (f, pdf) = (brdf.eval(wo, wi), brdf.pdf(wo, wi));
//!         prop_assert!(f.is_finite() && f >= 0.0, "f = {f}");
//!         prop_assert!(pdf.is_finite() && pdf >= 0.0, "pdf = {pdf}");
//!     }
//! }
//! ggx_is_total();
//! ```
//!
//! Values that are not uniform are drawn log-uniformly over their range, where the numerical
//! trouble lives (a cosine of 1e-6 is as likely as one of 1e-3), and the special values a
//! formula is most likely to get wrong (the exact horizon, the exact normal, `η = 1`, the
//! range ends) are mixed in. Every strategy shrinks toward a simpler case of its own kind: a
//! failing property reports a small counterexample.
//!
//! Directions are unit [`Vec3`]s in the local shading frame (`z` the normal) to within
//! `f32` round-off (`|‖w‖ − 1| < 1e-6`).

use crate::param::{Alpha, ComplexIor, Eta};
use crate::sampling::uniform_sphere;
use core::f64::consts::TAU;
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use proptest::sample::select;
use std::vec;

/// `10^(lo + (hi − lo) u)` for `u ∈ [0, 1]`: log-uniform over `[10^lo, 10^hi]`, shrinking
/// toward `10^lo`.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> + Clone {
    (0.0..=1.0_f64).prop_map(move |u| 10f64.powf(lo + (hi - lo) * u))
}

/// The unit direction with `cos θ = z` and azimuth `phi`, built in `f64` and rounded once.
fn from_cos_phi(z: f64, phi: f64) -> Vec3 {
    let r = ((1.0 - z) * (1.0 + z)).max(0.0).sqrt();
    Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32)
}

/// The unit direction with `sin θ = s` on the side `sign` (`±1`) and azimuth `phi`.
fn from_sin_phi(s: f64, sign: f64, phi: f64) -> Vec3 {
    let z = ((1.0 - s) * (1.0 + s)).max(0.0).sqrt();
    Vec3::new(
        (s * phi.cos()) as f32,
        (s * phi.sin()) as f32,
        (sign * z) as f32,
    )
}

/// An azimuth in `[0, 2π)`.
fn azimuths() -> impl Strategy<Value = f64> + Clone {
    0.0..TAU
}

/// A side of the surface: `+1` (outside, above) or `−1` (inside, below).
fn sides() -> impl Strategy<Value = f64> + Clone {
    any::<bool>().prop_map(|above| if above { 1.0 } else { -1.0 })
}

/// Directions uniformly distributed over the whole sphere, both sides of the surface.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert};
/// use lobe::verify::strategies::directions;
/// use proptest::prelude::*;
///
/// proptest! {
///     fn lambert_is_reciprocal(wo in directions(), wi in directions()) {
///         let brdf = Lambert::new(0.8_f32).unwrap();
///         prop_assert_eq!(brdf.eval(wo, wi), brdf.eval(wi, wo));
///     }
/// }
/// lambert_is_reciprocal();
/// ```
pub fn directions() -> impl Strategy<Value = Vec3> + Clone {
    (0.0..=1.0_f32, 0.0..1.0_f32).prop_map(|(a, b)| uniform_sphere(Vec2::new(a, b)))
}

/// Directions uniformly distributed over the upper hemisphere, strictly above the surface:
/// `cos θ ∈ (0, 1]`. The support of a one-sided BRDF.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert};
/// use lobe::verify::strategies::{unit_f32, unit_vec2, upper_directions};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn lambert_samples_above(wo in upper_directions(), u in unit_vec2(), uc in unit_f32()) {
///         let brdf = Lambert::new(0.8_f32).unwrap();
///         if let Some(s) = brdf.sample(wo, u, uc) {
///             prop_assert!(s.wi.z >= 0.0 && s.pdf > 0.0);
///         }
///     }
/// }
/// lambert_samples_above();
/// ```
pub fn upper_directions() -> impl Strategy<Value = Vec3> + Clone {
    // cos θ = 1 − u, u ∈ [0, 1): uniform in solid angle over (0, 1], shrinking to the normal.
    (0.0..1.0_f64, azimuths()).prop_map(|(u, phi)| from_cos_phi(1.0 - u, phi))
}

/// Grazing directions: `|cos θ|` log-uniform in `[1e-7, 1e-2]`, on either side of the
/// surface, any azimuth. Where formulas divide by `cos θ`, and masking and Fresnel terms reach
/// their limits.
///
/// ```
/// use lobe::bxdf::{Bxdf, Microfacet};
/// use lobe::fresnel::NoFresnel;
/// use lobe::microfacet::{Ggx, Masking};
/// use lobe::verify::strategies::{alphas, grazing_directions, upper_directions};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn ggx_is_finite_at_grazing(
///         wo in grazing_directions(),
///         wi in upper_directions(),
///         a in alphas(),
///     ) {
///         let f1 = NoFresnel::<f32>::new();
///         let brdf = Microfacet::new(Ggx::isotropic(a), Masking::HeightCorrelated, f1);
///         prop_assert!(brdf.eval(wo, wi).is_finite());
///     }
/// }
/// ggx_is_finite_at_grazing();
/// ```
pub fn grazing_directions() -> impl Strategy<Value = Vec3> + Clone {
    (log_uniform(-7.0, -2.0), sides(), azimuths())
        .prop_map(|(c, side, phi)| from_cos_phi(side * c, phi))
}

/// Directions near the normal, on either side: `sin θ` log-uniform in `[1e-7, 1e-1]`, or
/// exactly `±z` (one draw in eight). Where the azimuth is undefined and `sin θ` divides.
///
/// For the upper side only, map through [`upper`](crate::microfacet::upper):
/// `near_normal_directions().prop_map(lobe::microfacet::upper)`.
///
/// ```
/// use lobe::frame::{cos_phi, sin_phi};
/// use lobe::verify::strategies::near_normal_directions;
/// use proptest::prelude::*;
///
/// proptest! {
///     fn azimuth_is_defined_at_the_normal(w in near_normal_directions()) {
///         let (c, s) = (cos_phi(w), sin_phi(w));
///         prop_assert!(c.is_finite() && s.is_finite());
///     }
/// }
/// azimuth_is_defined_at_the_normal();
/// ```
pub fn near_normal_directions() -> impl Strategy<Value = Vec3> + Clone {
    let tilted = (log_uniform(-7.0, -1.0), sides(), azimuths())
        .prop_map(|(s, side, phi)| from_sin_phi(s, side, phi));
    prop_oneof![
        7 => tilted,
        1 => select(vec![Vec3::Z, Vec3::NEG_Z]),
    ]
}

/// Directions chosen to break things: uniform ([`directions`]) half of the time, otherwise
/// [`grazing_directions`], [`near_normal_directions`], or a direction exactly in the tangent
/// plane (`cos θ = ±0`), which a strict `>` or `≥` guard treats differently and which a
/// division by `cos θ` turns into infinity or NaN.
///
/// The input a totality ("no NaN, no negative value") property should range over.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert};
/// use lobe::verify::strategies::adversarial_directions;
/// use proptest::prelude::*;
///
/// proptest! {
///     fn lambert_is_total(wo in adversarial_directions(), wi in adversarial_directions()) {
///         let f = Lambert::new(0.8_f32).unwrap().eval(wo, wi);
///         prop_assert!(f.is_finite() && f >= 0.0);
///     }
/// }
/// lambert_is_total();
/// ```
pub fn adversarial_directions() -> impl Strategy<Value = Vec3> + Clone {
    let horizon = (select(vec![0.0_f32, -0.0]), azimuths())
        .prop_map(|(z, phi)| Vec3::new(phi.cos() as f32, phi.sin() as f32, z));
    prop_oneof![
        4 => directions(),
        2 => grazing_directions(),
        1 => near_normal_directions(),
        1 => horizon,
    ]
}

/// Microfacet widths [`Alpha`] over the whole accepted range `[1e-4, 10]`: log-uniform, and
/// the two ends exactly (one draw in ten each).
///
/// ```
/// use lobe::microfacet::{Ggx, NormalDistribution};
/// use lobe::verify::strategies::{alphas, directions};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn ggx_masking_is_a_fraction(a in alphas(), w in directions()) {
///         let g1 = Ggx::isotropic(a).g1(w);
///         prop_assert!((0.0..=1.0).contains(&g1), "G1 = {g1}");
///     }
/// }
/// ggx_masking_is_a_fraction();
/// ```
pub fn alphas() -> impl Strategy<Value = Alpha> + Clone {
    let (lo, hi) = (Alpha::MIN, Alpha::MAX);
    let spread = log_uniform(f64::from(lo).log10(), f64::from(hi).log10())
        .prop_map(move |a| (a as f32).clamp(lo, hi));
    prop_oneof![
        8 => spread,
        1 => Just(lo),
        1 => Just(hi),
    ]
    .prop_map(|a| Alpha::new(a).expect("within Alpha's range"))
}

/// Relative indices of refraction [`Eta`]: log-uniform over the accepted range
/// `[1e-3, 1e3]` (half the draws), within `1e-7…1e-2` of 1 on either side or exactly 1 (a
/// quarter: index-matched interfaces, where refraction formulas cancel), and the common
/// media and their inverses, water 1.33, glass 1.5 and diamond 2.4 (a quarter).
///
/// ```
/// use lobe::fresnel::dielectric;
/// use lobe::verify::strategies::{etas, unit_f32};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn fresnel_is_a_fraction(eta in etas(), c in unit_f32()) {
///         let f = dielectric(c, eta);
///         prop_assert!((0.0..=1.0).contains(&f), "F = {f} at η = {}", eta.get());
///     }
/// }
/// fresnel_is_a_fraction();
/// ```
pub fn etas() -> impl Strategy<Value = Eta> + Clone {
    let spread = log_uniform(-3.0, 3.0).prop_map(|e| e as f32);
    let near_one = prop_oneof![
        4 => (log_uniform(-7.0, -2.0), sides()).prop_map(|(d, side)| (1.0 + side * d) as f32),
        1 => Just(1.0_f32),
    ];
    let common = select(vec![1.33_f32, 1.5, 2.4, 1.0 / 1.33, 1.0 / 1.5, 1.0 / 2.4]);
    prop_oneof![
        2 => spread,
        1 => near_one,
        1 => common,
    ]
    .prop_map(|e| Eta::new(e.clamp(Eta::MIN, Eta::MAX)).expect("within Eta's range"))
}

/// Conductors' complex indices [`ComplexIor`] `η + iκ` (single channel): real metals (gold, silver,
/// copper and aluminium, per sRGB channel, as Mitsuba 3 tabulates them; a fifth of the draws),
/// metal-like values (`η` log-uniform in `[0.01, 5]`, `κ` uniform in `[0, 10]`; two fifths), and
/// extremes (`η` log-uniform in `[1e-3, 1e3]`, `κ` zero or log-uniform in `[1e-3, 1e3]`; two
/// fifths; [`ComplexIor::new`] accepts `η` down to `f32::MIN_POSITIVE`, which these draws do not
/// reach).
///
/// ```
/// use lobe::fresnel::conductor;
/// use lobe::verify::strategies::{complex_iors, unit_f32};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn conductor_fresnel_is_a_fraction(ior in complex_iors(), c in unit_f32()) {
///         let f = conductor(c, &ior);
///         prop_assert!((0.0..=1.0).contains(&f), "F = {f} for {ior:?}");
///     }
/// }
/// conductor_fresnel_is_a_fraction();
/// ```
pub fn complex_iors() -> impl Strategy<Value = ComplexIor<f32>> + Clone {
    // (η, κ) of Au, Ag, Cu, Al at the sRGB primaries (Mitsuba 3's spectra, integrated).
    let metals = select(vec![
        (0.143_f32, 3.983_f32),
        (0.375, 2.386),
        (1.442, 1.603),
        (0.155, 4.828),
        (0.117, 3.122),
        (0.138, 2.147),
        (0.200, 3.912),
        (0.924, 2.453),
        (1.102, 2.142),
        (1.657, 9.224),
        (0.880, 6.270),
        (0.521, 4.837),
    ]);
    let metal_like = (
        log_uniform(-2.0, f64::from(5.0_f32).log10()),
        0.0..=10.0_f32,
    )
        .prop_map(|(eta, k)| (eta as f32, k));
    let extreme_k = prop_oneof![
        1 => Just(0.0_f32),
        3 => log_uniform(-3.0, 3.0).prop_map(|k| k as f32),
    ];
    let extreme = (log_uniform(-3.0, 3.0), extreme_k).prop_map(|(eta, k)| (eta as f32, k));
    prop_oneof![
        1 => metals,
        2 => metal_like,
        2 => extreme,
    ]
    .prop_map(|(eta, k)| {
        ComplexIor::new(eta.clamp(1e-3, 1e3), k.clamp(0.0, 1e3)).expect("within ComplexIor's range")
    })
}

/// Numbers uniform in `[0, 1)`: the random numbers `uc` a sampler takes, and cosines.
///
/// ```
/// use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
/// use lobe::verify::strategies::unit_f32;
/// use proptest::prelude::*;
///
/// proptest! {
///     fn cosine_pdf_is_positive_inside(a in unit_f32(), b in unit_f32()) {
///         let w = cosine_hemisphere(lobe::Vec2::new(a, b));
///         prop_assert!(cosine_hemisphere_pdf(w.z) >= 0.0);
///     }
/// }
/// cosine_pdf_is_positive_inside();
/// ```
pub fn unit_f32() -> impl Strategy<Value = f32> + Clone {
    0.0..1.0_f32
}

/// Points uniform in `[0, 1)²`: the random numbers `u` of
/// [`Bxdf::sample`](crate::bxdf::Bxdf::sample) and of the warps in
/// [`sampling`](crate::sampling).
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert};
/// use lobe::verify::strategies::{unit_f32, unit_vec2, upper_directions};
/// use proptest::prelude::*;
///
/// proptest! {
///     fn sample_agrees_with_pdf(wo in upper_directions(), u in unit_vec2(), uc in unit_f32()) {
///         let brdf = Lambert::new(0.8_f32).unwrap();
///         if let Some(s) = brdf.sample(wo, u, uc) {
///             prop_assert!((s.pdf - brdf.pdf(wo, s.wi)).abs() <= 1e-6 * s.pdf);
///         }
///     }
/// }
/// sample_agrees_with_pdf();
/// ```
pub fn unit_vec2() -> impl Strategy<Value = Vec2> + Clone {
    (unit_f32(), unit_f32()).prop_map(|(a, b)| Vec2::new(a, b))
}
