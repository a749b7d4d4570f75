//! `Exact`: a number that is an exact rational over i128 while it can be,
//! beside its f64 value: the arithmetic `explain` evaluates the shapes'
//! own closed forms in (`numeric::Real`), so each step is shown exactly
//! where every input is a decimal. An input is the decimal its f64 prints
//! as (shortest round trip: the file's `0.1` is 1/10); π, a square root
//! that is not a rational's, an angle off a quarter turn and an overflow
//! of i128 leave the exact value behind (`exact` is then `None`) and the
//! f64 goes on.

// NOTE: a rational's sum and product divide by common factors: the
// arithmetic is the operation's, not a slip of one operator for another.
#![allow(clippy::suspicious_arithmetic_impl)]

use crate::numeric::{DD, Real};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational num/den (den > 0, lowest terms), if known, and its
/// value in f64.
#[derive(Clone, Copy, Debug)]
pub struct Exact {
    pub exact: Option<(i128, i128)>,
    pub approx: f64,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// num/den in lowest terms with den > 0; `None` for den 0 or an overflow.
fn reduced(num: i128, den: i128) -> Option<(i128, i128)> {
    if den == 0 {
        return None;
    }
    let g = gcd(num, den).max(1);
    let (n, d) = (num / g, den / g);
    if d < 0 {
        Some((n.checked_neg()?, d.checked_neg()?))
    } else {
        Some((n, d))
    }
}

/// The nearest f64 to num/den (one division of two f64s: each rounded once
/// when they exceed 2⁵³, close enough for a value shown beside the exact).
fn ratio_f64(num: i128, den: i128) -> f64 {
    if num.unsigned_abs() < (1 << 53) && den.unsigned_abs() < (1 << 53) {
        num as f64 / den as f64
    } else {
        let (q, r) = (num / den, num % den);
        q as f64 + r as f64 / den as f64
    }
}

/// The exact decimal an f64 prints as (its shortest round-trip form), as a
/// rational; `None` if it is not finite or outgrows i128.
pub fn decimal_of(x: f64) -> Option<(i128, i128)> {
    if !x.is_finite() {
        return None;
    }
    let s = format!("{x:e}");
    let (mantissa, exponent) = s.split_once('e')?;
    let exponent: i32 = exponent.parse().ok()?;
    let negative = mantissa.starts_with('-');
    let mantissa = mantissa.trim_start_matches('-');
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: i128 = format!("{int}{frac}").parse().ok()?;
    let shift = exponent - frac.len() as i32;
    let ten = |n: u32| 10i128.checked_pow(n);
    let (num, den) = if shift >= 0 {
        (digits.checked_mul(ten(shift as u32)?)?, 1)
    } else {
        (digits, ten(shift.unsigned_abs())?)
    };
    reduced(if negative { -num } else { num }, den)
}

impl Exact {
    /// An exact rational.
    pub fn ratio(num: i128, den: i128) -> Exact {
        match reduced(num, den) {
            Some((n, d)) => Exact {
                exact: Some((n, d)),
                approx: ratio_f64(n, d),
            },
            None => Exact::inexact(num as f64 / den as f64),
        }
    }

    /// A value known only in f64.
    pub fn inexact(x: f64) -> Exact {
        Exact {
            exact: None,
            approx: x,
        }
    }

    fn from_parts(exact: Option<(i128, i128)>, approx: f64) -> Exact {
        match exact {
            Some((n, d)) => Exact {
                exact: Some((n, d)),
                approx: ratio_f64(n, d),
            },
            None => Exact::inexact(approx),
        }
    }

