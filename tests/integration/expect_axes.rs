//! `[expect] principal_axes`: axes compared by angle, an axis and its
//! negative alike, only the axes the principal moments determine; `--bless`
//! writes them, `diff` shows how far each turned.
//!
//! The bodies, by hand: a 12 kg box 1 × 2 × 3 m has I = m/12 (b² + c²,
//! a² + c², a² + b²) = (13, 10, 5) kg·m² about its own x, y, z, so its
//! principal axes in ascending order are its z, y, x. Turned θ about the
//! file's z, its y is (−sin θ, cos θ, 0) and its x (cos θ, sin θ, 0). A
//! cylinder's two moments across its axis are equal (m (3r² + l²)/12), so
//! only its axis, that of the smallest moment m r²/2 for a long one, is
//! determined; a sphere's three are equal.

use crate::common::massprop;
use proptest::prelude::*;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    crate::common::scratch("expect_axes", name)
}

/// The box turned `theta` degrees about z.
fn turned_box(theta: f64) -> String {
    format!(
        "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\nrotation = {{ axis = [0, 0, 1], degrees = {theta:?} }}\n"
    )
}

/// The box's axes by hand, each row multiplied by its sign.
fn box_axes(theta: f64, signs: [f64; 3]) -> [[f64; 3]; 3] {
    let (s, c) = theta.to_radians().sin_cos();
    let rows = [[0.0, 0.0, 1.0], [-s, c, 0.0], [c, s, 0.0]];
    std::array::from_fn(|k| rows[k].map(|x| x * signs[k]))
}

fn entry(rows: &[[f64; 3]; 3], tol_degrees: f64) -> String {
    let row = |r: &[f64; 3]| format!("[{:?}, {:?}, {:?}]", r[0], r[1], r[2]);
    format!(
        "\n[expect]\nprincipal_axes = {{ value = [{}, {}, {}], tol_degrees = {tol_degrees:?} }}\n",
        row(&rows[0]),
        row(&rows[1]),
        row(&rows[2])
    )
}

