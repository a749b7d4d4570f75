//! `massprop check PATH...`: every part file's expectations and physical
//! validity, for CI (docs/check.md).
//!
//! Exit status: 0 when everything holds, 1 when an expectation or a validity
//! check fails, 2 when any file cannot be read or is invalid; every other
//! file is still checked.

use super::Outcome;
use crate::analysis::bless;
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
    /// `--axes`, as typed.
    pub axes: Option<String>,
    /// `--include-root` and `--base-dir`.
    pub includes: crate::model::Includes,
    /// How directories are searched.
    pub search: Search,
    /// The engines whose rules robot descriptions are checked by
    /// (`--engine`; all of them by default).
    pub engines: Vec<crate::robot::engine::Engine>,
}

/// What a search for part files found. Paths are kept as the file system
/// gave them (a name need not be UTF-8) and shown by `display_path`.
enum Found {
    /// A part file to check: as named (`false`), or found in a directory
    /// (`true`: a `*.toml` that does not read as a part file, such as
    /// `Cargo.toml`, is passed over, and nothing of it is quoted).
    File(PathBuf, bool),
    /// Something that is not checked, with why: a FIFO, socket or device
    /// named `*.toml` (never opened: reading one can block forever), or a
    /// directory that cannot be read. It counts as invalid; the search goes
    /// on.
    Skipped(String, Diagnostic),
}

/// How directories are searched (`--hidden`, `--exclude`).
#[derive(Debug, Clone, Default)]
pub struct Search {
    /// Hidden files and directories (names starting with `.`) too.
    pub hidden: bool,
    /// Globs of paths not to check, as in a `.gitignore` (relative to the
    /// directory searched).
    pub exclude: Vec<String>,
}

/// The part files named: files as given; directories searched recursively
/// as ripgrep searches them (the `ignore` crate: `.gitignore`, `.ignore`
/// and git's excludes honoured, hidden entries skipped unless
/// `--hidden`, `--exclude` globs), `*.toml` files in sorted order.
fn collect(paths: &[PathBuf], search: &Search) -> Result<Vec<Found>, Diagnostic> {
    /// `root`: the directory named, canonical.
    fn walk(
        dir: &Path,
        root: &Path,
        search: &Search,
        out: &mut Vec<Found>,
    ) -> Result<(), Diagnostic> {
        let mut excluded = ignore::overrides::OverrideBuilder::new(dir);
        for glob in &search.exclude {
            excluded
                .add(&format!("!{glob}"))
                .map_err(|e| Diagnostic::plain(format!("--exclude `{}`: {e}", visible(glob))))?;
        }
        let excluded = excluded
            .build()
            .map_err(|e| Diagnostic::plain(format!("--exclude: {e}")))?;
        // Symlinked directories are not followed (as ripgrep does not by
        // default: `ln -s .. up` would loop); symlinked files are, to a part
        // file inside the directory named.
        let walker = ignore::WalkBuilder::new(dir)
            .hidden(!search.hidden)
            .overrides(excluded)
            .follow_links(false)
            .sort_by_file_name(|a, b| a.cmp(b))
            .build();
        for entry in walker {
            let entry = match entry {
                Ok(entry) => entry,
                Err(e) => {
                    // An unreadable directory, or an ignore file that cannot
                    // be read or parsed: said, and the search goes on.
                    let name = display_path(dir);
                    let d = Diagnostic::file(&name, format!("cannot search: {e}"));
                    out.push(Found::Skipped(name, d));
                    continue;
                }
            };
            // Its own type (from the directory, not following a symlink).
            let Some(t) = entry.file_type() else {
                continue;
            };
            let p = entry.path();
            let wanted = |p: &Path| crate::io::is_toml(p) || crate::robot::may_be_robot(p);
            if t.is_dir() || !wanted(p) {
                continue;
            }
            if t.is_symlink()
                && std::fs::canonicalize(p).is_ok_and(|t| !(t.starts_with(root) && wanted(&t)))
            {
                // A file from a pull request, `x.toml -> ~/.cargo/credentials.toml`
                // or `-> .git/config`, would be read and quoted in the log.
                let name = display_path(p);
                let d = Diagnostic::file(
                    &name,
                    "not checked: a symlink to a file outside the directory searched, or to one that is not a `*.toml` file or robot description (check it by its own path)",
                );
                out.push(Found::Skipped(name, d));
                continue;
            }
            // The target's type, without opening it.
            match std::fs::metadata(p) {
                Ok(m) if m.is_file() => out.push(Found::File(p.to_path_buf(), true)),
                Ok(m) if m.is_dir() => {}
                _ => {
                    let name = display_path(p);
                    let d = Diagnostic::file(
                        &name,
                        "not a part file: not a regular file (a FIFO, socket, device or broken link), so not read",
                    );
                    out.push(Found::Skipped(name, d));
                }
            }
        }
        Ok(())
    }
    let mut out = Vec::new();
    for p in paths {
        if p.as_os_str() != "-" && p.is_dir() {
            let root = std::fs::canonicalize(p).unwrap_or_else(|_| p.clone());
            walk(p, &root, search, &mut out)?;
        } else {
            out.push(Found::File(p.clone(), false));
        }
    }
    Ok(out)
}

