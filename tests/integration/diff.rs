//! `massprop diff`: quantities against hand derivations (point masses and
//! the bent plate, whose parts' centroids are known), part matching, the
//! tolerance, the relative-change rule, the JSON contract and the errors.

use crate::common::{massprop, massprop_stdin};
use serde_json::Value;
use std::path::PathBuf;

const BENT_PLATE: &str = "shapes/bent-plate.toml";
const EPS: f64 = f64::EPSILON;

/// Write `files` into a fresh directory for one test; returns their paths.
fn files(test: &str, files: &[(&str, &str)]) -> Vec<String> {
    let dir: PathBuf =
        std::env::temp_dir().join(format!("massprop-diff-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("the temporary directory can be created");
    files
        .iter()
        .map(|(name, text)| {
            let path = dir.join(name);
            std::fs::write(&path, text).expect("the test file can be written");
            path.to_str().expect("a UTF-8 path").to_string()
        })
        .collect()
}

/// A TOML point mass.
fn point(name: Option<&str>, mass: f64, center: [f64; 3]) -> String {
    let name = name.map_or(String::new(), |n| format!("name = \"{n}\"\n"));
    format!(
        "[[part]]\n{name}shape = \"point\"\nmass = {mass:?}\ncenter = [{:?}, {:?}, {:?}]\n\n",
        center[0], center[1], center[2]
    )
}

/// Two 1 kg points at x = ±1 m: mass 2 kg, centre of mass at the origin,
/// C = diag(2, 0, 0) so I = diag(0, 2, 2) kg·m², size √(tr C / m) = 1 m.
fn pair() -> String {
    point(Some("a"), 1.0, [1.0, 0.0, 0.0]) + &point(Some("b"), 1.0, [-1.0, 0.0, 0.0])
}

/// Run `massprop diff OLD NEW --format json …`: status and parsed stdout.
fn diff_json(old: &str, new: &str, extra: &[&str]) -> (i32, Value) {
    let mut args = vec!["diff", old, new, "--format", "json"];
    args.extend(extra);
    let out = massprop(&args);
    let status = out.status.code().expect("massprop exits");
    assert!(
        status == 0 || status == 1,
        "status {status}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8 output");
    assert_eq!(text.lines().count(), 1, "one JSON line and nothing else");
    (
        status,
        serde_json::from_str(&text).expect("stdout is one JSON document"),
    )
}

/// The quantity object named `name`.
fn q<'a>(v: &'a Value, name: &str) -> &'a Value {
    v["quantities"]
        .as_array()
        .expect("`quantities` is an array")
        .iter()
        .find(|q| q["quantity"] == name)
        .unwrap_or_else(|| panic!("no quantity {name}"))
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: {got} vs {want} (tolerance {tol})"
    );
}

fn names(v: &Value) -> Vec<&str> {
    v.as_array()
        .expect("an array of names")
        .iter()
        .map(|n| n.as_str().expect("a name"))
        .collect()
}

const QUANTITIES: [&str; 13] = [
    "mass",
    "center_of_mass.x",
    "center_of_mass.y",
    "center_of_mass.z",
    "principal_moments.1",
    "principal_moments.2",
    "principal_moments.3",
    "inertia_com.xx",
    "inertia_com.yy",
    "inertia_com.zz",
    "inertia_com.xy",
    "inertia_com.xz",
    "inertia_com.yz",
];

#[test]
fn identical_files_exit_zero_with_nothing_changed() {
    let (status, v) = diff_json(BENT_PLATE, BENT_PLATE, &[]);
    assert_eq!(status, 0);
    assert_eq!(v["changed"], false);
    for name in QUANTITIES {
        let x = q(&v, name);
        assert_eq!(x["old"], x["new"], "{name}");
        assert_eq!(num(&x["abs_change"]), 0.0, "{name}");
        assert_eq!(x["changed"], false, "{name}");
    }
    assert_eq!(v["parts"]["added"], Value::Array(vec![]));
    assert_eq!(v["parts"]["removed"], Value::Array(vec![]));
    assert_eq!(v["parts"]["changed"], Value::Array(vec![]));
    let out = massprop(&["diff", BENT_PLATE, BENT_PLATE]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("result: no change beyond the tolerance"),
        "{text}"
    );
    assert!(
        text.contains("parts: none added, removed or changed"),
        "{text}"
    );
}

