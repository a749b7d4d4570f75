//! Triangle meshes (`shape = "mesh"`) against independent derivations: a
//! finely tessellated box (exact), a UV sphere and a torus converging to
//! their closed forms at the rate the tessellation predicts, thin shells,
//! invariance under translation (10⁹ sizes) and rotation, the three file
//! formats of one mesh, cut-outs, the same box as a `box` part, and each
//! refusal with its message.

use crate::common::{massprop, report_json_file, scratch};
use std::f64::consts::PI;
use std::path::Path;

type Tri = [[f64; 3]; 3];

/// A box [0, a] × [0, b] × [0, c] + o, each face an n × n grid of quads
/// (two triangles each), wound outward.
fn fine_box(a: f64, b: f64, c: f64, o: [f64; 3], n: usize) -> Vec<Tri> {
    let mut t = Vec::new();
    // Face: fixed axis k at side s (0 or 1), spanned by axes u, v.
    for k in 0..3 {
        let (u, v) = ((k + 1) % 3, (k + 2) % 3);
        for side in [0.0, 1.0] {
            let size = [a, b, c];
            let p = |i: usize, j: usize| {
                let mut x = [0.0; 3];
                x[k] = side * size[k];
                x[u] = size[u] * i as f64 / n as f64;
                x[v] = size[v] * j as f64 / n as f64;
                std::array::from_fn(|m| x[m] + o[m])
            };
            for i in 0..n {
                for j in 0..n {
                    let (p00, p10, p11, p01) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
                    // u × v = +k: counter-clockwise seen from +k at side 1.
                    if side == 1.0 {
                        t.push([p00, p10, p11]);
                        t.push([p00, p11, p01]);
                    } else {
                        t.push([p00, p11, p10]);
                        t.push([p00, p01, p11]);
                    }
                }
            }
        }
    }
    t
}

/// A UV sphere of radius r: `n` latitude bands, `2n` longitudes, inscribed.
fn uv_sphere(r: f64, n: usize) -> Vec<Tri> {
    let m = 2 * n;
    let p = |i: usize, j: usize| {
        let th = PI * i as f64 / n as f64;
        let ph = 2.0 * PI * (j % m) as f64 / m as f64;
        if i == 0 {
            return [0.0, 0.0, r];
        }
        if i == n {
            return [0.0, 0.0, -r];
        }
        [
            r * th.sin() * ph.cos(),
            r * th.sin() * ph.sin(),
            r * th.cos(),
        ]
    };
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if i != 0 {
                t.push([a, b, d]);
            }
            if i != n - 1 {
                t.push([b, c, d]);
            }
        }
    }
    t
}

/// A torus of radii R (centre line) and r (tube) about z, n × n.
fn torus(big: f64, small: f64, n: usize) -> Vec<Tri> {
    let p = |i: usize, j: usize| {
        let u = 2.0 * PI * (i % n) as f64 / n as f64;
        let v = 2.0 * PI * (j % n) as f64 / n as f64;
        let w = big + small * v.cos();
        [w * u.cos(), w * u.sin(), small * v.sin()]
    };
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    t
}

fn ascii_stl(t: &[Tri]) -> String {
    let mut s = String::from("solid test\n");
    for tri in t {
        s.push_str(" facet normal 0 0 0\n  outer loop\n");
        for p in tri {
            s.push_str(&format!("   vertex {:?} {:?} {:?}\n", p[0], p[1], p[2]));
        }
        s.push_str("  endloop\n endfacet\n");
    }
    s + "endsolid test\n"
}

fn binary_stl(t: &[Tri]) -> Vec<u8> {
    let mut b = vec![b' '; 80];
    b.extend((t.len() as u32).to_le_bytes());
    for tri in t {
        b.extend([0u8; 12]);
        for p in tri {
            for x in p {
                b.extend((*x as f32).to_le_bytes());
            }
        }
        b.extend([0u8; 2]);
    }
    b
}

/// OBJ with shared vertices (each distinct corner once).
fn obj(t: &[Tri]) -> String {
    let mut index = std::collections::HashMap::new();
    let mut s = String::new();
    let mut faces = String::new();
    for tri in t {
        faces.push('f');
        for p in tri {
            let key = p.map(f64::to_bits);
            let n = index.len() + 1;
            let k = *index.entry(key).or_insert_with(|| {
                s.push_str(&format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]));
                n
            });
            faces.push_str(&format!(" {k}"));
        }
        faces.push('\n');
    }
    s + &faces
}

/// The summary of a part file `toml` in `dir` beside its mesh files.
fn report(dir: &Path, toml: &str) -> serde_json::Value {
    let path = dir.join("parts.toml");
    std::fs::write(&path, toml).unwrap();
    report_json_file(&path, &[]).0
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap()
}

