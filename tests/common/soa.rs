//! Owned structure-of-arrays buffers for the batched calls (`lobe::batch`), readable per lane,
//! runs of a model's batched calls into them ([`eval_pdf_batched`], [`sample_batched`]), and
//! bit-for-bit equality with the scalar calls: shared by `tests/batch.rs` (which asserts) and
//! the fuzz example (`examples/fuzz/`, which counts; it includes this file by its path).

use lobe::batch::{Batch, Lanes, SampleOut, Vec2s, Vec3s, Vec3sMut, Vec4sMut};
use lobe::bxdf::{BxdfSample, Lobes};
use lobe::{Spectrum, Vec2, Vec3, Vec4};

/// One slice per coordinate.
pub struct Soa {
    /// The `x` of every lane.
    pub x: Vec<f32>,
    /// The `y` of every lane.
    pub y: Vec<f32>,
    /// The `z` of every lane.
    pub z: Vec<f32>,
}

impl Soa {
    /// The lanes `v`.
    pub fn of(v: &[Vec3]) -> Self {
        Self {
            x: v.iter().map(|w| w.x).collect(),
            y: v.iter().map(|w| w.y).collect(),
            z: v.iter().map(|w| w.z).collect(),
        }
    }
    /// `n` lanes of [`UNWRITTEN`].
    pub fn unwritten(n: usize) -> Self {
        Self {
            x: vec![UNWRITTEN; n],
            y: vec![UNWRITTEN; n],
            z: vec![UNWRITTEN; n],
        }
    }
    /// The lanes as a batched call's input.
    pub fn view(&self) -> Vec3s<'_> {
        Vec3s {
            x: &self.x,
            y: &self.y,
            z: &self.z,
        }
    }
    /// The lanes as a batched call's output.
    pub fn view_mut(&mut self) -> Vec3sMut<'_> {
        Vec3sMut {
            x: &mut self.x,
            y: &mut self.y,
            z: &mut self.z,
        }
    }
    /// Lane `k`.
    pub fn get(&self, k: usize) -> Vec3 {
        Vec3::new(self.x[k], self.y[k], self.z[k])
    }
}

/// What the output buffers hold before a batched call: a NaN whose bits no lane computes, so
/// that a lane the loop skipped differs, bit for bit, from the scalar call's answer (which is
/// often `+0`).
pub const UNWRITTEN: f32 = f32::from_bits(0x7fc0_beef);

/// A spectrum's batched output buffers, readable per lane.
pub trait Buffers: Lanes + Spectrum {
    /// The buffers: one `Vec` per channel.
    type Store;
    /// `n` lanes of [`UNWRITTEN`].
    fn store(n: usize) -> Self::Store;
    /// The buffers as a batched call's output.
    fn lanes_mut(s: &mut Self::Store) -> Self::Mut<'_>;
    /// Lane `k`.
    fn read(s: &Self::Store, k: usize) -> Self;
}

impl Buffers for f32 {
    type Store = Vec<f32>;
    fn store(n: usize) -> Vec<f32> {
        vec![UNWRITTEN; n]
    }
    fn lanes_mut(s: &mut Vec<f32>) -> &mut [f32] {
        s
    }
    fn read(s: &Vec<f32>, k: usize) -> f32 {
        s[k]
    }
}

impl Buffers for Vec3 {
    type Store = Soa;
    fn store(n: usize) -> Soa {
        Soa::unwritten(n)
    }
    fn lanes_mut(s: &mut Soa) -> Vec3sMut<'_> {
        s.view_mut()
    }
    fn read(s: &Soa, k: usize) -> Vec3 {
        s.get(k)
    }
}

/// Four channels (four wavelengths), one `Vec` each.
pub struct Channels4([Vec<f32>; 4]);

impl Buffers for Vec4 {
    type Store = Channels4;
    fn store(n: usize) -> Channels4 {
        Channels4([0; 4].map(|_| vec![UNWRITTEN; n]))
    }
    fn lanes_mut(s: &mut Channels4) -> Vec4sMut<'_> {
        let [x, y, z, w] = &mut s.0;
        Vec4sMut { x, y, z, w }
    }
    fn read(s: &Channels4, k: usize) -> Vec4 {
        Vec4::from_array(s.0.each_ref().map(|c| c[k]))
    }
}

/// Equal bit for bit, channel by channel: `-0` and `+0` differ (and a NaN equals only a NaN
/// of the same bits: no lane computes one, and [`UNWRITTEN`] marks a lane not written).
pub fn same<S: Spectrum>(a: S, b: S) -> bool {
    (0..S::CHANNELS).all(|c| a.channel(c).to_bits() == b.channel(c).to_bits())
}

/// What the sample's lobe buffer holds before a batched call: no sample comes from reflection
/// and transmission at once, so a lane the loop skipped shows.
pub fn lobe_unwritten() -> Lobes {
    Lobes::REFLECTION | Lobes::TRANSMISSION | Lobes::SPECULAR
}

