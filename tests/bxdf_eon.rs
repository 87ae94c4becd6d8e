//! The energy-preserving Oren-Nayar model (EON) through the law suite; the white furnace
//! by quadrature, with the paper's fitted FON albedo and with the exact one; the closed-form
//! albedo; values computed independently; totality at the normal and at grazing; refused
//! parameters.

mod common;

use common::exact::{
    assert_grey_value, assert_one_sided, assert_reciprocity_bit_exact,
    assert_reflectance_validated, assert_total_at_grazing, hemisphere_pairs,
};
use common::quadrature::albedo_quadrature;

use common::laws::{Model, assert_all_laws};
use lobe::Vec3;
use lobe::bxdf::{Bxdf, EnergyPreservingOrenNayar as Eon};
use lobe::verify::Pcg32;

/// The largest excess of the fitted model's albedo over 1 (ρ = 1), over `r ∈ [0, 1]` and
/// `θo < 90°`: `1.46e-4` at `r = 1`, `θo ≈ 82.3°`, computed independently in f64 (a Python
/// script integrating the published formulas), rounded up. The documented energy bound.
const FIT_EXCESS: f64 = 1.5e-4;

fn eon(rho: f32, r: f32) -> Eon {
    Eon::new(rho, r).unwrap()
}

#[test]
fn eon_obeys_every_law() {
    let settings = [
        (1.0f32, 0.1f32, false),
        (1.0, 0.5, false),
        (1.0, 1.0, false),
        (1.0, 1.0, true),
        (0.5, 0.7, false),
        (1.0, 0.0, false),
    ];
    for (rho, r, exact) in settings {
        let m = if exact {
            eon(rho, r).with_exact_albedo()
        } else {
            eon(rho, r)
        };
        let name = format!("EON ρ={rho} r={r}{}", if exact { " exact" } else { "" });
        // Exact E_F: albedo ≤ 1. The paper's fit: ≤ 1 + its measured excess.
        let bound = if exact { 1.0 } else { 1.0 + FIT_EXCESS };
        let model = Model {
            albedo_max: bound,
            ..Model::new(name, m)
        };
        assert_all_laws(&model, settings.len());
    }
}

#[test]
fn reciprocity_is_exact() {
    let mut rng = Pcg32::new(7, 3);
    for m in [eon(0.9, 0.8), eon(0.9, 0.8).with_exact_albedo()] {
        // Bit-for-bit: every term is symmetric, so the error is exactly 0.
        let pairs = hemisphere_pairs(&mut rng, 100_000);
        assert_reciprocity_bit_exact("EON ρ=0.9 r=0.8", &m, &pairs, false);
    }
}

/// The white furnace: with ρ = 1 the albedo is 1 at every `θo`, to the fit's error with the
/// paper's fitted `E_F`, to f32 round-off with the exact one.
#[test]
fn white_furnace() {
    // The fitted model's true albedo, predicted independently in f64 from the published
    // formulas (exact E_F in f_ss's integral, the fit in f_ms): (r, [(θo, albedo)]).
    let predicted: [(f32, [(f64, f64); 6]); 3] = [
        (
            0.1,
            [
                (0.0, 0.999_990_516),
                (17.5, 0.999_932_101),
                (30.0, 0.999_972_816),
                (60.0, 0.999_983_165),
                (82.3, 1.000_018_335),
                (89.0, 0.999_973_315),
            ],
        ),
        (
            0.5,
            [
                (0.0, 0.999_957_351),
                (17.5, 0.999_694_669),
                (30.0, 0.999_877_758),
                (60.0, 0.999_924_298),
                (82.3, 1.000_082_450),
                (89.0, 0.999_880_002),
            ],
        ),
        (
            1.0,
            [
                (0.0, 0.999_924_232),
                (17.5, 0.999_457_572),
                (30.0, 0.999_782_834),
                (60.0, 0.999_865_513),
                (82.3, 1.000_146_475),
                (89.0, 0.999_786_822),
            ],
        ),
    ];
    for (r, points) in predicted {
        let fitted = eon(1.0, r);
        let exact = fitted.with_exact_albedo();
        // The implementation integrates to the predicted albedo (f32 round-off of eval).
        for (deg, want) in points {
            let got = albedo_quadrature(&fitted, deg);
            assert!((got - want).abs() < 2e-6, "r={r} θo={deg}: {got} vs {want}");
        }
        // The deviation from 1 over θo ∈ [0°, 89°] in steps of 0.5°.
        let (mut fit_dev, mut fit_at, mut fit_excess, mut exact_dev) =
            (0.0f64, 0.0, 0.0f64, 0.0f64);
        for k in 0..=178 {
            let deg = 0.5 * f64::from(k);
            let e = albedo_quadrature(&fitted, deg) - 1.0;
            if e.abs() > fit_dev {
                (fit_dev, fit_at) = (e.abs(), deg);
            }
            fit_excess = fit_excess.max(e);
            exact_dev = exact_dev.max((albedo_quadrature(&exact, deg) - 1.0).abs());
        }
        eprintln!(
            "EON r={r}: white furnace max |albedo − 1| = {fit_dev:.2e} at θo = {fit_at}° (fit), \
             max excess {fit_excess:.2e}; {exact_dev:.1e} (exact E_F)"
        );
        // The documented figures: 6.8e-5, 3.1e-4, 5.4e-4 for the fit; f32 round-off exact.
        let fit_bound = match r {
            0.1 => 7e-5,
            0.5 => 3.2e-4,
            _ => 5.5e-4,
        };
        assert!(fit_dev < fit_bound, "r={r}: {fit_dev}");
        assert!(fit_excess < FIT_EXCESS, "r={r}: {fit_excess}");
        assert!(exact_dev < 1e-6, "r={r}: {exact_dev}");
    }
}

