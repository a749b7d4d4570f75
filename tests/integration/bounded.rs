//! Costs bounded by the work asked for (issue 28, item 6), checked without
//! a clock: `render` draws coincident copies once, so its SVG is as large
//! for N copies in one place as for one (but for the count's digits);
//! `report --uncertainty` of N and 4N independent copies scales as the
//! statistics say it must. Time and memory are in benches/render.sh and
//! benches/uncertainty.sh.

use super::common::{massprop_stdin, report_json};

/// `count` copies of a 1 kg box (± `tol` kg when given) stepped by `step`
/// (metres, along x).
fn copies(count: usize, step: &str, tol: Option<&str>) -> String {
    let mass = tol.map_or("1".to_string(), |t| format!("\"1 kg ± {t} kg\""));
    format!(
        "name = \"copies\"\n[[part]]\nname = \"box\"\nshape = \"box\"\nmass = {mass}\nsize = [0.1, 0.2, 0.3]\ncenter = [0, 0, 0]\narray = {{ count = {count}, step = [{step}, 0, 0] }}\n"
    )
}

/// `massprop render -` of `text`: the SVG.
fn svg(text: &str) -> String {
    let out = massprop_stdin(&["render", "-"], text);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("the SVG is UTF-8")
}

/// The counts of copies not drawn again, one per view that has any.
fn not_drawn_again(svg: &str) -> Vec<usize> {
    svg.lines()
        .filter(|l| l.contains("not drawn again"))
        .map(|l| {
            let words = &l[l.find('>').expect("a text element") + 1..];
            words
                .split(' ')
                .next()
                .and_then(|n| n.parse().ok())
                .expect("the note begins with its count")
        })
        .collect()
}

/// The outlines drawn for the parts (`class="c…"`).
fn outlines(svg: &str) -> usize {
    svg.matches("<path class=\"c").count()
}

#[test]
fn coincident_copies_are_drawn_once_in_each_view_with_their_count() {
    let svg = svg(&copies(1000, "0", None));
    assert_eq!(outlines(&svg), 4, "one outline in each of the four views");
    assert_eq!(not_drawn_again(&svg), vec![999; 4]);
}

#[test]
fn one_part_alone_draws_no_count() {
    let svg = svg(&copies(1, "0", None));
    assert_eq!(outlines(&svg), 4);
    assert!(not_drawn_again(&svg).is_empty());
}

#[test]
fn the_drawing_of_n_coincident_copies_is_the_size_of_one_but_for_the_count() {
    let one = svg(&copies(1, "0", None)).len();
    let n = svg(&copies(2000, "0", None)).len();
    let four_n = svg(&copies(8000, "0", None)).len();
    // Each of the four views adds one line of words for its count, whose
    // digits are all that differ between N and 4N (and the last digits
    // of the scale, which the figures' roundings may move: 17 a number).
    let note =
        "<text x=\"860.00\" y=\"420.00\">7999 coincident copies not drawn again</text>\n".len();
    assert!(n > one && n - one <= 4 * note + 64, "{one} → {n}");
    assert!(four_n.abs_diff(n) <= 4 * 2 + 64, "{n} → {four_n}");
}

#[test]
fn copies_closer_than_the_drawings_resolution_are_drawn_once() {
    // 1000 copies a nanometre apart span a micrometre: far below the
    // 0.01 px the numbers are written to, at a few hundred px a metre.
    let svg = svg(&copies(1000, "1e-9", None));
    // A copy may straddle the rounding of a coordinate: two outlines a
    // view at most.
    assert!(outlines(&svg) <= 8, "{}", outlines(&svg));
    let again: usize = not_drawn_again(&svg).iter().sum();
    assert!(again >= 4 * 998, "{again}");
}

#[test]
fn copies_in_different_places_are_each_drawn() {
    // Along x: the top and front views see ten boxes, the side view one
    // place (drawn once).
    let svg = svg(&copies(10, "1", None));
    assert_eq!(outlines(&svg), 10 + 10 + 10 + 1);
    assert_eq!(not_drawn_again(&svg), vec![9]);
}

