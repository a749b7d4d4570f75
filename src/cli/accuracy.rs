//! `--precision` and `--rtol`, the same for every command that composes,
//! and the relative tolerances users write (`1e-6`, `1%`).

use crate::analysis::summary::{Accuracy, PrecisionChoice};
use clap::builder::PossibleValue;
use clap::{Args, ValueEnum};

impl ValueEnum for PrecisionChoice {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            PrecisionChoice::Auto,
            PrecisionChoice::Standard,
            PrecisionChoice::Extended,
        ]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            PrecisionChoice::Auto => PossibleValue::new("auto").help(
                "`standard`, recomputed in `extended` where an error bound exceeds --rtol (the default)",
            ),
            PrecisionChoice::Standard => PossibleValue::new("standard")
                .help("f64 with compensated sums and a Jacobi eigen solver"),
            PrecisionChoice::Extended => PossibleValue::new("extended").help(
                "Double-double (~32 significant digits) throughout: for the smallest principal moment of very slender or flat bodies",
            ),
        })
    }
}

/// `--precision` and `--rtol`, the same for every command that composes.
#[derive(Args, Debug, Clone)]
pub struct AccuracyArgs {
    /// Arithmetic. Every value is reported with a rigorous bound on its
    /// rounding error (`error_bounds`); `auto` computes in `standard` and
    /// recomputes in `extended` when a bound exceeds --rtol, and warns of
    /// any value neither meets (JSON `error_bounds`, `accuracy_warnings`).
    #[arg(long, value_enum, default_value_t)]
    pub precision: PrecisionChoice,

    /// The accuracy asked for, relative to each value (a value zero to
    /// within its bound is judged against the largest of its kind).
    #[arg(
        long,
        value_name = "REL",
        default_value = "1e-12",
        value_parser = parse_rtol,
        allow_hyphen_values = true
    )]
    pub rtol: f64,
}

impl AccuracyArgs {
    pub(super) fn accuracy(&self) -> Accuracy {
        Accuracy {
            precision: self.precision,
            rtol: self.rtol,
        }
    }
}

/// A relative tolerance as users write it: a number (`1e-6`) or a
/// percentage (`1%`, `0.5 %`). Its range is the command's to check.
pub(super) fn parse_fraction(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let (number, scale) = match t.strip_suffix('%') {
        Some(n) => (n.trim_end(), 0.01),
        None => (t, 1.0),
    };
    number
        .parse::<f64>()
        .map(|x| x * scale)
        .map_err(|_| "expected a number such as 1e-6, or a percentage such as 1%".to_string())
}

/// An `--rtol`: finite, at least 2⁻⁵² (no f64 result is closer to the exact
/// value than its own rounding, up to 2⁻⁵³ of it) and below 1.
fn parse_rtol(text: &str) -> Result<f64, String> {
    let min = f64::EPSILON;
    match text.trim().parse::<f64>() {
        Ok(x) if (min..1.0).contains(&x) => Ok(x),
        Ok(x) if x.is_finite() && x > 0.0 && x < min => Err(format!(
            "{x:e} is below {min:e}: no f64 result is closer than its own rounding"
        )),
        _ => Err(format!(
            "expected a relative accuracy from {min:e} to below 1, such as 1e-12"
        )),
    }
}
