//! What an operation does (its stage), its share of Popma's regions, an
//! operation before it has a place in the order (`Draft`), and what the
//! finishing by radii and the holes' stages find (`RadiusFinish`,
//! `HoleStage`): the types the operations, their order and those steps
//! share.

use crate::drilling::DrillKind;
use crate::rest::Adjacency;
use crate::tools::CuttingTool;
use serde::Serialize;
use thinwall_machining::ToolBound;

/// What an operation does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    Rough,
    SemiFinish,
    /// Along the part's walls: a tool's boundary region (Popma's, within
    /// the finishing stepover of a part contour), down milling at the
    /// finishing conditions, after that tool's roughing of the layer. In a
    /// layer beside a thin wall there is none: the rough and semi-finish
    /// passes take their boundary region themselves (the step approach).
    FinishWalls,
    /// A floor's finishing layer.
    Finish,
    Drill,
    /// A pocket's walls, corners and floor fillet contoured by a tool
    /// chosen by its radii (`finishing.rs`), after its layers' milling.
    FinishRadii,
}

/// An operation's share of Popma's regions, mm² (they add up to its
/// area; a floor's finish has none).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Regions {
    pub boundary_mm2: f64,
    pub full_cut_mm2: f64,
    pub roughing_mm2: f64,
}

/// An operation before it has a place.
pub(crate) struct Draft<'a> {
    pub(crate) tool: &'a CuttingTool,
    pub(crate) layer: usize,
    pub(crate) stage: Stage,
    pub(crate) fields: Vec<usize>,
    pub(crate) adjacency: Adjacency,
    pub(crate) area: f64,
    pub(crate) regions: Option<Regions>,
    /// Of the area, what lies over a floor (rough and semi-finish: left
    /// to the floor's finish), mm².
    pub(crate) floor: f64,
    /// Drilling: how, its holes (indices into the sites), their volume
    /// in the layers (mm³) and the highest entry (mm).
    pub(crate) drill: Option<DrillKind>,
    pub(crate) holes: Vec<usize>,
    pub(crate) drilled_mm3: f64,
    pub(crate) entry_mm: f64,
}

/// Why part of a feature is left unfinished.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RestCause {
    /// No tool of the library is narrow enough for its corners: a wider
    /// one leaves material in them.
    Corner,
    /// No tool's corner radius is small enough for its floor fillet: a
    /// rounder one leaves material in it.
    FloorFillet,
    /// No tool that fits is long enough: the walls below its flutes'
    /// reach are left.
    Depth,
}

/// What no tool of the library finishes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RadiusRest {
    pub cause: RestCause,
    /// The tool that leaves it (the one finishing the rest of the feature),
    /// if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tool: Option<String>,
    /// The part's surface left unfinished, mm².
    pub area_mm2: f64,
    /// The material left standing on it, mm³ (corners and fillets; none
    /// below a short tool's reach, which the roughing decides).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub volume_mm3: Option<f64>,
}

/// One feature finished by its radii.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RadiusFinish {
    /// The machining feature (`M…`).
    pub feature: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corner_radius_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub floor_fillet_mm: Option<f64>,
    pub depth_mm: f64,
    /// The widest tool it allows (the recognizer's bound), mm, and what
    /// bounds it.
    pub largest_tool_mm: f64,
    pub bounded_by: ToolBound,
    /// The widest tool its walls and floor fillet allow, corners aside
    /// (the floor's widest circle, widened by the fillet a bull-nose's
    /// corner sits in), mm.
    pub walls_tool_mm: f64,
    /// Its walls' and floor fillet's finishing tool.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub walls: Option<String>,
    /// Its corners' (the walls' tool where it fits them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corners: Option<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rest: Vec<RadiusRest>,
    /// Along up in the removal frame: its top and bottom, mm.
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    /// Its walls' and blends' area, mm², and their length along the floor,
    /// mm (the contour's length).
    pub area_mm2: f64,
    pub contour_mm: f64,
    /// Its corners' area, mm², and their arcs' length, mm.
    pub corner_area_mm2: f64,
    pub corner_arc_mm: f64,
    /// Its floor fillets' length along the floor, mm.
    pub fillet_length_mm: f64,
}

/// What a stage does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum HoleStep {
    Spot,
    Countersink,
    Chamfer,
    /// A rounded edge (a corner-rounding cutter; none in a library of
    /// end mills, drills and cones).
    Blend,
}

/// One stage of a hole other than its bores.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct HoleStage {
    /// The machining feature (`M…`).
    pub hole: String,
    pub step: HoleStep,
    /// At the far end of a through hole from the tool: the other set-up's
    /// (or a back-chamfering tool's).
    pub at_exit: bool,
    /// The cone's included angle, degrees (spot: the tool's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_deg: Option<f64>,
    /// Its diameter on the face (spot: the drilled bore's), mm.
    pub diameter_mm: f64,
    /// Where it starts along up in the removal frame, and how deep it
    /// cuts, mm.
    pub z_top_mm: f64,
    pub depth_mm: f64,
    /// The tool of the library that makes it; none: why not.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tool: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub missing: Option<String>,
}
