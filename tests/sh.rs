//! Spherical harmonics (`lobe::sh`), proved by measurement: orthonormality, closed forms
//! against the recurrence, the addition theorem, exact projection, rotation (energy,
//! composition, commuting with evaluation), zonal convolution, irradiance against closed
//! forms and published constants, BRDF transfer, and fault checks that each law catches the
//! bug it exists for.
//!
//! Expected values never come from the code under test: they are closed forms derived here
//! (in comments), published constants (Ramamoorthi & Hanrahan 2001), or a second method (a
//! quadrature written in this file, in `f64`, with Abramowitz & Stegun's tabulated
//! Gauss–Legendre nodes; Monte Carlo with standard errors). Some tests also check that two of
//! the crate's own paths agree (Monte Carlo against `Sh::project_with`, `Zonal::rotated`
//! against `Sh::project`, the rotation paths, `Transfer::project` against its Monte Carlo, the
//! irradiance's three forms): consistency checks, anchored by the independent ones above.
//!
//! `cargo test --test sh -- --nocapture` prints every measured figure.

mod common;

use core::f64::consts::PI;
use glam::{Mat3, Quat};
use lobe::bxdf::{Bxdf, BxdfSample, Lambert, Lobes, Microfacet};
use lobe::fresnel::Conductor;
use lobe::microfacet::{Ggx, Masking};
use lobe::sampling::{cosine_hemisphere, cosine_hemisphere_pdf, uniform_sphere};
use lobe::sh::{
    C1, C2, C3, C4, C5, IrradianceQuadratic, Sh, ShRotation, SphereQuadrature, Transfer, Zonal,
    band_of, basis, basis_closed_form, basis_recurrence, clamped_cosine_eigenvalue, index,
    project_monte_carlo, transfer_monte_carlo,
};
use lobe::verify::Pcg32;
use lobe::{Alpha, ComplexIor, Frame, Vec2, Vec3};

// ---------------------------------------------------------------------------------------
// Independent references
// ---------------------------------------------------------------------------------------

/// 8-point Gauss–Legendre nodes (positive half) and weights on `[−1, 1]`, Abramowitz &
/// Stegun table 25.4: the test's own quadrature, independent of the library's
/// Newton-computed nodes.
const GL8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// Nodes and weights of composite 8-point Gauss–Legendre on `[a, b]` in `panels` panels:
/// exact for polynomials of degree 15, and converging fast for smooth integrands.
fn gl_composite(a: f64, b: f64, panels: usize) -> Vec<(f64, f64)> {
    let h = (b - a) / panels as f64;
    let mut out = Vec::with_capacity(panels * 8);
    for k in 0..panels {
        let mid = a + (k as f64 + 0.5) * h;
        for &(x, w) in &GL8 {
            out.push((mid - 0.5 * h * x, 0.5 * h * w));
            out.push((mid + 0.5 * h * x, 0.5 * h * w));
        }
    }
    out
}

/// A product rule on the sphere around the pole `frame.z`: composite Gauss–Legendre in
/// `cos θ` on `[z0, 1]` times `n_phi` equally spaced azimuths, as (direction, weight) in
/// `f64`. With `z0 = 0` it covers the hemisphere around the pole, so that an integrand cut
/// at the horizon `n·ω = 0` is smooth on the domain.
fn sphere_rule(frame: &Frame, z0: f64, panels: usize, n_phi: usize) -> Vec<(Vec3, f64)> {
    let mut out = Vec::new();
    for (z, wz) in gl_composite(z0, 1.0, panels) {
        let s = (1.0 - z * z).max(0.0).sqrt();
        for j in 0..n_phi {
            let phi = 2.0 * PI * (j as f64 + 0.5) / n_phi as f64;
            let local = Vec3::new((s * phi.cos()) as f32, (s * phi.sin()) as f32, z as f32);
            out.push((frame.to_world(local), wz * 2.0 * PI / n_phi as f64));
        }
    }
    out
}

/// Legendre `P_l(x)` in `f64` by Bonnet's recurrence (Abramowitz & Stegun 8.5.3).
fn legendre_f64(l: usize, x: f64) -> f64 {
    let (mut p0, mut p1) = (1.0, x);
    if l == 0 {
        return 1.0;
    }
    for k in 1..l {
        let k = k as f64;
        let p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
    }
    p1
}

/// Ramamoorthi & Hanrahan 2001's printed `Â_l` for `l = 0 … 6` (§3): `π, 2π/3, π/4, 0,
/// −π/24, 0, π/64`; extended to `l = 8` by their closed form by hand:
/// `Â_7 = 0`, `Â_8 = 2π (−1)³ / (10 · 7) · 8!/(2⁸ 4!²) = −2π/70 · 70/256 = −π/128`.
const A_HAT: [f64; 9] = [
    PI,
    2.0 * PI / 3.0,
    PI / 4.0,
    0.0,
    -PI / 24.0,
    0.0,
    PI / 64.0,
    0.0,
    -PI / 128.0,
];

/// A seeded unit direction.
fn random_dir(rng: &mut Pcg32) -> Vec3 {
    uniform_sphere(rng.next_vec2()).normalize()
}

/// A uniformly distributed rotation (Shoemake 1992, "Uniform random rotations").
fn random_rotation(rng: &mut Pcg32) -> Mat3 {
    let (u1, u2, u3) = (rng.next_f64(), rng.next_f64(), rng.next_f64());
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    let (t2, t3) = (2.0 * PI * u2, 2.0 * PI * u3);
    let q = Quat::from_xyzw(
        (a * t2.sin()) as f32,
        (a * t2.cos()) as f32,
        (b * t3.sin()) as f32,
        (b * t3.cos()) as f32,
    );
    Mat3::from_quat(q.normalize())
}

/// Seeded coefficients, uniform in `[−1, 1]`.
fn random_sh<const N: usize>(rng: &mut Pcg32) -> Sh<N> {
    Sh::new(core::array::from_fn(|_| 2.0 * rng.next_f32() - 1.0))
}

/// A measured figure against its bound.
#[derive(Debug)]
struct Check {
    name: String,
    measured: f64,
    bound: f64,
}

impl Check {
    fn new(name: &str, measured: f64, bound: f64) -> Self {
        let c = Self {
            name: name.to_owned(),
            measured,
            bound,
        };
        eprintln!(
            "{:<60} {:>12.3e}  (bound {:.1e}) {}",
            c.name,
            c.measured,
            c.bound,
            if c.passed() { "ok" } else { "FAILS" }
        );
        c
    }

    fn passed(&self) -> bool {
        self.measured <= self.bound
    }

    fn assert(&self) {
        assert!(self.passed(), "{self:?}");
    }
}

// ---------------------------------------------------------------------------------------
// The laws, each a function of the implementation under test (so that the fault checks at
// the end can hand them a broken one)
// ---------------------------------------------------------------------------------------

