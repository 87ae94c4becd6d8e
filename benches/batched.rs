//! The batched calls (`lobe::batch`) of 25 configurations of models and combinators, against their
//! scalar calls, on the 4,096 inputs of `benches/common/inputs.rs` (the transmissive models with
//! the sides mixed, `TwoSided` seen from below for half of them), in interleaved rounds.
//!
//! ```sh
//! cargo bench --bench batched            # all 25
//! cargo bench --bench batched -- Mix     # the models whose name contains "Mix"
//! cargo bench --bench batched -- --test  # one short round (CI runs every bench so)
//! cargo bench --bench batched -- --lanes 16  # batched calls of 16 lanes each
//! ```
//!
//! With `--lanes L`, every batched kernel passes the 4,096 inputs in calls of `L` lanes (the
//! last call shorter where `L` does not divide 4,096), as a renderer that sorts a wavefront
//! by material would: a batch of tens of lanes pays for the call and for the lanes that do
//! not fill the last vector.
//!
//! Each round times every kernel once, in turn (scalar `eval`, batched `eval`, scalar `pdf`,
//! … of one model, then the next model's), so that the machine's drift falls on all of them
//! alike; the table gives each kernel's median time per lane over the rounds with its range,
//! and the median of the per-round ratios batched / scalar. A ratio above 1 is a batched
//! loop slower than the scalar calls. The batched calls' results are the scalar calls',
//! bit for bit (`tests/batch.rs`): this bench times them only.

// `Inputs::uc` and friends are read by the other benches too.
#[allow(dead_code)]
#[path = "common/inputs.rs"]
mod inputs;
#[path = "common/interleave.rs"]
mod interleave;

use inputs::{Inputs, N, inputs, mirrored, two_sided};
use interleave::Kernel;
use lobe::batch::{Batch, Lanes, SampleOut, Vec2s, Vec3s, Vec3sMut};
use lobe::bxdf::{
    BlinnPhong, BlinnPhongForm, Bxdf, CoatedDiffuse, CompensatedDielectric, DiffuseTransmission,
    DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert, Lobes, Microfacet, Mirror, Mix,
    Mono, OrenNayar, Phong, Plastic, Prepare, RoughDielectric, Sheen, SmoothDielectric,
    ThinDielectric, TwoSided,
};
use lobe::fresnel::{Conductor, Dielectric, Schlick};
use lobe::microfacet::{Beckmann, Ggx, Masking};
use lobe::{Alpha, Eta, Roughness, Vec3, metals};
use std::hint::black_box;
use std::ops::Range;
use std::time::Duration;

/// Three coordinate slices.
struct Soa([Vec<f32>; 3]);

impl Soa {
    fn of(v: &[Vec3]) -> Self {
        Self([0, 1, 2].map(|c| v.iter().map(|w| w[c]).collect()))
    }

    fn zeros() -> Self {
        Self([vec![0.0; N], vec![0.0; N], vec![0.0; N]])
    }

    fn view(&self) -> Vec3s<'_> {
        let [x, y, z] = &self.0;
        Vec3s { x, y, z }
    }

    fn view_mut(&mut self) -> Vec3sMut<'_> {
        let [x, y, z] = &mut self.0;
        Vec3sMut { x, y, z }
    }
}

/// A spectrum's output slices, owned.
trait Store: Lanes {
    type Owned;
    /// `N` lanes of zeros.
    fn zeros() -> Self::Owned;
    /// All the lanes, as a batched call's output.
    fn lanes_mut(o: &mut Self::Owned) -> Self::Mut<'_>;
    /// Lanes `r` of an output.
    fn part<'a>(o: Self::Mut<'a>, r: Range<usize>) -> Self::Mut<'a>;
}

impl Store for f32 {
    type Owned = Vec<f32>;
    fn zeros() -> Vec<f32> {
        vec![0.0; N]
    }
    fn lanes_mut(o: &mut Vec<f32>) -> &mut [f32] {
        o
    }
    fn part<'a>(o: Self::Mut<'a>, r: Range<usize>) -> Self::Mut<'a> {
        &mut o[r]
    }
}

