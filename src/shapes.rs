//! The primitive shapes and their closed forms: second moments of mass about
//! the shape's own centroid along its own local axes, ∫x² dm, ∫y² dm, ∫z² dm
//! (kg·m²). The local frames are:
//!
//! - box: edges `a, b, c` along local x, y, z, centred on the origin;
//! - plate: thin rectangle `a × b` in the local x–y plane, zero thickness;
//! - rod: slender segment of length `L` along local z, zero radius;
//! - point: a point mass at the origin.
//!
//! For a uniform segment of length a centred on 0, ∫x² dm = m a²/12; each
//! shape is a product of such segments, so its second moments are diagonal
//! in local axes and need no products of inertia.
//!
//! A plate's real `thickness` and a rod's `diameter` never enter these: the
//! composition is the idealised one, and `report::ideal` compares it with
//! the solid box and cylinder they describe.

use nalgebra::Vector3;
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Shape {
    Box,
    Plate,
    Rod,
    Point,
}

impl Shape {
    pub const ALL: [Shape; 4] = [Shape::Box, Shape::Plate, Shape::Rod, Shape::Point];

    pub fn name(self) -> &'static str {
        match self {
            Shape::Box => "box",
            Shape::Plate => "plate",
            Shape::Rod => "rod",
            Shape::Point => "point",
        }
    }

    pub fn from_name(name: &str) -> Option<Shape> {
        Shape::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Number of edge vectors that span the shape (and of `size` entries).
    pub fn edge_count(self) -> usize {
        match self {
            Shape::Box => 3,
            Shape::Plate => 2,
            Shape::Rod => 1,
            Shape::Point => 0,
        }
    }

    /// The key of the density that this shape takes instead of `mass`.
    pub fn density_key(self) -> Option<&'static str> {
        match self {
            Shape::Box => Some("density"),
            Shape::Plate => Some("areal_density"),
            Shape::Rod => Some("linear_density"),
            Shape::Point => None,
        }
    }

    /// Volume, area or length (m³, m², m) of the given edge lengths, the
    /// measure that the density multiplies.
    pub fn measure(self, dims: &[f64]) -> f64 {
        dims.iter().product()
    }

    /// ∫x² dm, ∫y² dm, ∫z² dm about the centroid in local axes, for edge
    /// lengths `dims` (box: a, b, c; plate: a, b; rod: L; point: none).
    pub fn local_second_moment(self, mass: f64, dims: &[f64]) -> Vector3<f64> {
        let seg = |a: f64| mass * a * a / 12.0;
        match (self, dims) {
            (Shape::Box, &[a, b, c]) => Vector3::new(seg(a), seg(b), seg(c)),
            (Shape::Plate, &[a, b]) => Vector3::new(seg(a), seg(b), 0.0),
            (Shape::Rod, &[l]) => Vector3::new(0.0, 0.0, seg(l)),
            (Shape::Point, &[]) => Vector3::zeros(),
            _ => unreachable!("the model passes each shape its edge_count() dimensions"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gauss–Legendre nodes and weights on [−½, ½] (n = 5, exact to degree 9).
    fn gauss5() -> [(f64, f64); 5] {
        let a = (5.0 - 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let b = (5.0 + 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let wa = (322.0 + 13.0 * 70.0f64.sqrt()) / 900.0;
        let wb = (322.0 - 13.0 * 70.0f64.sqrt()) / 900.0;
        [(0.0, 128.0 / 225.0), (a, wa), (-a, wa), (b, wb), (-b, wb)]
            .map(|(x, w)| (x / 2.0, w / 2.0))
    }

    /// ∫ρρᵀ dm of a uniform parallelepiped by direct quadrature over its
    /// parameter cube: independent of the closed form's a²/12.
    fn quadrature(mass: f64, dims: &[f64]) -> Vector3<f64> {
        let g = gauss5();
        let mut out = Vector3::zeros();
        let n = dims.len();
        let mut idx = vec![0usize; n];
        loop {
            let mut w = mass;
            let mut p = Vector3::zeros();
            for k in 0..n {
                let (t, wt) = g[idx[k]];
                w *= wt;
                p[k + 3 - n] = t * dims[k]; // rods lie along z
            }
            if n == 2 {
                // plates lie in x–y
                p = Vector3::new(p[1], p[2], 0.0);
            }
            out += p.component_mul(&p) * w;
            let mut k = 0;
            while k < n {
                idx[k] += 1;
                if idx[k] < g.len() {
                    break;
                }
                idx[k] = 0;
                k += 1;
            }
            if k == n {
                break;
            }
        }
        out
    }

    fn assert_close(a: Vector3<f64>, b: Vector3<f64>) {
        let tol = 8.0 * f64::EPSILON * b.amax().max(f64::MIN_POSITIVE);
        assert!((a - b).amax() <= tol, "{a} vs {b}");
    }

    #[test]
    fn box_closed_form_matches_quadrature() {
        let dims = [0.3, 1.7, 0.05];
        assert_close(
            Shape::Box.local_second_moment(2.5, &dims),
            quadrature(2.5, &dims),
        );
    }

    #[test]
    fn plate_closed_form_matches_quadrature() {
        let dims = [0.125, 0.1];
        assert_close(
            Shape::Plate.local_second_moment(0.875, &dims),
            quadrature(0.875, &dims),
        );
    }

    #[test]
    fn rod_closed_form_matches_quadrature() {
        assert_close(
            Shape::Rod.local_second_moment(3.0, &[2.0]),
            quadrature(3.0, &[2.0]),
        );
    }

    #[test]
    fn point_has_no_second_moment() {
        assert_eq!(Shape::Point.local_second_moment(5.0, &[]), Vector3::zeros());
    }

    #[test]
    fn measure_is_volume_area_or_length() {
        assert_eq!(Shape::Box.measure(&[2.0, 3.0, 4.0]), 24.0);
        assert_eq!(Shape::Plate.measure(&[2.0, 3.0]), 6.0);
        assert_eq!(Shape::Rod.measure(&[2.0]), 2.0);
    }
}
