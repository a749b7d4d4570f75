//! Structures whose depth the input chooses (issue 28, item 2): a `group`
//! path, TOML tables and arrays nested in any key, a directory of files of
//! which one is deep. Whatever the depth, massprop answers or refuses with
//! a located error (`FILE:LINE:COL: error:`, status 2); it never crashes,
//! and one file never takes another's result with it.
//!
//! Each case runs the binary (a stack overflow aborts a process: in
//! process it would take this test binary with it). Deterministic
//! (`hostile::property`: fixed ChaCha seed, no persistence file).

use crate::common::{massprop, scratch};
use crate::hostile::property;
use proptest::prelude::*;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::Path;

/// The most names in a group path (docs/budget.md).
const LIMIT: usize = 64;

/// A point mass of `kg` kilograms, in group `group` (none if empty).
fn point(name: &str, kg: u32, group: &[String]) -> String {
    let mut s = format!(
        "[[part]]\nname = \"{name}\"\nshape = \"point\"\nmass = \"{kg} kg\"\ncenter = [0, 0, 0]\n"
    );
    if !group.is_empty() {
        s.push_str(&format!("group = \"{}\"\n", group.join("/")));
    }
    s
}

/// Whether `stderr` begins with a diagnostic at a place in `file`, on
/// line `line` if given.
fn located(stderr: &str, file: &str, line: Option<usize>) -> bool {
    let Some(rest) = stderr.strip_prefix(&format!("{file}:")) else {
        return false;
    };
    let mut parts = rest.splitn(3, ':');
    let row = parts.next().and_then(|r| r.parse::<usize>().ok());
    let col = parts.next().and_then(|c| c.parse::<usize>().ok());
    row.is_some()
        && col.is_some()
        && line.is_none_or(|l| row == Some(l))
        && parts.next().is_some_and(|r| r.starts_with(" error: "))
}

