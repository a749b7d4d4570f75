//! What the drawing's walks keep, and nothing more: the survey made
//! before anything is drawn (the legend's keys, the extent, the smallest
//! outline), the document's buffer (`Sink`: written out as it fills),
//! what one view has drawn (`Drawn`: copies drawn once), the last part
//! met (`Last`: a copy in the same place known at once), and the threads
//! the views are drawn on (`threads`).

use super::outline::{self, Outline, V3};
use crate::model::Model;
use crate::model::walk::{Event, Run};
use std::collections::{HashMap, HashSet};

/// The document as it is made: each element goes into a small buffer
/// that is handed to the writer whenever it fills, so the document is
/// never all in memory (only a copy's elements are remembered, to draw
/// them once: `Drawn`; and on two threads, the one view the helper draws
/// while the one before it is written: `w` is `None`).
pub(super) struct Sink<'w> {
    pub(super) s: String,
    /// `None`: a view drawn apart (on a thread of its own), held whole.
    pub(super) w: Option<&'w mut dyn std::io::Write>,
    /// The first write that failed: the walks that follow write nothing.
    pub(super) error: Option<std::io::Error>,
}

impl Sink<'_> {
    /// Bytes held before they are written.
    const SPILL: usize = 1 << 16;

    /// Hand the buffer to the writer once it is full (`all`: whatever it
    /// holds).
    pub(super) fn spill(&mut self, all: bool) {
        let Some(w) = &mut self.w else {
            return;
        };
        if self.s.len() < Self::SPILL && !all {
            return;
        }
        if self.error.is_none()
            && let Err(e) = w.write_all(self.s.as_bytes())
        {
            self.error = Some(e);
        }
        self.s.clear();
    }
}

/// What one view has drawn: each element's text (its path data rounded to
/// the drawing's resolution, 0.01 px) with the part it is a copy of, so
/// that a copy whose outline another copy of the same part has drawn
/// already (in the same place, or closer to it than the resolution) is
/// drawn once. Bounded by what is drawn, not by the number of copies.
///
/// NOTE: copies of one part only (an array's, a mirror's, an included
/// file's instances'): two parts written apart whose outlines meet in a
/// view (a pair of wings seen edge-on) are each drawn, as they always
/// were. So a part the walk meets once (`Copies`: most parts of a large
/// file) has nothing to be a copy of and is written at once, its text
/// neither hashed nor kept (issue 33, item 4: hashing and keeping every
/// element was a tenth of `render`'s time); only copies' elements are
/// kept, by part, in std's `HashSet` (SipHash with a key chosen at run
/// time: a file cannot be written so that its elements collide).
pub(super) struct Drawn<'c> {
    copies: &'c Copies,
    /// By part (`Leaf::own`: the same for each of its copies), the
    /// elements drawn for its copies.
    elements: HashMap<usize, HashSet<String>>,
    /// The copies not drawn again.
    pub(super) again: usize,
}

impl<'c> Drawn<'c> {
    pub(super) fn new(copies: &'c Copies) -> Self {
        Drawn {
            copies,
            elements: HashMap::new(),
            again: 0,
        }
    }

    /// Whether `part` has copies: its elements go through `draw`; else
    /// they may be written at once.
    pub(super) fn has_copies(&self, part: usize) -> bool {
        self.copies.of(part)
    }

    /// Write `element`, drawn for a copy of `part`, unless this view has
    /// drawn it for another.
    pub(super) fn draw(&mut self, s: &mut String, part: usize, element: &str) {
        let drawn = self.elements.entry(part).or_default();
        if drawn.contains(element) {
            self.again += 1;
        } else {
            s.push_str(element);
            drawn.insert(element.to_string());
        }
    }
}

/// The parts (`Leaf::own`) the walk meets more than once, sorted: the
/// only ones a view must remember what it drew for (`Drawn`). Found by
/// the survey; a run of coincident copies met as one (`Met::Again`) counts
/// once, as no view draws those.
#[derive(Default)]
pub(super) struct Copies(Vec<usize>);

impl Copies {
    pub(super) fn of(&self, part: usize) -> bool {
        !self.0.is_empty() && self.0.binary_search(&part).is_ok()
    }
}

/// `Copies` in the making: each part met, in the walk's order (`met`);
/// consecutive ones (an array's copies) kept once in `met` and noted at
/// once, so 2,000,000 copies take one entry.
#[derive(Default)]
struct Counter {
    met: Vec<usize>,
    copies: Vec<usize>,
    /// Whether the last part met is noted in `copies` already.
    noted: bool,
}

