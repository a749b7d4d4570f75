//! The keys of the shapes added by issue 17: a radius given as a
//! `diameter` (cylinder, disk, sphere, cone, hemisphere), and the
//! dimensions of a cone, a torus and a prism's polygon, each validated.

use super::Ctx;
use super::ctx::{Value, Whose};
use super::raw::{Quantity, RawPart};
use super::tolerance::{Index, Recorder};
use crate::diag::Diagnostic;
use crate::numeric::{DD, Real};
use crate::thresholds::COLLINEAR_TOLERANCE;
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// The most vertices a prism's polygon may have: its edges are checked
/// for crossings pair by pair, O(n²) (500,000 pairs at this many, a few
/// milliseconds), which a longer polygon would turn into a file that takes
/// minutes to read.
pub const MAX_POLYGON_VERTICES: usize = 1000;

/// A radius as the file gives it: by a radius key, or by a diameter key
/// (halved; halving is exact).
pub(super) struct Radius<'p> {
    pub q: &'p Spanned<Quantity>,
    pub key: &'static str,
    halve: bool,
}

impl Radius<'_> {
    fn scale(&self, x: f64) -> f64 {
        if self.halve { x / 2.0 } else { x }
    }
}

/// The quantity of a radius key or of the diameter key that may replace
/// it.
fn field<'p>(p: &'p RawPart, key: &str) -> Option<&'p Spanned<Quantity>> {
    match key {
        "radius" => p.radius.as_deref(),
        "diameter" => p.diameter.as_deref(),
        "inner_radius" => p.inner_radius.as_deref(),
        "inner_diameter" => p.inner_diameter.as_deref(),
        "top_radius" => p.top_radius.as_deref(),
        "top_inner_radius" => p.top_inner_radius.as_deref(),
        "tube_radius" => p.tube_radius.as_deref(),
        "inner_tube_radius" => p.inner_tube_radius.as_deref(),
        "length" => p.length.as_deref(),
        _ => unreachable!("`{key}` is no radius key"),
    }
}

