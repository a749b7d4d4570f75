//! The exact value of an expression whose rationals outgrow i128
//! (issue 30): `n / d · π^pi` in big integers, so that a rational value is
//! rounded to f64 once, to the nearest, however many digits its fractions
//! took on the way (a product of a few parameters written as f64, a
//! length in inches in a file in feet). `Expr::eval` goes on in
//! double-double where `exact::Q` overflows, and its rounding of the
//! result can miss the nearest f64 by an ulp where the exact value lies
//! within double-double's error of a midpoint; this evaluation decides it.
//!
//! Only what is rational is here: anything else (`sin`, a square root that
//! is not a square, a fractional power, different powers of π added) gives
//! `None`, and the double-double value stands. So does a number past
//! [`MAX_BITS`], which keeps the work bounded whatever the input.

use super::exact::Q as Small;
use num_bigint::{BigInt, Sign};
use std::cmp::Ordering;

/// The most bits a numerator or denominator may take (else `None`):
/// 16,384, far beyond f64's range for anything that rounds to a finite
/// value, and a few microseconds a product.
pub const MAX_BITS: u64 = 1 << 14;

/// `n / d · π^pi`, reduced, `d > 0`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Big {
    n: BigInt,
    d: BigInt,
    pi: i32,
}

fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut a, mut b) = (a.magnitude().clone(), b.magnitude().clone());
    while b != num_bigint::BigUint::ZERO {
        let r = &a % &b;
        a = b;
        b = r;
    }
    BigInt::from(a)
}

impl Big {
    /// `n / d · π^pi` reduced; `None` for a zero denominator or past
    /// [`MAX_BITS`].
    pub fn new(n: BigInt, d: BigInt, pi: i32) -> Option<Big> {
        if d.sign() == Sign::NoSign {
            return None;
        }
        let g = gcd(&n, &d);
        let (mut n, mut d) = (n / &g, d / &g);
        if d.sign() == Sign::Minus {
            (n, d) = (-n, -d);
        }
        if n.bits() > MAX_BITS || d.bits() > MAX_BITS {
            return None;
        }
        let pi = if n.sign() == Sign::NoSign { 0 } else { pi };
        Some(Big { n, d, pi })
    }

    pub fn of(q: Small) -> Big {
        Big {
            n: BigInt::from(q.n),
            d: BigInt::from(q.d),
            pi: q.pi,
        }
    }

