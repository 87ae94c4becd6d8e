//! Monte Carlo projection with standard errors, through `lobe::verify`'s estimators
//! (feature `verify`).

use super::basis::basis;
use super::coefficients::Sh;
use crate::bxdf::Bxdf;
use crate::sampling::uniform_sphere;
use crate::verify::{Accumulator, Estimate, Pcg32};
use core::f32::consts::PI;
use glam::Vec3;

/// Monte Carlo estimates of `N` SH coefficients, each with its standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShEstimate<const N: usize> {
    /// The estimate of coefficient `i`, at the flat index `l(l + 1) + m`.
    pub coeffs: [Estimate; N],
}

impl<const N: usize> ShEstimate<N> {
    /// The estimated coefficients (the means).
    #[must_use]
    pub fn mean(&self) -> Sh<N, f32> {
        Sh::new(self.coeffs.map(|e| e.mean as f32))
    }

    /// The largest `|z|`-score of the estimates against `exact`, in standard errors (see
    /// [`Estimate::z_score`]); NaN when any coefficient's score is NaN (an estimate of fewer
    /// than two samples, or a NaN mean or target), so that a check `z < k` fails, as
    /// [`within`](Self::within) does.
    #[must_use]
    pub fn max_z_score(&self, exact: &Sh<N, f32>) -> f64 {
        self.coeffs
            .iter()
            .zip(&exact.coeffs)
            .map(|(e, &x)| e.z_score(f64::from(x)).abs())
            // Not `f64::max`, which drops a NaN and would report agreement.
            .fold(
                0.0,
                |worst, z| if z > worst || z.is_nan() { z } else { worst },
            )
    }

    /// Whether every coefficient is within `k_sigma` standard errors of `exact` (see
    /// [`Estimate::within`]).
    #[must_use]
    pub fn within(&self, exact: &Sh<N, f32>, k_sigma: f64) -> bool {
        self.coeffs
            .iter()
            .zip(&exact.coeffs)
            .all(|(e, &x)| e.within(f64::from(x), k_sigma))
    }
}

/// Accumulates one weighted sample `value · Y_i(w)` into every coefficient's accumulator.
fn push<const N: usize>(acc: &mut [Accumulator; N], w: Vec3, value: f64) {
    if value == 0.0 {
        for a in acc.iter_mut() {
            a.push(0.0);
        }
        return;
    }
    let y = basis::<N>(w);
    for (a, yi) in acc.iter_mut().zip(y) {
        a.push(value * f64::from(yi));
    }
}

/// The coefficients of `f` by Monte Carlo: `samples` directions uniform on the sphere from
/// `rng`, the estimator `4π f(ω) Y_i(ω)` for each coefficient, accumulated in `f64`
/// ([`Accumulator`]). Unbiased for any integrable `f`; the standard error falls as
/// `1/√samples`. The deterministic [`Sh::project`] is exact for band-limited input and
/// should be preferred; this is the independent check, and the tool for functions no
/// quadrature resolves.
///
/// ```
/// use lobe::sh::{project_monte_carlo, Sh};
/// use lobe::verify::Pcg32;
/// let f = |w: lobe::Vec3| 1.0 + w.z;
/// let exact: Sh<4> = Sh::project(f, 2);
/// let mc = project_monte_carlo::<4>(f, 20_000, &mut Pcg32::new(1, 2));
/// assert!(mc.within(&exact, 5.0));
/// ```
#[must_use]
pub fn project_monte_carlo<const N: usize>(
    mut f: impl FnMut(Vec3) -> f32,
    samples: u64,
    rng: &mut Pcg32,
) -> ShEstimate<N> {
    let mut acc = [Accumulator::new(); N];
    for _ in 0..samples {
        let w = uniform_sphere(rng.next_vec2());
        push(&mut acc, w, f64::from(f(w)) * f64::from(4.0 * PI));
    }
    ShEstimate {
        coeffs: acc.map(|a| a.finish()),
    }
}

/// The transfer vector of `bxdf` for the viewing direction `wo` (see
/// [`Transfer`](super::Transfer)) by importance sampling with the model's own sampler: the
/// estimator `f |cos θi| / pdf · Y_i(ωi)` (the sample's [`weight`](crate::bxdf::BxdfSample::weight)),
/// zero when `sample` gives no direction or a delta lobe. Unbiased when the sampler's
/// density covers the lobe, which every model of the crate's does.
#[must_use]
pub fn transfer_monte_carlo<const N: usize, B: Bxdf<Spectrum = f32>>(
    bxdf: &B,
    wo: Vec3,
    samples: u64,
    rng: &mut Pcg32,
) -> ShEstimate<N> {
    let mut acc = [Accumulator::new(); N];
    for _ in 0..samples {
        let u = rng.next_vec2();
        let uc = rng.next_f32();
        match bxdf.sample(wo, u, uc) {
            Some(s) if !s.is_specular() && s.pdf > 0.0 => {
                push(&mut acc, s.wi, f64::from(s.weight()));
            }
            _ => push(&mut acc, Vec3::Z, 0.0),
        }
    }
    ShEstimate {
        coeffs: acc.map(|a| a.finish()),
    }
}
