//! SDFormat `<include>`s for the whole robot (`sdf_tree`): every file a
//! model or a world includes, at any depth, read once each.
//!
//! `<uri>` is a path relative to the including file's directory (or
//! absolute, or `file://`), or `model://NAME[/REST]`: NAME's directory is
//! the one `--package NAME=DIR` gives, else the including file's
//! directory's sibling `NAME/` (Gazebo's layout: every model a directory
//! of one resource path). A directory holds `model.config`, whose first
//! `<sdf>` names the model's file; without one the include is refused, as
//! libsdformat refuses it (Gazebo will not start the world). A file must lie, after
//! following symlinks, inside the top file's directory, a package
//! directory, a model directory found by `model://`, the working
//! directory, or an `--include-root`, as a part file's includes must.
//! Refused with their place: a missing `<uri>`, a URI that downloads
//! (`http://`, Fuel), a file outside those directories, includes in a
//! cycle (naming the chain), and includes deeper than `MAX_DEPTH`.

use super::{Xml, child, qname, quoted};
use crate::diag::{Diagnostic, Source};
use roxmltree::Node;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// How deep includes may nest (a file that includes one that includes …).
pub(super) const MAX_DEPTH: usize = 16;

/// Where includes are looked for: `--package NAME=DIR`s, and the
/// directories beyond the top file's that they may read.
#[derive(Clone, Debug, Default)]
pub struct Resolve {
    pub packages: Vec<(String, PathBuf)>,
    pub roots: Vec<PathBuf>,
}

/// Every file read: the top one (index 0) and those it includes.
pub(super) struct Files<'s> {
    pub top: &'s Source,
    pub included: Vec<Source>,
    /// (file, byte offset of an `<include>` element) → the file it names.
    pub targets: HashMap<(usize, usize), usize>,
    /// Per included file, where it was first included: `FILE:LINE:COL`.
    pub from: Vec<String>,
    /// The directories the files, and the mesh files they name, may be
    /// read from (after following symlinks): `roots`.
    pub roots: Vec<PathBuf>,
}

impl<'s> Files<'s> {
    /// `top` alone, before its includes are read.
    pub fn new(top: &'s Source) -> Self {
        Files {
            top,
            included: Vec::new(),
            targets: HashMap::new(),
            from: Vec::new(),
            roots: Vec::new(),
        }
    }

    pub fn source(&self, file: usize) -> &Source {
        match file {
            0 => self.top,
            k => &self.included[k - 1],
        }
    }

    /// `d` with where its file was included from, up to the top file.
    pub fn located(&self, d: Diagnostic) -> Diagnostic {
        located(&self.included, &self.from, d)
    }
}

/// `d` with where its file was included from, up to the top file, given
/// the included files and where each was first included (`Files`, or a
/// description's `robot::Included`): the one rule for every robot reader.
pub fn located(included: &[Source], from: &[String], d: Diagnostic) -> Diagnostic {
    let Some(path) = d.place().map(|p| p.path.clone()) else {
        return d;
    };
    let Some(k) = included.iter().position(|s| s.name == path) else {
        return d;
    };
    chain(included, from, k + 1)
        .into_iter()
        .fold(d, |d, site| d.included_from(site))
}

/// The sites that bring file `file` (1-based among `included`; 0 the top
/// file) in, innermost first, each where the file was first included.
pub fn chain(included: &[Source], from: &[String], file: usize) -> Vec<String> {
    let mut out = Vec::new();
    let mut at = file.checked_sub(1);
    while let Some(k) = at.filter(|&k| k < from.len() && out.len() <= MAX_DEPTH) {
        let site = from[k].clone();
        let file = site.rsplitn(3, ':').nth(2).unwrap_or_default().to_string();
        out.push(site);
        at = included.iter().position(|s| s.name == file);
    }
    out
}

/// The `<include>`s `doc` holds in a model or a world.
pub(super) fn includes<'a, 'i>(doc: &'a roxmltree::Document<'i>) -> Vec<Node<'a, 'i>> {
    doc.descendants()
        .filter(|n| {
            qname(*n) == "include"
                && n.parent_element()
                    .is_some_and(|p| matches!(qname(p), "model" | "world"))
        })
        .collect()
}

/// `p` after following symlinks, else as written (a file that is not
/// there is refused where it is read).
pub(super) fn canonical(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf())
}

