//! The fault-injection corpus: every law check of `lobe::verify` can fail.
//!
//! Each entry wraps a correct model or distribution of the crate and breaks one thing, the
//! way a real implementation goes wrong: a one-line slip. The test runs the public harness on
//! it ([`check_bxdf`] or [`check_ndf`], the same calls a renderer makes) and asserts that
//!
//! * the law meant to catch the bug **fails**, and
//! * every other law that the bug leaves intact **passes**, so that we know the failure
//!   comes from the right check and not from a harness that rejects everything.
//!
//! Where a bug legitimately breaks several laws (a `D` without its `1/π` is wrong in every
//! integral that contains `D`), the entry lists all of them and says which one names the bug.
//! The last test runs the correct counterparts under the same settings: they pass every law.
//!
//! `cargo test --test faults -- --nocapture` prints every report with its measured figure.

use core::f32::consts::PI;
use lobe::bxdf::{Bxdf, BxdfSample, Lambert, Lobes, Microfacet, RoughDielectric, TransportMode};
use lobe::frame::reflect_away;
use lobe::fresnel::{self, Fresnel, Schlick};
use lobe::microfacet::{Ggx, Masking, NormalDistribution};
use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf};
use lobe::verify::{
    Chi2Config, Config, Law, Report, albedo, check_bxdf, check_ndf, chi2_bxdf, sidak,
};
use lobe::{Alpha, Eta, Vec2, Vec3};

mod common;

use common::buggy_ggx::{BuggyNdf, NdfBug};

// ---------------------------------------------------------------------------------------
// Budgets
// ---------------------------------------------------------------------------------------

/// Harness runs in this file (one per entry, plus the correct counterparts): the family's
/// 1% chance of failing a correct law is shared among them.
const RUNS: usize = 38;

/// A small but sufficient budget: every bug below is caught by a wide margin at it.
fn config() -> Config {
    Config {
        albedo_samples: 20_000,
        chi2_samples: 50_000,
        pairs: 4_000,
        consistency_samples: 4_000,
        significance: sidak(0.01, RUNS),
        ..Config::default()
    }
}

/// The distributions' budget, with the proposal stretched to their width.
fn ndf_config(alpha: f32) -> Config {
    Config {
        integral_samples: 60_000,
        stretch: Vec2::splat(alpha),
        chi2_samples: 50_000,
        significance: sidak(0.01, RUNS),
        ..Config::default()
    }
}

/// Runs every law on `bxdf` at the corpus budget, prints the report, and asserts that exactly
/// the laws in `caught_by` failed (see [`assert_caught`]).
fn check_caught<B: Bxdf + ?Sized>(name: &str, bxdf: &B, caught_by: &[Law]) -> Report {
    let report = check_bxdf(name, bxdf, &config());
    assert_caught(&report, caught_by);
    report
}

/// Prints the report and asserts that exactly the laws in `caught_by` failed: each of them
/// is present and failed, every other law checked passed.
fn assert_caught(report: &Report, caught_by: &[Law]) {
    assert_caught_except(report, caught_by, &[]);
}

/// [`assert_caught`], passing no judgement on the laws in `unjudged`.
fn assert_caught_except(report: &Report, caught_by: &[Law], unjudged: &[Law]) {
    eprintln!("{report}");
    for &law in caught_by {
        let r = report
            .get(law)
            .unwrap_or_else(|| panic!("{}: law {law} was not checked", report.name));
        assert!(
            !r.passed,
            "{}: the bug slipped through {law}: {r}",
            report.name
        );
    }
    for r in &report.laws {
        if !caught_by.contains(&r.law) && !unjudged.contains(&r.law) {
            assert!(
                r.passed,
                "{}: {} should still hold (the bug does not touch it): {r}",
                report.name, r.law
            );
        }
    }
}

/// The figure of `law` in `report`.
fn figure(report: &Report, law: Law) -> f64 {
    report.get(law).map_or(f64::NAN, |r| r.figure)
}

/// A reflection sample of `wi` with value `f`, or `None` where the density is not positive
/// and finite.
fn reflection(wi: Vec3, f: f32, pdf: f32, lobe: Lobes) -> Option<BxdfSample<f32>> {
    (pdf > 0.0 && pdf.is_finite()).then_some(BxdfSample {
        wi,
        f,
        pdf,
        lobe,
        eta: 1.0,
    })
}

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

/// A glossy GGX reflector with Schlick's `F0 = 0.04`: the correct model most glossy entries
/// break.
fn glossy(a: f32) -> Microfacet<Ggx, Schlick> {
    Microfacet::new(
        Ggx::isotropic(alpha(a)),
        Masking::HeightCorrelated,
        Schlick::new(0.04).unwrap(),
    )
}

// ---------------------------------------------------------------------------------------
// Broken distributions (checked with `check_ndf`)
// ---------------------------------------------------------------------------------------

const NDF_ALPHA: f32 = 0.3;

fn buggy_ndf(bug: NdfBug) -> Report {
    let dist = BuggyNdf::new(NDF_ALPHA, bug);
    check_ndf(
        &format!("GGX α=0.3, {bug:?}"),
        &dist,
        &ndf_config(NDF_ALPHA),
    )
}

/// **1. Unnormalised D** (GGX's `D` without its `1/π`) → **D normalisation**: `∫ D cos θ`
/// measures π instead of 1. Projected area, visible normalisation and sampling integrate the
/// same `D` (the sampler's pdf is `D_w`, built from `D`) and fail too, by the same factor; D
/// normalisation is the check that names the culprit, being the only one with `D` alone.
#[test]
fn unnormalised_d_fails_d_normalisation() {
    let report = buggy_ndf(NdfBug::DMissingPi);
    assert_caught(
        &report,
        &[
            Law::DNormalization,
            Law::ProjectedArea,
            Law::VisibleNormalization,
            Law::Sampling,
        ],
    );
    let r = report.get(Law::DNormalization).unwrap();
    assert!(
        (r.figure - f64::from(PI)).abs() <= common::k_sigma(0.01, RUNS) * r.uncertainty,
        "{r}"
    );
}

