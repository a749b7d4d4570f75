//! Hostile input (issue 6): generated and mutated part files, run in
//! process through `report` (JSON in both precision modes, and the table)
//! and `check`. Whatever the file, massprop must not panic or hang, and
//! must either print finite results (status 0) or give a diagnostic
//! (status 2) that names the file. And wherever the reader
//! (`model::fast::parse`) reads a file, the reference parser reads it too,
//! every value at its place (`fast::reference::agrees`); wherever it
//! refuses one, the error has a place.
//!
//! - generated files: every shape, with keys and values drawn from lists
//!   rich in extremes (0, -0.0, subnormals, 1e308, f64::MAX, nan, inf,
//!   integers beyond i64), unit strings good and bad, rotations of every
//!   form with extreme angles, cut-outs, materials, `[analysis]`;
//! - mutations of the example files in shapes/: lines deleted or
//!   duplicated, numbers replaced by extremes, truncation at any byte,
//!   TOML punctuation and unicode inserted (and, for the fast path only,
//!   the same mutations of the examples without their `[expect]`);
//! - files written for the fast path: no `[expect]`, every key it reads,
//!   in every spelling and layout TOML allows.
//!
//! Deterministic (fixed ChaCha seed, no persistence), as in invariants.rs.

use clap::Parser;
use massprop::cli::Cli;
use massprop::model::fast;
use massprop::{Output, diag::Diagnostic};
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use serde_json::Value;
use std::cell::{Cell, RefCell};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

/// Generated files: each runs `report` three times and `check` once.
const GENERATED: u32 = 600;
/// Mutated example files.
const MUTATED: u32 = 400;
/// Longer than any sane run of one command in a debug build on a loaded
/// machine: a hang (the only clock these tests keep; times are
/// docs/performance.md's).
const HANG: Duration = Duration::from_secs(60);

// ---------------------------------------------------------------------------
// Running massprop in process

/// `massprop ARGS` in process, on its own thread: Err(message) if it panics
/// or takes longer than `HANG`.
pub(crate) fn run(args: &[&str]) -> Result<Result<Output, Diagnostic>, String> {
    let mut argv = vec!["massprop".to_string()];
    argv.extend(args.iter().map(|a| a.to_string()));
    let cli = Cli::try_parse_from(&argv).map_err(|e| format!("bad command line: {e}"))?;
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let result = std::panic::catch_unwind(|| massprop::run(&cli));
        let _ = tx.send(result);
    });
    match rx.recv_timeout(HANG) {
        Ok(Ok(result)) => Ok(result),
        Ok(Err(payload)) => {
            let text = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "(non-string payload)".to_string());
            Err(format!("massprop {} panicked: {text}", args.join(" ")))
        }
        Err(_) => Err(format!(
            "massprop {} did not finish within {HANG:?}",
            args.join(" ")
        )),
    }
}

/// Words that mean a non-finite number was printed. toml's own messages
/// name the keywords in backquotes (`invalid float, expected \`inf\``):
/// those are words, not results.
pub(crate) fn non_finite_word(text: &str) -> Option<String> {
    let text = &text.replace("`inf`", "").replace("`nan`", "");
    if text.contains('∞') {
        return Some("∞".to_string());
    }
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .find(|w| {
            let w = w.to_ascii_lowercase();
            w == "inf" || w == "infinity" || w == "nan"
        })
        .map(|w| w.to_string())
}

/// Keys whose value (or whose array's entries) may be `null`: docs/json.md
/// and docs/diff.md (`rel_change`: a zero scale or an overflowing ratio).
const MAY_BE_NULL: &[&str] = &[
    "name",
    "principal_moment_share",
    "envelope_margin",
    "relative_change",
    "rel_change",
];

/// Every number in `v` is finite and nothing is `null` except where
/// docs/json.md allows it; `key` is the key `v` (or its array) sits under.
pub(crate) fn walk(v: &Value, key: &str, path: &str) -> Result<(), String> {
    match v {
        Value::Null if MAY_BE_NULL.contains(&key) => Ok(()),
        Value::Null => Err(format!("null at {path}")),
        Value::Number(n) => match n.as_f64() {
            Some(x) if x.is_finite() => Ok(()),
            _ => Err(format!("non-finite number {n} at {path}")),
        },
        Value::Array(items) => items
            .iter()
            .enumerate()
            .try_for_each(|(i, item)| walk(item, key, &format!("{path}[{i}]"))),
        Value::Object(map) => map
            .iter()
            .try_for_each(|(k, item)| walk(item, k, &format!("{path}.{k}"))),
        Value::Bool(_) | Value::String(_) => Ok(()),
    }
}

/// A number, or an array (of arrays) of numbers and nothing else.
fn numeric(v: &Value) -> bool {
    match v {
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(items) => !items.is_empty() && items.iter().all(numeric),
        _ => false,
    }
}

pub(crate) fn check_json(stdout: &str) -> Result<(), String> {
    let json: Value =
        serde_json::from_str(stdout).map_err(|e| format!("output is not JSON ({e}): {stdout}"))?;
    for key in ["mass", "center_of_mass", "inertia_com", "principal_moments"] {
        if !json.get(key).is_some_and(numeric) {
            return Err(format!(
                "`{key}` is not finite numbers: {:?}",
                json.get(key)
            ));
        }
    }
    walk(&json, "", "$")
}

/// One file through `report` (JSON in both modes, table) and `check`.
/// Err describes the first broken promise; Ok(true) if some report
/// computed the body. `check` quotes the lines it rejects, so its output is
/// searched for "inf" and "nan" only when the file has none.
pub(crate) fn hostile(path: &str) -> Result<bool, String> {
    hostile_including(path, &[])
}

/// `hostile` for a file that includes the files `included` (whose text
/// messages may quote too).
pub(crate) fn hostile_including(path: &str, included: &[&[u8]]) -> Result<bool, String> {
    let input = std::fs::read(path).unwrap();
    let quiet_input = std::iter::once(&input[..])
        .chain(included.iter().copied())
        .all(|text| non_finite_word(&String::from_utf8_lossy(text)).is_none());
    let name = Path::new(path).file_name().unwrap().to_str().unwrap();
    let diagnostic = |d: &Diagnostic, what: &str| {
        let text = d.to_string();
        if text.trim().is_empty() {
            Err(format!("{what}: empty diagnostic"))
        } else if !text.contains(name) {
            Err(format!("{what}: diagnostic does not name the file: {text}"))
        } else {
            Ok(())
        }
    };
    let mut outcomes = Vec::new();
    for mode in ["standard", "extended"] {
        let args = ["report", "--format", "json", "--precision", mode, path];
        let what = format!("report --format json --precision {mode}");
        match run(&args)? {
            Ok(out) => {
                if out.status != 0 {
                    return Err(format!("{what}: Ok with status {}", out.status));
                }
                check_json(&out.stdout.text()).map_err(|e| format!("{what}: {e}"))?;
                outcomes.push(true);
            }
            Err(d) => {
                if std::env::var_os("HOSTILE_DEBUG").is_some() && mode == "standard" {
                    eprintln!("DIAG {}", d.message());
                }
                diagnostic(&d, &what)?;
                outcomes.push(false);
            }
        }
    }
    match run(&["report", "--format", "table", path])? {
        Ok(out) => {
            if out.status != 0 {
                return Err(format!("report (table): Ok with status {}", out.status));
            }
            if let Some(w) = non_finite_word(&out.stdout.text()) {
                return Err(format!(
                    "report (table) prints {w:?}:\n{}",
                    out.stdout.text()
                ));
            }
            if !outcomes[0] {
                return Err("the table reports a file the JSON rejects".to_string());
            }
        }
        Err(d) => diagnostic(&d, "report (table)")?,
    }
    // diff against an example and against itself (status 0 or 1, or a
    // diagnostic); materials lists the file's [materials].
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes/bent-plate.toml");
    let example = example.to_str().unwrap();
    for args in [
        vec!["diff", example, path, "--format", "json"],
        vec!["diff", path, path],
        vec!["materials", path, "--format", "json"],
        vec![
            "report",
            path,
            "--products",
            "positive",
            "--omega",
            "1e150,0,1",
            "--about",
            "1e100,0,0",
        ],
    ] {
        let what = args.join(" ");
        match run(&args)? {
            Ok(out) => {
                if out.status > 1 {
                    return Err(format!("{what}: Ok with status {}", out.status));
                }
                if args.contains(&"json") {
                    let json: Value = serde_json::from_str(&out.stdout.text())
                        .map_err(|e| format!("{what}: output is not JSON ({e})"))?;
                    walk(&json, "", "$").map_err(|e| format!("{what}: {e}"))?;
                } else if let Some(w) = non_finite_word(&out.stdout.text()).filter(|_| quiet_input)
                {
                    return Err(format!("{what} prints {w:?}:\n{}", out.stdout.text()));
                }
            }
            Err(d) => diagnostic(&d, &what)?,
        }
    }
    match run(&["check", path])? {
        Ok(out) => {
            if out.status > 2 {
                return Err(format!("check: status {}", out.status));
            }
            for text in [&out.stdout.text(), &out.stderr]
                .into_iter()
                .filter(|_| quiet_input)
            {
                if let Some(w) = non_finite_word(text) {
                    return Err(format!("check prints {w:?}:\n{text}"));
                }
            }
        }
        Err(d) => {
            if d.to_string().trim().is_empty() {
                return Err("check: empty diagnostic".to_string());
            }
        }
    }
    Ok(outcomes.contains(&true))
}

