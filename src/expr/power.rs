//! Powers `a ^ b`: the exponent's dimension and the base's, and the
//! value. An integer exponent is used whole, never cut to i64: exact where
//! the result is a rational in i128, by squaring in double-double up to
//! `SQUARING_LIMIT`, else by magnitude exp(e·ln|x|) and parity (an
//! exponent known only in double-double has no known parity).

use super::{Dim, Error, Num, Q, Value, describe, fail};
use crate::numeric::{DD, Real};
use std::ops::Range;

/// `a ^ b`: b dimensionless; an integer power exact where it fits, a
/// rational one (`^(1/2)`) where a's dimension allows it, in floating
/// point.
pub(super) fn pow(a: Value, b: Value, at: Range<usize>) -> Result<Value, Error> {
    if b.dim != Dim::DIMENSIONLESS {
        return fail(
            at,
            format!(
                "an exponent must be a plain number, not {}",
                describe(b.dim)
            ),
        );
    }
    if a.num.is_zero() && b.num.is_zero() {
        return fail(at, "0^0 is undefined");
    }
    if a.num.is_zero() && b.num.negative() {
        return fail(at, "division by zero: 0 to a negative power");
    }
    // The exponent as p/q, if it is rational; an integer known only in
    // double-double apart (`Exponent::Huge`).
    // NOTE: past 2^53 every f64 is an even integer, so a double-double
    // value there (rounded somewhere: exact values are `Q`s) may be an
    // integer of either parity, or none; below it, it is the integer it
    // shows.
    let ratio = match b.num {
        Num::Exact(q) if q.pi == 0 => Some((q.n, q.d)),
        Num::Float(x) if is_integer(x) && x.hi.abs() < TWO_53 => Some((x.hi as i128, 1)),
        _ => None,
    };
    let scaled = |p: i128, q: i128| -> Result<Dim, Error> {
        let one = |e: i32| -> Option<i32> {
            let v = i128::from(e).checked_mul(p)?;
            (v % q == 0)
                .then(|| v / q)
                .filter(|v| v.unsigned_abs() <= 1 << 20)
                .map(|v| v as i32)
        };
        match (one(a.dim.mass), one(a.dim.length), one(a.dim.time)) {
            (Some(mass), Some(length), Some(time)) => Ok(Dim { mass, length, time }),
            _ => fail(
                at.clone(),
                format!("{} cannot be raised to this power", describe(a.dim)),
            ),
        }
    };
    match ratio {
        Some((p, 1)) => {
            let dim = scaled(p, 1)?;
            Ok(Value {
                dim,
                num: int_pow(a.num, Exponent::Int(p), &at)?,
                angle: a.angle,
            })
        }
        Some((p, q)) => {
            let dim = scaled(p, q)?;
            if a.num.negative() {
                return fail(at, "a negative number to a fractional power");
            }
            let num = match (a.num, q) {
                // x^(p/2) = (√x)^p: exact where √x is rational.
                (Num::Exact(x), 2) => match x.sqrt() {
                    Some(r) => int_pow(Num::Exact(r), Exponent::Int(p), &at)?,
                    None => int_pow(Num::Float(x.dd().sqrt()), Exponent::Int(p), &at)?,
                },
                (x, 2) => int_pow(Num::Float(x.dd().sqrt()), Exponent::Int(p), &at)?,
                (x, _) => Num::Float(DD::from(x.dd().f64().powf(p as f64 / q as f64))),
            };
            Ok(Value {
                dim,
                num,
                angle: a.angle,
            })
        }
        None if matches!(b.num, Num::Float(x) if is_integer(x)) => {
            // An integer exponent past 2^53, known only in double-double:
            // only a plain number can be raised to it (a unit's power
            // would pass 2^20 anyway).
            let Num::Float(e) = b.num else {
                unreachable!("invariant: matched above")
            };
            if a.dim != Dim::DIMENSIONLESS {
                return fail(
                    at,
                    format!("{} cannot be raised to this power", describe(a.dim)),
                );
            }
            Ok(Value {
                dim: a.dim,
                num: int_pow(a.num, Exponent::Huge(e), &at)?,
                angle: a.angle || b.angle,
            })
        }
        None => {
            if a.dim != Dim::DIMENSIONLESS {
                return fail(
                    at,
                    format!("{} can be raised only to a rational power", describe(a.dim)),
                );
            }
            if a.num.negative() {
                return fail(at, "a negative number to a fractional power");
            }
            let v = a.num.dd().f64().powf(b.num.dd().f64());
            Ok(Value {
                dim: a.dim,
                num: Num::Float(DD::from(v)),
                angle: a.angle || b.angle,
            })
        }
    }
}

/// 2^53: below it, an integer-valued f64 is that integer.
const TWO_53: f64 = 9_007_199_254_740_992.0;

