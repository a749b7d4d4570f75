//! The physics, against derivations independent of the code under test:
//! quadrature of the definitions, point-mass sums, hand-derived closed
//! results, and invariances. Tolerances are multiples of f64::EPSILON scaled
//! by the size of the quantity compared.

use massprop::analysis::Products;
use massprop::analysis::summary::{Accuracy, Summary, summarize};
use massprop::compose::Precision;
use massprop::diag::Source;
use massprop::la::{Matrix3, Vector3};
use massprop::model::{Analysis, Model};
use massprop::numeric::Real;

const EPS: f64 = f64::EPSILON;

fn summary_with(text: &str, products: Products) -> Summary {
    let source = Source::new("test.toml", text);
    let model = Model::parse(&source).unwrap_or_else(|d| panic!("{d}"));
    summarize(
        &model,
        &model.analysis,
        products,
        &Accuracy::fixed(Precision::Standard),
    )
    .expect("summary")
}

fn summary(text: &str) -> Summary {
    summary_with(text, Products::Tensor)
}

fn m3(rows: &[[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| rows[i][j])
}

fn v3(a: &[f64; 3]) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}

/// Relative Frobenius distance.
fn rel(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).norm() / b.norm()
}

/// Full-precision TOML array of a vector.
fn arr(v: &Vector3<f64>) -> String {
    format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z)
}

/// Gauss–Legendre nodes and weights on [0, 1], 3 points: exact for
/// polynomials of degree ≤ 5, so for the quadratic integrands of inertia.
fn gauss3() -> [(f64, f64); 3] {
    let a = (0.6f64).sqrt() / 2.0;
    [
        (0.5 - a, 5.0 / 18.0),
        (0.5, 8.0 / 18.0),
        (0.5 + a, 5.0 / 18.0),
    ]
}

/// Weighted sample points (x, dm) of a uniform parallelepiped of `mass`
/// spanned by `edges` from `corner`: a quadrature rule for ∫ f dm.
fn samples(mass: f64, corner: Vector3<f64>, edges: &[Vector3<f64>]) -> Vec<(Vector3<f64>, f64)> {
    let g = gauss3();
    let mut out = vec![(corner, mass)];
    for e in edges {
        out = out
            .into_iter()
            .flat_map(|(x, w)| g.iter().map(move |&(t, wt)| (x + e * t, w * wt)))
            .collect();
    }
    out
}

/// The inertia tensor about `p` straight from its definition,
/// I = ∫(|r|² E − r rᵀ) dm with r = x − p.
fn inertia_by_definition(points: &[(Vector3<f64>, f64)], p: Vector3<f64>) -> Matrix3<f64> {
    points.iter().fold(Matrix3::zeros(), |acc, (x, w)| {
        let r = x - p;
        acc + (Matrix3::identity() * r.norm_squared() - r * r.transpose()) * *w
    })
}

/// Mutually perpendicular integer edges, all of length 3 and oblique to the
/// file axes: (2,1,2), (1,2,−2), (2,−2,−1).
fn oblique() -> [Vector3<f64>; 3] {
    [
        Vector3::new(2.0, 1.0, 2.0),
        Vector3::new(1.0, 2.0, -2.0),
        Vector3::new(2.0, -2.0, -1.0),
    ]
}

#[test]
fn two_cubes_touching_at_a_corner_have_dominant_products() {
    // Hand derivation: each cube contributes m/12 = 0.5 to each diagonal of
    // C about its centre, and m d dᵀ = 6 · 0.25 = 1.5 to every entry, so
    // C = [[4,3,3],[3,4,3],[3,3,4]], I = tr(C) E − C = diag 8, products −3;
    // eigenvalues 8 − 6 = 2 along (1,1,1) and 8 + 3 = 11 twice.
    let s = summary(
        r#"
        [[part]]
        shape = "box"
        mass = 6
        size = [1, 1, 1]
        center = [0.5, 0.5, 0.5]
        [[part]]
        shape = "box"
        mass = 6
        size = [1, 1, 1]
        center = [-0.5, -0.5, -0.5]
        "#,
    );
    let expect = Matrix3::new(8.0, -3.0, -3.0, -3.0, 8.0, -3.0, -3.0, -3.0, 8.0);
    assert!(rel(&m3(&s.inertia_com), &expect) <= 4.0 * EPS);
    for (m, e) in s.principal_moments.iter().zip([2.0, 11.0, 11.0]) {
        assert!((m - e).abs() <= 16.0 * EPS * 11.0, "{m} vs {e}");
    }
    assert_eq!(s.equal_moments, vec![1, 2]);
    let a0 = v3(&s.principal_axes[0]);
    assert!((a0 - Vector3::new(1.0, 1.0, 1.0).normalize()).amax() <= 8.0 * EPS);
}

#[test]
fn box_plate_and_rod_match_quadrature_of_the_definition() {
    let [e1, e2, e3] = oblique();
    let (e1, e2, e3) = (e1 * 0.1, e2 * 0.5, e3 * 2.0); // a 0.3 × 1.5 × 6 box
    let corner = Vector3::new(1.25, -2.5, 0.75);
    let about = Vector3::new(-0.5, 3.0, 2.0);
    let cases: Vec<(&str, Vec<Vector3<f64>>, String)> = vec![
        (
            "box",
            vec![e1, e2, e3],
            format!(
                "shape = \"box\"\nmass = 2.5\ncorner = {}\nedges = [{}, {}, {}]",
                arr(&corner),
                arr(&e1),
                arr(&e2),
                arr(&e3)
            ),
        ),
        (
            "plate",
            vec![e1, e3],
            format!(
                "shape = \"plate\"\nmass = 2.5\ncorner = {}\nedges = [{}, {}]",
                arr(&corner),
                arr(&e1),
                arr(&e3)
            ),
        ),
        (
            "rod",
            vec![e3],
            format!(
                "shape = \"rod\"\nmass = 2.5\nfrom = {}\nto = {}",
                arr(&corner),
                arr(&(corner + e3))
            ),
        ),
    ];
    for (name, edges, part) in cases {
        let s = summary(&format!(
            "[[part]]\n{part}\n[analysis]\nabout = {}\n",
            arr(&about)
        ));
        let pts = samples(2.5, corner, &edges);
        let want_ref = inertia_by_definition(&pts, about);
        let com: Vector3<f64> = pts.iter().map(|(x, w)| x * *w).sum::<Vector3<f64>>() / 2.5;
        let want_com = inertia_by_definition(&pts, com);
        assert!(
            rel(&m3(&s.inertia_ref), &want_ref) <= 64.0 * EPS,
            "{name} about the reference point"
        );
        assert!(
            rel(&m3(&s.inertia_com), &want_com) <= 64.0 * EPS,
            "{name} about its centre"
        );
        assert!(
            (v3(&s.center_of_mass) - com).amax() <= 8.0 * EPS * com.amax(),
            "{name} centre"
        );
    }
}

#[test]
fn densities_give_mass_from_volume_area_and_length() {
    let s = summary(
        r#"
        [[part]]
        shape = "box"
        density = "7.85 g/cm^3"
        size = ["20 mm", "30 mm", "40 mm"]
        center = [0, 0, 0]
        [[part]]
        shape = "plate"
        areal_density = "70 kg/m^2"
        size = [0.2, 0.5]
        center = [0, 0, 0]
        [[part]]
        shape = "rod"
        linear_density = "0.5 kg/m"
        length = "2 ft"
        center = [0, 0, 0]
        "#,
    );
    // 7850 kg/m³ · 24e-6 m³, 70 kg/m² · 0.1 m², 0.5 kg/m · 0.6096 m.
    let masses = [7850.0 * 24e-6, 70.0 * 0.1, 0.5 * 0.6096];
    for (p, m) in s.parts.collect().iter().zip(masses) {
        assert!(
            (p.mass - m).abs() <= 4.0 * EPS * m,
            "{} {} vs {m}",
            p.name,
            p.mass
        );
    }
}

