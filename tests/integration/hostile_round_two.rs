//! Hostile input, round two (issue 12): the classes the first round's
//! generators (hostile.rs) did not reach, each generated, run in process
//! through the commands, with the first round's promises (no panic or
//! hang, status 0, 1 or 2, a diagnostic that starts `file[:line:col]:
//! error:`, valid finite JSON, no `inf` or `NaN`) and the class's own:
//!
//! - include trees: random trees of part files (fan-out, a few levels,
//!   files shared by many includes, cycles, links), with includes that
//!   escape the directory (`..`, absolute paths, symlinks to a file or a
//!   directory outside) and includes of what is not a part file (text,
//!   binary, a directory, an empty file, a missing file, a FIFO). The
//!   outcome is predicted by walking the tree as the loader does: the total
//!   mass counts every instance, or the error is at the include (or in the
//!   file) the walk says. A marker planted in the files outside never
//!   appears in any output;
//! - hostile names: part, sub-assembly, material, file-level and file
//!   names with control characters (ESC sequences, CR, LF, BEL, NUL, DEL,
//!   C1), bidi overrides and thousands of characters. No raw control
//!   character (but newline and tab) reaches stdout, no line-per-record
//!   output gains a line (counted against a twin with plain names), and
//!   the JSON gives every name back exactly;
//! - `[expect]` entries one level too deep or with nothing to compare: a
//!   located error (status 2) at one of them, never a pass;
//! - values that underflow or overflow, and radii of gyration at the
//!   extremes: no `inf` or `NaN` anywhere, and a number printed as 0 in
//!   the table only where the JSON's is 0 (and a radius of gyration is 0
//!   only where its moment is).
//!
//! Deterministic (fixed ChaCha seed, no persistence), as hostile.rs.

use super::hostile::{check_json, hostile, non_finite_word, property, run, walk};
use proptest::prelude::*;
use serde_json::Value;
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// Include trees: each runs `report` twice, `check` on the top file and on
/// the tree's directory.
const TREES: u32 = 120;
/// Files with hostile names: each runs ten commands, and again on a twin
/// with plain names.
const NAMED: u32 = 60;
/// Files with `[expect]` entries too deep.
const DEEP: u32 = 100;
/// Files of extreme values: each runs hostile.rs's eight commands.
const EXTREMES: u32 = 120;

// ---------------------------------------------------------------------------
// Running a command

/// What a command printed, an error (`Err` from `massprop::run`) as
/// `main` prints it: status 2, its diagnostic on stderr.
#[derive(Debug)]
struct Out {
    status: u8,
    stdout: String,
    stderr: String,
    /// The run ended in a diagnostic.
    failed: bool,
}

/// `massprop ARGS`, with the first round's promises on what any command
/// prints: status 0, 1 or 2; an error is one diagnostic whose first line
/// is `FILE[:LINE:COL]: error: …` (nothing on stdout); `check` reports an
/// invalid file the same way on stderr.
fn exec(args: &[&str]) -> Result<Out, String> {
    let what = args.join(" ");
    let out = match run(args)? {
        Ok(o) => Out {
            status: o.status,
            stdout: o.stdout.text(),
            stderr: o.stderr,
            failed: false,
        },
        Err(d) => Out {
            status: 2,
            stdout: String::new(),
            stderr: d.to_string(),
            failed: true,
        },
    };
    if out.status > 2 {
        return Err(format!("{what}: status {}", out.status));
    }
    let located = |line: &str| {
        line.find(": error: ")
            .is_some_and(|at| at > 0 && !line.starts_with("error:"))
    };
    if out.failed && !out.stderr.lines().next().is_some_and(located) {
        return Err(format!(
            "{what}: the error does not start `file: error:`:\n{}",
            out.stderr
        ));
    }
    if !out.failed && out.status == 2 && !out.stderr.lines().any(located) {
        return Err(format!(
            "{what}: status 2 without a located error:\n{}",
            out.stderr
        ));
    }
    Ok(out)
}

/// The file an error's first line is located in (`FILE` of `FILE:L:C:
/// error:`).
fn error_file(stderr: &str) -> &str {
    let line = stderr.lines().next().unwrap_or("");
    let loc = &line[..line.find(": error: ").unwrap_or(0)];
    // Strip `:LINE:COL` if it is there.
    let mut parts = loc.rsplitn(3, ':');
    match (parts.next(), parts.next(), parts.next()) {
        (Some(c), Some(l), Some(file))
            if c.bytes().all(|b| b.is_ascii_digit()) && l.bytes().all(|b| b.is_ascii_digit()) =>
        {
            file
        }
        _ => loc,
    }
}

/// The 1-based line of an error's location, if it has one.
fn error_line(stderr: &str) -> Option<usize> {
    let line = stderr.lines().next()?;
    let loc = &line[..line.find(": error: ")?];
    let mut parts = loc.rsplitn(3, ':');
    let _col = parts.next()?;
    parts.next()?.parse().ok()
}

/// Remove a directory from `outside_cwd`, and its parent once empty.
fn remove_outside(dir: &Path) {
    std::fs::remove_dir_all(dir).ok();
    if let Some(parent) = dir.parent() {
        // Fails while another test still has its directory there.
        std::fs::remove_dir(parent).ok();
    }
}

/// A directory outside the working directory (the crate, where cargo runs
/// the tests, and which includes may always reach): includes that escape a
/// tree in it must be refused. Emptied first.
fn outside_cwd(name: &str) -> PathBuf {
    let dir = std::env::temp_dir()
        .join(format!("massprop-hostile-{}", std::process::id()))
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let dir = dir.canonicalize().unwrap();
    let cwd = std::env::current_dir().unwrap().canonicalize().unwrap();
    assert!(
        !dir.starts_with(&cwd),
        "the temporary directory {} is inside the working directory: includes from it cannot escape",
        dir.display()
    );
    dir
}

// ---------------------------------------------------------------------------
// Include trees

/// In the files outside the tree: no output may ever show it.
const MARKER: &str = "OUTSIDE-SECRET-5f3a9";

/// Where an include points.
#[derive(Clone, Debug)]
enum Target {
    /// A file of the tree, by a relative path (`../sub/f2.toml`), or
    /// `./`, or through a detour (`sub/../f2.toml`).
    File(usize, u8),
    /// A file of the tree by its absolute path.
    Absolute(usize),
    /// A symlink in the tree to a file of the tree.
    Link(usize),
    /// A file outside the tree: 0 `../outside/…`, 1 its absolute path, 2 a
    /// symlink in the tree to it, 3 through a symlink in the tree to the
    /// outside directory; the file is a valid part file, or (`bad`) one
    /// whose first line is a syntax error quoting the marker.
    Escape(u8, bool),
    /// Not a part file: 0 text, 1 binary, 2 a directory, 3 an empty file,
    /// 4 a missing file, 5 a FIFO.
    NonPart(u8),
}

#[derive(Clone, Debug)]
struct Include {
    target: Target,
    name: bool,
    origin: bool,
    rotation: bool,
}

