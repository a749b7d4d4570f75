//! Why a link's inertial could not be replaced in a file, each reason's
//! wording in one `Display`, and where in the text it is (`at`), so that
//! the caller can point at `file:line:col`.

use crate::robot::Dialect;
use std::fmt;

/// Why a link's inertial could not be replaced. `at` is the byte offset of
/// the offending element (or of the XML error) in the text, for a
/// `file:line:col` diagnostic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UpdateError {
    /// The text is not well-formed XML: roxmltree's message.
    Xml { message: String, at: Option<usize> },
    /// A reference to an entity the doctype declares, which the
    /// simulators do not expand (`robot::read::entity_in_use`'s message).
    Entity { message: String, at: usize },
    /// The root element is not the format's (`<robot>`, `<sdf>`,
    /// `<mujoco>`).
    Root {
        format: Dialect,
        found: String,
        at: Option<usize>,
    },
    /// No link (MJCF: body) of that name.
    NoLink {
        format: Dialect,
        link: String,
        /// The first names in document order, at most `LISTED`.
        names: Vec<String>,
        /// How many more there are.
        more: usize,
        /// The nearest name, if one is close enough to be a typo.
        suggestion: Option<String>,
    },
    /// More than one link of that name; `at` is the second.
    Duplicate {
        format: Dialect,
        link: String,
        at: Option<usize>,
    },
    /// The link has more than one `<inertial>`; `at` is the second.
    Inertials {
        format: Dialect,
        link: String,
        at: Option<usize>,
    },
}

/// How many of the existing names a "no such link" error lists.
pub(super) const LISTED: usize = 5;

impl UpdateError {
    /// The byte offset in the text the error is about, if there is one.
    pub fn at(&self) -> Option<usize> {
        match self {
            UpdateError::Xml { at, .. }
            | UpdateError::Root { at, .. }
            | UpdateError::Duplicate { at, .. }
            | UpdateError::Inertials { at, .. } => *at,
            UpdateError::Entity { at, .. } => Some(*at),
            UpdateError::NoLink { .. } => None,
        }
    }
}

/// What a format calls a link.
pub(super) fn noun(format: Dialect) -> &'static str {
    match format {
        Dialect::Urdf | Dialect::Sdf => "link",
        Dialect::Mjcf => "body",
    }
}

/// The root element a format's files have.
pub(super) fn root_name(format: Dialect) -> &'static str {
    match format {
        Dialect::Urdf => "robot",
        Dialect::Sdf => "sdf",
        Dialect::Mjcf => "mujoco",
    }
}

impl fmt::Display for UpdateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::diag::shorten;
        match self {
            UpdateError::Xml { message, .. } => write!(f, "not well-formed XML: {message}"),
            UpdateError::Entity { message, .. } => f.write_str(message),
            UpdateError::Root { format, found, .. } => write!(
                f,
                "the root element is <{}>, not the <{}> of a {} file",
                shorten(found),
                root_name(*format),
                format.name()
            ),
            UpdateError::NoLink {
                format,
                link,
                names,
                more,
                suggestion,
            } => {
                let noun = noun(*format);
                write!(f, "no {noun} named \"{}\"", shorten(link))?;
                if names.is_empty() {
                    write!(f, ": the file has none")?;
                } else {
                    let listed: Vec<String> = names
                        .iter()
                        .map(|n| format!("\"{}\"", shorten(n)))
                        .collect();
                    write!(f, " (the file has {}", listed.join(", "))?;
                    if *more > 0 {
                        write!(f, " and {more} more")?;
                    }
                    write!(f, ")")?;
                }
                if let Some(s) = suggestion {
                    write!(f, "; did you mean \"{}\"?", shorten(s))?;
                }
                Ok(())
            }
            UpdateError::Duplicate { format, link, .. } => write!(
                f,
                "more than one {} named \"{}\"",
                noun(*format),
                shorten(link)
            ),
            UpdateError::Inertials { format, link, .. } => write!(
                f,
                "{} \"{}\" has more than one <inertial>",
                noun(*format),
                shorten(link)
            ),
        }
    }
}

impl std::error::Error for UpdateError {}
