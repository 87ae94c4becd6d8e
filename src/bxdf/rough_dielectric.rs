//! Walter et al.'s rough dielectric: microfacet reflection and refraction.

use super::{At, BxdfSample, Lobes, Prepare, TransportMode, delta_scale, usable_pdf};
use crate::frame::{reflect_away, refract_away_lane};
use crate::fresnel::{dielectric, dielectric_refracted};
use crate::microfacet::{Masking, NormalDistribution, View};
use crate::param::Eta;
use glam::{Vec2, Vec3};

/// A rough interface between two dielectrics (glass, water): microfacet reflection and
/// transmission (Walter, Marschner, Li & Torrance 2007, "Microfacet Models for Refraction
/// through Rough Surfaces", eqs. 20–21):
///
/// ```text
/// f_r = F(wo·h) D(h) G2 / (4 |cos θo| |cos θi|),                 h ∝ wo + wi
/// f_t = |wi·h| |wo·h| (1 − F(wo·h)) D(h) G2 / (|cos θi| |cos θo| (wi·h + (wo·h)/η')²) / η'²
/// ```
///
/// with the generalised half vector `h ∝ η' wi + wo` for transmission, `η' = η` when `wo` is
/// outside and `1/η` inside, and `F` the exact dielectric Fresnel term. The final `1/η'²` is
/// the radiance scaling of refraction (Veach 1997, §5.2): it applies in
/// [`TransportMode::Radiance`] (the default) and not in [`TransportMode::Importance`].
///
/// `wo` may be on either side; `eta = η_inside / η_outside` with the normal pointing outside.
/// Total internal reflection is handled by the Fresnel term (it is 1 there).
///
/// Sampling: a normal from the distribution's own sampler (visible normals for GGX and Beckmann,
/// `D cos θ` for GTR and Blinn-Phong) for `wo` (or for `−wo` from the inside), then reflection with
/// probability `F(wo·m)` or refraction otherwise (Walter et al. 2007, §5.3); the density is the
/// normal's times the Jacobian of reflection, `1/(4 |wo·h|)`, or of refraction,
/// `|wi·h| / (wi·h + (wo·h)/η')²` (eqs. 14 and 17).
///
/// Laws (measured by `tests/bxdf_rough_dielectric.rs`): positive; reciprocal in the generalised
/// form `f(wo, wi)/η_o² = f(wi, wo)/η_i²` in radiance mode (largest relative error 4e-6, held below
/// 1e-5, over well-conditioned pairs at the law suite's η; below 1e-4, measured 6e-5, at η = 1e-3
/// and 1e3; the refraction's Fresnel term is computed from both cosines so that it is symmetric);
/// in importance mode the albedo is the fraction of flux scattered, at most 1, and single
/// scattering loses some with roughness: at `θo = 30°`, η = 1.5, 0.99994 (`α = 0.02`), 0.983 (0.3),
/// 0.854 (1).
///
/// **An index-matched interface** (`η = 1`, as two media of equal index give) is invisible:
/// the model passes light straight through, a delta transmission to `−wo` of all the light
/// ([`Lobes::SPECULAR_TRANSMISSION`]; `eval` and `pdf` are zero), as pbrt-v4 does — the
/// microfacet formulas have no answer there (every refraction goes to `−wo`, where the half
/// vector `wo + η' wi` is rounding noise; they lost 37% to 49% of the light). Within about
/// 1e-6 of 1 the formulas are ill-conditioned still, and lose more than their own limit:
/// importance albedo at `θo = 30°` for the `f32` just above 1 and just below, 0.874 and 0.652
/// at `α = 1` against 0.933 from `|η − 1| = 1e-5` on, 0.986 and 0.917 at `α = 0.3` against
/// 0.993, 1.000 at `α = 0.01` (measured by `tests/bxdf_rough_dielectric.rs`, which checks the
/// energy bound there; the limits by a run at `η = 1 ± 1e-5, 1e-4, 1e-3`, not in the tests).
///
/// With [`Masking::HeightCorrelated`] (the default) a transmitted pair gets the reflection
/// form `1/(1 + Λ(wo) + Λ(wi))`, as in pbrt-v4 and Mitsuba 3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughDielectric<D> {
    distribution: D,
    masking: Masking,
    eta: Eta,
    mode: TransportMode,
}

