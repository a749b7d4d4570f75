//! A number times an exact rational factor, correctly rounded: the f64
//! nearest to x · num / den (ties to even), as docs/accuracy.md promises
//! of a quantity written in another unit than the file's.
//!
//! NOTE: `x * num / den` rounds twice (the product, then the quotient) and
//! is up to an ulp off (`10.1 in` in a millimetre file, a density in kg/m³
//! in a pound file). Here the product is exact (a double-double), the
//! quotient's remainder exact (an FMA), so the result is the correctly
//! rounded one unless the exact value lies within a few units of 2⁻¹⁰⁶ of
//! a midpoint between two f64; that case (and factors beyond 2⁵³, and the
//! edges of the range) is decided in integers, exactly.

/// x · num / den correctly rounded, for num, den > 0.
pub(super) fn ratio(x: f64, num: i128, den: i128) -> f64 {
    debug_assert!(num > 0 && den > 0, "unit factors are positive");
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    const EXACT: i128 = 1 << 53;
    if num <= EXACT && den <= EXACT {
        let (n, d) = (num as f64, den as f64);
        if num == 1 {
            return x / d;
        }
        if den == 1 {
            return x * n;
        }
        if let Some(y) = by_double_double(x, n, d) {
            return y;
        }
    }
    exact(x, num.unsigned_abs(), den.unsigned_abs())
}

/// The fast path: `None` where it cannot certify its rounding.
fn by_double_double(x: f64, n: f64, d: f64) -> Option<f64> {
    // Far from underflow, every error term below is exact.
    const LOW: f64 = 1e-270;
    let p = x * n;
    if !p.is_finite() || p.abs() < LOW {
        return None;
    }
    let e = x.mul_add(n, -p); // x·n = p + e exactly
    let q0 = p / d;
    if q0.abs() < LOW || q0.abs() == f64::MAX {
        return None;
    }
    let r = (-q0).mul_add(d, p); // p = q0·d + r exactly
    // The exact value is q0 + (r + e)/d; t is (r + e)/d to 2.01 units.
    let t = (r + e) / d;
    let y = q0 + t;
    if !y.is_finite() || y.abs() == f64::MAX {
        return None;
    }
    // What y's rounding left (two_sum, exact).
    let z = y - q0;
    let lo = (q0 - (y - z)) + (t - z);
    let delta = 4.0 * f64::EPSILON * t.abs() + f64::from_bits(1) * 4.0;
    let (h_dn, h_up) = ((y - y.next_down()) / 2.0, (y.next_up() - y) / 2.0);
    (lo - delta > -h_dn && lo + delta < h_up).then_some(y)
}

/// The exact path: x = ±m·2^k, so x·num/den = ±(m·num/den)·2^k; the
/// quotient scaled to 66–68 bits in 256-bit integers, then rounded once.
fn exact(x: f64, num: u128, den: u128) -> f64 {
    let bits = x.abs().to_bits();
    let (biased, frac) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
    let (m, k) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), biased - 1075)
    };
    let n = U256::mul(m, num);
    // Shift so that the quotient has 66 bits or more.
    let s = 66 - (n.bits() as i32 - (128 - den.leading_zeros()) as i32);
    let (a, b) = if s >= 0 {
        (n.shl(s as u32), U256(0, den))
    } else {
        (n, U256(0, den).shl((-s) as u32))
    };
    let (q, sticky) = a.div(b);
    let y = round_scaled(q, sticky, k - s);
    if x < 0.0 { -y } else { y }
}

/// q·2^e2, q ≥ 2⁶⁵, with `sticky` for a non-zero rest below q's last bit,
/// rounded to the nearest f64 (ties to even), subnormals and overflow too.
fn round_scaled(q: u128, sticky: bool, e2: i32) -> f64 {
    let len = 128 - q.leading_zeros() as i32;
    let shift = (len - 53).max(-1074 - e2);
    if shift > len {
        return 0.0;
    }
    let shift = shift as u32;
    let (kept, rest) = if shift >= 128 {
        (0, q)
    } else {
        (q >> shift, q & ((1u128 << shift) - 1))
    };
    let half = 1u128 << (shift - 1);
    let up = rest > half || (rest == half && (sticky || kept & 1 == 1));
    scale(kept as f64 + if up { 1.0 } else { 0.0 }, e2 + shift as i32)
}

/// m·2^e, exactly where the result is representable (m ≤ 2⁵³).
fn scale(mut m: f64, mut e: i32) -> f64 {
    let pow = |e: i32| f64::from_bits(((e + 1023) as u64) << 52);
    while e > 1000 {
        m *= pow(1000);
        e -= 1000;
    }
    while e < -1000 {
        m *= pow(-1000);
        e += 1000;
    }
    m * pow(e)
}

