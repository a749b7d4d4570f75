//! σ of the body moving under `--uncertainty` (issue 35 item 4): the
//! angular momentum about the point and the kinetic energy (with ω), the
//! mass centre's velocity, the linear momentum, the angular momentum about
//! the centre of mass and both kinetic energies (with `velocity`), each
//! held to an independent derivation: the root sum of squares of central
//! finite differences of `report`'s own values (formed by
//! `analysis::motion` in double-double, not by the propagation) in files
//! written with each toleranced value moved; closed forms where the
//! derivative is simple; Monte Carlo against linear within its sampling
//! error.

use super::common::report_json;
use serde_json::Value;

/// The toleranced values of `TEMPLATE`: placeholder, nominal, σ (SI).
const SOURCES: [(&str, f64, f64); 6] = [
    ("{M1}", 4.0, 0.2),
    ("{SX}", 0.4, 0.01),
    ("{CX}", 0.3, 0.02),
    ("{CY}", 0.1, 0.01),
    ("{M2}", 1.0, 0.05),
    ("{CZ}", 0.1, 0.01),
];

/// A source's unit: the masses' kg, the rest m.
fn unit(key: &str) -> &'static str {
    if key.starts_with("{M") { "kg" } else { "m" }
}

/// Metres and kilograms, so each value is its SI value.
const TEMPLATE: &str = r#"
[units]
length = "m"
mass = "kg"

[[part]]
name = "block"
shape = "box"
mass = {M1}
size = [{SX}, 0.2, 0.1]
center = [{CX}, {CY}, 0]

[[part]]
name = "weight"
shape = "point"
mass = {M2}
center = [-0.2, 0.05, {CZ}]

[analysis]
omega = [1, -2, 3]
"#;

/// The outputs of the body moving, and their number of components.
const MOVING: [(&str, usize); 7] = [
    ("angular_momentum", 3),
    ("kinetic_energy", 1),
    ("velocity_com", 3),
    ("linear_momentum", 3),
    ("angular_momentum_com", 3),
    ("kinetic_energy_translational", 1),
    ("kinetic_energy_rotational", 1),
];

/// `TEMPLATE` with `extra` appended to `[analysis]`, each value written
/// as `value(placeholder, nominal, σ)`.
fn file(extra: &str, value: impl Fn(&str, f64, f64) -> String) -> String {
    let mut text = format!("{TEMPLATE}{extra}\n");
    for (key, nominal, sigma) in SOURCES {
        text = text.replace(key, &value(key, nominal, sigma));
    }
    text
}

fn toleranced(extra: &str) -> String {
    file(extra, |key, x, s| {
        let u = unit(key);
        format!("\"{x} {u} ± {s} {u}\"")
    })
}

/// Component `k` of `key` in a report's JSON.
fn value(v: &Value, key: &str, k: usize) -> f64 {
    match &v[key] {
        Value::Array(a) => a[k].as_f64().unwrap(),
        x => x.as_f64().unwrap(),
    }
}

fn name(key: &str, n: usize, k: usize) -> String {
    if n == 1 {
        key.to_string()
    } else {
        format!("{key}.{}", ["x", "y", "z"][k])
    }
}

fn output<'v>(v: &'v Value, q: &str) -> Option<&'v Value> {
    v["uncertainty"]["outputs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|o| o["quantity"] == q)
}

fn sigma(v: &Value, q: &str) -> f64 {
    output(v, q).unwrap_or_else(|| panic!("no output {q}"))["sigma"]
        .as_f64()
        .unwrap()
}

/// σ of each moving output by finite differences: Σ_s (∂f/∂x_s σ_s)², the
/// derivative central, the step a thousandth of σ_s.
fn by_finite_differences(extra: &str, keys: &[(&str, usize)]) -> Vec<(String, f64)> {
    let mut sum: Vec<(String, f64)> = Vec::new();
    for (source, _, s) in SOURCES {
        let h = s * 1e-3;
        let at = |shift: f64| {
            let text = file(extra, |key, x, _| {
                let x = if key == source { x + shift } else { x };
                format!("{x:?}")
            });
            report_json(&text, &[]).0
        };
        let (up, down) = (at(h), at(-h));
        for &(key, n) in keys {
            for k in 0..n {
                let d = (value(&up, key, k) - value(&down, key, k)) / (2.0 * h);
                let q = name(key, n, k);
                match sum.iter_mut().find(|(name, _)| *name == q) {
                    Some((_, acc)) => *acc += (d * s) * (d * s),
                    None => sum.push((q, (d * s) * (d * s))),
                }
            }
        }
    }
    sum.into_iter().map(|(q, v)| (q, v.sqrt())).collect()
}

