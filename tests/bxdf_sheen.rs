//! The Charlie sheen (issue 12): its `D` is normalised, the fitted `Λ` is close to the Smith
//! `Λ` of that `D` for `r ≥ 0.1` and the tabulated exact one (`with_exact_smith`) at every `r`
//! (the projected-area identity, measured), the albedo table agrees with Monte Carlo, and the
//! laws it meets — with the fit's energy-bound failure at grazing for small roughness
//! measured, as its docs say, and the exact masking's pass.
//!
//! `cargo test --test bxdf_sheen -- --nocapture` prints the figures.

mod common;

use core::f64::consts::PI;
use lobe::bxdf::{Bxdf, Sheen};
use lobe::verify::{Config, Law, albedo_sampled, check_bxdf};
use lobe::{ParamError, Spectrum, Vec3};

/// Statistical tests in this file: 5 harness runs, 7 sheens × 8 albedo angles.
const TESTS: usize = 5 + 56;

fn config() -> Config {
    common::combinator_budget(100_000, TESTS)
}

/// `2π ∫₀¹ g(μ) dμ` by the midpoint rule on `n` panels.
fn over_mu(n: usize, g: impl Fn(f64) -> f64) -> f64 {
    (0..n).map(|i| g((i as f64 + 0.5) / n as f64)).sum::<f64>() * 2.0 * PI / n as f64
}

#[test]
fn d_is_normalised() {
    for r in [0.01_f32, 0.1, 0.5, 1.0] {
        let s = Sheen::new(1.0_f32, r).unwrap();
        // ∫ D(m) cos θm dωm with dω = dμ dφ.
        let integral = over_mu(200_000, |mu| {
            let sin = (1.0 - mu * mu).sqrt();
            f64::from(s.d(Vec3::new(sin as f32, 0.0, mu as f32))) * mu
        });
        eprintln!("r={r}: ∫ D cos θ = {integral:.9}");
        assert!((integral - 1.0).abs() < 1e-6, "r={r}: {integral}");
    }
}

/// The relative error of `∫ G1(w) max(0, w·m) D(m) dm = cos θw` (Heitz 2014, eq. 2) with
/// `G1 = 1/(1 + Λ)` and the sheen's `Λ` (fitted or tabulated), at `θw = theta` degrees: how
/// close it is to the exact Smith `Λ` of this `D`, by a product midpoint rule in
/// `(cos θm, φm)`.
fn projected_area_error(s: &Sheen<f32>, theta: f64) -> f64 {
    let (st, ct) = theta.to_radians().sin_cos();
    let (nm, np) = (2_000, 400);
    let mut sum = 0.0;
    for i in 0..nm {
        let mu = (i as f64 + 0.5) / nm as f64;
        let sm = (1.0 - mu * mu).sqrt();
        let d = f64::from(s.d(Vec3::new(sm as f32, 0.0, mu as f32)));
        for j in 0..np {
            let phi = 2.0 * PI * (j as f64 + 0.5) / np as f64;
            let wm = st * sm * phi.cos() + ct * mu;
            sum += wm.max(0.0) * d;
        }
    }
    let projected = sum * 2.0 * PI / (nm * np) as f64 / (1.0 + f64::from(s.lambda(ct as f32)));
    (projected - ct) / ct
}

#[test]
fn the_fitted_lambda_nearly_satisfies_the_projected_area_identity() {
    let mut worst = 0.0_f64;
    for r in [0.1_f32, 0.5, 1.0] {
        let s = Sheen::new(1.0_f32, r).unwrap();
        for theta in [0.0_f64, 30.0, 60.0, 80.0] {
            let rel = projected_area_error(&s, theta);
            eprintln!("r={r} θ={theta}°: projected area off by {rel:+.4}");
            worst = worst.max(rel.abs());
        }
    }
    // The fit's error, the 5% `Sheen`'s docs quote for r ≥ 0.1 (measured 4.76%).
    assert!(worst < 0.05, "{worst}");
}

