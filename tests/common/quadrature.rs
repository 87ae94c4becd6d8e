//! Deterministic quadrature of a model's directional albedo, an estimator independent of
//! both Monte Carlo estimators (for the diffuse models, whose integrands are smooth).

use lobe::Vec3;
use lobe::bxdf::Bxdf;
use std::f64::consts::FRAC_PI_2;

/// 8-point Gauss-Legendre nodes and weights on `[−1, 1]`, the positive half (Abramowitz &
/// Stegun, table 25.4).
const GL8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// Composite 8-point Gauss-Legendre quadrature of `f` over `[a, b]` in `pieces` panels.
pub fn gauss(a: f64, b: f64, pieces: usize, mut f: impl FnMut(f64) -> f64) -> f64 {
    let h = (b - a) / pieces as f64;
    let mut sum = 0.0;
    for k in 0..pieces {
        let mid = a + (k as f64 + 0.5) * h;
        for &(x, w) in &GL8 {
            sum += w * (f(mid - 0.5 * h * x) + f(mid + 0.5 * h * x));
        }
    }
    0.5 * h * sum
}

/// The directional albedo `∫ f(wo, wi) cos θi dωi` at `θo` (azimuth 0.4) by quadrature in
/// `(θi, φi)`, with panels split at `θi = θo` and in azimuthal quarters around `φo` (where
/// Oren-Nayar's `max(0, cos Δφ)` has its kinks).
pub fn albedo_quadrature(bxdf: &impl Bxdf<Spectrum = f32>, theta_o_deg: f64) -> f64 {
    let (theta_o, phi_o) = (theta_o_deg.to_radians(), 0.4f64);
    let wo = Vec3::new(
        (theta_o.sin() * phi_o.cos()) as f32,
        (theta_o.sin() * phi_o.sin()) as f32,
        theta_o.cos() as f32,
    );
    let inner = |t: f64| {
        let (st, ct) = t.sin_cos();
        let mut sum = 0.0;
        for q in 0..4 {
            let lo = phi_o + (f64::from(q) - 2.0) * FRAC_PI_2;
            sum += gauss(lo, lo + FRAC_PI_2, 4, |p| {
                let wi = Vec3::new((st * p.cos()) as f32, (st * p.sin()) as f32, ct as f32);
                f64::from(bxdf.eval(wo, wi))
            });
        }
        sum * ct * st
    };
    let mut total = gauss(theta_o, FRAC_PI_2, 6, inner);
    if theta_o > 0.0 {
        total += gauss(0.0, theta_o, 6, inner);
    }
    total
}
