//! Operations along the plan (issue 17): every machining feature of the
//! plan layered and tooled on its own, and the order keeps every relation
//! of the plan's feature sequence (what lies above first, each wall's step
//! approach, the stiffness-feature sequence).

mod common;

use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_ops::operations::Stage;
use thinwall_ops::setup::along_plan;
use thinwall_ops::ToolLibrary;
use thinwall_plan::removal::pieces::Height;

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
    let mut all = common::thin_walled_parts();
    all.push(common::root().join("fixtures/ops/drill_plate.step"));
    for path in all {
        let what = path.display().to_string();
        let part = thinwall_step::read_file(&path).unwrap().0;
        let request = thinwall_pipeline::Request::default();
        let outcome = thinwall_pipeline::run(&part, None, &request).unwrap();
        let plan = thinwall_plan::plan(&what, &part, &outcome, &rules);
        if plan.removal.unavailable.is_some() {
            continue;
        }
        let a = PartAnalysis::new(
            &part,
            Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
        );
        let (_, ops) = along_plan(&a, &plan, &lib, None).unwrap();
        // The steps of each feature's operations.
        let steps = |id: &str| -> Vec<usize> {
            ops.operations
                .iter()
                .filter(|o| o.feature.as_deref() == Some(id))
                .map(|o| o.step)
                .collect()
        };
        for r in &plan.feature_sequence.relations {
            let (a, b) = (steps(&r.before), steps(&r.after));
            if let (Some(last), Some(first)) = (a.iter().max(), b.iter().min()) {
                assert!(
                    last < first,
                    "{what}: {} before {} ({}) broken: step {last} after {first}",
                    r.before,
                    r.after,
                    r.why
                );
                relations += 1;
            }
        }
        for o in &ops.operations {
            assert!(
                o.after.iter().all(|&s| s < o.step),
                "{what}: step {}",
                o.step
            );
            drills += usize::from(o.stage == Stage::Drill);
        }
        assert!(ops.tool_changes <= ops.plain_tool_changes, "{what}");
        for (l, fts) in ops.layers.iter().zip(&ops.field_tools) {
            let cleared: f64 = fts
                .iter()
                .flat_map(|ft| &ft.shares)
                .map(|s| s.cleared_mm2)
                .sum();
            let rest: f64 = fts.iter().map(|ft| ft.rest_mm2).sum();
            let drilled: f64 = l
                .fields
                .iter()
                .zip(fts)
                .filter(|(_, ft)| ft.drilled.is_some())
                .map(|(f, _)| f.area_mm2)
                .sum();
            assert!(
                (cleared + rest + drilled - l.area_mm2).abs() <= 1e-6 * l.area_mm2.max(1.0),
                "{what}: layer {} of {:?}",
                l.index,
                l.feature
            );
        }
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
            assert!(
                (layered - f.volume_mm3).abs() <= 1e-6 * f.volume_mm3.max(1.0),
                "{what}: {} layered {layered} mm³, volume {}",
                f.id,
                f.volume_mm3
            );
            exact += 1;
        }
        parts += 1;
    }
    eprintln!(
        "BY FEATURE {parts} parts, {relations} relations kept, {exact} flat features layered exactly, {drills} drilling operations"
    );
    assert!(parts >= 25 && relations > 100 && exact > 50 && drills >= 4);
}
