//! The parts of a file, made as they are read
//! (`fast::parse_streaming`).

use super::raw::{self, RawFile};
use super::tolerance::Recorder;
use super::{Ctx, Item, MAX_PARTS, Model};
use crate::diag::{Diagnostic, Source};
use crate::units::FileUnits;

/// Materials by name: density in SI and in the file's units.
type Materials = std::collections::BTreeMap<String, (f64, f64)>;

/// The parts of a file on the fast path, made as they are read
/// (`fast::parse_streaming`): such a file has no includes and no
/// `[materials]`, and its `units` come before its parts (the keys at the
/// top of a TOML file come before its tables; a `[units]` table after
/// them sends the file down the other path). Errors come in the order the
/// whole file read first gives them: the units, the part limit, then the
/// first part that is not valid.
#[derive(Default)]
pub(super) struct Streamed {
    /// Not used: the file is read whole first.
    pub(super) off: bool,
    /// The file's units as the first part found them: given or not, and
    /// read; and how many `[materials]` sections had been read by then.
    units_seen: Option<bool>,
    materials_seen: usize,
    /// The units and materials the parts are made with.
    ctx: Option<Result<(FileUnits, Materials), ()>>,
    pub(super) items: Vec<Item>,
    /// Parts read, made or not.
    count: usize,
    has_real_sizes: bool,
    /// The first part that is not valid.
    error: Option<Diagnostic>,
}

impl Streamed {
    /// For a file of `parts` parts (a capacity, not a limit).
    pub(super) fn with_room(parts: usize) -> Streamed {
        Streamed {
            items: Vec::with_capacity(parts.min(MAX_PARTS)),
            ..Streamed::default()
        }
    }

    /// Not used: the file is read whole first.
    pub(super) fn off() -> Streamed {
        Streamed {
            off: true,
            ..Streamed::default()
        }
    }

    pub(super) fn take(
        &mut self,
        source: &Source,
        units: Option<&toml::Spanned<raw::RawUnits>>,
        materials: Option<&raw::Materials>,
        p: toml::Spanned<raw::RawPart>,
    ) {
        let index = self.count;
        self.count += 1;
        let q = p.get_ref();
        if q.include.is_some() || q.array.is_some() || q.mirror.is_some() || super::mesh::is_mesh(q)
        {
            // Not here: a file with includes or copies is read whole (its
            // includes counted before any is read,
            // `include::Ctx::check_part_count`), and a mesh is read with
            // the files it names (`model::mesh`).
            self.off = true;
        }
        if self.off || self.error.is_some() || self.count > MAX_PARTS {
            return;
        }
        let made = self.ctx.get_or_insert_with(|| {
            self.units_seen = Some(units.is_some());
            self.materials_seen = materials.map_or(0, |m| m.get_ref().len());
            // An error is said again when the whole file is read.
            let mut ctx = Ctx {
                source,
                units: FileUnits::default(),
                materials: Default::default(),
                params: Default::default(),
                growth: Default::default(),
            };
            if let Some(u) = units {
                ctx.units = ctx.file_units(u).map_err(|_| ())?;
            }
            if let Some(table) = materials {
                // NOTE: a recorder dropped: a file with a tolerance is
                // not streamed (`tolerance::may_have`), none is recorded.
                let mut rec = Recorder::default();
                ctx.read_materials(&mut rec, table).map_err(|_| ())?;
            }
            Ok((ctx.units, ctx.materials))
        });
        let Ok((units, materials)) = made else { return };
        let ctx = Ctx {
            source,
            units: *units,
            materials: std::mem::take(materials),
            params: Default::default(),
            // NOTE: empty, and right to be: a file with `[growth]`,
            // `[budget]` or `[params]` is read whole (`saw_all_of`), so a
            // part's `maturity` here names a maturity the file does not
            // have, and the whole file's reading says so.
            growth: Default::default(),
        };
        // Its own recorder, as the whole file's reading has (no tolerance
        // here: `tolerance::may_have`).
        let mut rec = Recorder::default();
        let made = ctx.part(&mut rec, index, &p).and_then(|(part, real)| {
            let tag = ctx.tag(p.get_ref())?;
            Ok((part, real, tag))
        });
        // Handed back: a `Ctx` owns its materials.
        if let Some(Ok((_, m))) = &mut self.ctx {
            *m = ctx.materials;
        }
        match made {
            Ok((part, real, tag)) => {
                self.has_real_sizes |= real.is_some();
                self.items.push(Item::Part {
                    part,
                    real,
                    tag,
                    // A file with copies is read whole (`take`).
                    copies: None,
                });
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// Whether the parts were made with the file's units and materials:
    /// none came after the first part was read (a `[units]` or
    /// `[materials]` table at the end); and the file has no tables that
    /// its parts are made with beyond those (`[params]`, `[growth]`,
    /// `[budget]`: such a file is read whole).
    pub(super) fn saw_all_of(&self, raw: &RawFile) -> bool {
        if self.off || raw.params.is_some() || raw.growth.is_some() || raw.budget.is_some() {
            return false;
        }
        // `part = [..]`: parts not handed out (none came by the stream).
        if self.units_seen.is_none() && raw.part.is_some() {
            return false;
        }
        let materials = raw.materials.as_ref().map_or(0, |m| m.get_ref().len());
        self.units_seen
            .is_none_or(|seen| seen == raw.units.is_some() && materials == self.materials_seen)
    }

    /// The model, `ctx` with the file's units read (and `rec`, the
    /// tolerances of its parameters and materials).
    pub(super) fn model(self, ctx: &Ctx, rec: Recorder, raw: RawFile) -> Result<Model, Diagnostic> {
        if raw.part.is_none() {
            return Err(ctx
                .err(0..0, "the file has no parts")
                .help("add at least one `[[part]]` table with a `shape`"));
        }
        if self.count > MAX_PARTS {
            return Err(ctx.err(
                0..0,
                format!(
                    "the file has {} parts; the limit is {MAX_PARTS}",
                    self.count
                ),
            ));
        }
        if let Some(e) = self.error {
            return Err(e);
        }
        let mut items = self.items;
        items.shrink_to_fit();
        Model::rest(ctx, rec, &raw, items, self.count, self.has_real_sizes)
    }
}