/// **2. G1 = 1/(1/Λ)** → **projected area**: `∫ G1 ⟨wo, m⟩ D` misses `cos θo` (at normal
/// incidence `Λ = 0` and the buggy `G1` is 0). `D` is intact, so D normalisation passes,
/// which pins the bug on the masking. The visible-normal density contains `G1` and fails too,
/// and so does the sampler's pdf, which is that density.
#[test]
fn g1_equal_to_lambda_fails_projected_area() {
    let report = buggy_ndf(NdfBug::G1IsLambda);
    assert_caught(
        &report,
        &[Law::ProjectedArea, Law::VisibleNormalization, Law::Sampling],
    );
    assert!(figure(&report, Law::ProjectedArea) > 0.5);
}

/// **11. Visible normals without G1** → **visible normalisation**: `∫ D_w` is `1/G1(w) > 1`
/// (largest at grazing). `D` and `G1` are right, so D normalisation and projected area pass;
/// the sampler is checked against this density and fails too.
#[test]
fn visible_density_without_g1_fails_visible_normalisation() {
    let report = buggy_ndf(NdfBug::VisibleWithoutG1);
    assert_caught(&report, &[Law::VisibleNormalization, Law::Sampling]);
}

/// **12. A sampler and a pdf that belong to different methods** (the sampler upgraded to
/// visible normals, `pdf` still `D cos θ`) → **sampling (χ²)** only: every integral law holds.
#[test]
fn visible_sampler_with_d_cos_pdf_fails_chi_square() {
    let report = buggy_ndf(NdfBug::VisibleSamplerDcosPdf);
    assert_caught(&report, &[Law::Sampling]);
    assert!(figure(&report, Law::Sampling) < 1e-20);
}

// ---------------------------------------------------------------------------------------
// 3. Schlick's `1 − cos⁵`: a coupled coat over a diffuse base
// ---------------------------------------------------------------------------------------

/// Schlick's approximation, correct (`(1 − cos)⁵`) or with the handout's slip (`1 − cos⁵`).
#[derive(Clone, Copy, Debug)]
struct SchlickTerm {
    f0: f32,
    slip: bool,
}

impl Fresnel for SchlickTerm {
    type Spectrum = f32;
    fn eval(&self, cos_d: f32) -> f32 {
        let c = cos_d.abs().min(1.0);
        let w = if self.slip {
            1.0 - c.powi(5)
        } else {
            (1.0 - c).powi(5)
        };
        self.f0 + (1.0 - self.f0) * w
    }
}

/// A glossy dielectric coat (GGX, Schlick `F0`) over a Lambertian base of reflectance `ρ`,
/// energy-coupled by Shirley et al.'s closed form for a Schlick coat (Shirley, Hu, Smits &
/// Lafortune 1997, "A Practitioners' Assessment of Light Reflection Models"):
///
/// ```text
/// f = f_coat(wo, wi) + 21/(20π) (1 − F0) ρ (1 − (1 − cos θo)⁵) (1 − (1 − cos θi)⁵)
/// ```
///
/// whose diffuse albedo is `(1 − F0) ρ (1 − (1 − cos θo)⁵)`: exactly what Schlick's
/// `F(cos θo)` leaves over, so the sum stays below 1. Sampling: the coat or cosine-weighted
/// directions, one half each.
struct SchlickCoated {
    coat: Microfacet<Ggx, SchlickTerm>,
    f0: f32,
    rho: f32,
}

impl SchlickCoated {
    fn new(slip: bool) -> Self {
        let f0 = 0.04;
        Self {
            coat: Microfacet::new(
                Ggx::isotropic(alpha(0.1)),
                Masking::HeightCorrelated,
                SchlickTerm { f0, slip },
            ),
            f0,
            rho: 0.8,
        }
    }
}

impl Bxdf for SchlickCoated {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        let t = |c: f32| 1.0 - (1.0 - c.min(1.0)).powi(5);
        let diffuse = 21.0 / (20.0 * PI) * (1.0 - self.f0) * self.rho * t(wo.z) * t(wi.z);
        self.coat.eval(wo, wi) + diffuse
    }
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        if !(wo.z > 0.0) {
            return None;
        }
        let (wi, lobe) = if uc < 0.5 {
            (self.coat.sample(wo, u, uc)?.wi, Lobes::GLOSSY_REFLECTION)
        } else {
            (cosine_hemisphere(u), Lobes::DIFFUSE_REFLECTION)
        };
        let pdf = self.pdf(wo, wi);
        reflection(wi, self.eval(wo, wi), pdf, lobe)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        0.5 * self.coat.pdf(wo, wi) + 0.5 * cosine_hemisphere_pdf(wi.z)
    }
    fn lobes(&self) -> Lobes {
        Lobes::GLOSSY_REFLECTION | Lobes::DIFFUSE_REFLECTION
    }
}

/// **3. Schlick with `1 − cos⁵` instead of `(1 − cos)⁵`** → **energy bound**, through the
/// coupling.
///
/// On its own the slipped term is a *plausible* reflectance curve: `F0` at normal incidence,
/// 1 at grazing, within `[F0, 1]`, a function of `wo·h` only. A conductor or a bare coat that
/// uses it is positive, reciprocal, below the energy bound and consistently sampled: no
/// physical law is broken, only the value is wrong, and a value is what a reference test
/// checks (`fresnel::tests`, Schlick at `cos = 0.5` is 0.07; the slip gives 0.97). The law
/// it breaks is the *balance* between a coat and what lies under it: the diffuse base
/// receives `1 − F` computed in closed form from the correct Schlick curve, while the coat
/// now reflects far more than `F` — at `θo = 30°` the slipped `F` is 0.53 where Schlick's is
/// 0.04 — so coat plus base exceed 1 at every angle but the normal.
#[test]
fn schlick_one_minus_cos5_breaks_the_energy_bound_of_a_coupled_coat() {
    let report = check_caught(
        "Schlick 1 − cos⁵ coat over ρ = 0.8",
        &SchlickCoated::new(true),
        &[Law::EnergyBound],
    );
    assert!(figure(&report, Law::EnergyBound) > 1.2);
    // The bare coat with the slipped term breaks no law: the slip is a value error there.
    check_caught(
        "Schlick 1 − cos⁵, bare coat",
        &SchlickCoated::new(true).coat,
        &[],
    );
}

