//! `check`'s output: one line per file or failure in the form compilers
//! use (`file:line:col: error: …`), or one JSON document (docs/check.md).
//! The CI formats (GitHub annotations, JUnit, SARIF) are in `ci`.

use super::format::{DisplayUnits, fmt_num};
use crate::analysis::check::{Against, CheckResult, FileResult, Status, limits};
use crate::analysis::summary::{AccuracyWarning, MASSPROP_VERSION};
use crate::diag::{Diagnostic, Palette, Span, visible};
use crate::model::expect::{Bound, Tol};
use serde::Serialize;

/// How many files ended each way.
#[derive(Debug, Serialize, Default, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    pub files: usize,
    pub ok: usize,
    pub failed: usize,
    pub invalid: usize,
}

impl Counts {
    pub fn of(results: &[FileResult]) -> Counts {
        let count = |s: Status| results.iter().filter(|r| r.status == s).count();
        Counts {
            files: results.len(),
            ok: count(Status::Ok),
            failed: count(Status::Failed),
            invalid: count(Status::Invalid),
        }
    }
}

/// The version of `check`'s JSON contract (docs/check.md): 2 since an
/// invalid file's `error` is an object of fields rather than the rendered
/// message.
pub const CHECK_FORMAT_VERSION: u32 = 2;

#[derive(Serialize)]
struct JsonReport<'a> {
    format_version: u32,
    massprop_version: &'static str,
    files: Vec<JsonFile<'a>>,
    summary: Counts,
}

#[derive(Serialize)]
struct JsonFile<'a> {
    path: &'a str,
    /// `part`, or a robot description's format (`urdf`, `sdf`, `mjcf`).
    kind: &'static str,
    status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<JsonError<'a>>,
    checks: Vec<JsonCheck<'a>>,
    /// The failed validity checks' messages.
    validity: Vec<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    precision: Option<crate::compose::Precision>,
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    accuracy_warnings: &'a [AccuracyWarning],
    /// The plausibility warnings (`analysis::plausible`).
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    warnings: &'a [crate::analysis::plausible::Warning],
    /// A robot description's links (docs/robots.md).
    #[serde(skip_serializing_if = "Option::is_none")]
    links: Option<Vec<JsonLink<'a>>>,
}

/// A link checked, each failing engine's message added.
#[derive(Serialize)]
struct JsonLink<'a> {
    #[serde(flatten)]
    link: &'a crate::robot::check::LinkResult,
    /// Each invalid engine's message, as the table's error line has it.
    messages: Vec<String>,
}

#[derive(Serialize)]
struct JsonCheck<'a> {
    #[serde(flatten)]
    check: &'a CheckResult,
    /// A failure's message, as the table line has it after `error: `.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

/// An invalid file's error as fields: where (the file as named, and the
/// span when there is one) and what.
#[derive(Serialize)]
pub struct JsonError<'a> {
    pub path: &'a str,
    #[serde(flatten)]
    pub span: Option<Span>,
    pub message: &'a str,
    /// What the table prints after the carets under the span.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub help: Option<&'a str>,
    /// The include chain, innermost first.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub notes: &'a [String],
}

impl<'a> JsonError<'a> {
    /// `d`'s fields; `path` names the file when the error has no place.
    pub fn of(d: &'a Diagnostic, path: &'a str) -> JsonError<'a> {
        JsonError {
            path: d.place().map_or(path, |p| &p.path),
            span: d.place().and_then(|p| p.span),
            message: d.message(),
            label: d.label_text(),
            help: d.help_text(),
            notes: d.notes(),
        }
    }
}

/// The results as one JSON document.
pub fn json(results: &[FileResult]) -> String {
    let files = results
        .iter()
        .map(|r| JsonFile {
            path: &r.path,
            kind: kind(r),
            status: r.status,
            error: r.error.as_ref().map(|d| JsonError::of(d, &r.path)),
            checks: r
                .checks
                .iter()
                .map(|c| JsonCheck {
                    check: c,
                    message: (!c.pass).then(|| failure(c)),
                })
                .collect(),
            validity: r.validity_failures().collect(),
            precision: r.precision,
            accuracy_warnings: &r.accuracy_warnings,
            warnings: &r.warnings,
            links: r.robot.as_ref().map(|robot| {
                robot
                    .links
                    .iter()
                    .map(|l| JsonLink {
                        link: l,
                        messages: l
                            .engines
                            .iter()
                            .filter(|e| !e.verdict.valid)
                            .map(|e| super::robot::failure(l, e))
                            .collect(),
                    })
                    .collect()
            }),
        })
        .collect();
    super::json_line(&JsonReport {
        format_version: CHECK_FORMAT_VERSION,
        massprop_version: MASSPROP_VERSION,
        files,
        summary: Counts::of(results),
    })
}

/// What a file is: `part`, or its robot description format's name.
pub fn kind(r: &FileResult) -> &'static str {
    r.format.map_or("part", crate::robot::Dialect::name)
}

/// The results for people and CI logs; `style.colour`: each `error` as
/// cargo colours it (on a terminal); `style.width`: robot tables fitted.
pub fn table(results: &[FileResult], skipped: usize, style: super::Style) -> String {
    table_of(results, skipped, style, false)
}

