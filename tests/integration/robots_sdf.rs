//! SDFormat read whole (issue 34): nested models, worlds and includes.
//! Expected values come from independent descriptions of the same body:
//! the robot written flat with absolute poses worked out by hand
//! (tests/robots/sdf_flat.sdf), the included model written inline
//! (tests/robots/sdf_nested.sdf), a part file placing each model of a
//! world by `origin` and `rotation`. Hostile includes and scopes are
//! refused at their place, without a hang or a panic.

use crate::common::{
    assert_close, figures_flat as figures, numbers, report_cli as json, report_refused as refused,
    scratch_files,
};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn robots(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/robots")
        .join(file)
}

fn part_names(v: &Value) -> Vec<String> {
    v["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            p["assembly"]
                .as_array()
                .unwrap()
                .last()
                .unwrap()
                .as_str()
                .unwrap()
                .to_string()
        })
        .collect()
}

#[test]
fn a_nested_model_robot_is_the_same_robot_written_flat() {
    let nested = json(&robots("sdf_nested.sdf"), &[]);
    let flat = json(&robots("sdf_flat.sdf"), &[]);
    assert_close(&figures(&nested), &figures(&flat), 1e-14);
}

#[test]
fn a_nested_model_robot_moved_by_its_scoped_joints_is_the_flat_robot_moved() {
    let nested = json(
        &robots("sdf_nested.sdf"),
        &["--joints", "shoulder=0.4, arm::wrist=-0.7"],
    );
    let flat = json(
        &robots("sdf_flat.sdf"),
        &["--joints", "shoulder=0.4, wrist=-0.7"],
    );
    assert_close(&figures(&nested), &figures(&flat), 1e-14);
}

#[test]
fn links_of_nested_models_are_named_by_their_scopes() {
    let v = json(&robots("sdf_nested.sdf"), &[]);
    assert_eq!(part_names(&v), ["base", "arm::upper", "arm::hand::palm"]);
}

#[test]
fn only_a_nested_link_reports_its_subtree() {
    let v = json(&robots("sdf_nested.sdf"), &["--only", "arm::hand::palm"]);
    assert_eq!(numbers(&v["mass"]), [1.0]);
}

#[test]
fn an_include_by_model_uri_is_the_model_written_inline() {
    let inc = robots("sdf_include/models/robot/model.sdf");
    let nested = robots("sdf_nested.sdf");
    for joints in ["shoulder=0", "shoulder=-1.1, arm::wrist=2.5"] {
        let a = json(&inc, &["--joints", joints]);
        let b = json(&nested, &["--joints", joints]);
        assert_close(&figures(&a), &figures(&b), 1e-14);
        assert_eq!(part_names(&a), part_names(&b));
    }
}

#[test]
fn an_include_without_a_pose_takes_the_included_models_own() {
    // The arm's own `<pose>` is 0 0 0.25, its upper link 0.5 along x, the
    // link's inertial centre 0.25 further (its pitch turns the tensor,
    // not the centre).
    let dir = robots("sdf_include/models");
    let text = format!(
        "<?xml version='1.0'?>\n<sdf version='1.9'>\n<model name='m'>\n<include><uri>{}</uri></include>\n</model>\n</sdf>\n",
        dir.join("arm").display()
    );
    let path = scratch_files("robots_sdf", "own-pose", &[("m.sdf", &text)]);
    let v = json(&path, &["--only", "arm::upper"]);
    let c = numbers(&v["parts"][0]["center_of_mass"]);
    let want = [0.75, 0.0, 0.25];
    assert_close(&c, &want, 1e-14);
}

#[test]
fn a_world_of_two_models_is_a_part_file_including_both_at_their_poses() {
    let world = json(&robots("sdf_include/world.sdf"), &[]);
    let robot = robots("sdf_include/models/robot/model.sdf");
    let part = format!(
        "[[part]]\ninclude = {r:?}\norigin = [2, 0, 0]\n\n[[part]]\ninclude = {r:?}\norigin = [0, 3, 0]\nrotation = {{ axis = [0, 0, 1], degrees = 90 }}\n",
        r = robot.to_str().unwrap()
    );
    let path = scratch_files("robots_sdf", "world", &[("two.toml", &part)]);
    let root = robots("sdf_include");
    let parts = json(&path, &["--include-root", root.to_str().unwrap()]);
    assert_close(&figures(&world), &figures(&parts), 1e-14);
}

