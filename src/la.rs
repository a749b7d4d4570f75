//! Three-vectors and 3×3 matrices of f64: the small linear algebra the
//! composer, the shapes and the checks use (`Vector3`, `Matrix3`).
//!
//! NOTE: hand-written, not nalgebra: massprop used nalgebra's `Vector3`
//! and `Matrix3` of f64 alone, and nalgebra with simba, wide, safe_arch,
//! matrixmultiply, num-complex, approx and typenum was about a tenth of a
//! cold release build, its generics monomorphised again inside massprop's
//! own compile (docs/performance.md, "Build time"). The names, the
//! methods and their meanings are nalgebra's, so the call sites kept
//! their code (but for a vector's `as_slice`, which named fields cannot
//! give without unsafe code: `as_array` instead); every operation repeats nalgebra 0.35's floating-point
//! operations in nalgebra's order (a product accumulates column by column
//! as its gemv does; `norm_squared` and `trace` start from +0.0; `amax`
//! keeps the running value unless `a >= b` fails), so every result is
//! bit for bit what nalgebra gave (a NaN's sign and payload excepted,
//! which Rust itself leaves open). tests/integration/la_pin.rs holds each
//! operation to nalgebra's bits over random and adversarial inputs.
//! Storage is by column, as nalgebra's: `iter`, `map` and `from_fn` visit
//! a matrix's entries column by column.

use std::fmt;
use std::ops::{
    Add, AddAssign, Div, DivAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign,
};

/// A column vector of three components.
#[derive(Clone, Copy, PartialEq, Default)]
pub struct Vector3<T> {
    pub x: T,
    pub y: T,
    pub z: T,
}

/// A row vector of three components: a `Vector3` transposed.
#[derive(Clone, Copy, PartialEq, Default)]
pub struct RowVector3<T> {
    pub x: T,
    pub y: T,
    pub z: T,
}

/// A 3×3 matrix, stored by column: `cols[j][i]` is row i, column j.
#[derive(Clone, Copy, PartialEq, Default)]
pub struct Matrix3<T> {
    cols: [[T; 3]; 3],
}

// NOTE: nalgebra's `Debug` prints its storage, the array of columns; so
// does this (`[[x, y, z]]`, `[[m00, m10, m20], …]`), should a message
// ever show one.
impl<T: fmt::Debug + Copy> fmt::Debug for Vector3<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        [[self.x, self.y, self.z]].fmt(f)
    }
}

impl<T: fmt::Debug + Copy> fmt::Debug for RowVector3<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        [[self.x], [self.y], [self.z]].fmt(f)
    }
}

impl<T: fmt::Debug> fmt::Debug for Matrix3<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.cols.fmt(f)
    }
}

/// `(x, y, z)`, for test messages (nalgebra's boxed layout is not kept:
/// nothing massprop prints shows a vector this way).
impl<T: fmt::Display> fmt::Display for Vector3<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, {})", self.x, self.y, self.z)
    }
}

impl<T: Copy> Vector3<T> {
    pub const fn new(x: T, y: T, z: T) -> Self {
        Vector3 { x, y, z }
    }

    /// Component i is `f(i, 0)`, called for i = 0, 1, 2 in that order.
    pub fn from_fn(mut f: impl FnMut(usize, usize) -> T) -> Self {
        let x = f(0, 0);
        let y = f(1, 0);
        let z = f(2, 0);
        Vector3 { x, y, z }
    }

    pub fn map<U>(&self, mut f: impl FnMut(T) -> U) -> Vector3<U> {
        let x = f(self.x);
        let y = f(self.y);
        let z = f(self.z);
        Vector3 { x, y, z }
    }

    pub fn iter(&self) -> std::array::IntoIter<&T, 3> {
        [&self.x, &self.y, &self.z].into_iter()
    }

    pub fn transpose(&self) -> RowVector3<T> {
        RowVector3 {
            x: self.x,
            y: self.y,
            z: self.z,
        }
    }

    pub fn as_array(&self) -> [T; 3] {
        [self.x, self.y, self.z]
    }
}

