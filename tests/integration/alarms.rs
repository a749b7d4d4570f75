//! How often `auto` is right (issue 30 item 2): random assemblies like
//! tests/integration/auto.rs's — parts of `twelve_boxes`, `every_shape`,
//! `steel_assembly` and `turnable_assembly` — but as sub-assemblies, each
//! in its own units, included turned (every rotation form) and moved, and
//! copied (`array`, linear and polar, and `mirror`), from a fixed seed.
//! Each scene is reported with `--precision auto`, `extended` and, where
//! `auto` escalated, `standard`, and compared with its exact body
//! (tests/support). Counted:
//!
//! - (a) scenes where `auto` warned;
//! - (b) warnings whose value's actual error is worse than `--rtol`, judged
//!   as docs/accuracy.md ("How a value is judged against `--rtol`") says:
//!   the real alarms;
//! - (c) scenes where `auto` escalated to `extended` needlessly: every
//!   `standard` value was already within `--rtol`;
//! - (d) bounds more than 1000× max(actual error, storage floor) in the
//!   `auto` and `extended` runs.
//!
//! The targets are asserted: at least 9 of 10 warnings real, and no
//! bound beyond 1000× in `auto` and `extended`. `--nocapture` prints the
//! figures (docs/accuracy.md, "How often `auto` is right").

use crate::honesty::{FRAME_BOUNDS_THIN_WALLS, LENGTHS, MASSES, copies, rotation, thin_walled};
use crate::stress::{Rng, every_shape, steel_assembly, turnable_assembly, twelve_boxes};
use crate::support::honest::{self, Expected, Item};
use crate::support::placed;
use crate::support::reference::{self as r, ExactPart, V3};
use serde_json::Value;
use std::collections::BTreeSet;

const RTOL: f64 = 1e-12;
const TIGHT: f64 = 1000.0;

/// The scenes measured (a fixed seed each).
const SCENES: u64 = 200;

/// A scene's files and its exact body.
struct Scene {
    files: Vec<(String, String)>,
    expected: Expected,
}

/// Scene `seed`: two or three sub-assemblies, each a few parts of one of
/// auto.rs's assemblies in its own units, included (turned or not) and
/// maybe copied.
fn scene(seed: u64) -> Scene {
    let mut rng = Rng::new(0xa1a2 ^ seed.wrapping_mul(0x9e37_79b9));
    let rng = &mut rng;
    let mut seen = BTreeSet::new();
    let top_len = LENGTHS[(rng.next_u64() % 7) as usize];
    let top_mass = MASSES[(rng.next_u64() % 5) as usize];
    let l = top_len.si();
    let mut top = format!(
        "units = {{ length = \"{}\", mass = \"{}\" }}\n",
        top_len.symbol(),
        top_mass.symbol()
    );
    let mut files = Vec::new();
    let mut parts: Vec<ExactPart> = Vec::new();
    let n = 2 + rng.next_u64() % 2;
    for i in 0..n {
        let source = match rng.next_u64() % 4 {
            0 => twelve_boxes(rng),
            1 => every_shape(rng),
            2 => steel_assembly(rng),
            _ => turnable_assembly(rng),
        };
        // A few of its parts (NOTE: none with a wall thinner than a
        // thousandth of its radius while `FRAME_BOUNDS_THIN_WALLS` is
        // false: the frame's bound does not count them, honesty.rs says).
        let mut chosen: Vec<r::Part> = source
            .parts
            .into_iter()
            .filter(|p| FRAME_BOUNDS_THIN_WALLS || !thin_walled(p))
            .collect();
        let keep = 3 + (rng.next_u64() % 4) as usize;
        while chosen.len() > keep {
            chosen.remove((rng.next_u64() % chosen.len() as u64) as usize);
        }
        let sub_len = LENGTHS[(rng.next_u64() % 7) as usize];
        let sub_mass = MASSES[(rng.next_u64() % 5) as usize];
        let sub = r::Scene::si(chosen).in_units(sub_len, sub_mass);
        let name = format!("sub{i}.toml");
        files.push((name.clone(), r::to_toml(&sub)));
        let body: Vec<ExactPart> = sub
            .parts
            .iter()
            .map(|p| placed::on_grid(&r::exact_part(p, sub_len, sub_mass)))
            .collect();
        let origin: [f64; 3] = std::array::from_fn(|_| r::f(&(r::q(rng.range(-1.0, 1.0)) / &l)));
        let o: V3 = origin.map(|x| r::q(x) * &l);
        top.push_str(&format!(
            "\n[[part]]\ninclude = \"{name}\"\norigin = [{}, {}, {}]\n",
            r::number(origin[0]),
            r::number(origin[1]),
            r::number(origin[2])
        ));
        let turn = if !rng.next_u64().is_multiple_of(3) {
            let (t, m) = rotation(rng, &mut seen);
            top.push_str(&format!("rotation = {t}\n"));
            m
        } else {
            placed::identity()
        };
        let body: Vec<ExactPart> = body.iter().map(|p| placed::placed(p, &turn, &o)).collect();
        let (keys, body) = copies(rng, &l, body, &mut seen);
        top.push_str(&keys);
        parts.extend(body.iter().map(placed::on_grid));
    }
    files.push(("top.toml".to_string(), top));
    let body = r::compose_parts(parts, None);
    let point = body.com.clone();
    let zero = || [r::int(0), r::int(0), r::int(0)];
    Scene {
        files,
        expected: Expected {
            body,
            point,
            axes: placed::identity(),
            omega: zero(),
            alpha: zero(),
        },
    }
}

