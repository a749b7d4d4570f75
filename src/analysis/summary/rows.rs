//! The rows of a report, a part's or a sub-assembly's, made as they are
//! written and never all held: a body of 2²⁰ parts in a tree of includes
//! has 2²⁰ part rows and as many sub-assembly rows, more memory than the
//! rest of the report together when collected (and than the tree itself,
//! which holds each file once).
//!
//! `Parts` and `Assemblies` serialize as the JSON arrays `parts` and
//! `assemblies` (docs/json.md), walking the model as serde asks for each
//! element; the table walks them the same way (`each`).

use super::{AssemblySummary, PartSummary, formed::arr};
use crate::analysis::ideal::Shares;
use crate::model::{Item, Model, RowEvent};
use crate::numeric::{DD, Real};
use crate::part::SiFactors;
use serde::ser::SerializeSeq;
use std::sync::Arc;

/// What a row is made from: the model (its parts shared, not copied), the
/// unit factors, the shares of the principal moments and the total mass.
pub(super) struct RowData {
    pub(super) model: Model,
    pub(super) factors: SiFactors,
    pub(super) shares: Shares,
    /// kg.
    pub(super) mass: f64,
}

/// The body's parts, in file order, sub-assemblies expanded.
#[derive(Clone)]
pub struct Parts(pub(super) Arc<RowData>);

/// The sub-assemblies, parents before children.
#[derive(Clone)]
pub struct Assemblies(pub(super) Arc<RowData>);

impl Parts {
    /// How many.
    pub fn len(&self) -> usize {
        self.0.model.count
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Each part's row, in file order.
    pub fn each(&self, f: &mut dyn FnMut(&PartSummary)) {
        let mut row = PartSummary {
            name: String::new(),
            shape: crate::shapes::Shape::ALL[0],
            mass: 0.0,
            mass_fraction: 0.0,
            center_of_mass: [0.0; 3],
            principal_moment_share: [None; 3],
            assembly: Vec::new(),
        };
        // `a / b / `: the path, as the row's name begins.
        let mut prefix = String::new();
        let mut lengths = Vec::new();
        self.each_row(&mut |r| match r {
            Row::Enter(name) => {
                lengths.push(prefix.len());
                prefix.push_str(name);
                prefix.push_str(" / ");
                row.assembly.push(name.to_string());
            }
            Row::Exit => {
                prefix.truncate(lengths.pop().expect("an Exit follows its Enter"));
                row.assembly.pop();
            }
            Row::Part(p) => {
                row.name.clear();
                row.name.push_str(&prefix);
                p.push_name(&mut row.name);
                row.shape = p.shape;
                row.mass = p.mass;
                row.mass_fraction = p.mass_fraction;
                row.center_of_mass = p.center_of_mass;
                row.principal_moment_share = p.principal_moment_share;
                f(&row);
            }
        });
    }

    /// Each part's row, in file order, with the path of sub-assemblies as
    /// it changes (`Row::Enter`, `Row::Exit`): a writer makes each
    /// sub-assembly's part of the rows once, not once per part in it.
    pub fn each_row(&self, f: &mut dyn FnMut(Row<'_>)) {
        let s = &*self.0;
        s.model.each_row(&mut |e| match e {
            RowEvent::Enter(name) => f(Row::Enter(name)),
            RowEvent::Exit => f(Row::Exit),
            RowEvent::Part {
                part: p,
                own,
                k,
                copy,
            } => {
                // NOTE: as `Part::mass_si` and `Part::center_si`, the
                // mass and the centroid formed once for both.
                let m: f64 = p.mass();
                let mass = (DD::of(m) * s.factors.mass).f64();
                let c = p.centroid();
                let row = PartRow {
                    own,
                    k,
                    copy,
                    shape: p.shape(),
                    mass,
                    mass_fraction: mass / s.mass,
                    center_of_mass: c.map(|x| (x * s.factors.length).f64()),
                    principal_moment_share: s.shares.of(p),
                };
                f(Row::Part(&row));
            }
        });
    }

    /// All the rows, in memory (for tests).
    pub fn collect(&self) -> Vec<PartSummary> {
        let mut all = Vec::with_capacity(self.len());
        self.each(&mut |r| all.push(r.clone()));
        all
    }
}

/// What `Parts::each_row` meets, in file order: a sub-assembly entered
/// (its name in the path: `wheel[2]` for a copy), a part's row, the
/// sub-assembly left.
pub enum Row<'a> {
    Enter(&'a str),
    Part(&'a PartRow<'a>),
    Exit,
}

/// A part's row without its path (`PartSummary`'s other fields).
pub struct PartRow<'a> {
    own: &'a crate::part::Part,
    k: usize,
    copy: Option<usize>,
    pub shape: crate::shapes::Shape,
    pub mass: f64,
    pub mass_fraction: f64,
    pub center_of_mass: [f64; 3],
    pub principal_moment_share: [Option<f64>; 3],
}

impl PartRow<'_> {
    /// Its name after the path: its own, or `part N`, with its copy's
    /// index.
    pub fn push_name(&self, out: &mut String) {
        RowEvent::push_own_name(out, self.own, self.k, self.copy);
    }
}

