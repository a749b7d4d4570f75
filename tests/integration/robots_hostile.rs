//! Hostile robot descriptions (docs/fuzzing.md, "Robot descriptions"):
//! mutated fixtures and files generated from scratch, in URDF, SDFormat
//! and MJCF, run in process through `check` (every `--format`, every
//! `--engine`), `diff PART ROBOT --link NAME` and `export --update`
//! (`--dry-run`, and for real on a copy). Whatever the file, massprop must
//! not panic or hang; `check` exits 0, 1 or 2, prints no infinite or NaN
//! number (JSON: finite numbers, `null` only where docs/robots.md allows
//! it) and, at status 2, a diagnostic `FILE:LINE:COL: error: …`; `diff`
//! and `export` either succeed with finite output or fail with a
//! diagnostic naming the file; and an update either fails with the file
//! untouched or gives a file that reads back with the link's inertial
//! replaced (to the bit) and every other link as it was.
//!
//! And the shapes no generator reaches by chance: elements nested
//! thousands deep, 10⁴ links (their work counted, no clock), cycles of
//! joints, an entity expansion bomb, byte-order marks, CRLF, text that is
//! not UTF-8.
//!
//! Deterministic (fixed ChaCha seed, no persistence file), as hostile.rs.

use crate::hostile::{non_finite_word, property, run};
use massprop::diag::Source;
use massprop::robot::{Description, Dialect, Inertial, read::read};
use proptest::prelude::*;
use proptest::sample::Index;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Generated files.
const GENERATED: u32 = 150;
/// Mutated fixtures.
const MUTATED: u32 = 150;

/// The part file every `diff` and `export` compares or writes.
fn part() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("shapes/flywheel.toml")
        .to_str()
        .unwrap()
        .to_string()
}

// ---------------------------------------------------------------------------
// The promise, for one file

/// Keys whose value may be `null` in check's JSON of a robot description
/// (docs/robots.md): a rule's `margin` (a mass rule, no scale), a link's
/// `inertial` (none, or values that overflow) and an engine's `cause`.
const MAY_BE_NULL: &[&str] = &["margin", "inertial", "cause"];

/// Keys of diff's JSON that may be `null` (docs/diff.md).
const DIFF_MAY_BE_NULL: &[&str] = &["rel_change", "relative_change", "name"];

fn walk(v: &Value, key: &str, path: &str, nulls: &[&str]) -> Result<(), String> {
    match v {
        Value::Null if nulls.contains(&key) => Ok(()),
        Value::Null => Err(format!("null at {path}")),
        Value::Number(n) => match n.as_f64() {
            Some(x) if x.is_finite() => Ok(()),
            _ => Err(format!("non-finite number {n} at {path}")),
        },
        Value::Array(items) => items
            .iter()
            .enumerate()
            .try_for_each(|(i, item)| walk(item, key, &format!("{path}[{i}]"), nulls)),
        Value::Object(map) => map
            .iter()
            .try_for_each(|(k, item)| walk(item, k, &format!("{path}.{k}"), nulls)),
        Value::Bool(_) | Value::String(_) => Ok(()),
    }
}

/// The format a file is read as, as `check` decides it.
fn format_of(path: &Path, text: &str) -> Option<Dialect> {
    Dialect::of_path(path).or_else(|| Dialect::of_text(text.trim_start_matches('\u{feff}')))
}

/// The file read as a robot description by the library, if it can be.
fn described(path: &Path, bytes: &[u8]) -> Option<(Dialect, Description)> {
    let text = std::str::from_utf8(bytes).ok()?;
    let format = format_of(path, text)?;
    let d = read(&Source::new("f", text), format).ok()?;
    Some((format, d))
}

