//! The uncertainty of a body's mass properties from the tolerances of its
//! parts' quantities (`model::tolerance`): first-order propagation with
//! exact derivatives (`Method::Linear`: forward-mode automatic
//! differentiation through the parts' own physics, `dual::Dual`), or Monte
//! Carlo sampling (`Method::MonteCarlo`: reproducible, on every core).
//!
//! The outputs are the mass, the centre of mass, the inertia tensor about
//! the centre of mass (in the report axes and products convention) and the
//! principal moments, in SI (`N` of them, each its quantity's, numbered by
//! the table's `quantity::Info::sigma`). A tolerance on a part's key is
//! an independent source for each copy of the part (an array's copies,
//! each instance of an included file); one on a parameter or a material
//! is one source per instance of its file, shared by every key that uses
//! it; one on a sub-assembly's origin one per instance of the include.
//!
//! NOTE: both methods work on the body's three sums about the nominal
//! centre of mass c₀ (file units): M = Σ m, S = Σ m d and
//! P = Σ (Cᵢ + m d dᵀ), d = cᵢ − c₀, of which the outputs are functions:
//! c = c₀ + S/M and C = P − S Sᵀ/M. A part's derivative by a source moves
//! only its own terms, and reaches them through the linear part of the
//! frames that place it (`frame::Linear`): its own file's figures are
//! differentiated once, wherever it is included.

use super::Products;
use super::summary::Summary;
use crate::model::Model;
use crate::model::expect::Target;
use crate::numeric::{M3, Real};
use crate::quantity::{Layout, QUANTITIES, Quantity, UPPER, component};
use std::sync::LazyLock;

pub use super::sigma::{Contributor, Exceed, Output, Predicted, Uncertainty};

mod linear;
mod montecarlo;
mod motion;
mod walk;
use walk::Body;

/// How the tolerances are propagated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Linear,
    MonteCarlo { samples: usize, seed: u64 },
}

/// How many outputs one body has: mass, centre of mass, the six entries
/// of the inertia tensor, the principal moments (`quantity::OUTPUTS`:
/// the table's `sigma` numbers them).
const N: usize = crate::quantity::OUTPUTS;
/// How many outputs the body moving has (`motion`).
const K: usize = crate::quantity::MOTION_OUTPUTS;
/// The outputs of both bodies, the basic's first (the predicted body's
/// are zero where the file has none), then the basic body's motion's
/// (zero where it has none).
const W: usize = 2 * N + K;

/// Where quantity `q`'s outputs begin (`quantity::Info::sigma`).
const fn first(q: Quantity) -> usize {
    match QUANTITIES[q as usize].sigma {
        Some(o) => o,
        None => panic!("invariant: a quantity whose σ is propagated"),
    }
}
const MASS: usize = first(Quantity::Mass);
const CENTRE: usize = first(Quantity::CenterOfMass);
const INERTIA: usize = first(Quantity::InertiaCom);
const MOMENTS: usize = first(Quantity::PrincipalMoments);

/// The components (row-major for a matrix) of a quantity's value that
/// its outputs are, in their order: a symmetric matrix's upper triangle.
fn components(layout: Layout) -> Vec<usize> {
    match layout {
        Layout::Matrix => UPPER.iter().map(|&(_, i, j)| 3 * i + j).collect(),
        Layout::Scalar | Layout::Vector | Layout::Ordered | Layout::Axes => {
            (0..layout.count()).collect()
        }
    }
}

/// The basic body's quantities whose σ is propagated, each with its first
/// output.
fn propagated() -> impl Iterator<Item = (&'static crate::quantity::Info, usize)> {
    QUANTITIES
        .iter()
        .filter_map(|i| i.sigma.filter(|o| *o < N).map(|o| (i, o)))
}

/// The outputs' names, as `[expect]` names their components
/// (`center_of_mass.x`); the predicted body's prefixed `predicted_`
/// (`predicted_principal_moments.1`, which `[expect]` has no key for).
static NAMES: LazyLock<Vec<String>> = LazyLock::new(|| {
    let mut names = vec![String::new(); N];
    for (info, o) in propagated() {
        for (n, k) in components(info.layout).into_iter().enumerate() {
            names[o + n] = match info.layout {
                Layout::Scalar => info.key.to_string(),
                Layout::Vector | Layout::Ordered | Layout::Matrix | Layout::Axes => {
                    format!("{}.{}", info.key, component(info.layout, k))
                }
            };
        }
    }
    let predicted: Vec<String> = names.iter().map(|n| format!("predicted_{n}")).collect();
    names.extend(predicted);
    names.resize(W, String::new());
    for (info, o) in moving() {
        for (n, k) in components(info.layout).into_iter().enumerate() {
            names[o + n] = match info.layout {
                Layout::Scalar => info.key.to_string(),
                Layout::Vector | Layout::Ordered | Layout::Matrix | Layout::Axes => {
                    format!("{}.{}", info.key, component(info.layout, k))
                }
            };
        }
    }
    names
});

