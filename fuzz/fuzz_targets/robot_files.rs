//! Fuzz the robot description readers, the engines' rules, check's
//! renderers and the in-place update: any text, read as URDF, SDFormat and
//! MJCF (`robot::read::read`), is either refused with a diagnostic that
//! renders, or checked under every engine (`robot::check::check`) and
//! rendered as check's JSON (every number finite; `null` only for a rule's
//! `margin`, a link's `inertial` and an engine's `cause`), table (no `inf`
//! or `NaN` unless the text has the word), GitHub annotations, JUnit and
//! SARIF. And `output::inertial::update` of a fixed export into each of its
//! links either fails, with a place inside the text, or gives a text that
//! reads back with that link's inertial replaced (to the bit) and every
//! other link as it was. Neither reads a document with a reference to an
//! entity its doctype declares (`&m;`): the simulators' XML reader
//! (tinyxml2) does not expand it, roxmltree does, and an independent
//! reading of the values' bytes (`uses_declared_entity`) says which.
//! Panics, hangs and out-of-memory are the findings.
#![no_main]

use libfuzzer_sys::fuzz_target;
use massprop::analysis::check::{FileResult, Status};
use massprop::diag::Source;
use massprop::output::inertial::{Export, update};
use massprop::output::{Style, check, ci};
use massprop::robot::engine::Engine;
use massprop::robot::{Description, Dialect, Inertial, Tensor};
use serde_json::Value;

/// What every update writes: numbers no short decimal holds, one with an
/// exponent, a zero.
const EXPORT: Export = Export {
    mass: 1.0 / 3.0,
    pos: [0.30000000000000004, -2.5e-7, 0.0],
    tensor: Tensor {
        xx: 2.0 / 3.0,
        yy: 0.7,
        zz: 1.4285714285714285e-10,
        xy: -0.14285714285714285,
        xz: 0.0,
        yz: 3e-20,
    },
    principal: None,
};

/// At most this many links are updated per input and format.
const UPDATES: usize = 4;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let _ = Dialect::of_text(text);
    // A number word in the input may be quoted back (a name, a note, a
    // diagnostic's snippet), also with the controls between its letters
    // dropped (JUnit drops a tab from the snippet it quotes).
    let bare: String = text.chars().filter(|c| !c.is_control()).collect();
    let quiet = non_finite_word(text).is_none() && non_finite_word(&bare).is_none();
    let entity = uses_declared_entity(text);
    for format in [Dialect::Urdf, Dialect::Sdf, Dialect::Mjcf] {
        let source = Source::new("fuzz.xml", text);
        match massprop::robot::read::read(&source, format) {
            Ok(d) => {
                assert!(
                    !entity,
                    "read a document that uses an entity of its doctype"
                );
                checked(&source, &d, format, quiet);
                updated(&source, &d, format);
            }
            Err(e) => {
                let _ = e.render(false);
                let r = FileResult {
                    error: Some(e),
                    ..result(format, Status::Invalid, None)
                };
                rendered(&[r], quiet);
            }
        }
    }
});

fn result(
    format: Dialect,
    status: Status,
    robot: Option<massprop::robot::check::RobotResult>,
) -> FileResult {
    FileResult {
        path: "fuzz.xml".to_string(),
        status,
        error: None,
        checks: Vec::new(),
        validity: Vec::new(),
        precision: None,
        accuracy_warnings: Vec::new(),
        warnings: Vec::new(),
        robot,
        format: Some(format),
    }
}

/// Check under each engine alone and all together, and render.
fn checked(source: &Source, d: &Description, format: Dialect, quiet: bool) {
    for engines in [
        &Engine::ALL[..],
        &[Engine::Mujoco],
        &[Engine::Gazebo],
        &[Engine::Drake],
    ] {
        let r = massprop::robot::check::check(source, d, engines);
        assert_eq!(r.links.len(), d.links.len());
        let status = if r.failed() {
            Status::Failed
        } else {
            Status::Ok
        };
        rendered(&[result(format, status, Some(r))], quiet);
    }
}

/// check's JSON, table and CI formats of `results`.
fn rendered(results: &[FileResult], quiet: bool) {
    let json: Value = serde_json::from_str(&check::json(results)).expect("check's JSON parses");
    walk(&json, "", "$");
    for text in [
        check::table(
            results,
            0,
            Style {
                colour: false,
                width: None,
            },
        ),
        check::table(
            results,
            0,
            Style {
                colour: true,
                width: Some(60),
            },
        ),
        ci::github(results, 0),
        ci::junit(results),
        ci::sarif(results),
    ] {
        if quiet && let Some(w) = non_finite_word(&text) {
            panic!("{w:?} printed:\n{text}");
        }
    }
}