#[test]
fn adding_a_point_mass_changes_the_mass_by_one_and_moves_the_centre_of_mass() {
    // Bent plate (docs/part-file.md): plate A, 0.875 kg, centroid
    // (0, 62.5, 50) mm; plate B, 0.7875 kg, centroid (37.5, 125, 75) mm.
    // Add C, 1 kg at (100, 0, 0) mm.
    let text = std::fs::read_to_string(BENT_PLATE).unwrap();
    let with_c = text.replace(
        "[analysis]",
        "[[part]]\nname = \"C\"\nshape = \"point\"\nmass = 1\ncenter = [100, 0, 0]\n\n[analysis]",
    );
    assert_ne!(with_c, text, "the part was inserted");
    let paths = files("add-point", &[("new.toml", &with_c)]);
    let (status, v) = diff_json(BENT_PLATE, &paths[0], &[]);
    assert_eq!(status, 1);
    assert_eq!(v["changed"], true);

    let (ma, mb) = (0.875, 0.7875);
    let (ca, cb) = ([0.0, 0.0625, 0.05], [0.0375, 0.125, 0.075]);
    let m_old = ma + mb;
    let old_com: [f64; 3] = std::array::from_fn(|i| (ma * ca[i] + mb * cb[i]) / m_old);
    let c = [0.1, 0.0, 0.0];
    let new_com: [f64; 3] =
        std::array::from_fn(|i| (ma * ca[i] + mb * cb[i] + c[i]) / (m_old + 1.0));

    let mass = q(&v, "mass");
    close(num(&mass["old"]), m_old, 4.0 * EPS, "old mass");
    close(num(&mass["abs_change"]), 1.0, 4.0 * EPS, "mass change");
    close(
        num(&mass["rel_change"]),
        1.0 / m_old,
        4.0 * EPS,
        "relative mass change",
    );
    assert_eq!(mass["changed"], true);
    for (i, axis) in ["x", "y", "z"].iter().enumerate() {
        let x = q(&v, &format!("center_of_mass.{axis}"));
        close(num(&x["old"]), old_com[i], 1e-16, "old centre of mass");
        close(num(&x["new"]), new_com[i], 1e-16, "new centre of mass");
        close(
            num(&x["abs_change"]),
            new_com[i] - old_com[i],
            1e-16,
            "change of the centre of mass",
        );
        assert_eq!(x["changed"], true, "{axis}");
    }
    assert_eq!(names(&v["parts"]["added"]), ["C"]);
    assert!(names(&v["parts"]["removed"]).is_empty());
    assert_eq!(v["parts"]["changed"], Value::Array(vec![]));
}

