//! Tolerances on a part's quantities: `"700 mm ± 0.5 mm"`, `"7850 kg/m^3
//! ± 2 %"` (`+/-` for `±`), one standard deviation of a normal
//! distribution unless the tolerance ends in `uniform` (then the value
//! lies anywhere within ± the amount, σ = amount/√3). Each tolerance is a
//! source of uncertainty (`Toleranced`); a part records how its numbers move
//! with the sources (`Dep`), for `uncertainty` to propagate.
//!
//! The keys that may carry one are those that fill a number of the part's
//! `Spec` (`slot`): its mass or density, its sizes and radii (or
//! diameters), and the points and vectors that place it. Anywhere else a
//! tolerance is an error at its `±`.

use super::Ctx;
use super::raw::Quantity;
use crate::diag::Diagnostic;
use crate::part::{Dep, Slot};
use crate::shapes::{Key, Shape};
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
pub struct Toleranced {
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

/// Where a value stands in its key: the row of a list of points
/// (`edges`, `vertices`) and the component of a vector (0 for a scalar).
/// An argument of each reading, which names and places a tolerance on it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(super) struct Index {
    pub row: usize,
    pub component: usize,
}

impl Index {
    /// A scalar's (or the first component of the first row).
    pub const SCALAR: Index = Index {
        row: 0,
        component: 0,
    };

    /// Component `component` of a vector.
    pub fn component(component: usize) -> Index {
        Index { row: 0, component }
    }
}

/// The tolerances read while a file's numbers are read: owned by the
/// file's conversion and passed as `&mut` to whatever records one (a
/// part's reader holds it while it reads the part), as `&` where a
/// reading only needs to know whether a tolerance may stand, or to name
/// a parameter's source in an error.
#[derive(Debug, Default)]
pub(super) struct Recorder {
    /// The shape of the part whose keys are being read, if any (else a
    /// tolerance is refused on a part key), and the keys any part may
    /// have (`keys::COMMON`, handed in: the registry reads through this
    /// module), whose declarations say what a "±" on them moves.
    part: Option<Part>,
    /// Whether an include's `origin` is being read: its tolerances move
    /// the sub-assembly.
    in_origin: bool,
    /// Whether `[materials]` is being read: a density's tolerance is the
    /// material's, shared by every part made of it.
    pub(super) in_materials: bool,
    /// The materials with a tolerance: name → (source, rate relative to
    /// the density) for each source it moves with.
    materials: std::collections::BTreeMap<String, Vec<(u32, f64)>>,
    readings: Vec<Reading>,
    /// The file's sources so far, in file order.
    pub(super) sources: Vec<Toleranced>,
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
    New(Toleranced),
    Shared(u32),
}

/// The key of a given mass's tolerance, beside `mass`.
pub const TOL_KEY: &str = "tol";

/// Whether a part whose shape takes `keys` takes `key`: its own keys, and
/// `tol` wherever `mass` is one (the one rule, for the reader and the
/// schema).
pub fn accepts(keys: &[&str], key: &str) -> bool {
    keys.contains(&key) || (key == TOL_KEY && keys.contains(&"mass"))
}

/// Where a tolerance may stand, for the help of an error.
const TOLERANCES_GO: &str = "tolerances go on a part's mass, density, sizes, radii and position, a sub-assembly's `origin`, `[params]` and `[materials]` densities (docs/uncertainty.md)";

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

impl Recorder {
    /// The slot `key` fills where a tolerance may stand on it: a part's
    /// key that fills a number of its `Spec`, an include's `origin`, a
    /// material's density (no slot of a part: `Slot::Mass` stands for it).
    pub(super) fn allows(&self, key: &str, at: Index) -> Option<Slot> {
        let Index { row, component } = at;
        if let Some(part) = self.part {
            return slot(Some(part), key, row, component).map(|s| s.0);
        }
        if self.in_origin {
            return slot(None, key, row, component).map(|s| s.0);
        }
        self.in_materials.then_some(Slot::Mass)
    }
}

impl Ctx<'_> {
    /// The value's text of a quantity string, and its tolerance if it has
    /// one (refused where no tolerance may stand: `Recorder::allows`; a
    /// percentage of a point's coordinate, which depends on where the
    /// origin is).
    pub(super) fn tolerance_of<'t>(
        &self,
        rec: &Recorder,
        at_index: Index,
        q: &Spanned<Quantity>,
        text: &'t str,
        key: &str,
        dim: Dim,
    ) -> Result<(&'t str, Option<Tol>), Diagnostic> {
        let Some((value, _, at)) = split(text) else {
            return Ok((text, None));
        };
        let Some(slot) = rec.allows(key, at_index) else {
            return Err(self.not_allowed(self.source, q.span(), text, at, key));
        };
        let tol = self.amount(self.source, q.span(), text, dim, key)?;
        if tol.relative && slot.is_point() {
            return Err(self
                .err(
                    q.span(),
                    format!("`{key}`: a percentage of a coordinate depends on where the origin is"),
                )
                .help("give the tolerance of a position as a length: `± 0.5 mm`"));
        }
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
            super::span::sub_span(&source.text, span, text, at..at + (text.len() - at).min(3));
        source
            .error(here, format!("a tolerance is not allowed on `{key}`"))
            .help(TOLERANCES_GO)
    }
}

