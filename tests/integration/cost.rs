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

/// `levels` files in `dir`, `t0.toml` … : each includes the next `fan`
/// times; the last holds one point mass. `t0.toml` describes `fan^(levels
/// - 1)` parts.
fn include_tree(dir: &std::path::Path, levels: usize, fan: usize) -> String {
    for level in 0..levels {
        let body = if level + 1 == levels {
            point("leaf", 0.0)
        } else {
            (0..fan)
                .map(|k| {
                    format!(
                        "[[part]]\ninclude = \"t{}.toml\"\norigin = [{k}, 0, 0]\n",
                        level + 1
                    )
                })
                .collect()
        };
        std::fs::write(dir.join(format!("t{level}.toml")), body).unwrap();
    }
    dir.join("t0.toml").to_str().unwrap().to_string()
}

#[test]
fn a_tree_of_includes_past_the_part_limit_is_refused_at_its_include_before_expanding() {
    // 2³¹ parts from 32 files of two includes each: counted per file, the
    // first include already holds 2³⁰.
    let dir = scratch("cost", "tree-2-31");
    let top = include_tree(&dir, 32, 2);
    let out = massprop(&["report", &top]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with(&format!("{top}:2:11: error: with this include the body has 1073741824 parts, past the limit of 2000000: `")),
        "{err}"
    );
    assert!(
        err.contains("t1.toml` holds 1073741824 with its includes"),
        "{err}"
    );

    // 2²¹ = 2,097,152: just past the limit, at the second include.
    let dir = scratch("cost", "tree-2-21");
    let top = include_tree(&dir, 22, 2);
    let err = String::from_utf8(massprop(&["check", &top]).stderr).unwrap();
    assert!(
        err.contains(":5:11: error: with this include the body has 2097152 parts"),
        "{err}"
    );

    // 1000 copies in each level: the first include holds 10¹⁵ parts, or,
    // two levels down, 10²¹, past u64.
    for (levels, said) in [(7, "1000000000000000"), (9, "more than 2⁶⁴")] {
        let dir = scratch("cost", &format!("fan-{levels}"));
        let top = include_tree(&dir, levels, 1000);
        let err = String::from_utf8(massprop(&["report", &top]).stderr).unwrap();
        assert!(err.contains(&format!("the body has {said} parts")), "{err}");
        assert!(
            err.contains(&format!("t1.toml` holds {said} with")),
            "{err}"
        );
    }
}

#[test]
fn a_tree_of_includes_within_the_limit_is_composed_whole() {
    let dir = scratch("cost", "tree-2-10");
    let top = include_tree(&dir, 11, 2);
    let out = massprop(&["report", "--format", "json", &top]);
    assert!(out.status.success(), "{out:?}");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["parts"].as_array().unwrap().len(), 1 << 10);
    assert_eq!(json["mass"], 1024.0);
}
