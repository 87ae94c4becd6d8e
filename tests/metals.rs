//! The named metals: their RGB and spectral indices against the published data points.
//!
//! The expected values below were computed by hand (a few lines of Python, kept out of the
//! crate) from the two data points of each cited table that bracket 650, 550 and 450 nm,
//! interpolated linearly in wavelength — the rule the module documents — and never from
//! this crate's code. `F0 = ((η − 1)² + κ²) / ((η + 1)² + κ²)`.

use approx::{assert_abs_diff_eq, assert_relative_eq};
use lobe::metals::{self, Metal};
use lobe::{ComplexIor, Spectrum, Vec3, Vec4, fresnel};

/// Each preset with its expected normal-incidence reflectance (R at 650 nm, G at 550 nm, B
/// at 450 nm) and the bracketing data points it was computed from, as (λ nm, η, κ).
const EXPECTED_F0: [(&str, [f64; 3]); 11] = [
    // Johnson & Christy 1972: 616.8 (0.21, 3.272) – 659.5 (0.14, 3.697); 548.6 (0.43, 2.455)
    // – 582.1 (0.29, 2.863); 430.5 (1.45, 1.948) – 450.9 (1.38, 1.914).
    ("gold", [0.956_522, 0.791_553, 0.408_194]),
    // 616.8 (0.06, 4.152) – 659.5 (0.05, 4.483); 548.6 (0.06, 3.586) – 582.1 (0.05, 3.858);
    // 430.5 (0.04, 2.462) – 450.9 (0.04, 2.657).
    ("silver", [0.989_834, 0.983_054, 0.980_236]),
    // 616.8 (0.30, 3.205) – 659.5 (0.22, 3.747); 548.6 (1.02, 2.577) – 582.1 (0.70, 2.704);
    // 430.5 (1.25, 2.305) – 450.9 (1.24, 2.397).
    ("copper", [0.935_218, 0.623_510, 0.538_258]),
    // Johnson & Christy 1974: 617 (3.17, 3.30) – 659 (3.09, 3.34); 549 (3.18, 3.33) – 582
    // (3.22, 3.30); 431 (2.19, 3.04) – 451 (2.33, 3.14).
    ("chromium", [0.555_599, 0.554_536, 0.554_779]),
    // 617 (2.88, 3.05) – 659 (2.92, 3.10); 549 (2.95, 2.93) – 582 (2.94, 2.99); 431 (2.48,
    // 2.71) – 451 (2.59, 2.77).
    ("iron", [0.531_227, 0.512_359, 0.495_829]),
    // 617 (1.99, 4.02) – 659 (1.99, 4.26); 549 (1.92, 3.61) – 582 (1.96, 3.80); 431 (1.71,
    // 2.82) – 451 (1.73, 2.95).
    ("nickel", [0.701_338, 0.644_338, 0.570_745]),
    // 617 (2.67, 3.72) – 659 (2.76, 3.84); 549 (2.54, 3.43) – 582 (2.60, 3.58); 431 (2.21,
    // 3.01) – 451 (2.27, 3.04).
    ("titanium", [0.615_901, 0.582_291, 0.544_454]),
    // Rakić 1995: 619.93 (1.3660, 7.4052) – 652.25 (1.5724, 7.7354); 516.60 (0.87340,
    // 6.2418) – 563.57 (1.0728, 6.7839); 442.80 (0.60790, 5.3676) – 476.87 (0.72780, 5.7781).
    ("aluminium", [0.905_609, 0.915_369, 0.921_864]),
    // Rakić et al. 1998 (LD): 639.67 (2.3388, 4.1989) – 660.03 (2.4007, 4.3061); 540.54
    // (2.0671, 3.6502) – 559.93 (2.1161, 3.7597); 439.23 (1.8249, 3.0790) – 460.36 (1.8760,
    // 3.1981).
    ("platinum", [0.678_057, 0.640_584, 0.588_350]),
    // 639.67 (3.6935, 2.8874) – 660.03 (3.7359, 2.8786); 540.54 (3.4377, 2.7301) – 559.93
    // (3.4779, 2.7834); 439.23 (3.3645, 2.5180) – 460.36 (3.3732, 2.5376).
    ("tungsten", [0.513_466, 0.496_454, 0.471_090]),
    // Querry 1985 (Cu70Zn30), data points at exactly 650 (0.444, 3.695), 550 (0.527, 2.765)
    // and 450 nm (1.094, 1.829).
    ("brass", [0.887_153, 0.788_713, 0.433_900]),
];

