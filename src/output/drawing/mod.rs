//! `massprop render`'s drawing: the body's parts, its centre of mass, its
//! principal axes and its equivalent inertia ellipsoid, in three
//! orthographic views and an isometric one, as one SVG document
//! (docs/render.md).
//!
//! - `outline`: each part's outline in 3-D (the one place a shape's look
//!   is decided);
//! - `view`: the views, the projection, each piece's silhouette as path
//!   data;
//! - `walks`: what the walks keep (the survey, the document's buffer,
//!   what a view has drawn, to draw copies once, the threads the views
//!   are drawn on) and what the colours tell apart (one kind a drawing:
//!   group, else material, else shape);
//! - `labels`: each label's box and its place, clear of the centre of
//!   mass, the axis tips and the other labels;
//! - `legend`: the legend below the views;
//! - `envelope`: `--envelope`'s chart, a document of its own.
//!
//! Deterministic: numbers to two decimals in pixels, parts in file order,
//! nothing from the clock or the machine; a snapshot test pins the
//! README's images byte for byte.

pub mod envelope;
pub mod labels;
mod legend;
pub mod outline;
pub mod view;
mod walks;

use crate::analysis::summary::Summary;
use crate::model::Model;
use crate::units::Dim;
use labels::{Placer, Rect};
use legend::{legend_lines, write_legend};
use outline::{Marker, Outline, V3};
use std::fmt::Write as _;
pub use view::View;
use view::{Projector, num, pair};
pub use walks::with_threads;
use walks::{Drawn, Last, Met, Sink, Survey, each_part, key, threads};

/// What to draw besides the body.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// One view (`--view`), else all four.
    pub view: Option<View>,
    /// The reference point, file frame and length unit (`about`), if given.
    pub about: Option<V3>,
    /// ω in the file's frame (rad/s), if given.
    pub omega: Option<V3>,
    /// The title: the file's or the sub-assembly's name, or the file.
    pub title: String,
}

/// The page: 1200 px wide; four views in a 2×2 grid of 600 × 400 cells
/// (one view: one 1200 × 800 cell), the legend below.
const WIDTH: f64 = 1200.0;
const GRID_HEIGHT: f64 = 800.0;
/// Room in a cell: at each side, above (the label) and below (the scale
/// bar).
const SIDE: f64 = 30.0;
const ABOVE: f64 = 30.0;
const BELOW: f64 = 40.0;
/// The legend's lines and columns.
const LINE: f64 = 18.0;
const COLUMN: f64 = 300.0;

/// The colours of the legend's keys, in order of first appearance,
/// repeated past the ninth. Chosen farthest-first (each the sRGB colour,
/// on a grid of 17 a channel, farthest by CIEDE2000 from those before it)
/// among those at least 3:1 against white and at least ΔE00 15 from the
/// symbols' own colours (the axes, ω, the ellipsoid, black), from the
/// first (Dark2's green): the least ΔE00 between neighbours, the ninth
/// and the first included, is 27.76; between any two, 26.27 (docs/render.md,
/// tests/integration/drawing_legible.rs).
const PALETTE: [&str; 9] = [
    "#1b9e77", "#ff00aa", "#dd7700", "#225599", "#665500", "#993333", "#3399bb", "#998888",
    "#999900",
];
/// I1, I2, I3.
pub const AXIS_COLOURS: [&str; 3] = ["#e00000", "#00a000", "#0000e0"];
const ELLIPSOID_COLOUR: &str = "#444444";
const OMEGA_COLOUR: &str = "#8a2be2";
/// The centre-of-mass symbol's radius, px.
pub const CG_RADIUS: f64 = 7.0;

/// The body drawn: an SVG document, in memory (for tests; `render` writes
/// it as it is made, `write_svg`).
pub fn svg(model: &Model, summary: &Summary, o: &Options) -> String {
    let mut out = Vec::new();
    write_svg(model, summary, o, &mut out).expect("invariant: writing to memory does not fail");
    String::from_utf8(out).expect("invariant: the drawing is UTF-8")
}

