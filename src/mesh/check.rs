//! A mesh's corners welded into a surface (corners with exactly equal
//! coordinates are one vertex) and checked before anything is integrated:
//! finite coordinates, at least one triangle of nonzero area (a triangle
//! of zero area, a repeated vertex or three corners on one line, is left
//! out with a warning: it encloses nothing and its edges cancel along its
//! line); for a solid also closed and consistently oriented
//! (`classes`: the triangles' edges pair up with opposite orientations,
//! T-junctions allowed); `MeshBody::load` then has `shells` split it into
//! shells that must bound one solid.

use super::{At, MeshBody, MeshError, Mode, Sums, finish};
use crate::numeric::{DD, Real};

/// A welded mesh: its vertices, each triangle's three, and where each
/// triangle came from in the file.
#[derive(Debug)]
pub struct Mesh {
    pub vertices: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
    pub at: Places,
    /// Pairs of triangles on the two sides of a T-junction, which `shells`
    /// joins into one shell (`classes`), once found (`joins`).
    joins: std::sync::OnceLock<Vec<(u32, u32)>>,
}

/// Where each triangle of a mesh is in its file.
#[derive(Debug, Clone)]
pub enum Places {
    /// Each triangle's place, listed.
    Listed(Vec<At>),
    /// A binary STL's triangles, in the file's order (`StlRecords::at`).
    ///
    /// NOTE: not a list: a million records' places would be 16 MB of
    /// fresh memory, filled on one thread, for an error message.
    Records,
}

impl Places {
    /// Where triangle `i` is.
    pub fn of(&self, i: usize) -> At {
        match self {
            Places::Listed(at) => at[i],
            Places::Records => super::read::StlRecords::at(i),
        }
    }
}

/// "triangle 12 (line 80)": a triangle by its position in the file (from
/// 1) and where it is.
pub fn triangle(i: usize, at: At) -> String {
    match at {
        At::Whole => format!("triangle {}", i + 1),
        at => format!("triangle {} ({at})", i + 1),
    }
}

/// A point as the message shows it: (x, y, z), shortest round trip.
pub fn point(p: [f64; 3]) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

impl Mesh {
    /// A mesh of welded vertices and triangles (`weld` makes one).
    pub fn new(vertices: Vec<[f64; 3]>, faces: Vec<[u32; 3]>, at: Places) -> Mesh {
        Mesh {
            vertices,
            faces,
            at,
            joins: std::sync::OnceLock::new(),
        }
    }

    /// Pairs of triangles on the two sides of a T-junction (none until the
    /// closedness check has found them).
    pub fn joins(&self) -> &[(u32, u32)] {
        self.joins.get().map_or(&[], Vec::as_slice)
    }

    pub(super) fn set_joins(&self, joins: Vec<(u32, u32)>) {
        // A second check of the same mesh finds the same.
        let _ = self.joins.set(joins);
    }

    /// Every triangle's edges, sorted by (key, triangle, direction): each
    /// edge's run together, runs in the order of their keys: for the
    /// closedness check and the shells both (48 bytes a triangle, made
    /// once and let go of once the shells are found).
    ///
    /// NOTE: a counting sort by the edge's smaller vertex, then each
    /// vertex's few edges sorted: the same order as sorting the whole list
    /// (its entries are distinct: a triangle's three edges have distinct
    /// keys once degenerate triangles are refused), in linear time.
    pub fn edges(&self) -> Vec<Edge> {
        {
            let mut start = vec![0u32; self.vertices.len() + 1];
            for f in &self.faces {
                for k in 0..3 {
                    start[f[k].min(f[(k + 1) % 3]) as usize + 1] += 1;
                }
            }
            for v in 0..self.vertices.len() {
                start[v + 1] += start[v];
            }
            let mut fill = start.clone();
            let mut edges: Vec<Edge> = vec![(0, 0, false); 3 * self.faces.len()];
            for (i, f) in self.faces.iter().enumerate() {
                for k in 0..3 {
                    let (a, b) = (f[k], f[(k + 1) % 3]);
                    let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
                    let at = &mut fill[a.min(b) as usize];
                    edges[*at as usize] = (key, i as u32, a < b);
                    *at += 1;
                }
            }
            for w in start.windows(2) {
                edges[w[0] as usize..w[1] as usize].sort_unstable();
            }
            edges
        }
    }

