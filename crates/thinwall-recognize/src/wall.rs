//! A wall as the finders give it (its sides, thickness, region), and a
//! curved wall's surfaces and development: the data the flat (`walls`),
//! revolved (`curved`) and free-form (`offset`) finders share.

use geo::MultiPolygon;
use thinwall_brep::FaceId;
use thinwall_geom::{Frame, NurbsSurface, Point3, Vector3};

/// A wall before it is classified.
#[derive(Clone, Debug)]
pub struct Wall {
    /// Faces of side 0 (in plane `frame`, outward normal `frame.z`).
    pub sides: [Vec<FaceId>; 2],
    /// Outward normals of the two sides (tool access directions).
    pub normals: [Vector3; 2],
    /// Frame of side 0's plane: z is side 0's outward normal.
    pub frame: Frame,
    /// Distance between the side planes, mm (their mean distance over the
    /// region for a drafted wall).
    pub thickness: f64,
    /// Thinnest and thickest distance between the sides over the region,
    /// mm (equal unless drafted).
    pub thickness_range: (f64, f64),
    /// Side 1's plane: a point on it (side 0's is `frame.origin`).
    pub side1_point: Point3,
    /// Where the two sides bound the slab, in `frame`'s xy coordinates
    /// (developed, for a curved wall).
    pub region: MultiPolygon<f64>,
    /// A curved wall's surfaces and development (`None` for a flat wall).
    pub curved: Option<Box<CurvedWall>>,
}

/// A surface of revolution's coordinates: angle θ about `axis` from `u`,
/// distance `s` along the generator and offset across it (positive away
/// from the axis), for half-angle α (0 for a cylinder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Revolution {
    pub origin: Point3,
    pub axis: Vector3,
    pub u: Vector3,
    pub v: Vector3,
    /// Half-angle, radians (the radius grows along `axis`).
    pub half_angle: f64,
}

/// How a curved wall's region is laid flat: developed (x, y) and the
/// offset across the sides (towards side 0's outward normal) of a point,
/// and back.
#[derive(Clone, Debug, PartialEq)]
pub enum Development {
    Revolution(RevolutionDevelopment),
    /// Along side 0's free-form surface (the `offset` finder): x and y arc
    /// lengths on the mid-surface along the iso-curves through the centre;
    /// offsets from side 0 along its normal.
    Offset(Box<OffsetDevelopment>),
}

/// About an axis: x the arc at `r_mid` from the centre angle, y along the
/// generator from the centre; offsets are the family's.
#[derive(Clone, Debug, PartialEq)]
pub struct RevolutionDevelopment {
    pub rev: Revolution,
    /// The region's centre: angle (radians) and generator coordinate.
    pub theta_c: f64,
    pub s_c: f64,
    /// The mid-surface's radius at the centre.
    pub r_mid: f64,
}

/// A curved wall's surfaces and development.
#[derive(Clone, Debug, PartialEq)]
pub struct CurvedWall {
    pub dev: Development,
    /// Offsets of side 0 and side 1 (side 0's is the larger).
    pub off: [f64; 2],
    /// Each side's faces as developed polygons.
    pub side_polygons: [Vec<(FaceId, MultiPolygon<f64>)>; 2],
    /// Free-form walls: the thinnest and thickest distance measured
    /// between the sides, mm.
    pub measured: Option<(f64, f64)>,
}

/// Development along a free-form side (module docs): arc-length tables of
/// the mid-surface along the iso-curves through the centre of the face's
/// parameter box.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetDevelopment {
    pub(crate) surface: NurbsSurface,
    pub(crate) sign: f64,
    /// (parameter, arc length from the centre) along u and along v.
    pub(crate) u_table: Vec<(f64, f64)>,
    pub(crate) v_table: Vec<(f64, f64)>,
    pub(crate) length: f64,
}
