//! The arithmetic behind the precision modes: double-double numbers (`DD`,
//! about 106 significant bits), compensated (Neumaier) sums of f64, and the
//! `Real` trait that lets one composer and one eigen solver run in either
//! f64 or double-double.
//!
//! NOTE: the double-double algorithms are the classic error-free
//! transformations (Dekker 1971; Knuth; Joldes, Muller and Popescu, "Tight
//! and rigorous error bounds for basic building blocks of double-word
//! arithmetic", 2017): `two_sum` and `two_prod` return a rounded result and
//! its exact rounding error, and a DD is an unevaluated sum `hi + lo` with
//! |lo| ≤ ½ ulp(hi). Relative error of +, −, × is below 4u² with u = 2⁻⁵³
//! (≈ 5e-32), of ÷ and √ below 10u².

use std::fmt;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// A 3×3 matrix as rows, for the generic composer over any `Real` (f64,
/// double-double, dual numbers); `la::Matrix3` serves f64 alone.
pub type M3<T> = [[T; 3]; 3];

/// The arithmetic of composition and of the principal axes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// f64 with compensated sums and a Jacobi eigen solver (the default).
    #[default]
    Standard,
    /// Double-double (~32 significant digits) throughout: for the smallest
    /// principal moment of very slender or flat bodies.
    Extended,
}

/// The operations the composer and eigen solver need, for f64 and DD.
pub trait Real:
    Copy
    + PartialOrd
    + fmt::Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Unit roundoff of the type: 2⁻⁵³ for f64, 2⁻¹⁰⁶ for DD (nominal).
    const EPS: f64;
    fn of(x: f64) -> Self;
    /// Nearest f64.
    fn f64(self) -> f64;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self {
        if self < Self::of(0.0) { -self } else { self }
    }
    fn is_finite(self) -> bool {
        self.f64().is_finite()
    }
    /// sin and cos of an angle in degrees, exact at multiples of 90°.
    fn sin_cos_deg(deg: f64) -> (Self, Self);
    /// π to the type's precision.
    fn pi() -> Self;
    /// A double-double rounded to the type.
    fn of_dd(x: DD) -> Self;
    /// An input `x` moving at the rate `dx` (per unit of a tolerance):
    /// `x` itself for a number that carries no derivative (f64, DD), a
    /// dual number `x + dx ε` for `dual::Dual` (forward-mode automatic
    /// differentiation through the same arithmetic).
    #[inline]
    fn var(x: f64, _dx: f64) -> Self {
        Self::of(x)
    }
    /// `var` for an input formed in double-double.
    #[inline]
    fn var_dd(x: DD, _dx: f64) -> Self {
        Self::of_dd(x)
    }
}

/// Reduce degrees to x in [−45°, 45°] and a quarter-turn count q: both steps
/// are exact (`%` is exact, and r − 90q is a multiple of r's ulp below 45).
fn reduce_degrees(deg: f64) -> (f64, i64) {
    let r = deg % 360.0;
    let q = (r / 90.0).round();
    (r - 90.0 * q, (q as i64).rem_euclid(4))
}

