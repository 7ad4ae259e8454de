//! One function per command: a checked request in, a typed result out.
//! Each runs on the study's analysis of its set-up and on results the
//! study already holds; none builds an analysis or a mesh of its own.

use crate::request::{
    AccessRequest, ClassifyRequest, OperationsRequest, PlanRequest, RecognizeRequest,
    SizeWallRequest,
};
use crate::{contained, AtSetup, Study, StudyError};
use std::path::Path;
use std::sync::Arc;
use thinwall_access::reach::{self, ReachOptions};
use thinwall_analysis::Setup;
use thinwall_ops::OpsError;
use thinwall_pipeline::{MachiningRequest, Outcome, PipelineError};
use thinwall_plan::{Plan, RuleSet};
use thinwall_report::access::{AccessReport, ReachResult, ReachSettings};
use thinwall_report::operations::{LaterSetup, OperationsReport};
use thinwall_report::{ClassificationReport, InspectReport, RecognitionReport};
use thinwall_setups::turn as sequence;

/// `inspect`: the part's bodies, faces, edges and convexity.
pub struct Inspected<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub report: InspectReport,
}

/// `recognize`: the outcome and its report.
pub struct Recognized<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub outcome: Arc<Outcome>,
    pub report: RecognitionReport,
    /// Seconds per stage: the analysis, then the pipeline's.
    pub timings: Vec<(&'static str, f64)>,
}

/// `plan`: the recognition it planned and the plan (of the first set-up;
/// the later set-ups' plans are its `then`).
pub struct Planned<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub outcome: Arc<Outcome>,
    pub plan: Arc<Plan>,
    /// Each later set-up's analysis and recognition, in the order of
    /// `plan.then`.
    pub later: Vec<(Arc<AtSetup<'p>>, Arc<Outcome>)>,
}

/// `access`: flank milling and reach of every face.
pub struct Accessed<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub report: AccessReport,
}

/// `operations`: a set-up's operations.
pub struct Operated<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub report: OperationsReport,
}

/// `classify`: each volume's type and the faces it touches, with the
/// volumes (for pictures).
pub struct Classified<'p> {
    pub at: Arc<AtSetup<'p>>,
    pub report: ClassificationReport,
    pub volumes: Vec<thinwall_classify::Volume>,
}

/// A recognition failure of this study's part.
fn recognition(study: &Study, source: PipelineError) -> StudyError {
    StudyError::Recognition {
        file: study.name().to_string(),
        source,
    }
}

pub fn inspect<'p>(study: &Study<'p>) -> Result<Inspected<'p>, StudyError> {
    contained("inspect", study.name(), || {
        let at = study.at(&Setup::default())?;
        let loaded = study.loaded();
        let report = thinwall_report::inspect(&loaded.name, &at.analysis, &loaded.read);
        Ok(Inspected { at, report })
    })
}

pub fn recognize<'p>(
    study: &Study<'p>,
    req: &RecognizeRequest,
) -> Result<Recognized<'p>, StudyError> {
    contained("recognize", study.name(), || {
        req.check().map_err(StudyError::Request)?;
        let at = study.at(&req.setup)?;
        let outcome = at.outcome(req).map_err(|e| recognition(study, e))?;
        let loaded = study.loaded();
        let report = thinwall_report::recognition_report(&loaded.name, &loaded.part, &outcome)
            .with_read(&loaded.read);
        let mut timings = vec![("analysis", at.built_seconds)];
        timings.extend(outcome.timings.iter().copied());
        Ok(Recognized {
            at,
            outcome,
            report,
            timings,
        })
    })
}

pub fn plan<'p>(study: &Study<'p>, req: &PlanRequest) -> Result<Planned<'p>, StudyError> {
    plan_observed(study, req, &|_| {})
}

/// [`plan`], calling `stage` with what it does as each stage of set-ups
/// in turn begins (proposing them, recognizing and planning each: a host
/// shows it, the stages take minutes on large parts).
pub fn plan_observed<'p>(
    study: &Study<'p>,
    req: &PlanRequest,
    stage: &dyn Fn(&str),
) -> Result<Planned<'p>, StudyError> {
    contained("plan", study.name(), || {
        req.check()?;
        if req.several() {
            return plan_in_turn(study, req, stage);
        }
        let at = study.at(&req.recognize.setup)?;
        let outcome = at
            .outcome(&req.recognize)
            .map_err(|e| recognition(study, e))?;
        let plan = at.plan(study.name(), &req.recognize, &req.rules)?;
        Ok(Planned {
            at,
            outcome,
            plan,
            later: Vec::new(),
        })
    })
}

