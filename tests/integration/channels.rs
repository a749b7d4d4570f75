//! Every channel is escaped (issue 28, item 1): the binary run on
//! generated hostile files, in every command and every format, with text
//! from input (part, file-level, group and link names; material, parameter,
//! growth, `[expect]` and unknown keys; a value quoted; include, mesh and
//! part file names; `--only` and `--set`) holding ways to end a line (LF,
//! CR, VT, FF, NEL, U+2028, U+2029), terminal controls, bidirectional
//! overrides, U+FFFE/U+FFFF, and GitHub workflow commands
//! (`::error file=x::FORGED`, `::add-mask::`, `::stop-commands::`).
//!
//! On standard output and standard error alike:
//!
//! - no raw control, bidirectional, separator or noncharacter (U+FFFE,
//!   U+FFFF) character, but tab and the newlines massprop wrote;
//! - no line begins (leading blanks aside, as the runner reads it) with
//!   `::` unless it is massprop's own annotation in `--format github`,
//!   whose properties and message are parsed back; its `file` is a path
//!   the check's JSON names;
//! - no line begins with text the input chose (`FORGED`, each hostile
//!   text's own start), but a name or path that begins with a letter or
//!   digit, shown as it is (it cannot be a command; a path that begins
//!   otherwise is shown as `./PATH`, a title's name in backticks);
//! - JUnit and SVG parse as XML (roxmltree), SARIF as JSON, each SARIF URI
//!   percent-decoding to a file's name.
//!
//! Deterministic (hostile.rs's `property`: fixed ChaCha seed).

use super::common::scratch;
use super::hostile::property;
use proptest::prelude::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Generated files; each runs about fifteen commands.
const CASES: u32 = 48;

/// A line's text that a CI runner takes as a command, or a marker.
const COMMANDS: &[&str] = &[
    "::error file=x,line=1::FORGED",
    "\u{a0}::error::FORGED",
    "\u{3000}::notice::FORGED",
    "::add-mask::FORGED",
    "::stop-commands::FORGED",
    "  ::warning::FORGED",
    "FORGED",
];

/// Ways to end a line or hide text: the line breaks a reader may honour,
/// a terminal's controls, bidirectional overrides, noncharacters.
const BREAKS: &[&str] = &[
    "\n",
    "\r",
    "\r\n",
    "\u{b}",
    "\u{c}",
    "\u{85}",
    "\u{2028}",
    "\u{2029}",
    "\u{1b}[2K\r",
    "\u{9b}2J",
    "\u{202e}",
    "\u{2066}",
    "\u{fffe}",
    "\u{ffff}",
    "\u{7f}",
];

/// Where the hostile text goes.
#[derive(Debug, Clone, Copy)]
enum Slot {
    PartName,
    BodyName,
    Group,
    Material,
    UnknownMaterial,
    Param,
    Growth,
    ExpectKey,
    UnknownKey,
    Value,
    IncludeFile,
    MeshFile,
    FileName,
    Only,
    Set,
    LinkName,
}

const SLOTS: [Slot; 16] = [
    Slot::PartName,
    Slot::BodyName,
    Slot::Group,
    Slot::Material,
    Slot::UnknownMaterial,
    Slot::Param,
    Slot::Growth,
    Slot::ExpectKey,
    Slot::UnknownKey,
    Slot::Value,
    Slot::IncludeFile,
    Slot::MeshFile,
    Slot::FileName,
    Slot::Only,
    Slot::Set,
    Slot::LinkName,
];

/// A hostile text: a command, then breaks each followed by a command.
fn hostile_text() -> impl Strategy<Value = String> {
    (
        prop::sample::select(COMMANDS),
        prop::collection::vec(
            (prop::sample::select(BREAKS), prop::sample::select(COMMANDS)),
            1..4,
        ),
    )
        .prop_map(|(first, rest)| {
            let mut s = first.to_string();
            for (b, c) in rest {
                s.push_str(b);
                s.push_str(c);
            }
            s
        })
}

