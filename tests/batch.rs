//! The batched calls (`lobe::batch`) give the scalar calls' numbers, lane for lane, for every
//! model, over adversarial lanes: grazing and exactly tangent directions, directions below the
//! horizon, mirror pairs, `wo = ±wi`, random numbers at 0 and just below 1. Whatever the CPU
//! (the batched loops run compiled for AVX-512, AVX2 or the baseline, chosen at run time),
//! the arithmetic is the scalar path's: the test asserts equality bit for bit.

mod common;

use common::soa::{Buffers, Soa, UNWRITTEN, eval_pdf_batched, same, sample_batched};
use lobe::batch::{Batch, Lanes, LengthError, SampleOut, Vec2s, Vec3s};
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Lobes, Microfacet, Mirror, OrenNayar, Phong, Plastic, Prepare, RoughDielectric,
    SmoothDielectric, ThinDielectric, TransportMode,
};
use lobe::fresnel::{Conductor, Dielectric, Schlick};
use lobe::microfacet::{Beckmann, BlinnPhongNdf, Ggx, Gtr, Masking};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Eta, Roughness, Spectrum, Vec2, Vec3, Vec4};

/// Lanes per model: a few thousand, so that the vectorised loop and its remainder both run.
const N: usize = 4099;

/// Adversarial inputs, one lane each.
struct Inputs {
    wo: Vec<Vec3>,
    wi: Vec<Vec3>,
    u: Vec<Vec2>,
    uc: Vec<f32>,
}

