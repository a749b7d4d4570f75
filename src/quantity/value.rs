//! A quantity's numbers: borrowed in their shape (`Value`), owned
//! (`Owned`), and one of each quantity's, in the table's order (`Table`):
//! how `Summary` holds the values reported and `ErrorBounds` their bounds.

use super::{QUANTITIES, Quantity};

/// A quantity's value, or its bound, as `Summary` and `ErrorBounds` hold
/// it: its numbers in their shape, borrowed.
#[derive(Debug, Clone, Copy)]
pub enum Value<'a> {
    Scalar(f64),
    /// A vector, or an ordered triple (a set of axes' bound, an angle per
    /// axis).
    Triple(&'a [f64; 3]),
    /// A matrix's rows.
    Rows(&'a [[f64; 3]; 3]),
    /// Axes' rows and the moments flagged equal (`Info::equal`).
    Axes(&'a [[f64; 3]; 3], &'a [usize]),
}

impl Value<'_> {
    /// Component `k` (row-major for rows).
    pub fn component(self, k: usize) -> f64 {
        match self {
            Value::Scalar(x) => x,
            Value::Triple(v) => v[k],
            Value::Rows(m) | Value::Axes(m, _) => m[k / 3][k % 3],
        }
    }
}

/// Its numbers alone (a set of axes without its equal moments).
impl serde::Serialize for Value<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Value::Scalar(x) => x.serialize(s),
            Value::Triple(v) => v.serialize(s),
            Value::Rows(m) | Value::Axes(m, _) => m.serialize(s),
        }
    }
}

/// A `Value`, owned.
#[derive(Debug, Clone, PartialEq)]
pub enum Owned {
    Scalar(f64),
    Triple([f64; 3]),
    Rows([[f64; 3]; 3]),
    Axes([[f64; 3]; 3], Vec<usize>),
}

impl Owned {
    pub fn value(&self) -> Value<'_> {
        match self {
            Owned::Scalar(x) => Value::Scalar(*x),
            Owned::Triple(v) => Value::Triple(v),
            Owned::Rows(m) => Value::Rows(m),
            Owned::Axes(m, equal) => Value::Axes(m, equal),
        }
    }
}

/// One entry per quantity, at its row's position; `None` where a quantity
/// has none (not computed, not bounded).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table([Option<Owned>; QUANTITIES.len()]);

impl Table {
    pub fn get(&self, q: Quantity) -> Option<Value<'_>> {
        self.0[q as usize].as_ref().map(Owned::value)
    }

    pub fn set(&mut self, q: Quantity, v: Option<Owned>) {
        self.0[q as usize] = v;
    }

    /// Quantity `q`'s entry if it is a scalar.
    pub fn scalar(&self, q: Quantity) -> Option<f64> {
        match self.get(q)? {
            Value::Scalar(x) => Some(x),
            Value::Triple(_) | Value::Rows(_) | Value::Axes(..) => None,
        }
    }

    /// Quantity `q`'s entry if it is a triple.
    pub fn triple(&self, q: Quantity) -> Option<[f64; 3]> {
        match self.get(q)? {
            Value::Triple(v) => Some(*v),
            Value::Scalar(_) | Value::Rows(_) | Value::Axes(..) => None,
        }
    }

    /// Quantity `q`'s entry if it is rows (a matrix's, or a set of axes').
    pub fn rows(&self, q: Quantity) -> Option<[[f64; 3]; 3]> {
        match self.get(q)? {
            Value::Rows(m) | Value::Axes(m, _) => Some(*m),
            Value::Scalar(_) | Value::Triple(_) => None,
        }
    }

    /// The moments flagged equal of a set of axes.
    pub fn equal(&self, q: Quantity) -> Option<Vec<usize>> {
        match self.get(q)? {
            Value::Axes(_, equal) => Some(equal.to_vec()),
            Value::Scalar(_) | Value::Triple(_) | Value::Rows(_) => None,
        }
    }
}
