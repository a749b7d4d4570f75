//! Error bounds of the arithmetic: for every composed quantity, how far the
//! value massprop computed may lie from the exact value for the file's
//! numbers (docs/accuracy.md, "Error bounds"). Bounds are absolute, first
//! order in the unit roundoff, and cheap: a few sums beside the composer's
//! (`Tally`), then closed-form propagation through the shift, the eigen
//! solution and the products with ω and α.
//!
//! The composer's error, entry by entry of the second moment C:
//!
//! - each part's own C and its parallel-axis term m d dᵀ carry a relative
//!   error of κ units of their magnitudes (`part::error`); since each is
//!   positive semi-definite (or its negative), an off-diagonal entry is at
//!   most √(C_jj C_kk), and by Cauchy–Schwarz the sum over parts of
//!   κᵢ √(a_ij a_ik) is at most √(G_j G_k) with G_j = Σ κᵢ a_ij: three sums
//!   per body, not six per part;
//! - a rotation matrix's own rounding moves a large local moment into every
//!   entry (`Own::rot`), summed as is;
//! - a compensated sum of n terms is within 2u|S| + 4nu²Σ|xᵢ| of the exact
//!   sum (Neumaier; Higham, *Accuracy and Stability*, §4.3); a
//!   double-double running sum within (n − 1)U Σ|xᵢ|;
//! - the correction −s sᵀ/m by the residual first moment s, and the centre
//!   ĉ + s/m, carry the errors of s and m.

use crate::la::Vector3;
use crate::numeric::{DD, M3, Precision, Real};
use crate::part::Own;
use crate::quantity::{Quantity, Table, Value};
use serde::Serialize;

pub use crate::part::error::U64;

/// The unit in which the arithmetic's roundings are counted
/// (`part::error`): 2⁻⁵³ for f64, 7·2⁻¹⁰⁶ for double-double.
pub fn unit(p: Precision) -> f64 {
    match p {
        Precision::Standard => U64,
        Precision::Extended => crate::part::error::U_DD,
    }
}

/// A bound made safe against the rounding of its own arithmetic (each bound
/// is a few dozen f64 operations on non-negative numbers) and against
/// overflow: past f64's range it is the largest f64, which still bounds.
pub fn safe(x: f64) -> f64 {
    let y = x * (1.0 + 256.0 * f64::EPSILON);
    if y.is_nan() || y > f64::MAX {
        f64::MAX
    } else {
        y
    }
}

/// √(Σ xᵢ²) of a few numbers, scaled by the largest so that neither the
/// squares of bounds near f64's ends overflow nor tiny ones underflow.
fn root_sum_squares(xs: impl IntoIterator<Item = f64>) -> f64 {
    let xs: Vec<f64> = xs.into_iter().map(f64::abs).collect();
    let top = xs.iter().copied().fold(0.0, f64::max);
    if top == 0.0 || !top.is_finite() {
        return top;
    }
    top * xs.iter().map(|x| (x / top) * (x / top)).sum::<f64>().sqrt()
}

