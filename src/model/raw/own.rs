//! A shape's own keys on a part (`shapes::ShapeKind::OWN_KEYS`): kept
//! generically (`OwnValue`), not as fields of `RawPart`, and read on the
//! serde path by a filter over the part table's keys (`OwnKeys`) that
//! takes each declared own key's value by its kind and hands every other
//! key to the derived code.

use super::{Quantity, RawPart, Vector};
use crate::shapes::{Key, Kind};
use serde::Deserialize;
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, Visitor};
use std::fmt;
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

impl<'de> Deserialize<'de> for RawPart {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = RawPart;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a part table with `shape`")
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<RawPart, A::Error> {
                let mut own = Own::new();
                let filtered = OwnKeys {
                    inner: map,
                    own: &mut own,
                };
                let mut p = RawPart::deserialize(de::value::MapAccessDeserializer::new(filtered))?;
                if !own.is_empty() {
                    p.own = Some(Box::new(own));
                }
                Ok(p)
            }
        }
        d.deserialize_any(V)
    }
}

/// A part table's keys with the own keys taken out into `own`.
struct OwnKeys<'o, A> {
    inner: A,
    own: &'o mut Own,
}

/// A key as the derived code reads it, or a shape's own key with the
/// derived code's seed unspent.
type Peeked<K, V> = Result<V, (&'static Key, K)>;

/// Reads a key: a shape's own key is recognised by name, any other
/// handed to the derived code's seed (its errors made inside the
/// deserializer's key, so they keep the key's place).
struct KeySeed<K>(K);

impl<'de, K: DeserializeSeed<'de>> DeserializeSeed<'de> for KeySeed<K> {
    type Value = Peeked<K, K::Value>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        struct V<K>(K);
        impl<'de, K: DeserializeSeed<'de>> Visitor<'de> for V<K> {
            type Value = Peeked<K, K::Value>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a key")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Self::Value, E> {
                match crate::shapes::own_key(s) {
                    Some(k) => Ok(Err((k, self.0))),
                    None => self
                        .0
                        .deserialize(de::value::StrDeserializer::<E>::new(s))
                        .map(Ok),
                }
            }
        }
        d.deserialize_identifier(V(self.0))
    }
}

/// Reads an own key's value by its declared kind.
struct ValueSeed(&'static Key);

impl<'de> DeserializeSeed<'de> for ValueSeed {
    type Value = OwnValue;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<OwnValue, D::Error> {
        Ok(match self.0.kind {
            Kind::Quantity => OwnValue::Quantity(Deserialize::deserialize(d)?),
            Kind::Point | Kind::Quantities(_) => OwnValue::Quantities(Deserialize::deserialize(d)?),
            Kind::Rows { .. } => OwnValue::Rows(Deserialize::deserialize(d)?),
            Kind::Str => OwnValue::Str(Deserialize::deserialize(d)?),
            Kind::Bool => OwnValue::Bool(Deserialize::deserialize(d)?),
            Kind::Rotation | Kind::ArrayTable | Kind::MirrorTable | Kind::ParamsTable => {
                return Err(de::Error::custom(format!(
                    "`{}`: a shape's own key cannot be a table",
                    self.0.name
                )));
            }
        })
    }
}

impl<'de, A: MapAccess<'de>> MapAccess<'de> for OwnKeys<'_, A> {
    type Error = A::Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        // NOTE: a seed is spent by reading a key; an own key hands the
        // derived code's back unspent, for the next key.
        let mut seed = seed;
        loop {
            match self.inner.next_key_seed(KeySeed(seed))? {
                None => return Ok(None),
                Some(Ok(v)) => return Ok(Some(v)),
                Some(Err((key, s))) => {
                    let value = self.inner.next_value_seed(ValueSeed(key))?;
                    if self.own.iter().any(|(k, _)| *k == key.name) {
                        return Err(de::Error::custom(format!("duplicate key `{}`", key.name)));
                    }
                    self.own.push((key.name, value));
                    seed = s;
                }
            }
        }
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, A::Error> {
        self.inner.next_value_seed(seed)
    }
}