#[derive(Clone, Debug)]
struct TreeFile {
    /// 0 the tree's directory, 1 `sub/`, 2 `sub/deep/`.
    dir: u8,
    /// Own parts (points and boxes of mass 1).
    parts: usize,
    includes: Vec<Include>,
    /// The file states `units` (mm and g): placed sub-assemblies convert.
    units: bool,
}

fn include() -> impl Strategy<Value = Include> {
    let target = prop_oneof![
        14 => (0..8usize, 0..4u8).prop_map(|(j, how)| Target::File(j, how)),
        2 => (0..8usize).prop_map(Target::Absolute),
        2 => (0..8usize).prop_map(Target::Link),
        2 => (0..4u8, any::<bool>()).prop_map(|(how, bad)| Target::Escape(how, bad)),
        2 => (0..6u8).prop_map(Target::NonPart),
    ];
    (
        target,
        prop::bool::weighted(0.3),
        prop::bool::weighted(0.3),
        prop::bool::weighted(0.2),
    )
        .prop_map(|(target, name, origin, rotation)| Include {
            target,
            name,
            origin,
            rotation,
        })
}

fn tree() -> impl Strategy<Value = Vec<TreeFile>> {
    let file = (
        0..3u8,
        0..3usize,
        prop::collection::vec(include(), 0..=3),
        prop::bool::weighted(0.2),
    )
        .prop_map(|(dir, parts, includes, units)| TreeFile {
            dir,
            parts,
            includes,
            units,
        });
    prop::collection::vec(file, 1..=7).prop_map(|mut files| {
        let n = files.len();
        files[0].dir = 0;
        // Most includes go down the list (a tree, or a DAG where files are
        // shared); one in five goes to an earlier file or the file itself,
        // which may close a cycle. The last file has nothing below it.
        for (i, f) in files.iter_mut().enumerate() {
            f.includes.retain_mut(|inc| match &mut inc.target {
                Target::File(j, _) | Target::Absolute(j) | Target::Link(j) => {
                    if *j % 5 == 4 {
                        *j %= i + 1;
                        true
                    } else if i + 1 < n {
                        *j = i + 1 + *j % (n - i - 1);
                        true
                    } else {
                        false
                    }
                }
                _ => true,
            });
        }
        files
    })
}

/// A tree written into a directory: its files' paths and texts.
struct Written {
    dir: PathBuf,
    paths: Vec<PathBuf>,
    /// Lines (1-based) of each file's includes, in order.
    include_lines: Vec<Vec<usize>>,
}

fn dir_of(d: u8) -> &'static str {
    ["", "sub/", "sub/deep/"][usize::from(d)]
}

/// `to` (relative to the tree) as a path from a file in `from_dir`.
fn relative(from_dir: u8, to: &str) -> String {
    format!("{}{to}", "../".repeat(usize::from(from_dir)))
}

fn file_path(files: &[TreeFile], j: usize) -> String {
    format!("{}f{j}.toml", dir_of(files[j].dir))
}

/// Write the tree into `root/tree`; the files outside are `root/outside`.
fn write_tree(root: &Path, files: &[TreeFile]) -> Written {
    let dir = root.join("tree");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("sub/deep")).unwrap();
    let outside = root.join("outside");
    let mut include_lines = Vec::new();
    let mut links = 0;
    let symlink = |target: &Path, name: String| {
        std::os::unix::fs::symlink(target, dir.join(&name)).unwrap();
        name
    };
    let mut texts = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let mut lines = vec![format!("# tree file {i}")];
        if f.units {
            lines.push("units = { length = \"mm\", mass = \"g\" }".to_string());
        }
        for k in 0..f.parts {
            lines.push(String::new());
            lines.push("[[part]]".to_string());
            lines.push(format!("name = \"p{k}\""));
            if k % 2 == 0 {
                lines.push("shape = \"point\"".to_string());
            } else {
                lines.push("shape = \"box\"".to_string());
                lines.push("size = [1, 2, 3]".to_string());
            }
            lines.push("mass = 1".to_string());
            lines.push(format!("center = [{k}, 1, 2]"));
        }
        let mut at = Vec::new();
        for inc in &f.includes {
            let up = |to: &str| relative(f.dir, to);
            let path = match &inc.target {
                Target::File(j, how) => {
                    let to = file_path(files, *j);
                    match how {
                        0 => up(&to),
                        1 if f.dir == files[*j].dir => format!("./f{j}.toml"),
                        2 => up(&format!("sub/../{to}")),
                        _ => up(&to),
                    }
                }
                Target::Absolute(j) => dir.join(file_path(files, *j)).display().to_string(),
                Target::Link(j) => {
                    // Beside its target: includes inside it are relative
                    // to the link's directory (as the path names it).
                    links += 1;
                    let name = format!("{}link{links}.toml", dir_of(files[*j].dir));
                    up(&symlink(&dir.join(file_path(files, *j)), name))
                }
                Target::Escape(how, bad) => {
                    let file = if *bad {
                        "secret-bad.toml"
                    } else {
                        "secret.toml"
                    };
                    match how {
                        0 => up(&format!("../outside/{file}")),
                        1 => outside.join(file).display().to_string(),
                        2 => {
                            links += 1;
                            let name = symlink(&outside.join(file), format!("link{links}.toml"));
                            up(&name)
                        }
                        _ => {
                            links += 1;
                            let name = symlink(&outside, format!("linkdir{links}"));
                            up(&format!("{name}/{file}"))
                        }
                    }
                }
                Target::NonPart(k) => up([
                    "notes.txt",
                    "blob.bin",
                    "adir",
                    "empty.toml",
                    "missing.toml",
                    "fifo.toml",
                ][usize::from(*k)]),
            };
            lines.push(String::new());
            lines.push("[[part]]".to_string());
            if inc.name {
                lines.push(format!("name = \"asm{i}\""));
            }
            at.push(lines.len() + 1);
            lines.push(format!("include = \"{path}\""));
            if inc.origin {
                lines.push("origin = [1, 0, 0]".to_string());
            }
            if inc.rotation {
                lines.push("rotation = { axis = [0, 0, 1], degrees = 90 }".to_string());
            }
        }
        include_lines.push(at);
        texts.push(lines.join("\n") + "\n");
    }
    let mut paths = Vec::new();
    for (i, text) in texts.iter().enumerate() {
        let p = dir.join(file_path(files, i));
        std::fs::write(&p, text).unwrap();
        paths.push(p);
    }
    // What is not a part file.
    std::fs::write(dir.join("notes.txt"), "just some notes\nnot = [toml\n").unwrap();
    std::fs::write(dir.join("blob.bin"), b"\xff\xfe\x00binary\x80").unwrap();
    std::fs::create_dir_all(dir.join("adir")).unwrap();
    std::fs::write(dir.join("empty.toml"), "").unwrap();
    let fifo = std::process::Command::new("mkfifo")
        .arg(dir.join("fifo.toml"))
        .status();
    assert!(fifo.is_ok_and(|s| s.success()), "mkfifo makes a FIFO");
    Written {
        dir,
        paths,
        include_lines,
    }
}