/// With [`Sheen::with_exact_smith`] the identity holds at every roughness and angle, up to the
/// table's interpolation and the quadratures' error.
#[test]
fn the_exact_smith_lambda_satisfies_the_projected_area_identity() {
    let mut worst = 0.0_f64;
    for r in [0.01_f32, 0.03, 0.1, 0.5, 1.0] {
        let s = Sheen::new(1.0_f32, r).unwrap().with_exact_smith();
        assert!(s.has_exact_smith());
        for theta in [
            0.0_f64, 2.0, 5.0, 6.5, 8.0, 10.0, 15.0, 20.0, 25.0, 30.0, 45.0, 60.0, 70.0, 75.0,
            80.0, 85.0, 87.5, 89.0,
        ] {
            let rel = projected_area_error(&s, theta);
            eprintln!("exact Smith, r={r} θ={theta}°: projected area off by {rel:+.2e}");
            worst = worst.max(rel.abs());
        }
    }
    // Measured 9.3e-6 at worst (89°, r = 0.01, where the midpoint rule's own error grows).
    assert!(worst < 2e-5, "{worst}");
}

/// The exact masking's albedo stays below 1 up to the table's grazing end, where the energy-bound
/// law's directions do not reach: 0.995 to 0.999 as `μo → 0` (the first entry, integrated at
/// `μo = 1e-4`), as `Sheen`'s docs say (printed; held between 0.99 and 1); the fit's passes 1 there
/// for a smooth sheen (1.90 at `r = 0.01`).
#[test]
fn the_exact_smith_albedo_stays_below_one_to_grazing() {
    for r in [0.01_f32, 0.03, 0.1, 0.5, 1.0] {
        let exact = Sheen::new(1.0_f32, r).unwrap().with_exact_smith();
        let fit = Sheen::new(1.0_f32, r).unwrap();
        for mu in [1e-12_f32, 1e-4, 1e-3] {
            let (e, f) = (exact.albedo(mu), fit.albedo(mu));
            eprintln!("r={r} μo={mu:e}: exact Smith {e:.4}, fit {f:.4}");
            assert!(e > 0.9 && e < 1.0, "r={r} μo={mu}: {e}");
        }
        let end = exact.albedo(1e-12);
        assert!(end > 0.99 && end < 1.0, "r={r}: {end}");
    }
    assert!(Sheen::new(1.0_f32, 0.01).unwrap().albedo(1e-12) > 1.5);
}

/// Below `r = 0.1` the fit leaves the exact `Λ` far behind, which is what makes the sheen
/// reflect more than it receives at grazing (the exact `Λ` of this `D` keeps the albedo below
/// 1 at every `r`: 0.69 at 89° for `r = 0.01`, against the fit's 1.69): the projected area at
/// 60° is over by more than 10% at `r = 0.06`, 35% at `r = 0.03` and 100% at `r = 0.01`
/// (measured +12.2%, +40.8%, +120%), as `Sheen`'s docs say.
#[test]
fn below_r_one_tenth_the_fitted_lambda_is_far_from_the_exact_one() {
    for (r, over) in [(0.06_f32, 0.10), (0.03, 0.35), (0.01, 1.0)] {
        let rel = projected_area_error(&Sheen::new(1.0_f32, r).unwrap(), 60.0);
        eprintln!("r={r} θ=60°: projected area off by {rel:+.4}");
        assert!(rel > over, "r={r}: {rel}");
    }
}

#[test]
fn the_albedo_table_matches_monte_carlo() {
    let k = common::k_sigma(0.01, TESTS);
    let c = config();
    // The roughnesses and angles `Sheen`'s docs quote, and more.
    let sheens = [0.01_f32, 0.03, 0.1, 0.5, 1.0]
        .map(|r| Sheen::new(1.0_f32, r).unwrap())
        .into_iter()
        .chain([0.01_f32, 0.03].map(|r| Sheen::new(1.0_f32, r).unwrap().with_exact_smith()));
    for s in sheens {
        let (r, exact) = (s.roughness(), s.has_exact_smith());
        for theta in [0.0_f32, 30.0, 50.0, 60.0, 65.0, 80.0, 85.0, 89.0] {
            let wo = common::dir(theta, 0.0);
            let mc = albedo_sampled(&s, wo, &c);
            let table = f64::from(s.albedo(wo.z));
            eprintln!("r={r} exact Smith {exact} θo={theta}°: table {table:.4}, Monte Carlo {mc}");
            // The table's own error (quadrature, interpolation between 32 angles): 1.2%.
            assert!(
                (mc.mean - table).abs() <= 0.012 * table + 1e-4 + k * mc.std_err,
                "r={r} θo={theta}°: table {table}, {mc}"
            );
        }
    }
    // A tinted sheen's albedo is its colour times the white one's.
    let tinted = Sheen::new(Vec3::new(1.0, 0.5, 0.25), 0.5).unwrap();
    let white = Sheen::new(1.0_f32, 0.5).unwrap();
    assert_eq!(tinted.albedo(0.3).y, 0.5 * white.albedo(0.3));
}

