//! Loading cases (`[[case]]`, `model::case`): one case's body run through
//! the pipeline as a plain report's (`load_case`), every case's
//! (`load_all`), and a case's body with parameters passed in
//! (`load_with`, for a path between cases).
//!
//! A case's `Loaded` is exactly what `load_model` makes of the file edited
//! by hand to that case: the same settings (`--only`, `--about`, …), the
//! same summary, its `model.expect` the case's own `expect`.

use super::{Loaded, Settings, load_model};
use crate::diag::{Diagnostic, Source, shorten};
use crate::model::Model;
use crate::model::case::Case;

/// The case `name` of `model` (for `--case`), as a model of its own: the
/// case's body, with the file's list of includes.
pub fn case_model(model: &Model, name: &str) -> Result<Model, Diagnostic> {
    let Some(case) = model.cases.iter().find(|c| c.name == name) else {
        return Err(unknown(model, name));
    };
    Ok(as_file(model, case))
}

/// A case's model with what the file as read carries (`Model::parse`
/// fills in for the file it reads).
fn as_file(model: &Model, case: &Case) -> Model {
    Model {
        included: model.included.clone(),
        texts_read: model.texts_read,
        mesh_warnings: model.mesh_warnings.clone(),
        ..(*case.model).clone()
    }
}

/// `--case NAME` names no case of the file.
fn unknown(model: &Model, name: &str) -> Diagnostic {
    let shown = shorten(name);
    if model.cases.is_empty() {
        return Diagnostic::plain(format!("`--case {shown}`: the file has no `[[case]]`"));
    }
    let names: Vec<String> = (model.cases.iter().take(12))
        .map(|c| format!("`{}`", shorten(&c.name)))
        .collect();
    let more = model.cases.len().saturating_sub(names.len());
    let more = if more > 0 {
        format!(" and {more} more")
    } else {
        String::new()
    };
    Diagnostic::plain(format!(
        "`--case {shown}`: the file has no case of that name (its cases: {}{more})",
        names.join(", ")
    ))
    .suggest(crate::units::suggest(
        name,
        model.cases.iter().map(|c| c.name.as_str()),
    ))
}

/// `case` of the file `base` loaded, through the pipeline as `base` was
/// (its errors say which case).
pub fn load_of(base: &Loaded, case: &Case, settings: &Settings) -> Result<Loaded, Diagnostic> {
    load_model(base.source.clone(), as_file(&base.model, case), settings)
        .map_err(|d| d.note(format!("in case `{}`", shorten(&case.name))))
}

/// The file's case `name`, run through the pipeline as a plain report.
pub fn load_case(source: Source, settings: &Settings, name: &str) -> Result<Loaded, Diagnostic> {
    let model = Model::parse_with(&source, &settings.includes)?;
    let case = case_model(&model, name)?;
    load_model(source, case, settings)
}

/// The base and each case, in file order, each with its name.
pub fn load_all(
    source: Source,
    settings: &Settings,
) -> Result<(Loaded, Vec<(String, Loaded)>), Diagnostic> {
    let model = Model::parse_with(&source, &settings.includes)?;
    each(source, model, settings)
}

/// `load_all` of a model already parsed.
pub fn each(
    source: Source,
    model: Model,
    settings: &Settings,
) -> Result<(Loaded, Vec<(String, Loaded)>), Diagnostic> {
    let mut cases = Vec::with_capacity(model.cases.len());
    let base = load_model(source, model, settings)?;
    for case in &base.model.cases {
        cases.push((case.name.clone(), load_of(&base, case, settings)?));
    }
    Ok((base, cases))
}

/// The body of case `case` (the base for `None`) with the parameters
/// `values` in place of the file's and the case's definitions (and of
/// `--set`'s): for a point of a path between cases that differ only in
/// `params` (each value made by `model::case::value_like` from the
/// cases' `Param::value`s).
pub fn load_with(
    source: Source,
    settings: &Settings,
    case: Option<&str>,
    values: &[(String, crate::expr::Value)],
) -> Result<Loaded, Diagnostic> {
    let model = Model::parse_passing(&source, &settings.includes, &mut Vec::new(), values)?;
    let model = match case {
        Some(name) => case_model(&model, name)?,
        None => model,
    };
    load_model(source, model, settings)
}
