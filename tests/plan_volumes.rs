//! Step-approach layers as solids (truck sweeps, written as STEP by
//! truck-stepio): our reader reads each back as one closed solid of the
//! layer's volume, in any pose.

mod common;

use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_plan::{volumes, RuleSet};

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

/// A solid's volume by the removal decomposition along `up`.
fn volume_along(part: &thinwall_brep::Part, up: [f64; 3]) -> f64 {
    use thinwall_removal::{frame_of, Removal, StockShape};
    let a = PartAnalysis::new(part, Setup::default());
    let (f, lo, hi) = frame_of(&a, nalgebra::Vector3::new(up[0], up[1], up[2]));
    let size = a.bounding_box().diagonal();
    Removal::new(part, f, &StockShape::Block { lo, hi }, &[], size)
        .expect("planes and cylinders across up")
        .part_volume
}

fn layers_read_back(text: &str, up: [f64; 3]) -> usize {
    let (_, p) = common::plan_text(text, up, &RuleSet::default_rules());
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

/// Every machining feature of the whole removal plan, written as STEP,
/// reads back as closed solids of the feature's volume: those between
/// planes by the divergence theorem, those swept from a profile with arcs
/// (over foot fillets, inside holes through ribs: truck writes the arcs as
/// rational B-splines, which our reader sees as cylinders) by the
/// decomposition along up. Solids over a cone are not written yet and are
/// counted.
#[test]
fn removal_features_read_back_as_closed_solids_of_their_volume() {
    let mut parts = common::step_files(&common::shared_data().join("thinwall"));
    parts.push(common::root().join("fixtures/recognition/rib_grid_panel.step"));
    parts.push(common::root().join("fixtures/recognition/drafted_2.step"));
    let (mut written, mut skipped, mut curved) = (0, 0, 0);
    for path in parts {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).unwrap();
        let (_, p) = common::plan_text(&text, [0.0, 0.0, 1.0], &RuleSet::default_rules());
        for f in &p.machining_features {
            let (step, missing) = volumes::feature_step(&p, f);
            skipped += missing;
            let planar: Vec<_> = f
                .solids
                .iter()
                .filter(|s| volumes::planar_solid(&p.frame, s).is_some())
                .collect();
            let want: f64 = planar.iter().map(|s| s.volume_mm3).sum();
            if missing == f.solids.len() {
                continue;
            }
            let (solid, _) = thinwall_step::read_bytes(step.as_bytes(), "feature.step")
                .unwrap_or_else(|e| panic!("{name} {}: {e}", f.id));
            let a = PartAnalysis::new(&solid, Setup::default());
            assert!(a.free_edges().is_empty(), "{name} {}: open", f.id);
            assert_eq!(
                solid.bodies.len(),
                f.solids.len() - missing,
                "{name} {}",
                f.id
            );
            if planar.len() < f.solids.len() - missing {
                // Swept with arcs: our reader sees the arcs' rational
                // B-splines as cylinders; the decomposition along up
                // measures what it read.
                let want: f64 = f.solids.iter().map(|s| s.volume_mm3).sum();
                let got = volume_along(&solid, p.frame[3]);
                assert!(
                    (got - want).abs() <= 1e-6 * want + 1e-9 * p.removal.stock_volume_mm3,
                    "{name} {}: swept volume {got} want {want}",
                    f.id
                );
                curved += f.solids.len() - missing - planar.len();
                written += f.solids.len() - missing;
                continue;
            }
            let kinds: Vec<&str> = solid
                .face_ids()
                .map(|x| solid.face(x).surface.kind_name())
                .collect();
            assert!(
                kinds.iter().all(|k| *k == "plane"),
                "{name} {}: faces {kinds:?} of {:?}",
                f.id,
                f.solids
                    .iter()
                    .map(|s| (&s.lower, &s.upper))
                    .collect::<Vec<_>>()
            );
            let got = volume(&solid);
            assert!(
                (got - want).abs() <= 1e-9 * p.removal.stock_volume_mm3,
                "{name} {}: volume {got} want {want}",
                f.id
            );
            written += f.solids.len() - missing;
        }
    }
    eprintln!("{written} solids written and read back closed ({curved} swept with arcs), {skipped} not written");
    assert!(written > 200, "{written}");
    assert!(curved > 0, "no swept solid was written");
}
