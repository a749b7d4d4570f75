//! The steps of `explain`: each part of the file's own (or a line for a
//! sub-assembly, an array or a mesh), then the sums, the centre of mass,
//! the principal moments, H and T.

// NOTE: the three axes index several arrays together (a centroid, its
// axis's name, a sum), as the textbook's x, y, z do.
#![allow(clippy::needless_range_loop)]

use super::formula::{self, Symbols};
use super::number::{plain, tex};
use super::{
    AXIS, ENTRIES, M, Math, Piece, Row, Step, Units, V, entry_name, shift, shown_entry, t, zero,
};
use crate::analysis::{Loaded, Products};
use crate::explain::exact::Exact;
use crate::numeric::Real;
use crate::part::{MassSpec, Part, Spec};
use crate::shapes::{Fixed, Place, Shape, Slot};

/// One item's share of the sums: a part's, or a group's.
pub struct Share {
    pub mass: Exact,
    /// Σ m c.
    pub moment: V,
    /// The inertia tensor about O (tensor convention).
    pub about: M,
}

pub(super) fn eq(
    lhs: Math,
    form: Option<Math>,
    subst: Option<Math>,
    value: Exact,
    unit: &Math,
) -> Row {
    Row::Eq {
        lhs,
        form,
        subst,
        value,
        unit: unit.clone(),
        reported: None,
    }
}

/// `eq` for a final figure, shown as the report's f64 `reported` (where
/// the report has it in these units), `value` exactly beside it.
pub(super) fn eq_reported(
    lhs: Math,
    form: Option<Math>,
    subst: Option<Math>,
    value: Exact,
    unit: &Math,
    reported: Option<f64>,
) -> Row {
    match eq(lhs, form, subst, value, unit) {
        Row::Eq {
            lhs,
            form,
            subst,
            value,
            unit,
            ..
        } => Row::Eq {
            lhs,
            form,
            subst,
            value,
            unit,
            reported,
        },
        other => other,
    }
}

