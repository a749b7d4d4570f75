//! `check --format github|junit|sarif`: each read back by an independent
//! reader (the annotation grammar of GitHub's runner, an XML parser, the
//! SARIF 2.1.0 schema), and each pointing where the table does.
//!
//! The scene: one file that passes, one whose two expectations fail (one
//! of them spanning a multi-line entry), and one that is invalid. (A body
//! that is not physical is refused as it is read; `output::ci`'s unit test
//! covers the validity checks that back it up.)

use crate::common::{massprop, scratch};
use serde_json::Value;
use std::collections::BTreeMap;

const BOX: &str = "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [1, 2, 3]\n";

struct Scene {
    paths: Vec<String>,
    /// For each failure: the file, the line and column of its `[expect]`
    /// entry's value or of the error, as the table prints them.
    expected: Vec<(String, usize, usize)>,
}

fn scene(name: &str) -> Scene {
    let dir = scratch("ci", name);
    let file = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.display().to_string()
    };
    let ok = file(
        "a-ok.toml",
        &format!("{BOX}\n[expect]\nmass = {{ value = 12, tol = 1e-9 }}\n"),
    );
    let failed = file(
        "b-failed.toml",
        &format!(
            "{BOX}\n[expect]\nmass = {{ max = \"11.9 kg\" }}\nIzz = {{ value = 6,\n  tol = \"1%\" }}\nIxx = {{ value = 13, tol = \"1%\" }}\n"
        ),
    );
    let invalid = file(
        "d-invalid.toml",
        "[[part]]\nshape = \"box\"\nmass = 1\nsizee = [1, 2, 3]\ncenter = [0, 0, 0]\n",
    );
    Scene {
        expected: vec![
            (failed.clone(), 8, 8),
            (failed.clone(), 9, 7),
            (invalid.clone(), 4, 1),
        ],
        paths: vec![ok, failed, invalid],
    }
}

fn check(scene: &Scene, format: &str) -> (i32, String) {
    let mut args = vec!["check", "--format", format];
    args.extend(scene.paths.iter().map(String::as_str));
    let out = massprop(&args);
    (
        out.status.code().expect("exit status"),
        String::from_utf8(out.stdout).expect("UTF-8"),
    )
}

/// What the table says: `path:line:col` of each failure with a place.
fn table_places(scene: &Scene) -> Vec<(String, usize, usize)> {
    let mut args = vec!["check"];
    args.extend(scene.paths.iter().map(String::as_str));
    let out = massprop(&args);
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let mut places: Vec<_> = text
        .lines()
        .filter_map(|l| {
            let (place, _) = l.split_once(": error: ")?;
            let mut it = place.rsplitn(3, ':');
            let col = it.next()?.parse().ok()?;
            let line = it.next()?.parse().ok()?;
            Some((it.next()?.to_string(), line, col))
        })
        .collect();
    places.sort();
    places
}

#[test]
fn the_table_points_where_the_scene_says() {
    let s = scene("table");
    assert_eq!(table_places(&s), s.expected);
}

/// One GitHub workflow command: its level, properties and message, with
/// the runner's escapes undone.
fn parse_command(line: &str) -> Option<(String, BTreeMap<String, String>, String)> {
    let unescape = |s: &str| {
        s.replace("%0D", "\r")
            .replace("%0A", "\n")
            .replace("%3A", ":")
            .replace("%2C", ",")
            .replace("%25", "%")
    };
    let rest = line.strip_prefix("::")?;
    let (head, message) = rest.split_once("::")?;
    let (level, props) = head.split_once(' ')?;
    let props = props
        .split(',')
        .map(|p| {
            let (k, v) = p.split_once('=').expect("key=value");
            (k.to_string(), unescape(v))
        })
        .collect();
    Some((level.to_string(), props, unescape(message)))
}

#[test]
fn github_annotations_parse_back_to_every_failure_at_its_place() {
    let s = scene("github");
    let (code, out) = check(&s, "github");
    assert_eq!(code, 2, "{out}");
    let commands: Vec<_> = out.lines().filter_map(parse_command).collect();
    // Every line is a command but the summary.
    assert_eq!(commands.len() + 1, out.lines().count(), "{out}");
    assert!(out.ends_with("checked 3 files: 1 ok, 1 failed, 1 invalid\n"));
    assert!(commands.iter().all(|(level, _, _)| level == "error"));
    let mut places: Vec<_> = commands
        .iter()
        .filter(|(_, p, _)| p.contains_key("line"))
        .map(|(_, p, _)| {
            (
                p["file"].clone(),
                p["line"].parse().unwrap(),
                p["col"].parse().unwrap(),
            )
        })
        .collect();
    places.sort();
    assert_eq!(places, s.expected);
    // The multi-line entry spans to its closing brace.
    let izz = commands
        .iter()
        .find(|(_, p, _)| p.get("line").is_some_and(|l| l == "9"))
        .unwrap();
    assert_eq!(
        (izz.1["endLine"].as_str(), izz.1["endColumn"].as_str()),
        ("10", "14")
    );
    assert_eq!(izz.1["title"], "massprop check: Izz");
    assert_eq!(
        izz.2,
        "Izz 5 kg·m² is outside 6 kg·m² ± 1 % (off by -16.667 %)"
    );
    // The invalid file's message keeps its help line.
    let bad = commands
        .iter()
        .find(|(_, p, _)| p["file"] == s.paths[2])
        .unwrap();
    assert_eq!(bad.2, "unknown key `sizee`\ndid you mean `size`?");
}

