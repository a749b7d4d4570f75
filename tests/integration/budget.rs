//! `massprop budget` and the predicted body: a statement worked by hand,
//! groups and maturities through includes, the JSON read back, `check` on
//! `predicted_*`, and the predicted body's invariance under translation.

use crate::common::{massprop, scratch};
use serde_json::Value;

const STATEMENT: &str = "tests/cmd/budget.in/statement.toml";

fn json_of(args: &[&str]) -> (Value, Option<i32>) {
    let out = massprop(args);
    let text = String::from_utf8(out.stdout).unwrap();
    let v = serde_json::from_str(&text)
        .unwrap_or_else(|e| panic!("{e}: {text}{}", String::from_utf8_lossy(&out.stderr)));
    (v, out.status.code())
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0),
        "{what}: {a} against {b}"
    );
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

fn group<'a>(v: &'a Value, path: &[&str]) -> &'a Value {
    v["groups"]
        .as_array()
        .unwrap()
        .iter()
        .find(|g| g["path"] == serde_json::json!(path))
        .unwrap_or_else(|| panic!("no group {path:?} in {}", v["groups"]))
}

/// statement.toml, by hand (SI):
///
/// | part    | mass | centre     | group              | maturity  | growth |
/// |---------|------|------------|--------------------|-----------|--------|
/// | frame   | 4    | (1, 0, 0)  | structure          | 10 %      | 0.4    |
/// | bracket | 2    | (0, 1, 0)  | structure/brackets | 10 %      | 0.2    |
/// | camera  | 4    | (0, 0, 1)  | payload            | 2 %       | 0.08   |
/// | harness | 1    | (−1, 0, 0) | —                  | —         | 0      |
///
/// basic 11, growth 0.68, predicted 11.68; structure 6 + 0.6 = 6.6 (its
/// sub-group brackets 2 + 0.2 = 2.2), payload 4 + 0.08 = 4.08, no group 1;
/// shares 6.6/11.68, 2.2/11.68, 4.08/11.68, 1/11.68. Limit 12: margin
/// 0.32 kg, 0.32/12 = 2.67 % of it, met. Centres of mass: basic (4 − 1,
/// 2, 4)/11; predicted (4.4 − 1, 2.2, 4.08)/11.68.
#[test]
fn a_statement_worked_by_hand() {
    let (v, status) = json_of(&["budget", STATEMENT, "--format", "json"]);
    assert_eq!(status, Some(0));
    let t = &v["total"];
    close(num(&t["basic_mass"]), 11.0, "basic");
    close(num(&t["growth_mass"]), 0.68, "growth");
    close(num(&t["predicted_mass"]), 11.68, "predicted");
    close(num(&t["growth_fraction"]), 0.68 / 11.0, "growth %");
    let rows = [
        (&["structure"][..], 6.0, 0.6, 2),
        (&["structure", "brackets"][..], 2.0, 0.2, 1),
        (&["payload"][..], 4.0, 0.08, 1),
        (&[][..], 1.0, 0.0, 1),
    ];
    for (path, basic, growth, parts) in rows {
        let g = group(&v, path);
        assert_eq!(g["parts"], parts, "{path:?}");
        close(num(&g["basic_mass"]), basic, "basic");
        close(num(&g["growth_mass"]), growth, "growth");
        close(num(&g["predicted_mass"]), basic + growth, "predicted");
        close(num(&g["share"]), (basic + growth) / 11.68, "share");
    }
    // Parents before children, in the order they first appear.
    let order: Vec<&Value> = v["groups"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| &g["path"])
        .collect();
    assert_eq!(
        order,
        [
            &serde_json::json!(["structure"]),
            &serde_json::json!(["structure", "brackets"]),
            &serde_json::json!(["payload"]),
            &serde_json::json!([]),
        ]
    );
    assert_eq!(v["no_maturity"]["parts"], 1);
    close(num(&v["no_maturity"]["basic_mass"]), 1.0, "no maturity");
    let l = &v["limit"];
    assert_eq!(l["source"], "budget");
    close(num(&l["limit"]), 12.0, "limit");
    close(num(&l["margin"]), 0.32, "margin");
    close(num(&l["margin_fraction"]), 0.32 / 12.0, "margin %");
    assert_eq!(l["met"], true);
    let c = |b: &str, k: usize| num(&v[b]["center_of_mass"][k]);
    for (k, want) in [3.0 / 11.0, 2.0 / 11.0, 4.0 / 11.0].into_iter().enumerate() {
        close(c("basic", k), want, "basic centre");
    }
    for (k, want) in [3.4 / 11.68, 2.2 / 11.68, 4.08 / 11.68]
        .into_iter()
        .enumerate()
    {
        close(c("predicted", k), want, "predicted centre");
    }
    // The predicted inertia about its centre, by the parallel-axis sum of
    // the grown masses and the frame's own m (b² + c²)/12 = 4 · 0.08/12.
    let parts = [
        (4.4, [1.0, 0.0, 0.0]),
        (2.2, [0.0, 1.0, 0.0]),
        (4.08, [0.0, 0.0, 1.0]),
        (1.0, [-1.0, 0.0, 0.0]),
    ];
    let com = [3.4 / 11.68, 2.2 / 11.68, 4.08 / 11.68];
    let own = 4.0 * 0.08 / 12.0;
    for i in 0..3 {
        for j in 0..3 {
            let mut want = if i == j { own } else { 0.0 };
            for (m, p) in &parts {
                let d: Vec<f64> = (0..3).map(|k| p[k] - com[k]).collect();
                let dd: f64 = d.iter().map(|x| x * x).sum();
                want += m * (if i == j { dd } else { 0.0 } - d[i] * d[j]);
            }
            let got = num(&v["predicted"]["inertia_com"][i][j]);
            assert!(
                (got - want).abs() <= 1e-12 * 10.0,
                "I[{i}][{j}]: {got} against {want}"
            );
        }
    }
}

