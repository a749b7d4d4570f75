//! A rod: a slender segment of length `L` along local z, zero radius;
//! dimensions `[L]`. Its real `diameter` never enters its moments
//! (`analysis::ideal` compares it with the cylinder it describes).

use super::common::{add, at, axes, density_power, diagonal, exact_centroid_error, flip, local_z, mirror_axis, norm1, points, reset_turn, scaled, spanned, var};
use super::read::Reader;
use crate::diag::Diagnostic;
use super::lift::{Lift, lift3, xyz};
use super::outline::{Outline, Piece};
use super::{
    MaterialRule, Mover, Own, PER_LENGTH, Shape, ShapeInfo, ShapeKind, Slot, Solid, Spanned,
    Units, product, segment,
};
use crate::numeric::{DD, M3, Real, norm_of};
use crate::rotation::Orientation;

/// A rod, in its file's units: by its `center`, `length` and turn, or by
/// its ends, `from` and `to`.
#[derive(Debug, Clone, PartialEq)]
pub enum Rod {
    Centred {
        center: [f64; 3],
        length: f64,
        orientation: Orientation,
    },
    Ends {
        from: [f64; 3],
        to: [f64; 3],
    },
}

/// `to − from`, read through `l`.
fn span_in<T: Real, L: Lift>(from: &[f64; 3], to: &[f64; 3], l: L) -> [T; 3] {
    let a: [T; 3] = lift3(l, from, xyz(Slot::At));
    let b: [T; 3] = lift3(l, to, xyz(Slot::To));
    std::array::from_fn(|i| b[i] - a[i])
}

/// |b − a|.
fn distance(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3)
        .map(|i| (a[i] - b[i]) * (a[i] - b[i]))
        .sum::<f64>()
        .sqrt()
}

impl ShapeKind for Rod {
    const INFO: ShapeInfo = ShapeInfo {
        shape: Shape::Rod,
        name: "rod",
        keys: &[
            "linear_density",
            "length",
            "center",
            "rotation",
            "from",
            "to",
            "mass",
            "remove",
            "diameter",
            "material",
            "area",
        ],
        density: Some(PER_LENGTH),
        sizes: &["length"],
        size_items: 0,
        centred: &["length", "center", "rotation"],
        spanned: Some(Spanned::FromTo),
        material: MaterialRule::Section,
        real_size: Some(("diameter", Solid::Cylinder)),
        nonzero_moments: 1,
        degenerate: "`to` equal to `from`",
        help: "a rod takes `mass` or `linear_density`, and `length` with `center` (and optional `rotation`), or `from` and `to`; optionally its real `diameter`",
    };

    const EXPLAIN: super::Explain = super::Explain {
        form: "slender rod of length L along local z",
        dims: &[
            super::symbol("L", "L", super::Slot::Length),
        ],
        measure: "L",
        moments: [
            "m*L^2/12",
            "m*L^2/12",
            "0",
        ],
    };

    /// One product.
    const MEASURE_ROUNDINGS: f64 = 1.0;

    /// m L²/12: L², m·, /12, and one of slack.
    const MOMENT_ROUNDINGS: f64 = 4.0;

    const MIRROR_AXIS: Option<usize> = Some(0);

    fn measure_of<T: Real>(d: &[T]) -> T {
        product(d)
    }

    fn moments_of<T: Real>(m: T, d: &[T]) -> [T; 3] {
        let [l] = d else {
            unreachable!("the model passes a rod one dimension")
        };
        let zero = T::of(0.0);
        [zero, zero, segment(m, *l)]
    }

    fn offset_of<T: Real>(_: &[T]) -> T {
        T::of(0.0)
    }

    fn read(r: &mut impl Reader) -> Result<Self, Diagnostic> {
        if r.by_edges() {
            let from = r.point("from")?;
            return Ok(Rod::Ends {
                from,
                to: r.point("to")?,
            });
        }
        let length = r.length("length")?;
        Ok(Rod::Centred {
            center: r.point("center")?,
            length,
            orientation: r.orientation(),
        })
    }

    fn measure<T: Real, L: Lift>(&self, l: L) -> T {
        match self {
            Rod::Centred { length, .. } => Self::measure_of(&[var(*length, Slot::Length, l)]),
            Rod::Ends { from, to } => norm_of(&span_in::<T, L>(from, to, l)),
        }
    }

    /// Centred, its own count; by its ends, a norm (3 for the squares'
    /// sum, 2 for the root, 1 for the differences) and a product.
    fn measure_error(&self) -> f64 {
        match self {
            Rod::Centred { .. } => Self::MEASURE_ROUNDINGS,
            Rod::Ends { .. } => 7.0,
        }
    }

    fn centroid<T: Real, L: Lift>(&self, l: L) -> [T; 3] {
        match self {
            Rod::Centred { center, .. } => at(center, l),
            Rod::Ends { from, to } => {
                let half = T::of(0.5);
                let a: [T; 3] = lift3(l, from, xyz(Slot::At));
                let b: [T; 3] = lift3(l, to, xyz(Slot::To));
                std::array::from_fn(|i| (a[i] + b[i]) * half)
            }
        }
    }

