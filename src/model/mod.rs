//! The validated part file: every part kept as the numbers the file gave,
//! in the file's own units (`part::Spec`), from which the composer works in
//! the precision asked for. This module owns every check on the input; a
//! `Model` that exists is valid.
//!
//! `raw` (and its fast path `fast`) mirror the TOML; `ctx` reads values;
//! `params` evaluates `[params]` and expressions in quantity strings;
//! `parts` validates a `[[part]]` against its shape's description;
//! `include` places sub-assemblies (`only` keeps one, for `--only`);
//! `expect` reads `[expect]`; `rotation`
//! the rotation forms; `toml_error` words the TOML crate's errors;
//! `schema` is the file's JSON Schema, made from `raw` and the shapes.

pub mod budget;
pub mod case;
mod copies;
mod ctx;
pub mod envelope;
pub mod expect;
pub mod fast;
pub mod frame;
mod include;
mod keys;
mod material;
mod mesh;
mod only;
mod params;
mod parts;
mod place;
pub mod raw;
mod robot_body;
pub mod rotation;
pub mod schema;
mod solids;
mod span;
mod streamed;
pub mod tolerance;
pub mod walk;

pub use copies::{Copies, push_copy_name};
pub use frame::Frame;
pub use include::Includes;
pub use walk::{Event, Leaf, RowEvent};

use crate::diag::{Diagnostic, Source};
use crate::la::Vector3;
use crate::part::{Part, Solid};
use crate::units::{self, Dim, FileUnits};
use ctx::Ctx;
use raw::RawFile;
use std::ops::Range;
use streamed::Streamed;
use toml::Spanned;

/// The most parts a body may have, included ones counted: ~1 KB of memory
/// each while reading.
pub const MAX_PARTS: usize = 2_000_000;

#[derive(Debug, Clone)]
pub struct Model {
    /// The file's `name`, if given.
    pub name: Option<String>,
    pub units: FileUnits,
    /// Whether the file gives `units` (else they are m and kg by default).
    pub units_given: bool,
    /// The file's own parts and sub-assemblies, in file order. The body's
    /// parts, sub-assemblies expanded, come from a walk (`each_part`).
    /// Shared: a model is cloned (into a summary, for its rows) without
    /// copying its parts. (An `Arc<Vec>`, not an `Arc<[Item]>`: made from
    /// the `Vec` it moves, where the slice is a copy, 29 MB more at the
    /// peak of a 100,000-part file.)
    pub items: std::sync::Arc<Vec<Item>>,
    /// The parts of the body, sub-assemblies expanded.
    pub count: usize,
    pub analysis: Analysis,
    /// `[expect]`, one scalar check per component.
    pub expect: Vec<expect::Check>,
    /// Whether some part, at any depth, gives its real thickness or
    /// diameter (`Item::Part::real`).
    pub has_real_sizes: bool,
    /// `[materials]`: name → density, kg/m³.
    pub materials: std::collections::BTreeMap<String, f64>,
    /// `[budget]`'s limit of the predicted mass, if given.
    pub budget: Option<budget::Limit>,
    /// `[envelope]`, if given (the file's own; an include's is not read).
    pub envelope: Option<envelope::Envelope>,
    /// Every file this one includes, at any depth, by its canonical path
    /// (so that `-o` can refuse to write onto any of them).
    pub included: Vec<std::path::PathBuf>,
    /// How many part files' texts the reader read to make it (the file
    /// itself, each include parsed, each file parsed to count its parts):
    /// the tests count the work an include costs with it, not the time.
    #[doc(hidden)]
    pub texts_read: u64,
    /// The file's toleranced quantities, in file order (a part's
    /// `Part::tol` points into them).
    pub sources: Vec<tolerance::Toleranced>,
    /// The most names in a part's group path, its sub-assemblies' groups
    /// counted: at most `budget::MAX_GROUP_DEPTH`.
    pub group_depth: usize,
    /// The warnings of its mesh files, at any depth (`model::mesh`): what
    /// their answers survive, and what a `weld` merged.
    pub mesh_warnings: Vec<include::MeshNote>,
    /// `[[case]]`: the body's loading cases, in file order (`case`).
    pub cases: Vec<case::Case>,
}

