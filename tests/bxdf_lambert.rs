//! Lambert through the law suite, and its closed-form albedo.

mod common;

use common::laws::{Model, assert_all_laws};
use lobe::bxdf::{Bxdf, Lambert};
use lobe::{Vec2, Vec3};

#[test]
fn lambert_obeys_every_law() {
    for rho in [0.0f32, 0.5, 1.0] {
        assert_all_laws(
            &Model::new(format!("Lambert ρ={rho}"), Lambert::new(rho).unwrap()),
            3,
        );
    }
}

#[test]
fn lambert_value_and_weight() {
    let l = Lambert::new(Vec3::new(0.2, 0.5, 0.9)).unwrap();
    let (wo, wi) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.6, 0.0, 0.8));
    assert!((l.eval(wo, wi) - Vec3::new(0.2, 0.5, 0.9) / core::f32::consts::PI).length() < 1e-7);
    assert_eq!(l.eval(wo, -wi), Vec3::ZERO);
    let s = l.sample(wo, Vec2::new(0.25, 0.75), 0.0).unwrap();
    assert!((s.weight() - Vec3::new(0.2, 0.5, 0.9)).length() < 1e-6);
    assert!(Lambert::new(1.5f32).is_err() && Lambert::new(f32::NAN).is_err());
}
