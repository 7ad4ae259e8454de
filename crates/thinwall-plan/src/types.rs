//! The planner's shared data types: layers, wall shapes, removal features
//! and their solids, their types and order, the plan itself. Every other
//! module of the crate imports them from here, and this module imports
//! none of them back.

use crate::sequence::{Constraint, Rejected, Sequence};
use crate::sizing::Sizes;
use serde::Serialize;
use std::fmt;
use thinwall_analysis::{FeatureId, StiffnessKind, VolumeType};
use thinwall_classify::ProductAdjacency;
use thinwall_connect::Connection;
use thinwall_geom::{Point3, Vector3};
use thinwall_removal::pieces::Height;
use thinwall_removal::Bound;
use thinwall_removal::RemovalError;

/// Which rule of §4.1.3 changed the plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AdaptRule {
    ConnectedWall,
    LargeCutouts,
    CutoutInSequence,
    LargeHoles,
    HoleInSequence,
    Chamfer,
}

/// One change to a wall's step approach, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Adaptation {
    pub wall: FeatureId,
    /// The connected feature that asked for it.
    pub by: FeatureId,
    pub rule: AdaptRule,
    pub change: String,
}

/// How a wall's layers are laid out after the adaptations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallShape {
    /// Layer width on side 0 and side 1, mm.
    pub width: [f64; 2],
    /// A height above the foot where a large layer must end (the step
    /// separation line), mm.
    pub align_at: Option<f64>,
}

/// A wall's height axis: where its foot is and how tall it is.
#[derive(Clone, Copy, Debug)]
pub struct Axis {
    pub origin: Point3,
    pub height_dir: Vector3,
    pub length_dir: Vector3,
    /// `(p − origin)·height_dir` at the foot, mm.
    pub foot: f64,
    pub height: f64,
    /// The wall's extent along its length, mm.
    pub length: (f64, f64),
}

/// A large hole cut at its wall's step separation line: the material
/// inside it above the line and below it are two features (fig. 4.8).
#[derive(Clone, Debug, PartialEq)]
pub struct HoleSplit {
    pub hole: FeatureId,
    /// Its faces' step ids.
    pub faces: Vec<u64>,
    /// The line's height along up (the removal frame's z), mm.
    pub z: f64,
}

/// Large or small layer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SizeClass {
    Large,
    Small,
}

/// One layer of a wall's step approach.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Layer {
    /// `V1`, `V2`, … in plan order.
    pub id: VolumeId,
    /// The wall it helps create.
    pub owner: FeatureId,
    /// Which side of the owner (0 or 1, as the recognition's `sides`).
    pub side: u8,
    pub size_class: SizeClass,
    /// Its place in its wall's sequence (1 = first), as fig. 4.1 numbers it.
    pub step: usize,
    /// Heights above the wall's foot along its height direction, mm.
    pub from_foot: [f64; 2],
    /// Lowest and highest point along the set-up's up, mm.
    pub z_range: [f64; 2],
    /// Its bottom and top along up on the wall's height axis (where the
    /// removal plan cuts; a layer beside a drafted wall is a sheared box
    /// whose corners lie a little above and below these), mm.
    pub cut_heights: [f64; 2],
    /// Width beside the wall, height, length, mm.
    pub width: f64,
    pub height: f64,
    pub length: f64,
    /// Its eight corners, mm.
    pub corners: Vec<[f64; 3]>,
}

/// What a machining feature is in the plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FeatureClass {
    /// A step-approach layer, `H_RF` tall.
    Large,
    /// A step-approach layer, `h_RF` tall.
    Small,
    /// The rest reachable from up (pocket cores, above the walls, around
    /// the part).
    Bulk,
    /// Nothing of it is open to up: another set-up or 5 axes.
    OtherSetup,
    /// A detail's own feature: the material over a chamfer, up to its top
    /// (§4.1.3).
    Detail,
}

/// One piece of a feature: part of a cell of the decomposition between two
/// bounds.
#[derive(Clone, Debug)]
pub struct Piece {
    pub cell: usize,
    pub region: geo::MultiPolygon<f64>,
    pub lower: Bound,
    pub upper: Bound,
    /// Nominal heights of the two ends, mm.
    pub z: [f64; 2],
    pub volume: f64,
    /// The block it was cut from: its bounds say what it lies on and under.
    pub block: [Bound; 2],
}