impl Vector3<f64> {
    pub const fn zeros() -> Self {
        Vector3::new(0.0, 0.0, 0.0)
    }

    /// The vector with `val` at i and zeros elsewhere.
    pub fn ith(i: usize, val: f64) -> Self {
        let mut v = Self::zeros();
        v[i] = val;
        v
    }

    /// The unit vector along x.
    pub const fn x() -> Self {
        Vector3::new(1.0, 0.0, 0.0)
    }

    /// The unit vector along y.
    pub const fn y() -> Self {
        Vector3::new(0.0, 1.0, 0.0)
    }

    /// The unit vector along z.
    pub const fn z() -> Self {
        Vector3::new(0.0, 0.0, 1.0)
    }

    /// (x·x' + y·y') + z·z', nalgebra's order for three components.
    pub fn dot(&self, rhs: &Self) -> f64 {
        let a = self.x * rhs.x;
        let b = self.y * rhs.y;
        let c = self.z * rhs.z;
        a + b + c
    }

    pub fn cross(&self, b: &Self) -> Self {
        Vector3::new(
            self.y * b.z - self.z * b.y,
            self.z * b.x - self.x * b.z,
            self.x * b.y - self.y * b.x,
        )
    }

    /// +0.0 plus the dot product with itself, as nalgebra sums columns.
    pub fn norm_squared(&self) -> f64 {
        let mut res = 0.0;
        res += self.dot(self);
        res
    }

    pub fn norm(&self) -> f64 {
        self.norm_squared().sqrt()
    }

    /// Each component divided by the norm (no check for zero).
    pub fn normalize(&self) -> Self {
        let n = self.norm();
        self.map(|e| e / n)
    }

    /// The largest |component|; the running value is kept only where
    /// `a >= b` (simba's `simd_max`), so a NaN is dropped first, not last.
    pub fn amax(&self) -> f64 {
        let mut a = self.x.abs();
        for b in [self.y, self.z] {
            let b = b.abs();
            a = if a >= b { a } else { b };
        }
        a
    }

    /// The smallest |component|: the running value is kept where `a <= b`
    /// (simba's `simd_min`).
    pub fn amin(&self) -> f64 {
        let mut a = self.x.abs();
        for b in [self.y, self.z] {
            let b = b.abs();
            a = if a <= b { a } else { b };
        }
        a
    }

    /// The index of the first component of largest |value| (a later one
    /// wins only if strictly larger; a NaN never wins and, first, never loses).
    pub fn iamax(&self) -> usize {
        let mut the_max = self.x.abs();
        let mut the_i = 0;
        for (i, v) in [(1, self.y), (2, self.z)] {
            let val = v.abs();
            if val > the_max {
                the_max = val;
                the_i = i;
            }
        }
        the_i
    }

    pub fn component_mul(&self, rhs: &Self) -> Self {
        Vector3::new(self.x * rhs.x, self.y * rhs.y, self.z * rhs.z)
    }

    /// The matrix [v]× with [v]× w = v × w.
    pub fn cross_matrix(&self) -> Matrix3<f64> {
        Matrix3::new(
            0.0, -self.z, self.y, //
            self.z, 0.0, -self.x, //
            -self.y, self.x, 0.0,
        )
    }
}

impl<T> Index<usize> for Vector3<T> {
    type Output = T;
    fn index(&self, i: usize) -> &T {
        match i {
            0 => &self.x,
            1 => &self.y,
            2 => &self.z,
            _ => panic!("Vector3 index {i} out of range 0..3"),
        }
    }
}

impl<T> IndexMut<usize> for Vector3<T> {
    fn index_mut(&mut self, i: usize) -> &mut T {
        match i {
            0 => &mut self.x,
            1 => &mut self.y,
            2 => &mut self.z,
            _ => panic!("Vector3 index {i} out of range 0..3"),
        }
    }
}

impl<T> From<[T; 3]> for Vector3<T> {
    fn from([x, y, z]: [T; 3]) -> Self {
        Vector3 { x, y, z }
    }
}

impl<T> From<Vector3<T>> for [T; 3] {
    fn from(v: Vector3<T>) -> Self {
        [v.x, v.y, v.z]
    }
}

