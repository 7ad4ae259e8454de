//! Plans over several set-ups in turn (issue 37), on generated panels
//! pocketed from both sides of their web (corner radii, floor fillets,
//! lightening holes), as built and turned (the set-up turned with the
//! part): the proposed plan has two set-ups from opposite sides; each
//! later set-up's features and what the set-ups before it took add up to
//! stock − part; the features the set-ups machine (every set-up's
//! reachable ones) and the residue add up to stock − part too, so no
//! set-up machines what another already took; a thin web keeps the
//! support of the material under it in the first set-up (no step layers
//! there) and gets its layers in the set-up that mills its last side; the
//! same ups given in order give the same plans; operations along each
//! set-up's plan (`--by-feature`) keep its relations and drill each hole
//! once.

mod common;

use nalgebra::Vector3;
use std::path::Path;
use thinwall_plan::features::FeatureClass;
use thinwall_plan::Plan;
use thinwall_study::{LoadedPart, PlanRequest, RecognizeRequest, Study};

#[derive(serde::Deserialize)]
struct PanelTruth {
    both_sides: bool,
}

/// The plan of the part of `path` posed by `seed`: proposed (`ups` empty)
/// or along `ups`.
fn plan_of(path: &Path, seed: Option<u64>, ups: &[[f64; 3]]) -> Plan {
    let text = common::posed_step(&std::fs::read_to_string(path).unwrap(), seed);
    let (part, read) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    let loaded = LoadedPart::new("part.step", part, read);
    let study = Study::new(&loaded);
    let mut recognize = RecognizeRequest::default();
    if let Some(up) = ups.first() {
        recognize.setup.up = *up;
    }
    let mut req = PlanRequest::new(recognize, thinwall_plan::RuleSet::default_rules());
    req.propose = ups.is_empty();
    req.later_ups = ups.iter().skip(1).copied().collect();
    let planned = thinwall_study::plan(&study, &req)
        .unwrap_or_else(|e| panic!("{} {seed:?}: {e}", path.display()));
    Plan::clone(&planned.plan)
}

/// Every set-up's plan, the first's first.
fn setups(plan: &Plan) -> Vec<&Plan> {
    std::iter::once(plan).chain(&plan.then).collect()
}

/// The precision of a set-up's removal: a millionth of the stock, or its
/// meshed faces' bound and slivers if larger, mm³.
fn precision(p: &Plan) -> f64 {
    let r = &p.removal;
    (1e-6 * r.stock_volume_mm3).max(r.meshed.volume_bound_mm3 + r.slivers_mm3)
}

/// Each set-up: its features and what the set-ups before took are stock −
/// part; over every set-up, the features each reaches and the residue are
/// stock − part (no material machined twice, none left out).
fn assert_adds_up(plan: &Plan, name: &str) {
    let mut machined = 0.0;
    let mut tol = 0.0;
    for (k, p) in setups(plan).into_iter().enumerate() {
        let r = &p.removal;
        assert!(r.unavailable.is_none(), "{name} set-up {}: {r:?}", k + 1);
        let stock_part = r.stock_volume_mm3 - r.part_volume_mm3;
        let here = r.removed_volume_mm3 + r.cleared_before_mm3;
        assert!(
            (here - stock_part).abs() <= precision(p) + r.recut_mm3,
            "{name} set-up {}: {here} vs {stock_part}",
            k + 1
        );
        assert_eq!(
            k == 0,
            r.cleared_before_mm3 == 0.0,
            "{name} set-up {}",
            k + 1
        );
        machined += p
            .machining_features
            .iter()
            .filter(|f| f.size_class != FeatureClass::OtherSetup)
            .map(|f| f.volume_mm3)
            .sum::<f64>();
        tol += precision(p) + r.recut_mm3;
    }
    let r = &plan.removal;
    let residue = plan.residue.as_ref().expect("a residue").volume_mm3;
    let stock_part = r.stock_volume_mm3 - r.part_volume_mm3;
    assert!(
        (machined + residue - stock_part).abs() <= tol,
        "{name}: machined {machined} + residue {residue} vs {stock_part} (within {tol})"
    );
}

