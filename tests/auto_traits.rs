//! What a renderer assumes of every model, part and parameter without reading its source: it
//! can be shared by a thread pool (`Send + Sync`), copied into a material table (`Clone`,
//! `'static`) and printed (`Debug`). Plain-number types are also `Copy` and `PartialEq`.
//! Checked at compile time: a field that broke one of these (an `Rc`, a `Cell`, a borrowed
//! table) fails this file's build, not a user's.

use core::fmt::Debug;
use lobe::bxdf::{
    At, BlinnPhong, BlinnPhongForm, BxdfSample, CoatedConductor, CoatedDiffuse,
    CompensatedDielectric, CompensatedMicrofacet, CompensatedPlastic, CompensatedState,
    Compensation, DiffuseTransmission, DisneyDiffuse, EnergyPreservingOrenNayar, Glazed, Lambert,
    Layered, Lobes, Microfacet, Mirror, Mix, Mono, OrenNayar, Phong, Plastic, PlasticState,
    RoughConductor, RoughDielectric, Sheen, SmoothDielectric, ThinDielectric, TransportMode,
    TwoSided,
};
use lobe::fresnel::{Conductor, Dielectric, DielectricFresnel, NoFresnel, Schlick};
use lobe::metals::{IorSample, Metal};
use lobe::microfacet::{
    Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr, Masking, Sampling, View,
};
use lobe::sh::{
    IrradianceQuadratic, Sh3, ShEstimate, ShRotation, SphereQuadrature, Transfer, Zonal,
};
use lobe::tables::{AlbedoRow, DielectricAlbedo, bake::Family};
use lobe::{Alpha, ComplexIor, Eta, Frame, Ior, ParamError, Roughness, Vec3, Vec4};

/// Shared across threads, cloned into tables, printed.
fn shareable<T: Send + Sync + Clone + Debug + 'static>() {}

/// A handful of numbers: also copied and compared.
fn plain<T: Send + Sync + Copy + Debug + PartialEq + 'static>() {}

/// One line per type, so that a failure names it.
macro_rules! check {
    ($f:ident: $($t:ty),* $(,)?) => { $( $f::<$t>(); )* };
}

#[test]
fn parameters_and_errors_are_plain_values() {
    check!(plain: Alpha, Roughness, Eta, Ior, ComplexIor<f32>, ComplexIor<Vec3>, Frame);
    check!(plain: Masking, BeckmannMasking, Sampling, View, Lobes, TransportMode);
    check!(plain: BlinnPhongForm, Compensation, BxdfSample<Vec3>, BxdfSample<f32>);
    check!(plain: ParamError, lobe::batch::LengthError, lobe::batch::InstructionSet);
}

#[test]
fn prepared_states_tables_and_metals_are_plain_values() {
    check!(plain: At<View>, PlasticState<At<View>>);
    check!(plain: CompensatedState<At<View>, Vec3>);
    check!(plain: AlbedoRow, DielectricAlbedo, Family, Metal, IorSample);
}

#[test]
fn distributions_and_fresnel_terms_are_plain_values() {
    check!(plain: Ggx, Beckmann, BlinnPhongNdf, Gtr);
    check!(plain: Schlick<Vec3>, Conductor<Vec3>, Conductor<Vec4>, Dielectric);
    check!(plain: NoFresnel<f32>, DielectricFresnel);
}

#[test]
fn models_are_shareable() {
    check!(shareable: Lambert<Vec3>, OrenNayar<Vec3>, EnergyPreservingOrenNayar<Vec3>);
    check!(shareable: DisneyDiffuse<Vec3>, Phong<Vec3>, BlinnPhong<Vec3>, Glazed<Vec3>);
    check!(shareable: Sheen<Vec3>, DiffuseTransmission<Vec3>, SmoothDielectric, ThinDielectric);
    check!(shareable: Mirror<Conductor<Vec3>>, RoughConductor<Ggx, Vec3>);
    check!(shareable: Microfacet<Beckmann, Schlick<Vec3>>, RoughDielectric<Ggx>);
    check!(shareable: CompensatedMicrofacet<Ggx, Conductor<Vec3>>, CompensatedDielectric<Ggx>);
    check!(shareable: Plastic<Ggx, Vec3>, CompensatedPlastic<Ggx, Vec3>);
    check!(shareable: CoatedDiffuse<Ggx, Vec3>, CoatedConductor<Ggx, Ggx, Vec3>);
    check!(shareable: Layered<SmoothDielectric, Lambert<f32>>);
    check!(shareable: Mix<Lambert<Vec3>, RoughConductor<Ggx, Vec3>>, TwoSided<Lambert<Vec3>>);
    check!(shareable: Mono<RoughDielectric<Ggx>>);
}

#[test]
fn spherical_harmonics_are_shareable() {
    check!(plain: Sh3<Vec3>, Zonal<3>, IrradianceQuadratic<Vec3>);
    check!(shareable: ShRotation<9>, Transfer<9, Vec3>, SphereQuadrature, ShEstimate<9>);
}