#[test]
fn relative_changes_use_the_scale_of_the_whole_quantity() {
    // Add c, 1 kg at (0, 3, 0) m, to the pair: mass 3 kg, centre of mass
    // (0, 1, 0); offsets (1, −1, 0), (−1, −1, 0), (0, 2, 0) give
    // C = diag(2, 6, 0), I = diag(6, 2, 8), principal moments [2, 6, 8].
    // Old: I = diag(0, 2, 2), moments [0, 2, 2], both of norm √8; size 1 m.
    let new = pair() + &point(Some("c"), 1.0, [0.0, 3.0, 0.0]);
    let paths = files("whole-scale", &[("old.toml", &pair()), ("new.toml", &new)]);
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 1);
    let r8 = 8f64.sqrt();
    for (name, old, new, rel) in [
        ("mass", 2.0, 3.0, 0.5),
        // Centre of mass at the origin: its scale is the body's size, 1 m.
        ("center_of_mass.y", 0.0, 1.0, 1.0),
        ("principal_moments.1", 0.0, 2.0, 2.0 / r8),
        ("principal_moments.2", 2.0, 6.0, 4.0 / r8),
        ("principal_moments.3", 2.0, 8.0, 6.0 / r8),
        ("inertia_com.xx", 0.0, 6.0, 6.0 / r8),
        ("inertia_com.yy", 2.0, 2.0, 0.0),
        ("inertia_com.zz", 2.0, 8.0, 6.0 / r8),
        ("inertia_com.xy", 0.0, 0.0, 0.0),
    ] {
        let x = q(&v, name);
        close(num(&x["old"]), old, 8.0 * EPS, name);
        close(num(&x["new"]), new, 8.0 * EPS, name);
        close(num(&x["abs_change"]), new - old, 8.0 * EPS, name);
        close(num(&x["rel_change"]), rel, 8.0 * EPS, name);
        assert_eq!(x["changed"], rel != 0.0, "{name}");
    }
    assert_eq!(names(&v["parts"]["added"]), ["c"]);
}

#[test]
fn the_old_scale_falls_back_to_the_new_one_when_zero() {
    // A 1 kg point at the origin has zero inertia; a 1 kg unit cube there
    // has I = diag(1, 1, 1)/6, of norm √3/6: each moment changes by 1/√3 of it.
    let old = point(Some("p"), 1.0, [0.0; 3]);
    let new =
        "[[part]]\nname = \"p\"\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";
    let paths = files("fallback", &[("old.toml", &old), ("new.toml", new)]);
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 1);
    let third = 1.0 / 3f64.sqrt();
    for name in ["inertia_com.xx", "inertia_com.zz", "principal_moments.3"] {
        close(num(&q(&v, name)["rel_change"]), third, 4.0 * EPS, name);
        assert_eq!(q(&v, name)["changed"], true);
    }
    // Same mass and centroid, another shape: shape and second moment changed.
    let changed = &v["parts"]["changed"][0];
    assert_eq!(changed["name"], "p");
    assert_eq!(names(&changed["what"]), ["shape", "second_moment"]);
}

#[test]
fn rel_change_is_null_only_for_a_quantity_zero_in_both_files() {
    // One point mass at the origin, 1 kg then 2 kg: no inertia, and the
    // centre of mass is at the origin in a body of size zero.
    let paths = files(
        "null",
        &[
            ("old.toml", &point(None, 1.0, [0.0; 3])),
            ("new.toml", &point(None, 2.0, [0.0; 3])),
        ],
    );
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 1);
    close(num(&q(&v, "mass")["rel_change"]), 1.0, 0.0, "mass");
    for name in &QUANTITIES[1..] {
        let x = q(&v, name);
        assert!(x["rel_change"].is_null(), "{name}: {x}");
        assert_eq!(x["changed"], false, "{name}");
    }
    let changed = &v["parts"]["changed"][0];
    assert_eq!(changed["name"], "part 1");
    assert_eq!(names(&changed["what"]), ["mass"]);
}

#[test]
fn a_centre_of_mass_near_the_origin_is_compared_at_the_bodys_scale() {
    // Centre of mass at the origin up to the last bit of one coordinate,
    // and the parts reordered. Relative to the distance of the centre of
    // mass from the origin, moving `c` by one ulp is a change of over 100 %;
    // relative to the body's size it is ~1e-16, no change at all.
    let (a, b, c) = (
        point(Some("a"), 1.0, [0.1, 0.0, 0.0]),
        point(Some("b"), 1.0, [0.2, 0.0, 0.0]),
        point(Some("c"), 1.0, [-0.3, 0.0, 0.0]),
    );
    let c_ulp = point(Some("c"), 1.0, [-0.30000000000000004, 0.0, 0.0]);
    let paths = files(
        "near-origin",
        &[
            ("old.toml", &format!("{a}{b}{c}")),
            ("new.toml", &format!("{a}{c_ulp}{b}")),
        ],
    );
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    let x = q(&v, "center_of_mass.x");
    let (old, new) = (num(&x["old"]), num(&x["new"]));
    assert!(
        (old - new).abs() > old.abs().max(new.abs()),
        "the change is large relative to the centre's distance: the case is a test ({old:e} vs {new:e})"
    );
    assert!(old.abs() < 1e-16 && new.abs() < 1e-16);
    assert_eq!(status, 0, "{v}");
    assert_eq!(v["changed"], false);
}

