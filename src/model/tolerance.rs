//! Tolerances on a part's quantities: `"700 mm ± 0.5 mm"`, `"7850 kg/m^3
//! ± 2 %"` (`+/-` for `±`), one standard deviation of a normal
//! distribution unless the tolerance ends in `uniform` (then the value
//! lies anywhere within ± the amount, σ = amount/√3). Each tolerance is a
//! source of uncertainty (`Source`); a part records how its numbers move
//! with the sources (`Dep`), for `uncertainty` to propagate.
//!
//! The keys that may carry one are those that fill a number of the part's
//! `Spec` (`slot`): its mass or density, its sizes and radii (or
//! diameters), and the points and vectors that place it. Anywhere else a
//! tolerance is an error at its `±`.

use super::Ctx;
use super::raw::Quantity;
use crate::diag::Diagnostic;
use crate::part::{Dep, Place, Slot};
use crate::shapes::Shape;
use crate::units::{self, Dim};
use std::ops::Range;
use toml::Spanned;

/// How a toleranced value is distributed about its nominal value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Spread {
    /// The amount is one standard deviation.
    Normal,
    /// The value lies anywhere within ± the amount, equally likely.
    Uniform,
}

impl Spread {
    /// The standard deviation of a tolerance of `amount`.
    pub fn sigma(self, amount: f64) -> f64 {
        match self {
            Spread::Normal => amount,
            Spread::Uniform => amount / 3f64.sqrt(),
        }
    }
}

/// One toleranced quantity in a file: an independent source of
/// uncertainty for each copy of the part that carries it.
#[derive(Debug, Clone, PartialEq)]
pub struct Source {
    /// The key it is on, with its component: `mass`, `size[1]`,
    /// `edges[0][2]`.
    pub key: String,
    /// Its amount as written (after the `±`).
    pub written: String,
    pub spread: Spread,
    /// The quantity's string in the file.
    pub span: Range<usize>,
}

/// The tolerances read while a part's numbers are read (`Ctx::spec`).
#[derive(Debug, Default)]
pub(super) struct Recorder {
    /// Whether the reader is inside a part's keys (else a tolerance is
    /// refused whatever the key).
    pub(super) in_part: bool,
    /// The row (`edges`, `vertices`) and component being read.
    pub(super) row: usize,
    pub(super) component: usize,
    readings: Vec<Reading>,
    /// The file's sources so far, in file order.
    pub(super) sources: Vec<Source>,
}

#[derive(Debug)]
struct Reading {
    key: String,
    row: usize,
    component: usize,
    /// One standard deviation, in the key's file units.
    sigma: f64,
    source: Source,
}

/// The keys of a part that fill a number of its `Spec` (a tolerance
/// anywhere else is refused).
const TOLERABLE: &[&str] = &[
    "mass",
    "density",
    "areal_density",
    "linear_density",
    "size",
    "length",
    "radius",
    "diameter",
    "inner_radius",
    "inner_diameter",
    "top_radius",
    "top_inner_radius",
    "tube_radius",
    "inner_tube_radius",
    "center",
    "corner",
    "edges",
    "from",
    "to",
    "vertices",
];

/// Whether a file's text may hold a tolerance.
pub fn may_have(text: &str) -> bool {
    text.contains('±') || text.contains("+/-")
}

/// `text` split at its tolerance: the value's text, the amount's text
/// and where the `±` (or `+/-`) starts. None without one.
pub fn split(text: &str) -> Option<(&str, &str, usize)> {
    let at = text.find('±').or_else(|| text.find("+/-"))?;
    let sign = if text[at..].starts_with('±') {
        '±'.len_utf8()
    } else {
        3
    };
    Some((text[..at].trim_end(), &text[at + sign..], at))
}

