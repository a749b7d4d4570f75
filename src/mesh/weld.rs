//! Welding a file's corners into a mesh's vertices on every core: corners
//! with exactly equal coordinates (−0 and +0 equal) are one vertex, the
//! vertices numbered in the order the triangles first use them.
//!
//! NOTE: in steps, so that the numbering is the one-core order whatever
//! the number of cores: (1) each core reads a run of the points, links a
//! point equal to one just before it to that point, and sorts the others
//! by the share of the hashes their key (their coordinates' bits) falls
//! in; (2) each core takes a share and finds, in a table of its own, each
//! of its points' representative (the first point, in the file's order,
//! with its key: a point's share is its key's, so one core sees every
//! point of a key); (3) one pass over the triangles' corners in order
//! numbers each representative when it is first used, a few array reads
//! a corner. A table of u32 indices (4 bytes
//! a slot) is an eighth of a `HashMap<[u64; 3], u32>`'s memory, whose cache
//! misses cost more than its hashing.

use super::check::{Mesh, Places, point, triangle};
use super::read::{Corners, StlRecords, Triangles};
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

/// How many points back a corner is compared with before the table.
const RECENT: usize = 8;

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
    fn representative(&mut self, i: u32, k: &[u64; 3], h: u64, points: &impl Source) -> u32 {
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
            if key(&points.point(s as usize)) == *k {
                return s;
            }
            at = (at + 1) & mask;
        }
    }

    fn grow(&mut self, points: &impl Source) {
        let bigger = vec![EMPTY; 2 * self.slots.len()];
        let old = std::mem::replace(&mut self.slots, bigger);
        let mask = self.slots.len() - 1;
        for s in old.into_iter().filter(|s| *s != EMPTY) {
            let mut at = hash(&key(&points.point(s as usize))) as usize & mask;
            while self.slots[at] != EMPTY {
                at = (at + 1) & mask;
            }
            self.slots[at] = s;
        }
    }
}

/// The corners the weld reads: point `i` of `points()`, triangle `i`'s
/// three points, and where triangle `i` is in the file.
trait Source: Sync {
    fn points(&self) -> usize;
    fn point(&self, i: usize) -> [f64; 3];
    fn triangles(&self) -> usize;
    fn face(&self, i: usize) -> [u32; 3];
    fn at(&self, i: usize) -> At;
}

impl Source for Triangles {
    fn points(&self) -> usize {
        self.points.len()
    }
    #[inline]
    fn point(&self, i: usize) -> [f64; 3] {
        self.points[i]
    }
    fn triangles(&self) -> usize {
        self.faces.len()
    }
    #[inline]
    fn face(&self, i: usize) -> [u32; 3] {
        self.faces[i]
    }
    fn at(&self, i: usize) -> At {
        self.at[i]
    }
}

/// A binary STL's corners, point `3i + k` corner k of triangle i.
impl Source for StlRecords<'_> {
    fn points(&self) -> usize {
        3 * self.len()
    }
    #[inline]
    fn point(&self, i: usize) -> [f64; 3] {
        self.corner(i / 3, i % 3)
    }
    fn triangles(&self) -> usize {
        self.len()
    }
    #[inline]
    fn face(&self, i: usize) -> [u32; 3] {
        let i = 3 * i as u32;
        [i, i + 1, i + 2]
    }
    fn at(&self, i: usize) -> At {
        StlRecords::at(i)
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

    /// `weld` of a file's corners however read (`read::corners`).
    pub fn weld_corners(c: Corners) -> Result<Mesh, MeshError> {
        match c {
            Corners::Listed(t) => Mesh::weld(t),
            Corners::Stl(s) => {
                let threads = super::threads_for(s.points(), 1 << 16);
                let (vertices, faces) = welded(&s, threads)?;
                Ok(Mesh::new(vertices, faces, Places::Records))
            }
        }
    }

    /// `weld` on at most `threads` threads.
    pub fn weld_on(t: Triangles, threads: usize) -> Result<Mesh, MeshError> {
        let (vertices, faces) = welded(&t, threads)?;
        Ok(Mesh::new(vertices, faces, Places::Listed(t.at)))
    }
}

