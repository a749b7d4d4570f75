//! `[envelope]`, validated: the loading envelope that the base body and
//! every case must lie in (`analysis::envelope` holds them against it).
//! `axis` names a coordinate of the centre of mass in the report axes;
//! `points` are `[coordinate, mass]` corners of a simple polygon in the
//! file's units (or with units); `mac` gives the mean aerodynamic chord,
//! to show the coordinate in % MAC; `sequences` name cases joined by paths
//! (the case names are checked where the cases are known).

use super::ctx::Ctx;
use super::raw::{RawEnvelope, RawMac};
use super::tolerance::Recorder;
use crate::diag::Diagnostic;
use crate::units::Dim;
use std::ops::Range;
use toml::Spanned;

/// The most corners a polygon may have: the self-intersection check
/// compares every pair of edges.
pub const MAX_POINTS: usize = 1000;

/// `[envelope]`, valid: a simple polygon of non-zero area.
#[derive(Debug, Clone, PartialEq)]
pub struct Envelope {
    /// The report axis (0, 1, 2: x, y, z).
    pub axis: usize,
    /// The corners, `[coordinate (m), mass (kg)]`, in file order; a last
    /// corner repeating the first is dropped.
    pub points: Vec<[f64; 2]>,
    /// The mean aerodynamic chord, if given.
    pub mac: Option<Mac>,
    /// Each sequence: case names, at least two, joined by paths.
    pub sequences: Vec<Vec<Spanned<String>>>,
    /// Where `[envelope]` is, for messages that have no better place.
    pub span: Range<usize>,
}

/// The mean aerodynamic chord: where it begins along the axis and its
/// length, m (length positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mac {
    pub leading_edge: f64,
    pub length: f64,
}

impl Mac {
    /// `x` (m) in percent of the chord from its leading edge.
    pub fn percent(&self, x: f64) -> f64 {
        100.0 * (x - self.leading_edge) / self.length
    }
}

const HELP: &str = "give `axis` (\"x\", \"y\" or \"z\", of the report axes) and `points`, the polygon's corners as `[coordinate, mass]` pairs, e.g. points = [[2.0, 600], [2.4, 600], [2.4, 1100], [2.1, 1100]]";

