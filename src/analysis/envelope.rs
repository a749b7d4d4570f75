//! The loading envelope's geometry (`[envelope]`, `model::envelope`): where
//! a body's centre of mass lies against the polygon in (coordinate, mass),
//! its margin, and whether a path between two loadings stays inside.
//!
//! The margin of a point (x, m) is measured along the axis at its mass:
//! the horizontal line through it meets the outline at some coordinates;
//! the margin is the distance to the nearest, positive inside and negative
//! outside, `None` where m is outside the polygon's range of masses (the
//! line meets nothing). A point on the outline is inside (margin 0).
//!
//! A path (`sequences`) moves each parameter linearly in t ∈ [0, 1]. Where
//! the mass m and the first moment q = m x along the axis are affine in t,
//! x = q / m traces a branch of a hyperbola, x(m) = a + b / m (a straight
//! line when b = 0), and its meeting with each edge is the root of a
//! quadratic in t, found in closed form (`crossings`): the path is then
//! checked exactly. Otherwise it is sampled (`SAMPLES`), and the bound is
//! stated: an excursion shorter than 1/`SAMPLES` of the path can pass
//! between two samples unseen. `check_path` decides which (`PROBES`).

pub mod sequences;

use crate::model::envelope::{Envelope, Mac};
use crate::units::{Dim, FileUnits};

/// Intervals of the affinity probe: the model is evaluated at t = k /
/// `PROBES`, k = 0 … `PROBES`. NOTE: a polynomial of degree ≤ 16 in t that
/// agrees with a line at 17 distinct points is that line, so the probe
/// proves affinity for any mass and moment polynomial in the parameters up
/// to degree 16 (a box whose three sides and place all move with a
/// parameter is degree 4); a parameter under a rotation angle or in a
/// denominator is not polynomial, and could in principle fool it.
pub const PROBES: usize = 16;

/// Intervals of a path that is not affine: it is sampled at t = k /
/// `SAMPLES`, k = 0 … `SAMPLES`.
pub const SAMPLES: usize = 256;

/// How far from the line through the ends a probe may lie and the path
/// still count as affine, relative to the scale of the values: rounding
/// in the model's evaluation, with room.
pub const AFFINE_RTOL: f64 = 1e-9;

/// A body's place against the envelope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placed {
    /// The envelope's report axis (0, 1, 2: x, y, z).
    pub axis: usize,
    /// The centre of mass's coordinate along the axis, m.
    pub coordinate: f64,
    /// kg.
    pub mass: f64,
    /// The signed distance along the axis to the nearest edge, m; `None`
    /// where the mass is outside the polygon's range.
    pub margin: Option<f64>,
    /// That edge (0-based: from corner i to corner i + 1).
    pub edge: Option<usize>,
    /// The coordinate in % MAC, when `mac` is given.
    pub mac: Option<f64>,
}

impl Placed {
    /// Whether the point lies inside the envelope or on its outline.
    pub fn inside(&self) -> bool {
        self.margin.is_some_and(|m| m >= 0.0)
    }
}

/// The place of a centre of mass at `coordinate` (m) of a body of `mass`
/// (kg).
pub fn place(env: &Envelope, coordinate: f64, mass: f64) -> Placed {
    let (margin, edge) = match margin(&env.points, coordinate, mass) {
        Some((d, e)) => (Some(d), Some(e)),
        None => (None, None),
    };
    Placed {
        axis: env.axis,
        coordinate,
        mass,
        margin,
        edge,
        mac: env.mac.as_ref().map(|m: &Mac| m.percent(coordinate)),
    }
}

/// The signed margin of (x, m) and the nearest edge along the axis;
/// `None` where m is outside the polygon's masses (or not finite).
pub fn margin(p: &[[f64; 2]], x: f64, m: f64) -> Option<(f64, usize)> {
    let n = p.len();
    let mut best: Option<(f64, usize)> = None;
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
        if !(lo <= m && m <= hi) {
            continue;
        }
        let d = if a[1] == b[1] {
            // A horizontal edge at this mass: the distance to its span.
            let (l, h) = (a[0].min(b[0]), a[0].max(b[0]));
            (l - x).max(x - h).max(0.0)
        } else {
            let xc = a[0] + (m - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            // NOTE: the half-open rule (one end of each edge counted) makes
            // a corner on the line count once, for the parity.
            if (a[1] <= m) != (b[1] <= m) && xc > x {
                odd = !odd;
            }
            (xc - x).abs()
        };
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, i));
        }
    }
    let (d, e) = best?;
    Some((if odd || d == 0.0 { d } else { -d }, e))
}