#[test]
fn a_worlds_links_are_named_by_their_models() {
    let v = json(&robots("sdf_include/world.sdf"), &[]);
    let names = part_names(&v);
    assert_eq!(names[0], "first::base");
    assert_eq!(names[5], "second::arm::hand::palm");
}

#[test]
fn a_placement_frame_is_placed_at_the_include_pose() {
    // The link `l` is 0.5 m along the model's x; placed by `l` at
    // (1, 2, 3), the model frame is 0.5 m behind it.
    let model = "<?xml version='1.0'?>\n<sdf version='1.9'>\n<model name='box'>\n<link name='l'><pose>0.5 0 0 0 0 0</pose><inertial><mass>3</mass></inertial></link>\n</model>\n</sdf>\n";
    let top = "<?xml version='1.0'?>\n<sdf version='1.9'>\n<world name='w'>\n<include><uri>box.sdf</uri><pose>1 2 3 0 0 0</pose><placement_frame>l</placement_frame></include>\n</world>\n</sdf>\n";
    let path = scratch_files(
        "robots_sdf",
        "placement",
        &[("box.sdf", model), ("w.sdf", top)],
    );
    let v = json(&path, &[]);
    assert_close(&numbers(&v["center_of_mass"]), &[1.0, 2.0, 3.0], 1e-15);
}

#[test]
fn a_static_model_of_a_world_counts_with_its_mass() {
    let top = "<?xml version='1.0'?>\n<sdf version='1.9'>\n<world name='w'>\n<model name='a'><static>true</static><link name='l'><inertial><mass>2</mass></inertial></link></model>\n<model name='b'><pose>4 0 0 0 0 0</pose><link name='l'><inertial><mass>2</mass></inertial></link></model>\n</world>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "static", &[("w.sdf", top)]);
    let v = json(&path, &[]);
    assert_close(&numbers(&v["mass"]), &[4.0], 1e-15);
    assert_close(&numbers(&v["center_of_mass"]), &[2.0, 0.0, 0.0], 1e-15);
}

#[test]
fn an_include_without_a_uri_is_refused_at_the_include() {
    let top = "<sdf version='1.9'>\n<model name='m'><link name='a'/>\n<include><name>x</name></include>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "no-uri", &[("m.sdf", top)]);
    let e = refused(&path);
    assert!(
        e.contains("m.sdf:3:1: error: `<include>` is missing the required element `<uri>`"),
        "{e}"
    );
}

#[test]
fn an_include_outside_the_readable_directories_is_refused_at_its_uri() {
    let top = "<sdf version='1.9'>\n<model name='m'><link name='a'/>\n<include><uri>../../../../../../../../../../etc/hostname</uri></include>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "escape", &[("m.sdf", top)]);
    let e = refused(&path);
    assert!(e.contains("m.sdf:3:15: error: "), "{e}");
}

#[test]
fn includes_in_a_cycle_are_refused_naming_the_chain() {
    let a = "<sdf version='1.9'>\n<model name='a'><link name='l'/>\n<include><uri>b.sdf</uri></include>\n</model>\n</sdf>\n";
    let b = "<sdf version='1.9'>\n<model name='b'><link name='l'/>\n<include><uri>a.sdf</uri></include>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "cycle", &[("b.sdf", b), ("a.sdf", a)]);
    let e = refused(&path);
    assert!(e.contains("closes a cycle of includes"), "{e}");
    assert!(
        e.contains("a.sdf` → `") && e.contains("included from"),
        "{e}"
    );
}

#[test]
fn an_include_doubling_at_every_level_is_refused_without_a_hang() {
    // Each file includes the next twice: 2^16 models, past MAX_MODELS.
    let mut files = Vec::new();
    for i in 0..16 {
        files.push((
            format!("f{i}.sdf"),
            format!(
                "<sdf version='1.9'><model name='m{i}'><link name='l'/><include><uri>f{n}.sdf</uri><name>a</name></include><include><uri>f{n}.sdf</uri><name>b</name></include></model></sdf>",
                n = i + 1
            ),
        ));
    }
    files.push((
        "f16.sdf".into(),
        "<sdf version='1.9'><model name='end'><link name='l'/></model></sdf>".into(),
    ));
    files.rotate_left(1);
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(a, b)| (a.as_str(), b.as_str()))
        .collect();
    let path = scratch_files("robots_sdf", "doubling", &refs);
    let e = refused(&path);
    assert!(e.contains("the most the whole robot is composed of"), "{e}");
}

