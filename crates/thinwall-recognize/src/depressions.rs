//! Depressions in a wall: holes (closed openings through it, from the inner
//! loops of its side faces), cut-outs and notches (openings from its rim).

use crate::walls::Wall;
use std::collections::{BTreeSet, HashSet};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::Surface;
use thinwall_graph::Convexity;

/// A depression found in a wall.
#[derive(Clone, Debug)]
pub struct Depression {
    pub wall: usize,
    pub faces: Vec<FaceId>,
    pub kind: DepressionKind,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepressionKind {
    Hole { through: bool },
    Cutout,
    Notch,
}

/// Whether all of a face lies within the wall's slab (between its side planes).
pub fn within_slab(a: &PartAnalysis, wall: &Wall, f: FaceId) -> bool {
    let tol = a.tol().slab;
    if let Some(c) = &wall.curved {
        return a.boundary_points(f).iter().all(|p| c.within(p, tol));
    }
    let (q1, n1) = wall.side_plane(1);
    a.boundary_points(f).iter().all(|p| {
        let d = (p - wall.frame.origin).dot(&wall.frame.z);
        // A drafted wall's side 1 leans: test against its own plane.
        let inside1 = if wall.drafted() {
            (p - q1).dot(&n1) <= tol
        } else {
            d >= -wall.thickness - tol
        };
        d <= tol && inside1
    })
}

/// Holes of wall `w`: from each inner loop of a side face, the faces beyond
/// it, flooded while they stay within the slab.
pub fn holes(
    a: &PartAnalysis,
    walls: &[Wall],
    w: usize,
    taken: &mut HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
) -> Vec<Depression> {
    let (part, graph) = (a.part(), a.graph());
    let wall = &walls[w];
    let mut out = Vec::new();
    for s in 0..2 {
        for &f in &wall.sides[s] {
            let face = part.face(f);
            let outer = thinwall_analysis::polygon::outer_loops(part, f);
            for (i, &l) in face.loops.iter().enumerate() {
                if outer[i] {
                    continue;
                }
                // Faces across this loop's edges.
                let seeds: Vec<FaceId> = part
                    .loop_(l)
                    .coedges
                    .iter()
                    .flat_map(|ce| graph.edges[ce.edge.index()].faces.iter().copied())
                    .filter(|e| *e != f && !any_side.contains(e) && !taken.contains(e))
                    .collect();
                let set = a.reachable(
                    seeds,
                    |g| !taken.contains(&g) && !any_side.contains(&g) && within_slab(a, wall, g),
                    |_, _, _| true,
                );
                if set.is_empty() {
                    continue;
                }
                let touches = |side: usize| {
                    set.iter().any(|&h| {
                        graph
                            .neighbours(h)
                            .any(|(g, _)| wall.sides[side].contains(&g))
                    })
                };
                let through = touches(0) && touches(1);
                taken.extend(set.iter().copied());
                out.push(Depression {
                    wall: w,
                    faces: set.into_iter().collect(),
                    kind: DepressionKind::Hole { through },
                });
            }
        }
    }
    out
}

/// The rim of wall `w`: faces that touch both of its sides and lie within
/// its slab (top, ends, and the faces of openings from the edge).
pub fn rim_faces(
    a: &PartAnalysis,
    wall: &Wall,
    taken: &HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
) -> Vec<FaceId> {
    let graph = a.graph();
    let candidates: BTreeSet<FaceId> = wall.sides[0]
        .iter()
        .flat_map(|&f| graph.neighbours(f).map(|(g, _)| g))
        .collect();
    candidates
        .into_iter()
        .filter(|&g| {
            !any_side.contains(&g)
                && !taken.contains(&g)
                && graph.neighbours(g).any(|(h, _)| wall.sides[1].contains(&h))
                && within_slab(a, wall, g)
        })
        .collect()
}

/// Cut-outs and notches among a wall's rim faces: rim faces joined by
/// concave edges (the inside corners of a slot or step), or a single
/// concave cylindrical scallop.
///
/// A concave cylinder as long as the wall (the inner edge of a ring
/// sector) is the wall's curved end, not a scallop: a scallop's radius is
/// at most half the wall's `long_side`, mm.
pub fn edge_openings(
    a: &PartAnalysis,
    w: usize,
    rim: &[FaceId],
    long_side: f64,
) -> Vec<Depression> {
    let graph = a.graph();
    let concave =
        |_: FaceId, _: FaceId, adj: &thinwall_graph::Adjacency| adj.convexity == Convexity::Concave;
    let mut out = Vec::new();
    for comp in a.components(rim, concave) {
        let concave_arcs = comp
            .iter()
            .flat_map(|&f| graph.neighbours(f).map(move |(g, adj)| (f, g, adj)))
            .filter(|(f, g, adj)| f < g && adj.convexity == Convexity::Concave)
            .filter(|(_, g, _)| comp.binary_search(g).is_ok())
            .count();
        let start = comp[0];
        let kind = if comp.len() >= 2 && concave_arcs >= 2 {
            Some(DepressionKind::Cutout)
        } else if comp.len() == 2 && concave_arcs == 1 {
            Some(DepressionKind::Notch)
        } else if comp.len() == 1
            && a.is_concave_blend(start)
            && scallop_radius(a, start) <= 0.5 * long_side
            && matches!(a.part().face(start).surface, Surface::Cylinder { .. })
            && !graph
                .neighbours(start)
                .any(|(_, adj)| adj.convexity == Convexity::Smooth)
        {
            // A scallop from the edge. A concave cylinder tangent to its
            // neighbours is an inside corner radius (a fillet) instead.
            Some(DepressionKind::Cutout)
        } else {
            None
        };
        if let Some(kind) = kind {
            out.push(Depression {
                wall: w,
                faces: comp,
                kind,
            });
        }
    }
    out
}

/// A rim face's radius when it is a cylinder (infinite otherwise).
fn scallop_radius(a: &PartAnalysis, f: FaceId) -> f64 {
    a.cylinder(f).map_or(f64::INFINITY, |c| c.radius)
}
