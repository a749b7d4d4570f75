//! Each placed shape's outline in 3-D, in the file's frame and length
//! unit: the lines and curves whose orthographic projections draw it. The
//! one place that turns a placed shape into lines, by its `Place` and its
//! shape's `Drawn` (`ShapeKind::INFO`); `render::drawing::view` projects
//! the pieces.
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

use super::place::Place;
use super::{Drawn, Shape};

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
        faces: std::sync::Arc<[[u32; 3]]>,
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

impl Place {
    /// The outline of the placed `shape` in the file's frame.
    pub fn outline(&self, shape: Shape) -> Outline {
        match self {
            Place::Centered {
                center,
                extent,
                orientation,
            } => centred(
                shape.info().drawn,
                *center,
                extent,
                &axes(&orientation.matrix()),
            ),
            Place::Edges { corner, edges } => {
                let n = shape.edge_count().min(3);
                Outline::Pieces(vec![Piece::Hull(corners(*corner, &edges[..n]))])
            }
            Place::FromTo { from, to } => Outline::Pieces(vec![Piece::Line {
                points: vec![*from, *to],
                closed: false,
            }]),
            Place::Vertices(v) => Outline::Pieces(vec![Piece::Line {
                points: v.to_vec(),
                closed: true,
            }]),
            Place::Given { center, .. } => Outline::Marker(Marker::Inertia, *center),
            Place::Axial {
                center,
                dims,
                orientation,
            } => axial(
                shape.info().drawn,
                *center,
                dims,
                &axes(&orientation.matrix()),
            ),
            Place::Prism {
                origin,
                polygon,
                length,
                orientation,
            } => {
                let [x, y, z] = axes(&orientation.matrix());
                let at = |p: &[f64; 2], h: f64| add(*origin, comb(&[(p[0], x), (p[1], y), (h, z)]));
                let ends: [Vec<V3>; 2] =
                    [-0.5, 0.5].map(|h| polygon.iter().map(|p| at(p, h * length)).collect());
                let mut pieces: Vec<Piece> = ends
                    .iter()
                    .map(|e| Piece::Line {
                        points: e.clone(),
                        closed: true,
                    })
                    .collect();
                pieces.extend(ends[0].iter().zip(&ends[1]).map(|(a, b)| Piece::Line {
                    points: vec![*a, *b],
                    closed: false,
                }));
                Outline::Pieces(pieces)
            }
            Place::Mesh {
                origin,
                orientation,
                scale,
                mesh,
            } => {
                let [x, y, z] = axes(&orientation.matrix());
                let s = crate::numeric::Real::f64(*scale);
                let points = mesh
                    .points
                    .iter()
                    .map(|p| {
                        add(
                            *origin,
                            comb(&[(p[0] * s, x), (p[1] * s, y), (p[2] * s, z)]),
                        )
                    })
                    .collect();
                Outline::Pieces(vec![Piece::Silhouette {
                    points,
                    faces: mesh.faces.clone(),
                }])
            }
        }
    }
}

