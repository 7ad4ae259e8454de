//! Operations by the part's radii and holes' stages (issue 38), on the
//! generated pocketed panels and holes with their truth, as built and
//! turned:
//! - every pocket the set-up's tool enters (both sides of a web, each from
//!   its own up) is finished by its radii: its corner radius and floor
//!   fillet within 1e-6 of the truth; its corners by a tool no wider than
//!   twice their radius and its floor fillet by a cutter whose corner
//!   radius does not exceed it, or a rest of that cause with its area;
//!   the tools' operations (`finish_radii`) name it and come after the
//!   milling of its depth;
//! - every hole's countersink and chamfered entry is cut by a countersink
//!   of its angle at least as wide, after the hole's drilling; an exit
//!   chamfer and a blended edge are named with why no tool makes them;
//!   a counterbore's wider bore is never drilled (a point would cone its
//!   shoulder); a drilled bore is spotted first;
//! - the same tools, rests and stages on a turned copy.
//!
//! `THINWALL_POCKETS_DIR` / `THINWALL_HOLES_DIR` run the same checks on
//! held-out generated parts.

mod common;

use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_ops::drilling::DrillKind;
use thinwall_ops::finishing::{radius_finishes, RadiusFinish, RestCause};
use thinwall_ops::hole_stages::HoleStep;
use thinwall_ops::operations::{SetupOperations, Stage};
use thinwall_ops::ToolLibrary;

const TOL: f64 = 1e-6;

#[derive(serde::Deserialize)]
struct Pockets {
    pockets: Vec<Pocket>,
}

#[derive(serde::Deserialize)]
struct Pocket {
    side: f64,
    corner_radius: f64,
    floor_fillet: f64,
}

/// The operations of `text` (turned by `seed`) in the set-up whose up is
/// `up` as built.
fn operations(text: &str, seed: Option<u64>, up: [f64; 3]) -> Result<SetupOperations, String> {
    let (part, up) = posed(text, seed, up);
    let a = PartAnalysis::new(&part, Setup::new(up, Machine::ThreeAxis).unwrap());
    let features = common::features_in_setup(&a);
    thinwall_ops::plan_setup(&a, &features, &ToolLibrary::default_tools(), None, &[])
        .map(|(_, ops)| ops)
        .map_err(|e| e.code())
}

/// The finishes by radii of `text` (turned by `seed`) in the set-up whose
/// up is `up` as built, without operations.
fn finishes(text: &str, seed: Option<u64>, up: [f64; 3]) -> Vec<RadiusFinish> {
    let (part, up) = posed(text, seed, up);
    let a = PartAnalysis::new(&part, Setup::new(up, Machine::ThreeAxis).unwrap());
    let features = common::features_in_setup(&a);
    let frame = thinwall_removal::frame_of(&a, a.up()).0;
    radius_finishes(&a, &features, &frame, &ToolLibrary::default_tools())
}

/// The part of `text` turned by `seed`, and `up` turned with it.
fn posed(text: &str, seed: Option<u64>, up: [f64; 3]) -> (thinwall_brep::Part, [f64; 3]) {
    let posed = common::posed_step(text, seed);
    let part = thinwall_step::read_bytes(posed.as_bytes(), "posed")
        .unwrap()
        .0;
    let up = match seed {
        Some(s) => {
            let (r, _) = common::rigid_motion(s);
            let u = r * nalgebra::Vector3::new(up[0], up[1], up[2]);
            [u.x, u.y, u.z]
        }
        None => up,
    };
    (part, up)
}

/// What a pocketed panel's finishing by radii came to, pose-free: per
/// finished feature (corner radius, fillet, walls tool, corners tool,
/// rests' causes).
type Radii = Vec<(
    String,
    String,
    Option<String>,
    Option<String>,
    Vec<RestCause>,
)>;

fn summary(finishes: &[RadiusFinish]) -> Radii {
    let mm = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.6}"));
    let mut v: Radii = finishes
        .iter()
        .map(|f| {
            (
                mm(f.corner_radius_mm),
                mm(f.floor_fillet_mm),
                f.walls.clone(),
                f.corners.clone(),
                f.rest.iter().map(|r| r.cause).collect(),
            )
        })
        .collect();
    v.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    v
}

