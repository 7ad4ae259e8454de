//! Volume types and results.

use serde::{Deserialize, Serialize};

pub use thinwall_analysis::VolumeType;

/// The order in which types are tried when a pattern fits several (a U of
/// closed sides is a blind slot and also a chain, i.e. a step).
pub const DEFAULT_PRIORITY: [VolumeType; 11] = [
    VolumeType::Hole,
    VolumeType::Pocket,
    VolumeType::Passage,
    VolumeType::FreePocket,
    VolumeType::FreePassage,
    VolumeType::BlindSlot,
    VolumeType::ThroughSlot,
    VolumeType::CornerNotch,
    VolumeType::Step,
    VolumeType::FreeStep,
    VolumeType::Face,
];

/// Which closed faces touch the part itself.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ProductAdjacency {
    None,
    Side,
    Bottom,
    SideAndBottom,
}

impl ProductAdjacency {
    pub fn name(self) -> &'static str {
        match self {
            ProductAdjacency::None => "none",
            ProductAdjacency::Side => "side",
            ProductAdjacency::Bottom => "bottom",
            ProductAdjacency::SideAndBottom => "side_and_bottom",
        }
    }
}

/// The role of a volume face along the tool direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaceRole {
    /// The access face (normal along up).
    Top,
    Bottom,
    Side,
    /// Neither: the volume is not 2.5D along the tool direction.
    Other,
}

/// What a volume face coincides with.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Touch {
    /// A face of the part, by STEP entity id.
    Part { step_id: u64 },
    /// A face of another volume.
    Volume { index: usize, step_id: u64 },
}

/// One face of a volume.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VolumeFace {
    /// Entity id in the volume's own STEP file.
    pub step_id: u64,
    pub role: FaceRole,
    pub surface: String,
    /// Coincides over an area with the part or a volume not removed before this one.
    pub closed: bool,
    pub touches: Vec<Touch>,
}

/// The classification of one volume.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Classification {
    pub index: usize,
    pub name: String,
    #[serde(rename = "type")]
    pub kind: VolumeType,
    /// Why the volume is `unknown`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    pub product_adjacency: ProductAdjacency,
    /// Unit tool direction (from the access face into the part).
    pub direction: [f64; 3],
    pub bottom_open: bool,
    pub faces: Vec<VolumeFace>,
    /// Side faces touching the part (`step_id`s in the volume file).
    pub product_adjacent_sides: Vec<u64>,
    /// mm along the tool direction.
    pub depth: f64,
    /// Profile sizes, mm (minimum rectangle of the profile).
    pub length: f64,
    pub width: f64,
    /// Corner radii, mm.
    pub corner_radii: Vec<f64>,
}
