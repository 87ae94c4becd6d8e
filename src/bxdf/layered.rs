//! The stochastic layered BSDF: a dielectric interface over a base, evaluated by a random walk
//! between them.

use super::henyey_greenstein::HenyeyGreenstein;
use super::walk_rng::{Hasher, WalkRng};
use super::{At, Bxdf, BxdfSample, LayerInterface, Lobes, Prepare, TransportMode, usable_pdf};
use crate::frame::refract_away;
use crate::fresnel::dielectric;
use crate::param::{ParamError, unit_interval};
use crate::sampling::power_heuristic;
use crate::spectrum::Spectrum;
use glam::{Vec2, Vec3};

/// The default thickness of the layer between the interfaces, in mean free paths (pbrt-v4's).
pub(crate) const DEFAULT_THICKNESS: f32 = 0.01;
/// The default number of events a walk may have (interface hits and medium scatterings).
pub(crate) const DEFAULT_MAX_DEPTH: u32 = 64;
/// The largest accepted thickness.
const MAX_THICKNESS: f32 = 1e3;
/// The largest accepted maximum depth and sample count.
const MAX_COUNT: u32 = 4096;
/// The largest accepted `|g|` of the medium's phase function.
const MAX_G: f32 = 0.99;
/// Tags that keep the generators of `eval`, `pdf` and `sample` apart.
const TAG_EVAL: u64 = 0x6576_616c;
const TAG_PDF: u64 = 0x0070_6466;
const TAG_SAMPLE: u64 = 0x7361_6d70;

