//! How a quantity's value and its error bound are formed: the kind each
//! row of `QUANTITIES` declares, which `analysis::summary::formed` follows.

use super::Quantity;

/// The point a quantity is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum About {
    /// The centre of mass.
    Centre,
    /// The reference point (`about`; the centre of mass without one).
    Point,
}

/// How a quantity's value and its error bound are formed
/// (`analysis::summary::formed`), from the composed body. The order of
/// the variants is the order in which values are formed and checked
/// (which of two failures is reported).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Formed {
    /// The composed mass; bounded by the composer's mass bound.
    Mass,
    /// The centre of mass, a point in the file's frame; bounded by the
    /// composer's centre bound.
    Centre,
    /// The reference point: given (then bounded by its rounding to SI),
    /// or the centre of mass (then its bound).
    Point,
    /// The centre of mass from the reference point, c − p, report axes;
    /// bounded by the centre's bound and the difference's rounding.
    Offset,
    /// The report axes' rows, given: exact.
    Frame,
    /// The inertia tensor about the point, report axes; bounded from the
    /// second moment's bound (`bounds::inertia_of`).
    Tensor(About),
    /// The principal moments and axes about the point; bounded from the
    /// second moment's bound and the gaps between the moments
    /// (`bounds::eigen`; an axis's bound an angle).
    Moments(About),
    Axes(About),
    /// √(Iᵢ/m) of the principal moments about the point; bounded from the
    /// moments' and the mass's bounds (`bounds::radius`).
    Radii(About),
    /// √(I_jj/m) about the report axes through the point; bounded from the
    /// tensor's diagonal and the mass's bounds (`bounds::radius`).
    RadiiAxes(About),
    /// ω and α as given: exact.
    Omega,
    Alpha,
    /// H = I ω, T = ½ ωᵀ I ω and M = I α + ω × H about the reference point;
    /// bounded from the tensor's bound (`bounds::dynamics`).
    Momentum,
    Energy,
    EulerMoment,
    /// The body moving with the reference point's velocity v
    /// (`analysis::motion`): v as given (rounded into SI), v̄ = v + ω × r,
    /// G = m v̄, H_G = I_G ω, ½ m v̄·v̄ and ½ ω·H_G; bounded from the
    /// mass's, the offset's and the tensors' bounds (`analysis::motion`).
    Velocity,
    VelocityCom,
    LinearMomentum,
    MomentumCom,
    EnergyTranslational,
    EnergyRotational,
    /// The predicted body's quantity (its own summary's): not bounded.
    Predicted(Quantity),
}

impl Formed {
    /// Whether a value so formed has an error bound (a value given, the
    /// predicted body's, has none).
    pub fn bounded(self) -> bool {
        match self {
            Formed::Mass
            | Formed::Centre
            | Formed::Point
            | Formed::Offset
            | Formed::Tensor(_)
            | Formed::Moments(_)
            | Formed::Axes(_)
            | Formed::Radii(_)
            | Formed::RadiiAxes(_)
            | Formed::Momentum
            | Formed::Energy
            | Formed::EulerMoment
            | Formed::Velocity
            | Formed::VelocityCom
            | Formed::LinearMomentum
            | Formed::MomentumCom
            | Formed::EnergyTranslational
            | Formed::EnergyRotational => true,
            Formed::Frame | Formed::Omega | Formed::Alpha | Formed::Predicted(_) => false,
        }
    }

    /// The predicted body's quantity that a quantity so formed is.
    pub fn predicted(self) -> Option<Quantity> {
        match self {
            Formed::Predicted(q) => Some(q),
            Formed::Mass
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
            | Formed::Velocity
            | Formed::VelocityCom
            | Formed::LinearMomentum
            | Formed::MomentumCom
            | Formed::EnergyTranslational
            | Formed::EnergyRotational => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Needs, QUANTITIES};
    use super::*;

    #[test]
    fn a_row_has_a_place_in_error_bounds_exactly_when_its_value_is_formed_with_a_bound() {
        for info in &QUANTITIES {
            assert_eq!(info.bound.is_some(), info.formed.bounded(), "{}", info.key);
        }
    }

    /// What a formation reads (ω, α, the predicted body) is what the row
    /// says it needs, so `[expect]` asks for it and the JSON places it.
    #[test]
    fn a_row_needs_what_its_value_is_formed_from() {
        for info in &QUANTITIES {
            let needs = match info.formed {
                Formed::Omega | Formed::Momentum | Formed::Energy => Needs::Omega,
                Formed::Alpha | Formed::EulerMoment => Needs::Alpha,
                Formed::Predicted(_) => Needs::Predicted,
                Formed::Velocity
                | Formed::VelocityCom
                | Formed::LinearMomentum
                | Formed::MomentumCom
                | Formed::EnergyTranslational
                | Formed::EnergyRotational => Needs::Velocity,
                Formed::Mass
                | Formed::Centre
                | Formed::Point
                | Formed::Offset
                | Formed::Frame
                | Formed::Tensor(_)
                | Formed::Moments(_)
                | Formed::Axes(_)
                | Formed::Radii(_)
                | Formed::RadiiAxes(_) => Needs::Nothing,
            };
            assert_eq!(info.needs, needs, "{}", info.key);
        }
    }

    #[test]
    fn a_predicted_quantity_is_one_the_basic_body_forms_in_the_same_layout() {
        for info in &QUANTITIES {
            let Some(q) = info.formed.predicted() else {
                continue;
            };
            let basic = q.info();
            assert!(basic.formed.predicted().is_none(), "{}", info.key);
            assert_eq!(basic.layout, info.layout, "{}", info.key);
            assert_eq!(basic.dim, info.dim, "{}", info.key);
        }
    }

    #[test]
    fn no_two_rows_are_formed_alike() {
        let mut kinds: Vec<Formed> = QUANTITIES.iter().map(|i| i.formed).collect();
        let n = kinds.len();
        kinds.sort_unstable();
        kinds.dedup();
        assert_eq!(kinds.len(), n);
    }
}
