//! Conventional machining features: MFCAD per-face accuracy over its 16
//! classes (labels by face name), MFInstSeg's labelled sample, every NIST
//! B-rep part without error.

mod common;

use std::collections::BTreeMap;
use thinwall_machining::{mfcad_class, recognize};

fn run(
    path: &std::path::Path,
) -> (
    thinwall_brep::Part,
    Vec<thinwall_machining::MachiningFeature>,
) {
    let (part, _) = thinwall_step::read_file(path).unwrap_or_else(|e| panic!("{e}"));
    let graph = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
    let m = recognize(&part, &graph);
    (part, m)
}

#[test]
fn mfcad_train_face_accuracy_is_at_least_99_5_percent() {
    let files = common::step_files(&common::shared_data().join("mfcad/train"));
    assert_eq!(files.len(), 200);
    let mut confusion: BTreeMap<(u64, u64), usize> = BTreeMap::new();
    let (mut right, mut total) = (0usize, 0usize);
    for f in &files {
        let labels: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(f.with_extension("labels.json")).unwrap(),
        )
        .unwrap();
        let labels: Vec<u64> = labels["face_labels"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_u64().unwrap())
            .collect();
        let (part, m) = run(f);
        for face in &part.faces {
            let truth = labels[face
                .name
                .parse::<usize>()
                .expect("MFCAD faces are named by index")];
            let got = mfcad_class(&m, face.step_id);
            *confusion.entry((truth, got)).or_default() += 1;
            total += 1;
            right += usize::from(got == truth);
        }
    }
    let accuracy = right as f64 / total as f64;
    println!(
        "MFCAD train: {right}/{total} faces right ({:.3} %)",
        100.0 * accuracy
    );
    println!("confusion (truth -> predicted: faces), off-diagonal:");
    for ((t, p), n) in &confusion {
        if t != p {
            println!("  {t} -> {p}: {n}");
        }
    }
    assert_eq!(total, 4482);
    assert!(accuracy >= 0.995, "accuracy {accuracy}");
}

#[test]
fn mfinstseg_sample_holes_step_and_rounds() {
    let dir = common::shared_data().join("mfinstseg");
    let (part, m) = run(&dir.join("test.step"));
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("test.json")).unwrap()).unwrap();
    let seg = &t[0][1]["seg"];
    // Faces are labelled by their position in the shell (= file order here).
    let mut problems = Vec::new();
    for (i, face) in part.faces.iter().enumerate() {
        let class = seg[i.to_string()].as_u64().unwrap();
        let feat = m.iter().find(|f| f.faces.contains(&face.step_id));
        let ok = match class {
            // MFCAD++: 1 through_hole, 22 rectangular_blind_step, 23 round, 24 stock.
            1 => feat.is_some_and(|f| f.kind == "hole" && f.through),
            22 => {
                feat.is_some_and(|f| f.kind == "step" && !f.through && f.profile == "rectangular")
            }
            23 => feat.is_some_and(|f| f.kind == "fillet" && f.profile == "round"),
            24 => feat.is_none(),
            other => panic!("class {other} not in the sample"),
        };
        if !ok {
            problems.push(format!(
                "face {i} #{} class {class}: {:?}",
                face.step_id,
                feat.map(|f| (&f.kind, f.through, &f.profile))
            ));
        }
    }
    for p in &problems {
        println!("{p}");
    }
    assert!(problems.is_empty(), "{} faces wrong", problems.len());
}

#[test]
fn every_nist_brep_part_runs() {
    for f in common::step_files(&common::shared_data().join("nist")) {
        if f.to_string_lossy().contains("-tg") {
            continue;
        }
        let (part, m) = run(&f);
        // Every feature names faces of the part, none twice.
        let mut seen = std::collections::HashSet::new();
        for feat in &m {
            for id in &feat.faces {
                assert!(part.faces.iter().any(|x| x.step_id == *id));
                assert!(
                    seen.insert(*id),
                    "{}: face #{id} in two features",
                    f.display()
                );
            }
        }
    }
}
