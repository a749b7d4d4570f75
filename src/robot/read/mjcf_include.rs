//! MJCF `<include file="…"/>` for the whole robot (`report`, `diff`, a
//! part file's `include` of an MJCF robot), as MuJoCo follows it
//! (`xml.cc`, `IncludeXML`; XML reference, "include"): wherever an
//! `<include>` stands (under `<mujoco>`, in `<worldbody>`, a `<body>`, a
//! `<frame>`, `<default>`, `<asset>`, `<equality>`, …), the children of
//! the included file's root element (whatever its name: `<mujoco>`,
//! `<mujocoinclude>`, …) take its place, as if written there; includes
//! nest; the path is relative to the main model file's directory (else,
//! for an include inside an included file, to that file's directory,
//! MuJoCo's second try); a file included twice (the main file too) is
//! MuJoCo's error.
//!
//! Each file is read as a document of its own, so that a message names the
//! place in the file where the element is written, with where that file
//! was included from (`sdf_include::Files::located`). Every walk of the
//! model's elements goes through `Model::children` (and `descendants`,
//! `parent`), which splice each `<include>`: no reader sees one. A body,
//! inertial or joint of an included file stands, in the `Description` and
//! the tree, at the outermost `<include>` of the main file that brings it
//! in (`Model::range`, as an SDFormat include's links do): warnings about
//! it point there.
//!
//! Confined as SDFormat includes are (`sdf_include::roots`): the main
//! file's directory, the working directory, `--include-root`s. Refused
//! with their place: a missing `file`, a file that cannot be read or lies
//! outside those directories, one with no element under its root (MuJoCo:
//! "Empty include file"), one whose root is a URDF's `<robot>` or an
//! SDFormat `<sdf>` (MuJoCo splices their elements and refuses them as
//! MJCF), a file included twice (or in a cycle, named), an `<include>`
//! with children, and includes deeper than `MAX_DEPTH`.

use super::sdf_include::{Files, MAX_DEPTH, Resolve, canonical, inside, roots};
use super::{Xml, qname};
use crate::diag::{Diagnostic, Source};
use roxmltree::{Document, Node, NodeId};
use std::collections::HashMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// The sections of `<mujoco>` (MuJoCo's schema, `mjcf.xsd`): each stands
/// directly under `<mujoco>` only (`<default>` inside `<default>` is a
/// class).
const SECTIONS: [&str; 17] = [
    "actuator",
    "asset",
    "compiler",
    "contact",
    "custom",
    "default",
    "deformable",
    "equality",
    "extension",
    "keyframe",
    "option",
    "sensor",
    "size",
    "statistic",
    "tendon",
    "visual",
    "worldbody",
];

/// A model MuJoCo compiles from a main file and the files it includes.
pub(super) struct Model<'s, 'a, 'i> {
    /// Per file (0: the main one), for located messages.
    pub xmls: Vec<Xml<'s>>,
    /// The main file's `<mujoco>`.
    pub root: Node<'a, 'i>,
    /// Per file, its root element.
    pub roots: Vec<Node<'a, 'i>>,
    /// (file, an `<include>` element of it) → the file it brings in.
    targets: HashMap<(usize, NodeId), usize>,
    /// Per file, the `<include>` that brings it in: (file, element) (None
    /// for the main file).
    sites: Vec<Option<(usize, Node<'a, 'i>)>>,
    /// Per file, the main file's `<include>` element that brings it in
    /// (None for the main file).
    anchors: Vec<Option<Range<usize>>>,
    /// Where its files and mesh files may be read from (`roots`).
    pub dirs: Vec<PathBuf>,
}

/// The children of an element with each `<include>` spliced
/// (`Model::children`): a cursor per level of includes entered.
pub(super) struct Children<'m, 's, 'a, 'i> {
    m: &'m Model<'s, 'a, 'i>,
    /// (file, the next element to visit at that level), innermost last.
    stack: Vec<(usize, Option<Node<'a, 'i>>)>,
}