/// One `[[part]]` of a file: a part, or a sub-assembly placed.
///
/// NOTE: a part is held inline, a sub-assembly boxed: most items of most
/// files are parts, and a box each would cost an allocation per part.
#[derive(Debug, Clone)]
#[allow(clippy::large_enum_variant)]
pub enum Item {
    Part {
        part: Part,
        /// The real thickness of a plate or diameter of a rod that gives
        /// one, in the file's length unit.
        ///
        /// NOTE: kept beside the part, not in `Spec`, so that the composer
        /// cannot see it: the composition is the idealised one whatever
        /// this says, and only the report compares it with the solid.
        real: Option<(Solid, f64)>,
        /// Its `array` and `mirror`, if any (`copies`).
        copies: Option<Box<Copies>>,
        /// Its `group` and `maturity`, if any (`budget`).
        tag: Option<Box<budget::Tag>>,
    },
    Include(Box<Include>),
}

/// A sub-assembly: an included file, placed.
#[derive(Debug, Clone)]
pub struct Include {
    /// Its name in this file: `wheel`, `wheel #2`, …
    pub name: String,
    pub frame: Frame,
    /// The file, read once however often it is included.
    pub model: std::sync::Arc<Model>,
    /// Its `[[part]]` table in this file.
    pub span: Range<usize>,
    /// Its `array` and `mirror`, if any (`copies`): each copy a
    /// sub-assembly `name[i]`.
    pub copies: Option<Box<Copies>>,
    /// How its origin moves with this file's tolerances (`Slot::At`),
    /// in this file's units and frame.
    pub tol: Option<std::sync::Arc<[crate::part::Dep]>>,
    /// Its `group` (its parts' groups go under it) and `maturity` (the
    /// default of its parts that have none), if any (`budget`).
    pub tag: Option<Box<budget::Tag>>,
}

/// `[analysis]` in the file's units: reference point (file length), ω
/// (rad/s), α (rad/s²) — the file's units name no time, so ω and α are SI.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Analysis {
    pub about: Option<Vector3<f64>>,
    pub omega: Option<Vector3<f64>>,
    pub alpha: Option<Vector3<f64>>,
    /// The reference point's velocity (file length per second), in the
    /// report axes (`analysis::motion`).
    pub velocity: Option<Vector3<f64>>,
    /// Where the file gave `alpha`, to point at it if ω is missing.
    pub alpha_span: Option<Range<usize>>,
    /// Where the file gave `velocity`, likewise.
    pub velocity_span: Option<Range<usize>>,
    /// Two axles along a report axis (`analysis::axles`).
    pub axles: Option<Axles>,
    /// The acceleration of gravity, m/s² (SI: the file's units name no
    /// time); `analysis::axles::G` without it.
    pub g: Option<f64>,
    /// Where the file gave `about` and `omega`, to point at them when a
    /// result overflows.
    pub about_span: Option<Range<usize>>,
    pub omega_span: Option<Range<usize>>,
    /// The report axes: R, whose columns are they in the file's frame
    /// (`axes`); none for the file's own. ω and α are read in them.
    pub axes: Option<crate::rotation::Orientation>,
    /// `warnings`: `Some(false)` silences the plausibility warnings
    /// (`analysis::plausible`).
    pub warnings: Option<bool>,
}

/// `[analysis] axles`: the index of the report axis they lie along and
/// their positions on it, m (SI; distinct).
#[derive(Debug, Clone, PartialEq)]
pub struct Axles {
    pub axis: usize,
    pub front: f64,
    pub rear: f64,
}

impl Model {
    /// A model of no parts, to be filled in.
    fn empty(units: FileUnits) -> Model {
        Model {
            name: None,
            units,
            units_given: false,
            items: std::sync::Arc::new(Vec::new()),
            count: 0,
            analysis: Analysis::default(),
            expect: Vec::new(),
            has_real_sizes: false,
            materials: Default::default(),
            budget: None,
            envelope: None,
            included: Vec::new(),
            texts_read: 0,
            sources: Vec::new(),
            group_depth: 0,
            mesh_warnings: Vec::new(),
            cases: Vec::new(),
        }
    }

    /// Parse and validate a part file; its includes may come from its own
    /// directory tree and the working directory's.
    pub fn parse(source: &Source) -> Result<Model, Diagnostic> {
        Model::parse_with(source, &Includes::default())
    }

    /// `parse`, with includes as `includes` allows them.
    pub fn parse_with(source: &Source, includes: &Includes) -> Result<Model, Diagnostic> {
        Model::parse_reading(source, includes, &mut Vec::new())
    }

