//! The table for people: mass, length and inertia in the file's own units
//! (what the engineer wrote and would compare with a CAD dialog), dynamics in
//! SI, six significant digits. Full precision is in the JSON.

use super::format::{
    DisplayUnits, MOMENT_UNIT, UNDEFINED, equal_note, fmt_bounded, fmt_num, name, precision_label,
    products_label, push_percent,
};
use super::grid::{Cells, Fit, write_rows, write_table};
use crate::analysis::ideal::Idealisation;
use crate::analysis::summary::Summary;
use crate::quantity;
use crate::units::Dim;
use std::fmt::Write;

mod axles;
pub mod cases;
pub mod envelope;
mod full;
mod json_rows;
mod motion;
mod short;

/// How much of the report a table shows: the essentials (`short`), or
/// every table (`--full`). JSON always has everything.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Detail {
    /// Every table (`--full`): the report as it was before the short one.
    pub full: bool,
    /// The reference point was given by `--about`: the short report shows
    /// its tensors too (a table a flag asked for is shown).
    pub about_flag: bool,
}

/// The report as one JSON object (docs/json.md): the summary, SI.
pub fn json(summary: &Summary) -> String {
    super::json_line(summary)
}

/// The small tables' fit: their first column labels the rows.
fn fit(width: Option<usize>) -> Fit {
    Fit::new(width, 1)
}

/// Columns from the second on aligned right (numbers).
fn numbers(n: usize) -> Vec<bool> {
    (0..n).map(|i| i > 0).collect()
}

/// Entries to the digits their bounds `b` guarantee, read against the
/// largest entry (`fmt_bounded`).
pub(super) fn matrix_table(
    out: &mut String,
    (m, b): (&[[f64; 3]; 3], &[[f64; 3]; 3]),
    scale: f64,
    width: Option<usize>,
) {
    let header = ["", "x", "y", "z"].map(String::from);
    let top = m.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs())) / scale;
    let mut rows = Vec::new();
    for ((label, row), bounds) in ["x", "y", "z"].iter().zip(m).zip(b) {
        let mut cells = vec![label.to_string()];
        cells.extend(
            row.iter()
                .zip(bounds)
                .map(|(v, e)| fmt_bounded(v / scale, e / scale, top)),
        );
        rows.push(cells);
    }
    write_rows(out, &header, &rows, &numbers(header.len()), fit(width));
}

/// A principal table's values and their bounds (`error_bounds`).
struct Principal<'a> {
    moments: (&'a [f64; 3], &'a [f64; 3]),
    axes: (&'a [[f64; 3]; 3], &'a [f64; 3]),
    radii: Option<(&'a [f64; 3], &'a [f64; 3])>,
    /// The moments flagged equal: their axes are a choice.
    equal: &'a [usize],
}

/// The principal moments and axes about the reference point, headed, with
/// the note on equal moments (the full report's, and the short one's with
/// `--about`).
fn principal_about_reference(
    out: &mut String,
    s: &Summary,
    u: &DisplayUnits,
    width: Option<usize>,
) {
    let b = &s.error_bounds;
    let _ = writeln!(
        out,
        "principal moments and axes about the reference point (ascending)"
    );
    principal_table(
        out,
        Principal {
            moments: (&s.principal_moments_ref, &b.principal_moments_ref),
            axes: (&s.principal_axes_ref, &b.principal_axes_ref),
            radii: None,
            equal: &s.equal_moments_ref,
        },
        u,
        width,
    );
    equal_note(out, &s.equal_moments_ref);
}