fn vec3(v: &serde_json::Value) -> [f64; 3] {
    std::array::from_fn(|i| num(&v[i]))
}

fn mat(v: &serde_json::Value) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| vec3(&v[i]))
}

fn close(a: f64, b: f64, rel: f64, scale: f64) -> bool {
    (a - b).abs() <= rel * scale
}

fn mesh_part(file: &str, extra: &str) -> String {
    format!("[[part]]\nshape = \"mesh\"\nfile = \"{file}\"\nmesh_unit = \"m\"\n{extra}\n")
}

#[test]
fn a_finely_tessellated_box_is_the_box() {
    let dir = scratch("meshes", "box");
    // Sizes and origin in binary fractions: every corner exact.
    std::fs::write(
        dir.join("b.stl"),
        ascii_stl(&fine_box(2.0, 0.5, 1.25, [0.25, -1.0, 3.0], 8)),
    )
    .unwrap();
    let mesh = report(&dir, &mesh_part("b.stl", "density = 7.5"));
    let boxed = report(
        &dir,
        "[[part]]\nshape = \"box\"\nsize = [2, 0.5, 1.25]\ncenter = [1.25, -0.75, 3.625]\ndensity = 7.5\n",
    );
    assert_eq!(num(&mesh["mass"]), num(&boxed["mass"]));
    assert_eq!(
        vec3(&mesh["center_of_mass"]),
        vec3(&boxed["center_of_mass"])
    );
    let (a, b) = (mat(&mesh["inertia_com"]), mat(&boxed["inertia_com"]));
    for i in 0..3 {
        for j in 0..3 {
            assert!(close(a[i][j], b[i][j], 1e-14, a[0][0]), "{a:?} {b:?}");
        }
    }
}

/// The inscribed UV sphere's volume and moment approach the sphere's as
/// 1/n² (its facets' sag is r(1 − cos(π/2n)) ≈ r π²/8n²): the error at
/// 2n is a quarter of that at n, to within a few per cent.
#[test]
fn a_uv_sphere_converges_to_the_sphere_at_second_order() {
    let dir = scratch("meshes", "sphere");
    let r = 0.75;
    let mut errors = Vec::new();
    for n in [16, 32, 64] {
        std::fs::write(dir.join("s.stl"), ascii_stl(&uv_sphere(r, n))).unwrap();
        let s = report(&dir, &mesh_part("s.stl", "density = 1"));
        let m = num(&s["mass"]);
        let i = mat(&s["inertia_com"]);
        let v = 4.0 / 3.0 * PI * r.powi(3);
        let i_exact = 2.0 / 5.0 * v * r * r;
        errors.push(((v - m) / v, (i_exact - i[2][2]) / i_exact));
        // Centred at the origin by symmetry.
        assert!(vec3(&s["center_of_mass"]).iter().all(|x| x.abs() < 1e-15));
    }
    for w in errors.windows(2) {
        let ratio_v = w[0].0 / w[1].0;
        let ratio_i = w[0].1 / w[1].1;
        assert!((ratio_v - 4.0).abs() < 0.1, "{errors:?}");
        assert!((ratio_i - 4.0).abs() < 0.1, "{errors:?}");
    }
    // And inscribed: smaller than the sphere, by the order of its facets'
    // relative sag (π/n)²/8 (a few times it: the volume is lost over the
    // whole surface, three times the mean sag).
    let sag = (PI / 64.0).powi(2) / 8.0;
    assert!(
        errors[2].0 > 0.0 && errors[2].0 < 6.0 * sag,
        "{errors:?} {sag}"
    );
}

/// A torus: V = 2π²Rr², I_zz = m(R² + 3r²/4), I_xx = m(R²/2 + 5r²/8).
#[test]
fn a_torus_converges_to_the_torus() {
    let dir = scratch("meshes", "torus");
    let (big, small) = (2.0, 0.5);
    let mut last = f64::INFINITY;
    for n in [24, 48, 96] {
        std::fs::write(dir.join("t.obj"), obj(&torus(big, small, n))).unwrap();
        let s = report(&dir, &mesh_part("t.obj", "density = 1"));
        let m = num(&s["mass"]);
        let v = 2.0 * PI * PI * big * small * small;
        let i = mat(&s["inertia_com"]);
        let izz = v * (big * big + 0.75 * small * small);
        let ixx = v * (big * big / 2.0 + 5.0 / 8.0 * small * small);
        let e = ((m - v) / v)
            .abs()
            .max(((i[2][2] - izz) / izz).abs())
            .max(((i[0][0] - ixx) / ixx).abs());
        assert!(e < 4.0 * (PI / n as f64).powi(2), "n {n}: {e}");
        assert!(e < last / 3.5, "n {n}: {e} after {last}");
        last = e;
    }
}

