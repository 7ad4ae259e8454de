//! The HTML report (issue 15): one self-contained file, every face's
//! geometry in it, every feature present and linked to faces that are
//! drawn; the plan's and the classification's volumes likewise.

mod common;

use scraper::{Html, Selector};
use serde_json::Value;
use std::collections::HashSet;
use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_report::html;

fn read(path: &std::path::Path) -> thinwall_brep::Part {
    thinwall_step::read_file(path).unwrap().0
}

fn recognition(path: &std::path::Path) -> (thinwall_brep::Part, thinwall_pipeline::Outcome) {
    let part = read(path);
    let out = thinwall_pipeline::run(&part, None, &thinwall_pipeline::Request::default()).unwrap();
    (part, out)
}

/// Nothing in the page refers to another file or the network: no element
/// with a `src` or `href`, no stylesheet or frame, no `url(`/`@import` in
/// the style, and the only addresses anywhere are the XML namespaces the
/// viewer passes to `createElementNS` (identifiers, never fetched).
fn assert_self_contained(page: &str) {
    let doc = Html::parse_document(page);
    assert!(doc.errors.is_empty(), "HTML errors: {:?}", doc.errors);
    let any = |s: &str| doc.select(&Selector::parse(s).unwrap()).count();
    assert_eq!(any("[src]"), 0, "an element loads another file");
    assert_eq!(any("[href]"), 0, "an element links another file");
    assert_eq!(any("link, iframe, object, embed, img, base"), 0);
    for style in doc.select(&Selector::parse("style").unwrap()) {
        let css = style.inner_html();
        assert!(!css.contains("url(") && !css.contains("@import"));
    }
    let mut at = 0;
    while let Some(i) = page[at..].find("http") {
        let rest = &page[at + i..];
        let end = rest.find(['"', '\'', ' ', ')']).unwrap_or(rest.len());
        let address = &rest[..end];
        assert!(
            matches!(
                address,
                "http://www.w3.org/2000/svg" | "http://www.w3.org/1999/xhtml"
            ),
            "an address in the page: {address}"
        );
        at += i + 4;
    }
    // Three scripts (three.js, the data, the viewer), all inline, none of
    // which the HTML parser ends early.
    let scripts: Vec<_> = doc.select(&Selector::parse("script").unwrap()).collect();
    assert_eq!(scripts.len(), 3);
    for s in &scripts {
        assert!(!s.inner_html().contains("<!--"));
    }
    assert!(scripts[0].inner_html().contains("window.THREE"));
    assert!(scripts[0]
        .inner_html()
        .contains("Permission is hereby granted"));
}

/// Every face of `part` in the geometry, with triangles over its own
/// points.
fn assert_every_face_drawn(part: &thinwall_brep::Part, geometry: &Value) -> HashSet<(u64, u64)> {
    let faces = geometry["faces"].as_array().unwrap();
    assert_eq!(faces.len(), part.faces.len());
    let mut keys = HashSet::new();
    for f in faces {
        let points = f["points"].as_array().unwrap().len();
        let triangles = f["triangles"].as_array().unwrap();
        assert!(
            !triangles.is_empty() && triangles.len() % 3 == 0 && points % 3 == 0,
            "face #{} not drawn: {:?}",
            f["step_id"],
            f["issue"]
        );
        assert!(triangles
            .iter()
            .all(|t| (t.as_u64().unwrap() as usize) < points / 3));
        keys.insert((f["body"].as_u64().unwrap(), f["step_id"].as_u64().unwrap()));
    }
    let expected: HashSet<(u64, u64)> = part
        .face_ids()
        .map(|f| (part.face(f).body.0 as u64, part.face(f).step_id))
        .collect();
    assert_eq!(keys, expected);
    assert_eq!(
        geometry["edges"].as_array().unwrap().len(),
        part.edges.len()
    );
    keys
}

fn assert_features_linked(list: &Value, drawn: &HashSet<(u64, u64)>, what: &str) -> usize {
    let list = list.as_array().unwrap();
    for f in list {
        let body = f["body"].as_u64().unwrap_or(0);
        let faces = f["faces"].as_array().unwrap();
        assert!(!faces.is_empty(), "{what} {} has no faces", f["id"]);
        for s in faces {
            assert!(
                drawn.contains(&(body, s.as_u64().unwrap())),
                "{what} {}: face #{s} not in the picture",
                f["id"]
            );
        }
    }
    list.len()
}