/// A TOML basic string of `s`: C0 and DEL escaped, as TOML requires; the
/// rest (C1, bidirectional, separators, noncharacters) raw when `raw`, so
/// a source line quoted under a caret holds them.
fn toml_str(s: &str, raw: bool) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_ascii_control() && c != '\t' => {
                out.push_str(&format!("\\u{:04X}", u32::from(c)))
            }
            c if !raw && hidden(c) => out.push_str(&format!("\\u{:04X}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A file name of `s`: no `/` (a directory) and no NUL, at most 200
/// bytes (a file system's limit is 255).
fn file_name(s: &str) -> String {
    let mut name = s.replace(['/', '\0'], "_");
    while name.len() > 200 {
        name.pop();
    }
    name
}

/// An attribute's value in XML of `s`: the characters XML 1.0 allows,
/// escaped (a newline as `&#10;`, so the attribute keeps it).
fn xml_attr(s: &str) -> String {
    s.chars()
        .map(|c| match c {
            '&' => "&amp;".to_string(),
            '<' => "&lt;".to_string(),
            '"' => "&quot;".to_string(),
            '\t' | '\n' | '\r' => format!("&#{};", u32::from(c)),
            c if (c as u32) < 0x20 || c == '\u{fffe}' || c == '\u{ffff}' => "?".to_string(),
            c => c.to_string(),
        })
        .collect()
}

/// The characters no output may hold raw but tab and newline (the test's
/// own list, not massprop's): controls, bidirectional formatting
/// characters, the line and paragraph separators, U+FFFE and U+FFFF.
pub(crate) fn hidden(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{202a}'..='\u{202e}'
                | '\u{2066}'..='\u{2069}'
                | '\u{200e}'
                | '\u{200f}'
                | '\u{61c}'
                | '\u{2028}'
                | '\u{2029}'
                | '\u{fffe}'
                | '\u{ffff}'
        )
}

/// `s` as a terminal shows text from input: C0 as its picture, DEL as ␡,
/// the rest of `hidden` as U+FFFD.
fn pictures(s: &str) -> String {
    s.chars()
        .map(|c| match c {
            '\t' => c,
            '\0'..='\u{1f}' => char::from_u32(0x2400 + u32::from(c)).unwrap(),
            '\u{7f}' => '\u{2421}',
            c if hidden(c) => '\u{fffd}',
            c => c,
        })
        .collect()
}

const BOX: &str = "shape = \"box\"\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n";

/// A closed tetrahedron, outward.
const STL: &str = "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n";

/// A case's files, written into `dir`: the part file to run, extra
/// arguments for the commands that take a part file, and a robot
/// description with its link's name when there is one.
struct Case {
    top: PathBuf,
    extra: Vec<String>,
    robot: Option<(PathBuf, String)>,
}

fn write_case(dir: &Path, slot: Slot, s: &str, raw: bool) -> Case {
    let q = |t: &str| toml_str(t, raw);
    let part = |extra: &str| format!("[[part]]\nname = \"p\"\n{extra}");
    let mut top_name = "top.toml".to_string();
    let mut extra = Vec::new();
    let mut robot = None;
    let text = match slot {
        Slot::PartName => format!("[[part]]\nname = {}\nmass = 1\n{BOX}", q(s)),
        Slot::BodyName => format!("name = {}\n{}", q(s), part(&format!("mass = 1\n{BOX}"))),
        Slot::Group => part(&format!("mass = 1\n{BOX}group = {}\n", q(s))),
        Slot::Material => format!(
            "[materials]\n{} = {{ density = 1000 }}\n{}",
            q(s),
            part(&format!("{BOX}material = {}\n", q(s)))
        ),
        Slot::UnknownMaterial => part(&format!("{BOX}material = {}\n", q(s))),
        Slot::Param => format!(
            "[params]\n{} = 2\n{}",
            q(s),
            part(&format!("mass = 1\n{BOX}"))
        ),
        Slot::Growth => format!(
            "[growth]\n{} = \"10 %\"\n{}",
            q(s),
            part(&format!("mass = 1\n{BOX}maturity = {}\n", q(s)))
        ),
        Slot::ExpectKey => format!(
            "{}[expect]\n{} = 1\n",
            part(&format!("mass = 1\n{BOX}")),
            q(s)
        ),
        Slot::UnknownKey => part(&format!("mass = 1\n{BOX}{} = 1\n", q(s))),
        Slot::Value => part(&format!("mass = {}\n{BOX}", q(s))),
        Slot::IncludeFile => {
            let name = format!("{}.toml", file_name(s));
            std::fs::write(dir.join(&name), part(&format!("mass = 1\n{BOX}"))).unwrap();
            format!(
                "{}[[part]]\nname = \"sub\"\ninclude = {}\n",
                part(&format!("mass = 1\n{BOX}")),
                q(&name)
            )
        }
        Slot::MeshFile => {
            let name = format!("{}.stl", file_name(s));
            std::fs::write(dir.join(&name), STL).unwrap();
            format!(
                "[[part]]\nname = \"m\"\nshape = \"mesh\"\nfile = {}\ndensity = 1000\n",
                q(&name)
            )
        }
        Slot::FileName => {
            top_name = format!("{}.toml", file_name(s));
            part(&format!("mass = 1\n{BOX}"))
        }
        Slot::Only => {
            extra = vec!["--only".into(), s.into()];
            part(&format!("mass = 1\n{BOX}"))
        }
        Slot::Set => {
            extra = vec!["--set".into(), format!("{s}=1")];
            format!("[params]\nm = 1\n{}", part(&format!("mass = \"m\"\n{BOX}")))
        }
        Slot::LinkName => {
            let comment = s
                .replace("--", "- -")
                .replace(|c: char| (c as u32) < 0x20 && c != '\n' && c != '\t', "?");
            let comment = comment.replace(['\u{fffe}', '\u{ffff}'], "?");
            let link = xml_attr(s);
            let urdf = format!(
                "<robot name=\"r\">\n<!-- {comment} -->\n<link name=\"{link}\">\n<inertial>\n<origin xyz=\"0 0 0\"/>\n<mass value=\"1\"/>\n<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/>\n</inertial>\n</link>\n</robot>\n"
            );
            let path = dir.join(format!("{}.urdf", file_name(s)));
            std::fs::write(&path, urdf).unwrap();
            // The name as an XML reader gives it back.
            let given = s
                .chars()
                .map(|c| {
                    if ((c as u32) < 0x20 && !"\t\n\r".contains(c))
                        || c == '\u{fffe}'
                        || c == '\u{ffff}'
                    {
                        '?'
                    } else {
                        c
                    }
                })
                .collect();
            robot = Some((path, given));
            part(&format!("mass = 1\n{BOX}"))
        }
    };
    let top = dir.join(top_name);
    std::fs::write(&top, text).unwrap();
    Case { top, extra, robot }
}

/// What a run printed.
struct Run {
    what: String,
    status: Option<i32>,
    stdout: String,
    stderr: String,
}

fn run(args: &[&std::ffi::OsStr]) -> Run {
    let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(args)
        .output()
        .expect("the massprop binary runs");
    Run {
        what: format!("{args:?}"),
        status: out.status.code(),
        stdout: String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(out.stderr).expect("stderr is UTF-8"),
    }
}

/// The promises on one channel's text; `github`: lines beginning `::`
/// are to be massprop's annotations, whose files are among `files`;
/// `lead`: the input's text begins with a letter, and may begin a line
/// as it is (a name or path beginning with a letter or digit is shown as
/// it is: it cannot be a command), never after blanks.
fn channel(
    r: &Run,
    name: &str,
    text: &str,
    github: Option<&[String]>,
    lead: bool,
) -> Result<(), String> {
    let fail = |why: String| {
        Err(format!(
            "{} ({:?}), {name}: {why}\n--- {name} ---\n{text}\n--- end ---",
            r.what, r.status
        ))
    };
    if let Some(c) = text.chars().find(|&c| c != '\n' && c != '\t' && hidden(c)) {
        return fail(format!("a raw U+{:04X}", u32::from(c)));
    }
    // `export --dry-run`'s diff: a context line is ` ` and the robot
    // file's own line, by design; it may not be a command all the same.
    let diff = text.starts_with("--- a/");
    for line in text.lines() {
        let start = line.trim_start();
        let own = lead && line.starts_with("FORGED");
        if start.starts_with("FORGED") && !own && !(diff && line.starts_with(' ')) {
            return fail(format!("a line begins with the input's text: {line:?}"));
        }
        if !start.starts_with("::") {
            continue;
        }
        match github {
            Some(files) if line == start => annotation(line, files).or_else(&fail)?,
            _ => return fail(format!("a line begins with `::`: {line:?}")),
        }
    }
    Ok(())
}

/// A GitHub annotation, parsed by the runner's rules: `::LEVEL
/// PROPERTIES::MESSAGE`, properties `KEY=VALUE` separated by `,`, values
/// with `%`, CR, LF, `:` and `,` escaped; its `file` is one of `files`.
fn annotation(line: &str, files: &[String]) -> Result<(), String> {
    let rest = &line[2..];
    let (command, message) = rest
        .split_once("::")
        .ok_or_else(|| format!("an annotation without `::` after its command: {line:?}"))?;
    let (level, props) = command
        .split_once(' ')
        .ok_or_else(|| format!("an annotation without properties: {line:?}"))?;
    if !matches!(level, "error" | "warning") {
        return Err(format!("a command that is not massprop's: {line:?}"));
    }
    let decode = |v: &str| {
        v.replace("%3A", ":")
            .replace("%2C", ",")
            .replace("%0D", "\r")
            .replace("%0A", "\n")
            .replace("%25", "%")
    };
    let mut file = None;
    for p in props.split(',') {
        let (k, v) = p
            .split_once('=')
            .ok_or_else(|| format!("a property without `=`: {p:?} in {line:?}"))?;
        if !matches!(
            k,
            "file" | "line" | "col" | "endLine" | "endColumn" | "title"
        ) {
            return Err(format!("an unknown property {k:?} in {line:?}"));
        }
        if k == "file" {
            file = Some(decode(v));
        }
    }
    let file = file.ok_or_else(|| format!("an annotation without a file: {line:?}"))?;
    if !files.contains(&file) {
        return Err(format!(
            "the annotation's file {file:?} is none of {files:?}"
        ));
    }
    // The message's lines are massprop's (the message, its label, help
    // and notes): none begins with the input's text.
    let message = decode(message);
    if message.contains('\r')
        || message.lines().any(|l| {
            let l = l.trim_start();
            l.starts_with("::") || l.starts_with("FORGED")
        })
    {
        return Err(format!(
            "an annotation's message starts a line of the input's: {line:?}"
        ));
    }
    Ok(())
}

/// The paths `check --format json` names (files and errors' places), as
/// a GitHub annotation gives them: pictures, without a leading `./`.
fn json_paths(json: &str) -> Vec<String> {
    let v: Value = serde_json::from_str(json).unwrap_or_else(|e| panic!("{e}: {json}"));
    let mut out = Vec::new();
    for f in v["files"].as_array().unwrap() {
        for p in [&f["path"], &f["error"]["path"]] {
            if let Some(p) = p.as_str() {
                let shown = pictures(p);
                out.push(shown.strip_prefix("./").unwrap_or(&shown).to_string());
            }
        }
    }
    out
}

/// Percent-decoding (RFC 3986).
fn percent_decode(s: &str) -> Vec<u8> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            out.push(u8::from_str_radix(&s[i + 1..i + 3], 16).unwrap());
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    out
}