/// The body drawn: an SVG document, written to `w` as it is made.
pub fn write_svg(
    model: &Model,
    summary: &Summary,
    o: &Options,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let survey = Survey::of(model);
    let body = Body::of(model, summary, o, survey.extent);
    let views: Vec<View> = o.view.map_or(View::ALL.to_vec(), |v| vec![v]);
    let cells = layout(&views, &body);
    let min_scale = cells
        .iter()
        .map(|c| c.projector.scale)
        .fold(f64::INFINITY, f64::min);
    let drawn = |size: f64| size * min_scale >= 1.0;
    // NOTE: the legend's height is the document's first line, its words
    // its last: whether a part is too small to draw is known from the
    // smallest, how many are from the first view's walk.
    let any_small = usize::from(!drawn(survey.smallest));
    let lines = legend_lines(&survey, any_small, &body, o).len();

    let height = GRID_HEIGHT + LINE * (lines as f64 + 2.0);
    let mut out = Sink {
        s: String::new(),
        w: Some(w),
        error: None,
    };
    let s = &mut out.s;
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{height}\" viewBox=\"0 0 {WIDTH} {height}\">"
    );
    s.push_str("<style>\npath{fill:none;stroke-width:1.2;stroke-linejoin:round}\n.cut{stroke-dasharray:5 3}\ntext{font-family:sans-serif;font-size:13px;fill:#000}\n");
    for (k, c) in PALETTE.iter().enumerate() {
        let _ = writeln!(s, ".c{k}{{stroke:{c}}}");
    }
    s.push_str("</style>\n");
    let _ = writeln!(
        s,
        "<rect width=\"{WIDTH}\" height=\"{height}\" fill=\"#fff\"/>"
    );
    // NOTE: a walk per view, each written straight out as it is made: a
    // view's parts held apart until the end would hold the SVG twice
    // (187 MB for 100,000 parts); a walk costs a small part of that time.
    // On two threads (issue 33, item 4), each view with an odd index is
    // drawn by a helper into a buffer while this thread writes the one
    // before it out; the buffer follows it. One view is held at a time,
    // and the document is the same, byte for byte, on any number.
    let page = Page {
        model,
        survey: &survey,
        body: &body,
        o,
        min_scale,
    };
    let two = threads(survey.parts, cells.len()) > 1;
    let mut small = 0;
    std::thread::scope(|scope| {
        for (v, pair) in cells.chunks(2).enumerate() {
            let helper = match pair {
                [_, next] if two => Some(scope.spawn(|| {
                    let mut buffer = Sink {
                        s: String::new(),
                        w: None,
                        error: None,
                    };
                    draw_view(&page, next, &mut buffer);
                    buffer.s
                })),
                _ => None,
            };
            let n = draw_view(&page, &pair[0], &mut out);
            if v == 0 {
                small = n;
            }
            match (helper, pair) {
                (Some(helper), _) => {
                    let drawn = helper
                        .join()
                        .unwrap_or_else(|e| std::panic::resume_unwind(e));
                    out.spill(true);
                    let mine = std::mem::replace(&mut out.s, drawn);
                    out.spill(true);
                    out.s = mine;
                }
                (None, [_, next]) => {
                    draw_view(&page, next, &mut out);
                }
                (None, _) => {}
            }
        }
    });
    let legend = legend_lines(&survey, small, &body, o);
    debug_assert_eq!(legend.len(), lines, "the legend's height was known");
    write_legend(&mut out.s, &legend, cells.len() > 1);
    out.s.push_str("</svg>\n");
    out.spill(true);
    match out.error {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// What every view is drawn from (shared by the threads).
struct Page<'a> {
    model: &'a Model,
    survey: &'a Survey,
    body: &'a Body,
    o: &'a Options,
    /// The least scale of the views: a part smaller than a pixel at it is
    /// not drawn in any.
    min_scale: f64,
}

