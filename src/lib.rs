//! Mass properties of composite rigid bodies from TOML part files: mass,
//! centre of mass, inertia tensor about the centre and about a reference
//! point, principal moments and axes, radii of gyration, and for a given
//! angular velocity the angular momentum, kinetic energy and Euler moment —
//! each value with a rigorous bound on its rounding error.
//!
//! This is the library behind the `massprop` command. Its API is one entry
//! point: [`summarize`] reads a part file (or [`summarize_str`] a part
//! file's text) and returns its [`Summary`], the values
//! `massprop report --format json` prints, in SI units (kg, m, kg·m²,
//! rad/s, N·m·s, J, N·m), tensor convention for the products of inertia
//! (off-diagonals −∫xy dm) unless [`Settings::products`] says otherwise.
//! A file that cannot be read or is invalid gives an [`Error`] that
//! renders (`Display`) as the command prints it, `path:line:col: error: …`
//! with the source line, and gives its parts as fields.
//!
//! ```no_run
//! let summary = massprop::summarize("shapes/robot-arm.toml", &massprop::Settings::default())?;
//! println!("mass {} kg, centre of mass {:?} m", summary.mass, summary.center_of_mass);
//! println!("I about the centre of mass: {:?} kg·m²", summary.inertia_com);
//! # Ok::<(), massprop::Error>(())
//! ```
//!
//! The part file's format is docs/part-file.md in massprop's repository,
//! and `massprop man`; the summary's keys and units are docs/json.md.
//! `examples/library.rs` is a complete program.
//!
//! The modules below are massprop's internals, public only for its own
//! command, tests, benchmarks and fuzz target: they are hidden from this
//! documentation and follow no semantic-versioning promise. From the
//! bottom up (each uses only those above it; docs/architecture.md has the
//! list with each module's job):
//!
//! 1. numbers, units, diagnostics: `numeric`, `la`, `eigen`,
//!    `thresholds`, `units`, `diag`, `io`;
//! 2. shapes and parts: `shapes` (one description per shape and the closed
//!    forms), `rotation` (the forms of a part's turn), `mesh` (triangle
//!    meshes read, checked and integrated), `part` (a part and
//!    its physics), `materials`;
//! 3. the model: `model` (the part file read and validated);
//! 4. composition and principal axes: `compose`, `mass`, `bounds`;
//! 5. analysis: `analysis` (the one load pipeline; summary, checks, diff);
//! 6. output: `output` (tables, JSON, CI formats, the drawing);
//! 7. commands: `commands`, and `cli` (the command line, clap);
//! 8. `main.rs`: the process and its exit status.

#[doc(hidden)]
pub mod analysis;
#[doc(hidden)]
pub mod bounds;
#[doc(hidden)]
pub mod cli;
#[doc(hidden)]
pub mod commands;
#[doc(hidden)]
pub mod compose;
#[doc(hidden)]
pub mod diag;
#[doc(hidden)]
pub mod diff_lines;
#[doc(hidden)]
pub mod dual;
#[doc(hidden)]
pub mod eigen;
#[doc(hidden)]
pub mod explain;
#[doc(hidden)]
pub mod expr;
#[doc(hidden)]
pub mod io;
#[doc(hidden)]
pub mod la;
#[doc(hidden)]
pub mod mass;
#[doc(hidden)]
pub mod materials;
#[doc(hidden)]
pub mod mesh;
#[doc(hidden)]
pub mod model;
#[doc(hidden)]
pub mod numeric;
#[doc(hidden)]
pub mod output;
#[doc(hidden)]
pub mod part;
#[doc(hidden)]
pub mod quantity;
#[doc(hidden)]
pub mod robot;
#[doc(hidden)]
pub mod rotation;
#[doc(hidden)]
pub mod shapes;
#[doc(hidden)]
pub mod thresholds;
#[doc(hidden)]
pub mod units;

use std::path::Path;

// The API.
pub use analysis::summary::{Accuracy, AccuracyWarning, Parts, PrecisionChoice, SiUnits, Summary};
pub use analysis::{Overrides, Products, Settings};
pub use bounds::ErrorBounds;
pub use compose::Precision;
pub use diag::{Diagnostic as Error, Place, Span};

/// Read the part file at `path` (`-` reads standard input) and compute its
/// mass properties as `settings` asks (`Settings::default()`: as
/// `massprop report FILE` computes them).
///
/// Includes are resolved against the file's directory. Errors: the file
/// cannot be read, is not a valid part file, or describes a body that is
/// not physical.
pub fn summarize(path: impl AsRef<Path>, settings: &Settings) -> Result<Summary, Error> {
    Ok(analysis::load_source(io::read_source_at(path.as_ref())?, settings)?.summary)
}

/// [`summarize`] a part file's text; `name` is what errors call it, and
/// includes are resolved against its directory (the working directory for
/// a bare file name such as `"arm.toml"`).
pub fn summarize_str(name: &str, text: &str, settings: &Settings) -> Result<Summary, Error> {
    Ok(analysis::load_source(diag::Source::new(name, text), settings)?.summary)
}

// The command's own entry points (`main.rs` and the tests).
#[doc(hidden)]
pub use analysis::{Loaded, load, load_source};
#[doc(hidden)]
pub use commands::Outcome as Output;
#[doc(hidden)]
pub use commands::{Request, run as run_request};
#[doc(hidden)]
pub use io::{MAX_FILE_BYTES, read_source};

/// Run a parsed command line (`main` and the CLI tests): `cli` turns it into
/// a `Request` of plain options, which `run_request` runs. Errors are
/// user-facing diagnostics (exit 2).
#[doc(hidden)]
pub fn run(cli: &cli::Cli) -> Result<Output, diag::Diagnostic> {
    commands::run(&cli.request(), &cli.terminal())
}
