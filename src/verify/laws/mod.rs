//! The laws room: what a model must obey, measured, reported and checked, one file per
//! subject.
//!
//! What lives here: `bxdf.rs`, the laws of a BSDF of any spectrum (positivity, reciprocity, the
//! energy bound by two albedo estimators, sampling, consistency), [`check_bxdf`], and [`Channel`];
//! `expectation.rs`, the laws of a stochastic BSDF checked in expectation (reciprocity, sampling
//! against the expected density, the sampled weight against the expected value) and
//! [`check_bxdf_in_expectation`], which `check_bxdf` calls for one; `distribution.rs`, the laws of
//! a microfacet distribution (`D` normalisation, projected area, visible normals, sampling) and
//! [`check_ndf`]; and what they share: the one configuration ([`Config`], with the older
//! [`BxdfCheck`] that converts into it, `config.rs`) and the reports ([`Law`], [`LawReport`],
//! [`Report`], `report.rs`).
//!
//! Each file measures with the tools of the statistics room; `bxdf.rs` and `expectation.rs` use
//! each other (`check_bxdf` hands a stochastic model to `check_bxdf_in_expectation`, which reuses
//! the exact laws that hold for one), and `distribution.rs` uses neither.

mod bxdf;
mod config;
mod distribution;
mod expectation;
mod report;

pub use bxdf::{
    Albedo, Channel, ReciprocityPair, SUBNORMAL_FLOOR, albedo, albedo_cosine, albedo_sampled,
    check_bxdf, chi2_bxdf, consistency, energy_bound, positivity, reciprocity, reciprocity_pair,
    sample_consistency, sampling_chi2,
};
pub use config::{BxdfCheck, Config};
pub use distribution::{
    check_ndf, chi2_normals, d_normalization, projected_area, projected_area_masked,
    visible_normalization,
};
pub use expectation::{
    ExpectedPair, check_bxdf_in_expectation, consistency_in_expectation,
    reciprocity_in_expectation, reciprocity_pair_in_expectation,
    sampling_and_consistency_in_expectation, sampling_in_expectation,
};
pub use report::{Law, LawReport, Report};
