//! The operations planner layer (issue 17): what a CAM programmer would
//! recognise. So far the tool library ([`tools`]) and the roughing layers
//! with their cutter fields over the removal region ([`layers`],
//! Schuster ch. 4–5).

pub mod drilling;
pub mod layers;
pub mod operations;
pub mod rest;
pub mod tools;

pub use tools::{CuttingTool, ToolKind, ToolLibrary, ToolsError};
