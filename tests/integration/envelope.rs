//! `[envelope]` (issue 35 item 2): margins against polygons worked by
//! hand, `check` failing in every format on a point outside, the exact
//! path check against dense sampling with a point-in-polygon test written
//! here, and `render --envelope` rasterised by resvg.

use crate::common::{massprop, massprop_stdin, scratch_files};
use massprop::analysis::envelope::{Affine, SAMPLES, check_affine, check_samples};
use serde_json::Value;

/// A trapezoid in (x m, mass kg): the aft edge straight at 2.5 m, the
/// forward edge leaning from 2.0 m at 500 kg to 2.1 m at 1100 kg.
const TRAPEZOID: &str = "[[2.0, 500], [2.5, 500], [2.5, 1100], [2.1, 1100]]";

/// A part file of one point mass at x with `[envelope]` the trapezoid and
/// `extra` lines after it.
fn file(mass: f64, x: f64, extra: &str) -> String {
    format!(
        "name = \"plane\"\nunits = {{ length = \"m\", mass = \"kg\" }}\n[[part]]\nname = \"body\"\nshape = \"point\"\nmass = {mass}\ncenter = [{x}, 0, 0]\n\n[envelope]\naxis = \"x\"\npoints = {TRAPEZOID}\n{extra}"
    )
}

