//! The steps after the parts: the sums term by term, the inertia about
//! the centre of mass, the principal moments, H and T.

// NOTE: the three axes index several arrays together (a centroid, its
// axis's name, a sum), as the textbook's x, y, z do.
#![allow(clippy::needless_range_loop)]

use super::number::plain;
use super::parts::{Share, eq, eq_reported, joined, sum};
use super::{AXIS, ENTRIES, M, Math, Row, Step, Units, V, entry_name, shift, shown_entry, t, zero};
use crate::analysis::{Loaded, Products};
use crate::explain::exact::Exact;
use crate::numeric::Real;

/// The sums, the centre of mass, the principal moments, H and T.
pub fn totals(
    loaded: &Loaded,
    u: &Units,
    origin: &V,
    about_given: bool,
    products: Products,
    shares: &[Share],
    steps: &mut Vec<Step>,
) {
    let masses: Vec<Exact> = shares.iter().map(|s| s.mass).collect();
    let mass = sum(&masses);
    let mut rows = vec![Row::Note(vec![t(format!(
        "summing the respective terms of the {} items above",
        shares.len()
    ))])];
    let rep = &loaded.summary;
    // The report's figures are in SI: the same numbers where the file's
    // units are they.
    let si = u.inertia_si.exact == Some((1, 1));
    let kg = u.mass.text == "kg";
    let metre = u.length.text == "m";
    rows.push(eq_reported(
        Math::new("m", "m"),
        Some(Math::new("Σ m", "\\sum m")),
        Some(joined(&masses, " + ", " + ")),
        mass,
        &u.mass,
        reported(mass, rep.mass, kg),
    ));
    let mut g = [zero(); 3];
    for k in 0..3 {
        let terms: Vec<Exact> = shares.iter().map(|s| s.moment[k]).collect();
        let first = sum(&terms);
        let name = AXIS[k];
        rows.push(eq(
            Math::new(format!("Σ m·{name}_c"), format!("\\sum m\\,{name}_c")),
            None,
            Some(joined(&terms, " + ", " + ")),
            first,
            &Math::new(
                format!("{}·{}", u.mass.text, u.length.text),
                format!("{}\\,{}", u.mass.tex, u.length.tex),
            ),
        ));
        g[k] = if mass.is_zero() { zero() } else { first / mass };
        rows.push(eq_reported(
            Math::new(format!("{name}_G"), format!("{name}_G")),
            Some(Math::new(
                format!("Σ m·{name}_c / m"),
                format!("\\sum m\\,{name}_c / m"),
            )),
            Some(joined(&[first, mass], " / ", " / ")),
            g[k],
            &u.length,
            reported(g[k], rep.center_of_mass[k], metre),
        ));
    }
    let mut about = [[zero(); 3]; 3];
    for (a, b) in ENTRIES {
        let terms: Vec<Exact> = shares
            .iter()
            .map(|s| shown_entry(&s.about, (a, b), products))
            .collect();
        let total: Exact = shares.iter().fold(zero(), |acc, s| acc + s.about[a][b]);
        about[a][b] = total;
        about[b][a] = total;
        rows.push(eq(
            entry_name((a, b), "(O)", "(O)"),
            Some(Math::new(
                format!("Σ {}", entry_name((a, b), "(O)", "").text),
                format!("\\sum {}", entry_name((a, b), "", "").tex),
            )),
            Some(joined(&terms, " + ", " + ")),
            shown_entry(&about, (a, b), products),
            &u.inertia,
        ));
    }
    steps.push(Step {
        heading: vec![t(format!(
            "{}. the sums: mass, centre of mass G, inertia about O",
            steps.len() + 1
        ))],
        rows,
    });
    // About the centre of mass.
    let d: V = std::array::from_fn(|k| g[k] - origin[k]);
    let mut rows = vec![Row::Note(vec![t(
        "the parallel-axis theorem backwards, with d = G − O:",
    )])];
    let mut com = [[zero(); 3]; 3];
    for (a, b) in ENTRIES {
        com[a][b] = about[a][b] - shift(mass, &d, (a, b));
        com[b][a] = com[a][b];
        let o = shown_entry(&about, (a, b), products);
        let gv = shown_entry(&com, (a, b), products);
        let form = if a == b {
            let (j, k) = if a == 1 {
                (0, 2)
            } else {
                ((a + 1) % 3, (a + 2) % 3)
            };
            Math::new(
                format!(
                    "{} − m(d{}² + d{}²)",
                    entry_name((a, b), "(O)", "").text,
                    AXIS[j],
                    AXIS[k]
                ),
                format!(
                    "{} - m\\left(d_{}^{{2}} + d_{}^{{2}}\\right)",
                    entry_name((a, b), "", "(O)").tex,
                    AXIS[j],
                    AXIS[k]
                ),
            )
        } else {
            let s = if products == Products::Tensor {
                "+"
            } else {
                "−"
            };
            let st = if products == Products::Tensor {
                "+"
            } else {
                "-"
            };
            Math::new(
                format!(
                    "{} {s} m·d{}·d{}",
                    entry_name((a, b), "(O)", "").text,
                    AXIS[a],
                    AXIS[b]
                ),
                format!(
                    "{} {st} m\\,d_{}\\,d_{}",
                    entry_name((a, b), "", "(O)").tex,
                    AXIS[a],
                    AXIS[b]
                ),
            )
        };
        rows.push(eq_reported(
            entry_name((a, b), "(G)", "(G)"),
            Some(form),
            Some(joined(&[o, o - gv], " − ", " - ")),
            gv,
            &u.inertia,
            reported(
                gv,
                rep.inertia_com[a][b],
                si && loaded.analysis.axes.is_none(),
            ),
        ));
    }
    steps.push(Step {
        heading: vec![t(format!(
            "{}. the inertia about the centre of mass G",
            steps.len() + 1
        ))],
        rows,
    });
    principal(loaded, u, &com, steps);
    if about_given {
        dynamics(loaded, u, &about, products, steps);
    } else {
        dynamics(loaded, u, &com, products, steps);
    }
}

