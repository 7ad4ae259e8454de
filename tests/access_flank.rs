//! Flank milling of planar faces (issue 16, G-zones): what a planner
//! expects on the rib-grid panel, the same answer on turned copies, and
//! every shared thin-walled part runs.

mod common;

use thinwall_access::{flank_milling, FlankOptions, Nature, PlanarFaceAccess, Sharpness};
use thinwall_analysis::{Machine, PartAnalysis, Setup};

fn access(part: &thinwall_brep::Part, up: [f64; 3]) -> Vec<PlanarFaceAccess> {
    let setup = Setup::new(up, Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(part, setup);
    let mesh = thinwall_report::html::part_mesh(part);
    flank_milling(&a, &mesh, &FlankOptions::default())
}

fn read(path: &std::path::Path) -> thinwall_brep::Part {
    thinwall_step::read_file(path).unwrap().0
}

#[test]
fn rib_grid_panel_faces_as_a_planner_sees_them() {
    let part = read(&common::root().join("fixtures/recognition/rib_grid_panel.step"));
    let faces = access(&part, [0.0, 0.0, 1.0]);
    assert!(!faces.is_empty());
    for f in &faces {
        // Every face's verdict follows from its figures.
        assert_eq!(f.advisable, f.visibility >= 0.95, "face #{}", f.face);
        assert!(
            f.g_zone_mm2 <= f.area_mm2 * (1.0 + 1e-9),
            "face #{}: G-zone {} of {}",
            f.face,
            f.g_zone_mm2,
            f.area_mm2
        );
        assert!((0.0..=1.0 + 1e-12).contains(&f.visibility));
        let closed = f
            .edges
            .iter()
            .filter(|e| matches!(e.sharpness, Sharpness::Closed | Sharpness::TangentClosed))
            .count();
        let nature = match closed {
            0 => Nature::Open,
            n if n == f.edges.len() => Nature::Closed,
            _ => Nature::SemiOpen,
        };
        assert_eq!(f.nature, nature);
        if f.nature == Nature::Closed {
            assert!(!f.advisable && f.note.is_some());
        }
    }
    // The web's floors between ribs and flanges are closed all round: no
    // flank milling. The ribs' sides stand on the web (a closed foot) and
    // are open at the top: reached whole from above.
    let floors: Vec<&PlanarFaceAccess> = faces
        .iter()
        .filter(|f| f.nature == Nature::Closed)
        .collect();
    assert!(!floors.is_empty(), "closed floors");
    let sides: Vec<&PlanarFaceAccess> = faces
        .iter()
        .filter(|f| f.nature == Nature::SemiOpen && f.advisable)
        .collect();
    assert!(
        sides.len() >= 6,
        "{} advisable semi-open faces",
        sides.len()
    );
    for s in &sides {
        assert!(!s.used.is_empty() && s.used.len() <= s.candidates.len());
    }
}

/// The ribs' tops (one face, 25 mm high) lie 5 mm below the flanges'
/// tops all round: a tool lying on them cannot come in from outside, past
/// the flanges, whatever its size (the flanges stand in the slab of a Ø4
/// tool as of a Ø12 one). The flanges' top, the highest face and open all
/// round, is reached whole.
#[test]
fn the_rib_tops_are_shut_in_by_the_flanges_and_the_flange_top_is_not() {
    let part = read(&common::root().join("fixtures/recognition/rib_grid_panel.step"));
    let setup = Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(&part, setup);
    let mesh = thinwall_report::html::part_mesh(&part);
    for d in [4.0, 12.0] {
        let options = FlankOptions {
            tool_diameter: d,
            ..FlankOptions::default()
        };
        let faces = flank_milling(&a, &mesh, &options);
        let by_area = |area: f64| {
            faces
                .iter()
                .find(|f| (f.area_mm2 - area).abs() < 0.01)
                .expect("face by its area")
        };
        let rib_tops = by_area(646.32);
        assert_eq!(rib_tops.nature, Nature::SemiOpen);
        assert!(
            !rib_tops.advisable && rib_tops.visibility < 0.1,
            "Ø{d}: {rib_tops:?}"
        );
        let flange_top = by_area(876.0);
        assert_eq!(flange_top.nature, Nature::Open);
        assert_eq!(flange_top.obstacles, 0);
        assert!(flange_top.advisable && flange_top.visibility > 1.0 - 1e-9);
    }
}

#[test]
fn a_turned_part_gives_the_same_verdicts() {
    let path = common::root().join("fixtures/recognition/rib_grid_panel.step");
    let text = std::fs::read_to_string(&path).unwrap();
    let part = read(&path);
    let before = access(&part, [0.0, 0.0, 1.0]);
    for seed in [3, 11] {
        let (r, t) = common::rigid_motion(seed);
        let (turned, _) = common::turned_step(&text, &r, &t);
        let (tpart, _) = thinwall_step::read_bytes(turned.as_bytes(), "turned").unwrap();
        let up = r * nalgebra::Vector3::new(0.0, 0.0, 1.0);
        let after = access(&tpart, [up.x, up.y, up.z]);
        assert_eq!(before.len(), after.len());
        for (b, a) in before.iter().zip(&after) {
            assert_eq!(b.face, a.face);
            assert_eq!(b.nature, a.nature, "face #{}", b.face);
            assert_eq!(b.advisable, a.advisable, "face #{}", b.face);
            assert_eq!(b.obstacles, a.obstacles, "face #{}", b.face);
            assert!((b.area_mm2 - a.area_mm2).abs() <= 1e-6 * b.area_mm2.max(1.0));
            assert!(
                (b.visibility - a.visibility).abs() <= 1e-6,
                "face #{}",
                b.face
            );
            assert_eq!(b.used.len(), a.used.len(), "face #{}", b.face);
            for (x, y) in b.used.iter().zip(&a.used) {
                let turned = r * nalgebra::Vector3::from(x.direction);
                let dot = turned.dot(&nalgebra::Vector3::from(y.direction));
                assert!(dot > 1.0 - 1e-9, "face #{}: direction turned", b.face);
            }
        }
    }
}

#[test]
fn every_shared_thin_walled_part_runs() {
    let mut faces = 0;
    for path in common::thin_walled_parts() {
        let part = read(&path);
        for f in access(&part, [0.0, 0.0, 1.0]) {
            assert!(
                f.visibility.is_finite() && f.g_zone_mm2.is_finite(),
                "{}",
                path.display()
            );
            faces += 1;
        }
    }
    assert!(faces > 500, "{faces}");
}
