//! What the rules look at, per stiffness feature: its kind, its top along
//! the set-up's up, its base and crossings, and for walls the directions
//! of their length and height. Read from the pipeline's outcome; nothing
//! is recognised again.

use std::collections::{BTreeMap, BTreeSet};
use thinwall_analysis::measure::boundary_points;
use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_brep::Part;
use thinwall_connect::Connection;
use thinwall_geom::Vector3;
use thinwall_pipeline::Outcome;

/// One feature's facts.
#[derive(Clone, Debug)]
pub struct Fact {
    pub id: FeatureId,
    pub kind: StiffnessKind,
    /// Highest point of its faces along up, mm.
    pub top: f64,
    /// Walls: along the wall, square to its height (unit).
    pub length_direction: Option<Vector3>,
    /// Walls: its height direction, away from its base (unit).
    pub height_direction: Option<Vector3>,
}

/// The features and how they are connected.
#[derive(Clone, Debug)]
pub struct Scene {
    pub facts: Vec<Fact>,
    /// Leaf → base.
    pub base: BTreeMap<FeatureId, FeatureId>,
    /// Crossing pairs, both ways.
    pub crossings: BTreeSet<(FeatureId, FeatureId)>,
}

impl Scene {
    /// The scene of a pipeline run on `part`.
    pub fn of(part: &Part, out: &Outcome) -> Self {
        let up = out.setup.up_in_part();
        let by_step: BTreeMap<u64, thinwall_brep::FaceId> =
            part.face_ids().map(|f| (part.face(f).step_id, f)).collect();
        let facts = out
            .recognition
            .features
            .iter()
            .map(|f| {
                let top = f
                    .faces
                    .iter()
                    .filter_map(|s| by_step.get(s))
                    .flat_map(|&face| boundary_points(part, face))
                    .map(|p| p.coords.dot(&up))
                    .fold(f64::NEG_INFINITY, f64::max);
                let (length_direction, height_direction) = match &f.geometry {
                    Some(g) => {
                        let h = g.height_direction;
                        (g.frame.z.cross(&h).try_normalize(1e-9), Some(h))
                    }
                    None => (None, None),
                };
                Fact {
                    id: f.id,
                    kind: f.kind,
                    top,
                    length_direction,
                    height_direction,
                }
            })
            .collect();
        let mut base = BTreeMap::new();
        let mut crossings = BTreeSet::new();
        for c in &out.structure.connections {
            match c {
                Connection::BaseLeaf { base: b, leaf } => {
                    base.insert(*leaf, *b);
                }
                Connection::Crossing { features: [a, b] } => {
                    crossings.insert((*a, *b));
                    crossings.insert((*b, *a));
                }
            }
        }
        Self {
            facts,
            base,
            crossings,
        }
    }

    pub fn fact(&self, id: FeatureId) -> Option<&Fact> {
        self.facts.iter().find(|f| f.id == id)
    }
}
