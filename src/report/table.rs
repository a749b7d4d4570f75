//! The table for people: mass, length and inertia in the file's own units
//! (what the engineer wrote and would compare with a CAD dialog), dynamics in
//! SI, six significant digits. Full precision is in the JSON.

use super::ideal::Idealisation;
use super::{Products, Summary};
use crate::compose::Precision;
use crate::units::{Dim, FileUnits};
use comfy_table::{CellAlignment, Table, presets};
use std::fmt::Write;

/// `x` to six significant digits: fixed notation for moderate magnitudes,
/// scientific otherwise, trailing zeros dropped.
pub fn fmt_num(x: f64) -> String {
    fmt_sig(x, 6)
}

/// A fraction as a percentage to three significant digits (shares and
/// relative changes are read as orders of magnitude, not to six digits);
/// `None`, an undefined ratio, as "—".
pub fn fmt_percent(fraction: Option<f64>) -> String {
    match fraction {
        Some(f) => format!("{} %", fmt_sig(f * 100.0, 3)),
        None => "—".to_string(),
    }
}

/// `x` to `digits` significant digits (1 or more), as `fmt_num`.
fn fmt_sig(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".to_string();
    }
    if !x.is_finite() {
        // Unreachable through `summarize`, which refuses non-finite
        // results; printed honestly rather than panicking if it ever is.
        return x.to_string();
    }
    let places = digits.max(1) - 1;
    let sci = format!("{x:.places$e}");
    let (mantissa, exp) = sci.split_once('e').expect("{:e} always has an exponent");
    let exp: i32 = exp.parse().expect("{:e} exponent is an integer");
    if (-4..6).contains(&exp) {
        let decimals = (places as i32 - exp).max(0) as usize;
        let s = format!("{x:.decimals$}");
        trim_zeros(&s)
    } else {
        format!("{}e{exp}", trim_zeros(mantissa))
    }
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A table in the style every massprop table uses.
pub(crate) fn new_table() -> Table {
    let mut t = Table::new();
    t.load_style(presets::UTF8_FULL_CONDENSED);
    t
}

fn right_align(t: &mut Table, from: usize) {
    for (i, c) in t.column_iter_mut().enumerate() {
        if i >= from {
            c.set_cell_alignment(CellAlignment::Right);
        }
    }
}

fn matrix_table(m: &[[f64; 3]; 3], scale: f64) -> Table {
    let mut t = new_table();
    t.set_header(vec!["", "x", "y", "z"]);
    for (label, row) in ["x", "y", "z"].iter().zip(m) {
        let mut cells = vec![label.to_string()];
        cells.extend(row.iter().map(|v| fmt_num(v / scale)));
        t.add_row(cells);
    }
    right_align(&mut t, 1);
    t
}

fn equal_note(out: &mut String, equal: &[usize]) {
    let names: Vec<String> = equal.iter().map(|i| format!("I{}", i + 1)).collect();
    if !equal.is_empty() {
        let _ = writeln!(
            out,
            "note: {} are equal within {:e} relative: their axes are not unique",
            names.join(" = "),
            crate::compose::EQUAL_MOMENT_RTOL
        );
    }
}

fn principal_table(
    moments: &[f64; 3],
    axes: &[[f64; 3]; 3],
    radii: Option<&[f64; 3]>,
    u: &Units,
) -> Table {
    let mut t = new_table();
    let mut header = vec![format!("moment ({})", u.inertia_label)];
    if radii.is_some() {
        header.push(format!("radius of gyration ({})", u.length_label));
    }
    header.extend(["axis x", "axis y", "axis z"].map(String::from));
    header.insert(0, String::new());
    t.set_header(header);
    for i in 0..3 {
        let mut cells = vec![format!("I{}", i + 1), fmt_num(moments[i] / u.inertia)];
        if let Some(r) = radii {
            cells.push(fmt_num(r[i] / u.length));
        }
        cells.extend(axes[i].iter().map(|a| fmt_num(*a)));
        t.add_row(cells);
    }
    right_align(&mut t, 1);
    t
}

/// Display scale factors (SI per file unit) and their labels.
pub(crate) struct Units {
    pub mass: f64,
    pub length: f64,
    pub inertia: f64,
    pub mass_label: &'static str,
    pub length_label: &'static str,
    pub inertia_label: String,
}

