//! Prismatic bosses (islands): planar walls standing on one floor plane
//! (meeting it at a concave edge, or through a concave blend), meeting each
//! other at outside corners (convex edges, or rounded corners: convex
//! cylinders along the floor's normal), and closing a ring round that
//! normal. The material inside is left standing: a rib on a plate, an
//! island in a pocket. The feature is the wall to machine round it, from
//! its top down to its foot; the floor stays with whatever it belongs to.

use crate::shape::{ring_profile, surrounds, wall_neighbours};
use crate::{face_plane, same_direction, same_plane, MachiningFeature, Plane};
use geo::{Centroid, ConvexHull, MultiPoint};
use thinwall_analysis::polygon::min_rect_sides;
use thinwall_analysis::{MachiningKind, PartAnalysis};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::Vector3;
use thinwall_graph::Convexity;

/// A ring of walls standing on one floor plane.
pub(crate) struct Island {
    /// The planar walls, in face order.
    pub walls: Vec<FaceId>,
    /// The floor's outward normal: from the foot up to the top.
    pub up: Vector3,
    /// The floor's offset along `up`, mm.
    pub foot: f64,
    /// Other walls rising from the floor close round it: an island in a
    /// pocket (the pocket's), not a boss.
    pub in_pocket: bool,
}

/// A floor plane (its normal is up) and the walls standing on it.
struct Foot {
    plane: Plane,
    walls: Vec<FaceId>,
}

/// The islands whose walls are all among `faces`.
pub(crate) fn islands(a: &PartAnalysis, faces: &[FaceId]) -> Vec<Island> {
    let walls: Vec<FaceId> = faces
        .iter()
        .copied()
        .filter(|&f| a.planar(f).is_some())
        .collect();
    let found: Vec<Island> = feet(a, &walls)
        .iter()
        .flat_map(|foot| rings_on(a, foot))
        .collect();
    disjoint(a, found)
}

/// The rings closing round the walls standing on one floor plane.
fn rings_on(a: &PartAnalysis, foot: &Foot) -> Vec<Island> {
    let corners: std::collections::BTreeSet<FaceId> = foot
        .walls
        .iter()
        .flat_map(|&w| a.graph().neighbours(w))
        .map(|(g, _)| g)
        .filter(|&g| round_corner(a, g, &foot.plane.0))
        .collect();
    let members: Vec<FaceId> = foot.walls.iter().chain(&corners).copied().collect();
    let outside = |_: FaceId, _: FaceId, adj: &thinwall_graph::Adjacency| {
        matches!(adj.convexity, Convexity::Convex | Convexity::Smooth)
    };
    let mut out = Vec::new();
    for ring in a.components(&members, outside) {
        let walls: Vec<FaceId> = ring
            .iter()
            .copied()
            .filter(|f| foot.walls.contains(f))
            .collect();
        if closes(a, &ring, &walls, &foot.plane.0) {
            out.push(Island {
                in_pocket: false,
                walls,
                up: foot.plane.0,
                foot: foot.plane.1,
            });
        }
    }
    // Whether each stands in a pocket, by the walls of the floor that are
    // no island's (two ribs on a plate do not make each other a pocket).
    let on_rings: Vec<FaceId> = out.iter().flat_map(|i| i.walls.clone()).collect();
    for island in &mut out {
        island.in_pocket = in_a_pocket(a, &island.walls, &on_rings, foot);
    }
    out
}

/// Islands sharing no wall. A wall standing on two floors (a stepped foot)
/// may close two rings: the one with more walls, then more wall area,
/// keeps it (never the faces' order).
fn disjoint(a: &PartAnalysis, mut found: Vec<Island>) -> Vec<Island> {
    let area = |i: &Island| i.walls.iter().map(|&w| a.props(w).area).sum::<f64>();
    found.sort_by(|x, y| {
        y.walls
            .len()
            .cmp(&x.walls.len())
            .then(area(y).total_cmp(&area(x)))
    });
    let mut out: Vec<Island> = Vec::new();
    for island in found {
        if !out
            .iter()
            .any(|i| i.walls.iter().any(|w| island.walls.contains(w)))
        {
            out.push(island);
        }
    }
    out
}

/// The floor planes among the walls' neighbours and the walls standing on
/// each (square to it, meeting it concavely or through a concave blend).
fn feet(a: &PartAnalysis, walls: &[FaceId]) -> Vec<Foot> {
    let mut out: Vec<Foot> = Vec::new();
    for &w in walls {
        let Some(n) = a.props(w).normal else {
            continue;
        };
        for g in inside_corners(a, w) {
            let Some(plane) = face_plane(a, g).filter(|p| p.0.dot(&n).abs() < NEAR_PARALLEL_EPS)
            else {
                continue;
            };
            match out.iter_mut().find(|f| same_plane(a, &f.plane, &plane)) {
                Some(f) if !f.walls.contains(&w) => f.walls.push(w),
                Some(_) => {}
                None => out.push(Foot {
                    plane,
                    walls: vec![w],
                }),
            }
        }
    }
    out
}

