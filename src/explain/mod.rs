//! `massprop explain`: the worked solution of a part file, as a textbook
//! writes it (issue 36). Per part: its dimensions, its mass with its
//! formula and the file's numbers, its centroid, its own inertia about
//! its centroid in its own axes with the closed form named (the shape's
//! `ShapeKind::EXPLAIN`, its module's one place), the turn into the
//! file's axes, the parallel-axis terms to the reference point; then the
//! sums term by term, the inertia about the centre of mass, the principal
//! moments (the characteristic equation's invariants, the roots by
//! Jacobi rotations, the summary's), and with ω, H = I·ω and
//! T = ½ ωᵀ I ω written out. Sub-assemblies, arrays and meshes are a line
//! each.
//!
//! Every step is evaluated in `exact::Exact`, through the shapes' own
//! closed forms (`numeric::Real`): exact where every input is a decimal,
//! else the f64. The document (`Doc`) is written as text, markdown or
//! LaTeX by `render`.

pub mod exact;
pub mod formula;
pub mod number;
mod parts;
pub mod render;
mod totals;

use crate::analysis::{Loaded, Products};
use crate::numeric::Real;
use crate::units::Dim;
use exact::Exact;

/// A vector and a matrix of `Exact`.
pub type V = [Exact; 3];
pub type M = [[Exact; 3]; 3];

/// A piece of prose: the program's own text, a name from input (escaped
/// by each format), or a formula.
#[derive(Debug, Clone)]
pub enum Piece {
    Text(String),
    Name(String),
    Math(Math),
}

/// A formula as text and as TeX.
#[derive(Debug, Clone, Default)]
pub struct Math {
    pub text: String,
    pub tex: String,
}

impl Math {
    pub fn new(text: impl Into<String>, tex: impl Into<String>) -> Math {
        Math {
            text: text.into(),
            tex: tex.into(),
        }
    }
}

/// A unit as text and TeX (`kg·mm²`, `\mathrm{kg\,mm^{2}}`).
pub type Unit = Math;

/// One row of a step.
// NOTE: a document holds a few hundred rows at most: no box is worth it.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum Row {
    Note(Vec<Piece>),
    /// `lhs = form = subst = value unit`.
    Eq {
        lhs: Math,
        form: Option<Math>,
        subst: Option<Math>,
        value: Exact,
        unit: Unit,
        /// A final figure: the report's own f64 for it, shown in its
        /// place (shortest round-trip), the exact value beside it.
        reported: Option<f64>,
    },
    /// A sub-assembly, array or mesh in one line: its label, then each
    /// total.
    Summary {
        label: Vec<Piece>,
        items: Vec<(Math, Exact, Unit)>,
    },
}

/// A step: its heading and rows.
#[derive(Debug, Clone)]
pub struct Step {
    pub heading: Vec<Piece>,
    pub rows: Vec<Row>,
}

/// The worked solution.
#[derive(Debug, Clone)]
pub struct Doc {
    pub title: Vec<Piece>,
    pub conventions: Vec<Vec<Piece>>,
    pub steps: Vec<Step>,
}

fn t(s: impl Into<String>) -> Piece {
    Piece::Text(s.into())
}

/// The units of a file as `explain` shows them.
#[derive(Debug, Clone)]
pub struct Units {
    pub mass: Unit,
    pub length: Unit,
    pub inertia: Unit,
    pub density: [Unit; 3],
    /// kg·m² per file unit of inertia, exactly.
    pub inertia_si: Exact,
}

fn tex_unit(name: &str) -> String {
    name.chars()
        .map(|c| match c {
            'µ' | 'μ' => "\\mu{}".to_string(),
            c if c.is_ascii_alphabetic() => c.to_string(),
            _ => String::new(),
        })
        .collect()
}

impl Units {
    fn of(u: crate::units::FileUnits) -> Units {
        let (m, l) = (u.mass, u.length);
        let (mt, lt) = (tex_unit(m), tex_unit(l));
        let per = |p: u32, sup: &str| {
            Math::new(
                format!("{m}/{l}{sup}"),
                format!("\\mathrm{{{mt}/{lt}^{{{p}}}}}"),
            )
        };
        let (n, d, _) = u.factor(Dim::INERTIA).parts();
        Units {
            mass: Math::new(m, format!("\\mathrm{{{mt}}}")),
            length: Math::new(l, format!("\\mathrm{{{lt}}}")),
            inertia: Math::new(
                format!("{m}·{l}²"),
                format!("\\mathrm{{{mt}\\,{lt}^{{2}}}}"),
            ),
            density: [
                Math::new(format!("{m}/{l}"), format!("\\mathrm{{{mt}/{lt}}}")),
                per(2, "²"),
                per(3, "³"),
            ],
            inertia_si: Exact::ratio(n, d),
        }
    }
}

