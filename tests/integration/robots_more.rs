//! Robots read more fully (issue 34, second round): an MJCF robot weighed
//! from its geoms is the same body in `report` and in a part file that
//! includes it; SDFormat `<mimic>`, poses `relative_to` other frames and
//! `<frame>`s; MJCF default classes. Expected values are derived by hand
//! or from an independent description of the same robot (the same chain
//! written with absolute poses, or with every default written out), and,
//! where Python has `mujoco`, from MuJoCo itself
//! (`tests/oracle/mjcf_classes_oracle.py`).

use crate::common::{
    assert_close, figures_flat as figures, massprop, numbers, report_cli as json, scratch_files,
};
use std::path::Path;

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

fn fixture(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/robots")
        .join(name)
}

#[test]
fn sdformat_poses_relative_to_frames_are_the_chain_written_with_absolute_poses() {
    // frames_relative.sdf places `upper` relative to the joint `shoulder`,
    // the joint relative to a `<frame>` attached to `base`, and `fore`
    // relative to `elbow`; frames_absolute.sdf is the same robot with every
    // link's pose in the model frame (derived by hand in its comments'
    // place: mount at base + (0.2, 0, 0.3) turned 90° about z, so upper at
    // (0.2, 0, 0.4) and fore 0.5 along upper's x, which is the model's y),
    // the elbow's axis, model x, written in fore's frame as −y, and the
    // elbow's mimic, 2·(shoulder − 0.05) + 0.1, set by hand.
    let relative = fixture("frames_relative.sdf");
    let absolute = fixture("frames_absolute.sdf");
    for shoulder in [0.0, 0.3, -1.2, 2.5] {
        let elbow = 2.0 * (shoulder - 0.05) + 0.1;
        let a = json(&relative, &["--joints", &format!("shoulder={shoulder:?}")]);
        let b = json(
            &absolute,
            &[
                "--joints",
                &format!("shoulder={shoulder:?}, elbow={elbow:?}"),
            ],
        );
        assert_close(&figures(&a), &figures(&b), 1e-14);
    }
}

#[test]
fn an_sdformat_mimic_is_multiplier_times_leader_less_reference_plus_offset() {
    // Two sliders along x from a 2 kg palm at the origin: `a` carries 1 kg,
    // `b` (which mimics `a`: multiplier 3, offset 0.2, reference 0.1)
    // another. At a = 0.5, b = 3·(0.5 − 0.1) + 0.2 = 1.4, so the centre is
    // at x = (0.5 + 1.4)/4 = 0.475.
    let text = r#"<sdf version="1.11"><model name="g">
  <link name="palm"><inertial><mass>2</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial></link>
  <link name="ja"><inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial></link>
  <link name="jb"><inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial></link>
  <joint name="a" type="prismatic"><parent>palm</parent><child>ja</child><axis><xyz>1 0 0</xyz></axis></joint>
  <joint name="b" type="prismatic"><parent>palm</parent><child>jb</child><axis><xyz>1 0 0</xyz>
    <mimic joint="a"><multiplier>3</multiplier><offset>0.2</offset><reference>0.1</reference></mimic></axis></joint>
</model></sdf>
"#;
    let path = scratch_files("robots_more", "sdf-mimic", &[("g.sdf", text)]);
    let v = json(&path, &["--joints", "a=0.5"]);
    assert_close(&numbers(&v["center_of_mass"]), &[0.475, 0.0, 0.0], 1e-15);
    // A mimic without its optional numbers is a copy (multiplier 1).
    let plain = text.replace(
        "<multiplier>3</multiplier><offset>0.2</offset><reference>0.1</reference>",
        "",
    );
    let path = scratch_files("robots_more", "sdf-mimic-plain", &[("g.sdf", &plain)]);
    let v = json(&path, &["--joints", "a=0.5"]);
    assert_close(&numbers(&v["center_of_mass"]), &[0.25, 0.0, 0.0], 1e-15);
}