/// The sums beside the composer's, one part at a time (`add`), from which
/// `finish` forms the bounds of the composed body.
#[derive(Debug, Clone, Copy, Default)]
pub struct Tally {
    parts: f64,
    /// Σ μᵢ|mᵢ| (μ the mass's relative error in units) and Σ|mᵢ|.
    mass_w: f64,
    mass_abs: f64,
    /// Σ (μᵢ + 3)|mᵢ||dᵢ| and Σ|mᵢ||dᵢ| per axis: the residual first moment.
    first_w: [f64; 3],
    first_abs: [f64; 3],
    /// G_j = Σ κᵢ a_ij over the parts' own second moments, and over those
    /// whose own C is not diagonal (`Own::diagonal`) alone.
    own_w: [f64; 3],
    coupled_w: [f64; 3],
    /// Σ (μᵢ + 6)|mᵢ||d_ij||d_ik|, the parallel-axis terms, entry by entry
    /// (rows of the upper triangle: xx, xy, xz, yy, yz, zz).
    shift_w: [f64; 6],
    /// The same sums unweighted: what a sum's own rounding is relative to.
    own_abs: [f64; 3],
    coupled_abs: [f64; 3],
    shift_abs: [f64; 6],
    rot: f64,
    /// Absolute errors a part's centroid brings whatever the arithmetic
    /// (its double-double rounding, a frame's placement: o, from
    /// `part::error::centroid_error`): Σ|mᵢ|o_ij in the first moment, and
    /// Σ|mᵢ|(o_ij|d_ik| + |d_ij|o_ik + o_ij o_ik) in the parallel-axis terms.
    first_off: [f64; 3],
    shift_off: [f64; 6],
    /// Composed bodies placed (`add_body`): their absolute errors, in the
    /// mass, the first moment and the second moment (upper triangle), and
    /// the magnitudes of their terms beside the parts' (`body_abs`: C',
    /// s′dᵀ and d s′ᵀ), for the sums' own rounding.
    body_mass: f64,
    body_first: [f64; 3],
    body_second: [f64; 6],
    body_abs: [f64; 6],
}

/// A composed body as `Tally::add_body` takes it (`compose::placed`), in
/// file units: mass m, offset d of its pivot from the composer's, its
/// residual first moment s and second moment C about its pivot, with the
/// absolute bounds of each.
#[derive(Debug, Clone, Copy)]
pub struct BodyTerm {
    pub mass: f64,
    pub d: [f64; 3],
    pub first: [f64; 3],
    pub second: M3<f64>,
    pub e_mass: f64,
    pub e_first: [f64; 3],
    pub e_second: M3<f64>,
}

/// The absolute bounds of a composer's raw sums (`Tally::raw`): the mass,
/// the residual first moment about its pivot and the second moment about
/// the pivot (no correction by the residual).
#[derive(Debug, Clone, Copy)]
pub struct RawError {
    pub mass: f64,
    pub first: [f64; 3],
    pub second: M3<f64>,
}

/// The entries of the upper triangle, in `Tally::shift_w`'s order.
const UPPER: [(usize, usize); 6] = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)];

fn upper(j: usize, k: usize) -> usize {
    let (j, k) = if j <= k { (j, k) } else { (k, j) };
    UPPER
        .iter()
        .position(|e| *e == (j, k))
        .expect("an entry of a 3 × 3")
}

impl Tally {
    /// One part of mass `m` at offset `d` from the composer's pivot, the
    /// absolute error `off` of its centroid (`part::error::centroid_error`),
    /// its own second moment's error model `own`.
    #[inline]
    pub fn add(&mut self, m: f64, d: [f64; 3], off: [f64; 3], own: &Own) {
        let am = m.abs();
        self.parts += 1.0;
        self.mass_w += own.mass * am;
        self.mass_abs += am;
        let dm: [f64; 3] = d.map(f64::abs);
        let md = dm.map(|x| am * x);
        if off != [0.0; 3] {
            for (f, o) in self.first_off.iter_mut().zip(off) {
                *f += am * o;
            }
            for (i, (j, k)) in UPPER.into_iter().enumerate() {
                self.shift_off[i] += am * (off[j] * dm[k] + dm[j] * off[k] + off[j] * off[k]);
            }
        }
        let w = own.mass + 6.0;
        #[allow(clippy::needless_range_loop)] // six arrays by one index
        for j in 0..3 {
            self.first_w[j] += (own.mass + 3.0) * md[j];
            self.first_abs[j] += md[j];
            let a = own.kappa * own.mag[j];
            self.own_w[j] += a;
            self.own_abs[j] += own.mag[j];
            if !own.diagonal {
                self.coupled_w[j] += a;
                self.coupled_abs[j] += own.mag[j];
            }
        }
        for (i, (j, k)) in UPPER.into_iter().enumerate() {
            let b = md[j] * dm[k];
            self.shift_w[i] += w * b;
            self.shift_abs[i] += b;
        }
        self.rot += own.rot;
    }

