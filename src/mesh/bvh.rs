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

/// A box in f32, rounded outward from an `Aabb`: it holds the box, so
/// two that meet include every pair whose boxes meet (and a few whose
/// boxes only nearly do, which the exact tests then answer).
#[derive(Debug, Clone, Copy)]
pub struct Small {
    pub lo: [f32; 3],
    pub hi: [f32; 3],
}

impl Small {
    pub fn of(b: &Aabb) -> Small {
        let down = |x: f64| {
            let y = x as f32;
            if f64::from(y) > x { y.next_down() } else { y }
        };
        let up = |x: f64| {
            let y = x as f32;
            if f64::from(y) < x { y.next_up() } else { y }
        };
        Small {
            lo: b.lo.map(down),
            hi: b.hi.map(up),
        }
    }

    /// The box as f64 (exactly).
    pub fn wide(&self) -> Aabb {
        Aabb {
            lo: self.lo.map(f64::from),
            hi: self.hi.map(f64::from),
        }
    }

    /// `Aabb::meets`, in f32.
    ///
    /// NOTE: written out again, not one generic function for both: the
    /// generic form (the corners passed as arrays) took the million-
    /// triangle sphere's report 35 ms longer, side by side.
    #[inline]
    pub fn meets(&self, o: &Small) -> bool {
        (self.lo[0] <= o.hi[0])
            & (o.lo[0] <= self.hi[0])
            & (self.lo[1] <= o.hi[1])
            & (o.lo[1] <= self.hi[1])
            & (self.lo[2] <= o.hi[2])
            & (o.lo[2] <= self.hi[2])
    }
}

/// A box a tree is built over: its f64 box (exactly).
pub trait Boxed: Copy + Sync {
    fn wide(&self) -> Aabb;
}

impl Boxed for Aabb {
    #[inline]
    fn wide(&self) -> Aabb {
        *self
    }
}

impl Boxed for Small {
    #[inline]
    fn wide(&self) -> Aabb {
        Small::wide(self)
    }
}

/// Triangles a leaf holds at most.
///
/// NOTE: 8, not 4: half the nodes and a third fewer node pairs in the
/// self-join, whose leaf pairs' 64 box tests are gathered as bits without
/// a branch (`join`); the crossing search of a million triangles took 8 %
/// less time.
const LEAF: usize = 8;
// A leaf pair's box tests fit the bits of a u64.
const _: () = assert!(LEAF * LEAF <= 64);

/// A bounding-volume hierarchy over triangles' boxes: the items sorted
/// along a Morton (Z-order) curve through their boxes' centres, then cut
/// in halves of that order down to leaves (O(n), without recursion).
pub struct Bvh {
    pub nodes: Vec<Node>,
    /// Triangle numbers, each leaf's a contiguous range.
    pub items: Vec<u32>,
}

/// NOTE: aligned to 64 bytes (its size): a node is one cache line, so a
/// box test in the self-join reads one line, not two.
#[derive(Debug, Clone, Copy)]
#[repr(C, align(64))]
pub struct Node {
    pub bounds: Aabb,
    /// A leaf: items[start..end]; else children `left` and `left + 1`.
    pub start: u32,
    pub end: u32,
    pub left: u32,
}

impl Bvh {
    pub fn build<B: Boxed>(boxes: &[B], items: Vec<u32>) -> Bvh {
        // Few items are not worth a thread.
        let threads = super::threads_for(items.len(), 1 << 16);
        Bvh::build_on(boxes, items, threads)
    }