/// The body moving's quantities whose σ is propagated (`motion`), each
/// with its first output.
fn moving() -> impl Iterator<Item = (&'static crate::quantity::Info, usize)> {
    QUANTITIES
        .iter()
        .filter_map(|i| i.sigma.filter(|o| *o >= motion::FIRST).map(|o| (i, o)))
}

/// The name of output `o` of `W`.
fn name_of(o: usize) -> &'static str {
    &NAMES[o]
}
/// How many sources each output names as contributing most.
const TOP: usize = 3;

/// The body's sums about c₀, or their derivatives.
#[derive(Clone, Copy, Default)]
struct Sums {
    m: f64,
    s: [f64; 3],
    p: M3<f64>,
}

impl Sums {
    fn add_part(&mut self, m: f64, d: [f64; 3], c: &M3<f64>) {
        self.m += m;
        for i in 0..3 {
            self.s[i] += m * d[i];
            for j in 0..3 {
                self.p[i][j] += c[i][j] + m * d[i] * d[j];
            }
        }
    }

    fn plus(&mut self, o: &Sums, k: f64) {
        self.m += k * o.m;
        for i in 0..3 {
            self.s[i] += k * o.s[i];
            for j in 0..3 {
                self.p[i][j] += k * o.p[i][j];
            }
        }
    }
}

/// The conversions from the file's units and frame to what is reported.
struct Reported {
    mass: f64,
    length: f64,
    inertia: f64,
    /// The report axes' rows, in the file's frame.
    axes: M3<f64>,
    positive: bool,
    /// The principal axes (rows, report axes) of the nominal body.
    principal: M3<f64>,
}

impl Reported {
    fn new(model: &Model, summary: &Summary) -> Reported {
        let f = crate::part::SiFactors::of(model.units);
        Reported {
            mass: f.mass.f64(),
            length: f.length.f64(),
            inertia: f.inertia,
            axes: summary.axes,
            positive: summary.products_convention == Products::Positive,
            principal: summary.principal_axes,
        }
    }

    /// The inertia tensor (SI, report axes, its convention) of a second
    /// moment about the centre of mass (file units and axes).
    fn inertia(&self, c: &M3<f64>) -> M3<f64> {
        let tr = c[0][0] + c[1][1] + c[2][2];
        let i: M3<f64> = std::array::from_fn(|a| {
            std::array::from_fn(|b| if a == b { tr } else { 0.0 } - c[a][b])
        });
        let a = &self.axes;
        std::array::from_fn(|p| {
            std::array::from_fn(|q| {
                let v: f64 = (0..3)
                    .map(|k| (0..3).map(|l| a[p][k] * i[k][l] * a[q][l]).sum::<f64>())
                    .sum();
                let sign = if self.positive && p != q { -1.0 } else { 1.0 };
                sign * v * self.inertia
            })
        })
    }

    /// The tensor outputs (entries 4..10) of a tensor.
    fn entries(i: &M3<f64>, out: &mut [f64; N]) {
        for (k, &(_, a, b)) in UPPER.iter().enumerate() {
            out[INERTIA + k] = i[a][b];
        }
    }

    /// A change of the sums (file units) as a change of the outputs, to
    /// first order at the nominal body (S = 0 there).
    fn linear(&self, d: &Sums, m: f64) -> [f64; N] {
        let mut out = [0.0; N];
        out[MASS] = d.m * self.mass;
        for i in 0..3 {
            out[CENTRE + i] = d.s[i] / m * self.length;
        }
        // I in the report convention is linear in C: its derivative is
        // the same map of dC, less the sign of a product under `positive`
        // (which `inertia` applies to the entries alike).
        let di = self.inertia(&d.p);
        Reported::entries(&di, &mut out);
        // First-order perturbation of a simple eigenvalue: dλ = pᵀ dI p
        // (in the tensor convention, whatever is shown).
        let t = self.tensor(&di);
        for (k, p) in self.principal.iter().enumerate() {
            out[MOMENTS + k] = (0..3)
                .map(|a| (0..3).map(|b| p[a] * t[a][b] * p[b]).sum::<f64>())
                .sum();
        }
        out
    }

