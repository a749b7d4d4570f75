//! MJCF bodies weighed from their geoms (issue 34, third round): mesh
//! geoms (`<asset><mesh>`, `meshdir`, `scale`, `inertia`), a geom's
//! placement from its default class, and geoms inside `<frame>`s. Expected
//! values are closed forms derived by hand (a block, an L of three unit
//! cubes, a cube's surface) and, where Python has `mujoco`, MuJoCo's own
//! compiler (`tests/oracle/mjcf_mesh_oracle.py`; placement and frames in
//! `tests/oracle/mjcf_classes_oracle.py`, run from `robots_more`).

use crate::common::{massprop, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A 2 × 1 × 0.5 m block, its corner at the origin, triangles outward.
const BLOCK: &str = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 0.5\nv 2 0 0.5\nv 2 1 0.5\nv 0 1 0.5\n\
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

/// An L: the unit squares (0,0), (1,0), (0,1) extruded from z = 0 to 1.
const BRACKET: &str = "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n\
v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n\
f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 7 9 8\nf 7 10 9\nf 7 11 10\nf 7 12 11\n\
f 7 8 2\nf 7 2 1\nf 8 9 3\nf 8 3 2\nf 9 10 4\nf 9 4 3\nf 10 11 5\nf 10 5 4\nf 11 12 6\nf 11 6 5\nf 12 7 1\nf 12 1 6\n";

/// `files` written into a scratch directory (subdirectories made); the
/// path of the last.
fn files(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = scratch("robots_mjcf", name);
    let mut last = dir.clone();
    for (file, text) in files {
        last = dir.join(file);
        std::fs::create_dir_all(last.parent().unwrap()).unwrap();
        std::fs::write(&last, text).unwrap();
    }
    last
}

fn json(path: &Path) -> Value {
    let out = massprop(&["report", path.to_str().unwrap(), "--format", "json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn refused(path: &Path) -> String {
    let out = massprop(&["report", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Number(n) => vec![n.as_f64().unwrap()],
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        _ => panic!("{v}"),
    }
}

fn close(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len());
    let scale = want.iter().fold(1.0f64, |a, b| a.max(b.abs()));
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= 1e-12 * scale, "{got:?} vs {want:?}");
    }
}

/// One free body with `geoms`, after `head` (compiler, assets, defaults).
fn model(head: &str, geoms: &str) -> String {
    format!(
        "<mujoco>\n{head}\n<worldbody>\n<body name='b'><freejoint/>\n{geoms}\n</body>\n</worldbody>\n</mujoco>\n"
    )
}

#[test]
fn a_block_mesh_weighs_as_the_block_at_the_geoms_pose() {
    // Volume 1 m³ at MuJoCo's 1000 kg/m³; its centre (1, 0.5, 0.25) in the
    // mesh, turned a quarter about z (x → y, y → −x) and moved by pos.
    let path = files(
        "block",
        &[
            ("block.obj", BLOCK),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='block.obj' inertia='exact'/></asset>",
                    "<geom type='mesh' mesh='block' pos='1 2 3' euler='0 0 90'/>",
                ),
            ),
        ],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[1000.0]);
    close(
        &numbers(&v["center_of_mass"]),
        &[1.0 - 0.5, 2.0 + 1.0, 3.0 + 0.25],
    );
    // Turned, the block spans 1 along x, 2 along y, 0.5 along z:
    // I = m (b² + c²)/12 per axis.
    let m = 1000.0;
    let diag = [
        m * (4.0 + 0.25) / 12.0,
        m * (1.0 + 0.25) / 12.0,
        m * (1.0 + 4.0) / 12.0,
    ];
    let i = numbers(&v["inertia_com"]);
    close(&[i[0], i[4], i[8]], &diag);
    close(&[i[1], i[2], i[5]], &[0.0, 0.0, 0.0]);
}

#[test]
fn a_mesh_is_found_under_meshdir_and_scaled_with_a_mirror() {
    // scale 2 −1 1: volume 2 m³ (the mirror keeps it positive), centre
    // (2, −0.5, 0.25).
    let path = files(
        "meshdir",
        &[
            ("assets/block.obj", BLOCK),
            (
                "r.xml",
                &model(
                    "<compiler meshdir='assets'/><asset><mesh name='m' file='block.obj' scale='2 -1 1'/></asset>",
                    "<geom type='mesh' mesh='m'/>",
                ),
            ),
        ],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[2000.0]);
    close(&numbers(&v["center_of_mass"]), &[2.0, -0.5, 0.25]);
}