/// A machining feature of the plan.
#[derive(Clone, Debug, Serialize)]
pub struct RemovalFeature {
    /// `V…` for layers (their step-approach id), `B…` bulk, `X…` other
    /// set-up.
    pub id: VolumeId,
    /// The stiffness feature it belongs to (none: around the part).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub owner: Option<FeatureId>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub side: Option<u8>,
    /// Layers: its place in its wall's step approach (fig. 4.1).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step: Option<usize>,
    pub size_class: FeatureClass,
    /// Lowest and highest point along the set-up's up, mm.
    pub z_range: [f64; 2],
    /// mm³.
    pub volume_mm3: f64,
    /// Layers: the volume of the designed box, before the part and earlier
    /// features took their share, mm³.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub box_volume_mm3: Option<f64>,
    /// `step_id`s of the part faces it touches.
    pub faces: Vec<u64>,
    /// Whether the set-up's tool reaches it from up.
    pub reachable: bool,
    /// Other set-up: the direction to reach it from (unit), where known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<[f64; 3]>,
    /// What interference did to it, and why.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub changes: Vec<String>,
    /// Its pieces (in memory, while the decomposition is alive).
    #[serde(skip)]
    pub pieces: Vec<Piece>,
    /// Its solids: each a region of the set-up plane between two heights.
    pub solids: Vec<FeatureSolid>,
    /// Its type and product adjacency (`classified`).
    #[serde(flatten)]
    pub classification: Option<crate::types::FeatureType>,
}

/// A solid of a feature: a polygon of the set-up plane (in the plan's
/// `frame`) between a lower and an upper height (planes or half
/// cylinders).
#[derive(Clone, Debug, Serialize)]
pub struct FeatureSolid {
    /// The outer ring (counter-clockwise seen from up), then the holes; in
    /// the frame's x, y, mm.
    pub rings: Vec<Vec<[f64; 2]>>,
    pub lower: Height,
    pub upper: Height,
    pub volume_mm3: f64,
}

/// A feature's classification.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FeatureType {
    #[serde(rename = "type")]
    pub kind: VolumeType,
    pub product_adjacency: ProductAdjacency,
    /// The types of its other solids, where they differ.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub types: Vec<VolumeType>,
    /// Why it is `unknown`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

/// `before` comes out before `after`, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FeatureRelation {
    pub before: VolumeId,
    pub after: VolumeId,
    pub why: String,
}

/// The relations in force, those dropped, and the order.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FeatureSequence {
    pub relations: Vec<FeatureRelation>,
    pub dropped: Vec<FeatureRelation>,
    pub order: Vec<VolumeId>,
}

/// A feature as the plan lists it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlannedFeature {
    pub id: FeatureId,
    pub kind: StiffnessKind,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thin: Option<bool>,
    /// Highest point along the set-up's up, mm.
    pub top: f64,
}

/// A plan: the features, their connections and their sequence.
#[derive(Clone, Debug, Serialize)]
pub struct Plan {
    pub schema: String,
    pub thinwall_version: String,
    pub file: String,
    pub up: [f64; 3],
    /// Where the rules came from (`default` or a file).
    pub rules: String,
    pub stiffness_features: Vec<PlannedFeature>,
    pub connections: Vec<Connection>,
    /// The constraints in force.
    pub sequence: Vec<Constraint>,
    /// Candidates not enforced, with why.
    pub rejected: Vec<Rejected>,
    /// A valid order, level by level.
    pub order: Vec<Vec<FeatureId>>,
    /// Every thin wall's machining-feature sizes (webs face milled, the
    /// others peripheral), with the recognition's force, material and
    /// tool.
    pub walls: Vec<WallPlan>,
    /// What §4.1.3 changed in the walls' step approach, and why.
    pub adaptations: Vec<Adaptation>,
    /// The step approach's layers beside every peripherally milled thin
    /// wall as designed (boxes), in plan order.
    pub layers: Vec<Layer>,
    /// Between layers: each wall's steps in order, and a wall's last step
    /// before the next wall's first where the stiffness sequence says so.
    pub layer_sequence: Vec<LayerConstraint>,
    /// The whole removal: stock − part, exactly, and how it was cut.
    pub removal: RemovalSummary,
    /// The removal frame: origin, x, y and z (= up); feature solids are
    /// given in it.
    pub frame: [[f64; 3]; 4],
    /// Every bit of stock − part in one feature: the layers as they remain
    /// after interference, bulk, and what another set-up must reach.
    pub machining_features: Vec<RemovalFeature>,
    /// Relations between machining features and one order respecting them.
    pub feature_sequence: FeatureSequence,
    /// Where a planner layer did not apply, one line each (curved walls:
    /// sequenced and sized, but their step approach is not designed yet).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub limits: Vec<String>,
    /// Thin webs with material still under them in this set-up (a later
    /// set-up takes it): supported, so no step layers here (`turn.rs`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub supported_webs: Vec<FeatureId>,
    /// The set-ups after this one, planned in turn (issue 37): each one's
    /// stock what the set-ups before it left. Empty for a plan of one
    /// set-up; a later set-up's plan has none of its own.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub then: Vec<Plan>,
    /// What none of the set-ups reaches (a plan over several set-ups).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residue: Option<thinwall_setups::Residue>,
    /// The set-ups proposed and why (when they were not given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub proposal: Option<thinwall_setups::Proposal>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP and
    /// in a later set-up's plan (`then`: the first one's holds).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
    /// The in-memory sequence, for queries.
    #[serde(skip)]
    pub queries: Sequence,
}

