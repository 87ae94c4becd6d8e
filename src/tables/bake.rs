//! The integrators that bake the albedo tables: deterministic adaptive cubature over the
//! unit square of a distribution's visible-normal sampler, in `f64`.
//!
//! `examples/bake_tables.rs` calls [`conductor_entry`] and [`dielectric_entry`] to write the
//! tables under `src/tables/`, and `tests/energy_compensation.rs` calls them again to
//! re-bake a sample of the entries and compare them with the committed ones. They are plain
//! functions of their arguments — no state, no allocation, no randomness — so the same
//! build reproduces every entry bit for bit.
//!
//! **The integral.** The directional albedo `E(wo) = ∫ f(wo, wi) |cos θi| dωi` of a
//! microfacet model is written over the microfacet normal `m` that connects `wo` to `wi`
//! (Walter et al. 2007, eqs. 14 and 17). For a normal drawn from the distribution of visible
//! normals `D_wo(m)` with the unit square `u ∈ [0, 1)²` of the distribution's own sampler
//! ([`NormalDistribution::sample`]), the reflected direction `wi = 2 (wo·m) m − wo`
//! contributes `f |cos θi| / (D_wo(m) J_r)` with the reflection's Jacobian
//! `J_r = 1 / (4 |wo·m|)`, and the refracted one contributes `f |cos θi| / (D_wo(m) J_t)` with
//! `J_t = |wi·m| / (wi·m + (wo·m)/η')²`. The value `f` is the model's own
//! [`Bxdf::eval`], so a table holds the albedo of the model exactly as the crate evaluates
//! it. The integrand is bounded (for a conductor it is `G2/G1(wo)`, in `[0, 1]`) and
//! continuous, with a steep fall where `wi` nears the horizon.
//!
//! **The rule.** [`integrate_square_adaptive`]: the square is cut into quarters, at least
//! four times (256 cells) and at most eight (cells of side 1/256), each cell estimated by the
//! product 8 × 8 Gauss–Legendre rule and accepted once its quarters agree with it within the
//! tolerance times its area. A substitution `u = t³ (10 − 15t + 6t²)` in both coordinates
//! spreads the ends of the square, where the samplers' tails are. The rule's error is
//! measured in `tests/energy_compensation.rs` against a tolerance ten times tighter and
//! against Monte Carlo.

use crate::bxdf::{Bxdf, Microfacet, RoughDielectric, TransportMode};
use crate::frame::{reflect_away, refract_away};
use crate::fresnel::{NoFresnel, dielectric};
use crate::math::sqrt_f64;
use crate::microfacet::{Beckmann, Ggx, Masking, NormalDistribution};
use crate::param::{Alpha, Eta};
use glam::{Vec2, Vec3};

/// Gauss–Legendre nodes (the positive half) and weights on `[−1, 1]`, 8 points, to `f64`
/// precision (Abramowitz & Stegun, table 25.4).
const NODES: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
const WEIGHTS: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

/// The depth below which [`integrate_square_adaptive`] always refines (256 cells): shallower
/// acceptance was seen to miss a steep fall inside a cell whose quarters agreed by chance.
const MIN_DEPTH: u32 = 4;
/// The depth at which it stops refining (cells of side 2⁻⁸), where the `f32` round-off of a
/// grazing configuration, not the rule, sets the error.
const MAX_DEPTH: u32 = 8;

/// The tolerance of the conductor tables' entries.
pub const CONDUCTOR_TOLERANCE: f64 = 1e-6;
/// The tolerance of the dielectric tables' entries.
pub const DIELECTRIC_TOLERANCE: f64 = 1e-5;

/// The `k`-th of the 8 nodes of the Gauss–Legendre rule on `[0, 1]`, and its weight.
#[inline]
fn node(k: usize) -> (f64, f64) {
    let (x, w) = if k < 4 {
        (-NODES[3 - k], WEIGHTS[3 - k])
    } else {
        (NODES[k - 4], WEIGHTS[k - 4])
    };
    (0.5 + 0.5 * x, 0.5 * w)
}

/// The product 8 × 8 Gauss–Legendre rule on the cell `[x, x + h] × [y, y + h]`.
fn cell<const N: usize>(
    f: &mut impl FnMut(f64, f64) -> [f64; N],
    x: f64,
    y: f64,
    h: f64,
) -> [f64; N] {
    let mut sum = [0.0; N];
    for a in 0..8 {
        let (ta, wa) = node(a);
        for b in 0..8 {
            let (tb, wb) = node(b);
            let v = f(x + h * ta, y + h * tb);
            for (s, v) in sum.iter_mut().zip(v) {
                *s += wa * wb * v;
            }
        }
    }
    sum.map(|s| s * h * h)
}

