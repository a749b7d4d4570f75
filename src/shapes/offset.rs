//! The parts whose centroid lies off the point that places them: a cone or
//! hemisphere (`Place::Axial`: off its `center` along local z) and a prism
//! (`Place::Prism`: at its polygon's centroid, off its `origin`), and the
//! prism's own second moment, which has a product in its local axes.

use super::Shape;
use super::error::{self, Own};
use super::lift::{Lift, Slot, lift3, xyz};
use super::place::Place;
use super::prism::{Polygon, polygon};
use crate::numeric::{M3, Real};
use crate::rotation::Orientation;

/// The centroid's offset from the placing point in local axes (double-
/// double), and that point.
fn local_offset<T: Real, L: Lift>(
    shape: Shape,
    place: &Place,
    l: L,
) -> ([T; 3], [f64; 3], &Orientation) {
    match place {
        Place::Axial {
            center,
            dims,
            orientation,
        } => {
            let d: [T; 5] = super::lift::dims_in(dims, l);
            let z = shape.axial_offset(&d[..shape.dim_count()]);
            ([T::of(0.0), T::of(0.0), z], *center, orientation)
        }
        Place::Prism {
            origin,
            polygon: p,
            orientation,
            ..
        } => {
            let g = polygon(p).centroid;
            (
                [T::of_dd(g[0]), T::of_dd(g[1]), T::of(0.0)],
                *origin,
                orientation,
            )
        }
        _ => unreachable!("only an axial part or a prism has an offset centroid"),
    }
}

/// The centroid (file units) in double-double: the placing point plus R
/// times the local offset, so that far from the origin it keeps the digits
/// of the offset, as a triangle's centroid does.
pub(super) fn centroid<T: Real, L: Lift>(shape: Shape, place: &Place, lift: L) -> [T; 3] {
    let (l, at, orientation) = local_offset::<T, L>(shape, place, lift);
    let at: [T; 3] = lift3(lift, &at, xyz(Slot::At));
    if let Orientation::Identity = orientation {
        return std::array::from_fn(|i| at[i] + l[i]);
    }
    let r: M3<T> = orientation.matrix();
    std::array::from_fn(|i| at[i] + (r[i][0] * l[0] + r[i][1] * l[1] + r[i][2] * l[2]))
}

/// The units of the arithmetic `T` by which a prism's local figures
/// (`Polygon`, double-double) may be off, relative to the magnitudes `ell`
/// of the diagonal: 32 double-double units of the magnitudes each entry is
/// formed from.
fn polygon_units<T: Real>(poly: &Polygon, ell: &[f64; 3]) -> f64 {
    let s = poly.spread.second;
    let ratio = |x: f64, y: f64| if y > 0.0 { x / y } else { 0.0 };
    let worst = ratio(s[0], ell[0])
        .max(ratio(s[1], ell[1]))
        .max(ratio(s[2], (ell[0] * ell[1]).sqrt()));
    32.0 * error::U_DD / error::unit_of::<T>() * worst
}

