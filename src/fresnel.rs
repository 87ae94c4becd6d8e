//! Fresnel reflectance: Schlick's approximation, the exact dielectric and conductor
//! formulas, and the common closed-form conductor approximation.
//!
//! # Conventions
//!
//! * `cos_i` is the cosine of the angle between the incident direction and the normal of
//!   the interface. For a microfacet model that is the cosine between a direction and the
//!   microfacet normal, `wo·h` (Burley's `cos θd`), not `wo·n`.
//! * `eta` is a *relative* index of refraction, `η_inside / η_outside`, where the normal
//!   points to the outside (the crate-wide [`Eta`] convention). A positive `cos_i` (and
//!   `±0`) means the light arrives from the outside; a negative `cos_i` means it arrives
//!   from the inside, where the interface is seen with the index `1/η`.
//! * Reflectances are unpolarised: the mean of the s- and p-polarised reflectances.
//! * Every function here is total over `cos_i ∈ [-1, 1]` and valid parameters: the result is
//!   finite and in `[0, 1]`. A cosine slightly outside `[-1, 1]` (round-off) is treated as
//!   `±1`.
//!
//! The dielectric functions follow Mitsuba 3's `fresnel()` semantics exactly (inside versus
//! outside, the sign of the refracted cosine, total internal reflection), so the crate can be
//! checked against it record by record (`tests/fresnel.rs`).

mod average;

pub use average::{FresnelAverage, cosine_weighted_average};

use crate::math::{copysign, pow5, sqrt};
use crate::param::{ComplexIor, Eta};
use crate::spectrum::Spectrum;
use glam::Vec4;

/// Schlick's approximation of the Fresnel reflectance, `F0 + (1 − F0)(1 − cos θd)⁵`.
///
/// `f0` is the reflectance at normal incidence (per channel) and `cos_d` the cosine between
/// the incident direction and the (micro)facet normal. The fifth power applies to
/// `(1 − cos θd)`, not to the cosine alone: [the handout's](crate::handouts#seed-000)
/// `1 − cos⁵θd` is a typo ([ERRATA #1](crate::errata#erratum-1--schlick-exponent)).
///
/// The cosine enters as `|cos_d|`, saturated at 1: Schlick's form has no notion of the inside
/// of a surface, so a facet seen from behind reflects as one seen from the front, and a
/// round-off cosine above 1 gives `F0`. For light leaving a denser medium (where total
/// internal reflection is possible) use [`dielectric`], or pass the cosine on the less
/// dense side. For `f0` in `[0, 1]` the result lies in `[f0, 1]`.
///
/// Schlick (1994), "An Inexpensive BRDF Model for Physically-based Rendering", *Computer
/// Graphics Forum* 13(3): the Fresnel factor approximated by a fifth power of `1 − cos θd`.
#[inline(always)]
#[must_use]
pub fn schlick<S: Spectrum>(f0: S, cos_d: f32) -> S {
    // w = (1 − |cos θd|)⁵, the grazing weight of Schlick's interpolation.
    let w = pow5(1.0 - cos_d.abs().min(1.0));
    f0 + (S::one() - f0) * w
}

/// The full result of the dielectric Fresnel equations: the reflectance and what a
/// refraction through the same interface needs.
///
/// Returned by [`dielectric_full`]; the conventions are Mitsuba 3's `fresnel()`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DielectricFresnel {
    /// The unpolarised reflectance `F ∈ [0, 1]`; exactly 1 under total internal reflection.
    pub reflectance: f32,
    /// The cosine of the refracted direction with the normal. Its sign is always opposite to
    /// the sign *bit* of `cos_i` (the refracted ray continues through the interface), so
    /// `cos_i = −0.0` gives a positive `cos_t`. It is `∓0` under total internal reflection.
    pub cos_t: f32,
    /// The relative index in the direction of travel, `η_t / η_i` (transmitted side over
    /// incident side): `η` for `cos_i ≥ 0` (including `−0.0`), `1/η` for `cos_i < 0`.
    pub eta_it: f32,
    /// The reciprocal, `η_i / η_t`: `1/η` for `cos_i ≥ 0`, `η` for `cos_i < 0`. Snell's law
    /// reads `sin θt = eta_ti · sin θi`.
    pub eta_ti: f32,
}

