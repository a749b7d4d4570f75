//! Sub-assemblies: `[[part]] include = "motor.toml"` places another part
//! file's parts here, its origin at `origin` and its axes turned by
//! `rotation`, converted from its units to this file's.
//!
//! NOTE: each distinct file is read and validated once, however often it
//! is included with the same `params` (an include with other parameters
//! is another model: a file with `[params]` is parsed once all the same,
//! and converted again with only its changed parameters re-evaluated,
//! `Parsed`), and kept once (`Include` holds it by `Arc`); its parts are
//! moved into this file's frame and units as a walk reaches them
//! (`walk`), in f64 (each coordinate rounds once, as a unit string does); a
//! sub-assembly placed without rotation, at an origin and in units that make
//! the arithmetic exact (the same units, integer origins) is carried over
//! exactly.

use super::raw::RawPart;
use super::rotation::Orientation;
use super::{Ctx, Frame, Include, Item, Model};
use crate::diag::Diagnostic;
use crate::units::Dim;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use toml::Spanned;

/// Includes may nest this deep.
pub const MAX_INCLUDE_DEPTH: usize = 32;

/// Where includes may come from, and what a piped file's are relative to
/// (`--include-root`, `--base-dir`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Includes {
    /// More directory trees includes may come from.
    pub roots: Vec<PathBuf>,
    /// The directory that the includes of a file read from standard input
    /// or a pipe are relative to; without it, such a file may not include.
    pub base_dir: Option<PathBuf>,
    /// `--set NAME=VALUE`, as typed: parameters of the file named (not of
    /// the files it includes, which take theirs from `params` on the
    /// include).
    pub set: Vec<String>,
}

/// A warning of a mesh file (what its exact answer survives, what a
/// `weld` merged): the part file it is in, as named, and the place of the
/// part's `file` (or `weld`) key there. `analysis::plausible` reports it
/// with the plausibility warnings.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshNote {
    pub path: String,
    pub span: crate::diag::Span,
    pub message: String,
}

/// The files being read: the chain of includes (for cycles) and each file
/// parsed once, however many times it is included.
#[derive(Default)]
pub(super) struct Files {
    pub(super) stack: Vec<(PathBuf, String)>,
    /// By file and the parameters passed to it (`params`): an include
    /// with other parameters is another model.
    cache: HashMap<(PathBuf, String), std::sync::Arc<Model>>,
    /// Every file included
    /// (and every mesh file read), at any depth, as often as it is.
    pub(super) read: Vec<PathBuf>,
    /// Each mesh file read once, by its canonical path and mode, however
    /// many parts use it (`model::mesh`).
    pub(super) meshes:
        HashMap<(PathBuf, crate::mesh::Mode, Option<u64>), std::sync::Arc<crate::mesh::MeshBody>>,
    /// The warnings of the mesh files read (`model::mesh`), each once.
    pub(super) mesh_warnings: Vec<MeshNote>,
    /// Part files' texts the reader read (`Model::texts_read`).
    pub(super) reads: u64,
    /// The directory trees includes must stay in (canonical): the
    /// top-level file's, the working directory, and any `--include-root`.
    pub(super) roots: Vec<PathBuf>,
    /// `Includes::base_dir`, for the top-level file when it is piped.
    pub(super) base_dir: Option<PathBuf>,
    /// The parts each file holds with its includes, counted before any is
    /// expanded (`Ctx::count_includes`).
    counts: HashMap<PathBuf, u64>,
    /// Each included file that has parameters, parsed once, by its
    /// canonical path: another set of `params` converts it again without
    /// reading or parsing it.
    parsed: HashMap<PathBuf, Rc<Parsed>>,
}

/// An included file with `[params]`, parsed: its text, its raw TOML and
/// its own parameters evaluated (`params::Base`, made when it is first
/// converted).
///
/// NOTE: kept while the body is read, so its raw parts are not freed as
/// its parts are made (as a file read once has them): the price of not
/// parsing it again per set of `params` (40 includes of a file of 100,000
/// parameters took 50 s).
pub(super) struct Parsed {
    source: crate::diag::Source,
    raw: super::raw::RawFile,
    looks_like_a_part_file: bool,
    /// Its `[params]` evaluated alone (`params::Base::of`), once, as it
    /// is kept: each conversion re-evaluates only what a set of `params`
    /// changes.
    base: Option<super::params::Base>,
}

