//! `check`'s results in the formats CI systems read (docs/ci.md):
//!
//! - `github`: GitHub Actions workflow commands, `::error file=…,line=…::…`,
//!   one per failure, which the runner turns into annotations on the diff;
//! - `junit`: JUnit XML as cargo-nextest writes it (`output::junit`,
//!   byte for byte what its crate, quick-junit, writes): a test suite per file, a test case per expectation and
//!   validity check;
//! - `sarif`: SARIF 2.1.0, for code scanning.
//!
//! Each reports the same things: every failed expectation at its `[expect]`
//! entry, a predicted mass over `[budget] limit` at the `limit` entry, every failed validity check on its file, every invalid file at its
//! error's span, every value not certified to `--rtol` as a warning, and
//! for a robot description each link an engine refuses, at its
//! `<inertial>`, with the likely cause (one GitHub annotation and one SARIF
//! result per link, naming every engine that refuses it; a JUnit test case
//! per link and engine), and each link's warnings.

use super::check::{failure, message};
use super::robot;
use crate::analysis::check::{Against, CheckResult, FileResult};
use crate::analysis::summary::MASSPROP_VERSION;
use crate::diag::{Diagnostic, Span, visible};
use serde_json::{Value, json};

/// An annotation's title names the tool, so a reader of the pull request
/// knows where it came from.
const TITLE: &str = "massprop check";

/// A diagnostic's whole text for a single message: the message, then its
/// label, help and notes, each on a line of its own; each piece shown by
/// `visible`, so a newline from input is a picture, as on standard error,
/// and only these lines are lines.
fn diagnostic_text(d: &Diagnostic) -> String {
    let mut text = visible(d.message());
    if let Some(label) = d.label_text() {
        text.push_str(&format!("\n{}", visible(label)));
    }
    if let Some(help) = d.help_text() {
        text.push_str(&format!("\nhelp: {}", visible(help)));
    }
    for note in d.notes() {
        text.push_str(&format!("\nnote: {}", visible(note)));
    }
    text
}

/// A path as the CI system matches it against the repository's files:
/// without the `./` that searching `.` puts before each.
/// A file a robot includes is named through the directories of the files
/// that include it (`models/cart/../wheel/model.sdf`): each `DIR/..` is
/// taken out, as the runner matches a path with none. NOTE: lexically (a
/// symlinked DIR aside): the annotation names the repository's path.
fn repo_path(path: &str) -> String {
    let path = path.strip_prefix("./").unwrap_or(path);
    if !path.contains("/../") {
        return path.to_string();
    }
    let mut parts: Vec<&str> = Vec::new();
    for part in path.split('/') {
        match (part, parts.last()) {
            ("..", Some(&last)) if last != ".." && !last.is_empty() => {
                parts.pop();
            }
            _ => parts.push(part),
        }
    }
    parts.join("/")
}

/// Where a diagnostic points: its file (the file checked when it has no
/// place of its own, or an include's) and its span.
/// (The rule of check's JSON, `JsonError::of`.)
fn place<'a>(d: &'a Diagnostic, r: &'a FileResult) -> (&'a str, Option<Span>) {
    let e = super::check::JsonError::of(d, &r.path);
    (e.path, e.span)
}

/// A link's failures as one annotation (issue 31, item 4: one per link,
/// not one per engine): the engines that refuse it (`mujoco, drake`) and
/// each one's message, a line each; None when every engine accepts it.
fn link_failures(l: &crate::robot::check::LinkResult) -> Option<(String, String)> {
    let refused: Vec<_> = l.engines.iter().filter(|e| !e.verdict.valid).collect();
    if refused.is_empty() {
        return None;
    }
    let names: Vec<&str> = refused.iter().map(|e| e.verdict.engine.name()).collect();
    let text: Vec<String> = refused
        .iter()
        .map(|e| visible(&robot::failure(l, e)))
        .collect();
    Some((names.join(", "), text.join("\n") + &included(l)))
}

/// A link of an included file: where its file is included from, as a
/// diagnostic's notes say it (`diagnostic_text`); empty in the main file.
fn included(l: &crate::robot::check::LinkResult) -> String {
    l.included_from
        .iter()
        .map(|site| format!("\nnote: included from {}", visible(site)))
        .collect()
}

