//! `massprop check --bless`: write the computed values into a part file's
//! `[expect]` entries, keeping everything else byte for byte (toml_edit).
//!
//! - An entry with `value` gets the measured value, in the file's units
//!   (SI for H and T); its `tol` is kept, or a default one is added,
//!   computed from the value written (`default_tol`), never from the stale
//!   one the file had, and never zero.
//! - Each number is written with the fewest significant digits that keep
//!   it within 1/1000 of its tolerance of the exact value, in the form the
//!   file wrote it: a bare number stays one, a quantity string stays a
//!   string in its own unit (`digits`).
//! - Entries with only `min`/`max` are design limits and are never changed.
//! - A file without `[expect]` gets one for its mass, centre of mass and
//!   principal moments.
//! - A file that cannot be parsed, or whose edit would not parse, is left
//!   untouched.
//! - Each line keeps its own ending (LF or CRLF; `Endings`), and a
//!   byte-order mark stays.
//! - The file is read and replaced under an exclusive lock on it, so that
//!   concurrent blesses take turns (`io::Rewrite`): replaced atomically
//!   (temporary file + rename) keeping its permissions and owner, or in
//!   place when it has hard links, which a rename would break.

mod digits;

use super::Settings;
use super::summary::Summary;
use crate::diag::{Diagnostic, Source};
use crate::model::Model;
use crate::model::expect::{Bound, Check, Target, Tol};
use crate::quantity::{Bless, Compare, DEFAULT_TOL_DEGREES, QUANTITIES};
use crate::thresholds::{DEFAULT_RELATIVE_TOL, DEFAULT_VECTOR_TOL};
use crate::units::{Dim, FileUnits};
use std::collections::BTreeMap;
use toml_edit::{DocumentMut, InlineTable, Item, Value};

/// Bless one file: returns whether it changed. Errors leave it untouched.
pub fn bless_file(path: &str, settings: &Settings) -> Result<bool, Diagnostic> {
    if path == "-" {
        return Err(Diagnostic::plain(
            "`--bless` writes files; it cannot bless standard input",
        ));
    }
    // Locked from here until written: another bless of this file waits,
    // then reads what this one wrote.
    let (file, source) = crate::io::Rewrite::open(path)?;
    // toml_edit writes every line ending as LF: it edits the text with LF
    // endings, and each line gets its own ending back afterwards.
    let endings = Endings::of(&source.text);
    let mut doc = parse(&endings, &source, settings, path)?;
    let changed = bless_document(&mut doc, &source, settings)?;
    let text = endings.restore(&doc.to_string());
    if text == source.text {
        return Ok(false);
    }
    // The result must parse before it replaces the file.
    Model::parse_with(
        &Source::new(source.name.clone(), text.clone()),
        &settings.includes,
    )?;
    let text = if source.bom {
        format!("\u{feff}{text}")
    } else {
        text
    };
    file.replace(&text, "the blessed file")?;
    Ok(changed)
}

/// The file's text (LF endings) as a document to edit; a syntax error is
/// the model's, with its usual diagnostic.
fn parse(
    endings: &Endings,
    source: &Source,
    settings: &Settings,
    path: &str,
) -> Result<DocumentMut, Diagnostic> {
    endings.lf.parse().map_err(|_| {
        Model::parse_with(source, &settings.includes)
            .err()
            .unwrap_or_else(|| Diagnostic::file(path, "cannot parse"))
    })
}

