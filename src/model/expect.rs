//! `[expect]`: expected mass properties, validated into a flat list of
//! scalar checks, each remembering where in the file it was written.
//!
//! A vector or matrix expectation becomes one check per component, all
//! pointing at the same entry; component keys (`center_of_mass.z`,
//! `inertia_com.xy`, `principal_moments.1`) give single checks.

use super::Ctx;
use super::raw::{ExpectValue, Quantity, RawExpect, RawExpectation};
use crate::diag::Diagnostic;
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// The reported value a check reads: quantity and component indices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    Mass,
    CenterOfMass(usize),
    PrincipalMoment(usize),
    InertiaCom(usize, usize),
    InertiaRef(usize, usize),
    RadiusOfGyration(usize),
    /// About the x, y or z axis through the centre of mass.
    RadiusOfGyrationAxis(usize),
    AngularMomentum(usize),
    KineticEnergy,
    /// The predicted body's (basic and growth, `analysis::budget`).
    PredictedMass,
    PredictedCenterOfMass(usize),
    PredictedInertiaCom(usize, usize),
}

impl Target {
    /// Whether it reads the predicted body, which is composed only when a
    /// file expects something of it.
    pub fn is_predicted(self) -> bool {
        matches!(
            self,
            Target::PredictedMass
                | Target::PredictedCenterOfMass(_)
                | Target::PredictedInertiaCom(..)
        )
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

#[derive(Clone, Copy, PartialEq)]
enum Shape {
    Scalar,
    /// Components x, y, z in file axes.
    Vector,
    /// Components 1, 2, 3 in ascending order.
    Ordered,
    /// Components xx … yz of a symmetric matrix.
    Matrix,
}

/// How a top-level quantity's checks read the summary.
type Make = fn(usize, usize) -> Target;
/// A top-level `[expect]` key: name, entry, shape, dimension, target.
type Entry<'a> = (
    &'static str,
    &'a Option<Spanned<RawExpectation>>,
    Shape,
    Dim,
    Make,
);
/// A component key: name, entry, the shape it belongs to, indices.
type Component<'a> = (
    &'static str,
    &'a Option<Box<Spanned<RawExpectation>>>,
    Shape,
    usize,
    usize,
);

const XYZ: [&str; 3] = ["x", "y", "z"];
const ORD: [&str; 3] = ["1", "2", "3"];

/// The first component key an expectation has, with where it is.
fn first_component(e: &RawExpectation) -> Option<(&'static str, Range<usize>)> {
    [
        ("x", &e.x),
        ("y", &e.y),
        ("z", &e.z),
        ("1", &e.c1),
        ("2", &e.c2),
        ("3", &e.c3),
        ("xx", &e.xx),
        ("yy", &e.yy),
        ("zz", &e.zz),
        ("xy", &e.xy),
        ("xz", &e.xz),
        ("yz", &e.yz),
    ]
    .into_iter()
    .find_map(|(k, c)| c.as_ref().map(|c| (k, c.span())))
}