    pub(super) fn name(&self, f: usize) -> String {
        triangle(f, self.at.of(f))
    }

    /// The checks of the module comment for `mode`: the warnings of what
    /// the answer survives (a triangle of zero area left out, pieces that
    /// touch along an edge, T-junctions), one a class, or the error.
    pub fn check(&mut self, mode: Mode) -> Result<Vec<String>, MeshError> {
        let mut notes = self.leave_out_degenerate()?;
        if mode == Mode::Solid {
            notes.extend(self.closed_and_oriented(&self.edges())?);
        }
        Ok(notes)
    }

    /// The triangles of zero area left out (the first check), with its
    /// warning; every triangle of zero area is an error.
    pub fn leave_out_degenerate(&mut self) -> Result<Vec<String>, MeshError> {
        let mut notes = Vec::new();
        if let Some(first) = self.first_degenerate() {
            let keep: Vec<bool> = (0..self.faces.len())
                .map(|i| self.degenerate(i).is_none())
                .collect();
            let dropped = keep.iter().filter(|k| !**k).count();
            if dropped == keep.len() {
                return Err(MeshError::new(
                    first.at,
                    format!(
                        "every triangle of the mesh has zero area ({}); it encloses nothing",
                        first.message
                    ),
                ));
            }
            let mut k = keep.iter();
            let mut l = keep.iter();
            self.faces
                .retain(|_| *k.next().expect("one flag a triangle"));
            self.at = Places::Listed(
                (0..keep.len())
                    .filter(|_| *l.next().expect("one flag a triangle"))
                    .map(|i| self.at.of(i))
                    .collect(),
            );
            notes.push(format!(
                "{} of zero area left out ({}{}); the answer is still exact: such a triangle encloses nothing and its edges cancel along its line",
                if dropped == 1 { "a triangle".to_string() } else { format!("{dropped} triangles") },
                first.message,
                if dropped > 1 { ", the first" } else { "" }
            ));
        }
        Ok(notes)
    }

    /// The first degenerate triangle in the file's order, if any.
    pub fn first_degenerate(&self) -> Option<MeshError> {
        // NOTE: each thread finds the first in its share, the least wins.
        let n = self.faces.len();
        let threads = super::threads_for(n, 1 << 16);
        let piece = n.div_ceil(threads).max(1);
        let first = |from: usize| {
            (from..(from + piece).min(n)).find_map(|i| self.degenerate(i).map(|e| (i, e)))
        };
        let found = if threads == 1 {
            first(0)
        } else {
            std::thread::scope(|scope| {
                let handles: Vec<_> = (0..threads)
                    .map(|t| scope.spawn(move || first(t * piece)))
                    .collect();
                handles
                    .into_iter()
                    .filter_map(|h| {
                        h.join()
                            .expect("invariant: a triangle's check does not panic")
                    })
                    .min_by_key(|x| x.0)
            })
        };
        found.map(|(_, e)| e)
    }

    /// Why triangle `i` is degenerate, if it is.
    fn degenerate(&self, i: usize) -> Option<MeshError> {
        let f = self.faces[i];
        let [a, b, c] = f.map(|k| self.vertices[k as usize]);
        if f[0] == f[1] || f[1] == f[2] || f[2] == f[0] {
            let same = if f[0] == f[1] || f[0] == f[2] { a } else { b };
            return Some(MeshError::new(
                self.at.of(i),
                format!(
                    "{} is degenerate: two of its corners are the point {}",
                    self.name(i),
                    point(same)
                ),
            ));
        }
        if surely_not_collinear(a, b, c) {
            return None;
        }
        let d1: [DD; 3] = std::array::from_fn(|k| DD::of(b[k]) - DD::of(a[k]));
        let d2: [DD; 3] = std::array::from_fn(|k| DD::of(c[k]) - DD::of(a[k]));
        let x = super::cross(d1, d2);
        if x.iter().all(|v| v.hi == 0.0) {
            return Some(MeshError::new(
                self.at.of(i),
                format!(
                    "{} is degenerate: its corners {}, {} and {} are on one line (zero area)",
                    self.name(i),
                    point(a),
                    point(b),
                    point(c)
                ),
            ));
        }
        None
    }

