//! `massprop check PATH...`: every part file's expectations and physical
//! validity, reported the way compilers report errors, for CI.
//!
//! Exit status: 0 when everything holds, 1 when an expectation or a validity
//! check fails, 2 when any file cannot be read or is invalid; every other
//! file is still checked.

use crate::Output;
use crate::cli::{CheckArgs, Format};
use crate::compose::Precision;
use crate::diag::{Diagnostic, Source};
use crate::model::Model;
use crate::model::expect::{Bound, Check, Target, Tol};
use crate::report::{self, Products, Summary, table::fmt_num};
use crate::units::{Dim, FileUnits};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// A validity check fails when a moment is below −tolerance; the tolerance
/// is this multiple of the largest moment: far above rounding (~1e-16), far
/// below any physical effect.
pub const VALIDITY_RTOL: f64 = 1e-12;

/// The measured value of one check, SI.
pub(crate) fn measured(s: &Summary, t: Target) -> f64 {
    match t {
        Target::Mass => s.mass,
        Target::CenterOfMass(i) => s.center_of_mass[i],
        Target::PrincipalMoment(i) => s.principal_moments[i],
        Target::InertiaCom(i, j) => s.inertia_com[i][j],
        Target::InertiaRef(i, j) => s.inertia_ref[i][j],
        Target::RadiusOfGyration(i) => s.radii_of_gyration[i],
        Target::AngularMomentum(i) => s.angular_momentum.map_or(f64::NAN, |h| h[i]),
        Target::KineticEnergy => s.kinetic_energy.unwrap_or(f64::NAN),
    }
}

/// Bounds [lo, hi] of a check, SI.
fn limits(b: &Bound) -> (f64, f64) {
    match *b {
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
    }
}

