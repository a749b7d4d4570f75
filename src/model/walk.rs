//! The body's parts, sub-assemblies expanded as they are walked.
//!
//! NOTE: a `Model` keeps each file it includes once, however often it is
//! included, and each include as a placement of it (`Include`); the parts
//! of a sub-assembly are placed into this file's frame and units only as a
//! walk reaches them, and dropped after. So the memory of a body grows with
//! the distinct content of its files, not with the copies of them a tree
//! of includes makes (a tree of 21 files of 2²⁰ instances took 6.9 GB
//! expanded). Each part is placed by the same arithmetic, in the same
//! order, as when sub-assemblies were expanded once into a list: its own
//! sub-assembly's frame first, then each enclosing one's, every coordinate
//! rounded once per frame (`frame::Frame::place`); so results are the
//! same to the last bit. A part's or a sub-assembly's copies (`array`,
//! `mirror`: `copies`) are frames too, set as the walk reaches each copy
//! (the last copy's moved in place) and applied after the sub-assembly's
//! own: the copies are never held. A copy whose frames are the last
//! copy's to the bit (a step or turn of zero) is not placed again, and a
//! walk of runs (`Model::each_run`) hands it out as a count.

use super::budget::Tag;
use super::{Copies, Frame, Include, Item, Model, push_copy_name};
use crate::part::{EachPart, Part, RealSize};
use std::borrow::Cow;
use std::ops::Range;

impl EachPart for Model {
    fn each(&self, f: &mut dyn FnMut(&Part)) {
        self.each_body_part(f);
    }
}

/// A part of the body, as a walk meets it.
pub struct Leaf<'a> {
    /// Its position among all the parts of the body, in file order.
    pub index: usize,
    /// In this file's frame and units; named by its path
    /// (`elbow / motor / stator`) with its sub-assemblies in `assembly`,
    /// its span the `[[part]]` table in this file that holds it.
    pub part: &'a Part,
    /// Its real thickness or diameter, in this file's length unit.
    pub real: Option<RealSize>,
    /// Its own `group` and `maturity` (`budget`); the sub-assemblies'
    /// that hold it come with `Event::Enter`.
    pub tag: Option<&'a Tag>,
    /// The part as its own file gives it, and the frames that place it
    /// in this one (`Placing`).
    pub own: &'a Part,
    pub placing: Placing<'a>,
}

/// The frames a part is placed through, outermost first, and which copy
/// of its file and of itself it is.
#[derive(Clone, Copy)]
pub struct Placing<'a> {
    layers: &'a [Layer<'a>],
    /// Which instance of the part's file this is (its includes and their
    /// copies, from the root), and of the part itself (its copy too): the
    /// same on every run, the keys of its sources of uncertainty.
    pub file: u64,
    pub part: u64,
    /// The model of the file the part is in.
    pub model: &'a Model,
}

impl Placing<'_> {
    /// A spec of the part's own file placed in this one, as the walk
    /// places it.
    pub fn place(&self, spec: &mut crate::part::Spec) {
        for layer in self.layers.iter().rev() {
            layer.frame.place(spec);
        }
    }

    /// The shifts of the part by the tolerances of its sub-assemblies'
    /// origins (none for most parts).
    pub fn shifts(&self, f: &mut dyn FnMut(Shift<'_>)) {
        for (i, layer) in self.layers.iter().enumerate() {
            let Some(m) = &layer.moved else { continue };
            // The frames outside this include move its origin's shift.
            let outer = self.layers[..i]
                .iter()
                .fold(super::frame::Linear::IDENTITY, |acc, l| {
                    acc.after(&l.frame.linear())
                });
            for dep in m.deps {
                let crate::part::Slot::At(c) = dep.slot else {
                    continue;
                };
                // In the including file's units; `outer` takes them on.
                let mut d = [0.0; 3];
                d[usize::from(c)] = dep.rate;
                let source = &m.model.sources[dep.source as usize];
                // A parameter's source is the including file's instance's,
                // the origin's own this include's.
                let key = if source.shared {
                    mix(m.file, u64::from(dep.source), 0)
                } else {
                    mix(m.key, u64::from(dep.source), 2)
                };
                f(Shift {
                    key,
                    source,
                    include: &m.include.name,
                    dir: outer.dir(d),
                });
            }
        }
    }

    /// The linear part of the placing (`frame::Linear`).
    pub fn linear(&self) -> super::frame::Linear {
        self.layers
            .iter()
            .fold(super::frame::Linear::IDENTITY, |acc, l| {
                acc.after(&l.frame.linear())
            })
    }
}