#[test]
fn every_rotation_form_gives_the_same_box() {
    // A general rotation: 40° about (1, 2, 3)/√14.
    let k = Vector3::new(1.0, 2.0, 3.0).normalize();
    let (s, c) = 20f64.to_radians().sin_cos();
    let (w, v) = (c, k * s);
    // R from the quaternion by the vector form (w² − |v|²) E + 2 v vᵀ + 2 w [v]×,
    // a different formula from the one the code uses.
    let r = Matrix3::identity() * (w * w - v.norm_squared())
        + v * v.transpose() * 2.0
        + v.cross_matrix() * (2.0 * w);
    // Intrinsic z-y-x angles of R = Rz(ψ) Ry(θ) Rx(φ).
    let yaw = r[(1, 0)].atan2(r[(0, 0)]).to_degrees();
    let pitch = (-r[(2, 0)]).asin().to_degrees();
    let roll = r[(2, 1)].atan2(r[(2, 2)]).to_degrees();
    let size = [0.5, 1.25, 3.0];
    let center = Vector3::new(0.1, -0.2, 0.3);
    let rows = |i: usize| arr(&Vector3::new(r[(i, 0)], r[(i, 1)], r[(i, 2)]));
    let forms = [
        format!(
            "{{ quaternion = [{w:?}, {:?}, {:?}, {:?}] }}",
            v.x, v.y, v.z
        ),
        "{ axis = [1, 2, 3], degrees = 40 }".to_string(),
        format!("{{ matrix = [{}, {}, {}] }}", rows(0), rows(1), rows(2)),
        format!("{{ intrinsic = \"zyx\", degrees = [{yaw:?}, {pitch:?}, {roll:?}] }}"),
        format!("{{ extrinsic = \"xyz\", degrees = [{roll:?}, {pitch:?}, {yaw:?}] }}"),
    ];
    // Reference: the same box by corner and edges, edges = R's columns × size.
    let edges: Vec<Vector3<f64>> = (0..3).map(|j| r.column(j) * size[j]).collect();
    let corner = center - (edges[0] + edges[1] + edges[2]) * 0.5;
    let want = inertia_by_definition(&samples(3.0, corner, &edges), center);
    for form in forms {
        let s = summary(&format!(
            "[[part]]\nshape = \"box\"\nmass = 3\nsize = [0.5, 1.25, 3]\ncenter = {}\nrotation = {form}\n",
            arr(&center)
        ));
        assert!(
            rel(&m3(&s.inertia_com), &want) <= 64.0 * EPS,
            "{form}: {}",
            rel(&m3(&s.inertia_com), &want)
        );
    }
}

#[test]
fn a_quarter_turn_about_z_swaps_ixx_and_iyy() {
    let part = |rot: &str| {
        summary(&format!(
            "[[part]]\nshape = \"box\"\nmass = 2\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n{rot}\n"
        ))
    };
    let a = part("");
    let b = part("rotation = { axis = [0, 0, 1], degrees = 90 }");
    assert_eq!(b.inertia_com[0][0], a.inertia_com[1][1]);
    assert_eq!(b.inertia_com[1][1], a.inertia_com[0][0]);
    assert_eq!(b.inertia_com[2][2], a.inertia_com[2][2]);
}

#[test]
fn three_stacked_unit_cubes_equal_one_long_box() {
    let cubes = summary(
        r#"
        [[part]]
        shape = "box"
        mass = 1
        size = [1, 1, 1]
        center = [0, -1, 0]
        [[part]]
        shape = "box"
        mass = 1
        size = [1, 1, 1]
        center = [0, 0, 0]
        [[part]]
        shape = "box"
        mass = 1
        size = [1, 1, 1]
        center = [0, 1, 0]
        "#,
    );
    let long =
        summary("[[part]]\nshape = \"box\"\nmass = 3\nsize = [1, 3, 1]\ncenter = [0, 0, 0]\n");
    assert!(rel(&m3(&cubes.inertia_com), &m3(&long.inertia_com)) <= 4.0 * EPS);
    assert_eq!(cubes.mass, long.mass);
}

/// A mixed assembly of every shape, in oblique orientations, shifted by `t`.
/// All coordinates are dyadic, so shifting by an integer is exact in f64.
fn assembly(t: Vector3<f64>, reverse: bool) -> String {
    let [e1, e2, e3] = oblique();
    let mut parts = [
        format!(
            "shape = \"box\"\nmass = 4\ncorner = {}\nedges = [{}, {}, {}]",
            arr(&(Vector3::new(0.25, -0.5, 1.0) + t)),
            arr(&(e1 * 0.5)),
            arr(&(e2 * 0.25)),
            arr(&e3)
        ),
        format!(
            "shape = \"plate\"\nmass = 1.5\ncorner = {}\nedges = [{}, {}]",
            arr(&(Vector3::new(-1.0, 0.5, 0.0) + t)),
            arr(&e2),
            arr(&(e3 * 0.5))
        ),
        format!(
            "shape = \"rod\"\nmass = 0.75\nfrom = {}\nto = {}",
            arr(&(Vector3::new(0.0, 0.0, -2.0) + t)),
            arr(&(Vector3::new(3.0, 1.0, -1.0) + t))
        ),
        format!(
            "shape = \"point\"\nmass = 0.5\ncenter = {}",
            arr(&(Vector3::new(-2.0, 1.5, 0.5) + t))
        ),
    ];
    if reverse {
        parts.reverse();
    }
    parts.iter().map(|p| format!("[[part]]\n{p}\n")).collect()
}

#[test]
fn translating_the_assembly_leaves_the_inertia_about_its_centre_unchanged() {
    let base = summary(&assembly(Vector3::zeros(), false));
    let i0 = m3(&base.inertia_com);
    for k in 0..=9 {
        let t = Vector3::new(1.0, -2.0, 3.0) * 10f64.powi(k);
        let s = summary(&assembly(t, false));
        let err = rel(&m3(&s.inertia_com), &i0);
        // The shift is exact in f64 here, so only the composer's own
        // rounding counts: a few roundings per entry. Without the correction
        // for the rounded centre of mass this is ~30 eps at 10⁹.
        assert!(err <= 8.0 * EPS, "offset 1e{k}: relative error {err:e}");
        for (a, b) in s.principal_moments.iter().zip(base.principal_moments) {
            assert!((a - b).abs() <= 16.0 * EPS * base.principal_moments[2]);
        }
    }
}

#[test]
fn the_far_offset_scene_defeats_summing_about_the_origin() {
    // The scene above is hard: summing about the origin and shifting back
    // (I_origin − m |c|² E + m c cᵀ) loses every digit at 10⁹. This checks
    // the test scene is sensitive enough for the previous test to mean
    // something.
    let t = Vector3::new(1.0, -2.0, 3.0) * 1e9;
    let model = Model::parse(&Source::new("t.toml", assembly(t, false))).unwrap();
    let body = massprop::compose::compose(&model, Precision::Standard);
    let com = Vector3::from(body.center_of_mass.map(|c| c.f64()));
    let naive: Matrix3<f64> = model.flattened().iter().fold(Matrix3::zeros(), |acc, p| {
        let s = p.si(model.units);
        acc + s.second_moment + s.center * s.center.transpose() * s.mass
    }) - com * com.transpose() * body.mass.f64();
    let exact = summary(&assembly(Vector3::zeros(), false));
    let naive_i = massprop::mass::inertia_of(&naive);
    assert!(rel(&naive_i, &m3(&exact.inertia_com)) > 1e-3);
}

#[test]
fn the_order_of_parts_does_not_matter() {
    let a = summary(&assembly(Vector3::new(10.0, 20.0, 30.0), false));
    let b = summary(&assembly(Vector3::new(10.0, 20.0, 30.0), true));
    assert!(rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= 16.0 * EPS);
    assert!((v3(&a.center_of_mass) - v3(&b.center_of_mass)).amax() <= 16.0 * EPS * 30.0);
}

#[test]
fn rotating_the_assembly_rotates_the_tensor_and_keeps_the_moments() {
    // A rational rotation: rows (2,1,2)/3, (1,2,−2)/3, (−2,2,1)/3, det +1.
    let q: Matrix3<f64> = Matrix3::new(2.0, 1.0, 2.0, 1.0, 2.0, -2.0, -2.0, 2.0, 1.0) / 3.0;
    assert!((q.determinant() - 1.0).abs() < 1e-15);
    let base = summary(&assembly(Vector3::zeros(), false));
    // Rotate every part's placement about the origin by Q.
    let [e1, e2, e3] = oblique().map(|e| q * e);
    let pt = |x: f64, y: f64, z: f64| arr(&(q * Vector3::new(x, y, z)));
    let rotated = format!(
        "[[part]]\nshape = \"box\"\nmass = 4\ncorner = {}\nedges = [{}, {}, {}]\n\
         [[part]]\nshape = \"plate\"\nmass = 1.5\ncorner = {}\nedges = [{}, {}]\n\
         [[part]]\nshape = \"rod\"\nmass = 0.75\nfrom = {}\nto = {}\n\
         [[part]]\nshape = \"point\"\nmass = 0.5\ncenter = {}\n",
        pt(0.25, -0.5, 1.0),
        arr(&(e1 * 0.5)),
        arr(&(e2 * 0.25)),
        arr(&e3),
        pt(-1.0, 0.5, 0.0),
        arr(&e2),
        arr(&(e3 * 0.5)),
        pt(0.0, 0.0, -2.0),
        pt(3.0, 1.0, -1.0),
        pt(-2.0, 1.5, 0.5),
    );
    let s = summary(&rotated);
    let want = q * m3(&base.inertia_com) * q.transpose();
    assert!(rel(&m3(&s.inertia_com), &want) <= 64.0 * EPS);
    for (a, b) in s.principal_moments.iter().zip(base.principal_moments) {
        assert!((a - b).abs() <= 64.0 * EPS * base.principal_moments[2]);
    }
    // Principal axes rotate with the body (up to the sign rule).
    for k in 0..3 {
        let a = v3(&s.principal_axes[k]);
        let b = q * v3(&base.principal_axes[k]);
        assert!((a.dot(&b).abs() - 1.0).abs() <= 1e-12, "axis {k}");
    }
}

