//! The laws of a BSDF, measured, reported and checked: positivity, reciprocity (plain and
//! generalised across an interface), the energy bound by two independent albedo estimators,
//! the sampler against its pdf (chi-square), and the agreement of `sample` with `eval` and
//! `pdf`; [`check_bxdf`] runs every law that applies.
//!
//! The file reads top to bottom: the measurements (the albedo estimators, the chi-square test
//! of one viewer direction, the consistency of one viewer direction, one reciprocity pair),
//! then the law reports built on them, then [`check_bxdf`].
//!
//! **Any spectrum.** A law holds per channel, so the reports accept a model of any
//! [`Spectrum`]: each measurement runs once, on the same random numbers, and keeps one tally
//! per channel (an albedo estimate, a count of violations, a largest error); the report is the
//! worst channel's, and for more than one channel its detail names that channel ("blue
//! channel (worst of 3): …"). A monochrome model's reports are exactly what they were before
//! spectra were accepted. The sampler's chi-square test does not depend on the spectrum. The
//! public measurements take `f32` models; [`Channel`] views one channel of a spectral model as
//! one.

use super::config::Config;
use super::report::{Law, LawReport, Report};
use crate::Spectrum;
use crate::bxdf::{Bxdf, BxdfSample, Lobes};
use crate::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, uniform_sphere};
use crate::verify::stats::{
    Accumulator, Chi2Config, Chi2Report, Estimate, Pcg32, chi2_sphere_rng, sidak,
    two_sided_quantile,
};
use glam::{Vec2, Vec3};
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

/// The relative round-off of a weight computed in `f32` (a few ulps): what lets a
/// zero-variance estimator match an exact bound.
const F32_ROUND_OFF: f64 = 1e-6;

/// The stream of these checks' generator, apart from the chi-square test's.
const STREAM: u64 = 0x0062_7364;

// ---------------------------------------------------------------------------------------
// Channels
// ---------------------------------------------------------------------------------------

/// One channel of a spectral model, as a monochrome model: `eval` and `sample`'s `f` are that
/// channel of the model's, `pdf`, the sampled directions and the lobes are the model's own.
///
/// The law reports check every channel by themselves; this is for the measurements, which
/// take `f32` models:
///
/// ```
/// use lobe::bxdf::Lambert;
/// use lobe::verify::{albedo_sampled, Channel, Config};
/// use lobe::Vec3;
/// let rgb = Lambert::new(Vec3::new(0.2, 0.5, 0.8))?;
/// let quick = Config { albedo_samples: 1_000, ..Config::default() };
/// let blue = albedo_sampled(&Channel::new(&rgb, 2), Vec3::Z, &quick);
/// // Every weight of Lambert's sampler is its ρ, to f32 round-off.
/// assert!((blue.mean - 0.8).abs() < 1e-6, "{blue}");
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Debug)]
pub struct Channel<'a, B: ?Sized> {
    /// The spectral model.
    bxdf: &'a B,
    /// Which of its channels.
    index: usize,
}

impl<B: ?Sized> Clone for Channel<'_, B> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<B: ?Sized> Copy for Channel<'_, B> {}

impl<'a, B: Bxdf + ?Sized> Channel<'a, B> {
    /// Channel `index` of `bxdf`.
    ///
    /// # Panics
    ///
    /// If `index` is not below the spectrum's [`CHANNELS`](Spectrum::CHANNELS).
    #[must_use]
    pub fn new(bxdf: &'a B, index: usize) -> Self {
        assert!(
            index < B::Spectrum::CHANNELS,
            "channel {index} of a {}-channel spectrum",
            B::Spectrum::CHANNELS
        );
        Self { bxdf, index }
    }

    /// Which channel this is.
    #[must_use]
    pub fn index(&self) -> usize {
        self.index
    }
}

impl<B: Bxdf + ?Sized> Bxdf for Channel<'_, B> {
    type Spectrum = f32;

    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.bxdf.eval(wo, wi).channel(self.index)
    }

    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        self.bxdf.sample(wo, u, uc).map(|s| BxdfSample {
            wi: s.wi,
            f: s.f.channel(self.index),
            pdf: s.pdf,
            lobe: s.lobe,
            eta: s.eta,
        })
    }

    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.bxdf.pdf(wo, wi)
    }

    fn lobes(&self) -> Lobes {
        self.bxdf.lobes()
    }

    fn stochastic(&self) -> bool {
        self.bxdf.stochastic()
    }

    fn eval_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> f32 {
        self.bxdf.eval_seeded(wo, wi, seed).channel(self.index)
    }

    fn pdf_seeded(&self, wo: Vec3, wi: Vec3, seed: u64) -> f32 {
        self.bxdf.pdf_seeded(wo, wi, seed)
    }
}