/// Whether `stderr` starts with a diagnostic at a place in `name`:
/// `NAME:LINE:COL: error: `.
fn located(stderr: &str, name: &str) -> bool {
    let Some(rest) = stderr.strip_prefix(&format!("{name}:")) else {
        return false;
    };
    let mut parts = rest.splitn(3, ':');
    let number =
        |p: Option<&str>| p.is_some_and(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    number(parts.next())
        && number(parts.next())
        && parts.next().is_some_and(|r| r.starts_with(" error: "))
}

/// One robot file through every command: Err describes the first broken
/// promise; Ok(true) when `check` read it (status 0 or 1).
fn robot_hostile(path: &Path, link: &str) -> Result<bool, String> {
    let p = path.to_str().unwrap();
    let name = path.file_name().unwrap().to_str().unwrap();
    let bytes = std::fs::read(path).unwrap();
    // A word of the input may be quoted back (a name, a snippet), also
    // with the controls between its letters dropped (JUnit drops a tab
    // from the line it quotes: `infi<TAB>nity` shows as `infinity`).
    let lossy = String::from_utf8_lossy(&bytes);
    let bare: String = lossy.chars().filter(|c| !c.is_control()).collect();
    let quiet = non_finite_word(&lossy).is_none() && non_finite_word(&bare).is_none();
    let robot = Dialect::of_path(path).is_some();
    let mut read_ok = None;
    // check: JSON under each engine choice, the other formats under all.
    let mut runs: Vec<Vec<&str>> = [None, Some("mujoco"), Some("gazebo"), Some("drake")]
        .into_iter()
        .map(|e| {
            let mut a = vec!["check", "--format", "json", p];
            if let Some(e) = e {
                a.extend(["--engine", e]);
            }
            a
        })
        .collect();
    for f in ["table", "github", "junit", "sarif"] {
        runs.push(vec!["check", "--format", f, p]);
    }
    for args in &runs {
        let what = args.join(" ");
        let out = match run(args)? {
            Ok(out) => out,
            // A file that is no robot description and no part file either
            // (an `*.xml` with another root): the error names it.
            Err(d) if !robot && d.to_string().contains(name) => continue,
            Err(d) => return Err(format!("{what}: error without a report: {d}")),
        };
        let stdout = out.stdout.text();
        if out.status > 2 {
            return Err(format!("{what}: status {}", out.status));
        }
        if out.status == 2 && robot && !located(&out.stderr, p) {
            return Err(format!(
                "{what}: status 2 without NAME:LINE:COL: {}",
                out.stderr
            ));
        }
        if args.contains(&"json") {
            let json: Value = serde_json::from_str(&stdout)
                .map_err(|e| format!("{what}: output is not JSON ({e}): {stdout}"))?;
            walk(&json, "", "$", MAY_BE_NULL).map_err(|e| format!("{what}: {e}"))?;
            let status = json["files"][0]["status"].as_str().unwrap_or("");
            let expected = match out.status {
                0 => "ok",
                1 => "failed",
                _ => "invalid",
            };
            if status != expected {
                return Err(format!(
                    "{what}: status {} but the file is {status:?}",
                    out.status
                ));
            }
        } else if quiet {
            for text in [&stdout, &out.stderr] {
                if let Some(w) = non_finite_word(text) {
                    return Err(format!("{what} prints {w:?}:\n{text}"));
                }
            }
        }
        let ok = out.status < 2;
        if read_ok.replace(ok).is_some_and(|was| was != ok) {
            return Err(format!("{what}: read in one run, not in another"));
        }
    }
    // diff, either way round, JSON and table.
    let part = part();
    for args in [
        vec!["diff", &part, p, "--link", link, "--format", "json"],
        vec!["diff", p, &part, "--link", link],
    ] {
        let what = args.join(" ");
        match run(&args)? {
            Ok(out) => {
                if out.status > 1 {
                    return Err(format!("{what}: Ok with status {}", out.status));
                }
                let stdout = out.stdout.text();
                if args.contains(&"json") {
                    let json: Value = serde_json::from_str(&stdout)
                        .map_err(|e| format!("{what}: output is not JSON ({e})"))?;
                    walk(&json, "", "$", DIFF_MAY_BE_NULL).map_err(|e| format!("{what}: {e}"))?;
                } else if let Some(w) = non_finite_word(&stdout).filter(|_| quiet) {
                    return Err(format!("{what} prints {w:?}:\n{stdout}"));
                }
            }
            Err(d) => {
                let text = d.to_string();
                if !text.contains(name) && !text.contains("--link") {
                    return Err(format!("{what}: diagnostic does not name the file: {text}"));
                }
            }
        }
    }
    // report: the whole robot (issue 34), JSON and table: a report, or an
    // error that names the file.
    for args in [
        vec!["report", p, "--format", "json"],
        vec!["report", p, "--full"],
    ] {
        let what = args.join(" ");
        match run(&args)? {
            Ok(out) => {
                if out.status != 0 {
                    return Err(format!("{what}: Ok with status {}", out.status));
                }
                let stdout = out.stdout.text();
                if args.contains(&"json") {
                    serde_json::from_str::<Value>(&stdout)
                        .map_err(|e| format!("{what}: output is not JSON ({e})"))?;
                } else if let Some(w) = non_finite_word(&stdout).filter(|_| quiet) {
                    return Err(format!("{what} prints {w:?}:\n{stdout}"));
                }
            }
            Err(d) => {
                let text = d.to_string();
                if !text.contains(name) {
                    return Err(format!("{what}: diagnostic does not name the file: {text}"));
                }
            }
        }
    }
    // export --update: the dry run, then for real on a copy.
    let args = ["export", &part, "--update", p, "--link", link, "--dry-run"];
    let dry = match run(&args)? {
        Ok(out) => {
            if out.status != 0 {
                return Err(format!("{}: status {}", args.join(" "), out.status));
            }
            Some(out.stdout.text())
        }
        Err(d) => {
            let text = d.to_string();
            if !text.contains(name) && !text.contains("--link") {
                return Err(format!(
                    "export --dry-run: diagnostic does not name the file: {text}"
                ));
            }
            None
        }
    };
    let copy = path.with_file_name(format!("copy-{name}"));
    std::fs::write(&copy, &bytes).unwrap();
    let c = copy.to_str().unwrap();
    let args = ["export", &part, "--update", c, "--link", link];
    match run(&args)? {
        Ok(out) => {
            if dry.is_none() {
                return Err("export --update succeeded where --dry-run failed".to_string());
            }
            let after = std::fs::read(&copy).unwrap();
            if dry.as_deref() == Some("") && after != bytes {
                return Err("--dry-run showed no change, but the update changed the file".into());
            }
            updated(&copy, &bytes, &after, link).map_err(|e| {
                format!(
                    "export --update (status {}): {e}\n--- after ---\n{}",
                    out.status,
                    String::from_utf8_lossy(&after)
                )
            })?;
        }
        Err(d) => {
            if std::fs::read(&copy).unwrap() != bytes {
                return Err(format!("export --update failed ({d}) and changed the file"));
            }
            if dry.is_some() {
                return Err(format!(
                    "export --update failed where --dry-run succeeded: {d}"
                ));
            }
        }
    }
    Ok(read_ok == Some(true))
}

/// The inertial `export` writes for the part file, read back from its URDF
/// element (every format writes the same shortest round-trip numbers).
fn exported() -> Inertial {
    let out = run(&["export", &part(), "--to", "urdf"]).unwrap().unwrap();
    let text = format!(
        "<robot name='r'><link name='a'>{}</link></robot>",
        out.stdout.text()
    );
    let d = read(&Source::new("e.urdf", text), Dialect::Urdf).unwrap();
    d.links[0].inertial.clone().unwrap()
}

/// An inertial's values, the bytes it was read from left out.
fn values(i: &Inertial) -> (f64, [f64; 3], massprop::robot::Tensor) {
    (i.mass, i.pos, i.tensor_in_link())
}

/// The update of link `link` turned `before` into `after`: where the file
/// read before, it reads after, with the same links (names, motion,
/// parents) and inertials, but the link's, which is the exported one.
fn updated(path: &Path, before: &[u8], after: &[u8], link: &str) -> Result<(), String> {
    let Some((format, old)) = described(path, before) else {
        // The reader refuses what update accepted (a bad number in another
        // link, say): what changed must be an inertial, no other element
        // taken away, and the exported numbers written.
        let (b, a) = (before, after);
        let prefix = b.iter().zip(a).take_while(|(x, y)| x == y).count();
        let room = b.len().min(a.len()) - prefix;
        let suffix = b
            .iter()
            .rev()
            .zip(a.iter().rev())
            .take_while(|(x, y)| x == y)
            .count()
            .min(room);
        let old = String::from_utf8_lossy(&b[prefix..b.len() - suffix]);
        let new = String::from_utf8_lossy(&a[prefix..a.len() - suffix]);
        let mass = massprop::output::format::shortest(exported().mass);
        for tag in [
            "<link", "<body", "<model", "<joint", "<robot", "<sdf", "<mujoco", "<world",
        ] {
            if old.contains(tag) {
                return Err(format!("the update took away a {tag}: {old}"));
            }
        }
        return if new.contains(&mass) {
            Ok(())
        } else {
            Err(format!("the update wrote no exported mass {mass}: {new}"))
        };
    };
    let text = std::str::from_utf8(after).map_err(|_| "the update is not UTF-8".to_string())?;
    let new = read(&Source::new("f", text), format)
        .map_err(|d| format!("the update does not read back: {d}"))?;
    if old.links.len() != new.links.len() {
        return Err(format!(
            "{} links before, {} after",
            old.links.len(),
            new.links.len()
        ));
    }
    let e = values(&exported());
    let mut found = 0;
    for (a, b) in old.links.iter().zip(&new.links) {
        if (&a.name, a.moving, a.parent) != (&b.name, b.moving, b.parent) {
            return Err(format!("link {:?} became {:?}", a.name, b.name));
        }
        let (va, vb) = (
            a.inertial.as_ref().map(values),
            b.inertial.as_ref().map(values),
        );
        if a.name == link {
            found += 1;
            if vb != Some(e) {
                return Err(format!(
                    "link {link:?} reads back as {vb:?}, not the export {e:?}"
                ));
            }
        } else if va != vb {
            return Err(format!("link {:?} changed: {va:?} to {vb:?}", a.name));
        }
    }
    if found != 1 {
        return Err(format!("{found} links named {link:?} read back"));
    }
    Ok(())
}

/// A link name of the file to aim `diff` and `export` at: the `pick`th of
/// those the reader finds, else one from the text, else `base`.
fn aim(path: &Path, bytes: &[u8], pick: f64) -> String {
    let at = |n: usize| ((pick * n as f64) as usize).min(n - 1);
    if let Some((_, d)) = described(path, bytes)
        && !d.links.is_empty()
    {
        return d.links[at(d.links.len())].name.clone();
    }
    let text = String::from_utf8_lossy(bytes);
    let names: Vec<&str> = text
        .split("name=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .collect();
    if names.is_empty() {
        "base".to_string()
    } else {
        names[at(names.len())].to_string()
    }
}

/// Write `bytes` as `dir/file` and run it through `robot_hostile`.
fn hostile_robot(dir: &Path, file: &str, bytes: &[u8], pick: f64) -> Result<bool, String> {
    let path = dir.join(file);
    std::fs::write(&path, bytes).unwrap();
    let link = aim(&path, bytes, pick);
    robot_hostile(&path, &link).map_err(|e| {
        format!(
            "{e}\n--- {file}, link {link:?} ---\n{}",
            String::from_utf8_lossy(&bytes[..bytes.len().min(4000)])
        )
    })
}

// ---------------------------------------------------------------------------
// Generated files

/// Ordinary numbers: most inertials should reach the engines' rules.
const NICE: &[&str] = &[
    "1", "2", "3", "0.5", "0.1", "0", "0.01", "1e-3", "4", "-0.05",
];

/// Numbers a reader takes that break naive arithmetic: the edges of f64,
/// subnormals, negative zero, and spellings Rust's parser accepts.
const FINITE_EXTREME: &[&str] = &[
    "1e308",
    "-1e308",
    "1.7976931348623157e308",
    "-1.7976931348623157e308",
    "1e-308",
    "2.2250738585072014e-308",
    "5e-324",
    "1e-320",
    "-0",
    "-0.0",
    "1e154",
    "1e200",
    "-1e200",
    "1e-200",
    "-1",
    "+1",
    ".5",
    "5.",
    "1e-999",
    "&#49;",
    "1&#x2e;5",
    "1.0000000000000002",
    "0.30000000000000004",
];

/// Numbers a reader must refuse, at their place.
const BAD: &[&str] = &[
    "inf", "-inf", "nan", "NaN", "infinity", "1e999", "-1e999", "0x10", "", " ", "1_000", "1e",
    "1,2", "one", "1 2",
];

fn number() -> BoxedStrategy<String> {
    let long = "9".repeat(400);
    prop_oneof![
        40 => prop::sample::select(NICE).prop_map(str::to_string),
        6 => prop::sample::select(FINITE_EXTREME).prop_map(str::to_string),
        1 => prop::sample::select(BAD).prop_map(str::to_string),
        1 => Just(long),
        1 => Just(format!("0.{}1", "0".repeat(400))),
    ]
    .boxed()
}

/// Link names, plain, mirrored, duplicated and hostile: most are valid
/// XML (bidi, C1 controls, DEL, a tab, references, very long), a few not
/// (ESC, BEL, a quote that ends the attribute).
fn name() -> BoxedStrategy<String> {
    prop_oneof![
        12 => prop::sample::select(vec![
            "base", "arm", "left_finger", "right_finger", "FL_thigh", "FR_thigh", "l_hip", "r_hip",
            "tool", "a", "b",
        ])
        .prop_map(str::to_string),
        4 => prop::sample::select(vec![
            "\u{202e}evil", "tab\tname", "é", "x&lt;y", "&#x85;", "\u{85}c1", "\u{9b}csi",
            "a\u{7f}", "\u{feff}bom", "", "  spaced  ", "a::b", "inf", "nan", "left finger",
            "right finger", "&#x202e;r",
        ])
        .prop_map(str::to_string),
        1 => prop::sample::select(vec!["red\u{1b}[31m", "bell\u{7}", "line\nbreak", "quote\"", "a<b", "&bad;"])
            .prop_map(str::to_string),
        1 => (1usize..4).prop_map(|k| "n".repeat(10usize.pow(k as u32))),
    ]
    .boxed()
}

/// An inertial as written: mass, x y z, the six entries (xx xy xz yy
/// yz zz), an orientation.
type Written = (String, [String; 3], [String; 6], Option<String>);

#[derive(Clone, Debug)]
struct Spec {
    name: String,
    /// mass, x y z, the six entries, an orientation (format's own words).
    inertial: Option<Written>,
    /// The parent (an index, maybe itself or a later link: cycles) and
    /// whether the joint moves.
    joint: Option<(Index, bool)>,
}

fn spec() -> impl Strategy<Value = Spec> {
    let three = [number(), number(), number()];
    let six = [number(), number(), number(), number(), number(), number()];
    let rot = prop::option::weighted(
        0.3,
        prop_oneof![
            (number(), number(), number()).prop_map(|(a, b, c)| format!("{a} {b} {c}")),
            (number(), number(), number(), number())
                .prop_map(|(a, b, c, d)| format!("{a} {b} {c} {d}")),
            prop::sample::select(vec![
                "0 0 0",
                "1 0 0 0",
                "0.3 0.4 0.5",
                "1e200 0 0 0",
                "1e-200 0 0 0"
            ])
            .prop_map(str::to_string),
        ],
    );
    (
        name(),
        prop::option::weighted(0.85, (number(), three, six, rot)),
        prop::option::weighted(0.7, (any::<Index>(), any::<bool>())),
    )
        .prop_map(|(name, inertial, joint)| Spec {
            name,
            inertial,
            joint,
        })
}

/// Attribute-safe: a name may hold `"`, `<` or `&` and break the XML.
fn urdf(links: &[Spec], compiler: &str) -> String {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<robot name=\"r\">\n");
    if !compiler.is_empty() {
        s.push_str(&format!("  <mujoco><compiler {compiler}/></mujoco>\n"));
    }
    for l in links {
        s.push_str(&format!("  <link name=\"{}\">\n", l.name));
        if let Some((m, p, t, r)) = &l.inertial {
            let rpy = r
                .as_ref()
                .map_or(String::new(), |r| format!(" rpy=\"{r}\""));
            s.push_str(&format!(
                "    <inertial>\n      <origin xyz=\"{} {} {}\"{rpy}/>\n      <mass value=\"{m}\"/>\n      <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" iyz=\"{}\" izz=\"{}\"/>\n    </inertial>\n",
                p[0], p[1], p[2], t[0], t[1], t[2], t[3], t[4], t[5]
            ));
        }
        s.push_str("  </link>\n");
    }
    for (i, l) in links.iter().enumerate() {
        if let Some((parent, moving)) = &l.joint {
            let p = &links[parent.index(links.len())].name;
            let kind = if *moving { "revolute" } else { "fixed" };
            s.push_str(&format!(
                "  <joint name=\"j{i}\" type=\"{kind}\">\n    <parent link=\"{p}\"/>\n    <child link=\"{}\"/>\n  </joint>\n",
                l.name
            ));
        }
    }
    s + "</robot>\n"
}

fn sdf(links: &[Spec], nested: bool) -> String {
    let mut s =
        String::from("<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n  <model name=\"m\">\n");
    let link = |l: &Spec| {
        let mut s = format!("    <link name=\"{}\">\n", l.name);
        if let Some((m, p, t, r)) = &l.inertial {
            let (attr, rot) = match r.as_deref() {
                Some(r) if r.split(' ').count() == 4 => {
                    (" rotation_format=\"quat_xyzw\"", r.to_string())
                }
                Some(r) => ("", r.to_string()),
                None => ("", "0 0 0".to_string()),
            };
            s.push_str(&format!(
                "      <inertial>\n        <pose{attr}>{} {} {} {rot}</pose>\n        <mass>{m}</mass>\n        <inertia><ixx>{}</ixx><ixy>{}</ixy><ixz>{}</ixz><iyy>{}</iyy><iyz>{}</iyz><izz>{}</izz></inertia>\n      </inertial>\n",
                p[0], p[1], p[2], t[0], t[1], t[2], t[3], t[4], t[5]
            ));
        }
        s + "    </link>\n"
    };
    let half = if nested { links.len() / 2 } else { links.len() };
    for l in &links[..half] {
        s.push_str(&link(l));
    }
    if half < links.len() {
        s.push_str("    <model name=\"inner\">\n");
        for l in &links[half..] {
            s.push_str(&link(l));
        }
        s.push_str("    </model>\n");
    }
    for (i, l) in links.iter().enumerate() {
        if let Some((parent, moving)) = &l.joint {
            let scoped = |j: usize| {
                if j >= half {
                    format!("inner::{}", links[j].name)
                } else {
                    links[j].name.clone()
                }
            };
            let kind = if *moving { "revolute" } else { "fixed" };
            s.push_str(&format!(
                "    <joint name=\"j{i}\" type=\"{kind}\"><parent>{}</parent><child>{}</child></joint>\n",
                scoped(parent.index(links.len())),
                scoped(i)
            ));
        }
    }
    s + "  </model>\n</sdf>\n"
}

/// Bodies nested as their joints' parents say (a parent before the body),
/// else under the world body.
fn mjcf(links: &[Spec], compiler: &str, full: bool) -> String {
    let n = links.len();
    let parent: Vec<Option<usize>> = links
        .iter()
        .enumerate()
        .map(|(i, l)| l.joint.as_ref().map(|(p, _)| p.index(n)).filter(|&p| p < i))
        .collect();
    fn body(
        i: usize,
        links: &[Spec],
        parent: &[Option<usize>],
        full: bool,
        depth: usize,
    ) -> String {
        let l = &links[i];
        let pad = "  ".repeat(depth + 2);
        let mut s = format!("{pad}<body name=\"{}\">\n", l.name);
        if l.joint.as_ref().is_some_and(|(_, m)| *m) {
            s.push_str(&format!("{pad}  <joint/>\n"));
        }
        if let Some((m, p, t, r)) = &l.inertial {
            let inertia = if full {
                format!(
                    "fullinertia=\"{} {} {} {} {} {}\"",
                    t[0], t[3], t[5], t[1], t[2], t[4]
                )
            } else {
                let turn = match r.as_deref() {
                    Some(r) if r.split(' ').count() == 4 => format!(" quat=\"{r}\""),
                    Some(r) => format!(" euler=\"{r}\""),
                    None => String::new(),
                };
                format!("diaginertia=\"{} {} {}\"{turn}", t[0], t[3], t[5])
            };
            s.push_str(&format!(
                "{pad}  <inertial pos=\"{} {} {}\" mass=\"{m}\" {inertia}/>\n",
                p[0], p[1], p[2]
            ));
        }
        for j in (0..links.len()).filter(|&j| parent[j] == Some(i)) {
            s.push_str(&body(j, links, parent, full, depth + 1));
        }
        s + &format!("{pad}</body>\n")
    }
    let mut s = String::from("<mujoco model=\"m\">\n");
    if !compiler.is_empty() {
        s.push_str(&format!("  <compiler {compiler}/>\n"));
    }
    s.push_str("  <worldbody>\n");
    for i in (0..n).filter(|&i| parent[i].is_none()) {
        s.push_str(&body(i, links, &parent, full, 0));
    }
    s + "  </worldbody>\n</mujoco>\n"
}

const COMPILERS: &[&str] = &[
    "",
    "",
    "balanceinertia=\"true\"",
    "boundmass=\"1e-3\" boundinertia=\"1e-6\"",
    "boundmass=\"-1\" boundinertia=\"-1e308\"",
    "inertiafromgeom=\"true\"",
    "inertiafromgeom=\"false\"",
    "angle=\"radian\" eulerseq=\"XYZ\"",
    "boundinertia=\"1e308\" balanceinertia=\"true\"",
];

/// A generated file: its name and text.
fn generated() -> impl Strategy<Value = (String, String)> {
    (
        0usize..4,
        prop::collection::vec(spec(), 1..7),
        prop::sample::select(COMPILERS),
        any::<bool>(),
    )
        .prop_map(|(format, links, compiler, flag)| match format {
            0 => ("gen.urdf".to_string(), urdf(&links, compiler)),
            1 => ("gen.sdf".to_string(), sdf(&links, flag)),
            2 => ("gen.xml".to_string(), mjcf(&links, compiler, flag)),
            // An MJCF file by its name alone: not `*.urdf` or `*.sdf`.
            _ => ("gen-mjcf.xml".to_string(), mjcf(&links, compiler, !flag)),
        })
}

#[test]
fn generated_robot_files_keep_the_promise() {
    let dir = crate::common::scratch("robots_hostile", "generated");
    let strategy = (generated(), 0.0..1.0f64);
    property(
        "robots generated",
        GENERATED,
        strategy,
        |((file, text), pick)| hostile_robot(&dir, file, text.as_bytes(), *pick),
    );
}

// ---------------------------------------------------------------------------
// Mutated fixtures

/// The robot descriptions of the project: valid, known-bad, and the
/// snapshot cases' inputs.
fn fixtures() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> = ["shapes/robots", "tests/robots", "tests/cmd/robots.in"]
        .iter()
        .flat_map(|d| std::fs::read_dir(root.join(d)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.extension()
                .is_some_and(|x| x == "urdf" || x == "sdf" || x == "xml")
        })
        .collect();
    files.sort();
    assert!(files.len() >= 20, "the robot fixtures moved: {files:?}");
    files
}

