//! Fuzz the part-file parser, the composer and the checker: any text either
//! is rejected with a diagnostic or gives a summary whose JSON is finite and
//! valid, whose table renders, and whose `[expect]` messages print no
//! non-finite number; and wherever the fast path (`model::fast::parse`)
//! reads the text, serde (`toml::from_str::<RawFile>`) reads it too, to the
//! same values and spans. Panics, hangs and out-of-memory are the findings.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::Settings;
use massprop::analysis::check;
use massprop::compose::Precision;
use massprop::diag::Source;
use massprop::model::fast;
use massprop::model::raw::RawFile;
use massprop::render;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let source = Source::new("fuzz.toml", text);
    // As given, and as `Model::parse` gives it to the fast path (without a
    // byte-order mark).
    fast_path_agrees(text);
    if source.text != text {
        fast_path_agrees(&source.text);
    }
    for precision in [Precision::Standard, Precision::Extended] {
        // The pipeline every command runs: parse, resolve, compose.
        let settings = Settings {
            precision,
            ..Settings::default()
        };
        let loaded = match massprop::load_source(source.clone(), &settings) {
            Ok(loaded) => loaded,
            Err(d) => {
                // Rendering the diagnostic (snippet, carets) must not panic.
                let _ = d.to_string();
                return;
            }
        };
        let (model, summary) = (&loaded.model, &loaded.summary);
        let json = render::report::json(summary);
        let value: serde_json::Value = serde_json::from_str(&json)
            .unwrap_or_else(|e| panic!("JSON does not parse ({precision:?}): {e}\n{json}"));
        assert_no_null(&value, "", &json);
        let _ = render::report::table(summary, "fuzz.toml");
        let _ = check::validity(summary);
        for c in &model.expect {
            let r = check::evaluate(&source, summary, c);
            let message = render::check::message("fuzz.toml", &r);
            let words = message.split(|c: char| !c.is_ascii_alphanumeric());
            assert!(
                !words.into_iter().any(|w| w == "inf" || w == "NaN"),
                "non-finite number in a check message: {message}"
            );
        }
    }
});

/// src/model/fast.rs's promise: where `fast::parse` returns `Some`, serde
/// accepts the text too and gives the same `RawFile`, values and spans
/// (compared through `Debug`, as fast.rs's tests do: `RawFile` is not
/// `PartialEq`).
fn fast_path_agrees(text: &str) {
    let Some(fast) = fast::parse(text) else {
        return;
    };
    let serde = toml::from_str::<RawFile>(text)
        .unwrap_or_else(|e| panic!("the fast path reads a file that serde rejects: {e}"));
    assert_eq!(
        format!("{fast:?}"),
        format!("{serde:?}"),
        "the fast path and serde read the file differently"
    );
}

/// serde_json writes a non-finite f64 as `null` (it never writes `inf` or
/// `NaN`), so a finite summary has no `null` but where docs/json.md allows
/// one: the file's `name`, and the items of `principal_moment_share` and
/// `relative_change` (a zero moment). Part names are free text, so matching
/// "inf"/"NaN" in the string would give false alarms; the walk does not.
fn assert_no_null(v: &serde_json::Value, key: &str, json: &str) {
    use serde_json::Value;
    match v {
        Value::Null if matches!(key, "name" | "principal_moment_share" | "relative_change") => {}
        Value::Null => panic!("null under {key:?} in the JSON (a non-finite number):\n{json}"),
        Value::Array(a) => a.iter().for_each(|x| assert_no_null(x, key, json)),
        Value::Object(o) => o.iter().for_each(|(k, x)| assert_no_null(x, k, json)),
        Value::Number(n) => assert!(n.as_f64().is_some_and(f64::is_finite), "{n} under {key:?}"),
        _ => {}
    }
}