impl Counter {
    fn meet(&mut self, part: usize) {
        if self.met.last() == Some(&part) {
            if !self.noted {
                self.copies.push(part);
                self.noted = true;
            }
        } else {
            self.met.push(part);
            self.noted = false;
        }
    }

    fn done(mut self) -> Copies {
        // NOTE: a sort, not a hash of each part's address: the same cost
        // whatever the addresses, and nothing kept but the copies.
        self.met.sort_unstable();
        self.copies
            .extend(self.met.windows(2).filter(|w| w[0] == w[1]).map(|w| w[0]));
        self.copies.sort_unstable();
        self.copies.dedup();
        Copies(self.copies)
    }
}

/// The last part a walk met: the next, if it is a copy of the same part
/// in the same colour placed exactly where it is (an array's copies one
/// after another, with a step of zero), looks the same in every view, so
/// its outline and path data are not made again (they were most of the
/// cost of 2,000,000 copies in one place).
#[derive(Default)]
pub(super) struct Last {
    own: usize,
    key: Option<String>,
    shape: Option<crate::shapes::Shape>,
    place: Option<crate::part::Place>,
    removed: bool,
    /// In a view's walk: whether it was drawn (or was a copy of one
    /// drawn), not too small to draw.
    pub(super) drawn: bool,
}

impl Last {
    /// Whether `part`, a copy of `own` coloured by `key`, is the last part
    /// again; else it becomes the last.
    pub(super) fn again(
        &mut self,
        own: usize,
        key: Option<&str>,
        part: &crate::part::Part,
    ) -> bool {
        let same = self.own == own
            && self.key.as_deref() == key
            && self.shape == Some(part.shape())
            && self.removed == part.spec.removed
            && self.place.as_ref() == Some(&part.spec.place);
        if !same {
            self.own = own;
            match (&mut self.key, key) {
                (Some(k), Some(new)) => {
                    k.clear();
                    k.push_str(new);
                }
                (k, new) => *k = new.map(str::to_string),
            }
            self.shape = Some(part.shape());
            self.place = Some(part.spec.place.clone());
            self.removed = part.spec.removed;
        }
        same
    }
}

/// What one walk of the parts finds before anything is drawn: the
/// legend's keys and what it must explain, the box that holds the parts,
/// and the smallest outline's size (its largest extent), to know whether
/// any will be smaller than a pixel once the scale is known.
pub(super) struct Survey {
    /// The kind of the legend's keys, and the keys.
    pub(super) kind: Kind,
    pub(super) keys: Keys,
    pub(super) seen: Seen,
    /// The parts with copies that a view may draw.
    pub(super) copies: Copies,
    /// The parts met, a run of coincident copies as one: the views' work.
    pub(super) parts: usize,
    pub(super) extent: [V3; 2],
    /// NaN if any size is (never drawn, as a size below a pixel).
    pub(super) smallest: f64,
}

impl Survey {
    pub(super) fn of(model: &Model) -> Survey {
        let mut v = Survey {
            kind: Kind::Shape,
            keys: Keys::default(),
            seen: Seen::default(),
            copies: Copies::default(),
            parts: 0,
            extent: [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]],
            smallest: f64::INFINITY,
        };
        // NOTE: the kind is known once every part is met: the keys of
        // each kind are gathered in the one walk, and one kept.
        let mut keys: [Keys; 3] = Default::default();
        let mut last = Last::default();
        let mut copies = Counter::default();
        each_part(model, &mut |met| {
            // A coincident copy's key, marks, extent and size are its last's.
            let Met::Part(part, group, own) = met else {
                return;
            };
            copies.meet(own);
            v.parts += 1;
            if last.again(own, group, part) {
                return; // its keys, marks, extent and size are known
            }
            for (k, kind) in [Kind::Group, Kind::Material, Kind::Shape]
                .iter()
                .enumerate()
            {
                keys[k].index(key(*kind, part, group));
            }
            v.seen.cut |= part.spec.removed;
            let outline = outline::of(part);
            match &outline {
                Outline::Marker(kind, _) => v.seen.markers[*kind as usize] = true,
                Outline::Pieces(_) => {
                    let size = outline.size();
                    if !(size >= v.smallest) {
                        v.smallest = size;
                    }
                }
            }
            let [lo, hi] = outline.extent();
            for k in 0..3 {
                v.extent[0][k] = v.extent[0][k].min(lo[k]);
                v.extent[1][k] = v.extent[1][k].max(hi[k]);
            }
        });
        v.copies = copies.done();
        let [group, material, shape] = keys;
        (v.kind, v.keys) = if !group.index.is_empty() {
            (Kind::Group, group)
        } else if !material.index.is_empty() {
            (Kind::Material, material)
        } else {
            (Kind::Shape, shape)
        };
        v
    }
}