/// A basis: the first 81 functions (bands l ≤ 8) at a unit direction.
type Basis81 = dyn Fn(Vec3) -> [f32; 81];

/// `max |⟨Y_i, Y_j⟩ − δ_ij|` over all pairs up to l = 8, by this file's quadrature. The
/// product of two band-8 functions is a polynomial of degree 16: the composite rule (8
/// panels of 8 nodes, exact to degree 15 on each panel, error far below f32 round-off for
/// degree 16) and 40 azimuths (exact for trigonometric degree < 40) integrate it to f64
/// round-off. The bound, 1e-5, is the issue's; f32 basis values contribute ~1e-7.
fn orthonormality(basis: &Basis81) -> Check {
    let rule = sphere_rule(&Frame::from_normal(Vec3::Z), -1.0, 8, 40);
    let mut gram = vec![0.0_f64; 81 * 81];
    for (w, wt) in &rule {
        let y = basis(*w).map(f64::from);
        for i in 0..81 {
            let yi = y[i] * wt;
            for j in i..81 {
                gram[i * 81 + j] += yi * y[j];
            }
        }
    }
    let mut worst = 0.0_f64;
    for i in 0..81 {
        for j in i..81 {
            let want = if i == j { 1.0 } else { 0.0 };
            worst = worst.max((gram[i * 81 + j] - want).abs());
        }
    }
    Check::new("orthonormality, all pairs l ≤ 8", worst, 1e-5)
}

/// `max |closed − recurrence|` over 10 000 seeded directions, bands l ≤ 3. Both are f32
/// evaluations of the same polynomials by different orders of operation, with values below
/// 3 (`½√(105/π) ≈ 2.89` times `|xyz| ≤ 0.19`): they agree to a few ulps of 1, and
/// `8 ε` (≈ 9.5e-7) allows for eight roundings.
fn closed_forms_match_recurrence(closed: &dyn Fn(Vec3) -> [f32; 16]) -> Check {
    let mut rng = Pcg32::new(11, 1);
    let mut worst = 0.0_f64;
    for _ in 0..10_000 {
        let w = random_dir(&mut rng);
        let a = closed(w);
        let mut b = [0.0; 16];
        basis_recurrence(w, &mut b);
        for (x, y) in a.iter().zip(&b) {
            worst = worst.max(f64::from((x - y).abs()));
        }
    }
    Check::new(
        "closed forms = recurrence, l ≤ 3",
        worst,
        8.0 * f64::from(f32::EPSILON),
    )
}

/// The addition theorem `Σ_m Y_lm(a) Y_lm(b) = (2l+1)/4π P_l(a·b)` for 2 000 seeded pairs
/// and every l ≤ 8, `P_l` in f64 by this file's recurrence. Measured as the error relative
/// to `(2l+1)/4π` (the value at `a = b`); the bound allows 2l + 1 f32 products of values
/// each good to about `l` roundings: `(2l+1) · 4l ε ≤ 17 · 32 ε ≈ 6.5e-5` at l = 8, the
/// bound for all bands (measured: 6.0e-6).
fn addition_theorem(basis: &Basis81) -> Check {
    let mut rng = Pcg32::new(12, 1);
    let mut worst = 0.0_f64;
    for _ in 0..2_000 {
        let (a, b) = (random_dir(&mut rng), random_dir(&mut rng));
        let (ya, yb) = (basis(a), basis(b));
        let t = f64::from(a.dot(b)).clamp(-1.0, 1.0);
        for l in 0..=8 {
            let scale = (2 * l + 1) as f64 / (4.0 * PI);
            let mut sum = 0.0;
            for m in -(l as isize)..=(l as isize) {
                let i = index(l, m);
                sum += f64::from(ya[i]) * f64::from(yb[i]);
            }
            worst = worst.max((sum - scale * legendre_f64(l, t)).abs() / scale);
        }
    }
    Check::new(
        "addition theorem, l ≤ 8 (relative)",
        worst,
        17.0 * 32.0 * f64::from(f32::EPSILON),
    )
}

/// A rotation of order-9 coefficients: `g(ω) = f(R⁻¹ω)`.
type Rotate81 = dyn Fn(&Sh<81>, Mat3) -> Sh<81>;

/// Random rotations of random order-9 expansions preserve each band's energy `Σ_m f_lm²`:
/// the largest relative change over 200 rotations and 9 bands. Each output coefficient is a
/// sum of up to 17 products with matrices accurate to a few ulps per band of recurrence,
/// and band 8 is seven recurrence steps from band 1: bound `1e-4` (measured: 3.5e-6).
fn rotation_preserves_energy(rotate: &Rotate81) -> Check {
    let mut rng = Pcg32::new(13, 1);
    let mut worst = 0.0_f64;
    for _ in 0..200 {
        let f = random_sh::<81>(&mut rng);
        let g = rotate(&f, random_rotation(&mut rng));
        for l in 0..9 {
            let (ef, eg) = (f64::from(f.band_energy(l)), f64::from(g.band_energy(l)));
            worst = worst.max((eg - ef).abs() / ef);
        }
    }
    Check::new(
        "rotation preserves band energy, l ≤ 8 (relative)",
        worst,
        1e-4,
    )
}

/// Rotating by `R₂` then by `R₁` equals rotating by `R₁R₂` (with `g = f∘R⁻¹`, turning by
/// `R₂` then `R₁` gives `f∘R₂⁻¹∘R₁⁻¹ = f∘(R₁R₂)⁻¹`); the largest coefficient difference
/// relative to the expansion's norm. Bound `1e-4` as above.
fn rotation_composes(rotate: &Rotate81) -> Check {
    let mut rng = Pcg32::new(14, 1);
    let mut worst = 0.0_f64;
    for _ in 0..100 {
        let f = random_sh::<81>(&mut rng);
        let (r1, r2) = (random_rotation(&mut rng), random_rotation(&mut rng));
        let a = rotate(&rotate(&f, r2), r1);
        let b = rotate(&f, r1 * r2);
        let norm = f64::from(f.squared_norm()).sqrt();
        for (x, y) in a.coeffs.iter().zip(&b.coeffs) {
            worst = worst.max(f64::from((x - y).abs()) / norm);
        }
    }
    Check::new("rotation composes, R1 R2 = R2 then R1", worst, 1e-4)
}

/// The rotated coefficients evaluated at `ω` equal the original function at `R⁻¹ω`, at 20
/// seeded directions for each of 100 rotations; relative to the norm. Bound `1e-4` (the
/// evaluation sums 81 products of values ~1).
fn rotation_commutes_with_evaluation(rotate: &Rotate81) -> Check {
    let mut rng = Pcg32::new(15, 1);
    let mut worst = 0.0_f64;
    for _ in 0..100 {
        let f = random_sh::<81>(&mut rng);
        let r = random_rotation(&mut rng);
        let g = rotate(&f, r);
        let norm = f64::from(f.squared_norm()).sqrt();
        for _ in 0..20 {
            let w = random_dir(&mut rng);
            let d = f64::from(g.eval(w) - f.eval(r.transpose() * w));
            worst = worst.max(d.abs() / norm);
        }
    }
    Check::new("rotation commutes with evaluation", worst, 1e-4)
}

