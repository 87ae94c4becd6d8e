//! The crate's own small macros, declared before every module that uses them.

/// Accessors that return a field of the same name by value, each `#[inline]` and
/// `#[must_use]` with its one-line doc: written inside the type's `impl` block as
/// `getters! { /// The reflectance. reflectance: S, … }`.
macro_rules! getters {
    ($($(#[$doc:meta])+ $name:ident: $ty:ty),+ $(,)?) => {
        $(
            $(#[$doc])+
            #[inline]
            #[must_use]
            pub fn $name(&self) -> $ty {
                self.$name
            }
        )+
    };
}
