//! Relations between the plan's machining features and one order that
//! respects them all.
//!
//! Three kinds of `before`, added in this order:
//! 1. **above**: within one column of the decomposition, what lies above
//!    comes out first (the tool enters from up);
//! 2. **step approach**: a wall's layers in their fig. 4.1 order;
//! 3. **wall order**: the stiffness-feature sequence (a wall's last layer
//!    before the next wall's first). Such a relation is dropped, with the
//!    reason, where it would contradict 1 or 2 (a cycle).
//!
//! The order is a topological sort that takes, among the features free to
//! go, the one of this set-up before another set-up's, then the highest,
//! then the first designed.

pub use crate::types::{FeatureRelation, FeatureSequence};

use crate::types::RemovalFeature;
use crate::types::{LayerConstraint, VolumeId};
use petgraph::algo::has_path_connecting;
use petgraph::graph::{DiGraph, NodeIndex};
use std::cmp::Reverse;
use std::collections::{BTreeSet, BinaryHeap, HashMap};
use thinwall_removal::BoundId;

/// Relations and order of `features` (vanished layers already removed),
/// given the layer relations of the step approach and the wall order.
pub fn order(features: &[RemovalFeature], layer_rel: &[LayerConstraint]) -> FeatureSequence {
    let index: HashMap<&str, usize> = features
        .iter()
        .enumerate()
        .map(|(i, f)| (f.id.as_str(), i))
        .collect();
    let mut g: DiGraph<usize, ()> = DiGraph::new();
    let nodes: Vec<NodeIndex> = (0..features.len()).map(|i| g.add_node(i)).collect();
    let mut seq = FeatureSequence::default();
    let mut seen = BTreeSet::new();
    let mut add = |g: &mut DiGraph<usize, ()>, a: usize, b: usize, why: String| {
        if a == b || !seen.insert((a, b)) {
            return;
        }
        let rel = FeatureRelation {
            before: features[a].id.clone(),
            after: features[b].id.clone(),
            why,
        };
        // A relation closing a cycle is dropped. For the hard ones (height
        // and step approach, which agree) this does not happen; the graph
        // stays acyclic all the same.
        if has_path_connecting(&*g, nodes[b], nodes[a], None) {
            seq.dropped.push(rel);
            return;
        }
        g.add_edge(nodes[a], nodes[b], ());
        seq.relations.push(rel);
    };
    // 1. above: the feature whose piece begins where another's ends lies
    // above it.
    let mut at_top: HashMap<(usize, BoundId), usize> = HashMap::new();
    for (i, f) in features.iter().enumerate() {
        for p in &f.pieces {
            at_top.insert((p.cell, p.upper.id()), i);
        }
    }
    let mut above = BTreeSet::new();
    for (i, f) in features.iter().enumerate() {
        for p in &f.pieces {
            if let Some(&below) = at_top.get(&(p.cell, p.lower.id())) {
                if below != i {
                    above.insert((i, below));
                }
            }
        }
    }
    for (a, b) in above {
        add(
            &mut g,
            a,
            b,
            format!("{} lies above {}", features[a].id, features[b].id),
        );
    }
    // 2 and 3: the layers' relations, by the layer ids that remain; a
    // vanished layer passes its relations on.
    for (a, b, why) in through_vanished(layer_rel, &index) {
        add(&mut g, a, b, why);
    }
    seq.order = topo(features, &g, &nodes);
    seq
}

/// The layer relations between features that remain: a relation to or
/// from a vanished layer continues to what that layer comes before or
/// after (a wall whose small layers all vanished keeps its large ones in
/// step order; a cut-out inserted after a vanished layer follows the one
/// before it).
fn through_vanished(
    layer_rel: &[LayerConstraint],
    index: &HashMap<&str, usize>,
) -> Vec<(usize, usize, String)> {
    let mut next: HashMap<&str, Vec<&str>> = HashMap::new();
    let mut prev: HashMap<&str, Vec<&str>> = HashMap::new();
    for r in layer_rel {
        next.entry(r.before.as_str())
            .or_default()
            .push(r.after.as_str());
        prev.entry(r.after.as_str())
            .or_default()
            .push(r.before.as_str());
    }
    // The features that remain reached from `start` along `step`, and the
    // vanished layers passed on the way.
    let reach = |start: &str, step: &HashMap<&str, Vec<&str>>| -> Vec<(usize, Vec<String>)> {
        let mut out = Vec::new();
        let mut stack = vec![(start.to_string(), Vec::<String>::new())];
        let mut seen = BTreeSet::new();
        while let Some((id, via)) = stack.pop() {
            if !seen.insert(id.clone()) {
                continue;
            }
            if let Some(&i) = index.get(id.as_str()) {
                out.push((i, via));
                continue;
            }
            for n in step.get(id.as_str()).into_iter().flatten() {
                let mut v = via.clone();
                v.push(id.clone());
                stack.push((n.to_string(), v));
            }
        }
        out
    };
    let mut out = Vec::new();
    for r in layer_rel {
        for (a, via_a) in reach(r.before.as_str(), &prev) {
            for (b, via_b) in reach(r.after.as_str(), &next) {
                let via: Vec<String> = via_a.iter().chain(&via_b).cloned().collect();
                let why = match via.is_empty() {
                    true => r.why.clone(),
                    false => format!("{} (through vanished {})", r.why, via.join(", ")),
                };
                out.push((a, b, why));
            }
        }
    }
    out
}

/// Kahn's algorithm with the module's tie-break.
fn topo(features: &[RemovalFeature], g: &DiGraph<usize, ()>, nodes: &[NodeIndex]) -> Vec<VolumeId> {
    let key = |i: usize| {
        let f = &features[i];
        (!f.reachable, Reverse(ordered(f.z_range[1])), i)
    };
    let mut indeg: Vec<usize> = nodes
        .iter()
        .map(|&n| {
            g.neighbors_directed(n, petgraph::Direction::Incoming)
                .count()
        })
        .collect();
    let mut ready: BinaryHeap<Reverse<(bool, Reverse<i64>, usize)>> = (0..features.len())
        .filter(|&i| indeg[i] == 0)
        .map(|i| Reverse(key(i)))
        .collect();
    let mut out = Vec::with_capacity(features.len());
    while let Some(Reverse((_, _, i))) = ready.pop() {
        out.push(features[i].id.clone());
        for n in g.neighbors_directed(nodes[i], petgraph::Direction::Outgoing) {
            let j = g[n];
            indeg[j] -= 1;
            if indeg[j] == 0 {
                ready.push(Reverse(key(j)));
            }
        }
    }
    out
}

/// A height as a sortable integer (tenths of a micrometre: equal heights
/// compare equal whatever the rounding of a pose).
fn ordered(z: f64) -> i64 {
    (z * 1e4).round() as i64
}
