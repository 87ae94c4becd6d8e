//! Smith identities and totality of every microfacet distribution, over adversarial inputs
//! (proptest, seeded): `G1 = 1/(1+Λ)`, the symmetries of `Λ`, `G2 ≤ min(G1)`,
//! `G2_separable ≤ G2`, isotropy, and finite non-negative values for tiny and huge `α`,
//! grazing directions and normals below the horizon.

mod common;

use lobe::frame::reflect_away;
use lobe::microfacet::{
    Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr, NormalDistribution, SampleDCos,
};
use lobe::{Alpha, Vec2, Vec3};
use proptest::prelude::*;

/// A unit direction with `cos θ` from uniform down to 1e-7 (either hemisphere) and any `φ`.
fn direction() -> impl Strategy<Value = Vec3> {
    let cos = prop_oneof![
        3 => -1.0f32..=1.0,
        1 => (-7.0f32..-1.0).prop_map(|e| 10f32.powf(e)),
        1 => (-7.0f32..-1.0).prop_map(|e| -(10f32.powf(e))),
        1 => Just(1.0f32),
        1 => Just(0.0f32),
    ];
    (cos, 0.0f32..core::f32::consts::TAU).prop_map(|(c, phi)| {
        let s = (1.0 - c * c).max(0.0).sqrt();
        Vec3::new(s * phi.cos(), s * phi.sin(), c)
    })
}

/// A width log-uniform in `[1e-4, 10]`, with the ends.
fn alpha() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => (-4.0f32..1.0).prop_map(|e| 10f32.powf(e)),
        1 => Just(Alpha::MIN),
        1 => Just(Alpha::MAX),
    ]
}

/// A distribution with exact Smith masking, chosen by `kind`.
fn exact(kind: u8, ax: f32, ay: f32, gamma: f32) -> Box<dyn SampleDCos> {
    let (ax, ay) = (Alpha::new(ax).unwrap(), Alpha::new(ay).unwrap());
    match kind % 4 {
        0 => Box::new(Ggx::new(ax, ay)),
        1 => Box::new(Beckmann::new(ax, ay)),
        2 => Box::new(Gtr::new(ax, gamma).unwrap()),
        _ => {
            let a = Alpha::new(ax.get().min(1.0)).unwrap();
            Box::new(BlinnPhongNdf::new(a).unwrap().with_exact_smith())
        }
    }
}

/// Equal to within `rel` of the larger magnitude (`approx`'s relative comparison).
fn close(a: f32, b: f32, rel: f32) -> bool {
    approx::relative_eq!(a, b, epsilon = 0.0, max_relative = rel)
}