impl Ctx<'_> {
    pub(super) fn expectations(
        &self,
        raw: &Spanned<RawExpect>,
        have_omega: bool,
    ) -> Result<Vec<Check>, Diagnostic> {
        let e = raw.get_ref();
        let mut out = Vec::new();
        let entries: [Entry<'_>; 18] = [
            ("mass", &e.mass, Shape::Scalar, Dim::MASS, |_, _| {
                Target::Mass
            }),
            (
                "center_of_mass",
                &e.center_of_mass,
                Shape::Vector,
                Dim::LENGTH,
                |i, _| Target::CenterOfMass(i),
            ),
            (
                "principal_moments",
                &e.principal_moments,
                Shape::Ordered,
                Dim::INERTIA,
                |i, _| Target::PrincipalMoment(i),
            ),
            (
                "inertia_com",
                &e.inertia_com,
                Shape::Matrix,
                Dim::INERTIA,
                Target::InertiaCom,
            ),
            (
                "inertia_ref",
                &e.inertia_ref,
                Shape::Matrix,
                Dim::INERTIA,
                Target::InertiaRef,
            ),
            (
                "radii_of_gyration",
                &e.radii_of_gyration,
                Shape::Ordered,
                Dim::LENGTH,
                |i, _| Target::RadiusOfGyration(i),
            ),
            (
                "radii_of_gyration_axes",
                &e.radii_of_gyration_axes,
                Shape::Vector,
                Dim::LENGTH,
                |i, _| Target::RadiusOfGyrationAxis(i),
            ),
            (
                "angular_momentum",
                &e.angular_momentum,
                Shape::Vector,
                Dim::ANGULAR_MOMENTUM,
                |i, _| Target::AngularMomentum(i),
            ),
            (
                "kinetic_energy",
                &e.kinetic_energy,
                Shape::Scalar,
                Dim::ENERGY,
                |_, _| Target::KineticEnergy,
            ),
            (
                "predicted_mass",
                &e.predicted_mass,
                Shape::Scalar,
                Dim::MASS,
                |_, _| Target::PredictedMass,
            ),
            (
                "predicted_center_of_mass",
                &e.predicted_center_of_mass,
                Shape::Vector,
                Dim::LENGTH,
                |i, _| Target::PredictedCenterOfMass(i),
            ),
            (
                "predicted_inertia_com",
                &e.predicted_inertia_com,
                Shape::Matrix,
                Dim::INERTIA,
                Target::PredictedInertiaCom,
            ),
            ("Ixx", &e.ixx, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(0, 0)
            }),
            ("Iyy", &e.iyy, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(1, 1)
            }),
            ("Izz", &e.izz, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(2, 2)
            }),
            ("Ixy", &e.ixy, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(0, 1)
            }),
            ("Ixz", &e.ixz, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(0, 2)
            }),
            ("Iyz", &e.iyz, Shape::Scalar, Dim::INERTIA, |_, _| {
                Target::InertiaCom(1, 2)
            }),
        ];
        for (name, entry, shape, dim, make) in entries {
            let Some(entry) = entry else { continue };
            if !have_omega && matches!(name, "angular_momentum" | "kinetic_energy") {
                return Err(self
                    .err(
                        entry.span(),
                        format!("`{name}` needs `omega` in `[analysis]`"),
                    )
                    .help("the expectation is about the body turning at ω"));
            }
            self.expectation(name, entry, shape, dim, make, &mut out)?;
        }
        // Report in file order (stable: components keep their order).
        out.sort_by_key(|c| c.span.start);
        Ok(out)
    }

    fn expectation(
        &self,
        name: &str,
        raw: &Spanned<RawExpectation>,
        shape: Shape,
        dim: Dim,
        make: fn(usize, usize) -> Target,
        out: &mut Vec<Check>,
    ) -> Result<(), Diagnostic> {
        let e = raw.get_ref();
        let span = raw.span();
        // Component keys, each one scalar check.
        let components: [Component<'_>; 12] = [
            ("x", &e.x, Shape::Vector, 0, 0),
            ("y", &e.y, Shape::Vector, 1, 0),
            ("z", &e.z, Shape::Vector, 2, 0),
            ("1", &e.c1, Shape::Ordered, 0, 0),
            ("2", &e.c2, Shape::Ordered, 1, 0),
            ("3", &e.c3, Shape::Ordered, 2, 0),
            ("xx", &e.xx, Shape::Matrix, 0, 0),
            ("yy", &e.yy, Shape::Matrix, 1, 1),
            ("zz", &e.zz, Shape::Matrix, 2, 2),
            ("xy", &e.xy, Shape::Matrix, 0, 1),
            ("xz", &e.xz, Shape::Matrix, 0, 2),
            ("yz", &e.yz, Shape::Matrix, 1, 2),
        ];
        let mut any_component = false;
        for (key, c, cshape, i, j) in components {
            let Some(c) = c else { continue };
            if cshape != shape {
                let message = match shape {
                    Shape::Scalar => {
                        format!("`{name}` is a single number and has no component `{key}`")
                    }
                    Shape::Vector => {
                        format!("`{name}` has no component `{key}`; its components are x, y, z")
                    }
                    Shape::Ordered => format!(
                        "`{name}` has no component `{key}`; its components are 1, 2, 3 (ascending)"
                    ),
                    Shape::Matrix => format!(
                        "`{name}` has no component `{key}`; its components are xx, yy, zz, xy, xz, yz"
                    ),
                };
                return Err(self.err(c.span(), message));
            }
            any_component = true;
            let t = make(i, j);
            let n = format!("{name}.{key}");
            // A component is a single number: one level deeper
            // (`center_of_mass.x.y`) is an error, never a check of nothing.
            if let Some((sub, at)) = first_component(c.get_ref()) {
                return Err(self.err(
                    at,
                    format!("`{n}` is a single number and has no component `{sub}`"),
                ));
            }
            self.expectation_leaf(&n, c, Shape::Scalar, dim, &|_| t, out)?;
        }
        let has_own = e.value.is_some() || e.tol.is_some() || e.min.is_some() || e.max.is_some();
        if has_own {
            let targets = move |k: usize| match shape {
                Shape::Scalar => make(0, 0),
                Shape::Vector | Shape::Ordered => make(k, 0),
                Shape::Matrix => make(k / 3, k % 3),
            };
            self.expectation_leaf(name, raw, shape, dim, &targets, out)?;
        } else if !any_component {
            return Err(self
                .err(span, format!("expectation `{name}` is empty"))
                .help("give `value` and `tol`, or `min` and/or `max`"));
        }
        Ok(())
    }

    /// `value`/`tol` or `min`/`max` of one entry, expanded per component.
    fn expectation_leaf(
        &self,
        name: &str,
        raw: &Spanned<RawExpectation>,
        shape: Shape,
        dim: Dim,
        target: &dyn Fn(usize) -> Target,
        out: &mut Vec<Check>,
    ) -> Result<(), Diagnostic> {
        let e = raw.get_ref();
        let span = raw.span();
        let names: Vec<String> = match shape {
            Shape::Scalar => vec![name.to_string()],
            Shape::Vector => XYZ.iter().map(|c| format!("{name}.{c}")).collect(),
            Shape::Ordered => ORD.iter().map(|c| format!("{name}.{c}")).collect(),
            Shape::Matrix => XYZ
                .iter()
                .flat_map(|a| XYZ.iter().map(move |b| format!("{name}.{a}{b}")))
                .collect(),
        };
        let bounds: Vec<Bound> = match (&e.value, &e.tol, &e.min, &e.max) {
            (Some(v), Some(t), None, None) => {
                let tol = self.tolerance(t, dim)?;
                self.values(name, v, "value", shape, dim)?
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
                    .map(|m| self.values(name, m, "min", shape, dim))
                    .transpose()?;
                let hi = max
                    .as_ref()
                    .map(|m| self.values(name, m, "max", shape, dim))
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
        name: &str,
        v: &Spanned<ExpectValue>,
        key: &str,
        shape: Shape,
        dim: Dim,
    ) -> Result<Vec<f64>, Diagnostic> {
        let q = |x: &Quantity| self.quantity(&Spanned::new(v.span(), x.clone()), key, dim);
        let bad = |what: &str| self.err(v.span(), format!("`{name}`: `{key}` must be {what}"));
        match (shape, v.get_ref()) {
            (Shape::Scalar, ExpectValue::One(x)) => Ok(vec![q(x)?]),
            (Shape::Scalar, _) => Err(bad("a single number")),
            (Shape::Vector | Shape::Ordered, ExpectValue::Many(xs)) if xs.len() == 3 => xs
                .iter()
                .map(|x| match x {
                    ExpectValue::One(x) => q(x),
                    ExpectValue::Many(_) => Err(bad("an array of three numbers")),
                })
                .collect(),
            (Shape::Vector | Shape::Ordered, _) => Err(bad("an array of three numbers")),
            (Shape::Matrix, ExpectValue::Many(rows)) if rows.len() == 3 => {
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
            (Shape::Matrix, _) => Err(bad("three rows of three numbers")),
        }
    }

    /// `tol`: a plain number (absolute, file units), `"0.5%"` (relative) or a
    /// quantity with its own unit (absolute).
    fn tolerance(&self, t: &Spanned<Quantity>, dim: Dim) -> Result<Tol, Diagnostic> {
        let tol = match t.get_ref() {
            Quantity::Text(s) if s.trim_end().ends_with('%') => {
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
            _ => Tol::Abs(self.quantity(t, "tol", dim)?),
        };
        match tol {
            Tol::Abs(x) | Tol::Rel(x) if x >= 0.0 => Ok(tol),
            _ => Err(self.err(t.span(), "`tol` must not be negative")),
        }
    }
}
