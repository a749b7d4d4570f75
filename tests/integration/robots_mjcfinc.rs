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
fn an_included_urdf_file_is_refused_naming_its_root() {
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
            && e.contains("arm.urdf`: its root element is `<robot>`, a URDF file: MuJoCo"),
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
fn check_follows_an_include_as_report_does() {
    // Issue 34: `check` judges the included file's bodies too
    // (tests/integration/robots_follow.rs has the rest).
    let out = massprop(&["check", robots("scene.xml").to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("scene.xml: mjcf file, 4 links"), "{stdout}");
}

// Includes anywhere (issue 34, item 1): MuJoCo puts the children of the
// included file's root element wherever the `<include>` stands. Each case
// is the same model written in one file by hand (the `<include>` replaced
// by what the file holds), and must report bit for bit as it.

/// Report `main` (with `files` beside it) and `single`, each written in a
/// scratch directory of its own, at `joints`, and compare them bit for
/// bit (less `source`).
fn same_as_inline(name: &str, files: &[(&str, &str)], main: &str, single: &str, joints: &str) {
    let mut all = files.to_vec();
    all.push(("m.xml", main));
    let split = scratch_files("robots_mjcfinc", &format!("{name}-split"), &all);
    let one = scratch_files(
        "robots_mjcfinc",
        &format!("{name}-one"),
        &[("m.xml", single)],
    );
    let args = ["--joints", joints];
    assert_eq!(
        without_source(json(&split, &args)),
        without_source(json(&one, &args)),
        "{name}"
    );
}

/// A body with an inertial, for the cases.
const ARM: &str = "<body name='arm' pos='0.1 0.2 0.3' euler='10 20 30'><joint name='j' axis='0 1 0'/><geom type='box' size='0.1 0.2 0.3'/><body name='tip' pos='0.5 0 0'><joint name='k'/><inertial pos='0.01 0 0' mass='2' diaginertia='0.1 0.2 0.25'/></body></body>";

#[test]
fn an_include_inside_the_worldbody_is_the_bodies_written_there() {
    let inc = format!("<mujoco>{ARM}</mujoco>");
    same_as_inline(
        "in-world",
        &[("arm.xml", &inc)],
        "<mujoco><worldbody><body name='b'><geom size='0.1'/></body><include file='arm.xml'/></worldbody></mujoco>",
        &format!(
            "<mujoco><worldbody><body name='b'><geom size='0.1'/></body>{ARM}</worldbody></mujoco>"
        ),
        "j=0.4, k=-1",
    );
}

#[test]
fn an_include_inside_a_body_adds_its_joints_geoms_and_bodies_to_that_body() {
    let inner = "<joint name='h' axis='1 0 0'/><geom type='capsule' size='0.05 0.2' pos='0 0 0.1'/><body name='child' pos='0 0 0.4'><joint name='c'/><geom type='sphere' size='0.07' density='300'/></body>";
    let inc = format!("<anything>{inner}</anything>");
    same_as_inline(
        "in-body",
        &[("inner.xml", &inc)],
        "<mujoco><worldbody><body name='b' pos='1 0 0'><geom size='0.1'/><include file='inner.xml'/><geom type='box' size='0.1 0.1 0.1' pos='0 0.3 0'/></body></worldbody></mujoco>",
        &format!(
            "<mujoco><worldbody><body name='b' pos='1 0 0'><geom size='0.1'/>{inner}<geom type='box' size='0.1 0.1 0.1' pos='0 0.3 0'/></body></worldbody></mujoco>"
        ),
        "h=0.3, c=1.1",
    );
}

#[test]
fn an_included_inertial_is_the_inertial_of_the_body_it_stands_in() {
    let inertial = "<inertial pos='0.1 0 0' mass='3' diaginertia='0.3 0.4 0.5' euler='0 30 0'/>";
    same_as_inline(
        "inertial",
        &[("i.xml", &format!("<mujoco>{inertial}</mujoco>"))],
        "<mujoco><worldbody><body name='b'><joint name='j'/><include file='i.xml'/><body name='c' pos='0 1 0'><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></body></worldbody></mujoco>",
        &format!(
            "<mujoco><worldbody><body name='b'><joint name='j'/>{inertial}<body name='c' pos='0 1 0'><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></body></worldbody></mujoco>"
        ),
        "j=0.5",
    );
}

#[test]
fn an_include_inside_a_frame_is_placed_by_the_frame_and_takes_its_childclass() {
    let defaults = "<default><default class='dense'><geom density='5000'/><joint axis='1 0 0'/></default></default>";
    let inner = "<geom type='box' size='0.1 0.2 0.05'/><body name='c' pos='0.3 0 0'><joint name='j'/><geom type='cylinder' size='0.05 0.1'/></body>";
    same_as_inline(
        "in-frame",
        &[("f.xml", &format!("<mujoco>{inner}</mujoco>"))],
        &format!(
            "<mujoco>{defaults}<worldbody><body name='b'><geom size='0.1'/><frame pos='0.2 0 0' euler='0 0 40' childclass='dense'><include file='f.xml'/></frame></body></worldbody></mujoco>"
        ),
        &format!(
            "<mujoco>{defaults}<worldbody><body name='b'><geom size='0.1'/><frame pos='0.2 0 0' euler='0 0 40' childclass='dense'>{inner}</frame></body></worldbody></mujoco>"
        ),
        "j=0.8",
    );
}

#[test]
fn a_childclass_of_the_body_an_include_stands_in_reaches_the_included_joints() {
    let defaults = "<default><default class='k'><joint axis='0 1 0' ref='0.3'/><geom density='250'/></default></default>";
    let inner = "<joint name='j'/><geom type='box' size='0.3 0.1 0.1' pos='0.3 0 0'/>";
    same_as_inline(
        "childclass",
        &[("k.xml", &format!("<mujoco>{inner}</mujoco>"))],
        &format!(
            "<mujoco>{defaults}<worldbody><body name='b' childclass='k'><geom size='0.1'/><body name='c'><include file='k.xml'/></body></body></worldbody></mujoco>"
        ),
        &format!(
            "<mujoco>{defaults}<worldbody><body name='b' childclass='k'><geom size='0.1'/><body name='c'>{inner}</body></body></worldbody></mujoco>"
        ),
        "j=1.2",
    );
}

#[test]
fn an_include_inside_a_default_gives_that_class_its_values() {
    let inner = "<geom density='1500'/><default class='light'><geom density='100'/><joint axis='1 1 0'/></default>";
    let world = "<worldbody><body name='b'><geom type='box' size='0.1 0.2 0.3'/><body name='c' pos='0 0 1'><joint name='j' class='light'/><geom class='light' size='0.2'/></body></body></worldbody>";
    same_as_inline(
        "in-default",
        &[("d.xml", &format!("<mujoco>{inner}</mujoco>"))],
        &format!("<mujoco><default><include file='d.xml'/></default>{world}</mujoco>"),
        &format!("<mujoco><default>{inner}</default>{world}</mujoco>"),
        "j=0.6",
    );
}

#[test]
fn an_include_inside_an_asset_brings_its_meshes() {
    let mesh = std::fs::read_to_string(robots("meshes/block.obj")).unwrap();
    let assets = "<mesh name='m' file='block.obj' inertia='exact' scale='1 2 0.5'/>";
    let world = "<worldbody><body name='b'><joint name='j'/><geom type='mesh' mesh='m' pos='0 0 1'/></body></worldbody>";
    let inc = format!("<mujoco>{assets}</mujoco>");
    let main = format!("<mujoco><asset><include file='a.xml'/></asset>{world}</mujoco>");
    let a = scratch_files(
        "robots_mjcfinc",
        "in-asset-split",
        &[("block.obj", &mesh), ("a.xml", &inc), ("m.xml", &main)],
    );
    let b = scratch_files(
        "robots_mjcfinc",
        "in-asset-one",
        &[
            ("block.obj", mesh.as_str()),
            (
                "m.xml",
                &format!("<mujoco><asset>{assets}</asset>{world}</mujoco>"),
            ),
        ],
    );
    let args = ["--joints", "j=0.2"];
    assert_eq!(
        without_source(json(&a, &args)),
        without_source(json(&b, &args))
    );
    // The scaled block: 0.2 × 0.2 × 0.025 m at MuJoCo's 1000 kg/m³.
    assert_close(
        &numbers(&json(&a, &args)["mass"]),
        &[1000.0 * 0.2 * 0.2 * 0.025],
        1e-14,
    );
}

#[test]
fn an_include_inside_an_equality_couples_its_joints() {
    let world = "<worldbody><body name='a'><joint name='x'/><geom type='box' size='0.3 0.1 0.1' pos='0.3 0 0'/><body name='b' pos='0.6 0 0'><joint name='y'/><geom type='box' size='0.3 0.1 0.1' pos='0.3 0 0'/></body></body></worldbody>";
    let eq = "<joint joint1='y' joint2='x' polycoef='0.1 -2 0 0 0'/>";
    same_as_inline(
        "in-equality",
        &[("e.xml", &format!("<mujoco>{eq}</mujoco>"))],
        &format!("<mujoco>{world}<equality><include file='e.xml'/></equality></mujoco>"),
        &format!("<mujoco>{world}<equality>{eq}</equality></mujoco>"),
        "x=0.7",
    );
}

#[test]
fn includes_nested_at_different_depths_are_the_model_written_in_one_file() {
    // tests/robots/mjcf_include/anywhere.xml: includes in `<default>`,
    // `<asset>`, `<worldbody>`, `<equality>`, and, in the included files,
    // in a class, a `<frame>` and a `<body>`; anywhere_single.xml by hand.
    // (Joints within their limits: a warning's place differs, at the
    // `<include>` that brings the joint in.)
    for joints in ["shoulder=0", "shoulder=0.7, wrist=-0.5"] {
        let split = json(&robots("anywhere.xml"), &["--joints", joints]);
        let single = json(&robots("anywhere_single.xml"), &["--joints", joints]);
        assert_eq!(without_source(split), without_source(single), "{joints}");
    }
}

#[test]
fn an_included_root_of_any_name_is_spliced() {
    // MuJoCo's older include files are `<mujocoinclude>`; MuJoCo takes any
    // root element and drops it.
    same_as_inline(
        "any-root",
        &[("x.xml", &format!("<mujocoinclude>{ARM}</mujocoinclude>"))],
        "<mujoco><worldbody><include file='x.xml'/></worldbody></mujoco>",
        &format!("<mujoco><worldbody>{ARM}</worldbody></mujoco>"),
        "j=1",
    );
}

/// The refusal of `m.xml` with `files` beside it.
fn refusal(name: &str, files: &[(&str, &str)], main: &str) -> String {
    let mut all = files.to_vec();
    all.push(("m.xml", main));
    refused(&scratch_files("robots_mjcfinc", name, &all))
}

#[test]
fn a_missing_file_included_inside_a_body_is_refused_at_its_file_attribute() {
    let e = refusal(
        "missing-in-body",
        &[],
        "<mujoco>\n<worldbody>\n<body name='b'>\n  <include file='nope.xml'/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("m.xml:4:18: error: cannot read the included file `") && e.contains("nope.xml`"),
        "{e}"
    );
}

#[test]
fn a_cycle_through_includes_inside_bodies_is_refused_naming_the_chain() {
    let a = "<mujoco>\n<body name='a'>\n  <include file='b.xml'/>\n</body>\n</mujoco>\n";
    let b = "<mujoco>\n<body name='b'>\n  <include file='a.xml'/>\n</body>\n</mujoco>\n";
    let e = refusal(
        "cycle-in-body",
        &[("a.xml", a), ("b.xml", b)],
        "<mujoco>\n<worldbody>\n  <include file='a.xml'/>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("b.xml:3:18: error: `<include>` closes a cycle of includes: `"),
        "{e}"
    );
    assert!(
        e.contains("included from ") && e.contains("m.xml:3:18"),
        "{e}"
    );
}

#[test]
fn a_file_included_in_two_places_is_refused_at_the_second() {
    let g = "<mujoco><geom size='0.1'/></mujoco>";
    let e = refusal(
        "twice-in-body",
        &[("g.xml", g)],
        "<mujoco>\n<worldbody>\n<body name='a'><include file='g.xml'/></body>\n<body name='b'><include file='g.xml'/></body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("m.xml:4:31: error: `<include>` of `")
            && e.contains("the file is already included, at ")
            && e.contains("m.xml:3:31 (MuJoCo includes a file once)"),
        "{e}"
    );
}

#[test]
fn an_include_inside_a_body_escaping_the_readable_directories_is_refused() {
    let e = refusal(
        "escape-in-body",
        &[],
        "<mujoco>\n<worldbody>\n<body>\n  <include file='../../../../../../../../../../etc/hostname'/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("m.xml:4:18: error: the included `")
            && e.contains("lies outside the directories includes may read"),
        "{e}"
    );
}

#[test]
fn an_include_with_children_inside_a_body_is_refused_at_the_child() {
    let e = refusal(
        "children-in-body",
        &[("g.xml", "<mujoco><geom size='1'/></mujoco>")],
        "<mujoco>\n<worldbody>\n<body>\n  <include file='g.xml'><geom size='1'/></include>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("m.xml:4:25: error: an `<include>` cannot have children (MuJoCo refuses them)"),
        "{e}"
    );
}

#[test]
fn an_empty_included_file_and_one_without_elements_are_refused() {
    let e = refusal(
        "empty",
        &[("e.xml", "")],
        "<mujoco>\n<worldbody>\n  <include file='e.xml'/>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("m.xml:3:18: error: `<include>` of `")
            && e.contains("e.xml`: the file is empty (MuJoCo refuses an empty include)"),
        "{e}"
    );
    let e = refusal(
        "no-element",
        &[("e.xml", "<mujocoinclude> <!-- none --> </mujocoinclude>")],
        "<mujoco>\n<worldbody>\n  <include file='e.xml'/>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("e.xml`: its root element `<mujocoinclude>` holds no element (MuJoCo refuses an empty include)"),
        "{e}"
    );
}

#[test]
fn an_error_in_a_file_included_inside_a_body_names_that_file_and_the_include() {
    let bad = "<mujoco>\n<joint name='j' type='twist'/>\n</mujoco>\n";
    let e = refusal(
        "error-in-body",
        &[("bad.xml", bad)],
        "<mujoco>\n<worldbody>\n<body name='b'><geom size='1'/>\n  <include file='bad.xml'/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("bad.xml:2:23: error: `type` of joint \"j\": expected `hinge`"),
        "{e}"
    );
    assert!(
        e.contains("= note: included from ") && e.contains("m.xml:4:18"),
        "{e}"
    );
}

#[test]
fn a_mesh_warning_is_said_once_per_mesh_file_at_its_mesh_asset_in_the_included_file() {
    // The block with one more triangle, of zero area (two corners the
    // same): the mesh reader leaves it out and says so. Two `<mesh>`
    // assets name the file (spelt two ways); both are weighed.
    let mut mesh = std::fs::read_to_string(robots("meshes/block.obj")).unwrap();
    mesh.push_str("f 1 2 2\n");
    let assets = "<mujoco>\n  <asset>\n    <mesh name='m' file='b.obj' inertia='exact'/>\n    <mesh name='n' file='./b.obj' inertia='exact'/>\n  </asset>\n</mujoco>\n";
    let main = "<mujoco>\n<include file='a.xml'/>\n<worldbody><body name='b'><joint name='j'/><geom type='mesh' mesh='m'/><geom type='mesh' mesh='n' pos='1 0 0'/></body></worldbody>\n</mujoco>\n";
    let path = scratch_files(
        "robots_mjcfinc",
        "mesh-warning",
        &[("b.obj", &mesh), ("a.xml", assets), ("m.xml", main)],
    );
    let out = massprop(&["report", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let said: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("a triangle of zero area left out"))
        .collect();
    assert_eq!(said.len(), 1, "{stderr}");
    assert!(
        said[0].starts_with("warning: ") && said[0].contains("a.xml:3:5: the mesh file `"),
        "{stderr}"
    );
    let v = json(&path, &[]);
    let w = &v["warnings"].as_array().unwrap()[0];
    assert_eq!(
        (&w["kind"], &w["line"], &w["column"]),
        (&"mesh".into(), &3.into(), &5.into())
    );
    assert!(w["path"].as_str().unwrap().ends_with("a.xml"), "{w}");
}

#[test]
fn a_whole_model_included_inside_a_body_is_refused_at_its_worldbody() {
    // MuJoCo splices the file's `<worldbody>` into the body and refuses it
    // there (an unrecognized element); read, it would be another model.
    let arm = "<mujoco>\n  <worldbody>\n    <body name='arm'><geom size='1'/></body>\n  </worldbody>\n</mujoco>\n";
    let e = refusal(
        "whole-in-body",
        &[("arm.xml", arm)],
        "<mujoco>\n<worldbody>\n<body name='b'>\n  <include file='arm.xml'/>\n</body>\n</worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("arm.xml:2:3: error: `<worldbody>` inside `<body>`: MuJoCo refuses it there"),
        "{e}"
    );
    assert!(
        e.contains("= help: an `<include>` is replaced by the children of its file's root element")
            && e.contains("= note: included from ")
            && e.contains("m.xml:4:18"),
        "{e}"
    );
}

#[test]
fn an_asset_section_included_inside_an_asset_is_refused() {
    let a = "<mujoco>\n  <asset>\n    <mesh name='m' file='block.obj'/>\n  </asset>\n</mujoco>\n";
    let e = refusal(
        "asset-in-asset",
        &[("a.xml", a)],
        "<mujoco>\n<asset><include file='a.xml'/></asset>\n<worldbody><body name='b'><geom type='mesh' mesh='m'/></body></worldbody>\n</mujoco>\n",
    );
    assert!(
        e.contains("a.xml:2:3: error: `<asset>` inside `<asset>`: MuJoCo refuses it there"),
        "{e}"
    );
}

#[test]
fn a_nested_default_class_is_not_a_misplaced_section() {
    let d = "<x><default class='c'><geom density='10'/></default></x>";
    same_as_inline(
        "class-in-default",
        &[("d.xml", d)],
        "<mujoco><default><include file='d.xml'/></default><worldbody><body name='b'><joint name='j'/><geom class='c' size='1'/></body></worldbody></mujoco>",
        "<mujoco><default><default class='c'><geom density='10'/></default></default><worldbody><body name='b'><joint name='j'/><geom class='c' size='1'/></body></worldbody></mujoco>",
        "j=0",
    );
}