/// A sub-assembly's sums, in SI.
#[derive(Clone, Copy)]
struct Sums {
    parts: usize,
    mass: f64,
    center_of_mass: [f64; 3],
    share: [Option<f64>; 3],
}

/// Sub-assemblies summed as a walk meets them and their parts
/// (`Assemblies::summed`): each as it is left, from what its items sum to
/// (a part, or a sub-assembly already summed): its mass, and its centre
/// of mass as Σ (mᵢ/m) cᵢ over its items, the weights first as the
/// composer forms the pivot (m cᵢ alone can overflow where the centre
/// fits). Only the sums of each sub-assembly are kept, in the order it
/// was entered (~64 bytes each).
#[derive(Default)]
pub struct Summing {
    sums: Vec<Sums>,
    open: Vec<Open>,
    /// The items' lists of the sub-assemblies left, for the next ones
    /// entered: not an allocation per sub-assembly (a tree of 2²⁰
    /// instances has as many).
    spare: Vec<Vec<(f64, [f64; 3])>>,
}

/// A sub-assembly being summed: where its sums go, its items' masses and
/// centres, its parts and shares.
struct Open {
    at: usize,
    items: Vec<(f64, [f64; 3])>,
    parts: usize,
    share: [Option<f64>; 3],
}

impl Summing {
    /// A sub-assembly entered.
    pub fn enter(&mut self) {
        self.open.push(Open {
            at: self.sums.len(),
            items: self.spare.pop().unwrap_or_default(),
            parts: 0,
            share: [Some(0.0); 3],
        });
        self.sums.push(Sums {
            parts: 0,
            mass: 0.0,
            center_of_mass: [0.0; 3],
            share: [None; 3],
        });
    }

    /// Whether a sub-assembly is entered (a part met now is summed).
    pub fn inside(&self) -> bool {
        !self.open.is_empty()
    }

    /// A part, in SI: its mass, centroid and shares of the principal
    /// moments.
    pub fn part(&mut self, mass: f64, center: [f64; 3], share: [Option<f64>; 3]) {
        if let Some(top) = self.open.last_mut() {
            top.items.push((mass, center));
            top.parts += 1;
            for (t, x) in top.share.iter_mut().zip(share) {
                *t = t.zip(x).map(|(a, b)| a + b);
            }
        }
    }

    /// The sub-assembly last entered, left.
    pub fn exit(&mut self) {
        let mut done = self.open.pop().expect("an Exit follows its Enter");
        let mass: f64 = done.items.iter().map(|(m, _)| m).sum();
        let center_of_mass =
            std::array::from_fn(|i| done.items.iter().map(|(m, c)| m / mass * c[i]).sum());
        let mut items = std::mem::take(&mut done.items);
        items.clear();
        self.spare.push(items);
        self.sums[done.at] = Sums {
            parts: done.parts,
            mass,
            center_of_mass,
            share: done.share,
        };
        if let Some(parent) = self.open.last_mut() {
            // NOTE: a sub-assembly of no parts (a robot's massless link)
            // adds nothing: its 0/0 centre is no centre.
            if done.parts > 0 {
                parent.items.push((mass, center_of_mass));
            }
            parent.parts += done.parts;
            for (t, x) in parent.share.iter_mut().zip(done.share) {
                *t = t.zip(x).map(|(a, b)| a + b);
            }
        }
    }
}

impl Assemblies {
    /// Whether the body has none.
    pub fn is_empty(&self) -> bool {
        !self
            .0
            .model
            .items
            .iter()
            .any(|i| matches!(i, Item::Include(_)))
    }

