//! Measured complex indices of refraction of common metals, by name.
//!
//! Each [`Metal`] holds published optical constants `η + iκ` at the wavelengths its source
//! measured them, over the visible range (380–780 nm, with the nearest data point beyond
//! each end so that the whole range interpolates). From them it gives:
//!
//! * [`Metal::rgb`]: a [`ComplexIor<Vec3>`] for an RGB renderer, `const`;
//! * [`Metal::spectral`]: a [`ComplexIor<Vec4>`] at four wavelengths of a spectral renderer's
//!   choosing (the `Vec4` carrier), `const` too;
//! * [`Metal::at`]: the index at one wavelength.
//!
//! ```
//! use lobe::bxdf::{Bxdf, Microfacet};
//! use lobe::fresnel::Conductor;
//! use lobe::metals::{self, Metal};
//! use lobe::microfacet::{Ggx, Masking};
//! use lobe::{Alpha, ComplexIor, Vec3, Vec4};
//!
//! // RGB: pick the metal by name (a scene file) or by constant (code).
//! let gold = Metal::from_name("gold").expect("a known metal");
//! assert_eq!(gold, metals::GOLD);
//! let brdf = Microfacet::new(
//!     Ggx::isotropic(Alpha::new(0.2)?),
//!     Masking::HeightCorrelated,
//!     Conductor { ior: gold.rgb() },
//! );
//! let f: Vec3 = brdf.eval(Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.0, -0.6, 0.8));
//! assert!(f.x > f.z); // gold reflects more red than blue
//!
//! // Spectral: the four wavelengths (nm) a path carries.
//! let ior: ComplexIor<Vec4> = metals::COPPER.spectral(Vec4::new(420.0, 510.0, 600.0, 690.0));
//! let f0 = ior.f0();
//! assert!(f0.w > f0.x); // copper: red above violet
//!
//! // Both are `const`.
//! const SILVER: ComplexIor<Vec3> = metals::SILVER.rgb();
//! assert!(SILVER.f0().min_element() > 0.95);
//! # use lobe::Spectrum as _;
//! # Ok::<(), lobe::ParamError>(())
//! ```
//!
//! # How the RGB triple is derived
//!
//! `η` and `κ` are each interpolated linearly in wavelength between the two tabulated points
//! around **650 nm (R), 550 nm (G) and 450 nm (B)** ([`RGB_WAVELENGTHS`]), and the three
//! results make the channels. The triple is therefore the metal *point-sampled* at three
//! wavelengths, not a projection of its spectrum onto the sRGB primaries: each channel's
//! normal-incidence reflectance `((η − 1)² + κ²) / ((η + 1)² + κ²)` is the measured metal's
//! at that wavelength. Metals whose reflectance varies little across the visible range
//! (silver, aluminium, chromium, iron, tungsten) come out nearly grey either way; for gold,
//! copper and brass, and to a lesser degree nickel, titanium and platinum, a spectral
//! renderer ([`Metal::spectral`]) is the faithful path.
//!
//! # Sources
//!
//! The numbers are the published tables, as the [refractiveindex.info] database transcribes
//! them (CC0); the interpolation and everything else here is this crate's.
//!
//! | metal | source | data points used |
//! | --- | --- | --- |
//! | gold (Au), silver (Ag), copper (Cu) | P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", *Phys. Rev. B* **6**, 4370 (1972) | the 16 measured points from 367.9 to 821.1 nm |
//! | chromium (Cr), iron (Fe), nickel (Ni), titanium (Ti) | P. B. Johnson and R. W. Christy, "Optical constants of transition metals: Ti, V, Cr, Mn, Fe, Co, Ni, and Pd", *Phys. Rev. B* **9**, 5056 (1974) | the 16 measured points from 368 to 821 nm |
//! | aluminium (Al) | A. D. Rakić, "Algorithm for the determination of intrinsic optical constants of metal films: application to aluminum", *Appl. Opt.* **34**, 4755 (1995) | the 12 tabulated points from 364.7 to 794.8 nm |
//! | platinum (Pt), tungsten (W) | A. D. Rakić, A. B. Djurišić, J. M. Elazar and M. L. Majewski, "Optical properties of metallic films for vertical-cavity optoelectronic devices", *Appl. Opt.* **37**, 5271 (1998): their Lorentz–Drude fit to measured data | the model's values at the 21 wavelengths nearest to every 20 nm from 380 to 780 nm |
//! | brass (CuZn, 70% Cu, 30% Zn) | M. R. Querry, "Optical constants", Contractor Report CRDC-CR-85034 (1985) | the 41 measured points from 380 to 780 nm (every 10 nm) |
//!
//! Optical constants of real metals depend on how the sample was made (film or bulk,
//! polish, oxide, temperature); different measurements of the same metal differ by a few
//! percent in reflectance. These are room-temperature values of clean samples.
//!
//! [refractiveindex.info]: https://refractiveindex.info