/// The files outside the tree, with the marker: a valid part file that
/// names its part with it, and a file whose first line, quoting it, is a
/// syntax error.
fn write_outside(root: &Path) {
    let outside = root.join("outside");
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(
        outside.join("secret.toml"),
        format!(
            "# {MARKER}\nname = \"{MARKER}\"\n[[part]]\nname = \"{MARKER}\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n"
        ),
    )
    .unwrap();
    std::fs::write(outside.join("secret-bad.toml"), format!("{MARKER} = [\n")).unwrap();
}

/// What loading the tree's top file gives, walking it as the loader does
/// (depth first, in file order, each file parsed once): the number of parts
/// (each of mass 1), or the error: the file it is located in (as the path
/// it was named by: the tree file, or the non-part file), its line if it
/// is at an include, and words of its message.
#[derive(Debug, PartialEq)]
enum Predicted {
    /// Parts in files in kg, and in files in g (each of mass 1).
    Parts(u64, u64),
    Error {
        /// The tree file (its index) whose include is refused, or the
        /// name of the non-part file the error is in.
        at: Result<(usize, usize), &'static str>,
        words: &'static str,
    },
}

fn predict(files: &[TreeFile], written: &Written) -> Predicted {
    fn visit(
        files: &[TreeFile],
        written: &Written,
        i: usize,
        stack: &mut Vec<usize>,
        done: &mut Vec<Option<(u64, u64)>>,
    ) -> Result<(u64, u64), Predicted> {
        let f = &files[i];
        if f.parts == 0 && f.includes.is_empty() {
            unreachable!("every tree file has a part or an include");
        }
        stack.push(i);
        let own = f.parts as u64;
        let mut n = if f.units { (0, own) } else { (own, 0) };
        for (k, inc) in f.includes.iter().enumerate() {
            let line = written.include_lines[i][k];
            let refused = |words| Predicted::Error {
                at: Ok((i, line)),
                words,
            };
            let j = match &inc.target {
                Target::File(j, _) | Target::Absolute(j) | Target::Link(j) => *j,
                Target::Escape(..) => return Err(refused("is outside the directory")),
                // Not `*.toml`: refused before it is read.
                Target::NonPart(0 | 1) => return Err(refused("is not a part file (`*.toml`)")),
                Target::NonPart(2 | 5) => return Err(refused("is not a regular file")),
                // TOML without `[[part]]`: refused, nothing of it quoted.
                Target::NonPart(3) => {
                    return Err(refused("is not a part file: it has no `[[part]]` table"));
                }
                Target::NonPart(_) => return Err(refused("cannot read the included file")),
            };
            if stack.contains(&j) {
                return Err(refused("include cycle"));
            }
            let (kg, g) = match done[j] {
                Some(m) => m,
                None => visit(files, written, j, stack, done)?,
            };
            n = (n.0 + kg, n.1 + g);
        }
        stack.pop();
        done[i] = Some(n);
        Ok(n)
    }
    let mut done = vec![None; files.len()];
    match visit(files, written, 0, &mut Vec::new(), &mut done) {
        Ok((kg, g)) => Predicted::Parts(kg, g),
        Err(e) => e,
    }
}

/// The `*.toml` that `check DIR` finds in `dir` (not following symlinked
/// directories).
fn toml_files(dir: &Path) -> usize {
    fn count(dir: &Path, root: &Path) -> usize {
        let mut n = 0;
        for e in std::fs::read_dir(dir).unwrap() {
            let e = e.unwrap();
            let (p, t) = (e.path(), e.file_type().unwrap());
            if t.is_dir() {
                n += count(&p, root);
            } else if p.extension().is_some_and(|x| x == "toml") {
                // A symlink out of the tree, or to what is not `*.toml`, is
                // reported; so is anything not a regular file (a FIFO, a
                // broken link: never opened, reading a FIFO blocks). A
                // regular file is a part file when it has a `[[part]]`
                // table (an empty one is passed over).
                let escapes = t.is_symlink()
                    && std::fs::canonicalize(&p).is_ok_and(|t| {
                        !(t.starts_with(root) && t.extension().is_some_and(|x| x == "toml"))
                    });
                n += match std::fs::metadata(&p) {
                    _ if escapes => 1,
                    Ok(m) if m.is_dir() => 0,
                    Ok(m) if m.is_file() => usize::from(
                        std::fs::read_to_string(&p).map_or(true, |t| t.contains("[[part]]")),
                    ),
                    _ => 1,
                };
            }
        }
        n
    }
    count(dir, &std::fs::canonicalize(dir).unwrap())
}

fn no_marker(what: &str, out: &Out) -> Result<(), String> {
    if out.stdout.contains(MARKER) || out.stderr.contains(MARKER) {
        return Err(format!(
            "{what} quotes a file it must not (the marker shows):\n{}{}",
            out.stdout, out.stderr
        ));
    }
    Ok(())
}

/// One tree: its outcome as predicted, the marker nowhere.
fn tree_case(root: &Path, files: &[TreeFile]) -> Result<bool, String> {
    // A file with neither part nor include has no parts: give it one.
    let mut files = files.to_vec();
    for f in &mut files {
        if f.parts == 0 && f.includes.is_empty() {
            f.parts = 1;
        }
    }
    let written = write_tree(root, &files);
    let top = written.paths[0].to_str().unwrap();
    let predicted = predict(&files, &written);
    let json = exec(&["report", "--format", "json", top])?;
    no_marker("report --format json", &json)?;
    match &predicted {
        Predicted::Parts(kg, g) => {
            let n = kg + g;
            if json.status != 0 {
                return Err(format!("expected {n} parts, got:\n{}", json.stderr));
            }
            check_json(&json.stdout)?;
            let v: Value = serde_json::from_str(&json.stdout).unwrap();
            let parts = v["parts"].as_array().map_or(0, Vec::len) as u64;
            if parts != n {
                return Err(format!("expected {n} parts, the JSON has {parts}"));
            }
            // Every part has mass 1 in its own file's unit: 1 kg, or 1 g
            // where the file is in grams.
            let mass = v["mass"].as_f64().unwrap();
            let want = *kg as f64 + *g as f64 * 1e-3;
            if (mass - want).abs() > want * 1e-12 {
                return Err(format!("{kg} parts of 1 kg and {g} of 1 g weigh {mass} kg"));
            }
        }
        Predicted::Error { at, words } => {
            if !json.failed {
                return Err(format!(
                    "expected an error ({words}), got status {}",
                    json.status
                ));
            }
            let file = error_file(&json.stderr);
            let ok = match at {
                Ok((i, line)) => {
                    // As the include named it (`sub/../f3.toml`).
                    std::fs::canonicalize(file).ok() == written.paths[*i].canonicalize().ok()
                        && error_line(&json.stderr) == Some(*line)
                }
                Err(name) => file.ends_with(name),
            };
            if !ok || !json.stderr.contains(words) {
                return Err(format!(
                    "expected the error ({words:?}) at {at:?}, got:\n{}",
                    json.stderr
                ));
            }
        }
    }
    let table = exec(&["report", top])?;
    no_marker("report", &table)?;
    if table.failed != json.failed {
        return Err("the table and the JSON disagree".to_string());
    }
    if let Some(w) = non_finite_word(&table.stdout) {
        return Err(format!("report prints {w:?}"));
    }
    let check = exec(&["check", top])?;
    no_marker("check FILE", &check)?;
    if check.status != if json.failed { 2 } else { 0 } {
        return Err(format!("check FILE: status {}", check.status));
    }
    // `check DIR` on the tree: one line per `*.toml` and the summary.
    let dir = exec(&["check", written.dir.to_str().unwrap()])?;
    // A symlink named *.toml to a file outside is reported, not read.
    no_marker("check DIR", &dir)?;
    let expected = toml_files(&written.dir) + 1;
    if dir.failed || dir.stdout.lines().count() != expected {
        return Err(format!(
            "check DIR: {expected} lines expected:\n{}{}",
            dir.stdout, dir.stderr
        ));
    }
    Ok(!json.failed)
}