/// The number of channels of `bxdf`'s spectrum.
pub(super) fn channels<B: Bxdf + ?Sized>(_: &B) -> usize {
    B::Spectrum::CHANNELS
}

/// What a report calls channel `i` of `n`: the red, green and blue channel of three.
fn channel_name(i: usize, n: usize) -> String {
    match (n, i) {
        (3, 0) => "red channel".into(),
        (3, 1) => "green channel".into(),
        (3, 2) => "blue channel".into(),
        _ => format!("channel {i}"),
    }
}

/// The report of the worst channel: a failed one before a passed one, then the larger
/// figure (NaN the largest), then the first. With more than one channel its detail names the
/// channel ("blue channel (worst of 3): …", "… (worst of 3, tied with 2 others)" when other
/// channels measured the same). Every figure of a BSDF law is worse the larger it is.
pub(super) fn worst_channel(mut reports: Vec<LawReport>) -> LawReport {
    let n = reports.len();
    if n == 1 {
        return reports.swap_remove(0);
    }
    let worse = |a: &LawReport, b: &LawReport| {
        if a.passed != b.passed {
            !a.passed
        } else {
            (a.figure.is_nan() && !b.figure.is_nan()) || a.figure > b.figure
        }
    };
    let mut at = 0;
    for i in 1..n {
        if worse(&reports[i], &reports[at]) {
            at = i;
        }
    }
    let ties = reports
        .iter()
        .enumerate()
        .filter(|&(i, r)| i != at && !worse(&reports[at], r))
        .count();
    let mut report = reports.swap_remove(at);
    let tied = match ties {
        0 => String::new(),
        1 => String::from(", tied with 1 other"),
        k => format!(", tied with {k} others"),
    };
    report.detail = format!(
        "{} (worst of {n}{tied}): {}",
        channel_name(at, n),
        report.detail
    );
    report
}

/// One [`Accumulator`] per channel.
struct PerChannel(Vec<Accumulator>);

impl PerChannel {
    /// Empty accumulators for `bxdf`'s channels.
    fn new<B: Bxdf + ?Sized>(bxdf: &B) -> Self {
        Self(vec![Accumulator::new(); channels(bxdf)])
    }

    /// Adds `map` of each channel of `value` (in `f64`) to that channel's accumulator.
    fn push<S: Spectrum>(&mut self, value: S, map: impl Fn(f64) -> f64) {
        for (c, a) in self.0.iter_mut().enumerate() {
            a.push(map(f64::from(value.channel(c))));
        }
    }

    /// Adds a zero to every channel.
    fn push_zero(&mut self) {
        self.0.iter_mut().for_each(|a| a.push(0.0));
    }

    /// The estimates, one per channel.
    fn finish(&self) -> Vec<Estimate> {
        self.0.iter().map(Accumulator::finish).collect()
    }
}

