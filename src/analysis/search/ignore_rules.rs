//! One ignore file's rules (`.gitignore`, `.ignore`, `.git/info/exclude`,
//! git's global excludes file) and the `--exclude` globs: read as
//! gitignore(5) writes them, the way ripgrep's `ignore` crate reads them,
//! and matched against a path.
//!
//! A line: blank or `#` is nothing; trailing spaces go unless escaped
//! (`\ `); `\#` and `\!` start a literal `#` or `!`; `!` negates (a later
//! rule re-includes what an earlier one excluded); a trailing `/` matches
//! directories only; a `/` at the start or in the middle anchors the glob
//! to the file's directory, else it matches at any depth (`**/` is put in
//! front); a trailing `/**` matches what is inside, not the directory.
//! The last rule of a file that matches decides (`Rules::matched`).
//!
//! NOTE: hand-written rather than the `ignore` crate for compile time
//! (see `glob`); the reading follows the crate's own, line for line,
//! down to its error messages, and tests/integration/search_rules.rs
//! pins the result to it.

use super::glob::Glob;
use std::io::{BufRead, ErrorKind};
use std::path::{Path, PathBuf};

/// Whether a path is ignored, re-included by a `!` rule, or neither.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Match {
    None,
    Ignore,
    Whitelist,
}

impl Match {
    pub fn is_none(self) -> bool {
        self == Match::None
    }

    /// `self`, or `other` where `self` says nothing.
    pub fn or(self, other: impl FnOnce() -> Match) -> Match {
        if self.is_none() { other() } else { self }
    }
}

/// One rule: its glob, whether it is a `!` rule, whether for directories
/// only.
#[derive(Debug, Clone)]
struct Rule {
    glob: Glob,
    whitelist: bool,
    only_dir: bool,
}

/// A problem reading an ignore file, as the `ignore` crate words it.
/// `io`: an input/output error (which the crate drops when it is the
/// file's only problem).
#[derive(Debug, Clone)]
pub struct Problem {
    pub text: String,
    pub io: bool,
}

/// The rules of one ignore file (or of `--exclude`), relative to `root`.
#[derive(Debug, Clone)]
pub struct Rules {
    root: PathBuf,
    rules: Vec<Rule>,
    /// A class no regular expression compiles: no rule applies.
    poisoned: bool,
}

impl Rules {
    /// No rules, relative to `root` (a leading `./` taken off).
    pub fn new(root: &Path) -> Rules {
        let root = strip_prefix(Path::new("./"), root)
            .unwrap_or(root)
            .to_path_buf();
        Rules {
            root,
            rules: Vec::new(),
            poisoned: false,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.poisoned || self.rules.is_empty()
    }

    /// Adds a line of an ignore file; an error names the glob. An
    /// unclosed `[` is a literal where `allow_unclosed_class`.
    pub fn add_line(&mut self, line: &str, allow_unclosed_class: bool) -> Result<(), String> {
        let Some(parsed) = parse_line(line) else {
            return Ok(());
        };
        match Glob::new(&parsed.actual, allow_unclosed_class) {
            Ok(Some(glob)) => self.rules.push(Rule {
                glob,
                whitelist: parsed.whitelist,
                only_dir: parsed.only_dir,
            }),
            // NOTE: the regular expression the crate would build of the
            // whole file does not compile; it then keeps no rule of it.
            Ok(None) => self.poisoned = true,
            Err(e) => {
                let original = trim_trailing_unescaped_spaces(line);
                return Err(format!("error parsing glob '{original}': {e}"));
            }
        }
        Ok(())
    }

    /// Whether a glob's class made the whole file void (see `add_line`):
    /// the crate's message for it is its regular expression library's.
    pub fn void_problem(&self) -> Option<Problem> {
        self.poisoned.then(|| Problem {
            text: "error parsing glob: a character class of non-ASCII characters whose bytes are out of order".to_string(),
            io: false,
        })
    }

    /// Reads the ignore file at `path` (as the crate's
    /// `GitignoreBuilder::add`): a line that is not UTF-8 is passed over,
    /// a read error ends the file. The problems found, if any.
    pub fn add_file(&mut self, path: &Path) -> Vec<Problem> {
        let mut problems = Vec::new();
        let file = match std::fs::File::open(path) {
            Ok(f) => f,
            Err(e) => {
                problems.push(Problem {
                    text: format!("{}: {e}", path.display()),
                    io: true,
                });
                return problems;
            }
        };
        let mut reader = std::io::BufReader::new(file);
        let mut buf = Vec::new();
        for lineno in 1.. {
            buf.clear();
            match reader.read_until(b'\n', &mut buf) {
                Ok(0) => break,
                Ok(_) => {}
                Err(e) => {
                    let fatal = e.kind() != ErrorKind::InvalidData;
                    problems.push(Problem {
                        text: format!("{}: line {lineno}: {e}", path.display()),
                        io: true,
                    });
                    if fatal {
                        break;
                    }
                    continue;
                }
            }
            if buf.last() == Some(&b'\n') {
                buf.pop();
                if buf.last() == Some(&b'\r') {
                    buf.pop();
                }
            }
            let Ok(line) = std::str::from_utf8(&buf) else {
                problems.push(Problem {
                    text: format!(
                        "{}: line {lineno}: stream did not contain valid UTF-8",
                        path.display()
                    ),
                    io: true,
                });
                continue;
            };
            // Git's handling of a file that begins with a byte order mark.
            let line = if lineno == 1 {
                line.trim_start_matches('\u{feff}')
            } else {
                line
            };
            if let Err(e) = self.add_line(line, true) {
                problems.push(Problem {
                    text: format!("{}: line {lineno}: {e}", path.display()),
                    io: false,
                });
            }
        }
        problems
    }

    /// The last rule that matches `path` (a path as the search walks it,
    /// made relative to `root`), among those for directories only where
    /// `is_dir`.
    pub fn matched(&self, path: &Path, is_dir: bool) -> Match {
        if self.is_empty() {
            return Match::None;
        }
        let stripped = self.strip(path);
        // The directory's own name where stripping leaves nothing.
        let candidate = if stripped.as_os_str().is_empty() {
            path
        } else {
            stripped
        };
        let bytes = candidate.as_os_str().as_encoded_bytes();
        for rule in self.rules.iter().rev() {
            if (!rule.only_dir || is_dir) && rule.glob.is_match(bytes) {
                return if rule.whitelist {
                    Match::Whitelist
                } else {
                    Match::Ignore
                };
            }
        }
        Match::None
    }

    /// `path` relative to `root` (as the crate's `Gitignore::strip`).
    fn strip<'a>(&self, path: &'a Path) -> &'a Path {
        let mut path = strip_prefix(Path::new("./"), path).unwrap_or(path);
        let is_file_name = !path.as_os_str().as_encoded_bytes().contains(&b'/');
        if self.root != Path::new(".")
            && !is_file_name
            && let Some(p) = strip_prefix(&self.root, path)
        {
            path = strip_prefix(Path::new("/"), p).unwrap_or(p);
        }
        path
    }
}

