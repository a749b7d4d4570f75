//! Exact arithmetic stays exact, and names are unambiguous (issue 28,
//! items 4 and 7): integer powers past i64 by magnitude and parity, never
//! by an exponent wrapped or clamped; a literal below f64's normal range
//! "too small" at its own token, in an expression, a parameter, an
//! include's `params` or `--set`; `count` whole in exact rationals; an
//! error `--set` causes naming the flag and its value; a copy's name or an
//! automatic `#k` that clashes with a name written refused at both places.
//!
//! Expected values are computed here, independently of `massprop::expr`:
//! exact ones with big rationals (num-rational, num-bigint), those of huge
//! powers from the closed form exp(n·ln x) of Rust's f64 functions where
//! the correction terms are below f64's precision.

use crate::common::{massprop, scratch_files};
use crate::support::reference::{Q, f};
use massprop::diag::Source;
use massprop::expr::{Expr, Value};
use massprop::model::{Includes, Model};
use massprop::units::Factor;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

/// The value of an expression with no parameters (SI), or its error's
/// message and byte range.
fn eval(text: &str) -> Result<f64, (String, std::ops::Range<usize>)> {
    let e = Expr::parse(text).map_err(|e| (e.message, e.at))?;
    e.eval(&|_| None::<Value>, &Vec::new)
        .map(|v| v.in_units(Factor::ONE))
        .map_err(|e| (e.message, e.at))
}

fn value(text: &str) -> f64 {
    eval(text).unwrap_or_else(|e| panic!("{text}: {e:?}"))
}

fn error(text: &str) -> (String, std::ops::Range<usize>) {
    match eval(text) {
        Ok(x) => panic!("{text} gave {x}"),
        Err(e) => e,
    }
}

/// The model's error for a file `f.toml` (with `--set` flags), rendered.
fn refused(text: &str, set: &[&str]) -> String {
    let includes = Includes {
        set: set.iter().map(|s| s.to_string()).collect(),
        ..Includes::default()
    };
    match Model::parse_with(&Source::new("f.toml", text), &includes) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(d) => d.to_string(),
    }
}

fn accepted(text: &str) -> Model {
    Model::parse(&Source::new("f.toml", text)).unwrap_or_else(|d| panic!("{d}\n{text}"))
}

/// Units in the last place between two finite f64 of one sign.
fn ulps(a: f64, b: f64) -> u64 {
    assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "{a} {b}");
    a.abs().to_bits().abs_diff(b.abs().to_bits())
}

fn point(mass: &str, center: &str) -> String {
    format!("[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = {center}\n")
}

// ---------------------------------------------------------------------------
// Powers past i64

#[test]
fn minus_one_to_an_even_power_past_i64_is_one_and_to_an_odd_one_minus_one() {
    // 2^64 and 2^64 + 1, written out and as expressions.
    assert_eq!(value("(-1)^18446744073709551616"), 1.0);
    assert_eq!(value("(-1)^18446744073709551617"), -1.0);
    assert_eq!(value("(-1)^(2^64)"), 1.0);
    assert_eq!(value("(-1)^(2^64 + 1)"), -1.0);
    // i64::MAX + 1 is even (it was clamped to i64::MAX, odd).
    assert_eq!(value("(-1)^9223372036854775808"), 1.0);
    assert_eq!(value("(-1)^(2^126 + 1)"), -1.0);
    assert_eq!(value("(-1)^(-(2^100))"), 1.0);
    // 39 digits, below i128::MAX: read exactly, not rounded to an even f64.
    assert_eq!(
        value("(-1)^(-133444065459191554299362591149713024245)"),
        -1.0
    );
    assert_eq!(value("(-1)^170141183460469231731687303715884105727"), -1.0);
}

#[test]
fn zero_and_one_to_any_power_past_i64_are_zero_and_one() {
    assert_eq!(value("0^(2^100)"), 0.0);
    assert_eq!(value("1^(2^100)"), 1.0);
    assert_eq!(value("1^(-(2^120))"), 1.0);
    assert_eq!(value("1^(2^300)"), 1.0);
    assert_eq!(value("0^(2^300)"), 0.0);
    let (m, _) = error("0^(-(2^100))");
    assert!(m.contains("division by zero"), "{m}");
}