/// The shared core of [`dielectric`] and [`dielectric_full`]: `(F, |cos θt|, η_it, η_ti)`.
///
/// The textbook amplitudes (Born & Wolf, *Principles of Optics*, 7th ed., §1.5.2)
///
/// ```text
/// r_s = (cos θi − η cos θt) / (cos θi + η cos θt)
/// r_p = (cos θt − η cos θi) / (cos θt + η cos θi),      η = η_it, 1/η = η_ti
/// ```
///
/// cancel catastrophically in `f32` when `η ≈ 1`, exactly where `F` is tiny. Multiplying
/// numerator and denominator by the denominator and using Snell's law,
/// `cos²θt = 1 − η_ti² sin²θi`, removes the cancellation:
///
/// ```text
/// r_s = (1 − η²) / (cos θi + η cos θt)²
/// r_p = (1 − η²) (cos²θi − η_ti² sin²θi) / (cos θt + η cos θi)²
/// ```
///
/// `1 − η²` comes from `d = (1 − η)(1 + η)` of the *given* `η` (exact to one rounding near 1;
/// `1 − η_it² = −d η_it²` from the inside, which avoids the rounding of `1/η`). Likewise
/// `cos²θt` is evaluated as `1 − η_ti² sin²θi` or as `(1 − η_ti²) + η_ti² cos²θi`, whichever
/// rounds less (the second for `cos²θi < sin²θi`, where it keeps `cos θt` accurate at
/// grazing incidence with `η ≈ 1`). The identities need a real `cos θt`, so total internal
/// reflection (`cos²θt ≤ 0`) and grazing incidence are selected separately, as is `η = 1`,
/// which gives exactly 0.
#[inline(always)]
fn dielectric_core(cos_i: f32, eta: f32) -> (f32, f32, f32, f32) {
    let rcp_eta = 1.0 / eta;
    let d = (1.0 - eta) * (1.0 + eta);
    // `>=` keeps −0.0 on the outside, as Mitsuba does. one_minus_it2 = 1 − η_it²,
    // one_minus_ti2 = 1 − η_ti².
    let (eta_it, eta_ti, one_minus_it2, one_minus_ti2) = if cos_i >= 0.0 {
        (eta, rcp_eta, d, -d * rcp_eta * rcp_eta)
    } else {
        (rcp_eta, eta, -d * rcp_eta * rcp_eta, d)
    };
    let ci = cos_i.abs().min(1.0);
    let cos2_i = ci * ci;
    // sin²θi = (1 − cos θi)(1 + cos θi): accurate at both ends of the range.
    let sin2_i = (1.0 - ci) * (1.0 + ci);
    let eta_ti2 = eta_ti * eta_ti;
    // Snell: cos²θt = 1 − η_ti² sin²θi; negative under total internal reflection.
    let cos2_t = if cos2_i < sin2_i {
        one_minus_ti2 + eta_ti2 * cos2_i
    } else {
        1.0 - eta_ti2 * sin2_i
    };
    let ct = sqrt(cos2_t.max(0.0));

    let den_s = ci + eta_it * ct;
    let den_p = ct + eta_it * ci;
    let r_s = one_minus_it2 / (den_s * den_s);
    let r_p = one_minus_it2 * (cos2_i - eta_ti2 * sin2_i) / (den_p * den_p);
    // |r_s|, |r_p| ≤ 1 in exact arithmetic; the `min` absorbs a last-ulp overshoot at grazing.
    let f = (0.5 * (r_s * r_s + r_p * r_p)).min(1.0);

    let f = if cos2_t > 0.0 && ci > 0.0 { f } else { 1.0 };
    let f = if eta == 1.0 { 0.0 } else { f };
    (f, ct, eta_it, eta_ti)
}