/// The computed values written into `doc`'s `[expect]` (a default one
/// added when it has none): whether anything changed.
fn bless_document(
    doc: &mut DocumentMut,
    source: &Source,
    settings: &Settings,
) -> Result<bool, Diagnostic> {
    // Entries with `value` but no `tol` get a placeholder first, so that
    // the file parses as a model; their tolerance is computed from the
    // value written in its place (`write_values`).
    let cases = doc.get("case").map_or(0, |c| match c {
        Item::ArrayOfTables(a) => a.len(),
        Item::Value(Value::Array(a)) => a.len(),
        Item::None | Item::Value(_) | Item::Table(_) => 0,
    });
    let mut untoleranced = add_placeholder_tols(doc, None);
    // Each case's own `expect` too: its entries are written with its
    // body's values (`--bless` writes into the table it reads).
    for i in 0..cases {
        untoleranced.extend(add_placeholder_tols(doc, Some(i)));
    }
    let staged = Source::new(source.name.clone(), doc.to_string());
    let loaded = super::load_source(staged, settings)?;
    let mut changed = !untoleranced.is_empty();
    if doc.get("expect").is_none() {
        add_default_expect(doc, &loaded.summary);
        changed = true;
    } else {
        let (checks, s) = (&loaded.model.expect, &loaded.summary);
        changed |= write_values(doc, None, checks, s, &untoleranced);
    }
    for (i, case) in loaded.model.cases.iter().enumerate() {
        if case.model.expect.is_empty() {
            continue;
        }
        let one = super::cases::load_of(&loaded, case, settings)?;
        let checks = &case.model.expect;
        changed |= write_values(doc, Some(i), checks, &one.summary, &untoleranced);
    }
    Ok(changed)
}

/// A text's line endings, one per line, and the text with every line ending
/// in LF, so that an edit of the LF text can be given them back: every line
/// the edit leaves as it was keeps its exact bytes, a line the edit changes
/// keeps the ending of the line it replaces, and a new line takes the
/// ending most lines of the file have (LF on a tie).
struct Endings {
    /// The text, each CRLF line ending as LF.
    lf: String,
    /// The lines of `lf` (without endings).
    lines: Vec<String>,
    /// Whether each line ended in CRLF; `None` for the last, which has no
    /// ending (it is empty when the text ends with one).
    crlf: Vec<Option<bool>>,
    /// Whether most lines end in CRLF.
    mostly_crlf: bool,
}

impl Endings {
    fn of(text: &str) -> Endings {
        let pieces: Vec<&str> = text.split('\n').collect();
        let last = pieces.len() - 1;
        let mut lines = Vec::with_capacity(pieces.len());
        let mut crlf = Vec::with_capacity(pieces.len());
        for (i, piece) in pieces.into_iter().enumerate() {
            if i == last {
                lines.push(piece.to_string());
                crlf.push(None);
            } else {
                let stripped = piece.strip_suffix('\r');
                lines.push(stripped.unwrap_or(piece).to_string());
                crlf.push(Some(stripped.is_some()));
            }
        }
        let with_crlf = crlf.iter().filter(|c| **c == Some(true)).count();
        Endings {
            lf: lines.join("\n"),
            mostly_crlf: 2 * with_crlf > last,
            lines,
            crlf,
        }
    }

    /// `edited` (an edit of `lf`, LF endings) with the endings given back.
    fn restore(&self, edited: &str) -> String {
        let new: Vec<&str> = edited.split('\n').collect();
        let crlf = self.endings_of(&new);
        let mut out = String::with_capacity(edited.len() + new.len());
        let last = new.len() - 1;
        for (i, (line, crlf)) in new.iter().zip(crlf).enumerate() {
            out.push_str(line);
            if i < last {
                out.push_str(if crlf.unwrap_or(self.mostly_crlf) {
                    "\r\n"
                } else {
                    "\n"
                });
            }
        }
        out
    }

    /// The ending of each of the `new` lines: of the old line it is, or
    /// replaces; `None` for a line new to the text.
    fn endings_of(&self, new: &[&str]) -> Vec<Option<bool>> {
        let old: Vec<&str> = self.lines.iter().map(String::as_str).collect();
        let mut crlf: Vec<Option<bool>> = vec![None; new.len()];
        for op in similar::capture_diff_slices(similar::Algorithm::Myers, &old, new) {
            match op {
                similar::DiffOp::Equal {
                    old_index,
                    new_index,
                    len,
                } => crlf[new_index..new_index + len]
                    .copy_from_slice(&self.crlf[old_index..old_index + len]),
                similar::DiffOp::Replace {
                    old_index,
                    old_len,
                    new_index,
                    new_len,
                } => {
                    let n = old_len.min(new_len);
                    crlf[new_index..new_index + n]
                        .copy_from_slice(&self.crlf[old_index..old_index + n]);
                }
                similar::DiffOp::Delete { .. } | similar::DiffOp::Insert { .. } => {}
            }
        }
        crlf
    }
}

