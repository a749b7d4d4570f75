//! The types of a shape's description (`ShapeInfo`), which each shape's
//! module declares as its `ShapeKind::INFO` (docs/architecture.md).

use super::{Shape, Slot};
use crate::units::Dim;
use serde::Serialize;

/// What a shape's density is per, and so which key gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DensityKind {
    /// The key: `density`, `areal_density` or `linear_density`.
    pub key: &'static str,
    pub dim: Dim,
    /// The power of length the density is per (3, 2 or 1): how it scales
    /// when a sub-assembly's units are converted.
    pub length_power: i32,
}

/// Per volume: `density`, kg/m³.
pub const PER_VOLUME: DensityKind = DensityKind {
    key: "density",
    dim: Dim::DENSITY,
    length_power: 3,
};
/// Per area: `areal_density`, kg/m², for thin plates.
pub const PER_AREA: DensityKind = DensityKind {
    key: "areal_density",
    dim: Dim::AREAL_DENSITY,
    length_power: 2,
};
/// Per length: `linear_density`, kg/m, for slender rods.
pub const PER_LENGTH: DensityKind = DensityKind {
    key: "linear_density",
    dim: Dim::LINEAR_DENSITY,
    length_power: 1,
};

/// A second way to place a shape, by the vectors that span it, beside the
/// centred one (`center` and `rotation` with the dimensions).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spanned {
    /// `corner` and this many perpendicular `edges` (box 3, plate 2).
    CornerEdges(usize),
    /// `from` and `to` (rod).
    FromTo,
}

impl Spanned {
    /// The keys of this placement.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Spanned::CornerEdges(_) => &["corner", "edges"],
            Spanned::FromTo => &["from", "to"],
        }
    }

    /// The number of edge vectors.
    pub fn edges(self) -> usize {
        match self {
            Spanned::CornerEdges(n) => n,
            Spanned::FromTo => 1,
        }
    }
}

/// What turns a named `material`'s density (per volume) into the shape's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MaterialRule {
    /// Per volume already.
    Volume,
    /// Times the `thickness` (plates, disks, triangles).
    Thickness,
    /// Times the section: `area`, or the disc of `diameter` (rods).
    Section,
    /// The shape takes no material (`mass` only).
    None,
}

/// Everything the rules of a part file know about a shape: the one
/// description every reader consults (validation, includes, idealisation,
/// suggestions, docs/part-file.md). See docs/architecture.md for adding a
/// shape.
#[derive(Clone, Copy, Debug)]
pub struct ShapeInfo {
    pub shape: Shape,
    /// The name in part files (`shape = "box"`).
    pub name: &'static str,
    /// Every key a part of this shape accepts, besides `name` and `shape`.
    pub keys: &'static [&'static str],
    /// The density it takes instead of `mass`; `None`: `mass` only.
    pub density: Option<DensityKind>,
    /// The keys that give its size, beside its placement (`radius`,
    /// `inner_radius`, `length`; `size`; a triangle's `vertices`, a given
    /// `inertia`, a mesh's `file`), by name: where a tolerance fills one of
    /// its numbers (`model::tolerance`), what the schema requires, where
    /// an overflow of its second moments is reported. Its module reads
    /// them (`ShapeKind::read`).
    pub sizes: &'static [&'static str],
    /// How many lengths `size` holds (box 3, plate 2; 0 without `size`).
    pub size_items: usize,
    /// The keys of the centred placement that conflict with `spanned`'s.
    pub centred: &'static [&'static str],
    /// The other placement, if the shape has one.
    pub spanned: Option<Spanned>,
    pub material: MaterialRule,
    /// The key giving the real size of a thin or slender idealisation, and
    /// the solid it describes (`report::ideal`).
    pub real_size: Option<(&'static str, Solid)>,
    /// How many of the three local second moments are non-zero (0 where
    /// the model checks the shape's own way: a triangle, a given tensor).
    pub nonzero_moments: usize,
    /// What makes it degenerate, for the docs and messages.
    pub degenerate: &'static str,
    /// The help shown with an error about its keys.
    pub help: &'static str,
}

impl ShapeInfo {
    /// The shape's name with its article, as its help line begins ("a
    /// box", "an ellipsoid"): what a message says of a part of it.
    pub fn a_name(&self) -> &'static str {
        let article = if self.help.starts_with("an ") { 3 } else { 2 };
        &self.help[..article + self.name.len()]
    }
}

