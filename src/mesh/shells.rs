//! A solid mesh split into its closed shells and checked to bound one
//! solid: the shells must not cross themselves or each other, and their
//! windings must nest (an outward shell, inside it inward shells that are
//! its cavities, inside those outward islands, …), so that every point is
//! inside the solid once or not at all. The integral over all the
//! triangles is then the solid's (a cavity's negative volume subtracts).
//!
//! - Shells: triangles joined across edges shared by exactly two of them
//!   (after a pair of triangles with the same corners wound opposite ways,
//!   the wall between two pieces that share a face, is set aside: it
//!   cancels in every integral). An edge shared by four or more (pieces
//!   that touch along an edge) joins nothing, unless a piece would be
//!   left open without it.
//! - Crossings (`crossing`): every pair of triangles whose boxes meet,
//!   found by joining a bounding-volume hierarchy with itself, is tested
//!   with exact predicates (`exact`; Guigue and Devillers' test). Two triangles cross when they
//!   share a segment inside both (not coplanar), or overlap in an area
//!   while facing the same way (coplanar). Touching along an edge or at a
//!   point, and coplanar triangles facing opposite ways (two pieces in
//!   contact along a face), do not cross. Two that share only a corner
//!   whose triangles tile the turn about it (`crossing::tiled`) do not.
//! - Nesting: the winding number, at one corner of each shell, of all
//!   the other triangles (a ray along +x with a symbolic perturbation, so
//!   it never grazes an edge): 0 for an outward shell, 1 for an inward one.

use super::bvh::{Aabb, Bvh, Small};
use super::check::{Edge, Mesh, point, triangle};
use super::exact::{self, P3, orient2d, orient3d};
use super::{MeshError, Sums};
use crate::numeric::{DD, Real};
use crossing::first_crossing;
#[cfg(test)]
use crossing::{cross, cross_exact, first_crossing_on};

/// No shell: a triangle set aside (its opposite twin cancels it).
const NONE: u32 = u32::MAX;

/// Check that the (closed, consistently oriented) mesh bounds one solid.
/// Returns the number of shells.
pub fn check(mesh: &Mesh) -> Result<usize, MeshError> {
    check_with(mesh, mesh.edges(), || {
        volume_sign(&mesh.sums_dd(super::Mode::Solid, mesh.reference()))
    })
}

