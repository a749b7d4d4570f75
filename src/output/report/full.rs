//! The full report's tables of a row per part and per sub-assembly,
//! streamed from the model's walk as typed cells (`grid::stream_cells`):
//! a body of 2²⁰ instances has as many rows of each, never all held.

use super::super::format::DisplayUnits;
use super::super::grid::{Cell, Fit, stream_cells};
use crate::analysis::summary::{AssemblyRow, Row, Summary, Summing};

/// The cells a part's and a sub-assembly's rows share: mass and its
/// share, centre of mass, shares of the principal moments.
fn figures(
    u: &DisplayUnits,
    (mass, fraction): (f64, f64),
    center: &[f64; 3],
    shares: &[Option<f64>; 3],
) -> [Cell<'static>; 8] {
    let at = |x: f64| Cell::Sig(x / u.length, 6);
    [
        Cell::Sig(mass / u.mass, 6),
        Cell::Percent(Some(fraction)),
        at(center[0]),
        at(center[1]),
        at(center[2]),
        Cell::Percent(shares[0]),
        Cell::Percent(shares[1]),
        Cell::Percent(shares[2]),
    ]
}

/// A row: its first cells, then its figures.
fn row<'a, const N: usize, const M: usize>(
    first: [Cell<'a>; N],
    figures: [Cell<'a>; 8],
) -> [Cell<'a>; M] {
    debug_assert_eq!(
        N + 8,
        M,
        "invariant: a row is its first cells and its figures"
    );
    std::array::from_fn(|i| if i < N { first[i] } else { figures[i - N] })
}

/// The parts table, a row per part in file order; whether a principal
/// moment had no shares (the note below the table says what `—` means),
/// and the sub-assemblies summed from its first walk of the parts
/// (`Summing`), for `assemblies`.
///
/// NOTE: the sub-assemblies' table needs each summed, which takes a walk
/// placing every part (a fifth of the `--full` report of 2²⁰ instances,
/// on one core while the other idled): the rows walked here carry what is summed, the same
/// bits, so that walk is not made again.
pub(super) fn parts(
    w: &mut dyn std::io::Write,
    s: &Summary,
    u: &DisplayUnits,
    width: Option<usize>,
) -> std::io::Result<(bool, Option<Summing>)> {
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
    // Left-aligned: name and shape.
    let right: Vec<bool> = (0..header.len()).map(|i| !(1..3).contains(&i)).collect();
    let mut undefined = false;
    // Split, each part keeps the number and the name, and the centroid's
    // coordinates and the shares together.
    let fit = Fit {
        groups: &[(5, 8), (8, 11)],
        ..Fit::new(width, 2)
    };
    // NOTE: the path of sub-assemblies (`a / b / `) is made once per
    // sub-assembly entered (`Parts::each_row`), not per part; each row's
    // name is that and the part's own.
    let mut prefix = String::new();
    let mut lengths = Vec::new();
    let mut name = String::new();
    let mut summed = None;
    stream_cells(w, &header, &right, fit, &mut |sink| {
        let mut i = 0usize;
        prefix.clear();
        lengths.clear();
        // The first walk sums the sub-assemblies, if there are any.
        let mut summing = (summed.is_none() && !s.assemblies.is_empty()).then(Summing::default);
        s.parts.each_row(&mut |r| {
            let p = match r {
                Row::Enter(n) => {
                    lengths.push(prefix.len());
                    prefix.push_str(n);
                    prefix.push_str(" / ");
                    if let Some(x) = &mut summing {
                        x.enter();
                    }
                    return;
                }
                Row::Exit => {
                    prefix.truncate(lengths.pop().expect("an Exit follows its Enter"));
                    if let Some(x) = &mut summing {
                        x.exit();
                    }
                    return;
                }
                Row::Part(p) => p,
            };
            if let Some(x) = &mut summing {
                x.part(p.mass, p.center_of_mass, p.principal_moment_share);
            }
            i += 1;
            name.clear();
            name.push_str(&prefix);
            p.push_name(&mut name);
            undefined |= p.principal_moment_share.contains(&None);
            let figures = figures(
                u,
                (p.mass, p.mass_fraction),
                &p.center_of_mass,
                &p.principal_moment_share,
            );
            let first = [
                Cell::Count(i),
                Cell::Name(&name),
                Cell::Text(p.shape.name()),
            ];
            sink(&row::<3, 11>(first, figures));
        });
        if summing.is_some() {
            summed = summing;
        }
    })?;
    Ok((undefined, summed))
}

/// The sub-assemblies section: each with its mass, centre of mass and
/// shares, indented by depth, parents before children; `summing`: the
/// parts table's sums (`parts`), else they are summed here.
pub(super) fn assemblies(
    w: &mut dyn std::io::Write,
    s: &Summary,
    u: &DisplayUnits,
    width: Option<usize>,
    summing: Option<Summing>,
) -> std::io::Result<()> {
    let header = [
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
    ];
    let right: Vec<bool> = (0..header.len()).map(|i| i >= 1).collect();
    w.write_all(b"\nsub-assemblies\n")?;
    let fit = Fit {
        groups: &[(4, 7), (7, 10)],
        ..super::fit(width)
    };
    // NOTE: summed once (a walk placing every part), walked twice.
    let summed = match summing {
        Some(x) => s.assemblies.summed_from(x),
        None => s.assemblies.summed(),
    };
    stream_cells(w, &header, &right, fit, &mut |sink| {
        // How deep the walk is: a sub-assembly's indent is one less.
        let mut depth = 0usize;
        summed.each_row(&mut |r| match r {
            AssemblyRow::Enter(name, a) => {
                let figures = figures(
                    u,
                    (a.mass, a.mass_fraction),
                    &a.center_of_mass,
                    &a.principal_moment_share,
                );
                let first = [Cell::Indented(depth, name), Cell::Count(a.parts)];
                sink(&row::<2, 10>(first, figures));
                depth += 1;
            }
            AssemblyRow::Exit => depth -= 1,
        });
    })
}
