//! Line diffs: Myers' shortest edit script between two sequences, and the
//! unified diff of two texts written from it.
//!
//! NOTE: hand-written rather than taken from the `similar` crate, which
//! was about a tenth of a cold release build for two small uses (`--bless`
//! maps its edit back onto each line's own ending; `export --update
//! --dry-run` shows a robot file's update). The algorithm follows
//! `similar` 3.2's Myers step for step — the same middle-snake
//! divide-and-conquer, the same compaction that slides each run of
//! deletions or insertions to meet its neighbours, the same grouping into
//! replacements and into hunks — so the output is byte-identical to
//! `similar::TextDiff::from_lines(..).unified_diff()` wherever `similar`
//! runs its exact search (tests/integration/diff_junit.rs pins it with a
//! property test against `similar`). `similar` trades exactness for speed
//! on large, very different inputs (a middle-snake search past cost 256,
//! ranges of 96 lines or more that differ in length twofold, or of 512
//! each); there this module keeps searching for a shortest script until
//! its work budget (`MAX_WORK` steps of the search) is spent, and then
//! shows what is left as a deletion and an insertion. Every answer is a
//! correct edit script; only the choice among scripts may differ there.

use std::ops::Range;

/// The most steps (diagonals visited plus lines compared along snakes)
/// one diff may take in the middle-snake search before what is left is
/// shown as a plain deletion and insertion: 2²⁵, a fraction of a second,
/// so that two files of the size limit with nothing in common cannot hang
/// `--dry-run` (the search is O((N+M)·D) in the number of differences D).
pub const MAX_WORK: u64 = 1 << 25;

/// One step of an edit script: index ranges into the old and new
/// sequences.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `old[old..old + len]` equals `new[new..new + len]`.
    Equal { old: usize, new: usize, len: usize },
    /// `old[old..old + old_len]` is deleted (at `new` in the new sequence).
    Delete {
        old: usize,
        old_len: usize,
        new: usize,
    },
    /// `new[new..new + new_len]` is inserted (at `old` in the old sequence).
    Insert {
        old: usize,
        new: usize,
        new_len: usize,
    },
    /// `old[old..old + old_len]` is replaced by `new[new..new + new_len]`.
    Replace {
        old: usize,
        old_len: usize,
        new: usize,
        new_len: usize,
    },
}

impl Op {
    /// The range of the old sequence this step covers.
    pub fn old_range(&self) -> Range<usize> {
        match *self {
            Op::Equal { old, len, .. } => old..old + len,
            Op::Delete { old, old_len, .. } | Op::Replace { old, old_len, .. } => {
                old..old + old_len
            }
            Op::Insert { old, .. } => old..old,
        }
    }

    /// The range of the new sequence this step covers.
    pub fn new_range(&self) -> Range<usize> {
        match *self {
            Op::Equal { new, len, .. } => new..new + len,
            Op::Insert { new, new_len, .. } | Op::Replace { new, new_len, .. } => {
                new..new + new_len
            }
            Op::Delete { new, .. } => new..new,
        }
    }
}

/// The edit script from `old` to `new`: equal runs, and deletions and
/// insertions that meet grouped into replacements. Its number of
/// deleted plus inserted elements is the least possible (Myers' D) while
/// the work budget lasts.
pub fn diff<T: PartialEq>(old: &[T], new: &[T]) -> Vec<Op> {
    diff_counting(old, new).0
}

/// `diff`, and the steps its search took (for the tests of the budget).
pub fn diff_counting<T: PartialEq>(old: &[T], new: &[T]) -> (Vec<Op>, u64) {
    let mut search = Search::new(old, new);
    search.run();
    let mut ops = search.ops;
    compact::cleanup(old, new, &mut ops);
    (replace(&ops), search.work)
}

/// The text's lines, each with its ending: a line ends at `\n`, at `\r\n`
/// or at a lone `\r` (as `similar` splits them); the last may have none.
pub fn split_lines(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut lines = Vec::new();
    let mut start = 0;
    let mut i = 0;
    while i < bytes.len() {
        let end = match bytes[i] {
            b'\r' if bytes.get(i + 1) == Some(&b'\n') => i + 2,
            b'\r' | b'\n' => i + 1,
            _ => {
                i += 1;
                continue;
            }
        };
        lines.push(&text[start..end]);
        start = end;
        i = end;
    }
    if start < bytes.len() {
        lines.push(&text[start..]);
    }
    lines
}

