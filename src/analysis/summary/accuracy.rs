//! `--precision auto` and `--rtol`: which arithmetic meets the accuracy
//! asked for, judged by the error bounds (docs/accuracy.md, "auto").
//!
//! Each value's bound is held to `rtol` relative to the value itself. A
//! component of a vector or tensor (centre of mass, inertia entries, H, M)
//! that is zero to within its bound (a product of inertia of a symmetric
//! body) is judged against the largest of its kind instead; so is a
//! principal moment, radius of gyration or kinetic energy, but only in
//! `extended`: in `standard` such a value is exactly the smallest moment of
//! a very slender body, which f64 cannot resolve and double-double can, so
//! `auto` recomputes. An axis's bound is an angle, held to `rtol` radians;
//! axes of moments flagged equal are a choice, not judged.

use super::{Model, Products, Summary, SummaryError, summarize_in};
use crate::compose::Precision;
use crate::model::Analysis;
use crate::quantity::{self, Judge, Layout, Quantity, Scale, Value};
use serde::Serialize;

/// `--precision`: an arithmetic, or `auto`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PrecisionChoice {
    /// `standard`, and `extended` where a bound exceeds `--rtol`.
    #[default]
    Auto,
    Standard,
    Extended,
}

/// The default `--rtol`.
pub const DEFAULT_RTOL: f64 = 1e-12;

/// The accuracy asked for: `--precision` and `--rtol`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accuracy {
    pub precision: PrecisionChoice,
    /// Relative, ≥ 2⁻⁵² (no f64 value is closer than its own rounding).
    pub rtol: f64,
}

impl Default for Accuracy {
    fn default() -> Accuracy {
        Accuracy {
            precision: PrecisionChoice::Auto,
            rtol: DEFAULT_RTOL,
        }
    }
}

impl Accuracy {
    /// One arithmetic, at the default `rtol`.
    pub fn fixed(precision: Precision) -> Accuracy {
        Accuracy {
            precision: match precision {
                Precision::Standard => PrecisionChoice::Standard,
                Precision::Extended => PrecisionChoice::Extended,
            },
            ..Accuracy::default()
        }
    }
}

/// A value whose error bound exceeds `--rtol` in the arithmetic used.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AccuracyWarning {
    /// The value's JSON key, with its index: `principal_moments[0]`,
    /// `inertia_com[0][1]`.
    pub quantity: String,
    /// The value (absent for an axis, whose bound is an angle).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    /// Absolute, SI (radians for an axis).
    pub error_bound: f64,
    /// The sentence the table and standard error show.
    pub message: String,
}

pub(super) fn summarize(
    model: &Model,
    analysis: &Analysis,
    products: Products,
    accuracy: &Accuracy,
) -> Result<Summary, SummaryError> {
    let first = match accuracy.precision {
        PrecisionChoice::Auto | PrecisionChoice::Standard => Precision::Standard,
        PrecisionChoice::Extended => Precision::Extended,
    };
    let mut summary = summarize_in(model, analysis, products, first)?;
    let mut short = shortfalls(&summary, accuracy.rtol);
    if !short.is_empty() && accuracy.precision == PrecisionChoice::Auto {
        summary = summarize_in(model, analysis, products, Precision::Extended)?;
        short = shortfalls(&summary, accuracy.rtol);
    }
    summary.rtol = accuracy.rtol;
    summary.requested = accuracy.precision;
    summary.accuracy_warnings = short
        .into_iter()
        .map(|s| s.warning(summary.precision, accuracy.rtol))
        .collect();
    Ok(summary)
}

/// The unit of an axis's bound, which marks it.
const ANGLE: &str = "rad";

/// A value judged, and how.
struct Shortfall {
    quantity: String,
    value: f64,
    bound: f64,
    unit: &'static str,
}

impl Shortfall {
    fn warning(self, precision: Precision, rtol: f64) -> AccuracyWarning {
        let how = match precision {
            Precision::Extended => {
                "even in extended precision: double-double arithmetic does not certify it to that accuracy for the file's numbers (docs/accuracy.md: where the input, or the placement of a sub-assembly, is the limit)"
            }
            Precision::Standard => {
                "in standard precision; `--precision auto` or `extended` computes it in double-double"
            }
        };
        let what = if self.unit == ANGLE {
            format!(
                "the axis `{}` is within {:.2e} rad of the exact one",
                self.quantity, self.bound
            )
        } else {
            let ratio = self.bound / self.value.abs();
            let relative = if ratio.is_finite() {
                format!(" ({ratio:.1e} of it)")
            } else {
                String::new()
            };
            format!(
                "`{}` = {:e} {} is within ±{:.2e} {}{relative}",
                self.quantity, self.value, self.unit, self.bound, self.unit
            )
        };
        AccuracyWarning {
            message: format!("{what}, not --rtol {rtol:e}, {how}"),
            quantity: self.quantity,
            value: (self.unit != ANGLE).then_some(self.value),
            error_bound: self.bound,
        }
    }
}

