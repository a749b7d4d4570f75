//! `--precision auto` and `--rtol` (issue 13): `auto` stays in `standard`
//! on ordinary files, recomputes in `extended` exactly where a bound says
//! standard cannot meet the accuracy asked for, and then meets it — against
//! the exact reference, not against its own bounds — or says which value it
//! cannot.

use crate::stress::{Rng, every_shape, steel_assembly, turnable_assembly, twelve_boxes};
use crate::support::num_traits::Signed;
use crate::support::reference::{self as r, Amount, Part, Scene};
use serde_json::Value;

const RTOL: f64 = 1e-12;

/// `massprop report` on `text` with `args`: the JSON and standard error.
fn run(text: &str, args: &[&str]) -> (Value, String) {
    crate::common::report_json(text, args)
}

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

fn vec3(v: &Value) -> [f64; 3] {
    std::array::from_fn(|i| num(&v[i]))
}

/// |a − b| for an exact b.
fn diff(a: f64, b: &r::Q) -> f64 {
    r::f(&(r::q(a) - b).abs())
}

/// The exact values `auto` must meet: mass, principal moments, the tensor.
struct Exact {
    mass: r::Q,
    moments: [r::Q; 3],
    inertia: [[r::Q; 3]; 3],
}

impl Exact {
    fn of(scene: &Scene) -> Exact {
        let e = r::compose(scene);
        let p = e.principal();
        Exact {
            mass: e.mass,
            moments: p.moments,
            inertia: e.inertia,
        }
    }
}

/// The result meets `RTOL` against the exact values: mass and each
/// principal moment relative to themselves, the tensor relative to its
/// largest entry.
fn assert_meets(what: &str, v: &Value, exact: &Exact) {
    let mass = num(&v["mass"]);
    let e = diff(mass, &exact.mass);
    assert!(e <= RTOL * mass, "{what}: mass off by {e:e} of {mass:e}");
    let moments = vec3(&v["principal_moments"]);
    for (k, (m, x)) in moments.iter().zip(&exact.moments).enumerate() {
        let e = diff(*m, x);
        assert!(
            e <= RTOL * m,
            "{what}: moment {k} = {m:e} off by {e:e} ({:e} of it)",
            e / m
        );
    }
    let top = (0..3)
        .flat_map(|j| (0..3).map(move |k| (j, k)))
        .map(|(j, k)| num(&v["inertia_com"][j][k]).abs())
        .fold(0.0, f64::max);
    for j in 0..3 {
        for k in 0..3 {
            let e = diff(num(&v["inertia_com"][j][k]), &exact.inertia[j][k]);
            assert!(e <= RTOL * top, "{what}: I[{j}][{k}] off by {e:e}");
        }
    }
}

/// The arithmetic the report says it used, and its warnings.
fn precision(v: &Value) -> &str {
    v["precision"].as_str().expect("precision is a string")
}

fn warnings(v: &Value) -> Vec<String> {
    v["accuracy_warnings"]
        .as_array()
        .expect("accuracy_warnings is an array")
        .iter()
        .map(|w| w["quantity"].as_str().expect("a quantity").to_string())
        .collect()
}

#[test]
fn auto_stays_standard_on_every_file_in_shapes() {
    let files = crate::common::example_part_files();
    assert!(files.len() >= 7);
    for f in files {
        let (v, stderr) = crate::common::report_json_file(&f, &[]);
        assert_eq!(precision(&v), "standard", "{}", f.display());
        assert!(
            warnings(&v).is_empty(),
            "{}: {:?}",
            f.display(),
            warnings(&v)
        );
        assert!(stderr.is_empty(), "{}: {stderr}", f.display());
    }
}

