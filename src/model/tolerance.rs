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
    /// A parameter's: one variable for each instance of the file, shared
    /// by every key that uses it (else one for each copy of the part).
    pub shared: bool,
}

/// The tolerances read while a part's numbers are read (`Ctx::spec`).
#[derive(Debug, Default)]
pub(super) struct Recorder {
    /// Whether the reader is inside a part's keys (else a tolerance is
    /// refused whatever the key).
    pub(super) in_part: bool,
    /// Whether an include's `origin` is being read: its tolerances move
    /// the sub-assembly.
    in_origin: bool,
    /// Whether `[materials]` is being read: a density's tolerance is the
    /// material's, shared by every part made of it.
    pub(super) in_materials: bool,
    /// The materials with a tolerance: name → (source, σ relative).
    materials: std::collections::BTreeMap<String, (u32, f64)>,
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
    /// ∂value/∂z in the key's file units: one standard deviation of its
    /// own tolerance, or its derivative by a parameter's source.
    rate: f64,
    origin: Origin,
}

/// Where a reading's source is: its own tolerance, or a parameter's.
#[derive(Debug)]
enum Origin {
    New(Source),
    Shared(u32),
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
    "origin",
];

/// The key of a given mass's tolerance, beside `mass`.
pub const TOL_KEY: &str = "tol";

