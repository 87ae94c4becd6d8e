//! Checks of a BSDF: albedo by two independent estimators, reciprocity, the sampler against
//! its pdf, and the agreement of `sample` with `eval` and `pdf`.
//!
//! The laws are checked on `f32` models (they hold per channel); a spectral model is checked
//! by instantiating it on `f32`.

use super::{Accumulator, Chi2Config, Chi2Report, Estimate, Pcg32, chi2_sphere_rng};
use crate::bxdf::Bxdf;
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
use glam::Vec3;

/// The stream of these checks' generator, apart from the chi-square test's.
const STREAM: u64 = 0x0062_7364;

/// Settings of the Monte Carlo checks in this module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BxdfCheck {
    /// Samples per estimate. Default 200 000.
    pub samples: usize,
    /// Seed of the [`Pcg32`] that draws the random numbers. Default 1.
    pub seed: u64,
}

impl Default for BxdfCheck {
    fn default() -> Self {
        Self {
            samples: 200_000,
            seed: 1,
        }
    }
}

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` estimated with the model's own sampler:
/// the mean of [`BxdfSample::weight`](crate::bxdf::BxdfSample::weight), a failed sample
/// counting as zero. Includes delta lobes.
#[must_use]
pub fn albedo_sampled<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    check: &BxdfCheck,
) -> Estimate {
    let mut rng = Pcg32::new(check.seed, STREAM);
    let mut acc = Accumulator::new();
    for _ in 0..check.samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        let w = bxdf
            .sample(wo, u, uc)
            .map_or(0.0, |s| f64::from(s.weight()));
        acc.push(w);
    }
    acc.finish()
}

/// The directional albedo estimated independently of the model's sampler: `wi` cosine-
/// distributed over the upper hemisphere, and also over the lower one (each with probability
/// ½) when the model transmits. Misses delta lobes, which have no density.
#[must_use]
pub fn albedo_cosine<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    check: &BxdfCheck,
) -> Estimate {
    let both_sides = bxdf.lobes().is_transmissive();
    let mut rng = Pcg32::new(check.seed, STREAM ^ 1);
    let mut acc = Accumulator::new();
    for _ in 0..check.samples {
        let mut wi = cosine_hemisphere(rng.next_vec2());
        let mut pdf = f64::from(cosine_hemisphere_pdf(wi.z));
        if both_sides {
            pdf *= 0.5;
            if rng.next_f32() < 0.5 {
                wi.z = -wi.z;
            }
        }
        let value = if pdf > 0.0 {
            f64::from(bxdf.eval(wo, wi)) * f64::from(wi.z.abs()) / pdf
        } else {
            0.0
        };
        acc.push(value);
    }
    acc.finish()
}

/// The chi-square test of [`Bxdf::sample`] against [`Bxdf::pdf`] for the viewer direction
/// `wo`. Samples from delta lobes, and failed samples, count as "no sample": `pdf` then
/// integrates to less than one, and the test checks that the missing mass matches them.
pub fn chi2_bxdf<B: Bxdf + ?Sized>(bxdf: &B, wo: Vec3, config: &Chi2Config) -> Chi2Report {
    chi2_sphere_rng(
        |rng| {
            let u = rng.next_vec2();
            let uc = rng.next_f32();
            bxdf.sample(wo, u, uc)
                .filter(|s| !s.is_specular())
                .map(|s| s.wi)
        },
        |wi| f64::from(bxdf.pdf(wo, wi)),
        config,
    )
}

/// How far [`Bxdf::sample`]'s `f` and `pdf` are from [`Bxdf::eval`] and [`Bxdf::pdf`] at the
/// sampled direction: the largest relative differences `(f, pdf)` over `check.samples`
/// non-delta samples.
#[must_use]
pub fn sample_consistency<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    check: &BxdfCheck,
) -> (f64, f64) {
    let rel = |a: f32, b: f32| {
        let (a, b) = (f64::from(a), f64::from(b));
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    };
    let mut rng = Pcg32::new(check.seed, STREAM ^ 2);
    let (mut worst_f, mut worst_pdf) = (0.0_f64, 0.0_f64);
    for _ in 0..check.samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        if let Some(s) = bxdf.sample(wo, u, uc).filter(|s| !s.is_specular()) {
            worst_f = worst_f.max(rel(s.f, bxdf.eval(wo, s.wi)));
            worst_pdf = worst_pdf.max(rel(s.pdf, bxdf.pdf(wo, s.wi)));
        }
    }
    (worst_f, worst_pdf)
}

/// The relative reciprocity error of a pair of directions:
/// `|f(wo, wi)/η_o² − f(wi, wo)/η_i²| / max(…)`, where `η_o`, `η_i` are the indices of the
/// media on the sides of `wo` and `wi` (`1` above the surface, `eta` below). With `eta = 1`
/// (or for reflection, where both sides agree) this is plain Helmholtz reciprocity; across
/// an interface it is the generalised form for radiance transport (Veach 1997, eq. 5.12).
/// Zero when both values are zero.
#[must_use]
pub fn reciprocity_error<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
) -> f64 {
    let side = |w: Vec3| if w.z >= 0.0 { 1.0 } else { f64::from(eta) };
    let a = f64::from(bxdf.eval(wo, wi)) / (side(wo) * side(wo));
    let b = f64::from(bxdf.eval(wi, wo)) / (side(wi) * side(wi));
    if a == b {
        0.0
    } else {
        (a - b).abs() / a.abs().max(b.abs())
    }
}
