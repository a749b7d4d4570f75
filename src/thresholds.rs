//! Every threshold massprop's own checks apply, in one place, each with the
//! reason for its size. A threshold is a fraction of the scale named with
//! it, never an absolute number. (A part's "±" tolerance, the user's, is
//! `model::tolerance`.)

/// Physical validity: a principal moment (or second-moment eigenvalue) may
/// be negative, or the triangle inequality I1 + I2 ≥ I3 broken, by this
/// fraction of the largest — a given `inertia`'s rounding in a datasheet, a
/// composed body's rounding, a cut-out that removes exactly what was there
/// — no more. Far above the rounding of a composed tensor (~1e-16
/// relative), far below any real body's thinnest direction. Used by the
/// input check of `inertia` parts, the check of bodies with cut-outs and
/// `check`'s validity checks alike.
pub const VALIDITY_RTOL: f64 = 1e-12;

/// Principal moments within this fraction of the largest are reported as
/// equal, and their axes as not unique. 1e-9 is far above the rounding of a
/// composed tensor (~1e-16 relative) and far below any gap an engineer would
/// call distinct; below it the computed axes are noise.
pub const EQUAL_MOMENT_RTOL: f64 = 1e-9;

/// A triangle's area must exceed this fraction of its longest edge squared.
pub const COLLINEAR_TOLERANCE: f64 = 1e-9;

/// A given `inertia` must be symmetric to this fraction of its largest entry
/// (rounding in a datasheet, not a typo); it is then symmetrised.
pub const SYMMETRY_TOLERANCE: f64 = 1e-9;

/// Edges given as `corner` + `edges` must be perpendicular to this relative
/// tolerance: |eᵢ·eⱼ| ≤ 1e-9 |eᵢ||eⱼ|.
pub const PERPENDICULAR_TOLERANCE: f64 = 1e-9;

/// A rotation matrix must be orthonormal to this (max-norm of RᵀR − E).
pub const MATRIX_TOLERANCE: f64 = 1e-9;

/// A quaternion's norm may differ from 1 by this much: rounding in printed
/// values, not a typo. Its direction is used either way.
pub const QUATERNION_TOLERANCE: f64 = 1e-6;

/// Components of a unit axis whose magnitudes differ by less than this count
/// as tied for the sign rule, so rounding cannot flip an axis.
pub const SIGN_TIE: f64 = 1e-9;

/// A principal moment at most this many unit roundoffs of the largest is
/// zero to rounding: the composed second moment and the eigen solution each
/// carry absolute errors of a few roundoffs of the largest moment, so a
/// ratio to a smaller moment would be noise. At the threshold the error of
/// a ratio is below ~1e-3 of it, hence 2¹².
pub const NEGLIGIBLE_ROUNDOFFS: f64 = 4096.0;

/// A relative change this small and negative is the rounding of two
/// solutions of nearly the same tensor, not a decrease.
pub const ROUNDING_CHANGE: f64 = 64.0 * f64::EPSILON;

/// Default relative tolerance for a blessed scalar: 1e-6, far above the
/// rounding differences between machines and far below a design change.
pub const DEFAULT_RELATIVE_TOL: &str = "0.0001%";

/// Default absolute tolerance of a blessed vector or matrix, as a fraction
/// of its largest component (a relative tolerance per component would fail
/// on rounding noise in components that are zero).
pub const DEFAULT_VECTOR_TOL: f64 = 1e-6;

/// An expected principal axis (`[expect] principal_axes`) must have unit
/// length, and two of them a zero dot product, to this: rows written to
/// three decimals (0.707) are orthonormal to ~2e-4, while a row that is
/// not an axis misses by far more. The angle it allows (~0.06°) is below
/// any tolerance worth checking, and the rows are normalised before use.
pub const AXES_ORTHONORMAL: f64 = 1e-3;