/// The exact unpolarised Fresnel reflectance of a smooth dielectric interface.
///
/// `cos_i ≥ 0` (including `−0.0`): the light arrives from the outside and sees the
/// relative index `η`; `cos_i < 0`: it arrives from the inside and sees `1/η`. Total internal
/// reflection gives exactly `1`, as does grazing incidence `cos_i = ±0`; an index-matched
/// interface (`η == 1`) gives exactly `0`.
///
/// `F = ½(r_s² + r_p²)` with the Fresnel amplitudes of Born & Wolf, *Principles of Optics*
/// (7th ed.), §1.5.2; see also Pharr, Jakob & Humphreys, *PBR* 4th ed., §9.3.5. The amplitudes
/// are evaluated in a rearranged form that keeps full relative precision for `η ≈ 1`. Same
/// semantics as Mitsuba 3's `fresnel()`; see [`dielectric_full`] for the refracted cosine and
/// the indices.
///
/// ```
/// use lobe::{fresnel, Eta};
/// let glass = Eta::new(1.5)?;
/// // Normal incidence: ((1.5 − 1)/(1.5 + 1))² = 0.04, from either side.
/// assert!((fresnel::dielectric(1.0, glass) - 0.04).abs() < 1e-7);
/// assert!((fresnel::dielectric(-1.0, glass) - 0.04).abs() < 1e-7);
/// // From inside the glass beyond the critical angle (cos θc ≈ 0.745): total internal reflection.
/// assert_eq!(fresnel::dielectric(-0.3, glass), 1.0);
/// // No interface, no reflection.
/// assert_eq!(fresnel::dielectric(0.3, Eta::new(1.0)?), 0.0);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[inline(always)]
#[must_use]
pub fn dielectric(cos_i: f32, eta: Eta) -> f32 {
    dielectric_core(cos_i, eta.get()).0
}

/// The exact dielectric Fresnel reflectance together with the refracted cosine and the
/// relative indices on either side, with Mitsuba 3's conventions.
///
/// * `reflectance` is [`dielectric`]`(cos_i, eta)`, bit for bit.
/// * `cos_t = −copysign(|cos θt|, cos_i)`: opposite to the sign bit of `cos_i`, `∓0` under
///   total internal reflection. `|cos θt| = √(1 − η_ti² sin²θi)` (Snell's law).
/// * `eta_it`, `eta_ti`: see [`DielectricFresnel`].
///
/// Born & Wolf, *Principles of Optics*, §1.5.2; Mitsuba 3, `include/mitsuba/render/fresnel.h`
/// (semantics only).
///
/// ```
/// use lobe::{fresnel, Eta};
/// let r = fresnel::dielectric_full(0.5, Eta::new(1.5)?);
/// // sin θt = sin θi / 1.5, and the refracted ray goes inside (negative cosine).
/// assert!((r.cos_t + (1.0_f32 - 0.75 / 2.25).sqrt()).abs() < 1e-6);
/// assert_eq!((r.eta_it, r.eta_ti), (1.5, 1.0 / 1.5));
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[inline(always)]
#[must_use]
pub fn dielectric_full(cos_i: f32, eta: Eta) -> DielectricFresnel {
    let (reflectance, ct, eta_it, eta_ti) = dielectric_core(cos_i, eta.get());
    DielectricFresnel {
        reflectance,
        cos_t: copysign(ct, -cos_i),
        eta_it,
        eta_ti,
    }
}

/// The dielectric Fresnel reflectance when both cosines of a refraction are known: `cos_i`
/// on the incident side, `cos_t` on the transmitted side (magnitudes are used), and
/// `eta_it = η_t / η_i`.
///
/// `F = ½(r_s² + r_p²)`, `r_s = (cos θi − η cos θt)/(cos θi + η cos θt)`,
/// `r_p = (η cos θi − cos θt)/(η cos θi + cos θt)` (Born & Wolf, §1.5.2). Swapping the sides
/// (`cos_t`, `cos_i`, `1/eta_it`) gives the same value, which makes a refraction model built on
/// it exactly reciprocal; and it needs no `cos θt` from Snell's law, whose `1 − η² sin² θ`
/// cancels near the critical angle. Both cosines `0` (a grazing pair) gives `1`.
#[inline(always)]
#[must_use]
pub fn dielectric_refracted(cos_i: f32, cos_t: f32, eta_it: f32) -> f32 {
    let (ci, ct) = (cos_i.abs().min(1.0), cos_t.abs().min(1.0));
    let rs = ratio_or_one(ci - eta_it * ct, ci + eta_it * ct);
    let rp = ratio_or_one(eta_it * ci - ct, eta_it * ci + ct);
    (0.5 * (rs * rs + rp * rp)).min(1.0)
}

