//! The Blinn-Phong BRDF of [the handouts](crate::handouts#seed-003) ("modified Blinn-Phong") and its
//! normalised form.

use super::diffuse_glossy::{checked_parameters, cos_power_norm};
use crate::frame::reflect_away;
use crate::math::{Power, exp, sqrt};
use crate::param::ParamError;
use crate::sampling::cosine_hemisphere_pdf;
use crate::spectrum::Spectrum;
use core::f32::consts::{FRAC_1_PI, PI};
use glam::{Vec2, Vec3};

/// Which Blinn-Phong lobe: [the handout's](crate::handouts#seed-003) unnormalised one or the
/// normalised one.
///
/// Both are `k_s K(p) (n·h)^p` with `h` the half vector of `wo` and `wi`; they differ in the
/// factor `K`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BlinnPhongForm {
    /// `K = 1`: the "modified Blinn-Phong" of the handout ([seed 003](crate::handouts#seed-003), with
    /// the geometry term of [ERRATA #7](crate::errata#erratum-7--blinn-phong-geometry-factor)).
    /// **Not energy-normalised**: the lobe's albedo falls as `p` grows and
    /// exceeds 1 for small `p` (up to `π k_s` at `p = 0`); see [`BlinnPhong`].
    Modified,
    /// `K = (p + 8)/(8π)`: Akenine-Möller, Haines & Hoffman, *Real-Time Rendering*, 3rd ed.
    /// (2008), eq. 7.49. Approximately energy-conserving: at most 7.52% above `R + k_s`
    /// (measured 1.0752 at `p ≈ 8.8`).
    #[default]
    Normalized,
}

