//! `massprop report FILE`: the mass properties of one part file.

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::output::Format;

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// The part file; `-` is standard input.
    pub file: String,
    pub format: Format,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Products convention, precision, `--only` and the `[analysis]`
    /// overrides.
    pub settings: Settings,
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one).
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let loaded = analysis::load(&o.file, &o.settings)?;
    let read = super::files_of(&loaded);
    let stderr = super::accuracy_warnings(&loaded, terminal.stderr.colour);
    Ok(Outcome {
        stdout: super::Stdout::Report {
            summary: Box::new(loaded.summary),
            source: loaded.source.name,
            format: o.format,
            style: terminal.stdout,
        },
        stderr,
        status: 0,
        read,
    })
}
