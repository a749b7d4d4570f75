//! `weld`: corners closer than a given distance merged, opt in (a part's
//! `weld` key; never by default), and what the merge can change in the
//! integrals, added to their bounds.
//!
//! Each vertex, in order, joins the first earlier vertex that kept its
//! place (a representative) closer than d, found in a grid of cells of
//! side d; else it keeps its place. So a moved corner moves less than d,
//! to a corner of the file.
//!
//! The bound: every sum of `Sums` (w, w s, w (aaᵀ + bbᵀ + ccᵀ + ssᵀ), the
//! offsets a, b, c of a triangle's corners from the reference point p) is
//! a polynomial f in the corners' coordinates, and `Sums::add`'s magnitude
//! of it is a polynomial P with nonnegative coefficients no less than the
//! absolute values of f's. For corners x moved by Δ (|Δₖ| ≤ εₖ per
//! coordinate), each monomial changes by at most Π(|xₖ| + εₖ) − Π|xₖ|, so
//! |f(x + Δ) − f(x)| ≤ P(|x| + ε) − P(|x|), and that is increasing in |x|:
//! it holds with |x| taken from above. Summed over the triangles with a
//! moved corner (before any is left out for zero area), it bounds how far
//! the welded mesh's sums are from the file's own corners' sums about the
//! same p, and `finish` carries it into the measure, centroid and second
//! moment as it does the roundings.

use super::check::Mesh;
use std::collections::HashMap;

/// What a weld did: the corners merged and the bound of the change of each
/// of the ten sums (`Sums::moved`).
pub struct Welded {
    pub merged: usize,
    pub moved: [f64; 10],
}

impl Mesh {
    /// The mesh with corners closer than `d` (> 0) merged (module comment).
    pub fn weld_within(self, d: f64) -> (Mesh, Welded) {
        let v = &self.vertices;
        let cell = |p: &[f64; 3]| p.map(|x| (x / d).floor() as i64);
        let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut rep: Vec<u32> = Vec::with_capacity(v.len());
        let d2 = d * d;
        for (i, p) in v.iter().enumerate() {
            let c = cell(p);
            let mut found: Option<u32> = None;
            for dx in -1..=1i64 {
                for dy in -1..=1i64 {
                    for dz in -1..=1i64 {
                        let k = [
                            c[0].saturating_add(dx),
                            c[1].saturating_add(dy),
                            c[2].saturating_add(dz),
                        ];
                        for &r in grid.get(&k).map_or(&[][..], Vec::as_slice) {
                            let q = v[r as usize];
                            let dist2: f64 = (0..3).map(|k| (p[k] - q[k]) * (p[k] - q[k])).sum();
                            if dist2 < d2 && found.is_none_or(|f| r < f) {
                                found = Some(r);
                            }
                        }
                    }
                }
            }
            match found {
                Some(r) => rep.push(r),
                None => {
                    grid.entry(c).or_default().push(i as u32);
                    rep.push(i as u32);
                }
            }
        }
        let merged = rep
            .iter()
            .enumerate()
            .filter(|(i, r)| **r != *i as u32)
            .count();
        let mut number = vec![u32::MAX; v.len()];
        let mut vertices = Vec::new();
        for (i, r) in rep.iter().enumerate() {
            if *r == i as u32 {
                number[i] = vertices.len() as u32;
                vertices.push(v[i]);
            }
        }
        let faces: Vec<[u32; 3]> = self
            .faces
            .iter()
            .map(|f| f.map(|k| number[rep[k as usize] as usize]))
            .collect();
        let welded = Mesh::new(vertices, faces, self.at.clone());
        let p = welded.reference();
        let up = |x: f64| x * (1.0 + f64::EPSILON);
        let mut moved = [0.0f64; 10];
        let mut n = 0usize;
        for f in &self.faces {
            if f.iter().all(|k| rep[*k as usize] == *k) {
                continue;
            }
            n += 1;
            let to = f.map(|k| v[rep[k as usize] as usize]);
            let from = f.map(|k| v[k as usize]);
            let y: [[f64; 3]; 3] = to.map(|c| std::array::from_fn(|k| up((c[k] - p[k]).abs())));
            let e: [[f64; 3]; 3] =
                std::array::from_fn(|j| std::array::from_fn(|k| up((from[j][k] - to[j][k]).abs())));
            let ye: [[f64; 3]; 3] =
                std::array::from_fn(|j| std::array::from_fn(|k| up(y[j][k] + e[j][k])));
            let (hi, lo) = (magnitudes(ye), magnitudes(y));
            for k in 0..10 {
                moved[k] += hi[k] * (1.0 + 1e-12) - lo[k] * (1.0 - 1e-12);
            }
        }
        // The recursive sums' roundings, all terms nonnegative.
        let grow = 1.0 + 2.0 * (n as f64 + 1.0) * f64::EPSILON;
        (
            welded,
            Welded {
                merged,
                moved: moved.map(|m| m * grow),
            },
        )
    }
}

/// `Sums::add`'s magnitudes of a solid's ten terms for corner magnitudes
/// `y` (nonnegative).
fn magnitudes([a, b, c]: [[f64; 3]; 3]) -> [f64; 10] {
    let x = [
        b[1] * c[2] + b[2] * c[1],
        b[2] * c[0] + b[0] * c[2],
        b[0] * c[1] + b[1] * c[0],
    ];
    let w = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    let s: [f64; 3] = std::array::from_fn(|i| a[i] + b[i] + c[i]);
    let mut m = [0.0; 10];
    m[0] = w;
    for i in 0..3 {
        m[1 + i] = w * s[i];
    }
    for (k, &(i, j)) in super::PAIRS.iter().enumerate() {
        m[4 + k] = w * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
    }
    m
}
