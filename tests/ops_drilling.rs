//! Operations with holes (issue 17): the holes a drill of the library
//! matches leave the milling layers and become drilling operations by
//! subtype; the same operations on the part turned with its set-up and
//! with its faces in reverse order. Hand values: `fixtures/ops/
//! drill_plate.step` (`scripts/make_ops_fixtures.py`, docs/OPERATIONS.md).

mod common;

use thinwall_analysis::parallel::Work;

use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_geom::Vector3;
use thinwall_ops::drilling::{hole_sites, DrillKind};
use thinwall_ops::operations::{operations, SetupOperations, Stage};
use thinwall_ops::ToolLibrary;
use thinwall_removal::{frame_of, Removal, StockShape};

/// The operations of the part in `text` set up with `up`, as
/// `thinwall operations` plans them.
fn plan(text: &str, up: [f64; 3]) -> SetupOperations {
    let part = thinwall_step::read_bytes(text.as_bytes(), "part")
        .unwrap()
        .0;
    let a = PartAnalysis::new(&part, Setup::new(up, Machine::ThreeAxis).unwrap());
    let (frame, lo, hi) = frame_of(&a, Vector3::from(up).normalize());
    let r = Removal::new(
        &part,
        frame,
        &StockShape::Block { lo, hi },
        &[],
        a.bounding_box().diagonal(),
        Work::serial(),
    )
    .unwrap();
    let lib = ToolLibrary::default_tools();
    let holes = hole_sites(&common::features_in_setup(&a), &frame, &lib);
    operations(&r, &lib, None, &[], &holes, Work::serial())
}

fn text() -> String {
    std::fs::read_to_string(common::root().join("fixtures/ops/drill_plate.step")).unwrap()
}

/// A drill operation by tool and kind: its holes' count and volume.
fn drilling(p: &SetupOperations, tool: &str) -> (DrillKind, usize, f64) {
    let o = p
        .operations
        .iter()
        .find(|o| o.stage == Stage::Drill && o.tool == tool)
        .unwrap_or_else(|| panic!("no {tool} operation"));
    (o.drill.unwrap(), o.holes.len(), o.volume_mm3)
}

