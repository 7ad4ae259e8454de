//! Report contracts: plain serde structs built from a part and its graph,
//! plus a text rendering a person can scan. The CLI and the C ABI are thin
//! faces over these.

pub mod inspect;

pub use inspect::{inspect, InspectReport};