#[test]
fn the_tolerance_decides_whether_a_small_change_counts() {
    // a 1 g heavier: 1e-3 of a's mass, 5e-4 of the total.
    let heavier =
        point(Some("a"), 1.001, [1.0, 0.0, 0.0]) + &point(Some("b"), 1.0, [-1.0, 0.0, 0.0]);
    // a 1 ng heavier: 1e-12 of a's mass.
    let tiny = point(Some("a"), 1.000000000001, [1.0, 0.0, 0.0])
        + &point(Some("b"), 1.0, [-1.0, 0.0, 0.0]);
    let paths = files(
        "tolerance",
        &[
            ("old.toml", &pair()),
            ("heavier.toml", &heavier),
            ("tiny.toml", &tiny),
        ],
    );
    let status = |new: &str, tol: &[&str]| {
        let mut args = vec!["diff", paths[0].as_str(), new];
        args.extend(tol);
        let out = massprop(&args);
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        out.status.code()
    };
    assert_eq!(status(&paths[1], &[]), Some(1));
    assert_eq!(status(&paths[1], &["--tol", "1e-4"]), Some(1));
    assert_eq!(status(&paths[1], &["--tol", "1e-2"]), Some(0));
    assert_eq!(status(&paths[2], &[]), Some(0));
    assert_eq!(status(&paths[2], &["--tol", "1e-14"]), Some(1));
    assert_eq!(status(&paths[0], &["--tol", "0"]), Some(0));

    let (_, v) = diff_json(&paths[0], &paths[1], &["--tol", "1e-4"]);
    assert_eq!(num(&v["tolerance"]), 1e-4);
    assert_eq!(q(&v, "mass")["changed"], true);
    let changed = &v["parts"]["changed"][0];
    assert_eq!(changed["name"], "a");
    assert_eq!(names(&changed["what"]), ["mass"]);
}

#[test]
fn renaming_a_part_is_one_removed_and_one_added() {
    let renamed =
        point(Some("a"), 1.0, [1.0, 0.0, 0.0]) + &point(Some("bee"), 1.0, [-1.0, 0.0, 0.0]);
    let paths = files("rename", &[("old.toml", &pair()), ("new.toml", &renamed)]);
    // No mass property moved: reported, exit 0; `--names` fails on it.
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 0);
    assert_eq!(v["changed"], false);
    assert_eq!(diff_json(&paths[0], &paths[1], &["--names"]).0, 1);
    assert_eq!(names(&v["parts"]["removed"]), ["b"]);
    assert_eq!(names(&v["parts"]["added"]), ["bee"]);
    assert_eq!(v["parts"]["changed"], Value::Array(vec![]));
    for name in QUANTITIES {
        assert_eq!(q(&v, name)["changed"], false, "{name}");
    }
}

#[test]
fn unnamed_parts_match_by_position() {
    // Swapping two unnamed parts swaps `part 1` and `part 2`: both changed,
    // the body (a sum of two terms either way) not.
    let (p, r) = (
        point(None, 1.0, [1.0, 0.0, 0.0]),
        point(None, 2.0, [-1.0, 0.0, 0.0]),
    );
    let paths = files(
        "unnamed",
        &[
            ("old.toml", &format!("{p}{r}")),
            ("new.toml", &format!("{r}{p}")),
        ],
    );
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 0);
    assert_eq!(diff_json(&paths[0], &paths[1], &["--names"]).0, 1);
    for name in QUANTITIES {
        assert_eq!(q(&v, name)["changed"], false, "{name}");
    }
    let changed = v["parts"]["changed"].as_array().unwrap();
    assert_eq!(changed.len(), 2);
    for (c, name) in changed.iter().zip(["part 1", "part 2"]) {
        assert_eq!(c["name"], name);
        assert_eq!(names(&c["what"]), ["mass", "centroid"]);
    }
}

