//! The crossing search of `shells`: the first pair of triangles that
//! cross, from the pairs whose boxes meet (the triangles' tree joined with
//! itself, on every core), each pair tested with exact predicates
//! (Guigue and Devillers' test).

use super::super::bvh::{Aabb, Bvh};
use super::super::check::Mesh;
use super::super::exact::{P3, Plane, orient2d, orient3d};

/// The first pair (by the first triangle's number, then the second's) of
/// triangles that cross, if any; on every core.
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
    boxes: &[Aabb],
    bvh: &Bvh,
) -> Option<(usize, usize)> {
    let threads = super::super::threads_for(bvh.items.len(), 1);
    // Tasks of about 1/64 of a thread's share: enough for the threads to
    // even out, few enough that cutting them costs nothing.
    let size = (bvh.items.len() / (64 * threads)).max(256);
    first_crossing_on(mesh, pts, boxes, bvh, threads, size)
}

/// `first_crossing` on at most `threads` threads, the join cut into tasks
/// of `size` triangles.
pub(super) fn first_crossing_on(
    mesh: &Mesh,
    pts: &[P3],
    boxes: &[Aabb],
    bvh: &Bvh,
    threads: usize,
    size: usize,
) -> Option<(usize, usize)> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let tasks = bvh.join_tasks(size);
    let threads = threads.clamp(1, tasks.len().max(1));
    let tri = |i: usize| mesh.faces[i].map(|k| pts[k as usize]);
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
            bvh.join(boxes, task, &mut stack, |i, j| {
                let (i, j) = (i as usize, j as usize);
                if i > best.load(Ordering::Relaxed) || mine.is_some_and(|m| (i, j) >= m) {
                    return;
                }
                if cross(mesh.faces[i], mesh.faces[j], &tri(i), &tri(j)) {
                    mine = Some((i, j));
                    best.fetch_min(i, Ordering::Relaxed);
                }
            });
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
pub(super) fn cross(f: [u32; 3], g: [u32; 3], p: &[P3; 3], q: &[P3; 3]) -> bool {
    // NOTE: two triangles that run their shared edge in opposite
    // directions (the neighbours of a closed surface) never cross: not
    // coplanar, they meet on the planes' line only along that edge; coplanar,
    // they lie on the two sides of it (side by side) or face opposite ways
    // (folded flat). The exact path below answers the same (a test holds
    // them equal); this spares a third of a smooth mesh's pairs its
    // predicates.
    if let Some(k) = (0..3).find(|&k| g.contains(&f[k]) && g.contains(&f[(k + 1) % 3])) {
        let (u, v) = (f[k], f[(k + 1) % 3]);
        let at = g.iter().position(|x| *x == v).expect("v is shared");
        if g[(at + 1) % 3] == u && !g.contains(&f[(k + 2) % 3]) {
            return false;
        }
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