    /// A tensor in the report convention back in the tensor convention.
    fn tensor(&self, i: &M3<f64>) -> M3<f64> {
        std::array::from_fn(|a| {
            std::array::from_fn(|b| {
                if self.positive && a != b {
                    -i[a][b]
                } else {
                    i[a][b]
                }
            })
        })
    }

    /// The outputs of a body's sums about c₀ (`c0` the nominal centre in
    /// SI), for a sample.
    fn outputs(&self, sums: &Sums, c0: [f64; 3]) -> Option<[f64; N]> {
        let m = sums.m;
        if !(m > 0.0) {
            return None;
        }
        let mut out = [0.0; N];
        out[MASS] = m * self.mass;
        for i in 0..3 {
            out[CENTRE + i] = c0[i] + sums.s[i] / m * self.length;
        }
        let c: M3<f64> = std::array::from_fn(|a| {
            std::array::from_fn(|b| sums.p[a][b] - sums.s[a] * (sums.s[b] / m))
        });
        let i = self.inertia(&c);
        Reported::entries(&i, &mut out);
        let t = self.tensor(&i);
        let (mut moments, _) = crate::eigen::jacobi::<f64>(t)?;
        moments.sort_by(f64::total_cmp);
        out[MOMENTS..MOMENTS + 3].copy_from_slice(&moments);
        Some(out)
    }
}

/// One body whose outputs are propagated: how they are reported, its
/// nominal centre (file units) and mass (file units).
struct View {
    reported: Reported,
    c0: [f64; 3],
    m: f64,
}

impl View {
    fn new(model: &Model, summary: &Summary) -> View {
        let reported = Reported::new(model, summary);
        View {
            c0: std::array::from_fn(|i| summary.center_of_mass[i] / reported.length),
            m: summary.mass / reported.mass,
            reported,
        }
    }
}

/// How a part's figures move a body's sums, `k` its mass's factor in the
/// body (1, or 1 + its growth allowance: the growth a point mass at its
/// centroid): dm, dc and dC of the part (root frame), m its mass, d its
/// centroid from the body's pivot.
fn moved(dm: f64, dc: [f64; 3], dj: &M3<f64>, m: f64, d: [f64; 3], k: f64) -> Sums {
    let mut per = Sums {
        m: k * dm,
        ..Sums::default()
    };
    for i in 0..3 {
        per.s[i] = k * (dm * d[i] + m * dc[i]);
        for j in 0..3 {
            per.p[i][j] = dj[i][j] + k * (dm * d[i] * d[j] + m * (dc[i] * d[j] + d[i] * dc[j]));
        }
    }
    per
}