    /// Each sub-assembly's row, parents before children.
    ///
    /// NOTE: two walks. The first sums each sub-assembly as it is left,
    /// from what its items sum to (a part, or a sub-assembly already
    /// summed): its mass, and its centre of mass as Σ (mᵢ/m) cᵢ over its
    /// items, the weights first as the composer forms the pivot (m cᵢ
    /// alone can overflow where the centre fits). Only the sums of each
    /// sub-assembly are kept, in the order it was entered (~64 bytes each);
    /// the second walk, of the sub-assemblies alone, writes them in that
    /// order with their paths.
    pub fn each(&self, f: &mut dyn FnMut(&AssemblySummary)) {
        let mut row = AssemblySummary {
            path: Vec::new(),
            parts: 0,
            mass: 0.0,
            mass_fraction: 0.0,
            center_of_mass: [0.0; 3],
            principal_moment_share: [None; 3],
        };
        self.each_row(&mut |r| match r {
            AssemblyRow::Enter(name, sums) => {
                row.path.push(name.to_string());
                row.parts = sums.parts;
                row.mass = sums.mass;
                row.mass_fraction = sums.mass_fraction;
                row.center_of_mass = sums.center_of_mass;
                row.principal_moment_share = sums.principal_moment_share;
                f(&row);
            }
            AssemblyRow::Exit => {
                row.path.pop();
            }
        });
    }

    /// Each sub-assembly's row, parents before children, its path as it
    /// changes: `AssemblyRow::Enter` with its name and its row (its
    /// `path` left empty), then its children's, then `AssemblyRow::Exit`.
    pub fn each_row(&self, f: &mut dyn FnMut(AssemblyRow<'_>)) {
        self.summed().each_row(f);
    }

    /// Every sub-assembly summed (one walk of the parts), for its rows to
    /// be walked as often as a writer needs (`Summed::each_row`, a walk of
    /// the sub-assemblies alone): the `--full` table measures its columns,
    /// then writes them.
    pub fn summed(&self) -> Summed<'_> {
        let s = &*self.0;
        let mut summing = Summing::default();
        // NOTE: the parts placed as the rows' walk places them: the same
        // bits, no bound of their rounding formed (`Model::each_row`).
        s.model.each_row(&mut |e| match e {
            RowEvent::Enter(_) => summing.enter(),
            // The body's own parts are in no sub-assembly's sums.
            RowEvent::Part { part: p, .. } if summing.inside() => summing.part(
                p.mass_si(&s.factors),
                arr(&p.center_si(&s.factors)),
                s.shares.of(p),
            ),
            RowEvent::Part { .. } => {}
            RowEvent::Exit => summing.exit(),
        });
        self.summed_from(summing)
    }

    /// `summed`, from the sums a whole walk of the parts' rows made
    /// (`Parts::each_row`'s rows carry the same mass, centre and shares
    /// that `summed` adds up, the same bits): a writer that walks the
    /// parts anyway spares the sub-assemblies' table that walk.
    pub fn summed_from(&self, summing: Summing) -> Summed<'_> {
        debug_assert!(
            summing.open.is_empty(),
            "invariant: a whole walk, every Enter left"
        );
        Summed {
            data: &self.0,
            sums: summing.sums,
        }
    }

    /// All the rows, in memory (for tests).
    pub fn collect(&self) -> Vec<AssemblySummary> {
        let mut all = Vec::new();
        self.each(&mut |r| all.push(r.clone()));
        all
    }
}

/// Every sub-assembly's sums, in the order the walk enters them
/// (`Assemblies::summed`): ~88 bytes a sub-assembly.
pub struct Summed<'a> {
    data: &'a RowData,
    sums: Vec<Sums>,
}

impl Summed<'_> {
    /// As `Assemblies::each_row`.
    pub fn each_row(&self, f: &mut dyn FnMut(AssemblyRow<'_>)) {
        let mut row = AssemblySummary {
            path: Vec::new(),
            parts: 0,
            mass: 0.0,
            mass_fraction: 0.0,
            center_of_mass: [0.0; 3],
            principal_moment_share: [None; 3],
        };
        let mut next = 0;
        let s = self.data;
        write(&s.model, &self.sums, &mut next, &mut row, s.mass, f);
    }
}