/// Up to this exponent, a power is taken by squaring in double-double
/// (each squaring adds a rounding: about 2^-100 relative at this depth);
/// past it, by its magnitude `exp(e·ln|x|)`, whose one rounding does not
/// grow with the exponent.
const SQUARING_LIMIT: u128 = 1 << 12;

/// Whether a double-double value is a finite integer.
pub(super) fn is_integer(x: DD) -> bool {
    x.hi.is_finite() && x.lo.is_finite() && x.hi.fract() == 0.0 && x.lo.fract() == 0.0
}

/// An integer exponent: exact in i128, or past 2^53 and known only in
/// double-double (so its parity is not known).
#[derive(Clone, Copy, Debug)]
enum Exponent {
    Int(i128),
    Huge(DD),
}

/// `x^e`, e an integer (0 to a negative power is refused before): exact
/// where the result fits a rational in i128 (0, 1 and −1 to any power, by
/// parity); by squaring in double-double up to `SQUARING_LIMIT`; else by
/// magnitude and parity (`pow_by_magnitude`). Never by an exponent wrapped
/// or clamped to i64: a result past f64's range is ±inf or 0 here, which
/// the caller refuses at the `^`.
fn int_pow(x: Num, e: Exponent, at: &Range<usize>) -> Result<Num, Error> {
    if x.is_zero() {
        return Ok(Num::Exact(Q::ZERO));
    }
    if let (Num::Exact(q), Exponent::Int(p)) = (x, e) {
        if let Ok(k) = i64::try_from(p)
            && let Some(r) = q.powi(k)
        {
            return Ok(Num::Exact(r));
        }
        if q.pi == 0 && q.d == 1 && q.n.abs() == 1 {
            let odd = p & 1 == 1;
            return Ok(Num::Exact(if q.n < 0 && odd {
                Q::ONE.negated()
            } else {
                Q::ONE
            }));
        }
    }
    match e {
        Exponent::Int(p) if p.unsigned_abs() <= SQUARING_LIMIT => {
            Ok(Num::Float(powi_dd(x.dd(), p as i64)))
        }
        _ => pow_by_magnitude(x, e, at),
    }
}

/// `x^e` for a large integer e (x ≠ 0): |x|^e = exp(e·ln|x|), with ln|x|
/// = 2·atanh(u), u = (|x| − 1)/(|x| + 1), summed in double-double (u is
/// small wherever the result is within f64's range: |e| > 4096 needs
/// |ln|x|| < 0.25 there), and the sign by e's parity. A result past the
/// range is ±inf or 0 (refused by the caller); −x to a power whose parity
/// is not known (`Exponent::Huge`) and whose magnitude is in range is
/// refused.
fn pow_by_magnitude(x: Num, e: Exponent, at: &Range<usize>) -> Result<Num, Error> {
    let v = x.dd();
    let m = if v.hi < 0.0 { -v } else { v };
    let one = DD::from(1.0);
    // u exactly from an exact base: |n| − d has no rounding.
    let u = match x {
        Num::Exact(q) if q.pi == 0 => {
            let n = q.n.abs();
            DD::of_i128(n - q.d) / (DD::of_i128(n) + DD::of_i128(q.d))
        }
        _ => (m - one) / (m + one),
    };
    let e_dd = match e {
        Exponent::Int(p) => DD::of_i128(p),
        Exponent::Huge(h) => h,
    };
    // Far out of range either way: decided in f64 (the bound 1000 is well
    // past ln(f64::MAX) ≈ 709.8 and ln(2^-1074) ≈ −744.4).
    let estimate = e_dd.hi * m.hi.ln();
    let magnitude = if u.hi == 0.0 {
        one
    } else if estimate > 1000.0 {
        DD::from(f64::INFINITY)
    } else if estimate < -1000.0 {
        DD::from(0.0)
    } else {
        let l = e_dd * ln_by_atanh(u);
        let y = l.hi.exp();
        DD::from(y) + DD::from(y * l.lo)
    };
    let negative = x.negative();
    let odd = match e {
        Exponent::Int(p) => Some(p & 1 == 1),
        Exponent::Huge(_) => None,
    };
    let out_of_range = !magnitude.hi.is_finite() || magnitude.hi == 0.0;
    Ok(Num::Float(match (negative, odd) {
        (false, _) | (true, Some(false)) => magnitude,
        (true, Some(true)) => -magnitude,
        (true, None) if out_of_range => magnitude,
        (true, None) => {
            return fail(
                at.clone(),
                "a negative number to a power known only approximately (an integer past 2^53 that is not exact): whether it is even or odd is not known",
            );
        }
    }))
}

