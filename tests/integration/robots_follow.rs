//! Issue 34, items 1 and 3, link by link: `check`, `export --from-geometry`
//! and `--update` follow SDFormat worlds, nested models and `<include>`s,
//! and MJCF `<include>`s, as `report` does. Each robot is compared with the
//! same robot written as one file (tests/robots/follow/flat.sdf,
//! sdf_nested.sdf, mjcf_include/single.xml, written by hand); every link is
//! placed in the file where it is written (line and column found here in
//! the file's text); exported inertials agree with `report --only LINK`,
//! the whole-robot reader.

use crate::common::{massprop, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn robots(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/robots")
        .join(path)
}

/// `massprop args` run in `dir` (so that messages name files relative to
/// it, as a user in that directory sees them).
fn run_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the massprop binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `check --format json` of `file` in `dir`: its one file's links.
fn checked(dir: &Path, file: &str, more: &[&str]) -> Vec<Value> {
    let mut args = vec!["check", file, "--format", "json"];
    args.extend(more);
    let o = run_in(dir, &args);
    assert!(
        matches!(o.status.code(), Some(0 | 1)),
        "{}{}",
        stdout(&o),
        stderr(&o)
    );
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    v["files"][0]["links"].as_array().unwrap().clone()
}

/// A link's result without where it is written (which differs between a
/// robot and its one-file version by construction).
fn judged(link: &Value) -> Value {
    let mut l = link.clone();
    let o = l.as_object_mut().unwrap();
    for key in [
        "file",
        "included_from",
        "line",
        "column",
        "end_line",
        "end_column",
    ] {
        o.remove(key);
    }
    l
}

fn judged_all(links: &[Value]) -> Vec<Value> {
    links.iter().map(judged).collect()
}

fn names(links: &[Value]) -> Vec<String> {
    links
        .iter()
        .map(|l| l["name"].as_str().unwrap().to_string())
        .collect()
}

/// 1-based line and column of the `nth` (0-based) occurrence of `needle`
/// in the file `path`.
fn place(path: &Path, needle: &str, nth: usize) -> (usize, usize) {
    let text = std::fs::read_to_string(path).unwrap();
    let at = text.match_indices(needle).nth(nth).expect(needle).0;
    let line = text[..at].matches('\n').count() + 1;
    let column = at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, column)
}

/// A copy of the directory `from` (files and subdirectories) at `to`.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}

/// A scratch copy of tests/robots/follow.
fn follow_copy(name: &str) -> PathBuf {
    let dir = scratch("robots_follow", name);
    copy_dir(&robots("follow"), &dir);
    dir
}

// ---- check ----

#[test]
fn a_world_of_included_models_has_every_link_judged() {
    // The trust bug: `check world.sdf` said "0 links … 1 ok".
    let links = checked(&robots("sdf_include"), "world.sdf", &[]);
    let expected: Vec<String> = ["first", "second"]
        .iter()
        .flat_map(|m| ["base", "arm::upper", "arm::hand::palm"].map(|l| format!("{m}::{l}")))
        .collect();
    assert_eq!(names(&links), expected);
    for l in &links {
        assert_eq!(l["engines"].as_array().unwrap().len(), 3, "{l}");
    }
}

#[test]
fn a_world_checks_as_the_same_world_written_as_one_file() {
    let dir = robots("follow");
    let world = checked(&dir, "world.sdf", &[]);
    let flat = checked(&dir, "flat.sdf", &[]);
    assert_eq!(names(&world).len(), 4);
    assert_eq!(judged_all(&world), judged_all(&flat));
}

#[test]
fn a_model_including_its_arm_checks_as_the_arm_written_nested() {
    let included = checked(&robots("sdf_include/models/robot"), "model.sdf", &[]);
    let nested = checked(&robots(""), "sdf_nested.sdf", &[]);
    assert_eq!(names(&nested), ["base", "arm::upper", "arm::hand::palm"]);
    assert_eq!(judged_all(&included), judged_all(&nested));
}

#[test]
fn an_mjcf_scene_checks_as_its_model_written_in_one_file() {
    let dir = robots("mjcf_include");
    let scene = checked(&dir, "scene.xml", &[]);
    let single = checked(&dir, "single.xml", &[]);
    assert_eq!(names(&scene), ["base", "upper", "hand", "table"]);
    assert_eq!(judged_all(&scene), judged_all(&single));
}

