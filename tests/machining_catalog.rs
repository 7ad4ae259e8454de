//! The MFCAD++ catalogue: per-face accuracy of each machining feature's
//! `catalog` name on the parts made with the MFCAD++ generator
//! (`../shared/data/mfcadpp_gen`, labels by STEP entity id; stock = no
//! feature), printed with its confusion matrix; the same parts turned by
//! rigid motions get the same answer.

mod common;

use std::collections::{BTreeMap, HashMap};
use thinwall_analysis::{Catalog, PartAnalysis, Setup};
use thinwall_machining::{recognize, MachiningFeature};

const STOCK: u32 = 24;
/// A face of a feature with no catalogue name.
const UNNAMED: u32 = 25;

/// The class (0–24) our features give each face, by STEP entity id; a
/// face of a feature with no catalogue name is `UNNAMED`.
fn predicted(features: &[MachiningFeature]) -> HashMap<u64, u32> {
    let mut by_face = HashMap::new();
    for m in features {
        for &f in &m.faces {
            by_face.insert(f, m.catalog_of_face(f).map_or(UNNAMED, |c| c.id()));
        }
    }
    by_face
}

fn labels(path: &std::path::Path) -> HashMap<u64, u32> {
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path.with_extension("labels.json")).unwrap())
            .unwrap();
    v["face_labels_by_step_id"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, c)| (k.parse().unwrap(), c.as_u64().unwrap() as u32))
        .collect()
}

/// The features whose faces are not all of the class they give, and the
/// feature faces in no feature.
fn print_wrong(f: &std::path::Path, feats: &[MachiningFeature], truth: &HashMap<u64, u32>) {
    for m in feats {
        let t: Vec<u32> = m.faces.iter().map(|x| truth[x]).collect();
        let c = |x: &u64| m.catalog_of_face(*x).map_or(UNNAMED, |c| c.id());
        if m.faces.iter().zip(&t).all(|(x, &want)| c(x) == want) {
            continue;
        }
        println!(
            "{} {} {:?} {} {:?} {:?} faces {:?} truth {t:?} open {}",
            f.file_stem().unwrap().to_string_lossy(),
            m.id,
            m.kind,
            m.through,
            m.profile,
            m.catalog,
            m.faces,
            m.open_to.len()
        );
    }
    let mut missed: Vec<(u64, u32)> = truth
        .iter()
        .filter(|(f, &t)| t != STOCK && !feats.iter().any(|m| m.faces.contains(f)))
        .map(|(&f, &t)| (f, t))
        .collect();
    missed.sort();
    if !missed.is_empty() {
        println!(
            "{} in no feature: {missed:?}",
            f.file_stem().unwrap().to_string_lossy()
        );
    }
}

fn class_name(c: u32) -> &'static str {
    match c {
        STOCK => "stock",
        UNNAMED => "(feature, no catalogue name)",
        _ => Catalog::ALL[c as usize].name(),
    }
}

/// Faces right, faces in all, confusion (truth, predicted) → faces, and the
/// files with a wrong face.
struct Score {
    /// Per part, the class given to each face.
    given: Vec<HashMap<u64, u32>>,
    right: usize,
    total: usize,
    confusion: BTreeMap<(u32, u32), usize>,
    wrong_files: Vec<String>,
}

/// A part's machining features, as built or turned by the rigid motion
/// of `seed`.
fn recognize_file(
    f: &std::path::Path,
    seed: Option<u64>,
) -> (thinwall_brep::Part, Vec<MachiningFeature>) {
    let part = read_part(f, seed);
    let feats = recognize(&PartAnalysis::new(&part, Setup::default()));
    (part, feats)
}

/// A part as built, or turned by the rigid motion of `seed`.
fn read_part(f: &std::path::Path, seed: Option<u64>) -> thinwall_brep::Part {
    let text = common::posed_step(&std::fs::read_to_string(f).unwrap(), seed);
    thinwall_step::read_bytes(text.as_bytes(), "part.step")
        .unwrap_or_else(|e| panic!("{}: {e}", f.display()))
        .0
}

/// The shared parts, as built.
fn shared_files() -> Vec<std::path::PathBuf> {
    let files = common::step_files(&common::shared_data().join("mfcadpp_gen"));
    assert_eq!(files.len(), 240);
    files
}

