//! The sources of uncertainty as a walk of the body meets them, numbered
//! in the order it first meets them: the same numbers in every pass over
//! the same body, so that each method can walk it as often as it needs
//! and hold nothing per part.
//!
//! NOTE: a part's own source (one per copy of the part) is met in that
//! part's leaf only: it is numbered there and forgotten. Only the shared
//! ones (a parameter's or a material's, one per instance of its file; a
//! sub-assembly's origin's, one per instance of the include) are kept by
//! key, to be known again.

use super::View;
use crate::model::Model;
use crate::model::tolerance::Spread;
use crate::model::walk::{Leaf, mix};
use crate::numeric::Real;
use crate::part::Dep;
use std::collections::HashMap;

/// What the methods walk: the model, its bodies' views (basic,
/// predicted), and each part's growth allowance when there is a
/// predicted body (by its position in the walk).
pub(super) struct Body<'a> {
    pub(super) model: &'a Model,
    pub(super) views: &'a [View],
    pub(super) allowances: Option<&'a [f64]>,
    /// The basic body moving, where ω is given (`motion`).
    pub(super) motion: Option<&'a super::motion::Motion>,
}

impl Body<'_> {
    /// Whether output `o` (of `W`) is reported: a body's that exists, or
    /// a motion output the analysis gives.
    pub(super) fn live(&self, o: usize) -> bool {
        use super::{N, motion::FIRST};
        if o < FIRST {
            o < N * self.views.len()
        } else {
            self.motion.is_some_and(|m| m.live(o - FIRST))
        }
    }
}

/// A source as a part meets it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Met {
    /// Its number: the order in which the walk first met it.
    pub(super) id: usize,
    /// Met for the first time here.
    pub(super) new: bool,
    /// Shared by other parts (or other copies): met again elsewhere.
    pub(super) shared: bool,
    /// Monte Carlo: its spread is uniform (else normal).
    pub(super) uniform: bool,
}

/// The sources one part meets, in the order they are numbered: its
/// sub-assemblies' origins' (each with the shift per unit of its
/// variable, root frame and units, and its label when new), then its own
/// numbers' (`Dep`s).
pub(super) struct Meets {
    pub(super) shifts: Vec<(Met, [f64; 3], Option<String>)>,
    pub(super) deps: Vec<(Dep, Met)>,
}

impl Meets {
    /// No tolerance moves the part.
    pub(super) fn is_empty(&self) -> bool {
        self.shifts.is_empty() && self.deps.is_empty()
    }
}

/// The numbering of one walk.
#[derive(Default)]
pub(super) struct Numbering {
    shared: HashMap<u64, usize>,
    count: usize,
}

impl Numbering {
    /// How many sources the walk has met.
    pub(super) fn count(&self) -> usize {
        self.count
    }

    fn fresh(&mut self) -> usize {
        self.count += 1;
        self.count - 1
    }

    fn shared_id(&mut self, key: u64) -> (usize, bool) {
        if let Some(&id) = self.shared.get(&key) {
            return (id, false);
        }
        let id = self.fresh();
        self.shared.insert(key, id);
        (id, true)
    }

    /// The sources `leaf` meets.
    pub(super) fn meet(&mut self, leaf: &Leaf<'_>) -> Meets {
        let mut shifts = Vec::new();
        leaf.placing.shifts(&mut |s| {
            let (id, new) = self.shared_id(s.key);
            let label =
                new.then(|| format!("{}: {} ± {}", s.include, s.source.key, s.source.written));
            let met = Met {
                id,
                new,
                shared: true,
                uniform: s.source.spread == Spread::Uniform,
            };
            shifts.push((met, s.dir, label));
        });
        let no_deps: &[Dep] = &[];
        let deps = leaf.own.tol.as_deref().unwrap_or(no_deps);
        let file_sources = &leaf.placing.model.sources;
        // The part's own sources met so far: (its file's source, number).
        let mut own: Vec<(u32, usize)> = Vec::new();
        let deps = deps
            .iter()
            .map(|dep| {
                let s = &file_sources[dep.source as usize];
                let uniform = s.spread == Spread::Uniform;
                let met = if s.shared {
                    let (id, new) =
                        self.shared_id(mix(leaf.placing.file, u64::from(dep.source), 0));
                    Met {
                        id,
                        new,
                        shared: true,
                        uniform,
                    }
                } else if let Some(&(_, id)) = own.iter().find(|(k, _)| *k == dep.source) {
                    Met {
                        id,
                        new: false,
                        shared: false,
                        uniform,
                    }
                } else {
                    let id = self.fresh();
                    own.push((dep.source, id));
                    Met {
                        id,
                        new: true,
                        shared: false,
                        uniform,
                    }
                };
                (*dep, met)
            })
            .collect();
        Meets { shifts, deps }
    }
}

/// The label of a part's own number's source: `PART: KEY ± AMOUNT`, or a
/// parameter's `FILE: KEY ± AMOUNT`.
pub(super) fn dep_label(leaf: &Leaf<'_>, dep: &Dep) -> String {
    let s = &leaf.placing.model.sources[dep.source as usize];
    match (s.shared, leaf.part.assembly.last()) {
        (false, _) => format!("{}: {} ± {}", leaf.part.name, s.key, s.written),
        (true, Some(file)) => format!("{file}: {} ± {}", s.key, s.written),
        (true, None) => format!("{} ± {}", s.key, s.written),
    }
}

/// Where a part stands in each body: its mass (file units), its centroid
/// from each body's pivot, and its mass's factor there (1, or 1 + its
/// growth allowance in the predicted body).
pub(super) struct At {
    pub(super) m: f64,
    pub(super) ds: [[f64; 3]; 2],
    pub(super) ks: [f64; 2],
}

impl At {
    pub(super) fn of(body: &Body<'_>, leaf: &Leaf<'_>) -> At {
        let placed = leaf.part;
        let m: f64 = placed.mass();
        let cen = placed.centroid();
        let mut ds = [[0.0; 3]; 2];
        for (d, v) in ds.iter_mut().zip(body.views) {
            *d = std::array::from_fn(|i| (cen[i] - crate::numeric::DD::of(v.c0[i])).f64());
        }
        let grow = 1.0 + body.allowances.map_or(0.0, |a| a[leaf.index]);
        At {
            m,
            ds,
            ks: [1.0, grow],
        }
    }
}
