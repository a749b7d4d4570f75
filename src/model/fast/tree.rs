//! TOML's rules for where a key or a table may be written, as the reader
//! builds its tree of `Node`s: a key given twice, a table defined twice, a
//! dotted key or a header through a value, an inline table or a table
//! made the other way are refused, in the toml crate's words.

use super::failure::Failure;
use super::values::{Entry, How, Node, Seg};
use std::borrow::Cow;
use std::ops::Range;

/// Why TOML refuses a key where it is written: the key given twice, or
/// a dotted key or header through what is there (the node's type), at the
/// key's span.
pub(super) enum Refused {
    Duplicate(Range<usize>),
    Extend(Range<usize>, &'static str),
    /// Only after a syntax error (the parser reports it).
    Confused(Range<usize>),
}

impl Refused {
    /// In TOML's words (the toml crate's: "duplicate key", "cannot
    /// extend value of type integer with a dotted key").
    pub(super) fn word(self) -> Failure {
        match self {
            Refused::Duplicate(span) => Failure::toml(span, "duplicate key"),
            Refused::Extend(span, t) => Failure::toml(
                span,
                format!("cannot extend value of type {t} with a dotted key"),
            ),
            Refused::Confused(span) => Failure::toml(span, "invalid TOML here"),
        }
    }
}

/// `keys = node` (a dotted key through tables it makes) in `table`;
/// refused where TOML refuses it (no key, a key given twice, a dotted key
/// through a value or a table not its own).
pub(super) fn put<'i>(
    table: &mut Vec<Entry<'i>>,
    keys: &[Seg<'i>],
    node: Node<'i>,
    text: &str,
) -> Result<(), Refused> {
    let Some(((last, last_span), through)) = keys.split_last() else {
        return Err(Refused::Confused(node.span()));
    };
    let mut table = table;
    for (k, span) in through {
        table = descend(table, k, span, How::Dotted, text)?;
    }
    if table.iter().any(|(k, _, _)| k == last) {
        return Err(Refused::Duplicate(last_span.clone()));
    }
    table.push((last.clone(), last_span.clone(), node));
    Ok(())
}

/// The table at `path` (made by headers) below `table`.
pub(super) fn enter<'t, 'i>(
    mut table: &'t mut Vec<Entry<'i>>,
    path: &[Cow<'i, str>],
) -> Option<&'t mut Vec<Entry<'i>>> {
    for k in path {
        let i = table.iter().position(|(e, _, _)| e == k)?;
        match &mut table[i].2 {
            Node::Table(entries, _, _) => table = entries,
            // `[[case]]`'s keys go to the last table of its array.
            Node::Array(items, _) => match items.last_mut() {
                Some(Node::Table(entries, _, How::Header)) => table = entries,
                _ => return None,
            },
            _ => return None,
        }
    }
    Some(table)
}

/// The table under `key` in `table`, made `how` if there is none (its
/// span the key's, as toml gives it); refused where TOML refuses to go
/// through what is there: a value, a closed inline table, a table a
/// header defined for a dotted key, a dotted key's for a header.
fn descend<'t, 'i>(
    table: &'t mut Vec<Entry<'i>>,
    key: &Cow<'i, str>,
    span: &Range<usize>,
    how: How,
    text: &str,
) -> Result<&'t mut Vec<Entry<'i>>, Refused> {
    let i = match table.iter().position(|(e, _, _)| e == key) {
        Some(i) => i,
        None => {
            table.push((
                key.clone(),
                span.clone(),
                Node::Table(Vec::new(), span.clone(), how),
            ));
            table.len() - 1
        }
    };
    let refused = match &table[i].2 {
        Node::Table(_, _, h) if enterable(*h, how) => None,
        Node::Table(_, _, How::Inline) => Some(Refused::Extend(span.clone(), "inline table")),
        Node::Table(..) => Some(Refused::Duplicate(span.clone())),
        other => Some(Refused::Extend(span.clone(), other.type_str(text))),
    };
    match (refused, &mut table[i].2) {
        (None, Node::Table(entries, _, _)) => Ok(entries),
        (Some(r), _) => Err(r),
        (None, _) => Err(Refused::Confused(span.clone())),
    }
}

/// Whether a table made `made` may be gone through to add by `by`
/// (`How::Dotted`: a dotted key; `How::Implicit`: a header's path).
fn enterable(made: How, by: How) -> bool {
    match (made, by) {
        (How::Dotted, How::Dotted) => true,
        (How::Header | How::Implicit, How::Implicit) => true,
        (How::Inline | How::Header | How::Implicit, How::Dotted) => false,
        (How::Inline | How::Dotted, How::Implicit) => false,
        (How::Inline | How::Header | How::Implicit | How::Dotted, How::Inline | How::Header) => {
            false
        }
    }
}

/// Define the table of the header `[path]` (at `span`) below `table`;
/// refused where TOML refuses: a table defined twice, a path through a
/// value, an inline table or a dotted key's table.
pub(super) fn header_table<'i>(
    table: &mut Vec<Entry<'i>>,
    path: &[Seg<'i>],
    span: Range<usize>,
    text: &str,
) -> Result<(), Refused> {
    let Some(((last, last_span), through)) = path.split_last() else {
        return Err(Refused::Confused(span));
    };
    let mut table = table;
    for (k, s) in through {
        table = descend(table, k, s, How::Implicit, text)?;
    }
    match table.iter_mut().find(|(e, _, _)| e == last) {
        Some((_, _, Node::Table(_, s, how))) if *how == How::Implicit => {
            *s = span;
            *how = How::Header;
            Ok(())
        }
        Some(_) => Err(Refused::Duplicate(last_span.clone())),
        None => {
            table.push((
                last.clone(),
                last_span.clone(),
                Node::Table(Vec::new(), span, How::Header),
            ));
            Ok(())
        }
    }
}
