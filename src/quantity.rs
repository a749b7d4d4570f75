//! The reported quantities, each declared once: its key (in `[expect]`,
//! in the JSON of `report` and `error_bounds`, in `check`'s and `diff`'s
//! names), its dimension and shape, how its value and its error bound are
//! formed (`Formed`), how `[expect]` compares it, what `--bless` writes
//! for it, whether the uncertainty carries its σ, and how `diff` shows it.
//! `analysis::summary` forms each value and bound as its row says and
//! holds them by row (`Table`); `model::expect` reads `[expect]` from this
//! table, `analysis::check` compares by it, `analysis::uncertainty` names
//! and places the σ outputs by it, `analysis::bless` and `analysis::diff`
//! follow it.
//!
//! The table also writes the JSON: `report`'s keys (`Summary`'s
//! serialization) and `error_bounds`' each in its place, and says how
//! `--precision auto` and `--rtol` judge each bound (`Judge`).
//!
//! Adding a quantity (docs/architecture.md, "Adding a reported quantity"):
//! a `Quantity` variant and its row in `QUANTITIES` (a test holds the row
//! at the variant's position); a new kind of value, a `Formed` variant
//! and its arms in `analysis::summary::formed`. The compiler asks for the
//! rest (no `match` over quantities has a `_` arm).

use crate::units::Dim;

mod formed;
mod value;
pub use formed::{About, Formed};
pub use value::{Owned, Table, Value};

/// A reported quantity; the order of `QUANTITIES`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    Mass,
    CenterOfMass,
    PrincipalMoments,
    InertiaCom,
    InertiaRef,
    RadiiOfGyration,
    /// About the x, y and z axes through the centre of mass.
    RadiiOfGyrationAxes,
    AngularMomentum,
    KineticEnergy,
    /// The predicted body's (basic and growth, `analysis::budget`).
    PredictedMass,
    PredictedCenterOfMass,
    PredictedInertiaCom,
    /// The principal axes about the centre of mass (rows, ascending
    /// moments), compared by angle.
    PrincipalAxes,
    /// The reference point (`about`; the centre of mass without one), a
    /// point in the file's frame.
    ReferencePoint,
    /// The centre of mass from the reference point, c − p, report axes.
    CenterOfMassRef,
    /// The report axes, rows in the file's frame (`axes`; the identity
    /// for the file's own).
    ReportAxes,
    PrincipalMomentsRef,
    PrincipalAxesRef,
    RadiiOfGyrationAxesRef,
    /// ω and α as given (`[analysis]`), and M = I α + ω × H.
    Omega,
    Alpha,
    EulerMoment,
    /// The body moving (`analysis::motion`): the reference point's
    /// velocity v as given, the mass centre's v̄ = v + ω × r, G = m v̄,
    /// H_G = I_G ω, ½ m v̄·v̄ and ½ ω·H_G (`angular_momentum` is then
    /// H_O = H_G + r × G and `kinetic_energy` their sum).
    Velocity,
    VelocityCom,
    LinearMomentum,
    AngularMomentumCom,
    KineticEnergyTranslational,
    KineticEnergyRotational,
}

/// How a quantity's value is laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    Scalar,
    /// Components x, y, z in the report axes.
    Vector,
    /// Components 1, 2, 3 in ascending order.
    Ordered,
    /// Components xx … yz of a symmetric matrix, rows in the report axes.
    Matrix,
    /// Three unit rows, one per principal moment (ascending): an axis is
    /// its own negative, and among equal moments any axes serve.
    Axes,
}

impl Layout {
    /// How many numbers the value has.
    pub const fn count(self) -> usize {
        match self {
            Layout::Scalar => 1,
            Layout::Vector | Layout::Ordered => 3,
            Layout::Matrix | Layout::Axes => 9,
        }
    }
}