/// Keys whose value may be `null` in check's JSON of a robot description.
const MAY_BE_NULL: &[&str] = &["margin", "inertial", "cause"];

fn walk(v: &Value, key: &str, path: &str) {
    match v {
        Value::Null => assert!(MAY_BE_NULL.contains(&key), "null at {path}"),
        Value::Number(n) => assert!(
            n.as_f64().is_some_and(f64::is_finite),
            "non-finite {n} at {path}"
        ),
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                walk(item, key, &format!("{path}[{i}]"));
            }
        }
        Value::Object(map) => {
            for (k, item) in map {
                walk(item, k, &format!("{path}.{k}"));
            }
        }
        Value::Bool(_) | Value::String(_) => {}
    }
}

/// A word that means a non-finite number was printed.
fn non_finite_word(text: &str) -> Option<String> {
    if text.contains('∞') {
        return Some("∞".to_string());
    }
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .find(|w| {
            let w = w.to_ascii_lowercase();
            w == "inf" || w == "infinity" || w == "nan"
        })
        .map(str::to_string)
}

/// What a link is but for where its bytes are.
fn values(i: &Inertial) -> (f64, [f64; 3], Option<[[f64; 3]; 3]>, Tensor) {
    (i.mass, i.pos, i.rotation, i.tensor)
}

/// Update each of the first links (by name, once each) and read back.
fn updated(source: &Source, d: &Description, format: Dialect) {
    let mut names: Vec<&str> = d.links.iter().map(|l| l.name.as_str()).collect();
    names.dedup();
    names.truncate(UPDATES);
    for name in names {
        let new = match update(&source.text, format, name, &EXPORT) {
            Ok(new) => {
                assert!(
                    !uses_declared_entity(&source.text),
                    "updated a document that uses an entity of its doctype"
                );
                new
            }
            Err(e) => {
                assert!(!e.to_string().is_empty());
                if let Some(at) = e.at() {
                    assert!(at <= source.text.len(), "{e:?} past the text");
                }
                continue;
            }
        };
        let after = Source::new("fuzz.xml", new.as_str());
        let back = match massprop::robot::read::read(&after, format) {
            Ok(back) => back,
            Err(e) => panic!(
                "updating {name:?} gave a file that does not read back: {e}\n--- after ---\n{new}"
            ),
        };
        assert_eq!(back.links.len(), d.links.len(), "{name:?}:\n{new}");
        let mut replaced = 0;
        for (a, b) in d.links.iter().zip(&back.links) {
            assert_eq!(
                (&a.name, a.moving, a.parent),
                (&b.name, b.moving, b.parent),
                "{name:?}:\n{new}"
            );
            let (va, vb) = (
                a.inertial.as_ref().map(values),
                b.inertial.as_ref().map(values),
            );
            if a.name == name {
                replaced += 1;
                let vb = vb.unwrap_or_else(|| panic!("{name:?} has no inertial after:\n{new}"));
                assert_eq!(
                    vb,
                    (EXPORT.mass, EXPORT.pos, None, EXPORT.tensor),
                    "{name:?}:\n{new}"
                );
            } else {
                assert_eq!(va, vb, "{name:?} changed {:?}:\n{new}", a.name);
            }
        }
        assert_eq!(replaced, 1, "{name:?}:\n{new}");
    }
}

/// Whether the document of `text` (as roxmltree reads it, the doctype's
/// entities expanded) has an attribute value or a text whose bytes hold a
/// reference other than XML's five (`&lt;` `&gt;` `&amp;` `&apos;`
/// `&quot;`) and character references: an entity of the doctype, which
/// tinyxml2 would read as written.
fn uses_declared_entity(text: &str) -> bool {
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let Ok(doc) = roxmltree::Document::parse_with_options(text, options) else {
        return false;
    };
    doc.descendants().any(|n| {
        n.attributes().any(|a| references(&text[a.range_value()]))
            || (n.is_text() && references(&without_cdata(&text[n.range()])))
    })
}

/// Whether `raw` (an attribute value's or a text's bytes) holds a
/// reference to an entity other than XML's five.
fn references(raw: &str) -> bool {
    raw.split('&').skip(1).any(|r| {
        let name = r.split(';').next().unwrap_or("");
        !name.starts_with('#') && !["lt", "gt", "amp", "apos", "quot"].contains(&name)
    })
}

/// A text's bytes without its CDATA sections, whose `&` is a character.
fn without_cdata(raw: &str) -> String {
    let mut out = String::new();
    let mut rest = raw;
    while let Some(i) = rest.find("<![CDATA[") {
        out.push_str(&rest[..i]);
        rest = rest[i..].find("]]>").map_or("", |e| &rest[i + e + 3..]);
    }
    out.push_str(rest);
    out
}
