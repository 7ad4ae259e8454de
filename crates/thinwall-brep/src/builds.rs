//! How many times costly derived things (an analysis, a mesh) were built
//! for each part in this process, keyed by the part's address: a test asks
//! that every command builds its part's analysis and mesh once, whatever
//! it builds for other solids (a plan's volumes).

use crate::Part;
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

/// What was built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Built {
    Analysis,
    Mesh,
}

type Counts = Mutex<HashMap<(usize, Built), usize>>;

fn counts() -> &'static Counts {
    static COUNTS: OnceLock<Counts> = OnceLock::new();
    COUNTS.get_or_init(Counts::default)
}

/// Count one `what` built for `part`.
pub fn record(part: &Part, what: Built) {
    let key = (part as *const Part as usize, what);
    let mut counts = counts().lock().unwrap_or_else(|p| p.into_inner());
    *counts.entry(key).or_insert(0) += 1;
}

/// How many `what` were built for `part` (at its address) so far.
pub fn count(part: &Part, what: Built) -> usize {
    let key = (part as *const Part as usize, what);
    let counts = counts().lock().unwrap_or_else(|p| p.into_inner());
    counts.get(&key).copied().unwrap_or(0)
}
