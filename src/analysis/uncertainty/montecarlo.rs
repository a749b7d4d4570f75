//! Monte Carlo sampling of the tolerances: counter-based draws (the same
//! on every run and core), blocks of samples on every core combined in
//! order, and the statistics of the outputs.

use super::{Moving, N, Source, Sums, Uncertainty, View, W, split};
use crate::part::{Fixed, physics_in};

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

/// A block's samples' outputs, its sums for the contributions (Σ (out −
/// nominal) z per source, Σ z last) and its samples left out.
type Block = (Vec<[f64; W]>, Vec<[f64; W + 1]>, usize);

/// Samples per block: blocks are drawn on every core and combined in
/// order, so the result is the same on any number of cores.
const BLOCK: usize = 256;

/// What a Monte Carlo run samples: the sources, the parts they move, the
/// sums of the parts they do not, and the bodies (basic, predicted).
pub(super) struct Sampled<'a> {
    pub(super) sources: &'a [Source],
    pub(super) moving: &'a [Moving],
    pub(super) fixed: &'a [Sums; 2],
    pub(super) views: &'a [View],
}

/// One sample's outputs of each body, or none when a drawn part is no
/// body (a size, radius, mass or density below zero, or to zero from
/// above; an inner radius past the outer).
fn sample(sampled: &Sampled<'_>, z: &[f64]) -> Option<[f64; W]> {
    let mut sums = *sampled.fixed;
    for part in sampled.moving {
        let mut spec = part.spec.clone();
        for &(slot, k, rate) in &part.deps {
            let x = spec.number_mut(slot).expect("a recorded slot exists");
            let before = *x;
            *x += rate * z[k];
            if !slot.is_signed() && (*x < 0.0 || (*x == 0.0 && before > 0.0)) {
                return None;
            }
        }
        let (m, c, j) = physics_in::<f64, Fixed>(part.shape, &spec, Fixed);
        let sign = if spec.removed { -1.0 } else { 1.0 };
        if !(m * sign > 0.0) || (0..3).any(|a| j[a][a] * sign < 0.0) {
            return None;
        }
        let l = &part.linear;
        let mc = l.dir(c);
        let j = l.second(&j);
        for (b, k) in [1.0, part.grow]
            .into_iter()
            .enumerate()
            .take(sampled.views.len())
        {
            let mut d: [f64; 3] = std::array::from_fn(|i| mc[i] + part.shift[b][i]);
            for &(s, v) in &part.shifts {
                for i in 0..3 {
                    d[i] += z[s] * v[i];
                }
            }
            sums[b].add_part(k * l.mass * m, d, &j);
        }
    }
    let mut out = [0.0; W];
    for (b, v) in sampled.views.iter().enumerate() {
        let c0 = v.c0.map(|x| x * v.reported.length);
        out[b * N..(b + 1) * N].copy_from_slice(&v.reported.outputs(&sums[b], c0)?);
    }
    Some(out)
}

pub(super) fn monte_carlo_run(
    sampled: &Sampled<'_>,
    nominal: [f64; W],
    (samples, seed): (usize, u64),
) -> (Uncertainty, Vec<[f64; W]>) {
    let sources = sampled.sources;
    let blocks = samples.div_ceil(BLOCK);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let run_block = |b: usize| -> Block {
        let mut outs = Vec::with_capacity(BLOCK);
        let mut cov = vec![[0.0; W + 1]; sources.len()];
        let mut rejected = 0;
        let mut z = vec![0.0; sources.len()];
        for s in b * BLOCK..((b + 1) * BLOCK).min(samples) {
            for (k, src) in sources.iter().enumerate() {
                z[k] = draw(seed, s, k, src.uniform);
            }
            match sample(sampled, &z) {
                Some(o) => {
                    // Σ (out − nominal) z and, in the last column, Σ z:
                    // centred on the nominal value so that the sums keep
                    // the digits of the deviations.
                    for (k, row) in cov.iter_mut().enumerate() {
                        for (r, (v, n)) in row.iter_mut().zip(o.iter().zip(&nominal)) {
                            *r += (v - n) * z[k];
                        }
                        row[W] += z[k];
                    }
                    outs.push(o);
                }
                None => rejected += 1,
            }
        }
        (outs, cov, rejected)
    };
    let workers = std::thread::available_parallelism()
        .map_or(1, usize::from)
        .min(blocks.max(1));
    let mut results: Vec<Option<Block>> = vec![None; blocks];
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let b = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        if b >= blocks {
                            break;
                        }
                        mine.push((b, run_block(b)));
                    }
                    mine
                })
            })
            .collect();
        for h in handles {
            for (b, r) in h.join().expect("a Monte Carlo worker does not panic") {
                results[b] = Some(r);
            }
        }
    });
    let mut all: Vec<[f64; W]> = Vec::with_capacity(samples);
    let mut cov = vec![[0.0; W + 1]; sources.len()];
    let mut rejected = 0;
    for (outs, c, r) in results.into_iter().flatten() {
        all.extend(outs);
        for (acc, add) in cov.iter_mut().zip(&c) {
            for (a, x) in acc.iter_mut().zip(add) {
                *a += x;
            }
        }
        rejected += r;
    }
    let n = all.len();
    let width = N * sampled.views.len();
    let mean: [f64; W] =
        std::array::from_fn(|o| all.iter().map(|r| r[o]).sum::<f64>() / n.max(1) as f64);
    let covariance: Vec<Vec<f64>> = (0..W)
        .map(|a| {
            (0..W)
                .map(|b| {
                    if a >= width || b >= width {
                        return 0.0;
                    }
                    all.iter()
                        .map(|r| (r[a] - mean[a]) * (r[b] - mean[b]))
                        .sum::<f64>()
                        / (n.max(2) - 1) as f64
                })
                .collect()
        })
        .collect();
    // cov(out, z) estimates ∂out/∂z (E z = 0, var z = 1): its square over
    // the variance is the source's share.
    let share = |o: usize, var: f64| -> Vec<(usize, f64)> {
        cov.iter()
            .enumerate()
            .map(|(k, c)| {
                let g = (c[o] - (mean[o] - nominal[o]) * c[W]) / n.max(1) as f64;
                (
                    k,
                    if var > 0.0 {
                        (g * g / var).min(1.0)
                    } else {
                        0.0
                    },
                )
            })
            .collect()
    };
    let stats = |o: usize| {
        let mut v: Vec<f64> = all.iter().map(|r| r[o]).collect();
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
    let (outputs, covariance, predicted) = split(
        sampled.views.len(),
        &nominal,
        &covariance,
        &share,
        &stats,
        &|k| sources[k].label.clone(),
    );
    let u = Uncertainty {
        method: "montecarlo",
        samples: Some(samples),
        seed: Some(seed),
        rejected: Some(rejected),
        sources: sources.len(),
        outputs,
        covariance,
        predicted,
        exceed: Vec::new(),
        equal_moments: Vec::new(),
    };
    (u, all)
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
