//! Round bosses: convex cylinders standing on a face (not blends, not an
//! O-ring's core), going round (coaxial faces sweeping 300° or more). A
//! boss is material left standing: the feature is the wall to machine
//! round it, from its cap down to its foot.

use crate::MachiningFeature;
use thinwall_analysis::{Cylinder, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_graph::Convexity;

/// Coaxial convex faces sweeping this much together go round, degrees.
const ROUND_SWEEP_DEG: f64 = 300.0;

/// The boss groups among `faces` (convex cylinders chained along smooth
/// edges, going round, not an O-ring's core).
pub(crate) fn boss_groups(a: &PartAnalysis, faces: &[FaceId]) -> Vec<Vec<FaceId>> {
    let convex: Vec<FaceId> = faces
        .iter()
        .copied()
        .filter(|&f| a.cylinder(f).is_some_and(|c| c.convex))
        .collect();
    a.components(&convex, |_, _, adj| adj.convexity == Convexity::Smooth)
        .into_iter()
        .filter(|g| {
            let sweep: f64 = g.iter().filter_map(|&f| a.cylinder_sweep_deg(f)).sum();
            sweep >= ROUND_SWEEP_DEG && !is_groove_core(a, g)
        })
        .collect()
}

/// Whether the face the cylinders stand on is also bounded by a coaxial
/// concave cylinder: the core left in an O-ring groove.
fn is_groove_core(a: &PartAnalysis, group: &[FaceId]) -> bool {
    let Some(c) = a.cylinder(group[0]) else {
        return false;
    };
    let tol = crate::axis_tol(a);
    group
        .iter()
        .flat_map(|&f| a.graph().neighbours(f))
        .filter(|(_, adj)| adj.convexity == Convexity::Concave)
        .flat_map(|(foot, _)| a.graph().neighbours(foot))
        .any(|(g, _)| a.concave_cylinder(g).is_some_and(|h| h.coaxial(&c, tol)))
}

/// The boss feature of a group: down its axis from the cap to the foot
/// (the faces it meets along concave edges), its height and diameter.
pub(crate) fn boss_feature(a: &PartAnalysis, group: &[FaceId]) -> MachiningFeature {
    let c: Cylinder = a.cylinder(group[0]).expect("a boss group holds cylinders");
    let feet: Vec<FaceId> = group
        .iter()
        .flat_map(|&f| a.graph().neighbours(f))
        .filter(|(g, adj)| adj.convexity == Convexity::Concave && !group.contains(g))
        .map(|(g, _)| g)
        .collect();
    let (lo, hi) = a.extent(group, &c.axis);
    // The foot is at the end the concave neighbours are; the tool comes
    // from the other end.
    let (flo, fhi) = a.extent(&feet, &c.axis);
    let foot_low = feet.is_empty() || (flo + fhi) / 2.0 < (lo + hi) / 2.0;
    let dir = if foot_low { -c.axis } else { c.axis };
    let cap = if foot_low { hi } else { lo };
    let centre = c.origin + c.axis * (cap - c.origin.coords.dot(&c.axis));
    let radius = group
        .iter()
        .filter_map(|&f| a.cylinder(f))
        .map(|c| c.radius)
        .fold(0.0, f64::max);
    MachiningFeature {
        depth: hi - lo,
        length: 2.0 * radius,
        width: 2.0 * radius,
        centre: Some([centre.x, centre.y, centre.z]),
        radii: vec![radius],
        ..MachiningFeature::on_faces(a, MachiningKind::Boss, Profile::Circular, group, &dir)
    }
}
