//! One serializable summary of a body, in SI, that every output format
//! renders: `output::report` serializes it as the documented JSON contract
//! and prints it for people in the file's units.

pub mod accuracy;
mod axes;
mod cut_outs;
mod formed;
mod reported;
mod rows;

pub use accuracy::{Accuracy, AccuracyWarning, PrecisionChoice};

pub use super::errors::{Blame, Contribution, SummaryError};
pub use rows::{Assemblies, AssemblyRow, PartRow, Parts, Row, Summing, deferred};

use super::Products;
use super::ideal;
use crate::bounds;
use crate::compose::{self, Precision, Principal};
use crate::la::Vector3;
use crate::mass::inertia_of_rows;
use crate::model::{Analysis, Model};
use crate::numeric::{DD, M3, Real};
use crate::part::SiFactors;
use crate::quantity::{Info, QUANTITIES, Quantity, Table, unit};
use crate::units::Dim;
use crate::units::FileUnits;
use serde::Serialize;

/// Version of the JSON contract: bumped only if a key changes meaning.
/// Keys may be added; none is ever renamed or removed.
pub const FORMAT_VERSION: u32 = 1;

/// The version of massprop, which every JSON document carries
/// (`massprop_version`) beside `format_version`.
pub const MASSPROP_VERSION: &str = env!("CARGO_PKG_VERSION");

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

/// The SI units of a body's mass, length and inertia: the `units` object
/// of the JSON outputs that give only those (`budget`'s, `diff`'s), and
/// the first three of `SiUnits`. One definition of each unit's name.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct BodyUnits {
    pub mass: &'static str,
    pub length: &'static str,
    pub inertia: &'static str,
}

/// Each the unit of a quantity of the table (`quantity::Info::unit`).
pub const BODY_UNITS: BodyUnits = BodyUnits {
    mass: unit(Quantity::Mass),
    length: unit(Quantity::CenterOfMass),
    inertia: unit(Quantity::InertiaCom),
};

const SI_UNITS: SiUnits = SiUnits {
    mass: BODY_UNITS.mass,
    length: BODY_UNITS.length,
    inertia: BODY_UNITS.inertia,
    angular_velocity: unit(Quantity::Omega),
    angular_acceleration: unit(Quantity::Alpha),
    angular_momentum: unit(Quantity::AngularMomentum),
    energy: unit(Quantity::KineticEnergy),
    moment: unit(Quantity::EulerMoment),
};

#[derive(Debug, Clone, Serialize)]
pub struct PartSummary {
    pub name: String,
    pub shape: crate::shapes::Shape,
    pub mass: f64,
    /// Fraction of the total mass, 0 to 1.
    pub mass_fraction: f64,
    pub center_of_mass: [f64; 3],
    /// The part's share of each principal moment about the centre of mass
    /// (0 to 1; the shares of all parts sum to 1); `None` (null) where the
    /// moment is zero. See `ideal::shares`.
    pub principal_moment_share: [Option<f64>; 3],
    /// The sub-assemblies the part is in, outermost first (`include`);
    /// empty for the file's own parts.
    pub assembly: Vec<String>,
}

/// A sub-assembly (`include`): the sum of its parts. SI.
#[derive(Debug, Clone, Serialize)]
pub struct AssemblySummary {
    /// The path of sub-assembly names, outermost first; the last is its own.
    pub path: Vec<String>,
    pub parts: usize,
    pub mass: f64,
    pub mass_fraction: f64,
    pub center_of_mass: [f64; 3],
    /// The sum of its parts' shares of each principal moment.
    pub principal_moment_share: [Option<f64>; 3],
}

