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

use super::common::{add, axes, comb, density_power, flip, mirror_axis, norm1, offset_centroid, offset_centroid_error, points, reset_turn, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::error;
use super::lift::Lift;
use super::outline::{Outline, Piece, V3};
use super::{
    MaterialRule, Mover, Own, PER_VOLUME, Shape, ShapeInfo, ShapeKind, Slot, Units, turned,
};
use crate::numeric::M3;
use crate::rotation::Orientation;
use std::sync::Arc;
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


/// A prism, in its file's units: where its local origin goes, its
/// polygon in the local x–y plane (either orientation), its length along
/// local z (from −length/2 to +length/2) and the turn of its local axes.
#[derive(Debug, Clone, PartialEq)]
pub struct Prism {
    pub origin: [f64; 3],
    pub polygon: Arc<[[f64; 2]]>,
    pub length: f64,
    pub orientation: Orientation,
}

/// The units of the arithmetic `T` by which a prism's local figures
/// (`Polygon`, double-double) may be off, relative to the magnitudes `ell`
/// of the diagonal: 32 double-double units of the magnitudes each entry is
/// formed from.
fn polygon_units<T: Real>(poly: &Polygon, ell: &[f64; 3]) -> f64 {
    let s = poly.spread.second;
    let ratio = |x: f64, y: f64| if y > 0.0 { x / y } else { 0.0 };
    let worst = ratio(s[0], ell[0])
        .max(ratio(s[1], ell[1]))
        .max(ratio(s[2], (ell[0] * ell[1]).sqrt()));
    32.0 * error::U_DD / error::unit_of::<T>() * worst
}

impl ShapeKind for Prism {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Prism,
        name: "prism",
        keys: &[
            "density", "polygon", "length", "origin", "rotation", "mass", "remove", "material",
        ],
        density: Some(PER_VOLUME),
        sizes: &["polygon", "length"],
        size_items: 0,
        centred: &[],
        spanned: None,
        material: MaterialRule::Volume,
        real_size: None,
        nonzero_moments: 0,
        degenerate: "fewer than 3 vertices, a repeated vertex, crossing edges or no area",
        help: "a prism takes `mass` or `density`, a `polygon` = [[x, y], …] in its local x–y plane (either orientation) and `length` along its local z (from −length/2 to +length/2), with optional `origin` (where its local origin goes) and `rotation`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "polygon extruded along local z, length L; by Green's theorem over its edges (xᵢ, yᵢ)→(xᵢ₊₁, yᵢ₊₁), cᵢ = xᵢyᵢ₊₁ − xᵢ₊₁yᵢ: A = Σcᵢ/2, ∫x dA = Σ(xᵢ + xᵢ₊₁)cᵢ/6, ∫x² dA = Σ(xᵢ² + xᵢxᵢ₊₁ + xᵢ₊₁²)cᵢ/12, ∫xy dA = Σ(2xᵢyᵢ + xᵢyᵢ₊₁ + xᵢ₊₁yᵢ + 2xᵢ₊₁yᵢ₊₁)cᵢ/24 (y likewise), each less its centroid's share, times m/A; ∫z² dm = mL²/12",
        dims: &[],
        measure: "",
        moments: [
            "",
            "",
            "",
        ],
    };

    /// (its area is its polygon's: `shapes::error`).
    const MEASURE_ROUNDINGS: f64 = 2.0;

    /// (its second moment is its polygon’s: `shapes::offset`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(2);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [area, length] = d else {
            unreachable!("the model passes a prism its area and length")
        };
        *area * *length
    }

    fn moments_of<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [_, _] = d else {
            unreachable!("the model passes a prism its area and length")
        };
        [T::of(0.0); 3]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let origin = r.origin()?;
        let polygon = r.polygon()?.into();
        let length = r.length("length")?;
        Ok(Prism {
            origin,
            polygon,
            length,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        let area = polygon(&self.polygon).area;
        T::of_dd(area) * var(self.length, Slot::Length, l)
    }

    /// The polygon's area in double-double (32 of its units of the
    /// magnitudes Σ|cᵢ|/2 it is summed from, counted here as units of
    /// either arithmetic: 32 f64 units are far more than it needs), rounded
    /// once, times the length.
    fn measure_error(&self) -> f64 {
        3.0 + 32.0 * polygon(&self.polygon).spread.area
    }

    /// At its polygon's centroid, off its origin.
    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        let g = polygon(&self.polygon).centroid;
        let local = [T::of_dd(g[0]), T::of_dd(g[1]), T::of(0.0)];
        offset_centroid(local, &self.origin, &self.orientation, l)
    }

    /// The polygon's centroid's own error (`Spread`) and its turn.
    fn centroid_error(&self, at: f64, centroid: &[f64; 3]) -> [f64; 3] {
        let poly = polygon(&self.polygon);
        let g = poly.centroid.map(|x| x.f64().abs());
        let s = poly.spread.centroid;
        offset_centroid_error(
            [32.0 * s[0] + 4.0 * g[0], 32.0 * s[1] + 4.0 * g[1], 0.0],
            [g[0], g[1], 0.0],
            &self.orientation,
            at,
            centroid,
        )
    }

    /// In local axes the polygon's per-area second moments times m in x–y
    /// (with the product), m L²/12 along z; then R C Rᵀ.
    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        lift: L,
    ) -> (M3<T>, Option<Own>) {
        let poly = polygon(&self.polygon);
        let zero = T::of(0.0);
        let [xx, yy, xy] = poly.second.map(|x| m * T::of_dd(x));
        let l = var(self.length, Slot::Length, lift);
        let local: M3<T> = [
            [xx, xy, zero],
            [xy, yy, zero],
            [zero, zero, m * l * l / T::of(12.0)],
        ];
        let orientation = &self.orientation;
        let r: M3<T> = orientation.matrix();
        let j = turned(&r, &local);
        let own = units.map(|u| {
            let mu = u.errors().1;
            let r = r.map(|row| row.map(T::f64));
            let rho = error::turn_error(orientation, &r);
            let ell: [f64; 3] = std::array::from_fn(|k| local[k][k].f64().abs());
            let per_area = [
                poly.second[0].f64().abs(),
                poly.second[1].f64().abs(),
                (self.length * self.length / 12.0).abs(),
            ];
            // The polygon's units relative to its per-area moments (m
            // scales both alike); each local entry then rounds once to T
            // and takes a product with m (3), the axial one m L²/12 (4).
            let kappa = mu + error::GIVEN + 4.0 + polygon_units::<T>(&poly, &per_area);
            let v: [f64; 3] =
                std::array::from_fn(|a| (0..3).map(|k| r[a][k].abs() * ell[k].sqrt()).sum());
            let total = ell.iter().sum::<f64>() + 2.0 * local[0][1].f64().abs();
            Own::turned(mu, kappa, v.map(|x| x * x), rho, total)
        });
        (j, own)
    }

    /// Its vertices are scaled in its own frame, not placed: their
    /// rounding is in its sizes' units (`scaled_rounding`).
    fn shortest_span(&self) -> f64 {
        f64::INFINITY
    }

    /// Its one moment checked is the trace.
    fn independent_moments(&self, _: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
        ([j[0][0] + j[1][1] + j[2][2], 0.0, 0.0], 1, 1)
    }

    fn moved(&mut self, m: &impl Mover) {
        self.origin = m.point(self.origin);
        if m.length() != 1.0 {
            self.polygon = self
                .polygon
                .iter()
                .map(|v| v.map(|x| x * m.length()))
                .collect();
        }
        self.length *= m.length();
        m.turn(&mut self.orientation);
    }

    fn density_power(&self) -> i32 {
        density_power::<Self>()
    }

    /// Scaling its polygon in its own frame rounds each vertex by a unit
    /// of its distance from the origin: 2 max|p|/shortest edge units of
    /// its sizes (its centroid moves too, in `reach`).
    fn scaled_rounding(&self) -> Option<f64> {
        let polygon = &self.polygon;
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

    /// Its origin's, and its vertices' rounding as they are scaled moves
    /// its centroid by a unit of their distance from its origin.
    fn reach(&self) -> f64 {
        norm1(&self.origin)
            + self
                .polygon
                .iter()
                .map(|v| v[0].abs() + v[1].abs())
                .fold(0.0, f64::max)
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        points(&[self.origin])
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        for (i, x) in self.origin.iter_mut().enumerate() {
            f(Slot::At(i as u8), x);
        }
        f(Slot::Length, &mut self.length);
    }

    fn reset_from(&mut self, src: &Self) {
        self.origin = src.origin;
        if !Arc::ptr_eq(&self.polygon, &src.polygon) {
            self.polygon = src.polygon.clone();
        }
        self.length = src.length;
        reset_turn(&mut self.orientation, &src.orientation);
    }

    /// Its own image in local z (extruded from −length/2 to +length/2):
    /// its turn completed, its polygon unchanged.
    fn mirror(&mut self) {
        flip(mirror_axis::<Self>(), &mut self.orientation);
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn turn(&self) -> Option<M3<f64>> {
        Some(self.orientation.matrix())
    }

    /// Both ends' polygons and the edges between them.
    fn outline(&self) -> Outline {
        let [x, y, z] = axes(&self.orientation.matrix());
        let at = |p: &[f64; 2], h: f64| add(self.origin, comb(&[(p[0], x), (p[1], y), (h, z)]));
        let ends: [Vec<V3>; 2] =
            [-0.5, 0.5].map(|h| self.polygon.iter().map(|p| at(p, h * self.length)).collect());
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
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A prism's mirror image in its own local x–z plane (local y → −y):
    /// the same origin, length and turn, its polygon with y negated and
    /// its vertices reversed (`mirrored`).
    fn mirrored_in_local_xz(p: &Prism) -> Prism {
        Prism {
            polygon: mirrored(&p.polygon).into(),
            ..p.clone()
        }
    }

    /// The mirror image of an unturned prism: the same mass, its centroid
    /// and its x–y product with y negated, the rest unchanged.
    #[test]
    fn a_mirrored_prism_negates_its_y_figures() {
        use crate::part::{MassSpec, Place, Spec};
        use crate::rotation::Orientation;
        let prism = Prism {
            origin: [1.0, 2.0, 3.0],
            polygon: vec![
                [0.0, 0.0],
                [2.0, 0.0],
                [2.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ]
            .into(),
            length: 0.5,
            orientation: Orientation::Identity,
        };
        let mirror = mirrored_in_local_xz(&prism);
        let spec = |p: Prism| Spec {
            mass: MassSpec::Density(7.0),
            place: Place::Prism(p),
            removed: false,
            placed: Default::default(),
        };
        let (a, b) = (spec(prism), spec(mirror));
        let (ma, mb): (f64, f64) = (
            crate::part::mass_of(&a),
            crate::part::mass_of(&b),
        );
        assert_eq!(ma, mb);
        let (ca, cb) = (
            crate::part::centroid(&a.place),
            crate::part::centroid(&b.place),
        );
        assert_eq!(ca[0].f64(), cb[0].f64());
        assert_eq!(ca[1].f64() - 2.0, -(cb[1].f64() - 2.0));
        let (ja, jb): (M3<f64>, M3<f64>) = (
            crate::part::own_second_moment(&a, ma),
            crate::part::own_second_moment(&b, mb),
        );
        for (k, l) in [(0, 0), (1, 1), (2, 2)] {
            assert!((ja[k][l] - jb[k][l]).abs() <= 1e-15 * ja[k][l]);
        }
        assert!(ja[0][1] != 0.0 && (ja[0][1] + jb[0][1]).abs() <= 1e-15 * ja[0][0]);
    }

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
