//! A shape's own keys on a part (`shapes::ShapeKind::OWN_KEYS`): kept
//! generically (`OwnValue`), not as fields of `RawPart`; the reader reads
//! each by its declared kind (`fast::values::own_value`).

use super::{Quantity, Vector};
use crate::shapes::Kind;
use toml::Spanned;

/// The value of a shape's own key, as its declaration's kind reads it.
#[derive(Debug, Clone, PartialEq)]
pub enum OwnValue {
    /// `Kind::Quantity`.
    Quantity(Spanned<Quantity>),
    /// `Kind::Point` and `Kind::Quantities`.
    Quantities(Vector),
    /// `Kind::Rows`.
    Rows(Spanned<Vec<Vector>>),
    /// `Kind::Str`.
    Str(Spanned<String>),
    /// `Kind::Bool`.
    Bool(Spanned<bool>),
}

impl OwnValue {
    pub fn span(&self) -> std::ops::Range<usize> {
        match self {
            OwnValue::Quantity(v) => v.span(),
            OwnValue::Quantities(v) => v.span(),
            OwnValue::Rows(v) => v.span(),
            OwnValue::Str(v) => v.span(),
            OwnValue::Bool(v) => v.span(),
        }
    }
}

/// A part's own keys, in the order written.
pub type Own = Vec<(&'static str, OwnValue)>;

/// Whether a shape's own key may be of `kind`: the kinds `OwnValue`
/// holds (tables are the common keys').
pub fn holdable(kind: Kind) -> bool {
    match kind {
        Kind::Quantity | Kind::Point | Kind::Quantities(_) | Kind::Rows { .. } => true,
        Kind::Str | Kind::Bool => true,
        Kind::Rotation | Kind::ArrayTable | Kind::MirrorTable | Kind::ParamsTable => false,
    }
}