impl<'a, 'i> Iterator for Children<'_, '_, 'a, 'i> {
    type Item = (usize, Node<'a, 'i>);

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            let top = self.stack.last_mut()?;
            let (file, Some(node)) = *top else {
                self.stack.pop();
                continue;
            };
            top.1 = node.next_sibling_element();
            if qname(node) != "include" {
                return Some((file, node));
            }
            // NOTE: `load` read every `<include>` (or refused the model);
            // one without a target is only in a model of one file
            // (`single`), whose includes its callers refuse first.
            if let Some(&t) = self.m.targets.get(&(file, node.id())) {
                self.stack.push((t, self.m.roots[t].first_element_child()));
            }
        }
    }
}

impl<'s, 'a, 'i> Model<'s, 'a, 'i> {
    /// The model of one file, its includes not followed (`read`'s callers
    /// that refuse them first).
    pub fn single(source: &'s Source, root: Node<'a, 'i>) -> Self {
        Model {
            xmls: vec![Xml { source }],
            root,
            roots: vec![root],
            targets: HashMap::new(),
            sites: vec![None],
            anchors: vec![None],
            dirs: roots(source, &Resolve::default()),
        }
    }

    /// The model of `files`, each parsed into `docs` (in the same order).
    pub fn of(files: &'s Files<'s>, docs: &'a [Document<'i>]) -> Self {
        let count = docs.len();
        let mut m = Model {
            xmls: (0..count)
                .map(|k| Xml {
                    source: files.source(k),
                })
                .collect(),
            root: docs[0].root_element(),
            roots: docs.iter().map(Document::root_element).collect(),
            targets: HashMap::new(),
            sites: vec![None; count],
            anchors: vec![None; count],
            dirs: files.roots.clone(),
        };
        // A file brings in only files read after it (`load`): each file's
        // anchor is known before its own includes are met.
        for (k, doc) in docs.iter().enumerate() {
            for inc in doc.descendants().filter(|n| qname(*n) == "include") {
                let Some(&t) = files.targets.get(&(k, inc.range().start)) else {
                    continue;
                };
                m.targets.insert((k, inc.id()), t);
                m.sites[t] = Some((k, inc));
                m.anchors[t] = Some(m.anchors[k].clone().unwrap_or_else(|| inc.range()));
            }
        }
        m
    }

    /// The element children of `node` (of file `file`), each `<include>`
    /// replaced by the children of its file's root, at any depth: what
    /// MuJoCo's reader sees there. (file, element).
    pub fn children<'m>(&'m self, file: usize, node: Node<'a, 'i>) -> Children<'m, 's, 'a, 'i> {
        Children {
            m: self,
            stack: vec![(file, node.first_element_child())],
        }
    }

    /// The children of `node` named `name`.
    pub fn named<'m>(
        &'m self,
        file: usize,
        node: Node<'a, 'i>,
        name: &'m str,
    ) -> impl Iterator<Item = (usize, Node<'a, 'i>)> + 'm {
        self.children(file, node)
            .filter(move |(_, n)| qname(*n) == name)
    }

    /// The elements under `node`, at any depth, includes spliced, in
    /// document order (`node` itself not among them), with a stack of its
    /// own.
    pub fn descendants(&self, file: usize, node: Node<'a, 'i>) -> Vec<(usize, Node<'a, 'i>)> {
        let mut out = Vec::new();
        let mut stack: Vec<(usize, Node)> = self.children(file, node).collect();
        stack.reverse();
        while let Some((f, n)) = stack.pop() {
            out.push((f, n));
            let from = stack.len();
            stack.extend(self.children(f, n));
            stack[from..].reverse();
        }
        out
    }

    /// The element `node` (of file `file`) stands in once includes are
    /// spliced: its parent, or for a child of an included file's root, the
    /// parent of the `<include>` that brings it in. None for the main
    /// file's root.
    pub fn parent(&self, file: usize, node: Node<'a, 'i>) -> Option<(usize, Node<'a, 'i>)> {
        let (mut f, mut n) = (file, node);
        loop {
            let p = n.parent_element()?;
            match self.sites[f] {
                Some((g, inc)) if p == self.roots[f] => (f, n) = (g, inc),
                _ => return Some((f, p)),
            }
        }
    }

    /// Refuse `node` (of file `file`) if it is a section of `<mujoco>`
    /// standing anywhere else once includes are spliced (MuJoCo: "Schema
    /// violation: unrecognized element"): a whole model's file included
    /// inside `<worldbody>`, say, whose `<worldbody>` MuJoCo refuses there
    /// and massprop would otherwise read as a different model.
    pub fn in_place(&self, file: usize, node: Node<'a, 'i>) -> Result<(), Diagnostic> {
        let name = qname(node);
        if !SECTIONS.contains(&name) {
            return Ok(());
        }
        let Some((pf, parent)) = self.parent(file, node) else {
            return Ok(());
        };
        let within = qname(parent);
        if (pf == 0 && parent == self.root) || (name == "default" && within == "default") {
            return Ok(());
        }
        let xml = self.xml(file);
        let d = xml.error(
            xml.tag(node),
            format!("`<{name}>` inside `<{within}>`: MuJoCo refuses it there (an unrecognized element); `<{name}>` stands directly under `<mujoco>`"),
        );
        // Where an include put it there, say how an include is spliced.
        Err(
            if node.parent_element() == Some(self.roots[file]) && file > 0 {
                d.help(format!("an `<include>` is replaced by the children of its file's root element: a file included inside `<{within}>` holds what is written there (bodies, not a `<worldbody>` around them)"))
            } else {
                d
            },
        )
    }

    /// The file's `Xml`, for its located messages.
    pub fn xml(&self, file: usize) -> &Xml<'s> {
        &self.xmls[file]
    }

    /// The sections named `name` (`<mujoco>`'s children, includes
    /// spliced), each with its file's `Xml` and index.
    pub fn sections<'m>(
        &'m self,
        name: &'m str,
    ) -> impl Iterator<Item = (&'m Xml<'s>, usize, Node<'a, 'i>)> + 'm {
        self.named(0, self.root, name)
            .map(|(f, n)| (&self.xmls[f], f, n))
    }

    /// Where an element of `file` whose bytes are `range` stands in the
    /// main file: there, or at the `<include>` that brings its file in.
    pub fn range(&self, file: usize, range: Range<usize>) -> Range<usize> {
        self.anchors[file].clone().unwrap_or(range)
    }
}

