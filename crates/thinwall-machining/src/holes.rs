//! Compound holes: a hole is one feature with its stages from the entry
//! down, as a planner drills it (spot, drill, counterbore or countersink,
//! chamfer). The grouping leaves a hole's stages apart (a countersink's
//! cone meets the drill along a convex edge, so it is a chamfer of its own;
//! a counterbore is a hole of its own; a blended entry a round); here the
//! hole features, single-cone chamfers and torus rounds that share an axis
//! and a boundary are joined into one hole, and its form is read along the
//! axis: the entry (countersink, chamfer or blend), the bores from the
//! entry down (diameter and depth each), the exit, and the tip.

use crate::{radii, MachiningFeature};
use petgraph::unionfind::UnionFind;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use thinwall_analysis::{Catalog, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::{Point3, Surface, Vector3};

/// A conical entry narrower (radially) than this share of the drill's
/// diameter is a chamfer (an edge break); wider, a countersink (a seat for
/// a screw head).
const CHAMFER_WIDTH_SHARE: f64 = 0.2;

/// Whether an end widened to radius `r` over a drill of radius `drill` is
/// a seat (a countersink, a counterbore) rather than a chamfer.
fn is_seat(r: f64, drill: f64) -> bool {
    r - drill > CHAMFER_WIDTH_SHARE * 2.0 * drill
}

/// One end of a hole: how its edge is finished.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum HoleEnd {
    /// A cone seating a screw head: included angle, degrees; diameter on
    /// the face, mm.
    Countersink { angle_deg: f64, diameter: f64 },
    /// A cone breaking the edge: included angle, degrees; diameter on the
    /// face, mm.
    Chamfer { angle_deg: f64, diameter: f64 },
    /// A rounded edge: radius, mm.
    Blend { radius: f64 },
}

/// One cylindrical stage of a hole: diameter and depth along the axis, mm.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bore {
    pub diameter: f64,
    pub depth: f64,
}

/// How a hole ends.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HoleTip {
    Through,
    /// A flat bottom.
    Flat,
    /// A drill's cone: included angle, degrees.
    DrillPoint {
        angle_deg: f64,
    },
}

/// A hole's stages from the entry down.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct HoleForm {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entry: Option<HoleEnd>,
    /// From the entry down (a counterbore, then the drill; a stepped
    /// hole's steps; a counterbore at the far end last).
    pub bores: Vec<Bore>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exit: Option<HoleEnd>,
    pub tip: HoleTip,
}

/// An axis line: a point on it and its unit direction.
type Axis = (Point3, Vector3);

/// The axis a feature can share with a hole: a hole's first concave
/// cylinder, or the common axis of a chamfer's cones or a round's tori.
fn feature_axis(a: &PartAnalysis, m: &MachiningFeature, faces: &[FaceId]) -> Option<Axis> {
    let axis_of = |f: FaceId| match a.part().face(f).surface {
        Surface::Cylinder { frame, .. } if m.kind == MachiningKind::Hole => {
            Some((frame.origin, frame.z))
        }
        Surface::Cone { frame, .. } if m.kind == MachiningKind::Chamfer => {
            Some((frame.origin, frame.z))
        }
        Surface::Torus { frame, .. } if m.kind == MachiningKind::Fillet => {
            Some((frame.origin, frame.z))
        }
        _ => None,
    };
    match m.kind {
        MachiningKind::Hole => faces.iter().find_map(|&f| {
            a.concave_cylinder(f)
                .map(|c| (c.origin, c.axis))
                .filter(|_| axis_of(f).is_some())
        }),
        MachiningKind::Chamfer | MachiningKind::Fillet => {
            let axes: Vec<Axis> = faces.iter().map(|&f| axis_of(f)).collect::<Option<_>>()?;
            let first = *axes.first()?;
            let tol = crate::axis_tol(a);
            axes.iter()
                .all(|x| same_axis(&first, x, tol))
                .then_some(first)
        }
        _ => None,
    }
}

fn same_axis((p, u): &Axis, (q, v): &Axis, tol: f64) -> bool {
    let parallel = u.cross(v).norm() < 1e-6;
    let off = (q - p) - u * (q - p).dot(u);
    parallel && off.norm() < tol
}