/// Several set-ups planned in turn: each set-up recognized along its up
/// with the request's settings, its plan over what the set-ups before it
/// left. When the set-ups' removals cannot be made (a face no graph along
/// a given up), the first set-up is planned alone and its removal says
/// why.
fn plan_in_turn<'p>(
    study: &Study<'p>,
    req: &PlanRequest,
    stage: &dyn Fn(&str),
) -> Result<Planned<'p>, StudyError> {
    let first = study.at(&req.recognize.setup)?;
    let ups: Vec<[f64; 3]> = std::iter::once(req.recognize.setup.up)
        .chain(req.later_ups.iter().copied())
        .collect();
    stage(setups_stage(req.propose));
    let Ok((proposal, mut removals)) = thinwall_setups::setups(&first.analysis, &ups, req.propose)
    else {
        return plan(
            study,
            &PlanRequest::new(req.recognize.clone(), req.rules.clone()),
        );
    };
    sequence::in_turn(&mut removals);
    let residue = sequence::residue(&removals);
    stage(&setups_planned(removals.len()));
    // Each set-up's plan needs the removals alone, so they are planned on
    // the first set-up's threads.
    let order: Vec<usize> = (0..removals.len()).collect();
    let plans = first.analysis.work().map(&order, |&k| {
        let recognize = RecognizeRequest {
            setup: setup_along(&req.recognize.setup, &removals[k]),
            ..req.recognize.clone()
        };
        let at = study.at(&recognize.setup)?;
        let outcome = at.outcome(&recognize).map_err(|e| recognition(study, e))?;
        let turn = thinwall_plan::InTurn {
            this: &removals[k],
            earlier: &removals[..k],
        };
        let plan = thinwall_plan::plan_in_turn(
            study.name(),
            &at.analysis,
            &outcome,
            &req.rules,
            Some(&turn),
        )?;
        Ok::<_, StudyError>((at, outcome, plan))
    });
    let mut plans = plans
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?
        .into_iter();
    let (at, outcome, mut plan) = plans.next().expect("a set-up at least");
    let later: Vec<_> = plans.collect();
    plan.then = later.iter().map(|(_, _, p)| p.clone()).collect();
    plan.residue = Some(residue);
    plan.proposal = proposal;
    Ok(Planned {
        at,
        outcome,
        plan: Arc::new(plan),
        later: later.into_iter().map(|(a, o, _)| (a, o)).collect(),
    })
}

/// What set-ups in turn do first.
fn setups_stage(propose: bool) -> &'static str {
    if propose {
        "proposing set-ups"
    } else {
        "the set-ups' removals"
    }
}

/// The plans of `n` set-ups begin.
fn setups_planned(n: usize) -> String {
    format!("planning {n} set-up(s)")
}

/// Set-up `k` (of `n`) along `up` begins.
fn setup_stage(k: usize, n: usize, up: &[f64; 3]) -> String {
    format!(
        "set-up {} of {n}, up ({:.3}, {:.3}, {:.3})",
        k + 1,
        up[0],
        up[1],
        up[2]
    )
}

/// `base` with its up along removal `r`'s (+ 0.0: no negative zeros in a
/// report).
fn setup_along(base: &Setup, r: &thinwall_plan::removal::Removal) -> Setup {
    let z = r.frame.z;
    Setup {
        up: [z.x + 0.0, z.y + 0.0, z.z + 0.0],
        ..base.clone()
    }
}

/// Write each machining feature of `plan` as a STEP solid (`V1.step`, …)
/// into `dir`, and those of each later set-up (`plan.then`) into
/// `dir/setup-2`, …; the number of solids not written (bounded by a
/// cylinder or a cone: their volumes are in the plan).
pub fn write_volumes(plan: &Plan, dir: &Path) -> Result<usize, StudyError> {
    let mut skipped = write_setup_volumes(plan, dir)?;
    for (k, later) in plan.then.iter().enumerate() {
        skipped += write_setup_volumes(later, &dir.join(format!("setup-{}", k + 2)))?;
    }
    Ok(skipped)
}

/// [`write_volumes`] of one set-up's plan.
fn write_setup_volumes(plan: &Plan, dir: &Path) -> Result<usize, StudyError> {
    let io = |p: &Path, e: std::io::Error| StudyError::Io {
        path: p.display().to_string(),
        message: e.to_string(),
    };
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let mut skipped = 0;
    for f in &plan.machining_features {
        let (text, missing) = thinwall_plan::volumes::feature_step(plan, f);
        skipped += missing;
        if missing == f.solids.len() {
            continue;
        }
        let path = dir.join(format!("{}.step", f.id));
        std::fs::write(&path, text).map_err(|e| io(&path, e))?;
    }
    Ok(skipped)
}

pub fn access<'p>(study: &Study<'p>, req: &AccessRequest) -> Result<Accessed<'p>, StudyError> {
    access_observed(study, req, |_, _| {})
}

