//! The largest tool for each machining feature: the tool (the run's
//! proportions, along the set-up's up) that reaches every face of a pocket,
//! slot, step or hole whole, from its faces' largest tools, set beside the
//! recognizer's bound (`largest_tool_diameter`: the largest circle in the
//! floor, or a hole's bore), which knows the floor's shape but not the
//! material around it.

use super::FaceReach;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use thinwall_analysis::{MachiningId, MachiningKind};
use thinwall_machining::MachiningFeature;

/// One machining feature's largest tools.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FeatureTool {
    pub feature: MachiningId,
    pub kind: MachiningKind,
    /// The largest tool reaching every face of it whole, mm; none when
    /// some face no tool of at least the smallest size reaches whole (a
    /// sharp inside corner, a face turned away from up).
    pub largest_tool_mm: Option<f64>,
    /// The face whose own largest tool bounds it (STEP id).
    pub bounded_by: Option<u64>,
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
pub fn feature_tools(machining: &[MachiningFeature], faces: &[FaceReach]) -> Vec<FeatureTool> {
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
        let (largest_tool_mm, bounded_by) = smallest(&reach);
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
