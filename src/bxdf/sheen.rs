//! Estevez & Kulla's "Charlie" sheen: a microfacet model of cloth's grazing retroreflection.

use super::{At, BxdfSample, Lobes, Prepare, both_above, pdf_cosine, sample_cosine};
use crate::math::{exp, powf, safe_sqrt, sqrt};
use crate::microfacet::{catmull_rom, projected_area};
use crate::param::{ParamError, unit_interval};
use crate::spectrum::Spectrum;
use core::f32::consts::PI;
use glam::{Vec2, Vec3};

/// Entries of the albedo table, over `√(cos θ) ∈ [0, 1]`.
const TABLE: usize = 32;
/// Gauss-Legendre panels (8 nodes each) in `√(cos θi)` and in `φ` when integrating the
/// albedo at construction.
const T_PANELS: usize = 6;
const PHI_PANELS: usize = 4;
/// Nodes of the exact-Smith projected-area table, over `√(1 − √(cos θ)) ∈ [0, 1]`.
const SMITH: usize = 128;
/// The smallest accepted roughness.
const R_MIN: f32 = 0.01;

/// The fitted `L(x) = a / (1 + b x^c) + d x + e` of Estevez & Kulla 2017 (table 1) at `r = 0`
/// and `r = 1`: `(a, b, c, d, e)`.
const FIT_0: [f32; 5] = [25.3245, 3.32435, 0.16801, -1.27393, -4.85967];
const FIT_1: [f32; 5] = [21.5473, 3.82987, 0.19823, -1.97760, -4.32054];