/// Whether (x, m) is inside the polygon or on its outline.
pub fn inside(p: &[[f64; 2]], x: f64, m: f64) -> bool {
    margin(p, x, m).is_some_and(|(d, _)| d >= 0.0)
}

/// A path whose mass and first moment along the axis are affine in t:
/// (m0, q0) at t = 0 and (m1, q1) at t = 1; kg and kg·m, masses positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine {
    pub m0: f64,
    pub q0: f64,
    pub m1: f64,
    pub q1: f64,
}

impl Affine {
    /// (coordinate, mass) at t.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let m = self.m0 + t * (self.m1 - self.m0);
        let q = self.q0 + t * (self.q1 - self.q0);
        (q / m, m)
    }
}

/// Each t in [0, 1] where the path meets an edge, with the edge, sorted.
///
/// NOTE: edge i runs from A = (xa, ma) to B; a point (x, m) is on its
/// line where p (x − xa) − r (m − ma) = 0, p = mb − ma, r = xb − xa.
/// With x = q / m and m > 0, multiply by m: p (q − xa m) − r (m − ma) m
/// = 0, a quadratic in t as m and q are affine in t.
pub fn crossings(poly: &[[f64; 2]], path: &Affine) -> Vec<(f64, usize)> {
    let (dm, dq) = (path.m1 - path.m0, path.q1 - path.q0);
    let (m0, q0) = (path.m0, path.q0);
    let n = poly.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let (p, r) = (b[1] - a[1], b[0] - a[0]);
        let qa = -r * dm * dm;
        let qb = p * (dq - a[0] * dm) - r * (2.0 * m0 - a[1]) * dm;
        let qc = p * (q0 - a[0] * m0) - r * (m0 - a[1]) * m0;
        for t in roots(qa, qb, qc) {
            if !(-1e-12..=1.0 + 1e-12).contains(&t) {
                continue;
            }
            let t = t.clamp(0.0, 1.0);
            let (x, m) = path.at(t);
            let len2 = p * p + r * r;
            let s = ((x - a[0]) * r + (m - a[1]) * p) / len2;
            if (-1e-9..=1.0 + 1e-9).contains(&s) {
                out.push((t, i));
            }
        }
    }
    out.sort_by(|u, v| u.0.total_cmp(&v.0));
    out
}

/// The real roots of a t² + b t + c = 0 (of b t + c where a is zero),
/// by the formula that does not cancel.
fn roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let scale = a.abs().max(b.abs()).max(c.abs());
    if scale == 0.0 {
        return Vec::new();
    }
    if a.abs() <= 1e-14 * scale {
        return if b == 0.0 { Vec::new() } else { vec![-c / b] };
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return Vec::new();
    }
    let s = disc.sqrt();
    let q = -0.5 * (b + b.signum() * s);
    let mut r = vec![q / a];
    if q != 0.0 {
        r.push(c / q);
    }
    r
}

/// Where a path first leaves the envelope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exit {
    /// The fraction of the path, 0 at its first case.
    pub t: f64,
    /// (coordinate, mass) there.
    pub at: (f64, f64),
    /// The edge crossed (`None` where the path starts above or below the
    /// polygon's masses).
    pub edge: Option<usize>,
}

/// A path checked: where it first leaves (if it does), its least margin
/// found, and whether it was checked exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathCheck {
    pub exit: Option<Exit>,
    /// The least margin over the path's samples (and its crossings), m;
    /// `None` when some point is outside the polygon's masses.
    pub worst: Option<f64>,
    /// Checked in closed form (affine), or sampled.
    pub exact: bool,
}

/// An affine path checked exactly: split at its crossings, each piece is
/// inside or outside as its middle is.
pub fn check_affine(poly: &[[f64; 2]], path: &Affine) -> PathCheck {
    let cuts = crossings(poly, path);
    let mut ts: Vec<(f64, Option<usize>)> = vec![(0.0, None)];
    ts.extend(cuts.iter().map(|&(t, e)| (t, Some(e))));
    ts.push((1.0, None));
    let outside = |t: f64| {
        let (x, m) = path.at(t);
        !inside(poly, x, m)
    };
    let mut exit = None;
    if outside(0.0) {
        let (x, m) = path.at(0.0);
        exit = Some(Exit {
            t: 0.0,
            at: (x, m),
            edge: margin(poly, x, m).map(|(_, e)| e),
        });
    } else {
        for w in ts.windows(2) {
            let ((t0, e0), (t1, _)) = (w[0], w[1]);
            if t1 > t0 && outside(0.5 * (t0 + t1)) {
                exit = Some(Exit {
                    t: t0,
                    at: path.at(t0),
                    edge: e0,
                });
                break;
            }
        }
        if exit.is_none() && outside(1.0) {
            let (x, m) = path.at(1.0);
            exit = Some(Exit {
                t: 1.0,
                at: (x, m),
                edge: margin(poly, x, m).map(|(_, e)| e),
            });
        }
    }
    // The least margin: at the samples, and inside each piece between
    // crossings (a piece narrower than a sample's step, such as a notch
    // passed through, has its own points).
    let samples = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64);
    let pieces = ts.windows(2).flat_map(|w| {
        let (t0, t1) = (w[0].0, w[1].0);
        (1..32).map(move |k| t0 + (t1 - t0) * f64::from(k) / 32.0)
    });
    let worst = least(poly, samples.chain(pieces).map(|t| path.at(t)));
    PathCheck {
        exit,
        worst,
        exact: true,
    }
}