    /// The centre of the bounding box, the reference point of the sums.
    pub fn reference(&self) -> [f64; 3] {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for v in &self.vertices {
            for k in 0..3 {
                lo[k] = lo[k].min(v[k]);
                hi[k] = hi[k].max(v[k]);
            }
        }
        // Halves first: no overflow near f64::MAX.
        std::array::from_fn(|k| lo[k] / 2.0 + hi[k] / 2.0)
    }

    /// The sums of the terms about the reference point, in T.
    ///
    /// NOTE: the triangles are summed in chunks of `CHUNK`, on every core,
    /// and the chunks' sums then added in their order: the result is the
    /// same bits whatever the number of cores (it depends on `CHUNK`
    /// alone), and the integrals of a million triangles, most of a mesh's
    /// cost, take half the time on two cores. The error bound stays that
    /// of one recursive sum of all n terms (`Sums::error`), which a chunked
    /// sum never exceeds: its terms pass through at most CHUNK + n/CHUNK ≤ n
    /// additions.
    pub fn sums<T: Real + Send>(&self, mode: Mode, p: [f64; 3]) -> Sums<T> {
        self.sums_on(mode, p, super::threads_for(self.faces.len(), CHUNK))
    }

    /// `sums` on at most `threads` threads.
    pub fn sums_on<T: Real + Send>(&self, mode: Mode, p: [f64; 3], threads: usize) -> Sums<T> {
        let offset =
            |v: [f64; 3]| -> [DD; 3] { std::array::from_fn(|k| DD::of(v[k]) - DD::of(p[k])) };
        self.sums_with(threads, |faces| {
            let mut sums = Sums::<T>::new();
            for f in faces {
                sums.add(mode, f.map(|k| offset(self.vertices[k as usize])));
            }
            sums
        })
    }

    /// The sums of the triangles' chunks (of `CHUNK`), each by `chunk`,
    /// on at most `threads` threads, added in the chunks' order.
    pub(super) fn sums_with<T: Real + Send>(
        &self,
        threads: usize,
        chunk: impl Fn(&[[u32; 3]]) -> Sums<T> + Sync,
    ) -> Sums<T> {
        let chunks: Vec<&[[u32; 3]]> = self.faces.chunks(CHUNK).collect();
        let threads = threads.clamp(1, chunks.len().max(1));
        let mut parts: Vec<Option<Sums<T>>> = vec![None; chunks.len()];
        if threads == 1 {
            for (part, c) in parts.iter_mut().zip(&chunks) {
                *part = Some(chunk(c));
            }
        } else {
            std::thread::scope(|scope| {
                let handles: Vec<_> = (0..threads)
                    .map(|t| {
                        let (chunks, chunk) = (&chunks, &chunk);
                        scope.spawn(move || {
                            (t..chunks.len())
                                .step_by(threads)
                                .map(|i| (i, chunk(chunks[i])))
                                .collect::<Vec<_>>()
                        })
                    })
                    .collect();
                for h in handles {
                    for (i, sums) in h.join().expect("invariant: summing a chunk does not panic") {
                        parts[i] = Some(sums);
                    }
                }
            });
        }
        let mut sums = Sums::<T>::new();
        for part in parts {
            let part = part.expect("invariant: every chunk was summed");
            for k in 0..10 {
                sums.value[k] = sums.value[k] + part.value[k];
                sums.magnitude[k] += part.magnitude[k];
            }
            sums.n += part.n;
        }
        sums
    }