/// Every file `top` (an MJCF main file) includes, at any depth; each
/// document parsed (index 0: `top`'s).
pub(super) fn load<'s>(top: &'s Source, r: &Resolve) -> Result<Files<'s>, Diagnostic> {
    let mut l = Loader {
        files: Files::new(top),
        known: HashMap::new(),
        chain: vec![(canonical(top.path()), top.name.clone())],
        roots: roots(top, r),
        base: top
            .path()
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default(),
    };
    l.known.insert(canonical(top.path()), (0, top.name.clone()));
    l.file(0)?;
    l.files.roots = l.roots;
    Ok(l.files)
}

/// Parse every file of `files`, in its order.
pub(super) fn parse<'s>(files: &'s Files<'s>) -> Result<Vec<Document<'s>>, Diagnostic> {
    (0..files.included.len() + 1)
        .map(|k| super::parse(files.source(k)))
        .collect()
}

struct Loader<'s> {
    files: Files<'s>,
    /// Canonical path → (file index, where it was included from, or its
    /// name for the main file): MuJoCo reads each file once.
    known: HashMap<PathBuf, (usize, String)>,
    /// The files being read, outermost first: a file met again among them
    /// closes a cycle.
    chain: Vec<(PathBuf, String)>,
    roots: Vec<PathBuf>,
    /// The main file's directory, which MuJoCo resolves every include
    /// against first.
    base: PathBuf,
}

