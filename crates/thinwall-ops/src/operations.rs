//! Operations (Matsuda's milling features per tool and depth, Popma's
//! modular regions, Cohen et al.'s stages).
//!
//! Every layer's fields get their tools ([`crate::rest`]). A pass is one
//! tool in one layer at one stage: **rough** (the field's first tool),
//! **semi-finish** (a smaller tool in what larger ones left: rest
//! machining) or **finish** (the floor under a field, Popma's separate
//! bottom layer: its last `finish_axial_depth_mm` at finishing stepover).
//! Rough and semi-finish passes carry their share's regions (boundary,
//! full cut, roughing) and are timed region by region. **Drill**
//! operations take the holes a drill matches, or an end mill spirals down
//! ([`crate::drilling`]): the cutter fields within a hole's circle over
//! its depth leave the milling, and one operation per tool and kind drills
//! them all.
//!
//! The passes are ordered (`order.rs`) and consecutive passes of one
//! tool, stage and feature, going deeper, are joined into one operation.

pub(crate) use crate::stage::Draft;
pub use crate::stage::{Regions, Stage};

use crate::drilling::{drilling_time_min, DrillKind, HoleSite};
use crate::layers::{roughing_layers, CutterField, LayerOptions, RoughingLayer};
use crate::order::{group_edges, nested, precedence, tool_order};
use crate::rest::{open, Adjacency, FieldTools, ToolShare};
use crate::tools::{CuttingTool, ToolLibrary};
use petgraph::graph::NodeIndex;
use serde::Serialize;
use std::collections::HashMap;
use thinwall_analysis::boolean::Near;
use thinwall_analysis::parallel::Work;
use thinwall_removal::pieces::Meshed;
use thinwall_removal::Removal;

impl Stage {
    pub fn name(self) -> &'static str {
        match self {
            Stage::Rough => "rough",
            Stage::SemiFinish => "semi_finish",
            Stage::FinishWalls => "finish_walls",
            Stage::Finish => "finish",
            Stage::Drill => "drill",
            Stage::FinishRadii => "finish_radii",
        }
    }

    /// Whether it clears part of a layer's section (rough, semi-finish,
    /// wall finish), as opposed to a floor's skin or holes.
    pub fn clears(self) -> bool {
        matches!(self, Stage::Rough | Stage::SemiFinish | Stage::FinishWalls)
    }
}

/// One layer of an operation: what its tool does there.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Pass {
    pub layer: usize,
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    /// The layer's fields it works in (indices into the layer's fields).
    pub fields: Vec<usize>,
    /// Rough and semi-finish: what it clears that larger tools left;
    /// finish: the floor it finishes, mm².
    pub area_mm2: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regions: Option<Regions>,
    /// mm³: the area times the layer's thickness, less the floors'
    /// finishing layer (rough, semi-finish); the floor times that layer
    /// (finish).
    pub volume_mm3: f64,
    /// Region by region, the volume over the removal rate for its
    /// conditions (Q = a_p · a_e · f_z · z · n), min.
    pub time_min: f64,
}

/// One operation: a tool at a stage, in one layer or in consecutive ones
/// (Matsuda's milling feature per tool and group of depths): its passes
/// follow each other in the order with nothing between them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Operation {
    /// Place in the chosen order, from 1.
    pub step: usize,
    pub stage: Stage,
    pub tool: String,
    pub diameter_mm: f64,
    /// The plan's machining feature it works in (operations along the
    /// plan).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub feature: Option<thinwall_plan::VolumeId>,
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    /// The product adjacency of its fields together.
    pub adjacency: Adjacency,
    /// Its passes' areas added up (drilling: its holes' cross-sections),
    /// mm².
    pub area_mm2: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regions: Option<Regions>,
    pub volume_mm3: f64,
    pub time_min: f64,
    /// One per layer, top down (none for drilling).
    pub passes: Vec<Pass>,
    /// Steps it must follow.
    pub after: Vec<usize>,
    /// Drilling: how, and the holes (machining feature ids).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drill: Option<DrillKind>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub holes: Vec<String>,
    /// Finishing by radii: the machining features (`M…`) whose walls and
    /// floor fillets it contours, or (`corners`) whose corners alone.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub finishes: Vec<String>,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub corners: bool,
}

