//! `massprop diff OLD NEW`: the mass properties of two part files side by
//! side, with absolute and relative changes, and what happened to each part.
//! The contract (table, JSON keys, exit statuses, the relative-change rule)
//! is docs/diff.md.
//!
//! Two summaries (the same `report::summarize` the report uses, tensor
//! convention) → a list of compared quantities and part changes, in SI →
//! a table in the new file's units or one JSON object in SI.

use crate::Output;
use crate::cli::{DiffArgs, Format};
use crate::diag::{Diagnostic, Source};
use crate::model::Model;
use crate::shapes::Shape;
use nalgebra::{Matrix3, Vector3};
use crate::numeric::norm;
use crate::report::table::{Units, fmt_num, new_table};
use crate::report::{self, Products, Summary};
use comfy_table::CellAlignment;
use serde::Serialize;
use std::collections::{HashMap, VecDeque};
use std::fmt::Write;

/// Version of the diff JSON contract (docs/diff.md): bumped only if a key
/// changes meaning. Keys may be added; none is ever renamed or removed.
pub const FORMAT_VERSION: u32 = 1;

/// One part file, read, validated and summarized.
struct Side {
    source: Source,
    model: Model,
    summary: Summary,
    /// The model's parts in SI, in its order.
    parts: Vec<PartView>,
}

/// What `diff` compares of a part, SI.
struct PartView {
    name: String,
    shape: Shape,
    mass: f64,
    center: Vector3<f64>,
    second_moment: Matrix3<f64>,
}

fn load(path: &str, precision: crate::compose::Precision) -> Result<Side, Diagnostic> {
    let source = crate::read_source(path)?;
    let model = Model::parse(&source)?;
    // A file `report` rejects is invalid here too, although diff does not
    // use the dynamics: α needs ω (docs/part-file.md).
    if let (Some(span), None) = (&model.analysis.alpha_span, &model.analysis.omega) {
        return Err(source
            .error(
                span.clone(),
                "`alpha` needs `omega`: the Euler moment depends on both",
            )
            .help("give `omega` here; for a body starting from rest, `omega = [0, 0, 0]`"));
    }
    let summary = report::summarize(&model, &model.analysis, Products::Tensor, precision)
        .map_err(|e| e.diagnostic(&model, &model.analysis, &source))?;
    let parts = model
        .parts
        .iter()
        .map(|p| {
            let si = p.si(model.units);
            PartView {
                name: p.name.clone(),
                shape: p.shape,
                mass: si.mass,
                center: si.center,
                second_moment: si.second_moment,
            }
        })
        .collect();
    Ok(Side {
        source,
        model,
        summary,
        parts,
    })
}

/// What kind of value a quantity is, for its unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Mass,
    Length,
    Inertia,
}

/// One compared value, SI. Field names are the JSON keys.
#[derive(Debug, Clone, Serialize)]
struct QuantityDiff {
    /// `mass`, `center_of_mass.x`, `inertia_com.xy`, `principal_moments.1`.
    quantity: String,
    old: f64,
    new: f64,
    abs_change: f64,
    /// `abs_change` divided by the quantity's scale; `None` when the scale is
    /// zero (the quantity is zero in both files) or the ratio overflows.
    rel_change: Option<f64>,
    changed: bool,
    #[serde(skip)]
    label: String,
    #[serde(skip)]
    kind: Kind,
}

/// A part present in one file only: its position there (0-based).
#[derive(Debug, Clone, Copy)]
struct Lone {
    index: usize,
}

/// A part matched by name whose properties moved beyond the tolerance.
#[derive(Debug, Clone)]
struct PartChange {
    old: usize,
    new: usize,
    /// Among `shape`, `mass`, `centroid`, `second_moment`, in that order.
    what: Vec<&'static str>,
}

#[derive(Debug, Clone, Default)]
struct PartDiff {
    /// Parts of the new file only, in its order.
    added: Vec<Lone>,
    /// Parts of the old file only, in its order.
    removed: Vec<Lone>,
    /// In the old file's order.
    changed: Vec<PartChange>,
}

impl PartDiff {
    fn is_empty(&self) -> bool {
        self.added.is_empty() && self.removed.is_empty() && self.changed.is_empty()
    }
}

