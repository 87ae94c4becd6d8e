//! Calls lobe's public API from a `#![no_std]` staticlib (see Cargo.toml for why).
#![no_std]

use lobe::{Eta, Frame, Vec3};

/// Refracts a world-space direction through a glass surface and returns its local `z`.
#[unsafe(no_mangle)]
pub extern "C" fn lobe_no_std_refract_z(nx: f32, ny: f32, nz: f32) -> f32 {
    let frame = Frame::from_normal(Vec3::new(nx, ny, nz).normalize());
    let w = frame.to_local(Vec3::new(0.3, 0.4, 0.866).normalize());
    let Ok(eta) = Eta::new(1.5) else { return -1.0 };
    lobe::frame::refract(w, Vec3::Z, eta).map_or(0.0, |t| t.z) + lobe::math::erf(0.5)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}
