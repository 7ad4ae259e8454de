//! The product structure of a part in a set-up (DOMAIN.md §1, §3; Popma
//! 5.4.1, 6.1.2–6.1.3): base-leaf and crossing connections between the
//! stiffness features, validated as a forest plus symmetric crossings, and
//! whether each side of each wall can be reached by the tool.
//!
//! ```no_run
//! # let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! let setup = thinwall_connect::Setup::default();
//! let a = thinwall_analysis::PartAnalysis::new(&part, setup.clone());
//! let r = thinwall_recognize::recognize(&a, &thinwall_recognize::Config::default());
//! let s = thinwall_connect::connect(&r, &setup, &thinwall_connect::Options::default());
//! for c in &s.connections { println!("{c:?}"); }
//! ```

pub mod access;

pub use access::{side_access, swept_side_access, SideAccess};
pub use thinwall_analysis::{Machine, Setup};

use petgraph::algo::is_cyclic_directed;
use petgraph::graph::DiGraph;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use thinwall_analysis::FeatureId;
use thinwall_recognize::{Recognition, StiffnessFeature};
use thiserror::Error;

/// A link of the structure, by feature id.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Connection {
    /// The leaf is on or in the base.
    BaseLeaf { base: FeatureId, leaf: FeatureId },
    /// Two walls that meet and share a base; `features` in the order of
    /// their written ids ([`crossing`]).
    Crossing { features: [FeatureId; 2] },
}

/// A crossing of `a` and `b`, its features in the order of their written ids.
pub fn crossing(a: FeatureId, b: FeatureId) -> Connection {
    let features = if a.to_string() <= b.to_string() {
        [a, b]
    } else {
        [b, a]
    };
    Connection::Crossing { features }
}

/// Why a connection structure is not a forest with symmetric crossings.
#[derive(Debug, Error, PartialEq)]
pub enum StructureError {
    #[error("{0} is its own base")]
    OwnBase(FeatureId),
    #[error("{leaf} has two bases: {first} and {second}")]
    TwoBases {
        leaf: FeatureId,
        first: FeatureId,
        second: FeatureId,
    },
    #[error("base-leaf links form a cycle")]
    Cycle,
    #[error("{0} crosses itself")]
    CrossesItself(FeatureId),
    #[error("crossing {0} x {1} not in canonical order")]
    NotCanonical(FeatureId, FeatureId),
    #[error("{0} and {1} are both crossing and base-leaf")]
    CrossingAndBaseLeaf(FeatureId, FeatureId),
}

impl StructureError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            StructureError::OwnBase(_) => "own_base",
            StructureError::TwoBases { .. } => "two_bases",
            StructureError::Cycle => "cycle",
            StructureError::CrossesItself(_) => "crosses_itself",
            StructureError::NotCanonical(..) => "crossing_order",
            StructureError::CrossingAndBaseLeaf(..) => "crossing_and_base_leaf",
        }
    }
}

/// Connection options.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Options {
    /// Link thin walls to the thick walls they stand on (a clamping block,
    /// a thick foot). Off by default: thick walls are not stiffness
    /// features a planner sequences, so thin walls on them are roots.
    pub connect_thick_walls: bool,
}

/// The connection structure.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Structure {
    pub connections: Vec<Connection>,
    /// Per wall feature id: its two sides' accessibility.
    pub access: BTreeMap<FeatureId, [SideAccess; 2]>,
    /// Decisions worth telling the user (a second base suggested by the
    /// geometry, a cycle broken).
    pub notes: Vec<String>,
}

impl Structure {
    /// The base of a feature, if it has one.
    pub fn base_of(&self, id: FeatureId) -> Option<FeatureId> {
        self.connections.iter().find_map(|c| match c {
            Connection::BaseLeaf { base, leaf } if *leaf == id => Some(*base),
            _ => None,
        })
    }

    /// The structure as a petgraph graph: nodes are feature ids, edges
    /// `true` for base → leaf and `false` for a crossing (both directions).
    pub fn graph(&self) -> DiGraph<FeatureId, bool> {
        let mut g = DiGraph::new();
        let mut node = BTreeMap::new();
        let mut id = |g: &mut DiGraph<FeatureId, bool>, f: FeatureId| {
            *node.entry(f).or_insert_with(|| g.add_node(f))
        };
        for c in &self.connections {
            match *c {
                Connection::BaseLeaf { base, leaf } => {
                    let (a, b) = (id(&mut g, base), id(&mut g, leaf));
                    g.add_edge(a, b, true);
                }
                Connection::Crossing { features: [x, y] } => {
                    let (a, b) = (id(&mut g, x), id(&mut g, y));
                    g.add_edge(a, b, false);
                    g.add_edge(b, a, false);
                }
            }
        }
        g
    }