/// Estevez & Kulla's microfacet sheen ("Charlie"; 2017, "Production Friendly Microfacet Sheen
/// BRDF", Sony Pictures Imageworks technical report; Kulla & Conty 2017, "Revisiting
/// Physically Based Shading at Imageworks", SIGGRAPH course): a layer of fibres whose normals
/// lie near the surface's plane,
///
/// ```text
/// f(wo, wi) = c · D(h) G(wo, wi) / (4 cos θo cos θi),      h = normalize(wo + wi)
/// D(h) = (2 + 1/r) sin^{1/r} θh / (2π)                       (eq. 2)
/// G = 1 / (1 + Λ(cos θo) + Λ(cos θi))                         (height-correlated Smith)
/// Λ(μ) = exp(L(μ))               μ < ½
///      = exp(2 L(½) − L(1 − μ))  μ ≥ ½                        (eq. 3)
/// L(x) = a / (1 + b x^c) + d x + e
/// ```
///
/// with `(a, b, c, d, e)` interpolated between the paper's fits at `r = 0` and `r = 1` by
/// `(1 − r)²` (table 1): a fit of the Smith `Λ` of this `D`, which has no closed form;
/// [`new_exact_smith`](Self::new_exact_smith) and [`with_exact_smith`](Self::with_exact_smith)
/// tabulate the exact one instead. `c` is the sheen's colour (`[0, 1]` per channel) and
/// `r ∈ [0.01, 1]` its roughness (the paper's `r`, used as is). No Fresnel term; the paper's
/// terminator softening of `Λ` is not applied (it acts on the light's direction only, which
/// would break reciprocity).
///
/// Sampling: cosine-weighted directions (the lobe is wide; the paper samples uniformly).
///
/// **Albedo.** The directional albedo `E(μo) = ∫ f cos θi dωi` (with `c = 1`) is tabulated at
/// construction (32 angles, evenly spaced in `√μo`, each integrated by Gauss-Legendre rules: about
/// 50 000 evaluations of `D`, 0.43 ms in a release build by `cargo bench --bench combinators` on
/// 2026-11-23, 0.91 ms on the machine of 2026-11-27) and returned by [`albedo`](Self::albedo), so
/// that a renderer can layer the sheen over a base energy-consistently, as OpenPBR and Imageworks
/// do: `f_sheen + (1 − c E(μo)) f_base`. The table's values (white, `c = 1`; checked against
/// 100 000-sample Monte Carlo at each angle by `tests/bxdf_sheen.rs`): the albedo is small head-on
/// and grows toward grazing — at `θo = 0°, 60°, 80°, 89°`: 0.164, 0.356, 0.614, 0.922 (`r = 1`);
/// 0.087, 0.281, 0.546, 0.856 (`r = 0.5`); 0.002, 0.096, 0.388, 0.847 (`r = 0.1`); and for smoother
/// sheens it exceeds 1 at grazing (1.18 at 89° for `r = 0.03`, 1.69 for `r = 0.01`; nearer grazing
/// up to 1.33 and 2.10). That gain is the fitted `Λ`'s: it is not the exact Smith `Λ` of this `D`.
/// For `r ≥ 0.1` the projected-area identity `∫ G1 ⟨w, m⟩ D dm = cos θ` holds within 5% up to 80°
/// (`tests/bxdf_sheen.rs`; right at grazing the fit drifts further, −9.5% at 89.9° for `r = 1`),
/// but below it the fit overestimates the projected area badly, at 60° by +12% (`r = 0.06`), +41%
/// (`r = 0.03`) and +120% (`r = 0.01`), so that `G` masks too little. With the exact `Λ`
/// ([`with_exact_smith`](Self::with_exact_smith), the identity then within 2e-5, measured 9.3e-6,
/// from 0° to 89° at `r` from 0.01 to 1) the albedo stays below 1 at every `r`, Fresnel factor or
/// not: at `θo = 60°, 80°, 89°` 0.000, 0.080, 0.689 (`r = 0.01`; an independent `f64` quadrature
/// gave 0.69 at 89°), 0.014, 0.213, 0.785 (`r = 0.03`), 0.096, 0.391, 0.857 (`r = 0.1`), 0.359,
/// 0.617, 0.918 (`r = 1`), and 0.995 to 0.999 (from `r = 0.01` to 1) as `μo → 0`, the table's first
/// entry (integrated at `μo = 1e-4`). The table matches Monte Carlo within 1.2% plus 1e-4 plus the
/// estimate's k standard errors over `θo ≤ 89°` (the largest gap measured, 0.9%, is at `r = 0.01`,
/// `θo = 89°`, where the estimate's standard error is 1.8%).
///
/// Laws: positive, reciprocal (`D` and `G` are symmetric, to round-off), sampler and pdf
/// agree; energy conserving for `r ≥ 0.1` (the table's albedo peaks at grazing incidence,
/// below 0.95: 0.941 for `r = 1`, 0.897 for `r = 0.1`), and not at grazing angles below about
/// `r = 0.067`, where the peak passes 1 (1.04 for `r = 0.06`; above). With the exact Smith
/// masking, energy conserving at every `r` (measured at `r = 0.01` and `0.03`).
///
/// **Cost.** Built by [`new_exact_smith`](Self::new_exact_smith), the exact masking costs its 129
/// projected-area integrals of construction more than `new`: 1.62–1.78 ms against 1.25–1.52 ms
/// (three runs of `cargo bench --bench combinators -- "Sheen construction"`, 2026-11-30, on a
/// slower machine than the figures above); `new(…)?.with_exact_smith()`, which integrates the
/// albedo table a second time, 3.07–3.58 ms in the same runs. Each `Λ` is then two square roots, a
/// cubic and a division, cheaper than the fit's powers, division and exponential: at `r = 0.5`
/// `eval` 30.3 ns against 35.4 and `sample` 37.8 against 49.1 (medians of three runs of
/// `cargo bench --bench combinators -- Sheen`, 2026-11-27; the repository's `docs/benchmarks.md`
/// has their ranges). The option's field makes every `Sheen` 130 floats larger (about 690 bytes in
/// all).
///
/// ```
/// use lobe::bxdf::{Bxdf, Sheen};
/// use lobe::Vec3;
/// let velvet = Sheen::new(Vec3::new(0.9, 0.2, 0.3), 0.5)?;
/// // Sheen is strongest at grazing angles, toward the light (retroreflection).
/// let grazing = Vec3::new(0.0, 0.98, 0.2);
/// assert!(velvet.eval(grazing, grazing).x > velvet.eval(Vec3::Z, Vec3::Z).x);
/// assert!(velvet.albedo(0.2).x > velvet.albedo(1.0).x);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sheen<S = f32> {
    color: S,
    /// `r`, as given.
    roughness: f32,
    /// The exponent `1/r` of `sin θh`.
    inv_r: f32,
    /// `(2 + 1/r) / (2π)`.
    d_scale: f32,
    /// `(a, b, c, d, e)` interpolated at `r`.
    fit: [f32; 5],
    /// `2 L(½)`, the constant of [`lambda`](Self::lambda)'s upper half (a `powf`: computed
    /// once here rather than at every call with `μ ≥ ½`).
    two_l_half: f32,
    /// `E(μ)` at `√μ = i / (TABLE − 1)`, for `c = 1`.
    albedo: [f32; TABLE],
    /// The projected area `A(μ) = μ / G1(μ)` at `√(1 − √μ) = j / (SMITH − 1)`, between one
    /// padding value at each end: the exact Smith masking, in place of the fit
    /// ([`with_exact_smith`](Self::with_exact_smith)).
    smith: Option<[f32; SMITH + 2]>,
}