/// The transfer vector of a Lambertian BRDF `ρ/π` reproduces the clamped-cosine kernel:
/// `t_l0 = ρ/π · √((2l+1)/4π) Â_l` with the published `Â_l` ([`A_HAT`]), every `m ≠ 0`
/// coefficient zero, for several viewing directions (Lambert ignores `wo`). The split rule
/// of degree 9 is exact for `max(z, 0) · Y_lm` up to l = 8, so the bound is round-off:
/// `1e-6` against coefficients of size ≤ 0.3.
fn lambert_transfer(bxdf: &dyn Bxdf<Spectrum = f32>, rho: f64) -> Check {
    let rule = SphereQuadrature::exact_for_degree(9).split_at_equator();
    let mut worst = 0.0_f64;
    for wo in [
        Vec3::Z,
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(-0.3, 0.9, 0.3).normalize(),
    ] {
        let t: Transfer<81> = Transfer::project(&Dyn(bxdf), wo, &rule);
        for (i, c) in t.coefficients.coeffs.iter().enumerate() {
            let (l, m) = band_of(i);
            let want = if m == 0 {
                rho / PI * ((2 * l + 1) as f64 / (4.0 * PI)).sqrt() * A_HAT[l]
            } else {
                0.0
            };
            worst = worst.max((f64::from(*c) - want).abs());
        }
    }
    Check::new(
        "Lambert transfer = clamped-cosine kernel · ρ/π",
        worst,
        1e-6,
    )
}

/// `&dyn Bxdf` as a sized `Bxdf`.
struct Dyn<'a>(&'a dyn Bxdf<Spectrum = f32>);

impl Bxdf for Dyn<'_> {
    type Spectrum = f32;
    fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.0.eval(wo, wi)
    }
    fn sample(&self, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<f32>> {
        self.0.sample(wo, u, uc)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.0.pdf(wo, wi)
    }
    fn lobes(&self) -> Lobes {
        self.0.lobes()
    }
}

fn library_basis(w: Vec3) -> [f32; 81] {
    basis::<81>(w)
}

fn library_closed(w: Vec3) -> [f32; 16] {
    let mut y = [0.0; 16];
    basis_closed_form(w, &mut y);
    y
}

fn library_rotate(f: &Sh<81>, r: Mat3) -> Sh<81> {
    f.rotated(r)
}

// ---------------------------------------------------------------------------------------
// Basis
// ---------------------------------------------------------------------------------------

#[test]
fn basis_is_orthonormal_to_band_8() {
    orthonormality(&library_basis).assert();
    // The closed forms (bands ≤ 3) on their own, through the public entry point.
    let closed16 = |w: Vec3| {
        let mut full = basis::<81>(w);
        full[..16].copy_from_slice(&basis::<16>(w));
        full
    };
    orthonormality(&closed16).assert();
}

#[test]
fn closed_forms_equal_the_recurrence() {
    closed_forms_match_recurrence(&library_closed).assert();
}

#[test]
fn addition_theorem_holds_to_band_8() {
    addition_theorem(&library_basis).assert();
}

/// The printed table of the module docs (Ramamoorthi & Hanrahan 2001, eq. 3, to 6 digits),
/// at one direction, against the library: the convention, not just orthonormality.
#[test]
fn basis_matches_the_published_table() {
    let w = Vec3::new(0.48, -0.6, 0.64); // unit: 0.2304 + 0.36 + 0.4096 = 1
    let (x, y, z) = (f64::from(w.x), f64::from(w.y), f64::from(w.z));
    let want = [
        0.282_095,
        0.488_603 * y,
        0.488_603 * z,
        0.488_603 * x,
        1.092_548 * x * y,
        1.092_548 * y * z,
        0.315_392 * (3.0 * z * z - 1.0),
        1.092_548 * x * z,
        0.546_274 * (x * x - y * y),
    ];
    let got = basis::<9>(w);
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        // Six printed digits: the constants are good to 5e-7 relative.
        assert!((f64::from(*g) - w).abs() < 2e-6, "Y_{i}: {g} vs {w}");
    }
}

// ---------------------------------------------------------------------------------------
// Projection
// ---------------------------------------------------------------------------------------

/// The library's quadrature projects every basis function to a unit vector: `⟨Y_i, Y_j⟩`
/// by `Sh::project` (the rule exact for band-limited input of order 9).
#[test]
fn projection_of_each_basis_function_is_a_unit_vector() {
    let mut worst = 0.0_f64;
    for j in 0..81 {
        let f: Sh<81> = Sh::project(|w| basis::<81>(w)[j], 9);
        for (i, c) in f.coeffs.iter().enumerate() {
            let want = if i == j { 1.0 } else { 0.0 };
            worst = worst.max((f64::from(*c) - want).abs());
        }
    }
    Check::new("projection of Y_j gives e_j, l ≤ 8", worst, 1e-5).assert();
}

/// Band-limited functions round-trip: random order-6 coefficients, evaluated and projected
/// back (onto order 6 and onto order 8, whose extra bands must be zero).
#[test]
fn band_limited_functions_round_trip() {
    let mut rng = Pcg32::new(21, 1);
    let mut worst = 0.0_f64;
    for _ in 0..20 {
        let f = random_sh::<36>(&mut rng);
        let same: Sh<36> = Sh::project(|w| f.eval(w), 6);
        let wider: Sh<64> = Sh::project(|w| f.eval(w), 6);
        for i in 0..64 {
            let want = f.coeffs.get(i).copied().unwrap_or(0.0);
            worst = worst.max(f64::from((wider.coeffs[i] - want).abs()));
            if i < 36 {
                worst = worst.max(f64::from((same.coeffs[i] - want).abs()));
            }
        }
    }
    // Coefficients of size ≤ 1 summed over ~100 nodes in f32: a few 1e-7.
    Check::new("projection round trip, order 6", worst, 1e-5).assert();
}

/// Projection of functions given in closed form, against coefficients derived by hand:
/// `x = √(4π/3) Y_{1,1}`; `3z² − 1 = Y_{2,0} / (¼√(5/π))`, so its coefficient is
/// `4√(π/5)`; `1 = √(4π) Y_{0,0}`.
#[test]
fn projection_of_known_polynomials() {
    let f: Sh<16> = Sh::project(|w| w.x, 2);
    assert!((f64::from(f.get(1, 1)) - (4.0 * PI / 3.0).sqrt()).abs() < 1e-5);
    let g: Sh<16> = Sh::project(|w| 3.0 * w.z * w.z - 1.0, 3);
    assert!((f64::from(g.get(2, 0)) - 4.0 * (PI / 5.0).sqrt()).abs() < 1e-5);
    let one: Sh<16> = Sh::project(|_| 1.0, 1);
    assert!((f64::from(one.get(0, 0)) - (4.0 * PI).sqrt()).abs() < 1e-5);
    for (i, c) in g.coeffs.iter().enumerate() {
        if i != index(2, 0) {
            assert!(c.abs() < 1e-6, "coefficient {i} = {c}");
        }
    }
}

