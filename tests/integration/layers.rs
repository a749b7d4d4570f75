//! The module graph has layers and no cycles: docs/architecture.md lists
//! the modules from the bottom up, and no module of `src/` may use a
//! module listed after it (in a later layer, or later in its own). The document is the one statement of the
//! layers; this test holds the code to it.

use std::collections::HashMap;
use std::path::Path;

/// Top-level module → (layer, position in the list), from
/// docs/architecture.md's numbered list.
fn layers() -> HashMap<String, (usize, usize)> {
    let doc = std::fs::read_to_string("docs/architecture.md").unwrap();
    let start = doc.find("## Modules, from the bottom up").unwrap();
    let rest = &doc[start..];
    let end = rest[3..].find("\n## ").map_or(rest.len(), |i| i + 3);
    let mut out = HashMap::new();
    let mut layer = 0;
    for line in rest[..end].lines() {
        if let Some((n, _)) = line.split_once(". **")
            && let Ok(n) = n.trim().parse::<usize>()
        {
            layer = n;
        }
        for name in line.split('`').skip(1).step_by(2) {
            let is_module = Path::new("src").join(format!("{name}.rs")).exists()
                || Path::new("src").join(name).is_dir();
            if layer > 0 && is_module {
                let position = out.len();
                out.entry(name.to_string()).or_insert((layer, position));
            }
        }
    }
    out
}

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

#[test]
fn no_module_uses_a_module_of_a_later_layer() {
    let layers = layers();
    let mut files = Vec::new();
    sources(Path::new("src"), &mut files);
    let mut wrong = Vec::new();
    let mut unlisted = Vec::new();
    for f in &files {
        let rel = f.strip_prefix("src").unwrap();
        let top = rel
            .iter()
            .next()
            .unwrap()
            .to_string_lossy()
            .replace(".rs", "");
        if matches!(top.as_str(), "main" | "lib") {
            continue;
        }
        let Some(&own) = layers.get(&top) else {
            unlisted.push(top);
            continue;
        };
        let text = std::fs::read_to_string(f).unwrap();
        // Unit tests may reach anywhere.
        let code = text.split("#[cfg(test)]").next().unwrap();
        for (i, _) in code.match_indices("crate::") {
            let name: String = code[i + 7..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if let Some(&other) = layers.get(&name)
                && other.1 > own.1
            {
                wrong.push(format!(
                    "{} (layer {}) uses `{name}` (layer {}, listed after it)",
                    f.display(),
                    own.0,
                    other.0
                ));
            }
        }
    }
    unlisted.sort();
    unlisted.dedup();
    assert!(
        unlisted.is_empty(),
        "modules not in docs/architecture.md: {unlisted:?}"
    );
    assert!(
        wrong.is_empty(),
        "uses against the layers:\n{}",
        wrong.join("\n")
    );
    // The list is read at all: every layer has a module.
    for l in 1..=7 {
        assert!(
            layers.values().any(|v| v.0 == l),
            "layer {l} is empty: {layers:?}"
        );
    }
}

/// No source file grows past about 800 lines unless it says at its top why
/// it is one cohesive thing (a `//! NOTE: cohesive:` line).
#[test]
fn source_files_stay_under_800_lines_or_say_why() {
    let mut files = Vec::new();
    sources(Path::new("src"), &mut files);
    let long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            let lines = text.lines().count();
            (lines > 800 && !text.contains("//! NOTE: cohesive:"))
                .then(|| format!("{} ({lines} lines)", f.display()))
        })
        .collect();
    assert!(long.is_empty(), "split these or say why not: {long:?}");
}

/// The modules directly inside `folder` (each `NAME.rs` but `mod.rs`, and
/// each sub-folder) and, for each, the siblings its files use: by
/// `crate::PATH::NAME`, or by `super::NAME` from a file directly inside
/// `folder` (`super::super::NAME` one level down), braces included.
fn sibling_uses(folder: &Path) -> HashMap<String, Vec<String>> {
    let path = folder
        .strip_prefix("src")
        .unwrap()
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("::");
    let mut nodes: HashMap<String, Vec<std::path::PathBuf>> = HashMap::new();
    for e in std::fs::read_dir(folder).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        if p.is_dir() {
            let mut files = Vec::new();
            sources(&p, &mut files);
            nodes.entry(name).or_default().extend(files);
        } else if p.extension().is_some_and(|x| x == "rs") && name != "mod" {
            nodes.entry(name).or_default().push(p);
        }
    }
    let names: Vec<String> = nodes.keys().cloned().collect();
    let mut out = HashMap::new();
    for (node, files) in &nodes {
        let mut used = Vec::new();
        for f in files {
            let depth = f.strip_prefix(folder).unwrap().iter().count();
            let own = format!("{}::", vec!["super"; depth].join("::"));
            let text = std::fs::read_to_string(f).unwrap();
            for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
                for prefix in [format!("crate::{path}::"), own.clone()] {
                    for (at, _) in line.match_indices(&prefix) {
                        // `super::super::x` is not `super::x` one level up.
                        if line[..at].ends_with("super::") {
                            continue;
                        }
                        let rest = &line[at + prefix.len()..];
                        let heads: Vec<&str> = match rest.strip_prefix('{') {
                            Some(group) => group
                                .split('}')
                                .next()
                                .unwrap_or("")
                                .split(',')
                                .map(|s| s.trim().split("::").next().unwrap_or(""))
                                .collect(),
                            None => vec![
                                rest.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                                    .next()
                                    .unwrap_or(""),
                            ],
                        };
                        for h in heads {
                            if h != node && names.iter().any(|n| n == h) {
                                used.push(h.to_string());
                            }
                        }
                    }
                }
            }
        }
        used.sort();
        used.dedup();
        out.insert(node.clone(), used);
    }
    out
}

/// A circle of `uses`, if there is one.
fn circle(uses: &HashMap<String, Vec<String>>) -> Option<Vec<String>> {
    fn visit(
        n: &str,
        uses: &HashMap<String, Vec<String>>,
        path: &mut Vec<String>,
        done: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = path.iter().position(|p| p == n) {
            let mut c = path[i..].to_vec();
            c.push(n.to_string());
            return Some(c);
        }
        if done.iter().any(|d| d == n) {
            return None;
        }
        path.push(n.to_string());
        for m in uses.get(n).into_iter().flatten() {
            if let Some(c) = visit(m, uses, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.push(n.to_string());
        None
    }
    let mut nodes: Vec<&String> = uses.keys().collect();
    nodes.sort();
    let mut done = Vec::new();
    nodes
        .into_iter()
        .find_map(|n| visit(n, uses, &mut Vec::new(), &mut done))
}

/// Inside `analysis`, no module uses one that uses it back, however far
/// round (issue 29: summary ↔ uncertainty ↔ check ↔ budget ↔ ideal).
#[test]
fn the_analysis_modules_use_each_other_without_a_circle() {
    let uses = sibling_uses(Path::new("src/analysis"));
    assert!(uses["summary"].contains(&"ideal".to_string()), "{uses:?}");
    assert_eq!(circle(&uses), None, "{uses:?}");
}

#[test]
fn a_circle_of_uses_is_found() {
    let uses: HashMap<String, Vec<String>> = [("a", "b"), ("b", "c"), ("c", "a")]
        .into_iter()
        .map(|(a, b)| (a.to_string(), vec![b.to_string()]))
        .collect();
    assert_eq!(
        circle(&uses),
        Some(vec!["a".into(), "b".into(), "c".into(), "a".into()])
    );
}