/// A stochastic layered BSDF: a dielectric interface `T` (the coat) over a base `B` (any
/// reflecting [`Bxdf`]), with an optional homogeneous medium between them, evaluated by the
/// position-free Monte Carlo random walk of Guo, Hašan & Zhao (2018, "Position-Free Monte
/// Carlo Simulation for Arbitrary Layered BSDFs", ACM TOG 37(6)) in the form of pbrt-v4's
/// `LayeredBxDF` (Pharr, Jakob & Humphreys, *PBR* 4th ed., §14.3). [`CoatedDiffuse`](super::CoatedDiffuse)
/// (a rough dielectric over Lambert) and [`CoatedConductor`](super::CoatedConductor) (a rough
/// dielectric over a rough conductor) are its named instances.
///
/// **The BSDF.** Light enters through the top, scatters between the base and the underside of
/// the top (and, with a medium, inside the layer), and leaves through the top; a direction's
/// value is the sum over paths of the products of the interfaces' BSDFs:
///
/// ```text
/// f(wo, wi) = f_t(wo, wi)
///           + ∫∫ f_t(wo, d₁) |cos d₁| Tr(d₁) f_b(−d₁, d₂) |cos d₂| Tr(d₂) f_t(−d₂, wi) dd₁ dd₂ + …
/// Tr(w) = exp(−thickness / |cos θ_w|)
/// ```
///
/// (Guo et al. 2018, eq. 5; *PBR* eq. 14.8), `f_t` the top interface, `f_b` the base, `d`
/// the directions inside the layer. A one-sided BRDF: zero unless `wo` and `wi` are both
/// above the surface (wrap it in [`TwoSided`](super::TwoSided) for both sides). Light the
/// base transmits, if it does, leaves the stack and is not followed.
///
/// **Transport.** The walk enters with the top in radiance mode (its `1/η²` on the way in)
/// and leaves with `η²` on the way out, so the two cancel and the value is the same for
/// radiance and importance transport: the model has no transport mode. Where `eval` samples
/// the top from the light's side (`wi`), it uses the adjoint interface
/// ([`LayerInterface::for_transport`]`(Importance)`), whose value is the one the path needs.
///
/// **Estimators.** [`Bxdf::eval`] is pbrt-v4's: `samples` walks from `wo` (each entering by
/// a sample of the top), each connected to the exit at every event through a direction
/// sampled from the top at `wi` (next-event estimation) and through the event's own sampled
/// direction, combined by the power heuristic with the densities of the two strategies over
/// the same internal direction (pbrt-v4 weighs the second strategy with the top's density of
/// `wi` given that direction, not the density with which the first draws the direction from
/// `wi`, so its two weights need not sum to one; here they do, and the estimator is unbiased),
/// Russian roulette after four events once the throughput is below ¼. [`Bxdf::sample`] walks
/// from `wo` until the path leaves through the top (pbrt-v4's `Sample_f`, without its Russian
/// roulette, which would make the density depend on the spectrum): the sample's
/// [`weight`](BxdfSample::weight) is the path's unbiased weight, its `pdf` an independent estimate
/// of the density at its direction (what `pdf` computes, `samples` walks more: a renderer weighs it
/// by MIS as it would an exact model's; pbrt-v4 returns the path's density and flags it), its `f`
/// the value that keeps the weight. [`Bxdf::pdf`]
/// is an unbiased estimate of the density of [`Bxdf::sample`]'s directions — not pbrt-v4's
/// approximation, which mixes in a uniform density: the same walk as the sampler, summing at
/// each hit of the top from inside the density of leaving there toward `wi` (a rough top),
/// or at each event the density of the direction that refracts into `wi` times the chance of
/// reaching and crossing the top and the refraction's Jacobian `cos θi / (η² cos θt)` (a
/// smooth top); its walk enters a smooth top along the refracted direction, weighted by the
/// chance `1 − F(wo)` of crossing, instead of drawing the crossing (an estimate that drew it
/// would be zero whenever the top reflected, and a sample's `pdf` must be positive). Walks
/// stop after `max_depth` events; `eval` and `pdf` count the same paths as `sample`.
///
/// **A smooth top over a base with a delta lobe** (a mirror, a `Mix` with one, a `Glazed`):
/// under a smooth top, the exit toward `wi` is reached along one internal direction `d`, so
/// `eval` and `pdf` connect each non-delta event to it; between that event and the exit the
/// light may also make round trips — reflected down by the top's underside, back up along `d`
/// by the base's mirror — and, from a scattering in the medium, go down to the mirror first.
/// The connections count these delta chains too, as a sum over the number of round trips
/// (within `max_depth`), each trip taken with the probability `F` that the top reflects and
/// the base's delta reflectance drawn by its own sampler, as the sampler's walk would. A
/// delta bounce of the base that sends the light anywhere but back along the mirror image of
/// its arrival (none of the crate's models does) cannot be connected to: `eval` and `pdf`
/// leave it out and `sample` drops those paths, so that the three describe one BSDF. Before the chains (and in pbrt-v4's
/// `LayeredBxDF`, whose `f` and `PDF` stop at the last non-delta event) this light was lost:
/// 4% of a smooth coat (η 1.5) over `Mix(Mirror, Lambert 0.8)` at normal incidence (0.267
/// where 0.278 leaves), 38% over a mirror under a scattering layer (albedo 0.9, thickness 0.5;
/// 0.227 for 0.366 at 45°). `tests/layered_reference.rs` compares both, by the model's
/// sampler and by its `eval`, with a walk that follows every bounce; `tests/bxdf_layered.rs`
/// checks them against every law.
///
/// **Determinism and variance.** Each estimate draws from a PCG32 generator seeded with a
/// hash of its arguments, so `eval(wo, wi)` repeats itself exactly (a reciprocity pair is
/// reproducible) and [`Bxdf::eval_seeded`] gives independent estimates (`eval` is seed 0).
/// The estimates' standard deviation falls as `1/√samples`. Measured by
/// `tests/bxdf_layered.rs` at `θo = θi = 30°`, 90° apart in azimuth, with one walk per
/// estimate (the default): relative standard deviation of `eval` 0.70 and of `pdf` 0.80 for
/// a `CoatedDiffuse` (GGX `α = 0.3`, `η = 1.5`, `ρ = 0.8`), 0.64 and 0.81 for a
/// `CoatedConductor` (coat `α = 0.1`, copper `α = 0.3`); with four walks, half of each. A
/// renderer averages it over the pixel like any other noise; the expectation is what the
/// laws speak of.
///
/// **Cost** (`benches/combinators.rs`, RGB, one walk; the run in the repository's
/// `docs/benchmarks.md`): `eval` 0.48 µs, `pdf` 0.50 µs, `sample` 0.79 µs for the `CoatedDiffuse`
/// above, 0.60, 0.66 and 1.04 µs for a `CoatedConductor` of gold (coat `α = 0.1`, gold `α = 0.3`);
/// `eval` and `pdf` cost about `n` times as much with `n` walks (3.5× with four), `sample` less
/// (2.5×), whose path is one walk whatever `n`. The delta chains cost a smooth coat (η 1.5) over
/// `Mix(Mirror, Lambert)` 1.20×, 1.54× and 1.13× what its walks cost without them (0.15, 0.23 and
/// 0.22 µs with them), over a mirror under a scattering layer 1.41×, 1.58× and 1.47× (the
/// repository's `docs/benchmarks.md`, the combinators). A chain goes on with the probability `F`
/// that the coat's underside reflects, whatever the path's weight: under a coat that reflects
/// nearly everything from inside (η 1e3), a connection makes up to `max_depth / 2` round trips, and
/// a walk costs up to `max_depth²/2` draws of the base.
///
/// **Laws** (measured by `tests/bxdf_layered.rs` and `tests/layered_reference.rs`, in
/// expectation: [`verify::check_bxdf`](crate::verify::check_bxdf) checks a
/// [`stochastic`](Bxdf::stochastic) model by averaging independent estimates): positive,
/// reciprocal in expectation, the sampled and cosine-estimated albedos agree, the sampler
/// draws the expected density (chi-square), the sampled weight equals `eval`'s value in
/// expectation; the albedo and the value agree with an independent brute-force walk. A smooth
/// coat over a white Lambertian base with no absorption reflects everything (white furnace:
/// every sample's weight is 1, the albedo 1 within 2e-7 at `η` from 0.7 to 2.5), and over a
/// base of reflectance `ρ` its albedo is the closed form with internal reflection
/// `F + (1 − F)(1 − F̄ᵢ) ρ / (1 − ρ F̄ᵢ)` (within the standard error, ~6e-4); `Glazed`, which
/// leaves the internal reflection out, is brighter (`η = 1.5`, `ρ = 0.8`, normal incidence:
/// 0.808 against 0.633). A rough coat loses, each time the light meets it, what its
/// single-scattering microfacet interface loses (a [`RoughDielectric`](super::RoughDielectric) of
/// `η = 1.5` seen from inside loses 5–16% at `α = 0.2` and 25–35% at `α = 0.5` at
/// `θ = 0°, 40°, 70°, 85°`, measured by `tests/energy_compensation.rs`), so the white furnace
/// measures 0.99997 (`α = 0.001`), 0.975 (`α = 0.05`) and 0.70 (`α = 0.3`) at `η = 1.5`: a property
/// of the coat, not of the walk (the brute-force walk measures the same). With the
/// energy-compensated interface as the coat
/// ([`RoughDielectric::with_energy_compensation`](super::RoughDielectric::with_energy_compensation),
/// a [`CompensatedDielectric`](super::CompensatedDielectric) top) the loss is put back: the
/// furnace measures 0.9905 to 1.0027 (± 0.004) for `α` 0.05 to 0.6 and `η` 1.33 and 1.5,
/// where the plain coat keeps 0.46 to 0.98. Figures are in the tests and the README's
/// conformance matrix.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert, Layered, RoughDielectric};
/// use lobe::microfacet::Ggx;
/// use lobe::{Alpha, Eta};
/// // A rough coat that keeps the energy its microfacets scatter more than once.
/// let coat = RoughDielectric::new(Ggx::isotropic(Alpha::new(0.5)?), Eta::new(1.5)?)
///     .with_energy_compensation()?;
/// let lacquer = Layered::new(coat, Lambert::new(0.8_f32)?);
/// assert!(lacquer.stochastic());
/// # Ok::<(), lobe::ParamError>(())
/// ```
///
/// ```
/// use lobe::bxdf::{Bxdf, CoatedDiffuse};
/// use lobe::microfacet::Ggx;
/// use lobe::{Alpha, Eta, Vec3};
/// let coated = CoatedDiffuse::coated_diffuse(0.8_f32, Ggx::isotropic(Alpha::new(0.3)?), Eta::new(1.5)?)?;
/// let (wo, wi) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.6, 0.0, 0.8));
/// assert!(coated.stochastic());
/// // Deterministic for given inputs; independent estimates through the seed.
/// assert_eq!(coated.eval(wo, wi), coated.eval(wo, wi));
/// let mean: f32 = (0..256).map(|s| coated.eval_seeded(wo, wi, s)).sum::<f32>() / 256.0;
/// assert!(mean > 0.1 && mean < 0.3, "{mean}");
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layered<T, B: Bxdf> {
    /// The top interface, in radiance mode.
    top: T,
    /// The top interface in importance mode, for the directions sampled from `wi`.
    top_adjoint: T,
    bottom: B,
    thickness: f32,
    /// The medium's single-scattering albedo; zero for a purely absorbing layer.
    albedo: B::Spectrum,
    /// Whether the medium scatters (`albedo` not black).
    scattering: bool,
    phase: HenyeyGreenstein,
    g: f32,
    max_depth: u32,
    samples: u32,
}