/// Write `text` as `dir/file` and run it through `hostile`.
fn hostile_file(dir: &Path, file: &str, text: &[u8]) -> Result<bool, String> {
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    hostile(path.to_str().unwrap())
}

/// Run `cases` inputs from `strategy` through `body`, deterministically;
/// fail with the smallest failing input proptest finds. Returns the number
/// of cases run.
///
/// For a deeper local search: `HOSTILE_CASES=N` runs N cases instead, and
/// `HOSTILE_KEEP_GOING=1` reports every failing case (unshrunk) at the end
/// instead of stopping at the first.
pub(crate) fn property<S: Strategy>(
    name: &str,
    cases: u32,
    strategy: S,
    body: impl Fn(&S::Value) -> Result<bool, String>,
) -> u32
where
    S::Value: std::fmt::Debug,
{
    let cases = std::env::var("HOSTILE_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    let keep_going = std::env::var_os("HOSTILE_KEEP_GOING").is_some();
    let mut config = Config::with_cases(cases);
    config.failure_persistence = None;
    config.rng_algorithm = RngAlgorithm::ChaCha;
    // Shrinking re-runs four commands per step: keep it bounded.
    config.max_shrink_iters = 512;
    let mut runner = TestRunner::new_with_rng(
        config.clone(),
        TestRng::deterministic_rng(RngAlgorithm::ChaCha),
    );
    let failures = RefCell::new(Vec::new());
    let computed = RefCell::new(0usize);
    let result = runner.run(&strategy, |input| match body(&input) {
        Ok(ok) => {
            *computed.borrow_mut() += usize::from(ok);
            Ok(())
        }
        Err(e) if keep_going => {
            failures.borrow_mut().push(e);
            Ok(())
        }
        Err(e) => Err(TestCaseError::fail(e)),
    });
    if let Err(e) = result {
        panic!("property {name}: {e}");
    }
    // How deep the inputs reach: a file rejected by every command tests
    // only the parser.
    println!(
        "property {name}: {cases} cases, {} computed by some report",
        computed.into_inner()
    );
    let failures = failures.into_inner();
    if !failures.is_empty() {
        panic!(
            "property {name}: {} of {cases} cases failed:\n\n{}",
            failures.len(),
            failures.join("\n\n")
        );
    }
    cases
}

// ---------------------------------------------------------------------------
// Generated part files

/// Ordinary numbers: most parts should get far enough to be computed.
const NICE: &[&str] = &[
    "1", "2", "3", "0.5", "2.5", "10", "0.001", "100", "7", "0.25",
];

/// Numbers that break naive arithmetic or parsing.
const EXTREME: &[&str] = &[
    "0",
    "-0.0",
    "1e-320",
    "5e-324",
    "1e-308",
    "2.2250738585072014e-308",
    "1e-300",
    "1e-160",
    "1e154",
    "1e300",
    "1e308",
    "1.7976931348623157e308",
    "-1.7976931348623157e308",
    "-1",
    "-1e-300",
    "nan",
    "-nan",
    "inf",
    "-inf",
    "9223372036854775807",
    "-9223372036854775808",
    "99999999999999999999",
    "1e-16",
    "1.0000000000000002",
    "0x10",
    "1_000",
];

/// Extremes that are still valid sizes and masses: they reach the
/// arithmetic instead of stopping at validation.
const FINITE_EXTREME: &[&str] = &[
    "1e-320",
    "5e-324",
    "1e-308",
    "2.2250738585072014e-308",
    "1e-300",
    "1e-160",
    "1e-100",
    "1e-16",
    "1.0000000000000002",
    "1e16",
    "1e100",
    "1e154",
    "1e160",
    "1e300",
    "1e308",
    "1.7976931348623157e308",
    "9223372036854775807",
];

/// Quantities with their own units, good and bad.
const UNITS: &[&str] = &[
    "\"3 mm\"",
    "\"1e300 km\"",
    "\"1e-300 um\"",
    "\"7.85 g/cm^3\"",
    "\"1e308 t/um^3\"",
    "\"1e-320 kg/m^3\"",
    "\"70 kg/m^2\"",
    "\"40 g/m\"",
    "\"2 lb\"",
    "\"1e308 lb\"",
    "\"5 rpm\"",
    "\"1e300 rpm\"",
    "\"90 deg/s^2\"",
    "\"1.8e-4 kg*m^2\"",
    "\"1e300 kg*km^2\"",
    "\"3 furlongs\"",
    "\"3 kg\"",
    "\"inf m\"",
    "\"nan mm\"",
    "\"\"",
    "\"mm\"",
    "\"5 m²\"",
    "\"5 m^-1\"",
    "\"5 m/s/s\"",
    "\"1 m^99999999999\"",
    "\"1e309 m\"",
    "\"2 µm\"",
    "\"1 in\"",
    "\"1 ft\"",
];

/// A scalar: mostly ordinary, often a valid extreme, sometimes invalid or
/// with units, rarely not a number at all. A file has some twenty values:
/// about half the files have no invalid one and reach the arithmetic.
pub(crate) fn value(l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        60 => prop::sample::select(NICE).prop_map(str::to_string),
        8 => prop::sample::select(FINITE_EXTREME).prop_map(str::to_string),
        2 * l => prop::sample::select(EXTREME).prop_map(str::to_string),
        2 * l => prop::sample::select(UNITS).prop_map(str::to_string),
        l => prop::sample::select(vec!["true", "[]", "{}", "\"x\"", "[1, 2, 3]"])
            .prop_map(str::to_string),
    ]
    .boxed()
}

/// A value, or a coordinate only a position may have.
fn coordinate(l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        5 => value(l),
        1 => prop::sample::select(vec!["-2", "-0.5", "0", "-0.0", "-1e300", "-1e-320"])
            .prop_map(str::to_string),
    ]
    .boxed()
}

/// `[a, b, …]` of `n` values, sometimes one too few or too many.
fn vector(n: usize, l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        60 => prop::collection::vec(coordinate(l), n..=n),
        l => prop::collection::vec(value(l), n.saturating_sub(1)..=n + 1),
    ]
    .prop_map(|v| format!("[{}]", v.join(", ")))
    .boxed()
}

/// `[[..], [..], …]`: `rows` vectors of 3.
fn matrix(rows: usize, l: u32) -> BoxedStrategy<String> {
    prop::collection::vec(vector(3, l), rows..=rows)
        .prop_map(|v| format!("[{}]", v.join(", ")))
        .boxed()
}

/// Angles in degrees, extreme ones included.
fn angle(l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        2 => prop::sample::select(vec![
            "0", "90", "-90", "180", "270", "360", "45", "30", "720", "1e-300", "1e300",
            "1e308", "1e16", "1e-320", "nan", "inf", "-0.0",
        ])
        .prop_map(str::to_string),
        1 => value(l),
    ]
    .boxed()
}

/// `rotation = {…}` in every form.
fn rotation(l: u32) -> BoxedStrategy<String> {
    let seq = prop::sample::select(vec![
        "zyx", "xyz", "zxz", "xyx", "yzy", "zyz", "xzy", "zyx", "xyz", "xxy", "abc", "zy", "",
    ]);
    let angles = prop::collection::vec(angle(l), 3..=3).prop_map(|v| v.join(", "));
    prop_oneof![
        l => vector(4, l).prop_map(|q| format!("{{ quaternion = {q} }}")),
        3 => prop::sample::select(vec![
            "[1, 0, 0, 0]",
            "[0.5, 0.5, 0.5, 0.5]",
            "[0.7071067811865476, 0, 0.7071067811865476, 0]",
            "[1e-300, 1, 0, 0]",
            "[1.0000001, 0, 0, 0]",
            "[0, 0, 0, 0]",
        ])
        .prop_map(|q| format!("{{ quaternion = {q} }}")),
        3 => (vector(3, l), angle(l)).prop_map(|(a, d)| format!("{{ axis = {a}, degrees = {d} }}")),
        3 => (
            prop::sample::select(vec![
                "[0, 0, 1]",
                "[1, 0, 0]",
                "[1, 1, 1]",
                "[1e-300, 0, 0]"
            ]),
            angle(l)
        )
            .prop_map(|(a, d)| format!("{{ axis = {a}, degrees = {d} }}")),
        l => matrix(3, l).prop_map(|m| format!("{{ matrix = {m} }}")),
        3 => prop::sample::select(vec![
            "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]",
            "[[0, -1, 0], [1, 0, 0], [0, 0, 1]]",
            "[[-1, 0, 0], [0, 1, 0], [0, 0, 1]]",
            "[[1, 0, 0], [0, 1, 0], [0, 0, 1.0000000001]]",
        ])
        .prop_map(|m| format!("{{ matrix = {m} }}")),
        3 => (seq.clone(), angles.clone())
            .prop_map(|(s, a)| format!("{{ intrinsic = \"{s}\", degrees = [{a}] }}")),
        3 => (seq, angles).prop_map(|(s, a)| format!("{{ extrinsic = \"{s}\", degrees = [{a}] }}")),
        l => Just("{ axis = [0, 0, 1], degrees = 90, quaternion = [1, 0, 0, 0] }".to_string()),
        l => Just("{}".to_string()),
    ]
    .boxed()
}

