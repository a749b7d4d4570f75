//! The weight statement (`massprop budget`): each part's basic mass, its
//! mass growth allowance by design maturity, the predicted mass (basic +
//! growth) per group and sub-group, the margin against a not-to-exceed
//! limit, and the predicted body.
//!
//! The predicted body is the basic body and, for each part that grows, a
//! point mass g = basic × allowance (`growth`, the one place it is formed)
//! at that part's centroid. It is composed as any body is: a model of the
//! file's items and those points (`predicted_model`), summarized by
//! `summary::summarize`, so its values carry the same certified error
//! bounds, report axes and products convention as a report's.

use super::summary::{self, FORMAT_VERSION, MASSPROP_VERSION, Summary};
use super::{Loaded, Products, Settings};
use crate::diag::{Diagnostic, Source};
use crate::model::budget::{Maturity, Tag};
use crate::model::expect::{Bound, Target};
use crate::model::{Analysis, Event, Item, Model};
use crate::numeric::{DD, Real, Sum};
use crate::part::{MassSpec, Part, Place, Placed, SiFactors, Spec};
use crate::rotation::Orientation;
use crate::shapes::Shape;
use serde::Serialize;

/// A part's mass growth: its basic mass times its maturity's allowance
/// (a fraction). The one place a growth is formed: the statement's rows
/// and the predicted body's point masses both come from it. A cut-out's
/// basic mass is negative, and so is its growth: the part it is cut from
/// grows net of the hole.
pub fn growth(basic: f64, allowance: f64) -> f64 {
    basic * allowance
}

/// One group of the statement (SI): a subsystem or a sub-group, the sum of
/// its own parts and its sub-groups'.
#[derive(Debug, Clone, Serialize)]
pub struct Group {
    /// Names, outermost first: `["propulsion", "tanks"]`; `[]` for the
    /// parts that have no group.
    pub path: Vec<String>,
    /// Its parts, copies counted, its sub-groups' included.
    pub parts: usize,
    pub basic_mass: f64,
    pub growth_mass: f64,
    /// growth / basic; `None` (null) where the basic mass is zero.
    pub growth_fraction: Option<f64>,
    pub predicted_mass: f64,
    /// Of the total predicted mass; `None` (null) where that is zero.
    pub share: Option<f64>,
}

/// The totals of the statement (SI).
#[derive(Debug, Clone, Serialize)]
pub struct Total {
    pub parts: usize,
    /// The basic body's mass (the composite's).
    pub basic_mass: f64,
    /// The sum of every part's growth.
    pub growth_mass: f64,
    pub growth_fraction: Option<f64>,
    /// The predicted body's mass (the composite's): basic + growth.
    pub predicted_mass: f64,
}

/// The parts with no maturity: zero growth, said so a weight engineer sees
/// what is not yet classified. A cut-out counts as any part, by its signed
/// (negative) basic mass.
#[derive(Debug, Clone, Serialize)]
pub struct Unclassified {
    pub parts: usize,
    pub basic_mass: f64,
}

/// Where the limit comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LimitSource {
    /// `[budget] limit`.
    Budget,
    /// `[expect] mass = { max = … }`.
    ExpectMassMax,
}

/// The predicted mass against the not-to-exceed limit (SI).
#[derive(Debug, Clone, Serialize)]
pub struct Margin {
    pub source: LimitSource,
    pub limit: f64,
    /// limit − predicted mass.
    pub margin: f64,
    /// margin / limit.
    pub margin_fraction: f64,
    /// margin ≥ 0.
    pub met: bool,
}

/// A body's mass, centre of mass and inertia about it, with their error
/// bounds (SI; the tensor in the report axes, `products_convention`).
#[derive(Debug, Clone, Serialize)]
pub struct Body {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub inertia_com: [[f64; 3]; 3],
    pub error_bounds: BodyBounds,
}

#[derive(Debug, Clone, Serialize)]
pub struct BodyBounds {
    pub mass: f64,
    pub center_of_mass: [f64; 3],
    pub inertia_com: [[f64; 3]; 3],
}

impl Body {
    fn of(s: &Summary) -> Body {
        Body {
            mass: s.mass,
            center_of_mass: s.center_of_mass,
            inertia_com: s.inertia_com,
            error_bounds: BodyBounds {
                mass: s.error_bounds.mass,
                center_of_mass: s.error_bounds.center_of_mass,
                inertia_com: s.error_bounds.inertia_com,
            },
        }
    }
}

