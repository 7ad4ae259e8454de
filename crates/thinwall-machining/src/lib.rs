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

use geo::{Area, MultiPolygon};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use thinwall_brep::{compute_face_props, FaceId, FaceProps, Part};
use thinwall_geom::{Point3, Surface, Vector3};
use thinwall_graph::{AdjacencyGraph, Convexity};

/// A machining feature on the part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MachiningFeature {
    /// `M1`, `M2`, … by smallest face id.
    pub id: String,
    /// hole, pocket, slot, step, passage, chamfer, fillet.
    pub kind: String,
    /// Opens through the part (no bottom).
    pub through: bool,
    /// rectangular, triangular, hexagonal, circular, slanted, two_sided,
    /// free; for holes also counterbored / countersunk / multi_segment.
    pub profile: String,
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
}

/// The six planes of the part's bounding block: index `2k` is the `min`
/// side of axis `k`, `2k + 1` the `max` side.
fn stock_plane(p: &FaceProps, bb: &thinwall_geom::BoundingBox, tol: f64) -> Option<usize> {
    let n = p.normal?;
    (0..3).find_map(|k| {
        if n[k] > 1.0 - 1e-9
            && (p.bbox.min[k] - bb.max[k]).abs() < tol
            && (p.bbox.max[k] - bb.max[k]).abs() < tol
        {
            Some(2 * k + 1)
        } else if n[k] < -1.0 + 1e-9
            && (p.bbox.max[k] - bb.min[k]).abs() < tol
            && (p.bbox.min[k] - bb.min[k]).abs() < tol
        {
            Some(2 * k)
        } else {
            None
        }
    })
}

fn plane_normal(sp: usize) -> Vector3 {
    let mut v = Vector3::zeros();
    v[sp / 2] = if sp % 2 == 1 { 1.0 } else { -1.0 };
    v
}

/// A concave cylinder (outward normal towards its axis): a hole wall.
fn hole_cylinder(part: &Part, f: FaceId) -> Option<(Point3, Vector3, f64)> {
    let face = part.face(f);
    match face.surface {
        Surface::Cylinder { frame, radius } if !face.same_sense => {
            Some((frame.origin, frame.z, radius))
        }
        _ => None,
    }
}

fn coaxial(a: (Point3, Vector3, f64), b: (Point3, Vector3, f64), tol: f64) -> bool {
    let d = b.0 - a.0;
    a.1.dot(&b.1).abs() > 1.0 - 1e-9 && (d - a.1 * d.dot(&a.1)).norm() < tol
}

/// Recognize the machining features of `part`.
pub fn recognize(part: &Part, graph: &AdjacencyGraph) -> Vec<MachiningFeature> {
    let props: Vec<FaceProps> = part
        .face_ids()
        .map(|f| compute_face_props(part, f))
        .collect();
    recognize_with_props(part, graph, &props)
}

/// [`recognize`] with every face's properties already computed
/// (`props[face.index()]`): they are the costly part on free-form faces.
pub fn recognize_with_props(
    part: &Part,
    graph: &AdjacencyGraph,
    props: &[FaceProps],
) -> Vec<MachiningFeature> {
    let bb = part.bounding_box();
    let diag = bb.diagonal().max(1.0);
    let tol = 1e-6 * diag;
    let stock: Vec<Option<usize>> = props.iter().map(|p| stock_plane(p, &bb, tol)).collect();
    let is_blend = |f: FaceId| {
        if hole_cylinder(part, f).is_some()
            && graph
                .neighbours(f)
                .all(|(g, a)| a.convexity != Convexity::Smooth || hole_cylinder(part, g).is_some())
        {
            return false;
        }
        let curved = !matches!(part.face(f).surface, Surface::Plane { .. });
        let smooth: BTreeSet<FaceId> = graph
            .neighbours(f)
            .filter(|(_, a)| a.convexity == Convexity::Smooth)
            .map(|(g, _)| g)
            .collect();
        curved && smooth.len() >= 2
    };
    let mut taken: BTreeSet<FaceId> = part
        .face_ids()
        .filter(|f| stock[f.index()].is_some())
        .collect();
    let mut out: Vec<MachiningFeature> = Vec::new();
    // Blends: chains of tangent curved faces.
    let blends: BTreeSet<FaceId> = part
        .face_ids()
        .filter(|&f| !taken.contains(&f) && is_blend(f))
        .collect();
    for group in components(&blends, |f| {
        graph
            .neighbours(f)
            .filter(|(g, a)| a.convexity == Convexity::Smooth && blends.contains(g))
            .map(|(g, _)| g)
            .collect()
    }) {
        taken.extend(group.iter().copied());
        out.push(blend_feature(part, props, &group));
    }
    // Depressions: concave-connected groups (hole halves across their seam).
    let rest: BTreeSet<FaceId> = part.face_ids().filter(|f| !taken.contains(f)).collect();
    for group in components(&rest, |f| {
        graph
            .neighbours(f)
            .filter(|(g, a)| {
                rest.contains(g)
                    && (a.convexity == Convexity::Concave
                        || (a.convexity == Convexity::Smooth
                            && matches!((hole_cylinder(part, f), hole_cylinder(part, *g)), (Some(x), Some(y)) if coaxial(x, y, tol * 100.0))))
            })
            .map(|(g, _)| g)
            .collect()
    }) {
        let mut touched = BTreeSet::new();
        for &f in &group {
            for (h, _) in graph.neighbours(f) {
                if let Some(sp) = stock[h.index()] {
                    touched.insert(sp);
                }
            }
        }
        out.push(depression_feature(part, props, &group, &touched, tol));
    }
    out.sort_by_key(|m| m.faces.first().copied().unwrap_or(0));
    for (i, m) in out.iter_mut().enumerate() {
        m.id = format!("M{}", i + 1);
    }
    out
}