impl Parsed {
    /// Kept if it has parameters (only then may it be included with
    /// other values); the file `source` parsed into `raw`.
    fn keep(source: crate::diag::Source, raw: super::raw::RawFile) -> Rc<Parsed> {
        Rc::new(Parsed {
            looks_like_a_part_file: super::looks_like_a_part_file(&source.text),
            base: super::params::Base::of(&source, raw.params.as_ref()),
            source,
            raw,
        })
    }

    /// Its model with the values `passes`, as the include of `target`
    /// reads it: its errors said in the file as it names it, its own
    /// includes relative to that path (each include names it its own way,
    /// through a symlink perhaps).
    fn convert(
        &self,
        target: &Target,
        files: &mut Files,
        passes: &[super::params::Pass],
    ) -> Result<Model, Diagnostic> {
        let Target {
            canonical,
            shown,
            shown_name,
        } = target;
        let renamed;
        let source = if self.source.name == *shown_name && self.source.file.as_ref() == Some(shown)
        {
            &self.source
        } else {
            renamed = crate::diag::Source {
                name: shown_name.clone(),
                file: Some(shown.clone()),
                ..self.source.clone()
            };
            &renamed
        };
        let base = &self.base;
        files.stack.push((canonical.clone(), shown_name.clone()));
        let child = Model::from_raw(source, &self.raw, files, passes, base.as_ref());
        files.stack.pop();
        child
    }
}

impl Files {
    /// Every file included, at any depth, once each.
    pub(super) fn included(mut self) -> Vec<PathBuf> {
        self.read.sort();
        self.read.dedup();
        self.read
    }
}

/// The names given to one file's sub-assemblies: `wheel`, `wheel #2`, …
/// Kept as the file is read, so that N copies of one include cost O(N)
/// (scanning the parts, or counting up from #2, for each made it N² or N³).
#[derive(Default)]
pub(super) struct AssemblyNames {
    taken: std::collections::HashSet<String>,
    /// For each base name, the last `#k` given.
    last: HashMap<String, usize>,
    /// Each `name` written on an include, and where: a name the user wrote
    /// is never numbered (`Ctx::include` refuses it written twice), so
    /// `--only NAME` always selects what the user named.
    written: HashMap<String, std::ops::Range<usize>>,
}

impl AssemblyNames {
    fn claim(&mut self, base: &str) -> String {
        let k = self.last.entry(base.to_string()).or_insert(0);
        let mut name = base.to_string();
        loop {
            *k += 1;
            if *k > 1 {
                name = format!("{base} #{k}");
            }
            if self.taken.insert(name.clone()) {
                return name;
            }
        }
    }
}

/// Where an include points, checked.
pub(super) struct Target {
    /// Canonical: symlinks followed.
    pub(super) canonical: PathBuf,
    /// As the including file names it, relative to the working directory.
    pub(super) shown: PathBuf,
    pub(super) shown_name: String,
}

/// What a path a part names is: a part file to include, or a mesh file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Include,
    Mesh,
}

impl Kind {
    /// "the included `x`" or "the mesh file `x`".
    fn the(self, shown: &str) -> String {
        match self {
            Kind::Include => format!("the included `{shown}`"),
            Kind::Mesh => format!("the mesh file `{shown}`"),
        }
    }

    fn plural(self) -> &'static str {
        match self {
            Kind::Include => "includes",
            Kind::Mesh => "mesh files",
        }
    }

    fn key(self) -> &'static str {
        match self {
            Kind::Include => "include",
            Kind::Mesh => "file",
        }
    }
}

