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

    let out = massprop(&["report", "--full", file]);
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

/// A binary tree of `depth + 1` files: `t{l}.toml` includes `t{l+1}.toml`
/// at x = 0 and at x = 2^l (in millimetres below the top file, in metres,
/// when `mm` is set: the frames then scale as well as move), and the last
/// holds one point of 1 kg at the origin. So the body is 2^depth points of
/// 1 kg at x = 0, 1, …, 2^depth − 1 (in the top file's length unit), each
/// once; each sub-assembly at depth l (1 to `depth`) holds 2^(depth − l)
/// of them.
fn binary_tree(dir: &std::path::Path, depth: u32, mm: bool) -> String {
    for l in 0..=depth {
        let units = if mm && l > 0 {
            "units = { length = \"mm\" }\n"
        } else {
            ""
        };
        // Origins in the including file's unit: mm below the top.
        let scale = if mm && l > 0 { 1000.0 } else { 1.0 };
        let body = if l == depth {
            "[[part]]\nname = \"p\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n".to_string()
        } else {
            (0..2)
                .map(|k| {
                    format!(
                        "[[part]]\nname = \"a{k}\"\ninclude = \"t{}.toml\"\norigin = [{}, 0, 0]\n",
                        l + 1,
                        f64::from(k) * 2f64.powi(l as i32) * scale
                    )
                })
                .collect()
        };
        std::fs::write(dir.join(format!("t{l}.toml")), format!("{units}{body}")).unwrap();
    }
    dir.join("t0.toml").to_str().unwrap().to_string()
}

fn json_report(args: &[&str]) -> serde_json::Value {
    let out = massprop(args);
    assert!(out.status.success(), "{args:?}: {out:?}");
    serde_json::from_slice(&out.stdout).expect("the report is JSON")
}

/// Each sub-assembly file is kept once and placed for each copy; the body,
/// its parts and its sub-assemblies are those of the 2^depth points the
/// tree describes, against their closed forms: N points of 1 kg at
/// x = 0 … N − 1 have their centre at (N − 1)/2 and Iyy = Izz =
/// Σ (x − x̄)² = N (N² − 1)/12, Ixx = 0. Every figure is exact in f64
/// (integers and halves below 2⁵³), so they are compared exactly.
#[test]
fn an_include_tree_reports_the_body_it_describes() {
    for mm in [false, true] {
        let dir = scratch("cost", &format!("tree-{mm}"));
        let depth = 10;
        let top = binary_tree(&dir, depth, mm);
        let n = 2f64.powi(depth as i32);
        let v = json_report(&["report", "--format", "json", &top]);
        assert_eq!(v["mass"], n, "mm: {mm}");
        assert_eq!(v["center_of_mass"][0], (n - 1.0) / 2.0, "mm: {mm}");
        let i = n * (n * n - 1.0) / 12.0;
        assert_eq!(v["inertia_com"][1][1], i, "mm: {mm}");
        assert_eq!(v["inertia_com"][2][2], i, "mm: {mm}");
        assert_eq!(v["inertia_com"][0][0], 0.0, "mm: {mm}");

        // Every point once, named by its path.
        let parts = v["parts"].as_array().unwrap();
        assert_eq!(parts.len(), n as usize);
        let mut xs: Vec<f64> = parts
            .iter()
            .map(|p| p["center_of_mass"][0].as_f64().unwrap())
            .collect();
        xs.sort_by(f64::total_cmp);
        assert!(
            xs.iter().enumerate().all(|(k, x)| *x == k as f64),
            "mm: {mm}"
        );
        let last = &parts[parts.len() - 1];
        let path: Vec<&str> = (0..depth).map(|_| "a1").collect();
        assert_eq!(last["assembly"], serde_json::json!(path));
        assert_eq!(last["name"], format!("{} / p", path.join(" / ")));
        assert_eq!(last["center_of_mass"][0], n - 1.0);

        // Sub-assemblies, parents first: a0, then a0's a0, … down to a
        // depth-`depth` one of one point, then back up.
        let asm = v["assemblies"].as_array().unwrap();
        assert_eq!(asm.len(), (1usize << (depth + 1)) - 2);
        for (l, a) in asm.iter().take(depth as usize).enumerate() {
            let count = 2f64.powi((depth as usize - l - 1) as i32);
            assert_eq!(a["path"].as_array().unwrap().len(), l + 1);
            assert_eq!(a["parts"], count);
            assert_eq!(a["mass"], count);
            // The first copies (all a0) at depth l + 1: the points whose
            // lowest l + 1 binary digits are 0, x = 0, 2^(l+1), … up to
            // N − 2^(l+1).
            let step = 2f64.powi(l as i32 + 1);
            assert_eq!(a["center_of_mass"][0], (n - step) / 2.0);
            assert_eq!(a["mass_fraction"], count / n);
        }
        let second = &asm[asm.len() / 2];
        assert_eq!(second["path"], serde_json::json!(["a1"]));
        // The odd x: 1, 3, … N − 1.
        assert_eq!(second["center_of_mass"][0], n / 2.0);
    }
}

