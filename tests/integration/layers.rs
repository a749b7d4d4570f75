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

/// A file's module path: `src/model/parts.rs` → `model::parts`,
/// `src/model/mod.rs` → `model`, `src/lib.rs` → the crate root.
fn module_of(file: &Path) -> Vec<String> {
    let rel = file.strip_prefix("src").unwrap();
    let mut segs: Vec<String> = rel
        .iter()
        .map(|s| s.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(
        segs.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        segs.pop();
    }
    segs
}

/// The paths a file's code names (`crate::a::b`, `super::c`, `self::d`,
/// a child module's `e::f`, and each leaf of a `use` tree with braces),
/// as written: comments and unit tests left out.
fn named_paths(text: &str) -> Vec<Vec<String>> {
    let code = text.split("#[cfg(test)]").next().unwrap();
    // Comments and the text of string literals blanked (a path in an
    // attribute's string, `with = "super::x::Y"`, is not read: it is
    // farm-studio's reading too).
    let mut plain = Vec::with_capacity(code.len());
    let src = code.as_bytes();
    let mut k = 0;
    while k < src.len() {
        if src[k..].starts_with(b"//") {
            while k < src.len() && src[k] != b'\n' {
                k += 1;
            }
        } else if src[k] == b'"' {
            k += 1;
            while k < src.len() && src[k] != b'"' {
                k += if src[k] == b'\\' { 2 } else { 1 };
            }
            k += 1;
            plain.push(b' ');
        } else {
            plain.push(src[k]);
            k += 1;
        }
    }
    let b = &plain[..];
    let ident = |i: usize| -> usize {
        let mut j = i;
        while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_') {
            j += 1;
        }
        j
    };
    // Expands a path or `use` tree starting at `i` under `prefix`; returns
    // the index after it.
    fn tree(
        b: &[u8],
        mut i: usize,
        prefix: Vec<String>,
        ident: &dyn Fn(usize) -> usize,
        out: &mut Vec<Vec<String>>,
    ) -> usize {
        let mut path = prefix;
        loop {
            while i < b.len() && b[i].is_ascii_whitespace() {
                i += 1;
            }
            if i < b.len() && b[i] == b'{' {
                i += 1;
                loop {
                    while i < b.len() && (b[i].is_ascii_whitespace() || b[i] == b',') {
                        i += 1;
                    }
                    if i >= b.len() || b[i] == b'}' {
                        return i + 1;
                    }
                    i = tree(b, i, path.clone(), ident, out);
                }
            }
            let j = ident(i);
            if j == i {
                out.push(path);
                return i.max(1);
            }
            path.push(String::from_utf8_lossy(&b[i..j]).into_owned());
            i = j;
            if b[i..].starts_with(b"::") {
                i += 2;
            } else {
                out.push(path);
                return i;
            }
        }
    }
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let at_word =
            i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_' || b[i - 1] == b':');
        if at_word && b[i..].starts_with(b"use ") {
            i = tree(b, i + 4, Vec::new(), &ident, &mut out);
            continue;
        }
        if at_word && (b[i].is_ascii_alphabetic() || b[i] == b'_') {
            let j = ident(i);
            if b[j..].starts_with(b"::") {
                i = tree(b, i, Vec::new(), &ident, &mut out);
                continue;
            }
            i = j;
            continue;
        }
        i += 1;
    }
    out
}