// ---------------------------------------------------------------------------------------
// Measurements
// ---------------------------------------------------------------------------------------

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` estimated with the model's own sampler:
/// the mean of [`BxdfSample::weight`] over `config.albedo_samples` samples drawn with
/// `config.seed`, a failed sample counting as zero. Includes delta lobes.
///
/// `config` is a `&`[`Config`] (or the older `&`[`BxdfCheck`](super::BxdfCheck)).
#[must_use]
pub fn albedo_sampled<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> Estimate
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    albedo_sampled_channels(bxdf, wo, &config.into())[0]
}

/// [`albedo_sampled`] of every channel, on the same samples.
fn albedo_sampled_channels<B: Bxdf + ?Sized>(bxdf: &B, wo: Vec3, config: &Config) -> Vec<Estimate> {
    albedo_sampled_parts(bxdf, wo, config).0
}

/// [`albedo_sampled_channels`], and on the same samples the albedo of the lobes with a
/// density (a delta sample counting zero).
fn albedo_sampled_parts<B: Bxdf + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    config: &Config,
) -> (Vec<Estimate>, Vec<Estimate>) {
    let mut rng = Pcg32::new(config.seed, STREAM);
    let (mut all, mut density) = (PerChannel::new(bxdf), PerChannel::new(bxdf));
    for _ in 0..config.albedo_samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        match bxdf.sample(wo, u, uc) {
            Some(s) => {
                all.push(s.weight(), |w| w);
                if s.is_specular() {
                    density.push_zero();
                } else {
                    density.push(s.weight(), |w| w);
                }
            }
            None => {
                all.push_zero();
                density.push_zero();
            }
        }
    }
    (all.finish(), density.finish())
}

/// The directional albedo estimated independently of the model's sampler: `wi` cosine-
/// distributed over `wo`'s hemisphere, and over both (each with probability ½) when the model
/// transmits; `config.albedo_samples` samples drawn with `config.seed`.
/// Misses delta lobes, which have no density.
///
/// `config` is a `&`[`Config`] (or the older `&`[`BxdfCheck`](super::BxdfCheck)).
#[must_use]
pub fn albedo_cosine<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> Estimate
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    albedo_cosine_channels(bxdf, wo, &config.into())[0]
}

/// [`albedo_cosine`] of every channel, on the same samples.
fn albedo_cosine_channels<B: Bxdf + ?Sized>(bxdf: &B, wo: Vec3, config: &Config) -> Vec<Estimate> {
    let both_sides = bxdf.lobes().is_transmissive();
    let mut rng = Pcg32::new(config.seed, STREAM ^ 1);
    let mut acc = PerChannel::new(bxdf);
    for _ in 0..config.albedo_samples {
        let mut wi = cosine_hemisphere(rng.next_vec2());
        let mut pdf = f64::from(cosine_hemisphere_pdf(wi.z));
        if both_sides {
            pdf *= 0.5;
            if rng.next_f32() < 0.5 {
                wi.z = -wi.z;
            }
        } else if wo.z < 0.0 {
            // A reflection model seen from below (a two-sided one) reflects below.
            wi.z = -wi.z;
        }
        if pdf > 0.0 {
            let cos = f64::from(wi.z.abs());
            acc.push(bxdf.eval(wo, wi), |f| f * cos / pdf);
        } else {
            acc.push_zero();
        }
    }
    acc.finish()
}

/// The directional albedo at `wo` by two independent estimators.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Albedo {
    /// By the model's own sampler, delta lobes included.
    pub sampled: Estimate,
    /// By cosine sampling, or `None` for a model with delta lobes (which it cannot see).
    pub cosine: Option<Estimate>,
    /// For a model with delta lobes and lobes with a density both: the albedo of the lobes
    /// with a density, by the model's sampler (on the samples of `sampled`, a delta sample
    /// counting zero) and by cosine sampling. `None` for other models.
    pub density_lobes: Option<(Estimate, Estimate)>,
}

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` at `wo` by the model's sampler and, for
/// a model without delta lobes, by cosine sampling ([`albedo_sampled`], [`albedo_cosine`]);
/// for a model with both kinds of lobe, the part of the lobes with a density by both.
#[must_use]
pub fn albedo<B: Bxdf<Spectrum = f32> + ?Sized>(bxdf: &B, wo: Vec3, config: &Config) -> Albedo {
    albedo_channels(bxdf, wo, config)[0]
}

/// [`albedo`] of every channel.
fn albedo_channels<B: Bxdf + ?Sized>(bxdf: &B, wo: Vec3, config: &Config) -> Vec<Albedo> {
    let lobes = bxdf.lobes();
    let mixed = lobes.is_specular() && lobes.is_non_specular();
    let (sampled, part) = albedo_sampled_parts(bxdf, wo, config);
    let cosine = lobes
        .is_non_specular()
        .then(|| albedo_cosine_channels(bxdf, wo, config));
    sampled
        .into_iter()
        .enumerate()
        .map(|(c, sampled)| {
            let cos = cosine.as_ref().map(|e| e[c]);
            Albedo {
                sampled,
                cosine: cos.filter(|_| !mixed),
                density_lobes: cos.filter(|_| mixed).map(|cos| (part[c], cos)),
            }
        })
        .collect()
}

/// The chi-square test of [`Bxdf::sample`] against [`Bxdf::pdf`] for the viewer direction
/// `wo`. Samples from delta lobes, and failed samples, count as "no sample": `pdf` then
/// integrates to less than one, and the test checks that the missing mass matches them. The
/// spectrum plays no part.
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
/// sampled direction: the largest relative differences `(f, pdf)` over the non-delta samples
/// among `config.consistency_samples` drawn with `config.seed`; NaN if any
/// comparison is NaN.
///
/// `config` is a `&`[`Config`] (or the older `&`[`BxdfCheck`](super::BxdfCheck)).
#[must_use]
pub fn sample_consistency<'c, B, C>(bxdf: &B, wo: Vec3, config: &'c C) -> (f64, f64)
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    &'c C: Into<Config>,
{
    sample_consistency_channels(bxdf, wo, &config.into())[0]
}

