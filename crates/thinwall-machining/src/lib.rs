//! Conventional machining features on a part (DOMAIN.md §6: Alpha_1's
//! holes, pockets, slots; Matsuda's milled regions; the MFCAD taxonomy):
//! holes (through, blind, counterbored, countersunk), pockets, slots,
//! steps, passages, chamfers, fillets and rounds.
//!
//! The part is taken as cut from its bounding block: a face lying on one of
//! the block's six planes is **stock**. The other faces are grouped into
//! features: curved faces tangent to two or more faces are blends (fillets
//! and rounds, chained along tangent edges); the rest are joined across
//! concave edges (the inside corners of a depression), and the two halves
//! of a hole's cylinder across their tangent seam. Each group is typed from
//! which stock planes it opens to and its faces' directions:
//!
//! - a floor facing the only stock plane it opens to: **pocket**;
//! - opening to one stock plane without a floor, or to two opposite ones:
//!   **passage** (through);
//! - opening to two opposite planes and one more: **slot** (through);
//!   to two opposite planes and two more: **step** (through);
//! - to three planes, none opposite: blind **step**; to two: blind **slot**;
//! - one inclined face meeting three or more stock planes: **chamfer**;
//! - concave cylinders: **hole**, through when nothing closes its bottom.
//!
//! Profiles: the number of wall directions (3 triangular, 4 rectangular,
//! 6 hexagonal); a through slot of two faces is triangular (a V); a through
//! step of three faces two-sided, of two faces rectangular when its faces
//! are parallel to the block's, else slanted; a blind step of two faces
//! triangular.

mod stock;

pub use stock::Stock;

use geo::{Area, MultiPolygon};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use thinwall_analysis::polygon::{inscribed_radius, min_rect_sides};
use thinwall_analysis::{Cylinder, FeatureId, MachiningId, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::{NEAR_PARALLEL_EPS, UNIT_PARALLEL_EPS};
use thinwall_geom::{Surface, Vector3};
use thinwall_graph::Convexity;

/// A machining feature on the part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MachiningFeature {
    /// `M1`, `M2`, … by smallest face id.
    pub id: MachiningId,
    pub kind: MachiningKind,
    /// The body its faces are on (index into the report's `bodies`).
    pub body: u32,
    /// Opens through the part (no bottom).
    pub through: bool,
    pub profile: Profile,
    /// Unit tool (access) direction, into the part.
    pub direction: [f64; 3],
    /// `step_id`s of all faces it creates, floors included.
    pub faces: Vec<u64>,
    /// Faces facing the access direction (floors).
    pub bottom_faces: Vec<u64>,
    /// The other faces (walls).
    pub side_faces: Vec<u64>,
    /// Which block planes it opens to, as outward normals.
    pub open_to: Vec<[f64; 3]>,
    /// mm along the direction.
    pub depth: f64,
    /// Profile length and width (minimum rectangle), or hole diameter, mm.
    pub length: f64,
    pub width: f64,
    /// Radii of cylindrical faces (holes, corners, blends), mm.
    pub radii: Vec<f64>,
    /// Largest tool diameter that fits the floor (or the cross-section of a
    /// passage or hole), mm; absent when there is no floor to measure.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub largest_tool_diameter: Option<f64>,
    /// The stiffness features sharing a face with it (filled by the
    /// pipeline, which runs both recognizers).
    #[serde(default)]
    pub related: Vec<FeatureId>,
}

/// Whether two unit normals point the same way.
fn same_direction(a: &Vector3, b: &Vector3) -> bool {
    a.dot(b) > 1.0 - UNIT_PARALLEL_EPS
}