impl Ctx<'_> {
    /// `[envelope]`: each key checked, the polygon simple and not flat.
    pub(super) fn envelope(
        &self,
        rec: &Recorder,
        raw: &Spanned<RawEnvelope>,
    ) -> Result<Envelope, Diagnostic> {
        let r = raw.get_ref();
        let missing =
            |key: &str| (self.err(raw.span(), format!("`envelope` needs `{key}`"))).help(HELP);
        let axis = r.axis.as_ref().ok_or_else(|| missing("axis"))?;
        let axis = self.axis_index(
            axis,
            "the coordinate of the centre of mass, in the report axes, that the envelope bounds",
        )?;
        let points = r.points.as_ref().ok_or_else(|| missing("points"))?;
        let mut corners = Vec::new();
        let mut spans = Vec::new();
        for p in points.get_ref() {
            let [x, m] = p.get_ref().as_slice() else {
                return Err(self
                    .err(
                        p.span(),
                        format!(
                            "each of `points` must be a pair `[coordinate, mass]`, got {} values",
                            p.get_ref().len()
                        ),
                    )
                    .help(HELP));
            };
            let x = self.quantity(rec, x, "points", Dim::LENGTH)?;
            let m = self.quantity(rec, m, "points", Dim::MASS)?;
            corners.push([x, m]);
            spans.push(p.span());
        }
        // A closing corner that repeats the first, as a spreadsheet's
        // outline often has, is the same polygon.
        if corners.len() > 1 && corners.first() == corners.last() {
            corners.pop();
            spans.pop();
        }
        self.envelope_polygon(points.span(), &corners, &spans)?;
        let mac = r
            .mac
            .as_ref()
            .map(|m| self.envelope_mac(rec, m))
            .transpose()?;
        let mut sequences = Vec::new();
        for s in r.sequences.as_ref().map_or(&[][..], |s| s.get_ref()) {
            if s.get_ref().len() < 2 {
                return Err(self
                    .err(s.span(), "a sequence needs at least two case names")
                    .help("a sequence is a path between cases, e.g. sequences = [[\"ramp\", \"landing\"]]"));
            }
            sequences.push(s.get_ref().clone());
        }
        Ok(Envelope {
            axis,
            points: corners,
            mac,
            sequences,
            span: raw.span(),
        })
    }

    /// The polygon: at least three corners, no edge of zero length, no two
    /// edges crossing or touching but where adjacent ones share a corner,
    /// and an area.
    fn envelope_polygon(
        &self,
        all: Range<usize>,
        p: &[[f64; 2]],
        spans: &[Range<usize>],
    ) -> Result<(), Diagnostic> {
        let n = p.len();
        if n < 3 {
            return Err(self
                .err(
                    all,
                    format!("`points` needs at least three corners, got {n}"),
                )
                .help(HELP));
        }
        if n > MAX_POINTS {
            return Err(self
                .err(
                    all,
                    format!("`points` has {n} corners, more than the limit of {MAX_POINTS}"),
                )
                .help("an envelope's outline needs a few corners; simplify it"));
        }
        for i in 0..n {
            let j = (i + 1) % n;
            if p[i] == p[j] {
                return Err(self
                    .err(
                        spans[j].clone(),
                        format!("corner {} of `points` repeats corner {}", j + 1, i + 1),
                    )
                    .help("each edge joins two different corners; remove the repeated one"));
            }
        }
        for i in 0..n {
            for j in i + 1..n {
                let adjacent = j == i + 1 || (i == 0 && j == n - 1);
                let (a, b) = (p[i], p[(i + 1) % n]);
                let (c, d) = (p[j], p[(j + 1) % n]);
                let bad = if adjacent {
                    // Adjacent edges share one corner; they may not fold
                    // back over each other.
                    let (shared, e, f) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                    folds_back(shared, e, f)
                } else {
                    segments_meet(a, b, c, d)
                };
                if bad {
                    return Err(self
                        .err(
                            spans[j].clone(),
                            format!(
                                "`points` is not a simple polygon: the edge from corner {} to corner {} meets the edge from corner {} to corner {}",
                                i + 1,
                                (i + 1) % n + 1,
                                j + 1,
                                (j + 1) % n + 1
                            ),
                        )
                        .help("list the corners in order around the outline, with no edge crossing another"));
                }
            }
        }
        let area = area(p);
        // NOTE: the area is measured against the bounding box's: a polygon
        // whose corners all lie on one line has an area of rounding only.
        let (lo, hi) = bounds(p);
        let box_area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if !(area.is_finite() && box_area.is_finite()) {
            return Err(self
                .err(
                    all,
                    "`points` spans more than f64 can measure: its area overflows",
                )
                .help("give the envelope's corners in the file's units, within a sane range"));
        }
        if !(area.abs() > 1e-12 * box_area) {
            return Err(self
                .err(
                    all,
                    "`points` encloses no area: its corners lie on one line",
                )
                .help(HELP));
        }
        Ok(())
    }

    /// `mac`: both keys, the length positive.
    fn envelope_mac(&self, rec: &Recorder, m: &Spanned<RawMac>) -> Result<Mac, Diagnostic> {
        let r = m.get_ref();
        let missing = |key: &str| {
            self.err(m.span(), format!("`mac` needs `{key}`"))
                .help("give the mean aerodynamic chord's `leading_edge` (its place along `axis`) and its `length`")
        };
        let le = r
            .leading_edge
            .as_ref()
            .ok_or_else(|| missing("leading_edge"))?;
        let length = r.length.as_ref().ok_or_else(|| missing("length"))?;
        Ok(Mac {
            leading_edge: self.quantity(rec, le, "leading_edge", Dim::LENGTH)?,
            length: self.positive(rec, length, "length", Dim::LENGTH)?,
        })
    }
}

impl super::Model {
    /// The file's own value (its `[params]`, after `--set`) of each of
    /// `names`, `None` for a name it does not define: where a path
    /// between two cases moves a parameter only one of them gives, it
    /// moves from that value to the file's.
    pub fn file_params(
        source: &crate::diag::Source,
        includes: &super::Includes,
        names: &[String],
    ) -> Result<Vec<Option<crate::expr::Value>>, Diagnostic> {
        let raw = super::Model::raw(source)?;
        let passed = super::params::flags(&includes.set)?;
        let (ctx, _) = super::Model::context(source, &raw, &passed, None)?;
        Ok(names.iter().map(|n| ctx.params.get(n)).collect())
    }
}