/// [`sample_consistency`] of every channel, on the same samples (the `pdf` part is shared).
fn sample_consistency_channels<B: Bxdf + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    config: &Config,
) -> Vec<(f64, f64)> {
    let rel = |a: f32, b: f32| {
        let (a, b) = (f64::from(a), f64::from(b));
        if a == b {
            0.0
        } else {
            (a - b).abs() / a.abs().max(b.abs())
        }
    };
    // `f64::max` drops NaN; keep it, so that a NaN can only make things worse.
    let keep = |worst: f64, x: f64| {
        if x.is_nan() || worst.is_nan() {
            f64::NAN
        } else {
            worst.max(x)
        }
    };
    let mut rng = Pcg32::new(config.seed, STREAM ^ 2);
    let (mut worst_f, mut worst_pdf) = (vec![0.0_f64; channels(bxdf)], 0.0_f64);
    for _ in 0..config.consistency_samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        if let Some(s) = bxdf.sample(wo, u, uc).filter(|s| !s.is_specular()) {
            let f = bxdf.eval(wo, s.wi);
            for (c, w) in worst_f.iter_mut().enumerate() {
                *w = keep(*w, rel(s.f.channel(c), f.channel(c)));
            }
            worst_pdf = keep(worst_pdf, rel(s.pdf, bxdf.pdf(wo, s.wi)));
        }
    }
    worst_f.into_iter().map(|f| (f, worst_pdf)).collect()
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

    /// True when both sides are finite and agree within `rel_tol` relative error plus the
    /// round-off allowance (an infinite side would meet its own infinite allowance).
    #[must_use]
    pub fn holds(&self, rel_tol: f64) -> bool {
        let (a, b) = (self.forward, self.backward);
        a.is_finite()
            && b.is_finite()
            && (a - b).abs() <= rel_tol * a.abs().max(b.abs()) + self.round_off
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
    reciprocity_pair_channels(bxdf, wo, wi, eta)[0]
}

/// [`reciprocity_pair`] of every channel, from the same evaluations.
fn reciprocity_pair_channels<B: Bxdf + ?Sized>(
    bxdf: &B,
    wo: Vec3,
    wi: Vec3,
    eta: f32,
) -> Vec<ReciprocityPair> {
    let side = |w: Vec3| if w.z >= 0.0 { 1.0 } else { f64::from(eta) };
    // `f(a, b)` and the `η²` it is divided by.
    let forward = |a: Vec3, b: Vec3| (bxdf.eval(a, b), side(a) * side(a));
    let value = |(f, scale): &(B::Spectrum, f64), c: usize| f64::from(f.channel(c)) / scale;
    let (fwd, bwd) = (forward(wo, wi), forward(wi, wo));
    let eps = 4.0 * f32::EPSILON;
    let nudged: Vec<_> = (0..4)
        .map(|k| {
            let (po, pi) = (nudge(wo, k, eps), nudge(wi, k, eps));
            [
                forward(po, wi),
                forward(wo, pi),
                forward(wi, po),
                forward(pi, wo),
            ]
        })
        .collect();
    (0..channels(bxdf))
        .map(|c| {
            let (a, b) = (value(&fwd, c), value(&bwd, c));
            let mut spread = 0.0_f64;
            for [po_wi, wo_pi, wi_po, pi_wo] in &nudged {
                spread = spread
                    .max((value(po_wi, c) - a).abs())
                    .max((value(wo_pi, c) - a).abs())
                    .max((value(wi_po, c) - b).abs())
                    .max((value(pi_wo, c) - b).abs());
            }
            ReciprocityPair {
                forward: a,
                backward: b,
                round_off: 2.0 * spread + SUBNORMAL_FLOOR,
            }
        })
        .collect()
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

// ---------------------------------------------------------------------------------------
// Laws
// ---------------------------------------------------------------------------------------

/// A direction for the positivity check: uniform on the sphere (half the draws), within
/// 1e-7…1e-2 of the horizon (a quarter), or one of the places where formulas divide by zero
/// (a quarter): exactly on the horizon (`z = ±0`), a subnormal `z`, or exactly `±z`.
fn adversarial_direction(rng: &mut Pcg32) -> Vec3 {
    let u = rng.next_vec2();
    let pick = rng.next_f32();
    let sign = if rng.next_f32() < 0.5 { 1.0 } else { -1.0 };
    let phi = core::f32::consts::TAU * u.y;
    let around = |z: f32| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    };
    if pick < 0.5 {
        uniform_sphere(u)
    } else if pick < 0.75 {
        around(sign * 10f32.powf(-7.0 + 5.0 * u.x))
    } else if pick < 0.85 {
        around(sign * 0.0)
    } else if pick < 0.92 {
        around(sign * 1e-40)
    } else {
        Vec3::new(0.0, 0.0, sign)
    }
}

