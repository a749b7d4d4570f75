//! Compaction of an edit script: each run of deletions, then of
//! insertions, slid up and then down through the equal lines around it
//! as far as they repeat it, to meet and merge with its neighbours; the
//! steps of `similar` 3.2's `Compact` (after diffy's), kept as they are so
//! that the scripts agree (see the parent module's note).

use super::{Op, prefix_len, suffix_len};

#[derive(Clone, Copy, PartialEq, Eq)]
enum Tag {
    Equal,
    Delete,
    Insert,
    Replace,
}

fn tag(op: &Op) -> Tag {
    match op {
        Op::Equal { .. } => Tag::Equal,
        Op::Delete { .. } => Tag::Delete,
        Op::Insert { .. } => Tag::Insert,
        Op::Replace { .. } => Tag::Replace,
    }
}

/// Adds (or, with `sub`, subtracts) `offset` to the step's starts and
/// `len` to its lengths.
fn adjust(op: &mut Op, offset: usize, offset_sub: bool, len: usize, len_sub: bool) {
    let modify = |v: &mut usize, by: usize, sub: bool| {
        if sub {
            *v -= by;
        } else {
            *v += by;
        }
    };
    match op {
        Op::Equal { old, new, len: l } => {
            modify(old, offset, offset_sub);
            modify(new, offset, offset_sub);
            modify(l, len, len_sub);
        }
        Op::Delete { old, old_len, new } => {
            modify(old, offset, offset_sub);
            modify(old_len, len, len_sub);
            modify(new, offset, offset_sub);
        }
        Op::Insert { old, new, new_len } => {
            modify(old, offset, offset_sub);
            modify(new, offset, offset_sub);
            modify(new_len, len, len_sub);
        }
        Op::Replace {
            old,
            old_len,
            new,
            new_len,
        } => {
            modify(old, offset, offset_sub);
            modify(old_len, len, len_sub);
            modify(new, offset, offset_sub);
            modify(new_len, len, len_sub);
        }
    }
}

fn shift_left(op: &mut Op, n: usize) {
    adjust(op, n, true, 0, false);
}
fn shift_right(op: &mut Op, n: usize) {
    adjust(op, n, false, 0, false);
}
fn grow_left(op: &mut Op, n: usize) {
    adjust(op, n, true, n, false);
}
fn grow_right(op: &mut Op, n: usize) {
    adjust(op, 0, false, n, false);
}
fn shrink_left(op: &mut Op, n: usize) {
    adjust(op, 0, false, n, true);
}
fn shrink_right(op: &mut Op, n: usize) {
    adjust(op, n, false, n, true);
}

fn is_empty(op: &Op) -> bool {
    op.old_range().is_empty() && op.new_range().is_empty()
}

/// Compacts `ops` (equal runs, deletions and insertions) in place.
pub(super) fn cleanup<T: PartialEq>(old: &[T], new: &[T], ops: &mut Vec<Op>) {
    for which in [Tag::Delete, Tag::Insert] {
        let mut p = 0;
        while let Some(op) = ops.get(p) {
            if tag(op) == which {
                p = shift_up(ops, old, new, p);
                p = shift_down(ops, old, new, p);
            }
            p += 1;
        }
    }
    normalize_cursors(ops);
}

/// Makes each deletion's position in the new sequence, and each
/// insertion's in the old, follow from the steps before it.
fn normalize_cursors(ops: &mut [Op]) {
    let (mut old_cursor, mut new_cursor) = match ops.first() {
        Some(op) => (op.old_range().start, op.new_range().start),
        None => (0, 0),
    };
    for op in ops.iter_mut() {
        match op {
            Op::Equal { old, new, len } => {
                old_cursor = *old + *len;
                new_cursor = *new + *len;
            }
            Op::Delete { old, old_len, new } => {
                *new = new_cursor;
                old_cursor = *old + *old_len;
            }
            Op::Insert { old, new, new_len } => {
                *old = old_cursor;
                new_cursor = *new + *new_len;
            }
            Op::Replace {
                old,
                old_len,
                new,
                new_len,
            } => {
                old_cursor = *old + *old_len;
                new_cursor = *new + *new_len;
            }
        }
    }
}

/// Swaps the deletion and the insertion at `left` and `left + 1`, their
/// positions patched so the script stays contiguous.
fn swap_insert_delete(ops: &mut [Op], left: usize) {
    let right = left + 1;
    let old_start = ops[left].old_range().start;
    let old_end = ops[right].old_range().end;
    let new_start = ops[left].new_range().start;
    let new_end = ops[right].new_range().end;
    ops.swap(left, right);
    for (i, (o, n)) in [(left, (old_start, new_start)), (right, (old_end, new_end))] {
        match &mut ops[i] {
            Op::Insert { old, .. } => *old = o,
            Op::Delete { new, .. } => *new = n,
            Op::Equal { .. } | Op::Replace { .. } => {
                unreachable!("only a deletion and an insertion are swapped")
            }
        }
    }
}