#[test]
fn a_base_above_one_to_a_power_past_i64_overflows_at_its_caret() {
    for text in [
        "2^18446744073709551617",
        "2^(2^70)",
        "1.0000001^(2^64)",
        "(-2)^(2^64 + 1)",
        "(1/2)^(-(2^70))",
        "2^(2^200)",
    ] {
        let (m, at) = error(text);
        assert!(m.contains("overflows the range of f64"), "{text}: {m}");
        let caret = text.find('^').unwrap();
        assert_eq!(at, caret..caret + 1, "{text}");
    }
}

#[test]
fn a_base_below_one_to_a_power_past_i64_underflows_at_its_caret() {
    for text in ["0.5^1e30", "2^-(2^70)", "(1/3)^(2^64)", "(-0.5)^(2^200)"] {
        let (m, at) = error(text);
        assert!(m.contains("underflows f64"), "{text}: {m}");
        let caret = text.find('^').unwrap();
        assert_eq!(at, caret..caret + 1, "{text}");
    }
}

#[test]
fn a_base_near_one_to_a_huge_power_is_exp_of_n_ln_x() {
    // n·ln(1 ± 1/m) = ±n/m − n/(2m²) + …: with n = c·m, m = 1e20, the
    // correction is below 1e-19 relative, under f64's half ulp.
    for (text, c) in [
        ("(1 + 1e-20)^(10^21)", 10.0),
        ("(1 - 1e-20)^(10^21)", -10.0),
        ("(1 + 1/10^20)^(7 * 10^20)", 7.0),
        ("(1 + 2^-60)^(2^64)", 16.0),
    ] {
        let got = value(text);
        let want = f64::exp(c);
        assert!(ulps(got, want) <= 2, "{text}: {got} against {want}");
    }
    // An odd power of a negative base keeps its sign.
    let got = value("(-(1 + 1e-20))^(10^21 + 1)");
    assert!(ulps(got, -f64::exp(10.0)) <= 2, "{got}");
}

#[test]
fn a_fractional_power_past_i64_is_not_wrapped() {
    // 4^((2^64 + 1)/2) overflows; the numerator wrapped to 1 gave 2.
    let (m, _) = error("4^(18446744073709551617/2)");
    assert!(m.contains("overflows"), "{m}");
    let (m, _) = error("0.25^(18446744073709551617/2)");
    assert!(m.contains("underflows"), "{m}");
    assert_eq!(value("1^(18446744073709551617/2)"), 1.0);
}

#[test]
fn a_negative_base_to_a_power_beyond_i128_is_refused_when_its_parity_matters() {
    let (m, at) = error("(-1)^(2^200)");
    assert!(m.contains("even or odd"), "{m}");
    assert_eq!(at, 4..5);
}

#[test]
fn a_huge_power_in_a_file_is_refused_at_its_caret() {
    let e = refused(&point("\"kg * 2^(2^70)\"", "[0, 0, 0]"), &[]);
    // `mass = "kg * 2^(2^70)"`: the `^` is column 15.
    assert!(
        e.starts_with("f.toml:3:15: error: `mass`: the value overflows the range of f64 here"),
        "{e}"
    );
}

#[test]
fn an_even_power_of_minus_one_past_i64_is_a_positive_mass() {
    let m = accepted(&point("\"kg * (-1)^(2^64)\"", "[0, 0, 0]"));
    assert_eq!(m.count, 1);
}

// ---------------------------------------------------------------------------
// Literals below f64's range

#[test]
fn a_literal_below_the_normal_range_is_too_small_at_its_token() {
    for (text, lit) in [
        ("3 * 1e-400", "1e-400"),
        ("1e-320 * 1e300", "1e-320"),
        ("2 + 0.0000001e-302", "0.0000001e-302"),
        ("1e-99999999999999999999 * 2", "1e-99999999999999999999"),
    ] {
        let (m, at) = error(text);
        assert!(m.contains("is too small"), "{text}: {m}");
        let start = text.find(lit).unwrap();
        assert_eq!(at, start..start + lit.len(), "{text}");
    }
    // Zero written as zero is a value.
    assert_eq!(value("0e-400 + 1"), 1.0);
    assert_eq!(value("0.000e-999 * 5"), 0.0);
}