#[test]
fn sheen_obeys_its_laws() {
    let c = config();
    for r in [0.1_f32, 1.0] {
        let s = Sheen::new(Vec3::new(0.9, 0.6, 0.3), r).unwrap();
        let report = check_bxdf(&format!("Sheen r={r}"), &s, &c);
        eprintln!("{report}");
        assert!(report.passed(), "{report}");
    }
    // A smooth sheen reflects more than it receives at grazing angles (the documented finding):
    // every law but the energy bound holds.
    let s = Sheen::new(1.0_f32, 0.03).unwrap();
    let report = check_bxdf("Sheen r=0.03", &s, &c);
    eprintln!("{report}");
    for r in &report.laws {
        assert_eq!(r.passed, r.law != Law::EnergyBound, "{r}");
    }
    let bound = report.get(Law::EnergyBound).unwrap();
    assert!(bound.figure > 1.0, "{bound}");
    // With the exact Smith masking the same sheens, and the smoothest, obey every law.
    for r in [0.01_f32, 0.03] {
        let s = Sheen::new(1.0_f32, r).unwrap().with_exact_smith();
        let report = check_bxdf(&format!("Sheen r={r}, exact Smith"), &s, &c);
        eprintln!("{report}");
        assert!(report.passed(), "{report}");
    }
}

/// The albedo of a viewer below or on the surface is 0, as the sheen's value there (it read
/// the table's grazing end: 0.658 at `r = 0.3` for `cos θo = −0.5`).
#[test]
fn the_albedo_below_the_surface_is_zero() {
    let s = Sheen::new(1.0_f32, 0.3).unwrap();
    for c in [-0.5_f32, -0.0, 0.0, f32::NAN] {
        assert_eq!(s.albedo(c), 0.0, "cos θo = {c}");
    }
    assert!(s.albedo(1e-7) > 0.5 && s.albedo(1.0) > 0.0);
}

#[test]
fn parameters_are_validated() {
    // Both constructors refuse the same parameters.
    type Constructor = fn(f32, f32) -> Result<Sheen<f32>, ParamError>;
    let constructors: [Constructor; 2] = [Sheen::new, Sheen::new_exact_smith];
    for build in constructors {
        for (color, r, param) in [
            (1.0, 0.0, "roughness"),
            (1.0, f32::NAN, "roughness"),
            (1.0, 1.5, "roughness"),
            (1.2, 0.5, "color"),
        ] {
            assert_eq!(
                build(color, r).unwrap_err().param(),
                param,
                "({color}, {r})"
            );
        }
    }
    let s = Sheen::new(Vec3::splat(0.5), 0.5).unwrap();
    assert!(s.albedo(0.5).max_channel() < 0.5);
    assert!(s.eval(Vec3::Z, -Vec3::Z) == Vec3::ZERO);
}

/// `new_exact_smith` builds what `new(…)?.with_exact_smith()` builds (every field, the albedo
/// table included: a constructor that integrated its table before the exact masking's fails),
/// and `with_exact_smith` on it leaves it equal (its refusals: `parameters_are_validated`).
#[test]
fn new_exact_smith_is_new_then_with_exact_smith() {
    let c = Vec3::new(0.9, 0.4, 0.1);
    for r in [0.01, 0.03, 0.1, 0.5, 1.0] {
        let built = Sheen::new_exact_smith(c, r).unwrap();
        assert!(built.has_exact_smith());
        assert_eq!(
            built,
            Sheen::new(c, r).unwrap().with_exact_smith(),
            "r = {r}"
        );
        assert_eq!(built.with_exact_smith(), built, "r = {r}");
        assert_ne!(built.albedo(0.5), Vec3::ZERO, "r = {r}");
    }
}
