//! The quantities `report`'s JSON writes from the table of reported
//! quantities (issue 29, item 3): each row that `report` writes is in the
//! JSON of a turning body about a point, with its shape, once, and
//! documented in docs/json.md; each it bounds is in `error_bounds` and
//! named in docs/json.md's `error_bounds` row. The JSON is read by
//! serde_json and, for the keys' order and uniqueness, by a small scanner
//! of the text here, not by the writer.

use crate::common::massprop;
use massprop::quantity::{Layout, QUANTITIES};
use serde_json::Value;

/// The bent plate turning at ω with α and moving, about the origin, as
/// JSON text.
fn turning_report() -> String {
    let out = massprop(&[
        "report",
        "--format",
        "json",
        "--omega",
        "1,2,3",
        "--alpha",
        "0,0,1",
        "--velocity",
        "1,-2,0.5",
        "--about",
        "0,0,0",
        "shapes/bent-plate.toml",
    ]);
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The keys of the outermost object of `json`, in the order written.
fn top_level_keys(json: &str) -> Vec<String> {
    let (mut depth, mut keys) = (0usize, Vec::new());
    let mut chars = json.chars().peekable();
    let mut expect_key = false;
    while let Some(c) = chars.next() {
        match c {
            '{' | '[' => {
                depth += 1;
                expect_key = c == '{' && depth == 1;
            }
            '}' | ']' => depth -= 1,
            ',' => expect_key = depth == 1,
            '"' => {
                let mut s = String::new();
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => s.push(chars.next().unwrap()),
                        '"' => break,
                        c => s.push(c),
                    }
                }
                if expect_key {
                    keys.push(s);
                    expect_key = false;
                }
            }
            _ => {}
        }
    }
    keys
}

/// How many numbers a JSON value holds, arrays of arrays flattened.
fn numbers(v: &Value) -> usize {
    match v {
        Value::Number(_) => 1,
        Value::Array(a) => a.iter().map(numbers).sum(),
        other => panic!("not a number or an array of numbers: {other}"),
    }
}

fn documented_keys() -> Vec<String> {
    let doc = std::fs::read_to_string("docs/json.md").unwrap();
    doc.lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l.split('`').nth(1).unwrap().to_string())
        .collect()
}

#[test]
fn no_key_of_the_report_is_written_twice_and_each_is_documented() {
    let keys = top_level_keys(&turning_report());
    let documented = documented_keys();
    for (i, k) in keys.iter().enumerate() {
        assert!(!keys[..i].contains(k), "{k} twice");
        assert!(documented.contains(k), "docs/json.md has no row for `{k}`");
    }
}

#[test]
fn every_quantity_the_table_reports_is_in_the_json_with_its_number_of_components() {
    let v: Value = serde_json::from_str(&turning_report()).unwrap();
    for info in QUANTITIES.iter().filter(|i| i.report.is_some()) {
        let value = v.get(info.key).unwrap_or_else(|| panic!("no {}", info.key));
        assert_eq!(numbers(value), info.layout.count(), "{}", info.key);
        if let Some(equal) = info.equal {
            assert!(v[equal].is_array(), "{equal}");
        }
    }
}

#[test]
fn every_quantity_the_table_bounds_is_in_error_bounds_and_named_in_its_docs() {
    let v: Value = serde_json::from_str(&turning_report()).unwrap();
    let bounds = v["error_bounds"].as_object().unwrap();
    let doc = std::fs::read_to_string("docs/json.md").unwrap();
    let row = doc
        .lines()
        .find(|l| l.starts_with("| `error_bounds` |"))
        .unwrap();
    for info in QUANTITIES.iter().filter(|i| i.bound.is_some()) {
        let b = bounds
            .get(info.key)
            .unwrap_or_else(|| panic!("no bound of {}", info.key));
        // A set of axes is bounded by an angle per axis.
        let n = match info.layout {
            Layout::Axes => 3,
            Layout::Scalar | Layout::Vector | Layout::Ordered | Layout::Matrix => {
                info.layout.count()
            }
        };
        assert_eq!(numbers(b), n, "{}", info.key);
        assert!(row.contains(&format!("`{}`", info.key)), "{}", info.key);
    }
    let bounded = QUANTITIES.iter().filter(|i| i.bound.is_some()).count();
    assert_eq!(bounds.len(), bounded, "{bounds:?}");
}

#[test]
fn the_scanner_reads_the_outermost_keys_alone() {
    let keys = top_level_keys(r#"{"a":1,"b":{"c":[{"d":2}],"e":"x,\"f\":"},"g":[1,2]}"#);
    assert_eq!(keys, ["a", "b", "g"]);
}
