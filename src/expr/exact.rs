//! Exact rationals for expressions: `n / d · π^pi` in i128, every
//! operation checked (`None` when a result outgrows i128, and the caller
//! goes on in double-double), and the one rounding to f64 at the end,
//! correct to the last bit.

use crate::numeric::DD;

/// `n / d · π^pi`, reduced, `d > 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Q {
    pub n: i128,
    pub d: i128,
    pub pi: i32,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    // On magnitudes: i128::MIN has no i128 absolute value, so the callers
    // never hand it here (`new` refuses it).
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

impl Q {
    pub const ZERO: Q = Q { n: 0, d: 1, pi: 0 };
    pub const ONE: Q = Q { n: 1, d: 1, pi: 0 };

    /// `n / d · π^pi` reduced; `None` for a zero denominator or a value
    /// at i128's edge (`i128::MIN` has no negation).
    pub fn new(n: i128, d: i128, pi: i32) -> Option<Q> {
        if d == 0 || n == i128::MIN || d == i128::MIN {
            return None;
        }
        let g = gcd(n, d);
        let (mut n, mut d) = (n / g, d / g);
        if d < 0 {
            (n, d) = (-n, -d);
        }
        let pi = if n == 0 { 0 } else { pi };
        Some(Q { n, d, pi })
    }

    pub fn is_zero(self) -> bool {
        self.n == 0
    }

    pub fn negated(self) -> Q {
        Q { n: -self.n, ..self }
    }

    pub fn plus(self, o: Q) -> Option<Q> {
        if o.is_zero() {
            return Some(self);
        }
        if self.is_zero() {
            return Some(o);
        }
        if self.pi != o.pi {
            return None;
        }
        let g = gcd(self.d, o.d);
        let (a, b) = (self.d / g, o.d / g);
        let n = self.n.checked_mul(b)?.checked_add(o.n.checked_mul(a)?)?;
        Q::new(n, self.d.checked_mul(b)?, self.pi)
    }

    pub fn times(self, o: Q) -> Option<Q> {
        // Cross-reduced first, so that products of reduced fractions
        // overflow only when the result does.
        let g1 = gcd(self.n, o.d);
        let g2 = gcd(o.n, self.d);
        let n = (self.n / g1).checked_mul(o.n / g2)?;
        let d = (self.d / g2).checked_mul(o.d / g1)?;
        Q::new(n, d, self.pi.checked_add(o.pi)?)
    }

    /// `None` for zero too: the caller refuses a division by zero first.
    pub fn recip(self) -> Option<Q> {
        Q::new(self.d, self.n, self.pi.checked_neg()?)
    }

    /// `self^k` by squaring; `None` on overflow (or 0^negative).
    pub fn powi(self, k: i64) -> Option<Q> {
        let mut base = if k < 0 { self.recip()? } else { self };
        let mut e = k.unsigned_abs();
        let mut out = Q::ONE;
        while e > 0 {
            if e & 1 == 1 {
                out = out.times(base)?;
            }
            e >>= 1;
            if e > 0 {
                base = base.times(base)?;
            }
        }
        Some(out)
    }

    /// The exact square root, if it is rational (π to an even power).
    pub fn sqrt(self) -> Option<Q> {
        if self.n < 0 || self.pi % 2 != 0 {
            return None;
        }
        let (a, b) = (isqrt(self.n)?, isqrt(self.d)?);
        Q::new(a, b, self.pi / 2)
    }

    /// The integer this is, if it is one (and π-free).
    pub fn integer(self) -> Option<i128> {
        (self.d == 1 && self.pi == 0).then_some(self.n)
    }

    /// Compare, exactly where both are π-free or of one power of π.
    pub fn compare(self, o: Q) -> Option<std::cmp::Ordering> {
        if self.pi != o.pi && !self.is_zero() && !o.is_zero() {
            return None;
        }
        let l = self.n.checked_mul(o.d)?;
        let r = o.n.checked_mul(self.d)?;
        Some(l.cmp(&r))
    }