impl Operation {
    /// A one-pass operation.
    fn single(
        stage: Stage,
        tool: &CuttingTool,
        adjacency: Adjacency,
        feature: Option<thinwall_plan::VolumeId>,
        pass: Pass,
    ) -> Self {
        Operation {
            feature,
            area_mm2: pass.area_mm2,
            regions: pass.regions,
            volume_mm3: pass.volume_mm3,
            time_min: pass.time_min,
            ..Operation::empty(stage, tool, [pass.z_top_mm, pass.z_bottom_mm], adjacency)
        }
        .with_pass(pass)
    }

    fn with_pass(mut self, pass: Pass) -> Self {
        self.passes.push(pass);
        self
    }

    /// An operation of `tool` at `stage` between heights `z` (top, bottom)
    /// with nothing in it yet: no passes, figures, holes or features.
    pub(crate) fn empty(
        stage: Stage,
        tool: &CuttingTool,
        z: [f64; 2],
        adjacency: Adjacency,
    ) -> Self {
        Operation {
            step: 0,
            stage,
            tool: tool.name.clone(),
            diameter_mm: tool.diameter_mm,
            feature: None,
            z_top_mm: z[0],
            z_bottom_mm: z[1],
            adjacency,
            area_mm2: 0.0,
            regions: None,
            volume_mm3: 0.0,
            time_min: 0.0,
            passes: Vec::new(),
            after: Vec::new(),
            drill: None,
            holes: Vec::new(),
            finishes: Vec::new(),
            corners: false,
        }
    }

    /// Whether `next` continues it: the same tool, stage and feature, a
    /// milling stage, a deeper layer (passes go shallow to deep).
    fn continued_by(&self, next: &Operation) -> bool {
        let deeper = match (self.passes.last(), next.passes.first()) {
            (Some(a), Some(b)) => b.layer > a.layer,
            _ => false,
        };
        self.stage != Stage::Drill
            && next.stage == self.stage
            && next.tool == self.tool
            && next.feature == self.feature
            && deeper
    }

    /// Take `next`'s passes and figures.
    fn absorb(&mut self, next: Operation) {
        self.z_top_mm = self.z_top_mm.max(next.z_top_mm);
        self.z_bottom_mm = self.z_bottom_mm.min(next.z_bottom_mm);
        self.adjacency = self.adjacency.with(next.adjacency);
        self.area_mm2 += next.area_mm2;
        if let (Some(a), Some(b)) = (&mut self.regions, next.regions) {
            a.boundary_mm2 += b.boundary_mm2;
            a.full_cut_mm2 += b.full_cut_mm2;
            a.roughing_mm2 += b.roughing_mm2;
        }
        self.volume_mm3 += next.volume_mm3;
        self.time_min += next.time_min;
        self.passes.extend(next.passes);
        self.after.extend(next.after);
    }
}

/// The passes in `order`, consecutive ones of one tool, stage and feature
/// joined into one operation, numbered, with what each must follow.
fn joined(order: &[usize], passes: Vec<Operation>, preds: &[Vec<usize>]) -> Vec<Operation> {
    // Pass index (draft) -> operation number.
    let mut number = vec![0; passes.len()];
    let mut out: Vec<Operation> = Vec::new();
    let mut slots: Vec<Option<Operation>> = passes.into_iter().map(Some).collect();
    for &i in order {
        let mut op = slots[i].take().expect("each draft once");
        op.after = preds[i].clone();
        match out.last_mut() {
            Some(last) if last.continued_by(&op) => last.absorb(op),
            _ => out.push(op),
        }
        number[i] = out.len();
    }
    for (s, op) in out.iter_mut().enumerate() {
        op.step = s + 1;
        let mut after: Vec<usize> = op
            .after
            .iter()
            .map(|&d| number[d])
            .filter(|&n| n != s + 1)
            .collect();
        after.sort_unstable();
        after.dedup();
        op.after = after;
    }
    out
}