// ---------------------------------------------------------------------------------------
// Broken glossy reflectors
// ---------------------------------------------------------------------------------------

/// The bugs of a glossy microfacet reflector, each one line away from the crate's
/// [`Microfacet`].
#[derive(Clone, Copy, PartialEq, Debug)]
enum GlossyBug {
    None,
    /// `pdf()` returns the normal's density, forgetting the reflection Jacobian
    /// `1/(4 wo·h)`; `sample()` computes its own pdf correctly.
    PdfForgetsJacobian,
    /// The shared density helper forgets the Jacobian, so `sample().pdf` and `pdf()` agree
    /// with each other and are both wrong.
    DensityForgetsJacobian,
    /// The Fresnel term evaluated at `wo·n` instead of `wo·h`.
    FresnelAtNormal,
    /// `f − 0.01`: a constant (a misapplied compensation term) subtracted from the lobe.
    Negative,
    /// The horizon guard written `>=` instead of `>`: at `cos θ = 0` the value is
    /// `D G / (4 cos θo cos θi) = 0/0`.
    HorizonGuardInclusive,
    /// `sample()` forgets to reject reflections below the horizon, returning them with
    /// `f = 0` and the density of the normal that produced them; `pdf()` is 0 there.
    SampleBelowHorizon,
    /// `sample().f` computed with separable masking `G1 G1`, `eval` with height-correlated.
    SampleSeparableMasking,
}

struct BuggyGlossy {
    good: Microfacet<Ggx, Schlick>,
    bug: GlossyBug,
}

fn buggy_glossy(a: f32, bug: GlossyBug) -> BuggyGlossy {
    BuggyGlossy {
        good: glossy(a),
        bug,
    }
}

impl BuggyGlossy {
    fn dist(&self) -> &Ggx {
        self.good.distribution()
    }

    /// The half vector of `wo`, `wi` on the upper side.
    fn half(wo: Vec3, wi: Vec3) -> Vec3 {
        (wo + wi).normalize()
    }

    /// The density of the reflection sampler's normal `m` for `wo`, without the Jacobian.
    fn sampler_density(&self, wo: Vec3, m: Vec3) -> f32 {
        if self.dist().bounded_reflection() {
            self.dist().d_visible_bounded(wo, m)
        } else {
            self.dist().d_visible(wo, m)
        }
    }

    /// The density of the microfacet normal of `(wo, wi)`, without the Jacobian.
    fn normal_density(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        self.sampler_density(wo, Self::half(wo, wi))
    }
}

impl Bxdf for BuggyGlossy {
    type Spectrum = f32;

    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        match self.bug {
            GlossyBug::FresnelAtNormal => {
                // The crate's model with F = 1, times F at the macro-normal.
                let no_f = Microfacet::new(
                    *self.dist(),
                    Masking::HeightCorrelated,
                    fresnel::NoFresnel::<f32>::new(),
                );
                no_f.eval(wo, wi) * fresnel::schlick(0.04_f32, wo.z)
            }
            GlossyBug::Negative => {
                if wo.z > 0.0 && wi.z > 0.0 {
                    self.good.eval(wo, wi) - 0.01
                } else {
                    0.0
                }
            }
            GlossyBug::HorizonGuardInclusive => {
                if !(wo.z >= 0.0 && wi.z >= 0.0) {
                    return 0.0;
                }
                let h = Self::half(wo, wi);
                let d = self.dist().d(h);
                let g = self.dist().g2(wo, wi);
                fresnel::schlick(0.04_f32, wo.dot(h)) * d * g / (4.0 * wo.z * wi.z)
            }
            _ => self.good.eval(wo, wi),
        }
    }

    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        match self.bug {
            GlossyBug::SampleBelowHorizon => {
                if !(wo.z > 0.0) {
                    return None;
                }
                let m = self.dist().sample_reflection(&self.dist().view(wo), u);
                let wi = reflect_away(wo, m);
                // Missing: `if !(wi.z > 0.0) { return None; }`
                let pdf = self.sampler_density(wo, m) / (4.0 * wo.dot(m));
                reflection(wi, self.good.eval(wo, wi), pdf, Lobes::GLOSSY_REFLECTION)
            }
            _ => {
                let mut s = self.good.sample(wo, u, uc)?;
                s.f = self.eval(wo, s.wi);
                match self.bug {
                    GlossyBug::DensityForgetsJacobian => {
                        s.pdf = self.normal_density(wo, s.wi);
                    }
                    GlossyBug::SampleSeparableMasking => {
                        let separable = Microfacet::new(
                            *self.dist(),
                            Masking::Separable,
                            Schlick::new(0.04).unwrap(),
                        );
                        s.f = separable.eval(wo, s.wi);
                    }
                    _ => {}
                }
                (s.pdf > 0.0 && s.pdf.is_finite()).then_some(s)
            }
        }
    }

    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        match self.bug {
            GlossyBug::PdfForgetsJacobian | GlossyBug::DensityForgetsJacobian => {
                self.normal_density(wo, wi)
            }
            _ => self.good.pdf(wo, wi),
        }
    }

    fn lobes(&self) -> Lobes {
        Lobes::GLOSSY_REFLECTION
    }
}

/// **4a. `pdf()` forgets the reflection Jacobian `1/(4 wo·h)`** (while `sample()` divides by
/// it) → **sampling (χ²)** and **consistency**: the sampler's directions do not follow the
/// density `pdf()` claims, and `sample().pdf ≠ pdf()`. The values and the sampler are right,
/// so the energy bound and the two albedo estimators agree.
#[test]
fn pdf_without_reflection_jacobian_fails_chi_square_and_consistency() {
    let report = check_caught(
        "GGX α=0.3, pdf() without 1/(4 wo·h)",
        &buggy_glossy(0.3, GlossyBug::PdfForgetsJacobian),
        &[Law::Sampling, Law::Consistency],
    );
    assert!(figure(&report, Law::Sampling) < 1e-20);
}

