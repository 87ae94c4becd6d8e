//! Fresnel terms: bounds over adversarial inputs, identities against independent `f64`
//! formulas, the conductor approximation's measured error, and every record of the Mitsuba 3
//! reference set (`tests/data/mitsuba_fresnel.json`, conventions and tolerances in
//! `tests/data/mitsuba_CONVENTIONS.md`, §2 and §5), with Mitsuba's gold preset from
//! `tests/data/mitsuba_presets.json`.

mod common;

use common::dielectric_f64;
use common::reference::{field, field32, load};

use lobe::fresnel::{self, DielectricFresnel};
use lobe::{ComplexIor, Eta, Spectrum, Vec3, Vec4};
use proptest::prelude::*;
use serde_json::Value;

// ---------------------------------------------------------------------------------------------
// Independent f64 references: the textbook formulas, written without the rearrangements that
// the crate uses, and complex arithmetic for the conductor.
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug)]
struct C64 {
    re: f64,
    im: f64,
}

impl C64 {
    fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }
    fn add(self, o: Self) -> Self {
        Self::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: Self) -> Self {
        Self::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: Self) -> Self {
        Self::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn norm2(self) -> f64 {
        self.re * self.re + self.im * self.im
    }
    /// The principal square root.
    fn sqrt(self) -> Self {
        let r = self.norm2().sqrt();
        let re = (0.5 * (r + self.re)).max(0.0).sqrt();
        let im = (0.5 * (r - self.re)).max(0.0).sqrt();
        Self::new(re, if self.im < 0.0 { -im } else { im })
    }
}

/// Exact conductor Fresnel in f64 complex arithmetic: `r_s = (c − w)/(c + w)`,
/// `r_p = (n²c − w)/(n²c + w)`, `w = √(n² − sin²θ)`, `F = ½(|r_s|² + |r_p|²)`.
fn conductor_f64(cos_i: f64, eta: f64, k: f64) -> f64 {
    let c = C64::new(cos_i.abs(), 0.0);
    let n = C64::new(eta, k);
    let n2 = n.mul(n);
    let w = n2.sub(C64::new(1.0 - c.re * c.re, 0.0)).sqrt();
    let rs = c.sub(w).norm2() / c.add(w).norm2();
    let n2c = n2.mul(c);
    let rp = n2c.sub(w).norm2() / n2c.add(w).norm2();
    0.5 * (rs + rp)
}

fn eta(v: f32) -> Eta {
    Eta::new(v).unwrap()
}

fn cior(eta: f32, k: f32) -> ComplexIor<f32> {
    ComplexIor::new(eta, k).unwrap()
}

// ---------------------------------------------------------------------------------------------
// Bounds over adversarial inputs (seeded, reproducible, no persistence files).
// ---------------------------------------------------------------------------------------------

/// Cosines in `[-1, 1]`: uniform, the ends, signed zeros, and magnitudes down to 1e-38.
fn cosine() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => -1.0f32..=1.0,
        1 => prop::sample::select(vec![0.0f32, -0.0, 1.0, -1.0]),
        2 => (-38.0f32..0.0, prop::bool::ANY)
            .prop_map(|(e, neg)| if neg { -(10f32.powf(e)) } else { 10f32.powf(e) }),
    ]
}

/// `10^e` clamped into `[lo, hi]` (powf may land an ulp outside the range).
fn log_uniform(lo_exp: f32, hi_exp: f32, lo: f32, hi: f32) -> impl Strategy<Value = f32> {
    (lo_exp..=hi_exp).prop_map(move |e| 10f32.powf(e).clamp(lo, hi))
}

/// Relative indices in `[1e-3, 1e3]`: log-uniform, the ends, 1 and its neighbours.
fn rel_eta() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => log_uniform(-3.0, 3.0, Eta::MIN, Eta::MAX),
        1 => prop::sample::select(vec![Eta::MIN, Eta::MAX, 1.0, 1.0 + f32::EPSILON, 1.0 - f32::EPSILON / 2.0]),
        1 => (-1e-3f32..1e-3).prop_map(|d| 1.0 + d),
    ]
}

/// Real parts of a complex index in `(0, 1000]`.
fn cond_eta() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => log_uniform(-6.0, 3.0, f32::MIN_POSITIVE, 1e3),
        1 => prop::sample::select(vec![f32::MIN_POSITIVE, 1e-30, 1.0, 1e3]),
    ]
}

/// Extinction coefficients in `[0, 1000]`: zero often, log-uniform otherwise.
fn cond_k() -> impl Strategy<Value = f32> {
    prop_oneof![
        2 => Just(0.0f32),
        5 => log_uniform(-6.0, 3.0, 0.0, 1e3),
        1 => prop::sample::select(vec![1e-30f32, 1e3]),
    ]
}

