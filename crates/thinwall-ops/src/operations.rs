//! Roughing operations and their order (Matsuda's milling features per
//! tool and depth, ordered as Cohen et al. do to cut tool changes).
//!
//! Every layer's fields get their tools ([`crate::rest`]); an operation is
//! one tool in one layer. A tool may rough a layer once what lies above
//! what it clears is gone: when layer k + 1's section lies within layer
//! k's, what tool T clears in it lies within what T cleared in layer k (an
//! opening keeps inclusion), so T's operation follows the same and larger
//! tools' of layer k only; otherwise it follows all of layer k. The order is a
//! topological order of that graph that keeps the tool in the spindle
//! while it has work, shallow layers first; the plain order is layer by
//! layer, the largest tool first.

use crate::layers::{roughing_layers, LayerOptions, RoughingLayer};
use crate::rest::{select, FieldTools};
use crate::tools::{CuttingTool, ToolLibrary};
use geo::{Area, BooleanOps, MultiPolygon};
use petgraph::graph::{DiGraph, NodeIndex};
use rayon::prelude::*;
use serde::Serialize;
use thinwall_plan::removal::Removal;

/// One roughing operation: a tool in a layer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Operation {
    /// Place in the chosen order, from 1.
    pub step: usize,
    pub tool: String,
    pub diameter_mm: f64,
    pub layer: usize,
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    /// The layer's fields it works in (indices into the layer's fields).
    pub fields: Vec<usize>,
    /// What it clears that larger tools left, mm².
    pub area_mm2: f64,
    /// That area times the layer's thickness, mm³.
    pub volume_mm3: f64,
    /// The volume over the tool's removal rate Q = a_p · a_e · f_z · z · n,
    /// min.
    pub time_min: f64,
    /// Steps it must follow.
    pub after: Vec<usize>,
}

/// What no tool of the library reaches, where.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rest {
    pub layer: usize,
    pub field: usize,
    pub area_mm2: f64,
    pub width_mm: f64,
    pub outlines: Vec<Vec<[f64; 2]>>,
}

/// The roughing plan of one set-up.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Roughing {
    /// Depth of cut between levels, mm.
    pub axial_depth_mm: f64,
    pub layers: Vec<RoughingLayer>,
    /// Per layer, per field, its tools.
    pub field_tools: Vec<Vec<FieldTools>>,
    pub operations: Vec<Operation>,
    pub rest: Vec<Rest>,
    /// Tool changes in the chosen order, and in the plain one.
    pub tool_changes: usize,
    pub plain_tool_changes: usize,
    pub time_min: f64,
}

/// Plan the roughing of the removal `r` with the library's end mills.
/// `axial_depth_mm` defaults to the largest end mill's a_p.
pub fn roughing(r: &Removal, lib: &ToolLibrary, axial_depth_mm: Option<f64>) -> Roughing {
    let mills: Vec<&CuttingTool> = lib.end_mills().collect();
    let a_p = axial_depth_mm
        .or_else(|| mills.first().map(|t| t.axial_depth_mm))
        .unwrap_or(1.0);
    let smallest = mills.last().map_or(0.0, |t| t.diameter_mm);
    let layers = roughing_layers(
        r,
        &LayerOptions {
            axial_depth_mm: a_p,
            smallest_tool_mm: smallest,
        },
    );
    let field_tools: Vec<Vec<FieldTools>> = layers
        .par_iter()
        .map(|l| l.fields.par_iter().map(|f| select(f, &mills)).collect())
        .collect();
    let mut ops: Vec<Draft> = Vec::new();
    for (k, fts) in field_tools.iter().enumerate() {
        for t in &mills {
            let mut d = Draft {
                tool: t,
                layer: k,
                fields: Vec::new(),
                area: 0.0,
            };
            for (j, ft) in fts.iter().enumerate() {
                if let Some(s) = ft.shares.iter().position(|s| s.tool == t.name) {
                    d.fields.push(j);
                    d.area += ft.shares[s].cleared_mm2;
                }
            }
            if !d.fields.is_empty() {
                ops.push(d);
            }
        }
    }
    let graph = precedence(&ops, &nested(&layers, r.size));
    // Layer by layer, the largest tool first: always allowed.
    let plain: Vec<usize> = (0..ops.len()).collect();
    let changes = |o: &[usize]| {
        o.windows(2)
            .filter(|w| ops[w[0]].tool.name != ops[w[1]].tool.name)
            .count()
    };
    let grouped = tool_order(&ops, &graph);
    let order = if changes(&grouped) <= changes(&plain) {
        grouped
    } else {
        plain.clone()
    };
    let mut place = vec![0; ops.len()];
    for (s, &i) in order.iter().enumerate() {
        place[i] = s + 1;
    }
    let operations: Vec<Operation> = order
        .iter()
        .enumerate()
        .map(|(s, &i)| {
            let d = &ops[i];
            let l = &layers[d.layer];
            let volume = d.area * (l.z_top_mm - l.z_bottom_mm);
            let mut after: Vec<usize> = graph
                .neighbors_directed(NodeIndex::new(i), petgraph::Direction::Incoming)
                .map(|n| place[n.index()])
                .collect();
            after.sort_unstable();
            Operation {
                step: s + 1,
                tool: d.tool.name.clone(),
                diameter_mm: d.tool.diameter_mm,
                layer: d.layer,
                z_top_mm: l.z_top_mm,
                z_bottom_mm: l.z_bottom_mm,
                fields: d.fields.clone(),
                area_mm2: d.area,
                volume_mm3: volume,
                time_min: volume / d.tool.removal_rate_mm3_min(),
                after,
            }
        })
        .collect();
    let rest = field_tools
        .iter()
        .enumerate()
        .flat_map(|(k, fts)| {
            fts.iter()
                .enumerate()
                .filter(|(_, ft)| ft.rest_mm2 > 0.0 && !ft.rest.is_empty())
                .map(move |(j, ft)| Rest {
                    layer: k,
                    field: j,
                    area_mm2: ft.rest_mm2,
                    width_mm: ft.rest_width_mm,
                    outlines: ft.rest.clone(),
                })
        })
        .collect();
    Roughing {
        axial_depth_mm: a_p,
        time_min: operations.iter().map(|o| o.time_min).sum(),
        tool_changes: changes(&order),
        plain_tool_changes: changes(&plain),
        layers,
        field_tools,
        operations,
        rest,
    }
}