#[test]
fn include_trees_give_the_parts_or_the_error_and_never_leave_the_tree() {
    let root = outside_cwd("trees");
    write_outside(&root);
    property("include trees", TREES, tree(), |files| {
        tree_case(&root, files).map_err(|e| format!("{e}\n--- tree ---\n{files:#?}"))
    });
    remove_outside(&root);
}

/// The marker check can fail: with `--include-root` the outside file is
/// allowed, and its name shows.
#[test]
fn the_outside_marker_shows_when_an_include_root_allows_it() {
    let root = outside_cwd("marker");
    write_outside(&root);
    std::fs::create_dir_all(root.join("tree")).unwrap();
    let top = root.join("tree/top.toml");
    std::fs::write(&top, "[[part]]\ninclude = \"../outside/secret.toml\"\n").unwrap();
    let top = top.to_str().unwrap();
    let refused = exec(&["report", "--format", "json", top]).unwrap();
    assert!(
        refused.failed && no_marker("", &refused).is_ok(),
        "{refused:?}"
    );
    let outside = root.join("outside");
    let allowed = exec(&[
        "report",
        "--format",
        "json",
        "--include-root",
        outside.to_str().unwrap(),
        top,
    ])
    .unwrap();
    assert_eq!(allowed.status, 0, "{}", allowed.stderr);
    assert!(no_marker("", &allowed).is_err());
    remove_outside(&root);
}

/// Regression (issue 12, item 3): `check DIR` followed a symlink named
/// `*.toml` that a pull request may add (`x.toml -> /proc/self/environ`)
/// and quoted the file it leads to in its error: the environment, tokens
/// and all, in the CI log. A link found by the walk is followed only to a
/// `*.toml` file inside DIR.
#[test]
fn check_dir_does_not_quote_a_linked_file_outside_the_tree() {
    let root = outside_cwd("check-link");
    write_outside(&root);
    let tree = root.join("tree");
    std::fs::create_dir_all(&tree).unwrap();
    std::os::unix::fs::symlink(root.join("outside/secret-bad.toml"), tree.join("x.toml")).unwrap();
    let out = exec(&["check", tree.to_str().unwrap()]).unwrap();
    remove_outside(&root);
    no_marker("check DIR", &out).unwrap();
}

/// Regression (issue 12, item 3: "no error excerpt ever quotes a file that is
/// not a part file"): an include of a file inside the tree that is not a
/// part file (`.env`, `.git/config`, where actions/checkout keeps the
/// token) was parsed as TOML and its line quoted in the error. Now an
/// error at the include says the file is not a part file, quoting none of
/// it.
#[test]
fn an_include_of_a_file_that_is_not_a_part_file_is_not_quoted() {
    let dir = crate::common::scratch("hostile", "non-part");
    std::fs::write(dir.join(".env"), format!("API_TOKEN={MARKER}\n")).unwrap();
    let top = dir.join("top.toml");
    std::fs::write(&top, "[[part]]\ninclude = \".env\"\n").unwrap();
    let out = exec(&["report", top.to_str().unwrap()]).unwrap();
    assert_eq!(out.status, 2);
    no_marker("report", &out).unwrap();
}

// ---------------------------------------------------------------------------
// Hostile names

/// Pieces of names: control characters and sequences, bidi overrides,
/// what looks like a qualified or numbered name.
const PIECES: &[&str] = &[
    "a",
    "part",
    "\u{1b}[31m",
    "\u{1b}]0;title\u{7}",
    "\u{1b}[2J",
    "\r",
    "\n",
    "\r\n",
    "\u{7}",
    "\u{0}",
    "\u{7f}",
    "\u{9b}",
    "\u{85}",
    "\u{202e}",
    "\u{2028}",
    "\u{2066}",
    "\t",
    "é",
    " / ",
    " #2",
    "\u{feff}",
    "ok",
    ": ok",
];

/// A name: a few pieces, or thousands of characters.
fn name() -> BoxedStrategy<String> {
    prop_oneof![
        8 => prop::collection::vec(prop::sample::select(PIECES), 1..=5).prop_map(|v| v.concat()),
        1 => (1000..6000usize, prop::sample::select(vec!["x", "\u{1b}", "\n", "é"]))
            .prop_map(|(n, c)| c.repeat(n)),
    ]
    .boxed()
}

/// A file name from `text`: no `/` or NUL, at most 200 bytes, `.toml`.
fn file_name(text: &str, fallback: &str) -> String {
    let mut name: String = text.chars().filter(|c| !matches!(c, '/' | '\0')).collect();
    while name.len() > 200 {
        name.pop();
    }
    if name.is_empty() || name == "." || name == ".." {
        name = fallback.to_string();
    }
    format!("{name}.toml")
}

/// `text` as a TOML basic string: what TOML forbids raw escaped, and
/// (`all`) every non-ASCII character too.
fn quoted(text: &str, all: bool) -> String {
    let mut s = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '\t' if !all => s.push('\t'),
            c if (c as u32) < 0x20 || c == '\u{7f}' || (all && !c.is_ascii()) => {
                s.push_str(&format!("\\u{:04X}", c as u32));
            }
            c => s.push(c),
        }
    }
    s.push('"');
    s
}

#[derive(Clone, Debug)]
struct Names {
    file: String,
    top_file: String,
    sub_file: String,
    material: String,
    parts: Vec<String>,
    sub_parts: Vec<String>,
    /// The include's `name`, or (None) the sub-file's `name`, or (its
    /// stem) the sub-file's file name.
    assembly: Option<String>,
    sub_name: Option<String>,
    escape_all: bool,
    /// An `[expect]` that fails: `check` prints a line per failure.
    fail: bool,
}