    /// The mesh's integrals (see the module comment of `mesh`), in T.
    pub fn integrate<T: Real + Send>(&self, mode: Mode) -> MeshBody {
        self.integrate_moved::<T>(mode, [0.0; 10])
    }

    /// `integrate`, its sums' bounds widened by `moved` (`near`).
    pub fn integrate_moved<T: Real + Send>(&self, mode: Mode, moved: [f64; 10]) -> MeshBody {
        let p = self.reference();
        self.body_of(mode, p, self.sums::<T>(mode, p), moved)
    }

    /// The body of the sums about `p` (`reference`), their bounds widened
    /// by `moved`.
    pub fn body_of<T: Real>(
        &self,
        mode: Mode,
        p: [f64; 3],
        sums: Sums<T>,
        moved: [f64; 10],
    ) -> MeshBody {
        let (points, faces) = (self.vertices.clone(), self.faces.clone());
        body(mode, p, sums, moved, points, faces)
    }

    /// `body_of`, the mesh's vertices and triangles moved into it (not
    /// copied: 24 bytes a million triangles, and their pages).
    pub fn into_body<T: Real>(
        self,
        mode: Mode,
        p: [f64; 3],
        sums: Sums<T>,
        moved: [f64; 10],
    ) -> MeshBody {
        body(mode, p, sums, moved, self.vertices, self.faces)
    }
}

/// `Mesh::body_of` of a mesh's vertices and triangles.
fn body<T: Real>(
    mode: Mode,
    p: [f64; 3],
    mut sums: Sums<T>,
    moved: [f64; 10],
    points: Vec<[f64; 3]>,
    faces: Vec<[u32; 3]>,
) -> MeshBody {
    sums.moved = moved;
    let (measure, g, second, bound) = finish(mode, &sums);
    let dd = |x: T| DD::of(x.f64()) + DD::of((x - T::of(x.f64())).f64());
    MeshBody {
        mode,
        triangles: faces.len(),
        measure: dd(measure),
        centroid: std::array::from_fn(|k| DD::of(p[k]) + dd(g[k])),
        second: second.map(|r| r.map(dd)),
        bound: Bound {
            centroid: bound.centroid
                + 4.0 * super::unit_of::<DD>() * p.iter().fold(0.0, |m: f64, x| m.max(x.abs())),
            ..bound
        },
        extent: points.iter().fold(
            [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]],
            |[lo, hi], v| {
                [
                    std::array::from_fn(|k| lo[k].min(v[k])),
                    std::array::from_fn(|k| hi[k].max(v[k])),
                ]
            },
        ),
        points: std::sync::Arc::new(points),
        faces: std::sync::Arc::new(faces),
    }
}

use super::Bound;

/// Whether a component of (b − a) × (c − a) is certainly nonzero by an
/// f64 evaluation and its error bound (the double-double test in
/// `Mesh::check` then finds it nonzero too: its error is 10⁻¹⁵ of this
/// one's). Most triangles pass here; the rest take the double-double test.
fn surely_not_collinear(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> bool {
    let d1: [f64; 3] = std::array::from_fn(|k| b[k] - a[k]);
    let d2: [f64; 3] = std::array::from_fn(|k| c[k] - a[k]);
    [(1, 2), (2, 0), (0, 1)].into_iter().any(|(i, j)| {
        let (p, q) = (d1[i] * d2[j], d1[j] * d2[i]);
        // NOTE: each difference and product rounds once (relative 2⁻⁵³),
        // the final difference once more: 1e-14 of the magnitudes covers
        // them with room; overflow (an infinite product) is left to the
        // double-double test.
        // A magnitude well above f64's least normal: no product is
        // subnormal enough for its absolute rounding to matter.
        let m = p.abs() + q.abs();
        m.is_finite() && m > 1e-280 && (p - q).abs() > 1e-14 * m
    })
}

/// The triangles summed as one chunk (`Mesh::sums`).
pub(super) const CHUNK: usize = 1 << 15;

/// An edge of a triangle: its key (the two vertices, smaller first), the
/// triangle, and whether it runs from the smaller to the larger.
pub type Edge = (u64, u32, bool);