/// Every circle of files in src/ that import each other, inside a folder
/// or across folders: a file's import of a module of its own ancestors
/// (`super::Name` from a child) is the folder's face, not an arrow; a
/// parent's import of its child's names is one.
fn circles() -> Vec<Vec<String>> {
    let mut files = Vec::new();
    sources(Path::new("src"), &mut files);
    files.sort();
    let modules: Vec<Vec<String>> = files.iter().map(|f| module_of(f)).collect();
    let index: HashMap<Vec<String>, usize> = modules
        .iter()
        .enumerate()
        .map(|(i, m)| (m.clone(), i))
        .collect();
    let mut edges: Vec<Vec<usize>> = vec![Vec::new(); files.len()];
    for (f, file) in files.iter().enumerate() {
        let me = &modules[f];
        let text = std::fs::read_to_string(file).unwrap();
        for path in named_paths(&text) {
            let Some(first) = path.first() else { continue };
            let mut abs: Vec<String> = match first.as_str() {
                "crate" => Vec::new(),
                "self" => me.clone(),
                "super" => me[..me.len().saturating_sub(1)].to_vec(),
                _ => {
                    // A child module named by its own name (`values::x`).
                    let mut child = me.clone();
                    child.push(first.clone());
                    if !index.contains_key(&child) {
                        continue;
                    }
                    me.clone()
                }
            };
            let mut rest =
                &path[usize::from(matches!(first.as_str(), "crate" | "self" | "super"))..];
            while rest.first().is_some_and(|s| s == "super") {
                abs.pop();
                rest = &rest[1..];
            }
            abs.extend(rest.iter().cloned());
            let target = (0..=abs.len())
                .rev()
                .find_map(|n| index.get(&abs[..n]).copied());
            if let Some(t) = target
                && t != f
                && !me.starts_with(&modules[t])
                && !edges[f].contains(&t)
            {
                edges[f].push(t);
            }
        }
    }
    let out = components(&edges);
    // Each circle as its arrows, `a -> b`, sorted.
    out.into_iter()
        .map(|scc| {
            let mut arrows: Vec<String> = scc
                .iter()
                .flat_map(|&a| {
                    edges[a]
                        .iter()
                        .filter(|b| scc.contains(b))
                        .map(move |&b| (a, b))
                })
                .map(|(a, b)| format!("{} -> {}", files[a].display(), files[b].display()))
                .collect();
            arrows.sort();
            arrows
        })
        .collect()
}

/// The strongly connected components of two nodes or more (Tarjan): the
/// circles of a graph given as each node's arrows.
fn components(edges: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct Tarjan<'a> {
        edges: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on: Vec<bool>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    impl Tarjan<'_> {
        fn visit(&mut self, v: usize) {
            self.index[v] = Some(self.next);
            self.low[v] = self.next;
            self.next += 1;
            self.stack.push(v);
            self.on[v] = true;
            for &w in &self.edges[v] {
                match self.index[w] {
                    None => {
                        self.visit(w);
                        self.low[v] = self.low[v].min(self.low[w]);
                    }
                    Some(i) if self.on[w] => self.low[v] = self.low[v].min(i),
                    Some(_) => {}
                }
            }
            if Some(self.low[v]) == self.index[v] {
                let mut scc = Vec::new();
                while let Some(w) = self.stack.pop() {
                    self.on[w] = false;
                    scc.push(w);
                    if w == v {
                        break;
                    }
                }
                if scc.len() > 1 {
                    self.out.push(scc);
                }
            }
        }
    }
    let n = edges.len();
    let mut t = Tarjan {
        edges,
        index: vec![None; n],
        low: vec![0; n],
        stack: Vec::new(),
        on: vec![false; n],
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if t.index[v].is_none() {
            t.visit(v);
        }
    }
    t.out
}

/// No files of src/ import each other in a circle, inside a folder or
/// across (issue 29): the layers above order the top-level modules; this
/// orders the files within them.
#[test]
fn no_files_import_each_other_in_a_circle() {
    let found = circles();
    assert!(found.is_empty(), "import circles: {found:#?}");
}

/// The circle finder finds a circle: two files of a folder naming each
/// other, one by `super::`, the other by its child's path.
#[test]
fn the_circle_finder_reads_both_kinds_of_path() {
    let paths = named_paths(
        "use super::{a::B, c::{self, D}};\nuse crate::x::y;\nfn f() { super::e::g(); values::h(); }\n// crate::comment::z\n#[a(with = \"super::string::s\")]\n",
    );
    let strs: Vec<String> = paths.iter().map(|p| p.join("::")).collect();
    for want in [
        "super::a::B",
        "super::c::self",
        "super::c::D",
        "crate::x::y",
        "super::e::g",
        "values::h",
    ] {
        assert!(strs.contains(&want.to_string()), "{want} in {strs:?}");
    }
    assert!(
        !strs
            .iter()
            .any(|s| s.contains("comment") || s.contains("string")),
        "{strs:?}"
    );
}

/// The circle finder finds a circle and nothing else: a → b → c → a and
/// a tail c → d are one circle of three.
#[test]
fn the_circle_finder_finds_a_circle_and_only_it() {
    let edges = vec![vec![1], vec![2], vec![0, 3], vec![]];
    let mut found = components(&edges);
    for c in &mut found {
        c.sort();
    }
    assert_eq!(found, vec![vec![0, 1, 2]]);
    assert!(components(&[vec![1], vec![2], vec![]]).is_empty());
}
