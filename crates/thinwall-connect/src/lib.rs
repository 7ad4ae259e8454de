//! The product structure of a part in a set-up (DOMAIN.md §1, §3; Popma
//! 5.4.1, 6.1.2–6.1.3): base-leaf and crossing connections between the
//! stiffness features, validated as a forest plus symmetric crossings, and
//! whether each side of each wall can be reached by the tool.
//!
//! ```no_run
//! # let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! # let graph = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
//! let setup = thinwall_connect::Setup::default();
//! let config = thinwall_recognize::Config { up: setup.up, ..Default::default() };
//! let r = thinwall_recognize::recognize(&part, &graph, &config);
//! let s = thinwall_connect::connect(&r, &setup, &thinwall_connect::Options::default());
//! for c in &s.connections { println!("{c:?}"); }
//! ```

pub mod access;
pub mod setup;

pub use access::{side_access, SideAccess};
pub use setup::{Machine, Setup};

use petgraph::algo::is_cyclic_directed;
use petgraph::graph::DiGraph;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use thinwall_recognize::{Recognition, StiffnessFeature};

/// A link of the structure, by feature id.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Connection {
    /// The leaf is on or in the base.
    BaseLeaf { base: String, leaf: String },
    /// Two walls that meet and share a base; `features` sorted.
    Crossing { features: [String; 2] },
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
    pub access: BTreeMap<String, [SideAccess; 2]>,
    /// Decisions worth telling the user (a second base suggested by the
    /// geometry, a cycle broken).
    pub notes: Vec<String>,
}

impl Structure {
    /// The base of a feature, if it has one.
    pub fn base_of(&self, id: &str) -> Option<&str> {
        self.connections.iter().find_map(|c| match c {
            Connection::BaseLeaf { base, leaf } if leaf == id => Some(base.as_str()),
            _ => None,
        })
    }

    /// The structure as a petgraph graph: nodes are feature ids, edges
    /// `true` for base → leaf and `false` for a crossing (both directions).
    pub fn graph(&self) -> DiGraph<String, bool> {
        let mut g = DiGraph::new();
        let mut node = BTreeMap::new();
        let mut id = |g: &mut DiGraph<String, bool>, s: &str| {
            *node
                .entry(s.to_string())
                .or_insert_with(|| g.add_node(s.to_string()))
        };
        for c in &self.connections {
            match c {
                Connection::BaseLeaf { base, leaf } => {
                    let (a, b) = (id(&mut g, base), id(&mut g, leaf));
                    g.add_edge(a, b, true);
                }
                Connection::Crossing { features } => {
                    let (a, b) = (id(&mut g, &features[0]), id(&mut g, &features[1]));
                    g.add_edge(a, b, false);
                    g.add_edge(b, a, false);
                }
            }
        }
        g
    }

    /// Check the structure: base-leaf links form a forest (no cycle, no
    /// feature its own base, at most one base each), crossings are between
    /// distinct features and not also base-leaf.
    pub fn validate(&self) -> Result<(), String> {
        let mut bases: BTreeMap<&str, &str> = BTreeMap::new();
        let mut tree = DiGraph::<&str, ()>::new();
        let mut node = BTreeMap::new();
        for c in &self.connections {
            match c {
                Connection::BaseLeaf { base, leaf } => {
                    if base == leaf {
                        return Err(format!("{leaf} is its own base"));
                    }
                    if let Some(prev) = bases.insert(leaf, base) {
                        return Err(format!("{leaf} has two bases: {prev} and {base}"));
                    }
                    let a = *node
                        .entry(base.as_str())
                        .or_insert_with(|| tree.add_node(base.as_str()));
                    let b = *node
                        .entry(leaf.as_str())
                        .or_insert_with(|| tree.add_node(leaf.as_str()));
                    tree.add_edge(a, b, ());
                }
                Connection::Crossing { features } => {
                    if features[0] == features[1] {
                        return Err(format!("{} crosses itself", features[0]));
                    }
                    if features[0] > features[1] {
                        return Err(format!("crossing {features:?} not in canonical order"));
                    }
                }
            }
        }
        if is_cyclic_directed(&tree) {
            return Err("base-leaf links form a cycle".into());
        }
        for c in &self.connections {
            if let Connection::Crossing { features: [a, b] } = c {
                if bases.get(a.as_str()) == Some(&b.as_str())
                    || bases.get(b.as_str()) == Some(&a.as_str())
                {
                    return Err(format!("{a} and {b} are both crossing and base-leaf"));
                }
            }
        }
        Ok(())
    }
}

