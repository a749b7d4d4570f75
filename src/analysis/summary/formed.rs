//! Each reported quantity's value and error bound, formed as its row of
//! `quantity::QUANTITIES` declares (`quantity::Formed`) from the composed
//! body (`Body`, which `summarize_in` makes and checks once). A quantity
//! of a kind already here (a radius about another point, a tensor about
//! it) needs no code: its row says how it is formed. A new kind of value
//! is a `Formed` variant and its arms in `Body::value` and `Body::bound`,
//! which the compiler asks for.

use super::{Blame, Contribution, Products, SummaryError, finite};
use crate::analysis::motion::{self, Motion};
use crate::bounds::{self, BodyError};
use crate::compose::{Precision, Principal};
use crate::la::Vector3;
use crate::model::Analysis;
use crate::numeric::{DD, M3, Real};
use crate::quantity::{About, Formed, Owned};
use std::cell::OnceCell;

/// The composed body in SI, rounded where reported, and what its bounds
/// are formed from. A pair is about the centre of mass and about the
/// reference point (`About`), in the report axes.
pub(super) struct Body<'a> {
    pub analysis: &'a Analysis,
    pub products: Products,
    pub precision: Precision,
    pub mass_dd: DD,
    pub f_inertia: DD,
    pub mass: f64,
    pub com: [f64; 3],
    pub reference: [f64; 3],
    pub com_ref: [f64; 3],
    /// The report axes' rows.
    pub frame: [[f64; 3]; 3],
    /// The inertia tensors, SI, tensor convention; and rounded.
    pub inertia: [M3<DD>; 2],
    pub inertia_f: [M3<f64>; 2],
    pub principal: [Principal; 2],
    pub moments: [[f64; 3]; 2],
    /// H, T and M, rounded (not yet checked).
    pub h: Option<[f64; 3]>,
    pub t: Option<f64>,
    pub m: Option<[f64; 3]>,
    /// The body moving, where `velocity` is given (`analysis::motion`).
    pub motion: Option<Motion>,
    pub bounds: Inputs,
    /// The eigen bounds per point, formed once (three rows read each).
    pub eigen: [OnceCell<([f64; 3], [f64; 3])>; 2],
}

/// What the bounds are formed from: the composer's bounds (file units),
/// the unit factors, and per point the bound of C in the report axes, that
/// of C as the eigen solver took it, and C itself (rounded).
pub(super) struct Inputs {
    pub error: BodyError,
    pub f_mass: f64,
    pub f_length: f64,
    pub f_inertia: f64,
    /// Of c − p, file units, report axes.
    pub offset: [f64; 3],
    pub tensor: [M3<f64>; 2],
    pub solved: [M3<f64>; 2],
    pub second_moment: [M3<f64>; 2],
}

fn at<T>(pair: &[T; 2], about: About) -> &T {
    &pair[about as usize]
}

/// The rows of an inertia tensor in the products convention.
pub(super) fn rows(m: &M3<f64>, products: Products) -> [[f64; 3]; 3] {
    let sign = match products {
        Products::Tensor => 1.0,
        Products::Positive => -1.0,
    };
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { m[i][j] } else { sign * m[i][j] }))
}