fn principal_table(out: &mut String, p: Principal, u: &DisplayUnits, width: Option<usize>) {
    let Principal {
        moments: (moments, moments_b),
        axes: (axes, axes_b),
        radii,
        equal,
    } = p;
    let mut rows = Vec::new();
    let mut header = vec![format!("moment ({})", u.inertia_label)];
    if radii.is_some() {
        header.push(format!("radius of gyration ({})", u.length_label));
    }
    header.extend(["axis x", "axis y", "axis z"].map(String::from));
    header.insert(0, String::new());
    for i in 0..3 {
        let own = |v: f64, b: f64, scale: f64| fmt_bounded(v / scale, b / scale, (v / scale).abs());
        let mut cells = vec![
            format!("I{}", i + 1),
            own(moments[i], moments_b[i], u.inertia),
        ];
        if let Some((r, b)) = radii {
            cells.push(own(r[i], b[i], u.length));
        }
        // A component of a unit vector moves by at most the angle. Axes of
        // moments flagged equal are a choice, which the note says, not a
        // result to bound.
        let bound = if equal.contains(&i) { 0.0 } else { axes_b[i] };
        cells.extend(axes[i].iter().map(|a| fmt_bounded(*a, bound, 1.0)));
        rows.push(cells);
    }
    // The axes' components together.
    let fit = Fit {
        groups: if radii.is_some() {
            &[(3, 6)]
        } else {
            &[(2, 5)]
        },
        ..fit(width)
    };
    write_rows(out, &header, &rows, &numbers(header.len()), fit);
}

/// The first line: the body's name and the file (and the sub-assembly,
/// with `--only`), or the file alone.
pub(super) fn title(
    out: &mut String,
    body: &Option<String>,
    sub_assembly: &Option<Vec<String>>,
    source: &str,
) {
    let source = name(source);
    // The body's name begins the line: `line_name` (the file's name is
    // `display_path`'s, begun safely already).
    let _ = match (body, sub_assembly) {
        (Some(n), Some(path)) => writeln!(
            out,
            "{} (sub-assembly `{}` of {source})",
            super::format::line_name(n),
            name(&path.join(" / "))
        ),
        (Some(n), None) => writeln!(out, "{} ({source})", super::format::line_name(n)),
        (None, _) => writeln!(out, "{source}"),
    };
}

/// The lines under a title that say how to read a table's numbers: the
/// units (`units` after the file's own: `report`'s dynamics in SI), the
/// convention of the products of inertia and the axes.
pub(super) fn conventions(
    out: &mut String,
    u: &DisplayUnits,
    units: &str,
    products: crate::analysis::Products,
    axes: &[[f64; 3]; 3],
) {
    units_lines(out, u, units, products);
    let _ = writeln!(out, "{}", axes_line(axes));
}

/// `conventions` without the axes: the units and the products' sign.
fn units_lines(
    out: &mut String,
    u: &DisplayUnits,
    units: &str,
    products: crate::analysis::Products,
) {
    let _ = writeln!(
        out,
        "units: mass {}, length {}, inertia {}{units}",
        u.mass_label, u.length_label, u.inertia_label
    );
    let _ = writeln!(out, "products of inertia: {}", products_label(products));
}

/// Which axes the values are in: the file's, or the report axes given
/// (`axes`), each as its direction in the file's frame.
pub(super) fn axes_line(axes: &[[f64; 3]; 3]) -> String {
    if file_axes(axes) {
        return "axes: the file's".to_string();
    }
    let v = |r: &[f64; 3]| format!("({}, {}, {})", fmt_num(r[0]), fmt_num(r[1]), fmt_num(r[2]));
    format!(
        "axes: x = {}, y = {}, z = {} in the file's frame; tensors, principal axes, radii about the axes, ω, H, α and M in them",
        v(&axes[0]),
        v(&axes[1]),
        v(&axes[2])
    )
}

/// Whether the report axes are the file's own.
fn file_axes(axes: &[[f64; 3]; 3]) -> bool {
    (0..3).all(|i| (0..3).all(|j| axes[i][j] == f64::from(u8::from(i == j))))
}

/// The arithmetic used, and why: `auto`'s choice, or the one asked for;
/// how many values fall short of `--rtol` (the warnings say which).
fn precision_line(s: &Summary) -> String {
    use crate::analysis::summary::PrecisionChoice;
    use crate::compose::Precision;
    let why = match (s.requested, s.precision) {
        (PrecisionChoice::Auto, Precision::Standard) => "chosen by auto: every error bound within",
        (PrecisionChoice::Auto, Precision::Extended) => {
            "chosen by auto: standard's error bounds exceed"
        }
        _ => "as asked; error bounds judged against",
    };
    let mut line = format!(
        "precision: {}, {why} --rtol {:e}",
        precision_label(s.precision),
        s.rtol
    );
    match s.accuracy_warnings.len() {
        0 => {}
        1 => line.push_str("; 1 value is not within it (see the warning)"),
        n => {
            let _ = write!(line, "; {n} values are not within it (see the warnings)");
        }
    }
    line
}