/// A mesh translated 10⁹ of its sizes in its file, against the same mesh
/// placed there by `origin`: the same moments (the sums are about the
/// mesh's own centre), and against a rotation by `rotation` of the file's.
#[test]
fn translation_to_1e9_sizes_and_rotation_change_nothing() {
    let dir = scratch("meshes", "far");
    let shift = 2f64.powi(30);
    let near = fine_box(1.0, 2.0, 0.5, [0.0; 3], 3);
    let far: Vec<Tri> = near
        .iter()
        .map(|t| t.map(|p| [p[0] + shift, p[1] - shift, p[2] + shift]))
        .collect();
    std::fs::write(dir.join("near.obj"), obj(&near)).unwrap();
    std::fs::write(dir.join("far.obj"), obj(&far)).unwrap();
    let a = report(&dir, &mesh_part("far.obj", "mass = 3"));
    let b = report(
        &dir,
        &mesh_part(
            "near.obj",
            &format!("mass = 3\norigin = [{shift:?}, {:?}, {shift:?}]", -shift),
        ),
    );
    assert_eq!(vec3(&a["center_of_mass"]), vec3(&b["center_of_mass"]));
    // The same to double-double's rounding of the sums (each about the
    // mesh's own centre, so nothing of the 2³⁰ offset is left in them).
    let (i, j) = (mat(&a["inertia_com"]), mat(&b["inertia_com"]));
    for r in 0..3 {
        for c in 0..3 {
            assert!(close(i[r][c], j[r][c], 1e-30, 1.0), "{i:?} {j:?}");
        }
    }
    // The box's own: m(b² + c²)/12 …, exactly representable here.
    assert!(
        close(i[0][0], 3.0 * (4.0 + 0.25) / 12.0, 1e-15, 1.0),
        "{i:?}"
    );
    // A quarter turn about z swaps Ixx and Iyy.
    let turned = report(
        &dir,
        &mesh_part(
            "near.obj",
            "mass = 3\nrotation = { axis = [0, 0, 1], degrees = 90 }",
        ),
    );
    let t = mat(&turned["inertia_com"]);
    assert!(close(t[0][0], i[1][1], 1e-15, i[1][1]) && close(t[1][1], i[0][0], 1e-15, i[0][0]));
    // A general turn keeps the principal moments.
    let general = report(
        &dir,
        &mesh_part(
            "near.obj",
            "mass = 3\nrotation = { axis = [1, 2, 3], degrees = 37 }",
        ),
    );
    let (p, q) = (
        vec3(&general["principal_moments"]),
        vec3(&a["principal_moments"]),
    );
    for k in 0..3 {
        assert!(close(p[k], q[k], 1e-14, q[2]), "{p:?} {q:?}");
    }
}

#[test]
fn binary_ascii_stl_and_obj_of_one_mesh_give_identical_results() {
    let dir = scratch("meshes", "formats");
    // f32-exact coordinates: binary STL loses nothing.
    let t = fine_box(1.5, 0.75, 2.0, [0.5, 0.25, -1.0], 4);
    std::fs::write(dir.join("a.stl"), ascii_stl(&t)).unwrap();
    std::fs::write(dir.join("b.stl"), binary_stl(&t)).unwrap();
    std::fs::write(dir.join("c.obj"), obj(&t)).unwrap();
    let results: Vec<serde_json::Value> = ["a.stl", "b.stl", "c.obj"]
        .iter()
        .map(|f| report(&dir, &mesh_part(f, "material = \"aluminium-6061\"")))
        .collect();
    for r in &results[1..] {
        assert_eq!(r["mass"], results[0]["mass"]);
        assert_eq!(r["center_of_mass"], results[0]["center_of_mass"]);
        assert_eq!(r["inertia_com"], results[0]["inertia_com"]);
    }
}

