//! Monte Carlo sampling of the tolerances: counter-based draws (the same
//! on every run and core), streamed over the parts and the samples.
//!
//! NOTE: nothing is held per part or per source. A walk of the body
//! draws a chunk of samples, each toleranced part evaluated in each
//! sample as the walk meets it (the parts that no tolerance moves summed
//! once, first); the chunks go to every core. Each sample's outputs are
//! kept (13 or 26 numbers: the percentiles need them). A last walk meets
//! the sources again, in the same order, and forms each one's
//! contribution from the samples kept and its draws made again (a draw
//! is a function of the seed, the sample and the source), keeping the
//! largest three per output. Every sum is formed in the order it always
//! was: the same bits.

use super::motion::FIRST;
use super::walk::{At, Body, Numbering, dep_label};
use super::{N, Sums, TOP, Uncertainty, W, split};
use crate::numeric::M3;
use crate::part::{Fixed, physics_in};
use std::collections::HashMap;
use std::ops::Range;

/// A uniform number in (0, 1) from a key: the same for the same key on
/// every run and core (a counter-based generator: splitmix64's finaliser).
fn uniform(key: u64) -> f64 {
    let z = crate::model::walk::mix(key, 0x5851_F42D_4C95_7F2D, 0x1405_7B7E_F767_814F);
    ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// The standardised variable of source `k` in sample `s`: normal (Box–
/// Muller) or uniform on [−√3, √3], mean 0 and variance 1 both.
fn draw(seed: u64, s: usize, k: usize, uniform_spread: bool) -> f64 {
    let key = crate::model::walk::mix(seed, s as u64, k as u64);
    if uniform_spread {
        return (2.0 * uniform(key) - 1.0) * 3f64.sqrt();
    }
    let (u1, u2) = (uniform(key), uniform(key ^ 0xA076_1D64_78BD_642F));
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// Samples per block: each source's sums for the contributions are
/// formed block by block and the blocks added in order (the grouping of
/// those sums: the same bits however the samples are shared out).
const BLOCK: usize = 256;
/// Samples drawn in one walk of the body at most: each holds its body's
/// sums while the walk goes on.
const CHUNK: usize = 4096;
/// Sources whose contributions are formed together, on every core.
const BATCH: usize = 4096;

/// The parts that no tolerance moves, summed once (in walk order).
fn fixed(body: &Body<'_>) -> [Sums; 2] {
    let mut fixed = [Sums::default(); 2];
    let mut numbering = Numbering::default();
    body.model.each_part(&mut |leaf| {
        if !numbering.meet(&leaf).is_empty() {
            return;
        }
        let at = At::of(body, &leaf);
        let own: M3<f64> = leaf.part.own_second_moment(at.m);
        for (v, sums) in fixed.iter_mut().enumerate().take(body.views.len()) {
            sums.add_part(at.ks[v] * at.m, at.ds[v], &own);
        }
    });
    fixed
}

/// Samples `range`'s outputs of each body (none for a sample in which a
/// drawn part is no body: a size, radius, mass or density below zero, or
/// to zero from above; an inner radius past the outer): one walk, each
/// toleranced part drawn in every sample as it is met.
fn chunk(
    body: &Body<'_>,
    fixed: &[Sums; 2],
    seed: u64,
    range: Range<usize>,
) -> Vec<Option<[f64; W]>> {
    let views = body.views.len();
    let mut sums = vec![*fixed; range.len()];
    let mut alive = vec![true; range.len()];
    let mut numbering = Numbering::default();
    body.model.each_part(&mut |leaf| {
        let meets = numbering.meet(&leaf);
        if meets.is_empty() {
            return;
        }
        let at = At::of(body, &leaf);
        let l = leaf.placing.linear();
        let (_, own_c, _) = physics_in::<f64, Fixed>(&leaf.own.spec, Fixed);
        let mapped = l.dir(own_c);
        // Where its own centroid's image lies less the map of it: c' =
        // `l.dir(c)` + `shift` − c₀, about each body's centre.
        let shift: [[f64; 3]; 2] = at.ds.map(|d| std::array::from_fn(|i| d[i] - mapped[i]));
        'sample: for (j, s) in range.clone().enumerate() {
            if !alive[j] {
                continue;
            }
            let mut spec = leaf.own.spec.clone();
            for (dep, met) in &meets.deps {
                let x = spec.number_mut(dep.slot).expect("a recorded slot exists");
                let before = *x;
                *x += dep.rate * draw(seed, s, met.id, met.uniform);
                if !dep.slot.is_signed() && (*x < 0.0 || (*x == 0.0 && before > 0.0)) {
                    alive[j] = false;
                    continue 'sample;
                }
            }
            let (m, c, jm) = physics_in::<f64, Fixed>(&spec, Fixed);
            let sign = if spec.removed { -1.0 } else { 1.0 };
            if !(m * sign > 0.0) || (0..3).any(|a| jm[a][a] * sign < 0.0) {
                alive[j] = false;
                continue;
            }
            let mc = l.dir(c);
            let jm = l.second(&jm);
            for (b, k) in at.ks.into_iter().enumerate().take(views) {
                let mut d: [f64; 3] = std::array::from_fn(|i| mc[i] + shift[b][i]);
                for (met, v, _) in &meets.shifts {
                    let z = draw(seed, s, met.id, met.uniform);
                    for i in 0..3 {
                        d[i] += z * v[i];
                    }
                }
                sums[j][b].add_part(k * l.mass * m, d, &jm);
            }
        }
    });
    sums.iter()
        .zip(alive)
        .map(|(sums, alive)| {
            if !alive {
                return None;
            }
            let mut out = [0.0; W];
            for (b, v) in body.views.iter().enumerate() {
                let c0 = v.c0.map(|x| x * v.reported.length);
                out[b * N..(b + 1) * N].copy_from_slice(&v.reported.outputs(&sums[b], c0)?);
            }
            if let Some(m) = body.motion {
                let motion = m.outputs(&out[..N]);
                out[FIRST..].copy_from_slice(&motion);
            }
            Some(out)
        })
        .collect()
}

/// `f(i)` for each of `0..n` on every core, in order.
fn on_every_core<T: Send>(n: usize, f: &(dyn Fn(usize) -> T + Sync)) -> Vec<T> {
    let workers = std::thread::available_parallelism()
        .map_or(1, usize::from)
        .min(n.max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut results: Vec<Option<T>> = (0..n).map(|_| None).collect();
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        if i >= n {
                            break;
                        }
                        mine.push((i, f(i)));
                    }
                    mine
                })
            })
            .collect();
        for h in handles {
            for (i, r) in h.join().expect("a Monte Carlo worker does not panic") {
                results[i] = Some(r);
            }
        }
    });
    results
        .into_iter()
        .map(|r| r.expect("invariant: every task ran"))
        .collect()
}

