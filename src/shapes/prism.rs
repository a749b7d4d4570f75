//! A prism: a polygon in the local x–y plane extruded along local z from
//! −L/2 to +L/2. Its area, centroid and second moments come from the
//! polygon by Green's theorem, in double-double about its first vertex.
//!
//! NOTE: the derivation. For a simple polygon with vertices qᵢ (either
//! orientation) and cᵢ = qᵢ × qᵢ₊₁ = xᵢyᵢ₊₁ − xᵢ₊₁yᵢ, Green's theorem turns
//! each area integral into a sum over the edges (each edge with the origin
//! a triangle of signed area cᵢ/2):
//!
//! - 2A = Σ cᵢ;
//! - ∫x dA = Σ cᵢ (xᵢ + xᵢ₊₁)/6, ∫y dA likewise;
//! - ∫x² dA = Σ cᵢ (xᵢ² + xᵢxᵢ₊₁ + xᵢ₊₁²)/12, ∫y² dA likewise;
//! - ∫xy dA = Σ cᵢ (2xᵢyᵢ + xᵢyᵢ₊₁ + xᵢ₊₁yᵢ + 2xᵢ₊₁yᵢ₊₁)/24.
//!
//! Each sum is signed by the orientation, and their ratios are not: per
//! unit area about the centroid ḡ = (∫x, ∫y)/A, jₓₓ = ∫x²/A − ḡₓ², and so
//! on. The vertices are taken relative to the first one, q = p − p₀, exact
//! in double-double: a polygon far from its local origin keeps its digits
//! (and the centroid p₀ + ḡ too). The sums are in double-double; for a
//! convex polygon their terms share one sign (a fan of triangles from p₀),
//! for another the error model (`Polygon::spread`) takes the sum of their
//! magnitudes. The extrusion adds m L²/12 along z and nothing else: the
//! local tensor has an x–y product and is block-diagonal.

use super::{Dims, Drawn, MaterialRule, PER_VOLUME, Shape, ShapeInfo, ShapeKind};
use crate::numeric::{DD, Real};

/// A polygon's area and moments, per unit area about its centroid.
#[derive(Debug, Clone, Copy)]
pub struct Polygon {
    /// |A|.
    pub area: DD,
    /// The centroid, in the polygon's own coordinates.
    pub centroid: [DD; 2],
    /// ∫(x − ḡₓ)² dA/A, ∫(y − ḡ_y)² dA/A, ∫(x − ḡₓ)(y − ḡ_y) dA/A.
    pub second: [DD; 3],
    /// For the error model: Σ|cᵢ|/|2A| (1 for a convex polygon), and the
    /// magnitudes the three entries of `second` and the centroid's two
    /// components are formed from (`shapes::error`).
    pub spread: Spread,
}

/// The magnitudes a `Polygon`'s figures are formed from: each is within
/// a few double-double units of these.
#[derive(Debug, Clone, Copy)]
pub struct Spread {
    pub area: f64,
    pub second: [f64; 3],
    pub centroid: [f64; 2],
}

/// The polygon's figures (at least 3 vertices, non-zero area: the model
/// checks).
pub fn polygon(p: &[[f64; 2]]) -> Polygon {
    let p0 = p[0];
    let rel = |v: [f64; 2]| [DD::of(v[0]) - DD::of(p0[0]), DD::of(v[1]) - DD::of(p0[1])];
    let zero = DD::of(0.0);
    let (mut a2, mut sx, mut sy, mut sxx, mut syy, mut sxy) = (zero, zero, zero, zero, zero, zero);
    let mut mag = [0.0f64; 6];
    let n = p.len();
    for i in 0..n {
        let (a, b) = (rel(p[i]), rel(p[(i + 1) % n]));
        let c = a[0] * b[1] - b[0] * a[1];
        let cx = a[0] + b[0];
        let cy = a[1] + b[1];
        let xx = a[0] * a[0] + a[0] * b[0] + b[0] * b[0];
        let yy = a[1] * a[1] + a[1] * b[1] + b[1] * b[1];
        let xy = DD::of(2.0) * a[0] * a[1] + a[0] * b[1] + b[0] * a[1] + DD::of(2.0) * b[0] * b[1];
        a2 += c;
        sx += c * cx;
        sy += c * cy;
        sxx += c * xx;
        syy += c * yy;
        sxy += c * xy;
        // Magnitudes: |c| times the magnitudes its factor is formed from.
        let (ax, ay, bx, by) = (a[0].f64(), a[1].f64(), b[0].f64(), b[1].f64());
        let ca = (ax * by).abs() + (bx * ay).abs();
        mag[0] += ca;
        mag[1] += ca * (ax.abs() + bx.abs());
        mag[2] += ca * (ay.abs() + by.abs());
        mag[3] += ca * (ax * ax + (ax * bx).abs() + bx * bx);
        mag[4] += ca * (ay * ay + (ay * by).abs() + by * by);
        mag[5] += ca
            * (2.0 * (ax * ay).abs() + (ax * by).abs() + (bx * ay).abs() + 2.0 * (bx * by).abs());
    }
    let three = DD::of(3.0);
    let g = [sx / (three * a2), sy / (three * a2)];
    let second = [
        sxx / (DD::of(6.0) * a2) - g[0] * g[0],
        syy / (DD::of(6.0) * a2) - g[1] * g[1],
        sxy / (DD::of(12.0) * a2) - g[0] * g[1],
    ];
    let area = a2.abs() / DD::of(2.0);
    let a2f = a2.f64().abs();
    let cond = mag[0] / a2f;
    let (gx, gy) = (g[0].f64().abs(), g[1].f64().abs());
    let (ex, ey) = (mag[1] / (3.0 * a2f), mag[2] / (3.0 * a2f));
    let spread = Spread {
        area: cond,
        centroid: [ex + cond * gx, ey + cond * gy],
        second: [
            (mag[3] / (6.0 * a2f) + gx * gx) * (1.0 + cond) + 2.0 * gx * ex,
            (mag[4] / (6.0 * a2f) + gy * gy) * (1.0 + cond) + 2.0 * gy * ey,
            (mag[5] / (12.0 * a2f) + gx * gy) * (1.0 + cond) + gx * ey + gy * ex,
        ],
    };
    Polygon {
        area,
        centroid: [DD::of(p0[0]) + g[0], DD::of(p0[1]) + g[1]],
        second,
        spread,
    }
}

