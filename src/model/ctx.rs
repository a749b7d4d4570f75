//! What the conversion step reads values with: the source (for spans), the
//! file's units and materials, and the readers of quantities and vectors —
//! the one place a value is converted and range-checked.

use super::raw::{Quantity, RawAnalysis, Vector};
use super::tolerance::{Index, Recorder};
use super::{Analysis, raw};
use crate::diag::{Diagnostic, Source};
use crate::la::Vector3;
use crate::units::{self, Dim, FileUnits, UnitError};
use std::ops::Range;
use toml::Spanned;

/// What an array belongs to, for the message when its length is wrong
/// (formed only then: this is on every part's path).
#[derive(Clone, Copy)]
pub(super) enum Whose<'a> {
    /// A key: "`center` needs 3 components".
    Key(&'a str),
    /// A shape: "a box needs 3 `edges`".
    Shape(&'a str),
}

/// A quantity read once (`Ctx::value`): in the file's units, what a part
/// keeps and computes with, and in SI, what the range checks judge.
#[derive(Clone, Copy, Debug)]
pub(super) struct Value {
    pub file: f64,
    pub si: f64,
}

/// What the conversion step needs to read values: the source (for spans)
/// and the file's units.
pub(crate) struct Ctx<'a> {
    pub(super) source: &'a Source,
    pub(super) units: FileUnits,
    /// `[materials]`: name → density (kg/m³, and in file units).
    pub(super) materials: std::collections::BTreeMap<String, (f64, f64)>,
    /// `[params]`, evaluated (`model::params`).
    pub(super) params: super::params::Params,
    /// `[growth]`: maturity → allowance (`model::budget`).
    pub(super) growth: super::budget::Allowances,
}

