//! `--package NAME=DIR` for a robot a part file includes (issue 34 item
//! 2): tests/robots/sdf_package/carrier.sdf includes `model://gripper`,
//! which only `--package gripper=…/vendor/gripper` finds. Included by a
//! part file, at any depth, it reports as the robot alone placed at the
//! include's origin and rotation (the placement and the parallel-axis
//! shift computed here, from the robot's own report); a package not given
//! is refused at the robot's `<uri>`; the roots still confine; `check`
//! holds the part file's expectations with it.

use crate::common::{massprop, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Output;

/// The fixture's directory.
fn fixture() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/robots/sdf_package")
}

/// `gripper=DIR`, the package the fixture's robot needs.
fn gripper() -> String {
    format!("gripper={}", fixture().join("vendor/gripper").display())
}

/// The include's placement: origin, and a turn of 40° about (1, 2, 2)/3.
const ORIGIN: [f64; 3] = [1.0, -2.0, 0.5];
const AXIS: [f64; 3] = [1.0, 2.0, 2.0];
const DEGREES: f64 = 40.0;

/// A part file including the fixture's robot, placed, at `mount` 30°.
fn part_file(include: &str) -> String {
    format!(
        "name = \"cart\"\n[[part]]\ninclude = {include:?}\norigin = {ORIGIN:?}\nrotation = {{ axis = {AXIS:?}, degrees = {DEGREES:?} }}\njoints = {{ mount = \"30 deg\" }}\n"
    )
}

/// `massprop ARGS` run in `dir`.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("the massprop binary runs")
}

