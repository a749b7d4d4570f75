//! Fuzz expressions in quantity strings (`massprop::expr`) and `[params]`:
//! any text is either refused with an error inside it (its byte range
//! within the text) or evaluates to a finite value; the same text as a
//! parameter's definition and as a part's coordinate is refused with a
//! diagnostic that renders or read into a model; and an expression that
//! evaluates gives, in a file, the value `eval` gave. Panics, hangs (a
//! stack overflow, quadratic time) and out-of-memory are the findings.
//!
//! The expression edges (issue 28) are built from the same bytes too:
//! integer powers with exponents past i64 (written out, or as `2^k ± j`),
//! of bases at and near 0, ±1 and beyond, and literals near and below
//! f64's normal range. Whatever they are, a value accepted is finite and
//! not subnormal, and 0, 1 and −1 to an integer power exact in i128 are
//! 0, 1 and ±1 by its parity.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::diag::Source;
use massprop::expr::{Expr, Value};
use massprop::model::Model;
use massprop::units::Factor;

/// The bases the edges raise: at and near 0 and ±1, beyond, and tiny.
const BASES: &[&str] = &[
    "0",
    "1",
    "(-1)",
    "2",
    "(-2)",
    "0.5",
    "(1 + 1e-20)",
    "(-(1 + 1e-20))",
    "(1 - 1/10^30)",
    "1e-300",
    "(1/3)",
    "a",
];

/// An expression edge from `data`: a power of a base by an exponent
/// (written out up to 2^127, or `2^k + j`), times a literal `d·10^e`.
fn edge(data: &[u8]) -> Option<(String, Option<(usize, u128, bool)>)> {
    let (&b, rest) = data.split_first()?;
    let (&form, rest) = rest.split_first()?;
    let mut n = [0u8; 16];
    let take = rest.len().min(16);
    n[..take].copy_from_slice(&rest[..take]);
    let e = u128::from_le_bytes(n) >> (form % 4);
    let base = b as usize % BASES.len();
    let minus = form & 0x10 != 0;
    let sign = if minus { "-" } else { "" };
    let (exp, exact) = if form & 0x20 != 0 {
        let k = e % 400;
        let j = (e >> 16) % 5;
        (format!("({sign}(2^{k} + {j}))"), None)
    } else {
        (format!("({sign}{e})"), Some(e))
    };
    let lit = (form & 0x40 != 0).then(|| {
        let d = e % 9 + 1;
        let x = 290 + (e >> 8) % 120;
        format!(" * {d}e-{x}")
    });
    let text = format!("{}^{exp}{}", BASES[base], lit.clone().unwrap_or_default());
    Some((
        text,
        exact.filter(|_| lit.is_none()).map(|e| (base, e, minus)),
    ))
}

fuzz_target!(|data: &[u8]| {
    if let Some((text, exact)) = edge(data) {
        let a = Value::of_f64(0.7);
        let params = |n: &str| (n == "a").then_some(a);
        // A literal below f64's normal range is refused as it is read, at
        // its token; any other edge parses.
        let tiny = text.rsplit_once(" * ").and_then(|(_, lit)| {
            let x: f64 = lit.parse().ok()?;
            (x < f64::MIN_POSITIVE).then_some(text.len() - lit.len()..text.len())
        });
        let expr = match (Expr::parse(&text), tiny) {
            (Ok(expr), None) => expr,
            (Err(e), Some(at)) => {
                assert_eq!(e.at, at, "{text:?}: {e:?}");
                assert!(e.message.contains("too small"), "{text:?}: {e:?}");
                return;
            }
            (r, _) => panic!("{text:?}: {r:?}"),
        };
        match expr.eval(&params, &|| vec!["a".to_string()]) {
            Err(e) => assert!(e.at.end <= text.len(), "{e:?}"),
            Ok(v) => {
                let x = v.in_units(Factor::ONE);
                assert!(x.is_finite(), "{text:?} gave {x}");
                assert!(
                    x == 0.0 || x.abs() >= f64::MIN_POSITIVE,
                    "{text:?} gave {x}"
                );
                if let Some((base, e, minus)) = exact {
                    let want = match (base, minus) {
                        (0, _) => Some(0.0),
                        (1, _) => Some(1.0),
                        (2, _) => Some(if e & 1 == 1 { -1.0 } else { 1.0 }),
                        _ => None,
                    };
                    if let Some(want) = want {
                        assert_eq!(x, want, "{text:?}");
                    }
                }
            }
        }
    }
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let a = Value::of_f64(0.7);
    match Expr::parse(text) {
        Err(e) => assert!(e.at.start <= e.at.end && e.at.end <= text.len(), "{e:?}"),
        Ok(expr) => {
            let params = |n: &str| (n == "a").then_some(a);
            match expr.eval(&params, &|| vec!["a".to_string()]) {
                Err(e) => assert!(e.at.end <= text.len(), "{e:?}"),
                Ok(v) => {
                    let x = v.in_units(Factor::ONE);
                    assert!(x.is_finite(), "{text:?} gave {x}");
                }
            }
        }
    }
    // In a file: a parameter defined by the text, used by a coordinate,
    // and the text itself as a coordinate (a literal string, so that any
    // text but a `'` or a line end is one).
    if text.contains(['\'', '\n', '\r']) {
        return;
    }
    let file = format!(
        "[params]\na = 0.7\nb = '{text}'\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = ['{text}', 'b', 0]\n"
    );
    let source = Source::new("f.toml", file);
    match Model::parse(&source) {
        Err(d) => {
            let _ = d.to_string();
        }
        Ok(m) => assert_eq!(m.count, 1),
    }
});