    /// `parse_with`, adding to `read` every file it opened to include (by
    /// canonical path), whether the file turns out valid or not: `check -o`
    /// may write onto none of them, even after an invalid file.
    pub fn parse_reading(
        source: &Source,
        includes: &Includes,
        read: &mut Vec<std::path::PathBuf>,
    ) -> Result<Model, Diagnostic> {
        Model::parse_passing(source, includes, read, &[])
    }

    /// `parse_reading`, with the parameters `values` in place of the
    /// file's definitions, its cases' and `--set`'s (`analysis::cases`).
    pub fn parse_passing(
        source: &Source,
        includes: &Includes,
        read: &mut Vec<std::path::PathBuf>,
        values: &[(String, crate::expr::Value)],
    ) -> Result<Model, Diagnostic> {
        let mut files = include::Files::default();
        files.packages = includes.packages.clone();
        if source.piped {
            // A piped file's tree is the one it is based in.
            files.base_dir = includes.base_dir.clone();
            files
                .roots
                .extend((includes.base_dir.iter()).filter_map(|d| std::fs::canonicalize(d).ok()));
        } else if let Ok(p) = std::fs::canonicalize(source.path()) {
            files
                .roots
                .extend(p.parent().map(std::path::Path::to_path_buf));
            files.stack.push((p, source.name.clone()));
        }
        files.roots.extend(std::fs::canonicalize(".").ok());
        files
            .roots
            .extend((includes.roots.iter()).filter_map(|r| std::fs::canonicalize(r).ok()));
        let mut passed = params::flags(&includes.set)?;
        for (name, value) in values {
            passed.retain(|p| p.name != *name);
            passed.push(params::Pass::value(name, *value));
        }
        let model = Model::parse_in(source, &mut files, &passed);
        let reads = files.reads;
        let mesh_warnings = std::mem::take(&mut files.mesh_warnings);
        let included = files.included();
        read.extend(included.iter().cloned());
        let mut model = model?;
        envelope::check_sequences(source, &model)?;
        model.included = included;
        model.texts_read = reads;
        model.mesh_warnings = mesh_warnings;
        Ok(model)
    }

    /// The file as TOML, by the one reader (`fast`), which words its
    /// error too.
    fn raw(source: &Source) -> Result<RawFile, Diagnostic> {
        fast::read_file(&source.text).ok_or_else(|| fast::explain(source))
    }

    /// `parse`, inside the chain of files that include each other (for
    /// cycles).
    fn parse_in(
        source: &Source,
        files: &mut include::Files,
        passed: &[params::Pass],
    ) -> Result<Model, Diagnostic> {
        // Each part made as it is read; else (a part that includes a
        // file, or has copies: `Streamed::take`), or if the file's units
        // came after its parts (a `[units]` table at the end), the whole
        // file read first. So is a file with tolerances: their sources
        // are the file's.
        files.reads += 1;
        let whole = tolerance::may_have(&source.text);
        let (mut streamed, fast) = if whole {
            (Streamed::off(), fast::read_file(&source.text))
        } else {
            Streamed::read(source)
        };
        let raw = match fast {
            Some(raw) if whole => Some(raw),
            // A file with cases is read whole: each case is made from it.
            Some(raw) if streamed.saw_all_of(&raw) && raw.case.is_none() => Some(raw),
            // Read whole (a file the stream cannot take, or refused: then
            // read whole to be sure before its error is worded).
            Some(_) | None if !whole => {
                streamed = Streamed::off();
                fast::read_file(&source.text)
            }
            Some(_) | None => None,
        };
        let mut raw = match raw {
            Some(raw) => raw,
            None => return Err(fast::explain(source)),
        };
        let (ctx, mut rec) = Model::context(source, &raw, passed, None)?;
        if !streamed.off {
            return streamed.model(&ctx, rec, raw);
        }
        if raw.case.is_some() && files.stack.len() <= 1 {
            let mut model = Model::from_raw(source, &raw, files, passed, None)?;
            model.cases = Model::read_cases(source, &mut raw, files, passed)?;
            return Ok(model);
        }
        Model::check_parts(&ctx, &raw, files)?;
        // Each raw part dropped once read: its vectors and rare keys are
        // freed as the parts are made, not after all of them.
        let raw_parts = std::mem::take(raw.part.as_mut().expect("parts, checked above").get_mut());
        let (items, count, has_real_sizes) =
            Model::items(&ctx, &mut rec, raw_parts.into_iter(), files)?;
        Model::rest(&ctx, rec, &raw, items, count, has_real_sizes)
    }