/// `check`, given the mesh's edges (`Mesh::edges`), which it lets go
/// of once the shells are found: the mesh itself is only read, so that
/// its integrals can be summed meanwhile (`MeshBody::load_with`). `whole`:
/// the sign of the whole mesh's volume (`volume_sign`), asked only when
/// the mesh is one shell, whose volume it is.
///
/// NOTE: one shell's winding is the sign of the sums `MeshBody::load_with`
/// adds up meanwhile anyway (in double-double, its bound far tighter than
/// `volumes`' f64 sums'), not a second pass over every triangle: a
/// million-triangle mesh is one shell, and that pass took 50 ms of its
/// 0.6 s, alone on one core.
pub fn check_with(
    mesh: &Mesh,
    edges: Vec<Edge>,
    whole: impl FnOnce() -> i8,
) -> Result<usize, MeshError> {
    let n = mesh.faces.len();
    let live = cancel_twins(mesh, &edges);
    let (shell, open) = components(mesh, &live, &edges);
    drop(edges);
    let count = shell
        .iter()
        .filter(|s| **s != NONE)
        .fold(0, |m, s| m.max(*s + 1)) as usize;
    if count == 0 {
        return Err(MeshError::new(
            super::At::Whole,
            "the mesh encloses no volume: every triangle has a twin wound the other way",
        ));
    }
    let pts = scaled(mesh)?;
    // NOTE: the tiled stars (`crossing::tiled`, one pass over the
    // triangles on one core) are found on a thread of their own while the
    // tree is built, whose radix sort and node pass are one core's too.
    let (tiled, bvh, sorted) = std::thread::scope(|scope| {
        let tiled = || crossing::tiled(mesh, &pts, &shell, &open);
        let tiled = (super::threads_for(n, 1 << 16) > 1).then(|| scope.spawn(tiled));
        let boxes = boxes_of(mesh, &pts);
        let order: Vec<u32> = (0..n as u32)
            .filter(|&i| shell[i as usize] != NONE)
            .collect();
        let bvh = Bvh::build(&boxes, order);
        // NOTE: the boxes again, in the tree's item order (`Bvh::join`):
        // a leaf's read one after another.
        let sorted = bvh.sorted(&boxes);
        let tiled = match tiled {
            Some(h) => h
                .join()
                .expect("invariant: finding tiled stars does not panic"),
            None => crossing::tiled(mesh, &pts, &shell, &open),
        };
        (tiled, bvh, sorted)
    });
    if let Some((i, j)) = first_crossing(mesh, &pts, &sorted, &bvh, &tiled) {
        let same = shell[i] == shell[j];
        return Err(MeshError::new(
            mesh.at.of(i),
            format!(
                "{} and {} cross: {}; a solid's surface must not pass through itself (pieces may touch along an edge or at a corner, or face to face)",
                triangle(i, mesh.at.of(i)),
                triangle(j, mesh.at.of(j)),
                if same {
                    "the surface intersects itself"
                } else {
                    "two of the mesh's shells intersect or overlap"
                }
            ),
        ));
    }
    // Each shell's winding: the sign of its volume.
    let first = first_triangles(&shell, count);
    if count == 1 {
        let sign = whole();
        if sign == 0 {
            return Err(no_sign(mesh, 0, first[0]));
        }
        if sign < 0 {
            return Err(MeshError::new(
                super::At::Whole,
                "the mesh is inside out: its volume is negative, its faces point inward; flip the winding (every triangle's corners counter-clockwise seen from outside)",
            ));
        }
        return Ok(1);
    }
    let signs = volumes(mesh, &shell, count)?;
    let name = |s: usize| {
        let t = first[s];
        format!("shell {} (from {})", s + 1, triangle(t, mesh.at.of(t)))
    };
    let (list, start) = members(&shell, count);
    // NOTE: a shell winds around no point outside its box: the shells
    // whose boxes hold a corner are found in a tree of the shells' boxes,
    // most corners of a mesh of separate pieces have none (winding 0 at
    // once), and a ray need go no further than those shells' boxes.
    let mut shell_boxes = vec![Aabb::empty(); count];
    for (&t, b) in bvh.items.iter().zip(&sorted) {
        let s = &mut shell_boxes[shell[t as usize] as usize];
        *s = s.join(b.wide());
    }
    drop(sorted);
    let shell_tree = Bvh::build(&shell_boxes, (0..count as u32).collect());
    let near = Near {
        boxes: &shell_boxes,
        tree: &shell_tree,
    };
    let windings = per_shell(count, pts.len(), |s, scratch| {
        let mine = &list[start[s]..start[s + 1]];
        winding_around(mesh, &pts, &bvh, &near, &shell, mine, s as u32, scratch)
    });
    for (s, winding) in windings.into_iter().enumerate() {
        let c = match winding {
            Ok(c) => c,
            Err([(a, wa), (b, wb)]) => {
                return Err(MeshError::new(
                    mesh.at.of(a),
                    format!(
                        "{} passes through another shell where they only touch (along edges lying in its faces): the other shells wind {wa} times around a corner of {} and {wb} times around a corner of {}; a solid's surface must not pass through itself",
                        name(s),
                        triangle(a, mesh.at.of(a)),
                        triangle(b, mesh.at.of(b)),
                    ),
                ));
            }
        };
        let t = first[s];
        match (signs[s], c) {
            (1, 0) | (-1, 1) => {}
            (1, 1) => {
                return Err(MeshError::new(
                    mesh.at.of(t),
                    format!(
                        "{} lies inside another outward shell and is wound outward too: the volume they share would count twice; a shell inside a solid must be wound inward to be a cavity",
                        name(s)
                    ),
                ));
            }
            (-1, 0) => {
                return Err(MeshError::new(
                    mesh.at.of(t),
                    format!(
                        "{} is wound inward (its faces point inward) but lies in no solid (outside every outward shell, or in another cavity): it is a cavity of nothing; flip its winding (every triangle's corners counter-clockwise seen from outside)",
                        name(s)
                    ),
                ));
            }
            (_, c) => {
                return Err(MeshError::new(
                    mesh.at.of(t),
                    format!(
                        "{} is wound {} where the other shells wind {} times around it: outward and inward shells must alternate from the outside in (a solid, its cavities, islands in them)",
                        name(s),
                        if signs[s] > 0 { "outward" } else { "inward" },
                        c
                    ),
                ));
            }
        }
    }
    Ok(count)
}