    /// A composed body placed (`compose::placed`), its pivot at offset
    /// `b.d` from the composer's: its terms m, m d + s and
    /// C + m d dᵀ + s dᵀ + d sᵀ, with their errors.
    ///
    /// NOTE: the body's own errors are absolute and added as they are;
    /// what the products with d add: m d (the product and d's own
    /// rounding, a difference rounded once) 3 units of |m||d| and the
    /// sum with s one unit of |s|; m d dᵀ 6 units of |m||d_j||d_k|, each
    /// s dᵀ 3 units of |s_j||d_k|; the mass's error times |d| and |d|²,
    /// the first moment's times |d| (first order: d is exact but for its
    /// rounding, counted). A body is four terms of each sum: counted as
    /// two parts.
    pub fn add_body(&mut self, precision: Precision, b: &BodyTerm) {
        let u = unit(precision);
        let am = b.mass.abs();
        let dm = b.d.map(f64::abs);
        let sm = b.first.map(f64::abs);
        self.parts += 2.0;
        self.mass_abs += am;
        self.body_mass += b.e_mass;
        for j in 0..3 {
            let md = am * dm[j];
            self.first_abs[j] += md + sm[j];
            self.body_first[j] += u * (3.0 * md + sm[j]) + b.e_mass * dm[j] + b.e_first[j];
        }
        for (i, (j, k)) in UPPER.into_iter().enumerate() {
            let mdd = am * dm[j] * dm[k];
            let sd = sm[j] * dm[k] + dm[j] * sm[k];
            self.shift_abs[i] += mdd;
            self.body_abs[i] += b.second[j][k].abs() + sd;
            self.body_second[i] += u * (6.0 * mdd + 3.0 * sd)
                + b.e_mass * dm[j] * dm[k]
                + b.e_first[j] * dm[k]
                + dm[j] * b.e_first[k]
                + b.e_second[j][k];
        }
    }

    /// The bounds of the composer's raw sums (`RawError`): the total
    /// `mass`, the residual first moment `s` about the pivot and the
    /// second moment `c` about the pivot, with no correction.
    pub fn raw(&self, precision: Precision, mass: f64, s: [f64; 3], c: &M3<f64>) -> RawError {
        let (mass, first, second) = self.sums(precision, mass, s, c);
        RawError {
            mass: safe(mass),
            first: first.map(safe),
            second: second.map(|r| r.map(safe)),
        }
    }

    /// `raw`, unsafe: the mass's, the first moment's and the second
    /// moment's errors, as `finish` goes on from them.
    fn sums(
        &self,
        precision: Precision,
        mass: f64,
        s: [f64; 3],
        c: &M3<f64>,
    ) -> (f64, [f64; 3], M3<f64>) {
        let u = unit(precision);
        let n = self.parts;
        // A sum of `terms` terms of absolute sum `abs`, value `v`.
        let sum = |v: f64, abs: f64, terms: f64| match precision {
            Precision::Standard => 2.0 * u * v.abs() + 4.0 * terms * u * u * abs,
            Precision::Extended => terms * u * abs,
        };
        let dm = u * self.mass_w + sum(mass, self.mass_abs, n) + self.body_mass;
        let ds: [f64; 3] = std::array::from_fn(|j| {
            u * self.first_w[j]
                + sum(s[j], self.first_abs[j], n)
                + self.first_off[j]
                + self.body_first[j]
        });
        let root_w = self.coupled_w.map(f64::sqrt);
        let root_abs = self.coupled_abs.map(f64::sqrt);
        let e = std::array::from_fn(|j| {
            std::array::from_fn(|k| {
                // The own moments' errors: on the diagonal their sum; off
                // it, Cauchy–Schwarz over the parts whose own C is not
                // diagonal (the others' off-diagonal entries are exact
                // zeros).
                let (own, own_abs) = if j == k {
                    (self.own_w[j], self.own_abs[j])
                } else {
                    (root_w[j] * root_w[k], root_abs[j] * root_abs[k])
                };
                let shift = upper(j, k);
                self.shift_off[shift]
                    + u * (own + self.shift_w[shift] + self.rot)
                    + sum(
                        c[j][k],
                        own_abs + self.shift_abs[shift] + self.body_abs[shift],
                        2.0 * n + 1.0,
                    )
                    + self.body_second[shift]
            })
        });
        (dm, ds, e)
    }

