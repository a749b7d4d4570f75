//! Six significant digits without the exact rounding's big integers:
//! `push_sig`'s `{:.N$e}`, from the shortest digits rounded, where they
//! round as the number does.

#[cfg(test)]
use super::Ascii;
#[cfg(test)]
use std::fmt::Write;

/// `x` as `{x:.places$e}` writes it: `places` digits after the point,
/// from `rounded` where it rounds (what the tests hold to `{:e}`).
#[cfg(test)]
fn push_rounded_sci(buf: &mut Ascii<64>, x: f64, places: usize) {
    if places <= 14
        && x.is_normal()
        && let Some((neg, digits, exp)) = rounded(x, places)
    {
        let digit = |d: u8| char::from(b'0' + d);
        let _ = buf.write_str(if neg { "-" } else { "" });
        let _ = buf.write_char(digit(digits[0]));
        if places > 0 {
            let _ = buf.write_char('.');
        }
        for &d in &digits[1..=places] {
            let _ = buf.write_char(digit(d));
        }
        let _ = write!(buf, "e{exp}");
        return;
    }
    let _ = write!(buf, "{x:.places$e}");
}

/// `push_sig`'s text of `x` to `places` + 1 significant digits, after
/// `out`, made from the rounded digits (`digits`) with no text between:
/// whether it was (else a tie of the shortest digits, a number not
/// normal, more than 15 digits or a whole number past the digits,
/// `push_sig`'s own path).
///
/// NOTE: the same text as `push_sig` writes from `{x:.places$e}`: with an
/// exponent outside −4..6, the digits without trailing zeros; else fixed,
/// trailing zeros and a bare point dropped
/// (`push_sig_from_the_rounded_digits_is_push_sig_from_the_exact_rounding`).
pub(super) fn push_sig_fast(out: &mut String, x: f64, places: usize) -> bool {
    let Some(s) = Sig::of(x, places) else {
        return false;
    };
    out.push_str(std::str::from_utf8(s.text().as_bytes()).expect("invariant: ASCII"));
    true
}

/// `push_sig_fast` after bytes.
pub(super) fn extend_sig_fast(out: &mut Vec<u8>, x: f64, places: usize) -> bool {
    let Some(s) = Sig::of(x, places) else {
        return false;
    };
    out.extend_from_slice(s.text().as_bytes());
    true
}

/// The length of the text `push_sig_fast` writes for `x`, counted from its
/// digits and exponent without writing it; `None` where it writes none.
pub(super) fn sig_len(x: f64, places: usize) -> Option<usize> {
    let s = Sig::of(x, places)?;
    let digits = match s.layout {
        // d, then `.` and the digits up to the last not zero, `e`, the
        // exponent.
        Layout::Sci => 1 + if s.last > 0 { 1 + s.last } else { 0 } + 1 + int_len(s.exp),
        // `0` or the digits before the point, then `.`, the zeros and the
        // digits up to the last not zero.
        Layout::Fixed { before, zeros } => {
            before.max(1)
                + if s.last >= before {
                    1 + zeros + s.last + 1 - before
                } else {
                    0
                }
        }
    };
    Some(usize::from(s.neg) + digits)
}

/// The length of `n` in decimal, as `Text::int` writes it.
fn int_len(n: i32) -> usize {
    let mut m = n.unsigned_abs();
    let mut len = 1 + usize::from(n < 0);
    while m >= 10 {
        m /= 10;
        len += 1;
    }
    len
}

/// A number rounded for `push_sig`: its sign, its digits without
/// trailing zeros (as one integer: the first not zero), the index of the
/// last of them, the decimal exponent of the first, and how it is written.
struct Sig {
    neg: bool,
    digits: u64,
    last: usize,
    exp: i32,
    layout: Layout,
}

/// `push_sig`'s two notations.
#[derive(Clone, Copy)]
enum Layout {
    /// `d.ddde±x`: an exponent outside −4..6.
    Sci,
    /// `ddd.ddd` or `0.000ddd`: `before` digits before the point, `zeros`
    /// zeros after it before the first digit.
    Fixed { before: usize, zeros: usize },
}

impl Sig {
    /// `x` to `places` + 1 digits: from the integer scaling (`scaled`),
    /// else from the shortest digits rounded (`rounded`); `None` where
    /// neither answers or the fixed notation would round to a whole
    /// number past the digits.
    fn of(x: f64, places: usize) -> Option<Sig> {
        if places > 14 || !x.is_normal() {
            return None;
        }
        let (neg, n, exp) = match super::scaled::scaled(x, places) {
            Some(r) => r,
            None => {
                let (neg, d, exp) = rounded(x, places)?;
                let n = d[..=places]
                    .iter()
                    .fold(0u64, |n, &k| n * 10 + u64::from(k));
                (neg, n, exp)
            }
        };
        if n == 0 {
            return None;
        }
        let (mut digits, mut last) = (n, places);
        while digits % 10 == 0 {
            digits /= 10;
            last -= 1;
        }
        let layout = if !(-4..6).contains(&exp) {
            Layout::Sci
        } else if exp > places as i32 {
            return None;
        } else if exp >= 0 {
            Layout::Fixed {
                before: exp as usize + 1,
                zeros: 0,
            }
        } else {
            Layout::Fixed {
                before: 0,
                zeros: (-exp - 1) as usize,
            }
        };
        Some(Sig {
            neg,
            digits,
            last,
            exp,
            layout,
        })
    }

