//! MJCF orientations (`quat`, `axisangle`, `euler`, `xyaxes`, `zaxis`)
//! turned into a quaternion and then a matrix the way MuJoCo's compiler
//! does it (`ResolveOrientation`, `mjuu_normvec`, `mjuu_mulquat`,
//! `mjuu_frame2quat`, `mjuu_z2quat`, `mjuu_quat2mat` in user_objects.cc and
//! user_util.cc), tolerances included, so that the frame read here is the
//! frame MuJoCo compiles.

use super::{Value, Xml};
use crate::diag::Diagnostic;
use crate::numeric::M3;

use crate::robot::MujocoCompiler;
/// MuJoCo's mjEPS: the squared length below which a vector is too small to
/// normalise, and the distance from 1 within which a length is left alone.
pub(super) const EPS: f64 = 1e-14;

/// What the `<compiler>` elements set: MuJoCo's verdict options, and how
/// orientations read.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Settings {
    pub compiler: MujocoCompiler,
    /// `angle`: whether `axisangle` and `euler` angles are degrees (MJCF's
    /// default) or radians.
    pub degree: bool,
    /// `eulerseq`: three of `xyzXYZ`, lowercase turning about the rotating
    /// axes, uppercase about the fixed ones.
    pub eulerseq: [u8; 3],
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            compiler: MujocoCompiler::default(),
            degree: true,
            eulerseq: *b"xyz",
        }
    }
}

/// The unit quaternion (w, x, y, z) of one orientation attribute, as
/// MuJoCo's compiler forms it.
pub(super) fn orientation(
    xml: &Xml,
    form: &str,
    v: &Value,
    owner: &str,
    s: &Settings,
) -> Result<[f64; 4], Diagnostic> {
    let too_small = |what: &str| {
        xml.error(
            v.range.clone(),
            format!("`{form}` of {owner}: the {what} is too short to give a direction"),
        )
    };
    let radians = |a: f64| {
        if s.degree {
            a / 180.0 * std::f64::consts::PI
        } else {
            a
        }
    };
    Ok(match form {
        "quat" => {
            let mut q = xml.numbers::<4>(v, owner)?;
            if q.iter().all(|&c| c == 0.0) {
                return Err(xml.error(
                    v.range.clone(),
                    format!("`quat` of {owner}: a zero quaternion is no orientation"),
                ));
            }
            normalise(&mut q);
            q
        }
        "axisangle" => {
            let [x, y, z, angle] = xml.numbers::<4>(v, owner)?;
            let mut axis = [x, y, z];
            if normalise(&mut axis) < EPS {
                return Err(too_small("axis"));
            }
            let (s, c) = (radians(angle) / 2.0).sin_cos();
            [c, s * axis[0], s * axis[1], s * axis[2]]
        }
        "xyaxes" => {
            let [x0, x1, x2, y0, y1, y2] = xml.numbers::<6>(v, owner)?;
            let mut x = [x0, x1, x2];
            if normalise(&mut x) < EPS {
                return Err(too_small("x axis"));
            }
            // y made perpendicular to x, as MuJoCo does, then normalised.
            let d = x[0] * y0 + x[1] * y1 + x[2] * y2;
            let mut y = [y0 - x[0] * d, y1 - x[1] * d, y2 - x[2] * d];
            if normalise(&mut y) < EPS {
                return Err(too_small("y axis"));
            }
            let mut z = cross(&x, &y);
            if normalise(&mut z) < EPS {
                return Err(too_small("cross product of the axes"));
            }
            frame_to_quat(&x, &y, &z)
        }
        "zaxis" => {
            let mut z = xml.numbers::<3>(v, owner)?;
            if normalise(&mut z) < EPS {
                return Err(too_small("z axis"));
            }
            z_to_quat(&z)
        }
        _ => {
            let angles = xml.numbers::<3>(v, owner)?;
            let mut q = [1.0, 0.0, 0.0, 0.0];
            for (&axis, angle) in s.eulerseq.iter().zip(angles) {
                let (sa, ca) = (radians(angle) / 2.0).sin_cos();
                let mut step = [ca, 0.0, 0.0, 0.0];
                step[1 + usize::from(axis.to_ascii_lowercase() - b'x')] = sa;
                // Rotating axes (lowercase) compose on the right, fixed
                // axes (uppercase) on the left.
                q = if axis.is_ascii_lowercase() {
                    mul_quat(&q, &step)
                } else {
                    mul_quat(&step, &q)
                };
            }
            normalise(&mut q);
            q
        }
    })
}

