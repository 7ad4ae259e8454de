//! Step-approach layers as solids (truck sweeps, written as STEP by
//! truck-stepio): our reader reads each back as one closed solid of the
//! layer's volume, in any pose.

mod common;

use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_plan::{plan, volumes, RuleSet};

/// Volume of a closed solid with planar faces: Σ (n · c) A / 3.
fn volume(part: &thinwall_brep::Part) -> f64 {
    let a = PartAnalysis::new(part, Setup::default());
    part.face_ids()
        .map(|f| {
            let p = a.props(f);
            let n = p.normal.expect("a box has planar faces");
            n.dot(&p.centroid.coords) * p.area / 3.0
        })
        .sum()
}

fn layers_read_back(text: &str, up: [f64; 3]) -> usize {
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    let req = thinwall_pipeline::Request {
        setup: Setup::new(up, thinwall_analysis::Machine::ThreeAxis).unwrap(),
        ..Default::default()
    };
    let out = thinwall_pipeline::run(&part, None, &req).unwrap();
    let p = plan("part.step", &part, &out, &RuleSet::default_rules());
    for l in &p.layers {
        let step = volumes::layer_step(l);
        let (solid, _) = thinwall_step::read_bytes(step.as_bytes(), "layer.step")
            .unwrap_or_else(|e| panic!("{}: {e}", l.id));
        assert_eq!(solid.faces.len(), 6, "{}", l.id);
        let a = PartAnalysis::new(&solid, Setup::default());
        assert!(a.free_edges().is_empty(), "{}: open", l.id);
        let want = l.width * l.height * l.length;
        let got = volume(&solid);
        assert!(
            (got - want).abs() <= 1e-6 * want,
            "{}: volume {got} want {want}",
            l.id
        );
    }
    p.layers.len()
}

#[test]
fn layer_solids_are_closed_boxes_of_the_layer_volume_in_any_pose() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures/machining/rib_72_on_plate.step");
    let text = std::fs::read_to_string(path).unwrap();
    assert_eq!(layers_read_back(&text, [0.0, 0.0, 1.0]), 8);
    let (r, t) = common::rigid_motion(3);
    let (turned, _) = common::turned_step(&text, &r, &t);
    let up = r * nalgebra::Vector3::z();
    assert_eq!(layers_read_back(&turned, [up.x, up.y, up.z]), 8);
}
