//! Operations along the plan (issue 17): every machining feature of the
//! plan layered and tooled on its own, and the order keeps every relation
//! of the plan's feature sequence (what lies above first, each wall's step
//! approach, the stiffness-feature sequence).

mod common;

use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_ops::operations::Stage;
use thinwall_ops::setup::along_plan;
use thinwall_ops::ToolLibrary;
use thinwall_removal::pieces::Height;

/// On every thin-walled part and recognition fixture whose plan has
/// machining features:
/// - every relation of the plan holds in the order: all operations of the
///   feature before come before all of the feature after;
/// - in every layer the tools' shares and the rest make up the section
///   (1e-6);
/// - the order needs no more tool changes than the plain one;
/// - a feature whose solids are bounded by flat heights is layered
///   exactly: its layers' sections times their thickness add up to its
///   volume (1e-6).
#[test]
fn operations_keep_every_relation_of_the_plan() {
    let lib = ToolLibrary::default_tools();
    let rules = thinwall_plan::RuleSet::default_rules();
    let (mut parts, mut relations, mut exact, mut drills) = (0, 0, 0, 0);
    let mut meshed = 0;
    let mut all = common::thin_walled_parts();
    all.push(common::root().join("fixtures/ops/drill_plate.step"));
    // Tori, floor fillets across up, countersinks: meshed faces.
    all.extend(common::step_files(&common::root().join("fixtures/pockets")));
    all.extend(common::step_files(&common::root().join("fixtures/holes")));
    for path in all {
        let what = path.display().to_string();
        let part = thinwall_step::read_file(&path).unwrap().0;
        let request = thinwall_pipeline::Request::default();
        let a = PartAnalysis::new(
            &part,
            Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
        );
        let outcome = thinwall_pipeline::run_on(&a, &request).unwrap();
        let plan = thinwall_plan::plan(&what, &a, &outcome, &rules).expect("a plan");
        if plan.removal.unavailable.is_some() {
            continue;
        }
        let holes = common::features_in_setup(&a);
        meshed += usize::from(!plan.removal.meshed.is_empty());
        let (_, ops) = along_plan(&a, &plan, &holes, &lib, None).unwrap();
        relations += common::assert_relations_kept(&ops, &plan, &what);
        for o in &ops.operations {
            assert!(
                o.after.iter().all(|&s| s < o.step),
                "{what}: step {}",
                o.step
            );
            drills += usize::from(o.stage == Stage::Drill);
        }
        assert!(ops.tool_changes <= ops.plain_tool_changes, "{what}");
        common::assert_layers_add_up(&ops, &what);
        let flat = |h: &Height| matches!(*h, Height::Plane { gx, gy, .. } if gx.hypot(gy) < 1e-9);
        for f in plan.machining_features.iter().filter(|f| f.reachable) {
            if !f.solids.iter().all(|s| flat(&s.lower) && flat(&s.upper)) {
                continue;
            }
            let layered: f64 = ops
                .layers
                .iter()
                .filter(|l| l.feature.as_deref() == Some(f.id.as_str()))
                .map(|l| l.area_mm2 * (l.z_top_mm - l.z_bottom_mm))
                .sum();
            // A section's rings narrower on average than twice the
            // layers' tolerance are dropped as slivers (`without_slivers`):
            // at most the tolerance times their perimeter each.
            let tol = 1e-6 * a.bounding_box().diagonal();
            let slivers: f64 = f
                .solids
                .iter()
                .map(|s| {
                    let perimeter: f64 = s
                        .rings
                        .iter()
                        .map(|r| {
                            (0..r.len())
                                .map(|i| {
                                    let (p, q) = (r[i], r[(i + 1) % r.len()]);
                                    (p[0] - q[0]).hypot(p[1] - q[1])
                                })
                                .sum::<f64>()
                        })
                        .sum();
                    let h = |x: &Height| match *x {
                        Height::Plane { z0, .. } => z0,
                        _ => 0.0,
                    };
                    tol * perimeter * (h(&s.upper) - h(&s.lower)).abs()
                })
                .sum();
            assert!(
                (layered - f.volume_mm3).abs() <= 1e-6 * f.volume_mm3.max(1.0) + slivers,
                "{what}: {} layered {layered} mm³, volume {}",
                f.id,
                f.volume_mm3
            );
            exact += 1;
        }
        parts += 1;
    }
    eprintln!(
        "BY FEATURE {parts} parts ({meshed} meshed), {relations} relations kept, {exact} flat features layered exactly, {drills} drilling operations"
    );
    assert!(parts >= 30 && meshed >= 5 && relations > 100 && exact > 50 && drills >= 4);
}

