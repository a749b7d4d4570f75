//! A given inertia: a bought or previously computed component, its mass,
//! centre and inertia tensor about its centroid given. No closed form
//! here: the composer turns its tensor (`part::Place::Given`).

use super::common::{flip, given, mirror_axis, reset_turn};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::Lift;
use super::outline::{Marker, Outline};
use super::{MaterialRule, Mover, Own, Shape, ShapeInfo, ShapeKind, Slot, Units};
use crate::numeric::{DD, M3, Real};
use crate::rotation::Orientation;

/// A given inertia, in its file's units: its centroid `center`, its
/// tensor (tensor convention, symmetric, local axes) and its turn.
#[derive(Debug, Clone, PartialEq)]
pub struct Given {
    pub center: [f64; 3],
    pub inertia: Box<[[f64; 3]; 3]>,
    pub orientation: Orientation,
}

impl ShapeKind for Given {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Inertia,
        name: "inertia",
        keys: &[
            "mass", "center", "rotation", "inertia", "products", "remove",
        ],
        density: None,
        sizes: &["inertia"],
        size_items: 0,
        centred: &["center"],
        spanned: None,
        material: MaterialRule::None,
        real_size: None,
        nonzero_moments: 0,
        degenerate: "a tensor that is not symmetric or not physically valid",
        help: "an inertia part takes `mass`, `center`, `inertia` = [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] about its centroid in its local axes (optional `rotation`), tensor convention unless `products = \"positive\"`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "given inertia tensor, turned into the file's axes",
        dims: &[],
        measure: "",
        moments: [
            "",
            "",
            "",
        ],
    };

    /// None: its mass is given.
    const MEASURE_ROUNDINGS: f64 = 0.0;

    /// (its tensor is turned: `part::error::GIVEN`).
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        let [] = d else {
            unreachable!("the model passes a given inertia no dimensions")
        };
        T::of(1.0)
    }

    fn moments_of<T: Real>(_: T, d: &[T]) -> [T; 3] {
        let [] = d else {
            unreachable!("the model passes a given inertia no dimensions")
        };
        [T::of(0.0); 3]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        let inertia = Box::new(r.inertia()?);
        Ok(Given {
            center: r.point("center")?,
            inertia,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, _: L) -> T {
        T::of(1.0)
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        _: L,
    ) -> (M3<T>, Option<Own>) {
        given(&self.inertia, &self.orientation, m, units)
    }

    /// Its one moment checked is the trace.
    fn independent_moments(&self, _: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
        (
            [j[0][0] + j[1][1] + j[2][2], 0.0, 0.0],
            1,
            Self::INFO.nonzero_moments,
        )
    }

    fn moved(&mut self, m: &impl Mover) {
        self.center = m.point(self.center);
        *self.inertia = self
            .inertia
            .map(|r| r.map(|x| x * m.mass() * m.length() * m.length()));
        m.turn(&mut self.orientation);
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        for (i, x) in self.center.iter_mut().enumerate() {
            f(Slot::At(i as u8), x);
        }
    }

    fn reset_from(&mut self, src: &Self) {
        self.center = src.center;
        *self.inertia = *src.inertia;
        reset_turn(&mut self.orientation, &src.orientation);
    }

    /// Its turn completed as its mirror image, S R F, and its tensor
    /// F I F: its products with the flipped axis negated, so that
    /// (S R F)(F I F)(S R F)ᵀ = S R I Rᵀ S.
    fn mirror(&mut self) {
        let k = mirror_axis::<Self>();
        flip(k, &mut self.orientation);
        for j in 0..3 {
            if j != k {
                self.inertia[k][j] = -self.inertia[k][j];
                self.inertia[j][k] = -self.inertia[j][k];
            }
        }
    }

    fn real_size_direction(&self) -> Option<[DD; 3]> {
        None
    }

    fn turn(&self) -> Option<M3<f64>> {
        Some(self.orientation.matrix())
    }

    fn outline(&self) -> Outline {
        Outline::Marker(Marker::Inertia, self.center)
    }

    // Placed by its centre, its centroid; its measure's rounding (none:
    // its mass is given) is `MEASURE_ROUNDINGS`'.
    centre_placed!();

    centred_centroid!();
}
