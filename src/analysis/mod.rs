//! The load pipeline every command runs, and what it derives from a body:
//!
//! read (`io`) → parse and validate (`model`) → `--only` → resolve the
//! analysis once (the file's `[analysis]`, the command line's overrides and
//! every rule across keys and flags) → compose and summarize (`summary`).
//!
//! `report`, `check`, `check --bless`, `diff` and `materials` all go through
//! `load` or its stages, so a file one command accepts no other rejects,
//! and the other way round. The commands add only what is theirs: `check`
//! evaluates expectations (`check`), `diff` compares two summaries (`diff`).

pub mod axles;
pub mod bless;
pub mod budget;
pub mod cases;
pub mod check;
pub mod check_run;
pub mod diff;
pub mod envelope;
pub mod errors;
pub mod ideal;
pub mod link;
pub mod motion;
pub mod plausible;
pub mod search;
pub mod sigma;
pub mod summary;
pub mod uncertainty;

use crate::diag::{Diagnostic, Source};
use crate::model::{self, Analysis, Model};
use crate::units::Dim;
use serde::Serialize;
use summary::Summary;

/// How products of inertia are shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Products {
    /// Tensor entries: I_xy = −∫xy dm (the default).
    #[default]
    Tensor,
    /// CAD and Meriam convention: I_xy = +∫xy dm.
    Positive,
}

/// `[analysis]` values given on the command line, as typed: x,y,z with
/// optional units, overriding the file's.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Overrides {
    pub about: Option<String>,
    pub omega: Option<String>,
    pub alpha: Option<String>,
    /// `--velocity`: the reference point's velocity (`motion`).
    pub velocity: Option<String>,
    /// `--axes`, as typed (`model::parse_flag_axes`).
    pub axes: Option<String>,
}

/// What a command asks of the pipeline.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    pub products: Products,
    /// `--precision` and `--rtol`.
    pub accuracy: summary::Accuracy,
    /// Report one sub-assembly alone (`--only`).
    pub only: Option<String>,
    /// Where includes may come from, and what a piped file's are relative
    /// to (`--include-root`, `--base-dir`).
    pub includes: crate::model::Includes,
    pub overrides: Overrides,
    /// Propagate the file's tolerances (`--uncertainty`).
    pub uncertainty: Option<uncertainty::Method>,
    /// Compose the predicted body of a file that asks for it (`check`:
    /// `predicted_*` expectations, `[budget] limit`); the commands that
    /// show no predicted value leave it out.
    pub predicted: bool,
}

/// A part file read, validated, resolved and summarized.
#[derive(Debug, Clone)]
pub struct Loaded {
    pub source: Source,
    pub model: Model,
    /// The analysis the summary was made with: the file's, overridden.
    pub analysis: Analysis,
    pub summary: Summary,
}

/// Read a part file (`-`: standard input) and run it through the pipeline.
pub fn load(path: &str, settings: &Settings) -> Result<Loaded, Diagnostic> {
    load_source(crate::io::read_source(path)?, settings)
}

/// `load` of a source already read.
pub fn load_source(source: Source, settings: &Settings) -> Result<Loaded, Diagnostic> {
    load_source_reading(source, settings, &mut Vec::new())
}

/// `load_source`, adding to `read` every file included, valid or not
/// (`model::Model::parse_reading`).
pub fn load_source_reading(
    source: Source,
    settings: &Settings,
    read: &mut Vec<std::path::PathBuf>,
) -> Result<Loaded, Diagnostic> {
    let model = Model::parse_reading(&source, &settings.includes, read)?;
    load_model(source, model, settings)
}