impl<D: NormalDistribution> RoughDielectric<D> {
    /// A rough interface of relative index `eta`, with height-correlated Smith masking and
    /// radiance transport.
    #[must_use]
    pub fn new(distribution: D, eta: Eta) -> Self {
        Self {
            distribution,
            masking: Masking::HeightCorrelated,
            eta,
            mode: TransportMode::Radiance,
        }
    }

    /// The same interface with the masking `masking`.
    #[must_use]
    pub fn with_masking(self, masking: Masking) -> Self {
        Self { masking, ..self }
    }

    /// The same interface for the transport mode `mode`.
    #[must_use]
    pub fn with_mode(self, mode: TransportMode) -> Self {
        Self { mode, ..self }
    }

    /// The relative index of refraction.
    #[inline(always)]
    #[must_use]
    pub fn eta(&self) -> Eta {
        self.eta
    }

    /// The distribution of microfacet normals.
    #[inline(always)]
    #[must_use]
    pub fn distribution(&self) -> &D {
        &self.distribution
    }

    /// The transport mode.
    #[inline(always)]
    #[must_use]
    pub fn mode(&self) -> TransportMode {
        self.mode
    }

    /// The relative index `η'` seen by a transmission from `wo`'s side.
    #[inline(always)]
    fn etap(&self, wo: Vec3) -> f32 {
        self.eta.seen_from(wo.z)
    }

    /// An index-matched interface (`η = 1`): invisible, light passes straight through, as
    /// pbrt-v4's dielectric does at `η = 1`. The microfacet formulas have no answer there:
    /// every refraction goes to `−wo`, where the half vector `wo + η' wi` is rounding noise.
    #[inline(always)]
    pub(crate) fn index_matched(&self) -> bool {
        self.eta.get() == 1.0
    }

    /// The pass-through sample of an index-matched interface: `−wo`, all of the light
    /// (`F = 0`, `η' = 1`), a delta lobe of probability 1.
    #[inline(always)]
    pub(crate) fn pass_through(wo: Vec3) -> Option<BxdfSample<f32>> {
        let wi = -wo;
        Some(BxdfSample {
            wi,
            f: delta_scale(wi)?,
            pdf: 1.0,
            lobe: Lobes::SPECULAR_TRANSMISSION,
            eta: 1.0,
        })
    }

    /// The microfacet configuration that connects `wo` and `wi`, or `None` when no single
    /// microfacet can.
    #[inline(always)]
    fn configuration(&self, wo: Vec3, wi: Vec3) -> Option<Configuration> {
        if self.refuses(wo, wi) {
            return None;
        }
        let reflection = wo.z * wi.z > 0.0;
        let etap = if reflection { 1.0 } else { self.etap(wo) };
        let (h, len2) = half_vector(wo, wi, etap);
        if !(len2 > 0.0) {
            return None;
        }
        if !sees_from_its_side(wo, wi, h) {
            return None;
        }
        Some(Configuration {
            h,
            reflection,
            etap,
            denom2: jacobian_denominator(len2, etap),
        })
    }

    /// [`configuration`](Self::configuration) without a branch: the configuration and whether
    /// it is usable (the same tests). An unusable pair gets a harmless stand-in (`h = z`,
    /// `denom2 = 1`) that the caller must discard; a usable one the same numbers. A loop over
    /// lanes then has no early return to turn into selects: with them, LLVM did not
    /// vectorise the batched `eval` and `sample` under AVX2 (measured 2026-11-29).
    #[inline(always)]
    fn configuration_of_lane(&self, wo: Vec3, wi: Vec3) -> (Configuration, bool) {
        let reflection = wo.z * wi.z > 0.0;
        let etap = if reflection { 1.0 } else { self.etap(wo) };
        let (h, len2) = half_vector(wo, wi, etap);
        let usable = !self.refuses(wo, wi) && len2 > 0.0 && sees_from_its_side(wo, wi, h);
        let c = Configuration {
            h: if usable { h } else { Vec3::Z },
            reflection,
            etap,
            denom2: if usable {
                jacobian_denominator(len2, etap)
            } else {
                1.0
            },
        };
        (c, usable)
    }

