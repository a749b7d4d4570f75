//! A part: one primitive as the file gave it (`Spec`, file units), and its
//! physics — mass, centroid and own second moment — in the precision asked
//! for. The composer, the per-part figures of every report and the checks
//! on the input all use these functions: one path per quantity.

use crate::la::{Matrix3, Vector3};
use crate::numeric::{DD, M3, Real};
use crate::shapes::Shape;
use crate::units::{Dim, FileUnits};
use std::ops::Range;
use std::sync::Arc;

pub mod error;
mod lift;

pub use crate::shapes::{Dep, Fixed, Lift, Own, Place, Placed, Seed, Slot, Units};

pub use crate::shapes::Solid;

/// A plate's `thickness` or a rod's `diameter`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealSize {
    /// Index of the part in `Model::parts`.
    pub part: usize,
    pub solid: Solid,
    /// Thickness (box) or diameter (cylinder), in the file's length unit.
    pub size: f64,
}

/// One primitive: its shape and its numbers as the file gave them, in the
/// file's units. This is the only representation of a part; the SI view
/// (`Part::si`) and everything the composer uses are derived from `spec` by
/// the functions below, so a part's own figures and the composite's come
/// from the same arithmetic.
#[derive(Debug, Clone)]
pub struct Part {
    /// The part's `name`, or `part N` (1-based position in the file); for
    /// a part of a sub-assembly, its path: `elbow / motor / stator`. Empty
    /// in a model's items for a part the file does not name (`named`
    /// false): a walk that names parts (`Model::each_part`) gives it
    /// `part N`.
    pub name: String,
    /// Whether the file gave `name` (which may be `""`).
    pub named: bool,
    /// The part as the file gave it, in the file's units.
    pub spec: Spec,
    /// The sub-assemblies the part is in, outermost first (empty for a
    /// part of the file itself).
    pub assembly: Vec<String>,
    /// Its `[[part]]` table in the file (for a part of a sub-assembly, the
    /// table that includes it), to point at it when a sum overflows.
    pub span: Range<usize>,
    /// How its numbers move with its file's tolerances (none for most
    /// parts), in its own file's units and frame.
    pub tol: Option<Arc<[Dep]>>,
    /// The `material` it is made of, by name (drawings colour by it).
    pub material: Option<Arc<str>>,
}

/// A body's parts, for the passes of the composer and of the per-part
/// figures: a list, or a model walked (`model::walk`).
pub trait EachPart {
    /// Each part, in order.
    fn each(&self, f: &mut dyn FnMut(&Part));
}

impl EachPart for [Part] {
    fn each(&self, f: &mut dyn FnMut(&Part)) {
        self.iter().for_each(f);
    }
}

impl EachPart for Vec<Part> {
    fn each(&self, f: &mut dyn FnMut(&Part)) {
        self.iter().for_each(f);
    }
}

/// A part's mass properties in SI, derived from its `Spec` by exact unit
/// factors in double-double, the product rounded to f64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartSi {
    /// kg; negative for a cut-out (`remove = true`).
    pub mass: f64,
    /// Centroid in the file's frame, m.
    pub center: Vector3<f64>,
    /// ∫ρρᵀ dm about the centroid in the file's axes, kg·m² (negative
    /// semi-definite for a cut-out).
    pub second_moment: Matrix3<f64>,
}

/// The exact factors from a file's units to SI, formed once (each is a
/// rational computed in i128) for all the parts of a body.
#[derive(Debug, Clone, Copy)]
pub struct SiFactors {
    pub mass: DD,
    pub length: DD,
    /// kg·m² per file unit of inertia, rounded once.
    pub inertia: f64,
}

impl SiFactors {
    pub fn of(units: FileUnits) -> SiFactors {
        SiFactors {
            mass: units.factor(Dim::MASS).dd(),
            length: units.factor(Dim::LENGTH).dd(),
            inertia: units.factor(Dim::INERTIA).value(),
        }
    }
}