/// One tool's work in a set-up: its stages, how many operations, the
/// steps it first and last runs in, what it cuts and its time.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToolUse {
    pub tool: String,
    pub diameter_mm: f64,
    pub stages: Vec<Stage>,
    pub operations: usize,
    pub first_step: usize,
    pub last_step: usize,
    /// Spells in the spindle: how often it is loaded.
    pub loads: usize,
    pub volume_mm3: f64,
    pub time_min: f64,
}

/// The tool sheet of `operations` (in their order): each tool once, in
/// the order it first runs.
pub fn tool_sheet(operations: &[Operation]) -> Vec<ToolUse> {
    let mut out: Vec<ToolUse> = Vec::new();
    let mut loaded: Option<&str> = None;
    for o in operations {
        let k = match out.iter().position(|u| u.tool == o.tool) {
            Some(k) => k,
            None => {
                out.push(ToolUse {
                    tool: o.tool.clone(),
                    diameter_mm: o.diameter_mm,
                    stages: Vec::new(),
                    operations: 0,
                    first_step: o.step,
                    last_step: o.step,
                    loads: 0,
                    volume_mm3: 0.0,
                    time_min: 0.0,
                });
                out.len() - 1
            }
        };
        let u = &mut out[k];
        if !u.stages.contains(&o.stage) {
            u.stages.push(o.stage);
        }
        u.operations += 1;
        u.last_step = o.step;
        u.loads += usize::from(loaded != Some(o.tool.as_str()));
        u.volume_mm3 += o.volume_mm3;
        u.time_min += o.time_min;
        loaded = Some(o.tool.as_str());
    }
    out
}

/// What no tool of the library takes, where: what none reaches, and
/// what one would reach but under the minimum share (`below_minimum`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rest {
    pub layer: usize,
    pub field: usize,
    pub area_mm2: f64,
    pub width_mm: f64,
    pub outlines: Vec<Vec<[f64; 2]>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub below_minimum: Option<crate::rest::BelowMinimum>,
}

/// The operations of one set-up.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SetupOperations {
    /// Depth of cut between levels, mm.
    pub axial_depth_mm: f64,
    /// The holes along the tool axis, with their drill where one matches
    /// (the others are milled with the layers).
    pub holes: Vec<HoleSite>,
    pub layers: Vec<RoughingLayer>,
    /// Per layer, per field, its tools.
    pub field_tools: Vec<Vec<FieldTools>>,
    pub operations: Vec<Operation>,
    pub rest: Vec<Rest>,
    /// The pockets, slots, steps and passages finished by their corner
    /// radius and floor fillet, with their tools and rests.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub radius_finishes: Vec<crate::stage::RadiusFinish>,
    /// The holes' stages besides their bores (spot, countersink, chamfer,
    /// blend), each with its tool or why none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub hole_stages: Vec<crate::stage::HoleStage>,
    /// The plan's machining features left to another set-up (operations
    /// along the plan only).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub other_setup: Vec<thinwall_plan::VolumeId>,
    /// The removal's faces taken as triangles (tilted or free-form) and
    /// the volume bound they imply: the layers' sections are exact to
    /// the machining deviation there.
    #[serde(skip_serializing_if = "Meshed::is_empty")]
    pub meshed: Meshed,
    /// Material under the part that a tool along up cannot reach (the
    /// far side of a double-sided web, an undercut): another set-up's,
    /// mm³ (operations from the stock's top; along the plan, its features
    /// are in `other_setup`).
    #[serde(skip_serializing_if = "is_zero")]
    pub out_of_reach_mm3: f64,
    /// What a set-up from the opposite side took before this one (through
    /// columns: holes through the part, the stock round it), mm³; none
    /// for a first set-up.
    #[serde(skip_serializing_if = "is_zero")]
    pub cleared_before_mm3: f64,
    #[serde(skip_serializing_if = "is_zero")]
    /// At most this much of what it cuts an earlier set-up had taken: its
    /// blocks an earlier set-up along another axis reached in part (judged
    /// at points inside them), cut whole here, mm³.
    pub recut_mm3: f64,
    /// The tools in the order they first run, what each cuts and its
    /// time: the set-up's tool sheet.
    pub tool_sheet: Vec<ToolUse>,
    /// Tool changes in the chosen order, and in the plain one.
    pub tool_changes: usize,
    pub plain_tool_changes: usize,
    /// Travel between consecutive passes (their fields' centroids, a
    /// drill's holes' mean centre) across the tool axis, in the chosen
    /// order and in the plain one, mm.
    pub travel_mm: f64,
    pub plain_travel_mm: f64,
    pub time_min: f64,
}