/// The planar faces `w` meets at a concave edge, directly or across a
/// concave blend (a wall's floors, a floor's walls).
fn inside_corners(a: &PartAnalysis, w: FaceId) -> Vec<FaceId> {
    let mut out = Vec::new();
    for (g, adj) in a.graph().neighbours(w) {
        if adj.convexity == Convexity::Concave && a.planar(g).is_some() {
            out.push(g);
        } else if adj.convexity == Convexity::Smooth && a.is_concave_blend(g) {
            out.extend(
                a.graph()
                    .neighbours(g)
                    .map(|(h, _)| h)
                    .filter(|&h| h != w && a.planar(h).is_some()),
            );
        }
    }
    out
}

/// Whether the floor the ring stands on is a pocket's: walls rising from
/// it that are no island's close round it (seen along up, their normals
/// leave no half-turn free). An island in a pocket stays with its pocket
/// (a pocket with an island); one on an open face is a boss.
fn in_a_pocket(a: &PartAnalysis, ring: &[FaceId], islands: &[FaceId], foot: &Foot) -> bool {
    let up = foot.plane.0;
    let on_foot = |g: FaceId| face_plane(a, g).is_some_and(|p| same_plane(a, &p, &foot.plane));
    let floors: Vec<FaceId> = ring
        .iter()
        .flat_map(|&w| inside_corners(a, w))
        .filter(|&g| on_foot(g))
        .collect();
    let others: Vec<Vector3> = floors
        .iter()
        .flat_map(|&g| inside_corners(a, g))
        .filter(|w| !islands.contains(w))
        .filter_map(|w| a.props(w).normal)
        .filter(|n| n.dot(&up).abs() < NEAR_PARALLEL_EPS)
        .collect();
    surrounds(&others, &up)
}

/// A convex cylinder along `up`: an island's rounded corner.
fn round_corner(a: &PartAnalysis, f: FaceId, up: &Vector3) -> bool {
    a.cylinder(f)
        .is_some_and(|c| c.convex && c.axis.dot(up).abs() > 1.0 - NEAR_PARALLEL_EPS)
}

/// Whether a component closes a ring: three walls or more, every member
/// meeting two others of it, the walls' outward normals leaving no
/// half-turn free round `up`.
fn closes(a: &PartAnalysis, ring: &[FaceId], walls: &[FaceId], up: &Vector3) -> bool {
    let normals: Vec<Vector3> = walls.iter().filter_map(|&w| a.props(w).normal).collect();
    walls.len() >= 3
        && ring.iter().all(|&f| wall_neighbours(a, f, ring) >= 2)
        && surrounds(&normals, up)
}

/// The boss feature of an island: down from its top, its height above
/// its floor and the minimum rectangle round its walls seen from above.
/// Its top is the highest of its walls and the faces they meet at convex
/// edges (a cap, a bevel round it).
pub(crate) fn island_feature(a: &PartAnalysis, island: &Island) -> MachiningFeature {
    let up = island.up;
    let top: Vec<FaceId> = island
        .walls
        .iter()
        .flat_map(|&w| a.graph().neighbours(w))
        .filter(|(_, adj)| adj.convexity == Convexity::Convex)
        .map(|(g, _)| g)
        .chain(island.walls.iter().copied())
        .collect();
    let (_, hi) = a.extent(&top, &up);
    let (u, v, pts) = a.points_across(&island.walls, &up);
    let hull = MultiPoint::from(pts).convex_hull();
    let (length, width) = min_rect_sides(&hull).unwrap_or((0.0, 0.0));
    let centre = hull.centroid().map(|c| {
        let p = u * c.x() + v * c.y() + up * hi;
        [p.x, p.y, p.z]
    });
    let mut normals: Vec<Vector3> = Vec::new();
    for n in island.walls.iter().filter_map(|&w| a.props(w).normal) {
        if !normals.iter().any(|m| same_direction(m, &n)) {
            normals.push(n);
        }
    }
    MachiningFeature {
        depth: hi - island.foot,
        length: length.max(width),
        width: width.min(length),
        centre,
        ..MachiningFeature::on_faces(
            a,
            MachiningKind::Boss,
            ring_profile(&normals),
            &island.walls,
            &-up,
        )
    }
}
