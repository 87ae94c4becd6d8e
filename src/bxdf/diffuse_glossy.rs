//! What the Phong-family models share: a diffuse lobe `k_d/π` plus a glossy `cos^p` lobe,
//! their parameter checks, the choice of lobe and the lobe flags.

use super::Lobes;
use crate::param::ParamError;
use crate::spectrum::Spectrum;
use core::f32::consts::FRAC_1_PI;

/// The weights `kd`, `ks` and the exponent of a Phong-family model, validated, with the
/// probability of sampling its diffuse lobe: `(kd, ks, p, p_diffuse)`.
pub(super) fn checked_parameters<S: Spectrum>(
    kd: S,
    ks: S,
    exponent: f32,
) -> Result<(S, S, f32, f32), ParamError> {
    let kd = crate::param::unit_interval("kd", kd)?;
    let ks = crate::param::unit_interval("ks", ks)?;
    check_sum(kd, ks, "kd + ks")?;
    let p = check_exponent(exponent)?;
    Ok((kd, ks, p, diffuse_probability(kd, ks)))
}

/// Refuses a channel where the two weights sum above 1; the error names `param`.
fn check_sum<S: Spectrum>(kd: S, ks: S, param: &'static str) -> Result<(), ParamError> {
    let sum = kd + ks;
    for i in 0..S::CHANNELS {
        let s = sum.channel(i);
        if !(s <= 1.0) {
            return Err(ParamError::new(param, s, "[0, 1]"));
        }
    }
    Ok(())
}

/// Accepts an exponent in `[0, 1e6]`, refusing NaN.
fn check_exponent(p: f32) -> Result<f32, ParamError> {
    if (0.0..=1e6).contains(&p) {
        Ok(p)
    } else {
        Err(ParamError::new("exponent", p, "[0, 1000000]"))
    }
}

/// The probability of sampling the diffuse lobe: the diffuse share of the channel-averaged
/// weights, `1` when both are black.
fn diffuse_probability<S: Spectrum>(kd: S, ks: S) -> f32 {
    let (d, s) = (kd.average(), ks.average());
    if d + s > 0.0 { d / (d + s) } else { 1.0 }
}

/// The lobes with a non-zero weight (diffuse alone for a black model: what its sampler
/// reports).
pub(crate) fn weighted_lobes<S: Spectrum>(kd: S, ks: S) -> Lobes {
    let mut lobes = Lobes::NONE;
    if !kd.is_black() || ks.is_black() {
        lobes |= Lobes::DIFFUSE_REFLECTION;
    }
    if !ks.is_black() {
        lobes |= Lobes::GLOSSY_REFLECTION;
    }
    lobes
}

/// `(p + 1)/(2π)`: the normalisation of `cos^p θ` over the hemisphere.
#[inline]
pub(super) fn cos_power_norm(p: f32) -> f32 {
    (p + 1.0) * 0.5 * FRAC_1_PI
}
