//! Issue 29's ellipsoid through the whole program. Its closed forms are
//! checked against quadrature of its own definition in
//! src/shapes/ellipsoid.rs and against the exact reference
//! (`support::solids::ellipsoid`, the every-shape scene of `stress`, the
//! property tests of `invariants`); here, against the textbook forms
//! written out in each test: equal radii a sphere, a turned one R I Rᵀ,
//! its radii in any length unit, their tolerances' σ against the
//! derivatives, copies and mirrors of it, export in each format, its
//! drawing in each view, and its bad input.

use crate::common::{
    figures, massprop_stdin, report_json, report_json_file, same_body, scratch_files,
};

/// The textbook tensor of a solid ellipsoid of mass `m` and semi-axes
/// a, b, c about its centre in its own axes: m/5 diag(b² + c², a² + c²,
/// a² + b²).
fn textbook(m: f64, [a, b, c]: [f64; 3]) -> [f64; 3] {
    [
        m * (b * b + c * c) / 5.0,
        m * (a * a + c * c) / 5.0,
        m * (a * a + b * b) / 5.0,
    ]
}

/// The turn by `degrees` about the unit `axis` (Rodrigues' formula).
fn turn(axis: [f64; 3], degrees: f64) -> [[f64; 3]; 3] {
    let n = (axis.iter().map(|x| x * x).sum::<f64>()).sqrt();
    let [x, y, z] = axis.map(|v| v / n);
    let (s, c) = degrees.to_radians().sin_cos();
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

const PI: f64 = std::f64::consts::PI;

#[test]
fn an_ellipsoid_of_equal_radii_is_the_sphere() {
    let ellipsoid = "[[part]]\nshape = \"ellipsoid\"\ndensity = 7850\nradii = [0.3, 0.3, 0.3]\ncenter = [1, 2, 3]\n";
    let sphere = "[[part]]\nshape = \"sphere\"\ndensity = 7850\nradius = 0.3\ncenter = [1, 2, 3]\n";
    same_body(ellipsoid, sphere, 1e-15);
}

#[test]
fn its_mass_is_the_density_times_four_thirds_pi_abc() {
    let text = "[[part]]\nshape = \"ellipsoid\"\ndensity = 1000\nradii = [0.5, 2, 0.25]\ncenter = [0, 0, 0]\n";
    let (m, _, i, _) = figures(text, &[]);
    let want = 1000.0 * 4.0 / 3.0 * PI * 0.5 * 2.0 * 0.25;
    assert!(
        (m - want).abs() <= 4.0 * f64::EPSILON * want,
        "{m} vs {want}"
    );
    let d = textbook(want, [0.5, 2.0, 0.25]);
    for k in 0..3 {
        assert!(
            (i[k][k] - d[k]).abs() <= 8.0 * f64::EPSILON * d[k],
            "{i:?} vs {d:?}"
        );
    }
}

#[test]
fn a_turned_ellipsoid_has_its_textbook_tensor_turned() {
    // I = R diag(I_x, I_y, I_z) Rᵀ, R the turn written out here.
    let (m, radii, axis, deg) = (3.0, [0.5, 1.25, 2.0], [1.0, 2.0, 3.0], 37.0);
    let text = format!(
        "[[part]]\nshape = \"ellipsoid\"\nmass = {m}\nradii = [0.5, 1.25, 2]\ncenter = [4, -1, 2]\nrotation = {{ axis = [1, 2, 3], degrees = {deg} }}\n"
    );
    let (got_m, c, i, _) = figures(&text, &[]);
    assert_eq!(got_m, m);
    assert_eq!(c, [4.0, -1.0, 2.0]);
    let (r, d) = (turn(axis, deg), textbook(m, radii));
    for a in 0..3 {
        for b in 0..3 {
            let want: f64 = (0..3).map(|k| r[a][k] * d[k] * r[b][k]).sum();
            assert!(
                (i[a][b] - want).abs() <= 1e-14 * d[2],
                "[{a}][{b}]: {} vs {want}",
                i[a][b]
            );
        }
    }
}

#[test]
fn a_quarter_turn_about_z_swaps_its_x_and_y_moments() {
    let upright =
        "[[part]]\nshape = \"ellipsoid\"\nmass = 2\nradii = [1, 2, 3]\ncenter = [0, 0, 0]\n";
    let turned = "[[part]]\nshape = \"ellipsoid\"\nmass = 2\nradii = [2, 1, 3]\ncenter = [0, 0, 0]\nrotation = { axis = [0, 0, 1], degrees = 90 }\n";
    same_body(upright, turned, 1e-15);
}

#[test]
fn its_radii_are_read_in_any_length_unit() {
    let metres = "[[part]]\nshape = \"ellipsoid\"\ndensity = 2700\nradii = [0.1, 0.2, 0.05]\ncenter = [0, 0, 0]\n";
    let mixed = "[[part]]\nshape = \"ellipsoid\"\ndensity = 2700\nradii = [\"10 cm\", \"200 mm\", \"0.05 m\"]\ncenter = [0, 0, 0]\n";
    same_body(metres, mixed, 1e-15);
}

#[test]
fn the_linear_sigma_of_the_mass_by_each_radius_is_the_derivative_times_the_tolerance() {
    // m = ρ ⁴⁄₃π abc: ∂m/∂a = m/a, so with independent tolerances on a and
    // on b (1 %), σ_m = m √((σ_a/a)² + (0.01)²).
    let (rho, a, b, c, sigma_a) = (7850.0, 0.2, 0.3, 0.4, 0.001);
    let text = format!(
        "[[part]]\nshape = \"ellipsoid\"\ndensity = {rho}\nradii = [\"{a} m ± {sigma_a} m\", \"{b} m ± 1 %\", {c}]\ncenter = [0, 0, 0]\n"
    );
    let (v, _) = report_json(&text, &["--uncertainty", "linear"]);
    let sigma = |q: &str| {
        v["uncertainty"]["outputs"]
            .as_array()
            .expect("outputs")
            .iter()
            .find(|o| o["quantity"] == q)
            .and_then(|o| o["sigma"].as_f64())
            .unwrap_or_else(|| panic!("σ of {q}\n{v:#}"))
    };
    let m = rho * 4.0 / 3.0 * PI * a * b * c;
    let want = m * ((sigma_a / a).powi(2) + 0.01f64.powi(2)).sqrt();
    let got = sigma("mass");
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
    // I_zz = m (a² + b²)/5 = ρ ⁴⁄₃π c (a³b + ab³)/5: ∂/∂a = ρ ⁴⁄₃π c
    // (3a²b + b³)/5, ∂/∂b = ρ ⁴⁄₃π c (a³ + 3ab²)/5.
    let k = rho * 4.0 / 3.0 * PI * c / 5.0;
    let (da, db) = (
        k * (3.0 * a * a * b + b.powi(3)),
        k * (a.powi(3) + 3.0 * a * b * b),
    );
    let want = ((da * sigma_a).powi(2) + (db * 0.01 * b).powi(2)).sqrt();
    let got = sigma("inertia_com.zz");
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
}

#[test]
fn a_mirrored_and_arrayed_ellipsoid_is_each_copy_written_out() {
    // Two copies 3 m apart along x and their mirror images in y = 0, of an
    // ellipsoid off the plane and turned about x: four ellipsoids written
    // out, each image turned the other way (the reflection of the turn:
    // the ellipsoid is its own image in its local planes).
    let part = "shape = \"ellipsoid\"\nmass = 2\nradii = [0.25, 1, 0.5]\ncenter = [1, 2, 0.5]\nrotation = { axis = [1, 0, 0], degrees = 30 }\n";
    let copied = format!(
        "[[part]]\n{part}array = {{ count = 2, step = [3, 0, 0] }}\nmirror = {{ normal = [0, 1, 0] }}\n"
    );
    let written = [
        (0.0, 2.0, 30.0),
        (3.0, 2.0, 30.0),
        (0.0, -2.0, -30.0),
        (3.0, -2.0, -30.0),
    ]
    .iter()
    .map(|(dx, y, deg)| {
        format!(
            "[[part]]\nshape = \"ellipsoid\"\nmass = 2\nradii = [0.25, 1, 0.5]\ncenter = [{}, {y}, 0.5]\nrotation = {{ axis = [1, 0, 0], degrees = {deg} }}\n",
            1.0 + dx
        )
    })
    .collect::<String>();
    same_body(&copied, &written, 1e-14);
    // And the image is not the copy moved: centred on the mirror's plane,
    // the part and its image cancel each other's y–z product.
    let on_plane = part.replace("center = [1, 2, 0.5]", "center = [1, 0, 0.5]");
    let (_, _, pair, _) = figures(
        &format!("[[part]]\n{on_plane}mirror = {{ normal = [0, 1, 0] }}\n"),
        &[],
    );
    let (_, _, one, _) = figures(&format!("[[part]]\n{on_plane}"), &[]);
    assert!(one[1][2].abs() > 0.1, "{one:?}");
    assert!(pair[1][2].abs() <= 1e-14, "{pair:?}");
    assert!(
        (pair[0][0] - 2.0 * one[0][0]).abs() <= 1e-14,
        "{pair:?} vs {one:?}"
    );
}

#[test]
fn an_ellipsoid_in_a_turned_sub_assembly_in_millimetres_is_moved_scaled_and_turned() {
    // The sub-assembly in mm and g, turned 30° about y inside it; the
    // include turned 90° about z at (1, 0, 0) m: the body R_z R_y diag Rᵀ
    // about (1, 0, 0) + R_z (0.01, 0.02, 0.03) m.
    let top = scratch_files(
        "ellipsoid",
        "include",
        &[
            (
                "sub.toml",
                "units = { length = \"mm\", mass = \"g\" }\n[[part]]\nshape = \"ellipsoid\"\ndensity = \"2.7 g/cm^3\"\nradii = [100, 50, \"0.02 m\"]\ncenter = [10, 20, 30]\nrotation = { axis = [0, 1, 0], degrees = 30 }\n",
            ),
            (
                "top.toml",
                "[[part]]\ninclude = \"sub.toml\"\norigin = [1, 0, 0]\nrotation = { axis = [0, 0, 1], degrees = 90 }\n",
            ),
        ],
    );
    let (v, _) = report_json_file(&top, &[]);
    let m = 2700.0 * 4.0 / 3.0 * PI * 0.1 * 0.05 * 0.02;
    let got_m = v["mass"].as_f64().unwrap();
    assert!((got_m - m).abs() <= 1e-15 * m, "{got_m} vs {m}");
    for (k, want) in [0.98, 0.01, 0.03].iter().enumerate() {
        let got = v["center_of_mass"][k].as_f64().unwrap();
        assert!((got - want).abs() <= 1e-15, "centre {k}: {got} vs {want}");
    }
    let (rz, ry) = (turn([0.0, 0.0, 1.0], 90.0), turn([0.0, 1.0, 0.0], 30.0));
    let r: [[f64; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| rz[i][k] * ry[k][j]).sum()));
    let d = textbook(m, [0.1, 0.05, 0.02]);
    for a in 0..3 {
        for b in 0..3 {
            let want: f64 = (0..3).map(|k| r[a][k] * d[k] * r[b][k]).sum();
            let got = v["inertia_com"][a][b].as_f64().unwrap();
            assert!(
                (got - want).abs() <= 1e-14 * d[0],
                "[{a}][{b}]: {got} vs {want}"
            );
        }
    }
}