/// **Positivity** and totality: over `config.pairs` adversarial direction pairs (uniform,
/// grazing down to `cos θ = 1e-7`, exactly on the horizon, subnormal, and exactly along the
/// normal), `eval` and `pdf` are finite and non-negative, and every sample has a unit `wi`, a
/// finite non-negative `f` and a positive finite `pdf`; per channel. The figure is the number
/// of violations (of the worst channel).
#[must_use]
pub fn positivity<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut rng = Pcg32::new(config.seed, 0x0070_6f73);
    let n = channels(bxdf);
    let mut violations = vec![0usize; n];
    let mut details = vec![String::from("every value finite and non-negative"); n];
    for _ in 0..config.pairs {
        let (wo, wi) = (
            adversarial_direction(&mut rng),
            adversarial_direction(&mut rng),
        );
        let (f, p) = (bxdf.eval(wo, wi), bxdf.pdf(wo, wi));
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        let sample = bxdf.sample(wo, u, uc);
        for c in 0..n {
            let fc = f.channel(c);
            let bad_value = !(fc.is_finite() && fc >= 0.0 && p.is_finite() && p >= 0.0);
            let bad_sample = sample.is_some_and(|s| {
                let sf = s.f.channel(c);
                !(s.wi.is_finite()
                    && (s.wi.length() - 1.0).abs() < 1e-4
                    && sf.is_finite()
                    && sf >= 0.0
                    && s.pdf.is_finite()
                    && s.pdf > 0.0)
            });
            if bad_value || bad_sample {
                if violations[c] == 0 {
                    details[c] = if bad_value {
                        format!("first at wo = {wo:?}, wi = {wi:?}: eval = {fc}, pdf = {p}")
                    } else {
                        format!("first at wo = {wo:?}, u = {u:?}, uc = {uc}: {sample:?}")
                    };
                }
                violations[c] += 1;
            }
        }
    }
    let reports = violations
        .into_iter()
        .zip(details)
        .map(|(violations, detail)| LawReport {
            law: Law::Positivity,
            passed: violations == 0,
            figure: violations as f64,
            uncertainty: 0.0,
            figure_name: "violations",
            budget: format!("{} direction pairs", config.pairs),
            detail,
        })
        .collect();
    worst_channel(reports)
}

/// The reciprocity tally of one channel.
#[derive(Default)]
struct ReciprocityTally {
    /// The largest relative error over the well-conditioned pairs (NaN after a NaN).
    worst: f64,
    /// Pairs checked against their round-off allowance only.
    ill: usize,
    /// Pairs that failed.
    failures: usize,
    /// The first failure.
    detail: String,
}

/// **Reciprocity**: over `config.pairs` random pairs, `f(wo, wi)/η_o² = f(wi, wo)/η_i²`
/// within `config.reciprocity_tolerance` plus each pair's round-off allowance (see
/// [`ReciprocityPair`]), per channel; `config.eta` gives the generalised form. The figure is
/// the largest relative error over the well-conditioned pairs (of the worst channel).
#[must_use]
pub fn reciprocity<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut rng = Pcg32::new(config.seed, 0x0072_6563);
    let tol = config.reciprocity_tolerance;
    let mut tallies: Vec<ReciprocityTally> = (0..channels(bxdf))
        .map(|_| ReciprocityTally::default())
        .collect();
    for _ in 0..config.pairs {
        let (wo, wi) = (
            uniform_sphere(rng.next_vec2()),
            uniform_sphere(rng.next_vec2()),
        );
        let pairs = reciprocity_pair_channels(bxdf, wo, wi, config.eta);
        for (t, r) in tallies.iter_mut().zip(pairs) {
            if !r.holds(tol) {
                if t.failures == 0 {
                    t.detail = format!(
                        "first failure at wo = {wo:?}, wi = {wi:?}: {:.6e} vs {:.6e}",
                        r.forward, r.backward
                    );
                }
                t.failures += 1;
            }
            let scale = r.forward.abs().max(r.backward.abs());
            if !(r.forward.is_finite() && r.backward.is_finite()) {
                // Not a finite number: no figure can stand for it (`max` would drop a NaN).
                t.worst = f64::NAN;
            } else if scale > 1e3 * SUBNORMAL_FLOOR && r.round_off - SUBNORMAL_FLOOR <= tol * scale
            {
                t.worst = t.worst.max(r.relative_error());
            } else if scale > 0.0 {
                t.ill += 1;
            }
        }
    }
    let reports = tallies
        .into_iter()
        .map(|t| LawReport {
            law: Law::Reciprocity,
            passed: t.failures == 0,
            figure: t.worst,
            uncertainty: 0.0,
            figure_name: "max relative error",
            budget: format!("{} pairs, η = {}", config.pairs, config.eta),
            detail: if t.failures == 0 {
                format!(
                    "{} ill-conditioned pairs checked against their round-off only",
                    t.ill
                )
            } else {
                format!("{} pairs failed; {}", t.failures, t.detail)
            },
        })
        .collect();
    worst_channel(reports)
}

