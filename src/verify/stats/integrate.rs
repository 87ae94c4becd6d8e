//! Integration: what the statistics of this module integrate, and how.
//!
//! Two integrators live here. [`Quadrature`] is nested adaptive Simpson quadrature of a
//! density over `(cos θ, φ)` rectangles, deterministic, with its own error estimate: the
//! chi-square test's expected counts ([`chi2_sphere`](super::chi2_sphere)).
//! [`integrate_hemisphere`] is a Monte Carlo integral over the upper hemisphere whose
//! proposal is stretched to a lobe's width, with a standard error: the integrals of the
//! microfacet distribution laws.

use super::estimate::{Accumulator, Estimate};
use super::rng::Pcg32;
use crate::sampling::{cosine_hemisphere, uniform_hemisphere};
use core::f64::consts::{PI, TAU};
use glam::{Vec2, Vec3};

/// The stream of [`integrate_hemisphere`]'s generator (the seed is the caller's).
const STREAM: u64 = 0x006e_6466;

/// The inner quadrature (over `φ`) aims at this fraction of the outer tolerance, so that
/// its error does not drive the outer refinement.
const INNER_TOL_FRACTION: f64 = 0.1;
/// Maximum number of bisections of a base cell, on each axis: `2⁻¹²` of a base cell
/// locates a jump in the density to far below one sample.
const MAX_DEPTH: u32 = 12;
/// Density evaluations allowed per bin before refinement stops (reached only by densities
/// whose `f32` rounding noise exceeds the tolerance, where refining would not help: the
/// noise averages out of the integral but not out of the error estimate).
const BIN_EVAL_BUDGET: u64 = 100_000;

/// Nested adaptive Simpson quadrature of a density over `(cos θ, φ)` rectangles.
///
/// The chi-square test's expected counts: [`grid`](Self::grid) gives a bin's rough mass on
/// the base grid, [`bin`](Self::bin) integrates it adaptively to a tolerance.
pub(in crate::verify) struct Quadrature<'p, P> {
    /// The density.
    pdf: &'p P,
    /// Base cells per bin and axis.
    res: usize,
    /// Density values that were negative or not finite.
    pub(in crate::verify) invalid: usize,
    /// Density evaluations so far.
    pub(in crate::verify) evals: u64,
    /// Refinement stops once `evals` reaches this (the current bin's budget).
    limit: u64,
    /// Sum of the outer quadrature's error estimates so far.
    pub(in crate::verify) error: f64,
}

/// Simpson's rule on `[a, b]` from the values at the ends and the midpoint.
#[inline]
fn simpson(a: f64, b: f64, fa: f64, fm: f64, fb: f64) -> f64 {
    (b - a) / 6.0 * (fa + 4.0 * fm + fb)
}

impl<'p, P: Fn(Vec3) -> f64> Quadrature<'p, P> {
    /// A quadrature of `pdf` with `res × res` base cells per bin.
    pub(in crate::verify) fn new(pdf: &'p P, res: usize) -> Self {
        Self {
            pdf,
            res,
            invalid: 0,
            evals: 0,
            limit: 0,
            error: 0.0,
        }
    }

    /// The density at `(cos θ, φ)`; invalid values are counted and read as zero.
    fn density(&mut self, c: f64, phi: f64) -> f64 {
        self.evals += 1;
        let s = (1.0 - c * c).max(0.0).sqrt();
        let (sp, cp) = phi.sin_cos();
        let w = Vec3::new((s * cp) as f32, (s * sp) as f32, c as f32);
        let v = (self.pdf)(w);
        if v.is_finite() && v >= 0.0 {
            v
        } else {
            self.invalid += 1;
            0.0
        }
    }

    /// `∫∫ pdf d(cos θ) dφ` over one bin by the composite Simpson product rule on the base
    /// grid (`2 res + 1` nodes per axis), without refinement.
    pub(in crate::verify) fn grid(&mut self, c0: f64, c1: f64, phi0: f64, phi1: f64) -> f64 {
        let m = 2 * self.res;
        // Composite Simpson weights 1, 4, 2, 4, …, 4, 1 (times h / 3).
        let weight = |i: usize| match i {
            0 => 1.0,
            i if i == m => 1.0,
            i if i % 2 == 1 => 4.0,
            _ => 2.0,
        };
        let (hc, hp) = ((c1 - c0) / m as f64, (phi1 - phi0) / m as f64);
        let mut sum = 0.0;
        for i in 0..=m {
            let c = if i == m { c1 } else { c0 + hc * i as f64 };
            for j in 0..=m {
                let phi = if j == m { phi1 } else { phi0 + hp * j as f64 };
                sum += weight(i) * weight(j) * self.density(c, phi);
            }
        }
        sum * (hc / 3.0) * (hp / 3.0)
    }

