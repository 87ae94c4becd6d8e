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
/// non-delta samples; NaN if any comparison is NaN.
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
            // `f64::max` drops NaN; keep it, so that a NaN can only make things worse.
            let keep = |worst: f64, x: f64| {
                if x.is_nan() || worst.is_nan() {
                    f64::NAN
                } else {
                    worst.max(x)
                }
            };
            worst_f = keep(worst_f, rel(s.f, bxdf.eval(wo, s.wi)));
            worst_pdf = keep(worst_pdf, rel(s.pdf, bxdf.pdf(wo, s.wi)));
        }
    }
    (worst_f, worst_pdf)
}

/// One reciprocity measurement: the two sides of the (generalised) reciprocity relation for
/// a pair of directions, and how far apart f32 round-off alone can put them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReciprocityPair {
    /// `f(wo, wi) / η_o²`.
    pub forward: f64,
    /// `f(wi, wo) / η_i²`.
    pub backward: f64,
    /// The round-off allowance: the largest change of either side when `wo` or `wi` moves by
    /// a few ulps (four perturbations of `4 ε` radians each), twice, plus an absolute
    /// [`SUBNORMAL_FLOOR`]. An ill-conditioned pair (a microfacet seen edge-on) gets a large
    /// allowance; a well-conditioned one, almost none.
    pub round_off: f64,
}

impl ReciprocityPair {
    /// `|forward − backward| / max(|forward|, |backward|)`, zero when both are zero.
    #[must_use]
    pub fn relative_error(&self) -> f64 {
        let (a, b) = (self.forward, self.backward);
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    }

    /// True when the sides agree within `rel_tol` relative error plus the round-off
    /// allowance.
    #[must_use]
    pub fn holds(&self, rel_tol: f64) -> bool {
        let (a, b) = (self.forward, self.backward);
        (a - b).abs() <= rel_tol * a.abs().max(b.abs()) + self.round_off
    }
}

/// Values this small are products whose intermediate factors went below
/// `f32::MIN_POSITIVE` and lost their relative precision (a far tail of `D`); reciprocity is
/// not checked below it.
pub const SUBNORMAL_FLOOR: f64 = 1e-30;

/// Measures reciprocity for one pair: `f(wo, wi)/η_o²` against `f(wi, wo)/η_i²`, where
/// `η_o`, `η_i` are the indices on the sides of `wo` and `wi` (`1` above the surface, `eta`
/// below). With `eta = 1`, or both directions on one side, this is plain Helmholtz
/// reciprocity; across an interface it is the generalised form for radiance transport (Veach
/// 1997, eq. 5.12). For a model in importance mode pass `1/η`.
#[must_use]
pub fn reciprocity_pair<B: Bxdf<Spectrum = f32> + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
) -> ReciprocityPair {
    let side = |w: Vec3| if w.z >= 0.0 { 1.0 } else { f64::from(eta) };
    let forward = |a: Vec3, b: Vec3| f64::from(bxdf.eval(a, b)) / (side(a) * side(a));
    let (a, b) = (forward(wo, wi), forward(wi, wo));
    let mut spread = 0.0_f64;
    let eps = 4.0 * f32::EPSILON;
    for k in 0..4 {
        let (po, pi) = (nudge(wo, k, eps), nudge(wi, k, eps));
        spread = spread
            .max((forward(po, wi) - a).abs())
            .max((forward(wo, pi) - a).abs())
            .max((forward(wi, po) - b).abs())
            .max((forward(pi, wo) - b).abs());
    }
    ReciprocityPair {
        forward: a,
        backward: b,
        round_off: 2.0 * spread + SUBNORMAL_FLOOR,
    }
}

/// `w` turned by `eps` radians toward one of four tangent directions (`k` = 0…3).
fn nudge(w: Vec3, k: usize, eps: f32) -> Vec3 {
    let frame = crate::Frame::from_normal(w);
    let t = match k {
        0 => frame.x,
        1 => -frame.x,
        2 => frame.y,
        _ => -frame.y,
    };
    (w + t * eps).normalize()
}