/// Join holes with the chamfers, rounds and holes that share their axis
/// and meet them, and read each joined hole's form (a through hole with no
/// seat along the set-up's `up` is entered from above).
pub(crate) fn compound(
    a: &PartAnalysis,
    features: Vec<MachiningFeature>,
    up: Option<Vector3>,
) -> Vec<MachiningFeature> {
    let by_step: HashMap<(u32, u64), FaceId> = a
        .part()
        .face_ids()
        .map(|f| ((a.part().face(f).body.0, a.part().face(f).step_id), f))
        .collect();
    let faces: Vec<Vec<FaceId>> = features
        .iter()
        .map(|m| {
            m.faces
                .iter()
                .filter_map(|s| by_step.get(&(m.body, *s)).copied())
                .collect()
        })
        .collect();
    let axes: Vec<Option<Axis>> = features
        .iter()
        .zip(&faces)
        .map(|(m, f)| feature_axis(a, m, f))
        .collect();
    let mut owner: HashMap<FaceId, usize> = HashMap::new();
    for (i, fs) in faces.iter().enumerate() {
        for &f in fs {
            owner.insert(f, i);
        }
    }
    let mut sets = UnionFind::<usize>::new(features.len());
    let tol = crate::axis_tol(a);
    for (i, fs) in faces.iter().enumerate() {
        let Some(ax) = axes[i] else { continue };
        for &f in fs {
            for (g, _) in a.graph().neighbours(f) {
                let Some(&j) = owner.get(&g) else { continue };
                let holes = features[i].kind == MachiningKind::Hole
                    || features[j].kind == MachiningKind::Hole;
                if j != i && holes && axes[j].is_some_and(|bx| same_axis(&ax, &bx, tol)) {
                    sets.union(i, j);
                }
            }
        }
    }
    join(a, features, &faces, &axes, &mut sets, up)
}

/// One feature per set: a set with a hole is that hole, with every face of
/// the set and its form; the rest stay as they were.
fn join(
    a: &PartAnalysis,
    features: Vec<MachiningFeature>,
    faces: &[Vec<FaceId>],
    axes: &[Option<Axis>],
    sets: &mut UnionFind<usize>,
    up: Option<Vector3>,
) -> Vec<MachiningFeature> {
    let mut members: HashMap<usize, Vec<usize>> = HashMap::new();
    for i in 0..features.len() {
        members.entry(sets.find_mut(i)).or_default().push(i);
    }
    let mut out = Vec::new();
    let mut features: Vec<Option<MachiningFeature>> = features.into_iter().map(Some).collect();
    for i in 0..features.len() {
        let root = sets.find_mut(i);
        if root != i && members[&root].len() > 1 {
            continue;
        }
        let group = &members[&root];
        let Some(hole) = group.iter().copied().find(|&k| {
            features[k]
                .as_ref()
                .is_some_and(|m| m.kind == MachiningKind::Hole)
        }) else {
            out.extend(group.iter().filter_map(|&k| features[k].take()));
            continue;
        };
        let all: Vec<FaceId> = group.iter().flat_map(|&k| faces[k].clone()).collect();
        let mut m = features[hole].take().expect("each feature is taken once");
        for &k in group {
            if let Some(other) = features[k].take() {
                m.bottom_faces.extend(other.bottom_faces);
                m.side_faces.extend(&other.side_faces);
                match other.kind {
                    MachiningKind::Chamfer => m.chamfer_faces.extend(other.faces),
                    MachiningKind::Fillet => m.blend_faces.extend(other.faces),
                    _ => {}
                }
            }
        }
        m.chamfer_faces.sort();
        m.blend_faces.sort();
        shape_hole(a, &mut m, &all, axes[hole].expect("a hole has an axis"), up);
        out.push(m);
    }
    out
}

