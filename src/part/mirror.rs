//! A part's mirror image: the one rule of how each shape and placement is
//! reflected, for `mirror = { .. }` (`model::copies`).
//!
//! A reflection S = E − 2 n nᵀ moves the points a part is placed by
//! (centre, corner and edges, ends, vertices) as it moves any point: the
//! frame that places the copy does that (`model::Frame::place`). A part
//! placed by its centre and a turn R cannot be turned by S R, which is no
//! turn (its determinant is −1); but each shape is its own mirror image in
//! the plane of one of its local axes (F, that axis flipped), so its image
//! is the same shape turned by the proper rotation S R F. A given inertia
//! tensor I is not symmetric in F: it becomes F I F (its products with that
//! axis negated), so that (S R F)(F I F)(S R F)ᵀ = S R I Rᵀ S.
//!
//! NOTE: the hook for new shapes and placements. A shape's module answers
//! `ShapeKind::MIRROR_AXIS` (a new shape does not compile until it does);
//! a shape symmetric in no local plane (a mesh) answers `None` and
//! reflects its own data in `complete`'s arm for its placement.

use super::Place;
use crate::rotation::Orientation;
use crate::shapes::Shape;

/// The local axis in whose plane through the local origin the shape, as
/// its closed forms take it, is its own mirror image: each shape's module
/// says (`ShapeKind::MIRROR_AXIS`).
///
/// NOTE: x for every shape placed by its centre (a prism: z, the
/// extrusion it is centred in): a box, plate or rod is
/// symmetric in all three; a cylinder's, disk's or rod's axis is local z,
/// and every solid of revolution about z (cone, torus, hemisphere) is
/// symmetric in x; a sphere, a
/// point and a given tensor (flipped with it, `complete`) in any. A mesh
/// is symmetric in no local plane in general: `complete` reflects its
/// data (`part::reflect_mesh`).
pub fn symmetric_axis(shape: Shape) -> Option<usize> {
    shape.mirror_axis()
}

/// `place`, whose points a reflection has moved and whose turn it has
/// turned (`orientation` is then S R, or S for a part not turned),
/// completed as the part's mirror image: the turn becomes S R F, and a
/// given tensor F I F. Placements by points alone are complete already.
pub fn complete(shape: Shape, place: &mut Place) {
    let flip = |k: usize, o: &mut Orientation| {
        let mut n = [0.0; 3];
        n[k] = 1.0;
        let sr = std::mem::replace(o, Orientation::Identity);
        *o = Orientation::Then(Box::new(sr), Box::new(Orientation::Reflect(n)));
    };
    let k = symmetric_axis(shape).unwrap_or(0);
    match place {
        Place::Centered { orientation, .. }
        | Place::Axial { orientation, .. }
        | Place::Prism { orientation, .. } => flip(k, orientation),
        Place::Given {
            inertia,
            orientation,
            ..
        } => {
            flip(k, orientation);
            for j in 0..3 {
                if j != k {
                    inertia[k][j] = -inertia[k][j];
                    inertia[j][k] = -inertia[j][k];
                }
            }
        }
        Place::Mesh { orientation, .. } => {
            flip(k, orientation);
            // The mesh's own data reflected in the same local plane: the
            // image is S R F (F p) = S R p, for every point p of the mesh.
            super::reflect_mesh(place, k);
        }
        Place::Edges { .. } | Place::FromTo { .. } | Place::Vertices(_) => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::M3;

    fn mul(a: &M3<f64>, b: &M3<f64>) -> M3<f64> {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    }

    fn det(m: &M3<f64>) -> f64 {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }

    #[test]
    fn a_mirrored_turn_is_a_proper_rotation() {
        let mut place = Place::Centered {
            center: [0.0; 3],
            extent: [1.0, 2.0, 3.0],
            orientation: Orientation::Then(
                Box::new(Orientation::Reflect([1.0, 2.0, 2.0])),
                Box::new(Orientation::AxisAngle([1.0, 1.0, 0.0], 30.0)),
            ),
        };
        complete(Shape::Box, &mut place);
        let Place::Centered { orientation, .. } = &place else {
            unreachable!()
        };
        let r: M3<f64> = orientation.matrix();
        assert!((det(&r) - 1.0).abs() < 1e-15, "{}", det(&r));
        let rt: M3<f64> = std::array::from_fn(|i| std::array::from_fn(|j| r[j][i]));
        let e = mul(&r, &rt);
        for (i, row) in e.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((x - want).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn a_given_tensor_is_flipped_in_the_symmetric_axis() {
        let mut place = Place::Given {
            center: [0.0; 3],
            inertia: Box::new([[4.0, -1.0, -2.0], [-1.0, 5.0, -3.0], [-2.0, -3.0, 6.0]]),
            orientation: Orientation::Identity,
        };
        complete(Shape::Inertia, &mut place);
        let Place::Given { inertia, .. } = &place else {
            unreachable!()
        };
        assert_eq!(
            **inertia,
            [[4.0, 1.0, 2.0], [1.0, 5.0, -3.0], [2.0, -3.0, 6.0]]
        );
    }
}
