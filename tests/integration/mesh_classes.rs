//! Each class of mesh (issue 30 item 3), built here as STL or OBJ: the
//! closed ones that are not manifold, have zero-area triangles or
//! T-junctions are answered exactly (against the exact rational integrals
//! of their triangles) with one warning; a repeated triangle, an open
//! edge, an inside-out surface are refused in those words; `weld` merges a
//! gap and its bound holds the unwelded and the welded meshes' exact
//! values.

use crate::common::{massprop, scratch};
use crate::support::reference::{Q, f, q};
use num_traits::{Signed, Zero};
use std::path::Path;

type Tri = [[f64; 3]; 3];

/// A cube of side `s` from `lo`, two triangles a face, wound outward.
fn cube(lo: [f64; 3], s: f64) -> Vec<Tri> {
    let p = |i: usize, j: usize, k: usize| {
        [
            lo[0] + s * i as f64,
            lo[1] + s * j as f64,
            lo[2] + s * k as f64,
        ]
    };
    let quads = [
        [p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)],
        [p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)],
        [p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)],
        [p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)],
        [p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)],
        [p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)],
    ];
    quads
        .iter()
        .flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]])
        .collect()
}

/// The unit cube with its top face fanned from (0, 0, 1) through the
/// midpoint (0.5, 1, 1) of its edge with the face y = 1: a T-junction.
fn t_junction() -> Vec<Tri> {
    let c = cube([0.0; 3], 1.0);
    let top = [
        [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0]],
        [[0.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.5, 1.0, 1.0]],
        [[0.0, 0.0, 1.0], [0.5, 1.0, 1.0], [0.0, 1.0, 1.0]],
    ];
    c[..2].iter().chain(&top).chain(&c[4..]).copied().collect()
}

fn stl(t: &[Tri]) -> String {
    let mut s = String::from("solid t\n");
    for tri in t {
        s.push_str(" facet normal 0 0 0\n  outer loop\n");
        for p in tri {
            s.push_str(&format!("   vertex {:?} {:?} {:?}\n", p[0], p[1], p[2]));
        }
        s.push_str("  endloop\n endfacet\n");
    }
    s + "endsolid t\n"
}

fn obj(t: &[Tri]) -> String {
    let mut s = String::new();
    for p in t.iter().flatten() {
        s.push_str(&format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]));
    }
    for i in 0..t.len() {
        s.push_str(&format!("f {} {} {}\n", 3 * i + 1, 3 * i + 2, 3 * i + 3));
    }
    s
}

/// Mass (density 1), centre of mass and inertia about it of the solid
/// the triangles bound, exactly, as the divergence sum about `p` gives it.
fn exact(t: &[Tri], p: [f64; 3]) -> (Q, [Q; 3], [[Q; 3]; 3]) {
    let mut v = Q::zero();
    let mut s: [Q; 3] = std::array::from_fn(|_| Q::zero());
    let mut c: [[Q; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| Q::zero()));
    for tri in t {
        let [a, b, d] = tri.map(|x| -> [Q; 3] { std::array::from_fn(|k| q(x[k]) - q(p[k])) });
        let x = [
            &b[1] * &d[2] - &b[2] * &d[1],
            &b[2] * &d[0] - &b[0] * &d[2],
            &b[0] * &d[1] - &b[1] * &d[0],
        ];
        let w = &a[0] * &x[0] + &a[1] * &x[1] + &a[2] * &x[2];
        let sum: [Q; 3] = std::array::from_fn(|i| &a[i] + &b[i] + &d[i]);
        v += &w / q(6.0);
        for i in 0..3 {
            s[i] += &w * &sum[i] / q(24.0);
            for j in 0..3 {
                c[i][j] += &w * (&a[i] * &a[j] + &b[i] * &b[j] + &d[i] * &d[j] + &sum[i] * &sum[j])
                    / q(120.0);
            }
        }
    }
    let g: [Q; 3] = std::array::from_fn(|i| &s[i] / &v);
    let about: [[Q; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| &c[i][j] - &v * &g[i] * &g[j]));
    let tr = &about[0][0] + &about[1][1] + &about[2][2];
    let inertia = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let e = if i == j { tr.clone() } else { Q::zero() };
            e - &about[i][j]
        })
    });
    let com = std::array::from_fn(|i| q(p[i]) + &g[i]);
    (v, com, inertia)
}

