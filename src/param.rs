//! Typed, validated parameters and the error that refuses bad ones.
//!
//! The types keep apart values that share a unit but not a meaning: [`Alpha`] (microfacet
//! width) versus [`Roughness`] (perceptual, `α = r²`), and [`Eta`] (a *relative* index of
//! refraction) versus [`Ior`] (an *absolute* one). Every constructor rejects NaN, infinities
//! and out-of-range values with a [`ParamError`] that names the parameter and its range.
//!
//! The constructors of the scalar types, and [`ComplexIor::new_f32`], [`ComplexIor::new_vec3`]
//! and [`ComplexIor::new_vec4`], are `const fn`, so a validated parameter can be a `const`:
//!
//! ```
//! use lobe::{Alpha, ComplexIor, Vec3};
//!
//! const ROUGH: Alpha = match Alpha::new(0.3) {
//!     Ok(a) => a,
//!     Err(_) => panic!("alpha out of range"), // a compile-time error, never a run-time one
//! };
//! const COPPER: ComplexIor<Vec3> =
//!     match ComplexIor::new_vec3(Vec3::new(0.27, 1.12, 1.24), Vec3::new(3.61, 2.59, 2.39)) {
//!         Ok(ior) => ior,
//!         Err(_) => panic!("index out of range"),
//!     };
//! assert_eq!(ROUGH.get(), 0.3);
//! assert_eq!(COPPER.k().x, 3.61);
//! ```
//!
//! With the `serde` feature every type here is `Serialize`/`Deserialize`, and deserialising
//! goes through the same validation: a scene file cannot smuggle in `alpha = -1`. The scalar
//! types are plain numbers on the wire, [`ComplexIor`] is `{ "eta": …, "k": … }` with one
//! number per channel (glam's vectors are arrays):
//!
//! ```
//! # #[cfg(feature = "serde")] {
//! use lobe::{Alpha, ComplexIor, Eta, Vec3};
//! use serde::Deserialize;
//!
//! #[derive(Deserialize)]
//! struct Material {
//!     name: String,
//!     alpha: Alpha,
//!     #[serde(default)]
//!     coat: Option<Eta>,
//!     metal: Option<ComplexIor<Vec3>>,
//! }
//!
//! let json = r#"[
//!     { "name": "brushed gold", "alpha": 0.3,
//!       "metal": { "eta": [0.16, 0.42, 1.38], "k": [3.64, 2.41, 1.89] } },
//!     { "name": "lacquer", "alpha": 0.05, "coat": 1.5, "metal": null }
//! ]"#;
//! let materials: Vec<Material> = serde_json::from_str(json)?;
//! assert_eq!(materials[0].name, "brushed gold");
//! assert_eq!(materials[0].alpha.get(), 0.3);
//! assert_eq!(materials[1].coat.map(Eta::get), Some(1.5));
//! assert_eq!(materials[0].metal.unwrap().k(), Vec3::new(3.64, 2.41, 1.89));
//!
//! // Out-of-range values are refused with the parameter's name and its valid range.
//! let bad = r#"{ "name": "broken", "alpha": -1, "metal": null }"#;
//! let err = serde_json::from_str::<Material>(bad).err().unwrap();
//! assert!(err.to_string().starts_with("invalid alpha = -1: expected a value in [0.0001, 10]"));
//! let bad = r#"{ "name": "broken", "alpha": 0.3, "metal": { "eta": 0.2, "k": 3 } }"#;
//! assert!(serde_json::from_str::<Material>(bad).is_err()); // one number where RGB is due
//! # }
//! # Ok::<(), serde_json::Error>(())
//! ```

use crate::spectrum::Spectrum;
use core::fmt;
use glam::{Vec3, Vec4};

/// A parameter refused by a constructor: which one, the value given, and the valid range.
///
/// ```
/// let err = lobe::Alpha::new(f32::NAN).unwrap_err();
/// assert_eq!(err.param(), "alpha");
/// assert_eq!(err.to_string(), "invalid alpha = NaN: expected a value in [0.0001, 10]");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamError {
    param: &'static str,
    value: f32,
    range: &'static str,
}

impl ParamError {
    /// An error for parameter `param`, which was given `value` outside `range`.
    ///
    /// Public so that a downstream model can report its own parameters the same way.
    #[must_use]
    pub const fn new(param: &'static str, value: f32, range: &'static str) -> Self {
        Self {
            param,
            value,
            range,
        }
    }

