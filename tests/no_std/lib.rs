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
    fresnel::dielectric(w.z, eta) + fresnel::schlick(0.04, w.z) + f.x
        + sampling::cosine_hemisphere_pdf(w.z)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}
