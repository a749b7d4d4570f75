//! The values the reader reads (`Node`: its tables with each key's span,
//! and how each table was made), and their conversion into the `Raw`
//! types, or why not (`Failure`).

use super::super::raw::{
    Angles, Floats, OwnValue, Params, Quantity, RawArray, RawMirror, RawRotation, RawUnits, Vector,
};
use super::failure::{Failure, Found, Read, Valid, What};
use crate::shapes::Kind;
use std::borrow::Cow;
use std::ops::Range;
use toml::Spanned;

/// A value being read: only what part files contain.
#[derive(Clone)]
pub(super) enum Node<'i> {
    Str(Cow<'i, str>, Range<usize>),
    Num(f64, Range<usize>),
    Bool(bool, Range<usize>),
    Array(Vec<Node<'i>>, Range<usize>),
    Table(Vec<Entry<'i>>, Range<usize>, How),
    /// A value no key of a part file takes (a date-time, an integer
    /// beyond 64 bits): kept to be refused with its key.
    Other(Found, Range<usize>),
}

/// A key of a table, where the key is, and its value.
pub(super) type Entry<'i> = (Cow<'i, str>, Range<usize>, Node<'i>);

/// A key, or one part of a dotted key or header, and where it is.
pub(super) type Seg<'i> = (Cow<'i, str>, Range<usize>);

/// How a table was made, which decides what may add to it later (TOML's
/// rules): its keys, a header under it, a dotted key through it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum How {
    /// `{ .. }`: closed once written.
    Inline,
    /// By its header `[a.b]`: not to be opened again.
    Header,
    /// On the way to a header's table (`a` of `[a.b]`): a header may
    /// still define it.
    Implicit,
    /// By a dotted key (`a` of `a.b = 1`): more dotted keys of its table
    /// may add to it, no header.
    Dotted,
}

impl Node<'_> {
    pub(super) fn span(&self) -> Range<usize> {
        match self {
            Node::Str(_, s)
            | Node::Num(_, s)
            | Node::Bool(_, s)
            | Node::Array(_, s)
            | Node::Table(_, s, _)
            | Node::Other(_, s) => s.clone(),
        }
    }

    /// What it is, for a message about its type.
    fn found(&self) -> Found {
        match self {
            Node::Str(s, _) => Found::Str(s.to_string()),
            Node::Num(..) => Found::Number,
            Node::Bool(b, _) => Found::Bool(*b),
            Node::Array(..) => Found::Array,
            Node::Table(..) => Found::Table,
            Node::Other(f, _) => f.clone(),
        }
    }

    /// TOML's name of its type ("cannot extend value of type …").
    pub(super) fn type_str(&self, text: &str) -> &'static str {
        match self {
            Node::Str(..) => "string",
            Node::Num(_, s) if is_integer(&text[s.clone()]) => "integer",
            Node::Num(..) => "float",
            Node::Bool(..) => "boolean",
            Node::Array(..) => "array",
            Node::Table(_, _, How::Inline) => "inline table",
            Node::Table(..) => "table",
            Node::Other(Found::Wide, _) => "integer",
            Node::Other(..) => "datetime",
        }
    }
}

/// Whether a TOML number is written as an integer (`0x1F`, `1_000`), not
/// a float (`1.0`, `1e3`, `inf`).
pub(in crate::model) fn is_integer(literal: &str) -> bool {
    let l = literal.trim_start_matches(['+', '-']);
    l.starts_with("0x")
        || l.starts_with("0o")
        || l.starts_with("0b")
        || !l.contains(['.', 'e', 'E', 'i', 'n'])
}

/// `node` is not what `expecting` says.
pub(super) fn wrong<T>(node: &Node<'_>, expecting: &'static str) -> Read<T> {
    Err(Failure::new(
        node.span(),
        What::Type {
            key: None,
            depth: 0,
            found: node.found(),
            expecting,
            shape: None,
        },
    ))
}

/// `key` (at `span`) is none of `valid`.
pub(super) fn unknown<T>(
    key: &str,
    span: &Range<usize>,
    valid: &'static [&'static str],
) -> Read<T> {
    Err(Failure::new(
        span.clone(),
        What::Unknown {
            key: key.to_string(),
            valid: Valid::Keys(valid),
        },
    ))
}

/// What the readers of values expect, in a message.
pub(super) const QUANTITY: &str = "a number, or a string with a unit such as \"3 mm\"";
const STRING: &str = "a string";
const NUMBER: &str = "a number";
const BOOLEAN: &str = "a boolean";
const ARRAY: &str = "an array";
pub(super) const TABLE: &str = "a table";

/// Set a field once: a second value is a duplicate key (TOML finds those
/// first: only a key named twice in two spellings reaches here).
/// (`Into`: the rarely given keys of a part are boxed.)
pub(super) fn set<T, V: Into<T>>(field: &mut Option<T>, value: V, span: &Range<usize>) -> Read<()> {
    match field {
        Some(_) => Err(Failure::toml(span.clone(), "duplicate key")),
        None => {
            *field = Some(value.into());
            Ok(())
        }
    }
}

