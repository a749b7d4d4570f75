//! The summary's quantities as the table of reported quantities
//! (`quantity::QUANTITIES`) names them: each one's value
//! (`Summary::reported`, which `[expect]` reads through `value`), and the
//! JSON of `report`, each quantity under its key in its place.

use super::Summary;
use crate::model::expect::Target;
use crate::quantity::{self, Quantity, Value};
use serde::Serialize;

impl Summary {
    /// Quantity `q` as it is reported, SI; `None` where it was not computed
    /// (no ω, no α, no predicted body). The predicted body's quantities
    /// are its summary's (`load` makes it when the file expects them).
    pub fn reported(&self, q: Quantity) -> Option<Value<'_>> {
        let predicted = || self.predicted.as_deref();
        Some(match q {
            Quantity::Mass => Value::Scalar(self.mass),
            Quantity::CenterOfMass => Value::Triple(&self.center_of_mass),
            Quantity::PrincipalMoments => Value::Triple(&self.principal_moments),
            Quantity::InertiaCom => Value::Rows(&self.inertia_com),
            Quantity::InertiaRef => Value::Rows(&self.inertia_ref),
            Quantity::RadiiOfGyration => Value::Triple(&self.radii_of_gyration),
            Quantity::RadiiOfGyrationAxes => Value::Triple(&self.radii_of_gyration_axes),
            Quantity::AngularMomentum => Value::Triple(self.angular_momentum.as_ref()?),
            Quantity::KineticEnergy => Value::Scalar(self.kinetic_energy?),
            Quantity::PredictedMass => predicted()?.reported(Quantity::Mass)?,
            Quantity::PredictedCenterOfMass => predicted()?.reported(Quantity::CenterOfMass)?,
            Quantity::PredictedInertiaCom => predicted()?.reported(Quantity::InertiaCom)?,
            Quantity::PrincipalAxes => Value::Axes(&self.principal_axes, &self.equal_moments),
            Quantity::ReferencePoint => Value::Triple(&self.reference_point),
            Quantity::CenterOfMassRef => Value::Triple(&self.center_of_mass_ref),
            Quantity::ReportAxes => Value::Rows(&self.axes),
            Quantity::PrincipalMomentsRef => Value::Triple(&self.principal_moments_ref),
            Quantity::PrincipalAxesRef => {
                Value::Axes(&self.principal_axes_ref, &self.equal_moments_ref)
            }
            Quantity::RadiiOfGyrationAxesRef => Value::Triple(&self.radii_of_gyration_axes_ref),
            Quantity::Omega => Value::Triple(self.omega.as_ref()?),
            Quantity::Alpha => Value::Triple(self.alpha.as_ref()?),
            Quantity::EulerMoment => Value::Triple(self.euler_moment.as_ref()?),
        })
    }

    /// The value an `[expect]` target reads, SI: component `k` of a
    /// quantity (row-major for a matrix); NaN where it was not computed
    /// (no ω, no predicted body).
    pub fn value(&self, t: Target) -> f64 {
        self.reported(t.quantity)
            .map_or(f64::NAN, |v| v.component(t.component))
    }
}