/// `num / den`, or 1 where the ratio is the 0/0 limit of a grazing or vanishing-index
/// configuration (`den` is a sum of squares, so `den ≤ 0` means `den == 0`).
#[inline(always)]
fn ratio_or_one(num: f32, den: f32) -> f32 {
    if den > 0.0 { num / den } else { 1.0 }
}

/// [`conductor`]'s channels, given `c = |cos θi|`, `c² < sin²θi` as `grazing` and `sin²θi`: one
/// channel when `T` is `f32`, four at once when it is `Vec4` (the same operations in the same
/// order, so the same numbers, bit for bit).
///
/// With `n = η + iκ` and `a + ib = √(n² − sin²θi)` (the principal root, `a, b ≥ 0`):
///
/// ```text
/// a² − b² = η² − κ² − sin²θi
/// a b     = η κ
/// a² + b² = √((a² − b²)² + 4 η² κ²)
/// |r_s|² = ((c − a)² + b²) / ((c + a)² + b²)
/// |r_p|² = |r_s|² · ((a c − sin²θi)² + (b c)²) / ((a c + sin²θi)² + (b c)²)
/// ```
///
/// the real-arithmetic form of `r_s = (c − w)/(c + w)`, `r_p = (n² c − w)/(n² c + w)` with
/// `w = √(n² − sin²θi)`.
///
/// `η² − sin²θi` is evaluated as written for `cos²θi ≥ sin²θi` and as `(η − 1)(η + 1) + cos²θi`
/// otherwise: each form rounds less where the other cancels (the first keeps it exactly `η²`
/// at normal incidence, the second keeps the grazing reflectance of an interface with `η ≈ 1`
/// accurate). The larger of `a`, `b` comes from `√(½(a² + b² + |a² − b²|))` and the smaller
/// from `η κ` divided by it, which avoids the cancellation of the half-sum/half-difference
/// form. Writing every ratio as a sum of squares over a sum of squares keeps it in `[0, 1]`;
/// the two ratios share one division, so a channel costs two square roots and two divisions.
#[inline(always)]
fn conductor_channels<T: Lane>(c: f32, grazing: bool, sin2_i: f32, eta: T, k: T) -> T {
    let (one, zero) = (T::splat(1.0), T::splat(0.0));
    let (cv, c2, s2) = (T::splat(c), c * c, T::splat(sin2_i));
    // a² − b² = η² − κ² − sin²θi, in the form that rounds less (see above).
    let re = if grazing {
        (eta - one) * (eta + one) + T::splat(c2)
    } else {
        eta * eta - s2
    } - k * k;
    let ek = eta * k;
    let modulus = (re * re + ek * 4.0 * ek).sqrt();
    let big = ((modulus + re.abs()) * 0.5).sqrt();
    let small = big.positive_or(ek / big, zero);
    let a = re.non_negative_or(big, small);
    let b = re.non_negative_or(small, big);

    let b2 = b * b;
    // Each ratio num/den as a pair, (1, 1) where den is 0 ([`ratio_or_one`]'s limit): a
    // select, so that the two ratios can share one division.
    let ds = (cv + a) * (cv + a) + b2;
    let ns = ds.positive_or((cv - a) * (cv - a) + b2, one);
    let ds = ds.positive_or(ds, one);
    let ac = a * c;
    let bc2 = b2 * c2;
    let dp = (ac + s2) * (ac + s2) + bc2;
    let np = dp.positive_or((ac - s2) * (ac - s2) + bc2, one);
    let dp = dp.positive_or(dp, one);
    // ½ |r_s|² (1 + |r_p|²/|r_s|²) with the two ratios over one division.
    ns * 0.5 * (dp + np) / (ds * dp)
}

