//! Step-approach layers as solids (truck sweeps, written as STEP by
//! truck-stepio): our reader reads each back as one closed solid of the
//! layer's volume, in any pose.

mod common;

use thinwall_analysis::parallel::Work;
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
    Removal::new(
        part,
        f,
        &StockShape::Block { lo, hi },
        &[],
        size,
        Work::serial(),
    )
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

/// A loop as the points of its coedges' ends, in the loop's direction,
/// starting at its lowest point (lexicographically) so two numberings of
/// one loop compare.
fn loop_points(part: &thinwall_brep::Part, l: thinwall_brep::LoopId) -> Vec<[f64; 3]> {
    let pts: Vec<[f64; 3]> = part
        .loop_(l)
        .coedges
        .iter()
        .map(|c| {
            let e = part.edge(c.edge);
            let v = if c.forward { e.start } else { e.end };
            let p = part.vertex(v).point;
            [p.x, p.y, p.z]
        })
        .collect();
    let first = (0..pts.len())
        .min_by(|&i, &j| pts[i].partial_cmp(&pts[j]).unwrap())
        .unwrap_or(0);
    pts[first..].iter().chain(&pts[..first]).copied().collect()
}

fn close(a: &[f64; 3], b: &[f64; 3], tol: f64) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
}

/// The direct part and the round trip's are one B-rep: the same faces in
/// the same order with the same surfaces, senses and loops (as points),
/// and every edge's curve through the same points.
fn assert_same_brep(direct: &thinwall_brep::Part, read: &thinwall_brep::Part, what: &str) {
    assert_eq!(direct.bodies.len(), read.bodies.len(), "{what}: bodies");
    assert_eq!(direct.faces.len(), read.faces.len(), "{what}: faces");
    assert_eq!(direct.edges.len(), read.edges.len(), "{what}: edges");
    assert_eq!(
        direct.vertices.len(),
        read.vertices.len(),
        "{what}: vertices"
    );
    let tol = 1e-9 * direct.bounding_box().diagonal().max(1.0);
    for (fa, fb) in direct.faces.iter().zip(&read.faces) {
        assert_eq!(fa.surface.kind_name(), fb.surface.kind_name(), "{what}");
        assert_eq!(fa.loops.len(), fb.loops.len(), "{what}: loops");
        for (&la, &lb) in fa.loops.iter().zip(&fb.loops) {
            let (pa, pb) = (loop_points(direct, la), loop_points(read, lb));
            assert_eq!(pa.len(), pb.len(), "{what}: a loop's edges");
            for (a, b) in pa.iter().zip(&pb) {
                assert!(close(a, b, tol), "{what}: loop point {a:?} against {b:?}");
            }
        }
        // The outward normal at each loop's first vertex.
        let p = direct.vertex(direct.edge(direct.loop_(fa.loops[0]).coedges[0].edge).start);
        let (na, nb) = (
            fa.outward_normal(&p.point, &mut None),
            fb.outward_normal(&p.point, &mut None),
        );
        match (na, nb) {
            (Some(a), Some(b)) => assert!(a.dot(&b) > 1.0 - 1e-9, "{what}: normals {a} {b}"),
            (a, b) => assert_eq!(a.is_some(), b.is_some(), "{what}: a normal"),
        }
        if let (
            thinwall_geom::Surface::Cylinder { radius: ra, .. },
            thinwall_geom::Surface::Cylinder { radius: rb, .. },
        ) = (&fa.surface, &fb.surface)
        {
            assert!((ra - rb).abs() <= tol, "{what}: radius {ra} against {rb}");
        }
    }
    // Edges by their end points: each direct edge's curve passes where the
    // read edge with the same ends does.
    let key = |p: &thinwall_brep::Part, e: &thinwall_brep::Edge| {
        let (a, b) = (p.vertex(e.start).point, p.vertex(e.end).point);
        format!(
            "{:.6},{:.6},{:.6}>{:.6},{:.6},{:.6}",
            a.x, a.y, a.z, b.x, b.y, b.z
        )
    };
    let read_edges: std::collections::HashMap<String, &thinwall_brep::Edge> =
        read.edges.iter().map(|e| (key(read, e), e)).collect();
    for e in &direct.edges {
        let r = read_edges
            .get(&key(direct, e))
            .unwrap_or_else(|| panic!("{what}: no read edge from to {}", key(direct, e)));
        let (ca, cb) = (e.nurbs.as_ref().unwrap(), r.nurbs.as_ref().unwrap());
        // Our reader names a rational B-spline curve (a complex entity in
        // the file) `other`; built directly it is a B-spline.
        let rational_read_as_other =
            e.curve.name() == "bspline" && r.curve.name() == "other" && !cb.is_polynomial();
        if !rational_read_as_other {
            assert_eq!(e.curve.name(), r.curve.name(), "{what}");
        }
        let ((a0, a1), (b0, b1)) = (ca.domain(), cb.domain());
        for k in 0..=4 {
            let s = k as f64 / 4.0;
            let (pa, pb) = (ca.point(a0 + s * (a1 - a0)), cb.point(b0 + s * (b1 - b0)));
            assert!(
                (pa - pb).norm() <= tol,
                "{what}: edge point {pa} against {pb}"
            );
        }
    }
}

/// The planner's feature solids taken into our B-rep directly are the
/// B-rep the STEP round trip gives (truck writes, our reader reads), solid
/// by solid, on every thin-walled part and two fixtures, planar and swept.
#[test]
fn feature_solids_built_directly_are_the_round_trips_brep() {
    let mut parts = common::step_files(&common::shared_data().join("thinwall"));
    parts.push(common::root().join("fixtures/recognition/rib_grid_panel.step"));
    parts.push(common::root().join("fixtures/recognition/drafted_2.step"));
    let (mut compared, mut swept) = (0, 0);
    for path in parts {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).unwrap();
        let (_, p) = common::plan_text(&text, [0.0, 0.0, 1.0], &RuleSet::default_rules());
        for f in &p.machining_features {
            for (i, s) in f.solids.iter().enumerate() {
                let Some(solid) = volumes::feature_solid(&p.frame, s) else {
                    continue;
                };
                let what = format!("{name} {}#{}", f.id, i + 1);
                let direct = thinwall_plan::solid_part::part_of(&[(what.clone(), &solid)])
                    .unwrap_or_else(|e| panic!("{e}"));
                let step = volumes::solids_step(&[solid], &what);
                let (read, _) = thinwall_step::read_bytes(step.as_bytes(), &what).unwrap();
                assert_same_brep(&direct, &read, &what);
                compared += 1;
                swept += usize::from(
                    direct
                        .faces
                        .iter()
                        .any(|f| f.surface.kind_name() == "cylinder"),
                );
            }
        }
    }
    eprintln!("{compared} solids compared ({swept} with cylinders)");
    assert!(compared > 200, "{compared}");
    assert!(swept > 0, "no swept solid was compared");
}