/// **4b. The density helper forgets the Jacobian** (both `sample().pdf` and `pdf()` are the
/// normal's density) → **sampling (χ²)**, and the **albedo estimators** disagree (the
/// sampler's weights `f cos θi / pdf` are off by `4 wo·h`). Consistency passes: the two wrong
/// densities agree, which is why it cannot be the only check of a sampler.
#[test]
fn density_without_reflection_jacobian_fails_chi_square_and_albedo_agreement() {
    check_caught(
        "GGX α=0.3, density without 1/(4 wo·h)",
        &buggy_glossy(0.3, GlossyBug::DensityForgetsJacobian),
        &[Law::Sampling, Law::AlbedoEstimators],
    );
}

/// **6. Fresnel evaluated at `wo·n` instead of `wo·h`** → **reciprocity**: `F(cos θo)` is not
/// symmetric in `wo`, `wi`. Everything else holds (`F ≤ 1`, the sampler is untouched, and
/// `sample()` returns the same broken value as `eval`).
#[test]
fn fresnel_at_the_macro_normal_fails_reciprocity() {
    let report = check_caught(
        "GGX α=0.3, F(wo·n)",
        &buggy_glossy(0.3, GlossyBug::FresnelAtNormal),
        &[Law::Reciprocity],
    );
    assert!(figure(&report, Law::Reciprocity) > 0.5);
}

/// **8. NaN at grazing**: the horizon guard written `wo.z >= 0.0 && wi.z >= 0.0`, so a
/// direction exactly in the tangent plane reaches `D G / (4 cos θo cos θi)` with `G = 0`
/// and `cos θ = 0`: NaN → **positivity**.
///
/// This corpus entry found a defect in the harness: [`lobe::verify::positivity`] used to draw
/// its grazing directions with `cos θ ≥ 1e-7` only, where an `f32` division does not
/// overflow, so the bug went through. The check now also tries the horizon itself (`±0`),
/// subnormal cosines and the exact normal. The first assertion shows the bug is real; the
/// next test catches it with a property test over `adversarial_directions()` as well.
#[test]
fn nan_at_the_horizon_fails_positivity() {
    let model = buggy_glossy(0.3, GlossyBug::HorizonGuardInclusive);
    let grazing = Vec3::new(1.0, 0.0, 0.0);
    assert!(model.eval(Vec3::new(0.0, 0.6, 0.8), grazing).is_nan());
    check_caught("GGX α=0.3, horizon guard >=", &model, &[Law::Positivity]);
}

/// **8, by property test.** The bug that `positivity` misses is found by a proptest over
/// [`adversarial_directions`](lobe::verify::strategies::adversarial_directions), which puts
/// an eighth of its draws exactly on the horizon: the totality property fails, and shrinks
/// to a direction with `cos θ = 0`.
#[cfg(feature = "proptest")]
#[test]
fn nan_at_the_horizon_fails_a_totality_property_test() {
    use lobe::verify::strategies::adversarial_directions;
    use proptest::prelude::*;
    use proptest::test_runner::{Config as Runner, RngSeed, TestError, TestRunner};

    let model = buggy_glossy(0.3, GlossyBug::HorizonGuardInclusive);
    let mut runner = TestRunner::new(Runner {
        cases: 1_000,
        rng_seed: RngSeed::Fixed(1),
        failure_persistence: None,
        ..Runner::default()
    });
    let result = runner.run(
        &(adversarial_directions(), adversarial_directions()),
        |(wo, wi)| {
            let f = model.eval(wo, wi);
            prop_assert!(f.is_finite() && f >= 0.0, "f = {f}");
            Ok(())
        },
    );
    match result {
        Err(TestError::Fail(why, (wo, wi))) => {
            eprintln!("caught: {why} at wo = {wo:?}, wi = {wi:?}");
            assert!(wo.z == 0.0 || wi.z == 0.0, "{wo:?}, {wi:?}");
        }
        other => panic!("the totality property passed a NaN model: {other:?}"),
    }
}

/// **9. A negative lobe** (`f − 0.01`, as a misapplied compensation term would give) →
/// **positivity**: the lobe's tails are below 0.01. The offset is symmetric, `sample()`
/// returns it too, and it only lowers the albedo, so every other law holds.
#[test]
fn negative_lobe_fails_positivity() {
    let report = check_caught(
        "GGX α=0.3, f − 0.01",
        &buggy_glossy(0.3, GlossyBug::Negative),
        &[Law::Positivity],
    );
    assert!(figure(&report, Law::Positivity) > 100.0);
}

/// **13. `sample()` returns reflections below the horizon** (the rejection forgotten; `f = 0`
/// and a positive density there, where `pdf()` is 0) → **sampling (χ²)** with samples in
/// zero-density bins, and **consistency** (`sample().pdf ≠ pdf()`). Rough (`α = 0.8`) and
/// with the unbounded visible-normal sampler, so such reflections are common. The values
/// are right and the weights of the lost samples are 0, so the energy laws hold.
#[test]
fn sample_below_the_horizon_fails_chi_square_zero_bins() {
    let mut model = buggy_glossy(0.8, GlossyBug::SampleBelowHorizon);
    model.good = Microfacet::new(
        Ggx::isotropic(alpha(0.8)).with_bounded_reflection(false),
        Masking::HeightCorrelated,
        Schlick::new(0.04).unwrap(),
    );
    check_caught(
        "GGX α=0.8, samples below the horizon",
        &model,
        &[Law::Sampling, Law::Consistency],
    );
    // The chi-square test itself names the zero-density bins (the law report's one line
    // keeps only the statistic).
    let chi = Chi2Config {
        samples: 50_000,
        ..Chi2Config::default()
    };
    let r = chi2_bxdf(&model, Vec3::Z, &chi);
    eprintln!("{r}");
    assert!(r.zero_bin_hits > 1_000, "{r}");
}

/// **A sampler that misses half of a lobe, beside a mirror.** A mirror of reflectance 0.4 and
/// a diffuse lobe `0.9/π` whose sampler and `pdf` cover only `x > 0`: the two agree, so the
/// chi-square and consistency hold, and the sampled albedo (0.4 + 0.45) stays under 1, while
/// the model reflects 1.3. → **albedo estimators**, which compare the diffuse part by the
/// sampler (0.45) and by cosine sampling (0.9); the check once skipped every model with a
/// delta lobe.
struct HalfSampledBesideAMirror;