/// The JSON adds up: each parent is the sum of its own parts and its
/// children, the top-level groups sum to the totals, and the predicted
/// mass less the basic is the sum of the growths.
#[test]
fn the_statements_json_adds_up() {
    for file in [
        STATEMENT,
        "shapes/smallsat.toml",
        "tests/cmd/budget.in/stage.toml",
    ] {
        let (v, _) = json_of(&["budget", file, "--format", "json"]);
        let groups = v["groups"].as_array().unwrap();
        let top: Vec<&Value> = groups
            .iter()
            .filter(|g| g["path"].as_array().unwrap().len() <= 1)
            .collect();
        let sum = |key: &str| top.iter().map(|g| num(&g[key])).sum::<f64>();
        close(sum("basic_mass"), num(&v["total"]["basic_mass"]), file);
        close(sum("growth_mass"), num(&v["total"]["growth_mass"]), file);
        close(
            sum("predicted_mass"),
            num(&v["total"]["predicted_mass"]),
            file,
        );
        close(
            top.iter()
                .map(|g| g["parts"].as_u64().unwrap())
                .sum::<u64>() as f64,
            num(&v["total"]["parts"]),
            file,
        );
        close(
            num(&v["predicted"]["mass"]) - num(&v["basic"]["mass"]),
            num(&v["total"]["growth_mass"]),
            file,
        );
        close(sum("share"), 1.0, file);
        // A child's figures are within its parent's.
        for g in groups {
            let path = g["path"].as_array().unwrap();
            if path.len() > 1 {
                let parent = groups
                    .iter()
                    .find(|p| p["path"].as_array().unwrap()[..] == path[..path.len() - 1])
                    .unwrap();
                assert!(
                    num(&parent["basic_mass"]) >= num(&g["basic_mass"]),
                    "{file}"
                );
            }
        }
    }
}

/// Groups through includes: under the include's `group`, or kept as they
/// are; the include's `maturity` is the default of its parts that have
/// none, looked up in the including file's `[growth]`.
#[test]
fn groups_and_maturities_are_carried_through_includes() {
    let (v, _) = json_of(&[
        "budget",
        "tests/cmd/budget.in/stage.toml",
        "--format",
        "json",
    ]);
    // Main tank: shell 3 kg at its own 8 %, valve 0.5 kg at the include's 20 %.
    let p = group(&v, &["propulsion"]);
    close(num(&p["basic_mass"]), 3.5, "propulsion basic");
    close(
        num(&p["growth_mass"]),
        3.0 * 0.08 + 0.5 * 0.2,
        "propulsion growth",
    );
    let t = group(&v, &["propulsion", "tanks"]);
    close(num(&t["growth_mass"]), 0.24, "propulsion/tanks growth");
    // Spare tank: its groups as they are; its valve has no group, no maturity.
    close(num(&group(&v, &["tanks"])["basic_mass"]), 3.0, "tanks");
    let none = group(&v, &[]);
    close(num(&none["basic_mass"]), 0.5, "no group");
    close(num(&none["growth_mass"]), 0.0, "no group growth");
    assert_eq!(v["no_maturity"]["parts"], 1);
}