/// Fill a joined hole's faces, direction, sizes, profile and form.
fn shape_hole(
    a: &PartAnalysis,
    m: &mut MachiningFeature,
    all: &[FaceId],
    (p, u): Axis,
    up: Option<Vector3>,
) {
    let stations = Stations::of(a, all, p, u);
    // Into the part from the entry: the open end of a blind hole, else the
    // end with a seat, else from above (along the set-up's up), else the
    // way the hole was found.
    let found = Vector3::new(m.direction[0], m.direction[1], m.direction[2]);
    let given = match up {
        Some(up) if up.dot(&u).abs() > 1.0 - NEAR_PARALLEL_EPS => -up,
        _ => found,
    };
    let forward = match (stations.closed_at(false), stations.closed_at(true)) {
        (true, false) => true,
        (false, true) => false,
        _ => match stations.seat_side() {
            Some(near) => near,
            None => given.dot(&u) >= 0.0,
        },
    };
    let stations = if forward {
        stations
    } else {
        stations.reversed()
    };
    let d = if forward { u } else { -u };
    let form = stations.form();
    let entry = p + u * (if forward { stations.lo } else { -stations.lo });
    m.faces = a.step_ids(all);
    m.side_faces.sort();
    m.side_faces.dedup();
    m.bottom_faces.sort();
    m.bottom_faces.dedup();
    m.direction = [d.x, d.y, d.z];
    m.centre = Some([entry.x, entry.y, entry.z]);
    m.depth = stations.hi - stations.lo;
    m.through = form.tip == HoleTip::Through;
    m.radii = radii(a, all);
    let widest = form.bores.iter().map(|b| b.diameter).fold(0.0, f64::max);
    if widest > 0.0 {
        m.length = widest;
        m.width = widest;
    }
    m.largest_tool_diameter = form
        .bores
        .iter()
        .map(|b| b.diameter)
        .reduce(f64::min)
        .or(m.largest_tool_diameter);
    m.tool_bound = Some(crate::ToolBound::Bore);
    m.profile = match (&form.entry, form.bores.len()) {
        (Some(HoleEnd::Countersink { .. }), _) => Profile::Countersunk,
        (_, 2) => Profile::Counterbored,
        (_, n) if n > 2 => Profile::MultiSegment,
        _ => Profile::Circular,
    };
    if m.catalog.is_none() {
        m.catalog = Some(if m.through {
            Catalog::ThroughHole
        } else {
            Catalog::BlindHole
        });
    }
    m.hole = Some(form);
}

/// What one face of a hole is along its axis: from `t0` to `t1` (mm along
/// the axis from its point), its kind and sizes.
#[derive(Clone, Copy, Debug)]
struct Station {
    t0: f64,
    t1: f64,
    kind: StationKind,
}

#[derive(Clone, Copy, Debug)]
enum StationKind {
    Bore {
        radius: f64,
    },
    /// A cone: included angle, degrees; its smallest and largest radius.
    Cone {
        angle_deg: f64,
        r0: f64,
        r1: f64,
    },
    Blend {
        radius: f64,
    },
    /// A face across the axis with one boundary (a flat bottom).
    Bottom,
    Other,
}

/// A hole's faces along its axis, and the extent they span.
struct Stations {
    list: Vec<Station>,
    lo: f64,
    hi: f64,
    tol: f64,
}

impl Stations {
    fn of(a: &PartAnalysis, faces: &[FaceId], p: Point3, u: Vector3) -> Self {
        let list: Vec<Station> = faces.iter().map(|&f| station(a, f, &p, &u)).collect();
        let lo = list.iter().map(|s| s.t0).fold(f64::INFINITY, f64::min);
        let hi = list.iter().map(|s| s.t1).fold(f64::NEG_INFINITY, f64::max);
        Self {
            list,
            lo,
            hi,
            tol: a.tol().feature * 100.0,
        }
    }

    /// The same faces seen from the other end.
    fn reversed(self) -> Self {
        let list = self
            .list
            .iter()
            .map(|s| Station {
                t0: -s.t1,
                t1: -s.t0,
                kind: s.kind,
            })
            .collect();
        Self {
            list,
            lo: -self.hi,
            hi: -self.lo,
            tol: self.tol,
        }
    }

    /// Whether a face reaches the near end (`near`) or the far one.
    fn at_end(&self, s: &Station, near: bool) -> bool {
        if near {
            (s.t0 - self.lo).abs() < self.tol
        } else {
            (s.t1 - self.hi).abs() < self.tol
        }
    }

    /// A flat bottom or a drill point closes that end.
    fn closed_at(&self, near: bool) -> bool {
        self.list
            .iter()
            .any(|s| self.at_end(s, near) && self.closes(s))
    }

    fn closes(&self, s: &Station) -> bool {
        match s.kind {
            StationKind::Bottom => true,
            StationKind::Cone { r0, .. } => r0 < self.tol,
            _ => false,
        }
    }

    /// The end with a seat (a countersink or a counterbore: its widest
    /// radius there beyond the drill's by more than a chamfer): `true` at
    /// the near end, none where neither or both have one.
    fn seat_side(&self) -> Option<bool> {
        let drill = self.drill_radius()?;
        let seat = |near: bool| {
            self.list.iter().any(|s| {
                let end = self.at_end(s, near);
                let r = match s.kind {
                    StationKind::Bore { radius } => radius,
                    StationKind::Cone { r1, .. } => r1,
                    _ => 0.0,
                };
                end && is_seat(r, drill)
            })
        };
        match (seat(true), seat(false)) {
            (true, false) => Some(true),
            (false, true) => Some(false),
            _ => None,
        }
    }

    /// The drill's radius: the narrowest bore.
    fn drill_radius(&self) -> Option<f64> {
        self.list
            .iter()
            .filter_map(|s| match s.kind {
                StationKind::Bore { radius } => Some(radius),
                _ => None,
            })
            .reduce(f64::min)
    }

