//! Replacing one link's `<inertial>` in a robot description file, every
//! other byte kept: comments, quoting, indentation, line endings, the
//! declaration, trailing whitespace. A file under version control should
//! show a diff of the inertial alone.
//!
//! NOTE: the file is parsed (roxmltree) only to find byte ranges; the
//! result is the original text with one range replaced (or one element
//! inserted), never a re-serialised tree, which would re-quote, re-indent
//! and drop comments.

use super::error::{LISTED, UpdateError, root_name};
use super::{Export, inertial_element};
use crate::robot::Dialect;
use roxmltree::{Document, Node, ParsingOptions};
use std::ops::Range;

/// `text` with the `<inertial>` of the link (URDF, SDFormat) or body (MJCF)
/// named `link` replaced by `e`'s, or inserted as its first child when it
/// has none; every other byte as it was.
///
/// Names: a URDF `<link>` child of `<robot>`; an SDFormat `<link>` of a
/// `<model>`, a nested model's as `inner::link` (relative to the outermost
/// model, as `robot::Link` names it); a named MJCF `<body>` anywhere under
/// `<worldbody>`. The text has no byte-order mark (the caller strips and
/// re-adds it).
pub fn update(text: &str, format: Dialect, link: &str, e: &Export) -> Result<String, UpdateError> {
    update_where(text, format, link, e, None)
}

/// `update` of the link (body) whose element starts at byte `start` of
/// `text`, as the reader found it (`robot::Site::element`): a link of a
/// file the robot includes, whose name there is not the robot's. `link`
/// names it in messages.
pub fn update_at(
    text: &str,
    format: Dialect,
    start: usize,
    link: &str,
    e: &Export,
) -> Result<String, UpdateError> {
    update_where(text, format, link, e, Some(start))
}

/// `update`, the link found by its name, or by where it starts.
fn update_where(
    text: &str,
    format: Dialect,
    link: &str,
    e: &Export,
    start: Option<usize>,
) -> Result<String, UpdateError> {
    // A doctype is allowed (some exporters write one); roxmltree still
    // bounds entity expansion.
    let options = ParsingOptions {
        allow_dtd: true,
        ..ParsingOptions::default()
    };
    let doc = Document::parse_with_options(text, options).map_err(|err| {
        // The place goes in `at`, for the caller's `file:line:col`; most
        // of roxmltree's messages end with it too.
        let message = err.to_string();
        let place = format!(" at {}", err.pos());
        UpdateError::Xml {
            message: message.strip_suffix(&place).unwrap_or(&message).to_string(),
            at: Some(offset_of(text, err.pos())),
        }
    })?;
    // As the reader: a tree nested this deep is refused, before the
    // recursive walk of SDFormat models below could overflow the stack.
    if let Some(deep) = crate::robot::read::too_deep(&doc) {
        return Err(UpdateError::Xml {
            message: format!(
                "`<{}>` is nested {} elements deep: no robot description nests that deep",
                crate::diag::shorten(qname(text, deep)),
                crate::robot::read::MAX_DEPTH
            ),
            at: Some(deep.range().start),
        });
    }
    // As the reader: a reference to an entity the doctype declares is
    // refused (the simulators would not expand it).
    if let Some(e) = crate::robot::read::entity_in_use(text, &doc) {
        return Err(UpdateError::Entity {
            message: e.message(text),
            at: e.at.start,
        });
    }
    let root = doc.root_element();
    if qname(text, root) != root_name(format) {
        return Err(UpdateError::Root {
            format,
            found: qname(text, root).to_string(),
            at: Some(root.range().start),
        });
    }
    if let Some(start) = start {
        let found = doc
            .descendants()
            .find(|n| n.is_element() && n.range().start == start);
        return match found {
            Some(node) => replace(text, format, node, link, e),
            // NOTE: `start` is where the reader found the element in this
            // very text: only a file changed between the reading and the
            // writing has none there.
            None => Err(UpdateError::NoLink {
                format,
                link: link.to_string(),
                names: Vec::new(),
                more: 0,
                suggestion: None,
            }),
        };
    }
    let links = links(text, root, format);
    let mut named = links
        .iter()
        .filter(|(n, _)| n == link)
        .map(|&(_, node)| node);
    let Some(node) = named.next() else {
        let names: Vec<&str> = links.iter().map(|(n, _)| n.as_str()).collect();
        return Err(UpdateError::NoLink {
            format,
            link: link.to_string(),
            names: names.iter().take(LISTED).map(|n| n.to_string()).collect(),
            more: names.len().saturating_sub(LISTED),
            suggestion: crate::units::suggest(link, names.iter().copied()).map(str::to_string),
        });
    };
    if let Some(second) = named.next() {
        return Err(UpdateError::Duplicate {
            format,
            link: link.to_string(),
            at: Some(second.range().start),
        });
    }
    replace(text, format, node, link, e)
}

