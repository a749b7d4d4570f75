//! `export ROBOT --from-geometry` (issue 34 item 3): `--link NAME` reads
//! only that link's geometry, and a mesh's `scale` is read on each axis
//! (a box mesh scaled is the box of those sides; a mirror gives the
//! mirrored body), against closed forms.

use crate::common::{attr, massprop, scratch_files};
use std::path::{Path, PathBuf};

/// The unit cube [0, 1]³, outward triangles.
const CUBE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

/// The corner tetrahedron (0, 0, 0), e₁, e₂, e₃, outward triangles: its
/// products of inertia are not zero, so a mirror shows in their signs.
const TET: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

fn robot(name: &str, urdf: &str) -> PathBuf {
    scratch_files(
        "robots_export",
        name,
        &[("cube.obj", CUBE), ("tet.obj", TET), ("r.urdf", urdf)],
    )
}

/// A robot of one link, `a`, whose collision is `mesh` at `xyz`.
fn one_mesh(name: &str, mesh: &str, xyz: &str) -> PathBuf {
    robot(
        name,
        &format!(
            "<robot name=\"r\">\n  <link name=\"a\"><collision><origin xyz=\"{xyz}\"/><geometry>{mesh}</geometry></collision></link>\n</robot>\n"
        ),
    )
}

/// `export ROBOT --from-geometry collision --density RHO ARGS`.
fn run_export(robot: &Path, rho: &str, args: &[&str]) -> std::process::Output {
    let mut argv = vec![
        "export",
        robot.to_str().unwrap(),
        "--from-geometry",
        "collision",
        "--density",
        rho,
    ];
    argv.extend(args);
    massprop(&argv)
}