/// The Monte Carlo projection agrees with the exact one within k standard errors for every
/// coefficient (Šidák-corrected over the 16 coefficients), on a function with every band.
#[test]
fn monte_carlo_projection_agrees_within_its_error() {
    let f = |w: Vec3| (1.5 * w.z).exp() * (1.0 + 0.5 * w.x * w.y);
    let exact: Sh<16> = Sh::project_with(f, &SphereQuadrature::new(40, 80));
    let mc = project_monte_carlo::<16>(f, 200_000, &mut Pcg32::new(22, 1));
    let k = common::k_sigma(0.01, 16);
    let z = mc.max_z_score(&exact);
    Check::new("Monte Carlo projection, max |z| over 16 coefficients", z, k).assert();
    // And the errors are real: the standard error of c_00 is about σ(f)·√(4π)/√n.
    assert!(mc.coeffs[0].std_err > 1e-4 && mc.coeffs[0].std_err < 1e-2);
}

/// An undefined score is a failure, not agreement: `max_z_score` is NaN (so `z < k` is false)
/// when an estimate has one sample, when `f` is NaN, or when the exact value is, as `within`
/// is false.
#[test]
fn monte_carlo_max_z_score_does_not_hide_nan() {
    let f = |w: Vec3| 1.0 + w.z;
    let exact: Sh<4> = Sh::project(f, 2);
    let one_sample = project_monte_carlo::<4>(|_| 100.0, 1, &mut Pcg32::new(3, 1));
    let nan_f = project_monte_carlo::<4>(|_| f32::NAN, 1_000, &mut Pcg32::new(3, 1));
    let good = project_monte_carlo::<4>(f, 1_000, &mut Pcg32::new(3, 1));
    let mut nan_exact = exact;
    nan_exact.coeffs[2] = f32::NAN;
    for (name, mc, target) in [
        ("one sample", &one_sample, &exact),
        ("f NaN", &nan_f, &exact),
        ("exact NaN", &good, &nan_exact),
    ] {
        let z = mc.max_z_score(target);
        assert!(z.is_nan(), "{name}: max |z| {z}, expected NaN");
        assert!(!mc.within(target, 5.0), "{name}: within");
    }
    // The same estimate against the clean target is a number, and agrees.
    let z = good.max_z_score(&exact);
    assert!(z < common::k_sigma(0.01, 4), "max |z| {z}");
}

// ---------------------------------------------------------------------------------------
// Rotation
// ---------------------------------------------------------------------------------------

#[test]
fn rotation_preserves_band_energy() {
    rotation_preserves_energy(&library_rotate).assert();
}

#[test]
fn rotation_composes_as_matrices_do() {
    rotation_composes(&library_rotate).assert();
}

#[test]
fn rotation_commutes_with_evaluation_for_random_rotations() {
    rotation_commutes_with_evaluation(&library_rotate).assert();
}

/// Every path agrees: `Sh::rotated` (closed forms for bands 1–2, recurrence beyond),
/// `ShRotation::new` and `ShRotation::ivanic_ruedenberg` (band 2 by the recurrence too), and
/// the quaternion entry points; and band 2's closed-form matrix equals the recurrence's.
#[test]
fn rotation_paths_agree() {
    let mut rng = Pcg32::new(16, 1);
    let mut worst = 0.0_f64;
    let mut worst_band2 = 0.0_f64;
    for _ in 0..100 {
        let f = random_sh::<81>(&mut rng);
        let r = random_rotation(&mut rng);
        let a = f.rotated(r);
        let b = ShRotation::<81>::new(r).apply(&f);
        let ir = ShRotation::<81>::ivanic_ruedenberg(r);
        let c = ir.apply(&f);
        let q = Quat::from_mat3(&r);
        let d = f.rotated_quat(q);
        for i in 0..81 {
            for other in [b.coeffs[i], c.coeffs[i], d.coeffs[i]] {
                worst = worst.max(f64::from((a.coeffs[i] - other).abs()));
            }
        }
        let closed = ShRotation::<9>::new(r);
        for (x, y) in closed.block(2).iter().zip(ir.block(2)) {
            worst_band2 = worst_band2.max(f64::from((x - y).abs()));
        }
    }
    Check::new("rotation paths agree, order 9", worst, 1e-4).assert();
    Check::new("band 2: closed form = Ivanic-Ruedenberg", worst_band2, 1e-5).assert();
}

/// A reflection (an orthogonal matrix with det −1) turns the function too: the formulas are
/// polynomials of degree `l` in the matrix entries, so odd bands pick up the parity.
#[test]
fn reflections_commute_with_evaluation() {
    let mut rng = Pcg32::new(18, 1);
    let mirror = Mat3::from_diagonal(Vec3::new(1.0, 1.0, -1.0));
    let mut worst = 0.0_f64;
    for _ in 0..50 {
        let f = random_sh::<81>(&mut rng);
        let q = random_rotation(&mut rng) * mirror;
        let g = f.rotated(q);
        let norm = f64::from(f.squared_norm()).sqrt();
        for _ in 0..20 {
            let w = random_dir(&mut rng);
            let d = f64::from(g.eval(w) - f.eval(q.transpose() * w));
            worst = worst.max(d.abs() / norm);
        }
    }
    Check::new("reflection commutes with evaluation", worst, 1e-4).assert();
    let f = random_sh::<81>(&mut rng);
    let g = f.rotated(-Mat3::IDENTITY); // the antipodal map: f_lm (−1)^l
    for (i, (a, b)) in f.coeffs.iter().zip(&g.coeffs).enumerate() {
        let sign = if band_of(i).0.is_multiple_of(2) {
            1.0
        } else {
            -1.0
        };
        assert!((a * sign - b).abs() < 1e-5, "{i}: {a} vs {b}");
    }
}

