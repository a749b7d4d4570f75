//! The steps of work of the robot checks, counted per thread: a test
//! holds `check` to work linear in the file by them, with no clock.

thread_local! {
    /// The steps of work of the checks on this thread (`steps`).
    static STEPS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// Count `n` steps of work (`steps`).
pub(super) fn step(n: usize) {
    STEPS.with(|s| s.set(s.get().saturating_add(n as u64)));
}

/// The steps of work the checks on this thread have done so far: each
/// link and engine met, each link a walk down the tree visits, each byte
/// a span counts past, each name a mirror map files or looks at. A test
/// holds `check` to work linear in the file with it, with no clock
/// (tests/integration/robots_hostile.rs); a pass over all links made
/// once per link would show as the square.
#[doc(hidden)]
pub fn steps() -> u64 {
    STEPS.with(std::cell::Cell::get)
}