#[test]
fn albedo_closed_form() {
    // ρ = 0.5, r = 1, exact E_F: ρ E_F + ρ_ms (1 − E_F), computed independently in f64.
    let m = eon(0.5, 1.0).with_exact_albedo();
    for (deg, want) in [
        (0.0f64, 0.439_034_095),
        (45.0, 0.449_915_142),
        (80.0, 0.487_571_562),
    ] {
        let closed = f64::from(m.albedo(deg.to_radians().cos() as f32));
        let quad = albedo_quadrature(&m, deg);
        assert!((closed - want).abs() < 1e-6, "θo={deg}: {closed} vs {want}");
        assert!((quad - want).abs() < 2e-6, "θo={deg}: {quad} vs {want}");
    }
    // The fitted model's closed form is the paper's E_EON: 1 for ρ = 1 by construction.
    let white = eon(1.0, 0.6);
    for mu in [1.0f32, 0.7, 0.2, 1e-7] {
        assert!((white.albedo(mu) - 1.0).abs() < 1e-6);
    }
    assert_eq!(white.albedo(0.0), 0.0);
    assert_eq!(white.albedo(f32::NAN), 0.0);
    // The albedo of a coloured surface stays below ρ per channel.
    let m = Eon::new(Vec3::new(0.2, 0.5, 0.9), 1.0).unwrap();
    let a = m.albedo(0.5);
    assert!(a.x < 0.2 && a.y < 0.5 && a.z < 0.9, "{a}");
}

#[test]
fn values_match_an_independent_evaluation() {
    // f from the published formulas (s = wi·wo − μi μo from f64 vectors, E_F by the fit and
    // by the exact G with its 1/μ form), in f64, for ρ = 0.8, r = 0.7; (wo, wi, fit, exact).
    let cases = [
        ((40.0, 0.3), (65.0, 1.1), 3.103_528_733e-1, 3.103_620_222e-1),
        ((70.0, 0.0), (20.0, 2.5), 1.916_962_983e-1, 1.917_560_711e-1),
        ((0.0, 0.0), (50.0, 1.0), 2.456_648_548e-1, 2.456_358_196e-1),
        ((85.0, 0.2), (80.0, 0.25), 1.050_027_945, 1.050_020_818),
        ((30.0, 0.4), (30.0, 0.4), 2.944_526_703e-1, 2.945_073_442e-1),
    ];
    let fitted = Eon::new(Vec3::splat(0.8), 0.7).unwrap();
    let exact = fitted.with_exact_albedo();
    assert!(!fitted.is_exact() && exact.is_exact());
    for ((to, po), (ti, pi), want_fit, want_exact) in cases {
        let (wo, wi) = (common::dir(to, po), common::dir(ti, pi));
        for (m, want) in [(fitted, want_fit), (exact, want_exact)] {
            assert_grey_value(&m, wo, wi, want, 3e-6);
        }
    }
    // r = 0 is Lambert, with no multiple-scattering residue.
    let lambert = eon(0.6, 0.0);
    let f = lambert.eval(common::dir(80.0, 0.0), common::dir(85.0, 0.1));
    assert_eq!(f, 0.6 / core::f32::consts::PI);
}

#[test]
fn finite_at_the_normal_and_at_grazing() {
    for m in [eon(1.0, 1.0), eon(1.0, 1.0).with_exact_albedo()] {
        // At the normal s = 0 and the compensation of μ = 1 is C1 (f = A_F/π + multi C1²):
        // finite and positive.
        let f = m.eval(Vec3::Z, Vec3::Z);
        assert!(f.is_finite() && f > 0.0);
        assert_total_at_grazing("EON ρ=1 r=1", &m);
        // Below the horizon and exactly on it: nothing.
        assert_one_sided("EON ρ=1 r=1", &m, Vec3::Z, Vec3::Z);
    }
}

#[test]
fn refuses_bad_parameters() {
    for r in [f32::NAN, -1e-6, 1.000_001, f32::INFINITY] {
        let e = Eon::new(0.5f32, r).unwrap_err();
        assert_eq!((e.param(), e.range()), ("roughness", "[0, 1]"));
    }
    assert_reflectance_validated(|rho| Eon::new(rho, 0.3), |rho| Eon::new(rho, 0.3));
    assert!(Eon::new(1.0f32, 0.0).is_ok() && Eon::new(0.0f32, 1.0).is_ok());
}