/// The key path of an `[expect]` entry: `["center_of_mass"]`, or
/// `["center_of_mass", "z"]` for a component.
type EntryPath = Vec<String>;

/// Which expectations: the file's `[expect]` (`None`), or the `expect` of
/// its `i`-th `[[case]]`.
type At = Option<usize>;

/// The expectations' table at `at`, if the file has it.
fn expect_mut(doc: &mut DocumentMut, at: At) -> Option<&mut Item> {
    match at {
        None => doc.get_mut("expect"),
        Some(i) => doc.get_mut("case")?.get_mut(i)?.get_mut("expect"),
    }
}

/// Give every entry (and component entry) with a `value` but no `tol` a
/// placeholder tolerance, so that the file parses as a model; returns
/// their paths, whose tolerance `write_values` then computes from the
/// value it writes.
fn add_placeholder_tols(doc: &mut DocumentMut, at: At) -> Vec<(At, EntryPath)> {
    let mut added = Vec::new();
    if let Some(t) = expect_mut(doc, at).and_then(Item::as_table_like_mut) {
        for (key, entry) in t.iter_mut() {
            placeholder_tols(entry, &mut vec![key.get().to_string()], &mut added);
        }
    }
    added.into_iter().map(|p| (at, p)).collect()
}

/// `add_placeholder_tols` of one entry (at `path`) and its components.
fn placeholder_tols(entry: &mut Item, path: &mut EntryPath, added: &mut Vec<EntryPath>) {
    let Some(t) = entry.as_table_like_mut() else {
        return;
    };
    let (key, mut tol) = tolerance_of(&path[0]);
    if t.get("value").is_some() && t.get(key).is_none() {
        // Any tolerance the reader takes (`tol`'s is replaced before
        // the file is written).
        // In an inline table the space before `}` trails the last value;
        // move it after the new `tol`.
        if let Some(Item::Value(v)) = t.get_mut("value") {
            let suffix = v.decor().suffix().cloned();
            if let Some(sfx) = suffix {
                v.decor_mut().set_suffix("");
                tol.decor_mut().set_suffix(sfx);
            }
        }
        t.insert(key, Item::Value(tol));
        added.push(path.clone());
    }
    for key in [
        "x", "y", "z", "xx", "yy", "zz", "xy", "xz", "yz", "1", "2", "3",
    ] {
        if let Some(c) = t.get_mut(key) {
            path.push(key.to_string());
            placeholder_tols(c, path, added);
            path.pop();
        }
    }
}

/// The key of an `[expect]` entry's tolerance and a value it takes:
/// `tol_degrees` and its default for a quantity compared by angle, else
/// `tol` and any relative tolerance (an alias, `Ixx`, is no row).
fn tolerance_of(entry: &str) -> (&'static str, Value) {
    match QUANTITIES
        .iter()
        .find(|i| i.key == entry)
        .map(|i| i.compare)
    {
        Some(Compare::Angle) => ("tol_degrees", Value::from(DEFAULT_TOL_DEGREES)),
        Some(Compare::Bound) | None => ("tol", Value::from(DEFAULT_RELATIVE_TOL)),
    }
}

/// The default tolerance of an entry whose new value is `values` (in the
/// unit it is written in, `scale` SI per that unit), of dimension `dim`:
/// 1e-6 of the larger of its largest component and the body's own size in
/// its dimension (`body_size`). A single number whose own value is the
/// larger gets it as `"0.0001%"`, and so do the mass, the predicted mass
/// and the kinetic energy whenever they are not zero; anything else (a
/// vector, a matrix, a component small beside the body) gets it as an
/// absolute tolerance, rounded to one digit, since a relative tolerance
/// per component would trip on rounding noise in zero components.
///
/// So a centre of mass at (or by rounding near) the origin, or a product
/// of inertia that is zero, is not held to a zero tolerance, which
/// rounding on another machine would fail: only a user writes `tol = 0`.
fn default_tol(values: &[f64], target: Target, dim: Dim, scale: f64, s: &Summary) -> Value {
    let largest = values.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let size = body_size(s, dim) / scale;
    // NOTE: a body without extent (a lone point mass) or at rest has no
    // size in its dimension; 1e-6 of the unit the value is written in is
    // then the floor, so the tolerance is never zero.
    let size = if size.is_finite() && size > 0.0 {
        size
    } else {
        1.0
    };
    let whole_scalar = match target.quantity.info().bless {
        Bless::Relative => true,
        Bless::Absolute => false,
        Bless::Degrees => return Value::from(DEFAULT_TOL_DEGREES),
    };
    if values.len() == 1 && largest > 0.0 && (whole_scalar || largest >= size) {
        Value::from(DEFAULT_RELATIVE_TOL)
    } else {
        Value::from(round1(largest.max(size) * DEFAULT_VECTOR_TOL))
    }
}

