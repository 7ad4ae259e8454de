//! The operation sheet a planner would sign (issue 42), in the default
//! mode (operations from the stock's top, layer by layer):
//! - no end mill runs in a cutter field of a layer for less than the
//!   library's minimum share;
//! - the step approach of thin walls holds: beside a thin wall standing
//!   along up (the plan's sizes: its `h_RF`, its step layers' heights) no
//!   clearing pass is deeper than its `h_RF`, and each clearing pass there
//!   finishes its own walls (no wall finish apart, after the layers below
//!   are gone);
//! - the tool sheet lists every tool that runs, once, with its operations
//!   and time adding up to the set-up's.
//!
//! On every shared thin-walled part as built, and on turned copies (the
//! set-up turned with the part) whose sheets must be the same.

mod common;

use thinwall_ops::operations::{SetupOperations, Stage};
use thinwall_plan::{Plan, RuleSet};
use thinwall_study::{
    setup_of, LoadedPart, OperationsRequest, PlanRequest, RecognizeRequest, Study,
};

const TOL: f64 = 1e-6;

/// A thin wall standing along up: its heights and its `h_RF`.
struct ThinWall {
    id: String,
    z: [f64; 2],
    h: f64,
}

/// The plan's thin walls milled with the flank whose step layers stand
/// along up (their cut heights as far apart as their heights on the wall).
fn thin_walls(plan: &Plan) -> Vec<ThinWall> {
    let mut out = Vec::new();
    for w in plan.walls.iter().filter(|w| w.sizes.thin) {
        if w.sizes.milling != thinwall_plan::Milling::Peripheral {
            continue;
        }
        let layers: Vec<_> = plan.layers.iter().filter(|l| l.owner == w.id).collect();
        let standing = !layers.is_empty()
            && layers.iter().all(|l| {
                let cut = (l.cut_heights[1] - l.cut_heights[0]).abs();
                (cut - (l.from_foot[1] - l.from_foot[0]).abs()).abs() < 1e-6
            });
        if !standing {
            continue;
        }
        let lo = layers
            .iter()
            .flat_map(|l| l.cut_heights)
            .fold(f64::INFINITY, f64::min);
        let hi = layers
            .iter()
            .flat_map(|l| l.cut_heights)
            .fold(f64::NEG_INFINITY, f64::max);
        out.push(ThinWall {
            id: w.id.to_string(),
            z: [lo, hi],
            h: w.sizes.h,
        });
    }
    out
}

fn overlaps(top: f64, bottom: f64, w: &ThinWall) -> bool {
    top.min(w.z[1]) - bottom.max(w.z[0]) > TOL
}

/// Every clearing pass beside a thin wall within its `h_RF`, and its
/// walls finished in the same pass. Returns how many passes were checked.
fn assert_step_approach(ops: &SetupOperations, walls: &[ThinWall], what: &str) -> usize {
    let mut checked = 0;
    for o in &ops.operations {
        if !matches!(
            o.stage,
            Stage::Rough | Stage::SemiFinish | Stage::FinishWalls
        ) {
            continue;
        }
        for p in &o.passes {
            for w in walls
                .iter()
                .filter(|w| overlaps(p.z_top_mm, p.z_bottom_mm, w))
            {
                let depth = p.z_top_mm - p.z_bottom_mm;
                assert!(
                    depth <= w.h + TOL,
                    "{what}: step {} ({:?} {}) cuts {depth:.3} mm deep beside {} (h_RF {:.3})",
                    o.step,
                    o.stage,
                    o.tool,
                    w.id,
                    w.h
                );
                checked += 1;
            }
        }
    }
    // No wall finish apart from the clearing beside a thin wall: each
    // clearing pass there finishes its own boundary region (its walls)
    // while the layer below still holds them.
    let mut boundary = 0.0;
    for o in &ops.operations {
        for p in &o.passes {
            if !walls.iter().any(|w| overlaps(p.z_top_mm, p.z_bottom_mm, w)) {
                continue;
            }
            assert!(
                o.stage != Stage::FinishWalls,
                "{what}: step {} finishes walls apart in layer {}, beside a thin wall",
                o.step,
                p.layer + 1
            );
            boundary += p.regions.map_or(0.0, |r| r.boundary_mm2);
        }
    }
    assert!(
        checked == 0 || boundary > 0.0,
        "{what}: no pass beside a thin wall finishes it"
    );
    checked
}