/// The prism's mirror image in its local x–z plane (y → −y): the polygon
/// with y negated, its order reversed so that it keeps its orientation.
/// (A prism mirrored in any plane is this image turned by a proper
/// rotation.)
pub fn mirrored(p: &[[f64; 2]]) -> Vec<[f64; 2]> {
    p.iter().rev().map(|v| [v[0], -v[1]]).collect()
}

/// The prism, in the registry (`shapes::registry!`).
#[derive(Clone, Copy, Debug)]
pub struct Prism;

impl ShapeKind for Prism {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Prism,
        name: "prism",
        keys: &[
            "density", "polygon", "length", "origin", "rotation", "mass", "remove", "material",
        ],
        density: Some(PER_VOLUME),
        dims: Dims::Polygon,
        centred: &[],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        drawn: Drawn::Extruded,
        degenerate: "fewer than 3 vertices, a repeated vertex, crossing edges or no area",
        help: "a prism takes `mass` or `density`, a `polygon` = [[x, y], …] in its local x–y plane (either orientation) and `length` along its local z (from −length/2 to +length/2), with optional `origin` (where its local origin goes) and `rotation`",
    };

    /// (its area is its polygon's: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 2.0;

    /// (its second moment is its polygon’s: `shapes::offset`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(2);

    fn measure<T: Real>(d: &[T]) -> T {
        let [area, length] = d else {
            unreachable!("the model passes a prism its area and length")
        };
        *area * *length
    }

    fn second_moments<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [_, _] = d else {
            unreachable!("the model passes a prism its area and length")
        };
        [T::of(0.0); 3]
    }

    fn axial_offset<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rectangle [x0, x0 + a] × [y0, y0 + b]: its figures by hand.
    #[test]
    fn a_rectangle_far_from_its_origin_keeps_its_digits() {
        let (x0, y0, a, b) = (1e9, -3e8, 0.75, 0.125);
        for poly in [
            vec![[x0, y0], [x0 + a, y0], [x0 + a, y0 + b], [x0, y0 + b]],
            vec![[x0, y0 + b], [x0 + a, y0 + b], [x0 + a, y0], [x0, y0]],
        ] {
            let p = polygon(&poly);
            assert_eq!(p.area.f64(), a * b);
            assert_eq!(p.centroid[0].f64(), (DD::of(x0) + DD::of(a / 2.0)).f64());
            let c = [
                (p.centroid[0] - DD::of(x0)).f64(),
                (p.centroid[1] - DD::of(y0)).f64(),
            ];
            assert_eq!(c, [a / 2.0, b / 2.0]);
            let s = p.second.map(|x| x.f64());
            assert!((s[0] - a * a / 12.0).abs() <= 1e-15 * a * a);
            assert!((s[1] - b * b / 12.0).abs() <= 1e-15 * b * b);
            assert!(s[2].abs() <= 1e-15 * a * b);
            assert_eq!(p.spread.area, 1.0);
        }
    }

    #[test]
    fn the_mirror_negates_y_and_keeps_the_orientation() {
        let p = [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]];
        let m = mirrored(&p);
        assert_eq!(m, vec![[0.0, -1.0], [2.0, 0.0], [0.0, 0.0]]);
        let (a, b) = (polygon(&p), polygon(&m));
        assert_eq!(a.area.f64(), b.area.f64());
        assert_eq!(a.second[2].f64(), -b.second[2].f64());
    }
}
