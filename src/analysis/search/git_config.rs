//! Git's global excludes file, as ripgrep's `ignore` crate finds it: the
//! `core.excludesFile` of `$GIT_CONFIG_GLOBAL`, `~/.gitconfig`,
//! `$XDG_CONFIG_HOME/git/config` (else `~/.config/git/config`) or the
//! system configuration (`$GIT_CONFIG_SYSTEM`, else `/etc/gitconfig`),
//! the first that names one; else `$XDG_CONFIG_HOME/git/ignore` (else
//! `~/.config/git/ignore`). Its rules are relative to the current
//! directory.
//!
//! NOTE: the crate reads the setting with a regular expression,
//! `(?im-u)^\s*excludesfile\s*=\s*"?\s*(\S+?)\s*"?\s*$`, not as git
//! parses its configuration (the section is not looked at); `excludes_file`
//! matches that expression by hand, so that the same file is found.

use super::ignore_rules::Rules;
use std::path::PathBuf;

/// The global excludes file's rules (none where there is none).
pub fn global_rules() -> Rules {
    let Ok(cwd) = std::env::current_dir() else {
        return Rules::new(std::path::Path::new(""));
    };
    let mut rules = Rules::new(&cwd);
    if let Some(path) = excludes_path()
        && path.is_file()
    {
        // NOTE: its problems are not said (the crate only logs them).
        let _ = rules.add_file(&path);
    }
    rules
}

fn excludes_path() -> Option<PathBuf> {
    let read = |p: PathBuf| std::fs::read(p).ok();
    let env = |name: &str| {
        std::env::var_os(name)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    let xdg = || env("XDG_CONFIG_HOME").or_else(|| home().map(|h| h.join(".config")));
    env("GIT_CONFIG_GLOBAL")
        .and_then(read)
        .and_then(|d| excludes_file(&d))
        .or_else(|| {
            home()
                .and_then(|h| read(h.join(".gitconfig")))
                .and_then(|d| excludes_file(&d))
        })
        .or_else(|| {
            xdg()
                .and_then(|x| read(x.join("git/config")))
                .and_then(|d| excludes_file(&d))
        })
        .or_else(|| {
            let system =
                env("GIT_CONFIG_SYSTEM").unwrap_or_else(|| PathBuf::from("/etc/gitconfig"));
            read(system).and_then(|d| excludes_file(&d))
        })
        .or_else(|| xdg().map(|x| x.join("git/ignore")))
}

#[allow(deprecated)]
fn home() -> Option<PathBuf> {
    std::env::home_dir()
}

/// Whitespace as `\s` without Unicode.
fn space(b: u8) -> bool {
    matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r' | b' ')
}

fn skip_space(d: &[u8], mut i: usize) -> usize {
    while i < d.len() && space(d[i]) {
        i += 1;
    }
    i
}

/// The excludes file a configuration names (see the module's comment):
/// the first line that matches, its value a `~` expanded.
pub fn excludes_file(data: &[u8]) -> Option<PathBuf> {
    let starts = std::iter::once(0).chain(
        data.iter()
            .enumerate()
            .filter(|(_, b)| **b == b'\n')
            .map(|(i, _)| i + 1),
    );
    for start in starts {
        if let Some(value) = value_at(data, start) {
            return std::str::from_utf8(value)
                .ok()
                .map(|s| PathBuf::from(expand_tilde(s)));
        }
    }
    None
}

/// The expression's capture where it matches from `start`.
fn value_at(d: &[u8], start: usize) -> Option<&[u8]> {
    const KEY: &[u8] = b"excludesfile";
    let i = skip_space(d, start);
    if !d.get(i..i + KEY.len())?.eq_ignore_ascii_case(KEY) {
        return None;
    }
    let i = skip_space(d, i + KEY.len());
    if d.get(i) != Some(&b'=') {
        return None;
    }
    let i = skip_space(d, i + 1);
    // `"?` takes a quote first; without it the value starts at the quote.
    let quoted = (d.get(i) == Some(&b'"')).then(|| skip_space(d, i + 1));
    quoted.into_iter().chain([i]).find_map(|from| {
        let mut end = from;
        while end < d.len() && !space(d[end]) {
            end += 1;
            if tail_matches(&d[end..]) {
                return Some(&d[from..end]);
            }
        }
        None
    })
}

/// Whether `s` starts with `\s*"?\s*$` (`$`: the end, or before a
/// newline).
fn tail_matches(s: &[u8]) -> bool {
    let eol = |r: std::ops::Range<usize>| r.clone().any(|k| s[k] == b'\n') || r.end == s.len();
    let i = skip_space(s, 0);
    if eol(0..i) {
        return true;
    }
    s.get(i) == Some(&b'"') && eol(i + 1..skip_space(s, i + 1))
}

fn expand_tilde(path: &str) -> String {
    let Some(rest) = path.strip_prefix('~') else {
        return path.to_string();
    };
    if !rest.is_empty() && !rest.starts_with('/') {
        return path.to_string();
    }
    match home() {
        Some(h) => format!("{}{rest}", h.to_string_lossy()),
        None => path.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_excludes_file_setting_is_found_whatever_its_case() {
        let cfg = b"[core]\n\tExcludesFile = /etc/ignore\n";
        assert_eq!(excludes_file(cfg), Some(PathBuf::from("/etc/ignore")));
    }

    #[test]
    fn a_quoted_excludes_file_loses_its_quotes() {
        let cfg = b"[core]\nexcludesfile = \"/a/b\" \r\n";
        assert_eq!(excludes_file(cfg), Some(PathBuf::from("/a/b")));
    }

    #[test]
    fn a_value_with_a_space_in_it_is_not_read() {
        assert_eq!(excludes_file(b"excludesfile = /a b\n"), None);
    }

    #[test]
    fn a_commented_setting_is_not_read() {
        assert_eq!(excludes_file(b"# excludesfile = /a\n"), None);
    }
}