fn names() -> impl Strategy<Value = Names> {
    (
        (name(), name(), name(), name()),
        prop::collection::vec(name(), 1..=3),
        prop::collection::vec(name(), 1..=2),
        (
            prop::option::of(name()),
            prop::option::of(name()),
            any::<bool>(),
            any::<bool>(),
        ),
    )
        .prop_map(
            |((file, top_file, sub_file, material), parts, sub_parts, rest)| Names {
                file,
                top_file,
                sub_file,
                material,
                parts,
                sub_parts,
                assembly: rest.0,
                sub_name: rest.1,
                escape_all: rest.2,
                fail: rest.3,
            },
        )
}

impl Names {
    /// The same structure with plain names: what each output must match
    /// line for line.
    fn tame(&self) -> Names {
        let plain = |i: usize| format!("n{i}");
        Names {
            file: plain(0),
            top_file: plain(1),
            sub_file: plain(2),
            material: plain(3),
            parts: (0..self.parts.len()).map(|i| plain(10 + i)).collect(),
            sub_parts: (0..self.sub_parts.len()).map(|i| plain(20 + i)).collect(),
            assembly: self.assembly.as_ref().map(|_| plain(4)),
            sub_name: self.sub_name.as_ref().map(|_| plain(5)),
            ..self.clone()
        }
    }

    /// Write the top file and its sub-assembly (included twice) into
    /// `dir`, and a copy of the top file with other masses (for `diff`).
    /// Returns the three paths.
    fn write(&self, dir: &Path) -> [PathBuf; 3] {
        let _ = std::fs::remove_dir_all(dir);
        std::fs::create_dir_all(dir).unwrap();
        let q = |t: &str| quoted(t, self.escape_all);
        let sub_file = file_name(&self.sub_file, "sub");
        let top_file = file_name(&self.top_file, "top");
        let top_file = if top_file == sub_file {
            format!("top-{top_file}")
        } else {
            top_file
        };
        let mut sub = String::new();
        if let Some(n) = &self.sub_name {
            sub.push_str(&format!("name = {}\n", q(n)));
        }
        for (k, p) in self.sub_parts.iter().enumerate() {
            sub.push_str(&format!(
                "\n[[part]]\nname = {}\nshape = \"point\"\nmass = 1\ncenter = [{k}, 0, 0]\n",
                q(p)
            ));
        }
        let mut top = format!(
            "name = {}\n\n[materials]\n{} = {{ density = 1000 }}\n",
            q(&self.file),
            q(&self.material)
        );
        for (k, p) in self.parts.iter().enumerate() {
            top.push_str(&format!(
                "\n[[part]]\nname = {}\nshape = \"box\"\nmaterial = {}\nsize = [1, 1, 1]\ncenter = [{k}, 1, 0]\n",
                q(p),
                q(&self.material)
            ));
        }
        for (origin, name) in ["[0, 0, 1]", "[0, 0, 2]"].into_iter().zip(self.written()) {
            top.push_str("\n[[part]]\n");
            if let Some(a) = name {
                top.push_str(&format!("name = {}\n", q(&a)));
            }
            top.push_str(&format!("include = {}\norigin = {origin}\n", q(&sub_file)));
        }
        if self.fail {
            top.push_str("\n[expect]\nmass = { max = 1 }\ncenter_of_mass.z = { min = 10 }\n");
        }
        let paths = [
            dir.join(&top_file),
            dir.join(&sub_file),
            dir.join("other.toml"),
        ];
        std::fs::write(&paths[0], &top).unwrap();
        std::fs::write(&paths[1], &sub).unwrap();
        std::fs::write(&paths[2], top.replace("mass = 1\n", "mass = 2\n")).unwrap();
        paths
    }

    /// The `name`s written on the two includes: none, or two apart (a
    /// name written twice is refused).
    fn written(&self) -> [Option<String>; 2] {
        match &self.assembly {
            Some(a) => [Some(a.clone()), Some(format!("{a} second"))],
            None => [None, None],
        }
    }

    /// The sub-assemblies' names, as the JSON gives them.
    fn assemblies(&self) -> [String; 2] {
        if let [Some(a), Some(b)] = self.written() {
            return [a, b];
        }
        let base = match (&self.assembly, &self.sub_name) {
            (Some(a), _) => a.clone(),
            (None, Some(n)) => n.clone(),
            (None, None) => {
                let f = file_name(&self.sub_file, "sub");
                f[..f.len() - ".toml".len()].to_string()
            }
        };
        [base.clone(), format!("{base} #2")]
    }

    /// Every part's name, as the JSON gives them.
    fn part_names(&self) -> Vec<String> {
        let mut out = self.parts.clone();
        for a in self.assemblies() {
            out.extend(self.sub_parts.iter().map(|p| format!("{a} / {p}")));
        }
        out
    }
}

/// A raw control character (but newline and tab), a bidirectional mark
/// or another of `hidden`, in `text`.
fn raw_control(text: &str) -> Option<char> {
    text.chars()
        .find(|&c| hidden(c) && !matches!(c, '\n' | '\t'))
}

// A control, bidirectional mark, line or paragraph separator, U+FFFE or
// U+FFFF: the tests' own list (`channels::hidden`), not taken from
// `diag::is_hidden`, so that the test does not trust the rule it tests.
use crate::channels::hidden;

/// In JSON, a raw control character: any (tab too, which JSON escapes),
/// DEL and the C1 controls (which JSON allows raw but massprop escapes),
/// the bidirectional marks and line separators; but the line's end.
fn raw_json_control(text: &str) -> Option<char> {
    text.chars().find(|&c| hidden(c) && c != '\n')
}

/// The commands whose stdout is compared with the twin's, line for line.
fn named_commands(names: &Names, paths: &[PathBuf; 3], dir: &Path) -> Vec<Vec<String>> {
    let p = |i: usize| paths[i].to_str().unwrap().to_string();
    let s = |t: &str| t.to_string();
    vec![
        vec![s("report"), p(0)],
        vec![
            s("report"),
            p(0),
            s("--only"),
            names.assemblies()[1].clone(),
        ],
        vec![s("check"), p(0)],
        vec![s("check"), dir.to_str().unwrap().to_string()],
        vec![s("materials"), p(0)],
        vec![s("diff"), p(0), p(2)],
        vec![s("report"), s("--format"), s("json"), p(0)],
        vec![s("materials"), s("--format"), s("json"), p(0)],
        vec![s("check"), s("--format"), s("json"), p(0)],
        vec![s("diff"), s("--format"), s("json"), p(0), p(2)],
    ]
}

