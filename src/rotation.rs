//! The rotation forms of a part's local axes, each turned into the matrix R
//! whose columns are the local x, y, z axes in the file's frame: a point p in
//! local coordinates lies at `center + R·p`.
//!
//! All forms are active rotations. Euler angles name their meaning
//! explicitly: `intrinsic = "zyx"` turns about z, then about the *new* y, then
//! the newest x (R = Rz·Ry·Rx); `extrinsic = "xyz"` turns about the fixed x,
//! then fixed y, then fixed z (also R = Rz·Ry·Rx). `model::rotation` reads
//! them from a part file.

use crate::la::Matrix3;
use crate::numeric::{M3, Real, norm_of};

/// How a part's local axes are turned, as the file gave it, so that the
/// matrix can be formed in the precision the composer works in.
#[derive(Debug, Clone, PartialEq)]
pub enum Orientation {
    Identity,
    /// [w, x, y, z], within `QUATERNION_TOLERANCE` of unit length.
    Quaternion([f64; 4]),
    /// A non-zero axis (any length) and an angle in degrees.
    AxisAngle([f64; 3], f64),
    /// Axis sequence (0 = x), angles in degrees, intrinsic or not.
    Euler([u8; 3], [f64; 3], bool),
    /// Rows as given, orthonormal to `MATRIX_TOLERANCE`, determinant +1.
    /// (Boxed, as is a given tensor, so that a part takes ~200 bytes, not
    /// ~270: a file of a million parts holds them all.)
    Matrix(Box<M3<f64>>),
    /// The first turn applied after the second (R₁ R₂): a part of an
    /// included sub-assembly, turned with it.
    Then(Box<Orientation>, Box<Orientation>),
    /// The report axes given as two directions (`[analysis] axes = { x, y }`,
    /// any lengths, perpendicular to `MATRIX_TOLERANCE`): columns x/|x|,
    /// y/|y| and their cross product, made orthonormal, all formed in the
    /// arithmetic asked for (so in double-double in `extended`, not rounded
    /// to f64 first).
    Axes([f64; 3], [f64; 3]),
    /// The reflection E − 2 n nᵀ/|n|² in the plane through 0 normal to a
    /// non-zero `n` (any length). Not a turn (its determinant is −1): it
    /// is only ever a factor of a `Then` whose product is one, S R F of a
    /// mirrored part (`Place::mirror`).
    Reflect([f64; 3]),
}

impl Orientation {
    /// R, whose columns are the local axes in the file's frame.
    pub fn matrix<T: Real>(&self) -> M3<T> {
        match self {
            Orientation::Identity => identity(),
            Orientation::Quaternion(q) => quaternion(*q),
            Orientation::AxisAngle(k, deg) => axis_angle(*k, *deg),
            Orientation::Euler(seq, deg, intrinsic) => {
                euler(seq.map(usize::from), *deg, *intrinsic)
            }
            Orientation::Matrix(m) => orthonormalised(m),
            Orientation::Axes(x, y) => axes(x, y),
            Orientation::Then(outer, inner) => mul(&outer.matrix(), &inner.matrix()),
            Orientation::Reflect(n) => reflection(*n),
        }
    }
}

/// sin and cos of an angle in degrees, exact at multiples of 90°.
pub fn sin_cos_deg(deg: f64) -> (f64, f64) {
    f64::sin_cos_deg(deg)
}

fn identity<T: Real>() -> M3<T> {
    std::array::from_fn(|i| std::array::from_fn(|j| T::of(if i == j { 1.0 } else { 0.0 })))
}

fn mul<T: Real>(a: &M3<T>, b: &M3<T>) -> M3<T> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j])
    })
}

fn elementary<T: Real>(axis: usize, deg: f64) -> M3<T> {
    let (s, c) = T::sin_cos_deg(deg);
    let (o, z) = (T::of(1.0), T::of(0.0));
    match axis {
        0 => [[o, z, z], [z, c, -s], [z, s, c]],
        1 => [[c, z, s], [z, o, z], [-s, z, c]],
        _ => [[c, -s, z], [s, c, z], [z, z, o]],
    }
}