impl<S: Spectrum> Sheen<S> {
    /// A sheen of colour `color ∈ [0, 1]` per channel and roughness `roughness ∈ [0.01, 1]`.
    ///
    /// # Errors
    /// [`ParamError`] naming `color` or `roughness` for NaN or out-of-range values.
    pub fn new(color: S, roughness: f32) -> Result<Self, ParamError> {
        Ok(Self::untabulated(color, roughness)?.tabulated())
    }

    /// The sheen of [`new`](Self::new) with the exact Smith masking, as
    /// [`with_exact_smith`](Self::with_exact_smith) makes it (the same value, field for field),
    /// with its albedo table integrated once: `new(…)?.with_exact_smith()` integrates it twice,
    /// first with the fitted masking.
    ///
    /// ```
    /// use lobe::bxdf::Sheen;
    /// use lobe::Vec3;
    /// let velvet = Sheen::new_exact_smith(Vec3::new(0.9, 0.2, 0.3), 0.03)?;
    /// assert!(velvet.has_exact_smith());
    /// // The exact masking keeps a smooth sheen's albedo below 1 at grazing (0.69 in the red
    /// // channel at cos θo = 0.02, where the fitted masking's is 1.03).
    /// assert!(velvet.albedo(0.02).max_element() < 1.0);
    /// assert!(Sheen::new(Vec3::new(0.9, 0.2, 0.3), 0.03)?.albedo(0.02).x > 1.0);
    /// # Ok::<(), lobe::ParamError>(())
    /// ```
    ///
    /// # Errors
    /// [`ParamError`] naming `color` or `roughness` for NaN or out-of-range values.
    pub fn new_exact_smith(color: S, roughness: f32) -> Result<Self, ParamError> {
        Ok(Self::untabulated(color, roughness)?
            .exact_area()
            .tabulated())
    }

    /// The sheen's parameters checked and its constants computed, with an empty albedo table.
    fn untabulated(color: S, roughness: f32) -> Result<Self, ParamError> {
        let color = unit_interval("color", color)?;
        if !(R_MIN..=1.0).contains(&roughness) {
            return Err(ParamError::new("roughness", roughness, "[0.01, 1]"));
        }
        let t = (1.0 - roughness) * (1.0 - roughness);
        let mut fit = [0.0; 5];
        for (k, p) in fit.iter_mut().enumerate() {
            *p = t * FIT_0[k] + (1.0 - t) * FIT_1[k];
        }
        let inv_r = 1.0 / roughness;
        let mut sheen = Self {
            color,
            roughness,
            inv_r,
            d_scale: (2.0 + inv_r) / (2.0 * PI),
            fit,
            two_l_half: 0.0,
            albedo: [0.0; TABLE],
            smith: None,
        };
        sheen.two_l_half = 2.0 * sheen.l(0.5);
        Ok(sheen)
    }

    /// The same sheen with the exact Smith masking of its `D` in place of Estevez & Kulla's
    /// fitted `Λ`, and the albedo table integrated again with it. The projected area
    /// `A(μ) = ∫ max(0, w·m) D(m) dωm` determines the Smith masking uniquely: `G1 = μ / A`,
    /// `Λ = A/μ − 1` (Heitz 2014, eq. 14). It is integrated as for
    /// [`Gtr`](crate::microfacet::Gtr)'s masking at 128 values of `s = √(1 − √μ)` evenly
    /// spaced in `[0, 1]` and interpolated by a Catmull-Rom cubic. `A` is smooth and positive
    /// from grazing (`A(0) > 0`, where `G1 ∝ μ` has no relative accuracy to spare) to the
    /// normal (`A(1) = 1`); `s ≈ θ/2` near the normal, where `A` changes over `θ ≈ √r` and is
    /// even in `s` (the padding mirrors the second node), and `1 − s ≈ √μ/2` near grazing
    /// (the padding is `A` continued past grazing: `μ = (1 − s²)²` is a polynomial in `s`).
    /// It conserves energy at every roughness, where the fit gains 69% at 89° for `r = 0.01`
    /// and up to 110% nearer grazing (see the type's docs).
    ///
    /// ```
    /// use lobe::bxdf::Sheen;
    /// let fitted = Sheen::new(1.0_f32, 0.01)?;
    /// let exact = fitted.with_exact_smith();
    /// assert!(exact.has_exact_smith() && !fitted.has_exact_smith());
    /// // Seen 89° from the normal, the fitted sheen reflects 1.7× what it receives.
    /// let grazing = 89.0_f32.to_radians().cos();
    /// assert!(fitted.albedo(grazing) > 1.6 && exact.albedo(grazing) < 0.7);
    /// # Ok::<(), lobe::ParamError>(())
    /// ```
    ///
    /// A sheen built to have the exact masking is better built by
    /// [`new_exact_smith`](Self::new_exact_smith), which integrates the albedo table once (the
    /// table of `new` is integrated here again: 3.07–3.58 ms against 1.62–1.78 in the runs of
    /// the type's **Cost** paragraph). On a sheen that already has it, this returns the sheen
    /// unchanged.
    #[must_use]
    pub fn with_exact_smith(self) -> Self {
        if self.smith.is_some() {
            return self;
        }
        self.exact_area().tabulated()
    }