fn in_unit(f: f32) -> bool {
    f.is_finite() && (0.0..=1.0).contains(&f)
}

proptest! {
    #![proptest_config(common::proptest_config(4096))]

    #[test]
    fn dielectric_is_a_reflectance(c in cosine(), e in rel_eta()) {
        let r = fresnel::dielectric_full(c, eta(e));
        prop_assert!(in_unit(r.reflectance), "F({c}, {e}) = {}", r.reflectance);
        prop_assert_eq!(r.reflectance.to_bits(), fresnel::dielectric(c, eta(e)).to_bits());
        prop_assert!(r.cos_t.is_finite() && r.cos_t.abs() <= 1.0);
        // cos_t's sign bit is opposite to cos_i's (Mitsuba's rule, zeros included).
        prop_assert_ne!(r.cos_t.is_sign_negative(), c.is_sign_negative(), "cos_t = {}", r.cos_t);
        prop_assert!((r.eta_it * r.eta_ti - 1.0).abs() <= 2.0 * f32::EPSILON);
    }

    #[test]
    fn conductor_is_a_reflectance(c in cosine(), e in cond_eta(), k in cond_k()) {
        let ior = cior(e, k);
        let f = fresnel::conductor(c, &ior);
        prop_assert!(in_unit(f), "conductor({c}, {e} + {k}i) = {f}");
        let a = fresnel::conductor_approx(c, &ior);
        prop_assert!(in_unit(a), "conductor_approx({c}, {e} + {k}i) = {a}");
    }

    #[test]
    fn schlick_is_a_reflectance(c in cosine(), f0 in 0.0f32..=1.0) {
        let f = fresnel::schlick(f0, c);
        prop_assert!(in_unit(f), "schlick({f0}, {c}) = {f}");
        prop_assert!(f >= f0 * (1.0 - f32::EPSILON), "schlick({f0}, {c}) = {f} < F0");
    }
}

// ---------------------------------------------------------------------------------------------
// Dielectric identities.
// ---------------------------------------------------------------------------------------------

/// Indices from index-matched to extreme, both sides of 1.
const ETAS: [f32; 13] = [
    1.0001,
    0.9999,
    1.001,
    1.05,
    1.33,
    1.5,
    2.4,
    1.0 / 1.33,
    1.0 / 1.5,
    10.0,
    100.0,
    1e3,
    1e-3,
];

#[test]
fn normal_incidence_matches_f0_from_both_sides() {
    // F(±1) = ((η − 1)/(η + 1))², written here from the definition in f64. Tolerance: the crate
    // computes in f32 with a few roundings, each ≤ 2⁻²⁴ relative, and no cancellation (its
    // `1 − η²` is exact for η near 1), so 16 ulps of relative error is generous. A textbook
    // `(cos θi − η cos θt)` form would lose all digits at η = 1.0001 (F ≈ 2.5e-9).
    let mut worst = 0.0f64;
    for e in ETAS {
        let x = f64::from(e);
        let want = ((x - 1.0) / (x + 1.0)).powi(2);
        for c in [1.0f32, -1.0] {
            let got = f64::from(fresnel::dielectric(c, eta(e)));
            let rel = (got - want).abs() / want;
            worst = worst.max(rel);
            assert!(
                rel <= 16.0 * f64::from(f32::EPSILON),
                "F({c}, {e}) = {got}, want {want}"
            );
        }
    }
    eprintln!("normal incidence: max rel error vs ((η−1)/(η+1))² = {worst:.2e}");
}

const EPS: f64 = f32::EPSILON as f64;

/// A round-off bound for an `f32` evaluation of the reflectance `f` at `(c, η)`.
///
/// A backward-stable `f32` evaluation returns the exact value at inputs perturbed by a few
/// ulps, rounded to a few ulps. Its forward error is then at most
/// `K ε (F + |c ∂F/∂c| + |η ∂F/∂η| + ε)`: the condition numbers come from central differences
/// of the f64 reference, `K = 8` allows a handful of roundings on each input and on the
/// result, and the `ε²` term is the square of an amplitude's absolute round-off (it matters
/// only where `F` vanishes, at `η = 1`).
/// This is what "agrees to f32 round-off" means near the critical angle, where `∂F/∂c`
/// grows like `1/cos θt`.
fn roundoff_bound(f: impl Fn(f64, f64) -> f64, c: f64, e: f64) -> f64 {
    let h = 1e-9;
    let c_dfdc = (f(c * (1.0 + h), e) - f(c * (1.0 - h), e)) / (2.0 * h);
    let e_dfde = (f(c, e * (1.0 + h)) - f(c, e * (1.0 - h))) / (2.0 * h);
    8.0 * EPS * (f(c, e) + c_dfdc.abs() + e_dfde.abs() + EPS)
}