/// The directories a robot file's includes may read, after following
/// symlinks: the top file's directory, the working directory, each
/// `--include-root` and `--package` directory (SDFormat's `<include>` and
/// MJCF's `<include>` alike).
pub(super) fn roots(top: &Source, r: &Resolve) -> Vec<PathBuf> {
    let dir = top
        .path()
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default();
    let dir = if dir.as_os_str().is_empty() {
        PathBuf::from(".")
    } else {
        dir
    };
    let mut roots = vec![canonical(&dir)];
    if let Ok(cwd) = std::env::current_dir() {
        roots.push(canonical(&cwd));
    }
    roots.extend(r.roots.iter().map(|p| canonical(p)));
    roots.extend(r.packages.iter().map(|(_, p)| canonical(p)));
    roots
}

/// Whether the file `canonical` (symlinks followed) lies inside one of
/// `roots`.
pub(super) fn inside(roots: &[PathBuf], canonical: &Path) -> bool {
    roots.iter().any(|r| canonical.starts_with(r))
}

struct Loader<'s> {
    files: Files<'s>,
    /// Canonical path → file index; the chain being read (gray) is `chain`.
    known: HashMap<PathBuf, usize>,
    chain: Vec<(PathBuf, String)>,
    roots: Vec<PathBuf>,
    packages: Vec<(String, PathBuf)>,
}

/// Read every file `top` includes, at any depth.
pub(super) fn load<'s>(top: &'s Source, r: &Resolve) -> Result<Files<'s>, Diagnostic> {
    let mut l = Loader {
        files: Files::new(top),
        known: HashMap::new(),
        chain: vec![(canonical(top.path()), top.name.clone())],
        roots: roots(top, r),
        packages: r.packages.clone(),
    };
    l.file(0)?;
    l.files.roots = l.roots;
    Ok(l.files)
}

impl Loader<'_> {
    /// The includes of file `k`, each read (depth first).
    fn file(&mut self, k: usize) -> Result<(), Diagnostic> {
        let source = self.files.source(k).clone();
        let doc = super::parse(&source)?;
        let xml = Xml { source: &source };
        for inc in includes(&doc) {
            let (path, shown) = self.target(&xml, inc)?;
            let canonical = std::fs::canonicalize(&path).map_err(|e| {
                let uri = child(inc, "uri").map(|u| xml.text(u).range);
                xml.error(
                    uri.unwrap_or_else(|| xml.tag(inc)),
                    format!("cannot read the included file `{shown}`: {e}"),
                )
            })?;
            let at_uri = || {
                xml.text(child(inc, "uri").expect("a target has a uri"))
                    .range
            };
            let (line, col) = source.line_col(at_uri().start);
            let site = format!("{}:{line}:{col}", source.name);
            if let Some(i) = self.chain.iter().position(|(p, _)| *p == canonical) {
                let names: Vec<String> = self.chain[i..]
                    .iter()
                    .map(|(_, n)| format!("`{n}`"))
                    .chain([format!("`{shown}`")])
                    .collect();
                return Err(xml.error(
                    at_uri(),
                    format!(
                        "`<include>` closes a cycle of includes: {}",
                        names.join(" → ")
                    ),
                ));
            }
            if self.chain.len() > MAX_DEPTH {
                return Err(xml.error(
                    at_uri(),
                    format!(
                        "`<include>` of `{shown}`: includes nest more than {MAX_DEPTH} files deep"
                    ),
                ));
            }
            self.confined(&xml, &canonical, &shown, at_uri())?;
            let target = match self.known.get(&canonical) {
                Some(&t) => t,
                None => {
                    let bytes = std::fs::read(&canonical).map_err(|e| {
                        xml.error(
                            at_uri(),
                            format!("cannot read the included file `{shown}`: {e}"),
                        )
                    })?;
                    let s = crate::io::source_of(&shown, bytes)?.read_from(path.clone());
                    self.files.included.push(s);
                    self.files.from.push(site.clone());
                    let t = self.files.included.len();
                    self.known.insert(canonical.clone(), t);
                    self.chain.push((canonical, shown));
                    self.file(t).map_err(|d| d.included_from(site))?;
                    self.chain.pop();
                    t
                }
            };
            self.files.targets.insert((k, inc.range().start), target);
        }
        Ok(())
    }

    /// Refuse `canonical` outside the directories includes may read.
    fn confined(
        &self,
        xml: &Xml,
        canonical: &Path,
        shown: &str,
        at: std::ops::Range<usize>,
    ) -> Result<(), Diagnostic> {
        if inside(&self.roots, canonical) {
            return Ok(());
        }
        Err(xml
            .error(
                at,
                format!("the included `{shown}` lies outside the directories includes may read"),
            )
            .help("an SDFormat include may read the top file's directory, the working directory, `--package` and `model://` directories, and `--include-root`s"))
    }

    /// The file an `<include>` names, and how messages show it.
    fn target(&mut self, xml: &Xml, inc: Node) -> Result<(PathBuf, String), Diagnostic> {
        let Some(u) = child(inc, "uri") else {
            return Err(xml.error(
                xml.tag(inc),
                "`<include>` is missing the required element `<uri>`",
            ));
        };
        let uri = xml.text(u);
        let dir = xml.source.path().parent().unwrap_or(Path::new(""));
        let bad = |why: String| {
            xml.error(
                uri.range.clone(),
                format!("`<uri>` {}: {why}", quoted(&uri.text)),
            )
        };
        let mut path = if let Some(rest) = uri.text.strip_prefix("model://") {
            let (name, tail) = rest.split_once('/').unwrap_or((rest, ""));
            if name.is_empty() || name == "." || name == ".." {
                return Err(bad(
                    "expected `model://NAME`, NAME a model's directory".into()
                ));
            }
            let base = match self.packages.iter().find(|(n, _)| n == name) {
                Some((_, d)) => d.clone(),
                None => {
                    let sibling = dir.join("..").join(name);
                    if !sibling.is_dir() {
                        return Err(bad(format!(
                            "no directory `{name}` beside the including file's directory, and no `--package {name}=DIR`"
                        )));
                    }
                    sibling
                }
            };
            if let Ok(c) = std::fs::canonicalize(&base) {
                self.roots.push(c);
            }
            if tail.is_empty() {
                base
            } else {
                base.join(tail)
            }
        } else if let Some(rest) = uri.text.strip_prefix("file://") {
            PathBuf::from(rest)
        } else if uri.text.contains("://") {
            return Err(bad(
                "only `model://` and file paths are read (massprop downloads nothing)".into(),
            ));
        } else if uri.text.is_empty() {
            return Err(bad("expected a path or `model://NAME`".into()));
        } else {
            dir.join(&uri.text)
        };
        if path.is_dir() {
            let shown = path.display().to_string();
            let canonical = std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone());
            self.confined(xml, &canonical, &shown, uri.range.clone())?;
            path = model_file(xml, &path, &uri.range)?;
        }
        let shown = path.display().to_string();
        Ok((path, shown))
    }
}