fn quarter<T: Neg<Output = T>>(q: i64, s: T, c: T) -> (T, T) {
    match q {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

impl Real for f64 {
    const EPS: f64 = f64::EPSILON / 2.0;
    fn of(x: f64) -> f64 {
        x
    }
    fn f64(self) -> f64 {
        self
    }
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    fn sin_cos_deg(deg: f64) -> (f64, f64) {
        let (x, q) = reduce_degrees(deg);
        let (s, c) = x.to_radians().sin_cos();
        quarter(q, s, c)
    }
    fn pi() -> f64 {
        std::f64::consts::PI
    }
    fn of_dd(x: DD) -> f64 {
        x.f64()
    }
}

/// a + b = s + e exactly (Knuth's TwoSum, no condition on a, b).
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a + b = s + e exactly when |a| ≥ |b| (or a = 0).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp's split of `a` into two halves of 26 bits each, with a scaling
/// guard so that huge values do not overflow.
#[inline]
fn split(a: f64) -> (f64, f64) {
    const FACTOR: f64 = 134_217_729.0; // 2²⁷ + 1
    const BIG: f64 = 6.696_928_794_914_171e299; // 2⁹⁹⁶
    if a.abs() > BIG {
        let s = a * 3.725_290_298_461_914e-9; // 2⁻²⁸
        let c = FACTOR * s;
        let hi = c - (c - s);
        let lo = s - hi;
        (hi * 268_435_456.0, lo * 268_435_456.0)
    } else {
        let c = FACTOR * a;
        let hi = c - (c - a);
        (hi, a - hi)
    }
}

/// a · b = p + e exactly (barring underflow): the FMA instruction where the
/// target has one, else Dekker's product (software `mul_add` is slow).
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    if !p.is_finite() {
        // Overflow (or an infinite or NaN operand): no error term to add.
        return (p, 0.0);
    }
    if cfg!(target_feature = "fma") {
        return (p, a.mul_add(b, -p));
    }
    // Near the top of the range Dekker's halves can round up to infinity:
    // take the product of the larger operand scaled down by 2⁶⁰ (exact),
    // and scale its error back.
    const HUGE: f64 = 6.696_928_794_914_171e299; // 2⁹⁹⁶
    if a.abs() > HUGE || b.abs() > HUGE || p.abs() > HUGE {
        const DOWN: f64 = 8.673_617_379_884_035e-19; // 2⁻⁶⁰
        const UP: f64 = 1_152_921_504_606_846_976.0; // 2⁶⁰
        let (a, b) = if a.abs() >= b.abs() {
            (a * DOWN, b)
        } else {
            (a, b * DOWN)
        };
        return (p, dekker(a, b, p * DOWN) * UP);
    }
    (p, dekker(a, b, p))
}

/// The error a·b − p of the rounded product p, by Dekker's algorithm.
#[inline]
fn dekker(a: f64, b: f64, p: f64) -> f64 {
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// A double-double number hi + lo, |lo| ≤ ½ ulp(hi).
#[derive(Clone, Copy, Default, PartialEq)]
pub struct DD {
    pub hi: f64,
    pub lo: f64,
}

impl fmt::Debug for DD {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "DD({:e} + {:e})", self.hi, self.lo)
    }
}

impl DD {
    pub const fn new(hi: f64, lo: f64) -> DD {
        DD { hi, lo }
    }

    /// π to double-double precision.
    pub const PI: DD = DD::new(std::f64::consts::PI, 1.224_646_799_147_353_2e-16);

    /// An integer of up to 106 bits, exactly.
    pub fn of_i128(n: i128) -> DD {
        let hi = n as f64;
        // hi is n rounded; the remainder is below 2⁷⁴ and so fits in i128.
        let lo = (n - hi as i128) as f64;
        let (hi, lo) = fast_two_sum(hi, lo);
        DD { hi, lo }
    }

    fn renorm(hi: f64, lo: f64) -> DD {
        let (hi, lo) = fast_two_sum(hi, lo);
        DD { hi, lo }
    }

    /// self · x for an f64 x (cheaper than a full product).
    pub fn mul_f64(self, x: f64) -> DD {
        let (p, e) = two_prod(self.hi, x);
        DD::renorm(p, e + self.lo * x)
    }
}

impl From<f64> for DD {
    fn from(x: f64) -> DD {
        DD::of(x)
    }
}

impl PartialOrd for DD {
    fn partial_cmp(&self, o: &DD) -> Option<std::cmp::Ordering> {
        match self.hi.partial_cmp(&o.hi) {
            Some(std::cmp::Ordering::Equal) => self.lo.partial_cmp(&o.lo),
            other => other,
        }
    }
}

impl Add for DD {
    type Output = DD;
    /// Accurate double-word addition (Joldes et al., Algorithm 6).
    #[inline]
    fn add(self, o: DD) -> DD {
        let (s, e) = two_sum(self.hi, o.hi);
        if !s.is_finite() {
            return DD::new(s, 0.0);
        }
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = fast_two_sum(s, e + t);
        DD::renorm(s, e + f)
    }
}

impl AddAssign for DD {
    fn add_assign(&mut self, o: DD) {
        *self = *self + o;
    }
}

impl Neg for DD {
    type Output = DD;
    fn neg(self) -> DD {
        DD::new(-self.hi, -self.lo)
    }
}

impl Sub for DD {
    type Output = DD;
    #[inline]
    fn sub(self, o: DD) -> DD {
        self + -o
    }
}

impl Mul for DD {
    type Output = DD;
    /// Double-word product (Joldes et al., Algorithm 10 without FMA fusion).
    #[inline]
    fn mul(self, o: DD) -> DD {
        let (p, e) = two_prod(self.hi, o.hi);
        DD::renorm(p, e + (self.hi * o.lo + self.lo * o.hi))
    }
}

