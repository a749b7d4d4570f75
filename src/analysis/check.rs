//! What `check` finds in one part file: each `[expect]` entry against the
//! summary, and the body's physical validity. `check_run` walks the
//! files; `output::check` prints the results.

use super::Loaded;
use super::summary::Summary;
use crate::diag::{Diagnostic, Source, Span};
use crate::model::budget::Limit;
use crate::model::expect::{Bound, Check, Target, Tol};
use crate::quantity::Quantity;
use crate::thresholds::VALIDITY_RTOL;
use crate::units::{Dim, FileUnits};
use serde::Serialize;

/// The measured value of one check, SI.
pub fn measured(s: &Summary, t: Target) -> f64 {
    s.value(t)
}

/// Bounds [lo, hi] of a check, SI.
pub fn limits(b: &Bound) -> (f64, f64) {
    b.limits()
}

#[derive(Debug, Clone, Serialize)]
pub struct CheckResult {
    /// The `[[case]]` whose `expect` this is (none: the file's own
    /// `[expect]`, the base body's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
    pub quantity: String,
    pub line: usize,
    pub column: usize,
    /// The entry's last character (inclusive), for CI annotations.
    pub end_line: usize,
    pub end_column: usize,
    /// SI.
    pub measured: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tol: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tol_relative: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
    pub pass: bool,
    /// For axes (`principal_axes`): the axes compared, 1 to 3, those the
    /// principal moments determine (empty when all three are equal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compared_axes: Option<Vec<usize>>,
    /// For axes: the axis (1 to 3) at the largest angle, if any was
    /// compared.
    #[serde(skip)]
    pub worst_axis: Option<usize>,
    /// The expectation, SI, for the message (`output::check::message`).
    #[serde(skip)]
    pub bound: Bound,
    /// The dimension of the value, for its display unit.
    #[serde(skip)]
    pub dim: Dim,
    /// The file's units, in which the message shows the values.
    #[serde(skip)]
    pub file_units: FileUnits,
    /// What the value is held against: an `[expect]` entry, or `[budget]
    /// limit` (`quantity` `budget.limit`).
    #[serde(skip)]
    pub against: Against,
}

/// What a check holds a value against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Against {
    /// An `[expect]` entry.
    Expect,
    /// `[budget] limit`: the not-to-exceed limit of the predicted mass
    /// (docs/budget.md), held by `check` as `budget` holds it.
    BudgetLimit,
}

impl CheckResult {
    /// Its name in a list of checks: the quantity, after its case's name
    /// (`ferry: mass`).
    pub fn label(&self) -> String {
        match &self.case {
            Some(case) => format!("{case}: {}", self.quantity),
            None => self.quantity.clone(),
        }
    }

    /// The entry's place in its file.
    pub fn span(&self) -> Span {
        Span {
            line: self.line,
            column: self.column,
            end_line: self.end_line,
            end_column: self.end_column,
        }
    }
}

/// The outcome for one file, serialised by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Every expectation and validity check holds.
    Ok,
    /// An expectation or validity check does not.
    Failed,
    /// The file cannot be read or is not a valid part file.
    Invalid,
}

/// One file's outcome; `output::check` writes it in each format.
#[derive(Debug, Clone)]
pub struct FileResult {
    pub path: String,
    pub status: Status,
    /// Why the file is invalid.
    pub error: Option<Diagnostic>,
    pub checks: Vec<CheckResult>,
    /// Each physical-validity check, passed or not (none when invalid).
    pub validity: Vec<Validity>,
    /// The arithmetic the file was computed in (absent when invalid).
    pub precision: Option<crate::compose::Precision>,
    /// The values whose error bound exceeds `--rtol` (`summary::accuracy`).
    pub accuracy_warnings: Vec<crate::analysis::summary::AccuracyWarning>,
    /// The plausibility warnings (`analysis::plausible`).
    pub warnings: Vec<crate::analysis::plausible::Warning>,
    /// A robot description's links under each engine (None for a part
    /// file, and for a robot description that cannot be read).
    pub robot: Option<crate::robot::check::RobotResult>,
    /// The robot description format of the file (None: a part file), known
    /// even when it cannot be read.
    pub format: Option<crate::robot::Dialect>,
}

impl FileResult {
    /// The messages of the validity checks that fail.
    pub fn validity_failures(&self) -> impl Iterator<Item = &str> {
        self.validity.iter().filter_map(|v| v.failure.as_deref())
    }
}

/// One physical-validity check: its name (a JUnit test case's) and, when it
/// fails, why.
#[derive(Debug, Clone, PartialEq)]
pub struct Validity {
    pub name: std::borrow::Cow<'static, str>,
    pub failure: Option<String>,
}