/// GitHub Actions workflow commands (`::error …::message`), one per failure
/// (one per link a robot's engines refuse) and warning, then the summary
/// line as a plain log line.
pub fn github(results: &[FileResult], skipped: usize) -> String {
    // The runner's own escaping (actions/toolkit, `command.ts`): data
    // escapes `%`, CR and LF; a property also `:` and `,`.
    fn data(s: &str) -> String {
        s.replace('%', "%25")
            .replace('\r', "%0D")
            .replace('\n', "%0A")
    }
    fn property(s: &str) -> String {
        data(s).replace(':', "%3A").replace(',', "%2C")
    }
    fn command(level: &str, path: &str, span: Option<Span>, title: &str, text: &str) -> String {
        let mut props = format!("file={}", property(&visible(&repo_path(path))));
        if let Some(s) = span {
            props.push_str(&format!(
                ",line={},col={},endLine={},endColumn={}",
                s.line, s.column, s.end_line, s.end_column
            ));
        }
        props.push_str(&format!(
            ",title={}",
            property(&format!("{TITLE}: {title}"))
        ));
        format!("::{level} {props}::{}\n", data(text))
    }
    let mut out = String::new();
    for r in results {
        if let Some(d) = &r.error {
            let (path, span) = place(d, r);
            let title = match r.format {
                Some(_) => "invalid robot description",
                None => "invalid part file",
            };
            out.push_str(&command("error", path, span, title, &diagnostic_text(d)));
        }
        for v in &r.validity {
            if let Some(m) = &v.failure {
                out.push_str(&command(
                    "error",
                    &r.path,
                    None,
                    &visible(&v.name),
                    &visible(m),
                ));
            }
        }
        for c in r.checks.iter().filter(|c| !c.pass) {
            let span = c.span();
            let text = visible(&failure(c));
            out.push_str(&command(
                "error",
                &r.path,
                Some(span),
                &visible(&c.label()),
                &text,
            ));
        }
        for w in &r.accuracy_warnings {
            out.push_str(&command(
                "warning",
                &r.path,
                None,
                "accuracy",
                &visible(&w.message),
            ));
        }
        for w in &r.warnings {
            let text = visible(&w.message);
            out.push_str(&command(
                "warning",
                &w.path,
                Some(w.span),
                "plausibility",
                &text,
            ));
        }
        for l in r.robot.iter().flat_map(|robot| &robot.links) {
            if let Some((engines, text)) = link_failures(l) {
                let title = format!("link {} under {engines}", visible(&l.name));
                out.push_str(&command(
                    "error",
                    l.path(&r.path),
                    Some(l.span),
                    &title,
                    &text,
                ));
            }
            for w in &l.warnings {
                let title = format!("link {}", visible(&l.name));
                let text = visible(&robot::warning(l, w)) + &included(l);
                out.push_str(&command(
                    "warning",
                    l.path(&r.path),
                    Some(l.span),
                    &title,
                    &text,
                ));
            }
        }
    }
    out.push_str(&super::check::summary_line(results, skipped));
    out
}

