//! A sub-assembly's or a copy's frame: where an included file's origin
//! and axes go in the including file, in its units, and how a part is
//! placed through it (`Frame::place`), with the rounding that adds
//! (`Spec::placed`).

use super::rotation::Orientation;
use crate::numeric::M3;
use crate::part::{MassSpec, Spec};

/// Where an included file's frame goes in this file's.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// This file's units.
    pub(super) origin: [f64; 3],
    pub(super) r: M3<f64>,
    pub(super) orientation: Orientation,
    /// The included file's length and mass units in this file's.
    pub(super) length: f64,
    pub(super) mass: f64,
    /// A copy's frame (`model::copies`): the point it turns about, taken
    /// from each point before the turn (`origin + R (p − pivot)`); none
    /// for an include's.
    pub(super) pivot: Option<[f64; 3]>,
    /// A mirror's frame: R is a reflection, and a part placed by its
    /// centre and a turn is completed as its image by `Place::mirror`.
    pub(super) mirror: bool,
}

/// How an array places its copies.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Pattern {
    /// No array: the part alone (and its image, with a mirror).
    One,
    /// Copy i moved by i·`step` (file units).
    Linear { count: usize, step: [f64; 3] },
    /// Copy i turned by i·`degrees` about `axis` through `origin`.
    Polar {
        count: usize,
        axis: [f64; 3],
        degrees: f64,
        origin: [f64; 3],
    },
}

/// The linear part of placing a part through frames: its mass scales by
/// `mass`, a displacement d goes to `length` R d, and a second moment C
/// to `mass` `length`² R C Rᵀ (R a turn or a reflection). How a change
/// of a part's figures in its own file moves them in this one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Linear {
    pub mass: f64,
    pub length: f64,
    pub r: M3<f64>,
}

impl Linear {
    pub const IDENTITY: Linear = Linear {
        mass: 1.0,
        length: 1.0,
        r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    };

    /// This map after `inner`.
    pub fn after(&self, inner: &Linear) -> Linear {
        Linear {
            mass: self.mass * inner.mass,
            length: self.length * inner.length,
            r: std::array::from_fn(|i| {
                std::array::from_fn(|j| (0..3).map(|k| self.r[i][k] * inner.r[k][j]).sum())
            }),
        }
    }

    /// A displacement moved: `length` R d.
    pub fn dir(&self, d: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| self.length * (0..3).map(|k| self.r[i][k] * d[k]).sum::<f64>())
    }

    /// A second moment moved: `mass` `length`² R C Rᵀ.
    pub fn second(&self, c: &M3<f64>) -> M3<f64> {
        let k = self.mass * self.length * self.length;
        std::array::from_fn(|a| {
            std::array::from_fn(|b| {
                k * (0..3)
                    .map(|p| {
                        (0..3)
                            .map(|q| self.r[a][p] * c[p][q] * self.r[b][q])
                            .sum::<f64>()
                    })
                    .sum::<f64>()
            })
        })
    }
}

impl Frame {
    /// The linear part of placing through this frame.
    pub fn linear(&self) -> Linear {
        Linear {
            mass: self.mass,
            length: self.length,
            r: self.r,
        }
    }

