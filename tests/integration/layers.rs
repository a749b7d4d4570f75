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
