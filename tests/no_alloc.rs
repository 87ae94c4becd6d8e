//! No allocation in the shading hot loop (issue 9, item 6, the scalar part): `eval`, `pdf`,
//! `sample`, `prepare` and the prepared calls of every model, with several parameter sets
//! each, over 4,096 inputs (uniform, grazing, exactly normal and tangent directions on both
//! sides, mirror pairs, `wi = ±wo`), under a counting global allocator.
//!
//! The allocator wraps [`System`] and counts `alloc`, `alloc_zeroed`, `realloc` and `dealloc`
//! calls made by a thread while that thread's `COUNTING` flag is set. Flag and counter are
//! thread-local, so the test harness's own threads (its output capture, the other tests
//! running in parallel) neither add to a count nor see one: each counted section sees only
//! what its own thread did. The models and the inputs are built before a count starts
//! (building `Plastic` integrates its coat's albedo table; `Gtr` tabulates its Smith
//! function), and the results are folded into a checksum passed through `black_box`, so
//! that the optimiser cannot drop the calls being counted.

mod common;

use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Microfacet, Mirror, OrenNayar, Phong, Plastic, Prepare, RoughDielectric, SmoothDielectric,
    ThinDielectric, TransportMode,
};
use lobe::fresnel::{Conductor, Dielectric, NoFresnel, Schlick};
use lobe::microfacet::{Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr, Masking};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Eta, Roughness, Spectrum, Vec2, Vec3};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

/// [`System`], counting the calls of the threads that asked for it.
struct Counting;

thread_local! {
    /// Whether this thread's allocator calls are being counted.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    /// This thread's allocator calls since its count started.
    static CALLS: Cell<usize> = const { Cell::new(0) };
}

/// Counts one allocator call if this thread is counting. Const-initialised thread-locals
/// without destructors never allocate, so reading them from the allocator is sound;
/// `try_with` covers a thread being torn down.
fn record() {
    if COUNTING.try_with(Cell::get).unwrap_or(false) {
        let _ = CALLS.try_with(|c| c.set(c.get() + 1));
    }
}

// SAFETY: every call is forwarded unchanged to `System`, which upholds `GlobalAlloc`'s
// contract; the counting touches only const-initialised thread-locals and never allocates.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        record();
        // SAFETY: the caller's guarantees for `layout` are passed on.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        record();
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        record();
        // SAFETY: `ptr` came from `System` through this wrapper, with this `layout`.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        record();
        // SAFETY: as for `dealloc`, and the caller's guarantees for `new_size`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Runs `f` and returns its result with the number of allocator calls this thread made
/// meanwhile.
fn count_calls<R>(f: impl FnOnce() -> R) -> (R, usize) {
    CALLS.with(|c| c.set(0));
    COUNTING.with(|c| c.set(true));
    let r = f();
    COUNTING.with(|c| c.set(false));
    (r, CALLS.with(Cell::get))
}

const N: usize = 4096;

/// The inputs, shared by every model: `wo[k]`, `wi[k]`, `u[k]`, `uc[k]` go together.
struct Inputs {
    wo: Vec<Vec3>,
    wi: Vec<Vec3>,
    u: Vec<Vec2>,
    uc: Vec<f32>,
}

