//! The search of one directory, as ripgrep searches (its `ignore`
//! crate's `WalkBuilder` with `hidden`, `overrides`, no symlinked
//! directory followed and names sorted, the rest its defaults):
//! depth first, each directory's entries in byte order of their names.
//!
//! What is passed over, first rule that says something winning:
//! 1. an `--exclude` glob that matches (relative to the directory
//!    searched; a directory matched is not entered);
//! 2. the ignore files: `.ignore` rules over `.gitignore` rules over
//!    `.git/info/exclude` over git's global excludes file (the
//!    `core.excludesFile` of git's global or system configuration, else
//!    `$XDG_CONFIG_HOME/git/ignore`, relative to the current directory);
//!    of each kind the deepest file that matches decides, and in it the
//!    last rule; the directory searched and every directory above it
//!    count. The three git kinds only inside a git repository (a `.git`,
//!    or a `.jj`, in the directory or above), and not from above its top;
//!    `.ignore` everywhere. A `!` rule that matches re-includes, so a
//!    hidden file it names is searched too;
//! 3. a hidden name (starting with `.`) unless `--hidden`.
//!
//! Where it cannot read: a directory (said, and the search goes on); an
//! ignore file above the directory searched that has a glob error (said).
//! An ignore file inside it that cannot be read is passed over, its good
//! lines kept, as ripgrep does.
//!
//! NOTE: hand-written for compile time (`glob`); each step is the crate's
//! (ignore 0.4.35's `dir.rs` and `walk.rs`), and
//! tests/integration/search_rules.rs holds the files found equal to it.

use super::ignore_rules::{Match, Problem, Rules, strip_prefix};
use std::fs::FileType;
use std::path::{Path, PathBuf};

/// What the search meets: a file or directory not passed over, or why a
/// part of the tree cannot be searched (the `ignore` crate's message).
pub enum Event {
    Entry(PathBuf, FileType),
    Error(String),
}

/// The rules of one directory's ignore files.
struct Layer {
    ignore: Rules,
    gitignore: Rules,
    exclude: Rules,
    /// The top of a git repository (a `.git` or `.jj` in it).
    has_git: bool,
}

impl Layer {
    /// `dir`'s ignore files; the problems worth saying.
    fn load(dir: &Path) -> (Layer, Vec<Problem>) {
        let git_type = std::fs::metadata(dir.join(".git"))
            .ok()
            .map(|m| m.file_type());
        let has_git = git_type.is_some() || dir.join(".jj").exists();
        let mut problems = Vec::new();
        let ignore = rules_of(dir, &dir.join(".ignore"), &mut problems);
        let gitignore = rules_of(dir, &dir.join(".gitignore"), &mut problems);
        let exclude = match git_common_dir(dir, git_type) {
            Ok(git_dir) => rules_of(dir, &git_dir.join("info/exclude"), &mut problems),
            Err(p) => {
                problems.extend(p);
                Rules::new(dir)
            }
        };
        let layer = Layer {
            ignore,
            gitignore,
            exclude,
            has_git,
        };
        (layer, problems)
    }

    fn has_rules(&self) -> bool {
        !(self.ignore.is_empty() && self.gitignore.is_empty() && self.exclude.is_empty())
    }
}

/// The rules of the ignore file `file` (if there is one), relative to
/// `dir`. NOTE: as the crate, a file whose only problem is one of input
/// or output is passed over in silence.
fn rules_of(dir: &Path, file: &Path, problems: &mut Vec<Problem>) -> Rules {
    let mut rules = Rules::new(dir);
    if file.exists() {
        let found = rules.add_file(file);
        if !(found.len() == 1 && found[0].io) {
            problems.extend(found);
        }
    }
    problems.extend(rules.void_problem());
    rules
}

/// Where `dir`'s repository keeps `info/exclude`: `.git`, or for a
/// worktree (`.git` a file, `gitdir: …`) its common directory. `Err`: none
/// (with a problem where one of those files cannot be read).
fn git_common_dir(dir: &Path, git_type: Option<FileType>) -> Result<PathBuf, Option<Problem>> {
    let git = dir.join(".git");
    if !git_type.is_some_and(|t| t.is_file()) {
        return Ok(git);
    }
    let first_line = |path: &Path| -> Result<Option<String>, Problem> {
        let problem = |e: std::io::Error| Problem {
            text: format!("{}: {e}", path.display()),
            io: true,
        };
        let bytes = std::fs::read(path).map_err(problem)?;
        let line = bytes.split(|&b| b == b'\n').next().unwrap_or_default();
        if bytes.is_empty() {
            return Ok(None);
        }
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        let line = std::str::from_utf8(line).map_err(|_| {
            problem(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                "stream did not contain valid UTF-8",
            ))
        })?;
        Ok(Some(line.to_string()))
    };
    let line = first_line(&git).map_err(Some)?.ok_or(None)?;
    let real = PathBuf::from(line.strip_prefix("gitdir: ").ok_or(None)?);
    let common_file = real.join("commondir");
    if std::fs::File::open(&common_file).is_err() {
        return Err(None);
    }
    let common = first_line(&common_file).map_err(Some)?.ok_or(None)?;
    Ok(if common.starts_with('.') {
        real.join(common)
    } else {
        PathBuf::from(common)
    })
}

/// The search of `dir` (a directory): every entry not passed over, in
/// order. `hidden`: hidden entries too; `excluded`: `--exclude`'s globs,
/// relative to `dir`.
pub fn walk(dir: &Path, hidden: bool, excluded: &Rules) -> Vec<Event> {
    let mut w = Walker {
        hidden,
        excluded,
        global: super::git_config::global_rules(),
        parents: Vec::new(),
        absolute_base: None,
        parent_rules: false,
        root: dir.to_path_buf(),
        stack: Vec::new(),
        out: Vec::new(),
    };
    w.add_parents(dir);
    w.stack.push(Layer::load(dir).0);
    w.read(dir);
    w.out
}

