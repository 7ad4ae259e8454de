//! How many times costly derived things (an analysis, a mesh) were built
//! for each part on this thread, keyed by the part's address: a test asks
//! that every command builds its part's analysis and mesh once, whatever
//! it builds for other solids (a plan's volumes). Counted per thread (no
//! lock shared by a host's threads); the study builds both on the thread
//! that calls it. Only with the `count-builds` feature (tests turn it
//! on); without it, `record` does nothing and costs nothing.

use crate::Part;
#[cfg(feature = "count-builds")]
use std::cell::RefCell;
#[cfg(feature = "count-builds")]
use std::collections::HashMap;

/// What was built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Built {
    Analysis,
    Mesh,
}

#[cfg(feature = "count-builds")]
thread_local! {
    static COUNTS: RefCell<HashMap<(usize, Built), usize>> = RefCell::new(HashMap::new());
}

/// Count one `what` built for `part`.
#[cfg(feature = "count-builds")]
pub fn record(part: &Part, what: Built) {
    let key = (part as *const Part as usize, what);
    COUNTS.with(|c| *c.borrow_mut().entry(key).or_insert(0) += 1);
}

/// Without `count-builds`: nothing is counted.
#[cfg(not(feature = "count-builds"))]
#[inline(always)]
pub fn record(_part: &Part, _what: Built) {}

/// How many `what` were built for `part` (at its address) on this thread.
#[cfg(feature = "count-builds")]
pub fn count(part: &Part, what: Built) -> usize {
    let key = (part as *const Part as usize, what);
    COUNTS.with(|c| c.borrow().get(&key).copied().unwrap_or(0))
}
