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
use crate::model::{Event, Item, Model};
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
        let s = &*self.0;
        let mut row = PartSummary {
            name: String::new(),
            shape: crate::shapes::Shape::ALL[0],
            mass: 0.0,
            mass_fraction: 0.0,
            center_of_mass: [0.0; 3],
            principal_moment_share: [None; 3],
            assembly: Vec::new(),
        };
        s.model.each_part(&mut |l| {
            let p = l.part;
            let m = p.mass_si(&s.factors);
            row.name.clear();
            row.name.push_str(&p.name);
            row.shape = p.shape();
            row.mass = m;
            row.mass_fraction = m / s.mass;
            row.center_of_mass = arr(&p.center_si(&s.factors));
            row.principal_moment_share = s.shares.of(p);
            if row.assembly != p.assembly {
                row.assembly.clone_from(&p.assembly);
            }
            f(&row);
        });
    }

    /// All the rows, in memory (for tests).
    pub fn collect(&self) -> Vec<PartSummary> {
        let mut all = Vec::with_capacity(self.len());
        self.each(&mut |r| all.push(r.clone()));
        all
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
        let s = &*self.0;
        /// A sub-assembly being summed: where its sums go, its items'
        /// masses and centres, its parts and shares.
        struct Open {
            at: usize,
            items: Vec<(f64, [f64; 3])>,
            parts: usize,
            share: [Option<f64>; 3],
        }
        let mut sums: Vec<Sums> = Vec::new();
        let mut open: Vec<Open> = Vec::new();
        s.model.each_event(&mut |e| match e {
            Event::Enter(_) => {
                open.push(Open {
                    at: sums.len(),
                    items: Vec::new(),
                    parts: 0,
                    share: [Some(0.0); 3],
                });
                sums.push(Sums {
                    parts: 0,
                    mass: 0.0,
                    center_of_mass: [0.0; 3],
                    share: [None; 3],
                });
            }
            Event::Part(l) => {
                if let Some(top) = open.last_mut() {
                    let p = l.part;
                    top.items
                        .push((p.mass_si(&s.factors), arr(&p.center_si(&s.factors))));
                    top.parts += 1;
                    let share = s.shares.of(p);
                    for (t, x) in top.share.iter_mut().zip(share) {
                        *t = t.zip(x).map(|(a, b)| a + b);
                    }
                }
            }
            Event::Exit => {
                let done = open.pop().expect("an Exit follows its Enter");
                let mass: f64 = done.items.iter().map(|(m, _)| m).sum();
                let center_of_mass =
                    std::array::from_fn(|i| done.items.iter().map(|(m, c)| m / mass * c[i]).sum());
                let sum = Sums {
                    parts: done.parts,
                    mass,
                    center_of_mass,
                    share: done.share,
                };
                sums[done.at] = sum;
                if let Some(parent) = open.last_mut() {
                    // NOTE: a sub-assembly of no parts (a robot's massless
                    // link) adds nothing: its 0/0 centre is no centre.
                    if done.parts > 0 {
                        parent.items.push((mass, center_of_mass));
                    }
                    parent.parts += done.parts;
                    for (t, x) in parent.share.iter_mut().zip(done.share) {
                        *t = t.zip(x).map(|(a, b)| a + b);
                    }
                }
            }
        });
        let mut row = AssemblySummary {
            path: Vec::new(),
            parts: 0,
            mass: 0.0,
            mass_fraction: 0.0,
            center_of_mass: [0.0; 3],
            principal_moment_share: [None; 3],
        };
        let mut next = 0;
        write(&s.model, &sums, &mut next, &mut row, s.mass, f);
    }

    /// All the rows, in memory (for tests).
    pub fn collect(&self) -> Vec<AssemblySummary> {
        let mut all = Vec::new();
        self.each(&mut |r| all.push(r.clone()));
        all
    }
}

/// The rows of `model`'s sub-assemblies, from `sums[next..]`.
fn write(
    model: &Model,
    sums: &[Sums],
    next: &mut usize,
    row: &mut AssemblySummary,
    total: f64,
    f: &mut dyn FnMut(&AssemblySummary),
) {
    for item in model.items.iter() {
        let Item::Include(inc) = item else { continue };
        // A sub-assembly with copies is a row per copy, `wheel[i]`, as the
        // walk entered them.
        let mut one = |name: String, next: &mut usize, row: &mut AssemblySummary| {
            let s = sums[*next];
            *next += 1;
            row.path.push(name);
            row.parts = s.parts;
            row.mass = s.mass;
            row.mass_fraction = s.mass / total;
            row.center_of_mass = s.center_of_mass;
            row.principal_moment_share = s.share;
            f(row);
            write(&inc.model, sums, next, row, total, f);
            row.path.pop();
        };
        match &inc.copies {
            None => one(inc.name.clone(), next, row),
            Some(c) => {
                for i in c.indices() {
                    let mut name = String::new();
                    crate::model::push_copy_name(&mut name, &inc.name, i);
                    one(name, next, row);
                }
            }
        }
    }
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
        serialize_each(serializer, Some(self.len()), |f| self.each(f))
    }
}

impl serde::Serialize for Assemblies {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serialize_each(serializer, None, |f| self.each(f))
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