#[test]
fn recognition_page_is_one_file_with_every_face_and_feature() {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let (part, out) = recognition(&path);
    let report = thinwall_report::recognition_report("rib_grid_panel.step", &part, &out);
    let a = PartAnalysis::new(&part, out.setup.clone());
    let page = html::recognition_page("rib grid panel", &a, &report);
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert_self_contained(&page);
    let data = html::data_of(&page).expect("the data block parses");
    assert_eq!(data["schema"], html::HTML_DATA_SCHEMA);
    assert_eq!(data["view"], "recognition");
    let drawn = assert_every_face_drawn(&part, &data["part"]);
    let rec = &data["recognition"];
    let n = assert_features_linked(&rec["stiffness_features"], &drawn, "stiffness feature");
    assert_eq!(n, report.stiffness_features.len());
    assert_eq!(n, 13, "web, 3 ribs, 4 flanges, 3 holes, 2 cut-outs");
    let m = assert_features_linked(&rec["machining_features"], &drawn, "machining feature");
    assert_eq!(m, report.machining_features.len());
    assert!(m > 0);
    assert_eq!(
        rec["connections"].as_array().unwrap().len(),
        report.connections.len()
    );
    // Every kind shown has its colour.
    for f in rec["stiffness_features"].as_array().unwrap() {
        let key = format!("stiffness.{}", f["kind"].as_str().unwrap());
        assert!(data["palette"][&key].is_string(), "no colour for {key}");
    }
}

#[test]
fn plan_page_draws_every_machining_feature_in_order() {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let (part, out) = recognition(&path);
    let report = thinwall_report::recognition_report("rib_grid_panel.step", &part, &out);
    let a = PartAnalysis::new(&part, out.setup.clone());
    let plan = thinwall_plan::plan(
        "rib_grid_panel.step",
        &a,
        &out,
        &thinwall_plan::RuleSet::default_rules(),
    )
    .expect("a plan");
    let page = html::plan_page("plan", &a, &report, &plan);
    assert_self_contained(&page);
    let data = html::data_of(&page).unwrap();
    assert_eq!(data["view"], "plan");
    assert_every_face_drawn(&part, &data["part"]);
    let volumes = data["volumes"].as_array().unwrap();
    assert_eq!(volumes.len(), plan.machining_features.len());
    assert!(volumes.len() > 10);
    for (v, f) in volumes.iter().zip(&plan.machining_features) {
        assert_eq!(v["id"], f.id.as_str());
        // Every solid of this planar part is written, so every feature is
        // drawn, and closed: each triangle side used once each way.
        let g = &v["geometry"];
        assert!(g.is_object(), "{} not drawn: {}", f.id, v["note"]);
        assert_eq!(
            g["faces"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|x| x["triangles"].as_array().unwrap().is_empty())
                .count(),
            0
        );
    }
    let order = data["plan"]["feature_sequence"]["order"]
        .as_array()
        .unwrap();
    assert_eq!(order.len(), plan.machining_features.len());
}

#[test]
fn classification_page_shows_each_volume_with_its_faces() {
    let dir = common::root().join("fixtures/classify/stacked");
    let part = read(&dir.join("part.step"));
    let volumes: Vec<thinwall_classify::Volume> = ["v0.step", "v1.step"]
        .iter()
        .map(|v| thinwall_classify::Volume {
            name: v.to_string(),
            part: read(&dir.join(v)),
            current: None,
            up: None,
        })
        .collect();
    let setup = Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(&part, setup);
    let result = thinwall_classify::classify(&thinwall_classify::Request {
        part: &a,
        volumes: &volumes,
        before: &[(0, 1)],
        together: &[],
        priority: vec![],
    })
    .unwrap();
    let report =
        thinwall_report::ClassificationReport::new("part.step", [0.0, 0.0, 1.0], &[(0, 1)], result);
    let parts: Vec<&thinwall_brep::Part> = volumes.iter().map(|v| &v.part).collect();
    let page = html::classification_page("stacked", &a, &report, &parts);
    assert_self_contained(&page);
    let data = html::data_of(&page).unwrap();
    assert_eq!(data["view"], "classification");
    assert_every_face_drawn(&part, &data["part"]);
    for (k, v) in data["volumes"].as_array().unwrap().iter().enumerate() {
        let drawn = assert_every_face_drawn(&volumes[k].part, &v["geometry"]);
        let c = &data["classification"]["volumes"][k];
        let faces = c["faces"].as_array().unwrap();
        assert_eq!(faces.len(), drawn.len());
        assert!(faces.iter().any(|f| f["closed"] == true));
        assert!(faces.iter().any(|f| f["closed"] == false));
        for f in faces {
            assert!(drawn.contains(&(0, f["step_id"].as_u64().unwrap())));
        }
    }
}