#[test]
fn a_geoms_mass_is_spread_over_the_meshs_volume() {
    let path = files(
        "mass",
        &[
            ("block.obj", BLOCK),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='block.obj'/></asset>",
                    "<geom type='mesh' mesh='block' mass='12'/>",
                ),
            ),
        ],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[12.0]);
    let i = numbers(&v["inertia_com"]);
    close(&[i[0]], &[12.0 * (1.0 + 0.25) / 12.0]);
}

#[test]
fn an_exact_l_weighs_its_three_unit_cubes() {
    // Centre: the mean of the cubes' centres (0.5,0.5), (1.5,0.5), (0.5,1.5).
    let path = files(
        "l_exact",
        &[
            ("l.obj", BRACKET),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='l.obj' inertia='exact'/></asset>",
                    "<geom type='mesh' mesh='l'/>",
                ),
            ),
        ],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[3000.0]);
    close(&numbers(&v["center_of_mass"]), &[2.5 / 3.0, 2.5 / 3.0, 0.5]);
}

/// Unit squares extruded from z = 0 to 1, as OBJ: each face of a cell
/// that no other cell covers, two triangles outward.
fn polyomino(cells: &[(i32, i32)]) -> String {
    let mut out = String::new();
    let mut n = 0;
    let mut quad = |c: [(i32, i32, i32); 4]| {
        for (x, y, z) in c {
            out.push_str(&format!("v {x} {y} {z}\n"));
        }
        out.push_str(&format!(
            "f {} {} {}\nf {} {} {}\n",
            n + 1,
            n + 2,
            n + 3,
            n + 1,
            n + 3,
            n + 4
        ));
        n += 4;
    };
    let has = |c: (i32, i32)| cells.contains(&c);
    for &(x, y) in cells {
        quad([(x, y, 1), (x + 1, y, 1), (x + 1, y + 1, 1), (x, y + 1, 1)]);
        quad([(x, y, 0), (x, y + 1, 0), (x + 1, y + 1, 0), (x + 1, y, 0)]);
        if !has((x + 1, y)) {
            quad([
                (x + 1, y, 0),
                (x + 1, y + 1, 0),
                (x + 1, y + 1, 1),
                (x + 1, y, 1),
            ]);
        }
        if !has((x - 1, y)) {
            quad([(x, y, 0), (x, y, 1), (x, y + 1, 1), (x, y + 1, 0)]);
        }
        if !has((x, y + 1)) {
            quad([
                (x, y + 1, 0),
                (x, y + 1, 1),
                (x + 1, y + 1, 1),
                (x + 1, y + 1, 0),
            ]);
        }
        if !has((x, y - 1)) {
            quad([(x, y, 0), (x + 1, y, 0), (x + 1, y, 1), (x, y, 1)]);
        }
    }
    out
}

#[test]
fn the_legacy_default_over_counts_a_deep_u_as_mujoco_does() {
    // A U of seven unit cubes: 7000 kg exact. MuJoCo 4.0's legacy
    // weighing counts the tetrahedra from the surface's centroid to the
    // far faces positive, and compiles 8617.540091638031 kg with its centre
    // at y = 1.4263101374570457 (mujoco 4.0.0, `body_mass`, `body_ipos`).
    let u = polyomino(&[(0, 0), (1, 0), (2, 0), (0, 1), (2, 1), (0, 2), (2, 2)]);
    let run = |name: &str, attr: &str| {
        json(&files(
            name,
            &[
                ("u.obj", &u),
                (
                    "r.xml",
                    &model(
                        &format!("<asset><mesh file='u.obj'{attr}/></asset>"),
                        "<geom type='mesh' mesh='u'/>",
                    ),
                ),
            ],
        ))
    };
    let exact = run("u_exact", " inertia='exact'");
    close(&numbers(&exact["mass"]), &[7000.0]);
    close(&numbers(&exact["center_of_mass"]), &[1.5, 9.5 / 7.0, 0.5]);
    let legacy = run("u_legacy", "");
    let m = numbers(&legacy["mass"])[0];
    assert!((m / 8617.540091638031 - 1.0).abs() < 1e-12, "{m}");
    let c = numbers(&legacy["center_of_mass"]);
    assert!((c[1] / 1.4263101374570457 - 1.0).abs() < 1e-12, "{c:?}");
}