/// The arithmetic [`conductor_channels`] needs: `f32` (a channel) and `Vec4` (four).
trait Lane:
    Copy
    + core::ops::Add<Output = Self>
    + core::ops::Sub<Output = Self>
    + core::ops::Mul<Output = Self>
    + core::ops::Mul<f32, Output = Self>
    + core::ops::Div<Output = Self>
{
    /// Every lane `x`.
    fn splat(x: f32) -> Self;
    /// The correctly rounded square root of each lane.
    fn sqrt(self) -> Self;
    /// `|x|` per lane.
    fn abs(self) -> Self;
    /// Per lane, `yes` where `self > 0` and `no` elsewhere (NaN included).
    fn positive_or(self, yes: Self, no: Self) -> Self;
    /// Per lane, `yes` where `self ≥ 0` and `no` elsewhere (NaN included).
    fn non_negative_or(self, yes: Self, no: Self) -> Self;
}

impl Lane for f32 {
    #[inline(always)]
    fn splat(x: f32) -> Self {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f32::abs(self)
    }
    #[inline(always)]
    fn positive_or(self, yes: Self, no: Self) -> Self {
        if self > 0.0 { yes } else { no }
    }
    #[inline(always)]
    fn non_negative_or(self, yes: Self, no: Self) -> Self {
        if self >= 0.0 { yes } else { no }
    }
}

impl Lane for Vec4 {
    #[inline(always)]
    fn splat(x: f32) -> Self {
        Vec4::splat(x)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Vec4::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Vec4::abs(self)
    }
    #[inline(always)]
    fn positive_or(self, yes: Self, no: Self) -> Self {
        Vec4::select(self.cmpgt(Vec4::ZERO), yes, no)
    }
    #[inline(always)]
    fn non_negative_or(self, yes: Self, no: Self) -> Self {
        Vec4::select(self.cmpge(Vec4::ZERO), yes, no)
    }
}

/// The exact unpolarised Fresnel reflectance of a conductor with complex index `η + iκ`.
///
/// `F = ½(|r_s|² + |r_p|²)` with the complex Fresnel amplitudes, evaluated per channel in
/// real arithmetic (Born & Wolf, *Principles of Optics*, 7th ed., §14.2; Pharr, Jakob &
/// Humphreys, *PBR* 4th ed., §9.3.6; the real form as in *PBR* 3rd ed., §8.2.1). With `κ = 0`
/// it is the dielectric reflectance for `cos_i > 0` ([`dielectric`] seen from the outside),
/// total internal reflection included.
///
/// A conductor is opaque, so it has no inside: `cos_i < 0` is evaluated at `|cos_i|`. Grazing
/// incidence gives exactly 1 (the `0/0` of `η = 1, κ = 0` at `cos_i = 0` is defined as that
/// limit). The result is finite and in `[0, 1]` for every valid [`ComplexIor`].
///
/// ```
/// use lobe::{fresnel, ComplexIor, Vec3};
/// // Gold at normal incidence: ((η − 1)² + κ²) / ((η + 1)² + κ²) per channel.
/// let gold = ComplexIor::new(Vec3::new(0.143, 0.375, 1.442), Vec3::new(3.983, 2.386, 1.603))?;
/// let f = fresnel::conductor(1.0, &gold);
/// let r = ((0.143_f32 - 1.0).powi(2) + 3.983_f32.powi(2)) / ((1.143_f32).powi(2) + 3.983_f32.powi(2));
/// assert!((f.x - r).abs() < 1e-6);
/// assert_eq!(fresnel::conductor(0.0, &gold), Vec3::ONE);
/// # Ok::<(), lobe::ParamError>(())
/// ```
///
/// An RGB or four-channel spectrum is computed in one SIMD register, its channels side by
/// side (two square roots and two divisions for all of them); [`Fresnel::eval_per_channel`]
/// gives the same numbers channel by channel, for loops that vectorise across calls.
#[inline(always)]
#[must_use]
pub fn conductor<S: Spectrum>(cos_i: f32, ior: &ComplexIor<S>) -> S {
    let (c, grazing, sin2_i) = incidence(cos_i);
    if S::CHANNELS == 3 || S::CHANNELS == 4 {
        // A padding lane, if any, is the vacuum (η = 1, κ = 0): finite, and discarded.
        let lanes = |s: S, pad: f32| {
            let w = if S::CHANNELS == 4 { s.channel(3) } else { pad };
            Vec4::new(s.channel(0), s.channel(1), s.channel(2), w)
        };
        let f = conductor_channels(
            c,
            grazing,
            sin2_i,
            lanes(ior.eta(), 1.0),
            lanes(ior.k(), 0.0),
        );
        S::from_fn(|i| f[i])
    } else {
        conductor_per_channel(c, grazing, sin2_i, ior)
    }
}