/// The solid that a thin plate or slender rod idealises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Solid {
    /// A plate a × b of thickness t: the box a × b × t.
    Box,
    /// A rod of length L and diameter d: the solid circular cylinder.
    Cylinder,
}

impl Solid {
    pub fn name(self) -> &'static str {
        match self {
            Solid::Box => "box",
            Solid::Cylinder => "cylinder",
        }
    }
}

/// What a part key's value is (`Key::kind`): how the reader reads it, and
/// how a message says what was expected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A number, or a string with a unit (`"5 mm"`), an expression, a
    /// tolerance.
    Quantity,
    /// A point: an array of 3 quantities (`center`, `corner`, `origin`).
    Point,
    /// An array of quantities: this many, or as many as the shape says
    /// (`None`: a box's or plate's `size`).
    Quantities(Option<usize>),
    /// An array of rows, each an array of `width` quantities; `says`: one
    /// row and the whole as messages name them (`("an edge vector", "3
    /// edge vectors")`), `None` where they name neither.
    Rows {
        width: usize,
        says: Option<(&'static str, &'static str)>,
    },
    /// A string.
    Str,
    /// `true` or `false`.
    Bool,
    /// A rotation table (`{ axis = [..], degrees = θ }`, …).
    Rotation,
    /// An `array = { count = .., step = .. }` table.
    ArrayTable,
    /// A `mirror = { normal = .., origin = .. }` table.
    MirrorTable,
    /// A table of named quantities (an include's `params`).
    ParamsTable,
}

/// Which parts take a key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// Every part (`name`, `shape`, `array`, `mirror`, `group`,
    /// `maturity`).
    Every,
    /// The parts whose shape lists it in `ShapeInfo::keys` (and an
    /// include, for `include`, `origin`, `params`, `rotation`).
    Listed,
}

/// One part key, declared once: the common ones in `model::keys`, a
/// shape's own in its module's `ShapeKind::OWN_KEYS`. The reader, the
/// key checks, the did-you-mean and the messages' "expected …" all come
/// from these.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Key {
    /// The key in part files.
    pub name: &'static str,
    pub kind: Kind,
    /// The dimension of its quantities (`Dim::DIMENSIONLESS` for a key
    /// without any).
    pub dim: Dim,
    /// Which number of a part a tolerance ("±") on it moves, if it may
    /// carry one.
    pub fill: Fill,
    /// Whether each of its quantities must be > 0 (checked as read).
    pub positive: bool,
    pub scope: Scope,
    /// One line for the docs and the schema.
    pub doc: &'static str,
}

impl Key {
    /// A shape's own key: listed in its `INFO.keys`, read as declared.
    pub const fn own(name: &'static str, kind: Kind, dim: Dim, doc: &'static str) -> Key {
        Key {
            name,
            kind,
            dim,
            fill: Fill::No,
            positive: false,
            scope: Scope::Listed,
            doc,
        }
    }

    /// The same key, taking "±" (in the slot `Slot::Own` of its place
    /// among its shape's own keys).
    pub const fn tolerable(self) -> Key {
        Key {
            fill: Fill::Own,
            ..self
        }
    }

    /// Whether it may carry a tolerance ("±").
    pub fn takes_tolerance(&self) -> bool {
        self.fill != Fill::No
    }

    /// The same key, each of its quantities checked > 0.
    pub const fn positive(self) -> Key {
        Key {
            positive: true,
            ..self
        }
    }
}

/// Which number of a part's `Spec` (its `Slot`) a tolerance on a key
/// moves: declared with the key (`Key::fill`), so that a key, or a shape
/// that lists it, has its slot without a map elsewhere. Some fill only on
/// the shapes that give their size by the key (`ShapeInfo::sizes`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fill {
    /// None: the key takes no "±".
    No,
    /// The mass, given or by density (`mass`, a `material`'s density).
    Mass,
    /// The mass, where the key is the shape's density kind's
    /// (`ShapeInfo::density`).
    Density,
    /// A coordinate of the placing point (`center`, `corner`, `from`,
    /// `origin`).
    At,
    /// A coordinate of a rod's `to`.
    To,
    /// A component of an edge vector (`edges`).
    Edge,
    /// A coordinate of a vertex (`vertices`).
    Vertex,
    /// A component of `size`, where the shape's sizes name the key.
    Size,
    /// This slot, where the shape's sizes name the key (`length` fills
    /// `Slot::Length`).
    Dim(Slot),
    /// Half of what the named key fills (a `diameter`, the `radius`).
    Half(&'static str),
    /// A component of a shape's own key: `Slot::Own` of its place among
    /// the shape's `own_keys`.
    Own,
}