    /// Whether no microfacet connects the pair whatever its half vector: a pair whose product
    /// of cosines underflows (subnormal cos θ), where the value would be 0/0, and every pair
    /// of an index-matched interface, whose only lobe is the delta of `−wo`.
    #[inline(always)]
    fn refuses(&self, wo: Vec3, wi: Vec3) -> bool {
        (wo.z * wi.z).abs() < f32::MIN_POSITIVE || self.index_matched()
    }

    /// The Fresnel reflectance `F(wo·h)` of a configuration, which chooses between the lobes.
    #[inline(always)]
    fn fresnel(&self, wo: Vec3, c: &Configuration) -> f32 {
        dielectric(wo.dot(c.h), self.eta)
    }

    /// `f` for a configuration, with `d = D(h)` and `fresnel = F(wo·h)`, which only
    /// reflection uses, under `masking` (the model's; a parameter so that a batched loop can
    /// fix it, and its branch, outside the loop).
    #[inline(always)]
    fn value(
        &self,
        at: &At<View>,
        wi: Vec3,
        c: &Configuration,
        d: f32,
        fresnel: impl FnOnce() -> f32,
        masking: Masking,
    ) -> f32 {
        if d == 0.0 {
            return 0.0;
        }
        let wo = at.wo;
        // G2 / (4 |cos θo cos θi|).
        let v = masking.visibility(&self.distribution, &at.state, wi, c.h);
        if c.reflection {
            (fresnel() * d * v).min(f32::MAX)
        } else {
            // Fresnel from both cosines: symmetric in wo and wi, so f is reciprocal to
            // round-off even at the critical angle, where Snell's cos θt cancels.
            let (woh, wih) = (wo.dot(c.h), wi.dot(c.h));
            let f = dielectric_refracted(woh, wih, c.etap);
            let t = ((1.0 - f) * d * 4.0 * v * (wih * woh / c.denom2).abs()).min(f32::MAX);
            match self.mode {
                TransportMode::Radiance => t / (c.etap * c.etap),
                TransportMode::Importance => t,
            }
        }
    }

    /// The density of a configuration, with `d = D(h)` and `f = F(wo·h)`: the normal's
    /// density, the probability of the lobe and the Jacobian of reflection `1/(4 |wo·h|)` or
    /// of refraction `|wi·h| / (wi·h + (wo·h)/η')²` (Walter et al. 2007, eqs. 14 and 17).
    #[inline(always)]
    fn density(&self, at: &At<View>, wi: Vec3, c: &Configuration, d: f32, f: f32) -> f32 {
        let pdf_h = self.distribution.pdf(&at.state, c.h, d);
        if c.reflection {
            pdf_h * f / (4.0 * at.wo.dot(c.h).abs())
        } else {
            pdf_h * (1.0 - f) * wi.dot(c.h).abs() / c.denom2
        }
    }
}

/// The generalised half vector `h = ±s/|s|` (upper hemisphere) of `s = wo + η' wi`, and `|s|²`,
/// both from `s` in `f64`: for refraction the two nearly cancel around the straight-through
/// direction, and `|s|` sets both `h` and the Jacobian's denominator. `h` is of no use where
/// `|s|² = 0`.
#[inline(always)]
fn half_vector(wo: Vec3, wi: Vec3, etap: f32) -> (Vec3, f64) {
    let e = f64::from(etap);
    let s = [
        f64::from(wo.x) + e * f64::from(wi.x),
        f64::from(wo.y) + e * f64::from(wi.y),
        f64::from(wo.z) + e * f64::from(wi.z),
    ];
    let len2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    let scale = 1.0 / crate::math::sqrt_f64(len2) * if s[2] < 0.0 { -1.0 } else { 1.0 };
    let h = Vec3::new(
        (s[0] * scale) as f32,
        (s[1] * scale) as f32,
        (s[2] * scale) as f32,
    );
    (h, len2)
}

/// Whether each direction sees the microfacet `h` from its own side of the macro-surface.
#[inline(always)]
fn sees_from_its_side(wo: Vec3, wi: Vec3, h: Vec3) -> bool {
    !(wo.dot(h) * wo.z <= 0.0 || wi.dot(h) * wi.z <= 0.0)
}

/// The refraction Jacobian's denominator `(wi·h + (wo·h)/η')² = |s|²/η'²`, since `h ∥ s`: no
/// cancellation.
#[inline(always)]
fn jacobian_denominator(len2: f64, etap: f32) -> f32 {
    let e = f64::from(etap);
    (len2 / (e * e)) as f32
}

