//! The short report, plain `report`'s: the answer most readers want first
//! (mass, centre of mass, inertia about it, principal moments and axes,
//! and with ω the kinetic energy, H, α and M) in about 25 lines, in the
//! same tables as the full report (`super`, `--full`). A table a flag asked
//! for (`--about`'s tensors, `--uncertainty`) is shown too; the rest
//! (radii of gyration, the parts, the sub-assemblies, the idealisation) is
//! named on the last line, which says to ask `--full` for it.
//!
//! NOTE: no row per part: the short report of a tree of millions of
//! instances is as short as a plate's (issue 33).

use super::{Detail, Principal, file_axes, fit, precision_line, principal_table};
use crate::analysis::summary::Summary;
use crate::output::format::{DisplayUnits, MOMENT_UNIT, equal_note, fmt_bounded, fmt_num};
use crate::output::grid::{Fit, write_rows};
use crate::units::Dim;
use std::fmt::Write;

/// The short report of `s` (from the file `source`); tables wider than
/// `width` split (`grid::Fit`).
pub(super) fn table(s: &Summary, source: &str, detail: Detail, width: Option<usize>) -> String {
    let u = DisplayUnits::of(s.file_units);
    let mut out = String::new();
    super::title(&mut out, &s.name, &s.sub_assembly, source);
    super::units_lines(
        &mut out,
        &u,
        "; ω, H, T, α and M in SI",
        s.products_convention,
    );
    // The axes and the arithmetic only where they are not the defaults a
    // reader assumes: other axes are needed to read every number; a
    // precision asked for, or values short of `--rtol`, are worth a line.
    let turned = !file_axes(&s.axes);
    if turned {
        let _ = writeln!(out, "{}", super::axes_line(&s.axes));
    }
    let precision_shown = precision_worth_a_line(s);
    if precision_shown {
        let _ = writeln!(out, "{}", precision_line(s));
    }
    let b = &s.error_bounds;
    let own = |v: f64, e: f64, scale: f64| fmt_bounded(v / scale, e / scale, (v / scale).abs());
    let _ = write!(
        out,
        "\nmass: {} {}",
        own(s.mass, b.mass, u.mass),
        u.mass_label
    );
    if let (Some(t), Some(e)) = (s.kinetic_energy, b.kinetic_energy) {
        let (scale, unit) = u.of_dim(Dim::ENERGY);
        let parts = super::motion::energy_parts(s);
        let _ = write!(
            out,
            "; kinetic energy T: {} {unit}{parts}",
            own(t, e, scale)
        );
    }
    out.push('\n');
    body_table(&mut out, s, &u, width);
    super::axles::write(&mut out, s, &u, width);
    super::envelope::write(&mut out, s.envelope.as_ref(), &u);

    if detail.about_flag && s.reference_given {
        let p = s.reference_point.map(|x| fmt_num(x / u.length));
        let _ = writeln!(
            out,
            "inertia about the reference point ({}, {}, {}) {} ({})",
            p[0], p[1], p[2], u.length_label, u.inertia_label
        );
        super::matrix_table(&mut out, (&s.inertia_ref, &b.inertia_ref), u.inertia, width);
    }
    let _ = writeln!(
        out,
        "principal moments and axes about the centre of mass (ascending)"
    );
    principal_table(
        &mut out,
        Principal {
            moments: (&s.principal_moments, &b.principal_moments),
            axes: (&s.principal_axes, &b.principal_axes),
            radii: None,
            equal: &s.equal_moments,
        },
        &u,
        width,
    );
    equal_note(&mut out, &s.equal_moments);
    if detail.about_flag && s.reference_given {
        super::principal_about_reference(&mut out, s, &u, width);
    }
    if let Some(x) = &s.uncertainty {
        super::uncertainty(&mut out, x, &u, width);
    }
    let _ = writeln!(out, "{}", more_line(s, detail, precision_shown));
    out
}

/// Whether the short report keeps the precision line: when a precision
/// was asked for (`--precision`), or a value falls short of `--rtol`
/// (the warnings on standard error say which).
fn precision_worth_a_line(s: &Summary) -> bool {
    use crate::analysis::summary::PrecisionChoice;
    let asked = match s.requested {
        PrecisionChoice::Auto => false,
        PrecisionChoice::Standard | PrecisionChoice::Extended => true,
    };
    asked || !s.accuracy_warnings.is_empty()
}

