//! `[expect]`: expected mass properties, validated into a flat list of
//! scalar checks, each remembering where in the file it was written.
//!
//! A vector or matrix expectation becomes one check per component, all
//! pointing at the same entry; component keys (`center_of_mass.z`,
//! `inertia_com.xy`, `principal_moments.1`) give single checks.

use super::Ctx;
use super::raw::{ExpectValue, Quantity as Number, RawExpect, RawExpectation};
use super::tolerance::Recorder;
use crate::diag::Diagnostic;
use crate::quantity::{ALIASES, Layout, Needs, ORDINALS, QUANTITIES, Quantity, XYZ};
use crate::thresholds::AXES_ORTHONORMAL;
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// The reported value a check reads: a quantity and the index of its
/// component (row-major for a matrix; 0 for a scalar).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Target {
    pub quantity: Quantity,
    pub component: usize,
}

impl Target {
    /// Whether it reads the predicted body, which is composed only when a
    /// file expects something of it.
    pub fn is_predicted(self) -> bool {
        self.quantity.info().needs == Needs::Predicted
    }
}

/// A tolerance: absolute (SI) or relative (a fraction of the value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tol {
    Abs(f64),
    Rel(f64),
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// `value` ± `tol`.
    Value { value: f64, tol: Tol },
    /// `min` and/or `max`.
    Range { min: Option<f64>, max: Option<f64> },
    /// Axes (unit, orthogonal rows) within an angle `tol`, radians: the
    /// measured value is the largest angle between an expected axis and
    /// the computed one (`analysis::check::axes`).
    Axes { rows: [[f64; 3]; 3], tol: f64 },
}

impl Bound {
    /// The interval [lo, hi] a value must lie in, SI.
    pub fn limits(&self) -> (f64, f64) {
        match *self {
            Bound::Value { value, tol } => {
                let t = match tol {
                    Tol::Abs(t) => t,
                    Tol::Rel(r) => r * value.abs(),
                };
                (value - t, value + t)
            }
            Bound::Range { min, max } => (
                min.unwrap_or(f64::NEG_INFINITY),
                max.unwrap_or(f64::INFINITY),
            ),
            Bound::Axes { tol, .. } => (0.0, tol),
        }
    }
}

/// One scalar expectation, in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    /// As written in messages: `mass`, `center_of_mass.z`, `inertia_com.xy`.
    pub name: String,
    pub target: Target,
    pub bound: Bound,
    pub dim: Dim,
    /// The expectation's entry in the file.
    pub span: Range<usize>,
}

/// An expectation's component keys, in the order they are read: key, the
/// shape it belongs to, its index in that shape's value.
fn components(
    e: &RawExpectation,
) -> [(
    &'static str,
    Option<&Spanned<RawExpectation>>,
    Layout,
    usize,
); 12] {
    fn c(c: &Option<Box<Spanned<RawExpectation>>>) -> Option<&Spanned<RawExpectation>> {
        c.as_deref()
    }
    [
        ("x", c(&e.x), Layout::Vector, 0),
        ("y", c(&e.y), Layout::Vector, 1),
        ("z", c(&e.z), Layout::Vector, 2),
        ("1", c(&e.c1), Layout::Ordered, 0),
        ("2", c(&e.c2), Layout::Ordered, 1),
        ("3", c(&e.c3), Layout::Ordered, 2),
        ("xx", c(&e.xx), Layout::Matrix, 0),
        ("yy", c(&e.yy), Layout::Matrix, 4),
        ("zz", c(&e.zz), Layout::Matrix, 8),
        ("xy", c(&e.xy), Layout::Matrix, 1),
        ("xz", c(&e.xz), Layout::Matrix, 2),
        ("yz", c(&e.yz), Layout::Matrix, 5),
    ]
}

/// The first component key an expectation has, with where it is.
fn first_component(e: &RawExpectation) -> Option<(&'static str, Range<usize>)> {
    components(e)
        .into_iter()
        .find_map(|(k, c, _, _)| c.map(|c| (k, c.span())))
}

