//! Flank milling of planar faces (issue 16, G-zones): what a planner
//! expects on the rib-grid panel, the same answer on turned copies, and
//! every shared thin-walled part runs.

mod common;

use thinwall_access::{flank_milling, FlankOptions, Nature, PlanarFaceAccess, Sharpness};
use thinwall_analysis::{Machine, PartAnalysis, Setup};

fn access(part: &thinwall_brep::Part, up: [f64; 3]) -> Vec<PlanarFaceAccess> {
    let setup = Setup::new(up, Machine::ThreeAxis).unwrap();
    let a = PartAnalysis::new(part, setup);
    let mesh = thinwall_brep::tessellate::part_mesh(part);
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
    let mesh = thinwall_brep::tessellate::part_mesh(&part);
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

/// `fixtures/access/plate_with_block.step` (scripts/make_access_fixtures.py):
/// a 100 × 60 plate with a 10 × 10 block on its top at x 40..50, y 20..30.
/// The top face (5900 mm²) is shaded behind the block, by construction:
/// towards −y 200 mm², +y 300, −x 400, +x 500. The smallest comes first,
/// and alone leaves 1 − 200/5900 = 96.6 % reached: advisable after one
/// direction. With a Ø12 tool's radius widening the block by 6 to each
/// side, −y shades x 34..56 from the block's far side down, y 0..30:
/// 22 × 30 − the block's own 100 = 560 mm² (90.5 % reached: a second
/// direction, +y, is needed: 22 × 40 − 100 = 780, together 2 × 6 × 10 =
/// 120 left beside the block).
#[test]
fn a_block_on_a_plate_shades_its_strips_by_construction() {
    let path = common::root().join("fixtures/access/plate_with_block.step");
    let text = std::fs::read_to_string(&path).unwrap();
    let check = |part: &thinwall_brep::Part, up: [f64; 3], turn: &nalgebra::Rotation3<f64>| {
        let top = access(part, up)
            .into_iter()
            .find(|f| (f.area_mm2 - 5900.0).abs() < 1e-6 * 5900.0)
            .expect("the plate's top face");
        assert_eq!(top.nature, Nature::SemiOpen);
        let mut l: Vec<f64> = top
            .candidates
            .iter()
            .filter(|c| c.priority == 1)
            .map(|c| c.l_zone_mm2)
            .collect();
        l.sort_by(f64::total_cmp);
        for (got, want) in l.iter().zip([200.0, 300.0, 400.0, 500.0]) {
            assert!((got - want).abs() <= 1e-6 * want, "L-zones {l:?}");
        }
        assert_eq!(l.len(), 4, "{l:?}");
        assert_eq!(top.used.len(), 1);
        assert!((top.visibility - (1.0 - 200.0 / 5900.0)).abs() < 1e-9);
        assert!(top.advisable);
        let toward = turn * nalgebra::Vector3::new(0.0, -1.0, 0.0);
        assert!(nalgebra::Vector3::from(top.used[0].direction).dot(&toward) > 1.0 - 1e-9);
        let setup = Setup::new(up, Machine::ThreeAxis).unwrap();
        let a = PartAnalysis::new(part, setup);
        let mesh = thinwall_brep::tessellate::part_mesh(part);
        let options = FlankOptions {
            tool_radius: true,
            ..FlankOptions::default()
        };
        let widened = flank_milling(&a, &mesh, &options)
            .into_iter()
            .find(|f| f.face == top.face)
            .unwrap();
        let want = [(560.0, 560.0), (780.0, 120.0)];
        assert_eq!(widened.used.len(), 2, "{:?}", widened.used);
        for (u, (l, g)) in widened.used.iter().zip(want) {
            assert!((u.l_zone_mm2 - l).abs() <= 1e-6 * l, "{:?}", widened.used);
            assert!((u.g_zone_mm2 - g).abs() <= 1e-6 * g, "{:?}", widened.used);
        }
        assert!(widened.advisable);
    };
    check(
        &read(&path),
        [0.0, 0.0, 1.0],
        &nalgebra::Rotation3::identity(),
    );
    let (r, t) = common::rigid_motion(7);
    let (turned, _) = common::turned_step(&text, &r, &t);
    let (tpart, _) = thinwall_step::read_bytes(turned.as_bytes(), "turned").unwrap();
    let up = r * nalgebra::Vector3::new(0.0, 0.0, 1.0);
    check(&tpart, [up.x, up.y, up.z], &r);
}

/// Harik & Ris's worked case, rebuilt (their figures 6 and 10–13 are not
/// in the text: `fixtures/access/bay_with_lip.step`,
/// scripts/make_access_fixtures.py). The bay's floor is the trapezoid
/// (0,0) (60,−60/√3) (60,40+60/√3) (0,40): the back edge E1 (x = 0) is
/// closed with both neighbours closed, the side edges E0 (−30°) and E2
/// (+30°) are closed windows, the edge x = 60 is open. A lip Λ (x 40..50,
/// from E0 up to y = −10, z 4..8) hangs over it within the Ø12 slab.
///
/// Proposed, as the paper's rules give for three closed linear edges:
/// nine directions, priorities 1 (across E1), 2, 2 (across E0, E2),
/// 3, 3 (along E1), 4 × 4 (along E0, E2). L-zones by hand (a direction is
/// the way the tool moves in; a barrier shades what lies beyond it):
/// - across E1 (−x): Λ and the triangle T1 left of it between E0 and
///   y = −10;
/// - across E0: the part above the line from E2's open end at 240°
///   (E2 shades it) S2, with Λ and the sliver τ Λ shades down to E0;
/// - across E2: the mirror of S2, with the band Λ shades up to E2 beyond it;
/// - along E1 (±y): the open edge is parallel, the whole face;
/// - along E0 and E2 into the walls: the whole face; out of the walls:
///   Λ's shadow along E0 (a band 50/√3 − 10 wide over x 0..50), or along
///   E2 (Λ and 2τ).
///
/// The G-zone after E1's direction leaves Λ ∪ T1 (93.1 % reached), after
/// E0's Λ ∪ τ (95.6 %): the threshold is reached with two directions, as in
/// the paper's story. Asked for 99 %, every direction is tried, the
/// reached share never falls, and Λ ∪ τ is all no direction reaches.
#[test]
fn the_papers_worked_case_proposes_nine_directions_and_grows_to_the_threshold() {
    let r3 = 3f64.sqrt();
    let area = 2400.0 + 3600.0 / r3;
    let lip = 450.0 / r3 - 100.0;
    let t1 = (40.0 - 10.0 * r3).powi(2) / (2.0 * r3);
    let tau = 0.5 * (40.0 / r3 - 10.0) * (10.0 - 2.5 * r3);
    let shoelace = |p: &[(f64, f64)]| {
        let n = p.len();
        0.5 * (0..n)
            .map(|i| p[i].0 * p[(i + 1) % n].1 - p[(i + 1) % n].0 * p[i].1)
            .sum::<f64>()
            .abs()
    };
    // S2: the floor above the line through (60, 40 + 60/√3) at 240°.
    let top = 40.0 + 60.0 / r3;
    let x = (r3 * 60.0 - top) / (r3 + 1.0 / r3);
    let s2 = shoelace(&[(60.0, top), (0.0, 40.0), (0.0, 0.0), (x, -x / r3)]);
    // Across E2, beyond the mirror of S2: the band between the lines
    // y + √3x = c through (60, −60/√3) and through Λ's corner (50, −10),
    // from Λ's side x = 50 up to E2.
    let (c1, c2) = (-60.0 / r3 + r3 * 60.0, -10.0 + r3 * 50.0);
    let on_e2 = |c: f64| {
        let x = (c - 40.0) / (r3 + 1.0 / r3);
        (x, 40.0 + x / r3)
    };
    let band = shoelace(&[(50.0, c1 - r3 * 50.0), (50.0, -10.0), on_e2(c2), on_e2(c1)]);
    // (direction in the floor's plane, priority, L-zone)
    let want: [([f64; 2], u8, f64); 9] = [
        ([-1.0, 0.0], 1, lip + t1),
        ([-0.5, -0.5 * r3], 2, s2 + lip + tau),
        ([-0.5, 0.5 * r3], 2, s2 + band),
        ([0.0, -1.0], 3, area),
        ([0.0, 1.0], 3, area),
        ([-0.5 * r3, -0.5], 4, lip + 2.0 * tau),
        ([-0.5 * r3, 0.5], 4, 50.0 * (50.0 / r3 - 10.0)),
        ([0.5 * r3, -0.5], 4, area),
        ([0.5 * r3, 0.5], 4, area),
    ];
    let path = common::root().join("fixtures/access/bay_with_lip.step");
    let text = std::fs::read_to_string(&path).unwrap();
    let check = |part: &thinwall_brep::Part,
                 turn: &nalgebra::Rotation3<f64>,
                 threshold: f64|
     -> PlanarFaceAccess {
        let up = turn * nalgebra::Vector3::z();
        let setup = Setup::new([up.x, up.y, up.z], Machine::ThreeAxis).unwrap();
        let a = PartAnalysis::new(part, setup);
        let mesh = thinwall_brep::tessellate::part_mesh(part);
        let options = FlankOptions {
            threshold,
            ..FlankOptions::default()
        };
        let floor = flank_milling(&a, &mesh, &options)
            .into_iter()
            .find(|f| (f.area_mm2 - area).abs() <= 1e-6 * area)
            .expect("the bay's floor");
        assert_eq!(floor.nature, Nature::SemiOpen);
        assert_eq!(floor.candidates.len(), 9, "{:?}", floor.candidates);
        let priorities: Vec<u8> = floor.candidates.iter().map(|c| c.priority).collect();
        assert_eq!(priorities, [1, 2, 2, 3, 3, 4, 4, 4, 4]);
        for (d, priority, l) in want {
            let d = turn * nalgebra::Vector3::new(d[0], d[1], 0.0);
            let c = floor
                .candidates
                .iter()
                .find(|c| nalgebra::Vector3::from(c.direction).dot(&d) > 1.0 - 1e-9)
                .unwrap_or_else(|| panic!("no candidate along {d:?}"));
            assert_eq!(c.priority, priority, "{d:?}");
            assert!(
                (c.l_zone_mm2 - l).abs() <= 1e-6 * l,
                "{d:?}: L-zone {} mm², by hand {l}",
                c.l_zone_mm2
            );
        }
        floor
    };
    let reversed = common::faces_reversed(&text);
    let (r, t) = common::rigid_motion(5);
    let (turned, _) = common::turned_step(&text, &r, &t);
    let poses = [
        (text.as_str(), nalgebra::Rotation3::identity()),
        (reversed.as_str(), nalgebra::Rotation3::identity()),
        (turned.as_str(), r),
    ];
    for (text, turn) in &poses {
        let part = thinwall_step::read_bytes(text.as_bytes(), "bay").unwrap().0;
        let floor = check(&part, turn, 0.95);
        let reached = [1.0 - (lip + t1) / area, 1.0 - (lip + tau) / area];
        assert_eq!(floor.used.len(), 2, "{:?}", floor.used);
        for (u, want) in floor.used.iter().zip(reached) {
            assert!((u.visibility - want).abs() <= 1e-6, "{:?}", floor.used);
        }
        assert!(floor.advisable);
        let all = check(&part, turn, 0.99);
        assert_eq!(all.used.len(), 9);
        assert!(
            all.used
                .windows(2)
                .all(|w| w[1].visibility >= w[0].visibility - 1e-9),
            "{:?}",
            all.used.iter().map(|u| u.visibility).collect::<Vec<_>>()
        );
        assert!(
            (all.visibility - reached[1]).abs() <= 1e-6,
            "{}",
            all.visibility
        );
        assert!(!all.advisable);
    }
}
