//! How walls meet: T-junctions (a wall standing on another with base
//! material on both sides of its foot), L-junctions (at the edge of the
//! other), looking through concave blends (foot fillets).

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
    /// The base's side (0/1) the leaf's foot lies on.
    pub base_side: usize,
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
    let mut out = Vec::new();
    let mut keys: Vec<_> = links.keys().copied().collect();
    keys.sort();
    for (a, b) in keys {
        let m = links[&(a, b)];
        // a stands on b as a T: both sides of a reach the same side t of b.
        for (t, (from0, from1)) in m[0].iter().zip(&m[1]).enumerate() {
            if *from0 > 0.0 && *from1 > 0.0 {
                out.push(Junction {
                    leaf: a,
                    base: b,
                    tee: true,
                    base_side: t,
                    length: 0.5 * (from0 + from1),
                });
            }
        }
        // L: exactly one side of a meets exactly one side of b, and neither
        // is a T in either direction (checked from b's view as well).
        let reverse = links.get(&(b, a)).copied().unwrap_or([[0.0; 2]; 2]);
        let a_tee = (0..2).any(|t| m[0][t] > 0.0 && m[1][t] > 0.0);
        let b_tee = (0..2).any(|s| reverse[0][s] > 0.0 && reverse[1][s] > 0.0);
        if a_tee || b_tee || a > b {
            continue;
        }
        let pairs: Vec<(usize, usize)> = (0..2)
            .flat_map(|s| (0..2).map(move |t| (s, t)))
            .filter(|&(s, t)| m[s][t] > 0.0)
            .collect();
        if pairs.len() != 1 {
            continue;
        }
        let (s, t) = pairs[0];
        let length = m[s][t];
        // Both directions; `resolve_l_junctions` keeps the right one.
        out.push(Junction {
            leaf: a,
            base: b,
            tee: false,
            base_side: t,
            length,
        });
        out.push(Junction {
            leaf: b,
            base: a,
            tee: false,
            base_side: s,
            length,
        });
    }
    out
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
            if j.tee {
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