#[test]
fn a_title_cannot_break_out_of_the_page() {
    let path = common::root().join("fixtures/recognition/thin_plate.step");
    let (part, out) = recognition(&path);
    let evil = "</title><script src=\"x.js\"></script></script><!--";
    let report = thinwall_report::recognition_report(evil, &part, &out);
    let a = PartAnalysis::new(&part, out.setup.clone());
    let page = html::recognition_page(evil, &a, &report);
    assert_self_contained(&page);
    let data = html::data_of(&page).unwrap();
    assert_eq!(data["title"], evil);
    assert_eq!(data["recognition"]["part"]["file"], evil);
}

#[test]
fn access_page_colours_every_planar_face_and_outlines_g_zones() {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let part = read(&path);
    let setup = Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(&part, setup.clone());
    let mesh = thinwall_brep::tessellate::part_mesh(&part);
    let options = thinwall_access::FlankOptions::default();
    let faces = thinwall_access::flank_milling(&a, &mesh, &options);
    let reach_opts = thinwall_access::reach::ReachOptions::default();
    let reached = thinwall_access::reach::reach(&a, &mesh, &reach_opts).unwrap();
    let settings = thinwall_report::access::ReachSettings {
        tool: reach_opts.tool.clone(),
        machine: reach_opts.machine,
    };
    let report = thinwall_report::access::AccessReport::new(
        "rib_grid_panel.step",
        setup.up,
        options,
        faces,
        settings,
        thinwall_report::access::ReachResult {
            faces: reached,
            ..Default::default()
        },
    );
    let page = html::access_page("access", &a, &report);
    assert_self_contained(&page);
    let data = html::data_of(&page).unwrap();
    assert_eq!(data["view"], "access");
    let drawn = assert_every_face_drawn(&part, &data["part"]);
    // Every face's reach travels with the page.
    assert_eq!(
        data["access"]["faces"].as_array().unwrap().len(),
        part.face_ids().count()
    );
    let planar = data["access"]["planar_faces"].as_array().unwrap();
    assert_eq!(planar.len(), report.planar_faces.len());
    for f in planar {
        let key = (f["body"].as_u64().unwrap(), f["face"].as_u64().unwrap());
        assert!(drawn.contains(&key), "face {key:?} not drawn");
        // A face left partly unreached carries its G-zone's outline.
        let g = f["g_zone_mm2"].as_f64().unwrap();
        if f["nature"] != "closed" && g > 1e-6 {
            assert!(!f["g_zone"].as_array().unwrap().is_empty(), "{}", f["face"]);
        }
    }
    // A planar face the tool does not reach whole (more than 1e-4 of it
    // left) carries the outline of what it misses (the Reach view draws it).
    let mut outlined = 0;
    for f in data["access"]["faces"].as_array().unwrap() {
        let planar = f["contact"] == "floor" || f["contact"] == "side";
        if planar && f["fraction"].as_f64().unwrap() < 1.0 - 1e-4 {
            let rings = f["unreachable"].as_array().map_or(0, Vec::len);
            assert!(rings > 0, "face #{}", f["face"]);
            outlined += 1;
        }
    }
    assert!(outlined > 0);
    for key in [
        "access.advisable",
        "access.partial",
        "access.blocked",
        "access.closed",
        "reach.whole",
        "reach.most",
        "reach.part",
        "reach.none",
    ] {
        assert!(data["palette"][key].is_string());
    }
}