/// `cos²θt` in f64 for an f32 cosine and index (negative under total internal reflection).
fn cos2_t_f64(c: f32, e: f32) -> f64 {
    let ci = f64::from(c);
    let n_ti = if c >= 0.0 {
        1.0 / f64::from(e)
    } else {
        f64::from(e)
    };
    1.0 - n_ti * n_ti * (1.0 - ci * ci)
}

/// Within this distance of the critical angle (in `cos²θt`, ≈ 8 ulps of 1) `f32` and `f64`
/// may decide total internal reflection differently; such points are skipped.
const CRITICAL_BAND: f64 = 1e-6;

#[test]
fn dielectric_matches_textbook_f64_to_roundoff() {
    // A dense grid over both sides; the f64 textbook formula stands in for the exact value.
    let mut worst = 0.0f64;
    let mut worst_ct = 0.0f64;
    let mut n = 0;
    for e in ETAS {
        for i in -4000..=4000 {
            let c = i as f32 / 4000.0;
            if c == 0.0 || cos2_t_f64(c, e).abs() < CRITICAL_BAND {
                continue;
            }
            let (ci, ef) = (f64::from(c), f64::from(e));
            let (want, ct) = dielectric_f64(ci, ef);
            let bound = roundoff_bound(|c, e| dielectric_f64(c, e).0, ci, ef);
            let r = fresnel::dielectric_full(c, eta(e));
            let err = (f64::from(r.reflectance) - want).abs();
            worst = worst.max(err / bound);
            assert!(err <= bound, "F({c}, {e}) = {}, want {want}", r.reflectance);
            // cos θt = √(cos²θt): its rounding error (≈ 2ε absolute in cos²θt) is amplified by
            // 1/(2 cos θt), plus a few ulps of cos θt itself.
            let ct_bound = 4.0 * EPS * (ct + 1.0 / ct.max(1e-30));
            let ct_err = (f64::from(r.cos_t.abs()) - ct).abs();
            worst_ct = worst_ct.max(ct_err / ct_bound);
            assert!(
                ct_err <= ct_bound,
                "cos_t({c}, {e}) = {}, want {ct}",
                r.cos_t
            );
            n += 1;
        }
    }
    eprintln!(
        "dielectric vs f64 textbook ({n} points): max error {worst:.3} of the round-off bound (F), {worst_ct:.3} (cos_t)"
    );
}

#[test]
fn dielectric_tends_to_one_at_grazing() {
    for e in [1.0001f32, 1.33, 1.5, 2.4, 10.0, 1e3, 1.0 / 1.5] {
        for c in [1e-6f32, -1e-6] {
            let f = fresnel::dielectric(c, eta(e));
            assert!(f > 0.99, "F({c}, {e}) = {f}");
        }
    }
    // η = 1000 approaches 1 the slowest: for cos θ ≪ 1/η the p-amplitude is
    // r_p ≈ (1 − η cos θ)/(1 + η cos θ), so F ≈ 1 − 2η cos θ = 0.998 at cos θ = 1e-6.
}

#[test]
fn total_internal_reflection_exactly_where_snell_has_no_solution() {
    // TIR iff η_ti² sin²θi > 1. Away from the boundary by a relative 1e-5 (f32 decides the
    // boundary itself by rounding), F must be exactly 1 with cos_t = 0 beyond it and below 1
    // with cos_t ≠ 0 before it.
    let mut tir_points = 0;
    let mut open_points = 0;
    for e in [1.0001f32, 1.1, 1.33, 1.5, 2.4, 10.0, 1e3] {
        for (e_rel, side) in [(e, -1.0f32), (1.0 / e, 1.0)] {
            // Inside a dense medium (cos < 0, η > 1), or outside a less dense one (η < 1).
            for i in 1..=4000 {
                let c = side * i as f32 / 4000.0;
                let ci = f64::from(c);
                let r = fresnel::dielectric_full(c, eta(e_rel));
                // Snell's η_ti, from the side the light comes from.
                let n_ti = if c >= 0.0 {
                    1.0 / f64::from(e_rel)
                } else {
                    f64::from(e_rel)
                };
                let s = n_ti * n_ti * (1.0 - ci * ci);
                if s > 1.0 + 1e-5 {
                    assert_eq!(r.reflectance, 1.0, "cos {c}, eta {e_rel}");
                    assert_eq!(r.cos_t, 0.0);
                    tir_points += 1;
                } else if s < 1.0 - 1e-5 {
                    assert!(r.reflectance < 1.0, "cos {c}, eta {e_rel}");
                    assert!(r.cos_t != 0.0);
                    open_points += 1;
                }
            }
            // Just inside the critical angle (cos²θt = 1e-4): transmission, F visibly below 1.
            let n_ti = if side > 0.0 {
                1.0 / f64::from(e_rel)
            } else {
                f64::from(e_rel)
            };
            let cos_c = (1.0 - 1.0 / (n_ti * n_ti)).sqrt();
            let just_open = ((1.0 - (1.0 - 1e-4) / (n_ti * n_ti)).sqrt()) as f32;
            assert!(f64::from(just_open) > cos_c);
            let f = fresnel::dielectric(side * just_open, eta(e_rel));
            assert!(f < 1.0, "just inside the critical angle: F = {f}");
        }
    }
    assert!(tir_points > 10_000 && open_points > 10_000);
}

