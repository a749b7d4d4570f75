//! Why the reader refused a file, as it finds out (`Failure`): enough to
//! word the error (`errors::word`) without reading the file again by
//! another parser. Two classes, as TOML and a part file's form divide
//! them: what TOML itself refuses (a key given twice, a table defined
//! twice, a dotted key through a value: `toml`), and what the form of a
//! part file refuses (an unknown key, a value of the wrong type, a missing
//! key: every other). The first of the first class is the error; else the
//! first of the second in the file.

use crate::shapes::Shape;
use std::borrow::Cow;
use std::ops::Range;

/// One refusal, where it is.
#[derive(Debug, Clone)]
pub(in crate::model) struct Failure {
    pub span: Range<usize>,
    pub what: What,
}

#[derive(Debug, Clone)]
pub(in crate::model) enum What {
    /// TOML's own rule, in TOML's words ("duplicate key", "cannot extend
    /// value of type integer with a dotted key").
    Toml(Cow<'static, str>),
    /// `[part]` (one table) where parts are `[[part]]`.
    PartTable,
    /// A key no table here takes.
    Unknown { key: String, valid: Valid },
    /// A value of the wrong type: `key` the key it belongs to (set as the
    /// failure leaves the key's value), `depth` how many arrays inside
    /// that value it is, `found` what it is, `expecting` what the
    /// innermost reader wanted.
    Type {
        key: Option<String>,
        depth: usize,
        found: Found,
        expecting: &'static str,
        /// The part's shape, where in a part (the length of `size`).
        shape: Option<Shape>,
    },
    /// A key the table needs.
    Missing(&'static str),
    /// A dotted key or header of more parts than any part file has.
    TooDeep,
    /// Anything else the form refuses, said as it is.
    Other(String),
}

/// The keys a table takes, for "did you mean" and "valid keys here".
#[derive(Debug, Clone, Copy)]
pub(in crate::model) enum Valid {
    Keys(&'static [&'static str]),
    /// A part's: those of its shape when known, else every part key.
    Part(Option<Shape>),
}

/// What a value of the wrong type is.
#[derive(Debug, Clone)]
pub(in crate::model) enum Found {
    Str(String),
    Bool(bool),
    /// A number: said as written (integer or float by its form).
    Number,
    /// An integer beyond 64 bits.
    Wide,
    DateTime,
    Array,
    Table,
}

impl Failure {
    pub fn new(span: Range<usize>, what: What) -> Self {
        Failure { span, what }
    }

    /// TOML's own refusal.
    pub fn toml(span: Range<usize>, message: impl Into<Cow<'static, str>>) -> Self {
        Failure::new(span, What::Toml(message.into()))
    }

    /// Whether TOML itself refuses it (else the form of a part file).
    pub fn is_toml(&self) -> bool {
        match self.what {
            What::Toml(_) | What::PartTable => true,
            What::Unknown { .. }
            | What::Type { .. }
            | What::Missing(_)
            | What::TooDeep
            | What::Other(_) => false,
        }
    }

    /// A wrong type met inside an array: one array deeper in its key's
    /// value.
    pub fn in_array(mut self) -> Self {
        if let What::Type {
            key: None, depth, ..
        } = &mut self.what
        {
            *depth += 1;
        }
        self
    }

    /// A wrong type in a part of `shape`.
    pub fn in_part(mut self, s: Option<Shape>) -> Self {
        if let What::Type { shape, .. } = &mut self.what {
            *shape = s;
        }
        self
    }

    /// A wrong type in the value of `key`, not yet given a key.
    pub fn at_key(mut self, k: &str) -> Self {
        if let What::Type {
            key: key @ None, ..
        } = &mut self.what
        {
            *key = Some(k.to_string());
        }
        self
    }
}

/// The reader's result: the value, or why not.
pub(in crate::model) type Read<T> = Result<T, Failure>;
