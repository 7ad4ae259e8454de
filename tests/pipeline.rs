//! The library entry point: what planners get besides the JSON (each wall's
//! region, side polygons and foot line), the links from machining features
//! to the stiffness features on their faces, the same answer on a turned
//! copy, and typed errors.

mod common;

use geo::Area;
use std::collections::BTreeSet;
use thinwall_analysis::{Machine, Setup};
use thinwall_pipeline::{run, Outcome, PipelineError, Request};

fn outcome(name: &str) -> (thinwall_brep::Part, Outcome) {
    let (part, setup) = common::recognition_fixture(name);
    let req = Request {
        setup,
        ..Request::default()
    };
    let out = run(&part, None, &req).unwrap();
    (part, out)
}

#[test]
fn walls_keep_their_region_side_polygons_and_foot() {
    let (_, out) = outcome("rib_grid_panel");
    let walls: Vec<_> = out
        .recognition
        .features
        .iter()
        .filter(|f| f.kind.is_wall())
        .collect();
    assert!(walls.len() >= 8);
    for f in walls {
        let g = f.geometry.as_ref().expect("a wall keeps its geometry");
        assert_eq!(Some(g.thickness), f.thickness, "{}", f.id);
        assert!(g.region.unsigned_area() > 0.0, "{}", f.id);
        // Every side face has its polygon, in the wall's frame.
        for (k, side) in g.side_polygons.iter().enumerate() {
            assert_eq!(side.len(), f.sides.as_ref().unwrap()[k].len(), "{}", f.id);
            assert!(side.iter().all(|(_, p)| p.unsigned_area() > 0.0));
        }
        // The outline lies on the mid-plane.
        let mid = f.mid_plane.as_ref().unwrap();
        let n = thinwall_geom::Vector3::from(mid.normal);
        let p = thinwall_geom::Point3::from(mid.point);
        for q in g.outline() {
            assert!((q - p).dot(&n).abs() < 1e-9, "{}", f.id);
        }
        // A wall on a base has a foot as long as the wall, on the mid-plane.
        match (f.base, g.foot) {
            (Some(_), Some([a, b])) => {
                let len = (b - a).norm();
                assert!((len - f.length.unwrap()).abs() < 1e-6, "{}: {len}", f.id);
                assert!((a - p).dot(&n).abs() < 1e-9 && (b - p).dot(&n).abs() < 1e-9);
            }
            (None, _) => {}
            (Some(_), None) => panic!("{}: a wall on a base without a foot", f.id),
        }
    }
}

#[test]
fn machining_features_name_the_stiffness_features_on_their_faces() {
    let mut linked = 0;
    for name in [
        "rib_grid_panel",
        "c_frame",
        "filleted_chamfered_rib",
        "notched_rib",
    ] {
        let (_, out) = outcome(name);
        for m in &out.machining {
            let faces: BTreeSet<u64> = m.faces.iter().copied().collect();
            let want: BTreeSet<String> = out
                .recognition
                .features
                .iter()
                .filter(|f| f.faces.iter().any(|x| faces.contains(x)))
                .map(|f| f.id.to_string())
                .collect();
            let got: BTreeSet<String> = m.related.iter().map(|r| r.to_string()).collect();
            assert_eq!(got, want, "{name} {}", m.id);
            linked += got.len();
            // And the other way round.
            for f in &out.recognition.features {
                assert_eq!(
                    f.related.contains(&m.id),
                    want.contains(&f.id.to_string()),
                    "{name} {} {}",
                    f.id,
                    m.id
                );
            }
        }
        // In the JSON too.
        let (part, _) = thinwall_step::read_file(
            common::root().join(format!("fixtures/recognition/{name}.step")),
        )
        .unwrap();
        let json = thinwall_report::recognition_report(name, &part, &out).to_json();
        assert!(json.contains("\"related\": ["), "{name}");
    }
    assert!(linked > 10, "{linked} links");
}