/// The energy-bound tally of one channel.
struct EnergyTally {
    /// The largest sampled albedo and where (a NaN one, once seen).
    largest: Option<(Estimate, Vec3)>,
    /// Every sampled albedo within the bound so far.
    bound_ok: bool,
    /// The largest gap between the estimators: (|Δ|, its standard error, wo).
    worst_gap: (f64, f64, Vec3),
    /// The first disagreement of the estimators.
    agreement_failure: Option<String>,
}

/// **Energy bound** and **albedo estimators**: at every viewer direction the sampled albedo
/// is at most `config.albedo_bound` within `k` standard errors, and the two estimators agree
/// within `k` combined standard errors, per channel (`k` Šidák-corrected over the two tests,
/// the directions and the channels): of the whole albedo for a model without delta lobes, of
/// the lobes with a density for a model with both kinds ([`Albedo::density_lobes`]), none
/// for a model of delta lobes only. Returns the two reports, each of its worst channel.
#[must_use]
pub fn energy_bound<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> (LawReport, Option<LawReport>) {
    let directions = config.viewer_directions(bxdf);
    let n = channels(bxdf);
    let k = two_sided_quantile(sidak(config.significance, 2 * directions.len() * n));
    let mut tallies: Vec<EnergyTally> = (0..n)
        .map(|_| EnergyTally {
            largest: None,
            bound_ok: true,
            worst_gap: (0.0, 0.0, Vec3::ZERO),
            agreement_failure: None,
        })
        .collect();
    let mut agreement_checked = false;
    for &wo in &directions {
        for (t, a) in tallies.iter_mut().zip(albedo_channels(bxdf, wo, config)) {
            let s = a.sampled;
            let allowance = k * s.std_err + F32_ROUND_OFF * config.albedo_bound;
            // Written so that a NaN estimate fails.
            t.bound_ok &= s.mean <= config.albedo_bound + allowance;
            if s.mean.is_nan() {
                t.largest = Some((s, wo));
            }
            if t.largest
                .is_none_or(|(l, _)| s.mean > l.mean && !l.mean.is_nan())
            {
                t.largest = Some((s, wo));
            }
            // The two estimators of the whole albedo, or, for a model with delta lobes too,
            // of the lobes with a density (where a sampler that misses part of them and a
            // bound that misses `f` where `pdf` is zero would go unseen otherwise).
            let pair = a.cosine.map(|c| (s, c)).or(a.density_lobes);
            if let Some((s, c)) = pair {
                agreement_checked = true;
                let sigma = (s.std_err.powi(2) + c.std_err.powi(2)).sqrt();
                let diff = (s.mean - c.mean).abs();
                let agrees = diff <= k * sigma + F32_ROUND_OFF * s.mean.abs();
                if !agrees && t.agreement_failure.is_none() {
                    t.agreement_failure = Some(format!("at wo = {wo:?}: sampled {s}, cosine {c}"));
                }
                if diff > t.worst_gap.0 || diff.is_nan() {
                    t.worst_gap = (diff, sigma, wo);
                }
            }
        }
    }
    let budget = if n == 1 {
        format!(
            "{} samples × {} directions, k = {k:.2}",
            config.albedo_samples,
            directions.len()
        )
    } else {
        format!(
            "{} samples × {} directions × {n} channels, k = {k:.2}",
            config.albedo_samples,
            directions.len()
        )
    };
    let (bounds, agreements): (Vec<_>, Vec<_>) = tallies
        .into_iter()
        .map(|t| {
            let (best, at) = t.largest.unwrap_or((
                Estimate {
                    mean: 0.0,
                    std_err: 0.0,
                    n: 0,
                },
                Vec3::Z,
            ));
            let bound = LawReport {
                law: Law::EnergyBound,
                passed: t.bound_ok,
                figure: best.mean,
                uncertainty: best.std_err,
                figure_name: "max albedo",
                budget: budget.clone(),
                detail: format!(
                    "largest {best} at wo = {at:?}, bound {}",
                    config.albedo_bound
                ),
            };
            let agreement = LawReport {
                law: Law::AlbedoEstimators,
                passed: t.agreement_failure.is_none(),
                figure: t.worst_gap.0,
                uncertainty: t.worst_gap.1,
                figure_name: "max |sampled − cosine|",
                budget: budget.clone(),
                detail: t
                    .agreement_failure
                    .unwrap_or_else(|| format!("largest at wo = {:?}", t.worst_gap.2)),
            };
            (bound, agreement)
        })
        .unzip();
    (
        worst_channel(bounds),
        agreement_checked.then(|| worst_channel(agreements)),
    )
}