/// Every shape, which the part generator below writes by hand (a test
/// checks the list against `massprop::shapes::SHAPES`); `"spehre"` is the
/// unknown one, a misspelling that no shape will ever be named.
const SHAPES: &[&str] = &[
    "box",
    "plate",
    "rod",
    "cylinder",
    "disk",
    "sphere",
    "triangle",
    "point",
    "inertia",
    "cone",
    "torus",
    "hemisphere",
    "prism",
    "mesh",
    "capsule",
    "ellipsoid",
];

/// The generator knows every shape: a shape added to massprop without its
/// place in `part` below fails here (docs/architecture.md).
#[test]
fn the_part_generator_knows_every_shape() {
    let all: Vec<&str> = massprop::shapes::SHAPES.iter().map(|s| s.name).collect();
    assert_eq!(SHAPES, all.as_slice());
}

/// Three perpendicular edges, scaled by `s`.
fn edges3(s: &str) -> String {
    format!("[[{s}, 0, 0], [0, 0, {s}], [0, -2, 0]]")
}

/// A valid inertia tensor, or not.
const TENSORS: &[&str] = &[
    "[[2, 0, 0], [0, 2, 0], [0, 0, 1]]",
    "[[180, 0, 0], [0, 180, 0], [0, 0, 90]]",
    "[[2, 1, 0], [1, 2, 0], [0, 0, 1]]",
    "[[1e308, 0, 0], [0, 1e308, 0], [0, 0, 1e308]]",
    "[[1.7976931348623157e308, 0, 0], [0, 1.7976931348623157e308, 0], [0, 0, 1e308]]",
    "[[1e-320, 0, 0], [0, 1e-320, 0], [0, 0, 1e-320]]",
    "[[1, 0, 0], [0, 1, 0], [0, 0, 2]]",
    "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]",
    "[[1, 0, 0], [0, 1, 0], [0, 0, 3]]",
    "[[1, 2, 3], [4, 5, 6], [7, 8, 9]]",
    "[[\"1.8e-4 kg*m^2\", 0, 0], [0, \"1.8e-4 kg*m^2\", 0], [0, 0, \"1e300 kg*km^2\"]]",
];

/// Keys that belong to no shape, or to another one.
const EXTRA_KEYS: &[&str] = &[
    "mass",
    "density",
    "areal_density",
    "linear_density",
    "size",
    "radius",
    "inner_radius",
    "length",
    "center",
    "corner",
    "edges",
    "from",
    "to",
    "vertices",
    "inertia",
    "thickness",
    "diameter",
    "area",
    "material",
    "remove",
    "products",
    "include",
    "origin",
    "colour",
    "inner_diameter",
    "top_radius",
    "top_inner_radius",
    "tube_radius",
    "inner_tube_radius",
    "polygon",
];

/// One `[[part]]`: shape-appropriate keys with hostile values, plus noise.
fn part(l: u32) -> BoxedStrategy<String> {
    let sizes = (
        vector(3, l),
        vector(2, l),
        value(l),
        prop::option::weighted(0.4, (0..3u8, value(l))),
        value(l),
    );
    let placement = (
        vector(3, l),
        prop::option::weighted(0.6, rotation(l)),
        vector(3, l),
        prop_oneof![3 => value(l).prop_map(|s| edges3(&s)), l => matrix(3, l)],
        prop_oneof![
            3 => (value(l), value(l)).prop_map(|(a, b)| format!("[[{a}, 0, 0], [0, 0, {b}]]")),
            l => matrix(2, l),
        ],
        (vector(3, l), vector(3, l)),
        prop_oneof![
            3 => prop::sample::select(TENSORS).prop_map(str::to_string),
            l => matrix(3, l),
        ],
        any::<bool>(),
    );
    let amount = (
        0..9usize,
        value(l),
        value(l),
        prop::sample::select(vec![
            "steel",
            "aluminium-6061",
            "steel",
            "lead",
            "balsa",
            "foam",
            "unobtainium",
            "",
        ]),
        prop::option::of(value(l)),
        prop::option::weighted(0.2, value(l)),
    );
    let noise = (
        prop_oneof![
            100 => Just(None),
            3 * l => (prop::sample::select(EXTRA_KEYS), value(l)).prop_map(Some),
        ],
        prop::option::weighted(0.2, any::<bool>()),
        prop::option::weighted(
            0.3,
            prop_oneof![
                4 => prop::sample::select(vec!["\"positive\"", "\"tensor\""]),
                l => Just("1"),
            ],
        ),
        prop::option::weighted(
            0.7,
            prop::sample::select(vec!["a", "bracket", "hole +x", "é", "x\\ty", "", "part 1"]),
        ),
    );
    (
        prop_oneof![40 => prop::sample::select(SHAPES), l => Just("spehre")],
        sizes,
        placement,
        amount,
        noise,
    )
        .prop_map(|(shape, sizes, placement, amount, noise)| {
            let (size3, size2, radius, inner, length) = sizes;
            let (center, rot, corner, edges3, edges2, (from, to), tensor, by_edges) = placement;
            let (how, mass, density, material, thickness, extra_thick) = amount;
            let (extra, remove, products, name) = noise;
            let mut lines = vec!["[[part]]".to_string()];
            if let Some(n) = name {
                lines.push(format!("name = \"{n}\""));
            }
            lines.push(format!("shape = \"{shape}\""));
            let density_key = match shape {
                "box" | "cylinder" | "sphere" | "cone" | "torus" | "hemisphere" | "prism"
                | "mesh" | "capsule" | "ellipsoid" => "density",
                "plate" | "disk" | "triangle" => "areal_density",
                "rod" => "linear_density",
                _ => "mass",
            };
            // A material needs a thickness on flat shapes and an area or
            // diameter on a rod; points and given inertias take a mass.
            let flat = matches!(shape, "plate" | "disk" | "triangle");
            let how = if matches!(shape, "point" | "inertia") && how >= 4 {
                0
            } else {
                how
            };
            let mut thick = false;
            match how {
                0..=3 => lines.push(format!("mass = {mass}")),
                4 | 5 => lines.push(format!("{density_key} = {density}")),
                6 | 7 => {
                    lines.push(format!("material = \"{material}\""));
                    if let Some(t) = &thickness {
                        if flat {
                            lines.push(format!("thickness = {t}"));
                            thick = true;
                        } else if shape == "rod" {
                            let key = if how == 6 { "area" } else { "diameter" };
                            lines.push(format!("{key} = {t}"));
                            thick = true;
                        }
                    }
                }
                _ => {}
            }
            let by_edges = by_edges && matches!(shape, "box" | "plate" | "rod");
            match shape {
                "box" | "plate" if by_edges => {
                    lines.push(format!("corner = {corner}"));
                    let e = if shape == "box" { &edges3 } else { &edges2 };
                    lines.push(format!("edges = {e}"));
                }
                "rod" if by_edges => {
                    lines.push(format!("from = {from}"));
                    lines.push(format!("to = {to}"));
                }
                "triangle" => lines.push(format!("vertices = {tensor}")),
                "prism" => {
                    // A polygon from the first two rows of the tensor and
                    // the edges (hostile values, sometimes crossing or
                    // degenerate), placed by `origin`.
                    lines.push(format!(
                        "polygon = [{size2}, {size2}, [{radius}, {length}], [0, {radius}]]"
                    ));
                    lines.push(format!("origin = {corner}"));
                    lines.push(format!("length = {length}"));
                    if let Some(r) = rot {
                        lines.push(format!("rotation = {r}"));
                    }
                }
                // A file that is not there (or, beside the hostile files
                // of tests/integration/meshes.rs, is): its keys and
                // placement read, its file refused.
                "mesh" => {
                    lines.push("file = \"m.stl\"".to_string());
                    lines.push("mesh_unit = \"mm\"".to_string());
                    lines.push(format!("origin = {center}"));
                    if let Some(r) = rot {
                        lines.push(format!("rotation = {r}"));
                    } else {
                        // `weld` (issue 30), read before the file is.
                        lines.push(format!("weld = {length}"));
                    }
                }
                _ => {
                    lines.push(format!("center = {center}"));
                    if let Some(r) = rot.filter(|_| shape != "point") {
                        lines.push(format!("rotation = {r}"));
                    }
                }
            }
            match shape {
                "box" if !by_edges => lines.push(format!("size = {size3}")),
                "plate" if !by_edges => lines.push(format!("size = {size2}")),
                "rod" if !by_edges => lines.push(format!("length = {length}")),
                "cylinder" | "disk" | "sphere" | "capsule" => {
                    lines.push(format!("radius = {radius}"));
                    match inner {
                        Some((0, _)) => lines.push(format!("inner_radius = {radius}")),
                        Some((1, _)) => lines.push("inner_radius = 0".to_string()),
                        Some((_, r)) => lines.push(format!("inner_radius = {r}")),
                        None => {}
                    }
                    if matches!(shape, "cylinder" | "capsule") {
                        lines.push(format!("length = {length}"));
                    }
                }
                "hemisphere" => {
                    let key = if how % 2 == 0 { "diameter" } else { "radius" };
                    lines.push(format!("{key} = {radius}"));
                    if let Some((_, r)) = inner {
                        lines.push(format!("inner_radius = {r}"));
                    }
                }
                "cone" => {
                    lines.push(format!("radius = {radius}"));
                    let top = if how % 2 == 0 { "0" } else { radius.as_str() };
                    lines.push(format!("top_radius = {top}"));
                    match inner {
                        Some((0, r)) => {
                            lines.push(format!("inner_radius = {r}\ntop_inner_radius = 0"))
                        }
                        Some((1, r)) => lines.push(format!("inner_diameter = {r}")),
                        Some((_, r)) => {
                            lines.push(format!("inner_radius = {radius}\ntop_inner_radius = {r}"))
                        }
                        None => {}
                    }
                    lines.push(format!("length = {length}"));
                }
                "torus" => {
                    lines.push(format!("radius = {radius}"));
                    lines.push(format!("tube_radius = {length}"));
                    if let Some((_, r)) = inner {
                        lines.push(format!("inner_tube_radius = {r}"));
                    }
                }
                "inertia" => lines.push(format!("inertia = {tensor}")),
                "ellipsoid" => lines.push(format!("radii = {size3}")),
                _ => {}
            }
            match (shape, extra_thick) {
                ("plate", Some(t)) if !thick => lines.push(format!("thickness = {t}")),
                ("rod", Some(t)) if !thick => lines.push(format!("diameter = {t}")),
                _ => {}
            }
            if let Some(r) = remove.filter(|_| shape != "point") {
                lines.push(format!("remove = {r}"));
            }
            if let Some(p) = products.filter(|_| shape == "inertia") {
                lines.push(format!("products = {p}"));
            }
            if let Some((k, v)) = extra {
                lines.push(format!("{k} = {v}"));
            }
            lines.join("\n")
        })
        .boxed()
}