/// Recognize the machining features of the analysed part.
pub fn recognize(a: &PartAnalysis) -> Vec<MachiningFeature> {
    let part = a.part();
    let tol = a.tol().feature;
    let block = Stock::of(a);
    let stock: Vec<Option<usize>> = part.face_ids().map(|f| block.plane_of(a, f)).collect();
    let is_stock = |f: FaceId| stock[f.index()].is_some();
    let mut out: Vec<MachiningFeature> = Vec::new();
    // Blends: chains of tangent curved faces.
    let blends: Vec<FaceId> = part
        .face_ids()
        .filter(|&f| !is_stock(f) && is_blend(a, f))
        .collect();
    for group in a.components(&blends, |_, _, adj| adj.convexity == Convexity::Smooth) {
        out.push(blend_feature(a, &block, &group));
    }
    let blend_set: BTreeSet<FaceId> = blends.iter().copied().collect();
    // Depressions: concave-connected groups (hole halves across their seam).
    let rest: Vec<FaceId> = part
        .face_ids()
        .filter(|f| !is_stock(*f) && !blend_set.contains(f))
        .collect();
    let joined = |f: FaceId, g: FaceId, adj: &thinwall_graph::Adjacency| {
        adj.convexity == Convexity::Concave
            || (adj.convexity == Convexity::Smooth
                && matches!((a.concave_cylinder(f), a.concave_cylinder(g)),
                    (Some(x), Some(y)) if x.coaxial(&y, tol * 100.0)))
    };
    for group in a.components(&rest, joined) {
        let touched: BTreeSet<usize> = group
            .iter()
            .flat_map(|&f| a.graph().neighbours(f))
            .filter_map(|(h, _)| stock[h.index()])
            .collect();
        out.push(depression_feature(a, &block, &group, &touched));
    }
    // A feature has a depth and a profile, or it is not a feature (a lone
    // side face seen edge-on, a whole-part face of a casting).
    let least = a.tol().coplanar;
    out.retain(|m| {
        m.length > least && m.width > least && (m.depth > least || m.kind == MachiningKind::Chamfer)
    });
    out.sort_by_key(|m| m.faces.first().copied().unwrap_or(0));
    for (i, m) in out.iter_mut().enumerate() {
        m.id = MachiningId(i as u32 + 1);
    }
    out
}

/// A curved face tangent to two or more faces, but not a hole's cylinder
/// whose tangent neighbours are all hole cylinders (its other half).
fn is_blend(a: &PartAnalysis, f: FaceId) -> bool {
    if a.concave_cylinder(f).is_some()
        && a.graph()
            .neighbours(f)
            .all(|(g, adj)| adj.convexity != Convexity::Smooth || a.concave_cylinder(g).is_some())
    {
        return false;
    }
    let curved = !matches!(a.part().face(f).surface, Surface::Plane { .. });
    curved && a.smooth_degree(f) >= 2
}

/// Radii closer than this are one radius, mm.
const SAME_RADIUS_MM: f64 = 1e-9;

fn radii(a: &PartAnalysis, fs: &[FaceId]) -> Vec<f64> {
    let mut r: Vec<f64> = fs.iter().filter_map(|&f| a.blend_radius(f)).collect();
    r.sort_by(f64::total_cmp);
    r.dedup_by(|a, b| (*a - *b).abs() < SAME_RADIUS_MM);
    r
}

/// A blend chain: its radius (smallest) as depth, its length and width as
/// sizes.
fn blend_feature(a: &PartAnalysis, stock: &Stock, group: &[FaceId]) -> MachiningFeature {
    let convex = a.part().face(group[0]).same_sense;
    let dir = a.props(group[0]).axis.map_or(Vector3::z(), |ax| ax.1);
    let radii_v = radii(a, group);
    let along = |d: &Vector3| {
        let (lo, hi) = a.extent(group, d);
        if hi.is_finite() {
            hi - lo
        } else {
            0.0
        }
    };
    // Its length: the longest extent of the chain (along the stock's axes
    // and its own axis); its width: the developed arc, area over length,
    // never more than the length.
    let [x, y, z] = stock.axes;
    let length = [x, y, z, dir].iter().map(along).fold(0.0, f64::max);
    let area: f64 = group.iter().map(|&f| a.props(f).area).sum();
    let arc = if length > 0.0 { area / length } else { 0.0 };
    MachiningFeature {
        id: MachiningId::default(),
        kind: MachiningKind::Fillet,
        body: a.part().face(group[0]).body.0,
        through: false,
        profile: if convex {
            Profile::Round
        } else {
            Profile::Fillet
        },
        direction: [dir.x, dir.y, dir.z],
        faces: a.step_ids(group),
        bottom_faces: vec![],
        side_faces: a.step_ids(group),
        open_to: vec![],
        depth: radii_v.first().copied().unwrap_or(0.0),
        length,
        width: arc.min(length),
        radii: radii_v,
        largest_tool_diameter: None,
        related: vec![],
    }
}

/// Walls of `group` adjacent to wall `w` (sharing an edge).
fn wall_neighbours(a: &PartAnalysis, w: FaceId, walls: &[FaceId]) -> usize {
    a.graph()
        .neighbours(w)
        .filter(|(x, _)| *x != w && walls.contains(x))
        .map(|(x, _)| x)
        .collect::<BTreeSet<FaceId>>()
        .len()
}

/// What typing a depression group needs: the stock planes it opens to,
/// its distinct planes, its concave cylinders.
struct GroupShape<'g> {
    stock: &'g Stock,
    group: &'g [FaceId],
    touched: &'g BTreeSet<usize>,
    /// Axes with both block planes touched.
    opposite: Vec<usize>,
    /// Distinct planes among the planar faces: normal and offset.
    planes: Vec<(Vector3, f64)>,
    cylinders: Vec<Cylinder>,
    /// The stock plane it is entered from.
    entry: Option<usize>,
}