fn num(v: &Value) -> f64 {
    v.as_f64().expect("a number")
}

/// The largest magnitude of a JSON value's numbers.
fn largest(v: &Value) -> f64 {
    match v {
        Value::Number(x) => x.as_f64().expect("a number").abs(),
        Value::Array(a) => a.iter().map(largest).fold(0.0, f64::max),
        _ => 0.0,
    }
}

/// How docs/accuracy.md judges each quantity: a vector or tensor as a
/// whole (and what a value zero within its bound is held against), or
/// each number by itself, or an angle.
enum Judge {
    Whole(fn(&Value) -> f64),
    Each,
    Angle,
}

fn judge_of(key: &str) -> Option<Judge> {
    let length = |v: &Value| largest(&v["center_of_mass"]).max(largest(&v["radii_of_gyration"]));
    let moment =
        |v: &Value| largest(&v["principal_moments"]).max(largest(&v["principal_moments_ref"]));
    Some(match key {
        "center_of_mass" | "center_of_mass_ref" => Judge::Whole(length),
        "inertia_com" | "inertia_ref" => Judge::Whole(moment),
        "angular_momentum" | "euler_moment" => Judge::Whole(|_| 0.0),
        "mass"
        | "principal_moments"
        | "principal_moments_ref"
        | "radii_of_gyration"
        | "radii_of_gyration_axes"
        | "radii_of_gyration_axes_ref"
        | "kinetic_energy" => Judge::Each,
        "principal_axes" | "principal_axes_ref" => Judge::Angle,
        _ => return None,
    })
}

/// The judged quantities of a report whose actual error is worse than
/// `--rtol` (`quantity` as `accuracy_warnings` names them: `key` for a
/// whole, `key[i]` for each).
fn short(v: &Value, items: &[Item]) -> BTreeSet<String> {
    let extended = v["precision"] == "extended";
    let mut out = BTreeSet::new();
    let base = |k: &str| k.split('[').next().unwrap_or(k).to_string();
    let keys: BTreeSet<String> = items.iter().map(|i| base(&i.key)).collect();
    for key in keys {
        let Some(judge) = judge_of(&key) else {
            continue;
        };
        let mine: Vec<&Item> = items.iter().filter(|i| base(&i.key) == key).collect();
        match judge {
            Judge::Whole(scale) => {
                let top = largest(&v[&key]);
                let err = mine.iter().map(|i| i.error).fold(0.0, f64::max);
                let bound = mine.iter().map(|i| i.bound).fold(0.0, f64::max);
                let zero = top <= bound;
                if !(err <= RTOL * top || zero && err <= RTOL * scale(v)) {
                    out.insert(key.clone());
                }
            }
            Judge::Each => {
                let top = largest(&v[&key]);
                for i in mine {
                    let zero = i.value.abs() <= i.bound;
                    if !(i.error <= RTOL * i.value.abs()
                        || zero && extended && i.error <= RTOL * top)
                    {
                        out.insert(i.key.clone());
                    }
                }
            }
            Judge::Angle => {
                for i in mine.iter().filter(|i| !(i.error <= RTOL)) {
                    out.insert(i.key.clone());
                }
            }
        }
    }
    out
}

/// What one scene's runs count.
#[derive(Default, Debug)]
struct Figures {
    scenes: usize,
    warned: usize,
    warnings: usize,
    real: usize,
    escalated: usize,
    needless: usize,
    bounds: usize,
    loose: usize,
    /// Each bound beyond the limit: where, and its ratio.
    loose_at: Vec<String>,
    /// The loosest bound over max(error, floor), and where.
    worst: (f64, String),
    /// The quantities warned, with how many were real.
    by_key: std::collections::BTreeMap<String, (usize, usize)>,
    /// Values beyond their bounds (none expected: honesty.rs's property).
    dishonest: Vec<String>,
}

fn warnings(v: &Value) -> Vec<String> {
    v["accuracy_warnings"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|w| w["quantity"].as_str().unwrap().to_string())
                .collect()
        })
        .unwrap_or_default()
}