/// The documented JSON contract (docs/json.md): what the file and the
/// arithmetic were, then the body's quantities, its parts, what the body
/// turning adds (the quantities that need ω or α), and how far to trust
/// it. The quantities come from `quantity::QUANTITIES`, each in its place.
impl Serialize for Summary {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        // NOTE: the length is an upper bound (fields absent are not
        // written); serde_json closes at once an object announced empty.
        let mut m = s.serialize_struct("Summary", 16 + 2 * quantity::QUANTITIES.len())?;
        m.serialize_field("format_version", &self.format_version)?;
        m.serialize_field("massprop_version", self.massprop_version)?;
        if let Some(source) = &self.source {
            m.serialize_field("source", source)?;
        }
        m.serialize_field("name", &self.name)?;
        if let Some(path) = &self.sub_assembly {
            m.serialize_field("sub_assembly", path)?;
        }
        m.serialize_field("products_convention", &self.products_convention)?;
        m.serialize_field("precision", &self.precision)?;
        m.serialize_field("units", &self.units)?;
        let (turning, still): (Vec<_>, Vec<_>) =
            quantity::in_order(|i| i.report).partition(|i| i.turning());
        for info in still {
            quantity::serialize_field(&mut m, info, self.reported(info.quantity))?;
        }
        m.serialize_field("parts", &self.parts)?;
        for info in turning {
            quantity::serialize_field(&mut m, info, self.reported(info.quantity))?;
        }
        if let Some(i) = &self.idealisation {
            m.serialize_field("idealisation", i)?;
        }
        if let Some(u) = &self.uncertainty {
            m.serialize_field("uncertainty", u)?;
        }
        m.serialize_field("error_bounds", &self.error_bounds)?;
        m.serialize_field("rtol", &self.rtol)?;
        m.serialize_field("accuracy_warnings", &self.accuracy_warnings)?;
        // Written only when there are some: a plausible file's JSON is
        // as before.
        if !self.warnings.is_empty() {
            m.serialize_field("warnings", &self.warnings)?;
        }
        if !self.assemblies.is_empty() {
            m.serialize_field("assemblies", &self.assemblies)?;
        }
        m.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::Products;
    use crate::analysis::summary::{Accuracy, summarize};
    use crate::diag::Source;
    use crate::model::Model;

    /// A turning body, with every value `report` can write.
    fn turning_box() -> Summary {
        let text = "[[part]]\nshape = \"box\"\nmass = 2\nsize = [1, 2, 3]\ncenter = [1, 0, 0]\n[analysis]\nabout = [0, 1, 0]\nomega = [1, 2, 3]\nalpha = [0, 0, 1]\n";
        let model = Model::parse(&Source::new("f.toml", text)).unwrap();
        summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            &Accuracy::default(),
        )
        .unwrap()
    }

    #[test]
    fn a_summary_holds_a_value_for_each_quantity_the_table_reports_and_a_bound_for_each_it_bounds()
    {
        let s = turning_box();
        for info in &crate::quantity::QUANTITIES {
            let q = info.quantity;
            assert_eq!(
                s.reported(q).is_some(),
                info.report.is_some(),
                "{}",
                info.key
            );
            assert_eq!(
                s.error_bounds.of(q).is_some(),
                info.bound.is_some(),
                "{}",
                info.key
            );
        }
    }

    /// Read back by serde_json's parser; the keys' order is pinned by the
    /// JSON in tests/cmd.
    #[test]
    fn the_json_has_each_reported_key_with_its_shape_and_no_other_quantity() {
        let s = turning_box();
        let text = crate::output::json_line(&s);
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let bounds = &v["error_bounds"];
        for info in &crate::quantity::QUANTITIES {
            let (key, n) = (info.key, info.layout.count());
            let count = |x: &serde_json::Value| match x {
                serde_json::Value::Number(_) => 1,
                serde_json::Value::Array(a) => {
                    a.iter().map(|r| r.as_array().map_or(1, Vec::len)).sum()
                }
                other => panic!("{key}: {other}"),
            };
            assert_eq!(v.get(key).is_some(), info.report.is_some(), "{key}");
            assert_eq!(bounds.get(key).is_some(), info.bound.is_some(), "{key}");
            if info.report.is_some() {
                assert_eq!(count(&v[key]), n, "{key}");
            }
            if info.bound.is_some() {
                let per_axis = if info.layout == crate::quantity::Layout::Axes {
                    3
                } else {
                    n
                };
                assert_eq!(count(&bounds[key]), per_axis, "{key}");
            }
        }
        assert!(v["equal_moments"].is_array() && v["equal_moments_ref"].is_array());
    }
}