    /// Its text, as `push_sig` writes it: with an exponent, the digits
    /// without trailing zeros; fixed, trailing zeros and a bare point
    /// dropped.
    fn text(&self) -> Text {
        // The digits, 0 past the last (up to `places`).
        let mut d = [0u8; 16];
        let mut t = self.digits;
        for k in (0..=self.last).rev() {
            d[k] = (t % 10) as u8;
            t /= 10;
        }
        // At most a sign, 15 digits, a point, 4 zeros and an exponent's 5.
        let mut text = Text::default();
        if self.neg {
            text.push(b'-');
        }
        match self.layout {
            Layout::Sci => {
                text.push(b'0' + d[0]);
                if self.last > 0 {
                    text.push(b'.');
                    text.digits(&d[1..=self.last]);
                }
                text.push(b'e');
                text.int(self.exp);
            }
            Layout::Fixed { before, zeros } => {
                // The digits before the point, then after it.
                if before == 0 {
                    text.push(b'0');
                }
                text.digits(&d[..before]);
                if self.last >= before {
                    text.push(b'.');
                    for _ in 0..zeros {
                        text.push(b'0');
                    }
                    text.digits(&d[before..=self.last]);
                }
            }
        }
        text
    }
}

/// A number's text as it is made, on the stack.
struct Text {
    bytes: [u8; 40],
    len: usize,
}

impl Default for Text {
    fn default() -> Text {
        Text {
            bytes: [0; 40],
            len: 0,
        }
    }
}

impl Text {
    fn push(&mut self, b: u8) {
        self.bytes[self.len] = b;
        self.len += 1;
    }

    fn digits(&mut self, d: &[u8]) {
        for &k in d {
            self.push(b'0' + k);
        }
    }

    /// `n` in decimal, as `{n}` writes it.
    fn int(&mut self, n: i32) {
        if n < 0 {
            self.push(b'-');
        }
        let mut m = n.unsigned_abs();
        let mut digits = [0u8; 10];
        let mut k = digits.len();
        loop {
            k -= 1;
            digits[k] = (m % 10) as u8;
            m /= 10;
            if m == 0 {
                break;
            }
        }
        self.digits(&digits[k..]);
    }

    fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// `x` rounded to `places` + 1 significant digits from its shortest
/// digits: its sign, the digits and the decimal exponent of the first;
/// `None` at a tie (or where the shortest digits cannot be read).
///
/// NOTE: from the shortest digits that read back as `x` (serde_json's,
/// which JSON writes every number with), rounded as decimal digits: far
/// faster than the exact rounding, whose fallback to big integers was a
/// third of the time of `report --full` of a tree of 2²⁰ instances. They
/// round as `x` does unless they end in a tie, a `5` right after the
/// digits kept: x lies within half an ulp of them, and for a normal x and
/// up to 15 digits kept that is far less than a unit of the last digit;
/// a boundary of the rounding (a decimal of one digit more, ending in 5)
/// strictly between them and x would be a shorter or as short decimal
/// nearer x, which the shortest digits are not. A tie is rounded exactly
/// (Rust's `{:e}`, half to even on the exact value).
/// (`the_shortest_digits_rounded_are_the_rounding`.)
fn rounded(x: f64, places: usize) -> Option<(bool, [u8; 16], i32)> {
    let mut short = [0u8; 40];
    let mut w = &mut short[..];
    use serde_json::ser::Formatter as _;
    serde_json::ser::CompactFormatter
        .write_f64(&mut w, x)
        .ok()?;
    let len = 40 - w.len();
    let (neg, all, mut exp) = decimal(&short[..len])?;
    let kept = places + 1;
    let mut out = [0u8; 16];
    for (k, d) in out.iter_mut().enumerate().take(kept) {
        *d = all.get(k).copied().unwrap_or(0);
    }
    let up = match all.get(kept) {
        None => false,
        Some(&d) if d != 5 => d > 5,
        // A tie in the shortest digits: x is on either side of it.
        Some(_) if all.len() == kept + 1 => return None,
        Some(_) => true,
    };
    if up {
        let mut k = kept;
        loop {
            if k == 0 {
                // 9.99… rounded up: 1.00… times ten.
                out[0] = 1;
                exp += 1;
                break;
            }
            k -= 1;
            if out[k] == 9 {
                out[k] = 0;
            } else {
                out[k] += 1;
                break;
            }
        }
    }
    Some((neg, out, exp))
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
    fn push_sig_from_the_rounded_digits_is_push_sig_from_the_exact_rounding() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(20_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        let few = (any::<i32>(), -12i32..12, 0u32..4, -2i64..=2).prop_map(|(m, e, cut, step)| {
            let m = f64::from(m / 10i32.pow(cut));
            let x = m * 10f64.powi(e);
            f64::from_bits(x.to_bits().wrapping_add_signed(step))
        });
        let any_bits = any::<u64>().prop_map(f64::from_bits);
        let shares =
            (1u32..1_000_000, 1u32..5000).prop_map(|(a, b)| 100.0 * f64::from(a) / f64::from(b));
        runner
            .run(
                &(prop_oneof![few, any_bits, shares], 1usize..=15),
                |(x, digits)| {
                    if x.is_finite() {
                        let mut fast = String::from("≤");
                        let mut exact = String::from("≤");
                        super::super::push_sig(&mut fast, x, digits);
                        super::super::push_sig_exact(&mut exact, x, digits);
                        prop_assert_eq!(fast, exact, "{:e}, {} digits", x, digits);
                    }
                    Ok(())
                },
            )
            .unwrap();
    }

    /// Numbers of every kind a width is asked of: every bit pattern
    /// (subnormals, huge and tiny exponents, infinities, NaN); short
    /// decimals and dyadic fractions scaled by powers of ten and the
    /// doubles next to them (ties and near ties); shares; and the edges.
    fn any_number() -> impl proptest::strategy::Strategy<Value = f64> {
        use proptest::prelude::*;
        let few = (any::<i32>(), -30i32..30, 0u32..4, -2i64..=2).prop_map(|(m, e, cut, step)| {
            let m = f64::from(m / 10i32.pow(cut));
            let x = m * 10f64.powi(e);
            f64::from_bits(x.to_bits().wrapping_add_signed(step))
        });
        let dyadic = (any::<i32>(), -60i32..60).prop_map(|(m, e)| f64::from(m) * 2f64.powi(e));
        let any_bits = any::<u64>().prop_map(f64::from_bits);
        let subnormal = (1u64..(1 << 52), any::<bool>())
            .prop_map(|(m, neg)| f64::from_bits(m | (u64::from(neg) << 63)));
        let shares =
            (1u32..1_000_000, 1u32..5000).prop_map(|(a, b)| 100.0 * f64::from(a) / f64::from(b));
        let edges = prop::sample::select(vec![
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            999_999.5,
            99_999.95,
            0.000_099_999_95,
            1e-5,
            1e6,
        ]);
        prop_oneof![few, dyadic, any_bits, subnormal, shares, edges]
    }

    #[test]
    fn a_numbers_width_is_the_length_of_its_text() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(50_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        runner
            .run(&(any_number(), 1usize..=16), |(x, digits)| {
                let text = super::super::fmt_sig(x, digits);
                prop_assert_eq!(
                    super::super::sig_width(x, digits),
                    text.chars().count(),
                    "{:e} to {} digits: {:?}",
                    x,
                    digits,
                    text
                );
                Ok(())
            })
            .unwrap();
    }

    #[test]
    fn a_percentages_width_is_the_width_of_its_text() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        use unicode_width::UnicodeWidthStr;
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(20_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        let fraction = prop_oneof![
            9 => any_number().prop_map(Some),
            1 => Just(None),
        ];
        runner
            .run(&fraction, |f| {
                let text = super::super::fmt_percent(f);
                prop_assert_eq!(
                    super::super::percent_width(f),
                    text.width(),
                    "{:?}: {:?}",
                    f,
                    text
                );
                Ok(())
            })
            .unwrap();
    }

    #[test]
    fn the_shortest_digits_rounded_are_the_rounding() {
        use proptest::prelude::*;
        use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(20_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        // Every bit pattern; numbers of few digits (integers, halves,
        // short decimals, each scaled by a power of ten, and the doubles
        // next to them: ties and near ties of the rounding); and shares
        // as the tables show them (100 a / b, a percentage).
        let few = (any::<i32>(), -30i32..30, 0u32..4, -2i64..=2).prop_map(|(m, e, cut, step)| {
            let m = f64::from(m / 10i32.pow(cut));
            let x = m * 10f64.powi(e);
            f64::from_bits(x.to_bits().wrapping_add_signed(step))
        });
        let any_bits = any::<u64>().prop_map(f64::from_bits);
        let shares =
            (1u32..1_000_000, 1u32..5000).prop_map(|(a, b)| 100.0 * f64::from(a) / f64::from(b));
        runner
            .run(
                &(prop_oneof![few, any_bits, shares], 0usize..16),
                |(x, places)| {
                    if x.is_finite() {
                        same_as_exact(x, places);
                    }
                    Ok(())
                },
            )
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
