//! `massprop explain FILE`: the worked solution of a part file, step by
//! step (`explain`), as text, markdown or LaTeX.

use super::Outcome;
use crate::analysis::{self, Settings};
use crate::diag::Diagnostic;
use crate::explain::render::Style;

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// The part file; `-` is standard input.
    pub file: String,
    pub style: Style,
    /// Products convention, `--only` and the `[analysis]` overrides.
    pub settings: Settings,
}

pub fn run(o: &Options) -> Result<Outcome, Diagnostic> {
    let loaded = analysis::load(&o.file, &o.settings)?;
    let read = super::files_of(&loaded);
    let doc = crate::explain::explain(&loaded, o.settings.products);
    Ok(Outcome::ok(
        crate::explain::render::write(&doc, o.style),
        read,
    ))
}