/// Rotations with a known effect: a quarter turn about `z` maps `x → y`, so band 1's
/// `(f_{1,−1}, f_{1,0}, f_{1,1}) = (y, z, x)` components become `(x, z, −y)`; the identity
/// changes nothing; and a lobe about `+z` turned by a rotation taking `z` to `d` is the
/// zonal lobe rotated to `d` (Sloan's formula, a second method).
#[test]
fn rotations_with_known_effects() {
    let mut f = Sh::<16>::zero();
    f.coeffs[1] = 1.0; // y
    let g = f.rotated(Mat3::from_rotation_z(core::f32::consts::FRAC_PI_2));
    // f = K y; g(ω) = f(R⁻¹ω) = K (R⁻¹ω)_y = K (−x): only f_{1,1} = −1.
    assert!((g.get(1, 1) + 1.0).abs() < 1e-6 && g.get(1, -1).abs() < 1e-6);
    let mut rng = Pcg32::new(17, 1);
    let h = random_sh::<81>(&mut rng);
    let same = h.rotated(Mat3::IDENTITY);
    for (a, b) in h.coeffs.iter().zip(&same.coeffs) {
        assert!((a - b).abs() < 1e-6);
    }
    let lobe = Zonal::<9>::new(core::array::from_fn(|l| 1.0 / (l as f32 + 1.0)));
    for _ in 0..20 {
        let d = random_dir(&mut rng);
        let r = Mat3::from_quat(Quat::from_rotation_arc(Vec3::Z, d));
        let turned = lobe.to_sh::<81>().rotated(r);
        let direct: Sh<81> = lobe.rotated(d);
        for (a, b) in turned.coeffs.iter().zip(&direct.coeffs) {
            assert!((a - b).abs() < 2e-5, "{a} vs {b}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Zonal harmonics
// ---------------------------------------------------------------------------------------

/// The clamped cosine's `Â_l` equal the published values, and its zonal coefficients equal
/// a second method: `2π ∫ max(t, 0) √((2l+1)/4π) P_l(t) dt` by this file's quadrature.
#[test]
fn clamped_cosine_matches_published_values_and_quadrature() {
    for (l, want) in A_HAT.iter().enumerate() {
        let got = f64::from(clamped_cosine_eigenvalue(l));
        assert!((got - want).abs() < 1e-6, "Â_{l} = {got}, want {want}");
    }
    let k = Zonal::<9>::clamped_cosine();
    for l in 0..9 {
        let norm = ((2 * l + 1) as f64 / (4.0 * PI)).sqrt();
        let quad: f64 = gl_composite(0.0, 1.0, 2)
            .iter()
            .map(|&(t, w)| w * t * norm * legendre_f64(l, t))
            .sum::<f64>()
            * 2.0
            * PI;
        assert!((f64::from(k.coeffs[l]) - quad).abs() < 1e-6, "k_{l}");
    }
    // A profile given as a function: the library's own profile quadrature agrees.
    let from_profile = Zonal::<9>::from_profile(|t| t.max(0.0), 8);
    for l in 0..9 {
        assert!((from_profile.coeffs[l] - k.coeffs[l]).abs() < 1e-6);
    }
}

/// Funk–Hecke: convolving a band-limited `f` with a smooth kernel `k(t) = e^{2t}` equals
/// `∫ k(n·ω) f(ω) dω` by this file's quadrature, at seeded normals. Only the kernel's first
/// five bands meet an order-5 `f`, so the truncated kernel is exact.
#[test]
fn convolution_is_funk_hecke() {
    let mut rng = Pcg32::new(31, 1);
    let f = random_sh::<25>(&mut rng);
    let kernel = Zonal::<5>::from_profile(|t| (2.0 * t).exp(), 16);
    let conv = f.convolve(&kernel);
    let rule = sphere_rule(&Frame::from_normal(Vec3::Z), -1.0, 8, 48);
    let mut worst = 0.0_f64;
    for _ in 0..20 {
        let n = random_dir(&mut rng);
        let exact: f64 = rule
            .iter()
            .map(|(w, wt)| wt * (2.0 * f64::from(n.dot(*w))).exp() * f64::from(f.eval(*w)))
            .sum();
        worst = worst.max((f64::from(conv.eval(n)) - exact).abs() / exact.abs().max(1.0));
    }
    Check::new("Funk-Hecke convolution vs quadrature", worst, 1e-5).assert();
}

/// A zonal lobe turned to `d` equals the direct projection of `k(d·ω)`, for a polynomial
/// profile `k(t) = t³ − t/2 + 0.3` (band-limited to order 4: the projection is exact).
#[test]
fn rotated_zonal_lobe_equals_projection() {
    let profile = |t: f32| t * t * t - 0.5 * t + 0.3;
    let kernel = Zonal::<4>::from_profile(profile, 4);
    let mut rng = Pcg32::new(32, 1);
    let mut worst = 0.0_f64;
    for _ in 0..20 {
        let d = random_dir(&mut rng);
        let lobe: Sh<16> = kernel.rotated(d);
        let direct: Sh<16> = Sh::project(|w| profile(d.dot(w)), 4);
        for (a, b) in lobe.coeffs.iter().zip(&direct.coeffs) {
            worst = worst.max(f64::from((a - b).abs()));
        }
    }
    Check::new("rotated zonal lobe = projection", worst, 1e-5).assert();
}

// ---------------------------------------------------------------------------------------
// Irradiance
// ---------------------------------------------------------------------------------------

/// A constant environment of radiance `L` gives `E = π L` for every normal (`∫ max(n·ω, 0)
/// dω = π`), by both paths and in RGB.
#[test]
fn constant_environment_gives_pi_l() {
    let l = Vec3::new(0.5, 1.0, 2.0);
    let env: Sh<9, Vec3> = Sh::project(|_| l, 1);
    let wide: Sh<25, Vec3> = Sh::project(|_| l, 1);
    let quad = IrradianceQuadratic::new(&env);
    let mut rng = Pcg32::new(41, 1);
    let mut worst = 0.0_f64;
    for _ in 0..1000 {
        let n = random_dir(&mut rng);
        let want = l * std::f32::consts::PI;
        for e in [env.irradiance(n), wide.irradiance(n), quad.eval(n)] {
            worst = worst.max(f64::from(
                (e - want).abs().max_element() / want.max_element(),
            ));
        }
    }
    // A handful of f32 roundings of values up to 2π: eight ulps, 1e-6 relative.
    Check::new("constant environment: E = πL (relative)", worst, 1e-6).assert();
}

/// One directional light of irradiance `E₀` from `d`: the exact irradiance is
/// `E₀ max(t, 0)` with `t = n·d`, and order 3 gives `E₀ Σ_{l≤2} Â_l (2l+1)/4π P_l(t) =
/// E₀ (3/32 + t/2 + 15t²/32)`. Derived by hand: the error is `3/32 − t/2 + 15t²/32` for
/// `t ≥ 0` and its mirror image for `t < 0`, largest at the terminator `t = 0`: **max
/// 3/32 = 0.09375 E₀**; over normals uniform on the sphere (uniform in `t`), the mean
/// square is `∫₀¹ (3/32 − t/2 + 15t²/32)² dt = 1/768`: **RMS `1/√768 ≈ 0.03608 E₀`**.
/// Measured on 20 001 normals (the midpoint rule in `t`, whose error is ~1e-9 here), the max
/// exactly at `t = 0`.
#[test]
fn directional_light_has_the_known_order_3_error() {
    let d = Vec3::new(0.2, 0.3, 0.9).normalize();
    let e0 = 2.0_f32;
    let light: Sh<9> = Sh::from_direction(d, e0);
    let quad = IrradianceQuadratic::new(&light);
    let frame = Frame::from_normal(d);
    let (n_t, mut sum_sq, mut max_err) = (20_001, 0.0_f64, 0.0_f64);
    for k in 0..n_t {
        let t = -1.0 + 2.0 * (k as f64 + 0.5) / n_t as f64; // k = 10 000: t = 0
        let s = (1.0 - t * t).sqrt();
        let phi = 0.7 * k as f64;
        let n = frame
            .to_world(Vec3::new(
                (s * phi.cos()) as f32,
                (s * phi.sin()) as f32,
                t as f32,
            ))
            .normalize();
        let exact = f64::from(e0) * f64::from(n.dot(d)).max(0.0);
        let err = (f64::from(quad.eval(n)) - exact) / f64::from(e0);
        sum_sq += err * err;
        max_err = max_err.max(err.abs());
    }
    let rms = (sum_sq / n_t as f64).sqrt();
    eprintln!("directional light, order 3: RMS error {rms:.5} E0, max {max_err:.5} E0");
    Check::new(
        "directional light: |RMS − 1/√768| (units of E0)",
        (rms - 1.0 / 768f64.sqrt()).abs(),
        1e-5,
    )
    .assert();
    Check::new(
        "directional light: |max − 3/32| (units of E0)",
        (max_err - 3.0 / 32.0).abs(),
        1e-5,
    )
    .assert();
}

/// The 9-coefficient quadratic form equals the general path, and its constants are
/// Ramamoorthi & Hanrahan's printed ones (2001, eq. 12, six decimals).
#[test]
fn quadratic_form_equals_the_general_path() {
    for (got, printed) in [
        (C1, 0.429_043),
        (C2, 0.511_664),
        (C3, 0.743_125),
        (C4, 0.886_227),
        (C5, 0.247_708),
    ] {
        assert!(
            (f64::from(got) - printed).abs() <= 5e-7,
            "{got} vs {printed}"
        );
    }
    let mut rng = Pcg32::new(42, 1);
    let mut worst = 0.0_f64;
    for _ in 0..200 {
        let l = random_sh::<9>(&mut rng);
        let quad = IrradianceQuadratic::new(&l);
        let m = quad.matrix();
        for _ in 0..20 {
            let n = random_dir(&mut rng);
            let general = l.irradiance(n);
            let h = [n.x, n.y, n.z, 1.0];
            let mut via_matrix = 0.0;
            for i in 0..4 {
                for j in 0..4 {
                    via_matrix += h[i] * m[i][j] * h[j];
                }
            }
            let via_sh = l.irradiance_sh().eval(n);
            for other in [quad.eval(n), via_matrix, via_sh] {
                worst = worst.max(f64::from((general - other).abs()));
            }
        }
    }
    Check::new("quadratic form = general path, order 3", worst, 1e-5).assert();
}

/// The general path at order 5 is exact for radiance band-limited to order 5 (bands 3 and 4
/// included, with `Â_4 = −π/24`): against `∫ L(ω) max(n·ω, 0) dω` by this file's
/// quadrature over the hemisphere around `n` (where the integrand is a polynomial).
#[test]
fn general_irradiance_is_exact_for_band_limited_radiance() {
    let mut rng = Pcg32::new(43, 1);
    let l = random_sh::<25>(&mut rng);
    let mut worst = 0.0_f64;
    for _ in 0..20 {
        let n = random_dir(&mut rng);
        let rule = sphere_rule(&Frame::from_normal(n), 0.0, 2, 16);
        let exact: f64 = rule
            .iter()
            .map(|(w, wt)| wt * f64::from(l.eval(*w)) * f64::from(n.dot(*w)).max(0.0))
            .sum();
        worst = worst.max((f64::from(l.irradiance(n)) - exact).abs());
    }
    Check::new("irradiance, order 5, vs hemisphere quadrature", worst, 2e-5).assert();
}

/// `∫₀^{2π} max(a + b cos φ, 0) dφ` for `b ≥ 0`: `2πa` when `a ≥ b`, `0` when `a ≤ −b`, else
/// `2(a φ₀ + b sin φ₀)` with `φ₀ = arccos(−a/b)` (the arc where the integrand is positive).
fn ring_clamped(a: f64, b: f64) -> f64 {
    if a >= b {
        2.0 * PI * a
    } else if a <= -b {
        0.0
    } else {
        let phi0 = (-a / b).acos();
        2.0 * (a * phi0 + b * phi0.sin())
    }
}

/// The ray tracer's sky (a gradient from horizon to zenith over a uniform ground, with a
/// sharp horizon; its three channels, `z` up) at order 3, two ways.
///
/// First, sharply: the order-3 irradiance the library computes (projection by its split
/// quadrature, then `Â_l`) equals the order-3 irradiance derived here in closed form. The sky
/// is zonal, so `E₃(n) = Σ_{l≤2} Â_l (2l+1)/2 s_l P_l(n_z)` with `s_l = ∫₋₁¹ sky(z) P_l(z) dz`
/// ([`A_HAT`], [`legendre_f64`]); with `sky = ground` below the horizon and `horizon +
/// (zenith − horizon) √z` above, and `∫₀¹ zᵏ √z dz = 2/(2k + 3)`:
/// `s₀ = ground + horizon + (zenith − horizon) 2/3`,
/// `s₁ = −ground/2 + horizon/2 + (zenith − horizon) 2/5`,
/// `s₂ = (zenith − horizon) 2/21` (`∫ P₂` over either half is 0). The bound, 1e-5 of the mean
/// irradiance, is the projection's own error: its Gauss–Legendre nodes in `z` integrate
/// `√z P_l(z)` only to algebraic order (the square root's derivative is infinite at the
/// horizon), below 1e-6 at 64 nodes, plus the `f32` roundings (1e-7); measured 6.5e-7 at
/// worst (red). A wrong `Â₂` (zero, say: 6% of the mean) or a coefficient projected in the
/// wrong frame is off by percents.
///
/// Second, the figure Ramamoorthi & Hanrahan give for natural light (2001, abstract: average
/// errors of about 1%): order 3 against the exact irradiance, RMS ≤ 1% of the mean
/// irradiance in every channel; the maximum is printed. The exact irradiance, derived here:
/// `π ground + (horizon − ground) π (1 + n_z)/2` (a uniform upper hemisphere on a tilted
/// plane) plus `(zenith − horizon) ∫₀¹ √z R(z) dz`, where `R(z) = ∫ max(n·ω, 0) dφ` over the
/// ring at height `z` is [`ring_clamped`]`(n_z z, √(1 − z²) √(1 − n_z²))`; the last integral
/// is taken in `u = √z` by composite Gauss–Legendre (200 panels; 100 panels agree to the
/// printed figure).
#[test]
fn sky_irradiance_error_is_small() {
    // (zenith, horizon, ground) of the red, green and blue channels (examples/raytracer).
    let channels = [
        ("red", 0.10_f64, 0.42_f64, 0.10_f64),
        ("green", 0.18, 0.42, 0.09),
        ("blue", 0.40, 0.45, 0.08),
    ];
    // The ring formula integrates the uniform hemisphere to its closed form too (at
    // n = (0.6, 0, 0.8): π (1 + 0.8)/2).
    let cap: f64 = gl_composite(0.0, 1.0, 200)
        .iter()
        .map(|&(z, w)| w * ring_clamped(0.8 * z, (1.0 - z * z).sqrt() * 0.6))
        .sum();
    assert!((cap - PI * 1.8 / 2.0).abs() < 1e-6, "{cap}");
    for (name, zenith, horizon, ground) in channels {
        let sky = |w: Vec3| {
            if w.z < 0.0 {
                ground as f32
            } else {
                (horizon + (zenith - horizon) * f64::from(w.z).sqrt()) as f32
            }
        };
        let l: Sh<9> = Sh::project_with(sky, &SphereQuadrature::new(64, 16).split_at_equator());
        let exact = |n: Vec3, panels: usize| -> f64 {
            let nz = f64::from(n.z);
            let nr = (1.0 - nz * nz).max(0.0).sqrt();
            let gradient: f64 = gl_composite(0.0, 1.0, panels)
                .iter()
                .map(|&(u, w)| {
                    let z = u * u;
                    w * 2.0 * u * u * ring_clamped(nz * z, (1.0 - z * z).max(0.0).sqrt() * nr)
                })
                .sum();
            PI * ground + (horizon - ground) * PI * (1.0 + nz) / 2.0 + (zenith - horizon) * gradient
        };
        let gradient = zenith - horizon;
        let s = [
            ground + horizon + gradient * 2.0 / 3.0,
            -ground / 2.0 + horizon / 2.0 + gradient * 2.0 / 5.0,
            gradient * 2.0 / 21.0,
        ];
        let order_3 = |n: Vec3| -> f64 {
            (0..3)
                .map(|l| {
                    A_HAT[l] * (2 * l + 1) as f64 / 2.0 * s[l] * legendre_f64(l, f64::from(n.z))
                })
                .sum()
        };
        let mut rng = Pcg32::new(44, 1);
        let (mut sum_sq, mut sum_e, mut max_rel, mut ref_err, mut vs_closed) =
            (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
        let count = 2000;
        for _ in 0..count {
            let n = random_dir(&mut rng);
            let e = exact(n, 200);
            ref_err = ref_err.max((e - exact(n, 100)).abs() / e);
            let got = f64::from(l.irradiance(n));
            vs_closed = vs_closed.max((got - order_3(n)).abs());
            let err = got - e;
            sum_sq += err * err;
            sum_e += e;
            max_rel = max_rel.max(err.abs() / e);
        }
        let mean = sum_e / count as f64;
        let rms_rel = (sum_sq / count as f64).sqrt() / mean;
        eprintln!(
            "sky, {name}, order 3: RMS error {rms_rel:.2e} of the mean irradiance, max \
             {max_rel:.2e} of the local one (reference good to {ref_err:.1e})"
        );
        Check::new(
            &format!("sky, {name}: order 3 against its closed form (rel. to mean)"),
            vs_closed / mean,
            1e-5,
        )
        .assert();
        Check::new(
            &format!("sky, {name}: irradiance RMS error (relative to mean)"),
            rms_rel,
            0.01,
        )
        .assert();
    }
}

// ---------------------------------------------------------------------------------------
// BRDF transfer
// ---------------------------------------------------------------------------------------

#[test]
fn lambert_transfer_reproduces_the_clamped_cosine() {
    let rho = 0.7;
    lambert_transfer(&Lambert::new(rho).unwrap(), f64::from(rho)).assert();
}

/// The fraction of a Lambertian lobe's `L²` energy kept by each order, against the closed
/// form `Σ_{l<L} (2l+1)/4π Â_l² / (2π/3)` with the published `Â_l` (`∫ max(z,0)² dω =
/// 2π/3`): order 1 `3/8`, order 2 `7/8`, order 3 `127/128`.
#[test]
fn lambert_captured_fraction_matches_the_closed_form() {
    let white = Lambert::new(1.0_f32).unwrap();
    let rule = SphereQuadrature::exact_for_degree(9).split_at_equator();
    let t: Transfer<81> = Transfer::project(&white, Vec3::Z, &rule);
    let norm = f64::from(t.squared_norm);
    assert!(
        (norm - 2.0 / (3.0 * PI)).abs() < 1e-6,
        "∫ (cos/π)² = 2/(3π)"
    );
    assert!((f64::from(t.albedo) - 1.0).abs() < 1e-6);
    let mut kept = 0.0;
    for order in 1..=9 {
        let l = order - 1;
        kept += (2 * l + 1) as f64 / (4.0 * PI) * A_HAT[l] * A_HAT[l] / (PI * PI);
        let got: f64 = t.coefficients.coeffs[..order * order]
            .iter()
            .map(|c| f64::from(c * c))
            .sum::<f64>()
            / norm;
        eprintln!(
            "Lambert, order {order}: captured {got:.6} (closed form {:.6})",
            kept / norm
        );
        assert!((got - kept / norm).abs() < 1e-5);
    }
    let order3: f64 = t.coefficients.coeffs[..9]
        .iter()
        .map(|c| f64::from(c * c))
        .sum();
    assert!((order3 / norm - 127.0 / 128.0).abs() < 1e-5);
}

/// The fractions of a transfer vector's `L²` energy kept at orders 3, 4 and 9.
fn captured(t: &Transfer<81>) -> [f64; 3] {
    let norm = f64::from(t.squared_norm);
    [3, 4, 9].map(|order| {
        t.coefficients.coeffs[..order * order]
            .iter()
            .map(|c| f64::from(c * c))
            .sum::<f64>()
            / norm
    })
}

/// A GGX conductor (gold's red channel, height-correlated masking).
fn ggx_gold(a: f32) -> Microfacet<Ggx, Conductor<f32>> {
    let gold = ComplexIor::new(0.143_f32, 3.983).unwrap();
    Microfacet::new(
        Ggx::isotropic(Alpha::new(a).unwrap()),
        Masking::HeightCorrelated,
        Conductor { ior: gold },
    )
}

/// The viewing direction at `theta_deg` from the normal.
fn view(theta_deg: f32) -> Vec3 {
    let t = theta_deg.to_radians();
    Vec3::new(t.sin(), 0.0, t.cos())
}

/// The GGX conductor's transfer vector at θo = 30° for α ∈ {1, 0.5, 0.2}: the quadrature
/// (96 × 192 nodes per hemisphere; doubling them changes no figure in the fourth decimal)
/// is checked against importance-sampled Monte Carlo, every coefficient within k standard
/// errors (Šidák-corrected over 3 × 81 coefficients); then the fraction of the lobe the
/// irradiance order keeps falls as α falls (order 3: 0.975, 0.949, 0.507).
///
/// Not at every order: at α = 1 GGX's `D` is the constant `1/π`, and the lobe `f cos θi`
/// ends in a step at the horizon whose slowly decaying spectrum makes α = 1 keep *less* than
/// α = 0.5 at orders 4 and 9 (0.984 vs 0.988; 0.9988 vs 0.9996). The figures are printed.
#[test]
fn ggx_captured_fraction_falls_with_alpha() {
    let rule = SphereQuadrature::new(96, 192).split_at_equator();
    let wo = view(30.0);
    let k = common::k_sigma(0.01, 3 * 81);
    let mut previous = f64::INFINITY;
    for (seed, a) in [1.0_f32, 0.5, 0.2].into_iter().enumerate() {
        let ggx = ggx_gold(a);
        let t: Transfer<81> = Transfer::project(&ggx, wo, &rule);
        let mc =
            transfer_monte_carlo::<81, _>(&ggx, wo, 400_000, &mut Pcg32::new(50 + seed as u64, 1));
        let z = mc.max_z_score(&t.coefficients);
        Check::new(
            &format!("GGX α={a}: quadrature vs Monte Carlo, max |z|"),
            z,
            k,
        )
        .assert();
        let [o3, o4, o9] = captured(&t);
        eprintln!(
            "GGX gold (red) α={a}, θo=30°: albedo {:.4}, captured order 3 {o3:.4}, order 4 {o4:.4}, order 9 {o9:.4}",
            t.albedo
        );
        assert!(o3 < previous, "order 3 falls with α");
        assert!(o3 > 0.0 && o9 <= 1.0 + 1e-4);
        previous = o3;
    }
}

/// Below α = 0.5, where the lobe narrows away from the horizon, the captured fraction falls
/// with α at every order and every viewing angle: α ∈ {0.5, 0.35, 0.2, 0.1}, orders 3, 4, 9,
/// θo ∈ {0°, 30°, 60°}.
#[test]
fn narrow_ggx_lobes_lose_more_at_every_order() {
    let rule = SphereQuadrature::new(96, 192).split_at_equator();
    for theta in [0.0, 30.0, 60.0] {
        let mut previous = [f64::INFINITY; 3];
        for a in [0.5_f32, 0.35, 0.2, 0.1] {
            let t: Transfer<81> = Transfer::project(&ggx_gold(a), view(theta), &rule);
            let kept = captured(&t);
            eprintln!("GGX α={a}, θo={theta}°: captured {kept:.4?} (orders 3, 4, 9)");
            for (now, before) in kept.iter().zip(&previous) {
                assert!(now < before, "α={a}, θo={theta}: {kept:?} vs {previous:?}");
            }
            previous = kept;
        }
    }
}

// ---------------------------------------------------------------------------------------
// Fault checks (in the style of tests/faults.rs): each law catches its bug
// ---------------------------------------------------------------------------------------

/// A basis with one wrong normalisation constant: `Y_{2,0}` written with `½√(5/π)` instead
/// of `¼√(5/π)`. Orthonormality, the closed-form check and the addition theorem catch it.
#[test]
fn fault_wrong_normalisation_constant_is_caught() {
    let broken = |w: Vec3| {
        let mut y = basis::<81>(w);
        y[index(2, 0)] *= 2.0;
        y
    };
    let broken_closed = |w: Vec3| {
        let mut y = library_closed(w);
        y[index(2, 0)] *= 2.0;
        y
    };
    eprintln!("-- a basis with Y_20's constant doubled:");
    assert!(!orthonormality(&broken).passed());
    assert!(!closed_forms_match_recurrence(&broken_closed).passed());
    assert!(!addition_theorem(&broken).passed());
    // The same checks pass the correct basis: the failures are the bug's.
    assert!(orthonormality(&library_basis).passed());
    assert!(closed_forms_match_recurrence(&library_closed).passed());
    assert!(addition_theorem(&library_basis).passed());
}

/// A rotation with one sign flipped: Ivanic & Ruedenberg's matrices with the entry
/// `M³_{−1,2}` negated (as a `+` for `−` slip in one term of the recurrence would). Energy,
/// composition and evaluation all catch it.
#[test]
fn fault_rotation_sign_flip_is_caught() {
    let broken = |f: &Sh<81>, r: Mat3| {
        let rot = ShRotation::<81>::new(r);
        let mut out = rot.apply(f);
        let l = 3;
        let base = index(l, -3);
        // Recompute band 3 with one entry's sign flipped.
        for row in 0..7 {
            let mut sum = 0.0;
            for col in 0..7 {
                let (m, n) = (row as isize - 3, col as isize - 3);
                let mut e = rot.entry(l, m, n);
                if (m, n) == (-1, 2) {
                    e = -e;
                }
                sum += e * f.coeffs[base + col];
            }
            out.coeffs[base + row] = sum;
        }
        out
    };
    eprintln!("-- a rotation with one sign flipped:");
    assert!(!rotation_preserves_energy(&broken).passed());
    assert!(!rotation_composes(&broken).passed());
    assert!(!rotation_commutes_with_evaluation(&broken).passed());
    assert!(rotation_commutes_with_evaluation(&library_rotate).passed());
}

/// A Lambertian kernel missing its `1/π` (`f = ρ` instead of `ρ/π`, a renderer's classic
/// slip): the transfer check catches it (every coefficient π times too large).
#[test]
fn fault_kernel_missing_one_over_pi_is_caught() {
    struct NoPi(f32);
    impl Bxdf for NoPi {
        type Spectrum = f32;
        fn eval(&self, wo: Vec3, wi: Vec3) -> f32 {
            if wo.z > 0.0 && wi.z > 0.0 {
                self.0
            } else {
                0.0
            }
        }
        fn sample(&self, wo: Vec3, u: Vec2, _uc: f32) -> Option<BxdfSample<f32>> {
            let wi = cosine_hemisphere(u);
            let pdf = cosine_hemisphere_pdf(wi.z);
            (wo.z > 0.0 && pdf > 0.0).then(|| BxdfSample {
                wi,
                f: self.eval(wo, wi),
                pdf,
                lobe: Lobes::DIFFUSE_REFLECTION,
                eta: 1.0,
            })
        }
        fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
            if wo.z > 0.0 && wi.z > 0.0 {
                cosine_hemisphere_pdf(wi.z)
            } else {
                0.0
            }
        }
        fn lobes(&self) -> Lobes {
            Lobes::DIFFUSE_REFLECTION
        }
    }
    eprintln!("-- a Lambertian kernel without its 1/π:");
    assert!(!lambert_transfer(&NoPi(0.7), 0.7).passed());
    assert!(lambert_transfer(&Lambert::new(0.7_f32).unwrap(), 0.7).passed());
}
