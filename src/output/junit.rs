//! JUnit XML, written as cargo-nextest's crate (quick-junit 0.8 over
//! quick-xml 0.41) writes it: a `<testsuites>` report of `<testsuite>`s of
//! `<testcase>`s, four spaces of indentation, counts on every suite and on
//! the report, no timestamps, times or ids.
//!
//! NOTE: hand-written rather than taken from quick-junit, which (with
//! quick-xml, chrono, uuid and newtype-uuid) was about a twenty-fifth of a
//! cold release build for the one document `check --format junit` writes.
//! Byte-identical to what quick-junit wrote for every report massprop
//! makes (tests/integration/diff_junit.rs holds it to quick-junit over
//! generated reports with hostile names): text is cleaned as quick-junit's
//! `XmlString` cleans it (C0 controls but the newline, and C1 controls,
//! dropped: what XML 1.0 cannot hold, and what a terminal would act on)
//! and escaped as quick-xml escapes it (`&<>'"`, in attributes and text
//! alike). One difference, never reached: quick-junit drops a whole ANSI
//! escape sequence where this drops its ESC alone; massprop's texts never
//! hold ESC (`diag::visible` shows it as ␛).

/// A report: its name and its suites.
pub struct Report {
    pub name: String,
    pub suites: Vec<Suite>,
}

/// A suite: its name, its cases, and what it wrote to standard error.
pub struct Suite {
    pub name: String,
    pub cases: Vec<Case>,
    pub system_err: Option<String>,
}

/// A test case: its name, its class, and how it ended.
pub struct Case {
    pub name: String,
    pub classname: String,
    pub status: Status,
}

/// How a test case ended.
pub enum Status {
    Success,
    /// A `<failure>` (a check that failed) or, with `error`, an `<error>`
    /// (a check that could not run): its `type` and `message`
    /// attributes, and its text.
    NonSuccess {
        error: bool,
        ty: String,
        message: String,
        description: String,
    },
}

impl Status {
    fn is(&self, error: bool) -> bool {
        match self {
            Status::Success => false,
            Status::NonSuccess { error: e, .. } => *e == error,
        }
    }
}

/// Tests, failures and errors among `cases`.
fn counts<'a>(cases: impl Iterator<Item = &'a Case> + Clone) -> (usize, usize, usize) {
    let failures = cases.clone().filter(|c| c.status.is(false)).count();
    let errors = cases.clone().filter(|c| c.status.is(true)).count();
    (cases.count(), failures, errors)
}

/// `text` cleaned (see the module's note) and escaped.
fn push_escaped(out: &mut String, text: &str) {
    for c in text.chars() {
        match c {
            '\n' => out.push('\n'),
            '\0'..='\x1f' | '\u{80}'..='\u{9f}' => {}
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '\'' => out.push_str("&apos;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
}

/// ` key="value"`.
fn attribute(out: &mut String, key: &str, value: &str) {
    out.push(' ');
    out.push_str(key);
    out.push_str("=\"");
    push_escaped(out, value);
    out.push('"');
}

/// A new line indented to `level`.
fn line(out: &mut String, level: usize) {
    out.push('\n');
    out.extend(std::iter::repeat_n(' ', 4 * level));
}

/// `<tag>TEXT</tag>` on its own line at `level`, attributes given.
fn element(out: &mut String, level: usize, tag: &str, attrs: &[(&str, &str)], text: &str) {
    line(out, level);
    out.push('<');
    out.push_str(tag);
    for (k, v) in attrs {
        attribute(out, k, v);
    }
    out.push('>');
    push_escaped(out, text);
    out.push_str("</");
    out.push_str(tag);
    out.push('>');
}

/// The report as JUnit XML, ending with a newline.
pub fn write(report: &Report) -> String {
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    let all = report.suites.iter().flat_map(|s| &s.cases);
    let (tests, failures, errors) = counts(all);
    line(&mut out, 0);
    out.push_str("<testsuites");
    attribute(&mut out, "name", &report.name);
    attribute(&mut out, "tests", &tests.to_string());
    attribute(&mut out, "skipped", "0");
    attribute(&mut out, "failures", &failures.to_string());
    attribute(&mut out, "errors", &errors.to_string());
    out.push('>');
    for suite in &report.suites {
        let (tests, failures, errors) = counts(suite.cases.iter());
        line(&mut out, 1);
        out.push_str("<testsuite");
        attribute(&mut out, "name", &suite.name);
        attribute(&mut out, "tests", &tests.to_string());
        attribute(&mut out, "skipped", "0");
        attribute(&mut out, "errors", &errors.to_string());
        attribute(&mut out, "failures", &failures.to_string());
        if suite.cases.is_empty() && suite.system_err.is_none() {
            out.push_str("/>");
            continue;
        }
        out.push('>');
        for case in &suite.cases {
            line(&mut out, 2);
            out.push_str("<testcase");
            attribute(&mut out, "name", &case.name);
            attribute(&mut out, "classname", &case.classname);
            match &case.status {
                Status::Success => out.push_str("/>"),
                Status::NonSuccess {
                    error,
                    ty,
                    message,
                    description,
                } => {
                    out.push('>');
                    let tag = if *error { "error" } else { "failure" };
                    let attrs = [("message", message.as_str()), ("type", ty.as_str())];
                    element(&mut out, 3, tag, &attrs, description);
                    line(&mut out, 2);
                    out.push_str("</testcase>");
                }
            }
        }
        if let Some(err) = &suite.system_err {
            element(&mut out, 2, "system-err", &[], err);
        }
        line(&mut out, 1);
        out.push_str("</testsuite>");
    }
    line(&mut out, 0);
    out.push_str("</testsuites>\n");
    out
}