/// What the drawing's colours tell apart, one kind a drawing: the
/// parts' groups if any part has one, else their materials if any part
/// has one, else their shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Group,
    Material,
    Shape,
}

impl Kind {
    /// The legend's word for it, and for a part without one.
    pub(super) fn words(self) -> (&'static str, &'static str) {
        match self {
            Kind::Group => ("group", "(no group)"),
            Kind::Material => ("material", "(no material)"),
            Kind::Shape => ("shape", "(no shape)"),
        }
    }
}

/// What a part is coloured by in a drawing of `kind`: its group, its
/// material or its shape; `None` for a part without one.
pub(super) fn key<'a>(
    kind: Kind,
    part: &'a crate::part::Part,
    group: Option<&'a str>,
) -> Option<&'a str> {
    match kind {
        Kind::Group => group,
        Kind::Material => part.material.as_deref(),
        Kind::Shape => Some(part.shape().name()),
    }
}

/// What the drawing's walks meet (`each_part`).
pub(super) enum Met<'a> {
    /// A part with its group (its sub-assemblies' groups, then its own,
    /// joined by ` / `), if any, and which part it is a copy of (the
    /// address of the part as its own file holds it: the same for each
    /// copy, distinct for parts written apart).
    Part(&'a crate::part::Part, Option<&'a str>, usize),
    /// The part met last, `n` times more in the same place: coincident
    /// copies, each of which `Last::again` would find the last again.
    Again(usize),
}

