//! Every machining feature classified by `thinwall-classify` in the plan's
//! order: each solid of a feature is a volume (built by truck and taken
//! into our B-rep directly, [`crate::solid_part`]), removed after every solid it touches that comes
//! earlier in the order. A feature takes the type and product adjacency of
//! its largest classified solid; `types` lists the others' where they
//! differ. A feature none of whose solids could be classified is
//! `unknown`, with the reason.

pub use crate::types::FeatureType;

use crate::types::FeatureSequence;
use crate::types::RemovalFeature;
use std::collections::HashMap;
use thinwall_analysis::{PartAnalysis, VolumeType};
use thinwall_classify::{classify, ProductAdjacency, Request, Volume};

/// A solid's 3-D box in the removal frame: x, y, z lows and highs (a half
/// cylinder's crest counted, not only the corners).
fn solid_box(s: &crate::types::FeatureSolid) -> [f64; 6] {
    let ring = |r: &Vec<[f64; 2]>| {
        geo::LineString::from(r.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>())
    };
    let region = geo::MultiPolygon::new(vec![geo::Polygon::new(
        ring(&s.rings[0]),
        s.rings[1..].iter().map(ring).collect(),
    )]);
    let (lo, hi) = (s.lower.range_over(&region), s.upper.range_over(&region));
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        lo[0],
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
        hi[1],
    ];
    for p in s.rings.iter().flatten() {
        for k in 0..2 {
            b[k] = b[k].min(p[k]);
            b[k + 3] = b[k + 3].max(p[k]);
        }
    }
    b
}

fn touch(a: &[f64; 6], b: &[f64; 6], tol: f64) -> bool {
    (0..3).all(|k| a[k] <= b[k + 3] + tol && b[k] <= a[k + 3] + tol)
}

/// Classify every feature; `frame` is the plan's removal frame.
pub fn classify_features(
    a: &PartAnalysis,
    frame: &[[f64; 3]; 4],
    features: &mut [RemovalFeature],
    seq: &FeatureSequence,
) {
    let order: HashMap<&str, usize> = seq
        .order
        .iter()
        .enumerate()
        .map(|(i, id)| (id.as_str(), i))
        .collect();
    let solids = Solids::read(frame, features);
    let tol = 1e-6 * a.bounding_box().diagonal().max(1.0);
    let rank: Vec<usize> = solids
        .owner
        .iter()
        .map(|&(fi, _)| {
            order
                .get(features[fi].id.as_str())
                .copied()
                .unwrap_or(usize::MAX)
        })
        .collect();
    let (before, together) = solids.pairs(&rank, tol);
    let result = classify(&Request {
        part: a,
        volumes: &solids.volumes,
        before: &before,
        together: &together,
        priority: vec![],
    });
    let classes = match result {
        Ok(c) => c,
        Err(e) => {
            let why = format!("classify.{}: {e}", e.code());
            for f in features.iter_mut() {
                f.classification = Some(unknown(&why));
            }
            return;
        }
    };
    solids.assign(features, &classes);
}

/// Pairs of indices into [`Solids`]' volumes.
type Pairs = Vec<(usize, usize)>;

/// The features' solids that could be written, as volumes, each with its
/// feature and solid index and its box.
struct Solids {
    volumes: Vec<Volume>,
    owner: Vec<(usize, usize)>,
    boxes: Vec<[f64; 6]>,
    /// Why a feature's solid could not be built, by feature.
    unreadable: Vec<Option<String>>,
}

impl Solids {
    fn read(frame: &[[f64; 3]; 4], features: &[RemovalFeature]) -> Self {
        let mut volumes: Vec<Volume> = Vec::new();
        let mut owner: Vec<(usize, usize)> = Vec::new();
        let mut boxes: Vec<[f64; 6]> = Vec::new();
        let mut unreadable: Vec<Option<String>> = vec![None; features.len()];
        for (fi, f) in features.iter().enumerate() {
            for (si, s) in f.solids.iter().enumerate() {
                let name = format!("{}#{}", f.id, si + 1);
                let Some(solid) = crate::volumes::feature_solid(frame, s) else {
                    continue;
                };
                let part = match crate::solid_part::part_of(&[(name.clone(), &solid)]) {
                    Ok(part) => part,
                    Err(e) => {
                        unreadable[fi] = Some(format!("its {e}"));
                        continue;
                    }
                };
                volumes.push(Volume {
                    name,
                    part,
                    current: None,
                    up: f
                        .access
                        .map(|a| thinwall_geom::Vector3::new(a[0], a[1], a[2])),
                });
                owner.push((fi, si));
                boxes.push(solid_box(s));
            }
        }
        Self {
            volumes,
            owner,
            boxes,
            unreadable,
        }
    }