/// JUnit XML: the report `massprop check`, a test suite per file (named by
/// its path), in it a test case `valid part file`, one per expectation
/// (named by its key) and one per validity check (`validity: …`). A failed
/// expectation or validity check is a `<failure>`, an invalid file an
/// `<error>`; values not certified to `--rtol` go to the suite's
/// `<system-err>`.
pub fn junit(results: &[FileResult]) -> String {
    use super::junit::{Case, Report, Status, Suite, write};
    let failed = |error, ty: &str, message: &str, description: &str| Status::NonSuccess {
        error,
        ty: ty.to_string(),
        message: message.to_string(),
        description: description.to_string(),
    };
    let mut report = Report {
        name: TITLE.to_string(),
        suites: Vec::new(),
    };
    for r in results {
        let path = visible(&r.path);
        let mut cases = Vec::new();
        let case = |name: &str, status| Case {
            name: name.to_string(),
            classname: path.clone(),
            status,
        };
        let valid = match &r.error {
            Some(d) => failed(true, "invalid", &visible(d.message()), &d.to_string()),
            None => Status::Success,
        };
        let valid_name = match r.format {
            Some(f) => format!("valid {} file", f.name()),
            None => "valid part file".to_string(),
        };
        cases.push(case(&valid_name, valid));
        for l in r.robot.iter().flat_map(|robot| &robot.links) {
            for e in &l.engines {
                let status = if e.verdict.valid {
                    Status::Success
                } else {
                    let text = visible(&robot::failure(l, e));
                    failed(
                        false,
                        "inertial",
                        &text,
                        &format!(
                            "{}:{}:{}: error: {text}{}",
                            visible(l.path(&r.path)),
                            l.span.line,
                            l.span.column,
                            included(l)
                        ),
                    )
                };
                let name = format!("link {}: {}", visible(&l.name), e.verdict.engine.name());
                cases.push(case(&name, status));
            }
        }
        for c in &r.checks {
            let status = if c.pass {
                Status::Success
            } else {
                failed(
                    false,
                    rule_of(c),
                    &visible(&failure(c)),
                    &visible(&message(&r.path, c)),
                )
            };
            cases.push(case(&visible(&c.label()), status));
        }
        for v in &r.validity {
            let status = match &v.failure {
                None => Status::Success,
                Some(m) => failed(
                    false,
                    "validity",
                    &visible(m),
                    &format!("{path}: error: {}", visible(m)),
                ),
            };
            cases.push(case(&format!("validity: {}", visible(&v.name)), status));
        }
        let mut warnings: String = r
            .accuracy_warnings
            .iter()
            .map(|w| format!("warning: {path}: {}\n", visible(&w.message)))
            .collect();
        for w in &r.warnings {
            warnings.push_str(&format!(
                "warning: {path}:{}:{}: {}\n",
                w.span.line,
                w.span.column,
                visible(&w.message)
            ));
        }
        for l in r.robot.iter().flat_map(|robot| &robot.links) {
            for w in &l.warnings {
                let text = visible(&robot::warning(l, w));
                warnings.push_str(&format!(
                    "warning: {}:{}:{}: {text}{}\n",
                    visible(l.path(&r.path)),
                    l.span.line,
                    l.span.column,
                    included(l)
                ));
            }
        }
        report.suites.push(Suite {
            name: path.clone(),
            cases,
            system_err: (!warnings.is_empty()).then_some(warnings),
        });
    }
    write(&report)
}

/// A failed check's rule (SARIF's `ruleId`, JUnit's failure `type`).
fn rule_of(c: &CheckResult) -> &'static str {
    match c.against {
        Against::Expect => "expectation",
        Against::BudgetLimit => "budget-limit",
    }
}

/// The rules a SARIF result names (`ruleId`), in `ruleIndex` order.
const RULES: [(&str, &str); 8] = [
    (
        "expectation",
        "A value computed from the part file is outside its [expect] entry's tolerance or bounds",
    ),
    (
        "validity",
        "The body is not physical: mass not positive, inertia not positive definite, or the triangle inequality broken",
    ),
    (
        "invalid-file",
        "The part file cannot be read or is not valid",
    ),
    (
        "accuracy",
        "A value's rigorous error bound exceeds --rtol in the arithmetic used",
    ),
    (
        "inertial",
        "A robot description's inertial breaks a simulator's rule (MuJoCo, Gazebo, Drake)",
    ),
    (
        "inertial-warning",
        "A robot description's inertial looks wrong (mirrored links whose products disagree, a duplicate name, no inertial)",
    ),
    (
        "budget-limit",
        "The predicted mass (basic mass and growth) exceeds the part file's [budget] limit",
    ),
    (
        "plausibility",
        "A part file's numbers look written in other units than it says (a body over 100 m or 100 t without units, a density outside 1-25,000 kg/m3)",
    ),
];

