//! The four views and how a 3-D outline is projected into one: the
//! orthographic projection onto the view's plane, scaled to pixels, and
//! each piece's silhouette written as SVG path data.
//!
//! Views, each named by what points right and up on the page, the viewer
//! on the side the third axis points to (right-handed):
//! front: x right, z up (seen from −y); top: x right, y up (from +z);
//! side: y right, z up (from +x); iso: from (1, −1, 1), right (1, 1, 0)/√2,
//! up (−1, 1, 2)/√6.

use super::outline::{Piece, V3};
use std::fmt::Write as _;

/// A view of the body (`--view`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum View {
    Front,
    Top,
    Side,
    Iso,
}

impl View {
    /// The four, in the order they are drawn.
    pub const ALL: [View; 4] = [View::Top, View::Iso, View::Front, View::Side];

    pub fn name(self) -> &'static str {
        match self {
            View::Front => "front",
            View::Top => "top",
            View::Side => "side",
            View::Iso => "iso",
        }
    }

    /// Its label: the name and the axes.
    pub fn label(self) -> &'static str {
        match self {
            View::Front => "front: x right, z up",
            View::Top => "top: x right, y up",
            View::Side => "side: y right, z up",
            View::Iso => "isometric: from (1, −1, 1), z up",
        }
    }

    /// The directions that point right and up on the page, unit vectors
    /// in the file's frame.
    pub fn plane(self) -> [V3; 2] {
        let (s2, s6) = (0.5f64.sqrt(), (1.0f64 / 6.0).sqrt());
        match self {
            View::Front => [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
            View::Top => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            View::Side => [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            View::Iso => [[s2, s2, 0.0], [-s6, s6, 2.0 * s6]],
        }
    }
}

/// A view placed on the page: page x = `at`ₓ + scale (right·p), page y =
/// `at`ᵧ − scale (up·p).
#[derive(Debug, Clone, Copy)]
pub struct Projector {
    pub plane: [V3; 2],
    /// Pixels per file length unit.
    pub scale: f64,
    /// Where the file's origin goes on the page.
    pub at: [f64; 2],
}

type P2 = [f64; 2];

impl Projector {
    /// A point's place on the page.
    pub fn point(&self, p: &V3) -> P2 {
        let [r, u] = self.plane;
        [
            self.at[0] + self.scale * dot(&r, p),
            self.at[1] - self.scale * dot(&u, p),
        ]
    }

    /// A vector's image on the page (pixels; y down).
    pub fn vector(&self, v: &V3) -> P2 {
        let [r, u] = self.plane;
        [self.scale * dot(&r, v), -self.scale * dot(&u, v)]
    }

    /// Path data of a piece's silhouette, appended to `d`.
    pub fn piece(&self, piece: &Piece, d: &mut String) {
        match piece {
            Piece::Line { points, closed } => {
                // As `polyline` writes them, without a buffer.
                for (k, p) in points.iter().enumerate() {
                    d.push(if k == 0 { 'M' } else { 'L' });
                    pair(d, self.point(p));
                }
                if *closed && points.len() > 2 {
                    d.push('Z');
                }
            }
            Piece::Hull(points) => {
                let pts: Vec<P2> = points.iter().map(|p| self.point(p)).collect();
                polyline(d, &hull(pts), true);
            }
            Piece::Ellipsoid { c, m } => {
                ellipse(d, self.point(c), &m.map(|col| self.vector(&col)));
            }
            Piece::Side { c, r, u, v } => self.side(d, c, r, u, v),
            Piece::Dome { c, r, u, v, z } => {
                // The rim's ellipse, and the half of the sphere's outline
                // circle on the dome's side: its outline is their hull.
                let (p, rp) = (self.point(c), r * self.scale);
                let (pu, pv, pz) = (self.vector(u), self.vector(v), self.vector(z));
                let n = samples(rp);
                let mut pts: Vec<P2> = (0..n)
                    .map(|k| {
                        let t = std::f64::consts::TAU * k as f64 / n as f64;
                        let (s, co) = t.sin_cos();
                        [
                            p[0] + r * (pu[0] * co + pv[0] * s),
                            p[1] + r * (pu[1] * co + pv[1] * s),
                        ]
                    })
                    .collect();
                let zl = (pz[0] * pz[0] + pz[1] * pz[1]).sqrt();
                pts.extend((0..n).filter_map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n as f64;
                    let w = [t.cos(), t.sin()];
                    (zl == 0.0 || w[0] * pz[0] + w[1] * pz[1] >= 0.0)
                        .then(|| [p[0] + rp * w[0], p[1] + rp * w[1]])
                }));
                polyline(d, &hull(pts), true);
            }
            Piece::Torus { c, r, a, u, v } => self.torus(d, c, *r, *a, u, v),
            Piece::Silhouette { points, faces } => self.silhouette(d, points, faces),
        }
    }

    /// A triangle mesh's silhouette in this view: each edge between a
    /// triangle that faces the viewer and one that does not (the exact
    /// outline of an orthographic projection, inner folds included), and
    /// each edge of one triangle only (a shell's rim), in face order.
    fn silhouette(&self, d: &mut String, points: &[V3], faces: &[[u32; 3]]) {
        let [r, u] = self.plane;
        let toward = [
            r[1] * u[2] - r[2] * u[1],
            r[2] * u[0] - r[0] * u[2],
            r[0] * u[1] - r[1] * u[0],
        ];
        let facing = |f: &[u32; 3]| {
            let [a, b, c] = f.map(|i| points[i as usize]);
            let (e, g) = (
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            let n = [
                e[1] * g[2] - e[2] * g[1],
                e[2] * g[0] - e[0] * g[2],
                e[0] * g[1] - e[1] * g[0],
            ];
            dot(&n, &toward) > 0.0
        };
        let key = |a: u32, b: u32| (a.min(b), a.max(b));
        let mut first: std::collections::HashMap<(u32, u32), bool> =
            std::collections::HashMap::with_capacity(faces.len() * 3 / 2);
        let mut edges: Vec<(u32, u32)> = Vec::new();
        for f in faces {
            let side = facing(f);
            for e in 0..3 {
                let k = key(f[e], f[(e + 1) % 3]);
                match first.remove(&k) {
                    Some(other) if other != side => edges.push(k),
                    Some(_) => {}
                    None => {
                        first.insert(k, side);
                    }
                }
            }
        }
        // The edges of one triangle only, in face order (a map's order is
        // not the same on every run).
        for f in faces {
            for e in 0..3 {
                let k = key(f[e], f[(e + 1) % 3]);
                if first.remove(&k).is_some() {
                    edges.push(k);
                }
            }
        }
        for (a, b) in edges {
            let pts = [
                self.point(&points[a as usize]),
                self.point(&points[b as usize]),
            ];
            polyline(d, &pts, false);
        }
    }

    /// The two lines tangent to a frustum's (or cylinder's) rims, on the
    /// page.
    ///
    /// NOTE: the rims are images of one circle, so a linear map takes both
    /// to circles (radii r₀, r₁ about q₀, q₁); there the tangents touch
    /// at qₖ + rₖ n for the unit n with n·(q₁ − q₀) = r₀ − r₁, and the map
    /// back keeps them tangent. A rim seen edge-on is a segment: the side
    /// is then the quadrilateral of the segments' ends.
    fn side(&self, d: &mut String, c: &[V3; 2], r: &[f64; 2], u: &V3, v: &V3) {
        let p = c.map(|c| self.point(&c));
        let (mu, mv) = (self.vector(u), self.vector(v));
        let det = mu[0] * mv[1] - mu[1] * mv[0];
        let norm2 = mu[0] * mu[0] + mu[1] * mu[1] + mv[0] * mv[0] + mv[1] * mv[1];
        let at = |k: usize, n: P2| {
            [
                p[k][0] + r[k] * (mu[0] * n[0] + mv[0] * n[1]),
                p[k][1] + r[k] * (mu[1] * n[0] + mv[1] * n[1]),
            ]
        };
        if det.abs() <= 1e-9 * norm2 {
            // Edge-on: the rim is the segment ±s, s the longer column.
            let s = if mu[0].hypot(mu[1]) >= mv[0].hypot(mv[1]) {
                [1.0, 0.0]
            } else {
                [0.0, 1.0]
            };
            let m = [-s[0], -s[1]];
            polyline(d, &[at(0, s), at(1, s), at(1, m), at(0, m)], true);
            return;
        }
        // q = M⁻¹ p, M = [mu mv].
        let inv = |x: P2| {
            [
                (mv[1] * x[0] - mv[0] * x[1]) / det,
                (-mu[1] * x[0] + mu[0] * x[1]) / det,
            ]
        };
        let (q0, q1) = (inv(p[0]), inv(p[1]));
        let dq = [q1[0] - q0[0], q1[1] - q0[1]];
        let dist = dq[0].hypot(dq[1]);
        if dist <= (r[0] - r[1]).abs() {
            return; // one rim holds the other: seen along the axis.
        }
        let cos = (r[0] - r[1]) / dist;
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let e = [dq[0] / dist, dq[1] / dist];
        for sign in [1.0, -1.0] {
            let n = [
                cos * e[0] - sign * sin * e[1],
                cos * e[1] + sign * sin * e[0],
            ];
            polyline(d, &[at(0, n), at(1, n)], false);
        }
    }

    /// A torus's outline: the tube is a ball swept along its centre
    /// line, and a ball projects to a disc, so the outline is the centre
    /// line's ellipse widened by the tube's radius: outside, for each
    /// direction n, the ellipse's farthest point that way plus a n (the
    /// support point: exact where the ellipse is flat, seen edge-on);
    /// inside, minus a n, only where that bounds a hole (no cusps: the
    /// ellipse's least radius of curvature, b²/a, above the tube's).
    fn torus(&self, d: &mut String, c: &V3, r: f64, a: f64, u: &V3, v: &V3) {
        let p = self.point(c);
        let cols = [self.vector(u), self.vector(v), [0.0; 2]].map(|m| [r * m[0], r * m[1]]);
        let ap = a * self.scale;
        let [(big, _), (small, _)] = semi_axes(&cols);
        let (s00, s01, s11) = cols.iter().fold((0.0, 0.0, 0.0), |acc, m| {
            (
                acc.0 + m[0] * m[0],
                acc.1 + m[0] * m[1],
                acc.2 + m[1] * m[1],
            )
        });
        let n = samples(big + ap);
        let curve = |d: &mut String, off: f64| {
            let pts: Vec<P2> = (0..n)
                .filter_map(|k| {
                    let t = std::f64::consts::TAU * (k as f64 + 0.5) / n as f64;
                    let n = [t.cos(), t.sin()];
                    let sn = [s00 * n[0] + s01 * n[1], s01 * n[0] + s11 * n[1]];
                    let h = (n[0] * sn[0] + n[1] * sn[1]).max(0.0).sqrt();
                    let e = if h > 1e-12 * big * big.max(1.0) {
                        [sn[0] / h, sn[1] / h]
                    } else if off > 0.0 {
                        [0.0, 0.0]
                    } else {
                        return None;
                    };
                    Some([p[0] + e[0] + off * n[0], p[1] + e[1] + off * n[1]])
                })
                .collect();
            polyline(d, &pts, true);
        };
        curve(d, ap);
        if small > 1e-9 * big && small * small / big > ap {
            curve(d, -ap);
        }
    }
}