    /// The model of a file already parsed into `raw`, with the parameter
    /// values `passed`: the conversion step alone, everything that depends
    /// on a parameter's value (an included file parsed once is converted
    /// again for each distinct set of `params`, `include::Parsed`).
    fn from_raw(
        source: &Source,
        raw: &RawFile,
        files: &mut include::Files,
        passed: &[params::Pass],
        base: Option<&params::Base>,
    ) -> Result<Model, Diagnostic> {
        let (ctx, mut rec) = Model::context(source, raw, passed, base)?;
        Model::check_parts(&ctx, raw, files)?;
        let parts = raw.part.as_ref().expect("parts, checked above").get_ref();
        let (items, count, has_real_sizes) = Model::items(&ctx, &mut rec, parts.iter(), files)?;
        Model::rest(&ctx, rec, raw, items, count, has_real_sizes)
    }

    /// What the parts of a file are read in: its units, its parameters
    /// (with the values `passed`), its materials and its growth; and the
    /// recorder of its tolerances, with those of its parameters and
    /// materials (the file's first sources).
    fn context<'s>(
        source: &'s Source,
        raw: &RawFile,
        passed: &[params::Pass],
        base: Option<&params::Base>,
    ) -> Result<(Ctx<'s>, tolerance::Recorder), Diagnostic> {
        let ctx = Ctx {
            source,
            units: FileUnits::default(),
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        let units = match &raw.units {
            Some(u) => ctx.file_units(u)?,
            None => FileUnits::default(),
        };
        let mut ctx = Ctx {
            source,
            units,
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        let mut rec = tolerance::Recorder::default();
        match base {
            Some(base) => ctx.read_params_over(&mut rec, raw.params.as_ref(), passed, base)?,
            None => ctx.read_params(&mut rec, raw.params.as_ref(), passed)?,
        }
        if let Some(table) = &raw.materials {
            ctx.read_materials(&mut rec, table)?;
        }
        ctx.read_growth(raw.growth.as_ref())?;
        Ok((ctx, rec))
    }

    /// The file has parts, within the limit, its includes counted (by the
    /// file read first) before any is expanded.
    fn check_parts(ctx: &Ctx, raw: &RawFile, files: &mut include::Files) -> Result<(), Diagnostic> {
        let raw_parts = match &raw.part {
            Some(p) if !p.get_ref().is_empty() => p.get_ref(),
            Some(p) => {
                return Err(ctx.err(
                    p.span(),
                    "`part` is empty: a part file needs at least one part",
                ));
            }
            None => {
                return Err(ctx
                    .err(0..0, "the file has no parts")
                    .help("add at least one `[[part]]` table with a `shape`"));
            }
        };
        if raw_parts.len() > MAX_PARTS {
            return Err(ctx.err(
                0..0,
                format!(
                    "the file has {} parts; the limit is {MAX_PARTS}",
                    raw_parts.len()
                ),
            ));
        }
        // Counted with the includes before any is expanded, once, by the
        // file read first.
        if files.stack.len() <= 1 {
            ctx.check_part_count(raw_parts, files)?;
        }
        Ok(())
    }

    /// The file's parts and sub-assemblies, made from its raw parts (owned,
    /// each dropped once made, or borrowed from a file kept parsed); with
    /// the body's part count and whether any gives its real size.
    fn items<P: std::borrow::Borrow<Spanned<raw::RawPart>>>(
        ctx: &Ctx,
        rec: &mut tolerance::Recorder,
        raw_parts: impl ExactSizeIterator<Item = P>,
        files: &mut include::Files,
    ) -> Result<(Vec<Item>, usize, bool), Diagnostic> {
        let mut items = Vec::with_capacity(raw_parts.len());
        let (mut count, mut has_real_sizes) = (0, false);
        // The names given to sub-assemblies so far (`wheel`, `wheel #2`).
        let mut assembly_names = include::AssemblyNames::default();
        // The names written, of copies and numbered (`copies::Names`).
        let mut names = copies::Names::default();
        for (i, p) in raw_parts.enumerate() {
            let p = p.borrow();
            // Its copies first: a count past the limit is refused before
            // anything of the part is read or included.
            let copies = ctx.copies(rec, p.get_ref())?;
            if p.get_ref().include.is_some() {
                let mut item = ctx.include(rec, i, p, files, count, &mut assembly_names)?;
                if let Item::Include(inc) = &mut item {
                    count = ctx.count_copies(p, count, inc.model.count, copies.as_deref())?;
                    has_real_sizes |= inc.model.has_real_sizes;
                    inc.copies = copies;
                }
                ctx.copies_in_range(&item, p)?;
                names.note(i, p, &item);
                items.push(item);
                continue;
            }
            // NOTE: a part alone counts too, checked before it is made: after
            // an array or an include that reached the limit, each part
            // written alone was added unchecked (2,000,002 parts were read).
            if copies.is_none() && count >= MAX_PARTS {
                let at = p.get_ref().shape.as_ref().map_or(p.span(), Spanned::span);
                return Err(ctx
                    .err(
                        at,
                        format!("this part takes the body past {MAX_PARTS} parts, the limit"),
                    )
                    .help("the parts before it, with their copies and includes, already reach the limit"));
            }
            let (part, real) = if mesh::is_mesh(p.get_ref()) {
                (ctx.mesh_part(rec, i, p, files)?, None)
            } else {
                ctx.part(rec, i, p)?
            };
            has_real_sizes |= real.is_some();
            count = ctx.count_copies(p, count, 1, copies.as_deref())?;
            let tag = ctx.tag(p.get_ref())?;
            items.push(Item::Part {
                part,
                real,
                copies,
                tag,
            });
            ctx.copies_in_range(items.last().expect("just pushed"), p)?;
            names.note(i, p, items.last().expect("just pushed"));
        }
        names.check(ctx)?;
        Ok((items, count, has_real_sizes))
    }

    /// The model of `raw`'s keys other than its parts, with `items` and
    /// the file's tolerances, `rec`.
    fn rest(
        ctx: &Ctx,
        mut rec: tolerance::Recorder,
        raw: &RawFile,
        items: Vec<Item>,
        count: usize,
        has_real_sizes: bool,
    ) -> Result<Model, Diagnostic> {
        let analysis = match &raw.analysis {
            Some(a) => ctx.analysis(&mut rec, a)?,
            None => Analysis::default(),
        };
        let expect = match &raw.expect {
            Some(e) => ctx.expectations(&rec, e, &analysis)?,
            None => Vec::new(),
        };
        let budget = raw
            .budget
            .as_ref()
            .map(|b| ctx.budget(&rec, b))
            .transpose()?;
        let envelope = (raw.envelope.as_ref())
            .map(|e| ctx.envelope(&rec, e))
            .transpose()?;
        Ok(Model {
            group_depth: budget::group_depth(&items),
            name: raw.name.as_ref().map(|n| n.get_ref().clone()),
            units: ctx.units,
            units_given: raw.units.is_some(),
            items: std::sync::Arc::new(items),
            count,
            analysis,
            expect,
            materials: ctx
                .materials
                .iter()
                .map(|(k, v)| (k.clone(), v.0))
                .collect(),
            has_real_sizes,
            budget,
            envelope,
            // Filled in by `parse` for the file it reads.
            included: Vec::new(),
            texts_read: 0,
            sources: rec.sources,
            mesh_warnings: Vec::new(),
            cases: Vec::new(),
        })
    }
}

/// Whether `text` reads as a part file: it has a `[[part]]` table (or a
/// `part` array) at the start of a line, as every part file has and a file
/// of secrets or settings that happens to be TOML has not. The one rule
/// for "is this a part file" before it is parsed (or where its errors must
/// not be quoted): includes, and `-o`, which never replaces a part file.
pub fn looks_like_a_part_file(text: &str) -> bool {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines().any(|l| {
        let l = l.trim_start();
        is_part_table(l)
            || (!l.starts_with('[') && part_key(l).is_some_and(|r| r.trim_start().starts_with('=')))
    })
}

/// Whether a line (its leading blanks trimmed) opens a `[[part]]` table.
fn is_part_table(l: &str) -> bool {
    l.strip_prefix("[[").and_then(part_key).is_some()
}

/// After the key `part`, `"part"` or `'part'`: what follows it, if that is
/// `]` or `=`.
fn part_key(k: &str) -> Option<&str> {
    let k = k.trim_start();
    let k = k.strip_prefix(['"', '\'']).unwrap_or(k);
    let rest = k.strip_prefix("part")?;
    let rest = rest.strip_prefix(['"', '\'']).unwrap_or(rest).trim_start();
    rest.starts_with([']', '=']).then_some(rest)
}

/// How many `[[part]]` tables `text` opens, by its lines (see
/// `include::Ctx::check_part_count`).
fn part_tables(text: &str) -> u64 {
    text.lines()
        .filter(|l| is_part_table(l.trim_start()))
        .count() as u64
}

/// Parse a command-line vector into the file's units (rad/s for ω, rad/s²
/// for α): three comma-separated components. Plain numbers are in the
/// file's units. A unit on
/// the last component only applies to all three (`0,0,10 mm`); otherwise
/// each component carries its own unit (`1 mm,2 in,0 m`) or none does.
pub fn parse_flag_vector(text: &str, units: FileUnits, dim: Dim) -> Result<Vector3<f64>, String> {
    // `[0, 0, 10]`, as the file writes it, is the same vector.
    let text = text.trim();
    let text = text
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .unwrap_or(text);
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!(
            "expected three comma-separated components, got {}",
            parts.len()
        ));
    }
    let plain: Vec<Option<f64>> = parts.iter().map(|p| p.parse::<f64>().ok()).collect();
    let shared_unit = match (plain[0], plain[1], plain[2]) {
        (Some(_), Some(_), None) => {
            let (_, unit) =
                units::split_number(parts[2]).map_err(|e| format!("component 3: {e}"))?;
            Some(unit)
        }
        (Some(_), Some(_), Some(_)) => None,
        _ if plain.iter().all(Option::is_none) => None,
        _ => {
            return Err(
                "give a unit on every component, on none, or on the last one only (for all three)"
                    .to_string(),
            );
        }
    };
    let mut out = Vector3::zeros();
    for (i, p) in parts.iter().enumerate() {
        let v = match (plain[i], shared_unit) {
            (Some(x), _) if !x.is_finite() => {
                return Err(format!("component {} must be finite", i + 1));
            }
            (Some(x), None) => x,
            // The unit given once, at the end, for all three.
            (Some(x), Some(u)) => units::parse_quantity_in(&format!("{x:?} {u}"), dim, units)
                .map_err(|e| e.to_string())?,
            (None, _) => units::parse_quantity_in(p, dim, units)
                .map_err(|e| format!("component {}: {e}", i + 1))?,
        };
        if !v.is_finite() {
            return Err(format!(
                "component {} overflows when converted to the file's units",
                i + 1
            ));
        }
        // As in a file (`Ctx::representable`): a number that is not zero
        // as written, but zero or subnormal in f64 or in the file's units.
        if v.abs() < f64::MIN_POSITIVE && (v != 0.0 || ctx::nonzero_literal(p)) {
            return Err(format!(
                "component {} is too small: below {:e} in the file's units, f64 loses precision",
                i + 1,
                f64::MIN_POSITIVE
            ));
        }
        out[i] = v;
    }
    Ok(out)
}