/// The state of one random walk between the interfaces.
struct Walk {
    /// Height in the layer: `0` at the base, `thickness` at the top.
    z: f32,
    /// The direction of travel.
    w: Vec3,
    /// After [`Layered::advance`] reached an interface: whether it is the top (the heights
    /// cannot tell when the layer has no thickness).
    at_top: bool,
}

/// `exp(−|dz / cos θ|)`: the transmittance of a slab of `dz` mean free paths along `w`
/// (pbrt-v4 `Tr`), `1` for no slab.
#[inline(always)]
fn tr(dz: f32, w: Vec3) -> f32 {
    if dz.abs() <= f32::MIN_POSITIVE {
        1.0
    } else {
        crate::math::exp(-(dz / w.z).abs())
    }
}

/// A usable sample of a part: finite positive density, finite value, a direction off the
/// horizon.
#[inline(always)]
fn usable<S: Spectrum>(s: &BxdfSample<S>) -> bool {
    s.pdf > 0.0 && s.pdf.is_finite() && s.f.is_finite() && s.wi.z != 0.0
}

/// `s.f |cos θi| / s.pdf`, the sample's weight.
#[inline(always)]
fn weight<S: Spectrum>(s: &BxdfSample<S>) -> S {
    s.f * (s.wi.z.abs() / s.pdf)
}

/// How far, in squared length, a base's delta reflection may fall from the exact mirror image
/// and still count as one (the crate's mirrors compute it exactly).
const RETRACE_TOLERANCE: f32 = 1e-12;

/// Whether the base's sample `s`, for light travelling down along `down`, is a delta
/// reflection back up along the mirror image `(dx, dy, −dz)`: the bounce through which a
/// connection under a smooth top reaches the exit (every delta reflection of the crate's
/// models is one; a base whose delta lobe sends light elsewhere is not followed there, by
/// `eval`, `pdf` and `sample` alike).
#[inline(always)]
fn retraces<S: Spectrum>(down: Vec3, s: &BxdfSample<S>) -> bool {
    let mirror = Vec3::new(down.x, down.y, -down.z);
    s.is_specular() && (s.wi - mirror).length_squared() <= RETRACE_TOLERANCE
}

/// What the delta chains toward one exit need, the same for a whole walk: for the internal
/// direction `up` that leaves toward `wi`, its mirror image `down`, the top's reflectance `f`
/// from inside along `up`, the slab's transmittance `t` along it (a weight) and the chance
/// `reach` of crossing the slab along it without scattering (a probability).
#[derive(Clone, Copy)]
struct ChainExit {
    down: Vec3,
    f: f32,
    t: f32,
    reach: f32,
}

/// The kinds (diffuse, glossy, specular) of a set of lobes.
#[inline(always)]
fn kinds(l: Lobes) -> Lobes {
    let mut k = Lobes::NONE;
    for kind in [Lobes::DIFFUSE, Lobes::GLOSSY, Lobes::SPECULAR] {
        if l.intersects(kind) {
            k |= kind;
        }
    }
    k
}

impl<T: LayerInterface, B: Bxdf> Layered<T, B> {
    /// The top interface `top` (any transport mode: the model uses both) over the base
    /// `bottom`, with pbrt-v4's defaults for the layer and the estimates (a purely absorbing
    /// layer `0.01` mean free paths thick, one walk per estimate) and walks of at most 64
    /// events, where pbrt-v4 stops at 10: with a white base under a smooth coat of `η = 1.5`,
    /// 10 events lose about `0.6⁵ ≈ 8%` of the light, 64 about `0.6³² ≈ 1e-7`
    /// ([`with_max_depth`](Self::with_max_depth)).
    #[must_use]
    pub fn new(top: T, bottom: B) -> Self {
        Self {
            top_adjoint: top.for_transport(TransportMode::Importance),
            top: top.for_transport(TransportMode::Radiance),
            bottom,
            thickness: DEFAULT_THICKNESS,
            albedo: B::Spectrum::zero(),
            scattering: false,
            phase: HenyeyGreenstein::new(0.0),
            g: 0.0,
            max_depth: DEFAULT_MAX_DEPTH,
            samples: 1,
        }
    }

    /// The same stack with a layer `thickness` mean free paths thick (`0`: no layer).
    ///
    /// # Errors
    /// [`ParamError`] naming `thickness` for NaN or a value outside `[0, 1000]`.
    pub fn with_thickness(self, thickness: f32) -> Result<Self, ParamError> {
        if !(0.0..=MAX_THICKNESS).contains(&thickness) {
            return Err(ParamError::new("thickness", thickness, "[0, 1000]"));
        }
        Ok(Self { thickness, ..self })
    }