    /// A finite f64, exactly.
    pub fn of_f64(x: f64) -> Option<Big> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Big::zero());
        }
        let bits = x.abs().to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i32;
        let (m, e) = if exp == 0 {
            (bits & ((1 << 52) - 1), -1074)
        } else {
            ((bits & ((1 << 52) - 1)) | (1 << 52), exp - 1075)
        };
        let m = BigInt::from(m) * if x < 0.0 { -1 } else { 1 };
        if e >= 0 {
            Big::new(m << e as usize, BigInt::from(1), 0)
        } else {
            Big::new(m, BigInt::from(1) << (-e) as usize, 0)
        }
    }

    /// A decimal numeral (digits, `_`, one `.`, an exponent), exactly.
    pub fn decimal(text: &str) -> Option<Big> {
        let clean: String = text.chars().filter(|c| *c != '_').collect();
        let (mantissa, exp) = match clean.find(['e', 'E']) {
            Some(k) => (&clean[..k], clean[k + 1..].parse::<i64>().ok()?),
            None => (clean.as_str(), 0),
        };
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits = format!("{int}{frac}");
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let n: BigInt = digits.parse().ok()?;
        let scale = exp.checked_sub(frac.len() as i64)?;
        // 10^k has 3.33 k bits.
        if scale.unsigned_abs() > MAX_BITS / 3 {
            return None;
        }
        let p = BigInt::from(10).pow(scale.unsigned_abs() as u32);
        if scale >= 0 {
            Big::new(n * p, BigInt::from(1), 0)
        } else {
            Big::new(n, p, 0)
        }
    }

    pub fn zero() -> Big {
        Big {
            n: BigInt::ZERO,
            d: BigInt::from(1),
            pi: 0,
        }
    }

    pub fn is_zero(&self) -> bool {
        self.n.sign() == Sign::NoSign
    }

    pub fn negated(self) -> Big {
        Big { n: -self.n, ..self }
    }

    pub fn abs(self) -> Big {
        Big {
            n: BigInt::from(self.n.magnitude().clone()),
            ..self
        }
    }

    pub fn plus(&self, o: &Big) -> Option<Big> {
        if o.is_zero() {
            return Some(self.clone());
        }
        if self.is_zero() {
            return Some(o.clone());
        }
        if self.pi != o.pi {
            return None;
        }
        Big::new(&self.n * &o.d + &o.n * &self.d, &self.d * &o.d, self.pi)
    }

    pub fn times(&self, o: &Big) -> Option<Big> {
        Big::new(&self.n * &o.n, &self.d * &o.d, self.pi.checked_add(o.pi)?)
    }

    pub fn over(&self, o: &Big) -> Option<Big> {
        if o.is_zero() {
            return None;
        }
        Big::new(&self.n * &o.d, &self.d * &o.n, self.pi.checked_sub(o.pi)?)
    }

    /// `self^k` for an integer k (`None` past [`MAX_BITS`], or 0^k for
    /// k ≤ 0).
    pub fn powi(&self, k: &Big) -> Option<Big> {
        if k.pi != 0 || k.d != BigInt::from(1) {
            return None;
        }
        // ±1 to any power (`(-1)^(2^64)`): its parity decides.
        if self.d == BigInt::from(1)
            && self.pi == 0
            && self.n.magnitude() == &num_bigint::BigUint::from(1u8)
        {
            let odd = k.n.bit(0);
            let n = if self.n.sign() == Sign::Minus && odd {
                -1
            } else {
                1
            };
            return Some(Big::of(Small { n, d: 1, pi: 0 }));
        }
        let e: i64 = i64::try_from(&k.n).ok()?;
        if self.is_zero() {
            return (e > 0).then(Big::zero);
        }
        let bits = self.n.bits().max(self.d.bits()).max(1);
        if e.unsigned_abs().checked_mul(bits)? > MAX_BITS {
            return None;
        }
        let base = if e < 0 {
            Big::new(self.d.clone(), self.n.clone(), -self.pi)?
        } else {
            self.clone()
        };
        let m = e.unsigned_abs();
        let m32 = u32::try_from(m).ok()?;
        Big::new(
            base.n.pow(m32),
            base.d.pow(m32),
            base.pi.checked_mul(i32::try_from(m).ok()?)?,
        )
    }

    /// The square root, if it is rational (and π to an even power).
    pub fn sqrt(&self) -> Option<Big> {
        if self.n.sign() == Sign::Minus || self.pi % 2 != 0 {
            return None;
        }
        let (a, b) = (self.n.sqrt(), self.d.sqrt());
        if &a * &a == self.n && &b * &b == self.d {
            Some(Big {
                n: a,
                d: b,
                pi: self.pi / 2,
            })
        } else {
            None
        }
    }

    /// Compare, where both are of one power of π (or zero).
    pub fn compare(&self, o: &Big) -> Option<Ordering> {
        if self.pi != o.pi && !self.is_zero() && !o.is_zero() {
            return None;
        }
        Some((&self.n * &o.d).cmp(&(&o.n * &self.d)))
    }

    /// The value over the factor `num / den · π^pi`, rounded once to the
    /// nearest f64 (ties to even); `None` where π does not cancel.
    pub fn nearest_over(&self, num: i128, den: i128, pi: i32) -> Option<f64> {
        if self.is_zero() {
            return Some(0.0);
        }
        if self.pi != pi {
            return None;
        }
        Some(nearest(
            &(&self.n * BigInt::from(den)),
            &(&self.d * BigInt::from(num)),
        ))
    }
}

/// n / d to the nearest f64, ties to even (d ≠ 0): 66 quotient bits by one
/// big division, the rest a sticky bit, then the one rounding.
fn nearest(n: &BigInt, d: &BigInt) -> f64 {
    let negative = (n.sign() == Sign::Minus) != (d.sign() == Sign::Minus);
    let (n, d) = (n.magnitude(), d.magnitude());
    // q = n·2^s / d has 66 or 67 bits.
    let s = 66 + d.bits() as i64 - n.bits() as i64;
    let (a, b) = if s >= 0 {
        (n << s as usize, d.clone())
    } else {
        (n.clone(), d << (-s) as usize)
    };
    let (q, r) = (&a / &b, &a % &b);
    let sticky = r != num_bigint::BigUint::ZERO;
    let q: u128 = u128::try_from(&q).expect("invariant: 66 or 67 bits");
    let v = round_scaled(q, sticky, -s);
    if negative { -v } else { v }
}

