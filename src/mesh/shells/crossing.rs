//! The crossing search of `shells`: the first pair of triangles that
//! cross, from the pairs whose boxes meet (the triangles' tree joined with
//! itself, on every core), each pair tested with exact predicates
//! (Guigue and Devillers' test).

use super::super::bvh::{Bvh, Small};
use super::super::check::Mesh;
use super::super::exact::{P3, Plane, normal, orient2d, orient3d};

/// The first pair (by the first triangle's number, then the second's) of
/// triangles that cross, if any; on every core. `sorted`: the
/// triangles' boxes in the tree's items' order (`Bvh::sorted`).
///
/// NOTE: the pairs whose boxes meet come from the tree's self-join
/// (`Bvh::join`), cut into tasks that the threads take from a counter;
/// each thread keeps the least crossing pair it finds, and a pair that
/// cannot be less than one found (its first triangle past the least first
/// triangle found by any thread) is not tested. The least of the threads'
/// pairs is the least crossing pair whatever the threads' timing: the
/// same answer on any number of cores.
pub(super) fn first_crossing(
    mesh: &Mesh,
    pts: &[P3],
    sorted: &[Small],
    bvh: &Bvh,
    tiled: &[bool],
) -> Option<(usize, usize)> {
    let threads = super::super::threads_for(bvh.items.len(), 1);
    // Tasks of about 1/64 of a thread's share: enough for the threads to
    // even out, few enough that cutting them costs nothing.
    let size = (bvh.items.len() / (64 * threads)).max(256);
    first_crossing_on(mesh, pts, sorted, bvh, tiled, threads, size)
}

/// `first_crossing` on at most `threads` threads, the join cut into tasks
/// of `size` triangles; `tiled`: each vertex's `tiled` (or none).
pub(super) fn first_crossing_on(
    mesh: &Mesh,
    pts: &[P3],
    sorted: &[Small],
    bvh: &Bvh,
    tiled: &[bool],
    threads: usize,
    size: usize,
) -> Option<(usize, usize)> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let tasks = bvh.join_tasks(size);
    let threads = threads.clamp(1, tasks.len().max(1));
    let tri = |i: usize| mesh.faces[i].map(|k| pts[k as usize]);
    let planes = planes(mesh, pts);
    let best = AtomicUsize::new(usize::MAX);
    let next = AtomicUsize::new(0);
    let search = || -> Option<(usize, usize)> {
        let mut stack = Vec::with_capacity(64);
        let mut mine: Option<(usize, usize)> = None;
        loop {
            let t = next.fetch_add(1, Ordering::Relaxed);
            let Some(&task) = tasks.get(t) else {
                return mine;
            };
            // NOTE: inlined into the join's loop, a call a pair spared.
            bvh.join(
                sorted,
                task,
                &mut stack,
                #[inline(always)]
                |i, j| {
                    let (i, j) = (i as usize, j as usize);
                    if i > best.load(Ordering::Relaxed) || mine.is_some_and(|m| (i, j) >= m) {
                        return;
                    }
                    if cross_from(
                        mesh.faces[i],
                        mesh.faces[j],
                        [&planes[i], &planes[j]],
                        tiled,
                        || (tri(i), tri(j)),
                    ) {
                        mine = Some((i, j));
                        best.fetch_min(i, Ordering::Relaxed);
                    }
                },
            );
        }
    };
    if threads == 1 {
        return search();
    }
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads).map(|_| scope.spawn(search)).collect();
        handles
            .into_iter()
            .filter_map(|h| {
                h.join()
                    .expect("invariant: the crossing search does not panic")
            })
            .min()
    })
}

/// Whether two triangles (by their welded corners `f`, `g` and their
/// points) cross: share a segment inside both, or overlap in an area
/// facing the same way.
#[cfg(test)]
pub(super) fn cross(f: [u32; 3], g: [u32; 3], p: &[P3; 3], q: &[P3; 3]) -> bool {
    cross_from(f, g, [&Flat::of(p), &Flat::of(q)], &[], || (*p, *q))
}

