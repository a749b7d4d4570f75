//! Docs that run (issue 31): every ```toml block and every `$ massprop …`
//! line in README.md and docs/*.md is checked here, so no example can rot.
//!
//! A TOML block is read as a whole part file by massprop (`report --format
//! json`, status 0), or, marked a fragment, parsed as plain TOML. A
//! `$ massprop …` line in a ```console, ```sh, ```bash, ```text or bare ``` block
//! runs in its document's scratch directory (the repository's `shapes`,
//! `tests`, `docs`, `examples` visible, the document's saved files there),
//! must exit 0, and the lines after it, if any, are its output (stdout,
//! then stderr), trycmd-like: a line `...` (or `…`) stands for any number
//! of lines, `[..]` for any text within a line.
//! A pipe into another program (`| jq …`, `| python3 …`) runs through `sh`
//! when that program exists, and is skipped, saying so, when it does not.
//!
//! Markers: an HTML comment on the line right before a block's fence,
//! `<!-- docs-test: WORD … -->`, with the words
//! - `fragment`: not a whole part file (it must parse as TOML, and must
//!   not read as a whole part file, so the marker stays true);
//! - `file=NAME`: the block is saved as NAME in the scratch directory, for
//!   the commands after it in the same document;
//! - `copy=PATH`: the repository's file or directory PATH is copied into
//!   the scratch directory (under its own name) before the block;
//! - `status=N`: the block's commands exit with N;
//! - `skip REASON…`: not run, for the reason given (a reason is required).
//!
//! `MASSPROP_DOCS_OVERWRITE=1 cargo test --test integration docs_run`
//! rewrites each shown output that differs with the program's own, in
//! place (as `TRYCMD=overwrite` does), for review in the diff.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The repository's directories a document's commands may name.
const VISIBLE: [&str; 4] = ["shapes", "tests", "docs", "examples"];

/// What a marker asks of its block.
#[derive(Debug, Default, PartialEq, Clone)]
struct Marker {
    fragment: bool,
    file: Option<String>,
    copies: Vec<String>,
    status: Option<i32>,
    skip: Option<String>,
}

/// Reads `<!-- docs-test: … -->`; `Err` names what is wrong with it.
fn parse_marker(line: &str) -> Result<Option<Marker>, String> {
    let line = line.trim();
    let Some(rest) = line.strip_prefix("<!-- docs-test:") else {
        return Ok(None);
    };
    let body = rest
        .strip_suffix("-->")
        .ok_or("a docs-test marker must end on its line with `-->`")?;
    let mut marker = Marker::default();
    let mut words = body.split_whitespace();
    while let Some(word) = words.next() {
        if word == "skip" {
            let reason: Vec<&str> = words.by_ref().collect();
            if reason.is_empty() {
                return Err("`skip` must give its reason: `skip REASON`".into());
            }
            marker.skip = Some(reason.join(" "));
        } else if word == "fragment" {
            marker.fragment = true;
        } else if let Some(name) = word.strip_prefix("file=") {
            if name.is_empty() || name.contains("..") || name.starts_with('/') {
                return Err(format!("`{word}`: a plain name in the scratch directory"));
            }
            marker.file = Some(name.to_string());
        } else if let Some(path) = word.strip_prefix("copy=") {
            marker.copies.push(path.to_string());
        } else if let Some(n) = word.strip_prefix("status=") {
            marker.status = Some(n.parse().map_err(|_| format!("`{word}`: not a number"))?);
        } else {
            return Err(format!(
                "unknown docs-test word `{word}` (fragment, file=NAME, copy=PATH, status=N, skip REASON)"
            ));
        }
    }
    Ok(Some(marker))
}

/// One fenced block: where its body starts (0-based line), its info
/// string, indentation and lines (indentation removed).
struct Block {
    first: usize,
    info: String,
    indent: usize,
    lines: Vec<String>,
    marker: Result<Option<Marker>, String>,
}

