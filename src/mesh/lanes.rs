//! A solid's double-double sums (`Sums::<DD>::add`, `Mode::Solid`) for
//! `LANES` triangles at a time, written out so that the compiler can keep
//! the triangles in the lanes of its vector registers: the same operations
//! in the same order on each triangle as `Sums::add` (so the same bits),
//! the terms then added to the sums triangle by triangle in the file's
//! order (so the same sums).
//!
//! NOTE: `DD`'s operations branch on overflow (a non-finite sum, a product
//! near the top of f64's range, Veltkamp's split of a huge operand), which
//! keeps a loop over triangles from running in lanes. No branch is taken
//! when every coordinate of the mesh (and so every offset from the
//! reference point) is at most `LIMIT` in magnitude: the largest value a
//! term reaches is then below 2³⁴⁰, far from the branches' 2⁹⁹⁶. The mesh
//! is tested once (`fits`); one that does not fit takes `Sums::add`.
//! Without the branches each operation is the one `DD` performs
//! (`numeric::two_sum`, `two_prod`, Dekker's product or the FMA alike), so
//! a term's bits are the generic path's; `tests` pin them against it.

use super::check::Mesh;
use super::{Mode, PAIRS, Sums};
use crate::numeric::{DD, Real};

/// Triangles a block holds.
const LANES: usize = 4;

/// The largest coordinate (magnitude) the lanes take: 2⁶⁰.
const LIMIT: f64 = 1_152_921_504_606_846_976.0;

type V = [f64; LANES];

/// `LANES` double-double numbers.
#[derive(Clone, Copy)]
struct X {
    hi: V,
    lo: V,
}

#[inline(always)]
fn map2<const N: usize>(a: [f64; N], b: [f64; N], f: impl Fn(f64, f64) -> f64) -> [f64; N] {
    std::array::from_fn(|l| f(a[l], b[l]))
}

/// `numeric::two_sum`, lane by lane.
#[inline(always)]
fn two_sum<const N: usize>(a: [f64; N], b: [f64; N]) -> ([f64; N], [f64; N]) {
    let s = map2(a, b, |a, b| a + b);
    let e = std::array::from_fn(|l| {
        let bb = s[l] - a[l];
        (a[l] - (s[l] - bb)) + (b[l] - bb)
    });
    (s, e)
}

/// `numeric`'s fast two-sum, lane by lane.
#[inline(always)]
fn fast_two_sum<const N: usize>(a: [f64; N], b: [f64; N]) -> ([f64; N], [f64; N]) {
    let s = map2(a, b, |a, b| a + b);
    let e = std::array::from_fn(|l| b[l] - (s[l] - a[l]));
    (s, e)
}

/// `numeric::two_prod` where no operand or product exceeds 2⁹⁹⁶.
#[inline(always)]
fn two_prod(a: V, b: V) -> (V, V) {
    let p = map2(a, b, |a, b| a * b);
    let e = std::array::from_fn(|l| {
        if cfg!(target_feature = "fma") {
            return a[l].mul_add(b[l], -p[l]);
        }
        const FACTOR: f64 = 134_217_729.0; // 2²⁷ + 1
        let split = |x: f64| {
            let c = FACTOR * x;
            let hi = c - (c - x);
            (hi, x - hi)
        };
        let (ah, al) = split(a[l]);
        let (bh, bl) = split(b[l]);
        ((ah * bh - p[l]) + ah * bl + al * bh) + al * bl
    });
    (p, e)
}

impl X {
    fn of(hi: V, lo: V) -> X {
        X { hi, lo }
    }

    /// `DD + DD` (finite sums).
    #[inline(always)]
    fn add(self, o: X) -> X {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = fast_two_sum(s, map2(e, t, |e, t| e + t));
        let (hi, lo) = fast_two_sum(s, map2(e, f, |e, f| e + f));
        X { hi, lo }
    }