#[test]
fn a_step_below_the_normal_range_underflows_at_the_step() {
    // 1e-160 · 1e-160 is subnormal: it went on with 10 bits.
    let (m, at) = error("1e-160 * 1e-160 * 1e300");
    assert!(m.contains("underflows f64"), "{m}");
    assert_eq!(at, 7..8);
}

#[test]
fn a_tiny_literal_in_a_file_is_located_inside_its_string() {
    let e = refused(&point("1", "[\"3 * 1e-400 m\", 0, 0]"), &[]);
    // `center = ["3 * 1e-400 m"`: the literal starts at column 16.
    assert!(
        e.starts_with("f.toml:4:16: error: `center`: the number `1e-400` is too small"),
        "{e}"
    );
}

#[test]
fn a_parameter_below_the_normal_range_is_too_small_at_its_key() {
    for (def, col) in [
        ("n = 1e-400", 5),
        ("n = -4e-320", 5),
        ("n = \"2 * 1e-400\"", 10),
    ] {
        let text = format!("[params]\n{def}\n{}", point("1", "[\"n * 1 m\", 0, 0]"));
        let e = refused(&text, &[]);
        assert!(
            e.starts_with(&format!("f.toml:2:{col}: error: parameter `n`")),
            "{e}"
        );
        assert!(e.contains("too small"), "{e}");
    }
    let text = format!(
        "[params]\nn = 0e-400\n{}",
        point("1", "[\"n * 1 m\", 0, 0]")
    );
    accepted(&text);
}

#[test]
fn a_set_value_below_the_normal_range_is_too_small_in_the_flag() {
    let text = format!("[params]\nleg = \"1 m\"\n{}", point("1", "[\"leg\", 0, 0]"));
    let e = refused(&text, &["leg=1e-400 m"]);
    assert!(
        e.starts_with(
            "--set leg:1:1: error: `--set leg=1e-400 m`: the number `1e-400` is too small"
        ),
        "{e}"
    );
}

