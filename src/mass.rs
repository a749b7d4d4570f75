//! The mass-properties value and the one parallel-axis shift.
//!
//! NOTE: we keep the second moment C = ∫ρρᵀ dm rather than the inertia
//! tensor I = tr(C)·E − C. C shifts to a point at offset d as C + m d dᵀ,
//! with no sign to get wrong in the products (gz-math, trimesh and parry each
//! shipped a wrong-sign product in their I-form shift); I is formed only for
//! output.

use nalgebra::{Matrix3, Vector3};

#[derive(Debug, Clone, PartialEq)]
pub struct MassProps {
    /// kg
    pub mass: f64,
    /// Centre of mass in the file's frame, m.
    pub center_of_mass: Vector3<f64>,
    /// ∫ρρᵀ dm about the centre of mass, file axes, kg·m².
    pub second_moment: Matrix3<f64>,
}

impl MassProps {
    /// ∫ρρᵀ dm about `point`: the parallel-axis shift C + m d dᵀ, d = c − point.
    pub fn second_moment_about(&self, point: &Vector3<f64>) -> Matrix3<f64> {
        let d = self.center_of_mass - point;
        // (m d) dᵀ, not (d dᵀ) m: d dᵀ alone can underflow or overflow.
        self.second_moment + (d * self.mass) * d.transpose()
    }
}

/// The inertia tensor (tensor convention: off-diagonals −∫xy dm) of a second
/// moment C. Diagonals are formed as sums, I_xx = C_yy + C_zz, rather than
/// tr(C) − C_xx, so a small moment is not the difference of large ones.
pub fn inertia_of(c: &Matrix3<f64>) -> Matrix3<f64> {
    let mut i = -c;
    i[(0, 0)] = c[(1, 1)] + c[(2, 2)];
    i[(1, 1)] = c[(0, 0)] + c[(2, 2)];
    i[(2, 2)] = c[(0, 0)] + c[(1, 1)];
    i
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let p = MassProps {
            mass: 3.0,
            center_of_mass: Vector3::new(1.0, 0.0, 2.0),
            second_moment: Matrix3::identity(),
        };
        let c = p.second_moment_about(&Vector3::zeros());
        assert_eq!(c[(0, 2)], 6.0);
        assert_eq!(c[(2, 2)], 13.0);
        assert_eq!(c[(1, 1)], 1.0);
        assert_eq!(p.second_moment_about(&p.center_of_mass), p.second_moment);
    }
}