impl Add for Vector3<f64> {
    type Output = Self;
    fn add(self, r: Self) -> Self {
        Vector3::new(self.x + r.x, self.y + r.y, self.z + r.z)
    }
}

impl Sub for Vector3<f64> {
    type Output = Self;
    fn sub(self, r: Self) -> Self {
        Vector3::new(self.x - r.x, self.y - r.y, self.z - r.z)
    }
}

impl Neg for Vector3<f64> {
    type Output = Self;
    fn neg(self) -> Self {
        Vector3::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for Vector3<f64> {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        self.map(|e| e * s)
    }
}

/// `s * v` multiplies each component by s on its right, as nalgebra does.
impl Mul<Vector3<f64>> for f64 {
    type Output = Vector3<f64>;
    fn mul(self, v: Vector3<f64>) -> Vector3<f64> {
        v.map(|e| e * self)
    }
}

impl Div<f64> for Vector3<f64> {
    type Output = Self;
    fn div(self, s: f64) -> Self {
        self.map(|e| e / s)
    }
}

impl AddAssign for Vector3<f64> {
    fn add_assign(&mut self, r: Self) {
        *self = *self + r;
    }
}

impl SubAssign for Vector3<f64> {
    fn sub_assign(&mut self, r: Self) {
        *self = *self - r;
    }
}

impl MulAssign<f64> for Vector3<f64> {
    fn mul_assign(&mut self, s: f64) {
        *self = *self * s;
    }
}

impl DivAssign<f64> for Vector3<f64> {
    fn div_assign(&mut self, s: f64) {
        *self = *self / s;
    }
}

/// The outer product v wᵀ: entry (i, j) is v_i·w_j.
impl Mul<RowVector3<f64>> for Vector3<f64> {
    type Output = Matrix3<f64>;
    fn mul(self, w: RowVector3<f64>) -> Matrix3<f64> {
        let v = self.as_array();
        let w = [w.x, w.y, w.z];
        Matrix3::from_fn(|i, j| v[i] * w[j])
    }
}

impl<T: Copy> Matrix3<T> {
    /// From nine entries by row, as nalgebra's `Matrix3::new`.
    #[allow(clippy::too_many_arguments)]
    pub const fn new(
        m00: T,
        m01: T,
        m02: T,
        m10: T,
        m11: T,
        m12: T,
        m20: T,
        m21: T,
        m22: T,
    ) -> Self {
        Matrix3 {
            cols: [[m00, m10, m20], [m01, m11, m21], [m02, m12, m22]],
        }
    }

    /// Entry (i, j) is `f(i, j)`, called column by column.
    pub fn from_fn(mut f: impl FnMut(usize, usize) -> T) -> Self {
        let c0 = [f(0, 0), f(1, 0), f(2, 0)];
        let c1 = [f(0, 1), f(1, 1), f(2, 1)];
        let c2 = [f(0, 2), f(1, 2), f(2, 2)];
        Matrix3 { cols: [c0, c1, c2] }
    }

    pub fn column(&self, j: usize) -> Vector3<T> {
        Vector3::from(self.cols[j])
    }

    pub fn transpose(&self) -> Self {
        Matrix3::from_fn(|i, j| self.cols[i][j])
    }

    /// Each entry mapped, column by column.
    pub fn map<U: Copy>(&self, mut f: impl FnMut(T) -> U) -> Matrix3<U> {
        Matrix3::from_fn(|i, j| f(self.cols[j][i]))
    }

    /// The entries column by column.
    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.cols.iter().flatten()
    }

    /// The entries by column as one slice.
    pub fn as_slice(&self) -> &[T] {
        self.cols.as_flattened()
    }
}

impl Matrix3<f64> {
    pub const fn zeros() -> Self {
        Matrix3 {
            cols: [[0.0; 3]; 3],
        }
    }

    pub const fn identity() -> Self {
        Matrix3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    }

    pub fn from_diagonal(d: &Vector3<f64>) -> Self {
        let mut m = Self::zeros();
        m.cols[0][0] = d.x;
        m.cols[1][1] = d.y;
        m.cols[2][2] = d.z;
        m
    }

