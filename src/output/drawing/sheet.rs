//! One view of the drawing (`Sheet::view`), drawn by itself so that two
//! can be drawn at once (`write_svg`).

use super::walks::{Drawn, Last, Met, Sink, Survey, each_part, key};
use super::{ABOVE, BELOW, Outline, Rect};
use super::{Body, Cell, Options, PALETTE, frame, marker, outline, symbols, text};
use crate::model::Model;
use std::fmt::Write as _;

/// What every view is drawn from.
pub(super) struct Sheet<'a> {
    pub(super) model: &'a Model,
    pub(super) survey: &'a Survey,
    pub(super) body: &'a Body,
    pub(super) o: &'a Options,
    /// The smallest scale of the views: a part smaller than a pixel at it
    /// is not drawn in any view.
    pub(super) min_scale: f64,
}

impl Sheet<'_> {
    /// One view, into `out`: a walk of the parts (and one of the cut-outs,
    /// if any), then its symbols and frame. The parts too small to draw
    /// are counted for the `first` view only (the legend's count).
    pub(super) fn view(&self, cell: &Cell, first: bool, out: &mut Sink<'_>) -> usize {
        let Sheet {
            model,
            survey,
            body,
            o,
            min_scale,
        } = *self;
        let drawn = |size: f64| size * min_scale >= 1.0;
        let mut d = String::new();
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
        let mut seen = Drawn::default();
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
                        } else if first {
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
                        small += usize::from(first);
                    }
                    return;
                }
                last.drawn = true;
                let class = survey.keys.get(colour) % 9;
                let cut = if part.spec.removed { " cut" } else { "" };
                let outline = outline::of(part);
                element.clear();
                match &outline {
                    Outline::Marker(kind, at) => {
                        marker(
                            &mut element,
                            *kind,
                            cell.projector.point(at),
                            PALETTE[class],
                            cut,
                        );
                    }
                    Outline::Pieces(pieces) => {
                        if !drawn(outline.size()) {
                            last.drawn = false;
                            small += usize::from(first);
                            return;
                        }
                        d.clear();
                        pieces.iter().for_each(|p| cell.projector.piece(p, &mut d));
                        let _ = writeln!(element, "<path class=\"c{class}{cut}\" d=\"{d}\"/>");
                    }
                }
                seen.draw(&mut out.s, own, &element);
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
        // Its outlines forgotten before the next view's are drawn.
        drop(seen);
        out.spill(false);
        small
    }
}

#[cfg(test)]
mod tests {
    use crate::analysis::{Settings, load_source};
    use crate::diag::Source;

    /// The drawing of `text`, two views at once or one at a time.
    fn drawn(text: &str, view: Option<super::super::View>, two: bool) -> Vec<u8> {
        let loaded = load_source(Source::new("d.toml", text), &Settings::default()).expect("valid");
        let o = super::super::Options {
            view,
            title: "d".into(),
            ..Default::default()
        };
        let mut out = Vec::new();
        super::super::write_svg_on(&loaded.model, &loaded.summary, &o, &mut out, two)
            .expect("drawn");
        out
    }

    #[test]
    fn two_views_at_once_draw_the_bytes_of_one_at_a_time() {
        // Parts of every outline, one too small to draw, a cut-out and
        // coincident copies: every count the views keep.
        let text = "units = { length = \"mm\", mass = \"kg\" }\n\
            [[part]]\nshape = \"box\"\nmass = 2\nsize = [100, 50, 20]\ncenter = [0, 0, 0]\n\
            [[part]]\nshape = \"cylinder\"\nmass = 1\nradius = 20\nlength = 80\ncenter = [200, 0, 0]\nrotation = { axis = [1, 1, 0], degrees = 30 }\n\
            [[part]]\nshape = \"point\"\nmass = 0.5\ncenter = [0, 300, 0]\n\
            [[part]]\nshape = \"sphere\"\nmass = 0.01\nradius = 0.001\ncenter = [0, 0, 400]\n\
            [[part]]\nshape = \"box\"\ndensity = 1e-6\nsize = [10, 10, 10]\ncenter = [0, 0, 0]\nremove = true\n\
            [[part]]\nshape = \"box\"\nmass = 0.1\nsize = [10, 10, 10]\ncenter = [-200, 0, 0]\narray = { count = 5, step = [0, 0, 0] }\n";
        for view in [None, Some(super::super::View::Iso)] {
            let one = drawn(text, view, false);
            assert!(one.len() > 1000);
            assert_eq!(
                String::from_utf8(drawn(text, view, true)).unwrap(),
                String::from_utf8(one).unwrap()
            );
        }
    }
}