/// Each part in file order (`Met`), coincident copies counted, not
/// placed and handed out one by one (`Model::each_run`): five walks of
/// 2,000,000 copies in one place cost what five walks of one part do.
pub(super) fn each_part(model: &Model, f: &mut dyn FnMut(Met<'_>)) {
    // NOTE: each sub-assembly's joined prefix is made once as the walk
    // enters it, and a part's path is joined again only when the part or
    // the sub-assembly differs from the last one's: copies of one part (an
    // array of 2,000,000) share one join, not a join each of up to 64
    // names.
    let mut prefixes: Vec<String> = vec![String::new()];
    let mut entered = 0usize;
    let mut path = String::new();
    let mut last: Option<(usize, usize)> = None;
    let join = |to: &mut String, names: &[String]| {
        for name in names {
            if !to.is_empty() {
                to.push_str(" / ");
            }
            to.push_str(name);
        }
    };
    model.each_run(&mut |run| match run {
        Run::Again(n) => f(Met::Again(n)),
        Run::Event(Event::Enter(inc)) => {
            let mut prefix = prefixes.last().cloned().unwrap_or_default();
            if let Some(names) = inc.tag.as_ref().and_then(|t| t.group.as_ref()) {
                join(&mut prefix, names);
            }
            prefixes.push(prefix);
            entered += 1;
        }
        Run::Event(Event::Exit) => {
            prefixes.pop();
            entered += 1;
        }
        Run::Event(Event::Part(leaf)) => {
            let own = leaf.tag.and_then(|t| t.group.as_ref());
            let prefix = prefixes.last().map_or("", String::as_str);
            let which = own.map_or(0, |g| g as *const Vec<String> as usize);
            if last != Some((which, entered)) {
                path.clear();
                path.push_str(prefix);
                if let Some(names) = own {
                    join(&mut path, names);
                }
                last = Some((which, entered));
            }
            let own: *const crate::part::Part = leaf.own;
            f(Met::Part(
                leaf.part,
                (!path.is_empty()).then_some(path.as_str()),
                own as usize,
            ));
        }
    });
}

/// The legend's keys, in order of first appearance (`None`: a part
/// without one).
#[derive(Default)]
pub(super) struct Keys {
    pub(super) order: Vec<Option<String>>,
    index: HashMap<String, usize>,
    none: Option<usize>,
}

impl Keys {
    /// The key's place in the order, given one if it is new.
    pub(super) fn index(&mut self, key: Option<&str>) -> usize {
        let found = match key {
            Some(key) => self.index.get(key).copied(),
            None => self.none,
        };
        if let Some(k) = found {
            return k;
        }
        let k = self.order.len();
        self.order.push(key.map(str::to_string));
        match key {
            Some(key) => {
                self.index.insert(key.to_string(), k);
            }
            None => self.none = Some(k),
        }
        k
    }

    /// The place of a key the survey met.
    pub(super) fn get(&self, key: Option<&str>) -> usize {
        match key {
            Some(key) => self.index.get(key).copied(),
            None => self.none,
        }
        .expect("invariant: the survey met every key a view draws")
    }
}

/// What the legend must explain.
#[derive(Default)]
pub(super) struct Seen {
    pub(super) cut: bool,
    /// Point masses, given inertias (`Marker as usize`).
    pub(super) markers: [bool; 2],
}

/// The threads the views are drawn on: two when there are two views or
/// more, two cores, and enough parts to be worth a thread (or as
/// `with_threads` forces).
pub(super) fn threads(parts: usize, views: usize) -> usize {
    const GRAIN: usize = 1_000;
    let n = FORCED.with(std::cell::Cell::get).unwrap_or_else(|| {
        if parts < GRAIN {
            1
        } else {
            std::thread::available_parallelism().map_or(1, |t| t.get())
        }
    });
    n.clamp(1, 2).min(views.max(1))
}

thread_local! {
    static FORCED: std::cell::Cell<Option<usize>> = const { std::cell::Cell::new(None) };
}

/// Run `f` with the drawing's views on `threads` threads (at most two are
/// used), however few the parts: for the tests, which hold one and two
/// to the same document.
pub fn with_threads<T>(threads: usize, f: impl FnOnce() -> T) -> T {
    let before = FORCED.with(|c| c.replace(Some(threads.max(1))));
    let out = f();
    FORCED.with(|c| c.set(before));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn copies(met: &[usize]) -> Copies {
        let mut c = Counter::default();
        met.iter().for_each(|p| c.meet(*p));
        c.done()
    }

    #[test]
    fn a_part_met_twice_anywhere_has_copies_and_one_met_once_has_none() {
        let c = copies(&[7, 3, 9, 3, 5, 5, 5, 1]);
        assert_eq!(c.0, vec![3, 5]);
        assert!(!c.of(7) && !c.of(9) && !c.of(1) && !c.of(4));
    }

    #[test]
    fn an_array_met_in_a_row_is_kept_once() {
        let mut c = Counter::default();
        (0..1000).for_each(|_| c.meet(42));
        assert_eq!(c.met.len(), 1);
        assert_eq!(c.done().0, vec![42]);
    }

    #[test]
    fn elements_a_hundredth_of_a_pixel_apart_are_each_drawn() {
        let c = copies(&[1, 1]);
        let mut d = Drawn::new(&c);
        let mut s = String::new();
        d.draw(&mut s, 1, "<path d=\"M1.00 2.00\"/>\n");
        d.draw(&mut s, 1, "<path d=\"M1.00 2.01\"/>\n");
        d.draw(&mut s, 1, "<path d=\"M1.00 2.00\"/>\n");
        assert_eq!(s, "<path d=\"M1.00 2.00\"/>\n<path d=\"M1.00 2.01\"/>\n");
        assert_eq!(d.again, 1);
    }

    #[test]
    fn the_same_element_of_two_parts_is_drawn_for_each() {
        let c = copies(&[1, 2, 1, 2]);
        let mut d = Drawn::new(&c);
        let mut s = String::new();
        d.draw(&mut s, 1, "e\n");
        d.draw(&mut s, 2, "e\n");
        d.draw(&mut s, 1, "e\n");
        assert_eq!(s, "e\ne\n");
        assert_eq!(d.again, 1);
    }

    #[test]
    fn many_elements_differing_in_their_last_digit_are_each_drawn() {
        // Near-collisions a file could craft: every text kept apart.
        let c = copies(&[5, 5]);
        let mut d = Drawn::new(&c);
        let mut s = String::new();
        for k in 0..10_000 {
            d.draw(&mut s, 5, &format!("M0.00 {}.{:02}\n", k / 100, k % 100));
        }
        for k in 0..10_000 {
            d.draw(&mut s, 5, &format!("M0.00 {}.{:02}\n", k / 100, k % 100));
        }
        assert_eq!(s.lines().count(), 10_000);
        assert_eq!(d.again, 10_000);
    }
}
