//! The closed choices a model is built with, as `snake_case` names: [`Masking`],
//! [`BeckmannMasking`], [`TransportMode`], [`BlinnPhongForm`] and [`Compensation`].

use crate::bxdf::{BlinnPhongForm, Compensation, TransportMode};
use crate::microfacet::{BeckmannMasking, Masking};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// Serialises the unit-variant enum `$ty` (named `$name`) through the mirror `$def`, whose
/// variants serde names in `snake_case`. The mirror is a remote definition: a variant added
/// to `$ty` and not to `$def` fails to compile here.
macro_rules! by_name {
    ($ty:ident = $name:tt, $def:ident { $($variant:ident),+ $(,)? }) => {
        #[derive(Serialize, Deserialize)]
        #[serde(remote = $name, rename = $name, rename_all = "snake_case")]
        enum $def {
            $($variant),+
        }

        impl Serialize for $ty {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                $def::serialize(self, serializer)
            }
        }

        impl<'de> Deserialize<'de> for $ty {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                $def::deserialize(deserializer)
            }
        }
    };
}

by_name!(
    Masking = "Masking",
    MaskingDef {
        HeightCorrelated,
        Separable,
        VCavity
    }
);
by_name!(
    BeckmannMasking = "BeckmannMasking",
    BeckmannMaskingDef {
        Exact,
        WalterRational
    }
);
by_name!(
    TransportMode = "TransportMode",
    TransportModeDef {
        Radiance,
        Importance
    }
);
by_name!(
    BlinnPhongForm = "BlinnPhongForm",
    BlinnPhongFormDef {
        Modified,
        Normalized
    }
);
by_name!(
    Compensation = "Compensation",
    CompensationDef {
        KullaConty,
        Turquin
    }
);