/// SARIF 2.1.0: one run of the tool `massprop`, a result per failure and
/// warning. Columns count Unicode code points (`columnKind`), as massprop's
/// do; a region's `endColumn` is the column after its last character.
pub fn sarif(results: &[FileResult]) -> String {
    fn rule(id: &str) -> usize {
        RULES
            .iter()
            .position(|(r, _)| *r == id)
            .expect("invariant: every result names one of RULES")
    }
    fn result(id: &str, level: &str, text: &str, path: &str, span: Option<Span>) -> Value {
        let mut location = json!({ "artifactLocation": { "uri": uri(&repo_path(path)) } });
        if let Some(s) = span {
            location["region"] = json!({
                "startLine": s.line,
                "startColumn": s.column,
                "endLine": s.end_line,
                "endColumn": s.end_column + 1,
            });
        }
        json!({
            "ruleId": id,
            "ruleIndex": rule(id),
            "level": level,
            "message": { "text": text },
            "locations": [{ "physicalLocation": location }],
        })
    }
    let mut out = Vec::new();
    for r in results {
        if let Some(d) = &r.error {
            let (path, span) = place(d, r);
            out.push(result(
                "invalid-file",
                "error",
                &diagnostic_text(d),
                path,
                span,
            ));
        }
        for m in r.validity_failures() {
            out.push(result("validity", "error", &visible(m), &r.path, None));
        }
        for c in r.checks.iter().filter(|c| !c.pass) {
            let span = c.span();
            let text = visible(&failure(c));
            out.push(result(rule_of(c), "error", &text, &r.path, Some(span)));
        }
        for w in &r.accuracy_warnings {
            let text = visible(&w.message);
            out.push(result("accuracy", "warning", &text, &r.path, None));
        }
        for w in &r.warnings {
            let text = visible(&w.message);
            out.push(result(
                "plausibility",
                "warning",
                &text,
                &w.path,
                Some(w.span),
            ));
        }
        for l in r.robot.iter().flat_map(|robot| &robot.links) {
            if let Some((_, text)) = link_failures(l) {
                out.push(result(
                    "inertial",
                    "error",
                    &text,
                    l.path(&r.path),
                    Some(l.span),
                ));
            }
            for w in &l.warnings {
                let text = visible(&robot::warning(l, w)) + &included(l);
                out.push(result(
                    "inertial-warning",
                    "warning",
                    &text,
                    l.path(&r.path),
                    Some(l.span),
                ));
            }
        }
    }
    let rules: Vec<Value> = RULES
        .iter()
        .map(|(id, text)| json!({ "id": id, "shortDescription": { "text": text } }))
        .collect();
    super::json_line(&json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": { "driver": {
                "name": "massprop",
                "version": MASSPROP_VERSION,
                "rules": rules,
            }},
            "columnKind": "unicodeCodePoints",
            "results": out,
        }],
    }))
}

