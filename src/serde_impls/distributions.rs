//! The microfacet distributions: [`Ggx`], [`Beckmann`], [`Gtr`] and [`BlinnPhongNdf`], as
//! their widths (or exponent) and switches. What a distribution derives from them (GGX's
//! `1/α`, the tabulated Smith `G1` of GTR and exact-Smith Blinn-Phong) is computed again by
//! the constructor on the way in.

use super::{is_default, is_true, refused, renamed, yes};
use crate::microfacet::BLINN_PHONG_ALPHA;
use crate::microfacet::{Beckmann, BeckmannMasking, BlinnPhongNdf, Ggx, Gtr};
use crate::param::{Alpha, ParamError};
use core::fmt::{self, Write};
use serde::de::{self, Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

/// A distribution's widths as a file gives them: `alpha` for an isotropic distribution, or
/// `alpha_x` and `alpha_y`.
struct Widths {
    alpha: Option<f32>,
    alpha_x: Option<f32>,
    alpha_y: Option<f32>,
}

impl Widths {
    /// The fields that describe the widths `(αx, αy)`: `alpha` alone when they are equal.
    fn of((ax, ay): (f32, f32)) -> Self {
        if ax == ay {
            Self {
                alpha: Some(ax),
                alpha_x: None,
                alpha_y: None,
            }
        } else {
            Self {
                alpha: None,
                alpha_x: Some(ax),
                alpha_y: Some(ay),
            }
        }
    }

    /// The validated widths `(αx, αy)`; a refused width is named by its field.
    fn alphas<E: de::Error>(self) -> Result<(Alpha, Alpha), E> {
        let width = |v: f32, field| Alpha::new(v).map_err(|e| refused(renamed(e, field)));
        match (self.alpha, self.alpha_x, self.alpha_y) {
            (Some(a), None, None) => width(a, "alpha").map(|a| (a, a)),
            (None, Some(ax), Some(ay)) => Ok((width(ax, "alpha_x")?, width(ay, "alpha_y")?)),
            (None, None, None) => Err(E::missing_field("alpha")),
            (None, Some(_), None) => Err(E::missing_field("alpha_y")),
            (None, None, Some(_)) => Err(E::missing_field("alpha_x")),
            (Some(_), _, _) => Err(E::custom(
                "`alpha` (isotropic) and `alpha_x`/`alpha_y` (anisotropic) exclude each other",
            )),
        }
    }
}

/// `Serialize` and `Deserialize` for an anisotropic distribution through its wire struct,
/// which it also defines: the widths as [`Widths`] gives them and one switch, read by the
/// getter of the switch's name and set again by its `with_` method.
macro_rules! widths_wire {
    (
        $(#[$attr:meta])*
        $ty:ident as $name:literal $repr:ident {
            $(#[$fattr:meta])* $field:ident: $fty:ty => $with:ident
        }
    ) => {
        $(#[$attr])*
        #[derive(serde::Serialize, serde::Deserialize)]
        #[serde(rename = $name, deny_unknown_fields)]
        struct $repr {
            #[serde(default, skip_serializing_if = "Option::is_none")]
            alpha: Option<f32>,
            #[serde(default, skip_serializing_if = "Option::is_none")]
            alpha_x: Option<f32>,
            #[serde(default, skip_serializing_if = "Option::is_none")]
            alpha_y: Option<f32>,
            $(#[$fattr])*
            $field: $fty,
        }

        impl Serialize for $ty {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let w = Widths::of(self.alpha());
                let (alpha, alpha_x, alpha_y) = (w.alpha, w.alpha_x, w.alpha_y);
                let $field = self.$field();
                $repr { alpha, alpha_x, alpha_y, $field }.serialize(serializer)
            }
        }

        impl<'de> Deserialize<'de> for $ty {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let r = $repr::deserialize(deserializer)?;
                let w = Widths { alpha: r.alpha, alpha_x: r.alpha_x, alpha_y: r.alpha_y };
                let (ax, ay) = w.alphas()?;
                Ok(<$ty>::new(ax, ay).$with(r.$field))
            }
        }
    };
}

widths_wire! {
    /// [`Ggx`] on the wire: `{ "alpha": 0.3 }` or `{ "alpha_x": 0.3, "alpha_y": 0.1 }`, and
    /// `"bounded_reflection": false` when it is off.
    Ggx as "Ggx" GgxRepr {
        #[serde(default = "yes", skip_serializing_if = "is_true")]
        bounded_reflection: bool => with_bounded_reflection
    }
}

widths_wire! {
    /// [`Beckmann`] on the wire: the widths as for [`Ggx`], and
    /// `"masking": "walter_rational"` when it does not use the exact Smith `Λ`.
    Beckmann as "Beckmann" BeckmannRepr {
        #[serde(default, skip_serializing_if = "is_default")]
        masking: BeckmannMasking => with_masking
    }
}

wire! {
    /// [`Gtr`] on the wire: `{ "alpha": 0.1, "gamma": 1 }`. The Smith table is not written:
    /// the constructor tabulates it again.
    impl[] Gtr as "Gtr" GtrRepr |m| {
        alpha: f32 = m.alpha(),
        gamma: f32 = m.gamma(),
    } via |r| Alpha::new(r.alpha).and_then(|alpha| Gtr::new(alpha, r.gamma))
}

/// [`BlinnPhongNdf`] on the wire: `{ "alpha": 0.3 }` or `{ "exponent": 20 }` (one of the
/// two, as the two constructors take), and `"exact_smith": true` for its own Smith masking.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(rename = "BlinnPhongNdf", deny_unknown_fields)]
struct BlinnPhongNdfRepr {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    alpha: Option<f32>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    exponent: Option<f32>,
    #[serde(default, skip_serializing_if = "is_default")]
    exact_smith: bool,
}

/// The distribution a file's `alpha` or `exponent` describes, without its switch.
fn blinn_phong_ndf<E: de::Error>(
    alpha: Option<f32>,
    exponent: Option<f32>,
) -> Result<BlinnPhongNdf, E> {
    match (alpha, exponent) {
        // One range for the file's `alpha`, whichever check refuses it: Alpha's own
        // ([0.0001, 10]) would advertise widths Blinn-Phong refuses.
        (Some(a), None) => Alpha::new(a)
            .and_then(BlinnPhongNdf::new)
            .map_err(|e| refused(ParamError::new("alpha", e.value(), BLINN_PHONG_ALPHA))),
        (None, Some(p)) => BlinnPhongNdf::from_exponent(p).map_err(refused),
        (None, None) => Err(E::missing_field("alpha")),
        (Some(_), Some(_)) => Err(E::custom(
            "a Blinn-Phong distribution takes `alpha` or `exponent`, not both",
        )),
    }
}

impl Serialize for BlinnPhongNdf {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        // The two constructors round differently (`p = 2/α² − 2` from a width, `α = √(2/(p + 2))`
        // from an exponent), so a value need not come back from both. Write a parameter that
        // builds this very value again, the shorter number when both do (`"exponent": 20`
        // rather than `"alpha": 0.30151135`; `"alpha": 0.3` rather than `"exponent": 20.222221`).
        let exact_smith = self.has_exact_smith();
        let rebuilds = |alpha: Option<f32>, exponent: Option<f32>| {
            blinn_phong_ndf::<de::value::Error>(alpha, exponent)
                .ok()
                .map(|n| if exact_smith { n.with_exact_smith() } else { n })
                == Some(*self)
        };
        let (a, p) = (self.alpha(), self.exponent());
        let by_width = rebuilds(Some(a), None)
            && !(rebuilds(None, Some(p)) && printed_len(p) < printed_len(a));
        BlinnPhongNdfRepr {
            alpha: by_width.then_some(a),
            exponent: (!by_width).then_some(p),
            exact_smith,
        }
        .serialize(serializer)
    }
}

/// The length of `v` printed as the shortest decimal that reads back as `v`.
fn printed_len(v: f32) -> usize {
    /// Counts what is written to it.
    struct Count(usize);
    impl fmt::Write for Count {
        fn write_str(&mut self, s: &str) -> fmt::Result {
            self.0 += s.len();
            Ok(())
        }
    }
    let mut count = Count(0);
    // Writing to a counter cannot fail.
    let _ = write!(count, "{v}");
    count.0
}

impl<'de> Deserialize<'de> for BlinnPhongNdf {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let r = BlinnPhongNdfRepr::deserialize(deserializer)?;
        let ndf = blinn_phong_ndf(r.alpha, r.exponent)?;
        Ok(if r.exact_smith {
            ndf.with_exact_smith()
        } else {
            ndf
        })
    }
}
