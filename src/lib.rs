//! massprop: mass properties of composite rigid bodies from TOML part files.
//!
//! The modules, from the bottom up (each uses only those above it; the
//! full list with each module's job is docs/architecture.md):
//!
//! 1. numbers, units, diagnostics: `numeric`, `eigen`, `tolerance`,
//!    `units`, `diag`, `io`;
//! 2. shapes and parts: `shapes` (one description per shape and the closed
//!    forms), `rotation` (the forms of a part's turn), `part` (a part and
//!    its physics), `materials`;
//! 3. the model: `model` (the part file read and validated);
//! 4. composition and principal axes: `compose`, `mass`;
//! 5. analysis: `analysis` (the one load pipeline; summary, checks, diff);
//! 6. rendering: `render` (tables and JSON);
//! 7. commands: `commands`, and `cli` (the command line, clap);
//! 8. `main.rs`: the process and its exit status.

pub mod analysis;
pub mod bounds;
pub mod cli;
pub mod commands;
pub mod compose;
pub mod diag;
pub mod eigen;
pub mod io;
pub mod mass;
pub mod materials;
pub mod model;
pub mod numeric;
pub mod part;
pub mod render;
pub mod rotation;
pub mod shapes;
pub mod tolerance;
pub mod units;

// The API: the load pipeline every command runs, and the commands.
pub use analysis::{Loaded, Overrides, Products, Settings, load, load_source};
pub use commands::Outcome as Output;
pub use commands::{Request, run as run_request};
pub use io::{MAX_FILE_BYTES, read_source};

/// Run a parsed command line (`main` and the CLI tests): `cli` turns it into
/// a `Request` of plain options, which `run_request` runs. Errors are
/// user-facing diagnostics (exit 2).
pub fn run(cli: &cli::Cli) -> Result<Output, diag::Diagnostic> {
    commands::run(&cli.request(), &cli.terminal())
}