use crate::param::ComplexIor;
use glam::{Vec3, Vec4};

/// One measured point of a metal's complex index: the vacuum wavelength and `η + iκ` there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IorSample {
    /// The wavelength in vacuum, in nanometres.
    pub lambda: f32,
    /// The real part of the index, `η`.
    pub eta: f32,
    /// The extinction coefficient, `κ`.
    pub k: f32,
}

/// The wavelengths, in nanometres, at which [`Metal::rgb`] samples a metal for its red,
/// green and blue channels.
pub const RGB_WAVELENGTHS: [f32; 3] = [650.0, 550.0, 450.0];

/// A metal's measured complex index of refraction over the visible range, with where the
/// numbers come from.
///
/// The presets are constants of this module ([`GOLD`], [`SILVER`], …, [`ALL`]); see the
/// [module docs](self) for the sources and how the RGB triple is derived.
///
/// With the `serde` feature a metal serialises as its name and deserialises from a name or
/// symbol ([`Metal::from_name`]), so a scene file can say `"gold"`:
///
/// ```
/// # #[cfg(feature = "serde")] {
/// use lobe::metals::{self, Metal};
/// let m: Vec<Metal> = serde_json::from_str(r#"["gold", "Cu", "aluminum"]"#)?;
/// assert_eq!(m, [metals::GOLD, metals::COPPER, metals::ALUMINIUM]);
/// assert_eq!(serde_json::to_string(&metals::BRASS)?, r#""brass""#);
/// let err = serde_json::from_str::<Metal>(r#""mithril""#).unwrap_err().to_string();
/// assert!(err.starts_with("unknown variant `mithril`, expected one of `gold`, `silver`"));
/// # }
/// # Ok::<(), serde_json::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Metal {
    name: &'static str,
    symbol: &'static str,
    source: &'static str,
    samples: &'static [IorSample],
}

impl Metal {
    /// The metal's English name, lower case (`"gold"`, `"aluminium"`).
    #[inline]
    #[must_use]
    pub const fn name(&self) -> &'static str {
        self.name
    }

    /// Its chemical symbol (`"Au"`; `"CuZn"` for brass).
    #[inline]
    #[must_use]
    pub const fn symbol(&self) -> &'static str {
        self.symbol
    }

    /// The publication the data points come from, as a short citation.
    #[inline]
    #[must_use]
    pub const fn source(&self) -> &'static str {
        self.source
    }

    /// The data points, in increasing wavelength.
    #[inline]
    #[must_use]
    pub const fn samples(&self) -> &'static [IorSample] {
        self.samples
    }

    /// The complex index at wavelength `lambda` (nm): `η` and `κ` interpolated linearly
    /// between the two data points around it.
    ///
    /// Outside the tabulated range the nearest end's value is returned (NaN gives the first
    /// point's), so the result is always a valid index.
    #[inline]
    #[must_use]
    pub const fn at(&self, lambda: f32) -> ComplexIor<f32> {
        let (eta, k) = interpolate(self.samples, lambda);
        ComplexIor::from_valid_parts(eta, k)
    }

    /// The RGB complex index: the metal at 650, 550 and 450 nm ([`RGB_WAVELENGTHS`]) for the
    /// red, green and blue channels (see the [module docs](self)).
    #[inline]
    #[must_use]
    pub const fn rgb(&self) -> ComplexIor<Vec3> {
        let [r, g, b] = RGB_WAVELENGTHS;
        let (r, g, b) = (
            interpolate(self.samples, r),
            interpolate(self.samples, g),
            interpolate(self.samples, b),
        );
        ComplexIor::from_valid_parts(Vec3::new(r.0, g.0, b.0), Vec3::new(r.1, g.1, b.1))
    }

    /// The complex index at the four wavelengths `lambdas` (nm) of a spectral path, each as
    /// [`at`](Self::at) gives it.
    #[inline]
    #[must_use]
    pub const fn spectral(&self, lambdas: Vec4) -> ComplexIor<Vec4> {
        let l = lambdas.to_array();
        let mut eta = [0.0; 4];
        let mut k = [0.0; 4];
        let mut i = 0;
        while i < 4 {
            (eta[i], k[i]) = interpolate(self.samples, l[i]);
            i += 1;
        }
        ComplexIor::from_valid_parts(Vec4::from_array(eta), Vec4::from_array(k))
    }

    /// The preset called `name`: its [name](Self::name) or [symbol](Self::symbol), in any
    /// case (`"gold"`, `"Au"`, `"AU"`), or the American `"aluminum"`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        let name = name.trim();
        if name.eq_ignore_ascii_case("aluminum") {
            return Some(ALUMINIUM);
        }
        ALL.into_iter()
            .find(|m| name.eq_ignore_ascii_case(m.name) || name.eq_ignore_ascii_case(m.symbol))
    }
}

