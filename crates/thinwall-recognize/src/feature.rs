//! The recognizer's results: plain data with stable ids.

use geo::MultiPolygon;
use serde::{Deserialize, Serialize};
use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_brep::FaceId;
use thinwall_geom::{Frame, Point3, Vector3};

/// A point and unit normal, mm.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plane {
    pub point: [f64; 3],
    pub normal: [f64; 3],
}

/// A wall's figures on the far side of the base it runs through.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OtherSide {
    /// The base's side faces it stands on there (`step_id`s).
    pub base_faces: Vec<u64>,
    /// From that side of the base to the wall's end, mm.
    pub height: f64,
    /// Cantilever deflection of that part under the milling force, mm.
    pub deflection: f64,
    /// h/t of that part.
    pub slenderness: f64,
    pub thin: bool,
}

/// One stiffness feature. Walls fill the wall fields; depressions and
/// details name the `wall` they are in or on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StiffnessFeature {
    /// Stable within a report: kind prefix and a number (`R2`, `H1`).
    pub id: FeatureId,
    pub kind: StiffnessKind,
    /// The body (solid, or placed instance of an assembly) its faces are
    /// on, by index into the report's `bodies`: with it, a `step_id` names
    /// one face even where instances share ids. A feature never spans bodies.
    pub body: u32,
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
    /// mm; a drafted wall's thinnest (the section its thinness is judged on).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// Drafted walls: the thickness at the foot and at the top (the far
    /// end from the base), mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness_foot: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness_top: Option<f64>,
    /// mm: foot to free edge (walls on a base), or the largest distance to
    /// a supporting wall (webs); depth of a cut-out; hole height.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// A wall running through its base to both of its sides (a frame's
    /// outer wall, a rib through a double-sided web): its figures on the
    /// base's other side. `height`, `deflection` and the foot are on the
    /// side this set-up machines (the base's side facing up); `thin` holds
    /// when either side needs support.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_side: Option<OtherSide>,
    /// Cantilever deflection under the milling force, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deflection: Option<f64>,
    /// h/t (Sandvik: > 15 step-wise, > 30 pyramid).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slenderness: Option<f64>,
    /// Walls: where the figures leave the cantilever model's validity
    /// (a deflection over 10 % of h, h/t under 5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model_note: Option<String>,
    /// Flat walls: the plane half-way between the sides.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mid_plane: Option<Plane>,
    /// Curved walls, instead of `mid_plane`: the surface half-way between
    /// the sides (axis, radius, angle range).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mid_surface: Option<crate::curved::MidSurface>,
    /// Walls: tool access directions, one per side (outward side normals;
    /// a curved wall's at the middle of its arc).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access_directions: Option<[[f64; 3]; 2]>,
    /// Curved walls: per side, the outward normals at the two ends of the
    /// arc; the access direction sweeps between them about the axis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access_range: Option<[[[f64; 3]; 2]; 2]>,
    /// Walls: top and end faces (`step_id`s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub top_end_faces: Option<Vec<u64>>,
    /// Walls: the wall it stands on (may be a thick one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub base: Option<FeatureId>,
    /// Depressions and details: the wall it is in or on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wall: Option<FeatureId>,
    /// A pocket's blends (its corner radii and floor fillet, running round
    /// the floor a web is and up the walls standing on it): every wall they
    /// touch, the web (`wall`) first. Empty for a detail of one wall.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub walls: Vec<FeatureId>,
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
    /// The machining features sharing a face with it (filled by the
    /// pipeline, which runs both recognizers).
    #[serde(default)]
    pub related: Vec<thinwall_analysis::MachiningId>,
    /// Flat walls: the geometry a planner builds on (region, side polygons,
    /// foot line). Library only, not in the JSON. Curved walls have none
    /// yet: the planner layers say so where they skip them.
    #[serde(skip)]
    pub geometry: Option<WallGeometry>,
}

/// What a planner needs of a wall's shape, in the frame of its side 0
/// (`frame.z` is side 0's outward normal; side 1 lies at `z = −thickness`,
/// the mid-plane at `z = −thickness / 2`).
#[derive(Clone, Debug, PartialEq)]
pub struct WallGeometry {
    pub frame: Frame,
    /// mm.
    pub thickness: f64,
    /// Where the two sides bound the slab, in `frame`'s xy coordinates (mm):
    /// the wall's outline in its mid-plane.
    pub region: MultiPolygon<f64>,
    /// Each side's faces with their polygons in `frame`'s xy coordinates.
    pub side_polygons: [Vec<(FaceId, MultiPolygon<f64>)>; 2],
    /// Unit direction of its height (away from the base; in-plane up for a
    /// wall without a base).
    pub height_direction: Vector3,
    /// Walls on a base: where the mid-plane meets the base's side, from one
    /// end of the wall to the other (mm).
    pub foot: Option<[Point3; 2]>,
}

impl WallGeometry {
    /// The outline of the region on the mid-plane, in model coordinates.
    pub fn outline(&self) -> Vec<Point3> {
        crate::walls::region_outline(&self.frame, &self.region, -0.5 * self.thickness)
    }
}

impl StiffnessFeature {
    /// Walls: a point half-way between the sides (on the mid-plane, or the
    /// mid-surface's centre) and side 0's normal there.
    pub fn mid_point(&self) -> Option<([f64; 3], [f64; 3])> {
        match (&self.mid_plane, &self.mid_surface) {
            (Some(m), _) => Some((m.point, m.normal)),
            (None, Some(m)) => Some((m.centre, m.normal)),
            (None, None) => None,
        }
    }

    pub fn new(kind: StiffnessKind, faces: Vec<u64>) -> Self {
        Self {
            id: FeatureId::new(kind, 0),
            kind,
            body: 0,
            faces,
            side_faces: None,
            sides: None,
            thin: None,
            thickness: None,
            thickness_foot: None,
            thickness_top: None,
            height: None,
            length: None,
            other_side: None,
            deflection: None,
            slenderness: None,
            model_note: None,
            mid_plane: None,
            mid_surface: None,
            access_directions: None,
            access_range: None,
            top_end_faces: None,
            base: None,
            wall: None,
            walls: Vec::new(),
            diameter: None,
            large: None,
            through: None,
            radius: None,
            convex: None,
            width: None,
            related: Vec::new(),
            geometry: None,
        }
    }
}
