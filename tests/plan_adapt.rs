//! The step approach adapted to what is in and on a wall (Popma §4.1.3):
//! large holes align the layers at the step separation line and come
//! between the layers above and below it; large cut-outs size the wall as
//! the shortest piece they leave; cut-outs go in after the first layer
//! down to their bottom; a wall on a web is no wider there than the web's
//! permissible height; a chamfer's material is a feature of its own.

mod common;

use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_plan::adapt::AdaptRule;
use thinwall_plan::features::{FeatureClass, RemovalFeature};
use thinwall_plan::sizing::{size_wall, Milling, WallDimensions};
use thinwall_plan::{sizing_parameters, Plan, RuleSet};

fn plan(path: &str) -> Plan {
    let path = common::root().join(path);
    let expected = path.with_extension("expected.json");
    let up = match std::fs::read_to_string(&expected) {
        Ok(text) => {
            let v: serde_json::Value = serde_json::from_str(&text).unwrap();
            [0, 1, 2].map(|k| v["up"][k].as_f64().unwrap())
        }
        Err(_) => [0.0, 0.0, 1.0],
    };
    let text = std::fs::read_to_string(&path).unwrap();
    common::plan_text(&text, up, &RuleSet::default_rules()).1
}

/// A feature id by its name (`R1`, `H2`).
fn id(p: &Plan, s: &str) -> FeatureId {
    p.stiffness_features
        .iter()
        .map(|f| f.id)
        .find(|f| f.to_string() == s)
        .unwrap_or_else(|| panic!("no {s}"))
}

fn position(p: &Plan, feature: &str) -> usize {
    p.feature_sequence
        .order
        .iter()
        .position(|o| o == feature)
        .unwrap_or_else(|| panic!("{feature} not in the order"))
}

const PART: &str = "fixtures/machining/ribs_with_holes_and_cutouts.step";

#[test]
fn large_holes_align_the_layers_and_are_cut_at_the_line() {
    let p = plan(PART);
    let r1 = id(&p, "R1");
    let a = p
        .adaptations
        .iter()
        .find(|a| a.rule == AdaptRule::LargeHoles)
        .expect("a step separation line");
    assert_eq!(a.wall, r1);
    // Holes Ø40 and Ø24 centred 50 above the foot: the highest top is 70,
    // the line 70 − 2 × 12 = 46; it crosses both.
    let line = 46.0;
    let mine: Vec<_> = p.layers.iter().filter(|l| l.owner == r1).collect();
    assert!(mine.iter().any(|l| (l.from_foot[0] - line).abs() < 1e-6
        && l.size_class == thinwall_plan::steps::SizeClass::Large));
    let big_h = p.walls.iter().find(|w| w.id == r1).unwrap().sizes.big_h;
    for l in &mine {
        assert!(
            !(l.from_foot[0] < line - 1e-6 && l.from_foot[1] > line + 1e-6),
            "{} crosses the line: {:?}",
            l.id,
            l.from_foot
        );
        assert!(l.height <= big_h + 1e-9, "{}", l.id);
    }
    let present = |l: &&&thinwall_plan::steps::Layer| p.feature_sequence.order.contains(&l.id);
    // The foot is 10 above the plate's bottom: the line is at z = 56.
    let line_z = 56.0;
    for (hole, volume) in [
        ("H1", std::f64::consts::PI * 400.0 * 1.5),
        ("H2", std::f64::consts::PI * 144.0 * 1.5),
    ] {
        let feats: Vec<_> = p
            .machining_features
            .iter()
            .filter(|f| f.owner == Some(id(&p, hole)))
            .collect();
        // Two features, above and below the line, the hole's volume in all.
        assert_eq!(feats.len(), 2, "{hole}");
        let total: f64 = feats.iter().map(|f| f.volume_mm3).sum();
        assert!(
            (total - volume).abs() < 1e-6 * volume,
            "{hole}: {total} {volume}"
        );
        let (above, below): (Vec<&&RemovalFeature>, Vec<&&RemovalFeature>) =
            feats.iter().partition(|f| f.z_range[0] >= line_z - 1e-6);
        assert_eq!((above.len(), below.len()), (1, 1), "{hole}");
        assert!((below[0].z_range[1] - line_z).abs() < 1e-6);
        let (up, down) = (*above[0], *below[0]);
        assert_eq!(up.size_class, FeatureClass::OtherSetup);
        // The upper part after every layer above the line, before the
        // first layer below it on each side; the lower part after it.
        for l in mine.iter().filter(present) {
            if l.from_foot[0] >= line - 1e-6 {
                assert!(
                    position(&p, &l.id) < position(&p, &up.id),
                    "{} before {}",
                    l.id,
                    up.id
                );
            }
        }
        for side in [0, 1] {
            let below_line = mine
                .iter()
                .filter(present)
                .find(|l| l.side == side && l.from_foot[1] <= line + 1e-6)
                .unwrap();
            assert!(
                position(&p, &up.id) < position(&p, &below_line.id),
                "{} before {}",
                up.id,
                below_line.id
            );
        }
        assert!(position(&p, &up.id) < position(&p, &down.id));
    }
}

