//! How a part's physics reads the numbers of its `Spec`: as they are, or
//! one of them seeded for forward-mode differentiation (`dual::Dual`), and
//! which number a tolerance moves (`Slot`, `Dep`).

use super::{MassSpec, Place, Spec};
use crate::numeric::Real;

/// One number of a part's `Spec` that a tolerance can move: the model
/// records which a toleranced key fills (`model::tolerance`), and
/// `uncertainty` moves it (Monte Carlo) or differentiates by it (linear).
/// `Spec::number_mut` is the one map from a slot to its number.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Slot {
    /// The given mass, or the density (`MassSpec`).
    Mass,
    /// Coordinate i of the placing point: `center`, `corner`, `from`, or a
    /// prism's or mesh's `origin`.
    At(u8),
    /// Dimension k: `Place::Centered`'s `extent[k]`, `Place::Axial`'s
    /// `dims[k]`; a prism's `length` is `Dim(0)`.
    Dim(u8),
    /// Component i of edge e (`Place::Edges`).
    Edge(u8, u8),
    /// Coordinate i of a rod's `to`.
    To(u8),
    /// Coordinate i of a triangle's vertex v.
    Vertex(u8, u8),
}

/// How one number of a part moves with a source of uncertainty (a
/// toleranced quantity, `model::tolerance`): ∂(number)/∂z in the file's
/// units, z the source's standardised variable (mean 0, standard
/// deviation 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dep {
    pub slot: Slot,
    /// Index in its file's `Model::sources`.
    pub source: u32,
    pub rate: f64,
}

/// How a part's physics reads the numbers of its `Spec`: each as it is
/// (`Fixed`), or one of them seeded with a unit derivative (`Seed`), so
/// that evaluated in `dual::Dual` every result carries its derivative by
/// that number (`Real::var`).
pub trait Lift: Copy {
    /// The rate at which the number in `slot` moves.
    fn rate(self, slot: Slot) -> f64;
}

/// Every number as it is: what the composer and every report read.
#[derive(Clone, Copy, Debug)]
pub struct Fixed;

impl Lift for Fixed {
    #[inline(always)]
    fn rate(self, _: Slot) -> f64 {
        0.0
    }
}

/// The number in one slot seeded with the rate 1.
#[derive(Clone, Copy, Debug)]
pub struct Seed(pub Slot);

impl Lift for Seed {
    #[inline]
    fn rate(self, slot: Slot) -> f64 {
        if slot == self.0 { 1.0 } else { 0.0 }
    }
}

/// The slots of a coordinate triple.
pub(super) fn xyz(f: impl Fn(u8) -> Slot) -> [Slot; 3] {
    [f(0), f(1), f(2)]
}

/// Three coordinates read through `l`.
pub(super) fn lift3<T: Real, L: Lift>(l: L, v: &[f64; 3], slots: [Slot; 3]) -> [T; 3] {
    std::array::from_fn(|i| T::var(v[i], l.rate(slots[i])))
}

impl Spec {
    /// The number in `slot`, if the part has it (the one map from a
    /// `Slot` to a `Spec`'s number).
    pub fn number_mut(&mut self, slot: Slot) -> Option<&mut f64> {
        let three = |i: u8| usize::from(i).min(3);
        match (slot, &mut self.place) {
            (Slot::Mass, _) => Some(match &mut self.mass {
                MassSpec::Given(m) => m,
                MassSpec::Density(d) => d,
            }),
            (
                Slot::At(i),
                Place::Centered { center: p, .. }
                | Place::Given { center: p, .. }
                | Place::Axial { center: p, .. }
                | Place::Edges { corner: p, .. }
                | Place::FromTo { from: p, .. }
                | Place::Prism { origin: p, .. }
                | Place::Mesh { origin: p, .. },
            ) => p.get_mut(three(i)),
            (Slot::Dim(k), Place::Centered { extent, .. }) => extent.get_mut(usize::from(k)),
            (Slot::Dim(k), Place::Axial { dims, .. }) => dims.get_mut(usize::from(k)),
            (Slot::Dim(0), Place::Prism { length, .. }) => Some(length),
            (Slot::Edge(e, i), Place::Edges { edges, .. }) => edges
                .get_mut(usize::from(e))
                .and_then(|v| v.get_mut(three(i))),
            (Slot::To(i), Place::FromTo { to, .. }) => to.get_mut(three(i)),
            (Slot::Vertex(v, i), Place::Vertices(p)) => {
                p.get_mut(usize::from(v)).and_then(|v| v.get_mut(three(i)))
            }
            _ => None,
        }
    }
}
