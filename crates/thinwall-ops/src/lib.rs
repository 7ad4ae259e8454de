//! The operations planner layer (issue 17): what a CAM programmer would
//! recognise. The tool library ([`tools`]), the roughing layers with their
//! cutter fields over the removal region ([`layers`], Schuster ch. 4–5),
//! tools with rest areas and Popma's regions ([`rest`]), holes to drill
//! ([`drilling`]), operations by stage in order ([`operations`]),
//! pockets finished by their corner radius and floor fillet
//! ([`finishing`]), holes' spots, countersinks and chamfers
//! ([`hole_stages`]), and the whole run for a set-up ([`setup`]).

pub mod drilling;
pub mod finishing;
pub mod hole_stages;
pub mod layers;
pub mod operations;
mod order;
pub mod planned;
pub mod rest;
pub mod setup;
mod stage;
pub mod tools;

pub use setup::{plan_in_turn, plan_setup, OpsError};
pub use tools::{CuttingTool, ToolKind, ToolLibrary, ToolsError};
