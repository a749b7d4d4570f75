//! massprop's shared test support, one crate that the integration tests,
//! the benchmark and the accuracy example all depend on (as a path
//! dev-dependency) instead of including each other's files by `#[path]`.
//!
//! - [`reference`]: the exact rational reference composer and the scene
//!   description (`Scene`, `Part`, `to_toml`) every accuracy test uses;
//! - [`scenes`]: the stress scenes of docs/accuracy.md.
//!
//! It does not depend on massprop: the reference must stay independent of
//! the code it checks.

pub mod reference;
pub mod scenes;

// The rational types' crates, so that users of `reference::Q` need no
// dependencies (and versions) of their own to name its traits.
pub use num_bigint;
pub use num_rational;
pub use num_traits;
