//! Every model's [`Batch`] implementation.

use super::Batch;
use crate::bxdf::both_above;
use crate::bxdf::{
    BlinnPhong, CompensatedDielectric, CompensatedMicrofacet, DisneyDiffuse,
    EnergyPreservingOrenNayar, Glazed, Lambert, Microfacet, Mirror, OrenNayar, Phong, Plastic,
    RoughDielectric, SmoothDielectric, ThinDielectric,
};
use crate::bxdf::{Bxdf, CosineSampled, DiffuseTransmission, LayerInterface, Layered, Sheen};
use crate::fresnel::{Dielectric, Fresnel, FresnelAverage};
use crate::microfacet::NormalDistribution;
use crate::spectrum::Spectrum;

use super::kernel::{LaneOp, Plain};
use super::tabulated::chunked;
use super::tabulated::{TableLanes, TableOp, TableSample, TableSampleOp};
use super::{Lanes, LengthError, SampleOut, Vec2s, Vec3s, run};
use super::{eval_kernel, pdf_kernel, sample_kernel};
use crate::bxdf::{At, BxdfSample, CompensatedState, Compensation, FixedForm, Prepare};
use crate::bxdf::{CompensatedPlastic, PlasticState};
use crate::microfacet::Masking;
use crate::microfacet::View;
use glam::{Vec2, Vec3};

impl<S: Spectrum + Lanes> Batch for Lambert<S> {}
impl<S: Spectrum + Lanes> Batch for Phong<S> {}
impl<S: Spectrum + Lanes> Batch for BlinnPhong<S> {}
impl<S: Spectrum + Lanes> Batch for Glazed<S> {}
impl<S: Spectrum + Lanes> Batch for DiffuseTransmission<S> {}
impl<S: Spectrum + Lanes> Batch for Sheen<S> {}
impl<T: LayerInterface + Clone, B: Bxdf + Clone> Batch for Layered<T, B> where B::Spectrum: Lanes {}

// The models with delta lobes only: `eval` and `pdf` are zero for every pair.
impl<F: Fresnel> Batch for Mirror<F>
where
    F::Spectrum: Lanes,
{
    const DELTA_ONLY: bool = true;
}
impl Batch for SmoothDielectric {
    const DELTA_ONLY: bool = true;
}
impl Batch for ThinDielectric {
    const DELTA_ONLY: bool = true;
}
/// A model whose value depends on a masking term chosen at run time: the batched loops fix
/// it at compile time, so that the loop does not branch on it.
trait Masked: Prepare {
    /// `eval` under `masking`.
    fn eval_masked(&self, wo: Vec3, wi: Vec3, masking: Masking) -> Self::Spectrum;
    /// `sample` under `masking`.
    fn sample_masked(
        &self,
        wo: Vec3,
        u: Vec2,
        uc: f32,
        masking: Masking,
    ) -> Option<BxdfSample<Self::Spectrum>>;
}

/// `Masked` for a model with `masking()` and the named `eval(&at, wi, masking)` and
/// `sample(&at, u, uc, masking)` (for a microfacet model, the forms that take the Fresnel
/// term channel by channel: see [`Fresnel::eval_per_channel`]).
macro_rules! masked {
    (impl<$($g:ident: $b:path),*> for $t:ty =>
        $eval:ident $(::<$ef:tt>)?, $sample:ident $(::<$sf:tt>)?) => {
        impl<$($g: $b),*> Masked for $t {
            #[inline(always)]
            fn eval_masked(&self, wo: Vec3, wi: Vec3, masking: Masking) -> Self::Spectrum {
                self.$eval$(::<$ef>)?(&self.prepare(wo), wi, masking)
            }

            #[inline(always)]
            fn sample_masked(
                &self,
                wo: Vec3,
                u: Vec2,
                uc: f32,
                masking: Masking,
            ) -> Option<BxdfSample<Self::Spectrum>> {
                self.$sample$(::<$sf>)?(&self.prepare(wo), u, uc, masking)
            }
        }
    };
}

masked!(impl<D: NormalDistribution, F: Fresnel> for Microfacet<D, F> =>
    eval_with::<true>, sample_with::<true>);
masked!(impl<D: NormalDistribution> for RoughDielectric<D> => eval_lane, sample_with);