/// Check one panel's pockets facing `side` against their truth; returns
/// (pockets checked, errors).
fn pocket_errors(
    ops: &SetupOperations,
    truth: &Pockets,
    side: f64,
    what: &str,
) -> (usize, Vec<String>) {
    let lib = ToolLibrary::default_tools();
    let tool = |n: &str| lib.tools.iter().find(|t| t.name == n).unwrap().clone();
    let mut errors = Vec::new();
    let mut checked = 0;
    for p in truth.pockets.iter().filter(|p| p.side == side) {
        let Some(f) = ops.radius_finishes.iter().find(|f| {
            f.corner_radius_mm
                .is_some_and(|r| (r - p.corner_radius).abs() <= TOL)
        }) else {
            errors.push(format!(
                "{what}: no finish for the pocket of R {}",
                p.corner_radius
            ));
            continue;
        };
        checked += 1;
        if f.floor_fillet_mm
            .is_none_or(|r| (r - p.floor_fillet).abs() > TOL)
        {
            errors.push(format!(
                "{what}: {} fillet {:?} vs {}",
                f.feature, f.floor_fillet_mm, p.floor_fillet
            ));
        }
        let rest = |c: RestCause| f.rest.iter().find(|r| r.cause == c);
        match &f.corners {
            Some(t) if tool(t).diameter_mm > 2.0 * p.corner_radius + TOL => {
                errors.push(format!(
                    "{what}: {} corners R {} by {t}",
                    f.feature, p.corner_radius
                ));
            }
            None if rest(RestCause::Corner).is_none_or(|r| r.area_mm2 <= 0.0) => {
                errors.push(format!(
                    "{what}: {} corners: no tool and no rest",
                    f.feature
                ));
            }
            _ => {}
        }
        match &f.walls {
            Some(t)
                if tool(t).corner_radius_mm > p.floor_fillet + TOL
                    && rest(RestCause::FloorFillet).is_none_or(|r| r.area_mm2 <= 0.0) =>
            {
                errors.push(format!(
                    "{what}: {} fillet r {} by {t}, no rest",
                    f.feature, p.floor_fillet
                ));
            }
            None => errors.push(format!("{what}: {} no walls tool", f.feature)),
            _ => {}
        }
        // Its operations name it, after the milling of its depth.
        for t in [&f.walls, &f.corners].into_iter().flatten() {
            let Some(op) = ops.operations.iter().find(|o| {
                o.stage == Stage::FinishRadii && &o.tool == t && o.finishes.contains(&f.feature)
            }) else {
                errors.push(format!("{what}: {} no operation of {t}", f.feature));
                continue;
            };
            let milled = ops.operations.iter().filter(|o| {
                o.stage.clears() && o.z_bottom_mm < f.z_top_mm && o.z_top_mm > f.z_bottom_mm
            });
            for m in milled {
                if !op.after.contains(&m.step) || m.step >= op.step {
                    errors.push(format!(
                        "{what}: {} step {} not after {}",
                        f.feature, op.step, m.step
                    ));
                }
            }
        }
    }
    (checked, errors)
}

fn pocket_parts() -> Vec<std::path::PathBuf> {
    common::generated_parts("THINWALL_POCKETS_DIR", "pockets")
}

#[test]
fn pockets_are_finished_by_their_radii_in_any_pose() {
    let (mut checked, mut errors, mut refused) = (0, Vec::new(), Vec::new());
    let (mut rests, mut bull_noses) = (0, 0);
    for path in pocket_parts() {
        let text = std::fs::read_to_string(&path).unwrap();
        let truth: Pockets = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        for side in [1.0, -1.0] {
            if !truth.pockets.iter().any(|p| p.side == side) {
                continue;
            }
            let what = format!("{} from {side}", path.display());
            let built = match operations(&text, None, [0.0, 0.0, side]) {
                Ok(o) => o,
                Err(code) => {
                    // The removal engine's own gap, named by its code.
                    assert_eq!(code, "removal.inconsistent", "{what}");
                    refused.push(what);
                    continue;
                }
            };
            let (n, e) = pocket_errors(&built, &truth, side, &what);
            checked += n;
            errors.extend(e);
            rests += built
                .radius_finishes
                .iter()
                .map(|f| f.rest.len())
                .sum::<usize>();
            bull_noses += built
                .radius_finishes
                .iter()
                .filter(|f| f.walls.as_deref().is_some_and(|t| t.starts_with("BN")))
                .count();
            // Turned, the finishes themselves (they need no removal: a
            // turned copy's removal may not add up, the engine's own gap).
            let turned = finishes(&text, Some(7), [0.0, 0.0, side]);
            if summary(&turned) != summary(&built.radius_finishes) {
                errors.push(format!(
                    "{what}: turned {:?} vs built {:?}",
                    summary(&turned),
                    summary(&built.radius_finishes)
                ));
            }
        }
    }
    eprintln!(
        "RADII {checked} pockets finished by their radii ({bull_noses} by a bull-nose, {rests} rests), {} set-ups refused ({refused:?}), {} errors",
        refused.len(),
        errors.len()
    );
    assert!(errors.is_empty(), "{errors:#?}");
    assert!(checked >= 20, "{checked}");
    // pockets_3 (tori only): its removal is 0.4–0.6 mm³ off, over 1e-6 of
    // its stock (the removal engine's open item).
    assert!(refused.len() <= 2, "{refused:?}");
}