/// How `[expect]` compares it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Compare {
    /// `value` ± `tol`, or `min`/`max`, per component; components may be
    /// expected alone (`center_of_mass.z`).
    Bound,
    /// `value` (three unit, orthogonal rows) within `tol_degrees`: the
    /// angle between each expected axis and the computed one, an axis and
    /// its negative alike, only the axes the moments determine
    /// (`analysis::check::axes`).
    Angle,
}

/// What must be computed for the quantity to exist.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    Nothing,
    /// `omega` in `[analysis]`.
    Omega,
    /// The predicted body, composed when a file expects it.
    Predicted,
    /// `alpha` (with `omega`) in `[analysis]`.
    Alpha,
    /// `velocity` (with `omega`) in `[analysis]`.
    Velocity,
}

/// The tolerance `--bless` gives an entry that has none
/// (`analysis::bless::default_tol`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bless {
    /// A whole number that is not near zero by nature: relative
    /// (`"0.0001%"`) when not zero.
    Relative,
    /// Absolute, from the larger of its largest component and the body's
    /// size in its dimension (a component may be zero by symmetry).
    Absolute,
    /// `tol_degrees`, `DEFAULT_TOL_DEGREES`.
    Degrees,
}

/// How `diff` shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// Not compared.
    No,
    /// Per component, relative to the larger of its magnitude in the old
    /// file (the new one's where that is zero); a matrix its upper
    /// triangle.
    Own,
    /// Per component, relative to the body's length scale (a position has
    /// no natural zero).
    Position,
    /// Per axis, the angle between the old and the new axis (radians,
    /// itself the relative change), for the axes both files' moments
    /// determine.
    Angle,
}

/// How `--precision auto` and `--rtol` judge a quantity's error bound
/// (`analysis::summary::accuracy`), and its place among the warnings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Judge {
    /// Not judged.
    No,
    /// As a whole: its largest bound against its largest entry (the
    /// relative error of a vector or tensor is a norm's); zero within its
    /// bound, against `Scale`.
    Whole(u8, Scale),
    /// Each component against itself (`key[i]`); zero within its bound, in
    /// `extended` only, against `Scale`.
    Each(u8, Scale),
    /// Each axis's bound, an angle, against `rtol` radians; axes of moments
    /// flagged equal are a choice, not judged.
    Angle(u8),
}

/// What a value zero within its bound is judged against (`Judge`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// The body's length: the largest coordinate of the centre of mass or
    /// radius of gyration.
    Length,
    /// The body's largest principal moment, about either point.
    Moment,
    /// Its own largest component.
    Own,
    /// Zero: a value zero within its bound falls short.
    Zero,
}

/// One row of the table.
#[derive(Debug, Clone, Copy)]
pub struct Info {
    pub quantity: Quantity,
    /// The `[expect]` key and the JSON key of `report` and `error_bounds`.
    pub key: &'static str,
    /// How `diff`'s table names it, its component's name appended
    /// (`centre of mass x`, `principal moment I1`, `Ixy`).
    pub label: &'static str,
    pub dim: Dim,
    /// Its SI unit as the JSON names it (`units`; ASCII).
    pub unit: &'static str,
    pub layout: Layout,
    /// How its value and its bound are formed.
    pub formed: Formed,
    /// Whether `[expect]` takes it (the values given, and those about the
    /// reference point, it does not).
    pub expected: bool,
    pub compare: Compare,
    pub needs: Needs,
    /// The first of its outputs in the uncertainty (`analysis::sigma`):
    /// `None` for a quantity whose σ is not propagated.
    pub sigma: Option<usize>,
    /// Written into a new `[expect]` by `--bless`.
    pub blessed_by_default: bool,
    pub bless: Bless,
    pub diff: Shown,
    /// Its place among the keys of `report`'s JSON (`Summary`'s
    /// serialization), within its group: the body's values before its
    /// `parts`, what needs ω or α after them (`Info::turning`). `None` for
    /// the predicted body's, which `report` does not write. A new quantity
    /// takes the next number: a key is added after its group's others.
    pub report: Option<u8>,
    /// For a set of axes, the key of the moments flagged equal (their axes
    /// a choice), written after the axes.
    pub equal: Option<&'static str>,
    /// Its place in `error_bounds` (`bounds::ErrorBounds`), which bounds it
    /// absolutely, component by component in its unit (a set of axes: an
    /// angle per axis, radians); `None` for a value given, which is exact
    /// (`Some` exactly where `formed` is bounded: a test holds it).
    pub bound: Option<u8>,
    pub judge: Judge,
}

