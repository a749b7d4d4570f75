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
//! rounded once per frame (`include::Frame::place`); so results are the
//! same to the last bit.

use super::{Include, Item, Model};
use crate::part::{Part, Parts, RealSize};
use std::fmt::Write as _;

impl Parts for Model {
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
}

/// What a walk of the tree meets, in file order: a sub-assembly entered,
/// a part, the sub-assembly left.
pub enum Event<'a> {
    Enter(&'a Include),
    Part(Leaf<'a>),
    Exit,
}

impl Model {
    /// Every part of the body, named, in file order.
    pub fn each_part(&self, f: &mut dyn FnMut(Leaf<'_>)) {
        self.walk(&mut Vec::new(), true, &mut 0, &mut |e| {
            if let Event::Part(l) = e {
                f(l);
            }
        });
    }

    /// Every part and sub-assembly, in file order; parts unnamed, as
    /// `each_body_part`'s.
    pub fn each_event(&self, f: &mut dyn FnMut(Event<'_>)) {
        self.walk(&mut Vec::new(), false, &mut 0, f);
    }

    /// Every part of the body, in file order, for its physics only: a part
    /// of a sub-assembly has neither its name nor its sub-assemblies
    /// (nothing of them is allocated).
    pub fn each_body_part(&self, f: &mut dyn FnMut(&Part)) {
        self.walk(&mut Vec::new(), false, &mut 0, &mut |e| {
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
        self.walk(&mut Vec::new(), false, &mut 0, &mut |e| {
            if let Event::Part(Leaf { real: Some(r), .. }) = e {
                f(r);
            }
        });
    }

    /// Walk the items, `frames` the includes entered (outermost first),
    /// `next` the index of the next part.
    pub(super) fn walk<'m>(
        &'m self,
        frames: &mut Vec<&'m Include>,
        named: bool,
        next: &mut usize,
        f: &mut dyn FnMut(Event<'_>),
    ) {
        let mut walk = Walk {
            frames: std::mem::take(frames),
            named,
            next: *next,
            prefix: String::new(),
            placed: Part {
                name: String::new(),
                named: true,
                shape: crate::shapes::Shape::ALL[0],
                spec: crate::part::Spec {
                    mass: crate::part::MassSpec::Given(0.0),
                    place: crate::part::Place::Vertices([[0.0; 3]; 3]),
                    removed: false,
                    placed: Default::default(),
                },
                assembly: Vec::new(),
                span: 0..0,
            },
        };
        walk.items(self, f);
        *next = walk.next;
        *frames = walk.frames;
    }
}

/// A walk under way.
///
/// NOTE: the part handed out for a sub-assembly's part is one `Part`
/// reused, its path (`prefix`, `assembly`) kept as sub-assemblies are
/// entered and left: a part 20 sub-assemblies deep costs no allocation for
/// its name or path (made afresh for each, they were 40 of the 2²⁰ parts'
/// 42 allocations).
struct Walk<'m> {
    frames: Vec<&'m Include>,
    named: bool,
    next: usize,
    /// `a / b / `: the names of the sub-assemblies entered.
    prefix: String,
    placed: Part,
}

impl<'m> Walk<'m> {
    fn items(&mut self, model: &'m Model, f: &mut dyn FnMut(Event<'_>)) {
        for (k, item) in model.items.iter().enumerate() {
            match item {
                Item::Include(inc) => {
                    f(Event::Enter(inc));
                    self.frames.push(inc);
                    let len = self.prefix.len();
                    if self.named {
                        self.prefix.push_str(&inc.name);
                        self.prefix.push_str(" / ");
                        self.placed.assembly.push(inc.name.clone());
                    }
                    self.items(&inc.model, f);
                    if self.named {
                        self.prefix.truncate(len);
                        self.placed.assembly.pop();
                    }
                    self.frames.pop();
                    f(Event::Exit);
                }
                Item::Part { part, real } => {
                    let index = self.next;
                    self.next += 1;
                    let mut real = real.map(|(solid, size)| RealSize {
                        part: index,
                        solid,
                        size,
                    });
                    let unnamed = self.named && !part.named;
                    let Some(outermost) = self.frames.first() else {
                        if !unnamed {
                            f(Event::Part(Leaf { index, part, real }));
                            continue;
                        }
                        let placed = &mut self.placed;
                        placed.clone_from(part);
                        placed.name = format!("part {}", k + 1);
                        placed.named = true;
                        f(Event::Part(Leaf {
                            index,
                            part: placed,
                            real,
                        }));
                        continue;
                    };
                    let placed = &mut self.placed;
                    placed.shape = part.shape;
                    placed.span = outermost.span.clone();
                    placed.spec.clone_from(&part.spec);
                    for inc in self.frames.iter().rev() {
                        inc.frame.place(part.shape, &mut placed.spec);
                        if let Some(r) = &mut real {
                            r.size *= inc.frame.length;
                        }
                    }
                    if self.named {
                        placed.name.clear();
                        placed.name.push_str(&self.prefix);
                        if unnamed {
                            let _ = write!(placed.name, "part {}", k + 1);
                        } else {
                            placed.name.push_str(&part.name);
                        }
                    }
                    f(Event::Part(Leaf {
                        index,
                        part: placed,
                        real,
                    }));
                }
            }
        }
    }
}