#[test]
fn duplicate_names_match_in_order_of_appearance() {
    let bolt = |x: f64| point(Some("bolt"), 1.0, [x, 0.0, 0.0]);
    let paths = files(
        "duplicates",
        &[
            ("two.toml", &(bolt(1.0) + &bolt(2.0))),
            ("three.toml", &(bolt(1.0) + &bolt(2.0) + &bolt(3.0))),
            ("second.toml", &bolt(2.0)),
        ],
    );
    // A third bolt: the first two match the first two.
    let (_, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(names(&v["parts"]["added"]), ["bolt"]);
    assert!(names(&v["parts"]["removed"]).is_empty());
    assert_eq!(v["parts"]["changed"], Value::Array(vec![]));
    // Only the second bolt left: it matches the first, which moved, and
    // the second is removed.
    let (_, v) = diff_json(&paths[0], &paths[2], &[]);
    assert_eq!(names(&v["parts"]["removed"]), ["bolt"]);
    assert!(names(&v["parts"]["added"]).is_empty());
    let changed = &v["parts"]["changed"][0];
    assert_eq!(changed["name"], "bolt");
    assert_eq!(names(&changed["what"]), ["centroid"]);
    // The table numbers a name used more than once.
    let out = massprop(&["diff", &paths[0], &paths[2]]);
    let text = String::from_utf8(out.stdout).unwrap();
    let row = |name: &str| text.lines().find(|l| l.contains(name)).unwrap_or("");
    assert!(row("bolt (#1)").contains("centroid moved 1 m"), "{text}");
    assert!(row("bolt (#2)").contains("removed"), "{text}");
}

#[test]
fn turning_a_part_changes_its_second_moment_only() {
    // A 1 × 2 × 3 box turned a quarter about z: same mass and centroid;
    // Ixx and Iyy swap (m(b² + c²)/12 = 13/12 and m(a² + c²)/12 = 10/12).
    let boxed = |rotation: &str| {
        format!(
            "[[part]]\nname = \"block\"\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n{rotation}"
        )
    };
    let paths = files(
        "turned",
        &[
            ("old.toml", &boxed("")),
            (
                "new.toml",
                &boxed("rotation = { axis = [0, 0, 1], degrees = 90 }\n"),
            ),
        ],
    );
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 1);
    let changed = &v["parts"]["changed"][0];
    assert_eq!(changed["name"], "block");
    assert_eq!(names(&changed["what"]), ["second_moment"]);
    close(
        num(&q(&v, "inertia_com.xx")["old"]),
        13.0 / 12.0,
        4.0 * EPS,
        "Ixx",
    );
    close(
        num(&q(&v, "inertia_com.xx")["new"]),
        10.0 / 12.0,
        4.0 * EPS,
        "Ixx",
    );
    assert_eq!(q(&v, "inertia_com.xx")["changed"], true);
    // Principal moments do not depend on orientation.
    for i in 1..=3 {
        assert_eq!(q(&v, &format!("principal_moments.{i}"))["changed"], false);
    }
    assert_eq!(q(&v, "mass")["changed"], false);
}

