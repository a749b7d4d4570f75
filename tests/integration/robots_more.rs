//! Robots read more fully (issue 34, second round): an MJCF robot weighed
//! from its geoms is the same body in `report` and in a part file that
//! includes it; SDFormat `<mimic>`, poses `relative_to` other frames and
//! `<frame>`s; MJCF default classes. Expected values are derived by hand
//! or from an independent description of the same robot (the same chain
//! written with absolute poses, or with every default written out), and,
//! where Python has `mujoco`, from MuJoCo itself
//! (`tests/oracle/mjcf_classes_oracle.py`).

use crate::common::{massprop, scratch_files};
use serde_json::Value;
use std::path::Path;
use std::process::Command;

fn json(path: &Path, args: &[&str]) -> Value {
    let mut argv = vec!["report", path.to_str().unwrap(), "--format", "json"];
    argv.extend(args);
    let out = massprop(&argv);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Number(n) => vec![n.as_f64().unwrap()],
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        _ => panic!("{v}"),
    }
}

/// Mass, centre of mass and inertia about it, flattened.
fn figures(v: &Value) -> Vec<f64> {
    let mut out = numbers(&v["mass"]);
    out.extend(numbers(&v["center_of_mass"]));
    out.extend(numbers(&v["inertia_com"]));
    out
}

fn assert_close(a: &[f64], b: &[f64], rtol: f64) {
    assert_eq!(a.len(), b.len());
    let scale = a.iter().chain(b).fold(0.0f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= rtol * scale, "{a:?}\n{b:?}");
    }
}

/// An arm whose bodies have no `<inertial>`: MuJoCo weighs them from their
/// geoms (`inertiafromgeom="auto"`).
const GEOM_ARM: &str = r#"<mujoco model="arm">
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <geom type="box" size="0.2 0.1 0.05" density="800"/>
      <body name="upper" pos="0.2 0 0.05" euler="0 30 0">
        <joint name="shoulder" type="hinge" axis="0 1 0"/>
        <geom type="capsule" fromto="0 0 0 0.4 0 0" size="0.04"/>
        <geom type="sphere" pos="0.4 0 0" size="0.05" mass="0.3"/>
        <body name="hand" pos="0.45 0 0">
          <joint name="wrist" type="slide" axis="1 0 0"/>
          <geom type="cylinder" size="0.03 0.02" quat="1 1 0 0"/>
          <geom type="ellipsoid" size="0.02 0.03 0.04" pos="0.05 0 0"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"#;

#[test]
fn a_part_file_including_an_mjcf_robot_weighs_its_geom_only_bodies_as_report_does() {
    let part =
        "[[part]]\ninclude = \"arm.xml\"\njoints = { shoulder = \"20 deg\", wrist = 0.01 }\n";
    let path = scratch_files(
        "robots_more",
        "geom-include",
        &[("arm.xml", GEOM_ARM), ("with.toml", part)],
    );
    let robot = path.with_file_name("arm.xml");
    let alone = json(&robot, &["--joints", "shoulder=20deg, wrist=0.01"]);
    let included = json(&path, &[]);
    // The same numbers to the bit: one weighing, one composer.
    assert_eq!(figures(&alone), figures(&included));
    // The same bounds but for the part file's own level of composition,
    // which adds its roundings: no less, and of the same size.
    for key in ["mass", "center_of_mass", "inertia_com"] {
        let (a, b) = (
            numbers(&alone["error_bounds"][key]),
            numbers(&included["error_bounds"][key]),
        );
        for (x, y) in a.iter().zip(&b) {
            assert!(*y >= *x && *y <= 4.0 * x.max(1e-300), "{key}: {a:?} {b:?}");
        }
    }
    // And the figures are the geoms' (mass by hand: 800·0.4·0.2·0.1 +
    // 1000·π·0.04²·(0.4 + 4/3·0.04) + 0.3 + 1000·π·0.03²·0.04 +
    // 1000·4/3·π·0.02·0.03·0.04).
    let pi = std::f64::consts::PI;
    let mass = 800.0 * 0.4 * 0.2 * 0.1
        + 1000.0 * pi * 0.04f64.powi(2) * (0.4 + 4.0 / 3.0 * 0.04)
        + 0.3
        + 1000.0 * pi * 0.03f64.powi(2) * 0.04
        + 1000.0 * 4.0 / 3.0 * pi * 0.02 * 0.03 * 0.04;
    assert_close(&numbers(&included["mass"]), &[mass], 1e-14);
}

#[test]
fn a_geom_only_robot_included_in_a_part_file_is_not_massless() {
    let part = "[[part]]\ninclude = \"arm.xml\"\n";
    let path = scratch_files(
        "robots_more",
        "geom-include-bounds",
        &[("arm.xml", GEOM_ARM), ("with.toml", part)],
    );
    let v = json(&path, &[]);
    assert!(v["mass"].as_f64().unwrap() > 6.0, "{}", v["mass"]);
    assert_eq!(v["parts"].as_array().unwrap().len(), 3);
}