#[test]
fn file_units_and_unit_strings_agree_with_si() {
    let si = summary(
        "[[part]]\nshape = \"box\"\nmass = 0.25\nsize = [0.02, 0.03, 0.05]\ncenter = [0.1, 0, 0]\n",
    );
    let mm_g = summary(
        "units = { length = \"mm\", mass = \"g\" }\n[[part]]\nshape = \"box\"\nmass = 250\nsize = [20, 30, 50]\ncenter = [100, 0, 0]\n",
    );
    let strings = summary(
        "[[part]]\nshape = \"box\"\nmass = \"250 g\"\nsize = [\"2 cm\", \"30 mm\", 0.05]\ncenter = [\"100 mm\", 0, 0]\n",
    );
    for s in [&mm_g, &strings] {
        assert!(rel(&m3(&s.inertia_com), &m3(&si.inertia_com)) <= 8.0 * EPS);
        assert!((s.mass - si.mass).abs() <= 2.0 * EPS * si.mass);
        assert!((v3(&s.center_of_mass) - v3(&si.center_of_mass)).amax() <= 2.0 * EPS * 0.1);
    }
    // Inches and pounds, exactly defined: a 1 lb, 1 in cube.
    let imperial = summary(
        "units = { length = \"in\", mass = \"lb\" }\n[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n",
    );
    let want = 0.45359237 * 0.0254 * 0.0254 / 6.0;
    assert!((imperial.inertia_com[0][0] - want).abs() <= 8.0 * EPS * want);
}

#[test]
fn dynamics_match_sums_over_the_mass_distribution() {
    // H, T and M from their definitions over quadrature points of an oblique
    // box and a point mass, about a fixed point O:
    // H = Σ r × (ω × r) dm, T = ½ Σ |ω × r|² dm,
    // M = Σ r × (α × r + ω × (ω × r)) dm.
    let [e1, e2, e3] = oblique();
    let (e1, e2, e3) = (e1 * 0.5, e2 * 0.25, e3);
    let corner = Vector3::new(0.25, -0.5, 1.0);
    let point = Vector3::new(-2.0, 1.5, 0.5);
    let o = Vector3::new(0.5, 0.25, -0.75);
    let omega = Vector3::new(1.5, -2.0, 30.0);
    let alpha = Vector3::new(-3.0, 0.5, 2.0);
    let s = summary(&format!(
        "[[part]]\nshape = \"box\"\nmass = 4\ncorner = {}\nedges = [{}, {}, {}]\n\
         [[part]]\nshape = \"point\"\nmass = 0.5\ncenter = {}\n\
         [analysis]\nabout = {}\nomega = {}\nalpha = {}\n",
        arr(&corner),
        arr(&e1),
        arr(&e2),
        arr(&e3),
        arr(&point),
        arr(&o),
        arr(&omega),
        arr(&alpha)
    ));
    let mut pts = samples(4.0, corner, &[e1, e2, e3]);
    pts.push((point, 0.5));
    let (mut h, mut t, mut m) = (Vector3::zeros(), 0.0, Vector3::zeros());
    for (x, dm) in &pts {
        let r = x - o;
        let v = omega.cross(&r);
        h += r.cross(&v) * *dm;
        t += 0.5 * v.norm_squared() * dm;
        m += r.cross(&(alpha.cross(&r) + omega.cross(&v))) * *dm;
    }
    let got_h = v3(&s.angular_momentum.expect("H with ω"));
    let got_m = v3(&s.euler_moment.expect("M with α"));
    assert!((got_h - h).norm() <= 256.0 * EPS * h.norm());
    assert!((s.kinetic_energy.expect("T with ω") - t).abs() <= 256.0 * EPS * t);
    assert!((got_m - m).norm() <= 256.0 * EPS * m.norm());
}

#[test]
fn positive_products_flip_only_the_off_diagonals() {
    let text = assembly(Vector3::new(0.5, 0.25, 0.0), false);
    let t = summary_with(&text, Products::Tensor);
    let p = summary_with(&text, Products::Positive);
    for i in 0..3 {
        for j in 0..3 {
            let sign = if i == j { 1.0 } else { -1.0 };
            assert_eq!(p.inertia_com[i][j], sign * t.inertia_com[i][j]);
            assert_eq!(p.inertia_ref[i][j], sign * t.inertia_ref[i][j]);
        }
    }
    assert_eq!(p.principal_moments, t.principal_moments);
    assert_eq!(p.principal_axes, t.principal_axes);
    assert!(
        t.inertia_com[0][1] != 0.0,
        "the scene must have products to flip"
    );
}

#[test]
fn principal_axes_are_unit_right_handed_and_diagonalise_the_tensor() {
    let s = summary(&assembly(Vector3::new(0.5, 0.25, 0.0), false));
    let i = m3(&s.inertia_com);
    let a: Vec<Vector3<f64>> = s.principal_axes.iter().map(v3).collect();
    assert!((a[0].cross(&a[1]) - a[2]).amax() <= 8.0 * EPS);
    for (a, m) in a.iter().zip(s.principal_moments) {
        assert!((a.norm() - 1.0).abs() <= 4.0 * EPS);
        assert!((i * a - a * m).norm() <= 64.0 * EPS * i.norm());
    }
    assert!(
        s.principal_moments[0] <= s.principal_moments[1]
            && s.principal_moments[1] <= s.principal_moments[2]
    );
    // Radii of gyration: k = √(I/m).
    for k in 0..3 {
        let r = s.radii_of_gyration[k];
        assert!(
            (r * r * s.mass - s.principal_moments[k]).abs() <= 8.0 * EPS * s.principal_moments[k]
        );
    }
}

#[test]
fn overrides_replace_the_file_analysis() {
    let source = Source::new("t.toml", assembly(Vector3::zeros(), false));
    let model = Model::parse(&source).unwrap();
    let w = Vector3::new(0.0, 0.0, 2.0);
    let a = summarize(
        &model,
        &Analysis {
            about: Some(Vector3::new(1.0, 0.0, 0.0)),
            omega: Some(w),
            alpha: None,
            ..Analysis::default()
        },
        Products::Tensor,
        &Accuracy::fixed(Precision::Standard),
    )
    .unwrap();
    assert_eq!(a.reference_point, [1.0, 0.0, 0.0]);
    let h = m3(&a.inertia_ref) * w;
    assert_eq!(a.angular_momentum, Some([h.x, h.y, h.z]));
    assert!(a.euler_moment.is_none() && a.alpha.is_none());
}

#[test]
fn extreme_masses_and_lengths_scale_exactly() {
    // Scaling every mass by M and every length by L, both powers of two, is
    // exact in f64, so inertia must scale by exactly M L² and the centre by
    // L, right up to the edges of the f64 range. Squares of huge or tiny
    // intermediate values (|v|², s sᵀ) must not overflow or underflow.
    let base = summary(&assembly(Vector3::new(0.5, 0.25, 0.0), false));
    let p = |e: i32| 2f64.powi(e);
    for (me, le) in [
        (560, 0),
        (-500, 0),
        (660, -560),
        (0, 330),
        (-1000, 500),
        (900, -150),
    ] {
        let (m, l) = (p(me), p(le));
        let text = assembly(Vector3::new(0.5, 0.25, 0.0), false);
        let mut scaled = String::new();
        for line in text.lines() {
            let out = match line.split_once(" = ") {
                Some(("mass", v)) => format!("mass = {:?}", v.parse::<f64>().unwrap() * m),
                Some((k @ ("corner" | "from" | "to" | "center" | "edges"), v)) => {
                    let v: toml::Value = toml::from_str(&format!("x = {v}")).unwrap();
                    let scale = |x: &toml::Value| {
                        toml::Value::Float(
                            x.as_float().or(x.as_integer().map(|i| i as f64)).unwrap() * l,
                        )
                    };
                    let v = match &v["x"] {
                        toml::Value::Array(a) if a[0].is_array() => toml::Value::Array(
                            a.iter()
                                .map(|r| {
                                    toml::Value::Array(
                                        r.as_array().unwrap().iter().map(scale).collect(),
                                    )
                                })
                                .collect(),
                        ),
                        toml::Value::Array(a) => toml::Value::Array(a.iter().map(scale).collect()),
                        _ => unreachable!(),
                    };
                    format!("{k} = {v}")
                }
                _ => line.to_string(),
            };
            scaled.push_str(&out);
            scaled.push('\n');
        }
        let s = summary(&scaled);
        let want = m3(&base.inertia_com) * (m * l * l);
        assert!(
            rel(&m3(&s.inertia_com), &want) <= EPS,
            "2^{me} kg, 2^{le} m: relative error {:e}",
            rel(&m3(&s.inertia_com), &want)
        );
        assert!((s.mass - base.mass * m).abs() <= EPS * s.mass);
        assert!((v3(&s.center_of_mass) - v3(&base.center_of_mass) * l).amax() <= EPS * l);
        for (a, b) in s.principal_moments.iter().zip(base.principal_moments) {
            assert!(
                (a - b * m * l * l).abs() <= 2.0 * EPS * a,
                "2^{me} kg, 2^{le} m"
            );
        }
    }
}