#[derive(serde::Deserialize)]
struct Holes {
    upright: bool,
    holes: Vec<Hole>,
}

#[derive(serde::Deserialize)]
struct Hole {
    kind: String,
    bores: Vec<TruthBore>,
    entry: Option<End>,
    exit: Option<End>,
}

#[derive(serde::Deserialize)]
struct TruthBore {
    diameter: f64,
}

#[derive(serde::Deserialize)]
struct End {
    kind: String,
    angle_deg: Option<f64>,
    diameter: Option<f64>,
}

/// Pose-free: every stage (step, at exit, angle, diameter, tool).
fn stages_summary(ops: &SetupOperations) -> Vec<String> {
    let mut v: Vec<String> = ops
        .hole_stages
        .iter()
        .map(|s| {
            format!(
                "{:?} {} {:?} {:.6} {:?}",
                s.step,
                s.at_exit,
                s.angle_deg.map(|a| format!("{a:.6}")),
                s.diameter_mm,
                s.tool
            )
        })
        .collect();
    v.sort();
    v
}

#[test]
fn holes_get_their_spot_countersink_and_chamfer_in_any_pose() {
    let lib = ToolLibrary::default_tools();
    let (mut cones, mut named, mut errors) = (0, 0, Vec::new());
    for path in common::generated_parts("THINWALL_HOLES_DIR", "holes") {
        let truth: Holes = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        if truth.upright {
            // Holes across up: another set-up's.
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let what = path.display().to_string();
        let ops = operations(&text, None, [0.0, 0.0, 1.0]).unwrap();
        for h in &truth.holes {
            let ends = [(h.entry.as_ref(), false), (h.exit.as_ref(), true)];
            for (end, at_exit) in ends {
                let Some(e) = end else { continue };
                let want = e.diameter.unwrap_or(0.0);
                let stage = ops.hole_stages.iter().find(|s| {
                    s.at_exit == at_exit
                        && match e.kind.as_str() {
                            "countersink" => s.step == HoleStep::Countersink,
                            "chamfer" => s.step == HoleStep::Chamfer,
                            _ => s.step == HoleStep::Blend,
                        }
                        && (e.kind == "blend" || (s.diameter_mm - want).abs() <= TOL)
                });
                let Some(s) = stage else {
                    errors.push(format!("{what}: {} {} end: no stage", h.kind, e.kind));
                    continue;
                };
                if at_exit || e.kind == "blend" {
                    named += usize::from(s.tool.is_none() && s.missing.is_some());
                    if s.tool.is_some() {
                        errors.push(format!(
                            "{what}: {} {} end made by {:?}",
                            h.kind, e.kind, s.tool
                        ));
                    }
                    continue;
                }
                let angle = e.angle_deg.unwrap();
                let Some(t) = s
                    .tool
                    .as_deref()
                    .and_then(|n| lib.tools.iter().find(|t| t.name == n))
                else {
                    errors.push(format!(
                        "{what}: {} {} end: no tool ({:?})",
                        h.kind, e.kind, s.missing
                    ));
                    continue;
                };
                if t.point_angle_deg.is_none_or(|p| (p - angle).abs() > 0.5) || t.diameter_mm < want
                {
                    errors.push(format!(
                        "{what}: {} cone {angle}° Ø{want} by {}",
                        h.kind, t.name
                    ));
                }
                // Its operation comes after the hole's drilling.
                let op = ops.operations.iter().find(|o| {
                    o.tool == t.name
                        && o.holes.contains(&s.hole)
                        && matches!(o.drill, Some(DrillKind::Countersink | DrillKind::Chamfer))
                });
                let bores = ops.operations.iter().filter(|o| {
                    o.stage == Stage::Drill
                        && o.drill.is_some_and(|d| !d.is_stage())
                        && o.holes
                            .iter()
                            .any(|x| x == &s.hole || x.starts_with(&format!("{}.", s.hole)))
                });
                match op {
                    Some(op) => {
                        for b in bores {
                            if !op.after.contains(&b.step) {
                                errors.push(format!("{what}: {} cone before its bore", h.kind));
                            }
                        }
                    }
                    None => errors.push(format!("{what}: {} cone: no operation", h.kind)),
                }
                cones += 1;
            }
        }
        // A counterbore's flat shoulder is never a drill's point.
        for h in truth.holes.iter().filter(|h| h.kind == "counterbore") {
            let wide = h.bores[0].diameter;
            match ops
                .holes
                .iter()
                .find(|s| (s.diameter_mm - wide).abs() <= TOL)
            {
                Some(site) if matches!(site.kind, DrillKind::Counterbore | DrillKind::Helical) => {}
                other => errors.push(format!(
                    "{what}: counterbore Ø{wide}: {:?}",
                    other.map(|s| (s.kind, s.drill.clone()))
                )),
            }
        }
        for o in ops.operations.iter().filter(|o| o.stage == Stage::Drill) {
            if matches!(
                o.drill,
                Some(DrillKind::Through | DrillKind::Blind | DrillKind::Peck)
            ) {
                // Every drilled bore waits for a spot.
                let spotted = o
                    .after
                    .iter()
                    .any(|&a| ops.operations[a - 1].drill == Some(DrillKind::Spot));
                if !spotted {
                    errors.push(format!("{what}: step {} drills unspotted", o.step));
                }
            }
        }
        let turned = operations(&text, Some(5), [0.0, 0.0, 1.0]).unwrap();
        if stages_summary(&turned) != stages_summary(&ops) {
            errors.push(format!(
                "{what}: turned {:?} vs {:?}",
                stages_summary(&turned),
                stages_summary(&ops)
            ));
        }
    }
    eprintln!("STAGES {cones} cones cut by their countersink, {named} ends named without a tool, {} errors", errors.len());
    assert!(errors.is_empty(), "{errors:#?}");
    assert!(cones >= 4 && named >= 4, "{cones} {named}");
}

/// One answer to "which tool fits" (issue 38): on every pocketed panel and
/// plate of holes, each pocket and hole the set-up's tool enters gets the
/// same largest tool from `recognize` (`largest_tool_diameter`), `access`
/// (its feature tool, the recognizer's bound where no face's reach is
/// narrower) and `operations` (its finish by radii), with the same bound.
#[test]
fn recognize_access_and_operations_give_one_largest_tool() {
    use thinwall_study::{AccessRequest, LoadedPart, OperationsRequest, RecognizeRequest, Study};
    let mut parts = pocket_parts();
    parts.extend(common::generated_parts("THINWALL_HOLES_DIR", "holes"));
    let (mut same, mut finished) = (0, 0);
    for path in parts {
        let what = path.display().to_string();
        let loaded = LoadedPart::read_file(&path).unwrap();
        let study = Study::new(&loaded);
        let rec = thinwall_study::recognize(&study, &RecognizeRequest::default()).unwrap();
        let setup = RecognizeRequest::default().setup;
        let acc = thinwall_study::access(&study, &AccessRequest::new(setup.clone())).unwrap();
        let ops = thinwall_study::operations(&study, &OperationsRequest::new(setup)).ok();
        for m in &rec.outcome.machining {
            let Some(fit) = m.largest_tool_diameter else {
                continue;
            };
            let Some(t) = acc.report.features.iter().find(|t| t.feature == m.id) else {
                continue;
            };
            // Reached from up at all (the other side's pockets are not).
            let Some(got) = t.largest_tool_mm else {
                continue;
            };
            assert!(
                (got - fit).abs() <= TOL && t.bound == m.tool_bound,
                "{what}: {}: access Ø{got} ({:?}), recognizer Ø{fit} ({:?})",
                m.id,
                t.bound,
                m.tool_bound
            );
            same += 1;
            let finish = ops.as_ref().and_then(|o| {
                o.report
                    .setup
                    .radius_finishes
                    .iter()
                    .find(|f| f.feature == m.id.to_string())
            });
            if let Some(f) = finish {
                assert!(
                    (f.largest_tool_mm - fit).abs() <= TOL && Some(f.bounded_by) == m.tool_bound,
                    "{what}: {}: operations Ø{} vs Ø{fit}",
                    m.id,
                    f.largest_tool_mm
                );
                finished += 1;
            }
        }
    }
    eprintln!(
        "ONE ANSWER {same} features alike in recognize and access, {finished} in operations too"
    );
    assert!(same >= 40 && finished >= 12, "{same} {finished}");
}
