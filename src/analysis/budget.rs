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
use crate::model::expect::Bound;
use crate::model::{Analysis, Event, Item, Model};
use crate::numeric::{DD, Real, Sum};
use crate::part::{MassSpec, Part, Place, Placed, SiFactors, Spec};
use crate::quantity::Quantity;
use crate::rotation::Orientation;
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
///
/// NOTE: a group keeps its own name and its parent's place, not its path:
/// a path of n names is n groups of one name each, however many parts
/// share it (a path per group would cost n² names). JSON writes each
/// group's `path`, made from the parents as it is written (`groups_json`).
#[derive(Debug, Clone)]
pub struct Group {
    /// Its own name, the last of its path; `None` for the parts that have
    /// no group (JSON: `path` `[]`).
    pub name: Option<String>,
    /// Its parent's index in `Statement::groups` (parents come first);
    /// `None` for a subsystem.
    pub parent: Option<usize>,
    /// The names in its path: 1 for a subsystem, 0 for the parts with no
    /// group.
    pub depth: usize,
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

impl Group {
    /// Its path, outermost name first: `["propulsion", "tanks"]`; `[]` for
    /// the parts that have no group. `groups` is the statement's.
    pub fn path<'a>(&'a self, groups: &'a [Group]) -> Vec<&'a str> {
        let mut names = Vec::with_capacity(self.depth);
        let mut at = Some(self);
        while let Some(g) = at {
            names.extend(g.name.as_deref());
            at = g.parent.map(|p| &groups[p]);
        }
        names.reverse();
        names
    }
}

/// `Statement::groups` as JSON: each group's fields with its `path`
/// (docs/budget.md).
fn groups_json<S: serde::Serializer>(groups: &[Group], s: S) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct Shown<'a> {
        path: Vec<&'a str>,
        parts: usize,
        basic_mass: f64,
        growth_mass: f64,
        growth_fraction: Option<f64>,
        predicted_mass: f64,
        share: Option<f64>,
    }
    s.collect_seq(groups.iter().map(|g| Shown {
        path: g.path(groups),
        parts: g.parts,
        basic_mass: g.basic_mass,
        growth_mass: g.growth_mass,
        growth_fraction: g.growth_fraction,
        predicted_mass: g.predicted_mass,
        share: g.share,
    }))
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
    #[serde(serialize_with = "groups_json")]
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

/// A group being summed: its own name and its parent (`Walked::nodes`).
struct Node {
    /// `None`: the parts with no group.
    name: Option<String>,
    parent: Option<usize>,
    depth: usize,
    children: Vec<usize>,
    /// Its own parts, then (`Walked::total`) its sub-groups' too.
    parts: usize,
    basic: Sum,
    growth: Sum,
}

/// What one walk of the body finds: the groups (a tree, `nodes` reached
/// through `roots`; a parent before its children), the unclassified parts,
/// the total growth and the growth's point masses.
///
/// NOTE: nothing here recurses or copies a path: a group is found from its
/// parent by its name (`named`), and the group a tag's path leads to from
/// a group is remembered by the tag's address (`reached`: the model holds
/// every tag for the whole walk), so the copies of a part, and the parts
/// of a file included many times, find their group at once, however deep
/// it is. A part adds to its own group only; `total` adds each group into
/// its parent once, at the end.
#[derive(Default)]
struct Walked {
    nodes: Vec<Node>,
    roots: Vec<usize>,
    /// (parent, or `usize::MAX` for a subsystem; name) → group.
    named: std::collections::HashMap<(usize, String), usize>,
    /// (group, tag's address) → the group its path leads to.
    reached: std::collections::HashMap<(Option<usize>, *const Tag), Option<usize>>,
    /// The parts with no group's node, once one is met.
    no_group: Option<usize>,
    unclassified: (usize, Sum),
    growth: Sum,
    points: Vec<Part>,
}

impl Walked {
    /// A new group, a child of `parent` (or a subsystem).
    fn push(&mut self, name: Option<String>, parent: Option<usize>) -> usize {
        let i = self.nodes.len();
        self.nodes.push(Node {
            name,
            parent,
            depth: parent.map_or(0, |p| self.nodes[p].depth) + 1,
            children: Vec::new(),
            parts: 0,
            basic: Sum::default(),
            growth: Sum::default(),
        });
        match parent {
            Some(p) => self.nodes[p].children.push(i),
            None => self.roots.push(i),
        }
        i
    }

    /// The group `name` under `parent` (or the subsystem), made where new.
    fn child(&mut self, parent: Option<usize>, name: &str) -> usize {
        let key = (parent.unwrap_or(usize::MAX), name.to_string());
        if let Some(&i) = self.named.get(&key) {
            return i;
        }
        let i = self.push(Some(key.1.clone()), parent);
        self.named.insert(key, i);
        i
    }

    /// The group `tag`'s path leads to from `from` (a sub-assembly's
    /// group; `None` at the top): `from` itself if it has no group.
    fn reach(&mut self, from: Option<usize>, tag: Option<&Tag>) -> Option<usize> {
        let Some((tag, names)) = tag.and_then(|t| Some((t, t.group.as_ref()?))) else {
            return from;
        };
        let key = (from, std::ptr::from_ref(tag));
        if let Some(&to) = self.reached.get(&key) {
            return to;
        }
        let mut at = from;
        for name in names {
            at = Some(self.child(at, name));
        }
        self.reached.insert(key, at);
        at
    }

    /// The group of a part whose path leads to `at`: the parts with no
    /// group are a group of their own (`[]`), not every group's parent.
    fn group_of(&mut self, at: Option<usize>) -> usize {
        match (at, self.no_group) {
            (Some(i), _) | (None, Some(i)) => i,
            (None, None) => {
                let i = self.push(None, None);
                self.nodes[i].depth = 0;
                self.no_group = Some(i);
                i
            }
        }
    }