impl Ctx<'_> {
    /// Resolve `include = ".."` (see `target_of`).
    fn target(&self, inc: &Spanned<String>, files: &Files) -> Result<Target, Diagnostic> {
        self.target_of(inc, files, Kind::Include)
    }

    /// Resolve a path a part names (`include = ".."`, a mesh's `file`)
    /// and apply every rule on where it may point before anything of it is
    /// read: relative to the part file (or `--base-dir` for a piped one),
    /// inside the allowed directory trees, a regular file, within the size
    /// limit, of the kind's extension. The one place these rules live:
    /// counting and expanding includes, and reading meshes, all come
    /// through here.
    pub(super) fn target_of(
        &self,
        inc: &Spanned<String>,
        files: &Files,
        kind: Kind,
    ) -> Result<Target, Diagnostic> {
        let key = kind.key();
        let base = match (self.source.piped, &files.base_dir) {
            (false, _) => self.source.path().parent().unwrap_or(Path::new("")),
            (true, Some(dir)) => dir.as_path(),
            (true, None) => {
                // Relative to what? Not silently the working directory: a
                // file piped in (`git show OLD:arm.toml | massprop diff -
                // arm.toml`) would include today's sub-assemblies unasked.
                let what = if self.source.name == "<stdin>" {
                    "standard input"
                } else {
                    "a pipe"
                };
                return Err(self
                    .err(inc.span(), format!("`{key}` in a file read from {what}: its path has nothing to be relative to"))
                    .help(format!("give `--base-dir DIR`, the directory its {} are relative to, or the file by its path", kind.plural())));
            }
        };
        let shown = base.join(inc.get_ref());
        let shown_name = crate::diag::display_path(&shown);
        let the = kind.the(&shown_name);
        let unreadable = |e: std::io::Error| {
            let what = match kind {
                Kind::Include => "the included file",
                Kind::Mesh => "the mesh file",
            };
            self.err(
                inc.span(),
                format!("cannot read {what} `{shown_name}`: {e}"),
            )
            .help(match kind {
                Kind::Include => "the path is relative to the including file",
                Kind::Mesh => "the path is relative to the part file",
            })
        };
        let canonical = std::fs::canonicalize(&shown).map_err(|e| {
            let d = unreadable(e);
            match near_include(&shown, inc.get_ref(), &files.roots, kind) {
                Some(near) => {
                    let why = d.help_text().unwrap_or_default().to_string();
                    d.help(format!("did you mean `{near}`? ({why})"))
                }
                None => d,
            }
        })?;
        // Confined: a part file from a pull request must not read, and
        // quote in an error, any file it names (`/proc/self/environ`).
        if !files.roots.iter().any(|r| canonical.starts_with(r)) {
            return Err(self
                .err(
                    inc.span(),
                    format!(
                        "{the} is outside the directory of the part file and the working directory"
                    ),
                )
                .help(format!("{} stay inside those directory trees (after following symlinks); `--include-root DIR` allows another", kind.plural())));
        }
        let meta = std::fs::metadata(&canonical).map_err(unreadable)?;
        if meta.len() > crate::io::MAX_FILE_BYTES {
            return Err(self.err(
                inc.span(),
                format!(
                    "{the} is larger than the limit of {} MiB",
                    crate::io::MAX_FILE_BYTES >> 20
                ),
            ));
        }
        if !meta.is_file() {
            return Err(self
                .err(inc.span(), format!("{the} is not a regular file"))
                .help(match kind {
                    Kind::Include => "`include` names a part file",
                    Kind::Mesh => "`file` names a mesh file",
                }));
        }
        match kind {
            // Only part files: `.env` or `.git/config` (where a CI checkout
            // keeps its token) would be parsed as TOML and quoted in the error.
            Kind::Include
                if !crate::io::is_toml(&canonical) && !crate::robot::may_be_robot(&canonical) =>
            {
                return Err(self
                    .err(inc.span(), format!("{the} is not a part file (`*.toml`) or a robot description (`*.urdf`, `*.sdf`, `*.xml`)"))
                    .help("`include` names a part file or a robot description, after following symlinks"));
            }
            // Only mesh files, by their extension (after following
            // symlinks): nothing else is read and quoted as a mesh.
            Kind::Mesh if crate::mesh::FileType::of(&canonical).is_none() => {
                return Err(self
                    .err(
                        inc.span(),
                        format!("{the} is not a mesh file (`*.stl` or `*.obj`)"),
                    )
                    .help("`file` names an STL or Wavefront OBJ file, after following symlinks"));
            }
            _ => {}
        }
        Ok(Target {
            canonical,
            shown,
            shown_name,
        })
    }
}

