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

use super::Place;
use super::place::Placed;
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
    let shortest = place.shortest_span();
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

/// A triangle's area |a × b|/2 from its edges a and b (vertex offsets
/// rounded once): each component of the cross product is a difference of
/// products, 2 units of |a||b| (and 4 more from a and b's rounding), so
/// 6/sin θ units of the area for the angle θ between a and b; the norm 3.
pub(crate) fn triangle_area(v: &[[f64; 3]; 3]) -> f64 {
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
        // Each direction normalised (4 each: |v|² and its root, the
        // division), the cross product of the rounded units (3 on top of
        // theirs), then Newton–Schulz as for a matrix.
        Orientation::Axes(..) => 4.0 + 4.0 + 11.0 + 16.0,
        Orientation::Then(outer, inner) => form_error(outer) + form_error(inner) + 4.0,
        // The normal normalised (4), 2 k kᵀ and the difference (3).
        Orientation::Reflect(_) => 8.0,
    }
}

/// What the error model of a part's own second moment takes from the
/// part beyond its placed shape: the units of its rounding by the frames
/// that placed it (`placed_units`), its mass's own error
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
    pub fn errors(self) -> (f64, f64) {
        (self.placed, self.mass + self.placed)
    }
}
