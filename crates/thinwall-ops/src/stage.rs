//! What an operation does (its stage), its share of Popma's regions, and
//! an operation before it has a place in the order (`Draft`): the types
//! the operations and their order share.

use crate::drilling::DrillKind;
use crate::rest::Adjacency;
use crate::tools::CuttingTool;
use serde::Serialize;

/// What an operation does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    Rough,
    SemiFinish,
    /// Along the part's walls: a tool's boundary region (Popma's, within
    /// the finishing stepover of a part contour), down milling at the
    /// finishing conditions, after that tool's roughing of the layer.
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
