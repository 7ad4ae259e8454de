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

#[test]
fn include_and_exclude_filter_kinds() {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let (part, _) = thinwall_step::read_file(&path).unwrap();
    let only_holes = common::recognize_with(
        &part,
        [0.0, 0.0, 1.0],
        &Config {
            include: vec![Kind::Hole],
            ..Config::default()
        },
    );
    assert_eq!(only_holes.features.len(), 3);
    assert!(only_holes.features.iter().all(|f| f.kind == Kind::Hole));
    let no_ribs = common::recognize_with(
        &part,
        [0.0, 0.0, 1.0],
        &Config {
            exclude: vec![Kind::Rib, Kind::Cutout],
            ..Config::default()
        },
    );
    assert!(no_ribs
        .features
        .iter()
        .all(|f| f.kind != Kind::Rib && f.kind != Kind::Cutout));
    assert!(no_ribs.features.iter().any(|f| f.kind == Kind::Web));
}
