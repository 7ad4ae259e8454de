//! The attributed adjacency graph: a node per face, an arc per pair of
//! faces sharing edges, each shared edge with its convexity and dihedral
//! angle sampled along it.
//!
//! Convexity at a point of an edge between faces F1 and F2, with outward
//! normals n1 and n2 and the edge tangent t oriented as F1's loop runs it
//! (F1 on its left seen from n1): the edge is convex where
//! `(n1 × n2)·t > 0`, concave where it is negative, and smooth (tangent)
//! where the normals differ by less than the tangent angle. An edge whose
//! samples are both convex and concave is `mixed`.

use petgraph::graph::{NodeIndex, UnGraph};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use thinwall_brep::{EdgeId, FaceId, Part};
use thinwall_geom::{Surface, Tolerances};

/// How two faces meet along an edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, PartialOrd, Ord)]
#[serde(rename_all = "snake_case")]
pub enum Convexity {
    Convex,
    Concave,
    /// Tangent (G1) across the edge.
    Smooth,
    /// Convex somewhere and concave elsewhere along the edge.
    Mixed,
    /// Used twice by one face (a seam): no neighbour.
    Seam,
    /// Used by one face only: the shell is open there.
    Free,
    /// Used by three or more faces: the solid is not a manifold there.
    NonManifold,
    /// Between two faces, but no surface normal could be evaluated along it.
    Unknown,
}

impl Convexity {
    pub fn name(self) -> &'static str {
        match self {
            Convexity::Convex => "convex",
            Convexity::Concave => "concave",
            Convexity::Smooth => "smooth",
            Convexity::Mixed => "mixed",
            Convexity::Seam => "seam",
            Convexity::Free => "free",
            Convexity::NonManifold => "non_manifold",
            Convexity::Unknown => "unknown",
        }
    }
}

/// One edge of the part with its faces and how they meet.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EdgeAttr {
    pub edge: EdgeId,
    pub step_id: u64,
    /// The faces using the edge (two for a manifold edge; a seam lists its
    /// face twice).
    pub faces: Vec<FaceId>,
    pub convexity: Convexity,
    /// Interior (material-side) dihedral angle, degrees: < 180 convex,
    /// > 180 concave, 180 smooth. Min and max over the samples.
    pub angle_min_deg: f64,
    pub angle_max_deg: f64,
}

/// What an arc of the graph carries: the edges two faces share.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Adjacency {
    /// Indices into [`AdjacencyGraph::edges`].
    pub edges: Vec<usize>,
    /// Convexity of all shared edges together (`mixed` when they differ).
    pub convexity: Convexity,
}

/// The face adjacency graph of a part.
#[derive(Clone, Debug)]
pub struct AdjacencyGraph {
    pub graph: UnGraph<FaceId, Adjacency>,
    /// `nodes[face.index()]` is the node of that face.
    pub nodes: Vec<NodeIndex>,
    /// Every edge of the part, in part order.
    pub edges: Vec<EdgeAttr>,
}

/// Samples taken along a curved edge (a straight edge between planes needs one).
const SAMPLES: usize = 5;

impl AdjacencyGraph {
    /// Build the graph of `part` with tolerances `tol`.
    pub fn build(part: &Part, tol: &Tolerances) -> Self {
        // Which faces use each edge, with the direction their loop runs it.
        let mut uses: Vec<Vec<(FaceId, bool)>> = vec![Vec::new(); part.edges.len()];
        for l in &part.loops {
            for ce in &l.coedges {
                uses[ce.edge.index()].push((l.face, ce.forward));
            }
        }
        let mut graph = UnGraph::with_capacity(part.faces.len(), part.edges.len());
        let nodes: Vec<NodeIndex> = part.face_ids().map(|f| graph.add_node(f)).collect();
        let mut edges = Vec::with_capacity(part.edges.len());
        let mut arcs: HashMap<(FaceId, FaceId), Vec<usize>> = HashMap::new();
        for (i, u) in uses.iter().enumerate() {
            let edge = EdgeId(i as u32);
            let attr = classify(part, edge, u, tol);
            if u.len() >= 2 && u[0].0 != u[1].0 {
                let key = if u[0].0 < u[1].0 {
                    (u[0].0, u[1].0)
                } else {
                    (u[1].0, u[0].0)
                };
                arcs.entry(key).or_default().push(i);
            }
            edges.push(attr);
        }
        let mut keys: Vec<_> = arcs.keys().copied().collect();
        keys.sort();
        for key in keys {
            let list = arcs.remove(&key).unwrap_or_default();
            let mut convexity = edges[list[0]].convexity;
            if list.iter().any(|&e| edges[e].convexity != convexity) {
                convexity = Convexity::Mixed;
            }
            graph.add_edge(
                nodes[key.0.index()],
                nodes[key.1.index()],
                Adjacency {
                    edges: list,
                    convexity,
                },
            );
        }
        Self {
            graph,
            nodes,
            edges,
        }
    }