fn write(dir: &Path, file: &str, text: &str) -> String {
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// `check --format json` of one file: its exit status and its one check.
fn check_json(path: &str) -> (i32, Value) {
    let out = massprop(&["check", "--format", "json", path]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("stdout is JSON");
    let c = v["files"][0]["checks"][0].clone();
    (out.status.code().expect("exit status"), c)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// Whatever the turn and whichever rows are negated.
    #[test]
    fn a_turned_box_passes_its_hand_derived_axes_in_either_sign(
        theta in -179.0f64..179.0,
        signs in prop::array::uniform3(prop::bool::ANY),
    ) {
        let dir = scratch(&format!("pass-{}", theta.to_bits()));
        let signs = signs.map(|s| if s { -1.0 } else { 1.0 });
        let p = write(&dir, "box.toml", &(turned_box(theta) + &entry(&box_axes(theta, signs), 1e-6)));
        let (status, c) = check_json(&p);
        prop_assert_eq!(status, 0, "{}", c);
        prop_assert_eq!(&c["compared_axes"], &serde_json::json!([1, 2, 3]));
    }

    /// Axes turned δ past the body's fail above δ and pass within it, and
    /// the angle measured is δ.
    #[test]
    fn axes_turned_by_an_angle_fail_by_that_angle(
        theta in -90.0f64..90.0,
        delta in 0.05f64..20.0,
    ) {
        let dir = scratch(&format!("turn-{}-{}", theta.to_bits(), delta.to_bits()));
        let expected = box_axes(theta + delta, [1.0; 3]);
        let body = turned_box(theta);
        let fails = write(&dir, "fails.toml", &(body.clone() + &entry(&expected, delta * 0.99)));
        let (status, c) = check_json(&fails);
        prop_assert_eq!(status, 1);
        let measured = c["measured"].as_f64().unwrap();
        prop_assert!((measured - delta.to_radians()).abs() < 1e-9, "{} vs {}", measured, delta);
        let passes = write(&dir, "passes.toml", &(body + &entry(&expected, delta * 1.01)));
        prop_assert_eq!(check_json(&passes).0, 0);
    }
}

#[test]
fn a_failure_names_the_place_the_axis_and_its_angle() {
    let dir = scratch("message");
    let p = write(
        &dir,
        "box.toml",
        &(turned_box(30.0) + &entry(&box_axes(32.0, [1.0; 3]), 0.5)),
    );
    let out = massprop(&["check", &p]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    // Line 9 (after a blank line), the entry's value after `principal_axes = `.
    assert!(
        stdout.contains(&format!(
            "{p}:9:18: error: principal_axes axis 2 is 2° from the expected axis, beyond `tol_degrees` 0.5°"
        )),
        "{stdout}"
    );
}

/// A cylinder along z turned 40° about x: its axis (0, −sin 40°, cos 40°).
fn turned_rod() -> String {
    "[[part]]\nshape = \"cylinder\"\nmass = 2\nradius = 0.01\nlength = 1\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 40 }\n".to_string()
}

#[test]
fn equal_moments_leave_only_the_distinct_axis_compared() {
    let dir = scratch("rod");
    let (s, c) = 40f64.to_radians().sin_cos();
    // The other two rows any pair at right angles to the axis: here the
    // file's x and a turn of the axis's plane by 90°.
    let rows = [[0.0, -s, c], [1.0, 0.0, 0.0], [0.0, c, s]];
    let p = write(&dir, "rod.toml", &(turned_rod() + &entry(&rows, 1e-6)));
    let (status, check) = check_json(&p);
    assert_eq!(status, 0, "{check}");
    assert_eq!(check["compared_axes"], serde_json::json!([1]));
    let rows = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let p = write(&dir, "wrong.toml", &(turned_rod() + &entry(&rows, 1.0)));
    let out = massprop(&["check", &p]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("principal_axes axis 1 is 40° from the expected axis, beyond `tol_degrees` 1°; principal moments 2 and 3 are equal within their error bounds, so only axis 1 is compared"),
        "{stdout}"
    );
}

#[test]
fn a_body_of_three_equal_moments_passes_any_axes() {
    let dir = scratch("sphere");
    let (s, c) = 0.3f64.sin_cos();
    let rows = [[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, -1.0]];
    let p = write(
        &dir,
        "sphere.toml",
        &("[[part]]\nshape = \"sphere\"\nmass = 3\nradius = 0.2\ncenter = [1, 2, 3]\n".to_string()
            + &entry(&rows, 0.0)),
    );
    let (status, check) = check_json(&p);
    assert_eq!(status, 0, "{check}");
    assert_eq!(check["compared_axes"], serde_json::json!([]));
    assert_eq!(check["measured"], serde_json::json!(0.0));
}

/// The rows of `principal_axes`'s `value` in a blessed file.
fn blessed_rows(text: &str) -> (Vec<Vec<f64>>, f64) {
    let doc: toml::Table = text.parse().unwrap();
    let e = &doc["expect"]["principal_axes"];
    let rows = e["value"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_float().unwrap())
                .collect()
        })
        .collect();
    (rows, e["tol_degrees"].as_float().unwrap())
}

#[test]
fn bless_writes_the_computed_axes_and_keeps_tol_degrees() {
    let dir = scratch("bless");
    let p = write(
        &dir,
        "box.toml",
        &(turned_box(20.0) + &entry(&box_axes(35.0, [1.0; 3]), 0.25)),
    );
    assert_eq!(massprop(&["check", &p]).status.code(), Some(1));
    assert_eq!(massprop(&["check", "--bless", &p]).status.code(), Some(0));
    let (rows, tol) = blessed_rows(&std::fs::read_to_string(&p).unwrap());
    assert_eq!(tol, 0.25);
    let want = box_axes(20.0, [1.0; 3]);
    for (row, want) in rows.iter().zip(want) {
        // The same axis, whichever sign the sign rule gave it, to within a
        // thousandth of the tolerance (the digits `--bless` writes): the
        // sine of the angle between them, |row × want| / |row|.
        let cross = [
            row[1] * want[2] - row[2] * want[1],
            row[2] * want[0] - row[0] * want[2],
            row[0] * want[1] - row[1] * want[0],
        ];
        let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let sine = norm(&cross) / norm(row);
        assert!(sine <= 0.25f64.to_radians() * 1e-3, "{row:?} vs {want:?}");
    }
}

#[test]
fn bless_adds_tol_degrees_where_it_is_missing() {
    let dir = scratch("bless-default");
    let p = write(
        &dir,
        "box.toml",
        &(turned_box(10.0)
            + "\n[expect]\nprincipal_axes = { value = [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }\n"),
    );
    assert_eq!(massprop(&["check", &p]).status.code(), Some(2));
    assert_eq!(massprop(&["check", "--bless", &p]).status.code(), Some(0));
    let (_, tol) = blessed_rows(&std::fs::read_to_string(&p).unwrap());
    assert_eq!(tol, 0.5);
}

#[test]
fn diff_shows_the_turn_of_each_determined_axis_in_radians() {
    let dir = scratch("diff");
    let old = write(&dir, "old.toml", &turned_box(10.0));
    let new = write(&dir, "new.toml", &turned_box(13.0));
    let out = massprop(&["diff", "--format", "json", &old, &new]);
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let turn = |k: usize| {
        v["quantities"]
            .as_array()
            .unwrap()
            .iter()
            .find(|q| q["quantity"] == format!("principal_axes.{k}"))
            .map(|q| q["new"].as_f64().unwrap())
    };
    assert!(turn(1).unwrap() < 1e-12);
    for k in [2, 3] {
        assert!((turn(k).unwrap() - 3f64.to_radians()).abs() < 1e-9);
    }
    // A rod's two equal moments determine no axes: only its own is shown.
    let rod = write(&dir, "rod.toml", &turned_rod());
    let out = massprop(&["diff", "--format", "json", &rod, &rod]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let shown: Vec<&str> = v["quantities"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|q| q["quantity"].as_str())
        .filter(|q| q.starts_with("principal_axes"))
        .collect();
    assert_eq!(shown, ["principal_axes.1"]);
}
