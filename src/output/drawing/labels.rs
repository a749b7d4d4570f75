//! Where the drawing's words go: each label's box on the page, from the
//! font size and its characters (docs/render.md, "Labels"), and a place
//! for each label near what it names where it overlaps no other label,
//! the centre-of-mass symbol or an axis tip.
//!
//! NOTE: the viewer's font is not known (`font-family:sans-serif`), so a
//! label's width is an estimate from above: each ASCII character's
//! advance (and each of the drawing's own symbols', `× − ω …`) is at
//! least DejaVu Sans's (the widest of the usual sans-serif defaults;
//! Helvetica and Arial are narrower), by class. A box that holds the
//! text in that font holds it in the others.

/// The labels' font size, px (the `<style>`'s `font-size`).
pub const FONT: f64 = 13.0;
/// A label's box reaches this far above its baseline and below it, em.
pub const ASCENT: f64 = 0.95;
pub const DESCENT: f64 = 0.25;
/// The least gap between two labels' boxes, px.
const GAP: f64 = 1.0;

/// A character's advance, em: 1 for a wide one (`m`, `w`, `M`, `W`, and
/// those East Asian scripts draw two columns wide), 0.4 for a narrow one
/// (`i`, `l`, punctuation, the space), 0.64 for the other ASCII
/// lower-case letters and digits, 0.85 for anything else (capitals,
/// symbols, other scripts); 0 for a character of no width (a combining
/// mark).
pub fn advance(c: char) -> f64 {
    use unicode_width::UnicodeWidthChar;
    match c {
        'm' | 'w' | 'M' | 'W' | '@' | '%' | '…' | '—' => 1.0,
        'i' | 'j' | 'l' | 'f' | 't' | 'I' | ' ' | '.' | ',' | ':' | ';' | '\'' | '|' | '!'
        | '(' | ')' | '[' | ']' => 0.4,
        'a'..='z' | '0'..='9' => 0.64,
        c => match c.width() {
            Some(0) => 0.0,
            Some(2) => 1.0,
            _ => 0.85,
        },
    }
}

/// `t`'s width at the labels' font size, px.
pub fn width(t: &str) -> f64 {
    FONT * t.chars().map(advance).sum::<f64>()
}

/// `t` cut to at most `room` px, an ellipsis for what is left out.
pub fn fit(t: &str, room: f64) -> String {
    if width(t) <= room {
        return t.to_string();
    }
    let mut out = String::new();
    let mut w = FONT * advance('…');
    for c in t.chars() {
        w += FONT * advance(c);
        if w > room {
            break;
        }
        out.push(c);
    }
    out.push('…');
    out
}

/// `t` cut to at most `room` px from its start, an ellipsis for what is
/// left out: the end of a long path, which names the file.
pub fn fit_end(t: &str, room: f64) -> String {
    if width(t) <= room {
        return t.to_string();
    }
    let mut kept = Vec::new();
    let mut w = FONT * advance('…');
    for c in t.chars().rev() {
        w += FONT * advance(c);
        if w > room {
            break;
        }
        kept.push(c);
    }
    std::iter::once('…').chain(kept.into_iter().rev()).collect()
}

/// A box on the page, px: left, top, right, bottom.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect(pub [f64; 4]);

impl Rect {
    /// The box of `t` written from `at` (its baseline's start).
    pub fn text(at: [f64; 2], t: &str) -> Rect {
        Rect([
            at[0],
            at[1] - ASCENT * FONT,
            at[0] + width(t),
            at[1] + DESCENT * FONT,
        ])
    }

    fn meets(&self, o: &Rect) -> bool {
        let [a, b] = [self.0, o.0];
        a[0] < b[2] + GAP && b[0] < a[2] + GAP && a[1] < b[3] + GAP && b[1] < a[3] + GAP
    }

    fn within(&self, o: &Rect) -> bool {
        let [a, b] = [self.0, o.0];
        a[0] >= b[0] && a[1] >= b[1] && a[2] <= b[2] && a[3] <= b[3]
    }

    /// The distance from `p` to the box (0 inside).
    fn distance(&self, p: [f64; 2]) -> f64 {
        let [x0, y0, x1, y1] = self.0;
        let dx = (x0 - p[0]).max(p[0] - x1).max(0.0);
        let dy = (y0 - p[1]).max(p[1] - y1).max(0.0);
        dx.hypot(dy)
    }

    /// Whether the segment from `a` to `b` crosses the box (sampled every
    /// pixel: the segments are axes and arrows a few hundred px long).
    fn crossed(&self, a: [f64; 2], b: [f64; 2]) -> bool {
        let n = ((b[0] - a[0]).hypot(b[1] - a[1]).ceil() as usize).clamp(1, 4000);
        (0..=n).any(|k| {
            let t = k as f64 / n as f64;
            self.distance([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]) <= 0.0
        })
    }
}

/// The labels of one view, placed one by one: what each must keep off
/// (discs: the centre-of-mass symbol, the axis tips, the reference mark;
/// the labels already placed) and, where it can, off lines (the axes).
pub struct Placer {
    bounds: Rect,
    taken: Vec<Rect>,
    discs: Vec<([f64; 2], f64)>,
    lines: Vec<[[f64; 2]; 2]>,
}

/// How far from its anchor a label is tried, px (the nearest first).
const RINGS: [f64; 12] = [
    4.0, 8.0, 13.0, 20.0, 28.0, 38.0, 50.0, 65.0, 85.0, 110.0, 150.0, 200.0,
];
/// Beyond this, a thin line leads from the label to its anchor.
pub const LEADER: f64 = 20.0;

impl Placer {
    /// Labels kept within `bounds`.
    pub fn new(bounds: Rect) -> Placer {
        Placer {
            bounds,
            taken: Vec::new(),
            discs: Vec::new(),
            lines: Vec::new(),
        }
    }