/// `(c, c² < sin²θi, sin²θi)` for `c = |cos θi|` clamped to 1: what [`conductor_channels`]
/// takes.
#[inline(always)]
fn incidence(cos_i: f32) -> (f32, bool, f32) {
    let c = cos_i.abs().min(1.0);
    let sin2_i = (1.0 - c) * (1.0 + c);
    (c, c * c < sin2_i, sin2_i)
}

/// [`conductor`] one channel at a time, for `c = |cos θi|` and `sin²θi`.
#[inline(always)]
fn conductor_per_channel<S: Spectrum>(
    c: f32,
    grazing: bool,
    sin2_i: f32,
    ior: &ComplexIor<S>,
) -> S {
    ior.eta().zip_map(ior.k(), |eta, k| {
        conductor_channels(c, grazing, sin2_i, eta, k)
    })
}

/// The common closed-form *approximation* of the conductor Fresnel reflectance; use
/// [`conductor`] for the exact value.
///
/// ```text
/// ρ∥² = ((η² + κ²) cos²θ − 2η cos θ + 1) / ((η² + κ²) cos²θ + 2η cos θ + 1)
/// ρ⊥² = ((η² + κ²) − 2η cos θ + cos²θ)  / ((η² + κ²) + 2η cos θ + cos²θ)
/// F   = ½(ρ∥² + ρ⊥²)
/// ```
///
/// the pair printed in [the course handout](crate::handouts#seed-000)
/// ([ERRATA #6](crate::errata#erratum-6--conductor-fresnel-approximation)) and used by
/// *PBR* 2nd ed., §8.2.1
/// (`FrCond`). It drops the `sin²θ` terms of the exact result, so it is exact at normal
/// incidence and at grazing incidence (`F = 1`) and good when `η² + κ² ≫ 1` (metals), but
/// not in between for small `|n|`: it knows no total internal reflection and, at `κ = 0`,
/// it is *not* the dielectric formula.
///
/// Measured in `f32` (`tests/fresnel.rs`, which asserts these bounds) on the grid
/// `cos θ ∈ {0.001, 0.002, …, 1}`, `η ∈ {0.1, 0.15, …, 3}`, `κ ∈ {0, 0.1, …, 5}`, the
/// absolute error against [`conductor`] is at most
///
/// | region | max \|approx − exact\| | where |
/// | --- | --- | --- |
/// | whole grid | 0.997 | `η = 1, κ = 0, cos θ = 0.001`: it tends to 1 at grazing incidence even where there is no interface |
/// | `κ ≥ 1` | 0.064 | `η = 0.45, κ = 1, cos θ = 0.36` |
/// | `κ ≥ 2` | 0.0083 | `η = 2.2, κ = 2, cos θ = 0.12` |
///
/// and at `κ = 0` its distance from [`dielectric`] is at most 0.044 for `η ∈ [2, 3]`, 0.099
/// for `η ∈ [1.5, 3]` (at `η = 1.5, cos θ = 0.19`), 0.997 for `η ∈ [1, 3]` (near `η = 1`) and
/// 0.945 for `η < 1`, where the exact result is total internal reflection. On Mitsuba 3's
/// reference records (Au, Cu, Al per RGB channel and random `η, κ`) it is within 6.8e-3 of
/// the exact value.
///
/// Evaluated as `ρ∥² = ((η cos θ − 1)² + (κ cos θ)²) / ((η cos θ + 1)² + (κ cos θ)²)` and
/// `ρ⊥² = ((η − cos θ)² + κ²) / ((η + cos θ)² + κ²)`, the same expressions as sums of
/// squares, so each ratio stays in `[0, 1]`. `cos_i < 0` is evaluated at `|cos_i|`.
#[inline(always)]
#[must_use]
pub fn conductor_approx<S: Spectrum>(cos_i: f32, ior: &ComplexIor<S>) -> S {
    let c = cos_i.abs().min(1.0);
    ior.eta().zip_map(ior.k(), |eta, k| {
        let kc2 = (k * c) * (k * c);
        let ec = eta * c;
        let parallel = ratio_or_one((ec - 1.0) * (ec - 1.0) + kc2, (ec + 1.0) * (ec + 1.0) + kc2);
        let k2 = k * k;
        let perp = ratio_or_one((eta - c) * (eta - c) + k2, (eta + c) * (eta + c) + k2);
        0.5 * (parallel + perp)
    })
}

