//! How walls meet: T-junctions (a wall standing on another with base
//! material on both sides of its foot), L-junctions (at the edge of the
//! other), walls running through a base to both of its sides (a frame's
//! outer walls and the ribs through a double-sided web), looking through
//! concave blends (foot fillets).

use crate::walls::Wall;
use std::collections::HashMap;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::{FaceId, Part};
use thinwall_graph::{AdjacencyGraph, Convexity};

/// One wall meeting another.
#[derive(Clone, Debug, PartialEq)]
pub struct Junction {
    /// The wall that stands on `base`.
    pub leaf: usize,
    pub base: usize,
    /// T: the leaf's both sides meet the same side of the base.
    pub tee: bool,
    /// The base's side (0/1) the leaf's foot lies on; 0 for a wall through
    /// its base (sizing picks the side this set-up machines).
    pub base_side: usize,
    /// The leaf runs through the base and stands on both of its sides
    /// (on `1 - base_side` too): a rib through a double-sided web (`tee`),
    /// a frame's outer wall (an L on each side).
    pub through: bool,
    /// Length of the foot, mm (junction edges on one side of the leaf).
    pub length: f64,
}

/// Faces reached from `f` across concave edges, directly or through one
/// concave blend face (a fillet between them), with the length of the
/// edge on `f`'s side.
fn concave_reach(a: &PartAnalysis, f: FaceId) -> Vec<(FaceId, f64)> {
    let (part, graph) = (a.part(), a.graph());
    let mut out = Vec::new();
    for (g, adj) in graph.neighbours(f) {
        let len = edges_length(part, graph, &adj.edges);
        match adj.convexity {
            Convexity::Concave => out.push((g, len)),
            Convexity::Smooth if a.is_concave_blend(g) => {
                for (h, adj2) in graph.neighbours(g) {
                    if h != f && matches!(adj2.convexity, Convexity::Smooth | Convexity::Concave) {
                        out.push((h, len));
                    }
                }
            }
            _ => {}
        }
    }
    out
}

fn edges_length(part: &Part, graph: &AdjacencyGraph, edges: &[usize]) -> f64 {
    edges
        .iter()
        .map(|&e| {
            let edge = part.edge(graph.edges[e].edge);
            let Some(c) = &edge.nurbs else { return 0.0 };
            let mut len = 0.0;
            for (a, b) in c.spans() {
                let mut prev = c.point(a);
                for k in 1..=8 {
                    let p = c.point(a + (b - a) * k as f64 / 8.0);
                    len += (p - prev).norm();
                    prev = p;
                }
            }
            len
        })
        .sum()
}

/// All junctions between walls; an L-junction is listed both ways (see
/// [`resolve_l_junctions`]).
pub fn find_junctions(a: &PartAnalysis, walls: &[Wall]) -> Vec<Junction> {
    // face -> (wall, side)
    let mut side_of: HashMap<FaceId, (usize, usize)> = HashMap::new();
    for (w, wall) in walls.iter().enumerate() {
        for s in 0..2 {
            for &f in &wall.sides[s] {
                side_of.entry(f).or_insert((w, s));
            }
        }
    }
    // links[(a, b)] = per (side of a, side of b): total length
    let mut links: HashMap<(usize, usize), [[f64; 2]; 2]> = HashMap::new();
    for (w, wall) in walls.iter().enumerate() {
        for s in 0..2 {
            for &f in &wall.sides[s] {
                for (g, len) in concave_reach(a, f) {
                    if let Some(&(v, t)) = side_of.get(&g) {
                        if v != w {
                            links.entry((w, v)).or_insert([[0.0; 2]; 2])[s][t] += len;
                        }
                    }
                }
            }
        }
    }
    let mut keys: Vec<_> = links.keys().copied().collect();
    keys.sort();
    let mut out = Vec::new();
    for (a, b) in keys {
        let m = links[&(a, b)];
        let reverse = links.get(&(b, a)).copied().unwrap_or([[0.0; 2]; 2]);
        out.extend(junctions_of_pair(a, b, &m, &reverse));
    }
    out
}

