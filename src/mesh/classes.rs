//! Whether a solid mesh's surface is closed, and the words for what is
//! wrong when it is not.
//!
//! The integrals (`mesh`'s module comment) are a sum over the triangles of
//! terms that are exact for any surface whose boundary is nothing: every
//! edge of a triangle cancelled, as a segment, by edges of other triangles
//! that traverse it the other way. Then the sum is the integral over the
//! enclosed solid, whatever the reference point (Stokes), so the answer is
//! exact for:
//!
//! - an edge shared by two triangles, one each way (a manifold surface);
//! - an edge shared by four or more, half each way: pieces that touch
//!   along it (not manifold, but closed; a warning says so);
//! - a T-junction: an edge of one side covered by collinear edges of the
//!   other, which end at a corner inside it (the surface is closed as a
//!   set of segments; a warning says so, and `shells` joins the
//!   triangles on both sides into one shell).
//!
//! A triangle that repeats another's three corners wound the same way is
//! refused: it counts its surface twice (the edges still pair up). An edge
//! left uncancelled is an error: "open" when its triangles are odd in
//! number (a hole, or a gap), "inside out" when two traverse it the same
//! way (one wound the other way), "not manifold" when more than two meet
//! there unevenly.

use super::check::{Edge, Mesh, point};
use super::exact::orient2d;
use super::{At, MeshError};
use std::collections::HashMap;

/// An edge that does not pair up: its key, its triangles with their
/// directions (true: from the smaller vertex to the larger), and its net
/// count (forward less backward).
struct Loose {
    key: u64,
    run: Vec<(u32, bool)>,
    net: i32,
}

/// T-junctions that close the loose edges: the triangles to join across
/// them, the number of splits, and the loose edge to name.
type Junctions = (Vec<(u32, u32)>, usize, usize);

fn ends(key: u64) -> (u32, u32) {
    ((key >> 32) as u32, (key & 0xffff_ffff) as u32)
}

fn key_of(a: u32, b: u32) -> u64 {
    (u64::from(a.min(b)) << 32) | u64::from(a.max(b))
}

impl Mesh {
    /// The closedness check of the module comment: the warnings of the
    /// classes the answer survives, or the error.
    pub(super) fn closed_and_oriented(&self, edges: &[Edge]) -> Result<Vec<String>, MeshError> {
        let mut loose: Vec<Loose> = Vec::new();
        let mut crowded: Option<(u32, u64, usize, usize)> = None;
        let mut crowded_count = 0usize;
        let mut repeat: Option<(u32, u32)> = None;
        for run in edges.chunk_by(|x, y| x.0 == y.0) {
            let forward = run.iter().filter(|e| e.2).count();
            let net = 2 * forward as i32 - run.len() as i32;
            let first = run.iter().map(|e| e.1).min().expect("a run is not empty");
            if net != 0 {
                loose.push(Loose {
                    key: run[0].0,
                    run: run.iter().map(|e| (e.1, e.2)).collect(),
                    net,
                });
            } else if run.len() > 2 {
                crowded_count += 1;
                if crowded.is_none_or(|c| first < c.0) {
                    crowded = Some((first, run[0].0, forward, run.len()));
                }
            }
            // NOTE: a repeated triangle traverses each of its edges the
            // way its twin does: only runs with two triangles the same way
            // are searched, nearly none.
            if run.len() > 1 && (forward > 1 || run.len() - forward > 1) {
                for (k, x) in run.iter().enumerate() {
                    for y in &run[k + 1..] {
                        if x.2 == y.2 && self.same_winding(x.1, y.1) {
                            let pair = (x.1.min(y.1), x.1.max(y.1));
                            if repeat.is_none_or(|r| pair < r) {
                                repeat = Some(pair);
                            }
                        }
                    }
                }
            }
        }
        if let Some((a, b)) = repeat {
            return Err(MeshError::new(
                self.at.of(b as usize),
                format!(
                    "{} repeats {}: the same three corners wound the same way count that surface twice; remove one of them",
                    self.name(b as usize),
                    self.name(a as usize)
                ),
            ));
        }
        let mut notes = Vec::new();
        if !loose.is_empty() {
            // NOTE: the predicates are exact on the corners scaled as
            // `shells` scales them (by a power of two: exact, and no
            // product underflows); a mesh they cannot be exact on is
            // refused there.
            let pts = super::shells::scaled(self)?;
            match self.t_junctions(&loose, &pts) {
                Ok((joins, splits, example)) => {
                    self.set_joins(joins);
                    let l = &loose[example];
                    let (a, b) = ends(l.key);
                    let t = l.run.iter().map(|e| e.0).min().expect("a run is not empty");
                    notes.push(format!(
                        "the mesh has T-junctions ({splits} corner{} inside another triangle's edge), the first on the edge {} – {} of {}; the answer is still exact: the collinear edges of the other side cover that edge exactly, so the surface is closed",
                        if splits == 1 { "" } else { "s" },
                        point(self.vertices[a as usize]),
                        point(self.vertices[b as usize]),
                        self.name(t as usize)
                    ));
                }
                Err(bad) => return Err(self.loose_error(&loose[bad])),
            }
        }
        if let Some((first, key, forward, n)) = crowded {
            let (a, b) = ends(key);
            notes.push(format!(
                "the mesh is not manifold: the edge {} – {} is shared by {n} triangles (the first {}), {forward} each way, where pieces touch{}; the answer is still exact: the triangles pair up with opposite orientations along every edge, so the surface is closed",
                point(self.vertices[a as usize]),
                point(self.vertices[b as usize]),
                self.name(first as usize),
                if crowded_count > 1 {
                    format!(" ({crowded_count} such edges)")
                } else {
                    String::new()
                }
            ));
        }
        Ok(notes)
    }