/// `[analysis]` with extreme reference points and motions.
fn analysis(l: u32) -> BoxedStrategy<String> {
    let motion = || {
        prop_oneof![
            2 => vector(3, l),
            1 => prop::sample::select(vec![
                "[0, 0, \"1e300 rpm\"]",
                "[0, 0, \"5 rpm\"]",
                "[1e308, 1e308, 1e308]",
                "[1e-320, 0, 0]",
                "[0, 0, 0]",
                "[1e154, 1e154, 1e154]",
                "[0, 0, \"90 deg/s^2\"]",
                "[\"3 mm\", 0, 0]",
            ])
            .prop_map(str::to_string),
        ]
    };
    // `velocity` (issue 35): extreme speeds, speeds with units (`m/s`, or a
    // unit of another kind), and velocities without `omega`.
    let velocity = prop_oneof![
        2 => vector(3, l),
        1 => prop::sample::select(vec![
            "[0, 0, \"3 m/s\"]",
            "[0, \"1e300 km/h\", 0]",
            "[1e308, -1e308, 1e308]",
            "[0, 0, \"5 rpm\"]",
            "[\"2 mm/s\", \"1 in/s\", 0]",
        ])
        .prop_map(str::to_string),
    ];
    (
        prop::option::of(vector(3, l)),
        prop::option::weighted(0.7, motion()),
        prop::option::of(motion()),
        prop::option::weighted(0.3, velocity),
        // `axles` (issue 35): positions far apart, equal, with units, a
        // third axle, an axis that is none.
        prop::option::weighted(
            0.3,
            prop::sample::select(vec![
                "{ axis = \"x\", front = 1.35, rear = -1.25 }",
                "{ axis = \"z\", front = \"1 mm\", rear = \"1e300 m\" }",
                "{ axis = \"y\", front = 0, rear = 0 }",
                "{ axis = \"x\", front = 1, rear = 0, middle = 0.5 }",
                "{ axis = \"w\", front = 1, rear = 0 }",
                "{ axis = \"x\", front = 1e308, rear = -1e308 }",
            ]),
        ),
    )
        .prop_map(|(about, omega, alpha, velocity, axles)| {
            let mut lines = vec!["[analysis]".to_string()];
            for (k, v) in [
                ("about", about),
                ("omega", omega),
                ("alpha", alpha),
                ("velocity", velocity),
            ] {
                if let Some(v) = v {
                    lines.push(format!("{k} = {v}"));
                }
            }
            if let Some(a) = axles {
                lines.push(format!("axles = {a}"));
            }
            lines.join("\n")
        })
        .boxed()
}

/// `[envelope]` (issue 35): polygons of random corners (too few, crossing,
/// flat, extreme or mistyped numbers), fixed ones valid and not, a `mac`
/// of any length, and sequences naming cases the file lacks.
fn envelope(l: u32) -> BoxedStrategy<String> {
    let corner = (value(l), value(l)).prop_map(|(x, m)| format!("[{x}, {m}]"));
    let points = prop_oneof![
        2 => prop::collection::vec(corner, 0..=6).prop_map(|c| format!("[{}]", c.join(", "))),
        1 => prop::sample::select(vec![
            "[[0, 0], [1, 0], [1, 1], [0, 1]]",
            "[[0, 0], [1, 1], [1, 0], [0, 1]]",
            "[[0, 0], [1, 1], [2, 2]]",
            "[[-1e308, 0], [1e308, 0], [1e308, 1e308], [-1e308, 1e308]]",
            "[[\"1 mm\", \"1 g\"], [\"1 m\", \"1 g\"], [\"1 m\", \"1 t\"]]",
            "[[0, 0], [1e-320, 0], [0, 1e-320]]",
            "[[0, 0], [1, 0], [1, 0], [0, 1]]",
        ])
        .prop_map(str::to_string),
    ];
    (
        prop::sample::select(vec!["x", "y", "z", "w"]),
        points,
        prop::option::weighted(0.3, (value(l), value(l))),
        prop::option::weighted(
            0.2,
            prop::sample::select(vec!["[[\"a\", \"b\"]]", "[[]]", "[]"]),
        ),
    )
        .prop_map(|(axis, points, mac, sequences)| {
            let mut lines = vec![
                "[envelope]".to_string(),
                format!("axis = \"{axis}\""),
                format!("points = {points}"),
            ];
            if let Some((le, len)) = mac {
                lines.push(format!("mac = {{ leading_edge = {le}, length = {len} }}"));
            }
            if let Some(s) = sequences {
                lines.push(format!("sequences = {s}"));
            }
            lines.join("\n")
        })
        .boxed()
}

/// A whole part file.
fn part_file_at(l: u32) -> BoxedStrategy<String> {
    let units = (
        prop_oneof![
            20 => prop::sample::select(vec!["m", "mm", "um", "µm", "km", "in", "ft"]),
            l => Just("furlong"),
        ],
        prop_oneof![
            20 => prop::sample::select(vec!["kg", "g", "mg", "t", "lb"]),
            l => Just("stone"),
        ],
    );
    (
        prop::option::of(prop::sample::select(vec!["", "body", "a b", "ünïcode"])),
        prop::option::weighted(0.5, units),
        prop::option::weighted(0.15, value(l)),
        prop::collection::vec(part(l), 1..=4),
        prop::option::weighted(0.5, analysis(l)),
        prop::option::weighted(0.1, (value(l), prop::sample::select(vec!["min", "max"]))),
        // `principal_axes`: a first row and `tol_degrees` of any value.
        prop::option::weighted(0.1, (value(l), value(l))),
        Just(l),
        prop::option::weighted(0.15, envelope(l)),
        // `[[case]]`s: a name (twice: refused), a part taken out by a name
        // that may be none, a parameter the file may not define, an
        // expectation.
        prop::option::weighted(
            0.25,
            (
                prop::sample::select(vec!["a", "a", "b c"]),
                prop::sample::select(vec!["part 1", "part 2", "nope", "part 1[0]", ""]),
                prop::option::weighted(0.3, value(l)),
                prop::option::weighted(0.3, value(l)),
            ),
        ),
    )
        .prop_map(
            |(name, units, material, parts, analysis, expect, axes, l, envelope, case)| {
            let mut out = vec![format!("# hostility {l}")];
            if let Some(n) = name {
                out.push(format!("name = \"{n}\""));
            }
            if let Some((len, m)) = units {
                out.push(format!("units = {{ length = \"{len}\", mass = \"{m}\" }}"));
            }
            if let Some(d) = material {
                out.push(format!("\n[materials]\nfoam = {{ density = {d} }}"));
            }
            for p in parts {
                out.push(format!("\n{p}"));
            }
            if let Some(a) = analysis {
                out.push(format!("\n{a}"));
            }
            if expect.is_some() || axes.is_some() {
                out.push("\n[expect]".to_string());
            }
            if let Some((v, bound)) = expect {
                out.push(format!("mass = {{ {bound} = {v} }}"));
            }
            if let Some((x, tol)) = axes {
                out.push(format!(
                    "principal_axes = {{ value = [[{x}, 0, 0], [0, 1, 0], [0, 0, 1]], tol_degrees = {tol} }}"
                ));
            }
            if let Some(e) = envelope {
                out.push(format!("\n{e}"));
            }
            if let Some((second, without, param, mass)) = case {
                out.push("\n[[case]]\nname = \"a\"\nwithout_groups = []".to_string());
                out.push(format!("\n[[case]]\nname = \"{second}\"\nwithout = [\"{without}\"]"));
                if let Some(v) = param {
                    out.push(format!("params = {{ size = {v} }}"));
                }
                if let Some(v) = mass {
                    out.push(format!("[case.expect]\nmass = {{ max = {v} }}"));
                }
            }
            out.join("\n") + "\n"
            },
        )
        .boxed()
}