/// For each triangle, whether it counts: a triangle with the same three
/// corners as another wound the other way is set aside with it.
///
/// NOTE: two triangles with the same corners share all three edges, so
/// only triangles that meet another with the same corners in an edge's run
/// can have a twin: those few are paired as the whole list once was
/// (sorted by corners, winding and number), the rest pass at once.
fn cancel_twins(mesh: &Mesh, edges: &[Edge]) -> Vec<bool> {
    let faces = &mesh.faces;
    let mut maybe = vec![false; faces.len()];
    let same = |x: u32, y: u32| {
        let (mut a, mut b) = (faces[x as usize], faces[y as usize]);
        a.sort_unstable();
        b.sort_unstable();
        a == b
    };
    for run in edges.chunk_by(|x, y| x.0 == y.0) {
        if run.len() > 16 {
            // A crowded edge: all its triangles take the sort.
            run.iter().for_each(|e| maybe[e.1 as usize] = true);
            continue;
        }
        for (k, x) in run.iter().enumerate() {
            for y in &run[k + 1..] {
                if same(x.1, y.1) {
                    maybe[x.1 as usize] = true;
                    maybe[y.1 as usize] = true;
                }
            }
        }
    }
    let mut keyed: Vec<([u32; 3], bool, u32)> = faces
        .iter()
        .enumerate()
        .filter(|(i, _)| maybe[*i])
        .map(|(i, f)| {
            let mut s = *f;
            s.sort_unstable();
            // Even permutation of the sorted triple: the same winding.
            let rot = [s, [s[1], s[2], s[0]], [s[2], s[0], s[1]]];
            (s, rot.contains(f), i as u32)
        })
        .collect();
    keyed.sort_unstable();
    let mut live = vec![true; faces.len()];
    for run in keyed.chunk_by(|x, y| x.0 == y.0) {
        let plus: Vec<u32> = run.iter().filter(|k| k.1).map(|k| k.2).collect();
        let minus: Vec<u32> = run.iter().filter(|k| !k.1).map(|k| k.2).collect();
        for (p, m) in plus.iter().zip(&minus) {
            live[*p as usize] = false;
            live[*m as usize] = false;
        }
    }
    live
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let g = parent[parent[x as usize] as usize];
        parent[x as usize] = g;
        x = g;
    }
    x
}

fn union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra == rb {
        return false;
    }
    let (lo, hi) = (ra.min(rb), ra.max(rb));
    parent[hi as usize] = lo;
    true
}