    /// The name of the refused parameter.
    #[must_use]
    pub const fn param(&self) -> &'static str {
        self.param
    }

    /// The refused value (one channel of it, for a spectral parameter).
    #[must_use]
    pub const fn value(&self) -> f32 {
        self.value
    }

    /// The valid range, in interval notation.
    #[must_use]
    pub const fn range(&self) -> &'static str {
        self.range
    }
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "invalid {} = {}: expected a value in {}",
            self.param, self.value, self.range
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ParamError {}

/// Accepts `value` when `lo <= value <= hi`; NaN fails the comparison and is refused.
#[inline]
const fn check(
    param: &'static str,
    value: f32,
    lo: f32,
    hi: f32,
    range: &'static str,
) -> Result<f32, ParamError> {
    if value >= lo && value <= hi {
        Ok(value)
    } else {
        Err(ParamError::new(param, value, range))
    }
}

/// Checks every channel of a spectrum with [`check`].
fn check_spectrum<S: Spectrum>(
    param: &'static str,
    value: S,
    lo: f32,
    hi: f32,
    range: &'static str,
) -> Result<S, ParamError> {
    for i in 0..S::CHANNELS {
        check(param, value.channel(i), lo, hi, range)?;
    }
    Ok(value)
}

/// Accepts a spectrum whose every channel lies in `[0, 1]` (a reflectance or a weight),
/// refusing NaN; the error names `param`.
///
/// # Errors
/// [`ParamError`] naming `param` with the first offending channel.
pub(crate) fn unit_interval<S: Spectrum>(param: &'static str, value: S) -> Result<S, ParamError> {
    check_spectrum(param, value, 0.0, 1.0, "[0, 1]")
}

/// The microfacet width `α` of GGX, Beckmann and their kin: the RMS slope of the
/// microsurface (Beckmann) or the scale of its slope distribution (GGX).
///
/// Valid range `[1e-4, 10]`. A perfectly smooth surface (`α = 0`) is a delta lobe: use the
/// mirror and smooth dielectric models for it.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "f32", into = "f32"))]
pub struct Alpha(f32);

impl Alpha {
    /// The smallest accepted width.
    pub const MIN: f32 = 1e-4;
    /// The largest accepted width.
    pub const MAX: f32 = 10.0;

    /// A microfacet width `α ∈ [1e-4, 10]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `alpha` for NaN, infinite or out-of-range `alpha`.
    pub const fn new(alpha: f32) -> Result<Self, ParamError> {
        match check("alpha", alpha, Self::MIN, Self::MAX, "[0.0001, 10]") {
            Ok(a) => Ok(Self(a)),
            Err(e) => Err(e),
        }
    }
}

impl From<Roughness> for Alpha {
    #[inline]
    fn from(r: Roughness) -> Self {
        r.alpha()
    }
}

/// Perceptual roughness `r ∈ [0, 1]`, the artist-facing slider of Burley (2012), §5.4:
/// the microfacet width is `α = r²`.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "f32", into = "f32"))]
pub struct Roughness(f32);

impl Roughness {
    /// A perceptual roughness `r ∈ [0, 1]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `roughness` for NaN or `r` outside `[0, 1]`.
    pub const fn new(r: f32) -> Result<Self, ParamError> {
        match check("roughness", r, 0.0, 1.0, "[0, 1]") {
            Ok(r) => Ok(Self(r)),
            Err(e) => Err(e),
        }
    }

    /// The microfacet width `α = r²`, raised to [`Alpha::MIN`] for `r < 0.01`.
    #[inline]
    #[must_use]
    pub fn alpha(self) -> Alpha {
        Alpha((self.0 * self.0).max(Alpha::MIN))
    }
}

/// An absolute index of refraction: the ratio of the speed of light in vacuum to that in a
/// medium (1 for vacuum, about 1.5 for glass). Valid range `[1e-3, 1e3]`.
///
/// Models take a relative [`Eta`]; build one with [`Eta::relative`].
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "f32", into = "f32"))]
pub struct Ior(f32);

impl Ior {
    /// Vacuum, `1`.
    pub const VACUUM: Self = Self(1.0);

    /// An absolute index in `[1e-3, 1e3]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `ior` for NaN, infinite or out-of-range values.
    pub const fn new(ior: f32) -> Result<Self, ParamError> {
        match check("ior", ior, Eta::MIN, Eta::MAX, "[0.001, 1000]") {
            Ok(v) => Ok(Self(v)),
            Err(e) => Err(e),
        }
    }
}

