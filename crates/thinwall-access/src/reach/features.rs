//! The largest tool for each machining feature, one answer with the
//! recognizer and the operations (issue 38): the least of the recognizer's
//! bound (`largest_tool_diameter`: 2R at its corners, its floor's widest
//! circle widened by its floor fillet, a hole's bore) and the largest tool
//! (the run's proportions, along the set-up's up) that reaches its faces
//! whole, which knows the material around it. A floor its own fillet
//! bounds, and the blends, are the bull-nose's the fillet asks for: judged
//! by the bound, not by a flat tool's reach.

use super::largest::TOOL_PRECISION;
use super::FaceReach;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use thinwall_analysis::{MachiningId, MachiningKind, PartAnalysis};
use thinwall_geom::Surface;
use thinwall_machining::{MachiningFeature, ToolBound};

/// One machining feature's largest tools.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FeatureTool {
    pub feature: MachiningId,
    pub kind: MachiningKind,
    /// The largest tool reaching every face of it whole, mm; none when
    /// some face no tool of at least the smallest size reaches whole (a
    /// sharp inside corner, a face turned away from up).
    pub largest_tool_mm: Option<f64>,
    /// The face whose own largest tool bounds it (STEP id), when a face's
    /// reach does.
    pub bounded_by: Option<u64>,
    /// The recognizer's bound, when it decides (the feature's shape is
    /// narrower than any face's reach): its corner radius, its floor's
    /// width, its bore.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bound: Option<ToolBound>,
    /// The largest tool reaching every floor of it whole, mm (none without
    /// floors, or when a floor is not reached whole by any).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floors_mm: Option<f64>,
    /// The recognizer's bound from the floor's shape alone, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fits_mm: Option<f64>,
}

/// Each machining feature's largest tools, from its faces' (judged with
/// the largest-tool search on); features whose faces were not all judged
/// are left out.
pub fn feature_tools(
    a: &PartAnalysis,
    machining: &[MachiningFeature],
    faces: &[FaceReach],
) -> Vec<FeatureTool> {
    let by_face: BTreeMap<(u32, u64), &FaceReach> =
        faces.iter().map(|f| ((f.body, f.face), f)).collect();
    let mut out = Vec::new();
    for m in machining {
        let reach: Option<Vec<&FaceReach>> = m
            .faces
            .iter()
            .map(|s| by_face.get(&(m.body, *s)).copied())
            .collect();
        let Some(reach) = reach else { continue };
        // A floor its own fillet bounds all round, and the blends, are
        // reached by the bull-nose the fillet asks for (the recognizer's
        // bound, which knows its radii); their flat-tool reach answers for
        // another tool. The walls' reach (the holder's way down) still
        // counts.
        // Likewise a hole's cones and blends (its countersink, chamfers,
        // a drill's point) are the tools' of those stages: its bores are
        // judged.
        let cone = |step: u64| {
            a.part()
                .face_by_step_id(step)
                .is_some_and(|f| matches!(a.part().face(f).surface, Surface::Cone { .. }))
        };
        let formed = |f: &&FaceReach| {
            m.blend_faces.contains(&f.face)
                || m.chamfer_faces.contains(&f.face)
                || (m.bottom_faces.contains(&f.face) && m.floor_fillet.is_some())
                || (m.kind == MachiningKind::Hole && cone(f.face))
        };
        let judged: Vec<&FaceReach> = reach.iter().copied().filter(|f| !formed(f)).collect();
        let (by_faces, face) = smallest(&judged);
        let (largest_tool_mm, bounded_by, bound) = match (by_faces, m.largest_tool_diameter) {
            // Within the search's precision the exact bound wins.
            (Some(d), Some(fit)) if fit <= d + (TOOL_PRECISION * d).max(0.01) => {
                (Some(fit), None, m.tool_bound)
            }
            (None, Some(fit)) if judged.is_empty() => (Some(fit), None, m.tool_bound),
            (d, _) => (d, face, None),
        };
        let floors: Vec<&FaceReach> = reach
            .iter()
            .copied()
            .filter(|f| m.bottom_faces.contains(&f.face))
            .collect();
        out.push(FeatureTool {
            feature: m.id,
            kind: m.kind,
            largest_tool_mm,
            bounded_by,
            bound,
            floors_mm: if floors.is_empty() {
                None
            } else {
                smallest(&floors).0
            },
            fits_mm: m.largest_tool_diameter,
        });
    }
    out
}

/// The least of the faces' largest tools and its face (the first in the
/// feature's order among equals); none when some face has none.
fn smallest(faces: &[&FaceReach]) -> (Option<f64>, Option<u64>) {
    let mut best: Option<(f64, u64)> = None;
    for f in faces {
        let Some(d) = f.largest_tool_mm else {
            return (None, Some(f.face));
        };
        if best.is_none_or(|(b, _)| d < b) {
            best = Some((d, f.face));
        }
    }
    (best.map(|b| b.0), best.map(|b| b.1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reach::Contact;

    fn face(id: u64, largest: Option<f64>) -> FaceReach {
        FaceReach {
            face: id,
            body: 0,
            contact: Contact::Side,
            area_mm2: 1.0,
            fraction: 1.0,
            unreachable_mm2: 0.0,
            axis: [0.0, 0.0, 1.0],
            tilt_deg: 0.0,
            whole_axes: vec![],
            blocked_by: vec![],
            unreachable: vec![],
            largest_tool_mm: largest,
            note: None,
        }
    }

    #[test]
    fn the_least_face_bounds_the_feature_and_none_wins() {
        let faces = [face(5, Some(20.0)), face(7, Some(8.0)), face(9, Some(8.0))];
        let refs: Vec<&FaceReach> = faces.iter().collect();
        assert_eq!(smallest(&refs), (Some(8.0), Some(7)));
        let faces = [face(5, Some(20.0)), face(6, None)];
        let refs: Vec<&FaceReach> = faces.iter().collect();
        assert_eq!(smallest(&refs), (None, Some(6)));
    }
}
