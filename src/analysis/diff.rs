//! What `diff OLD NEW` compares: the mass properties of two part files,
//! each loaded by the one pipeline (tensor convention), as absolute and
//! relative changes in SI, and what happened to each part (matched by
//! name). The contract (table, JSON keys, exit statuses, the
//! relative-change rule) is docs/diff.md; `output::diff` prints it.

use super::Loaded;
use super::summary::Summary;
use crate::diag::Diagnostic;
use crate::numeric::norm;
use crate::part::PartSi;
use crate::quantity::{Layout, QUANTITIES, Quantity, Shown, UPPER, component};
use crate::shapes::Shape;
use crate::units::Dim;
use serde::Serialize;
use std::collections::{HashMap, VecDeque};

/// Version of the diff JSON contract (docs/diff.md): bumped only if a key
/// changes meaning. Keys may be added; none is ever renamed or removed.
pub const FORMAT_VERSION: u32 = 1;

/// One part file, loaded, with its parts in SI.
pub struct Side {
    pub loaded: Loaded,
    /// The model's parts in SI, in its order.
    pub parts: Vec<PartView>,
}

/// What `diff` compares of a part: its name and shape, and its SI view.
pub struct PartView {
    pub name: String,
    pub shape: Shape,
    pub si: PartSi,
}

impl Side {
    pub fn of(loaded: Loaded) -> Side {
        let model = &loaded.model;
        let factors = crate::part::SiFactors::of(model.units);
        // NOTE: every part of both files is in memory (its name and SI
        // view): parts are matched by name across the files.
        let mut parts = Vec::with_capacity(model.count);
        model.each_part(&mut |l| {
            let p = l.part;
            parts.push(PartView {
                name: p.name.clone(),
                shape: p.shape(),
                si: p.si_in(&factors),
            });
        });
        Side { loaded, parts }
    }
}

/// One compared value, SI. Field names are the JSON keys.
#[derive(Debug, Clone, Serialize)]
pub struct QuantityDiff {
    /// `mass`, `center_of_mass.x`, `inertia_com.xy`, `principal_moments.1`.
    pub quantity: String,
    pub old: f64,
    pub new: f64,
    pub abs_change: f64,
    /// `abs_change` divided by the quantity's scale; `None` when the scale is
    /// zero (the quantity is zero in both files) or the ratio overflows.
    pub rel_change: Option<f64>,
    pub changed: bool,
    /// How the table names it.
    #[serde(skip)]
    pub label: String,
    /// Its dimension, for its display unit.
    #[serde(skip)]
    pub dim: Dim,
}

/// A part present in one file only: its position there (0-based).
#[derive(Debug, Clone, Copy)]
pub struct Lone {
    pub index: usize,
}

/// What changed of a part matched by name, serialised by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Change {
    Shape,
    Mass,
    Centroid,
    SecondMoment,
}

/// A part matched by name whose properties moved beyond the tolerance.
#[derive(Debug, Clone)]
pub struct PartChange {
    pub old: usize,
    pub new: usize,
    /// In the order shape, mass, centroid, second moment.
    pub what: Vec<Change>,
}

#[derive(Debug, Clone, Default)]
pub struct PartDiff {
    /// Parts of the new file only, in its order.
    pub added: Vec<Lone>,
    /// Parts of the old file only, in its order.
    pub removed: Vec<Lone>,
    /// In the old file's order.
    pub changed: Vec<PartChange>,
}

impl PartDiff {
    pub fn is_empty(&self) -> bool {
        self.added.is_empty() && self.removed.is_empty() && self.changed.is_empty()
    }
}

/// Two files compared.
pub struct Diff {
    pub old: Side,
    pub new: Side,
    /// Relative tolerance (`--tol`).
    pub tol: f64,
    pub quantities: Vec<QuantityDiff>,
    pub parts: PartDiff,
    /// A mass property changed beyond the tolerance, or (with `--names`)
    /// a part was added, removed or changed: the exit status.
    pub changed: bool,
}

/// The mass properties `diff` compares, SI: of a summary, or of a robot
/// description's link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Props {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    /// Ascending.
    pub principal_moments: [f64; 3],
    /// About the centre of mass, tensor convention.
    pub inertia_com: [[f64; 3]; 3],
    /// The principal axes (rows) and those of them the moments determine
    /// (`check::determined`); `None` where not compared.
    pub principal_axes: Option<([[f64; 3]; 3], [bool; 3])>,
}