impl ShapeInfo {
    /// The number of a part of this shape that a tolerance on `key` moves
    /// (at `row` of a list of points, `component` of a vector), and the
    /// factor from the key's value to it (a diameter moves a radius,
    /// halved); `None` where no tolerance may stand. `common`: the keys
    /// any part may have, where `Fill::Half` finds the key it halves.
    pub fn slot(
        &self,
        key: &Key,
        row: usize,
        component: usize,
        common: &[Key],
    ) -> Option<(Slot, f64)> {
        let c = component.min(2) as u8;
        let r = row.min(2) as u8;
        let sized = self.sizes.contains(&key.name);
        let slot = match key.fill {
            Fill::No => return None,
            Fill::Mass => Slot::Mass,
            Fill::Density => {
                self.density.filter(|d| d.key == key.name)?;
                Slot::Mass
            }
            Fill::At => Slot::At(c),
            Fill::To => Slot::To(c),
            Fill::Edge => Slot::Edge(r, c),
            Fill::Vertex => Slot::Vertex(r, c),
            Fill::Size => sized.then_some(Slot::Size(c))?,
            Fill::Dim(slot) => sized.then_some(slot)?,
            Fill::Half(of) => {
                let of = common.iter().find(|k| k.name == of)?;
                let (slot, factor) = self.slot(of, row, component, common)?;
                return Some((slot, 0.5 * factor));
            }
            Fill::Own => {
                let own = self.shape.own_keys();
                let i = own.iter().position(|k| k.name == key.name)?;
                Slot::Own(i as u8, c)
            }
        };
        Some((slot, 1.0))
    }
}

/// The declaration of `name` if a shape declares it as its own
/// (`ShapeKind::OWN_KEYS`; the first, should two shapes declare one name).
pub fn own_key(name: &str) -> Option<&'static Key> {
    Shape::ALL
        .iter()
        .flat_map(|s| s.own_keys())
        .find(|k| k.name == name)
}

/// A shape's own key that no shape has, declared for the tests alone.
///
/// NOTE: the reading of an own key (read, tolerated, checked > 0) is
/// tested before any shape declares one (`model::keys`' tests): in test
/// builds `Shape::own_keys` gives it to the point, whose `INFO.keys` do
/// not list it (so no part file may use it).
#[cfg(test)]
pub const PROBE: Key = Key::own(
    "probe_radii",
    Kind::Quantities(Some(3)),
    Dim::LENGTH,
    "three lengths, for the tests",
)
.tolerable()
.positive();

/// How `massprop explain` writes a shape's closed forms (`ShapeKind::EXPLAIN`,
/// required of every shape: a shape without its explanation does not
/// compile). The formulas are templates over the dimensions' symbols and
/// `m`: `+ - * / ^ ( )`, numbers and `pi`; `explain::formula` writes them
/// as text or TeX, with the symbols or with the part's numbers, and the
/// shapes' tests evaluate them against `measure_of` and `moments_of`.
#[derive(Clone, Copy, Debug)]
pub struct Explain {
    /// The closed form's name: "thin rectangular plate a × b".
    pub form: &'static str,
    /// Its dimensions, in the order its closed forms take them.
    pub dims: &'static [Symbol],
    /// Volume, area or length over the symbols; "" where the shape has
    /// none (a mass only).
    pub measure: &'static str,
    /// The moments of inertia about its centroid along its local x, y, z
    /// (Ixx = ∫(y² + z²) dm, …); "" where there is no closed form over
    /// its dimensions (a triangle, a given tensor, a prism, a mesh).
    pub moments: [&'static str; 3],
}

/// A dimension of a shape as `explain` names it: its symbol in a
/// template and in text, its TeX, and the number of the part it is
/// (`Slot`: a box's `Size(k)`, which a box placed by its edges gives as
/// the length of edge k).
#[derive(Clone, Copy, Debug)]
pub struct Symbol {
    pub name: &'static str,
    pub tex: &'static str,
    pub slot: Slot,
}

/// A symbol of `explain`'s templates.
pub const fn symbol(name: &'static str, tex: &'static str, slot: Slot) -> Symbol {
    Symbol { name, tex, slot }
}