impl Loader<'_> {
    /// The includes of file `k`, each read (depth first).
    fn file(&mut self, k: usize) -> Result<(), Diagnostic> {
        let source = self.files.source(k).clone();
        let doc = super::parse(&source)?;
        let xml = Xml { source: &source };
        for inc in doc.descendants().filter(|n| qname(*n) == "include") {
            if let Some(c) = inc.children().find(Node::is_element) {
                return Err(xml.error(
                    xml.tag(c),
                    "an `<include>` cannot have children (MuJoCo refuses them)",
                ));
            }
            let file = xml.required(inc, "file", "an `<include>`")?;
            let at = file.range.clone();
            let written = Path::new(&file.text);
            // MuJoCo's first try is the main file's directory; an include
            // of an included file falls back to that file's directory.
            let first = self.base.join(written);
            let path = match source.path().parent() {
                Some(dir) if k > 0 && !first.exists() && !written.is_absolute() => {
                    dir.join(written)
                }
                _ => first,
            };
            let shown = crate::diag::display_path(&path);
            let canon = std::fs::canonicalize(&path).map_err(|e| {
                xml.error(
                    at.clone(),
                    format!("cannot read the included file `{shown}`: {e}"),
                )
                .help("an MJCF include's path is relative to the main model file's directory")
            })?;
            if let Some(i) = self.chain.iter().position(|(p, _)| *p == canon) {
                let names: Vec<String> = self.chain[i..]
                    .iter()
                    .map(|(_, n)| format!("`{n}`"))
                    .chain([format!("`{shown}`")])
                    .collect();
                return Err(xml.error(
                    at,
                    format!(
                        "`<include>` closes a cycle of includes: {}",
                        names.join(" → ")
                    ),
                ));
            }
            if let Some((_, first)) = self.known.get(&canon) {
                return Err(xml.error(
                    at,
                    format!("`<include>` of `{shown}`: the file is already included, at {first} (MuJoCo includes a file once)"),
                ));
            }
            if self.chain.len() > MAX_DEPTH {
                return Err(xml.error(
                    at,
                    format!(
                        "`<include>` of `{shown}`: includes nest more than {MAX_DEPTH} files deep"
                    ),
                ));
            }
            if !inside(&self.roots, &canon) {
                return Err(xml
                    .error(
                        at,
                        format!("the included `{shown}` lies outside the directories includes may read"),
                    )
                    .help("an MJCF include may read the main file's directory, the working directory, and `--include-root`s"));
            }
            let bytes = std::fs::read(&canon).map_err(|e| {
                xml.error(
                    at.clone(),
                    format!("cannot read the included file `{shown}`: {e}"),
                )
            })?;
            let (line, col) = source.line_col(at.start);
            let site = format!("{}:{line}:{col}", source.name);
            if bytes.is_empty() {
                return Err(xml.error(
                    at,
                    format!("`<include>` of `{shown}`: the file is empty (MuJoCo refuses an empty include)"),
                ));
            }
            let s = crate::io::source_of(&shown, bytes)
                .map_err(|d| d.included_from(site.clone()))?
                .read_from(path.clone());
            let included = super::parse(&s).map_err(|d| d.included_from(site.clone()))?;
            let found = qname(included.root_element());
            // NOTE: MuJoCo takes any root (`<mujoco>`, the older
            // `<mujocoinclude>`, …) and splices its children; a URDF's or
            // an SDFormat file's elements it then refuses as MJCF
            // ("unrecognized element"), and so does massprop, naming the
            // root rather than reading past elements it does not know.
            if let Some(format) = match found {
                "robot" => Some("a URDF file"),
                "sdf" => Some("an SDFormat file"),
                _ => None,
            } {
                return Err(xml.error(
                    at,
                    format!(
                        "`<include>` of `{shown}`: its root element is `<{found}>`, {format}: MuJoCo puts the children of the included file's root in the `<include>`'s place and refuses them as MJCF"
                    ),
                ));
            }
            if !included.root_element().children().any(|c| c.is_element()) {
                return Err(xml.error(
                    at,
                    format!("`<include>` of `{shown}`: its root element `<{}>` holds no element (MuJoCo refuses an empty include)", crate::diag::shorten(found)),
                ));
            }
            drop(included);
            self.files.included.push(s);
            self.files.from.push(site.clone());
            let t = self.files.included.len();
            self.known.insert(canon.clone(), (t, site.clone()));
            self.chain.push((canon, shown));
            self.file(t).map_err(|d| d.included_from(site))?;
            self.chain.pop();
            self.files.targets.insert((k, inc.range().start), t);
        }
        Ok(())
    }
}

/// `f` of the model of the MJCF main file `source` and its includes
/// (resolved by `r`), its errors located with where their file was
/// included from.
pub(super) fn with_model<T>(
    source: &Source,
    r: &Resolve,
    f: impl FnOnce(&Model) -> Result<T, Diagnostic>,
) -> Result<T, Diagnostic> {
    let files = load(source, r)?;
    let docs = parse(&files)?;
    let m = Model::of(&files, &docs);
    f(&m).map_err(|d| files.located(d))
}
