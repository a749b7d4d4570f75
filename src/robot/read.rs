//! Reading URDF, SDFormat and MJCF files into a `Description`.

use super::{Description, Format};
use crate::diag::{Diagnostic, Source};

/// Read `source` as a robot description of `format` (from `Format::of_path`
/// or `Format::of_text`).
pub fn read(source: &Source, format: Format) -> Result<Description, Diagnostic> {
    let _ = (source, format);
    Err(Diagnostic::plain("not yet"))
}
