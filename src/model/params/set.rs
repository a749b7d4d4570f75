//! A `--set NAME=VALUE` checked where it is given: a value of another
//! dimension than the file's definition it replaces is an error at the
//! flag, which names the definition and suggests the value in the file's
//! unit for its dimension (`--set d="200 mm"`).

use super::flag;
use crate::diag::{Diagnostic, Source};
use crate::expr::{self, Expr, Value};
use crate::model::Ctx;
use crate::model::raw::{Params as RawParams, Quantity};
use crate::model::tolerance::Recorder;
use crate::units::{self, Dim, FileUnits};
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

impl Ctx<'_> {
    /// The file's `[params]` as it defines them, read alone (no value
    /// passed in); `None` where they cannot be (an error that a `--set`
    /// may mend, such as a cycle it breaks).
    pub(super) fn own_params(&self, raw: Option<&RawParams>) -> Option<BTreeMap<String, Value>> {
        let mut alone = Ctx {
            source: self.source,
            units: self.units,
            materials: Default::default(),
            params: Default::default(),
            growth: Default::default(),
        };
        alone.read_params(&mut Recorder::default(), raw, &[]).ok()?;
        Some(alone.params.values)
    }

    /// A `--set` value of another dimension than the definition it
    /// replaces is refused at the flag (each use would fail at its key,
    /// as the file's error), with the value in the file's unit of the
    /// definition's dimension where it is a plain number (`--set
    /// d="200 mm"`). The definition's value is `own` (the file's
    /// parameters read alone), else the definition read alone in the
    /// parameters read so far, else unknown (no check).
    pub(super) fn same_dimension(
        &self,
        name: &str,
        s: &Source,
        (key, q): &(Range<usize>, &Spanned<Quantity>),
        own: Option<Value>,
        value: Value,
    ) -> Result<(), Diagnostic> {
        let file = match (own, q.get_ref()) {
            (Some(v), _) => v,
            (None, Quantity::Number(x)) => Value::of_f64(*x),
            (None, Quantity::Text(t)) => {
                let t = crate::model::tolerance::split(t).map_or(t.as_str(), |s| s.0);
                let params = &self.params;
                let Some(v) = Expr::parse(t)
                    .ok()
                    .and_then(|e| e.eval(&|n| params.get(n), &Vec::new).ok())
                else {
                    return Ok(());
                };
                v
            }
        };
        if file.dim == value.dim {
            return Ok(());
        }
        let (line, col) = self.source.line_col(key.start);
        let text = s.text.trim();
        // The number alone, if the value is one (with or without a unit).
        let number = units::split_number(text)
            .ok()
            .map(|(_, unit)| text[..text.len() - unit.len()].trim_end());
        let plain = number.is_some_and(|n| n.len() == text.len());
        let help = if file.dim == Dim::DIMENSIONLESS {
            match number {
                Some(n) if !plain => format!(
                    "`{name}` is a plain number in the file: did you mean `--set {name}={n}`?"
                ),
                _ => format!("give `{name}` a plain number, as the file's definition is"),
            }
        } else {
            match (file_unit(self.units, file.dim), number) {
                (Some(unit), Some(n)) if plain => format!(
                    "did you mean `--set {name}=\"{n} {unit}\"`, in the file's unit of {}?",
                    dim_word(file.dim)
                ),
                (Some(unit), _) => format!(
                    "give `{name}` a unit of {}, such as the file's `{unit}`",
                    dim_word(file.dim)
                ),
                (None, _) => format!(
                    "give `{name}` {}, as the file's definition is",
                    match file.dim.describe() {
                        "a quantity of another kind" => "in the file's dimension".to_string(),
                        _ => format!("with a unit of {}", dim_word(file.dim)),
                    }
                ),
            }
        };
        Err(s
            .error(
                0..s.text.len(),
                format!(
                    "`{}` gives {}, but the file's `{name}` is {}",
                    flag(name, s),
                    expr::describe(value.dim),
                    expr::describe(file.dim)
                ),
            )
            .note(format!(
                "`{name}` is defined at {}:{line}:{col}",
                self.source.name
            ))
            .help(help))
    }
}

/// The file's unit of a dimension of mass and length (`g/mm^3` in a file
/// in mm and g): what a plain number of it is read in. `None` for one of
/// time (read in SI) or a plain number.
fn file_unit(u: FileUnits, d: Dim) -> Option<String> {
    if d.time != 0 || d == Dim::DIMENSIONLESS {
        return None;
    }
    let power = |symbol: &str, p: i32| match p.abs() {
        1 => symbol.to_string(),
        n => format!("{symbol}^{n}"),
    };
    let (mut over, mut under) = (Vec::new(), Vec::new());
    for (symbol, p) in [(u.mass, d.mass), (u.length, d.length)] {
        if p > 0 {
            over.push(power(symbol, p));
        } else if p < 0 {
            under.push(power(symbol, p));
        }
    }
    if over.is_empty() {
        return None;
    }
    let mut unit = over.join("*");
    for u in under {
        unit.push('/');
        unit.push_str(&u);
    }
    Some(unit)
}

/// "a length" → "length", for "a unit of length".
fn dim_word(d: Dim) -> String {
    let w = d.describe();
    w.strip_prefix("a ")
        .or_else(|| w.strip_prefix("an "))
        .unwrap_or(w)
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    const MM_G: FileUnits = FileUnits {
        length: "mm",
        mass: "g",
    };

    #[test]
    fn the_files_unit_of_each_dimension_reads_back_as_that_dimension_and_factor() {
        for d in [
            Dim::LENGTH,
            Dim::AREA,
            Dim::MASS,
            Dim::DENSITY,
            Dim::AREAL_DENSITY,
            Dim::LINEAR_DENSITY,
            Dim::INERTIA,
        ] {
            let unit = file_unit(MM_G, d).unwrap_or_else(|| panic!("a unit for {d:?}"));
            let read = units::parse_unit(&unit).unwrap_or_else(|e| panic!("{unit}: {e:?}"));
            assert_eq!(read.dim, d, "{unit}");
            assert_eq!(read.factor, MM_G.factor(d), "{unit}");
        }
    }

    #[test]
    fn a_length_in_a_file_in_millimetres_is_suggested_in_mm() {
        assert_eq!(file_unit(MM_G, Dim::LENGTH).as_deref(), Some("mm"));
        assert_eq!(file_unit(MM_G, Dim::DENSITY).as_deref(), Some("g/mm^3"));
    }

    #[test]
    fn a_plain_number_or_a_dimension_of_time_has_no_file_unit() {
        assert_eq!(file_unit(MM_G, Dim::DIMENSIONLESS), None);
        assert_eq!(file_unit(MM_G, Dim::ANGULAR_VELOCITY), None);
    }
}