impl Props {
    /// Quantity `q`'s numbers (row-major for a matrix), if `Props` holds it.
    fn value(&self, q: Quantity) -> Option<Vec<f64>> {
        match q {
            Quantity::Mass => Some(vec![self.mass]),
            Quantity::CenterOfMass => Some(self.center_of_mass.to_vec()),
            Quantity::PrincipalMoments => Some(self.principal_moments.to_vec()),
            Quantity::InertiaCom => Some(flat(&self.inertia_com).to_vec()),
            Quantity::PrincipalAxes => self.principal_axes.as_ref().map(|(r, _)| flat(r).to_vec()),
            Quantity::InertiaRef
            | Quantity::RadiiOfGyration
            | Quantity::RadiiOfGyrationAxes
            | Quantity::AngularMomentum
            | Quantity::KineticEnergy
            | Quantity::PredictedMass
            | Quantity::PredictedCenterOfMass
            | Quantity::PredictedInertiaCom
            | Quantity::ReferencePoint
            | Quantity::CenterOfMassRef
            | Quantity::ReportAxes
            | Quantity::PrincipalMomentsRef
            | Quantity::PrincipalAxesRef
            | Quantity::RadiiOfGyrationAxesRef
            | Quantity::Omega
            | Quantity::Alpha
            | Quantity::EulerMoment
            | Quantity::Velocity
            | Quantity::VelocityCom
            | Quantity::LinearMomentum
            | Quantity::AngularMomentumCom
            | Quantity::KineticEnergyTranslational
            | Quantity::KineticEnergyRotational => None,
        }
    }

    /// A part file's, its centre of mass in the file's frame.
    pub fn of(s: &Summary) -> Props {
        Props {
            mass: s.mass,
            center_of_mass: s.center_of_mass,
            principal_moments: s.principal_moments,
            inertia_com: s.inertia_com,
            principal_axes: Some((s.principal_axes, {
                let d = super::check::determined(s);
                std::array::from_fn(|k| d.contains(&k))
            })),
        }
    }
}

/// A part file and a robot description's link compared (`diff --link`):
/// the part file's body in the link frame (its report frame:
/// `commands::export::export_of`) against the link's inertial.
pub struct LinkDiff {
    /// OLD's and NEW's names, as the command line gave them.
    pub old: String,
    pub new: String,
    /// The link compared.
    pub link: String,
    /// The part file's units, in which the table shows values.
    pub file_units: crate::units::FileUnits,
    pub tol: f64,
    pub quantities: Vec<QuantityDiff>,
    pub changed: bool,
}

impl LinkDiff {
    /// Compare `old` with `new` at relative tolerance `tol` (finite, ≥ 0).
    pub fn of(
        (old_name, old): (String, Props),
        (new_name, new): (String, Props),
        link: String,
        file_units: crate::units::FileUnits,
        tol: f64,
    ) -> Result<LinkDiff, Diagnostic> {
        let length = pick(props_length(&old), props_length(&new));
        let quantities = quantities(&old, &new, length, tol)
            .map_err(|d| Diagnostic::plain(format!("{old_name} → {new_name}: {}", d.message())))?;
        let changed = quantities.iter().any(|q| q.changed);
        Ok(LinkDiff {
            old: old_name,
            new: new_name,
            link,
            file_units,
            tol,
            quantities,
            changed,
        })
    }
}

impl Diff {
    /// Compare `old` with `new` at relative tolerance `tol` (finite, ≥ 0);
    /// `names`: the parts' differences count toward `changed` too.
    pub fn of(old: Loaded, new: Loaded, tol: f64, names: bool) -> Result<Diff, Diagnostic> {
        let (old, new) = (Side::of(old), Side::of(new));
        let (os, ns) = (&old.loaded.summary, &new.loaded.summary);
        let length = length_scale(os, ns);
        let quantities = quantities(&Props::of(os), &Props::of(ns), length, tol).map_err(|d| {
            Diagnostic::plain(format!(
                "{} → {}: {}",
                old.loaded.source.name,
                new.loaded.source.name,
                d.message()
            ))
        })?;
        let parts = part_diff(&old.parts, &new.parts, length, tol);
        // NOTE: the parts are matched by name, so a rename is a part removed
        // and one added though no mass property moved: that is reported,
        // and fails only when asked (`--names`).
        let changed = quantities.iter().any(|q| q.changed) || (names && !parts.is_empty());
        Ok(Diff {
            old,
            new,
            tol,
            quantities,
            parts,
            changed,
        })
    }
}