    fn dir(&self, v: [f64; 3]) -> [f64; 3] {
        let w = v.map(|x| x * self.length);
        std::array::from_fn(|i| self.r[i][0] * w[0] + self.r[i][1] * w[1] + self.r[i][2] * w[2])
    }

    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        let d = match self.pivot {
            None => self.dir(p),
            Some(o) => self.dir(std::array::from_fn(|i| p[i] - o[i])),
        };
        std::array::from_fn(|i| self.origin[i] + d[i])
    }

    /// A copy's frame (`model::copies`), in this file's units: a point p
    /// goes to `origin + R (p − pivot)`, R the matrix of `orientation`
    /// (a reflection when `mirror`).
    pub(super) fn copy(
        origin: [f64; 3],
        pivot: [f64; 3],
        orientation: Orientation,
        mirror: bool,
    ) -> Frame {
        Frame {
            origin,
            r: orientation.matrix(),
            orientation,
            length: 1.0,
            mass: 1.0,
            pivot: Some(pivot),
            mirror,
        }
    }

    /// The frame that places copy `k` (from 1) of an array: moved by
    /// k·step, or turned by k·θ about the axis through its origin.
    pub(super) fn of_copy(pattern: &Pattern, k: usize) -> Frame {
        match pattern {
            // Never asked: the part alone is copy 0 of its array.
            Pattern::One => Frame::copy([0.0; 3], [0.0; 3], Orientation::Identity, false),
            Pattern::Linear { step, .. } => {
                let k = k as f64;
                Frame::copy(step.map(|s| k * s), [0.0; 3], Orientation::Identity, false)
            }
            Pattern::Polar {
                axis,
                degrees,
                origin,
                ..
            } => Frame::copy(
                *origin,
                *origin,
                Orientation::AxisAngle(*axis, k as f64 * degrees),
                false,
            ),
        }
    }

    /// This frame, another copy's of the array `pattern` (`of_copy`),
    /// moved in place to copy `k`'s: only what differs from one copy to
    /// the next is made again (the step's multiple, or the turn and its
    /// matrix), to the same bits as `of_copy(pattern, k)`. Whether any
    /// bit of it changed (none, from one copy to the next, when the step
    /// or the turn is zero: the copies coincide).
    pub(super) fn move_to_copy(&mut self, pattern: &Pattern, k: usize) -> bool {
        let differ = |a: f64, b: f64| a.to_bits() != b.to_bits();
        match pattern {
            Pattern::One => false,
            Pattern::Linear { step, .. } => {
                let k = k as f64;
                let origin = step.map(|s| k * s);
                let moved = (0..3).any(|j| differ(origin[j], self.origin[j]));
                self.origin = origin;
                moved
            }
            Pattern::Polar { axis, degrees, .. } => {
                let turn = k as f64 * degrees;
                if matches!(self.orientation, Orientation::AxisAngle(_, t) if !differ(t, turn)) {
                    return false;
                }
                self.orientation = Orientation::AxisAngle(*axis, turn);
                self.r = self.orientation.matrix();
                true
            }
        }
    }

    /// `o` turned with this frame, in place.
    fn turn(&self, o: &mut Orientation) {
        match (&self.orientation, &*o) {
            (Orientation::Identity, _) => {}
            (f, Orientation::Identity) => *o = f.clone(),
            (f, _) => {
                let inner = std::mem::replace(o, Orientation::Identity);
                *o = Orientation::Then(Box::new(f.clone()), Box::new(inner));
            }
        }
    }

    /// A part of the included file (`s`), moved into this file's
    /// frame and units, in place (a walk places each part through every
    /// frame above it: a copy of the part per frame was a quarter of the
    /// time of a report of 2²⁰ instances).
    pub(super) fn place(&self, s: &mut Spec) {
        let reach = s.place.reach() * self.length;
        match &mut s.mass {
            MassSpec::Given(m) => *m *= self.mass,
            MassSpec::Density(d) => {
                // A density per volume, area or length scales with that power.
                let k = s.place.density_power();
                *d = *d * self.mass / self.length.powi(k);
            }
        }
        s.place.moved(self);
        if self.mirror {
            s.place.mirror();
        }
        s.placed = self.rounding(s.placed, reach);
        // A prism's vertices, scaled in its own frame, round each by a unit
        // of their distance from its origin (`Place::scaled_rounding`).
        if self.length != 1.0
            && let Some(units) = s.place.scaled_rounding()
        {
            s.placed =
                crate::part::Placed::new(f64::from(s.placed.units) + units, f64::from(s.placed.at))
                    .with_mass(f64::from(s.placed.mass));
        }
    }

    /// What placing a part through this frame adds to its rounding
    /// (`part::Placed`): none to its sizes when the frame neither turns
    /// (but by quarter turns, which are exact) nor scales; else a product
    /// per size and per mass, density (with its power of the length) or
    /// tensor entry, and an edge's turn (R w, three products summed, and
    /// the turn's own error ρ): 12 + 2ρ units. A position error already
    /// there is turned (×3 in the worst direction unless the turn is
    /// exact) and scaled; the new one is R (p·L) + origin's rounding,
    /// (4 + ρ) units of |origin| + |p·L|₁ (`reach`), or one of that when
    /// the frame is exact. A copy's frame adds the difference p − pivot
    /// (a unit of |p|₁ + |pivot|₁, turned) and its origin's own rounding
    /// (i·step, or the pivot itself: a unit of it).
    fn rounding(&self, old: crate::part::Placed, reach: f64) -> crate::part::Placed {
        // NOTE: no turn is exact, without its matrix asked (a copy along a
        // step, a sub-assembly not turned: most frames).
        let rho = if matches!(self.orientation, Orientation::Identity) {
            0.0
        } else {
            crate::part::error::turn_error(&self.orientation, &self.r)
        };
        let exact = rho == 0.0 && self.length == 1.0 && self.mass == 1.0;
        let grow = if rho == 0.0 { 1.0 } else { 3.0 };
        let size = if exact { 0.0 } else { 12.0 + 2.0 * rho };
        let ops = if exact { 1.0 } else { 4.0 + rho };
        let origin = self.origin.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let (ops, reach) = match self.pivot {
            None => (ops, reach),
            Some(o) => (
                ops + 2.0 + grow,
                reach + o.iter().map(|x| x.abs()).sum::<f64>(),
            ),
        };
        crate::part::Placed::new(
            f64::from(old.units) + size,
            f64::from(old.at) * self.length * grow
                + ops * crate::part::error::U64 * (origin + reach),
        )
        .with_mass(f64::from(old.mass))
    }

    /// A robot link's frame in its parent link's (`model::robot_body`):
    /// turned by `orientation` and moved to `origin`, SI on both sides.
    pub(super) fn of_link(origin: [f64; 3], orientation: Orientation) -> Frame {
        Frame {
            origin,
            r: orientation.matrix(),
            orientation,
            length: 1.0,
            mass: 1.0,
            pivot: None,
            mirror: false,
        }
    }
}

