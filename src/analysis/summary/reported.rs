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
        match q.info().formed.predicted() {
            Some(p) => self.predicted.as_deref()?.reported(p),
            None => self.values.get(q),
        }
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
        if let Some(a) = &self.axle_loads {
            m.serialize_field("axle_loads", a)?;
        }
        if let Some(e) = &self.envelope {
            m.serialize_field("envelope_margin", &e.margin)?;
            if let Some(mac) = e.mac {
                m.serialize_field("center_of_mass_mac", &mac)?;
            }
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

    /// A turning and moving body, with every value `report` can write.
    fn turning_box() -> Summary {
        let text = "[[part]]\nshape = \"box\"\nmass = 2\nsize = [1, 2, 3]\ncenter = [1, 0, 0]\n[analysis]\nabout = [0, 1, 0]\nomega = [1, 2, 3]\nalpha = [0, 0, 1]\nvelocity = [3, -1, 2]\n";
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

    /// The typed fields are copies of the table's entries, value and bound.
    #[test]
    fn each_typed_field_is_its_quantitys_value_and_bound_in_the_table() {
        let s = turning_box();
        let b = &s.error_bounds;
        let same = |q: Quantity, value: Value, bound: Option<Value>| {
            let json = |v: Option<Value>| serde_json::to_string(&v).unwrap();
            assert_eq!(json(s.reported(q)), json(Some(value)), "{q:?}");
            assert_eq!(json(b.of(q)), json(bound), "{q:?}");
        };
        use Value::{Axes, Rows, Scalar, Triple};
        same(Quantity::Mass, Scalar(s.mass), Some(Scalar(b.mass)));
        let com = Some(Triple(&b.center_of_mass));
        same(Quantity::CenterOfMass, Triple(&s.center_of_mass), com);
        let point = Some(Triple(&b.reference_point));
        same(Quantity::ReferencePoint, Triple(&s.reference_point), point);
        let offset = Some(Triple(&b.center_of_mass_ref));
        same(
            Quantity::CenterOfMassRef,
            Triple(&s.center_of_mass_ref),
            offset,
        );
        same(Quantity::ReportAxes, Rows(&s.axes), None);
        let i = Some(Rows(&b.inertia_com));
        same(Quantity::InertiaCom, Rows(&s.inertia_com), i);
        let i = Some(Rows(&b.inertia_ref));
        same(Quantity::InertiaRef, Rows(&s.inertia_ref), i);
        let m = Some(Triple(&b.principal_moments));
        same(Quantity::PrincipalMoments, Triple(&s.principal_moments), m);
        let m = Some(Triple(&b.principal_moments_ref));
        same(
            Quantity::PrincipalMomentsRef,
            Triple(&s.principal_moments_ref),
            m,
        );
        let a = Axes(&s.principal_axes, &s.equal_moments);
        same(Quantity::PrincipalAxes, a, Some(Triple(&b.principal_axes)));
        let a = Axes(&s.principal_axes_ref, &s.equal_moments_ref);
        same(
            Quantity::PrincipalAxesRef,
            a,
            Some(Triple(&b.principal_axes_ref)),
        );
        let k = Some(Triple(&b.radii_of_gyration));
        same(Quantity::RadiiOfGyration, Triple(&s.radii_of_gyration), k);
        let k = Some(Triple(&b.radii_of_gyration_axes));
        same(
            Quantity::RadiiOfGyrationAxes,
            Triple(&s.radii_of_gyration_axes),
            k,
        );
        let k = Some(Triple(&b.radii_of_gyration_axes_ref));
        let v = Triple(&s.radii_of_gyration_axes_ref);
        same(Quantity::RadiiOfGyrationAxesRef, v, k);
        let (w, a) = (s.omega.unwrap(), s.alpha.unwrap());
        same(Quantity::Omega, Triple(&w), None);
        same(Quantity::Alpha, Triple(&a), None);
        let (h, eh) = (s.angular_momentum.unwrap(), b.angular_momentum.unwrap());
        same(Quantity::AngularMomentum, Triple(&h), Some(Triple(&eh)));
        let (t, et) = (s.kinetic_energy.unwrap(), b.kinetic_energy.unwrap());
        same(Quantity::KineticEnergy, Scalar(t), Some(Scalar(et)));
        let (m, em) = (s.euler_moment.unwrap(), b.euler_moment.unwrap());
        same(Quantity::EulerMoment, Triple(&m), Some(Triple(&em)));
        // The equal moments too (the JSON of a set of axes is its rows).
        assert_eq!(
            s.values.equal(Quantity::PrincipalAxes).unwrap(),
            s.equal_moments
        );
        let equal = s.values.equal(Quantity::PrincipalAxesRef).unwrap();
        assert_eq!(equal, s.equal_moments_ref);
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