    /// The same stack with a homogeneous scattering medium in the layer: single-scattering
    /// albedo `albedo ∈ [0, 1]` per channel and a Henyey-Greenstein phase function of
    /// asymmetry `g ∈ [−0.99, 0.99]`. A black albedo is a purely absorbing layer.
    ///
    /// # Errors
    /// [`ParamError`] naming `albedo` or `g` for NaN or out-of-range values.
    pub fn with_medium(self, albedo: B::Spectrum, g: f32) -> Result<Self, ParamError> {
        let albedo = unit_interval("albedo", albedo)?;
        if !(-MAX_G..=MAX_G).contains(&g) {
            return Err(ParamError::new("g", g, "[-0.99, 0.99]"));
        }
        Ok(Self {
            albedo,
            scattering: !albedo.is_black(),
            phase: HenyeyGreenstein::new(g),
            g,
            ..self
        })
    }

    /// The same stack with walks of at most `max_depth` events (interface hits and medium
    /// scatterings). Longer paths are lost: with a white base under a smooth coat of
    /// `η = 1.5`, about `0.6^(max_depth/2)` of the light.
    ///
    /// # Errors
    /// [`ParamError`] naming `max_depth` outside `[1, 4096]`.
    pub fn with_max_depth(self, max_depth: u32) -> Result<Self, ParamError> {
        if !(1..=MAX_COUNT).contains(&max_depth) {
            return Err(ParamError::new("max_depth", max_depth as f32, "[1, 4096]"));
        }
        Ok(Self { max_depth, ..self })
    }

    /// The same stack averaging `samples` walks per `eval` and `pdf` (variance `∝ 1/samples`,
    /// cost `∝ samples`).
    ///
    /// # Errors
    /// [`ParamError`] naming `samples` outside `[1, 4096]`.
    pub fn with_samples(self, samples: u32) -> Result<Self, ParamError> {
        if !(1..=MAX_COUNT).contains(&samples) {
            return Err(ParamError::new("samples", samples as f32, "[1, 4096]"));
        }
        Ok(Self { samples, ..self })
    }

    /// The top interface (radiance mode).
    #[must_use]
    pub fn top(&self) -> &T {
        &self.top
    }

    /// The base.
    #[must_use]
    pub fn bottom(&self) -> &B {
        &self.bottom
    }

    /// The layer's thickness in mean free paths.
    #[must_use]
    pub fn thickness(&self) -> f32 {
        self.thickness
    }

    /// The medium's single-scattering albedo and phase asymmetry `g` (black: no scattering).
    #[must_use]
    pub fn medium(&self) -> (B::Spectrum, f32) {
        (self.albedo, self.g)
    }

    /// The largest number of events of a walk.
    #[must_use]
    pub fn max_depth(&self) -> u32 {
        self.max_depth
    }

    /// Walks per `eval` and `pdf`.
    #[must_use]
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// True when the top has delta lobes only (a smooth coat).
    #[inline(always)]
    fn smooth_top(&self) -> bool {
        !Prepare::lobes(&self.top).is_non_specular()
    }

    /// Moves the walk to its next event: a scattering inside the medium (`true`, with the
    /// walk at the scattering height) or the interface it reaches (`false`, the walk at `0`
    /// or `thickness`). Without scattering the walk reaches the other interface and `beta`
    /// takes the slab's transmittance.
    #[inline(always)]
    fn advance(&self, walk: &mut Walk, beta: &mut B::Spectrum, rng: &mut WalkRng) -> bool {
        if self.scattering {
            // A distance with density exp(−t) along w: dz = t |cos θ|.
            let u = rng.next_f32();
            let dz = -crate::math::ln_1p(-u) * walk.w.z.abs();
            let zp = if walk.w.z > 0.0 {
                walk.z + dz
            } else {
                walk.z - dz
            };
            if zp > 0.0 && zp < self.thickness {
                walk.z = zp;
                return true;
            }
        } else {
            *beta *= tr(self.thickness, walk.w);
        }
        walk.at_top = walk.w.z > 0.0;
        walk.z = if walk.at_top { self.thickness } else { 0.0 };
        false
    }

    /// The probability that a walk leaving height `z` along `w` (upward) reaches the top
    /// without scattering: `Tr` with a scattering medium, 1 without (the walk then always
    /// reaches it, the slab's absorption being a weight).
    #[inline(always)]
    fn reach_top(&self, z: f32, w: Vec3) -> f32 {
        if self.scattering {
            tr(self.thickness - z, w)
        } else {
            1.0
        }
    }

    /// The slab's transmittance from height `z` to the top along `w`, as a weight: what a
    /// connection to the exit is multiplied by.
    #[inline(always)]
    fn to_top(&self, z: f32, w: Vec3) -> f32 {
        tr(self.thickness - z, w)
    }

    /// The density that a smooth top turns the internal direction `w_star` (upward) into
    /// `wi`: `(1 − F) cos θi / (η² cos θ*)`, the probability of refracting times the
    /// refraction's Jacobian `dω*/dωi` (*PBR* eq. 9.7 inverted).
    #[inline(always)]
    fn smooth_exit_density(&self, w_star: Vec3, wi: Vec3) -> f32 {
        let eta = self.top.eta();
        let down = -w_star;
        let t = 1.0 - dielectric(down.z, eta);
        let e = eta.get();
        (t * wi.z.abs() / (e * e * w_star.z.abs())).max(0.0)
    }

    /// True when connections go through delta chains: a smooth top over a base with a delta
    /// reflection lobe.
    #[inline(always)]
    fn chains(&self) -> bool {
        self.smooth_top() && self.bottom.lobes().contains(Lobes::SPECULAR_REFLECTION)
    }

    /// How many round trips (the top's internal reflection, then the base's delta reflection)
    /// a path may add before it leaves through the top at event `exit` and stay within the
    /// depth: each adds two events.
    #[inline(always)]
    fn round_trips(&self, exit: u32) -> u32 {
        self.max_depth.saturating_sub(exit + 1) / 2
    }

