//! The error model of one part: how far its mass and its own second moment,
//! as the composer computes them, may lie from the exact values for the
//! file's numbers. Counted in units of the arithmetic's unit roundoff
//! (`bounds::unit`): each operation rounds by at most one unit relative to
//! its result (f64: 2⁻⁵³; double-double: 7·2⁻¹⁰⁶, its product's bound,
//! the worst of its operations).
//!
//! NOTE: the counts are of operations whose result keeps the digits of
//! its inputs: products, quotients, square roots and sums of terms of one
//! sign, and differences of the file's own numbers (rounded once, relative
//! to the difference). The closed forms are written so (`shapes`), and the
//! counts include a unit or two of slack each; the exact-rational reference
//! checks them (tests/integration/stress.rs, every shape, both modes).

use super::Shape;
use super::place::{Place, Placed};
use crate::numeric::{M3, Real};
use crate::rotation::Orientation;

/// Unit roundoff of f64, 2⁻⁵³.
pub const U64: f64 = f64::EPSILON / 2.0;

/// The unit in which double-double's roundings are counted: 7·2⁻¹⁰⁶, its
/// worst operation (the product of `numeric::DD`, Joldes, Muller and
/// Popescu 2017, Algorithm 10, within 7u²; a sum rounds by 3u²; the
/// division's three quotient digits and the square root's Newton step by
/// less).
pub const U_DD: f64 = 7.0 * U64 * U64;

/// The unit of the arithmetic `T`.
pub fn unit_of<T: Real>() -> f64 {
    if T::EPS < 1e-20 { U_DD } else { U64 }
}

/// Units of the arithmetic `T` that a part's rounding by the frames that
/// placed it (`Placed`, in f64 units) comes to: its sizes' relative
/// rounding, and for a shape its points span (a triangle, a rod from/to)
/// their positions' error over its shortest edge, twice (a second moment
/// is quadratic in its sizes).
pub fn placed_units<T: Real>(place: &Place, placed: &Placed) -> f64 {
    if placed.units == 0.0 && placed.at == 0.0 {
        return 0.0;
    }
    let length = |a: &[f64; 3], b: &[f64; 3]| {
        (0..3)
            .map(|i| (a[i] - b[i]) * (a[i] - b[i]))
            .sum::<f64>()
            .sqrt()
    };
    let shortest = match place {
        Place::Vertices(v) => length(&v[0], &v[1])
            .min(length(&v[1], &v[2]))
            .min(length(&v[2], &v[0])),
        Place::FromTo { from, to } => length(from, to),
        // A prism's vertices are scaled in its own frame, not placed: their
        // rounding is in `units` (`Frame::place`).
        _ => f64::INFINITY,
    };
    let spanned = 2.0 * f64::from(placed.at) / (U64 * shortest);
    2.0 * (f64::from(placed.units) + spanned) * U64 / unit_of::<T>()
}

/// The error of a part's own second moment C (about its centroid):
/// |δC_jk| ≤ unit · (kappa · √(mag_j mag_k) + rot), with `mag` non-negative
/// magnitudes of the diagonal (|C_jj| for a shape whose local tensor is
/// diagonal) and `rot` the share of the rotation matrix's own rounding,
/// which moves a large local moment into every entry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Own {
    /// The mass's relative error (`mass_error`), in units.
    pub mass: f64,
    /// Includes the mass's.
    pub kappa: f64,
    pub mag: [f64; 3],
    pub rot: f64,
    /// Whether C is diagonal in the file's axes with exact zeros off the
    /// diagonal (a shape not turned): its off-diagonal error is then zero.
    pub diagonal: bool,
}

impl Own {
    /// A turned part's: its local moments' errors (`kappa` units of
    /// `mag`), and its rotation matrix's own error of `rho` units per entry
    /// (`turn_error`), which moves (2ρ + 1) units of `spread`, the local
    /// moments' total magnitude, into every entry.
    pub fn turned(mass: f64, kappa: f64, mag: [f64; 3], rho: f64, spread: f64) -> Own {
        Own {
            mass,
            kappa,
            mag,
            rot: if rho > 0.0 {
                (2.0 * rho + 1.0) * spread
            } else {
                0.0
            },
            diagonal: false,
        }
    }
}