    /// +0.0 + m00 + m11 + m22, in that order (so a −0.0 diagonal gives +0.0).
    pub fn trace(&self) -> f64 {
        let mut res = 0.0;
        for i in 0..3 {
            res += self.cols[i][i];
        }
        res
    }

    /// The cofactor expansion along the first row, nalgebra's for 3×3.
    pub fn determinant(&self) -> f64 {
        let m = |i: usize, j: usize| self.cols[j][i];
        let minor_12_23 = m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2);
        let minor_11_23 = m(1, 0) * m(2, 2) - m(2, 0) * m(1, 2);
        let minor_11_22 = m(1, 0) * m(2, 1) - m(2, 0) * m(1, 1);
        m(0, 0) * minor_12_23 - m(0, 1) * minor_11_23 + m(0, 2) * minor_11_22
    }

    /// The Frobenius norm²: +0.0, then each column's dot product with itself.
    pub fn norm_squared(&self) -> f64 {
        let mut res = 0.0;
        for j in 0..3 {
            let c = self.column(j);
            res += c.dot(&c);
        }
        res
    }

    pub fn norm(&self) -> f64 {
        self.norm_squared().sqrt()
    }

    /// The largest |entry|, column by column, by `Vector3::amax`'s rule.
    pub fn amax(&self) -> f64 {
        let mut it = self.iter();
        let mut a = it.next().map_or(0.0, |e| e.abs());
        for b in it {
            let b = b.abs();
            a = if a >= b { a } else { b };
        }
        a
    }

    /// A·x as nalgebra's gemv: y = A₀x₀, then y += Aⱼxⱼ for j = 1, 2
    /// (nalgebra writes Aⱼxⱼ + y: addition commutes, to the bit).
    fn mul_vec(&self, x: &[f64; 3]) -> [f64; 3] {
        let mut y = self.cols[0].map(|a| a * x[0]);
        for (c, xj) in self.cols.iter().zip(x).skip(1) {
            for (yi, a) in y.iter_mut().zip(c) {
                *yi += a * xj;
            }
        }
        y
    }
}

impl<T> Index<(usize, usize)> for Matrix3<T> {
    type Output = T;
    fn index(&self, (i, j): (usize, usize)) -> &T {
        &self.cols[j][i]
    }
}

impl<T> IndexMut<(usize, usize)> for Matrix3<T> {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut T {
        &mut self.cols[j][i]
    }
}

impl Add for Matrix3<f64> {
    type Output = Self;
    fn add(self, r: Self) -> Self {
        Matrix3::from_fn(|i, j| self.cols[j][i] + r.cols[j][i])
    }
}

impl Sub for Matrix3<f64> {
    type Output = Self;
    fn sub(self, r: Self) -> Self {
        Matrix3::from_fn(|i, j| self.cols[j][i] - r.cols[j][i])
    }
}

impl Neg for Matrix3<f64> {
    type Output = Self;
    fn neg(self) -> Self {
        self.map(|e| -e)
    }
}

impl Mul<f64> for Matrix3<f64> {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        self.map(|e| e * s)
    }
}

impl Mul<Matrix3<f64>> for f64 {
    type Output = Matrix3<f64>;
    fn mul(self, m: Matrix3<f64>) -> Matrix3<f64> {
        m.map(|e| e * self)
    }
}

impl Div<f64> for Matrix3<f64> {
    type Output = Self;
    fn div(self, s: f64) -> Self {
        self.map(|e| e / s)
    }
}

impl AddAssign for Matrix3<f64> {
    fn add_assign(&mut self, r: Self) {
        *self = *self + r;
    }
}

impl SubAssign for Matrix3<f64> {
    fn sub_assign(&mut self, r: Self) {
        *self = *self - r;
    }
}

impl MulAssign<f64> for Matrix3<f64> {
    fn mul_assign(&mut self, s: f64) {
        *self = *self * s;
    }
}

impl Mul<Vector3<f64>> for Matrix3<f64> {
    type Output = Vector3<f64>;
    fn mul(self, v: Vector3<f64>) -> Vector3<f64> {
        Vector3::from(self.mul_vec(&v.as_array()))
    }
}