fn score(files: &[std::path::PathBuf], turn: bool) -> Score {
    let mut s = Score {
        given: vec![],
        right: 0,
        total: 0,
        confusion: BTreeMap::new(),
        wrong_files: vec![],
    };
    for (i, f) in files.iter().enumerate() {
        let truth = labels(f);
        let (part, feats) = recognize_file(f, turn.then_some(1000 + i as u64));
        let got = predicted(&feats);
        // TW_DEBUG=<file name part> [TW_TURN=1]: print the wrong features
        // (for work on the catalogue; silent otherwise).
        if std::env::var("TW_DEBUG").is_ok_and(|d| f.to_string_lossy().contains(&d))
            && std::env::var("TW_TURN").is_ok() == turn
        {
            print_wrong(f, &feats, &truth);
        }
        let before = s.right;
        let mut given = HashMap::new();
        for face in &part.faces {
            let t = truth[&face.step_id];
            let p = got.get(&face.step_id).copied().unwrap_or(STOCK);
            given.insert(face.step_id, p);
            *s.confusion.entry((t, p)).or_default() += 1;
            s.total += 1;
            s.right += usize::from(t == p);
        }
        s.given.push(given);
        if s.right - before != part.faces.len() {
            s.wrong_files
                .push(f.file_name().unwrap().to_string_lossy().to_string());
        }
    }
    s
}

fn print(s: &Score, what: &str) {
    println!(
        "{what}: {}/{} faces right ({:.3} %), {} parts with a wrong face",
        s.right,
        s.total,
        100.0 * s.right as f64 / s.total as f64,
        s.wrong_files.len()
    );
    println!("confusion, truth -> predicted: faces (off-diagonal only)");
    for ((t, p), n) in &s.confusion {
        if t != p {
            println!(
                "  {t:>2} {:<26} -> {p:>2} {:<26} {n}",
                class_name(*t),
                class_name(*p)
            );
        }
    }
    println!("wrong parts: {:?}", s.wrong_files);
}

/// The target, 99.5 % of faces. Measured on the data the rules
/// were written against (in-sample: 99.55 % today), so it says the rules
/// cover these parts, not how they do on unseen ones.
const FLOOR: f64 = 0.995;

#[test]
fn mfcadpp_catalog_face_accuracy() {
    let s = score(&shared_files(), false);
    print(&s, "MFCAD++ generated");
    assert_eq!(s.total, 8611);
    assert!(s.right as f64 >= FLOOR * s.total as f64);
}

#[test]
fn mfcadpp_turned_by_rigid_motions_gets_the_same_classes() {
    let files = shared_files();
    let (s, turned) = (score(&files, false), score(&files, true));
    print(&turned, "MFCAD++ generated, turned");
    let differ = differences(&s, &turned, &files);
    println!("faces classed differently when turned: {differ:#?}");
    assert!(differ.is_empty(), "{differ:#?}");
}

/// A corpus of parts made by `scripts/generate_mfcadpp.py` with seeds of our
/// own, in the folder THINWALL_MFCADPP_DIR (never committed; see
/// docs/GENERATOR.md): the floor per face, and the same classes
/// turned. Which seed range is in-sample and which held out is the
/// caller's record (docs/GENERATOR.md says which were looked at).
#[test]
#[ignore = "needs a generated corpus in THINWALL_MFCADPP_DIR (docs/GENERATOR.md)"]
fn mfcadpp_generated_corpus() {
    let dir = std::env::var("THINWALL_MFCADPP_DIR").expect("THINWALL_MFCADPP_DIR: a corpus folder");
    let files = common::step_files(std::path::Path::new(&dir));
    assert!(!files.is_empty(), "{dir}: no STEP files");
    let (s, turned) = (score(&files, false), score(&files, true));
    print(&s, &format!("{dir}, {} parts", files.len()));
    let differ = differences(&s, &turned, &files);
    println!("faces classed differently when turned: {}", differ.len());
    for d in differ.iter().take(40) {
        println!("  {d}");
    }
    assert!(s.right as f64 >= FLOOR * s.total as f64);
    assert!(differ.is_empty());
}

/// Each face given another class turned than as built, named.
fn differences(s: &Score, turned: &Score, files: &[std::path::PathBuf]) -> Vec<String> {
    let mut differ = Vec::new();
    for ((a, b), f) in s.given.iter().zip(&turned.given).zip(files) {
        for (face, c) in a {
            if b[face] != *c {
                differ.push(format!(
                    "{} #{face}: {} turned {}",
                    f.display(),
                    class_name(*c),
                    class_name(b[face])
                ));
            }
        }
    }
    differ
}