fn assert_minimum_share(ops: &SetupOperations, min: f64, what: &str) {
    for (k, fts) in ops.field_tools.iter().enumerate() {
        for (j, ft) in fts.iter().enumerate() {
            for s in &ft.shares {
                assert!(
                    s.cleared_mm2 >= min - TOL,
                    "{what}: layer {} field {j}: {} takes {:.3} mm², under the minimum {min}",
                    k + 1,
                    s.tool,
                    s.cleared_mm2
                );
            }
        }
    }
}

fn assert_tool_sheet(ops: &SetupOperations, what: &str) {
    let mut tools: Vec<&str> = ops.operations.iter().map(|o| o.tool.as_str()).collect();
    tools.dedup();
    let mut first_seen: Vec<&str> = Vec::new();
    for t in &tools {
        if !first_seen.contains(t) {
            first_seen.push(t);
        }
    }
    let sheet: Vec<&str> = ops.tool_sheet.iter().map(|u| u.tool.as_str()).collect();
    assert_eq!(sheet, first_seen, "{what}: the tool sheet's tools");
    let count: usize = ops.tool_sheet.iter().map(|u| u.operations).sum();
    assert_eq!(count, ops.operations.len(), "{what}");
    let loads: usize = ops.tool_sheet.iter().map(|u| u.loads).sum();
    assert_eq!(
        loads,
        ops.tool_changes + usize::from(!ops.operations.is_empty()),
        "{what}"
    );
    let time: f64 = ops.tool_sheet.iter().map(|u| u.time_min).sum();
    assert!(
        (time - ops.time_min).abs() <= 1e-9 * ops.time_min.max(1.0),
        "{what}"
    );
}

/// The default sheet of `text` along `up`, its plan's thin walls, and
/// how many passes were checked beside them.
fn sheet(text: &str, up: [f64; 3], what: &str) -> (SetupOperations, usize) {
    let loaded = LoadedPart::read_bytes(text.as_bytes(), what).unwrap();
    let study = Study::new(&loaded);
    let setup = setup_of(Some(up), thinwall_analysis::Machine::ThreeAxis).unwrap();
    let ops = thinwall_study::operations(&study, &OperationsRequest::new(setup.clone()))
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let recognize = RecognizeRequest {
        setup,
        ..Default::default()
    };
    let plan = thinwall_study::plan(
        &study,
        &PlanRequest::new(recognize, RuleSet::default_rules()),
    )
    .unwrap_or_else(|e| panic!("{what}: {e}"));
    let walls = thin_walls(&plan.plan);
    let ops = ops.report.setup.clone();
    let min = thinwall_ops::ToolLibrary::default_tools().min_share_mm2;
    assert_minimum_share(&ops, min, what);
    assert_tool_sheet(&ops, what);
    let checked = assert_step_approach(&ops, &walls, what);
    (ops, checked)
}

#[test]
fn the_default_sheet_keeps_the_minimum_share_and_the_step_approach() {
    let parts = common::step_files(&common::shared_data().join("thinwall"));
    assert!(
        parts.len() >= 10,
        "{} shared thin-walled parts",
        parts.len()
    );
    let mut checked = 0;
    let mut turned = 0;
    for (i, path) in parts.iter().enumerate() {
        let what = path.display().to_string();
        let text = std::fs::read_to_string(path).unwrap();
        let (ops, n) = sheet(&text, [0.0, 0.0, 1.0], &what);
        checked += n;
        // Every third part turned too: the same sheet.
        if i % 3 == 0 {
            let seed = 4200 + i as u64;
            let (r, _) = common::rigid_motion(seed);
            let up = r * nalgebra::Vector3::z();
            let (t, _) = sheet(
                &common::posed_step(&text, Some(seed)),
                [up.x, up.y, up.z],
                &what,
            );
            assert_eq!(t.operations.len(), ops.operations.len(), "{what} turned");
            assert_eq!(t.tool_changes, ops.tool_changes, "{what} turned");
            let tools = |o: &SetupOperations| -> Vec<(String, usize)> {
                o.tool_sheet
                    .iter()
                    .map(|u| (u.tool.clone(), u.operations))
                    .collect()
            };
            assert_eq!(tools(&t), tools(&ops), "{what} turned");
            turned += 1;
        }
    }
    assert!(
        checked > 100,
        "only {checked} passes beside thin walls checked"
    );
    assert!(turned >= 3);
}