fn named_case(root: &Path, names: &Names) -> Result<bool, String> {
    let dir = root.join("hostile");
    let twin_dir = root.join("tame");
    let paths = names.write(&dir);
    let tame = names.tame();
    let twin_paths = tame.write(&twin_dir);
    let raw_paths: Vec<String> = paths
        .iter()
        .map(|p| p.to_str().unwrap().to_string())
        .collect();
    for (args, twin_args) in named_commands(names, &paths, &dir)
        .iter()
        .zip(named_commands(&tame, &twin_paths, &twin_dir))
    {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let twin_args: Vec<&str> = twin_args.iter().map(String::as_str).collect();
        let what = format!("{:?}", args);
        let out = exec(&args)?;
        let twin = exec(&twin_args)?;
        if out.status != twin.status || out.failed != twin.failed {
            return Err(format!(
                "{what}: status {} where the twin with plain names has {}:\n{}",
                out.status, twin.status, out.stderr
            ));
        }
        let raw = if args.contains(&"json") {
            raw_json_control(&out.stdout)
        } else {
            raw_control(&out.stdout)
        };
        if let Some(c) = raw {
            return Err(format!("{what}: stdout has a raw {c:?}:\n{}", out.stdout));
        }
        if let Some(c) = raw_control(&out.stderr) {
            return Err(format!("{what}: stderr has a raw {c:?}:\n{}", out.stderr));
        }
        let lines = |t: &str| t.lines().count();
        if lines(&out.stdout) != lines(&twin.stdout) {
            return Err(format!(
                "{what}: {} lines where the twin with plain names has {}:\n{}\n--- twin ---\n{}",
                lines(&out.stdout),
                lines(&twin.stdout),
                out.stdout,
                twin.stdout
            ));
        }
        if args.contains(&"json") && !out.stdout.is_empty() {
            let v: Value =
                serde_json::from_str(&out.stdout).map_err(|e| format!("{what}: not JSON ({e})"))?;
            walk(&v, "", "$").map_err(|e| format!("{what}: {e}"))?;
            json_names(names, &args, &v, &raw_paths).map_err(|e| format!("{what}: {e}"))?;
        }
    }
    Ok(true)
}

/// The JSON gives every name back exactly.
fn json_names(names: &Names, args: &[&str], v: &Value, paths: &[String]) -> Result<(), String> {
    let same = |what: &str, got: &Value, want: &str| {
        if got.as_str() == Some(want) {
            Ok(())
        } else {
            Err(format!("{what} is {got:?}, not {want:?}"))
        }
    };
    match args[0] {
        "report" => {
            same("name", &v["name"], &names.file)?;
            let want = names.part_names();
            let got = v["parts"].as_array().ok_or("no parts")?;
            if got.len() != want.len() {
                return Err(format!("{} parts, not {}", got.len(), want.len()));
            }
            for (g, w) in got.iter().zip(&want) {
                same("a part's name", &g["name"], w)?;
            }
            let asm = v["assemblies"].as_array().ok_or("no assemblies")?;
            if asm.len() != 2 {
                return Err(format!("{} sub-assemblies, not 2", asm.len()));
            }
            for (g, w) in asm.iter().zip(names.assemblies()) {
                same("a sub-assembly's path", &g["path"][0], &w)?;
            }
        }
        "materials" => {
            let list = v["materials"].as_array().ok_or("no materials")?;
            if !list
                .iter()
                .any(|m| m["name"].as_str() == Some(&names.material))
            {
                return Err(format!("no material named {:?}", names.material));
            }
        }
        "diff" => {
            same("the old file", &v["old"], &paths[0])?;
            same("the new file", &v["new"], &paths[2])?;
        }
        _ => same("the path", &v["files"][0]["path"], &paths[0])?,
    }
    Ok(())
}

#[test]
fn hostile_names_are_shown_escaped_and_come_back_exactly_in_json() {
    let root = crate::common::scratch("hostile", "names");
    property("hostile names", NAMED, names(), |n| {
        named_case(&root, n).map_err(|e| format!("{e}\n--- names ---\n{n:#?}"))
    });
}

/// Regression (issue 12, item 4): a diagnostic's location showed the file
/// name raw, so a part file named with an escape sequence or a newline
/// coloured the terminal or added a line to the error output (`check`
/// prints one per invalid file). The location is escaped as the message is
/// (`diag::visible`).
#[test]
fn a_file_name_with_control_characters_is_escaped_in_diagnostics() {
    let dir = crate::common::scratch("hostile", "diag-name");
    let path = dir.join("bad\u{1b}[31mname\n.toml");
    std::fs::write(&path, "x = [\n").unwrap();
    let out = exec(&["check", path.to_str().unwrap()]).unwrap();
    assert_eq!(out.status, 2);
    assert_eq!(raw_control(&out.stderr), None, "{:?}", out.stderr);
}

/// Regression (issue 12, item 4): `check --bless` reported each file as
/// `PATH: blessed` (or `unchanged`, `not blessed`) on stderr with the path
/// raw, so a file name with a newline added a line and an escape sequence
/// acted on the terminal. The path is escaped, as `check`'s stdout shows
/// it.
#[test]
fn check_bless_escapes_the_file_name_it_reports() {
    let dir = crate::common::scratch("hostile", "bless-name");
    let path = dir.join("b\u{1b}[31m\nx.toml");
    std::fs::write(
        &path,
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n\n[expect]\nmass = { value = 2, tol = 0.1 }\n",
    )
    .unwrap();
    let out = exec(&["check", "--bless", path.to_str().unwrap()]).unwrap();
    assert_eq!(out.status, 0, "{}", out.stderr);
    assert_eq!(raw_control(&out.stderr), None, "{:?}", out.stderr);
}