#[test]
fn large_cutouts_size_the_wall_as_the_shortest_piece_left() {
    let p = plan(PART);
    let r2 = p.walls.iter().find(|w| w.id == id(&p, "R2")).unwrap();
    assert!(p
        .adaptations
        .iter()
        .any(|a| a.wall == r2.id && a.rule == AdaptRule::LargeCutouts));
    let params = sizing_parameters(Milling::Peripheral, &thinwall_recognize::Config::default());
    let dims = |length: f64| WallDimensions {
        length,
        thickness: 1.5,
        height: 48.0,
    };
    // Cut-outs at 40..60 and 120..140 on a rib from 10 to 190: 30, 60, 50.
    let short = size_wall(&dims(30.0), &params).unwrap();
    let whole = size_wall(&dims(180.0), &params).unwrap();
    assert!(
        (r2.sizes.wall.length - 30.0).abs() < 1e-6,
        "{}",
        r2.sizes.wall.length
    );
    assert_eq!(
        (r2.sizes.b, r2.sizes.h, r2.sizes.big_h),
        (short.b, short.h, short.big_h)
    );
    assert!(short.big_h < whole.big_h, "the short wall is more careful");
    // Its layers are those sizes.
    for l in p.layers.iter().filter(|l| l.owner == r2.id) {
        assert!(l.height <= short.big_h + 1e-9);
    }
}

#[test]
fn cutouts_go_in_after_the_first_layer_down_to_their_bottom() {
    for path in [PART, "fixtures/recognition/flange_cutouts.step"] {
        let p = plan(path);
        let mut seen = 0;
        for a in p
            .adaptations
            .iter()
            .filter(|a| a.rule == AdaptRule::CutoutInSequence)
        {
            let kind = p
                .stiffness_features
                .iter()
                .find(|f| f.id == a.by)
                .map(|f| f.kind);
            assert_eq!(kind, Some(StiffnessKind::Cutout));
            // The layer it follows: the first of its wall reaching down to
            // the cut-out's bottom (named in the change).
            let layer = a
                .change
                .split_whitespace()
                .nth(2)
                .unwrap()
                .trim_end_matches(',');
            let l = p.layers.iter().find(|l| l.id == layer).unwrap();
            assert_eq!(l.owner, a.wall);
            if path == PART {
                // Its large layer has material: the cut-out follows it.
                assert_eq!(l.size_class, thinwall_plan::steps::SizeClass::Large);
            }
            for f in p
                .machining_features
                .iter()
                .filter(|f| f.owner == Some(a.by))
            {
                let related = p
                    .feature_sequence
                    .relations
                    .iter()
                    .chain(&p.feature_sequence.dropped)
                    .any(|r| r.after == f.id && r.why.contains("inserted into"));
                assert!(related, "{path}: {} has no insertion", f.id);
                if p.feature_sequence.order.contains(&l.id) {
                    assert!(
                        position(&p, &l.id) < position(&p, &f.id),
                        "{path}: {} {}",
                        l.id,
                        f.id
                    );
                }
                seen += 1;
            }
        }
        assert!(seen > 0, "{path}");
    }
}

