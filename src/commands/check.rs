//! `massprop check PATH...`: every part file's expectations and physical
//! validity, for CI (docs/check.md).
//!
//! Exit status: 0 when everything holds, 1 when an expectation or a validity
//! check fails, 2 when any file cannot be read or is invalid; every other
//! file is still checked.

use super::{Outcome, bless};
use crate::analysis::check::{FileResult, Status, check_loaded};
use crate::analysis::{self, Settings};
use crate::compose::Precision;
use crate::diag::Diagnostic;
use crate::render::{self, Format};
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Part files, and directories searched for `*.toml`.
    pub paths: Vec<String>,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Write the computed values into the files' `[expect]` first.
    pub bless: bool,
    pub precision: Precision,
    pub format: Format,
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

pub fn run(o: &Options) -> Result<Outcome, Diagnostic> {
    let files = collect(&o.paths)?;
    if files.is_empty() {
        return Err(Diagnostic::plain(
            "no part files found (`check` looks for *.toml in directories)",
        ));
    }
    let mut results = Vec::new();
    let mut stderr = String::new();
    let settings = Settings {
        precision: o.precision,
        ..Settings::default()
    };
    // Every file found, valid or not, and every file those include.
    let mut read: Vec<PathBuf> = files
        .iter()
        .filter_map(|f| std::fs::canonicalize(f).ok())
        .collect();
    for f in &files {
        // A file that cannot be blessed is left untouched. If it is invalid
        // the check below says why; if it is valid, the bless failure
        // itself (standard input, a write error) is the error.
        let mut not_blessed = None;
        if o.bless {
            match bless::bless_file(f, o.precision) {
                Ok(true) => stderr.push_str(&format!("{f}: blessed\n")),
                Ok(false) => stderr.push_str(&format!("{f}: unchanged\n")),
                Err(d) => not_blessed = Some(d),
            }
        }
        let loaded = analysis::load(f, &settings).map(|l| {
            read.extend(super::files_of(&l));
            check_loaded(&l)
        });
        let checked = match (loaded, not_blessed) {
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
            Ok(r) => results.push(r),
            Err(d) => {
                stderr.push_str(&d.to_string());
                results.push(FileResult {
                    path: f.clone(),
                    status: Status::Invalid,
                    error: Some(d.to_string()),
                    checks: Vec::new(),
                    validity: Vec::new(),
                });
            }
        }
    }
    let worst = |s: Status| results.iter().any(|r| r.status == s);
    let status = if worst(Status::Invalid) {
        2
    } else if worst(Status::Failed) {
        1
    } else {
        0
    };
    Ok(Outcome {
        stdout: render::render(&render::Output::Check(&results), o.format),
        stderr,
        status,
        read,
    })
}
