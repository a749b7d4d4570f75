//! A bounding-volume hierarchy over axis-aligned boxes (a mesh's
//! triangles', or its shells'): the pairs of triangles `shells` tests for
//! crossing, and the triangles a ray meets, in O(log n) a query.

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
    pub fn meets(&self, o: &Aabb) -> bool {
        (0..3).all(|k| self.lo[k] <= o.hi[k] && o.lo[k] <= self.hi[k])
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
    pub fn build(boxes: &[Aabb], mut items: Vec<u32>) -> Bvh {
        let mut nodes: Vec<Node> = Vec::with_capacity(2 * items.len() / LEAF + 1);
        nodes.push(Node {
            bounds: Aabb::empty(),
            start: 0,
            end: items.len() as u32,
            left: 0,
        });
        let centre = |i: u32, k: usize| {
            let b = &boxes[i as usize];
            b.lo[k] / 2.0 + b.hi[k] / 2.0
        };
        let mut stack = vec![0usize];
        while let Some(at) = stack.pop() {
            let (s, e) = (nodes[at].start as usize, nodes[at].end as usize);
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
                    start: a as u32,
                    end: b as u32,
                    left: 0,
                });
            }
            nodes[at].left = left as u32;
            stack.push(left);
            stack.push(left + 1);
        }
        Bvh { nodes, items }
    }

    pub fn is_leaf(&self, n: &Node) -> bool {
        n.left == 0
    }
}
