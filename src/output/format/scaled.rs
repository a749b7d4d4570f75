//! A number rounded to a few significant digits by integer arithmetic on
//! its bits: `x · 10ᵏ` formed exactly as an integer and a remainder, so the
//! rounding (a tie too) is decided on the exact value, as `{:.N$e}`
//! decides it, without the shortest digits or the exact formatting's big
//! integers.
//!
//! NOTE: the `--full` table of a tree of 2²⁰ instances formats 17 million
//! numbers, twice (its columns are measured, then written): from the
//! shortest digits (`rounded`) each cost a float-to-text conversion and
//! the parsing of its text back, a third of the table's time.

/// 5ᵏ for k = 0..=22 (5²² < 2⁵³): with 2ᵏ, the powers of ten a double's
/// significand is scaled by.
const FIVE: [u64; 23] = {
    let mut t = [1u64; 23];
    let mut k = 1;
    while k < 23 {
        t[k] = t[k - 1] * 5;
        k += 1;
    }
    t
};

/// 10ᵏ for k = 0..=16.
pub(super) const TEN: [u64; 17] = {
    let mut t = [1u64; 17];
    let mut k = 1;
    while k < 17 {
        t[k] = t[k - 1] * 10;
        k += 1;
    }
    t
};

/// `x` rounded to `places` + 1 significant digits as `{x:.places$e}`
/// rounds it (to nearest, a tie to the even digit, on the exact value):
/// its sign, the digits as one integer of `places` + 1 digits, and the
/// decimal exponent of the first. `None` where the scale is out of this
/// arithmetic's reach (then the caller's slower path): `x` not normal,
/// more than 15 digits, or `x` so far from 1 that the scale 10ᵏ is past
/// 10²² (for six digits, |x| under 1e-17 or past 1e27).
pub(super) fn scaled(x: f64, places: usize) -> Option<(bool, u64, i32)> {
    if places > 14 || !x.is_normal() {
        return None;
    }
    let bits = x.to_bits();
    let neg = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    // |x| = m · 2^e2 exactly, and 2^b ≤ |x| < 2^(b+1).
    let m = (bits & ((1 << 52) - 1)) | (1 << 52);
    let e2 = biased - 1075;
    let b = biased - 1023;
    let low = TEN[places];
    let high = TEN[places + 1];
    // floor(b · log10 2), within one of the exponent of |x|'s first digit
    // (78913 / 2¹⁸ ≈ log10 2); corrected below on the exact value.
    // (Kept where 10ᵏ is in the tables: a number at the edge of the reach
    // whose estimate is one short is still answered.)
    let reach = places as i32 - 22..=places as i32 + 22;
    let mut e10 = ((b * 78913) >> 18).clamp(*reach.start(), *reach.end());
    for _ in 0..3 {
        let k = places as i32 - e10;
        let (q, frac) = match nearly(x.abs(), k) {
            Some(r) => r,
            None => scale(m, e2, k)?,
        };
        if q >= high {
            e10 += 1;
            continue;
        }
        if q < low {
            e10 -= 1;
            continue;
        }
        let up = match frac {
            Half::Below => false,
            Half::Above => true,
            // NOTE: a tie on the exact value rounds to the even digit, as
            // Rust's exact formatting does (held to it by the tests).
            Half::Exactly => q % 2 == 1,
        };
        let n = q + u64::from(up);
        return Some(if n == high {
            (neg, low, e10 + 1)
        } else {
            (neg, n, e10)
        });
    }
    None
}

/// 10ᵏ for k = 0..=22, each exactly a double.
const TEN_F64: [f64; 23] = {
    let mut t = [1.0f64; 23];
    let mut k = 1;
    while k < 23 {
        t[k] = t[k - 1] * 10.0;
        k += 1;
    }
    t
};

/// `a · 10ᵏ`'s integer part and where its fraction lies, from the product
/// (or quotient) rounded once to a double, where that decides: `None`
/// where its fraction is within the rounding's error of one half (then
/// `scale`, exact), or the product is past 2⁴⁰.
///
/// NOTE: 10ᵏ is exact (k ≤ 22), so `y` is within half an ulp, 2⁻⁵³ y, of
/// v = a · 10ᵏ, and `y`'s fraction (under 2⁴⁰) is exact; a fraction
/// farther than 2⁻⁵² y from ½ is on the same side of it as v's. Near an
/// integer the integer part may be v's ± 1 (v just under an integer that
/// `y` reached, or the reverse), with the fraction on the other side of
/// ½: its rounding, q + up, is the same integer, and `scaled`'s answer
/// too — at its decade's ends as well (q = 10ᵖ or 10ᵖ⁺¹ − 1 with v on the
/// far side: a retry in the next decade rounds to the same 10ᵖ, held by
/// the tests). Almost every number a table shows is decided here, in a
/// multiplication and a comparison.
fn nearly(a: f64, k: i32) -> Option<(u64, Half)> {
    let ten = *TEN_F64.get(k.unsigned_abs() as usize)?;
    let y = if k >= 0 { a * ten } else { a / ten };
    if !(y < (1u64 << 40) as f64) {
        return None;
    }
    // (Truncated: y ≥ 0; a conversion, not libm's `floor`.)
    let q = y as u64;
    let f = y - q as f64;
    let err = y * f64::EPSILON;
    if (f - 0.5).abs() <= err {
        return None;
    }
    Some((q, if f < 0.5 { Half::Below } else { Half::Above }))
}

/// Where a fraction lies against one half.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Half {
    Below,
    Exactly,
    Above,
}