/// `massprop export - --to FORMAT` on `text`: its XML.
fn export(text: &str, format: &str) -> String {
    let out = massprop_stdin(&["export", "-", "--to", format], text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn export_writes_the_ellipsoids_inertial_in_each_format() {
    // Turned a quarter about z: its local x along y, so I_xx is the
    // textbook's I_y and I_yy its I_x.
    let (m, radii) = (3.0, [0.5, 1.0, 2.0]);
    let text = format!(
        "[[part]]\nshape = \"ellipsoid\"\nmass = {m}\nradii = [0.5, 1, 2]\ncenter = [0.5, 0, 0]\nrotation = {{ axis = [0, 0, 1], degrees = 90 }}\n"
    );
    let [ix, iy, iz] = textbook(m, radii);
    let want = [iy, ix, iz];
    let near = |got: f64, want: f64, what: &str, xml: &str| {
        assert!(
            (got - want).abs() <= 1e-14 * iz,
            "{what}: {got} vs {want}\n{xml}"
        );
    };
    let number = |s: &str| -> f64 { s.trim().parse().unwrap() };
    // URDF: <inertia ixx … izz/> attributes.
    let xml = export(&text, "urdf");
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let node = |tag: &str| {
        doc.descendants()
            .find(|n| n.has_tag_name(tag))
            .unwrap_or_else(|| panic!("<{tag}>\n{xml}"))
    };
    near(
        number(node("mass").attribute("value").unwrap()),
        m,
        "mass",
        &xml,
    );
    for (k, key) in ["ixx", "iyy", "izz"].iter().enumerate() {
        near(
            number(node("inertia").attribute(*key).unwrap()),
            want[k],
            key,
            &xml,
        );
    }
    near(
        number(node("inertia").attribute("ixy").unwrap()),
        0.0,
        "ixy",
        &xml,
    );
    assert_eq!(node("origin").attribute("xyz"), Some("0.5 0 0"), "{xml}");
    // SDFormat: <ixx>…</ixx> elements.
    let xml = export(&text, "sdf");
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let text_of = |tag: &str| {
        number(
            doc.descendants()
                .find(|n| n.has_tag_name(tag))
                .and_then(|n| n.text())
                .unwrap_or_else(|| panic!("<{tag}>\n{xml}")),
        )
    };
    near(text_of("mass"), m, "mass", &xml);
    for (k, key) in ["ixx", "iyy", "izz"].iter().enumerate() {
        near(text_of(key), want[k], key, &xml);
    }
    // MJCF: fullinertia = "xx yy zz xy xz yz".
    let xml = export(&text, "mjcf");
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let inertial = doc
        .descendants()
        .find(|n| n.has_tag_name("inertial"))
        .expect("<inertial>");
    near(number(inertial.attribute("mass").unwrap()), m, "mass", &xml);
    let full: Vec<f64> = inertial
        .attribute("fullinertia")
        .expect("fullinertia")
        .split(' ')
        .map(number)
        .collect();
    for k in 0..3 {
        near(full[k], want[k], "fullinertia", &xml);
        near(full[k + 3], 0.0, "fullinertia's products", &xml);
    }
}

/// The semi-axes (largest first) of the ellipse that the ellipsoid
/// {M u : |u| ≤ 1} (`m`, its columns) projects to on the plane of the unit
/// vectors `right` and `up`: the square roots of the eigenvalues of the
/// 2 × 2 matrix P M Mᵀ Pᵀ, in closed form.
fn projected_semi_axes(m: [[f64; 3]; 3], [right, up]: [[f64; 3]; 2]) -> [f64; 2] {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cols = m.map(|col| [dot(col, right), dot(col, up)]);
    let (mut p, mut q, mut r) = (0.0, 0.0, 0.0);
    for [x, y] in cols {
        p += x * x;
        q += x * y;
        r += y * y;
    }
    let mean = (p + r) / 2.0;
    let spread = (((p - r) / 2.0).powi(2) + q * q).sqrt();
    [(mean + spread).sqrt(), (mean - spread).sqrt()]
}

#[test]
fn a_turned_ellipsoid_is_drawn_as_its_projection_in_each_view() {
    // Semi-axes 3, 1.5, 0.75 turned 40° about (1, 1, 0): in each view the
    // drawn ellipse's semi-axes (the SVG arc's radii over the view's
    // scale) are those of the projection computed here.
    let svg = {
        let out = massprop_stdin(
            &["render", "-"],
            "[[part]]\nshape = \"ellipsoid\"\nmass = 1\nradii = [3, 1.5, 0.75]\ncenter = [1, 2, 3]\nrotation = { axis = [1, 1, 0], degrees = 40 }\n",
        );
        assert_eq!(out.status.code(), Some(0));
        String::from_utf8(out.stdout).unwrap()
    };
    let r = turn([1.0, 1.0, 0.0], 40.0);
    let m: [[f64; 3]; 3] =
        std::array::from_fn(|j| std::array::from_fn(|i| r[i][j] * [3.0, 1.5, 0.75][j]));
    let (s2, s6) = (0.5f64.sqrt(), (1.0f64 / 6.0).sqrt());
    let doc = roxmltree::Document::parse(&svg).unwrap();
    for (view, plane) in [
        ("front", [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]),
        ("top", [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),
        ("side", [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
        ("iso", [[s2, s2, 0.0], [-s6, s6, 2.0 * s6]]),
    ] {
        let g = doc
            .descendants()
            .find(|n| n.attribute("id") == Some(view))
            .unwrap_or_else(|| panic!("no view {view}"));
        let scale: f64 = g.attribute("data-scale").unwrap().parse().unwrap();
        let d = g
            .descendants()
            .find(|n| n.attribute("class") == Some("c0"))
            .and_then(|n| n.attribute("d"))
            .unwrap_or_else(|| panic!("{view}: no outline"));
        // M x y A rx ry angle 0 1 x y A …
        let arc: Vec<f64> = d
            .split('A')
            .nth(1)
            .unwrap_or_else(|| panic!("{view}: no arc in {d}"))
            .split(' ')
            .take(2)
            .map(|x| x.parse().unwrap())
            .collect();
        let want = projected_semi_axes(m, plane).map(|x| x * scale);
        let mut got = [arc[0], arc[1]];
        got.sort_by(|a, b| b.total_cmp(a));
        for k in 0..2 {
            assert!(
                (got[k] - want[k]).abs() <= 0.011,
                "{view}: semi-axes {got:?} vs {want:?}"
            );
        }
    }
}

/// `massprop report -` on `text`, refused: its standard error.
fn refused(text: &str) -> String {
    let out = massprop_stdin(&["report", "-"], text);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty(), "{stderr}");
    stderr
}

#[test]
fn a_zero_or_negative_radius_is_refused_at_its_place() {
    for (radii, col) in [
        ("[1, 0, 3]", 13),
        ("[1, 2, \"-3 mm\"]", 16),
        ("[-1, 2, 3]", 10),
    ] {
        let e = refused(&format!(
            "[[part]]\nshape = \"ellipsoid\"\nmass = 1\nradii = {radii}\ncenter = [0, 0, 0]\n"
        ));
        assert!(
            e.starts_with(&format!("<stdin>:4:{col}: error: `radii` must be positive")),
            "{radii}: {e}"
        );
    }
}

#[test]
fn two_or_four_radii_are_refused() {
    for (radii, n) in [("[1, 2]", 2), ("[1, 2, 3, 4]", 4)] {
        let e = refused(&format!(
            "[[part]]\nshape = \"ellipsoid\"\nmass = 1\nradii = {radii}\ncenter = [0, 0, 0]\n"
        ));
        assert!(
            e.starts_with(&format!(
                "<stdin>:4:9: error: `radii` needs 3 components, got {n}"
            )),
            "{radii}: {e}"
        );
    }
}

#[test]
fn an_ellipsoid_without_radii_or_with_a_radius_is_refused() {
    let e = refused("[[part]]\nshape = \"ellipsoid\"\nmass = 1\ncenter = [0, 0, 0]\n");
    assert!(
        e.starts_with("<stdin>:2:9: error: this ellipsoid needs `radii`"),
        "{e}"
    );
    let e = refused(
        "[[part]]\nshape = \"ellipsoid\"\nmass = 1\nradius = 1\nradii = [1, 1, 1]\ncenter = [0, 0, 0]\n",
    );
    assert!(
        e.starts_with("<stdin>:4:10: error: `radius` does not apply to"),
        "{e}"
    );
    assert!(
        e.contains("`radii` = [a, b, c]"),
        "the help names the key: {e}"
    );
}