#[test]
fn a_scoped_name_two_frames_share_is_refused_as_ambiguous() {
    let top = "<sdf version='1.9'>\n<model name='m'><link name='n'/><model name='n'><link name='l'/></model>\n<joint name='j' type='fixed'><parent>n</parent><child>n::l</child></joint>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "shared", &[("m.sdf", top)]);
    let e = refused(&path);
    assert!(
        e.contains("m.sdf:3:55: error:") && e.contains("the frame is ambiguous"),
        "{e}"
    );
}

#[test]
fn a_link_named_with_a_scope_that_a_nested_link_also_has_is_refused() {
    let top = "<sdf version='1.9'>\n<model name='m'><link name='n::l'/><model name='n'><link name='l'/></model>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "colon", &[("m.sdf", top)]);
    let e = refused(&path);
    assert!(e.contains("two links are named \"n::l\""), "{e}");
}

#[test]
fn a_nested_model_without_a_link_cannot_be_a_joints_child() {
    let top = "<sdf version='1.9'>\n<model name='m'><link name='a'/><model name='n'><frame name='f'/></model>\n<joint name='j' type='fixed'><parent>a</parent><child>n</child></joint>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "canonical", &[("m.sdf", top)]);
    let e = refused(&path);
    assert!(
        e.contains("m.sdf:2:33: error: model \"n\" has no link"),
        "{e}"
    );
}

#[test]
fn models_nested_past_the_limit_are_refused_at_the_deepest() {
    let n = 80;
    let body: String = (0..n)
        .map(|i| format!("<model name='n{i}'><link name='l'/>"))
        .collect();
    let top = format!(
        "<sdf version='1.9'>\n<model name='m'><link name='a'/>{body}{}</model>\n</sdf>\n",
        "</model>".repeat(n)
    );
    let path = scratch_files("robots_sdf", "deep", &[("m.sdf", &top)]);
    let e = refused(&path);
    assert!(e.contains("nested 65 models deep"), "{e}");
}

#[test]
fn a_model_uri_is_found_through_package() {
    let robot = std::fs::read_to_string(robots("sdf_include/models/robot/model.sdf")).unwrap();
    let path = scratch_files("robots_sdf", "package", &[("r.sdf", &robot)]);
    let arm = robots("sdf_include/models/arm");
    let with = json(&path, &["--package", &format!("arm={}", arm.display())]);
    let nested = json(&robots("sdf_nested.sdf"), &[]);
    assert_close(&figures(&with), &figures(&nested), 1e-14);
}

#[test]
fn a_model_uri_without_its_directory_is_refused_naming_the_package_flag() {
    let robot = std::fs::read_to_string(robots("sdf_include/models/robot/model.sdf")).unwrap();
    let path = scratch_files("robots_sdf", "no-package", &[("r.sdf", &robot)]);
    let e = refused(&path);
    assert!(
        e.contains("r.sdf:14:12: error: `<uri>` \"model://arm\"")
            && e.contains("`--package arm=DIR`"),
        "{e}"
    );
}

#[test]
fn a_joint_from_a_frame_of_the_top_model_hangs_its_child_on_the_canonical_link() {
    // `f` is attached to the model frame, which is attached to the first
    // link `a`: `b` is `a`'s child, and `--only a` holds both.
    let top = "<sdf version='1.9'>\n<model name='m'><link name='a'><inertial><mass>1</mass></inertial></link>\n<frame name='f'><pose>1 0 0 0 0 0</pose></frame>\n<link name='b'><pose relative_to='f'/><inertial><mass>2</mass></inertial></link>\n<joint name='j' type='revolute'><parent>f</parent><child>b</child></joint>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", "top-frame", &[("m.sdf", top)]);
    let v = json(&path, &["--only", "a"]);
    assert_close(&numbers(&v["mass"]), &[3.0], 1e-15);
}

const WORLD_JOINT: &str = r#"<?xml version="1.0"?>
<sdf version="1.11"><model name="m">
<link name="a"><pose>0.3 0 0.5 0 0 0</pose><inertial><pose>0.1 0.02 -0.03 0 0 0</pose><mass>2</mass><inertia><ixx>0.1</ixx><iyy>0.2</iyy><izz>0.25</izz></inertia></inertial></link>
<joint name="spin" type="revolute"><pose>0.1 0.2 0 0 0 0</pose><parent>world</parent><child>a</child><axis><xyz>0 0 1</xyz></axis></joint>
</model></sdf>
"#;