/// `m · 2^e2 · 10ᵏ` as its integer part and where its fraction lies;
/// `None` beyond the tables or 128 bits.
fn scale(m: u64, e2: i32, k: i32) -> Option<(u64, Half)> {
    let half = |r: u128, unit: u128| match (2 * r).cmp(&unit) {
        std::cmp::Ordering::Less => Half::Below,
        std::cmp::Ordering::Equal => Half::Exactly,
        std::cmp::Ordering::Greater => Half::Above,
    };
    let five = u128::from(*FIVE.get(k.unsigned_abs() as usize)?);
    let (q, frac) = if k >= 0 {
        // m · 5ᵏ · 2^(e2 + k): under 2¹⁰⁶.
        let big = u128::from(m) * five;
        let t = e2 + k;
        if t >= 0 {
            if t > 20 {
                return None;
            }
            (big << t, Half::Below)
        } else {
            let s = t.unsigned_abs();
            if s >= 127 {
                return None;
            }
            let r = big & ((1u128 << s) - 1);
            (big >> s, half(r, 1u128 << s))
        }
    } else {
        // m · 2^(e2 + k) / 5^|k|.
        let t = e2 + k;
        if t >= 0 {
            if t > 70 {
                return None;
            }
            let big = u128::from(m) << t;
            (big / five, half(big % five, five))
        } else {
            let s = t.unsigned_abs();
            if s > 70 {
                return None;
            }
            let unit = five << s;
            let big = u128::from(m);
            (big / unit, half(big % unit, unit))
        }
    };
    Some((u64::try_from(q).ok()?, frac))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

    /// `scaled`'s digits as `{:e}` writes them, where it answers.
    fn as_sci(x: f64, places: usize) -> Option<String> {
        let (neg, n, exp) = scaled(x, places)?;
        let digits = n.to_string();
        assert_eq!(digits.len(), places + 1, "{x:e}: {n} has the digits asked");
        let (first, rest) = digits.split_at(1);
        let point = if places > 0 { "." } else { "" };
        let sign = if neg { "-" } else { "" };
        Some(format!("{sign}{first}{point}{rest}e{exp}"))
    }

    fn same_as_exact(x: f64, places: usize) {
        if let Some(ours) = as_sci(x, places) {
            assert_eq!(ours, format!("{x:.places$e}"), "{x:e}, {places} places");
        }
    }

    #[test]
    fn the_integer_rounding_is_the_exact_rounding() {
        let mut runner = TestRunner::new_with_rng(
            Config::with_cases(50_000),
            TestRng::deterministic_rng(RngAlgorithm::ChaCha),
        );
        // Short decimals and dyadic fractions (exact ties of the rounding)
        // scaled by powers of ten, and the doubles next to them; every bit
        // pattern; shares as the tables show them.
        let few = (any::<i32>(), -25i32..25, 0u32..4, -2i64..=2).prop_map(|(m, e, cut, step)| {
            let m = f64::from(m / 10i32.pow(cut));
            let x = m * 10f64.powi(e);
            f64::from_bits(x.to_bits().wrapping_add_signed(step))
        });
        let dyadic = (any::<i32>(), -40i32..40).prop_map(|(m, e)| f64::from(m) * 2f64.powi(e));
        let any_bits = any::<u64>().prop_map(f64::from_bits);
        let shares =
            (1u32..1_000_000, 1u32..5000).prop_map(|(a, b)| 100.0 * f64::from(a) / f64::from(b));
        let answered = std::cell::Cell::new(0);
        runner
            .run(
                &(prop_oneof![few, dyadic, any_bits, shares], 0usize..16),
                |(x, places)| {
                    if x.is_finite() {
                        same_as_exact(x, places);
                        answered.set(answered.get() + usize::from(scaled(x, places).is_some()));
                    }
                    Ok(())
                },
            )
            .unwrap();
        // Most numbers but the random bit patterns (mostly far from 1) are
        // answered here, not passed on.
        assert!(answered.get() > 25_000, "{} answered", answered.get());
    }

    #[test]
    fn exact_ties_round_to_the_even_digit_as_the_exact_formatting_does() {
        for (x, places) in [(0.125, 1), (0.375, 1), (2.5, 0), (3.5, 0), (31.25, 2)] {
            assert!(scaled(x, places).is_some(), "{x} is within reach");
            same_as_exact(x, places);
        }
        for k in 0..5000u32 {
            let x = f64::from(k) + 0.5;
            let places = x.log10().floor() as usize;
            same_as_exact(x, places);
            same_as_exact(x / 1024.0, places);
        }
    }

    #[test]
    fn a_carry_past_the_last_nine_moves_the_exponent() {
        assert_eq!(scaled(999_999.5, 5), Some((false, 100_000, 6)));
        assert_eq!(scaled(-9.999_995_1, 5), Some((true, 100_000, 1)));
        same_as_exact(0.099_999_96, 5);
    }

    #[test]
    fn the_edges_of_the_reach_answer_exactly_or_not_at_all() {
        for x in [
            1e-17,
            1.5e-17,
            9.99e-18,
            1e22,
            9.99e21,
            1e23,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            0.0,
            -0.0,
        ] {
            for places in 0..16 {
                same_as_exact(x, places);
                same_as_exact(-x, places);
            }
        }
        // Within the reach: the numbers a table shows.
        for x in [1e-17, 0.000_123, 1.0, 123_456.7, 1e21] {
            assert!(scaled(x, 5).is_some(), "{x:e}");
        }
        assert_eq!(scaled(0.0, 5), None);
        assert_eq!(scaled(5e-324, 5), None);
    }
}