/// ln((1 + u)/(1 − u)) = 2·(u + u³/3 + u⁵/5 + …), in double-double, for
/// |u| < 1 (small where it is used: the terms fall by u² each).
fn ln_by_atanh(u: DD) -> DD {
    let u2 = u * u;
    let mut power = u;
    let mut sum = u;
    for k in 1..200 {
        power = power * u2;
        let term = power / DD::from(f64::from(2 * k + 1));
        sum += term;
        if term.hi.abs() <= sum.hi.abs() * 1e-34 {
            break;
        }
    }
    sum + sum
}

/// x^k by squaring in double-double (an overflow becomes inf, which the
/// caller refuses).
fn powi_dd(x: DD, k: i64) -> DD {
    let mut base = if k < 0 { DD::from(1.0) / x } else { x };
    let mut e = k.unsigned_abs();
    let mut out = DD::from(1.0);
    while e > 0 {
        if e & 1 == 1 {
            out = out * base;
        }
        e >>= 1;
        if e > 0 {
            base = base * base;
            if !base.hi.is_finite() || base.hi == 0.0 {
                // Past the range either way: the result is inf or 0 (or
                // NaN from inf·0, refused as an overflow too).
                out = out * base;
                break;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::Expr;

    fn eval(text: &str) -> Result<Value, Error> {
        Expr::parse(text)?.eval(&|_| None, &Vec::new)
    }

    #[test]
    fn minus_one_to_an_exponent_past_i64_goes_by_parity() {
        let at = 0..1;
        let minus_one = Num::Exact(Q::ONE.negated());
        for (p, want) in [(1i128 << 64, 1), ((1 << 64) + 1, -1), (i128::MAX, -1)] {
            assert_eq!(
                int_pow(minus_one, Exponent::Int(p), &at),
                Ok(Num::Exact(Q::new(want, 1, 0).unwrap())),
                "{p}"
            );
        }
    }

    #[test]
    fn a_negative_base_to_a_power_of_unknown_parity_in_range_is_refused() {
        let base = Num::Exact(Q::ONE.negated());
        let e = int_pow(base, Exponent::Huge(DD::from(2f64.powi(200))), &(3..4));
        assert_eq!(e.unwrap_err().at, 3..4);
        // Out of range, the sign does not matter: an overflow for the caller.
        let two = Num::Exact(Q::new(-2, 1, 0).unwrap());
        let v = int_pow(two, Exponent::Huge(DD::from(2f64.powi(200))), &(0..1)).unwrap();
        assert!(!v.dd().hi.is_finite());
    }

    #[test]
    fn ln_by_atanh_agrees_with_ln_1p() {
        for x in [1.0 + 1e-10, 0.75, 1.25, 1.0 - 2f64.powi(-40)] {
            let u = (DD::from(x) - DD::from(1.0)) / (DD::from(x) + DD::from(1.0));
            let got = ln_by_atanh(u);
            let want = (x - 1.0).ln_1p();
            assert!(
                (got.hi - want).abs() <= want.abs() * 4e-16,
                "{x}: {got:?} {want}"
            );
        }
    }

    #[test]
    fn a_large_power_by_magnitude_is_the_power_by_squaring() {
        // 1.001^5000 both ways: exp(5000 ln 1.001) and 5000 squarings-and-products.
        let x = Num::Exact(Q::new(1001, 1000, 0).unwrap());
        let by_magnitude = pow_by_magnitude(x, Exponent::Int(5000), &(0..1)).unwrap();
        let by_squaring = powi_dd(x.dd(), 5000);
        let (a, b) = (by_magnitude.dd().f64(), by_squaring.f64());
        assert!(a.to_bits().abs_diff(b.to_bits()) <= 2, "{a} {b}");
    }

    #[test]
    fn whole_values_are_whole_in_the_rationals() {
        assert!(eval("10 / 3 * 3").unwrap().is_whole());
        assert!(eval("2^130 / 2^128").unwrap().is_whole());
        assert!(!eval("(1 + 1e-20) * 3").unwrap().is_whole());
        assert!(!eval("pi / pi * 3 + pi - pi + 1/3").unwrap().is_whole());
    }

    #[test]
    fn trailing_zeros_keep_a_long_literal_exact() {
        let v = eval("3.000000000000000000000000000000000000000000").unwrap();
        assert_eq!(v.num, Num::Exact(Q::new(3, 1, 0).unwrap()));
        let v = eval("25000000000000000000000000000000000000000000e-43").unwrap();
        assert_eq!(v.num, Num::Exact(Q::new(5, 2, 0).unwrap()));
    }

    #[test]
    fn a_subnormal_step_is_an_underflow_at_its_operator() {
        let e = eval("1e-160 * 1e-160 * 1e300").unwrap_err();
        assert_eq!(e.at, 7..8);
        assert!(e.message.contains("underflows"));
    }
}
