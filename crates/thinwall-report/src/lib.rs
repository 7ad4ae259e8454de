//! Report contracts: plain serde structs built from a part and its graph,
//! plus a text rendering a person can scan. The CLI and the C ABI are thin
//! faces over these.

pub mod classify;
pub mod inspect;
pub mod recognize;

pub use classify::ClassificationReport;
pub use inspect::{inspect, InspectReport};
pub use recognize::{recognition_report, run_recognition, FeatureEntry, RecognitionReport};