    /// The bounds of the composed body, from the composer's results in file
    /// units: the total `mass`, the residual first moment `s` about the
    /// pivot, the centre `com` and the second moment `c` about it.
    pub fn finish(
        &self,
        precision: Precision,
        mass: f64,
        s: [f64; 3],
        com: [f64; 3],
        c: &M3<f64>,
    ) -> BodyError {
        let u = unit(precision);
        let am = mass.abs();
        let (dm, ds, raw) = self.sums(precision, mass, s, c);
        let dc = std::array::from_fn(|j| {
            safe(
                ds[j] / am
                    + (s[j].abs() / am) * (dm / am)
                    + 2.0 * u * (s[j] / mass).abs()
                    + u * com[j].abs(),
            )
        });
        let e = std::array::from_fn(|j| {
            std::array::from_fn(|k| {
                let (sj, sk) = (s[j].abs(), s[k].abs());
                let correction = ds[j] * (sk / am)
                    + (sj / am) * ds[k]
                    + sj * (sk / am) * (dm / am)
                    + 3.0 * u * sj * (sk / am);
                safe(raw[j][k] + correction)
            })
        });
        BodyError {
            mass: safe(dm),
            center_of_mass: dc,
            second_moment: e,
        }
    }
}

/// Bounds of a composed body, file units: absolute, entry by entry.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyError {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    /// Of ∫ρρᵀ dm about the centre of mass.
    pub second_moment: M3<f64>,
}

impl BodyError {
    /// The bound of the second moment about a point at offset `r` = c − p
    /// from the centre (p exact: given, or the exact centre itself when
    /// `r` is zero), C + m r rᵀ formed in double-double.
    pub fn second_moment_about(&self, mass: f64, r: [f64; 3], c_about: &M3<f64>) -> M3<f64> {
        let am = mass.abs();
        let dc = self.center_of_mass;
        std::array::from_fn(|j| {
            std::array::from_fn(|k| {
                let (rj, rk) = (r[j].abs(), r[k].abs());
                safe(
                    self.second_moment[j][k]
                        + self.mass * rj * rk
                        + am * (dc[j] * rk + rj * dc[k] + dc[j] * dc[k])
                        + 16.0 * unit(Precision::Extended) * (c_about[j][k].abs() + am * rj * rk),
                )
            })
        })
    }
}

/// The bound of I = tr(C)E − C (I_jj = C_kk + C_ll, I_jk = −C_jk) from
/// that of C.
pub fn inertia_of(e: &M3<f64>) -> M3<f64> {
    std::array::from_fn(|j| {
        std::array::from_fn(|k| {
            if j == k {
                safe(e[(j + 1) % 3][(j + 1) % 3] + e[(j + 2) % 3][(j + 2) % 3])
            } else {
                e[j][k]
            }
        })
    })
}

/// A bound in file units made a bound of the SI value `value` (rounded to
/// f64, within u of itself) by the unit factor `factor`.
pub fn to_si(bound: f64, factor: f64, value: f64) -> f64 {
    safe(bound * factor + U64 * value.abs())
}

/// What the eigen solver gave (`compose::Principal`): per axis, its
/// eigenvalue of C and its eigenvector as found, the rotations it took,
/// and the axes of moments flagged equal.
#[derive(Debug, Clone, Copy)]
pub struct Solved<'a> {
    pub lambda: [f64; 3],
    pub eigenvectors: &'a [Vector3<f64>; 3],
    pub rotations: usize,
    pub equal: &'a [usize],
    /// `backward_error` of the solution.
    pub backward: f64,
}

