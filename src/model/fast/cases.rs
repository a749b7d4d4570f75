//! `[[case]]` as the reader meets it: each header opens a table at the
//! end of the root's `case` array (`[case.expect]` a table of the case
//! still open), and the array is converted with the file's own tables
//! (`cases`) into `RawCase`s.

use super::super::raw::RawCase;
use super::Builder;
use super::failure::{Failure, Read, Valid, What};
use super::tables;
use super::tree::{Refused, header_table};
use super::values::{self, How, Node, Seg, keyed, set, string, table, unknown, wrong};
use std::ops::Range;
use toml::Spanned;

/// A case's keys, in a message.
pub(in crate::model) const CASE_KEYS: &[&str] =
    &["name", "params", "without", "without_groups", "expect"];

impl<'i> Builder<'i> {
    /// A header whose path begins `case` (at `first_span`): `[[case]]`
    /// opens a case, `[case.expect]` a table of the one open.
    pub(super) fn open_case(&mut self, span: Range<usize>, path: Vec<Seg<'i>>, is_array: bool) {
        let first_span = path[0].1.clone();
        let rest = &path[1..];
        self.close_part();
        self.tables += 1;
        let at = self.root.iter().position(|(k, _, _)| k == "case");
        if is_array {
            if let Some((k, ks)) = rest.first() {
                return self.fail(Failure::new(
                    ks.clone(),
                    What::Unknown {
                        key: k.to_string(),
                        valid: Valid::Keys(CASE_KEYS),
                    },
                ));
            }
            let made = Node::Table(Vec::new(), span.clone(), How::Header);
            match at.map(|i| &mut self.root[i].2) {
                None => self
                    .root
                    .push(("case".into(), first_span, Node::Array(vec![made], span))),
                Some(Node::Array(items, _)) if of_headers(items) => items.push(made),
                // `case = [..]` written, then a `[[case]]`: TOML refuses.
                Some(_) => return self.fail(Failure::toml(first_span, "duplicate key")),
            }
            self.at = vec!["case".into()];
            return;
        }
        let open = match at.map(|i| &mut self.root[i].2) {
            Some(Node::Array(items, _)) if of_headers(items) => items.last_mut(),
            _ => None,
        };
        let Some(Node::Table(entries, _, _)) = open else {
            let what = if rest.is_empty() {
                "`case` is an array of tables: write `[[case]]`, one header per case"
            } else {
                "a table of a case (`[case.…]`) must follow its `[[case]]`"
            };
            return self.fail(Failure::new(span, What::Other(what.into())));
        };
        let text = self.source.input();
        if let Err(f) = header_table(entries, rest, span, text).map_err(Refused::word) {
            return self.fail(f);
        }
        self.at = path.into_iter().map(|(k, _)| k).collect();
    }
}

/// Whether `items` is an array of tables made by `[[case]]` headers (an
/// array written `case = [..]` holds inline tables, closed once written).
fn of_headers(items: &[Node<'_>]) -> bool {
    matches!(items.last(), Some(Node::Table(_, _, How::Header)))
}

/// What `case` holds, in a message.
const CASES: &str = "an array of tables, each a `[[case]]` with a `name`";

/// The file's `[[case]]` tables (or `case = [{ .. }]`).
pub(super) fn cases(node: Node<'_>) -> Read<Spanned<Vec<Spanned<RawCase>>>> {
    let Node::Array(items, span) = node else {
        return wrong(&node, CASES);
    };
    let cases = items
        .into_iter()
        .map(|n| case(n).map_err(Failure::in_array))
        .collect::<Read<_>>()?;
    Ok(Spanned::new(span, cases))
}

fn case(node: Node<'_>) -> Read<Spanned<RawCase>> {
    let (entries, span) = table(node, "a case table with `name`")?;
    let mut c = RawCase::default();
    for (k, ks, v) in entries {
        match &*k {
            "name" => set(&mut c.name, keyed(&k, string(v))?, &ks),
            "params" => set(&mut c.params, keyed(&k, tables::params(v))?, &ks),
            "without" => set(&mut c.without, keyed(&k, names(v))?, &ks),
            "without_groups" => set(&mut c.without_groups, keyed(&k, names(v))?, &ks),
            "expect" => set(&mut c.expect, keyed(&k, tables::expect(v))?, &ks),
            _ => unknown(&k, &ks, CASE_KEYS),
        }?;
    }
    if c.name.is_none() {
        return Err(Failure::new(span, What::Missing("name")));
    }
    Ok(Spanned::new(span, c))
}

/// `without`, `without_groups`: an array of names.
fn names(node: Node<'_>) -> Read<Spanned<Vec<Spanned<String>>>> {
    let Node::Array(items, span) = node else {
        return values::wrong(&node, "an array of names, such as [\"pilot\"]");
    };
    let names = items
        .into_iter()
        .map(|n| string(n).map_err(Failure::in_array))
        .collect::<Read<_>>()?;
    Ok(Spanned::new(span, names))
}