/// `η` and `κ` at `lambda`, linear between the data points around it, clamped to the ends;
/// NaN gives the first point. `samples` is non-empty and increasing in wavelength.
#[inline]
const fn interpolate(samples: &[IorSample], lambda: f32) -> (f32, f32) {
    let first = samples[0];
    if !(lambda > first.lambda) {
        return (first.eta, first.k);
    }
    let last = samples[samples.len() - 1];
    if lambda >= last.lambda {
        return (last.eta, last.k);
    }
    // first.lambda < lambda < last.lambda: the loop stops at the first point at or beyond.
    let mut i = 1;
    while samples[i].lambda < lambda {
        i += 1;
    }
    let (a, b) = (samples[i - 1], samples[i]);
    let t = (lambda - a.lambda) / (b.lambda - a.lambda);
    (a.eta + t * (b.eta - a.eta), a.k + t * (b.k - a.k))
}

/// A data point; wavelengths in the sources' micrometres are written here in nanometres.
const fn s(lambda: f32, eta: f32, k: f32) -> IorSample {
    IorSample { lambda, eta, k }
}

/// Johnson & Christy 1972.
const JC72: &str = "Johnson & Christy, Phys. Rev. B 6, 4370 (1972)";
/// Johnson & Christy 1974.
const JC74: &str = "Johnson & Christy, Phys. Rev. B 9, 5056 (1974)";
/// Rakić 1995 (aluminium).
const RAKIC95: &str = "Rakić, Appl. Opt. 34, 4755 (1995)";
/// Rakić et al. 1998 (Lorentz–Drude fits).
const RAKIC98: &str = "Rakić et al., Appl. Opt. 37, 5271 (1998), Lorentz-Drude model";
/// Querry 1985 (brass).
const QUERRY85: &str = "Querry, CRDC-CR-85034 (1985), Cu 70% Zn 30%";

/// Gold, Johnson & Christy 1972.
pub const GOLD: Metal = Metal {
    name: "gold",
    symbol: "Au",
    source: JC72,
    samples: &[
        s(367.9, 1.48, 1.895),
        s(381.5, 1.46, 1.933),
        s(397.4, 1.47, 1.952),
        s(413.3, 1.46, 1.958),
        s(430.5, 1.45, 1.948),
        s(450.9, 1.38, 1.914),
        s(471.4, 1.31, 1.849),
        s(495.9, 1.04, 1.833),
        s(520.9, 0.62, 2.081),
        s(548.6, 0.43, 2.455),
        s(582.1, 0.29, 2.863),
        s(616.8, 0.21, 3.272),
        s(659.5, 0.14, 3.697),
        s(704.5, 0.13, 4.103),
        s(756.0, 0.14, 4.542),
        s(821.1, 0.16, 5.083),
    ],
};

