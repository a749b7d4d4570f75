//! massprop's own `Vector3` and `Matrix3` (src/la.rs) held to nalgebra's,
//! which they replace, bit for bit: every operation massprop uses, on
//! random and adversarial f64 (±0, subnormals, values whose squares
//! overflow or underflow, ±∞, NaNs with payloads and signs, any bit
//! pattern at all), compared by `to_bits`, so a changed operation order,
//! a lost −0.0 or a different NaN is a failure. nalgebra is a
//! dev-dependency for this alone.
//!
//! Each property's expression is written once and evaluated twice, on
//! massprop's types and on nalgebra's (`same!`); where the two spell a
//! constructor differently, both spellings are given (`pin!`).
//! Deterministic: a fixed ChaCha seed, no persistence.

// The `by_reference` properties take references on purpose: they pin the
// operators on `&Vector3` and `&Matrix3` that massprop's code calls.
#![allow(clippy::op_ref)]

use massprop::la::{Matrix3, Vector3};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed};

/// Cases per property: each is a handful of flops.
const CASES: u32 = 1000;

fn config() -> Config {
    Config {
        cases: CASES,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(0x1a_0035),
        ..Config::default()
    }
}

/// Values where an operation's order, a sign of zero or a NaN's payload
/// shows: ±0, the smallest subnormal and normal, values whose squares
/// underflow or overflow, the largest finite, ±∞, NaNs of either sign
/// and two payloads, and ordinary numbers that cancel.
const ADVERSARIAL: [f64; 24] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.1,
    -3.0,
    5e-324,
    -5e-324,
    f64::MIN_POSITIVE,
    -f64::MIN_POSITIVE,
    1.1e-308,
    1e-170,
    -1e-160,
    1e155,
    -1.3e154,
    1e308,
    f64::MAX,
    f64::MIN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    -f64::NAN,
    // Quiet NaNs with payloads: which operand's NaN survives shows.
    f64::from_bits(0x7ff8_0000_0000_0001),
    f64::from_bits(0xfff8_0000_dead_beef),
];

/// An f64 of any kind: every class proptest knows (subnormal, ±∞, quiet
/// NaNs with random payloads), the adversarial list, ordinary numbers
/// that cancel and round, and any bit pattern (signalling NaNs too).
fn real() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => any::<f64>(),
        3 => proptest::sample::select(ADVERSARIAL.to_vec()),
        3 => -10.0..10.0f64,
        1 => any::<u64>().prop_map(f64::from_bits),
    ]
}

/// ±0 and ±1 alone: often enough that every entry a sum adds is −0.0
/// (where a sum started from +0.0 differs from one started from its
/// first term) or that terms cancel exactly.
fn small() -> impl Strategy<Value = f64> {
    proptest::sample::select(vec![0.0, -0.0, 1.0, -1.0])
}

fn vec3() -> impl Strategy<Value = Vector3<f64>> {
    prop_oneof![
        3 => [real(), real(), real()].prop_map(Vector3::from),
        1 => [small(), small(), small()].prop_map(Vector3::from),
    ]
}

fn mat3() -> impl Strategy<Value = Matrix3<f64>> {
    prop_oneof![
        3 => proptest::array::uniform9(real()),
        1 => proptest::array::uniform9(small()),
    ]
    .prop_map(|e| Matrix3::from_fn(|i, j| e[3 * i + j]))
}

fn index() -> impl Strategy<Value = usize> {
    0..3usize
}

/// A value of massprop's as its nalgebra counterpart.
trait Na {
    type Out;
    fn na(&self) -> Self::Out;
}

impl Na for f64 {
    type Out = f64;
    fn na(&self) -> f64 {
        *self
    }
}

impl Na for usize {
    type Out = usize;
    fn na(&self) -> usize {
        *self
    }
}

impl Na for Vector3<f64> {
    type Out = nalgebra::Vector3<f64>;
    fn na(&self) -> Self::Out {
        nalgebra::Vector3::new(self.x, self.y, self.z)
    }
}

impl Na for Matrix3<f64> {
    type Out = nalgebra::Matrix3<f64>;
    fn na(&self) -> Self::Out {
        nalgebra::Matrix3::from_fn(|i, j| self[(i, j)])
    }
}

