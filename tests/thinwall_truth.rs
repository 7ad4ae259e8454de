//! Stiffness features on `../shared/data/thinwall` against the ground truth
//! (`*.truth.json`): every thin wall, hole, cut-out and fillet found with
//! the right kind and faces; nothing else reported as a thin wall.

mod common;

use serde::Deserialize;
use std::collections::BTreeSet;
use thinwall_recognize::{Config, StiffnessFeature};

#[derive(Deserialize)]
struct TruthFeature {
    id: String,
    kind: String,
    #[serde(default)]
    thin: Option<bool>,
    #[serde(default)]
    thickness: Option<f64>,
    #[serde(default)]
    side_faces: Vec<u64>,
    #[serde(default)]
    faces: Vec<u64>,
    #[serde(default)]
    wall: Option<String>,
}

#[derive(Deserialize)]
struct TruthConnection {
    base: String,
    leaf: String,
    kind: String,
}

#[derive(Deserialize)]
struct Truth {
    part: String,
    up: [f64; 3],
    features: Vec<TruthFeature>,
    connections: Vec<TruthConnection>,
}

fn set(v: &[u64]) -> BTreeSet<u64> {
    v.iter().copied().collect()
}

/// Our feature id for each truth feature id (by faces).
fn id_map(truth: &Truth, ours: &[StiffnessFeature]) -> std::collections::HashMap<String, String> {
    let mut m = std::collections::HashMap::new();
    for t in &truth.features {
        let hit = ours.iter().find(|f| {
            if t.side_faces.is_empty() {
                set(&f.faces) == set(&t.faces)
            } else {
                f.side_faces
                    .as_deref()
                    .is_some_and(|s| set(s) == set(&t.side_faces))
            }
        });
        if let Some(f) = hit {
            m.insert(t.id.clone(), f.id.to_string());
        }
    }
    m
}

/// Connections in both, as comparable strings.
fn connection_set(
    truth: &Truth,
    ours: &thinwall_connect::Structure,
    ids: &std::collections::HashMap<String, String>,
) -> (BTreeSet<String>, BTreeSet<String>) {
    let want = truth
        .connections
        .iter()
        .map(|c| {
            let (b, l) = (
                ids.get(&c.base).cloned().unwrap_or(c.base.clone()),
                ids.get(&c.leaf).cloned().unwrap_or(c.leaf.clone()),
            );
            if c.kind == "crossing" {
                let (x, y) = if b <= l { (b, l) } else { (l, b) };
                format!("crossing {x} {y}")
            } else {
                format!("base_leaf {b} {l}")
            }
        })
        .collect();
    let got = ours
        .connections
        .iter()
        .map(|c| match c {
            thinwall_connect::Connection::BaseLeaf { base, leaf } => {
                format!("base_leaf {base} {leaf}")
            }
            thinwall_connect::Connection::Crossing { features } => {
                format!("crossing {} {}", features[0], features[1])
            }
        })
        .collect();
    (want, got)
}

/// Differences between the recognition of one part and its truth.
fn compare(truth: &Truth, ours: &[StiffnessFeature]) -> Vec<String> {
    let mut problems = Vec::new();
    let id_of = id_map(truth, ours);
    let matched: BTreeSet<String> = id_of.values().cloned().collect();
    for t in &truth.features {
        let Some(f) = id_of
            .get(&t.id)
            .and_then(|id| ours.iter().find(|f| f.id.to_string() == *id))
        else {
            problems.push(format!("{}: {} {} not found", truth.part, t.kind, t.id));
            continue;
        };
        if f.kind.name() != t.kind {
            problems.push(format!(
                "{}: {} is {} here, {} in the truth",
                truth.part,
                t.id,
                f.kind.name(),
                t.kind
            ));
        }
        if let Some(thin) = t.thin {
            if f.thin != Some(thin) {
                problems.push(format!(
                    "{}: {} thin {:?}, truth {thin}",
                    truth.part, t.id, f.thin
                ));
            }
        }
        if let Some(th) = t.thickness {
            if (f.thickness.unwrap_or(0.0) - th).abs() > 1e-6 {
                problems.push(format!(
                    "{}: {} thickness {:?}, truth {th}",
                    truth.part, t.id, f.thickness
                ));
            }
        }
    }
    // Depressions and details sit in the right wall.
    for t in &truth.features {
        if let (Some(w), Some(ours_id)) = (&t.wall, id_of.get(&t.id)) {
            let f = ours.iter().find(|f| f.id.to_string() == *ours_id).unwrap();
            if f.wall.map(|w| w.to_string()).as_ref() != id_of.get(w) {
                problems.push(format!(
                    "{}: {} is in {:?}, truth {w} ({:?})",
                    truth.part,
                    t.id,
                    f.wall,
                    id_of.get(w)
                ));
            }
        }
    }
    for f in ours {
        if f.thin == Some(true) && !matched.contains(&f.id.to_string()) {
            problems.push(format!(
                "{}: {} {} {:?} reported thin, not in the truth",
                truth.part,
                f.kind.name(),
                f.id,
                f.side_faces
            ));
        }
    }
    problems
}

/// Each part of the set with its truth and our recognition.
fn recognized_parts() -> Vec<(String, Truth, thinwall_recognize::Recognition)> {
    let dir = common::shared_data().join("thinwall");
    common::step_files(&dir)
        .into_iter()
        .map(|f| {
            let stem = f.file_stem().unwrap().to_string_lossy().to_string();
            let truth: Truth = serde_json::from_str(
                &std::fs::read_to_string(dir.join(format!("{stem}.truth.json"))).unwrap(),
            )
            .unwrap();
            let (part, _) = thinwall_step::read_file(&f).unwrap();
            let r = common::recognize_with(&part, truth.up, &Config::default());
            (stem, truth, r)
        })
        .collect()
}

#[test]
fn thinwall_parts_match_the_ground_truth() {
    let mut problems = Vec::new();
    let mut checked = 0;
    for (_, truth, r) in recognized_parts() {
        problems.extend(compare(&truth, &r.features));
        checked += truth.features.len();
    }
    for p in &problems {
        println!("{p}");
    }
    assert!(checked > 40, "{checked} truth features");
    assert!(
        problems.is_empty(),
        "{} differences from the ground truth",
        problems.len()
    );
}

#[test]
fn thinwall_connections_match_the_ground_truth() {
    let mut problems = Vec::new();
    let mut compared = 0;
    for (stem, truth, r) in recognized_parts() {
        let setup = thinwall_connect::Setup {
            up: truth.up,
            ..Default::default()
        };
        let s = thinwall_connect::connect(&r, &setup, &thinwall_connect::Options::default());
        s.validate().unwrap_or_else(|e| panic!("{stem}: {e}"));
        let ids = id_map(&truth, &r.features);
        let (want, got) = connection_set(&truth, &s, &ids);
        for w in want.difference(&got) {
            problems.push(format!("{stem}: missing {w}"));
        }
        // Links among features the truth knows must all be in the truth.
        let known: BTreeSet<&String> = ids.values().collect();
        for g in got.difference(&want) {
            let words: Vec<&str> = g.split(' ').collect();
            if known.contains(&words[1].to_string()) && known.contains(&words[2].to_string()) {
                problems.push(format!("{stem}: extra {g}"));
            }
        }
        compared += want.len();
    }
    for p in &problems {
        println!("{p}");
    }
    assert!(compared > 50, "{compared} truth connections");
    assert!(
        problems.is_empty(),
        "{} connection differences",
        problems.len()
    );
}