/// The full report for people (`--full`); `source` names the file it
/// came from; tables wider than `width` split (`grid::Fit`).
pub fn table(s: &Summary, source: &str, width: Option<usize>) -> String {
    let mut out = Vec::new();
    write_table_to(s, source, width, &mut out).expect("invariant: writing to memory does not fail");
    String::from_utf8(out).expect("invariant: the table is UTF-8")
}

/// The short report for people (plain `report`): see `short`.
pub fn short_table(s: &Summary, source: &str, detail: Detail, width: Option<usize>) -> String {
    short::table(s, source, detail, width)
}

/// The report `detail` asks for, written to `w`: the full one as it is
/// made (`write_table_to`), the short one (small) at once.
pub fn write_detail_to(
    s: &Summary,
    source: &str,
    detail: Detail,
    width: Option<usize>,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    if detail.full {
        write_table_to(s, source, width, w)
    } else {
        w.write_all(short::table(s, source, detail, width).as_bytes())
    }
}

/// The report as one JSON object, written to `w` as it is made: the same
/// bytes as `json`, the part rows written by `json_rows`.
pub fn write_json_to(summary: &Summary, w: &mut dyn std::io::Write) -> std::io::Result<()> {
    json_rows::write(summary, w)
}

/// `table` (the full report), written to `w` as it is made: the rows of parts and
/// sub-assemblies are never all in memory.
pub fn write_table_to(
    s: &Summary,
    source: &str,
    width: Option<usize>,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let u = DisplayUnits::of(s.file_units);
    let mut out = String::new();
    title(&mut out, &s.name, &s.sub_assembly, source);
    conventions(
        &mut out,
        &u,
        "; ω, H, T, α and M in SI",
        s.products_convention,
        &s.axes,
    );
    let _ = writeln!(out, "{}", precision_line(s));
    let b = &s.error_bounds;
    let own = |v: f64, e: f64, scale: f64| fmt_bounded(v / scale, e / scale, (v / scale).abs());
    let _ = writeln!(
        out,
        "\nmass: {} {}",
        own(s.mass, b.mass, u.mass),
        u.mass_label
    );
    if let (Some(t), Some(e)) = (s.kinetic_energy, b.kinetic_energy) {
        let (scale, unit) = u.of_dim(Dim::ENERGY);
        let parts = motion::energy_parts(s);
        let _ = writeln!(out, "kinetic energy T: {} {unit}{parts}", own(t, e, scale));
    }

    let header = ["", "x", "y", "z", "unit"].map(String::from);
    let mut vectors = Vec::new();
    // Given vectors (ω, α, a reference point given) are exact: no bound.
    let exact = [0.0; 3];
    let mut row = |label: &str, v: &[f64; 3], e: &[f64; 3], (scale, unit): (f64, &str)| {
        let mut cells = vec![label.to_string()];
        let top = v.iter().fold(0.0f64, |a, x| a.max(x.abs())) / scale;
        cells.extend(
            v.iter()
                .zip(e)
                .map(|(x, e)| fmt_bounded(x / scale, e / scale, top)),
        );
        cells.push(unit.to_string());
        vectors.push(cells);
    };
    let length = u.of_dim(Dim::LENGTH);
    // Points are in the file's frame whatever the report axes.
    let turned = !file_axes(&s.axes);
    let point = |label: &'static str| -> &'static str {
        match (turned, label) {
            (false, l) => l,
            (true, "centre of mass") => "centre of mass (file's frame)",
            (true, _) => "reference point (file's frame)",
        }
    };
    row(
        point("centre of mass"),
        &s.center_of_mass,
        &b.center_of_mass,
        length,
    );
    row(
        "radius of gyration k_xx, k_yy, k_zz",
        &s.radii_of_gyration_axes,
        &b.radii_of_gyration_axes,
        length,
    );
    if s.reference_given {
        row(point("reference point"), &s.reference_point, &exact, length);
        row(
            "centre of mass from the point",
            &s.center_of_mass_ref,
            &b.center_of_mass_ref,
            length,
        );
        row(
            "k_xx, k_yy, k_zz through the point",
            &s.radii_of_gyration_axes_ref,
            &b.radii_of_gyration_axes_ref,
            length,
        );
    }
    if let Some(w) = &s.omega {
        row(
            "angular velocity ω",
            w,
            &exact,
            u.of_dim(Dim::ANGULAR_VELOCITY),
        );
    }
    if let (Some(h), Some(e)) = (&s.angular_momentum, &b.angular_momentum) {
        row("angular momentum H", h, e, u.of_dim(Dim::ANGULAR_MOMENTUM));
    }
    for (label, v, e, unit) in motion::rows(s) {
        row(label, &v, &e, (1.0, unit));
    }
    if let Some(a) = &s.alpha {
        row(
            "angular acceleration α",
            a,
            &exact,
            u.of_dim(Dim::ANGULAR_ACCELERATION),
        );
    }
    if let (Some(m), Some(e)) = (&s.euler_moment, &b.euler_moment) {
        // A moment has the dimension of an energy, but is not one: SI,
        // labelled N·m.
        row("Euler moment M", m, e, (1.0, MOMENT_UNIT));
    }
    // Numbers right, the unit left.
    let right = [false, true, true, true, false];
    let fit = Fit {
        groups: &[(1, 4)],
        ..fit(width)
    };
    write_rows(&mut out, &header, &vectors, &right, fit);
    axles::write(&mut out, s, &u, width);
    envelope::write(&mut out, s.envelope.as_ref(), &u);

    let _ = writeln!(
        out,
        "\ninertia about the centre of mass ({})",
        u.inertia_label
    );
    matrix_table(&mut out, (&s.inertia_com, &b.inertia_com), u.inertia, width);
    if s.reference_given {
        let p = s.reference_point.map(|x| fmt_num(x / u.length));
        let _ = writeln!(
            out,
            "\ninertia about the reference point ({}, {}, {}) {} ({})",
            p[0], p[1], p[2], u.length_label, u.inertia_label
        );
        matrix_table(&mut out, (&s.inertia_ref, &b.inertia_ref), u.inertia, width);
    }

    let _ = writeln!(
        out,
        "\nprincipal moments and axes about the centre of mass (ascending)"
    );
    principal_table(
        &mut out,
        Principal {
            moments: (&s.principal_moments, &b.principal_moments),
            axes: (&s.principal_axes, &b.principal_axes),
            radii: Some((&s.radii_of_gyration, &b.radii_of_gyration)),
            equal: &s.equal_moments,
        },
        &u,
        width,
    );
    equal_note(&mut out, &s.equal_moments);
    if s.reference_given {
        out.push('\n');
        principal_about_reference(&mut out, s, &u, width);
    }

    let _ = writeln!(out, "\nparts");
    w.write_all(out.as_bytes())?;
    out.clear();
    let (undefined, summing) = full::parts(w, s, &u, width)?;
    let _ = writeln!(
        out,
        "I1–I3 share: each part's share of each principal moment about the centre of mass"
    );
    if undefined {
        let _ = writeln!(
            out,
            "note: {UNDEFINED} marks a principal moment that is zero (a lone rod's axial moment): it has no shares"
        );
    }
    if !s.assemblies.is_empty() {
        w.write_all(out.as_bytes())?;
        out.clear();
        full::assemblies(w, s, &u, width, summing)?;
    }
    if let Some(i) = &s.idealisation {
        idealisation(&mut out, i, &u, width);
    }
    if let Some(x) = &s.uncertainty {
        uncertainty(&mut out, x, &u, width);
    }
    w.write_all(out.as_bytes())
}