/// Shells: a thin spherical shell (m r²·2/3 per axis) and a box's surface.
#[test]
fn shell_mode_weighs_the_surface() {
    let dir = scratch("meshes", "shell");
    let r = 1.5;
    let mut last = f64::INFINITY;
    for n in [16, 32, 64] {
        std::fs::write(dir.join("s.stl"), ascii_stl(&uv_sphere(r, n))).unwrap();
        let s = report(
            &dir,
            &mesh_part("s.stl", "mode = \"shell\"\nareal_density = 2"),
        );
        let m = num(&s["mass"]);
        let area = 4.0 * PI * r * r;
        let i = mat(&s["inertia_com"]);
        let e = ((m - 2.0 * area) / (2.0 * area))
            .abs()
            .max(((i[1][1] - 2.0 / 3.0 * m * r * r) / (m * r * r)).abs());
        assert!(e < last / 3.5, "{n}: {e} after {last}");
        last = e;
    }
    // A box's surface a × b × c: each face a plate; the sum by hand.
    let (a, b, c) = (1.0, 2.0, 3.0);
    std::fs::write(
        dir.join("b.stl"),
        ascii_stl(&fine_box(a, b, c, [0.0; 3], 2)),
    )
    .unwrap();
    let s = report(
        &dir,
        &mesh_part("b.stl", "mode = \"shell\"\nthickness = 0.5\ndensity = 4"),
    );
    let rho = 2.0;
    let plates = [
        // (area, its own ∫x² about its centre, its offset along x)
        (b * c, 0.0, a / 2.0),
        (a * c, a * a / 12.0, 0.0),
        (a * b, a * a / 12.0, 0.0),
    ];
    let m: f64 = plates.iter().map(|p| 2.0 * rho * p.0).sum();
    let ixx_second: f64 = plates
        .iter()
        .map(|p| 2.0 * rho * p.0 * (p.1 + p.2 * p.2))
        .sum();
    assert!(close(num(&s["mass"]), m, 1e-15, m));
    // I_yy = ∫(x² + z²) dm: by symmetry in the formula, ∫x² from above and
    // ∫z² likewise.
    let plates_z = [
        (a * b, 0.0, c / 2.0),
        (b * c, c * c / 12.0, 0.0),
        (a * c, c * c / 12.0, 0.0),
    ];
    let izz_second: f64 = plates_z
        .iter()
        .map(|p| 2.0 * rho * p.0 * (p.1 + p.2 * p.2))
        .sum();
    let i = mat(&s["inertia_com"]);
    assert!(
        close(i[1][1], ixx_second + izz_second, 1e-14, i[1][1]),
        "{i:?}"
    );
    // An open mesh is a shell, not a solid.
    let open: Vec<Tri> = fine_box(a, b, c, [0.0; 3], 1)[2..].to_vec();
    std::fs::write(dir.join("open.stl"), ascii_stl(&open)).unwrap();
    report(&dir, &mesh_part("open.stl", "mode = \"shell\"\nmass = 1"));
}

#[test]
fn a_removed_mesh_is_a_hole() {
    let dir = scratch("meshes", "remove");
    std::fs::write(
        dir.join("hole.stl"),
        ascii_stl(&fine_box(1.0, 1.0, 1.0, [0.0; 3], 1)),
    )
    .unwrap();
    let with_mesh = report(
        &dir,
        &format!(
            "[[part]]\nshape = \"box\"\nsize = [4, 4, 4]\ncenter = [0, 0, 0]\ndensity = 3\n{}",
            mesh_part("hole.stl", "density = 3\nremove = true\norigin = [1, 1, 1]")
        ),
    );
    let with_box = report(
        &dir,
        "[[part]]\nshape = \"box\"\nsize = [4, 4, 4]\ncenter = [0, 0, 0]\ndensity = 3\n\
         [[part]]\nshape = \"box\"\nsize = [1, 1, 1]\ncenter = [1.5, 1.5, 1.5]\ndensity = 3\nremove = true\n",
    );
    assert_eq!(num(&with_mesh["mass"]), 189.0);
    assert_eq!(with_mesh["center_of_mass"], with_box["center_of_mass"]);
    let (a, b) = (
        mat(&with_mesh["inertia_com"]),
        mat(&with_box["inertia_com"]),
    );
    for i in 0..3 {
        for j in 0..3 {
            assert!(close(a[i][j], b[i][j], 1e-14, a[0][0]));
        }
    }
}