    /// The base's delta reflection of the light travelling down along `down` back up along
    /// its mirror image, drawn with the base's own sampler: the sample's weight when it is
    /// that reflection ([`retraces`]), `None` when the sampler chose anything else.
    fn base_mirror(&self, down: Vec3, rng: &mut WalkRng) -> Option<B::Spectrum> {
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        let s = self.bottom.sample(-down, u, uc).filter(usable)?;
        retraces(down, &s).then(|| weight(&s))
    }

    /// What [`delta_chains`](Self::delta_chains) needs toward the internal direction `up`,
    /// computed once per walk.
    fn chain_exit(&self, up: Vec3) -> ChainExit {
        ChainExit {
            down: Vec3::new(up.x, up.y, -up.z),
            f: dielectric(-up.z, self.top.eta()),
            t: tr(self.thickness, up),
            reach: self.reach_top(0.0, up),
        }
    }

    /// The delta chains of `c` ([`chain_exit`](Self::chain_exit)): those that light going up
    /// along `up` (the internal direction that refracts into `wi`) follows to the exit under a
    /// smooth top: straight out, or reflected by the top's underside (`F`), the layer crossed
    /// down and up again, reflected by the base's delta lobe back along `up`
    /// ([`base_mirror`](Self::base_mirror)), and so on, at most
    /// `trips` times. Returns the sum over the chains of their weights (`1` for straight
    /// out, then products of `F Tr² ρ`) and of their probabilities under the sampler's walk
    /// (products of `F`, the chance of crossing the layer twice without scattering and the
    /// base's chance of choosing that reflection): the factors by which a connection's
    /// weight and density grow when the chains are counted. Both are estimated as the
    /// sampler walks: each trip is taken with probability `F` (so `F` leaves the products)
    /// and the base's reflection drawn by its sampler; each sum is unbiased (`eval` uses the
    /// first, `pdf` the second). Taking every trip and multiplying by `F` instead drew the
    /// base at every connection, where `F` is mostly a few percent: 1.5 to 2.2 times the cost
    /// of the walk without chains, for the same expectation.
    fn delta_chains(&self, c: &ChainExit, trips: u32, rng: &mut WalkRng) -> (B::Spectrum, f32) {
        let (mut w_sum, mut p_sum) = (B::Spectrum::one(), 1.0);
        let (mut w, mut p) = (B::Spectrum::one(), 1.0);
        for _ in 0..trips {
            if !(rng.next_f32() < c.f) {
                break;
            }
            let Some(rho) = self.base_mirror(c.down, rng) else {
                break;
            };
            w = w * rho * (c.t * c.t);
            p *= c.reach * c.reach;
            w_sum += w;
            p_sum += p;
        }
        (w_sum, p_sum)
    }

    /// [`eval_chains`](Self::eval_chains)' density: the sampler's density of leaving from a
    /// scattering at height `z` through the delta chains of `c`, up along the exit's internal
    /// direction (`direct`: the straight connection's density) and down to the base's delta
    /// reflection first (`exit`: the density of leaving toward `wi` from that direction).
    #[allow(clippy::too_many_arguments)]
    fn pdf_chains(
        &self,
        depth: u32,
        z: f32,
        from: Vec3,
        c: &ChainExit,
        direct: f32,
        exit: f32,
        rng: &mut WalkRng,
    ) -> f32 {
        let mut density = direct * self.delta_chains(c, self.round_trips(depth + 1), rng).1;
        let p = self.phase.eval(from, c.down);
        if depth + 2 < self.max_depth && p > 0.0 && self.base_mirror(c.down, rng).is_some() {
            let chains = self.delta_chains(c, self.round_trips(depth + 2), rng).1;
            // The walk scatters only inside the layer: a medium, so `Tr` is the chance of
            // crossing down to the base, and `c.reach` the chance of crossing back.
            density += p * tr(z, c.down) * c.reach * exit * chains;
        }
        density
    }

    /// What a scattering in the medium at height `z` (event `depth`, light arriving from
    /// `from`) sends to the exit under a smooth top with a delta base, per unit throughput
    /// and albedo: up along the exit's internal direction and through the
    /// [`delta_chains`](Self::delta_chains) of `c` (`direct` is the straight connection's
    /// weight: phase function, transmittance to the top, exit), and down along `c.down` to the
    /// base's delta reflection, which sends it up that direction and through the chains
    /// (`exit` is the top's weight for leaving along it).
    #[allow(clippy::too_many_arguments)]
    fn eval_chains(
        &self,
        depth: u32,
        z: f32,
        from: Vec3,
        c: &ChainExit,
        direct: f32,
        exit: f32,
        rng: &mut WalkRng,
    ) -> B::Spectrum {
        let mut f = self.delta_chains(c, self.round_trips(depth + 1), rng).0 * direct;
        let p = self.phase.eval(from, c.down);
        if depth + 2 < self.max_depth
            && p > 0.0
            && let Some(rho) = self.base_mirror(c.down, rng)
        {
            let chains = self.delta_chains(c, self.round_trips(depth + 2), rng).0;
            let path = p * tr(z, c.down) * c.t * exit;
            f += rho * chains * path;
        }
        f
    }