/// Plan the operations for the removal `r` with the library's end mills,
/// and its drills for the `holes` they match. `axial_depth_mm` defaults
/// to the largest end mill's a_p; no layer over a thin wall's heights is
/// deeper than its `limits` allow.
pub fn operations(
    r: &Removal,
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
    limits: &[thinwall_plan::StepLimit],
    holes: &[HoleSite],
    work: Work<'_>,
) -> SetupOperations {
    let (mills, a_p) = mills_and_depth(lib, axial_depth_mm);
    let layers = roughing_layers(
        r,
        &LayerOptions {
            axial_depth_mm: a_p,
            smallest_tool_mm: mills.last().map_or(0.0, |t| t.diameter_mm),
            step_limits: limits.to_vec(),
        },
    );
    let tol = 1e-6 * r.size.max(1.0);
    let field_tools = tools_for(&layers, &mills, lib.min_share_mm2, holes, tol, work);
    assemble(
        Assembly {
            lib,
            a_p,
            holes,
            groups: &[],
            tol,
        },
        layers,
        field_tools,
    )
}

/// The library's end mills, largest first, and the depth of cut.
pub(crate) fn mills_and_depth(
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
) -> (Vec<&CuttingTool>, f64) {
    let mills: Vec<&CuttingTool> = lib.end_mills().collect();
    let a_p = axial_depth_mm
        .or_else(|| mills.first().map(|t| t.axial_depth_mm))
        .unwrap_or(1.0);
    (mills, a_p)
}

/// Every field's tools, or the hole whose drill takes it. Each distinct
/// field (the same contours, bit for bit) is opened once: a pocket's
/// layers cut one section again and again, and only their floors differ.
pub(crate) fn tools_for(
    layers: &[RoughingLayer],
    mills: &[&CuttingTool],
    min_share_mm2: f64,
    holes: &[HoleSite],
    tol: f64,
    work: Work<'_>,
) -> Vec<Vec<FieldTools>> {
    let mut seen: HashMap<Vec<u64>, usize> = HashMap::new();
    let mut distinct: Vec<&CutterField> = Vec::new();
    let slots: Vec<Vec<Slot>> = layers
        .iter()
        .map(|l| {
            l.fields
                .iter()
                .map(|f| match drilled_by(f, l, holes, tol) {
                    Some(h) => Slot::Drilled(h),
                    None => Slot::Opened(*seen.entry(field_key(f)).or_insert_with(|| {
                        distinct.push(f);
                        distinct.len() - 1
                    })),
                })
                .collect()
        })
        .collect();
    let opened = work.map(&distinct, |f| open(f, mills, min_share_mm2));
    let at: Vec<usize> = (0..layers.len()).collect();
    work.map(&at, |&k| {
        let floor = &layers[k].floor_region;
        let near = Near::of(floor);
        slots[k]
            .iter()
            .map(|slot| match *slot {
                Slot::Drilled(h) => FieldTools::drilled(&holes[h].id),
                Slot::Opened(i) => opened[i].on(near.as_ref()),
            })
            .collect()
    })
}