/// A result's bits, entry by entry (a matrix's column by column, read
/// through `(i, j)`, so storage order is not assumed).
trait Bits {
    fn bits(&self) -> Vec<u64>;
}

impl Bits for f64 {
    fn bits(&self) -> Vec<u64> {
        vec![self.to_bits()]
    }
}

impl Bits for usize {
    fn bits(&self) -> Vec<u64> {
        vec![*self as u64]
    }
}

impl Bits for Vec<f64> {
    fn bits(&self) -> Vec<u64> {
        self.iter().map(|x| x.to_bits()).collect()
    }
}

impl Bits for String {
    fn bits(&self) -> Vec<u64> {
        self.bytes().map(u64::from).collect()
    }
}

impl Bits for Vec<(usize, usize)> {
    fn bits(&self) -> Vec<u64> {
        self.iter()
            .flat_map(|&(i, j)| [i as u64, j as u64])
            .collect()
    }
}

impl Bits for Vector3<f64> {
    fn bits(&self) -> Vec<u64> {
        (0..3).map(|i| self[i].to_bits()).collect()
    }
}

impl Bits for nalgebra::Vector3<f64> {
    fn bits(&self) -> Vec<u64> {
        (0..3).map(|i| self[i].to_bits()).collect()
    }
}

impl Bits for massprop::la::RowVector3<f64> {
    fn bits(&self) -> Vec<u64> {
        [self.x, self.y, self.z].bits()
    }
}

impl Bits for nalgebra::RowVector3<f64> {
    fn bits(&self) -> Vec<u64> {
        (0..3).map(|j| self[(0, j)].to_bits()).collect()
    }
}

impl Bits for Matrix3<f64> {
    fn bits(&self) -> Vec<u64> {
        (0..9).map(|k| self[(k % 3, k / 3)].to_bits()).collect()
    }
}

impl Bits for nalgebra::Matrix3<f64> {
    fn bits(&self) -> Vec<u64> {
        (0..9).map(|k| self[(k % 3, k / 3)].to_bits()).collect()
    }
}

/// The sum of three, by the type's own `Sum`.
fn total<T: std::iter::Sum<T>>(xs: [T; 3]) -> T {
    xs.into_iter().sum()
}

/// Entries' bits as hex, for a failure's message; every NaN as `NaN`.
///
/// NOTE: a NaN is matched by a NaN, not by its bits: where an operation
/// meets a NaN, Rust leaves the result's sign and payload unspecified
/// (which operand's NaN, or a fresh one; RFC 3514), and LLVM may swap the
/// operands of `a + b`, so even nalgebra against itself, compiled twice,
/// need not agree on them. Every other value, ±0 and ±∞ included, must
/// agree to the bit.
fn hex(b: &[u64]) -> Vec<String> {
    b.iter()
        .map(|&x| {
            if f64::from_bits(x).is_nan() {
                "NaN".to_string()
            } else {
                format!("{x:#018x}")
            }
        })
        .collect()
}