/// The uncertainty of `model`'s body (`summary` its nominal figures), and
/// of its predicted body where `predicted` gives its nominal figures.
pub fn propagate(
    model: &Model,
    analysis: &crate::model::Analysis,
    summary: &Summary,
    predicted: Option<&Summary>,
    method: Method,
    source: &crate::diag::Source,
) -> Result<Uncertainty, crate::diag::Diagnostic> {
    let mut views = vec![View::new(model, summary)];
    views.extend(predicted.map(|p| View::new(model, p)));
    let allowances = predicted.map(|_| super::budget::allowances(model));
    let mut nominal = [0.0; W];
    nominal[..N].copy_from_slice(&nominal_outputs(summary));
    if let Some(p) = predicted {
        nominal[N..2 * N].copy_from_slice(&nominal_outputs(p));
    }
    let motion = summary.omega.map(|omega| {
        let velocity = summary
            .reported(Quantity::Velocity)
            .map(|v| std::array::from_fn(|k| v.component(k)));
        motion::Motion {
            axes: summary.axes,
            point: analysis.about.map(|_| summary.reference_point),
            omega,
            velocity,
            positive: summary.products_convention == Products::Positive,
            nominal: std::array::from_fn(|o| nominal[o]),
        }
    });
    if motion.is_some() {
        for (info, o) in moving() {
            if let Some(v) = summary.reported(info.quantity) {
                for (n, k) in components(info.layout).into_iter().enumerate() {
                    nominal[o + n] = v.component(k);
                }
            }
        }
    }
    let body = Body {
        model,
        views: &views,
        allowances: allowances.as_deref(),
        motion: motion.as_ref(),
    };
    // The chance of each `[expect]` entry on an output to fail, and of the
    // predicted mass to pass `[budget] limit`: (name, where, bounds, output).
    let mut checks: Vec<(String, usize, (f64, f64), usize)> = model
        .expect
        .iter()
        .filter_map(|c| {
            let o = output_of(c.target)?;
            body.live(o)
                .then(|| (c.name.clone(), c.span.start, c.bound.limits(), o))
        })
        .collect();
    if let (Some(limit), true) = (&model.budget, views.len() == 2) {
        checks.push((
            "budget.limit".into(),
            limit.span.start,
            (f64::NEG_INFINITY, limit.mass),
            N,
        ));
    }
    let (mut out, outside) = match method {
        Method::Linear => {
            let u = linear::run(&body, nominal);
            let sigma = |o: usize| {
                if !(N..motion::FIRST).contains(&o) {
                    u.outputs
                        .iter()
                        .find(|x| x.quantity == name_of(o))
                        .map_or(0.0, |x| x.sigma)
                } else {
                    u.predicted.as_ref().map_or(0.0, |p| p.outputs[o - N].sigma)
                }
            };
            let p = checks
                .iter()
                .map(|(_, _, (lo, hi), o)| outside_normal(nominal[*o], sigma(*o), *lo, *hi))
                .collect();
            (u, p)
        }
        Method::MonteCarlo { samples, seed } => {
            let (u, all) = montecarlo::run(&body, nominal, (samples, seed));
            if all.is_empty() {
                return Err(crate::diag::Diagnostic::plain(format!(
                    "{}: every one of the {samples} Monte Carlo samples was left out: in each, a part's size, radius, density or mass was drawn to zero or below (or an inner radius past its outer)",
                    source.name
                ))
                .help("are the tolerances as large as the values they are on? `--uncertainty linear` gives the first-order σ"));
            }
            let p = checks
                .iter()
                .map(|(_, _, (lo, hi), o)| {
                    let out = (0..all.len())
                        .filter(|&i| !(all.get(i, *o) >= *lo && all.get(i, *o) <= *hi))
                        .count();
                    out as f64 / all.len().max(1) as f64
                })
                .collect::<Vec<f64>>();
            (u, p)
        }
    };
    out.exceed = checks
        .iter()
        .zip(outside)
        .map(|((name, at, _, _), probability)| {
            let (line, column) = source.line_col(*at);
            Exceed {
                quantity: name.clone(),
                line,
                column,
                probability,
            }
        })
        .collect();
    out.equal_moments = summary.equal_moments.clone();
    // Never an `inf` or a NaN printed as a result.
    let finite = |outputs: &[Output], covariance: &[Vec<f64>]| {
        covariance.iter().flatten().all(|x| x.is_finite())
            && outputs
                .iter()
                .all(|o| o.sigma.is_finite() && o.mean.is_none_or(f64::is_finite))
    };
    let all_finite = finite(&out.outputs, &out.covariance)
        && out
            .predicted
            .as_ref()
            .is_none_or(|p| finite(&p.outputs, &p.covariance));
    if !all_finite {
        return Err(crate::diag::Diagnostic::plain(format!(
            "{}: the propagated uncertainty overflows the range of f64",
            source.name
        ))
        .help("are the tolerances as large as meant? (a percentage's `%` is of the value)"));
    }
    Ok(out)
}

/// P(X ∉ [lo, hi]) for X normal with mean `mu` and deviation `sigma`.
fn outside_normal(mu: f64, sigma: f64, lo: f64, hi: f64) -> f64 {
    if !(sigma > 0.0) {
        return if mu >= lo && mu <= hi { 0.0 } else { 1.0 };
    }
    // Φ(−x) = erfc(x/√2)/2 for each tail.
    let below = if lo.is_finite() {
        0.5 * erfc((mu - lo) / (sigma * std::f64::consts::SQRT_2))
    } else {
        0.0
    };
    let above = if hi.is_finite() {
        0.5 * erfc((hi - mu) / (sigma * std::f64::consts::SQRT_2))
    } else {
        0.0
    };
    (below + above).min(1.0)
}

/// The complementary error function, to a relative 1.2e-7 everywhere
/// (Chebyshev fit; Press et al., Numerical Recipes, §6.2, `erfcc`):
/// enough for a probability.
fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = -z * z - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let r = t * poly.exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