/// The rest of the pipeline for a model already made (a part file parsed,
/// or a robot description's body, `robot::body`): `--only`, the analysis
/// resolved, the summary.
pub fn load_model(
    source: Source,
    mut model: Model,
    settings: &Settings,
) -> Result<Loaded, Diagnostic> {
    let only = match &settings.only {
        Some(name) => Some(model.only(name).map_err(Diagnostic::plain)?),
        None => None,
    };
    let analysis = resolve(&model, &source, &settings.overrides)?;
    let mut summary = summary::summarize(&model, &analysis, settings.products, &settings.accuracy)
        .map_err(|e| e.diagnostic(&model, &analysis, &source))?;
    if let Some(path) = &only {
        summary.name = path.last().cloned();
        summary.sub_assembly = Some(path.clone());
    }
    summary.source = Some(source.name.clone());
    summary.warnings = plausible::warnings(&model, &source);
    // The predicted body where the command reads it, or the uncertainty
    // of a whole weight-budgeted body (the limit is the whole body's).
    let budgeted = budget::composes_predicted(&model);
    let predicted =
        if budgeted && (settings.predicted || (settings.uncertainty.is_some() && only.is_none())) {
            Some(budget::predicted(&model, &analysis, settings, &source)?)
        } else {
            None
        };
    if let Some(method) = settings.uncertainty {
        let whole = predicted.as_ref().filter(|_| only.is_none());
        summary.uncertainty = Some(uncertainty::propagate(
            &model, &analysis, &summary, whole, method, &source,
        )?);
    }
    if settings.predicted {
        summary.predicted = predicted.map(Box::new);
    }
    Ok(Loaded {
        source,
        model,
        analysis,
        summary,
    })
}

/// `--axes`, read (`model::rotation::parse_flag_axes`); its error names the
/// flag. `check` reads it once before any file, as a flag's error is no
/// file's.
pub fn flag_axes(text: &str) -> Result<crate::rotation::Orientation, Diagnostic> {
    model::rotation::parse_flag_axes(text)
        .map_err(|e| Diagnostic::plain(format!("invalid value {text:?} for `--axes`: {e}")))
}

/// The analysis to run: the file's `[analysis]` with the command line's
/// values in place of the file's, and every rule that spans keys and flags.
/// The one place such rules live.
pub fn resolve(
    model: &Model,
    source: &Source,
    overrides: &Overrides,
) -> Result<Analysis, Diagnostic> {
    let mut analysis = model.analysis.clone();
    let flag = |text: &Option<String>, name: &str, dim: Dim| {
        text.as_deref()
            .map(|t| {
                model::parse_flag_vector(t, model.units, dim).map_err(|e| {
                    Diagnostic::plain(format!("invalid value {t:?} for `--{name}`: {e}"))
                })
            })
            .transpose()
    };
    // A flag's value has no place in the file: its span goes.
    if let Some(v) = flag(&overrides.about, "about", Dim::LENGTH)? {
        analysis.about = Some(v);
        analysis.about_span = None;
    }
    if let Some(v) = flag(&overrides.omega, "omega", Dim::ANGULAR_VELOCITY)? {
        analysis.omega = Some(v);
        analysis.omega_span = None;
    }
    if let Some(v) = flag(&overrides.alpha, "alpha", Dim::ANGULAR_ACCELERATION)? {
        analysis.alpha = Some(v);
        analysis.alpha_span = None;
    }
    if let Some(v) = flag(&overrides.velocity, "velocity", Dim::VELOCITY)? {
        analysis.velocity = Some(v);
        analysis.velocity_span = None;
    }
    if let Some(t) = &overrides.axes {
        analysis.axes = Some(flag_axes(t)?);
    }
    // α without ω: point at the file's `alpha` unless it came from the flag.
    if analysis.alpha.is_some() && analysis.omega.is_none() {
        return Err(match (&analysis.alpha_span, &overrides.alpha) {
            (Some(span), None) => source
                .error(span.clone(), "`alpha` needs `omega`: the Euler moment depends on both")
                .help("give `omega` here (`report` also takes `--omega`); for a body starting from rest, `omega = [0, 0, 0]`"),
            _ => Diagnostic::plain("`--alpha` needs ω: give `--omega` or `[analysis].omega`"),
        });
    }
    // A velocity without ω: the same rule, for the same reason (v̄ = v_O
    // + ω × r). A body translating alone gives `omega = [0, 0, 0]`.
    if analysis.velocity.is_some() && analysis.omega.is_none() {
        return Err(match (&analysis.velocity_span, &overrides.velocity) {
            (Some(span), None) => source
                .error(span.clone(), "`velocity` needs `omega`: the mass centre's velocity is v + ω × r")
                .help("give `omega` here (`report` also takes `--omega`); for a body translating without turning, `omega = [0, 0, 0]`"),
            _ => Diagnostic::plain("`--velocity` needs ω: give `--omega` or `[analysis].omega`"),
        });
    }
    Ok(analysis)
}