proptest! {
    #![proptest_config(common::proptest_config(2048))]

    #[test]
    fn smith_identities_hold(
        kind in 0u8..4, ax in alpha(), ay in alpha(), gamma in 0.1f32..10.0,
        wo in direction(), wi in direction(),
    ) {
        let d = exact(kind, ax, ay, gamma);
        let (lo, li) = (d.lambda(wo), d.lambda(wi));
        let (go, gi) = (d.g1(wo), d.g1(wi));
        prop_assert!(lo >= 0.0 && li >= 0.0, "Λ < 0: {lo}, {li}");
        // G1 = 1/(1 + Λ), whichever of the two a type computes directly. For GGX these are two
        // closed forms; the tabulated types (GTR, Blinn-Phong with exact Smith) and Beckmann's
        // exact masking derive one from the other, so for them this checks that the two stay
        // consistent (their accuracy: `microfacet_gtr.rs`, `microfacet_reference.rs`).
        prop_assert!(close(go, 1.0 / (1.0 + lo), 1e-5), "G1 {go} vs 1/(1+Λ) {}", 1.0 / (1.0 + lo));
        // Λ depends on tan² θ and φ only: the same below the surface and for −w mirrored
        // in the normal plane.
        prop_assert!(close(d.lambda(Vec3::new(wo.x, wo.y, -wo.z)), lo, 1e-6));
        prop_assert!(close(d.lambda(Vec3::new(-wo.x, -wo.y, wo.z)), lo, 1e-6));
        // Height-correlated G2 is below either G1, and separable G2 below it.
        let g2 = d.g2(wo, wi);
        prop_assert!(g2 <= go.min(gi) * (1.0 + 1e-6), "G2 {g2} > min(G1) {}", go.min(gi));
        prop_assert!(d.g2_separable(wo, wi) <= g2 * (1.0 + 1e-6), "separable above correlated");
        prop_assert!((0.0..=1.0).contains(&go) && (0.0..=1.0).contains(&g2));
    }

    #[test]
    fn isotropic_results_do_not_depend_on_phi(
        kind in 0u8..4, a in alpha(), gamma in 0.1f32..10.0, w in direction(), m in direction(),
        rot in 0.0f32..core::f32::consts::TAU,
    ) {
        let d = exact(kind, a, a, gamma);
        let (s, c) = rot.sin_cos();
        let turn = |v: Vec3| Vec3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
        // Λ only ever enters as 1 + Λ (in G1 and G2), so compare that: Λ's far tail
        // (Beckmann's ~1e-15 near the normal) is a cancellation of two tiny terms.
        prop_assert!(close(1.0 + d.lambda(turn(w)), 1.0 + d.lambda(w), 1e-5), "Λ depends on φ");
        prop_assert!(close(d.d(turn(m)), d.d(m), 1e-4), "D depends on φ");
        prop_assert!(close(d.d_visible(turn(w), turn(m)), d.d_visible(w, m), 1e-3));
    }

    #[test]
    fn every_value_is_finite_and_non_negative(
        kind in 0u8..5, ax in alpha(), ay in alpha(), gamma in 0.1f32..10.0,
        w in direction(), m in direction(), u in (0.0f32..1.0, 0.0f32..1.0),
    ) {
        let d: Box<dyn SampleDCos> = if kind == 4 {
            let (ax, ay) = (Alpha::new(ax).unwrap(), Alpha::new(ay).unwrap());
            Box::new(Beckmann::new(ax, ay).with_masking(BeckmannMasking::WalterRational))
        } else {
            exact(kind, ax, ay, gamma)
        };
        let u = Vec2::new(u.0, u.1);
        let view = d.view(w);
        for (name, v) in [
            ("D", d.d(m)),
            ("G1", d.g1(w)),
            ("G2", d.g2(w, m)),
            ("G2 separable", d.g2_separable(w, m)),
            ("D_w", d.d_visible(w, m)),
            ("pdf", d.pdf(&view, m, d.d(m))),
            ("pdf reflection", d.pdf_reflection(&view, m, d.d(m))),
            ("pdf D cos", d.pdf_d_cos(m)),
        ] {
            prop_assert!(v.is_finite() && v >= 0.0, "{name} = {v} for w = {w:?}, m = {m:?}");
        }
        prop_assert!(d.lambda(w) >= 0.0 && !d.lambda(w).is_nan());
        if m.z <= 0.0 {
            prop_assert_eq!(d.d(m), 0.0);
        }
        for (name, s) in [
            ("sample", d.sample(&view, u)),
            ("sample_reflection", d.sample_reflection(&view, u)),
            ("sample_d_cos", d.sample_d_cos(u)),
        ] {
            prop_assert!(s.is_finite() && (s.length() - 1.0).abs() < 1e-4 && s.z >= 0.0,
                "{name} gave {s:?} for w = {w:?}, u = {u:?}");
        }
    }

    #[test]
    fn visible_samplers_are_total(
        beckmann in any::<bool>(), ax in alpha(), ay in alpha(), w in direction(),
        u in (0.0f32..=1.0, 0.0f32..=1.0),
    ) {
        let (ax, ay) = (Alpha::new(ax).unwrap(), Alpha::new(ay).unwrap());
        let u = Vec2::new(u.0, u.1);
        let ggx = Ggx::new(ax, ay);
        let m = if beckmann {
            let b = Beckmann::new(ax, ay);
            b.sample(&b.view(w), u)
        } else {
            ggx.sample(&ggx.view(w), u)
        };
        prop_assert!(m.is_finite() && (m.length() - 1.0).abs() < 1e-4 && m.z >= 0.0, "{m:?}");
        let b = ggx.sample_visible_bounded(w, u);
        prop_assert!(b.is_finite() && (b.length() - 1.0).abs() < 1e-4 && b.z >= 0.0, "{b:?}");
        let p = ggx.d_visible_bounded(w, b);
        prop_assert!(p.is_finite() && p >= 0.0);
    }
}