impl Units {
    pub(crate) fn of(f: FileUnits) -> Units {
        Units {
            mass: f.factor(Dim::MASS).value(),
            length: f.factor(Dim::LENGTH).value(),
            inertia: f.factor(Dim::MASS).value() * f.factor(Dim::LENGTH).value().powi(2),
            mass_label: f.mass,
            length_label: f.length,
            inertia_label: f.inertia_label(),
        }
    }
}

/// Render the report; `source` names the file it came from.
pub fn render(s: &Summary, source: &str) -> String {
    let u = Units::of(s.file_units);
    let mut out = String::new();
    match &s.name {
        Some(n) => {
            let _ = writeln!(out, "{n} ({source})");
        }
        None => {
            let _ = writeln!(out, "{source}");
        }
    }
    let _ = writeln!(
        out,
        "units: mass {}, length {}, inertia {}; ω, H, T, α and M in SI",
        u.mass_label, u.length_label, u.inertia_label
    );
    let _ = writeln!(
        out,
        "products of inertia: {}",
        match s.products_convention {
            Products::Tensor => "tensor convention, Ixy = −∫xy dm",
            Products::Positive => "positive convention (CAD, Meriam), Ixy = +∫xy dm",
        }
    );
    let _ = writeln!(
        out,
        "precision: {}",
        match s.precision {
            Precision::Standard => "standard (f64, compensated sums)",
            Precision::Extended => "extended (double-double, ~32 digits)",
        }
    );
    let _ = writeln!(out, "\nmass: {} {}", fmt_num(s.mass / u.mass), u.mass_label);
    if let Some(t) = s.kinetic_energy {
        let _ = writeln!(out, "kinetic energy T: {} J", fmt_num(t));
    }

    let mut vectors = new_table();
    vectors.set_header(vec!["", "x", "y", "z", "unit"]);
    let mut row = |label: &str, v: &[f64; 3], scale: f64, unit: &str| {
        let mut cells = vec![label.to_string()];
        cells.extend(v.iter().map(|x| fmt_num(x / scale)));
        cells.push(unit.to_string());
        vectors.add_row(cells);
    };
    row(
        "centre of mass",
        &s.center_of_mass,
        u.length,
        u.length_label,
    );
    if s.reference_given {
        row(
            "reference point",
            &s.reference_point,
            u.length,
            u.length_label,
        );
    }
    if let Some(w) = &s.omega {
        row("angular velocity ω", w, 1.0, "rad/s");
    }
    if let Some(h) = &s.angular_momentum {
        row("angular momentum H", h, 1.0, "N·m·s");
    }
    if let Some(a) = &s.alpha {
        row("angular acceleration α", a, 1.0, "rad/s²");
    }
    if let Some(m) = &s.euler_moment {
        row("Euler moment M", m, 1.0, "N·m");
    }
    right_align(&mut vectors, 1);
    if let Some(c) = vectors.column_mut(4) {
        c.set_cell_alignment(CellAlignment::Left);
    }
    let _ = writeln!(out, "{vectors}");

    let _ = writeln!(
        out,
        "\ninertia about the centre of mass ({})",
        u.inertia_label
    );
    let _ = writeln!(out, "{}", matrix_table(&s.inertia_com, u.inertia));
    if s.reference_given {
        let p = s.reference_point.map(|x| fmt_num(x / u.length));
        let _ = writeln!(
            out,
            "\ninertia about the reference point ({}, {}, {}) {} ({})",
            p[0], p[1], p[2], u.length_label, u.inertia_label
        );
        let _ = writeln!(out, "{}", matrix_table(&s.inertia_ref, u.inertia));
    }

    let _ = writeln!(
        out,
        "\nprincipal moments and axes about the centre of mass (ascending)"
    );
    let _ = writeln!(
        out,
        "{}",
        principal_table(
            &s.principal_moments,
            &s.principal_axes,
            Some(&s.radii_of_gyration),
            &u
        )
    );
    equal_note(&mut out, &s.equal_moments);
    if s.reference_given {
        let _ = writeln!(
            out,
            "\nprincipal moments and axes about the reference point (ascending)"
        );
        let _ = writeln!(
            out,
            "{}",
            principal_table(&s.principal_moments_ref, &s.principal_axes_ref, None, &u)
        );
        equal_note(&mut out, &s.equal_moments_ref);
    }

    let _ = writeln!(out, "\nparts");
    let mut parts = new_table();
    parts.set_header(vec![
        "#".to_string(),
        "name".to_string(),
        "shape".to_string(),
        format!("mass ({})", u.mass_label),
        "mass share".to_string(),
        format!("centroid x ({})", u.length_label),
        "y".to_string(),
        "z".to_string(),
        "I1 share".to_string(),
        "I2 share".to_string(),
        "I3 share".to_string(),
    ]);
    for (i, p) in s.parts.iter().enumerate() {
        let mut cells = vec![
            (i + 1).to_string(),
            p.name.clone(),
            p.shape.name().to_string(),
            fmt_num(p.mass / u.mass),
            format!("{:.1} %", p.mass_fraction * 100.0),
        ];
        cells.extend(p.center_of_mass.iter().map(|x| fmt_num(x / u.length)));
        cells.extend(p.principal_moment_share.map(fmt_percent));
        parts.add_row(cells);
    }
    right_align(&mut parts, 3);
    if let Some(c) = parts.column_mut(0) {
        c.set_cell_alignment(CellAlignment::Right);
    }
    let _ = writeln!(out, "{parts}");
    let _ = writeln!(
        out,
        "I1–I3 share: each part's share of each principal moment about the centre of mass"
    );
    if s.parts
        .iter()
        .any(|p| p.principal_moment_share.contains(&None))
    {
        let _ = writeln!(
            out,
            "note: — marks a principal moment that is zero (a lone rod's axial moment): it has no shares"
        );
    }
    if let Some(i) = &s.idealisation {
        idealisation(&mut out, i, &u);
    }
    out
}