impl Ctx<'_> {
    /// The part's `radius` or `diameter` (`inner`: its `inner_radius` or
    /// `inner_diameter`), if it gives one; both is an error at the later.
    pub(super) fn radius_of<'p>(
        &self,
        p: &'p RawPart,
        inner: bool,
    ) -> Result<Option<Radius<'p>>, Diagnostic> {
        let (rk, dk) = if inner {
            ("inner_radius", "inner_diameter")
        } else {
            ("radius", "diameter")
        };
        match (field(p, rk), field(p, dk)) {
            (Some(r), Some(d)) => {
                let (span, later, earlier) = if d.span().start > r.span().start {
                    (d.span(), dk, rk)
                } else {
                    (r.span(), rk, dk)
                };
                Err(self
                    .err(
                        span,
                        format!("`{later}` conflicts with `{earlier}`: give exactly one"),
                    )
                    .help(format!("`{dk}` is twice `{rk}`")))
            }
            (Some(q), None) => Ok(Some(Radius {
                q,
                key: rk,
                halve: false,
            })),
            (None, Some(q)) => Ok(Some(Radius {
                q,
                key: dk,
                halve: true,
            })),
            (None, None) => Ok(None),
        }
    }

    /// A radius read once (halved if a diameter).
    fn radius(&self, rec: &mut Recorder, r: &Radius<'_>) -> Result<Value, Diagnostic> {
        let v = self.value(rec, r.q, r.key, Dim::LENGTH)?;
        Ok(Value {
            file: r.scale(v.file),
            si: r.scale(v.si),
        })
    }

    /// A plain radius key (no diameter form) as a `Radius`.
    fn plain<'p>(&self, p: &'p RawPart, key: &'static str) -> Option<Radius<'p>> {
        field(p, key).map(|q| Radius {
            q,
            key,
            halve: false,
        })
    }

    /// An inner radius `inner` from 0 to the outer `outer` (SI), in the
    /// file's units; `help` says what its ends mean.
    fn inner_within(
        &self,
        rec: &mut Recorder,
        inner: &Radius<'_>,
        outer_key: &str,
        outer: f64,
        help: &str,
    ) -> Result<f64, Diagnostic> {
        let v = self.radius(rec, inner)?;
        if !(v.si >= 0.0 && v.si <= outer) {
            return Err(self
                .err(
                    inner.q.span(),
                    format!("`{}` must be from 0 to `{outer_key}`", inner.key),
                )
                .help(help));
        }
        Ok(v.file)
    }

    /// `radius` (or half `diameter`), positive, and `inner_radius` (or
    /// half `inner_diameter`) from 0 to it, 0 when absent: [R, r] in the
    /// file's units.
    pub(super) fn radii(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        missing: impl FnOnce() -> Diagnostic,
    ) -> Result<[f64; 2], Diagnostic> {
        let r = self.radius_of(p, false)?.ok_or_else(missing)?;
        let outer = self.radius(rec, &r)?;
        if !(outer.si > 0.0) {
            return Err(self.err(r.q.span(), format!("`{}` must be positive", r.key)));
        }
        let inner = match self.radius_of(p, true)? {
            None => 0.0,
            Some(q) => self.inner_within(
                rec,
                &q,
                r.key,
                outer.si,
                "0 (or leaving it out) is a solid; equal to `radius`, a thin shell",
            )?,
        };
        Ok([outer.file, inner])
    }

    /// A cone's dimensions in the file's units, [R₀, a₀, R₁, a₁, L]: radii
    /// from 0, not both 0, each inner radius from 0 to its outer one, both
    /// inner radii or neither, a positive length.
    pub(super) fn cone(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<[f64; 5], Diagnostic> {
        let info = crate::shapes::Shape::Cone.info();
        let missing = |key: &str| {
            let what = if key == "top_radius" {
                "`top_radius` (0 for a full cone)".to_string()
            } else {
                format!("`{key}`")
            };
            self.err(span.clone(), format!("this cone needs {what}"))
                .help(info.help)
        };
        let base = self.radius_of(p, false)?.ok_or_else(|| missing("radius"))?;
        let top = self
            .plain(p, "top_radius")
            .ok_or_else(|| missing("top_radius"))?;
        let mut out = [0.0; 5];
        let mut si = [0.0; 2];
        for (i, r) in [(0, &base), (2, &top)] {
            let v = self.radius(rec, r)?;
            if !(v.si >= 0.0) {
                return Err(self.err(r.q.span(), format!("`{}` must not be negative", r.key)));
            }
            (out[i], si[i / 2]) = (v.file, v.si);
        }
        if si == [0.0; 2] {
            return Err(self
                .err(
                    top.q.span(),
                    "a cone needs a radius above 0 at one end at least",
                )
                .help(
                    "`radius` is the base's, `top_radius` the top's; 0 at one end is a full cone",
                ));
        }
        let help = "0 (or leaving it out) is a solid; equal to the outer, a thin shell";
        match (self.radius_of(p, true)?, self.plain(p, "top_inner_radius")) {
            (Some(a0), Some(a1)) => {
                out[1] = self.inner_within(rec, &a0, base.key, si[0], help)?;
                out[3] = self.inner_within(rec, &a1, "top_radius", si[1], help)?;
            }
            (None, None) => {}
            (Some(one), None) | (None, Some(one)) => {
                return Err(self
                    .err(one.q.span(), "a hollow cone needs both `inner_radius` (or `inner_diameter`) and `top_inner_radius`")
                    .help("its bore is a frustum of the same length: give its radius at both ends (0 at one end for a conical bore)"));
            }
        }
        let l = field(p, "length").ok_or_else(|| missing("length"))?;
        let len = self.value(rec, l, "length", Dim::LENGTH)?;
        if len.si == 0.0 {
            return Err(self
                .err(l.span(), "a cone of zero `length` is flat")
                .help("use a disk (an annulus for a hollow one)"));
        }
        if !(len.si > 0.0) {
            return Err(self.err(l.span(), "`length` must be positive"));
        }
        out[4] = len.file;
        Ok(out)
    }

    /// A torus's dimensions in the file's units, [R, a, b]: a positive
    /// `radius`, a positive `tube_radius` at most it (above it the tube
    /// would pass through the axis and overlap itself), an
    /// `inner_tube_radius` from 0 to the tube's.
    pub(super) fn torus(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<[f64; 3], Diagnostic> {
        let info = crate::shapes::Shape::Torus.info();
        let missing = |key: &str| {
            self.err(span.clone(), format!("this torus needs `{key}`"))
                .help(info.help)
        };
        let r = self.plain(p, "radius").ok_or_else(|| missing("radius"))?;
        let big = self.positive_value(rec, r.q, "radius", Dim::LENGTH)?;
        let a = self
            .plain(p, "tube_radius")
            .ok_or_else(|| missing("tube_radius"))?;
        let tube = self.positive_value(rec, a.q, "tube_radius", Dim::LENGTH)?;
        if tube.si > big.si {
            return Err(self
                .err(a.q.span(), "`tube_radius` exceeds `radius`: the torus would intersect itself")
                .help("`radius` runs from the axis to the tube's centre; the tube may at most touch the axis (`tube_radius` = `radius`)"));
        }
        let inner = match self.plain(p, "inner_tube_radius") {
            Some(b) => self.inner_within(
                rec,
                &b,
                "tube_radius",
                tube.si,
                "0 (or leaving it out) is a solid; equal to the outer, a thin shell",
            )?,
            None => 0.0,
        };
        Ok([big.file, tube.file, inner])
    }

    /// A prism's `polygon` in the file's units, checked (in SI): 3 to
    /// `MAX_POLYGON_VERTICES` vertices, no vertex twice, no two edges
    /// crossing or touching (but neighbours at their common vertex), and
    /// an area above `COLLINEAR_TOLERANCE` of the square of its extent.
    pub(super) fn polygon(
        &self,
        rec: &mut Recorder,
        p: &RawPart,
        span: Range<usize>,
    ) -> Result<Vec<[f64; 2]>, Diagnostic> {
        let info = crate::shapes::Shape::Prism.info();
        let missing = |key: &str| {
            self.err(span.clone(), format!("this prism needs `{key}`"))
                .help(info.help)
        };
        let raw = p.polygon.as_deref().ok_or_else(|| missing("polygon"))?;
        let n = raw.get_ref().len();
        if n < 3 {
            return Err(self
                .err(
                    raw.span(),
                    format!("a prism's `polygon` needs at least 3 vertices, got {n}"),
                )
                .help(info.help));
        }
        if n > MAX_POLYGON_VERTICES {
            return Err(self
                .err(raw.span(), format!("a prism's `polygon` may have at most {MAX_POLYGON_VERTICES} vertices, got {n}"))
                .help("split it into several prisms"));
        }
        let (mut file, mut v) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for (row, vertex) in raw.get_ref().iter().enumerate() {
            let c = self.exactly(vertex, 2, Whose::Key("polygon"), "components")?;
            let mut at = |component: usize| {
                let at = Index { row, component };
                self.value_at(rec, at, &c[component], "polygon", Dim::LENGTH)
            };
            let (x, y) = (at(0)?, at(1)?);
            file.push([x.file, y.file]);
            v.push([x.si, y.si]);
        }
        let at = |i: usize| raw.get_ref()[i].span();
        if let Some((i, j)) = repeated(&v) {
            return Err(self
                .err(
                    at(j),
                    format!(
                        "vertices {} and {} of `polygon` are the same point",
                        i + 1,
                        j + 1
                    ),
                )
                .help("a polygon visits each vertex once"));
        }
        if let Some((i, j)) = crossing(&v) {
            let what = if j == i + 1 || (i == 0 && j == n - 1) {
                "fold back over each other"
            } else {
                "cross or touch"
            };
            return Err(self
                .err(at(j), format!("edges {} and {} of `polygon` {what}: the polygon intersects itself", i + 1, j + 1))
                .help(format!("edge k runs from vertex k to vertex k + 1 (edge {n} back to vertex 1); a prism's polygon must be simple")));
        }
        let (lo, hi) = v.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), p| {
                (
                    [lo[0].min(p[0]), lo[1].min(p[1])],
                    [hi[0].max(p[0]), hi[1].max(p[1])],
                )
            },
        );
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let area = crate::shapes::prism::polygon(&v).area.f64();
        if !(extent.is_finite() && area.is_finite()) {
            return Err(self.err(raw.span(), "this polygon is too large for f64"));
        }
        if !(area > COLLINEAR_TOLERANCE * extent * extent && area >= f64::MIN_POSITIVE) {
            return Err(self
                .err(
                    raw.span(),
                    "this `polygon` has no area: its vertices are (nearly) collinear",
                )
                .help(format!(
                    "its area must exceed {COLLINEAR_TOLERANCE:e} of the square of its extent"
                )));
        }
        Ok(file)
    }
}