/// **Sampling**: the chi-square test of `sample` against `pdf` at every viewer direction,
/// Šidák-corrected over the directions. The figure is the smallest p-value. Delta-lobe
/// samples count as "no sample" (see [`chi2_bxdf`]). The spectrum plays no part.
#[must_use]
pub fn sampling_chi2<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let directions = config.viewer_directions(bxdf);
    let significance = sidak(config.significance, directions.len());
    let mut min_p = (1.0_f64, Vec3::Z);
    let mut failure = None;
    for (i, &wo) in directions.iter().enumerate() {
        let chi = Chi2Config {
            samples: config.chi2_samples,
            seed: config.seed.wrapping_add(i as u64),
            significance,
            ..Chi2Config::default()
        };
        let r = chi2_bxdf(bxdf, wo, &chi);
        // A NaN (no degrees of freedom: a failed check) is reported, not hidden behind 1.
        if r.p_value < min_p.0 || r.p_value.is_nan() {
            min_p = (r.p_value, wo);
        }
        if !r.passed() && failure.is_none() {
            failure = Some(format!(
                "at wo = {wo:?}: p = {:.3e}, {} samples in zero-density bins, {} invalid samples, \
                 {} invalid pdf values, {} samples rejected (expected {:.1})",
                r.p_value,
                r.zero_bin_hits,
                r.invalid_samples,
                r.invalid_pdf_values,
                r.rejected_samples,
                r.expected_rejected
            ));
        }
    }
    LawReport {
        law: Law::Sampling,
        passed: failure.is_none(),
        figure: min_p.0,
        uncertainty: 0.0,
        figure_name: "min p-value",
        budget: format!(
            "{} samples × {} directions, significance {significance:.1e} each",
            config.chi2_samples,
            directions.len()
        ),
        detail: failure.unwrap_or_else(|| format!("smallest at wo = {:?}", min_p.1)),
    }
}

/// **Consistency**: `sample`'s `f` and `pdf` equal `eval` and `pdf` at the sampled direction
/// within `config.consistency_tolerance` (relative), per channel. The figure is the largest
/// relative difference (of the worst channel).
#[must_use]
pub fn consistency<B: Bxdf + ?Sized>(bxdf: &B, config: &Config) -> LawReport {
    let mut worst = vec![(0.0_f64, Vec3::Z); channels(bxdf)];
    for wo in config.viewer_directions(bxdf) {
        let gaps = sample_consistency_channels(bxdf, wo, config);
        for (w, (f, p)) in worst.iter_mut().zip(gaps) {
            // `f64::max` would drop a NaN: keep it, so that it fails.
            let gap = if f.is_nan() || p.is_nan() {
                f64::NAN
            } else {
                f.max(p)
            };
            if gap > w.0 || gap.is_nan() {
                *w = (gap, wo);
            }
        }
    }
    let reports = worst
        .into_iter()
        .map(|(gap, at)| LawReport {
            law: Law::Consistency,
            passed: gap <= config.consistency_tolerance, // false for NaN
            figure: gap,
            uncertainty: 0.0,
            figure_name: "max relative difference",
            budget: format!("{} samples per direction", config.consistency_samples),
            detail: format!(
                "largest at wo = {at:?}, tolerance {:.0e}",
                config.consistency_tolerance
            ),
        })
        .collect();
    worst_channel(reports)
}