    /// The form, read from the near end (the entry).
    fn form(&self) -> HoleForm {
        let drill = self.drill_radius().unwrap_or(0.0);
        let end = |near: bool| {
            self.list
                .iter()
                .filter(|s| self.at_end(s, near))
                .find_map(|s| hole_end(s, drill))
        };
        let tip = self
            .list
            .iter()
            .filter(|s| self.at_end(s, false))
            .find_map(|s| match s.kind {
                StationKind::Bottom => Some(HoleTip::Flat),
                StationKind::Cone { angle_deg, r0, .. } if r0 < self.tol => {
                    Some(HoleTip::DrillPoint { angle_deg })
                }
                _ => None,
            })
            .unwrap_or(HoleTip::Through);
        HoleForm {
            entry: end(true),
            bores: self.bores(),
            exit: if tip == HoleTip::Through {
                end(false)
            } else {
                None
            },
            tip,
        }
    }

    /// The cylinders by radius and place (a bore's halves are one; two
    /// counterbores of one size at either end are two), ordered from the
    /// entry, each with the depth it spans.
    fn bores(&self) -> Vec<Bore> {
        let mut spans: Vec<(f64, f64, f64)> = Vec::new(); // radius, t0, t1
        let mut list: Vec<&Station> = self.list.iter().collect();
        list.sort_by(|x, y| x.t0.total_cmp(&y.t0));
        for s in list {
            if let StationKind::Bore { radius } = s.kind {
                let joins = |b: &&mut (f64, f64, f64)| {
                    (b.0 - radius).abs() < self.tol
                        && s.t0 <= b.2 + self.tol
                        && b.1 <= s.t1 + self.tol
                };
                match spans.iter_mut().find(joins) {
                    Some(b) => {
                        b.1 = b.1.min(s.t0);
                        b.2 = b.2.max(s.t1);
                    }
                    None => spans.push((radius, s.t0, s.t1)),
                }
            }
        }
        spans.sort_by(|x, y| x.1.total_cmp(&y.1));
        spans
            .iter()
            .map(|&(r, t0, t1)| Bore {
                diameter: 2.0 * r,
                depth: t1 - t0,
            })
            .collect()
    }
}

/// How a face finishes an end of a hole whose drill has radius `drill`.
fn hole_end(s: &Station, drill: f64) -> Option<HoleEnd> {
    match s.kind {
        StationKind::Cone { angle_deg, r0, r1 } if r0 > 0.0 => {
            let diameter = 2.0 * r1;
            Some(if is_seat(r1, drill) {
                HoleEnd::Countersink {
                    angle_deg,
                    diameter,
                }
            } else {
                HoleEnd::Chamfer {
                    angle_deg,
                    diameter,
                }
            })
        }
        StationKind::Blend { radius } => Some(HoleEnd::Blend { radius }),
        _ => None,
    }
}

/// One face along the axis through `p` along `u`.
fn station(a: &PartAnalysis, f: FaceId, p: &Point3, u: &Vector3) -> Station {
    let pts = a.boundary_points(f);
    let along = |q: &Point3| (q - p).dot(u);
    let across = |q: &Point3| ((q - p) - u * (q - p).dot(u)).norm();
    let t0 = pts.iter().map(along).fold(f64::INFINITY, f64::min);
    let t1 = pts.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
    let kind = match a.part().face(f).surface {
        Surface::Cylinder { radius, .. } if a.concave_cylinder(f).is_some() => {
            StationKind::Bore { radius }
        }
        Surface::Cone { semi_angle, .. } => {
            let face = a.part().face(f);
            // A drill point comes to its apex (a vertex loop).
            let apex = face
                .loops
                .iter()
                .any(|&l| a.part().loop_(l).vertex.is_some());
            StationKind::Cone {
                angle_deg: 2.0 * semi_angle.abs().to_degrees(),
                r0: if apex {
                    0.0
                } else {
                    pts.iter().map(across).fold(f64::INFINITY, f64::min)
                },
                r1: pts.iter().map(across).fold(0.0, f64::max),
            }
        }
        Surface::Torus { minor_radius, .. } => StationKind::Blend {
            radius: minor_radius,
        },
        Surface::Plane { .. }
            if a.props(f)
                .normal
                .is_some_and(|n| n.dot(u).abs() > 1.0 - 1e-9)
                && a.part().face(f).loops.len() == 1 =>
        {
            StationKind::Bottom
        }
        _ => StationKind::Other,
    };
    Station { t0, t1, kind }
}