/// The expected F0 are rounded to 6 decimals; f32 round-off in η, κ and the quotient is
/// below 1e-6 for these magnitudes.
const F0_TOLERANCE: f64 = 2e-6;

fn metal(name: &str) -> Metal {
    Metal::from_name(name).unwrap_or_else(|| panic!("no preset called {name}"))
}

#[test]
fn rgb_normal_incidence_reflectance_matches_the_data() {
    for (name, want) in EXPECTED_F0 {
        let ior = metal(name).rgb();
        let exact: Vec3 = fresnel::conductor(1.0, &ior);
        let f0 = ior.f0();
        for (c, want) in want.into_iter().enumerate() {
            assert_abs_diff_eq!(f64::from(exact[c]), want, epsilon = F0_TOLERANCE);
            assert_abs_diff_eq!(f64::from(f0[c]), want, epsilon = F0_TOLERANCE);
        }
    }
}

#[test]
fn rgb_indices_are_the_data_interpolated_at_650_550_450() {
    // Gold: (η, κ) interpolated by hand from the same bracketing points as above.
    let gold = metals::GOLD.rgb();
    let eta: [f32; 3] = [0.155_574, 0.424_149, 1.383_088];
    let k: [f32; 3] = [3.602_445, 2.472_051, 1.915_5];
    for c in 0..3 {
        assert_abs_diff_eq!(gold.eta()[c], eta[c], epsilon = 2e-6);
        assert_abs_diff_eq!(gold.k()[c], k[c], epsilon = 2e-6);
    }
    // Brass has data points at exactly these wavelengths: the triple is the data itself.
    let brass = metals::BRASS.rgb();
    assert_eq!(brass.eta(), Vec3::new(0.444, 0.527, 1.094));
    assert_eq!(brass.k(), Vec3::new(3.695, 2.765, 1.829));
    assert_eq!(metals::RGB_WAVELENGTHS, [650.0, 550.0, 450.0]);
}

#[test]
fn spectral_path_agrees_with_the_data_and_with_rgb() {
    // At 700 nm: gold between 659.5 (0.14, 3.697) and 704.5 (0.13, 4.103) → (0.131, 4.0624),
    // F0 = 0.970532; brass has a data point at 700 nm (0.446, 4.106), F0 = 0.905858.
    let l = Vec4::new(650.0, 550.0, 450.0, 700.0);
    let gold: ComplexIor<Vec4> = metals::GOLD.spectral(l);
    assert_relative_eq!(gold.eta().w, 0.131, max_relative = 1e-5);
    assert_relative_eq!(gold.k().w, 4.0624, max_relative = 1e-5);
    assert_abs_diff_eq!(f64::from(gold.f0().w), 0.970_532, epsilon = F0_TOLERANCE);
    let brass = metals::BRASS.spectral(l);
    assert_eq!((brass.eta().w, brass.k().w), (0.446, 4.106));
    assert_abs_diff_eq!(f64::from(brass.f0().w), 0.905_858, epsilon = F0_TOLERANCE);
    // The spectral path at the RGB wavelengths is the RGB triple, exactly.
    for m in metals::ALL {
        let (s, rgb) = (m.spectral(l), m.rgb());
        assert_eq!(s.eta().truncate(), rgb.eta(), "{}", m.name());
        assert_eq!(s.k().truncate(), rgb.k(), "{}", m.name());
        assert_eq!(m.at(650.0).eta(), rgb.eta().x, "{}", m.name());
    }
}

#[test]
fn interpolation_hits_every_data_point_and_clamps_outside() {
    for m in metals::ALL {
        let samples = m.samples();
        for p in samples {
            let at = m.at(p.lambda);
            assert_eq!(
                (at.eta(), at.k()),
                (p.eta, p.k),
                "{} at {}",
                m.name(),
                p.lambda
            );
        }
        // Halfway between two points: the mean of the two.
        for w in samples.windows(2) {
            let mid = m.at(0.5 * (w[0].lambda + w[1].lambda));
            assert_relative_eq!(mid.eta(), 0.5 * (w[0].eta + w[1].eta), max_relative = 1e-5);
            assert_relative_eq!(mid.k(), 0.5 * (w[0].k + w[1].k), max_relative = 1e-5);
        }
        let (first, last) = (samples[0], samples[samples.len() - 1]);
        for (lambda, p) in [
            (100.0, first),
            (f32::NEG_INFINITY, first),
            (f32::NAN, first),
            (2000.0, last),
            (f32::INFINITY, last),
        ] {
            let at = m.at(lambda);
            assert_eq!((at.eta(), at.k()), (p.eta, p.k), "{} at {lambda}", m.name());
        }
    }
}