/// What `Insert` puts in: XML punctuation and structure, entities,
/// unicode and controls.
const SNIPPETS: &[&str] = &[
    "<",
    ">",
    "/>",
    "\"",
    "'",
    "&",
    "&amp;",
    "&#0;",
    "&#x1b;",
    "&lt;",
    "<!--",
    "-->",
    "<![CDATA[1]]>",
    "<?pi x?>",
    "\n",
    "\r\n",
    "\r",
    "\t",
    "\u{0}",
    "\u{1b}",
    "\u{7f}",
    "\u{85}",
    "\u{feff}",
    "\u{202e}",
    "é",
    "🦀",
    "<link name=\"left_x\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>",
    "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"2.5\"/></inertial>",
    "<joint name=\"c\" type=\"revolute\"><parent link=\"base\"/><child link=\"base\"/></joint>",
    "<body name=\"deep\"><joint/><body>",
    "</body>",
    "<model name=\"m2\"><link name=\"l\"/></model>",
    "<inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 3\"/>",
    "<include file=\"x.xml\"/>",
    "<compiler balanceinertia=\"true\"/>",
    "<frame>",
    "xmlns:x=\"u\" ",
    "x:",
    // Default classes, frames and followers (issue 34, second round).
    "<default class=\"c\"><joint type=\"slide\" axis=\"1 0 0\"/><geom size=\"0.1\"/></default>",
    " class=\"c\" ",
    " childclass=\"nope\" ",
    "<pose relative_to=\"base\">0 0 1 0 0 0</pose>",
    "<frame name=\"f\" attached_to=\"f\"/>",
    "<mimic joint=\"j\"><multiplier>2</multiplier></mimic>",
];