/// Evaluate one expectation against a summary.
pub fn evaluate(source: &Source, s: &Summary, c: &Check) -> CheckResult {
    let found = match &c.bound {
        Bound::Axes { rows, .. } => Some(axes(s, rows)),
        Bound::Value { .. } | Bound::Range { .. } => None,
    };
    let m = found
        .as_ref()
        .map_or_else(|| measured(s, c.target), |f| f.angle);
    let (lo, hi) = limits(&c.bound);
    let pass = m >= lo && m <= hi;
    let Span {
        line,
        column,
        end_line,
        end_column,
    } = source.span(c.span.clone());
    let (value, tol, tol_relative, min, max) = match c.bound {
        Bound::Value {
            value,
            tol: Tol::Abs(t),
        } => (Some(value), Some(t), None, None, None),
        Bound::Value {
            value,
            tol: Tol::Rel(r),
        } => (Some(value), None, Some(r), None, None),
        Bound::Range { min, max } => (None, None, None, min, max),
        Bound::Axes { tol, .. } => (None, None, None, None, Some(tol)),
    };
    CheckResult {
        case: None,
        quantity: c.name.clone(),
        line,
        column,
        end_line,
        end_column,
        measured: m,
        value,
        tol,
        tol_relative,
        min,
        max,
        pass,
        compared_axes: found
            .as_ref()
            .map(|f| f.compared.iter().map(|k| k + 1).collect()),
        worst_axis: found.and_then(|f| f.worst).map(|k| k + 1),
        bound: c.bound,
        dim: c.dim,
        file_units: s.file_units,
        against: Against::Expect,
    }
}

/// What an expectation of principal axes finds.
#[derive(Debug, Clone, PartialEq)]
pub struct AxesFound {
    /// The largest angle between an expected axis and the computed one,
    /// radians (0 when none is compared).
    pub angle: f64,
    /// The axes compared (0-based): those the principal moments determine.
    pub compared: Vec<usize>,
    /// The axis at the largest angle, if any was compared.
    pub worst: Option<usize>,
}

/// Expected principal axes (rows, ascending moments) against the
/// computed ones. An axis and its negative are the same axis: the angle
/// is atan2(|e × a|, |e · a|), 0 to 90°. Where two principal moments are
/// equal (`Summary::equal_moments`) or within their error bounds of each
/// other, their axes are any two at right angles in a plane: only the
/// third, distinct axis is compared (the plane is the one at right angles
/// to it, for both); where all three are, any axes pass.
pub fn axes(s: &Summary, expected: &[[f64; 3]; 3]) -> AxesFound {
    let mut found = AxesFound {
        angle: 0.0,
        compared: determined(s),
        worst: None,
    };
    for &k in &found.compared {
        let angle = angle_between(&expected[k], &s.principal_axes[k]);
        if found.worst.is_none() || angle > found.angle {
            found.angle = angle;
            found.worst = Some(k);
        }
    }
    found
}

/// The principal axes (0-based) a summary's moments determine: all three
/// where the moments differ; where two are equal (`Summary::equal_moments`)
/// or within their error bounds of each other, only the third; none where
/// all three are.
pub fn determined(s: &Summary) -> Vec<usize> {
    let m = s.principal_moments;
    let bound = s.error_bounds.principal_moments;
    let equal = |i: usize, j: usize| {
        (s.equal_moments.contains(&i) && s.equal_moments.contains(&j))
            || (m[j] - m[i]).abs() <= bound[i] + bound[j]
    };
    match (equal(0, 1), equal(1, 2)) {
        (true, true) => vec![],
        (true, false) => vec![2],
        (false, true) => vec![0],
        (false, false) => vec![0, 1, 2],
    }
}

/// The angle between two lines (directions `e`, `a`, any lengths but
/// zero), 0 to π/2: an axis is its own negative.
/// NOTE: atan2 of the cross and dot products, not acos of the dot: acos
/// loses half the digits of a small angle.
pub fn angle_between(e: &[f64; 3], a: &[f64; 3]) -> f64 {
    let cross = [
        e[1] * a[2] - e[2] * a[1],
        e[2] * a[0] - e[0] * a[2],
        e[0] * a[1] - e[1] * a[0],
    ];
    let dot: f64 = (0..3).map(|j| e[j] * a[j]).sum();
    crate::numeric::norm(&cross).atan2(dot.abs())
}

/// `[budget] limit` against the predicted mass, at the `limit` entry: the
/// check `budget`'s exit status makes. (`[expect] mass` holds the basic
/// mass; `--bless` writes neither a limit nor anything of it.)
pub fn budget_limit(source: &Source, s: &Summary, limit: &Limit) -> CheckResult {
    let c = Check {
        name: "budget.limit".to_string(),
        target: Target {
            quantity: Quantity::PredictedMass,
            component: 0,
        },
        bound: Bound::Range {
            min: None,
            max: Some(limit.mass),
        },
        dim: Dim::MASS,
        span: limit.span.clone(),
    };
    CheckResult {
        against: Against::BudgetLimit,
        ..evaluate(source, s, &c)
    }
}