#[test]
fn a_turned_copy_gets_the_same_wall_geometry() {
    let (_, a) = outcome("rib_grid_panel");
    let (_, b) = outcome("rib_grid_panel_turned");
    // Areas to 1e-3 mm² (polygon operations in turned frames round differently).
    let summary = |o: &Outcome| {
        let mut v: Vec<String> = o
            .recognition
            .features
            .iter()
            .filter_map(|f| {
                let g = f.geometry.as_ref()?;
                let foot = g.foot.map_or(0.0, |[p, q]| (q - p).norm());
                Some(format!(
                    "{} {:.3} {:.6} {:.6} {}",
                    f.id,
                    g.region.unsigned_area(),
                    foot,
                    g.thickness,
                    g.side_polygons[0].len() + g.side_polygons[1].len()
                ))
            })
            .collect();
        v.sort();
        v
    };
    assert_eq!(summary(&a), summary(&b));
}

#[test]
fn bad_settings_are_typed_errors() {
    let (part, _) =
        thinwall_step::read_file(common::root().join("fixtures/recognition/thin_plate.step"))
            .unwrap();
    let mut req = Request::default();
    req.config.thinness.force_n = -1.0;
    let e = run(&part, None, &req).unwrap_err();
    assert!(matches!(e, PipelineError::Config(_)), "{e:?}");
    assert_eq!(e.code(), "config.not_positive");
    let mut req = Request::default();
    req.setup.up = [0.0, 0.0, 0.0];
    let e = run(&part, None, &req).unwrap_err();
    assert_eq!(e.code(), "setup.zero_up");
    // Serial and parallel runs agree.
    let serial = Request {
        parallel: false,
        ..Request::default()
    };
    let a = run(&part, None, &serial).unwrap();
    let b = run(&part, None, &Request::default()).unwrap();
    assert_eq!(a.recognition.features, b.recognition.features);
    assert_eq!(a.machining, b.machining);
    assert_eq!(a.face_props, b.face_props);
}

#[test]
fn assembly_instances_are_told_apart_and_never_spanned() {
    let path = common::root().join("fixtures/bracket_assembly.step");
    let (part, _) = thinwall_step::read_file(&path).unwrap();
    assert_eq!(part.bodies.len(), 2, "two placed instances");
    let out = run(&part, None, &Request::default()).unwrap();
    let report = thinwall_report::recognition_report("bracket_assembly.step", &part, &out);
    assert_eq!(report.bodies.len(), 2);
    assert!(report.bodies.iter().all(|b| b.placement.is_some()));
    // Every feature's faces are faces of its own body.
    let of_body = |b: u32| -> BTreeSet<u64> {
        part.faces
            .iter()
            .filter(|f| f.body.0 == b)
            .map(|f| f.step_id)
            .collect()
    };
    for f in &out.recognition.features {
        let own = of_body(f.body);
        assert!(
            f.faces.iter().all(|x| own.contains(x)),
            "{} spans bodies",
            f.id
        );
    }
    for m in &out.machining {
        let own = of_body(m.body);
        assert!(
            m.faces.iter().all(|x| own.contains(x)),
            "{} spans bodies",
            m.id
        );
    }
    // The instances share STEP ids: features on the same ids differ by body.
    let mut seen: std::collections::BTreeMap<Vec<u64>, BTreeSet<u32>> = Default::default();
    for f in &out.recognition.features {
        seen.entry(f.faces.clone()).or_default().insert(f.body);
    }
    assert!(seen.values().any(|bodies| bodies.len() == 2));
    // No wall is longer than one bracket (120 mm): none spans both.
    for f in out.recognition.features.iter().filter(|f| f.kind.is_wall()) {
        assert!(
            f.length.unwrap() <= 120.0 + 1e-6,
            "{} L {:?}",
            f.id,
            f.length
        );
    }
    // And the JSON carries bodies and every face's body.
    let json: serde_json::Value = serde_json::from_str(&report.to_json()).unwrap();
    assert_eq!(json["bodies"].as_array().unwrap().len(), 2);
    assert!(json["faces"]
        .as_array()
        .unwrap()
        .iter()
        .all(|f| f["body"].is_u64()));
}