/// Stdout of `run_export`, which must succeed.
fn export(robot: &Path, rho: &str, args: &[&str]) -> String {
    let out = run_export(robot, rho, args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn close(got: f64, want: f64, scale: f64) {
    assert!(
        (got - want).abs() <= 1e-13 * scale,
        "{got} vs {want} (scale {scale})"
    );
}

#[test]
fn a_cube_mesh_scaled_two_by_three_by_a_half_is_that_box() {
    let r = one_mesh(
        "box",
        "<mesh filename=\"cube.obj\" scale=\"2 3 0.5\"/>",
        "0.1 0 0",
    );
    let text = export(&r, "1000", &[]);
    let (a, b, c) = (2.0, 3.0, 0.5);
    let m = 1000.0 * a * b * c;
    close(attr(&text, "value")[0], m, m);
    let at = attr(&text, "xyz");
    for (got, want) in at.iter().zip([0.1 + a / 2.0, b / 2.0, c / 2.0]) {
        close(*got, want, 1.0);
    }
    let ixx = m * (b * b + c * c) / 12.0;
    let iyy = m * (a * a + c * c) / 12.0;
    let izz = m * (a * a + b * b) / 12.0;
    for (k, want) in [("ixx", ixx), ("iyy", iyy), ("izz", izz)] {
        close(attr(&text, k)[0], want, izz);
    }
    for k in ["ixy", "ixz", "iyz"] {
        close(attr(&text, k)[0], 0.0, izz);
    }
}

/// The corner tetrahedron of density ρ: volume 1/6, centroid (¼, ¼, ¼),
/// ∫xy about the origin 1/120, so about the centroid ∫xy = 1/120 − 1/96 =
/// −1/480 and ∫x² = 1/60 − 1/96 = 1/160: Ixx = ρ/80, the tensor's Ixy =
/// ρ/480. Mirrored in y, the centroid's y and Ixy, Iyz change sign.
#[test]
fn a_mirrored_scale_gives_the_mirrored_body() {
    let r = one_mesh(
        "mirror",
        "<mesh filename=\"tet.obj\" scale=\"1 -1 1\"/>",
        "0 0 0",
    );
    let rho = 480.0;
    let text = export(&r, "480", &[]);
    close(attr(&text, "value")[0], rho / 6.0, rho);
    let at = attr(&text, "xyz");
    for (got, want) in at.iter().zip([0.25, -0.25, 0.25]) {
        close(*got, want, 1.0);
    }
    for k in ["ixx", "iyy", "izz"] {
        close(attr(&text, k)[0], rho / 80.0, rho / 80.0);
    }
    close(attr(&text, "ixy")[0], -rho / 480.0, rho / 80.0);
    close(attr(&text, "iyz")[0], -rho / 480.0, rho / 80.0);
    close(attr(&text, "ixz")[0], rho / 480.0, rho / 80.0);
}

#[test]
fn a_zero_scale_is_refused_at_the_attribute() {
    let r = one_mesh(
        "zero",
        "<mesh filename=\"cube.obj\" scale=\"1 0 1\"/>",
        "0 0 0",
    );
    let out = run_export(&r, "1000", &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    let text = std::fs::read_to_string(&r).unwrap();
    let col = text.lines().nth(1).unwrap().find("1 0 1").unwrap() + 1;
    assert!(
        err.contains(&format!("r.urdf:2:{col}: error: `scale`")),
        "{err}"
    );
}

/// A uniform scale that is no length unit's (1.5) grows the cube to a
/// cube of side 1.5.
#[test]
fn a_uniform_scale_that_is_no_unit_is_the_unit_cube_grown() {
    let r = one_mesh(
        "grown",
        "<mesh filename=\"cube.obj\" scale=\"1.5 1.5 1.5\"/>",
        "0 0 0",
    );
    let text = export(&r, "1000", &[]);
    let m = 1000.0 * 1.5f64.powi(3);
    close(attr(&text, "value")[0], m, m);
    close(attr(&text, "ixx")[0], m * 2.0 * 2.25 / 12.0, m);
}

const TWO: &str = r#"<robot name="r">
  <link name="a"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="z"><collision><geometry><mesh filename="missing.obj" scale="2 2 2"/></geometry></collision><visual><geometry/></visual></link>
  <joint name="j" type="fixed"><parent link="a"/><child link="z"/></joint>
</robot>
"#;

#[test]
fn another_links_missing_mesh_does_not_stop_the_chosen_link() {
    let r = robot("other", TWO);
    let text = export(&r, "1000", &["--link", "a"]);
    let m = 1000.0 * 4.0 / 3.0 * std::f64::consts::PI * 0.001;
    close(attr(&text, "value")[0], m, m);
    assert!(!text.contains("link \"z\""), "{text}");
}

#[test]
fn another_links_bad_geometry_does_not_stop_the_chosen_link() {
    let urdf = r#"<robot name="r">
  <link name="a"><visual><geometry><sphere radius="0.1"/></geometry></visual></link>
  <link name="z"><visual><geometry/></visual></link>
  <joint name="j" type="fixed"><parent link="a"/><child link="z"/></joint>
</robot>
"#;
    let r = robot("other_visual", urdf);
    let out = massprop(&[
        "export",
        r.to_str().unwrap(),
        "--from-geometry",
        "visual",
        "--density",
        "1000",
        "--link",
        "a",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn an_mjcf_bodys_missing_mesh_does_not_stop_another_body() {
    let xml = r#"<mujoco model="m">
  <asset><mesh name="gone" file="missing.stl"/></asset>
  <worldbody>
    <body name="a"><geom type="sphere" size="0.1"/></body>
    <body name="b"><geom type="mesh" mesh="gone"/></body>
  </worldbody>
</mujoco>
"#;
    let r = scratch_files("robots_export", "mjcf_other", &[("m.xml", xml)]);
    let out = massprop(&[
        "export",
        r.to_str().unwrap(),
        "--from-geometry",
        "collision",
        "--link",
        "a",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let m = 1000.0 * 4.0 / 3.0 * std::f64::consts::PI * 0.001;
    close(attr(&text, "mass")[0], m, m);
}

/// A tetrahedron with a fifth triangle of zero area: the mesh reader
/// leaves it out and says so (the answer still exact).
const TET_WITH_SLIVER: &str =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 5 2\n";

/// Stderr of a successful `export ROBOT --from-geometry collision
/// --density 1000`.
fn export_stderr(robot: &Path) -> String {
    let out = run_export(robot, "1000", &[]);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!out.stdout.is_empty());
    stderr
}

#[test]
fn a_urdf_meshs_warning_is_said_at_its_geometry_as_report_says_it() {
    let urdf = "<robot name=\"r\">\n  <link name=\"a\"><collision><geometry><mesh filename=\"s.obj\"/></geometry></collision></link>\n</robot>\n";
    let path = scratch_files(
        "robots_export",
        "sliver-urdf",
        &[("s.obj", TET_WITH_SLIVER), ("r.urdf", urdf)],
    );
    let e = export_stderr(&path);
    assert_eq!(e.matches("warning: ").count(), 1, "{e}");
    assert!(
        e.contains("r.urdf:2:18: link \"a\": the mesh file `")
            && e.contains("a triangle of zero area left out"),
        "{e}"
    );
}

#[test]
fn an_mjcf_meshs_warning_is_said_once_at_its_asset_however_many_geoms_use_it() {
    let xml = "<mujoco>\n  <asset>\n    <mesh name=\"s\" file=\"s.obj\"/>\n  </asset>\n  <worldbody>\n    <body name=\"a\"><freejoint/><geom type=\"mesh\" mesh=\"s\"/></body>\n    <body name=\"b\"><freejoint/><geom type=\"mesh\" mesh=\"s\"/></body>\n  </worldbody>\n</mujoco>\n";
    let path = scratch_files(
        "robots_export",
        "sliver-mjcf",
        &[("s.obj", TET_WITH_SLIVER), ("m.xml", xml)],
    );
    let e = export_stderr(&path);
    assert_eq!(e.matches("warning: ").count(), 1, "{e}");
    assert!(
        e.contains("m.xml:3:5: the mesh file `")
            && e.contains("s.obj`: a triangle of zero area left out"),
        "{e}"
    );
}

/// A unit cube as OBJ, its faces wound outward.
const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

/// `export --from-geometry` of one MJCF body whose geom is the cube mesh
/// of `<mesh inertia=MODE>`, with `args`.
fn mjcf_cube(name: &str, mode: &str, args: &[&str]) -> std::process::Output {
    let xml = format!(
        "<mujoco>\n  <asset><mesh name=\"c\" file=\"c.obj\" inertia=\"{mode}\"/></asset>\n  <worldbody><body name=\"a\"><freejoint/><geom type=\"mesh\" mesh=\"c\"/></body></worldbody>\n</mujoco>\n"
    );
    let path = scratch_files(
        "robots_export",
        name,
        &[("c.obj", CUBE_OBJ), ("m.xml", &xml)],
    );
    run_export(&path, "1000", args)
}

#[test]
fn a_shell_mesh_is_refused_by_export_which_weighs_solids() {
    // MuJoCo weighs a shell by its area (report: 6000 kg here); the export
    // weighs solids, so it refuses rather than give the solid's 1000 kg.
    for args in [&[][..], &["--link", "a"][..]] {
        let out = mjcf_cube("shell", "shell", args);
        let e = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{e}");
        assert!(out.stdout.is_empty());
        assert!(
            e.contains("a shell mesh (`inertia=\"shell\"`) is weighed by `report`, not by `export --from-geometry`"),
            "{e}"
        );
    }
}

#[test]
fn an_exact_mesh_exports_the_solid_cube() {
    let out = mjcf_cube("exact", "exact", &[]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // 1 m³ at 1000 kg/m³; m(a² + a²)/12 about each axis through the centre.
    assert!(text.contains("mass=\"1000\""), "{text}");
    assert!(
        text.contains("166.66666666666666 166.66666666666666 166.66666666666666 0 0 0"),
        "{text}"
    );
}