/// The least margin of the points; `None` if any has none.
fn least(poly: &[[f64; 2]], points: impl Iterator<Item = (f64, f64)>) -> Option<f64> {
    let mut w = f64::INFINITY;
    for (x, m) in points {
        w = w.min(margin(poly, x, m)?.0);
    }
    Some(w)
}

/// A path checked at its samples: the first sample outside is its exit.
pub fn check_samples(poly: &[[f64; 2]], samples: &[(f64, (f64, f64))]) -> PathCheck {
    let exit = samples.iter().find_map(|&(t, (x, m))| {
        (!inside(poly, x, m)).then(|| Exit {
            t,
            at: (x, m),
            edge: margin(poly, x, m).map(|(_, e)| e),
        })
    });
    PathCheck {
        exit,
        worst: least(poly, samples.iter().map(|s| s.1)),
        exact: false,
    }
}

/// A path between two loadings: `eval(t)` gives (mass kg, first moment
/// kg·m along the axis) with the parameters at t. Probed at `PROBES` + 1
/// points; affine within `AFFINE_RTOL`, checked exactly, else sampled at
/// `SAMPLES` + 1 points.
/// Also the path's points (coordinate m, mass kg) for drawing: 65 along
/// an affine path, the samples of another.
pub fn check_path<E>(
    poly: &[[f64; 2]],
    mut eval: impl FnMut(f64) -> Result<(f64, f64), E>,
) -> Result<(PathCheck, Vec<(f64, f64)>), E> {
    let probes = (0..=PROBES)
        .map(|k| {
            let t = k as f64 / PROBES as f64;
            eval(t).map(|v| (t, v))
        })
        .collect::<Result<Vec<_>, E>>()?;
    let (m0, q0) = probes[0].1;
    let (m1, q1) = probes[PROBES].1;
    let path = Affine { m0, q0, m1, q1 };
    let scale_m = m0.abs().max(m1.abs());
    let scale_q = probes.iter().map(|p| p.1.1.abs()).fold(0.0, f64::max)
        + scale_m * poly.iter().map(|c| c[0].abs()).fold(0.0, f64::max);
    let affine = probes.iter().all(|&(t, (m, q))| {
        let lm = m0 + t * (m1 - m0);
        let lq = q0 + t * (q1 - q0);
        (m - lm).abs() <= AFFINE_RTOL * scale_m && (q - lq).abs() <= AFFINE_RTOL * scale_q
    });
    let positive = probes.iter().all(|p| p.1.0 > 0.0);
    if affine && positive {
        let curve = (0..=64).map(|k| path.at(f64::from(k) / 64.0)).collect();
        return Ok((check_affine(poly, &path), curve));
    }
    let samples = (0..=SAMPLES)
        .map(|k| {
            let t = k as f64 / SAMPLES as f64;
            eval(t).map(|(m, q)| (t, (q / m, m)))
        })
        .collect::<Result<Vec<_>, E>>()?;
    let curve = samples.iter().map(|s| s.1).collect();
    Ok((check_samples(poly, &samples), curve))
}

/// The file's units as messages show values in them: SI per unit, and
/// the symbols.
#[derive(Debug, Clone, Copy)]
pub struct Shown {
    pub length: f64,
    pub mass: f64,
    pub length_label: &'static str,
    pub mass_label: &'static str,
}

impl Shown {
    pub fn of(u: FileUnits) -> Shown {
        Shown {
            length: u.factor(Dim::LENGTH).value(),
            mass: u.factor(Dim::MASS).value(),
            length_label: u.length,
            mass_label: u.mass,
        }
    }
}

/// `x` to six significant digits, trailing zeros dropped, as the tables
/// show numbers (here, below `output`, in check's messages).
pub fn num(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{}", if x == 0.0 { 0.0 } else { x });
    }
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s.to_string()
        }
    };
    let e = x.abs().log10().floor();
    if (-5.0..15.0).contains(&e) {
        let places = (5.0 - e).max(0.0) as usize;
        trim(&format!("{x:.places$}"))
    } else {
        let s = format!("{x:.5e}");
        let (m, ex) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{}e{ex}", trim(m))
    }
}