impl Bxdf for HalfSampledBesideAMirror {
    type Spectrum = f32;

    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z > 0.0 && wi.z > 0.0 {
            0.9 / PI
        } else {
            0.0
        }
    }

    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        if !(wo.z > 0.0) {
            return None;
        }
        if uc < 0.4 {
            let wi = reflect_away(wo, Vec3::Z);
            // (No mirror sample in the tangent plane, where 0.4 / cos θ is infinite.)
            return (wi.z > 1e-30)
                .then(|| reflection(wi, 0.4 / wi.z, 0.4, Lobes::SPECULAR_REFLECTION))
                .flatten();
        }
        let mut wi = cosine_hemisphere(u);
        wi.x = wi.x.abs();
        reflection(wi, 0.9 / PI, self.pdf(wo, wi), Lobes::DIFFUSE_REFLECTION)
    }

    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z > 0.0 && wi.z > 0.0 && wi.x >= 0.0 {
            0.6 * 2.0 * cosine_hemisphere_pdf(wi.z)
        } else {
            0.0
        }
    }

    fn lobes(&self) -> Lobes {
        Lobes::SPECULAR_REFLECTION | Lobes::DIFFUSE_REFLECTION
    }
}

#[test]
fn half_sampled_lobe_beside_a_mirror_fails_the_albedo_estimators() {
    let report = check_caught(
        "mirror 0.4 + diffuse 0.9, half sampled",
        &HalfSampledBesideAMirror,
        &[Law::AlbedoEstimators],
    );
    assert!(figure(&report, Law::EnergyBound) < 0.9, "{report}");
}

/// **14. `sample().f ≠ eval`** (the sampler's copy of the value uses separable masking,
/// `eval` height-correlated) → **consistency**, by up to 89% at grazing. Only consistency
/// sees it: the sampled albedo, built from `sample().f`, moves by less than the estimators'
/// noise at this budget (the two masking terms differ only where little light goes), and the
/// sampler's directions are untouched.
#[test]
fn sample_value_different_from_eval_fails_consistency() {
    let report = check_caught(
        "GGX α=0.3, sample().f with separable masking",
        &buggy_glossy(0.3, GlossyBug::SampleSeparableMasking),
        &[Law::Consistency],
    );
    assert!(figure(&report, Law::Consistency) > 0.1);
}

// ---------------------------------------------------------------------------------------
// A normalised Phong lobe that forgets to clamp its cosine
// ---------------------------------------------------------------------------------------

/// The normalised (modified) Phong lobe `ks (n + 2)/(2π) max(0, cos α)ⁿ`, `cos α = r·wi` with
/// `r` the mirror direction of `wo`, sampled by `cos α = u^(1/(n+1))` around `r` (Lafortune &
/// Willems 1994). With `clamp = false`, `powf` gets the negative cosines too, and a negative
/// base to a non-integer power is NaN.
struct PhongLobe {
    ks: f32,
    n: f32,
    clamp: bool,
}

impl PhongLobe {
    fn cos_alpha(wo: Vec3, wi: Vec3) -> f32 {
        reflect_away(wo, Vec3::Z).dot(wi).min(1.0)
    }
}

impl Bxdf for PhongLobe {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        let c = Self::cos_alpha(wo, wi);
        let c = if self.clamp { c.max(0.0) } else { c };
        self.ks * (self.n + 2.0) / (2.0 * PI) * c.powf(self.n)
    }
    fn sample(&self, wo: Vec3, u: Vec2, _uc: f32) -> Option<BxdfSample<f32>> {
        if !(wo.z > 0.0) {
            return None;
        }
        let cos_a = u.x.powf(1.0 / (self.n + 1.0));
        let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
        let (s, c) = (2.0 * PI * u.y).sin_cos();
        let frame = lobe::Frame::from_normal(reflect_away(wo, Vec3::Z));
        let wi = frame.to_world(Vec3::new(sin_a * c, sin_a * s, cos_a));
        if !(wi.z > 0.0) {
            return None;
        }
        let pdf = self.pdf(wo, wi);
        reflection(wi, self.eval(wo, wi), pdf, Lobes::GLOSSY_REFLECTION)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        (self.n + 1.0) / (2.0 * PI) * Self::cos_alpha(wo, wi).max(0.0).powf(self.n)
    }
    fn lobes(&self) -> Lobes {
        Lobes::GLOSSY_REFLECTION
    }
}

/// **8b. NaN away from the lobe**: the Phong lobe's `max(0, cos α)` forgotten, so
/// `cos α < 0` to the power `n = 20.5` is NaN → **positivity**, and reciprocity, whose
/// comparison of two NaNs fails too. This entry shows that positivity does flag NaN when
/// its directions reach it (compare entry 8, which it cannot reach). The sampler only draws
/// `cos α > 0`, so sampling and consistency hold.
///
/// The cosine albedo estimate is NaN here (cosine-distributed directions reach `cos α < 0`),
/// so the **estimator agreement** fails too. (This entry found a harness defect: the check
/// used to test `diff > k σ`, false for NaN, and passed; it now requires `diff ≤ k σ`.) The
/// sampler's own estimate stays finite, so the energy bound holds.
#[test]
fn nan_from_an_unclamped_cosine_fails_positivity() {
    let unclamped = PhongLobe {
        ks: 0.9,
        n: 20.5,
        clamp: false,
    };
    check_caught(
        "Phong n=20.5, powf of a negative cosine",
        &unclamped,
        &[Law::Positivity, Law::Reciprocity, Law::AlbedoEstimators],
    );
    // At θo = 60° the cosine estimate is NaN.
    let wo = Vec3::new(0.75_f32.sqrt(), 0.0, 0.5);
    let a = albedo(&unclamped, wo, &config());
    assert!(a.cosine.is_some_and(|c| c.mean.is_nan()), "{a:?}");
}

// ---------------------------------------------------------------------------------------
// Broken diffuse reflectors
// ---------------------------------------------------------------------------------------

#[derive(Clone, Copy, PartialEq, Debug)]
enum DiffuseBug {
    None,
    /// The value scaled by 1.05 (`ρ = 1.05` slipped past validation): albedo 1.05.
    Gains5Percent,
    /// The cosine pdf 10% too large, in `sample()` and `pdf()` alike.
    PdfTenPercentHigh,
    /// The disk sampled by rejection from the square, without the loop: `None` for
    /// `1 − π/4 ≈ 21%` of the samples, while `pdf()` integrates to 1.
    RejectionWithoutLoop,
}