/// How a value of dimension `dim` is shown: scale (SI per unit) and label.
pub(crate) fn display_unit(dim: Dim, u: FileUnits) -> (f64, String) {
    match dim {
        Dim::MASS => (u.factor(dim).value(), u.mass.to_string()),
        Dim::LENGTH => (u.factor(dim).value(), u.length.to_string()),
        Dim::INERTIA => (u.factor(dim).value(), u.inertia_label()),
        Dim::ANGULAR_MOMENTUM => (1.0, "N·m·s".to_string()),
        Dim::ENERGY => (1.0, "J".to_string()),
        _ => (1.0, String::new()),
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct CheckResult {
    pub quantity: String,
    pub line: usize,
    pub column: usize,
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
    /// The message shown when it fails.
    #[serde(skip)]
    pub message: String,
}

#[derive(Debug, Clone, Serialize)]
pub struct FileResult {
    pub path: String,
    /// "ok", "failed" or "invalid".
    pub status: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    pub checks: Vec<CheckResult>,
    /// Physical validity failures (empty when valid).
    pub validity: Vec<String>,
}

/// Evaluate one expectation against a summary.
pub fn evaluate(source: &Source, s: &Summary, c: &Check) -> CheckResult {
    let m = measured(s, c.target);
    let (lo, hi) = limits(&c.bound);
    let pass = m >= lo && m <= hi;
    let (line, column) = source.line_col(c.span.start);
    let (scale, unit) = display_unit(c.dim, s.file_units);
    let show = |x: f64| {
        format!("{} {unit}", fmt_num(x / scale))
            .trim_end()
            .to_string()
    };
    let message = match c.bound {
        Bound::Value { value, tol } => {
            let tol_text = match tol {
                Tol::Abs(t) => show(t),
                Tol::Rel(r) => format!("{} %", fmt_num(r * 100.0)),
            };
            // Relative when that is a readable finite number; absolute when
            // the value is zero or so small (subnormal) that the ratio
            // overflows; left out when even the difference overflows.
            let percent = (m - value) / value.abs() * 100.0;
            let off = if value != 0.0 && percent.is_finite() && percent.abs() < 1e6 {
                format!(" (off by {percent:+.3} %)")
            } else if value != 0.0 && percent.is_finite() {
                format!(" (off by {percent:+.3e} %)")
            } else if (m - value).is_finite() {
                let sign = if m >= value { "+" } else { "" };
                format!(" (off by {sign}{})", show(m - value))
            } else {
                String::new()
            };
            format!(
                "{} {} is outside {} ± {tol_text}{off}",
                c.name,
                show(m),
                show(value)
            )
        }
        Bound::Range { .. } if m < lo => {
            format!(
                "{} {} is below the minimum {} (by {})",
                c.name,
                show(m),
                show(lo),
                show(lo - m)
            )
        }
        Bound::Range { .. } => {
            format!(
                "{} {} is above the maximum {} (by {})",
                c.name,
                show(m),
                show(hi),
                show(m - hi)
            )
        }
    };
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
    };
    CheckResult {
        quantity: c.name.clone(),
        line,
        column,
        measured: m,
        value,
        tol,
        tol_relative,
        min,
        max,
        pass,
        message: format!("{}:{line}:{column}: error: {message}", source.name),
    }
}

/// Physical validity: positive mass, no negative principal moment, and the
/// triangle inequality I1 + I2 ≥ I3, each to `VALIDITY_RTOL` of I3.
pub fn validity(s: &Summary) -> Vec<String> {
    let mut out = Vec::new();
    let [i1, i2, i3] = s.principal_moments;
    let tol = VALIDITY_RTOL * i3.abs();
    if !(s.mass > 0.0) {
        out.push(format!("total mass {} kg is not positive", s.mass));
    }
    if i1 < -tol {
        out.push(format!(
            "inertia is not positive definite: principal moment I1 = {i1:e} kg·m² is negative"
        ));
    }
    if i1 + i2 < i3 - tol {
        out.push(format!(
            "principal moments violate the triangle inequality: I1 + I2 = {:e} < I3 = {i3:e} kg·m²",
            i1 + i2
        ));
    }
    out
}

/// Check one file; `Err` when it cannot be read or is invalid.
pub fn check_file(path: &str, precision: Precision) -> Result<FileResult, Diagnostic> {
    let source = crate::read_source(path)?;
    let model = Model::parse(&source)?;
    let summary = report::summarize(&model, &model.analysis, Products::Tensor, precision)
        .map_err(|e| e.diagnostic(&model, &model.analysis, &source))?;
    let validity = validity(&summary);
    let checks: Vec<CheckResult> = model
        .expect
        .iter()
        .map(|c| evaluate(&source, &summary, c))
        .collect();
    let ok = validity.is_empty() && checks.iter().all(|c| c.pass);
    Ok(FileResult {
        path: source.name.clone(),
        status: if ok { "ok" } else { "failed" },
        error: None,
        checks,
        validity,
    })
}

/// The part files named: files as given, directories searched recursively
/// for `*.toml` in sorted order.
fn collect(paths: &[String]) -> Result<Vec<String>, Diagnostic> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> Result<(), Diagnostic> {
        let read = std::fs::read_dir(dir).map_err(|e| {
            Diagnostic::file(
                &dir.display().to_string(),
                format!("cannot read directory: {e}"),
            )
        })?;
        // With each entry's own type (from the directory, not following a
        // symlink): symlinked directories are not followed (as ripgrep does
        // not by default: `ln -s .. up` would loop); symlinked files are.
        let mut entries: Vec<(PathBuf, bool)> = read
            .filter_map(|e| e.ok())
            .map(|e| (e.path(), e.file_type().is_ok_and(|t| t.is_dir())))
            .collect();
        entries.sort();
        for (p, dir) in entries {
            if dir {
                walk(&p, out)?;
            } else if p.extension().is_some_and(|e| e == "toml") && !p.is_dir() {
                out.push(p);
            }
        }
        Ok(())
    }
    let mut out = Vec::new();
    for p in paths {
        let path = Path::new(p);
        if p != "-" && path.is_dir() {
            let mut found = Vec::new();
            walk(path, &mut found)?;
            out.extend(found.into_iter().map(|f| f.display().to_string()));
        } else {
            out.push(p.clone());
        }
    }
    Ok(out)
}

#[derive(Serialize)]
struct JsonReport<'a> {
    format_version: u32,
    files: &'a [FileResult],
    summary: Counts,
}

#[derive(Serialize, Default)]
struct Counts {
    files: usize,
    ok: usize,
    failed: usize,
    invalid: usize,
}