fn xml(r: &Run) -> Result<(), String> {
    roxmltree::Document::parse(&r.stdout)
        .map(|_| ())
        .map_err(|e| format!("{}: not well-formed XML: {e}\n{}", r.what, r.stdout))
}

/// Every promise, for one case.
fn promises(slot: Slot, s: &str, raw: bool, n: usize) -> Result<bool, String> {
    let dir = scratch("channels", &format!("case-{n}"));
    let case = write_case(&dir, slot, s, raw);
    let lead = s.starts_with("FORGED");
    let top = case.top.as_os_str();
    let d = dir.as_os_str();
    let os = |a: &str| std::ffi::OsString::from(a);
    let extra: Vec<std::ffi::OsString> = case.extra.iter().map(|a| os(a)).collect();
    let with = |args: &[&str], file: &std::ffi::OsStr, more: &[std::ffi::OsString]| {
        let mut v: Vec<std::ffi::OsString> = args.iter().map(|a| os(a)).collect();
        v.push(file.to_os_string());
        v.extend(more.iter().cloned());
        let refs: Vec<&std::ffi::OsStr> = v.iter().map(|a| a.as_os_str()).collect();
        run(&refs)
    };
    let mut computed = false;
    let mut runs = Vec::new();
    for args in [
        &["report"][..],
        &["report", "--format", "json"],
        &["report", "--uncertainty", "linear"],
        &["budget"],
        &["render"],
        &["export", "--to", "urdf"],
        &["materials"],
    ] {
        let more: &[std::ffi::OsString] = if args[0] == "materials" { &[] } else { &extra };
        let r = with(args, top, more);
        computed |= args == ["report"] && r.status == Some(0);
        if args == ["render"] && r.status == Some(0) {
            xml(&r)?;
        }
        runs.push(r);
    }
    let mut diff = vec![os("diff"), top.to_os_string(), top.to_os_string()];
    diff.extend(extra.iter().cloned());
    runs.push(run(&diff.iter().map(|a| a.as_os_str()).collect::<Vec<_>>()));
    let mut checked: Vec<&std::ffi::OsStr> = vec![top, d];
    if let Some((urdf, link)) = &case.robot {
        checked.push(urdf.as_os_str());
        let update = [
            os("export"),
            top.to_os_string(),
            os("--update"),
            urdf.as_os_str().to_os_string(),
            os("--link"),
            os(link),
            os("--dry-run"),
        ];
        let r = run(&update.iter().map(|a| a.as_os_str()).collect::<Vec<_>>());
        // The diff is made: the link is found by its name.
        if r.status != Some(0) || !r.stdout.starts_with("--- a/") {
            return Err(format!("{}: no diff\n{}{}", r.what, r.stdout, r.stderr));
        }
        runs.push(r);
        let linked = [
            os("diff"),
            top.to_os_string(),
            urdf.as_os_str().to_os_string(),
            os("--link"),
            os(link),
        ];
        runs.push(run(&linked
            .iter()
            .map(|a| a.as_os_str())
            .collect::<Vec<_>>()));
    }
    for r in &runs {
        channel(r, "stdout", &r.stdout, None, lead)?;
        channel(r, "stderr", &r.stderr, None, lead)?;
    }
    for file in checked {
        let json = with(&["check", "--format", "json"], file, &[]);
        channel(&json, "stdout", &json.stdout, None, lead)?;
        channel(&json, "stderr", &json.stderr, None, lead)?;
        let files = json_paths(&json.stdout);
        for format in ["table", "github", "junit", "sarif"] {
            let r = with(&["check", "--format", format], file, &[]);
            let github = (format == "github").then_some(&files[..]);
            channel(&r, "stdout", &r.stdout, github, lead)?;
            channel(&r, "stderr", &r.stderr, None, lead)?;
            match format {
                "junit" => xml(&r)?,
                "sarif" => sarif_uris(&r, &files)?,
                _ => {}
            }
        }
    }
    Ok(computed)
}