/// A triangle's plane for the filter: x = (b − a) × (c − a) and the
/// largest of its components' magnitude bounds (|b − a|, |c − a| crossed
/// without cancellation), so that x · (d − a) is within 1e-15 · m · Σ|d −
/// a| of the exact orientation of (a, b, c, d) (`Plane::side`'s filter,
/// its per-axis bounds widened to their largest: the roundings of the
/// differences, the cross product and the dot product come to under
/// 7 · 2⁻⁵³ of Σ xmᵢ|dᵢ − aᵢ| ≤ m · Σ|dᵢ − aᵢ|).
///
/// NOTE: made once a triangle (32 bytes each), not once a pair: a
/// million-triangle mesh has some 8 million pairs whose boxes meet, most
/// of which the filter decides.
#[derive(Debug, Clone, Copy)]
pub(super) struct Flat {
    x: P3,
    m: f64,
}

impl Flat {
    #[inline]
    fn of(t: &[P3; 3]) -> Flat {
        let (x, xm) = normal(t);
        Flat {
            x,
            m: xm[0].max(xm[1]).max(xm[2]),
        }
    }

    /// Whether the points `d` all lie strictly on one side of the plane
    /// of the triangle whose first corner is `a`, by the filter alone
    /// (false: on both sides or on it, or the filter cannot tell).
    #[inline]
    fn strictly_one_side(&self, a: P3, d: &[P3]) -> bool {
        let side = |p: &P3| {
            let e = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
            let det = self.x[0] * e[0] + self.x[1] * e[1] + self.x[2] * e[2];
            let bound = 1e-15 * self.m * (e[0].abs() + e[1].abs() + e[2].abs());
            (det > bound) as i8 - (det < -bound) as i8
        };
        let s = side(&d[0]);
        s != 0 && d[1..].iter().all(|p| side(p) == s)
    }
}

/// Every triangle's `Flat`, on every core.
fn planes(mesh: &Mesh, pts: &[P3]) -> Vec<Flat> {
    super::super::filled(
        mesh.faces.len(),
        Flat {
            x: [0.0; 3],
            m: 0.0,
        },
        |i| Flat::of(&mesh.faces[i].map(|k| pts[k as usize])),
    )
}

/// `cross`, the triangles' points fetched (`points`) only when the
/// corners alone do not answer: a shared edge run both ways, or a shared
/// corner whose star is `tiled` (a vertex past its end: not tiled).
///
/// NOTE: a third of a smooth mesh's pairs are neighbours across an edge,
/// answered by their corners' numbers: their 18 coordinates, read from
/// wherever the corners' numbers put them, are not read at all.
#[inline(always)]
fn cross_from(
    f: [u32; 3],
    g: [u32; 3],
    [pf, pg]: [&Flat; 2],
    tiled: &[bool],
    points: impl FnOnce() -> ([P3; 3], [P3; 3]),
) -> bool {
    let at = f.map(|v| g.iter().position(|w| *w == v).unwrap_or(3));
    let shared = at.iter().filter(|m| **m < 3).count();
    if shared == 2 {
        // NOTE: two triangles that run their shared edge in opposite
        // directions (the neighbours of a closed surface) never cross:
        // not coplanar, they meet on the planes' line only along that
        // edge; coplanar, they lie on the two sides of it (side by
        // side) or face opposite ways (folded flat). The exact path
        // below answers the same (a test holds them equal); this
        // spares a third of a smooth mesh's pairs its predicates.
        // The edge from corner k to k + 1: the one without the corner
        // not shared.
        let alone = usize::from(at[1] == 3) + 2 * usize::from(at[2] == 3);
        let k = (alone + 1) % 3;
        if g[(at[(k + 1) % 3] + 1) % 3] == f[k] {
            return false;
        }
    }
    // The corner shared alone (by the corners' positions in f: 0, 1, 2).
    let one = usize::from(at[1] < 3) + 2 * usize::from(at[2] < 3);
    if shared == 1 && tiled.get(f[one] as usize) == Some(&true) {
        // NOTE: the most common pair of a smooth mesh's boxes that meet
        // (5 million of a million-triangle sphere's 9), answered without
        // their points.
        return false;
    }
    let (p, q) = points();
    let (p, q) = (&p, &q);
    match shared {
        2 => {}
        1 => {
            // NOTE: two triangles that share one corner v, the most
            // common pair of a mesh's boxes that meet (a million of them
            // in a sphere's two polar fans), meet only at v when p's two
            // other corners lie strictly on one side of q's plane: then
            // no predicate need be exact, and this filter (`Flat`'s, the
            // one `exact::Plane::side` tries first) decides most of them.
            // Undecided, the exact path answers (a test holds them equal).
            let k = one;
            if pg.strictly_one_side(q[0], &[p[(k + 1) % 3], p[(k + 2) % 3]]) {
                return false;
            }
        }
        // NOTE: no shared corner: p wholly on one side of q's plane, or q
        // of p's, meet nowhere; the same filter decides most such pairs of
        // a mesh's (neighbours a corner apart).
        0 if pg.strictly_one_side(q[0], p) || pf.strictly_one_side(p[0], q) => {
            return false;
        }
        _ => {}
    }
    cross_exact(f, g, p, q)
}

