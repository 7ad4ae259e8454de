//! Depressions in a wall: holes (closed openings through it, from the inner
//! loops of its side faces), cut-outs and notches (openings from its rim).

use crate::junctions::is_concave_blend;
use crate::walls::Wall;
use std::collections::{BTreeSet, HashSet, VecDeque};
use thinwall_brep::{FaceId, Part};
use thinwall_geom::Surface;
use thinwall_geom::{Point3, Vector3};
use thinwall_graph::{AdjacencyGraph, Convexity};

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

/// Sample points on a face's boundary.
pub fn face_points(part: &Part, f: FaceId) -> Vec<Point3> {
    let mut pts = Vec::new();
    for &l in &part.face(f).loops {
        let lp = part.loop_(l);
        if let Some(v) = lp.vertex {
            pts.push(part.vertex(v).point);
        }
        for ce in &lp.coedges {
            let e = part.edge(ce.edge);
            match &e.nurbs {
                Some(c) => {
                    for (a, b) in c.spans() {
                        for k in 0..=4 {
                            pts.push(c.point(a + (b - a) * k as f64 / 4.0));
                        }
                    }
                }
                None => pts.push(part.vertex(e.start).point),
            }
        }
    }
    pts
}

/// Whether all of a face lies within the wall's slab (between its side planes).
pub fn within_slab(part: &Part, wall: &Wall, f: FaceId, tol: f64) -> bool {
    face_points(part, f).iter().all(|p| {
        let d = (p - wall.frame.origin).dot(&wall.frame.z);
        d <= tol && d >= -wall.thickness - tol
    })
}

/// Holes of wall `w`: from each inner loop of a side face, the faces beyond
/// it, flooded while they stay within the slab.
pub fn holes(
    part: &Part,
    graph: &AdjacencyGraph,
    walls: &[Wall],
    w: usize,
    taken: &mut HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
    tol: f64,
) -> Vec<Depression> {
    let wall = &walls[w];
    let mut out = Vec::new();
    for s in 0..2 {
        for &f in &wall.sides[s] {
            let face = part.face(f);
            let outer = crate::planar::outer_loops(part, f);
            for (i, &l) in face.loops.iter().enumerate() {
                let lp = part.loop_(l);
                if outer[i] {
                    continue;
                }
                // Faces across this loop's edges.
                let mut seeds = Vec::new();
                for ce in &lp.coedges {
                    for e in &graph.edges[ce.edge.index()].faces {
                        if *e != f && !any_side.contains(e) && !taken.contains(e) {
                            seeds.push(*e);
                        }
                    }
                }
                let set = flood(part, graph, wall, seeds, taken, any_side, tol);
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

fn flood(
    part: &Part,
    graph: &AdjacencyGraph,
    wall: &Wall,
    seeds: Vec<FaceId>,
    taken: &HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
    tol: f64,
) -> BTreeSet<FaceId> {
    let mut set = BTreeSet::new();
    let mut queue: VecDeque<FaceId> = seeds.into_iter().collect();
    while let Some(f) = queue.pop_front() {
        if set.contains(&f)
            || taken.contains(&f)
            || any_side.contains(&f)
            || !within_slab(part, wall, f, tol)
        {
            continue;
        }
        set.insert(f);
        for (g, _) in graph.neighbours(f) {
            if !set.contains(&g) {
                queue.push_back(g);
            }
        }
    }
    set
}

/// The rim of wall `w`: faces that touch both of its sides and lie within
/// its slab (top, ends, and the faces of openings from the edge).
pub fn rim_faces(
    part: &Part,
    graph: &AdjacencyGraph,
    walls: &[Wall],
    w: usize,
    taken: &HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
    tol: f64,
) -> Vec<FaceId> {
    let wall = &walls[w];
    let mut candidates: BTreeSet<FaceId> = BTreeSet::new();
    for &f in &wall.sides[0] {
        for (g, _) in graph.neighbours(f) {
            candidates.insert(g);
        }
    }
    candidates
        .into_iter()
        .filter(|&g| {
            !any_side.contains(&g)
                && !taken.contains(&g)
                && graph.neighbours(g).any(|(h, _)| wall.sides[1].contains(&h))
                && within_slab(part, wall, g, tol)
        })
        .collect()
}

/// Cut-outs and notches among a wall's rim faces: rim faces joined by
/// concave edges (the inside corners of a slot or step), or a single
/// concave cylindrical scallop.
pub fn edge_openings(
    part: &Part,
    graph: &AdjacencyGraph,
    w: usize,
    rim: &[FaceId],
) -> Vec<Depression> {
    let in_rim: HashSet<FaceId> = rim.iter().copied().collect();
    let mut seen: HashSet<FaceId> = HashSet::new();
    let mut out = Vec::new();
    for &start in rim {
        if seen.contains(&start) {
            continue;
        }
        let mut comp = vec![start];
        seen.insert(start);
        let mut i = 0;
        let mut concave_arcs = 0;
        while i < comp.len() {
            let f = comp[i];
            for (g, adj) in graph.neighbours(f) {
                if in_rim.contains(&g) && adj.convexity == Convexity::Concave {
                    if f < g {
                        concave_arcs += 1;
                    }
                    if seen.insert(g) {
                        comp.push(g);
                    }
                }
            }
            i += 1;
        }
        comp.sort();
        let kind = if comp.len() >= 2 && concave_arcs >= 2 {
            Some(DepressionKind::Cutout)
        } else if comp.len() == 2 && concave_arcs == 1 {
            Some(DepressionKind::Notch)
        } else if comp.len() == 1
            && is_concave_blend(part, start)
            && matches!(part.face(start).surface, Surface::Cylinder { .. })
            && !graph
                .neighbours(start)
                .any(|(_, a)| a.convexity == Convexity::Smooth)
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

/// Extent of a set of faces along a direction, mm.
pub fn extent(part: &Part, faces: &[FaceId], dir: &Vector3) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for &f in faces {
        for p in face_points(part, f) {
            let x = p.coords.dot(dir);
            lo = lo.min(x);
            hi = hi.max(x);
        }
    }
    (lo, hi)
}