/// The values of `s` whose bound exceeds `rtol` (see the module's rules),
/// each quantity judged as its row of the table says (`Info::judge`), in
/// its place among the warnings.
fn shortfalls(s: &Summary, rtol: f64) -> Vec<Shortfall> {
    let extended = s.precision == Precision::Extended;
    let mut out = Vec::new();
    // `lenient`: a value zero within its bound is judged against `scale`.
    let mut judge = |name: String, v: f64, e: f64, scale: f64, lenient: bool, unit| {
        let zero = v.abs() <= e;
        let met = e <= rtol * v.abs() || (zero && lenient && e <= rtol * scale);
        if !met {
            out.push(Shortfall {
                quantity: name,
                value: v,
                bound: e,
                unit,
            });
        }
    };
    let top = |q: Quantity| s.reported(q).map_or(0.0, largest);
    let scale = |sc: Scale, v: Value| match sc {
        Scale::Length => top(Quantity::CenterOfMass).max(top(Quantity::RadiiOfGyration)),
        Scale::Moment => top(Quantity::PrincipalMomentsRef).max(top(Quantity::PrincipalMoments)),
        Scale::Own => largest(v),
        Scale::Zero => 0.0,
    };
    for info in quantity::in_order(|i| i.judge.place()) {
        let q = info.quantity;
        let (Some(v), Some(e)) = (s.reported(q), s.error_bounds.of(q)) else {
            continue;
        };
        let key = info.key;
        let each = |i: usize| match info.layout {
            Layout::Scalar => key.to_string(),
            Layout::Vector | Layout::Ordered | Layout::Matrix | Layout::Axes => {
                format!("{key}[{i}]")
            }
        };
        match info.judge {
            Judge::No => {}
            // A vector or tensor as a whole: its largest bound against its
            // largest entry (the relative error of a tensor is a norm's, as
            // the table of docs/accuracy.md gives it: a product of inertia a
            // thousandth of the moments is not held to 1e-12 of itself).
            Judge::Whole(_, sc) => judge(
                key.into(),
                largest(v),
                largest(e),
                scale(sc, v),
                true,
                info.unit,
            ),
            Judge::Each(_, sc) => {
                for i in 0..info.layout.count() {
                    let (x, b) = (v.component(i), e.component(i));
                    judge(each(i), x, b, scale(sc, v), extended, info.unit);
                }
            }
            Judge::Angle(_) => {
                let equal = match v {
                    Value::Axes(_, equal) => equal,
                    Value::Scalar(_) | Value::Triple(_) | Value::Rows(_) => &[],
                };
                for i in (0..3).filter(|i| !equal.contains(i)) {
                    // An angle, held to rtol radians.
                    judge(each(i), 1.0, e.component(i), 1.0, false, ANGLE);
                }
            }
        }
    }
    out
}

/// The largest magnitude among a value's numbers.
fn largest(v: Value) -> f64 {
    let top = |xs: &[f64]| xs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    match v {
        Value::Scalar(x) => x.abs(),
        Value::Triple(t) => top(t),
        Value::Rows(m) | Value::Axes(m, _) => top(m.as_flattened()),
    }
}

/// The values of `s`, and of its predicted body where it has one, whose
/// error bound exceeds `rtol`: the predicted body's prefixed `predicted.`.
pub fn with_predicted(s: &Summary) -> Vec<AccuracyWarning> {
    let mut out = s.accuracy_warnings.clone();
    if let Some(p) = &s.predicted {
        out.extend(p.accuracy_warnings.iter().map(|w| AccuracyWarning {
            quantity: format!("predicted.{}", w.quantity),
            message: format!("the predicted body's {}", w.message),
            ..w.clone()
        }));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Source;

    /// A slender turning rod about a point, in f64 held to f64's own
    /// rounding: most values fall short.
    fn short_of_everything() -> Summary {
        let text = "[[part]]\nshape = \"rod\"\nmass = 3\nlength = 7\ndiameter = 0.001\ncenter = [1, 2, 3]\n[analysis]\nabout = [0, 1, 0]\nomega = [1, 2, 3]\nalpha = [0, 0, 1]\n";
        let model = Model::parse(&Source::new("f.toml", text)).unwrap();
        let accuracy = Accuracy {
            precision: PrecisionChoice::Standard,
            rtol: f64::EPSILON,
        };
        summarize(&model, &model.analysis, Products::Tensor, &accuracy).unwrap()
    }

    #[test]
    fn a_warning_names_a_judged_quantity_by_its_key_and_a_component_by_its_index() {
        let s = short_of_everything();
        assert!(s.accuracy_warnings.len() > 5, "{:?}", s.accuracy_warnings);
        for w in &s.accuracy_warnings {
            let (key, index) = match w.quantity.split_once('[') {
                Some((k, i)) => (k, Some(i.trim_end_matches(']').parse::<usize>().unwrap())),
                None => (w.quantity.as_str(), None),
            };
            let info = quantity::by_key(key).unwrap_or_else(|| panic!("{}", w.quantity));
            let indexed = match info.judge {
                Judge::No => panic!("{key} is not judged"),
                Judge::Whole(..) => false,
                Judge::Each(..) => info.layout != Layout::Scalar,
                Judge::Angle(_) => true,
            };
            assert_eq!(index.is_some(), indexed, "{}", w.quantity);
            assert!(index.is_none_or(|i| i < 3), "{}", w.quantity);
            // An axis's bound is an angle: no value beside it.
            assert_eq!(w.value.is_none(), matches!(info.judge, Judge::Angle(_)));
        }
    }

    #[test]
    fn the_warnings_come_in_the_tables_order_of_judgement() {
        let s = short_of_everything();
        let place = |w: &AccuracyWarning| {
            let key = w.quantity.split('[').next().unwrap();
            quantity::by_key(key).unwrap().judge.place().unwrap()
        };
        let places: Vec<u8> = s.accuracy_warnings.iter().map(place).collect();
        assert!(places.is_sorted(), "{places:?}");
    }
}