/// A part file of one mesh (`name`, its text `mesh`) at density 1.
fn run(dir: &Path, name: &str, mesh: &str, extra: &str) -> std::process::Output {
    std::fs::write(dir.join(name), mesh).unwrap();
    let toml = dir.join("parts.toml");
    std::fs::write(
        &toml,
        format!(
            "[[part]]\nshape = \"mesh\"\nfile = \"{name}\"\nmesh_unit = \"m\"\ndensity = 1\n{extra}"
        ),
    )
    .unwrap();
    massprop(&["report", "--format", "json", toml.to_str().unwrap()])
}

/// The JSON and the mesh warnings of an answered mesh.
fn answered(dir: &Path, name: &str, mesh: &str, extra: &str) -> (serde_json::Value, Vec<String>) {
    let out = run(dir, name, mesh, extra);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{err}");
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let warnings = j["warnings"]
        .as_array()
        .map_or(&[][..], Vec::as_slice)
        .iter()
        .filter(|w| w["kind"] == "mesh")
        .map(|w| {
            format!(
                "{}:{}: {}",
                w["line"],
                w["column"],
                w["message"].as_str().unwrap()
            )
        })
        .collect();
    (j, warnings)
}

fn refused(dir: &Path, name: &str, mesh: &str) -> String {
    let out = run(dir, name, mesh, "");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(err.contains("parts.toml:3:8"), "{err}");
    err
}

/// Every value of mass, centre and inertia within its bound of the exact.
fn within_bounds(j: &serde_json::Value, want: &(Q, [Q; 3], [[Q; 3]; 3])) {
    let b = &j["error_bounds"];
    let off = |got: &serde_json::Value, want: &Q| (q(got.as_f64().unwrap()) - want).abs();
    assert!(
        off(&j["mass"], &want.0) <= q(b["mass"].as_f64().unwrap()),
        "mass {}",
        j["mass"]
    );
    for i in 0..3 {
        let c = off(&j["center_of_mass"][i], &want.1[i]);
        assert!(
            c <= q(b["center_of_mass"][i].as_f64().unwrap()),
            "centre {i}: {}",
            f(&c)
        );
        for k in 0..3 {
            let e = off(&j["inertia_com"][i][k], &want.2[i][k]);
            assert!(
                e <= q(b["inertia_com"][i][k].as_f64().unwrap()),
                "inertia {i}{k}: {}",
                f(&e)
            );
        }
    }
}

#[test]
fn two_cubes_touching_along_an_edge_are_answered_exactly_with_one_warning() {
    let dir = scratch("mesh_classes", "edge");
    let mut t = cube([0.0; 3], 1.0);
    t.extend(cube([1.0, 1.0, 0.0], 1.0));
    let (j, w) = answered(&dir, "m.stl", &stl(&t), "");
    within_bounds(&j, &exact(&t, [1.0, 1.0, 0.5]));
    assert_eq!(j["mass"], 2.0);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("3:8: the mesh file `")
            && w[0].contains("m.stl`: the mesh is not manifold: the edge (1, 1, 0) – (1, 1, 1) is shared by 4 triangles"),
        "{w:?}"
    );
    assert!(w[0].contains("still exact"), "{w:?}");
}

#[test]
fn a_t_junction_is_answered_exactly_with_one_warning() {
    let dir = scratch("mesh_classes", "tjunction");
    let t = t_junction();
    let (j, w) = answered(&dir, "m.stl", &stl(&t), "");
    within_bounds(&j, &exact(&t, [0.5; 3]));
    assert_eq!(j["mass"], 1.0);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("T-junctions (1 corner inside another triangle's edge)")
            && w[0].contains("still exact"),
        "{w:?}"
    );
}