fn report_json(text: &str) -> Value {
    let out = massprop_stdin(&["report", "-", "--format", "json"], text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The forward edge's x at mass m, by hand: 2.0 + 0.1 (m − 500) / 600.
fn forward(m: f64) -> f64 {
    2.0 + 0.1 * (m - 500.0) / 600.0
}

#[test]
fn a_point_nearer_the_forward_edge_has_its_distance_as_the_margin() {
    let v = report_json(&file(800.0, 2.2, ""));
    let expected = 2.2 - forward(800.0);
    let got = v["envelope_margin"].as_f64().unwrap();
    assert!((got - expected).abs() < 1e-12, "{got} vs {expected}");
}

#[test]
fn a_point_nearer_the_aft_edge_has_its_distance_as_the_margin() {
    let v = report_json(&file(600.0, 2.45, ""));
    let got = v["envelope_margin"].as_f64().unwrap();
    assert!((got - 0.05).abs() < 1e-12, "{got}");
}

#[test]
fn a_point_aft_of_the_envelope_has_a_negative_margin() {
    let v = report_json(&file(800.0, 2.6, ""));
    let got = v["envelope_margin"].as_f64().unwrap();
    assert!((got + 0.1).abs() < 1e-12, "{got}");
}

#[test]
fn a_mass_above_the_envelope_has_a_null_margin_and_report_exits_zero() {
    let v = report_json(&file(1200.0, 2.2, ""));
    assert!(v["envelope_margin"].is_null(), "{}", v["envelope_margin"]);
}

#[test]
fn the_margin_is_in_metres_in_json_and_in_the_file_unit_in_the_table() {
    let text = file(800.0, 2.6, "")
        .replace("length = \"m\"", "length = \"mm\"")
        .replace(
            TRAPEZOID,
            "[[2000, 500], [2500, 500], [2500, 1100], [2100, 1100]]",
        );
    let text = text.replace("center = [2.6, 0, 0]", "center = [2600, 0, 0]");
    let v = report_json(&text);
    assert!((v["envelope_margin"].as_f64().unwrap() + 0.1).abs() < 1e-12);
    let out = massprop_stdin(&["report", "-"], &text);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(table.contains("margin -100 mm, outside"), "{table}");
}

#[test]
fn the_centre_of_mass_in_percent_mac_is_measured_from_the_leading_edge() {
    let v = report_json(&file(
        800.0,
        2.2,
        "mac = { leading_edge = \"1.9 m\", length = \"150 cm\" }",
    ));
    let got = v["center_of_mass_mac"].as_f64().unwrap();
    assert!((got - 100.0 * 0.3 / 1.5).abs() < 1e-9, "{got}");
}

#[test]
fn without_mac_there_is_no_percent_mac_key() {
    let v = report_json(&file(800.0, 2.2, ""));
    assert!(v.get("center_of_mass_mac").is_none());
}

#[test]
fn a_closing_corner_that_repeats_the_first_is_the_same_polygon() {
    let closed = file(800.0, 2.2, "").replace(
        TRAPEZOID,
        "[[2.0, 500], [2.5, 500], [2.5, 1100], [2.1, 1100], [2.0, 500]]",
    );
    assert_eq!(
        report_json(&closed)["envelope_margin"],
        report_json(&file(800.0, 2.2, ""))["envelope_margin"]
    );
}

fn check(test: &str, text: &str, format: &str) -> (Option<i32>, String) {
    let path = scratch_files(
        "envelope",
        &format!("{test}-{format}"),
        &[("plane.toml", text)],
    );
    let out = massprop(&["check", path.to_str().unwrap(), "--format", format]);
    (out.status.code(), String::from_utf8(out.stdout).unwrap())
}

#[test]
fn check_passes_a_point_inside() {
    assert_eq!(check("inside", &file(800.0, 2.2, ""), "table").0, Some(0));
}

#[test]
fn check_fails_a_point_outside_naming_base_the_edge_and_the_margin_in_every_format() {
    let text = file(800.0, 2.6, "");
    for format in ["table", "json", "github", "junit", "sarif"] {
        let (code, out) = check("outside", &text, format);
        assert_eq!(code, Some(1), "{format}: {out}");
        assert!(
            out.contains("base: the centre of mass x = 2.6 m at 800 kg"),
            "{format}: {out}"
        );
        assert!(
            out.contains("the edge from corner 2 (2.5 m, 500 kg) to corner 3 (2.5 m, 1100 kg)"),
            "{format}: {out}"
        );
        assert!(out.contains("margin -0.1 m"), "{format}: {out}");
    }
}

#[test]
fn check_fails_a_mass_outside_the_range_saying_so() {
    let (code, out) = check("above", &file(1200.0, 2.2, ""), "table");
    assert_eq!(code, Some(1));
    assert!(
        out.contains("outside its range of masses, 500 to 1100 kg"),
        "{out}"
    );
}

// The exact path check against dense sampling.

/// Inside or on the outline, by the winding number (written here, not the
/// program's crossing rule), on a point not on an edge.
fn winding_inside(poly: &[[f64; 2]], p: [f64; 2]) -> bool {
    let n = poly.len();
    let mut w = 0i32;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let cross = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
        if a[1] <= p[1] {
            if b[1] > p[1] && cross > 0.0 {
                w += 1;
            }
        } else if b[1] <= p[1] && cross < 0.0 {
            w -= 1;
        }
    }
    w != 0
}

/// A notched outline: a notch 0.4 kg high cut into the aft edge at
/// 800.2–800.6 kg reaches forward to 2.3 m (between the masses of two
/// samples of `burn(2.34, 200.0, 2.7)`, 800 and 800.78 kg).
const NOTCHED: [[f64; 2]; 8] = [
    [2.0, 500.0],
    [2.5, 500.0],
    [2.5, 800.19],
    [2.3, 800.37],
    [2.3, 800.41],
    [2.5, 800.59],
    [2.5, 1100.0],
    [2.1, 1100.0],
];

/// Fuel burned from a body of 700 kg at `x0` with `fuel` kg at `xf`.
fn burn(x0: f64, fuel: f64, xf: f64) -> Affine {
    let (m0, m1) = (700.0 + fuel, 700.0);
    Affine {
        m0,
        q0: 700.0 * x0 + fuel * xf,
        m1,
        q1: 700.0 * x0,
    }
}

/// Where a dense sampling with the winding test first finds the path
/// outside, if it does.
fn dense_exit(poly: &[[f64; 2]], path: &Affine) -> Option<f64> {
    let n = 200_000;
    (0..=n).map(|k| k as f64 / n as f64).find(|&t| {
        let m = path.m0 + t * (path.m1 - path.m0);
        let q = path.q0 + t * (path.q1 - path.q0);
        !winding_inside(poly, [q / m, m])
    })
}

#[test]
fn a_path_through_the_notch_is_found_leaving_where_dense_sampling_finds_it() {
    // Fuel aft of the body: the path's x sweeps aft as fuel burns.
    let path = burn(2.34, 200.0, 2.7);
    let exact = check_affine(&NOTCHED, &path).exit.expect("it leaves");
    let dense = dense_exit(&NOTCHED, &path).expect("the dense sampling sees it leave");
    assert!((exact.t - dense).abs() < 1e-5, "{} vs {dense}", exact.t);
}

#[test]
fn a_path_that_leaves_and_reenters_between_samples_is_caught_exactly_not_by_samples() {
    let path = burn(2.34, 200.0, 2.7);
    let samples: Vec<(f64, (f64, f64))> = (0..=SAMPLES)
        .map(|k| {
            let t = k as f64 / SAMPLES as f64;
            let m = path.m0 + t * (path.m1 - path.m0);
            (t, ((path.q0 + t * (path.q1 - path.q0)) / m, m))
        })
        .collect();
    // The notch is narrower than a sample step in mass here: the samples
    // pass it by; the closed form does not.
    let sampled = check_samples(&NOTCHED, &samples);
    let exact = check_affine(&NOTCHED, &path);
    assert!(exact.exit.is_some());
    assert!(sampled.exit.is_none(), "{sampled:?}");
}

#[test]
fn paths_agree_with_dense_sampling_on_whether_they_leave() {
    let mut checked = 0;
    for i in 0..40 {
        for j in 0..5 {
            // Off the outline's corners and edges: the winding test
            // counts a point on an edge either way.
            let x0 = 2.005 + 0.49 * f64::from(i) / 39.0;
            let xf = 1.63 + 0.3 * f64::from(j);
            let path = burn(x0, 300.0, xf);
            let exact = check_affine(&NOTCHED, &path).exit.map(|e| e.t);
            let dense = dense_exit(&NOTCHED, &path);
            match (exact, dense) {
                (Some(a), Some(b)) => assert!((a - b).abs() < 1e-5, "{x0} {xf}: {a} {b}"),
                (None, None) => {}
                other => panic!("{x0} {xf}: exact and dense disagree: {other:?}"),
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 200);
}

// The chart.

fn parse(svg: &str) -> resvg::usvg::Tree {
    resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("not SVG: {e}\n{svg}"))
}

fn pixel_at(svg: &str, x: f64, m: f64) -> [u8; 3] {
    let tree = parse(svg);
    let size = tree.size().to_int_size();
    let mut map = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut map.as_mut(),
    );
    let doc = roxmltree::Document::parse(svg).unwrap();
    let g = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("envelope"))
        .expect("the chart's group");
    let nums = |a: &str| -> Vec<f64> {
        g.attribute(a)
            .unwrap()
            .split(' ')
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let (s, o) = (nums("data-scale"), nums("data-origin"));
    let p = [o[0] + s[0] * x, o[1] - s[1] * m];
    let c = map.pixel(p[0].floor() as u32, p[1].floor() as u32).unwrap();
    [c.red(), c.green(), c.blue()]
}

fn chart(text: &str) -> String {
    let out = massprop_stdin(&["render", "-", "--envelope"], text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn the_chart_shows_a_point_inside_on_the_envelope_fill() {
    let svg = chart(&file(800.0, 2.3, ""));
    assert_eq!(pixel_at(&svg, 2.3, 800.0), [0xdd, 0xe8, 0xf4]);
}

#[test]
fn the_chart_shows_a_point_outside_on_white() {
    let svg = chart(&file(800.0, 2.7, ""));
    assert_eq!(pixel_at(&svg, 2.7, 800.0), [255, 255, 255]);
}

#[test]
fn the_chart_escapes_a_hostile_name() {
    let text = file(800.0, 2.3, "").replace("name = \"plane\"", "name = \"<g>&\\\"x\\u0007\"");
    let svg = chart(&text);
    parse(&svg);
    assert!(svg.contains("&lt;g&gt;&amp;&quot;x"), "{svg}");
}

#[test]
fn render_envelope_without_an_envelope_is_an_error() {
    let text = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let out = massprop_stdin(&["render", "-", "--envelope"], text);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("`--envelope` needs an `[envelope]`"));
}

// Cases and sequences.

/// A body of 700 kg at `x0` and fuel of `fuel_fraction * 200 kg` at 2.7 m
/// (burning it moves the centre of mass forward), its cases `full` and
/// `reserve`, a `light` case without the fuel, and `[envelope]` with
/// `points` and `extra` lines.
fn fuelled(x0: f64, points: &str, extra: &str) -> String {
    format!(
        "name = \"plane\"\nunits = {{ length = \"m\", mass = \"kg\" }}\n[params]\nfuel_fraction = 1\n[[part]]\nname = \"body\"\nshape = \"point\"\nmass = 700\ncenter = [{x0}, 0, 0]\n[[part]]\nname = \"fuel\"\nshape = \"point\"\nmass = \"fuel_fraction * 200 kg\"\ncenter = [2.7, 0, 0]\n[[case]]\nname = \"full\"\nparams = {{ fuel_fraction = 1 }}\n[[case]]\nname = \"reserve\"\nparams = {{ fuel_fraction = 0.05 }}\n[[case]]\nname = \"light\"\nwithout = [\"fuel\"]\n\n[envelope]\naxis = \"x\"\npoints = {points}\n{extra}"
    )
}

/// `NOTCHED` as the file writes it.
fn notched() -> String {
    let p: Vec<String> = NOTCHED
        .iter()
        .map(|c| format!("[{}, {}]", c[0], c[1]))
        .collect();
    format!("[{}]", p.join(", "))
}

#[test]
fn each_case_has_its_margin_in_json() {
    let text = fuelled(2.34, TRAPEZOID, "");
    let out = massprop_stdin(&["report", "-", "--cases", "--format", "json"], &text);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    // `light`: 700 kg at 2.34 m; the forward edge at 700 kg by hand.
    let light = &v["cases"][2];
    assert_eq!(light["case"], "light");
    let expected = (2.34 - forward(700.0)).min(2.5 - 2.34);
    let got = light["envelope_margin"].as_f64().unwrap();
    assert!((got - expected).abs() < 1e-12, "{got} vs {expected}");
}

#[test]
fn report_cases_shows_a_margin_column() {
    let text = fuelled(2.34, TRAPEZOID, "");
    let out = massprop_stdin(&["report", "-", "--cases"], &text);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(table.contains("margin (m)"), "{table}");
}

#[test]
fn a_fuel_burn_that_stays_inside_passes_check() {
    let text = fuelled(2.34, TRAPEZOID, "sequences = [[\"full\", \"reserve\"]]");
    let (code, out) = check("burn-inside", &text, "table");
    assert_eq!(code, Some(0), "{out}");
}

#[test]
fn a_fuel_burn_through_a_notch_fails_check_though_both_ends_are_inside() {
    let text = fuelled(2.34, &notched(), "sequences = [[\"full\", \"reserve\"]]");
    let (code, out) = check("burn-notch", &text, "table");
    assert_eq!(code, Some(1), "{out}");
    assert!(out.contains("sequence full → reserve"), "{out}");
    // The mass falls as the fuel burns: the path meets the notch's upper
    // edge first, from corner 5 to corner 6.
    assert!(
        out.contains("across the edge from corner 5 (2.3 m, 800.41 kg)"),
        "{out}"
    );
    // Inside the notch the path is aft of its forward edge (2.3 m) by
    // about 2.385 − 2.3 m: the least margin is negative.
    let worst: f64 = out
        .split("least margin on the path ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|w| w.parse().ok())
        .expect("a least margin");
    assert!(worst < -0.05 && worst > -0.09, "{worst}");
    assert!(out.contains("checked exactly"), "{out}");
    assert!(
        !out.contains("case `full`") && !out.contains("case `reserve`"),
        "{out}"
    );
}

#[test]
fn a_case_outside_fails_check_naming_it() {
    // `light` (700 kg at 2.55 m) is aft of the trapezoid; `full` (900 kg
    // at (700·2.55 + 200·2.7)/900 = 2.583) too.
    let text = fuelled(2.55, TRAPEZOID, "");
    let (code, out) = check("case-outside", &text, "github");
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("case `light`: the centre of mass x = 2.55 m at 700 kg"),
        "{out}"
    );
}

#[test]
fn a_path_whose_mass_is_not_affine_is_sampled_and_says_so() {
    // The fuel a box whose side grows with the parameter: its mass goes
    // as the cube, not linearly.
    // A notch 20 kg high, wider than the samples' step in mass.
    let wide = "[[2.0, 500], [2.5, 500], [2.5, 790], [2.3, 799], [2.3, 801], [2.5, 810], [2.5, 1100], [2.1, 1100]]";
    let text = fuelled(2.34, wide, "sequences = [[\"full\", \"reserve\"]]")
        .replace(
            "shape = \"point\"\nmass = \"fuel_fraction * 200 kg\"",
            "shape = \"box\"\ndensity = 1000\nsize = [\"side\", \"side\", \"side\"]",
        )
        .replace(
            "fuel_fraction = 1\n[[part]]",
            "fuel_fraction = 1\nside = \"0.2 m + fuel_fraction * 0.4 m\"\n[[part]]",
        );
    let dir = scratch_files("envelope", "cubic", &[("plane.toml", &text)]);
    let out = massprop(&["check", dir.to_str().unwrap()]);
    let text_out = String::from_utf8(out.stdout).unwrap();
    // The path through the notch is found by its samples, and the
    // message says it was sampled, not checked exactly.
    assert!(!text_out.contains("checked exactly"), "{text_out}");
    assert!(text_out.contains("sampled at 257 points"), "{text_out}");
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn the_chart_labels_each_case_and_draws_the_path() {
    let text = fuelled(2.34, TRAPEZOID, "sequences = [[\"full\", \"reserve\"]]");
    let svg = chart(&text);
    for label in ["base, full", "reserve", "light", "full → reserve"] {
        assert!(svg.contains(&format!(">{label}</text>")), "{label}: {svg}");
    }
    assert_eq!(svg.matches("class=\"path\"").count(), 1);
}

#[test]
fn the_chart_escapes_a_hostile_case_name() {
    let text = fuelled(2.34, TRAPEZOID, "")
        .replace("name = \"light\"", "name = \"<\\u0007/text>&\\u202e\"");
    let svg = chart(&text);
    parse(&svg);
    assert!(!svg.contains("</text>&"), "{svg}");
    assert!(svg.contains("&lt;"), "{svg}");
}

#[test]
fn a_case_at_the_chart_fill_is_inside_and_one_on_white_is_outside() {
    // `light` at 2.3 m (inside at 700 kg); `full` at
    // (700·2.3 + 200·2.7)/900 = 2.3889 m, inside too; then move the body
    // aft so `light` is at 2.6 m, outside.
    let svg = chart(&fuelled(2.3, TRAPEZOID, ""));
    assert_eq!(pixel_at(&svg, 2.3, 700.0), [0xdd, 0xe8, 0xf4]);
    let svg = chart(&fuelled(2.6, TRAPEZOID, ""));
    assert_eq!(pixel_at(&svg, 2.6, 700.0), [255, 255, 255]);
}
