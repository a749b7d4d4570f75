//! Plausibility warnings (issue 31, item 4): numbers a file may well mean
//! in other units than it says. They never change a result; standard
//! error shows them (`warning: FILE:LINE:COL: …`, beside the accuracy
//! warnings) and the JSON lists them under `warnings`; a file silences
//! its own with `[analysis] warnings = false`.
//!
//! - `units`: a file without `units` whose own parts span more than
//!   100 m, or weigh more than 100 t: its lengths and masses are read in
//!   metres and kilograms, and a design in millimetres written without
//!   `units` reads 1000× too large (10⁹× too heavy by density).
//! - `density`: a density outside 1–25,000 kg/m³ once converted to SI
//!   (a part's `density`, a material of `[materials]`): lighter than air,
//!   or heavier than osmium (22,590 kg/m³).
//!
//! Each file's own `units` decides for its own parts: a sub-assembly in
//! mm included from a file in metres is judged by its own numbers, in its
//! own units. A file read once is judged once, however often included.
//!
//! A part's `array` and `mirror` copies count in the span and the mass:
//! they are the body (a walk of the file's own parts, `Model::each_event`,
//! only when the file gives no `units`; `Model::each_own_part`).

use crate::diag::{Palette, Source, Span};
use crate::model::{Item, Model};
use crate::part::MassSpec;
use crate::units::Dim;
use serde::Serialize;
use std::ops::Range;

/// The largest span of a file's parts, m, beyond which a file without
/// `units` is warned of.
pub const MAX_SPAN: f64 = 100.0;
/// The largest mass of a file's parts, kg (100 t), beyond which a file
/// without `units` is warned of.
pub const MAX_MASS: f64 = 1e5;
/// The densities, kg/m³, within which no warning is given (bounds
/// included): from aerogels and foams to osmium.
pub const DENSITY: [f64; 2] = [1.0, 25_000.0];
/// The most parts of one file whose density is warned of one by one; the
/// rest are counted in one more warning (a file of 10⁵ parts written in
/// the wrong unit is one slip, not 10⁵ lines).
pub const MAX_LISTED: usize = 10;

/// Which rule a warning is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// A file without `units` whose parts are too large or too heavy.
    Units,
    /// A density outside `DENSITY`.
    Density,
    /// A mesh file answered exactly despite a class of fault it survives,
    /// or welded (`model::mesh::MeshNote`).
    Mesh,
    /// A robot description's body composed as written: a link without an
    /// inertial, or one not physically valid, or a joint beyond its
    /// limits (`robot::body::Note`).
    Robot,
}

/// One plausibility warning: where (the file as named, and the span in it)
/// and what.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Warning {
    pub kind: Kind,
    pub path: String,
    #[serde(flatten)]
    pub span: Span,
    /// The sentence standard error shows after the place.
    pub message: String,
}

impl Warning {
    /// `warning: FILE:LINE:COL: message` and a newline, `warning` coloured
    /// when `colour`.
    pub fn line(&self, colour: bool) -> String {
        let at = format!("{}:{}:{}", self.path, self.span.line, self.span.column);
        Palette::of(colour).warning_line(&format!("{at}: {}", self.message))
    }
}

/// Every warning's line (`Warning::line`).
pub fn lines(warnings: &[Warning], colour: bool) -> String {
    warnings.iter().map(|w| w.line(colour)).collect()
}

/// The plausibility warnings of `model`, read from `source`; none when the
/// file says `[analysis] warnings = false`.
pub fn warnings(model: &Model, source: &Source) -> Vec<Warning> {
    if model.analysis.warnings == Some(false) {
        return Vec::new();
    }
    let mut walk = Walk {
        source,
        out: Vec::new(),
        seen: std::collections::HashSet::new(),
    };
    walk.file(model, None);
    walk.out.extend(model.mesh_warnings.iter().map(|n| Warning {
        kind: Kind::Mesh,
        path: n.path.clone(),
        span: n.span,
        message: n.message.clone(),
    }));
    walk.out
}