fn blocks(text: &str) -> Result<Vec<Block>, String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let trimmed = lines[i].trim_start();
        let Some(info) = trimmed.strip_prefix("```") else {
            let next = lines.get(i + 1).map_or("", |n| n.trim_start());
            if trimmed.starts_with("<!-- docs-test:") && !next.starts_with("```") {
                return Err(format!("line {}: a marker not right before a fence", i + 1));
            }
            i += 1;
            continue;
        };
        let indent = lines[i].len() - trimmed.len();
        let marker = i
            .checked_sub(1)
            .map_or(Ok(None), |p| parse_marker(lines[p]));
        let open = i;
        let mut body = Vec::new();
        i += 1;
        while i < lines.len() && lines[i].trim() != "```" {
            let l = lines[i];
            let cut = l.len() - l.trim_start().len();
            body.push(l[cut.min(indent)..].to_string());
            i += 1;
        }
        if i == lines.len() {
            return Err(format!("line {}: a fence that is never closed", open + 1));
        }
        out.push(Block {
            first: open + 1,
            info: info.trim().to_string(),
            indent,
            lines: body,
            marker,
        });
        i += 1;
    }
    Ok(out)
}

/// Does `line` match `pattern`, where `[..]` stands for any text?
fn line_matches(pattern: &str, line: &str) -> bool {
    let pieces: Vec<&str> = pattern.split("[..]").collect();
    if pieces.len() == 1 {
        return pattern == line;
    }
    let (first, last) = (pieces[0], pieces[pieces.len() - 1]);
    if !line.starts_with(first) || line.len() < first.len() + last.len() || !line.ends_with(last) {
        return false;
    }
    let mut rest = &line[first.len()..line.len() - last.len()];
    for piece in &pieces[1..pieces.len() - 1] {
        match rest.find(piece) {
            Some(at) => rest = &rest[at + piece.len()..],
            None => return false,
        }
    }
    true
}

fn is_elision(line: &str) -> bool {
    matches!(line.trim(), "..." | "…")
}

/// Does the shown output match the actual, with `...` lines for any
/// number of lines?
fn output_matches(shown: &[&str], actual: &[&str]) -> bool {
    match shown.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if is_elision(e) => {
            (0..=actual.len()).any(|skip| output_matches(rest, &actual[skip..]))
        }
        Some((e, rest)) => match actual.split_first() {
            Some((a, more)) => {
                line_matches(e.trim_end(), a.trim_end()) && output_matches(rest, more)
            }
            None => false,
        },
    }
}

/// A command line's words, as `sh` would split them (quotes, a `#`
/// comment), with a `*` in an unquoted word expanded in its last
/// component; then the file of a `> FILE` redirection, and the raw text of
/// what follows the first `|`. `Err` for shell syntax the test does not
/// run (which then needs a `skip` marker).
type Parsed = (Vec<String>, Option<String>, Option<String>);

fn split_command(line: &str, cwd: &Path) -> Result<Parsed, String> {
    let mut words: Vec<(String, bool)> = Vec::new();
    let (mut word, mut glob, mut in_word) = (String::new(), false, false);
    let mut chars = line.char_indices().peekable();
    let mut pipe = None;
    while let Some((at, c)) = chars.next() {
        match c {
            '\'' => {
                in_word = true;
                for (_, q) in chars.by_ref() {
                    if q == '\'' {
                        break;
                    }
                    word.push(q);
                }
            }
            '"' => {
                in_word = true;
                while let Some((_, q)) = chars.next() {
                    match q {
                        '"' => break,
                        '\\' => word.extend(chars.next().map(|(_, e)| e)),
                        '$' | '`' => return Err("a substitution in double quotes".into()),
                        _ => word.push(q),
                    }
                }
            }
            '#' if !in_word => break,
            '|' => {
                pipe = Some(line[at + 1..].trim().to_string());
                break;
            }
            ';' | '&' | '<' | '(' | ')' | '$' | '`' | '\\' | '~' | '?' | '[' | '{' => {
                return Err(format!("shell syntax `{c}`"));
            }
            c if c.is_whitespace() => {
                if in_word {
                    words.push((std::mem::take(&mut word), glob));
                }
                (in_word, glob) = (false, false);
            }
            '*' => {
                (in_word, glob) = (true, true);
                word.push(c);
            }
            c => {
                in_word = true;
                word.push(c);
            }
        }
    }
    if in_word {
        words.push((word, glob));
    }
    let mut redirect = None;
    if let Some(at) = words.iter().position(|(w, _)| w == ">") {
        let file = words.get(at + 1).map(|(w, _)| w.clone());
        let file = file.ok_or("`>` without a file")?;
        if at + 2 != words.len() || file.starts_with('/') || file.contains("..") {
            return Err("a redirection other than `> FILE` in the scratch directory".into());
        }
        redirect = Some(file);
        words.truncate(at);
    }
    let mut out = Vec::new();
    for (w, glob) in words {
        if w.contains('>') {
            return Err(format!("redirection `{w}`"));
        }
        if !glob {
            out.push(w);
            continue;
        }
        let (dir, pattern) = w.rsplit_once('/').unwrap_or((".", &w));
        let (head, tail) = pattern.split_once('*').ok_or("")?;
        let mut found: Vec<String> = std::fs::read_dir(cwd.join(dir))
            .map_err(|e| format!("`{w}`: {e}"))?
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .filter(|n| n.starts_with(head) && n.ends_with(tail) && n.len() >= pattern.len() - 1)
            .map(|n| if dir == "." { n } else { format!("{dir}/{n}") })
            .collect();
        found.sort();
        if found.is_empty() {
            return Err(format!("`{w}` matches no file"));
        }
        out.extend(found);
    }
    Ok((out, redirect, pipe))
}

