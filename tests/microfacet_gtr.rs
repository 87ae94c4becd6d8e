//! Burley's GTR distribution (Burley 2012, "Physically-Based Shading at Disney", appendix B.2)
//! against `f64` references written here: its `D cos θ` sampler against the closed-form CDF,
//! and its tabulated Smith `G1` against GGX's closed form (`γ = 2`) and an adaptive quadrature
//! of the projected-area identity (Heitz 2014, "Understanding the Masking-Shadowing Function in
//! Microfacet-Based BRDFs", eq. 14).

use core::f64::consts::{FRAC_PI_2, PI};
use lobe::microfacet::{BlinnPhongNdf, Gtr, NormalDistribution, SampleDCos};
use lobe::{Alpha, Vec2, Vec3};

/// The unit roundoff of `f32`, `2⁻²⁴`: half an ulp of 1.
const R: f64 = 1.0 / 16_777_216.0;

fn gtr(alpha: f32, gamma: f32) -> Gtr {
    Gtr::new(Alpha::new(alpha).unwrap(), gamma).unwrap()
}

/// The CDF of GTR's `D cos θ` in `f64`, from either end, with its density. Burley 2012,
/// appendix B.2: with `t = α² − 1`, the mass between grazing and `cos² θ = x` is
/// `F(x) = ((1 + t x)^(1−γ) − 1) / ((α²)^(1−γ) − 1)` (`ln(1 + t x) / ln α²` at `γ = 1`); the
/// mass between the normal and `sin² θ = s` is `1 − F(1 − s)`, which with
/// `1 + t (1 − s) = α² (1 + (1 − α²) s / α²)` is the same form with `α²` replaced by `1/α²`
/// in the exponent and `t x` by `(1 − α²) s / α²`.
struct Cdf {
    a2: f64,
    gamma: f64,
}

impl Cdf {
    fn new(alpha: f32, gamma: f32) -> Self {
        let a = f64::from(alpha);
        Self {
            a2: a * a,
            gamma: f64::from(gamma),
        }
    }

    /// `(G, dG/dv)` for `G(v) = ((1 + k v)^(1−γ) − 1) / (e^((1−γ) ℓ) − 1)`, or `ln(1 + k v)/ℓ`
    /// at `γ = 1`.
    fn form(&self, k: f64, v: f64, ell: f64) -> (f64, f64) {
        let g = 1.0 - self.gamma;
        let l = (k * v).ln_1p();
        if g == 0.0 {
            (l / ell, k / ((1.0 + k * v) * ell))
        } else {
            let den = (g * ell).exp_m1();
            (
                (g * l).exp_m1() / den,
                g * k * (-self.gamma * l).exp() / den,
            )
        }
    }

    /// The mass between grazing and `cos² θ = x`, and its density in `x`.
    fn mass_from_grazing(&self, x: f64) -> (f64, f64) {
        self.form(self.a2 - 1.0, x, self.a2.ln())
    }

    /// The mass between the normal and `sin² θ = s`, and its density in `s`.
    fn mass_from_normal(&self, s: f64) -> (f64, f64) {
        self.form((1.0 - self.a2) / self.a2, s, -self.a2.ln())
    }
}