/// The operations page of the drill plate: self-contained, the report's
/// operations in it in order, every pass's fields there to draw (each a
/// closed contour of at least three points), the drilled holes with
/// their axes, and a colour for each stage.
#[test]
fn operations_page_holds_every_operation_and_its_fields() {
    let part = read(&common::root().join("fixtures/ops/drill_plate.step"));
    let a = PartAnalysis::new(
        &part,
        Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
    );
    let lib = thinwall_ops::ToolLibrary::default_tools();
    let holes = common::features_in_setup(&a);
    let (frame, ops) = thinwall_ops::plan_setup(&a, &holes, &lib, None, &[]).unwrap();
    let count = ops.operations.len();
    let report = thinwall_report::operations::OperationsReport::new(
        "plate",
        [0.0, 0.0, 1.0],
        &frame,
        lib,
        ops,
    );
    let page = html::operations_page("operations", &a, &report);
    assert_self_contained(&page);
    let data = html::data_of(&page).expect("the page's data");
    assert_eq!(data["view"], "operations");
    let setup = &data["operations"]["setup"];
    let listed = setup["operations"].as_array().unwrap();
    assert_eq!(listed.len(), count);
    let mut drills = 0;
    for (k, o) in listed.iter().enumerate() {
        assert_eq!(o["step"].as_u64(), Some(k as u64 + 1));
        for p in o["passes"].as_array().unwrap() {
            let layer = &setup["layers"][p["layer"].as_u64().unwrap() as usize];
            for j in p["fields"].as_array().unwrap() {
                let f = &layer["fields"][j.as_u64().unwrap() as usize];
                assert!(f["outer"]["points"].as_array().unwrap().len() >= 3);
            }
        }
        if o["stage"] == "drill" {
            drills += 1;
            for h in o["holes"].as_array().unwrap() {
                assert!(setup["holes"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .any(|s| &s["id"] == h && s["centre"].is_array()));
            }
        }
        assert!(data["palette"][format!("ops.{}", o["stage"].as_str().unwrap())].is_string());
    }
    // Five drilling operations and a spot before the drills at each of
    // the two levels holes are entered from.
    assert_eq!(drills, 7);
}

/// The operations page of a panel pocketed from both sides, planned one
/// side after the other: its data holds the second set-up (up reversed,
/// its frame, its own operations with fields to draw), which the page
/// shows as a tab of its own.
#[test]
fn operations_page_holds_the_second_side() {
    let path = common::root().join("fixtures/pockets/pockets_4.step");
    let part = read(&path);
    let loaded = thinwall_study::LoadedPart::read_file(&path).unwrap();
    let study = thinwall_study::Study::new(&loaded);
    let mut req = thinwall_study::OperationsRequest::new(Setup::default());
    req.later_ups = vec![[0.0, 0.0, -1.0]];
    let report = thinwall_study::operations(&study, &req).unwrap().report;
    let count = report.then[0].setup.operations.len();
    assert!(count > 0 && report.setup.out_of_reach_mm3 > 0.0);
    let a = PartAnalysis::new(
        &part,
        Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
    );
    let page = html::operations_page("operations", &a, &report);
    assert_self_contained(&page);
    assert!(page.contains("'Set-up ' + (k + 2)"));
    let data = html::data_of(&page).expect("the page's data");
    let second = &data["operations"]["then"][0];
    assert_eq!(second["up"][2], -1.0);
    assert_eq!(second["frame"].as_array().map(Vec::len), Some(4));
    let listed = second["setup"]["operations"].as_array().unwrap();
    assert_eq!(listed.len(), count);
    let layers = second["setup"]["layers"].as_array().unwrap();
    for o in listed {
        for p in o["passes"].as_array().unwrap() {
            let layer = &layers[p["layer"].as_u64().unwrap() as usize];
            for j in p["fields"].as_array().unwrap() {
                let f = &layer["fields"][j.as_u64().unwrap() as usize];
                assert!(f["outer"]["points"].as_array().unwrap().len() >= 3);
            }
        }
    }
}