    /// A centre is a number of the file, and a sum of two halves exact.
    fn centroid_error(&self, at: f64, _: &[f64; 3]) -> [f64; 3] {
        exact_centroid_error(at)
    }

    fn own_second_moment<T: Real, L: Lift>(
        &self,
        m: T,
        units: Option<Units>,
        l: L,
    ) -> (M3<T>, Option<Own>) {
        match self {
            Rod::Centred {
                length,
                orientation,
                ..
            } => {
                let d = Self::moments_of(m, &[var(*length, Slot::Length, l)]);
                diagonal(d, orientation, units, Self::MOMENT_ROUNDINGS)
            }
            Rod::Ends { from, to } => spanned(m, &[span_in(from, to, l)], units),
        }
    }

    /// By its ends, its length: the frames' rounding of its ends over it.
    fn shortest_span(&self) -> f64 {
        match self {
            Rod::Centred { .. } => f64::INFINITY,
            Rod::Ends { from, to } => distance(from, to),
        }
    }

    fn independent_moments(&self, m: f64, j: &M3<f64>) -> ([f64; 3], usize, usize) {
        match self {
            Rod::Centred { length, .. } => (
                Self::moments_of(m, &[*length]),
                3,
                Self::INFO.nonzero_moments,
            ),
            Rod::Ends { .. } => (
                [j[0][0] + j[1][1] + j[2][2], 0.0, 0.0],
                1,
                Self::INFO.nonzero_moments,
            ),
        }
    }

    fn moved(&mut self, m: &impl Mover) {
        match self {
            Rod::Centred {
                center,
                length,
                orientation,
            } => {
                *center = m.point(*center);
                *length *= m.length();
                m.turn(orientation);
            }
            Rod::Ends { from, to } => {
                *from = m.point(*from);
                *to = m.point(*to);
            }
        }
    }

    fn density_power(&self) -> i32 {
        density_power::<Self>()
    }

    fn scaled_rounding(&self) -> Option<f64> {
        None
    }

    fn reach(&self) -> f64 {
        match self {
            Rod::Centred { center, .. } => norm1(center),
            Rod::Ends { from, to } => norm1(from).max(norm1(to)),
        }
    }

    fn positions(&self) -> ([[f64; 3]; 4], usize) {
        match self {
            Rod::Centred { center, .. } => points(&[*center]),
            Rod::Ends { from, to } => points(&[*from, *to]),
        }
    }

    fn numbers<'a>(&'a mut self, f: &mut dyn FnMut(Slot, &'a mut f64)) {
        match self {
            Rod::Centred { center, length, .. } => {
                for (i, x) in center.iter_mut().enumerate() {
                    f(Slot::At(i as u8), x);
                }
                f(Slot::Length, length);
            }
            Rod::Ends { from, to } => {
                for (i, x) in from.iter_mut().enumerate() {
                    f(Slot::At(i as u8), x);
                }
                for (i, x) in to.iter_mut().enumerate() {
                    f(Slot::To(i as u8), x);
                }
            }
        }
    }

    fn reset_from(&mut self, src: &Self) {
        match (self, src) {
            (
                Rod::Centred {
                    center,
                    length,
                    orientation,
                },
                Rod::Centred {
                    center: c,
                    length: l,
                    orientation: o,
                },
            ) => {
                *center = *c;
                *length = *l;
                reset_turn(orientation, o);
            }
            (Rod::Ends { from, to }, Rod::Ends { from: a, to: b }) => {
                *from = *a;
                *to = *b;
            }
            (d, s) => *d = s.clone(),
        }
    }

    /// Centred, its turn completed as its mirror image; by its ends, its
    /// points alone place it, already reflected.
    fn mirror(&mut self) {
        match self {
            Rod::Centred { orientation, .. } => flip(mirror_axis::<Self>(), orientation),
            Rod::Ends { .. } => {}
        }
    }

    /// Its axis: local z, or `to − from` (exact in double-double).
    fn real_size_direction(&self) -> Option<[DD; 3]> {
        Some(match self {
            Rod::Centred { orientation, .. } => local_z(orientation),
            Rod::Ends { from, to } => std::array::from_fn(|i| DD::of(to[i]) - DD::of(from[i])),
        })
    }

    fn turn(&self) -> Option<M3<f64>> {
        match self {
            Rod::Centred { orientation, .. } => Some(orientation.matrix()),
            Rod::Ends { .. } => None,
        }
    }

    fn outline(&self) -> Outline {
        let points = match self {
            Rod::Centred {
                center,
                length,
                orientation,
            } => {
                let [_, _, z] = axes(&orientation.matrix());
                vec![
                    add(*center, scaled(-length / 2.0, z)),
                    add(*center, scaled(length / 2.0, z)),
                ]
            }
            Rod::Ends { from, to } => vec![*from, *to],
        };
        Outline::Pieces(vec![Piece::Line {
            points,
            closed: false,
        }])
    }
}
