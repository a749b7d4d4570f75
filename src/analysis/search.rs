//! The part files and robot descriptions `check PATH...` names: files as
//! given, directories searched as ripgrep searches them (`find`).
//! `check_run` checks what is found.

use crate::diag::{Diagnostic, display_path, visible};
use std::path::{Path, PathBuf};

/// How directories are searched (`--hidden`, `--exclude`).
#[derive(Debug, Clone, Default)]
pub struct Search {
    /// Hidden files and directories (names starting with `.`) too.
    pub hidden: bool,
    /// Globs of paths not to check, as in a `.gitignore` (relative to the
    /// directory searched).
    pub exclude: Vec<String>,
}

/// What a search for part files found. Paths are kept as the file system
/// gave them (a name need not be UTF-8) and shown by `display_path`.
pub enum Found {
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

impl Found {
    /// Its name as results and messages show it (`<stdin>` for `-`).
    pub fn name(&self) -> String {
        match self {
            Found::File(path, _) => shown(path),
            Found::Skipped(name, _) => name.clone(),
        }
    }
}

/// A path as results and messages show it: `<stdin>` for `-`.
pub fn shown(path: &Path) -> String {
    if path.as_os_str() == "-" {
        "<stdin>".to_string()
    } else {
        display_path(path)
    }
}

/// The part files named: files as given; directories searched recursively
/// as ripgrep searches them (the `ignore` crate: `.gitignore`, `.ignore`
/// and git's excludes honoured, hidden entries skipped unless
/// `--hidden`, `--exclude` globs), `*.toml` files in sorted order.
pub fn find(paths: &[PathBuf], search: &Search) -> Result<Vec<Found>, Diagnostic> {
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

/// Every file `dir` holds that is checked or said to be skipped, in
/// sorted order. `root`: the directory named, canonical.
fn walk(dir: &Path, root: &Path, search: &Search, out: &mut Vec<Found>) -> Result<(), Diagnostic> {
    for entry in walker(dir, search)? {
        match entry {
            Ok(entry) => out.extend(found(&entry, root)),
            Err(e) => {
                // An unreadable directory, or an ignore file that cannot
                // be read or parsed: said, and the search goes on.
                let name = display_path(dir);
                let d = Diagnostic::file(&name, format!("cannot search: {e}"));
                out.push(Found::Skipped(name, d));
            }
        }
    }
    Ok(())
}

/// The search of `dir`, with `--hidden` and `--exclude`.
fn walker(dir: &Path, search: &Search) -> Result<ignore::Walk, Diagnostic> {
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
    Ok(ignore::WalkBuilder::new(dir)
        .hidden(!search.hidden)
        .overrides(excluded)
        .follow_links(false)
        .sort_by_file_name(|a, b| a.cmp(b))
        .build())
}

/// What one entry of a directory's search is: a file to check, one
/// skipped with why, or nothing (a directory, a file of another kind).
fn found(entry: &ignore::DirEntry, root: &Path) -> Option<Found> {
    // Its own type (from the directory, not following a symlink).
    let t = entry.file_type()?;
    let p = entry.path();
    let wanted = |p: &Path| crate::io::is_toml(p) || crate::robot::may_be_robot(p);
    if t.is_dir() || !wanted(p) {
        return None;
    }
    if t.is_symlink()
        && std::fs::canonicalize(p).is_ok_and(|t| !(t.starts_with(root) && wanted(&t)))
    {
        // A file from a pull request, `x.toml -> ~/.cargo/credentials.toml`
        // or `-> .git/config`, would be read and quoted in the log.
        return Some(skipped(
            p,
            "not checked: a symlink to a file outside the directory searched, or to one that is not a `*.toml` file or robot description (check it by its own path)",
        ));
    }
    // The target's type, without opening it.
    match std::fs::metadata(p) {
        Ok(m) if m.is_file() => Some(Found::File(p.to_path_buf(), true)),
        Ok(m) if m.is_dir() => None,
        _ => Some(skipped(
            p,
            "not a part file: not a regular file (a FIFO, socket, device or broken link), so not read",
        )),
    }
}

/// `p` not checked, and why.
fn skipped(p: &Path, why: &str) -> Found {
    let name = display_path(p);
    let d = Diagnostic::file(&name, why);
    Found::Skipped(name, d)
}