/// A part file at hostility 0 (valid keys, extreme but valid numbers),
/// 1 or 2 (ever more invalid values, units, keys and shapes).
fn part_file() -> BoxedStrategy<String> {
    (0..3u32).prop_flat_map(part_file_at).boxed()
}

#[test]
fn generated_part_files_give_finite_results_or_diagnostics() {
    let dir = crate::common::scratch("hostile", "generated");
    let taken = Cell::new(0);
    let cases = property("generated", GENERATED, part_file(), |text| {
        fast_path_checked(&taken, text.as_bytes())
            .and_then(|()| hostile_file(&dir, "generated.toml", text.as_bytes()))
            .map_err(|e| format!("{e}\n--- input ---\n{text}"))
    });
    let taken = taken.get();
    println!("property generated: the fast path took {taken} of {cases} files");
}

// ---------------------------------------------------------------------------
// The fast path (src/model/fast.rs) reads files as serde does

/// Files written for the fast path.
const FAST: u32 = 400;

/// Where `fast::read_file` takes `text` (returns `Some`), it reads it as
/// the reference parser does (`fast::reference::agrees`: the reference
/// accepts it, and every value is read at its place), and so in chunks;
/// where it refuses the file, reading it gives an error with a place.
/// Ok(true) if the reader took it.
fn fast_path_agrees(text: &[u8]) -> Result<bool, String> {
    let Ok(text) = std::str::from_utf8(text) else {
        return Ok(false);
    };
    if fast::read_file(text).is_none() {
        return refused_with_a_place(text).map(|()| false);
    }
    fast::reference::agrees(text)?;
    // Read in small chunks (every table its own, or a split inside a
    // value): the same, or declined.
    let whole = format!("{:#?}", fast::parse(text));
    for n in [1, 7] {
        if let Some(chunked) = fast::parse_in_chunks(text, n)
            && format!("{:#?}", Some(chunked)) != whole
        {
            return Err(format!(
                "the fast path in chunks of {n} tokens reads another file:\n{text}"
            ));
        }
    }
    // Read in pieces on several threads (`fast::pieces`, forced on a small
    // file): the same, or declined (then read on one core).
    for n in [2, 3] {
        if let Some(pieces) = fast::pieces::parse_in_pieces(text, n)
            && format!("{:#?}", Some(pieces)) != whole
        {
            return Err(format!(
                "the fast path in {n} pieces reads another file:\n{text}"
            ));
        }
    }
    Ok(true)
}

/// Reading `text`, which the reader refuses, gives an error with a place
/// (and so wherever the reference parser, `toml::from_str::<toml::Table>`,
/// rejects it).
fn refused_with_a_place(text: &str) -> Result<(), String> {
    let source = massprop::diag::Source::new("h.toml", text);
    match massprop::model::Model::parse(&source) {
        Ok(_) => Err(format!("read a file the reader refuses:\n{text}")),
        Err(d) if d.place().and_then(|p| p.span).is_some() => Ok(()),
        Err(d) => Err(format!("an error without a place: {d}\n{text}")),
    }
}

/// The model of `text` (or its error, in full) read on one core and in 3
/// pieces on as many threads (`fast::pieces`, forced on a small file):
/// the same.
fn one_core_and_pieces_agree(text: &[u8]) -> Result<(), String> {
    let Ok(text) = std::str::from_utf8(text) else {
        return Ok(());
    };
    let model = |pieces| {
        fast::pieces::with_pieces(pieces, || {
            let source = massprop::diag::Source::new("h.toml", text);
            format!("{:?}", massprop::model::Model::parse(&source))
        })
    };
    let one = model(1);
    if model(3) != one {
        return Err(format!("read in 3 pieces, another model or error:\n{text}"));
    }
    Ok(())
}

/// `fast_path_agrees`, counting in `taken` the files the fast path took.
fn fast_path_checked(taken: &Cell<u32>, text: &[u8]) -> Result<(), String> {
    one_core_and_pieces_agree(text)?;
    if fast_path_agrees(text)? {
        taken.set(taken.get() + 1);
    }
    Ok(())
}

/// Numbers in TOML's spellings: signs, underscores, exponents, radixes.
const SPELLED: &[&str] = &[
    "1",
    "+1",
    "2",
    "3",
    "0.5",
    "+0.5",
    "5e-1",
    "5E-1",
    "0.5e+0",
    "1_0",
    "1_000.5",
    "2.5_5",
    "0x1",
    "0x0A",
    "0xdead_BEEF",
    "0o7",
    "0o1_0",
    "0b1",
    "0b1_0",
    "1e0",
    "1.0",
    "0.001",
    "7e-3",
    "100",
    "0.25",
    "1e1_0",
];

/// Zero and below: valid only as coordinates.
const SIGNED: &[&str] = &[
    "-1", "-0.5", "-0", "+0", "-0.0", "0", "-1e-3", "-2_5", "0.0",
];

/// Numbers at the edges of what TOML and the fast path read: i64 and u64
/// limits in every radix, beyond them, overflow and underflow, inf, nan.
const EDGES: &[&str] = &[
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551615",
    "18446744073709551616",
    "-9223372036854775808",
    "-9223372036854775809",
    "0x7fffffffffffffff",
    "0xffffffffffffffff",
    "0x1_0000_0000_0000_0000",
    "0o777777777777777777777",
    "0o1777777777777777777777",
    "0b111111111111111111111111111111111111111111111111111111111111111",
    "0b1111111111111111111111111111111111111111111111111111111111111111",
    "1e-400",
    "5e-324",
    "1.7976931348623157e308",
    "1e309",
    "inf",
    "+inf",
    "-inf",
    "nan",
    "+nan",
    "-nan",
];

/// Quantities as strings in every kind of TOML string, with escapes.
const TEXTS: &[&str] = &[
    "\"3 mm\"",
    "'3 mm'",
    "\"\"\"3 mm\"\"\"",
    "'''3 mm'''",
    "\"\\u0033 mm\"",
    "\"\\U00000033 mm\"",
    "\"\\x33 mm\"",
    "\"3\\tmm\"",
    "\"\"\"\n3 mm\"\"\"",
    "\"\"\"3 \\\n    mm\"\"\"",
    "'''\n3 mm'''",
    "\"2 µm\"",
    "\"2 \\u00b5m\"",
    "\"7.85 g/cm^3\"",
    "\"70 kg/m^2\"",
    "\"40 g/m\"",
    "\"1 in\"",
    "\"5 rpm\"",
    "\"\"",
];

/// Names: every kind of string, escapes, unicode.
const NAMES: &[&str] = &[
    "\"bracket\"",
    "'C:\\parts\\bracket'",
    "\"é\"",
    "\"\\u00e9\"",
    "\"\\U0001F980 crab\"",
    "\"tab\\there\"",
    "\"quote \\\" inside\"",
    "\"back\\\\slash\"",
    "\"\\e[1m bold\"",
    "\"\"\"two\nlines\"\"\"",
    "'''lit\nlines'''",
    "\"\"\"\\\n    joined\"\"\"",
    "\"#not a comment\"",
    "\"e\u{301} \u{2014} 漢字 🇫🇷\"",
    "\"\"",
];

/// Comments after a value or header: unicode, and text that looks like
/// TOML or like `[expect]`.
const COMMENTS: &[&str] = &[
    "# c",
    "#",
    "# é — e\u{301}",
    "#[[part]]",
    "# expect 2 kg",
    "#\ttab",
    "# = [1, 2]",
];

/// What goes on a line above a key: a blank line or a comment.
const ABOVE: &[&str] = &["", "# a comment", "\t# indented", "# é — 漢字", "# expect"];

/// Spacing where TOML allows it.
const SPACES: &[&str] = &["", " ", " ", " ", "  ", "\t", " \t "];

/// How one key/value pair is written.
#[derive(Clone, Debug)]
struct Look {
    /// 0..=7 bare, 8 quoted, 9 literal, 10 every letter a `\u` escape,
    /// 11 the first letter a `\U` escape.
    key: u8,
    indent: &'static str,
    before: &'static str,
    after: &'static str,
    /// An array's or inline table's layout: 0..=3 plain, 4 spaced, 5 a
    /// trailing comma, 6 one item a line, 7 that with comments.
    layout: u8,
    comment: Option<&'static str>,
    above: Option<&'static str>,
}

fn look() -> impl Strategy<Value = Look> {
    (
        0..12u8,
        prop_oneof![6 => Just(""), 1 => prop::sample::select(SPACES)],
        prop::sample::select(SPACES),
        prop::sample::select(SPACES),
        0..8u8,
        prop::option::weighted(0.15, prop::sample::select(COMMENTS)),
        prop::option::weighted(0.1, prop::sample::select(ABOVE)),
    )
        .prop_map(
            |(key, indent, before, after, layout, comment, above)| Look {
                key,
                indent,
                before,
                after,
                layout,
                comment,
                above,
            },
        )
}

/// Hands out the looks of a file's lines in turn.
struct Looks<'a>(std::iter::Cycle<std::slice::Iter<'a, Look>>);

impl Looks<'_> {
    fn next(&mut self) -> &Look {
        self.0.next().expect("a file has at least one look")
    }
}