/// A relative index of refraction `η = η_inside / η_outside`, where the local `+z` (the
/// normal) points to the outside. Valid range `[1e-3, 1e3]`, closed under [`Eta::inv`].
///
/// `η > 1` is the usual case of a denser medium inside (glass in air, `η = 1.5`); `η < 1`
/// describes, for example, an air bubble in water.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "f32", into = "f32"))]
pub struct Eta(f32);

impl Eta {
    /// The smallest accepted relative index.
    pub const MIN: f32 = 1e-3;
    /// The largest accepted relative index.
    pub const MAX: f32 = 1e3;
    /// The largest normal-incidence reflectance [`Eta::from_f0`] accepts (`η ≤ 999`).
    pub const F0_MAX: f32 = 0.996;

    /// A relative index `η ∈ [1e-3, 1e3]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `eta` for NaN, infinite, non-positive or out-of-range values.
    pub const fn new(eta: f32) -> Result<Self, ParamError> {
        match check("eta", eta, Self::MIN, Self::MAX, "[0.001, 1000]") {
            Ok(v) => Ok(Self(v)),
            Err(e) => Err(e),
        }
    }

    /// The relative index `inside / outside` of two absolute indices.
    ///
    /// # Errors
    /// [`ParamError`] naming `eta` when the ratio leaves `[1e-3, 1e3]`.
    pub fn relative(inside: Ior, outside: Ior) -> Result<Self, ParamError> {
        Self::new(inside.0 / outside.0)
    }

    /// The index `η ≥ 1` of a dielectric whose normal-incidence reflectance is `f0`:
    /// `η = (1 + √f0) / (1 − √f0)`, the inverse of [`Eta::f0`].
    ///
    /// # Errors
    /// [`ParamError`] naming `f0` for NaN or `f0` outside `[0, 0.996]`.
    pub fn from_f0(f0: f32) -> Result<Self, ParamError> {
        let f0 = check("f0", f0, 0.0, Self::F0_MAX, "[0, 0.996]")?;
        let s = crate::math::sqrt(f0);
        Ok(Self((1.0 + s) / (1.0 - s)))
    }

    /// The reciprocal `1/η`: the same interface seen from the inside.
    #[inline]
    #[must_use]
    pub fn inv(self) -> Self {
        Self(1.0 / self.0)
    }

    /// The relative index a transmission leaving from the side of a direction with
    /// `cos θ = cos_theta` sees: `η` from the outside (`cos_theta > 0`), `1/η` from the inside
    /// (any other `cos_theta`, `±0` and NaN included, as the crate's models count a direction
    /// on the horizon).
    ///
    /// ```
    /// use lobe::Eta;
    /// let glass = Eta::new(1.5)?;
    /// assert_eq!(glass.seen_from(0.3), 1.5);
    /// assert_eq!(glass.seen_from(-0.3), 1.0 / 1.5);
    /// # Ok::<(), lobe::ParamError>(())
    /// ```
    #[inline(always)]
    #[must_use]
    pub fn seen_from(self, cos_theta: f32) -> f32 {
        if cos_theta > 0.0 {
            self.0
        } else {
            1.0 / self.0
        }
    }

    /// The normal-incidence Fresnel reflectance `F0 = ((η − 1)/(η + 1))²`.
    #[inline]
    #[must_use]
    pub fn f0(self) -> f32 {
        let r = (self.0 - 1.0) / (self.0 + 1.0);
        r * r
    }
}

/// `get` and `From<_> for f32` (the plain number) and `TryFrom<f32>` (the validating
/// constructor) for each scalar parameter, named in `get`'s doc by `$what`; the serde impls
/// go through the conversions.
macro_rules! scalar_conversions {
    ($($ty:ident $what:literal),*) => {$(
        impl $ty {
            #[doc = concat!("The ", $what, " as a plain number.")]
            #[inline]
            #[must_use]
            pub const fn get(self) -> f32 {
                self.0
            }
        }

        impl TryFrom<f32> for $ty {
            type Error = ParamError;

            #[inline]
            fn try_from(value: f32) -> Result<Self, ParamError> {
                Self::new(value)
            }
        }

        impl From<$ty> for f32 {
            #[inline]
            fn from(value: $ty) -> f32 {
                value.0
            }
        }
    )*};
}

scalar_conversions!(Alpha "width", Roughness "roughness", Ior "index", Eta "index");

