//! `render --envelope`: the loading envelope's chart as one SVG document —
//! the polygon in (coordinate, mass), each case's centre of mass as a
//! ring with its name, each sequence's path, the axis in the file's length
//! unit and, when `mac` is given, a second scale in % MAC below it.
//!
//! The chart states its placing as the views do: `<g id="envelope"
//! data-scale="SX SY" data-origin="OX OY">`, a point (x, m) in the file's
//! units lying at page (OX + SX x, OY − SY m). A ring is not filled: the
//! pixel at its centre shows the envelope's fill inside and the page's
//! white outside (the render tests read it).

use super::view::num;
use super::xml_text;
use crate::analysis::envelope::Placed;
use crate::model::envelope::{Envelope, bounds};
use crate::output::format::DisplayUnits;
use std::fmt::Write as _;

/// The page and the plot's box in it, px.
const WIDTH: f64 = 900.0;
const HEIGHT: f64 = 640.0;
const LEFT: f64 = 100.0;
const RIGHT: f64 = WIDTH - 40.0;
const TOP: f64 = 60.0;
const BOTTOM: f64 = HEIGHT - 130.0;
/// The envelope's fill and outline, the rings of points inside and
/// outside, the paths.
pub const FILL: &str = "#dde8f4";
const OUTLINE: &str = "#225599";
const INSIDE: &str = "#000000";
const OUTSIDE: &str = "#e00000";
const PATH: &str = "#dd7700";
/// A ring's radius, px.
pub const RING: f64 = 5.0;

/// What the chart shows.
#[derive(Debug, Clone)]
pub struct Chart<'a> {
    pub title: &'a str,
    pub envelope: &'a Envelope,
    pub units: DisplayUnits,
    /// Each point: its label (`base` or the case's name) and its place.
    pub points: Vec<(String, Placed)>,
    /// Each path: its label and its points, (coordinate m, mass kg).
    pub paths: Vec<(String, Vec<(f64, f64)>)>,
}

/// The chart as an SVG document.
pub fn svg(c: &Chart<'_>) -> String {
    let u = &c.units;
    // Everything drawn, in the file's units, for the ranges.
    let mut xs: Vec<f64> = Vec::new();
    let mut ms: Vec<f64> = Vec::new();
    let (lo, hi) = bounds(&c.envelope.points);
    xs.extend([lo[0] / u.length, hi[0] / u.length]);
    ms.extend([lo[1] / u.mass, hi[1] / u.mass]);
    for (_, p) in &c.points {
        xs.push(p.coordinate / u.length);
        ms.push(p.mass / u.mass);
    }
    for (_, path) in &c.paths {
        for &(x, m) in path {
            xs.push(x / u.length);
            ms.push(m / u.mass);
        }
    }
    let (x0, x1) = padded(&xs);
    let (m0, m1) = padded(&ms);
    let sx = (RIGHT - LEFT) / (x1 - x0);
    let sy = (BOTTOM - TOP) / (m1 - m0);
    let (ox, oy) = (LEFT - x0 * sx, BOTTOM + m0 * sy);
    let at = |x: f64, m: f64| [ox + sx * x / u.length, oy - sy * m / u.mass];

    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{HEIGHT}\" viewBox=\"0 0 {WIDTH} {HEIGHT}\">"
    );
    s.push_str("<style>\ntext{font-family:sans-serif;font-size:13px;fill:#000}\n.tick{font-size:11px}\n</style>\n");
    let _ = writeln!(
        s,
        "<rect width=\"{WIDTH}\" height=\"{HEIGHT}\" fill=\"#fff\"/>"
    );
    super::text(&mut s, [LEFT, 30.0], c.title, None);
    let _ = writeln!(
        s,
        "<g id=\"envelope\" data-scale=\"{sx} {sy}\" data-origin=\"{ox} {oy}\">"
    );

    // The polygon.
    s.push_str("<path d=\"");
    for (i, p) in c.envelope.points.iter().enumerate() {
        s.push_str(if i == 0 { "M" } else { " L" });
        let q = at(p[0], p[1]);
        num(&mut s, q[0]);
        s.push(' ');
        num(&mut s, q[1]);
    }
    let _ = writeln!(
        s,
        " Z\" style=\"fill:{FILL};stroke:{OUTLINE};stroke-width:1.5\"/>"
    );

    // The axes: the coordinate in the file's unit, and % MAC below it.
    axes(&mut s, c, (x0, x1), (m0, m1), sx, sy);

    // The paths, then the points over them.
    for (label, path) in &c.paths {
        if path.is_empty() {
            continue;
        }
        s.push_str("<path class=\"path\" d=\"");
        for (i, &(x, m)) in path.iter().enumerate() {
            s.push_str(if i == 0 { "M" } else { " L" });
            let q = at(x, m);
            num(&mut s, q[0]);
            s.push(' ');
            num(&mut s, q[1]);
        }
        let _ = writeln!(
            s,
            "\" style=\"fill:none;stroke:{PATH};stroke-width:1.5;stroke-dasharray:6 3\"/>"
        );
        let (x, m) = path[path.len() / 2];
        let q = at(x, m);
        super::text(&mut s, [q[0] + 8.0, q[1] + 16.0], label, Some(PATH));
    }
    // NOTE: states at one place (the base and a case that gives the
    // file's own values) share a ring, their names joined.
    let mut shown: Vec<(String, Placed)> = Vec::new();
    for (label, p) in &c.points {
        match shown
            .iter_mut()
            .find(|(_, q)| q.coordinate == p.coordinate && q.mass == p.mass)
        {
            Some((l, _)) => {
                l.push_str(", ");
                l.push_str(label);
            }
            None => shown.push((label.clone(), *p)),
        }
    }
    for (label, p) in &shown {
        let q = at(p.coordinate, p.mass);
        let colour = if p.inside() { INSIDE } else { OUTSIDE };
        s.push_str("<circle class=\"case\" cx=\"");
        num(&mut s, q[0]);
        s.push_str("\" cy=\"");
        num(&mut s, q[1]);
        let _ = writeln!(
            s,
            "\" r=\"{RING}\" style=\"fill:none;stroke:{colour};stroke-width:2\"/>"
        );
        super::text(&mut s, [q[0] + 8.0, q[1] - 8.0], label, Some(colour));
    }
    s.push_str("</g>\n</svg>\n");
    s
}

