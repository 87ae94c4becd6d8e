//! The law suite every BSDF model of the crate runs through, as thin assertions over the
//! public harness [`lobe::verify`]: totality, reciprocity, the energy bound by two
//! estimators, the sampler's chi-square test and `sample`/`eval`/`pdf` consistency.
//!
//! Each function asserts and prints its measured figure (`--nocapture` shows them).

use lobe::Vec3;
use lobe::bxdf::Bxdf;
use lobe::verify::{
    BxdfCheck, Config, Estimate, LawReport, check_bxdf, consistency, energy_bound, positivity,
    reciprocity, sampling_chi2, sidak,
};

/// A model under test.
pub struct Model {
    /// What the failure messages call it.
    pub name: String,
    /// The model, on `f32`.
    pub bxdf: Box<dyn Bxdf<Spectrum = f32>>,
    /// The relative index below the surface, for generalised reciprocity (1 for a BRDF;
    /// `1/η` for a model in importance mode).
    pub eta: f32,
    /// The largest directional albedo the model claims (1 for an energy-conserving model;
    /// the measured bound for one that gains energy).
    pub albedo_max: f64,
}

impl Model {
    /// A model that claims energy conservation.
    pub fn new(name: impl Into<String>, bxdf: impl Bxdf<Spectrum = f32> + 'static) -> Self {
        Self {
            name: name.into(),
            bxdf: Box::new(bxdf),
            eta: 1.0,
            albedo_max: 1.0,
        }
    }

    /// The harness settings for this model, one of `n_tests` models in the calling file (the
    /// family's 1% significance is shared among them, Šidák-corrected).
    pub fn config(&self, n_tests: usize) -> Config {
        Config {
            eta: self.eta,
            albedo_bound: self.albedo_max,
            significance: sidak(0.01, n_tests.max(1)),
            ..Config::default()
        }
    }
}

fn check(model: &Model, report: LawReport) -> LawReport {
    eprintln!("{}: {report}", model.name);
    assert!(report.passed(), "{}: {report}", model.name);
    report
}

/// The viewer directions the checks use for this model.
pub fn viewer_directions(model: &Model) -> Vec<Vec3> {
    model.config(1).viewer_directions(model.bxdf.as_ref())
}

/// Finite, non-negative `eval`, `pdf` and samples over `n` adversarial direction pairs.
pub fn assert_total(model: &Model, n: usize) {
    let config = Config {
        pairs: n,
        ..model.config(1)
    };
    check(model, positivity(model.bxdf.as_ref(), &config));
}

/// Reciprocity over `n` random pairs within `tol` plus each pair's round-off allowance;
/// returns the largest relative error over the well-conditioned pairs.
pub fn assert_reciprocal(model: &Model, n: usize, tol: f64) -> f64 {
    let config = Config {
        pairs: n,
        reciprocity_tolerance: tol,
        ..model.config(1)
    };
    check(model, reciprocity(model.bxdf.as_ref(), &config)).figure
}

/// The energy bound (and, without delta lobes, the agreement of the two estimators);
/// returns the largest albedo.
pub fn assert_energy_bound(model: &Model, budget: &BxdfCheck, n_tests: usize) -> f64 {
    let config = Config {
        albedo_samples: budget.samples,
        seed: budget.seed,
        ..model.config(n_tests)
    };
    let (bound, agreement) = energy_bound(model.bxdf.as_ref(), &config);
    if let Some(a) = agreement {
        check(model, a);
    }
    check(model, bound).figure
}

/// The sampler against its pdf at every viewer direction.
pub fn assert_sampling(model: &Model, samples: usize, n_tests: usize) {
    let config = Config {
        chi2_samples: samples,
        ..model.config(n_tests)
    };
    check(model, sampling_chi2(model.bxdf.as_ref(), &config));
}

/// `sample`'s `f` and `pdf` equal `eval` and `pdf` at the sampled direction within `tol`.
pub fn assert_consistent(model: &Model, tol: f64) {
    let config = Config {
        consistency_tolerance: tol,
        ..model.config(1)
    };
    check(model, consistency(model.bxdf.as_ref(), &config));
}

/// Every law, through [`check_bxdf`], at the harness's default budgets.
pub fn assert_all_laws(model: &Model, n_tests: usize) {
    let report = check_bxdf(&model.name, model.bxdf.as_ref(), &model.config(n_tests));
    eprint!("{report}");
    assert!(report.passed(), "{report}");
}

/// The albedo `a` the model's sampler measured against a closed form `exact`: equal to it
/// where the closed form is the albedo (`at_closed_form`, e.g. normal incidence), at most it
/// elsewhere; within `k` standard errors plus the `1e-6` relative rounding of the `f32`
/// weights the estimate averages (what the law suite allows for too).
pub fn assert_albedo_against(name: &str, a: &Estimate, exact: f64, k: f64, at_closed_form: bool) {
    let allowance = k * a.std_err + 1e-6 * exact;
    if at_closed_form {
        assert!(
            (a.mean - exact).abs() <= allowance,
            "{name}: albedo {a} vs {exact}"
        );
    } else {
        assert!(
            a.mean <= exact + allowance,
            "{name}: albedo {a} above {exact}"
        );
    }
}

/// Every law of every model in `models`, the family's 1% shared among them.
pub fn assert_every_model_obeys_every_law(models: &[Model]) {
    for m in models {
        assert_all_laws(m, models.len());
    }
}