    /// Each group's figures with its sub-groups' added: children after
    /// their parents in `nodes`, so each is complete before it is added.
    fn total(&mut self) {
        for i in (0..self.nodes.len()).rev() {
            let Some(p) = self.nodes[i].parent else {
                continue;
            };
            let (parts, basic, growth) = {
                let n = &self.nodes[i];
                (n.parts, n.basic.dd(), n.growth.dd())
            };
            let parent = &mut self.nodes[p];
            parent.parts += parts;
            for (sum, x) in [(&mut parent.basic, basic), (&mut parent.growth, growth)] {
                sum.add(x.hi);
                sum.add(x.lo);
            }
        }
    }
}

/// What a walk keeps of each sub-assembly entered: the group its parts go
/// under, and its maturity's allowance (the default of its parts).
#[derive(Clone, Copy)]
struct Entered {
    group: Option<usize>,
    allowance: Option<f64>,
}

/// A part's allowance: its own maturity's, else the innermost
/// sub-assembly's that gives one (`stack`, outermost first). The one rule,
/// for the statement and the uncertainty.
fn allowance_of(stack: &[Entered], own: Option<&Tag>) -> Option<f64> {
    own.and_then(|t| t.maturity.as_ref())
        .map(|m: &Maturity| m.allowance)
        .or_else(|| stack.iter().rev().find_map(|e| e.allowance))
}

/// A sub-assembly's maturity's allowance, if it gives one.
fn own_allowance(tag: Option<&Tag>) -> Option<f64> {
    tag.and_then(|t| t.maturity.as_ref()).map(|m| m.allowance)
}

/// Each part's growth allowance (a fraction; 0 without a maturity), by
/// its index in the body (`walk::Leaf::index`): what the predicted body
/// adds to it, for `uncertainty`.
pub fn allowances(model: &Model) -> Vec<f64> {
    let mut out = Vec::with_capacity(model.count);
    let mut stack: Vec<Entered> = Vec::new();
    model.each_event(&mut |e| match e {
        Event::Enter(inc) => stack.push(Entered {
            group: None,
            allowance: own_allowance(inc.tag.as_deref()),
        }),
        Event::Exit => {
            stack.pop();
        }
        Event::Part(leaf) => out.push(allowance_of(&stack, leaf.tag).unwrap_or(0.0)),
    });
    out
}

/// Walk the body once: each part's group (its sub-assemblies' groups, then
/// its own) and maturity (its own, else the innermost sub-assembly's that
/// gives one), its basic mass and growth, in SI.
fn walk(model: &Model) -> Walked {
    let factors = SiFactors::of(model.units);
    let mut w = Walked::default();
    // The sub-assemblies entered, outermost first.
    let mut stack: Vec<Entered> = Vec::new();
    model.each_event(&mut |e| match e {
        Event::Enter(inc) => {
            let from = stack.last().and_then(|e| e.group);
            stack.push(Entered {
                group: w.reach(from, inc.tag.as_deref()),
                allowance: own_allowance(inc.tag.as_deref()),
            });
        }
        Event::Exit => {
            stack.pop();
        }
        Event::Part(leaf) => {
            let from = stack.last().and_then(|e| e.group);
            let at = w.reach(from, leaf.tag);
            let i = w.group_of(at);
            let p = leaf.part;
            // Signed: a cut-out's is negative, and so is its growth.
            let basic = p.mass_si(&factors);
            let grown = match allowance_of(&stack, leaf.tag) {
                Some(allowance) => {
                    let g = growth(p.mass::<f64>(), allowance);
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
            let n = &mut w.nodes[i];
            n.parts += 1;
            n.basic.add(basic);
            n.growth.add(grown);
        }
    });
    w.total();
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
        spec: Spec {
            mass: MassSpec::Given(g.abs()),
            place: Place::Point(crate::shapes::point::Point {
                center,
                orientation: Orientation::Identity,
            }),
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

/// The not-to-exceed limit: `[budget] limit`, else `[expect] mass`'s `max`.
fn limit(model: &Model) -> Option<(LimitSource, f64)> {
    if let Some(l) = &model.budget {
        return Some((LimitSource::Budget, l.mass));
    }
    model
        .expect
        .iter()
        .filter(|c| c.target.quantity == Quantity::Mass)
        .find_map(|c| match c.bound {
            Bound::Range { max: Some(m), .. } => Some((LimitSource::ExpectMassMax, m)),
            Bound::Range { max: None, .. } | Bound::Value { .. } | Bound::Axes { .. } => None,
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
    // Depth first, each level in order of first appearance; `at[i]`, node
    // i's place in `groups` (a parent's is known before its children's).
    let mut at = vec![0; w.nodes.len()];
    let mut todo: Vec<usize> = w.roots.iter().rev().copied().collect();
    while let Some(i) = todo.pop() {
        let n = &mut w.nodes[i];
        let (basic, grown) = (n.basic.value(), n.growth.value());
        let predicted_mass = basic + grown;
        at[i] = groups.len();
        groups.push(Group {
            name: n.name.take(),
            parent: n.parent.map(|p| at[p]),
            depth: n.depth,
            parts: n.parts,
            basic_mass: basic,
            growth_mass: grown,
            growth_fraction: ratio(grown, basic),
            predicted_mass,
            share: ratio(predicted_mass, total_predicted),
        });
        todo.extend(w.nodes[i].children.iter().rev());
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
    let accuracy_warnings = summary::accuracy::with_predicted(&summary);
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
