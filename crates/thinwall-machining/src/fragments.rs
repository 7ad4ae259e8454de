//! Pieces of one feature that a later feature cut apart: a pocket split
//! in two by a hole through its floor, a step floor left as an island
//! inside an O-ring, a passage's walls on either side of a slot through
//! it. Such pieces lie on a common plane facing the same way (a floor, or
//! a wall), do not meet each other, and both meet a third group (the
//! feature that split them); they are typed as one feature.

use crate::{face_plane, same_plane, Plane};
use petgraph::unionfind::UnionFind;
use std::collections::{BTreeSet, HashMap};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_graph::Convexity;

/// A planar face of a group: its plane (normal, offset) and the other
/// groups it meets.
struct PlaneFace {
    plane: Plane,
    meets: BTreeSet<usize>,
}

/// Whether two groups are pieces of one feature: a planar face each on
/// one plane, facing the same way, both meeting one third group, which
/// either is cut down from that plane (nothing of it above: a hole through
/// a pocket's floor, an O-ring round an island of a step's floor) or
/// leaves the pieces sharing a second plane too (a passage's walls on
/// either side of a slot through it).
fn split_by_one(
    a: &PartAnalysis,
    groups: &[Vec<FaceId>],
    x: &[PlaneFace],
    y: &[PlaneFace],
) -> bool {
    let tol = crate::plane_tol(a);
    let coplanar = |p: &PlaneFace, q: &PlaneFace| same_plane(a, &p.plane, &q.plane);
    let below = |k: usize, p: &PlaneFace| {
        let (n, offset) = p.plane;
        a.extent(&groups[k], &n).1 < offset + tol
    };
    let mut shared: Vec<&PlaneFace> = Vec::new();
    let mut split = false;
    for p in x {
        for q in y.iter().filter(|q| coplanar(p, q)) {
            if !shared.iter().any(|s| coplanar(s, p)) {
                shared.push(p);
            }
            split |= p.meets.intersection(&q.meets).any(|&k| below(k, p));
        }
    }
    let common = x.iter().any(|p| {
        y.iter()
            .any(|q| coplanar(p, q) && p.meets.intersection(&q.meets).next().is_some())
    });
    split || (common && shared.len() >= 2)
}

/// Lone faces that are a piece of one other group's face: one plane that
/// the model split along an edge (the edge between them is smooth). A
/// face whose plane runs on into several groups (a floor two slots share)
/// joins none. Pairs (lone group, group of the other pieces).
fn split_faces(
    a: &PartAnalysis,
    groups: &[Vec<FaceId>],
    of: &HashMap<FaceId, usize>,
) -> Vec<(usize, usize)> {
    let coplanar = |f: FaceId, g: FaceId| match (face_plane(a, f), face_plane(a, g)) {
        (Some(p), Some(q)) => same_plane(a, &p, &q),
        _ => false,
    };
    let mut pairs = Vec::new();
    for (i, g) in groups.iter().enumerate().filter(|(_, g)| g.len() == 1) {
        let f = g[0];
        let others: BTreeSet<usize> = a
            .graph()
            .neighbours(f)
            .filter(|(h, adj)| adj.convexity == Convexity::Smooth && coplanar(f, *h))
            .filter_map(|(h, _)| of.get(&h).copied())
            .collect();
        if let [j] = others.into_iter().collect::<Vec<_>>()[..] {
            pairs.push((i, j));
        }
    }
    pairs
}

/// The groups with the pieces of one feature joined.
pub(crate) fn join_pieces(a: &PartAnalysis, groups: Vec<Vec<FaceId>>) -> Vec<Vec<FaceId>> {
    let of: HashMap<FaceId, usize> = groups
        .iter()
        .enumerate()
        .flat_map(|(i, g)| g.iter().map(move |&f| (f, i)))
        .collect();
    let meets = |f: FaceId, i: usize| -> BTreeSet<usize> {
        a.graph()
            .neighbours(f)
            .filter_map(|(h, _)| of.get(&h).copied())
            .filter(|&j| j != i)
            .collect()
    };
    let planes: Vec<Vec<PlaneFace>> = groups
        .iter()
        .enumerate()
        .map(|(i, g)| {
            g.iter()
                .filter_map(|&f| {
                    Some(PlaneFace {
                        plane: face_plane(a, f)?,
                        meets: meets(f, i),
                    })
                })
                .collect()
        })
        .collect();
    let touching: Vec<BTreeSet<usize>> = groups
        .iter()
        .enumerate()
        .map(|(i, g)| g.iter().flat_map(|&f| meets(f, i)).collect())
        .collect();
    let mut sets = UnionFind::new(groups.len());
    for i in 0..groups.len() {
        for j in i + 1..groups.len() {
            if !touching[i].contains(&j) && split_by_one(a, &groups, &planes[i], &planes[j]) {
                sets.union(i, j);
            }
        }
    }
    for (i, j) in split_faces(a, &groups, &of) {
        sets.union(i, j);
    }
    let mut joined: Vec<Vec<FaceId>> = vec![Vec::new(); groups.len()];
    for (i, g) in groups.into_iter().enumerate() {
        joined[sets.find(i)].extend(g);
    }
    joined.retain(|g| !g.is_empty());
    for g in &mut joined {
        g.sort();
    }
    joined
}