/// Random assemblies of every shape, the stress tests' own: ordinary
/// bodies, which f64 with compensated sums already gets to 1e-15. The one
/// thing `standard` cannot certify to 1e-12 in some of them is the axes of
/// two moments within a few 1e-3 of each other: an axis moves by the
/// tensor's error over the gap, and f64 holds the tensor to ~1e-16 of its
/// size (a bound of ~10 units); `auto` then recomputes, and must say only
/// that.
#[test]
fn auto_stays_standard_on_random_assemblies() {
    let mut rng = Rng::new(13);
    let mut escalated = 0;
    for trial in 0..6 {
        for (what, scene) in [
            ("twelve boxes", twelve_boxes(&mut rng)),
            ("every shape", every_shape(&mut rng)),
            ("steel assembly", steel_assembly(&mut rng)),
            ("turnable assembly", turnable_assembly(&mut rng)),
        ] {
            let (v, stderr) = run(&r::to_toml(&scene), &[]);
            if precision(&v) != "standard" {
                escalated += 1;
                let (s, _) = run(&r::to_toml(&scene), &["--precision", "standard"]);
                let m = vec3(&s["principal_moments"]);
                let gap = (m[1] - m[0]).min(m[2] - m[1]) / m[2];
                for w in warnings(&s) {
                    assert!(
                        w.starts_with("principal_axes") && gap < 1e-2,
                        "{what}, trial {trial}: {w} (relative gap {gap:e})"
                    );
                }
            }
            assert!(warnings(&v).is_empty(), "{what}, trial {trial}: {stderr}");
            assert_meets(&format!("{what}, trial {trial}"), &v, &Exact::of(&scene));
        }
    }
    assert!(escalated <= 2, "{escalated} of 24 assemblies left standard");
}

/// The cases of issue 13 that `standard` gets wrong: `auto` sees it in the
/// bounds, recomputes in `extended` and meets --rtol against the exact
/// reference. `standard` alone, asked for, says so in its warnings.
fn escalates_and_meets(what: &str, scene: &Scene, escalates: bool) {
    let exact = Exact::of(scene);
    let text = r::to_toml(scene);
    let (v, stderr) = run(&text, &[]);
    assert!(warnings(&v).is_empty(), "{what}: {stderr}");
    assert!(stderr.is_empty(), "{what}: {stderr}");
    assert_meets(what, &v, &exact);
    if !escalates {
        return;
    }
    assert_eq!(precision(&v), "extended", "{what}");
    let (v, stderr) = run(&text, &["--precision", "standard"]);
    assert_eq!(precision(&v), "standard", "{what}");
    assert!(
        !warnings(&v).is_empty(),
        "{what}: standard must say it falls short"
    );
    assert!(stderr.contains("warning: "), "{what}: {stderr}");
}

#[test]
fn slender_and_flat_turned_boxes_go_to_extended_and_meet_rtol() {
    let mut rng = Rng::new(21);
    for e in 4..=8 {
        let a = 10f64.powi(-e);
        for (kind, size) in [("slender", [a, a, 1.0]), ("flat", [1.0, 1.0, a])] {
            let scene = Scene::si(vec![Part::cuboid(
                size,
                rng.grid_point(),
                Some(rng.quaternion()),
                Amount::Mass(rng.range(0.5, 2.0)),
            )]);
            // A flat box's moments are sums of its two large second
            // moments: only the slender one's smallest moment is small.
            escalates_and_meets(&format!("{kind} 1e-{e}"), &scene, kind == "slender");
        }
    }
}

#[test]
fn a_triangle_with_a_tiny_angle_goes_to_extended_and_meets_rtol() {
    // The angle at the first vertex is 4e-9 rad: its area is a difference
    // of products 2.5e8 times smaller than they are.
    let scene = Scene::si(vec![Part::triangle(
        [
            [0.25, 0.5, -0.125],
            [1.25, 0.5, -0.125],
            [1.25, 0.500000004, -0.125],
        ],
        Amount::Density(2.5),
    )]);
    escalates_and_meets("triangle with a 4e-9 angle", &scene, true);
}