/// `massprop ARGS`: its status (a crash, which has none, fails), stdout
/// and stderr.
fn run(args: &[&str]) -> (i32, String, String) {
    let out = massprop(args);
    let status = out
        .status
        .code()
        .unwrap_or_else(|| panic!("massprop {args:?} crashed: {:?}", out.status));
    (
        status,
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn names(prefix: &str, n: usize) -> Vec<String> {
    (0..n).map(|i| format!("{prefix}{i}")).collect()
}

// ---------------------------------------------------------------------------
// Group paths

#[test]
fn a_group_of_thirty_thousand_names_is_refused_at_its_key_by_every_command() {
    let dir = scratch("depth", "deep-group");
    let file = dir.join("deep.toml");
    let text = point("p", 1, &vec!["a".to_string(); 30_000]) + "[budget]\nlimit = \"2 kg\"\n";
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    for command in ["check", "budget", "report", "render"] {
        let (status, stdout, stderr) = run(&[command, f]);
        assert_eq!(status, 2, "{command}: {stderr}");
        // The group is the part's sixth line.
        assert!(located(&stderr, f, Some(6)), "{command}: {stderr}");
        assert!(
            stderr.contains("`group` has 30000 names, past the limit of 64"),
            "{command}: {stderr}"
        );
        if command != "check" {
            assert!(stdout.is_empty(), "{command}: {stdout}");
        }
    }
}

#[test]
fn a_directory_with_a_deep_group_file_and_a_good_one_reports_both() {
    let dir = scratch("depth", "dir");
    let deep = point("p", 1, &vec!["a".to_string(); 30_000]) + "[budget]\nlimit = \"2 kg\"\n";
    std::fs::write(dir.join("a-deep.toml"), deep).unwrap();
    let good = point("q", 1, &names("g", 3)) + "[budget]\nlimit = \"2 kg\"\n";
    std::fs::write(dir.join("b-good.toml"), good).unwrap();
    let d = dir.to_str().unwrap();

    let (status, stdout, stderr) = run(&["check", "--format", "json", d]);
    assert_eq!(status, 2, "{stderr}");
    let json: Value = serde_json::from_str(&stdout).unwrap();
    let files = json["files"].as_array().unwrap();
    let status_of = |end: &str| {
        files
            .iter()
            .find(|f| f["path"].as_str().unwrap().ends_with(end))
            .map(|f| f["status"].as_str().unwrap().to_string())
    };
    assert_eq!(status_of("a-deep.toml").as_deref(), Some("invalid"));
    assert_eq!(status_of("b-good.toml").as_deref(), Some("ok"));

    // JUnit, read by a real XML parser: a suite per file.
    let (status, stdout, _) = run(&["check", "--format", "junit", d]);
    assert_eq!(status, 2);
    let doc = roxmltree::Document::parse(&stdout).expect("well-formed JUnit");
    let suites: Vec<(&str, &str)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("testsuite"))
        .map(|n| (n.attribute("name").unwrap(), n.attribute("errors").unwrap()))
        .collect();
    assert_eq!(suites.len(), 2, "{stdout}");
    assert!(suites[0].0.ends_with("a-deep.toml") && suites[0].1 == "1");
    assert!(suites[1].0.ends_with("b-good.toml") && suites[1].1 == "0");
}

#[test]
fn a_group_at_the_limit_is_answered_with_a_row_per_level() {
    let dir = scratch("depth", "at-limit");
    let file = dir.join("limit.toml");
    let path = names("g", LIMIT);
    std::fs::write(&file, point("p", 3, &path)).unwrap();
    let (status, stdout, stderr) = run(&["budget", "--format", "json", file.to_str().unwrap()]);
    assert_eq!(status, 0, "{stderr}");
    let json: Value = serde_json::from_str(&stdout).unwrap();
    let groups = json["groups"].as_array().unwrap();
    assert_eq!(groups.len(), LIMIT);
    for (k, g) in groups.iter().enumerate() {
        let shown: Vec<&str> = g["path"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_str().unwrap())
            .collect();
        assert_eq!(
            shown,
            path[..=k].iter().map(String::as_str).collect::<Vec<_>>()
        );
        assert_eq!(g["basic_mass"], 3.0);
    }
}

#[test]
fn a_deep_path_shared_by_many_copies_is_one_chain_of_groups() {
    // Memory for a group tree is linear in the text: a path of 64 names
    // shared by 100,000 copies is 64 groups, each counting every copy.
    let dir = scratch("depth", "shared");
    let file = dir.join("shared.toml");
    let text = point("p", 1, &names("g", LIMIT)) + "array = { count = 100000, step = [1, 0, 0] }\n";
    std::fs::write(&file, text).unwrap();
    let (status, stdout, stderr) = run(&["budget", "--format", "json", file.to_str().unwrap()]);
    assert_eq!(status, 0, "{stderr}");
    let json: Value = serde_json::from_str(&stdout).unwrap();
    let groups = json["groups"].as_array().unwrap();
    assert_eq!(groups.len(), LIMIT);
    assert!(groups.iter().all(|g| g["parts"] == 100_000));
    assert_eq!(groups[LIMIT - 1]["path"].as_array().unwrap().len(), LIMIT);
}

/// A part of a generated file: its own group path and mass (kg).
#[derive(Clone, Debug)]
struct Spec {
    path: Vec<String>,
    kg: u32,
}

/// Group paths of a few names from a small alphabet (so that paths share
/// prefixes), now and then up to and past the limit.
fn group_path() -> impl Strategy<Value = Vec<String>> {
    let name = prop::sample::select(vec!["a", "b", "c"]).prop_map(str::to_string);
    prop_oneof![
        8 => prop::collection::vec(name.clone(), 0..5),
        2 => prop::collection::vec(name.clone(), 30..=LIMIT),
        1 => prop::collection::vec(name, LIMIT - 2..LIMIT + 3),
    ]
}

fn spec() -> impl Strategy<Value = Spec> {
    (group_path(), 1u32..10).prop_map(|(path, kg)| Spec { path, kg })
}

/// A generated body: the root's parts, then optionally a sub-assembly of
/// its own parts included under a group.
#[derive(Clone, Debug)]
struct Body {
    root: Vec<Spec>,
    sub: Option<(Vec<String>, Vec<Spec>)>,
}

fn body() -> impl Strategy<Value = Body> {
    (
        prop::collection::vec(spec(), 1..8),
        prop::option::weighted(0.5, (group_path(), prop::collection::vec(spec(), 1..5))),
    )
        .prop_map(|(root, sub)| Body { root, sub })
}

/// Each part's whole path in walk order (the root's parts, the
/// sub-assembly's where its include stands: last), with its mass.
fn walked(b: &Body) -> Vec<(Vec<String>, u32)> {
    let mut out: Vec<(Vec<String>, u32)> = b.root.iter().map(|s| (s.path.clone(), s.kg)).collect();
    if let Some((prefix, parts)) = &b.sub {
        for s in parts {
            out.push(([prefix.clone(), s.path.clone()].concat(), s.kg));
        }
    }
    out
}

/// The statement's groups as an independent reading of the rules gives
/// them (docs/budget.md): every prefix of every part's path, and `[]` for
/// the parts with none; parts and basic mass summed over the parts under
/// each; parents before children, each level in order of first
/// appearance.
fn expected(parts: &[(Vec<String>, u32)]) -> Vec<(Vec<String>, usize, u32)> {
    let mut sums: BTreeMap<Vec<String>, (usize, u32, usize)> = BTreeMap::new();
    for (i, (path, kg)) in parts.iter().enumerate() {
        let prefixes: Vec<Vec<String>> = if path.is_empty() {
            vec![Vec::new()]
        } else {
            (1..=path.len()).map(|k| path[..k].to_vec()).collect()
        };
        for p in prefixes {
            let e = sums.entry(p).or_insert((0, 0, i));
            e.0 += 1;
            e.1 += kg;
        }
    }
    // Depth first from the roots, each level by first appearance.
    let children = |parent: Option<&Vec<String>>| {
        let mut c: Vec<&Vec<String>> = sums
            .keys()
            .filter(|k| match parent {
                None => k.len() <= 1,
                Some(p) => !p.is_empty() && k.len() == p.len() + 1 && k.starts_with(p),
            })
            .collect();
        c.sort_by_key(|k| sums[*k].2);
        c
    };
    let mut out = Vec::new();
    let mut todo: Vec<&Vec<String>> = children(None).into_iter().rev().collect();
    while let Some(k) = todo.pop() {
        let (n, kg, _) = sums[k];
        out.push((k.clone(), n, kg));
        todo.extend(children(Some(k)).into_iter().rev());
    }
    out
}

/// One generated body through `budget --format json`: Ok(true) when it
/// was answered, with the groups `expected` gives; Ok(false) when refused
/// at the `group` past the limit.
fn statement_of(dir: &Path, b: &Body) -> Result<bool, String> {
    let mut root = String::new();
    // The line of each `group` key, 1-based: a part's sixth line.
    let mut lines = 0;
    let mut too_deep = None;
    for (i, s) in b.root.iter().enumerate() {
        if s.path.len() > LIMIT && too_deep.is_none() {
            too_deep = Some(lines + 6);
        }
        let text = point(&format!("p{i}"), s.kg, &s.path);
        lines += text.lines().count();
        root.push_str(&text);
    }
    if let Some((prefix, parts)) = &b.sub {
        let sub: String = parts
            .iter()
            .enumerate()
            .map(|(i, s)| point(&format!("s{i}"), s.kg, &s.path))
            .collect();
        std::fs::write(dir.join("sub.toml"), sub).unwrap();
        root.push_str("[[part]]\nname = \"sub\"\ninclude = \"sub.toml\"\n");
        if !prefix.is_empty() {
            root.push_str(&format!("group = \"{}\"\n", prefix.join("/")));
        }
        let deepest = parts.iter().map(|s| s.path.len()).max().unwrap_or(0);
        if too_deep.is_none() && (prefix.len() > LIMIT || deepest > LIMIT) {
            // Its own file's error, or the include's group's.
            too_deep = Some(0);
        } else if too_deep.is_none() && prefix.len() + deepest > LIMIT {
            too_deep = Some(lines + 4);
        }
    }
    let file = dir.join("body.toml");
    std::fs::write(&file, &root).unwrap();
    let f = file.to_str().unwrap();
    let (status, stdout, stderr) = run(&["budget", "--format", "json", f]);
    if let Some(line) = too_deep {
        if status != 2 || !stdout.is_empty() {
            return Err(format!("a path past the limit: status {status}\n{stderr}"));
        }
        let sub = dir.join("sub.toml");
        let at = |line| {
            located(&stderr, f, (line > 0).then_some(line))
                || (line == 0 && located(&stderr, sub.to_str().unwrap(), None))
        };
        return if at(line) && stderr.contains("past the limit of 64") {
            Ok(false)
        } else {
            Err(format!("not refused at line {line} of the file:\n{stderr}"))
        };
    }
    if status != 0 {
        return Err(format!("status {status}\n{stderr}"));
    }
    let json: Value = serde_json::from_str(&stdout).map_err(|e| e.to_string())?;
    let got: Vec<(Vec<String>, usize, u32)> = json["groups"]
        .as_array()
        .unwrap()
        .iter()
        .map(|g| {
            let path = g["path"]
                .as_array()
                .unwrap()
                .iter()
                .map(|n| n.as_str().unwrap().to_string())
                .collect();
            let kg = g["basic_mass"].as_f64().unwrap();
            (path, g["parts"].as_u64().unwrap() as usize, kg as u32)
        })
        .collect();
    let want = expected(&walked(b));
    if got != want {
        return Err(format!("groups\n{got:?}\nexpected\n{want:?}"));
    }
    Ok(true)
}

#[test]
fn generated_group_trees_are_summed_level_by_level_or_refused_at_the_key() {
    let dir = scratch("depth", "generated-groups");
    let answered = property("group trees", 60, body(), |b| statement_of(&dir, b));
    assert!(answered >= 20, "only {answered} bodies answered");
}

// ---------------------------------------------------------------------------
// TOML nesting

/// Where a deep structure goes, and how it nests.
#[derive(Clone, Copy, Debug)]
enum Nest {
    /// `[a.a.….a]`
    Header,
    /// `a.a.….a = 1`
    Dotted,
    /// `[[[…]]]`
    Array,
    /// `{ a = { a = … } }`
    Inline,
}

/// A part file with a structure `depth` deep in `place`: the top level, a
/// `[[part]]`'s key, `[params]` or `[expect]`.
fn nested(nest: Nest, depth: usize, place: usize) -> String {
    let value = match nest {
        Nest::Array => "[".repeat(depth) + &"]".repeat(depth),
        Nest::Inline => "{ a = ".repeat(depth) + "1" + &" }".repeat(depth),
        Nest::Header | Nest::Dotted => "1".to_string(),
    };
    let key = vec!["a"; depth.max(1)].join(".");
    let part = "[[part]]\nname = \"p\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let deep = match nest {
        Nest::Header => format!("[{key}]\nx = 1\n"),
        Nest::Dotted => format!("{key} = 1\n"),
        Nest::Array | Nest::Inline => format!("x = {value}\n"),
    };
    match (place, nest) {
        // At the top level, before any table.
        (0, _) => format!("{deep}{part}"),
        (1, Nest::Header) => format!("{part}[part.{key}]\nx = 1\n"),
        (1, _) => format!("{part}{deep}"),
        (2, Nest::Header) => format!("{part}[params.{key}]\nx = 1\n"),
        (2, _) => format!("{part}[params]\n{deep}"),
        (_, Nest::Header) => format!("{part}[expect.{key}]\nx = 1\n"),
        (_, _) => format!("{part}[expect]\n{deep}"),
    }
}