/// The samples' outputs kept (at most `--samples` of them) for the
/// statistics and the sources' contributions.
pub(super) struct Kept {
    /// The samples that make a body: their numbers.
    at: Vec<usize>,
    /// Their outputs that are reported (`Body::live`), `live.len()` per
    /// sample: only those are held (8 bytes each).
    all: Vec<f64>,
    live: Vec<usize>,
    /// Output o's column among `live`, or `usize::MAX`.
    column: [usize; W],
}

impl Kept {
    fn new(body: &Body<'_>, samples: usize) -> Kept {
        let live: Vec<usize> = (0..W).filter(|&o| body.live(o)).collect();
        let mut column = [usize::MAX; W];
        for (c, &o) in live.iter().enumerate() {
            column[o] = c;
        }
        Kept {
            at: Vec::new(),
            all: Vec::with_capacity(samples.saturating_mul(live.len())),
            live,
            column,
        }
    }

    /// How many samples are kept.
    pub(super) fn len(&self) -> usize {
        self.at.len()
    }

    /// Whether every sample was left out.
    pub(super) fn is_empty(&self) -> bool {
        self.at.is_empty()
    }

    /// Output `o` of kept sample `i` (0 for an output not reported).
    pub(super) fn get(&self, i: usize, o: usize) -> f64 {
        match self.column[o] {
            usize::MAX => 0.0,
            c => self.all[i * self.live.len() + c],
        }
    }

    fn push(&mut self, s: usize, out: &[f64; W]) {
        self.at.push(s);
        self.all.extend(self.live.iter().map(|&o| out[o]));
    }

    /// Source `k`'s sums for its contribution: Σ (out − nominal) z over
    /// the samples kept and, last, Σ z, block by block, the blocks added
    /// in order.
    fn sums(&self, seed: u64, k: usize, uniform: bool, nominal: &[f64; W]) -> [f64; W + 1] {
        let mut acc = [0.0; W + 1];
        let mut i = 0;
        while i < self.at.len() {
            let block = self.at[i] / BLOCK;
            let mut row = [0.0; W + 1];
            while i < self.at.len() && self.at[i] / BLOCK == block {
                let z = draw(seed, self.at[i], k, uniform);
                // Centred on the nominal value, so that the sums keep the
                // digits of the deviations.
                let values = &self.all[i * self.live.len()..(i + 1) * self.live.len()];
                for (&o, v) in self.live.iter().zip(values) {
                    row[o] += (v - nominal[o]) * z;
                }
                row[W] += z;
                i += 1;
            }
            for (a, x) in acc.iter_mut().zip(&row) {
                *a += x;
            }
        }
        acc
    }
}

/// A source waiting for its contribution: number, spread, label.
type Waiting = (usize, bool, String);