/// One view, written into `out` as it is made: its group, its parts
/// (copies drawn once), its symbols and its words. The parts too small to
/// draw, each counted.
fn draw_view(page: &Page, cell: &Cell, out: &mut Sink) -> usize {
    let Page {
        model,
        survey,
        body,
        o,
        min_scale,
    } = *page;
    let drawn = |size: f64| size * min_scale >= 1.0;
    let mut element = String::new();
    let mut small = 0;
    // The view's placing, for tools (and the tests): pixels per
    // length unit, and where the file's origin lies on the page.
    let s = &mut out.s;
    let _ = write!(s, "<g id=\"{}\" data-scale=\"", cell.view.name());
    let _ = write!(s, "{}", cell.projector.scale);
    s.push_str("\" data-origin=\"");
    let _ = write!(s, "{} {}", cell.projector.at[0], cell.projector.at[1]);
    s.push_str("\">\n");
    let mut seen = Drawn::new(&survey.copies);
    // NOTE: cut-outs are drawn after every other part, in a second
    // walk when there are any: a hole is drawn over the parts it is
    // cut from, not hidden under them or under the parts after it.
    let passes: &[bool] = if survey.seen.cut {
        &[false, true]
    } else {
        &[false]
    };
    for &cuts in passes {
        let mut last = Last::default();
        // Whether the part met last belongs to the other walk.
        let mut other = false;
        each_part(model, &mut |met| {
            if out.error.is_some() {
                return;
            }
            let (part, group, own) = match met {
                Met::Part(part, group, own) => (part, group, own),
                // Each as a copy `last.again` finds below.
                Met::Again(n) => {
                    if other {
                        return;
                    }
                    if last.drawn {
                        seen.again += n;
                    } else {
                        small += n;
                    }
                    return;
                }
            };
            other = part.spec.removed != cuts;
            if other {
                return;
            }
            let colour = key(survey.kind, part, group);
            if last.again(own, colour, part) {
                if last.drawn {
                    seen.again += 1;
                } else {
                    small += 1;
                }
                return;
            }
            last.drawn = true;
            let class = survey.keys.get(colour) % 9;
            let cut = if part.spec.removed { " cut" } else { "" };
            let outline = outline::of(part);
            // NOTE: a part without copies is written straight into
            // the document; a copy's element is made apart first, to
            // be drawn once (`Drawn`).
            let copy = seen.has_copies(own);
            let to = if copy { &mut element } else { &mut out.s };
            match &outline {
                Outline::Marker(kind, at) => {
                    marker(to, *kind, cell.projector.point(at), PALETTE[class], cut);
                }
                Outline::Pieces(pieces) => {
                    if !drawn(outline.size()) {
                        last.drawn = false;
                        small += 1;
                        return;
                    }
                    to.push_str("<path class=\"c");
                    to.push(char::from(b'0' + class as u8));
                    to.push_str(cut);
                    to.push_str("\" d=\"");
                    pieces.iter().for_each(|p| cell.projector.piece(p, to));
                    to.push_str("\"/>\n");
                }
            }
            if copy {
                seen.draw(&mut out.s, own, &element);
                element.clear();
            }
            out.spill(false);
        });
    }
    let s = &mut out.s;
    // The symbols' labels keep to the room between the view's own
    // words above and below (`frame`).
    let [x, y] = cell.at;
    let bounds = Rect([
        x + 2.0,
        y + ABOVE,
        x + cell.size[0] - 2.0,
        y + cell.size[1] - BELOW,
    ]);
    symbols(s, &cell.projector, body, o, bounds);
    let note = frame(s, cell, model.units.length);
    if seen.again > 0 {
        // Beside the view's label.
        let n = seen.again;
        let plural = if n == 1 { "y" } else { "ies" };
        text(
            s,
            note,
            &format!("{n} coincident cop{plural} not drawn again"),
            None,
        );
    }
    s.push_str("</g>\n");
    out.spill(false);
    small
}

/// The body's figures in the file's frame and length unit.
struct Body {
    cg: V3,
    /// Principal axes (unit, file frame), each with its radius of gyration.
    axes: [(V3, f64); 3],
    /// The equivalent ellipsoid's semi-axes along `axes`.
    semi: [f64; 3],
    /// The box that holds everything drawn.
    extent: [V3; 2],
    unit: &'static str,
}

