//! massprop as a library: `summarize` and `summarize_str`, the one entry
//! point, give what the command gives, and errors as fields.

use massprop::{Settings, summarize, summarize_str};

/// The summary of a file is the command's JSON report of it, key for key.
#[test]
fn summarize_gives_what_report_prints() {
    for file in ["shapes/robot-arm.toml", "shapes/flywheel.toml"] {
        let summary = summarize(file, &Settings::default()).unwrap();
        let out = crate::common::massprop(&["report", file, "--format", "json"]);
        assert_eq!(out.status.code(), Some(0));
        let printed: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(serde_json::to_value(&summary).unwrap(), printed, "{file}");
    }
}

/// A rod from text: m L²/12 across it, nothing along it; includes resolve
/// against the name's directory.
#[test]
fn summarize_str_reads_text_and_resolves_includes_beside_its_name() {
    let rod = "[[part]]\nshape = \"rod\"\nmass = 3\nfrom = [0, 0, 0]\nto = [2, 0, 0]\n";
    let s = summarize_str("rod.toml", rod, &Settings::default()).unwrap();
    assert_eq!(s.mass, 3.0);
    assert_eq!(s.center_of_mass, [1.0, 0.0, 0.0]);
    let across = 3.0 * 4.0 / 12.0;
    assert!((s.inertia_com[2][2] - across).abs() <= 4.0 * f64::EPSILON * across);
    assert_eq!(s.inertia_com[0][0], 0.0);
    let arm = std::fs::read_to_string("shapes/robot-arm.toml").unwrap();
    let from_text = summarize_str("shapes/robot-arm.toml", &arm, &Settings::default()).unwrap();
    let from_file = summarize("shapes/robot-arm.toml", &Settings::default()).unwrap();
    assert_eq!(from_text.mass, from_file.mass);
    assert_eq!(from_text.inertia_com, from_file.inertia_com);
    // Named elsewhere, its include is not found.
    let e = summarize_str("elsewhere/arm.toml", &arm, &Settings::default()).unwrap_err();
    assert!(e.message().contains("motor-bracket.toml"), "{e}");
}

#[test]
fn an_error_gives_its_place_and_message_as_fields_and_renders_as_the_command_does() {
    let text = "[[part]]\nshape = \"box\"\nmass = 1\nsizee = [1, 2, 3]\n";
    let e = summarize_str("bad.toml", text, &Settings::default()).unwrap_err();
    let place = e.place().unwrap();
    assert_eq!(place.path, "bad.toml");
    let span = place.span.unwrap();
    assert_eq!(
        (span.line, span.column, span.end_line, span.end_column),
        (4, 1, 4, 5)
    );
    assert_eq!(e.message(), "unknown key `sizee`");
    assert_eq!(e.label_text(), Some("did you mean `size`?"));
    let out = crate::common::massprop_stdin(&["report", "-"], text);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr, e.to_string().replace("bad.toml", "<stdin>"));
}
