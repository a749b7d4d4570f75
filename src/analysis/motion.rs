//! The body moving: the reference point O moves with velocity v (given in
//! `[analysis] velocity` or `--velocity`, report axes) while the body turns
//! at ω. Then (ME101 lecture 39) the mass centre G moves with
//! v̄ = v + ω × r (r = r_G/O, `center_of_mass_ref`), the linear momentum is
//! G = m v̄, the angular momentum about G is H_G = I_G ω and about O
//! H_O = H_G + r × G, and the kinetic energy T = ½ m v̄·v̄ + ½ ω·H_G.
//!
//! NOTE: H_O and T are formed as today's values about O plus what v adds,
//! H_O = I_O ω + m r × v and T = ½ ω·I_O ω + m v·(ω × r) + ½ m v·v (the
//! same numbers: I_O = I_G + m(|r|²1 − r rᵀ)), so a body whose point does
//! not move gives today's H and T bit for bit, and without `velocity`
//! nothing is added at all. The Euler moment stays I_O α + ω × I_O ω: the
//! moment about O moving at constant velocity.
//!
//! Every value is formed in double-double and rounded once; its error
//! bound (absolute, SI) is formed from the bounds of what it is made of:
//! the mass, the offset r, the tensor about the centre of mass, and v's
//! rounding into SI (`bound`).

use crate::bounds::{U64, safe};
use crate::numeric::{DD, M3, Real};

/// What the motion is formed from: SI, report axes.
pub(super) struct Inputs<'a> {
    pub mass: DD,
    /// r = c − p, SI.
    pub r: [DD; 3],
    /// The inertia tensor about the centre of mass, tensor convention.
    pub i_com: &'a M3<DD>,
    pub omega: [f64; 3],
    /// v, SI.
    pub v: [DD; 3],
}

/// The values, rounded (`extra` not yet), and what v adds to H and T about
/// the point (double-double, added before they are rounded).
#[derive(Debug, Clone)]
pub(super) struct Motion {
    pub velocity: [f64; 3],
    pub velocity_com: [f64; 3],
    pub linear_momentum: [f64; 3],
    pub momentum_com: [f64; 3],
    pub energy_translational: f64,
    pub energy_rotational: f64,
    /// m r × v.
    pub h_extra: [DD; 3],
    /// m v·(ω × r) + ½ m v·v.
    pub t_extra: DD,
}

fn cross<T: Copy + std::ops::Mul<Output = T> + std::ops::Sub<Output = T>>(
    a: &[T; 3],
    b: &[T; 3],
) -> [T; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        a[j] * b[k] - a[k] * b[j]
    })
}

fn dot(a: &[DD; 3], b: &[DD; 3]) -> DD {
    (0..3).fold(DD::of(0.0), |acc, i| acc + a[i] * b[i])
}

/// The motion of a body of these inputs.
pub(super) fn motion(i: &Inputs) -> Motion {
    let w = i.omega.map(DD::of);
    let wr = cross(&w, &i.r);
    let vbar: [DD; 3] = std::array::from_fn(|j| i.v[j] + wr[j]);
    let g = vbar.map(|x| i.mass * x);
    let h_g: [DD; 3] = std::array::from_fn(|j| {
        (0..3).fold(DD::of(0.0), |acc, k| {
            acc + i.i_com[j][k].mul_f64(i.omega[k])
        })
    });
    let half = |x: DD| x.mul_f64(0.5);
    let t_rot = half(dot(&w, &h_g));
    let t_trans = half(i.mass * dot(&vbar, &vbar));
    let rxv = cross(&i.r, &i.v);
    Motion {
        velocity: i.v.map(DD::f64),
        velocity_com: vbar.map(DD::f64),
        linear_momentum: g.map(DD::f64),
        momentum_com: h_g.map(DD::f64),
        energy_translational: t_trans.f64(),
        energy_rotational: t_rot.f64(),
        h_extra: rxv.map(|x| i.mass * x),
        t_extra: i.mass * dot(&i.v, &wr) + half(i.mass * dot(&i.v, &i.v)),
    }
}

/// The bounds of what the values are formed from (absolute, SI).
pub(super) struct InputBounds<'a> {
    pub mass: (f64, f64),
    pub r: ([f64; 3], [f64; 3]),
    pub v: ([f64; 3], [f64; 3]),
    pub omega: [f64; 3],
    /// The tensor about the centre of mass's bound.
    pub e_com: &'a [[f64; 3]; 3],
}

/// The error bounds of `Motion`'s values, and of what v adds to H and T.
#[derive(Debug, Clone, Copy)]
pub(super) struct Bounds {
    pub velocity: [f64; 3],
    pub velocity_com: [f64; 3],
    pub linear_momentum: [f64; 3],
    pub momentum_com: [f64; 3],
    pub energy_translational: f64,
    pub energy_rotational: f64,
    /// Of m r × v and m v·(ω × r) + ½ m v·v, before H's and T's rounding.
    pub h_extra: [f64; 3],
    pub t_extra: f64,
}

/// |AB − ab| where |A − a| ≤ da and |B − b| ≤ db:
/// AB − ab = A(B − b) + b(A − a), and |A| ≤ |a| + da.
fn prod(a: f64, da: f64, b: f64, db: f64) -> f64 {
    (a.abs() + da) * db + b.abs() * da
}