    /// No label within `r` px of `c`.
    pub fn keep_off(&mut self, c: [f64; 2], r: f64) {
        self.discs.push((c, r));
    }

    /// No label across the segment if it can help it.
    pub fn avoid(&mut self, a: [f64; 2], b: [f64; 2]) {
        self.lines.push([a, b]);
    }

    fn free(&self, r: &Rect) -> bool {
        r.within(&self.bounds)
            && !self.taken.iter().any(|t| t.meets(r))
            && !self.discs.iter().any(|(c, d)| r.distance(*c) <= *d)
    }

    /// Where to write `t` (its baseline's start) for the point `anchor`,
    /// and whether it is far enough to want a leader: the nearest free
    /// place around it, one clear of the lines if there is one within
    /// 20 px; up and to the right first.
    pub fn place(&mut self, anchor: [f64; 2], t: &str) -> ([f64; 2], bool) {
        let (w, h) = (width(t), (ASCENT + DESCENT) * FONT);
        // The box's centre, `rho` from the anchor toward `d` (its nearer
        // corner or side there).
        let at = |rho: f64, d: [f64; 2]| -> Rect {
            let sign = |x: f64| {
                if x > 1e-9 {
                    1.0
                } else if x < -1e-9 {
                    -1.0
                } else {
                    0.0
                }
            };
            let cx = anchor[0] + rho * d[0] + sign(d[0]) * w / 2.0;
            let cy = anchor[1] + rho * d[1] + sign(d[1]) * h / 2.0;
            Rect([cx - w / 2.0, cy - h / 2.0, cx + w / 2.0, cy + h / 2.0])
        };
        let s = std::f64::consts::FRAC_1_SQRT_2;
        // Up right, up left, down right, down left, right, left, up, down.
        let dirs = [
            [s, -s],
            [-s, -s],
            [s, s],
            [-s, s],
            [1.0, 0.0],
            [-1.0, 0.0],
            [0.0, -1.0],
            [0.0, 1.0],
        ];
        let candidates = RINGS
            .iter()
            .flat_map(|&rho| dirs.iter().map(move |&d| (rho, at(rho, d))));
        let mut first = None;
        let mut chosen = None;
        for (rho, r) in candidates {
            if !self.free(&r) {
                continue;
            }
            first.get_or_insert((rho, r));
            if rho > LEADER {
                break;
            }
            if !self.lines.iter().any(|[a, b]| r.crossed(*a, *b)) {
                chosen = Some((rho, r));
                break;
            }
        }
        let (rho, r) = match chosen.or(first) {
            Some(found) => found,
            None => self.scan(anchor, w, h),
        };
        self.taken.push(r);
        ([r.0[0], r.0[3] - DESCENT * FONT], rho > LEADER)
    }

    /// The free place nearest `anchor` on a 4 px grid over the bounds (a
    /// view crowded past every ring); the anchor's own if there is none.
    fn scan(&self, anchor: [f64; 2], w: f64, h: f64) -> (f64, Rect) {
        let [x0, y0, x1, y1] = self.bounds.0;
        let mut best: Option<(f64, Rect)> = None;
        let mut y = y0;
        while y + h <= y1 {
            let mut x = x0;
            while x + w <= x1 {
                let r = Rect([x, y, x + w, y + h]);
                let d = r.distance(anchor);
                if best.is_none_or(|(b, _)| d < b) && self.free(&r) {
                    best = Some((d, r));
                }
                x += 4.0;
            }
            y += 4.0;
        }
        best.unwrap_or((
            0.0,
            Rect([anchor[0], anchor[1] - h, anchor[0] + w, anchor[1]]),
        ))
    }

    /// A label placed elsewhere (the view's own words): kept off.
    pub fn take(&mut self, r: Rect) {
        self.taken.push(r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_too_long_keeps_its_end_within_the_room() {
        let path = format!("/{}/budget.toml", "a".repeat(300));
        let room = 200.0;
        let cut = fit_end(&path, room);
        assert!(width(&cut) <= room, "{cut}");
        assert!(
            cut.starts_with('…') && cut.ends_with("/budget.toml"),
            "{cut}"
        );
        assert_eq!(fit_end("short.toml", room), "short.toml");
    }

    #[test]
    fn a_label_keeps_off_a_disc_at_its_anchor() {
        let mut p = Placer::new(Rect([0.0, 0.0, 400.0, 400.0]));
        p.keep_off([200.0, 200.0], 9.0);
        let (at, _) = p.place([200.0, 200.0], "I3");
        assert!(Rect::text(at, "I3").distance([200.0, 200.0]) > 9.0);
    }

    #[test]
    fn two_labels_at_one_anchor_do_not_meet() {
        let mut p = Placer::new(Rect([0.0, 0.0, 400.0, 400.0]));
        let (a, _) = p.place([100.0, 100.0], "I1");
        let (b, _) = p.place([100.0, 100.0], "I2");
        assert!(!Rect::text(a, "I1").meets(&Rect::text(b, "I2")));
    }

    #[test]
    fn a_label_stays_within_its_bounds_at_a_corner() {
        let mut p = Placer::new(Rect([0.0, 0.0, 400.0, 400.0]));
        let (at, _) = p.place([399.0, 1.0], "I1");
        assert!(Rect::text(at, "I1").within(&Rect([0.0, 0.0, 400.0, 400.0])));
    }

    #[test]
    fn a_long_text_is_cut_to_its_room_with_an_ellipsis() {
        let t = fit("abcdefghijklmnopqrstuvwxyz", 100.0);
        assert!(t.ends_with('…') && width(&t) <= 100.0, "{t}");
        assert_eq!(fit("ab", 100.0), "ab");
    }
}