// Idealisation: a plate's `thickness` and a rod's `diameter`; shares of the
// principal moments.

fn summary_in(text: &str, precision: Precision) -> Summary {
    let source = Source::new("test.toml", text);
    let model = Model::parse(&source).unwrap_or_else(|d| panic!("{d}"));
    summarize(
        &model,
        &model.analysis,
        Products::Tensor,
        &Accuracy::fixed(precision),
    )
    .expect("summary")
}

fn idealisation(s: &Summary) -> &massprop::analysis::ideal::Idealisation {
    s.idealisation.as_ref().expect("the file gives a real size")
}

/// A plate in an oblique orientation with a box beside it, once with the
/// plate's `thickness` and once with the plate replaced by the solid box it
/// stands for (same mass, centre and rotation).
fn plate_and_box(t: f64) -> (String, String) {
    let other =
        "[[part]]\nshape = \"box\"\nmass = 2\nsize = [0.5, 0.25, 1]\ncenter = [1, -0.5, 0.25]\n";
    let place = "center = [-0.25, 0.5, 0.125]\nrotation = { axis = [1, 2, -0.5], degrees = 33 }";
    let plate = format!(
        "{other}[[part]]\nshape = \"plate\"\nmass = 3\nsize = [1.5, 0.75]\n{place}\nthickness = {t:?}\n"
    );
    let solid =
        format!("{other}[[part]]\nshape = \"box\"\nmass = 3\nsize = [1.5, 0.75, {t:?}]\n{place}\n");
    (plate, solid)
}

#[test]
fn a_plate_with_thickness_reports_the_moments_of_the_solid_box() {
    for t in [0.1, 0.01, 0.6] {
        let (plate, solid) = plate_and_box(t);
        let (p, b) = (summary(&plate), summary(&solid));
        let i = idealisation(&p);
        for (k, (got, want)) in i
            .principal_moments_solid
            .iter()
            .zip(b.principal_moments)
            .enumerate()
        {
            // Both sides composed and diagonalised in f64: a few roundings
            // of the largest moment each.
            assert!(
                (got - want).abs() <= 32.0 * EPS * b.principal_moments[2],
                "t = {t}, I{}: {got} vs box {want}",
                k + 1,
            );
        }
        // Making a part solid adds a positive semi-definite term to the
        // inertia, so no moment decreases; each change is the box's moment
        // over the plate's, minus one.
        for (k, c) in i.relative_change.iter().enumerate() {
            let want = b.principal_moments[k] / p.principal_moments[k] - 1.0;
            let c = c.expect("no moment is zero");
            assert!(c >= 0.0);
            assert!(
                (c - want).abs() <= 64.0 * EPS * p.principal_moments[2] / p.principal_moments[k],
                "t = {t}: {c:e} vs {want:e}"
            );
        }
    }
}

#[test]
fn a_plate_by_corner_and_edges_reports_the_solid_box_too() {
    // Oblique edges of length 3 and 1.5; the box is the plate spread over
    // t/2 either side of it along the unit normal.
    let [e1, e2, e3] = oblique();
    let (e1, e2, n) = (e1, e2 * 0.5, e3 / 3.0);
    let (corner, t) = (Vector3::new(1e6, -2e6, 0.5), 0.25);
    let plate = format!(
        "[[part]]\nshape = \"plate\"\nmass = 5\ncorner = {}\nedges = [{}, {}]\nthickness = {t:?}\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = {}\n",
        arr(&corner),
        arr(&e1),
        arr(&e2),
        arr(&(corner + Vector3::new(2.0, 1.0, 0.5)))
    );
    let solid = format!(
        "[[part]]\nshape = \"box\"\nmass = 5\ncorner = {}\nedges = [{}, {}, {}]\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = {}\n",
        arr(&(corner - n * (t / 2.0))),
        arr(&e1),
        arr(&e2),
        arr(&(n * t)),
        arr(&(corner + Vector3::new(2.0, 1.0, 0.5)))
    );
    let (p, b) = (summary(&plate), summary(&solid));
    let got = idealisation(&p).principal_moments_solid;
    for (got, want) in got.iter().zip(b.principal_moments) {
        // The box's corner 1e6 from the origin rounds to 1e6 ε ≈ 2e-10 of
        // the edges: the moments agree to that.
        assert!(
            (got - want).abs() <= 1e-9 * b.principal_moments[2],
            "{got} vs box {want}"
        );
    }
}

#[test]
fn a_rod_with_diameter_reports_the_moments_of_the_solid_cylinder() {
    // Axis (1, 2, 2)/3, length 3: I_axial = m r²/2, I_across = m(3r² + L²)/12.
    let (m, l, d) = (4.0, 3.0, 0.2);
    let r = d / 2.0;
    let s = summary(&format!(
        "[[part]]\nshape = \"rod\"\nmass = {m:?}\nfrom = [1, -1, 2]\nto = [2, 1, 4]\ndiameter = {d:?}\n"
    ));
    let i = idealisation(&s);
    let want = [
        m * r * r / 2.0,
        m * (3.0 * r * r + l * l) / 12.0,
        m * (3.0 * r * r + l * l) / 12.0,
    ];
    for k in 0..3 {
        assert!(
            (i.principal_moments_solid[k] - want[k]).abs() <= 32.0 * EPS * want[2],
            "I{}: {} vs {}",
            k + 1,
            i.principal_moments_solid[k],
            want[k]
        );
    }
    // The idealised axial moment is 0: its change is not a number.
    assert_eq!(i.relative_change[0], None);
    assert_eq!(s.parts.collect()[0].principal_moment_share[0], None);
    let across = 3.0 * r * r / (l * l);
    for c in &i.relative_change[1..] {
        let c = c.expect("the moments across the rod are not zero");
        assert!((c - across).abs() <= 64.0 * EPS, "{c:e} vs {across:e}");
    }
    assert_eq!(i.parts[0].relative_change, i.relative_change);
}

#[test]
fn a_thin_plate_changes_its_moments_by_the_square_of_its_thinness() {
    // Square plate a × a, t = 1e-3 a: in-plane moments m(a² + t²)/12 against
    // m a²/12, a change of (t/a)² = 1e-6; the moment about the normal is
    // m a²/6 either way.
    let text = "[[part]]\nshape = \"plate\"\nmass = 2\nsize = [0.5, 0.5]\ncenter = [1, 2, 3]\nthickness = 5e-4\n";
    let c = idealisation(&summary(text))
        .relative_change
        .map(Option::unwrap);
    for c in &c[..2] {
        // Error: a few ε of I3 = 2 I1, relative to I1.
        assert!((c - 1e-6).abs() <= 16.0 * EPS, "{c:e}");
    }
    assert!(c[2].abs() <= 16.0 * EPS, "{:e}", c[2]);
}

#[test]
fn extended_precision_resolves_a_change_below_f64() {
    // t/a = 1e-9 in an oblique orientation: a change of 1e-18, beneath the
    // rounding of an f64 composition, is resolved in double-double.
    let text = "[[part]]\nshape = \"plate\"\nmass = 2\nsize = [0.5, 0.5]\ncenter = [1, 2, 3]\nrotation = { axis = [1, 2, 3], degrees = 40 }\nthickness = 5e-10\n";
    let s = summary_in(text, Precision::Extended);
    let c = idealisation(&s).relative_change.map(Option::unwrap);
    let dd = <massprop::numeric::DD as Real>::EPS;
    for c in &c[..2] {
        assert!((c - 1e-18).abs() <= 1e-18 * 1e-9 + 64.0 * dd, "{c:e}");
    }
    assert!(c[2].abs() <= 64.0 * dd, "{:e}", c[2]);
}

#[test]
fn thickness_and_diameter_change_nothing_in_the_composition() {
    let with = "[[part]]\nshape = \"plate\"\nmass = 3\nsize = [2, 1]\ncenter = [0, 1, 0]\nthickness = \"1 cm\"\n[[part]]\nshape = \"rod\"\nmass = 1\nfrom = [0, 0, 0]\nto = [1, 1, 0]\ndiameter = 0.05\n";
    let without = with
        .replace("thickness = \"1 cm\"\n", "")
        .replace("diameter = 0.05\n", "");
    let (a, b) = (summary(with), summary(&without));
    assert!(a.idealisation.is_some() && b.idealisation.is_none());
    let json = |s: &Summary| {
        let mut v: serde_json::Value =
            serde_json::from_str(&massprop::output::report::json(s)).unwrap();
        v.as_object_mut().unwrap().remove("idealisation");
        v
    };
    assert_eq!(json(&a), json(&b));
}