#[test]
fn json_carries_every_documented_key() {
    let paths = files(
        "keys",
        &[
            ("old.toml", &pair()),
            (
                "new.toml",
                &(pair() + &point(Some("c"), 1.0, [0.0, 3.0, 0.0])),
            ),
        ],
    );
    let (_, v) = diff_json(&paths[0], &paths[1], &["--tol", "1e-6"]);
    assert_eq!(v["format_version"], 1);
    assert_eq!(v["old"], paths[0].as_str());
    assert_eq!(v["new"], paths[1].as_str());
    assert_eq!(v["products_convention"], "tensor");
    assert_eq!(v["units"]["mass"], "kg");
    assert_eq!(v["units"]["length"], "m");
    assert_eq!(v["units"]["inertia"], "kg*m^2");
    assert_eq!(num(&v["tolerance"]), 1e-6);
    assert!(v["changed"].is_boolean());
    let got: Vec<&str> = v["quantities"]
        .as_array()
        .unwrap()
        .iter()
        .map(|q| q["quantity"].as_str().unwrap())
        .collect();
    // Then the turn of each principal axis both bodies determine.
    assert_eq!(got[..QUANTITIES.len()], QUANTITIES);
    assert!(
        got[QUANTITIES.len()..]
            .iter()
            .all(|q| q.starts_with("principal_axes.")),
        "{got:?}"
    );
    for x in v["quantities"].as_array().unwrap() {
        for key in ["old", "new", "abs_change"] {
            assert!(x[key].is_number(), "{key} in {x}");
        }
        assert!(
            x["rel_change"].is_number() || x["rel_change"].is_null(),
            "{x}"
        );
        assert!(x["changed"].is_boolean());
        assert_eq!(
            x.as_object().unwrap().len(),
            6,
            "no undocumented key in {x}"
        );
    }
    let parts = v["parts"].as_object().unwrap();
    assert_eq!(parts.len(), 3);
    for key in ["added", "removed", "changed"] {
        assert!(parts[key].is_array(), "{key}");
    }
}

#[test]
fn the_table_is_in_the_new_files_units() {
    // The pair in metres, then in millimetres with c at y = 3000 mm: the
    // centre of mass moves from 0 to 1000 mm, 100 % of the 1 m size.
    let new_mm = "units = { length = \"mm\", mass = \"kg\" }\n".to_string()
        + &point(Some("a"), 1.0, [1000.0, 0.0, 0.0])
        + &point(Some("b"), 1.0, [-1000.0, 0.0, 0.0])
        + &point(Some("c"), 1.0, [0.0, 3000.0, 0.0]);
    let paths = files("table", &[("old.toml", &pair()), ("new.toml", &new_mm)]);
    let out = massprop(&["diff", &paths[0], &paths[1]]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("units (the new file's): mass kg, length mm, inertia kg·mm²"),
        "{text}"
    );
    assert!(text.contains("tensor convention, Ixy = −∫xy dm"), "{text}");
    let row = |label: &str| -> Vec<String> {
        let line = text
            .lines()
            .find(|l| l.contains(label))
            .unwrap_or_else(|| panic!("no row {label} in\n{text}"));
        line.trim_matches('│')
            .split('┆')
            .map(|c| c.trim().to_string())
            .collect()
    };
    assert_eq!(
        row("centre of mass y"),
        [
            "centre of mass y",
            "0",
            "1000",
            "1000",
            "100 %",
            "mm",
            "changed"
        ]
    );
    // I_zz from 2 to 8 kg·m² = 2e6 to 8e6 kg·mm², 6/√8 = 212.132 %.
    assert_eq!(
        row("Izz"),
        ["Izz", "2e6", "8e6", "6e6", "212.132 %", "kg·mm²", "changed"]
    );
    assert_eq!(row("Iyy"), ["Iyy", "2e6", "2e6", "0", "0 %", "kg·mm²", ""]);
    assert!(text.contains("point, 1 kg at (0, 3000, 0) mm"), "{text}");
    assert!(
        text.ends_with("result: changed beyond the tolerance\n"),
        "{text}"
    );
}

