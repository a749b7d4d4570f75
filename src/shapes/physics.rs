//! A placed shape's physics in the file's units, generic over the
//! arithmetic and over how its numbers are read (`Lift`): the measure its
//! density multiplies, its centroid and its own second moment about that
//! centroid in the file's axes, with the error model of the arithmetic
//! that formed it (`error`). `part` composes these with a part's mass.

use super::error::{self, Own};
use super::lift::{Fixed, Lift, Slot, dims_in, lift3, xyz};
use super::place::Place;
use super::{Shape, offset, turned};
use crate::numeric::{DD, M3, Real, norm_of};
use crate::rotation::Orientation;

/// What the error model of a part's own second moment takes from the
/// part beyond its placement: the units of its rounding by the frames
/// that placed it (`error::placed_units`), its mass's own error
/// (`part::error::mass_error`), and whether that mass is a density times
/// the measure.
#[derive(Debug, Clone, Copy)]
pub struct Units {
    pub placed: f64,
    pub mass: f64,
    pub by_density: bool,
}

impl Units {
    /// The frames' units and the mass's, (placed, μ).
    fn errors(self) -> (f64, f64) {
        (self.placed, self.mass + self.placed)
    }
}

/// The diagonal entry `a` of ∫ρρᵀ dm = tr(I)/2 E − I of a given tensor:
/// (I_jj + I_kk − I_aa)/2, formed as ((I_jj − I_aa) + I_kk)/2 with I_jj
/// the one of the other two closer to I_aa.
///
/// NOTE: not tr(I)/2 − I_aa: for a long thin component given by its
/// datasheet (principal moments 1e-12, 1, 1: an antenna), tr(I)/2 rounds
/// to an ulp of 1 and the two small entries lost all but 4 digits (2e-4).
/// I_jj − I_aa of the closer pair is exact when they are within a factor
/// of 2 (Sterbenz), which the triangle inequality of a valid tensor makes
/// the case whenever the result is small; so the entry rounds once.
fn diagonal_second_moment<T: Real>(i: &M3<T>, a: usize) -> T {
    let (j, k) = ((a + 1) % 3, (a + 2) % 3);
    let distance = |b: usize| {
        let d = i[b][b] - i[a][a];
        if d < T::of(0.0) { -d } else { d }
    };
    let (j, k) = if distance(j) <= distance(k) {
        (j, k)
    } else {
        (k, j)
    };
    ((i[j][j] - i[a][a]) + i[k][k]) / T::of(2.0)
}

/// The magnitude the diagonal entry `a` of a given tensor's second moment
/// is formed from in `diagonal_second_moment`: (|I_jj − I_aa| + |I_kk|)/2,
/// its error at most 2 units of it.
fn diagonal_magnitude<T: Real>(i: &M3<T>, a: usize) -> f64 {
    let (j, k) = ((a + 1) % 3, (a + 2) % 3);
    let f = |x: T| x.f64();
    let dist = |b: usize| (f(i[b][b]) - f(i[a][a])).abs();
    let (j, k) = if dist(j) <= dist(k) { (j, k) } else { (k, j) };
    (dist(j) + f(i[k][k]).abs()) / 2.0
}

/// A corner-and-edges part's edges, read through `l`.
fn edges_in<T: Real, L: Lift>(edges: &[[f64; 3]; 3], l: L) -> [[T; 3]; 3] {
    std::array::from_fn(|e| lift3(l, &edges[e], xyz(|i| Slot::Edge(e as u8, i))))
}

/// A rod's `to − from`, read through `l`.
fn span_in<T: Real, L: Lift>(from: &[f64; 3], to: &[f64; 3], l: L) -> [T; 3] {
    let a: [T; 3] = lift3(l, from, xyz(Slot::At));
    let b: [T; 3] = lift3(l, to, xyz(Slot::To));
    std::array::from_fn(|i| b[i] - a[i])
}

