//! Recognition fixtures (`fixtures/recognition/*.expected.json`, made by
//! `scripts/make_recognition_fixtures.py`): loading, and mapping the
//! expected faces (given by centroid) to the faces Thinwall reads.

use serde::Deserialize;
use std::collections::{BTreeSet, HashMap};
use thinwall_brep::{compute_face_props, Part};
use thinwall_geom::Point3;
use thinwall_recognize::{Config, Recognition};

#[derive(Deserialize)]
pub struct Expected {
    pub kind: String,
    #[serde(default)]
    pub name: Option<String>,
    #[serde(default)]
    pub thin: Option<bool>,
    #[serde(default)]
    pub thickness: Option<f64>,
    #[serde(default)]
    pub side_faces_at: Vec<[f64; 3]>,
    #[serde(default)]
    pub faces_at: Vec<[f64; 3]>,
    #[serde(default)]
    pub wall: Option<String>,
    #[serde(default)]
    pub large: Option<bool>,
}

#[derive(Deserialize)]
pub struct Fixture {
    pub part: String,
    pub up: [f64; 3],
    pub features: Vec<Expected>,
}

pub fn dir() -> std::path::PathBuf {
    super::root().join("fixtures/recognition")
}

/// Read a fixture and recognize it with `up` (the fixture's own when `None`).
pub fn load_with_up(name: &str, up: Option<[f64; 3]>) -> (Part, Fixture, Recognition) {
    let fx: Fixture = serde_json::from_str(
        &std::fs::read_to_string(dir().join(format!("{name}.expected.json"))).unwrap(),
    )
    .unwrap();
    let (part, _) = thinwall_step::read_file(dir().join(&fx.part)).unwrap();
    let r = super::recognize_with(&part, up.unwrap_or(fx.up), &Config::default());
    (part, fx, r)
}

pub fn load(name: &str) -> (Part, Fixture, Recognition) {
    load_with_up(name, None)
}

/// Map centroids to face step ids.
pub fn ids_at(part: &Part, centroids: &[[f64; 3]]) -> BTreeSet<u64> {
    let props: Vec<Point3> = part
        .face_ids()
        .map(|f| compute_face_props(part, f).centroid)
        .collect();
    let diag = part.bounding_box().diagonal();
    centroids
        .iter()
        .map(|c| {
            let p = Point3::new(c[0], c[1], c[2]);
            let (i, d) = props
                .iter()
                .enumerate()
                .map(|(i, q)| (i, (q - p).norm()))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .unwrap();
            assert!(d < 1e-4 * diag, "no face at {p} (nearest {d})");
            part.faces[i].step_id
        })
        .collect()
}

/// Our feature id for an expected feature, if recognized with its faces.
pub fn our_id(part: &Part, r: &Recognition, e: &Expected) -> Option<String> {
    let is_wall = !e.side_faces_at.is_empty();
    let want = ids_at(
        part,
        if is_wall {
            &e.side_faces_at
        } else {
            &e.faces_at
        },
    );
    r.features
        .iter()
        .find(|f| {
            let got: BTreeSet<u64> = if is_wall {
                f.side_faces
                    .clone()
                    .unwrap_or_default()
                    .into_iter()
                    .collect()
            } else {
                f.faces.iter().copied().collect()
            };
            got == want
        })
        .map(|f| f.id.to_string())
}

/// Expected names (walls) to our ids.
pub fn names(part: &Part, fx: &Fixture, r: &Recognition) -> HashMap<String, String> {
    fx.features
        .iter()
        .filter_map(|e| Some((e.name.clone()?, our_id(part, r, e)?)))
        .collect()
}