/// Rodrigues' formula for the axis `k` (normalised here, in T):
/// `R = cos θ E + sin θ [k]× + (1 − cos θ) k kᵀ`.
pub fn axis_angle<T: Real>(k: [f64; 3], deg: f64) -> M3<T> {
    // The one scaled norm: no overflow in the squares, and no rounding of
    // the axis before it is in T.
    let k = k.map(T::of);
    let n = norm_of(&k);
    let k = k.map(|x| x / n);
    let (s, c) = T::sin_cos_deg(deg);
    let one_c = T::of(1.0) - c;
    let cross = [
        [T::of(0.0), -k[2], k[1]],
        [k[2], T::of(0.0), -k[0]],
        [-k[1], k[0], T::of(0.0)],
    ];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let d = if i == j { c } else { T::of(0.0) };
            d + s * cross[i][j] + one_c * k[i] * k[j]
        })
    })
}

/// The reflection E − 2 k kᵀ in the plane normal to `n` (normalised here,
/// in T, by the one scaled norm): exact for a normal along an axis.
pub fn reflection<T: Real>(n: [f64; 3]) -> M3<T> {
    let k = n.map(T::of);
    let len = norm_of(&k);
    let k = k.map(|x| x / len);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let d = if i == j { T::of(1.0) } else { T::of(0.0) };
            d - T::of(2.0) * k[i] * k[j]
        })
    })
}

/// R of a quaternion [w, x, y, z], dividing by |q|² instead of normalising
/// first, which keeps e.g. [1, 0, 0, 1] exact.
pub fn quaternion<T: Real>(q: [f64; 4]) -> M3<T> {
    let [w, x, y, z] = q.map(T::of);
    let two = T::of(2.0);
    let n = w * w + x * x + y * y + z * z;
    [
        [
            w * w + x * x - y * y - z * z,
            two * (x * y - w * z),
            two * (x * z + w * y),
        ],
        [
            two * (x * y + w * z),
            w * w - x * x + y * y - z * z,
            two * (y * z - w * x),
        ],
        [
            two * (x * z - w * y),
            two * (y * z + w * x),
            w * w - x * x - y * y + z * z,
        ],
    ]
    .map(|r| r.map(|v| v / n))
}

/// R of Euler angles: `seq` like "zyx", intrinsic or extrinsic.
pub fn euler<T: Real>(seq: [usize; 3], deg: [f64; 3], intrinsic: bool) -> M3<T> {
    let r: [M3<T>; 3] = [0, 1, 2].map(|i| elementary(seq[i], deg[i]));
    if intrinsic {
        mul(&mul(&r[0], &r[1]), &r[2])
    } else {
        mul(&mul(&r[2], &r[1]), &r[0])
    }
}

/// A nearly orthonormal matrix made orthonormal: Newton–Schulz iterations
/// R ← R (3E − RᵀR) / 2, each squaring the defect (1e-9 → 1e-18 → 1e-36),
/// leaving an exact rotation exact.
pub fn orthonormalised<T: Real>(m: &M3<f64>) -> M3<T> {
    newton_schulz(m.map(|row| row.map(T::of)))
}

/// The report axes x/|x|, y/|y| and z = x × y as columns, made orthonormal,
/// in T (`Orientation::Axes`).
fn axes<T: Real>(x: &[f64; 3], y: &[f64; 3]) -> M3<T> {
    let unit = |v: &[f64; 3]| {
        let v = v.map(T::of);
        let n = crate::numeric::norm_of(&v);
        v.map(|c| c / n)
    };
    let (x, y) = (unit(x), unit(y));
    let z = [
        x[1] * y[2] - x[2] * y[1],
        x[2] * y[0] - x[0] * y[2],
        x[0] * y[1] - x[1] * y[0],
    ];
    newton_schulz(std::array::from_fn(|i| [x[i], y[i], z[i]]))
}

/// Newton–Schulz steps towards the orthonormal matrix nearest `r`.
fn newton_schulz<T: Real>(mut r: M3<T>) -> M3<T> {
    let steps = if T::EPS < 1e-20 { 2 } else { 1 };
    for _ in 0..steps {
        let rt: M3<T> = std::array::from_fn(|i| std::array::from_fn(|j| r[j][i]));
        let rtr = mul(&rt, &r);
        let k: M3<T> = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let e = if i == j { T::of(3.0) } else { T::of(0.0) };
                (e - rtr[i][j]) / T::of(2.0)
            })
        });
        r = mul(&r, &k);
    }
    r
}

/// An f64 matrix of rows as a `Matrix3`.
pub fn to_matrix3(m: &M3<f64>) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m[i][j])
}