/// An operation before it has a place.
struct Draft<'a> {
    tool: &'a CuttingTool,
    layer: usize,
    fields: Vec<usize>,
    area: f64,
}

/// Per layer, whether its section lies within the one above (walls going
/// straight down or closing in): then what any tool clears in it lies
/// within what the same tool cleared above (an opening keeps inclusion).
fn nested(layers: &[RoughingLayer], size: f64) -> Vec<bool> {
    let section = |l: &RoughingLayer| -> MultiPolygon<f64> {
        MultiPolygon::new(l.fields.iter().map(|f| f.polygon()).collect())
    };
    let sections: Vec<MultiPolygon<f64>> = layers.iter().map(section).collect();
    let tiny = (1e-6 * size).powi(2);
    (0..layers.len())
        .map(|k| {
            k > 0 && {
                let extra = sections[k].difference(&sections[k - 1]).unsigned_area();
                extra <= tiny.max(1e-9 * layers[k].area_mm2)
            }
        })
        .collect()
}

/// Edges from each operation to those that must follow it: an operation
/// follows the larger or same tools' of the layer above when its layer is
/// `nested` in that one, else every operation of the layer above.
fn precedence(ops: &[Draft], nested: &[bool]) -> DiGraph<usize, ()> {
    let mut g = DiGraph::new();
    let nodes: Vec<NodeIndex> = (0..ops.len()).map(|i| g.add_node(i)).collect();
    for (i, d) in ops.iter().enumerate() {
        let Some(prev) = d.layer.checked_sub(1) else {
            continue;
        };
        for j in (0..ops.len()).filter(|&j| ops[j].layer == prev) {
            if !nested[d.layer] || ops[j].tool.diameter_mm >= d.tool.diameter_mm {
                g.add_edge(nodes[j], nodes[i], ());
            }
        }
    }
    g
}

/// A topological order keeping the tool while it has work: among the
/// ready operations the current tool's shallowest, else the largest
/// tool's shallowest.
fn tool_order(ops: &[Draft], g: &DiGraph<usize, ()>) -> Vec<usize> {
    debug_assert!(petgraph::algo::toposort(g, None).is_ok());
    let mut waiting: Vec<usize> = (0..ops.len())
        .map(|i| {
            g.neighbors_directed(NodeIndex::new(i), petgraph::Direction::Incoming)
                .count()
        })
        .collect();
    let mut done = vec![false; ops.len()];
    let mut out = Vec::with_capacity(ops.len());
    let mut current: Option<&str> = None;
    while out.len() < ops.len() {
        let ready = (0..ops.len()).filter(|&i| !done[i] && waiting[i] == 0);
        let key = |&i: &usize| {
            let same = current == Some(ops[i].tool.name.as_str());
            (!same, -ops[i].tool.diameter_mm, ops[i].layer)
        };
        let Some(next) = ready.min_by(|a, b| {
            let (ka, kb) = (key(a), key(b));
            ka.0.cmp(&kb.0)
                .then(ka.1.total_cmp(&kb.1))
                .then(ka.2.cmp(&kb.2))
        }) else {
            break;
        };
        done[next] = true;
        current = Some(ops[next].tool.name.as_str());
        for n in g.neighbors_directed(NodeIndex::new(next), petgraph::Direction::Outgoing) {
            waiting[n.index()] -= 1;
        }
        out.push(next);
    }
    out
}
