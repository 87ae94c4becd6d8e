//! GGX and Beckmann against every record of the Mitsuba 3.9.1 microfacet reference set
//! (`tests/data/mitsuba_microfacet.json`, `tests/data/mitsuba_microfacet_sample.json`;
//! conventions in `tests/data/mitsuba_CONVENTIONS.md` §1, tolerances in §5).
//!
//! **Which conventions are checked.** Mitsuba's `MicrofacetDistribution` is compared with
//! lobe's [`Ggx`] (exact Smith `G1`, as Mitsuba) and with lobe's [`Beckmann`] built with
//! [`BeckmannMasking::WalterRational`]: Mitsuba's Beckmann `G1` is Walter et al.'s (2007)
//! rational approximation, not the exact erf form that is lobe's default. lobe implements
//! the same rational form, so it inherits its quirks: `G1` exceeds 1 by up to 6.1e-5 just
//! below `a = 1.6` and jumps there by 5.7e-5 (both far inside the tolerance; one public record
//! has Mitsuba's `smith_g1_wo` = 1.0000261, and lobe agrees).
//!
//! **Mapping.** Mitsuba's `wi` is the viewer side (lobe's `wo`) and its `wo` the other side
//! (lobe's `wi`). For these per-direction functions only the placement of each field matters;
//! the JSON names are kept below.
//!
//! | Mitsuba | lobe |
//! | --- | --- |
//! | `eval(m)` = `D` | [`d(m)`](NormalDistribution::d) |
//! | `smith_g1(v, m)` | `0` if `(v·m)·v.z ≤ 0`, else [`g1(v)`](NormalDistribution::g1) (which is `1` at normal incidence, as Mitsuba's special case) |
//! | `G(wi, wo, m)` | [`g2_separable`](NormalDistribution::g2_separable) times both orientation factors `χ⁺((v·m)·v.z)` |
//! | `pdf(wi, m)`, `sample_visible = true` | [`d_visible(wi, m)`](NormalDistribution::d_visible) for `wi.z > 0`; `−d_visible(−wi, m)` for `wi.z < 0`; for Walter's rational `G1`, times `G1_rational(wi) / G1_exact(wi)` (lobe's density keeps the exact `G1`, which normalises what the sampler draws; Mitsuba's takes the rational one) |
//! | `pdf(wi, m)`, `sample_visible = false` | `D(m)·max(0, m.z)`, the density of [`SampleDCos`](lobe::microfacet::SampleDCos) |
//!
//! Mitsuba's visible pdf `D·smith_g1(wi, m)·|wi·m|/wi.z` is negative for `wi.z < 0`
//! (CONVENTIONS §6), whereas lobe's `d_visible` mirrors `wi` to the upper hemisphere. With
//! `G1(−w) = G1(w)`, Mitsuba's value there is exactly `−d_visible(−wi, m)`, and the test maps
//! it so. **No public record has `wi.z < 0`** (the test counts and prints them: 0), so that
//! branch of the mapping is exercised only if a set with such records is dropped in.
//!
//! **Zeros.** Mitsuba sets `D = 0` unless `D·m.z > 1e-20`; lobe returns the formula's value
//! down to `f32` underflow. A Beckmann tail below that cut is `≤ 1e-20/m.z`, far below the
//! absolute tolerance `1e-9`, so the test accepts it and lists such values (public set: one
//! Beckmann record, `D` = 2.9e-27 where Mitsuba has 0). Apart from
//! that, a value above `1e-9` where Mitsuba has `0` is a failure: the zeros test the
//! conventions (`m.z ≤ 0`, back-facing `v·m`). Mitsuba writes `pdf_no_visible = −0.0` for
//! `m.z < 0`; the comparison is numeric, so `+0` and `−0` agree.
//!
//! **Tolerance** (§5): `|lobe − oracle| ≤ 1e-9 + 1e-3·|oracle|` on every value.
//!
//! **Sampling.** lobe draws visible normals with other algorithms (GGX: spherical caps,
//! Dupuy & Benyoub 2023; Beckmann: a safeguarded Newton inversion) than Mitsuba (Heitz 2018;
//! Jakob 2014), so the same `(u1, u2)` gives a different `m`, which is not compared. What must
//! agree is the density: lobe's `d_visible(wi, m)` at Mitsuba's recorded `m` against the
//! recorded `pdf` (the same tolerance; §5 puts Mitsuba's own noise there at ≤ 7.5e-6 on every
//! record, the `u_extreme` ones included). Each record's `(wi, u)` is also fed to lobe's
//! sampler, which must return a finite unit `m` with `m.z ≥ 0` and `d_visible(wi, m) > 0`.
//!
//! The last tests show the check can fail: the exact Beckmann `G1`, a GGX `D` off by 1%, and
//! `G1` without the orientation factor are each rejected.