impl Plan {
    /// The removal frame (`frame`) as a frame.
    pub fn removal_frame(&self) -> thinwall_geom::Frame {
        let f = self.frame;
        thinwall_geom::Frame {
            origin: f[0].into(),
            x: f[1].into(),
            y: f[2].into(),
            z: f[3].into(),
        }
    }
}

/// The removal's figures, or why there is none.
#[derive(Clone, Debug, Default, Serialize)]
pub struct RemovalSummary {
    /// `block` (the set-up's bounding block), `block + offset`, or `solid`.
    pub stock: String,
    pub stock_volume_mm3: f64,
    pub part_volume_mm3: f64,
    /// Σ of the machining features' volumes, mm³.
    pub removed_volume_mm3: f64,
    /// Cells of the decomposition.
    pub cells: usize,
    /// Total of the boolean slivers left out (each under 1e-12 of the
    /// stock), mm³.
    pub slivers_mm3: f64,
    /// Why the removal could not be decomposed (no machining features
    /// then).
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "unavailable_text"
    )]
    pub unavailable: Option<RemovalError>,
    /// Layers left out of the removal (not prisms along up), with why.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// Faces taken as triangles (tilted cylinders, cones and tori,
    /// free-form faces): their area and the volume bound they imply.
    #[serde(skip_serializing_if = "thinwall_removal::pieces::Meshed::is_empty")]
    pub meshed: thinwall_removal::pieces::Meshed,
    /// A set-up after others: the volume of the blocks they took (no
    /// feature of this set-up's holds it), mm³.
    #[serde(skip_serializing_if = "is_zero")]
    pub cleared_before_mm3: f64,
    /// A set-up after others: the volume of the blocks they took in part,
    /// cut whole again here (at most that much is air), mm³.
    #[serde(skip_serializing_if = "is_zero")]
    pub recut_mm3: f64,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

/// A `before` relation between two layers and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LayerConstraint {
    pub before: VolumeId,
    pub after: VolumeId,
    pub why: String,
}

/// A thin wall's sizes.
#[derive(Clone, Debug, Serialize)]
pub struct WallPlan {
    pub id: FeatureId,
    pub kind: StiffnessKind,
    #[serde(flatten)]
    pub sizes: Sizes,
}

/// Why the removal is unavailable, as the plan's JSON gives it:
/// `removal.<code>: <message>`.
fn unavailable_text<S: serde::Serializer>(
    e: &Option<RemovalError>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match e {
        Some(e) => s.serialize_str(&format!("removal.{}: {e}", e.code())),
        None => s.serialize_none(),
    }
}

/// The id of a step-approach layer or of a removal (machining) feature:
/// `V3` (a layer, and the feature it becomes), `B1` (bulk), `X2` (another
/// set-up's). Typed so that it is never taken for a stiffness feature's
/// id; written as its text.
/// (The default, empty, is a placeholder until the id is given.)
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(transparent)]
pub struct VolumeId(String);

impl VolumeId {
    /// The `n`-th id with `prefix` (`V`, `B`, `X`).
    pub fn new(prefix: char, n: usize) -> Self {
        Self(format!("{prefix}{n}"))
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for VolumeId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::ops::Deref for VolumeId {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl std::borrow::Borrow<str> for VolumeId {
    fn borrow(&self) -> &str {
        &self.0
    }
}

impl PartialEq<str> for VolumeId {
    fn eq(&self, other: &str) -> bool {
        self.0 == other
    }
}

impl PartialEq<&str> for VolumeId {
    fn eq(&self, other: &&str) -> bool {
        self.0 == *other
    }
}