#[test]
fn each_link_is_placed_in_the_file_it_is_written_in_with_its_include_chain() {
    let dir = robots("follow");
    let links = checked(&dir, "world.sdf", &[]);
    let hub = &links[3];
    assert_eq!(hub["name"], "cart::wheel::hub");
    let file = "models/cart/../wheel/model.sdf";
    assert_eq!(hub["file"], file);
    let (line, column) = place(&dir.join("models/wheel/model.sdf"), "<inertial>", 0);
    assert_eq!(
        (hub["line"].as_u64(), hub["column"].as_u64()),
        (Some(line as u64), Some(column as u64))
    );
    let (cl, cc) = place(&dir.join("models/cart/cart.sdf"), "model://wheel", 0);
    let (wl, wc) = place(&dir.join("world.sdf"), "models/cart<", 0);
    assert_eq!(
        hub["included_from"],
        serde_json::json!([
            format!("models/cart/cart.sdf:{cl}:{cc}"),
            format!("world.sdf:{wl}:{wc}")
        ])
    );
    // The main file's link keeps the JSON it had: no `file`.
    assert!(links[0].get("file").is_none(), "{}", links[0]);
}

/// tests/robots/follow with the wheel's mass negative.
fn bad_wheel(name: &str) -> PathBuf {
    let dir = follow_copy(name);
    let wheel = dir.join("models/wheel/model.sdf");
    let text = std::fs::read_to_string(&wheel).unwrap();
    std::fs::write(
        &wheel,
        text.replace("<mass>0.5</mass>", "<mass>-0.5</mass>"),
    )
    .unwrap();
    dir
}