impl Ctx<'_> {
    /// Refuse a body of more than `MAX_PARTS` parts before any include is
    /// expanded: the parts of `raw_parts` counted with every file they
    /// include, each file read and counted once however often it is
    /// included. A binary tree of 32 files describing 2³¹ parts was
    /// refused only once 2²¹ of them had been built, after 7 GB.
    ///
    /// NOTE: an included file that includes others is parsed here and
    /// again when it is expanded; one that includes nothing (most, and the
    /// large ones) has its `[[part]]` lines counted, not parsed (parsing
    /// every included file twice cost 40 % on a file that includes one of
    /// 60,000 parts). Either count may miss parts written otherwise (a
    /// `part = [...]` array) or count a `[[part]]` line inside a multi-line
    /// string: the limit is enforced exactly again as parts are expanded.
    /// An include that cannot be counted (any error, a cycle) counts as one
    /// part: expanding it reports the error where it is.
    pub(super) fn check_part_count(
        &self,
        raw_parts: &[Spanned<RawPart>],
        files: &mut Files,
    ) -> Result<(), Diagnostic> {
        if !raw_parts.iter().any(|p| p.get_ref().include.is_some()) {
            return Ok(());
        }
        let max = super::MAX_PARTS as u64;
        let mut total = 0u64;
        for p in raw_parts {
            // Its copies (`array`, `mirror`) count it again each.
            let copies = super::copies::raw_multiplicity(p.get_ref());
            let Some(inc) = &p.get_ref().include else {
                total = total.saturating_add(copies);
                continue;
            };
            let (n, shown) = match self.count_include(inc, files) {
                Some((n, shown)) => (n, shown),
                None => (1, String::new()),
            };
            let n = n.saturating_mul(copies);
            total = total.saturating_add(n);
            if total > max {
                // A count that saturated is past u64.
                let said = |n: u64| match n {
                    u64::MAX => "more than 2⁶⁴".to_string(),
                    n => n.to_string(),
                };
                return Err(self
                    .err(
                        inc.span(),
                        format!(
                            "with this include the body has {} parts, past the limit of {max}: `{shown}` holds {} with its includes",
                            said(total),
                            said(n)
                        ),
                    )
                    .help("each copy of a sub-assembly counts its parts again"));
            }
        }
        Ok(())
    }

    /// The parts the file `inc` names holds with its includes, and its name
    /// as shown; `None` if it cannot be counted.
    fn count_include(&self, inc: &Spanned<String>, files: &mut Files) -> Option<(u64, String)> {
        let t = self.target(inc, files).ok()?;
        if let Some(n) = files.counts.get(&t.canonical) {
            return Some((*n, t.shown_name));
        }
        if files.stack.len() >= MAX_INCLUDE_DEPTH
            || files.stack.iter().any(|(c, _)| *c == t.canonical)
        {
            return None;
        }
        files.read.push(t.canonical.clone());
        let bytes = std::fs::read(&t.shown).ok()?;
        let source = crate::io::source_of(&t.shown_name, bytes)
            .ok()?
            .read_from(t.shown.clone());
        // A file that includes nothing holds its `[[part]]` tables: counted
        // from the text, not parsed (it is parsed when it is expanded).
        if !["include", "array", "mirror"]
            .iter()
            .any(|k| source.text.contains(k))
        {
            let n = super::part_tables(&source.text);
            files.counts.insert(t.canonical, n);
            return Some((n, t.shown_name));
        }
        files.reads += 1;
        let raw = Model::raw(&source).ok()?;
        // Kept, not parsed again when it is expanded, if it has parameters.
        let (raw, kept) = match raw.params {
            Some(_) => {
                let kept = Parsed::keep(source.clone(), raw);
                files.parsed.insert(t.canonical.clone(), kept.clone());
                (None, Some(kept))
            }
            None => (Some(raw), None),
        };
        let raw = raw.as_ref().or(kept.as_ref().map(|k| &k.raw))?;
        let child = Ctx {
            source: &source,
            units: Default::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        files
            .stack
            .push((t.canonical.clone(), t.shown_name.clone()));
        let n = raw.part.as_ref().map_or(0, |parts| {
            parts.get_ref().iter().fold(0u64, |n, p| {
                let copies = super::copies::raw_multiplicity(p.get_ref());
                n.saturating_add(copies.saturating_mul(match &p.get_ref().include {
                    None => 1,
                    Some(inc) => child.count_include(inc, files).map_or(1, |(n, _)| n),
                }))
            })
        });
        files.stack.pop();
        files.counts.insert(t.canonical, n);
        Some((n, t.shown_name))
    }
}

