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