/// Roundings of a shape's local second moments beyond its mass's: each
/// shape's module counts them over the operations of its closed forms
/// (`ShapeKind::MOMENT_ROUNDINGS`).
pub fn closed_form(shape: Shape) -> f64 {
    shape.moment_roundings()
}

/// Roundings of R diag(d) Rᵀ beyond diag(d): two products and two sums.
pub const TURN: f64 = 4.0;

/// Roundings of (m/12) Σ eₖeₖᵀ over up to three edges beyond the mass's:
/// m/12, two products, two sums, and the edge vector's own difference
/// (from/to, a triangle's vertices less its centroid) twice.
pub const OUTER: f64 = 9.0;

/// Roundings of a given tensor's R C Rᵀ: nine products of three factors
/// summed (10), and the diagonal of C = tr(I)/2 E − I (2, relative to
/// the magnitudes `part::diagonal_second_moment` takes).
pub const GIVEN: f64 = 12.0;

/// Roundings of a placed shape's measure (volume, area or length) from
/// its numbers, beyond the density's product: the shape's own count
/// (`ShapeKind::MEASURE_ROUNDINGS`), a norm per edge (3 for the squares'
/// sum, 2 for the root) and a product, a triangle's area from a cross
/// product, a polygon's area, a mesh's scale.
pub fn measure_error(shape: Shape, place: &Place) -> f64 {
    match place {
        // The shape's own count (`ShapeKind::MEASURE_ROUNDINGS`).
        Place::Centered { .. } | Place::Axial { .. } => shape.measure_roundings(),
        // A norm per edge (3 for the squares' sum, 2 for the root) and a
        // product.
        Place::Edges { .. } => 6.0 * shape.edge_count() as f64,
        Place::FromTo { .. } => 7.0,
        Place::Given { .. } => 0.0,
        Place::Vertices(v) => triangle_area(v),
        // The polygon's area in double-double (32 of its units of the
        // magnitudes Σ|cᵢ|/2 it is summed from, counted here as units of
        // either arithmetic: 32 f64 units are far more than it needs),
        // rounded once, times the length.
        Place::Prism { polygon, .. } => {
            3.0 + 32.0 * crate::shapes::prism::polygon(polygon).spread.area
        }
        // s^k (k products, and s's own rounding to T k times); the
        // measure's own bound, relative, is added by `part` in T's units.
        Place::Mesh { mesh, .. } => 2.0 * f64::from(mesh.mode.power()) + 1.0,
    }
}

/// A triangle's area |a × b|/2 from its edges a and b (vertex offsets
/// rounded once): each component of the cross product is a difference of
/// products, 2 units of |a||b| (and 4 more from a and b's rounding), so
/// 6/sin θ units of the area for the angle θ between a and b; the norm 3.
fn triangle_area(v: &[[f64; 3]; 3]) -> f64 {
    let a: [f64; 3] = std::array::from_fn(|i| v[1][i] - v[0][i]);
    let b: [f64; 3] = std::array::from_fn(|i| v[2][i] - v[0][i]);
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let sq = |x: [f64; 3]| x.iter().map(|t| t * t).sum::<f64>();
    // 1/sin θ = |a||b|/|a × b|; the model rejects degenerate triangles,
    // and a far one rounds its edges here: 2 units of slack, and a floor.
    let inv_sin = (sq(a) * sq(b) / sq(c)).sqrt();
    let inv_sin = if inv_sin.is_finite() { inv_sin } else { 1e16 };
    5.0 + 8.0 * inv_sin
}

