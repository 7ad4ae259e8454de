//! Prismatic bosses and pockets with islands, on generated parts
//! (`scripts/make_machining_fixtures.py`) and on NIST CTC 01, as built and
//! turned by rigid motions: a ring of walls standing on an open face is a
//! `boss`; standing in a pocket, it is the pocket's island.

mod common;

use thinwall_analysis::{Catalog, MachiningKind, PartAnalysis, Profile, Setup};
use thinwall_machining::{recognize, MachiningFeature};

fn fixture(name: &str) -> String {
    common::machining_fixture(name)
}

/// The features of a part as built (`seed` none) or turned.
fn features(text: &str, seed: Option<u64>) -> Vec<MachiningFeature> {
    let text = common::posed_step(text, seed);
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    recognize(&PartAnalysis::new(&part, Setup::default()))
}

const POSES: [Option<u64>; 3] = [None, Some(31), Some(32)];

fn one(ms: &[MachiningFeature], kind: MachiningKind) -> &MachiningFeature {
    let found: Vec<&MachiningFeature> = ms.iter().filter(|m| m.kind == kind).collect();
    assert_eq!(found.len(), 1, "one {kind}: {ms:#?}");
    found[0]
}

fn near(x: f64, y: f64) -> bool {
    (x - y).abs() < 1e-6
}

/// A 120 × 1 rib 48 high on a plate: its four walls are a rectangular boss
/// the height of the rib; the plate's top is a face to clear down to it,
/// not the floor of a pocket (its walls face out).
#[test]
fn a_rib_on_a_plate_is_a_boss_not_a_pocket() {
    let text = fixture("rib_48_on_plate.step");
    for pose in POSES {
        let ms = features(&text, pose);
        assert!(
            !ms.iter().any(|m| m.kind == MachiningKind::Pocket),
            "{pose:?}"
        );
        let boss = one(&ms, MachiningKind::Boss);
        assert_eq!(boss.profile, Profile::Rectangular);
        assert_eq!(boss.faces.len(), 4);
        assert!(near(boss.depth, 48.0) && near(boss.length, 120.0) && near(boss.width, 1.0));
        let face = one(&ms, MachiningKind::Face);
        assert_eq!(face.faces.len(), 1);
        assert!(near(face.depth, 48.0));
    }
}

/// Two ribs on one plate (one holed, one with cut-outs from its top): two
/// bosses, 72 and 48 high; neither is the other's pocket wall.
#[test]
fn two_ribs_on_a_plate_are_two_bosses() {
    let text = fixture("ribs_with_holes_and_cutouts.step");
    for pose in POSES {
        let ms = features(&text, pose);
        assert!(!ms.iter().any(|m| !m.island_faces.is_empty()), "{pose:?}");
        let mut bosses: Vec<(f64, f64, f64)> = ms
            .iter()
            .filter(|m| m.kind == MachiningKind::Boss)
            .map(|m| (m.depth, m.length, m.width))
            .collect();
        bosses.sort_by(|x, y| x.0.total_cmp(&y.0));
        assert_eq!(bosses.len(), 2, "{pose:?}");
        assert!(near(bosses[0].0, 48.0) && near(bosses[1].0, 72.0));
        assert!(bosses.iter().all(|b| near(b.1, 180.0) && near(b.2, 1.5)));
    }
}

/// A 40 × 20 boss 15 high with r3 corners: its four planar walls are the
/// boss, joined round the rounded corners (each a round of its own).
#[test]
fn a_boss_with_rounded_corners_is_one_boss() {
    let text = fixture("curved_corners/rounded_boss_plate.step");
    for pose in POSES {
        let ms = features(&text, pose);
        let boss = one(&ms, MachiningKind::Boss);
        assert_eq!(boss.profile, Profile::Rectangular, "{pose:?}");
        assert_eq!(boss.faces.len(), 4);
        assert!(near(boss.depth, 15.0) && near(boss.length, 40.0) && near(boss.width, 20.0));
        // Its top's centre, the tool coming down: where the turn takes
        // (50, 30, 25) and −z.
        let (r, t) = pose.map_or(
            (nalgebra::Rotation3::identity(), nalgebra::Vector3::zeros()),
            common::rigid_motion,
        );
        let want = r * nalgebra::Vector3::new(50.0, 30.0, 25.0) + t;
        let down = r * nalgebra::Vector3::new(0.0, 0.0, -1.0);
        let c = boss.centre.unwrap();
        assert!(
            (nalgebra::Vector3::from(c) - want).norm() < 1e-6,
            "{c:?} {want:?}"
        );
        assert!((nalgebra::Vector3::from(boss.direction) - down).norm() < 1e-9);
        assert!(near(one(&ms, MachiningKind::Face).depth, 15.0));
    }
}

/// An 80 × 40 pocket 10 deep with a 20 × 10 island standing to the top:
/// one rectangular pocket (the catalogue's), typed and measured without the
/// island, its walls listed as the island's; the largest tool is the 30 mm
/// between the island and the pocket's ends.
#[test]
fn an_island_in_a_pocket_stays_in_its_pocket() {
    let text = fixture("island_pocket.step");
    for pose in POSES {
        let ms = features(&text, pose);
        assert_eq!(ms.len(), 1, "{pose:?}: {ms:#?}");
        let p = &ms[0];
        assert_eq!(p.kind, MachiningKind::Pocket);
        assert_eq!(p.profile, Profile::Rectangular);
        assert_eq!(p.catalog, Some(Catalog::RectangularPocket));
        assert_eq!((p.faces.len(), p.island_faces.len()), (9, 4));
        assert!(p.island_faces.iter().all(|f| p.side_faces.contains(f)));
        assert!(near(p.depth, 10.0) && near(p.length, 80.0) && near(p.width, 40.0));
        let tool = p.largest_tool_diameter.unwrap();
        assert!((tool - 30.0).abs() < 0.1, "{tool}");
    }
}

/// NIST CTC 01: the hexagonal boss 100 across its flats in the middle of
/// the plate's top (r6 foot fillets, bevelled top) is a hexagonal boss; it
/// was a "hexagonal pocket" made of the plate's top and the boss's walls.
/// Its walls stand on the plate through the fillets: its height (50, to
/// the top of its bevel) is from the plate, not from where the fillets end
/// (44), nor to where the walls end (45).
#[test]
fn ctc_01s_hexagonal_boss() {
    let path = common::shared_data().join("nist/nist_ctc_01_asme1_ap242-e1.stp");
    let text = std::fs::read_to_string(path).unwrap();
    for pose in [None, Some(33)] {
        let ms = features(&text, pose);
        let hex: Vec<&MachiningFeature> = ms
            .iter()
            .filter(|m| m.profile == Profile::Hexagonal)
            .collect();
        assert_eq!(hex.len(), 1, "{pose:?}");
        assert_eq!(hex[0].kind, MachiningKind::Boss);
        assert_eq!(hex[0].faces, [869, 870, 871, 872, 873, 874]);
        assert!((hex[0].width - 100.0).abs() < 1e-6);
        assert!((hex[0].length - 200.0 / 3f64.sqrt()).abs() < 1e-6);
        assert!((hex[0].depth - 50.0).abs() < 1e-6, "{}", hex[0].depth);
    }
}
