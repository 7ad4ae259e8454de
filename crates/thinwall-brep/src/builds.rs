//! How many times costly derived things (an analysis, a mesh) were built
//! for each part on this thread, keyed by the part's address: a test asks
//! that every command builds its part's analysis and mesh once, whatever
//! it builds for other solids (a plan's volumes). Counted per thread (no
//! lock shared by a host's threads); the study builds both on the thread
//! that calls it.

use crate::Part;
use std::cell::RefCell;
use std::collections::HashMap;

/// What was built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Built {
    Analysis,
    Mesh,
}

thread_local! {
    static COUNTS: RefCell<HashMap<(usize, Built), usize>> = RefCell::new(HashMap::new());
}

/// Count one `what` built for `part`.
pub fn record(part: &Part, what: Built) {
    let key = (part as *const Part as usize, what);
    COUNTS.with(|c| *c.borrow_mut().entry(key).or_insert(0) += 1);
}

/// How many `what` were built for `part` (at its address) on this thread.
pub fn count(part: &Part, what: Built) -> usize {
    let key = (part as *const Part as usize, what);
    COUNTS.with(|c| c.borrow().get(&key).copied().unwrap_or(0))
}