/// [`access`], calling `done(faces done, faces)` as the reach of each face
/// is judged (it takes minutes on large parts: a host shows progress).
pub fn access_observed<'p>(
    study: &Study<'p>,
    req: &AccessRequest,
    done: impl Fn(usize, usize) + Sync,
) -> Result<Accessed<'p>, StudyError> {
    contained("access", study.name(), || {
        req.check()?;
        let at = study.at(req.setup())?;
        let a = &at.analysis;
        let faces = thinwall_access::flank_milling(a, a.mesh(), &req.flank());
        let opts = ReachOptions {
            tool: req.tool.clone(),
            machine: req.setup().machine,
            largest_tool: true,
        };
        let reached = reach::reach_observed(a, a.mesh(), &opts, |_| true, done)?;
        let outcome = at.outcome(&req.walls).map_err(|e| recognition(study, e))?;
        let reach = ReachResult::new(a, reached, &outcome, req.tool.diameter);
        let settings = ReachSettings {
            tool: req.tool.clone(),
            machine: req.setup().machine,
        };
        let mut report = AccessReport::new(
            study.name(),
            req.setup().up,
            req.flank(),
            faces,
            settings,
            reach,
        );
        report.opencascade_faces = study.loaded().part.occ_faces();
        Ok(Accessed { at, report })
    })
}

pub fn operations<'p>(
    study: &Study<'p>,
    req: &OperationsRequest,
) -> Result<Operated<'p>, StudyError> {
    operations_observed(study, req, &|_| {})
}

/// [`operations`], calling `stage` as each stage of set-ups in turn
/// begins (as [`plan_observed`]).
pub fn operations_observed<'p>(
    study: &Study<'p>,
    req: &OperationsRequest,
    stage: &dyn Fn(&str),
) -> Result<Operated<'p>, StudyError> {
    contained("operations", study.name(), || {
        req.check()?;
        if req.several() {
            return in_turn(study, req, stage);
        }
        let at = study.at(&req.setup)?;
        let a = &at.analysis;
        req.check_for_part(a.bounding_box().diagonal())?;
        // The holes are the machining features found in this set-up.
        let holes = found_in_setup(study, &at, &req.setup)?;
        let (frame, ops) = if req.by_feature {
            let recognize = RecognizeRequest {
                setup: req.setup.clone(),
                ..Default::default()
            };
            let plan = at.plan(study.name(), &recognize, &RuleSet::default_rules())?;
            thinwall_ops::setup::along_plan(
                a,
                &plan,
                &holes.machining,
                &req.tools,
                req.axial_depth,
            )?
        } else {
            let limits = thinwall_plan::step_limits(&holes)?;
            thinwall_ops::plan_setup(a, &holes.machining, &req.tools, req.axial_depth, &limits)?
        };
        let mut report =
            OperationsReport::new(study.name(), req.setup.up, &frame, req.tools.clone(), ops);
        report.opencascade_faces = study.loaded().part.occ_faces();
        Ok(Operated { at, report })
    })
}

/// Several set-ups in turn: each set-up's stock what those before it
/// left, each hole drilled in the first set-up that drills it, what none
/// reaches the residue.
fn in_turn<'p>(
    study: &Study<'p>,
    req: &OperationsRequest,
    stage: &dyn Fn(&str),
) -> Result<Operated<'p>, StudyError> {
    let first = study.at(&req.setup)?;
    req.check_for_part(first.analysis.bounding_box().diagonal())?;
    let mut ups = vec![req.setup.up];
    if req.both_sides {
        ups.push(req.setup.up.map(|c| -c));
    }
    ups.extend(&req.later_ups);
    if req.by_feature {
        return along_plans(study, req, ups, stage);
    }
    stage(setups_stage(req.choose_up));
    let (proposal, mut removals) =
        thinwall_setups::proposal::setups(&first.analysis, &ups, req.choose_up)
            .map_err(OpsError::from)?;
    let recut = sequence::in_turn(&mut removals);
    let residue = sequence::residue(&removals);
    let mut drilled: Vec<u64> = Vec::new();
    let mut sheets = Vec::new();
    for (k, (r, recut)) in removals.iter().zip(recut).enumerate() {
        let setup = setup_along(&req.setup, r);
        stage(&setup_stage(k, removals.len(), &setup.up));
        let at = study.at(&setup)?;
        let holes = found_in_setup(study, &at, &setup)?;
        let limits = thinwall_plan::step_limits(&holes)?;
        let (ops, here) = thinwall_ops::setup::plan_in_turn(
            &at.analysis,
            r,
            &holes.machining,
            &drilled,
            &req.tools,
            req.axial_depth,
            &limits,
        )?;
        drilled.extend(here);
        let ops = thinwall_ops::operations::SetupOperations {
            recut_mm3: recut,
            ..ops
        };
        sheets.push((at, setup.up, r.frame, ops));
    }
    let at = sheets[0].0.clone();
    let sheets = sheets
        .into_iter()
        .map(|(_, up, frame, ops)| (up, frame, ops));
    let report = report_of(study, req, sheets, Some(residue), proposal);
    Ok(Operated { at, report })
}