    /// `∫∫ pdf d(cos θ) dφ` over one bin, aiming at an absolute error below `tol`.
    pub(in crate::verify) fn bin(
        &mut self,
        c0: f64,
        c1: f64,
        phi0: f64,
        phi1: f64,
        tol: f64,
    ) -> f64 {
        self.limit = self.evals + BIN_EVAL_BUDGET;
        // The inner integral is multiplied by at most the bin's width in cos θ.
        let inner_tol = INNER_TOL_FRACTION * tol / (c1 - c0);
        let mut outer_error = 0.0;
        let (mut inner_error, mut inner_count) = (0.0, 0_u64);
        let mass = self.composite(c0, c1, tol, &mut outer_error, &mut |q: &mut Self, c| {
            inner_count += 1;
            q.composite(
                phi0,
                phi1,
                inner_tol,
                &mut inner_error,
                &mut |q: &mut Self, phi| q.density(c, phi),
            )
        });
        // The outer estimate misses a bias shared by all inner integrals; add their mean
        // error over the bin's width.
        self.error += outer_error + inner_error / inner_count.max(1) as f64 * (c1 - c0);
        mass
    }

    /// `∫ f` over `[a, b]` to an absolute tolerance `tol`: `res` equal cells, each refined
    /// adaptively with an equal share of the tolerance. Adds the error estimate to `error`.
    fn composite<F: FnMut(&mut Self, f64) -> f64>(
        &mut self,
        a: f64,
        b: f64,
        tol: f64,
        error: &mut f64,
        f: &mut F,
    ) -> f64 {
        let h = (b - a) / self.res as f64;
        let cell_tol = tol / self.res as f64;
        let mut fa = f(self, a);
        let mut sum = 0.0;
        for k in 0..self.res {
            let x0 = a + h * k as f64;
            let x1 = if k + 1 == self.res { b } else { x0 + h };
            let fm = f(self, 0.5 * (x0 + x1));
            let fb = f(self, x1);
            let whole = simpson(x0, x1, fa, fm, fb);
            sum += self.refine(f, (x0, x1), [fa, fm, fb], whole, cell_tol, MAX_DEPTH, error);
            fa = fb;
        }
        sum
    }

    /// Adaptive Simpson (Lyness 1969): accept the two half-interval estimates when they
    /// differ from the whole-interval estimate by at most `15 tol` (Simpson's error shrinks
    /// sixteenfold per halving, so the difference is about 15 times the halves' error),
    /// else recurse with `tol / 2` on each half. Returns the plain sum of the halves (no
    /// Richardson term), so a non-negative integrand gives a non-negative result that is
    /// zero only when every node is.
    #[allow(clippy::too_many_arguments)]
    fn refine<F: FnMut(&mut Self, f64) -> f64>(
        &mut self,
        f: &mut F,
        (a, b): (f64, f64),
        [fa, fm, fb]: [f64; 3],
        whole: f64,
        tol: f64,
        depth: u32,
        error: &mut f64,
    ) -> f64 {
        let m = 0.5 * (a + b);
        let flm = f(self, 0.5 * (a + m));
        let frm = f(self, 0.5 * (m + b));
        let left = simpson(a, m, fa, flm, fm);
        let right = simpson(m, b, fm, frm, fb);
        let diff = (left + right - whole).abs();
        if diff <= 15.0 * tol || depth == 0 || self.evals >= self.limit {
            *error += diff / 15.0;
            return left + right;
        }
        self.refine(f, (a, m), [fa, flm, fm], left, 0.5 * tol, depth - 1, error)
            + self.refine(f, (m, b), [fm, frm, fb], right, 0.5 * tol, depth - 1, error)
    }
}

