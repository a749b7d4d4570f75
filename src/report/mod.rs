//! One serializable summary of a body, in SI, that every output format
//! renders. `json` serializes it as the documented contract; `table` prints
//! it for people in the file's units.

pub mod json;
pub mod table;

use crate::compose::{self, Principal};
use crate::mass::inertia_of;
use crate::model::{Analysis, Model};
use crate::units::FileUnits;
use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

/// Version of the JSON contract: bumped only if a key changes meaning.
/// Keys may be added; none is ever renamed or removed.
pub const FORMAT_VERSION: u32 = 1;

/// How products of inertia are shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, clap::ValueEnum, Default)]
#[serde(rename_all = "lowercase")]
pub enum Products {
    /// Tensor entries: I_xy = −∫xy dm (the default).
    #[default]
    Tensor,
    /// CAD and Meriam convention: I_xy = +∫xy dm.
    Positive,
}

/// SI unit of each reported quantity, written in ASCII for scripts.
#[derive(Debug, Clone, Serialize)]
pub struct SiUnits {
    pub mass: &'static str,
    pub length: &'static str,
    pub inertia: &'static str,
    pub angular_velocity: &'static str,
    pub angular_acceleration: &'static str,
    pub angular_momentum: &'static str,
    pub energy: &'static str,
    pub moment: &'static str,
}

const SI_UNITS: SiUnits = SiUnits {
    mass: "kg",
    length: "m",
    inertia: "kg*m^2",
    angular_velocity: "rad/s",
    angular_acceleration: "rad/s^2",
    angular_momentum: "N*m*s",
    energy: "J",
    moment: "N*m",
};

#[derive(Debug, Clone, Serialize)]
pub struct PartSummary {
    pub name: String,
    pub shape: crate::shapes::Shape,
    pub mass: f64,
    /// Fraction of the total mass, 0 to 1.
    pub mass_fraction: f64,
    pub center_of_mass: [f64; 3],
}

/// Everything `report` prints, in SI. Field names are the JSON keys.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    pub format_version: u32,
    pub name: Option<String>,
    pub products_convention: Products,
    pub units: SiUnits,
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub reference_point: [f64; 3],
    /// Rows of the inertia tensor about the centre of mass, file axes.
    pub inertia_com: [[f64; 3]; 3],
    /// Rows of the inertia tensor about the reference point, file axes.
    pub inertia_ref: [[f64; 3]; 3],
    pub principal_moments: [f64; 3],
    pub principal_axes: [[f64; 3]; 3],
    /// Indices of principal moments equal within tolerance (axes not unique).
    pub equal_moments: Vec<usize>,
    pub principal_moments_ref: [f64; 3],
    pub principal_axes_ref: [[f64; 3]; 3],
    pub equal_moments_ref: Vec<usize>,
    /// √(Iᵢ/m) of the principal moments about the centre of mass.
    pub radii_of_gyration: [f64; 3],
    pub parts: Vec<PartSummary>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub omega: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angular_momentum: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kinetic_energy: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub euler_moment: Option<[f64; 3]>,
    /// Whether a reference point was given (else it is the centre of mass).
    #[serde(skip)]
    pub reference_given: bool,
    /// The file's units, for the table.
    #[serde(skip)]
    pub file_units: FileUnits,
}

/// Why a summary could not be formed from valid parts.
#[derive(Debug, Clone, PartialEq)]
pub enum SummaryError {
    /// A result overflowed f64 (parts or offsets too large).
    NotFinite(&'static str),
    NoConvergence,
}

impl std::fmt::Display for SummaryError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SummaryError::NotFinite(what) => {
                write!(
                    f,
                    "the {what} overflows the range of f64; are sizes, masses or offsets in the wrong units?"
                )
            }
            SummaryError::NoConvergence => write!(f, "the principal-axis solver did not converge"),
        }
    }
}

fn rows(m: &Matrix3<f64>, products: Products) -> [[f64; 3]; 3] {
    let sign = match products {
        Products::Tensor => 1.0,
        Products::Positive => -1.0,
    };
    std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { m[(i, j)] } else { sign * m[(i, j)] })
    })
}

fn arr(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn finite(v: &[f64], what: &'static str) -> Result<(), SummaryError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(SummaryError::NotFinite(what))
    }
}

/// Compose the model's parts and derive everything reported. `analysis`
/// (the file's, with command-line overrides applied) gives the reference
/// point and ω, α.
pub fn summarize(
    model: &Model,
    analysis: &Analysis,
    products: Products,
) -> Result<Summary, SummaryError> {
    let body = compose::compose(&model.parts);
    finite(&[body.mass], "total mass")?;
    finite(body.center_of_mass.as_slice(), "centre of mass")?;
    let reference = analysis.about.unwrap_or(body.center_of_mass);
    let c_ref = body.second_moment_about(&reference);
    let i_com = inertia_of(&body.second_moment);
    let i_ref = inertia_of(&c_ref);
    finite(i_com.as_slice(), "inertia about the centre of mass")?;
    finite(i_ref.as_slice(), "inertia about the reference point")?;
    let p_com = compose::principal(&body.second_moment).ok_or(SummaryError::NoConvergence)?;
    let p_ref = compose::principal(&c_ref).ok_or(SummaryError::NoConvergence)?;
    finite(&p_com.moments, "principal moments about the centre of mass")?;
    finite(
        &p_ref.moments,
        "principal moments about the reference point",
    )?;
    let radii = p_com.moments.map(|i| (i / body.mass).sqrt());
    finite(&radii, "radii of gyration")?;
    let axes = |p: &Principal| p.axes.map(|a| arr(&a));

    let h = analysis.omega.map(|w| i_ref * w);
    let t = analysis.omega.zip(h).map(|(w, h)| 0.5 * w.dot(&h));
    let m = analysis
        .alpha
        .zip(analysis.omega.zip(h))
        .map(|(a, (w, h))| i_ref * a + w.cross(&h));
    if let Some(h) = &h {
        finite(h.as_slice(), "angular momentum")?;
    }
    finite(&[t.unwrap_or(0.0)], "kinetic energy")?;
    if let Some(m) = &m {
        finite(m.as_slice(), "Euler moment")?;
    }

    Ok(Summary {
        format_version: FORMAT_VERSION,
        name: model.name.clone(),
        products_convention: products,
        units: SI_UNITS,
        mass: body.mass,
        center_of_mass: arr(&body.center_of_mass),
        reference_point: arr(&reference),
        inertia_com: rows(&i_com, products),
        inertia_ref: rows(&i_ref, products),
        principal_moments: p_com.moments,
        principal_axes: axes(&p_com),
        equal_moments: p_com.equal.clone(),
        principal_moments_ref: p_ref.moments,
        principal_axes_ref: axes(&p_ref),
        equal_moments_ref: p_ref.equal.clone(),
        radii_of_gyration: radii,
        parts: model
            .parts
            .iter()
            .map(|p| PartSummary {
                name: p.name.clone(),
                shape: p.shape,
                mass: p.mass,
                mass_fraction: p.mass / body.mass,
                center_of_mass: arr(&p.center),
            })
            .collect(),
        omega: analysis.omega.as_ref().map(arr),
        angular_momentum: h.as_ref().map(arr),
        kinetic_energy: t,
        alpha: analysis.alpha.as_ref().map(arr),
        euler_moment: m.as_ref().map(arr),
        reference_given: analysis.about.is_some(),
        file_units: model.units,
    })
}