mod common;

use common::reference::{
    Dev, Kind, assert_no_failures, field, field32, load, print_devs, vec_field,
};

use lobe::microfacet::{Beckmann, BeckmannMasking, Ggx, NormalDistribution, Sampling, View};
use lobe::{Alpha, Vec2, Vec3};
use serde_json::Value;

/// §5: `|lobe − oracle| ≤ ATOL + RTOL·|oracle|`.
const ATOL: f64 = 1e-9;
const RTOL: f64 = 1e-3;

/// How far from unit length a sampled normal may be (a few f32 ulps after `normalize`).
const UNIT_TOL: f32 = 1e-5;

const MICROFACET: &str = include_str!("data/mitsuba_microfacet.json");
const MICROFACET_SAMPLE: &str = include_str!("data/mitsuba_microfacet_sample.json");

/// The quantities of a `microfacet.json` record, in the order of [`mitsuba_values`].
const QUANTITIES: [&str; 6] = [
    "D",
    "smith_g1_wi",
    "smith_g1_wo",
    "G",
    "pdf",
    "pdf_no_visible",
];

// ---------------------------------------------------------------------------------------------
// Reading the records
// ---------------------------------------------------------------------------------------------

fn alpha(r: &Value, name: &str) -> Alpha {
    Alpha::new(field32(r, name)).unwrap_or_else(|e| panic!("{name} of {r}: {e}"))
}

/// GGX with the record's widths (`alpha_u` along local x, `alpha_v` along y).
fn ggx(r: &Value) -> Ggx {
    Ggx::new(alpha(r, "alpha_u"), alpha(r, "alpha_v"))
}

/// Beckmann with the record's widths and Mitsuba's masking, Walter's rational `G1`.
fn beckmann_walter(r: &Value) -> Beckmann {
    Beckmann::new(alpha(r, "alpha_u"), alpha(r, "alpha_v"))
        .with_masking(BeckmannMasking::WalterRational)
}

fn context(i: usize, r: &Value) -> String {
    format!(
        "record {i} ({} {}, alpha {}×{})",
        r["distribution"].as_str().unwrap_or("?"),
        r["case"].as_str().unwrap_or("?"),
        field(r, "alpha_u"),
        field(r, "alpha_v"),
    )
}

// ---------------------------------------------------------------------------------------------
// Mitsuba's functions in lobe's terms
// ---------------------------------------------------------------------------------------------

/// Mitsuba's orientation rule in `smith_g1(v, m)`: `v` and `m` must be on the same side of
/// the microsurface as `v` is of the macrosurface, `(v·m)·v.z > 0`.
fn oriented(v: Vec3, m: Vec3) -> bool {
    v.dot(m) * v.z > 0.0
}

/// Whether the Mitsuba mapping applies the orientation factor to `G1` (the real mapping
/// does; a mutant without it shows that the zero records catch its absence).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Orientation {
    Mitsuba,
    Ignored,
}