/// A conductor's complex index of refraction `η + iκ`, relative to the outside medium,
/// per channel of the spectrum `S`.
///
/// Valid ranges: `η ∈ [1.1754944e-38, 1000]` (positive and normal: `f32::MIN_POSITIVE` up), `κ ∈ [0, 1000]`,
/// every channel.
///
/// ```
/// use lobe::{ComplexIor, Vec3};
/// // Gold, as Mitsuba 3 tabulates it for the sRGB primaries.
/// let gold = ComplexIor::new(Vec3::new(0.143, 0.375, 1.442), Vec3::new(3.983, 2.386, 1.603))?;
/// assert_eq!(gold.k().x, 3.983);
/// # Ok::<(), lobe::ParamError>(())
/// ```
///
/// Measured metals by name are in [`metals`](crate::metals) (`lobe::metals::GOLD.rgb()`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(
    feature = "serde",
    serde(
        try_from = "ComplexIorFields<S>",
        bound(
            serialize = "S: serde::Serialize",
            deserialize = "S: Spectrum + serde::Deserialize<'de>"
        )
    )
)]
pub struct ComplexIor<S = f32> {
    eta: S,
    k: S,
}

/// The unvalidated fields of a [`ComplexIor`] as they arrive from a deserialiser; the
/// conversion to [`ComplexIor`] is [`ComplexIor::new`].
#[cfg(feature = "serde")]
#[derive(serde::Deserialize)]
#[serde(rename = "ComplexIor", deny_unknown_fields)]
struct ComplexIorFields<S> {
    eta: S,
    k: S,
}

#[cfg(feature = "serde")]
impl<S: Spectrum> TryFrom<ComplexIorFields<S>> for ComplexIor<S> {
    type Error = ParamError;

    fn try_from(raw: ComplexIorFields<S>) -> Result<Self, ParamError> {
        Self::new(raw.eta, raw.k)
    }
}

impl<S: Spectrum> ComplexIor<S> {
    /// A complex index with real part `eta` and extinction coefficient `k`.
    ///
    /// # Errors
    /// [`ParamError`] naming `eta` (range `[1.1754944e-38, 1000]`, positive and normal) or `k` (range `[0, 1000]`) for the
    /// first channel that is NaN, infinite or out of range.
    pub fn new(eta: S, k: S) -> Result<Self, ParamError> {
        let eta = check_spectrum("eta", eta, f32::MIN_POSITIVE, 1e3, "[1.1754944e-38, 1000]")?;
        let k = check_spectrum("k", k, 0.0, 1e3, "[0, 1000]")?;
        Ok(Self { eta, k })
    }

    getters! {
        /// The real part `η`.
        eta: S,
        /// The extinction coefficient `κ`.
        k: S,
    }

    /// The normal-incidence reflectance `F0 = ((η − 1)² + κ²) / ((η + 1)² + κ²)` per channel
    /// (the exact conductor Fresnel term at `cos θ = 1`).
    #[inline]
    #[must_use]
    pub fn f0(&self) -> S {
        self.eta.zip_map(self.k, |eta, k| {
            let k2 = k * k;
            ((eta - 1.0) * (eta - 1.0) + k2) / ((eta + 1.0) * (eta + 1.0) + k2)
        })
    }

    /// A complex index from parts known to be valid (tabulated data, interpolations of it).
    #[inline]
    pub(crate) const fn from_valid_parts(eta: S, k: S) -> Self {
        Self { eta, k }
    }
}

/// Validates the channels of a complex index at compile time or at run time, in the order of
/// [`ComplexIor::new`]: every `η` first, then every `κ`.
const fn check_channels(eta: &[f32], k: &[f32]) -> Result<(), ParamError> {
    let mut i = 0;
    while i < eta.len() {
        if let Err(e) = check(
            "eta",
            eta[i],
            f32::MIN_POSITIVE,
            1e3,
            "[1.1754944e-38, 1000]",
        ) {
            return Err(e);
        }
        i += 1;
    }
    let mut i = 0;
    while i < k.len() {
        if let Err(e) = check("k", k[i], 0.0, 1e3, "[0, 1000]") {
            return Err(e);
        }
        i += 1;
    }
    Ok(())
}

impl ComplexIor<f32> {
    /// [`ComplexIor::new`] for one channel, usable in a `const`.
    ///
    /// # Errors
    /// As [`ComplexIor::new`].
    pub const fn new_f32(eta: f32, k: f32) -> Result<Self, ParamError> {
        match check_channels(&[eta], &[k]) {
            Ok(()) => Ok(Self { eta, k }),
            Err(e) => Err(e),
        }
    }
}

impl ComplexIor<Vec3> {
    /// [`ComplexIor::new`] for RGB, usable in a `const`.
    ///
    /// # Errors
    /// As [`ComplexIor::new`].
    pub const fn new_vec3(eta: Vec3, k: Vec3) -> Result<Self, ParamError> {
        match check_channels(&eta.to_array(), &k.to_array()) {
            Ok(()) => Ok(Self { eta, k }),
            Err(e) => Err(e),
        }
    }
}