impl Part {
    /// Its shape: its placed form's.
    pub fn shape(&self) -> Shape {
        self.spec.place.shape()
    }

    /// Mass in file units: given, or density times volume, area or length;
    /// negative for a cut-out.
    pub fn mass<T: Real>(&self) -> T {
        mass_of(&self.spec)
    }

    /// `own_second_moment` with its error model (`part::error`).
    pub fn own_second_moment_bounded<T: Real>(&self, m: T) -> (M3<T>, Own) {
        own_second_moment_bounded(&self.spec, m)
    }

    /// Centroid in file units, in double-double (see `centroid`).
    pub fn centroid(&self) -> [DD; 3] {
        centroid(&self.spec.place)
    }

    /// ∫ρρᵀ dm about the centroid, file axes and units, for the mass `m`
    /// (see `own_second_moment`).
    pub fn own_second_moment<T: Real>(&self, m: T) -> M3<T> {
        own_second_moment(&self.spec, m)
    }

    /// The part in SI: mass and centroid from the same arithmetic the
    /// composer uses, times the exact unit factors in double-double, the
    /// product rounded to f64; the second
    /// moment in f64 (it serves comparisons and blame, not sums).
    pub fn si(&self, units: FileUnits) -> PartSi {
        self.si_in(&SiFactors::of(units))
    }

    /// `si` with the unit factors formed once for many parts.
    pub fn si_in(&self, f: &SiFactors) -> PartSi {
        let m: f64 = self.mass();
        let own: M3<f64> = self.own_second_moment(m);
        PartSi {
            mass: (DD::of(m) * f.mass).f64(),
            center: self.center_si(f),
            second_moment: Matrix3::from_fn(|i, j| own[i][j] * f.inertia),
        }
    }

    /// The mass in SI (kg): the f64 mass in file units that the `standard`
    /// composer sums (a density already converted to file units, so with
    /// the rounding of that conversion), times the exact unit factor in
    /// double-double, rounded to f64.
    ///
    /// NOTE: f64, not double-double: in `standard` this is exactly the mass
    /// the composite is made of, so the parts' masses add up to the body's
    /// to the rounding of the sum; in `extended` the composite's parts
    /// carry ~16 more digits that a figure rounded to f64 would not show.
    /// Double-double square roots for parts placed by edges would cost
    /// ~5 % of a 100,000-part report for none of those digits.
    pub fn mass_si(&self, f: &SiFactors) -> f64 {
        (DD::of(self.mass::<f64>()) * f.mass).f64()
    }

    /// The centroid in SI (m), as in `si`.
    pub fn center_si(&self, f: &SiFactors) -> Vector3<f64> {
        Vector3::from(self.centroid().map(|x| (x * f.length).f64()))
    }
}

/// A part's numbers as the file gave them, in the file's units (a quantity
/// written with its own unit converted once, by an exact ratio).
///
/// NOTE: the composer works from these, not from the SI values above, and
/// converts only its results to SI. Converting every input first would
/// round each coordinate on its own: for parts 10⁹ sizes from the origin in
/// a millimetre file that alone moves them relative to each other by 1e-7
/// of their size.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    pub mass: MassSpec,
    pub place: Place,
    /// `remove = true`: a cut-out, composed with negative mass.
    pub removed: bool,
    /// How far the frames of the sub-assemblies the part is in moved its
    /// numbers by rounding (`model::frame::Frame::place`); none for a
    /// part of the file itself.
    pub placed: Placed,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassSpec {
    Given(f64),
    /// Density per volume, area or length, times the shape's measure.
    Density(f64),
}

/// Mass of a part (file units): given, or density times volume, area or
/// length; negative for a cut-out.
pub fn mass_of<T: Real>(spec: &Spec) -> T {
    mass_in(spec, Fixed)
}