/// Physical validity: positive mass, no negative principal moment, and the
/// triangle inequality I1 + I2 ≥ I3, each to `VALIDITY_RTOL` of I3.
pub fn validity(s: &Summary) -> Vec<Validity> {
    let [i1, i2, i3] = s.principal_moments;
    let tol = VALIDITY_RTOL * i3.abs();
    let check = |name: &'static str, fails: bool, message: &dyn Fn() -> String| Validity {
        name: name.into(),
        failure: fails.then(message),
    };
    vec![
        check("mass is positive", !(s.mass > 0.0), &|| {
            format!("total mass {} kg is not positive", s.mass)
        }),
        check("inertia is positive definite", i1 < -tol, &|| {
            format!(
                "inertia is not positive definite: principal moment I1 = {i1:e} kg·m² is negative"
            )
        }),
        check("triangle inequality", i1 + i2 < i3 - tol, &|| {
            format!(
                "principal moments violate the triangle inequality: I1 + I2 = {:e} < I3 = {i3:e} kg·m²",
                i1 + i2
            )
        }),
    ]
}

/// The messages of the validity checks that fail.
pub fn validity_failures(s: &Summary) -> Vec<String> {
    validity(s).into_iter().filter_map(|v| v.failure).collect()
}

/// The expectations and validity of a file that loaded.
pub fn check_loaded(loaded: &Loaded) -> FileResult {
    let validity = validity(&loaded.summary);
    let mut checks: Vec<CheckResult> = loaded
        .model
        .expect
        .iter()
        .map(|c| evaluate(&loaded.source, &loaded.summary, c))
        .collect();
    if let Some(limit) = &loaded.model.budget {
        checks.push(budget_limit(&loaded.source, &loaded.summary, limit));
    }
    let ok = validity.iter().all(|v| v.failure.is_none()) && checks.iter().all(|c| c.pass);
    FileResult {
        path: loaded.source.name.clone(),
        status: if ok { Status::Ok } else { Status::Failed },
        error: None,
        checks,
        validity,
        precision: Some(loaded.summary.precision),
        accuracy_warnings: super::summary::accuracy::with_predicted(&loaded.summary),
        warnings: loaded.summary.warnings.clone(),
        robot: None,
        format: None,
    }
}

/// Each `[[case]]`'s own `expect` of a file checked (`check_loaded`),
/// its body summarized with the file's settings: each result names its
/// case, in file order after the file's own.
pub fn check_cases(
    loaded: &Loaded,
    settings: &super::Settings,
    r: &mut FileResult,
) -> Result<(), Diagnostic> {
    for case in &loaded.model.cases {
        if case.model.expect.is_empty() {
            continue;
        }
        let one = super::cases::load_of(loaded, case, settings)?;
        for c in &case.model.expect {
            let result = CheckResult {
                case: Some(case.name.clone()),
                ..evaluate(&loaded.source, &one.summary, c)
            };
            if !result.pass && r.status == Status::Ok {
                r.status = Status::Failed;
            }
            r.checks.push(result);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary() -> Summary {
        let source = Source::new(
            "t.toml",
            "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n",
        );
        crate::analysis::load_source(source, &crate::analysis::Settings::default())
            .unwrap()
            .summary
    }

    #[test]
    fn a_real_body_is_physically_valid() {
        let v = validity(&summary());
        assert_eq!(v.len(), 3);
        assert!(v.iter().all(|v| v.failure.is_none()), "{v:?}");
    }

    #[test]
    fn a_negative_principal_moment_is_reported() {
        let mut s = summary();
        // Sorted moments with a negative I1 also break I1 + I2 ≥ I3.
        s.principal_moments = [-1e-3, 10.0, 10.0];
        let v = validity_failures(&s);
        assert!(
            v.iter().any(|m| m.contains("not positive definite")),
            "{v:?}"
        );
    }

    #[test]
    fn rounding_below_the_tolerance_is_not_a_violation() {
        let mut s = summary();
        s.principal_moments = [-1e-15, 5.0, 5.0];
        assert!(validity_failures(&s).is_empty());
    }

    #[test]
    fn the_triangle_inequality_is_checked() {
        let mut s = summary();
        s.principal_moments = [1.0, 2.0, 4.0];
        let v = validity_failures(&s);
        assert_eq!(v.len(), 1);
        assert!(v[0].contains("triangle inequality"), "{v:?}");
    }

    #[test]
    fn a_non_positive_mass_is_reported() {
        let mut s = summary();
        s.mass = -1.0;
        assert!(validity_failures(&s)[0].contains("not positive"));
    }
}
