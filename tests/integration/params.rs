//! Parameters and expressions (issue 17, item 1): `[params]`, expressions
//! in quantity strings, `--set`, an include's `params`. Each value checked
//! against the same file written with literals, or against exact
//! rationals (num-rational) computed here independently of `massprop::expr`.

use crate::common::{massprop, report_json, scratch};
use crate::support::reference::{Q, f, frac, int};
use massprop::expr::{Expr, Value};
use massprop::units::Factor;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

/// The value of an expression with no parameters, in SI.
fn eval(text: &str) -> Result<f64, String> {
    let e = Expr::parse(text).map_err(|e| e.message)?;
    e.eval(&|_| None::<Value>, &Vec::new)
        .map(|v| v.in_units(Factor::ONE))
        .map_err(|e| e.message)
}

/// stderr of `report` on `text` (which must fail with status 2).
fn refused(text: &str, args: &[&str]) -> String {
    let dir = scratch("params", &format!("refused-{:x}", fxhash(text, args)));
    let path = dir.join("f.toml");
    std::fs::write(&path, text).unwrap();
    let mut argv = vec!["report"];
    argv.extend(args);
    argv.push(path.to_str().unwrap());
    let out = massprop(&argv);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{text}\n{stderr}");
    assert!(out.stdout.is_empty());
    stderr.replace(&format!("{}/", dir.display()), "")
}

fn fxhash(text: &str, args: &[&str]) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (text, args).hash(&mut h);
    h.finish()
}

fn point(mass: &str, center: &str) -> String {
    format!("[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = {center}\n")
}

const WHEEL_WITH_PARAMS: &str = r#"
units = { length = "mm" }

[params]
n = 32
rim_d = "622 mm"
rim_mass = "0.55 kg"
w = "(rim_d + 2 * tyre) / 2"
tyre = "28 mm"
hub = "rim_mass / 5"

[[part]]
name = "rim"
shape = "cylinder"
mass = "rim_mass"
radius = "rim_d / 2"
inner_radius = "rim_d / 2 - 20 mm"
length = "tyre"
center = [0, 0, 0]

[[part]]
name = "tyre"
shape = "box"
mass = "n * 0.01 kg"
size = ["w", "tyre", "tyre * 2"]
center = ["w / 2", 0, "-tyre"]

[[part]]
name = "hub"
shape = "sphere"
mass = "hub"
radius = "50 mm"
center = [0, 0, "0.1 mm + 0.2 mm"]
"#;

const WHEEL_WITH_LITERALS: &str = r#"
units = { length = "mm" }

[[part]]
name = "rim"
shape = "cylinder"
mass = 0.55
radius = 311
inner_radius = 291
length = 28
center = [0, 0, 0]

[[part]]
name = "tyre"
shape = "box"
mass = 0.32
size = [339, 28, 56]
center = [169.5, 0, -28]

[[part]]
name = "hub"
shape = "sphere"
mass = 0.11
radius = 50
center = [0, 0, 0.3]
"#;

/// A file with parameters and expressions gives the JSON of the same file
/// written with literals, to the bit (the literals are the exact values,
/// each the nearest f64: 0.55 / 5 is 0.11, 0.1 + 0.2 is 0.3).
#[test]
fn parameters_give_the_json_of_the_literals_to_the_bit() {
    let (mut a, _) = report_json(WHEEL_WITH_PARAMS, &[]);
    let (mut b, _) = report_json(WHEEL_WITH_LITERALS, &[]);
    a["source"].take();
    b["source"].take();
    assert_eq!(a, b);
}

#[test]
fn set_overrides_a_parameter_as_the_literal_would() {
    let (mut a, _) = report_json(
        WHEEL_WITH_PARAMS,
        &["--set", "tyre=\"30 mm\"", "--set", "n=2*16"],
    );
    let lit = WHEEL_WITH_LITERALS
        .replace("length = 28", "length = 30")
        .replace("size = [339, 28, 56]", "size = [341, 30, 60]")
        .replace("center = [169.5, 0, -28]", "center = [170.5, 0, -30]");
    let (mut b, _) = report_json(&lit, &[]);
    a["source"].take();
    b["source"].take();
    assert_eq!(a, b);
}