/// A key mixed with two numbers (splitmix64's finaliser): an instance's
/// key from its parent's, its item and its copy.
pub fn mix(key: u64, a: u64, b: u64) -> u64 {
    let mut z = key ^ a.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ b.wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// What a walk of the tree meets, in file order: a sub-assembly entered,
/// a part, the sub-assembly left.
pub enum Event<'a> {
    Enter(&'a Include),
    Part(Leaf<'a>),
    Exit,
}

/// What a walk of runs meets (`Model::each_run`): the events of
/// `each_event`, but a copy placed to the bit where the part met last is
/// (a copy of it) comes as a count.
pub enum Run<'a> {
    Event(Event<'a>),
    /// The part met last, `n` times more, each in the same place (and
    /// each a part of the body: the parts' indices count them).
    Again(usize),
}

/// Whom a walk hands what it meets: events alone (`Events`), or events
/// and counts of coincident copies (`Runs`, `RUNS`).
trait Visit {
    const RUNS: bool;
    fn event(&mut self, e: Event<'_>);
    fn again(&mut self, n: usize);
    /// A sub-assembly entered: its copy `copy` (`Rows` names it).
    fn enter(&mut self, inc: &Include, _copy: Option<usize>) {
        self.event(Event::Enter(inc));
    }
    /// A part, `k` its position in its file, its copy `copy` (`Rows`
    /// names it).
    fn leaf(&mut self, l: Leaf<'_>, _k: usize, _copy: Option<usize>) {
        self.event(Event::Part(l));
    }
}

struct Events<'f>(&'f mut dyn FnMut(Event<'_>));

impl Visit for Events<'_> {
    const RUNS: bool = false;
    fn event(&mut self, e: Event<'_>) {
        (self.0)(e);
    }
    fn again(&mut self, _: usize) {}
}

struct Runs<'f>(&'f mut dyn FnMut(Run<'_>));

impl Visit for Runs<'_> {
    const RUNS: bool = true;
    fn event(&mut self, e: Event<'_>) {
        (self.0)(Run::Event(e));
    }
    fn again(&mut self, n: usize) {
        (self.0)(Run::Again(n));
    }
}

/// What a walk for the report's rows meets (`Model::each_row`), in file
/// order: a sub-assembly entered, with the name its row path shows
/// (`wheel[2]` for a copy); a part, placed (its numbers only: no bound of
/// its rounding is formed), with what names it; the sub-assembly left.
pub enum RowEvent<'a> {
    Enter(&'a str),
    Part {
        /// Placed into the root's frame and units, its numbers the same
        /// bits as `each_part`'s.
        part: &'a Part,
        /// As its own file gives it (its `name` and `named`), `k` its
        /// position in that file and `copy` which copy it is.
        own: &'a Part,
        k: usize,
        copy: Option<usize>,
    },
    Exit,
}

impl RowEvent<'_> {
    /// A part's own name, as its row shows it after the path of its
    /// sub-assemblies: its name, or `part N`, with its copy's index.
    pub fn push_own_name(out: &mut String, own: &Part, k: usize, copy: Option<usize>) {
        write_name(out, "", k, own, copy);
    }
}

/// `RowEvent`s handed out, each name made once per sub-assembly entered.
struct Rows<'f> {
    f: &'f mut dyn FnMut(RowEvent<'_>),
    name: String,
}

impl Visit for Rows<'_> {
    const RUNS: bool = false;
    fn event(&mut self, e: Event<'_>) {
        match e {
            // Named by `enter`.
            Event::Enter(_) => {}
            // Handed out by `leaf`.
            Event::Part(_) => {}
            Event::Exit => (self.f)(RowEvent::Exit),
        }
    }
    fn again(&mut self, _: usize) {}
    fn enter(&mut self, inc: &Include, copy: Option<usize>) {
        self.name.clear();
        match copy {
            None => self.name.push_str(&inc.name),
            Some(i) => push_copy_name(&mut self.name, &inc.name, i),
        }
        (self.f)(RowEvent::Enter(&self.name));
    }
    fn leaf(&mut self, l: Leaf<'_>, k: usize, copy: Option<usize>) {
        (self.f)(RowEvent::Part {
            part: l.part,
            own: l.own,
            k,
            copy,
        });
    }
}