    /// One walk of `sample` from `wo` (prepared in `at`): pbrt-v4's `Sample_f` without its
    /// Russian roulette. Returns the direction that leaves, the path's weight (the product of
    /// `f |cos| / pdf` along it), its density (the product of the densities, in `f64` so that
    /// it neither overflows nor underflows) and its lobe.
    fn walk_sample(
        &self,
        at: &At<T::Prepared>,
        u: Vec2,
        uc: f32,
    ) -> Option<(Vec3, B::Spectrum, f64, Lobes)> {
        let wo = at.wo;
        if !(wo.z > 0.0) {
            return None;
        }
        let s0 = self.top.sample_prepared(&at.state, u, uc)?;
        if !usable(&s0) {
            return None;
        }
        let w0 = B::Spectrum::splat(weight(&s0));
        if s0.wi.z > 0.0 {
            // Reflected at the entry.
            return Some((s0.wi, w0, f64::from(s0.pdf), s0.lobe));
        }
        let mut rng = Hasher::new(TAG_SAMPLE, 0)
            .vec3(wo)
            .float(u.x)
            .float(u.y)
            .float(uc)
            .rng();
        let mut beta = w0;
        let mut pdf = f64::from(s0.pdf);
        let mut specular = s0.is_specular();
        let mut glossy = s0.lobe.intersects(Lobes::GLOSSY);
        // Under a smooth top, `eval` and `pdf` reach the exit from the last non-delta event
        // straight through the top or through delta chains ([`delta_chains`]): round trips of
        // the top's internal reflection and a base's delta reflection back along the same
        // direction. A path whose delta bounces since that event include one of the base's
        // that goes elsewhere ([`retraces`]) is one they cannot count, so the sampler drops
        // it too.
        let smooth_top = self.smooth_top();
        let (mut scattered, mut retraced) = (false, true);
        let mut walk = Walk {
            z: self.thickness,
            w: s0.wi,
            at_top: true,
        };
        for _ in 0..self.max_depth {
            if walk.w.z == 0.0 {
                return None;
            }
            if self.advance(&mut walk, &mut beta, &mut rng) {
                let ps = self.phase.sample(-walk.w, rng.next_vec2());
                if !(ps.pdf > 0.0 && ps.wi.z != 0.0) {
                    return None;
                }
                beta = beta * self.albedo;
                pdf *= f64::from(ps.pdf);
                specular = false;
                (scattered, retraced) = (true, true);
                walk.w = ps.wi;
                continue;
            }
            let (u, uc) = (rng.next_vec2(), rng.next_f32());
            // The interface's sample: direction, weight, density, lobe.
            let (wi, w, p, lobe) = if walk.at_top {
                let s = self.top.sample(-walk.w, u, uc).filter(usable)?;
                (s.wi, B::Spectrum::splat(weight(&s)), s.pdf, s.lobe)
            } else {
                let s = self.bottom.sample(-walk.w, u, uc).filter(usable)?;
                if s.wi.z < 0.0 {
                    // Through the base: the light leaves the stack.
                    return None;
                }
                if s.is_specular() && !retraces(walk.w, &s) {
                    retraced = false;
                }
                (s.wi, weight(&s), s.pdf, s.lobe)
            };
            beta = beta * w;
            pdf *= f64::from(p);
            specular &= lobe.is_specular();
            glossy |= lobe.intersects(Lobes::GLOSSY);
            if walk.at_top && wi.z > 0.0 {
                // Out through the top.
                if smooth_top && scattered && !retraced {
                    return None;
                }
                let kind = if specular {
                    Lobes::SPECULAR
                } else if glossy {
                    Lobes::GLOSSY
                } else {
                    Lobes::DIFFUSE
                };
                return Some((wi, beta, pdf, Lobes::REFLECTION | kind));
            }
            if !lobe.is_specular() {
                (scattered, retraced) = (true, true);
            }
            walk.w = wi;
        }
        None
    }

    /// One walk of `eval`: the light leaving toward `wi` from the paths that enter from `wo`
    /// (prepared in `at`), the entry's reflection excluded.
    fn eval_walk(&self, at: &At<T::Prepared>, wi: Vec3, rng: &mut WalkRng) -> B::Spectrum {
        let zero = B::Spectrum::zero();
        let mut f = zero;
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        let Some(wos) = self
            .top
            .sample_prepared(&at.state, u, uc)
            .filter(|s| usable(s) && s.wi.z < 0.0)
        else {
            return zero;
        };
        let (u, uc) = (rng.next_vec2(), rng.next_f32());
        // The direction inside sampled from the exit's side (pbrt-v4's `wis`), if the top
        // transmitted it.
        let wis = self
            .top_adjoint
            .sample(wi, u, uc)
            .filter(|s| usable(s) && s.wi.z < 0.0);
        let smooth_top = self.smooth_top();
        // The delta chains toward the exit direction, fixed for the walk.
        let chain = wis
            .filter(|_| self.chains())
            .map(|s| self.chain_exit(-s.wi));
        let specular_bottom = !self.bottom.lobes().is_non_specular();
        let mut beta = B::Spectrum::splat(weight(&wos));
        let mut walk = Walk {
            z: self.thickness,
            w: wos.wi,
            at_top: true,
        };
        for depth in 0..self.max_depth {
            // Russian roulette (pbrt-v4): unbiased, it trades variance for time.
            let m = beta.max_channel();
            if depth > 3 && m < 0.25 {
                let q = (1.0 - m).max(0.0);
                if rng.next_f32() < q {
                    break;
                }
                beta *= 1.0 / (1.0 - q);
            }
            if walk.w.z == 0.0 {
                break;
            }
            // Whether a connection through this event reaches the exit within the depth.
            let exit_ok = depth + 1 < self.max_depth;
            if self.advance(&mut walk, &mut beta, rng) {
                // Scattering in the medium at height z.
                let z = walk.z;
                if let (Some(wis), true) = (wis, exit_ok) {
                    let to = -wis.wi;
                    let p = self.phase.eval(-walk.w, to);
                    let wt = if smooth_top {
                        1.0
                    } else {
                        power_heuristic(1.0, wis.pdf, 1.0, p)
                    };
                    let direct = p * wt * self.to_top(z, to) * wis.f / wis.pdf;
                    if let Some(c) = &chain {
                        let exit = wis.f / wis.pdf;
                        f += self.eval_chains(depth, z, -walk.w, c, direct, exit, rng)
                            * beta
                            * self.albedo;
                    } else {
                        f += beta * self.albedo * direct;
                    }
                }
                let ps = self.phase.sample(-walk.w, rng.next_vec2());
                if !(ps.pdf > 0.0 && ps.wi.z != 0.0) {
                    break;
                }
                beta = beta * self.albedo;
                walk.w = ps.wi;
                if exit_ok && walk.w.z > 0.0 && !smooth_top {
                    let f_exit = self.top.eval(-walk.w, wi);
                    if f_exit > 0.0 {
                        let wt =
                            power_heuristic(1.0, ps.pdf, 1.0, self.top_adjoint.pdf(wi, -walk.w));
                        f += beta * (self.to_top(z, walk.w) * f_exit * wt);
                    }
                }
                continue;
            }
            if walk.at_top {
                // The top, from inside: the walk goes on only if it reflects (its
                // transmission is counted by the connections).
                let (u, uc) = (rng.next_vec2(), rng.next_f32());
                match self.top.sample(-walk.w, u, uc) {
                    Some(s) if usable(&s) && s.wi.z < 0.0 => {
                        beta *= weight(&s);
                        walk.w = s.wi;
                    }
                    _ => break,
                }
            } else {
                // The base: connect to the exit through `wis`, then scatter.
                let wo_b = -walk.w;
                if let (Some(wis), true, false) = (wis, exit_ok, specular_bottom) {
                    let to = -wis.wi;
                    let (fb, pb) = (self.bottom.eval(wo_b, to), self.bottom.pdf(wo_b, to));
                    let wt = if smooth_top {
                        1.0
                    } else {
                        power_heuristic(1.0, wis.pdf, 1.0, pb)
                    };
                    let scale = to.z.abs() * wt * self.to_top(0.0, to) * wis.f / wis.pdf;
                    if let (Some(c), false) = (&chain, fb.is_black()) {
                        let trips = self.round_trips(depth + 1);
                        f += beta * fb * scale * self.delta_chains(c, trips, rng).0;
                    } else {
                        f += beta * fb * scale;
                    }
                }
                let (u, uc) = (rng.next_vec2(), rng.next_f32());
                let bs = match self.bottom.sample(wo_b, u, uc) {
                    Some(s) if usable(&s) && s.wi.z > 0.0 => s,
                    _ => break,
                };
                beta = beta * weight(&bs);
                walk.w = bs.wi;
                if exit_ok && !smooth_top {
                    let f_exit = self.top.eval(-walk.w, wi);
                    if f_exit > 0.0 {
                        let wt = if bs.is_specular() {
                            1.0
                        } else {
                            power_heuristic(1.0, bs.pdf, 1.0, self.top_adjoint.pdf(wi, -walk.w))
                        };
                        f += beta * (self.to_top(0.0, walk.w) * f_exit * wt);
                    }
                }
            }
        }
        f
    }

