//! `massprop budget FILE`: the weight statement of one part file — basic
//! mass, growth by maturity and predicted mass per group, the margin
//! against the limit, and the basic and predicted bodies.

use super::Outcome;
use crate::analysis;
use crate::diag::Diagnostic;
use crate::output;

/// `report`'s options: a budget reads its file as `report` does.
pub type Options = super::report::Options;

/// Exit status 1 when a limit is given and the predicted mass exceeds it,
/// as `check`'s failed expectation (`main` maps it).
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let loaded = analysis::load(&o.file, &o.settings)?;
    let read = super::files_of(&loaded);
    let plausible = analysis::plausible::lines(&loaded.summary.warnings, terminal.stderr.colour);
    let statement = analysis::budget::statement(loaded, &o.settings)?;
    // Both bodies' warnings: the statement's own; then the file's
    // plausibility warnings.
    let stderr = super::warning_lines(
        &statement.source,
        &statement.accuracy_warnings,
        terminal.stderr.colour,
    ) + &plausible;
    let met = statement.limit.as_ref().is_none_or(|l| l.met);
    Ok(Outcome {
        stdout: super::Stdout::Text(output::render(
            &output::Output::Budget(&statement),
            o.format,
            terminal.stdout,
        )),
        stderr,
        status: if met { 0 } else { 1 },
        read,
    })
}