/// Bounds of principal moments and axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EigenError {
    /// Of each principal moment (file units of C).
    pub moments: [f64; 3],
    /// Of each axis, as the angle in radians between it and the exact axis;
    /// π/2 for an axis of equal moments, which is a choice (not unique).
    pub axes: [f64; 3],
}

/// The backward error of one Jacobi rotation, in units: a rotation computed
/// from a few operations and applied as two products and a sum per entry
/// (Demmel and Veselić 1992, §4: a perturbation of each entry by a few
/// units of √(a_pp a_qq)).
const JACOBI: f64 = 8.0;

/// Error bounds of the principal moments and axes computed from the second
/// moment `c` (as the solver took it) whose entries lie within `e` of the
/// exact ones.
///
/// Each eigenvalue λ of C moves by at most:
/// - `e_jj` when its eigenvector is a file axis j that C and the error
///   bound both leave uncoupled (row j off the diagonal zero in both): the
///   solver never touches it, so λ = C_jj;
/// - ‖E‖_F (Weyl), E the perturbation of the coupled rows plus the solver's
///   backward error;
/// - λ · η/(1 − η) with η = ‖D⁻¹ E D⁻¹‖_F / λ_min(D⁻¹ C D⁻¹), D = diag(√C_jj),
///   when below ½ (Demmel and Veselić 1992, Theorem 2.3: the relative
///   bound of a positive definite matrix whose scaled form is well
///   conditioned, which keeps the small moments of a slender body that is
///   not turned).
///
/// An axis moves by at most arcsin(‖r‖/(g − 2w)), r the part of E vᵢ
/// across vᵢ plus the solver's residual, w the Weyl bound and g the gap
/// from its eigenvalue to the others (Davis and Kahan's sin θ theorem with
/// the Rayleigh quotient), plus its rounding to a unit f64 vector.
pub fn eigen(c: &M3<f64>, e: &M3<f64>, p: &Solved, precision: Precision) -> EigenError {
    let u = unit(precision);
    // The uncoupled file axes.
    let free: [bool; 3] = std::array::from_fn(|j| {
        (0..3)
            .filter(|k| *k != j)
            .all(|k| c[j][k] == 0.0 && e[j][k] == 0.0)
    });
    let axis_of = |v: &Vector3<f64>| {
        let nonzero: Vec<usize> = (0..3).filter(|k| v[*k] != 0.0).collect();
        match nonzero[..] {
            [j] if free[j] => Some(j),
            _ => None,
        }
    };
    let coupled: Vec<usize> = (0..3).filter(|j| !free[*j]).collect();
    // For the relative bound, a priori: each rotation perturbs the scaled
    // matrix by a few units, and the stopping test drops off-diagonal
    // entries up to 2u √(a_pp a_qq) (three at most: 2√2 u each in the
    // Frobenius norm).
    let solver = JACOBI * u * p.rotations as f64 + 9.0 * u;
    // The solver's error as a perturbation F of C, a posteriori
    // (`backward_error`): typically a unit of ‖C‖ where an a priori count
    // of its rotations gives dozens.
    let backward = p.backward;
    let weyl = root_sum_squares(
        coupled
            .iter()
            .flat_map(|&j| coupled.iter().map(move |&k| e[j][k])),
    ) + backward;
    let relative = scaled_condition(c, e, &coupled).map(|(eta, low)| (eta + solver) / low);
    let mut lambda: [f64; 3] = std::array::from_fn(|i| match axis_of(&p.eigenvectors[i]) {
        Some(j) => e[j][j],
        None => {
            let rel = match relative {
                Some(r) if r < 0.5 => p.lambda[i].abs() * r / (1.0 - r),
                _ => f64::INFINITY,
            };
            weyl.min(rel)
        }
    });
    // Moments are reported sorted, and the exact ones sorted too: where
    // two eigenvalues' intervals overlap (an uncoupled axis's beside the
    // coupled block's), their order may differ from the exact one's. Sorting
    // is a contraction in the largest difference, so each eigenvalue of a
    // cluster of overlapping intervals takes the cluster's largest bound;
    // and its axis is not known to be the exact axis of that position.
    let mut clustered = [false; 3];
    for _ in 0..2 {
        for a in 0..3 {
            for b in a + 1..3 {
                if (p.lambda[a] - p.lambda[b]).abs() <= lambda[a] + lambda[b] {
                    let top = lambda[a].max(lambda[b]);
                    (lambda[a], lambda[b]) = (top, top);
                    (clustered[a], clustered[b]) = (true, true);
                }
            }
        }
    }
    let moments = std::array::from_fn(|i| {
        let (a, b) = ((i + 1) % 3, (i + 2) % 3);
        safe(lambda[a] + lambda[b] + 4.0 * u * (p.lambda[a].abs() + p.lambda[b].abs()))
    });
    let axes = std::array::from_fn(|i| {
        if p.equal.contains(&i) || clustered[i] {
            return std::f64::consts::FRAC_PI_2;
        }
        if axis_of(&p.eigenvectors[i]).is_some() {
            return 0.0;
        }
        let gap = (0..3)
            .filter(|k| *k != i)
            .map(|k| (p.lambda[i] - p.lambda[k]).abs())
            .fold(f64::INFINITY, f64::min);
        // The residual of vᵢ in the exact C: its part across vᵢ, bounded
        // in the basis of the other eigenvectors by |v_k|ᵀ|E||vᵢ| (a
        // perturbation along the file's axes does not turn an axis that
        // lies along them), plus the solver's residual.
        let v = &p.eigenvectors;
        let across = root_sum_squares((0..3).filter(|k| *k != i).map(|k| {
            coupled
                .iter()
                .flat_map(|&j| coupled.iter().map(move |&l| (j, l)))
                .map(|(j, l)| v[k][j].abs() * e[j][l] * v[i][l].abs())
                .sum::<f64>()
        })) + backward;
        let sin = if gap > 3.0 * weyl {
            across / (gap - 2.0 * weyl)
        } else {
            1.0
        };
        // The vector's own rounding, its normalisation and, for the third
        // axis, the cross product of the first two.
        safe(sin.min(1.0).asin() + 8.0 * U64)
    });
    EigenError { moments, axes }
}