/// A·B column by column: column j of the product is A·(column j of B).
impl Mul for Matrix3<f64> {
    type Output = Self;
    fn mul(self, b: Self) -> Self {
        Matrix3 {
            cols: b.cols.map(|c| self.mul_vec(&c)),
        }
    }
}

/// uᵀA, a row, as nalgebra's gemm: entry j is (u₀A₀ⱼ + u₁A₁ⱼ) + u₂A₂ⱼ.
impl Mul<Matrix3<f64>> for RowVector3<f64> {
    type Output = RowVector3<f64>;
    fn mul(self, a: Matrix3<f64>) -> RowVector3<f64> {
        let [x, y, z] = a.cols.map(|c| {
            let mut s = self.x * c[0];
            s += self.y * c[1];
            self.z * c[2] + s
        });
        RowVector3 { x, y, z }
    }
}

/// A 1×1 matrix: what a row times a column gives, read as `[(0, 0)]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrix1<T>(pub T);

impl<T> Index<(usize, usize)> for Matrix1<T> {
    type Output = T;
    fn index(&self, (i, j): (usize, usize)) -> &T {
        assert!((i, j) == (0, 0), "Matrix1 index ({i}, {j}) out of range");
        &self.0
    }
}

/// uᵀv as nalgebra's gemm: (u₀v₀ + u₁v₁) + u₂v₂.
impl Mul<Vector3<f64>> for RowVector3<f64> {
    type Output = Matrix1<f64>;
    fn mul(self, v: Vector3<f64>) -> Matrix1<f64> {
        let mut s = self.x * v.x;
        s += self.y * v.y;
        Matrix1(self.z * v.z + s)
    }
}

/// `&a op b`, `a op &b` and `&a op &b`, each the owned operation.
macro_rules! by_reference {
    ($($Trait:ident $method:ident: $L:ty, $R:ty;)*) => {$(
        impl $Trait<$R> for &$L {
            type Output = <$L as $Trait<$R>>::Output;
            fn $method(self, r: $R) -> Self::Output {
                (*self).$method(r)
            }
        }
        impl $Trait<&$R> for $L {
            type Output = <$L as $Trait<$R>>::Output;
            fn $method(self, r: &$R) -> Self::Output {
                self.$method(*r)
            }
        }
        impl $Trait<&$R> for &$L {
            type Output = <$L as $Trait<$R>>::Output;
            fn $method(self, r: &$R) -> Self::Output {
                (*self).$method(*r)
            }
        }
    )*};
}

by_reference! {
    Add add: Vector3<f64>, Vector3<f64>;
    Sub sub: Vector3<f64>, Vector3<f64>;
    Mul mul: Vector3<f64>, f64;
    Div div: Vector3<f64>, f64;
    Mul mul: f64, Vector3<f64>;
    Add add: Matrix3<f64>, Matrix3<f64>;
    Sub sub: Matrix3<f64>, Matrix3<f64>;
    Mul mul: Matrix3<f64>, f64;
    Div div: Matrix3<f64>, f64;
    Mul mul: f64, Matrix3<f64>;
    Mul mul: Matrix3<f64>, Vector3<f64>;
    Mul mul: Matrix3<f64>, Matrix3<f64>;
    Mul mul: Vector3<f64>, RowVector3<f64>;
    Mul mul: RowVector3<f64>, Matrix3<f64>;
    Mul mul: RowVector3<f64>, Vector3<f64>;
}

impl Neg for &Vector3<f64> {
    type Output = Vector3<f64>;
    fn neg(self) -> Vector3<f64> {
        -*self
    }
}

impl Neg for &Matrix3<f64> {
    type Output = Matrix3<f64>;
    fn neg(self) -> Matrix3<f64> {
        -*self
    }
}

/// +0 plus each vector in turn, as nalgebra sums.
impl std::iter::Sum for Vector3<f64> {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::zeros(), |acc, v| acc + v)
    }
}

impl std::iter::Sum for Matrix3<f64> {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::zeros(), |acc, m| acc + m)
    }
}