/// An MJCF arm whose joints and geoms take values from default classes.
const CLASSED: &str = r#"<mujoco model="classed">
  <default>
    <joint type="hinge" axis="0 1 0"/>
    <geom type="capsule" size="0.04 0.2" density="700"/>
    <default class="slider">
      <joint type="slide" axis="1 0 0" ref="0.05"/>
      <default class="heavy"><geom type="box" size="0.05 0.05 0.05" density="7800"/></default>
    </default>
  </default>
  <worldbody>
    <body name="base">
      <geom size="0.05 0.1"/>
      <body name="upper" pos="0 0 0.3">
        <joint name="shoulder" pos="0 0 -0.1"/>
        <geom pos="0 0 0.1"/>
        <body name="carriage" pos="0.1 0 0.2" childclass="heavy">
          <joint name="slide"/>
          <geom/>
          <geom class="main" pos="0 0 0.3"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"#;

/// The same arm with every value written on its element (MuJoCo's rules
/// applied by hand: `carriage` takes "heavy" through `childclass`, and
/// "heavy" inherits "slider"'s joint).
const WRITTEN: &str = r#"<mujoco model="classed">
  <worldbody>
    <body name="base">
      <geom type="capsule" size="0.05 0.1" density="700"/>
      <body name="upper" pos="0 0 0.3">
        <joint name="shoulder" type="hinge" axis="0 1 0" pos="0 0 -0.1"/>
        <geom type="capsule" size="0.04 0.2" density="700" pos="0 0 0.1"/>
        <body name="carriage" pos="0.1 0 0.2">
          <joint name="slide" type="slide" axis="1 0 0" ref="0.05"/>
          <geom type="box" size="0.05 0.05 0.05" density="7800"/>
          <geom type="capsule" size="0.04 0.2" density="700" pos="0 0 0.3"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"#;

#[test]
fn mjcf_default_classes_give_the_body_its_values_written_out() {
    let classed = scratch_files("robots_more", "classed", &[("c.xml", CLASSED)]);
    let written = scratch_files("robots_more", "written", &[("w.xml", WRITTEN)]);
    for joints in ["", "shoulder=0.4, slide=0.3", "shoulder=-1, slide=-0.2"] {
        let args: Vec<&str> = if joints.is_empty() {
            Vec::new()
        } else {
            vec!["--joints", joints]
        };
        assert_eq!(
            figures(&json(&classed, &args)),
            figures(&json(&written, &args)),
            "at {joints:?}"
        );
    }
}

#[test]
fn an_mjcf_slide_at_its_class_ref_is_at_its_written_pose() {
    // "slider"'s ref 0.05 (through "heavy", the carriage's childclass): at
    // slide = 0.05, and with no joints set (MuJoCo's qpos0 is ref), the
    // carriage is where the file writes it, its centre at x = 0.1 (both
    // geoms on its own x = 0); at slide = 0 it is 0.05 back along x.
    let path = scratch_files("robots_more", "classed-ref", &[("c.xml", CLASSED)]);
    let x = |args: &[&str]| {
        let mut a = vec!["--only", "carriage"];
        a.extend(args);
        numbers(&json(&path, &a)["center_of_mass"])[0]
    };
    assert_close(&[x(&[])], &[0.1], 1e-15);
    assert_close(&[x(&["--joints", "slide=0.05"])], &[0.1], 1e-15);
    assert_close(&[x(&["--joints", "slide=0"])], &[0.05], 1e-15);
}

#[test]
fn mjcf_robots_with_default_classes_agree_with_mujoco() {
    let python = crate::oracle::python();
    crate::oracle::oracle_or_skip(
        &python,
        "mujoco",
        "mjcf_classes_oracle.py",
        "12",
        "MuJoCo default-classes",
    );
}