/// `mass_of`, the spec's numbers read through `l`.
pub fn mass_in<T: Real, L: Lift>(spec: &Spec, l: L) -> T {
    let m: T = unsigned_mass_of(spec, l);
    if spec.removed { -m } else { m }
}

fn unsigned_mass_of<T: Real, L: Lift>(spec: &Spec, l: L) -> T {
    match spec.mass {
        MassSpec::Given(m) => T::var(m, l.rate(Slot::Mass)),
        MassSpec::Density(rho) => T::var(rho, l.rate(Slot::Mass)) * spec.place.measure(l),
    }
}

/// Centroid of a part (file units), in double-double: a corner plus half
/// its edges is not an f64 in general, and far from the origin its rounding
/// would move the part relative to its neighbours.
pub fn centroid(place: &Place) -> [DD; 3] {
    place.centroid(Fixed)
}

/// `centroid` in the arithmetic `T`, the numbers read through `l` (in
/// double-double with `Fixed`, the same operations as `centroid`).
pub fn centroid_in<T: Real, L: Lift>(place: &Place, l: L) -> [T; 3] {
    place.centroid(l)
}

/// ∫ρρᵀ dm of a part about its own centroid, in the file's axes and units.
///
/// A uniform segment of length a centred on 0 has ∫x² dm = m a²/12, and each
/// shape is a product of such segments: R diag(m aₖ²/12) Rᵀ for a turned
/// shape, and Σₖ (m/12) eₖ eₖᵀ for one spanned by edge vectors eₖ, which
/// needs neither their lengths nor a rotation.
pub fn own_second_moment<T: Real>(spec: &Spec, m: T) -> M3<T> {
    own_second_moment_in(spec, m, false, Fixed).0
}

/// A part's mass, centroid and own second moment (file units and axes)
/// in the arithmetic `T`, its numbers read through `l`: in `dual::Dual`
/// with a `Seed`, each with its derivative by the seeded number (the
/// same functions as the composer's, so the derivatives are those of
/// the figures it composes).
pub fn physics_in<T: Real, L: Lift>(spec: &Spec, l: L) -> (T, [T; 3], M3<T>) {
    let m: T = mass_in(spec, l);
    let c = centroid_in(&spec.place, l);
    let (j, _) = own_second_moment_in(spec, m, false, l);
    (m, c, j)
}

/// `own_second_moment`, with the error model of the arithmetic that formed
/// it (`part::error`): the error bounds' share of each part.
pub fn own_second_moment_bounded<T: Real>(spec: &Spec, m: T) -> (M3<T>, Own) {
    let (j, own) = own_second_moment_in(spec, m, true, Fixed);
    (j, own.expect("invariant: the error model was asked for"))
}

/// The one path of both: the error model formed only when `bound` asks
/// (the per-part figures and the checks on the input need none of it):
/// the frames' rounding of the part's numbers, on top of its own (its
/// sizes and mass relative; a shape spanned by vectors the frames turned
/// numerically, edges, ends, vertices, absolute in every entry, as a
/// turn's own error is), and its mass's.
fn own_second_moment_in<T: Real, L: Lift>(
    spec: &Spec,
    m: T,
    bound: bool,
    l: L,
) -> (M3<T>, Option<Own>) {
    let units = bound.then(|| Units {
        placed: error::placed_units::<T>(&spec.place, &spec.placed),
        mass: error::mass_error::<T>(spec),
        by_density: matches!(spec.mass, MassSpec::Density(_)),
    });
    spec.place.own_second_moment(m, units, l)
}

#[cfg(test)]
mod tests {
    use crate::numeric::DD;

    /// `mesh` counts roundings in the same unit as the error model (it
    /// comes before `part` and keeps its own copy of the rule).
    #[test]
    fn mesh_and_part_count_roundings_in_one_unit() {
        assert_eq!(
            crate::mesh::unit_of::<f64>(),
            super::error::unit_of::<f64>()
        );
        assert_eq!(crate::mesh::unit_of::<DD>(), super::error::unit_of::<DD>());
    }
}
