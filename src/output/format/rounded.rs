//! Six significant digits without the exact rounding's big integers:
//! `push_sig`'s `{:.N$e}`, from the shortest digits where they are the
//! rounding.

use super::Ascii;
use std::fmt::Write;

/// `x` as `{x:.places$e}` writes it: `places` digits after the point.
///
/// NOTE: the shortest digits that read back as `x` (serde_json's, which
/// JSON writes every number with: far faster than the exact rounding,
/// whose fallback to big integers was a third of the time of `report
/// --full` of a tree of 2²⁰ instances) are the rounding itself when there
/// are no more of them than asked for: x lies within half an ulp of them,
/// and for a normal x and up to 15 digits that is far less than half a
/// unit of the last digit, so no other decimal of that many digits is
/// nearer (nor a tie). They are then padded with zeros; else the exact
/// rounding is made. (`the_shortest_digits_padded_are_the_rounding`.)
pub(super) fn push_rounded_sci(buf: &mut Ascii<64>, x: f64, places: usize) {
    if places <= 14 && x.is_normal() {
        let mut short = [0u8; 40];
        let mut w = &mut short[..];
        use serde_json::ser::Formatter as _;
        if serde_json::ser::CompactFormatter
            .write_f64(&mut w, x)
            .is_ok()
        {
            let len = 40 - w.len();
            if let Some((neg, all, exp)) = decimal(&short[..len])
                && all.len() <= places + 1
            {
                let digits = &all[..];
                let digit = |d: u8| char::from(b'0' + d);
                let _ = buf.write_str(if neg { "-" } else { "" });
                let _ = buf.write_char(digit(digits[0]));
                if places > 0 {
                    let _ = buf.write_char('.');
                }
                for k in 1..=places {
                    let _ = buf.write_char(digit(digits.get(k).copied().unwrap_or(0)));
                }
                let _ = write!(buf, "e{exp}");
                return;
            }
        }
    }
    let _ = write!(buf, "{x:.places$e}");
}

/// A number as serde_json writes one (`-12.5`, `1e-7`, `1.5e300`,
/// `0.001`): its sign, its significant digits (the first not zero, none
/// after the last not zero) and the decimal exponent of the first, as
/// `{:e}` has it; `None` for zero or text that is not such a number.
fn decimal(text: &[u8]) -> Option<(bool, Digits, i32)> {
    let (neg, text) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exp) = match text.iter().position(|&b| b == b'e' || b == b'E') {
        Some(i) => (
            &text[..i],
            std::str::from_utf8(&text[i + 1..])
                .ok()?
                .parse::<i32>()
                .ok()?,
        ),
        None => (text, 0),
    };
    let point = mantissa
        .iter()
        .position(|&b| b == b'.')
        .unwrap_or(mantissa.len());
    let mut all = Digits::default();
    for (i, &b) in mantissa.iter().enumerate() {
        if i != point {
            if !b.is_ascii_digit() || all.len == all.digits.len() {
                return None;
            }
            all.digits[all.len] = b - b'0';
            all.len += 1;
        }
    }
    let first = all.iter().position(|&d| d != 0)?;
    let last = all.iter().rposition(|&d| d != 0)?;
    let lead = point as i32 - first as i32 - 1 + exp;
    all.digits.copy_within(first..=last, 0);
    all.len = last - first + 1;
    Some((neg, all, lead))
}

/// Decimal digits (0 to 9), on the stack.
#[derive(Default)]
struct Digits {
    digits: [u8; 32],
    len: usize,
}

impl std::ops::Deref for Digits {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        &self.digits[..self.len]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `push_rounded_sci`'s against the exact rounding's text.
    fn same_as_exact(x: f64, places: usize) {
        let mut ours = Ascii::<64>::new();
        push_rounded_sci(&mut ours, x, places);
        assert_eq!(
            ours.as_str(),
            format!("{x:.places$e}"),
            "{x:e}, {places} places"
        );
    }

    #[test]
    fn the_shortest_digits_padded_are_the_rounding() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(20_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        // Every bit pattern (the slow path, mostly), and numbers of few
        // digits (the fast one): integers, halves, short decimals, each
        // scaled by a power of ten, and the doubles next to them.
        let few = (any::<i32>(), -30i32..30, 0u32..4, -2i64..=2).prop_map(|(m, e, cut, step)| {
            let m = f64::from(m / 10i32.pow(cut));
            let x = m * 10f64.powi(e);
            f64::from_bits(x.to_bits().wrapping_add_signed(step))
        });
        let any_bits = any::<u64>().prop_map(f64::from_bits);
        runner
            .run(&(prop_oneof![few, any_bits], 0usize..16), |(x, places)| {
                if x.is_finite() {
                    same_as_exact(x, places);
                }
                Ok(())
            })
            .unwrap();
        for x in [
            1.0,
            37.0,
            0.5,
            1e-300,
            9.999995,
            99999.5,
            0.1 + 0.2,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            for places in 0..16 {
                same_as_exact(x, places);
                same_as_exact(-x, places);
            }
        }
    }
}