    /// `DD - DD`: the sum with the negation.
    #[inline(always)]
    fn sub(self, o: X) -> X {
        self.add(X {
            hi: o.hi.map(|x| -x),
            lo: o.lo.map(|x| -x),
        })
    }

    /// `DD * DD` (no branch taken).
    #[inline(always)]
    fn mul(self, o: X) -> X {
        let (p, e) = two_prod(self.hi, o.hi);
        let cross: V = std::array::from_fn(|l| self.hi[l] * o.lo[l] + self.lo[l] * o.hi[l]);
        let (hi, lo) = fast_two_sum(p, map2(e, cross, |e, c| e + c));
        X { hi, lo }
    }

    /// `|x.f64()|`, lane by lane.
    #[inline(always)]
    fn abs(self) -> V {
        map2(self.hi, self.lo, |h, l| (h + l).abs())
    }
}

/// `DD + DD` of N pairs side by side, with its branch (a non-finite sum
/// is that sum and 0) as a choice per pair.
#[inline(always)]
fn add_dd<const N: usize>(
    ahi: [f64; N],
    alo: [f64; N],
    bhi: [f64; N],
    blo: [f64; N],
) -> ([f64; N], [f64; N]) {
    let (s0, e0) = two_sum(ahi, bhi);
    let (t, f) = two_sum(alo, blo);
    let (s, e) = fast_two_sum(s0, map2(e0, t, |e, t| e + t));
    let (hi, lo) = fast_two_sum(s, map2(e, f, |e, f| e + f));
    let pick = |l: usize, x: [f64; N], y: f64| if s0[l].is_finite() { x[l] } else { y };
    (
        std::array::from_fn(|l| pick(l, hi, s0[l])),
        std::array::from_fn(|l| pick(l, lo, 0.0)),
    )
}

fn cross(b: [X; 3], c: [X; 3]) -> [X; 3] {
    [
        b[1].mul(c[2]).sub(b[2].mul(c[1])),
        b[2].mul(c[0]).sub(b[0].mul(c[2])),
        b[0].mul(c[1]).sub(b[1].mul(c[0])),
    ]
}

/// Whether every coordinate of the mesh is within `LIMIT` (then the
/// lanes' arithmetic is `DD`'s).
pub(super) fn fits(vertices: &[[f64; 3]], p: [f64; 3]) -> bool {
    p.iter().all(|x| x.abs() <= LIMIT)
        && vertices.iter().all(|v| v.iter().all(|x| x.abs() <= LIMIT))
}

/// A block's terms: w, w s, w q and their magnitudes, a lane a triangle.
struct Terms {
    value: [X; 10],
    magnitude: [V; 10],
}

/// The terms of `Sums::add` (`Mode::Solid`) for `LANES` triangles, each
/// corner's offset from `p` made as `Mesh::sums_on` makes it.
#[inline(always)]
fn terms(vertices: &[[f64; 3]], faces: &[[u32; 3]; LANES], p: [f64; 3]) -> Terms {
    let zero = [0.0; LANES];
    // DD::of(v) − DD::of(p), per coordinate of each corner.
    let corner = |c: usize| -> [X; 3] {
        std::array::from_fn(|k| {
            let v: V = std::array::from_fn(|l| vertices[faces[l][c] as usize][k]);
            X::of(v, zero).sub(X::of([p[k]; LANES], zero))
        })
    };
    let (a, b, c) = (corner(0), corner(1), corner(2));
    // `volume_term`.
    let x = cross(b, c);
    let w = a[0].mul(x[0]).add(a[1].mul(x[1])).add(a[2].mul(x[2]));
    let (am, bm, cm) = (a.map(X::abs), b.map(X::abs), c.map(X::abs));
    let two = |p: V, q: V, r: V, s: V| -> V { std::array::from_fn(|l| p[l] * q[l] + r[l] * s[l]) };
    let xm = [
        two(bm[1], cm[2], bm[2], cm[1]),
        two(bm[2], cm[0], bm[0], cm[2]),
        two(bm[0], cm[1], bm[1], cm[0]),
    ];
    let wmag: V =
        std::array::from_fn(|l| am[0][l] * xm[0][l] + am[1][l] * xm[1][l] + am[2][l] * xm[2][l]);
    let s: [X; 3] = std::array::from_fn(|i| a[i].add(b[i]).add(c[i]));
    let sm: [V; 3] =
        std::array::from_fn(|i| std::array::from_fn(|l| am[i][l] + bm[i][l] + cm[i][l]));
    let mut value = [w; 10];
    let mut magnitude = [wmag; 10];
    for i in 0..3 {
        value[1 + i] = w.mul(s[i]);
        magnitude[1 + i] = map2(wmag, sm[i], |w, s| w * s);
    }
    for (k, &(i, j)) in PAIRS.iter().enumerate() {
        let q = a[i]
            .mul(a[j])
            .add(b[i].mul(b[j]))
            .add(c[i].mul(c[j]))
            .add(s[i].mul(s[j]));
        let qm: V = std::array::from_fn(|l| {
            am[i][l] * am[j][l] + bm[i][l] * bm[j][l] + cm[i][l] * cm[j][l] + sm[i][l] * sm[j][l]
        });
        value[4 + k] = w.mul(q);
        magnitude[4 + k] = map2(wmag, qm, |w, q| w * q);
    }
    Terms { value, magnitude }
}