#[test]
fn idealisation_is_absent_from_json_without_real_sizes() {
    let s = summary(&assembly(Vector3::zeros(), false));
    let v: serde_json::Value = serde_json::from_str(&massprop::output::report::json(&s)).unwrap();
    assert!(v.get("idealisation").is_none());
    assert!(v["parts"][0]["principal_moment_share"].is_array());
}

#[test]
fn shares_of_every_principal_moment_sum_to_one() {
    for k in [0, 3, 9] {
        let t = Vector3::new(1.0, -2.0, 3.0) * 10f64.powi(k);
        let s = summary(&assembly(t, false));
        for m in 0..3 {
            let sum: f64 = s
                .parts
                .collect()
                .iter()
                .map(|p| p.principal_moment_share[m].unwrap())
                .sum();
            // Each share carries a few ε of I3 / I_m; four parts.
            let bound = 32.0 * EPS * s.principal_moments[2] / s.principal_moments[m];
            assert!(
                (sum - 1.0).abs() <= bound,
                "offset 1e{k}, I{}: {sum}",
                m + 1
            );
            assert!(
                s.parts
                    .collect()
                    .iter()
                    .all(|p| p.principal_moment_share[m] >= Some(0.0))
            );
        }
        // Far from the origin the shares are those of the same assembly at
        // the origin: offsets come from the centre of mass.
        let base = summary(&assembly(Vector3::zeros(), false));
        for (p, q) in s.parts.collect().iter().zip(&base.parts.collect()) {
            for m in 0..3 {
                let (a, b) = (p.principal_moment_share[m], q.principal_moment_share[m]);
                assert!(
                    (a.unwrap() - b.unwrap()).abs()
                        <= 64.0 * EPS * base.principal_moments[2] / base.principal_moments[m],
                    "offset 1e{k}: {a:?} vs {b:?}"
                );
            }
        }
    }
}

#[test]
fn a_gram_at_the_centre_of_mass_has_no_share_and_one_a_metre_away_a_small_one() {
    // A 10 kg unit cube and a 1 g point at its centre: the point adds
    // nothing to any moment.
    let cube = "[[part]]\nshape = \"box\"\nmass = 10\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";
    let s = summary(&format!(
        "{cube}[[part]]\nshape = \"point\"\nmass = 0.001\ncenter = [0, 0, 0]\n"
    ));
    for m in 0..3 {
        assert!(s.parts.collect()[1].principal_moment_share[m].unwrap() <= EPS);
        assert!((s.parts.collect()[0].principal_moment_share[m].unwrap() - 1.0).abs() <= 8.0 * EPS);
    }
    // One metre away along x: the centre moves by δ = 0.001/10.001; about
    // an axis across x the point contributes 0.001 (1 − δ)² of
    // I = 10/6 + 10 δ² + 0.001 (1 − δ)²; along x, nothing.
    let s = summary(&format!(
        "{cube}[[part]]\nshape = \"point\"\nmass = 0.001\ncenter = [1, 0, 0]\n"
    ));
    let delta = 0.001 / 10.001;
    let point = 0.001 * (1.0 - delta) * (1.0 - delta);
    let want = point / (10.0 / 6.0 + 10.0 * delta * delta + point);
    let axial = (0..3)
        .find(|&m| s.principal_axes[m][0].abs() > 0.5)
        .expect("one principal axis is x");
    for m in 0..3 {
        let share = s.parts.collect()[1].principal_moment_share[m].unwrap();
        if m == axial {
            assert!(share <= EPS, "{share:e}");
        } else {
            assert!(
                (share - want).abs() <= 16.0 * EPS * want,
                "{share:e} vs {want:e}"
            );
        }
    }
}

#[test]
fn round_shapes_match_their_textbook_moments_in_both_precisions() {
    // A tube turned a quarter turn about x (its axis, local z, along −y),
    // and a hollow sphere: I about the centre of mass from the closed forms
    // written out here, I_axis = m(R² + r²)/2, I_diam = m((R² + r²)/4 + L²/12),
    // I_sphere = 2/5 m (R⁵ − r⁵)/(R³ − r³).
    let text = "[[part]]\nshape = \"cylinder\"\nmass = 3\nradius = 0.5\ninner_radius = 0.25\n\
                length = 2\ncenter = [0, 0, 0]\nrotation = { axis = [1, 0, 0], degrees = 90 }\n\
                [[part]]\nshape = \"sphere\"\nmass = 2\nradius = 0.5\ninner_radius = 0.25\n\
                center = [0, 0, 0]\n";
    let (r2, rr2) = (0.25 + 0.0625, 0.25 + 0.0625);
    let axis = 3.0 * r2 / 2.0;
    let diam = 3.0 * (rr2 / 4.0 + 4.0 / 12.0);
    let sphere =
        0.4 * 2.0 * (0.5f64.powi(5) - 0.25f64.powi(5)) / (0.5f64.powi(3) - 0.25f64.powi(3));
    let want = [diam + sphere, axis + sphere, diam + sphere];
    for precision in [Precision::Standard, Precision::Extended] {
        let source = Source::new("t.toml", text);
        let model = Model::parse(&source).unwrap_or_else(|d| panic!("{d}"));
        let s = summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            &Accuracy::fixed(precision),
        )
        .unwrap();
        for (k, w) in want.iter().enumerate() {
            let got = s.inertia_com[k][k];
            assert!(
                (got - w).abs() <= 8.0 * EPS * w,
                "{precision:?} {k}: {got} vs {w}"
            );
        }
        assert!(s.inertia_com[0][1].abs() <= 8.0 * EPS * want[0]);
        assert!(s.inertia_com[1][2].abs() <= 8.0 * EPS * want[0]);
    }
}

#[test]
fn a_disk_with_a_disk_cut_out_is_an_annulus() {
    let cut = "[[part]]\nshape = \"disk\"\nareal_density = 40\nradius = 0.3\ncenter = [1, 2, 3]\n\
               [[part]]\nshape = \"disk\"\nareal_density = 40\nradius = 0.1\ncenter = [1, 2, 3]\n\
               remove = true\n";
    let ring = "[[part]]\nshape = \"disk\"\nareal_density = 40\nradius = 0.3\ninner_radius = 0.1\n\
                center = [1, 2, 3]\n";
    for precision in [Precision::Standard, Precision::Extended] {
        let (a, b) = (summary_in(cut, precision), summary_in(ring, precision));
        assert!((a.mass - b.mass).abs() <= 8.0 * EPS * b.mass);
        // The cut-out's mass is 1/9 of the disk's: rounding grows by 9/8.
        assert!(rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= 16.0 * EPS);
        assert_eq!(
            a.parts.collect()[1].mass.signum(),
            -1.0,
            "a cut-out's mass is negative"
        );
    }
}

#[test]
fn a_box_less_a_nearly_equal_box_keeps_its_digits_in_extended_precision() {
    // A closed box with walls t = 1e-6 of its size: a unit cube less a cube
    // of side b = 1 − 2t, both of density 1000. By hand, about the centre:
    // m = ρ(1 − b³), I_xx = ρ(1 − b⁵)/6. Each difference loses ~5 digits:
    // the cancellation factor κ = 1/(1 − b⁵) ≈ 1e5. Here in double-double
    // from the closed forms (b is an exact f64: 1 − 2⁻¹⁹·…, b⁵ exact in DD
    // to 1e-32).
    use massprop::numeric::DD;
    let b = 1.0 - 2.0 * 1e-6;
    let text = format!(
        "[[part]]\nshape = \"box\"\ndensity = 1000\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"box\"\ndensity = 1000\nsize = [{b:?}, {b:?}, {b:?}]\ncenter = [0, 0, 0]\n\
         remove = true\n"
    );
    let bd = DD::of(b);
    let b3 = bd * bd * bd;
    let b5 = b3 * bd * bd;
    let mass = (DD::of(1000.0) * (DD::of(1.0) - b3)).f64();
    let ixx = (DD::of(1000.0) * (DD::of(1.0) - b5) / DD::of(6.0)).f64();
    let kappa = 1.0 / (1.0 - b.powi(5));
    for (precision, bound) in [
        // Standard: each term is rounded before the difference, ~κ ε.
        (Precision::Standard, 8.0 * EPS * kappa),
        // Extended: the difference is taken in double-double.
        (Precision::Extended, 4.0 * EPS),
    ] {
        let s = summary_in(&text, precision);
        let err_m = (s.mass - mass).abs() / mass;
        let err_i = (s.inertia_com[0][0] - ixx).abs() / ixx;
        eprintln!("{precision:?}: mass {err_m:e}, Ixx {err_i:e} (bound {bound:e})");
        assert!(
            err_m <= bound && err_i <= bound,
            "{precision:?}: {err_m:e} {err_i:e}"
        );
        for k in 0..3 {
            assert!((s.principal_moments[k] - ixx).abs() <= bound * ixx);
        }
    }
}

