//! The values the reader reads (`Node`: its tables with each key's span,
//! and how each table was made), and their conversion into the `Raw`
//! types, `None` for a value of another type.

use super::super::raw::{
    Angles, Floats, OwnValue, Params, Quantity, RawArray, RawMirror, RawRotation, RawUnits, Vector,
};
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
}

/// A key of a table, where the key is, and its value.
pub(super) type Entry<'i> = (Cow<'i, str>, Range<usize>, Node<'i>);

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
            | Node::Table(_, s, _) => s.clone(),
        }
    }
}

/// Set a field once: a second value is a duplicate key. (`Into`: the
/// rarely given keys of a part are boxed.)
pub(super) fn set<T, V: Into<T>>(field: &mut Option<T>, value: V) -> Option<()> {
    match field {
        Some(_) => None,
        None => {
            *field = Some(value.into());
            Some(())
        }
    }
}

pub(super) fn units_key(u: &mut RawUnits, key: &str, node: Node<'_>) -> Option<()> {
    match key {
        "length" => set(&mut u.length, string(node)?),
        "mass" => set(&mut u.mass, string(node)?),
        _ => None,
    }
}

/// An array of vectors (`edges`, `vertices`, the rows of `inertia`).
pub(super) fn vectors(node: Node<'_>) -> Option<Spanned<Vec<Vector>>> {
    array_of(node, vector)
}

pub(super) fn string(node: Node<'_>) -> Option<Spanned<String>> {
    match node {
        Node::Str(s, span) => Some(Spanned::new(span, s.into_owned())),
        _ => None,
    }
}

pub(super) fn quantity(node: Node<'_>) -> Option<Spanned<Quantity>> {
    match node {
        Node::Num(x, span) => Some(Spanned::new(span, Quantity::Number(x))),
        Node::Str(s, span) => Some(Spanned::new(span, Quantity::Text(s.into_owned()))),
        _ => None,
    }
}

/// An array of what `item` reads.
fn array_of<'i, T>(node: Node<'i>, item: fn(Node<'i>) -> Option<T>) -> Option<Spanned<Vec<T>>> {
    let Node::Array(items, span) = node else {
        return None;
    };
    let items = items.into_iter().map(item).collect::<Option<_>>()?;
    Some(Spanned::new(span, items))
}

pub(super) fn vector(node: Node<'_>) -> Option<Vector> {
    array_of(node, quantity)
}

pub(super) fn number(node: Node<'_>) -> Option<Spanned<f64>> {
    match node {
        Node::Num(x, span) => Some(Spanned::new(span, x)),
        _ => None,
    }
}

pub(super) fn floats(node: Node<'_>) -> Option<Floats> {
    array_of(node, number)
}

pub(super) fn rotation(node: Node<'_>) -> Option<Spanned<RawRotation>> {
    let Node::Table(entries, span, _) = node else {
        return None;
    };
    let mut r = RawRotation::default();
    for (k, _, v) in entries {
        rotation_key(&mut r, &k, v)?;
    }
    Some(Spanned::new(span, r))
}

/// One key of a rotation table (a part's `rotation`, `[analysis] axes`).
pub(super) fn rotation_key(r: &mut RawRotation, k: &str, v: Node<'_>) -> Option<()> {
    {
        match k {
            "quaternion" => set(&mut r.quaternion, floats(v)?),
            "axis" => set(&mut r.axis, floats(v)?),
            "degrees" => {
                let degrees = match v {
                    Node::Num(x, s) => Spanned::new(s, Angles::One(x)),
                    Node::Array(items, s) => {
                        let xs = items
                            .into_iter()
                            .map(|n| match n {
                                Node::Num(x, _) => Some(x),
                                _ => None,
                            })
                            .collect::<Option<_>>()?;
                        Spanned::new(s, Angles::Three(xs))
                    }
                    _ => return None,
                };
                set(&mut r.degrees, degrees)
            }
            "matrix" => {
                let Node::Array(rows, s) = v else {
                    return None;
                };
                let rows = rows.into_iter().map(floats).collect::<Option<_>>()?;
                set(&mut r.matrix, Spanned::new(s, rows))
            }
            "intrinsic" => set(&mut r.intrinsic, string(v)?),
            "extrinsic" => set(&mut r.extrinsic, string(v)?),
            _ => None,
        }
    }
}