/// The numbers `x` joined by `op` (text and TeX), each shown plainly,
/// negative ones in parentheses.
pub(super) fn joined(xs: &[Exact], op: &str, tex_op: &str) -> Math {
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

pub(super) fn sum(xs: &[Exact]) -> Exact {
    xs.iter().fold(zero(), |a, &b| a + b)
}

/// A part's physics in `Exact`: mass, centroid, inertia about its
/// centroid in the file's axes (tensor convention).
fn physics(spec: &Spec) -> (Exact, V, M) {
    let (m, c, j) = crate::part::physics_in::<Exact, _>(spec, Fixed);
    (m, c, crate::mass::inertia_of_rows(&j))
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
    // `--only`: the sub-assembly's own parts are explained whole, its
    // sub-assemblies a line each.
    let skip = loaded.summary.sub_assembly.as_ref().map_or(0, Vec::len);
    loaded.model.each_part(&mut |leaf| {
        let key = match leaf.part.assembly.get(skip) {
            Some(a) => Key::Sub(a.clone()),
            // Its `[[part]]` table in its own file: its copies share it.
            None => Key::Own(leaf.own.span.clone()),
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
/// A dimension's value, and how it was found (text, TeX) where it is not
/// a number of the file's.
type Dimension = (Exact, Option<(String, String)>);

fn dims(spec: &Spec, shape: Shape) -> Option<Vec<Dimension>> {
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
                    (
                        format!("|edge {}|", k + 1),
                        format!("\\lvert e_{{{}}} \\rvert", k + 1),
                    ),
                ),
                Slot::Length => (
                    (0..3)
                        .map(|i| Some(get(Slot::To(i))? - get(Slot::At(i))?))
                        .collect::<Option<Vec<_>>>()?,
                    (
                        "|to − from|".into(),
                        "\\lvert \\mathrm{to} - \\mathrm{from} \\rvert".into(),
                    ),
                ),
                _ => return None,
            };
            Some((v.iter().fold(zero(), |a, &x| a + x * x).sqrt(), Some(how)))
        })
        .collect()
}

/// A part of the file's own, explained in full; its share.
/// R as the composer forms it (`Place::turn`), entry by entry.
fn turn_rows(p: &Part, rows: &mut Vec<Row>) {
    if let Some(r) = p.spec.place.turn() {
        for (a, row) in r.iter().enumerate() {
            for (b, x) in row.iter().enumerate() {
                rows.push(eq(
                    Math::new(
                        format!("R{}{}", a + 1, b + 1),
                        format!("R_{{{}{}}}", a + 1, b + 1),
                    ),
                    None,
                    None,
                    Exact::of(*x),
                    &Math::new("", ""),
                ));
            }
        }
    }
}

/// The working of a shape whose closed form is over its points or a
/// given tensor, not its dimensions: a given tensor as given, then R
/// (the turn the next rows are); a triangle's vertices less its
/// centroid, eₖ, whose (m/12) Σ eₖeₖᵀ is ∫ρρᵀ dm. (A prism's and a
/// mesh's sums are named in their form; their many terms are not
/// printed.)
fn written_out(p: &Part, u: &Units, rows: &mut Vec<Row>) {
    match &p.spec.place {
        Place::Inertia(g) => {
            rows.push(Row::Note(vec![t(
                "the tensor as given, about its centroid in its own axes x′, y′, z′ (tensor convention):",
            )]));
            for (a, b) in ENTRIES {
                rows.push(eq(
                    Math::new(
                        format!("I{}′{}′", AXIS[a], AXIS[b]),
                        format!("I_{{{}'{}'}}", AXIS[a], AXIS[b]),
                    ),
                    None,
                    None,
                    Exact::of(g.inertia[a][b]),
                    &u.inertia,
                ));
            }
            if p.spec.place.turn().is_some_and(|r| r != IDENTITY) {
                rows.push(Row::Note(vec![t(
                    "turned into the file's axes, I = R I′ Rᵀ, with R:",
                )]));
                turn_rows(p, rows);
            }
        }
        Place::Triangle(tri) => {
            let c: [Exact; 3] = std::array::from_fn(|k| {
                (Exact::of(tri.vertices[0][k])
                    + Exact::of(tri.vertices[1][k])
                    + Exact::of(tri.vertices[2][k]))
                    / Exact::of(3.0)
            });
            rows.push(Row::Note(vec![t(
                "its vertices less its centroid, eₖ = vₖ − c; ∫ρρᵀ dm = (m/12) Σ eₖeₖᵀ, I = tr(∫ρρᵀ dm) E − ∫ρρᵀ dm:",
            )]));
            for (n, v) in tri.vertices.iter().enumerate() {
                for k in 0..3 {
                    rows.push(eq(
                        Math::new(
                            format!("e{}{}", n + 1, AXIS[k]),
                            format!("e_{{{}{}}}", n + 1, AXIS[k]),
                        ),
                        None,
                        None,
                        Exact::of(v[k]) - c[k],
                        &u.length,
                    ));
                }
            }
        }
        Place::Box(_)
        | Place::Capsule(_)
        | Place::Cone(_)
        | Place::Cylinder(_)
        | Place::Disk(_)
        | Place::Ellipsoid(_)
        | Place::Hemisphere(_)
        | Place::Mesh(_)
        | Place::Plate(_)
        | Place::Point(_)
        | Place::Prism(_)
        | Place::Rod(_)
        | Place::Sphere(_)
        | Place::Torus(_) => {}
    }
}

const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

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
            let form = how.as_ref().map(|(h, tx)| Math::new(h.clone(), tx.clone()));
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
            // A cut-out's given mass counts negative: said as −m.
            let form = p.spec.removed.then(|| {
                Math::new(
                    format!("−{}", plain(Exact::of(given))),
                    format!("-{}", tex(Exact::of(given))),
                )
            });
            rows.push(eq(Math::new("m", "m"), form, None, m, &u.mass));
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
        // Exactly where both are exact; else to the roundings of two
        // evaluations of one form (a turn off a quarter turn is far more).
        let scale = own.iter().fold(0.0f64, |a, x| a.max(x.approx.abs()));
        let same = ENTRIES.iter().all(|&(a, b)| {
            let (x, y) = (i[a][b], if a == b { own[a] } else { zero() });
            match (x.exact, y.exact) {
                (Some(_), Some(_)) => x == y,
                _ => (x.approx - y.approx).abs() <= 1e-13 * scale,
            }
        });
        rows.push(Row::Note(vec![t(if same {
            "its own axes are the file's: these are its moments in the file's axes, its products 0"
        } else {
            "turned into the file's axes, I = R I′ Rᵀ (R's columns: its local axes in the file's frame, from its `rotation` or its edges):"
        })]));
        if !same {
            turn_rows(p, &mut rows);
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
        written_out(p, u, &mut rows);
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
            // The other two axes in order: m(dx² + dz²) for Iyy.
            let (j, k) = if a == 1 {
                (0, 2)
            } else {
                ((a + 1) % 3, (a + 2) % 3)
            };
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