impl Ctx<'_> {
    pub(super) fn expectations(
        &self,
        rec: &Recorder,
        raw: &Spanned<RawExpect>,
        analysis: &super::Analysis,
    ) -> Result<Vec<Check>, Diagnostic> {
        let e = raw.get_ref();
        let mut out = Vec::new();
        for info in &QUANTITIES {
            let Some(entry) = e.entry(info.quantity) else {
                continue;
            };
            let name = info.key;
            let (needs, help) = match info.needs {
                Needs::Omega if analysis.omega.is_none() => {
                    ("omega", "the expectation is about the body turning at ω")
                }
                Needs::Velocity if analysis.velocity.is_none() => (
                    "velocity",
                    "the expectation is about the body moving: give the reference point's velocity (and `omega`)",
                ),
                Needs::Nothing
                | Needs::Omega
                | Needs::Velocity
                | Needs::Predicted
                | Needs::Alpha => ("", ""),
            };
            if !needs.is_empty() {
                return Err(self
                    .err(
                        entry.span(),
                        format!("`{name}` needs `{needs}` in `[analysis]`"),
                    )
                    .help(help));
            }
            let quantity = info.quantity;
            let at = move |component| Target {
                quantity,
                component,
            };
            self.expectation(rec, name, entry, info.layout, info.dim, &at, &mut out)?;
        }
        for (&(name, quantity, i, j), entry) in ALIASES.iter().zip(e.aliases()) {
            let Some(entry) = entry else { continue };
            let info = quantity.info();
            let target = Target {
                quantity,
                component: 3 * i + j,
            };
            self.expectation(
                rec,
                name,
                entry,
                Layout::Scalar,
                info.dim,
                &|_| target,
                &mut out,
            )?;
        }
        // Report in file order (stable: components keep their order).
        out.sort_by_key(|c| c.span.start);
        Ok(out)
    }

    #[allow(clippy::too_many_arguments)] // `rec` only names a parameter's source in an error
    fn expectation(
        &self,
        rec: &Recorder,
        name: &str,
        raw: &Spanned<RawExpectation>,
        shape: Layout,
        dim: Dim,
        at: &dyn Fn(usize) -> Target,
        out: &mut Vec<Check>,
    ) -> Result<(), Diagnostic> {
        let e = raw.get_ref();
        let span = raw.span();
        let mut any_component = false;
        // Component keys, each one scalar check.
        for (key, c, cshape, k) in components(e) {
            let Some(c) = c else { continue };
            if cshape != shape {
                let message = match shape {
                    Layout::Scalar => {
                        format!("`{name}` is a single number and has no component `{key}`")
                    }
                    Layout::Vector => {
                        format!("`{name}` has no component `{key}`; its components are x, y, z")
                    }
                    Layout::Ordered => format!(
                        "`{name}` has no component `{key}`; its components are 1, 2, 3 (ascending)"
                    ),
                    Layout::Matrix => format!(
                        "`{name}` has no component `{key}`; its components are xx, yy, zz, xy, xz, yz"
                    ),
                    Layout::Axes => format!(
                        "`{name}` has no component `{key}`; give its three rows in `value`, with `tol_degrees`"
                    ),
                };
                return Err(self.err(c.span(), message));
            }
            any_component = true;
            let t = at(k);
            let n = format!("{name}.{key}");
            // A component is a single number: one level deeper
            // (`center_of_mass.x.y`) is an error, never a check of nothing.
            if let Some((sub, at)) = first_component(c.get_ref()) {
                return Err(self.err(
                    at,
                    format!("`{n}` is a single number and has no component `{sub}`"),
                ));
            }
            self.expectation_leaf(rec, &n, c, Layout::Scalar, dim, &|_| t, out)?;
        }
        let has_own = e.value.is_some()
            || e.tol.is_some()
            || e.tol_degrees.is_some()
            || e.min.is_some()
            || e.max.is_some();
        if has_own {
            self.expectation_leaf(rec, name, raw, shape, dim, at, out)?;
        } else if !any_component {
            return Err(self
                .err(span, format!("expectation `{name}` is empty"))
                .help("give `value` and `tol`, or `min` and/or `max`"));
        }
        Ok(())
    }

    /// `value`/`tol` or `min`/`max` of one entry, expanded per component.
    #[allow(clippy::too_many_arguments)] // `rec` only names a parameter's source in an error
    fn expectation_leaf(
        &self,
        rec: &Recorder,
        name: &str,
        raw: &Spanned<RawExpectation>,
        shape: Layout,
        dim: Dim,
        target: &dyn Fn(usize) -> Target,
        out: &mut Vec<Check>,
    ) -> Result<(), Diagnostic> {
        let e = raw.get_ref();
        let span = raw.span();
        if shape == Layout::Axes {
            return self.expected_axes(rec, name, raw, target(0), out);
        }
        if let Some(t) = &e.tol_degrees {
            return Err(self.err(
                t.span(),
                format!("`{name}`: `tol_degrees` is for `principal_axes`; give `tol`"),
            ));
        }
        let names: Vec<String> = match shape {
            Layout::Scalar => vec![name.to_string()],
            Layout::Vector => XYZ.iter().map(|c| format!("{name}.{c}")).collect(),
            Layout::Ordered => ORDINALS.iter().map(|c| format!("{name}.{c}")).collect(),
            Layout::Matrix => XYZ
                .iter()
                .flat_map(|a| XYZ.iter().map(move |b| format!("{name}.{a}{b}")))
                .collect(),
            Layout::Axes => unreachable!("invariant: axes are read by `axes`, above"),
        };
        let bounds: Vec<Bound> = match (&e.value, &e.tol, &e.min, &e.max) {
            (Some(v), Some(t), None, None) => {
                let tol = self.tolerance(rec, t, dim)?;
                self.values(rec, name, v, "value", shape, dim)?
                    .into_iter()
                    .map(|value| Bound::Value { value, tol })
                    .collect()
            }
            (Some(v), None, None, None) => {
                return Err(self
                    .err(v.span(), format!("`{name}`: `value` needs `tol`"))
                    .help("e.g. `tol = \"0.5%\"` (relative), `tol = 0.01` (file units) or `tol = \"10 g\"`"));
            }
            (None, Some(t), _, _) => {
                return Err(self.err(t.span(), format!("`{name}`: `tol` goes with `value`")));
            }
            (Some(v), _, Some(_), _) | (Some(v), _, _, Some(_)) => {
                return Err(self.err(
                    v.span(),
                    format!("`{name}`: give `value` with `tol`, or `min`/`max`, not both"),
                ));
            }
            (None, None, None, None) => {
                return Err(self
                    .err(span, format!("expectation `{name}` is empty"))
                    .help("give `value` and `tol`, or `min` and/or `max`"));
            }
            (None, None, min, max) => {
                let n = names.len();
                let lo = min
                    .as_ref()
                    .map(|m| self.values(rec, name, m, "min", shape, dim))
                    .transpose()?;
                let hi = max
                    .as_ref()
                    .map(|m| self.values(rec, name, m, "max", shape, dim))
                    .transpose()?;
                if let (Some(lo), Some(hi), Some(m)) = (&lo, &hi, max)
                    && lo.iter().zip(hi).any(|(a, b)| a > b)
                {
                    return Err(self.err(m.span(), format!("`{name}`: `max` is below `min`")));
                }
                (0..n)
                    .map(|k| Bound::Range {
                        min: lo.as_ref().map(|v| v[k]),
                        max: hi.as_ref().map(|v| v[k]),
                    })
                    .collect()
            }
        };
        for (k, (name, bound)) in names.into_iter().zip(bounds).enumerate() {
            out.push(Check {
                name,
                target: target(k),
                bound,
                dim,
                span: span.clone(),
            });
        }
        Ok(())
    }

    /// The values of `value`, `min` or `max`, flattened row by row, in SI.
    fn values(
        &self,
        rec: &Recorder,
        name: &str,
        v: &Spanned<ExpectValue>,
        key: &str,
        shape: Layout,
        dim: Dim,
    ) -> Result<Vec<f64>, Diagnostic> {
        let q = |x: &Number| self.quantity(rec, &Spanned::new(v.span(), x.clone()), key, dim);
        let bad = |what: &str| self.err(v.span(), format!("`{name}`: `{key}` must be {what}"));
        match (shape, v.get_ref()) {
            (Layout::Scalar, ExpectValue::One(x)) => Ok(vec![q(x)?]),
            (Layout::Scalar, _) => Err(bad("a single number")),
            (Layout::Vector | Layout::Ordered, ExpectValue::Many(xs)) if xs.len() == 3 => xs
                .iter()
                .map(|x| match x {
                    ExpectValue::One(x) => q(x),
                    ExpectValue::Many(_) => Err(bad("an array of three numbers")),
                })
                .collect(),
            (Layout::Vector | Layout::Ordered, _) => Err(bad("an array of three numbers")),
            (Layout::Matrix | Layout::Axes, ExpectValue::Many(rows)) if rows.len() == 3 => {
                let mut out = Vec::with_capacity(9);
                for row in rows {
                    match row {
                        ExpectValue::Many(r) if r.len() == 3 => {
                            for x in r {
                                match x {
                                    ExpectValue::One(x) => out.push(q(x)?),
                                    ExpectValue::Many(_) => {
                                        return Err(bad("three rows of three numbers"));
                                    }
                                }
                            }
                        }
                        _ => return Err(bad("three rows of three numbers")),
                    }
                }
                Ok(out)
            }
            (Layout::Matrix | Layout::Axes, _) => Err(bad("three rows of three numbers")),
        }
    }

    /// An entry compared by angle (`principal_axes`): `value`, three unit,
    /// orthogonal rows, and `tol_degrees`, an angle not negative.
    fn expected_axes(
        &self,
        rec: &Recorder,
        name: &str,
        raw: &Spanned<RawExpectation>,
        target: Target,
        out: &mut Vec<Check>,
    ) -> Result<(), Diagnostic> {
        let e = raw.get_ref();
        let example = "e.g. `principal_axes = { value = [[1, 0, 0], [0, 1, 0], [0, 0, 1]], tol_degrees = 0.5 }`";
        if let Some(t) = &e.tol {
            return Err(self
                .err(
                    t.span(),
                    format!("`{name}` is compared by angle: give `tol_degrees`, not `tol`"),
                )
                .help(example));
        }
        if let Some(m) = e.min.as_ref().or(e.max.as_ref()) {
            return Err(self
                .err(
                    m.span(),
                    format!("`{name}` is compared by angle: give `value` and `tol_degrees`, not `min` or `max`"),
                )
                .help(example));
        }
        let (v, t) = match (&e.value, &e.tol_degrees) {
            (Some(v), Some(t)) => (v, t),
            (Some(v), None) => {
                return Err(self
                    .err(v.span(), format!("`{name}`: `value` needs `tol_degrees`"))
                    .help(example));
            }
            (None, Some(t)) => {
                return Err(self
                    .err(
                        t.span(),
                        format!("`{name}`: `tol_degrees` goes with `value`"),
                    )
                    .help(example));
            }
            (None, None) => {
                return Err(self
                    .err(raw.span(), format!("expectation `{name}` is empty"))
                    .help(example));
            }
        };
        let tol = match t.get_ref() {
            Number::Number(x) if x.is_finite() && *x >= 0.0 => *x,
            Number::Number(x) if x.is_finite() => {
                return Err(self.err(
                    t.span(),
                    format!("`{name}`: `tol_degrees` must not be negative, got {x}"),
                ));
            }
            Number::Number(_) | Number::Text(_) => {
                return Err(self.err(
                    t.span(),
                    format!("`{name}`: `tol_degrees` must be a finite number of degrees"),
                ));
            }
        };
        let flat = self.values(rec, name, v, "value", Layout::Axes, Dim::DIMENSIONLESS)?;
        let rows: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| flat[3 * i + j]));
        let bad = |message: String| {
            Err(self
                .err(v.span(), format!("`{name}`: {message}"))
                .help("each row is a principal axis: unit length, at right angles to the others"))
        };
        for (k, r) in rows.iter().enumerate() {
            let n = crate::numeric::norm(r);
            if !((n - 1.0).abs() <= AXES_ORTHONORMAL) {
                return bad(format!(
                    "row {} of `value` is not a unit vector (its length is {n})",
                    k + 1
                ));
            }
        }
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let d: f64 = (0..3).map(|j| rows[a][j] * rows[b][j]).sum();
            if !(d.abs() <= AXES_ORTHONORMAL) {
                return bad(format!(
                    "rows {} and {} of `value` are not at right angles (their dot product is {d})",
                    a + 1,
                    b + 1
                ));
            }
        }
        out.push(Check {
            name: name.to_string(),
            target,
            bound: Bound::Axes {
                rows,
                tol: tol.to_radians(),
            },
            dim: Dim::DIMENSIONLESS,
            span: raw.span(),
        });
        Ok(())
    }

    /// `tol`: a plain number (absolute, file units), `"0.5%"` (relative) or a
    /// quantity with its own unit (absolute).
    fn tolerance(&self, rec: &Recorder, t: &Spanned<Number>, dim: Dim) -> Result<Tol, Diagnostic> {
        let tol = match t.get_ref() {
            Number::Text(s) if s.trim_end().ends_with('%') => {
                let num = s.trim_end().trim_end_matches('%').trim();
                match num.parse::<f64>() {
                    Ok(p) if p.is_finite() => Tol::Rel(p / 100.0),
                    _ => {
                        return Err(
                            self.err(t.span(), format!("`tol`: cannot read percentage {s:?}"))
                        );
                    }
                }
            }
            _ => Tol::Abs(self.quantity(rec, t, "tol", dim)?),
        };
        match tol {
            Tol::Abs(x) | Tol::Rel(x) if x >= 0.0 => Ok(tol),
            _ => Err(self.err(t.span(), "`tol` must not be negative")),
        }
    }
}
