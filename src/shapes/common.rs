//! What the shapes' modules share: a shape placed by its centre whose
//! local axes are principal (`diagonal`), one spanned by vectors
//! (`spanned`), a given tensor turned (`given`), and the small pieces of
//! their reading, moving and drawing. Each shape's module says which it
//! is; nothing here knows a shape.

use super::error::Units;
use super::error::{self, Own};
use super::lift::{Lift, Slot, lift3, xyz};
use super::outline::{Piece, V3};
use super::{ShapeKind, turned};
use crate::numeric::{DD, M3, Real, norm_of};
use crate::rotation::Orientation;

/// A point read through `l`, its coordinates the slots `At`.
pub fn at<T: Real, L: Lift>(p: &[f64; 3], l: L) -> [T; 3] {
    lift3(l, p, xyz(Slot::At))
}

/// A number read through `l`.
pub fn var<T: Real, L: Lift>(x: f64, slot: Slot, l: L) -> T {
    T::var(x, l.rate(slot))
}

/// The points that place a part (and its edges), held in place (asked of
/// every copy): up to four, and how many.
pub fn points(ps: &[[f64; 3]]) -> ([[f64; 3]; 4], usize) {
    let mut out = [[0.0; 3]; 4];
    out[..ps.len()].copy_from_slice(ps);
    (out, ps.len())
}

/// |p|₁.
pub fn norm1(p: &[f64; 3]) -> f64 {
    p.iter().map(|x| x.abs()).sum::<f64>()
}

/// The power of length a shape's density is per (`ShapeKind::INFO`).
pub fn density_power<K: ShapeKind>() -> i32 {
    K::INFO.density.map_or(0, |d| d.length_power)
}

/// The own second moment of a shape whose centroid is the point that
/// places it and whose local axes are principal: its local second
/// moments `d`, turned by `orientation` (R diag(d) Rᵀ, the upper triangle
/// formed and mirrored); with its error model when `units` are given, its
/// closed forms' roundings `closed_form`.
pub fn diagonal<T: Real>(
    d: [T; 3],
    orientation: &Orientation,
    units: Option<Units>,
    closed_form: f64,
) -> (M3<T>, Option<Own>) {
    let zero = T::of(0.0);
    if let Orientation::Identity = orientation {
        let own = units.map(|u| {
            let mu = u.errors().1;
            Own {
                mass: mu,
                kappa: mu + closed_form,
                mag: d.map(|x| x.f64().abs()),
                rot: 0.0,
                diagonal: true,
            }
        });
        let j = std::array::from_fn(|a| std::array::from_fn(|b| if a == b { d[a] } else { zero }));
        return (j, own);
    }
    let mut j = [[zero; 3]; 3];
    let r: M3<T> = orientation.matrix();
    for a in 0..3 {
        for b in a..3 {
            j[a][b] =
                r[a][0] * d[0] * r[b][0] + r[a][1] * d[1] * r[b][1] + r[a][2] * d[2] * r[b][2];
            j[b][a] = j[a][b];
        }
    }
    let own = units.map(|u| {
        let mu = u.errors().1;
        let rho = error::turn_error(orientation, &r.map(|row| row.map(T::f64)));
        let spread: f64 = d.iter().map(|x| x.f64().abs()).sum();
        let mag = std::array::from_fn(|a| j[a][a].f64().abs());
        let kappa = mu + closed_form + error::TURN;
        Own::turned(mu, kappa, mag, rho, spread)
    });
    (j, own)
}

/// (m/12) Σ eₖeₖᵀ over the vectors that span a part (a box's or plate's
/// edges, a rod's `to − from`, a triangle's vertices less its centroid),
/// with its error model when `units` are given: its roundings
/// (`error::OUTER`), and the frames' rounding of the vectors, absolute in
/// every entry, as a turn's own error is (a component that should be 0 is
/// not).
pub fn spanned<T: Real>(m: T, vectors: &[[T; 3]], units: Option<Units>) -> (M3<T>, Option<Own>) {
    let zero = T::of(0.0);
    let twelfth = m / T::of(12.0);
    let mut j = [[zero; 3]; 3];
    for e in vectors {
        for a in 0..3 {
            for b in 0..3 {
                j[a][b] = j[a][b] + twelfth * e[a] * e[b];
            }
        }
    }
    let own = units.map(|u| {
        let (placed, mu) = u.errors();
        let mag: [f64; 3] = std::array::from_fn(|a| j[a][a].f64().abs());
        Own {
            mass: mu,
            kappa: mu + error::OUTER,
            mag,
            rot: placed * mag.iter().sum::<f64>(),
            diagonal: false,
        }
    });
    (j, own)
}