/// `Sums::<DD>` of a solid's triangles `faces` about `p`, the same bits as
/// adding each with `Sums::add`; the mesh must `fit`.
pub(super) fn solid_sums(vertices: &[[f64; 3]], faces: &[[u32; 3]], p: [f64; 3]) -> Sums<DD> {
    // The ten sums side by side (hi, lo), each added to as `DD + DD`
    // adds, a triangle after another.
    let (mut hi, mut lo, mut magnitude) = ([0.0; 10], [0.0; 10], [0.0; 10]);
    let blocks = faces.chunks_exact(LANES);
    let rest = blocks.remainder();
    for block in blocks {
        let block: &[[u32; 3]; LANES] = block
            .try_into()
            .expect("invariant: chunks_exact gives blocks of LANES");
        let t = terms(vertices, block, p);
        for l in 0..LANES {
            let th: [f64; 10] = std::array::from_fn(|k| t.value[k].hi[l]);
            let tl: [f64; 10] = std::array::from_fn(|k| t.value[k].lo[l]);
            (hi, lo) = add_dd(hi, lo, th, tl);
            magnitude = map2(
                magnitude,
                std::array::from_fn(|k| t.magnitude[k][l]),
                |m, x| m + x,
            );
        }
    }
    let mut sums = Sums::<DD>::new();
    sums.value = std::array::from_fn(|k| DD::new(hi[k], lo[k]));
    sums.magnitude = magnitude;
    sums.n = faces.len() - rest.len();
    let offset = |v: [f64; 3]| -> [DD; 3] { std::array::from_fn(|k| DD::of(v[k]) - DD::of(p[k])) };
    for f in rest {
        sums.add(Mode::Solid, f.map(|k| offset(vertices[k as usize])));
    }
    sums
}