/// Silver, Johnson & Christy 1972.
pub const SILVER: Metal = Metal {
    name: "silver",
    symbol: "Ag",
    source: JC72,
    samples: &[
        s(367.9, 0.07, 1.657),
        s(381.5, 0.05, 1.864),
        s(397.4, 0.05, 2.070),
        s(413.3, 0.05, 2.275),
        s(430.5, 0.04, 2.462),
        s(450.9, 0.04, 2.657),
        s(471.4, 0.05, 2.869),
        s(495.9, 0.05, 3.093),
        s(520.9, 0.05, 3.324),
        s(548.6, 0.06, 3.586),
        s(582.1, 0.05, 3.858),
        s(616.8, 0.06, 4.152),
        s(659.5, 0.05, 4.483),
        s(704.5, 0.04, 4.838),
        s(756.0, 0.03, 5.242),
        s(821.1, 0.04, 5.727),
    ],
};

/// Copper, Johnson & Christy 1972.
pub const COPPER: Metal = Metal {
    name: "copper",
    symbol: "Cu",
    source: JC72,
    samples: &[
        s(367.9, 1.36, 1.975),
        s(381.5, 1.33, 2.045),
        s(397.4, 1.32, 2.116),
        s(413.3, 1.28, 2.207),
        s(430.5, 1.25, 2.305),
        s(450.9, 1.24, 2.397),
        s(471.4, 1.25, 2.483),
        s(495.9, 1.22, 2.564),
        s(520.9, 1.18, 2.608),
        s(548.6, 1.02, 2.577),
        s(582.1, 0.70, 2.704),
        s(616.8, 0.30, 3.205),
        s(659.5, 0.22, 3.747),
        s(704.5, 0.21, 4.205),
        s(756.0, 0.24, 4.665),
        s(821.1, 0.26, 5.180),
    ],
};

/// Aluminium, Rakić 1995.
pub const ALUMINIUM: Metal = Metal {
    name: "aluminium",
    symbol: "Al",
    source: RAKIC95,
    samples: &[
        s(364.66, 0.39877, 4.3957),
        s(413.28, 0.52135, 5.0008),
        s(442.80, 0.60790, 5.3676),
        s(476.87, 0.72780, 5.7781),
        s(516.60, 0.87340, 6.2418),
        s(563.57, 1.0728, 6.7839),
        s(619.93, 1.3660, 7.4052),
        s(652.25, 1.5724, 7.7354),
        s(688.81, 1.8301, 8.0601),
        s(729.32, 2.1606, 8.3565),
        s(774.91, 2.6154, 8.4914),
        s(794.78, 2.7675, 8.3866),
    ],
};

/// Chromium, Johnson & Christy 1974.
#[allow(
    clippy::approx_constant,
    reason = "measured data: κ = 3.14 at 451 nm is not π"
)]
pub const CHROMIUM: Metal = Metal {
    name: "chromium",
    symbol: "Cr",
    source: JC74,
    samples: &[
        s(368.0, 1.87, 2.69),
        s(381.0, 1.92, 2.74),
        s(397.0, 2.00, 2.83),
        s(413.0, 2.08, 2.93),
        s(431.0, 2.19, 3.04),
        s(451.0, 2.33, 3.14),
        s(471.0, 2.51, 3.24),
        s(496.0, 2.75, 3.30),
        s(521.0, 2.94, 3.33),
        s(549.0, 3.18, 3.33),
        s(582.0, 3.22, 3.30),
        s(617.0, 3.17, 3.30),
        s(659.0, 3.09, 3.34),
        s(704.0, 3.05, 3.39),
        s(756.0, 3.08, 3.42),
        s(821.0, 3.20, 3.48),
    ],
};

/// Iron, Johnson & Christy 1974.
pub const IRON: Metal = Metal {
    name: "iron",
    symbol: "Fe",
    source: JC74,
    samples: &[
        s(368.0, 2.02, 2.43),
        s(381.0, 2.12, 2.50),
        s(397.0, 2.24, 2.58),
        s(413.0, 2.35, 2.65),
        s(431.0, 2.48, 2.71),
        s(451.0, 2.59, 2.77),
        s(471.0, 2.67, 2.82),
        s(496.0, 2.74, 2.88),
        s(521.0, 2.86, 2.91),
        s(549.0, 2.95, 2.93),
        s(582.0, 2.94, 2.99),
        s(617.0, 2.88, 3.05),
        s(659.0, 2.92, 3.10),
        s(704.0, 2.86, 3.19),
        s(756.0, 2.87, 3.28),
        s(821.0, 2.94, 3.39),
    ],
};

