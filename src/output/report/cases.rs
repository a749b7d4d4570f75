//! `report --cases`: a row per state of the body, the base first, in the
//! file's units (mass, centre of mass, principal moments, `--full` the
//! inertia about the centre of mass, and the axle loads where the file
//! has axles); JSON: the base's plain report with `cases`, an array of
//! each case's plain report, its name under `case` first.

use crate::analysis::summary::Summary;
use crate::output::Format;
use crate::output::format::{DisplayUnits, fmt_num, push_name};
use crate::output::grid::write_rows;
use std::fmt::Write;

/// The document in `format` (the CI formats, which `report` has not, as
/// the table).
pub fn render(
    base: &Summary,
    cases: &[(&str, &Summary)],
    format: Format,
    full: bool,
    width: Option<usize>,
) -> String {
    match format {
        Format::Json => json(base, cases),
        Format::Table | Format::Github | Format::Junit | Format::Sarif => {
            table(base, cases, full, width)
        }
    }
}

/// The base's report object with `"cases": [...]` after its last key.
///
/// NOTE: each object is the plain report's own JSON (`report::json`, so
/// every key and number exactly as `report --case NAME --format json`
/// writes them), `"case"` put before its first key.
pub fn json(base: &Summary, cases: &[(&str, &Summary)]) -> String {
    let top = super::json(base);
    let top = top.trim_end();
    let head = top.strip_suffix('}').unwrap_or(top);
    let mut s = String::with_capacity(top.len() * (cases.len() + 1));
    s.push_str(head);
    s.push_str(if head.ends_with('{') {
        "\"cases\":["
    } else {
        ",\"cases\":["
    });
    for (k, (name, summary)) in cases.iter().enumerate() {
        let report = super::json(summary);
        let report = report.trim_end();
        let rest = report.strip_prefix('{').unwrap_or(report);
        let _ = write!(
            s,
            "{}{{\"case\":{}{}{rest}",
            if k == 0 { "" } else { "," },
            crate::output::json_line(name).trim_end(),
            if rest == "}" { "" } else { "," }
        );
    }
    s.push_str("]}\n");
    s
}

/// One row per state: the base, then each case in file order.
pub fn table(
    base: &Summary,
    cases: &[(&str, &Summary)],
    full: bool,
    width: Option<usize>,
) -> String {
    let u = DisplayUnits::of(base.file_units);
    let axles = base.axle_loads.is_some() || cases.iter().any(|(_, s)| s.axle_loads.is_some());
    let envelope = base.envelope.is_some() || cases.iter().any(|(_, s)| s.envelope.is_some());
    let mac = (base.envelope.iter())
        .chain(cases.iter().filter_map(|(_, s)| s.envelope.as_ref()))
        .any(|e| e.mac.is_some());
    let length = u.length_label;
    let mut header: Vec<String> = vec![
        "case".into(),
        format!("mass ({})", u.mass_label),
        format!("x ({length})"),
        format!("y ({length})"),
        format!("z ({length})"),
        format!("I1 ({})", u.inertia_label),
        "I2".into(),
        "I3".into(),
    ];
    if full {
        header.extend(["Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"].map(String::from));
    }
    if axles {
        header.extend(["front (N)", "front (%)", "rear (N)", "rear (%)"].map(String::from));
    }
    if envelope {
        header.push(format!("margin ({length})"));
    }
    if mac {
        header.push("% MAC".into());
    }
    let row = |name: &str, s: &Summary| {
        let mut label = String::new();
        push_name(&mut label, name);
        let mut cells = vec![label, fmt_num(s.mass / u.mass)];
        cells.extend(s.center_of_mass.map(|x| fmt_num(x / u.length)));
        cells.extend(s.principal_moments.map(|x| fmt_num(x / u.inertia)));
        if full {
            let i = s.inertia_com;
            let six = [i[0][0], i[1][1], i[2][2], i[0][1], i[0][2], i[1][2]];
            cells.extend(six.map(|x| fmt_num(x / u.inertia)));
        }
        if axles {
            match &s.axle_loads {
                Some(a) => cells.extend([
                    fmt_num(a.front.load),
                    fmt_num(100.0 * a.front.share),
                    fmt_num(a.rear.load),
                    fmt_num(100.0 * a.rear.share),
                ]),
                None => cells.extend(["-", "-", "-", "-"].map(String::from)),
            }
        }
        // The envelope's margin (`-` where the mass is outside its
        // range) and the coordinate in % MAC.
        if envelope {
            let margin = s.envelope.and_then(|e| e.margin);
            cells.push(margin.map_or("-".into(), |d| fmt_num(d / u.length)));
        }
        if mac {
            let p = s.envelope.and_then(|e| e.mac);
            cells.push(p.map_or("-".into(), fmt_num));
        }
        cells
    };
    let mut rows = vec![row("base", base)];
    rows.extend(cases.iter().map(|(name, s)| row(name, s)));
    let mut out = String::new();
    super::title(
        &mut out,
        &base.name,
        &base.sub_assembly,
        base.source.as_deref().unwrap_or(""),
    );
    super::units_lines(&mut out, &u, "", base.products_convention);
    out.push('\n');
    let right: Vec<bool> = (0..header.len()).map(|i| i > 0).collect();
    write_rows(&mut out, &header, &rows, &right, super::fit(width));
    out
}