/// What takes a field of a layer: a hole's drill (its index), or the
/// mills as they open a distinct field (its index among them).
enum Slot {
    Drilled(usize),
    Opened(usize),
}

/// A field's contours, bit for bit: its points and edge kinds, contour
/// by contour.
fn field_key(f: &CutterField) -> Vec<u64> {
    let mut key = Vec::new();
    for c in std::iter::once(&f.outer).chain(&f.islands) {
        key.push(c.points.len() as u64);
        key.extend(
            c.points
                .iter()
                .flat_map(|p| [p[0].to_bits(), p[1].to_bits()]),
        );
        key.extend(c.edges.iter().map(|e| *e as u64));
    }
    key
}

/// What the operations are assembled with besides the layers.
pub(crate) struct Assembly<'a> {
    pub lib: &'a ToolLibrary,
    pub a_p: f64,
    pub holes: &'a [HoleSite],
    /// Machining features (by `RoughingLayer::feature`) whose operations
    /// all come before another's: the plan's relations.
    pub groups: &'a [(thinwall_plan::VolumeId, thinwall_plan::VolumeId)],
    pub tol: f64,
}

/// Operations from the layers and their fields' tools, ordered.
pub(crate) fn assemble(
    x: Assembly,
    layers: Vec<RoughingLayer>,
    field_tools: Vec<Vec<FieldTools>>,
) -> SetupOperations {
    let (lib, a_p, holes, tol) = (x.lib, x.a_p, x.holes, x.tol);
    let (mills, _) = mills_and_depth(lib, Some(a_p));
    let tiny = tol.powi(2);
    let mut ops: Vec<Draft> = Vec::new();
    for (k, fts) in field_tools.iter().enumerate() {
        for stage in [
            Stage::Rough,
            Stage::SemiFinish,
            Stage::FinishWalls,
            Stage::Finish,
        ] {
            for t in &mills {
                if let Some(d) = draft(t, k, stage, fts, &layers[k], tiny) {
                    ops.push(d);
                }
            }
        }
    }
    ops.extend(drill_drafts(lib, holes, &layers, &field_tools));
    // Layer by layer, rough, semi-finish then finish, the largest tool
    // first, then the drills: always allowed.
    // Drills last: along the plan a later feature's layer may lie above a
    // hole's entry with a higher index.
    ops.sort_by(|a, b| {
        (a.stage == Stage::Drill, a.layer, a.stage)
            .cmp(&(b.stage == Stage::Drill, b.layer, b.stage))
            .then(b.tool.diameter_mm.total_cmp(&a.tool.diameter_mm))
            .then(a.drill.cmp(&b.drill))
    });
    let bottoms: Vec<f64> = layers.iter().map(|l| l.z_bottom_mm).collect();
    let mut graph = precedence(&ops, &layers, &nested(&layers, tol), &bottoms, tol);
    group_edges(&mut graph, &ops, &layers, x.groups);
    let plain: Vec<usize> = (0..ops.len()).collect();
    let changes = |o: &[usize]| {
        o.windows(2)
            .filter(|w| ops[w[0]].tool.name != ops[w[1]].tool.name)
            .count()
    };
    let pos: Vec<[f64; 2]> = ops.iter().map(|d| d.position(&layers, holes)).collect();
    let travel = |o: &[usize]| -> f64 {
        o.windows(2)
            .map(|w| {
                let (a, b) = (pos[w[0]], pos[w[1]]);
                (a[0] - b[0]).hypot(a[1] - b[1])
            })
            .sum::<f64>()
            + 0.0
    };
    let grouped = tool_order(&ops, &graph, &pos);
    let order = if changes(&grouped) <= changes(&plain) {
        grouped
    } else {
        plain.clone()
    };
    let preds: Vec<Vec<usize>> = (0..ops.len())
        .map(|i| {
            graph
                .neighbors_directed(NodeIndex::new(i), petgraph::Direction::Incoming)
                .map(|n| n.index())
                .collect()
        })
        .collect();
    let passes: Vec<Operation> = ops
        .iter()
        .map(|d| d.operation(&layers[d.layer], holes))
        .collect();
    let operations = joined(&order, passes, &preds);
    SetupOperations {
        axial_depth_mm: a_p,
        holes: holes.to_vec(),
        // (An empty sum is −0.)
        time_min: operations.iter().map(|o| o.time_min).sum::<f64>() + 0.0,
        tool_sheet: tool_sheet(&operations),
        tool_changes: changes(&order),
        plain_tool_changes: changes(&plain),
        travel_mm: travel(&order),
        plain_travel_mm: travel(&plain),
        rest: rests(&field_tools),
        other_setup: Vec::new(),
        radius_finishes: Vec::new(),
        hole_stages: Vec::new(),
        meshed: Meshed::default(),
        out_of_reach_mm3: 0.0,
        cleared_before_mm3: 0.0,
        recut_mm3: 0.0,
        layers,
        field_tools,
        operations,
    }
}

