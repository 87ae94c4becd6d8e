//! The reports a law check returns: what it measured, how sure it is, and whether it passed.

use std::fmt;
use std::format;
use std::string::String;
use std::vec::Vec;

/// A physical law, or a property of a sampler, that a check measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Law {
    /// Finite, non-negative `eval`, `pdf` and samples for any unit directions.
    Positivity,
    /// Helmholtz reciprocity, or its generalised form across an interface.
    Reciprocity,
    /// Directional albedo `∫ f |cos θi| dωi ≤` the claimed bound (1 for conservation).
    EnergyBound,
    /// The albedo by the model's sampler and by cosine sampling agree.
    AlbedoEstimators,
    /// `sample` draws directions with the density `pdf` claims (chi-square).
    Sampling,
    /// `sample`'s value and density equal `eval` and `pdf` at the sampled direction.
    Consistency,
    /// `∫ D(m) cos θm dωm = 1`.
    DNormalization,
    /// `∫ G1(wo) max(0, wo·m) D(m) dωm = cos θo`.
    ProjectedArea,
    /// `∫ D_w(m) dωm = 1`.
    VisibleNormalization,
}

impl Law {
    /// A short name, as the conformance matrix heads its columns.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Positivity => "positivity",
            Self::Reciprocity => "reciprocity",
            Self::EnergyBound => "energy bound",
            Self::AlbedoEstimators => "albedo estimators agree",
            Self::Sampling => "sampling (χ²)",
            Self::Consistency => "sample = eval/pdf",
            Self::DNormalization => "D normalisation",
            Self::ProjectedArea => "projected area",
            Self::VisibleNormalization => "visible normals",
        }
    }
}

impl fmt::Display for Law {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The outcome of one law check.
#[derive(Clone, Debug, PartialEq)]
pub struct LawReport {
    /// The law checked.
    pub law: Law,
    /// Whether the measurement is consistent with the law.
    pub passed: bool,
    /// The headline figure: what [`LawReport::figure_name`] says.
    pub figure: f64,
    /// The figure's standard error (`0` for a deterministic figure).
    pub uncertainty: f64,
    /// What the figure is, e.g. `"max relative error"`.
    pub figure_name: &'static str,
    /// The configuration it ran: sample counts, directions.
    pub budget: String,
    /// Where the worst case (or the failure) was: directions and values.
    pub detail: String,
}

impl LawReport {
    /// Whether the law held.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.passed
    }

    /// The figure with its uncertainty, compactly, as the conformance matrix shows it.
    #[must_use]
    pub fn cell(&self) -> String {
        let value = |x: f64| {
            if x == 0.0 || (1e-3..1e4).contains(&x.abs()) {
                format!("{x:.4}")
            } else {
                format!("{x:.1e}")
            }
        };
        if self.uncertainty > 0.0 {
            format!("{} ± {:.1e}", value(self.figure), self.uncertainty)
        } else {
            value(self.figure)
        }
    }
}

impl fmt::Display for LawReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} — {} {} ({}); {}",
            self.law,
            if self.passed { "passed" } else { "FAILED" },
            self.figure_name,
            self.cell(),
            self.budget,
            self.detail
        )
    }
}

/// The reports of every law checked on one model.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// What was checked.
    pub name: String,
    /// One report per law that applies.
    pub laws: Vec<LawReport>,
}

impl Report {
    /// True when every law checked passed.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.laws.iter().all(LawReport::passed)
    }

    /// The reports that failed.
    pub fn failures(&self) -> impl Iterator<Item = &LawReport> {
        self.laws.iter().filter(|r| !r.passed)
    }

    /// The report of `law`, if it was checked.
    #[must_use]
    pub fn get(&self, law: Law) -> Option<&LawReport> {
        self.laws.iter().find(|r| r.law == law)
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let failed = self.failures().count();
        writeln!(
            f,
            "{}: {}",
            self.name,
            if failed == 0 {
                String::from("every law holds")
            } else {
                format!("{failed} of {} laws FAILED", self.laws.len())
            }
        )?;
        for r in &self.laws {
            writeln!(f, "  {r}")?;
        }
        Ok(())
    }
}