pub fn run(args: &DiffArgs) -> Result<Output, Diagnostic> {
    let tol = args.tol;
    if !(tol >= 0.0 && tol.is_finite()) {
        return Err(Diagnostic::plain(format!(
            "invalid value {tol} for `--tol`: expected a finite relative tolerance ≥ 0, such as 1e-6"
        )));
    }
    if args.old == "-" && args.new == "-" {
        return Err(Diagnostic::plain(
            "OLD and NEW cannot both be `-`: standard input can be read only once",
        ));
    }
    let old = load(&args.old, args.precision)?;
    let new = load(&args.new, args.precision)?;
    let length = length_scale(&old.summary, &new.summary);
    let quantities = quantities(&old.summary, &new.summary, length, tol).map_err(|d| {
        Diagnostic::plain(format!(
            "{} → {}: {}",
            old.source.name,
            new.source.name,
            d.message()
        ))
    })?;
    let parts = part_diff(&old.parts, &new.parts, length, tol);
    let changed = quantities.iter().any(|q| q.changed) || !parts.is_empty();
    let d = Diff {
        old: &old,
        new: &new,
        tol,
        quantities,
        parts,
        changed,
    };
    let stdout = match args.format {
        Format::Table => render_table(&d),
        Format::Json => render_json(&d),
    };
    Ok(Output {
        stdout,
        stderr: String::new(),
        status: u8::from(changed),
    })
}

struct Diff<'a> {
    old: &'a Side,
    new: &'a Side,
    tol: f64,
    quantities: Vec<QuantityDiff>,
    parts: PartDiff,
    changed: bool,
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
    kind: Kind,
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
        kind,
    })
}

/// Mass, centre of mass, principal moments, and the six independent entries
/// of the inertia tensor about the centre of mass (upper triangle).
fn quantities(
    old: &Summary,
    new: &Summary,
    length: f64,
    tol: f64,
) -> Result<Vec<QuantityDiff>, Diagnostic> {
    let mut out = vec![compare(
        "mass".into(),
        "mass".into(),
        Kind::Mass,
        (old.mass, new.mass),
        pick(old.mass.abs(), new.mass.abs()),
        tol,
    )?];
    for (i, axis) in ["x", "y", "z"].iter().enumerate() {
        out.push(compare(
            format!("center_of_mass.{axis}"),
            format!("centre of mass {axis}"),
            Kind::Length,
            (old.center_of_mass[i], new.center_of_mass[i]),
            length,
            tol,
        )?);
    }
    let scale = pick(norm(&old.principal_moments), norm(&new.principal_moments));
    for i in 0..3 {
        out.push(compare(
            format!("principal_moments.{}", i + 1),
            format!("principal moment I{}", i + 1),
            Kind::Inertia,
            (old.principal_moments[i], new.principal_moments[i]),
            scale,
            tol,
        )?);
    }
    let scale = pick(norm(&flat(&old.inertia_com)), norm(&flat(&new.inertia_com)));
    for (i, j, ij) in [
        (0, 0, "xx"),
        (1, 1, "yy"),
        (2, 2, "zz"),
        (0, 1, "xy"),
        (0, 2, "xz"),
        (1, 2, "yz"),
    ] {
        out.push(compare(
            format!("inertia_com.{ij}"),
            format!("I{ij}"),
            Kind::Inertia,
            (old.inertia_com[i][j], new.inertia_com[i][j]),
            scale,
            tol,
        )?);
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
fn part_changes(o: &PartView, n: &PartView, length: f64, tol: f64) -> Vec<&'static str> {
    let mut what = Vec::new();
    if o.shape != n.shape {
        what.push("shape");
    }
    // `!(x <= limit)` also catches a NaN or infinite ratio as a change.
    // |m|: a cut-out's mass is negative.
    if !((n.mass - o.mass).abs() <= tol * o.mass.abs()) {
        what.push("mass");
    }
    let moved = norm((n.center - o.center).as_slice());
    if !(moved <= tol * length) {
        what.push("centroid");
    }
    let (co, cn) = (o.second_moment, n.second_moment);
    let scale = pick(norm(co.as_slice()), norm(cn.as_slice()));
    if !(norm((cn - co).as_slice()) <= tol * scale) {
        what.push("second_moment");
    }
    what
}

// ---------------------------------------------------------------- JSON

#[derive(Serialize)]
struct JsonUnits {
    mass: &'static str,
    length: &'static str,
    inertia: &'static str,
}

#[derive(Serialize)]
struct JsonPartChange<'a> {
    name: &'a str,
    what: &'a [&'static str],
}

