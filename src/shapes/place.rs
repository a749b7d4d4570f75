//! Where a part's shape is and how it is turned, in its file's units:
//! `Place`, each placement's numbers (a centre and dimensions, a corner
//! and edges, ends, vertices, a given tensor, an axial part, a prism's
//! polygon, a mesh), and what moves them: a frame (`Place::moved`), a
//! mirror (`Place::mirror`), a tolerance (`Place::number_mut`).

use super::Shape;
use super::lift::Slot;
use crate::numeric::{DD, M3, Real, pow2_scaled};
use crate::rotation::Orientation;
use std::sync::Arc;

/// The rounding of a part's numbers by the frames that placed it, for its
/// error bounds (`shapes::error`): `units` of f64's unit roundoff, relative,
/// in its sizes, edges, mass or density and tensor entries; `at`, absolute
/// (file units), in each coordinate of its position. Rounded up to f32
/// (they are bounds; a part stays small).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Placed {
    pub units: f32,
    pub at: f32,
}

impl Placed {
    /// `units` and `at`, each rounded up to f32.
    pub fn new(units: f64, at: f64) -> Placed {
        let up = |x: f64| {
            let y = x as f32;
            if f64::from(y) < x { y.next_up() } else { y }
        };
        Placed {
            units: up(units),
            at: up(at),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// `center`, the shape's dimensions as `Shape::second_moments` takes
    /// them (box [a, b, c], plate [a, b], rod `[L]`, cylinder [R, r, L], disk
    /// and sphere [R, r]), padded with 0, and the turn of the local axes.
    Centered {
        center: [f64; 3],
        extent: [f64; 3],
        orientation: Orientation,
    },
    /// `corner` and the shape's edges (a plate uses the first two).
    Edges {
        corner: [f64; 3],
        edges: [[f64; 3]; 3],
    },
    /// A rod `from` → `to`.
    FromTo { from: [f64; 3], to: [f64; 3] },
    /// A thin triangular plate's three vertices in the file's frame.
    Vertices([[f64; 3]; 3]),
    /// A given inertia tensor (tensor convention, symmetric, local axes,
    /// file units) about the centroid `center`, turned by `orientation`.
    Given {
        center: [f64; 3],
        inertia: Box<[[f64; 3]; 3]>,
        orientation: Orientation,
    },
    /// A cone or a hemisphere: `center` (the middle of the cone's axis,
    /// the centre of the hemisphere's sphere), the dimensions as
    /// `Shape::second_moments` takes them (cone [R₀, a₀, R₁, a₁, L],
    /// hemisphere [R, r]), padded with 0, and the turn of the local axes.
    /// Its centroid lies off `center` along local z
    /// (`Shape::axial_offset`).
    Axial {
        center: [f64; 3],
        dims: [f64; 5],
        orientation: Orientation,
    },
    /// A prism: where its local origin goes, its polygon in the local x–y
    /// plane (file units, either orientation), its length along local z
    /// (from −length/2 to +length/2) and the turn of the local axes.
    Prism {
        origin: [f64; 3],
        polygon: Arc<[[f64; 2]]>,
        length: f64,
        orientation: Orientation,
    },
    /// A triangle mesh's integrals (`mesh::MeshBody`, in its file's
    /// coordinates and units), scaled by `scale` (its file's unit in this
    /// file's length unit, exact in double-double), turned by
    /// `orientation` and its file's origin put at `origin`, as an include
    /// is placed.
    Mesh {
        origin: [f64; 3],
        orientation: Orientation,
        scale: DD,
        mesh: std::sync::Arc<crate::mesh::MeshBody>,
    },
}

// A part's mirror image: the one rule of how each shape and placement is
// reflected, for `mirror = { .. }` (`model::copies`).
//
// A reflection S = E − 2 n nᵀ moves the points a part is placed by
// (centre, corner and edges, ends, vertices) as it moves any point: the
// frame that places the copy does that (`model::Frame::place`). A part
// placed by its centre and a turn R cannot be turned by S R, which is no
// turn (its determinant is −1); but each shape is its own mirror image in
// the plane of one of its local axes (F, that axis flipped), so its image
// is the same shape turned by the proper rotation S R F. A given inertia
// tensor I is not symmetric in F: it becomes F I F (its products with that
// axis negated), so that (S R F)(F I F)(S R F)ᵀ = S R I Rᵀ S.
//
// NOTE: the hook for new shapes and placements. A shape's module answers
// `ShapeKind::MIRROR_AXIS` (a new shape does not compile until it does);
// a shape symmetric in no local plane (a mesh) answers `None` and
// reflects its own data in `complete`'s arm for its placement.

impl Place {
    /// The place, whose points a reflection has moved and whose turn it has
    /// turned (`orientation` is then S R, or S for a part not turned),
    /// completed as the part's mirror image: the turn becomes S R F, and a
    /// given tensor F I F. Placements by points alone are complete already.
    pub fn mirror(&mut self, shape: Shape) {
        let flip = |k: usize, o: &mut Orientation| {
            let mut n = [0.0; 3];
            n[k] = 1.0;
            let sr = std::mem::replace(o, Orientation::Identity);
            *o = Orientation::Then(Box::new(sr), Box::new(Orientation::Reflect(n)));
        };
        let k = shape.mirror_axis().unwrap_or(0);
        match self {
            Place::Centered { orientation, .. }
            | Place::Axial { orientation, .. }
            | Place::Prism { orientation, .. } => flip(k, orientation),
            Place::Given {
                inertia,
                orientation,
                ..
            } => {
                flip(k, orientation);
                for j in 0..3 {
                    if j != k {
                        inertia[k][j] = -inertia[k][j];
                        inertia[j][k] = -inertia[j][k];
                    }
                }
            }
            Place::Mesh { orientation, .. } => {
                flip(k, orientation);
                // The mesh's own data reflected in the same local plane: the
                // image is S R F (F p) = S R p, for every point p of the mesh.
                self.reflect_mesh(k);
            }
            Place::Edges { .. } | Place::FromTo { .. } | Place::Vertices(_) => {}
        }
    }

    /// A mesh part's mirror image, for mirrors (`array`/`mirror`): its mesh's
    /// data reflected through the plane through the mesh file's origin normal
    /// to local axis `axis` (`mesh::MeshBody::reflected`: the centroid's
    /// coordinate and the products with that axis change sign). The caller
    /// composes the rest of the mirror (a proper turn and the origin's image).
    /// Returns false, changing nothing, for a part that is not a mesh.
    fn reflect_mesh(&mut self, axis: usize) -> bool {
        match self {
            Place::Mesh { mesh, .. } => {
                *mesh = std::sync::Arc::new(mesh.reflected(axis));
                true
            }
            _ => false,
        }
    }
}

impl Place {
    /// The number in `slot` (not `Slot::Mass`, the part's), if the
    /// placement has it: the one map from a slot to a placement's number.
    pub fn number_mut(&mut self, slot: Slot) -> Option<&mut f64> {
        let three = |i: u8| usize::from(i).min(3);
        match slot {
            Slot::Mass => None,
            Slot::At(i) => match self {
                Place::Centered { center: p, .. }
                | Place::Given { center: p, .. }
                | Place::Axial { center: p, .. }
                | Place::Edges { corner: p, .. }
                | Place::FromTo { from: p, .. }
                | Place::Prism { origin: p, .. }
                | Place::Mesh { origin: p, .. } => p.get_mut(three(i)),
                Place::Vertices(_) => None,
            },
            Slot::Dim(k) => match self {
                Place::Centered { extent, .. } => extent.get_mut(usize::from(k)),
                Place::Axial { dims, .. } => dims.get_mut(usize::from(k)),
                Place::Prism { length, .. } => (k == 0).then_some(length),
                Place::Edges { .. }
                | Place::FromTo { .. }
                | Place::Vertices(_)
                | Place::Given { .. }
                | Place::Mesh { .. } => None,
            },
            Slot::Edge(e, i) => match self {
                Place::Edges { edges, .. } => edges
                    .get_mut(usize::from(e))
                    .and_then(|v| v.get_mut(three(i))),
                Place::Centered { .. }
                | Place::FromTo { .. }
                | Place::Vertices(_)
                | Place::Given { .. }
                | Place::Axial { .. }
                | Place::Prism { .. }
                | Place::Mesh { .. } => None,
            },
            Slot::To(i) => match self {
                Place::FromTo { to, .. } => to.get_mut(three(i)),
                Place::Centered { .. }
                | Place::Edges { .. }
                | Place::Vertices(_)
                | Place::Given { .. }
                | Place::Axial { .. }
                | Place::Prism { .. }
                | Place::Mesh { .. } => None,
            },
            Slot::Vertex(v, i) => match self {
                Place::Vertices(p) => p.get_mut(usize::from(v)).and_then(|v| v.get_mut(three(i))),
                Place::Centered { .. }
                | Place::Edges { .. }
                | Place::FromTo { .. }
                | Place::Given { .. }
                | Place::Axial { .. }
                | Place::Prism { .. }
                | Place::Mesh { .. } => None,
            },
        }
    }
}

/// What moves a placement's numbers into another frame: a sub-assembly's
/// or a copy's (`model::frame::Frame`).
pub trait Mover {
    /// A point moved.
    fn point(&self, p: [f64; 3]) -> [f64; 3];
    /// A displacement (an edge) moved: scaled and turned.
    fn dir(&self, e: [f64; 3]) -> [f64; 3];
    /// A turn turned with the frame.
    fn turn(&self, o: &mut Orientation);
    /// The frame's length unit in the outer file's.
    fn length(&self) -> f64;
    /// The frame's mass unit in the outer file's.
    fn mass(&self) -> f64;
}

impl Place {
    /// The power of length the density of the placed `shape` is per
    /// (3, 2 or 1; a mesh's by its mode): how it scales when a
    /// sub-assembly's units are converted.
    pub fn density_power(&self, shape: Shape) -> i32 {
        match self {
            // A mesh's density is per volume or per area by its mode.
            Place::Mesh { mesh, .. } => mesh.mode.power(),
            Place::Centered { .. }
            | Place::Edges { .. }
            | Place::FromTo { .. }
            | Place::Vertices(_)
            | Place::Given { .. }
            | Place::Axial { .. }
            | Place::Prism { .. } => shape.info().density.map_or(0, |d| d.length_power),
        }
    }

    /// Its numbers moved by `m`, in place: points moved, edges and sizes
    /// scaled (and edges turned), turns turned, a given tensor scaled by
    /// the mass and the length squared, a mesh's scale by the length.
    pub fn moved(&mut self, m: &impl Mover) {
        match self {
            Place::Centered {
                center,
                extent,
                orientation,
            } => {
                *center = m.point(*center);
                *extent = extent.map(|x| x * m.length());
                m.turn(orientation);
            }
            Place::Edges { corner, edges } => {
                *corner = m.point(*corner);
                *edges = edges.map(|e| m.dir(e));
            }
            Place::FromTo { from, to } => {
                *from = m.point(*from);
                *to = m.point(*to);
            }
            Place::Vertices(v) => *v = v.map(|x| m.point(x)),
            Place::Axial {
                center,
                dims,
                orientation,
            } => {
                *center = m.point(*center);
                *dims = dims.map(|x| x * m.length());
                m.turn(orientation);
            }
            Place::Prism {
                origin,
                polygon,
                length,
                orientation,
            } => {
                *origin = m.point(*origin);
                if m.length() != 1.0 {
                    *polygon = polygon.iter().map(|v| v.map(|x| x * m.length())).collect();
                }
                *length *= m.length();
                m.turn(orientation);
            }
            Place::Given {
                center,
                inertia,
                orientation,
            } => {
                *center = m.point(*center);
                **inertia = inertia.map(|r| r.map(|x| x * m.mass() * m.length() * m.length()));
                m.turn(orientation);
            }
            Place::Mesh {
                origin,
                orientation,
                scale,
                ..
            } => {
                *origin = m.point(*origin);
                *scale = scale.mul_f64(m.length());
                m.turn(orientation);
            }
        }
    }

    /// The largest |p|₁ of the points the placement gives (its centre,
    /// corner, ends or vertices; a prism's farthest vertex from its
    /// origin added), before a frame moves them.
    pub fn reach(&self) -> f64 {
        let norm = |p: &[f64; 3]| p.iter().map(|x| x.abs()).sum::<f64>();
        match self {
            Place::Centered { center, .. }
            | Place::Given { center, .. }
            | Place::Axial { center, .. } => norm(center),
            // Its vertices are scaled in its own frame: their rounding moves
            // its centroid by a unit of their distance from its origin (and
            // changes its shape, counted in its sizes' units, `Frame::place`).
            Place::Prism {
                origin, polygon, ..
            } => {
                norm(origin)
                    + polygon
                        .iter()
                        .map(|v| v[0].abs() + v[1].abs())
                        .fold(0.0, f64::max)
            }
            Place::Mesh { origin, .. } => norm(origin),
            Place::Edges { corner, .. } => norm(corner),
            Place::FromTo { from, to } => norm(from).max(norm(to)),
            Place::Vertices(v) => v.iter().map(norm).fold(0.0, f64::max),
        }
    }

    /// The units of its sizes by which scaling a prism's polygon in its
    /// own frame changes its shape: each vertex rounds by a unit of its
    /// distance from the origin, 2 max|p|/shortest edge units of its sizes
    /// (its centroid moves too, in `reach`); `None` for a placement with
    /// no polygon.
    pub fn scaled_rounding(&self) -> Option<f64> {
        match self {
            Place::Prism { polygon, .. } => {
                let n = polygon.len();
                let far = polygon
                    .iter()
                    .map(|v| v[0].abs().max(v[1].abs()))
                    .fold(0.0, f64::max);
                let short = (0..n)
                    .map(|i| {
                        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
                        (a[0] - b[0]).hypot(a[1] - b[1])
                    })
                    .fold(f64::INFINITY, f64::min);
                Some(2.0 * far / short)
            }
            Place::Centered { .. }
            | Place::Edges { .. }
            | Place::FromTo { .. }
            | Place::Vertices(_)
            | Place::Given { .. }
            | Place::Axial { .. }
            | Place::Mesh { .. } => None,
        }
    }
}

impl Place {
    /// Every coordinate of the points the placement gives, and its
    /// edges'.
    pub fn positions(&self) -> impl Iterator<Item = f64> + '_ {
        let points: Vec<[f64; 3]> = match self {
            Place::Centered { center, .. }
            | Place::Given { center, .. }
            | Place::Axial { center, .. } => vec![*center],
            Place::Prism { origin, .. } | Place::Mesh { origin, .. } => vec![*origin],
            Place::Edges { corner, edges } => std::iter::once(*corner).chain(*edges).collect(),
            Place::FromTo { from, to } => vec![*from, *to],
            Place::Vertices(v) => v.to_vec(),
        };
        points.into_iter().flatten()
    }
}

impl Place {
    /// A vector along the plate's normal (plate) or the rod's axis (rod), of
    /// any length, in the file's axes: local z, or e₁ × e₂ for a plate given by
    /// corner and edges, or `to` − `from` for a rod.
    pub fn real_size_direction(&self) -> [DD; 3] {
        match self {
            Place::Centered { orientation, .. } => {
                let r: M3<DD> = orientation.matrix();
                [r[0][2], r[1][2], r[2][2]]
            }
            Place::Edges { edges, .. } => {
                let [a, b] = [edges[0], edges[1]].map(|e| pow2_scaled(e.map(DD::of)));
                std::array::from_fn(|i| {
                    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                    a[j] * b[k] - a[k] * b[j]
                })
            }
            // Each difference of two f64 is exact in double-double.
            Place::FromTo { from, to } => std::array::from_fn(|i| DD::of(to[i]) - DD::of(from[i])),
            Place::Given { .. }
            | Place::Vertices(_)
            | Place::Axial { .. }
            | Place::Prism { .. }
            | Place::Mesh { .. } => {
                unreachable!("only plates and rods give a real size")
            }
        }
    }
}

impl Place {
    /// The second moments of the placed `shape` (mass `m`, its own second
    /// moment `j`) that must each be a normal f64 in the file's units:
    /// along its local axes, per edge (formed (m e) e, not m (e e): e²
    /// alone can underflow or overflow), or the trace (a triangle, a given
    /// tensor, a prism, a mesh); how many of them there are, and how many
    /// must be non-zero (a triangle's and a prism's one: its trace).
    pub fn independent_moments(
        &self,
        shape: Shape,
        m: f64,
        j: &M3<f64>,
    ) -> ([f64; 3], usize, usize) {
        let trace = || [j[0][0] + j[1][1] + j[2][2], 0.0, 0.0];
        match self {
            Place::Centered { extent, .. } => (
                shape.second_moments(m, &extent[..shape.dim_count()]),
                3,
                shape.nonzero_moments(),
            ),
            Place::Axial { dims, .. } => (
                shape.second_moments(m, &dims[..shape.dim_count()]),
                3,
                shape.nonzero_moments(),
            ),
            Place::Edges { edges, .. } => (
                edges.map(|e| e.iter().map(|x| (m / 12.0 * x) * x).sum()),
                shape.edge_count(),
                shape.nonzero_moments(),
            ),
            Place::Vertices(_) | Place::Prism { .. } => (trace(), 1, 1),
            Place::FromTo { .. } | Place::Given { .. } | Place::Mesh { .. } => {
                (trace(), 1, shape.nonzero_moments())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mul(a: &M3<f64>, b: &M3<f64>) -> M3<f64> {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    }

    fn det(m: &M3<f64>) -> f64 {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }

    #[test]
    fn a_mirrored_turn_is_a_proper_rotation() {
        let mut place = Place::Centered {
            center: [0.0; 3],
            extent: [1.0, 2.0, 3.0],
            orientation: Orientation::Then(
                Box::new(Orientation::Reflect([1.0, 2.0, 2.0])),
                Box::new(Orientation::AxisAngle([1.0, 1.0, 0.0], 30.0)),
            ),
        };
        place.mirror(Shape::Box);
        let Place::Centered { orientation, .. } = &place else {
            unreachable!()
        };
        let r: M3<f64> = orientation.matrix();
        assert!((det(&r) - 1.0).abs() < 1e-15, "{}", det(&r));
        let rt: M3<f64> = std::array::from_fn(|i| std::array::from_fn(|j| r[j][i]));
        let e = mul(&r, &rt);
        for (i, row) in e.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((x - want).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn a_given_tensor_is_flipped_in_the_symmetric_axis() {
        let mut place = Place::Given {
            center: [0.0; 3],
            inertia: Box::new([[4.0, -1.0, -2.0], [-1.0, 5.0, -3.0], [-2.0, -3.0, 6.0]]),
            orientation: Orientation::Identity,
        };
        place.mirror(Shape::Inertia);
        let Place::Given { inertia, .. } = &place else {
            unreachable!()
        };
        assert_eq!(
            **inertia,
            [[4.0, 1.0, 2.0], [1.0, 5.0, -3.0], [2.0, -3.0, 6.0]]
        );
    }
}