    /// One walk of `pdf`: the density with which the sampler's walk from `wo` leaves toward
    /// `wi`, the entry's reflection excluded.
    ///
    /// The walk is the sampler's. A rough top adds, at each event that sends the walk up, the
    /// density of leaving toward `wi` after the next segment, by two strategies combined with
    /// the power heuristic: the segment the walk itself samples (the top's density at the hit
    /// that follows), and the segment sampled from `wi` through the top (the event's density
    /// of it, the chance of reaching the top, the top's density, over the sampling density).
    /// A smooth top adds, at each such event, the density of the one direction that refracts
    /// into `wi`, and over a base with a delta lobe that of the delta chains that end in it
    /// ([`delta_chains`](Self::delta_chains), [`pdf_chains`](Self::pdf_chains)).
    fn pdf_walk(&self, at: &At<T::Prepared>, wi: Vec3, rng: &mut WalkRng) -> f32 {
        let smooth_top = self.smooth_top();
        // The entry. A smooth top transmits toward the refracted direction with probability
        // 1 − F(wo): the walk takes that branch and weighs its density by the probability
        // (the expectation over the top's choice), rather than drawing the choice and counting
        // zero when the entry reflects. The estimate stays unbiased, and a sample's `pdf`
        // (which must be positive) is not zero as often as the top reflects. A rough top's
        // entry is drawn.
        let (w0, entry) = if smooth_top {
            let eta = self.top.eta();
            match refract_away(at.wo, Vec3::Z, eta) {
                Some(w) if w.z < 0.0 => (w, 1.0 - dielectric(at.wo.z, eta)),
                _ => return 0.0,
            }
        } else {
            let (u, uc) = (rng.next_vec2(), rng.next_f32());
            match self
                .top
                .sample_prepared(&at.state, u, uc)
                .filter(|s| usable(s) && s.wi.z < 0.0)
            {
                Some(s0) => (s0.wi, 1.0),
                None => return 0.0,
            }
        };
        // For a smooth top: the internal direction that refracts into wi, travelling up, with
        // the density of leaving toward wi along it. For a rough one: a direction inside
        // sampled from wi, with the top's density of leaving toward wi from it.
        let (w_star, wis) = if smooth_top {
            match refract_away(wi, Vec3::Z, self.top.eta()) {
                Some(a) if a.z < 0.0 => (Some((-a, self.smooth_exit_density(-a, wi))), None),
                _ => return 0.0,
            }
        } else {
            let (u, uc) = (rng.next_vec2(), rng.next_f32());
            let wis = self
                .top_adjoint
                .sample(wi, u, uc)
                .filter(|s| usable(s) && s.wi.z < 0.0)
                .map(|s| (s, self.top.pdf(s.wi, wi)));
            (None, wis)
        };
        // The delta chains toward w_star, fixed for the walk.
        let chain = w_star
            .filter(|_| self.chains())
            .map(|(ws, _)| self.chain_exit(ws));
        let mut density = 0.0_f32;
        let mut beta = B::Spectrum::one();
        let mut walk = Walk {
            z: self.thickness,
            w: w0,
            at_top: true,
        };
        // The density with which the last event sampled the walk's direction (infinite for a
        // delta lobe).
        let mut last_pdf = f32::INFINITY;
        for depth in 0..self.max_depth {
            if walk.w.z == 0.0 {
                break;
            }
            let exit_ok = depth + 1 < self.max_depth;
            if self.advance(&mut walk, &mut beta, rng) {
                let z = walk.z;
                if exit_ok {
                    if let Some((ws, exit)) = w_star {
                        let direct = self.phase.eval(-walk.w, ws) * self.reach_top(z, ws) * exit;
                        density += match &chain {
                            Some(c) => self.pdf_chains(depth, z, -walk.w, c, direct, exit, rng),
                            None => direct,
                        };
                    }
                    if let Some((s, p_exit)) = wis {
                        let to = -s.wi;
                        let pe = self.phase.eval(-walk.w, to);
                        let wt = power_heuristic(1.0, s.pdf, 1.0, pe);
                        density += pe * self.reach_top(z, to) * p_exit * wt / s.pdf;
                    }
                }
                let ps = self.phase.sample(-walk.w, rng.next_vec2());
                if !(ps.pdf > 0.0 && ps.wi.z != 0.0) {
                    break;
                }
                walk.w = ps.wi;
                last_pdf = ps.pdf;
                continue;
            }
            if walk.at_top {
                if !smooth_top {
                    let p = self.top.pdf(-walk.w, wi);
                    if p > 0.0 {
                        let wt =
                            power_heuristic(1.0, last_pdf, 1.0, self.top_adjoint.pdf(wi, -walk.w));
                        density += p * wt;
                    }
                }
                let (u, uc) = (rng.next_vec2(), rng.next_f32());
                match self.top.sample(-walk.w, u, uc) {
                    Some(s) if usable(&s) && s.wi.z < 0.0 => walk.w = s.wi,
                    _ => break,
                }
                last_pdf = f32::INFINITY;
            } else {
                let wo_b = -walk.w;
                if exit_ok {
                    if let Some((ws, exit)) = w_star {
                        let direct = self.bottom.pdf(wo_b, ws) * self.reach_top(0.0, ws) * exit;
                        density += match &chain {
                            Some(c) if direct > 0.0 => {
                                direct * self.delta_chains(c, self.round_trips(depth + 1), rng).1
                            }
                            _ => direct,
                        };
                    }
                    if let Some((s, p_exit)) = wis {
                        let to = -s.wi;
                        let pb = self.bottom.pdf(wo_b, to);
                        let wt = power_heuristic(1.0, s.pdf, 1.0, pb);
                        density += pb * self.reach_top(0.0, to) * p_exit * wt / s.pdf;
                    }
                }
                let (u, uc) = (rng.next_vec2(), rng.next_f32());
                match self.bottom.sample(wo_b, u, uc) {
                    Some(s) if usable(&s) && s.wi.z > 0.0 => {
                        walk.w = s.wi;
                        last_pdf = if s.is_specular() {
                            f32::INFINITY
                        } else {
                            s.pdf
                        };
                    }
                    _ => break,
                }
            }
        }
        density * entry
    }
}