/// `cross` by the predicates alone.
pub(super) fn cross_exact(f: [u32; 3], g: [u32; 3], p: &[P3; 3], q: &[P3; 3]) -> bool {
    let shared = f.iter().filter(|v| g.contains(v)).count();
    if shared == 3 {
        // The same corners: the same way is a repeated surface (twins
        // wound opposite ways were set aside before).
        return true;
    }
    // The sides of p's corners of q's plane (a corner they share is on
    // it: welded corners are equal exactly when their points are).
    let side = |plane: &Plane, mine: u32, x: P3, theirs: &[u32; 3]| {
        if theirs.contains(&mine) {
            0
        } else {
            plane.side(x)
        }
    };
    let qp = Plane::of(q);
    let dp: [i8; 3] = std::array::from_fn(|k| side(&qp, f[k], p[k], &g));
    if dp.iter().all(|s| *s == 0) {
        return coplanar_overlap(p, q);
    }
    if !(dp.contains(&1) && dp.contains(&-1)) {
        // p meets q's plane at most along an edge or corner of p.
        return false;
    }
    let pp = Plane::of(p);
    let dq: [i8; 3] = std::array::from_fn(|k| side(&pp, g[k], q[k], &f));
    if !(dq.contains(&1) && dq.contains(&-1)) {
        return false;
    }
    // NOTE: Guigue and Devillers' canonical form: each triangle turned so
    // that its first corner is alone on its side of the other's plane
    // (positive), the other triangle's winding swapped when that side is
    // negative; the two segments on the planes' line then overlap in more
    // than a point exactly when both 4-point orientations below are
    // negative (zero: they meet at an end only, a touch).
    let (p, q) = canonical(*p, dp, *q);
    let dq2 = q.map(|x| orient3d(p[0], p[1], p[2], x));
    let (q, p) = canonical(q, dq2, p);
    orient3d(p[1], q[0], p[0], q[1]) < 0 && orient3d(p[0], q[0], p[2], q[2]) < 0
}

/// Turn `a` so that its first corner is the one alone on its side of the
/// other's plane (`s`: its corners' sides, both signs present); swap `b`'s
/// last two corners when that side is negative.
fn canonical(a: [P3; 3], s: [i8; 3], b: [P3; 3]) -> ([P3; 3], [P3; 3]) {
    let alone = (0..3)
        .find(|&i| s[i] != 0 && (0..3).all(|j| j == i || s[j] != s[i]))
        .expect("invariant: a triangle with corners on both sides has one alone on its side");
    let a = [a[alone], a[(alone + 1) % 3], a[(alone + 2) % 3]];
    let b = if s[alone] < 0 { [b[0], b[2], b[1]] } else { b };
    (a, b)
}