// ---------------------------------------------------------------------------------------------
// Conductor: exactness, the κ = 0 limit, spectra.
// ---------------------------------------------------------------------------------------------

#[test]
fn conductor_matches_complex_arithmetic() {
    // The crate's real-arithmetic form against f64 complex arithmetic. f32 inputs are exact
    // in f64; the crate's roundings (a dozen, ≤ 2⁻²⁴ each, some amplified by the c − a
    // cancellation when the interface nearly vanishes) stay under 1e-6 absolute + 1e-5
    // relative on this grid, which avoids κ = 0 near the critical angle (tested below).
    let mut worst = 0.0f64;
    let ks = [1e-3f32, 0.01, 0.1, 0.5, 1.0, 2.0, 3.98, 9.2, 100.0, 1e3];
    let etas = [
        1e-3f32, 0.037, 0.143, 0.5, 0.9, 1.0, 1.1, 1.44, 2.5, 4.37, 100.0, 1e3,
    ];
    for e in etas {
        for k in ks {
            for i in 1..=500 {
                let c = i as f32 / 500.0;
                let got = f64::from(fresnel::conductor(c, &cior(e, k)));
                let want = conductor_f64(f64::from(c), f64::from(e), f64::from(k));
                let err = (got - want).abs();
                worst = worst.max(err / (1e-6 + 1e-5 * want));
                assert!(
                    err <= 1e-6 + 1e-5 * want,
                    "F({c}, {e} + {k}i) = {got}, want {want}"
                );
            }
        }
    }
    eprintln!("conductor vs complex f64: max error = {worst:.3} of the tolerance");
}

#[test]
fn conductor_without_extinction_is_the_dielectric() {
    // κ = 0 makes the complex formula the dielectric one, total internal reflection included.
    // Both are f32 evaluations, so they agree within the sum of their round-off bounds (see
    // `roundoff_bound`: a few ulps, amplified only near the critical angle). Points within
    // `CRITICAL_BAND` of it, where either side may decide TIR by rounding, are skipped.
    let mut worst = 0.0f64;
    let mut tir = 0;
    for e in [
        0.1f32,
        0.5,
        1.0 / 1.5,
        1.0 / 1.33,
        0.99,
        0.9999,
        1.0,
        1.0001,
        1.01,
        1.33,
        1.5,
        2.4,
        10.0,
        1e3,
    ] {
        for i in 1..=4000 {
            let c = i as f32 / 4000.0;
            if cos2_t_f64(c, e).abs() < CRITICAL_BAND {
                continue;
            }
            let d = fresnel::dielectric(c, eta(e));
            let m = fresnel::conductor(c, &cior(e, 0.0));
            if d == 1.0 && m == 1.0 {
                tir += 1;
            }
            let err = f64::from((d - m).abs());
            let bound = 2.0 * roundoff_bound(|c, e| dielectric_f64(c, e).0, c.into(), e.into());
            worst = worst.max(err / bound);
            assert!(
                err <= bound,
                "cos {c}, eta {e}: dielectric {d}, conductor {m}"
            );
        }
    }
    assert!(tir > 1000, "the grid must reach total internal reflection");
    eprintln!("conductor(κ=0) vs dielectric: max difference {worst:.3} of the round-off bound");
}

/// A conductor preset of Mitsuba's (`tests/data/mitsuba_presets.json`): its RGB `(η, κ)`.
fn mitsuba_preset(name: &str) -> (Vec3, Vec3) {
    let (records, _) = load(
        include_str!("data/mitsuba_presets.json"),
        "mitsuba_presets.json",
    );
    let r = records
        .iter()
        .find(|r| r["name"] == name)
        .unwrap_or_else(|| panic!("no preset {name}"));
    let rgb = |part: &str| {
        let c = |channel: &str| field32(r, &format!("{part}_{channel}"));
        Vec3::new(c("r"), c("g"), c("b"))
    };
    (rgb("eta"), rgb("k"))
}