fn components(set: &BTreeSet<FaceId>, next: impl Fn(FaceId) -> Vec<FaceId>) -> Vec<Vec<FaceId>> {
    let mut seen = BTreeSet::new();
    let mut out = Vec::new();
    for &s in set {
        if !seen.insert(s) {
            continue;
        }
        let mut comp = vec![s];
        let mut i = 0;
        while i < comp.len() {
            for g in next(comp[i]) {
                if set.contains(&g) && seen.insert(g) {
                    comp.push(g);
                }
            }
            i += 1;
        }
        comp.sort();
        out.push(comp);
    }
    out
}

fn ids(part: &Part, fs: &[FaceId]) -> Vec<u64> {
    let mut v: Vec<u64> = fs.iter().map(|&f| part.face(f).step_id).collect();
    v.sort();
    v
}

fn radii(part: &Part, fs: &[FaceId]) -> Vec<f64> {
    let mut r: Vec<f64> = fs
        .iter()
        .filter_map(|&f| match part.face(f).surface {
            Surface::Cylinder { radius, .. } | Surface::Sphere { radius, .. } => Some(radius),
            Surface::Torus { minor_radius, .. } => Some(minor_radius),
            _ => None,
        })
        .collect();
    r.sort_by(f64::total_cmp);
    r.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    r
}

fn blend_feature(part: &Part, props: &[FaceProps], group: &[FaceId]) -> MachiningFeature {
    let convex = part.face(group[0]).same_sense;
    let dir = props[group[0].index()].axis.map_or(Vector3::z(), |a| a.1);
    MachiningFeature {
        id: String::new(),
        kind: "fillet".into(),
        through: false,
        profile: if convex {
            "round".into()
        } else {
            "fillet".into()
        },
        direction: [dir.x, dir.y, dir.z],
        faces: ids(part, group),
        bottom_faces: vec![],
        side_faces: ids(part, group),
        open_to: vec![],
        depth: 0.0,
        length: 0.0,
        width: 0.0,
        radii: radii(part, group),
        largest_tool_diameter: None,
    }
}

/// Extent of faces' boundary points along `dir`.
fn extent(part: &Part, fs: &[FaceId], dir: &Vector3) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for &f in fs {
        for p in thinwall_recognize::depressions::face_points(part, f) {
            let x = p.coords.dot(dir);
            lo = lo.min(x);
            hi = hi.max(x);
        }
    }
    (lo, hi)
}

/// Walls of `group` adjacent to wall `w` (sharing an edge).
fn wall_neighbours(part: &Part, w: FaceId, walls: &[FaceId]) -> usize {
    let mut n = BTreeSet::new();
    for &l in &part.face(w).loops {
        for ce in &part.loop_(l).coedges {
            for &x in walls {
                if x != w
                    && part
                        .face(x)
                        .loops
                        .iter()
                        .any(|&m| part.loop_(m).coedges.iter().any(|c| c.edge == ce.edge))
                {
                    n.insert(x);
                }
            }
        }
    }
    n.len()
}