/// Two coplanar triangles overlap in an area and face the same way.
fn coplanar_overlap(p: &[P3; 3], q: &[P3; 3]) -> bool {
    // A projection in which p is not degenerate; q is in p's plane and not
    // degenerate either, so it is not degenerate in it.
    let Some((i, j, sp)) = [(1, 2), (2, 0), (0, 1)]
        .into_iter()
        .map(|(i, j)| (i, j, orient2d(p[0], p[1], p[2], i, j)))
        .find(|x| x.2 != 0)
    else {
        return false;
    };
    let sq = orient2d(q[0], q[1], q[2], i, j);
    if sq != sp {
        // Facing opposite ways: in contact, not overlapping.
        return false;
    }
    // Separating axis: an edge of either with the other wholly on its
    // outer closed side.
    let separated = |a: &[P3; 3], b: &[P3; 3]| {
        (0..3).any(|k| {
            let (u, v) = (a[k], a[(k + 1) % 3]);
            b.iter().all(|w| orient2d(u, v, *w, i, j) * sp <= 0)
        })
    };
    !(separated(p, q) || separated(q, p))
}

/// For each vertex, whether its star is tiled: the live triangles around it
/// (`shell` not `NONE`), seen along one coordinate axis, all turn the same
/// way about it, their edges opposite it cross a ray from it once, and
/// every edge at it is paired (as many triangles run it one way as the
/// other; `open`: the ends of the edges that are not). Then any two of
/// them meet only at it or along the edge they share, and never cross.
///
/// Why: each triangle (v, a, b) turns the same way about v seen along
/// axis k (the sign of its normal's component k, which the corner it is
/// seen from does not change), so each covers an angle in (0, π) about v
/// in that view. Paired edges make the far edges (a → b) close into
/// cycles around v, each of which covers the full turn a whole number
/// (at least 1) of times; the number of far edges the ray crosses is the
/// sum of those numbers. Once: one cycle, around once, so the triangles'
/// angles do not overlap, and two of them meet, in the view and so in
/// space, only at v or along a shared edge. The ray runs along axis i
/// from v, a hair above it along axis j ((i, j, k) a cyclic turn): a far
/// edge of a triangle that turns positively crosses it exactly when it
/// rises past v (a_j ≤ v_j < b_j), one that turns negatively when it
/// falls (b_j ≤ v_j < a_j); the others cross on the other side. Every
/// test is a comparison, or the sign of a normal's component where
/// `orient2d`'s filter decides it; where that filter cannot tell, the
/// axis is not used.
///
/// NOTE: a pass over the triangles (scattered to their corners, on one
/// core) in place of the filter's point reads and plane tests for every
/// pair that shares one corner: the most common pair of a smooth mesh.
pub(super) fn tiled(mesh: &Mesh, pts: &[P3], shell: &[u32], open: &[u32]) -> Vec<bool> {
    // Per vertex: for each axis k, bit 2k: a triangle turns positively,
    // bit 2k + 1: negatively (both: one does not turn, or cannot tell);
    // then each axis's count of far edges that cross its ray, up to 2.
    let mut seen = vec![[0u8; 4]; pts.len()];
    for (f, _) in mesh
        .faces
        .iter()
        .zip(shell)
        .filter(|(_, s)| **s != super::NONE)
    {
        let p = f.map(|k| pts[k as usize]);
        let (x, xm) = normal(&p);
        let turn: [u8; 3] = std::array::from_fn(|k| {
            let bound = 1e-15 * xm[k];
            if x[k] > bound {
                1
            } else if x[k] < -bound {
                2
            } else {
                3
            }
        });
        let bits = turn[0] | turn[1] << 2 | turn[2] << 4;
        for r in 0..3 {
            let (v, a, b) = (p[r], p[(r + 1) % 3], p[(r + 2) % 3]);
            let s = &mut seen[f[r] as usize];
            s[0] |= bits;
            for k in 0..3 {
                let j = (k + 2) % 3;
                let crosses = match turn[k] {
                    1 => a[j] <= v[j] && v[j] < b[j],
                    2 => b[j] <= v[j] && v[j] < a[j],
                    _ => false,
                };
                s[1 + k] = (s[1 + k] + u8::from(crosses)).min(2);
            }
        }
    }
    let mut tiled: Vec<bool> = seen
        .iter()
        .map(|s| (0..3).any(|k| matches!((s[0] >> (2 * k)) & 3, 1 | 2) && s[1 + k] == 1))
        .collect();
    for &v in open {
        tiled[v as usize] = false;
    }
    tiled
}