/// The model file of directory `dir`: its `model.config`'s first `<sdf>`.
///
/// NOTE: libsdformat's `getModelFilePath` reads `model.config` (else the
/// deprecated `manifest.xml`, with a warning) and refuses a directory
/// without either ("Unable to resolve uri[…] since it does not contain a
/// model.config file"): Gazebo then does not start the world. A model
/// directory of `model.sdf` alone is refused here too, not read by a
/// guess a CI check would pass and Gazebo refuse; `manifest.xml` is
/// refused with the advice to rename it.
fn model_file(xml: &Xml, dir: &Path, at: &std::ops::Range<usize>) -> Result<PathBuf, Diagnostic> {
    let config = dir.join("model.config");
    if let Ok(bytes) = std::fs::read(&config) {
        let source = crate::io::source_of(&config.display().to_string(), bytes)?;
        let doc = super::parse(&source)?;
        let cx = Xml { source: &source };
        let sdf = doc.descendants().find(|n| qname(*n) == "sdf");
        match sdf.map(|s| cx.text(s)) {
            Some(v) if !v.text.is_empty() => return Ok(dir.join(v.text)),
            _ => {
                return Err(cx.error(
                    cx.tag(doc.root_element()),
                    "`model.config` names no model file: expected `<sdf>FILE</sdf>`",
                ));
            }
        }
    }
    let message = if dir.join("manifest.xml").is_file() {
        format!(
            "the included directory `{}` holds `manifest.xml`, not `model.config`: libsdformat reads `manifest.xml` only as a deprecated `model.config`",
            dir.display()
        )
    } else {
        format!(
            "the included directory `{}` holds no `model.config`: libsdformat (Gazebo) finds a model directory's file through its `model.config`, and refuses the include without one",
            dir.display()
        )
    };
    Err(xml.error(at.clone(), message).help(
        "write `model.config` in the directory: <model><sdf version=\"1.9\">model.sdf</sdf></model>",
    ))
}