impl Ctx<'_> {
    /// The value's text of a quantity string, and its tolerance if it has
    /// one (refused where no tolerance may stand), as (amount's text,
    /// spread, whether relative, amount: a fraction if relative, else in
    /// the key's file units).
    pub(super) fn tolerance_of<'t>(
        &self,
        q: &Spanned<Quantity>,
        text: &'t str,
        key: &str,
        dim: Dim,
    ) -> Result<(&'t str, Option<Tol>), Diagnostic> {
        let Some((value, amount, at)) = split(text) else {
            return Ok((text, None));
        };
        let here = |from: usize, to: usize| {
            super::params::sub_span(&self.source.text, q.span(), text, from..to)
        };
        let allowed = self.tol.borrow().in_part && TOLERABLE.contains(&key);
        if !allowed {
            return Err(self
                .err(
                    here(at, at + (text.len() - at).min(3)),
                    format!("a tolerance is not allowed on `{key}`"),
                )
                .help("tolerances go on a part's mass, density, sizes, radii and position (docs/uncertainty.md)"));
        }
        let start = text.len() - amount.len();
        let trimmed = amount.trim();
        let (body, spread) = match trimmed.rsplit_once(char::is_whitespace) {
            Some((b, "uniform")) => (b.trim_end(), Spread::Uniform),
            Some((b, "normal")) => (b.trim_end(), Spread::Normal),
            _ => (trimmed, Spread::Normal),
        };
        let bad = |message: String| {
            self.err(here(start, text.len()), message).help(format!(
                "a tolerance is an amount of the value's unit or a percentage, then `uniform` or `normal` (the default): `± {}`, `± 2 %`, `± {} uniform`",
                dim.example().trim_matches('"'),
                dim.example().trim_matches('"'),
            ))
        };
        if value.is_empty() {
            return Err(self.err(
                here(0, at),
                format!("`{key}`: a value must stand before the tolerance"),
            ));
        }
        let (relative, x) = if let Some(p) = body.strip_suffix('%') {
            match p.trim().parse::<f64>() {
                Ok(x) => (true, x / 100.0),
                Err(_) => {
                    return Err(bad(format!(
                        "`{key}`: the tolerance {body:?} is not a percentage"
                    )));
                }
            }
        } else if let Ok(x) = body.parse::<f64>() {
            (false, x)
        } else {
            match units::parse_quantity_in(body, dim, self.units) {
                Ok(x) => (false, x),
                Err(e) => return Err(bad(format!("`{key}`: the tolerance: {e}"))),
            }
        };
        if !(x.is_finite() && x >= 0.0) {
            return Err(bad(format!(
                "`{key}`: a tolerance must be a finite amount, zero or more"
            )));
        }
        Ok((
            value,
            Some(Tol {
                written: trimmed.to_string(),
                spread,
                relative,
                amount: x,
            }),
        ))
    }

    /// Record the tolerance `tol` of the value `value` (file units) read
    /// for `key`, if a part's numbers are being recorded.
    pub(super) fn record(&self, q: &Spanned<Quantity>, key: &str, value: f64, tol: Tol) {
        let mut r = self.tol.borrow_mut();
        let amount = if tol.relative {
            tol.amount * value.abs()
        } else {
            tol.amount
        };
        let (row, component) = (r.row, r.component);
        let key_text = match key {
            "edges" | "vertices" => format!("{key}[{row}][{component}]"),
            "size" | "center" | "corner" | "from" | "to" => format!("{key}[{component}]"),
            _ => key.to_string(),
        };
        r.readings.push(Reading {
            key: key.to_string(),
            row,
            component,
            sigma: tol.spread.sigma(amount),
            source: Source {
                key: key_text,
                written: tol.written,
                spread: tol.spread,
                span: q.span(),
            },
        });
    }

    /// Start reading a part's keys: tolerances are allowed and recorded.
    pub(super) fn enter_part(&self) {
        let mut r = self.tol.borrow_mut();
        r.in_part = true;
        r.readings.clear();
    }

    /// Stop reading a part's keys, and turn what was recorded into the
    /// part's `Dep`s, its sources appended to `sources`.
    pub(super) fn leave_part(&self, shape: Shape, place: &Place) -> Option<std::sync::Arc<[Dep]>> {
        let mut guard = self.tol.borrow_mut();
        let r = &mut *guard;
        r.in_part = false;
        if r.readings.is_empty() {
            return None;
        }
        let mut deps = Vec::new();
        let sources = &mut r.sources;
        for reading in r.readings.drain(..) {
            let (slot, factor) = slot(shape, place, &reading.key, reading.row, reading.component)
                .expect("invariant: every key a tolerance is allowed on fills a slot");
            deps.push(Dep {
                slot,
                source: sources.len() as u32,
                rate: factor * reading.sigma,
            });
            sources.push(reading.source);
        }
        (!deps.is_empty()).then(|| deps.into())
    }
}

/// A tolerance read from a quantity string (see `Ctx::tolerance_of`).
#[derive(Debug, Clone)]
pub(super) struct Tol {
    written: String,
    spread: Spread,
    relative: bool,
    amount: f64,
}

/// The number of a part's `Spec` that `key` (its `row` and `component`)
/// fills, and its factor (a diameter fills a radius, halved). The one
/// map from a key to a slot.
fn slot(
    shape: Shape,
    place: &Place,
    key: &str,
    row: usize,
    component: usize,
) -> Option<(Slot, f64)> {
    let c = component.min(2) as u8;
    let r = row.min(2) as u8;
    let dim = |k: &str| {
        let keys = shape.info().dims.keys();
        keys.iter()
            .position(|x| *x == k)
            .map(|i| Slot::Dim(i as u8))
    };
    Some(match (key, place) {
        ("mass" | "density" | "areal_density" | "linear_density", _) => (Slot::Mass, 1.0),
        ("center" | "corner" | "from", _) => (Slot::At(c), 1.0),
        ("to", _) => (Slot::To(c), 1.0),
        ("edges", _) => (Slot::Edge(r, c), 1.0),
        ("vertices", _) => (Slot::Vertex(r, c), 1.0),
        ("size", _) => (Slot::Dim(c), 1.0),
        ("length", Place::Prism { .. }) => (Slot::Dim(0), 1.0),
        ("diameter", _) => (dim("radius")?, 0.5),
        ("inner_diameter", _) => (dim("inner_radius")?, 0.5),
        (k, _) => (dim(k)?, 1.0),
    })
}
