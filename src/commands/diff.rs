//! `massprop diff OLD NEW`: two part files compared (docs/diff.md). Exit
//! status 1 when anything changed beyond the tolerance.

use super::Outcome;
use crate::analysis::diff::Diff;
use crate::analysis::summary::Accuracy;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::render::{self, Format};

#[derive(Debug, Clone)]
pub struct Options {
    pub old: String,
    pub new: String,
    pub format: Format,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Relative tolerance.
    pub tol: f64,
    /// `--precision` and `--rtol`.
    pub accuracy: Accuracy,
    /// `--axes`, as typed.
    pub axes: Option<String>,
    /// `--include-root` and `--base-dir`.
    pub includes: crate::model::Includes,
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one).
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let tol = o.tol;
    if !(tol >= 0.0 && tol.is_finite()) {
        return Err(Diagnostic::plain(format!(
            "invalid value {tol} for `--tol`: expected a finite relative tolerance ≥ 0, such as 1e-6"
        )));
    }
    if o.old == "-" && o.new == "-" {
        return Err(Diagnostic::plain(
            "OLD and NEW cannot both be `-`: standard input can be read only once",
        ));
    }
    // Tensor convention: the JSON contract of diff is fixed to it.
    let settings = Settings {
        accuracy: o.accuracy,
        includes: o.includes.clone(),
        overrides: crate::analysis::Overrides {
            axes: o.axes.clone(),
            ..Default::default()
        },
        ..Settings::default()
    };
    let old = analysis::load(&o.old, &settings)?;
    let new = analysis::load(&o.new, &settings)?;
    let read = [&old, &new].into_iter().flat_map(super::files_of).collect();
    let colour = terminal.stderr.colour;
    let stderr = super::accuracy_warnings(&old, colour) + &super::accuracy_warnings(&new, colour);
    let diff = Diff::of(old, new, tol)?;
    Ok(Outcome {
        stdout: super::Stdout::Text(render::render(
            &render::Output::Diff(&diff),
            o.format,
            terminal.stdout,
        )),
        stderr,
        status: u8::from(diff.changed),
        read,
    })
}
