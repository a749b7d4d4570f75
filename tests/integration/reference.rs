//! `massprop help part-file` and the man page carry the part-file
//! reference, made from the registries (issue 31 item 6): every shape and
//! every declared key appears, checked over the registries themselves, not
//! a pasted list, so a key added to them is checked too.

use crate::common::massprop;

/// The stdout of `args`, which must succeed.
fn stdout(args: &[&str]) -> String {
    let out = massprop(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// Every part key the schema declares (made from the key registry).
fn declared_part_keys() -> Vec<String> {
    let schema: serde_json::Value = serde_json::from_str(&stdout(&["schema"])).expect("JSON");
    let keys: Vec<String> = schema["$defs"]["Part"]["properties"]
        .as_object()
        .expect("the part's keys")
        .keys()
        .cloned()
        .collect();
    assert!(keys.len() > 30, "{keys:?}");
    keys
}

/// `text` names `word` as a line's entry (`  word: …`).
fn has_entry(text: &str, word: &str) -> bool {
    text.lines()
        .any(|l| l.trim_start().starts_with(&format!("{word}:")))
}

#[test]
fn help_part_file_names_every_shape_of_the_registry() {
    let text = stdout(&["help", "part-file"]);
    for s in massprop::shapes::SHAPES.iter() {
        assert!(has_entry(&text, s.name), "{}", s.name);
        for key in s.keys {
            assert!(text.contains(key), "{}: {key}", s.name);
        }
    }
}

#[test]
fn help_part_file_names_every_declared_part_key() {
    let text = stdout(&["help", "part-file"]);
    for key in declared_part_keys() {
        assert!(has_entry(&text, &key), "{key}");
    }
}

#[test]
fn help_part_file_names_every_expect_key_and_built_in_material() {
    let text = stdout(&["help", "part-file"]);
    for q in massprop::quantity::QUANTITIES.iter().filter(|q| q.expected) {
        assert!(has_entry(&text, q.key), "{}", q.key);
    }
    for m in massprop::materials::BUILT_IN {
        assert!(text.contains(m.name), "{}", m.name);
    }
}

#[test]
fn the_man_page_carries_every_shape_and_declared_part_key() {
    // roff escapes a hyphen as `\-`.
    let man = stdout(&["man"]).replace("\\-", "-");
    assert!(man.contains(".SH \"PART FILE\""));
    for s in massprop::shapes::SHAPES.iter() {
        assert!(has_entry(&man, s.name), "{}", s.name);
    }
    for key in declared_part_keys() {
        assert!(has_entry(&man, &key), "{key}");
    }
}

#[test]
fn help_for_a_command_is_still_clap_s() {
    let text = stdout(&["help", "report"]);
    assert!(text.starts_with("Report mass"), "{text}");
    assert!(text.contains("Usage: massprop report"));
}
