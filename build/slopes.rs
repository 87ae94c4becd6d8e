// The Beckmann visible-slope quantile in `f64`, shared by the build script (which tabulates
// it for the sampler in `src/microfacet/beckmann.rs`) and by that sampler's unit tests (which
// hold the `f32` sampler to it). Plain `std` only: the build script cannot depend on the crate.
//
// The visible slope `x̃` of the Beckmann distribution stretched to `α = 1`, for a view at
// polar angle `θ`, has the unnormalised CDF
// `C(x) = cos θ · erfc(−x)/2 + sin θ · e^(−x²)/(2√π)` on `x < cot θ` (Heitz & d'Eon 2014,
// supplemental).

/// The sampler's bracket: slopes below −6 carry less than 3e-16 of the mass.
pub const LIMIT: f64 = 6.0;

/// `erfc(x)` to about 1e-14: the Maclaurin series of `erf` for `|x| < 2.5`, Lentz's continued
/// fraction of `erfc` beyond (Abramowitz & Stegun 7.1.5 and 7.1.14).
pub fn erfc64(x: f64) -> f64 {
    if x.abs() < 2.5 {
        let (mut term, mut sum, x2) = (x, x, x * x);
        for n in 1..200 {
            term *= -x2 / n as f64;
            let t = term / (2 * n + 1) as f64;
            sum += t;
            if t.abs() < 1e-17 * sum.abs() {
                break;
            }
        }
        1.0 - 2.0 / std::f64::consts::PI.sqrt() * sum
    } else if x < 0.0 {
        2.0 - erfc64(-x)
    } else {
        // erfc x = e^(−x²)/√π · 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + …)))).
        let tiny = 1e-300;
        let (mut f, mut c, mut d) = (x, x, 0.0);
        for n in 1..500 {
            let a = n as f64 / 2.0;
            d = x + a * d;
            d = if d.abs() < tiny { tiny } else { d };
            c = x + a / c;
            c = if c.abs() < tiny { tiny } else { c };
            d = 1.0 / d;
            let delta = c * d;
            f *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        (-x * x).exp() / std::f64::consts::PI.sqrt() / f
    }
}

/// The unnormalised CDF `C(x)` for a view with cosine `cos` and sine `sin`.
pub fn slope_cdf64(cos: f64, sin: f64, x: f64) -> f64 {
    0.5 * (cos * erfc64(-x) + sin * (-x * x).exp() / std::f64::consts::PI.sqrt())
}

/// The upper end of the slopes, `min(cot θ, LIMIT)`.
pub fn slope_end64(cos: f64, sin: f64) -> f64 {
    if sin > 0.0 {
        (cos / sin).min(LIMIT)
    } else {
        LIMIT
    }
}

/// The quantile `x̃` at `u ∈ [0, 1]`, by bisection to the last bit.
pub fn slope_quantile64(cos: f64, sin: f64, u: f64) -> f64 {
    let hi0 = slope_end64(cos, sin);
    let target = u * slope_cdf64(cos, sin, hi0);
    let (mut lo, mut hi) = (-LIMIT, hi0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        if slope_cdf64(cos, sin, mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