/// Everything `report` prints, in SI. Its JSON (`Serialize`, below) is
/// written by the quantity table: each quantity under its key, in its
/// place (`quantity::Info::report`); the other fields under their names.
#[derive(Debug, Clone)]
pub struct Summary {
    pub format_version: u32,
    /// The massprop that computed it (`MASSPROP_VERSION`).
    pub massprop_version: &'static str,
    /// The part file, as named on the command line (`<stdin>` for standard
    /// input); absent for a summary not made from a file.
    pub source: Option<String>,
    /// The file's `name`; with `--only`, the sub-assembly's.
    pub name: Option<String>,
    /// With `--only`: the path of the sub-assembly reported, outermost
    /// first.
    pub sub_assembly: Option<Vec<String>>,
    pub products_convention: Products,
    /// The arithmetic used (`--precision`).
    pub precision: Precision,
    pub units: SiUnits,
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub reference_point: [f64; 3],
    /// The centre of mass from the reference point, c − p, in the report
    /// axes (zero when the point is the centre).
    pub center_of_mass_ref: [f64; 3],
    /// The report axes: rows are they in the file's frame (`axes`; the
    /// identity for the file's own). Tensors, principal axes, radii about
    /// the axes, ω, H, α and M are in them; `center_of_mass` and
    /// `reference_point` are points in the file's frame.
    pub axes: [[f64; 3]; 3],
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
    /// √(I_xx/m), √(I_yy/m), √(I_zz/m): about the x, y and z axes through
    /// the centre of mass (k_zz is plane motion's radius of gyration).
    pub radii_of_gyration_axes: [f64; 3],
    /// The same about the axes through the reference point.
    pub radii_of_gyration_axes_ref: [f64; 3],
    /// A row per part, made as it is written (`Parts::each`).
    pub parts: Parts,
    pub omega: Option<[f64; 3]>,
    pub angular_momentum: Option<[f64; 3]>,
    pub kinetic_energy: Option<f64>,
    pub alpha: Option<[f64; 3]>,
    pub euler_moment: Option<[f64; 3]>,
    /// The static loads on two axles (`[analysis] axles`, `axles`).
    pub axle_loads: Option<super::axles::AxleLoads>,
    /// The centre of mass against `[envelope]`, if the file gives one.
    pub envelope: Option<super::envelope::Placed>,
    /// The principal moments with thin plates and slender rods made solid;
    /// present only when a part gives its `thickness` or `diameter`.
    pub idealisation: Option<ideal::Idealisation>,
    /// The uncertainty from the file's tolerances (`--uncertainty`).
    pub uncertainty: Option<super::sigma::Uncertainty>,
    /// How far each value may lie from the exact value for the file's
    /// numbers, for the arithmetic used (`bounds`): absolute, SI.
    pub error_bounds: bounds::ErrorBounds,
    /// The accuracy asked for (`--rtol`), relative.
    pub rtol: f64,
    /// The values whose bound exceeds `rtol` in the arithmetic used
    /// (`accuracy`); empty when every value meets it.
    pub accuracy_warnings: Vec<AccuracyWarning>,
    /// The plausibility warnings (`analysis::plausible`), set by `load`.
    pub warnings: Vec<super::plausible::Warning>,
    /// The sub-assemblies (`include`), parents before children; absent
    /// when there are none.
    pub assemblies: Assemblies,
    /// The `--precision` asked for (`precision` is the one used).
    pub requested: PrecisionChoice,
    /// Whether a reference point was given (else it is the centre of mass).
    pub reference_given: bool,
    /// The file's units, for the table.
    pub file_units: FileUnits,
    /// Every quantity's value, by its row of `quantity::QUANTITIES`
    /// (`Summary::reported` reads it; the typed fields above are copies
    /// of the quantities reported when the JSON contract was fixed, for the
    /// library's users and the outputs that lay one out); the predicted
    /// body's are its own summary's.
    pub values: Table,
    /// The predicted body's summary (basic mass and growth,
    /// `analysis::budget`), made by `load` only for a file that expects
    /// something of it (`predicted_mass`, …).
    pub predicted: Option<Box<Summary>>,
}

fn finite(v: &[f64], what: &'static str, blame: Blame) -> Result<(), SummaryError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(SummaryError::NotFinite { what, blame })
    }
}

/// A value every body has (its row needs nothing).
fn must<T>(v: Option<T>) -> T {
    v.expect("invariant: a quantity that needs nothing is formed for every body")
}