/// Runs every law that applies to `bxdf`: positivity, the energy bound, and — for a model with
/// a lobe that has a density — reciprocity, sampling, consistency and the agreement of the
/// two albedo estimators (of the whole albedo, or of the lobes with a density for a model
/// with delta lobes too). For a [`stochastic`](Bxdf::stochastic)
/// model (a layered BSDF, whose `eval` and `pdf` are Monte Carlo estimates) reciprocity,
/// sampling and consistency are checked in expectation instead
/// ([`check_bxdf_in_expectation`](super::check_bxdf_in_expectation)). A model of any [`Spectrum`] — `f32`,
/// RGB [`Vec3`], four wavelengths [`Vec4`](glam::Vec4) — is checked per channel, and each
/// report is its worst channel's.
///
/// ```
/// use lobe::bxdf::Lambert;
/// use lobe::verify::{check_bxdf, Config};
/// use lobe::Vec3;
/// let quick = Config { albedo_samples: 20_000, chi2_samples: 50_000, pairs: 2_000, ..Config::default() };
/// let report = check_bxdf("Lambert", &Lambert::new(0.8_f32)?, &quick);
/// assert!(report.passed(), "{report}");
/// // RGB, as a renderer has it: the same three lines.
/// let report = check_bxdf("RGB Lambert", &Lambert::new(Vec3::new(0.2, 0.5, 0.8))?, &quick);
/// assert!(report.passed(), "{report}");
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[must_use]
pub fn check_bxdf<B: Bxdf + ?Sized>(name: &str, bxdf: &B, config: &Config) -> Report {
    if bxdf.stochastic() {
        return super::expectation::check_bxdf_in_expectation(name, bxdf, config);
    }
    let mut laws = Vec::new();
    laws.push(positivity(bxdf, config));
    // A model made only of delta lobes has `eval = 0` everywhere: nothing to compare.
    let density = bxdf.lobes().is_non_specular();
    if density {
        laws.push(reciprocity(bxdf, config));
    }
    // The statistical laws (the energy bound, the sampler's chi-square) share the run's
    // significance, so that it is the chance of failing a correct model for the whole run.
    let shared = config.shared_among(1 + usize::from(density));
    let (bound, agreement) = energy_bound(bxdf, &shared);
    laws.push(bound);
    laws.extend(agreement);
    if density {
        laws.push(sampling_chi2(bxdf, &shared));
        laws.push(consistency(bxdf, config));
    }
    Report {
        name: name.into(),
        laws,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bxdf::Lambert;

    /// An infinite side never holds, though its relative error is NaN and its allowance
    /// could be infinite too.
    #[test]
    fn an_infinite_side_breaks_reciprocity() {
        for (forward, backward) in [
            (f64::INFINITY, 0.5),
            (0.5, f64::INFINITY),
            (f64::INFINITY, f64::INFINITY),
        ] {
            let pair = ReciprocityPair {
                forward,
                backward,
                round_off: 1e-30,
            };
            assert!(!pair.holds(1e-5), "{pair:?}");
            let pair = ReciprocityPair {
                round_off: f64::INFINITY,
                ..pair
            };
            assert!(!pair.holds(1e-5), "{pair:?}");
        }
        assert!(
            ReciprocityPair {
                forward: 0.5,
                backward: 0.5,
                round_off: 0.0
            }
            .holds(1e-5)
        );
    }

    fn report(passed: bool, figure: f64) -> LawReport {
        LawReport {
            law: Law::EnergyBound,
            passed,
            figure,
            uncertainty: 0.0,
            figure_name: "max albedo",
            budget: String::new(),
            detail: String::from("here"),
        }
    }

    #[test]
    fn the_worst_channel_is_a_failure_then_the_largest_figure() {
        let one = worst_channel(vec![report(true, 0.5)]);
        assert_eq!(one.detail, "here");
        let r = worst_channel(vec![
            report(true, 0.9),
            report(false, 0.2),
            report(true, 0.5),
        ]);
        assert_eq!((r.passed, r.figure), (false, 0.2));
        assert_eq!(r.detail, "green channel (worst of 3): here");
        let r = worst_channel(vec![
            report(true, 0.1),
            report(true, 0.4),
            report(true, f64::NAN),
        ]);
        assert!(r.figure.is_nan());
        assert!(
            r.detail.starts_with("blue channel (worst of 3)"),
            "{}",
            r.detail
        );
        let r = worst_channel(vec![report(true, 0.3); 4]);
        assert_eq!(r.detail, "channel 0 (worst of 4, tied with 3 others): here");
    }

    #[test]
    #[should_panic(expected = "channel 3 of a 3-channel spectrum")]
    fn a_channel_beyond_the_spectrum_is_refused() {
        let rgb = Lambert::new(Vec3::splat(0.5)).unwrap();
        let _ = Channel::new(&rgb, 3);
    }

    #[test]
    fn a_channel_is_the_model_in_that_channel() {
        let rgb = Lambert::new(Vec3::new(0.2, 0.5, 0.8)).unwrap();
        let blue = Channel::new(&rgb, 2);
        let (wo, wi) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.6, 0.0, 0.8));
        assert_eq!(blue.index(), 2);
        assert_eq!(blue.eval(wo, wi), rgb.eval(wo, wi).z);
        assert_eq!(blue.pdf(wo, wi), rgb.pdf(wo, wi));
        assert_eq!(blue.lobes(), rgb.lobes());
        let (s, b) = (
            rgb.sample(wo, Vec2::new(0.3, 0.7), 0.5).unwrap(),
            blue.sample(wo, Vec2::new(0.3, 0.7), 0.5).unwrap(),
        );
        assert_eq!((b.wi, b.f, b.pdf), (s.wi, s.f.z, s.pdf));
    }
}