/// The bound of a x b component by component, from the bounds of each.
fn cross_bound(a: &[f64; 3], da: &[f64; 3], b: &[f64; 3], db: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        prod(a[j], da[j], b[k], db[k]) + prod(a[k], da[k], b[j], db[j])
    })
}

fn dot_bound(a: &[f64; 3], da: &[f64; 3], b: &[f64; 3], db: &[f64; 3]) -> f64 {
    (0..3).map(|j| prod(a[j], da[j], b[j], db[j])).sum()
}

fn dot_f(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|j| a[j] * b[j]).sum()
}

/// The bounds of `m`'s values. NOTE: the values each carry the rounding of
/// the double-double result to f64 (U64 of it); the products of bounds are
/// formed from f64 roundings of the true inputs, which `safe` covers.
pub(super) fn bound(m: &Motion, b: &InputBounds) -> Bounds {
    let (mass, dm) = b.mass;
    let (r, dr) = b.r;
    let (v, dv) = b.v;
    let w = b.omega;
    let none = [0.0; 3];
    let wr = cross(&w, &r);
    let dwr = cross_bound(&w, &none, &r, &dr);
    let dvbar: [f64; 3] = std::array::from_fn(|j| dv[j] + dwr[j]);
    let vbar = m.velocity_com;
    let s = |x: f64, value: f64| safe(x + U64 * value.abs());
    let de_w: [f64; 3] = std::array::from_fn(|j| (0..3).map(|k| b.e_com[j][k] * w[k].abs()).sum());
    let dss = dot_bound(&vbar, &dvbar, &vbar, &dvbar);
    let rxv = cross(&r, &v);
    let drxv = cross_bound(&r, &dr, &v, &dv);
    Bounds {
        velocity: std::array::from_fn(|j| s(dv[j], v[j])),
        velocity_com: std::array::from_fn(|j| s(dvbar[j], vbar[j])),
        linear_momentum: std::array::from_fn(|j| {
            s(prod(mass, dm, vbar[j], dvbar[j]), m.linear_momentum[j])
        }),
        momentum_com: std::array::from_fn(|j| s(de_w[j], m.momentum_com[j])),
        energy_translational: s(
            0.5 * prod(mass, dm, dot_f(&vbar, &vbar), dss),
            m.energy_translational,
        ),
        energy_rotational: s(0.5 * dot_f(&w.map(f64::abs), &de_w), m.energy_rotational),
        h_extra: std::array::from_fn(|j| safe(prod(mass, dm, rxv[j], drxv[j]))),
        t_extra: safe(
            prod(mass, dm, dot_f(&v, &wr), dot_bound(&v, &dv, &wr, &dwr))
                + 0.5 * prod(mass, dm, dot_f(&v, &v), dot_bound(&v, &dv, &v, &dv)),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inputs<'a>(i_com: &'a M3<DD>, r: [f64; 3], w: [f64; 3], v: [f64; 3]) -> Inputs<'a> {
        Inputs {
            mass: DD::of(2.0),
            r: r.map(DD::of),
            i_com,
            omega: w,
            v: v.map(DD::of),
        }
    }

    fn diag(d: [f64; 3]) -> M3<DD> {
        std::array::from_fn(|i| std::array::from_fn(|j| DD::of(if i == j { d[i] } else { 0.0 })))
    }

    #[test]
    fn a_body_translating_without_turning_has_half_m_v_squared_and_no_rotational_energy() {
        let i = diag([1.0, 2.0, 3.0]);
        let m = motion(&inputs(&i, [1.0, 0.0, 0.0], [0.0; 3], [0.0, 3.0, 4.0]));
        assert_eq!(m.velocity_com, [0.0, 3.0, 4.0]);
        assert_eq!(m.linear_momentum, [0.0, 6.0, 8.0]);
        assert_eq!(m.energy_translational, 25.0);
        assert_eq!(m.energy_rotational, 0.0);
        // H_O = r × G = (1, 0, 0) × (0, 6, 8) = (0, −8, 6).
        assert_eq!(m.h_extra.map(DD::f64), [0.0, -8.0, 6.0]);
    }

    #[test]
    fn the_mass_centre_of_a_body_turning_about_a_still_point_moves_with_omega_cross_r() {
        let i = diag([1.0, 1.0, 1.0]);
        let m = motion(&inputs(&i, [2.0, 0.0, 0.0], [0.0, 0.0, 3.0], [0.0; 3]));
        assert_eq!(m.velocity_com, [0.0, 6.0, 0.0]);
        // ½ · 2 · 36 and ½ · 3 · 1 · 3.
        assert_eq!(m.energy_translational, 36.0);
        assert_eq!(m.energy_rotational, 4.5);
        // v = 0 adds exactly nothing to H and T about the point.
        assert_eq!(m.h_extra.map(DD::f64), [0.0; 3]);
        assert_eq!(m.t_extra.f64(), 0.0);
    }

    #[test]
    fn the_bound_of_a_product_holds_the_worst_corner() {
        for (a, da, b, db) in [(3.0, 0.5, -2.0, 0.25), (0.0, 1.0, 0.0, 1.0)] {
            let bound = prod(a, da, b, db);
            for sa in [-1.0, 1.0] {
                for sb in [-1.0, 1.0] {
                    let err = ((a + sa * da) * (b + sb * db) - a * b).abs();
                    assert!(err <= bound, "{a} {b}: {err} > {bound}");
                }
            }
        }
    }
}