/// A web supported in the first set-up has no step layers there; the last
/// set-up supports none.
fn assert_webs_supported_until_their_last_side(plan: &Plan, name: &str) {
    for w in &plan.supported_webs {
        assert!(
            plan.layers.iter().all(|l| l.owner != *w),
            "{name}: supported web {w} layered in set-up 1"
        );
    }
    let last = setups(plan).pop().unwrap();
    assert!(
        last.supported_webs.is_empty(),
        "{name}: {:?}",
        last.supported_webs
    );
}

/// What the turned copy must keep: per set-up, its up (turned back), its
/// features' count and volume, and that set-up's precision.
fn signature(plan: &Plan, rot: &nalgebra::Rotation3<f64>) -> Vec<(Vector3<f64>, usize, f64, f64)> {
    setups(plan)
        .into_iter()
        .map(|p| {
            let v: f64 = p.machining_features.iter().map(|f| f.volume_mm3).sum();
            (
                rot.inverse() * Vector3::from(p.up),
                p.machining_features.len(),
                v,
                precision(p) + p.removal.recut_mm3,
            )
        })
        .collect()
}

#[test]
fn double_sided_panels_are_planned_in_two_set_ups_that_add_up() {
    let parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    let mut double = 0;
    for (i, path) in parts.iter().enumerate() {
        let truth: PanelTruth = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        if !truth.both_sides {
            continue;
        }
        double += 1;
        let seed = 7100 + i as u64;
        let mut signatures = Vec::new();
        for pose in [None, Some(seed)] {
            let name = format!("{} {pose:?}", path.display());
            let plan = plan_of(path, pose, &[]);
            assert_eq!(plan.then.len(), 1, "{name}: {:?}", plan.proposal);
            assert!(
                Vector3::from(plan.up).dot(&Vector3::from(plan.then[0].up)) < -1.0 + 1e-9,
                "{name}: {:?} then {:?}",
                plan.up,
                plan.then[0].up
            );
            assert_adds_up(&plan, &name);
            assert_webs_supported_until_their_last_side(&plan, &name);
            let rot = pose.map_or(nalgebra::Rotation3::identity(), |s| {
                common::rigid_motion(s).0
            });
            signatures.push(signature(&plan, &rot));
        }
        let (a, b) = (&signatures[0], &signatures[1]);
        for (x, y) in a.iter().zip(b) {
            assert!(
                (x.0 - y.0).norm() < 1e-9,
                "{}: {a:?} turned {b:?}",
                path.display()
            );
            assert_eq!(x.1, y.1, "{}: {a:?} turned {b:?}", path.display());
            assert!(
                (x.2 - y.2).abs() <= x.3 + y.3,
                "{}: {a:?} turned {b:?}",
                path.display()
            );
        }
    }
    assert!(double >= 1, "no double-sided panel among {parts:?}");
}

#[test]
fn the_proposed_set_ups_given_in_order_give_the_same_plans() {
    let path = common::root().join("fixtures/pockets/pockets_1.step");
    let proposed = plan_of(&path, None, &[]);
    let ups: Vec<[f64; 3]> = setups(&proposed).iter().map(|p| p.up).collect();
    let given = plan_of(&path, None, &ups);
    assert!(given.proposal.is_none());
    assert_eq!(
        signature(&proposed, &nalgebra::Rotation3::identity()),
        signature(&given, &nalgebra::Rotation3::identity())
    );
    // The web pocketed from both sides: supported while its far side is
    // still there, layered on its last side.
    assert!(!proposed.supported_webs.is_empty(), "{:?}", proposed.limits);
    let last = &proposed.then[0];
    for w in &proposed.supported_webs {
        assert!(
            last.layers.iter().any(|l| l.owner == *w),
            "{w} not layered in set-up 2"
        );
    }
}