impl<T: LayerInterface, B: Bxdf> Prepare for Layered<T, B> {
    type Spectrum = B::Spectrum;
    /// `wo` and the top's prepared state for it.
    type Prepared = At<T::Prepared>;

    #[inline]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        At {
            wo,
            state: self.top.prepare(wo),
        }
    }

    #[inline]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> B::Spectrum {
        self.eval_seeded_prepared(at, wi, 0)
    }

    #[inline]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        self.pdf_seeded_prepared(at, wi, 0)
    }

    fn eval_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> B::Spectrum {
        let wo = at.wo;
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return B::Spectrum::zero();
        }
        let mut rng = Hasher::new(TAG_EVAL, seed).vec3(wo).vec3(wi).rng();
        let mut sum = B::Spectrum::zero();
        for _ in 0..self.samples {
            sum += self.eval_walk(at, wi, &mut rng);
        }
        let f = B::Spectrum::splat(self.top.eval_prepared(&at.state, wi))
            + sum * (1.0 / self.samples as f32);
        // Total: a non-finite estimate (an overflow the guards above missed) is dropped.
        if f.is_finite() {
            f.map(|x| x.max(0.0))
        } else {
            B::Spectrum::zero()
        }
    }

    fn pdf_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> f32 {
        let wo = at.wo;
        if !(wo.z > 0.0 && wi.z > 0.0) {
            return 0.0;
        }
        let mut rng = Hasher::new(TAG_PDF, seed).vec3(wo).vec3(wi).rng();
        let mut sum = 0.0;
        for _ in 0..self.samples {
            sum += self.pdf_walk(at, wi, &mut rng);
        }
        let p = self.top.pdf_prepared(&at.state, wi) + sum / self.samples as f32;
        if p.is_finite() { p.max(0.0) } else { 0.0 }
    }

    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<B::Spectrum>> {
        let (wi, beta, path_pdf, lobe) = self.walk_sample(at, u, uc)?;
        // A sample from a lobe with a density carries an independent estimate of the density
        // at its direction (what `pdf` returns, for a renderer's MIS) and the value that keeps
        // its weight the walk's; a delta sample, the path's probability. Where the estimate is
        // zero (a walk that found no way out toward `wi`: a base whose sampled lobe has no
        // density, a walk of one event), the path's density stands in, as the sample's `pdf`
        // must be positive: a bias only there.
        let estimate = if lobe.is_specular() {
            0.0
        } else {
            let seed = Hasher::new(TAG_SAMPLE, 1)
                .float(u.x)
                .float(u.y)
                .float(uc)
                .rng()
                .next_u32();
            self.pdf_seeded_prepared(at, wi, u64::from(seed))
        };
        let pdf = if usable_pdf(estimate) {
            estimate
        } else {
            (path_pdf as f32).clamp(1e-30, 1e30)
        };
        let f = beta * (pdf / wi.z.abs());
        if !(f.is_finite() && wi.z != 0.0) {
            return None;
        }
        Some(BxdfSample::new(wi, f, pdf, lobe))
    }

    fn lobes(&self) -> Lobes {
        let mut k = kinds(Prepare::lobes(&self.top)) | kinds(self.bottom.lobes());
        if self.scattering {
            k |= Lobes::DIFFUSE;
        }
        Lobes::REFLECTION | k
    }

    #[inline]
    fn stochastic(&self) -> bool {
        true
    }
}