#[test]
fn a_turned_datasheet_antenna_goes_to_extended_and_meets_rtol() {
    // Principal moments 1e-12, 1, 1 kg·m²: a long thin antenna, turned.
    let mut rng = Rng::new(5);
    let inertia = [[1e-12, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let scene = Scene::si(vec![Part::given(
        0.3,
        inertia,
        r::Products::Tensor,
        [0.5, -0.25, 0.125],
        Some(r::Rotation::Quaternion(rng.quaternion())),
    )]);
    escalates_and_meets("antenna", &scene, true);
}

/// A steel block with a pocket that leaves 1e-9 of its mass: a hollow
/// shell, whose mass and moments are differences of nearly equal numbers.
/// The reference has no cut-outs; the exact values are formed here, in
/// rationals, from the file's own f64 numbers: mass ρ(a³ − s³), moments
/// 2ρ(a⁵ − s⁵)/12 about the common centre.
#[test]
fn a_cut_out_that_leaves_a_billionth_goes_to_extended_and_meets_rtol() {
    let (rho, a) = (7850.0, 0.1);
    // s³ = a³(1 − 1e-9).
    let s: f64 = 0.1 * (1.0f64 - 1e-9).cbrt();
    let block = |name: &str, size: f64, remove: bool| {
        format!(
            "[[part]]\nname = \"{name}\"\nshape = \"box\"\ndensity = {rho:?}\nsize = [{size:?}, {size:?}, {size:?}]\ncenter = [0.3, -0.2, 0.1]\nremove = {remove}\n"
        )
    };
    let text = block("block", a, false) + &block("pocket", s, true);
    let (rq, aq, sq) = (r::q(rho), r::q(a), r::q(s));
    let pow = |x: &r::Q, n: i32| (0..n).fold(r::int(1), |acc, _| acc * x);
    let mass = &rq * (pow(&aq, 3) - pow(&sq, 3));
    let moment = &rq * (pow(&aq, 5) - pow(&sq, 5)) * r::int(2) / r::int(12);
    let zero = r::int(0);
    let exact = Exact {
        mass,
        moments: [moment.clone(), moment.clone(), moment.clone()],
        inertia: std::array::from_fn(|j| {
            std::array::from_fn(|k| if j == k { moment.clone() } else { zero.clone() })
        }),
    };
    let (v, stderr) = run(&text, &[]);
    assert_eq!(precision(&v), "extended", "{stderr}");
    assert!(warnings(&v).is_empty(), "{stderr}");
    assert_meets("pocketed block", &v, &exact);
    // Standard is off by far more than 1e-12 and its bounds say so
    // (honestly: the actual error is within them).
    let (v, _) = run(&text, &["--precision", "standard"]);
    let mass = num(&v["mass"]);
    let e = diff(mass, &exact.mass);
    assert!(
        e > 1e-10 * mass,
        "standard was expected to lose digits: {e:e}"
    );
    assert!(e <= num(&v["error_bounds"]["mass"]), "{e:e}");
    assert!(warnings(&v).contains(&"mass".to_string()));
}

/// Where double-double cannot certify --rtol either, `auto` says which
/// value, on standard error and in `accuracy_warnings`, and still exits 0
/// with the most accurate result it has.
#[test]
fn where_extended_cannot_meet_rtol_auto_says_which_value() {
    // The smallest moment of a turned 1e-9-slender box is 2e-18 of the
    // largest: double-double's own rounding of the tensor (~1e-32 of it)
    // certifies it to about 3e-12 only.
    let mut rng = Rng::new(8);
    let scene = Scene::si(vec![Part::cuboid(
        [1e-9, 1e-9, 1.0],
        [0.0; 3],
        Some(rng.quaternion()),
        Amount::Mass(1.0),
    )]);
    let (v, stderr) = run(&r::to_toml(&scene), &[]);
    assert_eq!(precision(&v), "extended");
    let w = warnings(&v);
    assert!(w.contains(&"principal_moments[0]".to_string()), "{w:?}");
    assert!(
        stderr.contains("`principal_moments[0]` = ")
            && stderr.contains("even in extended precision"),
        "{stderr}"
    );
    // The bound is honest all the same.
    let exact = Exact::of(&scene);
    let m0 = num(&v["principal_moments"][0]);
    assert!(diff(m0, &exact.moments[0]) <= num(&v["error_bounds"]["principal_moments"][0]));
    // A looser --rtol is met, and then nothing is said.
    let (v, stderr) = run(&r::to_toml(&scene), &["--rtol", "1e-10"]);
    assert!(warnings(&v).is_empty() && stderr.is_empty(), "{stderr}");
    // And an --rtol at f64's own rounding is met by no value of any file.
    let (v, _) = run(
        "[[part]]\nshape = \"box\"\nmass = 3\nsize = [0.1, 0.2, 0.3]\ncenter = [0.1, 0.2, 0.7]\n",
        &["--rtol", "2.3e-16"],
    );
    assert_eq!(precision(&v), "extended");
    assert!(!warnings(&v).is_empty());
}

#[test]
fn rtol_outside_its_range_is_refused() {
    for bad in ["1e-17", "0", "-1e-12", "1", "nan", "inf", "ten"] {
        let e = <massprop::cli::Cli as clap::Parser>::try_parse_from([
            "massprop", "report", "--rtol", bad, "f.toml",
        ])
        .unwrap_err();
        assert_eq!(e.exit_code(), 2, "{bad}");
        let text = e.to_string();
        assert!(text.contains("--rtol"), "{bad}: {text}");
    }
}

/// `check` and `diff` compose as `report` does, and say which arithmetic
/// each file was computed in; `check` names a value short of --rtol in its
/// JSON without failing (an expectation's own tolerance decides that).
#[test]
fn check_and_diff_say_which_arithmetic_each_file_used() {
    let out = crate::common::massprop(&["check", "--format", "json", "shapes/flywheel.toml"]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["files"][0]["precision"], "standard", "{v}");
    assert!(v["files"][0].get("accuracy_warnings").is_none(), "{v}");
    let f = "shapes/robot-arm.toml";
    let out = crate::common::massprop(&["diff", "--format", "json", f, f]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["precision"]["old"], "standard", "{v}");
    assert_eq!(v["precision"]["new"], "standard", "{v}");
    // A turned 1e-9-slender needle: extended, and its smallest moment named
    // (double-double certifies it to ~3e-12, not the default 1e-12).
    let dir = crate::common::scratch("auto", "check");
    let needle = dir.join("needle.toml");
    std::fs::write(
        &needle,
        "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1e-9, 1e-9]\ncenter = [0, 0, 0]\nrotation = { axis = [1, 2, 3], degrees = 30 }\n",
    )
    .unwrap();
    let needle = needle.to_str().unwrap();
    let out = crate::common::massprop(&["check", "--format", "json", needle]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{v}");
    assert_eq!(v["files"][0]["precision"], "extended", "{v}");
    let w = &v["files"][0]["accuracy_warnings"];
    assert_eq!(w[0]["quantity"], "principal_moments[0]", "{v}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.starts_with(&format!("warning: {needle}: ")),
        "{stderr}"
    );
}

/// Over the stress scenes (tests/support/scenes.rs: 10⁶ and 10⁹ offsets,
/// slender and flat, moments 10⁻⁸ apart, mass ratio 10¹², µm and mg) and
/// nearly equal moments 10⁻⁴ … 10⁻¹², `auto` never falls short silently:
/// each mass, principal moment and tensor meets --rtol against the exact
/// reference, or its key is among the warnings. Scenes whose input
/// determines the answer to within double-double's reach (all but the
/// turned 1e-9 needle) meet it with no warning at all.
#[test]
fn auto_meets_rtol_on_the_stress_scenes_or_says_which_value_it_cannot() {
    let mut scenes: Vec<(String, Scene)> = crate::support::scenes::stress()
        .into_iter()
        .map(|n| (n.name.to_string(), n.scene))
        .collect();
    let mut rng = Rng::new(44);
    for e in [4, 6, 8, 10, 12] {
        let size = [1.0, 1.0 + 10f64.powi(-e), 0.5];
        let q = Some(rng.quaternion());
        let scene = Scene::si(vec![Part::cuboid(
            size,
            rng.grid_point(),
            q,
            Amount::Mass(2.0),
        )]);
        scenes.push((format!("moments 1e-{e} apart"), scene));
    }
    for (name, scene) in &scenes {
        let exact = Exact::of(scene);
        let (v, stderr) = run(&r::to_toml(scene), &[]);
        let named = warnings(&v);
        let mut short = Vec::new();
        let mass = num(&v["mass"]);
        if diff(mass, &exact.mass) > RTOL * mass {
            short.push("mass".to_string());
        }
        let moments = vec3(&v["principal_moments"]);
        for (k, (m, x)) in moments.iter().zip(&exact.moments).enumerate() {
            if diff(*m, x) > RTOL * m {
                short.push(format!("principal_moments[{k}]"));
            }
        }
        let top = moments[2];
        let tensor_short = (0..3).any(|j| {
            (0..3).any(|k| diff(num(&v["inertia_com"][j][k]), &exact.inertia[j][k]) > RTOL * top)
        });
        if tensor_short {
            short.push("inertia_com".to_string());
        }
        for q in &short {
            assert!(
                named.contains(q),
                "{name}: {q} misses 1e-12 silently: {stderr}"
            );
        }
        if name != "slender 1e-9" {
            assert!(named.is_empty(), "{name}: {stderr}");
        }
    }
}
