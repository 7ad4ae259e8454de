//! Every shared STEP file loads, and the faces of its solid bodies are
//! exactly the `ADVANCED_FACE`s its solids' shells reference (checked with
//! an independent scan of the file text).

mod common;

use std::collections::{BTreeSet, HashMap};
use std::path::Path;

/// `#id = KEYWORD(args);` statements of a Part 21 file, by id (simple
/// entities only; enough for the topology entities we check).
fn statements(text: &str) -> HashMap<u64, (String, String)> {
    let mut out = HashMap::new();
    let data = text.split("DATA;").nth(1).unwrap_or("");
    for stmt in data.split(";\n").chain(data.split(";\r\n")) {
        let stmt = stmt.trim();
        let Some(rest) = stmt.strip_prefix('#') else {
            continue;
        };
        let Some((id, body)) = rest.split_once('=') else {
            continue;
        };
        let Ok(id) = id.trim().parse::<u64>() else {
            continue;
        };
        let body = body.trim();
        let Some((kw, args)) = body.split_once('(') else {
            continue;
        };
        out.insert(id, (kw.trim().to_string(), args.to_string()));
    }
    out
}

fn refs(args: &str) -> Vec<u64> {
    let mut v = Vec::new();
    let b = args.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'#' {
            let mut j = i + 1;
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            if let Ok(n) = args[i + 1..j].parse() {
                v.push(n);
            }
            i = j;
        } else {
            i += 1;
        }
    }
    v
}

/// ADVANCED_FACE ids referenced by the shells of every solid in the file.
fn solid_face_ids(text: &str) -> BTreeSet<u64> {
    let st = statements(text);
    let mut faces = BTreeSet::new();
    for (kw, args) in st.values() {
        if kw != "MANIFOLD_SOLID_BREP" && kw != "BREP_WITH_VOIDS" {
            continue;
        }
        let mut stack = refs(args);
        while let Some(id) = stack.pop() {
            match st.get(&id) {
                Some((k, a)) if k == "CLOSED_SHELL" => stack.extend(refs(a)),
                Some((k, a)) if k == "ORIENTED_CLOSED_SHELL" => stack.extend(refs(a)),
                Some((k, _)) if k == "ADVANCED_FACE" => {
                    faces.insert(id);
                }
                _ => {}
            }
        }
    }
    faces
}

fn check(path: &Path) -> usize {
    let (part, _) = thinwall_step::read_file(path).unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
    let expected = solid_face_ids(&text);
    let ours: BTreeSet<u64> = part.faces.iter().map(|f| f.step_id).collect();
    assert_eq!(
        ours.len(),
        part.faces.len(),
        "{}: duplicate face ids",
        path.display()
    );
    assert_eq!(
        ours,
        expected,
        "{}: solid faces differ from the file's shells",
        path.display()
    );
    check_ordinals(&part, path);
    part.faces.len()
}

/// The faces' ordinals in OpenCascade's order are distinct and leave
/// exactly the supplemental surface models' faces unnamed (which face each
/// ordinal is, OpenCascade itself checks: `python/tests/test_ordinals.py`).
fn check_ordinals(part: &thinwall_brep::Part, path: &Path) {
    let order = part.occ_faces();
    assert_eq!(
        part.occ_ordinals.len(),
        part.faces.len(),
        "{}",
        path.display()
    );
    assert_eq!(
        order.len(),
        part.faces.len() + part.supplemental.face_count,
        "{}",
        path.display()
    );
    let named = order.iter().flatten().count();
    assert_eq!(
        named,
        part.faces.len(),
        "{}: an ordinal given twice",
        path.display()
    );
    for (i, f) in part.faces.iter().enumerate() {
        let key = order[part.occ_ordinals[i] as usize].expect("named");
        assert_eq!((key.body, key.step_id), (f.body.0, f.step_id));
    }
}

#[test]
fn mfcad_train_loads_with_exact_face_sets() {
    let files = common::step_files(&common::shared_data().join("mfcad/train"));
    assert_eq!(files.len(), 200);
    let faces: usize = files.iter().map(|f| check(f)).sum();
    assert!(faces > 4000, "{faces} faces");
}

#[test]
fn thinwall_and_mfinstseg_load_with_exact_face_sets() {
    for set in ["thinwall", "mfinstseg"] {
        for f in common::step_files(&common::shared_data().join(set)) {
            check(&f);
        }
    }
}

#[test]
fn nist_brep_files_load_and_the_tessellated_one_is_rejected() {
    let mut loaded = 0;
    for f in common::step_files(&common::shared_data().join("nist")) {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        if name.contains("-tg") {
            let err = thinwall_step::read_file(&f).expect_err("tessellated file must be rejected");
            let msg = err.to_string();
            assert_eq!(err.code(), "no_brep");
            assert!(msg.contains(&name) && msg.contains("tessellated"), "{msg}");
            continue;
        }
        check(&f);
        loaded += 1;
    }
    assert_eq!(loaded, 12);
}

#[test]
fn supplemental_surface_geometry_is_kept_apart() {
    let nist = common::shared_data().join("nist");
    let (part, _) = thinwall_step::read_file(nist.join("nist_ftc_10_asme1_ap242-e2.stp")).unwrap();
    assert_eq!(part.supplemental.face_count, 18);
    assert_eq!(part.bodies.len(), 1);
    // The supplemental faces are in no body and not in the face list.
    let in_bodies: usize = part
        .bodies
        .iter()
        .flat_map(|b| &b.shells)
        .map(|s| s.faces.len())
        .sum();
    assert_eq!(in_bodies, part.faces.len());
    let (ctc1, _) = thinwall_step::read_file(nist.join("nist_ctc_01_asme1_ap242-e1.stp")).unwrap();
    assert_eq!(ctc1.supplemental.face_count, 0);
    // OpenCascade numbers supplemental faces where the statement linking
    // their representation stands: after the solid's in FTC 10, before it
    // in STC 07 (its surface model's representation is linked first).
    let after = part.occ_faces();
    assert!(after[..part.faces.len()].iter().all(Option::is_some));
    let (stc7, _) = thinwall_step::read_file(nist.join("nist_stc_07_asme1_ap242-e3.stp")).unwrap();
    let before = stc7.occ_faces();
    assert_eq!(stc7.supplemental.face_count, 2);
    assert!(before[..2].iter().all(Option::is_none) && before[2..].iter().all(Option::is_some));
}

#[test]
fn units_are_converted_to_millimetres() {
    let nist = common::shared_data().join("nist");
    let (inch, _) = thinwall_step::read_file(nist.join("nist_ctc_05_asme1_ap242-e1.stp")).unwrap();
    assert!((inch.units.mm_per_unit - 25.4).abs() < 1e-9);
    // The file's vertex extent is 20.75 in along x (manifest): 527.05 mm.
    let size = inch.bounding_box().size();
    assert!((size[0] - 20.75 * 25.4).abs() < 0.01, "{size:?}");
    let (mm, _) = thinwall_step::read_file(nist.join("nist_ctc_01_asme1_ap242-e1.stp")).unwrap();
    assert_eq!(mm.units.mm_per_unit, 1.0);
    let s = mm.bounding_box().size();
    assert!(
        (s[0] - 800.0).abs() < 1e-6 && (s[1] - 450.0).abs() < 1e-6,
        "{s:?}"
    );
}
