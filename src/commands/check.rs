//! `massprop check PATH...`: every part file's expectations and physical
//! validity, for CI (docs/check.md).
//!
//! Exit status: 0 when everything holds, 1 when an expectation or a validity
//! check fails, 2 when any file cannot be read or is invalid; every other
//! file is still checked.

use super::{Outcome, bless};
use crate::analysis::check::{FileResult, Status, check_loaded};
use crate::analysis::summary::Accuracy;
use crate::analysis::{self, Settings};
use crate::diag::{Diagnostic, display_path, visible};
use crate::render::{self, Format};
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Part files, and directories searched for `*.toml` (`-` for
    /// standard input); any bytes, UTF-8 or not.
    pub paths: Vec<PathBuf>,
    /// `-o FILE`.
    pub output: Option<String>,
    /// Write the computed values into the files' `[expect]` first.
    pub bless: bool,
    /// `--precision` and `--rtol`.
    pub accuracy: Accuracy,
    pub format: Format,
    /// More directory trees includes may come from.
    pub include_roots: Vec<PathBuf>,
}

/// What a search for part files found. Paths are kept as the file system
/// gave them (a name need not be UTF-8) and shown by `display_path`.
enum Found {
    /// A part file to check: as named (`false`), or found in a directory
    /// (`true`: it must read as a part file before anything of it is
    /// quoted).
    File(PathBuf, bool),
    /// Something that is not checked, with why: a FIFO, socket or device
    /// named `*.toml` (never opened: reading one can block forever), or a
    /// directory that cannot be read. It counts as invalid; the search goes
    /// on.
    Skipped(String, Diagnostic),
}

/// The part files named: files as given, directories searched recursively
/// for `*.toml` in sorted order.
fn collect(paths: &[PathBuf]) -> Vec<Found> {
    /// `root`: the directory named, canonical.
    fn walk(dir: &Path, root: &Path, out: &mut Vec<Found>) {
        let read = match std::fs::read_dir(dir) {
            Ok(read) => read,
            Err(e) => {
                let name = display_path(dir);
                let d = Diagnostic::file(&name, format!("cannot read directory: {e}"));
                return out.push(Found::Skipped(name, d));
            }
        };
        // With each entry's own type (from the directory, not following a
        // symlink): symlinked directories are not followed (as ripgrep does
        // not by default: `ln -s .. up` would loop); symlinked files are,
        // to a part file inside the directory named.
        let mut entries: Vec<(PathBuf, bool, bool)> = read
            .filter_map(|e| e.ok())
            .map(|e| {
                let t = e.file_type();
                let dir = t.as_ref().is_ok_and(|t| t.is_dir());
                let link = t.is_ok_and(|t| t.is_symlink());
                (e.path(), dir, link)
            })
            .collect();
        entries.sort();
        for (p, dir, link) in entries {
            if dir {
                walk(&p, root, out);
            } else if link
                && crate::io::is_toml(&p)
                && std::fs::canonicalize(&p)
                    .is_ok_and(|t| !(t.starts_with(root) && crate::io::is_toml(&t)))
            {
                // A file from a pull request, `x.toml -> ~/.cargo/credentials.toml`
                // or `-> .git/config`, would be read and quoted in the log.
                let name = display_path(&p);
                let d = Diagnostic::file(
                    &name,
                    "not checked: a symlink to a file outside the directory searched, or to one that is not a `*.toml` file (check it by its own path)",
                );
                out.push(Found::Skipped(name, d));
            } else if crate::io::is_toml(&p) {
                // The target's type, without opening it.
                match std::fs::metadata(&p) {
                    Ok(m) if m.is_file() => out.push(Found::File(p, true)),
                    Ok(m) if m.is_dir() => {}
                    _ => {
                        let name = display_path(&p);
                        let d = Diagnostic::file(
                            &name,
                            "not a part file: not a regular file (a FIFO, socket, device or broken link), so not read",
                        );
                        out.push(Found::Skipped(name, d));
                    }
                }
            }
        }
    }
    let mut out = Vec::new();
    for p in paths {
        if p.as_os_str() != "-" && p.is_dir() {
            let root = std::fs::canonicalize(p).unwrap_or_else(|_| p.clone());
            walk(p, &root, &mut out);
        } else {
            out.push(Found::File(p.clone(), false));
        }
    }
    out
}