/// Copies keep their part's group and maturity: four copies of a 1 kg
/// part at 10 % grow by 0.4 kg in all, in the part's group.
#[test]
fn copies_keep_their_parts_group_and_maturity() {
    let dir = scratch("budget", "copies");
    let file = dir.join("legs.toml");
    std::fs::write(
        &file,
        "[growth]\nestimated = \"10 %\"\n\n[[part]]\nname = \"leg\"\nshape = \"point\"\nmass = 1\ncenter = [1, 0, 0]\ngroup = \"legs\"\nmaturity = \"estimated\"\narray = { count = 2, step = [0, 1, 0] }\nmirror = { normal = [1, 0, 0] }\n",
    )
    .unwrap();
    let (v, _) = json_of(&["budget", file.to_str().unwrap(), "--format", "json"]);
    let g = group(&v, &["legs"]);
    assert_eq!(g["parts"], 4);
    close(num(&g["growth_mass"]), 0.4, "legs growth");
    // The mirror pairs balance: the predicted centre is the basic one.
    close(num(&v["predicted"]["center_of_mass"][0]), 0.0, "x");
    close(num(&v["predicted"]["center_of_mass"][1]), 0.5, "y");
}

/// The limit from `[expect] mass`'s `max`, not met: exit status 1, and the
/// margin negative.
#[test]
fn a_limit_not_met_exits_with_status_1() {
    let (v, status) = json_of(&[
        "budget",
        "tests/cmd/budget.in/over.toml",
        "--format",
        "json",
    ]);
    assert_eq!(status, Some(1));
    assert_eq!(v["limit"]["source"], "expect_mass_max");
    close(num(&v["limit"]["margin"]), 12.0 - 12.5, "margin");
    assert_eq!(v["limit"]["met"], false);
}

/// Translating the whole file leaves the predicted body's inertia about
/// its centre of mass as it was, and moves its centre by the translation.
#[test]
fn the_predicted_inertia_does_not_change_when_the_file_is_translated() {
    let text = std::fs::read_to_string(STATEMENT).unwrap();
    let dir = scratch("budget", "translated");
    let moved = dir.join("moved.toml");
    // Every centre in the file is a literal `center = [x, y, z]`.
    let shift = [100.0, -50.0, 7.0];
    let out: String = text
        .lines()
        .map(|l| match l.strip_prefix("center = [") {
            Some(rest) => {
                let xs: Vec<f64> = rest
                    .trim_end_matches(']')
                    .split(',')
                    .map(|x| x.trim().parse().unwrap())
                    .collect();
                format!(
                    "center = [{}, {}, {}]\n",
                    xs[0] + shift[0],
                    xs[1] + shift[1],
                    xs[2] + shift[2]
                )
            }
            None => format!("{l}\n"),
        })
        .collect();
    assert_ne!(out, text);
    std::fs::write(&moved, out).unwrap();
    let (a, _) = json_of(&["budget", STATEMENT, "--format", "json"]);
    let (b, _) = json_of(&["budget", moved.to_str().unwrap(), "--format", "json"]);
    for i in 0..3 {
        let (ca, cb) = (
            num(&a["predicted"]["center_of_mass"][i]),
            num(&b["predicted"]["center_of_mass"][i]),
        );
        assert!((cb - ca - shift[i]).abs() < 1e-12 * 100.0, "centre {i}");
        for j in 0..3 {
            let (x, y) = (
                num(&a["predicted"]["inertia_com"][i][j]),
                num(&b["predicted"]["inertia_com"][i][j]),
            );
            assert!((x - y).abs() <= 1e-11, "I[{i}][{j}]: {x} against {y}");
        }
    }
}