pub(super) const UNITS_KEYS: &[&str] = &["length", "mass"];

pub(super) fn units_key(
    u: &mut RawUnits,
    key: &str,
    ks: &Range<usize>,
    node: Node<'_>,
) -> Read<()> {
    match key {
        "length" => set(&mut u.length, keyed(key, string(node))?, ks),
        "mass" => set(&mut u.mass, keyed(key, string(node))?, ks),
        _ => unknown(key, ks, UNITS_KEYS),
    }
}

/// The failure of a key's value, said of that key.
pub(super) fn keyed<T>(key: &str, r: Read<T>) -> Read<T> {
    r.map_err(|f| f.at_key(key))
}

/// An array of vectors (`edges`, `vertices`, the rows of `inertia`).
pub(super) fn vectors(node: Node<'_>) -> Read<Spanned<Vec<Vector>>> {
    array_of(node, vector)
}

pub(super) fn string(node: Node<'_>) -> Read<Spanned<String>> {
    match node {
        Node::Str(s, span) => Ok(Spanned::new(span, s.into_owned())),
        other => wrong(&other, STRING),
    }
}

pub(super) fn quantity(node: Node<'_>) -> Read<Spanned<Quantity>> {
    match node {
        Node::Num(x, span) => Ok(Spanned::new(span, Quantity::Number(x))),
        Node::Str(s, span) => Ok(Spanned::new(span, Quantity::Text(s.into_owned()))),
        other => wrong(&other, QUANTITY),
    }
}

/// An array of what `item` reads.
pub(super) fn array_of<'i, T>(
    node: Node<'i>,
    item: fn(Node<'i>) -> Read<T>,
) -> Read<Spanned<Vec<T>>> {
    let Node::Array(items, span) = node else {
        return wrong(&node, ARRAY);
    };
    let items = items
        .into_iter()
        .map(|n| item(n).map_err(Failure::in_array))
        .collect::<Read<_>>()?;
    Ok(Spanned::new(span, items))
}

pub(super) fn vector(node: Node<'_>) -> Read<Vector> {
    array_of(node, quantity)
}

pub(super) fn number(node: Node<'_>) -> Read<Spanned<f64>> {
    match node {
        Node::Num(x, span) => Ok(Spanned::new(span, x)),
        other => wrong(&other, NUMBER),
    }
}

pub(super) fn floats(node: Node<'_>) -> Read<Floats> {
    array_of(node, number)
}

pub(super) const ROTATION: &str = "a rotation table such as { axis = [0, 0, 1], degrees = 90 }";
/// `[analysis] axes`'s keys: `x` and `y`, or a rotation's.
pub(super) const AXES_KEYS: &[&str] = &[
    "x",
    "y",
    "quaternion",
    "axis",
    "degrees",
    "matrix",
    "intrinsic",
    "extrinsic",
];
/// A rotation's keys (a part's `rotation`): `AXES_KEYS` but `x` and `y`.
pub(super) const ROTATION_KEYS: &[&str] = AXES_KEYS.split_at(2).1;

pub(super) fn rotation(node: Node<'_>) -> Read<Spanned<RawRotation>> {
    let Node::Table(entries, span, _) = node else {
        return wrong(&node, ROTATION);
    };
    let mut r = RawRotation::default();
    for (k, ks, v) in entries {
        match rotation_key(&mut r, &k, &ks, v)? {
            true => {}
            false => return unknown(&k, &ks, ROTATION_KEYS),
        }
    }
    Ok(Spanned::new(span, r))
}

/// One key of a rotation table (a part's `rotation`, `[analysis] axes`):
/// `false` where it is none of a rotation's.
pub(super) fn rotation_key(
    r: &mut RawRotation,
    k: &str,
    ks: &Range<usize>,
    v: Node<'_>,
) -> Read<bool> {
    keyed(k, rotation_value(r, k, ks, v))
}

fn rotation_value(r: &mut RawRotation, k: &str, ks: &Range<usize>, v: Node<'_>) -> Read<bool> {
    const ANGLES: &str = "an angle in degrees, or an array of three for Euler angles";
    match k {
        "quaternion" => set(&mut r.quaternion, floats(v)?, ks)?,
        "axis" => set(&mut r.axis, floats(v)?, ks)?,
        "degrees" => {
            let degrees = match v {
                Node::Num(x, s) => Spanned::new(s, Angles::One(x)),
                Node::Array(items, s) => {
                    let xs = items
                        .into_iter()
                        .map(|n| match n {
                            Node::Num(x, _) => Ok(x),
                            other => wrong(&other, NUMBER).map_err(Failure::in_array),
                        })
                        .collect::<Read<_>>()?;
                    Spanned::new(s, Angles::Three(xs))
                }
                other => return wrong(&other, ANGLES),
            };
            set(&mut r.degrees, degrees, ks)?
        }
        "matrix" => {
            let Node::Array(rows, s) = v else {
                return wrong(&v, ARRAY);
            };
            let rows = rows
                .into_iter()
                .map(|n| floats(n).map_err(Failure::in_array))
                .collect::<Read<_>>()?;
            set(&mut r.matrix, Spanned::new(s, rows), ks)?
        }
        "intrinsic" => set(&mut r.intrinsic, string(v)?, ks)?,
        "extrinsic" => set(&mut r.extrinsic, string(v)?, ks)?,
        _ => return Ok(false),
    }
    Ok(true)
}

