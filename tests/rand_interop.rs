//! `verify::Pcg32` through `rand_core`'s traits: it feeds `rand`, and its sequence is still
//! the one `src/verify/stats/rng.rs` pins.
//!
//! The expected outputs are the pinned values of the generator's own tests (computed there
//! with an independent Python transcription of O'Neill's algorithm; the first also matches
//! the reference C implementation's demo for `pcg32_srandom_r(42, 54)`).

use lobe::verify::{Estimate, Pcg32};
use rand::distr::{Distribution, Uniform};
use rand::{Rng, RngCore, SeedableRng};

/// The first outputs of `Pcg32::new(42, 54)`.
const PINNED_42_54: [u32; 6] = [
    0xa15c_02b7,
    0x7b47_f409,
    0xba1d_3330,
    0x83d2_f293,
    0xbfa4_784b,
    0xcbed_606e,
];

/// `from_seed`'s layout: the seed's little-endian bytes, then the stream's.
fn seed(seed: u64, stream: u64) -> [u8; 16] {
    let mut s = [0; 16];
    s[..8].copy_from_slice(&seed.to_le_bytes());
    s[8..].copy_from_slice(&stream.to_le_bytes());
    s
}

#[test]
fn rng_core_gives_the_pinned_sequence() {
    let mut rng = Pcg32::from_seed(seed(42, 54));
    assert_eq!(rng, Pcg32::new(42, 54));
    for want in PINNED_42_54 {
        assert_eq!(RngCore::next_u32(&mut rng), want);
    }
    // The second pinned sequence, with a stream above 2³²: every byte of the seed counts.
    let mut rng = Pcg32::from_seed(seed(0x853c_49e6_748f_ea9b, 0xda3e_39cb_94b9_5bdb));
    for want in [0x1bbe_b4f2_u32, 0xe82e_89e9, 0x681c_fdeb, 0xe00f_a2ec] {
        assert_eq!(RngCore::next_u32(&mut rng), want);
    }
}

#[test]
fn next_u64_and_fill_bytes_are_little_endian_words() {
    let [a, b, c, d, ..] = PINNED_42_54.map(u64::from);
    let mut rng = Pcg32::new(42, 54);
    assert_eq!(rng.next_u64(), (b << 32) | a);
    assert_eq!(rng.next_u64(), (d << 32) | c);

    let mut rng = Pcg32::new(42, 54);
    let mut bytes = [0_u8; 10];
    rng.fill_bytes(&mut bytes);
    let mut want = Vec::new();
    for w in [a, b, c] {
        want.extend_from_slice(&(w as u32).to_le_bytes());
    }
    assert_eq!(bytes[..], want[..10]);
    // The 10 bytes took three words: 8 bytes from one u64 (two words), 2 bytes from the
    // third, the rest of which is dropped. The next output is the fourth word.
    assert_eq!(RngCore::next_u32(&mut rng), d as u32);
}

#[test]
fn rand_floats_are_the_generators_floats() {
    // rand's `StandardUniform` f32 keeps the top 24 bits of `next_u32`, as `next_f32` does:
    // the same values, so a check written with `rng.random()` replays `next_f32` exactly.
    let mut a = Pcg32::new(7, 0);
    let mut b = Pcg32::new(7, 0);
    for _ in 0..1000 {
        assert_eq!(a.random::<f32>(), b.next_f32());
    }
    // Its f64 takes 53 bits of `next_u64` (low word first); `next_f64` puts the first word
    // high. Both are exact functions of the pinned words.
    let [w0, w1, ..] = PINNED_42_54.map(u64::from);
    let mut rng = Pcg32::new(42, 54);
    let want = ((w1 << 32) | w0) >> 11;
    assert_eq!(rng.random::<f64>(), want as f64 / 9_007_199_254_740_992.0);
    let mut rng = Pcg32::new(42, 54);
    let want = ((w0 << 32) | w1) >> 11;
    assert_eq!(rng.next_f64(), want as f64 / 9_007_199_254_740_992.0);
}

#[test]
fn rand_distributions_sample_from_it() {
    // rand_distr-style use: a distribution object sampled with the crate's generator. The
    // mean of U(2, 5) is 3.5 and its standard deviation 3/√12; 10⁵ samples must agree within
    // five standard errors.
    let mut rng = Pcg32::seed_from_u64(2024);
    let uniform = Uniform::new(2.0_f64, 5.0).unwrap();
    let e = Estimate::from_samples((0..100_000).map(|_| uniform.sample(&mut rng)));
    assert!(e.within(3.5, 5.0), "{e}");
    // The standard error is itself estimated: for a uniform distribution (kurtosis 9/5) its
    // relative standard error is √((9/5 − 1)/(4n)) (the delta method); within five of them.
    let want = 3.0 / 12_f64.sqrt() / 100_000_f64.sqrt();
    let rel_err = (0.8 / (4.0 * 100_000.0_f64)).sqrt();
    assert!((e.std_err - want).abs() <= 5.0 * rel_err * want, "{e}");
    // Integer ranges and Bernoulli trials, through the `Rng` extension methods.
    let rolls: Vec<u8> = (0..6000).map(|_| rng.random_range(1..=6)).collect();
    assert!(rolls.iter().all(|r| (1..=6).contains(r)));
    for face in 1..=6 {
        // Expected 1000 per face, σ = √(6000 · 1/6 · 5/6) ≈ 28.9.
        let n = rolls.iter().filter(|&&r| r == face).count() as f64;
        assert!((n - 1000.0).abs() < 5.0 * 28.9, "face {face}: {n}");
    }
    let heads = (0..10_000).filter(|_| rng.random_bool(0.25)).count() as f64;
    assert!((heads - 2500.0).abs() < 5.0 * 43.3, "{heads}"); // σ = √(10⁴ · 0.25 · 0.75)
}

#[test]
fn seed_from_u64_is_deterministic_and_spreads_seeds() {
    let a: Vec<u32> = {
        let mut r = Pcg32::seed_from_u64(1);
        (0..4).map(|_| RngCore::next_u32(&mut r)).collect()
    };
    let b: Vec<u32> = {
        let mut r = Pcg32::seed_from_u64(1);
        (0..4).map(|_| RngCore::next_u32(&mut r)).collect()
    };
    let c: Vec<u32> = {
        let mut r = Pcg32::seed_from_u64(2);
        (0..4).map(|_| RngCore::next_u32(&mut r)).collect()
    };
    assert_eq!(a, b);
    assert_ne!(a, c);
}