#[derive(Clone, Debug)]
enum Mutation {
    DeleteLine(Index),
    DuplicateLine(Index),
    ReplaceNumber(Index, String),
    ReplaceName(Index, String),
    Truncate(Index),
    Insert(Index, &'static str),
    Crlf,
    Bom,
    NotUtf8(Index),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<Index>().prop_map(Mutation::DeleteLine),
        1 => any::<Index>().prop_map(Mutation::DuplicateLine),
        5 => (any::<Index>(), number()).prop_map(|(i, v)| Mutation::ReplaceNumber(i, v)),
        2 => (any::<Index>(), name()).prop_map(|(i, v)| Mutation::ReplaceName(i, v)),
        1 => any::<Index>().prop_map(Mutation::Truncate),
        3 => (any::<Index>(), prop::sample::select(SNIPPETS)).prop_map(|(i, s)| Mutation::Insert(i, s)),
        1 => Just(Mutation::Crlf),
        1 => Just(Mutation::Bom),
        1 => any::<Index>().prop_map(Mutation::NotUtf8),
    ]
}

/// Byte ranges of the numbers in `text`: maximal runs of digits, `.`, `e`,
/// `E`, `+`, `-` that contain a digit and are not part of a word.
fn numbers(text: &str) -> Vec<std::ops::Range<usize>> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let word_before = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if !word_before && (b[i].is_ascii_digit() || b"-.".contains(&b[i])) {
            let mut j = i + 1;
            while j < b.len() && (b[j].is_ascii_digit() || b".eE+-".contains(&b[j])) {
                j += 1;
            }
            let word_after = j < b.len() && (b[j].is_ascii_alphabetic() || b[j] == b'_');
            if !word_after && b[i..j].iter().any(u8::is_ascii_digit) {
                out.push(i..j);
            }
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

/// Byte ranges of the values of `name="…"` and `name='…'`.
fn names(text: &str) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    for q in ['"', '\''] {
        let open = format!("name={q}");
        let mut at = 0;
        while let Some(i) = text[at..].find(&open) {
            let start = at + i + open.len();
            match text[start..].find(q) {
                Some(end) => out.push(start..start + end),
                None => break,
            }
            at = start;
        }
    }
    out
}

fn apply(text: &[u8], m: &Mutation) -> Vec<u8> {
    let Ok(s) = std::str::from_utf8(text) else {
        // Already not UTF-8: only cut further.
        return match m {
            Mutation::Truncate(i) => text[..i.index(text.len() + 1)].to_vec(),
            _ => text.to_vec(),
        };
    };
    let mut out = text.to_vec();
    let lines: Vec<(usize, &str)> = {
        let mut at = 0;
        s.split_inclusive('\n')
            .map(|l| {
                let start = at;
                at += l.len();
                (start, l)
            })
            .collect()
    };
    let boundary = |i: &Index| {
        let mut at = i.index(s.len() + 1);
        while !s.is_char_boundary(at) {
            at -= 1;
        }
        at
    };
    match m {
        Mutation::DeleteLine(i) | Mutation::DuplicateLine(i) if !lines.is_empty() => {
            let (start, line) = lines[i.index(lines.len())];
            let with = if matches!(m, Mutation::DeleteLine(_)) {
                String::new()
            } else {
                format!("{line}{line}")
            };
            out.splice(start..start + line.len(), with.into_bytes());
        }
        Mutation::ReplaceNumber(i, v) => {
            let nums = numbers(s);
            if !nums.is_empty() {
                out.splice(nums[i.index(nums.len())].clone(), v.bytes());
            }
        }
        Mutation::ReplaceName(i, v) => {
            let found = names(s);
            if !found.is_empty() {
                out.splice(found[i.index(found.len())].clone(), v.bytes());
            }
        }
        Mutation::Truncate(i) => out.truncate(i.index(out.len() + 1)),
        Mutation::Insert(i, snippet) => {
            let at = boundary(i);
            out.splice(at..at, snippet.bytes());
        }
        Mutation::Crlf => out = s.replace("\r\n", "\n").replace('\n', "\r\n").into_bytes(),
        Mutation::Bom => out.splice(0..0, "\u{feff}".bytes()).for_each(drop),
        Mutation::NotUtf8(i) => {
            let at = boundary(i);
            out.splice(at..at, [0xff, 0xc3]);
        }
        _ => {}
    }
    out
}

#[test]
fn mutated_robot_fixtures_keep_the_promise() {
    let dir = crate::common::scratch("robots_hostile", "mutated");
    let files = fixtures();
    let originals: Vec<Vec<u8>> = files.iter().map(|f| std::fs::read(f).unwrap()).collect();
    let strategy = (
        0..files.len(),
        prop::collection::vec(mutation(), 1..=3),
        0.0..1.0f64,
    );
    property(
        "robots mutated",
        MUTATED,
        strategy,
        |(which, mutations, pick)| {
            let text = mutations
                .iter()
                .fold(originals[*which].clone(), |t, m| apply(&t, m));
            let name = files[*which].file_name().unwrap().to_str().unwrap();
            hostile_robot(&dir, &format!("mutant-{name}"), &text, *pick)
                .map_err(|e| format!("{e}\n--- {name} with {mutations:?}"))
        },
    );
}

