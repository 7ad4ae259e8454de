//! Report contracts: plain serde structs built from a pipeline outcome (or
//! a part and its graph, for `inspect`), plus a text rendering a person can
//! scan. Nothing here runs a recognizer: `thinwall-pipeline` does.

pub mod access;
pub mod classify;
pub mod expect;
pub mod html;
pub mod inspect;
pub mod operations;
pub mod palette;
pub mod plan;
pub mod recognize;
pub mod rests;
mod setups;
pub mod svg;

pub use classify::ClassificationReport;
pub use inspect::{inspect, InspectReport};
pub use recognize::{recognition_report, FeatureEntry, RecognitionReport};