pub(super) fn arr(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// A value of the body moving, what it is called and what it is blamed
/// on when it overflows.
fn moving(m: &Motion, formed: Formed) -> (Owned, &'static str, Blame) {
    match formed {
        Formed::VelocityCom => (
            Owned::Triple(m.velocity_com),
            "mass centre's velocity",
            Blame::Velocity,
        ),
        Formed::LinearMomentum => (
            Owned::Triple(m.linear_momentum),
            "linear momentum",
            Blame::Velocity,
        ),
        Formed::MomentumCom => (
            Owned::Triple(m.momentum_com),
            "angular momentum about the centre of mass",
            Blame::Omega,
        ),
        Formed::EnergyTranslational => (
            Owned::Scalar(m.energy_translational),
            "translational kinetic energy",
            Blame::Velocity,
        ),
        Formed::EnergyRotational => (
            Owned::Scalar(m.energy_rotational),
            "rotational kinetic energy",
            Blame::Omega,
        ),
        Formed::Velocity
        | Formed::Mass
        | Formed::Centre
        | Formed::Point
        | Formed::Offset
        | Formed::Frame
        | Formed::Tensor(_)
        | Formed::Moments(_)
        | Formed::Axes(_)
        | Formed::Radii(_)
        | Formed::RadiiAxes(_)
        | Formed::Omega
        | Formed::Alpha
        | Formed::Momentum
        | Formed::Energy
        | Formed::EulerMoment
        | Formed::Predicted(_) => (Owned::Triple(m.velocity), "velocity", Blame::Velocity),
    }
}

/// What a value about `about` is blamed on when it overflows.
fn blame(about: About) -> Blame {
    match about {
        About::Centre => Blame::Parts(Contribution::SecondMoment),
        About::Point => Blame::About,
    }
}

impl Body<'_> {
    /// The value of a quantity so formed, checked finite; `None` where it
    /// is not computed (no ω, no α) or is the predicted body's.
    pub fn value(&self, formed: Formed) -> Result<Option<Owned>, SummaryError> {
        Ok(Some(match formed {
            Formed::Mass => Owned::Scalar(self.mass),
            Formed::Centre => Owned::Triple(self.com),
            Formed::Point => Owned::Triple(self.reference),
            Formed::Offset => Owned::Triple(self.com_ref),
            Formed::Frame => Owned::Rows(self.frame),
            Formed::Tensor(a) => Owned::Rows(rows(at(&self.inertia_f, a), self.products)),
            Formed::Moments(a) => Owned::Triple(*at(&self.moments, a)),
            Formed::Axes(a) => {
                let p = at(&self.principal, a);
                Owned::Axes(p.axes.map(|v| arr(&v)), p.equal.clone())
            }
            Formed::Radii(a) => {
                let radii = self.radii(a);
                let what = match a {
                    About::Centre => "radii of gyration",
                    About::Point => "radii of gyration about the reference point",
                };
                finite(&radii, what, blame(a))?;
                Owned::Triple(radii)
            }
            Formed::RadiiAxes(a) => {
                let radii = self.radii_axes(a);
                let what = match a {
                    About::Centre => "radii of gyration about the axes",
                    About::Point => "radii of gyration about the axes through the reference point",
                };
                finite(&radii, what, blame(a))?;
                Owned::Triple(radii)
            }
            Formed::Omega => {
                return Ok(self.analysis.omega.as_ref().map(|w| Owned::Triple(arr(w))));
            }
            Formed::Alpha => {
                return Ok(self.analysis.alpha.as_ref().map(|a| Owned::Triple(arr(a))));
            }
            Formed::Momentum => {
                let Some(h) = self.h else { return Ok(None) };
                finite(&h, "angular momentum", Blame::Omega)?;
                Owned::Triple(h)
            }
            Formed::Energy => {
                finite(&[self.t.unwrap_or(0.0)], "kinetic energy", Blame::Omega)?;
                return Ok(self.t.map(Owned::Scalar));
            }
            Formed::EulerMoment => {
                let Some(m) = self.m else { return Ok(None) };
                finite(&m, "Euler moment", Blame::Alpha)?;
                Owned::Triple(m)
            }
            Formed::Velocity
            | Formed::VelocityCom
            | Formed::LinearMomentum
            | Formed::MomentumCom
            | Formed::EnergyTranslational
            | Formed::EnergyRotational => {
                let Some(m) = &self.motion else {
                    return Ok(None);
                };
                let (v, what, blame) = moving(m, formed);
                match &v {
                    Owned::Scalar(x) => finite(&[*x], what, blame)?,
                    Owned::Triple(x) => finite(x, what, blame)?,
                    Owned::Rows(_) | Owned::Axes(..) => {}
                }
                v
            }
            Formed::Predicted(_) => return Ok(None),
        }))
    }

    /// The error bound of a quantity so formed (absolute, SI, component by
    /// component; a set of axes' an angle per axis); `None` for a value
    /// given, one not computed, or the predicted body's.
    pub fn bound(&self, formed: Formed) -> Option<Owned> {
        let b = &self.bounds;
        Some(match formed {
            Formed::Mass => Owned::Scalar(self.mass_bound()),
            Formed::Centre => Owned::Triple(self.centre_bound()),
            Formed::Point => Owned::Triple(match self.analysis.about {
                Some(_) => self.reference.map(|x| bounds::U64 * x.abs()),
                None => self.centre_bound(),
            }),
            Formed::Offset => Owned::Triple(std::array::from_fn(|j| {
                bounds::to_si(b.offset[j], b.f_length, self.com_ref[j])
            })),
            Formed::Tensor(a) => Owned::Rows(self.tensor_bound(a)),
            Formed::Moments(a) => Owned::Triple(self.eigen_bound(a).0),
            Formed::Axes(a) => Owned::Triple(self.eigen_bound(a).1),
            Formed::Radii(a) => {
                let (radii, moments) = (self.radii(a), at(&self.moments, a));
                let (bound, mass_b) = (self.eigen_bound(a).0, self.mass_bound());
                Owned::Triple(std::array::from_fn(|i| {
                    bounds::radius(radii[i], moments[i], bound[i], self.mass, mass_b)
                }))
            }
            Formed::RadiiAxes(a) => {
                let (radii, i) = (self.radii_axes(a), at(&self.inertia_f, a));
                let (e, mass_b) = (self.tensor_bound(a), self.mass_bound());
                Owned::Triple(std::array::from_fn(|j| {
                    bounds::radius(radii[j], i[j][j], e[j][j], self.mass, mass_b)
                }))
            }
            Formed::Frame | Formed::Omega | Formed::Alpha | Formed::Predicted(_) => return None,
            Formed::Momentum => Owned::Triple(self.dynamics()?.0),
            Formed::Energy => Owned::Scalar(self.dynamics()?.1),
            Formed::EulerMoment => Owned::Triple(self.dynamics()?.2?),
            Formed::Velocity => Owned::Triple(self.motion_bound()?.velocity),
            Formed::VelocityCom => Owned::Triple(self.motion_bound()?.velocity_com),
            Formed::LinearMomentum => Owned::Triple(self.motion_bound()?.linear_momentum),
            Formed::MomentumCom => Owned::Triple(self.motion_bound()?.momentum_com),
            Formed::EnergyTranslational => Owned::Scalar(self.motion_bound()?.energy_translational),
            Formed::EnergyRotational => Owned::Scalar(self.motion_bound()?.energy_rotational),
        })
    }

    /// The bounds of the body moving, where `velocity` is given.
    fn motion_bound(&self) -> Option<motion::Bounds> {
        let m = self.motion.as_ref()?;
        let b = &self.bounds;
        let w = self.analysis.omega.as_ref().map(arr)?;
        let v = self.analysis.velocity.as_ref().map(arr)?;
        // v as read may be a unit string rounded into the file's unit.
        let dv = std::array::from_fn(|j| {
            bounds::to_si(bounds::U64 * v[j].abs(), b.f_length, m.velocity[j])
        });
        let dr = std::array::from_fn(|j| bounds::to_si(b.offset[j], b.f_length, self.com_ref[j]));
        Some(motion::bound(
            m,
            &motion::InputBounds {
                mass: (self.mass, self.mass_bound()),
                r: (self.com_ref, dr),
                v: (m.velocity, dv),
                omega: w,
                e_com: &self.tensor_bound(About::Centre),
            },
        ))
    }

    fn mass_bound(&self) -> f64 {
        let b = &self.bounds;
        bounds::to_si(b.error.mass, b.f_mass, self.mass)
    }

    fn centre_bound(&self) -> [f64; 3] {
        let b = &self.bounds;
        std::array::from_fn(|j| bounds::to_si(b.error.center_of_mass[j], b.f_length, self.com[j]))
    }

    fn tensor_bound(&self, about: About) -> [[f64; 3]; 3] {
        let e = bounds::inertia_of(at(&self.bounds.tensor, about));
        let v = at(&self.inertia_f, about);
        std::array::from_fn(|j| {
            std::array::from_fn(|k| bounds::to_si(e[j][k], self.bounds.f_inertia, v[j][k]))
        })
    }

    /// The bounds of the principal moments and of the axes (angles).
    fn eigen_bound(&self, about: About) -> ([f64; 3], [f64; 3]) {
        *at(&self.eigen, about).get_or_init(|| self.eigen_of(about))
    }

    fn eigen_of(&self, about: About) -> ([f64; 3], [f64; 3]) {
        let b = &self.bounds;
        let p = at(&self.principal, about);
        let e = bounds::eigen(
            at(&b.second_moment, about),
            at(&b.solved, about),
            &p.solved(),
            self.precision,
        );
        let values = at(&self.moments, about);
        (
            std::array::from_fn(|i| bounds::to_si(e.moments[i], b.f_inertia, values[i])),
            e.axes,
        )
    }

    /// The bounds of H, T and M, where ω is given.
    fn dynamics(&self) -> Option<([f64; 3], f64, Option<[f64; 3]>)> {
        let (w, h) = self.analysis.omega.zip(self.h)?;
        let (dh, dt, dm) = bounds::dynamics(
            &self.tensor_bound(About::Point),
            arr(&w),
            self.analysis.alpha.as_ref().map(arr),
            h,
            self.t.unwrap_or(0.0),
            self.m,
        );
        // What v adds to H and T about the point (`motion`).
        Some(match self.motion_bound() {
            Some(e) => (
                // NOTE: no `safe` here: `dh` and `dt` are already safe's,
                // and a point at rest adds exactly 0 (today's bound).
                std::array::from_fn(|j| dh[j] + e.h_extra[j]),
                dt + e.t_extra,
                dm,
            ),
            None => (dh, dt, dm),
        })
    }

    /// √I / √m of the principal moments, not √(I/m): the ratio alone can
    /// overflow or underflow where the radius itself is an ordinary number.
    fn radii(&self, about: About) -> [f64; 3] {
        at(&self.principal, about)
            .moments
            .map(|i| ((i * self.f_inertia).sqrt() / self.mass_dd.sqrt()).f64())
    }

    /// About the axes: each diagonal entry (≥ 0, but for rounding) alike.
    fn radii_axes(&self, about: About) -> [f64; 3] {
        let i = at(&self.inertia, about);
        std::array::from_fn(|k| {
            let d = if i[k][k] < DD::of(0.0) {
                DD::of(0.0)
            } else {
                i[k][k]
            };
            (d.sqrt() / self.mass_dd.sqrt()).f64()
        })
    }
}
