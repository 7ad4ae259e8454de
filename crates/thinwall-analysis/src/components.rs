//! Connected groups of faces over filtered views of the adjacency graph
//! (petgraph's `NodeFiltered` and `EdgeFiltered` with its `Bfs`): the one
//! flood fill every recognizer uses.

use petgraph::visit::{Bfs, EdgeFiltered, EdgeRef, NodeFiltered, VisitMap};
use std::collections::BTreeSet;
use thinwall_brep::FaceId;
use thinwall_graph::{Adjacency, AdjacencyGraph};

/// Faces reachable from `seeds` through faces accepted by `node_ok`, across
/// arcs accepted by `arc_ok(a, b, adjacency)`. Seeds `node_ok` refuses are
/// left out.
pub fn reachable(
    graph: &AdjacencyGraph,
    seeds: impl IntoIterator<Item = FaceId>,
    node_ok: impl Fn(FaceId) -> bool,
    arc_ok: impl Fn(FaceId, FaceId, &Adjacency) -> bool,
) -> BTreeSet<FaceId> {
    let g = &graph.graph;
    let arcs = EdgeFiltered::from_fn(g, |e| arc_ok(g[e.source()], g[e.target()], e.weight()));
    let view = NodeFiltered::from_fn(&arcs, |n| node_ok(g[n]));
    let mut out = BTreeSet::new();
    let mut seeds = seeds.into_iter().filter(|&f| node_ok(f));
    let Some(first) = seeds.next() else {
        return out;
    };
    let mut bfs = Bfs::new(&view, graph.nodes[first.index()]);
    for s in seeds {
        let n = graph.nodes[s.index()];
        if bfs.discovered.visit(n) {
            bfs.stack.push_back(n);
        }
    }
    while let Some(n) = bfs.next(&view) {
        out.insert(g[n]);
    }
    out
}

/// The groups of faces among `members` joined across arcs accepted by
/// `arc_ok`, each sorted, in the order of their first member in `members`.
pub fn components(
    graph: &AdjacencyGraph,
    members: &[FaceId],
    arc_ok: impl Fn(FaceId, FaceId, &Adjacency) -> bool,
) -> Vec<Vec<FaceId>> {
    let set: BTreeSet<FaceId> = members.iter().copied().collect();
    let mut seen: BTreeSet<FaceId> = BTreeSet::new();
    let mut out = Vec::new();
    for &start in members {
        if seen.contains(&start) {
            continue;
        }
        let group = reachable(graph, [start], |f| set.contains(&f), &arc_ok);
        seen.extend(group.iter().copied());
        out.push(group.into_iter().collect());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use thinwall_graph::Convexity;

    fn part() -> thinwall_brep::Part {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fixtures/recognition/notched_rib.step");
        thinwall_step::read_file(path).expect("fixture").0
    }

    #[test]
    fn groups_follow_the_arc_filter() {
        let p = part();
        let g = AdjacencyGraph::build(&p, &p.tolerances());
        let all: Vec<FaceId> = p.face_ids().collect();
        // The solid is connected: one group over all arcs.
        assert_eq!(components(&g, &all, |_, _, _| true).len(), 1);
        // No arc at all: every face alone.
        assert_eq!(components(&g, &all, |_, _, _| false).len(), all.len());
        // Concave arcs only: the notch's faces join, the rest stay alone.
        let concave = components(&g, &all, |_, _, a| a.convexity == Convexity::Concave);
        assert!(concave.iter().any(|c| c.len() >= 2));
        assert!(concave.len() < all.len());
        for c in &concave {
            assert!(c.windows(2).all(|w| w[0] < w[1]), "sorted");
        }
        // A refused seed is not in the result.
        let none = reachable(&g, [all[0]], |f| f != all[0], |_, _, _| true);
        assert!(none.is_empty());
    }
}