#[test]
fn the_legacy_default_weighs_an_l_as_its_solid() {
    // MuJoCo's legacy weighing counts each tetrahedron from the surface's
    // centroid positive: an L's centroid sees every face from inside, so
    // the L weighs its volume; the answer equals `exact`'s.
    let exact = files(
        "l_default_exact",
        &[
            ("l.obj", BRACKET),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='l.obj' inertia='exact'/></asset>",
                    "<geom type='mesh' mesh='l'/>",
                ),
            ),
        ],
    );
    let legacy = files(
        "l_default",
        &[
            ("l.obj", BRACKET),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='l.obj'/></asset>",
                    "<geom type='mesh' mesh='l'/>",
                ),
            ),
        ],
    );
    let (a, b) = (json(&exact), json(&legacy));
    close(&numbers(&b["mass"]), &numbers(&a["mass"]));
    close(&numbers(&b["inertia_com"]), &numbers(&a["inertia_com"]));
}

#[test]
fn a_cube_surface_weighed_as_a_shell_has_five_eighteenths_m_a_squared() {
    let cube = polyomino(&[(0, 0)]);
    let path = files(
        "shell",
        &[
            ("cube.obj", &cube),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='cube.obj' inertia='shell'/></asset>",
                    "<geom type='mesh' mesh='cube' density='2'/>",
                ),
            ),
        ],
    );
    let v = json(&path);
    // Six unit faces at 2 kg/m².
    let m = 12.0;
    close(&numbers(&v["mass"]), &[m]);
    close(&numbers(&v["principal_moments"]), &[5.0 * m / 18.0; 3]);
}

#[test]
fn a_frame_places_its_geoms_and_nested_frames_compose() {
    // Outer frame: at (1, 0, 0), a quarter turn about z; inner: at (1, 0,
    // 0) in the outer's axes, so at (1, 1, 0) in the body's.
    let path = files(
        "frames",
        &[(
            "r.xml",
            &model(
                "",
                "<frame pos='1 0 0' euler='0 0 90'><frame pos='1 0 0'><geom type='box' size='1 2 3'/></frame></frame>",
            ),
        )],
    );
    let v = json(&path);
    let m = 48_000.0;
    close(&numbers(&v["mass"]), &[m]);
    close(&numbers(&v["center_of_mass"]), &[1.0, 1.0, 0.0]);
    // Turned a quarter about z, the box spans 4 along x, 2 along y.
    let i = numbers(&v["inertia_com"]);
    close(
        &[i[0], i[4], i[8]],
        &[
            m * (4.0 + 36.0) / 12.0,
            m * (16.0 + 36.0) / 12.0,
            m * (16.0 + 4.0) / 12.0,
        ],
    );
}

#[test]
fn a_geoms_own_orientation_overrides_its_classs_and_the_class_places_it() {
    // The class: pos (0, 0, 1), a quarter turn about z; the geom's own
    // euler, a quarter turn about x, wins whatever its form.
    let path = files(
        "class_placement",
        &[(
            "r.xml",
            &model(
                "<default><geom pos='0 0 1' quat='1 0 0 1'/></default>",
                "<geom type='box' size='1 2 3' euler='90 0 0'/>",
            ),
        )],
    );
    let v = json(&path);
    let m = 48_000.0;
    close(&numbers(&v["center_of_mass"]), &[0.0, 0.0, 1.0]);
    // About x: extents 2 along x, 6 along y, 4 along z.
    let i = numbers(&v["inertia_com"]);
    close(
        &[i[0], i[4], i[8]],
        &[
            m * (36.0 + 16.0) / 12.0,
            m * (4.0 + 16.0) / 12.0,
            m * (4.0 + 36.0) / 12.0,
        ],
    );
}

#[test]
fn a_classs_fromto_places_a_capsule() {
    // A cylinder from (0,0,0) to (0,0,2) of radius 1: its centre (0,0,1).
    let path = files(
        "class_fromto",
        &[(
            "r.xml",
            &model(
                "<default><geom type='cylinder' fromto='0 0 0 0 0 2'/></default>",
                "<geom size='1'/>",
            ),
        )],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[1000.0 * std::f64::consts::PI * 2.0]);
    close(&numbers(&v["center_of_mass"]), &[0.0, 0.0, 1.0]);
}

#[test]
fn a_box_with_fromto_takes_its_first_size_across_as_mujoco_does() {
    // MuJoCo: half-sizes (r, r, l/2) = (0.5, 0.5, 1): a 1 × 1 × 2 box.
    let path = files(
        "box_fromto",
        &[(
            "r.xml",
            &model("", "<geom type='box' size='0.5 7 7' fromto='0 0 0 2 0 0'/>"),
        )],
    );
    let v = json(&path);
    close(&numbers(&v["mass"]), &[2000.0]);
    close(&numbers(&v["center_of_mass"]), &[1.0, 0.0, 0.0]);
}