impl ComplexIor<Vec4> {
    /// [`ComplexIor::new`] for four wavelength samples, usable in a `const`.
    ///
    /// # Errors
    /// As [`ComplexIor::new`].
    pub const fn new_vec4(eta: Vec4, k: Vec4) -> Result<Self, ParamError> {
        match check_channels(&eta.to_array(), &k.to_array()) {
            Ok(()) => Ok(Self { eta, k }),
            Err(e) => Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use std::string::ToString;

    const BAD: [f32; 4] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -1.0];

    /// `ComplexIor`'s `eta` range names the bound it checks: its lower end parses back to
    /// `f32::MIN_POSITIVE`, which is accepted, and the subnormal below it is refused (the range
    /// said 1.2e-38, above values it accepted).
    #[test]
    fn complex_ior_names_the_bound_it_checks() {
        let e = ComplexIor::new(0.0_f32, 0.0).unwrap_err();
        let lower: f32 = e.range()[1..].split(',').next().unwrap().parse().unwrap();
        assert_eq!(lower, f32::MIN_POSITIVE);
        assert!(ComplexIor::new(f32::MIN_POSITIVE, 0.0).is_ok());
        assert!(ComplexIor::new(1.18e-38_f32, 0.0).is_ok());
        let below = f32::from_bits(f32::MIN_POSITIVE.to_bits() - 1);
        assert!(ComplexIor::new(below, 0.0).is_err());
    }

    #[test]
    fn refuses_nan_infinite_negative_and_zero() {
        for v in BAD.into_iter().chain([0.0]) {
            assert_eq!(Alpha::new(v).unwrap_err().param(), "alpha");
            assert_eq!(Eta::new(v).unwrap_err().param(), "eta");
            assert_eq!(Ior::new(v).unwrap_err().param(), "ior");
            let e = ComplexIor::new(v, 1.0).unwrap_err();
            assert_eq!((e.param(), e.range()), ("eta", "[1.1754944e-38, 1000]"));
        }
        for v in BAD {
            assert_eq!(Roughness::new(v).unwrap_err().param(), "roughness");
            assert_eq!(Eta::from_f0(v).unwrap_err().param(), "f0");
            assert_eq!(ComplexIor::new(1.0, v).unwrap_err().param(), "k");
        }
    }

    #[test]
    fn refuses_out_of_range() {
        assert!(Alpha::new(5e-5).is_err());
        assert!(Alpha::new(10.5).is_err());
        assert!(Roughness::new(1.01).is_err());
        assert!(Eta::new(2e3).is_err());
        assert!(Eta::from_f0(1.0).is_err());
        let e = ComplexIor::new(Vec3::new(0.2, f32::NAN, 1.0), Vec3::ONE).unwrap_err();
        assert!(e.value().is_nan());
        assert_eq!(
            e.to_string(),
            "invalid eta = NaN: expected a value in [1.1754944e-38, 1000]"
        );
    }

    #[test]
    fn accepts_the_range_ends() {
        assert_eq!(Alpha::new(Alpha::MIN).unwrap().get(), 1e-4);
        assert_eq!(Alpha::new(Alpha::MAX).unwrap().get(), 10.0);
        assert_eq!(Roughness::new(0.0).unwrap().alpha().get(), Alpha::MIN);
        assert_eq!(Roughness::new(0.5).unwrap().alpha().get(), 0.25);
        assert!(Eta::new(1e-3).is_ok() && Eta::new(1e3).is_ok());
        assert!(Eta::new(1e-3).unwrap().inv().get() <= Eta::MAX);
        assert!(ComplexIor::new(1.0, 0.0).is_ok());
    }

    #[test]
    fn f0_and_eta_invert_each_other() {
        for eta in [1.0_f32, 1.33, 1.5, 2.4, 10.0, 900.0] {
            let e = Eta::new(eta).unwrap();
            let back = Eta::from_f0(e.f0()).unwrap().get();
            assert!(
                (back - eta).abs() <= 1e-4 * eta * eta.max(1.0),
                "{eta} -> {back}"
            );
        }
        // Glass: F0 = 0.04 exactly at η = 1.5.
        assert!((Eta::new(1.5).unwrap().f0() - 0.04).abs() < 1e-7);
        let water_in_air = Eta::relative(Ior::new(1.33).unwrap(), Ior::VACUUM).unwrap();
        assert_eq!(water_in_air.get(), 1.33);
    }
}