/// MuJoCo's `mjuu_normvec`: v made unit length unless it is already within
/// EPS of it; returns the length, or 0 (v untouched) when the squared
/// length is below EPS.
pub(super) fn normalise<const N: usize>(v: &mut [f64; N]) -> f64 {
    let squared: f64 = v.iter().map(|x| x * x).sum();
    if squared < EPS {
        return 0.0;
    }
    let n = squared.sqrt();
    if (n - 1.0).abs() > EPS {
        v.iter_mut().for_each(|x| *x /= n);
    }
    n
}

pub(super) fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// MuJoCo's `mjuu_mulquat`: the Hamilton product, normalised.
pub(super) fn mul_quat(a: &[f64; 4], b: &[f64; 4]) -> [f64; 4] {
    let mut q = [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ];
    normalise(&mut q);
    q
}

/// MuJoCo's `mjuu_z2quat`: the smallest turn taking ẑ to the unit vector
/// `z`; a half turn about x when `z` is −ẑ (or within 1e-10 of ±ẑ).
pub(super) fn z_to_quat(z: &[f64; 3]) -> [f64; 4] {
    let mut axis = cross(&[0.0, 0.0, 1.0], z);
    let s = normalise(&mut axis);
    if s < 1e-10 {
        axis = [1.0, 0.0, 0.0];
    }
    let angle = s.atan2(z[2]);
    let (sa, ca) = (angle / 2.0).sin_cos();
    [ca, axis[0] * sa, axis[1] * sa, axis[2] * sa]
}

/// MuJoCo's `mjuu_frame2quat`: the quaternion of the frame whose axes
/// (the matrix's columns) are x, y, z, by the largest of its components.
pub(super) fn frame_to_quat(x: &[f64; 3], y: &[f64; 3], z: &[f64; 3]) -> [f64; 4] {
    // m[c][r]: column c, row r, as MuJoCo indexes it.
    let m = [x, y, z];
    let mut q = if m[0][0] + m[1][1] + m[2][2] > 0.0 {
        let w = 0.5 * (1.0 + m[0][0] + m[1][1] + m[2][2]).sqrt();
        [
            w,
            0.25 * (m[1][2] - m[2][1]) / w,
            0.25 * (m[2][0] - m[0][2]) / w,
            0.25 * (m[0][1] - m[1][0]) / w,
        ]
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        let a = 0.5 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
        [
            0.25 * (m[1][2] - m[2][1]) / a,
            a,
            0.25 * (m[1][0] + m[0][1]) / a,
            0.25 * (m[2][0] + m[0][2]) / a,
        ]
    } else if m[1][1] > m[2][2] {
        let b = 0.5 * (1.0 - m[0][0] + m[1][1] - m[2][2]).sqrt();
        [
            0.25 * (m[2][0] - m[0][2]) / b,
            0.25 * (m[1][0] + m[0][1]) / b,
            b,
            0.25 * (m[2][1] + m[1][2]) / b,
        ]
    } else {
        let c = 0.5 * (1.0 - m[0][0] - m[1][1] + m[2][2]).sqrt();
        [
            0.25 * (m[0][1] - m[1][0]) / c,
            0.25 * (m[2][0] + m[0][2]) / c,
            0.25 * (m[2][1] + m[1][2]) / c,
            c,
        ]
    };
    normalise(&mut q);
    q
}

/// MuJoCo's `mjuu_quat2mat` for a unit quaternion (w, x, y, z): rows of
/// the matrix whose columns are the turned axes.
pub(super) fn quat_to_matrix(q: [f64; 4]) -> M3<f64> {
    let [w, x, y, z] = q;
    [
        [
            w * w + x * x - y * y - z * z,
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            w * w - x * x + y * y - z * z,
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            w * w - x * x - y * y + z * z,
        ],
    ]
}
