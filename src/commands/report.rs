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
    /// Every table (`--full`), not the short report's essentials.
    pub full: bool,
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
            detail: crate::output::report::Detail {
                full: o.full,
                // A reference point the command line gives was asked for:
                // its tensors are shown (one in the file is for H, T, M).
                about_flag: o.settings.overrides.about.is_some(),
            },
            style: terminal.stdout,
        },
        stderr,
        status: 0,
        read,
    })
}