/// Refines the cell `[x, x + h] × [y, y + h]`, whose 8 × 8 estimate is `whole`: its four
/// quarters are estimated and accepted when every component agrees with `whole` within
/// `tol` times the cell's area (from depth [`MIN_DEPTH`] on), else refined in turn, down to
/// [`MAX_DEPTH`].
fn refine<const N: usize>(
    f: &mut impl FnMut(f64, f64) -> [f64; N],
    (x, y, h): (f64, f64, f64),
    whole: [f64; N],
    tol: f64,
    depth: u32,
) -> [f64; N] {
    let k = 0.5 * h;
    let corners = [(x, y), (x + k, y), (x, y + k), (x + k, y + k)];
    let quarters = corners.map(|(cx, cy)| cell(f, cx, cy, k));
    let mut sum = [0.0; N];
    for q in &quarters {
        for (s, v) in sum.iter_mut().zip(q) {
            *s += v;
        }
    }
    let agree = sum
        .iter()
        .zip(&whole)
        .all(|(s, w)| (s - w).abs() <= tol * h * h);
    if depth >= MAX_DEPTH || (depth >= MIN_DEPTH && agree) {
        return sum;
    }
    let mut total = [0.0; N];
    for (q, (cx, cy)) in quarters.into_iter().zip(corners) {
        let r = refine(f, (cx, cy, k), q, tol, depth + 1);
        for (t, v) in total.iter_mut().zip(r) {
            *t += v;
        }
    }
    total
}

/// `∫∫_[0,1]² f(x, y) dx dy` for a vector of `N` integrands, by adaptive cubature: the
/// square is cut into quarters recursively (at least four times, at most eight), each cell
/// estimated by the product 8 × 8 Gauss–Legendre rule and accepted once its quarters agree
/// with it, component by component, within `tol` times its area — so that the accepted
/// differences, the error estimate, add up to at most `tol`. Deterministic; no allocation.
#[must_use]
pub fn integrate_square_adaptive<const N: usize>(
    tol: f64,
    mut f: impl FnMut(f64, f64) -> [f64; N],
) -> [f64; N] {
    let whole = cell(&mut f, 0.0, 0.0, 1.0);
    refine(&mut f, (0.0, 0.0, 1.0), whole, tol, 1)
}

/// The quintic smoothstep `u = t³ (10 − 15 t + 6 t²)` and its derivative `30 t² (1 − t)²`:
/// a substitution that spreads the ends of `[0, 1]`, where a sampler's tails are.
#[inline]
fn smoothstep(t: f64) -> (f64, f64) {
    let t2 = t * t;
    let u = t2 * t * (10.0 - 15.0 * t + 6.0 * t2);
    let s = 1.0 - t;
    (u, 30.0 * t2 * s * s)
}

/// The unit direction at `cos θ = mu` in the `xz` plane (`mu < 0`: below the surface).
#[inline]
#[must_use]
pub fn direction(mu: f32) -> Vec3 {
    let s = (1.0 - f64::from(mu) * f64::from(mu)).max(0.0);
    Vec3::new(sqrt_f64(s) as f32, 0.0, mu)
}

/// The directional albedo `∫ f(wo, wi) |cos θi| dωi` of a microfacet model whose lobes are
/// reached through the normals of `dist` (the model's own distribution), split into what
/// leaves by reflection and what leaves by refraction through the relative index `eta`
/// (given for a refracting model), each weighed by its Jacobian (see the
/// [module docs](self)): `[reflection, transmission]`, by [`integrate_square_adaptive`]
/// with tolerance `tol`. `[0, 0]` for a tangent `wo`.
#[must_use]
pub fn albedo<B, D>(bxdf: &B, dist: &D, eta: Option<Eta>, wo: Vec3, tol: f64) -> [f64; 2]
where
    B: Bxdf<Spectrum = f32> + ?Sized,
    D: NormalDistribution + ?Sized,
{
    if wo.z == 0.0 {
        return [0.0; 2];
    }
    let view = dist.view(wo);
    let integrand = |u: Vec2| -> [f64; 2] {
        let m = dist.sample(&view, u);
        let pdf = f64::from(dist.pdf(&view, m, dist.d(m)));
        if !(pdf > 0.0) {
            return [0.0; 2];
        }
        let wom = f64::from(wo.dot(m));
        let mut out = [0.0; 2];
        // Reflection: only a direction on wo's own side (the other side is refraction's).
        let wr = reflect_away(wo, m);
        if wr.z * wo.z > 0.0 {
            let f = f64::from(bxdf.eval(wo, wr));
            out[0] = f * f64::from(wr.z.abs()) * 4.0 * wom.abs() / pdf;
        }
        if let Some(e) = eta {
            let etap = if wo.z > 0.0 { e.get() } else { 1.0 / e.get() };
            if let Some(wt) = refract_away(wo, m, e) {
                let wim = f64::from(wt.dot(m));
                if wt.z * wo.z < 0.0 && wim != 0.0 {
                    let denom = wim + wom / f64::from(etap);
                    let f = f64::from(bxdf.eval(wo, wt));
                    out[1] = f * f64::from(wt.z.abs()) * denom * denom / (wim.abs() * pdf);
                }
            }
        }
        out
    };
    integrate_square_adaptive(tol, |tx, ty| {
        let ((x, dx), (y, dy)) = (smoothstep(tx), smoothstep(ty));
        let jacobian = dx * dy;
        if jacobian == 0.0 {
            return [0.0; 2];
        }
        integrand(Vec2::new(x as f32, y as f32)).map(|v| v * jacobian)
    })
}

