//! A depression's own blends: the corner radii round its walls and the
//! fillets round its floor (where the two meet, tori) are cut by the tool
//! that cuts the depression, so they are its faces, and their radii are
//! what decides its tools (CAMWorks and NX give a pocket its corner radius,
//! floor fillet and draft). A blend chain is a depression's own when every
//! face it is tangent to, apart from its own, is in that depression; a
//! blend between two features stays a fillet of its own.

use crate::MachiningFeature;
use std::collections::BTreeSet;
use thinwall_analysis::{MachiningKind, PartAnalysis};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::{MAX_SIDE_DRAFT_DEG, NEAR_PARALLEL_EPS};
use thinwall_geom::{Surface, Vector3};
use thinwall_graph::Convexity;

/// The kinds a blend chain can belong to: milled depressions (a hole's
/// blended entry is a stage of the hole, not taken here). They carry a
/// corner radius and floor fillet (and the operations finish them so).
pub fn takes_blends(kind: MachiningKind) -> bool {
    matches!(
        kind,
        MachiningKind::Pocket | MachiningKind::Slot | MachiningKind::Step | MachiningKind::Passage
    )
}

/// Which of `chains` are `group`'s own: chains with a concave blend, every
/// face they are tangent to outside themselves in `group`, and at least
/// one such face.
pub(crate) fn own_chains(a: &PartAnalysis, chains: &[Vec<FaceId>], group: &[FaceId]) -> Vec<usize> {
    let members: BTreeSet<FaceId> = group.iter().copied().collect();
    (0..chains.len())
        .filter(|&i| {
            let chain: BTreeSet<FaceId> = chains[i].iter().copied().collect();
            if !chains[i].iter().any(|&f| a.is_concave_blend(f)) {
                return false;
            }
            let mut tangent = chains[i]
                .iter()
                .flat_map(|&f| a.graph().neighbours(f))
                .filter(|(g, adj)| adj.convexity == Convexity::Smooth && !chain.contains(g))
                .peekable();
            tangent.peek().is_some() && tangent.all(|(g, _)| members.contains(&g))
        })
        .collect()
}

/// Put `blends` (a depression's own chains) into `m`, built from `group`:
/// its faces, its blend radii, its corner radius and floor fillet, and the
/// largest tool its corners allow.
pub(crate) fn attach(
    a: &PartAnalysis,
    m: &mut MachiningFeature,
    group: &[FaceId],
    blends: &[FaceId],
) {
    if !takes_blends(m.kind) {
        return;
    }
    let dir = Vector3::new(m.direction[0], m.direction[1], m.direction[2]);
    let measured = Radii::of(a, blends, &dir);
    m.wall_draft_deg = wall_draft_deg(a, group, &dir);
    if blends.is_empty() {
        return;
    }
    let all: Vec<FaceId> = group.iter().chain(blends).copied().collect();
    m.faces = a.step_ids(&all);
    m.blend_faces = a.step_ids(blends);
    // Not floors: they are among its side faces.
    m.side_faces.extend(&m.blend_faces);
    m.side_faces.sort();
    m.radii = crate::radii(a, &all);
    m.corner_radius = measured.corners.first().copied();
    m.corner_radii = measured.corners;
    m.floor_fillet = measured.floor.first().copied();
    // The floor's widest circle takes a tool that much wider whose corner
    // radius sits in the fillet all round (a bull-nose of the fillet's
    // radius).
    let width = m
        .largest_tool_diameter
        .filter(|_| m.tool_bound == Some(crate::ToolBound::Width))
        .map(|d| d + 2.0 * m.floor_fillet.unwrap_or(0.0));
    m.largest_tool_diameter = width;
    if let Some(r) = m.corner_radius {
        // A tool wider than the corner's diameter leaves the corner uncut.
        if width.is_none_or(|d| 2.0 * r <= d) {
            m.largest_tool_diameter = Some(2.0 * r);
            m.tool_bound = Some(crate::ToolBound::CornerRadius);
        }
    }
}

/// A depression's blend radii, each list distinct and smallest first, mm.
struct Radii {
    /// Concave cylinders along the tool axis: the corners round its walls.
    corners: Vec<f64>,
    /// Concave cylinders across the tool axis, tori and spheres: the
    /// fillets round its floor.
    floor: Vec<f64>,
}

impl Radii {
    fn of(a: &PartAnalysis, blends: &[FaceId], dir: &Vector3) -> Self {
        let (mut corners, mut floor) = (Vec::new(), Vec::new());
        for &f in blends {
            match a.part().face(f).surface {
                Surface::Cylinder { frame, radius } if a.is_concave_blend(f) => {
                    let along = frame.z.dot(dir).abs();
                    if along > 1.0 - NEAR_PARALLEL_EPS {
                        corners.push(radius);
                    } else if along < NEAR_PARALLEL_EPS.sqrt() {
                        floor.push(radius);
                    }
                }
                Surface::Torus { minor_radius, .. } if a.is_concave_blend(f) => {
                    floor.push(minor_radius)
                }
                Surface::Sphere { radius, .. } if !a.part().face(f).same_sense => {
                    floor.push(radius)
                }
                _ => {}
            }
        }
        Self {
            corners: distinct(corners),
            floor: distinct(floor),
        }
    }
}

fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|x, y| (*x - *y).abs() < crate::SAME_RADIUS_MM);
    v
}

/// The largest lean of a planar wall from the tool axis, degrees (0 for
/// upright walls); none without planar walls, and none where a wall leans
/// more than a draft ([`MAX_SIDE_DRAFT_DEG`]: a V-slot's flank is slanted,
/// not drafted). Floors and faces facing back along the axis are not
/// walls.
fn wall_draft_deg(a: &PartAnalysis, group: &[FaceId], dir: &Vector3) -> Option<f64> {
    group
        .iter()
        .filter_map(|&f| a.planar(f).and(a.props(f).normal))
        .map(|n| n.dot(dir).abs())
        .filter(|c| *c < std::f64::consts::FRAC_1_SQRT_2)
        .map(|c| c.asin().to_degrees())
        .reduce(f64::max)
        .filter(|d| *d <= MAX_SIDE_DRAFT_DEG)
}
