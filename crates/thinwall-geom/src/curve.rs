//! What an edge's curve is, beyond its evaluable NURBS form.

use crate::{Frame, Point3, Vector3};
use serde::{Deserialize, Serialize};

/// The analytic description of a curve, when it has one. Evaluation always
/// goes through the edge's exact NURBS form; this is for recognizers that
/// need "a circle of radius 6" rather than control points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum CurveKind {
    Line {
        origin: Point3,
        direction: Vector3,
    },
    Circle {
        frame: Frame,
        radius: f64,
    },
    Ellipse {
        frame: Frame,
        semi_axis_1: f64,
        semi_axis_2: f64,
    },
    Bspline,
    Polyline,
    /// Any other curve type, by its STEP keyword.
    Other {
        keyword: String,
    },
}

impl CurveKind {
    /// A short lower-case name (`line`, `circle`, …).
    pub fn name(&self) -> &str {
        match self {
            CurveKind::Line { .. } => "line",
            CurveKind::Circle { .. } => "circle",
            CurveKind::Ellipse { .. } => "ellipse",
            CurveKind::Bspline => "bspline",
            CurveKind::Polyline => "polyline",
            CurveKind::Other { .. } => "other",
        }
    }

    /// Whether the curve is straight.
    pub fn is_line(&self) -> bool {
        matches!(self, CurveKind::Line { .. })
    }
}