proptest! {
    #![proptest_config(common::proptest_config(2048))]

    /// `sample_reflected` (GGX and Beckmann reflect about their normal before normalising it)
    /// is the view reflected about `sample_reflection`'s unit normal, to a few ulps, and unit.
    /// (Only the distributions that override it: for the others it is that reflection.)
    #[test]
    fn reflected_samples_reflect_about_the_sampled_normal(
        kind in 0u8..4, ax in alpha(), ay in alpha(),
        w in direction(), u in (0.0f32..=1.0, 0.0f32..=1.0),
    ) {
        let (ax, ay) = (Alpha::new(ax).unwrap(), Alpha::new(ay).unwrap());
        let d: Box<dyn NormalDistribution> = match kind {
            0 => Box::new(Ggx::new(ax, ay)),
            1 => Box::new(Ggx::new(ax, ay).with_bounded_reflection(false)),
            2 => Box::new(Beckmann::new(ax, ay)),
            _ => Box::new(Beckmann::new(ax, ay).with_masking(BeckmannMasking::WalterRational)),
        };
        let u = Vec2::new(u.0, u.1);
        let view = d.view(w);
        let r = d.sample_reflected(&view, u);
        let want = reflect_away(view.w, d.sample_reflection(&view, u));
        prop_assert!((r - want).length() < 2e-6, "{r:?} against {want:?} for w = {w:?}, u = {u:?}");
        prop_assert!((r.length() - 1.0).abs() < 2e-6, "|{r:?}| = {}", r.length());
    }
}

/// At the end `u.y = 1` GGX's cap sampler can return a normal of zero or subnormal squared
/// length (the cap's lowest point on the stretched view's antipode): there the reflected
/// sample is still the reflection about that normal, on the same side of the surface as the
/// reflection about the normalised normal and within round-off of it (a fallback to `z` had
/// turned a horizontal normal's reflection, below the surface, into an accepted mirror
/// direction), and the reflection about `z` for a zero normal.
#[test]
fn reflected_samples_at_short_normals_reflect_about_the_normalised_one() {
    let tiny = Alpha::new(1e-4).unwrap();
    let one = Alpha::new(1.0).unwrap();
    let cases = [
        (Ggx::new(one, one).with_bounded_reflection(false), Vec3::Z),
        (
            Ggx::new(one, one).with_bounded_reflection(false),
            Vec3::new(1e-20, 0.0, 1.0),
        ),
        (
            Ggx::new(one, one).with_bounded_reflection(false),
            Vec3::new(0.0, -3e-21, 1.0),
        ),
        (Ggx::new(tiny, tiny), Vec3::new(1e-12, 0.0, 1.0)),
        (Ggx::new(tiny, tiny), Vec3::new(0.0, 1e-12, 1.0)),
        // Short normals whose unscaled squared length underflows to 0 (a review's cases).
        (
            Ggx::new(one, one).with_bounded_reflection(false),
            Vec3::new(1e-25, 0.0, 1.0),
        ),
        (Ggx::new(tiny, tiny), Vec3::new(1e-20, 0.0, 1.0)),
    ];
    for (d, w) in cases {
        let view = d.view(w);
        for ux in [0.0, 0.3, 0.75] {
            let u = Vec2::new(ux, 1.0);
            let r = d.sample_reflected(&view, u);
            let want = reflect_away(view.w, d.sample_reflection(&view, u));
            assert!(
                (r - want).length() < 1e-6 && (r.z > 0.0) == (want.z > 0.0),
                "w = {w:?}, u = {u:?}: {r:?} against {want:?}"
            );
        }
    }
}

