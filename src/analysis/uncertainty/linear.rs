//! First-order propagation, streamed over the parts: each source's row of
//! derivatives (the outputs' by its variable) is formed once complete,
//! added to the covariance and weighed as a contributor, and forgotten.
//!
//! NOTE: the rows are added in the order the walk first meets their
//! sources (the order of the sums the covariance has always had, so the
//! same bits). A part's own source is complete at the end of its part; a
//! shared one (a parameter's, a material's, an origin's) only once every
//! part that uses it is walked, and a source met later may not be added
//! before it. So a body with shared sources is walked twice: first for
//! the shared sources' rows alone (held: one row per shared source, not
//! per part), then for the rest, each shared row added where its source
//! was first met.

use super::motion::FIRST;
use super::walk::{At, Body, Meets, Met, Numbering, dep_label};
use super::{N, Sums, Uncertainty, W, moved, split};
use crate::dual::Dual;
use crate::model::walk::Leaf;
use crate::part::{Dep, Seed, Slot, physics_in};
use std::collections::HashMap;

/// How many contributors each output keeps while the rows stream by: the
/// largest |row[o]|, the first met among equals. The shares are their
/// squares over the variance, known at the end.
///
/// NOTE: more than `TOP`: shares of different squares can round to the
/// same share, where the first met then comes first; seven distinct
/// squares cannot round to one quotient, so eight hold every one that
/// can rank in the top three.
const KEPT: usize = 8;

/// The sums the rows stream into.
struct Sink {
    /// Σ row rowᵀ, each entry summed in the order the rows come, from the
    /// empty sum (as `Iterator::sum` sums).
    cov: Vec<[f64; W]>,
    /// Per output: (source, its row's entry), largest square first.
    kept: Vec<Vec<(usize, f64)>>,
    labels: HashMap<usize, String>,
}

impl Sink {
    fn new() -> Sink {
        let zero: f64 = std::iter::empty::<f64>().sum();
        Sink {
            cov: vec![[zero; W]; W],
            kept: vec![Vec::new(); W],
            labels: HashMap::new(),
        }
    }

    /// Source `id`'s row, complete.
    fn add(&mut self, id: usize, row: &[f64; W], label: &mut dyn FnMut() -> String) {
        // The upper triangle: row[a] row[b] is row[b] row[a] to the bit,
        // so the lower is its mirror (`covariance`).
        for (a, line) in self.cov.iter_mut().enumerate() {
            for (b, x) in line.iter_mut().enumerate().skip(a) {
                *x += row[a] * row[b];
            }
        }
        let mut evicted = Vec::new();
        let mut entered = false;
        for (o, kept) in self.kept.iter_mut().enumerate() {
            let r2 = row[o] * row[o];
            if !(r2 > 0.0) {
                continue; // no share (a NaN would have none either)
            }
            if kept.len() == KEPT && !(r2 > kept[KEPT - 1].1 * kept[KEPT - 1].1) {
                continue;
            }
            let at = kept.partition_point(|(_, r)| r * r >= r2);
            kept.insert(at, (id, row[o]));
            if kept.len() > KEPT {
                evicted.extend(kept.pop().map(|(k, _)| k));
            }
            entered = true;
        }
        if entered {
            self.labels.insert(id, label());
        }
        for k in evicted {
            if !self.kept.iter().flatten().any(|(j, _)| *j == k) {
                self.labels.remove(&k);
            }
        }
    }
}

/// Source rows, from the sums' derivatives: each body's outputs'.
fn row(body: &Body<'_>, d: &[Sums; 2]) -> [f64; W] {
    let mut row = [0.0; W];
    for (b, v) in body.views.iter().enumerate() {
        row[b * N..(b + 1) * N].copy_from_slice(&v.reported.linear(&d[b], v.m));
    }
    if let Some(m) = body.motion {
        let motion = m.linear(&row[..N]);
        row[FIRST..].copy_from_slice(&motion);
    }
    row
}

/// A part's derivatives by the sources `wanted` takes, each handed to
/// `add` (source, body, the change of the sums, its rate), in the order
/// the sums have always been formed: its origins' shifts, then one dual
/// evaluation per slot its own tolerances move.
fn differentiate(
    body: &Body<'_>,
    leaf: &Leaf<'_>,
    meets: &Meets,
    wanted: &dyn Fn(&Met) -> bool,
    add: &mut dyn FnMut(&Met, usize, &Sums, f64),
) {
    let at = At::of(body, leaf);
    let views = body.views.len();
    // Linear: a shift v moves the centroid by v, the rest stays.
    for (met, v, _) in &meets.shifts {
        if !wanted(met) {
            continue;
        }
        for b in 0..views {
            let per = moved(0.0, *v, &[[0.0; 3]; 3], at.m, at.ds[b], at.ks[b]);
            add(met, b, &per, 1.0);
        }
    }
    let linear = leaf.placing.linear();
    let mut done: Vec<Slot> = Vec::new();
    for (dep, _) in &meets.deps {
        if done.contains(&dep.slot) {
            continue;
        }
        done.push(dep.slot);
        let moves = |(o, met): &(Dep, Met)| o.slot == dep.slot && wanted(met);
        if !meets.deps.iter().any(moves) {
            continue;
        }
        let (dm, dc, dj) = physics_in::<Dual<f64>, Seed>(&leaf.own.spec, Seed(dep.slot));
        let dm = linear.mass * dm.d;
        let dc = linear.dir(dc.map(|x| x.d));
        let dj = linear.second(&dj.map(|r| r.map(|x| x.d)));
        for b in 0..views {
            let per = moved(dm, dc, &dj, at.m, at.ds[b], at.ks[b]);
            for d in meets.deps.iter().filter(|d| moves(d)) {
                add(&d.1, b, &per, d.0.rate);
            }
        }
    }
}