/// A sample's direction as [`RoughDielectric::draw`] forms it.
pub(crate) struct Drawn {
    /// The direction.
    pub(crate) wi: Vec3,
    /// Whether `uc` picked reflection.
    reflect: bool,
    /// Whether the refraction exists (no total internal reflection).
    refracts: bool,
}

impl Drawn {
    /// Whether the sample stands, given its direction's evaluation: a direction exists for
    /// the lobe picked, the pair is usable, and its configuration is the lobe picked.
    #[inline(always)]
    pub(crate) fn fits(&self, e: &Evaluated) -> bool {
        (self.reflect || self.refracts) && e.usable && e.reflection == self.reflect
    }
}

/// A direction evaluated by [`RoughDielectric::evaluate`].
pub(crate) struct Evaluated {
    /// The value `f(wo, wi)`.
    pub(crate) f: f32,
    /// The density of the interface's sampler.
    pub(crate) pdf: f32,
    /// The lobe: glossy reflection or transmission.
    pub(crate) lobe: Lobes,
    /// The relative index crossed (1 for reflection).
    pub(crate) eta: f32,
    /// Whether the pair is a reflection.
    reflection: bool,
    /// Whether the pair is usable (the numbers are a stand-in otherwise).
    pub(crate) usable: bool,
}

/// How a microfacet connects a pair of directions.
struct Configuration {
    /// The microfacet normal, upper hemisphere.
    h: Vec3,
    /// Reflection (both directions on one side) or refraction.
    reflection: bool,
    /// `η'`: `1` for reflection, the relative index seen from `wo`'s side for refraction.
    etap: f32,
    /// `(wi·h + (wo·h)/η')²`, the refraction Jacobian's denominator.
    denom2: f32,
}

impl<D: NormalDistribution> RoughDielectric<D> {
    /// [`Prepare::eval_prepared`] under `masking`.
    #[inline(always)]
    pub(crate) fn eval_with(&self, at: &At<View>, wi: Vec3, masking: Masking) -> f32 {
        // `match` rather than `map_or`: a closure is not always inlined.
        match self.configuration(at.wo, wi) {
            Some(c) => {
                let d = self.distribution.d(c.h);
                self.value(at, wi, &c, d, || self.fresnel(at.wo, &c), masking)
            }
            None => 0.0,
        }
    }

    /// [`eval_with`](Self::eval_with) for a batched loop, the same numbers: every lane
    /// computes a value and an unusable pair's is discarded, so that the loop has no branch
    /// to turn into selects ([`configuration_of_lane`](Self::configuration_of_lane)). A
    /// scalar call skips that work instead.
    #[inline(always)]
    pub(crate) fn eval_lane(&self, at: &At<View>, wi: Vec3, masking: Masking) -> f32 {
        let (c, usable) = self.configuration_of_lane(at.wo, wi);
        let d = self.distribution.d(c.h);
        let f = self.value(at, wi, &c, d, || self.fresnel(at.wo, &c), masking);
        if usable { f } else { 0.0 }
    }

    /// [`Prepare::eval_pdf_prepared`] under `masking`.
    #[inline(always)]
    pub(crate) fn eval_pdf_with(&self, at: &At<View>, wi: Vec3, masking: Masking) -> (f32, f32) {
        match self.configuration(at.wo, wi) {
            Some(c) => {
                let (d, f) = (self.distribution.d(c.h), self.fresnel(at.wo, &c));
                (
                    self.value(at, wi, &c, d, || f, masking),
                    self.density(at, wi, &c, d, f),
                )
            }
            None => (0.0, 0.0),
        }
    }

    /// The direction a sample draws (for an index-matched interface, a stand-in to discard:
    /// its sample is the delta of `−wo`, [`pass_through`](Self::pass_through)): a visible normal
    /// `m`, then reflection about it or refraction through it as `uc` picks, with probability
    /// `F(wo·m)`. Both directions are formed and one kept, without a branch.
    #[inline(always)]
    pub(crate) fn draw(&self, at: &At<View>, u: Vec2, uc: f32) -> Drawn {
        let wo = at.wo;
        let m = self.distribution.sample(&at.state, u);
        let reflect = crate::sampling::picks(uc, dielectric(wo.dot(m), self.eta));
        let (refracted, refracts) = refract_away_lane(wo, m, self.eta);
        let wi = if reflect {
            reflect_away(wo, m)
        } else {
            refracted
        };
        Drawn {
            wi,
            reflect,
            refracts,
        }
    }