#[test]
fn tables_are_valid_increasing_and_cover_the_visible_range() {
    assert_eq!(metals::ALL.len(), metals::NAMES.len());
    for (m, name) in metals::ALL.into_iter().zip(metals::NAMES) {
        assert_eq!(m.name(), name);
        let samples = m.samples();
        assert!(
            samples[0].lambda <= 380.0,
            "{name} starts at {}",
            samples[0].lambda
        );
        assert!(samples[samples.len() - 1].lambda >= 780.0, "{name}");
        assert!(
            samples.windows(2).all(|w| w[0].lambda < w[1].lambda),
            "{name}"
        );
        for p in samples {
            assert!(
                ComplexIor::new_f32(p.eta, p.k).is_ok(),
                "{name} at {}",
                p.lambda
            );
        }
        assert!(!m.source().is_empty());
    }
}

#[test]
fn colours_are_what_the_metals_look_like() {
    let f0 = |name: &str| metal(name).rgb().f0();
    // The coloured metals: red above green above blue, and clearly so.
    for name in ["gold", "copper", "brass"] {
        let c = f0(name);
        assert!(c.x > c.y && c.y > c.z, "{name}: {c}");
        assert!(c.x - c.z > 0.3, "{name}: {c}");
    }
    // Gold is yellower than copper (more green), copper redder than gold.
    assert!(f0("gold").y > f0("copper").y);
    // The white and grey metals: channels close to each other.
    for (name, spread) in [
        ("silver", 0.02),
        ("aluminium", 0.02),
        ("chromium", 0.01),
        ("iron", 0.05),
        ("tungsten", 0.05),
    ] {
        let c = f0(name);
        assert!(c.max_element() - c.min_element() < spread, "{name}: {c}");
    }
    // Silver and aluminium are the bright ones, the transition metals darker.
    assert!(f0("silver").min_element() > 0.97);
    assert!(f0("aluminium").min_element() > 0.9);
    for name in [
        "chromium", "iron", "nickel", "titanium", "platinum", "tungsten",
    ] {
        let c = f0(name);
        assert!(
            c.max_channel() < 0.75 && c.min_channel() > 0.45,
            "{name}: {c}"
        );
    }
}

#[test]
fn names_and_symbols_find_the_presets() {
    assert_eq!(Metal::from_name("gold"), Some(metals::GOLD));
    assert_eq!(Metal::from_name("Au"), Some(metals::GOLD));
    assert_eq!(Metal::from_name(" SILVER "), Some(metals::SILVER));
    assert_eq!(Metal::from_name("aluminum"), Some(metals::ALUMINIUM));
    assert_eq!(Metal::from_name("al"), Some(metals::ALUMINIUM));
    assert_eq!(Metal::from_name("CuZn"), Some(metals::BRASS));
    assert_eq!(Metal::from_name("w"), Some(metals::TUNGSTEN));
    assert_eq!(Metal::from_name("mithril"), None);
    assert_eq!(Metal::from_name(""), None);
    for m in metals::ALL {
        assert_eq!(Metal::from_name(m.name()), Some(m));
        assert_eq!(Metal::from_name(m.symbol()), Some(m));
    }
}

// The presets and their RGB triples are usable in constants.
const GOLD_RGB: ComplexIor<Vec3> = metals::GOLD.rgb();
const COPPER_AT_600: ComplexIor<f32> = metals::COPPER.at(600.0);

#[test]
fn presets_are_const() {
    assert_eq!(GOLD_RGB, metals::GOLD.rgb());
    // Copper between 582.1 (0.70, 2.704) and 616.8 (0.30, 3.205).
    let t = (600.0 - 582.1) / (616.8 - 582.1);
    assert_relative_eq!(
        COPPER_AT_600.eta(),
        0.70 + t * (0.30 - 0.70),
        max_relative = 1e-5
    );
    assert_relative_eq!(
        COPPER_AT_600.k(),
        2.704 + t * (3.205 - 2.704),
        max_relative = 1e-5
    );
}
