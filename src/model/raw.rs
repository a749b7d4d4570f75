//! The part file exactly as written: a serde mirror with every value
//! `Spanned`, so the conversion step in `model` can point at it.
//!
//! NOTE: parts are one *flat* struct with `shape` as a string, not a
//! `#[serde(tag = "shape")]` enum: with toml, internally tagged enums lose
//! error positions and let unknown keys through. Which keys apply to which
//! shape is checked in `model`.

use serde::Deserialize;
use serde::de::{self, Deserializer, Visitor};
use std::fmt;
use toml::Spanned;

/// An array of quantities, e.g. `center = [0, "5 mm", 1]`.
pub type Vector = Spanned<Vec<Spanned<Quantity>>>;
/// An array of plain numbers (rotation parameters carry no unit).
pub type Floats = Spanned<Vec<Spanned<f64>>>;

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields, expecting = "a part file")]
pub struct RawFile {
    pub name: Option<Spanned<String>>,
    pub units: Option<Spanned<RawUnits>>,
    pub part: Option<Spanned<Vec<Spanned<RawPart>>>>,
    pub analysis: Option<Spanned<RawAnalysis>>,
}

#[derive(Deserialize, Debug)]
#[serde(
    deny_unknown_fields,
    expecting = "a table such as { length = \"mm\", mass = \"kg\" }"
)]
pub struct RawUnits {
    pub length: Option<Spanned<String>>,
    pub mass: Option<Spanned<String>>,
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields, expecting = "a part table with `shape`")]
pub struct RawPart {
    pub name: Option<Spanned<String>>,
    pub shape: Spanned<String>,
    pub mass: Option<Spanned<Quantity>>,
    pub density: Option<Spanned<Quantity>>,
    pub areal_density: Option<Spanned<Quantity>>,
    pub linear_density: Option<Spanned<Quantity>>,
    pub size: Option<Vector>,
    pub length: Option<Spanned<Quantity>>,
    pub center: Option<Vector>,
    pub rotation: Option<Spanned<RawRotation>>,
    pub corner: Option<Vector>,
    pub edges: Option<Spanned<Vec<Vector>>>,
    pub from: Option<Vector>,
    pub to: Option<Vector>,
}

#[derive(Deserialize, Debug)]
#[serde(
    deny_unknown_fields,
    expecting = "a rotation table such as { axis = [0, 0, 1], degrees = 90 }"
)]
pub struct RawRotation {
    pub quaternion: Option<Floats>,
    pub axis: Option<Floats>,
    pub degrees: Option<Spanned<Angles>>,
    pub matrix: Option<Spanned<Vec<Floats>>>,
    pub intrinsic: Option<Spanned<String>>,
    pub extrinsic: Option<Spanned<String>>,
}

#[derive(Deserialize, Debug)]
#[serde(
    deny_unknown_fields,
    expecting = "a table with `about`, `omega` or `alpha`"
)]
pub struct RawAnalysis {
    pub about: Option<Vector>,
    pub omega: Option<Vector>,
    pub alpha: Option<Vector>,
}

/// A number in the file's units, or a string with its own unit (`"3 mm"`).
#[derive(Debug, Clone, PartialEq)]
pub enum Quantity {
    Number(f64),
    Text(String),
}

impl<'de> Deserialize<'de> for Quantity {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Quantity;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number, or a string with a unit such as \"3 mm\"")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Quantity, E> {
                Ok(Quantity::Number(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Quantity, E> {
                Ok(Quantity::Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Quantity, E> {
                Ok(Quantity::Number(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Quantity, E> {
                Ok(Quantity::Text(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

/// `degrees`: one angle (axis–angle) or three (Euler angles).
#[derive(Debug, Clone, PartialEq)]
pub enum Angles {
    One(f64),
    Three(Vec<f64>),
}

impl<'de> Deserialize<'de> for Angles {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Angles;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an angle in degrees, or an array of three for Euler angles")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Angles, E> {
                Ok(Angles::One(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Angles, E> {
                Ok(Angles::One(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Angles, E> {
                Ok(Angles::One(v as f64))
            }
            fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Angles, A::Error> {
                let mut out = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    out.push(x);
                }
                Ok(Angles::Three(out))
            }
        }
        d.deserialize_any(V)
    }
}
