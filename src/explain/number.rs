//! How `explain` writes a number: an exact value as its decimal where the
//! decimal ends (and is short), else the f64 in shortest round-trip form
//! (`output::format::shortest`, as `report`'s JSON writes it) with the
//! exact fraction beside it when that is short.

use super::exact::Exact;
use crate::output::format::shortest;

/// The longest decimal or fraction shown, in digits.
const SHORT: usize = 30;

/// A number as shown: the value, and the exact fraction where the value
/// is not exact and the fraction is short.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    pub value: String,
    pub fraction: Option<(String, String)>,
}

/// The decimal of n/d if d has no prime factor but 2 and 5 and the
/// decimal is at most `SHORT` digits.
fn decimal(n: i128, d: i128) -> Option<String> {
    let (mut twos, mut fives, mut rest) = (0u32, 0u32, d);
    while rest % 2 == 0 {
        rest /= 2;
        twos += 1;
    }
    while rest % 5 == 0 {
        rest /= 5;
        fives += 1;
    }
    if rest != 1 {
        return None;
    }
    let k = twos.max(fives);
    let scaled = n
        .checked_mul(2i128.checked_pow(k - twos)?)?
        .checked_mul(5i128.checked_pow(k - fives)?)?;
    let digits = scaled.unsigned_abs().to_string();
    if digits.len() > SHORT {
        return None;
    }
    let k = k as usize;
    let body = if k == 0 {
        digits
    } else if digits.len() > k {
        format!(
            "{}.{}",
            &digits[..digits.len() - k],
            &digits[digits.len() - k..]
        )
    } else {
        format!("0.{}{digits}", "0".repeat(k - digits.len()))
    };
    Some(if scaled < 0 { format!("-{body}") } else { body })
}

/// What a value beyond f64's range is shown as (an invariant of a large
/// tensor, I₃ ~ I³, can pass it when the tensor does not): never inf.
pub const BEYOND: &str = "beyond f64's range";

/// `x` as shown.
pub fn show(x: Exact) -> Shown {
    let approx = if x.approx == 0.0 { 0.0 } else { x.approx };
    if !approx.is_finite() && x.exact.is_none() {
        return Shown {
            value: BEYOND.into(),
            fraction: None,
        };
    }
    match x.exact {
        Some((n, d)) => match decimal(n, d) {
            Some(s) => Shown {
                value: s,
                fraction: None,
            },
            None => {
                let (ns, ds) = (n.to_string(), d.to_string());
                Shown {
                    value: shortest(approx),
                    fraction: (ns.len() + ds.len() <= SHORT).then_some((ns, ds)),
                }
            }
        },
        None => Shown {
            value: shortest(approx),
            fraction: None,
        },
    }
}

/// `x` as text: its value, and "(exactly n/d)" where `show` gives one.
pub fn text(x: Exact) -> String {
    let s = show(x);
    match s.fraction {
        Some((n, d)) => format!("{} (exactly {n}/{d})", s.value),
        None => s.value,
    }
}

/// A final figure: the report's f64 `r` (shortest round-trip, as its
/// JSON writes it), and `x` exactly as a fraction where it has one that
/// is short and the report's figure is not it already.
pub fn show_reported(x: Exact, r: f64) -> Shown {
    let value = shortest(if r == 0.0 { 0.0 } else { r });
    let fraction = x.exact.and_then(|(n, d)| {
        let same = decimal(n, d).is_some_and(|s| s == value);
        let (ns, ds) = (n.to_string(), d.to_string());
        (!same && ns.len() + ds.len() <= SHORT).then_some((ns, ds))
    });
    Shown { value, fraction }
}

/// `text` of a final figure (`show_reported`).
pub fn text_reported(x: Exact, r: f64) -> String {
    let s = show_reported(x, r);
    match s.fraction {
        Some((n, d)) => format!("{} (exactly {n}/{d})", s.value),
        None => s.value,
    }
}

/// `tex` of a final figure (`show_reported`).
pub fn tex_reported(x: Exact, r: f64) -> String {
    tex_shown(show_reported(x, r))
}

/// `x`'s value alone (inside a formula with numbers).
pub fn plain(x: Exact) -> String {
    show(x).value
}

/// `x` as TeX: the value, and the exact fraction as `\tfrac`.
pub fn tex(x: Exact) -> String {
    tex_shown(show(x))
}

fn tex_shown(s: Shown) -> String {
    let value = tex_number(&s.value);
    match s.fraction {
        Some((n, d)) => {
            let (sign, n) = match n.strip_prefix('-') {
                Some(n) => ("-", n.to_string()),
                None => ("", n),
            };
            format!("{value} \\;\\left(= {sign}\\tfrac{{{n}}}{{{d}}}\\right)")
        }
        None => value,
    }
}

/// A number as TeX: `1.5e-7` as `1.5 \times 10^{-7}`.
pub fn tex_number(s: &str) -> String {
    if s == BEYOND {
        return format!("\\text{{{BEYOND}}}");
    }
    match s.split_once('e') {
        Some((m, e)) if e.parse::<i32>().is_ok() => format!("{m} \\times 10^{{{e}}}"),
        _ => s.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_ending_decimal_is_shown_whole() {
        assert_eq!(text(Exact::ratio(7, 8)), "0.875");
        assert_eq!(text(Exact::ratio(-3, 400)), "-0.0075");
        assert_eq!(text(Exact::ratio(825234375, 100000000)), "8.25234375");
        assert_eq!(text(Exact::ratio(1250, 1)), "1250");
    }

    #[test]
    fn a_third_is_its_f64_and_its_fraction() {
        assert_eq!(
            text(Exact::ratio(4375, 6)),
            "729.1666666666666 (exactly 4375/6)"
        );
    }

    #[test]
    fn an_overflow_is_said_not_printed_as_inf() {
        assert_eq!(text(Exact::inexact(f64::INFINITY)), BEYOND);
        assert_eq!(text(Exact::inexact(f64::NAN)), BEYOND);
    }

    #[test]
    fn a_number_known_only_in_f64_is_its_shortest_form() {
        assert_eq!(
            text(Exact::inexact(std::f64::consts::PI)),
            "3.141592653589793"
        );
    }
}
