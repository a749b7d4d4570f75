//! A robot description as a whole body (`report ROBOT`, issue 34 items 1
//! and 4): against Pinocchio (`tests/oracle/pinocchio_oracle.py`, when the
//! interpreter `MASSPROP_ORACLE_PYTHON`, else `python3`, has `pin`), and
//! against exact references that need no Python: a robot and the same body
//! written as a part file compose to the same bits; a link turned by a
//! quarter turn moves its centre as the turn says.

use crate::common::{attr, massprop, report_cli as json, scratch_files};
use serde_json::Value;
use std::path::Path;

fn bits(v: &Value) -> Vec<u64> {
    match v {
        Value::Number(n) => vec![n.as_f64().unwrap().to_bits()],
        Value::Array(a) => a.iter().flat_map(bits).collect(),
        _ => panic!("{v}"),
    }
}

const ARM: &str = r#"<robot name="two">
  <link name="base"><inertial><origin xyz="0 0 0.5"/><mass value="2"/>
    <inertia ixx="0.25" ixy="0" ixz="0" iyy="0.5" iyz="0" izz="0.75"/></inertial></link>
  <link name="tip"><inertial><origin xyz="0 0.25 0"/><mass value="0.5"/>
    <inertia ixx="0.125" ixy="0.0625" ixz="0" iyy="0.25" iyz="0" izz="0.375"/></inertial></link>
  <joint name="hinge" type="revolute"><parent link="base"/><child link="tip"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1"/></joint>
</robot>
"#;

const SAME: &str = r#"
[[part]]
name = "base"
shape = "inertia"
mass = 2
center = [0, 0, 0.5]
inertia = [[0.25, 0, 0], [0, 0.5, 0], [0, 0, 0.75]]

[[part]]
name = "tip"
shape = "inertia"
mass = 0.5
center = [1, 0.25, 0]
inertia = [[0.125, 0.0625, 0], [0.0625, 0.25, 0], [0, 0, 0.375]]
"#;

#[test]
fn a_robot_and_its_part_file_compose_to_the_same_bits() {
    let robot = scratch_files("robot_body", "same", &[("two.urdf", ARM)]);
    let part = scratch_files("robot_body", "same_part", &[("two.toml", SAME)]);
    let (r, p) = (json(&robot, &[]), json(&part, &[]));
    for key in ["mass", "center_of_mass", "inertia_com", "principal_moments"] {
        assert_eq!(
            bits(&r[key]),
            bits(&p[key]),
            "{key}: {} vs {}",
            r[key],
            p[key]
        );
    }
}