impl Div for DD {
    type Output = DD;
    /// Long division: three f64 quotient digits.
    #[inline]
    fn div(self, o: DD) -> DD {
        let q1 = self.hi / o.hi;
        if !q1.is_finite() || !o.hi.is_finite() || q1 == 0.0 {
            // Overflow, division by zero or by infinity, or a zero quotient:
            // the f64 quotient is the answer, without a NaN from inf − inf.
            return DD::new(q1, 0.0);
        }
        let r = self - o.mul_f64(q1);
        let q2 = r.hi / o.hi;
        let r = r - o.mul_f64(q2);
        let q3 = r.hi / o.hi;
        let (q1, q2) = fast_two_sum(q1, q2);
        DD::new(q1, q2) + DD::new(q3, 0.0)
    }
}

impl Real for DD {
    const EPS: f64 = f64::EPSILON * f64::EPSILON / 4.0;
    fn of(x: f64) -> DD {
        DD::new(x, 0.0)
    }
    fn f64(self) -> f64 {
        self.hi + self.lo
    }
    fn sqrt(self) -> DD {
        if self.hi <= 0.0 {
            return DD::of(0.0);
        }
        // One Newton step from the f64 root doubles its 53 bits.
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        let r = (self - DD::new(p, e)).hi;
        DD::renorm(s, r / (2.0 * s))
    }
    fn pi() -> DD {
        DD::PI
    }
    fn of_dd(x: DD) -> DD {
        x
    }
    fn sin_cos_deg(deg: f64) -> (DD, DD) {
        let (x, q) = reduce_degrees(deg);
        if x.abs() < 1e-40 {
            // sin t = t and cos t = 1 to double-double precision (t² < 1e-80).
            let t = DD::PI.mul_f64(x) / DD::of(180.0);
            return quarter(q, t, DD::of(1.0));
        }
        // |x| ≤ 45° = π/4: the Taylor series reach 2⁻¹⁰⁶ within 27 terms.
        let t = DD::PI.mul_f64(x) / DD::of(180.0);
        let t2 = t * t;
        let (mut s, mut c) = (t, DD::of(1.0));
        let (mut ts, mut tc) = (t, DD::of(1.0));
        let mut k = 1.0;
        loop {
            // ts = t^(2k+1)/(2k+1)!, tc = t^(2k)/(2k)!, alternating signs.
            tc = -(tc * t2) / DD::of((2.0 * k - 1.0) * (2.0 * k));
            ts = -(ts * t2) / DD::of((2.0 * k) * (2.0 * k + 1.0));
            c += tc;
            s += ts;
            // Terms below 2⁻¹¹⁰ of their sums are gone; 30 terms reach that
            // for |t| ≤ π/4 whatever happens to the test.
            if (tc.hi.abs() <= 1e-33 && ts.hi.abs() <= 1e-33 * s.hi.abs()) || k >= 30.0 {
                break;
            }
            k += 1.0;
        }
        quarter(q, s, c)
    }
}

/// A compensated (Neumaier) sum of f64: the running sum and the exact sum
/// of its rounding errors, so the result is as if summed in ~twice the
/// precision and rounded once, whatever the order and cancellation.
#[derive(Clone, Copy, Debug, Default)]
pub struct Sum {
    s: f64,
    c: f64,
}

impl Sum {
    #[inline]
    pub fn add(&mut self, x: f64) {
        let (s, e) = two_sum(self.s, x);
        self.s = s;
        self.c += e;
    }

    /// The sum rounded to f64.
    pub fn value(self) -> f64 {
        self.s + self.c
    }

    /// The sum as a double-double.
    pub fn dd(self) -> DD {
        DD::renorm(self.s, self.c)
    }
}

/// A power of two near max |vᵢ| (1 for a zero or non-finite vector):
/// dividing by it is exact, and it keeps the squares of the scaled vector
/// away from overflow and underflow.
pub fn pow2_scale<T: Real>(v: &[T]) -> f64 {
    let big = v.iter().fold(0.0f64, |m, x| m.max(x.f64().abs()));
    if big == 0.0 || !big.is_finite() {
        return 1.0;
    }
    // 2^e from the biased exponent (log2 rounds up to 1024 near f64::MAX);
    // subnormals take 2⁻¹⁰²², by which dividing them is still exact.
    let biased = ((big.to_bits() >> 52) & 0x7ff).max(1);
    f64::from_bits(biased << 52)
}

