//! [`Mono`]: the wrapped model's own representation, the wrapper leaves no trace.

use crate::bxdf::Mono;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, Serializer};

impl<B: Serialize, S> Serialize for Mono<B, S> {
    fn serialize<Se: Serializer>(&self, serializer: Se) -> Result<Se::Ok, Se::Error> {
        self.inner().serialize(serializer)
    }
}

impl<'de, B: Deserialize<'de>, S> Deserialize<'de> for Mono<B, S> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        B::deserialize(deserializer).map(Mono::new)
    }
}