const MOVING_ABOUT_A_POINT: &str = "about = [0, 0, 0]\nvelocity = [0.5, 0, -1]";

#[test]
fn each_linear_sigma_of_the_body_moving_is_the_finite_difference_one() {
    let (v, _) = report_json(
        &toleranced(MOVING_ABOUT_A_POINT),
        &["--uncertainty", "linear"],
    );
    for (q, expected) in by_finite_differences(MOVING_ABOUT_A_POINT, &MOVING) {
        let got = sigma(&v, &q);
        // Central differences of a polynomial of degree ≤ 3 in each
        // variable, at a step of σ/1000: truncation ~1e-7 of the slope.
        assert!(
            (got - expected).abs() <= 1e-6 * expected.abs().max(1e-12),
            "{q}: {got} against {expected}"
        );
    }
}

#[test]
fn each_output_of_the_body_moving_is_reported_at_its_value() {
    let (v, _) = report_json(
        &toleranced(MOVING_ABOUT_A_POINT),
        &["--uncertainty", "linear"],
    );
    for (key, n) in MOVING {
        for k in 0..n {
            let o = output(&v, &name(key, n, k)).unwrap();
            assert_eq!(o["nominal"].as_f64().unwrap(), value(&v, key, k), "{key}");
        }
    }
}

#[test]
fn monte_carlo_agrees_with_linear_within_its_sampling_error() {
    let text = toleranced(MOVING_ABOUT_A_POINT);
    let n = 20_000;
    let (lin, _) = report_json(&text, &["--uncertainty", "linear"]);
    let (mc, _) = report_json(
        &text,
        &[
            "--uncertainty",
            "montecarlo",
            "--samples",
            &n.to_string(),
            "--seed",
            "7",
        ],
    );
    // A sample σ of n normal draws has a relative standard error of
    // 1/√(2n): six of them, plus 1 % for the second-order terms linear
    // leaves out (tolerances of 5 % at most: (5 %)² = 0.25 % each).
    let rel = 6.0 / (2.0 * n as f64).sqrt() + 0.01;
    for (key, k) in MOVING {
        for c in 0..k {
            let q = name(key, k, c);
            let (a, b) = (sigma(&lin, &q), sigma(&mc, &q));
            assert!((a - b).abs() <= rel * a, "{q}: linear {a}, Monte Carlo {b}");
        }
    }
}

#[test]
fn the_covariance_has_a_row_and_a_column_per_output_moving_or_not() {
    let (v, _) = report_json(
        &toleranced(MOVING_ABOUT_A_POINT),
        &["--uncertainty", "linear"],
    );
    let outputs = v["uncertainty"]["outputs"].as_array().unwrap();
    let cov = v["uncertainty"]["covariance"].as_array().unwrap();
    assert_eq!(outputs.len(), 13 + 15);
    assert_eq!(cov.len(), outputs.len());
    for (i, row) in cov.iter().enumerate() {
        let s = outputs[i]["sigma"].as_f64().unwrap();
        let var = row[i].as_f64().unwrap();
        assert!((var.sqrt() - s).abs() <= 1e-15 * s.max(1e-300), "{i}");
    }
}

#[test]
fn about_the_centre_of_mass_its_velocity_is_exact_and_g_moves_with_the_mass_alone() {
    // The point is the centre itself: r ≡ 0, so v̄ = v exactly and
    // G = m v: σ(G_x) = |v_x| σ_m with σ_m² = 0.2² + 0.05².
    let (v, _) = report_json(
        &toleranced("velocity = [0.5, 0, -1]"),
        &["--uncertainty", "linear"],
    );
    let sigma_m = (0.2f64 * 0.2 + 0.05 * 0.05).sqrt();
    for c in ["x", "y", "z"] {
        assert_eq!(sigma(&v, &format!("velocity_com.{c}")), 0.0);
    }
    let g = |c: &str| sigma(&v, &format!("linear_momentum.{c}"));
    assert!((g("x") - 0.5 * sigma_m).abs() <= 1e-15);
    assert_eq!(g("y"), 0.0);
    assert!((g("z") - sigma_m).abs() <= 1e-15);
}

#[test]
fn with_omega_alone_the_angular_momentum_and_the_energy_have_a_sigma_and_nothing_moving_else() {
    let (v, _) = report_json(&toleranced(""), &["--uncertainty", "linear"]);
    assert!(sigma(&v, "angular_momentum.z") > 0.0);
    assert!(sigma(&v, "kinetic_energy") > 0.0);
    assert!(output(&v, "velocity_com.x").is_none());
    assert!(output(&v, "kinetic_energy_translational").is_none());
    assert_eq!(v["uncertainty"]["outputs"].as_array().unwrap().len(), 17);
}