#[derive(Serialize)]
struct JsonParts<'a> {
    added: Vec<&'a str>,
    removed: Vec<&'a str>,
    changed: Vec<JsonPartChange<'a>>,
}

/// The JSON contract of docs/diff.md; field names are the keys.
#[derive(Serialize)]
struct JsonDiff<'a> {
    format_version: u32,
    old: &'a str,
    new: &'a str,
    products_convention: Products,
    units: JsonUnits,
    tolerance: f64,
    changed: bool,
    quantities: &'a [QuantityDiff],
    parts: JsonParts<'a>,
}

fn render_json(d: &Diff) -> String {
    let (op, np) = (&d.old.parts, &d.new.parts);
    let json = JsonDiff {
        format_version: FORMAT_VERSION,
        old: &d.old.source.name,
        new: &d.new.source.name,
        products_convention: Products::Tensor,
        units: JsonUnits {
            mass: "kg",
            length: "m",
            inertia: "kg*m^2",
        },
        tolerance: d.tol,
        changed: d.changed,
        quantities: &d.quantities,
        parts: JsonParts {
            added: d
                .parts
                .added
                .iter()
                .map(|l| np[l.index].name.as_str())
                .collect(),
            removed: d
                .parts
                .removed
                .iter()
                .map(|l| op[l.index].name.as_str())
                .collect(),
            changed: d
                .parts
                .changed
                .iter()
                .map(|c| JsonPartChange {
                    name: &op[c.old].name,
                    what: &c.what,
                })
                .collect(),
        },
    };
    let mut s = serde_json::to_string(&json).expect("a diff of finite numbers always serializes");
    s.push('\n');
    s
}

// ---------------------------------------------------------------- table

impl Units {
    fn of_kind(&self, k: Kind) -> (f64, &str) {
        match k {
            Kind::Mass => (self.mass, self.mass_label),
            Kind::Length => (self.length, self.length_label),
            Kind::Inertia => (self.inertia, &self.inertia_label),
        }
    }
}

/// `x` (SI) in display units; should the conversion overflow (a value near
/// the limit of f64, shown in smaller units), the SI value, marked as such.
fn show(x: f64, factor: f64) -> String {
    let v = x / factor;
    if v.is_finite() {
        fmt_num(v)
    } else {
        format!("{} (SI)", fmt_num(x))
    }
}

fn percent(r: Option<f64>) -> String {
    match r.map(|r| r * 100.0) {
        Some(p) if p.is_finite() => format!("{} %", fmt_num(p)),
        Some(_) => "> 1e306 %".to_string(),
        None => "–".to_string(),
    }
}

/// How a file is named in the table: its path, and its `name` if it has one.
fn title(side: &Side) -> String {
    match &side.model.name {
        Some(n) => format!("{} ({n})", side.source.name),
        None => side.source.name.clone(),
    }
}

/// A part's name, numbered when the name is not unique in its file.
fn part_label(parts: &[PartView], index: usize) -> String {
    let name = &parts[index].name;
    if parts.iter().filter(|p| &p.name == name).count() > 1 {
        let k = parts[..=index].iter().filter(|p| &p.name == name).count();
        format!("{name} (#{k})")
    } else {
        name.clone()
    }
}

fn describe_lone(p: &PartView, u: &Units) -> String {
    let c = p.center.as_slice();
    format!(
        "{}, {} {} at ({}, {}, {}) {}",
        p.shape.name(),
        show(p.mass, u.mass),
        u.mass_label,
        show(c[0], u.length),
        show(c[1], u.length),
        show(c[2], u.length),
        u.length_label
    )
}

