//! Arrays and mirrors (`array`, `mirror` on any part): each against the
//! same parts spelt out in a second file, against the reflection S J S
//! formed here, by invariants, and their names, errors and limits.

use crate::common::{massprop, report_json, scratch};
use serde_json::Value;

/// `report --precision standard` of `text`: mass, centre of mass and
/// inertia about it, as f64.
fn body(text: &str) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let (v, _) = report_json(text, &["--precision", "standard"]);
    let f = |x: &Value| x.as_f64().unwrap();
    let c = &v["center_of_mass"];
    let j = &v["inertia_com"];
    (
        f(&v["mass"]),
        std::array::from_fn(|i| f(&c[i])),
        std::array::from_fn(|i| std::array::from_fn(|k| f(&j[i][k]))),
    )
}

fn names(text: &str) -> Vec<String> {
    let (v, _) = report_json(text, &[]);
    v["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap().to_string())
        .collect()
}

/// Bit for bit the same body.
fn same_bits(a: &str, b: &str) {
    let (x, y) = (body(a), body(b));
    assert_eq!(x.0.to_bits(), y.0.to_bits(), "mass\n{a}\n{b}");
    for i in 0..3 {
        assert_eq!(
            x.1[i].to_bits(),
            y.1[i].to_bits(),
            "centre {i}: {x:?} {y:?}"
        );
        for k in 0..3 {
            assert_eq!(
                x.2[i][k].to_bits(),
                y.2[i][k].to_bits(),
                "inertia {i}{k}: {x:?} {y:?}"
            );
        }
    }
}

/// The same body to `rel` of its size: the mass relative, the centre
/// relative to `scale` (the layout's size), the tensor to its largest entry.
fn close(
    x: (f64, [f64; 3], [[f64; 3]; 3]),
    y: (f64, [f64; 3], [[f64; 3]; 3]),
    scale: f64,
    rel: f64,
) {
    assert!((x.0 - y.0).abs() <= rel * y.0.abs(), "mass {x:?} {y:?}");
    let big = y.2.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    for i in 0..3 {
        assert!(
            (x.1[i] - y.1[i]).abs() <= rel * scale,
            "centre {i}: {x:?} {y:?}"
        );
        for k in 0..3 {
            assert!(
                (x.2[i][k] - y.2[i][k]).abs() <= rel * big,
                "inertia {i}{k}: {:e} vs {:e} ({:e})",
                x.2[i][k],
                y.2[i][k],
                (x.2[i][k] - y.2[i][k]).abs() / big
            );
        }
    }
}

/// A point turned by `deg` about z through (ox, oy), as the test forms it:
/// exact at quarter turns (integer arithmetic), else radians and libm.
fn turn_z(p: [f64; 3], deg: f64, o: [f64; 3]) -> [f64; 3] {
    let (s, c) = match (deg.rem_euclid(360.0)) as i64 {
        _ if deg % 90.0 == 0.0 => match (deg / 90.0).rem_euclid(4.0) as i64 {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        },
        _ => deg.to_radians().sin_cos(),
    };
    let (x, y) = (p[0] - o[0], p[1] - o[1]);
    [o[0] + (c * x - s * y), o[1] + (s * x + c * y), p[2]]
}

fn v(p: [f64; 3]) -> String {
    format!("[{:?}, {:?}, {:?}]", p[0], p[1], p[2])
}

#[test]
fn a_linear_array_is_its_parts_spelt_out_to_the_last_bit() {
    let array = r#"
[[part]]
name = "slat"
shape = "box"
mass = 1.5
size = [1, 2, 0.25]
center = [3, -1, 2]
array = { count = 5, step = [0.5, 2, -1] }

[[part]]
name = "brace"
shape = "rod"
mass = 0.75
from = [0, 0, 0]
to = [1, 3, 2]
array = { count = 3, step = [0, 0, 4] }

[[part]]
name = "gusset"
shape = "triangle"
mass = 0.25
vertices = [[0, 0, 0], [1, 0, 0], [0, 2, 1]]
array = { count = 4, step = [-2, 0, 0] }
"#;
    let mut spelt = String::new();
    for i in 0..5 {
        let k = i as f64;
        let c = [3.0 + 0.5 * k, -1.0 + 2.0 * k, 2.0 - k];
        spelt += &format!(
            "[[part]]\nname = \"slat[{i}]\"\nshape = \"box\"\nmass = 1.5\nsize = [1, 2, 0.25]\ncenter = {}\n",
            v(c)
        );
    }
    for i in 0..3 {
        let z = 4.0 * i as f64;
        spelt += &format!(
            "[[part]]\nname = \"brace[{i}]\"\nshape = \"rod\"\nmass = 0.75\nfrom = {}\nto = {}\n",
            v([0.0, 0.0, z]),
            v([1.0, 3.0, 2.0 + z])
        );
    }
    for i in 0..4 {
        let x = -2.0 * i as f64;
        spelt += &format!(
            "[[part]]\nname = \"gusset[{i}]\"\nshape = \"triangle\"\nmass = 0.25\nvertices = [{}, {}, {}]\n",
            v([x, 0.0, 0.0]),
            v([1.0 + x, 0.0, 0.0]),
            v([x, 2.0, 1.0])
        );
    }
    same_bits(array, &spelt);
    assert_eq!(names(array), names(&spelt));
}

/// A polar array's parts, and the same spelt out as turned copies, for
/// `n` copies of `deg` each.
fn polar_pair(n: usize, deg: f64) -> (String, String) {
    let o = [1.0, -2.0, 0.0];
    let array = format!(
        r#"
[[part]]
name = "spoke"
shape = "rod"
mass = 0.1
from = [2, -2, 0]
to = [9, -1, 0.5]
array = {{ count = {n}, axis = [0, 0, 1], step_degrees = {deg:?}, origin = [1, -2, 0] }}

[[part]]
name = "weight"
shape = "box"
mass = 0.3
size = [1, 0.5, 0.25]
center = [7, -2, 0]
array = {{ count = {n}, axis = [0, 0, 2], step_degrees = {deg:?}, origin = [1, -2, 0] }}

[[part]]
name = "vane"
shape = "triangle"
mass = 0.05
vertices = [[3, -2, 0], [5, -2, 0], [4, 0, 1]]
array = {{ count = {n}, axis = [0, 0, 1], step_degrees = {deg:?}, origin = [1, -2, 0] }}

[[part]]
name = "motor"
shape = "inertia"
mass = 2
center = [4, -2, 1]
inertia = [[0.5, -0.01, 0.02], [-0.01, 0.4, 0.03], [0.02, 0.03, 0.3]]
array = {{ count = {n}, axis = [0, 0, 1], step_degrees = {deg:?}, origin = [1, -2, 0] }}
"#
    );
    let mut spelt = String::new();
    let a = |i: usize| i as f64 * deg;
    for i in 0..n {
        spelt += &format!(
            "[[part]]\nname = \"spoke[{i}]\"\nshape = \"rod\"\nmass = 0.1\nfrom = {}\nto = {}\n",
            v(turn_z([2.0, -2.0, 0.0], a(i), o)),
            v(turn_z([9.0, -1.0, 0.5], a(i), o))
        );
    }
    for i in 0..n {
        spelt += &format!(
            "[[part]]\nname = \"weight[{i}]\"\nshape = \"box\"\nmass = 0.3\nsize = [1, 0.5, 0.25]\ncenter = {}\n{}",
            v(turn_z([7.0, -2.0, 0.0], a(i), o)),
            if i == 0 {
                String::new()
            } else {
                format!("rotation = {{ axis = [0, 0, 2], degrees = {:?} }}\n", a(i))
            }
        );
    }
    for i in 0..n {
        spelt += &format!(
            "[[part]]\nname = \"vane[{i}]\"\nshape = \"triangle\"\nmass = 0.05\nvertices = [{}, {}, {}]\n",
            v(turn_z([3.0, -2.0, 0.0], a(i), o)),
            v(turn_z([5.0, -2.0, 0.0], a(i), o)),
            v(turn_z([4.0, 0.0, 1.0], a(i), o))
        );
    }
    for i in 0..n {
        spelt += &format!(
            "[[part]]\nname = \"motor[{i}]\"\nshape = \"inertia\"\nmass = 2\ncenter = {}\ninertia = [[0.5, -0.01, 0.02], [-0.01, 0.4, 0.03], [0.02, 0.03, 0.3]]\n{}",
            v(turn_z([4.0, -2.0, 1.0], a(i), o)),
            if i == 0 {
                String::new()
            } else {
                format!("rotation = {{ axis = [0, 0, 1], degrees = {:?} }}\n", a(i))
            }
        );
    }
    (array, spelt)
}

#[test]
fn a_polar_array_at_quarter_turns_is_its_parts_spelt_out_to_the_last_bit() {
    let (array, spelt) = polar_pair(4, 90.0);
    same_bits(&array, &spelt);
    // Past a full turn too: 7 quarter turns.
    let (array, spelt) = polar_pair(7, -90.0);
    same_bits(&array, &spelt);
    assert_eq!(names(&array), names(&spelt));
}

#[test]
fn a_polar_array_of_32_is_its_parts_spelt_out_to_1e_15() {
    let (array, spelt) = polar_pair(32, 360.0 / 32.0);
    close(body(&array), body(&spelt), 10.0, 1e-15);
    // The copies' placement feeds the error bounds: each file's bound is
    // against the exact value of its own numbers, and the spelt-out
    // file's are those rounded once, so the two bounds (with the input's
    // rounding, a unit of 10 per coordinate) cover the difference.
    let json = |t: &str| report_json(t, &["--precision", "standard"]).0;
    let (a, b) = (json(&array), json(&spelt));
    for i in 0..3 {
        for k in 0..3 {
            let f = |v: &Value, key: &str| v[key][i][k].as_f64().unwrap();
            let diff = (f(&a, "inertia_com") - f(&b, "inertia_com")).abs();
            let covered =
                f(&a["error_bounds"], "inertia_com") + f(&b["error_bounds"], "inertia_com") + 1e-14;
            assert!(diff <= covered, "{i}{k}: {diff:e} > {covered:e}");
            // The copies' rounding is counted: at least the spelt-out
            // parts' own.
            assert!(
                f(&a["error_bounds"], "inertia_com") >= f(&b["error_bounds"], "inertia_com"),
                "{i}{k}"
            );
        }
    }
}

#[test]
fn an_array_of_an_include_is_the_includes_spelt_out() {
    let dir = scratch("arrays", "include");
    std::fs::write(
        dir.join("leg.toml"),
        "[[part]]\nname = \"post\"\nshape = \"box\"\nmass = 2\nsize = [1, 1, 8]\ncenter = [0, 0, -4]\n\n[[part]]\nname = \"foot\"\nshape = \"rod\"\nmass = 0.5\nfrom = [0, 0, -8]\nto = [1, 0, -8]\n",
    )
    .unwrap();
    let array = "[[part]]\nname = \"leg\"\ninclude = \"leg.toml\"\norigin = [5, 3, 0]\narray = { count = 4, axis = [0, 0, 1], step_degrees = 90, origin = [1, 1, 0] }\n";
    let mut spelt = String::new();
    for i in 0..4 {
        let at = turn_z([5.0, 3.0, 0.0], 90.0 * i as f64, [1.0, 1.0, 0.0]);
        spelt += &format!(
            "[[part]]\nname = \"leg[{i}]\"\ninclude = \"leg.toml\"\norigin = {}\n{}",
            v(at),
            if i == 0 {
                String::new()
            } else {
                format!(
                    "rotation = {{ axis = [0, 0, 1], degrees = {:?} }}\n",
                    90.0 * i as f64
                )
            }
        );
    }
    let (a, b) = (dir.join("array.toml"), dir.join("spelt.toml"));
    std::fs::write(&a, array).unwrap();
    std::fs::write(&b, &spelt).unwrap();
    let json = |p: &std::path::Path| {
        let out = massprop(&[
            "report",
            "--format",
            "json",
            "--precision",
            "standard",
            p.to_str().unwrap(),
        ]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<Value>(&out.stdout).unwrap()
    };
    let (x, y) = (json(&a), json(&b));
    for key in ["mass", "center_of_mass", "inertia_com"] {
        assert_eq!(x[key], y[key], "{key}");
    }
    let parts = |v: &Value| -> Vec<String> {
        v["parts"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["name"].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(parts(&x), parts(&y));
    assert_eq!(parts(&x)[7], "leg[3] / foot");
    // Each copy is a sub-assembly row, named as its parts are.
    let rows: Vec<&str> = x["assemblies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["path"][0].as_str().unwrap())
        .collect();
    assert_eq!(rows, ["leg[0]", "leg[1]", "leg[2]", "leg[3]"]);
    // `--only` takes a copy, or all of them by the include's name.
    let only = |name: &str| {
        massprop(&[
            "report",
            "--format",
            "json",
            "--only",
            name,
            a.to_str().unwrap(),
        ])
    };
    let one: Value = serde_json::from_slice(&only("leg[2]").stdout).unwrap();
    assert_eq!(one["mass"].as_f64(), Some(2.5));
    assert_eq!(one["parts"][0]["name"], "leg[2] / post");
    let all: Value = serde_json::from_slice(&only("leg").stdout).unwrap();
    assert_eq!(all["mass"].as_f64(), Some(10.0));
    let out = only("leg[4]");
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("did you mean"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // `diff` matches the copies by name: nothing changed.
    let out = massprop(&["diff", a.to_str().unwrap(), b.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// R of a turn about `k` by `deg` (Rodrigues, formed here), S = E − 2nnᵀ.
fn rodrigues(k: [f64; 3], deg: f64) -> [[f64; 3]; 3] {
    let n = (k[0] * k[0] + k[1] * k[1] + k[2] * k[2]).sqrt();
    let k = k.map(|x| x / n);
    let (s, c) = deg.to_radians().sin_cos();
    let x = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (if i == j { c } else { 0.0 }) + s * x[i][j] + (1.0 - c) * k[i] * k[j]
        })
    })
}

fn mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn t(a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

/// S = E − 2 n nᵀ/|n|².
fn reflection(normal: [f64; 3]) -> [[f64; 3]; 3] {
    let nn: f64 = normal.iter().map(|x| x * x).sum();
    std::array::from_fn(|i| {
        std::array::from_fn(|k| (if i == k { 1.0 } else { 0.0 }) - 2.0 * normal[i] * normal[k] / nn)
    })
}

/// A body (m, c, J about c) and its mirror image in the plane through `o`
/// normal to `normal`, formed here: the image's centre o + S (c − o) and
/// tensor S J S, the pair's centre midway and its tensor by parallel axes.
fn pair_with_image(
    (m, c, j): (f64, [f64; 3], [[f64; 3]; 3]),
    normal: [f64; 3],
    o: [f64; 3],
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let s = reflection(normal);
    let sj = mul(&mul(&s, &j), &s);
    let image: [f64; 3] =
        std::array::from_fn(|i| o[i] + (0..3).map(|k| s[i][k] * (c[k] - o[k])).sum::<f64>());
    let g: [f64; 3] = std::array::from_fn(|i| (c[i] + image[i]) / 2.0);
    let h: [f64; 3] = std::array::from_fn(|i| c[i] - g[i]);
    let hh: f64 = h.iter().map(|x| x * x).sum();
    let want = std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            j[i][k] + sj[i][k] + 2.0 * m * ((if i == k { hh } else { 0.0 }) - h[i] * h[k])
        })
    });
    (2.0 * m, g, want)
}

#[test]
fn a_mirrored_box_is_s_j_s_and_the_hand_mirrored_file() {
    let (m, size, c) = (3.0, [1.0, 2.0, 3.0], [2.0, 1.0, -0.5]);
    let (axis, deg) = ([1.0, 2.0, 3.0], 37.0);
    let (normal, o) = ([1.0, -2.0, 2.0], [0.5, 1.0, -1.0]);
    let mirrored = format!(
        "[[part]]\nname = \"wing\"\nshape = \"box\"\nmass = {m:?}\nsize = {}\ncenter = {}\nrotation = {{ axis = {}, degrees = {deg:?} }}\nmirror = {{ normal = {}, origin = {} }}\n",
        v(size),
        v(c),
        v(axis),
        v(normal),
        v(o)
    );
    // Formed here: J = R diag(I) Rᵀ, S = E − 2 n nᵀ/|n|², the image's
    // centre o + S (c − o) and its tensor S J S.
    let r = rodrigues(axis, deg);
    let sq = size.map(|x| x * x);
    let d = [(sq[1] + sq[2]), (sq[0] + sq[2]), (sq[0] + sq[1])].map(|x| m * x / 12.0);
    let dm: [[f64; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| if i == j { d[i] } else { 0.0 }));
    let j = mul(&mul(&r, &dm), &t(&r));
    let s = reflection(normal);
    let pair = pair_with_image((m, c, j), normal, o);
    // The image's centre, 2 g − c.
    let image: [f64; 3] = std::array::from_fn(|i| 2.0 * pair.1[i] - c[i]);
    let got = body(&mirrored);
    close(got, pair, 4.0, 1e-14);
    // The image written by hand: S R F (F flips local x) as a matrix.
    let f = [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let srf = mul(&mul(&s, &r), &f);
    let rows: Vec<String> = srf.iter().map(|row| v(*row)).collect();
    let by_hand = format!(
        "[[part]]\nname = \"wing[0]\"\nshape = \"box\"\nmass = {m:?}\nsize = {}\ncenter = {}\nrotation = {{ axis = {}, degrees = {deg:?} }}\n\n[[part]]\nname = \"wing[1]\"\nshape = \"box\"\nmass = {m:?}\nsize = {}\ncenter = {}\nrotation = {{ matrix = [{}] }}\n",
        v(size),
        v(c),
        v(axis),
        v(size),
        v(image),
        rows.join(", ")
    );
    close(got, body(&by_hand), 4.0, 1e-14);
    assert_eq!(names(&mirrored), ["wing[0]", "wing[1]"]);
}

#[test]
fn a_mirrored_given_tensor_is_s_i_s() {
    // In the plane x = 0: S = diag(−1, 1, 1), so S I S negates the
    // products with x, exactly; the image of [2, 1, 1] is [−2, 1, 1].
    let i = "[[0.5, -0.01, 0.02], [-0.01, 0.4, 0.03], [0.02, 0.03, 0.3]]";
    let mirrored = format!(
        "[[part]]\nshape = \"inertia\"\nmass = 2\ncenter = [2, 1, 1]\ninertia = {i}\nmirror = {{ normal = [3, 0, 0] }}\n"
    );
    let by_hand = format!(
        "[[part]]\nshape = \"inertia\"\nmass = 2\ncenter = [2, 1, 1]\ninertia = {i}\n\n[[part]]\nshape = \"inertia\"\nmass = 2\ncenter = [-2, 1, 1]\ninertia = [[0.5, 0.01, -0.02], [0.01, 0.4, 0.03], [-0.02, 0.03, 0.3]]\n"
    );
    same_bits(&mirrored, &by_hand);
    assert_eq!(names(&mirrored), ["part 1[0]", "part 1[1]"]);
}

#[test]
fn a_mirrored_array_is_the_array_then_its_images() {
    // Table legs: two along x, mirrored in y = 0: four legs.
    let text = "[[part]]\nname = \"leg\"\nshape = \"box\"\nmass = 1\nsize = [0.1, 0.1, 1]\ncenter = [0.5, 0.4, 0.5]\narray = { count = 2, step = [-1, 0, 0] }\nmirror = { normal = [0, 1, 0] }\n";
    let spelt: String = [[0.5, 0.4], [-0.5, 0.4], [0.5, -0.4], [-0.5, -0.4]]
        .iter()
        .enumerate()
        .map(|(i, [x, y])| {
            format!("[[part]]\nname = \"leg[{i}]\"\nshape = \"box\"\nmass = 1\nsize = [0.1, 0.1, 1]\ncenter = [{x:?}, {y:?}, 0.5]\n{}", if i >= 2 { "rotation = { axis = [0, 0, 1], degrees = 180 }\n" } else { "" })
        })
        .collect();
    same_bits(text, &spelt);
    assert_eq!(names(text), names(&spelt));
}

#[test]
fn a_symmetric_polar_array_has_equal_moments_about_its_axis() {
    for n in [3, 5, 7, 32] {
        let text = format!(
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [2, 0.5, 0.3]\ncenter = [3, 1, 0.5]\nrotation = {{ axis = [1, 1, 0], degrees = 20 }}\narray = {{ count = {n}, axis = [0, 0, 1], step_degrees = {:?} }}\n",
            360.0 / n as f64
        );
        let (_, _, j) = body(&text);
        let scale = j[0][0].abs().max(j[2][2].abs());
        assert!((j[0][0] - j[1][1]).abs() <= 1e-14 * scale, "{n}: {j:?}");
        assert!(j[0][1].abs() <= 1e-14 * scale, "{n}: {j:?}");
    }
}

#[test]
fn copies_are_named_in_the_table_and_check_and_diff_use_the_names() {
    let dir = scratch("arrays", "names");
    let text = "[[part]]\nname = \"spoke\"\nshape = \"rod\"\nmass = 0.01\nfrom = [0.02, 0, 0]\nto = [0.3, 0, 0]\narray = { count = \"32\", axis = [0, 0, 1], step_degrees = 11.25 }\n\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\nmirror = { normal = [0, 0, 1], origin = [0, 0, 1] }\n\n[expect]\nmass = { value = 2.32, tol = \"1e-9%\" }\n";
    let file = dir.join("wheel.toml");
    std::fs::write(&file, text).unwrap();
    let out = massprop(&["report", "--full", file.to_str().unwrap()]);
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(
        table.contains("spoke[31]") && table.contains("part 2[1]"),
        "{table}"
    );
    let out = massprop(&["check", file.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    // One copy changed by hand: diff names it.
    let changed = text.replace("count = \"32\"", "count = 31");
    let other = dir.join("wheel2.toml");
    std::fs::write(&other, changed).unwrap();
    let out = massprop(&["diff", file.to_str().unwrap(), other.to_str().unwrap()]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{said}");
    assert!(said.contains("spoke[31]"), "{said}");
}

/// The file's error, refused: status 2, nothing on stdout.
fn refused(text: &str) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let dir = scratch(
        "arrays",
        &format!("refused{}", COUNT.fetch_add(1, Ordering::Relaxed)),
    );
    let file = dir.join("bad.toml");
    std::fs::write(&file, text).unwrap();
    let out = massprop(&["report", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{text}\n{err}");
    assert!(out.stdout.is_empty(), "{text}");
    err
}

const BOX: &str = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";

#[test]
fn a_bad_array_or_mirror_is_refused_where_it_is() {
    for (extra, line_col, said) in [
        (
            "array = { count = 3, stpe = [1, 0, 0] }",
            "6:22",
            "did you mean `step`",
        ),
        (
            "array = { count = 3, step = [1, 0, 0], axis = [0, 0, 1] }",
            "6:47",
            "`axis` conflicts with `step`",
        ),
        (
            "array = { count = 0, step = [1, 0, 0] }",
            "6:19",
            "whole number",
        ),
        (
            "array = { count = -2, step = [1, 0, 0] }",
            "6:19",
            "whole number",
        ),
        (
            "array = { count = 2.5, step = [1, 0, 0] }",
            "6:19",
            "whole number",
        ),
        (
            "array = { count = \"3 mm\", step = [1, 0, 0] }",
            "6:19",
            "plain number",
        ),
        ("array = { step = [1, 0, 0] }", "6:9", "needs `count`"),
        ("array = { count = 3 }", "6:9", "needs `step`"),
        (
            "array = { count = 3, axis = [0, 0, 1] }",
            "6:9",
            "needs `step_degrees`",
        ),
        (
            "array = { count = 3, axis = [0, 0, 0], step_degrees = 5 }",
            "6:29",
            "non-zero",
        ),
        ("array = { count = 3, step = [1, 0], }", "6:29", "needs 3"),
        (
            "array = { count = 3, step = [1, 0, 0], step_degrees = 5 }",
            "6:55",
            "applies to an array about an axis",
        ),
        (
            "array = { count = 3, step = [1e308, 0, 0] }",
            "6:29",
            "overflows",
        ),
        (
            "array = { count = 3, axis = [0, 0, 1], step_degrees = 1e308 }",
            "6:55",
            "overflows",
        ),
        ("mirror = { normal = [0, 0, 0] }", "6:21", "non-zero"),
        ("mirror = { origin = [0, 0, 0] }", "6:10", "needs `normal`"),
        (
            "mirror = { normal = [1, 0, 0], orgin = [0, 0, 0] }",
            "6:32",
            "did you mean `origin`",
        ),
        (
            "mirror = { normal = [1, 0, 0], origin = [1e308, 0, 0] }",
            "6:10",
            "beyond the range",
        ),
        ("array = [3]", "6:9", "a table such as"),
    ] {
        let err = refused(&format!("{BOX}{extra}\n"));
        assert!(
            err.contains(&format!("bad.toml:{line_col}")),
            "{extra}\n{err}"
        );
        assert!(err.contains(said), "{extra}\n{err}");
    }
}

/// Refused before any copy is made: at the `array` key, as the model is
/// read (copies are made only by a walk of a model that exists), not
/// after; no clock but the hang guard.
#[test]
fn a_huge_count_is_refused_before_any_copy_is_made() {
    for count in ["1000000000000", "2000001", "1e300"] {
        let text = format!("{BOX}array = {{ count = {count}, step = [1, 0, 0] }}\n");
        let dir = scratch("arrays", &format!("huge-{count}"));
        let file = dir.join("bad.toml");
        std::fs::write(&file, &text).unwrap();
        let out = crate::common::within_a_minute(&["report", file.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(out.stdout.is_empty());
        assert!(err.starts_with(&format!("{}:6:", file.display())), "{err}");
        assert!(err.contains("limit"), "{err}");
    }
    // At the limit with another part: past it.
    let err = refused(&format!(
        "{BOX}{BOX}array = {{ count = 2000000, step = [1, 0, 0] }}\n"
    ));
    assert!(err.contains("past 2000000 parts"), "{err}");
    // A mirror doubles an array at the limit.
    let err = refused(&format!(
        "{BOX}array = {{ count = 2000000, step = [1, 0, 0] }}\nmirror = {{ normal = [1, 0, 0] }}\n"
    ));
    assert!(err.contains("limit"), "{err}");
}

#[test]
fn an_included_array_counts_against_the_limit_before_it_is_expanded() {
    let dir = scratch("arrays", "nested_limit");
    std::fs::write(
        dir.join("row.toml"),
        format!("{BOX}array = {{ count = 1000000, step = [1, 0, 0] }}\n"),
    )
    .unwrap();
    let top = dir.join("top.toml");
    std::fs::write(
        &top,
        "[[part]]\ninclude = \"row.toml\"\narray = { count = 1000, step = [0, 1, 0] }\n",
    )
    .unwrap();
    let out = crate::common::within_a_minute(&["report", top.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("top.toml:2:") && err.contains("limit"),
        "{err}"
    );
}

#[test]
fn hostile_axes_and_normals_give_finite_results_or_located_errors() {
    // Tiny and huge directions are directions: the norm is scaled.
    for axis in [
        "[0, 0, 1e-300]",
        "[0, 0, 1e300]",
        "[1e308, 1e308, 1e308]",
        "[5e-324, 0, 0]",
    ] {
        let text = format!(
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [3, 0, 0]\narray = {{ count = 3, axis = {axis}, step_degrees = 120 }}\nmirror = {{ normal = {axis} }}\n"
        );
        let (m, c, j) = body(&text);
        assert_eq!(m, 6.0, "{axis}");
        assert!(
            c.iter().chain(j.iter().flatten()).all(|x| x.is_finite()),
            "{axis}: {c:?} {j:?}"
        );
    }
    for (axis, said) in [
        ("[nan, 0, 1]", "finite"),
        ("[inf, 0, 1]", "finite"),
        ("[0, 0]", "needs 3"),
    ] {
        let err = refused(&format!(
            "{BOX}array = {{ count = 3, axis = {axis}, step_degrees = 10 }}\n"
        ));
        assert!(err.contains("bad.toml:6:"), "{err}");
        assert!(err.contains(said), "{axis}: {err}");
    }
    let err = refused(&format!(
        "{BOX}array = {{ count = 3, axis = [0, 0, 1], step_degrees = nan }}\n"
    ));
    assert!(err.contains("finite"), "{err}");
}

#[test]
fn the_documented_example_is_32_spokes_and_four_legs() {
    let doc = std::fs::read_to_string("docs/part-file.md").unwrap();
    let section = doc
        .split("### Arrays and mirrors")
        .nth(1)
        .expect("docs/part-file.md has the section");
    let example = section
        .split("```toml\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .unwrap();
    let (m, c, _) = body(example);
    // 32 spokes of 6 g and four legs of 1.2 kg; the legs at (±0.55, ±0.35).
    assert!((m - (32.0 * 0.006 + 4.0 * 1.2)).abs() <= 1e-15 * m, "{m}");
    let legs = 4.0 * 1.2 * 0.35 / m;
    assert!((c[2] - legs).abs() <= 1e-15, "{c:?}");
    let names = names(example);
    assert_eq!(names.len(), 36);
    assert_eq!(names[31], "spoke[31]");
    assert_eq!(names[32..], ["leg[0]", "leg[1]", "leg[2]", "leg[3]"]);
}

#[test]
fn a_hundred_thousand_copies_are_walked_not_held() {
    // Each copy a point of 1 kg at x = i: the mass is 10⁵ and the centre
    // (10⁵ − 1)/2, both exact sums of integers.
    let n = 100_000;
    let text = format!(
        "[[part]]\nname = \"bead\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\narray = {{ count = {n}, step = [1, 0, 0] }}\n"
    );
    let (m, c, _) = body(&text);
    assert_eq!(m, n as f64);
    assert_eq!(c, [(n as f64 - 1.0) / 2.0, 0.0, 0.0]);
}

#[test]
fn copies_nest_through_includes_and_a_mirror_of_a_mirror_is_the_part() {
    let dir = scratch("arrays", "nested");
    std::fs::write(
        dir.join("side.toml"),
        "[[part]]\nname = \"panel\"\nshape = \"box\"\nmass = 2\nsize = [0.5, 1, 2]\ncenter = [1, 2, 3]\nmirror = { normal = [1, 0, 0] }\n\n[[part]]\nname = \"motor\"\nshape = \"inertia\"\nmass = 1\ncenter = [1, 1, 0]\ninertia = [[0.5, -0.01, 0.02], [-0.01, 0.4, 0.03], [0.02, 0.03, 0.3]]\nmirror = { normal = [1, 0, 0] }\n",
    )
    .unwrap();
    let top = dir.join("top.toml");
    std::fs::write(
        &top,
        "[[part]]\nname = \"side\"\ninclude = \"side.toml\"\nmirror = { normal = [0, 5, 0] }\n",
    )
    .unwrap();
    // Spelt out: panels at (±1, ±2, 3), each its own image twice over (a
    // box is symmetric in every local plane); the motors' tensors with the
    // products of x negated, then of y.
    let motor = |x: f64, y: f64| {
        let (sx, sy) = (x.signum(), y.signum());
        format!(
            "[[part]]\nshape = \"inertia\"\nmass = 1\ncenter = [{x:?}, {y:?}, 0.0]\ninertia = [[0.5, {:?}, {:?}], [{:?}, 0.4, {:?}], [{:?}, {:?}, 0.3]]\n",
            -0.01 * sx * sy,
            0.02 * sx,
            -0.01 * sx * sy,
            0.03 * sy,
            0.02 * sx,
            0.03 * sy
        )
    };
    let panel = |x: f64, y: f64| {
        format!(
            "[[part]]\nshape = \"box\"\nmass = 2\nsize = [0.5, 1, 2]\ncenter = [{x:?}, {y:?}, 3.0]\n"
        )
    };
    let spelt = [
        panel(1.0, 2.0),
        panel(-1.0, 2.0),
        motor(1.0, 1.0),
        motor(-1.0, 1.0),
        panel(1.0, -2.0),
        panel(-1.0, -2.0),
        motor(1.0, -1.0),
        motor(-1.0, -1.0),
    ]
    .concat();
    let spelt_file = dir.join("spelt.toml");
    std::fs::write(&spelt_file, &spelt).unwrap();
    let json = |p: &std::path::Path| {
        let out = massprop(&[
            "report",
            "--format",
            "json",
            "--precision",
            "standard",
            p.to_str().unwrap(),
        ]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice::<Value>(&out.stdout).unwrap()
    };
    let (x, y) = (json(&top), json(&spelt_file));
    for key in ["mass", "center_of_mass", "inertia_com"] {
        assert_eq!(x[key], y[key], "{key}");
    }
    let names: Vec<&str> = x["parts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "side[0] / panel[0]",
            "side[0] / panel[1]",
            "side[0] / motor[0]",
            "side[0] / motor[1]",
            "side[1] / panel[0]",
            "side[1] / panel[1]",
            "side[1] / motor[0]",
            "side[1] / motor[1]",
        ]
    );
}

/// The mirror image of each shape that is not a box, turned by a general
/// rotation and mirrored in a general plane: the pair is the part and the
/// image formed here from the part's own mass, centre and tensor (the
/// centre o + S (c − o), the tensor S J S), whatever the shape's own
/// symmetry (`part::mirror`: a cone, torus or hemisphere flipped in local
/// x, a prism in z, a mesh's own data reflected, an ellipsoid flipped in
/// local x).
#[test]
fn every_shape_mirrored_is_the_part_and_its_image_s_j_s() {
    let mesh = format!("{}/shapes/meshes/bracket.stl", env!("CARGO_MANIFEST_DIR"));
    let shapes = [
        "shape = \"cone\"\nmass = 2.0\nradius = 1.5\ntop_radius = 0.5\ninner_radius = 1.0\ntop_inner_radius = 0.25\nlength = 3\ncenter = [2, 1, -0.5]".to_string(),
        "shape = \"torus\"\nmass = 2.0\nradius = 2\ntube_radius = 0.5\ncenter = [2, 1, -0.5]".to_string(),
        "shape = \"hemisphere\"\nmass = 2.0\nradius = 1.5\ninner_radius = 1\ncenter = [2, 1, -0.5]".to_string(),
        "shape = \"prism\"\nmass = 2.0\npolygon = [[0, 0], [3, 0], [3, 1], [1, 1], [1, 2.5], [0, 2.5]]\nlength = 0.5\norigin = [2, 1, -0.5]".to_string(),
        format!("shape = \"mesh\"\nfile = \"{mesh}\"\nmesh_unit = \"m\"\nmass = 2.0\norigin = [2, 1, -0.5]"),
        "shape = \"ellipsoid\"\nmass = 2.0\nradii = [1.5, 0.5, 1]\ncenter = [2, 1, -0.5]".to_string(),
    ];
    let (normal, o) = ([1.0, -2.0, 2.0], [0.5, 1.0, -1.0]);
    for shape in shapes {
        let part = format!(
            "[[part]]\nname = \"p\"\n{shape}\nrotation = {{ axis = [1, 2, 3], degrees = 37 }}\n"
        );
        let (m, c, j) = body(&part);
        let mirrored = format!(
            "{part}mirror = {{ normal = {}, origin = {} }}\n",
            v(normal),
            v(o)
        );
        close(
            body(&mirrored),
            pair_with_image((m, c, j), normal, o),
            4.0,
            1e-13,
        );
        assert_eq!(names(&mirrored), ["p[0]", "p[1]"], "{shape}");
    }
}

/// Angles are dimensionless, so an angle unit in `step_degrees` (or
/// `count`), directly or through a parameter, would be read in radians as
/// degrees: refused at the key. Plain numbers and expressions of them work,
/// and `sin(30 deg)` (an angle turned into a ratio) is a plain number.
#[test]
fn an_angle_unit_in_step_degrees_or_count_is_refused() {
    let part = "[[part]]\nname = \"p\"\nshape = \"point\"\nmass = 1\ncenter = [1, 0, 0]\n";
    for (params, array, col) in [
        (
            "",
            "{ count = 4, axis = [0, 0, 1], step_degrees = \"90 deg\" }",
            55,
        ),
        (
            "",
            "{ count = 4, axis = [0, 0, 1], step_degrees = \"pi / 2 rad\" }",
            55,
        ),
        ("", "{ count = \"4 rad\", step = [1, 0, 0] }", 19),
        (
            "[params]\nn = 4\nturn = \"360 deg / n\"\n",
            "{ count = \"n\", axis = [0, 0, 1], step_degrees = \"turn\" }",
            57,
        ),
    ] {
        let text = format!("{params}{part}array = {array}\n");
        let err = refused(&text);
        let line = 6 + params.lines().count();
        assert!(
            err.contains(&format!("bad.toml:{line}:{col}:")),
            "{text}\n{err}"
        );
        assert!(err.contains("angle unit"), "{err}");
    }
    let ok = format!(
        "[params]\nn = 4\n{part}array = {{ count = \"n\", axis = [0, 0, 1], step_degrees = \"sin(30 deg) * 720 / n\" }}\n"
    );
    let spelt = format!(
        "{part}\n[[part]]\nname = \"q\"\nshape = \"point\"\nmass = 1\ncenter = [0, 1, 0]\n\n[[part]]\nname = \"r\"\nshape = \"point\"\nmass = 1\ncenter = [-1, 0, 0]\n\n[[part]]\nname = \"s\"\nshape = \"point\"\nmass = 1\ncenter = [0, -1, 0]\n"
    );
    close(body(&ok), body(&spelt), 1.0, 1e-15);
}