impl Body {
    /// The body's symbols and the box that holds them and `parts`.
    fn of(model: &Model, s: &Summary, o: &Options, parts: [V3; 2]) -> Body {
        let f = model.units.factor(Dim::LENGTH).value();
        let cg = s.center_of_mass.map(|x| x / f);
        // Rows of `axes` are the report axes in the file's frame.
        let to_file = |v: &[f64; 3]| -> V3 {
            std::array::from_fn(|j| (0..3).map(|k| v[k] * s.axes[k][j]).sum())
        };
        let axes = std::array::from_fn(|i| {
            (
                to_file(&s.principal_axes[i]),
                finite(s.radii_of_gyration[i] / f),
            )
        });
        // The uniform solid ellipsoid of the same mass and principal
        // moments: I_i = m/5 (a_j² + a_k²), so a_i² = 5/(2m) (I_j + I_k − I_i).
        let m = s.mass;
        let semi = std::array::from_fn(|i| {
            let [a, b, c] = [i, (i + 1) % 3, (i + 2) % 3].map(|k| s.principal_moments[k]);
            finite((5.0 / (2.0 * m) * (b + c - a)).max(0.0).sqrt() / f)
        });
        let mut extent = [cg, cg];
        let mut add = |p: V3| {
            for k in 0..3 {
                if p[k].is_finite() {
                    extent[0][k] = extent[0][k].min(p[k]);
                    extent[1][k] = extent[1][k].max(p[k]);
                }
            }
        };
        add(parts[0]);
        add(parts[1]);
        for (e, k) in &axes {
            add(std::array::from_fn(|j| cg[j] + k * e[j]));
            add(std::array::from_fn(|j| cg[j] - k * e[j]));
        }
        let [lo, hi] = Outline::Pieces(vec![ellipsoid(cg, &axes, &semi)]).extent();
        add(lo);
        add(hi);
        if let Some(p) = o.about {
            add(p);
        }
        Body {
            cg,
            axes,
            semi,
            extent,
            unit: model.units.length,
        }
    }
}

/// The equivalent ellipsoid about `cg`: semi-axes `semi` along the
/// principal axes.
fn ellipsoid(cg: V3, axes: &[(V3, f64); 3], semi: &[f64; 3]) -> outline::Piece {
    outline::Piece::Ellipsoid {
        c: cg,
        m: std::array::from_fn(|i| axes[i].0.map(|x| x * semi[i])),
    }
}

fn finite(x: f64) -> f64 {
    if x.is_finite() { x } else { 0.0 }
}

/// A view placed on the page.
struct Cell {
    view: View,
    /// Its top-left corner and size, px.
    at: [f64; 2],
    size: [f64; 2],
    projector: Projector,
}

/// Where each view goes and its scale: the orthographic views share one
/// scale, the largest at which each fits its cell; the isometric view is
/// fitted alone. Third-angle: top above front, side right of front, so
/// that x lines up between top and front and z between front and side.
fn layout(views: &[View], body: &Body) -> Vec<Cell> {
    let [lo, hi] = body.extent;
    let mid: V3 = std::array::from_fn(|k| (lo[k] + hi[k]) / 2.0);
    let mut half: V3 = std::array::from_fn(|k| (hi[k] - lo[k]) / 2.0);
    if half.iter().all(|h| *h <= 0.0) {
        half = [0.5; 3]; // a single point: one length unit across.
    }
    let single = views.len() == 1;
    let size = if single {
        [WIDTH, GRID_HEIGHT]
    } else {
        [WIDTH / 2.0, GRID_HEIGHT / 2.0]
    };
    let room = [size[0] - 2.0 * SIDE, size[1] - ABOVE - BELOW];
    // Half the width and height of the box seen in a view.
    let seen = |v: View| {
        v.plane()
            .map(|d| (0..3).map(|k| d[k].abs() * half[k]).sum::<f64>())
    };
    let fit = |v: View| {
        let [w, h] = seen(v);
        let sx = if w > 0.0 {
            room[0] / (2.0 * w)
        } else {
            f64::INFINITY
        };
        let sy = if h > 0.0 {
            room[1] / (2.0 * h)
        } else {
            f64::INFINITY
        };
        sx.min(sy)
    };
    let ortho = views
        .iter()
        .filter(|v| **v != View::Iso)
        .map(|v| fit(*v))
        .fold(f64::INFINITY, f64::min);
    views
        .iter()
        .map(|&view| {
            let pos = match (single, view) {
                (true, _) | (false, View::Top) => [0.0, 0.0],
                (false, View::Iso) => [size[0], 0.0],
                (false, View::Front) => [0.0, size[1]],
                (false, View::Side) => [size[0], size[1]],
            };
            let scale = if view == View::Iso || !ortho.is_finite() {
                fit(view)
            } else {
                ortho
            };
            let scale = if scale.is_finite() { scale } else { 1.0 };
            let [r, u] = view.plane();
            let centre = [
                pos[0] + SIDE + room[0] / 2.0,
                pos[1] + ABOVE + room[1] / 2.0,
            ];
            let dot = |a: &V3| (0..3).map(|k| a[k] * mid[k]).sum::<f64>();
            Cell {
                view,
                at: pos,
                size,
                projector: Projector {
                    plane: [r, u],
                    scale,
                    at: [centre[0] - scale * dot(&r), centre[1] + scale * dot(&u)],
                },
            }
        })
        .collect()
}

