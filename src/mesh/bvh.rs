//! A bounding-volume hierarchy over axis-aligned boxes (a mesh's
//! triangles', or its shells'): the pairs of triangles `shells` tests for
//! crossing (a self-join of the tree, `Bvh::join`), and the triangles a ray
//! meets, in O(log n) a query.

use super::exact::P3;

/// An axis-aligned box.
#[derive(Debug, Clone, Copy)]
pub struct Aabb {
    pub lo: P3,
    pub hi: P3,
}

impl Aabb {
    pub fn of(t: &[P3; 3]) -> Aabb {
        Aabb {
            lo: std::array::from_fn(|k| t[0][k].min(t[1][k]).min(t[2][k])),
            hi: std::array::from_fn(|k| t[0][k].max(t[1][k]).max(t[2][k])),
        }
    }
    pub fn empty() -> Aabb {
        Aabb {
            lo: [f64::INFINITY; 3],
            hi: [f64::NEG_INFINITY; 3],
        }
    }
    pub fn join(self, o: Aabb) -> Aabb {
        Aabb {
            lo: std::array::from_fn(|k| self.lo[k].min(o.lo[k])),
            hi: std::array::from_fn(|k| self.hi[k].max(o.hi[k])),
        }
    }
    /// Closed boxes meet (touching counts).
    ///
    /// NOTE: the six comparisons joined with `&`, not `&&`: no branch to
    /// mispredict in the self-join's innermost loop, where the answer is a
    /// coin toss.
    #[inline]
    pub fn meets(&self, o: &Aabb) -> bool {
        (self.lo[0] <= o.hi[0])
            & (o.lo[0] <= self.hi[0])
            & (self.lo[1] <= o.hi[1])
            & (o.lo[1] <= self.hi[1])
            & (self.lo[2] <= o.hi[2])
            & (o.lo[2] <= self.hi[2])
    }
}

/// Triangles a leaf holds at most.
const LEAF: usize = 4;

/// A bounding-volume hierarchy over triangles' boxes, built top-down by
/// median splits along each node's longest axis (O(n log n)), without
/// recursion.
pub struct Bvh {
    pub nodes: Vec<Node>,
    /// Triangle numbers, each leaf's a contiguous range.
    pub items: Vec<u32>,
}

#[derive(Debug, Clone, Copy)]
pub struct Node {
    pub bounds: Aabb,
    /// A leaf: items[start..end]; else children `left` and `left + 1`.
    pub start: u32,
    pub end: u32,
    pub left: u32,
}

impl Bvh {
    pub fn build(boxes: &[Aabb], items: Vec<u32>) -> Bvh {
        // Few items are not worth a thread.
        let threads = super::threads_for(items.len(), 1 << 14);
        Bvh::build_on(boxes, items, threads)
    }

