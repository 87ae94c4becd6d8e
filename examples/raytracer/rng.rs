//! Seeded random numbers: one independent generator per pixel, so that a render is the
//! same for a given seed whatever the threads do.

use lobe::verify::Pcg32;

/// SplitMix64's finaliser (Steele et al. 2014): a bijective hash of 64 bits.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The generator of pixel `index` for the render seed `seed`: state and stream both hashed,
/// so that neighbouring pixels get unrelated sequences.
pub fn pixel_rng(seed: u64, index: u64) -> Pcg32 {
    let h = mix(seed ^ mix(index));
    Pcg32::new(h, mix(h ^ index))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproducible_and_distinct() {
        assert_eq!(pixel_rng(7, 3).next_u32(), pixel_rng(7, 3).next_u32());
        assert_ne!(pixel_rng(7, 3).next_u32(), pixel_rng(7, 4).next_u32());
        assert_ne!(pixel_rng(7, 3).next_u32(), pixel_rng(8, 3).next_u32());
    }
}