    /// Check the structure: base-leaf links form a forest (no cycle, no
    /// feature its own base, at most one base each), crossings are between
    /// distinct features, in canonical order, and not also base-leaf.
    pub fn validate(&self) -> Result<(), StructureError> {
        let mut bases: BTreeMap<FeatureId, FeatureId> = BTreeMap::new();
        let mut tree = DiGraph::<FeatureId, ()>::new();
        let mut node = BTreeMap::new();
        for c in &self.connections {
            if let Connection::BaseLeaf { base, leaf } = *c {
                if base == leaf {
                    return Err(StructureError::OwnBase(leaf));
                }
                if let Some(first) = bases.insert(leaf, base) {
                    return Err(StructureError::TwoBases {
                        leaf,
                        first,
                        second: base,
                    });
                }
                let a = *node.entry(base).or_insert_with(|| tree.add_node(base));
                let b = *node.entry(leaf).or_insert_with(|| tree.add_node(leaf));
                tree.add_edge(a, b, ());
            }
        }
        if is_cyclic_directed(&tree) {
            return Err(StructureError::Cycle);
        }
        for c in &self.connections {
            if let Connection::Crossing { features: [a, b] } = *c {
                if a == b {
                    return Err(StructureError::CrossesItself(a));
                }
                if crossing(a, b) != *c {
                    return Err(StructureError::NotCanonical(a, b));
                }
                if bases.get(&a) == Some(&b) || bases.get(&b) == Some(&a) {
                    return Err(StructureError::CrossingAndBaseLeaf(a, b));
                }
            }
        }
        Ok(())
    }
}

fn height(f: &StiffnessFeature, up: &thinwall_geom::Vector3) -> f64 {
    f.mid_point()
        .map_or(0.0, |(p, _)| p[0] * up.x + p[1] * up.y + p[2] * up.z)
}

/// Build the connection structure of a recognition in a set-up.
pub fn connect(r: &Recognition, setup: &Setup, options: &Options) -> Structure {
    let up = setup.up_in_part();
    let feats = &r.features;
    let in_structure = |i: usize| {
        feats[i].kind.is_wall() && (options.connect_thick_walls || feats[i].thin == Some(true))
    };
    let mut notes = Vec::new();
    let mut base: BTreeMap<usize, usize> = r
        .bases
        .iter()
        .filter(|(&leaf, &b)| in_structure(leaf) && in_structure(b))
        .map(|(&leaf, &b)| (leaf, b))
        .collect();
    break_cycles(feats, &mut base, &up, &mut notes);
    let crossings = link_junctions(r, &in_structure, &mut base, &up, &mut notes);
    let mut connections: Vec<Connection> = base
        .iter()
        .map(|(&leaf, &b)| Connection::BaseLeaf {
            base: feats[b].id,
            leaf: feats[leaf].id,
        })
        .collect();
    // Depressions and details are leaves of the wall they are in or on.
    for f in feats.iter().filter(|f| !f.kind.is_wall()) {
        if let Some(w) = f.wall {
            connections.push(Connection::BaseLeaf {
                base: w,
                leaf: f.id,
            });
        }
    }
    for (a, b) in crossings {
        connections.push(crossing(feats[a].id, feats[b].id));
    }
    Structure {
        connections,
        access: access(feats, &up, setup),
        notes,
    }
}

/// Break cycles (two walls each standing on the other along equally long
/// feet): on each, drop the link whose base is highest, so the lower wall
/// stays the base.
fn break_cycles(
    feats: &[StiffnessFeature],
    base: &mut BTreeMap<usize, usize>,
    up: &thinwall_geom::Vector3,
    notes: &mut Vec<String>,
) {
    while let Some(on_cycle) = first_cycle(base) {
        let mut members = vec![on_cycle];
        let mut at = base[&on_cycle];
        while at != on_cycle {
            members.push(at);
            at = base[&at];
        }
        let drop = members
            .iter()
            .copied()
            .max_by(|&a, &b| height(&feats[base[&a]], up).total_cmp(&height(&feats[base[&b]], up)))
            .expect("cycle");
        notes.push(format!(
            "{} and {} stood on each other; {} kept as the base (lower in the set-up)",
            feats[drop].id, feats[base[&drop]].id, feats[drop].id
        ));
        base.remove(&drop);
    }
}

/// A wall on a cycle of bases: the first repeated wall on the walk down
/// from the first leaf (in order) whose walk repeats.
fn first_cycle(base: &BTreeMap<usize, usize>) -> Option<usize> {
    base.keys().find_map(|&start| {
        let mut seen = BTreeSet::new();
        let mut at = start;
        while let Some(&b) = base.get(&at) {
            if !seen.insert(at) {
                return Some(at);
            }
            at = b;
        }
        None
    })
}