/// A point mass (a filled dot) or a given inertia (a square with its
/// diagonals), 3.5 px across its centre.
fn marker(out: &mut String, kind: Marker, p: [f64; 2], colour: &str, cut: &str) {
    let mut d = String::new();
    match kind {
        Marker::Point => {
            circle(out, p, 3.5, &format!("fill:{colour}"));
            return;
        }
        Marker::Inertia => {
            for (dx, dy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                d.push(if dx < 0.0 && dy < 0.0 { 'M' } else { 'L' });
                num(&mut d, p[0] + 4.0 * dx);
                d.push(' ');
                num(&mut d, p[1] + 4.0 * dy);
            }
            d.push('Z');
            for (a, b) in [((-1.0, -1.0), (1.0, 1.0)), ((1.0, -1.0), (-1.0, 1.0))] {
                d.push('M');
                num(&mut d, p[0] + 4.0 * a.0);
                d.push(' ');
                num(&mut d, p[1] + 4.0 * a.1);
                d.push('L');
                num(&mut d, p[0] + 4.0 * b.0);
                d.push(' ');
                num(&mut d, p[1] + 4.0 * b.1);
            }
        }
    }
    let _ = writeln!(
        out,
        "<path class=\"{}\" style=\"stroke:{colour}\" d=\"{d}\"/>",
        cut.trim()
    );
}

