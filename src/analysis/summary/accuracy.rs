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

/// The values of `s` whose bound exceeds `rtol` (see the module's rules).
fn shortfalls(s: &Summary, rtol: f64) -> Vec<Shortfall> {
    let b = &s.error_bounds;
    let extended = s.precision == Precision::Extended;
    let mut out = Vec::new();
    let largest = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
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
    // A vector or tensor as a whole: its largest bound against its largest
    // entry (the relative error of a tensor is a norm's, as the table of
    // docs/accuracy.md gives it: a product of inertia a thousandth of the
    // moments is not held to 1e-12 of itself).
    let mut whole = |name: &str, v: &[f64], e: &[f64], scale: f64, unit| {
        let top = largest(v);
        judge(name.into(), top, largest(e), scale, true, unit);
    };
    let lengths = largest(&s.center_of_mass).max(largest(&s.radii_of_gyration));
    whole(
        "center_of_mass",
        &s.center_of_mass,
        &b.center_of_mass,
        lengths,
        "m",
    );
    whole(
        "center_of_mass_ref",
        &s.center_of_mass_ref,
        &b.center_of_mass_ref,
        lengths,
        "m",
    );
    let tensors = [
        ("inertia_com", &s.inertia_com, &b.inertia_com),
        ("inertia_ref", &s.inertia_ref, &b.inertia_ref),
    ];
    let moments = largest(&s.principal_moments_ref).max(largest(&s.principal_moments));
    for (key, t, e) in tensors {
        whole(key, t.as_flattened(), e.as_flattened(), moments, "kg*m^2");
    }
    for (key, v, e, unit) in [
        (
            "angular_momentum",
            s.angular_momentum,
            b.angular_momentum,
            "N*m*s",
        ),
        ("euler_moment", s.euler_moment, b.euler_moment, "N*m"),
    ] {
        if let (Some(v), Some(e)) = (v, e) {
            whole(key, &v, &e, 0.0, unit);
        }
    }
    judge("mass".into(), s.mass, b.mass, s.mass, extended, "kg");
    for (key, m, e) in [
        (
            "principal_moments",
            &s.principal_moments,
            &b.principal_moments,
        ),
        (
            "principal_moments_ref",
            &s.principal_moments_ref,
            &b.principal_moments_ref,
        ),
    ] {
        for i in 0..3 {
            judge(format!("{key}[{i}]"), m[i], e[i], m[2], extended, "kg*m^2");
        }
    }
    for i in 0..3 {
        let (r, e) = (s.radii_of_gyration[i], b.radii_of_gyration[i]);
        let top = s.radii_of_gyration[2];
        judge(format!("radii_of_gyration[{i}]"), r, e, top, extended, "m");
    }
    for (key, k, e) in [
        (
            "radii_of_gyration_axes",
            &s.radii_of_gyration_axes,
            &b.radii_of_gyration_axes,
        ),
        (
            "radii_of_gyration_axes_ref",
            &s.radii_of_gyration_axes_ref,
            &b.radii_of_gyration_axes_ref,
        ),
    ] {
        for i in 0..3 {
            judge(format!("{key}[{i}]"), k[i], e[i], largest(k), extended, "m");
        }
    }
    for (key, equal, e) in [
        ("principal_axes", &s.equal_moments, &b.principal_axes),
        (
            "principal_axes_ref",
            &s.equal_moments_ref,
            &b.principal_axes_ref,
        ),
    ] {
        for i in (0..3).filter(|i| !equal.contains(i)) {
            // An angle, held to rtol radians.
            judge(format!("{key}[{i}]"), 1.0, e[i], 1.0, false, ANGLE);
        }
    }
    if let (Some(t), Some(e)) = (s.kinetic_energy, b.kinetic_energy) {
        judge("kinetic_energy".into(), t, e, t, extended, "J");
    }
    out
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