/// `table`; `quiet` (`--quiet`): without the files that passed, so a long
/// run shows its failures and the summary line only. A robot description
/// that failed, or passed with warnings, keeps its table: its lines are
/// read in it.
pub fn table_of(
    results: &[FileResult],
    skipped: usize,
    style: super::Style,
    quiet: bool,
) -> String {
    let colour = style.colour;
    let e = Palette::of(colour).error;
    let mut s = String::new();
    for r in results {
        let warned = r
            .robot
            .as_ref()
            .is_some_and(|x| x.links.iter().any(|l| !l.warnings.is_empty()));
        if quiet && r.status == Status::Ok && !warned {
            continue;
        }
        if let Some(robot) = &r.robot {
            super::robot::table(&mut s, &r.path, robot, colour, style.width);
            continue;
        }
        match r.status {
            Status::Ok => s.push_str(&format!("{}: ok\n", visible(&r.path))),
            Status::Invalid => s.push_str(&format!(
                "{}: invalid (see the error above)\n",
                visible(&r.path)
            )),
            Status::Failed => {
                for v in r.validity_failures() {
                    s.push_str(&format!(
                        "{}: {e}error{e:#}: {}\n",
                        visible(&r.path),
                        visible(v)
                    ));
                }
                for c in r.checks.iter().filter(|c| !c.pass) {
                    s.push_str(&message_in(&visible(&r.path), c, e));
                    s.push('\n');
                }
            }
        }
    }
    s.push_str(&summary_line(results, skipped));
    s
}

/// `checked N files: A ok, B failed, C invalid`, and `, D skipped` when a
/// directory's search passed files over (`--verbose` names them), as the
/// table and GitHub's annotations end.
pub fn summary_line(results: &[FileResult], skipped: usize) -> String {
    let c = Counts::of(results);
    let skipped = if skipped == 0 {
        String::new()
    } else {
        format!(", {skipped} skipped")
    };
    format!(
        "checked {} file{}: {} ok, {} failed, {} invalid{skipped}\n",
        c.files,
        if c.files == 1 { "" } else { "s" },
        c.ok,
        c.failed,
        c.invalid
    )
}

/// The line a failed expectation gets, in the form compilers use:
/// `path:line:col: error: NAME VALUE is outside …`, values in the file's
/// units.
pub fn message(path: &str, c: &CheckResult) -> String {
    message_in(path, c, anstyle::Style::new())
}

/// `message`, its `error` in `style`; the failure shown by `visible`
/// (one line, whatever the key it names).
fn message_in(path: &str, c: &CheckResult, e: anstyle::Style) -> String {
    format!(
        "{path}:{}:{}: {e}error{e:#}: {}",
        c.line,
        c.column,
        visible(&failure(c))
    )
}

/// What is wrong with a failed expectation: `NAME VALUE is outside …`,
/// values in the file's units.
pub fn failure(c: &CheckResult) -> String {
    match &c.case {
        Some(case) => format!("case `{case}`: {}", failure_of(c)),
        None => failure_of(c),
    }
}

/// `failure`, its case aside.
fn failure_of(c: &CheckResult) -> String {
    let units = DisplayUnits::of(c.file_units);
    let show = |x: f64| units.show(x, c.dim);
    let m = c.measured;
    let (lo, hi) = limits(&c.bound);
    if c.against == Against::BudgetLimit {
        return format!(
            "the predicted mass {} exceeds `[budget] limit` {} (by {})",
            show(m),
            show(hi),
            show(m - hi)
        );
    }
    match c.bound {
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
                c.quantity,
                show(m),
                show(value)
            )
        }
        Bound::Range { .. } if m < lo => {
            format!(
                "{} {} is below the minimum {} (by {})",
                c.quantity,
                show(m),
                show(lo),
                show(lo - m)
            )
        }
        Bound::Axes { tol, .. } => {
            let axis = c.worst_axis.unwrap_or(0);
            // Where two moments are equal only the third axis is
            // determined, and compared; the message says so.
            let only = match c.compared_axes.as_deref() {
                Some([k]) => {
                    let pair: Vec<String> =
                        (1..=3).filter(|j| j != k).map(|j| j.to_string()).collect();
                    format!(
                        "; principal moments {} are equal within their error bounds, so only axis {k} is compared",
                        pair.join(" and ")
                    )
                }
                Some(_) | None => String::new(),
            };
            format!(
                "{} axis {axis} is {}° from the expected axis, beyond `tol_degrees` {}°{only}",
                c.quantity,
                fmt_num(m.to_degrees()),
                fmt_num(tol.to_degrees())
            )
        }
        Bound::Range { .. } => {
            format!(
                "{} {} is above the maximum {} (by {})",
                c.quantity,
                show(m),
                show(hi),
                show(m - hi)
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::summary_line;

    #[test]
    fn the_summary_line_counts_skipped_files_when_there_are_some() {
        assert_eq!(
            summary_line(&[], 2),
            "checked 0 files: 0 ok, 0 failed, 0 invalid, 2 skipped\n"
        );
    }

    #[test]
    fn the_summary_line_without_skipped_files_is_as_before() {
        assert_eq!(
            summary_line(&[], 0),
            "checked 0 files: 0 ok, 0 failed, 0 invalid\n"
        );
    }
}