impl Place {
    /// Volume, area or length of the placed shape, the measure its
    /// density multiplies, its numbers read through `l`.
    pub fn measure<T: Real, L: Lift>(&self, shape: Shape, l: L) -> T {
        match (self, shape) {
            (Place::Centered { extent: e, .. }, _) => {
                let e: [T; 3] = dims_in(e, l);
                shape.measure_of(&e[..shape.dim_count()])
            }
            (Place::Edges { edges, .. }, _) => edges_in::<T, L>(edges, l)[..shape.edge_count()]
                .iter()
                .fold(T::of(1.0), |acc, e| acc * norm_of(e)),
            (Place::FromTo { from, to }, _) => norm_of(&span_in::<T, L>(from, to, l)),
            (Place::Given { .. }, _) => T::of(1.0),
            (Place::Axial { dims, .. }, _) => {
                let d: [T; 5] = dims_in(dims, l);
                shape.measure_of(&d[..shape.dim_count()])
            }
            (
                Place::Prism {
                    polygon, length, ..
                },
                _,
            ) => {
                let area = crate::shapes::prism::polygon(polygon).area;
                T::of_dd(area) * T::var(*length, l.rate(Slot::Dim(0)))
            }
            (Place::Mesh { scale, mesh, .. }, _) => {
                let s = T::of_dd(*scale);
                let mut m = T::of_dd(mesh.measure);
                for _ in 0..mesh.mode.power() {
                    m = m * s;
                }
                m
            }
            (Place::Vertices(v), _) => {
                let d = triangle_offsets::<T, L>(v, l);
                let (a, b) = (sub3(d[1], d[0]), sub3(d[2], d[0]));
                let c = [
                    a[1] * b[2] - a[2] * b[1],
                    a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0],
                ];
                norm_of(&c) / T::of(2.0)
            }
        }
    }

    /// The centroid (file units) in the arithmetic `T`, the numbers read
    /// through `l`: in double-double with `Fixed`, `part::centroid`.
    pub fn centroid<T: Real, L: Lift>(&self, shape: Shape, l: L) -> [T; 3] {
        let half = T::of(0.5);
        match self {
            Place::Axial { .. } | Place::Prism { .. } => offset::centroid(shape, self, l),
            Place::Centered { center, .. } | Place::Given { center, .. } => {
                lift3(l, center, xyz(Slot::At))
            }
            Place::Vertices(v) => triangle_centroid(v, l),
            Place::Edges { corner, edges } => {
                let c: [T; 3] = lift3(l, corner, xyz(Slot::At));
                let e: [[T; 3]; 3] = edges_in(edges, l);
                std::array::from_fn(|i| e.iter().fold(c[i], |acc, e| acc + e[i] * half))
            }
            Place::FromTo { from, to } => {
                let a: [T; 3] = lift3(l, from, xyz(Slot::At));
                let b: [T; 3] = lift3(l, to, xyz(Slot::To));
                std::array::from_fn(|i| (a[i] + b[i]) * half)
            }
            Place::Mesh {
                origin,
                orientation,
                scale,
                mesh,
            } => {
                let r: M3<T> = orientation.matrix();
                let c = mesh.centroid.map(|x| T::of_dd(x * *scale));
                let o: [T; 3] = lift3(l, origin, xyz(Slot::At));
                std::array::from_fn(|i| o[i] + r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2])
            }
        }
    }

    /// ∫ρρᵀ dm of the placed shape about its own centroid, in the file's
    /// axes and units, for the mass `m`; with its error model when `units`
    /// are given (the per-part figures and the checks on the input need
    /// none of it).
    pub fn own_second_moment<T: Real, L: Lift>(
        &self,
        shape: Shape,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        let bound = units.is_some();
        // The frames' rounding of the part's numbers, on top of its own: its
        // sizes and mass relative; a shape spanned by vectors the frames
        // turned numerically (edges, ends, vertices) absolute in every entry,
        // as a turn's own error is (a component that should be 0 is not).
        // Returns (placed, μ): the frames' units and the mass's.
        let errors = || units.expect("the error model was asked for").errors();
        let outer = |j: &M3<T>| {
            let (placed, mu) = errors();
            let mag: [f64; 3] = std::array::from_fn(|a| j[a][a].f64().abs());
            Own {
                mass: mu,
                kappa: mu + error::OUTER,
                mag,
                rot: placed * mag.iter().sum::<f64>(),
                diagonal: false,
            }
        };
        let zero = T::of(0.0);
        let twelfth = m / T::of(12.0);
        let mut j = [[zero; 3]; 3];
        let mut add_outer = |e: [T; 3]| {
            for a in 0..3 {
                for b in 0..3 {
                    j[a][b] = j[a][b] + twelfth * e[a] * e[b];
                }
            }
        };
        if let Place::Mesh {
            orientation,
            scale,
            mesh,
            ..
        } = self
        {
            return mesh_second_moment(units, orientation, *scale, mesh, m);
        }
        let centred = match self {
            Place::Centered {
                extent,
                orientation,
                ..
            } => Some((&extent[..], orientation)),
            Place::Axial {
                dims, orientation, ..
            } => Some((&dims[..], orientation)),
            _ => None,
        };
        match self {
            Place::Centered { .. } | Place::Axial { .. } => {
                let (extent, orientation) = centred.expect("matched");
                let mut dims = [zero; 5];
                for (k, (d, x)) in dims.iter_mut().zip(extent).enumerate() {
                    *d = T::var(*x, l.rate(Slot::Dim(k as u8)));
                }
                let d = shape.second_moments(m, &dims[..shape.dim_count()]);
                if let Orientation::Identity = orientation {
                    let own = bound.then(|| {
                        let mu = errors().1;
                        Own {
                            mass: mu,
                            kappa: mu + error::closed_form(shape),
                            mag: d.map(|x| x.f64().abs()),
                            rot: 0.0,
                            diagonal: true,
                        }
                    });
                    let j = std::array::from_fn(|a| {
                        std::array::from_fn(|b| if a == b { d[a] } else { zero })
                    });
                    return (j, own);
                }
                let r: M3<T> = orientation.matrix();
                for a in 0..3 {
                    for b in a..3 {
                        j[a][b] = r[a][0] * d[0] * r[b][0]
                            + r[a][1] * d[1] * r[b][1]
                            + r[a][2] * d[2] * r[b][2];
                        j[b][a] = j[a][b];
                    }
                }
                let own = bound.then(|| {
                    let mu = errors().1;
                    let rho = error::turn_error(orientation, &r.map(|row| row.map(T::f64)));
                    let spread: f64 = d.iter().map(|x| x.f64().abs()).sum();
                    let mag = std::array::from_fn(|a| j[a][a].f64().abs());
                    let kappa = mu + error::closed_form(shape) + error::TURN;
                    Own::turned(mu, kappa, mag, rho, spread)
                });
                return (j, own);
            }
            Place::Edges { edges, .. } => {
                for e in &edges_in::<T, L>(edges, l)[..shape.edge_count()] {
                    add_outer(*e);
                }
            }
            Place::FromTo { from, to } => add_outer(span_in(from, to, l)),
            // ∫ρρᵀ dm of a uniform triangle about its centroid g is
            // (m/12) Σ dᵢdᵢᵀ with dᵢ = vᵢ − g (from ∫ρρᵀ dA = (A/12)(Σ vᵢvᵢᵀ + s sᵀ),
            // s = Σ vᵢ, about any origin).
            Place::Vertices(v) => {
                for d in triangle_offsets::<T, L>(v, l) {
                    add_outer(d);
                }
            }
            Place::Prism { .. } => {
                let (j, own) = offset::prism_second_moment(self, m, bound, errors, l);
                return (j, own);
            }
            Place::Mesh { .. } => unreachable!("a mesh returned above"),
            Place::Given {
                inertia,
                orientation,
                ..
            } => {
                // ∫ρρᵀ dm = tr(I)/2 E − I; a cut-out's is subtracted.
                let i: M3<T> = inertia.map(|r| r.map(T::of));
                let sign = T::of(if m < zero { -1.0 } else { 1.0 });
                let local: M3<T> = std::array::from_fn(|a| {
                    std::array::from_fn(|b| {
                        sign * if a == b {
                            diagonal_second_moment(&i, a)
                        } else {
                            -i[a][b]
                        }
                    })
                });
                let r: M3<T> = orientation.matrix();
                let j = turned(&r, &local);
                let own = bound.then(|| {
                    let mu = errors().1;
                    let r = r.map(|row| row.map(T::f64));
                    let rho = error::turn_error(orientation, &r);
                    // |C_kl| ≤ √(ℓ_k ℓ_l) for the positive semi-definite local
                    // C, ℓ the magnitudes its diagonal is formed from; so each
                    // entry of R C Rᵀ is at most v_a v_b, v = |R| √ℓ.
                    let spread: [f64; 3] = std::array::from_fn(|a| diagonal_magnitude(&i, a));
                    let v: [f64; 3] = std::array::from_fn(|a| {
                        (0..3).map(|k| r[a][k].abs() * spread[k].sqrt()).sum()
                    });
                    let total: f64 = spread.iter().sum::<f64>()
                        + (0..3)
                            .flat_map(|k| (0..3).filter(move |l| *l != k).map(move |l| (k, l)))
                            .map(|(k, l)| inertia[k][l].abs())
                            .sum::<f64>();
                    Own::turned(mu, mu + error::GIVEN, v.map(|x| x * x), rho, total)
                });
                return (j, own);
            }
        }
        let own = bound.then(|| outer(&j));
        (j, own)
    }
}

