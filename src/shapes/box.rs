//! A box: edges `a, b, c` along local x, y, z, centred on the origin;
//! dimensions [a, b, c]. Each ∫x² dm is a uniform segment's, m a²/12.

use super::common::{at, axes, centred_hull, corners, density_power, diagonal, edges_centroid, edges_centroid_error, edges_in, edges_measure, exact_centroid_error, flip, mirror_axis, norm1, points, reset_turn, spanned, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{Dims, MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Spanned, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use super::{PER_VOLUME, product, segment};

/// A box, in its file's units: by its `center`, `size` and turn, or by a
/// `corner` and the 3 perpendicular `edges` that span it.
#[derive(Debug, Clone, PartialEq)]
pub enum Cuboid {
    Centred {
        center: [f64; 3],
        size: [f64; 3],
        orientation: Orientation,
    },
    Spanned {
        corner: [f64; 3],
        edges: [[f64; 3]; 3],
    },
}

/// Its sizes as its closed forms take them, read through `l`.
fn sizes<T: Real, L: Lift>(size: &[f64; 3], l: L) -> [T; 3] {
    [var(size[0], Slot::Size(0), l), var(size[1], Slot::Size(1), l), var(size[2], Slot::Size(2), l)]
}

impl ShapeKind for Cuboid {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Box,
        name: "box",
        keys: &[
            "density", "size", "center", "rotation", "corner", "edges", "mass", "remove",
            "material",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Size(3),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(3)),
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 3,
        degenerate: "a zero or non-perpendicular edge",
        help: "a box takes `mass` or `density`, and `size` with `center` (and optional `rotation`), or `corner` with three `edges`",
    };

    /// Three products.
    const MEASURE_ROUNDINGS: f64 = 3.0;

    /// m a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b, c] = d else {
            unreachable!("the model passes a box three dimensions")
        };
        [segment(m, *a), segment(m, *b), segment(m, *c)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        if r.by_edges() {
            let edges = r.vectors("edges")?;
            return Ok(Cuboid::Spanned {
                corner: r.point("corner")?,
                edges,
            });
        }
        let size = r.sizes()?;
        Ok(Cuboid::Centred {
            center: r.point("center")?,
            size,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        match self {
            Cuboid::Centred { size, .. } => Self::measure_of(&sizes(size, l)),
            Cuboid::Spanned { edges, .. } => edges_measure(edges, l),
        }
    }

    /// Centred, its own count; spanned, a norm per edge (3 for the
    /// squares' sum, 2 for the root) and a product.
    fn measure_error(&self) -> f64 {
        match self {
            Cuboid::Centred { .. } => Self::MEASURE_ROUNDINGS,
            Cuboid::Spanned { .. } => 6.0 * 3.0,
        }
    }

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        match self {
            Cuboid::Centred { center, .. } => at(center, l),
            Cuboid::Spanned { corner, edges } => edges_centroid(corner, edges, l),
        }
    }

    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        match self {
            Cuboid::Centred { .. } => exact_centroid_error(at),
            Cuboid::Spanned { edges, .. } => edges_centroid_error(edges, at, centroid),
        }
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        match self {
            Cuboid::Centred {
                size, orientation, ..
            } => {
                let d = Self::moments_of(m, &sizes(size, l));
                diagonal(d, orientation, units, Self::MOMENT_ROUNDINGS)
            }
            Cuboid::Spanned { edges, .. } => spanned(m, &edges_in(edges, l), units),
        }
    }

    fn shortest_span(&self) -> f64 {
        f64::INFINITY
    }

    fn independent_moments(&self, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
        let parts = match self {
            Cuboid::Centred { size, .. } => Self::moments_of(m, size),
            Cuboid::Spanned { edges, .. } => {
                let mut parts = [0.0; 3];
                for (p, e) in parts.iter_mut().zip(edges) {
                    // (m e) e, not m (e e): e² alone can underflow or
                    // overflow.
                    *p = e.iter().map(|x| (m / 12.0 * x) * x).sum();
                }
                parts
            }
        };
        let count = match self {
            Cuboid::Centred { .. } => 3,
            Cuboid::Spanned { .. } => 3,
        };
        (parts, count, Self::INFO.nonzero_moments)
    }

    fn moved(&mut self, m: &impl Mover) {
        match self {
            Cuboid::Centred {
                center,
                size,
                orientation,
            } => {
                *center = m.point(*center);
                *size = size.map(|x| x * m.length());
                m.turn(orientation);
            }
            Cuboid::Spanned { corner, edges } => {
                *corner = m.point(*corner);
                *edges = edges.map(|e| m.dir(e));
            }
        }
    }

    fn density_power(&self) -> i32 {
        density_power::<Self>()
    }

    fn scaled_rounding(&self) -> Option<f64> {
        None
    }

    fn reach(&self) -> f64 {
        match self {
            Cuboid::Centred { center, .. } => norm1(center),
            Cuboid::Spanned { corner, .. } => norm1(corner),
        }
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        match self {
            Cuboid::Centred { center, .. } => points(&[*center]),
            Cuboid::Spanned { corner, edges } => points(&[*corner, edges[0], edges[1], edges[2]]),
        }
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        match self {
            Cuboid::Centred { center, size, .. } => {
                for (i, x) in center.iter_mut().enumerate() {
                    f(Slot::At(i as u8), x);
                }
                for (k, x) in size.iter_mut().enumerate() {
                    f(Slot::Size(k as u8), x);
                }
            }
            Cuboid::Spanned { corner, edges } => {
                for (i, x) in corner.iter_mut().enumerate() {
                    f(Slot::At(i as u8), x);
                }
                for (e, v) in edges.iter_mut().enumerate() {
                    for (i, x) in v.iter_mut().enumerate() {
                        f(Slot::Edge(e as u8, i as u8), x);
                    }
                }
            }
        }
    }

    fn reset_from(&mut self, src: &Self) {
        match (self, src) {
            (
                Cuboid::Centred {
                    center,
                    size,
                    orientation,
                },
                Cuboid::Centred {
                    center: c,
                    size: s,
                    orientation: o,
                },
            ) => {
                *center = *c;
                *size = *s;
                reset_turn(orientation, o);
            }
            (
                Cuboid::Spanned { corner, edges },
                Cuboid::Spanned {
                    corner: c,
                    edges: e,
                },
            ) => {
                *corner = *c;
                *edges = *e;
            }
            (d, s) => *d = s.clone(),
        }
    }

    /// Centred, its turn completed as its mirror image; spanned, its
    /// points alone place it, already reflected.
    fn mirror(&mut self) {
        match self {
            Cuboid::Centred { orientation, .. } => flip(mirror_axis::<Self>(), orientation),
            Cuboid::Spanned { .. } => {}
        }
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        match self {
            Cuboid::Centred { .. } => None,
            Cuboid::Spanned { .. } => None,
        }
    }

    fn outline(&self) -> Outline {
        match self {
            Cuboid::Centred {
                center,
                size,
                orientation,
            } => Outline::Pieces(vec![centred_hull(
                *center,
                size,
                &axes(&orientation.matrix()),
            )]),
            Cuboid::Spanned { corner, edges } => {
                Outline::Pieces(vec![Piece::Hull(corners(*corner, &edges[..]))])
            }
        }
    }
}