pub fn run(args: &CheckArgs) -> Result<Output, Diagnostic> {
    let files = collect(&args.paths)?;
    if files.is_empty() {
        return Err(Diagnostic::plain(
            "no part files found (`check` looks for *.toml in directories)",
        ));
    }
    let mut results = Vec::new();
    let mut stderr = String::new();
    let mut counts = Counts {
        files: files.len(),
        ..Counts::default()
    };
    for f in &files {
        // A file that cannot be blessed is left untouched. If it is invalid
        // the check below says why; if it is valid, the bless failure
        // itself (standard input, a write error) is the error.
        let mut not_blessed = None;
        if args.bless {
            match crate::bless::bless_file(f, args.precision) {
                Ok(true) => stderr.push_str(&format!("{f}: blessed\n")),
                Ok(false) => stderr.push_str(&format!("{f}: unchanged\n")),
                Err(d) => not_blessed = Some(d),
            }
        }
        let checked = check_file(f, args.precision);
        let checked = match (checked, not_blessed) {
            (Ok(_), Some(d)) => {
                stderr.push_str(&format!("{f}: not blessed\n"));
                Err(d)
            }
            (Err(d), Some(_)) => {
                stderr.push_str(&format!("{f}: not blessed (invalid; left untouched)\n"));
                Err(d)
            }
            (checked, None) => checked,
        };
        match checked {
            Ok(r) => {
                if r.status == "ok" {
                    counts.ok += 1;
                } else {
                    counts.failed += 1;
                }
                results.push(r);
            }
            Err(d) => {
                counts.invalid += 1;
                stderr.push_str(&d.to_string());
                results.push(FileResult {
                    path: f.clone(),
                    status: "invalid",
                    error: Some(d.to_string()),
                    checks: Vec::new(),
                    validity: Vec::new(),
                });
            }
        }
    }
    let status = if counts.invalid > 0 {
        2
    } else if counts.failed > 0 {
        1
    } else {
        0
    };
    let stdout = match args.format {
        Format::Json => {
            let mut s = serde_json::to_string(&JsonReport {
                format_version: report::FORMAT_VERSION,
                files: &results,
                summary: counts,
            })
            .expect("check results of finite numbers serialize");
            s.push('\n');
            s
        }
        Format::Table => {
            let mut s = String::new();
            for r in &results {
                match r.status {
                    "ok" => s.push_str(&format!("{}: ok\n", r.path)),
                    "invalid" => {
                        s.push_str(&format!("{}: invalid (see the error above)\n", r.path))
                    }
                    _ => {
                        for v in &r.validity {
                            s.push_str(&format!("{}: error: {v}\n", r.path));
                        }
                        for c in r.checks.iter().filter(|c| !c.pass) {
                            s.push_str(&c.message);
                            s.push('\n');
                        }
                    }
                }
            }
            s.push_str(&format!(
                "checked {} file{}: {} ok, {} failed, {} invalid\n",
                counts.files,
                if counts.files == 1 { "" } else { "s" },
                counts.ok,
                counts.failed,
                counts.invalid
            ));
            s
        }
    };
    Ok(Output {
        stdout,
        stderr,
        status,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary() -> Summary {
        let source = Source::new(
            "t.toml",
            "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n",
        );
        let model = Model::parse(&source).unwrap();
        report::summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            Precision::Standard,
        )
        .unwrap()
    }

    #[test]
    fn a_real_body_is_physically_valid() {
        assert!(validity(&summary()).is_empty());
    }

    #[test]
    fn a_negative_principal_moment_is_reported() {
        let mut s = summary();
        // Sorted moments with a negative I1 also break I1 + I2 ≥ I3.
        s.principal_moments = [-1e-3, 10.0, 10.0];
        let v = validity(&s);
        assert!(
            v.iter().any(|m| m.contains("not positive definite")),
            "{v:?}"
        );
    }

    #[test]
    fn rounding_below_the_tolerance_is_not_a_violation() {
        let mut s = summary();
        s.principal_moments = [-1e-15, 5.0, 5.0];
        assert!(validity(&s).is_empty());
    }

    #[test]
    fn the_triangle_inequality_is_checked() {
        let mut s = summary();
        s.principal_moments = [1.0, 2.0, 4.0];
        let v = validity(&s);
        assert_eq!(v.len(), 1);
        assert!(v[0].contains("triangle inequality"), "{v:?}");
    }

    #[test]
    fn a_non_positive_mass_is_reported() {
        let mut s = summary();
        s.mass = -1.0;
        assert!(validity(&s)[0].contains("not positive"));
    }
}