/// Where an included file's warnings point: the `[[part]]` table in the
/// file read that (at any depth) includes it, and its sub-assembly path.
#[derive(Clone)]
struct Anchor {
    span: Range<usize>,
    path: String,
}

struct Walk<'a> {
    source: &'a Source,
    out: Vec<Warning>,
    /// The files judged, by their model's address (a file included twice
    /// is one model).
    seen: std::collections::HashSet<*const Model>,
}

impl Walk<'_> {
    fn push(&mut self, kind: Kind, at: Range<usize>, message: String) {
        self.insert(self.out.len(), kind, at, message);
    }

    fn insert(&mut self, i: usize, kind: Kind, at: Range<usize>, message: String) {
        self.out.insert(
            i,
            Warning {
                kind,
                path: self.source.name.clone(),
                span: self.source.span(at),
                message,
            },
        );
    }

    /// Judge `m`'s own parts and materials, then its sub-assemblies';
    /// `anchor` is None for the file read.
    fn file(&mut self, m: &Model, anchor: Option<Anchor>) {
        // An included file's own `warnings = false` silences its own.
        let silent = anchor.is_some() && m.analysis.warnings == Some(false);
        if !silent {
            self.own(m, anchor.as_ref());
        }
        for item in m.items.iter() {
            let Item::Include(inc) = item else { continue };
            if !self.seen.insert(std::sync::Arc::as_ptr(&inc.model)) {
                continue;
            }
            let next = match &anchor {
                None => Anchor {
                    span: inc.span.clone(),
                    path: inc.name.clone(),
                },
                Some(a) => Anchor {
                    span: a.span.clone(),
                    path: format!("{} / {}", a.path, inc.name),
                },
            };
            self.file(&inc.model, Some(next));
        }
    }

    fn own(&mut self, m: &Model, anchor: Option<&Anchor>) {
        // The file's `units` warning comes before its densities'.
        let start = self.out.len();
        let to_si = m.units.factor(Dim::DENSITY).value();
        let whose = |what: &str| match anchor {
            None => what.to_string(),
            Some(a) => format!("{what} of the sub-assembly `{}`", a.path),
        };
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        let (mut mass, mut first) = (0.0, None);
        // The parts whose density is warned of, and the first one past
        // `MAX_LISTED`.
        let (mut dense, mut past) = (0, None);
        for item in m.items.iter() {
            let Item::Part { part, .. } = item else {
                continue;
            };
            first.get_or_insert(part.span.clone());
            if let MassSpec::Density(rho) = part.spec.mass
                && part.material.is_none()
                && part.spec.place.density_power() == 3
                && let Some(what) = outside(rho * to_si)
            {
                dense += 1;
                if dense > MAX_LISTED {
                    past.get_or_insert(part.span.clone());
                    continue;
                }
                let at = match anchor {
                    None => key_in(&self.source.text, part.span.clone(), "density"),
                    Some(a) => a.span.clone(),
                };
                let name = if part.named {
                    format!("`{}`", part.name)
                } else {
                    "a part".to_string()
                };
                let message = format!("the `density` of {} is {what}{}", whose(&name), no_units(m));
                self.push(Kind::Density, at, message);
            }
        }
        if let Some(span) = past {
            let at = anchor.map_or(span, |a| a.span.clone());
            let message = format!(
                "{} more parts {}have a `density` outside 1–25,000 kg/m³ (this one the first of them)",
                dense - MAX_LISTED,
                anchor.map_or(String::new(), |a| format!(
                    "of the sub-assembly `{}` ",
                    a.path
                )),
            );
            self.push(Kind::Density, at, message);
        }
        for (name, &rho) in &m.materials {
            if let Some(what) = outside(rho) {
                let at = match anchor {
                    None => material_key(&self.source.text, name).unwrap_or(0..0),
                    Some(a) => a.span.clone(),
                };
                let message = format!(
                    "the density of {} is {what}{}",
                    whose(&format!("the material `{name}`")),
                    no_units(m)
                );
                self.push(Kind::Density, at, message);
            }
        }
        if m.units_given {
            return;
        }
        let Some(first) = first else { return };
        // The file's own parts with their `array` and `mirror` copies, in
        // its frame and units (its sub-assemblies are judged by their own
        // units, as their own files).
        // NOTE: its own parts alone are walked (`each_own_part`): walking
        // the whole tree to skip its sub-assemblies' parts cost every
        // file of a tree of includes all the instances below it.
        m.each_own_part(&mut |l| {
            // Summed at most to f64::MAX: the warning prints no `inf`.
            if !l.part.spec.removed {
                mass = (mass + crate::part::mass_of::<f64>(&l.part.spec)).min(f64::MAX);
            }
            let [a, b] = l.part.spec.place.extent();
            for k in 0..3 {
                lo[k] = lo[k].min(a[k]);
                hi[k] = hi[k].max(b[k]);
            }
        });
        let span = (0..3)
            .map(|k| (hi[k] - lo[k]).min(f64::MAX))
            .fold(0.0, f64::max);
        if !(span > MAX_SPAN || mass > MAX_MASS) {
            return;
        }
        let (size, unit) = if span > MAX_SPAN {
            (format!("span {} m", rounded(span, 3)), "length = \"mm\"")
        } else {
            (format!("weigh {} kg", rounded(mass, 3)), "mass = \"g\"")
        };
        let also = if span > MAX_SPAN && mass > MAX_MASS {
            format!(" and weigh {} kg", rounded(mass, 3))
        } else {
            String::new()
        };
        let (at, what) = match anchor {
            None => (first, "the file has no `units`".to_string()),
            Some(a) => (
                a.span.clone(),
                format!("the sub-assembly `{}` has no `units`", a.path),
            ),
        };
        let message = format!(
            "{what} and its parts {size}{also}: lengths are read in metres and masses in kilograms: did you mean `units = {{ {unit} }}`?"
        );
        self.insert(start, Kind::Units, at, message);
    }
}

