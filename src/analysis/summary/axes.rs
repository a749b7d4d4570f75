//! The report axes (`[analysis] axes`, `--axes`): the change from the
//! file's axes to them, A = Rᵀ (its rows are the report axes in the file's
//! frame), applied to the composed second moments and vectors, and the
//! error bound it adds.
//!
//! A tensor is turned as A C Aᵀ in double-double, a vector as A v. A signed
//! permutation (quarter turns, the SAE and ISO vehicle axes) has entries 0
//! and ±1: every product is exact and every sum adds zeros, so the entries
//! are moved and negated exactly and the bounds with them. Any other turn
//! adds its matrix's own error (`part::error::turn_error`, units of the
//! arithmetic it is formed in) and the products' roundings.

use crate::compose::Precision;
use crate::numeric::{DD, M3, Real};
use crate::part::error::{TURN, U_DD, U64, turn_error};
use crate::rotation::Orientation;

/// The change of axes, formed in the precision of the composition.
#[derive(Debug, Clone)]
pub struct Turn {
    a: M3<DD>,
    /// A rounded to f64, for the output (`axes`) and the bounds.
    pub rows: M3<f64>,
    /// Units of error per entry of the product beyond the bounds carried
    /// in: 0 for a signed permutation.
    units: f64,
}

impl Turn {
    pub fn new(o: &Orientation, precision: Precision) -> Turn {
        let (r, unit): (M3<DD>, f64) = match precision {
            Precision::Standard => (o.matrix::<f64>().map(|r| r.map(DD::of)), U64),
            Precision::Extended => (o.matrix::<DD>(), U_DD),
        };
        let a: M3<DD> = std::array::from_fn(|i| std::array::from_fn(|j| r[j][i]));
        let rows = a.map(|r| r.map(DD::f64));
        let rho = turn_error(o, &rows);
        // The matrix's own error enters twice (A C Aᵀ), plus its square; the
        // two products of three terms each round in double-double.
        let units = if rho == 0.0 {
            0.0
        } else {
            (2.0 * rho + 1.0) * unit + 2.0 * TURN * U_DD
        };
        Turn { a, rows, units }
    }

    /// A C Aᵀ.
    pub fn tensor(&self, c: &M3<DD>) -> M3<DD> {
        let a = &self.a;
        let ac: M3<DD> = std::array::from_fn(|i| {
            std::array::from_fn(|k| (0..3).fold(DD::of(0.0), |s, j| s + a[i][j] * c[j][k]))
        });
        std::array::from_fn(|i| {
            std::array::from_fn(|l| (0..3).fold(DD::of(0.0), |s, k| s + ac[i][k] * a[l][k]))
        })
    }

    /// A v.
    pub fn vector(&self, v: &[DD; 3]) -> [DD; 3] {
        std::array::from_fn(|i| (0..3).fold(DD::of(0.0), |s, j| s + self.a[i][j] * v[j]))
    }

    /// The bound of A C Aᵀ from the bound `e` of C (entrywise) and C's
    /// magnitude: |A| e |A|ᵀ, and the turn's own error on Σ|C|.
    pub fn tensor_bound(&self, e: &M3<f64>, c: &M3<f64>) -> M3<f64> {
        let a = self.rows.map(|r| r.map(f64::abs));
        let spread: f64 = c.iter().flatten().map(|x| x.abs()).sum();
        std::array::from_fn(|i| {
            std::array::from_fn(|l| {
                let carried: f64 = (0..3)
                    .flat_map(|j| (0..3).map(move |k| (j, k)))
                    .map(|(j, k)| a[i][j] * e[j][k] * a[l][k])
                    .sum();
                // |A| ≤ 1 + ρu entrywise: a hair above the rounding; the
                // factor covers it and the sum's own rounding.
                (carried * (1.0 + 8.0 * U64)) + self.units * spread
            })
        })
    }

    /// The bound of A v from the bound `e` of v and v's magnitude.
    pub fn vector_bound(&self, e: &[f64; 3], v: &[f64; 3]) -> [f64; 3] {
        let spread: f64 = v.iter().map(|x| x.abs()).sum();
        std::array::from_fn(|i| {
            let carried: f64 = (0..3).map(|j| self.rows[i][j].abs() * e[j]).sum();
            carried * (1.0 + 8.0 * U64) + self.units * spread
        })
    }
}
