//! A plate: a thin rectangle `a × b` in the local x–y plane, zero
//! thickness; dimensions [a, b]. Its real `thickness` never enters its
//! moments (`analysis::ideal` compares it with the box it describes).

use super::common::{at, axes, centred_hull, corners, density_power, diagonal, edges_centroid, edges_centroid_error, edges_in, edges_measure, exact_centroid_error, flip, local_z, mirror_axis, norm1, points, reset_turn, spanned, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Outline, Piece};
use super::{Dims, MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Spanned, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;
use crate::numeric::pow2_scaled;
use super::{PER_AREA, Solid, product, segment};

/// A plate, in its file's units: by its `center`, `size` and turn, or by a
/// `corner` and the 2 perpendicular `edges` that span it.
#[derive(Debug, Clone, PartialEq)]
pub enum Plate {
    Centred {
        center: [f64; 3],
        size: [f64; 2],
        orientation: Orientation,
    },
    Spanned {
        corner: [f64; 3],
        edges: [[f64; 3]; 2],
    },
}

/// Its sizes as its closed forms take them, read through `l`.
fn sizes<T: Real, L: Lift>(size: &[f64; 2], l: L) -> [T; 2] {
    [var(size[0], Slot::Size(0), l), var(size[1], Slot::Size(1), l)]
}

impl ShapeKind for Plate {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Plate,
        name: "plate",
        keys: &[
            "areal_density",
            "size",
            "center",
            "rotation",
            "corner",
            "edges",
            "mass",
            "remove",
            "thickness",
            "material",
        ],
        density: Some(PER_AREA),
        dims: Dims::Size(2),
        centred: &["size", "center", "rotation"],
        spanned: Some(Spanned::CornerEdges(2)),
        material: MaterialRule::Thickness,
        real_size: Some(("thickness", Solid::Box)),
        nonzero_moments: 2,
        degenerate: "a zero or non-perpendicular edge",
        help: "a plate takes `mass` or `areal_density`, and `size` = [x, y] with `center` (and optional `rotation`), or `corner` with two `edges`; optionally its real `thickness`",
    };

    /// Two products.
    const MEASURE_ROUNDINGS: f64 = 2.0;

    /// m a²/12: a², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [a, b] = d else {
            unreachable!("the model passes a plate two dimensions")
        };
        [segment(m, *a), segment(m, *b), T::of(0.0)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &impl Reader) -> Result<Self, Diagnostic> {
        if r.by_edges() {
            let edges = r.vectors("edges")?;
            return Ok(Plate::Spanned {
                corner: r.point("corner")?,
                edges,
            });
        }
        let size = r.sizes()?;
        Ok(Plate::Centred {
            center: r.point("center")?,
            size,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        match self {
            Plate::Centred { size, .. } => Self::measure_of(&sizes(size, l)),
            Plate::Spanned { edges, .. } => edges_measure(edges, l),
        }
    }

    /// Centred, its own count; spanned, a norm per edge (3 for the
    /// squares' sum, 2 for the root) and a product.
    fn measure_error(&self) -> f64 {
        match self {
            Plate::Centred { .. } => Self::MEASURE_ROUNDINGS,
            Plate::Spanned { .. } => 6.0 * 2.0,
        }
    }

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        match self {
            Plate::Centred { center, .. } => at(center, l),
            Plate::Spanned { corner, edges } => edges_centroid(corner, edges, l),
        }
    }

    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        match self {
            Plate::Centred { .. } => exact_centroid_error(at),
            Plate::Spanned { edges, .. } => edges_centroid_error(edges, at, centroid),
        }
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        match self {
            Plate::Centred {
                size, orientation, ..
            } => {
                let d = Self::moments_of(m, &sizes(size, l));
                diagonal(d, orientation, units, Self::MOMENT_ROUNDINGS)
            }
            Plate::Spanned { edges, .. } => spanned(m, &edges_in(edges, l), units),
        }
    }

    fn shortest_span(&self) -> f64 {
        f64::INFINITY
    }

    fn independent_moments(&self, m: f64, _: &M3<f64>) -> ([f64; 3], usize, usize) {
        let parts = match self {
            Plate::Centred { size, .. } => Self::moments_of(m, size),
            Plate::Spanned { edges, .. } => {
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
            Plate::Centred { .. } => 3,
            Plate::Spanned { .. } => 2,
        };
        (parts, count, Self::INFO.nonzero_moments)
    }

    fn moved(&mut self, m: &impl Mover) {
        match self {
            Plate::Centred {
                center,
                size,
                orientation,
            } => {
                *center = m.point(*center);
                *size = size.map(|x| x * m.length());
                m.turn(orientation);
            }
            Plate::Spanned { corner, edges } => {
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
            Plate::Centred { center, .. } => norm1(center),
            Plate::Spanned { corner, .. } => norm1(corner),
        }
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        match self {
            Plate::Centred { center, .. } => points(&[*center]),
            Plate::Spanned { corner, edges } => points(&[*corner, edges[0], edges[1]]),
        }
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        match self {
            Plate::Centred { center, size, .. } => {
                for (i, x) in center.iter_mut().enumerate() {
                    f(Slot::At(i as u8), x);
                }
                for (k, x) in size.iter_mut().enumerate() {
                    f(Slot::Size(k as u8), x);
                }
            }
            Plate::Spanned { corner, edges } => {
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
                Plate::Centred {
                    center,
                    size,
                    orientation,
                },
                Plate::Centred {
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
                Plate::Spanned { corner, edges },
                Plate::Spanned {
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
            Plate::Centred { orientation, .. } => flip(mirror_axis::<Self>(), orientation),
            Plate::Spanned { .. } => {}
        }
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        match self {
            Plate::Centred { orientation, .. } => Some(local_z(orientation)),
            Plate::Spanned { edges, .. } => {
                let [a, b] = [edges[0], edges[1]].map(|e| pow2_scaled(e.map(DD::of)));
                Some(std::array::from_fn(|i| {
                    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                    a[j] * b[k] - a[k] * b[j]
                }))
            },
        }
    }

    fn outline(&self) -> Outline {
        match self {
            Plate::Centred {
                center,
                size,
                orientation,
            } => Outline::Pieces(vec![centred_hull(
                *center,
                &[size[0], size[1], 0.0],
                &axes(&orientation.matrix()),
            )]),
            Plate::Spanned { corner, edges } => {
                Outline::Pieces(vec![Piece::Hull(corners(*corner, &edges[..]))])
            }
        }
    }
}
