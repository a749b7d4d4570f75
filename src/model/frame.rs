//! A sub-assembly's or a copy's frame: where an included file's origin
//! and axes go in the including file, in its units, and how a part is
//! placed through it (`Frame::place`), with the rounding that adds
//! (`Spec::placed`); a frame as the composer places a composed body
//! through it (`Placement`); and bounds on every instance's numbers,
//! placed through frames once per distinct file (`Reach`).

use super::rotation::Orientation;
use super::{Item, Model};
use crate::numeric::{DD, M3, Real, two_prod};
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
    /// For the composer, which places a composed body in the arithmetic
    /// asked for (`Frame::placement`): the unit ratios `length` and
    /// `mass` in double-double, each within `units_rel` of the exact
    /// ratio (relative); what a linear copy's origin k·step rounded away
    /// (`origin + origin_lo` is exact) and a polar copy's turn k·θ
    /// (degrees).
    pub(super) units_dd: [DD; 2],
    pub(super) units_rel: [f64; 2],
    pub(super) origin_lo: [f64; 3],
    pub(super) angle_lo: f64,
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

/// A frame as the composer places a composed body through it
/// (`compose::placed`), in the arithmetic `T`: p ↦ origin + L R (p − pivot),
/// masses times k; with how far each of its numbers may lie from the exact
/// frame the file gives.
#[derive(Debug, Clone, Copy)]
pub struct Placement<T> {
    /// R̂, formed in `T`, and the same as double-double (exactly).
    pub r: M3<T>,
    pub r_dd: M3<DD>,
    /// |R̂ − R| entrywise, absolute: its form's roundings (`turn_error`,
    /// units of `T`) and, for a polar copy in f64, the rounding of its
    /// turn k·θ (|δθ| in radians: a turn's entries move by at most the
    /// angle).
    pub rho: f64,
    /// Whether R̂ is a signed permutation: products with it are exact.
    pub exact_turn: bool,
    /// Exact, as double-doubles.
    pub origin: [DD; 3],
    pub pivot: Option<[DD; 3]>,
    /// L and k in `T`, and L in double-double for points; each within its
    /// relative bound of the exact ratio (0 when it is exactly 1).
    pub length: T,
    pub mass: T,
    pub length_dd: DD,
    pub rel_length: f64,
    pub rel_mass: f64,
    pub rel_length_dd: f64,
}

