//! The first planner layer (issue 13): in what order to machine the
//! stiffness features of a part. Rules are data (`rules`), the facts they
//! read come from one pipeline run (`scene`), and the two-phase algorithm
//! (`sequence`) enforces, rejects and explains. `docs/PLANNING.md` has the
//! rules, the algorithm and every decision taken where the thesis is
//! silent.

pub mod adapt;
pub mod classified;
pub mod feature_order;
pub mod features;
mod limits;
pub mod rules;
pub mod scene;
pub mod sequence;
pub mod sizing;
pub mod solid_part;
pub mod steps;
mod touch;
pub mod turn;
mod types;
pub mod volumes;
mod whole;

pub use limits::StepLimit;
pub use rules::{Relation, Rule, RuleSet, RulesError};
pub use scene::Scene;
pub use sequence::{sequence, Constraint, Rejected, Rejection, Sequence};
pub use sizing::{size_wall, Milling, Sizes, SizingError, SizingParameters, WallDimensions};
/// The removal engine the plan is built over (its own crate).
pub use thinwall_removal as removal;
pub use turn::InTurn;
pub use types::{LayerConstraint, Plan, PlannedFeature, RemovalSummary, VolumeId, WallPlan};

use thinwall_analysis::{PartAnalysis, StiffnessKind};

use thinwall_pipeline::Outcome;

/// The plan's JSON contract name and version.
pub const PLAN_SCHEMA: &str = "thinwall/plan/2";

/// What the planner layers leave out, per feature: curved walls get their
/// place in the sequence and their sizes, not step-approach layers (those
/// are boxes on a flat wall's side, `steps`); their material stays in the
/// removal's bulk features.
fn limits(out: &Outcome, walls: &[WallPlan]) -> Vec<String> {
    walls
        .iter()
        .filter(|w| w.sizes.thin)
        .filter_map(|w| {
            let f = out.recognition.feature(w.id)?;
            let m = f.mid_surface.as_ref()?;
            let shape = match m.radius {
                Some(r) => format!("{} r {r:.2} mm", m.kind),
                None => m.kind.clone(),
            };
            Some(format!(
                "{}: curved wall ({shape}): sequenced and sized; step-approach layers are \
                 designed on flat walls only, so its material stays in bulk features",
                w.id
            ))
        })
        .collect()
}

/// Layer constraints: consecutive steps of one wall, and for every
/// stiffness constraint `A before B` the last step of A before the first
/// of B.
fn layer_constraints(layers: &[steps::Layer], seq: &[Constraint]) -> Vec<LayerConstraint> {
    let mut out = Vec::new();
    for w in layers.windows(2) {
        if w[0].owner == w[1].owner {
            out.push(LayerConstraint {
                before: w[0].id.clone(),
                after: w[1].id.clone(),
                why: format!("{} step approach", w[0].owner),
            });
        }
    }
    for c in seq.iter().filter(|c| c.relation == Relation::Before) {
        let last = layers.iter().rev().find(|l| l.owner == c.before);
        let first = layers.iter().find(|l| l.owner == c.after);
        if let (Some(a), Some(b)) = (last, first) {
            out.push(LayerConstraint {
                before: a.id.clone(),
                after: b.id.clone(),
                why: sequence::describe(c),
            });
        }
    }
    out
}

/// The sizing parameters of a wall milled `milling` under the
/// recognition's settings (force, material, deflection, tool).
pub fn sizing_parameters(milling: Milling, cfg: &thinwall_recognize::Config) -> SizingParameters {
    let mut p = SizingParameters::defaults(milling);
    p.force_n = cfg.thinness.force_n;
    p.youngs_modulus_n_mm2 = cfg.thinness.youngs_modulus_n_mm2;
    p.allowed_deflection_mm = cfg.thinness.allowed_deflection_mm;
    p.effective_length_factor = cfg.thinness.effective_length_factor;
    p.tool_diameter_mm = cfg.thresholds.preferred_tool_diameter_mm;
    if milling == Milling::Face {
        p.cut_height_mm = 0.5 * p.tool_diameter_mm + 1.0;
    }
    p
}

/// Why a plan cannot be made (a removal that cannot be decomposed is not
/// one: the plan says so in its `removal` and keeps the rest).
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum PlanError {
    /// The sizing parameters the recognition settings give (force, Young's
    /// modulus, allowed deflection, preferred tool) are out of range.
    #[error("sizing wall {wall}: {source} (from the recognition settings)")]
    Sizing {
        wall: thinwall_analysis::FeatureId,
        source: SizingError,
    },
}

impl PlanError {
    pub fn code(&self) -> String {
        match self {
            PlanError::Sizing { source, .. } => source.code().to_string(),
        }
    }
}