    /// Whether triangles x and y have the same corners wound the same way.
    fn same_winding(&self, x: u32, y: u32) -> bool {
        let (f, g) = (self.faces[x as usize], self.faces[y as usize]);
        (0..3).any(|r| [g[r], g[(r + 1) % 3], g[(r + 2) % 3]] == f)
    }

    /// Split the loose edges at the corners that lie inside them (exact
    /// predicates): if every piece then pairs up, the triangles to join
    /// across the junctions, the number of splits and the loose edge
    /// to name; else the loose edge (its index) that stays open, by its
    /// first triangle.
    ///
    /// NOTE: only corners of loose edges can lie inside one and close it
    /// (a corner where the other side's edges end is an end of loose
    /// edges), so the search is over those few corners, sorted along x.
    fn t_junctions(&self, loose: &[Loose], v: &[[f64; 3]]) -> Result<Junctions, usize> {
        let mut corners: Vec<u32> = loose
            .iter()
            .flat_map(|l| {
                let (a, b) = ends(l.key);
                [a, b]
            })
            .collect();
        corners.sort_unstable();
        corners.dedup();
        corners.sort_by(|p, q| v[*p as usize][0].total_cmp(&v[*q as usize][0]));
        let mut pieces: HashMap<u64, (i32, Vec<usize>)> = HashMap::new();
        let mut splits = 0;
        let mut example = None;
        for (i, l) in loose.iter().enumerate() {
            let (a, b) = ends(l.key);
            let (pa, pb) = (v[a as usize], v[b as usize]);
            let lo = pa[0].min(pb[0]);
            let hi = pa[0].max(pb[0]);
            let from = corners.partition_point(|c| v[*c as usize][0] < lo);
            let axis = (0..3)
                .max_by(|&i, &j| (pb[i] - pa[i]).abs().total_cmp(&(pb[j] - pa[j]).abs()))
                .expect("three axes");
            let mut inside: Vec<u32> = corners[from..]
                .iter()
                .take_while(|c| v[**c as usize][0] <= hi)
                .copied()
                .filter(|&c| c != a && c != b && between(pa, v[c as usize], pb))
                .collect();
            if !inside.is_empty() && example.is_none() {
                example = Some(i);
            }
            splits += inside.len();
            let sign = if pb[axis] > pa[axis] { 1.0 } else { -1.0 };
            inside.sort_by(|p, q| {
                (sign * v[*p as usize][axis]).total_cmp(&(sign * v[*q as usize][axis]))
            });
            let chain: Vec<u32> = std::iter::once(a).chain(inside).chain([b]).collect();
            for w in chain.windows(2) {
                // Net counts run from the smaller vertex to the larger.
                let net = if w[0] < w[1] { l.net } else { -l.net };
                let e = pieces.entry(key_of(w[0], w[1])).or_default();
                e.0 += net;
                e.1.push(i);
            }
        }
        let bad = pieces
            .values()
            .filter(|p| p.0 != 0)
            .flat_map(|p| p.1.iter().copied())
            .min_by_key(|&i| (loose[i].run.iter().map(|e| e.0).min(), i));
        if let Some(i) = bad {
            return Err(i);
        }
        let mut joins = Vec::new();
        for (_, users) in pieces.values() {
            let tris: Vec<u32> = users
                .iter()
                .flat_map(|&i| loose[i].run.iter().map(|e| e.0))
                .collect();
            joins.extend(tris.windows(2).map(|w| (w[0], w[1])));
        }
        joins.sort_unstable();
        joins.dedup();
        Ok((joins, splits, example.unwrap_or(0)))
    }

