//! The widths `(αx, αy)` of an anisotropic distribution, with the reciprocals its hot path
//! multiplies by.

use crate::param::Alpha;
use core::f32::consts::FRAC_1_PI;

/// `(αx, αy)`, with `1/αx`, `1/αy` and `1/(π αx αy)` computed once at construction so that a
/// distribution's `D` takes one division ([`Ggx`](super::Ggx), [`Beckmann`](super::Beckmann)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Widths {
    pub(crate) ax: f32,
    pub(crate) ay: f32,
    pub(crate) inv_ax: f32,
    pub(crate) inv_ay: f32,
    /// `1 / (π αx αy)`.
    pub(crate) norm: f32,
}

impl Widths {
    /// The widths `ax` along local `x` and `ay` along `y`.
    #[inline]
    pub(crate) fn new(ax: Alpha, ay: Alpha) -> Self {
        let (ax, ay) = (ax.get(), ay.get());
        Self {
            ax,
            ay,
            inv_ax: 1.0 / ax,
            inv_ay: 1.0 / ay,
            norm: FRAC_1_PI / (ax * ay),
        }
    }
}