/// `sequences` against the file's cases: each name a case's, and the
/// cases each two neighbours join differ only in `params` (the same
/// `without` and `without_groups`): a path moves parameters, it cannot
/// take a part in or out halfway.
pub(super) fn check_sequences(
    source: &crate::diag::Source,
    model: &super::Model,
) -> Result<(), Diagnostic> {
    let Some(env) = &model.envelope else {
        return Ok(());
    };
    for seq in &env.sequences {
        let mut before: Option<&super::case::Case> = None;
        for name in seq {
            let shown = crate::diag::shorten(name.get_ref());
            let Some(case) = model.cases.iter().find(|c| c.name == *name.get_ref()) else {
                let d = source.error(
                    name.span(),
                    format!("`sequences` names `{shown}`, and the file has no case of that name"),
                );
                let d = match crate::units::suggest(
                    name.get_ref(),
                    model.cases.iter().map(|c| c.name.as_str()),
                ) {
                    Some(s) => d.suggest(Some(s)),
                    None if model.cases.is_empty() => {
                        d.help("a sequence joins `[[case]]`s by their `name`; the file has none")
                    }
                    None => d.help("a sequence joins `[[case]]`s by their `name`"),
                };
                return Err(d);
            };
            if let Some(b) = before {
                fn names(l: &[(String, Range<usize>)]) -> Vec<&str> {
                    let mut v: Vec<&str> = l.iter().map(|(s, _)| s.as_str()).collect();
                    v.sort_unstable();
                    v
                }
                let key = if names(&b.without) != names(&case.without) {
                    Some("without")
                } else if names(&b.without_groups) != names(&case.without_groups) {
                    Some("without_groups")
                } else {
                    None
                };
                if let Some(key) = key {
                    return Err(source
                        .error(
                            name.span(),
                            format!(
                                "`sequences`: cases `{}` and `{shown}` differ in `{key}`, so no path joins them",
                                crate::diag::shorten(&b.name)
                            ),
                        )
                        .help("a path moves parameters (fuel burned); cases that take different parts out are separate states, not points of one path"));
                }
            }
            before = Some(case);
        }
    }
    Ok(())
}

/// The signed area (shoelace), positive counter-clockwise.
pub fn area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
        / 2.0
}

/// The smallest and largest coordinate and mass.
pub fn bounds(p: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for c in p {
        for k in 0..2 {
            lo[k] = lo[k].min(c[k]);
            hi[k] = hi[k].max(c[k]);
        }
    }
    (lo, hi)
}

/// The sign of the turn a → b → c: positive counter-clockwise.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether `c`, on the line through a and b, lies within the segment ab.
fn within(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    (0..2).all(|k| a[k].min(b[k]) <= c[k] && c[k] <= a[k].max(b[k]))
}

/// Whether the closed segments ab and cd share a point.
pub fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
        && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0))
    {
        return true;
    }
    (o1 == 0.0 && within(a, b, c))
        || (o2 == 0.0 && within(a, b, d))
        || (o3 == 0.0 && within(c, d, a))
        || (o4 == 0.0 && within(c, d, b))
}

/// Whether the edges `shared`–`e` and `shared`–`f` overlap beyond the
/// corner they share (the outline doubles back on itself).
fn folds_back(shared: [f64; 2], e: [f64; 2], f: [f64; 2]) -> bool {
    let u = [e[0] - shared[0], e[1] - shared[1]];
    let v = [f[0] - shared[0], f[1] - shared[1]];
    orient(shared, e, f) == 0.0 && u[0] * v[0] + u[1] * v[1] > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_unit_square_counter_clockwise_has_area_one() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(area(&sq), 1.0);
    }

    #[test]
    fn the_diagonals_of_a_square_meet_and_its_opposite_sides_do_not() {
        let (a, b, c, d) = ([0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]);
        assert!(segments_meet(a, c, b, d));
        assert!(!segments_meet(a, b, c, d));
    }

    #[test]
    fn an_edge_that_doubles_back_along_the_last_folds_back() {
        assert!(folds_back([1.0, 0.0], [0.0, 0.0], [0.5, 0.0]));
        assert!(!folds_back([1.0, 0.0], [0.0, 0.0], [2.0, 0.0]));
    }
}