#[cfg(test)]
mod part_file_tests {
    use super::looks_like_a_part_file as part_file;

    #[test]
    fn a_part_file_is_told_by_its_part_tables_however_written() {
        for text in [
            "[[part]]\nshape = \"point\"\n",
            "# a part\nname = \"x\"\n\n  [[ part ]]\n",
            "\u{feff}[[part]]\n",
            "[[\"part\"]]\n",
            "[[ 'part' ]]\n",
            "part = [{ shape = \"point\" }]\n",
            "\"part\" = []\n",
        ] {
            assert!(part_file(text), "{text:?}");
        }
    }

    #[test]
    fn part_tables_are_counted_by_their_header_lines() {
        let text = "[[part]]\nx = 1\n  [[ 'part' ]]\n# [[part]]\n[[parts]]\n[[\"part\"]]\n";
        assert_eq!(super::part_tables(text), 3);
        assert_eq!(super::part_tables("token = 1\n"), 0);
    }

    #[test]
    fn settings_secrets_and_lookalikes_are_not_part_files() {
        for text in [
            "",
            "token = \"abc\"\n",
            "API_TOKEN=abc\n",
            "# [[part]]\n",
            "[[parts]]\n",
            "[[part.x]]\n",
            "[part]\n",
            "partner = 1\n",
            "x = \"[[part]]\"\n",
        ] {
            assert!(!part_file(text), "{text:?}");
        }
    }
}