impl Model {
    /// Every part of the body, named, in file order.
    pub fn each_part(&self, f: &mut dyn FnMut(Leaf<'_>)) {
        self.walk(true, &mut 0, &mut |e| {
            if let Event::Part(l) = e {
                f(l);
            }
        });
    }

    /// The file's own parts, each copy of them too, in file order,
    /// unnamed; its sub-assemblies are passed over (their parts counted in
    /// `Leaf::index`, never placed): a pass that judges a file by its own
    /// parts costs its own parts, however deep its tree.
    pub fn each_own_part(&self, f: &mut dyn FnMut(Leaf<'_>)) {
        let mut walk = self.walker(false);
        walk.own_only = true;
        walk.items(
            self,
            &mut Events(&mut |e| {
                if let Event::Part(l) = e {
                    f(l);
                }
            }),
        );
    }

    /// Whether some part of the body, at any depth, is a cut-out: each
    /// distinct file looked at once.
    pub fn has_cut_outs(&self) -> bool {
        fn any(m: &Model, seen: &mut std::collections::HashSet<*const Model>) -> bool {
            m.items.iter().any(|item| match item {
                Item::Part { part, .. } => part.spec.removed,
                Item::Include(inc) => {
                    seen.insert(std::sync::Arc::as_ptr(&inc.model)) && any(&inc.model, seen)
                }
            })
        }
        any(self, &mut std::collections::HashSet::new())
    }

    /// Every part and sub-assembly, in file order; parts unnamed, as
    /// `each_body_part`'s.
    pub fn each_event(&self, f: &mut dyn FnMut(Event<'_>)) {
        self.walk(false, &mut 0, f);
    }

    /// Every part of the body, in file order, for its physics only: a part
    /// of a sub-assembly has neither its name nor its sub-assemblies
    /// (nothing of them is allocated).
    pub fn each_body_part(&self, f: &mut dyn FnMut(&Part)) {
        self.walk(false, &mut 0, &mut |e| {
            if let Event::Part(l) = e {
                f(l.part);
            }
        });
    }

    /// All the parts, expanded into memory: for tests and for `diff`, which
    /// matches every part of two files.
    pub fn flattened(&self) -> Vec<Part> {
        let mut parts = Vec::with_capacity(self.count);
        self.each_part(&mut |l| parts.push(l.part.clone()));
        parts
    }

    /// The part at `index` (as `Leaf::index`), named.
    pub fn part(&self, index: usize) -> Option<Part> {
        let mut found = None;
        self.each_part(&mut |l| {
            if l.index == index {
                found = Some(l.part.clone());
            }
        });
        found
    }

    /// The parts' real sizes (`thickness`, `diameter`), in file order.
    pub fn real_sizes(&self) -> Vec<RealSize> {
        let mut out = Vec::new();
        if self.has_real_sizes {
            self.each_body_part_real(&mut |r| out.push(r));
        }
        out
    }

    fn each_body_part_real(&self, f: &mut dyn FnMut(RealSize)) {
        self.walk(false, &mut 0, &mut |e| {
            if let Event::Part(Leaf { real: Some(r), .. }) = e {
                f(r);
            }
        });
    }

    /// Every part and sub-assembly, as `each_event`, but a copy placed to
    /// the bit where the copy before it is (an array's copies with a step
    /// or a turn of zero: coincident) comes as a count after it
    /// (`Run::Again`), not as a part: for the walks that do with a
    /// coincident copy nothing but count it (the drawing's, the range
    /// check's), its cost is the copies that differ.
    pub fn each_run(&self, f: &mut dyn FnMut(Run<'_>)) {
        self.walk_with(false, &mut 0, &mut Runs(f));
    }

    /// Every part of the body, in file order, for the report's rows
    /// (`RowEvent`): each sub-assembly named once as it is entered, not
    /// per part; each part placed through the same frames by the same
    /// arithmetic as `each_part` (the same bits), without the bound of
    /// its rounding (`Frame::place_numbers`), which no row shows.
    pub fn each_row(&self, f: &mut dyn FnMut(RowEvent<'_>)) {
        let mut walk = self.walker(false);
        walk.bounds = false;
        walk.items(
            self,
            &mut Rows {
                f,
                name: String::new(),
            },
        );
    }

    /// Walk the items, `next` the index of the next part.
    pub(super) fn walk(&self, named: bool, next: &mut usize, f: &mut dyn FnMut(Event<'_>)) {
        self.walk_with(named, next, &mut Events(f));
    }

    fn walk_with(&self, named: bool, next: &mut usize, f: &mut impl Visit) {
        let mut walk = self.walker(named);
        walk.next = *next;
        walk.items(self, f);
        *next = walk.next;
    }

    fn walker(&self, named: bool) -> Walk<'_> {
        Walk {
            own_only: false,
            bounds: true,
            frames: Vec::new(),
            keys: vec![0],
            named,
            next: 0,
            prefix: String::new(),
            placed: Part {
                name: String::new(),
                named: true,
                spec: crate::part::Spec {
                    mass: crate::part::MassSpec::Given(0.0),
                    place: crate::part::Place::Triangle(crate::shapes::triangle::Triangle {
                        vertices: [[0.0; 3]; 3],
                    }),
                    removed: false,
                    placed: Default::default(),
                },
                assembly: Vec::new(),
                span: 0..0,
                tol: None,
                material: None,
            },
        }
    }
}

/// A frame a part is placed through: an include's, or a copy's set as
/// the walk reaches it (`Walk::copy_frames`); with the `[[part]]` table
/// in this file that it comes from.
struct Layer<'m> {
    frame: Cow<'m, Frame>,
    span: &'m Range<usize>,
    /// An include's: the tolerances of its origin, in the including file.
    moved: Option<Moved<'m>>,
}

/// A sub-assembly whose origin carries tolerances, as a walk enters it.
#[derive(Clone, Copy)]
struct Moved<'m> {
    deps: &'m [crate::part::Dep],
    /// The including file's model (its `sources`).
    model: &'m Model,
    /// This instance of the include (its copy too), and of the file that
    /// includes it (whose parameters' sources are one per instance).
    key: u64,
    file: u64,
    include: &'m Include,
}

/// A shift of a part with a source of uncertainty: its sub-assembly's
/// origin moved, in the root file's frame and units, per unit of the
/// source's standardised variable.
pub struct Shift<'a> {
    /// The source's key: the same on every run, one per instance.
    pub key: u64,
    pub source: &'a super::tolerance::Toleranced,
    /// The sub-assembly's name in its including file.
    pub include: &'a str,
    pub dir: [f64; 3],
}

/// A walk under way.
///
/// NOTE: the part handed out for a sub-assembly's part is one `Part`
/// reused, its path (`prefix`, `assembly`) kept as sub-assemblies are
/// entered and left: a part 20 sub-assemblies deep costs no allocation for
/// its name or path (made afresh for each, they were 40 of the 2²⁰ parts'
/// 42 allocations).
struct Walk<'m> {
    /// Whether sub-assemblies are passed over (`Model::each_own_part`).
    own_only: bool,
    /// Whether a placed part's bound of its rounding is formed
    /// (`Spec::placed`); not for the rows (`Model::each_row`).
    bounds: bool,
    /// The frames entered, outermost first.
    frames: Vec<Layer<'m>>,
    /// The instance key of each file entered (`Placing::file`), the root's
    /// first.
    keys: Vec<u64>,
    named: bool,
    next: usize,
    /// `a / b / `: the names of the sub-assemblies entered.
    prefix: String,
    placed: Part,
}

impl<'m> Walk<'m> {
    fn items<V: Visit>(&mut self, model: &'m Model, f: &mut V) {
        for (k, item) in model.items.iter().enumerate() {
            match item {
                Item::Include(inc) if self.own_only => {
                    let copies = inc.copies.as_ref().map_or(1, |c| c.indices().len());
                    self.next += inc.model.count * copies;
                }
                Item::Include(inc) => match &inc.copies {
                    None => self.include(model, k, inc, None, f),
                    Some(c) => {
                        let base = self.frames.len();
                        for i in c.indices() {
                            self.copy_frames(c, i, &inc.span, base);
                            self.include(model, k, inc, Some(i), f);
                        }
                        self.frames.truncate(base);
                    }
                },
                Item::Part {
                    part,
                    real,
                    copies,
                    tag,
                } => match copies {
                    None => self.part(model, k, (part, tag.as_deref(), *real), None, true, f),
                    Some(c) => {
                        let base = self.frames.len();
                        let first = c.indices().start;
                        let mut again = 0;
                        for i in c.indices() {
                            // NOTE: a copy whose frames are the last copy's
                            // to the bit (a step or turn of zero) is placed
                            // where the last was: `placed` holds it already;
                            // a walk of runs counts it and hands out nothing.
                            let moved = self.copy_frames(c, i, &part.span, base) || i == first;
                            if V::RUNS && !moved {
                                again += 1;
                                self.next += 1;
                                continue;
                            }
                            if again > 0 {
                                f.again(std::mem::take(&mut again));
                            }
                            let part = (part, tag.as_deref(), *real);
                            self.part(model, k, part, Some(i), moved, f);
                        }
                        if again > 0 {
                            f.again(again);
                        }
                        self.frames.truncate(base);
                    }
                },
            }
        }
    }