/// Points on a sampled curve (a dome, a torus) of radius up to `r` px:
/// chords within a quarter pixel of the arc (r (1 − cos(π/n)) ≤ ¼), at
/// least 12 and at most 120 (every 3°). A small part stays a few bytes:
/// a 100,000-part drawing holds many.
fn samples(r: f64) -> usize {
    if !(r > 0.25) {
        return 12;
    }
    let n = (std::f64::consts::PI / (1.0 - 0.25 / r).acos()).ceil();
    (n as usize).clamp(12, 120)
}

fn dot(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The semi-axes of the ellipse {Σ cᵢ uᵢ : |u| ≤ 1} of the columns `c`,
/// longer first, each with its direction: from the eigen-decomposition of
/// S = Σ cᵢ cᵢᵀ.
pub fn semi_axes(c: &[P2; 3]) -> [(f64, P2); 2] {
    let (mut a, mut b, mut d) = (0.0, 0.0, 0.0);
    for v in c {
        a += v[0] * v[0];
        b += v[0] * v[1];
        d += v[1] * v[1];
    }
    let mean = (a + d) / 2.0;
    let root = ((a - d) / 2.0).hypot(b);
    let theta = 0.5 * (2.0 * b).atan2(a - d);
    let dir = [theta.cos(), theta.sin()];
    [
        ((mean + root).max(0.0).sqrt(), dir),
        ((mean - root).max(0.0).sqrt(), [-dir[1], dir[0]]),
    ]
}

/// An ellipse about `p`, its conjugate radii the columns `c` (pixels), as
/// two half arcs (a flat one, rᵧ = 0, is drawn by SVG as a line).
fn ellipse(d: &mut String, p: P2, c: &[P2; 3]) {
    let [(ra, dir), (rb, _)] = semi_axes(c);
    let deg = dir[1].atan2(dir[0]).to_degrees();
    let a = [p[0] + ra * dir[0], p[1] + ra * dir[1]];
    let b = [p[0] - ra * dir[0], p[1] - ra * dir[1]];
    d.push('M');
    pair(d, a);
    for end in [b, a] {
        d.push('A');
        num(d, ra);
        d.push(' ');
        num(d, rb);
        d.push(' ');
        num(d, deg);
        d.push_str(" 0 1 ");
        pair(d, end);
    }
    d.push('Z');
}

/// `M x y L x y …` (and `Z` if closed).
fn polyline(d: &mut String, pts: &[P2], closed: bool) {
    for (k, p) in pts.iter().enumerate() {
        d.push(if k == 0 { 'M' } else { 'L' });
        pair(d, *p);
    }
    if closed && pts.len() > 2 {
        d.push('Z');
    }
}

/// `x y`, as `num` writes each.
pub fn pair(d: &mut String, p: P2) {
    num(d, p[0]);
    d.push(' ');
    num(d, p[1]);
}

/// A number of the drawing: two decimals, no negative zero.
///
/// NOTE: written from the integer k = round(100 x) itself, its last two
/// digits after the point (issue 33, item 4: `{:.2}`'s exact float
/// formatting was a tenth of `render`'s time): the same text, since the
/// number `{:.2}` would print is the double nearest k/100, which is
/// within far less than 0.005 of k/100 while |k| < 2⁵³, so it prints as
/// k/100 exactly. Larger and non-finite values take `{:.2}` as before.
/// The digits are made by hand, not by `write!` (whose machinery was
/// still a quarter of `render`'s instructions), and k is rounded half
/// away from zero as `f64::round` does, without its library call: t − ⌊t⌉₀
/// (t less its truncation) is exact, so comparing it with ±½ decides.
pub fn num(d: &mut String, x: f64) {
    let t = x * 100.0;
    if t.abs() < 1e15 {
        // `as` truncates toward zero; |t| < 2⁵³ so `i as f64` is exact.
        let mut i = t as i64;
        let f = t - i as f64;
        if f >= 0.5 {
            i += 1;
        } else if f <= -0.5 {
            i -= 1;
        }
        if i.unsigned_abs() < 1_000_000_000_000_000 {
            digits(d, i);
            return;
        }
    }
    let x = t.round() / 100.0;
    let x = if x == 0.0 { 0.0 } else { x };
    write!(d, "{x:.2}").expect("invariant: writing to a String does not fail");
}

/// k/100 with two decimals (`-` before a negative k; none before zero).
fn digits(d: &mut String, k: i64) {
    if k < 0 {
        d.push('-');
    }
    let n = k.unsigned_abs();
    whole(d, n / 100);
    d.push('.');
    d.push_str(two(n % 100));
}

/// `n` in decimal, two digits at a time.
fn whole(d: &mut String, n: u64) {
    if n >= 100 {
        whole(d, n / 100);
        d.push_str(two(n % 100));
    } else if n >= 10 {
        d.push_str(two(n));
    } else {
        d.push(char::from(b'0' + n as u8));
    }
}

/// `n` < 100 as two digits.
fn two(n: u64) -> &'static str {
    const PAIRS: &str = "00010203040506070809101112131415161718192021222324252627282930313233343536373839404142434445464748495051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";
    let n = n as usize * 2;
    &PAIRS[n..n + 2]
}

