//! The named tolerances of Thinwall, in one place.
//!
//! Linear tolerances scale with the part: a tolerance that is right for a
//! 20 mm bracket is wrong for a 1.7 m wing panel, so [`Tolerances::for_part`]
//! derives them from the diagonal of the part's bounding box and clamps them
//! to a floor that is still far above floating-point noise.

use serde::{Deserialize, Serialize};

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
}