/// The outputs as `s` reports them.
fn nominal_outputs(s: &Summary) -> [f64; N] {
    let mut out = [0.0; N];
    for (info, o) in propagated() {
        let v = s
            .reported(info.quantity)
            .expect("invariant: a body reports what its σ is propagated for");
        for (n, k) in components(info.layout).into_iter().enumerate() {
            out[o + n] = v.component(k);
        }
    }
    out
}

fn top(
    shares: impl Iterator<Item = (usize, f64)>,
    labels: &dyn Fn(usize) -> String,
) -> Vec<Contributor> {
    let mut v: Vec<(usize, f64)> = shares.filter(|(_, s)| *s > 0.0).collect();
    v.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
    v.truncate(TOP);
    v.into_iter()
        .map(|(k, share)| Contributor {
            source: labels(k),
            share,
        })
        .collect()
}

/// The outputs `range` of `W` as reported: each one's σ from `cov` and
/// its three largest contributors from `share` (its source's share of
/// output o's variance `var`); Monte Carlo's mean and percentiles from
/// `stats`.
fn outputs_of(
    range: &[usize],
    nominal: &[f64; W],
    cov: &[Vec<f64>],
    share: &dyn Fn(usize, f64) -> Vec<(usize, f64)>,
    stats: &dyn Fn(usize) -> (Option<f64>, Option<[f64; 3]>),
    labels: &dyn Fn(usize) -> String,
) -> (Vec<Output>, Vec<Vec<f64>>) {
    let outputs = range
        .iter()
        .map(|&o| {
            let var = cov[o][o];
            let (mean, percentiles) = stats(o);
            Output {
                quantity: name_of(o),
                nominal: nominal[o],
                sigma: var.sqrt(),
                mean,
                percentiles,
                contributors: top(share(o, var).into_iter(), labels),
            }
        })
        .collect();
    let block = range
        .iter()
        .map(|&a| range.iter().map(|&b| cov[a][b]).collect())
        .collect();
    (outputs, block)
}

/// The basic body's outputs (its motion's among them) and, with a second
/// view, the predicted's.
fn split(
    body: &Body<'_>,
    nominal: &[f64; W],
    cov: &[Vec<f64>],
    share: &dyn Fn(usize, f64) -> Vec<(usize, f64)>,
    stats: &dyn Fn(usize) -> (Option<f64>, Option<[f64; 3]>),
    labels: &dyn Fn(usize) -> String,
) -> (Vec<Output>, Vec<Vec<f64>>, Option<Predicted>) {
    let basic: Vec<usize> = (0..N)
        .chain((motion::FIRST..W).filter(|&o| body.live(o)))
        .collect();
    let (outputs, covariance) = outputs_of(&basic, nominal, cov, share, stats, labels);
    let predicted = (body.views.len() == 2).then(|| {
        let range: Vec<usize> = (N..2 * N).collect();
        let (outputs, covariance) = outputs_of(&range, nominal, cov, share, stats, labels);
        Predicted {
            outputs,
            covariance,
        }
    });
    (outputs, covariance, predicted)
}

/// The output an `[expect]` target reads, if its σ is propagated
/// (`quantity::Info::sigma`).
pub fn output_of(t: Target) -> Option<usize> {
    let info = t.quantity.info();
    let first = info.sigma?;
    // An entry below a matrix's diagonal is the one above it.
    let k = match info.layout {
        Layout::Matrix => {
            let (a, b) = (t.component / 3, t.component % 3);
            3 * a.min(b) + a.max(b)
        }
        Layout::Scalar | Layout::Vector | Layout::Ordered | Layout::Axes => t.component,
    };
    components(info.layout)
        .iter()
        .position(|c| *c == k)
        .map(|n| first + n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_output_is_named_as_the_quantity_table_names_its_target() {
        for info in &crate::quantity::QUANTITIES {
            for k in 0..info.layout.count() {
                let t = Target {
                    quantity: info.quantity,
                    component: k,
                };
                let Some(o) = output_of(t) else { continue };
                // An entry below a matrix's diagonal is the one above it.
                let mut c: Vec<char> = crate::quantity::component(info.layout, k).chars().collect();
                let named = name_of(o);
                let (stem, last) = named.rsplit_once('.').unwrap_or((named, ""));
                let mut last: Vec<char> = last.chars().collect();
                c.sort_unstable();
                last.sort_unstable();
                assert_eq!((stem, c), (info.key, last), "output {o}");
            }
        }
    }
}