impl Mesh {
    /// `sums::<DD>`, a solid's by `solid_sums` where the mesh fits: the
    /// same chunks, the same bits.
    pub fn sums_dd(&self, mode: Mode, p: [f64; 3]) -> Sums<DD> {
        match mode {
            Mode::Solid if fits(&self.vertices, p) => self.sums_with(
                super::threads_for(self.faces.len(), super::check::CHUNK),
                |faces| solid_sums(&self.vertices, faces, p),
            ),
            Mode::Solid | Mode::Shell => self.sums::<DD>(mode, p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic generator of coordinates of many magnitudes.
    fn coords(seed: u64, n: usize, scale: f64) -> Vec<[f64; 3]> {
        let mut x = seed | 1;
        let mut r = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        (0..n)
            .map(|_| [r() * scale, r() * scale, r() * scale])
            .collect()
    }

    fn faces(n: usize, verts: usize) -> Vec<[u32; 3]> {
        (0..n)
            .map(|i| {
                let i = i as u32;
                let v = verts as u32;
                [i % v, (i * 7 + 1) % v, (i * 13 + 5) % v]
            })
            .collect()
    }

    fn generic(vertices: &[[f64; 3]], faces: &[[u32; 3]], p: [f64; 3]) -> Sums<DD> {
        let mut sums = Sums::<DD>::new();
        for f in faces {
            sums.add(
                Mode::Solid,
                f.map(|k| std::array::from_fn(|j| DD::of(vertices[k as usize][j]) - DD::of(p[j]))),
            );
        }
        sums
    }

    fn same(a: &Sums<DD>, b: &Sums<DD>) -> bool {
        a.n == b.n
            && (0..10).all(|k| {
                a.value[k].hi.to_bits() == b.value[k].hi.to_bits()
                    && a.value[k].lo.to_bits() == b.value[k].lo.to_bits()
                    && a.magnitude[k].to_bits() == b.magnitude[k].to_bits()
            })
    }

    #[test]
    fn the_lanes_give_the_generic_sums_bit_for_bit_at_every_scale() {
        for (seed, scale) in [
            (1, 1.0),
            (2, 1e-3),
            (3, 1e6),
            (4, 3e17),
            (5, 1e-150),
            (6, 7.0),
        ] {
            let v = coords(seed, 257, scale);
            let f = faces(1003, v.len());
            let p = [0.1 * scale, -0.37 * scale, 0.01 * scale];
            assert!(fits(&v, p));
            assert!(
                same(&solid_sums(&v, &f, p), &generic(&v, &f, p)),
                "scale {scale}"
            );
        }
    }

    #[test]
    fn the_lanes_give_the_generic_sums_with_subnormal_products() {
        // Offsets of 1e-160: their products underflow, where Dekker's
        // error term is itself inexact; the same operations give the same
        // inexact bits.
        let v = coords(9, 64, 1e-160);
        let f = faces(301, v.len());
        assert!(same(
            &solid_sums(&v, &f, [0.0; 3]),
            &generic(&v, &f, [0.0; 3])
        ));
    }

    #[test]
    fn a_mesh_beyond_the_limit_does_not_fit() {
        assert!(!fits(&[[0.0, 2.0 * LIMIT, 0.0]], [0.0; 3]));
        assert!(!fits(&[[0.0; 3]], [0.0, 0.0, -2.0 * LIMIT]));
        assert!(fits(&[[LIMIT, -LIMIT, 0.0]], [0.0; 3]));
    }

    #[test]
    fn a_far_mesh_takes_the_generic_path_with_the_same_sums() {
        let mut v = coords(11, 40, 1.0);
        v[0] = [1e300, 0.0, 0.0];
        let f = faces(97, v.len());
        let mesh = Mesh::new(
            v.clone(),
            f.clone(),
            super::super::check::Places::Listed(vec![super::super::At::Whole; f.len()]),
        );
        let p = mesh.reference();
        assert!(same(
            &mesh.sums_dd(Mode::Solid, p),
            &mesh.sums::<DD>(Mode::Solid, p)
        ));
    }

    #[test]
    fn a_mesh_of_several_chunks_sums_to_the_generic_bits_on_one_and_two_threads() {
        let v = coords(13, 5000, 0.05);
        let f = faces(3 * super::super::check::CHUNK + 77, v.len());
        let mesh = Mesh::new(
            v,
            f.clone(),
            super::super::check::Places::Listed(vec![super::super::At::Whole; f.len()]),
        );
        let p = mesh.reference();
        let want = mesh.sums_on::<DD>(Mode::Solid, p, 1);
        for threads in [1, 2] {
            let got = super::super::with_threads(threads, || mesh.sums_dd(Mode::Solid, p));
            assert!(same(&got, &want), "{threads} threads");
        }
    }
}