/// A weld's vertices and triangles.
type Welded = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// The welded vertices and triangles of `t`'s corners, on at most
/// `threads` threads.
fn welded<S: Source>(t: &S, threads: usize) -> Result<Welded, MeshError> {
    if t.triangles() == 0 {
        return Err(MeshError::new(At::Whole, "the mesh has no triangles"));
    }
    let n = t.points();
    let threads = threads.clamp(1, n.max(1));
    let rep: Vec<AtomicU32> = (0..n as u32).map(AtomicU32::new).collect();
    let rep_ref = &rep;
    // NOTE: in two passes, each point read once. (1) Each thread takes a
    // run of the points: a corner equal to one of the few points just
    // before it in its run (most are: a file's neighbouring triangles
    // share corners) is linked to that point, without a look in a table
    // (the links are followed below, so the representatives are the
    // same); each other point goes, with its key's hash, into the list
    // of its hash's share. (2) Each thread takes a share: the lists of
    // every run, in the runs' order, so the points in the file's order,
    // each found or put in its own table.
    let piece = n.div_ceil(threads).max(1);
    let scan = move |me: usize| -> Vec<Vec<(u32, u32)>> {
        let mut lists = vec![Vec::new(); threads];
        let mut recent = [[0u64; 3]; RECENT];
        let start = me * piece;
        for i in start..n.min(start + piece) {
            let k = key(&t.point(i));
            let back = (1..=(i - start).min(RECENT)).find(|m| recent[(i - m) % RECENT] == k);
            recent[i % RECENT] = k;
            if let Some(m) = back {
                rep_ref[i].store((i - m) as u32, Ordering::Relaxed);
                continue;
            }
            let h = hash(&k);
            // The hash's low half: the tables' slots (fewer than 2³²).
            lists[share(h, threads)].push((i as u32, h as u32));
        }
        lists
    };
    // NOTE: the tables allocated here, on the calling thread: memory a
    // thread allocates stays in its own arena once freed.
    let tables: Vec<Table> = (0..threads)
        .map(|_| Table::with_capacity(n / 6 / threads + 16))
        .collect();
    let find = |me: usize, mut table: Table, runs: &[Vec<Vec<(u32, u32)>>]| {
        for run in runs {
            for &(i, h) in &run[me] {
                let k = key(&t.point(i as usize));
                let r = table.representative(i, &k, u64::from(h), t);
                if r != i {
                    rep_ref[i as usize].store(r, Ordering::Relaxed);
                }
            }
        }
    };
    if threads == 1 {
        let runs = [scan(0)];
        tables.into_iter().for_each(|table| find(0, table, &runs));
    } else {
        let runs: Vec<Vec<Vec<(u32, u32)>>> = std::thread::scope(|scope| {
            let handles: Vec<_> = (0..threads)
                .map(|me| scope.spawn(move || scan(me)))
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("invariant: a weld's scan does not panic"))
                .collect()
        });
        let runs = &runs;
        std::thread::scope(|scope| {
            for (me, table) in tables.into_iter().enumerate() {
                let find = &find;
                scope.spawn(move || find(me, table, runs));
            }
        });
    }
    let mut rep: Vec<u32> = rep.into_iter().map(AtomicU32::into_inner).collect();
    // A link points back to a point whose representative is settled.
    for i in 0..n {
        rep[i] = rep[rep[i] as usize];
    }
    let mut number = vec![u32::MAX; n];
    let mut vertices = Vec::with_capacity(n / 6 + 3);
    let mut faces = Vec::with_capacity(t.triangles());
    for i in 0..t.triangles() {
        let tri = t.face(i);
        let mut f = [0u32; 3];
        for (k, &pi) in tri.iter().enumerate() {
            let r = rep[pi as usize] as usize;
            if number[r] == u32::MAX {
                let p = t.point(pi as usize);
                if !p.iter().all(|x| x.is_finite()) {
                    let at = t.at(i);
                    return Err(MeshError::new(
                        at,
                        format!(
                            "{} has a coordinate that is not a finite number: {}",
                            triangle(i, at),
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
    Ok((vertices, faces))
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

    /// A binary STL of `n` triangles whose corners take few f32 values
    /// (corners repeat often, near each other and far apart), −0 too.
    fn stl(seed: u64, n: usize) -> Vec<u8> {
        let mut x = seed | 1;
        let mut bytes = vec![b' '; 80];
        bytes.extend((n as u32).to_le_bytes());
        for _ in 0..n {
            bytes.extend([0u8; 12]);
            for _ in 0..9 {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                let v = ((x >> 11) % 7) as f32 * 0.375 - 1.125;
                let v = if v == 0.0 && x & 1 == 1 { -0.0 } else { v };
                bytes.extend(v.to_le_bytes());
            }
            bytes.extend([0u8; 2]);
        }
        bytes
    }

    #[test]
    fn a_binary_stl_welds_from_its_records_as_from_its_decoded_corners() {
        use crate::mesh::read::{self, FileType};
        for (seed, n) in [(3, 1), (11, 500), (29, 40_000)] {
            let bytes = stl(seed, n);
            let listed =
                Mesh::weld(read::read(FileType::Stl, &bytes, n).expect("valid")).expect("finite");
            for threads in [1, 2, 3] {
                let m = crate::mesh::with_threads(threads, || {
                    Mesh::weld_corners(read::corners(FileType::Stl, &bytes, n).expect("valid"))
                })
                .expect("finite");
                assert_eq!(m.faces, listed.faces, "{threads} threads");
                let bits =
                    |v: &[[f64; 3]]| v.iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>();
                assert_eq!(
                    bits(&m.vertices),
                    bits(&listed.vertices),
                    "{threads} threads"
                );
                for i in [0, n / 2, n - 1] {
                    assert_eq!(m.at.of(i), listed.at.of(i));
                    assert_eq!(m.at.of(i), At::Byte(84 + 50 * i as u64));
                }
            }
        }
    }

    #[test]
    fn a_binary_stl_names_its_first_corner_not_finite_by_its_record() {
        use crate::mesh::read::{self, FileType};
        let mut bytes = stl(5, 1000);
        // Triangle 701's second corner's y, and a later one's x.
        let at = |t: usize, c: usize, k: usize| 84 + 50 * t + 12 + 12 * c + 4 * k;
        bytes[at(700, 1, 1)..at(700, 1, 1) + 4].copy_from_slice(&f32::NAN.to_le_bytes());
        bytes[at(900, 0, 0)..at(900, 0, 0) + 4].copy_from_slice(&f32::INFINITY.to_le_bytes());
        for threads in [1, 2] {
            let e = crate::mesh::with_threads(threads, || {
                Mesh::weld_corners(read::corners(FileType::Stl, &bytes, 1000).expect("valid"))
            })
            .expect_err("not finite");
            assert_eq!(e.at, At::Byte(84 + 50 * 700));
            assert!(
                e.message.starts_with("triangle 701 (byte 35084) "),
                "{}",
                e.message
            );
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
