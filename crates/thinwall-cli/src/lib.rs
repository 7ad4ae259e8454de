//! The command line's flags and what they ask for: clap's view of every
//! command, the one step from flags to a use case's request, and running a
//! one-part job on a study. The `thinwall` binary and the Python package
//! (`python/`, whose keyword arguments are these flags) are both thin faces
//! over it.

pub mod args;
pub mod failure;
pub mod jobs;