/// v / 2ᵏ for the power of two nearest below max |vᵢ| (`pow2_scale`):
/// exact, and keeps the squares of a direction vector away from overflow
/// and underflow.
pub fn pow2_scaled(v: [DD; 3]) -> [DD; 3] {
    let scale = DD::of(pow2_scale(&v));
    v.map(|x| x / scale)
}

/// The scaled Euclidean norm (Frobenius for a matrix), the one used
/// everywhere: no overflow or underflow in the squares, since the vector is
/// first divided by `pow2_scale`, which is exact. `f64::MAX` at most for
/// finite input; infinite if an entry is infinite or NaN.
pub fn norm_of<T: Real>(v: &[T]) -> T {
    if v.iter().any(|x| !x.is_finite()) {
        return T::of(f64::INFINITY);
    }
    let scale = pow2_scale(v);
    let sum = v.iter().fold(T::of(0.0), |acc, &x| {
        let w = x / T::of(scale);
        acc + w * w
    });
    let r = T::of(scale) * sum.sqrt();
    if r.f64() > f64::MAX {
        T::of(f64::MAX)
    } else {
        r
    }
}

/// `norm_of` for f64.
pub fn norm(v: &[f64]) -> f64 {
    norm_of(v)
}

/// v / |v| for a non-zero finite v, robust to extreme magnitudes.
pub fn unit(v: &[f64; 3]) -> [f64; 3] {
    let s = pow2_scale(v);
    let w = v.map(|x| x / s);
    let n = norm(&w);
    w.map(|x| x / n)
}