/// The distributions the crate tabulates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// [`Ggx`].
    Ggx,
    /// [`Beckmann`] with its exact Smith `Λ`.
    Beckmann,
}

/// `μ` at which node `i` of a row of `nodes` is evaluated: `(i / (nodes − 1))²`, and for the
/// first node, where the model has no value (`μ = 0` is tangent), half a step in: `μ₀ =
/// (1 / (2 (nodes − 1)))²`.
#[inline]
#[must_use]
pub fn evaluation_mu(i: usize, nodes: usize) -> f32 {
    let step = 1.0 / (nodes - 1) as f32;
    let x = if i == 0 { 0.5 * step } else { i as f32 * step };
    x * x
}

/// The conductor table's entry at `μ` node `i` and `α` node `j` ([`super::MU_NODES`] ×
/// [`super::ALPHA_NODES`]): the albedo of `Microfacet<D, NoFresnel>` with height-correlated
/// masking at `μ = evaluation_mu(i)` and `α = (j / (ALPHA_NODES − 1))²`, integrated to
/// [`CONDUCTOR_TOLERANCE`] and rounded to `f32`. The row `α = 0` is the smooth mirror's
/// albedo, exactly 1.
#[must_use]
pub fn conductor_entry(family: Family, i: usize, j: usize) -> f32 {
    let alpha = super::alpha_node(j, super::ALPHA_NODES);
    if alpha == 0.0 {
        return 1.0;
    }
    let wo = direction(evaluation_mu(i, super::MU_NODES));
    let Ok(a) = Alpha::new(alpha) else {
        return 1.0;
    };
    let e = match family {
        Family::Ggx => conductor_albedo(&Ggx::isotropic(a), wo),
        Family::Beckmann => conductor_albedo(&Beckmann::isotropic(a), wo),
    };
    (e as f32).clamp(0.0, 1.0)
}

/// The albedo of the F = 1 conductor on `dist` at `wo`.
fn conductor_albedo<D: NormalDistribution + Copy>(dist: &D, wo: Vec3) -> f64 {
    let model = Microfacet::new(*dist, Masking::HeightCorrelated, NoFresnel::<f32>::new());
    albedo(&model, dist, None, wo, CONDUCTOR_TOLERANCE)[0]
}

/// The dielectric tables' entries at `μ` node `i`, `α` node `j` and `η` node `k`
/// ([`super::DIELECTRIC_MU_NODES`] × [`super::DIELECTRIC_ALPHA_NODES`] ×
/// [`super::ETA_NODES`]): `[E_out, R_out, E_in]`, the albedo of `RoughDielectric<D>` in
/// importance mode (reflection plus transmission) from the outside, the part of it that
/// reflects, and the albedo from the inside, at `|μ| = evaluation_mu(i)`,
/// `α = (j / (DIELECTRIC_ALPHA_NODES − 1))²` and `η = eta_node(k)`, integrated to
/// [`DIELECTRIC_TOLERANCE`] and rounded to `f32`. The row `α = 0` is the smooth
/// interface's: `E = 1` from either side and `R_out` the Fresnel reflectance.
#[must_use]
pub fn dielectric_entry(family: Family, i: usize, j: usize, k: usize) -> [f32; 3] {
    let alpha = super::alpha_node(j, super::DIELECTRIC_ALPHA_NODES);
    let mu = evaluation_mu(i, super::DIELECTRIC_MU_NODES);
    let Ok(eta) = Eta::new(super::eta_node(k)) else {
        return [1.0; 3];
    };
    let Ok(a) = Alpha::new(alpha) else {
        return [1.0, dielectric(mu, eta), 1.0];
    };
    let parts = match family {
        Family::Ggx => dielectric_albedo(&Ggx::isotropic(a), eta, mu),
        Family::Beckmann => dielectric_albedo(&Beckmann::isotropic(a), eta, mu),
    };
    parts.map(|v| (v as f32).clamp(0.0, 1.0))
}

/// `[E_out, R_out, E_in]` of the rough dielectric on `dist` at `|cos θo| = mu`.
fn dielectric_albedo<D: NormalDistribution + Copy>(dist: &D, eta: Eta, mu: f32) -> [f64; 3] {
    let model = RoughDielectric::new(*dist, eta).with_mode(TransportMode::Importance);
    let out = albedo(&model, dist, Some(eta), direction(mu), DIELECTRIC_TOLERANCE);
    let inside = albedo(
        &model,
        dist,
        Some(eta),
        direction(-mu),
        DIELECTRIC_TOLERANCE,
    );
    [out[0] + out[1], out[0], inside[0] + inside[1]]
}