#[test]
fn parts_written_apart_are_each_drawn_though_their_outlines_coincide() {
    // Two boxes written out, one in the other's place: the drawing is of
    // what the file says, both drawn (only copies of one part are drawn
    // once).
    let part = "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n";
    let svg = svg(&format!("{part}{part}"));
    assert_eq!(outlines(&svg), 8);
    assert!(not_drawn_again(&svg).is_empty());
}

/// σ of the mass and the number of sources of `copies` toleranced copies.
fn mass_sigma(count: usize, args: &[&str]) -> (f64, u64, serde_json::Value) {
    let (v, _) = report_json(&copies(count, "0.5", Some("0.1")), args);
    let u = &v["uncertainty"];
    let mass = &u["outputs"][0];
    assert_eq!(mass["quantity"], "mass");
    (
        mass["sigma"].as_f64().unwrap(),
        u["sources"].as_u64().unwrap(),
        mass.clone(),
    )
}

#[test]
fn the_linear_deviation_of_n_independent_copies_masses_is_root_n_times_one() {
    // Var(Σ mᵢ) = Σ Var(mᵢ) = N σ₁² for independent copies: σ = √N σ₁.
    for n in [250, 1000] {
        let (sigma, sources, _) = mass_sigma(n, &["--uncertainty", "linear"]);
        assert_eq!(sources, n as u64);
        let want = (n as f64).sqrt() * 0.1;
        assert!(
            (sigma - want).abs() <= 1e-12 * want,
            "{n}: {sigma} vs {want}"
        );
    }
}

#[test]
fn each_of_n_equal_copies_contributes_one_nth_first_met_first() {
    // Equal shares 1/N; among equals the first met is named first.
    let (_, _, mass) = mass_sigma(400, &["--uncertainty", "linear"]);
    let contributors = mass["contributors"].as_array().unwrap();
    let names: Vec<&str> = contributors
        .iter()
        .map(|c| c["source"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "box[0]: mass ± 0.1 kg",
            "box[1]: mass ± 0.1 kg",
            "box[2]: mass ± 0.1 kg"
        ]
    );
    for c in contributors {
        let share = c["share"].as_f64().unwrap();
        assert!((share - 1.0 / 400.0).abs() < 1e-12, "{share}");
    }
}

#[test]
fn the_monte_carlo_deviation_of_n_and_4n_copies_doubles() {
    // σ(4N) / σ(N) = √4 = 2; each estimated from 4000 samples, so to
    // about 1.1 % each (σ̂/σ has relative deviation 1/√(2·4000)).
    let args = [
        "--uncertainty",
        "montecarlo",
        "--samples",
        "4000",
        "--seed",
        "7",
    ];
    let (a, sources_a, _) = mass_sigma(60, &args);
    let (b, sources_b, _) = mass_sigma(240, &args);
    assert_eq!((sources_a, sources_b), (60, 240));
    for (sigma, n) in [(a, 60.0), (b, 240.0)] {
        let want = f64::sqrt(n) * 0.1;
        assert!((sigma / want - 1.0).abs() < 0.06, "{n}: {sigma} vs {want}");
    }
    assert!((b / a / 2.0 - 1.0).abs() < 0.08, "{a} → {b}");
}

#[test]
fn monte_carlo_names_a_copy_among_its_largest_contributors() {
    // Every copy's share estimates 1/N; the three named are copies.
    let args = [
        "--uncertainty",
        "montecarlo",
        "--samples",
        "500",
        "--seed",
        "3",
    ];
    let (_, _, mass) = mass_sigma(30, &args);
    let contributors = mass["contributors"].as_array().unwrap();
    assert_eq!(contributors.len(), 3);
    for c in contributors {
        let name = c["source"].as_str().unwrap();
        assert!(
            name.starts_with("box[") && name.ends_with("]: mass ± 0.1 kg"),
            "{name}"
        );
    }
}
