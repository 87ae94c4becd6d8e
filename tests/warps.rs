//! Every warp in `lobe::sampling` against its density, by Pearson's chi-square test at one
//! million samples; and deliberately wrong densities and samplers, which the same test must
//! reject, to show that it can fail.
//!
//! The passing tests share a family-wise significance of 1 %, Šidák-corrected over the
//! number of chi-square runs expected to pass. The failing ones assert a rejection at that
//! same corrected level (and print their p-values, as the passing ones do, with
//! `--nocapture`).

use lobe::sampling::{
    cosine_hemisphere, cosine_hemisphere_pdf, square_to_disk_concentric, uniform_cone,
    uniform_cone_of_width, uniform_cone_pdf, uniform_cone_pdf_of_width, uniform_hemisphere,
    uniform_hemisphere_pdf, uniform_sphere, uniform_sphere_pdf,
};
use lobe::verify::{Chi2Bin, Chi2Config, Chi2Report, chi2_sphere, sidak};
use lobe::{Vec2, Vec3};

/// Samples per chi-square run.
const SAMPLES: usize = 1_000_000;
/// Chi-square runs in this file that are expected to pass: cosine hemisphere, uniform
/// hemisphere, uniform sphere, concentric disk, three cones, the half-failing sampler
/// against its halved density, and three cosine-power lobes.
const PASSING_RUNS: usize = 11;

/// The configuration for one run: default bins, a seed of its own, corrected significance.
fn config(seed: u64) -> Chi2Config {
    Chi2Config {
        samples: SAMPLES,
        seed,
        significance: sidak(0.01, PASSING_RUNS),
        ..Chi2Config::default()
    }
}

fn assert_passes(name: &str, report: &Chi2Report) {
    println!("{name}: {report}");
    assert!(report.passed(), "{name} rejected:\n{report}");
    assert_eq!(report.invalid_samples, 0, "{name}");
    assert_eq!(report.zero_bin_hits, 0, "{name}");
    assert!(
        (report.pdf_integral - 1.0).abs() < 1e-5,
        "{name}: ∫ pdf = {}",
        report.pdf_integral
    );
}

fn assert_rejected(name: &str, report: &Chi2Report) {
    println!("{name}: {report}");
    assert!(!report.passed(), "{name} was accepted:\n{report}");
}

/// `pdf` on the upper hemisphere `z ≥ 0`, zero below.
fn upper(w: Vec3, pdf: f32) -> f64 {
    if w.z >= 0.0 { f64::from(pdf) } else { 0.0 }
}

/// The uniform density of the upper hemisphere.
fn uniform_upper(w: Vec3) -> f64 {
    upper(w, uniform_hemisphere_pdf())
}

/// The chi-square test of a warp that always returns a direction against `pdf`.
fn warp_chi2(warp: impl Fn(Vec2) -> Vec3, pdf: impl Fn(Vec3) -> f64, seed: u64) -> Chi2Report {
    chi2_sphere(|u| Some(warp(u)), pdf, &config(seed))
}

/// Cosine-distributed directions from half the draws (`u.x ≥ ½`, rescaled), `None` from the
/// other half.
fn half_failing(u: Vec2) -> Option<Vec3> {
    (u.x >= 0.5).then(|| cosine_hemisphere(Vec2::new(2.0 * u.x - 1.0, u.y)))
}

#[test]
fn cosine_hemisphere_matches_its_pdf() {
    let report = warp_chi2(
        cosine_hemisphere,
        |w| f64::from(cosine_hemisphere_pdf(w.z)),
        11,
    );
    assert_passes("cosine hemisphere", &report);
}

