//! The order of passes (Cohen et al.: cut tool changes within the
//! sequence constraints).
//!
//! A tool may work in a layer once what lies above what it clears is
//! gone: when layer k + 1's section lies within layer k's (of the same
//! feature), what tool T clears in it lies within what T cleared in layer
//! k (an opening keeps inclusion), so T's passes follow the same and
//! larger tools' of layer k only; otherwise they follow all of layer k's.
//! Within a field a smaller tool follows the larger ones, and a floor's
//! finish follows the field's milling by the same and larger tools. A
//! drill follows every pass of the layers above its holes' entry. Along
//! the plan, every pass of a feature precedes every pass of a feature the
//! plan puts after it. The precedences are a `petgraph` graph; the order
//! is a topological order of it that keeps the tool in the spindle while
//! it has work, the nearest ready pass first.

use crate::layers::RoughingLayer;
use crate::stage::{Draft, Stage};
use geo::{Area, BooleanOps, MultiPolygon};
use petgraph::graph::{DiGraph, NodeIndex};

/// Per layer, whether its section lies within the one above (walls going
/// straight down or closing in): then what any tool clears in it lies
/// within what the same tool cleared above (an opening keeps inclusion).
pub(crate) fn nested(layers: &[RoughingLayer], tol: f64) -> Vec<bool> {
    let section = |l: &RoughingLayer| -> MultiPolygon<f64> {
        MultiPolygon::new(l.fields.iter().map(|f| f.polygon()).collect())
    };
    let sections: Vec<MultiPolygon<f64>> = layers.iter().map(section).collect();
    (0..layers.len())
        .map(|k| {
            k > 0 && layers[k].feature == layers[k - 1].feature && {
                let extra = sections[k].difference(&sections[k - 1]).unsigned_area();
                extra <= (tol * tol).max(1e-9 * layers[k].area_mm2)
            }
        })
        .collect()
}

/// Edges from each operation to those that must follow it (module
/// docs): between layers by `nested`; within a layer and a field from
/// larger tools to smaller, and from milling to the floor's finish.
pub(crate) fn precedence(
    ops: &[Draft],
    layers: &[RoughingLayer],
    nested: &[bool],
    bottoms: &[f64],
    tol: f64,
) -> DiGraph<usize, ()> {
    let mut g = DiGraph::new();
    let nodes: Vec<NodeIndex> = (0..ops.len()).map(|i| g.add_node(i)).collect();
    for (i, d) in ops.iter().enumerate() {
        for (j, e) in ops.iter().enumerate() {
            if i == j || e.stage == Stage::Drill {
                continue;
            }
            if d.stage == Stage::Drill {
                // A drill enters once everything above its holes is gone.
                if bottoms[e.layer] >= d.entry_mm - tol {
                    g.add_edge(nodes[j], nodes[i], ());
                }
                continue;
            }
            if matches!(e.stage, Stage::Finish | Stage::FinishWalls) {
                continue;
            }
            // A finish comes after the roughing of its layer (a larger or
            // the same tool in a field it shares), nothing waits for it.
            let finish = matches!(d.stage, Stage::Finish | Stage::FinishWalls);
            let larger = e.tool.diameter_mm > d.tool.diameter_mm;
            let same = e.tool.name == d.tool.name;
            let same_feature = layers[e.layer].feature == layers[d.layer].feature;
            let follows = if e.layer + 1 == d.layer && same_feature {
                !finish && (!nested[d.layer] || larger || same)
            } else if e.layer == d.layer {
                let shared = e.fields.iter().any(|f| d.fields.contains(f));
                shared && (larger || (same && finish))
            } else {
                false
            };
            if follows {
                g.add_edge(nodes[j], nodes[i], ());
            }
        }
    }
    g
}

/// Every operation of a feature before every operation of a feature
/// `groups` puts after it.
pub(crate) fn group_edges(
    g: &mut DiGraph<usize, ()>,
    ops: &[Draft],
    layers: &[RoughingLayer],
    groups: &[(thinwall_plan::VolumeId, thinwall_plan::VolumeId)],
) {
    let of = |id: &str| -> Vec<usize> {
        (0..ops.len())
            .filter(|&i| layers[ops[i].layer].feature.as_deref() == Some(id))
            .collect()
    };
    for (before, after) in groups {
        let (a, b) = (of(before), of(after));
        for &i in &a {
            for &j in &b {
                g.update_edge(NodeIndex::new(i), NodeIndex::new(j), ());
            }
        }
    }
}

/// A topological order keeping the tool while it has work: among the
/// ready operations the current tool's nearest to where it is, else the
/// largest tool's nearest (the shallowest on a tie).
pub(crate) fn tool_order(ops: &[Draft], g: &DiGraph<usize, ()>, pos: &[[f64; 2]]) -> Vec<usize> {
    debug_assert!(petgraph::algo::toposort(g, None).is_ok());
    let mut waiting: Vec<usize> = (0..ops.len())
        .map(|i| {
            g.neighbors_directed(NodeIndex::new(i), petgraph::Direction::Incoming)
                .count()
        })
        .collect();
    let mut done = vec![false; ops.len()];
    let mut out = Vec::with_capacity(ops.len());
    let mut current: Option<(&str, Stage)> = None;
    let mut at: Option<[f64; 2]> = None;
    while out.len() < ops.len() {
        let ready = (0..ops.len()).filter(|&i| !done[i] && waiting[i] == 0);
        // The same tool, the nearest, then the same stage (where a tool
        // could go on down its layers or finish the walls of the one it
        // roughed, it goes on down: one operation each).
        let key = |&i: &usize| {
            let tool = current.is_some_and(|c| c.0 == ops[i].tool.name);
            let stage = current.is_some_and(|c| c.1 == ops[i].stage);
            let far = at.map_or(0.0, |p| (p[0] - pos[i][0]).hypot(p[1] - pos[i][1]));
            (!tool, -ops[i].tool.diameter_mm, far, !stage, ops[i].layer)
        };
        let Some(next) = ready.min_by(|a, b| {
            let (ka, kb) = (key(a), key(b));
            let far = if (ka.2 - kb.2).abs() <= FAR_TIE_MM {
                std::cmp::Ordering::Equal
            } else {
                ka.2.total_cmp(&kb.2)
            };
            ka.0.cmp(&kb.0)
                .then(ka.1.total_cmp(&kb.1))
                .then(far)
                .then(ka.3.cmp(&kb.3))
                .then(ka.4.cmp(&kb.4))
        }) else {
            break;
        };
        done[next] = true;
        current = Some((ops[next].tool.name.as_str(), ops[next].stage));
        at = Some(pos[next]);
        for n in g.neighbors_directed(NodeIndex::new(next), petgraph::Direction::Outgoing) {
            waiting[n.index()] -= 1;
        }
        out.push(next);
    }
    out
}

/// Distances within this are a tie, mm: fields' centroids carry the
/// booleans' rounding (1e-7 mm on a turned part), and a tie broken by it
/// would order a turned copy otherwise.
const FAR_TIE_MM: f64 = 1e-3;
