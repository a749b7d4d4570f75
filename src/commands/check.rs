//! `massprop check PATH...`: every part file's expectations and physical
//! validity, for CI (docs/check.md). The run over the files is
//! `analysis::check_run`; this takes its options and renders its results.
//!
//! Exit status: 0 when everything holds, 1 when an expectation or a validity
//! check fails, 2 when any file cannot be read or is invalid; every other
//! file is still checked.

use super::Outcome;
use crate::analysis::check_run::Run;
use crate::analysis::summary::Accuracy;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::output::{self, Format};
use std::path::PathBuf;

/// How directories are searched (`--hidden`, `--exclude`).
pub use crate::analysis::search::Search;

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Part files, and directories searched for `*.toml` (`-` for
    /// standard input); any bytes, UTF-8 or not.
    pub paths: Vec<PathBuf>,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Write the computed values into the files' `[expect]` first.
    pub bless: bool,
    /// `--precision` and `--rtol`.
    pub accuracy: Accuracy,
    pub format: Format,
    /// `--axes`, as typed.
    pub axes: Option<String>,
    /// `--include-root` and `--base-dir`.
    pub includes: crate::model::Includes,
    /// How directories are searched.
    pub search: Search,
    /// The engines whose rules robot descriptions are checked by
    /// (`--engine`; all of them by default).
    pub engines: Vec<crate::robot::engine::Engine>,
    /// The table's failures and summary line only (`--quiet`).
    pub quiet: bool,
    /// `--package NAME=DIR`, as typed: a robot description's `model://`
    /// includes (`report`'s).
    pub packages: Vec<String>,
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one);
/// invalid files' errors and warnings go to standard error, in its.
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    // NOTE: `--bless` writes what the file computes into its `[expect]`;
    // under `--set` that would be a what-if's values, which the file
    // without the flag does not compute.
    if o.bless && !o.includes.set.is_empty() {
        return Err(Diagnostic::plain(
            "`--set` cannot be used with `--bless`: the expectations written would be those of the overridden parameters, not of the file",
        )
        .help("change the parameter in the file's `[params]`, then bless"));
    }
    if let Some(t) = &o.axes {
        analysis::flag_axes(t)?;
    }
    let run = Run {
        packages: super::geometry::packages(&o.packages)?,
        settings: settings(o),
        bless: o.bless,
        engines: &o.engines,
        colour: terminal.stderr.colour,
    };
    let checked = run.check(&o.paths, &o.search)?;
    Ok(Outcome {
        stdout: super::Stdout::Text(output::render(
            &output::Output::Check(&checked.results, checked.skipped, o.quiet),
            o.format,
            terminal.stdout,
        )),
        status: checked.status(),
        stderr: checked.stderr,
        read: checked.read,
    })
}

/// What the pipeline is asked for each file.
fn settings(o: &Options) -> Settings {
    Settings {
        accuracy: o.accuracy,
        includes: o.includes.clone(),
        overrides: crate::analysis::Overrides {
            axes: o.axes.clone(),
            ..Default::default()
        },
        // `predicted_*` expectations and `[budget] limit` read it.
        predicted: true,
        ..Settings::default()
    }
}