/// A [`Masked`] model's lanes with the masking term `MASKINGS[K]`.
struct FixedMasking<const K: usize>;

/// The masking terms, by [`FixedMasking`]'s index.
const MASKINGS: [Masking; 3] = [
    Masking::HeightCorrelated,
    Masking::Separable,
    Masking::VCavity,
];

impl<const K: usize, M: Masked> LaneOp<M> for FixedMasking<K> {
    #[inline(always)]
    fn eval(m: &M, wo: Vec3, wi: Vec3) -> M::Spectrum {
        m.eval_masked(wo, wi, MASKINGS[K])
    }

    #[inline(always)]
    fn pdf(m: &M, wo: Vec3, wi: Vec3) -> f32 {
        m.pdf_prepared(&m.prepare(wo), wi)
    }

    #[inline(always)]
    fn sample(m: &M, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<M::Spectrum>> {
        m.sample_masked(wo, u, uc, MASKINGS[K])
    }
}

/// Chooses the loop for the model's masking term, run by `$run` (`run`, or `chunked` for a
/// model that reads tables).
macro_rules! by_masking {
    ($run:ident, $m:expr, $kernel:ident($($arg:expr),*)) => {
        match $m.masking() {
            Masking::HeightCorrelated => $run($kernel::<_, FixedMasking<0>>($m, $($arg),*)),
            Masking::Separable => $run($kernel::<_, FixedMasking<1>>($m, $($arg),*)),
            Masking::VCavity => $run($kernel::<_, FixedMasking<2>>($m, $($arg),*)),
        }
    };
}

/// `Batch` for a model whose loops fix something outside the loop, or take lanes of their own:
/// `eval` and `sample` chosen by `$by` (`by_masking`, `by_compensation`, `by_coat`, `by_form`,
/// `by_cosine`) and run by `$run`, `pdf` run by `$run` with the lane operation `$pdf` (the
/// density depends on neither). `run` for a model that reads no table (`$pdf` = `Plain`, as
/// `Batch`'s own `pdf_batch`); `chunked`, a chunk of lanes at a time (the module `tabulated`;
/// `$pdf` = `()`), for one that reads tables at each lane's directions.
macro_rules! batch_by {
    (impl<$($g:ident: $b:ident $(+ $more:ident)*),*> for $t:ty
        where $s:ty, $by:ident, $run:ident, $pdf:ty) => {
        impl<$($g: $b $(+ $more)*),*> Batch for $t
        where
            $s: Lanes,
        {
            fn eval_batch(
                &self,
                wo: Vec3s<'_>,
                wi: Vec3s<'_>,
                f: <$s as Lanes>::Mut<'_>,
            ) -> Result<(), LengthError> {
                $by!($run, self, eval_kernel(wo, wi, f))
            }

            fn pdf_batch(
                &self,
                wo: Vec3s<'_>,
                wi: Vec3s<'_>,
                pdf: &mut [f32],
            ) -> Result<(), LengthError> {
                $run(pdf_kernel::<_, $pdf>(self, wo, wi, pdf))
            }

            fn sample_batch(
                &self,
                wo: Vec3s<'_>,
                u: Vec2s<'_>,
                uc: &[f32],
                out: SampleOut<'_, $s>,
            ) -> Result<(), LengthError> {
                $by!($run, self, sample_kernel(wo, u, uc, out))
            }
        }
    };
}

batch_by!(impl<D: NormalDistribution + Clone, F: Fresnel>
    for Microfacet<D, F> where F::Spectrum, by_masking, run, Plain);

/// The lanes of a cosine-sampled diffuse model of the crate's whose `value` is defined (no
/// panic, no lookup at a computed index) for every finite pair: `eval` computes the value for
/// every pair and then keeps it where both directions are above the surface ([`Plain`]
/// returns zero first). The same numbers; what changes is the loop: Plain's early zero left the
/// loads of `x` and `y`, which only the value reads, behind the test, and LLVM vectorised them
/// as masked loads, which it prices high under AVX2. Without them the loop vectorises from
/// fewer lanes a call (rule 10 in `docs/batched-loops.md`). The scalar calls keep the
/// early zero: below the surface it skips the value's work. A model of the crate's only:
/// `CosineSampled` promises nothing of `value` below the surface, where this op calls it.
struct Cosine;

impl<M: CosineSampled> LaneOp<M> for Cosine {
    #[inline(always)]
    fn eval(m: &M, wo: Vec3, wi: Vec3) -> <M as Prepare>::Spectrum {
        let value = m.value(wo, wi);
        if both_above(wo, wi) {
            value
        } else {
            <M as Prepare>::Spectrum::zero()
        }
    }