#[test]
fn a_given_inertia_composes_like_the_shape_it_describes() {
    // A 2 × 1 × 0.5 box of 6 kg, turned, as a box and as its inertia
    // tensor written by hand: I = m/12 diag(b² + c², a² + c², a² + b²).
    let rot = "rotation = { axis = [1, 2, 2], degrees = 40 }";
    let as_box = format!(
        "[[part]]\nshape = \"box\"\nmass = 6\nsize = [2, 1, 0.5]\ncenter = [1, 0, 0]\n{rot}\n\
         [[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 3, 0]\n"
    );
    let given = format!(
        "[[part]]\nshape = \"inertia\"\nmass = 6\ncenter = [1, 0, 0]\n{rot}\n\
         inertia = [[0.625, 0, 0], [0, 2.125, 0], [0, 0, 2.5]]\n\
         [[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 3, 0]\n"
    );
    for precision in [Precision::Standard, Precision::Extended] {
        let (a, b) = (
            summary_in(&as_box, precision),
            summary_in(&given, precision),
        );
        assert!(
            rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= 16.0 * EPS,
            "{precision:?}"
        );
    }
    // Products: the same off-diagonal written +∫xy dm with `products =
    // "positive"` is the tensor entry with its sign flipped.
    let tensor = "[[part]]\nshape = \"inertia\"\nmass = 1\ncenter = [0, 0, 0]\n\
                  inertia = [[2, -0.5, 0], [-0.5, 3, 0], [0, 0, 4]]\n";
    let positive = "[[part]]\nshape = \"inertia\"\nmass = 1\ncenter = [0, 0, 0]\n\
                    inertia = [[2, 0.5, 0], [0.5, 3, 0], [0, 0, 4]]\nproducts = \"positive\"\n";
    let (a, b) = (summary(tensor), summary(positive));
    assert_eq!(a.inertia_com, b.inertia_com);
    assert_eq!(a.inertia_com[0][1], -0.5);
}

#[test]
fn two_triangles_make_the_rectangle_they_split() {
    // A 0.3125 × 0.25 rectangle in a tilted plane, 1e6 from the origin
    // (dyadic, so every vertex is exact in f64), split
    // along a diagonal: the two triangles compose to the plate exactly
    // (the same areal density, so the same mass), in both precisions.
    let o = [1e6, -2e6, 5e5];
    let (e1, e2) = ([0.1875, 0.25, 0.0], [0.0, 0.0, 0.25]);
    let at = |s: f64, t: f64| -> String {
        let p: Vec<String> = (0..3)
            .map(|i| format!("{:?}", o[i] + s * e1[i] + t * e2[i]))
            .collect();
        format!("[{}]", p.join(", "))
    };
    let tri = format!(
        "[[part]]\nshape = \"triangle\"\nareal_density = 12.5\nvertices = [{}, {}, {}]\n\
         [[part]]\nshape = \"triangle\"\nareal_density = 12.5\nvertices = [{}, {}, {}]\n",
        at(0.0, 0.0),
        at(1.0, 0.0),
        at(1.0, 1.0),
        at(0.0, 0.0),
        at(1.0, 1.0),
        at(0.0, 1.0)
    );
    let plate = format!(
        "[[part]]\nshape = \"plate\"\nareal_density = 12.5\ncorner = {}\nedges = [{:?}, {:?}]\n",
        at(0.0, 0.0),
        e1,
        e2
    );
    for precision in [Precision::Standard, Precision::Extended] {
        let (a, b) = (summary_in(&tri, precision), summary_in(&plate, precision));
        assert!(
            (a.mass - b.mass).abs() <= 8.0 * EPS * b.mass,
            "{precision:?}"
        );
        assert!(
            rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= 32.0 * EPS,
            "{precision:?}"
        );
    }
}

#[test]
fn a_triangle_matches_a_quadrature_of_its_definition() {
    // ∫ρρᵀ dm by the degree-2 rule at (⅙, ⅙, ⅔) and its permutations,
    // exact for the quadratic integrand, about the centroid.
    let v = [[0.1, 0.0, 0.3], [0.7, 0.2, -0.1], [0.2, 0.9, 0.4]];
    let text = format!(
        "[[part]]\nshape = \"triangle\"\nmass = 2\nvertices = [{:?}, {:?}, {:?}]\n",
        v[0], v[1], v[2]
    );
    let s = summary(&text);
    let g: Vec<f64> = (0..3)
        .map(|i| (v[0][i] + v[1][i] + v[2][i]) / 3.0)
        .collect();
    let mut c = Matrix3::zeros();
    for w in [
        [2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0],
        [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0],
        [1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0],
    ] {
        let p = Vector3::from_fn(|i, _| (0..3).map(|k| w[k] * v[k][i]).sum::<f64>() - g[i]);
        c += p * p.transpose() * (2.0 / 3.0);
    }
    let i = massprop::mass::inertia_of(&c);
    assert!(rel(&m3(&s.inertia_com), &i) <= 16.0 * EPS);
}

#[test]
fn extreme_inputs_found_in_review_give_answers_not_hangs_or_nan() {
    // A rotation of 1e-300 degrees is the identity to f64 precision (the
    // double-double sine once looped forever on it), with or without the
    // idealisation report, which always turns parts in double-double.
    let plain = "[[part]]\nshape = \"plate\"\nmass = 1\nsize = [1, 2]\ncenter = [0, 0, 0]\nthickness = 0.01\n";
    let turned = format!("{plain}rotation = {{ axis = [1, 0, 0], degrees = 1e-300 }}\n");
    for precision in [Precision::Standard, Precision::Extended] {
        let (a, b) = (summary_in(plain, precision), summary_in(&turned, precision));
        assert!(
            rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= EPS,
            "{precision:?}"
        );
    }
    // Two 1e300 kg points: the first moment Σ mᵢcᵢ would overflow, the
    // centre of mass and inertia do not.
    let heavy = "[[part]]\nshape = \"point\"\nmass = 1e300\ncenter = [1e9, 0, 0]\n\
                 [[part]]\nshape = \"point\"\nmass = 1e300\ncenter = [1e9, 1, 0]\n";
    for precision in [Precision::Standard, Precision::Extended] {
        let s = summary_in(heavy, precision);
        assert_eq!(s.center_of_mass, [1e9, 0.5, 0.0]);
        // I_xx = 2 m (½)² = 5e299.
        assert!((s.inertia_com[0][0] / 5e299 - 1.0).abs() <= 4.0 * EPS);
    }
    // A box 1e151 × 1e-150 × 1: the Jacobi angle's θ overflows unless it is
    // formed with care; both precisions agree on the moments.
    let long = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1e151, 1e-150, 1]\ncenter = [0, 0, 0]\n\
                rotation = { quaternion = [1, 0, 0, 1e-310] }\n";
    let (a, b) = (
        summary_in(long, Precision::Standard),
        summary_in(long, Precision::Extended),
    );
    for k in 1..3 {
        assert!((a.principal_moments[k] / b.principal_moments[k] - 1.0).abs() <= 8.0 * EPS);
    }
}

#[test]
fn every_rotation_form_keeps_the_smallest_moment_of_a_slender_box() {
    // The principal moments of a box do not depend on its orientation, so
    // the exact smallest moment of a 1e-9 × 1e-9 × 1 box of 1 kg is
    // (a² + a²)/12 for the f64 value a of 1e-9, whatever the rotation:
    // this checks the double-double sine and Newton–Schulz of every form
    // against an exact value (the exact reference covers quaternions).
    use massprop::numeric::DD;
    let a = 1e-9;
    let ad = DD::of(a);
    let exact = ((ad * ad + ad * ad) / DD::of(12.0)).f64();
    let top_over_min = (1.0 / 12.0) / exact;
    for rotation in [
        "{ axis = [1, 2, 3], degrees = 37.25 }",
        "{ intrinsic = \"zyx\", degrees = [10, 20.5, 30] }",
        "{ extrinsic = \"xzx\", degrees = [-70, 33, 12.125] }",
        // A Pythagorean rotation written to 17 digits: orthonormal to ~1e-16,
        // made exactly orthonormal by Newton–Schulz.
        "{ matrix = [[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]] }",
        "{ quaternion = [0.5, 0.5, -0.5, 0.5] }",
    ] {
        let text = format!(
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [{a:?}, {a:?}, 1]\ncenter = [0, 0, 0]\nrotation = {rotation}\n"
        );
        let ext = summary_in(&text, Precision::Extended).principal_moments[0];
        let err = (ext - exact).abs() / exact;
        assert!(err <= 1e-12, "{rotation}: extended {err:e}");
        // Standard: the tensor's entries round by ~ε·I_max; no better.
        let std = summary_in(&text, Precision::Standard).principal_moments[0];
        assert!(
            (std - exact).abs() <= 12.0 * EPS * top_over_min * exact,
            "{rotation}: standard"
        );
    }
}

