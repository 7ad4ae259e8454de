//! The bounds of a run that the command line sets once for every command:
//! the time a command may work on one part, and how many parts `batch` may
//! run at once.

use std::sync::OnceLock;
use std::time::Duration;
use thinwall_cli::failure::Failure;
use thinwall_study::{LoadedPart, Study};

static TIME_LIMIT: OnceLock<Option<Duration>> = OnceLock::new();

/// Most parts `batch` runs at once, per core (more only adds memory).
const JOBS_PER_CORE: usize = 4;

/// Set the time limit of every study of this run (once, from `--time-limit`).
pub fn set_time_limit(limit: Option<Duration>) {
    let _ = TIME_LIMIT.set(limit);
}

/// The time limit of this run's studies.
pub fn time_limit() -> Option<Duration> {
    TIME_LIMIT.get().copied().flatten()
}

/// A study of `loaded` within this run's time limit.
pub fn study(loaded: &LoadedPart) -> Study<'_> {
    Study::new(loaded).with_time_limit(time_limit())
}

/// The machine's cores.
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// `--jobs`: from 1 to four times the cores (the cores by default).
pub fn jobs(given: Option<usize>) -> Result<usize, Failure> {
    let most = JOBS_PER_CORE * cores();
    match given {
        None => Ok(cores()),
        Some(n) if (1..=most).contains(&n) => Ok(n),
        Some(n) => Err(Failure::Usage(format!(
            "--jobs: must be from 1 to {most} ({JOBS_PER_CORE} per core), got {n}"
        ))),
    }
}