fn height(f: &StiffnessFeature, up: &thinwall_geom::Vector3) -> f64 {
    f.mid_plane.as_ref().map_or(0.0, |m| {
        m.point[0] * up.x + m.point[1] * up.y + m.point[2] * up.z
    })
}

/// Build the connection structure of a recognition in a set-up.
pub fn connect(r: &Recognition, setup: &Setup, options: &Options) -> Structure {
    let up = setup.up_in_part();
    let feats = &r.features;
    let in_structure = |i: usize| {
        feats[i].kind.is_wall() && (options.connect_thick_walls || feats[i].thin == Some(true))
    };
    let mut base: BTreeMap<usize, usize> = BTreeMap::new();
    let mut notes = Vec::new();
    for (&leaf, &b) in &r.bases {
        if in_structure(leaf) && in_structure(b) {
            base.insert(leaf, b);
        }
    }
    // Break cycles (two walls each standing on the other along equally long
    // feet): keep the lower wall as the base.
    loop {
        let mut cycle = None;
        for &start in base.keys() {
            let mut seen = BTreeSet::new();
            let mut at = start;
            while let Some(&b) = base.get(&at) {
                if !seen.insert(at) {
                    cycle = Some(at);
                    break;
                }
                at = b;
            }
            if cycle.is_some() {
                break;
            }
        }
        let Some(on_cycle) = cycle else { break };
        let mut members = vec![on_cycle];
        let mut at = base[&on_cycle];
        while at != on_cycle {
            members.push(at);
            at = base[&at];
        }
        // Drop the link whose base is highest.
        let drop = members
            .iter()
            .copied()
            .max_by(|&a, &b| {
                height(&feats[base[&a]], &up).total_cmp(&height(&feats[base[&b]], &up))
            })
            .expect("cycle");
        notes.push(format!(
            "{} and {} stood on each other; {} kept as the base (lower in the set-up)",
            feats[drop].id, feats[base[&drop]].id, feats[drop].id
        ));
        base.remove(&drop);
    }
    let ancestors = |mut w: usize, base: &BTreeMap<usize, usize>| {
        let mut v = vec![w];
        while let Some(&b) = base.get(&w) {
            if v.contains(&b) {
                break;
            }
            v.push(b);
            w = b;
        }
        v
    };
    // Junctions not used as a base: crossing when the walls share a base,
    // else (procedure 2) base-leaf with the lower wall as base.
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
        let (anc_a, anc_b) = (ancestors(a, &base), ancestors(b, &base));
        let common = anc_a
            .iter()
            .any(|x| anc_b.contains(x) && *x != a && *x != b);
        if common || anc_a.contains(&b) || anc_b.contains(&a) {
            crossings.insert((a.min(b), a.max(b)));
            continue;
        }
        let (lower, upper) = if height(&feats[a], &up) <= height(&feats[b], &up) {
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
    let mut connections: Vec<Connection> = Vec::new();
    for (&leaf, &b) in &base {
        connections.push(Connection::BaseLeaf {
            base: feats[b].id.clone(),
            leaf: feats[leaf].id.clone(),
        });
    }
    // Depressions and details are leaves of the wall they are in or on.
    for f in feats.iter().filter(|f| !f.kind.is_wall()) {
        if let Some(w) = &f.wall {
            connections.push(Connection::BaseLeaf {
                base: w.clone(),
                leaf: f.id.clone(),
            });
        }
    }
    for (a, b) in crossings {
        let (x, y) = (feats[a].id.clone(), feats[b].id.clone());
        let features = if x <= y { [x, y] } else { [y, x] };
        connections.push(Connection::Crossing { features });
    }
    let access = feats
        .iter()
        .filter(|f| f.kind.is_wall())
        .filter_map(|f| {
            let d = f.access_directions.as_ref()?;
            Some((
                f.id.clone(),
                [
                    side_access(d[0], &up, &setup.machine),
                    side_access(d[1], &up, &setup.machine),
                ],
            ))
        })
        .collect();
    Structure {
        connections,
        access,
        notes,
    }
}
