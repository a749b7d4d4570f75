//! MJCF `<include file>` for the whole robot (issue 34): a scene that
//! includes the robot (which includes its default classes and mesh asset
//! from a subdirectory) is the model written inline in one file
//! (tests/robots/mjcf_include/single.xml, written by hand); the included
//! classes and mesh weigh the bodies as closed forms say; refusals name the
//! file, line and column where the `<include>` is written, and the files it
//! was included from.

use crate::common::{
    assert_close, massprop, numbers, report_cli as json, report_refused as refused, scratch_files,
};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn robots(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/robots/mjcf_include")
        .join(file)
}

/// The report without its `source`, which names the file run.
fn without_source(mut v: Value) -> Value {
    v.as_object_mut().unwrap().remove("source");
    v
}

#[test]
fn a_scene_including_the_robot_is_the_model_written_inline_bit_for_bit() {
    for joints in ["shoulder=0", "shoulder=0.7, wrist=-2.5"] {
        let scene = json(&robots("scene.xml"), &["--joints", joints]);
        let single = json(&robots("single.xml"), &["--joints", joints]);
        assert_eq!(without_source(scene), without_source(single), "{joints}");
    }
}

#[test]
fn a_part_file_including_the_scene_is_the_part_file_including_the_inline_model() {
    let part = |file: &str| {
        format!(
            "[[part]]\ninclude = {:?}\njoints = {{ shoulder = \"20 deg\" }}\norigin = [0, 2, 0]\n",
            robots(file).to_str().unwrap()
        )
    };
    let a = scratch_files(
        "robots_mjcfinc",
        "part-scene",
        &[("a.toml", &part("scene.xml"))],
    );
    let b = scratch_files(
        "robots_mjcfinc",
        "part-single",
        &[("b.toml", &part("single.xml"))],
    );
    let root = robots("");
    let args = ["--include-root", root.to_str().unwrap()];
    let (a, b) = (json(&a, &args), json(&b, &args));
    for key in ["mass", "center_of_mass", "inertia_com"] {
        assert_eq!(numbers(&a[key]), numbers(&b[key]), "{key}");
    }
}

#[test]
fn a_mesh_asset_and_default_density_from_a_nested_include_weigh_the_hand() {
    // The hand's geom is the included mesh, a 0.2 × 0.1 × 0.05 m box, at
    // the included default density 500 kg/m³.
    let v = json(&robots("scene.xml"), &["--only", "hand"]);
    let m = 500.0 * 0.2 * 0.1 * 0.05;
    assert_close(&numbers(&v["mass"]), &[m], 1e-15);
    let (a, b, c) = (0.2f64, 0.1f64, 0.05f64);
    let mut want = [
        m / 12.0 * (b * b + c * c),
        m / 12.0 * (a * a + c * c),
        m / 12.0 * (a * a + b * b),
    ];
    want.sort_by(f64::total_cmp);
    assert_close(&numbers(&v["principal_moments"]), &want, 1e-12);
}

#[test]
fn an_included_default_class_gives_the_upper_arm_its_density() {
    // A capsule of radius 0.02 m between two points 0.3 m apart, at the
    // class `heavy`'s 2000 kg/m³.
    let v = json(&robots("scene.xml"), &["--only", "upper"]);
    let (r, l) = (0.02f64, 0.3f64);
    let volume = std::f64::consts::PI * r * r * l + 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    let upper = numbers(&v["parts"][0]["mass"]);
    assert_close(&upper, &[2000.0 * volume], 1e-14);
}

#[test]
fn a_nested_include_is_found_from_the_main_files_directory_else_its_own() {
    // `sub/a.xml` names `sub/b.xml` (from the main file's directory) and
    // `c.xml` (only beside `sub/a.xml`: MuJoCo's second try).
    let body = |name: &str, mass: f64| {
        format!(
            "<mujoco>\n<worldbody><body name='{name}'><inertial pos='0 0 0' mass='{mass}' diaginertia='1 1 1'/></body></worldbody>\n</mujoco>\n"
        )
    };
    let dir = scratch_files("robots_mjcfinc", "nested", &[]);
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("sub/b.xml"), body("b", 2.0)).unwrap();
    std::fs::write(dir.join("sub/c.xml"), body("c", 3.0)).unwrap();
    std::fs::write(
        dir.join("sub/a.xml"),
        "<mujoco>\n<include file='sub/b.xml'/>\n<include file='c.xml'/>\n</mujoco>\n",
    )
    .unwrap();
    let main = dir.join("m.xml");
    std::fs::write(&main, "<mujoco>\n<include file='sub/a.xml'/>\n</mujoco>\n").unwrap();
    let v = json(&main, &[]);
    assert_eq!(numbers(&v["mass"]), [5.0]);
}

