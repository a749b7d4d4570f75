//! massprop's shared test support: a module that the integration tests,
//! the benchmark and the accuracy example each include
//! (`#[path = "…/tests/support/mod.rs"] mod support;`). A module, not a
//! crate of its own: a path dev-dependency is dropped from the published
//! package, whose tests must build and pass too. Its own unit tests run in
//! the integration test binary (`support::`).
//!
//! - [`reference`]: the exact rational reference composer and the scene
//!   description (`Scene`, `Part`, `to_toml`) every accuracy test uses;
//! - [`placed`]: parts placed by include frames, array copies, mirror
//!   images, and meshes, exactly (issue 30);
//! - [`honest`]: every value of a JSON report against the exact body, with
//!   its bound and storage floor;
//! - [`scenes`]: the stress scenes of docs/accuracy.md;
//! - [`solids`]: the reference's exact forms of the cone, torus,
//!   hemisphere and prism.
//!
//! It does not depend on massprop: the reference must stay independent of
//! the code it checks.

pub mod honest;
pub mod placed;
pub mod reference;
pub mod scenes;
pub mod solids;

// The rational types' crates, so that users of `reference::Q` name its
// traits through here.
#[allow(unused_imports)]
pub use num_traits;