/// The weight statement. Field names are the JSON keys (docs/budget.md).
#[derive(Debug, Clone, Serialize)]
pub struct Statement {
    pub format_version: u32,
    pub massprop_version: &'static str,
    pub source: String,
    pub name: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sub_assembly: Option<Vec<String>>,
    /// The arithmetic of the basic body and of the predicted body.
    pub precision: crate::compose::Precision,
    pub predicted_precision: crate::compose::Precision,
    pub products_convention: Products,
    pub units: summary::BodyUnits,
    /// The report axes, rows in the file's frame (`report`'s `axes`).
    pub axes: [[f64; 3]; 3],
    /// Parents before children, each group's sub-groups in the order they
    /// first appear in the file.
    pub groups: Vec<Group>,
    pub total: Total,
    pub no_maturity: Unclassified,
    /// Absent when no limit is given (or with `--only`: the limit is the
    /// whole body's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub limit: Option<Margin>,
    /// The file has a limit, not applied because of `--only` (for the
    /// table's wording).
    #[serde(skip)]
    pub limit_with_only: bool,
    pub basic: Body,
    pub predicted: Body,
    /// Both bodies' values whose bound exceeds `rtol` (`report`'s).
    pub accuracy_warnings: Vec<summary::AccuracyWarning>,
    /// The file's units, for the table.
    #[serde(skip)]
    pub file_units: crate::units::FileUnits,
    /// The `--precision` asked for and `--rtol`, for the table.
    #[serde(skip)]
    pub requested: summary::PrecisionChoice,
    #[serde(skip)]
    pub rtol: f64,
}

/// A group being summed.
struct Node {
    path: Vec<String>,
    children: Vec<usize>,
    parts: usize,
    basic: Sum,
    growth: Sum,
}

/// What one walk of the body finds: the groups (a tree, `nodes[..roots]`
/// reached through `roots`), the unclassified parts, the total growth and
/// the growth's point masses.
#[derive(Default)]
struct Walked {
    nodes: Vec<Node>,
    roots: Vec<usize>,
    index: std::collections::HashMap<Vec<String>, usize>,
    unclassified: (usize, Sum),
    growth: Sum,
    points: Vec<Part>,
}

impl Walked {
    /// The node of `path`, made (with its parents) where new.
    fn node(&mut self, path: &[String]) -> usize {
        if let Some(&i) = self.index.get(path) {
            return i;
        }
        let parent = match path {
            [] | [_] => None,
            [rest @ .., _] => Some(self.node(rest)),
        };
        let i = self.nodes.len();
        self.nodes.push(Node {
            path: path.to_vec(),
            children: Vec::new(),
            parts: 0,
            basic: Sum::default(),
            growth: Sum::default(),
        });
        match parent {
            Some(p) => self.nodes[p].children.push(i),
            None => self.roots.push(i),
        }
        self.index.insert(path.to_vec(), i);
        i
    }
}

/// A part's maturity: its own, else the innermost sub-assembly's that
/// gives one (`stack`: the tags of the sub-assemblies entered, outermost
/// first). The one rule, for the statement and the uncertainty.
fn maturity_of<'a>(stack: &'a [Option<Tag>], own: Option<&'a Tag>) -> Option<&'a Maturity> {
    own.and_then(|t| t.maturity.as_ref()).or_else(|| {
        stack
            .iter()
            .rev()
            .flatten()
            .find_map(|t| t.maturity.as_ref())
    })
}

/// Each part's growth allowance (a fraction; 0 without a maturity), by
/// its index in the body (`walk::Leaf::index`): what the predicted body
/// adds to it, for `uncertainty`.
pub fn allowances(model: &Model) -> Vec<f64> {
    let mut out = Vec::with_capacity(model.count);
    let mut stack: Vec<Option<Tag>> = Vec::new();
    model.each_event(&mut |e| match e {
        Event::Enter(inc) => stack.push(inc.tag.as_deref().cloned()),
        Event::Exit => {
            stack.pop();
        }
        Event::Part(leaf) => out.push(maturity_of(&stack, leaf.tag).map_or(0.0, |m| m.allowance)),
    });
    out
}