#[test]
fn a_bad_link_of_an_included_file_is_reported_at_its_own_place() {
    let dir = bad_wheel("bad-table");
    let o = run_in(&dir, &["check", "world.sdf", "--engine", "drake"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let (line, column) = place(&dir.join("models/wheel/model.sdf"), "<inertial>", 0);
    let (wl, wc) = place(&dir.join("world.sdf"), "models/cart<", 0);
    let out = stdout(&o);
    assert!(
        out.contains(&format!(
            "models/cart/../wheel/model.sdf:{line}:{column}: error: link \"cart::wheel::hub\" is invalid under drake"
        )),
        "{out}"
    );
    assert!(
        out.contains(&format!("   = note: included from world.sdf:{wl}:{wc}\n")),
        "{out}"
    );
}

#[test]
fn ci_formats_point_at_the_included_file_where_the_bad_link_is() {
    let dir = bad_wheel("bad-ci");
    let (line, column) = place(&dir.join("models/wheel/model.sdf"), "<inertial>", 0);
    let file = "models/cart/../wheel/model.sdf";
    let run = |format: &str| {
        stdout(&run_in(
            &dir,
            &[
                "check",
                "world.sdf",
                "--engine",
                "drake",
                "--format",
                format,
            ],
        ))
    };
    // The runners match a repository's path: `DIR/..` taken out there.
    let repo = "models/wheel/model.sdf";
    let github = run("github");
    assert!(
        github.contains(&format!("::error file={repo},line={line},col={column},")),
        "{github}"
    );
    let junit = run("junit");
    assert!(
        junit.contains(&format!("{file}:{line}:{column}: error: link")),
        "{junit}"
    );
    let sarif: Value = serde_json::from_str(&run("sarif")).unwrap();
    let result = &sarif["runs"][0]["results"][0];
    let location = &result["locations"][0]["physicalLocation"];
    assert_eq!(location["artifactLocation"]["uri"], repo, "{result}");
    assert_eq!(location["region"]["startLine"], line, "{result}");
}

#[test]
fn check_takes_package_for_a_model_include_as_report_does() {
    let dir = scratch("robots_follow", "package");
    copy_dir(&robots("follow/models/wheel"), &dir.join("parts/wheel"));
    copy_dir(&robots("follow/models/cart"), &dir.join("top"));
    let top = dir.join("top");
    let without = run_in(&top, &["check", "cart.sdf"]);
    assert_eq!(without.status.code(), Some(2), "{}", stdout(&without));
    assert!(
        stderr(&without).contains("`--package wheel=DIR`"),
        "{}",
        stderr(&without)
    );
    let links = checked(&top, "cart.sdf", &["--package", "wheel=../parts/wheel"]);
    assert_eq!(names(&links), ["body", "load", "wheel::hub"]);
}

// ---- export --from-geometry ----

fn export(dir: &Path, file: &str, more: &[&str]) -> String {
    let mut args = vec![
        "export",
        file,
        "--from-geometry",
        "collision",
        "--density",
        "1000",
    ];
    args.extend(more);
    let o = run_in(dir, &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    stdout(&o)
}

#[test]
fn inertials_from_geometry_of_a_world_are_those_of_the_world_in_one_file() {
    let dir = robots("follow");
    let world = export(&dir, "world.sdf", &[]);
    assert_eq!(world.matches("<!-- link").count(), 4, "{world}");
    assert_eq!(world, export(&dir, "flat.sdf", &[]));
}

#[test]
fn inertials_from_geometry_of_an_mjcf_scene_are_those_of_its_model_in_one_file() {
    let dir = robots("mjcf_include");
    assert_eq!(
        export(&dir, "scene.xml", &[]),
        export(&dir, "single.xml", &[])
    );
}

#[test]
fn a_geometry_error_in_an_included_file_is_said_there() {
    let dir = follow_copy("bad-geometry");
    let cart = dir.join("models/cart/cart.sdf");
    let text = std::fs::read_to_string(&cart).unwrap();
    std::fs::write(
        &cart,
        text.replace("<size>0.6 0.4 0.1</size>", "<size>0.6 0.4</size>"),
    )
    .unwrap();
    let o = run_in(
        &dir,
        &[
            "export",
            "world.sdf",
            "--from-geometry",
            "collision",
            "--density",
            "1000",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    let (line, column) = place(&cart, "0.6 0.4<", 0);
    let (wl, wc) = place(&dir.join("world.sdf"), "models/cart<", 0);
    let e = stderr(&o);
    assert!(
        e.starts_with(&format!("models/cart/cart.sdf:{line}:{column}: error: ")),
        "{e}"
    );
    assert!(
        e.contains(&format!("= note: included from world.sdf:{wl}:{wc}")),
        "{e}"
    );
}

// ---- --update ----

/// An `<inertial>` element's numbers (SDFormat): mass, pose xyz, and the
/// six tensor entries, read from `text` after `<link name="NAME">`.
fn inertial_after(text: &str, link: &str) -> (f64, [f64; 3], [f64; 6]) {
    let from = text.find(&format!("<link name=\"{link}\">")).expect(link);
    let rest = &text[from..];
    let value = |tag: &str| -> f64 {
        let open = format!("<{tag}>");
        let s = rest.find(&open).unwrap() + open.len();
        rest[s..s + rest[s..].find('<').unwrap()]
            .trim()
            .parse()
            .unwrap()
    };
    let inertial = &rest[rest.find("<inertial>").unwrap()..];
    let s = inertial.find("<pose>").unwrap() + 6;
    let pose: Vec<f64> = inertial[s..s + inertial[s..].find('<').unwrap()]
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    (
        value("mass"),
        [pose[0], pose[1], pose[2]],
        ["ixx", "iyy", "izz", "ixy", "ixz", "iyz"].map(value),
    )
}

#[test]
fn update_writes_each_link_in_the_file_it_is_written_in() {
    let dir = follow_copy("update");
    let printed = export(&dir, "world.sdf", &[]);
    let o = run_in(
        &dir,
        &[
            "export",
            "world.sdf",
            "--from-geometry",
            "collision",
            "--density",
            "1000",
            "--update",
            "world.sdf",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let read = |p: &str| std::fs::read_to_string(dir.join(p)).unwrap();
    // Each file holds the printed inertial of its own links.
    let element = |name: &str| {
        let at = printed.find(&format!("<!-- link \"{name}\" -->")).unwrap();
        let body = &printed[at..];
        let body = &body[body.find('\n').unwrap() + 1..];
        format!(
            "<link name=\"x\">{}",
            &body[..body.find("</inertial>").unwrap() + 11]
        )
    };
    for (file, local, name) in [
        ("world.sdf", "slab", "ground::slab"),
        ("models/cart/cart.sdf", "body", "cart::body"),
        ("models/cart/cart.sdf", "load", "cart::load"),
        ("models/wheel/model.sdf", "hub", "cart::wheel::hub"),
    ] {
        assert_eq!(
            inertial_after(&read(file), local),
            inertial_after(&element(name), "x"),
            "{file} {name}"
        );
    }
    // Read back, the robot exports the same again, and is unchanged by a
    // second update.
    assert_eq!(export(&dir, "world.sdf", &[]), printed);
}

/// The principal moments of a tensor whose only product is xy, ascending:
/// the closed form of a 2×2 block and the third moment.
fn principal_xy(t: [f64; 6]) -> [f64; 3] {
    let [xx, yy, zz, xy, xz, yz] = t;
    assert!(xz == 0.0 && yz == 0.0);
    let (m, d) = (
        (xx + yy) / 2.0,
        (((xx - yy) / 2.0).powi(2) + xy * xy).sqrt(),
    );
    let mut p = [m - d, m + d, zz];
    p.sort_by(f64::total_cmp);
    p
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

#[test]
fn exported_inertials_agree_with_report_of_each_leaf_link() {
    let dir = follow_copy("report");
    let o = run_in(
        &dir,
        &[
            "export",
            "world.sdf",
            "--from-geometry",
            "collision",
            "--density",
            "1000",
            "--update",
            "world.sdf",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let read = |p: &str| std::fs::read_to_string(dir.join(p)).unwrap();
    for (file, local, name) in [
        ("world.sdf", "slab", "ground::slab"),
        ("models/cart/cart.sdf", "load", "cart::load"),
        ("models/wheel/model.sdf", "hub", "cart::wheel::hub"),
    ] {
        let (mass, _, tensor) = inertial_after(&read(file), local);
        let o = run_in(
            &dir,
            &["report", "world.sdf", "--only", name, "--format", "json"],
        );
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert!(close(v["mass"].as_f64().unwrap(), mass), "{name}: {v}");
        let moments: Vec<f64> = v["principal_moments"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let expected = principal_xy(tensor);
        for (a, b) in moments.iter().zip(expected) {
            assert!(close(*a, b), "{name}: {moments:?} vs {expected:?}");
        }
    }
}

#[test]
fn dry_run_shows_one_diff_per_file_each_with_its_path_and_writes_nothing() {
    let dir = follow_copy("dry-run");
    let before: Vec<String> = [
        "world.sdf",
        "models/cart/cart.sdf",
        "models/wheel/model.sdf",
    ]
    .iter()
    .map(|p| std::fs::read_to_string(dir.join(p)).unwrap())
    .collect();
    let o = run_in(
        &dir,
        &[
            "export",
            "world.sdf",
            "--from-geometry",
            "collision",
            "--density",
            "1000",
            "--update",
            "world.sdf",
            "--dry-run",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let headers: Vec<&str> = out.lines().filter(|l| l.starts_with("--- ")).collect();
    assert_eq!(
        headers,
        [
            "--- a/world.sdf",
            "--- a/models/cart/cart.sdf",
            "--- a/models/cart/../wheel/model.sdf"
        ]
    );
    for (p, old) in [
        "world.sdf",
        "models/cart/cart.sdf",
        "models/wheel/model.sdf",
    ]
    .iter()
    .zip(before)
    {
        assert_eq!(std::fs::read_to_string(dir.join(p)).unwrap(), old, "{p}");
    }
}

#[test]
fn a_package_directory_outside_the_robot_is_written_only_under_an_include_root() {
    let dir = scratch("robots_follow", "outside");
    copy_dir(&robots("follow/models/wheel"), &dir.join("parts/wheel"));
    copy_dir(&robots("follow/models/cart"), &dir.join("top"));
    let top = dir.join("top");
    let wheel = dir.join("parts/wheel/model.sdf");
    let before = std::fs::read_to_string(&wheel).unwrap();
    let args = [
        "export",
        "cart.sdf",
        "--from-geometry",
        "collision",
        "--density",
        "1000",
        "--package",
        "wheel=../parts/wheel",
        "--update",
        "cart.sdf",
    ];
    let o = run_in(&top, &args);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    let (line, column) = place(&wheel, "<link", 0);
    let e = stderr(&o);
    assert!(
        e.starts_with(&format!(
            "../parts/wheel/model.sdf:{line}:{column}: error: `--update` does not write link \"wheel::hub\" into `../parts/wheel/model.sdf`"
        )),
        "{e}"
    );
    // Nothing written, the robot's own file neither.
    assert_eq!(std::fs::read_to_string(&wheel).unwrap(), before);
    let mut allowed = args.to_vec();
    allowed.extend(["--include-root", "../parts"]);
    let o = run_in(&top, &allowed);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_ne!(std::fs::read_to_string(&wheel).unwrap(), before);
}

#[test]
fn a_part_exported_into_a_link_of_an_included_file_is_written_there() {
    let dir = scratch("robots_follow", "part-into-include");
    copy_dir(&robots("sdf_include"), &dir);
    let part = dir.join("part.toml");
    std::fs::write(
        &part,
        "[[part]]\nname = \"p\"\nshape = \"box\"\nsize = [0.1, 0.2, 0.3]\nmass = 2\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let world_before = std::fs::read_to_string(dir.join("world.sdf")).unwrap();
    let o = run_in(
        &dir,
        &[
            "export",
            "part.toml",
            "--update",
            "world.sdf",
            "--link",
            "second::arm::upper",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(dir.join("world.sdf")).unwrap(),
        world_before
    );
    let arm = std::fs::read_to_string(dir.join("models/arm/arm.sdf")).unwrap();
    // The box's moments: m (b² + c²) / 12 about x.
    let (mass, _, t) = inertial_after(&arm, "upper");
    assert_eq!(mass, 2.0);
    assert!(close(t[0], 2.0 * (0.04 + 0.09) / 12.0), "{t:?}");
    // Both copies of the arm read the one element written.
    let links = checked(&dir, "world.sdf", &[]);
    for l in links
        .iter()
        .filter(|l| l["name"].as_str().unwrap().ends_with("arm::upper"))
    {
        assert_eq!(l["inertial"]["mass"], 2.0, "{l}");
    }
}

#[test]
fn an_mjcf_body_of_an_included_file_is_updated_in_that_file() {
    let dir = scratch("robots_follow", "mjcf-update");
    copy_dir(&robots("mjcf_include"), &dir);
    let part = dir.join("part.toml");
    std::fs::write(
        &part,
        "[[part]]\nname = \"p\"\nshape = \"sphere\"\nradius = 0.1\nmass = 3\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let scene_before = std::fs::read_to_string(dir.join("scene.xml")).unwrap();
    let o = run_in(
        &dir,
        &[
            "export",
            "part.toml",
            "--update",
            "scene.xml",
            "--link",
            "upper",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(dir.join("scene.xml")).unwrap(),
        scene_before
    );
    let links = checked(&dir, "scene.xml", &[]);
    let upper = links.iter().find(|l| l["name"] == "upper").unwrap();
    assert_eq!(upper["file"], "robot.xml", "{upper}");
    assert_eq!(upper["inertial"]["mass"], 3.0, "{upper}");
    // 2/5 m r² about every axis.
    let i = upper["inertial"]["principal_moments"][0].as_f64().unwrap();
    assert!(close(i, 0.4 * 3.0 * 0.01), "{upper}");
}

#[test]
fn report_still_reads_the_robot_check_now_follows() {
    // `massprop check` and `report` agree on which links there are.
    let o = massprop(&[
        "report",
        robots("follow/world.sdf").to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let text = v.to_string();
    for name in names(&checked(&robots("follow"), "world.sdf", &[])) {
        assert!(text.contains(&format!("\"{name}\"")), "{name}");
    }
}

#[test]
fn check_writes_no_report_over_a_file_the_robot_includes() {
    let dir = follow_copy("output-onto-include");
    let cart = dir.join("models/cart/cart.sdf");
    let before = std::fs::read_to_string(&cart).unwrap();
    let o = run_in(&dir, &["check", "world.sdf", "-o", "models/cart/cart.sdf"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("the report would replace it"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read_to_string(&cart).unwrap(), before);
}

#[test]
fn update_refuses_a_body_whose_inertial_an_include_inside_it_brings() {
    // MJCF `<include>` anywhere (issue 34): the body's `<inertial>` is
    // written in another file; a second one written into the body would
    // be MuJoCo's error, so `--update` refuses, at the body, and writes
    // nothing.
    let dir = scratch("robots_follow", "mjcf-elsewhere");
    let inner = "<mujoco>\n  <inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/>\n</mujoco>\n";
    let top = "<mujoco>\n  <worldbody>\n    <body name='b'>\n      <freejoint/>\n      <include file='in.xml'/>\n    </body>\n  </worldbody>\n</mujoco>\n";
    std::fs::write(dir.join("in.xml"), inner).unwrap();
    std::fs::write(dir.join("m.xml"), top).unwrap();
    std::fs::write(
        dir.join("part.toml"),
        "[[part]]\nname = \"p\"\nshape = \"sphere\"\nradius = 0.1\nmass = 3\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let o = run_in(
        &dir,
        &["export", "part.toml", "--update", "m.xml", "--link", "b"],
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert!(
        stderr(&o).contains("m.xml:3:5: error: `--update` does not write body \"b\": its `<inertial>` is brought in by an `<include>` inside it"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read_to_string(dir.join("m.xml")).unwrap(), top);
    assert_eq!(std::fs::read_to_string(dir.join("in.xml")).unwrap(), inner);
}
