//! The drawing's legend, below the views: the file and the kind of its
//! colours, what each colour is, each symbol, and what was left out; its
//! entries flow along rows of four columns, each taking as many columns
//! as its words need (`labels::width`), so no two meet.

use super::outline::Marker;
use super::view::pair;
use super::walks::Survey;
use super::{
    AXIS_COLOURS, Body, COLUMN, ELLIPSOID_COLOUR, GRID_HEIGHT, LINE, Options, PALETTE, WIDTH,
    cg_symbol, labels, marker, text,
};
use std::fmt::Write as _;

/// The legend's lines: what the colours tell apart and what each is,
/// each symbol, and what was left out; its entries flow along rows of
/// four columns, each taking as many as its words need (a name too long
/// for the page cut to it).
pub(super) fn legend_lines(survey: &Survey, small: usize, body: &Body, o: &Options) -> Vec<Entry> {
    let seen = &survey.seen;
    let (kind, none) = survey.kind.words();
    let room = WIDTH - 20.0 - SAMPLE;
    let mut e: Vec<Entry> = survey
        .keys
        .order
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let name = name
                .as_deref()
                .map_or_else(|| none.to_string(), crate::output::format::name);
            Entry::Colour(PALETTE[k % 9], labels::fit(&name, room))
        })
        .collect();
    e.push(Entry::Cg);
    e.push(Entry::Axes);
    e.push(Entry::Ellipsoid);
    if seen.cut {
        e.push(Entry::Cut);
    }
    if seen.markers[Marker::Point as usize] {
        e.push(Entry::Marker(Marker::Point));
    }
    if seen.markers[Marker::Inertia as usize] {
        e.push(Entry::Marker(Marker::Inertia));
    }
    if o.about.is_some() {
        e.push(Entry::Text("+ ref: the reference point (`about`)".into()));
    }
    if o.omega.is_some() {
        e.push(Entry::Text("ω: the angular velocity's direction".into()));
    }
    // NOTE: a long path gives up its start, never the words after it
    // (which kind the colours are is said here alone).
    let rest = format!(
        ": lengths in {}, third-angle views, colours by {kind}",
        body.unit
    );
    let room = WIDTH - 20.0 - labels::width(&rest);
    let name = labels::fit_end(&crate::output::format::name(&o.title), room);
    let title = labels::fit(&format!("{name}{rest}"), WIDTH - 20.0);
    let mut lines = vec![Entry::Text(title)];
    let mut row = Vec::new();
    let mut col = 0;
    for entry in e {
        let need = SAMPLE + labels::width(entry.words()) + 12.0;
        let span = ((need / COLUMN).ceil() as usize).max(1);
        if col + span > 4 && !row.is_empty() {
            lines.push(Entry::Row(std::mem::take(&mut row)));
            col = 0;
        }
        row.push((col, entry));
        col += span;
    }
    if !row.is_empty() {
        lines.push(Entry::Row(row));
    }
    if small > 0 {
        let s = if small == 1 { "" } else { "s" };
        lines.push(Entry::Text(format!(
            "{small} part{s} smaller than a pixel not drawn"
        )));
    }
    lines
}

/// A legend entry's words start this far right of its sample's start.
const SAMPLE: f64 = 30.0;

/// A line of the legend, or an entry of a row (with its column).
#[derive(Clone)]
pub(super) enum Entry {
    Text(String),
    Row(Vec<(usize, Entry)>),
    Colour(&'static str, String),
    Cg,
    Axes,
    Ellipsoid,
    Cut,
    Marker(Marker),
}

impl Entry {
    /// The words beside its sample.
    fn words(&self) -> &str {
        match self {
            Entry::Text(t) | Entry::Colour(_, t) => t,
            Entry::Row(_) => "",
            Entry::Cg => "centre of mass",
            Entry::Axes => "I1 I2 I3: principal axes, k long",
            Entry::Ellipsoid => "equivalent inertia ellipsoid",
            Entry::Cut => "cut-out (remove = true)",
            Entry::Marker(Marker::Point) => "point mass",
            Entry::Marker(Marker::Inertia) => "given inertia (shape = \"inertia\")",
        }
    }
}

pub(super) fn write_legend(s: &mut String, lines: &[Entry], grid: bool) {
    s.push_str("<g id=\"legend\">\n");
    // The cells' borders: the grid's middle lines for four views.
    let _ = write!(s, "<path d=\"M0 {GRID_HEIGHT}h{WIDTH}");
    if grid {
        let _ = write!(
            s,
            "M{} 0v{GRID_HEIGHT}M0 {}h{WIDTH}",
            WIDTH / 2.0,
            GRID_HEIGHT / 2.0
        );
    }
    s.push_str("\" style=\"stroke:#ccc;stroke-width:1\"/>\n");
    for (row, line) in lines.iter().enumerate() {
        let y = GRID_HEIGHT + LINE * (row as f64 + 1.2);
        match line {
            Entry::Row(items) => {
                for (col, item) in items {
                    entry(s, [10.0 + COLUMN * *col as f64, y], item);
                }
            }
            other => entry(s, [10.0, y], other),
        }
    }
    s.push_str("</g>\n");
}

/// One legend entry, its sample 24 px wide left of its words, `at` the
/// baseline's start.
fn entry(s: &mut String, at: [f64; 2], e: &Entry) {
    let (x, y) = (at[0], at[1]);
    let mid = y - 4.0;
    let line = |s: &mut String, style: &str| {
        s.push_str("<path d=\"M");
        pair(s, [x, mid]);
        let _ = writeln!(s, "h24\" style=\"{style}\"/>");
    };
    match e {
        Entry::Text(t) => return text(s, at, t, None),
        Entry::Row(_) => return,
        Entry::Colour(c, _) => line(s, &format!("stroke:{c};stroke-width:3")),
        Entry::Cg => cg_symbol(s, [x + 12.0, mid]),
        Entry::Axes => {
            for (i, c) in AXIS_COLOURS.iter().enumerate() {
                s.push_str("<path d=\"M");
                pair(s, [x + 9.0 * i as f64, mid]);
                let _ = writeln!(s, "h7\" style=\"stroke:{c};stroke-width:2.5\"/>");
            }
        }
        Entry::Ellipsoid => line(
            s,
            &format!("stroke:{ELLIPSOID_COLOUR};stroke-width:1;stroke-dasharray:2 3"),
        ),
        Entry::Cut => line(s, "stroke:#000;stroke-width:1.2;stroke-dasharray:5 3"),
        Entry::Marker(m) => marker(s, *m, [x + 12.0, mid], "#000", ""),
    }
    text(s, [x + SAMPLE, y], e.words(), None);
}
