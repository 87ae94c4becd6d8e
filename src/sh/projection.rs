//! Projection onto the basis by a deterministic product quadrature: Gauss–Legendre in
//! `cos θ`, uniform in `φ`.

use super::basis::basis;
use super::coefficients::Sh;
use crate::math::{sin_cos, sqrt_f64};
use crate::spectrum::Spectrum;
use core::f32::consts::PI;
use glam::Vec3;

/// A product quadrature rule on the unit sphere: `n_theta` Gauss–Legendre nodes in
/// `z = cos θ` times `n_phi` equally spaced azimuths `φ_j = 2π (j + ½) / n_phi`.
///
/// **Exactness.** The rule integrates exactly (to round-off) every polynomial in `x, y, z`
/// of total degree `≤ min(2 n_theta − 1, n_phi − 1)`: Gauss–Legendre with `n` nodes is exact
/// for polynomials in `z` of degree `2n − 1` (Abramowitz & Stegun 25.4.29), and the
/// trapezoidal rule in `φ` is exact for trigonometric polynomials of degree `< n_phi`. A
/// band-limited function of order `L` (degree `L − 1`) times a basis function of order `K`
/// is such a polynomial of degree `L + K − 2`, so [`for_projection`](Self::for_projection)
/// makes projection exact. With [`split_at_equator`](Self::split_at_equator) the nodes are
/// placed on each hemisphere separately (`n_theta` on each): exact for integrands that are
/// polynomial on each hemisphere with a kink or jump at `z = 0`, such as the clamped cosine
/// `max(cos θ, 0)` or a BRDF lobe cut by the horizon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SphereQuadrature {
    /// Gauss–Legendre nodes in `cos θ` (on each hemisphere when split); at least 1.
    n_theta: usize,
    /// Equally spaced azimuths; at least 1.
    n_phi: usize,
    /// Nodes placed on each hemisphere separately.
    split: bool,
}

impl SphereQuadrature {
    /// The rule with `n_theta × n_phi` nodes (each at least 1) on the whole sphere.
    #[inline]
    #[must_use]
    pub const fn new(n_theta: usize, n_phi: usize) -> Self {
        Self {
            n_theta: if n_theta == 0 { 1 } else { n_theta },
            n_phi: if n_phi == 0 { 1 } else { n_phi },
            split: false,
        }
    }

    /// The smallest rule exact for polynomials of total degree `degree`: `⌊degree/2⌋ + 1`
    /// Gauss–Legendre nodes (`2n − 1 ≥ degree`) and `degree + 1` azimuths.
    #[inline]
    #[must_use]
    pub const fn exact_for_degree(degree: usize) -> Self {
        Self::new(degree / 2 + 1, degree + 1)
    }

    /// The rule that projects a function band-limited to order `input_order` (bands
    /// `l < input_order`) onto the basis of order `output_order` exactly: exact for degree
    /// `input_order + output_order − 2`.
    #[inline]
    #[must_use]
    pub const fn for_projection(input_order: usize, output_order: usize) -> Self {
        Self::exact_for_degree((input_order + output_order).saturating_sub(2))
    }

    /// The same rule with its `cos θ` nodes on each hemisphere separately (twice the
    /// nodes): exact for integrands polynomial on each side of the equator `z = 0`.
    #[inline]
    #[must_use]
    pub const fn split_at_equator(self) -> Self {
        Self {
            split: true,
            ..self
        }
    }

    /// The Gauss–Legendre nodes in `cos θ` (on each hemisphere when split); at least 1.
    #[inline]
    #[must_use]
    pub const fn n_theta(&self) -> usize {
        self.n_theta
    }

    /// The equally spaced azimuths; at least 1.
    #[inline]
    #[must_use]
    pub const fn n_phi(&self) -> usize {
        self.n_phi
    }

    /// Whether the `cos θ` nodes are placed on each hemisphere separately
    /// ([`split_at_equator`](Self::split_at_equator)).
    #[inline]
    #[must_use]
    pub const fn is_split(&self) -> bool {
        self.split
    }

    /// The number of nodes.
    #[inline]
    #[must_use]
    pub const fn len(&self) -> usize {
        self.n_theta * self.n_phi * if self.split { 2 } else { 1 }
    }