/// DEL and the C1 controls (U+0080..U+009F; U+009B is the one-character
/// CSI that starts an escape sequence) are valid raw in a JSON string, and
/// serde_json wrote them raw, for a terminal to act on (`report --format
/// json | less`). They are escaped (`\u009b`): the names still come back
/// exactly.
#[test]
fn json_escapes_del_and_c1_controls() {
    let dir = crate::common::scratch("hostile", "json-c1");
    let path = dir.join("a.toml");
    std::fs::write(
        &path,
        "[[part]]\nname = \"a\\u007Fb\u{9b}c\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let out = exec(&["report", "--format", "json", path.to_str().unwrap()]).unwrap();
    assert_eq!(raw_control(&out.stdout), None, "{}", out.stdout);
}

/// A bidi override in a name (U+202E, U+2066) is not a control character
/// (Unicode's Cc), and `diag::visible` passed it: it reverses how the rest
/// of the line reads on a terminal (`check`'s `PATH: ok`, a table row), as
/// in the "Trojan Source" attack. It is shown as U+FFFD, as C1 controls
/// are.
#[test]
fn bidi_overrides_in_names_are_shown_escaped() {
    let dir = crate::common::scratch("hostile", "bidi");
    let path = dir.join("a.toml");
    std::fs::write(
        &path,
        "[[part]]\nname = \"ok \\u202Edeliaf\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n\n[[part]]\nname = \"b\"\nshape = \"point\"\nmass = 1\ncenter = [1, 0, 0]\n",
    )
    .unwrap();
    let out = exec(&["report", path.to_str().unwrap()]).unwrap();
    assert!(!out.stdout.contains('\u{202e}'), "{}", out.stdout);
}

// ---------------------------------------------------------------------------
// [expect] one level too deep, or with nothing to compare

/// Entries that must be an error: (the TOML, how many lines it spans).
const DEEP_ENTRIES: &[&str] = &[
    "center_of_mass.x.y = { max = 1 }",
    "inertia_com.xx.zz = { max = 1 }",
    "inertia_ref.xy.x = { min = -1 }",
    "principal_moments.1.x = { min = 0 }",
    "radii_of_gyration.2.z = { min = 0 }",
    "angular_momentum.z.z = { max = 1 }",
    "mass.x = { min = 0 }",
    "Ixx.y = { max = 1 }",
    "kinetic_energy.x = { min = 0 }",
    "center_of_mass = { x = { y = { max = 1 } } }",
    "center_of_mass.x = { max = 1, y = { max = 2 } }",
    "center_of_mass.x = {}",
    "center_of_mass = {}",
    "mass = {}",
    "principal_moments.1 = {}",
    "center_of_mass.x = { tol = 1 }",
    "inertia_com.xx = { value = [1, 2, 3], tol = 1 }",
    "mass = { min = [1, 2, 3] }",
    "principal_moments.4 = { min = 0 }",
    "center_of_mass.w = { min = 0 }",
    "inertia_com = { xx = { zz = { max = 1 } } }",
];

/// Entries that are fine and pass or fail on their own.
const GOOD_ENTRIES: &[&str] = &[
    "mass = { min = 0 }",
    "mass = { value = 8, tol = \"1%\" }",
    "center_of_mass.z = { max = 100 }",
    "center_of_mass = { value = [0, 0, 0], tol = 1 }",
    "principal_moments.1 = { min = 0 }",
    "inertia_com.xy = { max = 1 }",
    "Ixx = { min = 0 }",
    "radii_of_gyration = { min = [0, 0, 0] }",
    "mass = { max = 1 }",
];

/// A valid body, then `[expect]` with good entries and at least one bad
/// one, in any order, or a bad one as a `[expect.…]` table. Returns the
/// text and the lines of the bad entries.
fn deep_file() -> impl Strategy<Value = (String, Vec<usize>)> {
    (
        prop::collection::vec(prop::sample::select(GOOD_ENTRIES), 0..=3),
        prop::collection::vec(prop::sample::select(DEEP_ENTRIES), 1..=2),
        any::<prop::sample::Index>(),
        0..4u8,
    )
        .prop_map(|(good, bad, at, table)| {
            let mut lines = vec![
                "[[part]]".to_string(),
                "shape = \"box\"".to_string(),
                "size = [1, 2, 3]".to_string(),
                "mass = 8".to_string(),
                "center = [0, 0, 0]".to_string(),
                String::new(),
                "[analysis]".to_string(),
                "omega = [0, 0, 1]".to_string(),
                String::new(),
                "[expect]".to_string(),
            ];
            // Keys may appear once: drop repeats (a duplicate key is an
            // error of its own kind).
            let key = |e: &str| e.split(['=', '.']).next().unwrap().trim().to_string();
            let mut seen = HashSet::new();
            let mut entries: Vec<(&str, bool)> = Vec::new();
            for e in bad
                .iter()
                .map(|e| (*e, true))
                .chain(good.iter().map(|e| (*e, false)))
            {
                if seen.insert(key(e.0)) {
                    entries.push(e);
                }
            }
            let first = entries.remove(0);
            entries.insert(at.index(entries.len() + 1), first);
            let mut bad_lines = Vec::new();
            for (e, is_bad) in &entries {
                if *is_bad {
                    bad_lines.push(lines.len() + 1);
                }
                lines.push(e.to_string());
            }
            // The first bad entry as a table of its own, when it is a
            // dotted key with an inline table (`[expect.a.b]` then `c =`).
            if table == 0
                && let Some((k, v)) = first.0.split_once(" = ")
                && k.contains('.')
                && v.len() > 4
                && v.starts_with("{ ")
                && v.ends_with(" }")
            {
                let inner = &v[2..v.len() - 2];
                if !inner.contains('{') && !inner.is_empty() {
                    let at = lines.iter().position(|l| l == first.0).unwrap();
                    lines.remove(at);
                    bad_lines.retain(|&l| l != at + 1);
                    bad_lines
                        .iter_mut()
                        .filter(|l| **l > at + 1)
                        .for_each(|l| *l -= 1);
                    lines.push(String::new());
                    bad_lines.push(lines.len() + 1);
                    lines.push(format!("[expect.{k}]"));
                    for pair in inner.split(", ") {
                        bad_lines.push(lines.len() + 1);
                        lines.push(pair.to_string());
                    }
                }
            }
            (lines.join("\n") + "\n", bad_lines)
        })
}

#[test]
fn expect_entries_too_deep_or_empty_are_located_errors_never_a_pass() {
    let dir = crate::common::scratch("hostile", "deep");
    let path = dir.join("deep.toml");
    let file = path.to_str().unwrap();
    property("deep expect", DEEP, deep_file(), |(text, bad)| {
        std::fs::write(&path, text).unwrap();
        let context = |e: String| format!("{e}\n--- input ---\n{text}");
        let check = exec(&["check", file]).map_err(context)?;
        if check.status != 2 {
            return Err(context(format!(
                "check: status {} for an entry with nothing to compare:\n{}",
                check.status, check.stdout
            )));
        }
        let line = check
            .stderr
            .lines()
            .next()
            .and_then(|_| error_line(&check.stderr));
        if !line.is_some_and(|l| bad.contains(&l)) {
            return Err(context(format!(
                "check: the error is not at a bad entry (lines {bad:?}):\n{}",
                check.stderr
            )));
        }
        let json = exec(&["check", "--format", "json", file]).map_err(context)?;
        let v: Value = serde_json::from_str(&json.stdout)
            .map_err(|e| context(format!("check --format json: not JSON ({e})")))?;
        if json.status != 2 || v["files"][0]["status"] != "invalid" {
            return Err(context(format!("check --format json: {}", json.stdout)));
        }
        let report = exec(&["report", file]).map_err(context)?;
        if !report.failed {
            return Err(context("report accepts the file".to_string()));
        }
        Ok(false)
    });
}

// ---------------------------------------------------------------------------
// Underflow, overflow and radii of gyration at the extremes

/// Ordinary values, most of a file's: the arithmetic is reached.
const PLAIN_VALUES: &[&str] = &["1", "2", "0.5", "3", "10"];

/// Valid masses and densities at the edges of f64: subnormals, the
/// smallest normal, values whose products with the sizes or distances
/// squared underflow or overflow.
const EDGE_MASSES: &[&str] = &[
    "1e-320",
    "5e-324",
    "2.2250738585072014e-308",
    "1e-300",
    "1e-200",
    "1e-160",
    "1e-100",
    "1e100",
    "1e160",
    "1e200",
    "1e300",
    "1e308",
    "1.7976931348623157e308",
];

/// Sizes from small to large (f64 keeps a size's square representable
/// only within about 1e±150).
const EDGE_SIZES: &[&str] = &["1e-140", "1e-100", "1e-50", "1e50", "1e100", "1e140"];

/// Values that underflow to zero or overflow as written, or in SI: errors.
const PAST_EDGE_VALUES: &[&str] = &["1e-400", "1e309", "\"1e-320 mg\"", "\"1e308 t\""];

fn edge(list: &'static [&'static str]) -> BoxedStrategy<&'static str> {
    prop_oneof![
        10 => prop::sample::select(PLAIN_VALUES),
        8 => prop::sample::select(list),
        1 => prop::sample::select(PAST_EDGE_VALUES),
    ]
    .boxed()
}