/// `terminal.stdout` is the output's style (`-o`'s file's when it has one);
/// invalid files' errors and warnings go to standard error, in its.
pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let colour = terminal.stderr.colour;
    // NOTE: `--bless` writes what the file computes into its `[expect]`;
    // under `--set` that would be a what-if's values, which the file
    // without the flag does not compute.
    if o.bless && !o.includes.set.is_empty() {
        return Err(Diagnostic::plain(
            "`--set` cannot be used with `--bless`: the expectations written would be those of the overridden parameters, not of the file",
        )
        .help("change the parameter in the file's `[params]`, then bless"));
    }
    if let Some(t) = &o.axes {
        analysis::flag_axes(t)?;
    }
    let found = collect(&o.paths, &o.search)?;
    let settings = Settings {
        accuracy: o.accuracy,
        includes: o.includes.clone(),
        overrides: crate::analysis::Overrides {
            axes: o.axes.clone(),
            ..Default::default()
        },
        // `predicted_*` expectations and `[budget] limit` read it.
        predicted: true,
        ..Settings::default()
    };
    let each = Each {
        o,
        settings: &settings,
        colour,
    };
    let (results, stderr, read) = each.all(found);
    if results.is_empty() {
        return Err(Diagnostic::plain(
            "no part files or robot descriptions found (a directory is searched for `*.toml` files with a `[[part]]` table, and for `*.urdf`, `*.sdf` and `*.xml` robot descriptions; hidden and ignored ones are passed over)",
        ));
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
        stdout: super::Stdout::Text(render::render(
            &render::Output::Check(&results),
            o.format,
            terminal.stdout,
        )),
        stderr,
        status,
        read,
    })
}

/// The stack of the thread that checks the files: far more than any
/// check needs. NOTE: no reader recurses on a depth the input chooses
/// (group paths, expressions, TOML and XML are bounded or walked with
/// stacks of their own); this is the margin for one that someday does,
/// as `guarded` is for a panic: one file must never take the other files'
/// results, and the report, with it. Reserved, not committed: the pages
/// never touched cost nothing.
const STACK: usize = 256 << 20;

/// What the check of every file shares.
struct Each<'a> {
    o: &'a Options,
    settings: &'a Settings,
    colour: bool,
}