/// A Fresnel term as a value a model can hold: the reflectance of a (micro)facet as a
/// function of the cosine between the incident direction and the facet normal.
///
/// The models are generic over it, so the choice costs nothing in the shading loop.
pub trait Fresnel: Copy {
    /// The carrier of the reflectance.
    type Spectrum: Spectrum;

    /// The reflectance at `cos_d = wo·m` (Burley's `cos θd`).
    #[must_use]
    fn eval(&self, cos_d: f32) -> Self::Spectrum;

    /// [`eval`](Self::eval) computed channel by channel: the same numbers, bit for bit, in the
    /// form a loop over many calls vectorises across its calls ([`crate::batch`] uses it).
    /// The default is `eval`; [`Conductor`] overrides it, since its `eval` computes the
    /// channels of one call side by side in a SIMD register, which such a loop cannot widen.
    #[inline(always)]
    #[must_use]
    fn eval_per_channel(&self, cos_d: f32) -> Self::Spectrum {
        self.eval(cos_d)
    }
}

/// Schlick's approximation with normal-incidence reflectance `f0` ([`schlick`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Schlick<S = f32> {
    f0: S,
}

impl<S: Spectrum> Schlick<S> {
    /// Schlick's term for `f0 ∈ [0, 1]` per channel.
    ///
    /// # Errors
    /// [`ParamError`](crate::ParamError) naming `f0` for a channel that is NaN or outside
    /// `[0, 1]`.
    pub fn new(f0: S) -> Result<Self, crate::ParamError> {
        Ok(Self {
            f0: crate::param::unit_interval("f0", f0)?,
        })
    }

    getters! {
        /// The normal-incidence reflectance `f0`.
        f0: S,
    }
}

impl<S: Spectrum> Fresnel for Schlick<S> {
    type Spectrum = S;
    #[inline(always)]
    fn eval(&self, cos_d: f32) -> S {
        schlick(self.f0, cos_d)
    }
}

/// The exact conductor term for a complex index ([`conductor`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor<S = f32> {
    /// The complex index `η + iκ`.
    pub ior: ComplexIor<S>,
}

impl<S: Spectrum> Fresnel for Conductor<S> {
    type Spectrum = S;
    #[inline(always)]
    fn eval(&self, cos_d: f32) -> S {
        conductor(cos_d, &self.ior)
    }

    #[inline(always)]
    fn eval_per_channel(&self, cos_d: f32) -> S {
        let (c, grazing, sin2_i) = incidence(cos_d);
        conductor_per_channel(c, grazing, sin2_i, &self.ior)
    }
}

/// The exact dielectric term for a relative index ([`dielectric`]), the same in every channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric {
    /// The relative index `η_inside / η_outside`.
    pub eta: Eta,
}

impl Fresnel for Dielectric {
    type Spectrum = f32;
    #[inline(always)]
    fn eval(&self, cos_d: f32) -> f32 {
        dielectric(cos_d, self.eta)
    }
}

/// No Fresnel effect: reflectance `1` at every angle (a perfect reflector, Mitsuba's `none`
/// conductor), for checking a model's masking and energy alone.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NoFresnel<S = f32>(core::marker::PhantomData<S>);

impl<S> NoFresnel<S> {
    /// The term that is `1` everywhere.
    #[must_use]
    pub const fn new() -> Self {
        Self(core::marker::PhantomData)
    }
}