    /// Always false: a rule has at least one node.
    #[inline]
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        false
    }

    /// Visits the rule ring by ring: `visit(weight, ring)` for each `cos θ` node, with the
    /// weight of each of the ring's nodes (the Gauss–Legendre weight times `2π / n_phi`).
    /// The weights of all nodes sum to `4π`.
    pub(crate) fn for_each_ring(&self, mut visit: impl FnMut(f32, Ring)) {
        let dphi = 2.0 * PI / self.n_phi as f32;
        let halves: &[(f64, f64)] = if self.split {
            &[(-1.0, 0.0), (0.0, 1.0)]
        } else {
            &[(-1.0, 1.0)]
        };
        for &(a, b) in halves {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for i in 0..self.n_theta {
                let (x, wgt) = gauss_legendre(self.n_theta, i);
                let z = mid + half * x;
                let ring = Ring {
                    z: z as f32,
                    sin_theta: sqrt_f64((1.0 - z * z).max(0.0)) as f32,
                    n_phi: self.n_phi,
                    dphi,
                };
                visit((wgt * half) as f32 * dphi, ring);
            }
        }
    }

    /// Calls `f` at every node with its direction and weight.
    pub fn for_each(&self, mut f: impl FnMut(Vec3, f32)) {
        self.for_each_ring(|weight, ring| {
            for w in ring.directions() {
                f(w, weight);
            }
        });
    }

    /// `∫ f(ω) dω` over the sphere by the rule.
    ///
    /// ```
    /// use lobe::sh::SphereQuadrature;
    /// // ∫ z² dω = 4π/3, exactly for a rule of degree 2.
    /// let v = SphereQuadrature::exact_for_degree(2).integrate(|w| w.z * w.z);
    /// assert!((v - 4.0 * core::f32::consts::PI / 3.0).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn integrate<S: Spectrum>(&self, mut f: impl FnMut(Vec3) -> S) -> S {
        // Ring sums first, then weighted: fewer large-small additions.
        let mut total = S::zero();
        self.for_each_ring(|weight, ring| {
            let mut sum = S::zero();
            for w in ring.directions() {
                sum += f(w);
            }
            total += sum * weight;
        });
        total
    }
}

/// One ring of a [`SphereQuadrature`]: the nodes at one `cos θ`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ring {
    /// `cos θ`.
    pub(crate) z: f32,
    /// `sin θ`.
    sin_theta: f32,
    /// The number of azimuths.
    n_phi: usize,
    /// Their spacing.
    dphi: f32,
}

impl Ring {
    /// The ring's unit directions, `φ_j = (j + ½) Δφ`.
    pub(crate) fn directions(self) -> impl Iterator<Item = Vec3> {
        (0..self.n_phi).map(move |j| {
            let (sp, cp) = sin_cos((j as f32 + 0.5) * self.dphi);
            Vec3::new(self.sin_theta * cp, self.sin_theta * sp, self.z)
        })
    }
}

/// Node `i` (ascending) and weight of the `n`-point Gauss–Legendre rule on `[−1, 1]`, in
/// `f64`: Newton's iteration on `P_n` from the asymptotic guess
/// `cos(π (n − i − ¼)/(n + ½))`, weight `2 / ((1 − x²) P_n′(x)²)` (Abramowitz & Stegun
/// 25.4.29; Press et al., *Numerical Recipes* 3rd ed. §4.6). Precondition `i < n`.
#[must_use]
pub(crate) fn gauss_legendre(n: usize, i: usize) -> (f64, f64) {
    let nf = n as f64;
    // Roots descend with k = n − 1 − i; the guess needs only f32 accuracy, but not one that
    // rounds onto ±1, where P_n′'s formula is 0/0: `cos θ` is formed as `1 − 2 sin²(θ/2)` in
    // f64 from the angle to the nearer pole (for n ≥ 9,651 the end nodes' f32 cosine was ±1).
    let k = (n - 1 - i) as f64;
    let theta = core::f64::consts::PI * (k + 0.75) / (nf + 0.5);
    let from_pole = theta.min(core::f64::consts::PI - theta);
    let s = f64::from(crate::math::sin_cos((0.5 * from_pole) as f32).0);
    let near = 1.0 - 2.0 * s * s;
    let mut x = if theta <= core::f64::consts::FRAC_PI_2 {
        near
    } else {
        -near
    };
    let mut dp = 1.0;
    for _ in 0..20 {
        // Bonnet's recurrence for P_n(x), then P_n′ = n (x P_n − P_{n−1}) / (x² − 1).
        let (mut p0, mut p1) = (1.0_f64, x);
        for j in 1..n {
            let jf = j as f64;
            let p2 = ((2.0 * jf + 1.0) * x * p1 - jf * p0) / (jf + 1.0);
            p0 = p1;
            p1 = p2;
        }
        let pn = if n == 0 { 1.0 } else { p1 };
        let pn1 = if n <= 1 { 1.0 } else { p0 };
        dp = nf * (x * pn - pn1) / (x * x - 1.0);
        let dx = pn / dp;
        x -= dx;
        if dx.abs() <= 1e-15 {
            break;
        }
    }
    (x, 2.0 / ((1.0 - x * x) * dp * dp))
}