const fn row(
    quantity: Quantity,
    key: &'static str,
    (dim, unit): (Dim, &'static str),
    layout: Layout,
    formed: Formed,
) -> Info {
    Info {
        quantity,
        key,
        label: key,
        dim,
        unit,
        layout,
        formed,
        expected: true,
        compare: Compare::Bound,
        needs: Needs::Nothing,
        sigma: None,
        blessed_by_default: false,
        bless: Bless::Absolute,
        diff: Shown::No,
        report: None,
        equal: None,
        bound: None,
        judge: Judge::No,
    }
}

/// A row of a quantity that `report` writes but `[expect]` does not take.
const fn reported(
    quantity: Quantity,
    key: &'static str,
    dim: (Dim, &'static str),
    layout: Layout,
    formed: Formed,
) -> Info {
    Info {
        expected: false,
        ..row(quantity, key, dim, layout, formed)
    }
}

const MASS: (Dim, &str) = (Dim::MASS, "kg");
const LENGTH: (Dim, &str) = (Dim::LENGTH, "m");
const INERTIA: (Dim, &str) = (Dim::INERTIA, "kg*m^2");
const NUMBER: (Dim, &str) = (Dim::DIMENSIONLESS, "");
const ENERGY: (Dim, &str) = (Dim::ENERGY, "J");
const ANGULAR_MOMENTUM: (Dim, &str) = (Dim::ANGULAR_MOMENTUM, "N*m*s");

/// Every reported quantity, in the order of `Quantity` (the order in which
/// `[expect]` is read, hence which of two errors is reported).
pub const QUANTITIES: [Info; 28] = [
    Info {
        label: "mass",
        sigma: Some(0),
        blessed_by_default: true,
        bless: Bless::Relative,
        diff: Shown::Own,
        report: Some(0),
        bound: Some(0),
        judge: Judge::Each(6, Scale::Own),
        ..row(Quantity::Mass, "mass", MASS, Layout::Scalar, Formed::Mass)
    },
    Info {
        label: "centre of mass ",
        sigma: Some(1),
        blessed_by_default: true,
        diff: Shown::Position,
        report: Some(1),
        bound: Some(1),
        judge: Judge::Whole(0, Scale::Length),
        ..row(
            Quantity::CenterOfMass,
            "center_of_mass",
            LENGTH,
            Layout::Vector,
            Formed::Centre,
        )
    },
    Info {
        label: "principal moment I",
        sigma: Some(10),
        blessed_by_default: true,
        diff: Shown::Own,
        report: Some(7),
        bound: Some(5),
        judge: Judge::Each(7, Scale::Own),
        ..row(
            Quantity::PrincipalMoments,
            "principal_moments",
            INERTIA,
            Layout::Ordered,
            Formed::Moments(About::Centre),
        )
    },
    Info {
        label: "I",
        sigma: Some(4),
        diff: Shown::Own,
        report: Some(5),
        bound: Some(3),
        judge: Judge::Whole(2, Scale::Moment),
        ..row(
            Quantity::InertiaCom,
            "inertia_com",
            INERTIA,
            Layout::Matrix,
            Formed::Tensor(About::Centre),
        )
    },
    Info {
        report: Some(6),
        bound: Some(4),
        judge: Judge::Whole(3, Scale::Moment),
        ..row(
            Quantity::InertiaRef,
            "inertia_ref",
            INERTIA,
            Layout::Matrix,
            Formed::Tensor(About::Point),
        )
    },
    Info {
        report: Some(11),
        bound: Some(9),
        judge: Judge::Each(9, Scale::Own),
        ..row(
            Quantity::RadiiOfGyration,
            "radii_of_gyration",
            LENGTH,
            Layout::Ordered,
            Formed::Radii(About::Centre),
        )
    },
    Info {
        report: Some(12),
        bound: Some(10),
        judge: Judge::Each(10, Scale::Own),
        ..row(
            Quantity::RadiiOfGyrationAxes,
            "radii_of_gyration_axes",
            LENGTH,
            Layout::Vector,
            Formed::RadiiAxes(About::Centre),
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS),
        needs: Needs::Omega,
        report: Some(15),
        bound: Some(13),
        judge: Judge::Whole(4, Scale::Zero),
        ..row(
            Quantity::AngularMomentum,
            "angular_momentum",
            ANGULAR_MOMENTUM,
            Layout::Vector,
            Formed::Momentum,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 3),
        needs: Needs::Omega,
        bless: Bless::Relative,
        report: Some(16),
        bound: Some(14),
        judge: Judge::Each(14, Scale::Own),
        ..row(
            Quantity::KineticEnergy,
            "kinetic_energy",
            ENERGY,
            Layout::Scalar,
            Formed::Energy,
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS),
        bless: Bless::Relative,
        ..row(
            Quantity::PredictedMass,
            "predicted_mass",
            MASS,
            Layout::Scalar,
            Formed::Predicted(Quantity::Mass),
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS + 1),
        ..row(
            Quantity::PredictedCenterOfMass,
            "predicted_center_of_mass",
            LENGTH,
            Layout::Vector,
            Formed::Predicted(Quantity::CenterOfMass),
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS + 4),
        ..row(
            Quantity::PredictedInertiaCom,
            "predicted_inertia_com",
            INERTIA,
            Layout::Matrix,
            Formed::Predicted(Quantity::InertiaCom),
        )
    },
    Info {
        label: "principal axis ",
        compare: Compare::Angle,
        bless: Bless::Degrees,
        diff: Shown::Angle,
        report: Some(8),
        equal: Some("equal_moments"),
        bound: Some(6),
        judge: Judge::Angle(12),
        ..row(
            Quantity::PrincipalAxes,
            "principal_axes",
            NUMBER,
            Layout::Axes,
            Formed::Axes(About::Centre),
        )
    },
    Info {
        report: Some(2),
        bound: Some(2),
        ..reported(
            Quantity::ReferencePoint,
            "reference_point",
            LENGTH,
            Layout::Vector,
            Formed::Point,
        )
    },
    Info {
        report: Some(3),
        bound: Some(12),
        judge: Judge::Whole(1, Scale::Length),
        ..reported(
            Quantity::CenterOfMassRef,
            "center_of_mass_ref",
            LENGTH,
            Layout::Vector,
            Formed::Offset,
        )
    },
    // Rows, not a symmetric matrix; never compared.
    Info {
        report: Some(4),
        ..reported(
            Quantity::ReportAxes,
            "axes",
            NUMBER,
            Layout::Matrix,
            Formed::Frame,
        )
    },
    Info {
        report: Some(9),
        bound: Some(7),
        judge: Judge::Each(8, Scale::Own),
        ..reported(
            Quantity::PrincipalMomentsRef,
            "principal_moments_ref",
            INERTIA,
            Layout::Ordered,
            Formed::Moments(About::Point),
        )
    },
    Info {
        report: Some(10),
        equal: Some("equal_moments_ref"),
        bound: Some(8),
        judge: Judge::Angle(13),
        ..reported(
            Quantity::PrincipalAxesRef,
            "principal_axes_ref",
            NUMBER,
            Layout::Axes,
            Formed::Axes(About::Point),
        )
    },
    Info {
        report: Some(13),
        bound: Some(11),
        judge: Judge::Each(11, Scale::Own),
        ..reported(
            Quantity::RadiiOfGyrationAxesRef,
            "radii_of_gyration_axes_ref",
            LENGTH,
            Layout::Vector,
            Formed::RadiiAxes(About::Point),
        )
    },
    Info {
        needs: Needs::Omega,
        report: Some(14),
        ..reported(
            Quantity::Omega,
            "omega",
            (Dim::ANGULAR_VELOCITY, "rad/s"),
            Layout::Vector,
            Formed::Omega,
        )
    },
    Info {
        needs: Needs::Alpha,
        report: Some(17),
        ..reported(
            Quantity::Alpha,
            "alpha",
            (Dim::ANGULAR_ACCELERATION, "rad/s^2"),
            Layout::Vector,
            Formed::Alpha,
        )
    },
    // A moment has the dimension of an energy, but is not one: N·m.
    Info {
        needs: Needs::Alpha,
        report: Some(18),
        bound: Some(15),
        judge: Judge::Whole(5, Scale::Zero),
        ..reported(
            Quantity::EulerMoment,
            "euler_moment",
            (Dim::ENERGY, "N*m"),
            Layout::Vector,
            Formed::EulerMoment,
        )
    },
    // Given, but rounded into SI from the file's length unit: bounded.
    Info {
        needs: Needs::Velocity,
        report: Some(19),
        bound: Some(16),
        ..reported(
            Quantity::Velocity,
            "velocity",
            (Dim::VELOCITY, "m/s"),
            Layout::Vector,
            Formed::Velocity,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 4),
        needs: Needs::Velocity,
        report: Some(20),
        bound: Some(17),
        judge: Judge::Whole(15, Scale::Zero),
        ..row(
            Quantity::VelocityCom,
            "velocity_com",
            (Dim::VELOCITY, "m/s"),
            Layout::Vector,
            Formed::VelocityCom,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 7),
        needs: Needs::Velocity,
        report: Some(21),
        bound: Some(18),
        judge: Judge::Whole(16, Scale::Zero),
        ..row(
            Quantity::LinearMomentum,
            "linear_momentum",
            (Dim::MOMENTUM, "kg*m/s"),
            Layout::Vector,
            Formed::LinearMomentum,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 10),
        needs: Needs::Velocity,
        report: Some(22),
        bound: Some(19),
        judge: Judge::Whole(17, Scale::Zero),
        ..row(
            Quantity::AngularMomentumCom,
            "angular_momentum_com",
            ANGULAR_MOMENTUM,
            Layout::Vector,
            Formed::MomentumCom,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 13),
        needs: Needs::Velocity,
        bless: Bless::Relative,
        report: Some(23),
        bound: Some(20),
        judge: Judge::Each(18, Scale::Own),
        ..row(
            Quantity::KineticEnergyTranslational,
            "kinetic_energy_translational",
            ENERGY,
            Layout::Scalar,
            Formed::EnergyTranslational,
        )
    },
    Info {
        sigma: Some(2 * OUTPUTS + 14),
        needs: Needs::Velocity,
        bless: Bless::Relative,
        report: Some(24),
        bound: Some(21),
        judge: Judge::Each(19, Scale::Own),
        ..row(
            Quantity::KineticEnergyRotational,
            "kinetic_energy_rotational",
            ENERGY,
            Layout::Scalar,
            Formed::EnergyRotational,
        )
    },
];

/// The rows in the order of `place` (`Info::report`, `Info::bound`, the
/// place of `Info::judge`), those without one left out.
pub fn in_order(place: fn(&Info) -> Option<u8>) -> impl Iterator<Item = &'static Info> {
    let mut rows: Vec<(u8, &'static Info)> = QUANTITIES
        .iter()
        .filter_map(|i| place(i).map(|p| (p, i)))
        .collect();
    rows.sort_by_key(|r| r.0);
    rows.into_iter().map(|r| r.1)
}

impl Info {
    /// Whether it is one of what the body turning adds (it needs ω or α),
    /// which `report`'s JSON writes after the parts.
    pub fn turning(&self) -> bool {
        match self.needs {
            Needs::Omega | Needs::Alpha | Needs::Velocity => true,
            Needs::Nothing | Needs::Predicted => false,
        }
    }
}

/// Write a quantity's value or bound `v` into a JSON object under its key
/// (a set of axes' value: its equal moments after it, under `Info::equal`);
/// nothing where it is absent.
pub fn serialize_field<M: serde::ser::SerializeStruct>(
    m: &mut M,
    info: &Info,
    v: Option<Value>,
) -> Result<(), M::Error> {
    let Some(v) = v else { return Ok(()) };
    m.serialize_field(info.key, &v)?;
    match (v, info.equal) {
        (Value::Axes(_, equal), Some(key)) => m.serialize_field(key, equal),
        (Value::Scalar(_) | Value::Triple(_) | Value::Rows(_) | Value::Axes(..), _) => Ok(()),
    }
}

impl Judge {
    /// Its place among the warnings.
    pub fn place(self) -> Option<u8> {
        match self {
            Judge::No => None,
            Judge::Whole(n, _) | Judge::Each(n, _) | Judge::Angle(n) => Some(n),
        }
    }
}

/// How many σ outputs one body has (`analysis::sigma`): mass, centre of
/// mass, the six entries of the inertia tensor, the principal moments.
pub const OUTPUTS: usize = 13;

/// How many σ outputs the body moving has, after both bodies' outputs
/// (`analysis::uncertainty::motion`): the angular momentum about the
/// point and the kinetic energy (with ω), v̄, G, H_G and the two parts of
/// the kinetic energy (with `velocity`).
pub const MOTION_OUTPUTS: usize = 15;

/// The `[expect]` keys that name one entry of the inertia tensor about the
/// centre of mass: key, row, column.
pub const ALIASES: [(&str, Quantity, usize, usize); 6] = [
    ("Ixx", Quantity::InertiaCom, 0, 0),
    ("Iyy", Quantity::InertiaCom, 1, 1),
    ("Izz", Quantity::InertiaCom, 2, 2),
    ("Ixy", Quantity::InertiaCom, 0, 1),
    ("Ixz", Quantity::InertiaCom, 0, 2),
    ("Iyz", Quantity::InertiaCom, 1, 2),
];

/// The tolerance `--bless` gives `principal_axes` when it has none.
pub const DEFAULT_TOL_DEGREES: f64 = 0.5;

impl Quantity {
    /// Its row of `QUANTITIES`.
    pub fn info(self) -> &'static Info {
        &QUANTITIES[self as usize]
    }
}

/// Quantity `q`'s SI unit as the JSON names it (`Info::unit`).
pub const fn unit(q: Quantity) -> &'static str {
    QUANTITIES[q as usize].unit
}