/// Is `program` on PATH (as `sh` would find it)?
fn on_path(program: &str) -> bool {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path).any(|dir| dir.join(program).is_file())
}

fn copy_into(from: &Path, to: &Path) -> std::io::Result<()> {
    if from.is_dir() {
        std::fs::create_dir_all(to)?;
        for entry in std::fs::read_dir(from)? {
            let entry = entry?;
            copy_into(&entry.path(), &to.join(entry.file_name()))?;
        }
        Ok(())
    } else {
        std::fs::copy(from, to).map(|_| ())
    }
}

/// The scratch directory of one document: outside the repository (so no
/// `.gitignore` of it applies to `check DIR`), the repository's example
/// directories visible in it.
fn scratch_for(repo: &Path) -> tempfile::TempDir {
    let dir = tempfile::Builder::new()
        .prefix("massprop-docs-")
        .tempdir()
        .unwrap();
    for name in VISIBLE {
        let (from, to) = (repo.join(name), dir.path().join(name));
        #[cfg(unix)]
        std::os::unix::fs::symlink(&from, &to).unwrap();
        #[cfg(not(unix))]
        copy_into(&from, &to).unwrap();
    }
    dir
}

/// What running one document found.
#[derive(Default)]
struct Outcome {
    failures: Vec<String>,
    skipped: Vec<String>,
    /// The document with its differing shown outputs rewritten (overwrite).
    rewritten: Option<String>,
    /// Commands run and TOML blocks read.
    checked: usize,
}

fn massprop_in(dir: &Path) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_massprop"));
    cmd.current_dir(dir)
        .env_remove("CLICOLOR_FORCE")
        .env_remove("NO_COLOR")
        .stdin(Stdio::null());
    cmd
}