fn rests(field_tools: &[Vec<FieldTools>]) -> Vec<Rest> {
    field_tools
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
                    below_minimum: ft.below_minimum.clone(),
                })
        })
        .collect()
}

/// The hole whose drill takes field `f` of layer `l` whole: the layer
/// within the hole's depth (a layer across its entry is milled) and the
/// field within its circle.
fn drilled_by(f: &CutterField, l: &RoughingLayer, holes: &[HoleSite], tol: f64) -> Option<usize> {
    holes.iter().position(|h| {
        h.drill.is_some()
            && l.z_bottom_mm >= h.z_bottom_mm - tol
            && l.z_bottom_mm < h.z_top_mm - tol
            && l.z_top_mm <= h.z_top_mm + tol
            && f.outer.points.iter().all(|&p| h.holds(p, tol))
    })
}

/// One drilling operation per drill and kind, over the holes whose
/// material it takes from the layers.
fn drill_drafts<'a>(
    lib: &'a ToolLibrary,
    holes: &[HoleSite],
    layers: &[RoughingLayer],
    field_tools: &[Vec<FieldTools>],
) -> Vec<Draft<'a>> {
    let mut out: Vec<Draft> = Vec::new();
    for (i, h) in holes.iter().enumerate() {
        let Some(t) = h
            .drill
            .as_ref()
            .and_then(|n| lib.tools.iter().find(|t| &t.name == n))
        else {
            continue;
        };
        let mut first = None;
        let mut volume = 0.0;
        for (k, l) in layers.iter().enumerate() {
            for (f, ft) in l.fields.iter().zip(&field_tools[k]) {
                if ft.drilled.as_deref() == Some(h.id.as_str()) {
                    first.get_or_insert(k);
                    volume += f.area_mm2 * (l.z_top_mm - l.z_bottom_mm);
                }
            }
        }
        let Some(first) = first else { continue };
        let d = match out
            .iter_mut()
            .find(|d| d.tool.name == t.name && d.drill == Some(h.kind))
        {
            Some(d) => d,
            None => {
                out.push(Draft {
                    tool: t,
                    layer: first,
                    stage: Stage::Drill,
                    fields: Vec::new(),
                    adjacency: Adjacency::Side,
                    area: 0.0,
                    regions: None,
                    floor: 0.0,
                    drill: Some(h.kind),
                    holes: Vec::new(),
                    drilled_mm3: 0.0,
                    entry_mm: f64::NEG_INFINITY,
                });
                out.last_mut().expect("just pushed")
            }
        };
        d.layer = d.layer.min(first);
        d.holes.push(i);
        d.area += std::f64::consts::FRAC_PI_4 * h.diameter_mm.powi(2);
        d.drilled_mm3 += volume;
        d.entry_mm = d.entry_mm.max(h.z_top_mm);
    }
    out
}