/// `name(args) = ours, theirs;`: a property that massprop's expression
/// on the generated values has the bits of nalgebra's on the same values
/// (rebound to nalgebra's types before `theirs`).
macro_rules! pin {
    ($($(#[$doc:meta])* $name:ident($($arg:ident in $s:expr),*) = $ours:expr, $theirs:expr;)*) => {
        proptest! {
            #![proptest_config(config())]
            $(
                $(#[$doc])*
                #[test]
                #[allow(unused_variables)]
                fn $name($($arg in $s),*) {
                    let input = ($($arg,)*);
                    let ours = Bits::bits(&$ours);
                    let theirs = {
                        $(let $arg = Na::na(&$arg);)*
                        Bits::bits(&$theirs)
                    };
                    prop_assert_eq!(hex(&ours), hex(&theirs), "input {:?}", input);
                }
            )*
        }
    };
}

/// `name(args) = expr;`: `pin!` with one expression for both types.
macro_rules! same {
    ($($(#[$doc:meta])* $name:ident($($arg:ident in $s:expr),*) = $e:expr;)*) => {
        pin! { $($(#[$doc])* $name($($arg in $s),*) = $e, $e;)* }
    };
}

same! {
    dot_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a.dot(&b);
    cross_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a.cross(&b);
    vector_norm_squared_is_nalgebras_bit_for_bit(a in vec3()) = a.norm_squared();
    vector_norm_is_nalgebras_bit_for_bit(a in vec3()) = a.norm();
    normalize_is_nalgebras_bit_for_bit(a in vec3()) = a.normalize();
    vector_amax_is_nalgebras_bit_for_bit(a in vec3()) = a.amax();
    amin_is_nalgebras_bit_for_bit(a in vec3()) = a.amin();
    iamax_is_nalgebras_index(a in vec3()) = a.iamax();
    component_mul_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a.component_mul(&b);
    cross_matrix_is_nalgebras_bit_for_bit(a in vec3()) = a.cross_matrix();
    vector_index_reads_nalgebras_component(a in vec3(), i in index()) = a[i];
    vector_iter_visits_nalgebras_order(a in vec3()) = a.iter().copied().collect::<Vec<f64>>();
    vector_map_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = a.map(|e| e * s - s);
    vector_into_array_is_nalgebras(a in vec3()) = Into::<[f64; 3]>::into(a);
    vector_debug_prints_as_nalgebras(a in vec3()) = format!("{a:?}");
    vector_sum_is_nalgebras_bit_for_bit(a in vec3(), b in vec3(), c in vec3()) = total([a, b, c]);
    vector_add_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a + b;
    vector_sub_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a - b;
    vector_neg_is_nalgebras_bit_for_bit(a in vec3()) = -a;
    vector_times_scalar_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = a * s;
    scalar_times_vector_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = s * a;
    vector_over_scalar_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = a / s;
    vector_by_reference_is_nalgebras_bit_for_bit(a in vec3(), b in vec3(), s in real()) =
        &(&a - &b) * s + &a * (s / 2.0);
    vector_add_assign_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = {
        let mut a = a;
        a += b;
        a
    };
    vector_sub_assign_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = {
        let mut a = a;
        a -= b;
        a
    };
    vector_mul_assign_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = {
        let mut a = a;
        a *= s;
        a
    };
    vector_div_assign_is_nalgebras_bit_for_bit(a in vec3(), s in real()) = {
        let mut a = a;
        a /= s;
        a
    };
    outer_product_is_nalgebras_bit_for_bit(a in vec3(), b in vec3()) = a * b.transpose();
    row_times_matrix_is_nalgebras_bit_for_bit(a in vec3(), m in mat3()) = a.transpose() * m;
    quadratic_form_is_nalgebras_bit_for_bit(a in vec3(), m in mat3(), b in vec3()) =
        (a.transpose() * m * b)[(0, 0)];
    matrix_times_vector_is_nalgebras_bit_for_bit(m in mat3(), a in vec3()) = m * a;
    matrix_times_matrix_is_nalgebras_bit_for_bit(m in mat3(), n in mat3()) = m * n;
    matrix_products_by_reference_are_nalgebras(m in mat3(), n in mat3(), a in vec3()) =
        &(&m * &n) * &a;
    transpose_is_nalgebras(m in mat3()) = m.transpose();
    trace_is_nalgebras_bit_for_bit(m in mat3()) = m.trace();
    determinant_is_nalgebras_bit_for_bit(m in mat3()) = m.determinant();
    matrix_norm_squared_is_nalgebras_bit_for_bit(m in mat3()) = m.norm_squared();
    matrix_norm_is_nalgebras_bit_for_bit(m in mat3()) = m.norm();
    matrix_amax_is_nalgebras_bit_for_bit(m in mat3()) = m.amax();
    matrix_map_is_nalgebras_bit_for_bit(m in mat3(), s in real()) = m.map(|e| e * s - s);
    matrix_iter_visits_nalgebras_order(m in mat3()) = m.iter().copied().collect::<Vec<f64>>();
    matrix_as_slice_is_nalgebras_order(m in mat3()) = m.as_slice().to_vec();
    matrix_debug_prints_as_nalgebras(m in mat3()) = format!("{m:?}");
    matrix_index_reads_nalgebras_entry(m in mat3(), i in index(), j in index()) = m[(i, j)];
    matrix_sum_is_nalgebras_bit_for_bit(m in mat3(), n in mat3(), o in mat3()) = total([m, n, o]);
    matrix_add_is_nalgebras_bit_for_bit(m in mat3(), n in mat3()) = m + n;
    matrix_sub_is_nalgebras_bit_for_bit(m in mat3(), n in mat3()) = m - n;
    matrix_neg_is_nalgebras_bit_for_bit(m in mat3()) = -m;
    matrix_times_scalar_is_nalgebras_bit_for_bit(m in mat3(), s in real()) = m * s;
    scalar_times_matrix_is_nalgebras_bit_for_bit(m in mat3(), s in real()) = s * m;
    matrix_over_scalar_is_nalgebras_bit_for_bit(m in mat3(), s in real()) = m / s;
    matrix_by_reference_is_nalgebras_bit_for_bit(m in mat3(), n in mat3(), s in real()) =
        &(&(&m + &n) - &m) * s + -&n;
    matrix_add_assign_is_nalgebras_bit_for_bit(m in mat3(), n in mat3()) = {
        let mut m = m;
        m += n;
        m
    };
    matrix_sub_assign_is_nalgebras_bit_for_bit(m in mat3(), n in mat3()) = {
        let mut m = m;
        m -= n;
        m
    };
    matrix_mul_assign_is_nalgebras_bit_for_bit(m in mat3(), s in real()) = {
        let mut m = m;
        m *= s;
        m
    };
}

pin! {
    column_is_nalgebras(m in mat3(), j in index()) =
        m.column(j), m.column(j).into_owned();
    vector_from_fn_calls_as_nalgebra_does(a in vec3()) =
        {
            let mut calls = Vec::new();
            let v = Vector3::from_fn(|i, j| {
                calls.push((i, j));
                a[i]
            });
            (calls, v)
        },
        {
            let mut calls = Vec::new();
            let v = nalgebra::Vector3::from_fn(|i, j| {
                calls.push((i, j));
                a[i]
            });
            (calls, v)
        };
    matrix_from_fn_calls_as_nalgebra_does(m in mat3()) =
        {
            let mut calls = Vec::new();
            let n = Matrix3::from_fn(|i, j| {
                calls.push((i, j));
                m[(i, j)]
            });
            (calls, n)
        },
        {
            let mut calls = Vec::new();
            let n = nalgebra::Matrix3::from_fn(|i, j| {
                calls.push((i, j));
                m[(i, j)]
            });
            (calls, n)
        };
    matrix_new_takes_entries_by_row_as_nalgebras(
        a in real(), b in real(), c in real(), d in real(), e in real()
    ) =
        Matrix3::new(a, b, c, d, e, a, b, c, d),
        nalgebra::Matrix3::new(a, b, c, d, e, a, b, c, d);
    vector_from_array_is_nalgebras(a in real(), b in real(), c in real()) =
        Vector3::from([a, b, c]), nalgebra::Vector3::from([a, b, c]);
    ith_is_nalgebras(i in index(), s in real()) =
        Vector3::ith(i, s), nalgebra::Vector3::ith(i, s);
    from_diagonal_is_nalgebras(a in vec3()) =
        Matrix3::from_diagonal(&a), nalgebra::Matrix3::from_diagonal(&a);
    constants_are_nalgebras(s in real()) =
        (
            [Vector3::x(), Vector3::y(), Vector3::z(), Vector3::zeros()],
            [Matrix3::identity(), Matrix3::zeros()],
        ),
        (
            [
                nalgebra::Vector3::x(),
                nalgebra::Vector3::y(),
                nalgebra::Vector3::z(),
                nalgebra::Vector3::zeros(),
            ],
            [nalgebra::Matrix3::identity(), nalgebra::Matrix3::zeros()],
        );
}

impl<A: Bits, B: Bits> Bits for (A, B) {
    fn bits(&self) -> Vec<u64> {
        let mut b = self.0.bits();
        b.extend(self.1.bits());
        b
    }
}

impl<T: Bits, const N: usize> Bits for [T; N] {
    fn bits(&self) -> Vec<u64> {
        self.iter().flat_map(Bits::bits).collect()
    }
}