    /// Pairs of solids whose boxes touch: of different features, the
    /// earlier (by `rank`) first; of one feature, removed together.
    fn pairs(&self, rank: &[usize], tol: f64) -> (Pairs, Pairs) {
        let (boxes, owner) = (&self.boxes, &self.owner);
        // Sweep along x: pairs whose boxes touch, the earlier one first.
        let mut by_x: Vec<usize> = (0..self.volumes.len()).collect();
        by_x.sort_by(|&i, &j| boxes[i][0].total_cmp(&boxes[j][0]));
        let mut before = Vec::new();
        for (k, &i) in by_x.iter().enumerate() {
            for &j in &by_x[k + 1..] {
                if boxes[j][0] > boxes[i][3] + tol {
                    break;
                }
                if owner[i].0 == owner[j].0 || !touch(&boxes[i], &boxes[j], tol) {
                    continue;
                }
                match rank[i].cmp(&rank[j]) {
                    std::cmp::Ordering::Less => before.push((i, j)),
                    std::cmp::Ordering::Greater => before.push((j, i)),
                    std::cmp::Ordering::Equal => {}
                }
            }
        }
        // A feature's solids are removed together.
        let mut together = Vec::new();
        for i in 0..owner.len() {
            // A feature's solids come one after another.
            for j in (i + 1..owner.len()).take_while(|&j| owner[j].0 == owner[i].0) {
                if touch(&boxes[i], &boxes[j], tol) {
                    together.push((i, j));
                }
            }
        }
        (before, together)
    }

    /// Each feature's type: its largest solid's, with the other types its
    /// solids have.
    fn assign(
        &self,
        features: &mut [RemovalFeature],
        classes: &[thinwall_classify::Classification],
    ) {
        let (owner, unreadable) = (&self.owner, &self.unreadable);
        for (fi, f) in features.iter_mut().enumerate() {
            let mine: Vec<(usize, &thinwall_classify::Classification)> = classes
                .iter()
                .enumerate()
                .filter(|(k, _)| owner[*k].0 == fi)
                .map(|(k, c)| (owner[k].1, c))
                .collect();
            // The largest solid; between solids of equal volume (up to the
            // sampling of curved edges) the type first by name, so every pose
            // agrees.
            let Some(&(largest, c)) = mine.iter().max_by(|x, y| {
                let (vx, vy) = (f.solids[x.0].volume_mm3, f.solids[y.0].volume_mm3);
                if (vx - vy).abs()
                    <= thinwall_geom::tolerance::EQUAL_VOLUME * vx.abs().max(vy.abs())
                {
                    y.1.kind.name().cmp(x.1.kind.name())
                } else {
                    vx.total_cmp(&vy)
                }
            }) else {
                f.classification = Some(unknown(unreadable[fi].as_deref().unwrap_or(
                    "its solids are bounded by a cylinder or a cone: not classified yet",
                )));
                continue;
            };
            let mut types: Vec<VolumeType> = mine
                .iter()
                .filter(|(si, _)| *si != largest)
                .map(|(_, o)| o.kind)
                .filter(|k| *k != c.kind)
                .collect();
            types.sort_by_key(|k| k.name());
            types.dedup();
            f.classification = Some(FeatureType {
                kind: c.kind,
                product_adjacency: c.product_adjacency,
                types,
                reason: c.reason.clone(),
            });
        }
    }
}

fn unknown(why: &str) -> FeatureType {
    FeatureType {
        kind: VolumeType::Unknown,
        product_adjacency: ProductAdjacency::None,
        types: Vec::new(),
        reason: Some(why.to_string()),
    }
}