/// The row of the quantity with JSON key `key`.
pub fn by_key(key: &str) -> Option<&'static Info> {
    QUANTITIES.iter().find(|i| i.key == key)
}

/// The components of a vector, and of a matrix's rows and columns.
pub const XYZ: [&str; 3] = ["x", "y", "z"];
/// The components of an ordered triple.
pub const ORDINALS: [&str; 3] = ["1", "2", "3"];
/// A symmetric matrix's independent entries: name, row, column.
pub const UPPER: [(&str, usize, usize); 6] = [
    ("xx", 0, 0),
    ("yy", 1, 1),
    ("zz", 2, 2),
    ("xy", 0, 1),
    ("xz", 0, 2),
    ("yz", 1, 2),
];

/// The name of component `k` (row-major for a matrix) of a value of
/// `layout`: `x`, `2`, `xy`, or empty for a scalar. An axis is named by its
/// moment's ordinal.
pub fn component(layout: Layout, k: usize) -> String {
    match layout {
        Layout::Scalar => String::new(),
        Layout::Vector => XYZ[k].to_string(),
        Layout::Ordered => ORDINALS[k].to_string(),
        Layout::Matrix => format!("{}{}", XYZ[k / 3], XYZ[k % 3]),
        Layout::Axes => ORDINALS[k / 3].to_string(),
    }
}

#[cfg(test)]
mod tests;
