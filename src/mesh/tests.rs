//! The readers, the checks and the integrals against independent
//! derivations: a box's closed form, the three formats of one mesh, the
//! bound against a double-double evaluation of the same sums.

use super::*;

/// A box [0, a] × [0, b] × [0, c] + o as 12 outward triangles.
fn box_triangles(a: f64, b: f64, c: f64, o: [f64; 3]) -> Vec<[[f64; 3]; 3]> {
    let v = |x: usize, y: usize, z: usize| {
        [
            o[0] + a * x as f64,
            o[1] + b * y as f64,
            o[2] + c * z as f64,
        ]
    };
    let quads = [
        [v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)],
        [v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)],
        [v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)],
        [v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)],
        [v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)],
        [v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)],
    ];
    quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect()
}

fn ascii(t: &[[[f64; 3]; 3]]) -> Vec<u8> {
    let mut s = String::from("solid test\n");
    for tri in t {
        s.push_str("facet normal 0 0 0\nouter loop\n");
        for p in tri {
            s.push_str(&format!("vertex {:?} {:?} {:?}\n", p[0], p[1], p[2]));
        }
        s.push_str("endloop\nendfacet\n");
    }
    s.push_str("endsolid test\n");
    s.into_bytes()
}

fn binary(t: &[[[f64; 3]; 3]]) -> Vec<u8> {
    let mut b = vec![0u8; 80];
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

fn obj(t: &[[[f64; 3]; 3]]) -> Vec<u8> {
    let mut s = String::from("# test\no box\n");
    for tri in t {
        for p in tri {
            s.push_str(&format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]));
        }
    }
    for i in 0..t.len() {
        s.push_str(&format!(
            "f {} {}/1 {}//2\n",
            3 * i + 1,
            3 * i + 2,
            3 * i + 3
        ));
    }
    s.into_bytes()
}

fn load(format: FileType, bytes: &[u8], mode: Mode) -> Result<MeshBody, MeshError> {
    MeshBody::load(format, bytes, mode)
}

#[test]
fn a_box_has_the_closed_form_of_a_box() {
    let (a, b, c) = (2.0, 3.0, 5.0);
    let m = load(
        FileType::Stl,
        &ascii(&box_triangles(a, b, c, [1.0, -2.0, 7.0])),
        Mode::Solid,
    )
    .unwrap();
    assert_eq!(m.measure.f64(), a * b * c);
    assert_eq!(m.centroid.map(|x| x.f64()), [2.0, -0.5, 9.5]);
    let v = a * b * c;
    let expect = [v * a * a / 12.0, v * b * b / 12.0, v * c * c / 12.0];
    for (i, e) in expect.iter().enumerate() {
        assert!((m.second[i][i].f64() - e).abs() <= 1e-14 * e);
        for j in 0..3 {
            if i != j {
                assert!(m.second[i][j].f64().abs() <= 1e-14 * e);
            }
        }
    }
    // Its surface: area 2(ab + bc + ca).
    let s = load(
        FileType::Stl,
        &ascii(&box_triangles(a, b, c, [0.0; 3])),
        Mode::Shell,
    )
    .unwrap();
    assert_eq!(s.measure.f64(), 2.0 * (a * b + b * c + c * a));
}

#[test]
fn binary_and_ascii_stl_and_obj_of_one_mesh_agree_exactly() {
    // Coordinates exact in f32, so the binary file loses nothing.
    let t = box_triangles(0.5, 1.25, 3.0, [-4.0, 2.5, 0.75]);
    let x = load(FileType::Stl, &ascii(&t), Mode::Solid).unwrap();
    let y = load(FileType::Stl, &binary(&t), Mode::Solid).unwrap();
    let z = load(FileType::Obj, &obj(&t), Mode::Solid).unwrap();
    // ASCII keywords in capitals, as some exporters write them: the same.
    let upper = ascii(&t).to_ascii_uppercase();
    let u = load(FileType::Stl, &upper, Mode::Solid).unwrap();
    assert_eq!(x, y);
    assert_eq!(x, z);
    assert_eq!(x, u);
}

#[test]
fn a_box_far_from_its_origin_keeps_its_own_moments() {
    let near = load(
        FileType::Obj,
        &obj(&box_triangles(1.0, 2.0, 3.0, [0.0; 3])),
        Mode::Solid,
    )
    .unwrap();
    let far = 2f64.powi(40);
    let far = load(
        FileType::Obj,
        &obj(&box_triangles(1.0, 2.0, 3.0, [far, -far, far])),
        Mode::Solid,
    )
    .unwrap();
    assert_eq!(near.measure, far.measure);
    assert_eq!(near.second, far.second);
}