struct BuggyDiffuse {
    good: Lambert,
    bug: DiffuseBug,
}

fn buggy_diffuse(rho: f32, bug: DiffuseBug) -> BuggyDiffuse {
    BuggyDiffuse {
        good: Lambert::new(rho).unwrap(),
        bug,
    }
}

impl Bxdf for BuggyDiffuse {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        let f = self.good.eval(wo, wi);
        if self.bug == DiffuseBug::Gains5Percent {
            f * 1.05
        } else {
            f
        }
    }
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        if self.bug == DiffuseBug::RejectionWithoutLoop {
            if !(wo.z > 0.0) {
                return None;
            }
            let d = 2.0 * u - Vec2::ONE;
            let r2 = d.length_squared();
            if r2 >= 1.0 {
                return None; // should draw again
            }
            let wi = Vec3::new(d.x, d.y, (1.0 - r2).sqrt());
            let pdf = cosine_hemisphere_pdf(wi.z);
            return reflection(wi, self.eval(wo, wi), pdf, Lobes::DIFFUSE_REFLECTION);
        }
        let mut s = self.good.sample(wo, u, uc)?;
        s.f = self.eval(wo, s.wi);
        s.pdf = self.pdf(wo, s.wi);
        Some(s)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let p = self.good.pdf(wo, wi);
        if self.bug == DiffuseBug::PdfTenPercentHigh {
            p * 1.1
        } else {
            p
        }
    }
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION
    }
}

/// **5. A pdf 10% too large** → **sampling (χ²)**: the sampler delivers `N` samples where the
/// density predicts `1.1 N`. The sampler's weights are 10% low, so the **albedo estimators**
/// disagree too (0.727 against 0.8); `sample()` and `pdf()` share the error, so consistency
/// passes.
#[test]
fn pdf_ten_percent_off_fails_chi_square() {
    let report = check_caught(
        "Lambert ρ=0.8, pdf × 1.1",
        &buggy_diffuse(0.8, DiffuseBug::PdfTenPercentHigh),
        &[Law::Sampling, Law::AlbedoEstimators],
    );
    assert!(figure(&report, Law::Sampling) < 1e-20);
}

/// **7. An energy-gaining lobe** (Lambert with albedo 1.05) → **energy bound**. Both
/// estimators measure 1.05 and agree; every other law holds.
#[test]
fn energy_gaining_lobe_fails_the_energy_bound() {
    let report = check_caught(
        "Lambert × 1.05",
        &buggy_diffuse(1.0, DiffuseBug::Gains5Percent),
        &[Law::EnergyBound],
    );
    let r = report.get(Law::EnergyBound).unwrap();
    // Cosine sampling gives every sample the weight 1.05: the estimate is exact but for f32
    // round-off (measured 1.0499999748 ± 3.5e-10), so the bar is k σ plus 1e-6 relative.
    let k = common::k_sigma(0.01, RUNS);
    assert!(
        (r.figure - 1.05).abs() <= k * r.uncertainty + 1.05e-6,
        "{r}"
    );
}

/// **15. A sampler that returns `None` 21% of the time while its pdf integrates to 1**
/// (rejection sampling of the disk without the loop) → **sampling (χ²)**, in the no-sample
/// bin. The accepted directions are exactly cosine-distributed, so only that bin is off.
/// Its weights lose the rejected mass, so the **albedo estimators** disagree (0.63 against
/// 0.8).
#[test]
fn sampler_failing_more_than_its_pdf_admits_fails_chi_square() {
    let report = check_caught(
        "Lambert ρ=0.8, rejection without the loop",
        &buggy_diffuse(0.8, DiffuseBug::RejectionWithoutLoop),
        &[Law::Sampling, Law::AlbedoEstimators],
    );
    let r = report.get(Law::Sampling).unwrap();
    assert!(r.figure < 1e-20, "{r}");
}

// ---------------------------------------------------------------------------------------
// 10. Transmission without the η² scaling
// ---------------------------------------------------------------------------------------

/// **10. A transmission lobe missing the `1/η'²` radiance scaling** → **generalised
/// reciprocity**. The crate's rough dielectric with the scaling dropped computes exactly its
/// importance-mode values; the bug is to return them while claiming radiance transport, so
/// the check runs with the radiance-mode index (`Config::eta = η`) and the radiance-mode
/// albedo bound (`η²`, reached inside the denser medium). The unscaled values obey the
/// importance-mode relation `f(wo, wi)/η_i² = f(wi, wo)/η_o²`, so the radiance-mode sides
/// `f(wo, wi)/η_o²` and `f(wi, wo)/η_i²` differ by `(η_i/η_o)⁴ = η⁴ = 5.06` for every
/// refracted pair: a relative error of `1 − η⁻⁴ = 0.80`. The values are positive, the
/// sampler untouched, and the unscaled lobe conserves energy, so every other law holds.
#[test]
fn transmission_without_eta_squared_fails_generalised_reciprocity() {
    let eta = 1.5_f32;
    let missing_scale = RoughDielectric::new(Ggx::isotropic(alpha(0.3)), Eta::new(eta).unwrap())
        .with_mode(TransportMode::Importance);
    let claims_radiance = Config {
        eta,
        albedo_bound: f64::from(eta * eta),
        ..config()
    };
    let report = check_bxdf(
        "rough glass α=0.3 η=1.5, no 1/η'²",
        &missing_scale,
        &claims_radiance,
    );
    assert_caught(&report, &[Law::Reciprocity]);
    let r = report.get(Law::Reciprocity).unwrap();
    // Every refracted pair gives the ratio η⁴, so the figure is 1 − η⁻⁴ but for the f32
    // round-off of the two values, a few ulps (measured 1.3e-7 apart).
    let want = 1.0 - f64::from(eta).powi(-4);
    eprintln!("relative error {:.9}, 1 − η⁻⁴ = {want:.9}", r.figure);
    assert!((r.figure - want).abs() < 1e-6, "{r}");
}