/// The rows of `model`'s sub-assemblies, from `sums[next..]`.
fn write(
    model: &Model,
    sums: &[Sums],
    next: &mut usize,
    row: &mut AssemblySummary,
    total: f64,
    f: &mut dyn FnMut(AssemblyRow<'_>),
) {
    let mut name = String::new();
    for item in model.items.iter() {
        let Item::Include(inc) = item else { continue };
        // A sub-assembly with copies is a row per copy, `wheel[i]`, as the
        // walk entered them.
        let mut one = |name: &str, next: &mut usize, row: &mut AssemblySummary| {
            let s = sums[*next];
            *next += 1;
            row.parts = s.parts;
            row.mass = s.mass;
            row.mass_fraction = s.mass / total;
            row.center_of_mass = s.center_of_mass;
            row.principal_moment_share = s.share;
            f(AssemblyRow::Enter(name, row));
            write(&inc.model, sums, next, row, total, f);
            f(AssemblyRow::Exit);
        };
        match &inc.copies {
            None => one(&inc.name, next, row),
            Some(c) => {
                for i in c.indices() {
                    name.clear();
                    crate::model::push_copy_name(&mut name, &inc.name, i);
                    one(&name, next, row);
                }
            }
        }
    }
}

/// What `Assemblies::each_row` meets: a sub-assembly entered, its name
/// in the path and its row (`path` empty), and left.
pub enum AssemblyRow<'a> {
    Enter(&'a str, &'a AssemblySummary),
    Exit,
}

/// Serialized element by element as the walk meets them; the first error
/// is kept and the rest of the walk does nothing.
fn serialize_each<S: serde::Serializer, T: serde::Serialize>(
    serializer: S,
    len: Option<usize>,
    each: impl FnOnce(&mut dyn FnMut(&T)),
) -> Result<S::Ok, S::Error> {
    let mut seq = serializer.serialize_seq(len)?;
    let mut failed = None;
    each(&mut |row| {
        if failed.is_none()
            && let Err(e) = seq.serialize_element(row)
        {
            failed = Some(e);
        }
    });
    match failed {
        Some(e) => Err(e),
        None => seq.end(),
    }
}

impl serde::Serialize for Parts {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        if !self.is_empty() && deferred::armed() {
            // serde_json writes `[` now and `]` at `end`: the writer puts
            // the rows between (`deferred`).
            let seq = serializer.serialize_seq(Some(self.len()))?;
            deferred::mark(deferred::Rows::Parts);
            return serde::ser::SerializeSeq::end(seq);
        }
        serialize_each(serializer, Some(self.len()), |f| self.each(f))
    }
}

impl serde::Serialize for Assemblies {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        if !self.is_empty() && deferred::armed() {
            let seq = serializer.serialize_seq(None)?;
            deferred::mark(deferred::Rows::Assemblies);
            return serde::ser::SerializeSeq::end(seq);
        }
        serialize_each(serializer, None, |f| self.each(f))
    }
}

/// The rows left out of a serialization for its writer to write
/// (`output::report::write_json_to`, which writes each sub-assembly's part
/// of the rows once: issue 33, item 3).
///
/// NOTE: serde hands a `Serialize` only the serializer, never the stream
/// under it. While `armed` (on this thread), `Parts` and `Assemblies` serialize as an
/// array opened and closed with no element, and `mark`s which rows
/// belong there just before the close; the writer, which sees every write
/// serde_json makes, finds the mark (`take`) at the write of the array's
/// `]` and writes the rows first. (The idea of the `output` branch,
/// unmerged.)
pub mod deferred {
    use std::cell::Cell;

    /// Which rows go before the next write.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub enum Rows {
        Parts,
        Assemblies,
    }

    #[derive(Clone, Copy, PartialEq, Eq)]
    enum State {
        Off,
        Armed,
        Marked(Rows),
    }

    thread_local! {
        static STATE: Cell<State> = const { Cell::new(State::Off) };
    }

    /// `f` run with the rows left to the writer (on this thread).
    pub fn while_armed<T>(f: impl FnOnce() -> T) -> T {
        /// As it was again however `f` ends (a panic too).
        struct Restore(State);
        impl Drop for Restore {
            fn drop(&mut self) {
                STATE.with(|s| s.set(self.0));
            }
        }
        let _guard = Restore(STATE.with(|s| s.replace(State::Armed)));
        f()
    }

    pub(super) fn armed() -> bool {
        STATE.with(Cell::get) == State::Armed
    }

    pub(super) fn mark(rows: Rows) {
        STATE.with(|s| s.set(State::Marked(rows)));
    }

    /// The rows to write before the write under way, if any (then armed
    /// again).
    pub fn take() -> Option<Rows> {
        STATE.with(|s| match s.get() {
            State::Marked(r) => {
                s.set(State::Armed);
                Some(r)
            }
            State::Off | State::Armed => None,
        })
    }
}

impl std::fmt::Debug for Parts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Parts({})", self.len())
    }
}

impl std::fmt::Debug for Assemblies {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Assemblies")
    }
}