/// The `D cos θ` sampler inverts the CDF to within the rounding of its `f32` arithmetic.
///
/// The bound, per sample: the sampler forms `sin² θ` (where it is at most ½, else `cos² θ`)
/// from `q = 1 − u` (else `u`) by `ln(1 + k v) = ln_1p(q expm1(x)) / (1 − γ)` with
/// `x = (1 − γ) ℓ`, `ℓ = ∓ln α²`, then `v = expm1(·) / k`. Counting each rounding as `r = 2⁻²⁴`
/// relative (`2r`, one ulp, for `ln`, `expm1`, `ln_1p`) and carrying it to first order to the
/// CDF's value: `q` (r), `ln α²` and `x` (3r, which `expm1` turns into `3r·|x|eˣ/|expm1 x|`, at
/// most `3r (1 + max(0, x))`), `expm1` (2r), `q expm1` (r), `ln_1p` and the division by
/// `1 − γ` (3r on `ln(1 + k v)`, which moves the CDF by `3r (1 + k v) ln(1 + k v) / |expm1 x|`,
/// at most `3r q (1 + max(0, x))`) move the CDF by at most `(13 + 6 max(0, x)) r q`. Then
/// `v` itself (`expm1` 2r, `t = (α − 1)(α + 1)` 3r, the division r, and for `sin²` also
/// `α²` and its product, 2r) and the `f32` component `√v` read back as `v` (2r): at most `10r`
/// relative, which moves the CDF by `10 r v p(v)` with `p` its density. The assertion allows
/// the sum over both ends, `(13 + 6 max(0, x)) r (1 − u) + (13 + 6 max(0, −x)) r u
/// + 10 r v p(v)`, with `x = (1 − γ) ln(1/α²)`. (`u.y = 0` puts the sample in the `xz` plane,
/// so that the azimuth's rounding does not enter.) The old sampler, which took
/// `sin² θ = 1 − cos² θ`, was off by 0.059, 0.66 and 0.999 at `α = 1e-4` (γ = 1, 2, 10).
#[test]
fn d_cos_sampler_inverts_the_cdf() {
    let mut us: Vec<f32> = (0..4096).map(|k| k as f32 / 4096.0).collect();
    for j in 1..=24 {
        us.push(1.0 - (-(j as f32)).exp2());
    }
    for j in 13..=60 {
        us.push((-(j as f32)).exp2());
    }
    for alpha in [1e-4_f32, 1e-3, 1e-2, 0.3] {
        for gamma in [0.5_f32, 1.0, 1.5, 2.0, 10.0] {
            let d = gtr(alpha, gamma);
            let cdf = Cdf::new(alpha, gamma);
            let x = (1.0 - cdf.gamma) * (1.0 / cdf.a2).ln();
            let (k_normal, k_grazing) = (13.0 + 6.0 * x.max(0.0), 13.0 + 6.0 * (-x).max(0.0));
            let (mut worst, mut worst_ratio) = (0.0_f64, 0.0_f64);
            for &u in &us {
                let m = d.sample_d_cos(Vec2::new(u, 0.0));
                assert!(m.is_finite() && m.z >= 0.0 && m.y == 0.0, "u = {u}: {m}");
                let (s, c) = (f64::from(m.x).powi(2), f64::from(m.z).powi(2));
                let u = f64::from(u);
                let (err, v_p) = if s <= c {
                    let (g, p) = cdf.mass_from_normal(s);
                    ((g - (1.0 - u)).abs(), s * p)
                } else {
                    let (f, p) = cdf.mass_from_grazing(c);
                    ((f - u).abs(), c * p)
                };
                let bound = R * (k_normal * (1.0 - u) + k_grazing * u + 10.0 * v_p);
                assert!(
                    err <= bound,
                    "α = {alpha}, γ = {gamma}, u = {u}: |F(sample) − u| = {err:e} > {bound:e} \
                     (sin² θ = {s:e}, cos² θ = {c:e})"
                );
                worst = worst.max(err);
                worst_ratio = worst_ratio.max(err / bound);
            }
            eprintln!(
                "α = {alpha:e}, γ = {gamma}: max |F(sample) − u| = {worst:.2e}, \
                 {worst_ratio:.2} of the bound"
            );
        }
    }
}

/// Gauss-Legendre nodes (the positive half) and weights on `[−1, 1]`, 10 points (Abramowitz &
/// Stegun, table 25.4).
const GL10: [(f64, f64); 5] = [
    (0.148_874_338_981_631_2, 0.295_524_224_714_752_9),
    (0.433_395_394_129_247_2, 0.269_266_719_309_996_4),
    (0.679_409_568_299_024_4, 0.219_086_362_515_982),
    (0.865_063_366_688_984_5, 0.149_451_349_150_580_6),
    (0.973_906_528_517_171_7, 0.066_671_344_308_688_1),
];

fn gl10(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    GL10.iter()
        .map(|&(x, w)| w * (f(mid - half * x) + f(mid + half * x)))
        .sum::<f64>()
        * half
}

/// `∫ f` over `[a, b]` by bisection until a panel and its two halves agree to `tol` per unit
/// length.
fn adaptive(f: &impl Fn(f64) -> f64, a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
    let mid = 0.5 * (a + b);
    let (left, right) = (gl10(f, a, mid), gl10(f, mid, b));
    assert!(
        left.is_finite() && right.is_finite(),
        "[{a}, {b}]: {left}, {right}"
    );
    if depth == 0 || (left + right - whole).abs() <= tol * (b - a) {
        left + right
    } else {
        adaptive(f, a, mid, left, tol, depth - 1) + adaptive(f, mid, b, right, tol, depth - 1)
    }
}

/// GTR's `D` in `f64` (Burley 2012, appendix B.2, eqs. 4–5, with the normalisation of the
/// crate's ERRATA #3): `c / (sin² θ + α² cos² θ)^γ`; `c = 1/π` at `α = 1`.
fn d_f64(alpha: f32, gamma: f32) -> impl Fn(f64, f64) -> f64 {
    let a2 = f64::from(alpha).powi(2);
    let g = f64::from(gamma);
    let c = if a2 == 1.0 {
        1.0 / PI
    } else if g == 1.0 {
        (a2 - 1.0) / (PI * a2.ln())
    } else {
        (g - 1.0) * (a2 - 1.0) / (PI * (1.0 - a2.powf(1.0 - g)))
    };
    move |cos2, sin2| c * (sin2 + a2 * cos2).powf(-g)
}

