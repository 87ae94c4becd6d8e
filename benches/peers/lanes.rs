//! A loop over lanes compiled for the widest instruction set the CPU has, by the same
//! run-time dispatch as `lobe::batch` (pulp): what the peer benchmarks time lobe's batched
//! calls against when they measure a piece of arithmetic alone.

/// `out[k] = f(x[k], y[k])` for every lane.
pub struct PerLane<'a, F> {
    /// The first operands.
    pub x: &'a [f32],
    /// The second operands.
    pub y: &'a [f32],
    /// The results.
    pub out: &'a mut [f32],
    /// The lane's arithmetic.
    pub f: F,
}

impl<F: Fn(f32, f32) -> f32> pulp::WithSimd for PerLane<'_, F> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let n = self.out.len();
        let (x, y) = (&self.x[..n], &self.y[..n]);
        for (k, o) in self.out.iter_mut().enumerate() {
            *o = (self.f)(x[k], y[k]);
        }
    }
}
