//! `approx`'s traits on the crate's value types (feature `approx`): `BxdfSample` and
//! `verify::Estimate` compare field by field, and only when every field is close.

use approx::{
    AbsDiffEq, RelativeEq, abs_diff_eq, abs_diff_ne, assert_abs_diff_eq, assert_relative_eq,
    assert_relative_ne, relative_eq,
};
use lobe::bxdf::{Bxdf, BxdfSample, Lobes, Microfacet};
use lobe::fresnel::Conductor;
use lobe::microfacet::{Ggx, Masking};
use lobe::verify::{Accumulator, Estimate};
use lobe::{Alpha, Vec2, Vec3, metals};

fn sample() -> BxdfSample<Vec3> {
    BxdfSample {
        wi: Vec3::new(0.6, 0.0, 0.8),
        f: Vec3::new(0.9, 0.7, 0.3),
        pdf: 2.5,
        lobe: Lobes::GLOSSY_REFLECTION,
        eta: 1.0,
    }
}

#[test]
fn identical_samples_are_equal_at_zero_tolerance() {
    let s = sample();
    assert!(s.abs_diff_eq(&s, 0.0));
    assert!(s.relative_eq(&s, 0.0, 0.0));
    assert_relative_eq!(s, s);
}

#[test]
fn every_field_takes_part() {
    let s = sample();
    let variants = [
        BxdfSample {
            wi: Vec3::new(0.601, 0.0, 0.8),
            ..s
        },
        BxdfSample {
            f: Vec3::new(0.9, 0.7, 0.301),
            ..s
        },
        BxdfSample { pdf: 2.501, ..s },
        BxdfSample { eta: 1.001, ..s },
    ];
    for v in variants {
        // A difference of 1e-3 (relative ~4e-4 or more): within 1e-2, not within 1e-4.
        assert_abs_diff_eq!(s, v, epsilon = 1e-2);
        assert!(abs_diff_ne!(s, v, epsilon = 1e-4), "{v:?}");
        assert!(relative_eq!(s, v, epsilon = 0.0, max_relative = 1e-2));
        assert_relative_ne!(s, v, epsilon = 0.0, max_relative = 1e-4);
    }
    // A component that is zero in one sample: a relative tolerance alone never accepts a
    // difference from zero, approx's absolute floor `epsilon` does.
    let tilted = BxdfSample {
        wi: Vec3::new(0.6, 1e-3, 0.8),
        ..s
    };
    assert!(!relative_eq!(s, tilted, epsilon = 0.0, max_relative = 1e-2));
    assert!(relative_eq!(s, tilted, epsilon = 1e-2, max_relative = 1e-4));
    // The lobe is compared exactly: no tolerance makes glossy equal to specular.
    let other_lobe = BxdfSample {
        lobe: Lobes::SPECULAR_REFLECTION,
        ..s
    };
    assert!(!abs_diff_eq!(s, other_lobe, epsilon = 1e9));
    assert!(!relative_eq!(
        s,
        other_lobe,
        epsilon = 1e9,
        max_relative = 1e9
    ));
}

#[test]
fn nan_is_never_close() {
    let s = sample();
    let nan = BxdfSample { pdf: f32::NAN, ..s };
    assert!(!abs_diff_eq!(nan, nan, epsilon = f32::INFINITY));
    assert!(!relative_eq!(
        s,
        nan,
        epsilon = f32::INFINITY,
        max_relative = 1.0
    ));
}

#[test]
fn scalar_and_rgb_samples_of_one_model_agree() {
    // The same conductor on the f32 and the RGB carrier, channel 0 of RGB being the f32 one:
    // the samples differ only in the carrier, so the RGB sample's red channel and every
    // other field equal the monochrome sample's.
    let gold = metals::GOLD.rgb();
    let red = lobe::ComplexIor::new(gold.eta().x, gold.k().x).unwrap();
    let ggx = Ggx::isotropic(Alpha::new(0.3).unwrap());
    let rgb = Microfacet::new(ggx, Masking::HeightCorrelated, Conductor { ior: gold });
    let mono = Microfacet::new(ggx, Masking::HeightCorrelated, Conductor { ior: red });
    let wo = Vec3::new(0.3, -0.2, 0.93).normalize();
    for (u, uc) in [(Vec2::new(0.1, 0.2), 0.3), (Vec2::new(0.7, 0.9), 0.5)] {
        let (a, b) = (
            rgb.sample(wo, u, uc).unwrap(),
            mono.sample(wo, u, uc).unwrap(),
        );
        let red_of_a = BxdfSample {
            wi: a.wi,
            f: a.f.x,
            pdf: a.pdf,
            lobe: a.lobe,
            eta: a.eta,
        };
        assert_relative_eq!(red_of_a, b, max_relative = 1e-6);
        // The green channel is another metal's value: not the red one.
        let green_of_a = BxdfSample {
            f: a.f.y,
            ..red_of_a
        };
        assert_relative_ne!(green_of_a, b, max_relative = 1e-2);
    }
}

#[test]
fn merged_estimates_equal_the_single_pass_one() {
    let xs: Vec<f64> = (0..10_000)
        .map(|i| (f64::from(i) * 0.37).sin().abs())
        .collect();
    let whole = Estimate::from_samples(xs.iter().copied());
    let mut parts = Accumulator::new();
    for chunk in xs.chunks(777) {
        parts.merge(&chunk.iter().copied().collect());
    }
    let merged = parts.finish();
    // Welford and Chan et al. round differently: equal to ~1e-13, not bit for bit.
    assert_relative_eq!(merged, whole, max_relative = 1e-12);
    assert!(merged.relative_eq(&whole, 0.0, 1e-12));
    assert_abs_diff_eq!(merged, whole, epsilon = 1e-12);
    // One sample fewer is a different estimate, however close the numbers.
    let fewer = Estimate::from_samples(xs[1..].iter().copied());
    assert!(!merged.abs_diff_eq(&fewer, 1.0));
    assert!(!merged.relative_eq(&fewer, 1.0, 1.0));
    // A shifted mean or a different spread is caught too.
    let shifted = Estimate {
        mean: whole.mean + 1e-6,
        ..whole
    };
    let wider = Estimate {
        std_err: whole.std_err * (1.0 + 1e-6),
        ..whole
    };
    assert!(!abs_diff_eq!(shifted, whole, epsilon = 1e-9));
    assert!(!relative_eq!(wider, whole, max_relative = 1e-9));
    // An estimate of one sample has a NaN error: it is close to nothing, itself included.
    let one = Estimate::from_samples([1.0]);
    assert!(!abs_diff_eq!(one, one, epsilon = f64::INFINITY));
}
