//! What moves a placed shape's numbers (`Place`, each shape's module's
//! placed form): a frame (`Mover`, `Place::moved`), the frames' rounding
//! of them (`Placed`), a tolerance (`Place::number_mut`).

use super::Place;
use super::lift::Slot;
use crate::rotation::Orientation;

/// The rounding of a part's numbers by the frames that placed it, for its
/// error bounds (`shapes::error`): `units` of f64's unit roundoff, relative,
/// in its sizes, edges, mass or density and tensor entries; `at`, absolute
/// (file units), in each coordinate of its position; `mass`, units of
/// f64's unit roundoff, relative, by which its mass or density was rounded
/// before composition whatever the arithmetic (a material's density times
/// a `thickness`, `area` or `diameter`, formed in f64 as the file is
/// read). Rounded up to f32 (they are bounds; a part stays small).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Placed {
    pub units: f32,
    pub at: f32,
    pub mass: f32,
}

impl Placed {
    /// `units` and `at`, each rounded up to f32.
    pub fn new(units: f64, at: f64) -> Placed {
        let up = |x: f64| {
            let y = x as f32;
            if f64::from(y) < x { y.next_up() } else { y }
        };
        Placed {
            units: up(units),
            at: up(at),
            mass: 0.0,
        }
    }

    /// These, with `mass` units of its mass's rounding (rounded up).
    pub fn with_mass(self, mass: f64) -> Placed {
        let y = mass as f32;
        Placed {
            mass: if f64::from(y) < mass { y.next_up() } else { y },
            ..self
        }
    }
}

/// What moves a placement's numbers into another frame: a sub-assembly's
/// or a copy's (`model::frame::Frame`).
pub trait Mover {
    /// A point moved.
    fn point(&self, p: [f64; 3]) -> [f64; 3];
    /// A displacement (an edge) moved: scaled and turned.
    fn dir(&self, e: [f64; 3]) -> [f64; 3];
    /// A turn turned with the frame.
    fn turn(&self, o: &mut Orientation);
    /// The frame's length unit in the outer file's.
    fn length(&self) -> f64;
    /// The frame's mass unit in the outer file's.
    fn mass(&self) -> f64;
}

impl Place {
    /// The number in `slot` (not `Slot::Mass`, the part's), if the placed
    /// shape has it: the one map from a slot to a placed shape's number,
    /// by the slots its module names (`ShapeKind::numbers`).
    pub fn number_mut(&mut self, slot: Slot) -> Option<&mut f64> {
        let mut found = None;
        self.numbers(&mut |s, x| {
            if s == slot {
                found = Some(x);
            }
        });
        found
    }
}

impl Place {
    /// The turn R from its own axes into the file's, as the composer forms
    /// its tensor (R I′ Rᵀ; columns: its local axes in the file's frame),
    /// for `explain`; `None` where its numbers are in the file's axes
    /// already or no one turn places it (a triangle, a rod by its ends).
    // NOTE: matched here, not in `registry!`, to keep shapes/mod.rs under
    // 800 lines; the match is exhaustive, so a new shape must answer.
    pub fn turn(&self) -> Option<crate::numeric::M3<f64>> {
        use super::ShapeKind;
        match self {
            Place::Box(s) => s.turn(),
            Place::Plate(s) => s.turn(),
            Place::Rod(s) => s.turn(),
            Place::Cylinder(s) => s.turn(),
            Place::Disk(s) => s.turn(),
            Place::Sphere(s) => s.turn(),
            Place::Triangle(s) => s.turn(),
            Place::Point(s) => s.turn(),
            Place::Inertia(s) => s.turn(),
            Place::Cone(s) => s.turn(),
            Place::Torus(s) => s.turn(),
            Place::Hemisphere(s) => s.turn(),
            Place::Prism(s) => s.turn(),
            Place::Mesh(s) => s.turn(),
            Place::Capsule(s) => s.turn(),
            Place::Ellipsoid(s) => s.turn(),
        }
    }

    /// The box that holds its outline (`Outline::extent`), least then
    /// greatest coordinates: a mesh gives it without making its outline
    /// (a list of its every corner placed).
    // NOTE: matched here, as `turn`; exhaustive, so a new shape answers.
    pub fn extent(&self) -> [super::outline::V3; 2] {
        use super::ShapeKind;
        match self {
            Place::Mesh(s) => s.extent(),
            Place::Box(s) => s.outline().extent(),
            Place::Plate(s) => s.outline().extent(),
            Place::Rod(s) => s.outline().extent(),
            Place::Cylinder(s) => s.outline().extent(),
            Place::Disk(s) => s.outline().extent(),
            Place::Sphere(s) => s.outline().extent(),
            Place::Triangle(s) => s.outline().extent(),
            Place::Point(s) => s.outline().extent(),
            Place::Inertia(s) => s.outline().extent(),
            Place::Cone(s) => s.outline().extent(),
            Place::Torus(s) => s.outline().extent(),
            Place::Hemisphere(s) => s.outline().extent(),
            Place::Prism(s) => s.outline().extent(),
            Place::Capsule(s) => s.outline().extent(),
            Place::Ellipsoid(s) => s.outline().extent(),
        }
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
        let mut place = Place::Box(super::super::r#box::Cuboid::Centred {
            center: [0.0; 3],
            size: [1.0, 2.0, 3.0],
            orientation: Orientation::Then(
                Box::new(Orientation::Reflect([1.0, 2.0, 2.0])),
                Box::new(Orientation::AxisAngle([1.0, 1.0, 0.0], 30.0)),
            ),
        });
        place.mirror();
        let Place::Box(super::super::r#box::Cuboid::Centred { orientation, .. }) = &place else {
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
        let mut place = Place::Inertia(super::super::inertia::Given {
            center: [0.0; 3],
            inertia: Box::new([[4.0, -1.0, -2.0], [-1.0, 5.0, -3.0], [-2.0, -3.0, 6.0]]),
            orientation: Orientation::Identity,
        });
        place.mirror();
        let Place::Inertia(super::super::inertia::Given { inertia, .. }) = &place else {
            unreachable!()
        };
        assert_eq!(
            **inertia,
            [[4.0, 1.0, 2.0], [1.0, 5.0, -3.0], [2.0, -3.0, 6.0]]
        );
    }
}
