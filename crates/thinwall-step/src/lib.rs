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

/// Read a STEP file from disk.
pub fn read_file(path: impl AsRef<Path>) -> Result<(Part, ReadReport), StepError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| StepError::Io {
        file: name.clone(),
        source,
    })?;
    read_bytes(&bytes, &name)
}

/// Read STEP text held in memory; `name` is used in error messages.
///
/// Never panics: a panic inside the parser is caught and returned as
/// [`StepError::Internal`].
pub fn read_bytes(bytes: &[u8], name: &str) -> Result<(Part, ReadReport), StepError> {
    match std::panic::catch_unwind(|| bridge::read(bytes, name)) {
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
