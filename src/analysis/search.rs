//! The part files and robot descriptions `check PATH...` names: files as
//! given, directories searched as ripgrep searches them (`find`).
//! `check_run` checks what is found.

use crate::diag::{Diagnostic, display_path, visible};
use std::path::{Path, PathBuf};

mod git_config;
mod glob;
mod ignore_rules;
mod walk;

/// How directories are searched (`--hidden`, `--exclude`).
#[derive(Debug, Clone, Default)]
pub struct Search {
    /// Hidden files and directories (names starting with `.`) too.
    pub hidden: bool,
    /// Globs of paths not to check, as in a `.gitignore` (relative to the
    /// directory searched).
    pub exclude: Vec<String>,
    /// Name each file the search passes over, and why (`--verbose`), on
    /// standard error.
    pub verbose: bool,
}

/// What a search for part files found. Paths are kept as the file system
/// gave them (a name need not be UTF-8) and shown by `display_path`.
pub enum Found {
    /// A part file to check: as named (`false`), or found in a directory
    /// (`true`: a `*.toml` that is not `likely_part_file`, such as
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
/// as ripgrep searches them (`walk`, massprop's own: `.gitignore`,
/// `.ignore` and git's excludes honoured, hidden entries skipped unless
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
    let mut excluded = ignore_rules::Rules::new(dir);
    for glob in &search.exclude {
        // NOTE: as ripgrep's overrides: a `!` rule each, an unclosed `[`
        // an error.
        excluded
            .add_line(&format!("!{glob}"), false)
            .map_err(|e| Diagnostic::plain(format!("--exclude `{}`: {e}", visible(glob))))?;
    }
    if let Some(p) = excluded.void_problem() {
        return Err(Diagnostic::plain(format!("--exclude: {}", p.text)));
    }
    // Symlinked directories are not followed (as ripgrep does not by
    // default: `ln -s .. up` would loop); symlinked files are, to a part
    // file inside the directory named.
    for event in walk::walk(dir, search.hidden, &excluded) {
        match event {
            walk::Event::Entry(path, t) => out.extend(found(&path, t, root)),
            walk::Event::Error(e) => {
                // An unreadable directory, or an ignore file above the
                // directory named that cannot be parsed: said, and the
                // search goes on.
                let name = display_path(dir);
                let d = Diagnostic::file(&name, format!("cannot search: {e}"));
                out.push(Found::Skipped(name, d));
            }
        }
    }
    Ok(())
}

/// What one entry of a directory's search is: a file to check, one
/// skipped with why, or nothing (a directory, a file of another kind).
fn found(p: &Path, t: std::fs::FileType, root: &Path) -> Option<Found> {
    // `t`: its own type (from the directory, not following a symlink).
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

/// massprop's own top-level tables and keys but the generic `name`, which
/// any TOML file may have: a `*.toml` found in a directory with one of
/// these, or a near miss of one, is checked (`likely_part_file`). NOTE:
/// the schema's top-level properties less `name` (a test holds them
/// equal): a key the reader learns is a key this rule knows.
pub const TOP_LEVEL_KEYS: [&str; 10] = [
    "analysis",
    "budget",
    "case",
    "envelope",
    "expect",
    "growth",
    "materials",
    "params",
    "part",
    "units",
];

/// Whether a `*.toml` found in a directory is checked: it has one of
/// massprop's own top-level tables or keys (`TOP_LEVEL_KEYS`), or a near miss of
/// one (`[[parts]]`, `[Part]`, `[unit]`, `[materails]`), so that a typo
/// makes the file invalid rather than passed over. Read off the lines, not
/// parsed: a file that is not valid TOML is judged too, and nothing of a
/// file passed over is quoted. A key counts at the top level: a table
/// header's first key (`[part]`, `[[part]]`, `[expect.x]`), or a key
/// before the first header (`units = …`, `part = [ … ]`).
pub fn likely_part_file(text: &str) -> bool {
    top_level_keys(text).any(|k| near_own_key(&k))
}

/// The top-level keys of `text`, by its lines, quotes taken off (see
/// `likely_part_file`).
fn top_level_keys(text: &str) -> impl Iterator<Item = String> + '_ {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut root = true;
    text.lines().filter_map(move |l| {
        let l = l.trim_start();
        if let Some(header) = l.strip_prefix('[') {
            root = false;
            let header = header.strip_prefix('[').unwrap_or(header);
            return first_key(header);
        }
        if !root || l.starts_with('#') || !l.contains('=') {
            return None;
        }
        first_key(l)
    })
}

/// The first key of a dotted key at the start of `l`: up to `.`, `=`, `]`
/// or a blank, its quotes taken off.
fn first_key(l: &str) -> Option<String> {
    let l = l.trim_start();
    let (quoted, rest) = match l.strip_prefix(['"', '\'']) {
        Some(rest) => (true, rest),
        None => (false, l),
    };
    let end = if quoted {
        rest.find(['"', '\''])?
    } else {
        rest.find(|c: char| matches!(c, '.' | '=' | ']' | '[') || c.is_whitespace())
            .unwrap_or(rest.len())
    };
    let key = &rest[..end];
    (!key.is_empty()).then(|| key.to_string())
}