/// Positions: near, and far enough for I = m d² to overflow.
const EDGE_POSITIONS: &[&str] = &[
    "0", "1", "-1", "1e-300", "1e-160", "1e-100", "1e100", "1e150", "-1e150", "1e154", "1e160",
    "1e200", "1e300", "-1e300",
];

fn extreme_part() -> impl Strategy<Value = String> {
    (
        prop_oneof![3 => Just(0u8), 1 => 1..4u8],
        edge(EDGE_MASSES),
        prop::collection::vec(edge(EDGE_SIZES), 3),
        prop::collection::vec(
            prop_oneof![
                3 => prop::sample::select(vec!["0", "1", "-1", "2"]),
                1 => prop::sample::select(EDGE_POSITIONS),
            ],
            3,
        ),
    )
        .prop_map(|(shape, mass, size, c)| {
            let center = format!("[{}, {}, {}]", c[0], c[1], c[2]);
            match shape {
                0 => format!("shape = \"point\"\nmass = {mass}\ncenter = {center}"),
                1 => format!(
                    "shape = \"box\"\nmass = {mass}\nsize = [{}, {}, {}]\ncenter = {center}",
                    size[0], size[1], size[2]
                ),
                2 => format!(
                    "shape = \"sphere\"\ndensity = {mass}\nradius = {}\ncenter = {center}",
                    size[0]
                ),
                _ => format!(
                    "shape = \"rod\"\nlinear_density = {mass}\nlength = {}\ncenter = {center}",
                    size[1]
                ),
            }
        })
}

fn extreme_file() -> impl Strategy<Value = String> {
    (
        prop::collection::vec(extreme_part(), 1..=3),
        prop::option::weighted(0.3, prop::sample::select(vec!["mm", "km", "um"])),
        prop::option::weighted(0.3, prop::sample::select(vec!["g", "t", "mg"])),
    )
        .prop_map(|(parts, length, mass)| {
            let mut out = String::new();
            if length.is_some() || mass.is_some() {
                out.push_str(&format!(
                    "units = {{ length = \"{}\", mass = \"{}\" }}\n",
                    length.unwrap_or("m"),
                    mass.unwrap_or("kg")
                ));
            }
            for (k, p) in parts.iter().enumerate() {
                out.push_str(&format!("\n[[part]]\nname = \"p{k}\"\n{p}\n"));
            }
            out
        })
}

/// The cells of a table row (`│ a ┆ b │`).
fn cells(line: &str) -> Vec<&str> {
    line.trim()
        .trim_matches('│')
        .split('┆')
        .map(str::trim)
        .collect()
}

/// A number printed as zero (`0`, or `0 ± b`: zero to within its error
/// bound).
fn zero(cell: &str) -> bool {
    let value = cell.split(" ± ").next().unwrap_or(cell);
    value.parse::<f64>().is_ok_and(|x| x == 0.0)
}

/// A number the table shows as zero is zero in the JSON or within its
/// error bound (`error_bounds`) of zero — the table shows only the digits
/// a bound guarantees — and a number the JSON has as zero is shown as
/// zero; a radius of gyration is zero only with its moment.
fn zeros_agree(table: &str, json: &Value) -> Result<(), String> {
    let num = |v: &Value| v.as_f64().ok_or_else(|| format!("not a number: {v}"));
    let bounds = &json["error_bounds"];
    let agree = |what: &str, cell: &str, x: f64, bound: &Value| {
        let bound = num(bound)?;
        let ok = if zero(cell) {
            x.abs() <= bound
        } else {
            x != 0.0
        };
        if ok {
            Ok(())
        } else {
            Err(format!(
                "{what} is printed as {cell} where the JSON has {x:e} (bound {bound:e})"
            ))
        }
    };
    let moments = json["principal_moments"].as_array().ok_or("no moments")?;
    let radii = json["radii_of_gyration"].as_array().ok_or("no radii")?;
    for (k, (i, r)) in moments.iter().zip(radii).enumerate() {
        let (i, r) = (num(i)?, num(r)?);
        if (i > 0.0) != (r > 0.0) {
            return Err(format!(
                "principal moment {} is {i:e} but its radius of gyration {r:e}",
                k + 1
            ));
        }
    }
    for line in table.lines() {
        if let Some(rest) = line.strip_prefix("mass: ") {
            let cell = rest.split(' ').next().unwrap_or("");
            agree("the mass", cell, num(&json["mass"])?, &bounds["mass"])?;
        }
        let c = cells(line);
        if let Some(k) = ["I1", "I2", "I3"].iter().position(|n| c.first() == Some(n))
            && c.len() >= 3
        {
            let moment = &bounds["principal_moments"][k];
            agree("a principal moment", c[1], num(&moments[k])?, moment)?;
            let radius = &bounds["radii_of_gyration"][k];
            agree("a radius of gyration", c[2], num(&radii[k])?, radius)?;
        }
        if c.first() == Some(&"centre of mass") && c.len() >= 4 {
            for (axis, cell) in c[1..4].iter().enumerate() {
                agree(
                    "the centre of mass",
                    cell,
                    num(&json["center_of_mass"][axis])?,
                    &bounds["center_of_mass"][axis],
                )?;
            }
        }
    }
    Ok(())
}

#[test]
fn extreme_values_print_no_inf_and_zero_only_for_zero() {
    let dir = crate::common::scratch("hostile", "extremes");
    let path = dir.join("extreme.toml");
    let file = path.to_str().unwrap();
    property("extremes", EXTREMES, extreme_file(), |text| {
        std::fs::write(&path, text).unwrap();
        let context = |e: String| format!("{e}\n--- input ---\n{text}");
        let computed = hostile(file).map_err(context)?;
        if !computed {
            return Ok(false);
        }
        let json = exec(&["report", "--format", "json", file]).map_err(context)?;
        let table = exec(&["report", "--full", file]).map_err(context)?;
        let v: Value = serde_json::from_str(&json.stdout).unwrap();
        zeros_agree(&table.stdout, &v).map_err(|e| context(format!("{e}\n{}", table.stdout)))?;
        let ideal = exec(&["check", file]).map_err(context)?;
        if ideal.status != 0 {
            return Err(context(format!("check: status {}", ideal.status)));
        }
        Ok(true)
    });
}