#[test]
fn the_bound_holds_for_an_f64_evaluation_against_double_double() {
    // An irregular closed mesh: a box whose corners are jittered.
    let mut t = box_triangles(1.0, 1.0, 1.0, [1e3, 2e3, -3e3]);
    for tri in &mut t {
        for p in tri.iter_mut() {
            for x in p.iter_mut() {
                *x += (*x * 0.37).sin() * 0.01;
            }
        }
    }
    let at = vec![At::Whole; t.len()];
    let mesh = check::Mesh::weld(read::Triangles::of_corners(t, at)).unwrap();
    for mode in [Mode::Solid, Mode::Shell] {
        let p = mesh.reference();
        let lo = mesh.sums::<f64>(mode, p);
        let hi = mesh.sums::<DD>(mode, p);
        let err = lo.error();
        for (k, e) in err.iter().enumerate() {
            let d = (DD::of(lo.value[k]) - hi.value[k]).f64().abs();
            assert!(d <= *e, "{mode:?} sum {k}: {d:e} > {e:e}");
        }
        let (vl, gl, jl, bl) = finish(mode, &lo);
        let (vh, gh, jh, _) = finish(mode, &hi);
        assert!((DD::of(vl) - vh).f64().abs() <= bl.measure);
        for i in 0..3 {
            assert!((DD::of(gl[i]) - gh[i]).f64().abs() <= bl.centroid);
            for j in 0..3 {
                assert!((DD::of(jl[i][j]) - jh[i][j]).f64().abs() <= bl.second);
            }
        }
    }
}

fn message(format: FileType, bytes: &[u8], mode: Mode) -> String {
    load(format, bytes, mode).unwrap_err().message
}