    /// In double-double (π's power applied in double-double).
    ///
    /// NOTE: π^4096 is past f64's range either way (π^4096 > 10^2036, and
    /// |n/d| ≥ 2^-127), so a larger power of π gives the same overflow or
    /// underflow applied 4096 times.
    pub fn dd(self) -> DD {
        let mut v = DD::of_i128(self.n) / DD::of_i128(self.d);
        for _ in 0..self.pi.unsigned_abs().min(4096) {
            v = if self.pi > 0 { v * DD::PI } else { v / DD::PI };
        }
        v
    }

    /// The nearest f64 (ties to even), rounded once, where π does not
    /// enter; with a power of π, the double-double value rounded.
    pub fn f64(self) -> f64 {
        if self.pi != 0 {
            let v = self.dd();
            return v.hi + v.lo;
        }
        nearest(self.n, self.d)
    }
}

/// ⌊√n⌋ if n is a perfect square.
fn isqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    let n = n as u128;
    let mut r = (n as f64).sqrt() as u128;
    // Corrected from the f64 estimate.
    while r.checked_mul(r).is_none_or(|s| s > n) {
        r -= 1;
    }
    while (r + 1).checked_mul(r + 1).is_some_and(|s| s <= n) {
        r += 1;
    }
    (r * r == n).then_some(r as i128)
}

/// n / d rounded to the nearest f64, ties to even: 64 quotient bits by
/// long division, the rest folded into a sticky bit, and the u64 → f64
/// conversion (itself correctly rounded) does the one rounding.
fn nearest(n: i128, d: i128) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let negative = (n < 0) != (d < 0);
    let (n, d) = (n.unsigned_abs(), d.unsigned_abs());
    let (mut q, mut r) = (n / d, n % d);
    // The value is q·2^e + (r/d)·2^e.
    let mut e = 0i32;
    let mut sticky = false;
    if q >> 64 != 0 {
        let s = 64 - q.leading_zeros();
        sticky = q & ((1u128 << s) - 1) != 0;
        q >>= s;
        e = s as i32;
    } else {
        while q >> 63 == 0 {
            // r < d ≤ 2^127: 2r fits in u128.
            let r2 = r << 1;
            let bit = r2 >= d;
            q = (q << 1) | u128::from(bit);
            r = if bit { r2 - d } else { r2 };
            e -= 1;
        }
    }
    sticky |= r != 0;
    let m = (q as u64) | u64::from(sticky);
    // 2^e exactly, in two steps for the extremes of the range.
    let half = e / 2;
    let v = (m as f64) * 2f64.powi(half) * 2f64.powi(e - half);
    if negative { -v } else { v }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tenth_plus_two_tenths_is_three_tenths() {
        let a = Q::new(1, 10, 0).unwrap();
        let b = Q::new(2, 10, 0).unwrap();
        assert_eq!(a.plus(b).unwrap().f64(), 0.3);
    }

    #[test]
    fn nearest_is_the_division_of_floats_where_both_are_exact() {
        for (n, d) in [
            (1, 3),
            (2, 3),
            (7, 10),
            (-5, 7),
            (1, 1 << 70),
            (1 << 100, 3),
        ] {
            assert_eq!(nearest(n, d), n as f64 / d as f64, "{n}/{d}");
        }
        assert_eq!(nearest(i128::MAX, 1), i128::MAX as f64);
        assert_eq!(nearest(1, i128::MAX), 1.0 / i128::MAX as f64);
    }

    #[test]
    fn a_tie_rounds_to_even() {
        // 2^53 + 1 is halfway between 2^53 and 2^53 + 2.
        let n = (1i128 << 53) + 1;
        assert_eq!(nearest(n, 1), 9007199254740992.0);
        assert_eq!(nearest(n * 3, 3), 9007199254740992.0);
        // Just above the tie: rounds up.
        assert_eq!(nearest(n * 1000 + 1, 1000), 9007199254740994.0);
    }

    #[test]
    fn square_roots_of_squares_are_exact() {
        assert_eq!(Q::new(9, 4, 2).unwrap().sqrt(), Q::new(3, 2, 1));
        assert_eq!(Q::new(2, 1, 0).unwrap().sqrt(), None);
    }
}