impl Ctx<'_> {
    /// An error at `span` of this file (with a note naming any `--set`
    /// parameter the span's text names: `Params::blame_set`).
    pub(super) fn err(&self, span: Range<usize>, message: impl Into<String>) -> Diagnostic {
        let d = self.source.error(span.clone(), message);
        self.params.blame_set(&self.source.text, span, d)
    }

    pub(super) fn file_units(&self, u: &Spanned<raw::RawUnits>) -> Result<FileUnits, Diagnostic> {
        let pick = |v: &Option<Spanned<String>>,
                    allowed: &'static [&'static str],
                    key: &str,
                    default: &'static str| {
            let Some(v) = v else { return Ok(default) };
            allowed
                .iter()
                .copied()
                .find(|a| *a == v.get_ref())
                .ok_or_else(|| {
                    self.err(
                        v.span(),
                        format!("unknown {key} unit {:?} in `units`", v.get_ref()),
                    )
                    .label(
                        match units::suggest(v.get_ref(), allowed.iter().copied()) {
                            Some(s) => format!("did you mean \"{s}\"?"),
                            None => format!("expected one of {}", allowed.join(", ")),
                        },
                    )
                })
        };
        Ok(FileUnits {
            length: pick(&u.get_ref().length, units::LENGTH_UNITS, "length", "m")?,
            mass: pick(&u.get_ref().mass, units::MASS_UNITS, "mass", "kg")?,
        })
    }

    /// A scalar of dimension `dim` in SI: a plain number in file units, or a
    /// string with its own unit. Always finite. For a key read only in SI
    /// (`[expect]`, a budget's limit); a part's keys are read by `value`.
    pub(super) fn quantity(
        &self,
        rec: &Recorder,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<f64, Diagnostic> {
        let value = match q.get_ref() {
            Quantity::Number(x) => {
                if !x.is_finite() {
                    return Err(self.err(
                        q.span(),
                        format!("`{key}` must be a finite number, got {x}"),
                    ));
                }
                self.units.factor(dim).apply(*x)
            }
            Quantity::Text(t) => {
                let (t, _) = self.tolerance_of(rec, Index::SCALAR, q, t, key, dim)?;
                match units::parse_quantity(t, dim) {
                    Ok(v) => v,
                    Err(e) => match self.expression(rec, q, t, key, dim, units::Factor::ONE)? {
                        Some(v) => return self.in_file_units(q, key, dim, v),
                        None => return Err(self.unit_error(q, key, dim, e)),
                    },
                }
            }
        };
        self.checked(q, key, dim, value)
    }

    /// A scalar of dimension `dim`, read once: in the file's units (the
    /// number the part keeps, its tolerance recorded) and in SI (what the
    /// range checks judge), each checked. A plain number is converted to
    /// SI by the exact factor; a string with its own unit to each by its
    /// exact ratio (one rounding each); an expression is evaluated in the
    /// file's units and its SI value derived.
    pub(super) fn value(
        &self,
        rec: &mut Recorder,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<Value, Diagnostic> {
        self.value_at(rec, Index::SCALAR, q, key, dim)
    }

    /// `value`, of the component `at` of a vector (or of a row of one),
    /// which names a tolerance recorded on it.
    pub(super) fn value_at(
        &self,
        rec: &mut Recorder,
        at: Index,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<Value, Diagnostic> {
        let factor = self.units.factor(dim);
        let (file, si) = match q.get_ref() {
            Quantity::Number(x) => {
                if !x.is_finite() {
                    return Err(self.err(
                        q.span(),
                        format!("`{key}` must be a finite number, got {x}"),
                    ));
                }
                (*x, self.checked(q, key, dim, factor.apply(*x))?)
            }
            Quantity::Text(t) => {
                let (t, tol) = self.tolerance_of(rec, at, q, t, key, dim)?;
                // A plain number's string (`count = "32"`) is read as an
                // expression, whose angle units are refused there (`"4 rad"`).
                let plain = if dim == Dim::DIMENSIONLESS {
                    Err(UnitError::NoUnit)
                } else {
                    units::parse_quantity(t, dim)
                };
                let (file, si) = match plain {
                    Ok(si) => {
                        let si = self.checked(q, key, dim, si)?;
                        let file = units::parse_quantity_in(t, dim, self.units)
                            .map_err(|e| self.err(q.span(), format!("`{key}`: {e}")))?;
                        (file, si)
                    }
                    Err(e) => match self.expression_grad(rec, at, q, t, key, dim, factor)? {
                        // An expression's value comes checked in the
                        // file's units (its zero as computed, not as
                        // written).
                        Some((file, grad)) => {
                            rec.record_grad(at, key, &grad);
                            if let Some(tol) = tol {
                                self.record(rec, at, q, key, dim, file, tol)?;
                            }
                            let si = file * factor.value();
                            if !si.is_finite() {
                                return Err(self.err(
                                    q.span(),
                                    format!("`{key}` overflows when converted to SI units"),
                                ));
                            }
                            if file != 0.0 && si.abs() < f64::MIN_POSITIVE {
                                return Err(self.err(
                                    q.span(),
                                    format!(
                                        "`{key}` is too small: below {:e} in SI units, f64 loses precision",
                                        f64::MIN_POSITIVE
                                    ),
                                ));
                            }
                            return Ok(Value { file, si });
                        }
                        None => return Err(self.unit_error(q, key, dim, e)),
                    },
                };
                if let Some(tol) = tol {
                    self.record(rec, at, q, key, dim, file, tol)?;
                }
                (file, si)
            }
        };
        if !file.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` overflows when converted to the file's units"),
            ));
        }
        self.representable(q, key, file, "the file's units")?;
        Ok(Value { file, si })
    }

    /// `value`, positive.
    pub(super) fn positive_value(
        &self,
        rec: &mut Recorder,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<Value, Diagnostic> {
        let v = self.value(rec, q, key, dim)?;
        if v.si > 0.0 {
            Ok(v)
        } else {
            Err(self.err(q.span(), format!("`{key}` must be positive")))
        }
    }

    /// The unit reader's error for a plain quantity string.
    fn unit_error(&self, q: &Spanned<Quantity>, key: &str, dim: Dim, e: UnitError) -> Diagnostic {
        let d = self.err(q.span(), format!("`{key}`: {e}"));
        match e {
            UnitError::Unknown {
                suggestion: Some(s),
                ..
            } => d.suggest(Some(s)),
            _ => d.help(format!(
                "`{key}` is {}, e.g. {}",
                dim.describe(),
                dim.example()
            )),
        }
    }

    /// An SI value of an expression, checked against the file's units
    /// (as `checked` does for a plain quantity).
    fn in_file_units(
        &self,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
        value: f64,
    ) -> Result<f64, Diagnostic> {
        if !(value / self.units.factor(dim).value()).is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` is beyond the largest number in the file's units"),
            ));
        }
        Ok(value)
    }

    /// A plain value in SI, checked: finite, representable, and within
    /// the file's units too.
    fn checked(
        &self,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
        value: f64,
    ) -> Result<f64, Diagnostic> {
        if !value.is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` overflows when converted to SI units"),
            ));
        }
        self.representable(q, key, value, "SI units")?;
        // Results are shown in the file's units: a value within a rounding
        // of the largest f64 there can overflow on its way back from SI.
        if !(value / self.units.factor(dim).value()).is_finite() {
            return Err(self.err(
                q.span(),
                format!("`{key}` is beyond the largest number in the file's units"),
            ));
        }
        Ok(value)
    }

    /// The one check of an array's length, for every vector and matrix in
    /// a file: `v` must have exactly `n` items, or a located error says
    /// "{whose} needs {n} {items}, got {len}".
    pub(super) fn exactly<'v, T>(
        &self,
        v: &'v Spanned<Vec<T>>,
        n: usize,
        whose: Whose,
        items: &str,
    ) -> Result<&'v [T], Diagnostic> {
        let got = v.get_ref().len();
        if got != n {
            let whose = match whose {
                Whose::Key(k) => format!("`{k}`"),
                Whose::Shape(s) => format!("a {s}"),
            };
            return Err(self.err(v.span(), format!("{whose} needs {n} {items}, got {got}")));
        }
        Ok(v.get_ref())
    }

    /// Three quantities read once each (`value_at`, each its component of
    /// row `row`): in the file's units and in SI.
    pub(super) fn value3(
        &self,
        rec: &mut Recorder,
        row: usize,
        v: &Vector,
        key: &str,
        dim: Dim,
    ) -> Result<([f64; 3], Vector3<f64>), Diagnostic> {
        let items = self.exactly(v, 3, Whose::Key(key), "components")?;
        let (mut file, mut si) = ([0.0; 3], Vector3::zeros());
        for (i, q) in items.iter().enumerate() {
            let x = self.value_at(rec, Index { row, component: i }, q, key, dim)?;
            (file[i], si[i]) = (x.file, x.si);
        }
        Ok((file, si))
    }

    /// Refuse a value that is not zero as written but that f64 (or its
    /// conversion to `units`) made zero or subnormal: it would be computed
    /// with as 0, or with too few digits (`center = [1e-400, 0, 0]` was
    /// read as the origin). Zero itself, written as zero, is a value.
    fn representable(
        &self,
        q: &Spanned<Quantity>,
        key: &str,
        value: f64,
        units: &str,
    ) -> Result<(), Diagnostic> {
        if value.abs() >= f64::MIN_POSITIVE {
            return Ok(());
        }
        // The number as written: the span's text where the span is the
        // number alone (an `[expect]` component's span is its whole array,
        // and then only a subnormal value is caught).
        let written = match q.get_ref() {
            Quantity::Number(_) => self
                .source
                .text
                .get(q.span())
                .filter(|w| w.replace('_', "").trim().parse::<f64>().is_ok())
                .unwrap_or(""),
            Quantity::Text(t) => t.as_str(),
        };
        if value != 0.0 || nonzero_literal(written) {
            return Err(self.err(
                q.span(),
                format!(
                    "`{key}` is too small: below {:e} in {units}, f64 loses precision",
                    f64::MIN_POSITIVE
                ),
            ));
        }
        Ok(())
    }

    /// A parameter given as a TOML number (`n = 32` in `[params]`, or in an
    /// include's `params`), as a plain number: finite, and not zero or
    /// subnormal in f64 unless written as zero (`n = 1e-400` is too small
    /// here, as any quantity is).
    pub(super) fn number_param(
        &self,
        q: &Spanned<Quantity>,
        x: f64,
        what: &str,
    ) -> Result<crate::expr::Value, Diagnostic> {
        if !x.is_finite() {
            return Err(self.err(q.span(), format!("{what} must be a finite number, got {x}")));
        }
        let written = self.source.text.get(q.span()).unwrap_or("");
        if x.abs() < f64::MIN_POSITIVE && (x != 0.0 || nonzero_literal(written)) {
            return Err(self.err(
                q.span(),
                format!(
                    "{what} is too small: below {:e}, f64 loses precision",
                    f64::MIN_POSITIVE
                ),
            ));
        }
        Ok(crate::expr::Value::of_f64(x))
    }

    /// A positive quantity. Subnormal values (below 2.2e-308 in SI) are
    /// refused too, as for every quantity: they carry too few digits to
    /// compute with.
    pub(super) fn positive(
        &self,
        rec: &Recorder,
        q: &Spanned<Quantity>,
        key: &str,
        dim: Dim,
    ) -> Result<f64, Diagnostic> {
        let v = self.quantity(rec, q, key, dim)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(q.span(), format!("`{key}` must be positive")))
        }
    }

    /// `[analysis]`: the reference point, ω and α, in the file's units.
    pub(super) fn analysis(
        &self,
        rec: &mut Recorder,
        a: &Spanned<RawAnalysis>,
    ) -> Result<Analysis, Diagnostic> {
        let r = a.get_ref();
        let mut read = |v: &Option<Vector>, key: &str, dim: Dim| {
            v.as_ref()
                .map(|v| {
                    self.value3(rec, 0, v, key, dim)
                        .map(|(file, _)| Vector3::from(file))
                })
                .transpose()
        };
        let about = read(&r.about, "about", Dim::LENGTH)?;
        let omega = read(&r.omega, "omega", Dim::ANGULAR_VELOCITY)?;
        let alpha = read(&r.alpha, "alpha", Dim::ANGULAR_ACCELERATION)?;
        let velocity = read(&r.velocity, "velocity", Dim::VELOCITY)?;
        let axles = r.axles.as_ref().map(|a| self.axles(rec, a)).transpose()?;
        let g = (r.g.as_ref())
            .map(|q| self.positive(rec, q, "g", Dim::ACCELERATION))
            .transpose()?;
        let axes = r.axes.as_ref().map(|a| self.axes(a)).transpose()?;
        Ok(Analysis {
            about,
            omega,
            alpha,
            velocity,
            axles,
            g,
            axes,
            alpha_span: r.alpha.as_ref().map(Spanned::span),
            velocity_span: r.velocity.as_ref().map(Spanned::span),
            about_span: r.about.as_ref().map(Spanned::span),
            omega_span: r.omega.as_ref().map(Spanned::span),
            warnings: r.warnings,
        })
    }
}

impl Ctx<'_> {
    /// An `axis` key's coordinate: 0, 1 or 2 for "x", "y" or "z" (of the
    /// report axes); `help` says what the axis is for.
    pub(super) fn axis_index(
        &self,
        axis: &Spanned<String>,
        help: &str,
    ) -> Result<usize, Diagnostic> {
        match axis.get_ref().as_str() {
            "x" => Ok(0),
            "y" => Ok(1),
            "z" => Ok(2),
            other => Err(self
                .err(
                    axis.span(),
                    format!("`axis` must be \"x\", \"y\" or \"z\", not {other:?}"),
                )
                .help(help.to_string())),
        }
    }

    /// `[analysis] axles`: the axis and the two positions (SI), distinct.
    fn axles(
        &self,
        rec: &Recorder,
        a: &Spanned<raw::RawAxles>,
    ) -> Result<super::Axles, Diagnostic> {
        let r = a.get_ref();
        let missing = |key: &str| {
            self.err(a.span(), format!("`axles` needs `{key}`"))
                .help("give `axis` (\"x\", \"y\" or \"z\", of the report axes) and the `front` and `rear` axles' positions along it")
        };
        let axis = r.axis.as_ref().ok_or_else(|| missing("axis"))?;
        let k = self.axis_index(
            axis,
            "the axis of the report axes along which the axles lie",
        )?;
        let front = r.front.as_ref().ok_or_else(|| missing("front"))?;
        let rear = r.rear.as_ref().ok_or_else(|| missing("rear"))?;
        let f = self.quantity(rec, front, "front", Dim::LENGTH)?;
        let b = self.quantity(rec, rear, "rear", Dim::LENGTH)?;
        // NOTE: the loads divide by the wheelbase: equal positions have no
        // answer (the body's weight may split between them any way).
        if f == b {
            return Err(self
                .err(
                    rear.span(),
                    "`rear` is where `front` is: the axle loads are indeterminate",
                )
                .help("the two axles lie apart along `axis`"));
        }
        Ok(super::Axles {
            axis: k,
            front: f,
            rear: b,
        })
    }
}

/// Whether a number as written (`1e-400`, `"-3e-330 mm"`) is not zero: a
/// non-zero digit before any exponent, whatever its sign.
pub(super) fn nonzero_literal(text: &str) -> bool {
    let t = text
        .trim()
        .trim_matches('"')
        .trim_matches('\'')
        .trim_start();
    let t = t.strip_prefix(['-', '+']).unwrap_or(t);
    let mantissa = t
        .split(|c: char| c == 'e' || c == 'E' || c.is_whitespace())
        .next()
        .unwrap_or("");
    !t.starts_with("0x")
        && !t.starts_with("0o")
        && !t.starts_with("0b")
        && mantissa.chars().any(|c| ('1'..='9').contains(&c))
}

#[cfg(test)]
mod tests {
    use crate::diag::Source;
    use crate::model::Model;

    fn error(text: &str) -> Option<String> {
        Model::parse(&Source::new("f.toml", text))
            .err()
            .map(|e| e.to_string())
    }

    fn point(center: &str) -> String {
        format!("[[part]]\nshape = \"point\"\nmass = 1\ncenter = {center}\n")
    }

    /// The parts of `text`'s model, with the keys of its sources.
    fn sources(text: &str) -> (Vec<crate::model::Item>, Vec<String>) {
        let m = Model::parse(&Source::new("f.toml", text)).expect("a model");
        let keys = m.sources.iter().map(|s| s.key.clone()).collect();
        (m.items.to_vec(), keys)
    }

    /// The slots a part's tolerances move.
    fn slots(item: &crate::model::Item) -> Vec<crate::shapes::Slot> {
        let crate::model::Item::Part { part, .. } = item else {
            panic!("a part");
        };
        part.tol
            .iter()
            .flat_map(|d| d.iter().map(|d| d.slot))
            .collect()
    }

    #[test]
    fn a_tolerance_in_a_row_is_named_and_placed_by_the_row_and_component_read() {
        use crate::shapes::Slot;
        let (items, keys) = sources(
            "[[part]]\nshape = \"box\"\nmass = 1\ncorner = [0, 0, 0]\nedges = [[1, 0, 0], [0, 1, \"0 m ± 1 mm\"], [0, 0, 1]]\n\
             [[part]]\nshape = \"triangle\"\nmass = 1\nvertices = [[0, 0, 0], [1, 0, 0], [\"0 m ± 1 mm\", 1, 0]]\n\
             [[part]]\nshape = \"sphere\"\nmass = 1\nradius = \"1 m ± 1 mm\"\ncenter = [0, 0, 0]\n",
        );
        assert_eq!(keys, ["edges[1][2]", "vertices[2][0]", "radius"]);
        assert_eq!(slots(&items[0]), [Slot::Edge(1, 2)]);
        assert_eq!(slots(&items[1]), [Slot::Vertex(2, 0)]);
        assert_eq!(slots(&items[2]), [Slot::Radius]);
    }

    #[test]
    fn a_coordinate_that_f64_makes_zero_or_subnormal_is_too_small() {
        for (center, bad) in [
            ("[1e-400, 0, 0]", "1e-400"),
            ("[0, -1e-400, 0]", "-1e-400"),
            ("[0, 0, 1e-320]", "1e-320"),
            ("[\"1e-320 mm\", 0, 0]", "\"1e-320 mm\""),
            ("[\"-2e-400 m\", 0, 0]", "\"-2e-400 m\""),
        ] {
            let e = error(&point(center)).unwrap_or_else(|| panic!("{center} accepted"));
            // At the component: `center = ` is 9 columns.
            let col = 9 + center.find(bad).unwrap() + 1;
            assert!(
                e.starts_with(&format!(
                    "f.toml:4:{col}: error: `center` is too small: below 2.2250738585072014e-308"
                )),
                "{center}: {e}"
            );
        }
    }

    #[test]
    fn zero_written_as_zero_is_a_coordinate() {
        assert_eq!(error(&point("[0e-400, -0.0, \"0 mm\"]")), None);
        assert_eq!(error(&point("[+0.0, 0, 2.2250738585072014e-308]")), None);
    }

    #[test]
    fn analysis_vectors_that_underflow_are_too_small() {
        let body = point("[0, 0, 0]");
        for (key, line) in [("omega", 6), ("about", 6)] {
            let e = error(&format!("{body}[analysis]\n{key} = [1e-400, 0, 1]\n"))
                .unwrap_or_else(|| panic!("{key} accepted"));
            assert!(
                e.contains(&format!(":{line}:")) && e.contains(&format!("`{key}` is too small")),
                "{e}"
            );
        }
    }

    #[test]
    fn a_mass_that_underflows_is_too_small_whatever_its_sign_and_zero_is_not_positive() {
        let mass =
            |m: &str| format!("[[part]]\nshape = \"point\"\nmass = {m}\ncenter = [0, 0, 0]\n");
        for m in ["1e-400", "-1e-400", "4e-320"] {
            let e = error(&mass(m)).unwrap();
            assert!(e.contains("`mass` is too small"), "{m}: {e}");
        }
        for m in ["0", "-0.0", "-1"] {
            let e = error(&mass(m)).unwrap();
            assert!(e.contains("`mass` must be positive"), "{m}: {e}");
        }
    }
}