    /// `build`, its subtrees below the top levels built on `threads`
    /// threads.
    ///
    /// NOTE: the top levels (log₂ of the threads) are split on one thread;
    /// each subtree left below them is built on its own (its items a slice of their
    /// own), and its nodes then appended, renumbered. The tree has the
    /// same shape as one built on one thread (the same splits), numbered
    /// otherwise, which no answer depends on (the crossing search keeps
    /// the least pair, a winding is a sum).
    pub fn build_on(boxes: &[Aabb], mut items: Vec<u32>, threads: usize) -> Bvh {
        // Enough levels for a subtree per thread.
        let top = threads.next_power_of_two().trailing_zeros() as usize;
        let depth = if threads > 1 && items.len() > LEAF {
            top
        } else {
            usize::MAX
        };
        let mut nodes = Vec::with_capacity(node_count(items.len()));
        let centres = centres(boxes, threads);
        let (boxes, centres) = (boxes, &centres[..]);
        let pending = grow(boxes, centres, &mut items, 0, depth, &mut nodes);
        if pending.is_empty() {
            return Bvh { nodes, items };
        }
        // Each pending subtree's items, in the order of their ranges.
        let mut rest: &mut [u32] = &mut items;
        let mut taken = 0;
        let mut slices = Vec::with_capacity(pending.len());
        let mut order: Vec<usize> = (0..pending.len()).collect();
        order.sort_unstable_by_key(|&k| nodes[pending[k]].start);
        for &k in &order {
            let (s, e) = (
                nodes[pending[k]].start as usize,
                nodes[pending[k]].end as usize,
            );
            let (_, tail) = std::mem::take(&mut rest).split_at_mut(s - taken);
            let (mine, tail) = tail.split_at_mut(e - s);
            rest = tail;
            taken = e;
            // NOTE: each subtree's nodes allocated here, on the calling
            // thread, to their exact count: memory a thread allocates stays
            // in its own arena once freed, where the caller cannot reuse it.
            let room = Vec::with_capacity(node_count(e - s));
            slices.push((k, s, mine, room));
        }
        let subtrees: Vec<(usize, Vec<Node>)> = std::thread::scope(|scope| {
            let handles: Vec<_> = slices
                .into_iter()
                .map(|(k, s, mine, mut room)| {
                    scope.spawn(move || {
                        grow(boxes, centres, mine, s, usize::MAX, &mut room);
                        (k, room)
                    })
                })
                .collect();
            handles
                .into_iter()
                .map(|h| {
                    h.join()
                        .expect("invariant: building a subtree does not panic")
                })
                .collect()
        });
        for (k, sub) in subtrees {
            let at = pending[k];
            let base = nodes.len() as u32;
            // Local node l ≥ 1 is base + l − 1 (local 0, the root, is `at`,
            // and no node's child); `left` 0 marks a leaf.
            nodes[at] = renumbered(&sub[0], base);
            nodes.extend(sub[1..].iter().map(|n| renumbered(n, base)));
        }
        Bvh { nodes, items }
    }

    pub fn is_leaf(&self, n: &Node) -> bool {
        n.left == 0
    }

    /// The self-join cut into tasks that together visit every pair of
    /// items once (`join` each): the top of the tree expanded until each
    /// task's nodes hold at most `size` items, node pairs whose bounds do
    /// not meet left out. In a fixed order, so that threads can take them
    /// from a counter.
    pub fn join_tasks(&self, size: usize) -> Vec<Task> {
        let mut out = Vec::new();
        if self.nodes.is_empty() {
            return out;
        }
        let count = |a: u32| {
            let n = &self.nodes[a as usize];
            (n.end - n.start) as usize
        };
        let mut todo = vec![Task(0, 0)];
        while let Some(Task(a, b)) = todo.pop() {
            let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
            if a != b && !na.bounds.meets(&nb.bounds) {
                continue;
            }
            let big = count(a).max(count(b)) > size;
            if !big || (self.is_leaf(na) && self.is_leaf(nb)) {
                out.push(Task(a, b));
                continue;
            }
            todo.extend(self.split(a, b));
        }
        out
    }

    /// The children of a node pair (a self pair splits into its two
    /// children's self pairs and their pair; a pair into the larger
    /// node's children, each with the other).
    fn split(&self, a: u32, b: u32) -> impl Iterator<Item = Task> {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        let size = |n: &Node| n.end - n.start;
        let tasks: [Option<Task>; 3] = if a == b {
            let l = na.left;
            [
                Some(Task(l, l)),
                Some(Task(l + 1, l + 1)),
                Some(Task(l, l + 1)),
            ]
        } else if !self.is_leaf(na) && (self.is_leaf(nb) || size(na) >= size(nb)) {
            [Some(Task(na.left, b)), Some(Task(na.left + 1, b)), None]
        } else {
            [Some(Task(a, nb.left)), Some(Task(a, nb.left + 1)), None]
        };
        tasks.into_iter().flatten()
    }