/// Mitsuba's `smith_g1(v, m)`: lobe's `g1(v)` (no `χ⁺` inside) times the orientation factor.
fn smith_g1<N: NormalDistribution + ?Sized>(n: &N, v: Vec3, m: Vec3, o: Orientation) -> f32 {
    if o == Orientation::Mitsuba && !oriented(v, m) {
        0.0
    } else {
        n.g1(v)
    }
}

/// Mitsuba's `pdf(wi, m)` with `sample_visible = true`, `D·smith_g1(wi, m)·|wi·m|/wi.z`.
/// For `wi.z < 0` it is negative: `−d_visible(−wi, m)`, because `G1` is even in `wi`.
/// `d_visible` normalises with the exact `G1` (the view's `visible` factor), Mitsuba with the
/// `G1` it masks with: for Walter's rational `G1` the two differ by `G1_rational / G1_exact`
/// (up to 0.31%), which this puts back (for the exact masking functions it is 1 to rounding).
fn visible_pdf<N: NormalDistribution + ?Sized>(n: &N, wi: Vec3, m: Vec3) -> f32 {
    let (sign, w) = if wi.z < 0.0 { (-1.0, -wi) } else { (1.0, wi) };
    let visible = n.view(w).visible;
    let scale = if visible > 0.0 {
        n.g1(w) / (visible * w.z)
    } else {
        1.0
    };
    sign * n.d_visible(w, m) * scale
}

/// lobe's values for the quantities of a `microfacet.json` record, in [`QUANTITIES`] order.
/// `wi`, `wo` are Mitsuba's (viewer side first): lobe's `wo`, `wi`.
fn mitsuba_values<N: NormalDistribution + ?Sized>(n: &N, r: &Value, o: Orientation) -> [f64; 6] {
    let (wi, wo, m) = (vec_field(r, "wi"), vec_field(r, "wo"), vec_field(r, "m"));
    let g1_wi = smith_g1(n, wi, m, o);
    let g1_wo = smith_g1(n, wo, m, o);
    // Separable G from lobe's own `g2_separable(wo_lobe, wi_lobe)`, with both χ⁺ factors.
    let g = if o == Orientation::Ignored || (oriented(wi, m) && oriented(wo, m)) {
        n.g2_separable(wi, wo)
    } else {
        0.0
    };
    [
        n.d(m),
        g1_wi,
        g1_wo,
        g,
        visible_pdf(n, wi, m),
        n.d(m) * m.z.max(0.0),
    ]
    .map(f64::from)
}

// ---------------------------------------------------------------------------------------------
// Bookkeeping
// ---------------------------------------------------------------------------------------------

#[derive(Debug, Default)]
struct Report {
    records: usize,
    devs: Vec<(String, Dev)>,
    failures: Vec<String>,
    /// Records with at least one failure.
    failing_records: std::collections::BTreeSet<String>,
    /// Where lobe is non-zero but within `ATOL` and Mitsuba has an exact zero.
    tiny_where_zero: Vec<String>,
    /// Other lines for the log.
    notes: Vec<String>,
}

impl Report {
    fn dev(&mut self, category: &str) -> &mut Dev {
        let i = match self.devs.iter().position(|(c, _)| c == category) {
            Some(i) => i,
            None => {
                self.devs.push((category.to_owned(), Dev::default()));
                self.devs.len() - 1
            }
        };
        &mut self.devs[i].1
    }

    /// Records `|lobe − oracle|` under `category`, and a failure beyond `ATOL + RTOL·|oracle|`.
    fn check(&mut self, category: &str, ctx: &str, lobe: f64, oracle: f64) {
        let err = (lobe - oracle).abs();
        let fail = !(err <= ATOL + RTOL * oracle.abs());
        if self.dev(category).add(lobe, oracle, fail) {
            self.tiny_where_zero
                .push(format!("{ctx}: {category}: lobe {lobe:e}, mitsuba 0"));
        }
        if fail {
            self.failing_records.insert(ctx.to_owned());
            self.failures.push(format!(
                "{ctx}: {category}: lobe {lobe:e}, mitsuba {oracle:e}"
            ));
        }
    }