/// `text` with the `<inertial>` of the link element `node` replaced by
/// `e`'s, or inserted as its first child.
fn replace(
    text: &str,
    format: Dialect,
    node: Node,
    link: &str,
    e: &Export,
) -> Result<String, UpdateError> {
    let inertials: Vec<Node> = node
        .children()
        .filter(|c| c.is_element() && qname(text, *c) == "inertial")
        .collect();
    match inertials[..] {
        [] => Ok(insert(text, format, node, e)),
        [one] => {
            let range = one.range();
            let indent = indentation(text, range.start);
            let element = inertial_element(format, e, indent);
            let element = with_newline(&element, newline(text, range.start));
            Ok(splice(text, range, &element))
        }
        [_, second, ..] => Err(UpdateError::Inertials {
            format,
            link: link.to_string(),
            at: Some(second.range().start),
        }),
    }
}

/// The links of a document, named as `robot::Link` names them, with their
/// elements, in document order.
fn links<'a, 'i>(text: &str, root: Node<'a, 'i>, format: Dialect) -> Vec<(String, Node<'a, 'i>)> {
    let mut out = Vec::new();
    let named = |node: Node<'a, 'i>| node.attribute("name").map(str::to_string);
    match format {
        Dialect::Urdf => {
            for child in root.children().filter(|c| qname(text, *c) == "link") {
                out.extend(named(child).map(|n| (n, child)));
            }
        }
        Dialect::Sdf => {
            // Models are children of <sdf>, <world> or <model>; links
            // children of a model. Not every element is looked into: a
            // <plugin>'s contents are free-form and may say <link>. Depth
            // first in document order, with a stack of its own rather than
            // recursive calls (models nest up to read::MAX_DEPTH deep).
            // Each entry: the children still to walk, and the prefix of
            // their names (None outside every model).
            let top = |n: Node| n.children().filter(|c| qname(text, *c) == "model").count();
            let worlds = root.children().filter(|c| qname(text, *c) == "world");
            let several = top(root) + worlds.map(top).sum::<usize>() > 1;
            let mut stack = vec![(root.children(), None::<String>)];
            while let Some((children, prefix)) = stack.last_mut() {
                let Some(child) = children.next() else {
                    stack.pop();
                    continue;
                };
                let prefix = prefix.clone();
                match (qname(text, child), prefix) {
                    ("world", None) => stack.push((child.children(), None)),
                    // The outermost model's name is left out, unless the
                    // file has several (robot::read's names).
                    ("model", None) => {
                        let name = child.attribute("name").unwrap_or("");
                        let p = if several {
                            format!("{name}::")
                        } else {
                            String::new()
                        };
                        stack.push((child.children(), Some(p)));
                    }
                    ("model", Some(p)) => {
                        let name = child.attribute("name").unwrap_or("");
                        stack.push((child.children(), Some(format!("{p}{name}::"))));
                    }
                    ("link", Some(p)) => {
                        if let Some(name) = child.attribute("name") {
                            out.push((format!("{p}{name}"), child));
                        }
                    }
                    _ => {}
                }
            }
        }
        Dialect::Mjcf => {
            for world in root.children().filter(|c| qname(text, *c) == "worldbody") {
                for body in world.descendants().filter(|c| qname(text, *c) == "body") {
                    out.extend(named(body).map(|n| (n, body)));
                }
            }
        }
    }
    out
}

/// An element's name as written, prefix included (`xacro:link` is not a
/// `link`); empty for a node that is not an element.
fn qname<'t>(text: &'t str, node: Node) -> &'t str {
    if !node.is_element() {
        return "";
    }
    let tag = &text[node.range().start + 1..];
    let end = tag
        .find(|c: char| c.is_ascii_whitespace() || c == '>' || c == '/')
        .unwrap_or(tag.len());
    &tag[..end]
}