    /// Copy `i`'s frames in place of the copy before it's, above the
    /// first `base` (outermost first: its mirror's, then its array's).
    ///
    /// NOTE: a copy's frames are not made afresh: the mirror's is the one
    /// `Copies` holds, borrowed, and the array's is the last copy's, moved
    /// in place to this one (`Copies::move_array_frame`); made and pushed
    /// for each copy, a frame's bytes moved five times were 40 % of the
    /// time of `render` of 2,000,000 copies.
    ///
    /// Whether they moved: false when they are the last copy's to the bit.
    fn copy_frames(
        &mut self,
        c: &'m Copies,
        i: usize,
        span: &'m Range<usize>,
        base: usize,
    ) -> bool {
        let (k, image) = c.which(i);
        let mut at = base;
        let mut moved = false;
        if image {
            let mirror = c
                .image()
                .expect("invariant: a copy past the array's is an image in its mirror");
            let kept = matches!(
                self.frames.get(at),
                Some(Layer { frame: Cow::Borrowed(m), .. }) if std::ptr::eq(*m, mirror)
            );
            if !kept {
                self.frames.truncate(at);
                self.frames.push(Layer {
                    frame: Cow::Borrowed(mirror),
                    span,
                    moved: None,
                });
                moved = true;
            }
            at += 1;
        }
        if k > 0 {
            // Above `base`, an owned frame is an earlier copy's array's.
            match self.frames.get_mut(at) {
                Some(Layer {
                    frame: Cow::Owned(frame),
                    ..
                }) => moved |= c.move_array_frame(k, frame),
                _ => {
                    self.frames.truncate(at);
                    self.frames.push(Layer {
                        frame: Cow::Owned(c.array_frame(k)),
                        span,
                        moved: None,
                    });
                    moved = true;
                }
            }
            at += 1;
        }
        moved |= self.frames.len() != at;
        self.frames.truncate(at);
        moved
    }

