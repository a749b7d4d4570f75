//! Every real in every command's JSON is written as a float and never as
//! `-0.0` (docs/json.md, issue 31 item 7): over every file in shapes/, with
//! and without `--axes`, `--products positive` and ω.

use crate::common::massprop;
use serde_json::Value;

/// Keys whose values are counts, indices or positions in a file: integers
/// by the schema (docs/json.md); every other number is a real.
const INTEGER_KEYS: &[&str] = &[
    "format_version",
    "equal_moments",
    "equal_moments_ref",
    "compared_axes",
    "parts",
    "line",
    "column",
    "end_line",
    "end_column",
    "sources",
    "samples",
    "seed",
    "files",
    "ok",
    "failed",
    "invalid",
    "skipped",
    "index",
];

/// The part files of shapes/.
fn shape_files() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir("shapes")
        .expect("shapes/ is read")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert!(files.len() >= 10, "{files:?}");
    files
}

/// The flag sets each command is run with.
const FLAGS: &[&[&str]] = &[
    &[],
    &["--axes", "axis=0,0,1;degrees=90"],
    &["--axes", "x=0,1,0;y=-1,0,0"],
    &["--products", "positive"],
    &["--omega", "0,0,-3", "--products", "positive"],
    &["--uncertainty", "linear"],
];

/// Where a number of `v` (under key `key`) breaks the rule, as a path.
fn misplaced_integers(v: &Value, key: &str, path: &str, out: &mut Vec<String>) {
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                misplaced_integers(x, k, &format!("{path}.{k}"), out);
            }
        }
        Value::Array(a) => {
            for x in a {
                misplaced_integers(x, key, &format!("{path}[]"), out);
            }
        }
        Value::Number(n) if !n.is_f64() && !INTEGER_KEYS.contains(&key) => {
            out.push(format!("{path} = {n}"));
        }
        Value::Number(_) | Value::Null | Value::Bool(_) | Value::String(_) => {}
    }
}

/// A `-0.0` number token in `line` (a string holding it would be escaped
/// text, not a token: names in shapes/ hold none).
fn has_negative_zero(line: &str) -> bool {
    line.match_indices("-0.0").any(|(i, m)| {
        !line[i + m.len()..]
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_digit() || c == 'e' || c == 'E')
    })
}

/// Run `args` and check its JSON.
fn check_json(args: &[&str]) {
    let out = massprop(args);
    let stdout = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(
        !stdout.is_empty(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!has_negative_zero(&stdout), "{args:?} writes -0.0");
    let mut bad = Vec::new();
    for line in stdout.lines() {
        let v: Value = serde_json::from_str(line).expect("JSON");
        misplaced_integers(&v, "", "", &mut bad);
    }
    assert!(
        bad.is_empty(),
        "{args:?}: integers where reals are meant: {bad:?}"
    );
}

#[test]
fn the_negative_zero_test_sees_a_negative_zero_and_not_a_small_negative() {
    assert!(has_negative_zero("[0.0,-0.0]"));
    assert!(!has_negative_zero("[-0.01,-0.05,1e-0]"));
}

#[test]
fn report_json_writes_every_real_as_a_float_and_no_negative_zero() {
    for file in shape_files() {
        for flags in FLAGS {
            let mut args = vec!["report", file.as_str(), "--format", "json"];
            args.extend_from_slice(flags);
            check_json(&args);
        }
    }
}

#[test]
fn diff_budget_and_check_json_write_every_real_as_a_float_and_no_negative_zero() {
    for file in shape_files() {
        for axes in [None, Some("axis=0,0,1;degrees=90")] {
            let f = file.as_str();
            let commands: [Vec<&str>; 3] = [
                vec!["diff", f, f, "--format", "json"],
                vec!["budget", f, "--format", "json"],
                vec!["check", f, "--format", "json"],
            ];
            for mut args in commands {
                if let Some(a) = axes {
                    args.extend(["--axes", a]);
                }
                check_json(&args);
            }
        }
    }
}