impl<const N: usize, S: Spectrum> Sh<N, S> {
    /// The coefficients of `f`, exact (to round-off) when `f` is band-limited to order
    /// `input_order`: `f_i = ∫ f Y_i dω` by [`SphereQuadrature::for_projection`].
    ///
    /// A function that is not band-limited (a sky with a sharp horizon, a BRDF lobe) needs a
    /// finer rule: give it to [`project_with`](Self::project_with), and watch the result
    /// converge as the rule grows.
    ///
    /// ```
    /// use lobe::sh::Sh;
    /// // f = z is band 1: its only coefficient is f_{1,0} = √(4π/3).
    /// let f: Sh<9> = Sh::project(|w| w.z, 2);
    /// assert!((f.get(1, 0) - (4.0 * core::f32::consts::PI / 3.0).sqrt()).abs() < 1e-5);
    /// ```
    #[must_use]
    pub fn project(f: impl FnMut(Vec3) -> S, input_order: usize) -> Self {
        Self::project_with(
            f,
            &SphereQuadrature::for_projection(input_order, Self::ORDER),
        )
    }

    /// The coefficients of `f` by the quadrature `rule`: `f_i ≈ Σ_k w_k f(ω_k) Y_i(ω_k)`.
    #[must_use]
    pub fn project_with(mut f: impl FnMut(Vec3) -> S, rule: &SphereQuadrature) -> Self {
        let mut total = Self::zero();
        rule.for_each_ring(|weight, ring| {
            let mut sum = Self::zero();
            for w in ring.directions() {
                let v = f(w);
                let y = basis::<N>(w);
                for (c, yi) in sum.coeffs.iter_mut().zip(y) {
                    *c += v * yi;
                }
            }
            total += sum * weight;
        });
        total
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_matches_the_tables() {
        // Abramowitz & Stegun table 25.4, n = 3: ±√(3/5) with weight 5/9, 0 with 8/9.
        let (x, w) = gauss_legendre(3, 2);
        assert!((x - 0.6_f64.sqrt()).abs() < 1e-14 && (w - 5.0 / 9.0).abs() < 1e-14);
        let (x, w) = gauss_legendre(3, 1);
        assert!(x.abs() < 1e-14 && (w - 8.0 / 9.0).abs() < 1e-14);
        // n = 1: the midpoint, weight 2.
        let (x, w) = gauss_legendre(1, 0);
        assert!(x.abs() < 1e-14 && (w - 2.0).abs() < 1e-14);
        // Weights sum to 2 and ∫ x^(2n−2) = 2/(2n−1) for n = 40.
        let n = 40;
        let (mut sw, mut sx) = (0.0, 0.0);
        for i in 0..n {
            let (x, w) = gauss_legendre(n, i);
            sw += w;
            sx += w * x.powi(2 * n as i32 - 2);
        }
        assert!((sw - 2.0).abs() < 1e-13, "{sw}");
        assert!((sx - 2.0 / (2.0 * n as f64 - 1.0)).abs() < 1e-13, "{sx}");
    }

    #[test]
    fn gauss_legendre_keeps_its_end_nodes_inside_for_large_rules() {
        // For n ≥ 9,651 the end nodes' f32 guess rounded onto ±1 and Newton's step was 0/0:
        // NaN nodes and weights. Every node inside (−1, 1), ascending, with the weights summing
        // to 2 and the rule integrating x² (2/3) and x¹⁰ (2/11).
        for n in [9_651, 12_000] {
            let (mut sw, mut s2, mut s10, mut last) = (0.0, 0.0, 0.0, -1.0);
            for i in 0..n {
                let (x, w) = gauss_legendre(n, i);
                assert!(x > last && x < 1.0 && w > 0.0, "n = {n}, i = {i}: {x}, {w}");
                last = x;
                sw += w;
                s2 += w * x * x;
                s10 += w * x.powi(10);
            }
            assert!((sw - 2.0).abs() < 1e-10, "n = {n}: {sw}");
            assert!((s2 - 2.0 / 3.0).abs() < 1e-10, "n = {n}: {s2}");
            assert!((s10 - 2.0 / 11.0).abs() < 1e-10, "n = {n}: {s10}");
        }
    }

    #[test]
    fn split_rule_integrates_the_clamped_cosine() {
        // ∫ max(z, 0) dω = π; a single node per hemisphere suffices when split.
        let rule = SphereQuadrature::exact_for_degree(1).split_at_equator();
        let v = rule.integrate(|w: Vec3| w.z.max(0.0));
        assert!((v - PI).abs() < 1e-6, "{v}");
        assert_eq!(rule.len(), 2 * rule.n_theta * rule.n_phi);
    }
}