/// Each live triangle's shell (numbered by their first triangles, in the
/// file's order), `NONE` for those set aside; and the ends of the edges
/// whose live triangles do not pair up (as many one way as the other),
/// for `crossing::tiled`: none in a mesh without T-junctions.
fn components(mesh: &Mesh, live: &[bool], all: &[Edge]) -> (Vec<u32>, Vec<u32>) {
    let n = mesh.faces.len();
    // The live triangles' edges, in the sorted order (the whole list when
    // every triangle is live, as in nearly every mesh).
    let kept: Vec<Edge>;
    let edges: &[Edge] = if live.iter().all(|l| *l) {
        all
    } else {
        kept = all.iter().filter(|e| live[e.1 as usize]).copied().collect();
        &kept
    };
    let mut parent: Vec<u32> = (0..n as u32).collect();
    let mut crowded: Vec<&[(u64, u32, bool)]> = Vec::new();
    let mut open = Vec::new();
    for run in edges.chunk_by(|x, y| x.0 == y.0) {
        let paired = if run.len() == 2 {
            union(&mut parent, run[0].1, run[1].1);
            run[0].2 != run[1].2
        } else {
            crowded.push(run);
            2 * run.iter().filter(|e| e.2).count() == run.len()
        };
        if !paired {
            open.extend([(run[0].0 >> 32) as u32, run[0].0 as u32]);
        }
    }
    // The two sides of each T-junction (`classes`) are one shell.
    for &(a, b) in mesh.joins() {
        if live[a as usize] && live[b as usize] {
            union(&mut parent, a, b);
        }
    }
    // NOTE: an edge shared by four or more triangles joins nothing, so
    // that two pieces touching along it stay two shells; but a piece that
    // is not closed without it (one touching itself there, or two pieces
    // that share a face triangulated differently) is joined across it.
    // Merging only ever joins, so this ends after at most as many passes
    // as there are such edges, in practice one or two.
    loop {
        let mut changed = false;
        for run in &crowded {
            let mut balance: Vec<(u32, i32)> = run
                .iter()
                .map(|e| (find(&mut parent, e.1), if e.2 { 1 } else { -1 }))
                .collect();
            balance.sort_unstable();
            let open = balance
                .chunk_by(|x, y| x.0 == y.0)
                .any(|g| g.iter().map(|x| x.1).sum::<i32>() != 0);
            if open {
                for w in run.windows(2) {
                    changed |= union(&mut parent, w[0].1, w[1].1);
                }
            }
        }
        if !changed {
            break;
        }
    }
    let mut number = vec![NONE; n];
    let mut shell = vec![NONE; n];
    let mut next = 0;
    for i in 0..n {
        if !live[i] {
            continue;
        }
        let r = find(&mut parent, i as u32) as usize;
        if number[r] == NONE {
            number[r] = next;
            next += 1;
        }
        shell[i] = number[r];
    }
    (shell, open)
}

/// Each triangle's box (of its scaled corners), on every core, in f32
/// rounded outward (`Small`).
///
/// NOTE: in f32 (24 bytes a triangle, not 48): half the bytes to write,
/// gather into the tree's order and read in the self-join; the tree's
/// bounds hold them, so every pair of triangles whose boxes meet is still
/// visited (and a few whose f32 boxes alone do, which the exact tests
/// answer).
fn boxes_of(mesh: &Mesh, pts: &[P3]) -> Vec<Small> {
    let empty = Small {
        lo: [0.0; 3],
        hi: [0.0; 3],
    };
    super::filled(mesh.faces.len(), empty, |t| {
        Small::of(&Aabb::of(&mesh.faces[t].map(|k| pts[k as usize])))
    })
}

fn first_triangles(shell: &[u32], count: usize) -> Vec<usize> {
    let mut first = vec![usize::MAX; count];
    for (i, s) in shell.iter().enumerate() {
        if *s != NONE && first[*s as usize] == usize::MAX {
            first[*s as usize] = i;
        }
    }
    first
}

/// Each shell's winding: 1 outward, −1 inward, from the sign of its
/// volume (about its first corner, with the sums' error bound).
fn volumes(mesh: &Mesh, shell: &[u32], count: usize) -> Result<Vec<i8>, MeshError> {
    let first = first_triangles(shell, count);
    let refs: Vec<[f64; 3]> = first
        .iter()
        .map(|t| mesh.vertices[mesh.faces[*t][0] as usize])
        .collect();
    // NOTE: each shell's terms are added in the file's order, on one
    // thread (the shells are shared out in ranges, each thread reading
    // every triangle and keeping its own): the same sums on any number of
    // cores. Only the volume is summed (`Sums::add_volume`).
    let threads = super::threads_for(count, 1024);
    let range = |t: usize| t * count / threads..(t + 1) * count / threads;
    let sum = |t: usize| {
        let mine = range(t);
        let mut sums: Vec<Sums<f64>> = vec![Sums::new(); mine.len()];
        for (i, f) in mesh.faces.iter().enumerate() {
            let s = shell[i] as usize;
            if !mine.contains(&s) {
                continue;
            }
            let p = refs[s];
            let v = f.map(|k| {
                let c = mesh.vertices[k as usize];
                std::array::from_fn(|j| DD::of(c[j]) - DD::of(p[j]))
            });
            sums[s - mine.start].add_volume(v);
        }
        sums
    };
    let sums: Vec<Sums<f64>> = if threads == 1 {
        sum(0)
    } else {
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..threads).map(|t| scope.spawn(move || sum(t))).collect();
            handles
                .into_iter()
                .flat_map(|h| {
                    h.join()
                        .expect("invariant: a shell's volume does not panic")
                })
                .collect()
        })
    };
    let mut signs = Vec::with_capacity(count);
    for (s, sum) in sums.iter().enumerate() {
        match volume_sign(sum) {
            0 => return Err(no_sign(mesh, s, first[s])),
            sign => signs.push(sign),
        }
    }
    Ok(signs)
}