/// `check` holds `predicted_mass`: 10 kg at 15 % is 11.5 kg.
#[test]
fn check_holds_expectations_on_the_predicted_mass() {
    let dir = scratch("budget", "check");
    let file = dir.join("p.toml");
    let body = "[growth]\nestimated = \"15 %\"\n\n[[part]]\nshape = \"box\"\nmass = 10\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n\n[expect]\n";
    for (expect, status) in [
        ("predicted_mass = { value = 11.5, tol = \"1e-9%\" }\n", 0),
        ("predicted_mass = { value = 10, tol = \"1%\" }\n", 1),
        ("predicted_mass = { max = 11.4 }\n", 1),
        (
            "predicted_center_of_mass.z = { value = 0, tol = 1e-12 }\n",
            0,
        ),
    ] {
        std::fs::write(&file, format!("{body}{expect}")).unwrap();
        let out = massprop(&["check", file.to_str().unwrap()]);
        assert_eq!(
            out.status.code(),
            Some(status),
            "{expect}{}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
}

/// `check --bless` writes the predicted values into the entries the file
/// already has, and adds none.
#[test]
fn bless_writes_the_predicted_values_the_file_expects() {
    let dir = scratch("budget", "bless");
    let file = dir.join("p.toml");
    let body = "[growth]\nestimated = \"15 %\"\n\n[[part]]\nshape = \"point\"\nmass = 10\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n\n[expect]\npredicted_mass = { value = 1, tol = \"0.0001%\" }\n";
    std::fs::write(&file, body).unwrap();
    let out = massprop(&["check", "--bless", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0));
    let blessed = std::fs::read_to_string(&file).unwrap();
    assert!(
        blessed.contains("predicted_mass = { value = 11.5"),
        "{blessed}"
    );
    assert!(!blessed.contains("predicted_center_of_mass"), "{blessed}");
}

/// `files` (name, text) written to the scratch directory `name`; the
/// last one's statement (JSON) and exit status.
fn statement_of(name: &str, files: &[(&str, &str)]) -> (Value, Option<i32>) {
    let dir = scratch("budget", name);
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    let (last, _) = files.last().expect("a file");
    json_of(&[
        "budget",
        dir.join(last).to_str().unwrap(),
        "--format",
        "json",
    ])
}

fn run_text(args: &[&str]) -> (String, String, Option<i32>) {
    let out = massprop(args);
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
        out.status.code(),
    )
}

/// hole.toml, by hand (SI): a plate, box 2 × 2 × 0.1 of 10 kg at the
/// origin, less a hole, box 1 × 1.6 × 0.1 of 4 kg centred at (0.5, 0, 0)
/// (the plate's density: 0.16 of its 0.4 m³), both `structure` at 10 %.
///
/// basic 10 − 4 = 6; growth 1 − 0.4 = 0.6; predicted 6.6. Centre of mass
/// x: basic (0 − 4 · 0.5)/6 = −1/3; predicted (−2 + 1 · 0 − 0.4 · 0.5)/6.6
/// = −2.2/6.6 = −1/3, the same: the net part grown by 10 % everywhere.
/// (A hole that did not grow would give −2/7.) Inertia about (−1/3, 0, 0):
/// each body's own (m (b² + c²)/12 and so on, the hole's negative) and
/// m d² for the x offsets d = 1/3 (plate and its growth) and 5/6 (hole and
/// its growth), the hole's terms negative.
#[test]
fn a_cut_out_grows_by_its_negative_mass() {
    let (v, status) = json_of(&[
        "budget",
        "tests/cmd/budget.in/hole.toml",
        "--format",
        "json",
    ]);
    assert_eq!(status, Some(0));
    let t = &v["total"];
    close(num(&t["basic_mass"]), 6.0, "basic");
    close(num(&t["growth_mass"]), 0.6, "growth");
    close(num(&t["predicted_mass"]), 6.6, "predicted");
    let g = group(&v, &["structure"]);
    assert_eq!(g["parts"], 2);
    close(num(&g["basic_mass"]), 6.0, "structure basic");
    close(num(&g["growth_mass"]), 0.6, "structure growth");
    assert_eq!(v["no_maturity"]["parts"], 0);
    close(num(&v["basic"]["center_of_mass"][0]), -1.0 / 3.0, "basic x");
    close(num(&v["predicted"]["center_of_mass"][0]), -1.0 / 3.0, "x");
    close(num(&v["predicted"]["center_of_mass"][1]), 0.0, "y");
    close(num(&v["predicted"]["center_of_mass"][2]), 0.0, "z");
    // (mass, own [Ixx, Iyy, Izz], x offset from the centre of mass).
    let box_own = |m: f64, [a, b, c]: [f64; 3]| {
        [
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ]
    };
    let bodies = [
        (10.0, box_own(10.0, [2.0, 2.0, 0.1]), 1.0 / 3.0),
        (-4.0, box_own(-4.0, [1.0, 1.6, 0.1]), 5.0 / 6.0),
        (1.0, [0.0; 3], 1.0 / 3.0),
        (-0.4, [0.0; 3], 5.0 / 6.0),
    ];
    for k in 0..3 {
        // An x offset adds m d² to Iyy and Izz, nothing to Ixx.
        let want: f64 = bodies
            .iter()
            .map(|(m, own, d)| own[k] + if k == 0 { 0.0 } else { m * d * d })
            .sum();
        let got = num(&v["predicted"]["inertia_com"][k][k]);
        assert!(
            (got - want).abs() <= 1e-12 * 10.0,
            "I[{k}][{k}]: {got} against {want}"
        );
    }
}

/// A hole grouped apart from its part: its group's basic mass and growth
/// are negative; a hole with no maturity counts in `no_maturity` by its
/// negative mass, with no growth.
#[test]
fn a_cut_out_counts_by_its_signed_mass_in_its_group_and_unclassified() {
    let text = std::fs::read_to_string("tests/cmd/budget.in/hole.toml").unwrap();
    let (head, hole) = text.split_at(text.rfind("[[part]]").unwrap());
    let dir = scratch("budget", "signed-cut-out");
    let apart = dir.join("apart.toml");
    std::fs::write(
        &apart,
        format!("{head}{}", hole.replace("\"structure\"", "\"holes\"")),
    )
    .unwrap();
    let (v, _) = json_of(&["budget", apart.to_str().unwrap(), "--format", "json"]);
    close(
        num(&group(&v, &["holes"])["basic_mass"]),
        -4.0,
        "holes basic",
    );
    close(
        num(&group(&v, &["holes"])["growth_mass"]),
        -0.4,
        "holes growth",
    );
    close(
        num(&group(&v, &["structure"])["basic_mass"]),
        10.0,
        "structure",
    );
    close(num(&v["total"]["predicted_mass"]), 6.6, "predicted");
    let bare = dir.join("bare.toml");
    std::fs::write(
        &bare,
        format!("{head}{}", hole.replace("maturity = \"calculated\"\n", "")),
    )
    .unwrap();
    let (v, _) = json_of(&["budget", bare.to_str().unwrap(), "--format", "json"]);
    assert_eq!(v["no_maturity"]["parts"], 1);
    close(num(&v["no_maturity"]["basic_mass"]), -4.0, "unclassified");
    // Only the plate grows: 1 kg at its centre, x = −2/7.
    close(num(&v["total"]["growth_mass"]), 1.0, "growth");
    close(num(&v["predicted"]["center_of_mass"][0]), -2.0 / 7.0, "x");
}

/// A file whose predicted mass is 10 kg + 50 % = 15 kg, with `[budget]`
/// at `limit` (line 5, column 9: `limit = ` is 8 characters).
fn limited(limit: &str, expect: &str) -> String {
    format!(
        "[growth]\nestimated = \"50 %\"\n\n[budget]\nlimit = {limit}\n\n[[part]]\nshape = \"point\"\nmass = 10\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n{expect}"
    )
}

/// `check` holds `[budget] limit` against the predicted mass, at the
/// `limit` entry, in every format; a limit met passes.
#[test]
fn check_fails_a_predicted_mass_above_the_budget_limit() {
    let dir = scratch("budget", "check-limit");
    let file = dir.join("p.toml");
    let path = file.to_str().unwrap();
    std::fs::write(&file, limited("\"1 kg\"", "")).unwrap();
    let (out, _, status) = run_text(&["check", path]);
    assert_eq!(status, Some(1), "{out}");
    let line = format!(
        "{path}:5:9: error: the predicted mass 15 kg exceeds `[budget] limit` 1 kg (by 14 kg)"
    );
    assert!(out.contains(&line), "{out}");
    let (v, status) = json_of(&["check", path, "--format", "json"]);
    assert_eq!(status, Some(1));
    let c = &v["files"][0]["checks"][0];
    assert_eq!(c["quantity"], "budget.limit");
    assert_eq!(
        (c["line"].as_u64(), c["column"].as_u64()),
        (Some(5), Some(9))
    );
    close(num(&c["measured"]), 15.0, "measured");
    close(num(&c["max"]), 1.0, "max");
    assert_eq!(c["pass"], false);
    let (gh, _, status) = run_text(&["check", path, "--format", "github"]);
    assert_eq!(status, Some(1));
    assert!(
        gh.contains(",line=5,col=9,") && gh.contains("budget.limit"),
        "{gh}"
    );
    let (xml, _, status) = run_text(&["check", path, "--format", "junit"]);
    assert_eq!(status, Some(1));
    assert!(
        xml.contains("type=\"budget-limit\"") && xml.contains(":5:9: error"),
        "{xml}"
    );
    let (sarif, _, status) = run_text(&["check", path, "--format", "sarif"]);
    assert_eq!(status, Some(1));
    let s: Value = serde_json::from_str(&sarif).unwrap();
    let r = &s["runs"][0]["results"][0];
    assert_eq!(r["ruleId"], "budget-limit");
    assert_eq!(
        r["locations"][0]["physicalLocation"]["region"]["startLine"],
        5
    );
    assert_eq!(
        r["locations"][0]["physicalLocation"]["region"]["startColumn"],
        9
    );
    // 15 kg against 15 kg and 20 kg: met.
    for limit in ["15", "\"20 kg\""] {
        std::fs::write(&file, limited(limit, "")).unwrap();
        let (out, _, status) = run_text(&["check", path]);
        assert_eq!(status, Some(0), "{limit}: {out}");
    }
}

/// `[expect] mass`'s `max` is the basic mass's in `check` (10 kg, under
/// 12), the predicted mass's limit in `budget` (15 kg, over 12).
#[test]
fn expect_mass_max_is_the_basic_mass_in_check_and_the_limit_in_budget() {
    let dir = scratch("budget", "expect-max");
    let file = dir.join("p.toml");
    let text = limited("\"100 kg\"", "\n[expect]\nmass = { max = 12 }\n")
        .replace("[budget]\nlimit = \"100 kg\"\n", "");
    std::fs::write(&file, text).unwrap();
    let path = file.to_str().unwrap();
    assert_eq!(run_text(&["check", path]).2, Some(0));
    let (v, status) = json_of(&["budget", path, "--format", "json"]);
    assert_eq!(status, Some(1));
    assert_eq!(v["limit"]["source"], "expect_mass_max");
}

/// `check --bless` writes nothing of the limit: the `[expect]` it adds has
/// the basic mass, and a limit not met still fails.
#[test]
fn bless_does_not_write_the_budget_limit() {
    let dir = scratch("budget", "bless-limit");
    let file = dir.join("p.toml");
    std::fs::write(&file, limited("\"1 kg\"", "")).unwrap();
    let out = massprop(&["check", "--bless", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let blessed = std::fs::read_to_string(&file).unwrap();
    assert!(
        blessed.contains("[budget]\nlimit = \"1 kg\"\n"),
        "{blessed}"
    );
    let expect = &blessed[blessed.find("[expect]").expect("an [expect] added")..];
    assert!(expect.contains("mass = { value = 10"), "{expect}");
    assert!(
        !expect.contains("predicted") && !expect.contains("15"),
        "{expect}"
    );
}

/// The predicted body's accuracy warnings reach standard error in the
/// table's run, as the basic body's do (statement.toml in f64 is within a
/// few ulps, not 3e-16).
#[test]
fn the_predicted_bodys_accuracy_warnings_reach_standard_error() {
    let (_, err, status) = run_text(&[
        "budget",
        STATEMENT,
        "--precision",
        "standard",
        "--rtol",
        "3e-16",
    ]);
    assert_eq!(status, Some(0));
    assert!(err.contains(": `mass` = "), "{err}");
    assert!(err.contains(": the predicted body's `mass` = "), "{err}");
}

/// An allowance of 1000 % is the largest: 1001 % is refused at its value.
#[test]
fn an_allowance_above_1000_percent_is_refused_where_it_is_written() {
    let dir = scratch("budget", "allowance");
    let file = dir.join("p.toml");
    let path = file.to_str().unwrap();
    std::fs::write(&file, limited("200", "").replace("50 %", "1000 %")).unwrap();
    let (v, status) = json_of(&["budget", path, "--format", "json"]);
    assert_eq!(status, Some(0));
    close(num(&v["total"]["predicted_mass"]), 110.0, "eleven times");
    std::fs::write(&file, limited("200", "").replace("50 %", "1001 %")).unwrap();
    let (_, err, status) = run_text(&["budget", path]);
    assert_eq!(status, Some(2));
    assert!(err.contains(":2:13: error: `growth.estimated` is \"1001 %\", above 1000 %: a growth that large is not an allowance"), "{err}");
}

/// A basic body that fits f64 and a growth that takes it past: the error
/// names the growth, and blames no part.
#[test]
fn a_predicted_body_that_overflows_names_the_growth() {
    let dir = scratch("budget", "overflow");
    let file = dir.join("p.toml");
    std::fs::write(
        &file,
        "[growth]\nestimated = \"100 %\"\n\n[[part]]\nname = \"big\"\nshape = \"point\"\nmass = 1.5e308\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    assert_eq!(run_text(&["report", path]).2, Some(0));
    let (_, err, status) = run_text(&["budget", path]);
    assert_eq!(status, Some(2));
    assert!(
        err.contains("of the predicted body overflows the range of f64 once its growth is added"),
        "{err}"
    );
    assert!(
        err.contains("the largest growth is `big`'s, 1.5e308 kg"),
        "{err}"
    );
    assert!(!err.contains("contributes the most"), "{err}");
}

/// `--only` of a file with a limit says why no limit is shown.
#[test]
fn only_says_the_limit_is_not_applied() {
    let args = ["budget", "tests/cmd/budget.in/stage.toml"];
    let (out, _, _) = run_text(&args);
    assert!(out.contains("limit: 8 kg ([budget] limit)"), "{out}");
    let (out, _, _) = run_text(&[args[0], args[1], "--only", "main tank"]);
    assert!(
        out.contains("limit: not applied with --only (it is the whole body's)\n"),
        "{out}"
    );
    let (out, _, _) = run_text(&["budget", "tests/cmd/budget.in/hole.toml"]);
    assert!(
        out.contains("limit: none given ([budget] limit)\n"),
        "{out}"
    );
}

/// Three levels: each parent is its own parts and its children, exactly
/// (masses and growths 1, 2, 4 and 0.5, 1, 2 kg: sums exact in binary).
#[test]
fn a_parent_group_is_its_own_parts_and_its_children() {
    let part = |mass: u32, group: &str| {
        format!(
            "[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = [0, 0, {mass}]\ngroup = \"{group}\"\nmaturity = \"half\"\n\n"
        )
    };
    let text = format!(
        "[growth]\nhalf = \"50 %\"\n\n{}{}{}{}",
        part(4, "a/b/c"),
        part(1, "a"),
        part(2, "a/b"),
        part(8, "d"),
    );
    let (v, _) = statement_of("three-levels", &[("p.toml", &text)]);
    let row = |path: &[&str]| {
        let g = group(&v, path);
        (
            g["parts"].as_u64().unwrap(),
            num(&g["basic_mass"]),
            num(&g["growth_mass"]),
        )
    };
    // NOTE: compared exactly: each sum is of small integers and halves.
    assert_eq!(row(&["a", "b", "c"]), (1, 4.0, 2.0));
    assert_eq!(row(&["a", "b"]), (2, 2.0 + 4.0, 1.0 + 2.0));
    assert_eq!(row(&["a"]), (3, 1.0 + 6.0, 0.5 + 3.0));
    assert_eq!(row(&["d"]), (1, 8.0, 4.0));
    let order: Vec<&Value> = v["groups"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| &g["path"])
        .collect();
    assert_eq!(
        order,
        [
            &serde_json::json!(["a"]),
            &serde_json::json!(["a", "b"]),
            &serde_json::json!(["a", "b", "c"]),
            &serde_json::json!(["d"]),
        ]
    );
}

/// Includes two deep, each with a `maturity`: a part with none takes the
/// innermost include's (`inner`, 10 %, from the middle file's `[growth]`),
/// a part's own wins over both (`own`, 1 %, its file's); the middle
/// file's own part takes the outer include's (`outer`, 20 %, the root's).
#[test]
fn the_innermost_include_maturity_wins_and_a_parts_own_over_both() {
    let (v, status) = statement_of(
        "nested",
        &[
            (
                "leaf.toml",
                "[growth]\nown = \"1 %\"\n\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\ngroup = \"default\"\n\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\ngroup = \"own\"\nmaturity = \"own\"\n",
            ),
            (
                "mid.toml",
                "[growth]\ninner = \"10 %\"\n\n[[part]]\nname = \"leaf\"\ninclude = \"leaf.toml\"\nmaturity = \"inner\"\n\n[[part]]\nshape = \"point\"\nmass = 4\ncenter = [0, 0, 0]\ngroup = \"mid\"\n",
            ),
            (
                "root.toml",
                "[growth]\nouter = \"20 %\"\n\n[[part]]\nname = \"mid\"\ninclude = \"mid.toml\"\nmaturity = \"outer\"\n",
            ),
        ],
    );
    assert_eq!(status, Some(0), "{v}");
    close(
        num(&group(&v, &["default"])["growth_mass"]),
        0.1,
        "innermost",
    );
    close(num(&group(&v, &["own"])["growth_mass"]), 0.02, "own");
    close(num(&group(&v, &["mid"])["growth_mass"]), 0.8, "outer");
    assert_eq!(v["no_maturity"]["parts"], 0);
}

/// An array of includes under a group: each copy's parts in it, with the
/// include's maturity: 3 × (1 kg + 2 kg) at 20 %.
#[test]
fn an_array_of_includes_carries_its_group() {
    let (v, status) = statement_of(
        "array-include",
        &[
            (
                "unit.toml",
                "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n\n[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 1]\ngroup = \"cells\"\n",
            ),
            (
                "root.toml",
                "[growth]\nestimated = \"20 %\"\n\n[[part]]\nname = \"unit\"\ninclude = \"unit.toml\"\ngroup = \"battery\"\nmaturity = \"estimated\"\narray = { count = 3, step = [1, 0, 0] }\n",
            ),
        ],
    );
    assert_eq!(status, Some(0), "{v}");
    let b = group(&v, &["battery"]);
    assert_eq!(b["parts"], 6);
    close(num(&b["basic_mass"]), 9.0, "battery");
    close(num(&b["growth_mass"]), 1.8, "battery growth");
    let c = group(&v, &["battery", "cells"]);
    assert_eq!(c["parts"], 3);
    close(num(&c["basic_mass"]), 6.0, "cells");
    close(num(&c["growth_mass"]), 1.2, "cells growth");
    // The copies at x = 0, 1, 2: the predicted centre x is 1.
    close(num(&v["predicted"]["center_of_mass"][0]), 1.0, "x");
}

/// A file in g and mm: the table in g (1000 g + 500 g at 10 %), the JSON
/// in kg.
#[test]
fn a_file_in_grams_shows_its_statement_in_grams() {
    let dir = scratch("budget", "grams");
    let file = dir.join("p.toml");
    std::fs::write(
        &file,
        "units = { mass = \"g\", length = \"mm\" }\n\n[growth]\nestimated = \"10 %\"\n\n[[part]]\nshape = \"point\"\nmass = 1000\ncenter = [0, 0, 0]\ngroup = \"a\"\nmaturity = \"estimated\"\n\n[[part]]\nshape = \"point\"\nmass = 500\ncenter = [30, 0, 0]\ngroup = \"a\"\nmaturity = \"estimated\"\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    let (out, _, status) = run_text(&["budget", path]);
    assert_eq!(status, Some(0));
    assert!(out.contains("weight statement (g)\n"), "{out}");
    let total: Vec<&str> = out
        .lines()
        .find(|l| l.contains(" total "))
        .unwrap()
        .split(['│', '┆'])
        .map(str::trim)
        .filter(|c| !c.is_empty())
        .collect();
    assert_eq!(
        total,
        ["total", "2", "1500", "150", "10 %", "1650", "100 %"],
        "{out}"
    );
    // Centre of mass x: 500 · 30 / 1500 = 10 mm, in mm.
    assert!(out.contains("centre of mass x (mm)"), "{out}");
    let (v, _) = json_of(&["budget", path, "--format", "json"]);
    close(num(&v["total"]["predicted_mass"]), 1.65, "kg");
    close(num(&v["predicted"]["center_of_mass"][0]), 0.01, "m");
}

/// A `[growth]` table after the parts that use it: the fast streaming
/// reader, whose parts have no `[growth]`, must leave the file to serde
/// (else `maturity` would be unknown here).
#[test]
fn a_growth_table_after_the_parts_is_read() {
    let (v, status) = statement_of(
        "growth-last",
        &[(
            "p.toml",
            "[[part]]\nshape = \"point\"\nmass = 2\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n\n[growth]\nestimated = \"25 %\"\n\n[budget]\nlimit = 3\n",
        )],
    );
    assert_eq!(status, Some(0), "{v}");
    close(num(&v["total"]["predicted_mass"]), 2.5, "predicted");
}