/// How deep a layer beside each thin wall of `out` standing along its
/// set-up's up may be cut ([`StepLimit`]): the operations planner's levels
/// keep to them.
pub fn step_limits(out: &Outcome) -> Result<Vec<StepLimit>, PlanError> {
    Ok(limits::step_limits(out, &wall_plans(out)?))
}

/// Sizes for every thin wall with a length, thickness and height. A wall
/// the recognizer gave no positive size has nothing to size and is left
/// out; parameters out of range are an error.
fn wall_plans(out: &Outcome) -> Result<Vec<WallPlan>, PlanError> {
    let mut plans = Vec::new();
    for f in out
        .recognition
        .features
        .iter()
        .filter(|f| f.kind.is_wall() && f.thin == Some(true))
    {
        let (Some(length), Some(thickness), Some(height)) = (f.length, f.thickness, f.height)
        else {
            continue;
        };
        let w = WallDimensions {
            length,
            thickness,
            height,
        };
        let milling = if f.kind == StiffnessKind::Web {
            Milling::Face
        } else {
            Milling::Peripheral
        };
        let sizes = match size_wall(&w, &sizing_parameters(milling, &out.request.config)) {
            Ok(sizes) => sizes,
            Err(SizingError::Dimension { .. }) => continue,
            Err(source) => return Err(PlanError::Sizing { wall: f.id, source }),
        };
        plans.push(WallPlan {
            id: f.id,
            kind: f.kind,
            sizes,
        });
    }
    Ok(plans)
}

/// Plan the pipeline's outcome on the analysed part with `rules` (`out`
/// is the recognition of `analysis`'s part in its set-up).
pub fn plan(
    file: &str,
    analysis: &PartAnalysis,
    out: &Outcome,
    rules: &RuleSet,
) -> Result<Plan, PlanError> {
    plan_in_turn(file, analysis, out, rules, None)
}

/// [`plan`] of one set-up of several planned in turn (`turn`; none: the
/// only set-up): the blocks the earlier set-ups took are no features of
/// this one, and a thin web with material still under it gets no step
/// layers here ([`turn::supported_webs`]).
pub fn plan_in_turn(
    file: &str,
    analysis: &PartAnalysis,
    out: &Outcome,
    rules: &RuleSet,
    turn: Option<&InTurn>,
) -> Result<Plan, PlanError> {
    let part = analysis.part();
    let scene = Scene::of(part, out);
    let seq = sequence(&scene, rules);
    let mut walls = wall_plans(out)?;
    let faces = adapt::Faces::new(part);
    let (shapes, mut adaptations) = adapt::shapes(&faces, out, &scene, &mut walls);
    let supported = turn.map(|t| turn::supported_webs(out, &walls, t));
    let supported = supported.unwrap_or_default();
    let layered: Vec<WallPlan> = walls
        .iter()
        .filter(|w| !supported.contains(&w.id))
        .cloned()
        .collect();
    let layers = steps::layers(out, &scene, &seq, &layered, &shapes);
    let limits = limits(out, &walls);
    let layer_sequence = layer_constraints(&layers, &seq.constraints);
    let splits = adapt::hole_splits(&faces, out, &walls, &shapes);
    let earlier = turn.map_or(&[][..], |t| t.earlier);
    let this = turn.map(|t| t.this);
    let (removal, mut machining_features, frame) =
        whole::removal_plan(analysis, out, &layers, &splits, (this, earlier));
    let adapted = adapt::relations(
        &faces,
        out,
        &walls,
        &shapes,
        &layers,
        &machining_features,
        &mut adaptations,
    );
    let relations: Vec<LayerConstraint> = layer_sequence.iter().cloned().chain(adapted).collect();
    let feature_sequence = feature_order::order(&machining_features, &relations);
    classified::classify_features(analysis, &frame, &mut machining_features, &feature_sequence);
    Ok(Plan {
        schema: PLAN_SCHEMA.to_string(),
        thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
        file: file.to_string(),
        up: out.setup.up,
        rules: rules.source.clone(),
        stiffness_features: planned_features(out, &scene),
        connections: out.structure.connections.clone(),
        sequence: seq.constraints.clone(),
        rejected: seq.rejected.clone(),
        order: seq.order.clone(),
        walls,
        adaptations,
        layers,
        layer_sequence,
        removal,
        frame,
        machining_features,
        feature_sequence,
        limits,
        supported_webs: supported.into_iter().collect(),
        then: Vec::new(),
        residue: None,
        proposal: None,
        opencascade_faces: if earlier.is_empty() {
            analysis.part().occ_faces()
        } else {
            Vec::new()
        },
        queries: seq,
    })
}

/// Every stiffness feature with its top in the set-up.
fn planned_features(out: &Outcome, scene: &Scene) -> Vec<PlannedFeature> {
    out.recognition
        .features
        .iter()
        .zip(&scene.facts)
        .map(|(f, fact)| PlannedFeature {
            id: f.id,
            kind: f.kind,
            thin: f.thin,
            top: fact.top,
        })
        .collect()
}
