//! Fuzz the part-file parser, includes, the composer and the checker: any
//! set of files either is rejected with a diagnostic or gives a summary
//! whose JSON is finite and valid, whose table renders, and whose
//! `[expect]` messages print no non-finite number; an include never reads,
//! or quotes, a file outside the part file's directory; and wherever the
//! reader (`model::fast::parse`) reads a file, the reference parser reads
//! it too, every value at its place (`fast::reference::agrees`); where the
//! reader refuses a file, reading it gives an error with a place.
//! Every channel is escaped (issue 28): a diagnostic, as standard error
//! shows it, and the report's table have no raw control, bidirectional,
//! separator or noncharacter (U+FFFE, U+FFFF) character but tab and the
//! newlines massprop writes, and no line that begins (blanks aside) with
//! `::`, which a CI runner reads as a command; a diagnostic's lines are its
//! own (`PLACE: error: …`, the gutter, `= help:`, `= note:`).
//! Panics, hangs and out-of-memory are the findings.
//!
//! The input is one or more files: the text up to the first line that
//! starts with `#---- ` is the top-level part file `top.toml`; each such
//! line starts another file, named by the rest of the line (`#---- a.toml`,
//! `#---- sub/b.toml`). The files are written into a fresh directory for
//! each input (the loader reads includes from disk), and `top.toml` is
//! loaded from there, so `include = "a.toml"` finds `a.toml`. An input
//! without a separator line is one part file, as before includes were
//! fuzzed. Beside that directory lies `secret.toml`, a valid part file whose
//! name and comment hold a marker: an include may not reach it
//! (`include = "../secret.toml"`), so the marker may never appear in any
//! output.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::Settings;
use massprop::analysis::check;
use massprop::analysis::summary::Accuracy;
use massprop::compose::Precision;
use massprop::model::fast;
use massprop::output;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The line that starts another file.
const SEPARATOR: &str = "#---- ";
/// At most this many files per input (more only slows each run).
const MAX_FILES: usize = 16;
/// In `secret.toml`, outside the files' directory: never in any output.
const MARKER: &str = "FUZZ-SECRET-8c1e";

/// This process's scratch directory (`$TMPDIR/massprop-fuzz-PID`), with
/// `secret.toml` in it; each input's files go in its `run/`.
fn scratch() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("massprop-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("the fuzz scratch directory can be made");
        let secret = format!(
            "# {MARKER}\nname = \"{MARKER}\"\n[[part]]\nname = \"{MARKER}\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n"
        );
        std::fs::write(dir.join("secret.toml"), secret).expect("secret.toml can be written");
        dir
    })
}

/// Where includes may come from: the run directory and the working
/// directory (canonical).
fn roots() -> &'static [PathBuf] {
    static ROOTS: OnceLock<Vec<PathBuf>> = OnceLock::new();
    ROOTS.get_or_init(|| {
        let run = scratch().join("run");
        std::fs::create_dir_all(&run).expect("the run directory can be made");
        [run, PathBuf::from(".")]
            .iter()
            .map(|p| p.canonicalize().expect("the roots exist"))
            .collect()
    })
}

/// A file name from a separator line, kept inside the run directory: at
/// most three plain components (letters, digits, `.`, `-`, `_`; no `..`),
/// else `fN.toml`.
fn file_name(line: &str, n: usize) -> String {
    let name = line.trim_end_matches(['\r', ' ']);
    let plain = |c: &str| {
        !c.is_empty()
            && c != "."
            && c != ".."
            && c.len() <= 32
            && c.bytes()
                .all(|b| b.is_ascii_alphanumeric() || b"._-".contains(&b))
    };
    let parts: Vec<&str> = name.split('/').collect();
    if parts.len() <= 3 && parts.iter().all(|c| plain(c)) && name != "top.toml" {
        name.to_string()
    } else {
        format!("f{n}.toml")
    }
}

/// The input's files: (name, text), `top.toml` first.
fn split(text: &str) -> Vec<(String, &str)> {
    let mut files = Vec::new();
    let mut name = "top.toml".to_string();
    let mut start = 0;
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        if let Some(rest) = line.strip_prefix(SEPARATOR)
            && files.len() + 1 < MAX_FILES
        {
            files.push((name, &text[start..at]));
            name = file_name(rest.trim_end_matches('\n'), files.len());
            start = at + line.len();
        }
        at += line.len();
    }
    files.push((name, &text[start..]));
    files
}

