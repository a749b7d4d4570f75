//! The parts of a file, made as they are read
//! (`fast::parse_streaming`).

use super::fast::{self, pieces::Pieces};
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
    /// Parts read, made or not; the index in the file of the first (when
    /// read in pieces, `read`).
    count: usize,
    first: usize,
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

    /// The file read, its parts made as they are read: on every core for
    /// a large file (`fast::pieces`), else on one (`fast::parse_streaming`).
    /// `None` where the reader refuses the file.
    pub(super) fn read(source: &Source) -> (Streamed, Option<RawFile>) {
        let text = &source.text;
        let pieces = fast::pieces::pieces_for(text);
        if pieces > 1 {
            let new = |first, parts| Streamed {
                first,
                ..Streamed::with_room(parts)
            };
            let take = |s: &mut Streamed, units: Option<&_>, materials: Option<&_>, p| {
                s.take(source, units, materials, p);
            };
            if let Pieces::Read(raw, read) = fast::pieces::read(text, pieces, &new, &take) {
                return (Streamed::merge(read), Some(*raw));
            }
        }
        // At the size the file's `[[part]]` lines say: a list doubled up
        // to its size holds up to twice the parts.
        let mut streamed = Streamed::with_room(super::part_tables(text) as usize);
        let raw = fast::parse_streaming(text, fast::CHUNK, &mut |units, materials, p| {
            streamed.take(source, units, materials, p);
        });
        (streamed, raw)
    }

    /// The pieces' parts as one reading made them: in order, up to the
    /// first part that is not valid, whose error is the first in the file.
    /// (Each piece made its parts with the same units and materials, the
    /// preamble's: `fast::pieces`.)
    fn merge(pieces: Vec<Streamed>) -> Streamed {
        let mut pieces = pieces.into_iter();
        let mut all = pieces.next().unwrap_or_default();
        let more: usize = pieces.as_slice().iter().map(|p| p.items.len()).sum();
        all.items.reserve_exact(more);
        for mut p in pieces {
            all.off |= p.off;
            all.count += p.count;
            if all.error.is_none() {
                all.has_real_sizes |= p.has_real_sizes;
                all.items.append(&mut p.items);
                all.error = p.error;
            }
        }
        all
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
        let index = self.first + self.count;
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

#[cfg(test)]
mod tests {
    use super::super::{Model, fast::pieces::with_pieces};
    use crate::diag::Source;

    /// `n` parts of every kind the stream takes; `bad` parts (by index)
    /// with a negative mass, `unknown` ones with an unknown key.
    fn file(n: usize, bad: &[usize], unknown: &[usize]) -> String {
        let mut text = String::from(
            "name = \"pieces\"\nunits = { length = \"mm\", mass = \"g\" }\n[materials]\nfoam = { density = \"30 kg/m^3\" }\n",
        );
        for k in 0..n {
            let mass = if bad.contains(&k) { "-1" } else { "1.5" };
            let name = if k % 4 == 0 {
                String::new()
            } else {
                format!("name = \"p{k}\"\n")
            };
            let extra = if unknown.contains(&k) {
                "colour = 1\n"
            } else {
                ""
            };
            text += &match k % 3 {
                0 => format!(
                    "[[part]]\n{name}shape = \"point\"\nmass = {mass}\ncenter = [{k}, 0.25, 0]\n{extra}"
                ),
                1 => format!(
                    "[[part]]\n{name}shape = \"box\"\nmaterial = \"foam\"\nsize = [1, 2, {k}]\ncenter = [0, {k}, 0]\n{extra}"
                ),
                _ => format!(
                    "[[part]]\n{name}shape = \"rod\"\nmass = \"{mass} kg\"\nlength = {k}\ncenter = [0, 0, {k}]\n[part.rotation]\naxis = [0, 0, 1]\ndegrees = {k}\n{extra}"
                ),
            };
        }
        text
    }

    /// The model, or the error in full, read in `pieces` pieces.
    fn read(text: &str, pieces: usize) -> String {
        with_pieces(pieces, || {
            match Model::parse(&Source::new("p.toml", text)) {
                Ok(m) => format!("{:?} {} {:?}", m.flattened(), m.count, m.has_real_sizes),
                Err(d) => format!("error: {d}"),
            }
        })
    }

    fn same_on_one_core_and_in_pieces(text: &str) -> String {
        let one = read(text, 1);
        for n in 2..=5 {
            assert_eq!(read(text, n), one, "{n} pieces");
        }
        one
    }

    #[test]
    fn a_file_read_in_pieces_gives_the_model_of_one_core() {
        let one = same_on_one_core_and_in_pieces(&file(60, &[], &[]));
        assert!(!one.starts_with("error"), "{one}");
        assert!(
            one.contains("part 57"),
            "an unnamed part is numbered in the file"
        );
    }

    #[test]
    fn the_first_invalid_part_in_the_file_is_the_error_however_it_is_read() {
        for bad in [&[3][..], &[50], &[7, 41], &[58, 2]] {
            let one = same_on_one_core_and_in_pieces(&file(60, bad, &[]));
            assert!(one.starts_with("error"), "{one}");
        }
    }

    #[test]
    fn a_refused_key_is_the_error_however_the_file_is_read() {
        for unknown in [&[5][..], &[44], &[9, 30]] {
            let one = same_on_one_core_and_in_pieces(&file(60, &[30], unknown));
            assert!(one.contains("colour"), "{one}");
        }
    }
}
