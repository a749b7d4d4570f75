//! The reported quantities, each declared once: its key (in `[expect]`,
//! in the JSON of `report` and `error_bounds`, in `check`'s and `diff`'s
//! names), its dimension and shape, how `[expect]` compares it, what
//! `--bless` writes for it, whether the uncertainty carries its σ, and how
//! `diff` shows it. `model::expect` reads `[expect]` from this table,
//! `analysis::check` compares by it, `analysis::sigma` numbers the σ
//! outputs from it, `analysis::bless` and `analysis::diff` follow it.
//!
//! Adding a quantity: a `Quantity` variant and its row in `QUANTITIES`
//! (a test holds the row at the variant's position), its field in
//! `model::raw::RawExpect` (the serde mirror), and its value in
//! `analysis::summary::Summary::value`, which the compiler asks for (no
//! `match` over quantities has a `_` arm).

use crate::units::Dim;

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
    pub layout: Layout,
    pub compare: Compare,
    pub needs: Needs,
    /// The first of its outputs in the uncertainty (`analysis::sigma`):
    /// `None` for a quantity whose σ is not propagated.
    pub sigma: Option<usize>,
    /// Written into a new `[expect]` by `--bless`.
    pub blessed_by_default: bool,
    pub bless: Bless,
    pub diff: Shown,
}

const fn row(quantity: Quantity, key: &'static str, dim: Dim, layout: Layout) -> Info {
    Info {
        quantity,
        key,
        label: key,
        dim,
        layout,
        compare: Compare::Bound,
        needs: Needs::Nothing,
        sigma: None,
        blessed_by_default: false,
        bless: Bless::Absolute,
        diff: Shown::No,
    }
}

/// Every reported quantity, in the order of `Quantity` (the order in which
/// `[expect]` is read, hence which of two errors is reported).
pub const QUANTITIES: [Info; 13] = [
    Info {
        label: "mass",
        sigma: Some(0),
        blessed_by_default: true,
        bless: Bless::Relative,
        diff: Shown::Own,
        ..row(Quantity::Mass, "mass", Dim::MASS, Layout::Scalar)
    },
    Info {
        label: "centre of mass ",
        sigma: Some(1),
        blessed_by_default: true,
        diff: Shown::Position,
        ..row(
            Quantity::CenterOfMass,
            "center_of_mass",
            Dim::LENGTH,
            Layout::Vector,
        )
    },
    Info {
        label: "principal moment I",
        sigma: Some(10),
        blessed_by_default: true,
        diff: Shown::Own,
        ..row(
            Quantity::PrincipalMoments,
            "principal_moments",
            Dim::INERTIA,
            Layout::Ordered,
        )
    },
    Info {
        label: "I",
        sigma: Some(4),
        diff: Shown::Own,
        ..row(
            Quantity::InertiaCom,
            "inertia_com",
            Dim::INERTIA,
            Layout::Matrix,
        )
    },
    row(
        Quantity::InertiaRef,
        "inertia_ref",
        Dim::INERTIA,
        Layout::Matrix,
    ),
    row(
        Quantity::RadiiOfGyration,
        "radii_of_gyration",
        Dim::LENGTH,
        Layout::Ordered,
    ),
    row(
        Quantity::RadiiOfGyrationAxes,
        "radii_of_gyration_axes",
        Dim::LENGTH,
        Layout::Vector,
    ),
    Info {
        needs: Needs::Omega,
        ..row(
            Quantity::AngularMomentum,
            "angular_momentum",
            Dim::ANGULAR_MOMENTUM,
            Layout::Vector,
        )
    },
    Info {
        needs: Needs::Omega,
        bless: Bless::Relative,
        ..row(
            Quantity::KineticEnergy,
            "kinetic_energy",
            Dim::ENERGY,
            Layout::Scalar,
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS),
        bless: Bless::Relative,
        ..row(
            Quantity::PredictedMass,
            "predicted_mass",
            Dim::MASS,
            Layout::Scalar,
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS + 1),
        ..row(
            Quantity::PredictedCenterOfMass,
            "predicted_center_of_mass",
            Dim::LENGTH,
            Layout::Vector,
        )
    },
    Info {
        needs: Needs::Predicted,
        sigma: Some(OUTPUTS + 4),
        ..row(
            Quantity::PredictedInertiaCom,
            "predicted_inertia_com",
            Dim::INERTIA,
            Layout::Matrix,
        )
    },
    Info {
        label: "principal axis ",
        compare: Compare::Angle,
        bless: Bless::Degrees,
        diff: Shown::Angle,
        ..row(
            Quantity::PrincipalAxes,
            "principal_axes",
            Dim::DIMENSIONLESS,
            Layout::Axes,
        )
    },
];

/// How many σ outputs one body has (`analysis::sigma`): mass, centre of
/// mass, the six entries of the inertia tensor, the principal moments.
pub const OUTPUTS: usize = 13;

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
mod tests {
    use super::*;

    #[test]
    fn each_row_stands_at_its_variants_position() {
        for (k, info) in QUANTITIES.iter().enumerate() {
            assert_eq!(info.quantity as usize, k, "{}", info.key);
        }
    }

    #[test]
    fn the_sigma_outputs_of_one_body_are_numbered_without_overlap() {
        let mut taken = [false; 2 * OUTPUTS];
        for info in &QUANTITIES {
            let Some(first) = info.sigma else { continue };
            let n = match info.layout {
                Layout::Matrix => UPPER.len(),
                Layout::Scalar | Layout::Vector | Layout::Ordered | Layout::Axes => {
                    info.layout.count()
                }
            };
            for (o, t) in taken.iter_mut().enumerate().skip(first).take(n) {
                assert!(!*t, "{} overlaps output {o}", info.key);
                *t = true;
            }
        }
        // Every output of the basic body is some quantity's (the predicted
        // body's principal moments have no `[expect]` key).
        assert!(taken[..OUTPUTS].iter().all(|t| *t), "{taken:?}");
    }

    #[test]
    fn every_key_is_distinct() {
        let mut keys: Vec<&str> = QUANTITIES.iter().map(|i| i.key).collect();
        keys.extend(ALIASES.iter().map(|a| a.0));
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), n);
    }

    #[test]
    fn a_quantity_compared_by_angle_is_a_set_of_axes() {
        for info in &QUANTITIES {
            assert_eq!(
                info.compare == Compare::Angle,
                info.layout == Layout::Axes,
                "{}",
                info.key
            );
        }
    }
}
