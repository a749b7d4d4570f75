//! `check`'s run over a set of files: each file found (`search`) checked
//! in turn (`check::check_loaded`, or a robot description's
//! `robot::check`), blessed first under `--bless` (`bless`), a panic in
//! one file its own result, and the run's outcome (`Checked::status`).
//! `commands::check` takes the options and renders the results.

use super::Settings;
use super::bless;
use super::check::{FileResult, Status, check_loaded};
use super::search::{self, Found, Search};
use crate::diag::{Diagnostic, Source, visible};
use crate::robot::Dialect;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

/// The stack of the thread that checks the files: far more than any
/// check needs. NOTE: no reader recurses on a depth the input chooses
/// (group paths, expressions, TOML and XML are bounded or walked with
/// stacks of their own); this is the margin for one that someday does,
/// as `guarded` is for a panic: one file must never take the other files'
/// results, and the report, with it. Reserved, not committed: the pages
/// never touched cost nothing.
const STACK: usize = 256 << 20;

/// What the check of every file shares.
pub struct Run<'a> {
    /// `predicted` set: `predicted_*` expectations and `[budget] limit`
    /// read the predicted body.
    pub settings: Settings,
    /// Write the computed values into the files' `[expect]` first.
    pub bless: bool,
    /// The engines whose rules robot descriptions are checked by.
    pub engines: &'a [crate::robot::engine::Engine],
    /// Whether standard error is coloured.
    pub colour: bool,
}

/// What a run found: every file's result, in order, what it writes on
/// standard error, every file it read (those the files include too,
/// valid or not: `-o` may write onto none of them), and how many files a
/// directory's search passed over (the summary line counts them).
#[derive(Debug, Default)]
pub struct Checked {
    pub results: Vec<FileResult>,
    pub stderr: String,
    pub read: Vec<PathBuf>,
    pub skipped: usize,
}

/// Why a file a directory's search found is passed over, as `--verbose`
/// says it: nothing of the file itself is quoted.
type Passed = &'static str;

/// A `*.toml` with none of massprop's own top-level tables or keys.
const NOT_A_PART_FILE: Passed = "skipped: not a part file (none of massprop's top-level tables or keys `part`, `units`, `expect`, `analysis`, `params`, `materials`, `budget`, `growth`, nor a near miss of one)";

/// A `*.toml` of `[materials]` alone, for part files to use.
const A_MATERIALS_FILE: Passed =
    "skipped: a materials file (`[materials]` and no parts: `massprop materials FILE` lists it)";

/// A `*.xml` that is no robot description.
const NOT_A_ROBOT: Passed =
    "skipped: not a robot description (its root is not `<robot>`, `<sdf>` or `<mujoco>`)";

impl Checked {
    /// The exit status: 2 when any file is invalid, else 1 when any check
    /// fails, else 0.
    pub fn status(&self) -> u8 {
        let any = |s: Status| self.results.iter().any(|r| r.status == s);
        if any(Status::Invalid) {
            2
        } else if any(Status::Failed) {
            1
        } else {
            0
        }
    }
}