/// A `RawPart` field's type as the reader reads it from a value; `None`
/// for a value of another type, or one it leaves to the serde path.
pub(super) trait FromNode: Sized {
    fn from_node(node: Node<'_>) -> Option<Self>;
}

impl<T: FromNode> FromNode for Box<T> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        T::from_node(node).map(Box::new)
    }
}

impl FromNode for Spanned<String> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        string(node)
    }
}

impl FromNode for Spanned<Quantity> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        quantity(node)
    }
}

impl FromNode for Vector {
    fn from_node(node: Node<'_>) -> Option<Self> {
        vector(node)
    }
}

impl FromNode for Spanned<Vec<Vector>> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        vectors(node)
    }
}

impl FromNode for Spanned<bool> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        match node {
            Node::Bool(b, span) => Some(Spanned::new(span, b)),
            _ => None,
        }
    }
}

impl FromNode for Spanned<RawRotation> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        rotation(node)
    }
}

impl FromNode for Spanned<RawArray> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        let (entries, span) = table(node)?;
        let mut a = RawArray::default();
        for (k, _, v) in entries {
            match &*k {
                "count" => set(&mut a.count, quantity(v)?),
                "step" => set(&mut a.step, vector(v)?),
                "axis" => set(&mut a.axis, floats(v)?),
                "step_degrees" => set(&mut a.step_degrees, quantity(v)?),
                "origin" => set(&mut a.origin, vector(v)?),
                _ => None,
            }?;
        }
        Some(Spanned::new(span, a))
    }
}

impl FromNode for Spanned<RawMirror> {
    fn from_node(node: Node<'_>) -> Option<Self> {
        let (entries, span) = table(node)?;
        let mut m = RawMirror::default();
        for (k, _, v) in entries {
            match &*k {
                "normal" => set(&mut m.normal, floats(v)?),
                "origin" => set(&mut m.origin, vector(v)?),
                _ => None,
            }?;
        }
        Some(Spanned::new(span, m))
    }
}

/// `[params]`, `[growth]`, an include's `params`: name → quantity, each
/// name with its span.
impl FromNode for Params {
    fn from_node(node: Node<'_>) -> Option<Self> {
        let (entries, span) = table(node)?;
        let map = entries
            .into_iter()
            .map(|(k, ks, v)| Some((Spanned::new(ks, k.into_owned()), quantity(v)?)))
            .collect::<Option<_>>()?;
        Some(Spanned::new(span, map))
    }
}

/// A table's entries and span; `None` for any other value.
pub(super) fn table(node: Node<'_>) -> Option<(Vec<Entry<'_>>, Range<usize>)> {
    match node {
        Node::Table(entries, span, _) => Some((entries, span)),
        _ => None,
    }
}

/// Set a field once from `node`, read as its type reads it.
pub(super) fn set_from<T: FromNode>(field: &mut Option<T>, node: Node<'_>) -> Option<()> {
    match field {
        Some(_) => None,
        None => {
            *field = Some(T::from_node(node)?);
            Some(())
        }
    }
}

/// A shape's own key's value, read by its declared kind.
pub(super) fn own_value(kind: Kind, node: Node<'_>) -> Option<OwnValue> {
    Some(match kind {
        Kind::Quantity => OwnValue::Quantity(quantity(node)?),
        Kind::Point | Kind::Quantities(_) => OwnValue::Quantities(vector(node)?),
        Kind::Rows { .. } => OwnValue::Rows(vectors(node)?),
        Kind::Str => OwnValue::Str(string(node)?),
        Kind::Bool => OwnValue::Bool(Spanned::<bool>::from_node(node)?),
        Kind::Rotation | Kind::ArrayTable | Kind::MirrorTable | Kind::ParamsTable => return None,
    })
}