#[test]
fn conductor_spectra_are_channelwise() {
    let (eta3, k3) = mitsuba_preset("Au");
    let gold = ComplexIor::new(eta3, k3).unwrap();
    let gold4 = ComplexIor::new(eta3.extend(0.5), k3.extend(0.0)).unwrap();
    for c in [1.0f32, 0.7, 0.2, 1e-3, -0.3] {
        let f = fresnel::conductor(c, &gold);
        let a = fresnel::conductor_approx(c, &gold);
        let f4 = fresnel::conductor(c, &gold4);
        for i in 0..3 {
            let mono = cior(eta3[i], k3[i]);
            assert_eq!(f.channel(i), fresnel::conductor(c, &mono));
            assert_eq!(a.channel(i), fresnel::conductor_approx(c, &mono));
            assert_eq!(f4.channel(i), f.channel(i));
        }
        assert_eq!(f4.w, fresnel::conductor(c, &cior(0.5, 0.0)));
        let s = fresnel::schlick(Vec4::new(0.04, 0.5, 0.9, 1.0), c);
        assert_eq!(s.y, fresnel::schlick(0.5f32, c));
    }
}

/// An RGB or four-channel conductor computes its channels side by side in SIMD registers;
/// the monochrome one, and `eval_per_channel` (the form the batched loops use), channel by
/// channel. All three give the same numbers, bit for bit, over indices from the smallest
/// accepted to the largest and cosines from exactly grazing (and subnormal) to normal, on
/// both sides.
#[test]
fn conductor_channels_side_by_side_equal_channel_by_channel() {
    use lobe::fresnel::{Conductor, Fresnel};
    let values = [
        f32::MIN_POSITIVE,
        1e-20,
        1e-4,
        0.05,
        0.2,
        0.47,
        0.99,
        1.0,
        1.0001,
        1.5,
        2.4,
        7.0,
        50.0,
        1000.0,
    ];
    let cosines = [
        0.0, -0.0, 1e-38, 1e-20, 1e-7, 0.01, 0.2, 0.5, 0.71, 0.9, 0.999_999, 1.0, -0.3, -1.0,
    ];
    let mut checked = 0;
    for (i, &e) in values.iter().enumerate() {
        for (j, &k) in [0.0].iter().chain(&values).enumerate() {
            // Channels that differ from one another, each pair of the grid once in channel 0.
            let eta = Vec4::new(
                e,
                values[(i + j) % values.len()],
                values[(i + 3) % values.len()],
                1.3,
            );
            let kap = Vec4::new(
                k,
                values[(j + 5) % values.len()],
                0.0,
                values[i % values.len()],
            );
            let rgb = Conductor {
                ior: ComplexIor::new(eta.truncate(), kap.truncate()).unwrap(),
            };
            let four = Conductor {
                ior: ComplexIor::new(eta, kap).unwrap(),
            };
            for &c in &cosines {
                let (f3, f4) = (rgb.eval(c), four.eval(c));
                assert_eq!(
                    f3.to_array().map(f32::to_bits),
                    rgb.eval_per_channel(c).to_array().map(f32::to_bits)
                );
                assert_eq!(
                    f4.to_array().map(f32::to_bits),
                    four.eval_per_channel(c).to_array().map(f32::to_bits)
                );
                for ch in 0..4 {
                    let mono = fresnel::conductor(c, &cior(eta[ch], kap[ch]));
                    assert_eq!(
                        f4[ch].to_bits(),
                        mono.to_bits(),
                        "η {eta}, κ {kap}, cos {c}"
                    );
                    if ch < 3 {
                        assert_eq!(
                            f3[ch].to_bits(),
                            mono.to_bits(),
                            "η {eta}, κ {kap}, cos {c}"
                        );
                    }
                }
                checked += 1;
            }
        }
    }
    eprintln!("{checked} RGB and four-channel evaluations, equal to the channel-by-channel ones");
}

// ---------------------------------------------------------------------------------------------
// The handout's approximation (ERRATA #6): measured against the exact formulas.
// ---------------------------------------------------------------------------------------------

#[test]
fn conductor_approx_meets_the_exact_formula_at_normal_incidence() {
    for e in [0.037f32, 0.143, 0.5, 1.0, 1.5, 4.37, 100.0] {
        for k in [0.0f32, 0.5, 1.6, 3.98, 9.2, 100.0] {
            let ior = cior(e, k);
            let exact = fresnel::conductor(1.0, &ior);
            let approx = fresnel::conductor_approx(1.0, &ior);
            // Both reduce to ((η−1)² + κ²)/((η+1)² + κ²) through different roundings.
            assert!(
                (exact - approx).abs() <= 4.0 * f32::EPSILON,
                "{e} + {k}i: {exact} vs {approx}"
            );
            let want = ((f64::from(e) - 1.0).powi(2) + f64::from(k).powi(2))
                / ((f64::from(e) + 1.0).powi(2) + f64::from(k).powi(2));
            assert!((f64::from(approx) - want).abs() <= 1e-6);
        }
    }
}