impl<'g> GroupShape<'g> {
    fn new(
        a: &PartAnalysis,
        stock: &'g Stock,
        group: &'g [FaceId],
        touched: &'g BTreeSet<usize>,
    ) -> Self {
        let tol = a.tol().feature;
        let opposite: Vec<usize> = (0..3)
            .filter(|k| touched.contains(&(2 * k)) && touched.contains(&(2 * k + 1)))
            .collect();
        let mut planes: Vec<(Vector3, f64)> = Vec::new();
        for &f in group {
            if let Some(n) = a.props(f).normal {
                let off = n.dot(&a.props(f).centroid.coords);
                if !planes
                    .iter()
                    .any(|(m, o)| same_direction(m, &n) && (o - off).abs() < tol * 10.0)
                {
                    planes.push((n, off));
                }
            }
        }
        let cylinders = group
            .iter()
            .filter_map(|&f| a.concave_cylinder(f))
            .collect();
        // The entry: a touched plane not in an opposite pair, facing the
        // same way as a floor if there is one.
        let candidates: Vec<usize> = touched
            .iter()
            .copied()
            .filter(|sp| !opposite.contains(&(sp / 2)))
            .collect();
        let entry = candidates
            .iter()
            .copied()
            .find(|&sp| {
                planes
                    .iter()
                    .any(|(n, _)| same_direction(n, &stock.normal(sp)))
            })
            .or_else(|| candidates.first().copied())
            .or_else(|| touched.iter().next().copied());
        Self {
            stock,
            group,
            touched,
            opposite,
            planes,
            cylinders,
            entry,
        }
    }

    /// A floor facing the only stock plane it opens to.
    fn floor_up(&self) -> Option<Vector3> {
        if self.touched.len() == 1 {
            self.entry.map(|sp| self.stock.normal(sp))
        } else {
            None
        }
    }

    /// Walls closing a ring around the floor: each wall meets two others.
    fn ring(&self, a: &PartAnalysis) -> bool {
        let floor_up = self.floor_up();
        let walls: Vec<FaceId> = self
            .group
            .iter()
            .copied()
            .filter(|&f| {
                !floor_up.is_some_and(|u| a.props(f).normal.is_some_and(|n| same_direction(&n, &u)))
            })
            .collect();
        !walls.is_empty() && walls.iter().all(|&w| wall_neighbours(a, w, &walls) >= 2)
    }

    /// Kind, through and profile.
    fn typing(&self, a: &PartAnalysis) -> (MachiningKind, bool, Profile) {
        use MachiningKind::*;
        if !self.cylinders.is_empty() {
            return hole_typing(a, self.group, &self.cylinders);
        }
        let (t, d) = (self.touched.len(), self.planes.len());
        let opposite = !self.opposite.is_empty();
        let has_floor = self
            .floor_up()
            .is_some_and(|u| self.planes.iter().any(|(n, _)| same_direction(n, &u)));
        let tri_or_rect = |two: bool| {
            if two {
                Profile::Triangular
            } else {
                Profile::Rectangular
            }
        };
        if d == 1 && t >= 3 {
            (Chamfer, false, Profile::Slanted)
        } else if has_floor && self.ring(a) {
            (Pocket, false, Profile::of_sides(d - 1))
        } else if has_floor {
            // A floor whose walls do not close: it opens sideways into another feature.
            (Step, false, tri_or_rect(d <= 2))
        } else if t == 1 || (t == 2 && self.opposite.len() == 1) {
            (Passage, true, Profile::of_sides(d))
        } else if opposite && t == 3 {
            (Slot, true, tri_or_rect(d == 2))
        } else if opposite && t == 4 {
            let aligned = self.planes.iter().all(|(n, _)| self.stock.aligned(n));
            let profile = if d == 3 {
                Profile::TwoSided
            } else if aligned {
                Profile::Rectangular
            } else {
                Profile::Slanted
            };
            (Step, true, profile)
        } else if !opposite && t == 3 {
            (Step, false, tri_or_rect(d == 2))
        } else if !opposite && t == 2 && d == 4 {
            (Slot, false, Profile::Rectangular)
        } else if !opposite && t == 2 {
            (Step, false, tri_or_rect(d <= 2))
        } else {
            // Opens to no block plane, or in a way none of the above describes.
            (Pocket, false, Profile::Free)
        }
    }

    /// Into the part from the entry plane (holes: along the axis).
    fn direction(&self) -> Vector3 {
        if let Some(c) = self.cylinders.first() {
            match self.entry {
                Some(sp) if self.stock.normal(sp).dot(&c.axis) > 0.0 => -c.axis,
                _ => c.axis,
            }
        } else {
            self.entry
                .map(|sp| -self.stock.normal(sp))
                .unwrap_or(-Vector3::z())
        }
    }
}

