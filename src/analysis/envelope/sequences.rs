//! The envelope held against a file's states: the base, each case, and
//! each leg of `sequences` (a path between two cases, their parameters
//! moving linearly), for `check` (`add_to`) and the chart (`legs`).
//!
//! A point of a path is the case's body made again with the parameters
//! at t (`analysis::cases::load_with`): the file converted as a file with
//! those values would be, so the path's ends are the two cases exactly.
//! A parameter only one of the cases gives moves from its value there to
//! the file's (`Model::file_params`).

use super::{PathCheck, check_path};
use crate::analysis::check::{FileResult, Status, Validity};
use crate::analysis::summary::Summary;
use crate::analysis::{Loaded, Settings, cases};
use crate::diag::{Diagnostic, shorten};
use crate::expr::Value;
use crate::model::Model;
use crate::model::case::{Case, value_like};

/// One leg of a sequence: the cases it joins, how it was checked, and
/// its points (coordinate m, mass kg) for drawing.
#[derive(Debug, Clone)]
pub struct Leg {
    pub from: String,
    pub to: String,
    pub check: PathCheck,
    pub curve: Vec<(f64, f64)>,
}

/// Each leg of each sequence, in order; none without `[envelope]`.
pub fn legs(loaded: &Loaded, settings: &Settings) -> Result<Vec<Leg>, Diagnostic> {
    let model = &loaded.model;
    let Some(env) = &model.envelope else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for seq in &env.sequences {
        for pair in seq.windows(2) {
            let find = |n: &str| model.cases.iter().find(|c| c.name == n);
            // `Model::parse` checked every name; a name not found is a
            // model that did not come from the file.
            let (Some(a), Some(b)) = (find(pair[0].get_ref()), find(pair[1].get_ref())) else {
                continue;
            };
            out.push(leg(loaded, settings, env.axis, a, b)?);
        }
    }
    Ok(out)
}

/// The path from case `a` to case `b`.
fn leg(
    loaded: &Loaded,
    settings: &Settings,
    axis: usize,
    a: &Case,
    b: &Case,
) -> Result<Leg, Diagnostic> {
    let mut names: Vec<String> = (a.params.iter().chain(&b.params))
        .map(|p| p.name.clone())
        .collect();
    names.sort();
    names.dedup();
    let file = Model::file_params(&loaded.source, &settings.includes, &names)?;
    let end = |c: &Case, i: usize| -> Option<Value> {
        (c.params.iter().find(|p| p.name == names[i]))
            .map(|p| p.value)
            .or(file[i])
    };
    // Each parameter's two ends (a parameter neither the file nor the
    // other case defines stays at the one value given).
    let ends: Vec<(Value, f64, f64)> = (0..names.len())
        .filter_map(|i| {
            let (va, vb) = (end(a, i), end(b, i));
            let like = va.or(vb)?;
            let si = |v: Option<Value>| v.map(|v| v.in_units(crate::units::Factor::ONE));
            let (sa, sb) = (si(va), si(vb));
            let (sa, sb) = (sa.or(sb)?, sb.or(sa)?);
            Some((like, sa, sb))
        })
        .collect();
    let eval = |t: f64| -> Result<(f64, f64), Diagnostic> {
        let values: Vec<(String, Value)> = (names.iter().zip(&ends))
            .map(|(n, (like, sa, sb))| (n.clone(), value_like(like, sa + t * (sb - sa))))
            .collect();
        let at = cases::load_with(loaded.source.clone(), settings, Some(&a.name), &values)
            .map_err(|d| {
                d.note(format!(
                    "on the path from case `{}` to case `{}`, {} of the way",
                    shorten(&a.name),
                    shorten(&b.name),
                    super::num(t)
                ))
            })?;
        let s = &at.summary;
        let row = s.axes[axis];
        let x = (0..3).map(|j| row[j] * s.center_of_mass[j]).sum::<f64>();
        Ok((s.mass, s.mass * x))
    };
    let env = loaded
        .model
        .envelope
        .as_ref()
        .expect("invariant: legs only with an envelope");
    let (check, curve) = check_path(&env.points, eval)?;
    Ok(Leg {
        from: a.name.clone(),
        to: b.name.clone(),
        check,
        curve,
    })
}

/// `check`'s envelope checks added to the file's result `r`: the base,
/// each case in file order, each leg; a failure makes the file failed.
pub fn add_to(r: &mut FileResult, loaded: &Loaded, settings: &Settings) -> Result<(), Diagnostic> {
    let Some(env) = &loaded.model.envelope else {
        return Ok(());
    };
    let u = super::Shown::of(loaded.model.units);
    let (_, each) = cases::each(loaded.source.clone(), loaded.model.clone(), settings)?;
    let mut points: Vec<(String, String, &Summary)> =
        vec![("base".into(), "base".into(), &loaded.summary)];
    for (name, l) in &each {
        let shown = shorten(name);
        points.push((
            format!("case {shown}"),
            format!("case `{shown}`"),
            &l.summary,
        ));
    }
    let mut found = Vec::new();
    for (label, who, s) in points {
        if let Some(p) = &s.envelope {
            found.push(Validity {
                name: format!("envelope: {label}").into(),
                failure: super::point_failure(env, &who, p, &u),
            });
        }
    }
    for leg in legs(loaded, settings)? {
        let (a, b) = (shorten(&leg.from), shorten(&leg.to));
        found.push(Validity {
            name: format!("envelope: sequence {a} → {b}").into(),
            failure: super::path_failure(env, &a, &b, &leg.check, &u),
        });
    }
    if found.iter().any(|v| v.failure.is_some()) && r.status == Status::Ok {
        r.status = Status::Failed;
    }
    r.validity.extend(found);
    Ok(())
}