/// One set-up's plan (+z) on every generated fixture with curved faces
/// (tori, spheres, cones, tilted holes): its features are stock − part
/// within the removal's precision. A layer cut above a face taken as a
/// surface of revolution or as facets once counted its block twice.
#[test]
fn one_set_up_plans_of_curved_parts_add_up() {
    let mut parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    for (var, dir) in [
        ("THINWALL_FEATURES_DIR", "features"),
        ("THINWALL_HOLES_DIR", "holes"),
        ("THINWALL_BULGES_DIR", "bulges"),
    ] {
        parts.extend(common::generated_parts(var, dir));
    }
    for path in &parts {
        let plan = plan_of(path, None, &[[0.0, 0.0, 1.0]]);
        let r = &plan.removal;
        assert!(r.unavailable.is_none(), "{}: {r:?}", path.display());
        let stock_part = r.stock_volume_mm3 - r.part_volume_mm3;
        let sum: f64 = plan.machining_features.iter().map(|f| f.volume_mm3).sum();
        assert!(
            (sum - stock_part).abs() <= precision(&plan),
            "{}: features {sum} vs stock − part {stock_part} (within {})",
            path.display(),
            precision(&plan)
        );
    }
}

/// Operations along the plans of set-ups in turn (`operations
/// --by-feature` without `--up`) on the double-sided panels: two set-ups
/// from opposite sides, each with operations on its own plan's features
/// only (none on a feature another set-up's plan holds), every relation
/// of its plan kept in its order, its layers' shares, rest and drilled
/// areas making up each section, no hole drilled twice.
#[test]
fn operations_follow_each_set_ups_plan() {
    for path in common::generated_parts("THINWALL_POCKETS_DIR", "pockets") {
        let truth: PanelTruth = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        if !truth.both_sides {
            continue;
        }
        let name = path.display().to_string();
        let loaded = LoadedPart::read_file(&path).unwrap();
        let study = Study::new(&loaded);
        let mut req = thinwall_study::OperationsRequest::new(Default::default());
        req.by_feature = true;
        req.choose_up = true;
        let report = thinwall_study::operations(&study, &req)
            .unwrap_or_else(|e| panic!("{name}: {e}"))
            .report;
        assert_eq!(report.then.len(), 1, "{name}");
        let plan = plan_of(&path, None, &[]);
        let sheets = std::iter::once((&report.setup, report.frame))
            .chain(report.then.iter().map(|l| (&l.setup, l.frame)));
        // Each hole drilled, by its axis's point on the frame's plane,
        // in the part's coordinates.
        let mut drilled: Vec<Vector3<f64>> = Vec::new();
        for (k, ((ops, frame), plan)) in sheets.zip(setups(&plan)).enumerate() {
            let what = format!("{name} set-up {}", k + 1);
            assert!(!ops.operations.is_empty(), "{what}");
            for o in ops.operations.iter().filter_map(|o| o.feature.as_deref()) {
                assert!(
                    plan.machining_features.iter().any(|f| f.id == o),
                    "{what}: {o} is no feature of its plan"
                );
            }
            common::assert_relations_kept(ops, plan, &what);
            common::assert_layers_add_up(ops, &what);
            let [o, x, y, z] = frame.map(Vector3::from);
            for h in ops.holes.iter().filter(|h| h.drill.is_some()) {
                let at = o + x * h.centre[0] + y * h.centre[1];
                // Its axis: any point of it off this one by a multiple of z.
                let same = |p: &Vector3<f64>| {
                    let d = p - at;
                    (d - z * d.dot(&z)).norm() < 1e-6
                };
                assert!(!drilled.iter().any(same), "{what}: {} drilled twice", h.id);
                drilled.push(at);
            }
        }
    }
}