/// Each refusal: status 2, nothing on stdout, the part file's `file` key
/// located and the mesh file and place named.
#[test]
fn each_bad_mesh_is_refused_at_the_file_key_with_its_reason() {
    let dir = scratch("meshes", "bad");
    let good = fine_box(1.0, 1.0, 1.0, [0.0; 3], 1);
    let mut flipped = good.clone();
    flipped[4].swap(0, 1);
    let inward: Vec<Tri> = good.iter().map(|t| [t[0], t[2], t[1]]).collect();
    let mut nan = ascii_stl(&good);
    nan = nan.replacen("vertex 0.0 0.0 0.0", "vertex NaN 0.0 0.0", 1);
    let bin = binary_stl(&good);
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "open.stl",
            ascii_stl(&good[1..]).into_bytes(),
            "the mesh is open (not closed): the edge",
        ),
        (
            "flip.stl",
            ascii_stl(&flipped).into_bytes(),
            "(not consistently oriented): triangle",
        ),
        (
            "inward.stl",
            ascii_stl(&inward).into_bytes(),
            "faces point inward; flip the winding",
        ),
        (
            "nan.stl",
            nan.into_bytes(),
            "has a coordinate that is not a finite number",
        ),
        (
            "empty.stl",
            b"solid e\nendsolid e\n".to_vec(),
            "the mesh has no triangles",
        ),
        (
            "cut.stl",
            bin[..bin.len() - 1].to_vec(),
            "byte 80: the header says 12 triangles",
        ),
        (
            "word.obj",
            b"v 0 0 0\nv 1 0 zero\n".to_vec(),
            "line 2: vertex: `zero` is not a number",
        ),
    ];
    for (name, bytes, expected) in cases {
        std::fs::write(dir.join(name), bytes).unwrap();
        let toml = dir.join("parts.toml");
        std::fs::write(
            &toml,
            format!(
                "[[part]]\nshape = \"mesh\"\nfile = \"{name}\"\nmesh_unit = \"mm\"\ndensity = 1\n"
            ),
        )
        .unwrap();
        let out = massprop(&["report", toml.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(out.stdout.is_empty());
        assert!(err.contains("parts.toml:3:8"), "{name}: {err}");
        assert!(
            err.contains("the mesh file `") && err.contains(name),
            "{name}: {err}"
        );
        assert!(err.contains(expected), "{name}: {err}");
    }
}

#[test]
fn the_keys_of_a_mesh_are_checked() {
    let dir = scratch("meshes", "keys");
    std::fs::write(
        dir.join("b.stl"),
        ascii_stl(&fine_box(1.0, 1.0, 1.0, [0.0; 3], 1)),
    )
    .unwrap();
    std::fs::write(dir.join("b.txt"), "solid").unwrap();
    let cases = [
        (
            "file = \"b.stl\"\ndensity = 1\n",
            "this mesh needs `mesh_unit`",
        ),
        (
            "mesh_unit = \"mm\"\ndensity = 1\n",
            "this mesh needs `file`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mmm\"\ndensity = 1\n",
            "unknown length unit \"mmm\" in `mesh_unit`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\nmode = \"shel\"\ndensity = 1\n",
            "unknown mesh mode \"shel\"",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\n",
            "this mesh needs `mass`, `density` or `material`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\nmass = 1\ndensity = 2\n",
            "`density` conflicts with `mass`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\nareal_density = 2\n",
            "`areal_density` applies to a mesh with `mode = \"shell\"`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\ndensity = 2\n",
            "a shell mesh's `density` needs `thickness`",
        ),
        (
            "file = \"b.stl\"\nmesh_unit = \"mm\"\nsize = [1, 2, 3]\nmass = 1\n",
            "`size` does not apply to a mesh",
        ),
        (
            "file = \"b.txt\"\nmesh_unit = \"mm\"\nmass = 1\n",
            "is not a mesh file (`*.stl` or `*.obj`)",
        ),
        (
            "file = \"../../../../../../../../etc/passwd.stl\"\nmesh_unit = \"mm\"\nmass = 1\n",
            "cannot read the mesh file",
        ),
        (
            "file = \"missing.obj\"\nmesh_unit = \"mm\"\nmass = 1\n",
            "cannot read the mesh file",
        ),
    ];
    for (keys, expected) in cases {
        let toml = dir.join("parts.toml");
        std::fs::write(&toml, format!("[[part]]\nshape = \"mesh\"\n{keys}")).unwrap();
        let out = massprop(&["check", toml.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{keys}: {err}");
        assert!(err.contains(expected), "{keys}: {err}");
    }
}

/// A mesh file outside the part file's directory tree (and the working
/// directory's) is refused as an include is, before it is read.
#[test]
fn a_mesh_file_outside_the_allowed_trees_is_refused() {
    let dir = scratch("meshes", "confined");
    let inner = dir.join("inner");
    std::fs::create_dir_all(&inner).unwrap();
    std::fs::write(
        dir.join("outside.stl"),
        ascii_stl(&fine_box(1.0, 1.0, 1.0, [0.0; 3], 1)),
    )
    .unwrap();
    let toml = inner.join("parts.toml");
    std::fs::write(&toml, mesh_part("../outside.stl", "mass = 1")).unwrap();
    // Run from `inner` so that the working directory does not contain it.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["check", toml.to_str().unwrap()])
        .current_dir(&inner)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("is outside the directory of the part file"),
        "{err}"
    );
    // `--include-root` allows it.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args([
            "check",
            toml.to_str().unwrap(),
            "--include-root",
            dir.to_str().unwrap(),
        ])
        .current_dir(&inner)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A mesh in millimetres in a file of metres, and in an included
/// sub-assembly in inches: the mesh unit and the frames scale it.
#[test]
fn mesh_units_and_includes_scale_the_mesh() {
    let dir = scratch("meshes", "units");
    std::fs::write(
        dir.join("b.stl"),
        ascii_stl(&fine_box(10.0, 20.0, 40.0, [0.0; 3], 1)),
    )
    .unwrap();
    let s = report(
        &dir,
        "[[part]]\nshape = \"mesh\"\nfile = \"b.stl\"\nmesh_unit = \"mm\"\ndensity = \"1 g/cm^3\"\n",
    );
    // 8 cm³ of water: 8 g.
    assert!(close(num(&s["mass"]), 0.008, 1e-15, 0.008));
    assert!(close(vec3(&s["center_of_mass"])[2], 0.02, 1e-15, 0.02));
    std::fs::write(
        dir.join("sub.toml"),
        "units = { length = \"in\" }\n[[part]]\nshape = \"mesh\"\nfile = \"b.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\nareal_density = \"1 kg/m^2\"\norigin = [1, 0, 0]\n",
    )
    .unwrap();
    let s = report(
        &dir,
        "[[part]]\ninclude = \"sub.toml\"\norigin = [0, 0, 1]\n",
    );
    let area = 2.0 * (10.0 * 20.0 + 20.0 * 40.0 + 40.0 * 10.0) * 1e-6;
    assert!(close(num(&s["mass"]), area, 1e-15, area));
    let c = vec3(&s["center_of_mass"]);
    assert!(
        close(c[0], 0.0254 + 0.005, 1e-15, 1.0) && close(c[2], 1.02, 1e-15, 1.0),
        "{c:?}"
    );
}

// ---- Shells: several pieces, cavities, crossings (issue 28, item 3) ----

/// A box by its least corner and sizes, `n` × `n` quads a face, wound
/// inward when `inward`.
fn box_at(lo: [f64; 3], size: [f64; 3], inward: bool) -> Vec<Tri> {
    let t = fine_box(size[0], size[1], size[2], lo, 1);
    if inward {
        t.into_iter().map(|x| [x[0], x[2], x[1]]).collect()
    } else {
        t
    }
}

/// Mass, centre of mass and inertia about it of boxes of density `rho`
/// (a negative sign: a cavity), each by its corner and sizes, composed by
/// the parallel-axis theorem: the closed form the mesh must give.
fn boxes_closed_form(
    rho: f64,
    boxes: &[([f64; 3], [f64; 3], f64)],
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let mut m = 0.0;
    let mut first = [0.0; 3];
    for (lo, s, sign) in boxes {
        let mi = sign * rho * s[0] * s[1] * s[2];
        m += mi;
        for k in 0..3 {
            first[k] += mi * (lo[k] + s[k] / 2.0);
        }
    }
    let c = first.map(|f| f / m);
    let mut i = [[0.0; 3]; 3];
    for (lo, s, sign) in boxes {
        let mi = sign * rho * s[0] * s[1] * s[2];
        let d: [f64; 3] = std::array::from_fn(|k| lo[k] + s[k] / 2.0 - c[k]);
        let own = [
            mi * (s[1] * s[1] + s[2] * s[2]) / 12.0,
            mi * (s[0] * s[0] + s[2] * s[2]) / 12.0,
            mi * (s[0] * s[0] + s[1] * s[1]) / 12.0,
        ];
        let dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        for a in 0..3 {
            for b in 0..3 {
                let kron = if a == b { 1.0 } else { 0.0 };
                i[a][b] += kron * own[a] + mi * (kron * dd - d[a] * d[b]);
            }
        }
    }
    (m, c, i)
}

/// The mesh of `tris` (ASCII STL) reported at density `rho`: mass, centre
/// of mass, inertia about it.
fn mesh_of(dir: &Path, tris: &[Tri], rho: f64) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    std::fs::write(dir.join("m.stl"), ascii_stl(tris)).unwrap();
    let r = report(dir, &mesh_part("m.stl", &format!("density = {rho}")));
    (
        num(&r["mass"]),
        vec3(&r["center_of_mass"]),
        mat(&r["inertia_com"]),
    )
}