/// Walk the body once: each part's group (its sub-assemblies' groups, then
/// its own) and maturity (its own, else the innermost sub-assembly's that
/// gives one), its basic mass and growth, in SI.
fn walk(model: &Model) -> Walked {
    let factors = SiFactors::of(model.units);
    let mut w = Walked::default();
    // The tags of the sub-assemblies entered, outermost first (copied: a
    // walk's events live only as long as each call).
    let mut stack: Vec<Option<Tag>> = Vec::new();
    let mut path: Vec<String> = Vec::new();
    model.each_event(&mut |e| match e {
        Event::Enter(inc) => stack.push(inc.tag.as_deref().cloned()),
        Event::Exit => {
            stack.pop();
        }
        Event::Part(leaf) => {
            path.clear();
            let groups = stack.iter().flatten().chain(leaf.tag);
            for t in groups {
                path.extend(t.group.iter().flatten().cloned());
            }
            let maturity = maturity_of(&stack, leaf.tag);
            let p = leaf.part;
            // Signed: a cut-out's is negative, and so is its growth.
            let basic = p.mass_si(&factors);
            let grown = match maturity {
                Some(m) => {
                    let g = growth(p.mass::<f64>(), m.allowance);
                    if g != 0.0 {
                        w.points.push(point(p, g));
                    }
                    (DD::of(g) * factors.mass).f64()
                }
                None => {
                    w.unclassified.0 += 1;
                    w.unclassified.1.add(basic);
                    0.0
                }
            };
            w.growth.add(grown);
            // Its group and each group above it; the parts with no group
            // are a group of their own (`[]`), not every group's parent.
            let mut at = path.len();
            loop {
                let i = w.node(&path[..at]);
                let n = &mut w.nodes[i];
                n.parts += 1;
                n.basic.add(basic);
                n.growth.add(grown);
                if at <= 1 {
                    break;
                }
                at -= 1;
            }
        }
    });
    w
}

/// The point mass `g` (file units, signed) at `p`'s centroid: a cut-out's
/// growth is negative, a removed point (`remove = true`), so the part it
/// is cut from grows net of the hole.
///
/// NOTE: the point stands at the centroid rounded to f64; its `placed.at`
/// bounds how far that lies from the exact centroid (the centroid's own
/// error model and this rounding), so the predicted body's error bounds
/// cover it as they cover a part placed through a frame.
fn point(p: &Part, g: f64) -> Part {
    let c = p.centroid();
    let center = c.map(DD::f64);
    let error = crate::part::error::centroid_error(&p.spec, &center);
    let at = (0..3)
        .map(|j| error[j] + (c[j] - DD::of(center[j])).f64().abs())
        .fold(0.0, f64::max);
    Part {
        // Whose growth it is, for a message (`growth_error`).
        name: p.name.clone(),
        named: false,
        shape: Shape::Point,
        spec: Spec {
            mass: MassSpec::Given(g.abs()),
            place: Place::Centered {
                center,
                extent: [0.0; 3],
                orientation: Orientation::Identity,
            },
            removed: g < 0.0,
            placed: Placed::new(0.0, at),
        },
        assembly: Vec::new(),
        span: p.span.clone(),
        tol: None,
        material: None,
    }
}

/// The predicted body as a model: the file's items and the growth's point
/// masses after them.
fn predicted_model(model: &Model, points: Vec<Part>) -> Model {
    let count = model.count + points.len();
    let mut items: Vec<Item> = Vec::with_capacity(model.items.len() + points.len());
    items.extend(model.items.iter().cloned());
    items.extend(points.into_iter().map(|part| Item::Part {
        part,
        real: None,
        copies: None,
        tag: None,
    }));
    Model {
        items: std::sync::Arc::new(items),
        count,
        ..model.clone()
    }
}

/// The predicted body's summary, as `summary::summarize` makes any body's.
fn summarize_predicted(
    model: &Model,
    points: Vec<Part>,
    analysis: &Analysis,
    settings: &Settings,
    source: &Source,
) -> Result<Summary, Diagnostic> {
    // The largest growth, for a message: whose (the point carries its
    // part's name) and how much, in kg.
    let factors = SiFactors::of(model.units);
    let largest = points
        .iter()
        .map(|p| (&p.name, p.mass_si(&factors)))
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .map(|(name, g)| (crate::diag::shorten(name), g));
    let predicted = predicted_model(model, points);
    summary::summarize(&predicted, analysis, settings.products, &settings.accuracy)
        .map_err(|e| growth_error(&e, largest, source))
}

/// Why the predicted body cannot be formed. The basic body was formed, so
/// it is the growth that breaks it: the message names the growth and the
/// largest one, never a part as the cause (the part is valid; its growth's
/// point has no place in the file of its own).
fn growth_error(
    e: &summary::SummaryError,
    largest: Option<(String, f64)>,
    source: &Source,
) -> Diagnostic {
    let what = match e {
        summary::SummaryError::NotFinite { what, .. } => {
            format!("the {what} of the predicted body overflows the range of f64")
        }
        summary::SummaryError::NotPhysical { .. } => {
            "the predicted body is not physical: the cut-outs' growth removes more than the body has".to_string()
        }
    };
    let largest = match largest {
        Some((name, g)) => format!("; the largest growth is `{name}`'s, {g:e} kg"),
        None => String::new(),
    };
    Diagnostic::file(
        &source.name,
        format!("{what} once its growth is added (the basic body's does not{largest})"),
    )
    .help("a part's growth is its basic mass × its maturity's allowance (`[growth]`); are the allowances, and the masses' units, right?")
}

