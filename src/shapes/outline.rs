//! A placed shape's outline in 3-D, in the file's frame and length unit:
//! the lines and curves whose orthographic projections draw it. Each
//! shape's module makes its own (`ShapeKind::outline`);
//! `output::drawing::view` projects the pieces.
//!
//! - box, plate: the convex hull of the corners (the exact silhouette of
//!   a convex solid); a mesh: its silhouette edges in each view;
//! - rod: its segment; triangle: its three edges; prism: both ends'
//!   polygons and the edges between them (a polygon may be concave);
//! - cylinder, tube, cone: each rim a circle (an ellipse once projected),
//!   and the two lines tangent to both outer rims;
//! - disk: its rims; sphere: its outline circle (a hollow one's inner
//!   sphere is hidden); hemisphere: its rim and the outline of its dome;
//! - torus: the outline of the tube swept along its centre line;
//! - point mass and given inertia: a marker.

pub type V3 = [f64; 3];

/// A marker for a part with no drawable extent.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// `shape = "point"`.
    Point,
    /// `shape = "inertia"`: a given tensor.
    Inertia,
}

/// One line or curve of an outline.
#[derive(Debug, Clone, PartialEq)]
pub enum Piece {
    /// A polyline through the points, closed or not.
    Line { points: Vec<V3>, closed: bool },
    /// The convex hull of the points' projections.
    Hull(Vec<V3>),
    /// A triangle mesh's silhouette: the edges between a triangle that
    /// faces the viewer and one that does not, and its open edges.
    Silhouette {
        points: Vec<V3>,
        faces: std::sync::Arc<Vec<[u32; 3]>>,
    },
    /// The outline of the ellipsoid {c + M u : |u| ≤ 1}, `m` its columns
    /// (a zero column: a flat ellipse, the rim of a circle).
    Ellipsoid { c: V3, m: [V3; 3] },
    /// The lines tangent to two parallel rims c₀ + r₀(u cos t + v sin t)
    /// and c₁ + r₁(u cos t + v sin t), `u` and `v` orthonormal: the side
    /// of a cylinder or cone.
    Side {
        c: [V3; 2],
        r: [f64; 2],
        u: V3,
        v: V3,
    },
    /// The dome of a hemisphere about `c` of radius `r`, its rim in the
    /// plane of `u` and `v`, the dome toward `z` (all three orthonormal).
    Dome { c: V3, r: f64, u: V3, v: V3, z: V3 },
    /// A torus: its tube, of radius `a`, swept along the circle
    /// c + r(u cos t + v sin t).
    Torus { c: V3, r: f64, a: f64, u: V3, v: V3 },
}

/// How a part is drawn.
#[derive(Debug, Clone, PartialEq)]
pub enum Outline {
    Marker(Marker, V3),
    Pieces(Vec<Piece>),
}

impl Outline {
    /// The box that holds the outline: least and greatest coordinates.
    pub fn extent(&self) -> [V3; 2] {
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        let mut add = |c: V3, half: V3| {
            for k in 0..3 {
                b[0][k] = b[0][k].min(c[k] - half[k]);
                b[1][k] = b[1][k].max(c[k] + half[k]);
            }
        };
        match self {
            Outline::Marker(_, c) => add(*c, [0.0; 3]),
            Outline::Pieces(pieces) => {
                for p in pieces {
                    match p {
                        Piece::Line { points, .. }
                        | Piece::Hull(points)
                        | Piece::Silhouette { points, .. } => {
                            points.iter().for_each(|q| add(*q, [0.0; 3]));
                        }
                        Piece::Ellipsoid { c, m } => add(
                            *c,
                            std::array::from_fn(|k| {
                                (m[0][k].powi(2) + m[1][k].powi(2) + m[2][k].powi(2)).sqrt()
                            }),
                        ),
                        Piece::Side { c, r, u, v } => {
                            for (c, r) in c.iter().zip(r) {
                                add(*c, rim_half(*r, u, v, 0.0));
                            }
                        }
                        Piece::Dome { c, r, .. } => add(*c, [*r; 3]),
                        Piece::Torus { c, r, a, u, v } => add(*c, rim_half(*r, u, v, *a)),
                    }
                }
            }
        }
        b
    }
}

impl Outline {
    /// Its largest extent along x, y or z (0 for a marker).
    pub fn size(&self) -> f64 {
        let [lo, hi] = self.extent();
        (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max)
    }
}

/// The half-extent of the circle c + r(u cos t + v sin t) along each axis,
/// plus `pad`.
fn rim_half(r: f64, u: &V3, v: &V3, pad: f64) -> V3 {
    std::array::from_fn(|k| r * (u[k] * u[k] + v[k] * v[k]).sqrt() + pad)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parallelepiped_has_two_to_the_edges_corners() {
        let c = super::super::common::corners([1.0, 0.0, 0.0], &[[1.0, 0.0, 0.0], [0.0, 2.0, 0.0]]);
        assert_eq!(
            c,
            vec![
                [1.0, 0.0, 0.0],
                [2.0, 0.0, 0.0],
                [1.0, 2.0, 0.0],
                [2.0, 2.0, 0.0]
            ]
        );
    }

    #[test]
    fn a_sphere_extends_its_radius_each_way() {
        let o = Outline::Pieces(vec![Piece::Ellipsoid {
            c: [1.0, 2.0, 3.0],
            m: [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]],
        }]);
        assert_eq!(o.extent(), [[-1.0, 0.0, 1.0], [3.0, 4.0, 5.0]]);
    }

    #[test]
    fn a_torus_in_the_x_y_plane_is_flat_by_its_tube() {
        let o = Outline::Pieces(vec![Piece::Torus {
            c: [0.0; 3],
            r: 3.0,
            a: 1.0,
            u: [1.0, 0.0, 0.0],
            v: [0.0, 1.0, 0.0],
        }]);
        assert_eq!(o.extent(), [[-4.0, -4.0, -1.0], [4.0, 4.0, 1.0]]);
    }
}