impl Frame {
    /// This frame for the composer, in the arithmetic `T`.
    ///
    /// NOTE: a polar copy's turn is k·θ rounded to f64; in double-double
    /// the rest of k·θ (exact, `angle_lo`) is turned too, as a second turn
    /// about the same axis (R(a + b) = R(a) R(b)), so that the copies of
    /// an array are placed to double-double's accuracy, not f64's.
    pub fn placement<T: Real + Into<DD>>(&self) -> Placement<T> {
        let dd_arith = T::EPS < 1e-20;
        let unit = crate::part::error::unit_of::<T>();
        let (orientation, angle) = match (&self.orientation, self.angle_lo) {
            (Orientation::AxisAngle(axis, deg), lo) if lo != 0.0 && dd_arith => (
                Orientation::Then(
                    Box::new(Orientation::AxisAngle(*axis, *deg)),
                    Box::new(Orientation::AxisAngle(*axis, lo)),
                ),
                0.0,
            ),
            (o, lo) => (o.clone(), lo.abs() * (std::f64::consts::PI / 180.0) * 1.01),
        };
        // NOTE: in f64 too the matrix is formed in double-double and
        // rounded once, so that it is within a unit of the exact turn
        // rather than the f64 form's 10–35 units (an Euler turn's 24): a
        // placed body's bound carries R's error times its whole second
        // moment, which dominated the bounds of turned sub-assemblies.
        // A frame is placed once per instance, not per part: the cost is
        // a double-double turn per frame.
        let formed: M3<DD> = orientation.matrix();
        let r: M3<T> = if dd_arith {
            formed.map(|row| row.map(|x| T::of(x.hi) + T::of(x.lo)))
        } else {
            formed.map(|row| row.map(|x| T::of(x.f64())))
        };
        let r_dd: M3<DD> = r.map(|row| row.map(Into::into));
        let r64 = r_dd.map(|row| row.map(DD::f64));
        let exact_turn = r64.iter().flatten().all(|x| *x == 0.0 || x.abs() == 1.0);
        let form = crate::part::error::turn_error(&orientation, &r64) * crate::part::error::U_DD;
        let rounding = if dd_arith || form == 0.0 { 0.0 } else { unit };
        let rho = form + rounding + angle;
        let exact_turn = exact_turn && rho == 0.0;
        // A ratio in `T`, and its relative error: the exact ratio's
        // double-double's (`units_rel`) and its rounding to `T`.
        let ratio = |k: usize| -> (T, f64) {
            let x = T::of_dd(self.units_dd[k]);
            if self.units_rel[k] == 0.0 {
                return (x, 0.0);
            }
            let back: DD = x.into();
            let off = ((back - self.units_dd[k]).f64() / self.units_dd[k].f64()).abs();
            (x, (off + self.units_rel[k]) * 1.01)
        };
        let (length, rel_length) = ratio(0);
        let (mass, rel_mass) = ratio(1);
        Placement {
            r,
            r_dd,
            rho,
            exact_turn,
            origin: std::array::from_fn(|i| DD::new(self.origin[i], self.origin_lo[i])),
            pivot: self.pivot.map(|q| q.map(DD::of)),
            length,
            mass,
            length_dd: self.units_dd[0],
            rel_length,
            rel_mass,
            rel_length_dd: self.units_rel[0],
        }
    }

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
            units_dd: [DD::of(1.0); 2],
            units_rel: [0.0; 2],
            origin_lo: [0.0; 3],
            angle_lo: 0.0,
        }
    }

    /// An include's frame: `origin`, turned by `orientation`, the
    /// included file's length and mass units `units` (exact ratios) in
    /// this file's.
    pub(super) fn include(
        origin: [f64; 3],
        orientation: Orientation,
        units: [Option<crate::units::Factor>; 2],
        fallback: [f64; 2],
    ) -> Frame {
        let value = |k: usize| units[k].map_or(fallback[k], |f| f.value());
        // NOTE: a ratio that outgrew i128 is the quotient of two f64
        // factors: three roundings of f64.
        let dd = |k: usize| units[k].map_or(DD::of(fallback[k]), |f| f.dd());
        let rel = |k: usize| match units[k] {
            Some(f) if f.parts().0 == f.parts().1 && f.parts().2 == 0 => 0.0,
            Some(_) => 16.0 * crate::part::error::U_DD,
            None => 3.0 * crate::part::error::U64,
        };
        Frame {
            origin,
            r: orientation.matrix(),
            orientation,
            length: value(0),
            mass: value(1),
            pivot: None,
            mirror: false,
            units_dd: [dd(0), dd(1)],
            units_rel: [rel(0), rel(1)],
            origin_lo: [0.0; 3],
            angle_lo: 0.0,
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
                let mut f =
                    Frame::copy(step.map(|s| k * s), [0.0; 3], Orientation::Identity, false);
                f.origin_lo = step.map(|s| two_prod(k, s).1);
                f
            }
            Pattern::Polar {
                axis,
                degrees,
                origin,
                ..
            } => {
                let mut f = Frame::copy(
                    *origin,
                    *origin,
                    Orientation::AxisAngle(*axis, k as f64 * degrees),
                    false,
                );
                f.angle_lo = two_prod(k as f64, *degrees).1;
                f
            }
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
                self.origin_lo = step.map(|s| two_prod(k, s).1);
                moved
            }
            Pattern::Polar { axis, degrees, .. } => {
                let turn = k as f64 * degrees;
                self.angle_lo = two_prod(k as f64, *degrees).1;
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
        self.place_numbers(s);
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

    /// `place`'s numbers alone (the same arithmetic), without the bound of
    /// their rounding (`Spec::placed`, left as it was): for the report's
    /// rows (`Model::each_row`), which show the numbers only. (perf, the
    /// JSON of 2¹⁷ instances: `place` 7 % of the time, `Place::moved`,
    /// the numbers, 3 %.)
    pub(super) fn place_numbers(&self, s: &mut Spec) {
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
            units_dd: [DD::of(1.0); 2],
            units_rel: [0.0; 2],
            origin_lo: [0.0; 3],
            angle_lo: 0.0,
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

/// Bounds on the numbers of every part of a body over all its instances,
/// in its own frame and units: the largest coordinate, the largest and
/// smallest |mass|, the largest entry of a part's own second moment, and
/// the smallest of the independent moments a part must have normal
/// (`ShapeKind::independent_moments`). Formed once per distinct file
/// (`Reach::of`), placed through a frame conservatively (`placed`): what
/// lets the range check of a sub-assembly placed in another file's units
/// (`include`, `copies`) see at once that no instance can leave f64's
/// range, instead of placing each (2²⁰ of them, each through 20 frames,
/// in a tree of includes).
#[derive(Debug, Clone, Copy)]
pub(super) struct Reach {
    pos: f64,
    mass_max: f64,
    mass_min: f64,
    moment_max: f64,
    need_min: f64,
}

impl Reach {
    const NONE: Reach = Reach {
        pos: 0.0,
        mass_max: 0.0,
        mass_min: f64::INFINITY,
        moment_max: 0.0,
        need_min: f64::INFINITY,
    };

    fn join(&mut self, o: Reach) {
        self.pos = self.pos.max(o.pos);
        self.mass_max = self.mass_max.max(o.mass_max);
        self.mass_min = self.mass_min.min(o.mass_min);
        self.moment_max = self.moment_max.max(o.moment_max);
        self.need_min = self.need_min.min(o.need_min);
    }

    fn part(p: &crate::part::Part) -> Reach {
        let spec = &p.spec;
        let m = crate::part::mass_of::<f64>(spec).abs();
        let j = crate::part::own_second_moment::<f64>(spec, m);
        let (moments, count, expected) = spec.place.independent_moments(m, &j);
        let mut moments = moments[..count].to_vec();
        moments.sort_by(|a, b| b.partial_cmp(a).unwrap_or(std::cmp::Ordering::Equal));
        let need_min = match expected {
            0 => f64::INFINITY,
            e => moments.get(e - 1).copied().unwrap_or(0.0),
        };
        let pos = spec.place.positions().fold(0.0f64, |a, x| a.max(x.abs())) + spec.place.reach();
        let top = j
            .iter()
            .flatten()
            .chain(&moments)
            .fold(0.0f64, |a, x| a.max(x.abs()));
        Reach {
            pos,
            mass_max: m,
            mass_min: m,
            moment_max: top,
            need_min,
        }
    }

    /// Every instance of `model`'s parts, its sub-assemblies' reaches
    /// (kept in `memo` by model) placed through their frames.
    pub(super) fn of(
        model: &Model,
        memo: &mut std::collections::HashMap<*const Model, Reach>,
    ) -> Reach {
        let mut r = Reach::NONE;
        for item in model.items.iter() {
            let (one, copies) = match item {
                Item::Part { part, copies, .. } => (Reach::part(part), copies.as_deref()),
                Item::Include(inc) => {
                    let key = std::sync::Arc::as_ptr(&inc.model);
                    let child = match memo.get(&key) {
                        Some(c) => *c,
                        None => {
                            let c = Reach::of(&inc.model, memo);
                            memo.insert(key, c);
                            c
                        }
                    };
                    (child.placed(&inc.frame), inc.copies.as_deref())
                }
            };
            r.join(match copies {
                None => one,
                Some(c) => one.copied(c),
            });
        }
        r
    }

    /// Placed through `f`: coordinates |o + L R (p − q)|∞ ≤ |o|∞ +
    /// 1.8 L (|p|∞ + |q|∞); masses times k; a second moment's entries
    /// times k L² (three times that turned), its independent moments no
    /// less than k L²/16 of themselves (a turn moves them by rounding
    /// alone).
    pub(super) fn placed(self, f: &Frame) -> Reach {
        let inf = |v: &[f64; 3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let q = f.pivot.as_ref().map_or(0.0, inf);
        let scale = f.mass * f.length * f.length;
        Reach {
            pos: inf(&f.origin) + 1.8 * f.length * (self.pos + q),
            mass_max: self.mass_max * f.mass,
            mass_min: self.mass_min * f.mass,
            moment_max: self.moment_max * scale * 3.0,
            need_min: self.need_min * scale / 16.0,
        }
    }

    /// Every copy of `c` of a body of this reach.
    fn copied(self, c: &super::Copies) -> Reach {
        Reach {
            pos: c.reach(self.pos),
            moment_max: self.moment_max * 3.0,
            need_min: self.need_min / 16.0,
            ..self
        }
    }

    /// Whether every number of every instance is far inside f64's range
    /// (so that no range check can fail: `parts::in_file_range`, and the
    /// coordinates in SI, times `si`, finite).
    pub(super) fn safe(&self, si: f64) -> bool {
        const BIG: f64 = 1e290;
        const SMALL: f64 = 1e-290;
        self.pos * si.max(1.0) < BIG
            && self.pos < BIG
            && self.mass_max < BIG
            && self.moment_max < BIG
            && self.mass_min >= SMALL
            && self.need_min >= SMALL
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
