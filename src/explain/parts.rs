//! The steps of `explain`: each part of the file's own (or a line for a
//! sub-assembly, an array or a mesh), then the sums, the centre of mass,
//! the principal moments, H and T.

// NOTE: the three axes index several arrays together (a centroid, its
// axis's name, a sum), as the textbook's x, y, z do.
#![allow(clippy::needless_range_loop)]

use super::formula::{self, Symbols};
use super::number::{plain, tex};
use super::{
    ENTRIES, M, Math, Piece, Row, Step, Units, V, entry_name, shift, shown_entry, t, tensor, zero,
};
use crate::analysis::{Loaded, Products};
use crate::explain::exact::Exact;
use crate::numeric::Real;
use crate::part::{MassSpec, Part, Spec};
use crate::shapes::{Fixed, Shape, Slot};

/// One item's share of the sums: a part's, or a group's.
pub struct Share {
    pub mass: Exact,
    /// Σ m c.
    pub moment: V,
    /// The inertia tensor about O (tensor convention).
    pub about: M,
}

const AXIS: [&str; 3] = ["x", "y", "z"];

fn eq(lhs: Math, form: Option<Math>, subst: Option<Math>, value: Exact, unit: &Math) -> Row {
    Row::Eq {
        lhs,
        form,
        subst,
        value,
        unit: unit.clone(),
    }
}

/// The numbers `x` joined by `op` (text and TeX), each shown plainly,
/// negative ones in parentheses.
fn joined(xs: &[Exact], op: &str, tex_op: &str) -> Math {
    let one = |x: &Exact, tx: bool| {
        let s = if tx {
            super::number::tex_number(&plain(*x))
        } else {
            plain(*x)
        };
        if *x < zero() { format!("({s})") } else { s }
    };
    Math::new(
        xs.iter()
            .map(|x| one(x, false))
            .collect::<Vec<_>>()
            .join(op),
        xs.iter()
            .map(|x| one(x, true))
            .collect::<Vec<_>>()
            .join(tex_op),
    )
}

fn sum(xs: &[Exact]) -> Exact {
    xs.iter().fold(zero(), |a, &b| a + b)
}

/// A part's physics in `Exact`: mass, centroid, inertia about its
/// centroid in the file's axes (tensor convention).
fn physics(spec: &Spec) -> (Exact, V, M) {
    let (m, c, j) = crate::part::physics_in::<Exact, _>(spec, Fixed);
    (m, c, tensor(&j))
}

/// The share of a part at its centroid `c` about O.
fn share_of(m: Exact, c: &V, i: &M, origin: &V) -> Share {
    let d: V = std::array::from_fn(|k| c[k] - origin[k]);
    let about = std::array::from_fn(|a| {
        std::array::from_fn(|b| i[a][b] + shift(m, &d, (a.min(b), a.max(b))))
    });
    Share {
        mass: m,
        moment: c.map(|x| m * x),
        about,
    }
}

/// A group of the body's parts met together: one part of the file, its
/// copies, or a sub-assembly.
struct Group {
    key: Key,
    parts: Vec<Part>,
}

#[derive(PartialEq)]
enum Key {
    Own(std::ops::Range<usize>),
    Sub(String),
}

/// Explain each item of the file in turn; their shares.
pub fn each(
    loaded: &Loaded,
    u: &Units,
    origin: &V,
    products: Products,
    steps: &mut Vec<Step>,
) -> Vec<Share> {
    let mut groups: Vec<Group> = Vec::new();
    loaded.model.each_part(&mut |leaf| {
        let key = match leaf.part.assembly.first() {
            Some(a) => Key::Sub(a.clone()),
            None => Key::Own(leaf.part.span.clone()),
        };
        match groups.last_mut() {
            Some(g) if g.key == key => g.parts.push(leaf.part.clone()),
            _ => groups.push(Group {
                key,
                parts: vec![leaf.part.clone()],
            }),
        }
    });
    let mut shares = Vec::new();
    let mut lines = Vec::new();
    for g in groups {
        let single = g.parts.len() == 1 && matches!(g.key, Key::Own(_));
        if single && g.parts[0].shape() != Shape::Mesh {
            let (step, share) = part_step(&g.parts[0], steps.len() + 1, u, origin, products);
            steps.push(step);
            shares.push(share);
        } else {
            let (row, share) = group_line(&g, u, origin, products);
            lines.push(row);
            shares.push(share);
        }
    }
    if !lines.is_empty() {
        steps.push(Step {
            heading: vec![t(format!(
                "{}. sub-assemblies, arrays and meshes, a line each (`--only NAME` explains a sub-assembly)",
                steps.len() + 1
            ))],
            rows: lines,
        });
    }
    shares
}