/// An unsigned 256-bit integer (high, low), as much as `exact` needs.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct U256(u128, u128);

impl U256 {
    fn mul(a: u64, b: u128) -> U256 {
        let (a, lo, hi) = (u128::from(a), b & u128::from(u64::MAX), b >> 64);
        let (p0, p1) = (a * lo, a * hi); // each below 2¹²⁸
        let (low, carry) = p0.overflowing_add(p1 << 64);
        U256((p1 >> 64) + u128::from(carry), low)
    }

    fn bits(self) -> u32 {
        if self.0 != 0 {
            256 - self.0.leading_zeros()
        } else {
            128 - self.1.leading_zeros()
        }
    }

    fn shl(self, s: u32) -> U256 {
        match s {
            0 => self,
            1..128 => U256((self.0 << s) | (self.1 >> (128 - s)), self.1 << s),
            _ => U256(self.1 << (s - 128), 0),
        }
    }

    fn sub(self, o: U256) -> U256 {
        let (low, borrow) = self.1.overflowing_sub(o.1);
        U256(self.0 - o.0 - u128::from(borrow), low)
    }

    /// The quotient (below 2¹²⁸) and whether a remainder is left.
    fn div(mut self, b: U256) -> (u128, bool) {
        let mut q = 0u128;
        let top = self.bits().saturating_sub(b.bits()) + 1;
        for i in (0..top.min(127)).rev() {
            let d = b.shl(i);
            if self >= d {
                self = self.sub(d);
                q |= 1 << i;
            }
        }
        (q, self != U256(0, 0))
    }
}

#[cfg(test)]
mod tests {
    use super::ratio;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::ToPrimitive;

    /// The f64 nearest to x·num/den, by num-rational (an independent
    /// correctly rounded conversion).
    fn nearest(x: f64, num: i128, den: i128) -> f64 {
        let q = BigRational::from_float(x).unwrap()
            * BigRational::new(BigInt::from(num), BigInt::from(den));
        // (num-rational gives `None` past f64's range: infinity.)
        q.to_f64().unwrap_or(f64::INFINITY.copysign(x))
    }

    /// Every factor a file's units give a length, mass, area, density or
    /// inertia, from one unit to another (a few, and their inverses).
    const FACTORS: &[(i128, i128)] = &[
        (127, 5),
        (5, 127),
        (381, 1250),
        (1250, 381),
        (45_359_237, 100_000),
        (100_000, 45_359_237),
        (16_129, 25),
        (2_048_383, 125),
        (45_359_237_000_000_000, 2_048_383),
        (2_048_383, 45_359_237_000_000_000_000),
        (1, 1000),
        (1000, 1),
        (1_000_000_000_000_000_000, 3),
    ];

    #[test]
    fn a_number_times_a_unit_ratio_is_correctly_rounded() {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for _ in 0..20_000 {
            // Decimal-looking numbers and raw bit patterns over the range.
            let x = match next() % 3 {
                0 => (next() % 100_000) as f64 / 10f64.powi((next() % 6) as i32),
                1 => f64::from_bits(next() >> 2 | 0x3000_0000_0000_0000),
                _ => f64::from_bits(next() >> 1),
            };
            let x = if next() % 2 == 0 { -x } else { x };
            if !x.is_finite() {
                continue;
            }
            for &(n, d) in FACTORS {
                let want = nearest(x, n, d);
                let got = ratio(x, n, d);
                assert!(
                    got == want || (got.is_infinite() && want.is_infinite()),
                    "{x:e} · {n}/{d}: {got:e}, nearest {want:e}"
                );
            }
        }
    }

    #[test]
    fn the_ten_point_one_inches_of_the_issue_are_the_nearest_millimetres() {
        assert_eq!(ratio(10.1, 127, 5), nearest(10.1, 127, 5));
        // f64 10.1 is below 10.1: its 25.4 times is below 256.54.
        assert_eq!(ratio(10.1, 127, 5), 256.539_999_999_999_96);
        assert_ne!(ratio(10.1, 127, 5), 10.1 * 127.0 / 5.0);
    }

    #[test]
    fn subnormal_and_overflowing_results_round_as_ieee_does() {
        for &(x, n, d) in &[
            (f64::MIN_POSITIVE, 1, 3_i128),
            (f64::MIN_POSITIVE, 127, 5000),
            (5e-324, 127, 5),
            (3e-320, 5, 127),
            (f64::MAX, 127, 5),
            (1.7e308, 127, 128),
            (f64::MAX, 5, 127),
        ] {
            assert_eq!(
                ratio(x, n, d).to_bits(),
                nearest(x, n, d).to_bits(),
                "{x:e}·{n}/{d}"
            );
        }
    }
}
