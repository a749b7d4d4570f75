//! The composed body and the one parallel-axis shift.
//!
//! NOTE: we keep the second moment C = ∫ρρᵀ dm rather than the inertia
//! tensor I = tr(C)·E − C. C shifts to a point at offset d as C + m d dᵀ,
//! with no sign to get wrong in the products (gz-math, trimesh and parry each
//! shipped a wrong-sign product in their I-form shift); I is formed only for
//! output.

use crate::la::Matrix3;
use crate::numeric::{DD, M3, Real};

/// A composed body in the file's units and axes, held in double-double so
/// that the `extended` mode loses nothing before output (the `standard`
/// composer stores f64 values in it).
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    pub mass: DD,
    /// Centre of mass in the file's frame.
    pub center_of_mass: [DD; 3],
    /// ∫ρρᵀ dm about the centre of mass, file axes.
    pub second_moment: M3<DD>,
}

impl Body {
    /// ∫ρρᵀ dm about `point`: the parallel-axis shift C + m d dᵀ, d = c − point.
    pub fn second_moment_about(&self, point: &[DD; 3]) -> M3<DD> {
        let d: [DD; 3] = std::array::from_fn(|i| self.center_of_mass[i] - point[i]);
        std::array::from_fn(|i| {
            // (m d) dᵀ, not (d dᵀ) m: d dᵀ alone can underflow or overflow.
            std::array::from_fn(|j| self.second_moment[i][j] + (self.mass * d[i]) * d[j])
        })
    }
}

/// The inertia tensor (tensor convention: off-diagonals −∫xy dm) of a second
/// moment C. Diagonals are formed as sums, I_xx = C_yy + C_zz, rather than
/// tr(C) − C_xx, so a small moment is not the difference of large ones.
pub fn inertia_of_rows<T: Real>(c: &M3<T>) -> M3<T> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                c[(i + 1) % 3][(i + 1) % 3] + c[(i + 2) % 3][(i + 2) % 3]
            } else {
                -c[i][j]
            }
        })
    })
}

/// `inertia_of_rows` for a `Matrix3`.
pub fn inertia_of(c: &Matrix3<f64>) -> Matrix3<f64> {
    let rows: M3<f64> = std::array::from_fn(|i| std::array::from_fn(|j| c[(i, j)]));
    let i = inertia_of_rows(&rows);
    Matrix3::from_fn(|r, k| i[r][k])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::la::Vector3;

    #[test]
    fn inertia_of_a_point_mass_matches_the_textbook_form() {
        // A 2 kg point at (1, 2, 3): I = m (|r|² E − r rᵀ).
        let r = Vector3::new(1.0, 2.0, 3.0);
        let c = r * r.transpose() * 2.0;
        let expect = (Matrix3::identity() * r.norm_squared() - r * r.transpose()) * 2.0;
        assert_eq!(inertia_of(&c), expect);
        // Products are −∫xy dm in the tensor convention.
        assert_eq!(inertia_of(&c)[(0, 1)], -4.0);
    }

    #[test]
    fn shift_adds_m_d_dt() {
        let eye: M3<DD> = std::array::from_fn(|i| {
            std::array::from_fn(|j| DD::of(if i == j { 1.0 } else { 0.0 }))
        });
        let p = Body {
            mass: DD::of(3.0),
            center_of_mass: [1.0, 0.0, 2.0].map(DD::of),
            second_moment: eye,
        };
        let c = p.second_moment_about(&[DD::of(0.0); 3]);
        assert_eq!(c[0][2], DD::of(6.0));
        assert_eq!(c[2][2], DD::of(13.0));
        assert_eq!(c[1][1], DD::of(1.0));
        assert_eq!(p.second_moment_about(&p.center_of_mass), p.second_moment);
    }
}
