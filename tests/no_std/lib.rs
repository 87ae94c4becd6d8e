//! Calls lobe's public API from a `#![no_std]` staticlib (see Cargo.toml for why).
#![no_std]

use lobe::{ComplexIor, Eta, Frame, Vec2, Vec3, fresnel, sampling};

/// Refracts a world-space direction through a glass surface and returns its local `z`.
#[unsafe(no_mangle)]
pub extern "C" fn lobe_no_std_refract_z(nx: f32, ny: f32, nz: f32) -> f32 {
    let frame = Frame::from_normal(Vec3::new(nx, ny, nz).normalize());
    let w = frame.to_local(Vec3::new(0.3, 0.4, 0.866).normalize());
    let Ok(eta) = Eta::new(1.5) else { return -1.0 };
    lobe::frame::refract_away(w, Vec3::Z, eta).map_or(0.0, |t| t.z) + lobe::math::erf(0.5)
}

/// Fresnel reflectance of glass and of a conductor at a cosine-sampled direction.
#[unsafe(no_mangle)]
pub extern "C" fn lobe_no_std_fresnel(u0: f32, u1: f32) -> f32 {
    let w = sampling::cosine_hemisphere(Vec2::new(u0, u1));
    let Ok(eta) = Eta::new(1.5) else { return -1.0 };
    let Ok(metal) = ComplexIor::new(Vec3::new(0.2, 0.4, 1.4), Vec3::new(3.9, 2.4, 1.6)) else {
        return -1.0;
    };
    let f: Vec3 = fresnel::conductor(w.z, &metal);
    fresnel::dielectric(w.z, eta)
        + fresnel::schlick(0.04, w.z)
        + f.x
        + sampling::cosine_hemisphere_pdf(w.z)
}

// Under `cargo test` the test harness links std, which brings its own panic handler.
#[cfg(not(test))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// What runs here is lobe built without `std`: the harness links std into the test binary,
/// but lobe's `std` feature stays off (this crate asks for `libm` alone and has no
/// dev-dependencies to turn it on). Run by .ci/run: `cargo test --manifest-path
/// tests/no_std/Cargo.toml`.
#[cfg(test)]
mod tests {
    use lobe::Vec3;
    use lobe::batch::{Batch, InstructionSet, instruction_set};
    use lobe::bxdf::{Bxdf, Lambert};

    /// Without std there is no safe check that the OS has enabled AVX (std's reads XCR0;
    /// pulp's without std reads CPUID alone), so on x86 the batched calls run the baseline
    /// loop, and say so.
    #[test]
    fn the_batched_calls_run_the_baseline_without_std() {
        let isa = instruction_set();
        if cfg!(any(target_arch = "x86", target_arch = "x86_64")) {
            assert_eq!(isa, InstructionSet::Baseline);
        } else {
            assert_eq!(isa, InstructionSet::Target);
        }
        // And a batched call runs there, with the scalar call's value.
        let m = Lambert::new(0.5_f32).unwrap();
        let (x, y, z) = ([0.0, 0.6], [0.6, 0.0], [0.8, 0.8]);
        let wo = lobe::batch::Vec3s {
            x: &x,
            y: &y,
            z: &z,
        };
        let mut f = [0.0; 2];
        m.eval_batch(wo, wo, &mut f).unwrap();
        let one = m.eval(Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.6, 0.0, 0.8));
        assert_eq!(f[1].to_bits(), one.to_bits());
    }
}