/// Tool `t`'s operation at `stage` in layer `k`, if it has work there.
fn draft<'a>(
    t: &'a CuttingTool,
    k: usize,
    stage: Stage,
    fts: &[FieldTools],
    layer: &RoughingLayer,
    tiny: f64,
) -> Option<Draft<'a>> {
    let stepped = layer.step_limit_mm.is_some();
    let mut d = Draft {
        tool: t,
        layer: k,
        stage,
        fields: Vec::new(),
        adjacency: Adjacency::None,
        area: 0.0,
        regions: (stage != Stage::Finish).then(Regions::default),
        floor: 0.0,
        drill: None,
        holes: Vec::new(),
        drilled_mm3: 0.0,
        entry_mm: 0.0,
    };
    for (j, ft) in fts.iter().enumerate() {
        let Some(s) = ft.shares.iter().find(|s| s.tool == t.name) else {
            continue;
        };
        // Beside a thin wall each clearing pass finishes its walls too.
        let walls = if stepped { 0.0 } else { wall_share(s) };
        let works = match stage {
            Stage::Rough => s.first && s.cleared_mm2 - walls > 0.0,
            Stage::SemiFinish => !s.first && s.cleared_mm2 - walls > 0.0,
            Stage::FinishWalls => !stepped && walls > tiny,
            Stage::Finish => s.floor_mm2 > tiny && !layer.floors.is_empty(),
            Stage::Drill | Stage::FinishRadii => false,
        };
        if !works {
            continue;
        }
        d.fields.push(j);
        d.adjacency = d.adjacency.with(ft.adjacency);
        add_share(&mut d, s, stage, stepped);
    }
    (!d.fields.is_empty()).then_some(d)
}

/// What of a tool's share the wall finish takes: its boundary region, or
/// all of it when what is left for roughing is below the disks' polygon
/// noise (a small tool's corner is all boundary).
fn wall_share(s: &ToolShare) -> f64 {
    let boundary = s.boundary_mm2.min(s.cleared_mm2);
    if s.cleared_mm2 - boundary <= crate::rest::noise(s.diameter_mm) {
        s.cleared_mm2
    } else {
        boundary
    }
}

/// Add a tool's share of a field to a draft: a floor finish takes its
/// floor; a wall finish its boundary region; rough and semi-finish the
/// rest of what it clears, or all of it in a layer beside a thin wall
/// (`stepped`: the boundary region finished in the same pass, Popma
/// §4.3.1). The floor under what it clears goes with each in proportion
/// (its finishing skin is the floor finish's).
fn add_share(d: &mut Draft, s: &ToolShare, stage: Stage, stepped: bool) {
    let boundary = if stepped { 0.0 } else { wall_share(s) };
    let on_floor = |area: f64| {
        if s.cleared_mm2 > 0.0 {
            s.floor_mm2 * area / s.cleared_mm2
        } else {
            0.0
        }
    };
    match stage {
        Stage::Finish => d.area += s.floor_mm2,
        Stage::FinishWalls => {
            d.area += boundary;
            d.floor += on_floor(boundary);
            if let Some(r) = &mut d.regions {
                r.boundary_mm2 += boundary;
            }
        }
        _ => {
            let area = s.cleared_mm2 - boundary;
            d.area += area;
            d.floor += on_floor(area);
            if let Some(r) = &mut d.regions {
                r.full_cut_mm2 += s.full_cut_mm2;
                r.roughing_mm2 += s.roughing_mm2;
                if stepped {
                    r.boundary_mm2 += s.boundary_mm2;
                }
            }
        }
    }
}

