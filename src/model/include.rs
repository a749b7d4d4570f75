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
//!
//! Where an include may point (resolved, confined, of its kind) is
//! `target`; counting a body's parts before it is expanded, `count`.

mod count;
mod target;

pub(super) use target::{Kind, Target};

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
    /// `--package NAME=DIR` (`package`): the directory an SDFormat
    /// `<include>`'s `model://NAME` names (and a mesh's `package://NAME/`
    /// in `export --from-geometry`), for a robot description named on the
    /// command line or included by a part file at any depth.
    pub packages: Vec<(String, PathBuf)>,
}

impl Includes {
    /// `--package`'s value read: `NAME=DIR`, NAME not empty, DIR an
    /// existing directory. The one rule of the flag (every command that
    /// takes `--include-root` takes it, through `cli::IncludeArgs`).
    pub fn package(text: &str) -> Result<(String, PathBuf), String> {
        let (name, dir) = match text.split_once('=') {
            Some((n, d)) if !n.is_empty() && !d.is_empty() => (n, d),
            _ => {
                return Err(
                    "expected `NAME=DIR`: the directory that `model://NAME` (or `package://NAME/`) names"
                        .to_string(),
                );
            }
        };
        // NOTE: checked here, not where a robot first names it: a mistyped
        // DIR would otherwise pass in silence for a file that happens not
        // to use it, and be said as a missing model where one does.
        if !Path::new(dir).is_dir() {
            return Err(format!(
                "`{}` is not a directory (`--package NAME=DIR` names the directory of package `{}`)",
                crate::diag::shorten(dir),
                crate::diag::shorten(name)
            ));
        }
        Ok((name.to_string(), PathBuf::from(dir)))
    }

    /// Where a robot description named on the command line reads its
    /// includes from: `--package` and `--include-root` (the robot file's
    /// directory and the working directory are its own).
    pub fn resolve(&self) -> crate::robot::read::Resolve {
        crate::robot::read::Resolve {
            packages: self.packages.clone(),
            roots: self.roots.clone(),
        }
    }
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
    /// `Includes::packages`, for the robot descriptions included.
    pub(super) packages: Vec<(String, PathBuf)>,
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
            // NOTE: an SDFormat robot's own includes may read where the
            // part file's may (`--include-root` too), `--package`'s
            // directories, and the robot file's directory.
            let resolve = crate::robot::read::Resolve {
                packages: files.packages.clone(),
                roots: files.roots.clone(),
            };
            std::sync::Arc::new(self.robot_include(
                inc,
                &shown,
                &shown_name,
                p.joints.as_deref(),
                &resolve,
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