#[test]
fn with_omega_alone_the_energy_sigma_is_the_finite_difference_one() {
    let (v, _) = report_json(&toleranced(""), &["--uncertainty", "linear"]);
    for (q, expected) in by_finite_differences("", &MOVING[..2]) {
        let got = sigma(&v, &q);
        assert!(
            (got - expected).abs() <= 1e-6 * expected.abs().max(1e-12),
            "{q}: {got} against {expected}"
        );
    }
}

#[test]
fn without_omega_the_outputs_are_the_thirteen_of_a_body_at_rest() {
    let text = toleranced("").replace("omega = [1, -2, 3]", "");
    let (v, _) = report_json(&text, &["--uncertainty", "linear"]);
    assert_eq!(v["uncertainty"]["outputs"].as_array().unwrap().len(), 13);
}

#[test]
fn an_expectation_on_the_linear_momentum_gets_its_chance_to_fail() {
    let text = format!(
        "{}\n[expect]\nlinear_momentum.y = {{ min = 2.5 }}\n",
        toleranced(MOVING_ABOUT_A_POINT)
    );
    let (v, _) = report_json(&text, &["--uncertainty", "linear"]);
    let s = sigma(&v, "linear_momentum.y");
    let mu = value(&v, "linear_momentum", 1);
    let p = v["uncertainty"]["exceed"][0]["probability"]
        .as_f64()
        .unwrap();
    // Φ((2.5 − μ)/σ) by Simpson's rule over the normal density.
    let z = (2.5 - mu) / s;
    let (a, n) = (-12.0, 20_000);
    let h = (z - a) / n as f64;
    let f = |x: f64| (-x * x / 2.0).exp() / (2.0 * std::f64::consts::PI).sqrt();
    let mut sum = f(a) + f(z);
    for i in 1..n {
        sum += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    let expected = sum * h / 3.0;
    assert!((p - expected).abs() < 1e-6, "{p} against {expected}");
}

#[test]
fn the_products_convention_shown_does_not_move_a_sigma_of_the_body_moving() {
    let text = toleranced(MOVING_ABOUT_A_POINT);
    let (tensor, _) = report_json(&text, &["--uncertainty", "linear"]);
    let (positive, _) = report_json(
        &text,
        &["--uncertainty", "linear", "--products", "positive"],
    );
    for (key, n) in MOVING {
        for k in 0..n {
            let q = name(key, n, k);
            let (a, b) = (sigma(&tensor, &q), sigma(&positive, &q));
            assert!((a - b).abs() <= 1e-14 * a, "{q}: {a} against {b}");
        }
    }
}

#[test]
fn in_turned_axes_about_another_point_each_linear_sigma_is_the_finite_difference_one() {
    // r = A (c − p): the report axes' rows A and the point p both enter.
    let extra = "about = [0.1, -0.2, 0.05]\nvelocity = [0.5, 0, -1]\naxes = { x = [0, 1, 0], y = [-1, 0, 0] }";
    let (v, _) = report_json(&toleranced(extra), &["--uncertainty", "linear"]);
    for (q, expected) in by_finite_differences(extra, &MOVING) {
        let got = sigma(&v, &q);
        assert!(
            (got - expected).abs() <= 1e-6 * expected.abs().max(1e-12),
            "{q}: {got} against {expected}"
        );
    }
}

/// The outputs docs/uncertainty.md's `outputs[]` row lists, in its order
/// (`center_of_mass.x/y/z` is three).
fn documented_outputs() -> Vec<String> {
    let doc = std::fs::read_to_string("docs/uncertainty.md").unwrap();
    let row = doc
        .lines()
        .find(|l| l.starts_with("| `outputs[]` |"))
        .expect("docs/uncertainty.md has a row for `outputs[]`");
    let mut out = Vec::new();
    for token in row.split('`').skip(1).step_by(2) {
        if matches!(token, "outputs[]" | "omega" | "velocity" | "[expect]") {
            continue;
        }
        match token.split_once('.') {
            Some((stem, comps)) => out.extend(comps.split('/').map(|c| format!("{stem}.{c}"))),
            None => out.push(token.to_string()),
        }
    }
    out
}

#[test]
fn docs_list_every_output_of_a_body_moving_in_the_order_json_gives_them() {
    let (v, _) = report_json(
        &toleranced(MOVING_ABOUT_A_POINT),
        &["--uncertainty", "linear"],
    );
    let given: Vec<String> = v["uncertainty"]["outputs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| o["quantity"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(documented_outputs(), given);
}
