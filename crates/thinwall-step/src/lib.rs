//! Reading STEP (ISO 10303-21: AP203, AP214, AP242) into Thinwall's B-rep.
//!
//! step-io (pinned exactly) does the parsing; [`bridge`] is the one module
//! that knows its API. The reader keeps topology as the file has it — one
//! face per STEP face, no splitting or healing — converts lengths to mm and
//! angles to radians, applies assembly placements, and reports what it
//! dropped or repaired in a [`ReadReport`] instead of printing it.
//!
//! ```no_run
//! let (part, report) = thinwall_step::read_file("part.step").unwrap();
//! println!("{} faces, {} dropped entities", part.faces.len(), report.dropped.len());
//! ```

mod bridge;
mod error;
pub mod id_scan;
mod occ_order;
mod references;
pub mod sanity;
mod seam;

pub use error::StepError;

use serde::{Deserialize, Serialize};
use std::path::Path;
use thinwall_brep::Part;

/// Something the reader dropped or repaired, with the entity it concerns.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReadIssue {
    pub entity: Option<u64>,
    pub message: String,
}

/// What happened on the way in.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ReadReport {
    pub entities_read: usize,
    pub entities_kept: usize,
    /// Entities step-io could not keep, with the reason.
    pub dropped: Vec<ReadIssue>,
    /// Values normalized, syntax repaired, defaults assumed.
    pub repaired: Vec<ReadIssue>,
}

/// How much a file may ask of the reader. A file past a limit is refused
/// with [`StepError::BudgetExceeded`] (or [`StepError::TooManyInstances`])
/// before the work it would take is done.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadLimits {
    /// Largest file read, bytes (a device such as `/dev/zero` is read up to
    /// this and refused).
    pub max_bytes: u64,
    /// Most faces placed in all (an assembly places its parts' faces once
    /// per instance; mapped items likewise).
    pub max_faces: usize,
    /// Most definition instances an assembly walk visits (a definition used
    /// twice at each of 32 levels would otherwise place 2³² of them).
    pub max_instances: usize,
}

impl Default for ReadLimits {
    /// 256 MiB, 250,000 faces, 100,000 instances: about 100 times the
    /// largest NIST test part, and within 2 GiB of memory.
    fn default() -> Self {
        Self {
            max_bytes: 256 << 20,
            max_faces: 250_000,
            max_instances: 100_000,
        }
    }
}

/// Read a STEP file from disk, within the default [`ReadLimits`].
pub fn read_file(path: impl AsRef<Path>) -> Result<(Part, ReadReport), StepError> {
    read_file_with(path, &ReadLimits::default())
}

/// Read a STEP file from disk, within `limits`.
pub fn read_file_with(
    path: impl AsRef<Path>,
    limits: &ReadLimits,
) -> Result<(Part, ReadReport), StepError> {
    use std::io::Read;
    let path = path.as_ref();
    let name = path.display().to_string();
    let io = |source| StepError::Io {
        file: name.clone(),
        source,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .map_err(io)?
        .take(limits.max_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limits.max_bytes {
        return Err(StepError::BudgetExceeded {
            file: name,
            what: "the file's size (bytes)",
            limit: limits.max_bytes,
        });
    }
    read_bytes_with(&bytes, &name, limits)
}

/// Read STEP text held in memory; `name` is used in error messages.
///
/// Never panics: a panic inside the parser is caught and returned as
/// [`StepError::Internal`].
pub fn read_bytes(bytes: &[u8], name: &str) -> Result<(Part, ReadReport), StepError> {
    read_bytes_with(bytes, name, &ReadLimits::default())
}

/// [`read_bytes`] within `limits`.
pub fn read_bytes_with(
    bytes: &[u8],
    name: &str,
    limits: &ReadLimits,
) -> Result<(Part, ReadReport), StepError> {
    if bytes.len() as u64 > limits.max_bytes {
        return Err(StepError::BudgetExceeded {
            file: name.to_string(),
            what: "the file's size (bytes)",
            limit: limits.max_bytes,
        });
    }
    match std::panic::catch_unwind(|| bridge::read(bytes, name, limits)) {
        Ok(r) => r,
        Err(panic) => {
            let message = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "panic".to_string());
            Err(StepError::Internal {
                file: name.to_string(),
                message,
            })
        }
    }
}