/// Holes: concave cylinders. Blind when a face closes the far end: a plane
/// across the axis, or a drill point (cone, sphere) there.
fn hole_typing(
    a: &PartAnalysis,
    group: &[FaceId],
    cylinders: &[Cylinder],
) -> (MachiningKind, bool, Profile) {
    let part = a.part();
    let tol = a.tol().feature;
    let axis = cylinders[0].axis;
    let (lo, hi) = a.extent(group, &axis);
    let at_end = |f: FaceId| {
        let (x, y) = a.extent(&[f], &axis);
        (x - lo).abs() < tol * 100.0 || (y - hi).abs() < tol * 100.0
    };
    let closes = |f: FaceId| {
        let face = part.face(f);
        match face.surface {
            Surface::Plane { .. } => {
                a.props(f)
                    .normal
                    .is_some_and(|n| n.dot(&axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
                    && at_end(f)
                    && face.loops.len() == 1
            }
            // A drill point: at the far end, coming to a tip (a vertex
            // loop) or a single boundary.
            Surface::Cone { .. } | Surface::Sphere { .. } => {
                at_end(f)
                    && (face.loops.len() == 1
                        || face.loops.iter().any(|&l| part.loop_(l).vertex.is_some()))
            }
            _ => false,
        }
    };
    let bottom = group.iter().any(|&f| closes(f));
    let distinct_r = radii(a, group).len();
    let cone = group
        .iter()
        .any(|&f| matches!(part.face(f).surface, Surface::Cone { .. }));
    let profile = if cone && distinct_r >= 1 {
        Profile::Countersunk
    } else if distinct_r == 2 {
        Profile::Counterbored
    } else if distinct_r > 2 {
        Profile::MultiSegment
    } else {
        Profile::Circular
    };
    (MachiningKind::Hole, !bottom, profile)
}

/// The largest tool that fits: a hole's diameter, or twice the inscribed
/// radius of the floor.
fn largest_tool(
    a: &PartAnalysis,
    kind: MachiningKind,
    radii: &[f64],
    bottom: &[FaceId],
) -> Option<f64> {
    if kind == MachiningKind::Hole {
        return radii.first().map(|r| 2.0 * r);
    }
    if bottom.is_empty() {
        return None;
    }
    let floors: MultiPolygon<f64> = MultiPolygon::new(
        bottom
            .iter()
            .filter_map(|&f| a.polygon(f))
            .flat_map(|p| p.0)
            .collect(),
    );
    (floors.unsigned_area() > 0.0).then(|| 2.0 * inscribed_radius(&floors))
}

fn depression_feature(
    a: &PartAnalysis,
    stock: &Stock,
    group: &[FaceId],
    touched: &BTreeSet<usize>,
) -> MachiningFeature {
    let shape = GroupShape::new(a, stock, group, touched);
    let (kind, through, profile) = shape.typing(a);
    let dir = shape.direction();
    let (bottom, sides): (Vec<FaceId>, Vec<FaceId>) = group.iter().partition(|&&f| {
        a.props(f)
            .normal
            .is_some_and(|n| n.dot(&-dir) > 1.0 - NEAR_PARALLEL_EPS)
    });
    let (lo, hi) = a.extent(group, &dir);
    let radii_v = radii(a, group);
    // A hole's profile is its widest concave cylinder: its true diameter,
    // not the extent of boundary samples.
    let hole_diameter = shape
        .cylinders
        .iter()
        .map(|c| 2.0 * c.radius)
        .fold(0.0, f64::max);
    let (length, width) = if kind == MachiningKind::Hole && hole_diameter > 0.0 {
        (hole_diameter, hole_diameter)
    } else if kind == MachiningKind::Chamfer {
        // A chamfer is one inclined face: its own long and short sides.
        a.polygon(group[0])
            .and_then(|p| min_rect_sides(&p))
            .unwrap_or_else(|| a.sizes_across(group, &dir))
    } else {
        a.sizes_across(group, &dir)
    };
    MachiningFeature {
        id: MachiningId::default(),
        kind,
        body: a.part().face(group[0]).body.0,
        through,
        profile,
        direction: [dir.x, dir.y, dir.z],
        faces: a.step_ids(group),
        bottom_faces: a.step_ids(&bottom),
        side_faces: a.step_ids(&sides),
        open_to: touched
            .iter()
            .map(|&sp| {
                let n = stock.normal(sp);
                [n.x, n.y, n.z]
            })
            .collect(),
        depth: if hi.is_finite() { hi - lo } else { 0.0 },
        length,
        width,
        largest_tool_diameter: largest_tool(a, kind, &radii_v, &bottom),
        radii: radii_v,
        related: vec![],
    }
}
