//! A streamed table's rows on two cores: the walk that makes them stays on
//! this thread, which copies each block of rows out of it; a second thread
//! measures or formats a block whenever it is free, this one the blocks it
//! is not free for; the results are taken in the order of the blocks, so
//! the bytes are those of one thread (held to them in the tests).
//!
//! NOTE: the walk (placing every part through its frames) cannot be split
//! without the model's help, and formatting is about two thirds of a
//! row's time: the second thread takes the formatting this one would
//! otherwise wait on. Blocks in flight are few (`AHEAD`), so memory stays
//! bounded whatever the rows.

use super::{Cell, CellSink};
use std::cell::Cell as StdCell;
use std::collections::VecDeque;
use std::sync::mpsc;

/// Rows a block holds.
const ROWS: usize = 1024;

/// Blocks given out and not yet taken back, at most.
const AHEAD: usize = 4;

thread_local! {
    static FORCED: StdCell<Option<usize>> = const { StdCell::new(None) };
}

/// `f` run with streamed tables made on `threads` threads (1 or 2), for
/// the tests that hold the bytes of both to each other.
pub fn with_threads<T>(threads: usize, f: impl FnOnce() -> T) -> T {
    let before = FORCED.with(|c| c.replace(Some(threads.max(1))));
    let out = f();
    FORCED.with(|c| c.set(before));
    out
}

/// The threads a streamed table is made on: two where there are two
/// cores (or as `with_threads` forces).
pub(super) fn threads() -> usize {
    FORCED
        .with(StdCell::get)
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |t| t.get()))
        .clamp(1, 2)
}

/// A cell copied out of the walk: text as a range of its block's `text`.
#[derive(Clone, Copy)]
enum Owned {
    Text(usize, usize),
    Name(usize, usize),
    Indented(usize, usize, usize),
    Count(usize),
    Sig(f64, usize),
    Percent(Option<f64>),
}

/// Rows of owned cells.
#[derive(Default)]
pub(super) struct Block {
    text: String,
    cells: Vec<Owned>,
    /// Cells a row.
    width: usize,
}