/// A Lambertian term plus a Blinn-Phong lobe around the normal, in the half vector:
///
/// ```text
/// f(wo, wi) = R/π + k_s K(p) (n·h)^p,    h = (wo + wi)/|wo + wi|,
/// K = 1 (BlinnPhongForm::Modified)  or  (p + 8)/(8π) (BlinnPhongForm::Normalized)
/// ```
///
/// for `wo`, `wi` above the surface (zero otherwise). Blinn 1977, "Models of light
/// reflection for computer synthesized pictures"; the handout's "modified Blinn-Phong"
/// ([seed 003](crate::handouts#seed-003),
/// [ERRATA #7](crate::errata#erratum-7--blinn-phong-geometry-factor): its geometry factor is
/// `max(0, n·l)/r²`, supplied by the renderer,
/// not part of `f`) and the normalised form of Real-Time Rendering, 3rd ed., eq. 7.49. Both
/// are reciprocal: `h` is symmetric in `wo` and `wi`.
///
/// This is the *shading-model* Blinn-Phong. The exactly normalised Blinn-Phong *distribution*
/// `D = (p + 2)/(2π) (n·m)^p`
/// ([ERRATA #8](crate::errata#erratum-8--normalised-blinn-phong-distribution)), with masking and
/// Fresnel, is
/// [`BlinnPhongNdf`](crate::microfacet::BlinnPhongNdf) inside a microfacet model.
///
/// **Parameters.** `R, k_s ∈ [0, 1]` per channel with `R + k_s ≤ 1` in every channel, and the
/// exponent `p ∈ [0, 10⁶]` ([`BlinnPhong::MAX_EXPONENT`]).
///
/// **Energy** (measured in `tests/bxdf_blinn_phong.rs`). At normal incidence the lobe's albedo
/// has the closed form `k_s K(p) · 8π (p + 2^(−p/2)) / ((p + 2)(p + 4))`
/// ([`albedo_at_normal`](BlinnPhong::albedo_at_normal); with `wo = n`, `θi = 2θh`), and it is
/// the largest over the viewing angles: measured at θo = 0°, 15°, …, 75°, 80°, 89° for
/// `p = 0, 1, 8.76, 10, 30, 100, 1000`, the albedo falls with θo (for `p = 0` it is constant),
/// and at θo = 0° it matches the closed form within the Monte Carlo error. The closed form,
/// for `k_s = 1`, `R = 0`:
///
/// | `p` | 0 | 1 | 2 | 5 | 10 | 20 | 30 | 100 | 1000 |
/// | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |
/// | `Modified` | 3.142 | 2.860 | 2.618 | 2.065 | 1.501 | 0.952 | 0.693 | 0.237 | 0.025 |
/// | `Normalized` | 1.000 | 1.024 | 1.042 | 1.068 | 1.075 | 1.061 | 1.048 | 1.018 | 1.002 |
///
/// and measured away from the normal (θo = 0°, 30°, 60°, 80°, 89°; 200 000 samples, standard
/// errors ≤ 0.009; `tests/bxdf_blinn_phong.rs`): `Modified`, `p = 1`: 2.863, 2.738, 2.354,
/// 1.943, 1.712; `Normalized`, `p = 10`: 1.075, 0.867, 0.432, 0.190, 0.115.
///
/// So the `Modified` form **gains energy** (albedo above 1) whenever `R + k_s · 8π (p +
/// 2^(−p/2))/((p + 2)(p + 4)) > 1`: for `k_s = 1` at every `p` below 18.7, by up to a factor
/// π (at `p = 0`, where `f = R/π + k_s` is constant). The `Normalized` form is approximately
/// energy-conserving: with `R + k_s ≤ 1` its albedo is at most `R + 1.0752 k_s ≤ 1.0752`
/// (the maximum of the lobe's factor, at `p ≈ 8.76`; a gain [found by
/// measurement](crate::errata#measured-2--normalised-blinn-phong-gain)), and it tends to
/// `R + k_s` as `p` grows.
///
/// **Sampling.** With probability `P_d = R̄/(R̄ + k̄_s)` (channel averages; `1` for a black
/// model) the diffuse lobe, cosine-weighted; otherwise the half vector `h` with density
/// `(p + 1)/(2π) (n·h)^p` and `wi = reflect_away(wo, h)`, whose density is that over
/// `4 (wo·h)`. A reflected direction below the horizon is the sampler's missing mass:
/// `sample` returns `None`. [`Bxdf::pdf`](super::Bxdf::pdf) is the mixture of the two densities and a sample's
/// `f` the whole BRDF.
///
/// **Precision.** `(n·h)^p` is computed, for `θh < 45°`, as `exp(p/2 · ln(1 − sin² θh))` from
/// `sin² θh = (s_x² + s_y²)/|s|²`, `s = wo + wi`, which has no cancellation near the normal (where
/// a large `p` magnifies it) and is exactly symmetric in `wo` and `wi`; beyond 45°, as `powf` of
/// the cosine.
///
/// **Laws** (measured in `tests/bxdf_blinn_phong.rs`):
/// * positive and finite for every finite unit input, grazing (`z = 10⁻⁷`), exact mirror and
///   normal configurations and opposite directions whose sum underflows included;
/// * reciprocal exactly: `f(wo, wi)` and `f(wi, wo)` are equal bit for bit over 20 000 random
///   pairs for `p` from 1 to 100, and over up to 2 000 pairs with `h` near the normal for the
///   sharp lobes (10³ to 10⁶), which random pairs rarely reach (the law suite's relative error
///   over their well-conditioned random pairs: 0);
/// * energy as above: conserved by `Normalized` up to its 7.52% margin, not by `Modified`;
/// * the sampler matches its density (the same for both forms): for `k_s = 1` the chi-square
///   p-values at θo = 0°, 30°, 60°, 80°, 89° (200 000 samples) are 0.91, 0.25, 0.31, 0.44,
///   0.026 (`p = 1`), 0.73, 0.94, 0.94, 0.60, 0.010 (`p = 10`) and 0.38, 0.51, 0.48, 0.68,
///   0.80 (`p = 100`), all above the Šidák-corrected level (at 89°, `p = 10`, four seeds of
///   2 000 000 samples give 0.87, 0.15, 0.14, 0.57); `sample` agrees with `eval` and `pdf`
///   exactly (one code path computes the lobe for both).
///
/// ```
/// use lobe::bxdf::{BlinnPhong, BlinnPhongForm, Bxdf};
/// use lobe::{Vec2, Vec3};
/// let shiny = BlinnPhong::new(0.5_f32, 0.5, 32.0, BlinnPhongForm::Normalized)?;
/// // Mirror configuration: h = n, so f = R/π + k_s (p + 8)/(8π).
/// let (wo, wi) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(-0.6, 0.0, 0.8));
/// let peak = (0.5 + 0.5 * 40.0 / 8.0) / core::f32::consts::PI;
/// assert!((shiny.eval(wo, wi) - peak).abs() < 1e-6 * peak);
/// // The handout's model reflects more than it receives for a broad lobe.
/// let seed = BlinnPhong::new(0.0_f32, 1.0, 1.0, BlinnPhongForm::Modified)?;
/// assert!(seed.albedo_at_normal() > 2.8);
/// if let Some(s) = shiny.sample(wo, Vec2::new(0.3, 0.7), 0.9) {
///     assert!(s.wi.z > 0.0 && s.pdf > 0.0);
/// }
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlinnPhong<S = f32> {
    kd: S,
    ks: S,
    /// The exponent `p`, with the base below which `(n·h)^p` is zero.
    power: Power,
    form: BlinnPhongForm,
    /// `R / π`.
    diffuse_over_pi: S,
    /// `k_s K(p)`.
    glossy: S,
    /// The probability of sampling the diffuse lobe.
    p_diffuse: f32,
    /// `(1 − P_d)(p + 1)/(2π) / 2`: the glossy share of the pdf, over `(n·h)^p / |wo + wi|`.
    pdf_glossy: f32,
}