/// A key as `look` spells it.
fn spell(key: &str, look: &Look) -> String {
    match look.key {
        8 => format!("\"{key}\""),
        9 => format!("'{key}'"),
        10 => {
            let escaped: String = key
                .chars()
                .map(|c| format!("\\u{:04x}", u32::from(c)))
                .collect();
            format!("\"{escaped}\"")
        }
        11 => {
            let mut chars = key.chars();
            let first = chars.next().map_or(0, u32::from);
            format!("\"\\U{first:08X}{}\"", chars.as_str())
        }
        _ => key.to_string(),
    }
}

/// `[a, b, c]` laid out as `look` says (nested arrays plainly).
fn array(items: &[String], look: &Look) -> String {
    let sp = look.after;
    match look.layout {
        4 => format!("[{sp}{}{sp}]", items.join(&format!("{sp},{sp}"))),
        5 => format!("[{},{sp}]", items.join(",")),
        6 => format!(
            "[\n{}]",
            items
                .iter()
                .map(|i| format!("  {i},\n"))
                .collect::<String>()
        ),
        7 => {
            let lines: Vec<String> = items
                .iter()
                .enumerate()
                .map(|(n, i)| {
                    format!(
                        "  {i}{} # item {n}\n",
                        if n + 1 < items.len() { "," } else { "" }
                    )
                })
                .collect();
            format!("[ # opening\n{}\n  # before the end\n]", lines.concat())
        }
        _ => format!("[{}]", items.join(", ")),
    }
}

/// `{ k = v, … }` laid out as `look` says; TOML 1.1 lets it span lines.
fn inline_table(entries: &[(&str, String)], look: &Look) -> String {
    let (sp, b, a) = (look.after, look.before, look.after);
    let pairs: Vec<String> = entries
        .iter()
        .map(|(k, v)| format!("{}{b}={a}{v}", spell(k, look)))
        .collect();
    match look.layout {
        4 => format!("{{{sp}{}{sp}}}", pairs.join(&format!("{sp},{sp}"))),
        5 => format!("{{{}}}", pairs.join(",")),
        6 | 7 => format!(
            "{{\n{}}}",
            pairs
                .iter()
                .map(|p| format!("  {p},\n"))
                .collect::<String>()
        ),
        _ if pairs.is_empty() => "{}".to_string(),
        _ => format!("{{ {} }}", pairs.join(", ")),
    }
}

/// `key = value` as `look` writes it, with what goes above it.
fn pair(key: &str, value: &str, look: &Look) -> String {
    let above = look.above.map(|a| format!("{a}\n")).unwrap_or_default();
    let comment = look.comment.map(|c| format!(" {c}")).unwrap_or_default();
    format!(
        "{above}{}{}{}={}{value}{comment}",
        look.indent,
        spell(key, look),
        look.before,
        look.after
    )
}

/// A number in one of TOML's spellings: at level 0 a positive one, at
/// level 1 sometimes zero, negative or an edge case.
fn spelled_number(l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        30 => prop::sample::select(SPELLED).prop_map(str::to_string),
        3 * l => prop::sample::select(SIGNED).prop_map(str::to_string),
        2 * l => prop::sample::select(EDGES).prop_map(str::to_string),
    ]
    .boxed()
}

/// A quantity: a number, or (at level 1) a string with a unit.
fn spelled_quantity(l: u32) -> BoxedStrategy<String> {
    prop_oneof![
        5 => spelled_number(l),
        l => prop::sample::select(TEXTS).prop_map(str::to_string),
    ]
    .boxed()
}

/// The values a part may use, drawn once per part.
#[derive(Clone, Debug)]
struct PartValues {
    shape: &'static str,
    /// 0 the shape spelled `"box"`, 1 `'box'`, 2 with a `\u` escape, 3
    /// multi-line.
    shape_spelling: u8,
    name: Option<&'static str>,
    by_mass: bool,
    by_edges: bool,
    scalars: Vec<String>,
    vectors: Vec<Vec<String>>,
    edges: Vec<Vec<String>>,
    rotation: Option<RotationValues>,
    optional: Vec<bool>,
}

/// A rotation's values: its form (0 quaternion, 1 axis and angle, 2
/// matrix, 3 Euler angles), nine numbers, three angles, an Euler sequence,
/// and whether its keys come in reverse order (and Euler angles are
/// extrinsic).
#[derive(Clone, Debug)]
struct RotationValues {
    form: u8,
    numbers: Vec<String>,
    angles: Vec<String>,
    sequence: &'static str,
    reversed: bool,
}

fn part_values(l: u32) -> impl Strategy<Value = PartValues> {
    let shapes = ["box", "plate", "rod", "cylinder", "disk", "sphere", "point"];
    let rotation = (
        0..4u8,
        prop::collection::vec(spelled_number(l), 9),
        prop::collection::vec(spelled_number(l), 3),
        prop::sample::select(vec!["zyx", "xyz", "zxz", "yzy"]),
        any::<bool>(),
    )
        .prop_map(
            |(form, numbers, angles, sequence, reversed)| RotationValues {
                form,
                numbers,
                angles,
                sequence,
                reversed,
            },
        );
    (
        (prop::sample::select(shapes.to_vec()), 0..4u8),
        prop::option::weighted(0.6, prop::sample::select(NAMES)),
        (any::<bool>(), any::<bool>()),
        prop::collection::vec(spelled_quantity(l), 6),
        prop::collection::vec(prop::collection::vec(spelled_quantity(l), 3), 5),
        prop::collection::vec(prop::collection::vec(spelled_quantity(l), 3), 3),
        prop::option::weighted(0.6, rotation),
        prop::collection::vec(any::<bool>(), 4),
    )
        .prop_map(
            |(
                (shape, shape_spelling),
                name,
                (by_mass, by_edges),
                scalars,
                vectors,
                edges,
                rotation,
                optional,
            )| {
                PartValues {
                    shape,
                    shape_spelling,
                    name,
                    by_mass,
                    by_edges,
                    scalars,
                    vectors,
                    edges,
                    rotation,
                    optional,
                }
            },
        )
}

/// `rotation = {…}` in one of its forms, keys in either order.
fn rotation_value(r: &RotationValues, look: &Look) -> String {
    let RotationValues {
        form,
        numbers,
        angles,
        sequence,
        reversed,
    } = r;
    let plain = Look {
        layout: 0,
        ..look.clone()
    };
    let mut entries: Vec<(&str, String)> = match form {
        0 => vec![("quaternion", array(&numbers[..4], look))],
        1 => vec![
            ("axis", array(&numbers[..3], look)),
            ("degrees", angles[0].clone()),
        ],
        2 => {
            let rows: Vec<String> = numbers.chunks(3).map(|row| array(row, &plain)).collect();
            vec![("matrix", array(&rows, look))]
        }
        _ => {
            let which = if *reversed { "extrinsic" } else { "intrinsic" };
            vec![
                (which, format!("\"{sequence}\"")),
                ("degrees", array(angles, &plain)),
            ]
        }
    };
    if *reversed {
        entries.reverse();
    }
    inline_table(&entries, look)
}

/// One `[[part]]` of any shape, with the keys the fast path reads.
fn fast_part(v: &PartValues, looks: &mut Looks) -> String {
    let header = [
        "[[part]]",
        "[[ part ]]",
        "[[\"part\"]]",
        "[[ 'part' ]]",
        "\t[[part]]",
    ];
    let l = looks.next();
    let mut lines = vec![
        header[usize::from(l.key) % header.len()].to_string()
            + &l.comment.map(|c| format!(" {c}")).unwrap_or_default(),
    ];
    let mut push = |key: &str, value: String, looks: &mut Looks| {
        let l = looks.next();
        lines.push(pair(key, &value, l));
    };
    let s = v.shape;
    let shape = match v.shape_spelling {
        0 => format!("\"{s}\""),
        1 => format!("'{s}'"),
        2 => format!("\"\\u{:04X}{}\"", u32::from(s.as_bytes()[0]), &s[1..]),
        _ => format!("\"\"\"{s}\"\"\""),
    };
    if let Some(n) = v.name {
        push("name", n.to_string(), looks);
    }
    push("shape", shape, looks);
    let amount = match (s, v.by_mass) {
        ("point", _) | (_, true) => "mass",
        ("box" | "cylinder" | "sphere", false) => "density",
        ("plate" | "disk", false) => "areal_density",
        _ => "linear_density",
    };
    push(amount, v.scalars[0].clone(), looks);
    let vector = |i: usize, n: usize, looks: &mut Looks| array(&v.vectors[i][..n], looks.next());
    let edges = |n: usize, looks: &mut Looks| {
        let plain = Look {
            layout: 0,
            ..looks.next().clone()
        };
        let rows: Vec<String> = v.edges[..n].iter().map(|e| array(e, &plain)).collect();
        array(&rows, looks.next())
    };
    let by_edges = v.by_edges && matches!(s, "box" | "plate" | "rod");
    let mut centred = !by_edges;
    match s {
        "box" | "plate" if by_edges => {
            let c = vector(0, 3, looks);
            push("corner", c, looks);
            let e = edges(if s == "box" { 3 } else { 2 }, looks);
            push("edges", e, looks);
        }
        "box" => {
            let size = vector(1, 3, looks);
            push("size", size, looks);
        }
        "plate" => {
            let size = vector(1, 2, looks);
            push("size", size, looks);
        }
        "rod" if by_edges => {
            let (from, to) = (vector(2, 3, looks), vector(3, 3, looks));
            push("from", from, looks);
            push("to", to, looks);
        }
        "rod" => push("length", v.scalars[1].clone(), looks),
        "cylinder" | "disk" | "sphere" => {
            push("radius", v.scalars[2].clone(), looks);
            if v.optional[0] {
                push("inner_radius", v.scalars[3].clone(), looks);
            }
            if s == "cylinder" {
                push("length", v.scalars[1].clone(), looks);
            }
        }
        _ => centred = true,
    }
    if centred {
        let c = vector(4, 3, looks);
        push("center", c, looks);
        if let Some(r) = v.rotation.as_ref().filter(|_| s != "point") {
            let value = rotation_value(r, looks.next());
            push("rotation", value, looks);
        }
    }
    match s {
        "plate" if v.optional[1] => push("thickness", v.scalars[4].clone(), looks),
        "rod" if v.optional[1] => push("diameter", v.scalars[5].clone(), looks),
        _ => {}
    }
    lines.join("\n")
}