/// The unified diff of `old` to `new` by lines, `context` lines of context
/// around each change, headed `--- OLD_NAME` and `+++ NEW_NAME`; empty
/// when there is no change. A line without an ending is followed by
/// `\ No newline at end of file`.
pub fn unified(old: &str, new: &str, context: usize, old_name: &str, new_name: &str) -> String {
    let a = split_lines(old);
    let b = split_lines(new);
    let mut out = String::new();
    for (i, hunk) in group(diff(&a, &b), context).iter().enumerate() {
        if i == 0 {
            out.push_str(&format!("--- {old_name}\n+++ {new_name}\n"));
        }
        let (first, last) = (hunk[0], hunk[hunk.len() - 1]);
        out.push_str(&format!(
            "@@ -{} +{} @@\n",
            HunkRange(first.old_range().start, last.old_range().end),
            HunkRange(first.new_range().start, last.new_range().end)
        ));
        for op in hunk {
            let mut line = |tag: char, text: &str| {
                out.push(tag);
                out.push_str(text);
                if !text.ends_with(['\r', '\n']) {
                    out.push_str("\n\\ No newline at end of file\n");
                }
            };
            match *op {
                Op::Equal { old, len, .. } => a[old..old + len].iter().for_each(|l| line(' ', l)),
                Op::Delete { old, old_len, .. } => {
                    a[old..old + old_len].iter().for_each(|l| line('-', l));
                }
                Op::Insert { new, new_len, .. } => {
                    b[new..new + new_len].iter().for_each(|l| line('+', l));
                }
                Op::Replace {
                    old,
                    old_len,
                    new,
                    new_len,
                } => {
                    a[old..old + old_len].iter().for_each(|l| line('-', l));
                    b[new..new + new_len].iter().for_each(|l| line('+', l));
                }
            }
        }
    }
    out
}

/// A hunk header's range: `START,LEN` (1-based), `START` alone for one
/// line, and an empty range at the line before it.
struct HunkRange(usize, usize);

impl std::fmt::Display for HunkRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let len = self.1.saturating_sub(self.0);
        match len {
            1 => write!(f, "{}", self.0 + 1),
            0 => write!(f, "{},0", self.0),
            _ => write!(f, "{},{len}", self.0 + 1),
        }
    }
}

/// The script cut into hunks: runs of more than `2n` equal lines end a
/// hunk, `n` lines of context kept on each side.
fn group(mut ops: Vec<Op>, n: usize) -> Vec<Vec<Op>> {
    if ops.is_empty() {
        return Vec::new();
    }
    if let Some(Op::Equal { old, new, len }) = ops.first_mut() {
        let offset = len.saturating_sub(n);
        *old += offset;
        *new += offset;
        *len -= offset;
    }
    if let Some(Op::Equal { len, .. }) = ops.last_mut() {
        *len -= len.saturating_sub(n);
    }
    let mut hunks = Vec::new();
    let mut pending = Vec::new();
    for op in ops {
        if let Op::Equal { old, new, len } = op
            && len > n * 2
        {
            pending.push(Op::Equal { old, new, len: n });
            hunks.push(std::mem::take(&mut pending));
            let offset = len.saturating_sub(n);
            pending.push(Op::Equal {
                old: old + offset,
                new: new + offset,
                len: len - offset,
            });
            continue;
        }
        pending.push(op);
    }
    if !matches!(pending[..], [] | [Op::Equal { .. }]) {
        hunks.push(pending);
    }
    hunks
}

/// Deletions and insertions with no equal run between them become one
/// replacement; neighbouring equal runs merge.
fn replace(ops: &[Op]) -> Vec<Op> {
    let mut out = Vec::with_capacity(ops.len());
    let mut eq: Option<(usize, usize, usize)> = None;
    let mut del: Option<(usize, usize, usize)> = None;
    let mut ins: Option<(usize, usize, usize)> = None;
    fn flush_del_ins(
        out: &mut Vec<Op>,
        del: &mut Option<(usize, usize, usize)>,
        ins: &mut Option<(usize, usize, usize)>,
    ) {
        match (del.take(), ins.take()) {
            (Some((old, old_len, _)), Some((_, new, new_len))) => out.push(Op::Replace {
                old,
                old_len,
                new,
                new_len,
            }),
            (Some((old, old_len, new)), None) => out.push(Op::Delete { old, old_len, new }),
            (None, Some((old, new, new_len))) => out.push(Op::Insert { old, new, new_len }),
            (None, None) => {}
        }
    }
    for op in ops {
        match *op {
            Op::Equal { old, new, len } => {
                flush_del_ins(&mut out, &mut del, &mut ins);
                eq = Some(match eq {
                    Some((o, n, l)) => (o, n, l + len),
                    None => (old, new, len),
                });
            }
            Op::Delete { old, old_len, new } => {
                if let Some((old, new, len)) = eq.take() {
                    out.push(Op::Equal { old, new, len });
                }
                del = Some(match del {
                    Some((o, l, n)) => (o, l + old_len, n),
                    None => (old, old_len, new),
                });
            }
            Op::Insert { old, new, new_len } => {
                if let Some((old, new, len)) = eq.take() {
                    out.push(Op::Equal { old, new, len });
                }
                ins = Some(match ins {
                    Some((o, n, l)) => (o, n, l + new_len),
                    None => (old, new, new_len),
                });
            }
            Op::Replace { .. } => {
                if let Some((old, new, len)) = eq.take() {
                    out.push(Op::Equal { old, new, len });
                }
                out.push(*op);
            }
        }
    }
    if let Some((old, new, len)) = eq.take() {
        out.push(Op::Equal { old, new, len });
    }
    flush_del_ins(&mut out, &mut del, &mut ins);
    out
}

