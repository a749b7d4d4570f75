//! The self-join against the per-item query it replaces and against every
//! pair: the same pairs, each once, however the join is cut into tasks
//! (the join's boxes are the f32 `Small`s, rounded outward: every pair
//! whose boxes meet, and a few whose `Small`s alone do).

use super::*;
use proptest::prelude::*;

/// Every pair (i < j) whose boxes meet, by the per-item query.
fn by_query(bvh: &Bvh, boxes: &[Aabb]) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for &i in &bvh.items {
        bvh.query(boxes, &boxes[i as usize], |j| {
            if j > i {
                out.push((i, j));
            }
        });
    }
    out.sort_unstable();
    out
}

/// Every pair whose boxes meet, by the join cut into tasks of `size`,
/// unsorted (a pair seen twice would show).
fn by_join(bvh: &Bvh, boxes: &[Aabb], size: usize) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    let mut stack = Vec::new();
    let small: Vec<Small> = boxes.iter().map(Small::of).collect();
    let sorted = bvh.sorted(&small);
    for task in bvh.join_tasks(size) {
        bvh.join(&sorted, task, &mut stack, |i, j| out.push((i, j)));
    }
    out
}

fn brute(boxes: &[Aabb], items: &[u32]) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for &i in items {
        for &j in items {
            if i < j && boxes[i as usize].meets(&boxes[j as usize]) {
                out.push((i, j));
            }
        }
    }
    out.sort_unstable();
    out
}

/// Every pair (i < j) whose `Small` boxes meet.
fn brute_small(boxes: &[Aabb], items: &[u32]) -> Vec<(u32, u32)> {
    let small: Vec<Small> = boxes.iter().map(Small::of).collect();
    let mut out = Vec::new();
    for &i in items {
        for &j in items {
            if i < j && small[i as usize].meets(&small[j as usize]) {
                out.push((i, j));
            }
        }
    }
    out.sort_unstable();
    out
}

fn check(boxes: &[Aabb], items: Vec<u32>, size: usize) -> Result<(), TestCaseError> {
    let want = brute(boxes, &items);
    let want_small = brute_small(boxes, &items);
    prop_assert!(want.iter().all(|p| want_small.binary_search(p).is_ok()));
    let bvh = Bvh::build(boxes, items);
    prop_assert_eq!(&by_query(&bvh, boxes), &want);
    let mut got = by_join(&bvh, boxes, size);
    let n = got.len();
    got.sort_unstable();
    got.dedup();
    prop_assert_eq!(got.len(), n, "a pair was visited twice");
    // Every pair whose boxes meet, and only pairs whose `Small`s meet (the
    // nodes' f64 bounds may leave out a pair whose `Small`s alone meet).
    prop_assert!(
        want.iter().all(|p| got.binary_search(p).is_ok()),
        "a pair was missed"
    );
    prop_assert!(got.iter().all(|p| want_small.binary_search(p).is_ok()));
    Ok(())
}

/// Boxes a hair apart or a hair overlapping (a gap or overlap of a few
/// f64 units, far below an f32's): their `Small`s meet.
fn near_box() -> impl Strategy<Value = Aabb> {
    (prop::array::uniform3(0u8..6), -4i32..5, 0usize..3).prop_map(|(lo, step, axis)| {
        let lo = lo.map(|x| 0.3 + f64::from(x) * 0.125);
        let mut hi = lo.map(|x| x + 0.125);
        let mut h = hi[axis];
        for _ in 0..step.unsigned_abs() {
            h = if step < 0 { h.next_down() } else { h.next_up() };
        }
        hi[axis] = h;
        Aabb { lo, hi }
    })
}

/// A box on a coarse grid (so that boxes touch, coincide and nest often),
/// possibly flat or a point.
fn grid_box() -> impl Strategy<Value = Aabb> {
    (
        prop::array::uniform3(0i32..12),
        prop::array::uniform3(0i32..4),
    )
        .prop_map(|(lo, d)| Aabb {
            lo: lo.map(f64::from),
            hi: std::array::from_fn(|k| f64::from(lo[k] + d[k])),
        })
}