/// Smith `G1` in `f64` from the projected-area identity, Heitz 2014 eq. 14:
/// `G1(w) = cos θw / ∫ max(0, w·m) D(m) dωm`. The `φm` integral is done in closed form,
/// `∫₀^2π max(0, A + B cos φ) dφ = 2πA` (`A ≥ B`), else `2 (A acos(−A/B) + √(B² − A²))`,
/// with `A = cos θw cos θm`, `B = sin θw sin θm`; the `θm` integral adaptively in
/// `y = ln tan θm` over `[−60, 60]` (the rest is below `e⁻⁶⁰` of it), split at the kink
/// `θm = π/2 − θw`, to `1e-10` of the integral. The variable spreads every width evenly, from
/// `α = 1e-4` to 10.
fn g1_reference(d: &impl Fn(f64, f64) -> f64, cos_w: f64, sin_w: f64) -> f64 {
    if cos_w <= 0.0 {
        return 0.0;
    }
    let f = |y: f64| {
        // sin θ, cos θ and dθ/dy = sin θ cos θ at tan θ = eʸ.
        let (s, c) = (
            1.0 / (1.0 + (-2.0 * y).exp()).sqrt(),
            1.0 / (1.0 + (2.0 * y).exp()).sqrt(),
        );
        let (a, b) = (cos_w * c, sin_w * s);
        let phi = if a >= b {
            2.0 * PI * a
        } else {
            2.0 * (a * (-a / b).acos() + (b * b - a * a).sqrt())
        };
        d(c * c, s * s) * s * phi * s * c
    };
    let kink = if sin_w > 0.0 {
        (cos_w / sin_w).ln().clamp(-60.0, 60.0)
    } else {
        60.0
    };
    let pieces = [(-60.0, kink), (kink, 60.0)];
    let coarse: f64 = pieces
        .iter()
        .map(|&(a, b)| {
            let n = 64;
            (0..n)
                .map(|i| {
                    let h = (b - a) / f64::from(n);
                    gl10(&f, a + h * f64::from(i), a + h * f64::from(i + 1))
                })
                .sum::<f64>()
        })
        .sum();
    let tol = 1e-10 * coarse / 120.0;
    let total: f64 = pieces
        .iter()
        .filter(|&&(a, b)| b > a)
        .map(|&(a, b)| adaptive(&f, a, b, gl10(&f, a, b), tol, 40))
        .sum();
    (cos_w / total).min(1.0)
}

/// Directions from the normal to grazing: uniform in `θ`, and `θ = π/2 − 10⁻ᵉ` for
/// `e ∈ [0, 6]`, where a narrow lobe's `G1` changes. Each as the `f32` vector the model is
/// given, with the `f64` `(cos θ, sin θ)` of that vector.
fn directions() -> Vec<(Vec3, f64, f64)> {
    let mut thetas: Vec<f64> = (0..=360)
        .map(|i| f64::from(i) / 360.0 * FRAC_PI_2)
        .collect();
    thetas.extend((0..=120).map(|i| FRAC_PI_2 - 10f64.powf(-f64::from(i) / 20.0)));
    thetas
        .into_iter()
        .map(|t| {
            let w = Vec3::new(t.sin() as f32, 0.0, t.cos() as f32);
            let (x, z) = (f64::from(w.x), f64::from(w.z));
            let n = x.hypot(z);
            (w, z / n, x / n)
        })
        .collect()
}

/// The largest `|G1 − G1_reference|` of `d` over `dirs`, with the angle `θ` (degrees) where
/// it is, against [`g1_reference`] for the `f64` density `reference(cos² θm, sin² θm)`.
fn worst_g1_error(
    d: &impl NormalDistribution,
    reference: &impl Fn(f64, f64) -> f64,
    dirs: &[(Vec3, f64, f64)],
) -> (f32, f64) {
    let mut worst = (0.0_f32, 0.0);
    for &(w, c, s) in dirs {
        let err = (d.g1(w) - g1_reference(reference, c, s) as f32).abs();
        if err > worst.0 {
            worst = (err, c.acos().to_degrees());
        }
    }
    worst
}

/// Prints `case`'s largest `|ΔG1|` and its angle (`worst`), asserts it ≤ `bound`, returns it.
fn assert_g1_within(case: &str, worst: (f32, f64), bound: f32) -> f32 {
    eprintln!("{case}: max |ΔG1| = {:.2e} at θ = {:.4}°", worst.0, worst.1);
    assert!(worst.0 <= bound, "{case}: {worst:?}");
    worst.0
}

