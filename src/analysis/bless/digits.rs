//! `--bless`'s numbers: each value with the fewest significant digits
//! that keep it within 1/1000 of its tolerance of the exact value
//! (`fewest_digits`), in the form the file wrote it (`Form`): a bare
//! number stays a bare number, a quantity string (`"4.176 kg"`) stays a
//! string in its own unit (`"4.18 kg"`), so a hand-kept file's diff shows
//! what changed and nothing else.

use crate::units::Dim;
use toml_edit::{Array, Value};

/// The share of an entry's tolerance a written value may lie off the
/// exact one: small enough that a blessed file checks as the exact value
/// would, whatever the check's rounding.
pub const SHARE: f64 = 1e-3;

/// The most significant digits an f64 needs to be read back exactly.
const MAX_DIGITS: usize = 17;

/// `v` rounded to the fewest significant digits (1 to 17) that keep it
/// within `within` of `v`; `v` itself when none does (a `within` of 0, or
/// not finite), which Rust then writes in its shortest exact form.
pub fn fewest_digits(v: f64, within: f64) -> f64 {
    if !v.is_finite() || v == 0.0 {
        return v;
    }
    (1..=MAX_DIGITS)
        .map(|d| rounded(v, d))
        .find(|r| (r - v).abs() <= within)
        .unwrap_or(v)
}

/// `v` to `d` significant digits (the nearest decimal of `d` digits, as
/// Rust's `{:e}` rounds it, read back).
pub fn rounded(v: f64, d: usize) -> f64 {
    format!("{:.*e}", d.saturating_sub(1), v)
        .parse()
        .unwrap_or(v)
}

/// How one number of an `[expect]` value was written.
#[derive(Clone, Debug, PartialEq)]
pub enum Form {
    /// A bare number, in the unit `[expect]` reads plain numbers in.
    Number,
    /// A string: `unit` its unit as written (empty for a plain number in
    /// a string), `factor` SI per that unit.
    Quantity { unit: String, factor: f64 },
}

impl Form {
    /// The form of `old` (a number of dimension `dim`; `scale` SI per
    /// plain number): a string that is a number and a unit of that
    /// dimension (or a number alone) keeps its form; anything else (an
    /// expression, no old value) is written as a bare number.
    pub fn of(old: Option<&Value>, dim: Dim, scale: f64) -> Form {
        let Some(Value::String(s)) = old else {
            return Form::Number;
        };
        let Ok((_, unit)) = crate::units::split_number(s.value()) else {
            return Form::Number;
        };
        let unit = unit.trim();
        if unit.is_empty() {
            return Form::Quantity {
                unit: String::new(),
                factor: scale,
            };
        }
        match crate::units::parse_quantity(&format!("1 {unit}"), dim) {
            Ok(factor) if factor.is_finite() && factor > 0.0 => Form::Quantity {
                unit: unit.to_string(),
                factor,
            },
            Ok(_) | Err(_) => Form::Number,
        }
    }

    /// `si` (SI) written in this form, with the fewest digits that keep it
    /// within `SHARE` of `tol` (SI) of `si`; `scale`: SI per plain number.
    pub fn write(&self, si: f64, tol: f64, scale: f64) -> Value {
        match self {
            Form::Number => Value::from(fewest_digits(si / scale, tol / scale * SHARE)),
            Form::Quantity { unit, factor } => {
                let n = number_text(fewest_digits(si / factor, tol / factor * SHARE));
                Value::from(if unit.is_empty() {
                    n
                } else {
                    format!("{n} {unit}")
                })
            }
        }
    }
}

