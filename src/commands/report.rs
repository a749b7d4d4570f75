//! `massprop report FILE`: the mass properties of one part file.

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::render::{self, Format};

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

pub fn run(o: &Options) -> Result<Outcome, Diagnostic> {
    let loaded = analysis::load(&o.file, &o.settings)?;
    let out = render::Output::Report(&loaded.summary, &loaded.source.name);
    Ok(Outcome::ok(
        render::render(&out, o.format),
        super::files_of(&loaded),
    ))
}
