//! The fixed inputs the shading benchmarks run on, shared by the crate's benches (`shading.rs`,
//! `combinators.rs`, `conductor.rs`, `materials.rs`, `batched.rs`) and the peer benchmarks
//! (`benches/peers/`): 4,096 viewer and light directions above the surface, 5% of each grazing
//! (within 1° of the horizon), and the random numbers of `sample`.

use lobe::verify::Pcg32;
use lobe::{Vec2, Vec3};

/// How many inputs each benchmark pass runs over.
pub const N: usize = 4096;

/// One set of inputs: `wo[k]`, `wi[k]`, `u[k]`, `uc[k]` go together.
pub struct Inputs {
    /// Viewer directions.
    pub wo: Vec<Vec3>,
    /// Light directions.
    pub wi: Vec<Vec3>,
    /// The sampler's two-dimensional random numbers.
    pub u: Vec<Vec2>,
    /// The lobe-choice random numbers.
    pub uc: Vec<f32>,
}

/// A direction on the upper hemisphere: uniform in solid angle, or (one time in twenty)
/// within 1° of the horizon.
pub fn direction(rng: &mut Pcg32) -> Vec3 {
    let grazing = rng.next_f32() < 0.05;
    let z = if grazing {
        1f32.to_radians().sin() * rng.next_f32()
    } else {
        rng.next_f32()
    };
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = core::f32::consts::TAU * rng.next_f32();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The benchmark inputs, the same on every run (seeded).
pub fn inputs() -> Inputs {
    let mut rng = Pcg32::new(0x10be, 9);
    let wo = (0..N).map(|_| direction(&mut rng)).collect();
    let wi = (0..N).map(|_| direction(&mut rng)).collect();
    let u = (0..N).map(|_| rng.next_vec2()).collect();
    let uc = (0..N).map(|_| rng.next_f32()).collect();
    Inputs { wo, wi, u, uc }
}

/// The inputs with the sides mixed, for the transmissive models: `wi` below the surface for
/// odd `k`, `wo` below for `k mod 4 ≥ 2`.
pub fn two_sided(i: &Inputs) -> Inputs {
    let flip = |w: Vec3, below: bool| if below { Vec3::new(w.x, w.y, -w.z) } else { w };
    Inputs {
        wo: (0..N).map(|k| flip(i.wo[k], k % 4 >= 2)).collect(),
        wi: (0..N).map(|k| flip(i.wi[k], k % 2 == 1)).collect(),
        u: i.u.clone(),
        uc: i.uc.clone(),
    }
}

/// The inputs seen from below for `k mod 4 ≥ 2` (both directions mirrored), for
/// `TwoSided`.
#[allow(dead_code)] // Not every bench that includes this file times a two-sided model.
pub fn mirrored(i: &Inputs) -> Inputs {
    let flip = |w: Vec3, below: bool| if below { Vec3::new(w.x, w.y, -w.z) } else { w };
    Inputs {
        wo: (0..N).map(|k| flip(i.wo[k], k % 4 >= 2)).collect(),
        wi: (0..N).map(|k| flip(i.wi[k], k % 4 >= 2)).collect(),
        u: i.u.clone(),
        uc: i.uc.clone(),
    }
}