    /// The same sheen with the exact Smith masking's projected-area table (its albedo table
    /// left as it was).
    fn exact_area(self) -> Self {
        let d = |_cos: f32, sin: f32| self.d_sin2(sin * sin);
        // Near grazing D ≈ e^(−cos²θm / 2r) changes over cos θm ≈ √r.
        let width = 1.0 / sqrt(self.roughness);
        // Node j at s = j / (SMITH − 1) is area[j + 1]; j = SMITH is the padding past grazing.
        let mut area = [0.0; SMITH + 2];
        for j in 0..=SMITH {
            // μ = (1 − s²)², and sin θ = s √((2 − s²)(1 + μ)) without the cancellation of
            // 1 − μ² near the normal.
            let s = j as f32 / (SMITH - 1) as f32;
            let root = 1.0 - s * s;
            let mu = root * root;
            let sin = s * sqrt((2.0 - s * s) * (1.0 + mu));
            area[j + 1] = projected_area(&d, mu, sin, width);
        }
        area[0] = area[2];
        Self {
            smith: Some(area),
            ..self
        }
    }

    /// Whether the masking is the exact Smith `G1` of `D` (else the fit).
    #[inline]
    #[must_use]
    pub fn has_exact_smith(&self) -> bool {
        self.smith.is_some()
    }

    /// The same sheen with its albedo table integrated under its current masking.
    fn tabulated(mut self) -> Self {
        for i in 0..TABLE {
            let t = i as f32 / (TABLE - 1) as f32;
            self.albedo[i] = self.white_albedo((t * t).max(1e-4));
        }
        self
    }

    /// `L(x)` of the fit.
    #[inline(always)]
    fn l(&self, x: f32) -> f32 {
        let [a, b, c, d, e] = self.fit;
        a / (1.0 + b * powf(x, c)) + d * x + e
    }

    /// Smith's `Λ(μ)` for `μ = |cos θ|`: by the fit (eq. 3), or exact after
    /// [`new_exact_smith`](Self::new_exact_smith) or [`with_exact_smith`](Self::with_exact_smith);
    /// at most `f32::MAX`.
    #[inline(always)]
    #[must_use]
    pub fn lambda(&self, cos_theta: f32) -> f32 {
        let mu = cos_theta.abs().min(1.0);
        if let Some(area) = &self.smith {
            // Λ = A/μ − 1 ≥ 0 (G1 ≤ 1); +∞ at μ = 0, capped.
            let a = catmull_rom(area, sqrt(1.0 - sqrt(mu)) * (SMITH - 1) as f32);
            return (a / mu - 1.0).clamp(0.0, f32::MAX);
        }
        let l = if mu < 0.5 {
            self.l(mu)
        } else {
            self.two_l_half - self.l(1.0 - mu)
        };
        exp(l).min(f32::MAX)
    }

    /// The distribution of fibre normals, `D(h) = (2 + 1/r) sin^{1/r} θh / (2π)`
    /// (Estevez & Kulla 2017, eq. 2), for a unit `h`.
    #[inline(always)]
    #[must_use]
    pub fn d(&self, h: Vec3) -> f32 {
        self.d_sin2((1.0 - h.z * h.z).max(0.0))
    }

    /// `D` from `sin² θh`.
    #[inline(always)]
    fn d_sin2(&self, sin2: f32) -> f32 {
        self.d_scale * powf(sin2, 0.5 * self.inv_r)
    }

    /// `D` at the direction of `s ≠ 0` (any multiple of the normal), from `|s|² = len2`:
    /// `sin² θh = (sx² + sy²)/|s|²`, without normalising `s`.
    #[inline(always)]
    fn d_along(&self, s: Vec3, len2: f32) -> f32 {
        self.d_sin2(((s.x * s.x + s.y * s.y) / len2).min(1.0))
    }

