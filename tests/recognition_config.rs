//! Recognition settings: kinds left out stay out, the priority order
//! decides who claims a face, and no face is ever claimed twice.

mod common;

use std::collections::HashMap;
use thinwall_recognize::{Config, StiffnessKind as Kind};

fn parts() -> Vec<std::path::PathBuf> {
    let mut v = common::step_files(&common::root().join("fixtures/recognition"));
    v.extend(common::step_files(&common::shared_data().join("thinwall")));
    v.push(common::shared_data().join("nist/nist_ctc_01_asme1_ap242-e1.stp"));
    v
}

#[test]
fn no_face_is_claimed_twice_in_any_priority_order() {
    let orders = [
        Config::default().priority,
        vec![
            Kind::Chamfer,
            Kind::Fillet,
            Kind::Notch,
            Kind::Cutout,
            Kind::Hole,
        ],
        vec![Kind::Fillet, Kind::Hole],
    ];
    for path in parts() {
        let (part, _) = thinwall_step::read_file(&path).unwrap();
        for priority in &orders {
            let r = common::recognize_with(
                &part,
                [0.0, 0.0, 1.0],
                &Config {
                    priority: priority.clone(),
                    ..Config::default()
                },
            );
            let mut owner: HashMap<u64, String> = HashMap::new();
            for f in &r.features {
                // A wall's faces are its own (sides, top, ends); depressions
                // and details claim theirs once.
                for id in &f.faces {
                    if let Some(prev) = owner.insert(*id, f.id.to_string()) {
                        panic!(
                            "{}: face #{id} in {prev} and {} ({priority:?})",
                            path.display(),
                            f.id
                        );
                    }
                }
            }
        }
    }
}

/// The report of rib_grid_panel with `include` and `exclude`.
fn report_with(include: Vec<Kind>, exclude: Vec<Kind>) -> thinwall_report::RecognitionReport {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let (part, _) = thinwall_step::read_file(&path).unwrap();
    let mut req = thinwall_pipeline::Request::default();
    req.config.include = include;
    req.config.exclude = exclude;
    let out = thinwall_pipeline::run(&part, None, &req).unwrap();
    thinwall_report::recognition_report("rib_grid_panel.step", &part, &out)
}

#[test]
fn include_and_exclude_only_hide_rows() {
    let all = report_with(vec![], vec![]);
    let ids = |r: &thinwall_report::RecognitionReport| -> Vec<String> {
        r.stiffness_features
            .iter()
            .map(|e| e.feature.id.to_string())
            .collect()
    };
    let only_holes = report_with(vec![Kind::Hole], vec![]);
    assert_eq!(only_holes.stiffness_features.len(), 3);
    assert!(only_holes
        .stiffness_features
        .iter()
        .all(|e| e.feature.kind == Kind::Hole));
    // Hiding the web and the cut-outs: the other rows, ids and links stay
    // exactly as in the whole report (no rib becomes the base of a rib).
    let no_web = report_with(vec![], vec![Kind::Web, Kind::Cutout]);
    let kept: Vec<String> = all
        .stiffness_features
        .iter()
        .filter(|e| !matches!(e.feature.kind, Kind::Web | Kind::Cutout))
        .map(|e| e.feature.id.to_string())
        .collect();
    assert_eq!(ids(&no_web), kept);
    let hidden = |id: &thinwall_recognize::FeatureId| matches!(id.kind, Kind::Web | Kind::Cutout);
    let expected: Vec<_> = all
        .connections
        .iter()
        .filter(|c| match c {
            thinwall_connect::Connection::BaseLeaf { base, leaf } => !hidden(base) && !hidden(leaf),
            thinwall_connect::Connection::Crossing { features } => !features.iter().any(hidden),
        })
        .cloned()
        .collect();
    assert!(!expected.is_empty() && expected.len() < all.connections.len());
    assert_eq!(no_web.connections, expected);
    // Ribs and flanges only: the same walls, the same links among them.
    let walls = report_with(vec![Kind::Rib, Kind::Flange], vec![]);
    for c in &walls.connections {
        assert!(all.connections.contains(c), "{c:?} not in the whole report");
    }
    assert!(walls
        .machining_features
        .iter()
        .flat_map(|m| &m.related)
        .all(|r| matches!(r.kind, Kind::Rib | Kind::Flange)));
    // Contradictory filters are an error.
    let mut req = thinwall_pipeline::Request::default();
    req.config.include = vec![Kind::Hole];
    req.config.exclude = vec![Kind::Hole];
    let (part, _) =
        thinwall_step::read_file(common::root().join("fixtures/recognition/rib_grid_panel.step"))
            .unwrap();
    let e = thinwall_pipeline::run(&part, None, &req).unwrap_err();
    assert_eq!(e.code(), "config.included_and_excluded");
}
