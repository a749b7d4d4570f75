//! The table for people: mass, length and inertia in the file's own units
//! (what the engineer wrote and would compare with a CAD dialog), dynamics in
//! SI, six significant digits. Full precision is in the JSON.

use super::ideal::Idealisation;
use super::{Products, Summary};
use crate::compose::Precision;
use crate::units::{Dim, FileUnits};
use comfy_table::{CellAlignment, Table, presets};
use std::fmt::Write;
use unicode_width::UnicodeWidthStr;

/// `x` to six significant digits: fixed notation for moderate magnitudes,
/// scientific otherwise, trailing zeros dropped.
pub fn fmt_num(x: f64) -> String {
    fmt_sig(x, 6)
}

/// A fraction as a percentage to three significant digits (shares and
/// relative changes are read as orders of magnitude, not to six digits);
/// `None`, an undefined ratio, as "—".
pub fn fmt_percent(fraction: Option<f64>) -> String {
    let mut s = String::new();
    push_percent(&mut s, fraction);
    s
}

/// Append `fmt_percent(fraction)` to `out`.
fn push_percent(out: &mut String, fraction: Option<f64>) {
    match fraction {
        Some(f) => {
            push_sig(out, f * 100.0, 3);
            out.push_str(" %");
        }
        None => out.push('—'),
    }
}

/// `x` to `digits` significant digits (1 to 40), as `fmt_num`.
fn fmt_sig(x: f64, digits: usize) -> String {
    let mut s = String::new();
    push_sig(&mut s, x, digits);
    s
}