    /// `f / c` for `wo`, `wi` above the surface with `Λ(cos θo) = lambda_o`.
    #[inline(always)]
    fn value(&self, wo: Vec3, lambda_o: f32, wi: Vec3) -> f32 {
        let s = wo + wi;
        let len2 = s.length_squared();
        let cos2 = wo.z * wi.z;
        if !(len2 > 0.0 && cos2 > 0.0) {
            return 0.0;
        }
        let g = 1.0 / (1.0 + lambda_o + self.lambda(wi.z));
        (self.d_along(s, len2) * g / (4.0 * cos2)).min(f32::MAX)
    }

    /// The white sheen's albedo at `cos θo = mu`: `∫ f cos θi dωi` by the product of
    /// 8-point Gauss-Legendre rules on panels, in `t = √(cos θi)` (which gathers the nodes
    /// toward grazing, where the lobe of a smooth sheen is) and in `φ` over `[0, π]` (the
    /// integrand is symmetric about `wo`'s plane).
    fn white_albedo(&self, mu: f32) -> f32 {
        let wo = Vec3::new(safe_sqrt(1.0 - mu * mu), 0.0, mu);
        let lambda_o = self.lambda(mu);
        let panels = |n: usize, a: f32, b: f32, g: &dyn Fn(f32) -> f32| -> f32 {
            (0..n)
                .map(|k| {
                    let (lo, hi) = (
                        a + (b - a) * k as f32 / n as f32,
                        a + (b - a) * (k + 1) as f32 / n as f32,
                    );
                    crate::math::gauss_legendre(lo, hi, g)
                })
                .sum()
        };
        // ∫₀¹ ∫₀^2π f μi dφ dμi with μi = t², dμi = 2t dt.
        // f μi = D(h) G / (4 μo), with G fixed along each ring of constant μi.
        2.0 * panels(T_PANELS, 0.0, 1.0, &|t| {
            let mu_i = t * t;
            let sin_i = safe_sqrt(1.0 - mu_i * mu_i);
            let g = 1.0 / (1.0 + lambda_o + self.lambda(mu_i));
            let ring = panels(PHI_PANELS, 0.0, PI, &|phi| {
                let (s, c) = crate::math::sin_cos(phi);
                let h = wo + Vec3::new(sin_i * c, sin_i * s, mu_i);
                let len2 = h.length_squared();
                if len2 > 0.0 {
                    self.d_along(h, len2)
                } else {
                    0.0
                }
            });
            ring * g / (4.0 * mu) * 2.0 * t
        })
    }

    /// The table's abscissa of `cos θ`: `√(cos θ)`, scaled to the entries.
    #[inline(always)]
    fn table_x(cos_theta: f32) -> f32 {
        safe_sqrt(cos_theta.clamp(0.0, 1.0)) * (TABLE - 1) as f32
    }

    getters! {
        /// The sheen's colour `c`.
        color: S,
        /// The roughness `r`, as given to [`new`](Self::new).
        roughness: f32,
    }

    /// The directional albedo `c E(cos θo)` from the table (linear interpolation), for
    /// layering the sheen over a base (see the type's docs); zero for a viewer below or on
    /// the surface (`cos θo ≤ 0`, or NaN), where the sheen reflects nothing.
    #[must_use]
    pub fn albedo(&self, cos_theta: f32) -> S {
        if !(cos_theta > 0.0) {
            return S::zero();
        }
        let x = Self::table_x(cos_theta);
        let i = (x as usize).min(TABLE - 2);
        let t = x - i as f32;
        let e = self.albedo[i] + t * (self.albedo[i + 1] - self.albedo[i]);
        self.color * e
    }
}

impl<S: Spectrum> Prepare for Sheen<S> {
    type Spectrum = S;
    /// `wo` and `Λ(cos θo)`.
    type Prepared = At<f32>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At {
            wo,
            state: self.lambda(wo.z),
        }
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> S {
        if both_above(at.wo, wi) {
            self.color * self.value(at.wo, at.state, wi)
        } else {
            S::zero()
        }
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        pdf_cosine(at.wo, wi)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, _uc: f32) -> Option<BxdfSample<S>> {
        sample_cosine(at.wo, u, |wi| self.color * self.value(at.wo, at.state, wi)).map(|s| {
            BxdfSample {
                lobe: Lobes::GLOSSY_REFLECTION,
                ..s
            }
        })
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::GLOSSY_REFLECTION
    }
}