/// The old file's scale, or the new one's when the old is zero.
fn pick(old: f64, new: f64) -> f64 {
    if old > 0.0 { old } else { new }
}

/// The length scale of a body: the larger of the distance of its centre of
/// mass from the origin and its r.m.s. size √(tr C / m) = |k| / √2 (k the
/// principal radii of gyration). NOTE: a position has no natural zero; with
/// the distance alone, a centre of mass at the origin (a symmetric body)
/// would turn every rounding of ~1e-17 m into a 100 % change.
fn body_length(s: &Summary) -> f64 {
    norm(&s.center_of_mass).max(norm(&s.radii_of_gyration) / std::f64::consts::SQRT_2)
}

/// `body_length` of `Props`: √(tr C / m) from the principal moments
/// (tr C = (I1 + I2 + I3)/2), or the distance of the centre alone when
/// the mass is not positive.
fn props_length(p: &Props) -> f64 {
    let tr_c = (p.principal_moments.iter().sum::<f64>() / 2.0).max(0.0);
    let rms = if p.mass > 0.0 {
        (tr_c / p.mass).sqrt()
    } else {
        0.0
    };
    norm(&p.center_of_mass).max(rms)
}

fn length_scale(old: &Summary, new: &Summary) -> f64 {
    pick(body_length(old), body_length(new))
}

fn flat(m: &[[f64; 3]; 3]) -> [f64; 9] {
    std::array::from_fn(|k| m[k / 3][k % 3])
}

/// Compare one value against `scale`. Errors only if the change itself
/// overflows f64 (two huge values of opposite signs).
fn compare(
    quantity: String,
    label: String,
    dim: Dim,
    (old, new): (f64, f64),
    scale: f64,
    tol: f64,
) -> Result<QuantityDiff, Diagnostic> {
    let abs_change = new - old;
    if !abs_change.is_finite() {
        return Err(Diagnostic::plain(format!(
            "the change in `{quantity}` overflows the range of f64; are sizes, masses or offsets in the wrong units?"
        )));
    }
    let rel_change = if scale > 0.0 {
        Some(abs_change / scale).filter(|r| r.is_finite())
    } else {
        None
    };
    let changed = match rel_change {
        Some(r) => r.abs() > tol,
        // Scale zero (then the change is zero too) or a ratio beyond f64.
        None => abs_change != 0.0,
    };
    Ok(QuantityDiff {
        quantity,
        old,
        new,
        abs_change,
        rel_change,
        changed,
        label,
        dim,
    })
}

/// The quantities the table has `diff` show (`quantity::Info::diff`), in
/// its order: mass, centre of mass, principal moments, and the six
/// independent entries of the inertia tensor about the centre of mass
/// (upper triangle).
fn quantities(
    old: &Props,
    new: &Props,
    length: f64,
    tol: f64,
) -> Result<Vec<QuantityDiff>, Diagnostic> {
    let mut out = Vec::new();
    for info in &QUANTITIES {
        let (Some(o), Some(n)) = (old.value(info.quantity), new.value(info.quantity)) else {
            continue;
        };
        let scale = match (info.diff, info.layout) {
            (Shown::No, _) => continue,
            (Shown::Angle, _) => {
                let (Some((o, o_axes)), Some((n, n_axes))) =
                    (&old.principal_axes, &new.principal_axes)
                else {
                    continue;
                };
                // Each axis both files determine: the angle between them
                // (radians, itself the relative change; "old" is 0).
                for k in (0..3).filter(|&k| o_axes[k] && n_axes[k]) {
                    let c = component(info.layout, 3 * k);
                    let angle = super::check::angle_between(&o[k], &n[k]);
                    out.push(compare(
                        format!("{}.{c}", info.key),
                        format!("{}{c}", info.label),
                        info.dim,
                        (0.0, angle),
                        1.0,
                        tol,
                    )?);
                }
                continue;
            }
            (Shown::Position, _) => length,
            (Shown::Own, Layout::Scalar) => pick(o[0].abs(), n[0].abs()),
            (Shown::Own, Layout::Vector | Layout::Ordered | Layout::Matrix | Layout::Axes) => {
                pick(norm(&o), norm(&n))
            }
        };
        let components: Vec<usize> = match info.layout {
            Layout::Scalar | Layout::Vector | Layout::Ordered => (0..info.layout.count()).collect(),
            Layout::Matrix => UPPER.iter().map(|&(_, i, j)| 3 * i + j).collect(),
            Layout::Axes => unreachable!("invariant: axes are shown by angle, above"),
        };
        for k in components {
            let c = component(info.layout, k);
            let name = if c.is_empty() {
                info.key.to_string()
            } else {
                format!("{}.{c}", info.key)
            };
            let label = format!("{}{c}", info.label);
            out.push(compare(name, label, info.dim, (o[k], n[k]), scale, tol)?);
        }
    }
    Ok(out)
}