/// A joint from `world` turns its child (it was read and then dropped;
/// found by tests/oracle/drake_body_oracle.py). By hand: the joint's axis
/// is vertical through (0.4, 0.2) (its pose in the child's frame, the
/// child at (0.3, 0, 0.5)); the centre (0.4, 0.02, 0.47) turned a quarter
/// about it is (0.58, 0.2, 0.47), and Ixx and Iyy change places.
#[test]
fn a_joint_from_the_world_turns_its_child() {
    let path = scratch_files("robots_sdf", "world_joint", &[("w.sdf", WORLD_JOINT)]);
    let v = json(&path, &["--joints", "spin=90deg"]);
    let want = [
        2.0, 0.58, 0.2, 0.47, 0.2, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.25,
    ];
    let got = figures(&v);
    assert_eq!(got.len(), want.len(), "{got:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= 1e-15, "{got:?} against {want:?}");
    }
}

/// A link is the child of one joint, from `world` or from a link.
#[test]
fn a_link_with_a_joint_from_the_world_and_another_parent_is_refused() {
    let two = WORLD_JOINT.replace(
        "</model>",
        r#"<link name="b"/><joint name="j2" type="fixed"><parent>b</parent><child>a</child></joint></model>"#,
    );
    let path = scratch_files("robots_sdf", "world_joint_two", &[("w.sdf", &two)]);
    let msg = refused(&path);
    assert!(msg.contains("already has a parent joint"), "{msg}");
}

/// A model directory and a top file including it, in a scratch directory;
/// `extra`: another file in the model directory.
fn model_dir_without_config(name: &str, extra: Option<(&str, &str)>) -> PathBuf {
    let model = "<?xml version='1.0'?>\n<sdf version='1.9'>\n<model name='arm'><link name='upper'><inertial><mass>2</mass></inertial></link></model>\n</sdf>\n";
    let top = "<?xml version='1.0'?>\n<sdf version='1.9'>\n<model name='m'>\n<link name='base'/>\n<include><uri>arm</uri></include>\n</model>\n</sdf>\n";
    let path = scratch_files("robots_sdf", name, &[("m.sdf", top)]);
    let arm = path.parent().unwrap().join("arm");
    std::fs::create_dir_all(&arm).unwrap();
    std::fs::write(arm.join("model.sdf"), model).unwrap();
    if let Some((file, text)) = extra {
        std::fs::write(arm.join(file), text).unwrap();
    }
    path
}

#[test]
fn a_model_directory_without_model_config_is_refused_as_libsdformat_refuses_it() {
    let e = refused(&model_dir_without_config("no-config", None));
    assert!(
        e.contains("m.sdf:5:15: error: the included directory `")
            && e.contains("arm` holds no `model.config`"),
        "{e}"
    );
}

#[test]
fn a_manifest_xml_is_refused_with_the_advice_to_rename_it() {
    let manifest = "<?xml version='1.0'?>\n<model><sdf version='1.9'>model.sdf</sdf></model>\n";
    let e = refused(&model_dir_without_config(
        "manifest",
        Some(("manifest.xml", manifest)),
    ));
    assert!(
        e.contains("holds `manifest.xml`, not `model.config`"),
        "{e}"
    );
}

#[test]
fn the_same_directory_with_its_model_config_is_read() {
    let config = "<?xml version='1.0'?>\n<model><sdf version='1.9'>model.sdf</sdf></model>\n";
    let path = model_dir_without_config("with-config", Some(("model.config", config)));
    let out = crate::common::massprop(&["report", path.to_str().unwrap(), "--format", "json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn a_robot_without_mass_is_refused_in_words_not_as_an_overflow() {
    // Every link massless: the centre of mass is 0/0. Said as what it is.
    let path = scratch_files(
        "robots_sdf",
        "massless",
        &[(
            "r.sdf",
            "<?xml version='1.0'?>\n<sdf version='1.9'>\n<model name='m'><link name='a'/><link name='b'/></model>\n</sdf>\n",
        )],
    );
    let e = refused(&path);
    assert!(
        e.contains("r.sdf:2:1: error: the robot has no mass: none of its 2 links has an `<inertial>` with mass"),
        "{e}"
    );
    assert!(!e.contains("overflows"), "{e}");
}