/// The shared sources' rows and labels, by number: one walk that follows
/// them alone.
fn shared_rows(body: &Body<'_>) -> HashMap<usize, ([f64; W], String)> {
    let mut open: HashMap<usize, ([Sums; 2], String)> = HashMap::new();
    let mut numbering = Numbering::default();
    body.model.each_part(&mut |leaf| {
        let meets = numbering.meet(&leaf);
        for (met, _, label) in &meets.shifts {
            if met.new {
                let label = label.clone().unwrap_or_default();
                open.insert(met.id, ([Sums::default(); 2], label));
            }
        }
        for (dep, met) in &meets.deps {
            if met.new && met.shared {
                open.insert(met.id, ([Sums::default(); 2], dep_label(&leaf, dep)));
            }
        }
        differentiate(
            body,
            &leaf,
            &meets,
            &|m| m.shared,
            &mut |met, b, per, rate| {
                if let Some((d, _)) = open.get_mut(&met.id) {
                    d[b].plus(per, rate);
                }
            },
        );
    });
    open.into_iter()
        .map(|(id, (d, label))| (id, (row(body, &d), label)))
        .collect()
}

/// The walk that adds every row in order: each part's own sources' at the
/// end of the part, each shared one's (from `shared`) where it is first
/// met. Without `shared`, none if a shared source is met.
fn rows_in_order(
    body: &Body<'_>,
    mut shared: Option<HashMap<usize, ([f64; W], String)>>,
) -> Option<(Sink, usize)> {
    let mut sink = Sink::new();
    let mut numbering = Numbering::default();
    let mut stuck = false;
    // The part's own sources: their numbers and sums.
    let mut own: Vec<(usize, Dep, [Sums; 2])> = Vec::new();
    body.model.each_part(&mut |leaf| {
        if stuck {
            return;
        }
        let meets = numbering.meet(&leaf);
        if meets.is_empty() {
            return;
        }
        let firsts = meets
            .shifts
            .iter()
            .map(|(met, _, _)| (*met, None))
            .chain(meets.deps.iter().map(|(dep, met)| (*met, Some(*dep))))
            .filter(|(met, _)| met.new);
        own.clear();
        let mut new: Vec<Met> = Vec::new();
        for (met, dep) in firsts {
            if met.shared && shared.is_none() {
                stuck = true;
                return;
            }
            if let (false, Some(dep)) = (met.shared, dep) {
                own.push((met.id, dep, [Sums::default(); 2]));
            }
            new.push(met);
        }
        differentiate(
            body,
            &leaf,
            &meets,
            &|m| !m.shared,
            &mut |met, b, per, rate| {
                if let Some((_, _, d)) = own.iter_mut().find(|(id, _, _)| *id == met.id) {
                    d[b].plus(per, rate);
                }
            },
        );
        for met in new {
            if met.shared {
                let rows = shared.as_mut().expect("checked above");
                let (r, label) = rows
                    .remove(&met.id)
                    .expect("invariant: both walks number the shared sources alike");
                sink.add(met.id, &r, &mut || label.clone());
            } else {
                let (_, dep, d) = own
                    .iter()
                    .find(|(id, _, _)| *id == met.id)
                    .expect("invariant: a part's own source is in `own`");
                sink.add(met.id, &row(body, d), &mut || dep_label(&leaf, dep));
            }
        }
    });
    (!stuck).then(|| (sink, numbering.count()))
}

/// First-order propagation over `body`.
pub(super) fn run(body: &Body<'_>, nominal: [f64; W]) -> Uncertainty {
    let (sink, sources) = rows_in_order(body, None).unwrap_or_else(|| {
        rows_in_order(body, Some(shared_rows(body)))
            .expect("invariant: with the shared rows known, the walk adds every row")
    });
    let cov: Vec<Vec<f64>> = (0..W)
        .map(|a| (0..W).map(|b| sink.cov[a.min(b)][a.max(b)]).collect())
        .collect();
    let share = |o: usize, var: f64| -> Vec<(usize, f64)> {
        sink.kept[o]
            .iter()
            .map(|&(k, r)| (k, if var > 0.0 { r * r / var } else { 0.0 }))
            .collect()
    };
    let (outputs, covariance, predicted) =
        split(body, &nominal, &cov, &share, &|_| (None, None), &|k| {
            sink.labels[&k].clone()
        });
    Uncertainty {
        method: "linear",
        samples: None,
        seed: None,
        rejected: None,
        sources,
        outputs,
        covariance,
        predicted,
        exceed: Vec::new(),
        equal_moments: Vec::new(),
    }
}