/// Whether `key` is one of `TOP_LEVEL_KEYS` or a near miss of one: the same but
/// for case, `_`, `-` and a plural `s`, or (for a key of five letters or
/// more, where a slip of one letter is still unlike an ordinary word)
/// one letter added, dropped, changed or two swapped. NOTE: `part` only
/// by case and plural: one letter from it are `path`, `port`, `park`,
/// words a settings file has.
fn near_own_key(key: &str) -> bool {
    let k: String = key
        .chars()
        .filter(|c| !matches!(c, '_' | '-'))
        .flat_map(char::to_lowercase)
        .collect();
    let singular = k.strip_suffix('s').unwrap_or(&k).to_string();
    let forms = [k.clone(), format!("{k}s"), singular];
    TOP_LEVEL_KEYS.iter().any(|own| {
        forms
            .iter()
            .any(|f| f == own || (own.len() >= 5 && strsim::osa_distance(f, own) <= 1))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_part_file_is_likely_a_part_file() {
        assert!(likely_part_file(
            "name = \"x\"\n[[part]]\nshape = \"sphere\"\n"
        ));
    }

    #[test]
    fn a_plural_parts_table_is_likely_a_part_file() {
        assert!(likely_part_file("[[parts]]\nshape = \"sphere\"\n"));
    }

    #[test]
    fn a_single_bracket_part_table_is_likely_a_part_file() {
        assert!(likely_part_file("[part]\nshape = \"sphere\"\n"));
    }

    #[test]
    fn a_capitalised_part_table_is_likely_a_part_file() {
        assert!(likely_part_file("[[Part]]\nshape = \"sphere\"\n"));
    }

    #[test]
    fn an_expect_table_alone_is_likely_a_part_file() {
        assert!(likely_part_file("[expect]\nmass = \"1 kg\"\n"));
    }

    #[test]
    fn a_top_level_units_key_is_likely_a_part_file() {
        assert!(likely_part_file("units = { length = \"mm\" }\n"));
    }

    #[test]
    fn a_dotted_own_key_at_the_top_is_likely_a_part_file() {
        assert!(likely_part_file("analysis.about = [0, 0, 0]\n"));
    }

    #[test]
    fn a_quoted_own_table_is_likely_a_part_file() {
        assert!(likely_part_file("[\"budget\"]\nlimit = \"1 kg\"\n"));
    }

    #[test]
    fn a_one_letter_slip_of_a_long_key_is_likely_a_part_file() {
        assert!(likely_part_file("[materails]\n"));
        assert!(likely_part_file("[unit]\n"));
        assert!(likely_part_file("[expct]\n"));
    }

    #[test]
    fn a_file_that_is_not_toml_is_judged_by_its_lines() {
        assert!(likely_part_file("[[parts]\nshape = = \n"));
    }

    #[test]
    fn a_cargo_manifest_is_not_a_part_file() {
        let cargo = "[package]\nname = \"x\"\nversion = \"0.1.0\"\n\n[dependencies]\nserde = \"1\"\n\n[features]\ndefault = []\n\n[[bench]]\nname = \"b\"\npath = \"b.rs\"\n\n[profile.release]\nlto = true\n\n[lints.rust]\nunsafe_code = \"forbid\"\n\n[badges]\n[target.'cfg(unix)'.dependencies]\n[workspace]\n[patch.crates-io]\n";
        assert!(!likely_part_file(cargo));
    }

    #[test]
    fn a_pyproject_is_not_a_part_file() {
        let py = "[build-system]\nrequires = [\"x\"]\n[project]\nname = \"x\"\n[tool.units]\nparts = 1\n[dependency-groups]\n";
        assert!(!likely_part_file(py));
    }

    #[test]
    fn a_credentials_file_is_not_a_part_file() {
        assert!(!likely_part_file("[registry]\ntoken = \"secret\"\n"));
    }

    #[test]
    fn a_settings_file_with_a_path_key_is_not_a_part_file() {
        assert!(!likely_part_file(
            "path = \"/tmp\"\nport = 80\nname = \"x\"\n"
        ));
    }

    #[test]
    fn an_own_key_inside_another_table_is_not_at_the_top_level() {
        assert!(!likely_part_file(
            "[server]\nunits = \"metric\"\npart = 1\n"
        ));
    }

    #[test]
    fn a_name_alone_is_not_a_part_file() {
        assert!(!likely_part_file("name = \"x\"\n"));
    }

    #[test]
    fn the_own_keys_are_the_schemas_top_level_keys_but_name() {
        let schema = crate::model::schema::schema();
        let mut keys: Vec<&str> = schema["properties"]
            .as_object()
            .expect("the schema's properties")
            .keys()
            .map(String::as_str)
            .filter(|k| *k != "name")
            .collect();
        keys.sort_unstable();
        assert_eq!(keys, TOP_LEVEL_KEYS);
    }
}