/// Equal elements at the starts of `old[a]` and `new[b]`.
fn prefix_len<T: PartialEq>(old: &[T], a: Range<usize>, new: &[T], b: Range<usize>) -> usize {
    old[a]
        .iter()
        .zip(&new[b])
        .take_while(|(x, y)| x == y)
        .count()
}

/// Equal elements at the ends of `old[a]` and `new[b]`.
fn suffix_len<T: PartialEq>(old: &[T], a: Range<usize>, new: &[T], b: Range<usize>) -> usize {
    old[a]
        .iter()
        .rev()
        .zip(new[b].iter().rev())
        .take_while(|(x, y)| x == y)
        .count()
}

/// The search's state: the furthest-reaching rows of the forward and
/// backward D-paths (indexed by diagonal), the script so far, the work.
struct Search<'a, T> {
    old: &'a [T],
    new: &'a [T],
    vf: Vec<usize>,
    vb: Vec<usize>,
    /// The diagonal offset of `vf` and `vb`: diagonal k is at `k + offset`.
    offset: isize,
    ops: Vec<Op>,
    work: u64,
}

/// Half the longest possible script, plus one: the most D the middle
/// snake needs to explore.
fn max_d(n: usize, m: usize) -> usize {
    (n + m).div_ceil(2) + 1
}

impl<'a, T: PartialEq> Search<'a, T> {
    fn new(old: &'a [T], new: &'a [T]) -> Self {
        let d = max_d(old.len(), new.len());
        Search {
            old,
            new,
            vf: vec![0; 2 * d + 2],
            vb: vec![0; 2 * d + 2],
            offset: d as isize,
            ops: Vec::new(),
            work: 0,
        }
    }

    fn run(&mut self) {
        let (n, m) = (self.old.len(), self.new.len());
        let prefix = prefix_len(self.old, 0..n, self.new, 0..m);
        let suffix = suffix_len(self.old, prefix..n, self.new, prefix..m);
        if prefix > 0 {
            self.equal(0, 0, prefix);
        }
        let (a, b) = (prefix..n - suffix, prefix..m - suffix);
        if a.is_empty() && b.is_empty() {
        } else if a.is_empty() {
            self.ops.push(Op::Insert {
                old: a.start,
                new: b.start,
                new_len: b.len(),
            });
        } else if b.is_empty() {
            self.ops.push(Op::Delete {
                old: a.start,
                old_len: a.len(),
                new: b.start,
            });
        } else {
            self.conquer(a, b);
        }
        if suffix > 0 {
            self.equal(n - suffix, m - suffix, suffix);
        }
    }

    fn equal(&mut self, old: usize, new: usize, len: usize) {
        self.ops.push(Op::Equal { old, new, len });
    }

    fn conquer(&mut self, mut a: Range<usize>, mut b: Range<usize>) {
        let prefix = prefix_len(self.old, a.clone(), self.new, b.clone());
        if prefix > 0 {
            self.equal(a.start, b.start, prefix);
        }
        a.start += prefix;
        b.start += prefix;
        let suffix = suffix_len(self.old, a.clone(), self.new, b.clone());
        a.end -= suffix;
        b.end -= suffix;
        if a.is_empty() && b.is_empty() {
        } else if b.is_empty() {
            self.ops.push(Op::Delete {
                old: a.start,
                old_len: a.len(),
                new: b.start,
            });
        } else if a.is_empty() {
            self.ops.push(Op::Insert {
                old: a.start,
                new: b.start,
                new_len: b.len(),
            });
        } else if let Some((x, y)) = self.middle_snake(a.clone(), b.clone()) {
            self.conquer(a.start..x, b.start..y);
            self.conquer(x..a.end, y..b.end);
        } else {
            self.ops.push(Op::Delete {
                old: a.start,
                old_len: a.len(),
                new: b.start,
            });
            self.ops.push(Op::Insert {
                old: a.start,
                new: b.start,
                new_len: b.len(),
            });
        }
        if suffix > 0 {
            self.equal(a.end, b.end, suffix);
        }
    }