/// The range of `v` with 8 % room at each side (a unit of room where
/// it is one value).
fn padded(v: &[f64]) -> (f64, f64) {
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let pad = if hi > lo {
        0.08 * (hi - lo)
    } else {
        lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// A step of 1, 2 or 5 × 10^k giving about six ticks over `span`, and
/// the decimals its labels need.
fn step(span: f64) -> (f64, usize) {
    let raw = span / 6.0;
    let k = raw.log10().floor();
    let base = 10f64.powf(k);
    let f = raw / base;
    let m = if f < 1.5 {
        1.0
    } else if f < 3.5 {
        2.0
    } else if f < 7.5 {
        5.0
    } else {
        10.0
    };
    let decimals = if k < 0.0 { (-k) as usize } else { 0 };
    (m * base, decimals.min(12))
}

/// The ticks of [lo, hi] and their labels.
fn ticks(lo: f64, hi: f64) -> Vec<(f64, String)> {
    let (st, d) = step(hi - lo);
    let first = (lo / st).ceil() as i64;
    let last = (hi / st).floor() as i64;
    (first..=last)
        .map(|k| {
            let v = k as f64 * st;
            (v, format!("{:.*}", d, if v == 0.0 { 0.0 } else { v }))
        })
        .collect()
}

/// The frame's lines, ticks and captions.
fn axes(
    s: &mut String,
    c: &Chart<'_>,
    (x0, x1): (f64, f64),
    (m0, m1): (f64, f64),
    sx: f64,
    sy: f64,
) {
    let u = &c.units;
    let line = |s: &mut String, a: [f64; 2], b: [f64; 2]| {
        s.push_str("<path d=\"M");
        num(s, a[0]);
        s.push(' ');
        num(s, a[1]);
        s.push_str(" L");
        num(s, b[0]);
        s.push(' ');
        num(s, b[1]);
        s.push_str("\" style=\"stroke:#000;stroke-width:1\"/>\n");
    };
    let tick_text = |s: &mut String, at: [f64; 2], t: &str, anchor: &str| {
        s.push_str("<text class=\"tick\" x=\"");
        num(s, at[0]);
        s.push_str("\" y=\"");
        num(s, at[1]);
        let _ = write!(s, "\" text-anchor=\"{anchor}\">");
        xml_text(s, t);
        s.push_str("</text>\n");
    };
    line(s, [LEFT, BOTTOM], [RIGHT, BOTTOM]);
    line(s, [LEFT, TOP], [LEFT, BOTTOM]);
    for (v, t) in ticks(x0, x1) {
        let px = LEFT + (v - x0) * sx;
        line(s, [px, BOTTOM], [px, BOTTOM + 5.0]);
        tick_text(s, [px, BOTTOM + 18.0], &t, "middle");
    }
    const AXES: [&str; 3] = ["x", "y", "z"];
    let caption = format!("{} ({})", AXES[c.envelope.axis], u.length_label);
    tick_text(s, [(LEFT + RIGHT) / 2.0, BOTTOM + 36.0], &caption, "middle");
    for (v, t) in ticks(m0, m1) {
        let py = BOTTOM - (v - m0) * sy;
        line(s, [LEFT - 5.0, py], [LEFT, py]);
        tick_text(s, [LEFT - 8.0, py + 4.0], &t, "end");
    }
    let caption = format!("mass ({})", u.mass_label);
    tick_text(s, [LEFT, TOP - 10.0], &caption, "middle");
    if let Some(mac) = &c.envelope.mac {
        // % MAC is affine in the coordinate: its ticks where their
        // coordinates fall.
        let y = BOTTOM + 62.0;
        line(s, [LEFT, y], [RIGHT, y]);
        let (p0, p1) = (mac.percent(x0 * u.length), mac.percent(x1 * u.length));
        for (v, t) in ticks(p0.min(p1), p0.max(p1)) {
            let x = (mac.leading_edge + v / 100.0 * mac.length) / u.length;
            let px = LEFT + (x - x0) * sx;
            line(s, [px, y], [px, y + 5.0]);
            tick_text(s, [px, y + 18.0], &t, "middle");
        }
        tick_text(s, [(LEFT + RIGHT) / 2.0, y + 36.0], "% MAC", "middle");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_span_of_ten_has_ticks_every_two() {
        assert_eq!(step(10.0).0, 2.0);
    }

    #[test]
    fn ticks_of_a_small_span_keep_their_decimals() {
        let t = ticks(0.96, 1.25);
        assert_eq!(t.first().map(|x| x.1.as_str()), Some("1.00"));
    }
}