/// What the sample's `eta` buffer holds before a batched call: no lane writes a negative one.
pub const ETA_UNWRITTEN: f32 = -1.0;

/// What a model's batched `eval` and `pdf` wrote, lane by lane.
pub struct Values<S: Buffers> {
    /// `eval_batch`'s values.
    pub f: S::Store,
    /// `pdf_batch`'s densities.
    pub pdf: Vec<f32>,
}

/// Runs `m`'s batched `eval` and `pdf` over the lanes `(wo[k], wi[k])`, one call each, into
/// buffers that start [`UNWRITTEN`].
///
/// Panics if the slices differ in length.
pub fn eval_pdf_batched<M>(m: &M, wo: &[Vec3], wi: &[Vec3]) -> Values<M::Spectrum>
where
    M: Batch<Spectrum: Buffers>,
{
    let n = wo.len();
    let (wo, wi) = (Soa::of(wo), Soa::of(wi));
    let mut f = M::Spectrum::store(n);
    let mut pdf = vec![UNWRITTEN; n];
    let lengths = "the inputs' and outputs' slices have one length";
    m.eval_batch(wo.view(), wi.view(), M::Spectrum::lanes_mut(&mut f))
        .expect(lengths);
    m.pdf_batch(wo.view(), wi.view(), &mut pdf).expect(lengths);
    Values { f, pdf }
}

/// What a model's batched `sample` wrote, lane by lane.
pub struct Samples<S: Buffers> {
    /// The sampled directions.
    pub wi: Soa,
    /// The values.
    pub f: S::Store,
    /// The densities.
    pub pdf: Vec<f32>,
    /// The lobes.
    pub lobe: Vec<Lobes>,
    /// The relative indices of refraction.
    pub eta: Vec<f32>,
}

/// One lane of [`Samples`].
#[derive(Debug)]
pub struct SampleLane<S> {
    /// The sampled direction.
    pub wi: Vec3,
    /// The value.
    pub f: S,
    /// The density.
    pub pdf: f32,
    /// The lobe.
    pub lobe: Lobes,
    /// The relative index of refraction.
    pub eta: f32,
}

impl<S: Buffers> Samples<S> {
    /// Lane `k`.
    pub fn lane(&self, k: usize) -> SampleLane<S> {
        SampleLane {
            wi: self.wi.get(k),
            f: S::read(&self.f, k),
            pdf: self.pdf[k],
            lobe: self.lobe[k],
            eta: self.eta[k],
        }
    }
}

impl<S: Spectrum> SampleLane<S> {
    /// The scalar call's answer `scalar`, bit for bit; where it has no sample, every output
    /// zero and the lobe [`Lobes::NONE`], as `SampleOut` documents.
    pub fn agrees(&self, scalar: Option<&BxdfSample<S>>) -> bool {
        match scalar {
            Some(s) => {
                same(self.wi, s.wi)
                    && same(self.f, s.f)
                    && same(self.pdf, s.pdf)
                    && self.lobe == s.lobe
                    && same(self.eta, s.eta)
            }
            None => {
                same(self.wi, Vec3::ZERO)
                    && same(self.f, S::zero())
                    && same(self.pdf, 0.0)
                    && self.lobe == Lobes::NONE
                    && same(self.eta, 0.0)
            }
        }
    }
}

/// Runs `m`'s batched `sample` over the lanes `(wo[k], u[k], uc[k])`, one call, into buffers
/// that start with values no lane writes ([`UNWRITTEN`], [`lobe_unwritten`],
/// [`ETA_UNWRITTEN`]).
///
/// Panics if the slices differ in length.
pub fn sample_batched<M>(m: &M, wo: &[Vec3], u: &[Vec2], uc: &[f32]) -> Samples<M::Spectrum>
where
    M: Batch<Spectrum: Buffers>,
{
    let n = wo.len();
    let wo = Soa::of(wo);
    let (ux, uy): (Vec<f32>, Vec<f32>) = u.iter().map(|u| (u.x, u.y)).unzip();
    let mut s = Samples {
        wi: Soa::unwritten(n),
        f: M::Spectrum::store(n),
        pdf: vec![UNWRITTEN; n],
        lobe: vec![lobe_unwritten(); n],
        eta: vec![ETA_UNWRITTEN; n],
    };
    let out = SampleOut {
        wi: s.wi.view_mut(),
        f: M::Spectrum::lanes_mut(&mut s.f),
        pdf: &mut s.pdf,
        lobe: &mut s.lobe,
        eta: &mut s.eta,
    };
    m.sample_batch(wo.view(), Vec2s { x: &ux, y: &uy }, uc, out)
        .expect("the inputs' and outputs' slices have one length");
    s
}
