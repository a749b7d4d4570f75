//! How a part's physics reads the numbers of its `Spec`: as they are, or
//! one of them seeded for forward-mode differentiation (`dual::Dual`), and
//! which number a tolerance moves (`Slot`, `Dep`).

use crate::numeric::Real;

/// One number of a part's `Spec` that a tolerance can move: the model
/// records which a toleranced key fills (`model::tolerance`), and
/// `uncertainty` moves it (Monte Carlo) or differentiates by it (linear).
/// Each shape's module names its numbers' slots (`ShapeKind::numbers`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Slot {
    /// The given mass, or the density (`MassSpec`).
    Mass,
    /// Coordinate i of the placing point: `center`, `corner`, `from`, or a
    /// prism's or mesh's `origin`.
    At(u8),
    /// Component k of a box's or plate's `size`.
    Size(u8),
    /// A rod's, cylinder's, cone's or prism's `length`.
    Length,
    /// A `radius` (or half a `diameter`): a cylinder's, disk's, sphere's,
    /// hemisphere's, a cone's base's, a torus's centre line.
    Radius,
    /// An `inner_radius` (or half an `inner_diameter`).
    InnerRadius,
    /// A cone's `top_radius`.
    TopRadius,
    /// A cone's `top_inner_radius`.
    TopInnerRadius,
    /// A torus's `tube_radius`.
    TubeRadius,
    /// A torus's `inner_tube_radius`.
    InnerTubeRadius,
    /// Component i of edge e of a box or plate placed by its edges.
    Edge(u8, u8),
    /// Coordinate i of a rod's `to`.
    To(u8),
    /// Coordinate i of a triangle's vertex v.
    Vertex(u8, u8),
    /// Component i of a shape's own key k, by its place in the shape's
    /// `ShapeKind::OWN_KEYS` (an ellipsoid's `radii`).
    Own(u8, u8),
}

impl Slot {
    /// A coordinate of a point (a centre, a corner, an end, a vertex, an
    /// origin): where the origin is decides its value, so a percentage of
    /// it means nothing.
    pub fn is_point(self) -> bool {
        matches!(self, Slot::At(_) | Slot::To(_) | Slot::Vertex(..))
    }

    /// A coordinate of a point or a vector's component: any sign is a
    /// body (a size, a radius, a mass or a density below zero is none).
    pub fn is_signed(self) -> bool {
        self.is_point() || matches!(self, Slot::Edge(..))
    }
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
pub fn xyz(f: impl Fn(u8) -> Slot) -> [Slot; 3] {
    [f(0), f(1), f(2)]
}

/// Three coordinates read through `l`.
pub fn lift3<T: Real, L: Lift>(l: L, v: &[f64; 3], slots: [Slot; 3]) -> [T; 3] {
    std::array::from_fn(|i| T::var(v[i], l.rate(slots[i])))
}
