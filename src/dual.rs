//! Dual numbers x + ẋ ε (ε² = 0) over any `Real`: forward-mode automatic
//! differentiation through the same arithmetic the composer runs, for the
//! first-order propagation of tolerances (`uncertainty`).
//!
//! NOTE: a part's physics is generic over `Real`; evaluated in `Dual<f64>`
//! with one input seeded (`Real::var`, `part::Lift`), every result carries
//! its exact derivative with respect to that input: the chain rule applied
//! operation by operation, with no step size and no truncation error (what
//! finite differences cannot give). The derivative parts are rounded as
//! any f64 arithmetic is; nothing here is certified.

use crate::numeric::{DD, Real};
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `v + d ε`: a value and its derivative with respect to one input.
#[derive(Clone, Copy, Default)]
pub struct Dual<T> {
    pub v: T,
    pub d: T,
}

impl<T: Real> Dual<T> {
    pub fn new(v: T, d: T) -> Dual<T> {
        Dual { v, d }
    }
}

impl<T: Real> fmt::Debug for Dual<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Dual({:?} + {:?}ε)", self.v, self.d)
    }
}

/// Equal and ordered by value alone: the branches a closed form takes (a
/// sign, the closer of two moments, an exact zero) are those of the
/// nominal input.
impl<T: Real> PartialEq for Dual<T> {
    fn eq(&self, o: &Self) -> bool {
        self.v == o.v
    }
}

impl<T: Real> PartialOrd for Dual<T> {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        self.v.partial_cmp(&o.v)
    }
}

impl<T: Real> Add for Dual<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Dual::new(self.v + o.v, self.d + o.d)
    }
}

impl<T: Real> Sub for Dual<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Dual::new(self.v - o.v, self.d - o.d)
    }
}

impl<T: Real> Mul for Dual<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Dual::new(self.v * o.v, self.d * o.v + self.v * o.d)
    }
}

impl<T: Real> Div for Dual<T> {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        let q = self.v / o.v;
        Dual::new(q, (self.d - q * o.d) / o.v)
    }
}

impl<T: Real> Neg for Dual<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Dual::new(-self.v, -self.d)
    }
}

impl<T: Real> Real for Dual<T> {
    const EPS: f64 = T::EPS;
    #[inline]
    fn of(x: f64) -> Self {
        Dual::new(T::of(x), T::of(0.0))
    }
    fn f64(self) -> f64 {
        self.v.f64()
    }
    fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        // √ of 0 has no derivative; `Real::sqrt` gives 0 there, and so
        // does its derivative here (the closed forms take √ of positive
        // sums only).
        let d = if r.f64() == 0.0 {
            T::of(0.0)
        } else {
            self.d / (T::of(2.0) * r)
        };
        Dual::new(r, d)
    }
    fn is_finite(self) -> bool {
        self.v.is_finite() && self.d.is_finite()
    }
    fn sin_cos_deg(deg: f64) -> (Self, Self) {
        let (s, c) = T::sin_cos_deg(deg);
        (Dual::new(s, T::of(0.0)), Dual::new(c, T::of(0.0)))
    }
    fn pi() -> Self {
        Dual::new(T::pi(), T::of(0.0))
    }
    fn of_dd(x: DD) -> Self {
        Dual::new(T::of_dd(x), T::of(0.0))
    }
    #[inline]
    fn var(x: f64, dx: f64) -> Self {
        Dual::new(T::of(x), T::of(dx))
    }
    #[inline]
    fn var_dd(x: DD, dx: f64) -> Self {
        Dual::new(T::of_dd(x), T::of(dx))
    }
}

#[cfg(test)]
mod tests {
    use super::Dual;
    use crate::numeric::{DD, Real};

    fn x(v: f64) -> Dual<f64> {
        Dual::var(v, 1.0)
    }

    #[test]
    fn the_product_and_quotient_rules_hold() {
        // d/dx (x³ / (1 + x)) = (3x²(1 + x) − x³)/(1 + x)², at x = 2: 28/9.
        let f = x(2.0) * x(2.0) * x(2.0) / (Dual::of(1.0) + x(2.0));
        assert_eq!(f.v, 8.0 / 3.0);
        assert!((f.d - 28.0 / 9.0).abs() <= 4.0 * f64::EPSILON * 28.0 / 9.0);
    }

    #[test]
    fn the_square_root_rule_holds() {
        let f = x(9.0).sqrt();
        assert_eq!((f.v, f.d), (3.0, 1.0 / 6.0));
    }

    #[test]
    fn constants_carry_no_derivative() {
        let c: Dual<DD> = Real::of(5.0);
        assert_eq!(c.d.f64(), 0.0);
        assert_eq!(Dual::<f64>::pi().d, 0.0);
    }

    #[test]
    fn double_double_duals_carry_more_digits() {
        // d/dx (x² − 1e16·x) at x = 1e8 + 1: 2x − 1e16 = 2e8 + 2 − 1e16 exactly.
        let v = 1e8 + 1.0;
        let f = |t: Dual<DD>| t * t - Dual::of(1e16) * t;
        let r = f(Dual::var(v, 1.0));
        assert_eq!(r.d.f64(), 2.0 * v - 1e16);
    }
}