    #[inline(always)]
    fn pdf(m: &M, wo: Vec3, wi: Vec3) -> f32 {
        Plain::pdf(m, wo, wi)
    }

    #[inline(always)]
    fn sample(m: &M, wo: Vec3, u: Vec2, uc: f32) -> Option<BxdfSample<<M as Prepare>::Spectrum>> {
        Plain::sample(m, wo, u, uc)
    }
}

/// Runs a diffuse model's loop with [`Cosine`]'s lanes.
macro_rules! by_cosine {
    ($run:ident, $m:expr, $kernel:ident($($arg:expr),*)) => {
        $run($kernel::<_, Cosine>($m, $($arg),*))
    };
}

batch_by!(impl<S: Spectrum + Lanes> for OrenNayar<S> where S, by_cosine, run, Plain);
batch_by!(impl<S: Spectrum + Lanes> for DisneyDiffuse<S> where S, by_cosine, run, Plain);

/// EON's lanes with its albedo's form, exact or fitted, fixed ([`FixedForm`]).
struct FixedExact<const EXACT: bool>;

impl<const EXACT: bool, S: Spectrum> LaneOp<EnergyPreservingOrenNayar<S>> for FixedExact<EXACT> {
    #[inline(always)]
    fn eval(m: &EnergyPreservingOrenNayar<S>, wo: Vec3, wi: Vec3) -> S {
        // The exact form calls `acosf`, so its loop stays scalar: the early zero saves work.
        if EXACT {
            Plain::eval(&FixedForm::<S, EXACT>(m), wo, wi)
        } else {
            Cosine::eval(&FixedForm::<S, EXACT>(m), wo, wi)
        }
    }

    #[inline(always)]
    fn pdf(m: &EnergyPreservingOrenNayar<S>, wo: Vec3, wi: Vec3) -> f32 {
        Plain::pdf(m, wo, wi)
    }

    #[inline(always)]
    fn sample(
        m: &EnergyPreservingOrenNayar<S>,
        wo: Vec3,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<S>> {
        Plain::sample(&FixedForm::<S, EXACT>(m), wo, u, uc)
    }
}

/// Chooses EON's loop for its albedo's form.
macro_rules! by_form {
    ($run:ident, $m:expr, $kernel:ident($($arg:expr),*)) => {
        if $m.is_exact() {
            $run($kernel::<_, FixedExact<true>>($m, $($arg),*))
        } else {
            $run($kernel::<_, FixedExact<false>>($m, $($arg),*))
        }
    };
}

batch_by!(impl<S: Spectrum + Lanes> for EnergyPreservingOrenNayar<S> where S, by_form, run, Plain);
batch_by!(impl<D: NormalDistribution + Clone>
    for RoughDielectric<D> where f32, by_masking, run, Plain);

/// Chooses a compensated model's loop, run by `$run`, for its masking term and compensation.
macro_rules! by_compensation {
    ($run:ident, $m:expr, $kernel:ident($($arg:expr),*)) => {{
        use Compensation::{KullaConty, Turquin};
        use Masking::{HeightCorrelated, Separable, VCavity};
        match ($m.masking(), $m.compensation()) {
            (HeightCorrelated, KullaConty) => $run($kernel::<_, Fixed<0, true>>($m, $($arg),*)),
            (Separable, KullaConty) => $run($kernel::<_, Fixed<1, true>>($m, $($arg),*)),
            (VCavity, KullaConty) => $run($kernel::<_, Fixed<2, true>>($m, $($arg),*)),
            (HeightCorrelated, Turquin) => $run($kernel::<_, Fixed<0, false>>($m, $($arg),*)),
            (Separable, Turquin) => $run($kernel::<_, Fixed<1, false>>($m, $($arg),*)),
            (VCavity, Turquin) => $run($kernel::<_, Fixed<2, false>>($m, $($arg),*)),
        }
    }};
}

impl<D: NormalDistribution, F: FresnelAverage> TableLanes for CompensatedMicrofacet<D, F> {
    type Looked = f32;