    /// Where a shortest script of `old[a]` to `new[b]` crosses its middle
    /// (Myers 1986, section 4b), in absolute indices; `None` once the work
    /// budget is spent.
    fn middle_snake(&mut self, a: Range<usize>, b: Range<usize>) -> Option<(usize, usize)> {
        let (n, m) = (a.len(), b.len());
        let delta = n as isize - m as isize;
        let odd = delta & 1 == 1;
        let o = self.offset;
        let at = |k: isize| (k + o) as usize;
        self.vf[at(1)] = 0;
        self.vb[at(1)] = 0;
        for d in 0..max_d(n, m) as isize {
            let mut k = d;
            while k >= -d {
                self.work += 1;
                if self.work > MAX_WORK {
                    return None;
                }
                let mut x = if k == -d || (k != d && self.vf[at(k - 1)] < self.vf[at(k + 1)]) {
                    self.vf[at(k + 1)]
                } else {
                    self.vf[at(k - 1)] + 1
                };
                let y = (x as isize - k) as usize;
                let (x0, y0) = (x, y);
                if x < n && y < m {
                    let run =
                        prefix_len(self.old, a.start + x..a.end, self.new, b.start + y..b.end);
                    self.work += run as u64;
                    x += run;
                }
                self.vf[at(k)] = x;
                if odd && (k - delta).abs() < d && self.vf[at(k)] + self.vb[at(-(k - delta))] >= n {
                    return Some((x0 + a.start, y0 + b.start));
                }
                k -= 2;
            }
            let mut k = d;
            while k >= -d {
                self.work += 1;
                if self.work > MAX_WORK {
                    return None;
                }
                let mut x = if k == -d || (k != d && self.vb[at(k - 1)] < self.vb[at(k + 1)]) {
                    self.vb[at(k + 1)]
                } else {
                    self.vb[at(k - 1)] + 1
                };
                let mut y = (x as isize - k) as usize;
                if x < n && y < m {
                    let run = suffix_len(
                        self.old,
                        a.start..a.start + n - x,
                        self.new,
                        b.start..b.start + m - y,
                    );
                    self.work += run as u64;
                    x += run;
                    y += run;
                }
                self.vb[at(k)] = x;
                if !odd && (k - delta).abs() <= d && self.vb[at(k)] + self.vf[at(-(k - delta))] >= n
                {
                    return Some((n - x + a.start, m - y + b.start));
                }
                k -= 2;
            }
        }
        None
    }
}

mod compact;

#[cfg(test)]
mod tests {
    use super::*;

    /// `new`, rebuilt from `old` and the script.
    fn apply<'a>(old: &[&'a str], new: &[&'a str], ops: &[Op]) -> Vec<&'a str> {
        let mut out = Vec::new();
        for op in ops {
            match *op {
                Op::Equal { old: o, len, .. } => out.extend_from_slice(&old[o..o + len]),
                Op::Delete { .. } => {}
                Op::Insert {
                    new: n, new_len, ..
                }
                | Op::Replace {
                    new: n, new_len, ..
                } => {
                    out.extend_from_slice(&new[n..n + new_len]);
                }
            }
        }
        out
    }

    #[test]
    fn lines_keep_their_endings_and_a_lone_cr_ends_a_line() {
        assert_eq!(split_lines("a\nb\r\nc\rd"), ["a\n", "b\r\n", "c\r", "d"]);
        assert_eq!(split_lines(""), Vec::<&str>::new());
    }

    #[test]
    fn one_changed_line_is_one_replacement() {
        let (a, b) = (["x", "y", "z"], ["x", "Y", "z"]);
        let ops = diff(&a, &b);
        assert_eq!(
            ops[1],
            Op::Replace {
                old: 1,
                old_len: 1,
                new: 1,
                new_len: 1
            }
        );
        assert_eq!(apply(&a, &b, &ops), b);
    }

    #[test]
    fn a_missing_final_newline_is_marked() {
        let d = unified("a\nb", "a\nc", 3, "x", "y");
        assert_eq!(
            d,
            "--- x\n+++ y\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+c\n\\ No newline at end of file\n"
        );
    }

    #[test]
    fn equal_texts_give_no_diff() {
        assert_eq!(unified("a\nb\n", "a\nb\n", 3, "x", "y"), "");
    }
}