    /// The sub-assembly `inc` (its copy `copy`), entered, walked and left.
    fn include(
        &mut self,
        model: &'m Model,
        k: usize,
        inc: &'m Include,
        copy: Option<usize>,
        f: &mut impl Visit,
    ) {
        f.enter(inc, copy);
        let file = *self.keys.last().expect("the root's key");
        let key = mix(file, k as u64, copy.map_or(u64::MAX, |i| i as u64));
        self.keys.push(key);
        self.frames.push(Layer {
            frame: Cow::Borrowed(&inc.frame),
            span: &inc.span,
            moved: inc.tol.as_deref().map(|deps| Moved {
                deps,
                model,
                key,
                file,
                include: inc,
            }),
        });
        let len = self.prefix.len();
        if self.named {
            let at = self.prefix.len();
            match copy {
                None => self.prefix.push_str(&inc.name),
                Some(i) => push_copy_name(&mut self.prefix, &inc.name, i),
            }
            self.placed.assembly.push(self.prefix[at..].to_string());
            self.prefix.push_str(" / ");
        }
        self.items(&inc.model, f);
        if self.named {
            self.prefix.truncate(len);
            self.placed.assembly.pop();
        }
        self.frames.pop();
        self.keys.pop();
        f.event(Event::Exit);
    }