/// The operations as (stage, tool, feature, first layer, area, volume),
/// sorted.
fn summary(
    ops: &thinwall_ops::operations::SetupOperations,
) -> Vec<(Stage, String, Option<String>, usize, f64, f64)> {
    let mut v: Vec<_> = ops
        .operations
        .iter()
        .map(|o| {
            let first = o.passes.first().map_or(usize::MAX, |p| p.layer);
            let f = o.feature.as_ref().map(|f| f.to_string());
            (o.stage, o.tool.clone(), f, first, o.area_mm2, o.volume_mm3)
        })
        .collect();
    v.sort_by(|a, b| (a.0, &a.1, &a.2, a.3).cmp(&(b.0, &b.1, &b.2, b.3)));
    v
}

/// Operations along the plan of a part and of its copies turned by rigid
/// motions (with the set-up) are the same: stages, tools, features, first
/// layers, areas and volumes (within 1e-6 of the set-up's totals), and
/// tool changes. (It found an edge of a cutter field that is part along
/// one stretch and blank along another classified by its middle alone, so
/// that a collinear vertex changed the tools.)
#[test]
fn operations_along_the_plan_do_not_depend_on_pose() {
    let lib = ToolLibrary::default_tools();
    let rules = thinwall_plan::RuleSet::default_rules();
    let text =
        std::fs::read_to_string(common::root().join("fixtures/recognition/flange_cutouts.step"))
            .unwrap();
    let run = |text: &str, up: [f64; 3]| {
        let (part, plan) = common::plan_text(text, up, &rules);
        let a = PartAnalysis::new(&part, Setup::new(up, Machine::ThreeAxis).unwrap());
        let holes = common::features_in_setup(&a);
        let (_, ops) = along_plan(&a, &plan, &holes, &lib, None).unwrap();
        ops
    };
    let base = run(&text, [0.0, 0.0, 1.0]);
    let want = summary(&base);
    assert!(want.len() >= 10, "{}", want.len());
    // Areas and volumes within a millionth of the set-up's totals (a rest
    // of a few mm² carries the booleans' rounding).
    let area: f64 = want.iter().map(|w| w.4).sum();
    let volume: f64 = want.iter().map(|w| w.5).sum();
    for seed in [3, 11] {
        let (r, t) = common::rigid_motion(seed);
        let up = r * nalgebra::Vector3::z();
        let turned = common::turned_step(&text, &r, &t).0;
        let ops = run(&turned, [up.x, up.y, up.z]);
        let got = summary(&ops);
        assert_eq!(got.len(), want.len(), "turned {seed}");
        for (g, w) in got.iter().zip(&want) {
            assert_eq!(
                (g.0, &g.1, &g.2, g.3),
                (w.0, &w.1, &w.2, w.3),
                "turned {seed}"
            );
            for (a, b, total) in [(g.4, w.4, area), (g.5, w.5, volume)] {
                assert!(
                    (a - b).abs() <= 1e-6 * total,
                    "turned {seed}: {g:?} vs {w:?}"
                );
            }
        }
        assert_eq!(ops.tool_changes, base.tool_changes, "turned {seed}");
    }
}
