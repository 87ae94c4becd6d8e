//! Energy compensation (issue 11): the white furnace of the compensated conductors, rough
//! dielectrics and plastic, the law suite on the compensated models, the baked tables
//! re-baked and their interpolation error measured against fresh integration, the Fresnel
//! averages, and fault checks showing the furnace test catches a broken table.
//!
//! `cargo test --test energy_compensation -- --nocapture` prints every figure, with the
//! uncompensated model's beside the compensated one's.

mod common;

use lobe::bxdf::{
    Bxdf, CompensatedMicrofacet, Compensation, Microfacet, Plastic, RoughDielectric, TransportMode,
};
use lobe::fresnel::{
    Conductor, Dielectric, FresnelAverage, NoFresnel, Schlick, cosine_weighted_average, dielectric,
};
use lobe::microfacet::{Beckmann, BeckmannMasking, Ggx, Masking};
use lobe::tables::bake::{self, Family};
use lobe::tables::{
    ALPHA_NODES, AlbedoRow, BECKMANN_E, BECKMANN_E_AVG, ConductorTable, DIELECTRIC_ALPHA_NODES,
    DIELECTRIC_MU_NODES, ETA_NODES, GGX_DIELECTRIC_INSIDE, GGX_DIELECTRIC_OUTSIDE,
    GGX_DIELECTRIC_REFLECTION, GGX_E, GGX_E_AVG, MU_NODES, TabulatedAlbedo, TabulatedDielectric,
    alpha_node, eta_node,
};
use lobe::verify::{
    Accumulator, BxdfCheck, Config, Estimate, Pcg32, albedo_sampled, check_bxdf, sidak,
};
use lobe::{Alpha, ComplexIor, Eta, Vec2, Vec3};

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

fn eta(x: f32) -> Eta {
    Eta::new(x).unwrap()
}

/// `E ± σ` as the tables print it.
fn show(e: &Estimate) -> String {
    format!("{:.4} ± {:.1e}", e.mean, e.std_err)
}

/// A white-furnace measurement: the directional albedo at one direction.
struct Furnace {
    label: String,
    /// The compensated model's albedo: the single-scattering lobe by its own sampler plus
    /// the rest by quadrature ([`split_albedo`]), or the whole by the model's sampler.
    compensated: Estimate,
    /// The compensated model's albedo by its own (mixture) sampler, when measured too.
    sampled: Option<Estimate>,
    /// The single-scattering model's albedo.
    single: f64,
}