/// The tabulated `G1` against exact Smith `G1` in `f64` over the whole domain of `α` and `γ`: GGX's
/// closed form at `γ = 2` (Heitz 2014, eq. 72, `G1 = 2 / (1 + √(1 + α² tan² θ))`) from `α = 1e-4`
/// to 10, and the quadrature of the projected-area identity elsewhere, including the corners
/// `α = 10, γ = 10` (where the old quadrature, with one interval over `θm ∈ [1, π/2]`, missed the
/// lobe at grazing: 0.0849 for 0.1002) and `α = 1e-4, γ = 1` (whose slopes span about three and a
/// quarter decades: the old table's last cell spanned `θ` from 0 to 51°, 0.0039 off).
///
/// The bound is the accuracy `Gtr`'s documentation states. What it allows for: the cubic
/// interpolation between the table's nodes, whose error the same table built in `f64` puts
/// at 2.6e-5 at worst over
/// these cases (`γ = 1`, `α = 1e-4`, near grazing) and below 5e-6 for `γ ≥ 1.5`; and the
/// `f32` arithmetic of the nodes (about 200 rounded terms of a positive sum, some 1e-6).
#[test]
fn tabulated_g1_matches_f64_references() {
    const BOUND: f32 = 3e-5;
    // What a construction costs (the table is built in `Gtr::new`), for the record.
    let start = std::time::Instant::now();
    for i in 0..100 {
        std::hint::black_box(gtr(1e-4 + 0.1 * i as f32, 1.0 + 0.09 * i as f32));
    }
    eprintln!("Gtr::new: {:.0?} per construction", start.elapsed() / 100);
    let dirs = directions();
    let mut overall = 0.0_f32;
    // γ = 2 is GGX.
    for alpha in [1e-4_f32, 1e-3, 1e-2, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0] {
        let d = gtr(alpha, 2.0);
        let a2 = f64::from(alpha).powi(2);
        let mut worst = (0.0_f32, 0.0);
        for &(w, c, s) in &dirs {
            let exact = 2.0 / (1.0 + (1.0 + a2 * (s / c) * (s / c)).sqrt());
            let err = (d.g1(w) - exact as f32).abs();
            if err > worst.0 {
                worst = (err, c.acos().to_degrees());
            }
        }
        let case = format!("γ = 2, α = {alpha:e}");
        overall = overall.max(assert_g1_within(&case, worst, BOUND));
    }
    let alphas = [
        1e-4_f32, 3e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1, 0.3, 0.7, 1.0, 1.5, 3.0, 10.0,
    ];
    let gammas = [0.1_f32, 0.3, 0.5, 0.8, 1.0, 1.2, 1.5, 2.5, 4.0, 7.0, 10.0];
    for (alpha, gamma) in alphas
        .into_iter()
        .flat_map(|a| gammas.into_iter().map(move |g| (a, g)))
    {
        let worst = worst_g1_error(&gtr(alpha, gamma), &d_f64(alpha, gamma), &dirs);
        let case = format!("γ = {gamma}, α = {alpha:e}");
        overall = overall.max(assert_g1_within(&case, worst, BOUND));
    }
    eprintln!("max |ΔG1| = {overall:.2e}");
}

/// The normalised Blinn-Phong distribution's own Smith `G1` ([`BlinnPhongNdf::with_exact_smith`])
/// shares the table code: against the same `f64` quadrature of Heitz 2014 eq. 14 with
/// `D = (p + 2)/(2π) cos^p θm`, `p = 2/α² − 2`, over `α` from 0.01 to 1, within the bound
/// `Gtr`'s table meets (the same interpolation and `f32` node arithmetic).
#[test]
fn blinn_phong_exact_smith_matches_the_f64_reference() {
    const BOUND: f32 = 3e-5;
    let dirs = directions();
    let mut overall = 0.0_f32;
    for alpha in [0.01_f32, 0.05, 0.1, 0.3, 0.6, 1.0] {
        let d = BlinnPhongNdf::new(Alpha::new(alpha).unwrap())
            .unwrap()
            .with_exact_smith();
        // p = 2/α² − 2, the exponent of `D = (n·h)^p (p + 2)/(2π)`, in f64, not the type's own.
        let p = 2.0 / (f64::from(alpha) * f64::from(alpha)) - 2.0;
        // cos^p θ from sin² θ, which keeps its digits next to the normal where the lobe is.
        // (p = 0 at α = 1: the uniform D, whose 0 · ln 0 would be NaN.)
        let dd = move |_cos2: f64, sin2: f64| {
            let cos_p = if p == 0.0 {
                1.0
            } else {
                (0.5 * p * (-sin2).ln_1p()).exp()
            };
            (p + 2.0) / (2.0 * PI) * cos_p
        };
        let worst = worst_g1_error(&d, &dd, &dirs);
        let case = format!("Blinn-Phong α = {alpha:e}");
        overall = overall.max(assert_g1_within(&case, worst, BOUND));
    }
    eprintln!("Blinn-Phong: max |ΔG1| = {overall:.2e}");
}