/// q·2^e, q ≥ 2⁶⁵, with `sticky` for a non-zero rest below q's last bit,
/// rounded to the nearest f64 (ties to even), subnormals and overflow too.
fn round_scaled(q: u128, sticky: bool, e: i64) -> f64 {
    let len = 128 - i64::from(q.leading_zeros());
    // Keep 53 bits, fewer below the normal range.
    let shift = (len - 53).max(-1074 - e);
    if shift > len {
        return 0.0;
    }
    let (kept, rest) = if shift >= 128 {
        (0, q)
    } else {
        (q >> shift, q & ((1u128 << shift) - 1))
    };
    let half = 1u128 << (shift - 1);
    let up = rest > half || (rest == half && (sticky || kept & 1 == 1));
    let m = kept + u128::from(up);
    let mut x = m as f64;
    let mut k = e + shift;
    // x·2^k in steps that stay exact until the last.
    while k > 0 {
        let step = k.min(1000);
        x *= 2f64.powi(step as i32);
        k -= step;
    }
    while k < 0 {
        let step = (-k).min(1000);
        x /= 2f64.powi(step as i32);
        k += step;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Big {
        Big::new(BigInt::from(n), BigInt::from(d), 0).unwrap()
    }

    #[test]
    fn a_third_rounds_as_f64_division_does() {
        assert_eq!(q(1, 3).nearest_over(1, 1, 0), Some(1.0 / 3.0));
        assert_eq!(q(-7, 10).nearest_over(1, 1000, 0), Some(-700.0));
    }

    #[test]
    fn a_tie_rounds_to_even_and_just_above_it_rounds_up() {
        let tie = Big::new((BigInt::from(1) << 53usize) + 1, BigInt::from(1), 0).unwrap();
        assert_eq!(tie.nearest_over(1, 1, 0), Some(9007199254740992.0));
        let above = Big::new(
            (BigInt::from(1) << 200usize) + (BigInt::from(1) << 147usize) + 1,
            BigInt::from(1) << 147usize,
            0,
        )
        .unwrap();
        assert_eq!(above.nearest_over(1, 1, 0), Some(9007199254740994.0));
    }

    #[test]
    fn subnormals_and_the_top_of_the_range_round_once() {
        let tiny = Big::new(BigInt::from(3), BigInt::from(1) << 1076usize, 0).unwrap();
        assert_eq!(tiny.nearest_over(1, 1, 0), Some(f64::from_bits(1)));
        let max = Big::of_f64(f64::MAX).unwrap();
        assert_eq!(max.nearest_over(1, 1, 0), Some(f64::MAX));
    }

    #[test]
    fn a_decimal_and_an_f64_are_read_exactly() {
        assert_eq!(Big::decimal("0.1"), Some(q(1, 10)));
        assert_eq!(Big::decimal("1_000e-3"), Some(q(1, 1)));
        assert_eq!(Big::of_f64(0.5), Some(q(1, 2)));
    }

    /// `1 + 2^-53 + 2^-160`: i128 holds 2⁻⁵³ but not 2⁻¹⁶⁰, so the sum
    /// goes on in double-double, whose low part cannot hold 2⁻⁵³ + 2⁻¹⁶⁰:
    /// it keeps the tie 1 + 2⁻⁵³, which rounds to even, 1. The exact value
    /// is above the tie: its nearest f64 is 1 + 2⁻⁵².
    #[test]
    fn a_value_just_above_a_tie_rounds_up_where_double_double_rounds_down() {
        use crate::units::Factor;
        let e = crate::expr::Expr::parse("1 + 2^-53 + 2^-160").unwrap();
        let v = e.eval(&|_| None, &Vec::new).unwrap();
        assert_eq!(v.in_units(Factor::ONE), 1.0, "double-double's rounding");
        let exact = e.exact(&|_| None).unwrap();
        assert_eq!(exact.nearest_over(1, 1, 0), Some(1.0 + f64::EPSILON));
    }

    /// The same below a tie, in a unit: `(1 - 2^-54 - 2^-170) * 1 in` read
    /// in inches is just below 1 − 2⁻⁵⁴, so 1 − 2⁻⁵³.
    #[test]
    fn a_value_just_below_a_tie_in_inches_rounds_down() {
        let e = crate::expr::Expr::parse("(1 - 2^-54 - 2^-170) * 1 in").unwrap();
        let exact = e.exact(&|_| None).unwrap();
        assert_eq!(
            exact.nearest_over(254, 10_000, 0),
            Some(1.0 - f64::EPSILON / 2.0)
        );
    }

    #[test]
    fn what_is_not_rational_has_no_exact_value() {
        for t in ["sin(1)", "sqrt(2)", "pi + 1", "2^(1/3)"] {
            let e = crate::expr::Expr::parse(t).unwrap();
            assert_eq!(e.exact(&|_| None), None, "{t}");
        }
        let e = crate::expr::Expr::parse("sqrt(9/4) * pi").unwrap();
        assert!(e.exact(&|_| None).is_some());
    }

    #[test]
    fn powers_of_one_and_minus_one_stay_small_and_others_are_capped() {
        let big = Big::decimal("100000000000000000000").unwrap();
        assert_eq!(q(-1, 1).powi(&big), Some(q(1, 1)));
        assert_eq!(q(3, 1).powi(&big), None);
        assert_eq!(q(2, 3).powi(&q(-2, 1)), Some(q(9, 4)));
    }
}