#[test]
fn standard_input_can_be_either_file() {
    let text = std::fs::read_to_string(BENT_PLATE).unwrap();
    for args in [
        ["diff", "-", BENT_PLATE, "--format", "json"],
        ["diff", BENT_PLATE, "-", "--format", "json"],
    ] {
        let out = massprop_stdin(&args, &text);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert!(v["old"] == "<stdin>" || v["new"] == "<stdin>", "{v}");
    }
}

#[test]
fn errors_exit_two_with_nothing_on_stdout() {
    let far = |x: &str| format!("[[part]]\nshape = \"point\"\nmass = 1\ncenter = [{x}, 0, 0]\n");
    let paths = files(
        "errors",
        &[
            ("syntax.toml", "[[part]\nshape = \"point\"\n"),
            ("minus.toml", &far("-1e308")),
            ("plus.toml", &far("1e308")),
        ],
    );
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["does-not-exist.toml", BENT_PLATE],
            "does-not-exist.toml: error: cannot read file",
        ),
        (vec![BENT_PLATE, &paths[0]], "syntax.toml:1:"),
        (
            vec![BENT_PLATE, "tests/cmd/bad-input.in/summary-overflow.toml"],
            "summary-overflow.toml:7:9: error: the inertia about the reference point",
        ),
        (
            vec![
                "tests/cmd/bad-input.in/alpha-without-omega.toml",
                BENT_PLATE,
            ],
            "alpha-without-omega.toml:7:9: error: `alpha` needs `omega`",
        ),
        (vec!["-", "-"], "cannot both be `-`"),
        (vec![BENT_PLATE, BENT_PLATE, "--tol=-1"], "`--tol`"),
        (vec![BENT_PLATE, BENT_PLATE, "--tol", "inf"], "`--tol`"),
        (vec![BENT_PLATE, BENT_PLATE, "--tol", "NaN"], "`--tol`"),
        // −1e308 to 1e308: a change of 2e308 m is beyond f64.
        (
            vec![&paths[1], &paths[2]],
            "the change in `center_of_mass.x` overflows",
        ),
    ];
    for (files, message) in cases {
        for format in ["table", "json"] {
            let mut args = vec!["diff"];
            args.extend(&files);
            args.extend(["--format", format]);
            let out = massprop(&args);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
            assert!(out.stdout.is_empty(), "{args:?} printed on stdout");
            assert!(stderr.contains(message), "{args:?}: {stderr}");
        }
    }
}

/// Each file is compared in its own report axes (`[analysis] axes`): the
/// same body in SAE vehicle axes (y and z of an ISO file negated) has the
/// same mass, centre (a point, in the file's frame) and principal moments,
/// I_xx, I_yy, I_zz and I_yz (two signs flip), and I_xy, I_xz negated.
#[test]
fn each_file_is_compared_in_its_own_report_axes() {
    let body = "[[part]]\nshape = \"box\"\nmass = 4\nsize = [1, 2, 3]\ncenter = [1, 2, 3]\n\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [-1, 0.5, 2]\n";
    let sae = format!("{body}\n[analysis]\naxes = {{ x = [1, 0, 0], y = [0, -1, 0] }}\n");
    let paths = files("axes", &[("iso.toml", body), ("sae.toml", &sae)]);
    let (status, v) = diff_json(&paths[0], &paths[1], &[]);
    assert_eq!(status, 1, "the products of inertia changed sign");
    for same in [
        "mass",
        "center_of_mass.x",
        "center_of_mass.y",
        "center_of_mass.z",
        "principal_moments.1",
        "principal_moments.2",
        "principal_moments.3",
        "inertia_com.xx",
        "inertia_com.yy",
        "inertia_com.zz",
        "inertia_com.yz",
    ] {
        assert_eq!(q(&v, same)["old"], q(&v, same)["new"], "{same}");
    }
    for flipped in ["inertia_com.xy", "inertia_com.xz"] {
        let (old, new) = (num(&q(&v, flipped)["old"]), num(&q(&v, flipped)["new"]));
        assert!(old != 0.0, "{flipped} is not zero");
        assert_eq!(new, -old, "{flipped}");
    }
}