/// The body's own size in dimension `dim`, SI: its largest radius of
/// gyration (a length), its largest principal moment (an inertia; the
/// largest component an inertia tensor can have), its mass, and that moment
/// times |ω| (angular momentum) or times |ω|²/2 (energy); 0 for anything
/// else.
fn body_size(s: &Summary, dim: Dim) -> f64 {
    let largest = |v: [f64; 3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let moment = largest(s.principal_moments);
    let omega = s
        .omega
        .map_or(0.0, |w| w.iter().map(|x| x * x).sum::<f64>().sqrt());
    // The body moving (`analysis::motion`): its mass centre's speed.
    let speed = s
        .values
        .triple(crate::quantity::Quantity::VelocityCom)
        .map_or(0.0, |v| v.iter().map(|x| x * x).sum::<f64>().sqrt());
    let offset = s
        .center_of_mass_ref
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        .sqrt();
    if dim == Dim::LENGTH {
        largest(s.radii_of_gyration)
    } else if dim == Dim::INERTIA {
        moment
    } else if dim == Dim::MASS {
        s.mass
    } else if dim == Dim::ANGULAR_MOMENTUM {
        moment * omega + s.mass * offset * speed
    } else if dim == Dim::ENERGY {
        moment * omega * omega / 2.0 + s.mass * speed * speed / 2.0
    } else if dim == Dim::VELOCITY {
        speed
    } else if dim == Dim::MOMENTUM {
        s.mass * speed
    } else {
        0.0
    }
}

/// `x` to one significant digit, so a default tolerance reads `6e-5`.
fn round1(x: f64) -> f64 {
    format!("{x:.0e}").parse().unwrap_or(x)
}

/// Write measured values into every entry that has a `value`, and into
/// each of `untoleranced` its default tolerance, from the value written.
fn write_values(
    doc: &mut DocumentMut,
    at: At,
    checks: &[Check],
    s: &Summary,
    untoleranced: &[(At, EntryPath)],
) -> bool {
    let mut changed = false;
    for group in entries(checks).values() {
        let first = group[0];
        let scale = written_scale(s.file_units, first.dim);
        let si = measured(group, s, 1.0);
        let measured: Vec<f64> = si.iter().map(|v| v / scale).collect();
        // The entry's key path: `center_of_mass.z` for a component, the
        // quantity itself for a whole vector or matrix.
        let mut path: Vec<&str> = first.name.split('.').collect();
        if group.len() > 1 {
            path.pop();
        }
        let tol = untoleranced
            .iter()
            .any(|(a, p)| *a == at && p.iter().map(String::as_str).eq(path.iter().copied()))
            .then(|| default_tol(&measured, first.target, first.dim, scale, s));
        let within = match &tol {
            Some(t) => tolerances_of(t, &si, scale, degrees(first.target)),
            None => tolerances(group, &si),
        };
        let value = |old: Option<&Value>| digits::shaped(old, &si, &within, first.dim, scale);
        changed |= write_entry(doc, at, &path, value, tol);
    }
    changed
}

/// The tolerance of each component of a principal axis for an angle `tol`
/// (radians): the three components' errors together turn the row by up to
/// √3 times one's, so each gets `tol`/√3; and no more than keeps the rows
/// orthonormal within a tenth of what the reader allows
/// (`AXES_ORTHONORMAL`) however wide the angle.
fn axis_tol(tol: f64) -> f64 {
    let widest = crate::thresholds::AXES_ORTHONORMAL / 10.0 / digits::SHARE;
    tol.min(widest) / 3f64.sqrt()
}

/// Whether an entry's tolerance is an angle (`tol_degrees`).
fn degrees(target: Target) -> bool {
    match target.quantity.info().bless {
        Bless::Degrees => true,
        Bless::Relative | Bless::Absolute => false,
    }
}

/// Each component's tolerance, SI, as the entry's checks hold it (`si`:
/// the exact values): an absolute one as it is, a relative one of the
/// value written, an angle (axes, radians) as it is on a unit vector's
/// components.
fn tolerances(group: &[&Check], si: &[f64]) -> Vec<f64> {
    group
        .iter()
        .flat_map(|c| match c.bound {
            Bound::Axes { tol, .. } => vec![Tol::Abs(axis_tol(tol)); 9],
            Bound::Value { tol, .. } => vec![tol],
            // Not an entry with a value (`entries`): held exactly.
            Bound::Range { .. } => vec![Tol::Abs(0.0)],
        })
        .zip(si)
        .map(|(t, v)| match t {
            Tol::Abs(t) => t,
            Tol::Rel(r) => r * v.abs(),
        })
        .collect()
}

/// Each component's tolerance, SI, from a default tolerance as written
/// (`default_tol`): a percentage of each value, degrees, or a number in
/// the unit written (`scale` SI per unit); `degrees` for axes, whose
/// default tolerance is an angle.
fn tolerances_of(tol: &Value, si: &[f64], scale: f64, degrees: bool) -> Vec<f64> {
    let each = |v: f64| match tol {
        Value::String(p) => {
            let percent = p.value().trim().trim_end_matches('%').trim();
            percent.parse::<f64>().map_or(0.0, |r| r / 100.0 * v.abs())
        }
        Value::Float(x) if degrees => axis_tol(x.value().to_radians()),
        Value::Float(x) => x.value() * scale,
        Value::Integer(x) => *x.value() as f64 * scale,
        Value::Boolean(_) | Value::Datetime(_) | Value::Array(_) | Value::InlineTable(_) => 0.0,
    };
    si.iter().map(|v| each(*v)).collect()
}

/// The checks of each entry with a `value`, in order: the checks of one
/// entry share its span.
fn entries(checks: &[Check]) -> BTreeMap<usize, Vec<&Check>> {
    let mut entries: BTreeMap<usize, Vec<&Check>> = BTreeMap::new();
    for c in checks
        .iter()
        .filter(|c| matches!(c.bound, Bound::Value { .. } | Bound::Axes { .. }))
    {
        entries.entry(c.span.start).or_default().push(c);
    }
    entries
}

/// The measured values of one entry's checks, in the unit written
/// (`scale` SI per unit). An entry compared by angle is one check of the
/// whole value.
fn measured(group: &[&Check], s: &Summary, scale: f64) -> Vec<f64> {
    group
        .iter()
        .flat_map(|c| match c.bound {
            Bound::Axes { .. } => (0..9)
                .map(|component| Target {
                    component,
                    ..c.target
                })
                .collect(),
            Bound::Value { .. } | Bound::Range { .. } => vec![c.target],
        })
        .map(|t| s.value(t) / scale)
        .collect()
}

/// `value` (of the old one) written into the entry at `path`, keeping the old value's
/// decor, and `tol` in place of its placeholder tolerance: whether the
/// entry changed.
fn write_entry(
    doc: &mut DocumentMut,
    at: At,
    path: &[&str],
    value: impl FnOnce(Option<&Value>) -> Value,
    tol: Option<Value>,
) -> bool {
    let Some(t) = entry_mut(doc, at, path).and_then(Item::as_table_like_mut) else {
        return false;
    };
    let Some(old) = t.get_mut("value") else {
        return false;
    };
    let mut changed = false;
    let decor = old.as_value().map(|v| v.decor().clone());
    let mut new = value(old.as_value());
    if let Some(d) = decor {
        *new.decor_mut() = d;
    }
    if old.as_value().map(|v| v.to_string()) != Some(new.to_string()) {
        *old = Item::Value(new);
        changed = true;
    }
    if let Some(mut tol) = tol
        && let Some(Item::Value(placeholder)) = t.get_mut(tolerance_of(path[0]).0)
    {
        *tol.decor_mut() = placeholder.decor().clone();
        *placeholder = tol;
        changed = true;
    }
    changed
}

/// The `[expect]` entry at `path` (`["center_of_mass", "z"]`).
fn entry_mut<'a>(doc: &'a mut DocumentMut, at: At, path: &[&str]) -> Option<&'a mut Item> {
    let mut item = expect_mut(doc, at)?;
    for key in path {
        item = item.get_mut(*key)?;
    }
    Some(item)
}

