//! pbrt-v4's diffuse transmission: Lambertian reflection and Lambertian transmission.

use super::{BxdfSample, Lobes, Prepare, usable_pdf};
use crate::param::{ParamError, unit_interval};
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, picks};
use crate::spectrum::Spectrum;
use core::f32::consts::FRAC_1_PI;
use glam::{Vec2, Vec3};

/// A thin diffuse sheet (a leaf, paper, a lampshade): Lambertian reflection of reflectance `R`
/// on the side light arrives from and Lambertian transmission of transmittance `T` to the
/// other side,
///
/// ```text
/// f(wo, wi) = R / π    wo, wi on the same side
/// f(wo, wi) = T / π    on opposite sides
/// ```
///
/// pbrt-v4's `DiffuseTransmissionBxDF` (*PBR* 4th ed., §9.3.2 and the `diffusetransmission`
/// material). Both sides alike; no refraction (the crossed index is 1).
///
/// Sampling (pbrt-v4's): reflection with probability `p_r = max R / (max R + max T)` (the
/// largest channels), transmission otherwise, each by cosine-weighted directions on its side:
/// `pdf = p_r |cos θi| / π` or `(1 − p_r) |cos θi| / π`.
///
/// Laws (measured by `tests/bxdf_diffuse_transmission.rs`): positive; reciprocal (`f` is
/// symmetric); directional albedo `R + T` for every `wo`, exactly (a closed form: the
/// constructor requires `R + T ≤ 1`, so it conserves energy), which both estimators measure;
/// the sampler draws its pdf (chi-square).
///
/// ```
/// use lobe::bxdf::{Bxdf, DiffuseTransmission};
/// use lobe::{Vec2, Vec3};
/// let leaf = DiffuseTransmission::new(0.3_f32, 0.5)?;
/// let s = leaf.sample(Vec3::Z, Vec2::new(0.4, 0.6), 0.9).unwrap(); // uc above 3/8: transmitted
/// assert!(s.wi.z < 0.0);
/// assert!((s.weight() - 0.8).abs() < 1e-6); // R + T, for every sample of a grey sheet
/// assert!(DiffuseTransmission::new(0.6_f32, 0.5).is_err()); // R + T > 1
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffuseTransmission<S = f32> {
    reflectance: S,
    transmittance: S,
    /// The probability of sampling reflection, `max R / (max R + max T)` (0 when both are 0).
    p_reflect: f32,
}

impl<S: Spectrum> DiffuseTransmission<S> {
    /// A sheet of reflectance `R = reflectance` and transmittance `T = transmittance`, each in
    /// `[0, 1]` per channel with `R + T ≤ 1`.
    ///
    /// # Errors
    /// [`ParamError`] naming `reflectance` or `transmittance` for a channel that is NaN or
    /// outside `[0, 1]`, and `transmittance` where `R + T > 1` in a channel.
    pub fn new(reflectance: S, transmittance: S) -> Result<Self, ParamError> {
        let reflectance = unit_interval("reflectance", reflectance)?;
        let transmittance = unit_interval("transmittance", transmittance)?;
        for c in 0..S::CHANNELS {
            let (r, t) = (reflectance.channel(c), transmittance.channel(c));
            if !(r + t <= 1.0) {
                return Err(ParamError::new("transmittance", t, "[0, 1 − reflectance]"));
            }
        }
        let (pr, pt) = (reflectance.max_channel(), transmittance.max_channel());
        let p_reflect = if pr + pt > 0.0 { pr / (pr + pt) } else { 0.0 };
        Ok(Self {
            reflectance,
            transmittance,
            p_reflect,
        })
    }

    /// The directional albedo `R + T`, the same for every `wo`.
    #[must_use]
    pub fn albedo(&self) -> S {
        self.reflectance + self.transmittance
    }

    /// `R`.
    #[must_use]
    pub fn reflectance(&self) -> S {
        self.reflectance
    }

    /// `T`.
    #[must_use]
    pub fn transmittance(&self) -> S {
        self.transmittance
    }

    /// The value and density for `wi` against `wo`.
    #[inline(always)]
    fn eval_pdf(&self, wo: Vec3, wi: Vec3) -> (S, f32) {
        let (a, b) = (wo.z, wi.z);
        // `|`, not `||`, and the side's coefficients selected before they are scaled: no
        // branch the batched loop would have to keep (`lobe::batch`).
        if (a == 0.0) | (b == 0.0) {
            return (S::zero(), 0.0);
        }
        let cos = cosine_hemisphere_pdf(b.abs());
        let (f, p) = if (a > 0.0) == (b > 0.0) {
            (self.reflectance, self.p_reflect)
        } else {
            (self.transmittance, 1.0 - self.p_reflect)
        };
        (f * FRAC_1_PI, p * cos)
    }
}

impl<S: Spectrum> Prepare for DiffuseTransmission<S> {
    type Spectrum = S;
    /// `wo` itself.
    type Prepared = Vec3;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Vec3 {
        wo
    }

    #[inline(always)]
    fn eval_prepared(&self, &wo: &Vec3, wi: Vec3) -> S {
        self.eval_pdf(wo, wi).0
    }

    #[inline(always)]
    fn pdf_prepared(&self, &wo: &Vec3, wi: Vec3) -> f32 {
        self.eval_pdf(wo, wi).1
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, &wo: &Vec3, wi: Vec3) -> (S, f32) {
        self.eval_pdf(wo, wi)
    }

    #[inline(always)]
    fn sample_prepared(&self, &wo: &Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<S>> {
        // A tangent `wo` has no sample: `eval_pdf` gives it the density 0, refused below.
        let reflect = picks(uc, self.p_reflect);
        let mut wi = cosine_hemisphere(u);
        // Reflection stays on wo's side, transmission goes to the other.
        wi.z = if (wo.z < 0.0) == reflect { -wi.z } else { wi.z };
        let (f, pdf) = self.eval_pdf(wo, wi);
        if !usable_pdf(pdf) {
            return None;
        }
        let lobe = if reflect {
            Lobes::DIFFUSE_REFLECTION
        } else {
            Lobes::DIFFUSE | Lobes::TRANSMISSION
        };
        Some(BxdfSample::new(wi, f, pdf, lobe))
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        // The sides the sampler can draw (both black: transmission, where it goes).
        let mut lobes = Lobes::NONE;
        if self.p_reflect > 0.0 {
            lobes |= Lobes::DIFFUSE_REFLECTION;
        }
        if self.p_reflect < 1.0 {
            lobes |= Lobes::DIFFUSE | Lobes::TRANSMISSION;
        }
        lobes
    }
}