/// The sign of the volume whose terms `sums` adds up (`Sums::add` or
/// `add_volume`): 1 or −1, or 0 when its bound cannot tell it from zero.
pub fn volume_sign<T: Real>(sums: &Sums<T>) -> i8 {
    let w = sums.value[0].f64();
    if w.abs() <= sums.error()[0] {
        0
    } else if w > 0.0 {
        1
    } else {
        -1
    }
}

/// Shell `s`, from triangle `t`, whose volume's sign cannot be told.
fn no_sign(mesh: &Mesh, s: usize, t: usize) -> MeshError {
    MeshError::new(
        mesh.at.of(t),
        format!(
            "shell {} (from {}) encloses no volume that can be told from zero, so whether it is wound outward or inward cannot be told",
            s + 1,
            triangle(t, mesh.at.of(t))
        ),
    )
}

/// The corners scaled by one power of two so that the largest magnitude is
/// below 1 (exact), for the predicates; refuses a nonzero coordinate
/// below `exact::TINY` of that (see `exact`).
pub(super) fn scaled(mesh: &Mesh) -> Result<Vec<P3>, MeshError> {
    let big = mesh
        .vertices
        .iter()
        .flat_map(|v| v.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    // 2^e > big, e = exponent of big + 1.
    let e = if big == 0.0 {
        0
    } else {
        ((big.to_bits() >> 52) & 0x7ff) as i32 - 1022
    };
    let mul = |x: f64| {
        // x · 2^−e in steps that stay within f64's range.
        let mut y = x;
        let mut k = -e;
        while k != 0 {
            let step = k.clamp(-600, 600);
            y *= f64::powi(2.0, step);
            k -= step;
        }
        y
    };
    let pts: Vec<P3> = mesh.vertices.iter().map(|v| v.map(mul)).collect();
    for (i, f) in mesh.faces.iter().enumerate() {
        for &k in f {
            let p = pts[k as usize];
            if p.iter().any(|x| *x != 0.0 && x.abs() < exact::TINY) {
                return Err(MeshError::new(
                    mesh.at.of(i),
                    format!(
                        "{} has the corner {}, a coordinate of which is nonzero but less than 2⁻²⁰⁰ of the mesh's largest ({big}): too wide a range of magnitudes to check the mesh's shells exactly; round it to zero",
                        triangle(i, mesh.at.of(i)),
                        point(mesh.vertices[k as usize])
                    ),
                ));
            }
        }
    }
    Ok(pts)
}

/// The winding number, at the corners of shell `s` that lie on no other
/// shell's surface, of every other live triangle: the same at each of them,
/// or the two corners (their triangles and windings) where it differs.
///
/// NOTE: every free corner is asked, not the first alone: a shell can pass
/// into another exactly through edges lying in the other's faces (a double
/// pyramid whose waist lies in a cube's face, one apex inside), where no
/// two triangles cross and only the corners on either side tell. Each
/// corner is asked once (`seen`, stamped with the shell); most have no
/// other shell's box around them and cost one look in the tree of boxes.
/// A shell all of whose corners lie on other shells takes the perturbed
/// point's answer at its last corner.
#[allow(clippy::too_many_arguments)] // the shared read-only state of one judgement
fn winding_around(
    mesh: &Mesh,
    pts: &[P3],
    bvh: &Bvh,
    near: &Near,
    shell: &[u32],
    members: &[u32],
    s: u32,
    scratch: &mut Scratch,
) -> Result<i64, [(usize, i64); 2]> {
    let mut last = 0;
    let mut free: Option<(usize, i64)> = None;
    for &i in members {
        for &k in &mesh.faces[i as usize] {
            if scratch.seen[k as usize] == s + 1 {
                continue;
            }
            scratch.seen[k as usize] = s + 1;
            let (w, on) = winding_at(pts[k as usize], mesh, pts, bvh, near, shell, s, scratch);
            last = w;
            if on {
                continue;
            }
            match free {
                None => free = Some((i as usize, w)),
                Some((t, w0)) if w0 != w => return Err([(t, w0), (i as usize, w)]),
                Some(_) => {}
            }
        }
    }
    Ok(free.map_or(last, |(_, w)| w))
}

/// One thread's working space for the shells' windings: a mark per
/// vertex (`winding_around`), the shells around a corner and a tree walk's
/// stack, reused from corner to corner.
struct Scratch {
    seen: Vec<u32>,
    around: Vec<u32>,
    stack: Vec<u32>,
}

/// `f(s, scratch)` for every shell s, on every core: shells in blocks the
/// threads take from a counter, each thread with its own `Scratch`
/// (`vertices` marks), the results in the shells' order.
/// Each shell's answer depends on the shell alone, so they are the
/// one-core answers, and the caller reads them in order.
fn per_shell<R: Send>(
    count: usize,
    vertices: usize,
    f: impl Fn(usize, &mut Scratch) -> R + Sync,
) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    const BLOCK: usize = 256;
    let threads = super::threads_for(count, BLOCK);
    let next = AtomicUsize::new(0);
    // Each thread's marks allocated here, on the calling thread (memory a
    // thread allocates stays in its own arena once freed).
    let scratches = (0..threads).map(|_| Scratch {
        seen: vec![0u32; vertices],
        around: Vec::new(),
        stack: Vec::new(),
    });
    let work = |mut scratch: Scratch| {
        let mut out = Vec::new();
        loop {
            let b = next.fetch_add(1, Ordering::Relaxed);
            if b * BLOCK >= count {
                return out;
            }
            for s in b * BLOCK..((b + 1) * BLOCK).min(count) {
                out.push((s, f(s, &mut scratch)));
            }
        }
    };
    let mut parts: Vec<Vec<(usize, R)>> = if threads == 1 {
        scratches.map(work).collect()
    } else {
        std::thread::scope(|scope| {
            let work = &work;
            let handles: Vec<_> = scratches
                .map(|scratch| scope.spawn(move || work(scratch)))
                .collect();
            handles
                .into_iter()
                .map(|h| {
                    h.join()
                        .expect("invariant: a shell's judgement does not panic")
                })
                .collect()
        })
    };
    let mut all: Vec<(usize, R)> = parts.drain(..).flatten().collect();
    all.sort_unstable_by_key(|x| x.0);
    all.into_iter().map(|x| x.1).collect()
}