/// The operations report of set-ups in turn: each set-up's up, removal
/// frame and operations, the first's first.
fn report_of(
    study: &Study<'_>,
    req: &OperationsRequest,
    mut sheets: impl Iterator<
        Item = (
            [f64; 3],
            thinwall_geom::Frame,
            thinwall_ops::operations::SetupOperations,
        ),
    >,
    residue: Option<thinwall_setups::Residue>,
    proposal: Option<thinwall_setups::Proposal>,
) -> OperationsReport {
    let (up, frame, ops) = sheets.next().expect("a set-up at least");
    let mut report = OperationsReport::new(study.name(), up, &frame, req.tools.clone(), ops);
    report.then = sheets
        .map(|(up, frame, ops)| LaterSetup::new(up, &frame, ops))
        .collect();
    report.residue = residue;
    report.proposal = proposal;
    report.opencascade_faces = study.loaded().part.occ_faces();
    report
}

/// Several set-ups in turn along their plans ([`plan_in_turn`]): each
/// machining feature of each set-up's plan layered and tooled on its own,
/// in an order that keeps the plan's relations; each hole drilled in the
/// first set-up that drills it.
fn along_plans<'p>(
    study: &Study<'p>,
    req: &OperationsRequest,
    ups: Vec<[f64; 3]>,
    stage: &dyn Fn(&str),
) -> Result<Operated<'p>, StudyError> {
    let recognize = RecognizeRequest {
        setup: req.setup.clone(),
        ..Default::default()
    };
    let mut plan_req = PlanRequest::new(recognize, RuleSet::default_rules());
    plan_req.later_ups = ups[1..].to_vec();
    plan_req.propose = req.choose_up;
    let planned = plan_in_turn(study, &plan_req, stage)?;
    let ats = std::iter::once(&planned.at).chain(planned.later.iter().map(|(a, _)| a));
    let plans = std::iter::once(planned.plan.as_ref()).chain(&planned.plan.then);
    let mut drilled: Vec<u64> = Vec::new();
    let mut sheets = Vec::new();
    for (at, plan) in ats.zip(plans) {
        let setup = Setup {
            up: plan.up,
            ..req.setup.clone()
        };
        let holes = found_in_setup(study, at, &setup)?;
        let (ops, here) = thinwall_ops::setup::along_plan_in_turn(
            &at.analysis,
            plan,
            &holes.machining,
            &drilled,
            &req.tools,
            req.axial_depth,
        )?;
        drilled.extend(here);
        sheets.push((plan.up, plan.removal_frame(), ops));
    }
    let report = report_of(
        study,
        req,
        sheets.into_iter(),
        planned.plan.residue.clone(),
        planned.plan.proposal.clone(),
    );
    Ok(Operated {
        at: planned.at.clone(),
        report,
    })
}

/// The recognition with the machining features found in `setup` (its up
/// the tool axis): the holes operations drill.
fn found_in_setup(
    study: &Study<'_>,
    at: &AtSetup<'_>,
    setup: &Setup,
) -> Result<Arc<Outcome>, StudyError> {
    let in_setup = RecognizeRequest {
        setup: setup.clone(),
        allow_open: true,
        machining: MachiningRequest {
            in_setup: true,
            ..Default::default()
        },
        ..Default::default()
    };
    at.outcome(&in_setup).map_err(|e| recognition(study, e))
}

pub fn classify<'p>(study: &Study<'p>, req: ClassifyRequest) -> Result<Classified<'p>, StudyError> {
    contained("classify", study.name(), || {
        req.check()?;
        let at = study.at(&req.setup)?;
        let result = thinwall_classify::classify(&thinwall_classify::Request {
            part: &at.analysis,
            volumes: &req.volumes,
            before: &req.before,
            together: &[],
            priority: vec![],
        })?;
        let mut report = ClassificationReport::new(study.name(), req.setup.up, &req.before, result);
        report.opencascade_faces = study.loaded().part.occ_faces();
        Ok(Classified {
            at,
            report,
            volumes: req.volumes,
        })
    })
}

/// `size-wall`: B_RF, h_RF and H_RF of a thin wall (no part needed).
pub fn size_wall(req: &SizeWallRequest) -> Result<thinwall_plan::Sizes, StudyError> {
    contained("size-wall", "size-wall", || {
        Ok(thinwall_plan::size_wall(&req.wall, &req.parameters)?)
    })
}