#[test]
fn a_third_times_three_is_exactly_the_value() {
    for a in ["0.7", "1e-3", "123.456", "0.1", "7", "2.5e10"] {
        let v = eval(&format!("{a} m / 3 * 3")).unwrap();
        assert_eq!(v, a.parse::<f64>().unwrap(), "{a}");
        let v = eval(&format!("({a} m / 7) * (7 / 3) * 3")).unwrap();
        assert_eq!(v, a.parse::<f64>().unwrap(), "{a}");
    }
}

#[test]
fn a_sum_of_decimals_is_rounded_once() {
    assert_eq!(eval("0.1 + 0.2").unwrap(), 0.3);
    assert_eq!(eval("0.1 m + 0.2 m").unwrap(), 0.3);
    // Fifty times 0.01 in f64 is 0.5000000000000002; exactly it is 0.5.
    let sum = vec!["0.01"; 50].join(" + ");
    assert_eq!(eval(&sum).unwrap(), 0.5);
    let folded = (0..50).fold(0.0, |s, _| s + 0.01);
    assert_ne!(folded, 0.5, "the test means something only if f64 drifts");
    // 1000 terms of 0.001 m, with a subtraction: exactly 0.9 m.
    let mut long = vec!["0.001 m"; 1000].join(" + ");
    long.push_str(" - 100 mm");
    assert_eq!(eval(&long).unwrap(), 0.9);
}

#[test]
fn units_in_expressions_convert_exactly() {
    assert_eq!(eval("7.85 g/cm^3").unwrap(), 7850.0);
    assert_eq!(
        eval("2 in + 1 ft").unwrap(),
        f(&(frac(254, 100) * int(2) / int(100) + frac(3048, 10000)))
    );
    assert_eq!(eval("360 deg / (1 rev)").unwrap(), 1.0);
    assert_eq!(eval("10^3 kg / (1 t)").unwrap(), 1.0);
    assert_eq!(eval("sqrt(9 m^2 / 4)").unwrap(), 1.5);
    assert_eq!(eval("sin(30 deg)").unwrap(), 0.5);
    assert_eq!(eval("cos(60 deg)").unwrap(), 0.5);
    assert_eq!(eval("max(1 m, 2 mm, -3 km)").unwrap(), 1.0);
    assert_eq!(eval("min(1 m, 2 mm, -3 km)").unwrap(), -3000.0);
    assert_eq!(eval("abs(-2.5 mm)").unwrap(), 0.0025);
    assert_eq!(eval("-2^2").unwrap(), -4.0);
    assert_eq!(eval("2^3^2").unwrap(), 512.0);
    assert_eq!(eval("2^-2").unwrap(), 0.25);
    assert_eq!(eval("4^(1/2)").unwrap(), 2.0);
    assert_eq!(eval("3 * mm").unwrap(), 0.003);
    let pi = eval("pi").unwrap();
    assert_eq!(pi, std::f64::consts::PI);
    // π d²/4 with d = 2 in: the double-double value rounded once.
    let area = eval("pi * (2 in)^2 / 4").unwrap();
    let d = 0.0508f64;
    assert!((area - std::f64::consts::PI * d * d / 4.0).abs() <= 2.0 * f64::EPSILON * area);
}

/// What the file says is wrong, with the exact line and column of the
/// token inside the string.
#[test]
fn errors_point_at_the_token_inside_the_string() {
    let cases = [
        // (mass, center, expected start of the message)
        (
            r#""2 kg + 3 mm""#,
            "[0, 0, 0]",
            "f.toml:3:14: error: `mass`: `+` of a mass (kg) and a length (m)",
        ),
        (
            r#"'1 kg / (2 - 2)'"#,
            "[0, 0, 0]",
            "f.toml:3:14: error: `mass`: division by zero",
        ),
        (
            r#""\u0032 kg + lgg""#,
            "[0, 0, 0]",
            "f.toml:3:21: error: `mass`: unknown name `lgg`",
        ),
        (
            r#""0^0 kg""#,
            "[0, 0, 0]",
            "f.toml:3:10: error: `mass`: 0^0 is undefined",
        ),
        (
            r#""10^400 kg""#,
            "[0, 0, 0]",
            "f.toml:3:11: error: `mass`: the value overflows the range of f64 here",
        ),
        (
            r#""2 kg * foo(3)""#,
            "[0, 0, 0]",
            "f.toml:3:16: error: `mass`: unknown function `foo`",
        ),
        (
            r#""sqrt(2 kg)""#,
            "[0, 0, 0]",
            "f.toml:3:9: error: `mass`: `sqrt` of a mass (kg): an odd power of a unit",
        ),
        (
            r#""2 kg +""#,
            "[0, 0, 0]",
            "f.toml:3:15: error: `mass`: the expression ends where a value was expected",
        ),
        (
            r#""(2 kg""#,
            "[0, 0, 0]",
            "f.toml:3:14: error: `mass`: expected `)`",
        ),
        (
            "1",
            r#"[0, "2 * 1 kg", 0]"#,
            "f.toml:4:14: error: `center` is a length (m), but the expression gives a mass (kg)",
        ),
        (
            "1",
            r#"[0, "sin(2 m) * 1 m", 0]"#,
            "f.toml:4:15: error: `center`: `sin` takes an angle",
        ),
    ];
    for (mass, center, want) in cases {
        let e = refused(&point(mass, center), &[]);
        assert!(e.starts_with(want), "{mass} {center}:\n{e}");
    }
}

