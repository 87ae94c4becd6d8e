//! GGX with one realistic bug, shared by the fault corpus (`tests/faults.rs`) and the
//! microfacet law checks' own tests (`tests/microfacet_faults.rs`).

use lobe::microfacet::{Ggx, NormalDistribution, Sampling, View};
use lobe::{Alpha, Vec2, Vec3};

/// The distribution bugs, each a one-line slip away from GGX.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum NdfBug {
    /// No bug: GGX itself.
    None,
    /// `D` without its `1/π`.
    DMissingPi,
    /// `D` 10% too large.
    DTenPercent,
    /// `G1 = 1/(1/Λ)` (that is `Λ`) instead of `1/(1 + Λ)`.
    G1IsLambda,
    /// The visible-normal density without `G1`: `max(0, w·m) D(m) / cos θw`.
    VisibleWithoutG1,
    /// The sampler draws visible normals but declares the old `D(m) cos θm`, so `pdf` is that.
    VisibleSamplerDcosPdf,
}

/// GGX with one bug. As in a real implementation, the derived quantities are built from the
/// (possibly broken) parts: the view's visible-normal factor from `g1`, the sampler's `pdf`
/// from the view and `d`, so a bug propagates wherever the code would carry it.
pub struct BuggyNdf {
    pub ggx: Ggx,
    pub bug: NdfBug,
}

impl BuggyNdf {
    /// Isotropic GGX of width `alpha` with `bug`.
    pub fn new(alpha: f32, bug: NdfBug) -> Self {
        Self {
            ggx: Ggx::isotropic(Alpha::new(alpha).unwrap()),
            bug,
        }
    }
}

impl NormalDistribution for BuggyNdf {
    /// The sampler always draws GGX's visible normals; one bug declares `D cos θ`.
    fn sampling(&self) -> Sampling {
        if self.bug == NdfBug::VisibleSamplerDcosPdf {
            Sampling::DCos
        } else {
            Sampling::VisibleNormals
        }
    }
    fn d(&self, m: Vec3) -> f32 {
        let d = self.ggx.d(m);
        match self.bug {
            NdfBug::DMissingPi => d * core::f32::consts::PI,
            NdfBug::DTenPercent => d * 1.1,
            _ => d,
        }
    }
    fn lambda(&self, w: Vec3) -> f32 {
        self.ggx.lambda(w)
    }
    fn g1(&self, w: Vec3) -> f32 {
        if self.bug == NdfBug::G1IsLambda {
            1.0 / (1.0 / self.lambda(w))
        } else {
            1.0 / (1.0 + self.lambda(w))
        }
    }
    /// GGX's view (its sampler's state) with Λ, G1 and the visible-normal factor built from
    /// the possibly broken parts.
    fn view(&self, w: Vec3) -> View {
        let mut view = self.ggx.view(w);
        view.lambda = self.lambda(view.w);
        let g1 = if self.bug == NdfBug::VisibleWithoutG1 {
            1.0
        } else {
            self.g1(view.w)
        };
        view.visible = if view.w.z > 0.0 { g1 / view.w.z } else { 0.0 };
        view
    }
    fn sample(&self, view: &View, u: Vec2) -> Vec3 {
        self.ggx.sample(view, u)
    }
}