    /// Every pair of items under a task whose boxes meet, each once, as
    /// (smaller, larger) item: a dual-tree self-join, without recursion
    /// (`stack` is scratch space, reused between tasks). `sorted` holds
    /// the boxes in the items' order (`sorted`: `sorted[k]` is the box of
    /// `items[k]`).
    ///
    /// NOTE: the boxes in the items' order, so that a leaf's boxes are
    /// read one after another rather than each from wherever its item's
    /// number puts it: the same pairs, in the same order.
    ///
    /// NOTE: hand-written (parry's and bvh's trees answer one box's query
    /// at a time, the per-triangle search this replaces): a million
    /// triangles' queries each descend from the root, where the join
    /// descends each pair of nearby nodes once. `tests` hold it to the
    /// per-item query's pairs exactly.
    pub fn join(
        &self,
        sorted: &[Aabb],
        task: Task,
        stack: &mut Vec<Task>,
        mut visit: impl FnMut(u32, u32),
    ) {
        stack.clear();
        stack.push(task);
        while let Some(Task(a, b)) = stack.pop() {
            let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
            if a == b {
                if self.is_leaf(na) {
                    let r = na.start as usize..na.end as usize;
                    let (items, bs) = (&self.items[r.clone()], &sorted[r]);
                    for (k, (&x, bx)) in items.iter().zip(bs).enumerate() {
                        for (&y, by) in items[k + 1..].iter().zip(&bs[k + 1..]) {
                            if bx.meets(by) {
                                visit(x.min(y), x.max(y));
                            }
                        }
                    }
                } else {
                    stack.extend(self.split(a, b));
                }
                continue;
            }
            if !na.bounds.meets(&nb.bounds) {
                continue;
            }
            if self.is_leaf(na) && self.is_leaf(nb) {
                let rb = nb.start as usize..nb.end as usize;
                let (ys, bys) = (&self.items[rb.clone()], &sorted[rb]);
                let ra = na.start as usize..na.end as usize;
                for (&x, bx) in self.items[ra.clone()].iter().zip(&sorted[ra]) {
                    if !bx.meets(&nb.bounds) {
                        continue;
                    }
                    for (&y, by) in ys.iter().zip(bys) {
                        if bx.meets(by) {
                            visit(x.min(y), x.max(y));
                        }
                    }
                }
            } else {
                stack.extend(self.split(a, b));
            }
        }
    }

    /// The items' boxes in their order (`join`'s `sorted`), on every
    /// core (each thread writes, and so faults in, its share's pages).
    pub fn sorted(&self, boxes: &[Aabb]) -> Vec<Aabb> {
        let n = self.items.len();
        let threads = super::threads_for(n, 1 << 16);
        if threads == 1 {
            return self.items.iter().map(|&i| boxes[i as usize]).collect();
        }
        let mut out = vec![Aabb::empty(); n];
        let piece = n.div_ceil(threads).max(1);
        std::thread::scope(|scope| {
            for (out, items) in out.chunks_mut(piece).zip(self.items.chunks(piece)) {
                scope.spawn(move || {
                    for (b, &i) in out.iter_mut().zip(items) {
                        *b = boxes[i as usize];
                    }
                });
            }
        });
        out
    }

    /// The items whose boxes meet `b` (the per-item query the join
    /// replaces; kept for the tests that hold the join to it).
    pub fn query(&self, boxes: &[Aabb], b: &Aabb, mut visit: impl FnMut(u32)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = vec![0u32];
        while let Some(at) = stack.pop() {
            let node = &self.nodes[at as usize];
            if !node.bounds.meets(b) {
                continue;
            }
            if self.is_leaf(node) {
                for &j in &self.items[node.start as usize..node.end as usize] {
                    if boxes[j as usize].meets(b) {
                        visit(j);
                    }
                }
            } else {
                stack.push(node.left);
                stack.push(node.left + 1);
            }
        }
    }
}