/// The junctions of wall `a` on wall `b` from the lengths `m[s][t]` along
/// which side `s` of `a` meets side `t` of `b` (and `reverse`, `b`'s on
/// `a`): a T on one side of `b` or through it (a T on both), a flange
/// through `b` (one side of `a` meets both of `b`'s), or an L (both
/// directions, for [`resolve_l_junctions`]).
fn junctions_of_pair(
    a: usize,
    b: usize,
    m: &[[f64; 2]; 2],
    reverse: &[[f64; 2]; 2],
) -> Vec<Junction> {
    let junction = |leaf, base, tee, base_side, through, length| Junction {
        leaf,
        base,
        tee,
        base_side,
        through,
        length,
    };
    let meets = |s: usize, t: usize| m[s][t] > 0.0;
    let tees: Vec<usize> = (0..2).filter(|&t| meets(0, t) && meets(1, t)).collect();
    let tee_length = |t: usize| 0.5 * (m[0][t] + m[1][t]);
    match tees.len() {
        2 => {
            let length = tee_length(0).max(tee_length(1));
            return vec![junction(a, b, true, 0, true, length)];
        }
        1 => return vec![junction(a, b, true, tees[0], false, tee_length(tees[0]))],
        _ => {}
    }
    // A flange through `b`: one side of `a` meets both sides of `b`, the
    // other side none (kept only where `b` is a floor: `prefer_floors`).
    for (s, row) in m.iter().enumerate() {
        if meets(s, 0) && meets(s, 1) && !meets(1 - s, 0) && !meets(1 - s, 1) {
            return vec![junction(a, b, false, 0, true, row[0].max(row[1]))];
        }
    }
    // L: exactly one side of a meets exactly one side of b, and neither is
    // a T in either direction (checked from b's view as well).
    let b_tee = (0..2).any(|s| reverse[0][s] > 0.0 && reverse[1][s] > 0.0);
    let pairs: Vec<(usize, usize)> = (0..2)
        .flat_map(|s| (0..2).map(move |t| (s, t)))
        .filter(|&(s, t)| meets(s, t))
        .collect();
    if b_tee || a > b || pairs.len() != 1 {
        return Vec::new();
    }
    let (s, t) = pairs[0];
    // Both directions; `resolve_l_junctions` keeps the right one.
    vec![
        junction(a, b, false, t, false, m[s][t]),
        junction(b, a, false, s, false, m[s][t]),
    ]
}

/// Where a wall runs through a floor (a wall whose sides face along up,
/// within `cos_floor`) the floor is its base, never its leaf: a frame's
/// web is crossed by its outer walls and ribs, which stand on both of its
/// sides. A flange-through reading of any other pair is dropped (the other
/// wall is then a T on it, as before), and so is a floor standing on a wall
/// that runs through it.
pub fn prefer_floors(
    junctions: Vec<Junction>,
    walls: &[Wall],
    up: &thinwall_geom::Vector3,
    cos_floor: f64,
) -> Vec<Junction> {
    let floor =
        |w: usize| walls[w].curved.is_none() && walls[w].normals[0].dot(up).abs() >= cos_floor;
    let crossed: std::collections::HashSet<(usize, usize)> = junctions
        .iter()
        .filter(|j| j.through && floor(j.base) && !floor(j.leaf))
        .map(|j| (j.leaf, j.base))
        .collect();
    junctions
        .into_iter()
        .filter(|j| {
            if crossed.contains(&(j.base, j.leaf)) {
                return false; // the floor as a leaf of a wall through it
            }
            !j.through || j.tee || crossed.contains(&(j.leaf, j.base))
        })
        .collect()
}

/// Decide which wall of each L-junction is the base: a wall carrying
/// stiffeners (the wall some wall stands on by its longest T-foot) over one
/// that does not — a
/// vertical web carrying flanges and stiffeners is a web — otherwise the
/// lower one in the set-up (`height`); at equal height both ways.
pub fn resolve_l_junctions(
    junctions: Vec<Junction>,
    height: impl Fn(usize) -> f64,
    tie_tol: f64,
) -> Vec<Junction> {
    // A carrier is the wall some wall stands on by its longest T-foot.
    let mut best_tee: HashMap<usize, &Junction> = HashMap::new();
    for j in junctions.iter().filter(|j| j.tee) {
        let e = best_tee.entry(j.leaf).or_insert(j);
        if j.length > e.length {
            *e = j;
        }
    }
    let carriers: std::collections::HashSet<usize> = best_tee.values().map(|j| j.base).collect();
    junctions
        .into_iter()
        .filter_map(|j| {
            if j.tee || j.through {
                return Some(j);
            }
            let (leaf_carries, base_carries) =
                (carriers.contains(&j.leaf), carriers.contains(&j.base));
            if base_carries != leaf_carries {
                return base_carries.then_some(j);
            }
            let (hl, hb) = (height(j.leaf), height(j.base));
            if (hl - hb).abs() <= tie_tol {
                Some(j)
            } else {
                (hl > hb).then_some(j)
            }
        })
        .collect()
}