    /// The part `part` with its tag and real size, `k` its position in its
    /// file (its copy `copy`); `moved` false when `placed` holds it placed through
    /// these very frames already (the last copy, in the same place).
    ///
    /// NOTE: the part handed out is `part` itself when nothing places or
    /// names it, else `placed` made `part` again in place (`reset`: no
    /// temporary, no reference count touched when it holds the same
    /// material) and moved through the frames.
    fn part(
        &mut self,
        model: &'m Model,
        k: usize,
        (part, tag, real): (&'m Part, Option<&'m Tag>, Option<(crate::part::Solid, f64)>),
        copy: Option<usize>,
        moved: bool,
        f: &mut impl Visit,
    ) {
        let index = self.next;
        self.next += 1;
        let mut real = real.map(|(solid, size)| RealSize {
            part: index,
            solid,
            size,
        });
        let unnamed = self.named && !part.named;
        let file = *self.keys.last().expect("the root's key");
        let placing = Placing {
            layers: &self.frames,
            file,
            part: mix(file, k as u64, copy.map_or(u64::MAX, |i| i as u64)),
            model,
        };
        let placed = &mut self.placed;
        let Some(outermost) = self.frames.first() else {
            if !unnamed && copy.is_none() {
                let leaf = Leaf {
                    index,
                    part,
                    real,
                    own: part,
                    placing,
                    tag,
                };
                f.leaf(leaf, k, copy);
                return;
            }
            // As `placed.clone_from(part)`, its buffers kept.
            placed.name.clone_from(&part.name);
            placed.named = part.named;
            if moved {
                reset::spec(&mut placed.spec, &part.spec);
                placed.assembly.clone_from(&part.assembly);
                placed.span.clone_from(&part.span);
                reset::shared(&mut placed.tol, &part.tol);
                reset::shared(&mut placed.material, &part.material);
            }
            if self.named {
                placed.name.clear();
                write_name(&mut placed.name, "", k, part, copy);
                placed.named = true;
            }
            let leaf = Leaf {
                index,
                part: placed,
                real,
                own: part,
                placing,
                tag,
            };
            f.leaf(leaf, k, copy);
            return;
        };
        if moved {
            placed.span.clone_from(outermost.span);
            reset::spec(&mut placed.spec, &part.spec);
            reset::shared(&mut placed.material, &part.material);
        }
        for layer in self.frames.iter().rev() {
            if moved && self.bounds {
                layer.frame.place(&mut placed.spec);
            } else if moved {
                layer.frame.place_numbers(&mut placed.spec);
            }
            if let Some(r) = &mut real {
                r.size *= layer.frame.length;
            }
        }
        if self.named {
            placed.name.clear();
            write_name(&mut placed.name, &self.prefix, k, part, copy);
        }
        let leaf = Leaf {
            index,
            part: placed,
            real,
            own: part,
            placing,
            tag,
        };
        f.leaf(leaf, k, copy);
    }
}

/// A value made another again in place, as `clone_from` would, without
/// the temporary a derived `clone_from` makes (a clone, a drop and a
/// move of the whole value, for each part a walk places).
mod reset {
    use crate::part::Spec;
    use std::sync::Arc;

    pub(super) fn spec(dst: &mut Spec, src: &Spec) {
        dst.mass = src.mass;
        dst.removed = src.removed;
        dst.placed = src.placed;
        // NOTE: field by field where both are one shape's (a part's copies
        // and the parts of one shape, one after another:
        // `Place::reset_from`); any other pair is made whole, as before.
        dst.place.reset_from(&src.place);
    }

    /// A shared value (a material's name, a part's tolerances): its count
    /// left alone when it is the same one.
    pub(super) fn shared<T: ?Sized>(dst: &mut Option<Arc<T>>, src: &Option<Arc<T>>) {
        let same = match (&*dst, src) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            (Some(_), None) | (None, Some(_)) => false,
        };
        if !same {
            dst.clone_from(src);
        }
    }
}

/// A part's name, after `prefix` (the path of its sub-assemblies): its
/// own, or `part N` (`k` + 1), with its copy's index.
fn write_name(out: &mut String, prefix: &str, k: usize, part: &Part, copy: Option<usize>) {
    use std::fmt::Write as _;
    out.push_str(prefix);
    match (part.named, copy) {
        (true, None) => out.push_str(&part.name),
        (true, Some(i)) => push_copy_name(out, &part.name, i),
        (false, None) => {
            let _ = write!(out, "part {}", k + 1);
        }
        // As `push_copy_name` writes it, with no name made first.
        (false, Some(i)) => {
            let _ = write!(out, "part {}[{i}]", k + 1);
        }
    }
}