#[test]
fn materials_give_the_mass_of_their_density_times_the_size() {
    // By hand: 30 kg/m³ foam, 0.1 m cube: 0.03 kg; 2 mm 6061 plate
    // 0.1 × 0.05 m: 2700 · 1e-5 = 0.027 kg; a steel rod of 4 mm diameter,
    // overridden to 7900 kg/m³, 0.2 m long: 7900 · π · 4e-6 · 0.2;
    // Ti-6Al-4V rod of 12 mm² section, 0.1 m: 4430 · 1.2e-6.
    let text = "units = { length = \"mm\", mass = \"kg\" }\n\
                [materials]\nfoam = { density = \"30 kg/m^3\" }\nsteel = { density = 7.9e-6 }\n\
                [[part]]\nshape = \"box\"\nmaterial = \"foam\"\nsize = [100, 100, 100]\ncenter = [0, 0, 0]\n\
                [[part]]\nshape = \"plate\"\nmaterial = \"aluminium-6061\"\nthickness = 2\nsize = [100, 50]\ncenter = [0, 0, 60]\n\
                [[part]]\nshape = \"rod\"\nmaterial = \"steel\"\ndiameter = 4\nlength = 200\ncenter = [0, 0, -60]\n\
                [[part]]\nshape = \"rod\"\nmaterial = \"titanium-6al-4v\"\narea = \"12 mm^2\"\nlength = 100\ncenter = [0, 0, -70]\n";
    let s = summary(text);
    let want = [
        0.03,
        0.027,
        7900.0 * std::f64::consts::PI * 4e-6 * 0.2,
        4430.0 * 1.2e-6,
    ];
    for (p, w) in s.parts.collect().iter().zip(want) {
        assert!(
            (p.mass - w).abs() <= 8.0 * EPS * w,
            "{}: {} vs {w}",
            p.name,
            p.mass
        );
    }
}