/// `None` for a density within `DENSITY`, else what it is: "0.9 kg/m³,
/// outside …".
fn outside(rho: f64) -> Option<String> {
    // NOTE: a bound written in other units comes back within a few ulps
    // of itself (1 kg/m³ in g/mm³ and back): those few ulps are inside.
    let [lo, hi] = DENSITY;
    let slack = 1e-12;
    (!(lo * (1.0 - slack)..=hi * (1.0 + slack)).contains(&rho)).then(|| {
        format!(
            "{} kg/m³, outside 1–25,000 kg/m³ (from foams to osmium): check its number and unit",
            short(rho)
        )
    })
}

/// Said after a density of a file without `units`.
fn no_units(m: &Model) -> &'static str {
    if m.units_given {
        ""
    } else {
        " (the file has no `units`: a plain number is kg/m³)"
    }
}

/// `x` to 6 significant digits, as Rust writes it; in exponent form when
/// large or small (`1.15e8`).
pub fn short(x: f64) -> String {
    rounded(x, 6)
}

/// `x` to `digits` significant digits (`numeric::significant`).
pub fn rounded(x: f64, digits: usize) -> String {
    crate::numeric::significant(x, digits)
}

/// The span of key `key` (a whole word, followed by `=`) in the table at
/// `table` of `text`, or the table's if it is not found there (written
/// with quotes).
fn key_in(text: &str, table: Range<usize>, key: &str) -> Range<usize> {
    // NOTE: a part's span may be its header alone: its keys run to the
    // next table header.
    let end = text
        .get(table.end..)
        .and_then(|rest| rest.find("\n[").map(|i| table.end + i))
        .unwrap_or(text.len())
        .max(table.end);
    let Some(within) = text.get(table.start..end) else {
        return table;
    };
    find_key(within, key).map_or(table.clone(), |r| {
        table.start + r.start..table.start + r.end
    })
}