#[test]
fn junit_is_well_formed_xml_of_nextests_shape() {
    let s = scene("junit");
    let (code, out) = check(&s, "junit");
    assert_eq!(code, 2);
    let doc = roxmltree::Document::parse(&out).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "testsuites");
    let count = |n: roxmltree::Node, tag: &str| {
        n.descendants()
            .filter(|d| d.tag_name().name() == tag)
            .count()
    };
    let attr = |n: roxmltree::Node, a: &str| -> usize { n.attribute(a).unwrap().parse().unwrap() };
    let suites: Vec<_> = root.children().filter(|n| n.is_element()).collect();
    assert_eq!(suites.len(), 3);
    for (suite, path) in suites.iter().zip(&s.paths) {
        assert_eq!(suite.tag_name().name(), "testsuite");
        assert_eq!(suite.attribute("name"), Some(path.as_str()));
        // The counts agree with the children, as JUnit readers check.
        assert_eq!(attr(*suite, "tests"), count(*suite, "testcase"));
        assert_eq!(attr(*suite, "failures"), count(*suite, "failure"));
        assert_eq!(attr(*suite, "errors"), count(*suite, "error"));
        for case in suite.children().filter(|n| n.is_element()) {
            assert_eq!(case.tag_name().name(), "testcase");
            assert_eq!(case.attribute("classname"), Some(path.as_str()));
        }
    }
    assert_eq!(attr(root, "tests"), count(root, "testcase"));
    assert_eq!(attr(root, "failures"), 2);
    assert_eq!(attr(root, "errors"), 1);
    let names = |i: usize| -> Vec<&str> {
        suites[i]
            .children()
            .filter(|n| n.is_element())
            .map(|n| n.attribute("name").unwrap())
            .collect()
    };
    // The failed file: validity of the file, its three expectations, the
    // three validity checks.
    assert_eq!(
        names(1),
        [
            "valid part file",
            "mass",
            "Izz",
            "Ixx",
            "validity: mass is positive",
            "validity: inertia is positive definite",
            "validity: triangle inequality"
        ]
    );
    let failed: Vec<_> = suites[1]
        .descendants()
        .filter(|n| n.tag_name().name() == "failure")
        .map(|n| n.parent().unwrap().attribute("name").unwrap())
        .collect();
    assert_eq!(failed, ["mass", "Izz"]);
    // The invalid file: one test case, an error carrying the message.
    let error = suites[2]
        .descendants()
        .find(|n| n.tag_name().name() == "error")
        .unwrap();
    assert_eq!(error.attribute("message"), Some("unknown key `sizee`"));
    assert!(error.text().unwrap().contains(":4:1: error: unknown key"));
}

#[test]
fn sarif_is_valid_against_the_2_1_0_schema_and_points_at_each_failure() {
    let schema: Value = serde_json::from_str(include_str!("../schemas/sarif-2.1.0.json")).unwrap();
    let validator = jsonschema::validator_for(&schema).expect("the SARIF schema compiles");
    let s = scene("sarif");
    let (code, out) = check(&s, "sarif");
    assert_eq!(code, 2);
    let v: Value = serde_json::from_str(&out).expect("one JSON document");
    let errors: Vec<String> = validator.iter_errors(&v).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{errors:#?}");
    // The validator does reject what is not SARIF: a result without its
    // message.
    let mut broken = v.clone();
    broken["runs"][0]["results"][0]
        .as_object_mut()
        .unwrap()
        .remove("message");
    assert!(!validator.is_valid(&broken));
    let results = v["runs"][0]["results"].as_array().unwrap();
    assert_eq!(results.len(), 3);
    let mut places: Vec<(String, usize, usize)> = results
        .iter()
        .filter_map(|r| {
            let l = &r["locations"][0]["physicalLocation"];
            let region = l.get("region")?;
            Some((
                l["artifactLocation"]["uri"].as_str().unwrap().to_string(),
                region["startLine"].as_u64().unwrap() as usize,
                region["startColumn"].as_u64().unwrap() as usize,
            ))
        })
        .collect();
    places.sort();
    assert_eq!(places, s.expected);
    // Rules are named and indexed consistently.
    let rules = v["runs"][0]["tool"]["driver"]["rules"].as_array().unwrap();
    for r in results {
        let i = r["ruleIndex"].as_u64().unwrap() as usize;
        assert_eq!(rules[i]["id"], r["ruleId"]);
    }
}

#[test]
fn ci_formats_are_offered_to_check_alone() {
    let out = massprop(&["report", "shapes/flywheel.toml", "--format", "sarif"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("possible values: table, json"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn check_json_gives_an_invalid_files_error_as_fields() {
    let s = scene("json");
    let (code, out) = check(&s, "json");
    assert_eq!(code, 2);
    let v: Value = serde_json::from_str(&out).unwrap();
    let e = &v["files"][2]["error"];
    assert_eq!(e["path"], s.paths[2].as_str());
    assert_eq!((&e["line"], &e["column"]), (&4.into(), &1.into()));
    assert_eq!((&e["end_line"], &e["end_column"]), (&4.into(), &5.into()));
    assert_eq!(e["message"], "unknown key `sizee`");
    assert_eq!(e["label"], "did you mean `size`?");
    let failed = &v["files"][1]["checks"];
    assert_eq!(
        failed[0]["message"],
        "mass 12 kg is above the maximum 11.9 kg (by 0.1 kg)"
    );
    assert_eq!(v["files"][1]["validity"].as_array().unwrap().len(), 0);
}