/// The largest `|approx − exact|` over `cos ∈ (0, 1]` (1000 steps) and the given η, κ lists,
/// with the place where it happens.
fn approx_error(etas: &[f32], ks: &[f32]) -> (f32, f32, f32, f32) {
    let mut worst = (0.0f32, 0.0, 0.0, 0.0);
    for &e in etas {
        for &k in ks {
            let ior = cior(e, k);
            for i in 1..=1000 {
                let c = i as f32 / 1000.0;
                let err = (fresnel::conductor_approx(c, &ior) - fresnel::conductor(c, &ior)).abs();
                if err > worst.0 {
                    worst = (err, c, e, k);
                }
            }
        }
    }
    worst
}

/// The grid of `conductor_approx`'s documentation: η ∈ [0.1, 3] and κ ∈ [0, 5] in steps of
/// 0.05 and 0.1, restricted to `η ∈ [eta_lo, 3]`, `κ ∈ [k_lo, k_hi]`.
fn doc_grid(eta_lo: f32, k_lo: f32, k_hi: f32) -> (Vec<f32>, Vec<f32>) {
    let etas = (2..=60)
        .map(|i| i as f32 * 0.05)
        .filter(|&e| e >= eta_lo - 1e-6)
        .collect();
    let ks = (0..=50)
        .map(|i| i as f32 * 0.1)
        .filter(|&k| k >= k_lo - 1e-6 && k <= k_hi + 1e-6)
        .collect();
    (etas, ks)
}

#[test]
fn conductor_approx_error_is_bounded_as_documented() {
    // Each row: the region, the measured maximum |approx − exact| rounded up in its second
    // significant digit (the figure in the doc comment), and a floor showing that the
    // deviation is real and not round-off.
    let rows = [
        ("η∈[0.1,3], κ∈[0,5]", doc_grid(0.1, 0.0, 5.0), 0.997, 0.9),
        ("η∈[0.1,3], κ∈[1,5]", doc_grid(0.1, 1.0, 5.0), 0.064, 0.05),
        ("η∈[0.1,3], κ∈[2,5]", doc_grid(0.1, 2.0, 5.0), 0.0083, 0.005),
    ];
    for (label, (etas, ks), bound, floor) in rows {
        let (err, c, e, k) = approx_error(&etas, &ks);
        eprintln!(
            "conductor_approx vs conductor, {label}: max |Δ| = {err:.4} at cos {c}, {e} + {k}i"
        );
        assert!(err <= bound, "{label}: {err} > {bound}");
        assert!(err > floor, "{label}: {err}");
    }
}

#[test]
fn conductor_approx_at_zero_extinction_vs_dielectric() {
    // ERRATA #6: at κ = 0 the approximation is not the dielectric formula. Measured bounds
    // (rounded up in the second digit; in `conductor_approx`'s doc): it approaches it as η
    // grows, is far off near η = 1 (it reflects almost everything at grazing incidence even
    // when there is no interface) and has no total internal reflection for η < 1.
    let rows = [
        ("η∈[2,3]", 2.0f32, 3.0f32, 0.044, 0.03),
        ("η∈[1.5,3]", 1.5, 3.0, 0.099, 0.09),
        ("η∈[1,3]", 1.0, 3.0, 0.997, 0.9),
        ("η∈[0.1,0.95]", 0.1, 0.95, 0.945, 0.9),
    ];
    for (label, lo, hi, bound, floor) in rows {
        let mut worst = (0.0f32, 0.0, 0.0);
        for i in 2..=60 {
            let e = i as f32 * 0.05;
            if e < lo - 1e-6 || e > hi + 1e-6 {
                continue;
            }
            for j in 1..=1000 {
                let c = j as f32 / 1000.0;
                let approx = fresnel::conductor_approx(c, &cior(e, 0.0));
                let err = (approx - fresnel::dielectric(c, eta(e))).abs();
                if err > worst.0 {
                    worst = (err, c, e);
                }
            }
        }
        let (err, c, e) = worst;
        eprintln!(
            "conductor_approx(κ=0) vs dielectric, {label}: max |Δ| = {err:.4} at cos {c}, η {e}"
        );
        assert!(err <= bound, "{label}: {err} > {bound}");
        assert!(err > floor, "{label}: {err}");
    }
}

// ---------------------------------------------------------------------------------------------
// Mitsuba 3.9.1 reference records (CONVENTIONS.md §2, tolerances of §5).
// ---------------------------------------------------------------------------------------------