/// A wall and its bases down to the root.
fn ancestors(mut w: usize, base: &BTreeMap<usize, usize>) -> Vec<usize> {
    let mut v = vec![w];
    while let Some(&b) = base.get(&w) {
        if v.contains(&b) {
            break;
        }
        v.push(b);
        w = b;
    }
    v
}

/// Junctions not used as a base: a crossing when the walls share a base,
/// else (procedure 2) base-leaf with the lower wall as base. Returns the
/// crossings (by position, smaller first).
fn link_junctions(
    r: &Recognition,
    in_structure: &impl Fn(usize) -> bool,
    base: &mut BTreeMap<usize, usize>,
    up: &thinwall_geom::Vector3,
    notes: &mut Vec<String>,
) -> BTreeSet<(usize, usize)> {
    let feats = &r.features;
    let mut crossings: BTreeSet<(usize, usize)> = BTreeSet::new();
    let mut junctions: Vec<(usize, usize)> = r.junctions.iter().map(|j| (j.leaf, j.base)).collect();
    junctions.sort();
    junctions.dedup();
    for (a, b) in junctions {
        if a == b || !in_structure(a) || !in_structure(b) {
            continue;
        }
        if base.get(&a) == Some(&b) || base.get(&b) == Some(&a) {
            continue;
        }
        let (anc_a, anc_b) = (ancestors(a, base), ancestors(b, base));
        let common = anc_a
            .iter()
            .any(|x| anc_b.contains(x) && *x != a && *x != b);
        if common || anc_a.contains(&b) || anc_b.contains(&a) {
            crossings.insert((a.min(b), a.max(b)));
            continue;
        }
        let (lower, upper) = if height(&feats[a], up) <= height(&feats[b], up) {
            (a, b)
        } else {
            (b, a)
        };
        match base.entry(upper) {
            std::collections::btree_map::Entry::Occupied(kept) => {
                notes.push(format!(
                    "{} meets {} too; it keeps {} as its base (longest foot), the meeting is reported as a crossing",
                    feats[upper].id, feats[lower].id, feats[*kept.get()].id
                ));
                crossings.insert((a.min(b), a.max(b)));
            }
            std::collections::btree_map::Entry::Vacant(slot) => {
                slot.insert(lower);
            }
        }
    }
    crossings
}

/// Each wall's two sides judged for access in the set-up.
fn access(
    feats: &[StiffnessFeature],
    up: &thinwall_geom::Vector3,
    setup: &Setup,
) -> BTreeMap<FeatureId, [SideAccess; 2]> {
    feats
        .iter()
        .filter(|f| f.kind.is_wall())
        .filter_map(|f| {
            let d = f.access_directions.as_ref()?;
            let judge = |s: usize| match swept_normals(f, s) {
                Some(dirs) => swept_side_access(&dirs, up, &setup.machine)
                    .unwrap_or_else(|| side_access(d[s], up, &setup.machine)),
                None => side_access(d[s], up, &setup.machine),
            };
            Some((f.id, [judge(0), judge(1)]))
        })
        .collect()
}

/// Samples a curved wall's side normal takes along its arc (every few
/// degrees, both ends included); `None` for a flat wall.
fn swept_normals(f: &StiffnessFeature, side: usize) -> Option<Vec<[f64; 3]>> {
    let m = f.mid_surface.as_ref()?;
    let v3 = |a: [f64; 3]| thinwall_geom::Vector3::from(a);
    let (Some(axis), Some(u), Some([t0, t1])) = (m.axis, m.reference, m.angle_range_deg) else {
        // A free-form wall: its normals at both ends and the middle.
        let r = f.access_range.as_ref()?[side];
        let mid = f.access_directions.as_ref()?[side];
        return Some(vec![r[0], mid, r[1]]);
    };
    let (axis, u) = (v3(axis), v3(u));
    let v = axis.cross(&u);
    let alpha = m.half_angle_deg.unwrap_or(0.0).to_radians();
    let steps = ((t1 - t0).abs() / SWEEP_STEP_DEG).ceil().max(1.0) as usize;
    let sign = if side == 0 { 1.0 } else { -1.0 };
    Some(
        (0..=steps)
            .map(|k| {
                let t = (t0 + (t1 - t0) * k as f64 / steps as f64).to_radians();
                let radial = u * t.cos() + v * t.sin();
                let n = (radial * alpha.cos() - axis * alpha.sin()) * sign;
                [n.x, n.y, n.z]
            })
            .collect(),
    )
}

/// Step between the sampled normals of a curved side, degrees.
const SWEEP_STEP_DEG: f64 = 2.0;