/// The keys of a part that includes a file, besides `name` (the JSON
/// Schema reads them too: `model::schema`).
pub(super) const INCLUDE_KEYS: [&str; 5] = ["include", "origin", "rotation", "params", "joints"];

impl Ctx<'_> {
    /// Read `[[part]] include = ".."` at position `index` into the
    /// sub-assembly it places, `parts` the parts of the body before it.
    pub(super) fn include(
        &self,
        rec: &mut super::tolerance::Recorder,
        index: usize,
        raw: &Spanned<RawPart>,
        files: &mut Files,
        parts: usize,
        names: &mut AssemblyNames,
    ) -> Result<Item, Diagnostic> {
        let p = raw.get_ref();
        let inc = p.include.as_deref().expect("the caller checked `include`");
        if let Some((key, span)) = super::keys::present_keys(p)
            .into_iter()
            .filter(|(k, _)| !INCLUDE_KEYS.contains(k))
            .find_map(|(k, s)| s.map(|s| (k, s)))
        {
            let what = if key == "shape" {
                "`shape` conflicts with `include`: a part is a shape or a sub-assembly".to_string()
            } else {
                format!("`{key}` does not apply to an included sub-assembly")
            };
            return Err(self.err(span, what).help(
                "an include takes `include`, and optionally `name`, `origin` and `rotation`",
            ));
        }
        let target = self.target(inc, files)?;
        let (canonical, shown, shown_name) = (
            target.canonical.clone(),
            target.shown.clone(),
            target.shown_name.clone(),
        );
        let unreadable = |e: std::io::Error| {
            self.err(
                inc.span(),
                format!("cannot read the included file `{shown_name}`: {e}"),
            )
            .help("the path is relative to the including file")
        };
        if files.stack.len() >= MAX_INCLUDE_DEPTH {
            let chain: Vec<&str> = files.stack.iter().map(|(_, n)| n.as_str()).collect();
            return Err(self
                .err(
                    inc.span(),
                    format!(
                        "includes nest deeper than {MAX_INCLUDE_DEPTH} files: {} → {shown_name}",
                        chain.join(" → ")
                    ),
                )
                .help("a deeper tree is almost certainly a mistake; flatten it")
                .with_chain_in_message());
        }
        if let Some(at) = files.stack.iter().position(|(c, _)| *c == canonical) {
            let chain: Vec<&str> = files.stack[at..].iter().map(|(_, n)| n.as_str()).collect();
            return Err(self
                .err(
                    inc.span(),
                    format!("include cycle: {} → {shown_name}", chain.join(" → ")),
                )
                .help("a sub-assembly cannot contain itself")
                .with_chain_in_message());
        }
        let robot = !crate::io::is_toml(&canonical);
        if let (false, Some(j)) = (robot, &p.joints) {
            return Err(self
                .err(j.span(), "`joints` sets the joints of an included robot description, and this include names a part file")
                .help("a robot description is a `*.urdf`, `*.sdf` or `*.xml` (URDF, SDFormat, MJCF)"));
        }
        if let (true, Some(table)) = (robot, &p.params) {
            return Err(self
                .err(table.span(), "`params` passes parameters to an included part file, and this include names a robot description")
                .help("an included robot takes `joints = { NAME = VALUE }`"));
        }
        let passes = match &p.params {
            Some(table) => self.include_params(table, &shown_name)?,
            None => Vec::new(),
        };
        let key = (canonical.clone(), super::params::cache_key(&passes));
        files.read.push(canonical.clone());
        let child = if robot {
            std::sync::Arc::new(self.robot_include(
                inc,
                &shown,
                &shown_name,
                p.joints.as_deref(),
                &files.roots,
            )?)
        } else {
            match files.cache.get(&key) {
                Some(m) => m.clone(),
                None => {
                    // An error inside says where it was included from, as
                    // compilers do: one note per level, innermost first.
                    let included_here = |d: Diagnostic| {
                        let (line, col) = self.source.line_col(inc.span().start);
                        d.included_from(format!("{}:{line}:{col}", self.source.name))
                    };
                    // An error inside a file that is not a part file at all
                    // (a `secrets.toml`) is said without quoting any of it.
                    let not_a_part_file = || {
                        self.err(
                        inc.span(),
                        format!("the included `{shown_name}` is not a part file: it has no `[[part]]` table"),
                    )
                    .help("`include` names a part file; its contents are not shown")
                    };
                    let quoted = |looks_like_a_part_file: bool| {
                        move |d: Diagnostic| {
                            if looks_like_a_part_file {
                                included_here(d)
                            } else {
                                not_a_part_file()
                            }
                        }
                    };
                    let (child, looks_like_a_part_file) =
                        match files.parsed.get(&canonical).cloned() {
                            Some(parsed) => (
                                parsed.convert(&target, files, &passes),
                                parsed.looks_like_a_part_file,
                            ),
                            None => {
                                let bytes = std::fs::read(&shown).map_err(unreadable)?;
                                let looks_like_a_part_file =
                                    super::looks_like_a_part_file(&String::from_utf8_lossy(&bytes));
                                let source = crate::io::source_of(&shown_name, bytes)
                                    .map_err(quoted(looks_like_a_part_file))?
                                    .read_from(shown.clone());
                                // NOTE: a file that may have parameters is parsed
                                // once and kept (`Parsed`): each other set of
                                // `params` converts it again, re-evaluating only
                                // the parameters that change.
                                let child = if source.text.contains("params") {
                                    files.reads += 1;
                                    Model::raw(&source).and_then(|raw| {
                                        let parsed = Parsed::keep(source, raw);
                                        if parsed.raw.params.is_some() {
                                            files.parsed.insert(canonical.clone(), parsed.clone());
                                        }
                                        parsed.convert(&target, files, &passes)
                                    })
                                } else {
                                    files.stack.push((canonical.clone(), shown_name.clone()));
                                    let child = Model::parse_in(&source, files, &passes);
                                    files.stack.pop();
                                    child
                                };
                                (child, looks_like_a_part_file)
                            }
                        };
                    let child = std::sync::Arc::new(child.map_err(|d| {
                        // A name the included file does not define: said at
                        // the include's key, in this file.
                        if passes.iter().any(|p| p.undefined.message() == d.message()) {
                            d
                        } else {
                            quoted(looks_like_a_part_file)(d)
                        }
                    })?);
                    files.cache.insert(key, child.clone());
                    child
                }
            }
        };

        let base_name = match (&p.name, &child.name) {
            (Some(n), _) => n.get_ref().clone(),
            (None, Some(n)) => n.clone(),
            (None, None) => shown
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| format!("part {}", index + 1)),
        };
        // A name written on two includes is refused, both places named: a
        // `#2` would make one of them a name the user did not write.
        if let Some(n) = &p.name
            && let Some(first) = names.written.insert(n.get_ref().clone(), n.span())
        {
            let (line, col) = self.source.line_col(first.start);
            return Err(self
                .err(
                    n.span(),
                    format!(
                        "the sub-assembly name `{}` is written twice",
                        crate::diag::shorten(n.get_ref())
                    ),
                )
                .label("written again here")
                .note(format!("first written at {}:{line}:{col}", self.source.name))
                .help("name the sub-assemblies apart, each `name` its own: `--only` selects a sub-assembly by the name written (two includes without a `name` are numbered: `wheel`, `wheel #2`)"));
        }
        // Two copies of a sub-assembly in one file named by their file
        // (its stem or its own `name`) get distinct names: `wheel`,
        // `wheel #2`, … (so `--only` and `diff` can tell them apart).
        let name = names.claim(&base_name);
        let ratio = |dim: Dim| {
            child
                .units
                .factor(dim)
                .per(self.units.factor(dim))
                .map(|f| f.value())
                .unwrap_or_else(|| child.units.factor(dim).value() / self.units.factor(dim).value())
        };
        let orientation = match &p.rotation {
            Some(r) => self.rotation(r)?,
            None => Orientation::Identity,
        };
        // Its origin may carry tolerances: the sub-assembly's place.
        rec.enter_origin();
        let origin = match &p.origin {
            // Checked in SI too, as every length is.
            Some(o) => self.value3(rec, 0, o, "origin", Dim::LENGTH)?.0,
            None => [0.0; 3],
        };
        let tol = rec.leave_origin();
        let exact = |dim: Dim| child.units.factor(dim).per(self.units.factor(dim));
        let frame = Frame::include(
            origin,
            orientation,
            [exact(Dim::LENGTH), exact(Dim::MASS)],
            [ratio(Dim::LENGTH), ratio(Dim::MASS)],
        );
        if parts + child.count > super::MAX_PARTS {
            return Err(self.err(
                inc.span(),
                format!(
                    "this include takes the body past {} parts, the limit",
                    super::MAX_PARTS
                ),
            ));
        }
        let tag = self.include_tag(p, &child)?;
        let include = Include {
            name,
            frame,
            model: child,
            span: raw.span(),
            copies: None,
            tag,
            tol,
        };
        // Representable in this file's units too (the composer works in
        // them): a sub-assembly in µm and mg can underflow in km and t.
        // Each part of it as placed here (its own sub-assemblies' frames
        // already checked when that file was read).
        let one = Model {
            items: std::sync::Arc::new(vec![Item::Include(Box::new(include))]),
            ..Model::empty(self.units)
        };
        let mut bad = None;
        // NOTE: walked only when some instance might leave the range: a
        // bound on every instance, formed once per distinct file, says
        // at once that none can (`frame::Reach`).
        let si = self.units.factor(Dim::LENGTH).value();
        let reach = super::frame::Reach::of(&one, &mut HashMap::new());
        if !reach.safe(si) {
            one.each_event(&mut |e| {
                if let super::Event::Part(l) = e
                    && bad.is_none()
                    && self.in_file_range(&l.part.spec, "", 0..0).is_err()
                {
                    bad = Some(l.index);
                }
            });
        }
        if let Some(index) = bad {
            // Again, named (names are made for the one part that fails).
            let p = one.part(index).expect("the part the walk met");
            self.in_file_range(&p.spec, &p.name, inc.span())?;
        }
        Ok(one.items[0].clone())
    }
}