/// Well-conditioned records (§5): `|rust − oracle| ≤ 1e-9 + 1e-3·|oracle|`.
const WELL: (f64, f64) = (1e-9, 1e-3);
/// Ill-conditioned records (§5): f32 decides total internal reflection by rounding there.
const ILL_TAGS: [&str; 3] = ["near_critical", "eta_near_1", "u_extreme"];
const ILL_ATOL_F: f64 = 0.06;
const ILL_ATOL_COS_T: f64 = 5e-4;

/// Every record of the reference file, and the count its `meta` announces (equal: checked).
fn load_reference() -> (Vec<Value>, usize) {
    load(
        include_str!("data/mitsuba_fresnel.json"),
        "mitsuba_fresnel.json",
    )
}

/// The largest deviations in one category of records.
#[derive(Debug, Default, Clone, Copy)]
struct Dev {
    records: usize,
    max_abs: f64,
    /// Over records with a non-zero oracle value.
    max_rel: f64,
}

impl Dev {
    fn add(&mut self, rust: f64, oracle: f64) {
        let err = (rust - oracle).abs();
        self.records += 1;
        self.max_abs = self.max_abs.max(err);
        if oracle != 0.0 {
            self.max_rel = self.max_rel.max(err / oracle.abs());
        }
    }
}

impl std::fmt::Display for Dev {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} values, max abs {:.2e}, max rel {:.2e}",
            self.records, self.max_abs, self.max_rel
        )
    }
}

#[derive(Debug, Default)]
struct Report {
    dielectric: usize,
    conductor: usize,
    failures: Vec<String>,
    /// Deviations by category, in order of first appearance.
    devs: Vec<(&'static str, Dev)>,
}

impl Report {
    fn dev(&mut self, category: &'static str) -> &mut Dev {
        let i = match self.devs.iter().position(|(c, _)| *c == category) {
            Some(i) => i,
            None => {
                self.devs.push((category, Dev::default()));
                self.devs.len() - 1
            }
        };
        &mut self.devs[i].1
    }

