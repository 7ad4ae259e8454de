//! The named tolerances of Thinwall, in one place.
//!
//! Linear tolerances scale with the part: a tolerance that is right for a
//! 20 mm bracket is wrong for a 1.7 m wing panel, so [`Tolerances::for_part`]
//! derives them from the diagonal of the part's bounding box and clamps them
//! to a floor that is still far above floating-point noise.

use serde::{Deserialize, Serialize};

/// A free-form surface within this of a cylinder over its whole domain is
/// that cylinder, mm.
pub const FREEFORM_FIT_MM: f64 = 1e-7;

/// Relative linear tolerance: fraction of the part's bounding-box diagonal.
pub const RELATIVE_LINEAR: f64 = 1e-7;
/// Smallest linear tolerance we ever use, mm (STEP writers typically model
/// at 1e-7 … 1e-3 mm).
pub const MIN_LINEAR_MM: f64 = 1e-6;
/// Angle under which two face normals across an edge count as tangent
/// (smooth edge), radians. OpenCascade's `BRepOffset_Analyse` is usually
/// run with a 0.01 rad tangency angle; we use the same.
pub const TANGENT_ANGLE_RAD: f64 = 0.01;
/// Angle under which two directions count as parallel, radians.
pub const PARALLEL_ANGLE_RAD: f64 = 1e-3;

/// The tolerances in force for one part.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Tolerances {
    /// Distance under which two points are the same, mm.
    pub linear: f64,
    /// Normal angle under which an edge is smooth (tangent), radians.
    pub tangent_angle: f64,
    /// Angle under which two directions are parallel, radians.
    pub parallel_angle: f64,
}

impl Default for Tolerances {
    fn default() -> Self {
        Self {
            linear: MIN_LINEAR_MM,
            tangent_angle: TANGENT_ANGLE_RAD,
            parallel_angle: PARALLEL_ANGLE_RAD,
        }
    }
}

impl Tolerances {
    /// Tolerances for a part whose bounding-box diagonal is `diagonal` mm.
    pub fn for_part(diagonal: f64) -> Self {
        let linear = if diagonal.is_finite() {
            (diagonal * RELATIVE_LINEAR).max(MIN_LINEAR_MM)
        } else {
            MIN_LINEAR_MM
        };
        Self {
            linear,
            ..Self::default()
        }
    }
}

/// Angle within which two feature directions count as parallel, degrees
/// (wall side faces, volume faces, set-up directions). Not 0.5°: that is a
/// common draft, and a draft on the boundary tips one way or the other
/// with the rounding of a turned part.
pub const FEATURE_PARALLEL_DEG: f64 = 0.3;
/// Largest lean of a volume's side from the tool direction, degrees: a
/// side beside a drafted wall is a side. Above the recognizer's largest
/// wall draft (5° by default) with a margin, so that no common draft sits
/// on the boundary and tips with the rounding of a turned part.
pub const MAX_SIDE_DRAFT_DEG: f64 = 6.0;
/// `1 − cos` under which two unit normals of feature faces are the same
/// direction (machining features: block planes, floors).
pub const UNIT_PARALLEL_EPS: f64 = 1e-9;

/// `1 − cos` under which two unit directions count as parallel where a
/// looser test than [`UNIT_PARALLEL_EPS`] is wanted (a hole's closing
/// face across its axis, floors facing back along a feature's direction).
pub const NEAR_PARALLEL_EPS: f64 = 1e-6;
/// A cross product of unit vectors shorter than this gives no direction
/// (the two were parallel).
pub const DIRECTION_NORM_MIN: f64 = 1e-6;

/// The linear tolerances recognizers and planners use, all derived from one
/// part's bounding-box diagonal (mm) and built once per part by the
/// analysis context. Each is a named multiple of the part's size with a
/// floor, so a 20 mm bracket and a 2 m panel are judged alike.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PartTolerances {
    /// The part's bounding-box diagonal, mm.
    pub diagonal: f64,
    /// Point coincidence ([`Tolerances::linear`]), mm.
    pub linear: f64,
    /// Two planar faces lie in one plane, mm: 100 × linear, at least 1e-4.
    pub coplanar: f64,
    /// Smallest overlap area of two wall side faces, mm².
    pub min_overlap_area: f64,
    /// A face lies within a wall's slab, mm: 1000 × linear, at least 1e-3.
    pub slab: f64,
    /// Feature geometry coincides (block planes, hole ends, equal heights),
    /// mm: 1e-6 of the diagonal (of at least 1 mm).
    pub feature: f64,
    /// Faces of a volume and of the part coincide, mm: 1e-6 of the diagonal,
    /// at least 1e-5.
    pub coincidence: f64,
    /// Smallest coincidence area of two faces, mm².
    pub min_coincidence_area: f64,
}

