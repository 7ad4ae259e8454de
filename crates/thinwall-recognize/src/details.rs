//! Details on walls: fillets and rounds (blend chains) and chamfers.

use std::collections::HashSet;
use thinwall_brep::{FaceId, Part};
use thinwall_geom::Surface;
use thinwall_graph::{AdjacencyGraph, Convexity};

/// A blend chain: connected blend faces.
#[derive(Clone, Debug)]
pub struct Blend {
    pub faces: Vec<FaceId>,
    pub radius: Option<f64>,
    /// A round (convex) rather than a fillet (concave).
    pub convex: bool,
}

fn blend_radius(part: &Part, f: FaceId) -> Option<f64> {
    match part.face(f).surface {
        Surface::Cylinder { radius, .. } => Some(radius),
        Surface::Torus { minor_radius, .. } => Some(minor_radius),
        Surface::Sphere { radius, .. } => Some(radius),
        _ => None,
    }
}

pub fn is_blend_candidate(part: &Part, graph: &AdjacencyGraph, f: FaceId) -> bool {
    let face = part.face(f);
    let curved = matches!(
        face.surface,
        Surface::Cylinder { .. }
            | Surface::Torus { .. }
            | Surface::Sphere { .. }
            | Surface::Freeform { .. }
    );
    if !curved {
        return false;
    }
    let smooth: HashSet<FaceId> = graph
        .neighbours(f)
        .filter(|(_, a)| a.convexity == Convexity::Smooth)
        .map(|(g, _)| g)
        .collect();
    smooth.len() >= 2
}

/// Blend chains among faces not `taken`.
pub fn blends(part: &Part, graph: &AdjacencyGraph, taken: &HashSet<FaceId>) -> Vec<Blend> {
    let cands: Vec<FaceId> = part
        .face_ids()
        .filter(|f| !taken.contains(f) && is_blend_candidate(part, graph, *f))
        .collect();
    let set: HashSet<FaceId> = cands.iter().copied().collect();
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for &start in &cands {
        if !seen.insert(start) {
            continue;
        }
        let mut comp = vec![start];
        let mut i = 0;
        while i < comp.len() {
            let f = comp[i];
            for (g, a) in graph.neighbours(f) {
                if set.contains(&g) && a.convexity == Convexity::Smooth && seen.insert(g) {
                    comp.push(g);
                }
            }
            i += 1;
        }
        comp.sort();
        let radius = comp
            .iter()
            .filter_map(|&f| blend_radius(part, f))
            .fold(None, |m: Option<f64>, r| Some(m.map_or(r, |x| x.min(r))));
        let convex = part.face(comp[0]).same_sense;
        out.push(Blend {
            faces: comp,
            radius,
            convex,
        });
    }
    out
}

/// Chamfers: planar faces meeting two neighbours at convex edges with an
/// obtuse interior angle (100°–170°) and narrow (width ≤ `max_width`,
/// and less than a quarter of the face's length).
pub fn chamfers(
    part: &Part,
    graph: &AdjacencyGraph,
    taken: &HashSet<FaceId>,
    max_width: f64,
) -> Vec<(FaceId, f64)> {
    let mut out = Vec::new();
    for f in part.face_ids() {
        if taken.contains(&f) || !matches!(part.face(f).surface, Surface::Plane { .. }) {
            continue;
        }
        let bevels = graph
            .neighbours(f)
            .filter(|(_, a)| {
                a.convexity == Convexity::Convex
                    && a.edges.iter().all(|&e| {
                        let ea = &graph.edges[e];
                        ea.angle_min_deg > 100.0 && ea.angle_max_deg < 170.0
                    })
            })
            .count();
        if bevels < 2 {
            continue;
        }
        let props = thinwall_brep::compute_face_props(part, f);
        let longest = crate::depressions::face_points(part, f)
            .windows(2)
            .map(|w| (w[1] - w[0]).norm())
            .sum::<f64>()
            .max(1e-9)
            / 2.0;
        let width = props.area / longest;
        if width <= max_width && width < 0.25 * longest {
            out.push((f, width));
        }
    }
    out
}