/// Each shell's triangles, in the file's order (`start[s]..start[s + 1]`
/// of the list).
fn members(shell: &[u32], count: usize) -> (Vec<u32>, Vec<usize>) {
    let mut start = vec![0usize; count + 1];
    for s in shell.iter().filter(|s| **s != NONE) {
        start[*s as usize + 1] += 1;
    }
    for k in 0..count {
        start[k + 1] += start[k];
    }
    let mut fill = start.clone();
    let mut list = vec![0u32; start[count]];
    for (i, s) in shell.iter().enumerate() {
        if *s != NONE {
            list[fill[*s as usize]] = i as u32;
            fill[*s as usize] += 1;
        }
    }
    (list, start)
}

/// The winding number at v (perturbed to (x, y + ε, z + ε²)) of the live
/// triangles not in shell `s`, by a ray along +x; and whether v lies on
/// one of them.
#[allow(clippy::too_many_arguments)] // the shared read-only state of one judgement
fn winding_at(
    v: P3,
    mesh: &Mesh,
    pts: &[P3],
    bvh: &Bvh,
    near: &Near,
    shell: &[u32],
    s: u32,
    scratch: &mut Scratch,
) -> (i64, bool) {
    let Scratch { around, stack, .. } = scratch;
    near.around(v, s, around, stack);
    let Some(reach) = around
        .iter()
        .map(|t| near.boxes[*t as usize].hi[0])
        .reduce(f64::max)
    else {
        return (0, false);
    };
    let mut w = 0i64;
    let mut on = false;
    if bvh.nodes.is_empty() {
        return (0, false);
    }
    stack.clear();
    stack.push(0);
    while let Some(at) = stack.pop() {
        let node = &bvh.nodes[at as usize];
        let b = &node.bounds;
        if b.hi[0] < v[0]
            || b.lo[0] > reach
            || b.lo[1] > v[1]
            || b.hi[1] < v[1]
            || b.lo[2] > v[2]
            || b.hi[2] < v[2]
        {
            continue;
        }
        if bvh.is_leaf(node) {
            for &t in &bvh.items[node.start as usize..node.end as usize] {
                let of = shell[t as usize];
                if of == s || around.binary_search(&of).is_err() {
                    continue;
                }
                match ray_hit(v, &mesh.faces[t as usize].map(|k| pts[k as usize])) {
                    Hit::Miss => {}
                    Hit::On => on = true,
                    Hit::Ahead(sign) => w += i64::from(sign),
                }
            }
        } else {
            stack.push(node.left);
            stack.push(node.left + 1);
        }
    }
    (w, on)
}