/// A mesh's own second moment, C = m s² R (J/V) Rᵀ for its integrals'
/// J about the centroid and measure V (volume or area) in its file's
/// units and the scale s to this file's, with its error model: J/V's
/// bound (absolute, from `mesh::Bound`) moved through R into every entry
/// (at most 3 of it, |R| rows of 1-norm √3 twice), and the mass's.
fn mesh_second_moment<T: Real>(
    units: Option<Units>,
    orientation: &Orientation,
    scale: DD,
    mesh: &crate::mesh::MeshBody,
    m: T,
) -> (M3<T>, Option<Own>) {
    let v = T::of_dd(mesh.measure);
    let s = T::of_dd(scale);
    let k = m * s * s / v;
    let local: M3<T> = mesh.second.map(|row| row.map(|x| k * T::of_dd(x)));
    let r: M3<T> = orientation.matrix();
    let mut j = [[T::of(0.0); 3]; 3];
    for a in 0..3 {
        for b in a..3 {
            let mut x = T::of(0.0);
            for p in 0..3 {
                for q in 0..3 {
                    x = x + r[a][p] * local[p][q] * r[b][q];
                }
            }
            j[a][b] = x;
            j[b][a] = x;
        }
    }
    let own = units.map(|u| {
        let unit = error::unit_of::<T>();
        let rel_v = mesh.bound.measure / mesh.measure.hi.abs();
        let measured = if u.by_density { rel_v / unit } else { 0.0 };
        let mu = u.mass + u.placed + measured;
        let kf = k.f64().abs();
        let rf = r.map(|row| row.map(T::f64));
        let rho = error::turn_error(orientation, &rf);
        let spread: f64 = (0..3).map(|a| local[a][a].f64().abs()).sum::<f64>()
            + (0..3)
                .flat_map(|p| (0..3).filter(move |q| *q != p).map(move |q| (p, q)))
                .map(|(p, q)| local[p][q].f64().abs())
                .sum::<f64>();
        // J/V's relative rounding of V (its bound) and J's absolute bound.
        let mut own = Own::turned(
            mu,
            mu + rel_v / unit + error::GIVEN + 4.0,
            std::array::from_fn(|a| j[a][a].f64().abs()),
            rho,
            spread,
        );
        own.rot += 3.0 * kf * mesh.bound.second / unit + spread * rel_v / unit;
        own
    });
    (j, own)
}

fn triangle_centroid<T: Real, L: Lift>(v: &[[f64; 3]; 3], l: L) -> [T; 3] {
    let p: [[T; 3]; 3] =
        std::array::from_fn(|k| lift3(l, &v[k], xyz(|i| Slot::Vertex(k as u8, i))));
    std::array::from_fn(|i| (p[0][i] + p[1][i] + p[2][i]) / T::of(3.0))
}

/// A triangle's vertices less its centroid, in double-double before the
/// rounding to T: far from the origin the offsets keep their digits (the
/// rates through `l` beside them: the vertex's less the centroid's).
fn triangle_offsets<T: Real, L: Lift>(v: &[[f64; 3]; 3], l: L) -> [[T; 3]; 3] {
    let g: [DD; 3] = triangle_centroid(v, Fixed);
    let rate = |k: usize, i: usize| l.rate(Slot::Vertex(k as u8, i as u8));
    std::array::from_fn(|k| {
        std::array::from_fn(|i| {
            let mean = (rate(0, i) + rate(1, i) + rate(2, i)) / 3.0;
            T::var_dd(DD::of(v[k][i]) - g[i], rate(k, i) - mean)
        })
    })
}

fn sub3<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    std::array::from_fn(|i| a[i] - b[i])
}