/// A frame moves a placement's numbers (`Place::moved`).
impl crate::shapes::Mover for Frame {
    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        Frame::point(self, p)
    }

    fn dir(&self, e: [f64; 3]) -> [f64; 3] {
        Frame::dir(self, e)
    }

    fn turn(&self, o: &mut Orientation) {
        Frame::turn(self, o)
    }

    fn length(&self) -> f64 {
        self.length
    }

    fn mass(&self) -> f64 {
        self.mass
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn linear(step: [f64; 3]) -> Pattern {
        Pattern::Linear { count: 7, step }
    }

    fn polar(degrees: f64) -> Pattern {
        Pattern::Polar {
            count: 7,
            axis: [1.0, 2.0, 3.0],
            degrees,
            origin: [0.5, -1.0, 2.0],
        }
    }

    /// To the bit: Debug writes each float's shortest exact form.
    fn bits(f: &Frame) -> String {
        format!("{f:?}")
    }

    #[test]
    fn a_frame_moved_to_a_copy_is_the_frame_made_for_it() {
        for p in [linear([1.0, -0.25, 3.0e-3]), polar(51.3)] {
            let mut f = Frame::of_copy(&p, 1);
            for k in [2, 6, 3] {
                assert!(f.move_to_copy(&p, k), "copy {k} of {p:?}");
                assert_eq!(bits(&f), bits(&Frame::of_copy(&p, k)));
            }
        }
    }

    #[test]
    fn a_frame_moved_by_a_zero_step_or_turn_is_unchanged() {
        for p in [linear([0.0, -0.0, 0.0]), polar(0.0), polar(-0.0)] {
            let mut f = Frame::of_copy(&p, 1);
            for k in 2..7 {
                assert!(!f.move_to_copy(&p, k), "copy {k} of {p:?}");
                assert_eq!(bits(&f), bits(&Frame::of_copy(&p, k)));
            }
        }
    }
}