/// The shells' boxes and a tree of them.
struct Near<'a> {
    boxes: &'a [Aabb],
    tree: &'a Bvh,
}

impl Near<'_> {
    /// The shells other than `s` whose (closed) boxes hold v, sorted, into
    /// `out` (`stack` is scratch space).
    fn around(&self, v: P3, s: u32, out: &mut Vec<u32>, stack: &mut Vec<u32>) {
        out.clear();
        let inside = |b: &Aabb| (0..3).all(|k| b.lo[k] <= v[k] && v[k] <= b.hi[k]);
        if self.tree.nodes.is_empty() {
            return;
        }
        stack.clear();
        stack.push(0);
        while let Some(at) = stack.pop() {
            let node = &self.tree.nodes[at as usize];
            if !inside(&node.bounds) {
                continue;
            }
            if self.tree.is_leaf(node) {
                for &t in &self.tree.items[node.start as usize..node.end as usize] {
                    if t != s && inside(&self.boxes[t as usize]) {
                        out.push(t);
                    }
                }
            } else {
                stack.push(node.left);
                stack.push(node.left + 1);
            }
        }
        out.sort_unstable();
    }
}

enum Hit {
    Miss,
    /// The point is on the triangle.
    On,
    /// The ray crosses it ahead, its normal's x component of this sign.
    Ahead(i8),
}

/// The ray from v (perturbed as in `winding_at`) along +x and a triangle.
fn ray_hit(v: P3, t: &[P3; 3]) -> Hit {
    let area = orient2d(t[0], t[1], t[2], 1, 2);
    if area == 0 {
        // Parallel to the ray: the perturbed ray misses it.
        return Hit::Miss;
    }
    for k in 0..3 {
        let (u, w) = (t[k], t[(k + 1) % 3]);
        let mut s = orient2d(u, w, v, 1, 2);
        if s == 0 {
            // The perturbation's terms: −(w_z − u_z) ε + (w_y − u_y) ε².
            s = match w[2].partial_cmp(&u[2]).expect("finite coordinates") {
                std::cmp::Ordering::Greater => -1,
                std::cmp::Ordering::Less => 1,
                std::cmp::Ordering::Equal => {
                    match w[1].partial_cmp(&u[1]).expect("finite coordinates") {
                        std::cmp::Ordering::Greater => 1,
                        std::cmp::Ordering::Less => -1,
                        std::cmp::Ordering::Equal => return Hit::Miss,
                    }
                }
            };
        }
        if s != area {
            return Hit::Miss;
        }
    }
    let side = orient3d(t[0], t[1], t[2], v);
    if side == 0 {
        return Hit::On;
    }
    if side != area {
        Hit::Ahead(area)
    } else {
        Hit::Miss
    }
}

mod crossing;
#[cfg(test)]
mod tests;