#[test]
fn an_include_parameter_below_the_normal_range_is_too_small_at_its_key() {
    let sub = format!("[params]\nn = 1\n{}", point("\"n * 1 kg\"", "[0, 0, 0]"));
    let top = "[[part]]\ninclude = \"sub.toml\"\nparams = { n = 1e-400 }\n";
    let top = scratch_files(
        "exact",
        "include-tiny",
        &[("sub.toml", &sub), ("top.toml", top)],
    );
    let out = massprop(&["report", top.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(
        stderr.contains("top.toml:3:16: error: parameter `n` is too small"),
        "{stderr}"
    );
}

// ---------------------------------------------------------------------------
// Whole-number keys

fn array(count: &str) -> String {
    format!(
        "{}array = {{ count = {count}, step = [1, 0, 0] }}\n",
        point("1", "[0, 0, 0]")
    )
}

#[test]
fn a_count_exactly_whole_in_rationals_is_that_many_copies() {
    for (count, n) in [
        ("\"10/3*3\"", 10),
        ("\"0.1*30\"", 3),
        ("\"2^130 / 2^128\"", 4),
        ("\"sqrt(16)\"", 4),
        ("4.0", 4),
        ("\"1e1\"", 10),
    ] {
        assert_eq!(accepted(&array(count)).count, n, "{count}");
    }
}

#[test]
fn a_count_whole_only_after_rounding_to_f64_is_refused() {
    for count in [
        "\"(1 + 1e-20) * 3\"",
        "3.0000000000000001",
        "\"7 - 1/10^30\"",
        "\"0.1 * 3 * 10 + 1e-25\"",
    ] {
        let e = refused(&array(count), &[]);
        assert!(
            e.starts_with("f.toml:5:19: error: `count` must be a whole number of copies")
                && e.contains("is not exactly whole"),
            "{count}: {e}"
        );
    }
    let e = refused(&array("\"10/3\""), &[]);
    assert!(
        e.contains("`count` must be a whole number of copies"),
        "{e}"
    );
}

// ---------------------------------------------------------------------------
// --set

fn with_leg() -> String {
    format!(
        "[params]\nleg = \"700 mm\"\n{}",
        point("1", "[\"leg\", 0, 0]")
    )
}

#[test]
fn an_error_in_a_set_value_names_the_flag_and_its_value() {
    let e = refused(&with_leg(), &["leg=1/0 m"]);
    assert!(
        e.starts_with("--set leg:1:2: error: `--set leg=1/0 m`: division by zero"),
        "{e}"
    );
    let e = refused(&with_leg(), &["leg=2^(2^70) m"]);
    assert!(
        e.contains("`--set leg=2^(2^70) m`: the value overflows"),
        "{e}"
    );
}

#[test]
fn a_set_value_of_another_dimension_is_refused_at_the_flag_with_the_files_place() {
    let e = refused(&with_leg(), &["leg=3 kg"]);
    assert!(
        e.starts_with(
            "--set leg:1:1: error: `--set leg=3 kg` gives a mass (kg), but the file's `leg` is a length (m)"
        ),
        "{e}"
    );
    assert!(e.contains("note: `leg` is defined at f.toml:2:1"), "{e}");
}

#[test]
fn an_error_at_a_key_a_set_value_caused_notes_the_flag() {
    // A zero mass: the file's key is where it fails, the flag is why.
    let text = format!("[params]\nw = \"1 kg\"\n{}", point("\"w\"", "[0, 0, 0]"));
    let e = refused(&text, &["w=0 kg"]);
    assert!(
        e.starts_with("f.toml:5:8: error: `mass` must be positive"),
        "{e}"
    );
    assert!(
        e.contains("note: `--set w=0 kg` gives `w` here, in place of its definition at f.toml:2:1"),
        "{e}"
    );
    // And in a parameter of the file that uses it.
    let text = format!(
        "[params]\nw = \"1 kg\"\nhalf = \"w / (w - 1 kg)\"\n{}",
        point("\"half\"", "[0, 0, 0]")
    );
    let e = refused(&text, &["w=1000 g"]);
    assert!(e.contains("parameter `half`: division by zero"), "{e}");
    assert!(e.contains("note: `--set w=1000 g` gives `w` here"), "{e}");
}

#[test]
fn an_error_the_flag_did_not_touch_has_no_note() {
    let text = format!(
        "[params]\nw = \"1 kg\"\n{}{}",
        point("\"w\"", "[0, 0, 0]"),
        point("0", "[0, 0, 0]")
    );
    let e = refused(&text, &["w=2 kg"]);
    assert!(
        e.contains("`mass` must be positive") && !e.contains("note"),
        "{e}"
    );
}

// ---------------------------------------------------------------------------
// Names

#[test]
fn a_name_written_that_is_a_copys_name_is_refused_at_both_places() {
    let text = format!(
        "{}name = \"leg\"\narray = {{ count = 3, step = [1, 0, 0] }}\n[[part]]\nname = \"leg[2]\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n",
        point("1", "[0, 0, 0]")
    );
    let e = refused(&text, &[]);
    assert!(
        e.starts_with("f.toml:8:8: error: the name `leg[2]` is also the name of a copy"),
        "{e}"
    );
    assert!(
        e.contains("note: `leg`'s copies are asked for at f.toml:6:9"),
        "{e}"
    );
    // Past the copies, or with a leading zero, it names none.
    accepted(&text.replace("leg[2]", "leg[3]"));
    accepted(&text.replace("leg[2]", "leg[02]"));
}

#[test]
fn a_mirror_names_its_image_and_an_unnamed_part_its_copies() {
    let text = format!(
        "{}mirror = {{ normal = [1, 0, 0] }}\n{}name = \"part 1[1]\"\n",
        point("1", "[1, 0, 0]"),
        point("1", "[0, 0, 0]")
    );
    let e = refused(&text, &[]);
    assert!(
        e.contains("the name `part 1[1]` is also the name of a copy"),
        "{e}"
    );
}

fn run_files(name: &str, files: &[(&str, &str)]) -> (Option<i32>, String) {
    // `top.toml` last: the file run.
    let top = scratch_files("exact", name, files);
    let out = massprop(&["report", top.to_str().unwrap()]);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const WHEEL: &str =
    "name = \"wheel\"\n[[part]]\nname = \"hub\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";

#[test]
fn a_sub_assembly_named_as_an_automatic_number_is_refused_in_either_order() {
    let wheels = "[[part]]\ninclude = \"wheel.toml\"\n\n[[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";
    let named = "\n[[part]]\nname = \"wheel #2\"\ninclude = \"other.toml\"\n";
    for (order, top, line) in [
        ("after", format!("{wheels}{named}"), 9),
        ("before", format!("{named}\n{wheels}"), 3),
    ] {
        let (status, e) = run_files(
            &format!("numbered-{order}"),
            &[
                ("wheel.toml", WHEEL),
                ("other.toml", WHEEL),
                ("top.toml", &top),
            ],
        );
        assert_eq!(status, Some(2), "{e}");
        assert!(
            e.contains(&format!(
                "top.toml:{line}:8: error: the sub-assembly name `wheel #2` is also a number given automatically"
            )),
            "{order}: {e}"
        );
        assert!(
            e.contains("note: the sub-assembly numbered `wheel #"),
            "{e}"
        );
    }
}

#[test]
fn an_included_files_name_that_is_a_copys_name_is_refused() {
    // The include's name is its file name's stem: `wheel[1]`.
    let top = "[[part]]\nname = \"wheel\"\ninclude = \"other.toml\"\nmirror = { normal = [1, 0, 0] }\n\n[[part]]\ninclude = \"wheel[1].toml\"\n";
    let sub = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let (status, e) = run_files(
        "include-stem",
        &[
            ("other.toml", WHEEL),
            ("wheel[1].toml", sub),
            ("top.toml", top),
        ],
    );
    assert_eq!(status, Some(2), "{e}");
    assert!(
        e.contains("top.toml:7:11: error: the name `wheel[1]` is also the name of a copy"),
        "{e}"
    );
}

#[test]
fn a_sub_assembly_name_written_twice_is_refused_at_both_places() {
    // Numbered `left #2`, the second would not be what the user wrote, and
    // `--only left` could never select it.
    let top = "[[part]]\nname = \"left\"\ninclude = \"wheel.toml\"\n\n[[part]]\nname = \"left\"\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";
    let (status, e) = run_files("written-twice", &[("wheel.toml", WHEEL), ("top.toml", top)]);
    assert_eq!(status, Some(2), "{e}");
    assert!(
        e.contains("top.toml:6:8: error: the sub-assembly name `left` is written twice"),
        "{e}"
    );
    assert!(e.contains("note: first written at "), "{e}");
    assert!(e.contains("top.toml:2:8"), "{e}");
}

#[test]
fn two_includes_without_a_written_name_are_still_numbered() {
    let top = "[[part]]\ninclude = \"wheel.toml\"\n\n[[part]]\ninclude = \"wheel.toml\"\norigin = [1, 0, 0]\n";
    let dir = scratch_files(
        "exact",
        "numbered-unwritten",
        &[("wheel.toml", WHEEL), ("top.toml", top)],
    );
    for (only, x) in [("wheel", 0.0), ("wheel #2", 1.0)] {
        let out = massprop(&[
            "report",
            "--format",
            "json",
            "--only",
            only,
            dir.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(0), "{out:?}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["center_of_mass"][0].as_f64(), Some(x), "{only}: {v}");
    }
}

#[test]
fn distinct_names_and_automatic_numbers_alone_are_accepted() {
    let top = "[[part]]\ninclude = \"wheel.toml\"\narray = { count = 2, step = [1, 0, 0] }\n\n[[part]]\ninclude = \"wheel.toml\"\n\n[[part]]\nname = \"wheel #2[0]\"\ninclude = \"other.toml\"\n";
    // `wheel #2[0]` is not a copy: the second `wheel` has no array.
    let (status, e) = run_files(
        "distinct",
        &[
            ("wheel.toml", WHEEL),
            ("other.toml", WHEEL),
            ("top.toml", top),
        ],
    );
    assert_eq!(status, Some(0), "{e}");
}

// ---------------------------------------------------------------------------
// Properties over expression edges, against big rationals

fn big(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

/// x^n exactly (n may be negative; x ≠ 0 then).
fn pow(x: &Q, n: i64) -> Q {
    let mut out = Q::one();
    let mut base = if n < 0 { x.recip() } else { x.clone() };
    let mut e = n.unsigned_abs();
    while e > 0 {
        if e & 1 == 1 {
            out *= &base;
        }
        e >>= 1;
        if e > 0 {
            base = &base * &base;
        }
    }
    out
}

/// Whether |x| is within a factor 1.001 of f64's largest or smallest
/// normal value (where a double-double step may round either way).
fn near_an_edge(x: &Q) -> bool {
    let a = x.abs();
    let max = Q::from_float(f64::MAX).unwrap();
    let min = Q::from_float(f64::MIN_POSITIVE).unwrap();
    let k = Q::new(BigInt::from(1001), BigInt::from(1000));
    (a > &max / &k && a < &max * &k) || (a > &min / &k && a < &min * &k)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// (±p/q)^n for |n| up to 3000: the exact power, rounded, within 2
    /// ulps (exact paths round once; double-double ones nearly so); past
    /// f64's range an overflow or an underflow at the `^`.
    #[test]
    fn integer_powers_match_big_rationals(
        p in 1i64..2000, q in 1i64..2000, negative: bool, n in -3000i64..3000,
    ) {
        let x = Q::new(BigInt::from(if negative { -p } else { p }), BigInt::from(q));
        let text = format!("({}{p}/{q})^({n})", if negative { "-" } else { "" });
        let want = pow(&x, n);
        prop_assume!(!near_an_edge(&want));
        let max = Q::from_float(f64::MAX).unwrap();
        let min = Q::from_float(f64::MIN_POSITIVE).unwrap();
        let caret = text.find(")^").unwrap() + 1;
        if want.abs() > max {
            let (m, at) = error(&text);
            prop_assert!(m.contains("overflows"), "{}: {}", text, m);
            prop_assert_eq!(at, caret..caret + 1);
        } else if want.abs() < min {
            let (m, at) = error(&text);
            prop_assert!(m.contains("underflows"), "{}: {}", text, m);
            prop_assert_eq!(at, caret..caret + 1);
        } else {
            let got = value(&text);
            prop_assert!(ulps(got, f(&want)) <= 2, "{}: {} against {}", text, got, f(&want));
        }
    }

    /// 0, 1 and −1 to exponents past i64 (written out, up to i128::MAX): by
    /// parity; any other base overflows or underflows, by its magnitude.
    #[test]
    fn powers_past_i64_go_by_parity_and_magnitude(
        e in (1u128 << 63)..=(i128::MAX as u128), base in 0usize..7, minus: bool,
    ) {
        let exp = if minus { format!("(-{e})") } else { e.to_string() };
        let odd = e & 1 == 1;
        let text = match base {
            0 => format!("0^{exp}"),
            1 => format!("1^{exp}"),
            2 => format!("(-1)^{exp}"),
            3 => format!("(1 + 1/1000000)^{exp}"),
            4 => format!("(-(1 + 1/1000000))^{exp}"),
            5 => format!("(1 - 1/1000000)^{exp}"),
            _ => format!("2.5^{exp}"),
        };
        match base {
            0 if minus => prop_assert!(error(&text).0.contains("division by zero")),
            0 => prop_assert_eq!(value(&text), 0.0),
            1 => prop_assert_eq!(value(&text), 1.0),
            2 => prop_assert_eq!(value(&text), if odd { -1.0 } else { 1.0 }),
            _ => {
                // |x| > 1 to a positive power, or < 1 to a negative one,
                // grows: n·|ln|x|| ≥ 2^63 · 1e-6 ≫ 710.
                let grows = (base == 5) == minus;
                let (m, _) = error(&text);
                prop_assert!(
                    m.contains(if grows { "overflows" } else { "underflows" }),
                    "{}: {}", text, m
                );
            }
        }
    }

    /// (1 + 1/m)^(c·m) with m past i64: e^c to within 2 ulps (the next
    /// terms of n·ln(1 + 1/m) are below c/(2m) < 1e-19).
    #[test]
    fn a_power_of_a_base_near_one_is_exp_of_n_ln_x(
        c in -40i64..40, k in 20u32..30, down: bool,
    ) {
        prop_assume!(c != 0);
        let m = format!("10^{k}");
        let text = format!(
            "(1 {} 1/{m})^({c} * {m})",
            if down { "-" } else { "+" }
        );
        let want = f64::exp(if down { -c } else { c } as f64);
        let got = value(&text);
        prop_assert!(ulps(got, want) <= 2, "{}: {} against {}", text, got, want);
    }

    /// A literal d·10^e: below the normal range it is "too small" at its
    /// token; above it, twice it is 2 × Rust's reading of it.
    #[test]
    fn tiny_literals_are_too_small_at_their_token(
        d in 1u32..10, e in -400i32..-300, pad in 0usize..4,
    ) {
        let lit = format!("{d}e{e}");
        let text = format!("{}2 * {lit}", " ".repeat(pad));
        let x: f64 = lit.parse().unwrap();
        if x < f64::MIN_POSITIVE {
            let (m, at) = error(&text);
            prop_assert!(m.contains("is too small"), "{}: {}", text, m);
            prop_assert_eq!(at, pad + 4..pad + 4 + lit.len());
        } else {
            prop_assert_eq!(value(&text), 2.0 * x);
        }
    }

    /// `count = "a/b*c"`: accepted iff exactly a whole number from 1 (the
    /// part and its copies, that many), by big rationals.
    #[test]
    fn a_count_is_accepted_iff_exactly_whole(
        a in 1i64..200, b in 1i64..50, c in 1i64..50, tiny: bool,
    ) {
        let expr = if tiny { format!("{a}/{b}*{c} + 1/10^30") } else { format!("{a}/{b}*{c}") };
        let mut want = Q::new(BigInt::from(a * c), BigInt::from(b));
        if tiny {
            want += Q::new(BigInt::one(), BigInt::from(10).pow(30));
        }
        let text = array(&format!("\"{expr}\""));
        let whole = want.is_integer() && want >= big(1);
        match Model::parse(&Source::new("f.toml", text.as_str())) {
            Ok(m) => {
                prop_assert!(whole, "{} accepted", expr);
                prop_assert_eq!(Q::from_integer(BigInt::from(m.count)), want);
            }
            Err(d) => {
                prop_assert!(!whole, "{} refused: {}", expr, d);
                prop_assert!(d.to_string().contains("`count` must be a whole number"), "{}", d);
            }
        }
    }

    /// A `--set` value that fails (by dimension, a division by zero, a
    /// tiny literal) is refused naming the flag and its value.
    #[test]
    fn set_errors_name_the_flag_and_its_value(kind in 0usize..4, k in 1u32..1000) {
        let value = match kind {
            0 => format!("{k} kg"),
            1 => format!("{k} m / 0"),
            2 => format!("{k}e-400 m"),
            _ => format!("{k} m * 2^(2^70)"),
        };
        let e = refused(&with_leg(), &[&format!("leg={value}")]);
        let flag = format!("`--set leg={value}`");
        prop_assert!(e.starts_with("--set leg:1:"), "{}", e);
        prop_assert!(e.contains(&flag), "{}", e);
    }
}

#[test]
fn the_big_rational_power_is_the_power() {
    // The reference itself: (−3/2)^−3 = −8/27, x^0 = 1.
    let x = Q::new(BigInt::from(-3), BigInt::from(2));
    assert_eq!(pow(&x, -3), Q::new(BigInt::from(-8), BigInt::from(27)));
    assert_eq!(pow(&x, 0), Q::one());
    assert!(pow(&Q::zero(), 5).is_zero());
}