/// The fixtures themselves keep the promise: the harness accepts good
/// files, and checks known-bad ones.
#[test]
fn robot_fixtures_keep_the_promise() {
    let dir = crate::common::scratch("robots_hostile", "fixtures");
    for f in fixtures() {
        let bytes = std::fs::read(&f).unwrap();
        let name = f.file_name().unwrap().to_str().unwrap();
        for pick in [0.0, 0.5, 0.99] {
            hostile_robot(&dir, name, &bytes, pick).unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

// ---------------------------------------------------------------------------
// Shapes no generator reaches by chance

/// A URDF link with a valid inertial.
fn urdf_link(name: &str) -> String {
    format!(
        "<link name=\"{name}\"><inertial><origin xyz=\"0 0 0\"/><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0.1\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1.5\"/></inertial></link>\n"
    )
}

#[test]
fn elements_nested_thousands_deep_are_refused_or_read_without_overflowing_the_stack() {
    // In process, on a thread of 2 MiB: the readers' walks and update's
    // are iterative, and a tree nested 1000 deep is refused.
    let dir = crate::common::scratch("robots_hostile", "deep");
    let inertial = "<inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/>";
    for (depth, refused) in [(990, false), (1_000, true), (20_000, true)] {
        let body = |i: usize| format!("<body name=\"b{i}\"><joint/>{inertial}\n");
        let mjcf = format!(
            "<mujoco><worldbody>\n{}{}</worldbody></mujoco>\n",
            (0..depth).map(body).collect::<String>(),
            "</body>".repeat(depth)
        );
        let model =
            |i: usize| format!("<model name=\"m{i}\"><link name=\"l\"><inertial/></link>\n");
        let sdf = format!(
            "<sdf version=\"1.9\">\n{}{}</sdf>\n",
            (0..depth).map(model).collect::<String>(),
            "</model>".repeat(depth)
        );
        let urdf = format!(
            "<robot name=\"r\">{}<link name=\"a\"/></robot>\n",
            "<x>".repeat(depth) + &"</x>".repeat(depth)
        );
        for (file, text, link) in [
            (format!("deep{depth}.xml"), mjcf, "b1"),
            (format!("deep{depth}.sdf"), sdf, "l"),
            (format!("deep{depth}.urdf"), urdf, "a"),
        ] {
            let path = dir.join(&file);
            std::fs::write(&path, &text).unwrap();
            // Every command on the deepest accepted MJCF; on the others,
            // check and update (the SDFormat names, `m1::m2::…`, make its
            // tables megabytes long).
            if depth == 990 && file.ends_with(".xml") {
                robot_hostile(&path, link).unwrap_or_else(|e| panic!("{file}: {e}"));
            }
            let p = path.to_str().unwrap();
            let out = run(&["check", "--format", "json", p]).unwrap().unwrap();
            let deep = out.stderr.contains("elements deep");
            assert_eq!(out.status == 2 && deep, refused, "{file}: {}", out.stderr);
            let update = run(&[
                "export",
                &part(),
                "--update",
                p,
                "--link",
                link,
                "--dry-run",
            ])
            .unwrap();
            match update {
                Ok(out) => assert!(!refused && out.status == 0, "{file}"),
                Err(d) => assert!(
                    refused && d.to_string().contains("elements deep"),
                    "{file}: {d}"
                ),
            }
        }
    }
}

/// A URDF of `n` links: a chain of moving links, each with a fixed child,
/// mirror pairs by name, every hundredth name used twice.
fn many_links(n: usize) -> String {
    let mut s = String::from("<robot name=\"many\">\n");
    for i in 0..n {
        let side = if i.is_multiple_of(2) { "left" } else { "right" };
        let name = if i % 100 == 99 {
            "dup".to_string()
        } else {
            format!("{side}_{}", i / 2)
        };
        s.push_str(&urdf_link(&name));
    }
    let name = |i: usize| {
        if i % 100 == 99 {
            "dup".to_string()
        } else {
            format!(
                "{}_{}",
                if i.is_multiple_of(2) { "left" } else { "right" },
                i / 2
            )
        }
    };
    for i in 1..n {
        let (parent, kind) = if i.is_multiple_of(2) {
            (i - 2, "revolute")
        } else {
            (i - 1, "fixed")
        };
        s.push_str(&format!(
            "<joint name=\"j{i}\" type=\"{kind}\"><parent link=\"{}\"/><child link=\"{}\"/></joint>\n",
            name(parent),
            name(i)
        ));
    }
    s + "</robot>\n"
}

/// 10⁴ links through `check` (JSON and table) and an update. Their time
/// is benches/robots.sh's (docs/performance.md), their work
/// `four_times_the_links_are_four_times_the_work`'s; here only `run`'s hang
/// guard holds the clock. `ROBOTS_MANY=100000` tries more.
#[test]
fn ten_thousand_links_are_checked_and_updated() {
    let n = std::env::var("ROBOTS_MANY")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(10_000);
    let dir = crate::common::scratch("robots_hostile", "many");
    let path = dir.join("many.urdf");
    std::fs::write(&path, many_links(n)).unwrap();
    let p = path.to_str().unwrap();
    for args in [
        vec!["check", "--format", "json", p],
        vec!["check", p],
        vec![
            "export",
            &part(),
            "--update",
            p,
            "--link",
            "right_7",
            "--dry-run",
        ],
    ] {
        let out = run(&args).unwrap().unwrap();
        assert!(out.status <= 1, "{args:?}: {}", out.stderr);
    }
}

/// The steps of work (`robot::check::steps`, counted on this thread) of
/// checking `many_links(n)` under every engine.
fn check_steps(n: usize) -> u64 {
    let source = Source::new("many.urdf", many_links(n));
    let d = read(&source, Dialect::Urdf).unwrap();
    let before = massprop::robot::check::steps();
    let r = massprop::robot::check::check(&source, &d, &massprop::robot::engine::Engine::ALL);
    assert_eq!(r.links.len(), n);
    massprop::robot::check::steps() - before
}

/// Linear, counted without a clock: four times the links, about four
/// times the steps; a pass over all links once per link (as the line
/// numbers of the spans and the mirror pairs once were: 23 s for 10⁴
/// links) would take sixteen.
#[test]
fn four_times_the_links_are_four_times_the_work() {
    let (small, large) = (check_steps(2_500), check_steps(10_000));
    assert!(small > 2_500, "{small} steps: the work is not counted");
    assert!(
        large <= 5 * small,
        "{small} steps for 2,500 links, {large} for 10,000"
    );
}

#[test]
fn cycles_of_joints_are_read_and_checked() {
    let dir = crate::common::scratch("robots_hostile", "cycles");
    let joint = |i: usize, kind: &str, p: &str, c: &str| {
        format!(
            "<joint name=\"j{i}\" type=\"{kind}\"><parent link=\"{p}\"/><child link=\"{c}\"/></joint>\n"
        )
    };
    let massless = |n: &str| format!("<link name=\"{n}\"/>\n");
    for (k, kinds) in [
        ["fixed", "fixed"],
        ["revolute", "fixed"],
        ["revolute", "revolute"],
    ]
    .iter()
    .enumerate()
    {
        // a → b → a, a → a, and a longer loop through massless links.
        let text = format!(
            "<robot name=\"r\">{}{}{}{}{}{}{}{}{}</robot>\n",
            massless("a"),
            massless("b"),
            massless("c"),
            urdf_link("d"),
            joint(0, kinds[0], "a", "b"),
            joint(1, kinds[1], "b", "a"),
            joint(2, kinds[1], "a", "a"),
            joint(3, kinds[0], "b", "c"),
            joint(4, kinds[1], "c", "b"),
        );
        let path = dir.join(format!("cycle{k}.urdf"));
        std::fs::write(&path, &text).unwrap();
        robot_hostile(&path, "d").unwrap_or_else(|e| panic!("{k}: {e}"));
    }
}

#[test]
fn an_entity_expansion_bomb_is_refused() {
    let dir = crate::common::scratch("robots_hostile", "laughs");
    let mut dtd = String::from("<!ENTITY l0 \"lol\">\n");
    for i in 1..10 {
        dtd.push_str(&format!(
            "<!ENTITY l{i} \"{}\">\n",
            format!("&l{};", i - 1).repeat(10)
        ));
    }
    for (file, root) in [
        ("laughs.urdf", "robot"),
        ("laughs.sdf", "sdf"),
        ("laughs.xml", "mujoco"),
    ] {
        let text = format!(
            "<?xml version=\"1.0\"?>\n<!DOCTYPE {root} [\n{dtd}]>\n<{root} name=\"&l9;\"><link name=\"&l9;\"/></{root}>\n"
        );
        let path = dir.join(file);
        std::fs::write(&path, &text).unwrap();
        robot_hostile(&path, "l").unwrap_or_else(|e| panic!("{file}: {e}"));
        let out = run(&["check", path.to_str().unwrap()]).unwrap().unwrap();
        assert_eq!(out.status, 2, "{file}: {}", out.stderr);
        assert!(out.stderr.contains("entity"), "{file}: {}", out.stderr);
    }
}

#[test]
fn byte_order_marks_line_ends_and_bytes_that_are_not_utf8() {
    let dir = crate::common::scratch("robots_hostile", "bytes");
    let base = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("shapes/robots/arm.urdf"),
    )
    .unwrap();
    let crlf = base.replace('\n', "\r\n");
    let variants: Vec<(&str, Vec<u8>)> = vec![
        ("bom.urdf", format!("\u{feff}{base}").into_bytes()),
        ("crlf.urdf", crlf.clone().into_bytes()),
        ("bom-crlf.urdf", format!("\u{feff}{crlf}").into_bytes()),
        ("mixed.urdf", base.replacen('\n', "\r\n", 5).into_bytes()),
        ("cr.urdf", base.replace('\n', "\r").into_bytes()),
        ("latin1.urdf", {
            let mut b = base.clone().into_bytes();
            b.splice(10..10, [0xe9]);
            b
        }),
        (
            "utf16.urdf",
            base.encode_utf16().flat_map(u16::to_le_bytes).collect(),
        ),
        ("empty.urdf", Vec::new()),
        ("nul.urdf", vec![0; 64]),
        ("root.urdf", b"<sdf version=\"1.9\"/>".to_vec()),
        ("none.xml", b"<project/>".to_vec()),
        ("text.urdf", b"just text".to_vec()),
    ];
    for (file, bytes) in variants {
        hostile_robot(&dir, file, &bytes, 0.3).unwrap_or_else(|e| panic!("{file}: {e}"));
    }
    // A BOM and CRLF are kept by an update, and the file reads back.
    let path = dir.join("bom-crlf.urdf");
    let before = std::fs::read(&path).unwrap();
    run(&[
        "export",
        &part(),
        "--update",
        path.to_str().unwrap(),
        "--link",
        "forearm",
    ])
    .unwrap()
    .unwrap();
    let after = std::fs::read_to_string(&path).unwrap();
    assert!(after.starts_with('\u{feff}'));
    assert_eq!(after.matches('\n').count(), after.matches("\r\n").count());
    assert_ne!(before, after.into_bytes());
}

/// Every robot description that once broke the promise stays a test: the
/// files `tests/fuzz-regressions/robot-*` (the fuzz target robot_files'
/// findings and this test's, docs/fuzzing.md), each aimed at each of its
/// links in turn.
#[test]
fn robot_fuzz_regressions_keep_the_promise() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz-regressions");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("robot-"))
        })
        .collect();
    files.sort();
    assert!(
        files.len() >= 6,
        "tests/fuzz-regressions/ lost its robot files"
    );
    let dir = crate::common::scratch("robots_hostile", "regressions");
    for f in files {
        let bytes = std::fs::read(&f).unwrap();
        let name = f.file_name().unwrap().to_str().unwrap();
        let links = described(&f, &bytes).map_or(1, |(_, d)| d.links.len().max(1));
        for k in 0..links {
            let pick = (k as f64 + 0.5) / links as f64;
            hostile_robot(&dir, name, &bytes, pick).unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

// ---------------------------------------------------------------------------
// MJCF bodies weighed from their geoms (issue 34, third round): mesh
// assets (a closed block, an open surface, bytes that are no mesh, a file
// that is missing or outside the model's directory), `meshdir`, `scale`,
// every `<mesh inertia>`, geoms inside nested `<frame>`s and placed by
// their default class.

/// A closed block and an open surface, as OBJ; bytes that are no mesh.
const MESH_FILES: &[(&str, &str)] = &[
    (
        "block.obj",
        "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\n\
         f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n",
    ),
    (
        "open.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n",
    ),
    ("junk.stl", "solid nothing\nendsolid\n\u{0}\u{1}"),
];

/// What a mesh asset's `file` may name.
const MESH_NAMES: &[&str] = &[
    "block.obj",
    "block.obj",
    "open.obj",
    "junk.stl",
    "missing.obj",
    "../outside.obj",
    "/etc/passwd",
    "block.OBJ",
    "",
];

const MESH_INERTIAS: &[&str] = &["", "", "exact", "legacy", "convex", "shell", "solid"];

const ORIENTATION_FORMS: &[(&str, usize)] = &[
    ("quat", 4),
    ("euler", 3),
    ("axisangle", 4),
    ("zaxis", 3),
    ("xyaxes", 6),
];

fn numbers_of(n: usize) -> BoxedStrategy<String> {
    prop::collection::vec(number(), n..=n)
        .prop_map(|v| v.join(" "))
        .boxed()
}

/// An orientation attribute (one form), or none.
fn turn_attr() -> BoxedStrategy<String> {
    prop_oneof![
        2 => Just(String::new()),
        3 => (prop::sample::select(ORIENTATION_FORMS), numbers_of(6))
            .prop_map(|((form, n), nums)| {
                let v: Vec<&str> = nums.split(' ').take(n).collect();
                format!(" {form}=\"{}\"", v.join(" "))
            }),
    ]
    .boxed()
}

/// One geom: a type (a mesh sometimes), a size, a placement and a weight.
fn mesh_geom() -> BoxedStrategy<String> {
    (
        prop::sample::select(&["mesh", "mesh", "box", "capsule", "sphere", "plane", ""][..]),
        numbers_of(3),
        prop_oneof![
            Just(String::new()),
            numbers_of(3).prop_map(|p| format!(" pos=\"{p}\"")),
            numbers_of(6).prop_map(|p| format!(" fromto=\"{p}\"")),
        ],
        turn_attr(),
        prop_oneof![
            3 => Just(String::new()),
            1 => number().prop_map(|m| format!(" mass=\"{m}\"")),
            1 => number().prop_map(|d| format!(" density=\"{d}\"")),
            1 => Just(" shellinertia=\"true\"".to_string()),
        ],
        prop::sample::select(&["m0", "m1", "m2", "nope"][..]),
    )
        .prop_map(|(kind, size, place, turn, weight, mesh)| {
            let kind = if kind.is_empty() {
                String::new()
            } else {
                format!(" type=\"{kind}\"")
            };
            format!("<geom{kind} mesh=\"{mesh}\" size=\"{size}\"{place}{turn}{weight}/>")
        })
        .boxed()
}

/// A generated MJCF file of mesh assets, classes and frames.
fn mesh_model() -> impl Strategy<Value = String> {
    (
        prop::collection::vec(
            (
                prop::sample::select(MESH_NAMES),
                prop::sample::select(MESH_INERTIAS),
                prop_oneof![Just(String::new()), numbers_of(3)],
            ),
            1..4,
        ),
        prop::sample::select(&["", "meshdir=\"sub\"", "meshdir=\"..\"", "assetdir=\".\""][..]),
        (mesh_geom(), turn_attr()),
        prop::collection::vec((mesh_geom(), 0usize..3, turn_attr(), any::<bool>()), 1..5),
        prop::sample::select(&["", "inertiafromgeom=\"true\""][..]),
    )
        .prop_map(|(meshes, dir, (default_geom, frame_turn), geoms, fromgeom)| {
            let assets: String = meshes
                .iter()
                .enumerate()
                .map(|(i, (file, inertia, scale))| {
                    let mut a = format!("<mesh name=\"m{i}\" file=\"{file}\"");
                    if !inertia.is_empty() {
                        a.push_str(&format!(" inertia=\"{inertia}\""));
                    }
                    if !scale.is_empty() {
                        a.push_str(&format!(" scale=\"{scale}\""));
                    }
                    a + "/>"
                })
                .collect();
            let mut body = String::new();
            for (g, depth, turn, joint) in &geoms {
                if *joint {
                    body.push_str("<body><joint/>");
                }
                for _ in 0..*depth {
                    body.push_str(&format!("<frame pos=\"0.1 0 0\"{turn}{frame_turn}>"));
                }
                body.push_str(g);
                body.push_str(&"</frame>".repeat(*depth));
                if *joint {
                    body.push_str("</body>");
                }
            }
            format!(
                "<mujoco>\n<compiler {dir} {fromgeom}/>\n<default>{}</default>\n<asset>{assets}</asset>\n\
                 <worldbody>\n<body name=\"b\"><freejoint/>\n{body}\n</body>\n</worldbody>\n</mujoco>\n",
                default_geom
            )
        })
}

#[test]
fn generated_mjcf_mesh_frame_and_class_files_keep_the_promise() {
    let dir = crate::common::scratch("robots_hostile", "mesh_models");
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    for (name, text) in MESH_FILES {
        std::fs::write(dir.join(name), text).unwrap();
        std::fs::write(dir.join("sub").join(name), text).unwrap();
    }
    std::fs::write(dir.parent().unwrap().join("outside.obj"), MESH_FILES[0].1).unwrap();
    property(
        "MJCF mesh, frame and class files generated",
        GENERATED,
        (mesh_model(), 0.0..1.0f64),
        |(text, pick)| hostile_robot(&dir, "mesh.xml", text.as_bytes(), *pick),
    );
}

// ---------------------------------------------------------------------------
// SDFormat scopes: nested models, worlds, includes (issue 34)

/// Names an SDFormat reference may give: the generated frames', scoped
/// ones, the reserved ones, and names of nothing.
const SDF_REFS: &[&str] = &[
    "base",
    "arm",
    "n",
    "n::arm",
    "n::n::base",
    "s::l",
    "__model__",
    "n::__model__",
    "world",
    "",
    "f",
    "j",
    "nothing",
    "::",
    "n::",
    "::arm",
];

/// What an `<include>` may name: a model beside it, itself (a cycle), a
/// directory with a `model.config`, nothing, a place outside, a URL.
const SDF_URIS: &[&str] = &[
    "side.sdf",
    "gen-scope.sdf",
    "sidedir",
    "model://sidedir",
    "model://",
    "model://..",
    "missing.sdf",
    "../../../../../../../../etc",
    "https://fuel.gazebosim.org/x",
    "",
];

/// One piece of a generated model: an element, or the start or the end
/// of a nested model.
fn sdf_piece() -> BoxedStrategy<String> {
    let r = || prop::sample::select(SDF_REFS);
    let name = || prop::sample::select(vec!["base", "arm", "n", "s", "f", "j", "l"]);
    prop_oneof![
        4 => (name(), r(), number()).prop_map(|(n, r, m)| format!(
            "<link name=\"{n}\"><pose relative_to=\"{r}\">0 0 0.5 0 0 0.3</pose><inertial><mass>{m}</mass></inertial></link>"
        )),
        3 => (name(), r(), r()).prop_map(|(n, c, p)| format!(
            "<model name=\"{n}\" canonical_link=\"{c}\" placement_frame=\"{p}\"><pose>0.1 0 0 0 0 0</pose>"
        )),
        3 => Just("</model>".to_string()),
        3 => (prop::sample::select(SDF_URIS), name(), r(), r(), any::<bool>()).prop_map(
            |(u, n, rel, pf, st)| format!(
                "<include><uri>{u}</uri><name>{n}</name><pose relative_to=\"{rel}\">1 0 0 0 0 1</pose><placement_frame>{pf}</placement_frame><static>{st}</static></include>"
            )
        ),
        2 => (name(), r()).prop_map(|(n, a)| format!(
            "<frame name=\"{n}\" attached_to=\"{a}\"><pose>0 1 0 0 0 0</pose></frame>"
        )),
        4 => (name(), prop::sample::select(vec!["revolute", "fixed", "prismatic", "ball"]), r(), r(), r(), r())
            .prop_map(|(n, t, p, c, e, m)| format!(
                "<joint name=\"{n}\" type=\"{t}\"><parent>{p}</parent><child>{c}</child><axis><xyz expressed_in=\"{e}\">0 0 1</xyz><mimic joint=\"{m}\"/></axis></joint>"
            )),
    ]
    .boxed()
}

/// A model or a world of generated pieces, nested models balanced.
fn sdf_scoped() -> impl Strategy<Value = String> {
    (any::<bool>(), prop::collection::vec(sdf_piece(), 0..14)).prop_map(|(world, pieces)| {
        let (open, close) = if world {
            ("<world name=\"w\">", "</world>")
        } else {
            ("<model name=\"m\">", "</model>")
        };
        let mut s = format!("<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n{open}\n");
        let mut depth = 0;
        for p in pieces {
            if p == "</model>" {
                if depth == 0 {
                    continue;
                }
                depth -= 1;
            } else if p.starts_with("<model") {
                depth += 1;
            }
            s.push_str(&p);
            s.push('\n');
        }
        s.push_str(&"</model>".repeat(depth));
        s + close + "\n</sdf>\n"
    })
}

#[test]
fn generated_sdformat_scopes_and_includes_keep_the_promise() {
    let dir = crate::common::scratch("robots_hostile", "scopes");
    let side = "<?xml version=\"1.0\"?>\n<sdf version=\"1.9\"><model name=\"side\"><link name=\"l\"><inertial><mass>1</mass></inertial></link><link name=\"base\"/><joint name=\"j\" type=\"revolute\"><parent>l</parent><child>base</child></joint></model></sdf>\n";
    std::fs::write(dir.join("side.sdf"), side).unwrap();
    std::fs::create_dir_all(dir.join("sidedir")).unwrap();
    std::fs::write(dir.join("sidedir/s.sdf"), side).unwrap();
    std::fs::write(
        dir.join("sidedir/model.config"),
        "<?xml version=\"1.0\"?><model><sdf version=\"1.9\">s.sdf</sdf></model>",
    )
    .unwrap();
    property(
        "SDFormat scopes generated",
        GENERATED,
        (sdf_scoped(), 0.0..1.0f64),
        |(text, pick)| hostile_robot(&dir, "gen-scope.sdf", text.as_bytes(), *pick),
    );
}

// ---------------------------------------------------------------------------
// MJCF includes anywhere (issue 34, item 1): a valid model written in one
// file, then split at random elements into included files (nested, in
// sections, bodies, frames, default classes), reports bit for bit as the
// one file: MuJoCo puts an included file's root's children where the
// `<include>` stands.

/// A small deterministic generator (SplitMix64): the model and its cuts
/// come from the seeds proptest draws.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    fn nums(&mut self, n: usize, lo: f64, hi: f64) -> String {
        (0..n)
            .map(|_| format!("{:?}", lo + (hi - lo) * self.unit()))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// An XML element: its tag with attributes, and its children.
struct El {
    head: String,
    tag: &'static str,
    kids: Vec<El>,
}

fn el(tag: &'static str, attrs: String, kids: Vec<El>) -> El {
    El {
        head: format!("{tag}{attrs}"),
        tag,
        kids,
    }
}

/// A body of the generated model (`depth` more levels below it), its
/// joints' names pushed to `joints`.
fn split_body(r: &mut Mix, depth: usize, count: &mut usize, joints: &mut Vec<String>) -> El {
    *count += 1;
    let k = *count;
    let mut attrs = format!(" name=\"b{k}\" pos=\"{}\"", r.nums(3, -0.5, 0.5));
    if r.chance(0.5) {
        attrs.push_str(&format!(" euler=\"{}\"", r.nums(3, -90.0, 90.0)));
    }
    if r.chance(0.3) {
        attrs.push_str(&format!(" childclass=\"{}\"", ["a", "b"][r.below(2)]));
    }
    let mut kids = Vec::new();
    for j in 0..r.below(3) {
        let name = format!("j{k}_{j}");
        let class = if r.chance(0.4) { " class=\"a\"" } else { "" };
        kids.push(el("joint", format!(" name=\"{name}\"{class}"), Vec::new()));
        joints.push(name);
    }
    if r.chance(0.3) {
        let a = format!(
            " pos=\"{}\" mass=\"{:?}\" diaginertia=\"0.02 0.03 0.04\"",
            r.nums(3, -0.1, 0.1),
            0.5 + 2.0 * r.unit()
        );
        kids.push(el("inertial", a, Vec::new()));
    }
    for _ in 0..1 + r.below(2) {
        let kind = ["sphere", "box", "capsule", "cylinder", "ellipsoid"][r.below(5)];
        let mut a = format!(" type=\"{kind}\" size=\"{}\"", r.nums(3, 0.02, 0.2));
        if r.chance(0.5) {
            a.push_str(&format!(" pos=\"{}\"", r.nums(3, -0.1, 0.1)));
        }
        if r.chance(0.3) {
            a.push_str(&format!(" euler=\"{}\"", r.nums(3, -90.0, 90.0)));
        }
        if r.chance(0.4) {
            a.push_str(&format!(" class=\"{}\"", ["a", "b"][r.below(2)]));
        }
        kids.push(el("geom", a, Vec::new()));
    }
    if depth > 0 {
        for _ in 0..1 + r.below(2) {
            kids.push(split_body(r, depth - 1, count, joints));
        }
    }
    // Some of its children inside a `<frame>`, placed by its pose.
    if r.chance(0.4) {
        let lo = kids
            .iter()
            .position(|e| matches!(e.tag, "geom" | "body"))
            .unwrap_or(kids.len());
        if lo < kids.len() {
            let moved: Vec<El> = kids.drain(lo..).collect();
            let a = format!(
                " pos=\"{}\" euler=\"{}\"",
                r.nums(3, -0.3, 0.3),
                r.nums(3, -90.0, 90.0)
            );
            kids.push(el("frame", a, moved));
        }
    }
    el("body", attrs, kids)
}

/// A valid MJCF model: classes, nested bodies (frames, joints, geoms,
/// inertials), a joint equality.
fn split_model(r: &mut Mix) -> El {
    let mut kids = Vec::new();
    if r.chance(0.5) {
        kids.push(el("compiler", " angle=\"radian\"".to_string(), Vec::new()));
    }
    let b = el(
        "default",
        " class=\"b\"".to_string(),
        vec![el(
            "geom",
            format!(" density=\"{:?}\"", 100.0 + 5000.0 * r.unit()),
            Vec::new(),
        )],
    );
    let a = el(
        "default",
        " class=\"a\"".to_string(),
        vec![
            el(
                "joint",
                format!(" axis=\"{}\"", r.nums(3, 0.1, 1.0)),
                Vec::new(),
            ),
            el(
                "geom",
                format!(" density=\"{:?}\"", 100.0 + 5000.0 * r.unit()),
                Vec::new(),
            ),
            b,
        ],
    );
    let main = vec![
        el(
            "geom",
            format!(" density=\"{:?}\"", 200.0 + 3000.0 * r.unit()),
            Vec::new(),
        ),
        a,
    ];
    kids.push(el("default", String::new(), main));
    let (mut count, mut joints) = (0, Vec::new());
    let bodies = (0..1 + r.below(2))
        .map(|_| split_body(r, 2, &mut count, &mut joints))
        .collect();
    kids.push(el("worldbody", String::new(), bodies));
    if let [first, .., last] = joints.as_slice() {
        let e = format!(
            " joint1=\"{last}\" joint2=\"{first}\" polycoef=\"0 {:?} 0 0 0\"",
            r.unit()
        );
        kids.push(el(
            "equality",
            String::new(),
            vec![el("joint", e, Vec::new())],
        ));
    }
    el("mujoco", " model=\"split\"".to_string(), kids)
}

/// `e`'s children written out; where `cut` says, a run of them moved into
/// a new file of `files` (nested cuts inside it, up to `depth` files
/// deep) and an `<include>` of it in their place.
fn write_kids(e: &El, cut: &mut Option<&mut Mix>, depth: usize, files: &mut Vec<String>) -> String {
    let mut out = String::new();
    let mut i = 0;
    while i < e.kids.len() {
        let split = match cut.as_deref_mut() {
            Some(r) if depth < 5 => {
                let n = e.kids.len() - i;
                r.chance(0.3).then(|| i + 1 + r.below(n))
            }
            _ => None,
        };
        match split {
            Some(end) => {
                let inner: String = e.kids[i..end]
                    .iter()
                    .map(|k| write_el(k, cut, depth + 1, files))
                    .collect();
                let root = match cut.as_deref_mut().map(|r| r.below(2)) {
                    Some(0) => "mujocoinclude",
                    _ => "mujoco",
                };
                files.push(format!("<{root}>\n{inner}</{root}>\n"));
                out.push_str(&format!("<include file=\"inc{}.xml\"/>\n", files.len()));
                i = end;
            }
            None => {
                out.push_str(&write_el(&e.kids[i], cut, depth, files));
                i += 1;
            }
        }
    }
    out
}

fn write_el(e: &El, cut: &mut Option<&mut Mix>, depth: usize, files: &mut Vec<String>) -> String {
    if e.kids.is_empty() {
        return format!("<{}/>\n", e.head);
    }
    let inner = write_kids(e, cut, depth, files);
    format!("<{}>\n{inner}</{}>\n", e.head, e.tag)
}

/// The report's JSON of `path`, less `source`, or why not.
fn report_json(path: &Path) -> Result<Value, String> {
    let out = crate::common::massprop(&["report", path.to_str().unwrap(), "--format", "json"]);
    if out.status.code() != Some(0) {
        return Err(format!(
            "report {} failed: {}",
            path.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let mut v: Value = serde_json::from_slice(&out.stdout).map_err(|e| e.to_string())?;
    v.as_object_mut().unwrap().remove("source");
    Ok(v)
}

#[test]
fn a_valid_mjcf_model_split_into_included_files_anywhere_reports_as_the_one_file() {
    let top = crate::common::scratch("robots_hostile", "mjcf_split");
    let split_cases = std::cell::Cell::new(0);
    property(
        "MJCF models split over includes",
        16,
        (any::<u64>(), any::<u64>()),
        |&(model, cut)| {
            let e = split_model(&mut Mix(model));
            let single = write_el(&e, &mut None, 0, &mut Vec::new());
            let mut files = Vec::new();
            let mut r = Mix(cut);
            // The root's own children are cut too: sections in files.
            let inner = write_kids(&e, &mut Some(&mut r), 0, &mut files);
            let main = format!("<{}>\n{inner}</mujoco>\n", e.head);
            let dir = top.join(format!("{model:x}-{cut:x}"));
            std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
            for (k, f) in files.iter().enumerate() {
                std::fs::write(dir.join(format!("inc{}.xml", k + 1)), f)
                    .map_err(|e| e.to_string())?;
            }
            std::fs::write(dir.join("split.xml"), &main).map_err(|e| e.to_string())?;
            std::fs::write(dir.join("single.xml"), &single).map_err(|e| e.to_string())?;
            let (a, b) = (
                report_json(&dir.join("split.xml"))?,
                report_json(&dir.join("single.xml"))?,
            );
            if a != b {
                return Err(format!(
                    "{}: split over {} files, reports otherwise than the one file",
                    dir.display(),
                    files.len()
                ));
            }
            split_cases.set(split_cases.get() + u32::from(!files.is_empty()));
            Ok(true)
        },
    );
    // Most cases cut somewhere (a case without a cut proves nothing).
    let n = split_cases.get();
    assert!(n >= 8, "{n} of 16 cases split the model");
}

// ---------------------------------------------------------------------------
// Include trees checked link by link (issue 34)

/// One generated SDFormat file of an include tree: its links (name, mass,
/// whether a box collision) and the files it includes (by index, each
/// under a name of its own).
#[derive(Clone, Debug)]
struct TreeFile {
    links: Vec<(String, &'static str, bool)>,
    includes: Vec<usize>,
}

fn tree_file() -> impl Strategy<Value = TreeFile> {
    (
        prop::collection::vec(
            (
                prop::sample::select(vec!["a", "b", "c", "a"]),
                prop::sample::select(NICE.to_vec()),
                any::<bool>(),
            ),
            0..3,
        ),
        prop::collection::vec(0..4usize, 0..3),
    )
        .prop_map(|(links, includes)| TreeFile {
            links: links
                .into_iter()
                .map(|(n, m, g)| (n.to_string(), m, g))
                .collect(),
            includes,
        })
}

/// The text of file `k` of `files`: a model `mK` (the main file, a world).
fn tree_text(files: &[TreeFile], k: usize) -> String {
    let f = &files[k];
    let mut body = String::new();
    for (name, mass, geometry) in &f.links {
        body.push_str(&format!(
            "<link name=\"{name}\"><inertial><mass>{mass}</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>{}</link>\n",
            if *geometry { "<collision name=\"c\"><geometry><box><size>1 2 3</size></box></geometry></collision>" } else { "" }
        ));
    }
    for (i, &t) in f.includes.iter().enumerate() {
        body.push_str(&format!(
            "<include><uri>f{t}.sdf</uri><name>i{i}</name></include>\n"
        ));
    }
    let (open, close) = if k == 0 {
        ("<world name=\"w\">".to_string(), "</world>")
    } else {
        (format!("<model name=\"m{k}\">"), "</model>")
    };
    format!("<?xml version=\"1.0\"?>\n<sdf version=\"1.9\">\n{open}\n{body}{close}\n</sdf>\n")
}

/// `check` of a generated include tree exits 0, 1 or 2 without a panic;
/// when it judges the robot, each link is placed in a file of the tree at
/// a line that file has, and `export --from-geometry --update --dry-run`
/// either refuses it or shows diffs of files of the tree only.
fn include_tree_holds(dir: &Path, files: &[TreeFile]) -> Result<bool, String> {
    for k in 0..files.len() {
        std::fs::write(dir.join(format!("f{k}.sdf")), tree_text(files, k)).unwrap();
    }
    let main = dir.join("f0.sdf");
    let main = main.to_str().unwrap();
    let out = crate::common::massprop(&["check", main, "--format", "json"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let code = out.status.code();
    if !matches!(code, Some(0..=2)) {
        return Err(format!(
            "check exited {code:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let v: Value = serde_json::from_str(&stdout).map_err(|e| format!("{e}: {stdout}"))?;
    let file = &v["files"][0];
    let Some(links) = file["links"].as_array() else {
        return Ok(false);
    };
    for l in links {
        let path = l["file"].as_str().unwrap_or(main);
        let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}: {l}"))?;
        let line = l["line"].as_u64().unwrap() as usize;
        if line == 0 || line > text.lines().count() {
            return Err(format!("line {line} is not in {path}: {l}"));
        }
        if !text.lines().nth(line - 1).unwrap().contains("<inertial>") {
            return Err(format!("{path}:{line} holds no `<inertial>`: {l}"));
        }
    }
    let out = crate::common::massprop(&[
        "export",
        main,
        "--from-geometry",
        "collision",
        "--density",
        "1000",
        "--update",
        main,
        "--dry-run",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    match out.status.code() {
        Some(0) => {
            for header in text.lines().filter(|l| l.starts_with("--- a/")) {
                let path = &header["--- a/".len()..];
                if !Path::new(path).starts_with(dir) {
                    return Err(format!("a diff of a file outside the tree: {header}"));
                }
            }
        }
        Some(2) => {}
        other => return Err(format!("export exited {other:?}")),
    }
    Ok(true)
}

#[test]
fn generated_include_trees_are_checked_link_by_link_in_their_own_files() {
    let dir = crate::common::scratch("robots_hostile", "include-trees");
    let judged = property(
        "SDFormat include trees checked",
        GENERATED / 3,
        prop::collection::vec(tree_file(), 1..5),
        |files| include_tree_holds(&dir, files),
    );
    // Most trees are robots (the rest a cycle or a file not there).
    assert!(judged >= GENERATED / 10, "only {judged} trees judged");
}