#[test]
fn each_fault_of_a_surface_is_named() {
    let t = box_triangles(1.0, 1.0, 1.0, [0.0; 3]);
    // A hole: one triangle left out.
    let m = message(FileType::Stl, &ascii(&t[1..]), Mode::Solid);
    assert!(
        m.contains("not closed") && m.contains("belongs to no other triangle"),
        "{m}"
    );
    // …which a shell takes.
    assert!(load(FileType::Stl, &ascii(&t[1..]), Mode::Shell).is_ok());
    // One triangle wound the other way.
    let mut flipped = t.clone();
    flipped[3].swap(1, 2);
    let m = message(FileType::Stl, &ascii(&flipped), Mode::Solid);
    assert!(
        m.contains("not consistently oriented") && m.contains("triangle 4"),
        "{m}"
    );
    // All wound inward.
    let inward: Vec<_> = t.iter().map(|x| [x[0], x[2], x[1]]).collect();
    let m = message(FileType::Stl, &ascii(&inward), Mode::Solid);
    assert!(m.contains("faces point inward; flip the winding"), "{m}");
    // A triangle repeated: its edges are shared by 3 triangles.
    let mut three = t.clone();
    three.push(t[0]);
    let m = message(FileType::Stl, &ascii(&three), Mode::Solid);
    assert!(
        m.contains("triangle 13 (line 86) repeats triangle 1 (line 2)"),
        "{m}"
    );
    // Degenerate: a repeated corner, collinear corners.
    let mut d = t.clone();
    d[0][1] = d[0][0];
    // (left out, with a warning: `check`)
    let (_, notes) = MeshBody::load_with(FileType::Stl, &ascii(&d), Mode::Shell, None).unwrap();
    assert!(
        notes[0].contains("triangle 1 (line 2) is degenerate: two of its corners"),
        "{notes:?}"
    );
    let line = vec![[[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]];
    let m = message(FileType::Stl, &ascii(&line), Mode::Shell);
    assert!(m.contains("zero area"), "{m}");
    // Empty, NaN.
    assert_eq!(
        message(FileType::Stl, b"solid x\nendsolid x\n", Mode::Solid),
        "the mesh has no triangles"
    );
    let mut nan = t.clone();
    nan[5][2][1] = f64::NAN;
    let m = message(FileType::Obj, &obj(&nan), Mode::Solid);
    assert!(m.contains("not a finite number"), "{m}");
}

#[test]
fn hostile_files_are_refused_with_where() {
    let t = box_triangles(1.0, 1.0, 1.0, [0.0; 3]);
    let b = binary(&t);
    // Truncated, and a count that lies (huge).
    let m = message(FileType::Stl, &b[..b.len() - 7], Mode::Solid);
    assert!(
        m.starts_with("byte 80: the header says 12 triangles"),
        "{m}"
    );
    let mut lying = b.clone();
    lying[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let m = message(FileType::Stl, &lying, Mode::Solid);
    assert!(m.contains("4294967295 triangles"), "{m}");
    let m = message(FileType::Stl, &b[..40], Mode::Solid);
    assert!(m.contains("ends after 40 bytes"), "{m}");
    // ASCII: a bad number, a square facet, a file cut inside a facet.
    let m = message(
        FileType::Stl,
        b"solid\nfacet normal 0 0 1\nouter loop\nvertex 1 x 2\n",
        Mode::Solid,
    );
    assert_eq!(m, "line 4: vertex: `x` is not a number");
    let quad = b"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n";
    assert!(
        message(FileType::Stl, quad, Mode::Solid).starts_with("line 7: a facet with more than 3")
    );
    let cut = b"solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";
    assert!(
        message(FileType::Stl, cut, Mode::Solid).contains("ends inside the facet begun on line 2")
    );
    // OBJ: non-UTF-8 where a number is, an index out of range, zero.
    let m = message(FileType::Obj, b"v 0 0 0\nv 1 \xff 0\n", Mode::Solid);
    assert!(
        m.starts_with("line 2: vertex: `") && m.contains("is not a number"),
        "{m}"
    );
    let m = message(
        FileType::Obj,
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
        Mode::Shell,
    );
    assert_eq!(
        m,
        "line 4: face: vertex 4 does not exist (3 vertices are read so far)"
    );
    let m = message(FileType::Obj, b"v 0 0 0\nf 0 1 1\n", Mode::Shell);
    assert!(m.contains("vertex 0 does not exist"), "{m}");
    // Non-UTF-8 in a comment is nothing.
    let ok = b"# \xff\xfe\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n";
    assert!(load(FileType::Obj, ok, Mode::Shell).is_ok());
}

#[test]
fn a_polygon_is_fanned_into_triangles() {
    // A unit square as one quad, shell: area 1, centroid (0.5, 0.5, 0).
    let m = load(
        FileType::Obj,
        b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
        Mode::Shell,
    )
    .unwrap();
    assert_eq!(m.measure.f64(), 1.0);
    assert_eq!(m.centroid.map(|x| x.f64()), [0.5, 0.5, 0.0]);
    // ∫x² dA about the centroid of a unit square: 1/12.
    assert!((m.second[0][0].f64() - 1.0 / 12.0).abs() < 1e-16);
}

#[test]
fn a_reflection_flips_the_centroid_and_the_products_of_its_axis() {
    let mut t = box_triangles(1.0, 2.0, 3.0, [0.5, 0.25, 0.125]);
    // Shear a corner so products are not zero.
    for tri in &mut t {
        for p in tri.iter_mut() {
            p[0] += 0.5 * p[2];
        }
    }
    let m = load(FileType::Obj, &obj(&t), Mode::Solid).unwrap();
    let mirrored: Vec<_> = t
        .iter()
        .map(|x| [x[0], x[2], x[1]].map(|p| [p[0], -p[1], p[2]]))
        .collect();
    let r = load(FileType::Obj, &obj(&mirrored), Mode::Solid).unwrap();
    let f = m.reflected(1);
    assert_eq!(f.measure, r.measure);
    for i in 0..3 {
        assert!((f.centroid[i] - r.centroid[i]).f64().abs() < 1e-28);
        for j in 0..3 {
            assert!((f.second[i][j] - r.second[i][j]).f64().abs() < 1e-28);
        }
    }
}

/// Summed in chunks on any number of threads, the same bits; and the
/// chunked f64 sums within the bound of one recursive sum of all terms,
/// against double-double.
#[test]
fn the_sums_are_the_same_bits_on_any_number_of_threads_and_within_their_bound() {
    let mut t = Vec::new();
    for k in 0..10_000 {
        let o = [
            (k % 100) as f64 * 1.5,
            (k / 100) as f64 * 1.5,
            (k as f64 * 0.1).sin(),
        ];
        t.extend(box_triangles(1.0, 0.5 + (k as f64).cos() * 0.1, 0.75, o));
    }
    assert!(t.len() > 3 * 32_768, "more than three chunks");
    let at = vec![At::Whole; t.len()];
    let mesh = check::Mesh::weld(read::Triangles::of_corners(t, at)).unwrap();
    let p = mesh.reference();
    let one = mesh.sums_on::<f64>(Mode::Solid, p, 1);
    for threads in [2, 3, 8] {
        let many = mesh.sums_on::<f64>(Mode::Solid, p, threads);
        for k in 0..10 {
            assert_eq!(
                one.value[k].to_bits(),
                many.value[k].to_bits(),
                "sum {k}, {threads} threads"
            );
            assert_eq!(one.magnitude[k].to_bits(), many.magnitude[k].to_bits());
        }
        assert_eq!(one.n, many.n);
    }
    let hi = mesh.sums_on::<DD>(Mode::Solid, p, 1);
    for (k, e) in one.error().iter().enumerate() {
        let d = (DD::of(one.value[k]) - hi.value[k]).f64().abs();
        assert!(d <= *e, "sum {k}: {d:e} > {e:e}");
    }
}

#[test]
fn a_truncated_binary_stl_whose_header_begins_with_solid_is_called_truncated() {
    let t = box_triangles(1.0, 1.0, 1.0, [0.0; 3]);
    let mut b = binary(&t);
    b[..11].copy_from_slice(b"solid cube ");
    // Whole, it is binary by its size; cut, it is still binary.
    assert!(load(FileType::Stl, &b, Mode::Solid).is_ok());
    let m = message(FileType::Stl, &b[..b.len() - 30], Mode::Solid);
    assert!(
        m.starts_with("byte 80: the header says 12 triangles")
            && m.contains("a truncated binary STL"),
        "{m}"
    );
}

#[test]
fn an_ascii_stl_that_does_not_parse_is_still_read_as_ascii() {
    let m = message(
        FileType::Stl,
        b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 y 2\n",
        Mode::Solid,
    );
    assert_eq!(m, "line 4: vertex: `y` is not a number");
}

#[test]
fn an_obj_face_is_fanned_as_it_is_read_and_meets_the_limit_at_its_index() {
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf");
    for k in 0..1000 {
        obj.push_str([" 1", " 2", " 3", " 4"][k % 4]);
    }
    obj.push('\n');
    let t = read::read(FileType::Obj, obj.as_bytes(), 10_000).unwrap();
    assert_eq!(t.faces.len(), 998);
    assert_eq!(t.points.len(), 4);
    let e = read::read(FileType::Obj, obj.as_bytes(), 100).unwrap_err();
    assert_eq!(e.at, At::Line(5));
    assert!(
        e.message.contains("more than 100 triangles"),
        "{}",
        e.message
    );
}

#[test]
fn an_obj_face_with_a_bad_index_late_in_a_long_line_is_named() {
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 1 1 0\nf");
    for _ in 0..500 {
        obj.push_str(" 1 2 3");
    }
    obj.push_str(" 9\n");
    let m = message(FileType::Obj, obj.as_bytes(), Mode::Shell);
    assert_eq!(
        m,
        "line 4: face: vertex 9 does not exist (3 vertices are read so far)"
    );
}

#[test]
fn the_first_degenerate_triangle_is_named_on_any_number_of_threads() {
    // 200,000 separate triangles (a shell mesh: no closedness asked), two
    // of them on one line, in different threads' shares.
    let n = 200_000;
    let mut t: Vec<[[f64; 3]; 3]> = (0..n)
        .map(|i| {
            let x = i as f64;
            [[x, 0.0, 0.0], [x + 0.5, 0.0, 0.0], [x, 0.5, 0.0]]
        })
        .collect();
    t[170_000][2] = [170_001.0, 0.0, 0.0];
    t[120_000][2] = [120_000.25, 0.0, 0.0];
    let at = (0..n).map(|_| At::Whole).collect();
    let mesh = check::Mesh::weld(read::Triangles::of_corners(t, at)).unwrap();
    let e = mesh.first_degenerate().expect("degenerate");
    assert!(
        e.message.starts_with("triangle 120001 is degenerate"),
        "{}",
        e.message
    );
}

#[test]
fn the_f64_filter_never_passes_a_triangle_on_one_line() {
    // Corners a, a + d, a + k d exactly (small integers times a power of
    // two), far from the origin and near it: collinear, so degenerate.
    let mut x = 0x853c_49e6_748f_ea9bu64;
    let mut r = |m: u64| {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % m) as f64 - (m / 2) as f64
    };
    for _ in 0..5000 {
        let scale = 2f64.powi(r(200) as i32);
        let a = [r(1 << 20), r(1 << 20), r(1 << 20)].map(|v| v * scale);
        let d = [r(64), r(64), r(64)].map(|v| v * scale);
        let k = r(16);
        if d == [0.0; 3] || k == 0.0 || k == 1.0 {
            continue;
        }
        let b: [f64; 3] = std::array::from_fn(|i| a[i] + d[i]);
        let c: [f64; 3] = std::array::from_fn(|i| a[i] + k * d[i]);
        let t = vec![[a, b, c]];
        let mesh = check::Mesh::weld(read::Triangles::of_corners(t, vec![At::Whole])).unwrap();
        let e = mesh.first_degenerate().expect("collinear");
        assert!(e.message.contains("on one line"), "{}", e.message);
    }
}
