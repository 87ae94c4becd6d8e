# The crate's optional features that build without std (with `libm` for the float functions),
# named once for every CI step that builds the no_std path with all of them: .ci/run's no_std,
# no_std-consumer and bare-metal builds, and .ci/minimal-versions. A new optional feature that
# must stay no_std goes here. Sourced, not run.
# shellcheck shell=bash
no_std_features=libm,serde,approx,mint,bytemuck
# The features that need std (`verify` and `proptest` turn `std` on). .ci/run checks that every
# feature of Cargo.toml is in one list or the other.
std_features=default,std,verify,proptest
# The same features but `libm` (which the consumer crate turns on itself), as the consumer's
# dependency features: lobe/serde,lobe/approx,...
no_std_consumer_features=$(printf '%s' "$no_std_features" | tr ',' '\n' | grep -vx libm |
    sed 's|^|lobe/|' | paste -sd, -)