/// Whether a part whose shape takes `keys` takes `key`: its own keys, and
/// `tol` wherever `mass` is one (the one rule, for the reader and the
/// schema).
pub fn accepts(keys: &[&str], key: &str) -> bool {
    keys.contains(&key) || (key == TOL_KEY && keys.contains(&"mass"))
}

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
    /// one (refused where no tolerance may stand: outside a part's keys
    /// that fill its numbers, `TOLERABLE`).
    pub(super) fn tolerance_of<'t>(
        &self,
        q: &Spanned<Quantity>,
        text: &'t str,
        key: &str,
        dim: Dim,
    ) -> Result<(&'t str, Option<Tol>), Diagnostic> {
        let Some((value, _, at)) = split(text) else {
            return Ok((text, None));
        };
        let allowed = {
            let r = self.tol.borrow();
            (r.in_part && TOLERABLE.contains(&key))
                || r.in_materials
                || (r.in_origin && key == "origin")
        };
        if !allowed {
            return Err(self.not_allowed(self.source, q.span(), text, at, key));
        }
        let tol = self.amount(self.source, q.span(), text, dim, key)?;
        Ok((value, Some(tol)))
    }

    /// The error for a tolerance at byte `at` of `text` (the string at
    /// `span` of `source`) where none may stand.
    pub(super) fn not_allowed(
        &self,
        source: &crate::diag::Source,
        span: Range<usize>,
        text: &str,
        at: usize,
        key: &str,
    ) -> Diagnostic {
        let here =
            super::params::sub_span(&source.text, span, text, at..at + (text.len() - at).min(3));
        source
            .error(here, format!("a tolerance is not allowed on `{key}`"))
            .help("tolerances go on a part's mass, density, sizes, radii and position, and on `[params]` (docs/uncertainty.md)")
    }

    /// The tolerance just read for material `name`'s density (`file`, in
    /// the file's units), if it has one, as a source shared by every part
    /// made of it.
    pub(super) fn material_tolerance(&self, name: &str, file: f64) {
        let mut guard = self.tol.borrow_mut();
        let r = &mut *guard;
        let Some(reading) = r.readings.pop() else {
            return;
        };
        let Origin::New(mut source) = reading.origin else {
            return;
        };
        source.key = format!("material `{name}`");
        source.shared = true;
        r.sources.push(source);
        let k = (r.sources.len() - 1) as u32;
        r.materials
            .insert(name.to_string(), (k, reading.rate / file));
    }

    /// Record how a part made of a material with a tolerance moves with
    /// it: its density (`spec`'s, the material's made the shape's) in the
    /// same ratio.
    pub(super) fn record_material(&self, p: &super::raw::RawPart, spec: &crate::part::Spec) {
        let (Some(name), crate::part::MassSpec::Density(d)) = (&p.material, spec.mass) else {
            return;
        };
        let mut r = self.tol.borrow_mut();
        let Some(&(k, rel)) = r.materials.get(name.get_ref()) else {
            return;
        };
        r.readings.push(Reading {
            key: "material".to_string(),
            row: 0,
            component: 0,
            rate: d * rel,
            origin: Origin::Shared(k),
        });
    }

    /// Start reading an include's `origin`: its tolerances are recorded.
    pub(super) fn enter_origin(&self) {
        let mut r = self.tol.borrow_mut();
        r.in_origin = true;
        r.readings.clear();
    }

    /// Stop reading an include's `origin`, and turn its tolerances into
    /// `Dep`s on the point (`Slot::At`), its sources appended.
    pub(super) fn leave_origin(&self) -> Option<std::sync::Arc<[Dep]>> {
        let mut guard = self.tol.borrow_mut();
        let r = &mut *guard;
        r.in_origin = false;
        let deps = r.readings.drain(..).map(|reading| {
            let source = match reading.origin {
                Origin::New(s) => {
                    r.sources.push(s);
                    (r.sources.len() - 1) as u32
                }
                Origin::Shared(k) => k,
            };
            Dep {
                slot: Slot::At(reading.component.min(2) as u8),
                source,
                rate: reading.rate,
            }
        });
        let deps: Vec<Dep> = deps.collect();
        (!deps.is_empty()).then(|| deps.into())
    }

    /// Refuse `tol` on a part without `mass` (a density's tolerance goes
    /// in its string).
    pub(super) fn tol_needs_mass(&self, p: &super::raw::RawPart) -> Result<(), Diagnostic> {
        match (&p.tol, &p.mass) {
            (Some(t), None) => Err(self
                .err(t.span(), "`tol` is the tolerance of `mass`, and this part gives none")
                .help("a density's or a size's tolerance goes in its string: `density = \"7850 kg/m^3 ± 2 %\"`")),
            _ => Ok(()),
        }
    }

    /// The given mass (file units) of a part with `mass` = `m`, its
    /// tolerance recorded: in the string, or `tol` beside it (not both).
    pub(super) fn mass_with_tol(
        &self,
        p: &super::raw::RawPart,
        m: &Spanned<Quantity>,
    ) -> Result<f64, Diagnostic> {
        let value = self.file_quantity(m, "mass", Dim::MASS)?;
        let Some(tol) = p.tol.as_deref() else {
            return Ok(value);
        };
        if matches!(m.get_ref(), Quantity::Text(t) if split(t).is_some()) {
            return Err(self.err(
                tol.span(),
                "`tol` conflicts with the tolerance in `mass`: give one",
            ));
        }
        let t = match tol.get_ref() {
            Quantity::Number(x) => {
                if !(x.is_finite() && *x >= 0.0) {
                    return Err(self.err(
                        tol.span(),
                        "`tol`: a tolerance must be a finite amount, zero or more",
                    ));
                }
                Tol {
                    written: format!("{x}"),
                    spread: Spread::Normal,
                    relative: false,
                    amount: self.units.factor(Dim::MASS).apply(*x),
                }
            }
            Quantity::Text(text) => {
                let body = text.trim_start();
                let sign = ["±", "+/-"]
                    .iter()
                    .find_map(|s| body.strip_prefix(s).map(|_| s.len()))
                    .unwrap_or(0);
                let start = text.len() - body.len() + sign;
                let at = Written {
                    source: self.source,
                    span: tol.span(),
                    text,
                };
                self.amount_at(&at, start, None, Dim::MASS, "tol")?
            }
        };
        self.record(m, "mass", Dim::MASS, value, t);
        Ok(value)
    }

    /// The tolerance of `text` (which has one: `split`), the string at
    /// `span` of `source`, for a value of dimension `dim`: its amount in
    /// SI, or a fraction if relative.
    pub(super) fn amount(
        &self,
        source: &crate::diag::Source,
        span: Range<usize>,
        text: &str,
        dim: Dim,
        key: &str,
    ) -> Result<Tol, Diagnostic> {
        let (value, amount, at) = split(text).expect("invariant: the text has a tolerance");
        let start = text.len() - amount.len();
        let written = Written { source, span, text };
        self.amount_at(&written, start, Some((value, at)), dim, key)
    }

    /// The amount of a tolerance that starts at byte `start` of the
    /// string (after the value and its `±` at `before`, if it has them).
    fn amount_at(
        &self,
        w: &Written<'_>,
        start: usize,
        before: Option<(&str, usize)>,
        dim: Dim,
        key: &str,
    ) -> Result<Tol, Diagnostic> {
        let (source, span, text) = (w.source, w.span.clone(), w.text);
        // The amount's first character, past the spaces after `±`.
        let start = start + (text.len() - start - text[start..].trim_start().len());
        let amount = &text[start..];
        let here = |from: usize, to: usize| {
            super::params::sub_span(&source.text, span.clone(), text, from..to)
        };
        let trimmed = amount.trim();
        let (body, spread) = match trimmed.rsplit_once(char::is_whitespace) {
            Some((b, "uniform")) => (b.trim_end(), Spread::Uniform),
            Some((b, "normal")) => (b.trim_end(), Spread::Normal),
            _ => (trimmed, Spread::Normal),
        };
        let example = dim.example();
        let example = example.trim_matches('"');
        let bad = |message: String| {
            source.error(here(start, text.len()), message).help(format!(
                "a tolerance is an amount of the value's unit or a percentage, then `uniform` or `normal` (the default): `± {example}`, `± 2 %`, `± {example} uniform`"
            ))
        };
        if let Some(("", at)) = before {
            return Err(source.error(
                here(0, at.max(1)),
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
            (false, self.units.factor(dim).apply(x))
        } else {
            match units::parse_quantity(body, dim) {
                Ok(x) => (false, x),
                Err(e) => return Err(bad(format!("`{key}`: the tolerance: {e}"))),
            }
        };
        if !(x.is_finite() && x >= 0.0) {
            return Err(bad(format!(
                "`{key}`: a tolerance must be a finite amount, zero or more"
            )));
        }
        Ok(Tol {
            written: trimmed.to_string(),
            spread,
            relative,
            amount: x,
        })
    }

    /// Record the tolerance `tol` of the value `value` (file units) read
    /// for `key`, if a part's numbers are being recorded.
    pub(super) fn record(&self, q: &Spanned<Quantity>, key: &str, dim: Dim, value: f64, tol: Tol) {
        let mut r = self.tol.borrow_mut();
        // In the key's file units, as `value`.
        let amount = if tol.relative {
            tol.amount * value.abs()
        } else {
            tol.amount / self.units.factor(dim).value()
        };
        let (row, component) = (r.row, r.component);
        let key_text = match key {
            "edges" | "vertices" => format!("{key}[{row}][{component}]"),
            "size" | "center" | "corner" | "from" | "to" | "origin" => {
                format!("{key}[{component}]")
            }
            _ => key.to_string(),
        };
        r.readings.push(Reading {
            key: key.to_string(),
            row,
            component,
            rate: tol.spread.sigma(amount),
            origin: Origin::New(Source {
                key: key_text,
                written: tol.written,
                spread: tol.spread,
                span: q.span(),
                shared: false,
            }),
        });
    }

    /// Record how the value read for `key` moves with the sources of the
    /// parameters its expression uses: `grad` in SI, `factor` the key's
    /// unit (refused where no tolerance may stand).
    /// Refuse a value that moves with a parameter's tolerance (`grad`,
    /// not empty) where no tolerance may stand, or where it has no
    /// derivative.
    pub(super) fn tolerable_grad(
        &self,
        q: &Spanned<Quantity>,
        key: &str,
        grad: &crate::expr::tangent::Grad,
    ) -> Result<(), Diagnostic> {
        let r = self.tol.borrow();
        if !((r.in_part && TOLERABLE.contains(&key)) || (r.in_origin && key == "origin")) {
            let names = r.sources[grad[0].0 as usize].key.clone();
            return Err(self
                .err(
                    q.span(),
                    format!("`{key}` uses a parameter with a tolerance ({names}), and a tolerance is not allowed on `{key}`"),
                )
                .help("tolerances go on a part's mass, density, sizes, radii and position (docs/uncertainty.md)"));
        }
        if grad.iter().any(|(_, d)| !d.is_finite()) {
            return Err(self.err(
                q.span(),
                format!("`{key}` has no derivative by its parameters' tolerances here (a square root of 0?)"),
            ));
        }
        Ok(())
    }

    /// Record how the value read for `key` moves with the sources of the
    /// parameters its expression uses (`grad`, in the key's file units).
    pub(super) fn record_grad(&self, key: &str, grad: &crate::expr::tangent::Grad) {
        let mut r = self.tol.borrow_mut();
        let (row, component) = (r.row, r.component);
        for &(source, d) in grad {
            r.readings.push(Reading {
                key: key.to_string(),
                row,
                component,
                rate: d,
                origin: Origin::Shared(source),
            });
        }
    }

    /// A parameter's own tolerance as a source shared by every key that
    /// uses it, in this instance of the file; its index.
    pub(super) fn shared_source(&self, name: &str, span: Range<usize>, tol: &Tol) -> u32 {
        let mut r = self.tol.borrow_mut();
        r.sources.push(Source {
            key: format!("param `{name}`"),
            written: tol.written.clone(),
            spread: tol.spread,
            span,
            shared: true,
        });
        (r.sources.len() - 1) as u32
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
            let source = match reading.origin {
                Origin::New(s) => {
                    sources.push(s);
                    (sources.len() - 1) as u32
                }
                Origin::Shared(k) => k,
            };
            deps.push(Dep {
                slot,
                source,
                rate: factor * reading.rate,
            });
        }
        (!deps.is_empty()).then(|| deps.into())
    }
}

/// A string as written: its text, and where it is.
struct Written<'a> {
    source: &'a crate::diag::Source,
    span: Range<usize>,
    text: &'a str,
}

/// A tolerance read from a quantity string (see `Ctx::amount`).
#[derive(Debug, Clone)]
pub(super) struct Tol {
    written: String,
    spread: Spread,
    relative: bool,
    /// SI, or a fraction of the value if `relative`.
    amount: f64,
}

impl Tol {
    /// One standard deviation for a value `value` (SI).
    pub(super) fn sigma_of(&self, value: f64) -> f64 {
        let amount = if self.relative {
            self.amount * value.abs()
        } else {
            self.amount
        };
        self.spread.sigma(amount)
    }
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
        ("mass" | "density" | "areal_density" | "linear_density" | "material", _) => {
            (Slot::Mass, 1.0)
        }
        ("center" | "corner" | "from" | "origin", _) => (Slot::At(c), 1.0),
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