fn direction(rng: &mut Pcg32) -> Vec3 {
    let z = match rng.next_u32() % 8 {
        // Both zeros: `TwoSided` mirrors a direction with `z < 0` only, so `-0` stays.
        0 => [0.0, -0.0][(rng.next_u32() % 2) as usize],
        1 => 1e-7 * (2.0 * rng.next_f32() - 1.0),
        2 => 1.0,
        3 => -1.0,
        _ => 2.0 * rng.next_f32() - 1.0,
    };
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = core::f32::consts::TAU * rng.next_f32();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

fn inputs() -> Inputs {
    let mut rng = Pcg32::new(2024, 7);
    let (mut wo, mut wi) = (Vec::new(), Vec::new());
    for _ in 0..N {
        let o = direction(&mut rng);
        let i = common::partner(&mut rng, o, 6, direction);
        wo.push(o);
        wi.push(i);
    }
    let unit = |rng: &mut Pcg32| match rng.next_u32() % 6 {
        0 => 0.0,
        1 => 1.0 - f32::EPSILON / 2.0,
        _ => rng.next_f32(),
    };
    let u = (0..N)
        .map(|_| Vec2::new(unit(&mut rng), unit(&mut rng)))
        .collect();
    let uc = (0..N).map(|_| unit(&mut rng)).collect();
    Inputs { wo, wi, u, uc }
}

/// Within `tol` of each other, relative to the larger, channel by channel (two zeros agree).
fn close<S: Spectrum>(a: S, b: S, tol: f32) -> bool {
    (0..S::CHANNELS).all(|c| {
        let (x, y) = (a.channel(c), b.channel(c));
        (x - y).abs() <= tol * x.abs().max(y.abs())
    })
}

/// How close a sample's `(f, pdf)` must be to `eval`/`pdf` at its direction: the default of
/// `verify`'s law of the same name (`Config::consistency_tolerance`), which every model of the
/// crate meets (the conformance matrix).
const CONSISTENCY: f32 = 1e-4;

/// A model the checks take: batched, with one spectrum for both paths, held in [`Buffers`].
trait Checked: Batch<Spectrum: Buffers> + Bxdf<Spectrum = <Self as Prepare>::Spectrum> {}

impl<M: Batch<Spectrum: Buffers> + Bxdf<Spectrum = <M as Prepare>::Spectrum>> Checked for M {}

/// Checks every lane of `m`'s batched calls against its scalar calls, bit for bit (the sample's
/// lobe and `eta` too), and returns the lobes the scalar samples came from (so that a caller can
/// ask that every branch of a sampler was compared). Where a lane's sample is not specular, its
/// `(f, pdf)` must also be what `eval_batch` and `pdf_batch` give at the sampled direction (to
/// [`CONSISTENCY`], 1e-4 relative: a sampler computes them by another route), so that a renderer
/// can weigh it against a light sample; a specular lane's `pdf` is a lobe's probability instead,
/// which the lobe flag tells apart.
fn check<M: Checked>(name: &str, m: &M) -> Vec<Lobes> {
    check_lanes(name, m, true)
}

/// [`check`] for a stochastic layered model, whose sample carries its own random walk's
/// estimates of `f` and `pdf`, not `eval`'s and `pdf`'s: compared with the scalar calls bit
/// for bit only.
fn check_stochastic<M: Checked>(name: &str, m: &M) -> Vec<Lobes> {
    check_lanes(name, m, false)
}

/// [`check`], comparing a non-specular sample with `eval` and `pdf` where `deterministic`.
fn check_lanes<M: Checked>(name: &str, m: &M, deterministic: bool) -> Vec<Lobes> {
    let (lobes, checked_samples, non_specular) = compare_lanes(name, m, deterministic, N);
    eprintln!("{name}: {checked_samples} samples, {non_specular} not specular");
    // The comparison means something only where there are samples: at α = 10 most
    // reflections leave below the horizon, and about one lane in ten still samples.
    assert!(
        checked_samples > 200,
        "{name}: only {checked_samples} lanes sampled"
    );
    lobes
}

/// The comparisons of [`check_lanes`] on the first `n` lanes of the inputs: the lobes the
/// scalar samples came from, how many lanes sampled, and how many of those not specularly.
fn compare_lanes<M: Checked>(
    name: &str,
    m: &M,
    deterministic: bool,
    n: usize,
) -> (Vec<Lobes>, usize, usize) {
    type S<M> = <M as Prepare>::Spectrum;
    let i = inputs();
    let (wo, u, uc) = (&i.wo[..n], &i.u[..n], &i.uc[..n]);
    let values = eval_pdf_batched(m, wo, &i.wi[..n]);
    let samples = sample_batched(m, wo, u, uc);
    // The batched eval and pdf at the sampled directions.
    let sampled: Vec<Vec3> = (0..n).map(|k| samples.wi.get(k)).collect();
    let at = eval_pdf_batched(m, wo, &sampled);

    let mut non_specular = 0;
    let mut checked_samples = 0;
    let mut lobes = Vec::new();
    for k in 0..n {
        let (o, w) = (i.wo[k], i.wi[k]);
        let (got, want) = (S::<M>::read(&values.f, k), m.eval(o, w));
        assert!(
            same(got, want),
            "{name}: eval lane {k} (wo {o}, wi {w}): batch {got:?} vs scalar {want:?}"
        );
        let (got, want) = (values.pdf[k], m.pdf(o, w));
        assert!(
            same(got, want),
            "{name}: pdf lane {k}: batch {got} vs scalar {want}"
        );
        let scalar = m.sample(o, i.u[k], i.uc[k]);
        let lane = samples.lane(k);
        assert!(
            lane.agrees(scalar.as_ref()),
            "{name}: sample lane {k} (wo {o}, u {:?}, uc {}): batch {lane:?} vs scalar {scalar:?}",
            i.u[k],
            i.uc[k],
        );
        let Some(s) = scalar else { continue };
        checked_samples += 1;
        if !lobes.contains(&s.lobe) {
            lobes.push(s.lobe);
        }
        if deterministic && !s.lobe.is_specular() {
            non_specular += 1;
            let at_f = S::<M>::read(&at.f, k);
            assert!(
                close(at_f, s.f, CONSISTENCY) && close(at.pdf[k], s.pdf, CONSISTENCY),
                "{name}: {} sample lane {k} (wo {o}, wi {}): (f, pdf) = ({:?}, {}), \
                 eval_batch and pdf_batch there ({at_f:?}, {})",
                s.lobe,
                s.wi,
                s.f,
                s.pdf,
                at.pdf[k]
            );
        }
    }
    (lobes, checked_samples, non_specular)
}

/// Asserts that the scalar samples `check` compared came from both the diffuse and the glossy
/// reflection lobe: a two-lobe model's batched loop was compared on both of its branches.
fn assert_both_lobes(name: &str, lobes: &[Lobes]) {
    assert_sampled(
        name,
        lobes,
        &[Lobes::DIFFUSE_REFLECTION, Lobes::GLOSSY_REFLECTION],
    );
}

/// Asserts that the scalar samples `check` compared came from each of the lobes `wanted`.
fn assert_sampled(name: &str, lobes: &[Lobes], wanted: &[Lobes]) {
    for &lobe in wanted {
        assert!(
            lobes.contains(&lobe),
            "{name}: no lane sampled {lobe:?} ({lobes:?})"
        );
    }
}

/// Asserts that the scalar samples `check` compared came from a delta lobe and from a lobe
/// with a density: the batched lobe flags were compared on both kinds of lane.
fn assert_specular_and_not(name: &str, lobes: &[Lobes]) {
    assert!(
        lobes.iter().any(|l| l.is_specular()) && lobes.iter().any(|l| !l.is_specular()),
        "{name}: the samples came from {lobes:?} only"
    );
}

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

#[test]
fn microfacet_conductors_equal_the_scalar_path() {
    let gold = common::gold();
    let schlick = Schlick::new(Vec3::new(0.95, 0.64, 0.54)).unwrap();
    for masking in [
        Masking::HeightCorrelated,
        Masking::Separable,
        Masking::VCavity,
    ] {
        for (ax, ay) in [(0.3, 0.3), (1e-4, 1e-4), (0.05, 0.6), (10.0, 10.0)] {
            let ggx = Ggx::new(a(ax), a(ay));
            check("GGX Schlick", &Microfacet::new(ggx, masking, schlick));
            check(
                "GGX gold",
                &Microfacet::new(ggx, masking, Conductor { ior: gold }),
            );
            check(
                "GGX gold, plain visible normals",
                &Microfacet::new(
                    ggx.with_bounded_reflection(false),
                    masking,
                    Conductor { ior: gold },
                ),
            );
        }
        check(
            "Beckmann gold",
            &Microfacet::new(
                Beckmann::isotropic(a(0.3)),
                masking,
                Conductor { ior: gold },
            ),
        );
        check(
            "GTR Schlick",
            &Microfacet::new(Gtr::new(a(0.3), 1.5).unwrap(), masking, schlick),
        );
        check(
            "Blinn-Phong NDF",
            &Microfacet::new(BlinnPhongNdf::new(a(0.3)).unwrap(), masking, schlick),
        );
    }
}

#[test]
fn rough_dielectrics_equal_the_scalar_path() {
    for masking in [
        Masking::HeightCorrelated,
        Masking::Separable,
        Masking::VCavity,
    ] {
        for mode in [TransportMode::Radiance, TransportMode::Importance] {
            for eta in [1.5, 1.0 / 1.33, 1.0001, 1.0] {
                for alpha in [0.3, 1e-4, 2.0] {
                    // At η = 1 every sample passes straight through, a delta lobe.
                    check(
                        &format!("rough glass η {eta}, α {alpha}, {masking:?}, {mode:?}"),
                        &RoughDielectric::new(Ggx::isotropic(a(alpha)), Eta::new(eta).unwrap())
                            .with_masking(masking)
                            .with_mode(mode),
                    );
                }
            }
        }
    }
}

#[test]
fn the_other_models_equal_the_scalar_path() {
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    check("Lambert", &Lambert::new(rgb).unwrap());
    check("Lambert mono", &Lambert::new(0.7_f32).unwrap());
    check("Oren-Nayar", &OrenNayar::new(rgb, 0.4).unwrap());
    // EON's loops fix its albedo's form, fitted or exact: both compared.
    let eon = EnergyPreservingOrenNayar::new(rgb, 0.4).unwrap();
    check("EON", &eon);
    check("EON, exact albedo", &eon.with_exact_albedo());
    check(
        "Disney diffuse",
        &DisneyDiffuse::new(rgb, Roughness::new(0.5).unwrap()).unwrap(),
    );
    check(
        "Phong",
        &Phong::new(rgb * 0.5, Vec3::splat(0.4), 30.0).unwrap(),
    );
    check(
        "Blinn-Phong",
        &BlinnPhong::new(
            rgb * 0.5,
            Vec3::splat(0.4),
            30.0,
            BlinnPhongForm::Normalized,
        )
        .unwrap(),
    );
    let glazed = check("Glazed", &Glazed::new(rgb, glass).unwrap());
    assert_specular_and_not("Glazed", &glazed);
    // The plastic's loops fix its coat's masking term: GGX and Beckmann coats, RGB and
    // monochrome, both lobes compared.
    let plastic = check(
        "Plastic",
        &Plastic::new(rgb, Ggx::isotropic(a(0.2)), glass).unwrap(),
    );
    assert_both_lobes("Plastic", &plastic);
    let plastic = check(
        "Plastic, Beckmann coat",
        &Plastic::new(rgb, Beckmann::isotropic(a(0.5)), glass).unwrap(),
    );
    assert_both_lobes("Plastic, Beckmann coat", &plastic);
    let plastic = check(
        "Plastic, monochrome",
        &Plastic::new(0.6_f32, Ggx::isotropic(a(0.3)), glass).unwrap(),
    );
    assert_both_lobes("Plastic, monochrome", &plastic);
    check("Mirror", &Mirror::new(Dielectric { eta: glass }));
    // The smooth glass's lanes form both directions and select one (its transport mode by a
    // select too): both modes, both lobes compared.
    for mode in [TransportMode::Radiance, TransportMode::Importance] {
        let name = format!("smooth glass, {mode:?}");
        let lobes = check(&name, &SmoothDielectric::new(glass).with_mode(mode));
        let wanted = [Lobes::SPECULAR_REFLECTION, Lobes::SPECULAR_TRANSMISSION];
        assert_sampled(&name, &lobes, &wanted);
    }
    check("thin glass", &ThinDielectric::new(glass));
}

#[test]
fn slices_of_different_lengths_are_refused_without_writing() {
    use lobe::bxdf::{Mix, Mono, TwoSided};
    let lambert = Lambert::new(0.5_f32).unwrap();
    refuses_without_writing("Lambert", &lambert);
    // The loops that read albedo tables a chunk at a time.
    let schlick = Schlick::new(0.9_f32).unwrap();
    let conductor = Microfacet::new(Ggx::isotropic(a(0.3)), Masking::HeightCorrelated, schlick);
    let compensated = conductor.with_energy_compensation().unwrap();
    refuses_without_writing("GGX compensated", &compensated);
    // The models built from others check the lengths before they call their parts.
    refuses_without_writing("Mix", &Mix::new(lambert, lambert, 0.5).unwrap());
    refuses_without_writing("TwoSided", &TwoSided::new(lambert));
    let glass = SmoothDielectric::new(Eta::new(1.5).unwrap());
    refuses_without_writing("Mono", &Mono::<_, f32>::new(glass));
    // The delta models' `eval` and `pdf` run without the dispatch (`Batch::DELTA_ONLY`).
    refuses_without_writing("smooth glass", &glass);
}

/// `Batch::DELTA_ONLY` is set by the crate's models with delta lobes only, and is a hint only:
/// a model that sets it wrongly still gets its scalar calls' numbers from the batched calls.
#[test]
fn delta_only_is_a_hint_set_by_the_delta_models() {
    // Checked when the test compiles.
    const { assert!(SmoothDielectric::DELTA_ONLY && ThinDielectric::DELTA_ONLY) };
    const { assert!(<Mirror<Schlick<Vec3>> as Batch>::DELTA_ONLY) };
    const { assert!(!Lambert::<Vec3>::DELTA_ONLY && !RoughDielectric::<Ggx>::DELTA_ONLY) };
    let glass = Eta::new(1.5).unwrap();
    let mirror = Mirror::new(Schlick::new(Vec3::new(0.9, 0.7, 0.5)).unwrap());
    let specular = Lobes::SPECULAR_REFLECTION | Lobes::SPECULAR_TRANSMISSION;
    let (smooth, thin) = (SmoothDielectric::new(glass), ThinDielectric::new(glass));
    for lobes in [
        Bxdf::lobes(&smooth),
        Bxdf::lobes(&thin),
        Bxdf::lobes(&mirror),
    ] {
        assert!(specular.contains(lobes), "{lobes:?}");
    }
    check(
        "Lambert marked delta-only",
        &Mislabelled(Lambert::new(Vec3::splat(0.5)).unwrap()),
    );
}

/// A model that sets [`Batch::DELTA_ONLY`] without being delta-only.
#[derive(Clone, Copy)]
struct Mislabelled<M>(M);

impl<M: Prepare> Prepare for Mislabelled<M> {
    type Spectrum = M::Spectrum;
    type Prepared = M::Prepared;

    fn prepare(&self, wo: Vec3) -> M::Prepared {
        self.0.prepare(wo)
    }

    fn eval_prepared(&self, at: &M::Prepared, wi: Vec3) -> M::Spectrum {
        self.0.eval_prepared(at, wi)
    }

    fn pdf_prepared(&self, at: &M::Prepared, wi: Vec3) -> f32 {
        self.0.pdf_prepared(at, wi)
    }

    fn sample_prepared(
        &self,
        at: &M::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<lobe::bxdf::BxdfSample<M::Spectrum>> {
        self.0.sample_prepared(at, u, uc)
    }

    fn lobes(&self) -> Lobes {
        self.0.lobes()
    }
}

impl<M: Prepare + Clone> Batch for Mislabelled<M>
where
    M::Spectrum: Lanes,
{
    const DELTA_ONLY: bool = true;
}

/// `m`'s three batched calls refuse slices of different lengths, writing nothing, and accept
/// empty ones.
fn refuses_without_writing<M: Batch<Spectrum = f32>>(name: &str, m: &M) {
    let (wo, wi) = (Soa::of(&[Vec3::Z; 4]), Soa::of(&[Vec3::Z; 3]));
    let mut out = vec![-1.0; 4];
    assert_eq!(
        m.eval_batch(wo.view(), wi.view(), &mut out),
        Err(LengthError {
            expected: 4,
            found: 3
        }),
        "{name}"
    );
    assert_eq!(out, vec![-1.0; 4], "{name}");
    // A short coordinate slice inside one argument is refused too.
    let bad = Vec3s {
        x: &wo.x,
        y: &wo.y[..2],
        z: &wo.z,
    };
    assert!(m.pdf_batch(bad, wo.view(), &mut out).is_err(), "{name}");
    assert_eq!(out, vec![-1.0; 4], "{name}");
    // Empty batches are fine.
    let empty = Soa::of(&[]);
    assert_eq!(
        m.eval_batch(empty.view(), empty.view(), &mut []),
        Ok(()),
        "{name}"
    );
    assert_eq!(
        m.pdf_batch(empty.view(), empty.view(), &mut []),
        Ok(()),
        "{name}"
    );
    // `sample`: refused for a `uc` one lane short (nothing written), accepted when empty.
    for n in [4, 0] {
        let wo = Soa::of(&vec![Vec3::Z; n]);
        let (half, uc) = (vec![0.5; n], vec![0.5; n.saturating_sub(1)]);
        // `SPECULAR` alone (no side) is a lobe no sample has.
        let (mut swi, mut lobe) = (Soa::unwritten(n), vec![Lobes::SPECULAR; n]);
        let (mut f, mut pdf, mut eta) = (vec![-1.0; n], vec![-1.0; n], vec![-1.0; n]);
        let out = SampleOut {
            wi: swi.view_mut(),
            f: &mut f[..],
            pdf: &mut pdf,
            lobe: &mut lobe,
            eta: &mut eta,
        };
        let u = Vec2s { x: &half, y: &half };
        let refused = m.sample_batch(wo.view(), u, &uc, out).is_err();
        assert_eq!(refused, n > 0, "{name}, {n} lanes");
        assert!(
            f.iter().chain(&pdf).chain(&eta).all(|&x| x == -1.0),
            "{name}"
        );
        let mut wi = swi.x.iter().chain(&swi.y).chain(&swi.z);
        assert!(wi.all(|x| x.to_bits() == UNWRITTEN.to_bits()), "{name}");
        assert!(lobe.iter().all(|&l| l == Lobes::SPECULAR), "{name}");
    }
}

/// The combinators and the stochastic layered models (issue 12) through the default batched
/// methods: the same numbers as the scalar calls, lane by lane (a layered model's estimates
/// are seeded from their arguments, so a lane repeats the scalar call exactly).
#[test]
fn the_combinators_and_layered_models_equal_the_scalar_path() {
    use lobe::bxdf::{CoatedDiffuse, DiffuseTransmission, Mix, Sheen, TwoSided};
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    let coated = CoatedDiffuse::coated_diffuse(rgb, Ggx::isotropic(a(0.3)), glass).unwrap();
    check_stochastic("CoatedDiffuse", &coated);
    check(
        "Mix(Lambert, Plastic)",
        &Mix::new(
            Lambert::new(rgb).unwrap(),
            Plastic::new(rgb, Ggx::isotropic(a(0.2)), glass).unwrap(),
            0.3,
        )
        .unwrap(),
    );
    // A delta lobe and a diffuse one, picked per lane.
    let mirror = Mirror::new(Schlick::new(Vec3::new(0.9, 0.7, 0.5)).unwrap());
    let lobes = check(
        "Mix(Lambert, Mirror)",
        &Mix::new(Lambert::new(rgb).unwrap(), mirror, 0.4).unwrap(),
    );
    assert_specular_and_not("Mix(Lambert, Mirror)", &lobes);
    check_stochastic("TwoSided(CoatedDiffuse)", &TwoSided::new(coated));
    check(
        "DiffuseTransmission",
        &DiffuseTransmission::new(rgb * 0.5, rgb * 0.4).unwrap(),
    );
    check("Sheen", &Sheen::new(rgb, 0.4).unwrap());
    check(
        "Sheen, exact Smith",
        &Sheen::new(rgb, 0.05).unwrap().with_exact_smith(),
    );
}

/// Four-wavelength (`Vec4`) models: a spectrum of four channels through the loops, the
/// stack space of the models built from others (four rows, the most it holds) and the
/// compensated models' chunk buffers (their largest, for the compensated plastic's `sample`).
#[test]
fn the_four_wavelength_models_equal_the_scalar_path() {
    use lobe::bxdf::{CoatedDiffuse, DiffuseTransmission, Mix, Mono, Sheen, TwoSided};
    let rho = Vec4::new(0.8, 0.5, 0.2, 0.65);
    let glass = Eta::new(1.5).unwrap();
    let gold = Conductor {
        ior: lobe::metals::GOLD.spectral(Vec4::new(650.0, 550.0, 450.0, 700.0)),
    };
    let lambert = Lambert::new(rho).unwrap();
    check("Lambert, Vec4", &lambert);
    check("Oren-Nayar, Vec4", &OrenNayar::new(rho, 0.4).unwrap());
    check(
        "EON, Vec4",
        &EnergyPreservingOrenNayar::new(rho, 0.4).unwrap(),
    );
    check(
        "Disney diffuse, Vec4",
        &DisneyDiffuse::new(rho, Roughness::new(0.5).unwrap()).unwrap(),
    );
    for masking in [
        Masking::HeightCorrelated,
        Masking::Separable,
        Masking::VCavity,
    ] {
        check(
            &format!("GGX gold, Vec4, {masking:?}"),
            &Microfacet::new(Ggx::isotropic(a(0.3)), masking, gold),
        );
    }
    let schlick = Microfacet::new(
        Ggx::isotropic(a(0.3)),
        Masking::HeightCorrelated,
        Schlick::new(rho).unwrap(),
    );
    check("GGX Schlick, Vec4", &schlick);
    let compensated = Microfacet::new(Ggx::isotropic(a(0.6)), Masking::HeightCorrelated, gold)
        .with_energy_compensation()
        .unwrap();
    let lobes = check("GGX gold compensated, Vec4", &compensated);
    assert_both_lobes("GGX gold compensated, Vec4", &lobes);
    let plastic = Plastic::new(rho, Ggx::isotropic(a(0.2)), glass).unwrap();
    assert_both_lobes("Plastic, Vec4", &check("Plastic, Vec4", &plastic));
    let coat = Plastic::compensated(rho, Ggx::isotropic(a(0.4)), glass).unwrap();
    let lobes = check("plastic compensated, Vec4", &coat);
    assert_both_lobes("plastic compensated, Vec4", &lobes);
    let mix = Mix::new(lambert, schlick, 0.5).unwrap();
    assert_both_lobes("Mix(Lambert, GGX Schlick), Vec4", &check("Mix, Vec4", &mix));
    check("TwoSided(GGX Schlick), Vec4", &TwoSided::new(schlick));
    let rough = RoughDielectric::new(Ggx::isotropic(a(0.3)), glass);
    check("Mono(rough glass), Vec4", &Mono::<_, Vec4>::new(rough));
    check(
        "DiffuseTransmission, Vec4",
        &DiffuseTransmission::new(rho * 0.5, rho * 0.4).unwrap(),
    );
    check("Sheen, Vec4", &Sheen::new(rho, 0.4).unwrap());
    let coated = CoatedDiffuse::coated_diffuse(rho, Ggx::isotropic(a(0.3)), glass).unwrap();
    check_stochastic("CoatedDiffuse, Vec4", &coated);
}

/// The models built from others (`Mix`, `TwoSided`, `Mono`) pass chunks of lanes to their
/// parts' own batched calls (`src/batch/parts.rs`): parts with loops of their own (a masking
/// term fixed outside the loop, tables looked up a chunk at a time), nested blends, a blend
/// that samples through its stochastic part, and a transmitting part. `N` lanes span several
/// chunks and end in a partial one.
#[test]
fn the_models_built_from_others_equal_the_scalar_path_through_their_parts() {
    use lobe::bxdf::{CoatedDiffuse, CompensatedDielectric, Mix, Mono, TwoSided};
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    let lambert = Lambert::new(rgb).unwrap();
    let conductor = |masking| {
        Microfacet::new(
            Beckmann::isotropic(a(0.4)),
            masking,
            Conductor {
                ior: common::gold(),
            },
        )
    };
    for masking in [
        Masking::HeightCorrelated,
        Masking::Separable,
        Masking::VCavity,
    ] {
        let gold = conductor(masking);
        let name = format!("Mix(Lambert, Beckmann gold, {masking:?})");
        assert_both_lobes(&name, &check(&name, &Mix::new(lambert, gold, 0.5).unwrap()));
        check(
            &format!("TwoSided(Beckmann gold, {masking:?})"),
            &TwoSided::new(gold),
        );
    }
    let gold = conductor(Masking::HeightCorrelated);
    // One part never chosen: its share of every chunk is empty.
    for w in [0.0, 1.0] {
        check(
            &format!("Mix(Lambert, Beckmann gold) w {w}"),
            &Mix::new(lambert, gold, w).unwrap(),
        );
    }
    let mirror = Mirror::new(Schlick::new(Vec3::new(0.9, 0.7, 0.5)).unwrap());
    let nested = Mix::new(Mix::new(lambert, gold, 0.3).unwrap(), mirror, 0.2).unwrap();
    let lobes = check("Mix(Mix(Lambert, Beckmann gold), Mirror)", &nested);
    assert_specular_and_not("Mix(Mix(Lambert, Beckmann gold), Mirror)", &lobes);
    check(
        "TwoSided(Mix(Lambert, Mirror))",
        &TwoSided::new(Mix::new(lambert, mirror, 0.4).unwrap()),
    );
    let coated = CoatedDiffuse::coated_diffuse(rgb, Ggx::isotropic(a(0.3)), glass).unwrap();
    check_stochastic(
        "Mix(Lambert, CoatedDiffuse)",
        &Mix::new(lambert, coated, 0.5).unwrap(),
    );
    let rough = RoughDielectric::new(Ggx::isotropic(a(0.3)), glass);
    let lobes = check("Mono(rough glass)", &Mono::<_, Vec3>::new(rough));
    assert_sampled(
        "Mono(rough glass)",
        &lobes,
        &[Lobes::GLOSSY_REFLECTION, Lobes::GLOSSY_TRANSMISSION],
    );
    let compensated = CompensatedDielectric::new(
        RoughDielectric::new(Ggx::isotropic(a(0.5)), glass).with_mode(TransportMode::Importance),
    )
    .unwrap();
    check(
        "Mono(compensated glass)",
        &Mono::<_, Vec3>::new(compensated),
    );
    check(
        "Mono(smooth glass)",
        &Mono::<_, Vec3>::new(SmoothDielectric::new(glass)),
    );
}

/// The energy-compensated models: Kulla & Conty's lobe on a conductor and on a white
/// microfacet, Turquin's scaling, the compensated glass in both transport modes (the
/// compensated microfacet model and glass take one loop per masking term, as the plain
/// ones: each term is checked, with a table of one's own where the crate's is for another),
/// and the compensated plastic.
#[test]
fn the_compensated_models_equal_the_scalar_path() {
    use lobe::bxdf::{CompensatedDielectric, CompensatedMicrofacet, Compensation};
    use lobe::fresnel::NoFresnel;
    let hc = Masking::HeightCorrelated;
    let glass = Eta::new(1.5).unwrap();
    let gold = common::gold();
    // The batched sample draws both lobes' directions in every lane and keeps one: compared
    // on lanes of each lobe, for GGX and for Beckmann (whose sampler is another loop).
    fn both_lobes_of<D: lobe::tables::TabulatedAlbedo + Clone>(
        name: &str,
        d: D,
        ior: ComplexIor<Vec3>,
    ) {
        let m = Microfacet::new(d, Masking::HeightCorrelated, Conductor { ior });
        assert_both_lobes(name, &check(name, &m.with_energy_compensation().unwrap()));
    }
    both_lobes_of("GGX gold compensated", Ggx::isotropic(a(0.6)), gold);
    both_lobes_of(
        "Beckmann gold compensated",
        Beckmann::isotropic(a(0.7)),
        gold,
    );
    // The other masking terms take a table of one's own (here the height-correlated row:
    // the loops, not the compensation's accuracy, are under test).
    use lobe::tables::{TabulatedAlbedo, TabulatedDielectric};
    let row = Ggx::isotropic(a(0.6)).conductor_albedo().unwrap();
    for masking in [Masking::Separable, Masking::VCavity] {
        for compensation in [Compensation::KullaConty, Compensation::Turquin] {
            let inner = Microfacet::new(Ggx::isotropic(a(0.6)), masking, Conductor { ior: gold });
            check(
                &format!("GGX gold {compensation:?}, {masking:?}"),
                &CompensatedMicrofacet::with_albedo(inner, row, compensation),
            );
        }
    }
    check(
        "GGX white compensated",
        &Microfacet::new(Ggx::isotropic(a(0.6)), hc, NoFresnel::<f32>::new())
            .with_energy_compensation()
            .unwrap(),
    );
    check(
        "GGX Turquin",
        &CompensatedMicrofacet::new(
            Microfacet::new(
                Ggx::isotropic(a(0.6)),
                hc,
                Schlick::new(Vec3::splat(0.5)).unwrap(),
            ),
            Compensation::Turquin,
        )
        .unwrap(),
    );
    let glass_row = Ggx::isotropic(a(0.4)).dielectric_albedo(glass).unwrap();
    for mode in [TransportMode::Radiance, TransportMode::Importance] {
        let interface = RoughDielectric::new(Ggx::isotropic(a(0.4)), glass).with_mode(mode);
        // Its batched sample draws from the compensation lobes and the interface in every
        // lane and keeps one: compared on lanes of each of the four lobes.
        let name = format!("rough glass compensated, {mode:?}");
        let lobes = check(&name, &interface.with_energy_compensation().unwrap());
        let wanted = [
            Lobes::DIFFUSE_REFLECTION,
            Lobes::DIFFUSE | Lobes::TRANSMISSION,
            Lobes::GLOSSY_REFLECTION,
            Lobes::GLOSSY_TRANSMISSION,
        ];
        assert_sampled(&name, &lobes, &wanted);
        // An index-matched interface (`η = 1`, whose sample is the delta of `−wo`) with
        // another's tables, so that the compensation lobes are drawn too: the lanes select
        // that sample rather than branch on it.
        let matched = RoughDielectric::new(Ggx::isotropic(a(0.4)), Eta::new(1.0).unwrap());
        let name = format!("index-matched interface compensated, {mode:?}");
        let m = CompensatedDielectric::with_albedo(matched.with_mode(mode), glass_row);
        let wanted = [Lobes::DIFFUSE_REFLECTION, Lobes::SPECULAR_TRANSMISSION];
        assert_sampled(&name, &check(&name, &m), &wanted);
        for masking in [Masking::Separable, Masking::VCavity] {
            check(
                &format!("rough glass compensated, {mode:?}, {masking:?}"),
                &CompensatedDielectric::with_albedo(interface.with_masking(masking), glass_row),
            );
        }
    }
    let lobes = check(
        "plastic compensated",
        &Plastic::compensated(Vec3::new(0.8, 0.5, 0.2), Ggx::isotropic(a(0.4)), glass).unwrap(),
    );
    assert_both_lobes("plastic compensated", &lobes);
    // A black base: the plastic always picks its coat (p = 1), so its diffuse samples all
    // come from the coat's compensation lobe, a branch of the batched lane of its own.
    let black = Plastic::compensated(Vec3::ZERO, Ggx::isotropic(a(0.4)), glass).unwrap();
    let lobes = check("plastic compensated, black base", &black);
    assert_both_lobes("plastic compensated, black base", &lobes);
}

/// The loops that read a table run 256 lanes at a time, 64 for a call of at most 64 (the
/// tables looked up in passes of their own: the energy-compensated microfacet model's, for
/// both compensations, both plastics' and the compensated glass's): batches of no lane, of
/// one, and ending just before, at and just after a chunk's end, equal the scalar calls lane
/// by lane, bit for bit. (The other tests' batches have
/// 4,099 lanes: sixteen whole chunks and three lanes.)
#[test]
fn the_chunked_loops_equal_the_scalar_path_at_every_chunk_boundary() {
    use lobe::bxdf::{CompensatedMicrofacet, Compensation};
    let gold = common::gold();
    let inner = Microfacet::new(
        Ggx::isotropic(a(0.6)),
        Masking::HeightCorrelated,
        Conductor { ior: gold },
    );
    for compensation in [Compensation::KullaConty, Compensation::Turquin] {
        let m = CompensatedMicrofacet::new(inner, compensation).unwrap();
        at_every_chunk_boundary(&format!("{compensation:?}"), &m);
    }
    let glass = Eta::new(1.5).unwrap();
    let plastic = Plastic::new(Vec3::new(0.8, 0.5, 0.2), Ggx::isotropic(a(0.4)), glass);
    at_every_chunk_boundary("plastic", &plastic.unwrap());
    let compensated = Plastic::compensated(Vec3::new(0.8, 0.5, 0.2), Ggx::isotropic(a(0.4)), glass);
    at_every_chunk_boundary("compensated plastic", &compensated.unwrap());
    let interface = RoughDielectric::new(Ggx::isotropic(a(0.4)), glass);
    let compensated = interface.with_energy_compensation().unwrap();
    at_every_chunk_boundary("compensated glass", &compensated);
}

/// [`the_chunked_loops_equal_the_scalar_path_at_every_chunk_boundary`] for one model: the
/// comparisons of [`check`] on the first `n` lanes.
fn at_every_chunk_boundary<M: Checked>(model: &str, m: &M) {
    for n in [0, 1, 255, 256, 257, 511, 512, 513] {
        compare_lanes(&format!("{model}, {n} lanes"), m, true, n);
    }
}

/// Short batches through the plain loops (one loop over the lanes, run by the CPU's vectors
/// where there are enough lanes for them and by the scalar code for the rest) and through the
/// loops over one chunk of the models that read albedo tables, and through the models built
/// from others: every length from 0 to 40 lanes and a few past it, so that batches shorter
/// than one vector, of exactly one or several, and with every remainder of the 8 and 16 lanes
/// of the AVX2 and AVX-512 loops equal the scalar calls lane by lane, bit for bit.
#[test]
fn short_batches_equal_the_scalar_path_at_every_length() {
    use lobe::bxdf::{CompensatedDielectric, Compensation, Mix, Mono, TwoSided};
    let gold = common::gold();
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    let conductor = Microfacet::new(
        Ggx::isotropic(a(0.3)),
        Masking::HeightCorrelated,
        Conductor { ior: gold },
    );
    let rough_glass = RoughDielectric::new(Ggx::isotropic(a(0.3)), glass);
    let (lambert, glazed) = (Lambert::new(rgb).unwrap(), Glazed::new(rgb, glass).unwrap());
    // The models that read albedo tables: their loops over a chunk's lanes are written the
    // same way (`at_every_chunk_boundary` checks the chunks' ends).
    let compensated = conductor.with_energy_compensation().unwrap();
    let compensated_glass = CompensatedDielectric::new(rough_glass).unwrap();
    let plastic = Plastic::new(rgb, Ggx::isotropic(a(0.2)), glass).unwrap();
    let compensated_plastic = Plastic::compensated(rgb, Ggx::isotropic(a(0.2)), glass).unwrap();
    // Turquin's scaling: samples finished as drawn (no table read at the sampled direction).
    let turquin = lobe::bxdf::CompensatedMicrofacet::new(conductor, Compensation::Turquin);
    let turquin = turquin.unwrap();
    // The models built from others take stack space of 64 lanes for a call of at most 64,
    // and of a long chunk for a longer one: both sides of that.
    let mix = Mix::new(lambert, conductor, 0.5).unwrap();
    let (two_sided, mono) = (TwoSided::new(conductor), Mono::<_, Vec3>::new(rough_glass));
    // The diffuse models whose `eval` computes the value on every lane (vectorised from 16 or
    // 24 lanes under AVX2), and EON's exact form, which keeps the early zero.
    let oren_nayar = OrenNayar::new(rgb, 0.4).unwrap();
    let disney = DisneyDiffuse::new(rgb, Roughness::new(0.5).unwrap()).unwrap();
    let eon = EnergyPreservingOrenNayar::new(rgb, 0.4).unwrap();
    let eon_exact = eon.with_exact_albedo();
    // Each model by name, compared at `n` lanes.
    macro_rules! compare {
        ($n:expr; $($name:literal: $m:expr),* $(,)?) => {
            $(compare_lanes(&format!("{}, {} lanes", $name, $n), $m, true, $n);)*
        };
    }
    for n in (0..=40).chain([63, 64, 65, 100]) {
        compare!(n; "Lambert": &lambert, "GGX gold": &conductor, "rough glass": &rough_glass,
            "Glazed": &glazed, "GGX gold compensated": &compensated, "plastic": &plastic,
            "compensated glass": &compensated_glass, "compensated plastic": &compensated_plastic,
            "GGX gold, Turquin": &turquin, "Mix(Lambert, GGX gold)": &mix,
            "TwoSided(GGX gold)": &two_sided, "Mono(rough glass)": &mono,
            "Oren-Nayar": &oren_nayar, "Disney diffuse": &disney, "EON": &eon,
            "EON, exact albedo": &eon_exact);
    }
}

/// The instruction set the batched calls ran on is the one this CPU's features call for (the
/// x86-64-v4 and v3 levels as the dispatch defines them; checked on x86_64), and is printed,
/// so that a log shows which path the bit-for-bit checks above covered. CI runs this file
/// again under QEMU's user mode with an emulated CPU and sets `LOBE_EXPECT_INSTRUCTION_SET` to
/// the path that CPU must take (`AVX2`, `baseline`, `target`), so that an emulation that fell
/// back to another path fails.
#[test]
fn the_instruction_set_is_the_cpus() {
    let isa = lobe::batch::instruction_set();
    eprintln!("batched path: {isa}");
    #[cfg(target_arch = "x86_64")]
    {
        use lobe::batch::InstructionSet;
        macro_rules! all {
            ($($f:tt),*) => { true $(&& std::is_x86_feature_detected!($f))* };
        }
        let v3 = all!(
            "fxsr", "sse3", "ssse3", "sse4.1", "sse4.2", "popcnt", "avx", "avx2", "bmi1", "bmi2",
            "fma", "lzcnt"
        );
        let v4 = v3 && all!("avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl");
        let want = if v4 {
            InstructionSet::Avx512
        } else if v3 {
            InstructionSet::Avx2
        } else {
            InstructionSet::Baseline
        };
        assert_eq!(isa, want, "the CPU's features call for {want}");
    }
    if let Ok(want) = std::env::var("LOBE_EXPECT_INSTRUCTION_SET") {
        assert_eq!(isa.name(), want, "LOBE_EXPECT_INSTRUCTION_SET");
    }
}