fn refused(name: &str, text: &str, args: &[&str]) -> String {
    let path = scratch_files("robots_more", name, &[(name, text)]);
    let mut argv = vec!["report", path.to_str().unwrap()];
    argv.extend(args);
    let out = massprop(&argv);
    assert_eq!(out.status.code(), Some(2), "{name}");
    assert!(out.stdout.is_empty(), "{name}");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn a_childclass_naming_no_class_is_refused_at_its_name() {
    let text = "<mujoco><default><default class='arm'/></default>\n<worldbody><body childclass='leg'><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></worldbody></mujoco>\n";
    let err = refused("childclass.xml", text, &[]);
    assert!(
        err.contains("childclass.xml:2:30: error: `childclass` names no default class: \"leg\""),
        "{err}"
    );
}

#[test]
fn two_default_classes_of_one_name_are_refused_at_the_second() {
    let text = "<mujoco><default><default class='a'/>\n<default class='a'/></default><worldbody/></mujoco>\n";
    let err = refused("twice.xml", text, &[]);
    assert!(
        err.contains("twice.xml:2:17: error: `class` \"a\": two default classes"),
        "{err}"
    );
}

#[test]
fn a_default_classs_geom_with_two_orientations_is_refused_at_the_second() {
    // A geom's placement comes from its class (tests/integration/
    // robots_mjcf.rs); a class that writes two orientations is MuJoCo's
    // error ("multiple orientation specifiers").
    let text = "<mujoco><default><geom euler='0 90 0' quat='1 0 0 0'/></default>\n<worldbody><body><geom size='1'/></body></worldbody></mujoco>\n";
    let err = refused("placed.xml", text, &[]);
    assert!(
        err.contains("placed.xml:1:45: error: a default class's `<geom>` gives two orientations, `euler` and `quat`: MuJoCo allows one"),
        "{err}"
    );
}

#[test]
fn frames_relative_to_each_other_in_a_long_cycle_are_refused_without_hanging() {
    let mut text = String::from("<sdf version='1.9'><model name='m'><link name='l'/>\n");
    let n = 5000;
    for i in 0..n {
        text.push_str(&format!(
            "<frame name='f{i}'><pose relative_to='f{}'/></frame>\n",
            (i + 1) % n
        ));
    }
    text.push_str("<joint name='j' type='fixed'><parent>l</parent><child>l2</child></joint><link name='l2'><pose relative_to='f0'/></link></model></sdf>\n");
    let err = refused("long-cycle.sdf", &text, &[]);
    assert!(err.contains("is relative to frames in a cycle"), "{err}");
}

#[test]
fn a_mimic_of_the_second_axis_is_refused_at_its_axis() {
    let text = "<sdf version='1.11'><model name='m'><link name='a'/><link name='b'/><link name='c'/>\n<joint name='j1' type='revolute'><parent>a</parent><child>b</child></joint>\n<joint name='j2' type='revolute'><parent>a</parent><child>c</child><axis><mimic joint='j1' axis='axis2'/></axis></joint></model></sdf>\n";
    let err = refused("axis2.sdf", text, &[]);
    assert!(
        err.contains("axis2.sdf:3:98: error: `axis` of the `<mimic>` of joint \"j2\""),
        "{err}"
    );
}

#[test]
fn an_mjcf_equality_cycle_is_refused_at_its_first_joint() {
    let text = "<mujoco><worldbody><body name='a'><joint name='x'/><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/>\n<body name='b'><joint name='y'/><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></body></worldbody>\n<equality><joint joint1='x' joint2='y'/><joint joint1='y' joint2='x'/></equality></mujoco>\n";
    let err = refused("eq-cycle.xml", text, &[]);
    assert!(
        err.contains(
            "eq-cycle.xml:1:35: error: joint \"x\" follows itself through a cycle of followers"
        ),
        "{err}"
    );
}

#[test]
fn a_cycle_in_an_included_robot_is_refused_at_the_joint_and_the_include() {
    let robot = "<mujoco><worldbody><body name='a'><joint name='x'/><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/>\n<body name='b'><joint name='y'/><inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></body></worldbody>\n<equality><joint joint1='x' joint2='y'/><joint joint1='y' joint2='x'/></equality></mujoco>\n";
    let path = scratch_files(
        "robots_more",
        "included-cycle",
        &[
            ("r.xml", robot),
            ("p.toml", "[[part]]\ninclude = \"r.xml\"\n"),
        ],
    );
    let out = massprop(&["report", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("r.xml:1:35: error: joint \"x\" follows itself"),
        "{err}"
    );
    assert!(err.contains("p.toml:2:"), "{err}");
}