#[test]
fn a_part_file_including_a_mesh_robot_composes_the_same_body() {
    let dir_files = [
        ("robot/meshes/block.obj", BLOCK),
        (
            "robot/r.xml",
            &model(
                "<compiler meshdir='meshes'/><asset><mesh file='block.obj'/></asset>",
                "<geom type='mesh' mesh='block' pos='0 0 1'/>",
            ) as &str,
        ),
        ("body.toml", "[[part]]\ninclude = \"robot/r.xml\"\n"),
    ];
    let part = files("include", &dir_files);
    let robot = part.parent().unwrap().join("robot/r.xml");
    let (a, b) = (json(&robot), json(&part));
    for key in ["mass", "center_of_mass", "inertia_com"] {
        close(&numbers(&a[key]), &numbers(&b[key]));
    }
    close(&numbers(&a["center_of_mass"]), &[1.0, 0.5, 1.25]);
}

#[test]
fn a_mesh_file_outside_the_model_files_directory_is_refused_at_file() {
    let path = files(
        "escape",
        &[
            ("block.obj", BLOCK),
            (
                "inner/r.xml",
                &model(
                    "<asset><mesh name='m' file='../block.obj'/></asset>",
                    "<geom type='mesh' mesh='m'/>",
                ),
            ),
        ],
    );
    let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["report", "r.xml"])
        .current_dir(path.parent().unwrap())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with("r.xml:2:29: error: the mesh file `../block.obj` is outside the directory of the model file and the working directory"),
        "{err}"
    );
}

/// `--include-root` lets a mesh file outside the model file's directory
/// and the working directory be read, as it lets a part file's include.
#[test]
fn a_mesh_file_under_an_include_root_is_read() {
    let path = files(
        "include_root",
        &[
            ("block.obj", BLOCK),
            (
                "inner/r.xml",
                &model(
                    "<asset><mesh name='m' file='../block.obj'/></asset>",
                    "<geom type='mesh' mesh='m'/>",
                ),
            ),
        ],
    );
    let inner = path.parent().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args([
            "report",
            "r.xml",
            "--format",
            "json",
            "--include-root",
            "..",
        ])
        .current_dir(inner)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    // The block is 2 × 1 × 0.5 m at MuJoCo's 1000 kg/m³.
    close(&numbers(&v["mass"]), &[1000.0]);
}

#[test]
fn a_geom_naming_no_mesh_asset_is_refused_with_the_nearest_name() {
    let path = files(
        "no_asset",
        &[
            ("block.obj", BLOCK),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='block.obj'/></asset>",
                    "<geom type='mesh' mesh='blok'/>",
                ),
            ),
        ],
    );
    let err = refused(&path);
    assert!(
        err.contains("error: `mesh` of a geom of body \"b\": no `<mesh>` asset is named \"blok\"; did you mean \"block\"?"),
        "{err}"
    );
}

#[test]
fn a_mesh_on_a_primitive_geom_is_refused_as_mujocos_fitted_shape() {
    let path = files(
        "fitted",
        &[
            ("block.obj", BLOCK),
            (
                "r.xml",
                &model(
                    "<asset><mesh file='block.obj'/></asset>",
                    "<geom mesh='block'/>",
                ),
            ),
        ],
    );
    let err = refused(&path);
    assert!(
        err.contains("`mesh` of a sphere geom of body \"b\": MuJoCo fits a sphere to the mesh"),
        "{err}"
    );
}

#[test]
fn an_unread_mesh_on_a_body_with_an_inertial_is_not_opened() {
    // inertiafromgeom="auto": the body keeps its inertial, its geoms are
    // not weighed, so a missing file is no error.
    let path = files(
        "unread",
        &[(
            "r.xml",
            "<mujoco><asset><mesh file='missing.obj'/></asset><worldbody><body><freejoint/>\
             <inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/><geom type='mesh' mesh='missing'/>\
             </body></worldbody></mujoco>\n",
        )],
    );
    close(&numbers(&json(&path)["mass"]), &[1.0]);
}

#[test]
fn mjcf_mesh_geoms_agree_with_mujocos_compiler() {
    let python = crate::oracle::python();
    crate::oracle::oracle_or_skip(
        &python,
        "mujoco",
        "mjcf_mesh_oracle.py",
        "20",
        "MuJoCo mesh-geom",
    );
}