/// For an include or a mesh that does not exist: the path as the file
/// writes it, its file name replaced by the nearest name of its kind in
/// its directory (`io::near_name`: `arm.tom` → `arm.toml`), when that
/// directory lies inside the roots includes may read: no name outside
/// them is listed.
fn near_include(shown: &Path, written: &str, roots: &[PathBuf], kind: Kind) -> Option<String> {
    let dir = shown
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let dir = std::fs::canonicalize(dir).ok()?;
    if !roots.iter().any(|r| dir.starts_with(r)) {
        return None;
    }
    let near = crate::io::near_name(shown, |p| match kind {
        Kind::Include => crate::io::is_toml(p),
        Kind::Mesh => crate::mesh::FileType::of(p).is_some(),
    })?;
    let name = Path::new(&near).file_name()?;
    Some(crate::diag::display_path(
        &Path::new(written).with_file_name(name),
    ))
}

#[cfg(test)]
mod tests {
    use super::AssemblyNames;

    #[test]
    fn copies_are_numbered_past_names_already_taken() {
        let mut names = AssemblyNames::default();
        assert_eq!(names.claim("wheel"), "wheel");
        // A sub-assembly the file itself called "wheel #3".
        assert_eq!(names.claim("wheel #3"), "wheel #3");
        assert_eq!(names.claim("wheel"), "wheel #2");
        assert_eq!(names.claim("wheel"), "wheel #4");
        assert_eq!(names.claim("arm"), "arm");
        // "wheel #3" asked for again gets its own number.
        assert_eq!(names.claim("wheel #3"), "wheel #3 #2");
    }
}