/// An edge as a message names it: its corners, 1-based, and where they
/// are, in the file's units.
pub fn edge_name(env: &Envelope, e: usize, u: &Shown) -> String {
    let n = env.points.len();
    let corner = |i: usize| {
        let [x, m] = env.points[i];
        format!(
            "corner {} ({} {}, {} {})",
            i + 1,
            num(x / u.length),
            u.length_label,
            num(m / u.mass),
            u.mass_label
        )
    };
    format!("the edge from {} to {}", corner(e), corner((e + 1) % n))
}

/// Why a point is outside (`None` inside): `who` is `base` or the case's
/// name, as the message shows it.
pub fn point_failure(env: &Envelope, who: &str, p: &Placed, u: &Shown) -> Option<String> {
    if p.inside() {
        return None;
    }
    Some(outside(env, who, p.coordinate, p.mass, p.edge, p.margin, u))
}

/// "`who`: the centre of mass … is outside `[envelope]`, past …".
fn outside(
    env: &Envelope,
    who: &str,
    x: f64,
    m: f64,
    edge: Option<usize>,
    margin: Option<f64>,
    u: &Shown,
) -> String {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let at = format!(
        "{} = {} {} at {} {}",
        AXES[env.axis],
        num(x / u.length),
        u.length_label,
        num(m / u.mass),
        u.mass_label
    );
    match (edge, margin) {
        (Some(e), Some(d)) => format!(
            "{who}: the centre of mass {at} is outside `[envelope]`, past {}: margin {} {}",
            edge_name(env, e, u),
            num(d / u.length),
            u.length_label
        ),
        _ => {
            let (lo, hi) = crate::model::envelope::bounds(&env.points);
            format!(
                "{who}: the centre of mass {at} is outside `[envelope]`: the mass is outside its range of masses, {} to {} {} (no margin)",
                num(lo[1] / u.mass),
                num(hi[1] / u.mass),
                u.mass_label
            )
        }
    }
}

/// Why a path leaves (`None` if it stays inside): `from` and `to` are the
/// cases it joins; where it first leaves, across which edge, and the
/// least margin found on it.
pub fn path_failure(
    env: &Envelope,
    from: &str,
    to: &str,
    c: &PathCheck,
    u: &Shown,
) -> Option<String> {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let exit = c.exit?;
    let (x, m) = exit.at;
    let how = if c.exact {
        "checked exactly".to_string()
    } else {
        format!("sampled at {} points", SAMPLES + 1)
    };
    let worst = c.worst.map_or(
        "none: some of it is outside the envelope's range of masses".to_string(),
        |w| format!("{} {}", num(w / u.length), u.length_label),
    );
    let across = match exit.edge {
        Some(e) => format!(", across {}", edge_name(env, e, u)),
        None => ", outside the envelope's range of masses".to_string(),
    };
    let place = if exit.t == 0.0 {
        "starts outside `[envelope]`".to_string()
    } else {
        format!("leaves `[envelope]` {} of the way", num(exit.t))
    };
    Some(format!(
        "sequence {from} → {to}: the path {place}, at {} = {} {} and {} {}{across}; least margin on the path {worst} ({how})",
        AXES[env.axis],
        num(x / u.length),
        u.length_label,
        num(m / u.mass),
        u.mass_label,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];

    #[test]
    fn the_centre_of_a_square_has_a_margin_of_half_its_side() {
        assert_eq!(margin(&SQUARE, 1.0, 1.0), Some((1.0, 1)));
    }

    #[test]
    fn a_point_beside_a_square_has_a_negative_margin() {
        let (d, e) = margin(&SQUARE, 2.5, 1.0).unwrap();
        assert_eq!((d, e), (-0.5, 1));
    }

    #[test]
    fn a_mass_above_the_polygon_has_no_margin() {
        assert_eq!(margin(&SQUARE, 1.0, 3.0), None);
    }

    #[test]
    fn numbers_show_six_significant_digits_without_trailing_zeros() {
        assert_eq!(num(-0.10000000000000009), "-0.1");
        assert_eq!(num(2.309134615), "2.30913");
        assert_eq!(num(1100.0), "1100");
        assert_eq!(num(1.865e-14), "1.865e-14");
    }

    #[test]
    fn the_roots_of_a_quadratic_are_both_found() {
        let mut r = roots(1.0, -3.0, 2.0);
        r.sort_by(f64::total_cmp);
        assert_eq!(r, vec![1.0, 2.0]);
    }
}