fn describe_change(o: &PartView, n: &PartView, what: &[&str], u: &Units) -> String {
    what.iter()
        .map(|w| match *w {
            "shape" => format!("shape {} → {}", o.shape.name(), n.shape.name()),
            "mass" => format!(
                "mass {} → {} {} ({})",
                show(o.mass, u.mass),
                show(n.mass, u.mass),
                u.mass_label,
                percent(Some((n.mass - o.mass) / o.mass))
            ),
            "centroid" => {
                let moved = norm((n.center - o.center).as_slice());
                if moved < f64::MAX {
                    format!(
                        "centroid moved {} {}",
                        show(moved, u.length),
                        u.length_label
                    )
                } else {
                    "centroid moved".to_string()
                }
            }
            "second_moment" => "second moment".to_string(),
            other => other.to_string(),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

fn render_table(d: &Diff) -> String {
    let u = Units::of(d.new.summary.file_units);
    let mut out = String::new();
    let _ = writeln!(out, "old: {}", title(d.old));
    let _ = writeln!(out, "new: {}", title(d.new));
    let _ = writeln!(
        out,
        "units (the new file's): mass {}, length {}, inertia {}",
        u.mass_label, u.length_label, u.inertia_label
    );
    let _ = writeln!(
        out,
        "Ixx … Iyz: inertia about the centre of mass, tensor convention, Ixy = −∫xy dm"
    );
    let _ = writeln!(
        out,
        "relative: change ÷ the scale of the whole quantity (docs/diff.md); tolerance {:e}",
        d.tol
    );

    let mut t = new_table();
    t.set_header(vec!["", "old", "new", "change", "relative", "unit", ""]);
    for q in &d.quantities {
        let (factor, unit) = u.of_kind(q.kind);
        t.add_row(vec![
            q.label.clone(),
            show(q.old, factor),
            show(q.new, factor),
            show(q.abs_change, factor),
            percent(q.rel_change),
            unit.to_string(),
            if q.changed { "changed" } else { "" }.to_string(),
        ]);
    }
    for (i, c) in t.column_iter_mut().enumerate() {
        if (1..=4).contains(&i) {
            c.set_cell_alignment(CellAlignment::Right);
        }
    }
    let _ = writeln!(out, "\n{t}");

    let (op, np) = (&d.old.parts, &d.new.parts);
    let p = &d.parts;
    if p.is_empty() {
        let _ = writeln!(out, "\nparts: none added, removed or changed");
    } else {
        let _ = writeln!(
            out,
            "\nparts: {} added, {} removed, {} changed (matched by name)",
            p.added.len(),
            p.removed.len(),
            p.changed.len()
        );
        let mut t = new_table();
        t.set_header(vec!["part", "", "what"]);
        for l in &p.removed {
            t.add_row(vec![
                part_label(op, l.index),
                "removed".to_string(),
                describe_lone(&op[l.index], &u),
            ]);
        }
        for l in &p.added {
            t.add_row(vec![
                part_label(np, l.index),
                "added".to_string(),
                describe_lone(&np[l.index], &u),
            ]);
        }
        for c in &p.changed {
            t.add_row(vec![
                part_label(op, c.old),
                "changed".to_string(),
                describe_change(&op[c.old], &np[c.new], &c.what, &u),
            ]);
        }
        let _ = writeln!(out, "{t}");
    }
    let _ = writeln!(
        out,
        "\n{}",
        if d.changed {
            "result: changed beyond the tolerance"
        } else {
            "result: no change beyond the tolerance"
        }
    );
    out
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
            Kind::Inertia,
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
        let q = compare("q".into(), "q".into(), Kind::Mass, (0.0, 0.0), 0.0, 0.0).unwrap();
        assert_eq!(q.rel_change, None);
        assert!(!q.changed);
    }

    #[test]
    fn an_overflowing_ratio_is_a_change_without_a_relative_value() {
        let q = compare(
            "q".into(),
            "q".into(),
            Kind::Length,
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
            Kind::Length,
            (-f64::MAX, f64::MAX),
            f64::MAX,
            1e-9,
        )
        .unwrap_err();
        assert!(e.message().contains("`center_of_mass.x` overflows"), "{e}");
    }

    #[test]
    fn a_value_beyond_f64_in_display_units_is_shown_in_si() {
        assert_eq!(show(2.5e-3, 1e-3), "2.5");
        assert_eq!(show(1e308, 1e-3), "1e308 (SI)");
    }

    #[test]
    fn percentages_never_print_infinity() {
        assert_eq!(percent(Some(0.5)), "50 %");
        assert_eq!(percent(Some(f64::MAX)), "> 1e306 %");
        assert_eq!(percent(None), "–");
    }
}
