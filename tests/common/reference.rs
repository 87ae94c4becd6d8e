//! Reading and bookkeeping shared by the tests against Mitsuba 3's reference values.

use lobe::Vec3;
use serde_json::Value;

/// The records of a reference file (its text and name) and the count its `meta` announces,
/// which the record count must equal.
pub fn load(text: &str, file: &str) -> (Vec<Value>, usize) {
    let data: Value = serde_json::from_str(text).unwrap_or_else(|e| panic!("{file} parses: {e}"));
    let records = data["records"]
        .as_array()
        .unwrap_or_else(|| panic!("{file}: records"))
        .clone();
    let n_meta = data["meta"]["n_records"]
        .as_u64()
        .unwrap_or_else(|| panic!("{file}: meta.n_records")) as usize;
    assert_eq!(
        records.len(),
        n_meta,
        "{file}: record count disagrees with meta"
    );
    (records, n_meta)
}

/// A numeric field of a record.
pub fn field(r: &Value, name: &str) -> f64 {
    r[name]
        .as_f64()
        .unwrap_or_else(|| panic!("field {name} in {r}"))
}

/// An input field. The JSON holds exact f32 values (CONVENTIONS §0), so the cast is exact.
pub fn field32(r: &Value, name: &str) -> f32 {
    field(r, name) as f32
}

/// The vector stored as `{prefix}_x`, `{prefix}_y`, `{prefix}_z`.
pub fn vec_field(r: &Value, prefix: &str) -> Vec3 {
    Vec3::new(
        field32(r, &format!("{prefix}_x")),
        field32(r, &format!("{prefix}_y")),
        field32(r, &format!("{prefix}_z")),
    )
}

/// The microfacet distribution a record names in its `distribution` field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Ggx,
    Beckmann,
}

impl Kind {
    /// The record's distribution.
    pub fn of(r: &Value) -> Self {
        match r["distribution"].as_str() {
            Some("ggx") => Self::Ggx,
            Some("beckmann") => Self::Beckmann,
            other => panic!("unknown distribution {other:?} in {r}"),
        }
    }

    /// Its name in the records.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ggx => "ggx",
            Self::Beckmann => "beckmann",
        }
    }
}

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

impl Dev {
    /// Adds one comparison of lobe's value with the oracle's, `fail`ing the tolerance or not;
    /// returns whether lobe is non-zero (but within tolerance) where the oracle is exactly zero.
    pub fn add(&mut self, lobe: f64, oracle: f64, fail: bool) -> bool {
        let err = (lobe - oracle).abs();
        let tiny = oracle == 0.0 && lobe != 0.0 && !fail;
        self.values += 1;
        self.max_abs = self.max_abs.max(err);
        if oracle != 0.0 {
            self.max_rel = self.max_rel.max(err / oracle.abs());
        } else {
            self.zeros += 1;
        }
        self.tiny_where_zero += usize::from(tiny);
        self.failures += usize::from(fail);
        tiny
    }
}

/// Prints each category's deviations, indented.
pub fn print_devs<'a, C: std::fmt::Display>(
    indent: &str,
    devs: impl IntoIterator<Item = (C, &'a Dev)>,
) {
    for (category, dev) in devs {
        eprintln!("{indent}{category}: {dev}");
    }
}

/// Asserts that no record failed, listing the failures otherwise.
pub fn assert_no_failures(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
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
