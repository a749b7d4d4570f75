//! `massprop diff OLD NEW`: the mass properties of two part files side by
//! side, with absolute and relative changes, and what happened to each part.

use crate::Output;
use crate::cli::DiffArgs;
use crate::diag::Diagnostic;

pub fn run(args: &DiffArgs) -> Result<Output, Diagnostic> {
    Err(Diagnostic::plain(format!(
        "`diff` of {} and {} is not built yet",
        args.old, args.new
    )))
}