#[test]
fn cosine_power_hemisphere_matches_its_pdf() {
    // n = 0 is the uniform hemisphere and n = 1 the cosine one; n = 8 is a narrow lobe still
    // several bins wide.
    for (i, n) in [0.0f32, 1.0, 8.0].into_iter().enumerate() {
        let report = chi2_sphere(
            |u| Some(lobe::sampling::cosine_power_hemisphere(u, n)),
            |w| f64::from(lobe::sampling::cosine_power_hemisphere_pdf(w.z, n)),
            &config(40 + i as u64),
        );
        assert_passes(&format!("cosine power n = {n}"), &report);
    }
}

#[test]
fn uniform_hemisphere_matches_its_pdf() {
    let report = warp_chi2(uniform_hemisphere, uniform_upper, 12);
    assert_passes("uniform hemisphere", &report);
}

#[test]
fn uniform_sphere_matches_its_pdf() {
    let report = warp_chi2(uniform_sphere, |_| f64::from(uniform_sphere_pdf()), 13);
    assert_passes("uniform sphere", &report);
}

#[test]
fn concentric_disk_is_uniform() {
    // Lift the disk to the hemisphere with Lambert's azimuthal equal-area projection,
    // (x, y) ↦ (x √(2 − r²), y √(2 − r²), 1 − r²), which sends the uniform density 1/π on
    // the unit disk to the uniform density 1/(2π) on the hemisphere. A different lift from
    // the cosine warp's, so the two tests check the disk map through different eyes.
    let lift = |u: Vec2| {
        let p = square_to_disk_concentric(u);
        let r2 = p.length_squared().min(1.0);
        let s = (2.0 - r2).sqrt();
        Some(Vec3::new(p.x * s, p.y * s, 1.0 - r2))
    };
    let report = chi2_sphere(lift, uniform_upper, &config(14));
    assert_passes("concentric disk (equal-area lift)", &report);
}

/// A cone given by its width `w = 1 − cos θmax` keeps its angle where `cos θmax` would round
/// to 1 (below `w ≈ 6e-8`): the samples' `sin² θ` is `u w (2 − u w)` to round-off, every
/// sample inside the cone, and the density integrates to 1 over its solid angle `2π w`; for
/// a cone `f32` can hold either way, both forms give the same bits.
#[test]
fn a_narrow_cone_by_its_width_keeps_its_angle() {
    for w in [1e-12_f32, 1e-9, 3e-8, 1e-4] {
        for ux in [0.0_f32, 0.25, 0.5, 1.0] {
            let d = uniform_cone_of_width(Vec2::new(ux, 0.3), w);
            let sin2 = f64::from(d.x).powi(2) + f64::from(d.y).powi(2);
            let want = f64::from(ux) * f64::from(w) * (2.0 - f64::from(ux) * f64::from(w));
            assert!(
                (sin2 - want).abs() <= 1e-6 * want,
                "w {w}, u {ux}: sin² θ {sin2} vs {want}"
            );
            assert!((d.length() - 1.0).abs() < 1e-6, "{d:?}");
        }
        let mass =
            f64::from(uniform_cone_pdf_of_width(w)) * 2.0 * std::f64::consts::PI * f64::from(w);
        assert!((mass - 1.0).abs() < 1e-6, "w {w}: {mass}");
    }
    for cos_max in [0.95_f32, 0.5, -0.3] {
        let u = Vec2::new(0.7, 0.2);
        assert_eq!(
            uniform_cone(u, cos_max).to_array().map(f32::to_bits),
            uniform_cone_of_width(u, 1.0 - cos_max)
                .to_array()
                .map(f32::to_bits)
        );
        assert_eq!(
            uniform_cone_pdf(cos_max).to_bits(),
            uniform_cone_pdf_of_width(1.0 - cos_max).to_bits()
        );
    }
}

#[test]
fn uniform_cone_matches_its_pdf() {
    // A narrow cone needs finer rings: 160 rings of width 0.0125 put four across it.
    for (cos_max, theta_bins, seed) in [(0.95_f32, 160, 15), (0.5, 16, 16), (-0.3, 16, 17)] {
        let report = chi2_sphere(
            |u| Some(uniform_cone(u, cos_max)),
            |w| {
                if w.z >= cos_max {
                    f64::from(uniform_cone_pdf(cos_max))
                } else {
                    0.0
                }
            },
            &Chi2Config {
                theta_bins,
                ..config(seed)
            },
        );
        assert_passes(&format!("uniform cone, cos θmax = {cos_max}"), &report);
    }
}