/// Insert `e`'s inertial as the first child of `link`, which has none: on
/// its own line after the start tag, one indentation step in. An empty
/// element `<link name="x"/>` is opened and closed.
fn insert(text: &str, format: Dialect, link: Node, e: &Export) -> String {
    let start = link.range().start;
    let tag_end = start_tag_end(text, start);
    let own = indentation(text, start);
    let nl = newline(text, start);
    let inner = format!("{own}{}", step(text, link));
    let element = with_newline(&inertial_element(format, e, &inner), nl);
    let opened = format!("{nl}{inner}{element}");
    if text[..tag_end].ends_with("/>") {
        // `<link name="x" />` → `<link name="x">`, then the element and
        // the end tag on a line of its own.
        let before = text[start..tag_end - 2].trim_end();
        let tag = format!("{before}>{opened}{nl}{own}</{}>", qname(text, link));
        return splice(text, start..tag_end, &tag);
    }
    // An element with nothing but spaces in it (`<link name="x"></link>`)
    // gets its end tag on a line of its own too.
    let end_tag = text[..link.range().end].rfind("</").unwrap_or(tag_end);
    let content = &text[tag_end..end_tag];
    if content.trim().is_empty() && !content.contains('\n') {
        return splice(text, tag_end..tag_end, &format!("{opened}{nl}{own}"));
    }
    splice(text, tag_end..tag_end, &opened)
}

/// The offset just past the `>` of the start tag at `start`: the first
/// `>` outside quotes (an attribute value may hold one).
fn start_tag_end(text: &str, start: usize) -> usize {
    let mut quote = None;
    for (i, b) in text.bytes().enumerate().skip(start) {
        match (quote, b) {
            (None, b'"' | b'\'') => quote = Some(b),
            (Some(q), _) if q == b => quote = None,
            (None, b'>') => return i + 1,
            _ => {}
        }
    }
    // roxmltree parsed the tag, so it is closed.
    text.len()
}

/// The indentation step the file uses at `link`: its first child
/// element's indentation beyond its own, else its own beyond its parent's,
/// else two spaces.
fn step<'t>(text: &'t str, link: Node) -> &'t str {
    let beyond = |inner: Node, outer: Node| {
        let (i, o) = (inner.range().start, outer.range().start);
        if !own_line(text, i) || !own_line(text, o) {
            return None;
        }
        indentation(text, i)
            .strip_prefix(indentation(text, o))
            .filter(|s| !s.is_empty())
    };
    link.children()
        .find(Node::is_element)
        .and_then(|child| beyond(child, link))
        .or_else(|| link.parent_element().and_then(|p| beyond(link, p)))
        .unwrap_or("  ")
}

/// The spaces and tabs that start the line `at` is on.
fn indentation(text: &str, at: usize) -> &str {
    let line = &text[line_start(text, at)..at];
    let end = line
        .find(|c: char| c != ' ' && c != '\t')
        .unwrap_or(line.len());
    &line[..end]
}

/// Whether only spaces and tabs come before `at` on its line.
fn own_line(text: &str, at: usize) -> bool {
    text[line_start(text, at)..at]
        .bytes()
        .all(|b| b == b' ' || b == b'\t')
}

fn line_start(text: &str, at: usize) -> usize {
    text[..at].rfind('\n').map_or(0, |i| i + 1)
}

/// The line ending the file uses where `at` is: that of the first line
/// break after it, else of the last before it, else `\n`. (Looked up
/// where the edit is, so that a file with mixed endings stays as mixed.)
fn newline(text: &str, at: usize) -> &'static str {
    let crlf = |i: usize| i > 0 && text.as_bytes()[i - 1] == b'\r';
    let after = text[at..].find('\n').map(|i| at + i);
    match after.or_else(|| text[..at].rfind('\n')) {
        Some(i) if crlf(i) => "\r\n",
        _ => "\n",
    }
}

/// `element` (written with `\n`) with `nl` for its line breaks.
fn with_newline(element: &str, nl: &str) -> String {
    if nl == "\n" {
        element.to_string()
    } else {
        element.replace('\n', nl)
    }
}

fn splice(text: &str, range: Range<usize>, with: &str) -> String {
    let mut out = String::with_capacity(text.len() - range.len() + with.len());
    out.push_str(&text[..range.start]);
    out.push_str(with);
    out.push_str(&text[range.end..]);
    out
}

/// The byte offset of roxmltree's row and column (1-based; the column in
/// characters), clamped to the text.
fn offset_of(text: &str, pos: roxmltree::TextPos) -> usize {
    let mut start = 0;
    for _ in 1..pos.row {
        match text[start..].find('\n') {
            Some(i) => start += i + 1,
            None => return text.len(),
        }
    }
    text[start..]
        .char_indices()
        .nth(pos.col.saturating_sub(1) as usize)
        .map_or(text.len(), |(i, _)| start + i)
}

#[cfg(test)]
#[path = "update_tests.rs"]
mod tests;