#[test]
fn a_zero_area_sliver_is_left_out_and_the_answer_is_exact() {
    let dir = scratch("mesh_classes", "sliver");
    let mut t = t_junction();
    // The sliver that closes the T-junction edge by edge.
    t.push([[1.0, 1.0, 1.0], [0.0, 1.0, 1.0], [0.5, 1.0, 1.0]]);
    let (j, w) = answered(&dir, "m.obj", &obj(&t), "");
    within_bounds(&j, &exact(&t, [0.5; 3]));
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(
        w[0].contains("a triangle of zero area left out (triangle 14 (line 56) is degenerate"),
        "{w:?}"
    );
    assert!(w[1].contains("T-junctions"), "{w:?}");
}

#[test]
fn a_triangle_with_a_repeated_corner_is_left_out() {
    let dir = scratch("mesh_classes", "repeated-corner");
    let mut t = cube([0.0; 3], 2.0);
    t.insert(3, [[0.0; 3], [0.0; 3], [2.0, 2.0, 2.0]]);
    let (j, w) = answered(&dir, "m.stl", &stl(&t), "");
    within_bounds(&j, &exact(&t, [1.0; 3]));
    assert_eq!(j["mass"], 8.0);
    assert!(
        w.len() == 1 && w[0].contains("triangle 4 (line 23) is degenerate: two of its corners"),
        "{w:?}"
    );
}

#[test]
fn a_repeated_triangle_is_refused_naming_both() {
    let dir = scratch("mesh_classes", "repeat");
    let mut t = cube([0.0; 3], 1.0);
    t.push(t[4]);
    let err = refused(&dir, "m.stl", &stl(&t));
    assert!(
        err.contains("triangle 13 (line 86) repeats triangle 5 (line 30)") && err.contains("twice"),
        "{err}"
    );
}

#[test]
fn an_open_edge_is_refused_as_open() {
    let dir = scratch("mesh_classes", "open");
    let t = cube([0.0; 3], 1.0);
    let err = refused(&dir, "m.obj", &obj(&t[1..]));
    assert!(
        err.contains("the mesh is open (not closed): the edge"),
        "{err}"
    );
}

#[test]
fn a_t_junction_that_does_not_close_is_refused_as_open() {
    let dir = scratch("mesh_classes", "open-junction");
    let mut t = t_junction();
    // The fan's last triangle stops short of the edge's end.
    t[4][2] = [0.25, 1.0, 1.0];
    let err = refused(&dir, "m.stl", &stl(&t));
    assert!(err.contains("the mesh is open"), "{err}");
}

#[test]
fn a_surface_wound_inward_is_refused_as_inside_out() {
    let dir = scratch("mesh_classes", "inward");
    let t: Vec<Tri> = cube([0.0; 3], 1.0)
        .iter()
        .map(|x| [x[0], x[2], x[1]])
        .collect();
    assert!(
        refused(&dir, "m.stl", &stl(&t)).contains("the mesh is inside out: its volume is negative")
    );
}

#[test]
fn one_triangle_wound_the_other_way_is_refused_as_inside_out_in_part() {
    let dir = scratch("mesh_classes", "flipped");
    let mut t = cube([0.0; 3], 1.0);
    t[3].swap(1, 2);
    let err = refused(&dir, "m.stl", &stl(&t));
    assert!(
        err.contains("the mesh is inside out in part") && err.contains("triangle 4"),
        "{err}"
    );
}

/// The unit cube with the corner (1, 1, 1) of its last triangle that has
/// it moved `gap` along x (the earlier triangles keep it: it welds there).
fn gapped(gap: f64) -> Vec<Tri> {
    let mut t = cube([0.0; 3], 1.0);
    assert_eq!(t[11][1], [1.0; 3]);
    t[11][1][0] += gap;
    t
}

#[test]
fn a_gap_is_open_without_weld() {
    let dir = scratch("mesh_classes", "gap");
    assert!(refused(&dir, "m.stl", &stl(&gapped(1e-6))).contains("the mesh is open"));
}