fn measure(seeds: std::ops::Range<u64>) -> Figures {
    let mut f = Figures::default();
    for seed in seeds {
        let s = scene(seed);
        let prepared = honest::prepare(&s.expected);
        let dir = crate::common::scratch("alarms", &format!("{seed}"));
        for (name, text) in &s.files {
            std::fs::write(dir.join(name), text).unwrap();
        }
        let path = dir.join("top.toml");
        let run = |p: &str| {
            let (v, _) = crate::common::report_json_file(&path, &["--precision", p]);
            let items = honest::measure(&v, &s.expected, &prepared);
            (v, items)
        };
        f.scenes += 1;
        let (auto, auto_items) = run("auto");
        let named = warnings(&auto);
        if !named.is_empty() {
            f.warned += 1;
        }
        let actual = short(&auto, &auto_items);
        for w in &named {
            f.warnings += 1;
            let real = actual.contains(w);
            f.real += usize::from(real);
            let e = f
                .by_key
                .entry(w.split('[').next().unwrap().to_string())
                .or_default();
            e.0 += 1;
            e.1 += usize::from(real);
        }
        if auto["precision"] == "extended" {
            f.escalated += 1;
            let (standard, items) = run("standard");
            if short(&standard, &items).is_empty() {
                f.needless += 1;
            }
        }
        let (_, extended_items) = run("extended");
        for items in [&auto_items, &extended_items] {
            f.dishonest.extend(
                honest::dishonest(items)
                    .into_iter()
                    .map(|d| format!("seed {seed}: {d}")),
            );
        }
        for (what, items) in [("auto", &auto_items), ("extended", &extended_items)] {
            for i in items.iter() {
                f.bounds += 1;
                let ratio = i.bound / i.error.max(i.floor);
                if ratio > TIGHT {
                    f.loose += 1;
                    f.loose_at.push(format!(
                        "seed {seed}, {what}: {} {:.3e}× (bound {:e}, error {:e}, floor {:e})",
                        i.key, ratio, i.bound, i.error, i.floor
                    ));
                }
                if ratio > f.worst.0 {
                    f.worst = (ratio, format!("seed {seed}, {what}: {}", i.key));
                }
            }
        }
    }
    f
}

fn print(f: &Figures) {
    eprintln!(
        "alarms over {} scenes (rtol {RTOL:e}), {} values beyond their bounds:\n  (a) auto warned in {} scenes\n  (b) {} of {} warnings real ({:.1} %)\n  (c) escalated {}, needlessly {}\n  (d) {} of {} bounds beyond {TIGHT}× max(error, floor) in auto and extended; loosest {:.3e} ({})\n  warnings by quantity (warned, real): {:?}",
        f.scenes,
        f.dishonest.len(),
        f.warned,
        f.real,
        f.warnings,
        if f.warnings == 0 {
            100.0
        } else {
            100.0 * f.real as f64 / f.warnings as f64
        },
        f.escalated,
        f.needless,
        f.loose,
        f.bounds,
        f.worst.0,
        f.worst.1,
        f.by_key
    );
}

/// The targets: at least 9 of 10 of `auto`'s warnings name a value
/// actually worse than `--rtol`, and every bound of an `auto` or `extended`
/// run is within 1000× of max(actual error, storage floor). Expected to
/// fail until sub-assemblies and copies are placed in double-double in
/// `extended` (issue 30 item 2, the compose branch): the "before" figures
/// are in docs/accuracy.md.
#[test]
fn auto_s_warnings_are_nine_in_ten_real_and_every_bound_within_1000_times_on_random_assemblies() {
    let scenes = std::env::var("ALARMS_SCENES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(SCENES);
    let f = measure(0..scenes);
    print(&f);
    assert!(
        f.dishonest.is_empty(),
        "beyond their bounds: {:?}",
        f.dishonest
    );
    assert!(
        f.real * 10 >= f.warnings * 9,
        "{} of {} warnings real: {f:?}",
        f.real,
        f.warnings
    );
    assert!(f.loose == 0, "{} bounds beyond {TIGHT}×: {f:?}", f.loose);
}

/// The generator writes what the measurement is about: includes in other
/// units, turned, and copies of both kinds.
#[test]
fn the_alarm_scenes_include_turned_sub_assemblies_and_copies() {
    let mut text = String::new();
    for seed in 0..30 {
        for (_, t) in scene(seed).files {
            text.push_str(&t);
        }
    }
    for key in [
        "include",
        "rotation",
        "step =",
        "step_degrees",
        "mirror",
        "units = { length = \"in\"",
    ] {
        assert!(text.contains(key), "no {key}");
    }
}

/// The judge follows docs/accuracy.md: a tensor off by 1e-11 of its
/// largest entry is short, one off by 1e-13 is not, whatever its small
/// entries' own relative error.
#[test]
fn a_tensor_is_judged_as_a_whole_against_its_largest_entry() {
    let v: Value = serde_json::json!({
        "precision": "standard",
        "inertia_com": [[1.0, 1e-6, 0.0], [1e-6, 2.0, 0.0], [0.0, 0.0, 3.0]],
        "principal_moments": [1.0, 2.0, 3.0],
    });
    let item = |key: &str, value: f64, error: f64| Item {
        key: key.into(),
        value,
        error,
        bound: 1e-10,
        floor: 0.0,
        honest: true,
    };
    let fine = [
        item("inertia_com[0][1]", 1e-6, 1e-13),
        item("inertia_com[2][2]", 3.0, 1e-13),
    ];
    assert!(short(&v, &fine).is_empty());
    let off = [item("inertia_com[0][1]", 1e-6, 4e-11)];
    assert!(short(&v, &off).contains("inertia_com"));
    let _ = num(&v["principal_moments"][0]);
}