/// A new `[expect]` with the quantities the table blesses by default
/// (`quantity::Info::blessed_by_default`: the mass, centre of mass and
/// principal moments).
fn add_default_expect(doc: &mut DocumentMut, s: &Summary) {
    let mut t = toml_edit::Table::new();
    t.decor_mut()
        .set_prefix("\n# Expected mass properties, written by `massprop check --bless`.\n");
    for info in QUANTITIES.iter().filter(|i| i.blessed_by_default) {
        let scale = written_scale(s.file_units, info.dim);
        let target = |component| Target {
            quantity: info.quantity,
            component,
        };
        let v: Vec<f64> = (0..info.layout.count())
            .map(|k| s.value(target(k)) / scale)
            .collect();
        let mut entry = InlineTable::new();
        let tol = default_tol(&v, target(0), info.dim, scale, s);
        let si: Vec<f64> = v.iter().map(|x| x * scale).collect();
        let within = tolerances_of(&tol, &si, scale, degrees(target(0)));
        entry.insert("value", digits::shaped(None, &si, &within, info.dim, scale));
        entry.insert("tol", tol);
        t.insert(info.key, Item::Value(Value::InlineTable(entry)));
    }
    doc.insert("expect", Item::Table(t));
}

/// SI per unit of the plain numbers written for a value of dimension
/// `dim`: the file's units for a mass, a length or an inertia, SI for the
/// rest (H, T) and plain numbers for axes, as `[expect]` reads them and
/// `output::format::DisplayUnits` shows them.
fn written_scale(u: FileUnits, dim: Dim) -> f64 {
    if dim == Dim::MASS || dim == Dim::LENGTH || dim == Dim::INERTIA {
        u.factor(dim).value()
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::Endings;

    /// What `restore` gives for `edit` applied to the LF text of `text`.
    fn edited(text: &str, edit: impl Fn(&str) -> String) -> String {
        let endings = Endings::of(text);
        endings.restore(&edit(&endings.lf))
    }

    #[test]
    fn an_unedited_text_comes_back_byte_for_byte() {
        for text in [
            "",
            "a",
            "a\n",
            "a\r\n",
            "a\r\nb\nc",
            "a\n\r\n\nb\r\n",
            "a\r\r\n",
        ] {
            assert_eq!(edited(text, str::to_string), text);
        }
    }

    #[test]
    fn an_edited_line_keeps_its_own_ending() {
        let text = "a = 1\nb = 2\r\nc = 3\n";
        assert_eq!(
            edited(text, |t| t.replace("b = 2", "b = 5.0")),
            "a = 1\nb = 5.0\r\nc = 3\n"
        );
        assert_eq!(
            edited(text, |t| t.replace("a = 1", "a = 7")),
            "a = 7\nb = 2\r\nc = 3\n"
        );
    }

    #[test]
    fn a_new_line_takes_the_ending_most_lines_have() {
        let mostly_crlf = "a = 1\r\nb = 2\nc = 3\r\n";
        assert_eq!(
            edited(mostly_crlf, |t| t.replace("b = 2\n", "b = 2\nt = 0\n")),
            "a = 1\r\nb = 2\nt = 0\r\nc = 3\r\n"
        );
        let mostly_lf = "a = 1\nb = 2\r\nc = 3\n";
        assert_eq!(
            edited(mostly_lf, |t| format!("{t}d = 4\n")),
            "a = 1\nb = 2\r\nc = 3\nd = 4\n"
        );
    }

    #[test]
    fn a_tie_gives_new_lines_lf() {
        assert_eq!(edited("a\r\nb\n", |t| format!("{t}c\n")), "a\r\nb\nc\n");
    }

    #[test]
    fn a_last_line_without_an_ending_gets_one_when_lines_follow() {
        assert_eq!(edited("a\r\nb", |t| format!("{t}\nc\n")), "a\r\nb\r\nc\r\n");
    }
}