    #[inline(always)]
    fn look_up<const L: usize>(&self, z: &[f32], e: &mut [f32; L]) {
        self.albedo().e_chunk(z, e);
    }

    #[inline(always)]
    fn prepare_from(&self, wo: Vec3, e_wo: f32) -> Self::Prepared {
        self.prepare_given(wo, || e_wo)
    }
}

impl<D: NormalDistribution, F: FresnelAverage> TableSample for CompensatedMicrofacet<D, F> {
    type Outgoing = F::Spectrum;

    #[inline(always)]
    fn outgoing(at: &Self::Prepared) -> F::Spectrum {
        at.outgoing
    }

    #[inline(always)]
    fn finish(&self, f: F::Spectrum, outgoing: F::Spectrum, _: f32, e_wi: f32) -> F::Spectrum {
        CompensatedMicrofacet::finish(self, f, outgoing, e_wi)
    }
}

/// A compensated model's lanes with the masking term `MASKINGS[K]` and the compensation
/// (Kulla & Conty's where `KULLA`, else Turquin's) fixed.
struct Fixed<const K: usize, const KULLA: bool>;

impl<const K: usize, const KULLA: bool> Fixed<K, KULLA> {
    /// The compensation.
    const COMPENSATION: Compensation = if KULLA {
        Compensation::KullaConty
    } else {
        Compensation::Turquin
    };
}

impl<const K: usize, const KULLA: bool, D: NormalDistribution, F: FresnelAverage>
    TableOp<CompensatedMicrofacet<D, F>> for Fixed<K, KULLA>
{
    #[inline(always)]
    fn eval(
        m: &CompensatedMicrofacet<D, F>,
        at: &CompensatedState<At<View>, F::Spectrum>,
        wi: Vec3,
        e_wi: f32,
    ) -> F::Spectrum {
        m.eval_given::<true>(at, wi, MASKINGS[K], Self::COMPENSATION, || e_wi)
    }
}

impl<const K: usize, const KULLA: bool, D: NormalDistribution, F: FresnelAverage>
    TableSampleOp<CompensatedMicrofacet<D, F>> for Fixed<K, KULLA>
{
    const UNFINISHED: bool = KULLA;

    #[inline(always)]
    fn sample(
        m: &CompensatedMicrofacet<D, F>,
        at: &CompensatedState<At<View>, F::Spectrum>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<F::Spectrum>> {
        m.sample_compensated::<true, false>(at, u, uc, MASKINGS[K], Self::COMPENSATION)
    }
}

// The compensated microfacet model's three loops look its albedo table up a chunk of lanes
// at a time (the module `tabulated`), with the masking term and the compensation fixed.
batch_by!(impl<D: NormalDistribution + Clone, F: FresnelAverage>
    for CompensatedMicrofacet<D, F> where F::Spectrum, by_compensation, chunked, ());

/// The compensated glass reads its albedo tables at `wo` and `wi`, each on its direction's
/// side: its loops look them up a chunk of lanes at a time (both sides' rows, then a select),
/// with the masking term fixed.
impl<D: NormalDistribution> TableLanes for CompensatedDielectric<D> {
    type Looked = f32;

    #[inline(always)]
    fn look_up<const L: usize>(&self, z: &[f32], e: &mut [f32; L]) {
        self.albedo().e_chunk(z, e);
    }

    #[inline(always)]
    fn prepare_from(&self, wo: Vec3, e_wo: f32) -> Self::Prepared {
        self.prepare_given(wo, || e_wo)
    }

    #[inline(always)]
    fn pdf_lane(&self, at: &Self::Prepared, wi: Vec3) -> f32 {
        CompensatedDielectric::pdf_lane(self, at, wi)
    }
}

impl<D: NormalDistribution> TableSample for CompensatedDielectric<D> {
    type Outgoing = (f32, f32);

    #[inline(always)]
    fn outgoing(at: &Self::Prepared) -> (f32, f32) {
        (at.outgoing, at.inner.wo.z)
    }

    #[inline(always)]
    fn finish(&self, f: f32, outgoing: (f32, f32), wi_z: f32, e_wi: f32) -> f32 {
        CompensatedDielectric::finish(self, f, outgoing, wi_z, e_wi)
    }
}

impl<const K: usize, D: NormalDistribution> TableOp<CompensatedDielectric<D>> for FixedMasking<K> {
    #[inline(always)]
    fn eval(
        m: &CompensatedDielectric<D>,
        at: &CompensatedState<At<View>, f32>,
        wi: Vec3,
        e_wi: f32,
    ) -> f32 {
        m.eval_lane(at, wi, e_wi, MASKINGS[K])
    }
}

impl<const K: usize, D: NormalDistribution> TableSampleOp<CompensatedDielectric<D>>
    for FixedMasking<K>
{
    const UNFINISHED: bool = true;

    #[inline(always)]
    fn sample(
        m: &CompensatedDielectric<D>,
        at: &CompensatedState<At<View>, f32>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<f32>> {
        m.sample_unfinished::<true>(at, u, uc, MASKINGS[K])
    }
}

batch_by!(impl<D: NormalDistribution + Clone>
    for CompensatedDielectric<D> where f32, by_masking, chunked, ());

/// A plastic's lanes with the coat's masking term fixed (height-correlated): read per lane,
/// the term kept the plastic's loops from vectorising (as for the microfacet models; under
/// AVX2 the table reads do too: see the `lobe::batch` docs).
struct HeightCorrelatedCoat;

/// Whether a plastic's coat is the one its batched loops fix: height-correlated masking and,
/// for the compensated coat, Kulla & Conty's compensation. The constructors build no other; a
/// coat that was not would take the plain loops (the same numbers, not vectorised).
trait FixedCoat {
    /// True for the coat the loops fix.
    fn fixed(&self) -> bool;
}

impl<D: NormalDistribution> FixedCoat for Microfacet<D, Dielectric> {
    #[inline(always)]
    fn fixed(&self) -> bool {
        self.masking() == Masking::HeightCorrelated
    }
}

impl<D: NormalDistribution> FixedCoat for CompensatedMicrofacet<D, Dielectric> {
    #[inline(always)]
    fn fixed(&self) -> bool {
        self.masking() == Masking::HeightCorrelated
            && self.compensation() == Compensation::KullaConty
    }
}

/// Chooses a plastic's `eval` or `sample` loop: with the coat fixed ([`FixedCoat`]), run by
/// `$run`, or the plain loop for another coat. (Its density does not depend on the masking
/// term.)
macro_rules! by_coat {
    ($run:ident, $m:expr, $kernel:ident($($arg:expr),*)) => {
        if $m.coat().fixed() {
            $run($kernel::<_, HeightCorrelatedCoat>($m, $($arg),*))
        } else {
            run($kernel::<_, Plain>($m, $($arg),*))
        }
    };
}

batch_by!(impl<D: NormalDistribution + Clone, S: Spectrum + Lanes>
    for Plastic<D, S, Microfacet<D, Dielectric>> where S, by_coat, chunked, ());
batch_by!(impl<D: NormalDistribution + Clone, S: Spectrum + Lanes>
    for Plastic<D, S, CompensatedMicrofacet<D, Dielectric>> where S, by_coat, chunked, ());

/// The plastic with the plain coat reads its own coat-albedo table at `wo` and `wi`: its
/// `eval` and `sample` loops look it up a chunk of lanes at a time.
impl<D: NormalDistribution, S: Spectrum> TableLanes for Plastic<D, S, Microfacet<D, Dielectric>> {
    type Looked = f32;

    #[inline(always)]
    fn look_up<const L: usize>(&self, z: &[f32], e: &mut [f32; L]) {
        self.coat_albedo_chunk(z, e);
    }

    #[inline(always)]
    fn prepare_from(&self, wo: Vec3, e_wo: f32) -> Self::Prepared {
        self.prepare_given(wo, e_wo, self.coat().prepare(wo))
    }
}

impl<D: NormalDistribution, S: Spectrum> TableOp<Plastic<D, S, Microfacet<D, Dielectric>>>
    for HeightCorrelatedCoat
{
    #[inline(always)]
    fn eval(
        m: &Plastic<D, S, Microfacet<D, Dielectric>>,
        at: &At<PlasticState<At<View>>>,
        wi: Vec3,
        e_wi: f32,
    ) -> S {
        let coat_at = Plastic::<D, S>::coat_state(at);
        let coat_f = m
            .coat()
            .eval_with::<false>(coat_at, wi, Masking::HeightCorrelated);
        m.eval_given(at, wi, coat_f, e_wi)
    }
}

impl<D: NormalDistribution, S: Spectrum> TableSample for Plastic<D, S> {
    type Outgoing = f32;

    #[inline(always)]
    fn outgoing(at: &Self::Prepared) -> f32 {
        Self::transmittance(at)
    }

    #[inline(always)]
    fn finish(&self, f: S, t_o: f32, _: f32, e_wi: f32) -> S {
        Plastic::finish(self, f, t_o, e_wi)
    }
}

impl<D: NormalDistribution, S: Spectrum> TableSampleOp<Plastic<D, S>> for HeightCorrelatedCoat {
    const UNFINISHED: bool = true;

    #[inline(always)]
    fn sample(
        m: &Plastic<D, S>,
        at: &At<PlasticState<At<View>>>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<S>> {
        m.sample_lane(at, u, uc, Masking::HeightCorrelated)
    }
}

/// The compensated plastic reads two tables at `wo` and `wi`, its own coat albedo and the
/// coat's `E(μ)`: its loops look both up a chunk of lanes at a time.
impl<D: NormalDistribution, S: Spectrum> TableLanes for CompensatedPlastic<D, S> {
    type Looked = (f32, f32);

    #[inline(always)]
    fn look_up<const L: usize>(&self, z: &[f32], e: &mut [(f32, f32); L]) {
        let (mut plastic, mut coat) = ([0.0; L], [0.0; L]);
        self.coat_albedo_chunk(z, &mut plastic);
        self.coat().albedo().e_chunk(z, &mut coat);
        for ((e, &p), &c) in e.iter_mut().zip(&plastic).zip(&coat) {
            *e = (p, c);
        }
    }

    #[inline(always)]
    fn prepare_from(&self, wo: Vec3, (e_wo, coat_e_wo): (f32, f32)) -> Self::Prepared {
        let coat = self.coat().prepare_given(wo, || coat_e_wo);
        self.prepare_given(wo, e_wo, coat)
    }
}

impl<D: NormalDistribution, S: Spectrum> TableOp<CompensatedPlastic<D, S>>
    for HeightCorrelatedCoat
{
    #[inline(always)]
    fn eval(
        m: &CompensatedPlastic<D, S>,
        at: &At<PlasticState<CompensatedState<At<View>, f32>>>,
        wi: Vec3,
        (e_wi, coat_e_wi): (f32, f32),
    ) -> S {
        let (masking, kulla) = (Masking::HeightCorrelated, Compensation::KullaConty);
        let coat_at = CompensatedPlastic::<D, S>::coat_state(at);
        let coat_f = m
            .coat()
            .eval_given::<false>(coat_at, wi, masking, kulla, || coat_e_wi);
        m.eval_given(at, wi, coat_f, e_wi)
    }
}

impl<D: NormalDistribution, S: Spectrum> TableSample for CompensatedPlastic<D, S> {
    type Outgoing = (f32, f32);

    #[inline(always)]
    fn outgoing(at: &Self::Prepared) -> (f32, f32) {
        CompensatedPlastic::<D, S>::finishing_state(at)
    }

    #[inline(always)]
    fn finish(&self, f: S, outgoing: (f32, f32), _: f32, e_wi: (f32, f32)) -> S {
        self.finish_compensated(f, outgoing, e_wi)
    }
}

impl<D: NormalDistribution, S: Spectrum> TableSampleOp<CompensatedPlastic<D, S>>
    for HeightCorrelatedCoat
{
    const UNFINISHED: bool = true;

    #[inline(always)]
    fn sample(
        m: &CompensatedPlastic<D, S>,
        at: &At<PlasticState<CompensatedState<At<View>, f32>>>,
        u: Vec2,
        uc: f32,
    ) -> Option<BxdfSample<S>> {
        m.sample_lane(at, u, uc, Masking::HeightCorrelated)
    }
}