/// `x` to `digits` significant digits, as Rust writes it; in exponent
/// form when large or small (`1.3e154`): the plausibility warnings' numbers.
pub fn significant(x: f64, digits: usize) -> String {
    // NOTE: rounding up may pass f64::MAX (1.7976…e308 to 3 digits is
    // 1.80e308): the number is then shown as it is.
    let r = format!("{x:.*e}", digits.saturating_sub(1))
        .parse()
        .ok()
        .filter(|r: &f64| r.is_finite())
        .unwrap_or(x);
    if r != 0.0 && !(1e-3..1e6).contains(&r.abs()) {
        format!("{r:e}")
    } else {
        format!("{r}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norm_neither_overflows_nor_underflows() {
        // Two roundings (the sum of squares, the root) and an exact scaling:
        // within 2 ulps wherever the magnitudes are.
        let close = |a: f64, b: f64| (a - b).abs() <= 2.0 * f64::EPSILON * b;
        assert_eq!(norm(&[3.0, 4.0]), 5.0);
        assert!(close(norm(&[3e300, 4e300]), 5e300));
        assert!(close(norm(&[3e-300, 4e-300]), 5e-300));
        assert_eq!(norm(&[0.0, 0.0]), 0.0);
        assert_eq!(norm(&[f64::MAX, f64::MAX]), f64::MAX);
        assert_eq!(norm(&[f64::INFINITY, 1.0]), f64::INFINITY);
        assert_eq!(norm(&[f64::NAN, 1.0]), f64::INFINITY);
    }

    /// 2⁻¹⁰⁰: far below f64's resolution at 1, well within DD's.
    const TINY: f64 = 7.888_609_052_210_118e-31;

    #[test]
    fn two_sum_and_two_prod_are_exact() {
        let (s, e) = two_sum(1.0, TINY);
        assert_eq!((s, e), (1.0, TINY));
        // (1 + 2⁻³⁰)² = 1 + 2⁻²⁹ + 2⁻⁶⁰: the last term is the error.
        let a = 1.0 + 2f64.powi(-30);
        assert_eq!(two_prod(a, a), (1.0 + 2f64.powi(-29), 2f64.powi(-60)));
        // Huge operands take the scaled split, and stay exact.
        let big = 2f64.powi(1000) * a;
        let (p, e) = two_prod(big, 2f64.powi(-1000) * a);
        assert_eq!((p, e), (1.0 + 2f64.powi(-29), 2f64.powi(-60)));
    }

    #[test]
    fn dd_keeps_what_f64_rounds_away() {
        let x = DD::of(1.0) + DD::of(TINY);
        assert_eq!((x - DD::of(1.0)).f64(), TINY);
        let third = DD::of(1.0) / DD::of(3.0);
        // 3 · (1/3) − 1 vanishes to DD precision, not f64 precision.
        assert!((third * DD::of(3.0) - DD::of(1.0)).f64().abs() < 1e-31);
        assert!((third.f64() - 1.0 / 3.0).abs() == 0.0);
    }

    #[test]
    fn dd_sqrt_squares_back() {
        for x in [2.0, 3.0, 1e-300, 7.5e250, 0.1] {
            let r = DD::of(x).sqrt();
            let back = r * r - DD::of(x);
            assert!(back.f64().abs() <= 4.0 * DD::EPS * x, "{x}: {back:?}");
        }
    }

    #[test]
    fn dd_integers_up_to_106_bits_are_exact() {
        let n: i128 = (1 << 100) + 12_345;
        let d = DD::of_i128(n);
        assert_eq!(d.hi as i128 + d.lo as i128, n);
    }

    #[test]
    fn dd_sin_cos_obey_pythagoras_and_the_double_angle() {
        for deg in [1.0, 17.25, 44.9, 45.0, -30.0, 123.0, 359.0, 1e6 + 0.5] {
            let (s, c) = DD::sin_cos_deg(deg);
            let one = s * s + c * c - DD::of(1.0);
            assert!(one.f64().abs() < 1e-30, "{deg}: {one:?}");
            // sin 2x = 2 sin x cos x, with 2x reduced independently.
            let (s2, _) = DD::sin_cos_deg(2.0 * deg);
            let d = s2 - DD::of(2.0) * s * c;
            assert!(d.f64().abs() < 1e-30, "{deg}: {d:?}");
            // And the f64 value is the correctly rounded-ish f64 sine.
            let (sf, cf) = f64::sin_cos_deg(deg);
            assert!((s.f64() - sf).abs() <= 2.0 * f64::EPSILON);
            assert!((c.f64() - cf).abs() <= 2.0 * f64::EPSILON);
        }
        // sin 30° = ½ exactly, to DD precision.
        let (s, _) = DD::sin_cos_deg(30.0);
        assert!((s - DD::of(0.5)).f64().abs() < 1e-31);
        assert_eq!(DD::sin_cos_deg(90.0), (DD::of(1.0), DD::of(0.0)));
    }

    #[test]
    fn dd_sin_cos_of_tiny_angles_end_and_are_the_angle() {
        for deg in [1e-300, -3e-290, 1e-45, 1e-20, 5e-324] {
            let (s, c) = DD::sin_cos_deg(deg);
            let t = deg.to_radians();
            assert!(
                (s.f64() - t).abs() <= 2.0 * f64::EPSILON * t.abs(),
                "{deg}: {s:?}"
            );
            assert_eq!(c.f64(), 1.0);
        }
    }

    #[test]
    fn dd_at_the_ends_of_the_range_gives_inf_or_zero_not_nan() {
        let max = f64::MAX;
        let p = DD::of(max) * DD::of(0.999_999_999_999_999_9);
        assert!(p.f64().is_finite() && p.f64() > 1.79e308, "{p:?}");
        assert_eq!(two_prod(max, 0.5).0, max * 0.5);
        assert!(two_prod(max, 0.5).1 == 0.0);
        assert_eq!((DD::of(1e300) / DD::of(1e-10)).f64(), f64::INFINITY);
        assert_eq!((DD::of(1.0) / DD::of(f64::INFINITY)).f64(), 0.0);
        assert_eq!((DD::of(f64::INFINITY) + DD::of(1.0)).f64(), f64::INFINITY);
        // Products near the top keep their error term.
        let a = 1.0 + 2f64.powi(-30);
        let (p, e) = two_prod(2f64.powi(1000) * a, 2f64.powi(20) * a);
        assert_eq!(
            (p, e),
            (
                2f64.powi(1020) * (1.0 + 2f64.powi(-29)),
                2f64.powi(1020 - 60)
            )
        );
    }

    #[test]
    fn compensated_sum_survives_cancellation() {
        // 1 + 1e-20 − 1, plus a thousand 1e-20s: plain summation gives 0.
        let mut s = Sum::default();
        s.add(1.0);
        s.add(1e-20);
        s.add(-1.0);
        for _ in 0..1000 {
            s.add(1e-20);
        }
        assert!((s.value() - 1001e-20).abs() < 1e-30);
    }
}