/// A line's glob as the crate builds it: `actual` the glob matched
/// against the path relative to the ignore file's directory.
struct Parsed {
    actual: String,
    whitelist: bool,
    only_dir: bool,
}

/// `None` for a line that is no rule: blank, a comment, or `!` or `/`
/// with nothing after it.
fn parse_line(line: &str) -> Option<Parsed> {
    if line.starts_with('#') {
        return None;
    }
    let mut line = trim_trailing_unescaped_spaces(line);
    if line.is_empty() {
        return None;
    }
    let mut whitelist = false;
    let mut anchored = false;
    if line.starts_with("\\!") || line.starts_with("\\#") {
        line = &line[1..];
        anchored = line.starts_with('/');
    } else {
        if let Some(rest) = line.strip_prefix('!') {
            whitelist = true;
            line = rest;
        }
        if let Some(rest) = line.strip_prefix('/') {
            line = rest;
            anchored = true;
        }
    }
    if line.is_empty() {
        return None;
    }
    let mut only_dir = false;
    if let Some(rest) = line.strip_suffix('/') {
        only_dir = true;
        line = rest.strip_suffix('\\').unwrap_or(rest);
    }
    let mut actual = line.to_string();
    if !(anchored || line.contains('/') || actual.starts_with("**/") || actual == "**") {
        actual = format!("**/{actual}");
    }
    if actual.ends_with("/**") {
        actual.push_str("/*");
    }
    Some(Parsed {
        actual,
        whitelist,
        only_dir,
    })
}

/// `line` less its trailing spaces, but those escaped by a `\`.
fn trim_trailing_unescaped_spaces(line: &str) -> &str {
    let bytes = line.as_bytes();
    let mut last_space = None;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => {
                if i + 1 >= bytes.len() {
                    return line;
                }
                i += 2;
                last_space = None;
            }
            b' ' => {
                last_space = last_space.or(Some(i));
                i += 1;
            }
            _ => {
                last_space = None;
                i += 1;
            }
        }
    }
    &line[..last_space.unwrap_or(line.len())]
}

/// `path` less `prefix`, byte for byte, not splitting a component (as the
/// crate's `pathutil::strip_prefix`).
pub fn strip_prefix<'a>(prefix: &Path, path: &'a Path) -> Option<&'a Path> {
    let prefix = prefix.as_os_str().as_encoded_bytes();
    let bytes = path.as_os_str().as_encoded_bytes();
    let rest = bytes.strip_prefix(prefix)?;
    if prefix.last().is_some_and(|&b| b != b'/') && rest.first().is_some_and(|&b| b != b'/') {
        return None;
    }
    let skip = bytes.len() - rest.len();
    Some(Path::new(os_from_bytes(&bytes[skip..])))
}

#[cfg(unix)]
fn os_from_bytes(b: &[u8]) -> &std::ffi::OsStr {
    use std::os::unix::ffi::OsStrExt;
    std::ffi::OsStr::from_bytes(b)
}

#[cfg(not(unix))]
fn os_from_bytes(b: &[u8]) -> &std::ffi::OsStr {
    std::ffi::OsStr::new(std::str::from_utf8(b).unwrap_or_default())
}