    /// Records the deviation under `category` and a failure when `|rust − oracle|` exceeds
    /// `atol + rtol·|oracle|` (with `atol = 1e-9`, an oracle zero demands a zero).
    fn check(
        &mut self,
        category: &'static str,
        ctx: &str,
        rust: f64,
        oracle: f64,
        (atol, rtol): (f64, f64),
    ) {
        self.dev(category).add(rust, oracle);
        if (rust - oracle).abs() > atol + rtol * oracle.abs() {
            self.failures.push(format!(
                "{ctx}: {category}: rust {rust:e}, mitsuba {oracle:e}"
            ));
        }
    }
}

/// Checks every record with the given dielectric and conductor functions.
fn check_reference(
    dielectric: impl Fn(f32, Eta) -> DielectricFresnel,
    conductor: impl Fn(f32, &ComplexIor<f32>) -> f32,
) -> Report {
    let (records, _) = load_reference();
    let mut rep = Report::default();
    for r in &records {
        let case = r["case"].as_str().expect("case");
        let ill = ILL_TAGS.iter().any(|t| case.contains(t));
        // The JSON holds exact f32 values, so the narrowing casts are exact.
        let cos_i = field(r, "cos_theta_i") as f32;
        match r["kind"].as_str() {
            Some("dielectric") => {
                rep.dielectric += 1;
                let e = field(r, "eta") as f32;
                let ctx = format!("{case} (cos {cos_i}, eta {e})");
                let got = dielectric(cos_i, eta(e));
                let (f, ct) = (field(r, "F"), field(r, "cos_theta_t"));
                let (rf, rct) = (f64::from(got.reflectance), f64::from(got.cos_t));
                if ill {
                    rep.check("ill F", &ctx, rf, f, (ILL_ATOL_F, 0.0));
                    rep.check("ill cos_t", &ctx, rct, ct, (ILL_ATOL_COS_T, 0.0));
                    // Not asserted: who is closer to the exact (f64) value on these records.
                    let (exact_f, _) = dielectric_f64(cos_i.into(), e.into());
                    rep.dev("ill F, rust vs f64 textbook").add(rf, exact_f);
                    rep.dev("ill F, mitsuba vs f64 textbook").add(f, exact_f);
                } else {
                    rep.check("dielectric F", &ctx, rf, f, WELL);
                    rep.check("dielectric cos_t", &ctx, rct, ct, WELL);
                }
                // The sign rule is exact on every record, signed zeros included.
                if got.cos_t.is_sign_negative() != ct.is_sign_negative() {
                    rep.failures.push(format!(
                        "{ctx}: cos_t sign: rust {}, mitsuba {ct}",
                        got.cos_t
                    ));
                }
                let (it, ti) = (field(r, "eta_it"), field(r, "eta_ti"));
                rep.check("eta_it/eta_ti", &ctx, got.eta_it.into(), it, WELL);
                rep.check("eta_it/eta_ti", &ctx, got.eta_ti.into(), ti, WELL);
            }
            Some("conductor") => {
                rep.conductor += 1;
                let (e, k) = (field(r, "eta_re") as f32, field(r, "eta_im") as f32);
                let ctx = format!("{case} (cos {cos_i}, {e} + {k}i)");
                let got = conductor(cos_i, &cior(e, k));
                rep.check("conductor F", &ctx, got.into(), field(r, "F"), WELL);
            }
            other => panic!("unknown record kind {other:?}"),
        }
    }
    rep
}

#[test]
fn agrees_with_every_mitsuba_record() {
    // `load` asserts that the file's record count equals its meta.
    let (_, n_meta) = load_reference();

    let rep = check_reference(fresnel::dielectric_full, fresnel::conductor::<f32>);
    eprintln!(
        "Mitsuba fresnel: {} records checked ({} dielectric, {} conductor)",
        rep.dielectric + rep.conductor,
        rep.dielectric,
        rep.conductor
    );
    for (category, dev) in &rep.devs {
        eprintln!("  {category}: {dev}");
    }
    assert!(
        rep.failures.is_empty(),
        "{} failures:\n{}",
        rep.failures.len(),
        rep.failures.join("\n")
    );
    assert_eq!(
        rep.dielectric + rep.conductor,
        n_meta,
        "every record is checked"
    );
    assert!(rep.dielectric > 100 && rep.conductor > 50);
}

// ---------------------------------------------------------------------------------------------
// The checks can fail: known-wrong formulas are caught.
// ---------------------------------------------------------------------------------------------

#[test]
fn the_reference_check_catches_wrong_conventions() {
    // Ignoring the inside (always η, never 1/η) must fail on the negative-cosine records.
    let outside_only = |c: f32, e: Eta| fresnel::dielectric_full(c.abs(), e);
    let rep = check_reference(outside_only, fresnel::conductor::<f32>);
    assert!(rep.failures.len() > 20, "{} failures", rep.failures.len());
    // The seed's approximation in place of the exact conductor formula must fail too.
    let mut rep = check_reference(fresnel::dielectric_full, fresnel::conductor_approx::<f32>);
    let approx_dev = *rep.dev("conductor F");
    eprintln!(
        "conductor_approx vs Mitsuba's exact conductor records: {}; {} records fail",
        approx_dev,
        rep.failures.len()
    );
    // The figure quoted in `conductor_approx`'s documentation (measured 6.72e-3).
    assert!(approx_dev.max_abs <= 6.8e-3, "{approx_dev}");
    assert!(
        rep.failures.iter().any(|f| f.contains(": conductor F:")),
        "conductor_approx passed as exact"
    );
}

/// The handout's slipped Schlick, `F0 + (1 − F0)(1 − cos⁵θ)` (ERRATA #1).
fn schlick_slipped(f0: f32, c: f32) -> f32 {
    f0 + (1.0 - f0) * (1.0 - c.powi(5))
}

#[test]
fn slipped_schlick_is_caught_by_hand_values_and_by_mitsuba() {
    // By hand, F0 = 0.04 at cos 0.5: 0.04 + 0.96/32 = 0.07 (slipped: 0.04 + 0.96·31/32 = 0.97).
    assert!((fresnel::schlick(0.04f32, 0.5) - 0.07).abs() <= 1e-7);
    assert!((schlick_slipped(0.04, 0.5) - 0.07).abs() > 0.5);

    // Against Mitsuba's glass (η = 1.5, outside, cos in (0, 1]): Schlick is an approximation
    // with a known error of a few percent; the slip is off by almost 1.
    let (records, _) = load_reference();
    let mut n = 0;
    let (mut good, mut bad) = (0.0f64, 0.0f64);
    for r in &records {
        if r["kind"] != "dielectric"
            || field(r, "eta") as f32 != 1.5
            || field(r, "cos_theta_i") <= 0.0
        {
            continue;
        }
        let c = field(r, "cos_theta_i") as f32;
        let f = field(r, "F");
        good = good.max((f64::from(fresnel::schlick(0.04f32, c)) - f).abs());
        bad = bad.max((f64::from(schlick_slipped(0.04, c)) - f).abs());
        n += 1;
    }
    eprintln!("Schlick vs Mitsuba glass ({n} records): max |Δ| {good:.4}, slipped form {bad:.4}");
    assert!(n >= 6);
    assert!(good < 0.05, "{good}");
    assert!(bad > 0.5, "{bad}");
}