/// A number as a quantity string writes it: plainly, or with an exponent
/// when plainly it would take more than a few zeros (`1.5e-9`, `2.5e20`).
pub fn number_text(x: f64) -> String {
    let e = if x == 0.0 {
        0
    } else {
        x.abs().log10().floor() as i32
    };
    if (-5..16).contains(&e) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The value of an entry written in the form of `old`: one number, a
/// vector of three, or rows of three, each number in the form of the old
/// one at its place. `si` and `tol`: each component's exact value and
/// tolerance, SI.
pub fn shaped(old: Option<&Value>, si: &[f64], tol: &[f64], dim: Dim, scale: f64) -> Value {
    let one = |old: Option<&Value>, k: usize| Form::of(old, dim, scale).write(si[k], tol[k], scale);
    fn at(old: Option<&Value>, i: usize) -> Option<&Value> {
        old.and_then(Value::as_array).and_then(|a| a.get(i))
    }
    match si.len() {
        1 => one(old, 0),
        3 => Value::Array((0..3).map(|k| one(at(old, k), k)).collect::<Array>()),
        n => Value::Array(
            (0..n.div_ceil(3))
                .map(|row| {
                    let old_row = at(old, row);
                    Value::Array(
                        (3 * row..(3 * row + 3).min(n))
                            .map(|k| one(at(old_row, k - 3 * row), k))
                            .collect::<Array>(),
                    )
                })
                .collect::<Array>(),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A written bare number as a TOML reader reads it back.
    fn reread(v: &Value) -> f64 {
        let doc: toml::Table = toml::from_str(&format!("x = {v}")).expect("it parses");
        doc["x"].as_float().expect("a float")
    }

    #[test]
    fn a_mass_to_a_thousandth_of_its_tolerance_keeps_the_digits_it_needs() {
        // 0.1 % of 4.176 kg is 4.176 g; a thousandth of that is 4.176 mg:
        // 4.17633 is 4.65 mg off, 4.176325 0.35 mg.
        assert_eq!(fewest_digits(4.176_325_349_566, 4.176e-3 * SHARE), 4.176325);
    }

    #[test]
    fn a_zero_tolerance_keeps_the_exact_value() {
        assert_eq!(
            fewest_digits(5.035_625_349_566_263_5, 0.0),
            5.035_625_349_566_263_5
        );
    }

    #[test]
    fn a_quantity_string_stays_a_string_in_its_own_unit() {
        let old = Value::from("4.176 kg");
        // Within 0.05 kg / 1000 = 50 mg: 4.181 is 234.5 mg off, 4.1812 34.5.
        let new = shaped(Some(&old), &[4.1812345], &[0.05], Dim::MASS, 1.0);
        assert_eq!(new.as_str(), Some("4.1812 kg"));
        // Within 1 mm / 1000: 12.35 mm is 4.4 µm off, 12.346 0.4 µm.
        let old = Value::from("12 mm");
        let new = shaped(Some(&old), &[0.012_345_6], &[1e-3], Dim::LENGTH, 1.0);
        assert_eq!(new.as_str(), Some("12.346 mm"));
    }

    #[test]
    fn a_bare_number_stays_a_bare_number() {
        let new = shaped(
            Some(&Value::from(4.0)),
            &[4.1812345],
            &[0.05],
            Dim::MASS,
            1.0,
        );
        assert_eq!(new.as_float(), Some(4.1812));
    }

    #[test]
    fn a_vector_keeps_each_components_form() {
        let old: Value = "[\"1 mm\", 2, \"3 in\"]".parse().unwrap();
        let new = shaped(
            Some(&old),
            &[0.001_234_1, 2.000_01, 0.0762],
            &[1e-3; 3],
            Dim::LENGTH,
            1.0,
        );
        // Within 1 µm: 1.234 mm (0.1 µm off), 2.00001 m (2.0 is 10 µm
        // off), and 3 in exactly.
        assert_eq!(new.to_string(), "[\"1.234 mm\", 2.00001, \"3 in\"]");
    }

    #[test]
    fn an_expression_is_written_as_a_bare_number() {
        let old = Value::from("2 * leg");
        assert_eq!(Form::of(Some(&old), Dim::LENGTH, 1.0), Form::Number);
    }

    proptest! {
        /// The number written, read back, is within a thousandth of the
        /// tolerance of the exact value, and one digit fewer would not be
        /// (unless it has one digit already).
        #[test]
        fn the_fewest_digits_stay_within_a_thousandth_of_the_tolerance(
            mantissa in 1.0f64..10.0,
            exponent in -12i32..12,
            negative in any::<bool>(),
            relative in 1e-9f64..0.5,
        ) {
            let v = mantissa * 10f64.powi(exponent) * if negative { -1.0 } else { 1.0 };
            let tol = relative * v.abs();
            let written = Form::Number.write(v, tol, 1.0);
            let back = reread(&written);
            prop_assert!((back - v).abs() <= tol * SHARE, "{v} → {written}");
            let digits = format!("{:e}", back.abs())
                .split('e')
                .next()
                .map_or(0, |m| m.chars().filter(char::is_ascii_digit).count());
            if digits > 1 {
                let fewer = rounded(v, digits - 1);
                prop_assert!((fewer - v).abs() > tol * SHARE, "{v}: {fewer} would do");
            }
        }

        /// A quantity string, read back by the unit parser, is as near.
        #[test]
        fn a_quantity_string_read_back_is_within_a_thousandth_of_the_tolerance(
            mantissa in 1.0f64..10.0,
            exponent in -6i32..6,
            relative in 1e-9f64..0.5,
        ) {
            let v = mantissa * 10f64.powi(exponent);
            let tol = relative * v;
            let form = Form::of(Some(&Value::from("1 g")), Dim::MASS, 1.0);
            let written = form.write(v, tol, 1.0);
            let text = written.as_str().expect("a string").to_string();
            prop_assert!(text.ends_with(" g"), "{text}");
            let back = crate::units::parse_quantity(&text, Dim::MASS).expect("it reads");
            // The unit's factor is exact (1/1000), one rounding each way.
            prop_assert!((back - v).abs() <= tol * SHARE * (1.0 + 1e-9) + v * 4.0 * f64::EPSILON, "{v} → {text}");
        }
    }
}
