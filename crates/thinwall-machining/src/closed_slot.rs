//! Through slots whose open side was closed lower down: a slot cut at an
//! edge of a face goes through the part, and where material lies beyond
//! that edge further down, the cut leaves a wall there too. By its faces
//! it is a ring of walls, a passage; what tells it apart is that one wall,
//! the one under the entry edge, never meets the face the slot was entered
//! from, while every other wall does.

use crate::{face_plane, same_plane, Plane};
use std::collections::{BTreeMap, BTreeSet};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::Vector3;

/// A ring of walls through the part, square to one axis.
struct Ring<'r> {
    a: &'r PartAnalysis<'r>,
    group: &'r [FaceId],
    planes: &'r [Plane],
    walls: &'r [FaceId],
    /// Indices into `planes` of the walls' planes.
    wall_planes: BTreeSet<usize>,
    axis: Vector3,
    /// Within this of a plane is on it, mm.
    tol: f64,
}

impl<'r> Ring<'r> {
    /// The ring of `walls` (faces of `group` on `planes`), when they are
    /// three planes or more all square to one axis.
    fn new(
        a: &'r PartAnalysis<'r>,
        group: &'r [FaceId],
        planes: &'r [Plane],
        walls: &'r [FaceId],
    ) -> Option<Self> {
        let mut ring = Ring {
            a,
            group,
            planes,
            walls,
            wall_planes: BTreeSet::new(),
            axis: Vector3::zeros(),
            tol: crate::plane_tol(a),
        };
        ring.wall_planes = walls.iter().filter_map(|&f| ring.plane_of(f)).collect();
        let normals: Vec<Vector3> = ring.wall_planes.iter().map(|&p| planes[p].0).collect();
        ring.axis = normals
            .iter()
            .flat_map(|n| normals.iter().map(move |m| n.cross(m)))
            .max_by(|x, y| x.norm().total_cmp(&y.norm()))?
            .try_normalize(NEAR_PARALLEL_EPS)?;
        let square = normals
            .iter()
            .all(|n| n.dot(&ring.axis).abs() < NEAR_PARALLEL_EPS);
        (normals.len() >= 3 && square).then_some(ring)
    }

    /// Which of the group's planes face `f` lies on.
    fn plane_of(&self, f: FaceId) -> Option<usize> {
        let q = face_plane(self.a, f)?;
        self.planes.iter().position(|p| same_plane(self.a, p, &q))
    }

    /// The faces outside the group that `f` meets.
    fn beyond(&self, f: FaceId) -> impl Iterator<Item = FaceId> + '_ {
        self.a
            .graph()
            .neighbours(f)
            .map(|(g, _)| g)
            .filter(|g| !self.group.contains(g))
    }

    /// A face square to the axis: where the ring is entered or left.
    fn end_face(&self, g: FaceId) -> bool {
        self.a
            .props(g)
            .normal
            .is_some_and(|n| n.dot(&self.axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
    }

    /// Which wall planes meet each end face.
    fn end_meets(&self) -> BTreeMap<FaceId, BTreeSet<usize>> {
        let mut meets: BTreeMap<FaceId, BTreeSet<usize>> = BTreeMap::new();
        for &w in self.walls {
            let Some(p) = self.plane_of(w) else { continue };
            for g in self.beyond(w).filter(|&g| self.end_face(g)) {
                meets.entry(g).or_default().insert(p);
            }
        }
        meets
    }

    /// The wall under the entry edge, for an end face `entry` that every
    /// wall plane but one (`met`) meets: that one meets material beyond
    /// the edge (any face but the exit, which every wall meets, a blend or
    /// a bevel: a passage's rim chamfered on one edge stays a passage), and
    /// `entry` has an edge in its plane (the slot's open side was sketched
    /// on it; a passage whose exit another cut split has none there).
    fn odd_wall(
        &self,
        entry: FaceId,
        met: &BTreeSet<usize>,
        meets: &BTreeMap<FaceId, BTreeSet<usize>>,
    ) -> Option<usize> {
        let odd = *self.wall_planes.difference(met).next()?;
        let all = self.wall_planes.len();
        let entry_normal = self.a.props(entry).normal;
        // Every wall meets the exit, and the floor of another cut that
        // split the ring (facing the way the entry does) too.
        let split_floor = |g: FaceId| {
            matches!((self.a.props(g).normal, entry_normal),
                (Some(n), Some(m)) if crate::same_direction(&n, &m))
        };
        let material = |g: FaceId| {
            (meets.get(&g).is_none_or(|ps| ps.len() < all) || split_floor(g))
                && !crate::is_blend(self.a, g)
                && !crate::chamfer::is_chamfer(self.a, g)
        };
        let closed = self
            .walls
            .iter()
            .filter(|&&w| self.plane_of(w) == Some(odd))
            .flat_map(|&w| self.beyond(w))
            .any(material);
        (closed && self.edge_in_plane(entry, self.planes[odd])).then_some(odd)
    }

    /// Whether face `f` has an edge, with a face outside the group, lying
    /// in `plane`.
    fn edge_in_plane(&self, f: FaceId, (n, off): Plane) -> bool {
        let part = self.a.part();
        let on = |v| (n.dot(&part.vertex(v).point.coords) - off).abs() < self.tol;
        self.a.graph().neighbours(f).any(|(h, adj)| {
            !self.group.contains(&h)
                && adj.edges.iter().any(|&e| {
                    let edge = part.edge(self.a.graph().edges[e].edge);
                    on(edge.start) && on(edge.end)
                })
        })
    }
}

/// For a ring of `walls` (faces of `group` on `planes`) that is a slot
/// whose open side was closed lower down (module docs), the normals of
/// its other walls; none for a passage.
pub(crate) fn slot_walls(
    a: &PartAnalysis,
    group: &[FaceId],
    planes: &[Plane],
    walls: &[FaceId],
) -> Option<Vec<Vector3>> {
    let ring = Ring::new(a, group, planes, walls)?;
    let meets = ring.end_meets();
    let all = ring.wall_planes.len();
    let odd = meets
        .iter()
        .filter(|(_, met)| met.len() == all - 1)
        .find_map(|(&entry, met)| ring.odd_wall(entry, met, &meets))?;
    Some(
        ring.wall_planes
            .iter()
            .filter(|&&p| p != odd)
            .map(|&p| planes[p].0)
            .collect(),
    )
}