impl Store for Vec3 {
    type Owned = Soa;
    fn zeros() -> Soa {
        Soa::zeros()
    }
    fn lanes_mut(o: &mut Soa) -> Vec3sMut<'_> {
        o.view_mut()
    }
    fn part<'a>(o: Self::Mut<'a>, r: Range<usize>) -> Self::Mut<'a> {
        part_mut(o, r)
    }
}

/// One set of inputs as slices.
struct Lanesets {
    wo: Soa,
    wi: Soa,
    u: [Vec<f32>; 2],
    uc: Vec<f32>,
}

impl Lanesets {
    fn of(i: &Inputs) -> Self {
        Self {
            wo: Soa::of(&i.wo),
            wi: Soa::of(&i.wi),
            u: [
                i.u.iter().map(|u| u.x).collect(),
                i.u.iter().map(|u| u.y).collect(),
            ],
            uc: i.uc.clone(),
        }
    }

    fn u(&self) -> Vec2s<'_> {
        Vec2s {
            x: &self.u[0],
            y: &self.u[1],
        }
    }
}

/// Lanes `r` of three coordinate slices.
fn part(v: Vec3s<'_>, r: Range<usize>) -> Vec3s<'_> {
    let (x, y, z) = (&v.x[r.clone()], &v.y[r.clone()], &v.z[r]);
    Vec3s { x, y, z }
}

/// Lanes `r` of three output slices.
fn part_mut(v: Vec3sMut<'_>, r: Range<usize>) -> Vec3sMut<'_> {
    let (x, y, z) = (&mut v.x[r.clone()], &mut v.y[r.clone()], &mut v.z[r]);
    Vec3sMut { x, y, z }
}

/// The calls of `lanes` lanes (at most) that cover the inputs.
fn calls(lanes: usize) -> impl Iterator<Item = Range<usize>> {
    (0..N).step_by(lanes).map(move |s| s..(s + lanes).min(N))
}

/// A model both paths take, with one spectrum.
trait Timed: Batch<Spectrum: Store> + Bxdf<Spectrum = <Self as Prepare>::Spectrum> {}

impl<M: Batch<Spectrum: Store> + Bxdf<Spectrum = <M as Prepare>::Spectrum>> Timed for M {}

/// The six kernels of one model: scalar and batched `eval`, `pdf` and `sample`, the batched
/// ones in calls of `lanes` lanes.
fn kernels<'a, M: Timed + 'a>(
    name: &str,
    m: M,
    (i, l): (&'a Inputs, &'a Lanesets),
    lanes: usize,
) -> Vec<Kernel<'a>> {
    type S<M> = <M as Prepare>::Spectrum;
    let m = black_box(m);
    let (m1, m2, m3, m4, m5) = (m.clone(), m.clone(), m.clone(), m.clone(), m.clone());
    let mut f = S::<M>::zeros();
    let mut pdf = vec![0.0; N];
    let (mut wi, mut sf, mut spdf) = (Soa::zeros(), S::<M>::zeros(), vec![0.0; N]);
    let (mut lobe, mut eta) = (vec![Lobes::NONE; N], vec![0.0; N]);
    vec![
        Kernel::new(format!("{name}|eval|scalar"), N, move || {
            for k in 0..N {
                black_box(m1.eval(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name}|eval|batched"), N, move || {
            for r in calls(lanes) {
                let out = S::<M>::part(S::<M>::lanes_mut(&mut f), r.clone());
                let (wo, wi) = (part(l.wo.view(), r.clone()), part(l.wi.view(), r));
                m2.eval_batch(wo, wi, out).unwrap();
            }
            black_box(&f);
        }),
        Kernel::new(format!("{name}|pdf|scalar"), N, move || {
            for k in 0..N {
                black_box(m3.pdf(i.wo[k], i.wi[k]));
            }
        }),
        Kernel::new(format!("{name}|pdf|batched"), N, move || {
            for r in calls(lanes) {
                let (wo, wi) = (part(l.wo.view(), r.clone()), part(l.wi.view(), r.clone()));
                m4.pdf_batch(wo, wi, &mut pdf[r]).unwrap();
            }
            black_box(&pdf);
        }),
        Kernel::new(format!("{name}|sample|scalar"), N, move || {
            for k in 0..N {
                black_box(m5.sample(i.wo[k], i.u[k], i.uc[k]));
            }
        }),
        Kernel::new(format!("{name}|sample|batched"), N, move || {
            for r in calls(lanes) {
                let out = SampleOut {
                    wi: part_mut(wi.view_mut(), r.clone()),
                    f: S::<M>::part(S::<M>::lanes_mut(&mut sf), r.clone()),
                    pdf: &mut spdf[r.clone()],
                    lobe: &mut lobe[r.clone()],
                    eta: &mut eta[r.clone()],
                };
                let u = l.u();
                let u = Vec2s {
                    x: &u.x[r.clone()],
                    y: &u.y[r.clone()],
                };
                m.sample_batch(part(l.wo.view(), r.clone()), u, &l.uc[r], out)
                    .unwrap();
            }
            black_box(&spdf);
        }),
    ]
}

fn a(x: f32) -> Alpha {
    Alpha::new(x).unwrap()
}

fn main() {
    // `cargo bench` passes `--bench`; a further argument filters the models by name, and
    // `--test` (CI's smoke run of every bench) times one short round.
    let args: Vec<String> = std::env::args().skip(1).collect();
    // The filter: the first argument that is neither a flag nor `--lanes`'s number.
    let filter = args
        .iter()
        .enumerate()
        .find(|&(p, a)| !a.starts_with("--") && (p == 0 || args[p - 1] != "--lanes"))
        .map(|(_, a)| a.clone())
        .unwrap_or_default();
    if let Some(a) = args.iter().find(|a| a.starts_with("--lanes=")) {
        panic!("{a}: write `--lanes L`, with a space");
    }
    let lanes = match args.iter().position(|a| a == "--lanes") {
        Some(p) => match args.get(p + 1).and_then(|l| l.parse::<usize>().ok()) {
            Some(l) if l > 0 => l,
            _ => panic!("--lanes wants a number of lanes per call, 1 or more"),
        },
        None => N,
    };
    let (rounds, per_round) = if args.iter().any(|a| a == "--test") {
        (1, Duration::from_millis(1))
    } else {
        (15, Duration::from_millis(20))
    };
    let (above, sides) = (inputs(), two_sided(&inputs()));
    let below = mirrored(&above);
    let (la, ls, lb) = (
        Lanesets::of(&above),
        Lanesets::of(&sides),
        Lanesets::of(&below),
    );
    let (i, s, b) = ((&above, &la), (&sides, &ls), (&below, &lb));
    let rgb = Vec3::new(0.8, 0.5, 0.2);
    let glass = Eta::new(1.5).unwrap();
    let hc = Masking::HeightCorrelated;
    let gold = Conductor {
        ior: metals::GOLD.rgb(),
    };
    let ggx_gold = Microfacet::new(Ggx::isotropic(a(0.3)), hc, gold);
    let lambert = Lambert::new(rgb).unwrap();
    let rough = RoughDielectric::new(Ggx::isotropic(a(0.3)), glass);

    let mut all: Vec<Kernel<'_>> = Vec::new();
    macro_rules! time {
        ($name:expr, $model:expr, $inputs:expr) => {
            if $name.contains(filter.as_str()) {
                all.extend(kernels($name, $model, $inputs, lanes));
            }
        };
    }
    time!("Lambert", lambert, i);
    time!("Oren-Nayar σ 0.4", OrenNayar::new(rgb, 0.4).unwrap(), i);
    let eon = EnergyPreservingOrenNayar::new(rgb, 0.4).unwrap();
    time!("EON r 0.4", eon, i);
    let disney = DisneyDiffuse::new(rgb, Roughness::new(0.5).unwrap()).unwrap();
    time!("Disney diffuse", disney, i);
    let phong = Phong::new(rgb * 0.5, Vec3::splat(0.4), 30.0).unwrap();
    time!("Phong n 30", phong, i);
    let form = BlinnPhongForm::Normalized;
    let blinn = BlinnPhong::new(rgb * 0.5, Vec3::splat(0.4), 30.0, form).unwrap();
    time!("Blinn-Phong n 30", blinn, i);
    time!("Glazed η 1.5", Glazed::new(rgb, glass).unwrap(), i);
    let schlick = Schlick::new(Vec3::new(0.95, 0.64, 0.54)).unwrap();
    time!(
        "GGX Schlick α 0.3",
        Microfacet::new(Ggx::isotropic(a(0.3)), hc, schlick),
        i
    );
    time!("GGX gold α 0.3", ggx_gold, i);
    let beckmann = Microfacet::new(Beckmann::isotropic(a(0.3)), hc, gold);
    time!("Beckmann gold α 0.3", beckmann, i);
    let compensated = ggx_gold.with_energy_compensation().unwrap();
    time!("GGX gold α 0.3 compensated", compensated, i);
    let plastic = Plastic::new(rgb, Ggx::isotropic(a(0.2)), glass).unwrap();
    time!("Plastic α 0.2", plastic, i);
    let plastic = Plastic::compensated(rgb, Ggx::isotropic(a(0.2)), glass).unwrap();
    time!("Plastic α 0.2 compensated", plastic, i);
    time!("Sheen r 0.5", Sheen::new(rgb, 0.5).unwrap(), i);
    let sheet = DiffuseTransmission::new(rgb * 0.5, rgb * 0.4).unwrap();
    time!("DiffuseTransmission", sheet, s);
    time!(
        "Mix(Lambert, GGX gold) w 0.5",
        Mix::new(lambert, ggx_gold, 0.5).unwrap(),
        i
    );
    time!(
        "Mix(Lambert, Beckmann gold) w 0.5",
        Mix::new(lambert, beckmann, 0.5).unwrap(),
        i
    );
    time!("TwoSided(GGX gold), half below", TwoSided::new(ggx_gold), b);
    time!("Mono(rough glass) RGB", Mono::<_, Vec3>::new(rough), s);
    let coated = CoatedDiffuse::coated_diffuse(rgb, Ggx::isotropic(a(0.3)), glass).unwrap();
    time!("CoatedDiffuse α 0.3 (1 walk)", coated, i);
    time!("rough glass α 0.3 (mono)", rough, s);
    let compensated = CompensatedDielectric::new(rough).unwrap();
    time!("rough glass α 0.3 compensated (mono)", compensated, s);
    time!(
        "Mirror, dielectric (mono)",
        Mirror::new(Dielectric { eta: glass }),
        i
    );
    time!("smooth glass (mono)", SmoothDielectric::new(glass), s);
    time!("thin glass (mono)", ThinDielectric::new(glass), s);

    let times = interleave::rounds(&mut all, rounds, per_round);
    println!("| model | call | scalar (ns per lane) | batched | batched / scalar |");
    println!("| --- | --- | --- | --- | --- |");
    for (k, t) in all.chunks(2).zip(times.chunks(2)) {
        let (s, s_min, s_max) = interleave::spread(&t[0]);
        let (b, b_min, b_max) = interleave::spread(&t[1]);
        let (r, r_min, r_max) = interleave::ratio(&t[1], &t[0]);
        let mut parts = k[0].name.split('|');
        let (model, call) = (parts.next().unwrap(), parts.next().unwrap());
        println!(
            "| {model} | {call} | {s:.2} [{s_min:.2}, {s_max:.2}] | {b:.2} [{b_min:.2}, \
             {b_max:.2}] | {r:.2} [{r_min:.2}, {r_max:.2}] |"
        );
    }
    println!("instruction set: {}", lobe::batch::instruction_set().name());
    println!("batched calls of {} lanes", lanes.min(N));
}