impl<S: Spectrum> Fresnel for NoFresnel<S> {
    type Spectrum = S;
    #[inline(always)]
    fn eval(&self, _cos_d: f32) -> S {
        S::one()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eta(v: f32) -> Eta {
        Eta::new(v).unwrap()
    }

    #[test]
    fn schlick_raises_one_minus_cos_to_the_fifth() {
        // By hand: 0.04 + 0.96 · (1 − 0.5)⁵ = 0.04 + 0.96/32 = 0.07.
        assert!((schlick(0.04_f32, 0.5) - 0.07).abs() < 1e-7);
        // The handout's slip, 0.04 + 0.96 · (1 − 0.5⁵) = 0.97, is far from it.
        let slipped = 0.04 + 0.96 * (1.0 - 0.5_f32.powi(5));
        assert!((schlick(0.04_f32, 0.5) - slipped).abs() > 0.5);
        // The ends: F0 at normal incidence, 1 at grazing, and |cos| for negative cosines.
        assert_eq!(schlick(0.04_f32, 1.0), 0.04);
        assert_eq!(schlick(0.04_f32, 0.0), 1.0);
        assert_eq!(schlick(0.04_f32, -0.5), schlick(0.04_f32, 0.5));
        assert_eq!(schlick(0.04_f32, 1.000_001), 0.04);
    }

    #[test]
    fn index_matched_interface_reflects_nothing() {
        for c in [1.0, 0.5, 1e-3, 0.0, -0.0, -0.5, -1.0] {
            assert_eq!(dielectric(c, eta(1.0)), 0.0, "cos {c}");
        }
        // Mitsuba's example: fresnel(0.5, 1) = (0, −0.5, 1, 1).
        let r = dielectric_full(0.5, eta(1.0));
        assert_eq!((r.reflectance, r.eta_it, r.eta_ti), (0.0, 1.0, 1.0));
        assert!((r.cos_t + 0.5).abs() < 1e-7);
    }

    #[test]
    fn total_internal_reflection_is_exactly_one() {
        // Inside glass (η = 1.5): sin θc = 1/1.5, cos θc = √(1 − 1/2.25) ≈ 0.745.
        for c in [-0.7, -0.5, -0.3, -1e-3] {
            let r = dielectric_full(c, eta(1.5));
            assert_eq!(r.reflectance, 1.0, "cos {c}");
            assert_eq!(r.cos_t, 0.0);
            assert!(r.cos_t.is_sign_positive());
        }
        // Outside a bubble (η = 1/1.5) the same happens for positive cosines.
        let r = dielectric_full(0.3, eta(1.0 / 1.5));
        assert_eq!(r.reflectance, 1.0);
        assert!(r.cos_t == 0.0 && r.cos_t.is_sign_negative());
        // Just inside the critical angle there is transmission.
        assert!(dielectric(-0.75, eta(1.5)) < 1.0);
    }

    #[test]
    fn grazing_and_signed_zero() {
        assert_eq!(dielectric(0.0, eta(1.5)), 1.0);
        assert_eq!(dielectric(-0.0, eta(1.5)), 1.0);
        // −0.0 is outside for the indices but flips the sign of cos_t (sign-bit rule).
        let r = dielectric_full(-0.0, eta(1.5));
        assert_eq!((r.eta_it, r.eta_ti), (1.5, 1.0 / 1.5));
        assert!(r.cos_t > 0.0);
        assert!(dielectric_full(0.0, eta(1.5)).cos_t < 0.0);
    }

    #[test]
    fn conductor_is_opaque_and_one_at_grazing() {
        let ior = ComplexIor::new(0.2_f32, 3.0).unwrap();
        assert_eq!(conductor(-0.4, &ior), conductor(0.4, &ior));
        assert_eq!(conductor(0.0, &ior), 1.0);
        // The 0/0 case: no interface at grazing incidence.
        let matched = ComplexIor::new(1.0_f32, 0.0).unwrap();
        assert_eq!(conductor(0.0, &matched), 1.0);
        assert!(conductor(0.5, &matched) < 1e-6);
        assert_eq!(conductor_approx(0.0, &ior), 1.0);
    }
}