#[test]
fn weld_merges_the_gap_warns_and_bounds_both_meshes() {
    let dir = scratch("mesh_classes", "weld");
    let t = gapped(1e-6);
    let (j, w) = answered(&dir, "m.stl", &stl(&t), "weld = \"0.01 mm\"\n");
    assert!(
        w.len() == 1
            && w[0].starts_with("6:8: the mesh file `")
            && w[0].contains("m.stl`: `weld` merged 1 corner"),
        "{w:?}"
    );
    // The welded mesh is the unit cube; the file's corners summed about
    // the same point (its box's centre) differ from it by ~1e-7.
    within_bounds(&j, &exact(&cube([0.0; 3], 1.0), [0.5; 3]));
    let unwelded = exact(&t, [0.5; 3]);
    assert!(
        (unwelded.0.clone() - q(1.0)).abs() > q(1e-8),
        "the gap moves the volume"
    );
    within_bounds(&j, &unwelded);
    // …and the bound is of the gap's size, not vacuous.
    assert!(j["error_bounds"]["mass"].as_f64().unwrap() < 1e-4);
}

#[test]
fn weld_is_never_applied_by_default_and_not_to_a_shell() {
    let dir = scratch("mesh_classes", "weld-shell");
    let out = run(
        &dir,
        "m.stl",
        &stl(&gapped(1e-6)),
        "mode = \"shell\"\nthickness = 1\nweld = \"1 mm\"\n",
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("`weld` applies to a solid mesh"), "{err}");
}

#[test]
fn weld_bounds_several_gaps_in_a_box_away_from_the_origin() {
    let dir = scratch("mesh_classes", "weld-gaps");
    let lo = [3.0, -2.0, 5.0];
    let welded = cube(lo, 2.0);
    let mut t = welded.clone();
    // A corner each of three later triangles moved off its place in
    // different directions (each first used, in place, by an earlier one).
    for (i, k) in [(5usize, 1.0), (8, -3.0), (11, 2.0)] {
        t[i][0] = [
            t[i][0][0] + k * 1e-7,
            t[i][0][1] - k * 2e-7,
            t[i][0][2] + k * 0.5e-7,
        ];
    }
    let (j, w) = answered(&dir, "m.obj", &obj(&t), "weld = \"0.001 mm\"\n");
    assert!(w[0].contains("`weld` merged 3 corners"), "{w:?}");
    let p = [4.0, -1.0, 6.0];
    let unwelded = exact(&t, p);
    assert!(
        (unwelded.0.clone() - q(8.0)).abs() > q(1e-8),
        "the gaps move the volume"
    );
    within_bounds(&j, &exact(&welded, p));
    within_bounds(&j, &unwelded);
    assert!(j["error_bounds"]["mass"].as_f64().unwrap() < 1e-3);
}

#[test]
fn a_lid_joined_to_its_box_only_by_t_junctions_is_one_solid() {
    let dir = scratch("mesh_classes", "lid");
    let c = cube([0.0; 3], 1.0);
    // The top fanned from its centre through every edge's midpoint: no
    // edge of it is an edge of a side.
    let ring = [
        [0.0, 0.0],
        [0.5, 0.0],
        [1.0, 0.0],
        [1.0, 0.5],
        [1.0, 1.0],
        [0.5, 1.0],
        [0.0, 1.0],
        [0.0, 0.5],
    ];
    let mut t: Vec<Tri> = c[..2].iter().chain(&c[4..]).copied().collect();
    for i in 0..8 {
        let (a, b) = (ring[i], ring[(i + 1) % 8]);
        t.push([[0.5, 0.5, 1.0], [a[0], a[1], 1.0], [b[0], b[1], 1.0]]);
    }
    let (j, w) = answered(&dir, "m.stl", &stl(&t), "");
    within_bounds(&j, &exact(&t, [0.5; 3]));
    assert_eq!(j["mass"], 1.0);
    assert!(
        w.len() == 1 && w[0].contains("T-junctions (4 corners inside"),
        "{w:?}"
    );
}