    /// Whether it is exactly zero.
    pub fn is_zero(self) -> bool {
        match self.exact {
            Some((n, _)) => n == 0,
            None => self.approx == 0.0,
        }
    }
}

impl PartialEq for Exact {
    fn eq(&self, o: &Exact) -> bool {
        self.partial_cmp(o) == Some(Ordering::Equal)
    }
}

impl PartialOrd for Exact {
    fn partial_cmp(&self, o: &Exact) -> Option<Ordering> {
        if let (Some((a, b)), Some((c, d))) = (self.exact, o.exact)
            && let (Some(l), Some(r)) = (a.checked_mul(d), c.checked_mul(b))
        {
            return Some(l.cmp(&r));
        }
        self.approx.partial_cmp(&o.approx)
    }
}

impl Add for Exact {
    type Output = Exact;
    fn add(self, o: Exact) -> Exact {
        let exact = self.exact.zip(o.exact).and_then(|((a, b), (c, d))| {
            let g = gcd(b, d).max(1);
            let (bg, dg) = (b / g, d / g);
            reduced(
                a.checked_mul(dg)?.checked_add(c.checked_mul(bg)?)?,
                b.checked_mul(dg)?,
            )
        });
        Exact::from_parts(exact, self.approx + o.approx)
    }
}

impl Neg for Exact {
    type Output = Exact;
    fn neg(self) -> Exact {
        let exact = self.exact.and_then(|(a, b)| Some((a.checked_neg()?, b)));
        Exact::from_parts(exact, -self.approx)
    }
}

impl Sub for Exact {
    type Output = Exact;
    fn sub(self, o: Exact) -> Exact {
        self + (-o)
    }
}

impl Mul for Exact {
    type Output = Exact;
    fn mul(self, o: Exact) -> Exact {
        let exact = self.exact.zip(o.exact).and_then(|((a, b), (c, d))| {
            // Cross-reduced first, so that the products stay small.
            let (g1, g2) = (gcd(a, d).max(1), gcd(c, b).max(1));
            reduced((a / g1).checked_mul(c / g2)?, (b / g2).checked_mul(d / g1)?)
        });
        Exact::from_parts(exact, self.approx * o.approx)
    }
}

impl Div for Exact {
    type Output = Exact;
    fn div(self, o: Exact) -> Exact {
        let inverse = o.exact.and_then(|(c, d)| reduced(d, c));
        let exact = self.exact.zip(inverse).and_then(|(x, y)| {
            (Exact::from_parts(Some(x), 0.0) * Exact::from_parts(Some(y), 0.0)).exact
        });
        Exact::from_parts(exact, self.approx / o.approx)
    }
}

/// The integer square root of n ≥ 0, if n is a perfect square.
fn exact_sqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    let mut r = (n as f64).sqrt() as i128;
    while r > 0 && r.checked_mul(r).is_none_or(|s| s > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|s| s <= n) {
        r += 1;
    }
    (r * r == n).then_some(r)
}

impl Real for Exact {
    const EPS: f64 = f64::EPSILON / 2.0;

    /// The decimal `x` prints as, exactly.
    fn of(x: f64) -> Exact {
        Exact::from_parts(decimal_of(x), x)
    }

    fn f64(self) -> f64 {
        self.approx
    }

    fn sqrt(self) -> Exact {
        let exact = self
            .exact
            .and_then(|(n, d)| Some((exact_sqrt(n)?, exact_sqrt(d)?)));
        Exact::from_parts(exact, self.approx.sqrt())
    }

    fn sin_cos_deg(deg: f64) -> (Exact, Exact) {
        let (s, c) = f64::sin_cos_deg(deg);
        // Exact at multiples of 90° (f64's are then 0 and ±1 exactly).
        if deg % 90.0 == 0.0 {
            (Exact::of(s), Exact::of(c))
        } else {
            (Exact::inexact(s), Exact::inexact(c))
        }
    }

    fn pi() -> Exact {
        Exact::inexact(std::f64::consts::PI)
    }

    fn of_dd(x: DD) -> Exact {
        Exact::inexact(x.f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_decimal_is_read_as_written() {
        assert_eq!(decimal_of(0.1), Some((1, 10)));
        assert_eq!(decimal_of(7e-5), Some((7, 100_000)));
        assert_eq!(decimal_of(-125.0), Some((-125, 1)));
        assert_eq!(decimal_of(1e300), None);
        assert_eq!(decimal_of(f64::NAN), None);
    }

    #[test]
    fn a_perfect_square_keeps_its_root_exact_and_two_does_not() {
        assert_eq!(Exact::ratio(9, 4).sqrt().exact, Some((3, 2)));
        assert_eq!(Exact::of(2.0).sqrt().exact, None);
        assert_eq!(Exact::pi().exact, None);
    }

    #[test]
    fn an_overflow_leaves_the_exact_value_and_keeps_the_f64() {
        let big = Exact::ratio(i128::MAX / 2, 1);
        let x = big * big;
        assert_eq!(x.exact, None);
        assert!(x.approx > 1e75);
    }
}
