//! `check`'s output: one line per file or failure in the form compilers
//! use (`file:line:col: error: …`), or one JSON document (docs/check.md).

use super::format::{DisplayUnits, fmt_num};
use crate::analysis::check::{CheckResult, FileResult, Status, limits};
use crate::analysis::summary::{FORMAT_VERSION, MASSPROP_VERSION};
use crate::diag::visible;
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

#[derive(Serialize)]
struct JsonReport<'a> {
    format_version: u32,
    massprop_version: &'static str,
    files: &'a [FileResult],
    summary: Counts,
}

/// The results as one JSON document.
pub fn json(results: &[FileResult]) -> String {
    super::json_line(&JsonReport {
        format_version: FORMAT_VERSION,
        massprop_version: MASSPROP_VERSION,
        files: results,
        summary: Counts::of(results),
    })
}

/// The results for people and CI logs.
pub fn table(results: &[FileResult]) -> String {
    let mut s = String::new();
    for r in results {
        match r.status {
            Status::Ok => s.push_str(&format!("{}: ok\n", visible(&r.path))),
            Status::Invalid => s.push_str(&format!(
                "{}: invalid (see the error above)\n",
                visible(&r.path)
            )),
            Status::Failed => {
                for v in &r.validity {
                    s.push_str(&format!("{}: error: {v}\n", visible(&r.path)));
                }
                for c in r.checks.iter().filter(|c| !c.pass) {
                    s.push_str(&message(&visible(&r.path), c));
                    s.push('\n');
                }
            }
        }
    }
    let counts = Counts::of(results);
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

/// The line a failed expectation gets, in the form compilers use:
/// `path:line:col: error: NAME VALUE is outside …`, values in the file's
/// units.
pub fn message(path: &str, c: &CheckResult) -> String {
    let units = DisplayUnits::of(c.file_units);
    let show = |x: f64| units.show(x, c.dim);
    let m = c.measured;
    let (lo, hi) = limits(&c.bound);
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
        Bound::Range { .. } => {
            format!(
                "{} {} is above the maximum {} (by {})",
                c.quantity,
                show(m),
                show(hi),
                show(m - hi)
            )
        }
    };
    format!("{path}:{}:{}: error: {message}", c.line, c.column)
}