/// A bound on the eigen solver's backward error ‖F‖₂ (its eigenpairs are
/// exact for C − F), a posteriori: ‖R‖_F (1 + δ) + 2‖C‖_F δ with the
/// residual R = C V − V Λ and δ = ‖VᵀV − E‖_F, formed in double-double
/// from the solver's own C, V and Λ (in its arithmetic, before rounding),
/// with the rounding of that formation counted (four units of
/// double-double of its terms).
pub fn backward_error<T: Real + Into<DD>>(c: &M3<T>, lambda: &[T; 3], v: &M3<T>) -> f64 {
    let dd = |x: T| -> DD { x.into() };
    // Four double-double operations' rounding, relative to the terms.
    let slack = 4.0 * unit(Precision::Extended);
    let mut r = Vec::with_capacity(9);
    let mut terms = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            // Column i of V is the eigenvector of λᵢ.
            let mut acc = -(dd(lambda[i]) * dd(v[j][i]));
            terms += (lambda[i].f64() * v[j][i].f64()).abs();
            for k in 0..3 {
                acc += dd(c[j][k]) * dd(v[k][i]);
                terms += (c[j][k].f64() * v[k][i].f64()).abs();
            }
            r.push(acc.f64());
        }
    }
    let mut o2 = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let mut acc = DD::new(if i == j { -1.0 } else { 0.0 }, 0.0);
            for row in v {
                acc += dd(row[i]) * dd(row[j]);
            }
            o2 += acc.f64() * acc.f64();
        }
    }
    let delta = o2.sqrt() * (1.0 + 1e-15) + 9.0 * slack;
    let norm = root_sum_squares(c.iter().flatten().map(|x| x.f64()));
    let r = root_sum_squares(r);
    safe((r * (1.0 + 1e-15) + slack * terms) * (1.0 + delta) + 2.0 * norm * delta)
}