/// Write the files into a fresh `run/` directory; the top-level file's
/// path.
fn write_files(files: &[(String, &str)]) -> PathBuf {
    let run = scratch().join("run");
    let _ = std::fs::remove_dir_all(&run);
    std::fs::create_dir_all(&run).expect("the run directory can be made");
    for (name, text) in files {
        let path = run.join(name);
        if let Some(dir) = path.parent() {
            // A name that is also a directory of another name: the later
            // one is not written (an include of it is then an error).
            let _ = std::fs::create_dir_all(dir);
        }
        let _ = std::fs::write(&path, text);
    }
    run.join("top.toml")
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let files = split(text);
    for (_, t) in &files {
        // As given, and as `Model::parse` gives it to the fast path
        // (without a byte-order mark).
        fast_path_agrees(t);
        if let Some(bare) = t.strip_prefix('\u{feff}') {
            fast_path_agrees(bare);
        }
    }
    let top = write_files(&files);
    let top = top.to_str().expect("the scratch path is UTF-8");
    for accuracy in [
        Accuracy::fixed(Precision::Standard),
        Accuracy::fixed(Precision::Extended),
        Accuracy::default(),
    ] {
        let precision = accuracy.precision;
        // The pipeline every command runs: read, parse (includes from
        // disk), resolve, compose (and, with `auto`, compose again where a
        // bound asks).
        let settings = Settings {
            accuracy,
            ..Settings::default()
        };
        let loaded = match massprop::load(top, &settings) {
            Ok(loaded) => loaded,
            Err(d) => {
                // Rendering the diagnostic (snippet, carets) must not panic,
                // and it quotes no file outside the directory.
                let text = d.to_string();
                assert!(
                    !text.contains(MARKER),
                    "an error quotes secret.toml:\n{text}"
                );
                escaped(&text);
                diagnostic_lines(&text);
                return;
            }
        };
        let (model, summary) = (&loaded.model, &loaded.summary);
        let outside = model
            .included
            .iter()
            .find(|p| !roots().iter().any(|r| p.starts_with(r)));
        assert!(
            outside.is_none(),
            "an include outside the roots: {outside:?}"
        );
        let json = output::report::json(summary);
        let value: serde_json::Value = serde_json::from_str(&json)
            .unwrap_or_else(|e| panic!("JSON does not parse ({precision:?}): {e}\n{json}"));
        assert_no_null(&value, "", &json);
        assert!(
            !json.contains(MARKER),
            "the JSON shows secret.toml:\n{json}"
        );
        let table = output::report::table(summary, top, None);
        assert!(
            !table.contains(MARKER),
            "the table shows secret.toml:\n{table}"
        );
        escaped(&table);
        let _ = check::validity(summary);
        for c in &model.expect {
            let r = check::evaluate(&loaded.source, summary, c);
            // `check` words only the failures: a passing `{ min = … }` has
            // no maximum to be above.
            if r.pass {
                continue;
            }
            let message = output::check::message("fuzz.toml", &r);
            let words = message.split(|c: char| !c.is_ascii_alphanumeric());
            assert!(
                !words.into_iter().any(|w| w == "inf" || w == "NaN"),
                "non-finite number in a check message: {message}"
            );
        }
    }
});

/// The characters no output may hold raw but tab and newline (this
/// target's own list): controls, bidirectional formatting characters, the
/// line and paragraph separators, U+FFFE and U+FFFF.
fn hidden(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{202a}'..='\u{202e}'
                | '\u{2066}'..='\u{2069}'
                | '\u{200e}'
                | '\u{200f}'
                | '\u{61c}'
                | '\u{2028}'
                | '\u{2029}'
                | '\u{fffe}'
                | '\u{ffff}'
        )
}

/// Text for a terminal or a CI log: nothing hidden raw, no line a runner
/// reads as a command.
fn escaped(text: &str) {
    if let Some(c) = text.chars().find(|&c| c != '\n' && c != '\t' && hidden(c)) {
        panic!("a raw U+{:04X} in:\n{text}", u32::from(c));
    }
    if let Some(line) = text.lines().find(|l| l.trim_start().starts_with("::")) {
        panic!("a line begins with `::`: {line:?} in:\n{text}");
    }
}

/// A diagnostic's lines are its own: `PLACE: error: …` (or `error: …`),
/// then the gutter's (`  |`, `12 | …`) and `= help:`, `= note:` lines.
fn diagnostic_lines(text: &str) {
    let mut lines = text.lines();
    let first = lines.next().unwrap_or("");
    assert!(
        first.starts_with("error: ") || first.contains(": error: "),
        "a diagnostic's first line: {first:?} in:\n{text}"
    );
    for line in lines {
        let start = line.trim_start();
        let own = start.starts_with('|')
            || start.starts_with("= help: ")
            || start.starts_with("= note: ")
            || start
                .split_once(" |")
                .is_some_and(|(n, _)| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
        assert!(own, "a line not the diagnostic's own: {line:?} in:\n{text}");
    }
}

/// src/model/fast.rs's promise: where `fast::read_file` returns `Some`,
/// it reads the text as the reference parser does (`fast::reference::
/// agrees`), and so in chunks; where it returns `None`, reading the text
/// gives an error with a place.
fn fast_path_agrees(text: &str) {
    if fast::read_file(text).is_none() {
        let source = massprop::diag::Source::new("top.toml", text);
        let e = massprop::model::Model::parse(&source)
            .err()
            .expect("a file the reader refuses is not read");
        assert!(e.place().and_then(|p| p.span).is_some(), "no place: {e}");
        return;
    }
    if let Err(e) = fast::reference::agrees(text) {
        panic!("{e}");
    }
    let fast = format!("{:?}", fast::parse(text).expect("read_file took it"));
    // Read a few tokens at a time, the same file or declined (a chunk that
    // ends inside a value), never another.
    for n in [1, 5] {
        if let Some(chunked) = fast::parse_in_chunks(text, n) {
            assert_eq!(
                format!("{chunked:?}"),
                fast,
                "the fast path reads the file otherwise in chunks of {n} tokens"
            );
        }
    }
}

/// serde_json writes a non-finite f64 as `null` (it never writes `inf` or
/// `NaN`), so a finite summary has no `null` but where docs/json.md allows
/// one: the file's `name`, and the items of `principal_moment_share` and
/// `relative_change` (a zero moment). Part names are free text, so matching
/// "inf"/"NaN" in the string would give false alarms; the walk does not.
fn assert_no_null(v: &serde_json::Value, key: &str, json: &str) {
    use serde_json::Value;
    match v {
        Value::Null if matches!(key, "name" | "principal_moment_share" | "relative_change") => {}
        Value::Null => panic!("null under {key:?} in the JSON (a non-finite number):\n{json}"),
        Value::Array(a) => a.iter().for_each(|x| assert_no_null(x, key, json)),
        Value::Object(o) => o.iter().for_each(|(k, x)| assert_no_null(x, k, json)),
        Value::Number(n) => assert!(n.as_f64().is_some_and(f64::is_finite), "{n} under {key:?}"),
        _ => {}
    }
}
