//! The normalised Blinn-Phong distribution.

use super::smith_table::{SmithTable, lambda_from_g1};
use super::{Beckmann, NormalDistribution, SampleDCos, Sampling, View};
use crate::math::{Power, exp, exp_m1, ln, sqrt};
use crate::param::{Alpha, ParamError};
use core::f32::consts::FRAC_1_PI;
use glam::{Vec2, Vec3};

/// The range of a Blinn-Phong distribution's `α`, as its refusals name it.
pub(crate) const BLINN_PHONG_ALPHA: &str = "[0.0001, 1] (Blinn-Phong)";

/// The normalised Blinn-Phong distribution of microfacet normals:
///
/// ```text
/// D(m) = (p + 2)/(2π) cos^p θm = 1/(π α²) cos^(2/α² − 2) θm           (m.z > 0)
/// ```
///
/// with the exponent `p = 2/α² − 2` tied to the Beckmann width `α` (Walter et al. 2007,
/// eqs. 30–32; [the handout's](crate::handouts#seed-000) form,
/// [ERRATA #8](crate::errata#erratum-8--normalised-blinn-phong-distribution):
/// `(p + 2)/(2π) = 1/(π α²)`). Widths
/// `α ∈ [1e-4, 1]`, exponents `p ∈ [0, 2·10⁸)` (`from_exponent` takes `[0, 10⁸]`); `α = 1`
/// is `p = 0`, the uniform `D = 1/π`. (A width above 1 would make `p` negative and `D`
/// infinite at grazing.)
///
/// **Masking** is, by default, the exact Smith `Λ` of the Beckmann distribution of the same
/// `α`, the equivalence Walter et al. (2007, §5.2) recommend. It is an approximation that
/// holds for narrow lobes only; the tests measure how far it is from conserving this
/// distribution's projected area (`max |∫ G1 ⟨wo, m⟩ D dm / cos θo − 1|` over θo up to 89°):
/// within the Monte Carlo error (±0.2%) for `α ≤ 0.1`, 9.9% at `α = 0.5`, 75% at `α = 1` (held
/// below 0.5%, 12% and 80% plus k standard errors).
/// Likewise `D` itself: the L1 distance `∫ |D − D_Beckmann| cos θ dω` is 1e-4 at `α = 0.01`,
/// 0.005 at 0.1, 0.12 at 0.5 and 0.41 at 1. [`BlinnPhongNdf::with_exact_smith`] switches to
/// this distribution's own Smith `G1`, tabulated like [`Gtr`](super::Gtr)'s, which conserves
/// the projected area at every `α`.
///
/// Sampling: `D cos θ`, `cos θm = u^(1/(p+2))`; there is no exact visible-normal sampler, so
/// [`sample`](NormalDistribution::sample) is that sampler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlinnPhongNdf {
    /// The exponent `p`, with the base below which `cos^p θ` is zero.
    power: Power,
    /// `(p + 2) / (2π)`.
    norm: f32,
    beckmann: Beckmann,
    /// This distribution's own Smith `G1`, when chosen over Beckmann's.
    smith: Option<SmithTable>,
}

impl BlinnPhongNdf {
    /// The distribution equivalent to Beckmann width `alpha ≤ 1`: `p = 2/α² − 2 ≥ 0`.
    ///
    /// # Errors
    /// [`ParamError`] naming `alpha` for `α > 1`, where the exponent would be negative and
    /// `D` would diverge at grazing.
    pub fn new(alpha: Alpha) -> Result<Self, ParamError> {
        let a = alpha.get();
        if a > 1.0 {
            return Err(ParamError::new("alpha", a, BLINN_PHONG_ALPHA));
        }
        let exponent = 2.0 / (a * a) - 2.0;
        Ok(Self {
            power: Power::new(exponent),
            norm: FRAC_1_PI / (a * a),
            beckmann: Beckmann::isotropic(alpha),
            smith: None,
        })
    }

    /// The distribution with exponent `p ∈ [0, 1e8]`, `α = √(2/(p + 2))`.
    ///
    /// # Errors
    /// [`ParamError`] naming `exponent` for NaN or `p` outside `[0, 1e8]`.
    pub fn from_exponent(p: f32) -> Result<Self, ParamError> {
        if !(0.0..=1e8).contains(&p) {
            return Err(ParamError::new("exponent", p, "[0, 1e8]"));
        }
        let alpha = Alpha::new(sqrt(2.0 / (p + 2.0)))?;
        Ok(Self {
            power: Power::new(p),
            norm: (p + 2.0) * 0.5 * FRAC_1_PI,
            beckmann: Beckmann::isotropic(alpha),
            smith: None,
        })
    }

    /// The same distribution with its own exact Smith masking, tabulated at construction
    /// (see [`Gtr`](super::Gtr) for the method), instead of Beckmann's.
    #[must_use]
    pub fn with_exact_smith(self) -> Self {
        let (power, norm) = (self.power, self.norm);
        let p = power.exponent();
        let d = move |cos: f32, sin: f32| norm * power.cos_pow(cos, sin * sin);
        // The median slope of D cos θ: cos θ = ½^(1/(p+2)).
        let l = ln(0.5) / (p + 2.0);
        let beta = sqrt((-exp_m1(2.0 * l)).max(0.0)) / exp(l);
        Self {
            smith: Some(SmithTable::new(d, beta, self.alpha())),
            ..self
        }
    }

    /// Whether the masking is this distribution's own Smith `G1` (else Beckmann's).
    #[inline]
    #[must_use]
    pub fn has_exact_smith(&self) -> bool {
        self.smith.is_some()
    }

    /// The exponent `p`.
    #[inline]
    #[must_use]
    pub fn exponent(&self) -> f32 {
        self.power.exponent()
    }

    /// The equivalent Beckmann width `α = √(2/(p + 2))`.
    #[inline]
    #[must_use]
    pub fn alpha(&self) -> f32 {
        self.beckmann.alpha().0
    }
}

impl NormalDistribution for BlinnPhongNdf {
    #[inline]
    fn sampling(&self) -> Sampling {
        Sampling::DCos
    }

    #[inline(always)]
    fn d(&self, m: Vec3) -> f32 {
        if !(m.z > 0.0) {
            return 0.0;
        }
        self.norm * self.power.cos_pow(m.z, m.x * m.x + m.y * m.y)
    }

    #[inline(always)]
    fn lambda(&self, w: Vec3) -> f32 {
        match &self.smith {
            None => self.beckmann.lambda(w),
            Some(_) => lambda_from_g1(self.g1(w)),
        }
    }

    #[inline(always)]
    fn g1(&self, w: Vec3) -> f32 {
        match &self.smith {
            None => self.beckmann.g1(w),
            Some(table) => table.g1(w.z, sqrt(w.x * w.x + w.y * w.y)),
        }
    }

    #[inline]
    fn sample(&self, _view: &View, u: Vec2) -> Vec3 {
        self.sample_d_cos(u)
    }
}

impl SampleDCos for BlinnPhongNdf {
    /// `cos θm = u^(1/(p+2))`, the inverse of the CDF `cos^(p+2)` of `D cos θ` over `cos θ`
    /// (Walter et al. 2007, eq. 31); `sin² θm = −expm1(2 ln u/(p+2))` keeps its digits for
    /// large `p`.
    fn sample_d_cos(&self, u: Vec2) -> Vec3 {
        // D cos θ ∝ cos^(p+1) θ.
        crate::sampling::cosine_power_hemisphere(u, self.power.exponent() + 1.0)
    }
}