/// For the coupled rows of C: η = ‖D⁻¹ E D⁻¹‖_F with D = diag(√(C_jj − E_jj))
/// and a lower bound of λ_min(D⁻¹ C D⁻¹) (a 2 × 2 with off-diagonal a:
/// 1 − |a|; a 3 × 3, whose eigenvalues are ≥ 0 and sum to 3: det/(3/2)²),
/// or `None` when a diagonal entry is not clearly positive or the scaled
/// matrix is not clearly definite.
fn scaled_condition(c: &M3<f64>, e: &M3<f64>, coupled: &[usize]) -> Option<(f64, f64)> {
    let root: [f64; 3] = std::array::from_fn(|j| (c[j][j] - e[j][j]).max(0.0).sqrt());
    if coupled.iter().any(|&j| root[j] == 0.0 || c[j][j] <= 0.0) {
        return None;
    }
    let eta = coupled
        .iter()
        .flat_map(|&j| coupled.iter().map(move |&k| (j, k)))
        .map(|(j, k)| {
            let x = e[j][k] / root[j] / root[k];
            x * x
        })
        .sum::<f64>()
        .sqrt();
    let scaled = |j: usize, k: usize| c[j][k] / c[j][j].sqrt() / c[k][k].sqrt();
    let low = match coupled {
        [] | [_] => 1.0,
        [j, k] => 1.0 - scaled(*j, *k).abs() - 4.0 * U64,
        _ => {
            // det/(3/2)² bounds λ_min below only for a positive definite
            // matrix: with a unit diagonal, when 1 − a² and det are both
            // clearly positive (Sylvester).
            let (a, b, d) = (scaled(0, 1), scaled(0, 2), scaled(1, 2));
            let det = 1.0 + 2.0 * a * b * d - a * a - b * b - d * d - 32.0 * U64;
            if 1.0 - a * a - 4.0 * U64 > 0.0 {
                det / 2.25
            } else {
                0.0
            }
        }
    };
    (low > 0.0 && eta.is_finite()).then_some((eta, low))
}

/// The error bounds of everything `report` prints, in SI, absolute: the
/// same keys as the values they bound (docs/json.md). Axes as angles.
/// Each quantity's bound is formed as its row of the quantity table says
/// (`quantity::Formed`, `analysis::summary::formed`) and held by the row
/// (`of`); the typed fields are copies of the bounds of the quantities
/// reported when the JSON contract was fixed, for the library's users
/// and the outputs that lay one out. Written (`Serialize`, below) by the
/// quantity table, each in its place (`quantity::Info::bound`).
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorBounds {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub reference_point: [f64; 3],
    pub inertia_com: [[f64; 3]; 3],
    pub inertia_ref: [[f64; 3]; 3],
    pub principal_moments: [f64; 3],
    /// Radians.
    pub principal_axes: [f64; 3],
    pub principal_moments_ref: [f64; 3],
    /// Radians.
    pub principal_axes_ref: [f64; 3],
    pub radii_of_gyration: [f64; 3],
    pub radii_of_gyration_axes: [f64; 3],
    pub radii_of_gyration_axes_ref: [f64; 3],
    pub center_of_mass_ref: [f64; 3],
    pub angular_momentum: Option<[f64; 3]>,
    pub kinetic_energy: Option<f64>,
    pub euler_moment: Option<[f64; 3]>,
    bounds: Table,
}

/// A bound every body has (its quantity needs nothing).
fn must<T>(b: Option<T>) -> T {
    b.expect("invariant: a bounded quantity that needs nothing is bounded for every body")
}

