//! A reflection model used from both sides of a surface.

use super::{At, BxdfSample, Lobes, Prepare};
use glam::{Vec2, Vec3};

/// Mirrors a direction through the surface's plane: `(x, y, −z)`.
#[inline(always)]
fn mirror(w: Vec3) -> Vec3 {
    Vec3::new(w.x, w.y, -w.z)
}

/// A one-sided reflection model `B` made two-sided: from above it is `B`; from below, the
/// mirror image of `B` through the surface's plane,
///
/// ```text
/// f(wo, wi) = f_B(wo, wi)                    wo.z ≥ 0
/// f(wo, wi) = f_B(mirror(wo), mirror(wi))    wo.z < 0,   mirror(x, y, z) = (x, y, −z)
/// ```
///
/// Mitsuba 3's `twosided` (with one model on both faces; it flips `z` the same way). The
/// sampler, the density and the lobes are `B`'s, mirrored. Light never crosses: `f = 0` when
/// `wo` and `wi` are on opposite sides, as it is for `B`.
///
/// Batched ([`Batch`](crate::batch::Batch)): through `B`'s own batched calls on the directions
/// seen from above, a chunk of lanes at a time, so `B` implements `Batch`.
///
/// Laws (measured by `tests/bxdf_mix.rs`): `B`'s on each side — the value from below is
/// exactly `B`'s mirror image, so positivity, reciprocity, the energy bound and the sampler
/// carry over; `check_bxdf` passes with viewer directions on both sides.
///
/// ```
/// use lobe::bxdf::{Bxdf, Lambert, TwoSided};
/// use lobe::Vec3;
/// let leaf = TwoSided::new(Lambert::new(0.5_f32)?);
/// let (wo, wi) = (Vec3::new(0.0, 0.6, -0.8), Vec3::new(0.6, 0.0, -0.8));
/// assert_eq!(leaf.eval(wo, wi), 0.5 / core::f32::consts::PI);
/// # Ok::<(), lobe::ParamError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoSided<B> {
    inner: B,
}

impl<B: Prepare> TwoSided<B> {
    /// `inner` on both sides.
    ///
    /// Precondition: `inner` only reflects (its [`lobes`](Prepare::lobes) have no
    /// [`Lobes::TRANSMISSION`]). A transmitting model, such as a dielectric, would be mirrored
    /// as if its inside were its outside (its relative index not inverted from below): use it
    /// as it is, since it already answers from both sides. Not checked (`new` is `const`).
    #[must_use]
    pub const fn new(inner: B) -> Self {
        Self { inner }
    }

    /// The one-sided model.
    #[must_use]
    pub fn inner(&self) -> &B {
        &self.inner
    }
}

impl<B: Prepare> Prepare for TwoSided<B> {
    type Spectrum = B::Spectrum;
    /// Whether `wo` is below (and the frame mirrored), and the model's prepared state for
    /// `wo` as seen from above.
    type Prepared = At<(B::Prepared, bool)>;

    #[inline(always)]
    fn prepare(&self, wo: Vec3) -> Self::Prepared {
        let below = wo.z < 0.0;
        let up = if below { mirror(wo) } else { wo };
        At {
            wo,
            state: (self.inner.prepare(up), below),
        }
    }

    #[inline(always)]
    fn eval_prepared(&self, at: &Self::Prepared, wi: Vec3) -> B::Spectrum {
        let (p, below) = &at.state;
        self.inner
            .eval_prepared(p, if *below { mirror(wi) } else { wi })
    }

    #[inline(always)]
    fn pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        let (p, below) = &at.state;
        self.inner
            .pdf_prepared(p, if *below { mirror(wi) } else { wi })
    }

    #[inline(always)]
    fn eval_pdf_prepared(&self, at: &Self::Prepared, wi: Vec3) -> (B::Spectrum, f32) {
        let (p, below) = &at.state;
        self.inner
            .eval_pdf_prepared(p, if *below { mirror(wi) } else { wi })
    }

    #[inline(always)]
    fn sample_prepared(
        &self,
        at: &Self::Prepared,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<B::Spectrum>> {
        let (p, below) = &at.state;
        let s = self.inner.sample_prepared(p, u, uc)?;
        Some(if *below {
            BxdfSample {
                wi: mirror(s.wi),
                ..s
            }
        } else {
            s
        })
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        self.inner.lobes()
    }

    #[inline]
    fn stochastic(&self) -> bool {
        self.inner.stochastic()
    }

    #[inline]
    fn eval_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> B::Spectrum {
        let (p, below) = &at.state;
        self.inner
            .eval_seeded_prepared(p, if *below { mirror(wi) } else { wi }, seed)
    }

    #[inline]
    fn pdf_seeded_prepared(&self, at: &Self::Prepared, wi: Vec3, seed: u64) -> f32 {
        let (p, below) = &at.state;
        self.inner
            .pdf_seeded_prepared(p, if *below { mirror(wi) } else { wi }, seed)
    }
}