#[test]
fn the_two_views_never_disagree_without_a_note() {
    let mut parts = common::step_files(&common::root().join("fixtures/recognition"));
    parts.extend(
        common::step_files(&common::shared_data().join("nist"))
            .into_iter()
            .filter(|f| !f.to_string_lossy().contains("-tg")),
    );
    let mut noted = 0;
    for path in parts {
        let (part, _) = thinwall_step::read_file(&path).unwrap();
        let out = run(&part, None, &Request::default()).unwrap();
        for m in &out.machining {
            for id in &m.related {
                let f = out.recognition.feature(*id).unwrap();
                if !f.kind.agrees_with(m.kind) {
                    let prefix = format!("{} ({}) and {} (", f.id, f.kind, m.id);
                    assert!(
                        out.view_notes.iter().any(|n| n.starts_with(&prefix)),
                        "{}: {} and {} disagree without a note",
                        path.display(),
                        f.id,
                        m.id
                    );
                    noted += 1;
                }
            }
        }
        assert_eq!(out.view_notes.len(), {
            let mut n = 0;
            for m in &out.machining {
                n += m
                    .related
                    .iter()
                    .filter(|id| {
                        !out.recognition
                            .feature(**id)
                            .unwrap()
                            .kind
                            .agrees_with(m.kind)
                    })
                    .count();
            }
            n
        });
    }
    assert!(noted > 0, "no disagreement at all: the check is idle");
}

/// Sorted (kind, profile, through, depth, length, width) of machining
/// features, and (kind, height, length, width) of stiffness details.
fn sizes(out: &Outcome) -> (Vec<String>, Vec<String>) {
    let mut m: Vec<String> = out
        .machining
        .iter()
        .map(|m| {
            format!(
                "{} {} {} {:.4} {:.4} {:.4}",
                m.kind, m.profile, m.through, m.depth, m.length, m.width
            )
        })
        .collect();
    let mut s: Vec<String> = out
        .recognition
        .features
        .iter()
        .filter(|f| !f.kind.is_wall())
        .map(|f| {
            format!(
                "{} {:.4?} {:.4?} {:.4?}",
                f.kind, f.height, f.length, f.width
            )
        })
        .collect();
    m.sort();
    s.sort();
    (m, s)
}

#[test]
fn turned_copies_get_the_same_machining_features_and_details() {
    // A fixture turned by OpenCascade, and one turned here (its STEP text).
    let read = |rel: &str| {
        thinwall_step::read_file(common::root().join(rel))
            .unwrap()
            .0
    };
    let run_default = |p: &thinwall_brep::Part| run(p, None, &Request::default()).unwrap();
    let (a, b) = (
        read("fixtures/bracket_with_pocket.step"),
        read("fixtures/bracket_turned.step"),
    );
    assert_eq!(sizes(&run_default(&a)).0, sizes(&run_default(&b)).0);
    let text =
        std::fs::read_to_string(common::root().join("fixtures/recognition/engraved_plate.step"))
            .unwrap();
    let (r, t) = common::rigid_motion(7);
    let (turned, n) = common::turned_step(&text, &r, &t);
    assert!(n > 100);
    let plate = thinwall_step::read_bytes(text.as_bytes(), "plate.step")
        .unwrap()
        .0;
    let turned = thinwall_step::read_bytes(turned.as_bytes(), "turned.step")
        .unwrap()
        .0;
    let up = r * thinwall_geom::Vector3::z();
    let turned_req = Request {
        setup: Setup::new([up.x, up.y, up.z], Machine::ThreeAxis).unwrap(),
        ..Request::default()
    };
    let (x, y) = (
        sizes(&run_default(&plate)),
        sizes(&run(&turned, None, &turned_req).unwrap()),
    );
    assert!(x.1.iter().any(|d| d.starts_with("engraving")), "{:?}", x.1);
    assert_eq!(x, y);
}