fn nest() -> impl Strategy<Value = Nest> {
    prop::sample::select(vec![Nest::Header, Nest::Dotted, Nest::Array, Nest::Inline])
}

/// Depths from 1 to 200,000, about evenly in their logarithm.
fn depth() -> impl Strategy<Value = usize> {
    (0.0..5.3f64).prop_map(|e| 10f64.powf(e) as usize)
}

#[test]
fn structures_nested_to_any_depth_are_read_or_refused_where_they_are() {
    let dir = scratch("depth", "nested");
    let file = dir.join("nested.toml");
    let f = file.to_str().unwrap().to_string();
    let strategy = (nest(), depth(), 0usize..4);
    property("deep nesting", 40, strategy, |(nest, depth, place)| {
        std::fs::write(&file, nested(*nest, *depth, *place)).unwrap();
        let (status, _, stderr) = run(&["check", &f]);
        match status {
            0 | 1 => Ok(true),
            2 if located(&stderr, &f, None) => Ok(false),
            _ => Err(format!("status {status} without a place:\n{stderr}")),
        }
    });
}

#[test]
fn a_hundred_thousand_levels_of_tables_arrays_and_inline_tables_are_refused() {
    let dir = scratch("depth", "hundred-thousand");
    for nest in [Nest::Header, Nest::Dotted, Nest::Array, Nest::Inline] {
        for place in 0..4 {
            let file = dir.join(format!("{nest:?}-{place}.toml"));
            std::fs::write(&file, nested(nest, 100_000, place)).unwrap();
            let f = file.to_str().unwrap();
            let (status, stdout, stderr) = run(&["report", f]);
            assert_eq!(status, 2, "{nest:?} at {place}: {stderr}");
            assert!(stdout.is_empty());
            assert!(located(&stderr, f, None), "{nest:?} at {place}: {stderr}");
        }
    }
}