impl ErrorBounds {
    /// The bounds, one per quantity by its row (`None` where it has none).
    pub fn new(bounds: Table) -> ErrorBounds {
        let triple = |q: Quantity| must(bounds.triple(q));
        ErrorBounds {
            mass: must(bounds.scalar(Quantity::Mass)),
            center_of_mass: triple(Quantity::CenterOfMass),
            reference_point: triple(Quantity::ReferencePoint),
            inertia_com: must(bounds.rows(Quantity::InertiaCom)),
            inertia_ref: must(bounds.rows(Quantity::InertiaRef)),
            principal_moments: triple(Quantity::PrincipalMoments),
            principal_axes: triple(Quantity::PrincipalAxes),
            principal_moments_ref: triple(Quantity::PrincipalMomentsRef),
            principal_axes_ref: triple(Quantity::PrincipalAxesRef),
            radii_of_gyration: triple(Quantity::RadiiOfGyration),
            radii_of_gyration_axes: triple(Quantity::RadiiOfGyrationAxes),
            radii_of_gyration_axes_ref: triple(Quantity::RadiiOfGyrationAxesRef),
            center_of_mass_ref: triple(Quantity::CenterOfMassRef),
            angular_momentum: bounds.triple(Quantity::AngularMomentum),
            kinetic_energy: bounds.scalar(Quantity::KineticEnergy),
            euler_moment: bounds.triple(Quantity::EulerMoment),
            bounds,
        }
    }

    /// The bound of quantity `q`; `None` for a value given (exact), one
    /// not computed (no ω, no α) or the predicted body's.
    pub fn of(&self, q: Quantity) -> Option<Value<'_>> {
        self.bounds.get(q)
    }
}

/// `error_bounds` (docs/json.md): each bound under its quantity's key, in
/// its place in the table.
impl Serialize for ErrorBounds {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        // An upper bound: serde_json closes an object announced empty.
        let mut m = s.serialize_struct("ErrorBounds", crate::quantity::QUANTITIES.len())?;
        for info in crate::quantity::in_order(|i| i.bound) {
            crate::quantity::serialize_field(&mut m, info, self.of(info.quantity))?;
        }
        m.end()
    }
}

/// The bound of a radius of gyration k = √(I/m) from those of I and m:
/// √(I + δI) − √I ≤ min(δI/(2√I), √δI).
pub fn radius(k: f64, moment: f64, d_moment: f64, mass: f64, d_mass: f64) -> f64 {
    let root = if moment > 0.0 {
        (d_moment / (2.0 * moment.sqrt())).min(d_moment.sqrt())
    } else {
        d_moment.sqrt()
    };
    safe(
        root / mass.sqrt()
            + k * d_mass / (2.0 * mass - 2.0 * d_mass).max(f64::MIN_POSITIVE)
            + 2.0 * U64 * k,
    )
}

/// The bounds of H = I ω, T = ½ ωᵀ I ω and M = I α + ω × H from the bound
/// `e` of I (SI) and the computed H, T and M, each formed in double-double
/// and rounded once.
pub fn dynamics(
    e: &M3<f64>,
    omega: [f64; 3],
    alpha: Option<[f64; 3]>,
    h: [f64; 3],
    t: f64,
    m: Option<[f64; 3]>,
) -> ([f64; 3], f64, Option<[f64; 3]>) {
    let times = |v: [f64; 3]| -> [f64; 3] {
        std::array::from_fn(|j| (0..3).map(|k| e[j][k] * v[k].abs()).sum())
    };
    let dh_exact = times(omega);
    let dh = std::array::from_fn(|j| safe(dh_exact[j] + U64 * h[j].abs()));
    let dt = safe(0.5 * (0..3).map(|j| omega[j].abs() * dh_exact[j]).sum::<f64>() + U64 * t.abs());
    let dm = alpha.zip(m).map(|(a, m)| {
        let ia = times(a);
        std::array::from_fn(|j| {
            let (k, l) = ((j + 1) % 3, (j + 2) % 3);
            safe(
                ia[j]
                    + omega[k].abs() * dh_exact[l]
                    + omega[l].abs() * dh_exact[k]
                    + U64 * m[j].abs(),
            )
        })
    });
    (dh, dt, dm)
}