/// Append `fmt_sig(x, digits)` to `out`, without allocating.
///
/// NOTE: one `{:.N$e}` formatting gives the digits of both notations where
/// the fixed one keeps `digits` significant digits (exponent ≤ digits − 1,
/// always so for six): both round at the same decimal place. Above that the
/// fixed notation rounds to a whole number, a second formatting. The table
/// of 100,000 parts formats ~800,000 numbers.
fn push_sig(out: &mut String, x: f64, digits: usize) {
    debug_assert!((1..=40).contains(&digits), "the buffers hold 40 digits");
    if x == 0.0 {
        out.push('0');
        return;
    }
    if !x.is_finite() {
        // Unreachable through `summarize`, which refuses non-finite
        // results; printed honestly rather than panicking if it ever is.
        let _ = write!(out, "{x}");
        return;
    }
    let places = digits.max(1) - 1;
    let mut sci = Ascii::<64>::new();
    let _ = write!(sci, "{x:.places$e}");
    let sci = sci.as_str();
    let (mantissa, exp) = sci.split_once('e').expect("{:e} always has an exponent");
    let exp: i32 = exp.parse().expect("{:e} exponent is an integer");
    if !(-4..6).contains(&exp) {
        out.push_str(trim_zeros(mantissa));
        let _ = write!(out, "e{exp}");
        return;
    }
    let mut fixed = Ascii::<64>::new();
    if exp > places as i32 {
        let _ = write!(fixed, "{x:.0}");
    } else {
        let (sign, m) = match mantissa.strip_prefix('-') {
            Some(m) => ("-", m),
            None => ("", mantissa),
        };
        // m is "d" or "d.ddd…": `digits` digits.
        let (first, rest) = m.split_at(1);
        let rest = rest.strip_prefix('.').unwrap_or(rest);
        let _ = fixed.write_str(sign);
        if exp >= 0 {
            let e = exp as usize;
            let _ = fixed.write_str(first);
            let _ = fixed.write_str(&rest[..e]);
            if e < places {
                let _ = fixed.write_str(".");
                let _ = fixed.write_str(&rest[e..]);
            }
        } else {
            let _ = fixed.write_str("0.");
            for _ in 0..(-exp - 1) {
                let _ = fixed.write_str("0");
            }
            let _ = fixed.write_str(first);
            let _ = fixed.write_str(rest);
        }
    }
    out.push_str(trim_zeros(fixed.as_str()));
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// A fixed-size ASCII buffer on the stack for `write!`.
struct Ascii<const N: usize> {
    bytes: [u8; N],
    len: usize,
}

impl<const N: usize> Ascii<N> {
    fn new() -> Self {
        Ascii {
            bytes: [0; N],
            len: 0,
        }
    }

    fn as_str(&self) -> &str {
        std::str::from_utf8(&self.bytes[..self.len]).expect("only str is written")
    }
}

impl<const N: usize> Write for Ascii<N> {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let end = self.len + s.len();
        self.bytes
            .get_mut(self.len..end)
            .ok_or(std::fmt::Error)?
            .copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
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
    let header = [
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
    ];
    let mut cells = Cells::with_capacity(s.parts.len() * header.len());
    for (i, p) in s.parts.iter().enumerate() {
        let _ = write!(cells.text, "{}", i + 1);
        cells.end();
        cells.text.push_str(&p.name);
        cells.end();
        cells.text.push_str(p.shape.name());
        cells.end();
        push_sig(&mut cells.text, p.mass / u.mass, 6);
        cells.end();
        let _ = write!(cells.text, "{:.1} %", p.mass_fraction * 100.0);
        cells.end();
        for x in &p.center_of_mass {
            push_sig(&mut cells.text, x / u.length, 6);
            cells.end();
        }
        for share in p.principal_moment_share {
            push_percent(&mut cells.text, share);
            cells.end();
        }
    }
    // Left-aligned: name and shape.
    let right: Vec<bool> = (0..header.len()).map(|i| !(1..3).contains(&i)).collect();
    write_table(&mut out, &header, &cells, &right);
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
    if !s.assemblies.is_empty() {
        assemblies(&mut out, s, &u);
    }
    if let Some(i) = &s.idealisation {
        idealisation(&mut out, i, &u);
    }
    out
}

/// The sub-assemblies section: each with its mass, centre of mass and
/// shares, indented by depth.
fn assemblies(out: &mut String, s: &Summary, u: &Units) {
    let mut t = new_table();
    t.set_header(vec![
        "sub-assembly".to_string(),
        "parts".to_string(),
        format!("mass ({})", u.mass_label),
        "mass share".to_string(),
        format!("centre of mass x ({})", u.length_label),
        "y".to_string(),
        "z".to_string(),
        "I1 share".to_string(),
        "I2 share".to_string(),
        "I3 share".to_string(),
    ]);
    for a in &s.assemblies {
        let indent = "  ".repeat(a.path.len() - 1);
        let mut row = vec![
            format!("{indent}{}", a.path.last().expect("a path is never empty")),
            a.parts.to_string(),
            fmt_num(a.mass / u.mass),
            fmt_percent(Some(a.mass_fraction)),
        ];
        row.extend(a.center_of_mass.iter().map(|x| fmt_num(x / u.length)));
        row.extend(a.principal_moment_share.iter().map(|x| fmt_percent(*x)));
        t.add_row(row);
    }
    let _ = writeln!(out, "\nsub-assemblies\n{t}");
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
        row(&p.name, p.solid.name(), &p.relative_change);
    }
    write_table(out, &header, &cells, &[false, false, true, true, true]);
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

/// The text of a table's cells, row after row, in one buffer.
struct Cells {
    text: String,
    ends: Vec<usize>,
}

impl Cells {
    fn with_capacity(n: usize) -> Cells {
        Cells {
            text: String::with_capacity(n * 12),
            ends: Vec::with_capacity(n),
        }
    }

    /// Close the cell written since the last call.
    fn end(&mut self) {
        self.ends.push(self.text.len());
    }

    fn iter(&self) -> impl Iterator<Item = &str> {
        let starts = std::iter::once(0).chain(self.ends.iter().copied());
        starts.zip(&self.ends).map(|(a, b)| &self.text[a..*b])
    }
}

/// Write a table exactly as comfy-table prints it in `new_table`'s style
/// (columns as wide as their widest cell, one space of padding, no row
/// separators; `right[i]` aligns column i right), then a newline.
///
/// NOTE: the parts table has a row per part, 100,000 and more: through
/// comfy-table (a `String` and several `Vec`s per cell and per line) it
/// took 0.44 s for 100,000 parts, more than the rest of `report` after
/// parsing; written here, 0.1 s. Tables with a line break in a cell
/// (comfy-table splits those into lines) or a column wider than comfy-table
/// measures (u16) still go through comfy-table.
fn write_table(out: &mut String, header: &[String], cells: &Cells, right: &[bool]) {
    let n = header.len();
    let mut widths: Vec<usize> = header.iter().map(|h| h.width().max(1)).collect();
    let mut multiline = false;
    for (i, c) in cells.iter().enumerate() {
        multiline |= c.contains('\n');
        let w = &mut widths[i % n];
        *w = (*w).max(c.width());
    }
    if multiline || widths.iter().any(|w| *w > usize::from(u16::MAX)) {
        let mut t = new_table();
        t.set_header(header.to_vec());
        let all: Vec<&str> = cells.iter().collect();
        for row in all.chunks(n) {
            t.add_row(row.to_vec());
        }
        for (c, r) in t.column_iter_mut().zip(right) {
            if *r {
                c.set_cell_alignment(CellAlignment::Right);
            }
        }
        let _ = writeln!(out, "{t}");
        return;
    }
    let rule = |out: &mut String, [left, fill, junction, end]: [char; 4]| {
        out.push(left);
        for (i, w) in widths.iter().enumerate() {
            if i > 0 {
                out.push(junction);
            }
            out.extend(std::iter::repeat_n(fill, w + 2));
        }
        out.push(end);
        out.push('\n');
    };
    let row = |out: &mut String, row: &mut dyn Iterator<Item = &str>| {
        out.push('│');
        for (i, c) in row.enumerate() {
            let pad = widths[i] - c.width();
            out.push(' ');
            if right[i] {
                out.extend(std::iter::repeat_n(' ', pad));
                out.push_str(c);
            } else {
                out.push_str(c);
                out.extend(std::iter::repeat_n(' ', pad));
            }
            out.push(' ');
            out.push(if i + 1 < n { '┆' } else { '│' });
        }
        out.push('\n');
    };
    out.reserve(cells.text.len() + cells.ends.len() * 8);
    rule(out, ['┌', '─', '┬', '┐']);
    row(out, &mut header.iter().map(String::as_str));
    rule(out, ['╞', '═', '╪', '╡']);
    let mut it = cells.iter();
    for _ in 0..cells.ends.len() / n {
        row(out, &mut it.by_ref().take(n));
    }
    rule(out, ['└', '─', '┴', '┘']);
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

    /// `fmt_sig` formats once where it can; this reference, as it was,
    /// twice (`{:.N$e}`, then fixed). Rounding that bumps the exponent
    /// (9.999996 → 10.0000) and decimal ties (123456.5) included.
    #[test]
    fn one_formatting_gives_the_digits_of_two() {
        fn reference(x: f64, digits: usize) -> String {
            let trim = |s: &str| {
                if s.contains('.') {
                    s.trim_end_matches('0').trim_end_matches('.').to_string()
                } else {
                    s.to_string()
                }
            };
            if x == 0.0 {
                return "0".to_string();
            }
            let places = digits.max(1) - 1;
            let sci = format!("{x:.places$e}");
            let (mantissa, exp) = sci.split_once('e').unwrap();
            let exp: i32 = exp.parse().unwrap();
            if (-4..6).contains(&exp) {
                let decimals = (places as i32 - exp).max(0) as usize;
                trim(&format!("{x:.decimals$}"))
            } else {
                format!("{}e{exp}", trim(mantissa))
            }
        }
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut xs = vec![
            9.999995,
            9.999996,
            99999.95,
            999999.5,
            0.000099999995,
            123456.5,
            2.5,
            99.95,
            0.5,
        ];
        for _ in 0..50_000 {
            xs.push(f64::from_bits(next()));
            // Uniform in [0, 10) times 1e-6 … 1e7: the fixed range and its edges.
            let m = (next() >> 11) as f64 / (1u64 << 53) as f64 * 10.0;
            xs.push(m * 10f64.powi((next() % 14) as i32 - 6));
        }
        for x in xs.into_iter().filter(|x| x.is_finite()) {
            for digits in [1, 3, 6, 17] {
                assert_eq!(
                    super::fmt_sig(x, digits),
                    reference(x, digits),
                    "{x:e}, {digits}"
                );
                assert_eq!(
                    super::fmt_sig(-x, digits),
                    reference(-x, digits),
                    "{:e}, {digits}",
                    -x
                );
            }
        }
    }
}