#[cfg(test)]
mod streaming_tests {
    use super::Model;
    use crate::diag::Source;

    fn points(n: usize, bad: Option<usize>) -> String {
        (0..n)
            .map(|k| {
                let mass = if Some(k) == bad { "-1" } else { "1.5" };
                format!("[[part]]\nshape = \"point\"\nmass = {mass}\ncenter = [{k}, 0.25, 0]\n")
            })
            .collect()
    }

    fn parse(text: &str) -> Result<Model, String> {
        Model::parse(&Source::new("s.toml", text)).map_err(|d| d.to_string())
    }

    /// Enough parts for several chunks of the fast path.
    const MANY: usize = 12_000;

    /// Parts made as they are read are the parts of the file read whole:
    /// the same file sent down the serde path (a `[materials]` table is
    /// the fast path's to decline) gives the same parts.
    #[test]
    fn parts_made_as_read_are_those_of_the_file_read_whole() {
        let text = format!("units = {{ length = \"mm\" }}\n{}", points(MANY, None));
        let fast = parse(&text).unwrap();
        let whole = parse(&format!("{text}[materials]\nfoam = {{ density = 30 }}\n")).unwrap();
        assert_eq!(fast.count, MANY);
        assert_eq!(
            format!("{:?}", fast.flattened()),
            format!("{:?}", whole.flattened())
        );
    }