/// The first pair of equal vertices (i < j), if any.
fn repeated(v: &[[f64; 2]]) -> Option<(usize, usize)> {
    let mut order: Vec<usize> = (0..v.len()).collect();
    order.sort_by(|&a, &b| {
        v[a][0]
            .total_cmp(&v[b][0])
            .then(v[a][1].total_cmp(&v[b][1]))
    });
    order
        .windows(2)
        .filter(|w| v[w[0]] == v[w[1]])
        .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
        .min_by_key(|&(_, j)| j)
}

/// The sign of (b − a) × (c − a), in double-double from the exact
/// differences: exact but where the three points are within ~1e-30 of
/// collinear.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> i8 {
    let d = |p: [f64; 2], i: usize| DD::of(p[i]) - DD::of(a[i]);
    let x = d(b, 0) * d(c, 1) - d(b, 1) * d(c, 0);
    let z = DD::of(0.0);
    if x > z {
        1
    } else if x < z {
        -1
    } else {
        0
    }
}

/// Whether c, collinear with a and b, lies within their bounding box.
fn within(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    (0..2).all(|i| a[i].min(b[i]) <= c[i] && c[i] <= a[i].max(b[i]))
}

/// Whether the closed segments ab and cd meet.
fn meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let box_apart =
        (0..2).any(|i| a[i].max(b[i]) < c[i].min(d[i]) || c[i].max(d[i]) < a[i].min(b[i]));
    if box_apart {
        return false;
    }
    let (o1, o2, o3, o4) = (
        orient(a, b, c),
        orient(a, b, d),
        orient(c, d, a),
        orient(c, d, b),
    );
    if o1 != o2 && o3 != o4 {
        return true;
    }
    (o1 == 0 && within(a, b, c))
        || (o2 == 0 && within(a, b, d))
        || (o3 == 0 && within(c, d, a))
        || (o4 == 0 && within(c, d, b))
}

