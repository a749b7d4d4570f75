//! The σ of the body moving (`analysis::motion`): the angular momentum
//! about the point H_O and the kinetic energy T wherever ω is given, and
//! with `velocity` also v̄, G = m v̄, H_G = I_G ω, ½ m v̄·v̄ and ½ ω·H_G.
//!
//! NOTE: each is a function of the body's own outputs alone (its mass m,
//! its centre of mass c and its inertia tensor about c; ω, v and the
//! reference point p are given, exact): r = A (c − p) in the report axes A
//! (0 when the point is the centre itself, which moves with it), v̄ = v +
//! ω × r, and so on. So the methods need nothing new from the parts: a
//! Monte Carlo sample's motion is this function of its outputs, and a
//! source's first-order row is this function's derivative along the
//! source's row of outputs, formed exactly by evaluating it in dual
//! numbers (`dual::Dual`) seeded with that row — the chain rule through
//! the parts' physics and then through these formulas.

use super::{CENTRE, INERTIA, MASS, N};
use crate::dual::Dual;
use crate::numeric::{M3, Real};
use crate::quantity::{MOTION_OUTPUTS as K, UPPER};

/// Where the motion's outputs begin among all outputs: after both
/// bodies' (`quantity::Info::sigma` numbers them there).
pub(super) const FIRST: usize = 2 * N;

/// What the motion is formed from besides the body's outputs.
pub(super) struct Motion {
    /// The report axes' rows, in the file's frame.
    pub(super) axes: M3<f64>,
    /// The reference point (SI, file's frame); `None` for the centre of
    /// mass itself.
    pub(super) point: Option<[f64; 3]>,
    /// ω (rad/s, report axes).
    pub(super) omega: [f64; 3],
    /// v (SI, report axes), when given.
    pub(super) velocity: Option<[f64; 3]>,
    /// The products of inertia shown with the positive sign.
    pub(super) positive: bool,
    /// The body's nominal outputs, where the rows are derivatives.
    pub(super) nominal: [f64; N],
}

fn cross<T: Real>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        a[j] * b[k] - a[k] * b[j]
    })
}

fn dot<T: Real>(a: &[T; 3], b: &[T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Motion {
    /// Whether motion output `k` (of `K`) is reported: H_O and T (the
    /// first four) with ω, the rest with v.
    pub(super) fn live(&self, k: usize) -> bool {
        k < 4 || self.velocity.is_some()
    }

    /// The motion's outputs of a body's outputs `o` (`N` of them): H_O,
    /// T, v̄, G, H_G, ½ m v̄·v̄, ½ ω·H_G (zero where not reported).
    fn values<T: Real>(&self, o: &[T]) -> [T; K] {
        let zero = T::of(0.0);
        let m = o[MASS];
        let r: [T; 3] = match self.point {
            Some(p) => std::array::from_fn(|i| {
                (0..3).fold(zero, |acc, j| {
                    acc + T::of(self.axes[i][j]) * (o[CENTRE + j] - T::of(p[j]))
                })
            }),
            None => [zero; 3],
        };
        let mut i_com = [[zero; 3]; 3];
        for (k, &(_, a, b)) in UPPER.iter().enumerate() {
            let e = o[INERTIA + k];
            let e = if self.positive && a != b { -e } else { e };
            i_com[a][b] = e;
            i_com[b][a] = e;
        }
        let w = self.omega.map(T::of);
        let v = self.velocity.unwrap_or([0.0; 3]).map(T::of);
        let wr = cross(&w, &r);
        let vbar: [T; 3] = std::array::from_fn(|i| v[i] + wr[i]);
        let g = vbar.map(|x| m * x);
        let h_g: [T; 3] = std::array::from_fn(|i| dot(&i_com[i], &w));
        let half = T::of(0.5);
        let t_trans = half * m * dot(&vbar, &vbar);
        let t_rot = half * dot(&w, &h_g);
        let rg = cross(&r, &g);
        let h_o: [T; 3] = std::array::from_fn(|i| h_g[i] + rg[i]);
        let mut out = [zero; K];
        out[..3].copy_from_slice(&h_o);
        out[3] = t_trans + t_rot;
        if self.velocity.is_some() {
            out[4..7].copy_from_slice(&vbar);
            out[7..10].copy_from_slice(&g);
            out[10..13].copy_from_slice(&h_g);
            out[13] = t_trans;
            out[14] = t_rot;
        }
        out
    }

    /// A sample's motion, from its outputs.
    pub(super) fn outputs(&self, o: &[f64]) -> [f64; K] {
        self.values(o)
    }

    /// A source's row of motion outputs, from its row of the body's
    /// outputs: their derivative along it at the nominal body.
    pub(super) fn linear(&self, row: &[f64]) -> [f64; K] {
        let seeded: [Dual<f64>; N] = std::array::from_fn(|i| Dual::new(self.nominal[i], row[i]));
        self.values(&seeded).map(|x| x.d)
    }
}