    /// Failures whose category ends with `quantity`.
    fn failures_of(&self, quantity: &str) -> usize {
        self.devs
            .iter()
            .filter(|(c, _)| c.ends_with(quantity))
            .map(|(_, d)| d.failures)
            .sum()
    }

    fn print(&self, title: &str) {
        eprintln!("{title}: {} records checked", self.records);
        print_devs("  ", self.devs.iter().map(|(c, d)| (c, d)));
        for note in &self.tiny_where_zero {
            eprintln!("  (within atol) {note}");
        }
        for note in &self.notes {
            eprintln!("  {note}");
        }
    }

    fn assert_clean(&self) {
        assert_no_failures(&self.failures);
    }
}

/// The records of the kinds in `kinds`, with their index and kind.
fn of_kinds<'a>(
    records: &'a [Value],
    kinds: &'a [Kind],
) -> impl Iterator<Item = (usize, &'a Value, Kind)> + 'a {
    records
        .iter()
        .enumerate()
        .map(|(i, r)| (i, r, Kind::of(r)))
        .filter(|(_, _, kind)| kinds.contains(kind))
}

/// Compares `values(record)` with every `microfacet.json` record of the kinds in `kinds`.
fn check_microfacet(kinds: &[Kind], values: impl Fn(Kind, &Value) -> [f64; 6]) -> Report {
    let (records, _) = load(MICROFACET, "mitsuba_microfacet.json");
    let mut rep = Report::default();
    for (i, r, kind) in of_kinds(&records, kinds) {
        rep.records += 1;
        let ctx = context(i, r);
        let lobe = values(kind, r);
        for (q, &got) in QUANTITIES.iter().zip(&lobe) {
            rep.check(&format!("{} {q}", kind.name()), &ctx, got, field(r, q));
        }
    }
    rep
}

/// lobe's values with the real mapping: GGX, and Beckmann with Walter's rational `G1`.
fn lobe_mitsuba_values(kind: Kind, r: &Value) -> [f64; 6] {
    match kind {
        Kind::Ggx => mitsuba_values(&ggx(r), r, Orientation::Mitsuba),
        Kind::Beckmann => mitsuba_values(&beckmann_walter(r), r, Orientation::Mitsuba),
    }
}

/// Compares lobe's visible-normal density with every `microfacet_sample.json` record, and
/// checks lobe's own sample for each record's `(wi, u)`.
fn check_samples(
    kinds: &[Kind],
    sample: impl Fn(Kind, &Value, Vec3, Vec3, Vec2) -> SampleOutcome,
) -> Report {
    let (records, _) = load(MICROFACET_SAMPLE, "mitsuba_microfacet_sample.json");
    let mut rep = Report::default();
    let mut max_unit_err = 0f32;
    let mut max_angle_to_mitsuba = 0f32;
    for (i, r, kind) in of_kinds(&records, kinds) {
        rep.records += 1;
        let ctx = context(i, r);
        let wi = vec_field(r, "wi");
        let u = Vec2::new(field32(r, "u1"), field32(r, "u2"));
        let m_mitsuba = vec_field(r, "m");
        let out = sample(kind, r, wi, m_mitsuba, u);
        rep.check(
            &format!("{} pdf at Mitsuba's m", kind.name()),
            &ctx,
            out.pdf_at_mitsuba_m.into(),
            field(r, "pdf"),
        );
        let m = out.own_m;
        let unit_err = (m.length() - 1.0).abs();
        let ok = m.is_finite() && unit_err <= UNIT_TOL && m.z >= 0.0 && out.own_pdf > 0.0;
        if !ok {
            rep.failures.push(format!(
                "{ctx}: lobe's sample_visible(wi {wi}, u {u}) = {m} (|m| − 1 = {unit_err:e}), \
                 d_visible {}",
                out.own_pdf
            ));
        }
        if m.is_finite() {
            max_unit_err = max_unit_err.max(unit_err);
            max_angle_to_mitsuba = max_angle_to_mitsuba.max(m.angle_between(m_mitsuba));
        }
    }
    rep.notes.push(format!(
        "lobe's own samples: max ||m| − 1| {max_unit_err:.2e}; angle to Mitsuba's m for the \
         same u up to {max_angle_to_mitsuba:.3} rad (different algorithm, not compared)"
    ));
    rep
}

/// What lobe gives for one `microfacet_sample.json` record.
struct SampleOutcome {
    /// `d_visible(wi, m)` at Mitsuba's recorded `m`.
    pdf_at_mitsuba_m: f32,
    /// `sample_visible(wi, u)`.
    own_m: Vec3,
    /// `d_visible(wi, own_m)`.
    own_pdf: f32,
}

fn sample_outcome<N: NormalDistribution>(
    n: &N,
    wi: Vec3,
    m_mitsuba: Vec3,
    u: Vec2,
) -> SampleOutcome {
    assert_eq!(n.sampling(), Sampling::VisibleNormals);
    let own_m = n.sample(&n.view(wi), u);
    SampleOutcome {
        pdf_at_mitsuba_m: visible_pdf(n, wi, m_mitsuba),
        own_m,
        own_pdf: n.d_visible(wi, own_m),
    }
}

fn lobe_sample(kind: Kind, r: &Value, wi: Vec3, m: Vec3, u: Vec2) -> SampleOutcome {
    match kind {
        Kind::Ggx => sample_outcome(&ggx(r), wi, m, u),
        Kind::Beckmann => sample_outcome(&beckmann_walter(r), wi, m, u),
    }
}

// ---------------------------------------------------------------------------------------------
// The reference checks
// ---------------------------------------------------------------------------------------------

#[test]
fn microfacet_functions_agree_with_every_mitsuba_record() {
    let (records, n_meta) = load(MICROFACET, "mitsuba_microfacet.json");
    let below = records
        .iter()
        .filter(|r| field(r, "wi_z") < 0.0 || field(r, "wo_z") < 0.0)
        .count();
    let wi_below = records.iter().filter(|r| field(r, "wi_z") < 0.0).count();

    let rep = check_microfacet(&[Kind::Ggx, Kind::Beckmann], lobe_mitsuba_values);
    rep.print("Mitsuba microfacet.json (GGX exact G1; Beckmann Walter rational G1; separable G)");
    eprintln!(
        "  records with a direction below the horizon: {below}; with wi.z < 0 (negative \
         Mitsuba pdf, mapped to −d_visible(−wi, m)): {wi_below}"
    );
    assert_eq!(rep.records, n_meta, "every record is checked");
    for q in QUANTITIES {
        for kind in [Kind::Ggx, Kind::Beckmann] {
            let category = format!("{} {q}", kind.name());
            let dev = rep.devs.iter().find(|(c, _)| *c == category);
            assert!(
                dev.is_some_and(|(_, d)| d.values > 50),
                "{category} checked on too few records"
            );
        }
    }
    rep.assert_clean();
}

#[test]
fn visible_normal_densities_agree_with_every_mitsuba_sample() {
    let (records, n_meta) = load(MICROFACET_SAMPLE, "mitsuba_microfacet_sample.json");
    let extreme = records
        .iter()
        .filter(|r| r["case"].as_str().is_some_and(|c| c.contains("u_extreme")))
        .count();
    let rep = check_samples(&[Kind::Ggx, Kind::Beckmann], lobe_sample);
    rep.print("Mitsuba microfacet_sample.json (density at the recorded m)");
    eprintln!("  of which u_extreme: {extreme}");
    assert_eq!(rep.records, n_meta, "every record is checked");
    assert!(extreme > 0, "the u_extreme records are present");
    rep.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// The checks can fail
// ---------------------------------------------------------------------------------------------

/// A distribution whose `D` is scaled by a constant: a wrong normalisation.
struct ScaledD<N> {
    inner: N,
    scale: f32,
}

impl<N: NormalDistribution> NormalDistribution for ScaledD<N> {
    fn sampling(&self) -> Sampling {
        self.inner.sampling()
    }
    fn d(&self, m: Vec3) -> f32 {
        self.scale * self.inner.d(m)
    }
    fn lambda(&self, w: Vec3) -> f32 {
        self.inner.lambda(w)
    }
    fn g1(&self, w: Vec3) -> f32 {
        self.inner.g1(w)
    }
    fn view(&self, w: Vec3) -> View {
        self.inner.view(w)
    }
    fn sample(&self, view: &View, u: Vec2) -> Vec3 {
        self.inner.sample(view, u)
    }
}

#[test]
fn the_check_rejects_the_exact_beckmann_g1() {
    // lobe's default Beckmann masking is the exact erf form: up to 0.31% from Walter's.
    let exact = |_: Kind, r: &Value| {
        let b = Beckmann::new(alpha(r, "alpha_u"), alpha(r, "alpha_v"));
        assert_eq!(b.masking(), BeckmannMasking::Exact);
        mitsuba_values(&b, r, Orientation::Mitsuba)
    };
    let rep = check_microfacet(&[Kind::Beckmann], exact);
    let g1 = rep.failures_of("smith_g1_wi") + rep.failures_of("smith_g1_wo");
    rep.print(&format!(
        "exact Beckmann G1 vs Mitsuba's Walter G1 ({} records fail)",
        rep.failing_records.len()
    ));
    assert!(g1 > 0, "the exact G1 must disagree with Walter's somewhere");
    assert!(rep.failures_of(" G") > 0 && rep.failures_of(" pdf") > 0);
    // The failure is where it should be: D does not involve masking.
    assert_eq!(rep.failures_of(" D"), 0);
    assert_eq!(rep.failures_of("pdf_no_visible"), 0);
}

#[test]
fn the_check_rejects_a_ggx_d_off_by_one_percent() {
    let scaled = |r: &Value| ScaledD {
        inner: ggx(r),
        scale: 1.01,
    };
    let rep = check_microfacet(&[Kind::Ggx], |_, r| {
        mitsuba_values(&scaled(r), r, Orientation::Mitsuba)
    });
    let n_nonzero_d = load(MICROFACET, "mitsuba_microfacet.json")
        .0
        .iter()
        .filter(|r| Kind::of(r) == Kind::Ggx && field(r, "D") > 0.0)
        .count();
    eprintln!(
        "GGX with 1.01·D: {} D failures of {n_nonzero_d} non-zero D records",
        rep.failures_of(" D")
    );
    assert_eq!(rep.failures_of(" D"), n_nonzero_d);
    assert!(rep.failures_of("pdf_no_visible") > 0 && rep.failures_of(" pdf") > 0);
    // Masking does not involve D.
    assert_eq!(
        rep.failures_of("smith_g1_wi") + rep.failures_of("smith_g1_wo"),
        0
    );
    assert_eq!(rep.failures_of(" G"), 0);

    // The sample records' density check catches it too.
    let rep = check_samples(&[Kind::Ggx], |_, r, wi, m, u| {
        sample_outcome(&scaled(r), wi, m, u)
    });
    assert_eq!(
        rep.failures_of("pdf at Mitsuba's m"),
        rep.records,
        "every GGX sample record fails"
    );
}

#[test]
fn the_check_rejects_g1_without_the_orientation_factor() {
    // lobe's g1 has no χ⁺; forgetting to apply it must fail on the back-facing records.
    let rep = check_microfacet(&[Kind::Ggx, Kind::Beckmann], |kind, r| match kind {
        Kind::Ggx => mitsuba_values(&ggx(r), r, Orientation::Ignored),
        Kind::Beckmann => mitsuba_values(&beckmann_walter(r), r, Orientation::Ignored),
    });
    let g1 = rep.failures_of("smith_g1_wi") + rep.failures_of("smith_g1_wo");
    eprintln!("G1 without χ⁺: {g1} G1 failures");
    assert!(g1 > 0);
}