/// Match parts by name, the k-th part of a name in the old file with the
/// k-th of that name in the new one (unnamed parts are `part N`, so they
/// match by position), and say what was added, removed or changed.
fn part_diff(old: &[PartView], new: &[PartView], length: f64, tol: f64) -> PartDiff {
    let mut unmatched_new: HashMap<&str, VecDeque<usize>> = HashMap::new();
    for (i, p) in new.iter().enumerate() {
        unmatched_new.entry(&p.name).or_default().push_back(i);
    }
    let mut diff = PartDiff::default();
    let mut matched_new = vec![false; new.len()];
    for (i, o) in old.iter().enumerate() {
        match unmatched_new
            .get_mut(o.name.as_str())
            .and_then(|q| q.pop_front())
        {
            Some(j) => {
                matched_new[j] = true;
                let what = part_changes(o, &new[j], length, tol);
                if !what.is_empty() {
                    diff.changed.push(PartChange {
                        old: i,
                        new: j,
                        what,
                    });
                }
            }
            None => diff.removed.push(Lone { index: i }),
        }
    }
    diff.added = (0..new.len())
        .filter(|&j| !matched_new[j])
        .map(|index| Lone { index })
        .collect();
    diff
}

/// Beyond the tolerance: mass relative to the old part's mass (its size, for
/// a cut-out's negative mass); centroid by
/// the distance moved, relative to the body's length scale; second moment
/// (∫ρρᵀ dm about the centroid) by the norm of its change, relative to the
/// old part's (the new one's if the old is zero, as for a point mass).
fn part_changes(o: &PartView, n: &PartView, length: f64, tol: f64) -> Vec<Change> {
    let mut what = Vec::new();
    if o.shape != n.shape {
        what.push(Change::Shape);
    }
    // `!(x <= limit)` also catches a NaN or infinite ratio as a change.
    // |m|: a cut-out's mass is negative.
    if !((n.si.mass - o.si.mass).abs() <= tol * o.si.mass.abs()) {
        what.push(Change::Mass);
    }
    let moved = norm(&(n.si.center - o.si.center).as_array());
    if !(moved <= tol * length) {
        what.push(Change::Centroid);
    }
    let (co, cn) = (o.si.second_moment, n.si.second_moment);
    let scale = pick(norm(co.as_slice()), norm(cn.as_slice()));
    if !(norm((cn - co).as_slice()) <= tol * scale) {
        what.push(Change::SecondMoment);
    }
    what
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_entry_of_a_large_quantity_is_not_a_large_change() {
        // A product of inertia from 1e-18 to 2e-18 on a tensor of size 1.
        let q = compare(
            "q".into(),
            "q".into(),
            Dim::INERTIA,
            (1e-18, 2e-18),
            1.0,
            1e-9,
        )
        .unwrap();
        assert!(!q.changed);
        assert_eq!(q.rel_change, Some(1e-18));
    }

    #[test]
    fn zero_scale_gives_no_relative_change() {
        let q = compare("q".into(), "q".into(), Dim::MASS, (0.0, 0.0), 0.0, 0.0).unwrap();
        assert_eq!(q.rel_change, None);
        assert!(!q.changed);
    }

    #[test]
    fn an_overflowing_ratio_is_a_change_without_a_relative_value() {
        let q = compare(
            "q".into(),
            "q".into(),
            Dim::LENGTH,
            (0.0, 1e300),
            1e-300,
            1.0,
        )
        .unwrap();
        assert_eq!(q.rel_change, None);
        assert!(q.changed);
    }

    #[test]
    fn an_overflowing_change_is_an_error_not_infinity() {
        let e = compare(
            "center_of_mass.x".into(),
            "x".into(),
            Dim::LENGTH,
            (-f64::MAX, f64::MAX),
            f64::MAX,
            1e-9,
        )
        .unwrap_err();
        assert!(e.message().contains("`center_of_mass.x` overflows"), "{e}");
    }
}