/// The idealisation section: the change of each principal moment with the
/// plates and rods that give their real size made solid.
fn idealisation(out: &mut String, i: &Idealisation, u: &Units) {
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
    let mut t = new_table();
    t.set_header(vec![
        "made solid",
        "as",
        "I1 change",
        "I2 change",
        "I3 change",
    ]);
    let mut row = |name: &str, solid: &str, change: &[Option<f64>; 3]| {
        let mut cells = vec![name.to_string(), solid.to_string()];
        cells.extend(change.map(fmt_percent));
        t.add_row(cells);
    };
    row("all together", "", &i.relative_change);
    for p in &i.parts {
        row(&p.name, p.solid.name(), &p.relative_change);
    }
    right_align(&mut t, 2);
    let _ = writeln!(out, "{t}");
    let _ = writeln!(
        out,
        "change: (solid − idealised) / idealised of each principal moment, ascending"
    );
    if i.relative_change.contains(&None) {
        let _ = writeln!(
            out,
            "note: — marks a principal moment that is zero when idealised (a lone rod's axial moment); compare the moments"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::fmt_num;

    #[test]
    fn numbers_show_six_significant_digits() {
        assert_eq!(fmt_num(1.6625), "1.6625");
        assert_eq!(fmt_num(0.5501562), "0.550156");
        assert_eq!(fmt_num(-0.06644531), "-0.0664453");
        assert_eq!(fmt_num(123456.7), "123457");
        assert_eq!(fmt_num(1234567.0), "1.23457e6");
        assert_eq!(fmt_num(0.00001234567), "1.23457e-5");
        assert_eq!(fmt_num(0.0), "0");
        assert_eq!(fmt_num(2.0), "2");
    }

    #[test]
    fn percentages_show_three_significant_digits_and_a_dash_for_none() {
        use super::fmt_percent;
        assert_eq!(fmt_percent(Some(1.0 / 3.0)), "33.3 %");
        assert_eq!(fmt_percent(Some(1e-6)), "0.0001 %");
        assert_eq!(fmt_percent(Some(1.234_567e-9)), "1.23e-7 %");
        assert_eq!(fmt_percent(Some(1.0)), "100 %");
        assert_eq!(fmt_percent(Some(0.0)), "0 %");
        assert_eq!(fmt_percent(None), "—");
    }
}