/// A tree over `items` (numbered from `offset` in the whole list), by
/// median splits along each node's longest axis, without recursion; nodes
/// at `depth` with more than a leaf's items are left unsplit and returned
/// (the pending subtrees' roots).
fn grow(
    boxes: &[Aabb],
    centres: &[P3],
    items: &mut [u32],
    offset: usize,
    depth: usize,
    nodes: &mut Vec<Node>,
) -> Vec<usize> {
    let mut pending = Vec::new();
    nodes.push(Node {
        bounds: Aabb::empty(),
        start: offset as u32,
        end: (offset + items.len()) as u32,
        left: 0,
    });
    let centre = |i: u32, k: usize| centres[i as usize][k];
    let mut stack = vec![(0usize, 0usize)];
    while let Some((at, level)) = stack.pop() {
        let (s, e) = (
            nodes[at].start as usize - offset,
            nodes[at].end as usize - offset,
        );
        if e - s > LEAF && level == depth {
            pending.push(at);
            continue;
        }
        let bounds = items[s..e]
            .iter()
            .fold(Aabb::empty(), |b, &i| b.join(boxes[i as usize]));
        nodes[at].bounds = bounds;
        if e - s <= LEAF {
            continue;
        }
        let k = (0..3)
            .max_by(|&a, &b| {
                (bounds.hi[a] - bounds.lo[a]).total_cmp(&(bounds.hi[b] - bounds.lo[b]))
            })
            .expect("three axes");
        let mid = (e - s) / 2;
        items[s..e].select_nth_unstable_by(mid, |&a, &b| centre(a, k).total_cmp(&centre(b, k)));
        let left = nodes.len();
        for (a, b) in [(s, s + mid), (s + mid, e)] {
            nodes.push(Node {
                bounds: Aabb::empty(),
                start: (offset + a) as u32,
                end: (offset + b) as u32,
                left: 0,
            });
        }
        nodes[at].left = left as u32;
        stack.push((left, level + 1));
        stack.push((left + 1, level + 1));
    }
    pending
}

/// Each box's centre (halves added: no overflow), which the splits
/// compare: computed once rather than at each comparison, on `threads`
/// threads.
fn centres(boxes: &[Aabb], threads: usize) -> Vec<P3> {
    let centre = |b: &Aabb| std::array::from_fn(|k| b.lo[k] / 2.0 + b.hi[k] / 2.0);
    if threads <= 1 {
        return boxes.iter().map(centre).collect();
    }
    let mut out = vec![[0.0; 3]; boxes.len()];
    let piece = boxes.len().div_ceil(threads).max(1);
    std::thread::scope(|scope| {
        for (out, boxes) in out.chunks_mut(piece).zip(boxes.chunks(piece)) {
            scope.spawn(move || {
                for (c, b) in out.iter_mut().zip(boxes) {
                    *c = centre(b);
                }
            });
        }
    });
    out
}

/// A subtree's node moved to the whole tree, its nodes from `base` on.
fn renumbered(n: &Node, base: u32) -> Node {
    Node {
        left: if n.left == 0 { 0 } else { base + n.left - 1 },
        ..*n
    }
}

/// How many nodes `grow` makes for `n` items (every split halves a node's
/// items, the smaller half first): a sum over the levels, each of which
/// holds nodes of at most two sizes.
fn node_count(n: usize) -> usize {
    let mut level: Vec<(usize, usize)> = vec![(n, 1)];
    let mut total = 0;
    while !level.is_empty() {
        let mut next: Vec<(usize, usize)> = Vec::with_capacity(2);
        for (size, count) in level {
            total += count;
            if size > LEAF {
                for half in [size / 2, size - size / 2] {
                    match next.iter_mut().find(|x| x.0 == half) {
                        Some(x) => x.1 += count,
                        None => next.push((half, count)),
                    }
                }
            }
        }
        level = next;
    }
    total
}

/// A pair of nodes to join (equal: a node with itself).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Task(pub u32, pub u32);

#[cfg(test)]
mod tests;