    /// `build`, the items' Morton codes computed on `threads` threads.
    ///
    /// NOTE: a linear-time build (issue 33, item 4), in place of median
    /// splits along each node's longest axis (`select_nth` at every level:
    /// O(n log n), ~10 % of a million triangles' profile). The items are
    /// sorted (radix, stable) by the Morton code of their boxes' centres,
    /// quantized to 16 bits an axis in the box of the centres, and each
    /// node's range cut at its middle (the smaller half first): the nodes'
    /// ranges, and so their count, are those the median splits made;
    /// only which items fall in each changes. The bounds are then joined
    /// from the leaves up. No answer depends on the tree's shape: the
    /// self-join visits every pair of items whose boxes meet, whatever
    /// the tree (the crossing search keeps the least crossing pair, a
    /// winding is a sum); `tests` hold the join to every pair.
    pub fn build_on<B: Boxed>(boxes: &[B], items: Vec<u32>, threads: usize) -> Bvh {
        let items = morton_sorted(boxes, items, threads);
        let n = items.len();
        let mut nodes = Vec::with_capacity(node_count(n));
        nodes.push(Node {
            bounds: Aabb::empty(),
            start: 0,
            end: n as u32,
            left: 0,
        });
        // Breadth first: a node's children come after it, so the bounds
        // can be joined in one backward sweep.
        let mut at = 0;
        while at < nodes.len() {
            let Node { start, end, .. } = nodes[at];
            if (end - start) as usize > LEAF {
                let mid = start + (end - start) / 2;
                let left = nodes.len() as u32;
                nodes[at].left = left;
                for (s, e) in [(start, mid), (mid, end)] {
                    nodes.push(Node {
                        bounds: Aabb::empty(),
                        start: s,
                        end: e,
                        left: 0,
                    });
                }
            }
            at += 1;
        }
        for at in (0..nodes.len()).rev() {
            let node = nodes[at];
            nodes[at].bounds = if node.left == 0 {
                items[node.start as usize..node.end as usize]
                    .iter()
                    .fold(Aabb::empty(), |b, &i| b.join(boxes[i as usize].wide()))
            } else {
                let l = node.left as usize;
                nodes[l].bounds.join(nodes[l + 1].bounds)
            };
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
    /// (smaller, larger) item, and perhaps a few whose `Small`s alone meet:
    /// a dual-tree self-join, without recursion (`stack` is scratch space,
    /// reused between tasks). `sorted` holds the boxes in the items' order
    /// as `Small`s (`sorted`: `sorted[k]` holds the box of `items[k]`).
    ///
    /// NOTE: the boxes in the items' order, so that a leaf's boxes are
    /// read one after another rather than each from wherever its item's
    /// number puts it; in f32, rounded outward, half the bytes.
    ///
    /// NOTE: hand-written (parry's and bvh's trees answer one box's query
    /// at a time, the per-triangle search this replaces): a million
    /// triangles' queries each descend from the root, where the join
    /// descends each pair of nearby nodes once. `tests` hold it to the
    /// per-item query's pairs (all of them, each once, and no pair whose
    /// `Small`s do not meet).
    pub fn join(
        &self,
        sorted: &[Small],
        task: Task,
        stack: &mut Vec<Task>,
        mut visit: impl FnMut(u32, u32),
    ) {
        stack.clear();
        let (na, nb) = (&self.nodes[task.0 as usize], &self.nodes[task.1 as usize]);
        if task.0 == task.1 || na.bounds.meets(&nb.bounds) {
            stack.push(task);
        }
        // NOTE: a pair of distinct nodes is pushed only if their bounds
        // meet (tested here, while the nodes are in cache, not when it is
        // popped): the stack holds fewer pairs, and the pairs visited and
        // their order are the same.
        let push = |stack: &mut Vec<Task>, t: Task| {
            if t.0 == t.1 || {
                let (x, y) = (&self.nodes[t.0 as usize], &self.nodes[t.1 as usize]);
                x.bounds.meets(&y.bounds)
            } {
                stack.push(t);
            }
        };
        while let Some(Task(a, b)) = stack.pop() {
            let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
            if a == b {
                if self.is_leaf(na) {
                    let r = na.start as usize..na.end as usize;
                    let (items, bs) = (&self.items[r.clone()], &sorted[r]);
                    // NOTE: the pairs whose boxes meet gathered as bits
                    // first, then visited: no branch a box test (a coin
                    // toss, mispredicted half the time).
                    let mut met = 0u64;
                    for k in 0..bs.len() {
                        for l in k + 1..bs.len() {
                            met |= u64::from(bs[k].meets(&bs[l])) << (k * LEAF + l);
                        }
                    }
                    while met != 0 {
                        let bit = met.trailing_zeros() as usize;
                        met &= met - 1;
                        let (x, y) = (items[bit / LEAF], items[bit % LEAF]);
                        visit(x.min(y), x.max(y));
                    }
                } else {
                    self.split(a, b).for_each(|t| push(stack, t));
                }
                continue;
            }
            if self.is_leaf(na) && self.is_leaf(nb) {
                let rb = nb.start as usize..nb.end as usize;
                let (ys, bys) = (&self.items[rb.clone()], &sorted[rb]);
                let ra = na.start as usize..na.end as usize;
                let (xs, bxs) = (&self.items[ra.clone()], &sorted[ra]);
                let mut met = 0u64;
                for (k, bx) in bxs.iter().enumerate() {
                    for (l, by) in bys.iter().enumerate() {
                        met |= u64::from(bx.meets(by)) << (k * LEAF + l);
                    }
                }
                while met != 0 {
                    let bit = met.trailing_zeros() as usize;
                    met &= met - 1;
                    let (x, y) = (xs[bit / LEAF], ys[bit % LEAF]);
                    visit(x.min(y), x.max(y));
                }
            } else {
                self.split(a, b).for_each(|t| push(stack, t));
            }
        }
    }

    /// The items' boxes in their order (`join`'s `sorted`), on every core.
    pub fn sorted(&self, boxes: &[Small]) -> Vec<Small> {
        let empty = Small {
            lo: [0.0; 3],
            hi: [0.0; 3],
        };
        super::filled(self.items.len(), empty, |k| boxes[self.items[k] as usize])
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

/// Bits of each axis in a Morton code (three axes in a u64's 48 low bits).
const BITS: u32 = 16;

/// `items` sorted by the Morton codes of their boxes' centres (in the box
/// of those centres), stably: items of equal codes keep their order.
fn morton_sorted<B: Boxed>(boxes: &[B], items: Vec<u32>, threads: usize) -> Vec<u32> {
    let n = items.len();
    if n <= LEAF {
        return items;
    }
    // Halves added: no overflow.
    let centre = |i: u32| -> P3 {
        let b = boxes[i as usize].wide();
        std::array::from_fn(|k| b.lo[k] / 2.0 + b.hi[k] / 2.0)
    };
    let piece = n.div_ceil(threads.max(1)).max(1);
    let span = |items: &[u32]| {
        items.iter().fold(Aabb::empty(), |b, &i| {
            let c = centre(i);
            b.join(Aabb { lo: c, hi: c })
        })
    };
    let whole = parallel(&items, piece, span)
        .into_iter()
        .fold(Aabb::empty(), Aabb::join);
    let top = ((1u32 << BITS) - 1) as f64;
    let scale: P3 = std::array::from_fn(|k| {
        let w = whole.hi[k] - whole.lo[k];
        // A flat or unbounded extent: that axis adds nothing to the code.
        if w > 0.0 && w.is_finite() {
            top / w
        } else {
            0.0
        }
    });
    let code = |i: u32| -> u64 {
        let c = centre(i);
        (0..3).fold(0u64, |m, k| {
            // NaN (an empty box) becomes 0; the clamp keeps rounding in range.
            let q = ((c[k] - whole.lo[k]) * scale[k]).clamp(0.0, top) as u64;
            m | (spread(q) << k)
        })
    };
    let codes: Vec<u64> = parallel(&items, piece, |items| {
        items.iter().map(|&i| code(i)).collect::<Vec<_>>()
    })
    .concat();
    radix_sorted(codes, items)
}

/// `f` of each `piece`-long slice of `items`, on a thread each.
fn parallel<T: Send>(items: &[u32], piece: usize, f: impl Fn(&[u32]) -> T + Sync) -> Vec<T> {
    if items.len() <= piece {
        return vec![f(items)];
    }
    std::thread::scope(|scope| {
        let f = &f;
        let handles: Vec<_> = items
            .chunks(piece)
            .map(|c| scope.spawn(move || f(c)))
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("invariant: a Morton code does not panic"))
            .collect()
    })
}

/// The 16 low bits of `x` spread to every third bit.
fn spread(x: u64) -> u64 {
    let x = x & 0xffff;
    let x = (x | (x << 16)) & 0x0000_ff00_00ff;
    let x = (x | (x << 8)) & 0x00f0_0f00_f00f;
    let x = (x | (x << 4)) & 0x0c30_c30c_30c3;
    (x | (x << 2)) & 0x2492_4924_9249
}

/// `items` sorted by their `codes` (48 bits, one an item), stably: a
/// radix sort, 16 bits a pass, a pass skipped where every code has one
/// digit.
///
/// NOTE: codes and items in two lists (12 bytes an item, twice for the
/// sort's two buffers), not one list of (code, item) pairs (16 bytes,
/// padded): 8 MB less at a million items.
fn radix_sorted(mut codes: Vec<u64>, mut items: Vec<u32>) -> Vec<u32> {
    let n = codes.len();
    let mut other_codes = vec![0u64; n];
    let mut other_items = vec![0u32; n];
    let mut count = vec![0u32; 1 << 16];
    for pass in 0..3 {
        let digit = |k: u64| ((k >> (16 * pass)) & 0xffff) as usize;
        count.iter_mut().for_each(|c| *c = 0);
        for &k in &codes {
            count[digit(k)] += 1;
        }
        if count.iter().any(|&c| c as usize == n) {
            continue;
        }
        let mut at = 0u32;
        for c in count.iter_mut() {
            let here = *c;
            *c = at;
            at += here;
        }
        for (&k, &i) in codes.iter().zip(&items) {
            let slot = &mut count[digit(k)];
            other_codes[*slot as usize] = k;
            other_items[*slot as usize] = i;
            *slot += 1;
        }
        std::mem::swap(&mut codes, &mut other_codes);
        std::mem::swap(&mut items, &mut other_items);
    }
    items
}

/// How many nodes a build makes for `n` items (every split halves a node's
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