/// The ellipsoid, the principal axes, ω, the reference point and the
/// centre of mass (on top), in one view; their labels placed
/// (`labels::Placer`) within `bounds` clear of the centre of mass, the
/// axis tips, the reference mark, ω and one another.
fn symbols(s: &mut String, p: &Projector, body: &Body, o: &Options, bounds: Rect) {
    let mut d = String::new();
    p.piece(&ellipsoid(body.cg, &body.axes, &body.semi), &mut d);
    let _ = writeln!(
        s,
        "<path d=\"{d}\" style=\"stroke:{ELLIPSOID_COLOUR};stroke-width:1;stroke-dasharray:2 3\"/>"
    );
    let c = p.point(&body.cg);
    let tips: [[f64; 2]; 3] = std::array::from_fn(|i| {
        let (e, k) = &body.axes[i];
        p.point(&std::array::from_fn(|j| body.cg[j] + k * e[j]))
    });
    let w = o
        .omega
        .and_then(|w| omega_arrow(p, o.about.unwrap_or(body.cg), w, body));
    let q = o.about.map(|a| p.point(&a));
    let mut place = Placer::new(bounds);
    place.keep_off(c, CG_RADIUS + 2.0);
    for (tip, axis) in tips.iter().zip(&body.axes) {
        place.keep_off(*tip, 4.0);
        // An axis shorter than a pixel is seen end-on: a point.
        if axis.1 > 0.0 {
            place.avoid(c, *tip);
        }
    }
    if let Some(q) = q {
        place.keep_off(q, 8.0);
    }
    if let Some(w) = &w {
        match w.tip {
            Some(tip) => {
                place.keep_off(tip, 4.0);
                place.avoid(w.from, tip);
            }
            None => place.keep_off(w.from, 8.0),
        }
    }
    let mut label = |s: &mut String, anchor: [f64; 2], t: &str, colour: &str| {
        let (at, far) = place.place(anchor, t);
        if far {
            // A thin line from the label's nearer side to what it names.
            let r = Rect::text(at, t).0;
            s.push_str("<path d=\"M");
            pair(s, anchor);
            s.push('L');
            pair(
                s,
                [anchor[0].clamp(r[0], r[2]), anchor[1].clamp(r[1], r[3])],
            );
            let _ = writeln!(s, "\" style=\"stroke:{colour};stroke-width:0.75\"/>");
        }
        text(s, at, t, Some(colour));
    };
    for (i, tip) in tips.iter().enumerate() {
        let colour = AXIS_COLOURS[i];
        s.push_str("<path d=\"M");
        pair(s, c);
        s.push('L');
        pair(s, *tip);
        let _ = writeln!(s, "\" style=\"stroke:{colour};stroke-width:2.5\"/>");
        label(s, *tip, &format!("I{}", i + 1), colour);
    }
    if let Some(w) = &w {
        w.draw(s);
        label(s, w.tip.unwrap_or(w.from), "ω", OMEGA_COLOUR);
    }
    if let Some(q) = q {
        s.push_str("<path d=\"M");
        pair(s, [q[0] - 6.0, q[1]]);
        s.push_str("h12M");
        pair(s, [q[0], q[1] - 6.0]);
        s.push_str("v12\" style=\"stroke:#000;stroke-width:1.5\"/>\n");
        label(s, q, "ref", "#000");
    }
    cg_symbol(s, c);
}

/// The centre-of-mass symbol: a circle, its upper-right and lower-left
/// quarters filled.
fn cg_symbol(s: &mut String, c: [f64; 2]) {
    let r = CG_RADIUS;
    circle(s, c, r, "fill:#fff;stroke:#000;stroke-width:1.5");
    s.push_str("<path d=\"M");
    pair(s, c);
    // Right, then up (page y down): arcs against the clock on the page.
    let _ = write!(s, "h{r}a{r} {r} 0 0 0 -{r} -{r}ZM");
    pair(s, c);
    let _ = writeln!(
        s,
        "h-{r}a{r} {r} 0 0 0 {r} {r}Z\" style=\"fill:#000;stroke:none\"/>"
    );
}

/// ω on the page: an arrow from `from`, a third of the body's size
/// long; seen along its line (shorter than 8 px), ⊙ (toward the viewer)
/// or ⊗ at `from`.
struct Omega {
    from: [f64; 2],
    /// The arrow's tip; `None` seen along its line.
    tip: Option<[f64; 2]>,
    toward: bool,
}

fn omega_arrow(p: &Projector, from: V3, w: V3, body: &Body) -> Option<Omega> {
    let n = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    if !(n > 0.0) {
        return None;
    }
    let [lo, hi] = body.extent;
    let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let len = if size > 0.0 { size / 3.0 } else { 1.0 };
    let a = p.point(&from);
    let v = p.vector(&w.map(|x| x / n * len));
    let [r, u] = p.plane;
    let toward = (r[1] * u[2] - r[2] * u[1]) * w[0]
        + (r[2] * u[0] - r[0] * u[2]) * w[1]
        + (r[0] * u[1] - r[1] * u[0]) * w[2];
    Some(Omega {
        from: a,
        tip: (v[0].hypot(v[1]) >= 8.0).then(|| [a[0] + v[0], a[1] + v[1]]),
        toward: toward > 0.0,
    })
}