#[test]
fn a_plain_quantity_keeps_the_unit_readers_messages() {
    let e = refused(&point(r#""3 furlongs""#, "[0, 0, 0]"), &[]);
    assert!(
        e.starts_with("f.toml:3:8: error: `mass`: unknown unit `furlongs`"),
        "{e}"
    );
    let e = refused(&point(r#""2 m^5""#, "[0, 0, 0]"), &[]);
    assert!(
        e.starts_with("f.toml:3:8: error: `mass`: cannot read unit `m^5`"),
        "{e}"
    );
}

#[test]
fn a_cycle_is_named_at_its_first_parameter() {
    let text = format!(
        "[params]\nb = \"c * 2\"\na = \"b + 1 mm\"\nc = \"a\"\nd = \"1 mm\"\n{}",
        point("1", "[0, 0, 0]")
    );
    let e = refused(&text, &[]);
    assert!(
        e.starts_with("f.toml:3:1: error: parameters form a cycle: a → b → c → a"),
        "{e}"
    );
    let text = format!("[params]\na = \"a\"\n{}", point("1", "[0, 0, 0]"));
    let e = refused(&text, &[]);
    assert!(
        e.starts_with("f.toml:2:1: error: parameters form a cycle: a → a"),
        "{e}"
    );
}

#[test]
fn an_undefined_name_suggests_a_near_one() {
    let text = format!(
        "[params]\nleg = \"700 mm\"\n{}",
        point("1", r#"[0, 0, "2 * lge"]"#)
    );
    let e = refused(&text, &[]);
    assert!(
        e.starts_with("f.toml:6:22: error: `center`: unknown name `lge`"),
        "{e}"
    );
    assert!(e.contains("did you mean `leg`?"), "{e}");
    // In a parameter's own definition too.
    let text = format!(
        "[params]\nleg = \"700 mm\"\nw = \"lge / 2\"\n{}",
        point("1", "[0, 0, 0]")
    );
    let e = refused(&text, &[]);
    assert!(
        e.starts_with("f.toml:3:6: error: parameter `w`: unknown name `lge`"),
        "{e}"
    );
}

#[test]
fn a_parameter_named_as_a_unit_a_function_or_pi_is_refused() {
    for (name, what) in [
        ("mm", "a unit symbol"),
        ("t", "a unit symbol"),
        ("pi", "the constant π"),
        ("sqrt", "a function"),
    ] {
        let e = refused(
            &format!("[params]\n{name} = 3\n{}", point("1", "[0, 0, 0]")),
            &[],
        );
        assert!(
            e.starts_with(&format!(
                "f.toml:2:1: error: the parameter `{name}` is named as {what}"
            )),
            "{e}"
        );
    }
}

#[test]
fn set_refuses_a_name_the_file_does_not_define() {
    let text = format!(
        "[params]\nleg = \"700 mm\"\n{}",
        point("1", r#"[0, 0, "leg"]"#)
    );
    let e = refused(&text, &["--set", "lge=1 m"]);
    assert!(
        e.starts_with("error: `--set lge`: ") && e.contains(".toml defines no parameter `lge`"),
        "{e}"
    );
    assert!(e.contains("did you mean `leg`?"), "{e}");
    let e = refused(&text, &["--set", "leg"]);
    assert!(e.contains("expected NAME=VALUE"), "{e}");
    // A value of another dimension than the file's is refused at the flag.
    let e = refused(&text, &["--set", "leg=2 kg"]);
    assert!(
        e.starts_with(
            "--set leg:1:1: error: `--set leg=2 kg` gives a mass (kg), but the file's `leg` is a length (m)"
        ),
        "{e}"
    );
    assert!(e.contains("note: `leg` is defined at f.toml:2:1"), "{e}");
    // A bad value is located in the flag's value, the flag named.
    let e = refused(&text, &["--set", "leg=2 ** 3"]);
    assert!(
        e.starts_with("--set leg:1:4: error: `--set leg=2 ** 3`: "),
        "{e}"
    );
}

#[test]
fn set_works_for_check_and_diff_and_bless_refuses_it() {
    let dir = scratch("params", "set-commands");
    let text = format!(
        "[params]\nload = \"2 kg\"\n{}[expect]\nmass = {{ value = 2, tol = \"0%\" }}\n",
        point("\"load\"", "[0, 0, 0]")
    );
    let a = dir.join("a.toml");
    std::fs::write(&a, &text).unwrap();
    let a = a.to_str().unwrap();
    assert_eq!(massprop(&["check", a]).status.code(), Some(0));
    assert_eq!(
        massprop(&["check", a, "--set", "load=3 kg"]).status.code(),
        Some(1)
    );
    assert_eq!(
        massprop(&["check", a, "--set", "load=1 kg + 1000 g"])
            .status
            .code(),
        Some(0)
    );
    let out = massprop(&["check", "--bless", a, "--set", "load=3 kg"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("`--set` cannot be used with `--bless`"));
    // diff: --set applies to both files alike.
    let b = dir.join("b.toml");
    std::fs::write(&b, text.replace("load = \"2 kg\"", "load = \"2000 g\"")).unwrap();
    let b = b.to_str().unwrap();
    assert_eq!(massprop(&["diff", a, b]).status.code(), Some(0));
    assert_eq!(
        massprop(&["diff", a, b, "--set", "load=5 kg"])
            .status
            .code(),
        Some(0)
    );
    let out = massprop(&["report", "--format", "json", a, "--set", "load=5 kg"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["mass"], 5.0);
}

#[test]
fn two_includes_of_one_file_with_different_params_are_different_bodies() {
    let dir = scratch("params", "include");
    std::fs::write(
        dir.join("wheel.toml"),
        "[params]\nd = \"600 mm\"\nmw = \"1 kg\"\n[[part]]\nshape = \"sphere\"\nmass = \"mw\"\nradius = \"d / 2\"\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let top = "[params]\nbig = \"700 mm\"\n\
        [[part]]\ninclude = \"wheel.toml\"\nparams = { d = \"big\", mw = \"2 kg\" }\n\
        [[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n\
        [[part]]\ninclude = \"wheel.toml\"\norigin = [2, 0, 0]\nparams = { d = \"0.7 m\", mw = \"2000 g\" }\n";
    let path = dir.join("top.toml");
    std::fs::write(&path, top).unwrap();
    let out = massprop(&["report", "--format", "json", path.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Literals: two wheels of 2 kg and 0.35 m, one of 1 kg and 0.3 m.
    let lit = "[[part]]\nshape = \"sphere\"\nmass = 2\nradius = 0.35\ncenter = [0, 0, 0]\n\
        [[part]]\nshape = \"sphere\"\nmass = 1\nradius = 0.3\ncenter = [1, 0, 0]\n\
        [[part]]\nshape = \"sphere\"\nmass = 2\nradius = 0.35\ncenter = [2, 0, 0]\n";
    let (b, _) = report_json(lit, &[]);
    let a: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in ["mass", "center_of_mass", "inertia"] {
        assert_eq!(a[key], b[key], "{key}");
    }
    // A name the included file does not define: at the include's key.
    std::fs::write(
        &path,
        "[[part]]\ninclude = \"wheel.toml\"\nparams = { dd = \"1 m\" }\n",
    )
    .unwrap();
    let out = massprop(&["report", path.to_str().unwrap()]);
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        e.contains("top.toml:3:12: error: `params`: the included `"),
        "{e}"
    );
    assert!(
        e.contains("defines no parameter `dd`") && e.contains("did you mean `d`?"),
        "{e}"
    );
    // Parameters do not leak: the included file does not see `big`.
    std::fs::write(
        dir.join("leak.toml"),
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [\"big\", 0, 0]\n",
    )
    .unwrap();
    std::fs::write(
        &path,
        "[params]\nbig = \"1 m\"\n[[part]]\ninclude = \"leak.toml\"\n",
    )
    .unwrap();
    let out = massprop(&["report", path.to_str().unwrap()]);
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(e.contains("unknown name `big`"), "{e}");
    // `params` on a shape is not a key of it.
    let e = refused(
        &format!("{}params = {{ a = 1 }}\n", point("1", "[0, 0, 0]")),
        &[],
    );
    assert!(e.contains("`params`"), "{e}");
}

/// Hostile input: bounded nesting, huge exponents, long expressions in
/// linear time, overflow an error and not inf.
#[test]
fn hostile_expressions_are_refused_quickly() {
    let deep = format!("{}1{}", "(".repeat(100_000), ")".repeat(100_000));
    assert!(eval(&deep).unwrap_err().contains("nests deeper than 64"));
    let minus = format!("{}1", "-".repeat(100_000));
    assert!(eval(&minus).unwrap_err().contains("nests deeper"));
    let pow = format!("2{}", "^2".repeat(100_000));
    assert!(eval(&pow).unwrap_err().contains("nests deeper"));
    assert!(eval("2^100000000000").unwrap_err().contains("overflows"));
    assert!(
        eval("2^-100000000000 * 1")
            .unwrap_err()
            .contains("underflows")
    );
    assert!(eval("1e-200 * 1e-200").unwrap_err().contains("underflows"));
    assert_eq!(eval("0 * 1e-200").unwrap(), 0.0);
    assert!(eval("1e308 * 10").unwrap_err().contains("overflows"));
    assert!(eval("1e400").unwrap_err().contains("beyond the range"));
    assert!(
        eval("(1 m)^100000000")
            .unwrap_err()
            .contains("cannot be raised")
    );
    assert_eq!(eval("1^100000000000000").unwrap(), 1.0);
    // Linear, without a clock: 400,000 terms are read and summed within a
    // generous hang guard (a quadratic reader would take 10¹¹ steps, far
    // past it, where a linear one takes about a second unoptimised); the
    // figures are in benches/, not here.
    let n = 400_000;
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let long = vec!["1.5 mm"; n].join("+");
        let _ = tx.send(eval(&long));
    });
    let sum = rx
        .recv_timeout(std::time::Duration::from_secs(120))
        .expect("400,000 terms were not summed within two minutes: not linear");
    assert_eq!(sum.unwrap(), n as f64 * 1.5e-3);
}

/// A reference evaluator, written here: the same grammar over exact
/// rationals (BigRational), without units.
mod reference {
    use super::*;

    #[derive(Clone, Debug)]
    pub enum E {
        Num(i64, u32),
        Neg(Box<E>),
        Bin(char, Box<E>, Box<E>),
        Pow(Box<E>, i32),
    }

    impl E {
        pub fn text(&self) -> String {
            match self {
                E::Num(n, k) => {
                    let s = n.unsigned_abs().to_string();
                    let s = if *k == 0 { s } else { format!("{s}e-{k}") };
                    if *n < 0 { format!("(-{s})") } else { s }
                }
                E::Neg(e) => format!("-({})", e.text()),
                E::Bin(op, a, b) => format!("({} {op} {})", a.text(), b.text()),
                E::Pow(a, k) => format!("({})^{k}", a.text()),
            }
        }

        pub fn value(&self) -> Option<Q> {
            Some(match self {
                E::Num(n, k) => int(*n) / Q::from_integer(num_bigint::BigInt::from(10).pow(*k)),
                E::Neg(e) => -e.value()?,
                E::Bin(op, a, b) => {
                    let (a, b) = (a.value()?, b.value()?);
                    match op {
                        '+' => a + b,
                        '-' => a - b,
                        '*' => a * b,
                        _ if b.is_zero() => return None,
                        _ => a / b,
                    }
                }
                E::Pow(a, k) => {
                    let a = a.value()?;
                    if a.is_zero() && *k <= 0 {
                        return None;
                    }
                    num_traits::pow::Pow::pow(a, *k)
                }
            })
        }
    }

    pub fn expr() -> impl Strategy<Value = E> {
        let leaf = (-2000i64..2000, 0u32..4).prop_map(|(n, k)| E::Num(n, k));
        leaf.prop_recursive(5, 40, 2, |inner| {
            prop_oneof![
                inner.clone().prop_map(|e| E::Neg(Box::new(e))),
                (
                    inner.clone(),
                    inner.clone(),
                    prop_oneof![Just('+'), Just('-'), Just('*'), Just('/')]
                )
                    .prop_map(|(a, b, op)| E::Bin(op, Box::new(a), Box::new(b))),
                (inner, -3i32..4).prop_map(|(a, k)| E::Pow(Box::new(a), k)),
            ]
        })
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Random expressions evaluate to the reference's exact value rounded
    /// once: bit for bit wherever the rational stays within i128 (every
    /// intermediate below 2^120 here, so massprop's checked i128
    /// arithmetic never falls back); else within the double-double
    /// fallback's error, a few units of 2^-104 of the largest
    /// intermediate, relative to the result.
    #[test]
    fn expressions_evaluate_to_the_exact_rational_rounded_once(e in reference::expr()) {
        let text = e.text();
        let got = eval(&text);
        match e.value() {
            None => prop_assert!(got.is_err(), "{text}: {got:?}"),
            Some(v) => {
                let want = f(&v);
                if !want.is_finite() || (want != 0.0 && want.abs() < f64::MIN_POSITIVE) {
                    return Ok(());
                }
                let small = v.numer().bits() < 100 && v.denom().bits() < 100;
                let got = got.map_err(|m| TestCaseError::fail(format!("{text}: {m}")))?;
                if small && got != want {
                    // The i128 path may still have fallen back on an
                    // intermediate: allow the fallback's error.
                    let err = (Q::from_float(got).unwrap() - v.clone()).abs();
                    prop_assert!(
                        err <= v.abs() * frac(1, 1 << 40),
                        "{text}: {got:e} != {want:e}"
                    );
                } else if !small {
                    let rel = ((got - want) / want).abs();
                    prop_assert!(rel < 1e-9 || got == want, "{text}: {got:e} vs {want:e}");
                }
            }
        }
    }
}

/// A file with expressions and no `[params]` is streamed (each part made as
/// read); an empty `[params]` has it read whole first: both give the same
/// body, to the bit.
#[test]
fn expressions_read_alike_streamed_and_read_whole() {
    let parts = "units = { length = \"mm\" }\n[[part]]\nshape = \"box\"\nmass = \"1 kg / 3 * 2\"\n\
        size = [\"0.1 m + 0.2 m\", \"pi * 2 mm\", \"sqrt(2) * 1 mm\"]\ncenter = [\"1 in / 7\", 0, \"-(3 mm)^2 / 1 m\"]\n";
    let fast = parts.to_string();
    assert!(
        massprop::model::fast::read_file(&fast).is_some(),
        "the fast path reads it"
    );
    let whole = format!("{parts}[params]\n");
    assert!(
        massprop::model::fast::read_file(&whole).is_some_and(|raw| raw.params.is_some()),
        "the reader reads `[params]`"
    );
    let (mut a, _) = report_json(&fast, &[]);
    let (mut b, _) = report_json(&whole, &[]);
    a["source"].take();
    b["source"].take();
    assert_eq!(a, b);
}

/// Parameters reach `[materials]`, `[analysis]` and `[expect]` too.
#[test]
fn parameters_reach_materials_analysis_and_expect() {
    let text = "[params]\nrho = \"7850 kg/m^3\"\nside = \"0.1 m\"\nspin = \"3000 rpm\"\n\
        [materials]\nsteel2 = { density = \"rho * 2\" }\n\
        [[part]]\nshape = \"box\"\nmaterial = \"steel2\"\nsize = [\"side\", \"side\", \"side\"]\ncenter = [0, 0, 0]\n\
        [analysis]\nomega = [0, 0, \"spin\"]\n\
        [expect]\nmass = { value = \"rho * 2 * side^3\", tol = \"1e-12%\" }\n";
    let dir = scratch("params", "reach");
    let path = dir.join("f.toml");
    std::fs::write(&path, text).unwrap();
    let out = massprop(&["check", path.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The body's mass is the material's density times the box's volume
    // (each rounded once in f64): within a few roundings of 15.7 kg.
    let (v, _) = report_json(text, &[]);
    let mass = v["mass"].as_f64().unwrap();
    let exact = f(&(int(15700) * frac(1, 1000)));
    assert!((mass - exact).abs() <= 4.0 * f64::EPSILON * exact, "{mass}");
    // And a tolerance of 0 fails it only if the product is not exact:
    // the expected value is the exact 15.7, not a rounded product.
    let strict = text.replace("1e-12%", "0%");
    std::fs::write(&path, &strict).unwrap();
    let code = massprop(&["check", path.to_str().unwrap()]).status.code();
    assert_eq!(code, Some(if mass == exact { 0 } else { 1 }));
}
