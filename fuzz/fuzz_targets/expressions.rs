//! Fuzz expressions in quantity strings (`massprop::expr`) and `[params]`:
//! any text is either refused with an error inside it (its byte range
//! within the text) or evaluates to a finite value; the same text as a
//! parameter's definition and as a part's coordinate is refused with a
//! diagnostic that renders or read into a model; and an expression that
//! evaluates gives, in a file, the value `eval` gave. Panics, hangs (a
//! stack overflow, quadratic time) and out-of-memory are the findings.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::diag::Source;
use massprop::expr::{Expr, Value};
use massprop::model::Model;
use massprop::units::Factor;

fuzz_target!(|data: &[u8]| {
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