/// A part file the fast path should read: no `[expect]`, every key it
/// reads, in every spelling and layout TOML allows (spacing, comments,
/// CRLF, quoted and escaped keys, escapes in strings, integer radixes),
/// `[units]` inline or as a table, tables in any order. Level 0: positive
/// numbers only, so that some files reach the arithmetic; level 1: zero,
/// negative and edge numbers, quantities with units.
fn fast_path_file() -> BoxedStrategy<String> {
    (0..2u32).prop_flat_map(fast_path_file_at).boxed()
}

fn fast_path_file_at(l: u32) -> BoxedStrategy<String> {
    let units = (
        prop::sample::select(vec!["\"mm\"", "'m'", "\"in\"", "\"\\u00b5m\"", "\"ft\""]),
        prop::sample::select(vec!["\"kg\"", "'g'", "\"lb\"", "\"\\u006Bg\""]),
        0..4u8,
    );
    let analysis = (
        prop::collection::vec(prop::collection::vec(spelled_quantity(l), 3), 3),
        prop::collection::vec(any::<bool>(), 3),
    );
    (
        (
            prop::option::weighted(0.6, prop::sample::select(NAMES)),
            prop::option::weighted(0.6, units),
            prop::option::weighted(0.4, analysis),
            prop::option::weighted(0.3, (spelled_quantity(l), any::<bool>())),
        ),
        prop::collection::vec(part_values(l), 1..=4),
        prop::collection::vec(look(), 24),
        (
            0..3u8,
            prop::bool::weighted(0.05),
            any::<prop::sample::Index>(),
        ),
    )
        .prop_map(
            |((name, units, analysis, case), parts, looks, (newline, bom, order))| {
                let mut looks = Looks(looks.iter().cycle());
                let mut top = Vec::new();
                let mut tables = Vec::new();
                if bom {
                    top.push("\u{feff}# with a byte-order mark".to_string());
                }
                if let Some(n) = name {
                    top.push(pair("name", n, looks.next()));
                }
                if let Some((length, mass, how)) = units {
                    let entries = match how {
                        0 => vec![("length", length.to_string())],
                        1 => vec![("mass", mass.to_string())],
                        _ => vec![("length", length.to_string()), ("mass", mass.to_string())],
                    };
                    if how == 3 {
                        let header = ["[units]", "[ units ]", "[\"units\"]"];
                        let mut t = vec![header[usize::from(looks.next().key) % 3].to_string()];
                        for (k, v) in &entries {
                            t.push(pair(k, v, looks.next()));
                        }
                        tables.push(t.join("\n"));
                    } else {
                        let value = inline_table(&entries, looks.next());
                        top.push(pair("units", &value, looks.next()));
                    }
                }
                if let Some((vectors, present)) = analysis {
                    let header = ["[analysis]", "[ analysis ]", "['analysis'] # motion"];
                    let mut t = vec![header[usize::from(looks.next().key) % 3].to_string()];
                    for ((k, v), on) in ["about", "omega", "alpha"]
                        .iter()
                        .zip(&vectors)
                        .zip(&present)
                    {
                        if *on {
                            let value = array(v, looks.next());
                            t.push(pair(k, &value, looks.next()));
                        }
                    }
                    tables.push(t.join("\n"));
                }
                // A `[[case]]` (its `expect` a table of its own, or inline).
                if let Some((q, sub)) = case {
                    let header = ["[[case]]", "[[ case ]]", "[[\"case\"]] # a case"];
                    let mut t = vec![header[usize::from(looks.next().key) % 3].to_string()];
                    t.push(pair("name", "\"full\"", looks.next()));
                    let names = ["\"pilot\"".to_string(), "'cargo / box[2]'".to_string()];
                    let without = array(&names, looks.next());
                    t.push(pair("without", &without, looks.next()));
                    let params = inline_table(&[("fuel", q.clone())], looks.next());
                    t.push(pair("params", &params, looks.next()));
                    let mass = inline_table(&[("value", q), ("tol", "1".into())], looks.next());
                    if sub {
                        t.push("[case.expect]".to_string());
                        t.push(pair("mass", &mass, looks.next()));
                    } else {
                        let expect = inline_table(&[("mass", mass)], looks.next());
                        t.push(pair("expect", &expect, looks.next()));
                    }
                    tables.push(t.join("\n"));
                }
                // `[units]` and `[analysis]` anywhere among the parts.
                let mut all: Vec<String> = parts.iter().map(|p| fast_part(p, &mut looks)).collect();
                for t in tables {
                    all.insert(order.index(all.len() + 1), t);
                }
                let text = top.into_iter().chain(all).collect::<Vec<_>>().join("\n\n") + "\n";
                match newline {
                    0 => text,
                    1 => text.replace('\n', "\r\n"),
                    // Every other line ends in CRLF.
                    _ => text
                        .split_inclusive('\n')
                        .enumerate()
                        .map(|(i, l)| match l.strip_suffix('\n') {
                            Some(l) if i % 2 == 0 => format!("{l}\r\n"),
                            _ => l.to_string(),
                        })
                        .collect(),
                }
            },
        )
        .boxed()
}

#[test]
fn the_fast_path_reads_part_files_as_serde_reads_them() {
    let dir = crate::common::scratch("hostile", "fast");
    let taken = Cell::new(0);
    let cases = property("fast path", FAST, fast_path_file(), |text| {
        fast_path_checked(&taken, text.as_bytes())
            .and_then(|()| hostile_file(&dir, "fast.toml", text.as_bytes()))
            .map_err(|e| format!("{e}\n--- input ---\n{text}"))
    });
    let taken = taken.get();
    println!("property fast path: the fast path took {taken} of {cases} files");
    // The files are written for the fast path: most must take it, or the
    // comparison tests nothing.
    assert!(
        taken * 100 >= cases * 60,
        "the fast path took only {taken} of {cases} files written for it"
    );
}

// ---------------------------------------------------------------------------
// Mutated example files

const EXAMPLES: &[&str] = &[
    "bent-plate.toml",
    "cubesat-6u.toml",
    "flywheel.toml",
    "motor-bracket.toml",
    "quadcopter.toml",
    "robot-arm.toml",
    "welded-bracket.toml",
];

/// What `Insert` puts in: TOML punctuation, line structure, unicode.
const SNIPPETS: &[&str] = &[
    "[",
    "]",
    "=",
    "\"",
    "{",
    "}",
    ",",
    "\n",
    "#",
    "'",
    "\"\"\"",
    "[[part]]\n",
    "[analysis]\n",
    "\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
    "é",
    "²",
    "µ",
    "\u{0}",
    "\t",
    "\r",
    "\u{feff}",
    "\u{202e}",
    "🦀",
    "-",
    "e",
    "e999",
    ".",
    "0",
    "\\",
    "remove = true\n",
    "inf",
    "nan",
];

#[derive(Clone, Debug)]
enum Mutation {
    DeleteLine(Index),
    DuplicateLine(Index),
    ReplaceNumber(Index, String),
    Truncate(Index),
    Insert(Index, &'static str),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<Index>().prop_map(Mutation::DeleteLine),
        1 => any::<Index>().prop_map(Mutation::DuplicateLine),
        4 => (any::<Index>(), prop::sample::select(EXTREME)).prop_map(|(i, v)| Mutation::ReplaceNumber(i, v.to_string())),
        1 => (any::<Index>(), prop::sample::select(UNITS)).prop_map(|(i, v)| Mutation::ReplaceNumber(i, v.to_string())),
        1 => any::<Index>().prop_map(Mutation::Truncate),
        2 => (any::<Index>(), prop::sample::select(SNIPPETS)).prop_map(|(i, s)| Mutation::Insert(i, s)),
    ]
}

/// Byte ranges of the numbers in `text` (outside comments): maximal runs
/// of digits, `.`, `e`, `+`, `-`, `_` that start with a digit, `-` or `.`
/// and contain a digit, not part of a word.
fn numbers(text: &str) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    for (start, line) in line_starts(text) {
        let code = line.split('#').next().unwrap();
        let b = code.as_bytes();
        let mut i = 0;
        while i < b.len() {
            let prev_word = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
            if !prev_word && (b[i].is_ascii_digit() || b[i] == b'-' || b[i] == b'.') {
                let mut j = i + 1;
                while j < b.len() && (b[j].is_ascii_digit() || b"._eE+-".contains(&b[j])) {
                    j += 1;
                }
                let word_after = j < b.len() && b[j].is_ascii_alphabetic();
                if !word_after && b[i..j].iter().any(u8::is_ascii_digit) {
                    out.push(start + i..start + j);
                }
                i = j;
            } else {
                i += 1;
            }
        }
    }
    out
}