/// Nickel, Johnson & Christy 1974.
pub const NICKEL: Metal = Metal {
    name: "nickel",
    symbol: "Ni",
    source: JC74,
    samples: &[
        s(368.0, 1.70, 2.40),
        s(381.0, 1.72, 2.48),
        s(397.0, 1.72, 2.57),
        s(413.0, 1.70, 2.69),
        s(431.0, 1.71, 2.82),
        s(451.0, 1.73, 2.95),
        s(471.0, 1.78, 3.09),
        s(496.0, 1.82, 3.25),
        s(521.0, 1.85, 3.42),
        s(549.0, 1.92, 3.61),
        s(582.0, 1.96, 3.80),
        s(617.0, 1.99, 4.02),
        s(659.0, 1.99, 4.26),
        s(704.0, 2.06, 4.50),
        s(756.0, 2.13, 4.73),
        s(821.0, 2.26, 4.97),
    ],
};

/// Titanium, Johnson & Christy 1974.
pub const TITANIUM: Metal = Metal {
    name: "titanium",
    symbol: "Ti",
    source: JC74,
    samples: &[
        s(368.0, 1.90, 2.90),
        s(381.0, 1.99, 2.93),
        s(397.0, 2.08, 2.95),
        s(413.0, 2.14, 2.98),
        s(431.0, 2.21, 3.01),
        s(451.0, 2.27, 3.04),
        s(471.0, 2.32, 3.10),
        s(496.0, 2.36, 3.19),
        s(521.0, 2.44, 3.30),
        s(549.0, 2.54, 3.43),
        s(582.0, 2.60, 3.58),
        s(617.0, 2.67, 3.72),
        s(659.0, 2.76, 3.84),
        s(704.0, 2.86, 3.96),
        s(756.0, 3.00, 4.01),
        s(821.0, 3.21, 4.01),
    ],
};

/// Platinum, Rakić et al. 1998 (Lorentz–Drude model).
pub const PLATINUM: Metal = Metal {
    name: "platinum",
    symbol: "Pt",
    source: RAKIC98,
    samples: &[
        s(379.99, 1.6698, 2.7309),
        s(399.83, 1.7237, 2.8515),
        s(420.71, 1.7784, 2.9734),
        s(439.23, 1.8249, 3.0790),
        s(460.36, 1.8760, 3.1981),
        s(480.63, 1.9238, 3.3120),
        s(499.82, 1.9690, 3.4201),
        s(519.78, 2.0164, 3.5328),
        s(540.54, 2.0671, 3.6502),
        s(559.93, 2.1161, 3.7597),
        s(580.02, 2.1690, 3.8725),
        s(600.82, 2.2261, 3.9881),
        s(619.95, 2.2806, 4.0928),
        s(639.67, 2.3388, 4.1989),
        s(660.03, 2.4007, 4.3061),
        s(681.03, 2.4661, 4.4139),
        s(699.96, 2.5263, 4.5083),
        s(719.41, 2.5889, 4.6028),
        s(739.41, 2.6538, 4.6970),
        s(759.96, 2.7207, 4.7909),
        s(781.08, 2.7893, 4.8844),
    ],
};

/// Tungsten, Rakić et al. 1998 (Lorentz–Drude model).
pub const TUNGSTEN: Metal = Metal {
    name: "tungsten",
    symbol: "W",
    source: RAKIC98,
    samples: &[
        s(379.99, 3.2635, 2.5309),
        s(399.83, 3.3153, 2.5200),
        s(420.71, 3.3487, 2.5138),
        s(439.23, 3.3645, 2.5180),
        s(460.36, 3.3732, 2.5376),
        s(480.63, 3.3793, 2.5716),
        s(499.82, 3.3887, 2.6158),
        s(519.78, 3.4069, 2.6701),
        s(540.54, 3.4377, 2.7301),
        s(559.93, 3.4779, 2.7834),
        s(580.02, 3.5291, 2.8302),
        s(600.82, 3.5880, 2.8652),
        s(619.95, 3.6424, 2.8831),
        s(639.67, 3.6935, 2.8874),
        s(660.03, 3.7359, 2.8786),
        s(681.03, 3.7646, 2.8594),
        s(699.96, 3.7755, 2.8371),
        s(719.41, 3.7713, 2.8133),
        s(739.41, 3.7511, 2.7916),
        s(759.96, 3.7153, 2.7757),
        s(781.08, 3.6648, 2.7691),
    ],
};