    /// The value, density and lobe at `wi` (of the configuration of `(wo, wi)`, as `eval`
    /// and `pdf` compute them; D and F(wo·h) once, for both), under `masking`, without a
    /// branch: an unusable pair's numbers are a stand-in to discard.
    #[inline(always)]
    pub(crate) fn evaluate(&self, at: &At<View>, wi: Vec3, masking: Masking) -> Evaluated {
        let (c, usable) = self.configuration_of_lane(at.wo, wi);
        let (d, f_wo) = (self.distribution.d(c.h), self.fresnel(at.wo, &c));
        let pdf = self.density(at, wi, &c, d, f_wo);
        let f = self.value(at, wi, &c, d, || f_wo, masking);
        let (lobe, eta) = if c.reflection {
            (Lobes::GLOSSY_REFLECTION, 1.0)
        } else {
            (Lobes::GLOSSY_TRANSMISSION, c.etap)
        };
        Evaluated {
            f,
            pdf,
            lobe,
            eta,
            reflection: c.reflection,
            usable,
        }
    }

    /// [`Prepare::pdf_prepared`] for a batched loop, the same numbers, without a branch
    /// ([`eval_lane`](Self::eval_lane)).
    #[inline(always)]
    pub(crate) fn pdf_lane(&self, at: &At<View>, wi: Vec3) -> f32 {
        let (c, usable) = self.configuration_of_lane(at.wo, wi);
        let (d, f) = (self.distribution.d(c.h), self.fresnel(at.wo, &c));
        let pdf = self.density(at, wi, &c, d, f);
        if usable { pdf } else { 0.0 }
    }

    /// [`Prepare::sample_prepared`] under `masking`, without early returns but for the
    /// index-matched interface (the same for every lane of a batch), so that a batched loop
    /// has no branch to turn into selects: both directions are formed and the one `uc` picks
    /// is kept, and a refused sample is refused at the end. (A sample is seldom refused, so a
    /// scalar call does little work in vain: the refraction when it reflects.)
    #[inline(always)]
    pub(crate) fn sample_with(
        &self,
        at: &At<View>,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<f32>> {
        let wo = at.wo;
        if self.index_matched() {
            return if wo.z == 0.0 {
                None
            } else {
                Self::pass_through(wo)
            };
        }
        let drawn = self.draw(at, u, uc);
        // Evaluate at the configuration of (wo, wi), as `eval` and `pdf` do.
        let e = self.evaluate(at, drawn.wi, masking);
        let kept = wo.z != 0.0 && drawn.fits(&e) && usable_pdf(e.pdf);
        if kept {
            Some(BxdfSample {
                wi: drawn.wi,
                f: e.f,
                pdf: e.pdf,
                lobe: e.lobe,
                eta: e.eta,
            })
        } else {
            None
        }
    }

    /// The masking-shadowing term.
    #[inline(always)]
    #[must_use]
    pub fn masking(&self) -> Masking {
        self.masking
    }
}

impl<D: NormalDistribution> Prepare for RoughDielectric<D> {
    type Spectrum = f32;
    type Prepared = At<View>;

    /// `wo` and the distribution's view of it (of `−wo` from the inside).
    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At::view(&self.distribution, wo)
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        self.eval_with(at, wi, self.masking)
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        match self.configuration(at.wo, wi) {
            Some(c) => {
                let (d, f) = (self.distribution.d(c.h), self.fresnel(at.wo, &c));
                self.density(at, wi, &c, d, f)
            }
            None => 0.0,
        }
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (f32, f32) {
        self.eval_pdf_with(at, wi, self.masking)
    }

    #[inline(always)]
    fn sample_prepared(&self, at: &Self::Prepared, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        self.sample_with(at, u, uc, self.masking)
    }

    /// Glossy reflection and transmission; specular transmission only for an index-matched
    /// interface (`η = 1`).
    #[inline(always)]
    fn lobes(&self) -> Lobes {
        if self.index_matched() {
            Lobes::SPECULAR_TRANSMISSION
        } else {
            Lobes::GLOSSY_REFLECTION | Lobes::GLOSSY_TRANSMISSION
        }
    }
}