/// The predicted body's summary of a model (`load` makes it for a file
/// that expects something of it).
pub fn predicted(
    model: &Model,
    analysis: &Analysis,
    settings: &Settings,
    source: &Source,
) -> Result<Summary, Diagnostic> {
    summarize_predicted(model, walk(model).points, analysis, settings, source)
}

/// Whether `load` composes the predicted body: the file expects something
/// of it (`predicted_*`), or has a `[budget] limit`, which `check` holds
/// against it (and `budget` needs it in any case).
///
/// (`load` composes it only where `Settings::predicted` asks: `check`;
/// `budget` composes its own with the statement.)
pub fn composes_predicted(model: &Model) -> bool {
    model.budget.is_some() || model.expect.iter().any(|c| c.target.is_predicted())
}

/// The values of `s`, and of its predicted body where it has one, whose
/// error bound exceeds `rtol`: the predicted body's prefixed `predicted.`.
pub fn accuracy_warnings(s: &Summary) -> Vec<summary::AccuracyWarning> {
    let mut out = s.accuracy_warnings.clone();
    if let Some(p) = &s.predicted {
        out.extend(
            p.accuracy_warnings
                .iter()
                .map(|w| summary::AccuracyWarning {
                    quantity: format!("predicted.{}", w.quantity),
                    message: format!("the predicted body's {}", w.message),
                    ..w.clone()
                }),
        );
    }
    out
}

/// The not-to-exceed limit: `[budget] limit`, else `[expect] mass`'s `max`.
fn limit(model: &Model) -> Option<(LimitSource, f64)> {
    if let Some(l) = &model.budget {
        return Some((LimitSource::Budget, l.mass));
    }
    model.expect.iter().find_map(|c| match (c.target, c.bound) {
        (Target::Mass, Bound::Range { max: Some(m), .. }) => Some((LimitSource::ExpectMassMax, m)),
        _ => None,
    })
}

/// The weight statement of a loaded part file.
pub fn statement(loaded: Loaded, settings: &Settings) -> Result<Statement, Diagnostic> {
    let Loaded {
        source,
        model,
        analysis,
        mut summary,
    } = loaded;
    let mut w = walk(&model);
    let predicted = match summary.predicted.take() {
        Some(p) => *p,
        None => summarize_predicted(
            &model,
            std::mem::take(&mut w.points),
            &analysis,
            settings,
            &source,
        )?,
    };
    let total_predicted = predicted.mass;
    let ratio = |a: f64, b: f64| (b != 0.0).then(|| a / b);
    let mut groups = Vec::with_capacity(w.nodes.len());
    // Depth first, each level in order of first appearance.
    let mut todo: Vec<usize> = w.roots.iter().rev().copied().collect();
    while let Some(i) = todo.pop() {
        let n = &w.nodes[i];
        let (basic, grown) = (n.basic.value(), n.growth.value());
        let predicted_mass = basic + grown;
        groups.push(Group {
            path: n.path.clone(),
            parts: n.parts,
            basic_mass: basic,
            growth_mass: grown,
            growth_fraction: ratio(grown, basic),
            predicted_mass,
            share: ratio(predicted_mass, total_predicted),
        });
        todo.extend(n.children.iter().rev());
    }
    let growth_mass = w.growth.value();
    let given = limit(&model);
    let limit_with_only = settings.only.is_some() && given.is_some();
    let limit = match settings.only {
        Some(_) => None,
        None => given,
    }
    .map(|(source, limit)| {
        let margin = limit - total_predicted;
        Margin {
            source,
            limit,
            margin,
            margin_fraction: margin / limit,
            met: margin >= 0.0,
        }
    });
    summary.predicted = Some(Box::new(predicted));
    let accuracy_warnings = accuracy_warnings(&summary);
    let predicted = summary
        .predicted
        .as_deref()
        .expect("invariant: the predicted body was just put in place");
    Ok(Statement {
        format_version: FORMAT_VERSION,
        massprop_version: MASSPROP_VERSION,
        source: source.name.clone(),
        name: summary.name.clone(),
        sub_assembly: summary.sub_assembly.clone(),
        precision: summary.precision,
        predicted_precision: predicted.precision,
        products_convention: summary.products_convention,
        units: summary::BODY_UNITS,
        axes: summary.axes,
        groups,
        total: Total {
            parts: model.count,
            basic_mass: summary.mass,
            growth_mass,
            growth_fraction: ratio(growth_mass, summary.mass),
            predicted_mass: total_predicted,
        },
        no_maturity: Unclassified {
            parts: w.unclassified.0,
            basic_mass: w.unclassified.1.value(),
        },
        limit,
        limit_with_only,
        basic: Body::of(&summary),
        predicted: Body::of(predicted),
        accuracy_warnings,
        file_units: model.units,
        requested: summary.requested,
        rtol: summary.rtol,
    })
}