impl Block {
    fn push(&mut self, row: &[Cell<'_>]) {
        self.width = row.len();
        for c in row {
            let mut keep = |t: &str| {
                let start = self.text.len();
                self.text.push_str(t);
                (start, self.text.len())
            };
            let owned = match *c {
                Cell::Text(t) => {
                    let (a, b) = keep(t);
                    Owned::Text(a, b)
                }
                Cell::Name(t) => {
                    let (a, b) = keep(t);
                    Owned::Name(a, b)
                }
                Cell::Indented(n, t) => {
                    let (a, b) = keep(t);
                    Owned::Indented(n, a, b)
                }
                Cell::Count(n) => Owned::Count(n),
                Cell::Sig(x, d) => Owned::Sig(x, d),
                Cell::Percent(f) => Owned::Percent(f),
            };
            self.cells.push(owned);
        }
    }

    fn rows(&self) -> usize {
        self.cells.len() / self.width.max(1)
    }

    fn clear(&mut self) {
        self.text.clear();
        self.cells.clear();
    }

    /// Each row, as cells again, handed to `f`.
    pub(super) fn each(&self, f: &mut dyn FnMut(&[Cell<'_>])) {
        let mut row: Vec<Cell<'_>> = Vec::with_capacity(self.width);
        for owned in self.cells.chunks(self.width.max(1)) {
            row.clear();
            row.extend(owned.iter().map(|o| match *o {
                Owned::Text(a, b) => Cell::Text(&self.text[a..b]),
                Owned::Name(a, b) => Cell::Name(&self.text[a..b]),
                Owned::Indented(n, a, b) => Cell::Indented(n, &self.text[a..b]),
                Owned::Count(n) => Cell::Count(n),
                Owned::Sig(x, d) => Cell::Sig(x, d),
                Owned::Percent(f) => Cell::Percent(f),
            }));
            f(&row);
        }
    }
}

/// A block's result, waiting for its turn.
enum Pending<R> {
    /// Made here.
    Here(R),
    /// Given to the second thread; its results come back in order.
    There,
}

/// The rows `rows` hands out, in blocks, each made into a result by `work`
/// (on the second thread when it is free, else here), each result handed
/// to `done` in the order of the blocks. After `done` fails, no more work
/// is done (the walk runs out) and its error is returned.
pub(super) fn in_blocks<R: Send>(
    rows: &mut dyn FnMut(&mut CellSink<'_>),
    work: &(dyn Fn(&Block) -> R + Sync),
    done: &mut dyn FnMut(R) -> std::io::Result<()>,
) -> std::io::Result<()> {
    std::thread::scope(|scope| {
        let (give, take) = mpsc::sync_channel::<Block>(1);
        let (back, results) = mpsc::channel::<(Block, R)>();
        scope.spawn(move || {
            while let Ok(block) = take.recv() {
                let r = work(&block);
                if back.send((block, r)).is_err() {
                    return;
                }
            }
        });
        let mut pending: VecDeque<Pending<R>> = VecDeque::new();
        let mut spare: Vec<Block> = Vec::new();
        let mut failed: std::io::Result<()> = Ok(());
        // Results handed on while they are at the front (`wait`: until
        // fewer than `AHEAD` are out).
        let mut drain = |pending: &mut VecDeque<Pending<R>>,
                         spare: &mut Vec<Block>,
                         failed: &mut std::io::Result<()>,
                         wait: usize| {
            while let Some(front) = pending.front() {
                let r = match front {
                    Pending::There => {
                        let got = if pending.len() > wait {
                            results.recv().ok()
                        } else {
                            results.try_recv().ok()
                        };
                        let Some((mut block, r)) = got else { break };
                        block.clear();
                        spare.push(block);
                        r
                    }
                    Pending::Here(_) => match pending.pop_front() {
                        Some(Pending::Here(r)) => {
                            if failed.is_ok() {
                                *failed = done(r);
                            }
                            continue;
                        }
                        _ => unreachable!("invariant: the front was made here"),
                    },
                };
                pending.pop_front();
                if failed.is_ok() {
                    *failed = done(r);
                }
            }
        };
        let mut block = Block::default();
        let mut hand_on = |block: &mut Block,
                           pending: &mut VecDeque<Pending<R>>,
                           spare: &mut Vec<Block>,
                           failed: &mut std::io::Result<()>| {
            let full = std::mem::replace(block, spare.pop().unwrap_or_default());
            match give.try_send(full) {
                Ok(()) => pending.push_back(Pending::There),
                Err(mpsc::TrySendError::Full(full) | mpsc::TrySendError::Disconnected(full)) => {
                    pending.push_back(Pending::Here(work(&full)));
                    let mut full = full;
                    full.clear();
                    spare.push(full);
                }
            }
            drain(pending, spare, failed, AHEAD);
        };
        rows(&mut |row| {
            if failed.is_err() {
                return;
            }
            block.push(row);
            if block.rows() >= ROWS {
                hand_on(&mut block, &mut pending, &mut spare, &mut failed);
            }
        });
        if !block.cells.is_empty() && failed.is_ok() {
            hand_on(&mut block, &mut pending, &mut spare, &mut failed);
        }
        drop(give);
        drain(&mut pending, &mut spare, &mut failed, 0);
        failed
    })
}

#[cfg(test)]
mod tests {
    use super::super::{Fit, stream_cells};
    use super::*;

    /// A table of `rows` rows of every kind of cell, made on `threads`
    /// threads, to a writer that takes `left` bytes and then fails as a
    /// closed pipe does: what it took, and the error.
    fn table(rows: usize, threads: usize, fit: Fit, left: usize) -> (Vec<u8>, bool) {
        struct Closing(Vec<u8>, usize);
        impl std::io::Write for Closing {
            fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
                if self.1 == 0 {
                    return Err(std::io::ErrorKind::BrokenPipe.into());
                }
                let n = buf.len().min(self.1);
                self.0.extend_from_slice(&buf[..n]);
                self.1 -= n;
                Ok(n)
            }
            fn flush(&mut self) -> std::io::Result<()> {
                Ok(())
            }
        }
        let header: Vec<String> = ["#", "name", "x", "share", "sub"]
            .map(String::from)
            .to_vec();
        let right = [true, false, true, true, false];
        let mut out = Closing(Vec::new(), left);
        let failed = with_threads(threads, || {
            stream_cells(&mut out, &header, &right, fit, &mut |sink| {
                let mut name = String::new();
                for i in 0..rows {
                    name.clear();
                    name.push_str(&"part / ".repeat(i % 17));
                    name.push_str(if i % 5 == 0 { "漢字 \u{1b}" } else { "bolt" });
                    let x = (i as f64 - 700.5) * 1.37e-3_f64.powi((i % 7) as i32);
                    sink(&[
                        Cell::Count(i + 1),
                        Cell::Name(&name),
                        Cell::Sig(x, 6),
                        Cell::Percent(Some(x / 3.0).filter(|_| i % 3 > 0)),
                        Cell::Indented(i % 4, "wheel #2"),
                    ]);
                }
            })
        })
        .is_err();
        (out.0, failed)
    }

    #[test]
    fn two_threads_write_the_bytes_of_one() {
        for rows in [0, 1, ROWS - 1, ROWS, ROWS + 1, 9 * ROWS + 17] {
            let one = table(rows, 1, Fit::WHOLE, usize::MAX);
            let two = table(rows, 2, Fit::WHOLE, usize::MAX);
            assert!(!one.1 && !two.1);
            assert_eq!(one.0.len(), two.0.len(), "{rows} rows");
            assert!(one.0 == two.0, "{rows} rows: the same bytes");
        }
    }

    #[test]
    fn two_threads_split_a_wide_table_as_one_does() {
        let fit = Fit::new(Some(60), 2);
        let one = table(3 * ROWS + 5, 1, fit, usize::MAX);
        let two = table(3 * ROWS + 5, 2, fit, usize::MAX);
        assert!(
            String::from_utf8(one.0.clone())
                .unwrap()
                .contains("table split into")
        );
        assert!(one.0 == two.0);
    }

    #[test]
    fn a_write_that_fails_on_two_threads_ends_with_its_error_after_the_same_prefix() {
        let whole = table(6 * ROWS, 1, Fit::WHOLE, usize::MAX).0;
        for left in [0, 100, 70_000, whole.len() / 2, whole.len() - 1] {
            let one = table(6 * ROWS, 1, Fit::WHOLE, left);
            let two = table(6 * ROWS, 2, Fit::WHOLE, left);
            assert!(one.1 && two.1, "{left}: the error is returned");
            assert_eq!(two.0, whole[..left], "{left}: a prefix of the whole");
            assert_eq!(one.0, two.0);
        }
    }
}