impl PartTolerances {
    /// The tolerances of a part whose bounding-box diagonal is `diagonal` mm.
    pub fn for_diagonal(diagonal: f64) -> Self {
        let linear = Tolerances::for_part(diagonal).linear;
        let coplanar = (linear * 100.0).max(1e-4);
        let coincidence = (diagonal * 1e-6).max(1e-5);
        Self {
            diagonal,
            linear,
            coplanar,
            min_overlap_area: (coplanar * coplanar * 100.0).max(1e-6),
            slab: (linear * 1000.0).max(1e-3),
            feature: 1e-6 * diagonal.max(1.0),
            coincidence,
            min_coincidence_area: coincidence.powi(2) * 100.0,
        }
    }
}

// The planner's and the removal's tolerances (lengths in mm; fractions of
// the quantity named: the part's size, the stock's volume).

/// Lengths closer than this are equal when sizes and layer heights are
/// compared: a wall measured on a turned part is its height up to the
/// rounding of the turn, and a comparison at a boundary must not tip.
pub const SAME_LENGTH_MM: f64 = 1e-6;

/// A piece under this fraction of the stock's volume is a sliver of the
/// 2-D booleans (edges that coincide up to rounding), not material.
pub const SLIVER: f64 = 1e-9;

/// A bulk or other-set-up feature under this fraction of the stock's
/// volume (a skim of a hundredth of a millimetre left by a drafted wall's
/// top) joins the feature above or below it in its column.
pub const MERGE: f64 = 1e-6;

/// Solids whose volumes differ by less than this fraction are equal (up to
/// the sampling of curved edges) when a feature's main solid is chosen.
pub const EQUAL_VOLUME: f64 = 1e-6;

/// A cell whose mean width (2·area / perimeter) is under this fraction of
/// the part's size is a sliver of the 2-D booleans: the booleans round to
/// a grid of about 1e-9 of their inputs' extent, so their decisions there
/// are noise. Cell vertices closer than it are one vertex when a feature's
/// cells are joined into solids.
pub const SLIVER_WIDTH: f64 = 1e-6;

/// The largest deviation of the triangles a face the removal cannot take
/// exactly is meshed into (a tilted cylinder, a free-form face), mm: the
/// finishing tolerance of Schuster's roughing (0.01 mm) halved.
pub const MACHINING_DEVIATION_MM: f64 = 0.005;

/// The same as a fraction of the part's size (a small part meshes finer).
pub const MACHINING_DEVIATION_REL: f64 = 1e-5;

/// The machining deviation for a part of size `size` (its bounding
/// diagonal), mm: min(0.005 mm, 1e-5 × size).
pub fn machining_deviation(size: f64) -> f64 {
    MACHINING_DEVIATION_MM.min(MACHINING_DEVIATION_REL * size)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_tolerance_scales_with_part_and_has_a_floor() {
        assert_eq!(Tolerances::for_part(1.0).linear, MIN_LINEAR_MM);
        let big = Tolerances::for_part(2000.0).linear;
        assert!((big - 2e-4).abs() < 1e-12);
        assert_eq!(Tolerances::for_part(f64::NAN).linear, MIN_LINEAR_MM);
    }

    #[test]
    fn part_tolerances_scale_and_keep_their_floors() {
        let small = PartTolerances::for_diagonal(1.0);
        assert_eq!(small.coplanar, 1e-4);
        assert_eq!(small.slab, 1e-3);
        assert_eq!(small.coincidence, 1e-5);
        let big = PartTolerances::for_diagonal(20_000.0);
        assert!((big.slab - 2.0).abs() < 1e-12, "{}", big.slab);
        assert!((big.feature - 0.02).abs() < 1e-15);
        assert!(big.min_overlap_area > small.min_overlap_area);
    }
}