/// The plate x 0..120, y 0..80, z 0..20 with a pocket 60 × 60, 8 deep,
/// and six holes along z (the script's docstring):
/// - two Ø5 through from the top: DR5, through, 2 · π 2.5² · 20 = 785.40;
/// - Ø10 blind 12 deep: DR10, blind, π 5² · 12 = 942.48;
/// - Ø3.3 blind 18 deep (over 4 Ø): DR3.3, peck, π 1.65² · 18 = 153.94;
/// - Ø6.6 through the pocket's floor (12 thick, entered from below by the
///   recognizer, drilled from up): DR6.6, through, π 3.3² · 12 = 410.50,
///   after every milling of the pocket's layer;
/// - Ø8 through the floor: no drill matches; the Ø6 end mill (between half
///   and 0.8 of it) spirals down it, helical, π 4² · 12 = 603.19, after
///   the pocket's layer too; nothing is left below the floor to mill
///   in layers.
#[test]
fn holes_a_drill_matches_are_drilled_by_kind() {
    let p = plan(&text(), [0.0, 0.0, 1.0]);
    let pi = std::f64::consts::PI;
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-3 * b;
    for (tool, kind, n, v) in [
        ("DR5", DrillKind::Through, 2, 2.0 * pi * 6.25 * 20.0),
        ("DR10", DrillKind::Blind, 1, pi * 25.0 * 12.0),
        ("DR3.3", DrillKind::Peck, 1, pi * 1.65f64.powi(2) * 18.0),
        ("DR6.6", DrillKind::Through, 1, pi * 3.3f64.powi(2) * 12.0),
        ("EM6", DrillKind::Helical, 1, pi * 16.0 * 12.0),
    ] {
        let (k, count, volume) = drilling(&p, tool);
        assert_eq!((k, count), (kind, n), "{tool}");
        assert!(close(volume, v), "{tool}: {volume} mm³, by hand {v}");
    }
    assert_eq!(p.holes.len(), 6);
    assert!(p.holes.iter().all(|h| h.drill.is_some()));
    // Below the floor (z 12) every field is a hole's, so no milling.
    assert!(p
        .operations
        .iter()
        .all(|o| o.stage == Stage::Drill || o.z_bottom_mm >= 12.0 - 1e-9));
    // The helix: 12 / tan 3° mm at Ø6's feed.
    let em6 = p
        .operations
        .iter()
        .find(|o| o.stage == Stage::Drill && o.tool == "EM6")
        .unwrap();
    let lib = ToolLibrary::default_tools();
    let feed = lib
        .tools
        .iter()
        .find(|t| t.name == "EM6")
        .unwrap()
        .feed_mm_min();
    let helix = 12.0 / 3f64.to_radians().tan() / feed;
    assert!(
        (em6.time_min - helix).abs() <= 1e-9 * helix,
        "{}",
        em6.time_min
    );
    // DR6.6 enters at the floor: after every operation above it.
    let dr66 = p.operations.iter().find(|o| o.tool == "DR6.6").unwrap();
    let above: Vec<usize> = p
        .operations
        .iter()
        .filter(|o| o.z_bottom_mm >= 12.0 - 1e-9 && o.stage != Stage::Drill)
        .map(|o| o.step)
        .collect();
    assert!(!above.is_empty());
    assert!(above
        .iter()
        .all(|s| dr66.after.contains(s) && *s < dr66.step));
    // No drilled field is left to the end mills or the rest.
    for ft in p
        .field_tools
        .iter()
        .flatten()
        .filter(|ft| ft.drilled.is_some())
    {
        assert!(ft.shares.is_empty() && ft.rest_mm2 == 0.0);
    }
    common::assert_layers_add_up(&p, "drilled plate");
    assert!(p.tool_changes <= p.plain_tool_changes);
}

/// The operations as (stage, tool, first layer, area, volume), sorted.
fn summary(p: &SetupOperations) -> Vec<(Stage, String, usize, f64, f64)> {
    let mut v: Vec<_> = p
        .operations
        .iter()
        .map(|o| {
            let first = o.passes.first().map_or(usize::MAX, |p| p.layer);
            (o.stage, o.tool.clone(), first, o.area_mm2, o.volume_mm3)
        })
        .collect();
    v.sort_by(|a, b| (a.0, &a.1, a.2).cmp(&(b.0, &b.1, b.2)));
    v
}

/// Turned by rigid motions with its set-up, or with its faces listed the
/// other way round, the plate gets the same operations: stages, tools,
/// layers, areas and volumes (1e-6 relative), and the same tool changes.
#[test]
fn operations_do_not_depend_on_pose_or_face_order() {
    let text = text();
    let base = plan(&text, [0.0, 0.0, 1.0]);
    let want = summary(&base);
    let mut cases = vec![(
        "reversed".to_string(),
        common::faces_reversed(&text),
        [0.0, 0.0, 1.0],
    )];
    for seed in [3, 11] {
        let (r, t) = common::rigid_motion(seed);
        let up = r * nalgebra::Vector3::z();
        cases.push((
            format!("turned {seed}"),
            common::turned_step(&text, &r, &t).0,
            [up.x, up.y, up.z],
        ));
    }
    for (what, text, up) in cases {
        let p = plan(&text, up);
        let got = summary(&p);
        assert_eq!(got.len(), want.len(), "{what}");
        for (g, w) in got.iter().zip(&want) {
            assert_eq!((g.0, &g.1, g.2), (w.0, &w.1, w.2), "{what}");
            for (a, b) in [(g.3, w.3), (g.4, w.4)] {
                assert!((a - b).abs() <= 1e-6 * b.max(1.0), "{what}: {g:?} vs {w:?}");
            }
        }
        assert_eq!(p.tool_changes, base.tool_changes, "{what}");
    }
}