struct Walker<'a> {
    hidden: bool,
    excluded: &'a Rules,
    global: Rules,
    /// The directories above the one searched, from `/` down: their
    /// rules match its canonical path.
    parents: Vec<Layer>,
    absolute_base: Option<PathBuf>,
    /// Whether any of `parents` has a rule.
    parent_rules: bool,
    /// The directory searched, as named.
    root: PathBuf,
    /// It and the directories below it being searched, deepest last.
    stack: Vec<Layer>,
    out: Vec<Event>,
}

impl Walker<'_> {
    /// The ignore files above `dir`; their problems said as one.
    fn add_parents(&mut self, dir: &Path) {
        let Ok(base) = std::fs::canonicalize(dir) else {
            return;
        };
        let mut above: Vec<&Path> = base.ancestors().skip(1).collect();
        above.reverse();
        let mut problems = Vec::new();
        for parent in above {
            let (layer, p) = Layer::load(parent);
            problems.extend(p);
            self.parent_rules |= layer.has_rules();
            self.parents.push(layer);
        }
        self.absolute_base = Some(base);
        if !problems.is_empty() {
            let text: Vec<String> = problems.into_iter().map(|p| p.text).collect();
            self.out.push(Event::Error(text.join("\n")));
        }
    }

    /// The entries of `dir`, and below each directory not passed over.
    fn read(&mut self, dir: &Path) {
        let entries = match std::fs::read_dir(dir) {
            Ok(rd) => rd,
            Err(e) => return self.out.push(Event::Error(io_error(dir, &e))),
        };
        let mut found = Vec::new();
        for entry in entries {
            match entry.map(|e| (e.file_name(), e.path(), e.file_type())) {
                Ok((name, path, Ok(t))) => found.push((name, path, t)),
                Ok((_, path, Err(e))) => self.out.push(Event::Error(io_error(&path, &e))),
                Err(e) => self.out.push(Event::Error(e.to_string())),
            }
        }
        found.sort_by(|a, b| a.0.cmp(&b.0));
        for (name, path, t) in found {
            if self.passed_over(&path, &name, t.is_dir()) {
                continue;
            }
            if t.is_dir() {
                self.stack.push(Layer::load(&path).0);
                self.out.push(Event::Entry(path.clone(), t));
                self.read(&path);
                self.stack.pop();
            } else {
                self.out.push(Event::Entry(path, t));
            }
        }
    }

    /// Whether `path` is passed over: excluded, ignored, or hidden.
    fn passed_over(&self, path: &Path, name: &std::ffi::OsStr, is_dir: bool) -> bool {
        let m = self.matched(path, is_dir);
        match m {
            Match::Ignore => true,
            Match::Whitelist => false,
            Match::None => self.hidden_skipped(name),
        }
    }

    fn hidden_skipped(&self, name: &std::ffi::OsStr) -> bool {
        !self.hidden && name.as_encoded_bytes().starts_with(b".")
    }

    /// What the exclusions and ignore files say of `path`.
    fn matched(&self, path: &Path, is_dir: bool) -> Match {
        let path = strip_prefix(Path::new("./"), path).unwrap_or(path);
        // `--exclude` first: its globs are `!` rules read inverted.
        let m = match self.excluded.matched(path, is_dir) {
            Match::Whitelist => Match::Ignore,
            Match::Ignore => Match::Whitelist,
            Match::None => Match::None,
        };
        if !m.is_none() {
            return m;
        }
        self.ignored(path, is_dir)
    }

    /// What the ignore files say of `path` (see the module's comment).
    fn ignored(&self, path: &Path, is_dir: bool) -> Match {
        let any_git = self.stack.iter().chain(&self.parents).any(|l| l.has_git);
        let (mut m_ignore, mut m_git, mut m_exclude) = (Match::None, Match::None, Match::None);
        let mut saw_git = false;
        let mut visit = |layer: &Layer, path: &Path| {
            if m_ignore.is_none() {
                m_ignore = layer.ignore.matched(path, is_dir);
            }
            if any_git && !saw_git && m_git.is_none() {
                m_git = layer.gitignore.matched(path, is_dir);
            }
            if any_git && !saw_git && m_exclude.is_none() {
                m_exclude = layer.exclude.matched(path, is_dir);
            }
            saw_git = saw_git || layer.has_git;
        };
        for layer in self.stack.iter().rev() {
            visit(layer, path);
        }
        if self.parent_rules
            && let Some(base) = &self.absolute_base
        {
            // The path below the directory searched, under its canonical
            // name, for the rules above it.
            let rel = if self.root == Path::new(".") {
                path
            } else {
                let root = strip_prefix(Path::new("./"), &self.root).unwrap_or(&self.root);
                let r = strip_prefix(root, path).unwrap_or(path);
                strip_prefix(Path::new("/"), r).unwrap_or(r)
            };
            let abs = base.join(rel);
            for layer in self.parents.iter().rev() {
                visit(layer, &abs);
            }
        }
        let global = || {
            if any_git {
                self.global.matched(path, is_dir)
            } else {
                Match::None
            }
        };
        m_ignore.or(|| m_git).or(|| m_exclude).or(global)
    }
}

/// An unreadable directory's error, as walkdir and ignore word it.
fn io_error(path: &Path, e: &std::io::Error) -> String {
    let p = path.display();
    format!("{p}: IO error for operation on {p}: {e}")
}