/// A path as a relative URI reference (RFC 3986): every byte of the name
/// but the unreserved ones and `/` percent-encoded, so a space or `#` in a
/// name does not end or change the reference; `path` is the name as
/// `display_path` showed it, read back to the name's own bytes
/// (`path_bytes`), so a name that is not UTF-8 gives its bytes, not the
/// `\xNN` that shows them.
fn uri(path: &str) -> String {
    let mut out = String::new();
    for b in crate::diag::path_bytes(path) {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(char::from(b))
            }
            _ => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::check::{Status, Validity};

    #[test]
    fn a_path_through_an_including_files_directory_is_the_repositorys() {
        assert_eq!(
            repo_path("./models/cart/../wheel/m.sdf"),
            "models/wheel/m.sdf"
        );
        assert_eq!(repo_path("a/b/../../c/../d.sdf"), "d.sdf");
        assert_eq!(repo_path("../up/x.sdf"), "../up/x.sdf");
        assert_eq!(repo_path("a/../../x.sdf"), "../x.sdf");
    }

    /// A file whose body breaks the triangle inequality (the reader refuses
    /// such files, so this is built by hand): each format reports it on
    /// the file, with the check's name.
    #[test]
    fn a_failed_validity_check_is_reported_on_its_file() {
        let r = FileResult {
            path: "a,b:c.toml".into(),
            status: Status::Failed,
            error: None,
            checks: Vec::new(),
            validity: vec![
                Validity {
                    name: "mass is positive".into(),
                    failure: None,
                },
                Validity {
                    name: "triangle inequality".into(),
                    failure: Some("I1 + I2 = 2 < I3 = 5".into()),
                },
            ],
            precision: None,
            accuracy_warnings: Vec::new(),
            warnings: Vec::new(),
            robot: None,
            format: None,
        };
        let results = [r];
        assert_eq!(
            github(&results, 0),
            "::error file=a%2Cb%3Ac.toml,title=massprop check%3A triangle inequality::I1 + I2 = 2 < I3 = 5\nchecked 1 file: 0 ok, 1 failed, 0 invalid\n"
        );
        let xml = junit(&results);
        assert!(
            xml.contains(r#"<testcase name="validity: mass is positive" classname="a,b:c.toml"/>"#),
            "{xml}"
        );
        assert!(
            xml.contains(r#"<failure message="I1 + I2 = 2 &lt; I3 = 5" type="validity">"#),
            "{xml}"
        );
        let sarif: serde_json::Value = serde_json::from_str(&sarif(&results)).unwrap();
        let result = &sarif["runs"][0]["results"][0];
        assert_eq!(result["ruleId"], "validity");
        assert_eq!(
            result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            "a%2Cb%3Ac.toml"
        );
        assert!(
            result["locations"][0]["physicalLocation"]
                .get("region")
                .is_none()
        );
    }

    /// Characters XML 1.0 forbids or a reader acts on, and the markup's
    /// own: a text of them is the worst a name, a path or a message can be.
    const HOSTILE: &[char] = &[
        '\0',
        '\u{1}',
        '\u{8}',
        '\t',
        '\n',
        '\u{b}',
        '\u{c}',
        '\r',
        '\u{1b}',
        '\u{1f}',
        '\u{7f}',
        '\u{80}',
        '\u{85}',
        '\u{9b}',
        '\u{9f}',
        '\u{202e}',
        '\u{2066}',
        '\u{2028}',
        '\u{2029}',
        '\u{fffe}',
        '\u{ffff}',
        '\u{feff}',
        '\u{10ffff}',
        '<',
        '>',
        '&',
        '"',
        '\'',
        ']',
        '-',
        ':',
        ',',
        '%',
        '=',
        ' ',
        'a',
        'é',
    ];

    fn hostile() -> impl proptest::strategy::Strategy<Value = String> {
        use proptest::prelude::*;
        prop::collection::vec(prop::sample::select(HOSTILE), 0..24)
            .prop_map(|c| c.into_iter().collect())
    }

    /// A file with every kind of text from input: its path, an error's
    /// message, label, help and note, a validity failure.
    fn hostile_result(path: &str, message: &str, other: &str) -> FileResult {
        let source = crate::diag::Source::new(path, format!("a = 1 # {other}\n"));
        FileResult {
            path: path.to_string(),
            status: Status::Invalid,
            error: Some(
                source
                    .error(0..1, message)
                    .label(other)
                    .help(other)
                    .note(other),
            ),
            checks: Vec::new(),
            validity: vec![Validity {
                name: "triangle inequality".into(),
                failure: Some(other.to_string()),
            }],
            precision: None,
            accuracy_warnings: Vec::new(),
            warnings: Vec::new(),
            robot: None,
            format: None,
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config {
            cases: 256,
            failure_persistence: None,
            ..Default::default()
        })]

        #[test]
        fn junit_is_well_formed_xml_whatever_the_text(
            path in hostile(), message in hostile(), other in hostile()
        ) {
            let xml = junit(&[hostile_result(&path, &message, &other)]);
            let doc = roxmltree::Document::parse(&xml);
            proptest::prop_assert!(doc.is_ok(), "{:?}\n{}", doc.err(), xml);
        }

        #[test]
        fn sarif_is_json_and_github_lines_are_massprops_whatever_the_text(
            path in hostile(), message in hostile(), other in hostile()
        ) {
            let results = [hostile_result(&path, &message, &other)];
            let sarif: Result<serde_json::Value, _> = serde_json::from_str(&sarif(&results));
            proptest::prop_assert!(sarif.is_ok());
            let github = github(&results, 0);
            for line in github.lines() {
                proptest::prop_assert!(
                    line.starts_with("::error file=") || line.starts_with("checked "),
                    "{:?}", line
                );
                proptest::prop_assert!(
                    !line.chars().any(|c| c != '\t' && crate::diag::is_hidden(c)),
                    "{:?}", line
                );
            }
            proptest::prop_assert_eq!(github.lines().count(), 3);
        }
    }

    #[test]
    fn paths_become_relative_uri_references() {
        assert_eq!(uri("shapes/a b#1%.toml"), "shapes/a%20b%231%25.toml");
        assert_eq!(uri("dir\\x.toml"), "dir%5Cx.toml");
        assert_eq!(uri("é.toml"), "%C3%A9.toml");
    }

    #[cfg(unix)]
    #[test]
    fn a_uri_gives_the_bytes_of_a_name_that_is_not_utf8() {
        use std::os::unix::ffi::OsStrExt;
        let path = std::path::Path::new(std::ffi::OsStr::from_bytes(b"d\xe9/a\\b\xff.toml"));
        let shown = crate::diag::display_path(path);
        assert_eq!(uri(&shown), "d%E9/a%5Cb%FF.toml");
        // A UTF-8 name holding the text `\xff` is that text.
        let shown = crate::diag::display_path(std::path::Path::new("a\\xff.toml"));
        assert_eq!(uri(&shown), "a%5Cxff.toml");
    }
}