/// Each line (with its newline) and the byte offset it starts at.
fn line_starts(text: &str) -> Vec<(usize, &str)> {
    let mut at = 0;
    text.split_inclusive('\n')
        .map(|l| {
            let s = at;
            at += l.len();
            (s, l)
        })
        .collect()
}

fn apply(text: &[u8], m: &Mutation) -> Vec<u8> {
    let Ok(s) = std::str::from_utf8(text) else {
        // An earlier truncation split a character: only cut further.
        return match m {
            Mutation::Truncate(i) => text[..i.index(text.len() + 1)].to_vec(),
            _ => text.to_vec(),
        };
    };
    let lines = line_starts(s);
    let mut out = text.to_vec();
    match m {
        Mutation::DeleteLine(i) | Mutation::DuplicateLine(i) if !lines.is_empty() => {
            let (start, line) = lines[i.index(lines.len())];
            let range = start..start + line.len();
            let mut line = line.to_string();
            if !line.ends_with('\n') {
                line.push('\n');
            }
            let with = if matches!(m, Mutation::DeleteLine(_)) {
                String::new()
            } else {
                line.repeat(2)
            };
            out.splice(range, with.into_bytes());
        }
        Mutation::ReplaceNumber(i, v) => {
            let nums = numbers(s);
            if !nums.is_empty() {
                out.splice(nums[i.index(nums.len())].clone(), v.bytes());
            }
        }
        Mutation::Truncate(i) => out.truncate(i.index(out.len() + 1)),
        Mutation::Insert(i, snippet) => {
            let mut at = i.index(s.len() + 1);
            while !s.is_char_boundary(at) {
                at -= 1;
            }
            out.splice(at..at, snippet.bytes());
        }
        _ => {}
    }
    out
}

#[test]
fn mutated_example_files_give_finite_results_or_diagnostics() {
    let shapes = Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes");
    let dir = crate::common::scratch("hostile", "mutated");
    // robot-arm.toml includes motor-bracket.toml by a relative path: the
    // mutants sit next to an intact copy.
    std::fs::copy(
        shapes.join("motor-bracket.toml"),
        dir.join("motor-bracket.toml"),
    )
    .unwrap();
    let originals: Vec<Vec<u8>> = EXAMPLES
        .iter()
        .map(|f| std::fs::read(shapes.join(f)).unwrap())
        .collect();
    std::fs::copy(shapes.join("robot-arm.toml"), dir.join("arm.toml")).unwrap();
    let bracket = dir.join("motor-bracket.toml");
    let bracket_index = EXAMPLES
        .iter()
        .position(|f| *f == "motor-bracket.toml")
        .unwrap();
    // The fast path leaves files with `[expect]` (every example) to serde:
    // the same mutations of the examples without it are hostile text for
    // the fast path.
    let bare: Vec<Vec<u8>> = originals.iter().map(|t| without_expect(t)).collect();
    let (taken, bare_taken) = (Cell::new(0), Cell::new(0));
    let strategy = (0..EXAMPLES.len(), prop::collection::vec(mutation(), 1..=3));
    let cases = property("mutated", MUTATED, strategy, |(which, mutations)| {
        let text = mutations
            .iter()
            .fold(originals[*which].clone(), |t, m| apply(&t, m));
        let context = |e: String| {
            format!(
                "{e}\n--- {} with {mutations:?} ---\n{}",
                EXAMPLES[*which],
                String::from_utf8_lossy(&text)
            )
        };
        fast_path_checked(&taken, &text).map_err(context)?;
        let bare_text = mutations
            .iter()
            .fold(bare[*which].clone(), |t, m| apply(&t, m));
        fast_path_checked(&bare_taken, &bare_text).map_err(|e| {
            format!(
                "{e}\n--- {} without [expect], with {mutations:?} ---\n{}",
                EXAMPLES[*which],
                String::from_utf8_lossy(&bare_text)
            )
        })?;
        let computed = hostile_file(&dir, "mutant.toml", &text).map_err(context)?;
        if EXAMPLES[*which] != "motor-bracket.toml" {
            return Ok(computed);
        }
        // The mutant as a sub-assembly: the intact robot arm includes it
        // (twice), and errors inside it must still name the including file.
        std::fs::write(&bracket, &text).unwrap();
        let arm = hostile_including(dir.join("arm.toml").to_str().unwrap(), &[&text])
            .map_err(|e| context(format!("included by robot-arm.toml: {e}")));
        std::fs::write(&bracket, &originals[bracket_index]).unwrap();
        Ok(computed | arm?)
    });
    let (taken, bare_taken) = (taken.get(), bare_taken.get());
    println!(
        "property mutated: the fast path took {taken} of {cases} mutants, \
         {bare_taken} of them without [expect]"
    );
    // Without `[expect]`, the examples' parts are the fast path's (most of
    // them): the comparison must have been made often.
    assert!(
        bare_taken * 100 >= cases * 25,
        "the fast path took only {bare_taken} of {cases} mutants without [expect]"
    );
}

/// `text` up to its `[expect]` table.
fn without_expect(text: &[u8]) -> Vec<u8> {
    let s = std::str::from_utf8(text).expect("the examples are UTF-8");
    let end = line_starts(s)
        .into_iter()
        .find(|(_, l)| l.trim_start().starts_with("[expect"))
        .map_or(s.len(), |(at, _)| at);
    text[..end].to_vec()
}

/// The example files themselves pass: the harness accepts good files.
#[test]
fn example_files_pass_the_hostile_checks() {
    let shapes = Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes");
    for f in EXAMPLES {
        let path = shapes.join(f);
        hostile(path.to_str().unwrap()).unwrap_or_else(|e| panic!("{f}: {e}"));
        let text = std::fs::read(&path).unwrap();
        fast_path_agrees(&text).unwrap_or_else(|e| panic!("{f}: {e}"));
        fast_path_agrees(&without_expect(&text))
            .unwrap_or_else(|e| panic!("{f} without [expect]: {e}"));
        let out = run(&["report", "--format", "json", path.to_str().unwrap()])
            .unwrap()
            .unwrap_or_else(|d| panic!("{f}: {d}"));
        assert_eq!(out.status, 0, "{f}");
    }
}

/// Every input the fuzzer (fuzz/, docs/fuzzing.md) has crashed massprop
/// with stays a test: each file in tests/fuzz-regressions/. An input of several
/// files (lines `#---- NAME`) is split as the fuzz target splits it.
#[test]
fn fuzz_regressions_give_finite_results_or_diagnostics() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz-regressions");
    // `robot-*`: robot descriptions, replayed by robots_hostile.rs.
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            !p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("robot-")
        })
        .collect();
    files.sort();
    assert!(files.len() >= 4, "tests/fuzz-regressions/ lost its files");
    let scratch = crate::common::scratch("hostile", "regressions");
    for path in files {
        let bytes = std::fs::read(&path).unwrap();
        let framed = std::str::from_utf8(&bytes)
            .ok()
            .filter(|t| t.starts_with(SEPARATOR) || t.contains(&format!("\n{SEPARATOR}")));
        let (top, texts) = match framed {
            Some(text) => {
                let files = unframe(text);
                let run = scratch.join(path.file_name().unwrap());
                for (name, t) in &files {
                    let p = run.join(name);
                    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
                    let _ = std::fs::write(&p, t);
                }
                let texts = files.iter().map(|(_, t)| t.as_bytes().to_vec()).collect();
                (run.join("top.toml"), texts)
            }
            None => (path.clone(), vec![bytes]),
        };
        hostile(top.to_str().unwrap()).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for t in texts {
            fast_path_agrees(&t).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
}

/// The line that starts another file in a fuzz input.
const SEPARATOR: &str = "#---- ";

/// A fuzz input's files, (name, text), `top.toml` first, as
/// fuzz/fuzz_targets/parse_and_compose.rs splits it: a line `#---- NAME`
/// starts the file NAME (at most three plain components, else `fN.toml`),
/// at most 16 files.
fn unframe(text: &str) -> Vec<(String, &str)> {
    let file_name = |line: &str, n: usize| {
        let name = line.trim_end_matches(['\r', ' ']);
        let plain = |c: &str| {
            !c.is_empty()
                && c != "."
                && c != ".."
                && c.len() <= 32
                && c.bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b"._-".contains(&b))
        };
        let parts: Vec<&str> = name.split('/').collect();
        if parts.len() <= 3 && parts.iter().all(|c| plain(c)) && name != "top.toml" {
            name.to_string()
        } else {
            format!("f{n}.toml")
        }
    };
    let mut files = Vec::new();
    let (mut name, mut start, mut at) = ("top.toml".to_string(), 0, 0);
    for line in text.split_inclusive('\n') {
        if let Some(rest) = line.strip_prefix(SEPARATOR)
            && files.len() + 1 < 16
        {
            files.push((name, &text[start..at]));
            name = file_name(rest.trim_end_matches('\n'), files.len());
            start = at + line.len();
        }
        at += line.len();
    }
    files.push((name, &text[start..]));
    files
}