// ---------------------------------------------------------------------------------------
// A budget too small to judge
// ---------------------------------------------------------------------------------------

/// **A chi-square without degrees of freedom** (a budget so small that every bin expects
/// fewer than five samples, so all are pooled into one) is a failed check reported as
/// `p = NaN`, not a pass behind a p-value of 1: for a model (`sampling_chi2`, through
/// `check_bxdf`) and for a distribution (`check_ndf`), whose other laws still pass.
#[test]
fn chi_square_without_degrees_of_freedom_fails_with_a_nan_p_value() {
    let starved = Config {
        chi2_samples: 100,
        ..config()
    };
    let lambert = Lambert::new(0.8_f32).unwrap();
    let report = check_bxdf("Lambert ρ=0.8, 100 χ² samples", &lambert, &starved);
    assert_caught(&report, &[Law::Sampling]);
    let sampling = report.get(Law::Sampling).unwrap();
    assert!(sampling.figure.is_nan(), "{sampling}");
    assert!(sampling.to_string().contains("p = NaN"), "{sampling}");

    let ndf = Config {
        chi2_samples: 100,
        ..ndf_config(NDF_ALPHA)
    };
    let report = check_ndf(
        "GGX α=0.3, 100 χ² samples",
        &BuggyNdf::new(NDF_ALPHA, NdfBug::None),
        &ndf,
    );
    assert_caught(&report, &[Law::Sampling]);
    let sampling = report.get(Law::Sampling).unwrap();
    assert!(sampling.figure.is_nan(), "{sampling}");
    assert!(sampling.to_string().contains("p = NaN"), "{sampling}");
}

// ---------------------------------------------------------------------------------------
// The correct counterparts
// ---------------------------------------------------------------------------------------

/// Every model and distribution of the corpus without its bug passes every law, under the
/// same budgets: the failures above are the bugs', not the harness's.
#[test]
fn correct_counterparts_pass_every_law() {
    let report = check_ndf(
        "GGX α=0.3",
        &BuggyNdf::new(NDF_ALPHA, NdfBug::None),
        &ndf_config(NDF_ALPHA),
    );
    assert_caught(&report, &[]);
    check_caught(
        "Schlick (1 − cos)⁵ coat over ρ = 0.8",
        &SchlickCoated::new(false),
        &[],
    );
    for a in [0.3, 0.8] {
        check_caught(
            &format!("GGX α={a}, Schlick 0.04"),
            &buggy_glossy(a, GlossyBug::None),
            &[],
        );
    }
    check_caught(
        "Phong n=20.5",
        &PhongLobe {
            ks: 0.9,
            n: 20.5,
            clamp: true,
        },
        &[],
    );
    for rho in [0.8, 1.0] {
        check_caught(
            &format!("Lambert ρ={rho}"),
            &buggy_diffuse(rho, DiffuseBug::None),
            &[],
        );
    }
    let eta = 1.5_f32;
    let radiance = RoughDielectric::new(Ggx::isotropic(alpha(0.3)), Eta::new(eta).unwrap());
    let report = check_bxdf(
        "rough glass α=0.3 η=1.5, radiance",
        &radiance,
        &Config {
            eta,
            albedo_bound: f64::from(eta * eta),
            ..config()
        },
    );
    assert_caught(&report, &[]);
}

// ---------------------------------------------------------------------------------------
// Composition and layering (issue 12): checked in expectation
// ---------------------------------------------------------------------------------------

use lobe::bxdf::{At, CoatedDiffuse, LayerInterface, Layered, Mix, Prepare};
use lobe::microfacet::View;

/// A top interface for a layered model that ignores the transport mode it is asked for and
/// always scatters as in importance mode: the layered walk then enters without the `1/η²` of
/// refraction. Built honestly (`mode_blind: false`) it is the rough dielectric itself.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Coat {
    inner: RoughDielectric<Ggx>,
    mode_blind: bool,
}

impl Prepare for Coat {
    type Spectrum = f32;
    type Prepared = At<View>;
    fn prepare(&self, wo: Vec3) -> At<View> {
        self.inner.prepare(wo)
    }
    fn eval_prepared(&self, at: &At<View>, wi: Vec3) -> f32 {
        self.inner.eval_prepared(at, wi)
    }
    fn pdf_prepared(&self, at: &At<View>, wi: Vec3) -> f32 {
        self.inner.pdf_prepared(at, wi)
    }
    fn sample_prepared(&self, at: &At<View>, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        self.inner.sample_prepared(at, u, uc)
    }
    fn lobes(&self) -> Lobes {
        Prepare::lobes(&self.inner)
    }
}

impl LayerInterface for Coat {
    fn eta(&self) -> Eta {
        self.inner.eta()
    }
    fn for_transport(&self, mode: TransportMode) -> Self {
        let mode = if self.mode_blind {
            TransportMode::Importance
        } else {
            mode
        };
        Self {
            inner: self.inner.with_mode(mode),
            ..*self
        }
    }
}

/// A Lambertian base whose samples carry `f / |cos θi|` when `drop_cosine` is set: the walk's
/// throughput update `f |cos θi| / pdf` at the base then loses the base's cosine, as a walk
/// that multiplies by `f / pdf` does. `eval` and `pdf` are Lambert's.
struct Base {
    inner: Lambert<f32>,
    drop_cosine: bool,
}

impl Bxdf for Base {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.inner.eval(wo, wi)
    }
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        let s = self.inner.sample(wo, u, uc)?;
        Some(if self.drop_cosine {
            BxdfSample {
                f: s.f / s.wi.z.abs(),
                ..s
            }
        } else {
            s
        })
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.inner.pdf(wo, wi)
    }
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION
    }
}

/// A rough coat (GGX `α = 0.3`, `η = 1.5`) over a Lambertian base of reflectance `rho`, with
/// the injected faults.
fn layered(rho: f32, mode_blind: bool, drop_cosine: bool) -> Layered<Coat, Base> {
    Layered::new(
        Coat {
            inner: RoughDielectric::new(Ggx::isotropic(alpha(0.3)), Eta::new(1.5).unwrap()),
            mode_blind,
        },
        Base {
            inner: Lambert::new(rho).unwrap(),
            drop_cosine,
        },
    )
}

