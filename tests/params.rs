//! The parameter types' `const` constructors and conversions agree with `new`.

use approx::assert_relative_eq;
use lobe::{Alpha, ComplexIor, Eta, Ior, ParamError, Roughness, Vec3, Vec4};

/// Values around and outside every range, NaN and the infinities included.
const PROBES: [f32; 14] = [
    f32::NAN,
    f32::NEG_INFINITY,
    -1.0,
    0.0,
    1e-38,
    5e-5,
    1e-4,
    0.5,
    1.0,
    1.5,
    10.0,
    999.0,
    1e3,
    f32::INFINITY,
];

/// `Ok` values are compared by bits (so NaN could never pass), errors field by field.
fn same<T: Copy + PartialEq + core::fmt::Debug>(
    a: Result<T, ParamError>,
    b: Result<T, ParamError>,
) -> bool {
    match (a, b) {
        (Ok(x), Ok(y)) => x == y,
        (Err(x), Err(y)) => {
            x.param() == y.param()
                && x.range() == y.range()
                && x.value().to_bits() == y.value().to_bits()
        }
        _ => false,
    }
}

// Validated parameters as constants: a bad literal here would fail the build.
const ALPHA: Alpha = match Alpha::new(0.2) {
    Ok(a) => a,
    Err(_) => panic!(),
};
const GLASS: Eta = match Eta::new(1.5) {
    Ok(e) => e,
    Err(_) => panic!(),
};
const MONO: ComplexIor = match ComplexIor::new_f32(0.2, 3.0) {
    Ok(c) => c,
    Err(_) => panic!(),
};
const REFUSED: Result<Roughness, ParamError> = Roughness::new(1.5);

#[test]
fn const_values_are_the_run_time_ones() {
    assert_eq!(ALPHA, Alpha::new(0.2).unwrap());
    assert_eq!(GLASS.f0(), Eta::new(1.5).unwrap().f0());
    assert_eq!(MONO, ComplexIor::new(0.2_f32, 3.0).unwrap());
    let e = REFUSED.unwrap_err();
    assert_eq!(
        (e.param(), e.value(), e.range()),
        ("roughness", 1.5, "[0, 1]")
    );
}

#[test]
fn try_from_is_new_and_into_gives_the_number_back() {
    for v in PROBES {
        assert!(same(Alpha::try_from(v), Alpha::new(v)), "alpha {v}");
        assert!(
            same(Roughness::try_from(v), Roughness::new(v)),
            "roughness {v}"
        );
        assert!(same(Eta::try_from(v), Eta::new(v)), "eta {v}");
        assert!(same(Ior::try_from(v), Ior::new(v)), "ior {v}");
        if let Ok(a) = Alpha::new(v) {
            assert_eq!(f32::from(a).to_bits(), v.to_bits());
        }
        if let Ok(e) = Eta::new(v) {
            let back: f32 = e.into();
            assert_eq!(back.to_bits(), v.to_bits());
        }
    }
}

#[test]
fn const_complex_constructors_refuse_what_new_refuses() {
    for a in PROBES {
        for b in PROBES {
            assert!(
                same(ComplexIor::new_f32(a, b), ComplexIor::new(a, b)),
                "({a}, {b})"
            );
            // One odd channel among good ones, in every position, for η and for κ: the
            // same first refusal as the generic constructor (every η before any κ).
            for i in 0..3 {
                let mut eta = Vec3::new(0.2, 0.9, 1.1);
                let mut k = Vec3::new(3.9, 2.4, 2.1);
                eta[i] = a;
                k[(i + 1) % 3] = b;
                assert!(same(ComplexIor::new_vec3(eta, k), ComplexIor::new(eta, k)));
            }
            for i in 0..4 {
                let mut eta = Vec4::splat(0.5);
                let mut k = Vec4::splat(2.0);
                eta[i] = b;
                k[3 - i] = a;
                assert!(same(ComplexIor::new_vec4(eta, k), ComplexIor::new(eta, k)));
            }
        }
    }
}

#[test]
fn f0_is_the_conductor_fresnel_at_normal_incidence() {
    // Within a few f32 roundings of the exact value.
    let tol = 4.0 * f64::from(f32::EPSILON);
    // ((η − 1)² + κ²) / ((η + 1)² + κ²) by hand: η = 0.2, κ = 3: (0.64 + 9) / (1.44 + 9).
    assert_relative_eq!(f64::from(MONO.f0()), 9.64 / 10.44, max_relative = tol);
    // κ = 0 is a dielectric: F0 = ((η − 1)/(η + 1))², 0.04 for η = 1.5.
    let glassy = ComplexIor::new_f32(1.5, 0.0).unwrap();
    assert_relative_eq!(f64::from(glassy.f0()), 0.04, max_relative = tol);
    let rgb = ComplexIor::new_vec3(Vec3::new(1.5, 0.2, 1.0), Vec3::new(0.0, 3.0, 0.0)).unwrap();
    let f0 = rgb.f0();
    assert_relative_eq!(f64::from(f0.x), 0.04, max_relative = tol);
    assert_relative_eq!(f64::from(f0.y), 9.64 / 10.44, max_relative = tol);
    assert_eq!(f0.z, 0.0); // η = 1, κ = 0: no interface at all
}
