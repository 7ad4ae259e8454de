//! Errors of the STEP reader. Each names the file, and the entity where
//! there is one.

use thiserror::Error;

/// Why a STEP file could not be read into a part.
#[derive(Debug, Error)]
pub enum StepError {
    #[error("{file}: cannot read file: {source}")]
    Io {
        file: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{file}: not a readable ISO 10303-21 file: {message}")]
    Syntax { file: String, message: String },
    #[error("{file}: no B-rep solid in the file{detail}")]
    NoBrep { file: String, detail: String },
    #[error("{file}: solid #{solid} is bounded by shell #{shell}, which is not closed")]
    OpenShell {
        file: String,
        solid: u64,
        shell: u64,
    },
    #[error("{file}: entity ids could not be matched to the model ({keyword}: {found} in the file, {expected} read)")]
    IdMismatch {
        file: String,
        keyword: &'static str,
        expected: usize,
        found: usize,
    },
    #[error("{file}: the assembly is cyclic: {detail}")]
    CyclicAssembly { file: String, detail: String },
    #[error("{file}: entities refer to each other in a circle: {entities}")]
    CyclicReference { file: String, entities: String },
    #[error("{}: {} {} is {}{}", .file, .what, number(*.value), .why, at(*.entity))]
    BadNumber {
        file: String,
        /// The entity whose geometry holds the value (none for the units).
        entity: Option<u64>,
        what: String,
        value: f64,
        why: &'static str,
    },
    #[error("{file}: {what} exceeds the reader's budget of {limit} (a setting: ReadLimits)")]
    BudgetExceeded {
        file: String,
        what: &'static str,
        limit: u64,
    },
    #[error("{file}: the assembly places more than {limit} instances")]
    TooManyInstances { file: String, limit: usize },
    #[error("{file}: internal error while reading: {message}")]
    Internal { file: String, message: String },
}

impl StepError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            StepError::Io { .. } => "io",
            StepError::Syntax { .. } => "syntax",
            StepError::NoBrep { .. } => "no_brep",
            StepError::OpenShell { .. } => "open_shell",
            StepError::IdMismatch { .. } => "id_mismatch",
            StepError::CyclicAssembly { .. } => "cyclic_assembly",
            StepError::CyclicReference { .. } => "cyclic_reference",
            StepError::BadNumber { .. } => "bad_number",
            StepError::BudgetExceeded { .. } => "budget_exceeded",
            StepError::TooManyInstances { .. } => "too_many_instances",
            StepError::Internal { .. } => "internal",
        }
    }
}

/// A number as a person reads it: plain for everyday magnitudes, in
/// scientific notation for the extreme ones a bad file holds.
fn number(v: f64) -> String {
    if v != 0.0 && !(1e-4..1e7).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// ` (entity #N)`, or nothing.
fn at(entity: Option<u64>) -> String {
    entity
        .map(|e| format!(" (entity #{e})"))
        .unwrap_or_default()
}