/// The six entries in order: xx, yy, zz, xy, xz, yz.
pub const ENTRIES: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
/// The axes' names.
pub const AXIS: [&str; 3] = ["x", "y", "z"];

/// What a product of inertia is shown as under `products`: the tensor's
/// entry, or its negative (+∫xy dm).
pub fn shown_entry(i: &M, (a, b): (usize, usize), products: Products) -> Exact {
    match products {
        Products::Positive if a != b => -i[a][b],
        Products::Positive | Products::Tensor => i[a][b],
    }
}

/// `I_xy` as text and TeX, with a suffix (`(O)`, `′`).
pub fn entry_name((a, b): (usize, usize), text_suffix: &str, tex_suffix: &str) -> Math {
    Math::new(
        format!("I{}{}{text_suffix}", AXIS[a], AXIS[b]),
        format!("I_{{{}{}}}{tex_suffix}", AXIS[a], AXIS[b]),
    )
}

/// The worked solution of a loaded part file (`--only` already applied
/// by `analysis::load`), its products of inertia shown as `products`
/// says.
pub fn explain(loaded: &Loaded, products: Products) -> Doc {
    let units = Units::of(loaded.model.units);
    let about: Option<V> = loaded
        .analysis
        .about
        .map(|p| [p.x, p.y, p.z].map(Exact::of));
    // The parts' parallel-axis terms go to O: the file's `about`, else the
    // file's origin (the inertia about the centre of mass follows from it).
    let origin = about.unwrap_or([Exact::of(0.0); 3]);
    let mut doc = Doc {
        title: title(loaded),
        conventions: conventions(loaded, &units, about.is_some(), products),
        steps: Vec::new(),
    };
    let sums = parts::each(loaded, &units, &origin, products, &mut doc.steps);
    totals::totals(
        loaded,
        &units,
        &origin,
        about.is_some(),
        products,
        &sums,
        &mut doc.steps,
    );
    doc
}

fn title(loaded: &Loaded) -> Vec<Piece> {
    let mut title = vec![t("worked solution: ")];
    match &loaded.summary.name {
        Some(name) => title.push(Piece::Name(name.clone())),
        None => title.push(t("the body")),
    }
    title.push(t(" ("));
    title.push(Piece::Name(loaded.source.name.clone()));
    title.push(t(")"));
    title
}

fn conventions(loaded: &Loaded, u: &Units, about: bool, products: Products) -> Vec<Vec<Piece>> {
    let mut out = vec![vec![t(format!(
        "units: mass {}, length {}, inertia {} (the file's); ω in rad/s, H in N·m·s and T in J (SI)",
        u.mass.text, u.length.text, u.inertia.text
    ))]];
    out.push(vec![t(match products {
        Products::Tensor => {
            "products of inertia: tensor convention, Ixy = −∫xy dm (`--products tensor`)"
        }
        Products::Positive => {
            "products of inertia: positive convention, Ixy = +∫xy dm (`--products positive`)"
        }
    })]);
    out.push(vec![t(if about {
        "reference point O: the file's `about`; parallel-axis terms are taken to O"
    } else {
        "reference point: none given, so the report's is the centre of mass; parallel-axis terms are taken to O, the file's origin, then moved to the centre of mass"
    })]);
    out.push(vec![t(
        "numbers: each value as the file's decimals, in the file's axes; exact where every input is a decimal (a fraction beside it where the decimal does not end); otherwise the f64, in shortest round-trip form",
    )]);
    if loaded.analysis.axes.is_some() {
        out.push(vec![t(
            "the file's `axes` turn the report's tensors; this solution stays in the file's own axes",
        )]);
    }
    out
}

/// Exact `Real` helpers.
pub fn zero() -> Exact {
    Exact::of(0.0)
}

/// `x` squared.
pub fn sq(x: Exact) -> Exact {
    x * x
}

/// The inertia tensor's parallel-axis term of a mass `m` at `d` from the
/// point: entry (a, b) of m(|d|² E − d dᵀ).
pub fn shift(m: Exact, d: &V, (a, b): (usize, usize)) -> Exact {
    if a == b {
        let (j, k) = ((a + 1) % 3, (a + 2) % 3);
        m * (sq(d[j]) + sq(d[k]))
    } else {
        -(m * d[a] * d[b])
    }
}