/// `∫ (f(wo, wi) − f_ss(wo, wi)) |cos θi| dωi`, the part of the compensated model that is
/// not the single-scattering lobe (the compensation lobes, a plastic's diffuse base): smooth
/// in `wi`, integrated by product Gauss–Legendre in `(√|μi|, φi)` — 64 panels of 4 points in
/// `√μ`, aligned with the tables' nodes, times 16 azimuths — over the upper hemisphere, and
/// the lower one too when `both` is set.
fn remainder(
    model: &dyn Bxdf<Spectrum = f32>,
    single: &dyn Bxdf<Spectrum = f32>,
    wo: Vec3,
    both: bool,
) -> f64 {
    const GL4: [(f64, f64); 4] = [
        (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
        (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    ];
    let (panels, azimuths) = (64, 16);
    let mut sum = 0.0;
    for side in if both {
        &[1.0f64, -1.0][..]
    } else {
        &[1.0][..]
    } {
        for p in 0..panels {
            for (t, w) in GL4 {
                let x = (p as f64 + 0.5 + 0.5 * t) / panels as f64;
                let mu = x * x;
                let sin = (1.0 - mu * mu).max(0.0).sqrt();
                for k in 0..azimuths {
                    let phi = std::f64::consts::TAU * (k as f64 + 0.5) / azimuths as f64;
                    let wi = Vec3::new(
                        (sin * phi.cos()) as f32,
                        (sin * phi.sin()) as f32,
                        (side * mu) as f32,
                    );
                    let f = f64::from(model.eval(wo, wi)) - f64::from(single.eval(wo, wi));
                    // dω = dμ dφ = 2x dx dφ; the cosine μ = x².
                    sum += f
                        * mu
                        * 2.0
                        * x
                        * (0.5 * w / panels as f64)
                        * (std::f64::consts::TAU / azimuths as f64);
                }
            }
        }
    }
    sum
}

/// The directional albedo by `model`'s own sampler with jittered-stratified `u` (32 × 32
/// strata) and an independent `uc`, 64 independent times: the mean of the 64 replicate
/// means, with the standard error of their spread (randomised quasi-Monte Carlo: unbiased,
/// and far less noisy than independent samples for the smooth single-scattering weights).
fn stratified_albedo(model: &dyn Bxdf<Spectrum = f32>, wo: Vec3, seed: u64) -> Estimate {
    const SIDE: usize = 32;
    const REPLICATES: usize = 64;
    let below_one = |x: f32| x.min(1.0 - f32::EPSILON / 2.0);
    let mut rng = Pcg32::new(seed, 41);
    let mut acc = Accumulator::new();
    for _ in 0..REPLICATES {
        let mut sum = 0.0;
        for i in 0..SIDE {
            for j in 0..SIDE {
                let u = Vec2::new(
                    below_one((i as f32 + rng.next_f32()) / SIDE as f32),
                    below_one((j as f32 + rng.next_f32()) / SIDE as f32),
                );
                let uc = rng.next_f32();
                sum += model
                    .sample(wo, u, uc)
                    .map_or(0.0, |s| f64::from(s.weight()));
            }
        }
        acc.push(sum / (SIDE * SIDE) as f64);
    }
    acc.finish()
}

/// The compensated model's albedo as the single-scattering lobe's, by its own sampler
/// ([`stratified_albedo`], which carries the standard error), plus the [`remainder`] by
/// quadrature; and the single-scattering albedo alone.
fn split_albedo(
    model: &dyn Bxdf<Spectrum = f32>,
    single: &dyn Bxdf<Spectrum = f32>,
    wo: Vec3,
) -> (Estimate, f64) {
    let ss = stratified_albedo(single, wo, 7);
    let rest = remainder(model, single, wo, model.lobes().is_transmissive());
    (
        Estimate {
            mean: ss.mean + rest,
            ..ss
        },
        ss.mean,
    )
}

/// The furnace points of one model, one per polar angle of `wo` in `thetas`, labelled `label`
/// and the angle: the compensated model's albedo ([`split_albedo`]: the single-scattering
/// lobe by its stratified sampler, the compensation by quadrature; and by the whole model's
/// own sampler with `sampled = (samples, seed)` when `samples > 0`) beside the
/// single-scattering model's.
fn furnace_points(
    rows: &mut Vec<Furnace>,
    label: &str,
    (compensated, single): (&dyn Bxdf<Spectrum = f32>, &dyn Bxdf<Spectrum = f32>),
    thetas: &[f32],
    (samples, seed): (usize, u64),
) {
    for &theta in thetas {
        let wo = common::dir(theta, 0.7);
        let (e, ss) = split_albedo(compensated, single, wo);
        rows.push(Furnace {
            label: format!("{label} θo = {theta:>3}°"),
            compensated: e,
            sampled: (samples > 0)
                .then(|| albedo_sampled(compensated, wo, &BxdfCheck { samples, seed })),
            single: ss,
        });
    }
}

/// Asserts that every measurement lies inside `1 ± bar` with its `k`-sigma interval, and
/// that the model's own sampler agrees with the split measurement where both were taken,
/// printing them all; returns how many lie outside (for the fault checks) without asserting
/// when `assert` is false.
fn judge(title: &str, rows: &[Furnace], bar: f64, assert: bool) -> usize {
    let k = common::k_sigma(0.01, rows.len());
    eprintln!(
        "\n{title}: bar 1 ± {bar}, k = {k:.2} over {} points",
        rows.len()
    );
    eprintln!("  where | compensated | by its own sampler | single scattering");
    let mut outside = 0;
    let mut worst = (0.0_f64, String::new());
    let mut worst_gap = 0.0_f64;
    for r in rows {
        let e = &r.compensated;
        let reach = (e.mean - 1.0).abs() + k * e.std_err;
        if reach > worst.0 {
            worst = (reach, r.label.clone());
        }
        let ok = reach <= bar;
        outside += usize::from(!ok);
        let sampled = r.sampled.map_or(String::from("—"), |s| {
            let sigma = (s.std_err.powi(2) + e.std_err.powi(2)).sqrt();
            let gap = (s.mean - e.mean).abs() / sigma;
            // Beyond the round-off of f32 weights (a few ulps) where both are all but exact.
            worst_gap = worst_gap.max(((s.mean - e.mean).abs() - 1e-6).max(0.0) / sigma);
            if assert {
                assert!(
                    gap <= k || (s.mean - e.mean).abs() <= 1e-6,
                    "{title}, {}: sampled {s} vs {e}",
                    r.label
                );
            }
            show(&s)
        });
        eprintln!(
            "  {} | {} | {sampled} | {:.4}{}",
            r.label,
            show(e),
            r.single,
            if ok { "" } else { "   ✗" }
        );
    }
    eprintln!(
        "  largest |E − 1| + kσ = {:.2e} at {}; {outside} outside; own sampler within {worst_gap:.2}σ",
        worst.0, worst.1
    );
    if assert {
        assert_eq!(outside, 0, "{title}: {outside} points outside 1 ± {bar}");
    }
    outside
}

const CONDUCTOR_ALPHAS: [f32; 7] = [0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0];
const CONDUCTOR_THETAS: [f32; 7] = [0.0, 20.0, 40.0, 60.0, 70.0, 80.0, 85.0];

/// The furnace of `F = 1` conductors on `dist` over `alphas` × `thetas`, compensated.
fn conductor_furnace<D: TabulatedAlbedo + Copy>(
    dist: impl Fn(Alpha) -> D,
    alphas: &[f32],
    thetas: &[f32],
    sampled: usize,
) -> Vec<Furnace> {
    let mut rows = Vec::new();
    for &alpha in alphas {
        let single = Microfacet::new(
            dist(a(alpha)),
            Masking::HeightCorrelated,
            NoFresnel::<f32>::new(),
        );
        let compensated = single.with_energy_compensation().unwrap();
        let label = format!("α = {alpha:<4}");
        furnace_points(
            &mut rows,
            &label,
            (&compensated, &single),
            thetas,
            (sampled, 29),
        );
    }
    rows
}

/// Bar: compensated GGX and Beckmann conductors with `F = 1` have directional albedo
/// `1 ± 0.005` for `α ∈ [0.05, 1]` and `θo ∈ [0°, 85°]`.
#[test]
fn conductors_pass_the_white_furnace() {
    let ggx = conductor_furnace(Ggx::isotropic, &CONDUCTOR_ALPHAS, &CONDUCTOR_THETAS, 50_000);
    judge("GGX conductor, F = 1", &ggx, 0.005, true);
    let beckmann = conductor_furnace(
        Beckmann::isotropic,
        &CONDUCTOR_ALPHAS,
        &CONDUCTOR_THETAS,
        20_000,
    );
    judge("Beckmann conductor, F = 1", &beckmann, 0.005, true);
}

/// Turquin's scaling conserves the `F = 1` energy too (its weakness is reciprocity):
/// measured whole with its own sampler (the single-scattering one, its weights scaled).
#[test]
fn turquin_scaling_passes_the_white_furnace() {
    let mut rows = Vec::new();
    for alpha in [0.05f32, 0.3, 1.0] {
        let single = Microfacet::new(
            Ggx::isotropic(a(alpha)),
            Masking::HeightCorrelated,
            NoFresnel::<f32>::new(),
        );
        let t = CompensatedMicrofacet::new(single, Compensation::Turquin).unwrap();
        for theta in [0.0f32, 45.0, 85.0] {
            rows.push(Furnace {
                label: format!("α = {alpha:<4} θo = {theta:>2}°"),
                compensated: stratified_albedo(&t, common::dir(theta, 0.7), 31),
                sampled: None,
                single: stratified_albedo(&single, common::dir(theta, 0.7), 31).mean,
            });
        }
    }
    judge(
        "GGX conductor, F = 1, Turquin's scaling",
        &rows,
        0.005,
        true,
    );
}

/// Beckmann with Walter's rational `G1` reads the exact-`Λ` tables, within the bar. An
/// anisotropic distribution is compensated at its RMS width: the furnace measures what that
/// costs, a documented limitation (an isotropic table cannot follow the azimuth).
#[test]
fn rational_masking_and_anisotropy_are_measured() {
    let mut rows = Vec::new();
    for alpha in [0.1f32, 0.5, 1.0] {
        let single = Microfacet::new(
            Beckmann::isotropic(a(alpha)).with_masking(BeckmannMasking::WalterRational),
            Masking::HeightCorrelated,
            NoFresnel::<f32>::new(),
        );
        let c = single.with_energy_compensation().unwrap();
        for theta in [0.0f32, 60.0, 85.0] {
            let (e, ss) = split_albedo(&c, &single, common::dir(theta, 0.7));
            rows.push(Furnace {
                label: format!("α = {alpha:<4} θo = {theta:>2}°"),
                compensated: e,
                sampled: None,
                single: ss,
            });
        }
    }
    // The figure `CompensatedMicrofacet`'s docs quote (measured 3.22e-3, |E − 1| + kσ at
    // α = 0.5, 85°; the bar leaves it two standard errors, 2 × 1.6e-4, of the worst point).
    // The tables hold the exact Λ's albedo, and the rational G1 is within 3.2e-3 of the
    // exact one either way, so the compensated model reflects from 0.21% less to 0.27% more
    // than it receives. (Before the model's density kept the exact G1, the single-scattering
    // estimate by its own sampler was biased by G1_exact/G1_rational at wo and showed 1.7e-3.)
    judge(
        "Beckmann with Walter's rational G1, F = 1",
        &rows,
        0.0036,
        true,
    );

    let mut rows = Vec::new();
    // (αx, αy) and the range of the furnace documented in `CompensatedMicrofacet`.
    for ((ax, ay), (lo, hi)) in [
        ((0.2f32, 0.3f32), (0.975, 1.017)),
        ((0.1, 0.4), (0.90, 1.036)),
        ((0.05, 0.8), (0.744, 1.057)),
    ] {
        let single = Microfacet::new(
            Ggx::new(a(ax), a(ay)),
            Masking::HeightCorrelated,
            NoFresnel::<f32>::new(),
        );
        let c = single.with_energy_compensation().unwrap();
        let (mut least, mut most) = (f64::INFINITY, f64::NEG_INFINITY);
        for theta in [0.0f32, 60.0, 85.0] {
            for phi in [0.0f32, 0.8, 1.6] {
                let (s, co) = theta.to_radians().sin_cos();
                let wo = Vec3::new(s * phi.cos(), s * phi.sin(), co);
                let (e, ss) = split_albedo(&c, &single, wo);
                least = least.min(e.mean - 3.0 * e.std_err);
                most = most.max(e.mean + 3.0 * e.std_err);
                rows.push(Furnace {
                    label: format!("α = ({ax}, {ay}) θo = {theta:>2}° φo = {phi}"),
                    compensated: e,
                    sampled: None,
                    single: ss,
                });
            }
        }
        eprintln!(
            "α = ({ax}, {ay}): furnace from {least:.4} to {most:.4} (documented {lo} to {hi})"
        );
        assert!(
            least >= lo && most <= hi,
            "α = ({ax}, {ay}): {least}..{most} outside the documented {lo}..{hi}"
        );
    }
    judge(
        "anisotropic GGX at its RMS width, F = 1 (not held to the bar)",
        &rows,
        0.005,
        false,
    );
}

/// The width an anisotropic distribution is read at (`TabulatedAlbedo`'s docs): at normal
/// incidence the table at the RMS width `√((αx² + αy²)/2)` is closer to the anisotropic
/// model's own albedo than the table at the geometric mean `√(αx αy)` or at the arithmetic
/// mean `(αx + αy)/2`, by a wide margin.
#[test]
fn the_rms_width_matches_the_anisotropic_albedo_best() {
    for (ax, ay) in [(0.1f32, 0.4f32), (0.05, 0.8)] {
        let single = Microfacet::new(
            Ggx::new(a(ax), a(ay)),
            Masking::HeightCorrelated,
            NoFresnel::<f32>::new(),
        );
        let own = stratified_albedo(&single, Vec3::Z, 11);
        let at = |alpha: f32| {
            let row = Ggx::isotropic(a(alpha)).conductor_albedo().unwrap();
            f64::from(row.e(1.0))
        };
        let rms = at(((ax * ax + ay * ay) / 2.0).sqrt());
        let (geometric, arithmetic) = (at((ax * ay).sqrt()), at(0.5 * (ax + ay)));
        eprintln!(
            "α = ({ax}, {ay}), normal incidence: albedo {own}; table at the RMS width {rms:.4}, \
             at the geometric mean {geometric:.4}, at the arithmetic mean {arithmetic:.4}"
        );
        let k = common::k_sigma(0.01, 4);
        for other in [geometric, arithmetic] {
            assert!(
                (rms - own.mean).abs() + k * own.std_err < (other - own.mean).abs(),
                "α = ({ax}, {ay}): {own}, RMS {rms}, another mean {other}"
            );
        }
    }
}

const DIELECTRIC_ETAS: [f32; 4] = [1.1, 1.33, 1.5, 2.0];
const DIELECTRIC_ALPHAS: [f32; 4] = [0.05, 0.2, 0.5, 1.0];
/// Outside (0°–85°) and inside (95°–180°).
const DIELECTRIC_THETAS: [f32; 8] = [0.0, 40.0, 70.0, 85.0, 180.0, 140.0, 110.0, 95.0];

/// The importance-mode furnace of compensated rough dielectrics.
fn dielectric_furnace<D: TabulatedDielectric + Copy>(
    dist: impl Fn(Alpha) -> D,
    etas: &[f32],
    alphas: &[f32],
    sampled: usize,
) -> Vec<Furnace> {
    let mut rows = Vec::new();
    for &n in etas {
        for &alpha in alphas {
            let single =
                RoughDielectric::new(dist(a(alpha)), eta(n)).with_mode(TransportMode::Importance);
            let c = single.with_energy_compensation().unwrap();
            let label = format!("η = {n:<4} α = {alpha:<4}");
            let thetas = &DIELECTRIC_THETAS;
            furnace_points(&mut rows, &label, (&c, &single), thetas, (sampled, 37));
        }
    }
    rows
}

/// Bar: the compensated rough dielectric's reflection + transmission albedo is `1 ± 0.01`
/// from both sides for `η ∈ {1.1, 1.33, 1.5, 2}`, `α ∈ [0.05, 1]`, importance mode.
#[test]
fn dielectrics_pass_the_white_furnace_from_both_sides() {
    let ggx = dielectric_furnace(Ggx::isotropic, &DIELECTRIC_ETAS, &DIELECTRIC_ALPHAS, 20_000);
    judge("GGX rough dielectric, importance", &ggx, 0.01, true);
}

/// The radiance-mode interface is the importance-mode one with the transmission scaled by
/// `1/η'²`, pair by pair (so its albedo is `R + T/η'²`), and `η < 1` is the same interface
/// seen from the other side.
#[test]
fn radiance_mode_and_inverse_index_relations_hold() {
    let mut rng = Pcg32::new(5, 0);
    let (mut worst, mut worst_flip) = (0.0_f64, 0.0_f64);
    for (n, alpha) in [(1.5f32, 0.4f32), (1.1, 1.0), (2.0, 0.1)] {
        let d = Ggx::isotropic(a(alpha));
        let imp = RoughDielectric::new(d, eta(n))
            .with_mode(TransportMode::Importance)
            .with_energy_compensation()
            .unwrap();
        let rad = RoughDielectric::new(d, eta(n))
            .with_energy_compensation()
            .unwrap();
        // The same interface described from the other side: η → 1/η, z → −z.
        let flipped = RoughDielectric::new(d, eta(1.0 / n))
            .with_mode(TransportMode::Importance)
            .with_energy_compensation()
            .unwrap();
        for _ in 0..20_000 {
            let wo = lobe::sampling::uniform_sphere(rng.next_vec2());
            let wi = lobe::sampling::uniform_sphere(rng.next_vec2());
            let (fi, fr) = (f64::from(imp.eval(wo, wi)), f64::from(rad.eval(wo, wi)));
            let crossing = wo.z * wi.z < 0.0;
            let etap = f64::from(if wo.z > 0.0 { n } else { 1.0 / n });
            let want = if crossing { fi / (etap * etap) } else { fi };
            let scale = fr.abs().max(want.abs());
            if scale > 1e-30 {
                worst = worst.max((fr - want).abs() / scale);
            }
            let mirror = |w: Vec3| Vec3::new(w.x, w.y, -w.z);
            let ff = f64::from(flipped.eval(mirror(wo), mirror(wi)));
            let scale = fi.abs().max(ff.abs());
            if scale > 1e-30 {
                worst_flip = worst_flip.max((fi - ff).abs() / scale);
            }
        }
    }
    eprintln!("radiance = importance / η'² across, largest relative error {worst:.1e}");
    eprintln!("η and 1/η seen from the other side, largest relative difference {worst_flip:.1e}");
    assert!(worst < 1e-6, "{worst}");
    // f32 rounding of 1/η in the single-scattering lobe and of the tables' weights: measured
    // 4.8e-6.
    assert!(worst_flip < 1e-5, "{worst_flip}");
}

/// Bar: the plastic with the compensated coat and `ρ = 1` passes the white furnace.
#[test]
fn compensated_plastic_passes_the_white_furnace() {
    let mut rows = Vec::new();
    for n in [1.5f32, 1.33, 2.0] {
        for alpha in [0.05f32, 0.3, 1.0] {
            for theta in [0.0f32, 45.0, 70.0, 85.0] {
                let wo = common::dir(theta, 0.7);
                let d = Ggx::isotropic(a(alpha));
                let c = Plastic::compensated(1.0f32, d, eta(n)).unwrap();
                let s = Plastic::new(1.0f32, d, eta(n)).unwrap();
                let coat =
                    Microfacet::new(d, Masking::HeightCorrelated, Dielectric { eta: eta(n) });
                let (e, old) = (split_albedo(&c, &coat, wo).0, split_albedo(&s, &coat, wo).0);
                rows.push(Furnace {
                    label: format!("GGX η = {n:<4} α = {alpha:<4} θo = {theta:>2}°"),
                    compensated: e,
                    sampled: None,
                    single: old.mean,
                });
            }
        }
    }
    judge(
        "plastic ρ = 1, compensated coat (the uncompensated plastic beside)",
        &rows,
        0.005,
        true,
    );
}

/// Reciprocity, positivity, the energy bound with two estimators, chi-square and consistency
/// through `check_bxdf`, for every compensated model; Turquin's scaling fails reciprocity
/// (a documented property) and passes the rest.
#[test]
fn compensated_models_obey_the_laws() {
    let gold_red = Conductor {
        ior: ComplexIor::new(0.143f32, 3.983).unwrap(),
    };
    let n_models = 10;
    let config = |eta: f32| Config {
        albedo_samples: 40_000,
        chi2_samples: 100_000,
        pairs: 4_000,
        consistency_samples: 4_000,
        significance: sidak(0.01, n_models),
        eta,
        ..Config::default()
    };
    let hc = Masking::HeightCorrelated;
    let models: Vec<(&str, Box<dyn Bxdf<Spectrum = f32>>, f32)> = vec![
        (
            "GGX F=1 α=1",
            Box::new(
                Microfacet::new(Ggx::isotropic(a(1.0)), hc, NoFresnel::new())
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.0,
        ),
        (
            "GGX gold (red) α=0.3",
            Box::new(
                Microfacet::new(Ggx::isotropic(a(0.3)), hc, gold_red)
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.0,
        ),
        (
            "GGX Schlick α=(0.1, 0.6)",
            Box::new(
                Microfacet::new(Ggx::new(a(0.1), a(0.6)), hc, Schlick::new(0.7f32).unwrap())
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.0,
        ),
        (
            "Beckmann F=1 α=0.5",
            Box::new(
                Microfacet::new(Beckmann::isotropic(a(0.5)), hc, NoFresnel::new())
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.0,
        ),
        (
            "rough glass GGX α=0.5 η=1.5 (importance)",
            Box::new(
                RoughDielectric::new(Ggx::isotropic(a(0.5)), eta(1.5))
                    .with_mode(TransportMode::Importance)
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.0 / 1.5,
        ),
        (
            "rough glass GGX α=0.8 η=1.33 (radiance)",
            Box::new(
                RoughDielectric::new(Ggx::isotropic(a(0.8)), eta(1.33))
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.33,
        ),
        (
            "rough bubble GGX α=0.3 η=1/1.5 (importance)",
            Box::new(
                RoughDielectric::new(Ggx::isotropic(a(0.3)), eta(1.0 / 1.5))
                    .with_mode(TransportMode::Importance)
                    .with_energy_compensation()
                    .unwrap(),
            ),
            1.5,
        ),
        (
            "plastic GGX α=0.3 ρ=1 (compensated coat)",
            Box::new(Plastic::compensated(1.0f32, Ggx::isotropic(a(0.3)), eta(1.5)).unwrap()),
            1.0,
        ),
        (
            "plastic GGX α=0.7 ρ=0.5 η=1.33 (compensated coat)",
            Box::new(Plastic::compensated(0.5f32, Ggx::isotropic(a(0.7)), eta(1.33)).unwrap()),
            1.0,
        ),
    ];
    assert_eq!(models.len() + 1, n_models);
    for (name, model, e) in &models {
        // In radiance transport refraction scales radiance by η'², so the albedo from the
        // denser side is bounded by η² (by 1 in importance transport, and for a BRDF).
        let bound = if name.contains("(radiance)") {
            f64::from(e * e)
        } else {
            1.0
        };
        let config = Config {
            albedo_bound: bound,
            ..config(*e)
        };
        let report = check_bxdf(name, model.as_ref(), &config);
        eprint!("{report}");
        assert!(report.passed(), "{report}");
    }
    let turquin = CompensatedMicrofacet::new(
        Microfacet::new(Ggx::isotropic(a(0.7)), hc, gold_red),
        Compensation::Turquin,
    )
    .unwrap();
    let report = check_bxdf("GGX gold α=0.7, Turquin's scaling", &turquin, &config(1.0));
    eprint!("{report}");
    let failed: Vec<_> = report.failures().map(|l| l.law).collect();
    assert_eq!(
        failed,
        vec![lobe::verify::Law::Reciprocity],
        "Turquin's scaling is documented as failing reciprocity only: {report}"
    );
}

/// A re-baked table entry against the committed one.
///
/// The tables were baked with the standard library's float functions: on that path a
/// re-baked entry is the committed `f32`, bit for bit. On the `libm` path (the `no_std` float
/// functions, `--cfg lobe_force_libm`) the functions differ from the standard library's by up
/// to a unit or so in the last place, each integrand value by a few, and so does an average of
/// them: there the entry must be within `4 ε` relative of the committed one (4 to 8 units in
/// the last place; measured: one). A cell that the adaptive integrator refined on one path and
/// accepted on the other would move an entry by more, and fail here: that is a change to look
/// at, not noise (the picks are seeded). Returns the difference in units of `ε` relative.
fn same_entry(fresh: f32, committed: f32, what: &str) -> f64 {
    let diff = (f64::from(fresh) - f64::from(committed)).abs();
    // 0/0 for two zeros: no difference.
    let relative = if diff == 0.0 {
        0.0
    } else {
        diff / (f64::from(f32::EPSILON) * f64::from(committed.abs()))
    };
    if cfg!(lobe_force_libm) {
        assert!(
            relative <= 4.0,
            "{what}: re-baked {fresh}, committed {committed}, {relative:.2} ε relative apart"
        );
    } else {
        assert_eq!(
            fresh.to_bits(),
            committed.to_bits(),
            "{what}: re-baked {fresh}, committed {committed}"
        );
    }
    relative
}

/// The generator reproduces the committed tables: a sample of entries re-baked with the
/// same integrator are the committed `f32`s, bit for bit (within `4 ε` relative on the
/// `libm` path: [`same_entry`]), and the baked averages are those of the committed rows.
#[test]
fn generator_reproduces_the_committed_tables() {
    let mut rng = Pcg32::new(17, 3);
    let mut pick = |n: usize| (rng.next_u32() as usize) % n;
    let mut checked = 0;
    let mut largest = 0.0_f64;
    for (family, table, avg) in [
        (Family::Ggx, &GGX_E, &GGX_E_AVG),
        (Family::Beckmann, &BECKMANN_E, &BECKMANN_E_AVG),
    ] {
        for _ in 0..5 {
            let (i, j) = (pick(MU_NODES), 1 + pick(ALPHA_NODES - 1));
            let fresh = bake::conductor_entry(family, i, j);
            let what = format!("{family:?} E[{j}][{i}]");
            let diff = same_entry(fresh, table[j][i], &what);
            largest = largest.max(diff);
            checked += 1;
        }
        for (j, row) in table.iter().enumerate() {
            let average = AlbedoRow::from_nodes(*row).unwrap().average();
            assert_eq!(average.to_bits(), avg[j].to_bits(), "{family:?} E_avg[{j}]");
        }
    }
    for (family, tables) in [(
        Family::Ggx,
        [
            &GGX_DIELECTRIC_OUTSIDE,
            &GGX_DIELECTRIC_REFLECTION,
            &GGX_DIELECTRIC_INSIDE,
        ],
    )] {
        for _ in 0..5 {
            let (i, j, k) = (
                pick(DIELECTRIC_MU_NODES),
                1 + pick(DIELECTRIC_ALPHA_NODES - 1),
                pick(ETA_NODES),
            );
            let fresh = bake::dielectric_entry(family, i, j, k);
            for (t, v) in tables.iter().zip(fresh) {
                let what = format!("{family:?} [{k}][{j}][{i}]");
                let diff = same_entry(v, t[k][j][i], &what);
                largest = largest.max(diff);
            }
            checked += 1;
        }
    }
    if cfg!(lobe_force_libm) {
        eprintln!(
            "{checked} re-baked entries, at most {largest:.2} ε relative from the committed ones (libm)"
        );
    } else {
        eprintln!("{checked} re-baked entries identical to the committed ones, bit for bit");
    }
}

/// The tables' interpolation error, against fresh integration (the bake's own integrator)
/// halfway between the nodes in every coordinate — where linear interpolation errs most —
/// and the integrator's own error, against a ten times tighter tolerance and against Monte
/// Carlo.
#[test]
fn interpolation_and_quadrature_errors_are_measured() {
    // Conductors: midpoints in √μ and √α, in the bar's region (α ≥ 0.05, θo ≤ 85°) and out
    // of it.
    let mut worst_bar = (0.0_f32, String::new());
    let mut worst_all = (0.0_f32, String::new());
    for family in [Family::Ggx, Family::Beckmann] {
        for (x, r) in [
            (0.17f32, 0.23f32),
            (0.31, 0.27),
            (0.51, 0.41),
            (0.74, 0.6),
            (0.93, 0.82),
            (0.99, 0.99),
            (0.05, 0.1),
            (0.3, 0.15),
        ] {
            // Halfway between nodes.
            let x = ((x * 64.0).floor() + 0.5) / 64.0;
            let r = ((r * 64.0).floor() + 0.5) / 64.0;
            let (mu, alpha) = (x * x, r * r);
            let wo = bake::direction(mu);
            let (fresh, row) = match family {
                Family::Ggx => {
                    let d = Ggx::isotropic(a(alpha));
                    let m = Microfacet::new(d, Masking::HeightCorrelated, NoFresnel::<f32>::new());
                    (
                        bake::albedo(&m, &d, None, wo, 1e-6)[0],
                        d.conductor_albedo().unwrap(),
                    )
                }
                Family::Beckmann => {
                    let d = Beckmann::isotropic(a(alpha));
                    let m = Microfacet::new(d, Masking::HeightCorrelated, NoFresnel::<f32>::new());
                    (
                        bake::albedo(&m, &d, None, wo, 1e-6)[0],
                        d.conductor_albedo().unwrap(),
                    )
                }
            };
            let err = (row.e(mu) - fresh as f32).abs();
            let label = format!(
                "{family:?} μ = {mu:.4}, α = {alpha:.4}: table {:.5}, fresh {fresh:.5}",
                row.e(mu)
            );
            if err > worst_all.0 {
                worst_all = (err, label.clone());
            }
            if alpha >= 0.05 && mu >= 0.087 && err > worst_bar.0 {
                worst_bar = (err, label);
            }
        }
    }
    eprintln!(
        "conductor tables, largest interpolation error in the bar's region: {:.1e} ({})",
        worst_bar.0, worst_bar.1
    );
    eprintln!(
        "conductor tables, largest anywhere sampled: {:.1e} ({})",
        worst_all.0, worst_all.1
    );
    // The README's figure (4.5e-4), rounded up.
    assert!(worst_bar.0 < 5e-4, "{worst_bar:?}");

    // Dielectric: midpoints in √μ, √α and √(η − 1), both sides.
    let mut worst = (0.0_f32, String::new());
    for (x, r, k) in [
        (0.3f32, 0.3f32, 2usize),
        (0.6, 0.5, 5),
        (0.85, 0.8, 8),
        (0.45, 0.95, 12),
        (0.95, 0.2, 3),
        (0.35, 0.6, 0),
        (0.7, 0.25, 6),
        (0.5, 0.7, 9),
        (0.99, 0.99, 14),
        (0.2, 0.4, 10),
    ] {
        let x = ((x * 32.0).floor() + 0.5) / 32.0;
        let r = ((r * 32.0).floor() + 0.5) / 32.0;
        let c = 0.5 * ((eta_node(k) - 1.0).sqrt() + (eta_node(k + 1) - 1.0).sqrt());
        let (mu, alpha, n) = (x * x, r * r, 1.0 + c * c);
        let d = Ggx::isotropic(a(alpha));
        let m = RoughDielectric::new(d, eta(n)).with_mode(TransportMode::Importance);
        let rows = d.dielectric_albedo(eta(n)).unwrap();
        for (side, row) in [(1.0f32, &rows.outside), (-1.0, &rows.inside)] {
            let fresh: f64 = bake::albedo(&m, &d, Some(eta(n)), bake::direction(side * mu), 1e-5)
                .iter()
                .sum();
            let err = (row.e(mu) - fresh as f32).abs();
            if err > worst.0 {
                worst = (
                    err,
                    format!(
                        "μ = {:.4}, α = {alpha:.4}, η = {n:.4}: table {:.5}, fresh {fresh:.5}",
                        side * mu,
                        row.e(mu)
                    ),
                );
            }
        }
    }
    eprintln!(
        "dielectric tables, largest interpolation error: {:.1e} ({})",
        worst.0, worst.1
    );
    // The README's figure (3.3e-3), rounded up.
    assert!(worst.0 < 3.5e-3, "{worst:?}");

    // The integrator: tolerance 1e-6 against 1e-7, and against 2M Monte Carlo samples.
    let k = common::k_sigma(0.01, 4);
    for (alpha, mu) in [(0.05f32, 0.1f32), (0.3, 0.5), (1.0, 0.9), (0.6, 0.02)] {
        let d = Ggx::isotropic(a(alpha));
        let m = Microfacet::new(d, Masking::HeightCorrelated, NoFresnel::<f32>::new());
        let wo = bake::direction(mu);
        let (q6, q7) = (
            bake::albedo(&m, &d, None, wo, 1e-6)[0],
            bake::albedo(&m, &d, None, wo, 1e-7)[0],
        );
        let mc = albedo_sampled(
            &m,
            wo,
            &BxdfCheck {
                samples: 2_000_000,
                seed: 19,
            },
        );
        eprintln!(
            "quadrature α = {alpha}, μ = {mu}: {q6:.7} (tol 1e-6), {q7:.7} (1e-7), apart {:.1e}, \
             Monte Carlo {}",
            (q6 - q7).abs(),
            show(&mc)
        );
        // The README's figure: the two tolerances agree to 1e-7.
        assert!(
            (q6 - q7).abs() < 1e-7,
            "tolerance 1e-6 gives {q6}, 1e-7 gives {q7}"
        );
        assert!(mc.within(q6, k), "{mc} vs {q6}");
    }
}

/// `F_avg`: Schlick's closed form equals the quadrature; the conductor's and dielectric's
/// quadratures agree with a 2¹⁶-interval midpoint rule in `f64`; the dielectric's `η < 1` average
/// through the smooth interface's reciprocity equals direct integration across the critical angle.
#[test]
fn fresnel_averages_are_exact() {
    let fine = |f: &dyn Fn(f64) -> f64| {
        // Midpoint rule on 2¹⁶ intervals, in f64.
        let n = 1 << 16;
        (0..n)
            .map(|i| {
                let mu = (i as f64 + 0.5) / n as f64;
                2.0 * f(mu) * mu
            })
            .sum::<f64>()
            / n as f64
    };
    let mut worst = [0.0_f64; 3];
    for f0 in [0.04f32, 0.5, 0.95] {
        let s = Schlick::new(f0).unwrap();
        let want = fine(&|mu| f64::from(lobe::fresnel::schlick(f0, mu as f32)));
        worst[0] = worst[0].max((f64::from(s.average()) - want).abs());
        let quad = cosine_weighted_average(|mu| lobe::fresnel::schlick(f0, mu));
        worst[0] = worst[0].max((f64::from(quad) - want).abs());
    }
    // With η < 1 and small κ the term bends sharply at μc = √(1 − η²) (a kink at κ = 0).
    for (n, k) in [
        (0.143f32, 3.983f32),
        (1.5, 0.0),
        (0.2, 1.0),
        (1.0, 0.0),
        (0.3, 0.0),
        (0.3, 1e-3),
        (0.7, 0.0),
        (0.5, 0.01),
        (0.2, 0.01),
    ] {
        let c = Conductor {
            ior: ComplexIor::new(n, k).unwrap(),
        };
        let want = fine(&|mu| f64::from(lobe::fresnel::conductor(mu as f32, &c.ior)));
        worst[1] = worst[1].max((f64::from(c.average()) - want).abs());
    }
    let dielectric_error = |n: f32| {
        let d = Dielectric { eta: eta(n) };
        let want = fine(&|mu| f64::from(dielectric(mu as f32, eta(n))));
        eprintln!("F_avg(η = {n:.5}) = {:.7} (direct {want:.7})", d.average());
        (f64::from(d.average()) - want).abs()
    };
    for n in [
        1.001f32,
        1.1,
        1.5,
        2.4,
        1.0 / 1.001,
        1.0 / 1.33,
        1.0 / 1.5,
        1.0 / 2.4,
    ] {
        worst[2] = worst[2].max(dielectric_error(n));
    }
    // Closer to 1 than the documented range: the rise at grazing incidence is narrower than a
    // panel, and the bound the docs give there is 1e-6.
    let near_one = dielectric_error(1.0001).max(dielectric_error(1.0 / 1.0001));
    eprintln!(
        "F_avg against a 2¹⁶-interval midpoint rule in f64: Schlick {:.1e}, conductor {:.1e}, \
         dielectric {:.1e}; dielectric at η = 1.0001 and its inverse {near_one:.1e}",
        worst[0], worst[1], worst[2]
    );
    // The documented bound (`fresnel::cosine_weighted_average`), above the f32 round-off of
    // 64 weighted terms that these figures are.
    assert!(worst.iter().all(|&w| w < 2.5e-7), "{worst:?}");
    assert!(near_one < 1e-6, "{near_one:.2e}");
}

/// A furnace run over a small grid for a fault check: how many points fall outside the bar.
fn faulty_furnace(row: AlbedoRow, alpha: f32) -> usize {
    let single = Microfacet::new(
        Ggx::isotropic(a(alpha)),
        Masking::HeightCorrelated,
        NoFresnel::<f32>::new(),
    );
    let c = CompensatedMicrofacet::with_albedo(single, row, Compensation::KullaConty);
    let rows: Vec<Furnace> = [0.0f32, 45.0, 70.0, 85.0]
        .iter()
        .map(|&theta| {
            let (e, ss) = split_albedo(&c, &single, common::dir(theta, 0.7));
            Furnace {
                label: format!("α = {alpha} θo = {theta}°"),
                compensated: e,
                sampled: None,
                single: ss,
            }
        })
        .collect();
    judge("fault check", &rows, 0.005, false)
}

/// Fault checks: the furnace test catches a table transposed in `(μ, α)` and an `E_avg` taken
/// from the wrong distribution, while the right table passes the same run.
#[test]
fn furnace_catches_a_transposed_table_and_a_foreign_average() {
    let mut transposed: ConductorTable = GGX_E;
    for (j, row) in transposed.iter_mut().enumerate() {
        for (i, v) in row.iter_mut().enumerate() {
            *v = GGX_E[i][j];
        }
    }
    for alpha in [0.2f32, 0.6, 1.0] {
        let right = AlbedoRow::from_table(&GGX_E, &GGX_E_AVG, alpha).unwrap();
        assert_eq!(
            faulty_furnace(right, alpha),
            0,
            "the right table fails at α = {alpha}"
        );
        let t = AlbedoRow::from_table(&transposed, &GGX_E_AVG, alpha).unwrap();
        let foreign = right
            .with_average(
                AlbedoRow::from_table(&BECKMANN_E, &BECKMANN_E_AVG, alpha)
                    .unwrap()
                    .average(),
            )
            .unwrap();
        let (a_t, a_f) = (faulty_furnace(t, alpha), faulty_furnace(foreign, alpha));
        eprintln!(
            "α = {alpha}: transposed table {a_t} of 4 points outside, Beckmann's E_avg {a_f} of 4"
        );
        // Every point of the furnace falls outside the bar with either fault.
        assert_eq!(a_t, 4, "the transposed table went unnoticed at α = {alpha}");
        assert_eq!(a_f, 4, "the foreign E_avg went unnoticed at α = {alpha}");
    }
}

/// Constructors refuse what the tables do not hold, naming the parameter.
#[test]
fn constructors_refuse_what_the_tables_do_not_hold() {
    let sep = Microfacet::new(
        Ggx::isotropic(a(0.3)),
        Masking::Separable,
        NoFresnel::<f32>::new(),
    );
    assert!(
        sep.with_energy_compensation()
            .unwrap_err()
            .param()
            .starts_with("masking")
    );
    let wide = Microfacet::new(
        Ggx::isotropic(a(1.5)),
        Masking::HeightCorrelated,
        NoFresnel::<f32>::new(),
    );
    assert_eq!(
        wide.with_energy_compensation().unwrap_err().param(),
        "alpha (compensated)"
    );
    let matched = RoughDielectric::new(Ggx::isotropic(a(0.3)), eta(1.005));
    assert_eq!(
        matched.with_energy_compensation().unwrap_err().param(),
        "eta (compensated)"
    );
    let dense = RoughDielectric::new(Ggx::isotropic(a(0.3)), eta(3.5));
    assert_eq!(
        dense.with_energy_compensation().unwrap_err().param(),
        "eta (compensated)"
    );
    assert!(
        RoughDielectric::new(Ggx::isotropic(a(0.3)), eta(0.5))
            .with_energy_compensation()
            .is_ok()
    );
    let inside_out = Plastic::compensated(0.5f32, Ggx::isotropic(a(0.3)), eta(0.8)).unwrap_err();
    assert_eq!(
        inside_out.to_string(),
        "invalid eta (compensated) = 0.8: expected a value in [1.01, 3]"
    );
    assert_eq!(
        Plastic::compensated(1.5f32, Ggx::isotropic(a(0.3)), eta(1.5))
            .unwrap_err()
            .param(),
        "reflectance"
    );
    // The table's α = 0 column and μ nodes: E = 1 for the mirror.
    assert!(GGX_E[0].iter().all(|&e| e == 1.0));
    assert!((alpha_node(ALPHA_NODES - 1, ALPHA_NODES) - 1.0).abs() < 1e-7);
}

/// Turquin's factor (at least 1) on a value `Microfacet` already holds at `f32::MAX` — a
/// grazing mirror pair of a narrow lobe under V-cavity masking, which only a table of your own
/// (`with_albedo`) can pair with — stays finite in `eval`, `eval_pdf` and `sample`.
#[test]
fn turquin_scaling_stays_finite_at_the_clamped_value() {
    let gold = common::gold();
    let inner = Microfacet::new(
        Ggx::new(a(0.2), a(0.7)),
        Masking::VCavity,
        Conductor { ior: gold },
    );
    let row = Ggx::isotropic(a(0.6)).conductor_albedo().unwrap();
    let m = CompensatedMicrofacet::with_albedo(inner, row, Compensation::Turquin);
    let (wo, wi) = (Vec3::new(1.0, 0.0, 1e-20), Vec3::new(-1.0, -0.0, 1e-20));
    assert_eq!(
        inner.eval(wo, wi).max_element(),
        f32::MAX,
        "the case is the clamped one"
    );
    let f = m.eval(wo, wi);
    assert!(f.is_finite() && f.min_element() >= 0.0, "{f:?}");
    let mut rng = Pcg32::new(7, 0);
    let wo = Vec3::new(1.0, 0.0, 1e-7).normalize();
    let mut drawn = 0;
    for _ in 0..10_000 {
        if let Some(s) = m.sample(wo, rng.next_vec2(), rng.next_f32()) {
            assert!(s.f.is_finite() && s.pdf.is_finite(), "{s:?}");
            drawn += 1;
        }
    }
    assert!(drawn > 0, "no sample drawn at grazing: nothing was checked");
}