    /// The error for a loose edge that no T-junction closes.
    fn loose_error(&self, l: &Loose) -> MeshError {
        let (a, b) = ends(l.key);
        let edge = format!(
            "the edge {} – {}",
            point(self.vertices[a as usize]),
            point(self.vertices[b as usize])
        );
        let mut faces: Vec<u32> = l.run.iter().map(|e| e.0).collect();
        faces.sort_unstable();
        let names = |fs: &[u32]| {
            let mut list: Vec<String> = fs.iter().take(4).map(|f| self.name(*f as usize)).collect();
            if fs.len() > 4 {
                list.push(format!("and {} more", fs.len() - 4));
            }
            list.join(", ")
        };
        let first = faces[0] as usize;
        let forward = l.run.iter().filter(|e| e.1).count();
        let at: At = self.at.of(first);
        MeshError::new(
            at,
            match l.run.len() {
                1 => format!(
                    "the mesh is open (not closed): {edge} of {} belongs to no other triangle (a hole, or a gap between corners that are not exactly equal: `weld` merges corners closer than a distance you give); a solid needs a closed surface, `mode = \"shell\"` takes an open one",
                    names(&faces)
                ),
                2 => format!(
                    "the mesh is inside out in part (not consistently oriented): {} and {} both traverse {edge} in the same direction (one of them is wound the other way)",
                    self.name(first),
                    self.name(faces[1] as usize)
                ),
                n => format!(
                    "the mesh is not manifold and {}: {edge} is shared by {n} triangles ({}), {forward} traversing it one way and {} the other; a closed surface's triangles pair up along each edge with opposite orientations (two, or four where two pieces touch)",
                    if n % 2 == 1 {
                        "open (not closed)"
                    } else {
                        "inside out in part"
                    },
                    names(&faces),
                    n - forward
                ),
            },
        )
    }
}

/// Whether m lies on the segment a–b strictly between its ends (m is
/// neither): collinear by exact predicates in the three coordinate planes,
/// then within the segment's box.
fn between(a: [f64; 3], m: [f64; 3], b: [f64; 3]) -> bool {
    if m == a || m == b {
        return false;
    }
    let inside = (0..3).all(|k| a[k].min(b[k]) <= m[k] && m[k] <= a[k].max(b[k]));
    inside
        && [(0, 1), (1, 2), (2, 0)]
            .iter()
            .all(|&(i, j)| orient2d(a, m, b, i, j) == 0)
}