fn assert_matches(got: (f64, [f64; 3], [[f64; 3]; 3]), want: (f64, [f64; 3], [[f64; 3]; 3])) {
    let (m, c, i) = got;
    let (wm, wc, wi) = want;
    assert!(close(m, wm, 1e-12, wm), "mass {m} against {wm}");
    let size = wc.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for k in 0..3 {
        assert!(
            close(c[k], wc[k], 1e-12, size),
            "centre {c:?} against {wc:?}"
        );
    }
    let scale = wi[0][0].abs().max(wi[1][1].abs()).max(wi[2][2].abs());
    for a in 0..3 {
        for b in 0..3 {
            assert!(
                close(i[a][b], wi[a][b], 1e-11, scale),
                "inertia {i:?} against {wi:?}"
            );
        }
    }
}

/// A mesh refused at the part's `file` key, status 2, nothing on stdout:
/// the message.
fn refused_mesh(dir: &Path, tris: &[Tri]) -> String {
    std::fs::write(dir.join("m.stl"), ascii_stl(tris)).unwrap();
    let toml = dir.join("parts.toml");
    std::fs::write(&toml, mesh_part("m.stl", "density = 1")).unwrap();
    let out = massprop(&["report", toml.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(
        err.contains("parts.toml:3:8") && err.contains("the mesh file `") && err.contains("m.stl`"),
        "{err}"
    );
    err
}

#[test]
fn two_disjoint_cubes_weigh_the_sum_of_their_masses() {
    let dir = scratch("meshes", "two-cubes");
    let (a, b) = (
        ([0.0; 3], [1.0, 2.0, 0.5], 1.0),
        ([3.0, -1.0, 0.25], [0.5, 0.5, 1.5], 1.0),
    );
    let mut t = box_at(a.0, a.1, false);
    t.extend(box_at(b.0, b.1, false));
    assert_matches(mesh_of(&dir, &t, 2.5), boxes_closed_form(2.5, &[a, b]));
}

#[test]
fn a_cube_with_an_inward_cube_inside_weighs_the_difference() {
    let dir = scratch("meshes", "hollow");
    let outer = ([0.0; 3], [4.0, 3.0, 2.0], 1.0);
    let cavity = ([0.5, 1.0, 0.25], [1.0, 1.5, 1.0], -1.0);
    let mut t = box_at(outer.0, outer.1, false);
    t.extend(box_at(cavity.0, cavity.1, true));
    assert_matches(
        mesh_of(&dir, &t, 7.0),
        boxes_closed_form(7.0, &[outer, cavity]),
    );
}

#[test]
fn two_cubes_sharing_a_face_weigh_the_sum() {
    let dir = scratch("meshes", "face");
    let (a, b) = (([0.0; 3], [1.0; 3], 1.0), ([1.0, 0.0, 0.0], [1.0; 3], 1.0));
    let mut t = box_at(a.0, a.1, false);
    t.extend(box_at(b.0, b.1, false));
    assert_matches(mesh_of(&dir, &t, 3.0), boxes_closed_form(3.0, &[a, b]));
}

#[test]
fn two_cubes_sharing_an_edge_weigh_the_sum() {
    let dir = scratch("meshes", "edge");
    let (a, b) = (([0.0; 3], [1.0; 3], 1.0), ([1.0, 1.0, 0.0], [1.0; 3], 1.0));
    let mut t = box_at(a.0, a.1, false);
    t.extend(box_at(b.0, b.1, false));
    assert_matches(mesh_of(&dir, &t, 3.0), boxes_closed_form(3.0, &[a, b]));
}

#[test]
fn two_cubes_sharing_a_corner_weigh_the_sum() {
    let dir = scratch("meshes", "corner");
    let (a, b) = (([0.0; 3], [1.0; 3], 1.0), ([1.0, 1.0, 1.0], [1.0; 3], 1.0));
    let mut t = box_at(a.0, a.1, false);
    t.extend(box_at(b.0, b.1, false));
    assert_matches(mesh_of(&dir, &t, 3.0), boxes_closed_form(3.0, &[a, b]));
}

#[test]
fn two_overlapping_cubes_are_refused_naming_two_triangles_that_cross() {
    let dir = scratch("meshes", "overlap");
    let mut t = box_at([0.0; 3], [1.0; 3], false);
    t.extend(box_at([0.5, 0.25, 0.25], [1.0; 3], false));
    let err = refused_mesh(&dir, &t);
    assert!(err.contains("shells intersect or overlap"), "{err}");
    // Two triangles by number and line: "triangle N (line L) and triangle M (line K) cross".
    assert_eq!(err.matches("triangle ").count(), 2, "{err}");
    assert!(err.contains(" cross: "), "{err}");
}

#[test]
fn a_cube_folded_through_itself_is_refused() {
    let dir = scratch("meshes", "fold");
    let t: Vec<Tri> = box_at([0.0; 3], [1.0; 3], false)
        .into_iter()
        .map(|tri| {
            tri.map(|p| {
                if p == [1.0, 1.0, 1.0] {
                    [1.0, 1.0, -1.0]
                } else {
                    p
                }
            })
        })
        .collect();
    let err = refused_mesh(&dir, &t);
    assert!(err.contains("the surface intersects itself"), "{err}");
}

#[test]
fn an_inward_shell_alone_is_refused() {
    let dir = scratch("meshes", "inward-alone");
    let err = refused_mesh(&dir, &box_at([0.0; 3], [1.0; 3], true));
    assert!(
        err.contains("faces point inward; flip the winding"),
        "{err}"
    );
}

#[test]
fn an_inward_shell_outside_the_outward_one_is_refused() {
    let dir = scratch("meshes", "inward-outside");
    let mut t = box_at([0.0; 3], [1.0; 3], false);
    t.extend(box_at([2.0, 0.0, 0.0], [1.0; 3], true));
    let err = refused_mesh(&dir, &t);
    assert!(
        err.contains("shell 2 (from triangle 13 (line 86))") && err.contains("a cavity of nothing"),
        "{err}"
    );
}

#[test]
fn an_outward_shell_inside_another_outward_shell_is_refused() {
    let dir = scratch("meshes", "nested-outward");
    let mut t = box_at([0.0; 3], [4.0; 3], false);
    t.extend(box_at([1.0; 3], [1.0; 3], false));
    let err = refused_mesh(&dir, &t);
    assert!(
        err.contains("shell 2") && err.contains("would count twice"),
        "{err}"
    );
}

/// Boxes in cells 3 apart along x (they may touch the next cell's box
/// face to face, never overlap): sizes and offsets in eighths.
fn disjoint_boxes() -> impl proptest::strategy::Strategy<Value = Vec<([f64; 3], [f64; 3])>> {
    use proptest::prelude::*;
    prop::collection::vec(
        (
            (0u8..=8, 0u8..=16, 0u8..=16),
            (4u8..=16, 4u8..=16, 4u8..=16),
        ),
        1..5,
    )
    .prop_map(|cells| {
        cells
            .into_iter()
            .enumerate()
            .map(|(i, ((x, y, z), (a, b, c)))| {
                let e = |k: u8| f64::from(k) / 8.0;
                ([3.0 * i as f64 + e(x), e(y), e(z)], [e(a), e(b), e(c)])
            })
            .collect()
    })
}

fn runner(cases: u32) -> proptest::test_runner::TestRunner {
    use proptest::test_runner::{Config, RngAlgorithm, TestRunner};
    let mut config = Config::with_cases(cases);
    config.failure_persistence = None;
    config.rng_algorithm = RngAlgorithm::ChaCha;
    config.max_shrink_iters = 64;
    TestRunner::new_with_rng(
        config.clone(),
        proptest::test_runner::TestRng::deterministic_rng(config.rng_algorithm),
    )
}

#[test]
fn random_disjoint_boxes_weigh_the_sum_of_their_closed_forms() {
    let dir = scratch("meshes", "prop-disjoint");
    runner(24)
        .run(&disjoint_boxes(), |boxes| {
            let t: Vec<Tri> = boxes
                .iter()
                .flat_map(|(lo, s)| box_at(*lo, *s, false))
                .collect();
            let want: Vec<_> = boxes.iter().map(|(lo, s)| (*lo, *s, 1.0)).collect();
            assert_matches(mesh_of(&dir, &t, 1.5), boxes_closed_form(1.5, &want));
            Ok(())
        })
        .unwrap();
}

#[test]
fn random_overlapping_pairs_of_boxes_are_refused() {
    use proptest::prelude::*;
    let dir = scratch("meshes", "prop-overlap");
    let pairs = (
        (4u8..=16, 4u8..=16, 4u8..=16),
        (1u8..=7, 1u8..=7, 1u8..=7),
        (4u8..=16, 4u8..=16, 4u8..=16),
    );
    runner(24)
        .run(&pairs, |((a, b, c), (fx, fy, fz), (p, q, r))| {
            let e = |k: u8| f64::from(k) / 8.0;
            let size = [e(a), e(b), e(c)];
            // The second box's least corner strictly inside the first.
            let lo = [size[0] * e(fx), size[1] * e(fy), size[2] * e(fz)];
            let mut t = box_at([0.0; 3], size, false);
            t.extend(box_at(lo, [e(p), e(q), e(r)], false));
            let err = refused_mesh(&dir, &t);
            prop_assert!(
                err.contains(" cross: ") || err.contains("would count twice"),
                "{}",
                err
            );
            Ok(())
        })
        .unwrap();
}