/// The JSON of a run that succeeded.
fn ok_json(out: Output) -> Value {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The standard error of a run refused: status 2, nothing on stdout.
fn refused(out: Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

/// A scratch directory holding `files`, each (name, text).
fn scratch_dir(name: &str, files: &[(&str, String)]) -> PathBuf {
    let dir = scratch("robots_package", name);
    for (file, text) in files {
        let path = dir.join(file);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

/// The fixture's robot included by `part.toml` in a scratch directory.
fn included(name: &str) -> PathBuf {
    let robot = fixture().join("carrier.sdf");
    scratch_dir(name, &[("part.toml", part_file(robot.to_str().unwrap()))])
}

/// The robot alone, at `mount` 30°: mass, centre, inertia about it.
fn robot_alone() -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let robot = fixture().join("carrier.sdf");
    let v = ok_json(massprop(&[
        "report",
        robot.to_str().unwrap(),
        "--package",
        &gripper(),
        "--joints",
        "mount=30deg",
        "--format",
        "json",
    ]));
    figures(&v)
}

fn figures(v: &Value) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let m = v["mass"].as_f64().unwrap();
    let c = std::array::from_fn(|i| v["center_of_mass"][i].as_f64().unwrap());
    let i =
        std::array::from_fn(|a| std::array::from_fn(|b| v["inertia_com"][a][b].as_f64().unwrap()));
    (m, c, i)
}

/// The turn `AXIS`, `DEGREES` as a matrix (Rodrigues' formula).
fn turn() -> [[f64; 3]; 3] {
    let n = (AXIS[0] * AXIS[0] + AXIS[1] * AXIS[1] + AXIS[2] * AXIS[2]).sqrt();
    let [x, y, z] = AXIS.map(|a| a / n);
    let (s, c) = DEGREES.to_radians().sin_cos();
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

/// The robot alone, placed as the include places it: its centre turned
/// and moved, its tensor turned (R I Rᵀ).
fn placed() -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let (m, c, i) = robot_alone();
    let r = turn();
    let center = std::array::from_fn(|a| ORIGIN[a] + (0..3).map(|k| r[a][k] * c[k]).sum::<f64>());
    let inertia = std::array::from_fn(|a| {
        std::array::from_fn(|b| {
            (0..3)
                .flat_map(|k| (0..3).map(move |l| (k, l)))
                .map(|(k, l)| r[a][k] * i[k][l] * r[b][l])
                .sum::<f64>()
        })
    });
    (m, center, inertia)
}

/// `a` and `b` agree to 1e-12 of their scale (mass; the centre's
/// coordinates; the tensor's largest entry).
fn assert_same(a: (f64, [f64; 3], [[f64; 3]; 3]), b: (f64, [f64; 3], [[f64; 3]; 3])) {
    let tol = 1e-12;
    assert!((a.0 - b.0).abs() <= tol * b.0, "mass {} vs {}", a.0, b.0);
    let size = b.1.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    let big = b.2.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for k in 0..3 {
        assert!(
            (a.1[k] - b.1[k]).abs() <= tol * size,
            "centre {:?} vs {:?}",
            a.1,
            b.1
        );
        for l in 0..3 {
            assert!(
                (a.2[k][l] - b.2[k][l]).abs() <= tol * big,
                "inertia {:?} vs {:?}",
                a.2,
                b.2
            );
        }
    }
}

#[test]
fn a_robot_in_a_part_file_finds_its_model_uri_through_package() {
    let dir = included("placed");
    let root = fixture();
    let v = ok_json(run_in(
        &dir,
        &[
            "report",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &gripper(),
            "--format",
            "json",
        ],
    ));
    assert_same(figures(&v), placed());
}

#[test]
fn the_placed_robots_inertia_about_the_part_files_origin_is_the_parallel_axis_shift() {
    let dir = included("about");
    let root = fixture();
    let v = ok_json(run_in(
        &dir,
        &[
            "report",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &gripper(),
            "--about",
            "0,0,0",
            "--format",
            "json",
        ],
    ));
    let (m, c, i) = placed();
    // I_O = I_G + m (|c|² E − c cᵀ)
    let cc: f64 = c.iter().map(|x| x * x).sum();
    let shifted: [[f64; 3]; 3] = std::array::from_fn(|a| {
        std::array::from_fn(|b| i[a][b] + m * (if a == b { cc } else { 0.0 } - c[a] * c[b]))
    });
    let got: [[f64; 3]; 3] =
        std::array::from_fn(|a| std::array::from_fn(|b| v["inertia_ref"][a][b].as_f64().unwrap()));
    let big = shifted.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for a in 0..3 {
        for b in 0..3 {
            assert!(
                (got[a][b] - shifted[a][b]).abs() <= 1e-12 * big,
                "{got:?} vs {shifted:?}"
            );
        }
    }
}

#[test]
fn a_robot_included_two_files_deep_finds_its_package_too() {
    let robot = fixture().join("carrier.sdf");
    let dir = scratch_dir(
        "deep",
        &[
            ("sub/inner.toml", part_file(robot.to_str().unwrap())),
            (
                "outer.toml",
                "[[part]]\ninclude = \"sub/inner.toml\"\n".to_string(),
            ),
        ],
    );
    let root = fixture();
    let v = ok_json(run_in(
        &dir,
        &[
            "report",
            "outer.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &gripper(),
            "--format",
            "json",
        ],
    ));
    assert_same(figures(&v), placed());
}

#[test]
fn without_package_the_robots_model_uri_is_refused_at_its_uri_naming_the_flag() {
    let dir = included("missing");
    let root = fixture();
    let e = refused(run_in(
        &dir,
        &[
            "report",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
        ],
    ));
    assert!(
        e.contains("carrier.sdf:15:12: error: `<uri>` \"model://gripper\"")
            && e.contains("`--package gripper=DIR`")
            && e.contains("included from part.toml:3:11"),
        "{e}"
    );
}

#[test]
fn a_package_of_another_name_leaves_the_model_uri_unresolved() {
    let dir = included("other");
    let root = fixture();
    let other = format!("hand={}", fixture().join("vendor/gripper").display());
    let e = refused(run_in(
        &dir,
        &[
            "report",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &other,
        ],
    ));
    assert!(e.contains("`--package gripper=DIR`"), "{e}");
}

/// Every command that takes `--include-root` takes `--package`, and
/// refuses a DIR that does not exist before reading anything.
#[test]
fn every_command_refuses_a_package_directory_that_does_not_exist() {
    let dir = included("no_dir");
    for command in [
        &["report", "part.toml"][..],
        &["check", "part.toml"],
        &["diff", "part.toml", "part.toml"],
        &["render", "part.toml"],
        &["budget", "part.toml"],
        &["export", "part.toml", "--to", "urdf"],
        &["materials", "part.toml"],
        &["explain", "part.toml"],
    ] {
        let mut args = command.to_vec();
        args.extend(["--package", "gripper=no/such/dir"]);
        let e = refused(run_in(&dir, &args));
        assert!(
            e.contains("'--package <NAME=DIR>'") && e.contains("`no/such/dir` is not a directory"),
            "{command:?}: {e}"
        );
    }
}

#[test]
fn every_command_that_reads_part_files_passes_package_to_the_robot() {
    let dir = included("every");
    let root = fixture();
    let package = gripper();
    for command in [
        &["report", "part.toml"][..],
        &["check", "part.toml"],
        &["diff", "part.toml", "part.toml"],
        &["render", "part.toml"],
        &["budget", "part.toml"],
        &["export", "part.toml", "--to", "urdf"],
        &["materials", "part.toml"],
        &["explain", "part.toml"],
    ] {
        let mut args = command.to_vec();
        args.extend(["--include-root", root.to_str().unwrap()]);
        let without = run_in(&dir, &args);
        assert_eq!(without.status.code(), Some(2), "{command:?}");
        args.extend(["--package", &package]);
        let with = run_in(&dir, &args);
        assert_eq!(
            with.status.code(),
            Some(0),
            "{command:?}: {}",
            String::from_utf8_lossy(&with.stderr)
        );
    }
}

#[test]
fn a_package_flag_without_a_name_is_refused_naming_the_flag() {
    let e = refused(massprop(&["report", "x.toml", "--package", "=dir"]));
    assert!(
        e.contains("'--package <NAME=DIR>'") && e.contains("expected `NAME=DIR`"),
        "{e}"
    );
}

#[test]
fn a_package_named_twice_is_refused_naming_the_flag() {
    let e = refused(massprop(&[
        "check",
        "x.toml",
        "--package",
        "gripper=.",
        "--package",
        "gripper=tests",
    ]));
    assert!(e.contains("`--package gripper=DIR` is given twice"), "{e}");
}

/// The robot's own include reaching outside every root (the part file's
/// directory, the working directory, `--include-root`s, the robot's
/// directory and the `--package` directories) is refused at its `<uri>`.
#[test]
fn confinement_still_refuses_a_robot_include_outside_the_roots() {
    let outside =
        std::env::temp_dir().join(format!("massprop-robots-package-{}", std::process::id()));
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(
        outside.join("x.sdf"),
        "<sdf version='1.9'><model name='x'><link name='l'/></model></sdf>\n",
    )
    .unwrap();
    let robot = std::fs::read_to_string(fixture().join("carrier.sdf"))
        .unwrap()
        .replace(
            "    <joint name=\"mount\"",
            &format!(
                "    <include><uri>file://{}</uri></include>\n    <joint name=\"mount\"",
                outside.join("x.sdf").display()
            ),
        );
    let dir = scratch_dir(
        "confined",
        &[
            ("robot/carrier.sdf", robot),
            ("part.toml", part_file("robot/carrier.sdf")),
        ],
    );
    let e = refused(run_in(
        &dir,
        &["report", "part.toml", "--package", &gripper()],
    ));
    std::fs::remove_dir_all(&outside).ok();
    assert!(
        e.contains("carrier.sdf:18:19: error: the included")
            && e.contains("lies outside the directories includes may read")
            && e.contains("included from part.toml:3:11"),
        "{e}"
    );
}

/// `--package` opens a directory to the robot's includes, not to the part
/// file's: a part file including a robot inside a package directory still
/// needs `--include-root`.
#[test]
fn a_package_directory_is_no_root_for_the_part_files_own_includes() {
    let robot = fixture().join("vendor/gripper/gripper.sdf");
    let dir = scratch_dir(
        "not_a_root",
        &[(
            "part.toml",
            format!("[[part]]\ninclude = {:?}\n", robot.to_str().unwrap()),
        )],
    );
    let e = refused(run_in(
        &dir,
        &["report", "part.toml", "--package", &gripper()],
    ));
    assert!(
        e.contains("part.toml:2:11: error: the included") && e.contains("is outside the directory"),
        "{e}"
    );
}

/// `[expect]` of the part file, written from the robot alone placed.
fn expecting(mass: f64) -> String {
    let robot = fixture().join("carrier.sdf");
    let (_, c, _) = placed();
    format!(
        "{}[expect]\nmass = {{ value = {mass:?}, tol = \"1e-9%\" }}\ncenter_of_mass = {{ value = {c:?}, tol = 1e-9 }}\n",
        part_file(robot.to_str().unwrap())
    )
}

#[test]
fn check_holds_the_part_files_expectations_with_package() {
    let (m, _, _) = placed();
    let dir = scratch_dir("check_pass", &[("part.toml", expecting(m))]);
    let root = fixture();
    let out = run_in(
        &dir,
        &[
            "check",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &gripper(),
        ],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("part.toml: ok"), "{stdout}");
}

#[test]
fn check_fails_an_expectation_the_robot_does_not_meet_with_package() {
    let (m, _, _) = placed();
    let dir = scratch_dir("check_fail", &[("part.toml", expecting(1.05 * m))]);
    let root = fixture();
    let out = run_in(
        &dir,
        &[
            "check",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
            "--package",
            &gripper(),
        ],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("part.toml:8:8: error: mass"), "{stdout}");
}

#[test]
fn check_without_package_finds_the_part_file_invalid() {
    let (m, _, _) = placed();
    let dir = scratch_dir("check_invalid", &[("part.toml", expecting(m))]);
    let root = fixture();
    let out = run_in(
        &dir,
        &[
            "check",
            "part.toml",
            "--include-root",
            root.to_str().unwrap(),
        ],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("`--package gripper=DIR`"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