impl Omega {
    fn draw(&self, s: &mut String) {
        let a = self.from;
        let style = format!("style=\"stroke:{OMEGA_COLOUR};stroke-width:2\"");
        let Some(tip) = self.tip else {
            let ring = format!("fill:none;stroke:{OMEGA_COLOUR};stroke-width:2");
            circle(s, a, 6.0, &ring);
            if self.toward {
                circle(s, a, 2.0, &format!("fill:{OMEGA_COLOUR}"));
            } else {
                s.push_str("<path d=\"M");
                pair(s, [a[0] - 4.0, a[1] - 4.0]);
                let _ = writeln!(s, "l8 8m0 -8l-8 8\" {style}/>");
            }
            return;
        };
        let v = [tip[0] - a[0], tip[1] - a[1]];
        let l = v[0].hypot(v[1]);
        let (ux, uy) = (v[0] / l, v[1] / l);
        let head = |side: f64| {
            [
                tip[0] - 10.0 * ux + side * 4.0 * uy,
                tip[1] - 10.0 * uy - side * 4.0 * ux,
            ]
        };
        s.push_str("<path d=\"M");
        pair(s, a);
        s.push('L');
        pair(s, tip);
        s.push('M');
        pair(s, head(1.0));
        s.push('L');
        pair(s, tip);
        s.push('L');
        pair(s, head(-1.0));
        let _ = writeln!(s, "\" {style}/>");
    }
}

/// The view's label and its scale bar: a round length (1, 2 or 5 × 10ⁿ
/// file units) near a fifth of the cell. Where a note beside the label
/// may go (its baseline's start).
fn frame(s: &mut String, cell: &Cell, unit: &str) -> [f64; 2] {
    let label = cell.view.label();
    let at = [cell.at[0] + 10.0, cell.at[1] + 20.0];
    text(s, at, label, None);
    let note = [at[0] + labels::width(label) + 12.0, at[1]];
    let scale = cell.projector.scale;
    let want = cell.size[0] / 5.0 / scale;
    let ten = 10f64.powf(want.log10().floor());
    let len = [5.0, 2.0, 1.0]
        .iter()
        .map(|m| m * ten)
        .find(|l| *l <= want)
        .unwrap_or(ten);
    let px = len * scale;
    let y = cell.at[1] + cell.size[1] - 18.0;
    let x = cell.at[0] + SIDE;
    s.push_str("<path d=\"M");
    pair(s, [x, y - 4.0]);
    s.push_str("v4h");
    num(s, px);
    s.push_str("v-4\" style=\"stroke:#000;stroke-width:1.5\"/>\n");
    let label = format!("{} {unit}", crate::output::format::fmt_sig(len, 6));
    text(s, [x + px + 6.0, y + 4.0], &label, None);
    if cell.view == View::Iso {
        // Beside the bar's label, inside the view.
        text(
            s,
            [x + px + 6.0 + labels::width(&label) + 12.0, y + 4.0],
            "lengths parallel to the page: x, y, z ×0.82",
            None,
        );
    }
    note
}

/// A circle about `c` of radius `r` px, styled.
fn circle(s: &mut String, c: [f64; 2], r: f64, style: &str) {
    s.push_str("<circle cx=\"");
    num(s, c[0]);
    s.push_str("\" cy=\"");
    num(s, c[1]);
    s.push_str("\" r=\"");
    num(s, r);
    let _ = writeln!(s, "\" style=\"{style}\"/>");
}

/// Text at `at` (its baseline's start), escaped for XML.
fn text(s: &mut String, at: [f64; 2], t: &str, colour: Option<&str>) {
    s.push_str("<text x=\"");
    num(s, at[0]);
    s.push_str("\" y=\"");
    num(s, at[1]);
    s.push('"');
    if let Some(c) = colour {
        let _ = write!(s, " style=\"fill:{c}\"");
    }
    s.push('>');
    xml_text(s, t);
    s.push_str("</text>\n");
}

/// `t` as XML character data or an attribute's value: shown as text from
/// input always is (`diag::push_visible`: controls as pictures; C1,
/// bidirectional and separator characters, U+FFFE and U+FFFF as �, none of
/// which XML 1.0 allows or a reader should act on), then `&`, `<`, `>` and
/// `"` escaped. So the document is well-formed whatever a name holds.
fn xml_text(s: &mut String, t: &str) {
    let mut shown = String::new();
    let t = if crate::diag::may_hide(t) {
        crate::diag::push_visible(&mut shown, t);
        shown.as_str()
    } else {
        t
    };
    for ch in t.chars() {
        match ch {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            c => s.push(c),
        }
    }
}