fn shift_up<T: PartialEq>(ops: &mut Vec<Op>, old: &[T], new: &[T], mut p: usize) -> usize {
    while p > 0 {
        let prev = ops[p - 1];
        let this = ops[p];
        match (tag(&this), tag(&prev)) {
            (Tag::Insert, Tag::Equal) | (Tag::Delete, Tag::Equal) => {
                let deleting = tag(&this) == Tag::Delete;
                if deleting && !(p >= 2 && tag(&ops[p - 2]) == Tag::Delete) {
                    break;
                }
                let (old_r, new_r) = if deleting {
                    (this.old_range(), prev.new_range())
                } else {
                    (prev.old_range(), this.new_range())
                };
                let n = suffix_len(old, old_r.clone(), new, new_r.clone());
                if n > 0 {
                    if ops.get(p + 1).map(tag) == Some(Tag::Equal) {
                        grow_left(&mut ops[p + 1], n);
                    } else {
                        ops.insert(
                            p + 1,
                            Op::Equal {
                                old: old_r.end - n,
                                new: new_r.end - n,
                                len: n,
                            },
                        );
                    }
                    shift_left(&mut ops[p], n);
                    shrink_left(&mut ops[p - 1], n);
                    if is_empty(&ops[p - 1]) {
                        ops.remove(p - 1);
                        p -= 1;
                    }
                } else if is_empty(&ops[p - 1]) {
                    ops.remove(p - 1);
                    p -= 1;
                } else {
                    break;
                }
            }
            (Tag::Insert, Tag::Delete) | (Tag::Delete, Tag::Insert) => {
                swap_insert_delete(ops, p - 1);
                p -= 1;
            }
            (Tag::Insert, Tag::Insert) => {
                grow_right(&mut ops[p - 1], this.new_range().len());
                ops.remove(p);
                p -= 1;
            }
            (Tag::Delete, Tag::Delete) => {
                grow_right(&mut ops[p - 1], this.old_range().len());
                ops.remove(p);
                p -= 1;
            }
            (Tag::Equal | Tag::Replace, _) | (_, Tag::Replace) => {
                unreachable!("a deletion or an insertion moves, past no replacement")
            }
        }
    }
    p
}

fn shift_down<T: PartialEq>(ops: &mut Vec<Op>, old: &[T], new: &[T], mut p: usize) -> usize {
    while let Some(&next) = ops.get(p + 1) {
        let this = ops[p];
        match (tag(&this), tag(&next)) {
            (Tag::Insert, Tag::Equal) | (Tag::Delete, Tag::Equal) => {
                let deleting = tag(&this) == Tag::Delete;
                if deleting && ops.get(p + 2).map(tag) != Some(Tag::Delete) {
                    break;
                }
                let (old_r, new_r) = if deleting {
                    (this.old_range(), next.new_range())
                } else {
                    (next.old_range(), this.new_range())
                };
                let n = prefix_len(old, old_r.clone(), new, new_r.clone());
                if n > 0 {
                    if p > 0 && tag(&ops[p - 1]) == Tag::Equal {
                        grow_right(&mut ops[p - 1], n);
                    } else {
                        let start = if deleting {
                            (this.old_range().start, this.new_range().start)
                        } else {
                            (next.old_range().start, this.new_range().start)
                        };
                        ops.insert(
                            p,
                            Op::Equal {
                                old: start.0,
                                new: start.1,
                                len: n,
                            },
                        );
                        p += 1;
                    }
                    shift_right(&mut ops[p], n);
                    shrink_right(&mut ops[p + 1], n);
                    if is_empty(&ops[p + 1]) {
                        ops.remove(p + 1);
                    }
                } else if is_empty(&ops[p + 1]) {
                    ops.remove(p + 1);
                } else {
                    break;
                }
            }
            (Tag::Insert, Tag::Delete) | (Tag::Delete, Tag::Insert) => {
                swap_insert_delete(ops, p);
                p += 1;
            }
            (Tag::Insert, Tag::Insert) => {
                grow_right(&mut ops[p], next.new_range().len());
                ops.remove(p + 1);
            }
            (Tag::Delete, Tag::Delete) => {
                grow_right(&mut ops[p], next.old_range().len());
                ops.remove(p + 1);
            }
            (Tag::Equal | Tag::Replace, _) | (_, Tag::Replace) => {
                unreachable!("a deletion or an insertion moves, past no replacement")
            }
        }
    }
    p
}