fn depression_feature(
    part: &Part,
    props: &[FaceProps],
    group: &[FaceId],
    touched: &BTreeSet<usize>,
    tol: f64,
) -> MachiningFeature {
    let t = touched.len();
    let opposite: Vec<usize> = (0..3)
        .filter(|k| touched.contains(&(2 * k)) && touched.contains(&(2 * k + 1)))
        .collect();
    // Distinct planes among the planar faces.
    let mut planes: Vec<(Vector3, f64)> = Vec::new();
    for &f in group {
        if let Some(n) = props[f.index()].normal {
            let off = n.dot(&props[f.index()].centroid.coords);
            if !planes
                .iter()
                .any(|(m, o)| m.dot(&n) > 1.0 - 1e-9 && (o - off).abs() < tol * 10.0)
            {
                planes.push((n, off));
            }
        }
    }
    let d = planes.len();
    let cylinders: Vec<(Point3, Vector3, f64)> = group
        .iter()
        .filter_map(|&f| hole_cylinder(part, f))
        .collect();
    let aligned = planes
        .iter()
        .all(|(n, _)| n.iter().any(|c| c.abs() > 1.0 - 1e-9));
    let profile_of = |k: usize| match k {
        3 => "triangular",
        4 => "rectangular",
        6 => "hexagonal",
        _ => "free",
    };
    // The stock plane it is entered from: the one not in an opposite pair,
    // facing the same way as a floor if there is one.
    let entry: Option<usize> = {
        let candidates: Vec<usize> = touched
            .iter()
            .copied()
            .filter(|sp| !opposite.contains(&(sp / 2)))
            .collect();
        candidates
            .iter()
            .copied()
            .find(|&sp| {
                planes
                    .iter()
                    .any(|(n, _)| n.dot(&plane_normal(sp)) > 1.0 - 1e-9)
            })
            .or_else(|| candidates.first().copied())
            .or_else(|| touched.iter().next().copied())
    };
    let floor_up = if t == 1 {
        entry.map(plane_normal)
    } else {
        None
    };
    let has_floor = floor_up.is_some_and(|u| planes.iter().any(|(n, _)| n.dot(&u) > 1.0 - 1e-9));
    // Walls closing a ring around the floor: each wall meets two others.
    let ring = {
        let walls: Vec<FaceId> = group
            .iter()
            .copied()
            .filter(|&f| {
                !floor_up.is_some_and(|u| {
                    props[f.index()]
                        .normal
                        .is_some_and(|n| n.dot(&u) > 1.0 - 1e-9)
                })
            })
            .collect();
        !walls.is_empty() && walls.iter().all(|&w| wall_neighbours(part, w, &walls) >= 2)
    };
    let (kind, through, profile): (&str, bool, String) = if !cylinders.is_empty() {
        // Holes: concave cylinders. Blind when a face closes the far end:
        // a plane across the axis, or a drill point (cone, sphere) there.
        let axis = cylinders[0].1;
        let (lo, hi) = extent(part, group, &axis);
        let at_end = |f: FaceId| {
            let (a, b) = extent(part, &[f], &axis);
            (a - lo).abs() < tol * 100.0 || (b - hi).abs() < tol * 100.0
        };
        let closes = |f: FaceId| match part.face(f).surface {
            Surface::Plane { .. } => {
                props[f.index()]
                    .normal
                    .is_some_and(|n| n.dot(&axis).abs() > 1.0 - 1e-6)
                    && at_end(f)
                    && part.face(f).loops.len() == 1
            }
            // A drill point: at the far end, coming to a tip (a vertex
            // loop) or a single boundary.
            Surface::Cone { .. } | Surface::Sphere { .. } => {
                let face = part.face(f);
                at_end(f)
                    && (face.loops.len() == 1
                        || face.loops.iter().any(|&l| part.loop_(l).vertex.is_some()))
            }
            _ => false,
        };
        let bottom = group.iter().any(|&f| closes(f));
        let distinct_r = radii(part, group).len();
        let cone = group
            .iter()
            .any(|&f| matches!(part.face(f).surface, Surface::Cone { .. }));
        let profile = if cone && distinct_r >= 1 {
            "countersunk"
        } else if distinct_r == 2 {
            "counterbored"
        } else if distinct_r > 2 {
            "multi_segment"
        } else {
            "circular"
        };
        ("hole", !bottom, profile.to_string())
    } else if d == 1 && t >= 3 {
        ("chamfer", false, "slanted".to_string())
    } else if has_floor && ring {
        ("pocket", false, profile_of(d - 1).to_string())
    } else if has_floor {
        // A floor whose walls do not close: it opens sideways into another feature.
        (
            "step",
            false,
            if d <= 2 { "triangular" } else { "rectangular" }.to_string(),
        )
    } else if t == 1 || (t == 2 && opposite.len() == 1) {
        ("passage", true, profile_of(d).to_string())
    } else if !opposite.is_empty() && t == 3 {
        (
            "slot",
            true,
            if d == 2 { "triangular" } else { "rectangular" }.to_string(),
        )
    } else if !opposite.is_empty() && t == 4 {
        (
            "step",
            true,
            if d == 3 {
                "two_sided"
            } else if aligned {
                "rectangular"
            } else {
                "slanted"
            }
            .to_string(),
        )
    } else if opposite.is_empty() && t == 3 {
        (
            "step",
            false,
            if d == 2 { "triangular" } else { "rectangular" }.to_string(),
        )
    } else if opposite.is_empty() && t == 2 && d == 4 {
        ("slot", false, "rectangular".to_string())
    } else if opposite.is_empty() && t == 2 {
        (
            "step",
            false,
            if d <= 2 { "triangular" } else { "rectangular" }.to_string(),
        )
    } else {
        // Opens to no block plane, or in a way none of the above describes.
        ("pocket", false, "free".to_string())
    };
    // Direction: into the part from the entry plane (holes: along the axis).
    let dir = if let Some(c) = cylinders.first() {
        let a = c.1;
        match entry {
            Some(sp) if plane_normal(sp).dot(&a) > 0.0 => -a,
            _ => a,
        }
    } else {
        entry.map(|sp| -plane_normal(sp)).unwrap_or(-Vector3::z())
    };
    let bottom: Vec<FaceId> = group
        .iter()
        .copied()
        .filter(|&f| {
            props[f.index()]
                .normal
                .is_some_and(|n| n.dot(&-dir) > 1.0 - 1e-6)
        })
        .collect();
    let sides: Vec<FaceId> = group
        .iter()
        .copied()
        .filter(|f| !bottom.contains(f))
        .collect();
    let (lo, hi) = extent(part, group, &dir);
    // Profile sizes: the faces' points projected on the plane across `dir`.
    let u = thinwall_geom::frame::any_perpendicular(&dir);
    let v = dir.cross(&u);
    let mut pts: Vec<geo::Coord<f64>> = Vec::new();
    for &f in group {
        for p in thinwall_recognize::depressions::face_points(part, f) {
            pts.push(geo::Coord {
                x: p.coords.dot(&u),
                y: p.coords.dot(&v),
            });
        }
    }
    let (length, width) = {
        use geo::MinimumRotatedRect;
        let mp =
            geo::MultiPoint::from(pts.iter().map(|c| geo::Point::from(*c)).collect::<Vec<_>>());
        mp.minimum_rotated_rect().map_or((0.0, 0.0), |r| {
            let c: Vec<geo::Coord<f64>> = r.exterior().coords().copied().collect();
            let a = ((c[1].x - c[0].x).powi(2) + (c[1].y - c[0].y).powi(2)).sqrt();
            let b = ((c[2].x - c[1].x).powi(2) + (c[2].y - c[1].y).powi(2)).sqrt();
            (a.max(b), a.min(b))
        })
    };
    let radii_v = radii(part, group);
    let largest_tool_diameter = if kind == "hole" {
        radii_v.first().map(|r| 2.0 * r)
    } else if !bottom.is_empty() {
        let floors: MultiPolygon<f64> = MultiPolygon::new(
            bottom
                .iter()
                .filter_map(|&f| thinwall_recognize::planar::PlanarFace::new(part, f))
                .flat_map(|p| p.polygon_in(&p.frame).0)
                .collect(),
        );
        (floors.unsigned_area() > 0.0)
            .then(|| 2.0 * thinwall_recognize::planar::inscribed_radius(&floors))
    } else {
        None
    };
    MachiningFeature {
        id: String::new(),
        kind: kind.into(),
        through,
        profile,
        direction: [dir.x, dir.y, dir.z],
        faces: ids(part, group),
        bottom_faces: ids(part, &bottom),
        side_faces: ids(part, &sides),
        open_to: touched
            .iter()
            .map(|&sp| {
                let n = plane_normal(sp);
                [n.x, n.y, n.z]
            })
            .collect(),
        depth: if hi.is_finite() { hi - lo } else { 0.0 },
        length,
        width,
        radii: radii_v,
        largest_tool_diameter,
    }
}

/// The MFCAD class (0–15) of a face, from the features (15 = stock).
pub fn mfcad_class(features: &[MachiningFeature], step_id: u64) -> u64 {
    let Some(m) = features.iter().find(|m| m.faces.contains(&step_id)) else {
        return 15;
    };
    match (m.kind.as_str(), m.through, m.profile.as_str()) {
        ("chamfer", _, _) => 0,
        ("passage", true, "triangular") => 1,
        ("passage", true, "rectangular") => 2,
        ("passage", true, "hexagonal") => 3,
        ("slot", true, "triangular") => 4,
        ("slot", true, "rectangular") => 5,
        ("step", true, "rectangular") => 6,
        ("step", true, "two_sided") => 7,
        ("step", true, "slanted") => 8,
        ("pocket", false, "triangular") => 9,
        ("pocket", false, "rectangular") => 10,
        ("pocket", false, "hexagonal") => 11,
        ("slot", false, "rectangular") => 12,
        ("step", false, "triangular") => 13,
        ("step", false, "rectangular") => 14,
        _ => 99,
    }
}
