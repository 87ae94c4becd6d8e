//! Which instruction set the batched loops run on this CPU.

use core::fmt;

/// The instruction set the batched calls run on, as the run-time dispatch chooses it
/// ([`instruction_set`]).
///
/// Every path gives the same numbers, bit for bit (the scalar path's); only the speed
/// differs. `tests/batch.rs` checks the machine's own, and CI, where QEMU's user mode can be
/// installed, AVX2, the baseline and aarch64's under an emulated CPU (AVX-512 only on a
/// machine that has it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum InstructionSet {
    /// AVX-512 (x86-64-v4).
    Avx512,
    /// AVX2 with FMA (x86-64-v3).
    Avx2,
    /// The x86 target's own features (SSE2 on the default `x86_64` target): a CPU without
    /// AVX2, or any x86 CPU in a build without the `std` feature.
    Baseline,
    /// A target other than x86: the loops are compiled for the target's own features.
    Target,
}

impl InstructionSet {
    /// A short name: `"AVX-512"`, `"AVX2"`, `"baseline"` or `"target"`.
    #[inline]
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Avx512 => "AVX-512",
            Self::Avx2 => "AVX2",
            Self::Baseline => "baseline",
            Self::Target => "target",
        }
    }
}

impl fmt::Display for InstructionSet {
    #[inline]
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The instruction set the batched calls run on this CPU: the widest of AVX-512, AVX2 with
/// FMA and the baseline that the CPU has and the operating system has enabled, on x86 with
/// the `std` feature; [`InstructionSet::Baseline`] on x86 without `std`;
/// [`InstructionSet::Target`] elsewhere.
///
/// The same check the batched calls act on, for a renderer's log or a benchmark's label.
///
/// Without `std` there is no safe way to ask whether the operating system saves the AVX
/// registers (std's `is_x86_feature_detected!` reads XCR0 for that; pulp without std reads
/// CPUID alone, which reports what the CPU has even where the OS, a kernel or UEFI
/// application, has not enabled it, and an AVX instruction there faults). So a `no_std`
/// build on x86 runs the loops compiled for the target's own features: SSE2 on the default
/// `x86_64` target, AVX2 if the build itself enables it (`-C target-cpu`, `-C
/// target-feature`).
///
/// ```
/// use lobe::batch::{InstructionSet, instruction_set};
///
/// let isa = instruction_set();
/// println!("lobe's batched path: {isa}");
/// if cfg!(target_arch = "x86_64") {
///     assert_ne!(isa, InstructionSet::Target);
/// }
/// ```
#[inline]
#[must_use]
pub fn instruction_set() -> InstructionSet {
    #[cfg(all(feature = "std", any(target_arch = "x86", target_arch = "x86_64")))]
    {
        match pulp::Arch::new() {
            pulp::Arch::V4(_) => InstructionSet::Avx512,
            pulp::Arch::V3(_) => InstructionSet::Avx2,
            pulp::Arch::Scalar => InstructionSet::Baseline,
            // `Arch` is non-exhaustive; pulp 0.22 has no other x86 level (a new one would need
            // a variant here, and `tests/batch.rs` would catch the mismatch on such a CPU).
            _ => InstructionSet::Baseline,
        }
    }
    #[cfg(all(not(feature = "std"), any(target_arch = "x86", target_arch = "x86_64")))]
    {
        InstructionSet::Baseline
    }
    #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
    {
        InstructionSet::Target
    }
}