/// A pair of edges (i < j; edge k from vertex k to k + 1) that cross or
/// touch, or of neighbours that fold back over each other, if any; the
/// vertices are distinct. Neighbours first (O(n)), then the others by a
/// sweep in x: the edges sorted by their left end, each compared only with
/// those that start before it ends (O(n²) at worst, as for a comb; near
/// O(n log n) for the usual outline).
fn crossing(v: &[[f64; 2]]) -> Option<(usize, usize)> {
    let n = v.len();
    let e = |k: usize| (v[k], v[(k + 1) % n]);
    for i in 0..n {
        let (j, k) = ((i + 1) % n, (i + 2) % n);
        // Edges i and j meet at v[j]: folded back if v[k] lies on the ray
        // v[j] → v[i].
        let (a, b, d) = (v[i], v[j], v[k]);
        if orient(a, b, d) == 0
            && (a[0] - b[0]) * (d[0] - b[0]) + (a[1] - b[1]) * (d[1] - b[1]) > 0.0
        {
            return Some((i.min(j), i.max(j)));
        }
    }
    let left = |k: usize| v[k][0].min(v[(k + 1) % n][0]);
    let right = |k: usize| v[k][0].max(v[(k + 1) % n][0]);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| left(a).total_cmp(&left(b)).then(a.cmp(&b)));
    for (at, &i) in order.iter().enumerate() {
        for &j in &order[at + 1..] {
            if left(j) > right(i) {
                break;
            }
            let neighbours = (i + 1) % n == j || (j + 1) % n == i;
            if neighbours {
                continue;
            }
            let ((a, b), (c, d)) = (e(i), e(j));
            if meet(a, b, c, d) {
                return Some((i.min(j), i.max(j)));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_are_found_and_simple_polygons_pass() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(crossing(&square), None);
        let l_shape = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ];
        assert_eq!(crossing(&l_shape), None);
        let bow_tie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert_eq!(crossing(&bow_tie), Some((0, 2)));
        // A vertex touching a non-adjacent edge.
        let pinched = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 0.0], [0.0, 2.0]];
        assert!(crossing(&pinched).is_some());
        // Folding back along the previous edge.
        let folded = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
        assert_eq!(crossing(&folded), Some((0, 1)));
        assert_eq!(
            repeated(&[[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]]),
            Some((0, 2))
        );
        assert_eq!(repeated(&square), None);
    }
}