/// How far each component of a part's centroid, as `part::centroid` forms
/// it in double-double, may lie from the exact centroid: nothing where it
/// is a number of the file (a centre) or a sum of two halves (from/to), or
/// where the vertices or the edges do not move it off the corner along
/// that axis; else 2⁻⁹⁸ of it (a few double-double operations); and the
/// rounding of its position by the frames that placed it (`Placed::at`).
pub fn centroid_error(place: &Place, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
    if let Place::Axial { .. } | Place::Prism { .. } = place {
        return offset_centroid_error(place, centroid).map(|e| e + at);
    }
    let inexact = |j: usize| match place {
        Place::Centered { .. } | Place::Given { .. } | Place::FromTo { .. } => false,
        Place::Edges { edges, .. } => edges.iter().any(|e| e[j] != 0.0),
        Place::Vertices(v) => !(v[0][j] == v[1][j] && v[1][j] == v[2][j]),
        Place::Axial { .. } | Place::Prism { .. } => unreachable!("returned above"),
        Place::Mesh { .. } => true,
    };
    // A mesh's centroid: its integrals' bound, scaled and turned (a row of
    // R has 1-norm at most √3 < 2).
    let mesh = match place {
        Place::Mesh { scale, mesh, .. } => 2.0 * mesh.bound.centroid * scale.hi.abs(),
        _ => 0.0,
    };
    std::array::from_fn(|j| {
        at + mesh
            + if inexact(j) {
                centroid[j].abs() * 3.155_443_620_884_047e-30
            } else {
                0.0
            }
    })
}

/// How far each component of an offset part's centroid may lie from the
/// exact one (see `centroid_error`): the local offset's own error
/// (a few tens of double-double units of the magnitudes it is formed
/// from: `Spread` for a prism's polygon, the larger of the radius and
/// the length for a cone or hemisphere), its turn by R (the rotation's own
/// error ρ per entry, two products and sums), and the sum with the
/// placing point.
fn offset_centroid_error(place: &Place, centroid: &[f64; 3]) -> [f64; 3] {
    let (spread, offset, orientation): ([f64; 3], [f64; 3], &Orientation) = match place {
        Place::Axial {
            dims, orientation, ..
        } => {
            let big = dims[0].abs().max(dims[4].abs()).max(dims[2].abs());
            ([0.0, 0.0, 64.0 * big], [0.0, 0.0, big], orientation)
        }
        Place::Prism {
            polygon: p,
            orientation,
            ..
        } => {
            let poly = crate::shapes::prism::polygon(p);
            let g = poly.centroid.map(|x| x.f64().abs());
            let s = poly.spread.centroid;
            (
                [32.0 * s[0] + 4.0 * g[0], 32.0 * s[1] + 4.0 * g[1], 0.0],
                [g[0], g[1], 0.0],
                orientation,
            )
        }
        Place::Centered { .. }
        | Place::Edges { .. }
        | Place::FromTo { .. }
        | Place::Vertices(_)
        | Place::Given { .. }
        | Place::Mesh { .. } => {
            unreachable!("only an axial part or a prism has an offset centroid")
        }
    };
    let r: M3<f64> = orientation.matrix();
    let rho = turn_error(orientation, &r);
    let u = U_DD;
    std::array::from_fn(|i| {
        let turned: f64 = (0..3)
            .map(|k| r[i][k].abs() * spread[k] + (rho + 3.0) * offset[k])
            .sum();
        u * (turned + 4.0 * centroid[i].abs())
    })
}

/// How far each entry of a rotation matrix as computed may lie from the
/// exact rotation the file gives, in units: none for a signed permutation
/// (quarter turns are exact in every form); else by the form's operations.
pub fn turn_error(o: &Orientation, r: &M3<f64>) -> f64 {
    let exact = r.iter().flatten().all(|x| *x == 0.0 || x.abs() == 1.0);
    if exact { 0.0 } else { form_error(o) }
}

fn form_error(o: &Orientation) -> f64 {
    match o {
        Orientation::Identity => 0.0,
        // Sums of four products over |q|², and the division.
        Orientation::Quaternion(_) => 10.0,
        // The axis normalised (4), sin and cos (3), c + s k + (1 − c) k kᵀ.
        Orientation::AxisAngle(..) => 16.0,
        // Three elementary turns (3 each) multiplied twice.
        Orientation::Euler(..) => 24.0,
        // Newton–Schulz leaves the orthonormal defect δ as ~δ² (1e-18 at
        // the model's 1e-9) and a product's roundings.
        Orientation::Matrix(_) => 16.0,
        Orientation::Then(outer, inner) => form_error(outer) + form_error(inner) + 4.0,
        // The normal normalised (4), 2 k kᵀ and the difference (3).
        Orientation::Reflect(_) => 8.0,
    }
}
