//! Cost in proportion to the work (issue 12, item 6): what the program
//! does with input that is small to write and expensive to expand or show.
//! Times and memory are measured in docs/performance.md, never here; these
//! tests pin the behaviour that keeps them bounded.

use crate::common::{massprop, scratch};

fn point(name: &str, x: f64) -> String {
    format!("[[part]]\nname = \"{name}\"\nshape = \"point\"\nmass = 1\ncenter = [{x}, 0, 0]\n")
}

#[test]
fn a_long_name_is_cut_in_tables_and_whole_in_json() {
    let dir = scratch("cost", "long-name");
    let long = "é".repeat(70_000);
    let file = dir.join("long.toml");
    std::fs::write(&file, format!("{}{}", point(&long, 0.0), point("b", 1.0))).unwrap();
    let file = file.to_str().unwrap();

    let out = massprop(&["report", file]);
    assert!(out.status.success(), "{out:?}");
    let table = String::from_utf8(out.stdout).unwrap();
    let row = table
        .lines()
        .find(|l| l.contains("(70000 characters)"))
        .expect("the name's row says how long the name is");
    assert!(row.contains(&format!("{}…", "é".repeat(99))), "{row}");
    // No line of any table is wider than a name cut to 100 characters
    // and the widest numeric columns allow.
    let widest = table.lines().map(|l| l.chars().count()).max().unwrap();
    assert!(widest < 400, "a line {widest} characters wide");

    let out = massprop(&["report", "--format", "json", file]);
    assert!(out.status.success(), "{out:?}");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["parts"][0]["name"], long.as_str());
}

#[test]
fn parts_of_one_name_are_numbered_in_diff_in_file_order() {
    let dir = scratch("cost", "diff-same-names");
    let n = 3_000;
    let body = |shift: f64| -> String { (0..n).map(|i| point("bolt", i as f64 + shift)).collect() };
    let (old, new) = (dir.join("old.toml"), dir.join("new.toml"));
    std::fs::write(&old, body(0.0)).unwrap();
    std::fs::write(&new, body(0.5)).unwrap();
    let out = massprop(&["diff", old.to_str().unwrap(), new.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    let labels: Vec<usize> = text
        .lines()
        .filter_map(|l| l.split("bolt (#").nth(1))
        .map(|rest| rest.split(')').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(labels, (1..=n).collect::<Vec<_>>());
}