/// A small box anywhere in the unit cube.
fn scattered_box() -> impl Strategy<Value = Aabb> {
    (
        prop::array::uniform3(0.0f64..1.0),
        prop::array::uniform3(0.0f64..0.1),
    )
        .prop_map(|(lo, d)| Aabb {
            lo,
            hi: std::array::from_fn(|k| lo[k] + d[k]),
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_join_finds_exactly_the_pairs_the_query_finds_on_a_grid(
        boxes in prop::collection::vec(grid_box(), 0..300),
        size in 1usize..64,
    ) {
        let items = (0..boxes.len() as u32).collect();
        check(&boxes, items, size)?;
    }

    #[test]
    fn the_join_finds_exactly_the_pairs_the_query_finds_on_scattered_boxes(
        boxes in prop::collection::vec(scattered_box(), 0..400),
        size in 1usize..200,
    ) {
        let items = (0..boxes.len() as u32).collect();
        check(&boxes, items, size)?;
    }

    #[test]
    fn the_join_finds_every_pair_of_boxes_a_hair_apart_or_overlapping(
        boxes in prop::collection::vec(near_box(), 0..200),
        size in 1usize..64,
    ) {
        let items = (0..boxes.len() as u32).collect();
        check(&boxes, items, size)?;
    }

    #[test]
    fn a_small_box_holds_its_box_and_no_f32_box_inside_it_does(
        lo in prop::array::uniform3(-1e6f64..1e6),
        d in prop::array::uniform3(0.0f64..1e3),
    ) {
        let b = Aabb { lo, hi: std::array::from_fn(|k| lo[k] + d[k]) };
        let s = Small::of(&b);
        let w = s.wide();
        for k in 0..3 {
            prop_assert!(w.lo[k] <= b.lo[k] && b.hi[k] <= w.hi[k]);
            prop_assert!(f64::from(s.lo[k].next_up()) > b.lo[k]);
            prop_assert!(f64::from(s.hi[k].next_down()) < b.hi[k]);
        }
    }

    #[test]
    fn the_join_covers_a_subset_of_the_items(
        boxes in prop::collection::vec(grid_box(), 1..200),
        keep in prop::collection::vec(any::<bool>(), 200),
    ) {
        let items = (0..boxes.len() as u32).filter(|i| keep[*i as usize]).collect();
        check(&boxes, items, 8)?;
    }
}

#[test]
fn one_box_repeated_many_times_pairs_every_two() {
    let b = Aabb {
        lo: [0.0; 3],
        hi: [1.0; 3],
    };
    let boxes = vec![b; 50];
    let bvh = Bvh::build(&boxes, (0..50).collect());
    let got = by_join(&bvh, &boxes, 4);
    assert_eq!(got.len(), 50 * 49 / 2);
}

#[test]
fn an_empty_tree_has_no_pairs() {
    let bvh = Bvh::build::<Aabb>(&[], Vec::new());
    assert!(by_join(&bvh, &[], 1).is_empty());
}

/// Every node's bounds hold its items' boxes, its children split its items,
/// and every item is in one leaf.
fn well_formed(bvh: &Bvh, boxes: &[Aabb]) {
    let mut seen = vec![0u32; boxes.len()];
    let mut stack = vec![0u32];
    while let Some(at) = stack.pop() {
        let n = &bvh.nodes[at as usize];
        for &i in &bvh.items[n.start as usize..n.end as usize] {
            let b = &boxes[i as usize];
            assert!((0..3).all(|k| n.bounds.lo[k] <= b.lo[k] && b.hi[k] <= n.bounds.hi[k]));
        }
        if bvh.is_leaf(n) {
            for &i in &bvh.items[n.start as usize..n.end as usize] {
                seen[i as usize] += 1;
            }
        } else {
            let (l, r) = (&bvh.nodes[n.left as usize], &bvh.nodes[n.left as usize + 1]);
            assert_eq!((l.start, l.end, r.end), (n.start, r.start, n.end));
            stack.extend([n.left, n.left + 1]);
        }
    }
    assert!(seen.iter().all(|s| *s == 1));
}

#[test]
fn a_tree_built_on_many_threads_finds_the_pairs_one_built_on_one_finds() {
    let mut x = 0x2545_f491_4f6c_dd1du64;
    let mut r = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let boxes: Vec<Aabb> = (0..40_000)
        .map(|_| {
            let lo = [r(), r(), r()];
            Aabb {
                lo,
                hi: std::array::from_fn(|k| lo[k] + 0.01 * r()),
            }
        })
        .collect();
    let items: Vec<u32> = (0..boxes.len() as u32).collect();
    let one = Bvh::build_on(&boxes, items.clone(), 1);
    let four = Bvh::build_on(&boxes, items, 4);
    well_formed(&one, &boxes);
    well_formed(&four, &boxes);
    let pairs = |b: &Bvh| {
        let mut p = by_join(b, &boxes, 512);
        p.sort_unstable();
        p
    };
    let want = pairs(&one);
    assert!(!want.is_empty());
    assert_eq!(pairs(&four), want);
    assert_eq!(by_query(&four, &boxes), want);
}

#[test]
fn the_node_count_is_the_count_a_build_makes() {
    for n in [0usize, 1, 4, 5, 9, 17, 1000, 40_001] {
        let boxes: Vec<Aabb> = (0..n)
            .map(|i| Aabb {
                lo: [i as f64; 3],
                hi: [i as f64 + 0.5; 3],
            })
            .collect();
        let bvh = Bvh::build_on(&boxes, (0..n as u32).collect(), 1);
        assert_eq!(bvh.nodes.len(), node_count(n).max(1), "{n}");
    }
}

#[test]
fn spreading_puts_each_bit_three_places_apart() {
    for x in [0u64, 1, 2, 3, 0x8000, 0xffff, 0x1234, 0xa5a5] {
        let want = (0..16).fold(0u64, |m, b| m | (((x >> b) & 1) << (3 * b)));
        assert_eq!(spread(x), want, "{x:#x}");
    }
}

#[test]
fn the_radix_sort_orders_as_a_stable_sort_by_key() {
    let mut x = 0x9e37_79b9_7f4a_7c15u64;
    let keyed: Vec<(u64, u32)> = (0..5000u32)
        .map(|i| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Few distinct keys in every 16-bit digit: ties, and passes
            // with one digit skipped.
            let k = (x % 7) | ((x >> 8) % 3) << 16 | ((x >> 16) % 5) << 32;
            (k, i)
        })
        .collect();
    let mut want = keyed.clone();
    want.sort_by_key(|p| p.0);
    let want: Vec<u32> = want.into_iter().map(|p| p.1).collect();
    let (codes, items): (Vec<u64>, Vec<u32>) = keyed.into_iter().unzip();
    assert_eq!(radix_sorted(codes, items), want);
}

#[test]
fn the_tree_is_the_same_built_on_one_thread_or_four() {
    let boxes: Vec<Aabb> = (0..70_000u32)
        .map(|i| {
            let t = f64::from(i) * 0.001;
            let lo = [t.sin(), t.cos(), (3.0 * t).sin()];
            Aabb {
                lo,
                hi: lo.map(|x| x + 0.002),
            }
        })
        .collect();
    let items: Vec<u32> = (0..boxes.len() as u32).rev().collect();
    let one = Bvh::build_on(&boxes, items.clone(), 1);
    let four = Bvh::build_on(&boxes, items, 4);
    assert_eq!(one.items, four.items);
    well_formed(&four, &boxes);
}