/// Walter's rational `G1` exceeds 1 by at most 6.2e-5 (measured 6.1e-5, just below `a = 1.6`),
/// as its docs say.
#[test]
fn rational_g1_overshoot_is_bounded() {
    let b =
        Beckmann::isotropic(Alpha::new(0.5).unwrap()).with_masking(BeckmannMasking::WalterRational);
    let mut max = 0.0f32;
    for i in 1..100_000 {
        // a = cot θ / α from 0 to 5.
        let a = i as f32 * 5e-5;
        let cot = a * 0.5;
        let w = Vec3::new(1.0, 0.0, cot).normalize();
        max = max.max(b.g1(w));
    }
    eprintln!("max rational G1 = {max}");
    assert!(max > 1.0 && max <= 1.0 + 6.2e-5, "max G1 = {max}");
}

/// GTR with `γ = 2` is GGX: the same `D`, and the tabulated Smith `G1` agrees with GGX's closed
/// form to the table's interpolation error.
#[test]
fn gtr_with_gamma_two_is_ggx() {
    let mut worst = 0.0f32;
    for alpha in [0.01f32, 0.1, 0.5, 1.0, 2.0] {
        let a = Alpha::new(alpha).unwrap();
        let (gtr, ggx) = (Gtr::new(a, 2.0).unwrap(), Ggx::isotropic(a));
        for i in 0..=200 {
            let theta = i as f32 / 200.0 * (core::f32::consts::FRAC_PI_2 - 1e-4);
            let w = Vec3::new(theta.sin(), 0.0, theta.cos());
            assert!(
                close(gtr.d(w), ggx.d(w), 1e-4),
                "D at θ = {theta}: {} vs {}",
                gtr.d(w),
                ggx.d(w)
            );
            worst = worst.max((gtr.g1(w) - ggx.g1(w)).abs());
        }
    }
    // The table's accuracy, the bound `Gtr`'s docs state (3e-5; tests/microfacet_gtr.rs
    // measures it against f64 references over the whole range).
    eprintln!("GTR(γ=2) vs GGX: max |ΔG1| = {worst:.3e}");
    assert!(worst <= 3e-5, "max |ΔG1| = {worst}");
}

/// Normalised Blinn-Phong and Beckmann of the same `α` (Walter et al. 2007, eq. 32): close for
/// narrow lobes, apart for wide ones. The figure is the L1 distance between their `D cos θ`
/// densities, `∫ |D_bp − D_b| cos θ dω`, by midpoint quadrature in `θ` (both are isotropic).
#[test]
fn blinn_phong_approaches_beckmann_for_narrow_lobes() {
    let mut previous = 0.0;
    for alpha in [0.01f32, 0.05, 0.1, 0.3, 0.5, 1.0] {
        let a = Alpha::new(alpha).unwrap();
        let (bp, b) = (BlinnPhongNdf::new(a).unwrap(), Beckmann::isotropic(a));
        let n = 200_000;
        let mut l1 = 0.0f64;
        for i in 0..n {
            let theta = (i as f64 + 0.5) / n as f64 * std::f64::consts::FRAC_PI_2;
            let m = Vec3::new(theta.sin() as f32, 0.0, theta.cos() as f32);
            let diff = f64::from(bp.d(m)) - f64::from(b.d(m));
            l1 += diff.abs() * theta.cos() * theta.sin();
        }
        l1 *= std::f64::consts::TAU * std::f64::consts::FRAC_PI_2 / n as f64;
        eprintln!("α = {alpha}: ∫ |D_BlinnPhong − D_Beckmann| cos θ dω = {l1:.4}");
        assert!(
            l1 > previous,
            "the distance should grow with α: {l1} after {previous}"
        );
        if alpha <= 0.1 {
            assert!(l1 < 0.02, "α = {alpha}: L1 distance {l1}");
        }
        previous = l1;
    }
}