impl Draft<'_> {
    /// Where it works across the tool axis: its fields' centroid, or its
    /// holes' mean centre.
    fn position(&self, layers: &[RoughingLayer], sites: &[HoleSite]) -> [f64; 2] {
        use geo::Centroid;
        let mut sum = [0.0; 3];
        if self.stage == Stage::Drill {
            for &h in &self.holes {
                sum = [
                    sum[0] + sites[h].centre[0],
                    sum[1] + sites[h].centre[1],
                    sum[2] + 1.0,
                ];
            }
        } else {
            for &j in &self.fields {
                let f = &layers[self.layer].fields[j];
                if let Some(c) = f.polygon().centroid() {
                    let w = f.area_mm2.max(1e-12);
                    sum = [sum[0] + w * c.x(), sum[1] + w * c.y(), sum[2] + w];
                }
            }
        }
        if sum[2] > 0.0 {
            [sum[0] / sum[2], sum[1] / sum[2]]
        } else {
            [0.0, 0.0]
        }
    }

    fn operation(&self, l: &RoughingLayer, sites: &[HoleSite]) -> Operation {
        if self.stage == Stage::Drill {
            return self.drilling(sites);
        }
        let h = l.z_top_mm - l.z_bottom_mm;
        // The floors' finishing layer, never more than the layer.
        let skin = self.tool.finish_axial_depth_mm.min(h);
        let t = self.tool;
        let (volume, time) = match &self.regions {
            None => (self.area * skin, self.area * skin / t.floor_rate_mm3_min()),
            Some(r) => {
                let volume = self.area * h - self.floor * skin;
                // The floor's skin comes off every region alike.
                let f = if self.area > 0.0 {
                    volume / (self.area * h)
                } else {
                    0.0
                };
                let time = f
                    * h
                    * (r.boundary_mm2 / t.boundary_rate_mm3_min()
                        + r.full_cut_mm2 / t.full_cut_rate_mm3_min()
                        + r.roughing_mm2 / t.removal_rate_mm3_min());
                (volume, time)
            }
        };
        Operation::single(
            self.stage,
            t,
            self.adjacency,
            l.feature.clone(),
            Pass {
                layer: self.layer,
                z_top_mm: l.z_top_mm,
                z_bottom_mm: l.z_bottom_mm,
                fields: self.fields.clone(),
                area_mm2: self.area,
                regions: self.regions,
                volume_mm3: volume,
                time_min: time,
            },
        )
    }

    fn drilling(&self, sites: &[HoleSite]) -> Operation {
        let holes: Vec<&HoleSite> = self.holes.iter().map(|&i| &sites[i]).collect();
        let top = holes
            .iter()
            .map(|h| h.z_top_mm)
            .fold(f64::NEG_INFINITY, f64::max);
        let bottom = holes
            .iter()
            .map(|h| h.z_bottom_mm)
            .fold(f64::INFINITY, f64::min);
        Operation {
            area_mm2: self.area,
            volume_mm3: self.drilled_mm3,
            time_min: holes
                .iter()
                .map(|h| drilling_time_min(self.tool, h.kind, h.z_top_mm - h.z_bottom_mm))
                .sum(),
            drill: self.drill,
            holes: holes.iter().map(|h| h.id.clone()).collect(),
            ..Operation::empty(Stage::Drill, self.tool, [top, bottom], self.adjacency)
        }
    }
}

/// The sheet's time and tool changes over its operations as they now
/// stand (the plain order's changes grow by as many as the chosen's).
pub(crate) fn recount(ops: &mut SetupOperations) {
    let changes = ops
        .operations
        .windows(2)
        .filter(|w| w[0].tool != w[1].tool)
        .count();
    ops.plain_tool_changes += changes.saturating_sub(ops.tool_changes);
    ops.tool_changes = changes;
    ops.time_min = ops.operations.iter().map(|o| o.time_min).sum::<f64>() + 0.0;
    ops.tool_sheet = tool_sheet(&ops.operations);
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}