/// The uncertainty section: each output's nominal value and standard
/// deviation (Monte Carlo: mean and percentiles too) in the file's units,
/// the sources that contribute most, the chance of each `[expect]` entry
/// to fail.
fn uncertainty(
    out: &mut String,
    x: &crate::analysis::uncertainty::Uncertainty,
    u: &DisplayUnits,
    width: Option<usize>,
) {
    let how = match x.samples {
        Some(n) => format!(
            "Monte Carlo, {n} samples, seed {}",
            x.seed.unwrap_or_default()
        ),
        None => "linear, first order with exact derivatives".to_string(),
    };
    let _ = writeln!(
        out,
        "\nuncertainty ({how}; {} independent source{})",
        x.sources,
        if x.sources == 1 { "" } else { "s" }
    );
    let mc = x.samples.is_some();
    let mut header = vec!["quantity", "unit", "nominal", "σ"];
    if mc {
        header.extend(["mean", "5 %", "50 %", "95 %"]);
    }
    header.push("most of the variance from");
    let header: Vec<String> = header.into_iter().map(String::from).collect();
    let mut cells = Cells::with_capacity(x.outputs.len() * header.len());
    let predicted = x.predicted.iter().flat_map(|p| p.outputs.iter());
    for o in x.outputs.iter().chain(predicted) {
        // The quantity's row names its dimension (`mass`,
        // `predicted_center_of_mass.x`: the basic body's key).
        let key = o.quantity.trim_start_matches("predicted_");
        let key = key.split_once('.').map_or(key, |(k, _)| k);
        let dim = quantity::by_key(key).map_or(Dim::DIMENSIONLESS, |i| i.dim);
        let (scale, unit) = u.of_dim(dim);
        cells.text.push_str(o.quantity);
        cells.end();
        cells.text.push_str(unit);
        cells.end();
        let mut num = |v: f64| {
            cells.text.push_str(&fmt_num(v / scale));
            cells.end();
        };
        num(o.nominal);
        num(o.sigma);
        if let (Some(m), Some(p)) = (o.mean, o.percentiles) {
            num(m);
            p.iter().for_each(|v| num(*v));
        }
        for (k, c) in o.contributors.iter().enumerate() {
            if k > 0 {
                cells.text.push_str("; ");
            }
            let _ = write!(cells.text, "{} ", name(&c.source));
            push_percent(&mut cells.text, Some(c.share));
        }
        cells.end();
    }
    let right: Vec<bool> = (0..header.len())
        .map(|i| i >= 2 && i + 1 < header.len())
        .collect();
    write_table(out, &header, &cells, &right, fit(width));
    if let Some(r) = x.rejected.filter(|r| *r > 0) {
        let _ = writeln!(
            out,
            "note: {r} samples left out, in which a size, radius, density or mass fell to zero or below"
        );
    }
    if !x.equal_moments.is_empty() {
        let _ = writeln!(
            out,
            "note: equal principal moments have no derivative; their σ is first order in a direction the tolerances choose"
        );
    }
    for e in &x.exceed {
        let _ = if e.quantity == "budget.limit" {
            write!(
                out,
                "chance that the predicted mass exceeds `[budget] limit` (line {}): ",
                e.line
            )
        } else {
            write!(
                out,
                "chance that `{}` (line {}) is outside its [expect] bounds: ",
                e.quantity, e.line
            )
        };
        push_percent(out, Some(e.probability));
        out.push('\n');
    }
}