fn group_line(g: &Group, u: &Units, origin: &V, products: Products) -> (Row, Share) {
    let first = &g.parts[0];
    let label = match &g.key {
        Key::Sub(name) => vec![
            t("sub-assembly "),
            Piece::Name(name.clone()),
            t(format!(" ({} parts)", g.parts.len())),
        ],
        Key::Own(_) if g.parts.len() > 1 => vec![
            t("part "),
            Piece::Name(first.name.clone()),
            t(format!(" and its copies ({} in all)", g.parts.len())),
        ],
        Key::Own(_) => vec![t("mesh "), Piece::Name(first.name.clone())],
    };
    let mut total = Share {
        mass: zero(),
        moment: [zero(); 3],
        about: [[zero(); 3]; 3],
    };
    for p in &g.parts {
        let (m, c, i) = physics(&p.spec);
        let s = share_of(m, &c, &i, origin);
        total.mass = total.mass + s.mass;
        for k in 0..3 {
            total.moment[k] = total.moment[k] + s.moment[k];
            for l in 0..3 {
                total.about[k][l] = total.about[k][l] + s.about[k][l];
            }
        }
    }
    let mut items = vec![(Math::new("m", "m"), total.mass, u.mass.clone())];
    if !total.mass.is_zero() {
        for k in 0..3 {
            items.push((
                Math::new(format!("{}_c", AXIS[k]), format!("{}_c", AXIS[k])),
                total.moment[k] / total.mass,
                u.length.clone(),
            ));
        }
    }
    for e in ENTRIES {
        items.push((
            entry_name(e, "(O)", "(O)"),
            shown_entry(&total.about, e, products),
            u.inertia.clone(),
        ));
    }
    (Row::Summary { label, items }, total)
}

/// The symbols of a shape's templates with their values, or as symbols.
struct Values<'a> {
    names: &'a [crate::shapes::Symbol],
    values: &'a [Exact],
    m: Exact,
    numeric: bool,
}

impl Symbols for Values<'_> {
    fn symbol(&self, i: usize, tx: bool) -> String {
        match (self.numeric, i == usize::MAX) {
            (false, true) => "m".into(),
            (false, false) if tx => self.names[i].tex.into(),
            (false, false) => self.names[i].name.into(),
            (true, true) if tx => super::number::tex_number(&plain(self.m)),
            (true, true) => plain(self.m),
            (true, false) if tx => super::number::tex_number(&plain(self.values[i])),
            (true, false) => plain(self.values[i]),
        }
    }
    fn negative(&self, i: usize) -> bool {
        self.numeric
            && if i == usize::MAX {
                self.m < zero()
            } else {
                self.values[i] < zero()
            }
    }
    fn numeric(&self) -> bool {
        self.numeric
    }
}

/// A template written both ways: with the symbols, and with the numbers.
fn written(template: &str, v: &Values) -> Option<(Math, Math)> {
    let names: Vec<&str> = v.names.iter().map(|s| s.name).collect();
    let n = formula::parse(template, &names).ok()?;
    let sym = Values {
        numeric: false,
        ..*v
    };
    let num = Values {
        numeric: true,
        ..*v
    };
    Some((
        Math::new(
            formula::write(&n, &sym, false),
            formula::write(&n, &sym, true),
        ),
        Math::new(
            formula::write(&n, &num, false),
            formula::write(&n, &num, true),
        ),
    ))
}

/// A shape's dimensions in the order of its closed forms, from its
/// numbers by slot (a size given by an edge: the edge's length; a rod by
/// its ends: their distance), with how each was found.
fn dims(spec: &Spec, shape: Shape) -> Option<Vec<(Exact, Option<String>)>> {
    let mut place = spec.place.clone();
    let mut found: Vec<(Slot, f64)> = Vec::new();
    place.numbers(&mut |s, x| found.push((s, *x)));
    let get = |s: Slot| {
        found
            .iter()
            .find(|(f, _)| *f == s)
            .map(|(_, x)| Exact::of(*x))
    };
    shape
        .explain()
        .dims
        .iter()
        .map(|sym| {
            if let Some(x) = get(sym.slot) {
                return Some((x, None));
            }
            let (v, how) = match sym.slot {
                Slot::Size(k) => (
                    (0..3)
                        .map(|i| get(Slot::Edge(k, i)))
                        .collect::<Option<Vec<_>>>()?,
                    format!("|edge {}|", k + 1),
                ),
                Slot::Length => (
                    (0..3)
                        .map(|i| Some(get(Slot::To(i))? - get(Slot::At(i))?))
                        .collect::<Option<Vec<_>>>()?,
                    "|to − from|".into(),
                ),
                _ => return None,
            };
            Some((v.iter().fold(zero(), |a, &x| a + x * x).sqrt(), Some(how)))
        })
        .collect()
}