/// The report's figure `r` for `x`, where it is in the same units and
/// axes (`same`).
// NOTE: and within 1e-9 of the exact value: the report's f64 rounds the
// same sum; a figure further off is not this one (a convention or axes
// not accounted for), and the exact value is shown alone rather than it.
fn reported(x: Exact, r: f64, same: bool) -> Option<f64> {
    (same
        && r.is_finite()
        && (r - x.approx).abs() <= 1e-9 * x.approx.abs().max(r.abs()).max(f64::MIN_POSITIVE))
    .then_some(r)
}

/// The principal moments about G: the characteristic equation's
/// invariants exactly, its roots as the report's Jacobi solver found them.
fn principal(loaded: &Loaded, u: &Units, i: &M, steps: &mut Vec<Step>) {
    let i1 = i[0][0] + i[1][1] + i[2][2];
    let i2 = i[0][0] * i[1][1] + i[1][1] * i[2][2] + i[2][2] * i[0][0]
        - i[0][1] * i[0][1]
        - i[1][2] * i[1][2]
        - i[0][2] * i[0][2];
    let i3 = i[0][0] * (i[1][1] * i[2][2] - i[1][2] * i[1][2])
        - i[0][1] * (i[0][1] * i[2][2] - i[1][2] * i[0][2])
        + i[0][2] * (i[0][1] * i[1][2] - i[1][1] * i[0][2]);
    let mut rows = vec![Row::Note(vec![t(
        "the principal moments are the roots λ of the characteristic equation det(I(G) − λE) = λ³ − I₁λ² + I₂λ − I₃ = 0 (the tensor's own entries, whatever the products' sign convention), with",
    )])];
    let inertia2 = Math::new(
        format!("({})²", u.inertia.text),
        format!("\\left({}\\right)^{{2}}", u.inertia.tex),
    );
    let inertia3 = Math::new(
        format!("({})³", u.inertia.text),
        format!("\\left({}\\right)^{{3}}", u.inertia.tex),
    );
    rows.push(eq(
        Math::new("I₁", "I_1"),
        Some(Math::new("Ixx + Iyy + Izz", "I_{xx} + I_{yy} + I_{zz}")),
        None,
        i1,
        &u.inertia,
    ));
    rows.push(eq(
        Math::new("I₂", "I_2"),
        Some(Math::new(
            "Ixx·Iyy + Iyy·Izz + Izz·Ixx − Ixy² − Iyz² − Ixz²",
            "I_{xx}I_{yy} + I_{yy}I_{zz} + I_{zz}I_{xx} - I_{xy}^2 - I_{yz}^2 - I_{xz}^2",
        )),
        None,
        i2,
        &inertia2,
    ));
    rows.push(eq(
        Math::new("I₃", "I_3"),
        Some(Math::new("det I(G)", "\\det I(G)")),
        None,
        i3,
        &inertia3,
    ));
    rows.push(Row::Note(vec![t(
        "its roots, found by Jacobi rotations (massprop's eigen solver; the cubic's closed form loses digits where two roots are close), ascending, with their axes in the report's axes:",
    )]));
    let s = &loaded.summary;
    let per = u.inertia_si.approx;
    for k in 0..3 {
        let a = s.principal_axes[k];
        rows.push(eq(
            Math::new(format!("λ{}", k + 1), format!("\\lambda_{}", k + 1)),
            None,
            None,
            Exact::inexact(s.principal_moments[k] / per),
            &u.inertia,
        ));
        rows.push(Row::Note(vec![t(format!(
            "axis {}: ({}, {}, {})",
            k + 1,
            crate::output::format::shortest(a[0]),
            crate::output::format::shortest(a[1]),
            crate::output::format::shortest(a[2])
        ))]));
    }
    steps.push(Step {
        heading: vec![t(format!(
            "{}. principal moments and axes about G",
            steps.len() + 1
        ))],
        rows,
    });
}