/// The idealisation section: the change of each principal moment with the
/// plates and rods that give their real size made solid.
fn idealisation(out: &mut String, i: &Idealisation, u: &DisplayUnits, width: Option<usize>) {
    let _ = writeln!(
        out,
        "\nidealisation (thin plates and slender rods as solids)"
    );
    let m = i.principal_moments_solid.map(|x| fmt_num(x / u.inertia));
    let _ = writeln!(
        out,
        "principal moments with the parts below solid ({}): {}, {}, {}",
        u.inertia_label, m[0], m[1], m[2]
    );
    let header = ["made solid", "as", "I1 change", "I2 change", "I3 change"].map(String::from);
    let mut cells = Cells::with_capacity((i.parts.len() + 1) * header.len());
    let mut row = |name: &str, solid: &str, change: &[Option<f64>; 3]| {
        cells.text.push_str(name);
        cells.end();
        cells.text.push_str(solid);
        cells.end();
        for c in change {
            push_percent(&mut cells.text, *c);
            cells.end();
        }
    };
    row("all together", "", &i.relative_change);
    for p in &i.parts {
        row(&name(&p.name), p.solid.name(), &p.relative_change);
    }
    let right = [false, false, true, true, true];
    write_table(out, &header, &cells, &right, fit(width));
    let _ = writeln!(
        out,
        "change: (solid − idealised) / idealised of each principal moment, ascending"
    );
    if i.relative_change.contains(&None) {
        let _ = writeln!(
            out,
            "note: {UNDEFINED} marks a principal moment that is zero when idealised (a lone rod's axial moment); compare the moments"
        );
    }
}