#[test]
fn sampler_that_fails_half_the_time_matches_a_halved_pdf() {
    // The directions are cosine-distributed, but half the draws return None: the density
    // integrates to ½ and the no-sample bin expects N/2.
    let report = chi2_sphere(
        half_failing,
        |w| 0.5 * f64::from(cosine_hemisphere_pdf(w.z)),
        &config(18),
    );
    println!("half-failing sampler, halved pdf: {report}");
    assert!(report.passed(), "{report}");
    assert!((report.pdf_integral - 0.5).abs() < 1e-5);
    assert!((report.expected_rejected - 0.5 * SAMPLES as f64).abs() < 10.0);
    // Binomial(10⁶, ½): σ = 500.
    assert!(report.rejected_samples.abs_diff(SAMPLES / 2) < 2_500);
}

#[test]
fn cosine_sampling_is_rejected_against_the_uniform_hemisphere_pdf() {
    let report = warp_chi2(cosine_hemisphere, uniform_upper, 21);
    assert_rejected("cosine samples vs uniform hemisphere pdf", &report);
    assert!(report.p_value < report.significance);
    // No outright failure: it is the statistic that rejects.
    assert_eq!(report.zero_bin_hits + report.invalid_samples, 0);
}

#[test]
fn uniform_sphere_is_rejected_against_a_pdf_ten_percent_off_in_one_half() {
    // Still a density (it integrates to 1): 10 % too high for x > 0, 10 % too low else.
    let skewed = |w: Vec3| {
        let base = f64::from(uniform_sphere_pdf());
        if w.x > 0.0 { 1.1 * base } else { 0.9 * base }
    };
    let report = chi2_sphere(|u| Some(uniform_sphere(u)), skewed, &config(22));
    assert_rejected("uniform sphere vs pdf 10 % off in one half", &report);
    assert!(report.p_value < report.significance);
    assert_eq!(report.zero_bin_hits + report.invalid_samples, 0);
    assert!((report.pdf_integral - 1.0).abs() < 1e-5);
}

#[test]
fn samples_where_the_pdf_is_zero_are_rejected() {
    // One sample in a thousand is mirrored below the horizon, where the cosine density
    // is zero: about a thousand zero-bin hits, each an outright failure.
    let mut k = 0_u32;
    let leaky = |u: Vec2| {
        k += 1;
        let w = cosine_hemisphere(u);
        Some(if k.is_multiple_of(1000) {
            Vec3::new(w.x, w.y, -w.z)
        } else {
            w
        })
    };
    let report = chi2_sphere(
        leaky,
        |w| f64::from(cosine_hemisphere_pdf(w.z)),
        &config(23),
    );
    assert_rejected("cosine sampler leaking below the horizon", &report);
    // Mirrored samples with z exactly 0 stay on the horizon: allow a few.
    assert!(
        report.zero_bin_hits > 990 && report.zero_bin_hits <= 1000,
        "{report}"
    );
    assert!(matches!(
        report.worst.map(|w| w.bin),
        Some(Chi2Bin::Direction { theta, .. }) if theta < 8
    ));
}

#[test]
fn sampler_that_fails_half_the_time_is_rejected_against_its_full_pdf() {
    let report = chi2_sphere(
        half_failing,
        |w| f64::from(cosine_hemisphere_pdf(w.z)),
        &config(24),
    );
    assert_rejected("half-failing sampler vs full pdf", &report);
    assert!(report.rejected_samples.abs_diff(SAMPLES / 2) < 2_500);
    assert!(report.expected_rejected < 1.0);
    assert!(report.p_value < report.significance);
}