/// Runs every example of the document `label` (its text `text`), with
/// paths relative to `repo`; with `overwrite`, differing shown outputs
/// are replaced by the actual ones.
fn run_doc(label: &str, text: &str, repo: &Path, overwrite: bool) -> Outcome {
    let mut out = Outcome::default();
    let blocks = match blocks(text) {
        Ok(b) => b,
        Err(e) => {
            out.failures.push(format!("{label}: {e}"));
            return out;
        }
    };
    let scratch = scratch_for(repo);
    let dir = scratch.path();
    // (first line, end line, new lines), 0-based, end exclusive.
    let mut edits: Vec<(usize, usize, Vec<String>)> = Vec::new();
    for block in &blocks {
        let at = format!("{label}:{}", block.first);
        let marker = match &block.marker {
            Ok(m) => m.clone().unwrap_or_default(),
            Err(e) => {
                out.failures
                    .push(format!("{label}:{}: {e}", block.first - 1));
                continue;
            }
        };
        let body = block.lines.join("\n") + "\n";
        let commands = matches!(block.info.as_str(), "console" | "sh" | "bash" | "text" | "")
            && block.lines.iter().any(|l| l.starts_with("$ "));
        if let Some(reason) = &marker.skip {
            out.skipped.push(format!("{at}: {reason}"));
            continue;
        }
        for path in &marker.copies {
            let from = repo.join(path);
            let name = from
                .file_name()
                .expect("a copy= path names a file or directory");
            if let Err(e) = copy_into(&from, &dir.join(name)) {
                out.failures.push(format!("{at}: copy={path}: {e}"));
            }
        }
        if commands {
            run_commands(block, &at, &marker, dir, overwrite, &mut out, &mut edits);
            continue;
        }
        if let Some(name) = &marker.file {
            std::fs::write(dir.join(name), &body).unwrap();
        }
        if block.info != "toml" {
            continue;
        }
        out.checked += 1;
        if let Err(e) = body.parse::<toml::Table>() {
            out.failures.push(format!("{at}: not valid TOML: {e}"));
            continue;
        }
        let name = marker
            .file
            .clone()
            .unwrap_or_else(|| format!("block-{}.toml", block.first));
        if marker.file.is_none() {
            std::fs::write(dir.join(&name), &body).unwrap();
        }
        let run = massprop_in(dir)
            .args(["report", &name, "--format", "json"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        let reads = run.status.success()
            && serde_json::from_slice::<serde_json::Value>(&run.stdout).is_ok();
        match (marker.fragment, reads) {
            (false, false) => out.failures.push(format!(
                "{at}: not a whole part file (`massprop report` says: {}); \
                 if it is a fragment, mark it `<!-- docs-test: fragment -->`",
                stderr.trim()
            )),
            (true, true) => out.failures.push(format!(
                "{at}: marked `fragment` but reads as a whole part file: drop the marker"
            )),
            (false, true) | (true, false) => {}
        }
    }
    if overwrite && !edits.is_empty() {
        let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
        edits.sort_by_key(|e| std::cmp::Reverse(e.0));
        for (first, end, new) in edits {
            lines.splice(first..end, new);
        }
        out.rewritten = Some(lines.join("\n") + "\n");
    }
    out
}

/// Runs a block's `$ massprop …` lines in `dir`, comparing shown output.
fn run_commands(
    block: &Block,
    at: &str,
    marker: &Marker,
    dir: &Path,
    overwrite: bool,
    out: &mut Outcome,
    edits: &mut Vec<(usize, usize, Vec<String>)>,
) {
    let starts: Vec<usize> = (0..block.lines.len())
        .filter(|&i| block.lines[i].starts_with("$ "))
        .collect();
    let others: Vec<&str> = starts
        .iter()
        .map(|&i| &block.lines[i][2..])
        .filter(|c| !c.starts_with("massprop "))
        .collect();
    if others.len() == starts.len() {
        return; // No massprop line: cargo, git, a bench script.
    }
    if !others.is_empty() {
        out.failures.push(format!(
            "{at}: `{}` is not a massprop command: mark the block \
             `<!-- docs-test: skip REASON -->` if it needs set-up the test cannot do",
            others[0]
        ));
        return;
    }
    if let Some(stray) = block.lines[..starts[0]]
        .iter()
        .find(|l| !l.trim().is_empty())
    {
        out.failures
            .push(format!("{at}: `{stray}` before the first `$` line"));
    }
    for (k, &i) in starts.iter().enumerate() {
        let end = starts.get(k + 1).copied().unwrap_or(block.lines.len());
        let line_no = block.first + 1 + i;
        let here = format!("{}:{line_no}", at.rsplit_once(':').unwrap().0);
        let command = &block.lines[i][2..];
        let shown: Vec<&str> = block.lines[i + 1..end].iter().map(String::as_str).collect();
        let (words, redirect, pipe) = match split_command(command, dir) {
            Ok(p) => p,
            Err(e) => {
                out.failures.push(format!(
                    "{here}: `{command}`: {e}: the test runs `massprop …` with quotes, `*`, \
                     `> FILE` and one `| PROGRAM …`; mark the block `skip REASON` otherwise"
                ));
                continue;
            }
        };
        let program = pipe
            .as_ref()
            .map(|p| p.split_whitespace().next().unwrap_or(""));
        if let Some(program) = program.filter(|p| !on_path("sh") || !on_path(p)) {
            out.skipped
                .push(format!("{here}: `{program}` is not installed"));
            continue;
        }
        out.checked += 1;
        let run = massprop_in(dir).args(&words[1..]).output().unwrap();
        let want = marker.status.unwrap_or(0);
        let mut failed = Vec::new();
        if run.status.code() != Some(want) {
            failed.push(format!("exit status {:?}, not {want}", run.status.code()));
        }
        let mut actual = String::new();
        if let Some(file) = &redirect {
            std::fs::write(dir.join(file), &run.stdout).unwrap();
        } else if let Some(script) = &pipe {
            let mut child = Command::new("sh")
                .args(["-c", script])
                .current_dir(dir)
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap();
            use std::io::Write;
            let _ = child.stdin.take().unwrap().write_all(&run.stdout);
            let piped = child.wait_with_output().unwrap();
            if !piped.status.success() {
                failed.push(format!("`{script}` exited with {:?}", piped.status.code()));
            }
            actual.push_str(&String::from_utf8_lossy(&piped.stdout));
            actual.push_str(&String::from_utf8_lossy(&piped.stderr));
        } else {
            actual.push_str(&String::from_utf8_lossy(&run.stdout));
        }
        actual.push_str(&String::from_utf8_lossy(&run.stderr));
        let actual_lines: Vec<&str> = actual.lines().collect();
        let differs = !shown.is_empty() && !output_matches(&shown, &actual_lines);
        if differs && overwrite {
            // NOTE: an excerpt (shown lines, then an elision) stays one:
            // as many of the new lines, then the same elision.
            let tail = shown
                .last()
                .filter(|l| is_elision(l) && shown.len() < actual_lines.len());
            let head = &actual_lines[..tail.map_or(actual_lines.len(), |_| shown.len() - 1)];
            let indent = " ".repeat(block.indent);
            let new = head
                .iter()
                .chain(tail)
                .map(|l| format!("{indent}{l}").trim_end().to_string());
            edits.push((line_no, block.first + end, new.collect()));
        } else if differs {
            failed.push(format!(
                "its output differs from the shown one; it is:\n{actual}\
                 (MASSPROP_DOCS_OVERWRITE=1 rewrites it in place)"
            ));
        }
        if !failed.is_empty() {
            out.failures
                .push(format!("{here}: `{command}`: {}", failed.join("; ")));
        }
    }
}

/// README.md and every docs/*.md, sorted.
fn documents(repo: &Path) -> Vec<PathBuf> {
    let mut docs: Vec<PathBuf> = std::fs::read_dir(repo.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    docs.insert(0, repo.join("README.md"));
    docs
}

#[test]
fn every_toml_block_and_massprop_command_in_the_readme_and_docs_runs_as_shown() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    let overwrite = std::env::var_os("MASSPROP_DOCS_OVERWRITE").is_some_and(|v| v == "1");
    let (mut failures, mut checked) = (Vec::new(), 0);
    for path in documents(repo) {
        let label = path
            .strip_prefix(repo)
            .unwrap()
            .to_string_lossy()
            .into_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        let outcome = run_doc(&label, &text, repo, overwrite);
        for skipped in &outcome.skipped {
            eprintln!("docs_run: not run: {skipped}");
        }
        if let Some(new) = outcome.rewritten {
            std::fs::write(&path, new).unwrap();
            eprintln!("docs_run: rewrote shown outputs in {label}");
        }
        checked += outcome.checked;
        failures.extend(outcome.failures);
    }
    assert!(
        failures.is_empty(),
        "{} failing examples:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(checked >= 40, "only {checked} examples checked");
}

/// Runs `text` as the document `label` and returns its failures.
fn failures_of(label: &str, text: &str) -> Vec<String> {
    run_doc(label, text, Path::new(env!("CARGO_MANIFEST_DIR")), false).failures
}

/// The one failure of the document `doc.md` whose text is `text`.
fn the_failure(text: &str) -> String {
    let failures = failures_of("doc.md", text);
    assert_eq!(failures.len(), 1, "{failures:?}");
    failures.into_iter().next().unwrap()
}

#[test]
fn an_unmarked_toml_block_that_is_not_a_part_file_fails_with_its_file_and_line() {
    let doc = "# t\n\n```toml\n[expect]\nmass = { max = 2 }\n```\n";
    let f = the_failure(doc);
    assert!(f.starts_with("doc.md:3: not a whole part file"), "{f}");
}

#[test]
fn invalid_toml_fails_even_when_marked_a_fragment() {
    // docs/check.md's old first example: an inline table extended by a
    // dotted key.
    let doc = "<!-- docs-test: fragment -->\n```toml\n[expect]\n\
               c = { value = [1, 2, 3], tol = 0.5 }\nc.z = { max = 4 }\n```\n";
    let f = the_failure(doc);
    assert!(f.starts_with("doc.md:2: not valid TOML"), "{f}");
}

#[test]
fn a_fragment_marker_on_a_whole_part_file_fails() {
    let doc = "<!-- docs-test: fragment -->\n```toml\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n```\n";
    let f = the_failure(doc);
    assert!(f.contains("drop the marker"), "{f}");
}

#[test]
fn a_command_whose_output_changed_fails_with_its_line() {
    let doc = "text\n\n```console\n$ massprop check shapes/bent-plate.toml\n\
               shapes/bent-plate.toml: failed\n```\n";
    let f = the_failure(doc);
    assert!(f.starts_with("doc.md:4: `massprop check"), "{f}");
    assert!(f.contains("shapes/bent-plate.toml: ok"), "{f}");
}

#[test]
fn a_command_that_exits_otherwise_than_its_marker_says_fails() {
    let doc =
        "<!-- docs-test: status=1 -->\n```console\n$ massprop check shapes/bent-plate.toml\n```\n";
    let f = the_failure(doc);
    assert!(f.contains("exit status Some(0), not 1"), "{f}");
}

#[test]
fn a_saved_file_is_there_for_the_commands_after_it() {
    let doc = "<!-- docs-test: file=one.toml -->\n```toml\n[[part]]\nshape = \"point\"\n\
               mass = 2\ncenter = [0, 0, 0]\n```\n\n```console\n$ massprop check one.toml\none.toml: ok\n...\n```\n";
    assert_eq!(failures_of("doc.md", doc), Vec::<String>::new());
}

#[test]
fn a_skip_without_a_reason_and_an_unknown_marker_word_are_refused() {
    assert!(parse_marker("<!-- docs-test: skip -->").is_err());
    assert!(parse_marker("<!-- docs-test: fragmnet -->").is_err());
    let skip = parse_marker("<!-- docs-test: skip needs a robot -->")
        .unwrap()
        .unwrap();
    assert_eq!(skip.skip.as_deref(), Some("needs a robot"));
}

#[test]
fn shell_syntax_the_test_cannot_run_needs_a_skip_marker() {
    let doc = "```console\n$ massprop report <(cat shapes/bent-plate.toml)\n```\n";
    let f = the_failure(doc);
    assert!(f.contains("mark the block `skip REASON`"), "{f}");
}

#[test]
fn elisions_stand_for_lines_and_for_text_within_a_line() {
    let actual = ["a", "b", "c", "mass: 5.26 kg", "d"];
    assert!(output_matches(&["a", "...", "mass: [..] kg", "…"], &actual));
    assert!(output_matches(&["...", "d"], &actual));
    assert!(!output_matches(
        &["a", "...", "mass: 5.27 kg", "..."],
        &actual
    ));
    assert!(!output_matches(&["a", "b"], &actual));
}

#[test]
fn the_readme_links_the_quickstart_before_any_other_document() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let first = readme.find("](").expect("README.md has a link");
    assert!(
        readme[first..].starts_with("](docs/quickstart.md)"),
        "first link: {}",
        &readme[first..first + 40]
    );
    assert!(
        readme[..first].lines().count() <= 10,
        "the quickstart link is not near the top"
    );
}

/// docs/quickstart.md shows shapes/quickstart.toml whole, so the page and
/// the example the README's commands use cannot drift apart.
#[test]
fn the_quickstart_page_shows_the_quickstart_part_file_as_it_is() {
    let page = std::fs::read_to_string("docs/quickstart.md").unwrap();
    let file = std::fs::read_to_string("shapes/quickstart.toml").unwrap();
    let block = blocks(&page)
        .unwrap()
        .into_iter()
        .find(|b| b.info == "toml")
        .unwrap();
    assert_eq!(block.lines.join("\n") + "\n", file);
}

/// A number at the start of a quantity string (`"5.26 kg"`) or a plain
/// number, and whether a tolerance is relative (`"0.01 %"`).
fn number(v: &toml::Value) -> (f64, bool) {
    let s = v.as_str().map_or_else(|| v.to_string(), str::to_string);
    let n = s.split_whitespace().next().unwrap().trim_end_matches('%');
    (n.parse().expect("a number"), s.ends_with('%'))
}

/// Within its own tolerance of `exact`: the `[expect]` entry `key`.
fn holds(expect: &toml::Table, key: &str, exact: &[f64]) {
    let entry = expect[key].as_table().unwrap();
    let values: Vec<f64> = match &entry["value"] {
        toml::Value::Array(a) => a.iter().map(|v| number(v).0).collect(),
        v => vec![number(v).0],
    };
    let (tol, relative) = number(&entry["tol"]);
    assert_eq!(values.len(), exact.len(), "{key}");
    for (v, x) in values.iter().zip(exact) {
        let allowed = if relative { tol / 100.0 * v.abs() } else { tol };
        assert!(
            (v - x).abs() <= allowed,
            "{key}: {v} is not {x} within {allowed}"
        );
    }
}

/// The quickstart's `[expect]` is the body's, by the textbook forms (box
/// m(a² + b²)/12, tube m(R² + r²)/2 about its axis, solid sphere 2/5 m R²,
/// slender rod m L²/12 about its middle, parallel axes), in mm and kg:
/// derived here, not read from massprop.
#[test]
fn the_quickstart_expectations_are_the_closed_form_values() {
    let base = 2700.0 * 0.2 * 0.2 * 0.02; // aluminium-6061, kg
    let parts = [
        // (mass, centroid x, centroid z, own Izz about its centroid)
        (base, 0.0, 10.0, base * (200.0_f64.powi(2) * 2.0) / 12.0),
        (
            0.9,
            0.0,
            320.0,
            0.9 * (15.0_f64.powi(2) + 12.0_f64.powi(2)) / 2.0,
        ),
        (1.2, 0.0, 670.0, 0.4 * 1.2 * 50.0_f64.powi(2)),
        (0.4, 75.0, 600.0, 0.4 * 150.0_f64.powi(2) / 12.0),
        (0.6, -50.0, 30.0, 0.0),
    ];
    let m: f64 = parts.iter().map(|p| p.0).sum();
    let x = parts.iter().map(|p| p.0 * p.1).sum::<f64>() / m;
    let z = parts.iter().map(|p| p.0 * p.2).sum::<f64>() / m;
    // Every centroid lies on y = 0: Izz about the centre of mass is each
    // part's own plus m (x − x̄)².
    let izz: f64 = parts.iter().map(|p| p.3 + p.0 * (p.1 - x).powi(2)).sum();
    assert!((base - 2.16).abs() < 1e-12 && x.abs() < 1e-12, "{base} {x}");
    let file: toml::Table = std::fs::read_to_string("shapes/quickstart.toml")
        .unwrap()
        .parse()
        .unwrap();
    let expect = file["expect"].as_table().unwrap();
    holds(expect, "mass", &[m]);
    holds(expect, "center_of_mass", &[x, 0.0, z]);
    holds(expect, "Izz", &[izz]);
    assert_eq!(expect.len(), 3, "a new entry needs its derivation here");
}

/// docs/check.md's first example is the bent plate's: in place of the
/// bent plate's own `[expect]`, it passes `check`.
#[test]
fn the_check_guide_s_first_example_holds_for_the_bent_plate() {
    let guide = std::fs::read_to_string("docs/check.md").unwrap();
    let example = blocks(&guide)
        .unwrap()
        .into_iter()
        .find(|b| b.info == "toml")
        .unwrap();
    let plate = std::fs::read_to_string("shapes/bent-plate.toml").unwrap();
    let body = &plate[..plate
        .find("\n[expect]\n")
        .expect("the bent plate has [expect]")];
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("plate.toml"),
        format!("{body}\n{}\n", example.lines.join("\n")),
    )
    .unwrap();
    let run = massprop_in(dir.path())
        .args(["check", "plate.toml"])
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stdout)
    );
}
