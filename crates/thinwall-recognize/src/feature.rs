//! The recognizer's results: plain data with stable ids.

use crate::config::Kind;
use serde::{Deserialize, Serialize};

/// A point and unit normal, mm.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plane {
    pub point: [f64; 3],
    pub normal: [f64; 3],
}

/// One stiffness feature. Walls fill the wall fields; depressions and
/// details name the `wall` they are in or on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StiffnessFeature {
    /// Stable within a report: kind prefix and a number (`R2`, `H1`).
    pub id: String,
    pub kind: Kind,
    /// `step_id`s of all its faces.
    pub faces: Vec<u64>,
    /// Walls: `step_id`s of the faces of both sides.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub side_faces: Option<Vec<u64>>,
    /// Walls: the two sides separately.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sides: Option<[Vec<u64>; 2]>,
    /// Walls: needs stiffness support (cantilever deflection above the limit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thin: Option<bool>,
    /// mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// mm: foot to free edge (walls on a base), or the largest distance to
    /// a supporting wall (webs); depth of a cut-out; hole height.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// Cantilever deflection under the milling force, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deflection: Option<f64>,
    /// h/t (Sandvik: > 15 step-wise, > 30 pyramid).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slenderness: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mid_plane: Option<Plane>,
    /// Walls: tool access directions, one per side (outward side normals).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access_directions: Option<[[f64; 3]; 2]>,
    /// Walls: top and end faces (`step_id`s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub top_end_faces: Option<Vec<u64>>,
    /// Walls: the wall it stands on (may be a thick one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub base: Option<String>,
    /// Depressions and details: the wall it is in or on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wall: Option<String>,
    /// Holes: mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diameter: Option<f64>,
    /// Holes: height above 1.5 × the preferred tool diameter.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub large: Option<bool>,
    /// Holes: opens on both sides of the wall.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub through: Option<bool>,
    /// Fillets: mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Fillets: a convex round rather than a concave fillet.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub convex: Option<bool>,
    /// Cut-outs, notches, chamfers: width, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<f64>,
}

impl StiffnessFeature {
    pub fn new(kind: Kind, faces: Vec<u64>) -> Self {
        Self {
            id: String::new(),
            kind,
            faces,
            side_faces: None,
            sides: None,
            thin: None,
            thickness: None,
            height: None,
            length: None,
            deflection: None,
            slenderness: None,
            mid_plane: None,
            access_directions: None,
            top_end_faces: None,
            base: None,
            wall: None,
            diameter: None,
            large: None,
            through: None,
            radius: None,
            convex: None,
            width: None,
        }
    }
}

/// Id prefix of a kind.
pub fn prefix(kind: Kind) -> &'static str {
    match kind {
        Kind::Web => "W",
        Kind::Rib => "R",
        Kind::Flange => "F",
        Kind::Wall => "L",
        Kind::Hole => "H",
        Kind::Cutout => "C",
        Kind::Notch => "N",
        Kind::Chamfer => "CH",
        Kind::Fillet => "FL",
    }
}
