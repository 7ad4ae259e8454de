//! Dedicated classification on `fixtures/classify/*` (made by
//! `scripts/make_classify_fixtures.py`): every type, stacked and facing
//! volumes with a sequence, a stepped bottom, a volume overlapping the part;
//! each also turned with its up direction.

mod common;

use serde::Deserialize;
use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_classify::{classify, Classification, Request, Touch, Volume, VolumeType};

#[derive(Deserialize)]
struct ExpectedVolume {
    file: String,
    #[serde(rename = "type")]
    kind: String,
    product_adjacency: String,
    bottom_open: bool,
}

#[derive(Deserialize)]
struct Expected {
    up: [f64; 3],
    before: Vec<[usize; 2]>,
    volumes: Vec<ExpectedVolume>,
}

fn run(
    case: &str,
    before_override: Option<Vec<(usize, usize)>>,
) -> (Expected, Vec<Classification>) {
    let dir = common::root().join("fixtures/classify").join(case);
    let exp: Expected =
        serde_json::from_str(&std::fs::read_to_string(dir.join("expected.json")).unwrap()).unwrap();
    let (part, _) = thinwall_step::read_file(dir.join("part.step")).unwrap();
    let volumes: Vec<Volume> = exp
        .volumes
        .iter()
        .map(|v| Volume {
            name: v.file.clone(),
            part: thinwall_step::read_file(dir.join(&v.file)).unwrap().0,
            current: None,
            up: None,
        })
        .collect();
    let before: Vec<(usize, usize)> =
        before_override.unwrap_or_else(|| exp.before.iter().map(|b| (b[0], b[1])).collect());
    let setup = Setup::new(exp.up, Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(&part, setup);
    let r = classify(&Request {
        part: &a,
        volumes: &volumes,
        before: &before,
        together: &[],
        priority: vec![],
    })
    .unwrap();
    (exp, r)
}

#[test]
fn every_classify_fixture_gets_its_type_and_adjacency() {
    let mut problems = Vec::new();
    let mut cases: Vec<String> = std::fs::read_dir(common::root().join("fixtures/classify"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    cases.sort();
    assert!(cases.len() >= 30, "{cases:?}");
    let mut types_seen = std::collections::BTreeSet::new();
    for case in &cases {
        let (exp, r) = run(case, None);
        for (e, c) in exp.volumes.iter().zip(&r) {
            types_seen.insert(c.kind);
            let got = (c.kind.name(), c.product_adjacency.name(), c.bottom_open);
            let want = (e.kind.as_str(), e.product_adjacency.as_str(), e.bottom_open);
            if got != want {
                problems.push(format!(
                    "{case}/{}: got {got:?} ({:?}), expected {want:?}",
                    e.file, c.reason
                ));
            }
        }
    }
    for p in &problems {
        println!("{p}");
    }
    assert!(problems.is_empty(), "{} problems", problems.len());
    for t in [
        VolumeType::Hole,
        VolumeType::Pocket,
        VolumeType::Passage,
        VolumeType::BlindSlot,
        VolumeType::ThroughSlot,
        VolumeType::CornerNotch,
        VolumeType::Step,
        VolumeType::Face,
        VolumeType::FreePocket,
        VolumeType::Unknown,
    ] {
        assert!(types_seen.contains(&t), "no fixture yields {}", t.name());
    }
}

#[test]
fn turned_copies_agree_in_every_figure() {
    for case in ["pocket", "free_pocket", "facing", "stacked", "hole"] {
        let (_, a) = run(case, None);
        let (_, b) = run(&format!("{case}_turned"), None);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(x.kind, y.kind, "{case}");
            assert!(
                (x.depth - y.depth).abs() < 1e-6
                    && (x.length - y.length).abs() < 1e-6
                    && (x.width - y.width).abs() < 1e-6,
                "{case}"
            );
            let closed = |c: &Classification| c.faces.iter().filter(|f| f.closed).count();
            assert_eq!(closed(x), closed(y), "{case}");
        }
    }
}

#[test]
fn the_sequence_decides_who_sees_whom_as_closed() {
    // 0 before 1: 0 is a pocket (1 closes its side), 1 a blind slot.
    let (_, r) = run("facing", None);
    assert_eq!(
        (r[0].kind, r[1].kind),
        (VolumeType::Pocket, VolumeType::BlindSlot)
    );
    let shared = r[1]
        .faces
        .iter()
        .find(|f| {
            f.touches
                .iter()
                .any(|t| matches!(t, Touch::Volume { index: 0, .. }))
        })
        .unwrap();
    assert!(!shared.closed, "a face touching a predecessor is open");
    // Reversed sequence: the roles swap (re-classification, Popma fig. 5.11).
    let (_, r) = run("facing", Some(vec![(1, 0)]));
    assert_eq!(
        (r[0].kind, r[1].kind),
        (VolumeType::BlindSlot, VolumeType::Pocket)
    );
    // No sequence: each sees the other as closed: two pockets.
    let (_, r) = run("facing", Some(vec![]));
    assert_eq!(
        (r[0].kind, r[1].kind),
        (VolumeType::Pocket, VolumeType::Pocket)
    );
}

#[test]
fn stacked_volumes_report_depth_sizes_and_touches() {
    let (_, r) = run("stacked", None);
    assert!((r[0].depth - 10.0).abs() < 1e-9 && (r[1].depth - 10.0).abs() < 1e-9);
    assert!((r[0].length - 40.0).abs() < 1e-9 && (r[0].width - 40.0).abs() < 1e-9);
    assert_eq!(r[0].product_adjacent_sides.len(), 4);
    // The upper's bottom touches the lower volume, closed (lower not removed before it).
    let bottom = r[0]
        .faces
        .iter()
        .find(|f| f.role == thinwall_classify::FaceRole::Bottom)
        .unwrap();
    assert!(
        bottom.closed
            && bottom
                .touches
                .iter()
                .all(|t| matches!(t, Touch::Volume { index: 1, .. }))
    );
}

#[test]
fn unknown_volumes_keep_their_adjacency_and_say_why() {
    let (_, r) = run("overlap", None);
    assert_eq!(r[0].kind, VolumeType::Unknown);
    assert!(r[0]
        .reason
        .as_deref()
        .unwrap()
        .contains("overlaps part material"));
    assert!(r[0].faces.iter().any(|f| f.closed && !f.touches.is_empty()));
    let (_, r) = run("stepped_bottom", None);
    assert!(r[0].reason.as_deref().unwrap().contains("stepped bottom"));
}

#[test]
fn current_type_is_kept_while_it_still_fits() {
    let dir = common::root().join("fixtures/classify/blind_slot");
    let (part, _) = thinwall_step::read_file(dir.join("part.step")).unwrap();
    let v = thinwall_step::read_file(dir.join("v0.step")).unwrap().0;
    let volumes = vec![Volume {
        name: "v0".into(),
        part: v,
        current: Some(VolumeType::Step),
        up: None,
    }];
    let a = PartAnalysis::new(&part, Setup::default());
    let r = classify(&Request {
        part: &a,
        volumes: &volumes,
        before: &[],
        together: &[],
        priority: vec![],
    })
    .unwrap();
    // A U of closed sides is also a chain: a volume already typed a step stays one.
    assert_eq!(r[0].kind, VolumeType::Step);
    let e = classify(&Request {
        part: &a,
        volumes: &volumes,
        before: &[(0, 3)],
        together: &[],
        priority: vec![],
    })
    .unwrap_err();
    assert_eq!(e.code(), "sequence");
}

/// Classify `volumes` (paths under fixtures/classify) against `part`.
fn request_error(
    part: &str,
    volumes: &[&str],
    before: &[(usize, usize)],
) -> thinwall_classify::ClassifyError {
    let dir = common::root().join("fixtures/classify");
    let (p, _) = thinwall_step::read_file(dir.join(part)).unwrap();
    let vols: Vec<Volume> = volumes
        .iter()
        .map(|v| Volume {
            name: v.to_string(),
            part: match *v {
                "bracket_assembly" => {
                    thinwall_step::read_file(common::root().join("fixtures/bracket_assembly.step"))
                }
                _ => thinwall_step::read_file(dir.join(v)),
            }
            .unwrap()
            .0,
            current: None,
            up: None,
        })
        .collect();
    let a = PartAnalysis::new(&p, Setup::default());
    classify(&Request {
        part: &a,
        volumes: &vols,
        before,
        together: &[],
        priority: vec![],
    })
    .unwrap_err()
}

#[test]
fn requests_that_make_no_sense_are_refused_with_the_right_message() {
    let two = ["stacked/v0.step", "stacked/v1.step"];
    let e = request_error("stacked/part.step", &two, &[(0, 1), (1, 0)]);
    assert_eq!(e.code(), "cycle", "{e}");
    let e = request_error("stacked/part.step", &two, &[(0, 0)]);
    assert_eq!(e.code(), "self_pair");
    assert_eq!(e.to_string(), "volume 0 cannot be removed before itself");
    let e = request_error("stacked/part.step", &two, &[(0, 2)]);
    assert_eq!(e.code(), "sequence");
    let e = request_error(
        "stacked/part.step",
        &["stacked/v0.step", "stacked/v0.step"],
        &[],
    );
    assert_eq!(e.code(), "duplicate");
    let e = request_error("stacked/part.step", &["stacked/part.step"], &[]);
    assert_eq!(e.code(), "part_as_volume");
    let e = request_error("stacked/part.step", &["bracket_assembly"], &[]);
    assert_eq!(e.code(), "multi_body");
    let e = request_error(
        "pocket/part.step",
        &["pocket/v0.step", "stacked/v0.step"],
        &[],
    );
    assert_eq!(e.code(), "overlap", "{e}");
}

#[test]
fn volumes_removed_together_leave_the_face_between_them_open() {
    let dir = common::root().join("fixtures/classify/stacked");
    let (part, _) = thinwall_step::read_file(dir.join("part.step")).unwrap();
    let volumes: Vec<Volume> = ["v0.step", "v1.step"]
        .iter()
        .map(|f| Volume {
            name: f.to_string(),
            part: thinwall_step::read_file(dir.join(f)).unwrap().0,
            current: None,
            up: None,
        })
        .collect();
    let a = PartAnalysis::new(&part, Setup::default());
    let run = |before: &[(usize, usize)], together: &[(usize, usize)]| {
        classify(&Request {
            part: &a,
            volumes: &volumes,
            before,
            together,
            priority: vec![],
        })
        .unwrap()
    };
    // v0 above v1, removed first: its bottom is closed by v1.
    let apart = run(&[(0, 1)], &[]);
    assert!(!apart[0].bottom_open);
    // Removed together (one feature's solids): the face between is open.
    let together = run(&[], &[(0, 1)]);
    assert!(together[0].bottom_open, "{:?}", together[0].kind);
    assert_eq!(together[1].kind, apart[1].kind);
    let e = classify(&Request {
        part: &a,
        volumes: &volumes,
        before: &[],
        together: &[(0, 5)],
        priority: vec![],
    })
    .unwrap_err();
    assert_eq!(e.code(), "sequence");
}
