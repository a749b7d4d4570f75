//! The self-join against the per-item query it replaces and against every
//! pair: the same pairs, each once, however the join is cut into tasks.

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
    for task in bvh.join_tasks(size) {
        bvh.join(boxes, task, &mut stack, |i, j| out.push((i, j)));
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

fn check(boxes: &[Aabb], items: Vec<u32>, size: usize) -> Result<(), TestCaseError> {
    let want = brute(boxes, &items);
    let bvh = Bvh::build(boxes, items);
    prop_assert_eq!(&by_query(&bvh, boxes), &want);
    let mut got = by_join(&bvh, boxes, size);
    let n = got.len();
    got.sort_unstable();
    got.dedup();
    prop_assert_eq!(got.len(), n, "a pair was visited twice");
    prop_assert_eq!(&got, &want);
    Ok(())
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
    let bvh = Bvh::build(&[], Vec::new());
    assert!(by_join(&bvh, &[], 1).is_empty());
}