/// H = I·ω and T = ½ ωᵀ I ω about the reference point, in SI.
fn dynamics(loaded: &Loaded, u: &Units, i: &M, products: Products, steps: &mut Vec<Step>) {
    let Some(w) = loaded.analysis.omega else {
        return;
    };
    if loaded.analysis.axes.is_some() {
        return;
    }
    let w: V = [w.x, w.y, w.z].map(Exact::of);
    let si: M = i.map(|r| r.map(|x| x * u.inertia_si));
    let mut rows = vec![Row::Note(vec![t(format!(
        "ω = ({}, {}, {}) rad/s; I about the reference point in kg·m² (× {} per {}):",
        plain(w[0]),
        plain(w[1]),
        plain(w[2]),
        plain(u.inertia_si),
        u.inertia.text
    ))])];
    let kgm2 = Math::new("kg·m²", "\\mathrm{kg\\,m^{2}}");
    for e in ENTRIES {
        rows.push(eq(
            entry_name(e, "", ""),
            None,
            None,
            shown_entry(&si, e, products),
            &kgm2,
        ));
    }
    let mut h = [zero(); 3];
    for a in 0..3 {
        h[a] = (0..3).fold(zero(), |acc, b| acc + si[a][b] * w[b]);
        let names: Vec<Math> = (0..3)
            .map(|b| entry_name((a.min(b), a.max(b)), "", ""))
            .collect();
        let form_t: Vec<String> = (0..3)
            .map(|b| format!("{}·ω{}", names[b].text, AXIS[b]))
            .collect();
        let form_x: Vec<String> = (0..3)
            .map(|b| format!("{}\\,\\omega_{}", names[b].tex, AXIS[b]))
            .collect();
        let sub: Vec<Math> = (0..3)
            .map(|b| {
                joined(
                    &[shown_entry(&si, (a.min(b), a.max(b)), products), w[b]],
                    " × ",
                    " \\times ",
                )
            })
            .collect();
        // In order x, y, z; a product's term negative under the positive
        // convention (the tensor's entry is −Ixy).
        let join = |v: Vec<String>, tex: bool| {
            (0..3)
                .map(|b| {
                    let minus = products == Products::Positive && b != a;
                    match (b == 0, minus, tex) {
                        (true, false, _) => v[b].clone(),
                        (true, true, false) => format!("−{}", v[b]),
                        (true, true, true) => format!("-{}", v[b]),
                        (false, false, _) => format!(" + {}", v[b]),
                        (false, true, false) => format!(" − {}", v[b]),
                        (false, true, true) => format!(" - {}", v[b]),
                    }
                })
                .collect::<String>()
        };
        rows.push(eq_reported(
            Math::new(format!("H{}", AXIS[a]), format!("H_{}", AXIS[a])),
            Some(Math::new(join(form_t, false), join(form_x, true))),
            Some(Math::new(
                join(sub.iter().map(|m| m.text.clone()).collect(), false),
                join(sub.iter().map(|m| m.tex.clone()).collect(), true),
            )),
            h[a],
            &Math::new("N·m·s", "\\mathrm{N\\,m\\,s}"),
            loaded
                .summary
                .angular_momentum
                .and_then(|r| reported(h[a], r[a], true)),
        ));
    }
    let energy = (0..3).fold(zero(), |acc, a| acc + w[a] * h[a]) * Exact::ratio(1, 2);
    rows.push(eq_reported(
        Math::new("T", "T"),
        Some(Math::new("½ ωᵀ I ω = ½(ωx·Hx + ωy·Hy + ωz·Hz)", "\\tfrac{1}{2}\\,\\omega^{T} I\\,\\omega = \\tfrac{1}{2}\\left(\\omega_x H_x + \\omega_y H_y + \\omega_z H_z\\right)")),
        Some({
            let x = joined(&[w[0], h[0], w[1], h[1], w[2], h[2]], " × ", " \\times ");
            let parts: Vec<&str> = x.text.split(" × ").collect();
            let tparts: Vec<&str> = x.tex.split(" \\times ").collect();
            Math::new(
                format!("½({} × {} + {} × {} + {} × {})", parts[0], parts[1], parts[2], parts[3], parts[4], parts[5]),
                format!("\\tfrac{{1}}{{2}}\\left({} \\times {} + {} \\times {} + {} \\times {}\\right)", tparts[0], tparts[1], tparts[2], tparts[3], tparts[4], tparts[5]),
            )
        }),
        energy,
        &Math::new("J", "\\mathrm{J}"),
        loaded
            .summary
            .kinetic_energy
            .and_then(|r| reported(energy, r, true)),
    ));
    steps.push(Step {
        heading: vec![t(format!(
            "{}. angular momentum H = I·ω and kinetic energy T = ½ ωᵀ I ω",
            steps.len() + 1
        ))],
        rows,
    });
}
