//! `check`'s output: one line per file or failure in the form compilers
//! use (`file:line:col: error: …`), or one JSON document (docs/check.md).

use crate::analysis::check::{FileResult, Status};
use crate::analysis::summary::FORMAT_VERSION;
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
    files: &'a [FileResult],
    summary: Counts,
}

/// The results as one JSON document.
pub fn json(results: &[FileResult]) -> String {
    let mut s = serde_json::to_string(&JsonReport {
        format_version: FORMAT_VERSION,
        files: results,
        summary: Counts::of(results),
    })
    .expect("check results of finite numbers serialize");
    s.push('\n');
    s
}

/// The results for people and CI logs.
pub fn table(results: &[FileResult]) -> String {
    let mut s = String::new();
    for r in results {
        match r.status {
            Status::Ok => s.push_str(&format!("{}: ok\n", r.path)),
            Status::Invalid => s.push_str(&format!("{}: invalid (see the error above)\n", r.path)),
            Status::Failed => {
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