/// A given tensor's second moment (`inertia`: tensor convention, local
/// axes, about the centroid) turned by `orientation`, for the mass `m`
/// (its sign: a cut-out's is subtracted), with its error model when
/// `units` are given.
pub fn given<T: Real>(
    inertia: &[[f64; 3]; 3],
    orientation: &Orientation,
    m: T,
    units: Option<Units>,
) -> (M3<T>, Option<Own>) {
    let zero = T::of(0.0);
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
    let own = units.map(|u| {
        let mu = u.errors().1;
        let r = r.map(|row| row.map(T::f64));
        let rho = error::turn_error(orientation, &r);
        // |C_kl| ≤ √(ℓ_k ℓ_l) for the positive semi-definite local
        // C, ℓ the magnitudes its diagonal is formed from; so each
        // entry of R C Rᵀ is at most v_a v_b, v = |R| √ℓ.
        let spread: [f64; 3] = std::array::from_fn(|a| diagonal_magnitude(&i, a));
        let v: [f64; 3] =
            std::array::from_fn(|a| (0..3).map(|k| r[a][k].abs() * spread[k].sqrt()).sum());
        let total: f64 = spread.iter().sum::<f64>()
            + (0..3)
                .flat_map(|k| (0..3).filter(move |l| *l != k).map(move |l| (k, l)))
                .map(|(k, l)| inertia[k][l].abs())
                .sum::<f64>();
        Own::turned(mu, mu + error::GIVEN, v.map(|x| x * x), rho, total)
    });
    (j, own)
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

/// Vectors spanning a part (edges), read through `l`: component i of
/// vector e fills `Edge(e, i)`.
pub fn edges_in<T: Real, L: Lift, const N: usize>(edges: &[[f64; 3]; N], l: L) -> [[T; 3]; N] {
    std::array::from_fn(|e| lift3(l, &edges[e], xyz(|i| Slot::Edge(e as u8, i))))
}

/// The product of the edges' lengths (a box's volume, a plate's area).
pub fn edges_measure<T: Real, L: Lift, const N: usize>(edges: &[[f64; 3]; N], l: L) -> T {
    edges_in::<T, L, N>(edges, l)
        .iter()
        .fold(T::of(1.0), |acc, e| acc * norm_of(e))
}

/// The centre of the parallelepiped at `corner` spanned by `edges`, read
/// through `l`.
pub fn edges_centroid<T: Real, L: Lift, const N: usize>(
    corner: &[f64; 3],
    edges: &[[f64; 3]; N],
    l: L,
) -> [T; 3] {
    let half = T::of(0.5);
    let c: [T; 3] = at(corner, l);
    let e: [[T; 3]; N] = edges_in(edges, l);
    std::array::from_fn(|i| e.iter().fold(c[i], |acc, e| acc + e[i] * half))
}

/// The error of the centroid of a part spanned by edges, in double-double:
/// 2⁻⁹⁸ of it along each axis the edges move it off the corner, and the
/// frames' `at`.
pub fn edges_centroid_error<const N: usize>(
    edges: &[[f64; 3]; N],
    at: f64,
    centroid: &[f64; 3],
) -> [f64; 3] {
    std::array::from_fn(|j| {
        at + if edges.iter().any(|e| e[j] != 0.0) {
            centroid[j].abs() * 3.155_443_620_884_047e-30
        } else {
            0.0
        }
    })
}

/// A centred shape's centroid's error: its centre is a number of the file;
/// only the frames' rounding of it, `at`.
pub fn exact_centroid_error(at: f64) -> [f64; 3] {
    [at; 3]
}

/// Its turn completed as a mirror image (`Place::mirror`): S R becomes
/// S R F, F the flip of local axis `k`.
pub fn flip(k: usize, o: &mut Orientation) {
    let mut n = [0.0; 3];
    n[k] = 1.0;
    let sr = std::mem::replace(o, Orientation::Identity);
    *o = Orientation::Then(Box::new(sr), Box::new(Orientation::Reflect(n)));
}

/// The local axis a mirror flips for a shape of kind `K`.
pub fn mirror_axis<K: ShapeKind>() -> usize {
    K::MIRROR_AXIS.unwrap_or(0)
}

/// A turn's local z in the file's axes, in double-double.
pub fn local_z(orientation: &Orientation) -> [DD; 3] {
    let r: M3<DD> = orientation.matrix();
    [r[0][2], r[1][2], r[2][2]]
}

/// The columns of a turn: the local x, y and z axes in the file's frame.
pub fn axes(r: &[[f64; 3]; 3]) -> [V3; 3] {
    std::array::from_fn(|j| std::array::from_fn(|i| r[i][j]))
}

/// A circle of radius `r` about `at` in the plane of `x` and `y`.
pub fn rim(at: V3, r: f64, x: &V3, y: &V3) -> Piece {
    Piece::Ellipsoid {
        c: at,
        m: [scaled(r, *x), scaled(r, *y), [0.0; 3]],
    }
}

/// Every corner of the parallelepiped at `corner` spanned by `edges`.
pub fn corners(corner: V3, edges: &[V3]) -> Vec<V3> {
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

pub fn add(a: V3, b: V3) -> V3 {
    std::array::from_fn(|k| a[k] + b[k])
}

pub fn scaled(s: f64, v: V3) -> V3 {
    v.map(|x| s * x)
}

/// Σ sᵢ vᵢ.
pub fn comb(terms: &[(f64, V3)]) -> V3 {
    terms
        .iter()
        .fold([0.0; 3], |acc, (s, v)| add(acc, scaled(*s, *v)))
}

/// A box's or plate's hull, centred at `c` with sides `e` along `x`, `y`,
/// `z` (a plate's third 0).
pub fn centred_hull(c: V3, e: &[f64; 3], [x, y, z]: &[V3; 3]) -> Piece {
    let corner = add(
        c,
        comb(&[(-e[0] / 2.0, *x), (-e[1] / 2.0, *y), (-e[2] / 2.0, *z)]),
    );
    Piece::Hull(corners(
        corner,
        &[scaled(e[0], *x), scaled(e[1], *y), scaled(e[2], *z)],
    ))
}

/// The centroid of a shape whose centroid lies off the point `at` that
/// places it, by `local` in its local axes (a cone's or hemisphere's along
/// z, a prism's polygon's): `at` plus R times the local offset, so that
/// far from the origin it keeps the digits of the offset, as a triangle's
/// centroid does.
pub fn offset_centroid<T: Real, L: Lift>(
    local: [T; 3],
    at_point: &[f64; 3],
    orientation: &Orientation,
    lift: L,
) -> [T; 3] {
    let at: [T; 3] = at(at_point, lift);
    if let Orientation::Identity = orientation {
        return std::array::from_fn(|i| at[i] + local[i]);
    }
    let r: M3<T> = orientation.matrix();
    std::array::from_fn(|i| at[i] + (r[i][0] * local[0] + r[i][1] * local[1] + r[i][2] * local[2]))
}

/// How far each component of an offset centroid may lie from the exact
/// one: the local offset's own error (`spread`: a few tens of
/// double-double units of the magnitudes it is formed from), its turn by
/// R (the rotation's own error ρ per entry, two products and sums, of
/// `offset`'s magnitudes), the sum with the placing point, and the frames'
/// `at`.
pub fn offset_centroid_error(
    spread: [f64; 3],
    offset: [f64; 3],
    orientation: &Orientation,
    at: f64,
    centroid: &[f64; 3],
) -> [f64; 3] {
    let r: M3<f64> = orientation.matrix();
    let rho = error::turn_error(orientation, &r);
    let u = error::U_DD;
    let e: [f64; 3] = std::array::from_fn(|i| {
        let turned: f64 = (0..3)
            .map(|k| r[i][k].abs() * spread[k] + (rho + 3.0) * offset[k])
            .sum();
        u * (turned + 4.0 * centroid[i].abs())
    });
    e.map(|e| e + at)
}

/// A turn made another's again in place: left alone when both are the
/// identity (no clone, no drop).
pub fn reset_turn(dst: &mut Orientation, src: &Orientation) {
    if !matches!((&*dst, src), (Orientation::Identity, Orientation::Identity)) {
        *dst = src.clone();
    }
}

/// A box's or plate's `size`, read through `l`: component k fills
/// `Size(k)`.
pub fn sizes<T: Real, L: Lift, const N: usize>(size: &[f64; N], l: L) -> [T; N] {
    std::array::from_fn(|k| var(size[k], Slot::Size(k as u8), l))
}

/// A plate's `size` as a box's, its third side 0.
pub fn pad<const N: usize>(size: &[f64; N]) -> [f64; 3] {
    std::array::from_fn(|k| size.get(k).copied().unwrap_or(0.0))
}

/// A corner and the edges that span a part, as `points`.
pub fn spanned_points<const N: usize>(
    corner: &[f64; 3],
    edges: &[[f64; 3]; N],
) -> ([[f64; 3]; 4], usize) {
    let mut out = [[0.0; 3]; 4];
    out[0] = *corner;
    out[1..=N].copy_from_slice(edges);
    (out, N + 1)
}