impl Recorder {
    /// The tolerance just read for material `name`'s density (`file`, in
    /// the file's units), if it has one, as a source shared by every part
    /// made of it.
    pub(super) fn material_tolerance(&mut self, name: &str, file: f64) {
        let r = self;
        let mut moves = Vec::new();
        for reading in r.readings.drain(..) {
            let k = match reading.origin {
                Origin::New(mut source) => {
                    source.key = format!("material `{name}`");
                    source.shared = true;
                    r.sources.push(source);
                    (r.sources.len() - 1) as u32
                }
                Origin::Shared(k) => k,
            };
            moves.push((k, reading.rate / file));
        }
        if !moves.is_empty() {
            r.materials.insert(name.to_string(), moves);
        }
    }

    /// Record how a part made of a material with a tolerance moves with
    /// it: its density (`spec`'s, the material's made the shape's) in the
    /// same ratio.
    pub(super) fn record_material(&mut self, p: &super::raw::RawPart, spec: &crate::part::Spec) {
        let (Some(name), crate::part::MassSpec::Density(d)) = (&p.material, spec.mass) else {
            return;
        };
        let r = self;
        let Some(moves) = r.materials.get(name.get_ref()) else {
            return;
        };
        for &(k, rel) in moves {
            r.readings.push(Reading {
                key: "material".to_string(),
                row: 0,
                component: 0,
                rate: d * rel,
                origin: Origin::Shared(k),
            });
        }
    }

    /// Start reading an include's `origin`: its tolerances are recorded.
    pub(super) fn enter_origin(&mut self) {
        let r = self;
        r.in_origin = true;
        r.readings.clear();
    }

    /// Stop reading an include's `origin`, and turn its tolerances into
    /// `Dep`s on the point (`Slot::At`), its sources appended.
    pub(super) fn leave_origin(&mut self) -> Option<std::sync::Arc<[Dep]>> {
        let r = self;
        r.in_origin = false;
        r.deps(None)
    }

    /// Scale the rates recorded so far for `key` by `factor`: the key's
    /// value enters the part's number multiplied by it.
    pub(super) fn scale_readings(&mut self, key: &str, factor: f64) {
        for reading in self.readings.iter_mut().filter(|x| x.key == key) {
            reading.rate *= factor;
        }
    }
}