/// A direction with cosine `z` and a random azimuth.
fn with_cos(z: f32, rng: &mut Pcg32) -> Vec3 {
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = core::f32::consts::TAU * rng.next_f32();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// A direction on either side: uniform on the sphere mostly, else grazing, normal or
/// tangent.
fn direction(rng: &mut Pcg32) -> Vec3 {
    let sign = if rng.next_f32() < 0.5 { 1.0 } else { -1.0 };
    let z = match rng.next_u32() % 8 {
        0 => 1e-7,
        1 => 1.0,
        2 => 0.0,
        3 => 1e-3 * rng.next_f32(),
        _ => rng.next_f32(),
    };
    with_cos(sign * z, rng)
}

fn inputs() -> Inputs {
    let mut rng = Pcg32::new(0xa110c, 6);
    let mut i = Inputs {
        wo: Vec::with_capacity(N),
        wi: Vec::with_capacity(N),
        u: Vec::with_capacity(N),
        uc: Vec::with_capacity(N),
    };
    for _ in 0..N {
        let wo = direction(&mut rng);
        let wi = common::partner(&mut rng, wo, 8, direction);
        i.wo.push(wo);
        i.wi.push(wi);
        i.u.push(rng.next_vec2());
        i.uc.push(rng.next_f32());
    }
    i
}

/// Every call of the hot loop over all inputs, with the number of allocator calls they
/// made; panics naming `name` if there were any.
fn assert_no_alloc<M: Prepare>(name: &str, model: &M, i: &Inputs) {
    let (checksum, calls) = count_calls(|| {
        let mut sum = 0.0f32;
        for k in 0..N {
            let (wo, wi, u, uc) = (i.wo[k], i.wi[k], i.u[k], i.uc[k]);
            // The plain calls (the blanket `Bxdf` impl, through `Prepare`'s methods).
            sum += lobe::bxdf::Bxdf::eval(model, wo, wi).average();
            sum += lobe::bxdf::Bxdf::pdf(model, wo, wi);
            if let Some(s) = lobe::bxdf::Bxdf::sample(model, wo, u, uc) {
                sum += s.pdf + s.f.average() + s.wi.z;
            }
            // The prepared calls.
            let at = black_box(model.prepare(wo));
            sum += model.eval_prepared(&at, wi).average();
            sum += model.pdf_prepared(&at, wi);
            let (f, pdf) = model.eval_pdf_prepared(&at, wi);
            sum += f.average() + pdf;
            if let Some(s) = model.sample_prepared(&at, u, uc) {
                sum += s.pdf + s.f.average() + s.wi.z;
            }
        }
        black_box(sum)
    });
    assert_eq!(
        calls, 0,
        "{name}: {calls} allocator calls over {N} inputs (checksum {checksum})"
    );
}

fn alpha(a: f32) -> Alpha {
    Alpha::new(a).unwrap()
}

fn eta(e: f32) -> Eta {
    Eta::new(e).unwrap()
}

/// The extreme and a middle width: isotropic 1e-4, 0.3 and 10, anisotropic 1e-4 × 10.
fn alphas() -> [(Alpha, Alpha); 4] {
    [
        (alpha(1e-4), alpha(1e-4)),
        (alpha(0.3), alpha(0.3)),
        (alpha(10.0), alpha(10.0)),
        (alpha(1e-4), alpha(10.0)),
    ]
}

fn etas() -> [Eta; 4] {
    [eta(1.5), eta(1.0 / 1.5), eta(1.0 + 1e-4), eta(1e3)]
}

const MASKINGS: [Masking; 3] = [
    Masking::HeightCorrelated,
    Masking::Separable,
    Masking::VCavity,
];

fn gold() -> ComplexIor<Vec3> {
    lobe::metals::GOLD.rgb()
}

/// The counter itself: an allocation inside a counted section is seen, one outside is not,
/// and another thread's allocations do not reach this thread's count.
#[test]
fn the_counter_counts_this_threads_allocations_only() {
    let (v, calls) = count_calls(|| black_box(Vec::<u64>::with_capacity(16)));
    assert_eq!(calls, 1, "one allocation");
    let ((), calls) = count_calls(|| drop(black_box(v)));
    assert_eq!(calls, 1, "one deallocation");
    let (_, calls) = count_calls(|| black_box(0.5f32).sqrt());
    assert_eq!(calls, 0, "no allocation");
    // A first spawn caches what the standard library looks up once (the stack size).
    std::thread::scope(|s| s.spawn(|| ()).join().unwrap());
    let (_, calls) = count_calls(|| {
        std::thread::scope(|s| {
            // Spawning allocates on this thread; the spawned thread's own allocations must
            // not be counted here. Count once without them, then with them.
            s.spawn(|| black_box(vec![0u8; 64])).join().unwrap()
        })
    });
    let (_, baseline) = count_calls(|| std::thread::scope(|s| s.spawn(|| ()).join().unwrap()));
    assert_eq!(
        calls, baseline,
        "the other thread's vector does not reach this thread's count"
    );
}

#[test]
fn diffuse_models_do_not_allocate() {
    let i = inputs();
    for r in [0.0, 0.5, 1.0] {
        assert_no_alloc("Lambert", &Lambert::new(r).unwrap(), &i);
        assert_no_alloc(
            "Lambert RGB",
            &Lambert::new(Vec3::new(r, 0.5, 0.2)).unwrap(),
            &i,
        );
        assert_no_alloc(
            "OrenNayar",
            &OrenNayar::new(Vec3::splat(0.8), r * OrenNayar::<f32>::SIGMA_MAX).unwrap(),
            &i,
        );
        let eon = EnergyPreservingOrenNayar::new(Vec3::splat(0.8), r).unwrap();
        assert_no_alloc("EON", &eon, &i);
        assert_no_alloc("EON exact", &eon.with_exact_albedo(), &i);
        assert_no_alloc(
            "EON f32",
            &EnergyPreservingOrenNayar::new(0.8, r).unwrap(),
            &i,
        );
        assert_no_alloc(
            "DisneyDiffuse",
            &DisneyDiffuse::new(Vec3::splat(0.8), Roughness::new(r).unwrap()).unwrap(),
            &i,
        );
    }
}

#[test]
fn phong_models_do_not_allocate() {
    let i = inputs();
    for p in [0.0, 20.0, 1e6] {
        assert_no_alloc(
            "Phong",
            &Phong::new(Vec3::splat(0.3), Vec3::splat(0.6), p).unwrap(),
            &i,
        );
        assert_no_alloc("Phong f32", &Phong::new(0.0, 1.0, p).unwrap(), &i);
        for form in [BlinnPhongForm::Modified, BlinnPhongForm::Normalized] {
            assert_no_alloc(
                "BlinnPhong",
                &BlinnPhong::new(Vec3::splat(0.3), Vec3::splat(0.6), p, form).unwrap(),
                &i,
            );
            assert_no_alloc(
                "BlinnPhong f32",
                &BlinnPhong::new(1.0, 0.0, p, form).unwrap(),
                &i,
            );
        }
    }
}

#[test]
fn microfacet_models_do_not_allocate() {
    let i = inputs();
    let kappa50 = ComplexIor::new(0.5, 50.0).unwrap();
    for (ax, ay) in alphas() {
        for masking in MASKINGS {
            let conductor = Conductor { ior: gold() };
            assert_no_alloc(
                "Microfacet GGX",
                &Microfacet::new(Ggx::new(ax, ay), masking, conductor),
                &i,
            );
            assert_no_alloc(
                "Microfacet GGX unbounded",
                &Microfacet::new(
                    Ggx::new(ax, ay).with_bounded_reflection(false),
                    masking,
                    Schlick::new(Vec3::new(1.0, 0.78, 0.34)).unwrap(),
                ),
                &i,
            );
            assert_no_alloc(
                "Microfacet Beckmann",
                &Microfacet::new(Beckmann::new(ax, ay), masking, conductor),
                &i,
            );
            assert_no_alloc(
                "Microfacet Beckmann Walter",
                &Microfacet::new(
                    Beckmann::new(ax, ay).with_masking(BeckmannMasking::WalterRational),
                    masking,
                    Conductor { ior: kappa50 },
                ),
                &i,
            );
            assert_no_alloc(
                "Microfacet GTR",
                &Microfacet::new(Gtr::new(ax, 1.5).unwrap(), masking, conductor),
                &i,
            );
            let narrow = alpha(ax.get().min(1.0));
            assert_no_alloc(
                "Microfacet BlinnPhongNdf",
                &Microfacet::new(BlinnPhongNdf::new(narrow).unwrap(), masking, conductor),
                &i,
            );
            assert_no_alloc(
                "Microfacet BlinnPhongNdf exact Smith",
                &Microfacet::new(
                    BlinnPhongNdf::new(narrow).unwrap().with_exact_smith(),
                    masking,
                    Dielectric { eta: eta(1.5) },
                ),
                &i,
            );
            assert_no_alloc(
                "Microfacet GTR γ = 10, no Fresnel",
                &Microfacet::new(
                    Gtr::new(ax, 10.0).unwrap(),
                    masking,
                    NoFresnel::<f32>::new(),
                ),
                &i,
            );
        }
    }
}

#[test]
fn dielectric_models_do_not_allocate() {
    let i = inputs();
    for e in etas() {
        for mode in [TransportMode::Radiance, TransportMode::Importance] {
            for (ax, ay) in alphas() {
                for masking in MASKINGS {
                    assert_no_alloc(
                        "RoughDielectric GGX",
                        &RoughDielectric::new(Ggx::new(ax, ay), e)
                            .with_masking(masking)
                            .with_mode(mode),
                        &i,
                    );
                }
                assert_no_alloc(
                    "RoughDielectric Beckmann",
                    &RoughDielectric::new(Beckmann::new(ax, ay), e).with_mode(mode),
                    &i,
                );
                assert_no_alloc(
                    "RoughDielectric GTR",
                    &RoughDielectric::new(Gtr::new(ax, 2.5).unwrap(), e).with_mode(mode),
                    &i,
                );
            }
            assert_no_alloc(
                "SmoothDielectric",
                &SmoothDielectric::new(e).with_mode(mode),
                &i,
            );
        }
        assert_no_alloc("ThinDielectric", &ThinDielectric::new(e), &i);
        assert_no_alloc("Mirror dielectric", &Mirror::new(Dielectric { eta: e }), &i);
    }
    assert_no_alloc("Mirror gold", &Mirror::new(Conductor { ior: gold() }), &i);
    assert_no_alloc(
        "Mirror Schlick",
        &Mirror::new(Schlick::new(0.04f32).unwrap()),
        &i,
    );
}

#[test]
fn coated_models_do_not_allocate() {
    let i = inputs();
    for e in [eta(1.5), eta(1.0 + 1e-4), eta(1e3)] {
        for r in [0.0, 1.0] {
            assert_no_alloc(
                "Glazed",
                &Glazed::new(Vec3::new(r, 0.5, 0.2), e).unwrap(),
                &i,
            );
            assert_no_alloc("Glazed f32", &Glazed::new(r, e).unwrap(), &i);
        }
        for (a, _) in [alphas()[0], alphas()[1]] {
            assert_no_alloc(
                "Plastic GGX",
                &Plastic::new(Vec3::new(0.8, 0.5, 0.2), Ggx::isotropic(a), e).unwrap(),
                &i,
            );
            assert_no_alloc(
                "Plastic Beckmann",
                &Plastic::new(0.5f32, Beckmann::isotropic(a), e).unwrap(),
                &i,
            );
        }
    }
}

/// The seeded calls of a stochastic model, counted like [`assert_no_alloc`]'s.
fn assert_seeded_no_alloc<M: Prepare>(name: &str, model: &M, i: &Inputs) {
    let (checksum, calls) = count_calls(|| {
        let mut sum = 0.0f32;
        for k in 0..N {
            let (wo, wi) = (i.wo[k], i.wi[k]);
            sum += lobe::bxdf::Bxdf::eval_seeded(model, wo, wi, k as u64).average();
            sum += lobe::bxdf::Bxdf::pdf_seeded(model, wo, wi, k as u64);
        }
        black_box(sum)
    });
    assert_eq!(
        calls, 0,
        "{name}: {calls} allocator calls over {N} seeded inputs (checksum {checksum})"
    );
}

/// The combinators and the stochastic layered models (issue 12): the random walk lives on
/// the stack (its generator is eight bytes), and so do the blends' prepared states.
#[test]
fn composed_models_do_not_allocate() {
    use lobe::bxdf::{
        CoatedConductor, CoatedDiffuse, DiffuseTransmission, Layered, Mix, Sheen, TwoSided,
    };
    let i = inputs();
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    for e in [eta(1.5), eta(1e3)] {
        let coated = CoatedDiffuse::coated_diffuse(rgb, Ggx::isotropic(alpha(0.3)), e).unwrap();
        assert_no_alloc("CoatedDiffuse", &coated, &i);
        assert_seeded_no_alloc("CoatedDiffuse", &coated, &i);
        let scattering = coated
            .with_thickness(0.5)
            .unwrap()
            .with_medium(rgb, 0.3)
            .unwrap()
            .with_samples(4)
            .unwrap();
        assert_no_alloc("CoatedDiffuse with a medium", &scattering, &i);
        assert_seeded_no_alloc("CoatedDiffuse with a medium", &scattering, &i);
        let conductor = CoatedConductor::coated_conductor(
            Ggx::isotropic(alpha(0.1)),
            e,
            Beckmann::isotropic(alpha(0.3)),
            gold(),
        )
        .unwrap();
        assert_no_alloc("CoatedConductor", &conductor, &i);
        let smooth = Layered::new(SmoothDielectric::new(e), Lambert::new(0.5f32).unwrap());
        assert_no_alloc("smooth coat", &smooth, &i);
        assert_seeded_no_alloc("smooth coat", &smooth, &i);
        // Over a base with a delta lobe, with a scattering layer: the delta chains.
        let half_mirror = Mix::new(
            lobe::bxdf::Mirror::new(lobe::fresnel::NoFresnel::<f32>::new()),
            Lambert::new(0.5f32).unwrap(),
            0.5,
        )
        .unwrap();
        let chains = Layered::new(SmoothDielectric::new(e), half_mirror)
            .with_thickness(0.5)
            .unwrap()
            .with_medium(0.9, 0.0)
            .unwrap();
        assert_no_alloc("smooth coat over Mix(Mirror, Lambert)", &chains, &i);
        assert_seeded_no_alloc("smooth coat over Mix(Mirror, Lambert)", &chains, &i);
        assert_no_alloc("TwoSided(CoatedDiffuse)", &TwoSided::new(coated), &i);
        let mix = Mix::new(coated, Lambert::new(rgb).unwrap(), 0.4).unwrap();
        assert_no_alloc("Mix(CoatedDiffuse, Lambert)", &mix, &i);
        assert_seeded_no_alloc("Mix(CoatedDiffuse, Lambert)", &mix, &i);
    }
    let gloss = Microfacet::new(
        Ggx::isotropic(alpha(0.2)),
        Masking::HeightCorrelated,
        Conductor { ior: gold() },
    );
    assert_no_alloc(
        "Mix(Lambert, GGX)",
        &Mix::new(Lambert::new(rgb).unwrap(), gloss, 0.5).unwrap(),
        &i,
    );
    assert_no_alloc("TwoSided(GGX)", &TwoSided::new(gloss), &i);
    assert_no_alloc(
        "DiffuseTransmission",
        &DiffuseTransmission::new(rgb * 0.5, rgb * 0.5).unwrap(),
        &i,
    );
    assert_no_alloc("Sheen", &Sheen::new(rgb, 0.3).unwrap(), &i);
    assert_no_alloc(
        "Sheen, exact Smith",
        &Sheen::new(rgb, 0.3).unwrap().with_exact_smith(),
        &i,
    );
}

/// The batched calls (`lobe::batch`) of the three models the issue names, RGB and mono, and
/// of the models built from others, including their run-time dispatch to the widest SIMD the
/// CPU has: no allocation either.
#[test]
fn batched_calls_do_not_allocate() {
    use lobe::batch::{Batch, SampleOut, Vec2s, Vec3s};
    let i = inputs();
    let col = |v: &[Vec3], c: usize| v.iter().map(|w| w[c]).collect::<Vec<f32>>();
    let (wox, woy, woz) = (col(&i.wo, 0), col(&i.wo, 1), col(&i.wo, 2));
    let (wix, wiy, wiz) = (col(&i.wi, 0), col(&i.wi, 1), col(&i.wi, 2));
    let ux: Vec<f32> = i.u.iter().map(|u| u.x).collect();
    let uy: Vec<f32> = i.u.iter().map(|u| u.y).collect();
    let wo = Vec3s {
        x: &wox,
        y: &woy,
        z: &woz,
    };
    let wi = Vec3s {
        x: &wix,
        y: &wiy,
        z: &wiz,
    };
    let u = Vec2s { x: &ux, y: &uy };
    let mut out: Vec<Vec<f32>> = vec![vec![0.0; N]; 8];
    let mut lobes = vec![lobe::bxdf::Lobes::NONE; N];
    let conductor = Microfacet::new(
        Ggx::isotropic(alpha(0.3)),
        Masking::HeightCorrelated,
        Conductor { ior: gold() },
    );
    let schlick = Microfacet::new(
        Ggx::isotropic(alpha(0.3)),
        Masking::VCavity,
        Schlick::new(Vec3::new(0.9, 0.6, 0.3)).unwrap(),
    );
    let lambert = Lambert::new(Vec3::new(0.8, 0.5, 0.2)).unwrap();
    let glass = RoughDielectric::new(Ggx::isotropic(alpha(0.3)), eta(1.5));
    // All three calls of an RGB model into the eight buffers and the lobes.
    fn rgb_calls<M: Batch<Spectrum = Vec3>>(
        m: &M,
        wo: Vec3s,
        wi: Vec3s,
        u: Vec2s,
        uc: &[f32],
        o: &mut [Vec<f32>],
        lobes: &mut [lobe::bxdf::Lobes],
    ) {
        let [a, b, c, d, e, f, g, h] = o else {
            unreachable!()
        };
        m.eval_batch(wo, wi, rgb(a, b, c)).unwrap();
        m.pdf_batch(wo, wi, d).unwrap();
        let out = SampleOut {
            wi: rgb(a, b, c),
            f: rgb(d, e, f),
            pdf: g,
            lobe: lobes,
            eta: h,
        };
        m.sample_batch(wo, u, uc, out).unwrap();
    }
    let ((), calls) = count_calls(|| {
        rgb_calls(&conductor, wo, wi, u, &i.uc, &mut out, &mut lobes);
        rgb_calls(&schlick, wo, wi, u, &i.uc, &mut out, &mut lobes);
        rgb_calls(&lambert, wo, wi, u, &i.uc, &mut out, &mut lobes);
        // The models built from others, whose parts' calls take chunks in stack space.
        let mix = lobe::bxdf::Mix::new(lambert, conductor, 0.5).unwrap();
        rgb_calls(&mix, wo, wi, u, &i.uc, &mut out, &mut lobes);
        let two_sided = lobe::bxdf::TwoSided::new(conductor);
        rgb_calls(&two_sided, wo, wi, u, &i.uc, &mut out, &mut lobes);
        let mono = lobe::bxdf::Mono::<_, Vec3>::new(glass);
        rgb_calls(&mono, wo, wi, u, &i.uc, &mut out, &mut lobes);
        let [a, b, c, d, e, f, g, h] = &mut out[..] else {
            unreachable!()
        };
        glass.eval_batch(wo, wi, &mut *a).unwrap();
        glass.pdf_batch(wo, wi, &mut *b).unwrap();
        glass
            .sample_batch(
                wo,
                u,
                &i.uc,
                SampleOut {
                    wi: rgb(c, d, e),
                    f: &mut *f,
                    pdf: g,
                    lobe: &mut lobes,
                    eta: h,
                },
            )
            .unwrap();
    });
    black_box((&out, &lobes));
    assert_eq!(calls, 0, "the batched calls allocated {calls} times");
}

/// Three slices as one RGB output.
fn rgb<'a>(x: &'a mut [f32], y: &'a mut [f32], z: &'a mut [f32]) -> lobe::batch::Vec3sMut<'a> {
    lobe::batch::Vec3sMut { x, y, z }
}