impl Run<'_> {
    /// The files `paths` name (`search::find`), each checked; an error when
    /// there are none to check, or a search cannot start.
    pub fn check(&self, paths: &[PathBuf], search: &Search) -> Result<Checked, Diagnostic> {
        let found = search::find(paths, search)?;
        let checked = self.all(found, search.verbose);
        if checked.results.is_empty() {
            return Err(Diagnostic::plain(
                "no part files or robot descriptions found (a directory is searched for `*.toml` files with a `[[part]]` table, and for `*.urdf`, `*.sdf` and `*.xml` robot descriptions; hidden and ignored ones are passed over)",
            ));
        }
        Ok(checked)
    }

    /// Every file found, in order, on a thread of a large stack (`STACK`),
    /// a file's panic its own result (`guarded`).
    fn all(&self, found: Vec<Found>, verbose: bool) -> Checked {
        let found = std::sync::Mutex::new(Some(found));
        let work = || {
            let found = found.lock().ok().and_then(|mut f| f.take());
            self.each(found.unwrap_or_default(), verbose)
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

    /// Every file in turn; those passed over counted, and under
    /// `--verbose` named with why on standard error.
    fn each(&self, found: Vec<Found>, verbose: bool) -> Checked {
        let mut c = Checked::default();
        for found in found {
            let name = found.name();
            let r = guarded(&name, self.colour, &mut c.stderr, |stderr| {
                self.one(found, stderr, &mut c.read)
            });
            match r {
                Ok(r) => c.results.push(r),
                Err(why) => {
                    c.skipped += 1;
                    if verbose {
                        c.stderr.push_str(&format!("{}: {why}\n", visible(&name)));
                    }
                }
            }
        }
        c
    }

    /// One file checked: its result, or why a directory's search passes
    /// it over (a `*.toml` that is no part file, a `*.xml` that is no robot
    /// description).
    fn one(
        &self,
        found: Found,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> Result<FileResult, Passed> {
        let (path, found) = match found {
            Found::File(path, found) => (path, found),
            Found::Skipped(path, d) => return Ok(invalid(path, d, stderr, self.colour)),
        };
        read.extend(std::fs::canonicalize(&path).ok());
        let f = search::shown(&path);
        let stdin = if crate::io::is_toml(&path) {
            None
        } else {
            match self.not_toml(&path, &f, found, stderr, read) {
                ControlFlow::Break(r) => return r,
                ControlFlow::Continue(stdin) => stdin,
            }
        };
        self.part_file(&path, &f, found, stdin, stderr, read)
    }

    /// A file not named `*.toml`: a robot description, by its name
    /// (`*.urdf`, `*.sdf`), else by its root element (`<robot>`, `<sdf>`,
    /// `<mujoco>`), checked (`Break` with its result); else passed over
    /// when a directory's search found it (`Break(Err)`), or read as a
    /// part file (`Continue`, with standard input's text when it is `-`:
    /// standard input read to tell its format is not read again).
    fn not_toml(
        &self,
        path: &Path,
        f: &str,
        found: bool,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> ControlFlow<Result<FileResult, Passed>, Option<Result<Source, Diagnostic>>> {
        let source = crate::io::read_source_at(path);
        let format = Dialect::of_path(path)
            .or_else(|| source.as_ref().ok().and_then(|s| Dialect::of_text(&s.text)));
        if let Some(format) = format {
            return ControlFlow::Break(Ok(self.robot(f, source, format, stderr, read)));
        }
        if found {
            return ControlFlow::Break(Err(NOT_A_ROBOT));
        }
        ControlFlow::Continue((path.as_os_str() == "-").then_some(source))
    }

    /// A robot description's links checked under each engine.
    fn robot(
        &self,
        f: &str,
        source: Result<Source, Diagnostic>,
        format: Dialect,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> FileResult {
        if self.bless {
            stderr.push_str(&format!(
                "{}: not blessed (a robot description has no `[expect]`)\n",
                visible(f)
            ));
        }
        let r = source.and_then(|s| {
            // Every file the robot includes is read, its links judged
            // (`--include-root` and `--package` reach further).
            let r = crate::robot::read::Resolve {
                packages: self.settings.includes.packages.clone(),
                roots: self.settings.includes.roots.clone(),
            };
            let d = crate::robot::read::read_in(&s, format, &r)?;
            // The files it includes are inputs too: `-o` writes none.
            read.extend(
                d.files
                    .sources
                    .iter()
                    .filter_map(|f| std::fs::canonicalize(f.path()).ok()),
            );
            Ok(crate::robot::check::check(&s, &d, self.engines))
        });
        match r {
            Ok(r) => FileResult {
                path: f.to_string(),
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
                warnings: Vec::new(),
                robot: Some(r),
                format: Some(format),
            },
            Err(d) => FileResult {
                format: Some(format),
                ..invalid(f.to_string(), d, stderr, self.colour)
            },
        }
    }

    /// A part file (or a `*.toml` found in a directory that turns out no
    /// part file, passed over: `Err`, see `passed_over`), blessed first
    /// under `--bless`, then checked. `stdin`: standard input's text, read
    /// already.
    fn part_file(
        &self,
        path: &Path,
        f: &str,
        found: bool,
        mut stdin: Option<Result<Source, Diagnostic>>,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> Result<FileResult, Passed> {
        // A `*.toml` found in a directory that is no part file
        // (`Cargo.toml`, a `settings.toml`, a `credentials.toml`) is passed
        // over as a search passes over any other file: not checked, not
        // blessed, nothing of it quoted. Read once, here, unless `--bless`
        // rewrites it first.
        let mut source = (found || !self.bless).then(|| {
            stdin
                .take()
                .unwrap_or_else(|| crate::io::read_source_at(path))
        });
        if found {
            let why = match &source {
                Some(Ok(s)) => self.passed_over(s),
                // Not UTF-8 (UTF-16, say): judged by its text as far as
                // it can be read, and passed over unquoted when it is no
                // part file, as a UTF-8 one would be.
                Some(Err(_)) => crate::io::sniffed_text(path)
                    .filter(|t| !search::likely_part_file(t))
                    .map(|_| NOT_A_PART_FILE),
                None => None,
            };
            if let Some(why) = why {
                return Err(why);
            }
        }
        let mut not_blessed = None;
        if self.bless {
            not_blessed = self.bless(path, f, stderr);
            source = None;
        }
        let source = source
            .or(stdin)
            .unwrap_or_else(|| crate::io::read_source_at(path));
        let checked = self.load_and_check(source, stderr, read);
        Ok(match blessed_or_not(checked, not_blessed, f, stderr) {
            Ok(r) => r,
            Err(d) => invalid(f.to_string(), d, stderr, self.colour),
        })
    }

    /// Why a `*.toml` a directory's search found is passed over, if it is:
    /// it is not `search::likely_part_file` (no top-level table or key of
    /// massprop's, nor a near miss of one), or it is a materials file that
    /// reads as one. Any other is checked, and invalid if it does not
    /// read: a `[[parts]]` or `[part]` typo fails the run rather than
    /// passing it.
    fn passed_over(&self, s: &Source) -> Option<Passed> {
        if crate::model::looks_like_a_part_file(&s.text) {
            return None;
        }
        if !search::likely_part_file(&s.text) {
            return Some(NOT_A_PART_FILE);
        }
        // NOTE: a materials file's errors are the check's own (it is
        // checked, and invalid); one that reads is no part file to check.
        match crate::model::Model::materials_file(s, &self.settings.includes) {
            Ok(Some(_)) => Some(A_MATERIALS_FILE),
            Ok(None) | Err(_) => None,
        }
    }

    /// `--bless` of one part file: said on standard error, or why it could
    /// not be blessed. A file that cannot be blessed is left untouched. If
    /// it is invalid the check says why; if it is valid, the bless failure
    /// itself (standard input, a write error) is the error
    /// (`blessed_or_not`).
    fn bless(&self, path: &Path, f: &str, stderr: &mut String) -> Option<Diagnostic> {
        // NOTE: `bless_file` takes a UTF-8 path; a name that is not
        // UTF-8 is checked, not blessed.
        let blessed = match path.to_str() {
            Some(p) => bless::bless_file(p, &self.settings),
            None => Err(Diagnostic::file(
                f,
                "`--bless` cannot write a file whose name is not UTF-8; rename it to bless it",
            )),
        };
        match blessed {
            Ok(true) => stderr.push_str(&format!("{}: blessed\n", visible(f))),
            Ok(false) => stderr.push_str(&format!("{}: unchanged\n", visible(f))),
            Err(d) => return Some(d),
        }
        None
    }

    /// A part file's text loaded and checked, its accuracy warnings (the
    /// predicted body's too, where the file has one) on standard error.
    /// Every file a part file includes joins `read` even if it turns out
    /// invalid: `-o` may write onto none of them.
    fn load_and_check(
        &self,
        source: Result<Source, Diagnostic>,
        stderr: &mut String,
        read: &mut Vec<PathBuf>,
    ) -> Result<FileResult, Diagnostic> {
        let loaded = source.and_then(|s| super::load_source_reading(s, &self.settings, read))?;
        let mut r = check_loaded(&loaded);
        super::check::check_cases(&loaded, &self.settings, &mut r)?;
        super::envelope::sequences::add_to(&mut r, &loaded, &self.settings)?;
        stderr.push_str(&warning_lines(
            &loaded.source.name,
            &r.accuracy_warnings,
            self.colour,
        ));
        stderr.push_str(&super::plausible::lines(&r.warnings, self.colour));
        Ok(r)
    }
}

/// A file's check, with its bless's failure (`not_blessed`) if it had
/// one: that failure is the file's error when it checked, its own error
/// when it did not; either way said on standard error.
fn blessed_or_not(
    checked: Result<FileResult, Diagnostic>,
    not_blessed: Option<Diagnostic>,
    f: &str,
    stderr: &mut String,
) -> Result<FileResult, Diagnostic> {
    match (checked, not_blessed) {
        (Ok(_), Some(d)) => {
            stderr.push_str(&format!("{}: not blessed\n", visible(f)));
            Err(d)
        }
        (Err(d), Some(_)) => {
            stderr.push_str(&format!(
                "{}: not blessed (invalid; left untouched)\n",
                visible(f)
            ));
            Err(d)
        }
        (checked, None) => checked,
    }
}

/// `warning: FILE: …`, one line per value of `file` not certified to
/// `--rtol`, `warning` coloured when `colour`.
pub fn warning_lines(
    file: &str,
    warnings: &[super::summary::AccuracyWarning],
    colour: bool,
) -> String {
    let file = visible(file);
    let palette = crate::diag::Palette::of(colour);
    warnings
        .iter()
        .map(|w| palette.warning_line(&format!("{file}: {}", w.message)))
        .collect()
}

/// `check` of one file (`name`, as shown), a panic in it (a bug) made its
/// result: invalid, with an internal error that says so, so that the
/// other files are still checked and reported.
fn guarded(
    name: &str,
    colour: bool,
    stderr: &mut String,
    check: impl FnOnce(&mut String) -> Result<FileResult, Passed>,
) -> Result<FileResult, Passed> {
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
            Ok(invalid(name.to_string(), d, stderr, colour))
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
        warnings: Vec::new(),
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

    /// A run whose files end with `statuses`.
    fn checked(statuses: &[Status]) -> Checked {
        let d = || Diagnostic::plain("x");
        let results = statuses
            .iter()
            .map(|&status| FileResult {
                status,
                ..invalid("f.toml".to_string(), d(), &mut String::new(), false)
            })
            .collect();
        Checked {
            results,
            ..Checked::default()
        }
    }

    #[test]
    fn an_invalid_file_makes_the_run_exit_2_whatever_else_fails() {
        let c = checked(&[Status::Ok, Status::Failed, Status::Invalid, Status::Ok]);
        assert_eq!(c.status(), 2);
    }

    #[test]
    fn a_failed_check_without_an_invalid_file_makes_the_run_exit_1() {
        assert_eq!(checked(&[Status::Ok, Status::Failed]).status(), 1);
    }

    #[test]
    fn a_run_where_everything_holds_exits_0() {
        assert_eq!(checked(&[Status::Ok, Status::Ok]).status(), 0);
    }

    #[test]
    fn a_file_checked_without_a_panic_keeps_its_own_result() {
        let mut stderr = String::new();
        assert!(
            guarded("passed-over.toml", false, &mut stderr, |_| Err(
                NOT_A_PART_FILE
            ))
            .is_err()
        );
        assert!(stderr.is_empty());
    }
}