    /// Faces adjacent to `face`, with what they share.
    pub fn neighbours(&self, face: FaceId) -> impl Iterator<Item = (FaceId, &Adjacency)> + '_ {
        self.graph.edges(self.nodes[face.index()]).map(move |e| {
            let (a, b) = (e.source(), e.target());
            let other = if a == self.nodes[face.index()] { b } else { a };
            (self.graph[other], e.weight())
        })
    }

    /// Count of edges by convexity.
    pub fn convexity_counts(&self) -> std::collections::BTreeMap<Convexity, usize> {
        let mut m = std::collections::BTreeMap::new();
        for e in &self.edges {
            *m.entry(e.convexity).or_insert(0) += 1;
        }
        m
    }
}

use petgraph::visit::EdgeRef;

fn classify(part: &Part, edge: EdgeId, uses: &[(FaceId, bool)], tol: &Tolerances) -> EdgeAttr {
    let e = part.edge(edge);
    let mut attr = EdgeAttr {
        edge,
        step_id: e.step_id,
        faces: uses.iter().map(|u| u.0).collect(),
        convexity: Convexity::Seam,
        angle_min_deg: 180.0,
        angle_max_deg: 180.0,
    };
    match uses.len() {
        0 | 1 => {
            attr.convexity = Convexity::Free;
            return attr;
        }
        2 if uses[0].0 == uses[1].0 => return attr,
        2 => {}
        _ => {
            attr.convexity = Convexity::NonManifold;
            return attr;
        }
    }
    let Some(curve) = &e.nurbs else {
        attr.convexity = Convexity::Unknown;
        return attr;
    };
    let ((f1, fwd1), (f2, _)) = (uses[0], uses[1]);
    let both_planes = matches!(part.face(f1).surface, Surface::Plane { .. })
        && matches!(part.face(f2).surface, Surface::Plane { .. });
    let n_samples = if both_planes && e.curve.is_line() {
        1
    } else {
        SAMPLES
    };
    let (a, b) = curve.domain();
    let (mut convex, mut concave, mut smooth, mut fold) = (0, 0, 0, 0);
    let (mut amin, mut amax) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut hint1, mut hint2) = (None, None);
    for k in 0..n_samples {
        let t = a + (b - a) * (k as f64 + 0.5) / n_samples as f64;
        let (p, d) = curve.eval(t);
        let (Some(n1), Some(n2)) = (
            part.face(f1).outward_normal(&p, &mut hint1),
            part.face(f2).outward_normal(&p, &mut hint2),
        ) else {
            continue;
        };
        let Some(t1) = (if fwd1 { d } else { -d }).try_normalize(1e-300) else {
            continue;
        };
        let cross = n1.cross(&n2);
        let phi = cross.norm().atan2(n1.dot(&n2));
        // Faces folding back onto each other (a knife edge, normals
        // opposite): which side is material cannot be told, so the edge
        // is neither convex nor concave.
        fold += usize::from(std::f64::consts::PI - phi < tol.tangent_angle);
        let interior = if phi < tol.tangent_angle {
            smooth += 1;
            std::f64::consts::PI
        } else if cross.dot(&t1) > 0.0 {
            convex += 1;
            std::f64::consts::PI - phi
        } else {
            concave += 1;
            std::f64::consts::PI + phi
        };
        amin = amin.min(interior);
        amax = amax.max(interior);
    }
    attr.convexity = match (convex > 0, concave > 0, smooth > 0) {
        _ if fold > 0 => Convexity::Mixed,
        (true, true, _) => Convexity::Mixed,
        (true, false, _) => Convexity::Convex,
        (false, true, _) => Convexity::Concave,
        (false, false, true) => Convexity::Smooth,
        (false, false, false) => Convexity::Unknown,
    };
    if amin.is_finite() {
        attr.angle_min_deg = amin.to_degrees();
        attr.angle_max_deg = amax.to_degrees();
    }
    attr
}