/// A prism's ∫ρρᵀ dm about its centroid in the file's axes, for the mass
/// `m` (negative for a cut-out): in local axes the polygon's per-area
/// second moments times m in x–y (with the product), m L²/12 along z;
/// then R C Rᵀ. With its error model when `bound` asks (`errors` gives the
/// frames' units and the mass's).
pub(super) fn prism_second_moment<T: Real, L: Lift>(
    place: &Place,
    m: T,
    bound: bool,
    errors: impl Fn() -> (f64, f64),
    lift: L,
) -> (M3<T>, Option<Own>) {
    let Place::Prism {
        polygon: p,
        length,
        orientation,
        ..
    } = place
    else {
        unreachable!("a prism is placed as one")
    };
    let poly = polygon(p);
    let zero = T::of(0.0);
    let [xx, yy, xy] = poly.second.map(|x| m * T::of_dd(x));
    let l = T::var(*length, lift.rate(Slot::Dim(0)));
    let local: M3<T> = [
        [xx, xy, zero],
        [xy, yy, zero],
        [zero, zero, m * l * l / T::of(12.0)],
    ];
    let r: M3<T> = orientation.matrix();
    let j = super::turned(&r, &local);
    let own = bound.then(|| {
        let mu = errors().1;
        let r = r.map(|row| row.map(T::f64));
        let rho = error::turn_error(orientation, &r);
        let ell: [f64; 3] = std::array::from_fn(|k| local[k][k].f64().abs());
        let per_area = [
            poly.second[0].f64().abs(),
            poly.second[1].f64().abs(),
            (*length * *length / 12.0).abs(),
        ];
        // The polygon's units relative to its per-area moments (m scales
        // both alike); each local entry then rounds once to T and takes a
        // product with m (3), the axial one m L²/12 (4).
        let kappa = mu + error::GIVEN + 4.0 + polygon_units::<T>(&poly, &per_area);
        let v: [f64; 3] =
            std::array::from_fn(|a| (0..3).map(|k| r[a][k].abs() * ell[k].sqrt()).sum());
        let total = ell.iter().sum::<f64>() + 2.0 * local[0][1].f64().abs();
        Own::turned(mu, kappa, v.map(|x| x * x), rho, total)
    });
    (j, own)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::part::{MassSpec, Spec};

    /// A prism's mirror image in its own local x–z plane (local y → −y):
    /// the same origin, length and turn, its polygon with y negated and
    /// its vertices reversed (`shapes::prism::mirrored`). A mirror in any
    /// plane of the file is this image turned by the proper rotation
    /// S R F (S the file's reflection, R the prism's turn, F = diag(1, −1,
    /// 1)) about the reflected origin.
    fn mirrored_in_local_xz(place: &Place) -> Place {
        let Place::Prism {
            origin,
            polygon: p,
            length,
            orientation,
        } = place
        else {
            panic!("a prism")
        };
        Place::Prism {
            origin: *origin,
            polygon: crate::shapes::prism::mirrored(p).into(),
            length: *length,
            orientation: orientation.clone(),
        }
    }

    /// The mirror image of an unturned prism: the same mass, its centroid
    /// and its x–y product with y negated, the rest unchanged.
    #[test]
    fn a_mirrored_prism_negates_its_y_figures() {
        let place = Place::Prism {
            origin: [1.0, 2.0, 3.0],
            polygon: vec![
                [0.0, 0.0],
                [2.0, 0.0],
                [2.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ]
            .into(),
            length: 0.5,
            orientation: Orientation::Identity,
        };
        let mirror = mirrored_in_local_xz(&place);
        let spec = |place: Place| Spec {
            mass: MassSpec::Density(7.0),
            place,
            removed: false,
            placed: Default::default(),
        };
        let (a, b) = (spec(place), spec(mirror));
        let (ma, mb): (f64, f64) = (
            crate::part::mass_of(Shape::Prism, &a),
            crate::part::mass_of(Shape::Prism, &b),
        );
        assert_eq!(ma, mb);
        let (ca, cb) = (
            crate::part::centroid(Shape::Prism, &a.place),
            crate::part::centroid(Shape::Prism, &b.place),
        );
        assert_eq!(ca[0].f64(), cb[0].f64());
        assert_eq!(ca[1].f64() - 2.0, -(cb[1].f64() - 2.0));
        let (ja, jb): (M3<f64>, M3<f64>) = (
            crate::part::own_second_moment(Shape::Prism, &a, ma),
            crate::part::own_second_moment(Shape::Prism, &b, mb),
        );
        for (k, l) in [(0, 0), (1, 1), (2, 2)] {
            assert!((ja[k][l] - jb[k][l]).abs() <= 1e-15 * ja[k][l]);
        }
        assert!(ja[0][1] != 0.0 && (ja[0][1] + jb[0][1]).abs() <= 1e-15 * ja[0][0]);
    }
}