/// A `RawPart` field's type as the reader reads it from a value, or why
/// not.
pub(super) trait FromNode: Sized {
    fn from_node(node: Node<'_>) -> Read<Self>;
}

impl<T: FromNode> FromNode for Box<T> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        T::from_node(node).map(Box::new)
    }
}

impl FromNode for Spanned<String> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        string(node)
    }
}

impl FromNode for Spanned<Quantity> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        quantity(node)
    }
}

impl FromNode for Vector {
    fn from_node(node: Node<'_>) -> Read<Self> {
        vector(node)
    }
}

impl FromNode for Spanned<Vec<Vector>> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        vectors(node)
    }
}

impl FromNode for Spanned<bool> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        match node {
            Node::Bool(b, span) => Ok(Spanned::new(span, b)),
            other => wrong(&other, BOOLEAN),
        }
    }
}

impl FromNode for Spanned<RawRotation> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        rotation(node)
    }
}

impl FromNode for Spanned<RawArray> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        const KEYS: &[&str] = &["count", "step", "axis", "step_degrees", "origin"];
        let (entries, span) = table(
            node,
            "a table such as { count = 4, step = [1, 0, 0] } or { count = 32, axis = [0, 0, 1], step_degrees = 11.25 }",
        )?;
        let mut a = RawArray::default();
        for (k, ks, v) in entries {
            match &*k {
                "count" => set(&mut a.count, keyed(&k, quantity(v))?, &ks),
                "step" => set(&mut a.step, keyed(&k, vector(v))?, &ks),
                "axis" => set(&mut a.axis, keyed(&k, floats(v))?, &ks),
                "step_degrees" => set(&mut a.step_degrees, keyed(&k, quantity(v))?, &ks),
                "origin" => set(&mut a.origin, keyed(&k, vector(v))?, &ks),
                _ => unknown(&k, &ks, KEYS),
            }?;
        }
        Ok(Spanned::new(span, a))
    }
}

impl FromNode for Spanned<RawMirror> {
    fn from_node(node: Node<'_>) -> Read<Self> {
        const KEYS: &[&str] = &["normal", "origin"];
        let (entries, span) = table(
            node,
            "a table such as { normal = [1, 0, 0], origin = [0, 0, 0] }",
        )?;
        let mut m = RawMirror::default();
        for (k, ks, v) in entries {
            match &*k {
                "normal" => set(&mut m.normal, keyed(&k, floats(v))?, &ks),
                "origin" => set(&mut m.origin, keyed(&k, vector(v))?, &ks),
                _ => unknown(&k, &ks, KEYS),
            }?;
        }
        Ok(Spanned::new(span, m))
    }
}

/// `[params]`, `[growth]`, an include's `params`: name → quantity, each
/// name with its span.
impl FromNode for Params {
    fn from_node(node: Node<'_>) -> Read<Self> {
        let (entries, span) = table(node, TABLE)?;
        let map = entries
            .into_iter()
            .map(|(k, ks, v)| {
                let q = keyed(&k, quantity(v))?;
                Ok((Spanned::new(ks, k.into_owned()), q))
            })
            .collect::<Read<_>>()?;
        Ok(Spanned::new(span, map))
    }
}

/// A table's entries and span; any other value is not what `expecting`
/// says.
pub(super) fn table<'i>(
    node: Node<'i>,
    expecting: &'static str,
) -> Read<(Vec<Entry<'i>>, Range<usize>)> {
    match node {
        Node::Table(entries, span, _) => Ok((entries, span)),
        other => wrong(&other, expecting),
    }
}

/// Set a field once from `node`, read as its type reads it.
pub(super) fn set_from<T: FromNode>(
    field: &mut Option<T>,
    node: Node<'_>,
    span: &Range<usize>,
) -> Read<()> {
    let value = T::from_node(node)?;
    set(field, value, span)
}

/// A shape's own key's value, read by its declared kind.
pub(super) fn own_value(kind: Kind, node: Node<'_>) -> Read<OwnValue> {
    Ok(match kind {
        Kind::Quantity => OwnValue::Quantity(quantity(node)?),
        Kind::Point | Kind::Quantities(_) => OwnValue::Quantities(vector(node)?),
        Kind::Rows { .. } => OwnValue::Rows(vectors(node)?),
        Kind::Str => OwnValue::Str(string(node)?),
        Kind::Bool => OwnValue::Bool(Spanned::<bool>::from_node(node)?),
        Kind::Rotation | Kind::ArrayTable | Kind::MirrorTable | Kind::ParamsTable => {
            // `raw::holdable`: no shape declares such an own key (tested).
            return Err(Failure::new(
                node.span(),
                What::Other("a shape's own key cannot be a table".into()),
            ));
        }
    })
}