/// ERRATA #9: Walter's rational G1 approximates the exact Beckmann Smith G1; the bound between
/// them, measured over `a = cot θ / α ∈ (0, 5]`, is held to the figure the docs quote.
#[test]
fn rational_g1_stays_near_the_exact_one() {
    let alpha = Alpha::new(0.5).unwrap();
    let exact = Beckmann::isotropic(alpha);
    let rational = exact.with_masking(BeckmannMasking::WalterRational);
    let (mut worst, mut at) = (0.0f32, 0.0f32);
    for i in 1..=50_000 {
        let a = i as f32 * 1e-4;
        let w = Vec3::new(1.0, 0.0, a * 0.5).normalize();
        let d = (rational.g1(w) - exact.g1(w)).abs();
        if d > worst {
            (worst, at) = (d, a);
        }
    }
    eprintln!("max |G1 rational − G1 exact| = {worst:.2e} at a = {at}");
    assert!(worst < 3.2e-3, "{worst} at a = {at}");
    assert!(worst > 1e-4, "the approximation is not exact: {worst}");
}

/// Walter's rational `G1` masks, but the sampler draws the exact visible normals, so the
/// visible-normal density (the sampler's pdf) keeps the exact `G1`: with the rational one it
/// would integrate to `G1_rational / G1_exact` (up to 1.0031, at `a ≈ 1.34`), not 1.
#[test]
fn rational_masking_keeps_the_exact_visible_density() {
    let alpha = Alpha::new(0.5).unwrap();
    let exact = Beckmann::isotropic(alpha);
    let rational = exact.with_masking(BeckmannMasking::WalterRational);
    let m = Vec3::new(0.3, -0.2, 0.9).normalize();
    let mut masking_differs = 0;
    for i in 1..=400 {
        let a = i as f32 * 0.01;
        let w = Vec3::new(1.0, 0.0, a * 0.5).normalize();
        let (ve, vr) = (exact.view(w), rational.view(w));
        assert_eq!(vr.visible.to_bits(), ve.visible.to_bits(), "a = {a}");
        assert_eq!(
            rational.d_visible(w, m).to_bits(),
            exact.d_visible(w, m).to_bits(),
            "a = {a}"
        );
        // The masking is still the rational one.
        let g1 = 1.0 / (1.0 + vr.lambda);
        assert!(
            (g1 - rational.g1(w)).abs() <= 1e-6,
            "a = {a}: {g1} vs {}",
            rational.g1(w)
        );
        masking_differs += usize::from((rational.g1(w) - exact.g1(w)).abs() > 1e-4);
    }
    assert!(masking_differs > 100, "{masking_differs}");
}

/// A tangent direction whose `z` is `−0` (which [`upper`](lobe::microfacet::upper) keeps) has
/// the same view as `+0`'s: `Λ = +∞`, so that `1 + Λo + Λi` is never `−∞ + ∞`.
#[test]
fn a_tangent_view_with_negative_zero_is_the_positive_zeros() {
    let a = Alpha::new(0.3).unwrap();
    let dists: [(&str, Box<dyn NormalDistribution>); 3] = [
        ("GGX", Box::new(Ggx::isotropic(a))),
        ("Beckmann", Box::new(Beckmann::isotropic(a))),
        (
            "GGX anisotropic",
            Box::new(Ggx::new(a, Alpha::new(0.7).unwrap())),
        ),
    ];
    for (name, dist) in &dists {
        for w in [Vec3::new(1.0, 0.0, -0.0), Vec3::new(0.6, -0.8, -0.0)] {
            let (neg, pos) = (dist.view(w), dist.view(Vec3::new(w.x, w.y, 0.0)));
            assert_eq!(neg.lambda, f32::INFINITY, "{name} {w:?}");
            assert_eq!(pos.lambda, f32::INFINITY, "{name} {w:?}");
            assert_eq!(neg.visible, 0.0, "{name} {w:?}");
        }
    }
}