/// A part placed by its centre, its local axes `x`, `y`, `z` (columns of
/// its turn) and its dimensions as `Shape::second_moments` takes them.
fn centred(drawn: Drawn, c: V3, e: &[f64; 3], [x, y, z]: &[V3; 3]) -> Outline {
    let rim = |at: V3, r: f64| Piece::Ellipsoid {
        c: at,
        m: [scaled(r, *x), scaled(r, *y), [0.0; 3]],
    };
    let pieces = match drawn {
        Drawn::Point => return Outline::Marker(Marker::Point, c),
        Drawn::Corners => {
            let corner = add(
                c,
                comb(&[(-e[0] / 2.0, *x), (-e[1] / 2.0, *y), (-e[2] / 2.0, *z)]),
            );
            vec![Piece::Hull(corners(
                corner,
                &[scaled(e[0], *x), scaled(e[1], *y), scaled(e[2], *z)],
            ))]
        }
        Drawn::Segment => vec![Piece::Line {
            points: vec![
                add(c, scaled(-e[0] / 2.0, *z)),
                add(c, scaled(e[0] / 2.0, *z)),
            ],
            closed: false,
        }],
        Drawn::Frustum => {
            let (r, inner, l) = (e[0], e[1], e[2]);
            let ends = [add(c, scaled(-l / 2.0, *z)), add(c, scaled(l / 2.0, *z))];
            let mut p = vec![rim(ends[0], r), rim(ends[1], r)];
            p.push(Piece::Side {
                c: ends,
                r: [r, r],
                u: *x,
                v: *y,
            });
            if inner > 0.0 {
                p.extend(ends.map(|at| rim(at, inner)));
            }
            p
        }
        Drawn::Rims => {
            let mut p = vec![rim(c, e[0])];
            if e[1] > 0.0 {
                p.push(rim(c, e[1]));
            }
            p
        }
        Drawn::Ball => vec![Piece::Ellipsoid {
            c,
            m: [[e[0], 0.0, 0.0], [0.0, e[0], 0.0], [0.0, 0.0, e[0]]],
        }],
        Drawn::Ring => vec![Piece::Torus {
            c,
            r: e[0],
            a: e[1],
            u: *x,
            v: *y,
        }],
        // Not placed by a centre and dimensions (`model::place`): drawn
        // as the point their centre is, should one ever be.
        Drawn::Edges | Drawn::Given | Drawn::Dome | Drawn::Extruded | Drawn::Silhouette => {
            return Outline::Marker(Marker::Point, c);
        }
    };
    Outline::Pieces(pieces)
}

/// A cone (dimensions [R₀, a₀, R₁, a₁, L], `c` the middle of its axis) or
/// a hemisphere ([R, r], `c` its sphere's centre).
fn axial(drawn: Drawn, c: V3, d: &[f64; 5], [x, y, z]: &[V3; 3]) -> Outline {
    let rim = |at: V3, r: f64| Piece::Ellipsoid {
        c: at,
        m: [scaled(r, *x), scaled(r, *y), [0.0; 3]],
    };
    let pieces = if drawn == Drawn::Dome {
        vec![
            rim(c, d[0]),
            Piece::Dome {
                c,
                r: d[0],
                u: *x,
                v: *y,
                z: *z,
            },
        ]
    } else {
        let ends = [
            add(c, scaled(-d[4] / 2.0, *z)),
            add(c, scaled(d[4] / 2.0, *z)),
        ];
        let mut p = vec![Piece::Side {
            c: ends,
            r: [d[0], d[2]],
            u: *x,
            v: *y,
        }];
        for (at, r) in [
            (ends[0], d[0]),
            (ends[0], d[1]),
            (ends[1], d[2]),
            (ends[1], d[3]),
        ] {
            if r > 0.0 {
                p.push(rim(at, r));
            }
        }
        p
    };
    Outline::Pieces(pieces)
}

/// The columns of a turn: the local x, y and z axes in the file's frame.
fn axes(r: &[[f64; 3]; 3]) -> [V3; 3] {
    std::array::from_fn(|j| std::array::from_fn(|i| r[i][j]))
}

/// Every corner of the parallelepiped at `corner` spanned by `edges`.
fn corners(corner: V3, edges: &[V3]) -> Vec<V3> {
    (0..1usize << edges.len())
        .map(|bits| {
            edges
                .iter()
                .enumerate()
                .filter(|(k, _)| bits >> k & 1 == 1)
                .fold(corner, |p, (_, e)| add(p, *e))
        })
        .collect()
}

fn add(a: V3, b: V3) -> V3 {
    std::array::from_fn(|k| a[k] + b[k])
}

fn scaled(s: f64, v: V3) -> V3 {
    v.map(|x| s * x)
}

/// Σ sᵢ vᵢ.
fn comb(terms: &[(f64, V3)]) -> V3 {
    terms
        .iter()
        .fold([0.0; 3], |acc, (s, v)| add(acc, scaled(*s, *v)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parallelepiped_has_two_to_the_edges_corners() {
        let c = corners([1.0, 0.0, 0.0], &[[1.0, 0.0, 0.0], [0.0, 2.0, 0.0]]);
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