/// A part of the file's own, explained in full; its share.
fn part_step(p: &Part, n: usize, u: &Units, origin: &V, products: Products) -> (Step, Share) {
    let shape = p.shape();
    let e = shape.explain();
    let mut heading = vec![t(format!("{n}. part ")), Piece::Name(p.name.clone())];
    heading.push(t(format!(": {}, {}", shape.name(), e.form)));
    let mut rows = Vec::new();
    let (m, c, i) = physics(&p.spec);
    let dims = dims(&p.spec, shape);
    let values: Vec<Exact> = dims.iter().flatten().map(|d| d.0).collect();
    let v = Values {
        names: e.dims,
        values: &values,
        m,
        numeric: false,
    };
    // Its dimensions.
    if let Some(dims) = &dims {
        for (sym, (x, how)) in e.dims.iter().zip(dims) {
            let form = how
                .as_ref()
                .map(|h| Math::new(h.clone(), format!("\\text{{{}}}", h.replace('−', "-"))));
            rows.push(eq(Math::new(sym.name, sym.tex), form, None, *x, &u.length));
        }
    }
    // Its mass.
    let sign = if p.spec.removed {
        ("−", "-")
    } else {
        ("", "")
    };
    match p.spec.mass {
        MassSpec::Given(given) => {
            rows.push(Row::Note(vec![t("its mass is given")]));
            rows.push(eq(
                Math::new("m", "m"),
                Some(Math::new(
                    format!("{}{}", sign.0, plain(Exact::of(given))),
                    format!("{}{}", sign.1, tex(Exact::of(given))),
                )),
                None,
                m,
                &u.mass,
            ));
        }
        MassSpec::Density(rho) => {
            let rho = Exact::of(rho);
            let power = shape.info().density.map_or(3, |d| d.length_power) as usize;
            let measure = if e.measure.is_empty() || dims.is_none() {
                let q: Exact = p.spec.place.measure(Fixed);
                let name = ["L", "A", "V"][power.clamp(1, 3) - 1];
                Some((
                    Math::new(name, name),
                    Math::new(plain(q), super::number::tex_number(&plain(q))),
                ))
            } else {
                written(e.measure, &v)
            };
            if let Some((sym, num)) = measure {
                rows.push(eq(
                    Math::new("m", "m"),
                    Some(Math::new(
                        format!("{}ρ·{}", sign.0, sym.text),
                        format!("{}\\rho \\cdot {}", sign.1, sym.tex),
                    )),
                    Some(Math::new(
                        format!("{}{} × {}", sign.0, plain(rho), num.text),
                        format!(
                            "{}{} \\times {}",
                            sign.1,
                            super::number::tex_number(&plain(rho)),
                            num.tex
                        ),
                    )),
                    m,
                    &u.mass,
                ));
            }
            rows.push(Row::Note(vec![
                t(format!("ρ = {} ", super::number::text(rho))),
                t(u.density[power.clamp(1, 3) - 1].text.clone()),
            ]));
        }
    }
    if p.spec.removed {
        rows.push(Row::Note(vec![t(
            "a cut-out (`remove = true`): its mass and inertia count negative",
        )]));
    }
    // Its centroid.
    for k in 0..3 {
        rows.push(eq(
            Math::new(format!("{}_c", AXIS[k]), format!("{}_c", AXIS[k])),
            None,
            None,
            c[k],
            &u.length,
        ));
    }
    // Its own inertia: in its own axes by its closed form, then turned.
    let closed = dims.is_some() && e.moments.iter().all(|f| !f.is_empty());
    if closed {
        rows.push(Row::Note(vec![t(format!(
            "own inertia about its centroid in its own axes x′, y′, z′ ({})",
            e.form
        ))]));
        let s = shape.second_moments(m, &values);
        let own: V = std::array::from_fn(|k| s[(k + 1) % 3] + s[(k + 2) % 3]);
        for k in 0..3 {
            let (sym, num) = written(e.moments[k], &v).unwrap_or_default();
            rows.push(eq(
                Math::new(
                    format!("I{0}′{0}′", AXIS[k]),
                    format!("I_{{{0}'{0}'}}", AXIS[k]),
                ),
                Some(sym),
                Some(num),
                own[k],
                &u.inertia,
            ));
        }
        let same = ENTRIES.iter().all(|&(a, b)| {
            if a == b {
                i[a][a] == own[a]
            } else {
                i[a][b].is_zero()
            }
        });
        rows.push(Row::Note(vec![t(if same {
            "its own axes are the file's: these are its moments in the file's axes, its products 0"
        } else {
            "turned into the file's axes, I = R I′ Rᵀ (R's columns: its local axes in the file's frame, from its `rotation` or its edges):"
        })]));
        if !same {
            for e in ENTRIES {
                rows.push(eq(
                    entry_name(e, "", ""),
                    None,
                    None,
                    shown_entry(&i, e, products),
                    &u.inertia,
                ));
            }
        }
    } else {
        rows.push(Row::Note(vec![t(format!(
            "own inertia about its centroid in the file's axes ({})",
            e.form
        ))]));
        for e in ENTRIES {
            rows.push(eq(
                entry_name(e, "", ""),
                None,
                None,
                shown_entry(&i, e, products),
                &u.inertia,
            ));
        }
    }
    // The parallel-axis terms to O.
    let d: V = std::array::from_fn(|k| c[k] - origin[k]);
    rows.push(Row::Note(vec![t(
        "parallel-axis terms to O, with d = c − O:",
    )]));
    for k in 0..3 {
        rows.push(eq(
            Math::new(format!("d{}", AXIS[k]), format!("d_{}", AXIS[k])),
            None,
            Some(joined(&[c[k], origin[k]], " − ", " - ")),
            d[k],
            &u.length,
        ));
    }
    let mut about = [[zero(); 3]; 3];
    for (a, b) in ENTRIES {
        let term = shift(m, &d, (a, b));
        let shown = match products {
            Products::Positive if a != b => -term,
            _ => term,
        };
        let (lhs, subst) = if a == b {
            let (j, k) = ((a + 1) % 3, (a + 2) % 3);
            (
                Math::new(
                    format!("m(d{}² + d{}²)", AXIS[j], AXIS[k]),
                    format!("m\\left(d_{}^{{2}} + d_{}^{{2}}\\right)", AXIS[j], AXIS[k]),
                ),
                {
                    let x = joined(&[m], "", "");
                    let y = joined(&[d[j], d[k]], "² + ", "^{2} + ");
                    Math::new(
                        format!("{} × ({}²)", x.text, y.text),
                        format!("{} \\times \\left({}^{{2}}\\right)", x.tex, y.tex),
                    )
                },
            )
        } else {
            let (s, st) = match products {
                Products::Tensor => ("−", "-"),
                Products::Positive => ("", ""),
            };
            (
                Math::new(
                    format!("{s}m·d{}·d{}", AXIS[a], AXIS[b]),
                    format!("{st}m\\,d_{}\\,d_{}", AXIS[a], AXIS[b]),
                ),
                {
                    let x = joined(&[m, d[a], d[b]], " × ", " \\times ");
                    Math::new(format!("{s}{}", x.text), format!("{st}{}", x.tex))
                },
            )
        };
        rows.push(eq(lhs, None, Some(subst), shown, &u.inertia));
        about[a][b] = i[a][b] + term;
        about[b][a] = about[a][b];
    }
    rows.push(Row::Note(vec![t(
        "its inertia about O, own plus parallel-axis term:",
    )]));
    for e in ENTRIES {
        let (own, term) = (
            shown_entry(&i, e, products),
            shown_entry(&about, e, products) - shown_entry(&i, e, products),
        );
        rows.push(eq(
            entry_name(e, "(O)", "(O)"),
            None,
            Some(joined(&[own, term], " + ", " + ")),
            shown_entry(&about, e, products),
            &u.inertia,
        ));
    }
    let share = Share {
        mass: m,
        moment: c.map(|x| m * x),
        about,
    };
    (Step { heading, rows }, share)
}

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
    rows.push(eq(
        Math::new("m", "m"),
        Some(Math::new("Σ m", "\\sum m")),
        Some(joined(&masses, " + ", " + ")),
        mass,
        &u.mass,
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
        rows.push(eq(
            Math::new(format!("{name}_G"), format!("{name}_G")),
            Some(Math::new(
                format!("Σ m·{name}_c / m"),
                format!("\\sum m\\,{name}_c / m"),
            )),
            Some(joined(&[first, mass], " / ", " / ")),
            g[k],
            &u.length,
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
            let (j, k) = ((a + 1) % 3, (a + 2) % 3);
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
        rows.push(eq(
            entry_name((a, b), "(G)", "(G)"),
            Some(form),
            Some(joined(&[o, o - gv], " − ", " - ")),
            gv,
            &u.inertia,
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
        rows.push(eq(
            Math::new(format!("H{}", AXIS[a]), format!("H_{}", AXIS[a])),
            Some(Math::new(join(form_t, false), join(form_x, true))),
            Some(Math::new(
                join(sub.iter().map(|m| m.text.clone()).collect(), false),
                join(sub.iter().map(|m| m.tex.clone()).collect(), true),
            )),
            h[a],
            &Math::new("N·m·s", "\\mathrm{N\\,m\\,s}"),
        ));
    }
    let energy = (0..3).fold(zero(), |acc, a| acc + w[a] * h[a]) * Exact::ratio(1, 2);
    rows.push(eq(
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
    ));
    steps.push(Step {
        heading: vec![t(format!(
            "{}. angular momentum H = I·ω and kinetic energy T = ½ ωᵀ I ω",
            steps.len() + 1
        ))],
        rows,
    });
}
