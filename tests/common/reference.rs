//! Bookkeeping shared by the tests against Mitsuba 3's reference values.

/// The largest deviations of one quantity.
#[derive(Debug, Default, Clone, Copy)]
pub struct Dev {
    pub values: usize,
    pub max_abs: f64,
    /// Over values with a non-zero oracle.
    pub max_rel: f64,
    pub failures: usize,
    /// Values where the oracle is exactly zero (lobe must be within the absolute tolerance).
    pub zeros: usize,
    /// Oracle exactly zero, lobe non-zero but within the absolute tolerance (Mitsuba's
    /// `1e-20` cut of `D`).
    pub tiny_where_zero: usize,
}

impl std::fmt::Display for Dev {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} values ({} oracle zeros), max abs {:.2e}, max rel {:.2e}, {} failures",
            self.values, self.zeros, self.max_abs, self.max_rel, self.failures
        )?;
        if self.tiny_where_zero > 0 {
            write!(
                f,
                ", {} non-zero (≤ 1e-9) where Mitsuba has 0",
                self.tiny_where_zero
            )?;
        }
        Ok(())
    }
}
