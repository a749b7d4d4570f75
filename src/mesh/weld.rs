//! Welding a file's corners into a mesh's vertices on every core: corners
//! with exactly equal coordinates (−0 and +0 equal) are one vertex, the
//! vertices numbered in the order the triangles first use them.
//!
//! NOTE: in two steps, so that the numbering is the one-core order
//! whatever the number of cores: (1) each core takes the points whose key
//! (their coordinates' bits) hashes into its share of the hashes and
//! finds, in a table of its own, each point's representative (the first
//! point, in the file's order, with its key: a point's share is its
//! key's, so one core sees every point of a key); (2) one pass over the
//! triangles' corners in order numbers each representative when it is
//! first used, a few array reads a corner. A table of u32 indices (4 bytes
//! a slot) is an eighth of a `HashMap<[u64; 3], u32>`'s memory, whose cache
//! misses cost more than its hashing.

use super::check::{Mesh, point, triangle};
use super::read::Triangles;
use super::{At, MeshError};
use std::sync::atomic::{AtomicU32, Ordering};

/// Murmur3's finaliser over the three coordinates' bits: every input bit
/// reaches the high bits (the share) and the low ones (the slot), as the
/// coordinates of a smooth surface differ in their low mantissa bits.
fn hash(key: &[u64; 3]) -> u64 {
    let mut h = 0u64;
    for &x in key {
        h = (h.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^ (h >> 33)
}

/// A point's key: its coordinates' bits, −0 as +0.
fn key(p: &[f64; 3]) -> [u64; 3] {
    p.map(|x| (x + 0.0).to_bits())
}

/// Which of `shares` a hash belongs to (its high bits).
fn share(h: u64, shares: usize) -> usize {
    (((h >> 32) * shares as u64) >> 32) as usize
}

/// An open-addressing table of point indices, keyed by the points' keys.
struct Table {
    slots: Vec<u32>,
    len: usize,
}

const EMPTY: u32 = u32::MAX;

impl Table {
    fn with_capacity(n: usize) -> Table {
        Table {
            slots: vec![EMPTY; (2 * n).next_power_of_two().max(16)],
            len: 0,
        }
    }

    /// The first point with point `i`'s key (`i` itself if none before);
    /// `h` its key's hash.
    fn representative(&mut self, i: u32, k: &[u64; 3], h: u64, points: &[[f64; 3]]) -> u32 {
        if 2 * (self.len + 1) > self.slots.len() {
            self.grow(points);
        }
        let mask = self.slots.len() - 1;
        let mut at = h as usize & mask;
        loop {
            let s = self.slots[at];
            if s == EMPTY {
                self.slots[at] = i;
                self.len += 1;
                return i;
            }
            if key(&points[s as usize]) == *k {
                return s;
            }
            at = (at + 1) & mask;
        }
    }

    fn grow(&mut self, points: &[[f64; 3]]) {
        let bigger = vec![EMPTY; 2 * self.slots.len()];
        let old = std::mem::replace(&mut self.slots, bigger);
        let mask = self.slots.len() - 1;
        for s in old.into_iter().filter(|s| *s != EMPTY) {
            let mut at = hash(&key(&points[s as usize])) as usize & mask;
            while self.slots[at] != EMPTY {
                at = (at + 1) & mask;
            }
            self.slots[at] = s;
        }
    }
}

impl Mesh {
    /// Weld the corners: exactly equal coordinates are one vertex (−0 and
    /// +0 equal). Refuses a non-finite coordinate (the first corner, in
    /// the triangles' order, that has one).
    pub fn weld(t: Triangles) -> Result<Mesh, MeshError> {
        let threads = super::threads_for(t.points.len(), 1 << 16);
        Mesh::weld_on(t, threads)
    }

    /// `weld` on at most `threads` threads.
    pub fn weld_on(t: Triangles, threads: usize) -> Result<Mesh, MeshError> {
        if t.faces.is_empty() {
            return Err(MeshError::new(At::Whole, "the mesh has no triangles"));
        }
        let n = t.points.len();
        let threads = threads.clamp(1, n.max(1));
        let rep: Vec<AtomicU32> = (0..n as u32).map(AtomicU32::new).collect();
        let (points, rep_ref) = (&t.points, &rep);
        // NOTE: every thread hashes every point (a few nanoseconds each)
        // and keeps those of its share: cheaper in memory than a list of
        // hashes or keys (24 bytes a point each).
        // NOTE: the tables allocated here, on the calling thread: memory a
        // thread allocates stays in its own arena once freed.
        let tables: Vec<Table> = (0..threads)
            .map(|_| Table::with_capacity(n / 6 / threads + 16))
            .collect();
        let find = move |me: usize, mut table: Table| {
            for (i, p) in points.iter().enumerate() {
                let k = key(p);
                let h = hash(&k);
                if share(h, threads) == me {
                    let r = table.representative(i as u32, &k, h, points);
                    if r != i as u32 {
                        rep_ref[i].store(r, Ordering::Relaxed);
                    }
                }
            }
        };
        if threads == 1 {
            tables.into_iter().for_each(|t| find(0, t));
        } else {
            std::thread::scope(|scope| {
                for (me, table) in tables.into_iter().enumerate() {
                    scope.spawn(move || find(me, table));
                }
            });
        }
        let rep: Vec<u32> = rep.into_iter().map(AtomicU32::into_inner).collect();
        let mut number = vec![u32::MAX; n];
        let mut vertices = Vec::with_capacity(n / 6 + 3);
        let mut faces = Vec::with_capacity(t.faces.len());
        for (i, tri) in t.faces.iter().enumerate() {
            let mut f = [0u32; 3];
            for (k, &pi) in tri.iter().enumerate() {
                let r = rep[pi as usize] as usize;
                if number[r] == u32::MAX {
                    let p = t.points[pi as usize];
                    if !p.iter().all(|x| x.is_finite()) {
                        return Err(MeshError::new(
                            t.at[i],
                            format!(
                                "{} has a coordinate that is not a finite number: {}",
                                triangle(i, t.at[i]),
                                point(p)
                            ),
                        ));
                    }
                    number[r] = vertices.len() as u32;
                    vertices.push(p.map(|x| x + 0.0));
                }
                f[k] = number[r];
            }
            faces.push(f);
        }
        Ok(Mesh::new(vertices, faces, t.at))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The one-core weld of the version before this module: a hash map
    /// from coordinates' bits to vertices, filled as the triangles use them.
    fn by_map(t: &Triangles) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let mut index = std::collections::HashMap::new();
        let mut vertices = Vec::new();
        let faces = t
            .faces
            .iter()
            .map(|tri| {
                tri.map(|pi| {
                    let p = t.points[pi as usize].map(|x| x + 0.0);
                    let next = vertices.len() as u32;
                    *index.entry(p.map(f64::to_bits)).or_insert_with(|| {
                        vertices.push(p);
                        next
                    })
                })
            })
            .collect();
        (vertices, faces)
    }

    fn soup(seed: u64, n: usize, grid: f64) -> Triangles {
        let mut x = seed | 1;
        let mut r = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Few distinct values: corners repeat often; −0 as well.
            let v = ((x >> 11) % 9) as f64 / grid - 4.0 / grid;
            if v == 0.0 && x & 1 == 1 { -0.0 } else { v }
        };
        let corners = (0..n)
            .map(|_| std::array::from_fn(|_| [r(), r(), r()]))
            .collect();
        Triangles::of_corners(corners, vec![At::Whole; n])
    }

    #[test]
    fn the_weld_numbers_vertices_as_a_hash_map_in_one_pass_does_on_any_number_of_threads() {
        for (seed, n) in [(1, 10), (7, 1000), (99, 70_000)] {
            let t = soup(seed, n, 2.0);
            let (vertices, faces) = by_map(&t);
            for threads in [1, 2, 3, 8] {
                let t = Triangles {
                    points: t.points.clone(),
                    faces: t.faces.clone(),
                    at: t.at.clone(),
                };
                let m = Mesh::weld_on(t, threads).expect("finite");
                assert_eq!(m.faces, faces, "{threads} threads");
                let bits =
                    |v: &[[f64; 3]]| v.iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>();
                assert_eq!(bits(&m.vertices), bits(&vertices), "{threads} threads");
            }
        }
    }

    #[test]
    fn shared_points_are_numbered_by_the_triangles_that_first_use_them() {
        // An OBJ's points: the second triangle uses the last point first.
        let t = Triangles {
            points: vec![
                [0.0; 3],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0],
                [-0.0, 0.0, 0.0],
            ],
            faces: vec![[3, 1, 2], [4, 2, 1]],
            at: vec![At::Whole; 2],
        };
        let m = Mesh::weld_on(t, 2).expect("finite");
        assert_eq!(m.faces, vec![[0, 1, 2], [3, 2, 1]]);
        assert_eq!(m.vertices[3], [0.0; 3]);
    }

    #[test]
    fn the_first_corner_not_finite_is_named_whatever_the_threads() {
        let mut t = soup(5, 200_000, 2.0);
        t.points[400_000][1] = f64::NAN;
        t.points[300_001][2] = f64::INFINITY;
        let e = Mesh::weld_on(t, 2).expect_err("not finite");
        assert!(e.message.starts_with("triangle 100001 "), "{}", e.message);
    }
}