pub fn run(o: &Options) -> Result<Outcome, Diagnostic> {
    let found = collect(&o.paths);
    if found.is_empty() {
        return Err(Diagnostic::plain(
            "no part files found (`check` looks for *.toml in directories)",
        ));
    }
    let mut results = Vec::new();
    let mut stderr = String::new();
    let settings = Settings {
        accuracy: o.accuracy,
        include_roots: o.include_roots.clone(),
        ..Settings::default()
    };
    let invalid = |path: String, d: Diagnostic, stderr: &mut String| {
        stderr.push_str(&d.to_string());
        FileResult {
            path,
            status: Status::Invalid,
            error: Some(d),
            checks: Vec::new(),
            validity: Vec::new(),
            precision: None,
            accuracy_warnings: Vec::new(),
        }
    };
    // Every file found, valid or not, and every file those include.
    let mut read: Vec<PathBuf> = Vec::new();
    for found in found {
        let (path, found) = match found {
            Found::File(path, found) => (path, found),
            Found::Skipped(path, d) => {
                results.push(invalid(path, d, &mut stderr));
                continue;
            }
        };
        read.extend(std::fs::canonicalize(&path).ok());
        let f = if path.as_os_str() == "-" {
            "<stdin>".to_string()
        } else {
            display_path(&path)
        };
        // A file that cannot be blessed is left untouched. If it is invalid
        // the check below says why; if it is valid, the bless failure
        // itself (standard input, a write error) is the error.
        let mut not_blessed = None;
        if o.bless {
            // NOTE: `bless_file` takes a UTF-8 path; a name that is not
            // UTF-8 is checked, not blessed.
            let blessed = match path.to_str() {
                Some(p) => bless::bless_file(p, &settings),
                None => Err(Diagnostic::file(
                    &f,
                    "`--bless` cannot write a file whose name is not UTF-8; rename it to bless it",
                )),
            };
            match blessed {
                Ok(true) => stderr.push_str(&format!("{}: blessed\n", visible(&f))),
                Ok(false) => stderr.push_str(&format!("{}: unchanged\n", visible(&f))),
                Err(d) => not_blessed = Some(d),
            }
        }
        // A `*.toml` found in a directory that is no part file (a
        // `settings.toml`, a `credentials.toml`) is not checked, and none
        // of it is quoted in an error. Every file a part file includes
        // joins `read` even if it turns out invalid: `-o` may write onto
        // none of them.
        let part_file = |source: crate::diag::Source| {
            if found && !crate::model::looks_like_a_part_file(&source.text) {
                Err(Diagnostic::file(
                    &f,
                    "not a part file: it has no `[[part]]` table, so it is not checked (nor quoted)",
                ))
            } else {
                Ok(source)
            }
        };
        let loaded = crate::io::read_source_at(&path)
            .and_then(part_file)
            .and_then(|source| analysis::load_source_reading(source, &settings, &mut read))
            .map(|l| {
                stderr.push_str(&super::accuracy_warnings(&l));
                check_loaded(&l)
            });
        let checked = match (loaded, not_blessed) {
            (Ok(_), Some(d)) => {
                stderr.push_str(&format!("{}: not blessed\n", visible(&f)));
                Err(d)
            }
            (Err(d), Some(_)) => {
                stderr.push_str(&format!(
                    "{}: not blessed (invalid; left untouched)\n",
                    visible(&f)
                ));
                Err(d)
            }
            (checked, None) => checked,
        };
        match checked {
            Ok(r) => results.push(r),
            Err(d) => results.push(invalid(f, d, &mut stderr)),
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
        stdout: super::Stdout::Text(render::render(&render::Output::Check(&results), o.format)),
        stderr,
        status,
        read,
    })
}
