//! Curved walls (issue 18) on the fixtures of `scripts/make_curved_fixtures.py`:
//! frame segments with flanges on their curved edges, a curved skin with
//! straight stringers, a conical flange; each also turned with its set-up.
//! Every wall is found with its side faces, kind, thin flag, thickness
//! (1e-6 relative), height and developed length, holes in curved walls
//! with their wall and diameter, and the base-leaf connections are right.

mod common;

use serde::Deserialize;
use std::collections::{BTreeMap, BTreeSet};
use thinwall_analysis::{Machine, Setup};
use thinwall_connect::Connection;

use common::fixtures::ids_at;

#[derive(Deserialize)]
struct Wall {
    name: String,
    kind: String,
    thin: bool,
    thickness: f64,
    height: Option<f64>,
    length: Option<f64>,
    side_faces_at: Vec<[f64; 3]>,
}

#[derive(Deserialize)]
struct Hole {
    wall: String,
    diameter: f64,
    through: bool,
    faces_at: Vec<[f64; 3]>,
}

#[derive(Deserialize)]
struct Fixture {
    part: String,
    up: [f64; 3],
    features: Vec<Wall>,
    connections: Vec<[String; 2]>,
    #[serde(default)]
    holes: Vec<Hole>,
}

fn dir() -> std::path::PathBuf {
    common::root().join("fixtures/curved")
}