impl<S: Spectrum> BlinnPhong<S> {
    /// The largest accepted exponent.
    pub const MAX_EXPONENT: f32 = 1e6;

    /// A Blinn-Phong BRDF with diffuse weight `kd` ([the handout's](crate::handouts#seed-003)
    /// reflectance `R`), specular
    /// weight `ks`, exponent
    /// `exponent` and the lobe's `form`.
    ///
    /// # Errors
    /// [`ParamError`] naming `kd` or `ks` for a channel that is NaN or outside `[0, 1]`,
    /// `kd + ks` for a channel where their sum exceeds 1, or `exponent` for NaN or a value
    /// outside `[0, 1e6]`.
    pub fn new(kd: S, ks: S, exponent: f32, form: BlinnPhongForm) -> Result<Self, ParamError> {
        let (kd, ks, p, p_diffuse) = checked_parameters(kd, ks, exponent)?;
        Ok(Self {
            kd,
            ks,
            power: Power::new(p),
            form,
            diffuse_over_pi: kd * FRAC_1_PI,
            glossy: ks * lobe_factor(form, p),
            p_diffuse,
            pdf_glossy: (1.0 - p_diffuse) * cos_power_norm(p) * 0.5,
        })
    }

    getters! {
        /// The diffuse weight `k_d` ([the handout's](crate::handouts#seed-003) `R`).
        kd: S,
        /// The specular weight `k_s`.
        ks: S,
        /// Which lobe.
        form: BlinnPhongForm,
    }

    /// The exponent `p`.
    #[inline]
    #[must_use]
    pub fn exponent(&self) -> f32 {
        self.power.exponent()
    }

    /// The directional albedo at normal incidence, in closed form:
    /// `R + k_s K(p) · 8π (p + 2^(−p/2)) / ((p + 2)(p + 4))`. (With `wo = n`, `θi = 2θh` and
    /// `dωi = 4 cos θh dωh`, so the lobe integrates `cos^(p+1) θh cos 2θh` over
    /// `θh ∈ [0, π/4]`.) It is the largest albedo over the viewing angles, as measured for
    /// the exponents tested; above 1 it measures the model's energy gain.
    #[must_use]
    pub fn albedo_at_normal(&self) -> S {
        let p = self.power.exponent();
        let lobe =
            8.0 * PI * (p + exp(-0.5 * core::f32::consts::LN_2 * p)) / ((p + 2.0) * (p + 4.0));
        self.kd + self.glossy * lobe
    }

    /// `((n·h)^p, |wo + wi|)` for `wo`, `wi` above the surface; `(0, 1)` when `wo + wi`
    /// underflows (subnormal, opposite grazing directions).
    #[inline(always)]
    fn lobe(&self, wo: Vec3, wi: Vec3) -> (f32, f32) {
        let s = wo + wi;
        let sxy = s.x * s.x + s.y * s.y;
        let s2 = sxy + s.z * s.z;
        if !(s2 >= f32::MIN_POSITIVE) {
            return (0.0, 1.0);
        }
        let len = sqrt(s2);
        (self.power.cos_pow(s.z / len, sxy / s2), len)
    }

    /// The BRDF from `(n·h)^p`.
    #[inline(always)]
    fn value(&self, (cos_pow, _): (f32, f32)) -> S {
        self.diffuse_over_pi + self.glossy * cos_pow
    }

    /// The mixture density from `cos θi`, `(n·h)^p` and `|wo + wi| = 2 (wo·h)`.
    #[inline(always)]
    fn density(&self, cos_i: f32, (cos_pow, len): (f32, f32)) -> f32 {
        self.p_diffuse * cosine_hemisphere_pdf(cos_i) + self.pdf_glossy * cos_pow / len
    }

    /// A direction of the glossy lobe: `wo` reflected about a half vector drawn from
    /// `cos^p θh`; below the surface when `wo·h ≤ 0`, which the caller refuses.
    #[inline(always)]
    fn sample_glossy(&self, wo: Vec3, u: Vec2) -> Vec3 {
        reflect_away(
            wo,
            crate::sampling::cosine_power_hemisphere(u, self.power.exponent()),
        )
    }
}

/// `K(p)`: 1 for [the handout's](crate::handouts#seed-003) form, `(p + 8)/(8π)` for the normalised
/// one.
fn lobe_factor(form: BlinnPhongForm, p: f32) -> f32 {
    match form {
        BlinnPhongForm::Modified => 1.0,
        BlinnPhongForm::Normalized => (p + 8.0) * 0.125 * FRAC_1_PI,
    }
}

diffuse_glossy_model!(BlinnPhong);