impl Ctx<'_> {
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

    /// Record the tolerance of a part's given mass, `mass` = `m` read as
    /// `value` (file units), when it is `tol` beside it (a tolerance in
    /// the string was recorded as it was read: not both).
    pub(super) fn mass_tol(
        &self,
        rec: &mut Recorder,
        p: &super::raw::RawPart,
        m: &Spanned<Quantity>,
        value: f64,
    ) -> Result<(), Diagnostic> {
        let Some(tol) = p.tol.as_deref() else {
            return Ok(());
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
        self.record(rec, Index::SCALAR, m, "mass", Dim::MASS, value, t)
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
            super::span::sub_span(&source.text, span.clone(), text, from..to)
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
            // A bare number is in the file's units, as a bare value is: a
            // value with its own unit wants its tolerance's too
            // (`"2 g ± 0.1"` is not 0.1 kg).
            if let Some((value, _)) = before
                && value.trim().parse::<f64>().is_err()
            {
                return Err(bad(format!(
                    "`{key}`: the tolerance {body:?} has no unit, and its value has one"
                )));
            }
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
    #[allow(clippy::too_many_arguments)] // the recorder, where the value stands, and the value
    pub(super) fn record(
        &self,
        r: &mut Recorder,
        at: Index,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
        value: f64,
        tol: Tol,
    ) -> Result<(), Diagnostic> {
        // In the key's file units, as `value`.
        let amount = if tol.relative {
            tol.amount * value.abs()
        } else {
            tol.amount / self.units.factor(dim).value()
        };
        if !amount.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}`: the tolerance overflows the range of f64 in the file's units"),
            ));
        }
        let Index { row, component } = at;
        // Named by its component as the file indexes it.
        let key_text = match r.allows(key, at) {
            Some(Slot::Edge(..) | Slot::Vertex(..)) => format!("{key}[{row}][{component}]"),
            Some(Slot::At(_) | Slot::To(_)) => format!("{key}[{component}]"),
            Some(Slot::Size(_)) => format!("{key}[{component}]"),
            _ => key.to_string(),
        };
        r.readings.push(Reading {
            key: key.to_string(),
            row,
            component,
            rate: tol.spread.sigma(amount),
            origin: Origin::New(Toleranced {
                key: key_text,
                written: tol.written,
                spread: tol.spread,
                span: q.span(),
                shared: false,
            }),
        });
        Ok(())
    }

    /// Refuse a value that moves with a parameter's tolerance (`grad`,
    /// not empty) where no tolerance may stand, or where it has no
    /// derivative.
    pub(super) fn tolerable_grad(
        &self,
        r: &Recorder,
        at: Index,
        q: &Spanned<Quantity>,
        key: &str,
        grad: &crate::expr::tangent::Grad,
    ) -> Result<(), Diagnostic> {
        if r.allows(key, at).is_none() {
            let names = r.sources[grad[0].0 as usize].key.clone();
            return Err(self
                .err(
                    q.span(),
                    format!("`{key}` uses a parameter with a tolerance ({names}), and a tolerance is not allowed on `{key}`"),
                )
                .help(TOLERANCES_GO));
        }
        if grad.iter().any(|(_, d)| !d.is_finite()) {
            return Err(self.err(
                q.span(),
                format!("`{key}`: its expression has no finite derivative by its parameters' tolerances at their values"),
            ).help("a square root of 0, or a power of 0, changes infinitely fast there"));
        }
        Ok(())
    }
}

impl Recorder {
    /// Record how the value read for `key` (at `at`) moves with the
    /// sources of the parameters its expression uses (`grad`, in the
    /// key's file units).
    pub(super) fn record_grad(&mut self, at: Index, key: &str, grad: &crate::expr::tangent::Grad) {
        let r = self;
        let Index { row, component } = at;
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
    pub(super) fn shared_source(&mut self, name: &str, span: Range<usize>, tol: &Tol) -> u32 {
        let r = self;
        r.sources.push(Toleranced {
            key: format!("param `{name}`"),
            written: tol.written.clone(),
            spread: tol.spread,
            span,
            shared: true,
        });
        (r.sources.len() - 1) as u32
    }

    /// Start reading a part's keys, of a `shape`: tolerances are allowed
    /// on those that fill its numbers, and recorded.
    pub(super) fn enter_part(&mut self, shape: Shape, common: &'static [Key]) {
        let r = self;
        r.part = Some((shape, common));
        r.readings.clear();
    }

    /// Stop reading a part's keys, and turn what was recorded into the
    /// part's `Dep`s, its sources appended to `sources`.
    pub(super) fn leave_part(&mut self) -> Option<std::sync::Arc<[Dep]>> {
        let r = self;
        let shape = r.part.take();
        r.deps(shape)
    }

    /// The readings recorded, as `Dep`s of a part of `shape` (`None`: an
    /// include's origin), their new sources appended.
    fn deps(&mut self, shape: Option<Part>) -> Option<std::sync::Arc<[Dep]>> {
        if self.readings.is_empty() {
            return None;
        }
        let mut deps = Vec::new();
        let sources = &mut self.sources;
        for reading in self.readings.drain(..) {
            let (slot, factor) = slot(shape, &reading.key, reading.row, reading.component)
                .expect("invariant: a key a tolerance was allowed on fills a slot");
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

/// A part's shape and the keys any part may have (`Recorder::part`).
type Part = (Shape, &'static [Key]);

/// The number of a part's `Spec` that `key` (its `row` and `component`)
/// fills, of a part of `shape` (`None`: an include, whose `origin` is its
/// point), and its factor (a diameter fills a radius, halved): as the
/// key's declaration says (`Key::fill`, `ShapeInfo::slot`). A key without
/// one takes no tolerance.
fn slot(part: Option<Part>, key: &str, row: usize, component: usize) -> Option<(Slot, f64)> {
    let Some((shape, common)) = part else {
        return (key == "origin").then_some((Slot::At(component.min(2) as u8), 1.0));
    };
    // The shape's own declaration first (as `Ctx::part` reads its keys).
    let declared = shape
        .own_keys()
        .iter()
        .chain(common)
        .find(|k| k.name == key)?;
    shape.info().slot(declared, row, component, common)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_includes_origin_alone_takes_a_tolerance() {
        assert_eq!(slot(None, "origin", 0, 2), Some((Slot::At(2), 1.0)));
        assert_eq!(slot(None, "center", 0, 2), None);
    }
}