/// SARIF parses as JSON, and each URI percent-decodes to a path the check
/// names (UTF-8 here: pictures compared).
fn sarif_uris(r: &Run, files: &[String]) -> Result<(), String> {
    let v: Value = serde_json::from_str(&r.stdout)
        .map_err(|e| format!("{}: SARIF is not JSON: {e}\n{}", r.what, r.stdout))?;
    for result in v["runs"][0]["results"].as_array().unwrap() {
        let uri = result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
            .as_str()
            .unwrap();
        let path = String::from_utf8(percent_decode(uri)).map_err(|e| format!("{uri}: {e}"))?;
        if !files.contains(&pictures(&path)) {
            return Err(format!("{}: the URI {uri} is none of {files:?}", r.what));
        }
    }
    Ok(())
}

#[test]
fn no_line_of_stdout_or_stderr_begins_with_text_the_input_chose() {
    let counter = std::sync::atomic::AtomicUsize::new(0);
    property(
        "channels",
        CASES,
        (
            prop::sample::select(&SLOTS[..]),
            hostile_text(),
            any::<bool>(),
        ),
        |(slot, s, raw)| {
            let n = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            promises(*slot, s, *raw, n)
        },
    );
}

#[test]
fn every_slot_is_tried_with_every_way_to_end_a_line() {
    // The generated cases reach each slot at random; this runs each slot
    // once with the hostile text of every break, in order.
    for (i, slot) in SLOTS.iter().enumerate() {
        let s: String = BREAKS
            .iter()
            .zip(COMMANDS.iter().cycle())
            .map(|(b, c)| format!("{b}{c}"))
            .collect();
        let s = format!("::error::FORGED{s}");
        promises(*slot, &s, i % 2 == 0, 10_000 + i).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[cfg(unix)]
#[test]
fn a_sarif_uri_gives_the_bytes_of_a_file_name_that_is_not_utf8() {
    use std::os::unix::ffi::OsStrExt;
    let dir = scratch("channels", "non-utf8");
    let name = std::ffi::OsStr::from_bytes(b"::\xff\xfe a\\b\xe9.toml");
    let path = dir.join(name);
    std::fs::write(
        &path,
        "[[part]]\nname = \"p\"\nmass = 1\nsize = [1, 1]\nshape = \"box\"\ncenter = [0, 0, 0]\n",
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_massprop"))
        .args(["check", "--format", "sarif"])
        .arg(&path)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let uri =
        v["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
            .as_str()
            .unwrap();
    assert_eq!(percent_decode(uri), path.as_os_str().as_bytes(), "{uri}");
}

#[test]
fn an_error_about_the_command_line_quotes_its_arguments_escaped() {
    // A file name from a shell's glob that clap takes for a flag, and a
    // value clap refuses: each quoted on one line of its own making.
    for args in [
        vec!["report", "--x\n::error::FORGED"],
        vec!["check", "--format", "table\n::add-mask::FORGED"],
        vec!["report", "a.toml", "b\u{2028}::error::FORGED.toml"],
    ] {
        let r = run(&args.iter().map(std::ffi::OsStr::new).collect::<Vec<_>>());
        assert_eq!(r.status, Some(2), "{}: {}", r.what, r.stderr);
        assert!(r.stderr.contains("FORGED"), "{}: {}", r.what, r.stderr);
        channel(&r, "stderr", &r.stderr, None, false).unwrap_or_else(|e| panic!("{e}"));
        channel(&r, "stdout", &r.stdout, None, false).unwrap_or_else(|e| panic!("{e}"));
    }
}