/// Compose the model's parts and derive everything reported. `analysis`
/// (the file's, with command-line overrides applied; file units) gives the
/// reference point and ω, α.
///
/// NOTE: everything after composition (the shift to the reference point, the
/// conversion to SI by exact factors, H, T and M) is done in double-double
/// from the composed body and rounded once, whatever the precision: it costs
/// nothing next to reading the file, and T = ½ ωᵀIω of a body spinning about
/// its slender axis would otherwise be a difference of large numbers.
pub fn summarize(
    model: &Model,
    analysis: &Analysis,
    products: Products,
    accuracy: &Accuracy,
) -> Result<Summary, SummaryError> {
    accuracy::summarize(model, analysis, products, accuracy)
}

/// `summarize` in one arithmetic, with the error bounds of every value.
fn summarize_in(
    model: &Model,
    analysis: &Analysis,
    products: Products,
    precision: Precision,
) -> Result<Summary, SummaryError> {
    let (body, error) = compose::compose_model(model, precision);
    let u = model.units;
    let factors = SiFactors::of(u);
    let (f_mass, f_length) = (factors.mass, factors.length);
    let f_inertia = u.factor(Dim::INERTIA).dd();
    let mass_dd = body.mass * f_mass;
    let mass = mass_dd.f64();
    finite(&[mass], "total mass", Blame::Parts(Contribution::Mass))?;
    cut_outs::leave_a_body(model, &body, mass)?;
    let com = body.center_of_mass.map(|c| (c * f_length).f64());
    finite(
        &com,
        "centre of mass",
        Blame::Parts(Contribution::FirstMoment),
    )?;
    let about: [DD; 3] = match analysis.about {
        Some(a) => [a.x, a.y, a.z].map(DD::of),
        None => body.center_of_mass,
    };
    let reference = about.map(|c| (c * f_length).f64());
    finite(&reference, "reference point", Blame::About)?;
    let c_ref_file = body.second_moment_about(&about);
    // In the report axes from here on (`axes`): the second moments turned
    // once; ω and α are given in them.
    let turn = analysis
        .axes
        .as_ref()
        .map(|o| axes::Turn::new(o, precision));
    let turned = |c: &M3<DD>| turn.as_ref().map_or(*c, |t| t.tensor(c));
    let (c_com, c_ref) = (turned(&body.second_moment), turned(&c_ref_file));
    let offset: [DD; 3] = std::array::from_fn(|j| body.center_of_mass[j] - about[j]);
    let com_ref_dd = turn.as_ref().map_or(offset, |t| t.vector(&offset));
    let com_ref = com_ref_dd.map(|x| (x * f_length).f64());
    finite(
        &com_ref,
        "centre of mass from the reference point",
        Blame::About,
    )?;
    let si = |c: &M3<DD>| inertia_of_rows(c).map(|r| r.map(|x| x * f_inertia));
    let (i_com, i_ref) = (si(&c_com), si(&c_ref));
    let round = |m: &M3<DD>| m.map(|r| r.map(DD::f64));
    let (i_com_f, i_ref_f) = (round(&i_com), round(&i_ref));
    finite(
        i_com_f.as_flattened(),
        "inertia about the centre of mass",
        Blame::Parts(Contribution::SecondMoment),
    )?;
    finite(
        i_ref_f.as_flattened(),
        "inertia about the reference point",
        Blame::About,
    )?;
    // The second moments are finite here, so `None` means a principal
    // moment beyond f64 (the solver converges on finite input).
    let not_finite = SummaryError::NotFinite {
        what: "principal moments about the centre of mass",
        blame: Blame::Parts(Contribution::SecondMoment),
    };
    let p_com = compose::principal_bounded(&c_com, precision).ok_or(not_finite.clone())?;
    // The parts' shares and the idealisation project the parts, which are
    // in the file's axes: the same principal axes, found there.
    let p_file = match &turn {
        None => p_com.clone(),
        Some(_) => compose::principal_bounded(&body.second_moment, precision).ok_or(not_finite)?,
    };
    let p_ref = compose::principal_bounded(&c_ref, precision).ok_or(SummaryError::NotFinite {
        what: "principal moments about the reference point",
        blame: Blame::About,
    })?;
    let moments = |p: &Principal| p.moments.map(|m| (m * f_inertia).f64());
    let (m_com, m_ref) = (moments(&p_com), moments(&p_ref));
    finite(
        &m_com,
        "principal moments about the centre of mass",
        Blame::Parts(Contribution::SecondMoment),
    )?;
    finite(
        &m_ref,
        "principal moments about the reference point",
        Blame::About,
    )?;

    let times = |m: &M3<DD>, v: &Vector3<f64>| -> [DD; 3] {
        std::array::from_fn(|i| (0..3).fold(DD::of(0.0), |acc, j| acc + m[i][j].mul_f64(v[j])))
    };
    let h = analysis.omega.map(|w| times(&i_ref, &w));
    // The body moving (`motion`): what v adds to H and T about the point.
    let motion = analysis.velocity.zip(analysis.omega).map(|(v, w)| {
        super::motion::motion(&super::motion::Inputs {
            mass: mass_dd,
            r: com_ref_dd.map(|x| x * f_length),
            i_com: &i_com,
            omega: [w.x, w.y, w.z],
            v: [v.x, v.y, v.z].map(|x| DD::of(x) * f_length),
        })
    });
    let t = analysis.omega.zip(h).map(|(w, h)| {
        let t = (0..3)
            .fold(DD::of(0.0), |acc, i| acc + h[i].mul_f64(w[i]))
            .mul_f64(0.5);
        match &motion {
            Some(m) => (t + m.t_extra).f64(),
            None => t.f64(),
        }
    });
    let h_about = h.map(|h| match &motion {
        Some(m) => std::array::from_fn(|j| h[j] + m.h_extra[j]),
        None => h,
    });
    let m = analysis
        .alpha
        .zip(analysis.omega.zip(h))
        .map(|(a, (w, h))| {
            let ia = times(&i_ref, &a);
            // ω × H
            let cross = |i: usize| {
                let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                h[k].mul_f64(w[j]) - h[j].mul_f64(w[k])
            };
            std::array::from_fn::<f64, 3, _>(|i| (ia[i] + cross(i)).f64())
        });

    let inputs = {
        let f = |x: DD| x.f64();
        let c_about_file = c_ref_file.map(|r| r.map(f));
        let offset_f = offset.map(f);
        // About the centre of mass itself (no point given), the exact
        // value is the exact C: the error is the composer's alone.
        let e_ref = match analysis.about {
            Some(_) => error.second_moment_about(f(body.mass), offset_f, &c_about_file),
            None => error.second_moment,
        };
        // The offset c − p: exactly 0 without a point; else the centre's
        // error and the double-double difference's rounding.
        let e_offset: [f64; 3] = match analysis.about {
            Some(_) => std::array::from_fn(|j| {
                error.center_of_mass[j] + crate::part::error::U_DD * offset_f[j].abs()
            }),
            None => [0.0; 3],
        };
        // Into the report axes.
        let (e_com, e_ref, e_offset) = match &turn {
            None => (error.second_moment, e_ref, e_offset),
            Some(t) => (
                t.tensor_bound(&error.second_moment, &body.second_moment.map(|r| r.map(f))),
                t.tensor_bound(&e_ref, &c_about_file),
                t.vector_bound(&e_offset, &offset_f),
            ),
        };
        let c_com = c_com.map(|r| r.map(f));
        let c_about = c_ref.map(|r| r.map(f));
        // The f64 solver takes C about the point rounded to f64.
        let e_solved = match precision {
            Precision::Standard => std::array::from_fn(|j| {
                std::array::from_fn(|k| e_ref[j][k] + bounds::U64 * c_about[j][k].abs())
            }),
            Precision::Extended => e_ref,
        };
        formed::Inputs {
            error,
            f_mass: f(f_mass),
            f_length: f(f_length),
            f_inertia: f(f_inertia),
            offset: e_offset,
            tensor: [e_com, e_ref],
            solved: [e_com, e_solved],
            second_moment: [c_com, c_about],
        }
    };
    let shares = ideal::Shares::new(&body, &p_file);
    let formed = formed::Body {
        analysis,
        products,
        precision,
        mass_dd,
        f_inertia,
        mass,
        com,
        reference,
        com_ref,
        frame: turn.as_ref().map_or(
            std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j)))),
            |t| t.rows,
        ),
        inertia: [i_com, i_ref],
        inertia_f: [i_com_f, i_ref_f],
        principal: [p_com, p_ref],
        moments: [m_com, m_ref],
        h: h_about.map(|h| h.map(DD::f64)),
        t,
        m,
        motion,
        bounds: inputs,
        eigen: Default::default(),
    };

    // Each quantity as its row says, in the order of `Formed` (which of
    // two failures is reported); what the body turning adds after the
    // idealisation.
    let mut values = Table::default();
    let mut order: Vec<&Info> = QUANTITIES.iter().collect();
    order.sort_by_key(|i| i.formed);
    let (turning, still): (Vec<&Info>, Vec<&Info>) = order.into_iter().partition(|i| i.turning());
    for info in still {
        values.set(info.quantity, formed.value(info.formed)?);
    }
    let idealisation = ideal::idealisation(model, &body, &p_file, precision, f_inertia)?;
    for info in turning {
        values.set(info.quantity, formed.value(info.formed)?);
    }
    let mut error_bounds = Table::default();
    for info in &QUANTITIES {
        error_bounds.set(info.quantity, formed.bound(info.formed));
    }

    // The axle loads: the centre of mass's coordinate along the report
    // axis, the axles' positions in SI.
    let axle_loads = match &analysis.axles {
        None => None,
        Some(a) => {
            let row = formed.frame[a.axis];
            let along = (0..3).map(|j| row[j] * com[j]).sum::<f64>();
            let g = analysis.g.unwrap_or(super::axles::G);
            let loads = super::axles::loads(mass, along, a.front, a.rear, g);
            Some(loads.ok_or(SummaryError::NotFinite {
                what: "axle load",
                blame: Blame::Parts(Contribution::Mass),
            })?)
        }
    };
    // The envelope: the same coordinate along its axis, against the mass.
    let envelope = match &model.envelope {
        None => None,
        Some(e) => {
            let row = formed.frame[e.axis];
            let along = (0..3).map(|j| row[j] * com[j]).sum::<f64>();
            let placed = super::envelope::place(e, along, mass);
            let bad = |v: Option<f64>| v.is_some_and(|x| !x.is_finite());
            // NOTE: a centre of mass far out overflows its distance to an
            // edge or its % MAC; said, not printed as null.
            let what = if bad(placed.margin) {
                Some("envelope margin")
            } else if bad(placed.mac) {
                Some("centre of mass in % MAC")
            } else {
                None
            };
            if let Some(what) = what {
                return Err(SummaryError::NotFinite {
                    what,
                    blame: Blame::Parts(Contribution::Mass),
                });
            }
            Some(placed)
        }
    };
    let made_from = std::sync::Arc::new(rows::RowData {
        model: model.clone(),
        factors,
        shares,
        mass,
    });
    Ok(Summary {
        format_version: FORMAT_VERSION,
        massprop_version: MASSPROP_VERSION,
        source: None,
        name: model.name.clone(),
        sub_assembly: None,
        products_convention: products,
        units: SI_UNITS,
        precision,
        parts: Parts(made_from.clone()),
        assemblies: Assemblies(made_from),
        idealisation,
        uncertainty: None,
        error_bounds: bounds::ErrorBounds::new(error_bounds),
        rtol: 0.0,
        accuracy_warnings: Vec::new(),
        warnings: Vec::new(),
        requested: PrecisionChoice::Auto,
        reference_given: analysis.about.is_some(),
        file_units: model.units,
        predicted: None,
        mass: must(values.scalar(Quantity::Mass)),
        center_of_mass: must(values.triple(Quantity::CenterOfMass)),
        reference_point: must(values.triple(Quantity::ReferencePoint)),
        center_of_mass_ref: must(values.triple(Quantity::CenterOfMassRef)),
        axes: must(values.rows(Quantity::ReportAxes)),
        inertia_com: must(values.rows(Quantity::InertiaCom)),
        inertia_ref: must(values.rows(Quantity::InertiaRef)),
        principal_moments: must(values.triple(Quantity::PrincipalMoments)),
        principal_axes: must(values.rows(Quantity::PrincipalAxes)),
        equal_moments: must(values.equal(Quantity::PrincipalAxes)),
        principal_moments_ref: must(values.triple(Quantity::PrincipalMomentsRef)),
        principal_axes_ref: must(values.rows(Quantity::PrincipalAxesRef)),
        equal_moments_ref: must(values.equal(Quantity::PrincipalAxesRef)),
        radii_of_gyration: must(values.triple(Quantity::RadiiOfGyration)),
        radii_of_gyration_axes: must(values.triple(Quantity::RadiiOfGyrationAxes)),
        radii_of_gyration_axes_ref: must(values.triple(Quantity::RadiiOfGyrationAxesRef)),
        omega: values.triple(Quantity::Omega),
        angular_momentum: values.triple(Quantity::AngularMomentum),
        kinetic_energy: values.scalar(Quantity::KineticEnergy),
        alpha: values.triple(Quantity::Alpha),
        euler_moment: values.triple(Quantity::EulerMoment),
        axle_loads,
        envelope,
        values,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Source;

    fn blamed(text: &str) -> String {
        let source = Source::new("f.toml", text);
        let model = Model::parse(&source).unwrap();
        let e = summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            &Accuracy::default(),
        )
        .unwrap_err();
        e.diagnostic(&model, &model.analysis, &source).to_string()
    }

    const POINT: &str = "[[part]]\nshape = \"point\"\n";

    #[test]
    fn an_overflowing_sum_names_the_largest_contributor_wherever_it_is() {
        // Masses: the largest is named, first or last.
        let a = format!("{POINT}name = \"a\"\nmass = 1e308\ncenter = [0, 0, 0]\n");
        let b = format!("{POINT}name = \"b\"\nmass = 1.7e308\ncenter = [0, 0, 0]\n");
        for text in [format!("{a}{b}"), format!("{b}{a}")] {
            let d = blamed(&text);
            assert!(d.contains("the total mass overflows"), "{d}");
            assert!(d.contains("`b` contributes the most"), "{d}");
        }
        // Moments: m·d² about the centre of mass, not about the origin, and
        // not the mass alone: `far` is lighter but farther out.
        let near = format!("{POINT}name = \"near\"\nmass = 2e100\ncenter = [-1e104, 0, 0]\n");
        let far = format!("{POINT}name = \"far\"\nmass = 1e100\ncenter = [1e104, 0, 0]\n");
        for text in [format!("{near}{far}"), format!("{far}{near}")] {
            let d = blamed(&text);
            assert!(
                d.contains("inertia about the centre of mass overflows"),
                "{d}"
            );
            assert!(d.contains("`far` contributes the most"), "{d}");
        }
    }

    #[test]
    fn an_overflow_through_the_analysis_points_at_its_key() {
        let body = format!("{POINT}mass = 1e100\ncenter = [0, 0, 0]\n");
        let d = blamed(&format!("{body}[analysis]\nabout = [1e105, 0, 0]\n"));
        assert!(
            d.starts_with("f.toml:6:9: error: the inertia about the reference point"),
            "{d}"
        );
        let boxed = "[[part]]\nshape = \"box\"\nmass = 1e100\nsize = [1e50, 1e50, 1e50]\ncenter = [0, 0, 0]\n";
        let d = blamed(&format!("{boxed}[analysis]\nomega = [1e300, 0, 0]\n"));
        assert!(
            d.starts_with("f.toml:7:9: error: the angular momentum"),
            "{d}"
        );
        let d = blamed(&format!(
            "{boxed}[analysis]\nomega = [0, 0, 1]\nalpha = [1e300, 0, 0]\n"
        ));
        assert!(d.starts_with("f.toml:8:9: error: the Euler moment"), "{d}");
    }

    /// A 1 kg box, 1 m a side, at the origin, and cut-outs (name, mass,
    /// x of the centre) of 0.1 m boxes.
    fn box_with_cut_outs(cuts: &[(&str, f64, &str)]) -> String {
        let mut text =
            "[[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n"
                .to_string();
        for (name, mass, x) in cuts {
            text += &format!(
                "[[part]]\nname = \"{name}\"\nshape = \"box\"\nmass = {mass}\nsize = [0.1, 0.1, 0.1]\ncenter = [{x}, 0, 0]\nremove = true\n"
            );
        }
        text
    }

    /// The body is not physical however far the cut-out is: also where its
    /// second moment overflows f64 (which ended in "the principal-axis
    /// solver did not converge").
    #[test]
    fn a_far_cut_out_is_named_as_leaving_a_body_that_is_not_physical() {
        for x in ["30", "1e8", "1e160", "1e300"] {
            let d = blamed(&box_with_cut_outs(&[("far", 0.001, x)]));
            assert!(
                d.starts_with("f.toml:6:1: error: the body is not physical: its second moment along (1.000, 0.000, 0.000) is negative; the cut-out `far` removes more material along it than the body has\n"),
                "{x}: {d}"
            );
            assert!(d.contains("^^^^^^^^ this cut-out"), "{d}");
        }
    }

    #[test]
    fn of_several_cut_outs_the_one_that_removes_the_most_is_named() {
        // `in` lies inside the box; `out` beyond it; `far` farther out but
        // so light that it removes less along x than `out`.
        let text =
            box_with_cut_outs(&[("in", 0.01, "0.2"), ("out", 0.05, "2"), ("far", 1e-5, "20")]);
        let d = blamed(&text);
        assert!(
            d.contains(
                "the 3 cut-outs remove more material along it than the body has, `out` the most\n"
            ),
            "{d}"
        );
        assert!(d.starts_with("f.toml:13:1:"), "{d}");
        let d = blamed(&box_with_cut_outs(&[("a", 0.5, "0"), ("b", 0.6, "0")]));
        assert!(
            d.contains("of parts: the 2 cut-outs remove all of the material, `b` the most\n"),
            "{d}"
        );
    }

    #[test]
    fn a_cut_out_in_a_sub_assembly_is_pointed_at_by_its_include() {
        let dir = std::env::temp_dir().join(format!("massprop-cut-out-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("arm.toml"),
            box_with_cut_outs(&[("hole", 0.001, "1e200")]),
        )
        .unwrap();
        let text = "[[part]]\nname = \"arm\"\ninclude = \"arm.toml\"\norigin = [0, 0, 0]\n";
        let top = dir.join("top.toml");
        std::fs::write(&top, text).unwrap();
        let source = Source::new(top.to_str().unwrap(), text);
        let model = Model::parse(&source).unwrap();
        let e = summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            &Accuracy::default(),
        );
        let d = e
            .unwrap_err()
            .diagnostic(&model, &model.analysis, &source)
            .to_string();
        std::fs::remove_dir_all(&dir).ok();
        assert!(d.contains(":1:1: error: the body is not physical"), "{d}");
        assert!(d.contains("the cut-out `arm / hole` removes more"), "{d}");
        assert!(
            d.contains("^^^^^^^^ the sub-assembly `arm` with the cut-out\n"),
            "{d}"
        );
    }

    #[test]
    fn cut_outs_inside_the_body_leave_a_body() {
        let text = box_with_cut_outs(&[("a", 0.01, "0.2"), ("b", 0.01, "-0.3")]);
        let model = Model::parse(&Source::new("f.toml", text.as_str())).unwrap();
        let s = summarize(
            &model,
            &model.analysis,
            Products::Tensor,
            &Accuracy::default(),
        );
        assert!(s.is_ok(), "{s:?}");
    }
}