/// Where two faces fold back onto each other (a knife edge: s2718_0023's
/// half cylinder and the plane it meets at 360°), the sign that tells
/// convex from concave is rounding noise, which a rigid motion tipped (the
/// slot's faces were grouped one way as built and another way turned).
/// Such an edge is `mixed` in every pose.
#[test]
fn a_knife_edge_has_no_convexity_in_any_pose() {
    let f = common::shared_data().join("mfcadpp_gen/s2718_0023.step");
    for seed in [None, Some(7), Some(8)] {
        let part = read_part(&f, seed);
        let graph = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
        let knife = graph.edges.iter().find(|e| e.step_id == 1152).unwrap();
        assert_eq!(
            knife.convexity,
            thinwall_graph::Convexity::Mixed,
            "turned {seed:?}"
        );
    }
}

/// What other cuts left of a feature keeps its catalogue name, as built
/// and turned: a through hole's slivers between a hexagonal passage's
/// walls (no block face, no floor); a quarter-round corner step whose
/// floor a V-notch cut away; a slot along an edge whose quarter-round end
/// a chamfer trimmed below 90°; a slot's one round end that a through hole
/// split in two (not a pocket's two ends); a triangular pocket whose inside
/// corner a chamfer took, the bevel wider than what is left of the two
/// faces it joins; two walls in a V of a triangular pocket, with a floor,
/// opening onto no block plane (not a two-sided step).
#[test]
fn pieces_other_cuts_left_keep_their_catalogue_name() {
    let cases: [(&str, &[u64], Catalog); 14] = [
        ("s2718_0108", &[4612], Catalog::ThroughHole),
        ("s2718_0151", &[6234, 6260], Catalog::ThroughHole),
        ("s2718_0195", &[1908], Catalog::CircularBlindStep),
        (
            "s2718_0113",
            &[902, 1459, 1612, 1639],
            Catalog::HCircularEndBlindSlot,
        ),
        (
            "s2718_0167",
            &[1765, 1837, 1909, 2220, 2248],
            Catalog::VCircularEndBlindSlot,
        ),
        (
            "s2718_0163",
            &[17, 165, 747, 773],
            Catalog::TriangularPocket,
        ),
        ("s2718_0163", &[236], Catalog::Chamfer),
        ("s2718_0123", &[2147, 2196, 2222], Catalog::TriangularPocket),
        (
            "s2718_0029",
            &[3126, 3175, 3201, 3377, 3426, 3453, 3514, 3541],
            Catalog::RectangularPocket,
        ),
        ("s2718_0091", &[1244], Catalog::RectangularPassage),
        (
            "s2718_0011",
            &[2244, 2271, 2419, 2466, 2493],
            Catalog::TriangularThroughSlot,
        ),
        (
            "s2718_0094",
            &[1192, 1466, 1515, 2726, 2887],
            Catalog::RectangularBlindSlot,
        ),
        ("s2718_0113", &[641], Catalog::Chamfer),
        ("s2718_0023", &[1121], Catalog::Chamfer),
    ];
    let dir = common::shared_data().join("mfcadpp_gen");
    for (stem, faces, want) in cases {
        let f = dir.join(format!("{stem}.step"));
        assert!(faces.iter().all(|x| labels(&f)[x] == want.id()));
        for seed in [None, Some(7), Some(8)] {
            let (_, feats) = recognize_file(&f, seed);
            let got = predicted(&feats);
            for x in faces {
                assert_eq!(got.get(x), Some(&want.id()), "{stem} #{x} turned {seed:?}");
            }
        }
    }
}

/// What other cuts leave of a feature, drawn small
/// (`scripts/make_catalog_fixtures.py`), keeps its catalogue name as built
/// and turned: three walls of a hexagonal pocket (two meeting at 120°
/// inside, which no triangle has) with their floor; what a passage left of
/// a blind hole drilled from a step's floor (entered from a face that is
/// not the block's).
#[test]
fn cut_pieces_drawn_small_keep_their_catalogue_name() {
    let dir = common::root().join("fixtures/machining/catalog");
    let cases = [
        ("hexagon_pocket_three_walls", Catalog::SixSidesPocket, 4),
        ("blind_hole_from_step_floor", Catalog::BlindHole, 2),
    ];
    for (stem, want, faces) in cases {
        let f = dir.join(format!("{stem}.step"));
        for seed in [None, Some(7), Some(8)] {
            let (_, feats) = recognize_file(&f, seed);
            let named: Vec<_> = feats.iter().filter(|m| m.catalog == Some(want)).collect();
            assert_eq!(named.len(), 1, "{stem} turned {seed:?}: {feats:#?}");
            assert_eq!(named[0].faces.len(), faces, "{stem} turned {seed:?}");
        }
    }
}