/// Write `files` (name, text) into a fresh directory; the paths back.
fn scratch(tag: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("massprop-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    dir
}

fn summary_of_file(path: &std::path::Path) -> Summary {
    let source = massprop::read_source(path.to_str().unwrap()).unwrap();
    let model = Model::parse(&source).unwrap_or_else(|d| panic!("{d}"));
    summarize(
        &model,
        &model.analysis,
        Products::Tensor,
        &Accuracy::fixed(Precision::Standard),
    )
    .unwrap()
}

#[test]
fn an_included_sub_assembly_is_its_parts_moved_turned_and_converted() {
    // The motor in mm and g, included twice into a file in m and kg: once
    // as it is, once at (0.4, 0, 0) turned a quarter turn about x (local z
    // to −y), nested one level deeper through `elbow.toml`. By hand, the
    // same parts written inline in m and kg, moved and turned.
    let motor = "name = \"motor\"\nunits = { length = \"mm\", mass = \"g\" }\n\
                 [[part]]\nname = \"stator\"\nshape = \"cylinder\"\nmass = 300\nradius = 20\nlength = 30\ncenter = [0, 0, 5]\n\
                 [[part]]\nname = \"shaft\"\nshape = \"rod\"\nmass = 20\nfrom = [0, 0, -10]\nto = [0, 0, 40]\n";
    let elbow = "[[part]]\ninclude = \"motor.toml\"\nname = \"elbow motor\"\norigin = [0.25, 0, 0]\n\
                 rotation = { axis = [1, 0, 0], degrees = 90 }\n";
    let arm = "[[part]]\nname = \"link\"\nshape = \"box\"\nmass = 1\nsize = [0.4, 0.05, 0.05]\ncenter = [0.2, 0, 0]\n\
               [[part]]\ninclude = \"sub/elbow.toml\"\nname = \"elbow\"\norigin = [0.15, 0, 0]\n\
               [[part]]\ninclude = \"sub/motor.toml\"\n";
    let inline = "[[part]]\nname = \"link\"\nshape = \"box\"\nmass = 1\nsize = [0.4, 0.05, 0.05]\ncenter = [0.2, 0, 0]\n\
                  [[part]]\nshape = \"cylinder\"\nmass = 0.3\nradius = 0.02\nlength = 0.03\ncenter = [0.4, -0.005, 0]\n\
                  rotation = { axis = [1, 0, 0], degrees = 90 }\n\
                  [[part]]\nshape = \"rod\"\nmass = 0.02\nfrom = [0.4, 0.01, 0]\nto = [0.4, -0.04, 0]\n\
                  [[part]]\nshape = \"cylinder\"\nmass = 0.3\nradius = 0.02\nlength = 0.03\ncenter = [0, 0, 0.005]\n\
                  [[part]]\nshape = \"rod\"\nmass = 0.02\nfrom = [0, 0, -0.01]\nto = [0, 0, 0.04]\n";
    let dir = scratch("include", &[("arm.toml", arm), ("inline.toml", inline)]);
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("sub/motor.toml"), motor).unwrap();
    std::fs::write(dir.join("sub/elbow.toml"), elbow).unwrap();
    let (a, b) = (
        summary_of_file(&dir.join("arm.toml")),
        summary_of_file(&dir.join("inline.toml")),
    );
    assert!((a.mass - b.mass).abs() <= 4.0 * EPS * b.mass);
    assert!((v3(&a.center_of_mass) - v3(&b.center_of_mass)).amax() <= 8.0 * EPS);
    assert!(rel(&m3(&a.inertia_com), &m3(&b.inertia_com)) <= 16.0 * EPS);
    // The tree: elbow > elbow motor, and motor.
    let paths: Vec<Vec<String>> = a
        .assemblies
        .collect()
        .iter()
        .map(|s| s.path.clone())
        .collect();
    assert_eq!(
        paths,
        [vec!["elbow"], vec!["elbow", "elbow motor"], vec!["motor"]]
    );
    assert_eq!(a.parts.collect()[1].assembly, ["elbow", "elbow motor"]);
    assert_eq!(a.parts.collect()[1].name, "elbow / elbow motor / stator");
    assert!((a.assemblies.collect()[0].mass - 0.32).abs() <= 4.0 * EPS);
    // --only: the sub-assembly alone.
    let source = massprop::read_source(dir.join("arm.toml").to_str().unwrap()).unwrap();
    let mut model = Model::parse(&source).unwrap();
    model.only("motor").unwrap();
    let s = summarize(
        &model,
        &model.analysis,
        Products::Tensor,
        &Accuracy::fixed(Precision::Standard),
    )
    .unwrap();
    assert!((s.mass - 0.32).abs() <= 4.0 * EPS);
    // Centre of the unmoved motor by hand: (0.3 · 5 + 0.02 · 15) mm / 0.32.
    assert!((s.center_of_mass[2] - 0.0018 / 0.32).abs() <= 8.0 * EPS);
    assert!(model.only("nothing").is_err());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn copies_of_a_sub_assembly_get_distinct_names_and_only_takes_paths() {
    // A car with a front and a rear axle, each with two unnamed wheels.
    let wheel = "name = \"wheel\"\n[[part]]\nname = \"hub\"\nshape = \"disk\"\nmass = 2\nradius = 0.3\ncenter = [0, 0, 0]\n";
    let axle = "[[part]]\ninclude = \"wheel.toml\"\norigin = [0, 0.8, 0]\n\
                [[part]]\ninclude = \"wheel.toml\"\norigin = [0, -0.8, 0]\n";
    let car = "[[part]]\nname = \"front\"\ninclude = \"axle.toml\"\norigin = [1.2, 0, 0]\n\
               [[part]]\nname = \"rear\"\ninclude = \"axle.toml\"\norigin = [-1.2, 0, 0]\n";
    let dir = scratch(
        "car",
        &[
            ("wheel.toml", wheel),
            ("axle.toml", axle),
            ("car.toml", car),
        ],
    );
    let s = summary_of_file(&dir.join("car.toml"));
    let paths: Vec<String> = s
        .assemblies
        .collect()
        .iter()
        .map(|a| a.path.join(" / "))
        .collect();
    assert_eq!(
        paths,
        [
            "front",
            "front / wheel",
            "front / wheel #2",
            "rear",
            "rear / wheel",
            "rear / wheel #2"
        ]
    );
    let source = massprop::read_source(dir.join("car.toml").to_str().unwrap()).unwrap();
    let model = Model::parse(&source).unwrap();
    let mut m = model.clone();
    let err = m.only("wheel").unwrap_err();
    assert!(err.contains("ambiguous"), "{err}");
    let mut m = model.clone();
    m.only("rear / wheel #2").unwrap();
    assert_eq!(m.count, 1);
    assert_eq!(
        m.flattened()[0].si(m.units).center,
        Vector3::new(-1.2, -0.8, 0.0)
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_included_part_must_fit_the_including_files_units() {
    // Two tiny spheres in um and mg are fine there, subnormal in km and t.
    let small = "units = { length = \"um\", mass = \"mg\" }\n\
                 [[part]]\nshape = \"sphere\"\nmass = 1e-285\nradius = 1\ncenter = [0, 0, 0]\n";
    let big = "units = { length = \"km\", mass = \"t\" }\n[[part]]\ninclude = \"small.toml\"\n";
    let dir = scratch("units-range", &[("small.toml", small), ("big.toml", big)]);
    let source = massprop::read_source(dir.join("big.toml").to_str().unwrap()).unwrap();
    let err = Model::parse(&source).unwrap_err().to_string();
    assert!(
        err.contains("big.toml:3:11") && err.contains("underflow"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_built_in_material_converts_like_its_density_written_with_units() {
    // One exact conversion either way: the same f64 mass in ft and lb.
    let part = |m: &str| {
        format!(
            "units = {{ length = \"ft\", mass = \"lb\" }}\n[[part]]\nshape = \"box\"\n{m}\nsize = [3, 7, 11]\ncenter = [0, 0, 0]\n"
        )
    };
    let a = summary(&part("material = \"steel\""));
    let b = summary(&part("density = \"7850 kg/m^3\""));
    assert_eq!(a.mass, b.mass);
}

/// One representation of a part (issue 11): in a millimetre file, a
/// triangle and a rod 10⁸ mm from the origin get the part masses the file
/// describes exactly (6 mm² × 2 kg/mm², 7 mm × 3 kg/mm; the SI path once
/// gave them 4e-11 off), and the parts' masses add up to the body's.
#[test]
fn parts_far_out_in_millimetres_have_exact_masses_that_sum_to_the_body() {
    let text = "units = { length = \"mm\", mass = \"kg\" }\n\
        [[part]]\nshape = \"triangle\"\nareal_density = 2\n\
        vertices = [[1e8, 0, 0], [100000003, 0, 0], [1e8, 4, 0]]\n\
        [[part]]\nshape = \"rod\"\nlinear_density = 3\nfrom = [1e8, 0, 0]\nto = [1e8, 0, 7]\n\
        [[part]]\nshape = \"box\"\ndensity = \"7850 kg/m^3\"\ncorner = [-1e8, 0, 0]\n\
        edges = [[0.1, 0.1, 0], [-0.3, 0.3, 0], [0, 0, 0.7]]\n";
    for precision in [Precision::Standard, Precision::Extended] {
        let s = summary_in(text, precision);
        assert_eq!(s.parts.collect()[0].mass, 12.0, "{precision:?}");
        assert_eq!(s.parts.collect()[1].mass, 21.0, "{precision:?}");
        // Each part's mass is its exact value rounded once, and the body's
        // the exact sum rounded once: the sum of the rounded parts is
        // within an ulp of each of their roundings.
        let sum: f64 = s.parts.collect().iter().map(|p| p.mass).sum();
        let ulps = s.parts.len() as f64 * f64::EPSILON * s.mass;
        assert!((sum - s.mass).abs() <= ulps, "{sum} vs {}", s.mass);
        let fractions: f64 = s.parts.collect().iter().map(|p| p.mass_fraction).sum();
        assert!((fractions - 1.0).abs() <= 4.0 * f64::EPSILON, "{fractions}");
    }
}

/// `--only NAME` says what it reports: the table's title and the JSON
/// `name` give the sub-assembly's name, and JSON `sub_assembly` its path.
#[test]
fn only_names_the_sub_assembly_in_the_table_and_the_json() {
    let dir = crate::common::scratch("physics", "only-names");
    std::fs::write(
        dir.join("wheel.toml"),
        "name = \"wheel\"\n[[part]]\nname = \"rim\"\nshape = \"cylinder\"\nmass = 2\nradius = 0.3\ninner_radius = 0.28\nlength = 0.05\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("cart.toml"),
        "name = \"cart\"\n[[part]]\nname = \"deck\"\nshape = \"box\"\nmass = 5\nsize = [1, 0.5, 0.02]\ncenter = [0, 0, 0.2]\n\
         [[part]]\nname = \"front\"\ninclude = \"wheel.toml\"\norigin = [0.4, 0, 0]\n\
         [[part]]\nname = \"rear\"\ninclude = \"wheel.toml\"\norigin = [-0.4, 0, 0]\n",
    )
    .unwrap();
    let cart = dir.join("cart.toml");
    let cart = cart.to_str().unwrap();
    let out = crate::common::massprop(&["report", cart, "--only", "rear", "--format", "json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["name"], "rear");
    assert_eq!(v["sub_assembly"], serde_json::json!(["rear"]));
    assert_eq!(v["mass"].as_f64(), Some(2.0));
    let out = crate::common::massprop(&["report", cart, "--only", "rear"]);
    let table = String::from_utf8(out.stdout).unwrap();
    let title = table.lines().next().unwrap();
    assert_eq!(title, format!("rear (sub-assembly `rear` of {cart})"));
    // Without `--only`, no `sub_assembly` key: the contract is unchanged.
    let out = crate::common::massprop(&["report", cart, "--format", "json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["name"], "cart");
    assert!(v.get("sub_assembly").is_none());
}

/// A radius of gyration is √I / √m: where I/m alone overflows (light parts
/// very far apart) or underflows (heavy parts very close), the radius is
/// still an ordinary number and is reported, to a few ulps.
#[test]
fn radii_of_gyration_whose_ratio_over_or_underflows_are_reported() {
    for (m, d) in [(1e-300, 1e155), (1e300, 1e-155)] {
        let text = format!(
            "[[part]]\nshape = \"point\"\nmass = {m:e}\ncenter = [{d:e}, 0, 0]\n\
             [[part]]\nshape = \"point\"\nmass = {m:e}\ncenter = [{:e}, 0, 0]\n",
            -d
        );
        let s = summary(&text);
        // Two points at ±d: I_yy = I_zz = 2 m d², so k = d; I_xx = 0.
        for k in &s.radii_of_gyration[1..] {
            assert!((k / d - 1.0).abs() <= 8.0 * f64::EPSILON, "{k:e} vs {d:e}");
        }
        assert_eq!(s.radii_of_gyration[0], 0.0);
    }
}

/// A long thin bought component given by its datasheet tensor, principal
/// moments 1e-12, 1 and 1 kg·m² (an antenna along x), keeps its small
/// moment in `standard` when it is given in axes the file's are a
/// permutation of: ∫ρρᵀ dm has entries (1e-12 + 1 − 1)/2, which tr(I)/2 − I
/// formed from an ulp of 1 (2e-4 relative error). Against the exact
/// values: the principal moments are the given ones, each to a few ulps.
#[test]
fn a_datasheet_tensor_keeps_its_small_principal_moment() {
    for rotation in [
        "",
        "rotation = { matrix = [[0, 1, 0], [-1, 0, 0], [0, 0, 1]] }\n",
        "rotation = { matrix = [[0, 0, 1], [1, 0, 0], [0, 1, 0]] }\n",
    ] {
        let s = summary(&format!(
            "[[part]]\nshape = \"inertia\"\nmass = 1\ncenter = [0, 0, 0]\n\
             inertia = [[1e-12, 0, 0], [0, 1, 0], [0, 0, 1]]\n{rotation}"
        ));
        let want = [1e-12, 1.0, 1.0];
        for (got, want) in s.principal_moments.iter().zip(want) {
            assert!(
                (got - want).abs() <= 4.0 * EPS * want,
                "{rotation}: {:?}",
                s.principal_moments
            );
        }
    }
}

/// Radii of gyration about the file's axes, by hand: a 12 kg box
/// 1 × 2 × 3 m centred at (1, 2, 3) m has I = (13, 10, 5) kg·m² about the
/// axes through its centre, k = √(I/m); about the origin's axes the
/// parallel-axis shift adds m (y² + z², x² + z², x² + y²) = (156, 120, 60).
#[test]
fn radii_of_gyration_about_the_axes_through_the_centre_and_the_point() {
    let text = "[[part]]\nshape = \"box\"\nmass = 12\nsize = [1, 2, 3]\ncenter = [1, 2, 3]\n\n[analysis]\nabout = [0, 0, 0]\n";
    let (v, _) = crate::common::report_json(text, &[]);
    let close = |got: &serde_json::Value, want: f64| {
        let got = got.as_f64().unwrap();
        assert!(
            (got - want).abs() <= 2.0 * f64::EPSILON * want,
            "{got} vs {want}"
        );
    };
    for (j, (i_com, i_ref)) in [(13.0, 169.0), (10.0, 130.0), (5.0, 65.0)]
        .into_iter()
        .enumerate()
    {
        close(&v["radii_of_gyration_axes"][j], f64::sqrt(i_com / 12.0));
        close(&v["radii_of_gyration_axes_ref"][j], f64::sqrt(i_ref / 12.0));
    }
    // Without a point, the reference is the centre: the same radii.
    let (v, _) = crate::common::report_json(&text.replace("about = [0, 0, 0]", ""), &[]);
    assert_eq!(v["radii_of_gyration_axes"], v["radii_of_gyration_axes_ref"]);
}