#[test]
fn a_missing_included_file_is_refused_at_its_file_attribute() {
    let path = scratch_files(
        "robots_mjcfinc",
        "missing",
        &[(
            "m.xml",
            "<mujoco>\n  <include file='nope.xml'/>\n</mujoco>\n",
        )],
    );
    let e = refused(&path);
    assert!(
        e.contains("m.xml:2:18: error: cannot read the included file `") && e.contains("nope.xml`"),
        "{e}"
    );
}

#[test]
fn an_include_outside_the_readable_directories_is_refused_at_its_file_attribute() {
    let top =
        "<mujoco>\n  <include file='../../../../../../../../../../etc/hostname'/>\n</mujoco>\n";
    let path = scratch_files("robots_mjcfinc", "escape", &[("m.xml", top)]);
    let e = refused(&path);
    assert!(
        e.contains("m.xml:2:18: error: the included `")
            && e.contains("lies outside the directories includes may read"),
        "{e}"
    );
}

#[test]
fn includes_in_a_cycle_are_refused_naming_the_chain() {
    let a = "<mujoco>\n  <include file='b.xml'/>\n</mujoco>\n";
    let b = "<mujoco>\n  <include file='a.xml'/>\n</mujoco>\n";
    let path = scratch_files("robots_mjcfinc", "cycle", &[("b.xml", b), ("a.xml", a)]);
    let e = refused(&path);
    assert!(
        e.contains("b.xml:2:18: error: `<include>` closes a cycle of includes: `"),
        "{e}"
    );
    assert!(
        e.contains("included from ") && e.contains("a.xml:2:18"),
        "{e}"
    );
}

#[test]
fn a_file_included_twice_is_refused_at_the_second_naming_the_first() {
    let w = "<mujoco>\n<worldbody><body name='x'/></worldbody>\n</mujoco>\n";
    let top = "<mujoco>\n  <include file='w.xml'/>\n  <include file='w.xml'/>\n</mujoco>\n";
    let path = scratch_files("robots_mjcfinc", "twice", &[("w.xml", w), ("m.xml", top)]);
    let e = refused(&path);
    assert!(
        e.contains("m.xml:3:18: error: `<include>` of `")
            && e.contains("the file is already included, at ")
            && e.contains("m.xml:2:18 (MuJoCo includes a file once)"),
        "{e}"
    );
}

#[test]
fn an_included_file_whose_root_is_not_mujoco_is_refused_naming_it() {
    let urdf = "<robot name='r'>\n  <link name='l'/>\n</robot>\n";
    let top = "<mujoco>\n  <include file='arm.urdf'/>\n</mujoco>\n";
    let path = scratch_files(
        "robots_mjcfinc",
        "not-mujoco",
        &[("arm.urdf", urdf), ("m.xml", top)],
    );
    let e = refused(&path);
    assert!(
        e.contains("m.xml:2:18: error: `<include>` of `")
            && e.contains("arm.urdf`: its root element is `<robot>`, expected `<mujoco>`"),
        "{e}"
    );
}

#[test]
fn an_error_inside_an_included_file_names_that_file_and_where_it_was_included() {
    let bad = "<mujoco>\n<worldbody><body name='x'><inertial pos='0 0 0' mass='1' diaginertia='1 1 q'/></body></worldbody>\n</mujoco>\n";
    let top = "<mujoco>\n  <include file='bad.xml'/>\n</mujoco>\n";
    let path = scratch_files(
        "robots_mjcfinc",
        "inside",
        &[("bad.xml", bad), ("m.xml", top)],
    );
    let e = refused(&path);
    assert!(
        e.contains(
            "bad.xml:2:75: error: `diaginertia` of body \"x\": expected a number, found \"q\""
        ),
        "{e}"
    );
    assert!(
        e.contains("= note: included from ") && e.contains("m.xml:2:18"),
        "{e}"
    );
}

#[test]
fn an_include_inside_the_worldbody_is_refused_at_it() {
    let w = "<mujoco>\n<worldbody><body name='x'/></worldbody>\n</mujoco>\n";
    let top = "<mujoco>\n  <worldbody>\n    <include file='w.xml'/>\n  </worldbody>\n</mujoco>\n";
    let path = scratch_files(
        "robots_mjcfinc",
        "in-world",
        &[("w.xml", w), ("m.xml", top)],
    );
    let e = refused(&path);
    assert!(
        e.contains("m.xml:3:5: error: `<include>` inside `<worldbody>` is not followed"),
        "{e}"
    );
}

#[test]
fn check_follows_an_include_as_report_does() {
    // Issue 34: `check` judges the included file's bodies too
    // (tests/integration/robots_follow.rs has the rest).
    let out = massprop(&["check", robots("scene.xml").to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("scene.xml: mjcf file, 4 links"), "{stdout}");
}