/// One table of the vectors and the inertia tensor, which share its
/// columns (x, y, z, unit): the centre of mass, the tensor's rows about
/// it, then ω, H, α and M when the file or a flag gives ω.
fn body_table(out: &mut String, s: &Summary, u: &DisplayUnits, width: Option<usize>) {
    let b = &s.error_bounds;
    let mut rows = Vec::new();
    // Given vectors (ω, α) are exact: no bound.
    let exact = [0.0; 3];
    let row = |label: String, v: &[f64; 3], e: &[f64; 3], (scale, unit): (f64, &str), top| {
        let mut cells = vec![label];
        cells.extend(
            v.iter()
                .zip(e)
                .map(|(x, e)| fmt_bounded(x / scale, e / scale, top)),
        );
        cells.push(unit.to_string());
        cells
    };
    // Each vector's digits read against its largest entry; the tensor's
    // against its largest, as `matrix_table` does.
    let top_of = |v: &[f64], scale: f64| v.iter().fold(0.0f64, |a, x| a.max(x.abs())) / scale;
    let length = u.of_dim(Dim::LENGTH);
    let turned = !file_axes(&s.axes);
    let com = if turned {
        "centre of mass (file's frame)"
    } else {
        "centre of mass"
    };
    rows.push(row(
        com.to_string(),
        &s.center_of_mass,
        &b.center_of_mass,
        length,
        top_of(&s.center_of_mass, length.0),
    ));
    let inertia = (u.inertia, u.inertia_label.as_str());
    let top = top_of(s.inertia_com.as_flattened(), u.inertia);
    let first = "inertia about it x";
    for (i, axis) in ["x", "y", "z"].iter().enumerate() {
        // The tensor's rows under one label, their axis letters aligned.
        let label = if i == 0 {
            first.to_string()
        } else {
            format!("{}{axis}", " ".repeat(first.len() - 1))
        };
        rows.push(row(
            label,
            &s.inertia_com[i],
            &b.inertia_com[i],
            inertia,
            top,
        ));
    }
    // H, T and M are about the reference point when one is given (about
    // the centre of mass else): its row, named O, says where.
    let about = if s.reference_given && s.omega.is_some() {
        rows.push(row(
            "reference point O".into(),
            &s.reference_point,
            &exact,
            length,
            top_of(&s.reference_point, length.0),
        ));
        " about O"
    } else {
        ""
    };
    if let Some(w) = &s.omega {
        let unit = u.of_dim(Dim::ANGULAR_VELOCITY);
        let top = top_of(w, unit.0);
        rows.push(row("angular velocity ω".into(), w, &exact, unit, top));
    }
    if let (Some(h), Some(e)) = (&s.angular_momentum, &b.angular_momentum) {
        let unit = u.of_dim(Dim::ANGULAR_MOMENTUM);
        let top = top_of(h, unit.0);
        rows.push(row(format!("angular momentum H{about}"), h, e, unit, top));
    }
    for (label, v, e, unit) in super::motion::rows(s) {
        let top = top_of(&v, 1.0);
        rows.push(row(label.into(), &v, &e, (1.0, unit), top));
    }
    if let Some(a) = &s.alpha {
        let unit = u.of_dim(Dim::ANGULAR_ACCELERATION);
        let top = top_of(a, unit.0);
        rows.push(row("angular acceleration α".into(), a, &exact, unit, top));
    }
    if let (Some(m), Some(e)) = (&s.euler_moment, &b.euler_moment) {
        // A moment has the dimension of an energy, but is not one: SI,
        // labelled N·m.
        let top = top_of(m, 1.0);
        rows.push(row(
            format!("Euler moment M{about}"),
            m,
            e,
            (1.0, MOMENT_UNIT),
            top,
        ));
    }
    let header = ["", "x", "y", "z", "unit"].map(String::from);
    // Numbers right, the unit left.
    let right = [false, true, true, true, false];
    let fit = Fit {
        groups: &[(1, 4)],
        ..fit(width)
    };
    write_rows(out, &header, &rows, &right, fit);
}

/// The last line: what `--full` adds for this body.
fn more_line(s: &Summary, detail: Detail, precision_shown: bool) -> String {
    let mut more = vec!["radii of gyration".to_string()];
    if s.reference_given && !detail.about_flag {
        // The body table names the point O when it shows H about it.
        more.push(match s.omega {
            Some(_) => "the tensors about O".to_string(),
            None => "the reference point's tensors".to_string(),
        });
    }
    if !precision_shown {
        more.push("precision".to_string());
    }
    more.push(match s.parts.len() {
        1 => "the part".to_string(),
        n => format!("the {n} parts"),
    });
    if !s.assemblies.is_empty() {
        more.push("sub-assemblies".to_string());
    }
    if s.idealisation.is_some() {
        more.push("idealisation".to_string());
    }
    let last = more.pop().expect("invariant: the list has the parts");
    if more.is_empty() {
        format!("`--full` for {last}")
    } else {
        format!("`--full` for {} and {last}", more.join(", "))
    }
}