#[test]
fn a_quarter_turn_of_the_joint_turns_the_childs_centre_about_the_axis() {
    let robot = scratch_files("robot_body", "quarter", &[("two.urdf", ARM)]);
    let v = json(&robot, &["--joints", "hinge=90 deg"]);
    // The tip's centre (0, 0.25, 0) in its frame turns to (−0.25, 0, 0),
    // at x = 1: (0.75, 0, 0); the base's at (0, 0, 0.5).
    let c: Vec<f64> = v["center_of_mass"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let want = [0.5 * 0.75 / 2.5, 0.0, 2.0 * 0.5 / 2.5];
    for k in 0..3 {
        assert!((c[k] - want[k]).abs() < 1e-15, "{c:?} vs {want:?}");
    }
}

#[test]
fn an_unknown_joint_is_refused_with_the_nearest_name() {
    let robot = scratch_files("robot_body", "unknown", &[("two.urdf", ARM)]);
    let out = massprop(&["report", robot.to_str().unwrap(), "--joints", "hinje=1"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(
        stderr.contains("`--joints`") && stderr.contains("did you mean `hinge`?"),
        "{stderr}"
    );
}

#[test]
fn a_value_beyond_a_limit_is_a_warning_naming_the_limit() {
    let robot = scratch_files("robot_body", "limit", &[("two.urdf", ARM)]);
    let out = massprop(&["report", robot.to_str().unwrap(), "--joints", "hinge=2"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("beyond its upper limit 1"), "{stderr}");
}

#[test]
fn a_sweep_has_one_sample_per_value_with_its_joints() {
    let robot = scratch_files("robot_body", "sweep", &[("two.urdf", ARM)]);
    let v = json(&robot, &["--sweep", "hinge=-1..1:5"]);
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 5);
    assert_eq!(samples[0]["joints"]["hinge"], -1.0);
    assert_eq!(samples[4]["joints"]["hinge"], 1.0);
    // The mass never moves; the centre does.
    assert!(samples.iter().all(|s| s["mass"] == 2.5));
    assert_ne!(samples[0]["center_of_mass"], samples[4]["center_of_mass"]);
}

#[test]
fn only_a_link_reports_its_subtree() {
    let robot = scratch_files("robot_body", "only", &[("two.urdf", ARM)]);
    let v = json(&robot, &["--only", "tip"]);
    assert_eq!(v["mass"], 0.5);
}

#[test]
fn a_link_without_an_inertial_is_massless_and_named() {
    let text = ARM.replace(
        r#"<link name="tip"><inertial><origin xyz="0 0.25 0"/><mass value="0.5"/>
    <inertia ixx="0.125" ixy="0.0625" ixz="0" iyy="0.25" iyz="0" izz="0.375"/></inertial></link>"#,
        r#"<link name="tip"/>"#,
    );
    let robot = scratch_files("robot_body", "massless", &[("two.urdf", &text)]);
    let out = massprop(&["report", robot.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("link \"tip\" has no `<inertial>`: composed massless"),
        "{stderr}"
    );
}

#[test]
fn joints_on_a_part_file_are_refused() {
    let part = scratch_files("robot_body", "part_joints", &[("two.toml", SAME)]);
    let out = massprop(&["report", part.to_str().unwrap(), "--joints", "a=1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

#[test]
fn every_example_robot_reports_as_a_whole_body() {
    for dir in ["shapes/robots", "tests/robots"] {
        for e in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(dir)).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_none_or(|x| x == "md") {
                continue;
            }
            let out = massprop(&["report", p.to_str().unwrap(), "--format", "json"]);
            // Readable files report; the others are refused with a place.
            match out.status.code() {
                Some(0) => {
                    let _: Value = serde_json::from_slice(&out.stdout).unwrap();
                }
                Some(2) => assert!(out.stdout.is_empty(), "{p:?}"),
                c => panic!("{p:?}: {c:?}"),
            }
        }
    }
}

#[test]
fn the_whole_body_agrees_with_pinocchio() {
    let python = crate::oracle::python();
    crate::oracle::oracle_or_skip(
        &python,
        "pinocchio",
        "pinocchio_oracle.py",
        "6",
        "Pinocchio",
    );
}

fn figures(v: &Value) -> (f64, Vec<f64>, Vec<f64>) {
    let nums = |x: &Value| -> Vec<f64> { bits(x).into_iter().map(f64::from_bits).collect() };
    (
        v["mass"].as_f64().unwrap(),
        nums(&v["center_of_mass"]),
        nums(&v["inertia_com"]),
    )
}

#[test]
fn a_robot_included_at_an_origin_is_the_robot_moved_there() {
    let part = "[[part]]\ninclude = \"two.urdf\"\norigin = [0.5, -2, 3]\njoints = { hinge = \"40 deg\" }\n";
    let path = scratch_files(
        "robot_body",
        "included",
        &[("two.urdf", ARM), ("with.toml", part)],
    );
    let robot = path.with_file_name("two.urdf");
    let (m, c, i) = figures(&json(&path, &[]));
    let (m0, c0, i0) = figures(&json(&robot, &["--joints", "hinge=40deg"]));
    assert_eq!(m, m0);
    for (k, o) in [0.5, -2.0, 3.0].iter().enumerate() {
        assert!((c[k] - (c0[k] + o)).abs() < 1e-15, "{c:?} vs {c0:?}");
    }
    for k in 0..9 {
        assert!(
            (i[k] - i0[k]).abs() < 1e-15 * i0[0].abs(),
            "{i:?} vs {i0:?}"
        );
    }
}

#[test]
fn an_included_robots_unknown_joint_is_refused_at_its_key() {
    let part = "[[part]]\ninclude = \"two.urdf\"\njoints = { hinje = 1 }\n";
    let path = scratch_files(
        "robot_body",
        "included_bad",
        &[("two.urdf", ARM), ("with.toml", part)],
    );
    let out = massprop(&["report", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(
        stderr.starts_with(&format!("{}:3:12: error: `joints`", path.display())),
        "{stderr}"
    );
    assert!(stderr.contains("did you mean `hinge`?"), "{stderr}");
}

#[test]
fn joints_on_an_included_part_file_are_refused() {
    let part = "[[part]]\ninclude = \"same.toml\"\njoints = { hinge = 1 }\n";
    let path = scratch_files(
        "robot_body",
        "joints_on_part",
        &[("same.toml", SAME), ("with.toml", part)],
    );
    let out = massprop(&["report", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr.contains(":3:10: error: `joints` sets the joints of an included robot description"),
        "{stderr}"
    );
}

#[test]
fn a_mirrored_pair_of_robots_weighs_twice_one() {
    let part =
        "[[part]]\ninclude = \"two.urdf\"\norigin = [0, 1, 0]\nmirror = { normal = [0, 1, 0] }\n";
    let path = scratch_files(
        "robot_body",
        "mirrored",
        &[("two.urdf", ARM), ("with.toml", part)],
    );
    let robot = path.with_file_name("two.urdf");
    let (m, c, _) = figures(&json(&path, &[]));
    let (m0, _, _) = figures(&json(&robot, &[]));
    assert_eq!(m, 2.0 * m0);
    assert!(c[1].abs() < 1e-15, "{c:?}");
}

const GEOMETRY: &str = r#"<robot name="g">
  <link name="ball"><collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="bracket"><collision><origin xyz="0 0.25 0"/><geometry><mesh filename="package://demo/bracket.stl" scale="0.001 0.001 0.001"/></geometry></collision></link>
  <link name="bare"/>
  <joint name="a" type="fixed"><parent link="ball"/><child link="bracket"/></joint>
  <joint name="b" type="fixed"><parent link="ball"/><child link="bare"/></joint>
</robot>
"#;

fn geometry_robot(name: &str) -> std::path::PathBuf {
    scratch_files("robot_body", name, &[("g.urdf", GEOMETRY)])
}

fn meshes() -> String {
    format!("demo={}/shapes/meshes", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn a_spheres_inertial_from_geometry_is_its_closed_form() {
    let robot = geometry_robot("sphere");
    let out = massprop(&[
        "export",
        robot.to_str().unwrap(),
        "--from-geometry",
        "collision",
        "--density",
        "1000",
        "--link",
        "ball",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let m = 1000.0 * 4.0 / 3.0 * std::f64::consts::PI * 0.05f64.powi(3);
    let got = attr(&text, "value")[0];
    assert!((got - m).abs() <= 2.0 * f64::EPSILON * m, "{got} vs {m}");
    let i = 0.4 * m * 0.05 * 0.05;
    for k in ["ixx", "iyy", "izz"] {
        let got = attr(&text, k)[0];
        assert!(
            (got - i).abs() <= 4.0 * f64::EPSILON * i,
            "{k}: {got} vs {i}"
        );
    }
    assert!(text.contains("<origin xyz=\"0.5 0 0\""), "{text}");
}

#[test]
fn a_meshs_inertial_from_geometry_is_the_mesh_readers() {
    let robot = geometry_robot("mesh");
    let out = massprop(&[
        "export",
        robot.to_str().unwrap(),
        "--from-geometry",
        "collision",
        "--density",
        "2700",
        "--link",
        "bracket",
        "--package",
        &meshes(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let stl = format!("{}/shapes/meshes/bracket.stl", env!("CARGO_MANIFEST_DIR"));
    let part = format!(
        "[[part]]\nshape = \"mesh\"\nfile = {stl:?}\nmesh_unit = \"mm\"\ndensity = 2700\norigin = [0, 0.25, 0]\n"
    );
    let path = scratch_files("robot_body", "mesh_part", &[("m.toml", &part)]);
    let dir = format!("{}/shapes/meshes", env!("CARGO_MANIFEST_DIR"));
    let v = json(&path, &["--include-root", &dir]);
    assert_eq!(attr(&text, "value")[0], v["mass"].as_f64().unwrap());
}

/// A robot given by a path with a directory, its mesh relative to it, is
/// read from the robot's directory once (it was looked for at
/// `dir/dir/meshes/…`).
#[test]
fn a_relative_mesh_of_a_robot_in_another_directory_is_found_beside_the_robot() {
    let dir = crate::common::scratch("robot_body", "relative_mesh");
    std::fs::create_dir_all(dir.join("ex/meshes")).unwrap();
    let stl = format!("{}/shapes/meshes/bracket.stl", env!("CARGO_MANIFEST_DIR"));
    std::fs::copy(&stl, dir.join("ex/meshes/bracket.stl")).unwrap();
    let urdf = GEOMETRY.replace("package://demo/bracket.stl", "meshes/bracket.stl");
    std::fs::write(dir.join("ex/g.urdf"), urdf).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .current_dir(&dir)
        .args([
            "export",
            "ex/g.urdf",
            "--from-geometry",
            "collision",
            "--density",
            "2700",
            "--link",
            "bracket",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let part = format!(
        "[[part]]\nshape = \"mesh\"\nfile = {stl:?}\nmesh_unit = \"mm\"\ndensity = 2700\norigin = [0, 0.25, 0]\n"
    );
    let path = scratch_files("robot_body", "relative_mesh_part", &[("m.toml", &part)]);
    let meshes = format!("{}/shapes/meshes", env!("CARGO_MANIFEST_DIR"));
    let v = json(&path, &["--include-root", &meshes]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(attr(&text, "value")[0], v["mass"].as_f64().unwrap());
}

#[test]
fn a_link_without_geometry_keeps_its_inertial_with_a_note() {
    let robot = geometry_robot("bare");
    let out = massprop(&[
        "export",
        robot.to_str().unwrap(),
        "--from-geometry",
        "visual",
        "--density",
        "1000",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("link \"bare\" has no <visual> geometry: it keeps its inertial"),
        "{stderr}"
    );
    assert!(out.stdout.is_empty());
}

#[test]
fn inertials_from_geometry_written_in_place_read_back_as_computed() {
    let robot = geometry_robot("update");
    let r = robot.to_str().unwrap();
    let printed = massprop(&[
        "export",
        r,
        "--from-geometry",
        "collision",
        "--material",
        "steel",
        "--package",
        &meshes(),
    ]);
    assert_eq!(
        printed.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&printed.stderr)
    );
    let out = massprop(&[
        "export",
        r,
        "--from-geometry",
        "collision",
        "--material",
        "steel",
        "--package",
        &meshes(),
        "--update",
        r,
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&robot).unwrap();
    let printed = String::from_utf8_lossy(&printed.stdout);
    assert_eq!(attr(&text, "value"), attr(&printed, "value"));
    assert_eq!(attr(&text, "ixx"), attr(&printed, "ixx"));
}

#[test]
fn a_package_not_given_is_refused_at_the_geometry() {
    let robot = geometry_robot("package");
    let out = massprop(&[
        "export",
        robot.to_str().unwrap(),
        "--from-geometry",
        "collision",
        "--density",
        "1",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(
        stderr.contains(":3:24: error: link \"bracket\"") && stderr.contains("--package demo=DIR"),
        "{stderr}"
    );
}

#[test]
fn an_sdformat_leg_turns_about_its_joint_through_the_childs_origin() {
    // shapes/robots/quadruped_leg.sdf by hand: each link's pose and centre
    // in the model frame; FL_thigh_joint (axis y, at FL_thigh's origin
    // (0.19, 0.13, 0.45)) turns the thigh, calf and foot by 0.8 rad.
    let links: [([f64; 3], f64, [f64; 3], bool); 9] = [
        ([0.0, 0.0, 0.45], 5.2, [0.0; 3], false),
        ([0.19, 0.05, 0.45], 0.55, [0.0, 0.012, 0.0], false),
        (
            [0.19, 0.13, 0.45],
            0.95,
            [-0.00575696, 0.0116627, -0.109582],
            true,
        ),
        (
            [0.19, 0.13, 0.23],
            0.106877,
            [0.0138982, 0.0052336, -0.0988911],
            true,
        ),
        ([0.19, 0.13, 0.03], 0.06, [0.0; 3], true),
        ([0.19, -0.05, 0.45], 0.55, [0.0, -0.012, 0.0], false),
        (
            [0.19, -0.13, 0.45],
            0.95,
            [-0.00575696, -0.0116627, -0.109582],
            false,
        ),
        (
            [0.19, -0.13, 0.23],
            0.106877,
            [0.0138982, -0.0052336, -0.0988911],
            false,
        ),
        ([0.19, -0.13, 0.03], 0.06, [0.0; 3], false),
    ];
    let (s, c) = 0.8f64.sin_cos();
    let pivot = [0.19, 0.13, 0.45];
    let (mut mass, mut moment) = (0.0, [0.0; 3]);
    for (p, m, o, turned) in links {
        let mut w: [f64; 3] = std::array::from_fn(|i| p[i] + o[i]);
        if turned {
            let d: [f64; 3] = std::array::from_fn(|i| w[i] - pivot[i]);
            let d = [c * d[0] + s * d[2], d[1], -s * d[0] + c * d[2]];
            w = std::array::from_fn(|i| pivot[i] + d[i]);
        }
        mass += m;
        for i in 0..3 {
            moment[i] += m * w[i];
        }
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes/robots/quadruped_leg.sdf");
    let v = json(&path, &["--joints", "FL_thigh_joint=0.8"]);
    let (m, com, _) = figures(&v);
    assert!((m - mass).abs() < 1e-14);
    for i in 0..3 {
        assert!((com[i] - moment[i] / mass).abs() < 1e-15, "{com:?}");
    }
}

// MJCF bodies without `<inertial>`: what MuJoCo's compiler gives them
// (`inertiafromgeom`), from their geoms, against closed forms.

fn mjcf(name: &str, bodies: &str) -> std::path::PathBuf {
    let text = format!("<mujoco><worldbody>{bodies}</worldbody></mujoco>\n");
    scratch_files("robot_body", name, &[("r.xml", text.as_str())])
}

#[test]
fn a_box_geom_gives_a_body_its_mass_and_inertia_from_half_extents() {
    let path = mjcf(
        "geom-box",
        "<body name='b'><geom type='box' size='0.5 1 1.5' pos='1 2 3' density='2'/></body>",
    );
    let v = json(&path, &[]);
    let (a, b, c) = (1.0_f64, 2.0_f64, 3.0_f64);
    let m = 2.0 * a * b * c;
    assert!((v["mass"].as_f64().unwrap() - m).abs() < 1e-12 * m);
    let com: Vec<f64> = bits(&v["center_of_mass"])
        .into_iter()
        .map(f64::from_bits)
        .collect();
    assert_eq!(com, vec![1.0, 2.0, 3.0]);
    let i = &v["inertia_com"];
    let want = [
        m * (b * b + c * c) / 12.0,
        m * (a * a + c * c) / 12.0,
        m * (a * a + b * b) / 12.0,
    ];
    for k in 0..3 {
        let got = i[k][k].as_f64().unwrap();
        assert!(
            (got - want[k]).abs() < 1e-12 * want[k],
            "{got} vs {}",
            want[k]
        );
    }
}

#[test]
fn a_geoms_mass_wins_over_density_and_the_default_density_is_1000() {
    let path = mjcf(
        "geom-mass",
        "<body><geom size='0.1' mass='3' density='5'/><geom size='0.2' pos='0 0 1'/></body>",
    );
    let v = json(&path, &[]);
    let second = 1000.0 * 4.0 / 3.0 * std::f64::consts::PI * 0.2_f64.powi(3);
    let want = 3.0 + second;
    assert!((v["mass"].as_f64().unwrap() - want).abs() < 1e-12 * want);
}

#[test]
fn a_capsule_from_to_is_its_segment_with_hemispherical_ends() {
    let path = mjcf(
        "geom-capsule",
        "<body><geom type='capsule' fromto='0 0 0 2 0 0' size='0.5' density='1'/></body>",
    );
    let v = json(&path, &[]);
    let (r, h) = (0.5_f64, 2.0_f64);
    let pi = std::f64::consts::PI;
    let (mc, ms) = (pi * r * r * h, 4.0 / 3.0 * pi * r.powi(3));
    let axial = mc * r * r / 2.0 + ms * 2.0 * r * r / 5.0;
    let across = mc * (3.0 * r * r + h * h) / 12.0
        + ms * (2.0 * r * r / 5.0 + h * h / 4.0 + 3.0 * h * r / 8.0);
    assert!((v["mass"].as_f64().unwrap() - (mc + ms)).abs() < 1e-12 * (mc + ms));
    let com = v["center_of_mass"][0].as_f64().unwrap();
    assert!((com - 1.0).abs() < 1e-12);
    let i = &v["inertia_com"];
    assert!((i[0][0].as_f64().unwrap() - axial).abs() < 1e-12 * axial);
    assert!((i[1][1].as_f64().unwrap() - across).abs() < 1e-12 * across);
}

#[test]
fn a_geom_outside_the_inertia_group_range_weighs_nothing() {
    let path = mjcf(
        "geom-group",
        "<body><geom size='1' mass='2'/><geom size='1' mass='7' group='6'/></body>",
    );
    assert_eq!(json(&path, &[])["mass"].as_f64(), Some(2.0));
}

#[test]
fn export_from_geometry_reads_mjcf_geoms() {
    let path = mjcf(
        "geom-export",
        "<body name='b'><geom size='0.5' mass='2'/></body>",
    );
    let out = massprop(&[
        "export",
        path.to_str().unwrap(),
        "--from-geometry",
        "collision",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    // A solid sphere: 2/5 m r² = 0.2.
    assert!(
        text.contains("mass=\"2\" fullinertia=\"0.2 0.2 0.2 0 0 0\""),
        "{text}"
    );
}

#[test]
fn a_mesh_geom_naming_no_mesh_asset_is_refused_at_its_mesh() {
    // Mesh geoms are weighed (tests/integration/robots_mjcf.rs); one whose
    // `mesh` names no `<asset><mesh>` is an error at the name.
    let path = mjcf("geom-mesh", "<body>\n<geom type='mesh' mesh='m'/></body>");
    let out = massprop(&["report", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(
            "r.xml:2:25: error: `mesh` of a geom of body 1: no `<mesh>` asset is named \"m\""
        ),
        "{err}"
    );
}

#[test]
fn inertials_from_geometry_agree_with_mujocos_compiler() {
    let python = crate::oracle::python();
    crate::oracle::oracle_or_skip(&python, "mujoco", "geoms_oracle.py", "40", "MuJoCo geoms");
}

#[test]
fn each_sweep_sample_is_the_plain_report_at_its_joints() {
    let path = scratch_files("robot_body", "sweep-keys", &[("two.urdf", ARM)]);
    let swept = json(&path, &["--sweep", "hinge=-0.5..0.5:3"]);
    let samples = swept["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 3);
    for s in samples {
        let x = s["joints"]["hinge"].as_f64().unwrap();
        let plain = json(&path, &["--joints", &format!("hinge={x:?}")]);
        let mut rest = s.as_object().unwrap().clone();
        rest.remove("joints");
        assert_eq!(Value::Object(rest), plain, "at hinge = {x}");
    }
}