/// Brass (70% copper, 30% zinc), Querry 1985.
pub const BRASS: Metal = Metal {
    name: "brass",
    symbol: "CuZn",
    source: QUERRY85,
    samples: &[
        s(380.0, 1.487, 1.818),
        s(390.0, 1.471, 1.813),
        s(400.0, 1.445, 1.805),
        s(410.0, 1.405, 1.794),
        s(420.0, 1.350, 1.786),
        s(430.0, 1.278, 1.784),
        s(440.0, 1.191, 1.797),
        s(450.0, 1.094, 1.829),
        s(460.0, 0.994, 1.883),
        s(470.0, 0.900, 1.957),
        s(480.0, 0.816, 2.046),
        s(490.0, 0.745, 2.145),
        s(500.0, 0.686, 2.250),
        s(510.0, 0.639, 2.358),
        s(520.0, 0.602, 2.464),
        s(530.0, 0.573, 2.568),
        s(540.0, 0.549, 2.668),
        s(550.0, 0.527, 2.765),
        s(560.0, 0.505, 2.860),
        s(570.0, 0.484, 2.958),
        s(580.0, 0.468, 3.059),
        s(590.0, 0.460, 3.159),
        s(600.0, 0.450, 3.253),
        s(610.0, 0.452, 3.345),
        s(620.0, 0.449, 3.434),
        s(630.0, 0.445, 3.522),
        s(640.0, 0.444, 3.609),
        s(650.0, 0.444, 3.695),
        s(660.0, 0.445, 3.778),
        s(670.0, 0.444, 3.860),
        s(680.0, 0.444, 3.943),
        s(690.0, 0.445, 4.025),
        s(700.0, 0.446, 4.106),
        s(710.0, 0.448, 4.186),
        s(720.0, 0.450, 4.266),
        s(730.0, 0.452, 4.346),
        s(740.0, 0.455, 4.424),
        s(750.0, 0.457, 4.501),
        s(760.0, 0.458, 4.579),
        s(770.0, 0.460, 4.657),
        s(780.0, 0.464, 4.737),
    ],
};

/// Every preset, in the order of the [module docs](self)' table.
pub const ALL: [Metal; 11] = [
    GOLD, SILVER, COPPER, CHROMIUM, IRON, NICKEL, TITANIUM, ALUMINIUM, PLATINUM, TUNGSTEN, BRASS,
];

/// The presets' names, in the order of [`ALL`].
pub const NAMES: [&str; 11] = [
    "gold",
    "silver",
    "copper",
    "chromium",
    "iron",
    "nickel",
    "titanium",
    "aluminium",
    "platinum",
    "tungsten",
    "brass",
];

// A metal serialises as its name, and deserialises from a name or symbol.
#[cfg(feature = "serde")]
mod serde_impls {
    use super::{Metal, NAMES};
    use core::fmt;
    use serde::de::{self, Deserializer, Visitor};
    use serde::{Deserialize, Serialize, Serializer};

    impl Serialize for Metal {
        fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
            serializer.serialize_str(self.name)
        }
    }

    /// Reads a metal's name.
    struct MetalName;

    impl Visitor<'_> for MetalName {
        type Value = Metal;

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("the name or chemical symbol of a metal")
        }

        fn visit_str<E: de::Error>(self, v: &str) -> Result<Metal, E> {
            Metal::from_name(v).ok_or_else(|| E::unknown_variant(v, &NAMES))
        }
    }

    impl<'de> Deserialize<'de> for Metal {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            deserializer.deserialize_str(MetalName)
        }
    }
}