/// A fixture's expectations, `NAME.expected.json`.
fn fixture(name: &str) -> Fixture {
    let text = std::fs::read_to_string(dir().join(format!("{name}.expected.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn run(fx: &Fixture) -> (thinwall_brep::Part, thinwall_pipeline::Outcome) {
    let (part, _) = thinwall_step::read_file(dir().join(&fx.part)).unwrap();
    let req = thinwall_pipeline::Request {
        setup: Setup::new(fx.up, Machine::ThreeAxis).unwrap(),
        ..Default::default()
    };
    let out = thinwall_pipeline::run(&part, None, &req).unwrap();
    (part, out)
}

fn close(got: Option<f64>, want: f64, rel: f64) -> bool {
    got.is_some_and(|g| (g - want).abs() <= rel * want.abs().max(1.0))
}

fn check(name: &str) -> Vec<String> {
    let fx = fixture(name);
    let (part, out) = run(&fx);
    let feats = &out.recognition.features;
    let mut problems = Vec::new();
    let mut ours: BTreeMap<String, thinwall_analysis::FeatureId> = BTreeMap::new();
    for e in &fx.features {
        let want = ids_at(&part, &e.side_faces_at);
        let Some(f) = feats.iter().find(|f| {
            f.side_faces
                .clone()
                .unwrap_or_default()
                .into_iter()
                .collect::<BTreeSet<_>>()
                == want
        }) else {
            problems.push(format!(
                "{name}: wall {} not found with its side faces",
                e.name
            ));
            continue;
        };
        ours.insert(e.name.clone(), f.id);
        let id = format!("{name}: {} ({})", e.name, f.id);
        if f.kind.name() != e.kind {
            problems.push(format!("{id} is a {}, expected {}", f.kind.name(), e.kind));
        }
        if f.thin != Some(e.thin) {
            problems.push(format!("{id} thin {:?}", f.thin));
        }
        if !close(f.thickness, e.thickness, 1e-6) {
            problems.push(format!(
                "{id} thickness {:?}, expected {}",
                f.thickness, e.thickness
            ));
        }
        // Heights and developed lengths within a millionth (arcs from
        // sampled boundaries: their vertices lie on the exact arcs).
        if let Some(h) = e.height {
            if !close(f.height, h, 1e-6) {
                problems.push(format!("{id} height {:?}, expected {h}", f.height));
            }
        }
        if let Some(l) = e.length {
            if !close(f.length, l, 1e-6) {
                problems.push(format!("{id} length {:?}, expected {l}", f.length));
            }
        }
    }
    // Holes in curved walls, found as in flat ones: faces, wall, diameter.
    for h in &fx.holes {
        let want = ids_at(&part, &h.faces_at);
        let found = feats.iter().find(|f| {
            f.kind.name() == "hole" && f.faces.iter().copied().collect::<BTreeSet<_>>() == want
        });
        let Some(f) = found else {
            problems.push(format!(
                "{name}: hole Ø{} in {} not found",
                h.diameter, h.wall
            ));
            continue;
        };
        if f.wall != ours.get(&h.wall).copied()
            || !close(f.diameter, h.diameter, 1e-9)
            || f.through != Some(h.through)
        {
            problems.push(format!(
                "{name}: {} in {:?} Ø{:?} through {:?}, expected in {} Ø{} through {}",
                f.id, f.wall, f.diameter, f.through, h.wall, h.diameter, h.through
            ));
        }
    }
    // Base-leaf connections between the walls, exactly the expected ones.
    let got: BTreeSet<(thinwall_analysis::FeatureId, thinwall_analysis::FeatureId)> = out
        .structure
        .connections
        .iter()
        .filter_map(|c| match c {
            Connection::BaseLeaf { base, leaf } if leaf.kind.is_wall() => Some((*base, *leaf)),
            _ => None,
        })
        .collect();
    let want: BTreeSet<_> = fx
        .connections
        .iter()
        .filter_map(|[b, l]| Some((*ours.get(b)?, *ours.get(l)?)))
        .collect();
    if got != want {
        problems.push(format!("{name}: connections {got:?}, expected {want:?}"));
    }
    let walls = feats.iter().filter(|f| f.kind.is_wall()).count();
    if walls != fx.features.len() {
        problems.push(format!(
            "{name}: {walls} walls, expected {}",
            fx.features.len()
        ));
    }
    problems
}

fn names() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .filter_map(|e| {
            let n = e.ok()?.file_name().to_string_lossy().into_owned();
            n.strip_suffix(".expected.json").map(str::to_string)
        })
        .collect();
    v.sort();
    v
}

#[test]
fn every_curved_fixture_yields_its_walls_turned_or_not() {
    let names = names();
    assert!(names.len() >= 8, "{names:?}");
    assert!(names.iter().any(|n| n.ends_with("_turned")));
    let problems: Vec<String> = names.iter().flat_map(|n| check(n)).collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn a_curved_wall_reports_its_mid_surface_and_access_range() {
    let fx = fixture("frame_r400");
    let (_, out) = run(&fx);
    let outer = out
        .recognition
        .features
        .iter()
        .filter(|f| f.kind.name() == "flange")
        .find(|f| {
            f.mid_surface
                .as_ref()
                .and_then(|m| m.radius)
                .is_some_and(|r| r > 470.0)
        })
        .expect("the outer flange");
    let m = outer.mid_surface.as_ref().unwrap();
    assert_eq!(m.kind, "cylinder");
    assert!((m.radius.unwrap() - 479.2).abs() < 1e-6, "{:?}", m.radius);
    let [a0, a1] = m.angle_range_deg.unwrap();
    assert!(((a1 - a0) - 30.0).abs() < 1e-4);
    assert!(
        outer.mid_plane.is_none(),
        "a curved wall has a mid-surface instead"
    );
    // Side 0 faces away from the axis; its normal sweeps the 30° of the arc.
    let [a, b] = outer.access_range.unwrap()[0];
    let (a, b) = (
        thinwall_geom::Vector3::from(a),
        thinwall_geom::Vector3::from(b),
    );
    assert!((a.angle(&b).to_degrees() - 30.0).abs() < 1e-4);
    let c = thinwall_geom::Vector3::from(m.centre);
    assert!(a.dot(&c) > 0.0 && b.dot(&c) > 0.0);
    // Both sides vertical in the set-up: reachable, the sweep in the reason.
    let access = &out.structure.access[&outer.id];
    assert!(access
        .iter()
        .all(|s| s.reachable && s.reason.contains("sweeps 30.0°")));
    // Planner geometry is for flat walls only (for now).
    assert!(outer.geometry.is_none());
}

#[test]
fn a_boss_around_a_hole_is_not_a_curved_wall_and_a_tube_is() {
    // The boss (5 thick at radius 7.5: under three thicknesses) stays a
    // machining feature; the tube beside it, its faces closed round the
    // axis, is one curved wall all the way round.
    for name in ["tube_and_boss", "tube_and_boss_turned"] {
        let fx = fixture(name);
        let (_, out) = run(&fx);
        let radii: Vec<f64> = out
            .recognition
            .features
            .iter()
            .filter_map(|f| f.mid_surface.as_ref()?.radius)
            .collect();
        assert_eq!(radii.len(), 1, "{name}: {radii:?}");
        assert!((radii[0] - 19.25).abs() < 1e-9, "{name}: {radii:?}");
        assert!(out.machining.iter().any(|m| m.kind.name() == "boss"));
    }
}

#[test]
fn the_plan_says_where_curved_walls_are_not_planned_yet() {
    let text = std::fs::read_to_string(dir().join("frame_r400.step")).unwrap();
    let rules = thinwall_plan::RuleSet::default_rules();
    let (_, plan) = common::plan_text(&text, [0.0, 0.0, 1.0], &rules);
    // Both flanges are sequenced before the web and sized ...
    let flanges: Vec<_> = plan
        .walls
        .iter()
        .filter(|w| w.kind.name() == "flange")
        .collect();
    assert_eq!(flanges.len(), 2);
    for w in &flanges {
        assert!((w.sizes.big_h - 23.0).abs() < 1e-6, "{}", w.sizes.big_h);
        // ... but get no step-approach layers, and the plan says so.
        assert!(plan.layers.iter().all(|l| l.owner != w.id));
        assert!(
            plan.limits
                .iter()
                .any(|l| l.starts_with(&format!("{}: curved wall", w.id))),
            "{:?}",
            plan.limits
        );
    }
    assert!(thinwall_report::plan::to_text(&plan).contains("not planned yet"));
}

#[test]
fn machining_features_on_a_frame_segment_are_not_degenerate() {
    let fx = fixture("frame_r400_turned");
    let (part, out) = run(&fx);
    let extent = part.bounding_box().diagonal();
    for m in &out.machining {
        assert!(m.depth > 0.0 && m.length > 0.0 && m.width > 0.0, "{m:?}");
        assert!(m.depth.max(m.length).max(m.width) < extent, "{m:?}");
        assert_ne!(m.kind.name(), "chamfer", "{m:?}");
        assert_ne!(m.kind.name(), "hole", "{m:?}");
    }
    // The outer flange's outside is the part's curved envelope under the
    // block: a face feature, as deep as the arc's rise (480 (1 − cos 30°)).
    let outer = out
        .machining
        .iter()
        .find(|m| m.kind.name() == "face" && m.faces.len() == 1)
        .expect("the outer flange's envelope");
    let rise = 480.0 * (1.0 - 30f64.to_radians().cos());
    assert!((outer.depth - rise).abs() < 1e-3, "{}", outer.depth);
}

#[test]
fn a_free_form_wall_reports_its_measured_thickness_and_sweep() {
    for name in ["freeform_rib", "freeform_rib_turned"] {
        let fx = fixture(name);
        let (_, out) = run(&fx);
        let rib = out
            .recognition
            .features
            .iter()
            .find(|f| f.kind.name() == "rib")
            .expect("the rib");
        let m = rib.mid_surface.as_ref().expect("a mid-surface");
        assert_eq!(m.kind, "offset");
        assert!(m.axis.is_none() && m.radius.is_none());
        // The sides are fitted offsets: sampled within a millionth of 1.5.
        let [lo, hi] = m.thickness_range.unwrap();
        assert!(
            (lo - 1.5).abs() < 1.5e-6 && (hi - 1.5).abs() < 1.5e-6,
            "{lo} {hi}"
        );
        // The S turns its sides' normals through about 83°, both vertical.
        let access = &out.structure.access[&rib.id];
        for side in access {
            assert!(side.reachable, "{}", side.reason);
            let sweep: f64 = side.reason["curved: the normal sweeps ".len()..]
                .split('°')
                .next()
                .unwrap()
                .parse()
                .unwrap();
            assert!((75.0..90.0).contains(&sweep), "{}", side.reason);
        }
    }
}