#[test]
fn a_wall_on_a_web_is_no_wider_there_than_the_web_allows() {
    let p = plan("fixtures/recognition/c_frame.step");
    let capped: Vec<_> = p
        .adaptations
        .iter()
        .filter(|a| a.rule == AdaptRule::ConnectedWall)
        .collect();
    assert!(!capped.is_empty());
    for a in capped {
        let web = p.walls.iter().find(|w| w.id == a.by).unwrap();
        assert_eq!(web.kind, StiffnessKind::Web);
        assert!(web.sizes.deflection_mm <= web.sizes.parameters.allowed_deflection_mm);
        let widths: Vec<f64> = p
            .layers
            .iter()
            .filter(|l| l.owner == a.wall)
            .map(|l| l.width)
            .collect();
        assert!(
            widths
                .iter()
                .any(|&w| (w - web.sizes.h).abs() < 1e-9 || (w - web.sizes.big_h).abs() < 1e-9),
            "{}: {widths:?}",
            a.wall
        );
        let own = p.walls.iter().find(|w| w.id == a.wall).unwrap();
        assert!(widths.iter().all(|&w| w <= own.sizes.b + 1e-9));
    }
}

#[test]
fn a_chamfer_is_a_feature_of_its_own() {
    let p = plan("fixtures/recognition/filleted_chamfered_rib.step");
    let ch = p
        .stiffness_features
        .iter()
        .find(|f| f.kind == StiffnessKind::Chamfer)
        .unwrap()
        .id;
    let d: Vec<_> = p
        .machining_features
        .iter()
        .filter(|f| f.owner == Some(ch))
        .collect();
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].size_class, FeatureClass::Detail);
    assert!(d[0].id.starts_with('D'));
    // A 45° chamfer 1 mm down the rib's 100 mm top edge: 0.5 × 1 × 1 × 100.
    assert!((d[0].volume_mm3 - 50.0).abs() < 1e-6, "{}", d[0].volume_mm3);
    // Small: after the top layer on each side of its rib.
    let rib = p.walls[0].id;
    for side in [0, 1] {
        let top = p
            .layers
            .iter()
            .find(|l| l.owner == rib && l.side == side && p.feature_sequence.order.contains(&l.id))
            .unwrap();
        assert!(position(&p, &top.id) < position(&p, &d[0].id));
    }
}

/// A sizing parameter out of range is a typed plan error naming the wall
/// (recognition settings are checked before any run, so only a caller
/// handing the planner an edited outcome meets it), never a silently
/// unsized wall.
#[test]
fn a_sizing_parameter_out_of_range_is_a_plan_error() {
    let text = std::fs::read_to_string(common::root().join(PART)).unwrap();
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    let req = thinwall_pipeline::Request::default();
    let a = thinwall_analysis::PartAnalysis::new(&part, req.setup.clone());
    let mut out = thinwall_pipeline::run_on(&a, &req).unwrap();
    out.request.config.thinness.allowed_deflection_mm = 0.0;
    let e = thinwall_plan::plan("part.step", &a, &out, &RuleSet::default_rules()).unwrap_err();
    assert_eq!(e.code(), "sizing.parameter");
    let thinwall_plan::PlanError::Sizing { wall, .. } = &e;
    assert!(wall.to_string().starts_with('R'), "{e}");
    assert!(e.to_string().contains("allowed_deflection_mm"), "{e}");
}