    /// Units given after the parts (a `[units]` table at the end, chunks
    /// after the first part is read) apply to them: the file is read whole
    /// first. (A part's numbers are kept in the file's units: "1.5 kg" is
    /// 1500 in grams; made in kilograms, 1.5, it would read as 1.5 g.)
    #[test]
    fn units_after_the_parts_apply_to_them() {
        let part = "[[part]]\nshape = \"point\"\nmass = \"1.5 kg\"\ncenter = [0, 0, 0]\n";
        let text = format!("{}[units]\nmass = \"g\"\n", part.repeat(MANY));
        // A file the fast path reads (else this tests nothing of it).
        assert!(super::fast::parse(&text).is_some());
        let m = parse(&text).unwrap();
        let si = m.flattened()[1].si(m.units);
        assert_eq!(si.mass, 1.5);
    }

    /// A material the parts use, defined before them or after them (in a
    /// later chunk: the file is then read whole first), gives the same
    /// parts; an expectation at the end keeps the file's line and column.
    #[test]
    fn materials_and_expectations_anywhere_are_read_with_the_files_spans() {
        let part = "[[part]]\nshape = \"box\"\nmaterial = \"foam\"\nsize = [1, 2, 4]\ncenter = [0, 0, 0]\n";
        let parts = part.repeat(MANY);
        let foam = "[materials]\nfoam = { density = \"30 kg/m^3\" }\n";
        let before = parse(&format!("{foam}{parts}")).unwrap();
        let after = parse(&format!("{parts}{foam}")).unwrap();
        for m in [&before, &after] {
            assert_eq!(m.flattened()[MANY - 1].si(m.units).mass, 240.0);
        }
        let expect = "[expect]\nmass = { value = 1, tol = \"1 %\" }\n";
        let m = parse(&format!("{parts}{foam}{expect}")).unwrap();
        let (line, col) = Source::new("s.toml", format!("{parts}{foam}{expect}"))
            .line_col(m.expect[0].span.start);
        assert_eq!((line, col), (5 * MANY + 4, 8));
    }

    /// A part the file does not name is `part N` (its place in its file),
    /// one named `""` keeps its empty name.
    #[test]
    fn unnamed_parts_are_numbered_and_empty_names_kept() {
        let point = "shape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
        let m = parse(&format!("[[part]]\nname = \"\"\n{point}[[part]]\n{point}")).unwrap();
        let names: Vec<String> = m.flattened().into_iter().map(|p| p.name).collect();
        assert_eq!(names, ["", "part 2"]);
    }

    /// Errors in the order of a file read whole: a syntax error anywhere
    /// first, then the first part that is not valid, wherever it is.
    #[test]
    fn a_syntax_error_after_an_invalid_part_is_said_first() {
        let bad = MANY - 100;
        let text = points(MANY, Some(bad));
        let e = parse(&text).unwrap_err();
        let line = 4 * bad + 3;
        assert!(e.starts_with(&format!("s.toml:{line}:8: error:")), "{e}");
        assert!(e.contains("`mass`"), "{e}");
        let e = parse(&format!("{text}x = = 1\n")).unwrap_err();
        assert!(e.starts_with(&format!("s.toml:{}:", 4 * MANY + 1)), "{e}");
    }
}
