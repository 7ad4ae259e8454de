//! Details on walls: fillets and rounds (blend chains) and chamfers.

use std::collections::HashSet;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_graph::Convexity;

/// A blend chain: connected blend faces.
#[derive(Clone, Debug)]
pub struct Blend {
    pub faces: Vec<FaceId>,
    pub radius: Option<f64>,
    /// A round (convex) rather than a fillet (concave).
    pub convex: bool,
}

/// Blend chains among faces not `taken`.
pub fn blends(a: &PartAnalysis, taken: &HashSet<FaceId>) -> Vec<Blend> {
    let cands: Vec<FaceId> = a
        .part()
        .face_ids()
        .filter(|f| !taken.contains(f) && a.is_blend_candidate(*f))
        .collect();
    a.components(&cands, |_, _, adj| adj.convexity == Convexity::Smooth)
        .into_iter()
        .map(|faces| {
            let radius = faces
                .iter()
                .filter_map(|&f| a.blend_radius(f))
                .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |x| x.min(r))));
            let convex = a.part().face(faces[0]).same_sense;
            Blend {
                faces,
                radius,
                convex,
            }
        })
        .collect()
}

/// Chamfers: chamfer candidates ([`PartAnalysis::is_chamfer_candidate`])
/// that are narrow (width ≤ `max_width`, and less than a quarter of the
/// face's length).
pub fn chamfers(a: &PartAnalysis, taken: &HashSet<FaceId>, max_width: f64) -> Vec<(FaceId, f64)> {
    a.part()
        .face_ids()
        .filter(|f| !taken.contains(f) && a.is_chamfer_candidate(*f))
        .filter_map(|f| {
            let (width, length) = a.strip_width(f);
            (width <= max_width && width < 0.25 * length).then_some((f, width))
        })
        .collect()
}