/// The first `key` in `text` that is a whole word followed by `=`, `.` or
/// `]` (a key, a dotted key, a table header).
fn find_key(text: &str, key: &str) -> Option<Range<usize>> {
    let word = |c: char| c.is_alphanumeric() || c == '_' || c == '-';
    text.match_indices(key).find_map(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + key.len()..].trim_start_matches([' ', '\t']);
        let key_like = before.is_none_or(|c| !word(c))
            && after
                .chars()
                .next()
                .is_some_and(|c| matches!(c, '=' | '.' | ']'));
        key_like.then(|| i..i + key.len())
    })
}

/// Where `[materials]` defines `name`: its key after the `materials` key
/// or table, if written bare.
fn material_key(text: &str, name: &str) -> Option<Range<usize>> {
    let from = find_key(text, "materials")?.end;
    find_key(&text[from..], name).map(|r| from + r.start..from + r.end)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn warned(text: &str) -> Vec<Warning> {
        let source = Source::new("f.toml", text);
        let model = Model::parse(&source).unwrap();
        warnings(&model, &source)
    }

    const BASE: &str = "[[part]]\nname = \"base\"\nshape = \"cylinder\"\nmass = 1.2\nradius = 100\nlength = 20\ncenter = [0, 0, 10]\n";

    #[test]
    fn a_base_of_200_read_as_metres_is_warned_of_at_its_part() {
        let w = warned(BASE);
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(w[0].kind, Kind::Units);
        assert_eq!((w[0].span.line, w[0].span.column), (1, 1));
        assert!(w[0].message.contains("span 200 m"), "{}", w[0].message);
        assert!(
            w[0].message
                .contains("did you mean `units = { length = \"mm\" }`?"),
            "{}",
            w[0].message
        );
    }

    #[test]
    fn the_same_base_in_millimetres_is_not_warned_of() {
        assert_eq!(
            warned(&format!("units = {{ length = \"mm\" }}\n{BASE}")),
            vec![]
        );
    }

    #[test]
    fn explicit_metres_are_taken_at_their_word() {
        assert_eq!(
            warned(&format!("units = {{ length = \"m\" }}\n{BASE}")),
            vec![]
        );
    }

    #[test]
    fn masses_that_sum_past_f64_max_print_no_inf() {
        let part =
            "[[part]]\nshape = \"point\"\nmass = 1.7976931348623157e308\ncenter = [0, 0, 0]\n";
        let w = warned(&part.repeat(2));
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(!w[0].message.contains("inf"), "{}", w[0].message);
    }

    #[test]
    fn warnings_false_silences_the_file() {
        assert_eq!(
            warned(&format!("{BASE}[analysis]\nwarnings = false\n")),
            vec![]
        );
    }

    #[test]
    fn many_parts_of_one_implausible_density_give_max_listed_warnings_and_a_count() {
        let part =
            "[[part]]\nshape = \"box\"\ndensity = 0.5\nsize = [1, 1, 1]\ncenter = [0, 0, 0]\n";
        let w = warned(&part.repeat(MAX_LISTED + 5));
        assert_eq!(w.len(), MAX_LISTED + 1, "{w:?}");
        let last = &w[MAX_LISTED];
        assert!(
            last.message.starts_with("5 more parts have"),
            "{}",
            last.message
        );
        assert_eq!(last.span.line, 5 * MAX_LISTED + 1);
    }

    #[test]
    fn a_density_key_is_found_as_a_whole_word_before_an_equals_sign() {
        let text = "areal_density = 1\ndensity_x = 2\n density = 3\n";
        assert_eq!(find_key(text, "density"), Some(33..40));
    }

    #[test]
    fn short_numbers_keep_six_digits_and_go_to_exponents_far_from_one() {
        assert_eq!(short(25_001.0), "25001");
        assert_eq!(short(0.9), "0.9");
        assert_eq!(short(1.15e8), "1.15e8");
        assert_eq!(short(363.241_57), "363.242");
        assert_eq!(rounded(1.696_46e9, 3), "1.7e9");
        assert_eq!(rounded(f64::MAX, 3), "1.7976931348623157e308");
    }
}