/// **16. A layered `eval` that forgets the `1/η²` on the way in** (the top's transport mode
/// ignored: pbrt-v4's `mode` left out of the entry's `Sample_f`) → **albedo estimators** and
/// **consistency in expectation**: `eval`'s light that went through the coat is `η² = 2.25`
/// times too bright, while the sampler's walk, which crosses the coat twice with the same
/// interface, loses `1/η²` going in and `η²` coming out and stays right. The sampled albedo is
/// unchanged (the energy bound passes) and `eval` stays symmetric (reciprocity passes): the
/// checks of `eval` against the sampler name the bug.
#[test]
fn layered_eval_without_eta_squared_on_the_way_in_fails_the_estimators() {
    let report = check_caught(
        "coated ρ=0.8, entry without 1/η²",
        &layered(0.8, true, false),
        &[Law::AlbedoEstimators, Law::Consistency],
    );
    assert!(figure(&report, Law::Consistency) > 10.0);
}

/// **17. A walk that drops the base's cosine** (the throughput multiplied by `f / pdf` at the
/// base) → **albedo estimators** and **consistency in expectation**: each bounce the walk
/// continues from a Lambertian base weighs `ρ / cos θ` instead of `ρ`, twice as much on
/// average, so the sampled albedo grows (0.52 at normal incidence for `ρ = 0.5`, where the
/// correct stack reflects 0.37); `eval` loses the cosine only on the paths it continues from
/// the base, not on its connections through the direction sampled from `wi`, so its
/// expectation is neither the sampler's nor the correct one. The density is untouched
/// (sampling passes); the gain stays below 1 at this `ρ` (the energy bound passes), and the
/// value's asymmetry is below what 64 estimates a side resolve (reciprocity passes).
#[test]
fn walk_without_the_base_cosine_fails_the_estimators() {
    let bug = layered(0.5, false, true);
    let report = check_caught(
        "coated ρ=0.5, base cosine dropped",
        &bug,
        &[Law::AlbedoEstimators, Law::Consistency],
    );
    let correct = albedo(&layered(0.5, false, false), Vec3::Z, &config());
    let buggy = albedo(&bug, Vec3::Z, &config());
    eprintln!(
        "albedo at normal incidence: {} (correct {})",
        buggy.sampled, correct.sampled
    );
    // The bug gains more than 0.1, by more than k standard errors of the difference.
    let (b, c) = (&buggy.sampled, &correct.sampled);
    let k = common::k_sigma(0.01, 1);
    assert!(
        b.mean - c.mean - 0.1 > k * b.std_err.hypot(c.std_err),
        "{b} vs {c}"
    );
    assert!(figure(&report, Law::Consistency) > 5.0);
}

/// A blend of a Lambertian and a glossy model whose density uses the weights the wrong way
/// round when `swapped` (the value and the choice of part are right).
struct BuggyMix {
    matte: Lambert<f32>,
    gloss: Microfacet<Ggx, Schlick<f32>>,
    weight: f32,
    swapped: bool,
}

impl BuggyMix {
    fn density(&self, wo: Vec3, wi: Vec3) -> f32 {
        let (wa, wb) = if self.swapped {
            (self.weight, 1.0 - self.weight)
        } else {
            (1.0 - self.weight, self.weight)
        };
        wa * self.matte.pdf(wo, wi) + wb * self.gloss.pdf(wo, wi)
    }
}

impl Bxdf for BuggyMix {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        (1.0 - self.weight) * self.matte.eval(wo, wi) + self.weight * self.gloss.eval(wo, wi)
    }
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        let wi = if uc < 1.0 - self.weight {
            self.matte.sample(wo, u, 0.5)?.wi
        } else {
            self.gloss.sample(wo, u, 0.5)?.wi
        };
        reflection(
            wi,
            self.eval(wo, wi),
            self.density(wo, wi),
            Lobes::GLOSSY_REFLECTION,
        )
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.density(wo, wi)
    }
    fn lobes(&self) -> Lobes {
        Lobes::DIFFUSE_REFLECTION | Lobes::GLOSSY_REFLECTION
    }
}

fn buggy_mix(swapped: bool) -> BuggyMix {
    BuggyMix {
        matte: Lambert::new(0.5).unwrap(),
        gloss: glossy(0.2),
        weight: 0.2,
        swapped,
    }
}

/// **18. A mixture pdf with the wrong weights** (`w pdf_A + (1 − w) pdf_B` for a sampler that
/// picks `A` with probability `1 − w`) → **sampling (χ²)**: the sampler draws the right
/// mixture, the density claims another. The sample's weight is divided by that density, so
/// the sampled albedo is wrong too and the estimators disagree; `sample` and `pdf` share the
/// density, so consistency holds.
#[test]
fn mixture_pdf_with_swapped_weights_fails_chi_square() {
    let report = check_caught(
        "Mix(Lambert 0.5, GGX α=0.2, w = 0.2), pdf weights swapped",
        &buggy_mix(true),
        &[Law::Sampling, Law::AlbedoEstimators],
    );
    assert!(figure(&report, Law::Sampling) < 1e-10);
}

/// The composition corpus's correct counterparts pass every law, in expectation where the
/// model is stochastic, under the same budget; and the crate's own `Mix` of the same parts.
#[test]
fn correct_compositions_pass_every_law() {
    check_caught("coated ρ=0.8", &layered(0.8, false, false), &[]);
    check_caught("coated ρ=0.5", &layered(0.5, false, false), &[]);
    check_caught(
        "Mix(Lambert 0.5, GGX α=0.2, w = 0.2)",
        &buggy_mix(false),
        &[],
    );
    let crate_mix = Mix::new(Lambert::new(0.5).unwrap(), glossy(0.2), 0.2).unwrap();
    check_caught("lobe::bxdf::Mix of the same", &crate_mix, &[]);
    let coated =
        CoatedDiffuse::coated_diffuse(0.8_f32, Ggx::isotropic(alpha(0.3)), Eta::new(1.5).unwrap())
            .unwrap();
    let report = check_caught("lobe::bxdf::CoatedDiffuse of the same", &coated, &[]);
    assert!(
        report
            .get(Law::Reciprocity)
            .unwrap()
            .figure_name
            .contains("expectation")
    );
}