pub(super) fn run(
    body: &Body<'_>,
    nominal: [f64; W],
    (samples, seed): (usize, u64),
) -> (Uncertainty, Kept) {
    let fixed = fixed(body);
    let workers = std::thread::available_parallelism().map_or(1, usize::from);
    // Enough chunks for every core, none larger than `CHUNK`.
    let chunks = samples.div_ceil(CHUNK).max(workers).div_ceil(workers) * workers;
    let size = samples.div_ceil(chunks).max(1);
    let chunks = samples.div_ceil(size);
    let outs = on_every_core(chunks, &|c| {
        chunk(body, &fixed, seed, c * size..((c + 1) * size).min(samples))
    });
    let mut kept = Kept::new(body, samples);
    let mut rejected = 0;
    for (s, o) in outs.into_iter().flatten().enumerate() {
        match o {
            Some(o) => kept.push(s, &o),
            None => rejected += 1,
        }
    }
    let all = &kept;
    let n = all.len();
    let mean: [f64; W] =
        std::array::from_fn(|o| (0..n).map(|i| all.get(i, o)).sum::<f64>() / n.max(1) as f64);
    let covariance: Vec<Vec<f64>> = (0..W)
        .map(|a| {
            (0..W)
                .map(|b| {
                    if !body.live(a) || !body.live(b) {
                        return 0.0;
                    }
                    (0..n)
                        .map(|i| (all.get(i, a) - mean[a]) * (all.get(i, b) - mean[b]))
                        .sum::<f64>()
                        / (n.max(2) - 1) as f64
                })
                .collect()
        })
        .collect();
    // cov(out, z) estimates ∂out/∂z (E z = 0, var z = 1): its square over
    // the variance is the source's share. Each output keeps its `TOP`
    // largest, the first met among equals, as the sources stream by.
    let mut best: Vec<Vec<(usize, f64)>> = vec![Vec::new(); W];
    let mut labels: HashMap<usize, String> = HashMap::new();
    let mut weigh = |batch: &mut Vec<Waiting>| {
        let sums = on_every_core(batch.len().div_ceil(64), &|c| {
            batch[c * 64..((c + 1) * 64).min(batch.len())]
                .iter()
                .map(|(k, uniform, _)| kept.sums(seed, *k, *uniform, &nominal))
                .collect::<Vec<_>>()
        });
        for ((k, _, label), c) in batch.drain(..).zip(sums.into_iter().flatten()) {
            let mut entered = false;
            for (o, best) in best.iter_mut().enumerate() {
                let var = covariance[o][o];
                let g = (c[o] - (mean[o] - nominal[o]) * c[W]) / n.max(1) as f64;
                let share = if var > 0.0 {
                    (g * g / var).min(1.0)
                } else {
                    0.0
                };
                if !(share > 0.0) || (best.len() == TOP && !(share > best[TOP - 1].1)) {
                    continue;
                }
                let at = best.partition_point(|(_, s)| *s >= share);
                best.insert(at, (k, share));
                best.truncate(TOP);
                entered = true;
            }
            if entered {
                labels.insert(k, label);
            }
        }
        labels.retain(|k, _| best.iter().flatten().any(|(j, _)| j == k));
    };
    let mut numbering = Numbering::default();
    let mut batch: Vec<Waiting> = Vec::with_capacity(BATCH);
    body.model.each_part(&mut |leaf| {
        let meets = numbering.meet(&leaf);
        for (met, _, label) in &meets.shifts {
            if met.new {
                batch.push((met.id, met.uniform, label.clone().unwrap_or_default()));
            }
        }
        for (dep, met) in &meets.deps {
            if met.new {
                batch.push((met.id, met.uniform, dep_label(&leaf, dep)));
            }
        }
        if batch.len() >= BATCH {
            weigh(&mut batch);
        }
    });
    weigh(&mut batch);
    let share = |o: usize, _var: f64| best[o].clone();
    let stats = |o: usize| {
        let mut v: Vec<f64> = (0..n).map(|i| all.get(i, o)).collect();
        v.sort_by(f64::total_cmp);
        (
            Some(mean[o]),
            Some([
                percentile(&v, 0.05),
                percentile(&v, 0.5),
                percentile(&v, 0.95),
            ]),
        )
    };
    let (outputs, covariance, predicted) =
        split(body, &nominal, &covariance, &share, &stats, &|k| {
            labels[&k].clone()
        });
    let u = Uncertainty {
        method: "montecarlo",
        samples: Some(samples),
        seed: Some(seed),
        rejected: Some(rejected),
        sources: numbering.count(),
        outputs,
        covariance,
        predicted,
        exceed: Vec::new(),
        equal_moments: Vec::new(),
    };
    (u, kept)
}

/// The p-quantile of sorted values (linear between order statistics).
fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let h = p * (sorted.len() - 1) as f64;
    let (lo, hi) = (h.floor() as usize, h.ceil() as usize);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}