impl Each<'_> {
    /// Every file found, in order, on a thread of a large stack (`STACK`),
    /// a file's panic its own result (`guarded`): the results, standard
    /// error, and every file read (those the files include too, valid or
    /// not: `-o` may write onto none of them).
    fn all(&self, found: Vec<Found>) -> (Vec<FileResult>, String, Vec<PathBuf>) {
        let found = std::sync::Mutex::new(Some(found));
        let work = || {
            let found = found.lock().ok().and_then(|mut f| f.take());
            self.each(found.unwrap_or_default())
        };
        std::thread::scope(|scope| {
            let w = &work;
            match std::thread::Builder::new()
                .name("check".to_string())
                .stack_size(STACK)
                .spawn_scoped(scope, w)
            {
                Ok(thread) => thread
                    .join()
                    .expect("invariant: a file's panic is caught by `guarded`"),
                // No thread to be had (a limit on threads or memory): the
                // files are checked here, on this thread's stack.
                Err(_) => work(),
            }
        })
    }

    fn each(&self, found: Vec<Found>) -> (Vec<FileResult>, String, Vec<PathBuf>) {
        let (mut results, mut stderr, mut read) = (Vec::new(), String::new(), Vec::new());
        for found in found {
            let name = match &found {
                Found::File(path, _) if path.as_os_str() == "-" => "<stdin>".to_string(),
                Found::File(path, _) => display_path(path),
                Found::Skipped(name, _) => name.clone(),
            };
            let r = guarded(&name, self.colour, &mut stderr, |stderr| {
                self.one(found, stderr, &mut read)
            });
            results.extend(r);
        }
        (results, stderr, read)
    }

    /// One file checked: its result, or `None` for a file a directory's
    /// search passes over (a `*.toml` that is no part file).
    fn one(
        &self,
        found: Found,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> Option<FileResult> {
        let (o, settings, colour) = (self.o, self.settings, self.colour);
        let (path, found) = match found {
            Found::File(path, found) => (path, found),
            Found::Skipped(path, d) => return Some(invalid(path, d, stderr, colour)),
        };
        read.extend(std::fs::canonicalize(&path).ok());
        let f = if path.as_os_str() == "-" {
            "<stdin>".to_string()
        } else {
            display_path(&path)
        };
        // A robot description: by its name (`*.urdf`, `*.sdf`), else by its
        // root element (`<robot>`, `<sdf>`, `<mujoco>`). An `*.xml` found
        // in a directory that is none is passed over, as below.
        // Standard input read to tell its format is not read again.
        let mut stdin = None;
        if !crate::io::is_toml(&path) {
            let source = crate::io::read_source_at(&path);
            let format = crate::robot::Dialect::of_path(&path).or_else(|| {
                source
                    .as_ref()
                    .ok()
                    .and_then(|s| crate::robot::Dialect::of_text(&s.text))
            });
            if let Some(format) = format {
                if o.bless {
                    stderr.push_str(&format!(
                        "{}: not blessed (a robot description has no `[expect]`)\n",
                        visible(&f)
                    ));
                }
                let r = source.and_then(|s| {
                    let d = crate::robot::read::read(&s, format)?;
                    Ok(crate::robot::check::check(&s, &d, &o.engines))
                });
                return Some(match r {
                    Ok(r) => FileResult {
                        path: f,
                        status: if r.failed() {
                            Status::Failed
                        } else {
                            Status::Ok
                        },
                        error: None,
                        checks: Vec::new(),
                        validity: Vec::new(),
                        precision: None,
                        accuracy_warnings: Vec::new(),
                        robot: Some(r),
                        format: Some(format),
                    },
                    Err(d) => FileResult {
                        format: Some(format),
                        ..invalid(f, d, stderr, colour)
                    },
                });
            }
            if found {
                return None;
            }
            if path.as_os_str() == "-" {
                stdin = Some(source);
            }
        }
        // A `*.toml` found in a directory that is no part file
        // (`Cargo.toml`, a `settings.toml`, a `credentials.toml`) is passed
        // over as a search passes over any other file: not checked, not
        // blessed, nothing of it quoted. Read once, here, unless `--bless`
        // rewrites it first.
        let mut source = (found || !o.bless).then(|| {
            stdin
                .take()
                .unwrap_or_else(|| crate::io::read_source_at(&path))
        });
        if found && matches!(&source, Some(Ok(s)) if !crate::model::looks_like_a_part_file(&s.text))
        {
            return None;
        }
        // A file that cannot be blessed is left untouched. If it is invalid
        // the check below says why; if it is valid, the bless failure
        // itself (standard input, a write error) is the error.
        let mut not_blessed = None;
        if o.bless {
            // NOTE: `bless_file` takes a UTF-8 path; a name that is not
            // UTF-8 is checked, not blessed.
            let blessed = match path.to_str() {
                Some(p) => bless::bless_file(p, settings),
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
            source = None;
        }
        // Every file a part file includes joins `read` even if it turns out
        // invalid: `-o` may write onto none of them.
        let loaded = source
            .or(stdin)
            .unwrap_or_else(|| crate::io::read_source_at(&path))
            .and_then(|source| analysis::load_source_reading(source, settings, read))
            .map(|l| {
                let r = check_loaded(&l);
                // The predicted body's too, where the file has one.
                stderr.push_str(&super::warning_lines(
                    &l.source.name,
                    &r.accuracy_warnings,
                    colour,
                ));
                r
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
        Some(match checked {
            Ok(r) => r,
            Err(d) => invalid(f, d, stderr, colour),
        })
    }
}

/// `check` of one file (`name`, as shown), a panic in it (a bug) made its
/// result: invalid, with an internal error that says so, so that the
/// other files are still checked and reported.
fn guarded(
    name: &str,
    colour: bool,
    stderr: &mut String,
    check: impl FnOnce(&mut String) -> Option<FileResult>,
) -> Option<FileResult> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| check(&mut *stderr))) {
        Ok(r) => r,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let d = Diagnostic::file(
                name,
                format!(
                    "internal error while checking this file: {}",
                    crate::diag::shorten(&visible(&what))
                ),
            )
            .help("a bug in massprop, not in the file: please report it, with the file; the other files are checked");
            Some(invalid(name.to_string(), d, stderr, colour))
        }
    }
}

/// A file that cannot be checked: its error, on standard error too.
fn invalid(path: String, d: Diagnostic, stderr: &mut String, colour: bool) -> FileResult {
    stderr.push_str(&d.render(colour));
    FileResult {
        path,
        status: Status::Invalid,
        error: Some(d),
        checks: Vec::new(),
        validity: Vec::new(),
        precision: None,
        accuracy_warnings: Vec::new(),
        robot: None,
        format: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_while_checking_a_file_is_that_files_internal_error() {
        let mut stderr = String::from("before\n");
        let r = guarded("bad.toml", false, &mut stderr, |stderr| {
            stderr.push_str("partly written\n");
            panic!("a bug at \u{1b}[31m this place")
        })
        .expect("a result for the file");
        assert_eq!(r.path, "bad.toml");
        assert_eq!(r.status, Status::Invalid);
        let message = r.error.expect("an error").to_string();
        assert!(
            message
                .starts_with("bad.toml: error: internal error while checking this file: a bug at "),
            "{message}"
        );
        assert!(!message.contains('\u{1b}'), "{message}");
        assert!(
            stderr.starts_with("before\npartly written\nbad.toml: error: internal error"),
            "{stderr}"
        );
    }

    #[test]
    fn a_file_checked_without_a_panic_keeps_its_own_result() {
        let mut stderr = String::new();
        assert!(guarded("passed-over.toml", false, &mut stderr, |_| None).is_none());
        assert!(stderr.is_empty());
    }
}