/// The convex hull of points, counter-clockwise on the page from the
/// lowest-leftmost (Andrew's monotone chain); collinear points dropped.
pub fn hull(mut pts: Vec<P2>) -> Vec<P2> {
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: P2, a: P2, b: P2| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut h: Vec<P2> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = h.len();
        let it: Box<dyn Iterator<Item = &P2>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &p in it {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], p) <= 0.0 {
                h.pop();
            }
            h.push(p);
        }
        h.pop();
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hull_of_a_square_and_its_centre_is_the_square() {
        let h = hull(vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [0.5, 0.5],
            [1.0, 1.0],
            [0.0, 1.0],
        ]);
        assert_eq!(h.len(), 4);
        assert!(!h.contains(&[0.5, 0.5]));
    }

    #[test]
    fn the_hull_of_collinear_points_is_their_ends() {
        let h = hull(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]);
        assert_eq!(h, vec![[0.0, 0.0], [2.0, 2.0]]);
    }

    #[test]
    fn a_circle_seen_obliquely_keeps_its_radius_across_the_line_of_sight() {
        // A unit circle in the x–y plane seen from the front: a segment.
        let [(a, _), (b, _)] = semi_axes(&[[1.0, 0.0], [0.0, 0.0], [0.0, 0.0]]);
        assert_eq!((a, b), (1.0, 0.0));
    }

    #[test]
    fn each_view_is_right_handed_with_the_viewer_on_its_third_axis() {
        for v in View::ALL {
            let [r, u] = v.plane();
            let n = [
                r[1] * u[2] - r[2] * u[1],
                r[2] * u[0] - r[0] * u[2],
                r[0] * u[1] - r[1] * u[0],
            ];
            assert!((dot(&n, &n) - 1.0).abs() < 1e-12, "{v:?}");
            assert!(dot(&r, &u).abs() < 1e-12, "{v:?}");
        }
    }

    #[test]
    fn numbers_have_two_decimals_and_no_negative_zero() {
        let mut s = String::new();
        num(&mut s, -0.001);
        s.push(' ');
        num(&mut s, 1.005_1);
        assert_eq!(s, "0.00 1.01");
    }

    /// `num` writes what `{:.2}` of x rounded to hundredths wrote (the
    /// version before issue 33), for numbers of every size and sign,
    /// halves and near-halves, and the non-finite.
    #[test]
    fn num_writes_what_the_float_formatting_wrote() {
        let old = |x: f64| {
            let x = (x * 100.0).round() / 100.0;
            let x = if x == 0.0 { 0.0 } else { x };
            format!("{x:.2}")
        };
        let mut v = vec![
            0.0,
            -0.0,
            0.004,
            -0.004,
            0.005,
            -0.005,
            0.015,
            1.005,
            -2.675,
            99.995,
            1e12 + 0.125,
            -7e12 - 0.375,
            9.99e12,
            1e13,
            3e14,
            -1e16,
            1e300,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
        ];
        // Multiples of 0.005: x·100 lands on or beside a half.
        v.extend((-4000..4000).map(|j| f64::from(j) * 0.005));
        v.extend((-4000..4000).map(|j| f64::from(j) * 0.005 + 1e6));
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for k in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let u = (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            v.push(u * 10f64.powi(k % 16));
        }
        for x in v {
            let mut d = String::new();
            num(&mut d, x);
            assert_eq!(d, old(x), "{x:e}");
        }
    }
}