/// The rows of parts and sub-assemblies, made as they are written, agree
/// with each other: each sub-assembly sums the part rows under its path
/// (counted, and its mass and centre summed here independently), in the
/// table as in JSON; and `-o` writes what stdout shows.
#[test]
fn sub_assembly_rows_sum_the_part_rows_under_them() {
    let dir = scratch("cost", "tree-rows");
    let top = binary_tree(&dir, 6, true);
    let v = json_report(&["report", "--format", "json", &top]);
    let parts = v["parts"].as_array().unwrap();
    for a in v["assemblies"].as_array().unwrap() {
        let path = a["path"].as_array().unwrap();
        let inside: Vec<&serde_json::Value> = parts
            .iter()
            .filter(|p| p["assembly"].as_array().unwrap().starts_with(path))
            .collect();
        assert_eq!(a["parts"], inside.len(), "{path:?}");
        let mass: f64 = inside.iter().map(|p| p["mass"].as_f64().unwrap()).sum();
        let x: f64 = inside
            .iter()
            .map(|p| p["mass"].as_f64().unwrap() * p["center_of_mass"][0].as_f64().unwrap())
            .sum::<f64>()
            / mass;
        assert_eq!(a["mass"], mass, "{path:?}");
        let got = a["center_of_mass"][0].as_f64().unwrap();
        assert!(
            (got - x).abs() <= 64.0 * f64::EPSILON * x.abs().max(1.0),
            "{path:?}: {got} vs {x}"
        );
    }
    let out = massprop(&["report", &top]);
    let table = String::from_utf8(out.stdout).unwrap();
    assert_eq!(table.matches("│").count() % 2, 0);
    let out_file = dir.join("report.json");
    let o = massprop(&[
        "report",
        "--format",
        "json",
        &top,
        "-o",
        out_file.to_str().unwrap(),
    ]);
    assert!(o.status.success() && o.stdout.is_empty(), "{o:?}");
    let written: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&out_file).unwrap()).unwrap();
    assert_eq!(written, v);
}

/// `--only` in a tree: the sub-assembly at a path deep down, alone, placed
/// where the tree puts it.
#[test]
fn only_picks_one_copy_deep_in_a_tree() {
    let dir = scratch("cost", "tree-only");
    let top = binary_tree(&dir, 8, false);
    let v = json_report(&["report", "--format", "json", &top, "--only", "a1 / a0 / a1"]);
    // x = 1 (level 0) + 0 (level 1) + 4 (level 2) + 8 k, k = 0 … 31.
    assert_eq!(v["mass"], 32.0);
    assert_eq!(v["center_of_mass"][0], 5.0 + 8.0 * 15.5);
    assert_eq!(v["sub_assembly"], serde_json::json!(["a1", "a0", "a1"]));
    assert_eq!(v["parts"].as_array().unwrap().len(), 32);
}