/// The Monte Carlo estimate of `∫ f(m) dωm` over the upper hemisphere, from `samples` draws
/// of [`Pcg32::new(seed, …)`](Pcg32) on a stream of its own.
///
/// The proposal is a defensive mixture (Hesterberg 1995) of three densities in equal parts:
/// cosine-weighted and uniform directions stretched by `stretch = (sx, sy)` (`normalize(sx hx,
/// sy hy, hz)`), and uniform directions unstretched. The stretched parts follow a lobe of
/// width `stretch` (pass a distribution's widths `(αx, αy)`); the unstretched part bounds the
/// weights of a lobe whose tails are wider than its width suggests (GTR with a small `γ`).
/// The proposal knows nothing else of the integrand, so a check built on it is not circular.
/// The components take turns (sample `i` from component `i mod 3`), and the standard error is
/// that of such a stratified mixture; it needs two draws of each (`samples ≥ 6`) and is NaN
/// with fewer.
///
/// ```
/// use lobe::verify::integrate_hemisphere;
/// use lobe::Vec2;
/// // ∫ cos θ dω = π over the hemisphere.
/// let e = integrate_hemisphere(|m| f64::from(m.z), 100_000, 1, Vec2::ONE);
/// assert!(e.within(std::f64::consts::PI, 4.0), "{e}");
/// ```
#[must_use]
pub fn integrate_hemisphere(
    f: impl Fn(Vec3) -> f64,
    samples: usize,
    seed: u64,
    stretch: Vec2,
) -> Estimate {
    let mut rng = Pcg32::new(seed, STREAM);
    // The components take turns, so their counts are fixed (a stratified mixture, not a
    // random one): the estimate's variance is the components' own, `Σ (n_k/N)² s_k²/n_k`,
    // without the spread between their means (which the pooled sample variance would add:
    // 1.25× the standard error for GGX α = 0.3).
    let mut parts = [Accumulator::new(); 3];
    for i in 0..samples {
        let u = rng.next_vec2();
        let m = match i % 3 {
            0 => stretch_direction(cosine_hemisphere(u), stretch),
            1 => stretch_direction(uniform_hemisphere(u), stretch),
            _ => uniform_hemisphere(u),
        };
        let pdf = proposal_pdf(m, stretch);
        parts[i % 3].push(if pdf > 0.0 { f(m) / pdf } else { 0.0 });
    }
    let n = samples as f64;
    let (mut mean, mut var) = (0.0, 0.0);
    for part in parts.iter().filter(|p| !p.is_empty()) {
        let (e, share) = (part.finish(), part.len() as f64 / n);
        mean += share * e.mean;
        // One draw of a component has no spread of its own to show: all of them, then.
        let v = if part.len() > 1 {
            e.std_err * e.std_err
        } else {
            f64::NAN
        };
        var += share * share * v;
    }
    Estimate {
        mean: if samples == 0 { f64::NAN } else { mean },
        // Fewer than two draws of a component: no spread to show (NaN, as documented).
        std_err: if samples < 6 { f64::NAN } else { var.sqrt() },
        n: samples as u64,
    }
}

/// The density of [`integrate_hemisphere`]'s proposal at `m`, in solid angle.
fn proposal_pdf(m: Vec3, stretch: Vec2) -> f64 {
    let (sx, sy) = (f64::from(stretch.x), f64::from(stretch.y));
    // h = normalize(M⁻¹ m) is the unstretched direction; dω_h/dω_m = 1 / (sx sy |M⁻¹ m|³).
    let (x, y, z) = (f64::from(m.x) / sx, f64::from(m.y) / sy, f64::from(m.z));
    let len = (x * x + y * y + z * z).sqrt();
    let hz = z / len;
    let jacobian = 1.0 / (sx * sy * len * len * len);
    let stretched_cos = hz.max(0.0) / PI * jacobian;
    let stretched_uniform = jacobian / TAU;
    (stretched_cos + stretched_uniform + 1.0 / TAU) / 3.0
}

/// `normalize(sx hx, sy hy, hz)`.
pub(in crate::verify) fn stretch_direction(h: Vec3, s: Vec2) -> Vec3 {
    Vec3::new(s.x * h.x, s.y * h.y, h.z).normalize_or(Vec3::Z)
}
