//! What the report's tables show of the body moving (`analysis::motion`):
//! the rows of v, v̄, G and H_G, and the two parts of T, each present only
//! where `velocity` is given. SI, as ω and H are.

use crate::analysis::summary::Summary;
use crate::output::format::fmt_bounded;
use crate::quantity::Quantity;

/// The vector rows: label, value, bound, unit.
const ROWS: [(&str, Quantity, &str); 4] = [
    ("velocity of the point v", Quantity::Velocity, "m/s"),
    ("velocity of the centre v̄", Quantity::VelocityCom, "m/s"),
    ("linear momentum G", Quantity::LinearMomentum, "kg·m/s"),
    (
        "angular momentum H_G",
        Quantity::AngularMomentumCom,
        "N·m·s",
    ),
];

/// The rows of the body moving, each with its bound; none without
/// `velocity`.
pub(super) fn rows(s: &Summary) -> Vec<(&'static str, [f64; 3], [f64; 3], &'static str)> {
    ROWS.iter()
        .filter_map(|&(label, q, unit)| {
            let v = s.values.triple(q)?;
            let b = s.error_bounds.of(q)?;
            Some((label, v, std::array::from_fn(|j| b.component(j)), unit))
        })
        .collect()
}

/// ` = a J translational + b J rotational` after T; empty without
/// `velocity`.
pub(super) fn energy_parts(s: &Summary) -> String {
    let part = |q: Quantity| -> Option<String> {
        let v = s.values.scalar(q)?;
        let b = s.error_bounds.of(q)?.component(0);
        Some(fmt_bounded(v, b, v.abs()))
    };
    match (
        part(Quantity::KineticEnergyTranslational),
        part(Quantity::KineticEnergyRotational),
    ) {
        (Some(t), Some(r)) => format!(" = {t} J translational + {r} J rotational"),
        _ => String::new(),
    }
}
